"""The budget of a drawing file, checked before its outline is built (for :mod:`outlines`).

An SVG or DXF file of a few kilobytes can ask for hours of work or gigabytes of
memory: ``<use>`` elements that each repeat the one before (2¹⁷ copies from 17
lines), a circle of radius 1e308, a thousand arcs flattened to 1e-9.  Each is
refused here, from the text or the entities alone, before the libraries expand
or flatten anything:

* :func:`svg_utf8` decodes the SVG by its byte order mark or XML declaration
  (UTF-8, UTF-16 either way, UTF-32) and refuses a ``DOCTYPE`` with an internal
  subset (where general and parameter entities live) in the *decoded* text, so a
  UTF-16 file cannot hide one from a byte test; the text handed on is UTF-8;
* :func:`check_use_expansion` counts the elements an SVG has once every
  ``<use>`` is expanded (at most :data:`MAX_SVG_ELEMENTS`) and refuses a cycle;
* :func:`check_coordinates` refuses coordinates beyond :data:`MAX_COORDINATE`
  drawing units (or not finite), so sizes and chord counts stay finite;
* :func:`chord_budget` counts chords before they are made (at most
  :data:`MAX_VERTICES` in the whole drawing);
* :func:`check_extent` refuses an outline in metres whose size is outside
  :data:`EXTENT_METRES` (``unit="1e300m"``: infinite area; ``unit="1e-300m"``: none).

Examples
--------
>>> svg_utf8('<svg xmlns="http://www.w3.org/2000/svg"/>'.encode("utf-16"))[:4]
b'<svg'
>>> check_extent(0.05, "part.svg")
"""

from __future__ import annotations

import codecs
import math
import re
from typing import Any

from ..boundary.errors import InputError, InputTooLargeError

__all__ = [
    "EXTENT_METRES",
    "MAX_COORDINATE",
    "MAX_SVG_ELEMENTS",
    "MAX_VERTICES",
    "check_coordinates",
    "check_extent",
    "check_use_expansion",
    "chord_budget",
    "svg_utf8",
]

#: Most elements of an SVG with every ``<use>`` expanded.
MAX_SVG_ELEMENTS = 100_000
#: Largest |coordinate| of a drawing, in its own units.
MAX_COORDINATE = 1e12
#: Most vertices of all flattened outlines of one drawing.
MAX_VERTICES = 200_000
#: Smallest and largest size (the larger side of the bounding box) of a part, in metres.
EXTENT_METRES = (1e-9, 1e6)

_BOMS = (
    (codecs.BOM_UTF32_LE, "utf-32-le"),
    (codecs.BOM_UTF32_BE, "utf-32-be"),
    (codecs.BOM_UTF8, "utf-8"),
    (codecs.BOM_UTF16_LE, "utf-16-le"),
    (codecs.BOM_UTF16_BE, "utf-16-be"),
)
_DECL = re.compile(r"""^\s*<\?xml[^>]*?\bencoding\s*=\s*["']([A-Za-z0-9._-]+)["'][^>]*\?>""")
_XML_DECL = re.compile(r"^\s*<\?xml[^>]*\?>")


def _encoding(data: bytes) -> tuple[str, int]:
    for bom, name in _BOMS:
        if data.startswith(bom):
            return name, len(bom)
    if data[:2] == b"<\0":
        return "utf-16-le", 0
    if data[:2] == b"\0<":
        return "utf-16-be", 0
    m = _DECL.match(data[:200].decode("latin-1"))
    if m is None:
        return "utf-8", 0
    try:
        return codecs.lookup(m.group(1)).name, 0
    except LookupError:
        raise InputError(f"the SVG declares the unknown encoding {m.group(1)!r}") from None


