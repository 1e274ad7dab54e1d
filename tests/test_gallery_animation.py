"""Issue 23 (a): the gallery's construction animation embeds whole.

sphinx-gallery embeds the example's ``FuncAnimation`` by its ``to_jshtml()``
(``docs/conf.py``: ``"matplotlib_animations": (True, "jshtml")``), and matplotlib's
player drops every frame past ``rcParams["animation.embed_limit"]`` (with a logged
warning).  The example is run as the gallery runs it; the page's frames are counted in
the HTML itself (one ``frames[i] = …`` per frame of the player) against the timeline's.
"""

from __future__ import annotations

import logging
import re
import runpy
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import pytest
from PIL import Image

EXAMPLE = Path(__file__).parents[1] / "gallery" / "animations" / "plot_08_construction_animation.py"
#: the embedded page stays under half the limit: room for a longer recipe or larger text
MARGIN = 0.5


@pytest.fixture(scope="module")
def example():
    names = runpy.run_path(str(EXAMPLE), run_name="__main__")
    yield names
    plt.close("all")


def test_the_gallery_animation_embeds_every_frame_under_the_limit(example, caplog):
    anim = example["animation"]
    player = example["construction_animation"]  # what sphinx-gallery finds and embeds
    assert player is anim.animation
    limit = matplotlib.rcParams["animation.embed_limit"] * 1024 * 1024
    with caplog.at_level(logging.WARNING, logger="matplotlib.animation"):
        html = player.to_jshtml()
    assert not [r for r in caplog.records if "embed_limit" in r.getMessage()]
    assert len(html.encode()) < MARGIN * limit, len(html)
    # every frame of the timeline is in the player, in order, each an image or a
    # reference to an earlier image
    count = int(re.search(r"var frames = new Array\((\d+)\);", html).group(1))
    assert count == anim.timeline.frame_count
    assigned = [int(i) for i in re.findall(r"^\s*frames\[(\d+)\] = ", html, re.M)]
    assert assigned == list(range(count))
    images = {
        int(i) for i in re.findall(r'^\s*frames\[(\d+)\] = "data:image/png;base64,', html, re.M)
    }
    refs = [
        (int(i), int(k))
        for i, k in re.findall(r"^\s*frames\[(\d+)\] = frames\[(\d+)\]", html, re.M)
    ]
    assert len(images) + len(refs) == count
    assert all(k in images and k < i for i, k in refs)
    assert 0 in images


def test_the_embedded_frames_are_the_animation_s(example):
    """A stored image is the frame drawn in full (up to its 256 colours), and a reference
    stands for a frame equal to the image it names."""
    import base64
    import io

    import numpy as np

    anim = example["animation"]
    html = anim.animation.to_jshtml()
    data = dict(
        re.findall(r'^\s*frames\[(\d+)\] = "data:image/png;base64,([^"]*)"', html, re.M | re.S)
    )
    refs = dict(re.findall(r"^\s*frames\[(\d+)\] = frames\[(\d+)\]", html, re.M))
    step = anim.construction.step("V3").index
    f = anim.timeline.last_frame_of_step(step)
    shown = int(refs.get(str(f), f))
    png = base64.b64decode(data[str(shown)].replace("\\\n", ""))
    im = np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)
    full = anim.render(f).astype(int)
    assert im.shape == full.shape
    assert np.abs(im - full).mean() < 3.0  # palette rounding only
    # the caption is legible: at least 14 px text (the standard quality's rule) and each
    # step's caption on screen at least 2 s
    assert min(anim.caption_seconds_of_step(s.index) for s in anim.construction.steps) >= 2.0
    cap = anim._caption.get_fontsize() * anim.figure.dpi / 72
    assert cap >= 14.0


def test_the_gallery_thumbnail_gif_is_the_animation_scaled(example, tmp_path):
    """sphinx-gallery also saves the animation as a GIF at a thumbnail's dpi
    (``anim.save(path, writer=..., dpi=...)``): the player's own writer, every frame's
    time in the file, the size that dpi gives."""
    anim = example["animation"]
    out = tmp_path / "thumb.gif"
    anim.animation.save(out, writer="pillow", dpi=31)
    w, h = anim.figure.get_size_inches() * 31
    with Image.open(out) as im:
        assert im.size == (round(w), round(h))
        durations = []
        for i in range(im.n_frames):
            im.seek(i)
            durations.append(im.info["duration"])
    # a GIF keeps durations in hundredths of a second: each of its frames within 10 ms
    total = anim.frame_count * 1000 / anim.fps
    assert abs(sum(durations) - total) <= 10 * len(durations)
