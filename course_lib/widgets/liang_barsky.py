r"""Liang-Barsky visualizer: the entering and leaving parameters t of the four sides on a number
line, and the interval [t_in, t_out] shrinking side by side, while the student drags the
segment's end points."""
from dataclasses import dataclass, field

import numpy as np

from .. import clipping, draw, format as fmt
from . import _style
from ._clip2d import BOX_MAX, BOX_MIN, LIMITS, StepExplorer
from ._drag import pseudocode_html

__all__ = ["LiangBarskyExplorer", "PSEUDOCODE", "State", "T_RANGE", "scene"]

PSEUDOCODE = [
    "t_in, t_out = 0, 1;   Δ = p1 - p0",
    "for each side k (left, right, bottom, top):",
    "    (p_k, q_k) = (-Δx, x0-xmin), (Δx, xmax-x0), (-Δy, y0-ymin), (Δy, ymax-y0)",
    "    if p_k == 0 and q_k < 0: reject (parallel, outside)",
    "    if p_k < 0: t_in  = max(t_in,  q_k / p_k)    # entering",
    "    if p_k > 0: t_out = min(t_out, q_k / p_k)    # leaving",
    "    if t_in > t_out: reject",
    "return p0 + t_in Δ, p0 + t_out Δ",
]
T_RANGE = (-1.0, 2.0)
"""The part of the number line drawn; values beyond it are pinned to its ends."""
ENTER, LEAVE = "#2e7d32", "#c62828"


@dataclass
class State:
    """The segment's end points and the step shown (one per side, then the result).

    Examples
    --------
    >>> State().step
    4
    """

    p0: np.ndarray = field(default_factory=lambda: np.array([-2.4, -1.6]))
    p1: np.ndarray = field(default_factory=lambda: np.array([2.5, 1.6]))
    step: int = 4


def scene(state):
    r"""Pure part: Liang-Barsky's sides up to the chosen step, and what to draw.

    Returns
    -------
    dict
        ``steps`` (from :func:`course_lib.clipping.liang_barsky_steps`), ``step`` (clamped),
        ``count`` (the number of steps: the sides processed, plus the result when the segment
        survives), ``markers`` (for each side processed so far: side, t, kind, point on the
        line), ``t_in``, ``t_out``, ``visible`` (the part kept so far, 2x2, or None),
        ``result`` (shown at the last step) and ``text``.

    Examples
    --------
    >>> s = scene(State(np.array([-2.0, 0.0]), np.array([2.0, 0.0]), step=1))
    >>> [(m["side"], m["kind"], m["t"]) for m in s["markers"]]
    [('left', 'entering', 0.25), ('right', 'leaving', 0.875)]
    """
    result, steps = clipping.liang_barsky_steps(state.p0, state.p1, BOX_MIN, BOX_MAX)
    count = len(steps) + (result is not None)
    k = min(max(int(state.step), 0), count - 1)
    p0, delta = np.asarray(state.p0, float), np.asarray(state.p1, float) - state.p0
    shown = steps[:k + 1]
    markers = [{"side": st["side"], "t": st["t"], "kind": st["kind"],
                "point": None if st["t"] is None else p0 + st["t"] * delta} for st in shown]
    last = shown[-1]
    t_in, t_out = last["t_in"], last["t_out"]
    visible = None if t_in > t_out else np.array([p0 + t_in * delta, p0 + t_out * delta])
    if k == len(steps):                          # the result step
        line = 7
        note = (f"The interval is [{fmt.number(t_in)}, {fmt.number(t_out)}]: the segment is "
                f"clipped to p({fmt.number(t_in)}) = ({fmt.number(visible[0][0], 2)}, "
                f"{fmt.number(visible[0][1], 2)}) ... p({fmt.number(t_out)}) = "
                f"({fmt.number(visible[1][0], 2)}, {fmt.number(visible[1][1], 2)}).")
    else:
        st = steps[k]
        head = (f"<b>Side {k + 1}: {st['side']}.</b> p = {fmt.number(st['p'])}, "
                f"q = {fmt.number(st['q'])}. ")
        if st["kind"] == "parallel outside":
            line, note = 3, head + "p = 0 and q < 0: the line runs parallel to this side, " \
                "outside it. Reject."
        elif st["kind"] == "parallel inside":
            line, note = 3, head + "p = 0 and q ≥ 0: parallel to this side and inside; no change."
        else:
            entering = st["kind"] == "entering"
            line = 4 if entering else 5
            note = head + (f"t = q/p = {fmt.number(st['t'])}: "
                           + ("p < 0, the line <b>enters</b> here, t_in = max(t_in, t) = "
                              if entering else
                              "p > 0, the line <b>leaves</b> here, t_out = min(t_out, t) = ")
                           + fmt.number(t_in if entering else t_out) + ".")
        if t_in > t_out:
            line = 6 if st["kind"] != "parallel outside" else 3
            note += (f" Now t_in = {fmt.number(t_in)} > t_out = {fmt.number(t_out)}: the "
                     "interval is empty, reject.")
    return {"steps": steps, "step": k, "count": count, "markers": markers, "t_in": t_in,
            "t_out": t_out, "visible": visible, "result": result if k == len(steps) else None,
            "text": pseudocode_html(PSEUDOCODE, line, note)}


