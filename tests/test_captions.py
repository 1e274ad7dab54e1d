"""Issue 23: the captions of the construction animation typeset as mathtext.

For every step's caption of the presets and of a random grasp, in the ``lecture``
(side panel) and ``standard`` (below) layouts: no ``_`` outside a formula ``$…$``,
the ``$`` balanced on every line (so no formula is broken across lines), each formula
parsed by matplotlib's mathtext, and the caption as drawn (its bounding box from the
renderer, not from the wrapping's own measure) inside its panel.  The frames are small
(low dpi) so that the file stays fast.
"""

from __future__ import annotations

import random
import re

import matplotlib

matplotlib.use("Agg")

import pytest
from matplotlib.mathtext import MathTextParser

from graspcompass import Grasp, internal_force_diagram
from graspcompass.presets import PRESETS
from graspcompass.render._anim_layout import _mathtext, _wrap
from graspcompass.render.animate import animate_construction


def _random_grasp(seed: int) -> Grasp:
    """A grasp drawn as in tests/test_made_before.py: each cone holds the normal."""
    rnd = random.Random(seed)

    def angle() -> tuple[int, int]:
        phi = rnd.randint(20, 160)
        return phi, rnd.randint(abs(phi - 90) + 2, 85)

    (p1, k1), (p2, k2) = angle(), angle()
    x1, x2, y = rnd.randint(10, 200) / 100, rnd.randint(10, 200) / 100, rnd.randint(0, 150) / 100
    return Grasp(x1, x2, y, f"{p1}*pi/180", f"{p2}*pi/180", xi1=f"{k1}*pi/180", xi2=f"{k2}*pi/180")


GRASPS = {name: Grasp.preset(name) for name in PRESETS} | {"random": _random_grasp(23)}
#: (quality, figsize, dpi): the presets' frames at a third of their resolution (the
#: text is as many points; the 14 px rule is not what this file checks)
LAYOUTS = {"lecture": ((12.8, 7.2), 30), "standard": ((8.0, 9.0), 27)}
_PARSER = MathTextParser("path")


def _formulas(line: str) -> list[str]:
    return re.findall(r"(?<!\\)\$([^$]*)\$", line)


def _outside(line: str) -> str:
    return re.sub(r"(?<!\\)\$[^$]*\$", "", line)


@pytest.fixture(scope="module", params=sorted(GRASPS))
def construction(request):
    return internal_force_diagram(GRASPS[request.param])


@pytest.mark.parametrize("quality", sorted(LAYOUTS))
def test_captions_are_typeset_whole_and_fit_their_panel(construction, quality) -> None:
    figsize, dpi = LAYOUTS[quality]
    anim = animate_construction(
        construction,
        quality=quality,
        figsize=figsize,
        dpi=dpi,
        min_text_px=0,
        camera=False,
        frames_per_step=1,
        pause_frames=0,
        hold_frames=1,
        caption_seconds=0,
        reading_rate=0,
    )
    fig = anim.figure
    w, h = fig.get_size_inches() * fig.dpi
    renderer = anim._canvas.get_renderer()
    anim._apply(0)
    axes_box = anim.axes.get_tightbbox(renderer)  # with the tick labels
    tl = anim.timeline
    frames = [tl.frames_of_step(s.index)[0] for s in construction.steps]
    frames.append(next(f for f in range(anim.frame_count) if tl.at(f).kind == "hold"))
    for f in frames:
        text = anim.caption_at(f)
        for line in text.split("\n"):
            dollars = line.count("$") - line.count(r"\$")
            assert dollars % 2 == 0, (f, line)  # no formula runs over a line break
            assert "_" not in _outside(line), (f, line)
            for formula in _formulas(line):
                _PARSER.parse(f"${formula}$")  # valid mathtext (raises otherwise)
        # the names of the points are typeset: no plain P1, X1, O_M, V1 in the text
        assert not re.search(r"\b[PXYVBCS]\d", _outside(text).replace("§", " ")), (f, text)
        anim._caption.set_text(text)
        box = anim._caption.get_window_extent(renderer)
        assert 0 <= box.x0 and box.y0 >= 0 and box.y1 <= h, (f, box)
        if anim.layout == "side":  # the panel: right of the diagram, inside the margin
            assert box.x0 >= axes_box.x1 and box.x1 <= w - 0.02 * w, (f, box, axes_box)
        else:  # the band: below the diagram's tick labels, above the progress bar
            assert box.x1 <= w - 0.02 * w, (f, box)
            assert box.y1 <= axes_box.y0 and box.y0 >= anim._bar.get_height() * h, (f, box)


def test_formulas_are_whole_at_any_width() -> None:
    """Wrapped as narrow as one word a line, a formula still stays on one line."""
    text = _mathtext("Plot V1 = (−O_M X1, −O Y1) and F_int = k_grasp/(x1 + x2)·F_e")
    lines = _wrap(text, 1.0, len).split("\n")
    assert lines == [
        "Plot",
        r"$V_1 = ({-}O_M\ X_1, {-}O\ Y_1)$",
        "and",
        r"$F_\mathrm{int} = k_\mathrm{grasp}/(x_1 + x_2)\cdot F_e$",
    ]


@pytest.mark.parametrize(
    ("plain", "typeset"),
    [
        ("Signed length O_M X1 = −S1", r"Signed length $O_M\ X_1 = {-}S_1$"),
        ("Contact point P2 = (−x2, y)", r"Contact point $P_2 = ({-}x_2, y)$"),
        ("the polar graph of k_grasp(θ)", r"the polar graph of $k_\mathrm{grasp}(\theta)$"),
        ("Step 10 of 0–46 · perpendicular", "Step 10 of 0–46 · perpendicular"),
        ("costs $5 here", "costs $5 here"),  # no formula: the text as it is
        ("costs $5 at P1", r"costs \$5 at $P_1$"),  # a dollar of the prose escaped
        ("a Fig. 4(a) ref", "a Fig.\u00a04(a) ref"),  # a reference and its number together
    ],
)
def test_mathtext_of_a_caption(plain: str, typeset: str) -> None:
    assert _mathtext(plain) == typeset
