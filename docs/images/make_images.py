"""Make the screenshots of docs/images again, as a user gets them (issue 23).

Each picture is made by the command or the call a user would run, at the size the user
gets; the web pages are shot in headless Chromium (Playwright) at 1280x800 and 390x844.
Look at every one of them before committing.

Run:  python docs/images/make_images.py [NAME ...]     (default: all)
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

HERE = Path(__file__).resolve().parent
OWN = "--x1 1.2 --x2 0.3 --y 0.4 --phi1 61deg --phi2 118deg --xi1 67deg --xi2 49deg".split()


def _run(*argv: str, cwd: Path | None = None) -> None:
    subprocess.run([sys.executable, "-m", "graspcompass", *argv], check=True, cwd=cwd)


def fig6_diagram(tmp: Path) -> None:
    """The main job's picture (README, docs index): ``graspcompass`` in an empty folder."""
    _run(cwd=tmp)
    shutil.copy(tmp / "graspcompass-out" / "fig6-diagram.png", HERE / "fig6-diagram.png")


def inset_own_grasp(tmp: Path) -> None:
    """A grasp of one's own with its zoomed inset (README)."""
    _run("draw", *OWN, "-o", str(HERE / "inset-own-grasp.png"), "-q")


def worksheet(tmp: Path) -> None:
    """The two pages of ``graspcompass worksheet`` (docs/howto/draw-by-hand.md), 70 dpi."""
    pdf = tmp / "worksheet.pdf"
    _run("worksheet", "-o", str(pdf), "-q")
    subprocess.run(["pdftoppm", "-r", "70", "-png", str(pdf), str(tmp / "ws")], check=True)
    shutil.copy(tmp / "ws-1.png", HERE / "worksheet-fig6.png")
    shutil.copy(tmp / "ws-2.png", HERE / "worksheet-fig6-solution.png")


def lecture_frame(tmp: Path) -> None:
    """Frames of the lecture video (1280x720): the end of the circle on O V4, the zoom on the
    crowded centre after the hold, and the last."""
    import matplotlib.pyplot as plt

    import graspcompass as gc
    from graspcompass.render import animate_construction

    c = gc.internal_force_diagram(gc.Grasp.preset("fig6"))
    anim = animate_construction(c, quality="lecture")
    tl = anim.timeline
    zoom = next(tl.segment_range(i) for i, s in enumerate(tl.segments) if s.kind == "inset")
    frames = {
        "lecture-frame.png": tl.last_frame_of_step(c.step("circle4").index),
        "lecture-zoom.png": zoom[len(zoom) // 2],  # resting on the crowded centre
        "lecture-final.png": anim.frame_count - 1,
    }
    for name, frame in frames.items():
        plt.imsave(HERE / name, anim.render(frame))


def web(tmp: Path) -> None:
    """The web page of Fig. 6 as it opens and at its last step, at 1280x800 and on a phone
    (390x844; the last step scrolled to the board, its inset below it)."""
    from playwright.sync_api import sync_playwright

    page_path = tmp / "fig6.html"
    _run("export", "--format", "html", "-o", str(page_path), "-q")
    exe = shutil.which("chromium") or shutil.which("chromium-browser")
    shots = (
        ((1280, 800), False, "web-explorer.png"),
        ((390, 844), False, "web-explorer-phone.png"),
        ((1280, 800), True, "web-1280x800.png"),
        ((390, 844), True, "web-390x844.png"),
    )
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=exe, args=["--no-sandbox"])
        for (w, h), last, name in shots:
            page = browser.new_page(viewport={"width": w, "height": h})
            page.goto(page_path.as_uri())
            page.wait_for_selector("body[data-ready='1']", timeout=20_000)
            if last:
                page.click("#gc-fit")
                page.evaluate("graspcompass.step(0)")  # the page opens at its last step
                page.click("#gc-last")
                if w < 600:
                    page.evaluate("document.querySelector('.jxgbox').scrollIntoView()")
            page.screenshot(path=str(HERE / name))
            page.close()
        browser.close()


def matplotlib_explorer(tmp: Path) -> None:
    """The matplotlib explorer of Fig. 6 (docs/explore.md), as ``graspcompass explore``
    opens it (11 x 7.5 in), at 80 dpi."""
    from matplotlib.figure import Figure

    import graspcompass as gc
    from graspcompass.render.explorer import Explorer

    ex = Explorer(gc.Grasp.preset("fig6"), fig=Figure(figsize=(11, 7.5), dpi=80))
    ex.fig.savefig(HERE / "matplotlib-explorer.png", dpi=80)


MAKERS: dict[str, Callable[[Path], None]] = {
    "fig6-diagram": fig6_diagram,
    "inset-own-grasp": inset_own_grasp,
    "worksheet": worksheet,
    "lecture": lecture_frame,
    "web": web,
    "matplotlib-explorer": matplotlib_explorer,
}


def main() -> None:
    names = sys.argv[1:] or list(MAKERS)
    for name in names:
        with tempfile.TemporaryDirectory() as tmp:
            print(f"{name} ...", flush=True)
            MAKERS[name](Path(tmp))


if __name__ == "__main__":
    main()