def svg_utf8(data: bytes) -> bytes:
    """The SVG's text as UTF-8 without its XML declaration; any DTD refused.

    Raises
    ------
    InputError
        Text that does not decode, or that declares a DTD or entities.
    """
    name, skip = _encoding(data)
    try:
        text = data[skip:].decode(name)
    except UnicodeDecodeError as exc:
        raise InputError(f"the SVG is not readable {name} text (byte {exc.start})") from None
    low = text.lower()
    doctype = low.find("<!doctype")
    subset = doctype >= 0 and "[" in low[doctype : low.find(">", doctype) + 1 or None]
    if subset or any(word in low for word in ("<!entity", "<!element", "<!attlist")):
        raise InputError(
            "the SVG declares entities (a DOCTYPE with an internal subset, <!ENTITY ...>): refused"
        )
    return _XML_DECL.sub("", text, count=1).encode("utf-8")


def check_use_expansion(text: bytes, where: str) -> None:
    """Refuse an SVG whose ``<use>`` elements expand beyond :data:`MAX_SVG_ELEMENTS`.

    ``text`` is the UTF-8 of :func:`svg_utf8` (no DTD, so no entity expansion here).
    """
    import xml.etree.ElementTree as ET

    try:
        root = ET.fromstring(text)
    except ET.ParseError as exc:
        raise InputError(f"{where}: not a readable SVG file: {exc}") from None
    by_id = {e.get("id"): e for e in root.iter() if e.get("id")}
    sizes: dict[int, int] = {}
    active: set[int] = set()

    def size(e: Any) -> int:
        key = id(e)
        if key in sizes:
            return sizes[key]
        if key in active:
            raise InputError(f"{where}: a <use> refers to itself (through {e.get('id')!r})")
        active.add(key)
        total = 1
        stack = list(e)
        total += sum(size(child) for child in stack)
        if e.tag.rsplit("}", 1)[-1] == "use":
            ref = e.get("href") or e.get("{http://www.w3.org/1999/xlink}href") or ""
            if ref.startswith("#") and ref[1:] in by_id:
                total += size(by_id[ref[1:]])
        active.discard(key)
        sizes[key] = total = min(total, MAX_SVG_ELEMENTS + 1)
        return total

    import sys

    depth = sys.getrecursionlimit()
    try:
        sys.setrecursionlimit(max(depth, 20_000))
        n = size(root)
    except RecursionError:
        raise InputTooLargeError(f"{where}: the SVG nests too deep") from None
    finally:
        sys.setrecursionlimit(depth)
    if n > MAX_SVG_ELEMENTS:
        raise InputTooLargeError(
            f"{where}: the SVG has more than {MAX_SVG_ELEMENTS} elements "
            "once its <use> elements are expanded"
        )


def check_coordinates(values: Any, where: str) -> None:
    """Refuse coordinates beyond :data:`MAX_COORDINATE` or not finite."""
    for v in values:
        v = float(v)
        if not (math.isfinite(v) and abs(v) <= MAX_COORDINATE):
            raise InputError(
                f"{where}: a coordinate {v:g} is beyond {MAX_COORDINATE:g} drawing "
                "units (or not finite): give the drawing in other units"
            )


class chord_budget:
    """Counts vertices against :data:`MAX_VERTICES` as they are planned or made."""

    def __init__(self, where: str) -> None:
        self.where, self.used = where, 0

    def take(self, n: int) -> None:
        self.used += n
        if self.used > MAX_VERTICES:
            raise InputTooLargeError(
                f"{self.where}: flattening the drawing's curves needs more than {MAX_VERTICES} "
                "vertices (a larger tolerance, or fewer curves)"
            )


def check_extent(size_m: float, where: str) -> None:
    """Refuse a part whose size in metres is outside :data:`EXTENT_METRES`."""
    lo, hi = EXTENT_METRES
    if not (math.isfinite(size_m) and lo <= size_m <= hi):
        raise InputError(
            f"{where}: the part would be {size_m:g} m across, outside {lo:g} m to "
            f"{hi:g} m: check the drawing's unit (unit=, --shape-unit)"
        )
