"""Sphinx configuration of the graspcompass documentation.

Markdown pages (MyST) with the furo theme, the gallery of the paper's figures
(sphinx-gallery, scripts in ``../gallery``), the API reference (autodoc +
napoleon, numpydoc style) and pages generated at build time into
``_generated/`` (never edited by hand, ignored by git):

- ``proof-report.md``: ``graspcompass verify --markdown``, run in-process;
- ``fig6-steps.md``: the construction protocol of the Fig. 6 grasp, each
  step linked to the paper's equation and to the gallery figure;
- ``main-job/``: what ``graspcompass`` (the README's first command) writes;
- ``explorer-static/explorer.html``: the web explorer of the Fig. 6 grasp
  (``graspcompass.export.html.write_html``), served as ``_static/explorer.html``.

The site works offline: MathJax 3 (``_static/mathjax``) and the icons of the
animation players (``_static/fontawesome``) are vendored, and intersphinx reads
the inventories in ``_intersphinx/`` only (never the network; see its README).

Build: ``sphinx-build -W --keep-going -b html docs docs/_build/html``
(``.ci/build-docs.sh``).
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import sys
from pathlib import Path
from typing import Any

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
GENERATED = DOCS / "_generated"
sys.path.insert(0, str(ROOT / "src"))  # the package as checked out, installed or not
os.environ.setdefault("MPLBACKEND", "agg")

import matplotlib  # noqa: E402

import graspcompass  # noqa: E402

# The gallery shows the library's standalone Figures and animations through pyplot with
# ``plt.figure(fig)``, which registers a Figure made without pyplot (Matplotlib 3.11).
if tuple(int(p) for p in re.findall(r"\d+", matplotlib.__version__)[:2]) < (3, 11):
    raise RuntimeError(f"the documentation needs matplotlib >= 3.11 (plt.figure(fig) on a "
                       f"standalone Figure); found {matplotlib.__version__}")

# -- project -----------------------------------------------------------------------------------
project = "graspcompass"
author = "graspcompass developers"
copyright = "graspcompass developers (MIT licence)"
version = release = graspcompass.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.napoleon",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "sphinx.ext.intersphinx",
    "sphinx_copybutton",
    "sphinx_gallery.gen_gallery",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "_generated/**", "_intersphinx", "**/GALLERY_HEADER.rst",
                    "Thumbs.db", ".DS_Store"]
# a broken cross-reference to our own pages is an error (-W); a reference into Python,
# numpy, sympy or matplotlib links there when its inventory is in _intersphinx/, and stays
# plain text otherwise
nitpicky = False

# -- MyST --------------------------------------------------------------------------------------
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence", "deflist", "attrs_inline"]
myst_heading_anchors = 3
myst_dmath_double_inline = True

# -- HTML --------------------------------------------------------------------------------------
html_theme = "furo"
html_title = f"graspcompass {release}"
html_static_path = ["_static"]
html_css_files = ["graspcompass.css"]
html_show_sourcelink = False
html_favicon = "_static/favicon.svg"
html_theme_options = {
    "sidebar_hide_name": False,
    "navigation_with_keys": True,
}

# MathJax 3.2.2 (npm package ``mathjax``, Apache-2.0), vendored in _static/mathjax: the
# combined component ``tex-chtml-full.js`` (TeX input with every extension, so nothing is
# autoloaded) and its woff fonts; the formulas render with no network at all.
mathjax_path = "mathjax/tex-chtml-full.js"
mathjax3_config = {
    "chtml": {"matchFontHeight": False},
    # MyST sets options.processHtmlClass (its pages are marked tex2jax_ignore)
    "options": {"enableMenu": True},
}

# The animation players that matplotlib writes (to_jshtml) link Font Awesome 4 on a CDN for
# their button icons; the gallery pages load the vendored subset instead (see
# _fix_animation_player below).
html_css_files.append("fontawesome/player.css")
_FONT_AWESOME_LINK = re.compile(
    r'<link rel="stylesheet"\s+href="https://maxcdn\.bootstrapcdn\.com/font-awesome/'
    r'[0-9.]+/css/font-awesome\.min\.css">\s*')

# The web explorer of the Fig. 6 grasp, written at build time into this folder and served
# as _static/explorer.html (explore.md embeds it in an iframe).
EXPLORER_STATIC = GENERATED / "explorer-static"
EXPLORER_STATIC.mkdir(parents=True, exist_ok=True)
html_static_path.append("_generated/explorer-static")

# -- copy buttons ------------------------------------------------------------------------------
# copy only the input of ``>>>``/``...`` sessions and ``$`` console lines, without the prompt
copybutton_prompt_text = r">>> |\.\.\. |\$ "
copybutton_prompt_is_regexp = True
copybutton_only_copy_prompt_lines = True
copybutton_exclude = ".linenos, .gp, .go"

# -- intersphinx (offline) ---------------------------------------------------------------------
# Each inventory is a file in _intersphinx/ (see _intersphinx/README.md: where they come from
# and how to refresh them); a missing file drops that project, and the build never fetches.
INTERSPHINX = DOCS / "_intersphinx"
_INVENTORIES = {
    "python": "https://docs.python.org/3/",
    "numpy": "https://numpy.org/doc/stable/",
    "sympy": "https://docs.sympy.org/latest/",
    "matplotlib": "https://matplotlib.org/stable/",
}
intersphinx_mapping = {name: (url, str(INTERSPHINX / f"{name}.inv"))
                       for name, url in _INVENTORIES.items()
                       if (INTERSPHINX / f"{name}.inv").is_file()}
intersphinx_timeout = 1
intersphinx_disabled_reftypes = ["*:doc", "std:label", "std:term"]

# -- autodoc (numpydoc style through napoleon) -------------------------------------------------
autodoc_typehints = "description"
autodoc_typehints_description_target = "documented_params"
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "show-inheritance": True, "no-value": True}
autodoc_preserve_defaults = True
autoclass_content = "class"
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_rtype = False
# numpydoc lets one entry describe several names (``x1, x2, y : number or str``).  As
# :param:/:ivar: fields Sphinx splits such a group: each parameter got the whole group's
# text, and an attribute group ``a, b`` read as "type a, name b".  Napoleon's own field
# lists keep a group one entry, as numpydoc shows it: "x1, x2, y (number or str) – ...".
# "Attributes" is laid out the same way (a field list, so dataclass fields are not
# described twice).
napoleon_use_param = False
napoleon_custom_sections = [("Attributes", "params_style")]

# -- the gallery -------------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "../gallery",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",
    "within_subsection_order": "FileNameSortKey",
    "matplotlib_animations": (True, "jshtml"),
    "image_scrapers": ("matplotlib",),
    "remove_config_comments": True,
    "abort_on_example_error": True,
    "write_computation_times": False,
    "show_signature": False,
    "capture_repr": ("_repr_html_", "__repr__"),
    # a block that ends in a drawing call must not print the artist's repr
    "ignore_repr_types": r"matplotlib|list|tuple|dict|NoneType",
    "min_reported_time": 1,
}


# -- pages generated at build time -------------------------------------------------------------
def _write(path: Path, text: str) -> None:
    """Write ``text`` unless the file already holds it (keeps incremental builds quiet)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


