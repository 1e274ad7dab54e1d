"""Step-by-step animation of the ruler-and-compass construction (§3.3, Figs. 3-5).

As in Manim, the drawn object (every artist of the finished construction, made
once by :func:`~graspcompass.render.draw_construction`), the
:class:`~graspcompass.render.timeline.Timeline` (pure data) and the animation
(which sets the artists for a frame from the two) are kept apart.  A ruler
line grows from its anchor point, a compass arc sweeps round, a point is
marked; the new element is highlighted, the earlier ones dimmed (those the
step uses stay bright); a caption gives the step's text and the paper's
reference; the animation pauses on each V_n (eq. (30)), each circle on O V_n
(eq. (31)) and the envelope (eq. (25)).  The geometry is only read; the same
input gives the same frames.  :class:`FrameAnimation` is the player shared
with :mod:`graspcompass.render.anim_physics`: it draws frames by blitting and
writes GIF, MP4 or HTML; in Jupyter an animation shows itself (``_repr_html_``).

The animation of the construction is made here; its parts are private modules,
every name still importable from here: the player (``_anim_player``), the
artists' states, dimming and highlighting (``_anim_ink``) and the layout of the
caption (``_anim_layout``).

Examples
--------
>>> from graspcompass import Grasp, internal_force_diagram
>>> c = internal_force_diagram(Grasp.preset("table1a"))
>>> anim = animate_construction(c, frames_per_step=2, pause_frames=1, hold_frames=1,
...                             caption_seconds=0)
>>> anim.frame_count == 2 * len(c.steps) + 9 + 1
True

By default each step's caption stays at least 2 s (the drawing, then a rest):

>>> anim = animate_construction(c, frames_per_step=2, pause_frames=1, hold_frames=1)
>>> tl = anim.timeline
>>> min(sum(len(tl.segment_range(i)) for i, s in enumerate(tl.segments)
...         if s.step == k and s.kind in ("draw", "rest"))
...     for k in range(len(c.steps))) / anim.fps
2.0
>>> print(anim.caption_at(anim.timeline.frames_of_step(13)[0]))
Step 13 of 0–46 · perpendicular
§3.3 $V_1$ (2): perpendicular from $P_{2x}$ to the upper side of the cone at $P_1$
"""

from __future__ import annotations

import textwrap
from typing import TYPE_CHECKING, Any

from matplotlib.artist import Artist
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch, Rectangle
from matplotlib.text import Annotation, Text

from ..scene import labelling
from ..scene.layout import numeric_objects
from ..scene.picture import scene_of
from ._anim_apply import _ApplyFrames
from ._anim_camera import camera_box, step_boxes, zoomed
from ._anim_frames import _CameraFrames
from ._anim_ink import _inks, _quality, _snap, dim_alpha
from ._anim_labels import ViewLabels
from ._anim_layout import _layout, _mathtext, _shown, _text_width, _wrap  # noqa: F401
from ._anim_panel import SidePanel
from ._anim_player import FrameAnimation
from ._figure_parts import box_patch
from .figure import draw_construction
from .theme import DEFAULT_THEME, MIN_CONTRAST, Quality, Theme
from .timeline import Timeline, check_fps, reading_frames, save_frames

if TYPE_CHECKING:
    from ..construction.protocol import Construction, Step

__all__ = [
    "AX_RECT",
    "ConstructionAnimation",
    "FrameAnimation",
    "animate_construction",
    "dim_alpha",
    "save_frames",
]

#: Where the diagram axes start (figure fraction); the layout then moves them so that the
#: longest caption fits below (``standard``) or beside (``lecture``) the diagram.
AX_RECT = (0.1, 0.2, 0.86, 0.72)


