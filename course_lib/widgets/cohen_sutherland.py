"""Cohen-Sutherland visualizer: region codes, and the algorithm stepped through one iteration
at a time while the student drags the segment's end points."""
from dataclasses import dataclass, field

import numpy as np

from .. import clipping, draw, format as fmt
from . import _style
from ._clip2d import BOX_MAX, BOX_MIN, StepExplorer, window_figure
from ._drag import pseudocode_html

__all__ = ["CohenSutherlandExplorer", "PSEUDOCODE", "State", "scene"]

PSEUDOCODE = [
    "repeat:",
    "    c0, c1 = outcode(p0), outcode(p1)",
    "    if c0 | c1 == 0: accept the segment, stop",
    "    if c0 & c1 != 0: reject the segment, stop",
    "    p = an end point that is outside (code != 0)",
    "    side = a side named by p's code (lowest bit)",
    "    p = the segment's intersection with that side",
]
_LINE = {"accept": 2, "reject": 3, "clip": 6}


def _point(p):
    return f"({fmt.number(p[0], 2)}, {fmt.number(p[1], 2)})"


@dataclass
class State:
    """The segment's end points and the step shown.

    Examples
    --------
    >>> State().p0.tolist()
    [-2.5, -0.5]
    """

    p0: np.ndarray = field(default_factory=lambda: np.array([-2.5, -0.5]))
    p1: np.ndarray = field(default_factory=lambda: np.array([2.2, 1.9]))
    step: int = 0


def scene(state):
    """Pure part: the iterations of Cohen-Sutherland and what to draw for the chosen step.

    Returns
    -------
    dict
        ``steps`` (from :func:`course_lib.clipping.cohen_sutherland_steps`), ``step`` (the
        index shown, clamped), ``segment`` (the current end points, 2x2), ``codes`` (their
        outcodes as 4-bit strings), ``new_point`` (the point this step computes, or None),
        ``result`` (the final clipped segment or None), ``final`` (whether the shown step is the
        last one) and ``text`` (pseudocode with the current line, and what happens).

    Examples
    --------
    >>> s = scene(State(np.array([-2.0, 0.0]), np.array([0.0, 0.0]), step=0))
    >>> s["codes"], len(s["steps"])
    (['0001', '0000'], 2)
    """
    result, steps = clipping.cohen_sutherland_steps(state.p0, state.p1, BOX_MIN, BOX_MAX)
    k = min(max(int(state.step), 0), len(steps) - 1)
    st = steps[k]
    codes = [format(st["code0"], "04b"), format(st["code1"], "04b")]
    head = (f"<b>Iteration {k + 1} of {len(steps)}.</b> outcode(p0) = {codes[0]}, "
            f"outcode(p1) = {codes[1]}: OR = {format(st['code0'] | st['code1'], '04b')}, "
            f"AND = {format(st['code0'] & st['code1'], '04b')}. ")
    if st["action"] == "accept":
        note = head + "Both end points are inside: accept " + (
            f"the segment {_point(st['p0'])} - {_point(st['p1'])}." if k else "it as it is.")
    elif st["action"] == "reject":
        side = clipping.describe_outcode(st["code0"] & st["code1"]).split("(")[1][:-1]
        note = head + f"Both end points lie beyond the same side ({side}): reject."
    else:
        end = f"p{st['endpoint']}"
        note = head + (f"{end} is outside; its code names the <b>{st['side']}</b> side, so "
                       f"{end} moves to the intersection with it: {_point(st['new_point'])}.")
    return {"steps": steps, "step": k, "segment": np.array([st["p0"], st["p1"]]),
            "codes": codes, "new_point": st.get("new_point"), "result": result,
            "final": k == len(steps) - 1,
            "text": pseudocode_html(PSEUDOCODE, _LINE[st["action"]], note)}


class CohenSutherlandExplorer(StepExplorer):
    """Drag the end points; step through the iterations with the slider or the buttons.

    In a notebook, after ``%matplotlib widget``, end a cell with ``CohenSutherlandExplorer()``.

    Examples
    --------
    >>> explorer = CohenSutherlandExplorer()
    >>> explorer.drag.press(*explorer.state.p1); explorer.drag.move(0.5, 0.5)   # drag p1 inside
    >>> explorer.state.p1.tolist()
    [0.5, 0.5]
    >>> explorer.step.value = explorer.step.max          # the last iteration
    >>> "accept" in explorer.info.value
    True
    """

    summary = ("Cohen-Sutherland visualizer (interactive): drag the segment's end points; the "
               "region codes, each iteration and the clipped segment are shown.")

    def __init__(self, state=None):
        self.state = state or State()
        self.fig, ax = window_figure("Cohen-Sutherland: region codes (bits TBRL)", regions=True)
        s = scene(self.state)
        (self.original,) = ax.plot(*np.array([self.state.p0, self.state.p1]).T, color="0.55",
                                   ls="--", lw=1.2, zorder=3)
        (self.current,) = ax.plot(*s["segment"].T, color="C0", lw=2.2, zorder=4)
        (self.result,) = ax.plot([], [], color="#1b5e20", lw=4.5, alpha=0.7, zorder=5)
        (self.new_point,) = ax.plot([], [], "*", color="C3", ms=14, zorder=6)
        (self.ends,) = ax.plot(*np.array([self.state.p0, self.state.p1]).T, "o", color="C0",
                               ms=9, mec="white", zorder=7)
        self.labels = [ax.text(0, 0, "", fontsize=_style.ANNOTATION, family="monospace", zorder=8,
                               bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="0.7"))
                       for _ in range(2)]
        self.blitter = draw.Blitter(self.fig, [self.original, self.current, self.result,
                                               self.new_point, self.ends, *self.labels])
        self._wire(ax, [self.state.p0, self.state.p1], info_width="430px")

    def _scene(self):
        return scene(self.state)

    def _step_count(self):
        return len(scene(self.state)["steps"])

    def _draw(self, s):
        self.original.set_data(*np.array([self.state.p0, self.state.p1]).T)
        self.ends.set_data(*np.array([self.state.p0, self.state.p1]).T)
        self.current.set_data(*s["segment"].T)
        point = s["new_point"]
        self.new_point.set_data(*(([point[0]], [point[1]]) if point is not None else ([], [])))
        if s["final"] and s["result"] is not None:
            self.result.set_data(*np.array(s["result"]).T)
        else:
            self.result.set_data([], [])
        for label, p, code in zip(self.labels, s["segment"], s["codes"]):
            label.set_position(p + [0.12, 0.12])
            label.set_text(code)
        self.info.value = s["text"]