class LiangBarskyExplorer(StepExplorer):
    """Drag the end points; step through the four sides and watch [t_in, t_out] shrink.

    In a notebook, after ``%matplotlib widget``, end a cell with ``LiangBarskyExplorer()``.

    Examples
    --------
    >>> explorer = LiangBarskyExplorer()
    >>> explorer.step.value = 0                 # only the left side processed
    >>> "left" in explorer.info.value
    True
    """

    summary = ("Liang-Barsky visualizer (interactive): drag the segment's end points; the t "
               "values of the four sides on a number line and the clipped interval.")

    def __init__(self, state=None):
        self.state = state or State()
        self.fig = draw.figure(figsize=(4.6, 5.6))
        grid = self.fig.add_gridspec(2, 1, height_ratios=(4.2, 1), left=0.11, right=0.97,
                                     bottom=0.07, top=0.95, hspace=0.28)
        ax = self.fig.add_subplot(grid[0])
        draw.setup_axes_2d(ax, LIMITS, title="Liang-Barsky: p(t) = p0 + t (p1 - p0)", grid=False)
        (x0, y0), (x1, y1) = BOX_MIN, BOX_MAX
        ax.fill([x0, x1, x1, x0], [y0, y0, y1, y1], color="#e8f3e8", zorder=0)
        ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], color="#2e7d32", lw=1.5)
        (self.line,) = ax.plot([], [], color="0.6", lw=0.8, ls=":")
        (self.segment,) = ax.plot([], [], color="0.45", lw=1.5, ls="--")
        (self.kept,) = ax.plot([], [], color="C0", lw=3)
        (self.result,) = ax.plot([], [], color="#1b5e20", lw=5, alpha=0.7)
        (self.enter_pts,) = ax.plot([], [], ">", color=ENTER, ms=9)
        (self.leave_pts,) = ax.plot([], [], "<", color=LEAVE, ms=9)
        (self.ends,) = ax.plot([], [], "o", color="C0", ms=9, mec="white")
        line = self.fig.add_subplot(grid[1])
        line.set(xlim=T_RANGE, ylim=(-1.9, 1.9), yticks=[], xlabel="t")
        line.axvspan(0, 1, color="0.93")
        for t in (0, 1):
            line.axvline(t, color="0.4", lw=0.8)
        line.spines[["left", "right", "top"]].set_visible(False)
        (self.interval,) = line.plot([], [], color="C0", lw=6, solid_capstyle="butt")
        (self.enter_t,) = line.plot([], [], ">", color=ENTER, ms=9)
        (self.leave_t,) = line.plot([], [], "<", color=LEAVE, ms=9)
        # left and right labelled above the line, bottom and top below it
        self.t_labels = [line.text(0, 0, "", fontsize=_style.ANNOTATION, ha="center",
                                   va="bottom" if k < 2 else "top") for k in range(4)]
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.line, self.segment, self.kept, self.result,
                                               self.enter_pts, self.leave_pts, self.ends,
                                               self.interval, self.enter_t, self.leave_t,
                                               *self.t_labels])
        self._wire(ax, [self.state.p0, self.state.p1], info_width="480px")

    def _scene(self):
        return scene(self.state)

    def _step_count(self):
        return scene(self.state)["count"]

    def _draw(self, s):
        p0, p1 = np.asarray(self.state.p0), np.asarray(self.state.p1)
        d = p1 - p0
        far = 10.0 / max(np.linalg.norm(d), 1e-9)
        self.line.set_data(*np.array([p0 - far * d, p1 + far * d]).T)
        self.segment.set_data(*np.array([p0, p1]).T)
        self.ends.set_data(*np.array([p0, p1]).T)
        visible = s["visible"]
        self.kept.set_data(*(visible.T if visible is not None else ([], [])))
        self.result.set_data(*(np.array(s["result"]).T if s["result"] is not None else ([], [])))
        for kind, points, ticks in (("entering", self.enter_pts, self.enter_t),
                                    ("leaving", self.leave_pts, self.leave_t)):
            marks = [m for m in s["markers"] if m["kind"] == kind]
            points.set_data([m["point"][0] for m in marks], [m["point"][1] for m in marks])
            ticks.set_data([np.clip(m["t"], *T_RANGE) for m in marks], [0.0] * len(marks))
        for k, (label, m) in enumerate(zip(self.t_labels, s["markers"] + [None] * 4)):
            if m is None or m["t"] is None:
                label.set_text("")
            else:
                label.set_position((np.clip(m["t"], *T_RANGE), 0.35 if k < 2 else -0.35))
                label.set_text(f"{m['side']}\n{fmt.number(m['t'], 2)}" if k < 2
                               else f"{fmt.number(m['t'], 2)}\n{m['side']}")
        if s["t_in"] <= s["t_out"]:
            self.interval.set_data(np.clip([s["t_in"], s["t_out"]], *T_RANGE), [0, 0])
            self.interval.set_color("C0")
        else:
            self.interval.set_data(np.clip([s["t_out"], s["t_in"]], *T_RANGE), [0, 0])
            self.interval.set_color("#c62828")
        self.info.value = s["text"]