def _proof_report() -> None:
    """``graspcompass verify --markdown _generated/proof-report.md`` (about 5 s)."""
    from graspcompass.cli import main

    out = GENERATED / "proof-report.md"
    tmp = GENERATED / "proof-report.tmp.md"
    status = main(["verify", "--markdown", str(tmp), "--quiet"])
    text = tmp.read_text(encoding="utf-8")
    tmp.unlink()
    if status != 0:
        raise RuntimeError("graspcompass verify failed (an UNDECIDED claim, or a refuted "
                           "claim without a proved correction): see the proof report")
    _write(out, text)


# The paper's equations that paper.md gives a target ``(eq-N)=`` to.
_EQUATIONS = {int(n) for n in re.findall(r"^\(eq-(\d+)\)=$",
                                         (DOCS / "paper.md").read_text(encoding="utf-8"), re.M)}
_FIGURE_PAGES = {
    "2": "auto_examples/plot_01_fig2_grasp_and_friction_cones",
    "3": "auto_examples/plot_02_fig3_thales_circle",
    "4": "auto_examples/plot_03_fig4_drawing_V1_to_V4",
    "5": "auto_examples/plot_04_fig5_circles_and_envelope",
    "6": "auto_examples/plot_05_fig6_construction_vs_computer",
}