class ConstructionAnimation(_ApplyFrames, _CameraFrames, FrameAnimation):
    """The construction of §3.3 replayed step by step; see :func:`animate_construction`."""

    # set by ``_layout`` (render/_anim_layout.py)
    layout: str
    _bar: Rectangle
    _caption: Text
    _title: Text
    _wrapped: list[str]
    _hold_wrapped: str
    _inset_wrapped: str
    _fade_region: Any  # a numpy index of the rows (or columns) that fade
    _panel_box: tuple[float, ...] | None  # the side panel in pixels (see _anim_panel.py)

    def __init__(
        self,
        construction: Construction,
        fps: float | None = None,
        frames_per_step: int | None = None,
        pause_frames: int | None = None,
        hold_frames: int | None = None,
        theme: Theme = DEFAULT_THEME,
        figsize: tuple[float, float] | None = None,
        dpi: float | None = None,
        labels: bool = True,
        rate: str = "smoothstep",
        dim: float = 0.3,
        quality: str | Quality = "standard",
        caption_seconds: float | None = None,
        reading_rate: float | None = None,
        camera: bool | None = None,
        title_seconds: float | None = None,
        min_text_px: float | None = None,
        inset_seconds: float | None = None,
        break_points: bool = False,
    ) -> None:
        q = self.quality = _quality(quality)
        self.camera = q.camera if camera is None else bool(camera)
        fps = check_fps(q.fps if fps is None else fps)
        fpstep = q.frames_per_step if frames_per_step is None else frames_per_step
        pause = q.frames(q.pause_seconds, fps) if pause_frames is None else pause_frames
        hold = q.frames(q.hold_seconds, fps) if hold_frames is None else hold_frames
        figsize = q.figsize if figsize is None else figsize
        dpi = q.dpi if dpi is None else dpi
        self.caption_seconds = q.caption_seconds if caption_seconds is None else caption_seconds
        self.reading_rate = q.reading_rate if reading_rate is None else reading_rate
        caption_pt = q.caption_size * theme.font_size / DEFAULT_THEME.font_size
        theme = theme.scaled(q.scale) if q.scale != 1 else theme
        # every text at least q.min_text_px pixels high at this dpi (labels, captions, ticks)
        least_px = q.min_text_px if min_text_px is None else float(min_text_px)
        self._least_pt = least_px * 72.0 / float(dpi)
        caption_pt = max(caption_pt, self._least_pt)
        theme = theme.with_(font_size=max(theme.font_size, self._least_pt))
        self.construction, self.theme, self.dim = construction, theme, float(dim)
        steps = construction.steps
        self._texts = [_mathtext(self._caption_text(s)) for s in steps]  # typeset
        self._hold_text = _mathtext(self._caption_text(None))
        self._inset_text = _mathtext(
            "Zoom on the dashed square: the points that crowd there, each named"
        )
        least = None
        if self.caption_seconds > 0 or self.reading_rate > 0:
            # paced by step: a key step rests on its result after its caption is read
            least = [
                reading_frames(_shown(t), fps, self.caption_seconds, self.reading_rate)
                + (pause if s.key else 0)
                for t, s in zip(self._texts, steps)
            ]
            if hold:
                hold = max(
                    hold,
                    reading_frames(
                        _shown(self._hold_text), fps, self.caption_seconds, self.reading_rate
                    ),
                )
        title = q.title_seconds if title_seconds is None else float(title_seconds)
        timeline = Timeline.from_keys(
            [s.key for s in steps],
            fpstep,
            pause,
            hold,
            rate,
            least_frames=least,
            title_frames=q.frames(title, fps),
        )
        super().__init__(Figure(figsize=figsize, dpi=dpi), timeline, fps)
        fig = self.figure
        self.axes = ax = fig.add_axes(AX_RECT)
        _layout(self, q.layout, caption_pt)
        # the labels are the views' own (render/_anim_labels.py): placed for each view
        self.artists = arts = draw_construction(
            construction, ax=ax, theme=theme, labels=False, break_points=break_points
        )
        ax.tick_params(labelsize=max(theme.font_size * 0.7, self._least_pt))
        self._num = numeric_objects(construction)
        box = scene_of(construction).box
        self._whole = (box[0], box[1], box[2], box[3])
        self._boxes = step_boxes(
            construction, self._num, self._whole, scene_of(construction).instruments
        )
        if self.camera:  # a zoomed view shows only what is inside it
            for t in ax.texts:
                if isinstance(t, Annotation):
                    t.set_annotation_clip(True)
                    t.set_clip_on(True)
                    if t.arrow_patch is not None:
                        t.arrow_patch.set_clip_box(ax.bbox)
                        t.arrow_patch.set_clip_on(True)
        self._card = fig.text(
            0.5,
            0.5,
            self._card_text(),
            ha="center",
            va="center",
            fontsize=caption_pt * 1.3,
            linespacing=1.6,
            visible=False,
            zorder=20,
            bbox=dict(boxstyle="square,pad=40", fc="white", ec="none"),
        )
        self._items: list[list[tuple[Artist, str, dict[str, Any]]]] = [[] for _ in steps]
        seen: set[int] = set()
        made = scene_of(construction).made
        for cone in ("cone1", "cone2"):  # a friction cone appears once both its sides exist
            if cone in arts and cone in made:
                seen.update(id(a) for a in arts[cone])
                self._items[made[cone]] += [(a, "cone", _snap(a)) for a in arts[cone]]
        for s in steps:  # each artist belongs to the first step naming it
            for a in arts.get(s.name, []):
                if id(a) in seen:
                    continue
                seen.add(id(a))
                self._items[s.index].append((a, self._role(a, s), _snap(a)))
        frame_pt = ax.bbox.width * 72.0 / fig.dpi
        self._views: ViewLabels | None = None
        if labels:
            n = len(steps)
            self._views = ViewLabels(
                construction,
                ax,
                theme,
                self._boxes if self.camera else [self._whole] * n,
                self._whole,
                self._num,
                theme.font_size * labelling.FRAME_PT / frame_pt,
                frame_pt / labelling.FRAME_PT,
                zoom=self.camera,
                dim=self.dim,
                break_points=break_points,
            )
            self._boxes = self._views.boxes
            for lab in self._views.labels:  # by name, as draw_construction's labels are
                for nm in {steps[i].name for i, _ in lab.parts}:
                    arts.setdefault(nm, []).extend(
                        a for a in (lab.text, lab.leader) if a is not None
                    )
        # after the hold, a zoom on each crowd of points the whole view cannot name, each
        # marked by a dashed square in the hold
        self._zooms = [] if self._views is None else self._views.zoom_boxes
        self._zoom_frames = [
            ax.add_patch(
                box_patch(
                    z, fill=False, ls=(0, (4, 3)), lw=0.8, ec="0.35", zorder=5.8, visible=False
                )
            )
            for z in self._zooms
        ]
        each = q.frames(q.inset_seconds if inset_seconds is None else inset_seconds, fps)
        for _ in self._zooms if each > 0 else ():
            self.timeline = self.timeline.with_inset(each)
        #: segment index -> the final zoom it shows
        self._zoom_of = {
            i: k
            for k, i in enumerate(
                i for i, seg in enumerate(self.timeline.segments) if seg.kind == "inset"
            )
        }
        bg = ax.get_facecolor()
        self._dimf = [
            dim_alpha(
                _inks(a, sn), bg, MIN_CONTRAST["text" if r == "label" else "graphics"], self.dim
            )
            if r not in ("fill", "cone")
            else self.dim
            for items in self._items
            for a, r, sn in items
        ]
        hl, thin = theme.highlight_color, theme.thin_width
        self._aid = ax.plot([], [], color=hl, lw=thin * 1.5, ls=(0, (3, 2)), zorder=6)[0]
        self._arc = ax.plot([], [], color=hl, zorder=6)[0]
        self._arm = ax.plot(
            [],
            [],
            color=hl,
            lw=thin * 1.5,
            marker="o",
            ms=theme.point_size * 0.75,
            markevery=[0],
            zorder=6.5,
        )[0]
        self._halo = ax.plot([], [], "o", mfc="none", mec=hl, zorder=7)[0]
        self._aids = (self._aid, self._arc, self._arm, self._halo)
        self._keys: list[Any] = [None] * len(self._dimf)
        self._layer: tuple[Any, int, Any] | None = None
        self._dynamic = [a for items in self._items for a, _, _ in items]
        self._dynamic += [] if self._views is None else self._views.artists
        self._dynamic += [*self._aids, *self._zoom_frames, self._caption, self._bar, self._card]
        side = self._panel_box  # the side panel (lecture): what is made so far, k_grasp(θ)
        self._panel = None if side is None else SidePanel(self, side, self._least_pt)
        self._dynamic += [] if self._panel is None else self._panel.artists

    def _card_text(self) -> str:
        g = self.construction.grasp
        head = "\n".join(textwrap.wrap(getattr(g, "title", None) or "", 56))
        return (
            "The internal force diagram\nby ruler and compass\n\n"
            + (head + "\n\n" if head else "")
            + "Ito, Tanaka and Sasaki, Robotica 2012, §3.3"
        )

    @staticmethod
    def _role(a: Artist, s: Step) -> str:
        if (a.get_gid() or "").startswith("instrument:"):
            return "instrument"
        if isinstance(a, Annotation) and a.arrow_patch is not None:
            return "arrow"
        if isinstance(a, Text):
            return "label"
        if isinstance(a, Patch):
            return "circle" if s.kind == "circle" else "fill"
        if s.kind == "envelope":
            return "trace"
        solid = not isinstance(a, Line2D) or a.get_linestyle() != "None"
        return "line" if s.kind == "line" and solid else "marker"

    # -- captions -----------------------------------------------------------------------------
    def _caption_text(self, s: Step | None) -> str:
        """Head and body of a step's caption (``None``: the final hold), not yet wrapped.

        The step numbers are the protocol's (``graspcompass steps``): 0 to len − 1.
        """
        if s is None:
            return (
                "The internal force diagram (Fig. 5)\nin the direction e(θ) of the "
                "external force, the distance from O to the envelope is k_grasp(θ), "
                "eq. (25); F_int = k_grasp/(x1 + x2)·F_e, eq. (17)"
            )
        last = len(self.construction.steps) - 1
        text = s.caption[0].lower() + s.caption[1:] if s.caption[1:2].islower() else s.caption
        return (
            f"Step {s.index} of 0–{last} · {s.instrument}\n{s.ref.replace(' step ', ' ')}: {text}"
        )

    def caption_at(self, frame: int) -> str:
        """The caption of ``frame`` as shown: the step's number in the protocol (as
        ``graspcompass steps`` prints it), the instrument, the paper's reference, the text."""
        st = self.timeline.at(frame)
        if st.kind == "inset":  # the zoom's, for the whole zoom: each caption shown long
            return self._inset_wrapped
        return self._hold_wrapped if st.kind in ("hold", "inset") else self._wrapped[st.step]

    def caption_seconds_of_step(self, step: int) -> float:
        """How long the caption of ``step`` is on screen, in seconds at :attr:`fps`."""
        return self.timeline.seconds_of_step(step, self.fps)

    def key_frames(self) -> list[tuple[int, str]]:
        """The frame at the end of each protocol step, named ``step-NN-name``."""
        return [
            (self.timeline.last_frame_of_step(s.index), f"step-{s.index:02d}-{s.name}")
            for s in self.construction.steps
        ]

    # -- frames -------------------------------------------------------------------------------
    def _movers(self, segment: int) -> list[Artist]:
        step = self.timeline.segments[segment].step
        return (
            [a for a, _, _ in self._items[step]]
            + ([] if self._views is None else self._views.movers(step))
            + [*self._aids, self._bar]
            + ([] if self._panel is None else self._panel.movers(step))
        )

    def _group_key(self, segment: int) -> Any:
        seg = self.timeline.segments[segment]
        return (seg.step, seg.kind) if seg.kind in ("hold", "inset") else seg.step

    def _crossfade(self, segment: int) -> Any:
        """The final hold: the elements fade back to their colours, the caption does not."""
        if self.timeline.segments[segment].kind != "hold":
            return None
        return self._fade_region

    def _zoom_state(self, st: Any) -> tuple[Any, bool]:
        """The camera's box and whether the zoom's labels show, at a frame of a final zoom."""
        z = self._zooms[self._zoom_of[st.segment]]
        return camera_box(self._boxes, self._whole, st.step, "inset", st.raw, z), zoomed(st.raw)

    def _still(self, frame: int) -> bool:
        st = self.timeline.at(frame)
        if st.kind == "inset" and frame > 0:  # the camera resting on a crowd
            before = self.timeline.at(frame - 1)
            return before.segment == st.segment and self._zoom_state(st) == self._zoom_state(before)
        return st.kind == "rest" or (st.kind == "title" and frame > 0)


