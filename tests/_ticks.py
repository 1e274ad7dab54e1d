"""The axes' numbers measured in a browser: they give way to the points' labels and markers.

On a phone (390×844), and at 1280×800 too, the tick numbers of the web page's axes stood
over point labels and markers (Fig. 6: "−1" over the label and the marker of P2x, "−2"
over X2's), at every step of the protocol: the label rules did not know the ticks.  A tick
number now gives way (is hidden) where it would come within 3 px of a shown label or
marker, and only there.  Measured from the browser's own layout (``getBoundingClientRect``
of the JSXGraph tick labels, point markers and labels, and ``getComputedStyle``), not from
the page's numbers; tests/test_web_inset.py checks it at the steps it visits.
"""

from __future__ import annotations

from typing import Any

from _label_rules import overlap

#: How near (px) a shown tick number may come to a label or marker: two texts closer than
#: this read as one ("−1P2x"); the page's labels keep the same space between themselves.
SPACE = 3.0

#: Every tick number JSXGraph draws on the board now (its rectangle, whether the browser
#: shows it), and every point shown on the board in view (its marker's rectangle, its
#: label's when one is shown).
#: JavaScript: ``b`` the board, ``rect`` an element's client rectangle, ``seen`` whether the
#: browser shows it, ``box`` the board's rectangle (the measures of this module and of
#: tests/test_web_inset.py).
BOARD_JS = """  const b = graspcompass.board;
  const rect = (n) => { const r = n.getBoundingClientRect(); return [r.left, r.top, r.right,
    r.bottom]; };
  const drawn = (n) => n && n.isConnected && n.getAttribute('display') !== 'none' &&
    getComputedStyle(n).display !== 'none';
  const seen = (n) => drawn(n) && getComputedStyle(n).visibility !== 'hidden';
  const box = rect(b.containerObj);
"""

#: JavaScript: ``pts``, every point shown on the board in view: its id and name, its
#: marker's rectangle, its label's (null: none shown) and the label's text.
POINTS_JS = """  const pts = [];
  for (const el of b.objectsList) {
    if (el.elType !== 'point' || !el.visPropCalc.visible || !seen(el.rendNode)) continue;
    const m = rect(el.rendNode);
    const cx = (m[0] + m[2]) / 2, cy = (m[1] + m[3]) / 2;
    if (cx < box[0] || cx > box[2] || cy < box[1] || cy > box[3]) continue;
    const l = el.label;
    const on = l && l.visPropCalc.visible && seen(l.rendNode) && l.rendNode.textContent.trim();
    pts.push({id: el.id, name: el.name, m, t: on ? rect(l.rendNode) : null,
      text: on ? l.rendNode.textContent : null});
  }
"""

MEASURE_TICKS = (
    "() => {\n"
    + BOARD_JS
    + """  const ticks = [];
  for (const el of b.objectsList) {
    if (el.elType !== 'ticks') continue;
    for (const l of el.labels || []) {
      if (!l || !l.visPropCalc.visible || !drawn(l.rendNode)) continue;
      if (!l.rendNode.textContent.trim()) continue;
      const r = rect(l.rendNode);
      if (r[2] < box[0] || r[0] > box[2] || r[3] < box[1] || r[1] > box[3]) continue;
      ticks.push({text: l.rendNode.textContent, r, shown: seen(l.rendNode),
        axis: el.line.name || el.line.id});
    }
  }
"""
    + POINTS_JS
    + """  return {step: graspcompass.get('step'), ticks, pts};
}"""
)


def _grow(r: list[float], d: float) -> list[float]:
    return [r[0] - d, r[1] - d, r[2] + d, r[3] + d]


def tick_faults(states: list[dict[str, Any]], where: str) -> list[str]:
    """Every shown tick number over a shown label or marker, and every hidden one that had
    no label or marker within SPACE px (a tick that gave way without cause)."""
    bad = []
    for st in states:
        at = f"{where} step {st['step']}"
        things = [(f"label of {p['name']}", p["t"]) for p in st["pts"] if p["t"] is not None]
        things += [(f"marker of {p['name']}", p["m"]) for p in st["pts"]]
        for t in st["ticks"]:
            if t["shown"]:
                bad += [
                    f"{at}: tick {t['text']} over the {n}" for n, r in things if overlap(t["r"], r)
                ]
            elif not any(overlap(_grow(t["r"], SPACE + 0.5), r) for _, r in things):
                bad.append(f"{at}: tick {t['text']} hidden with nothing near it")
    return bad