def link_reference(ref: str) -> str:
    """The paper reference of a protocol step as MyST, with links.

    Each equation number after ``eq.``/``eqs.`` links to its target in
    ``paper.md`` (``eq. (28)-(29)`` gives two links), ``Fig. 4(a)`` links to
    the gallery page of that figure; section numbers stay text.

    >>> link_reference("§3.3 V1 step (1), eq. (28)-(29)")
    '§3.3 V1 step (1), eq. {ref}`(28) <eq-28>`-{ref}`(29) <eq-29>`'
    """
    def number(m: re.Match[str]) -> str:
        n = int(m.group(1))
        return f"{{ref}}`({n}) <eq-{n}>`" if n in _EQUATIONS else m.group(0)

    def equations(m: re.Match[str]) -> str:
        return m.group(1) + re.sub(r"\((\d+)\)", number, m.group(2))

    def figure(m: re.Match[str]) -> str:
        page = _FIGURE_PAGES.get(m.group(1))
        return f"{{doc}}`{m.group(0)} </{page}>`" if page else m.group(0)

    out = re.sub(r"(eqs?\. )(\(\d+\)(?:[-–/, ]+\(\d+\))*)", equations, ref)
    return re.sub(r"Fig\. (\d)(\([a-d]\))?", figure, out)


def _steps_table() -> None:
    """The protocol of the Fig. 6 grasp as a Markdown table (construction page)."""
    from graspcompass import Grasp, internal_force_diagram
    from graspcompass.construction import describe

    c = internal_force_diagram(Grasp.preset("fig6"))
    rows = ["| # | object | instrument | what is drawn | paper | exact value |",
            "| --: | --- | --- | --- | --- | --- |"]
    for s in c.steps:
        value = describe(s.obj)
        if len(value) > 80:
            value = value[:77] + "…"
        cells = [str(s.index), f"`{s.name}`", s.instrument, _md(s.caption),
                 link_reference(s.ref), _md(value)]
        rows.append("| " + " | ".join(cells) + " |")
    _write(GENERATED / "fig6-steps.md", "\n".join(rows) + "\n")


def _md(text: str) -> str:
    """Plain text safe in a Markdown table cell."""
    return re.sub(r"([|*_`\\[\]<>])", r"\\\1", text)


def _main_job() -> None:
    """Run ``graspcompass`` in ``_generated/``; keep its files and an excerpt of its output
    (the givens, the drawing of V1 and the envelope)."""
    from graspcompass.cli import main

    buf = io.StringIO()
    here = os.getcwd()
    os.chdir(GENERATED)
    try:
        with contextlib.redirect_stdout(buf):
            status = main([])
    finally:
        os.chdir(here)
    if status != 0:
        raise RuntimeError("the main job `graspcompass` failed")
    keep, gap = [], False
    for line in buf.getvalue().rstrip().splitlines():
        row = re.match(r"(\d+) ", line)
        if row and int(row.group(1)) not in (0, 1, 2, 3, 4, 12, 13, 14, 15, 16, 17, 46):
            if not gap:
                keep.append("...")
            gap = True
            continue
        gap = False
        keep.append(line if len(line) < 150 else line[:147] + "...")
    _write(GENERATED / "main-job.txt", "\n".join(keep) + "\n")


def _explorer() -> None:
    """The web explorer of the Fig. 6 grasp: ``_static/explorer.html`` of the site."""
    from graspcompass import Grasp, internal_force_diagram
    from graspcompass.export.html import write_html

    write_html(internal_force_diagram(Grasp.preset("fig6")), EXPLORER_STATIC / "explorer.html")


# -- the animation players of the gallery ------------------------------------------------------
def _fix_animation_player(app: object, docname: str, source: list[str]) -> None:
    """Drop the CDN stylesheet of matplotlib's animation player from a gallery page (the
    icons come from ``_static/fontawesome/player.css``, on every page)."""
    if docname.startswith("auto_examples/"):
        source[0] = _FONT_AWESOME_LINK.sub("", source[0])


def _generate(app: object) -> None:
    GENERATED.mkdir(exist_ok=True)
    _proof_report()
    _steps_table()
    _main_job()
    _explorer()