def animate_construction(
    construction: Construction,
    fps: float | None = None,
    frames_per_step: int | None = None,
    pause_frames: int | None = None,
    hold_frames: int | None = None,
    theme: Theme = DEFAULT_THEME,
    figsize: tuple[float, float] | None = None,
    dpi: float | None = None,
    labels: bool = True,
    rate: str = "smoothstep",
    quality: str | Quality = "standard",
    caption_seconds: float | None = None,
    reading_rate: float | None = None,
    camera: bool | None = None,
    title_seconds: float | None = None,
    min_text_px: float | None = None,
    inset_seconds: float | None = None,
    break_points: bool = False,
) -> ConstructionAnimation:
    """Animate the ruler-and-compass drawing of the internal force diagram (§3.3).

    Every value left out (None) comes from ``quality`` (:data:`~.theme.QUALITIES`):
    ``"standard"`` is 640 × 720 pixels, 10 fps, 8 frames per step, the caption
    below the diagram, every text at least 14 pixels high, each caption on
    screen at least 2 s, lines and labels 1.3 × larger; ``"lecture"`` is for a
    projector: 1280 × 720 pixels, 15 fps, a title card, the caption at 20 pt in
    a panel right of the diagram (with what is made so far and, from the
    envelope on, the plot of k_grasp(θ)), lines and labels 1.6 × larger, each
    step's caption on screen at least 2.5 s and longer by its length (15
    characters a second), a key step 3 s longer.

    Parameters
    ----------
    construction : Construction
        From :func:`graspcompass.internal_force_diagram` with numbers; only read.
    fps : float
        Frames per second of the saved files.
    frames_per_step, pause_frames, hold_frames : int
        Frames drawing each step; resting on each key result (V_n, eq. (30);
        the circles on O V_n, eq. (31), Fig. 3; the envelope, eq. (25),
        Fig. 5); and holding the finished diagram, into which the dimmed
        elements fade back: the last frame is the static figure of
        :func:`~graspcompass.render.draw_construction`.
    theme, figsize, dpi, labels
        Style, size in inches, resolution, point labels on or off.
    rate : {"smoothstep", "linear", "smootherstep"}
        Easing of the drawing.
    quality : {"standard", "lecture"} or Quality
        The preset of the values left out.
    caption_seconds, reading_rate : float
        Each step lasts until its caption has been on screen ``caption_seconds``
        and ``len(caption) / reading_rate`` seconds (the rest is a still frame);
        0 turns a rule off.
    camera : bool
        The view follows the step being drawn (``render/_anim_camera.py``): it zooms
        in on a step near O (X3, Y3, V3 of Fig. 6) and out for a far one (V1); the
        whole diagram in the final hold.
    title_seconds : float
        A title card this long before the first step (0: none; lecture: 4 s).
    min_text_px : float
        Every text (captions, labels, ticks, title) at least this many pixels high at
        the frame's ``dpi`` (default 14; 0: the theme's sizes as they are).
    inset_seconds : float
        With the camera, where points crowd (the static figure's inset,
        :attr:`graspcompass.scene.picture.Scene.inset`): after the hold the camera zooms
        on that region, marked by a dashed square, names every point in it and comes
        back, for this long (standard 5 s, lecture 8 s; 0: no zoom).
    break_points : bool
        Each break point (steps ``B12`` to ``B34``) is named at its own step; with
        ``break_points`` the finished diagram names those on the envelope too (where
        k_grasp passes from one circle to the next), as ``draw --break-points``.

    Returns
    -------
    ConstructionAnimation
        With ``.save(path)``, ``.to_html()``, ``.frame_count``, ``.timeline``,
        ``.figure``, ``.caption_at(frame)``, ``.caption_seconds_of_step(step)``
        and ``_repr_html_``.

    Notes
    -----
    The step numbers of the captions are the protocol's, as ``graspcompass
    steps`` prints them (0 to len − 1).  A label shared by coincident points
    (``O = O_M = Y_4``) names only the points made so far.  The labels are placed
    for each view of the camera at the size they are drawn, by the rules of every
    picture (none over another label or a marker, each nearer its own point than
    any other: ``render/_anim_labels.py``); one that finds no such place in its view
    shows only while its point is the new object.  The earlier steps are
    dimmed to at most ``dim`` opacity, but each keeps a contrast of 3 : 1 (lines,
    markers) or 4.5 : 1 (labels) against the background (:data:`~.theme.MIN_CONTRAST`).
    """
    return ConstructionAnimation(
        construction,
        fps=fps,
        frames_per_step=frames_per_step,
        pause_frames=pause_frames,
        hold_frames=hold_frames,
        theme=theme,
        figsize=figsize,
        dpi=dpi,
        labels=labels,
        rate=rate,
        quality=quality,
        caption_seconds=caption_seconds,
        reading_rate=reading_rate,
        camera=camera,
        title_seconds=title_seconds,
        min_text_px=min_text_px,
        inset_seconds=inset_seconds,
        break_points=break_points,
    )