# -- viewcode backlinks --------------------------------------------------------------------------
# sphinx.ext.viewcode keeps one module name per source module (the first page documenting
# one of its objects, e.g. ``graspcompass.geometry`` for a re-exported Point) and one page
# per object (the last documenting it, e.g. the package page, where its id is
# ``graspcompass.Point``): the "[docs]" link of the source page then points at an id that
# page does not have (33 broken anchors).  The module name of a source's links is the one
# under which most of its objects are documented, each backlink goes to a page documenting
# the object under it.  An object documented only under another module name keeps its
# block on the source page (the "[source]" link of its page points there: dropping it broke
# 9 of those links) and its backlink goes to a page documenting it, whose signature gets
# the id the backlink asks for as a second id.
def _documented(app: Any, doctree: Any) -> None:
    from sphinx import addnodes
    from sphinx.ext.viewcode import _get_full_modname

    env = app.env
    seen = env.__dict__.setdefault("_gc_documented", {})
    for sig in doctree.findall(addnodes.desc_signature):
        mod, full = sig.get("module"), sig.get("fullname")
        if not mod or not full or f"{mod}.{full}" not in sig.get("ids", []):
            continue  # a :no-index: entry has no id to link to
        src = _get_full_modname(mod, full) or mod
        seen.setdefault((src, full), {}).setdefault(mod, env.docname)


def _purge_documented(app: Any, env: Any, docname: str) -> None:
    for where in getattr(env, "_gc_documented", {}).values():
        for mod in [m for m, d in where.items() if d == docname]:
            del where[mod]


def _merge_documented(app: Any, env: Any, docnames: Any, other: Any) -> None:
    mine = env.__dict__.setdefault("_gc_documented", {})
    for key, where in getattr(other, "_gc_documented", {}).items():
        for mod, doc in where.items():
            mine.setdefault(key, {}).setdefault(mod, doc)


def _fix_backlinks(app: Any, env: Any) -> list[str]:
    """After every page is read: each source's module name and each object's backlink
    page; the pages that must carry a second id (``env._gc_alias``) are written again."""
    from collections import Counter

    seen = getattr(env, "_gc_documented", {})
    modules = getattr(env, "_viewcode_modules", {})
    alias: dict[str, set[tuple[str, str]]] = {}
    for src, entry in list(modules.items()):
        if not entry:
            continue
        code, tags, used, refname = entry
        # the module name under which most of the source's objects are documented
        votes = Counter(m for name in used for m in seen.get((src, name), {}))
        if votes:
            refname = max(votes, key=lambda m: (votes[m], m == src))
            modules[src] = (code, tags, used, refname)
        for name in list(used):
            where = seen.get((src, name), {})
            page = where.get(refname)
            if page is None and where:  # documented under other names only
                mod = min(where)
                page = where[mod]
                alias.setdefault(page, set()).add((f"{mod}.{name}", f"{refname}.{name}"))
            if page is not None:
                used[name] = page
            # else: no page has an id for it; viewcode's own page stays
    env._gc_alias = alias
    return sorted(alias)


def _alias_ids(app: Any, doctree: Any, docname: str) -> None:
    from sphinx import addnodes

    wanted = dict(getattr(app.env, "_gc_alias", {}).get(docname, ()))
    if not wanted:
        return
    for sig in doctree.findall(addnodes.desc_signature):
        for have in list(sig.get("ids", [])):
            if have in wanted and wanted[have] not in sig["ids"]:
                sig["ids"].append(wanted[have])


def setup(app: object) -> dict[str, object]:
    # the generated files are read later, with the other sources
    app.connect("builder-inited", _generate, priority=400)  # type: ignore[attr-defined]
    app.connect("source-read", _fix_animation_player)  # type: ignore[attr-defined]
    app.connect("doctree-read", _documented)  # type: ignore[attr-defined]
    app.connect("env-purge-doc", _purge_documented)  # type: ignore[attr-defined]
    app.connect("env-merge-info", _merge_documented)  # type: ignore[attr-defined]
    # after every page is read, before any is written (and before viewcode's own
    # html-collect-pages writes the source pages)
    app.connect("env-updated", _fix_backlinks)  # type: ignore[attr-defined]
    app.connect("doctree-resolved", _alias_ids)  # type: ignore[attr-defined]
    return {"parallel_read_safe": True, "parallel_write_safe": True}
