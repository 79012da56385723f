"""Sutherland-Hodgman visualizer: a polygon clipped by one side of the window at a time,
while the student drags its vertices."""
from dataclasses import dataclass, field

import numpy as np

from .. import clipping, draw, format as fmt
from . import _style
from ._clip2d import BOX_MAX, BOX_MIN, LIMITS, StepExplorer, window_figure
from ._drag import pseudocode_html

__all__ = ["PSEUDOCODE", "State", "SutherlandHodgmanExplorer", "scene"]

PSEUDOCODE = [
    "for each side of the window (left, right, bottom, top):",
    "    output = []",
    "    for each edge S -> E of the polygon:",
    "        S in,  E in:   output E",
    "        S in,  E out:  output the intersection I",
    "        S out, E in:   output I, then E",
    "        S out, E out:  output nothing",
    "    polygon = output",
]
_SIDES = clipping.BIT_NAMES[:4]


def _default_polygon():
    return np.array([[-2.2, -0.4], [0.2, -2.3], [2.4, -0.2], [0.6, 0.2], [1.0, 2.3], [-1.4, 1.6]])


@dataclass
class State:
    """The polygon's vertices and the step shown (0: the input, k: after the k-th side).

    Examples
    --------
    >>> len(State().polygon), State().step
    (6, 4)
    """

    polygon: np.ndarray = field(default_factory=_default_polygon)
    step: int = 4


def _side_line(side):
    """Two points spanning the window side's line across the figure."""
    (x0, y0), (x1, y1) = BOX_MIN, BOX_MAX
    a, b = LIMITS
    return {"left": [[x0, a], [x0, b]], "right": [[x1, a], [x1, b]],
            "bottom": [[a, y0], [b, y0]], "top": [[a, y1], [b, y1]]}[side]


def _outside_region(side):
    """The part of the figure beyond the side (shaded while that side is being clipped)."""
    (x0, y0), (x1, y1) = BOX_MIN, BOX_MAX
    a, b = LIMITS
    return np.array({"left": [[a, a], [x0, a], [x0, b], [a, b]],
                     "right": [[x1, a], [b, a], [b, b], [x1, b]],
                     "bottom": [[a, a], [b, a], [b, y0], [a, y0]],
                     "top": [[a, y1], [b, y1], [b, b], [a, b]]}[side])


def scene(state):
    """Pure part: the polygon before and after the chosen side, and the explanation.

    Returns
    -------
    dict
        ``steps`` (from :func:`course_lib.clipping.sutherland_hodgman_steps`), ``step``,
        ``before`` and ``after`` (the polygons around the shown side; at step 0 both are the
        input), ``side`` (None at step 0), ``side_line``, ``outside`` (the region cut away),
        ``counts`` (vertices after each side) and ``text``.

    Examples
    --------
    >>> s = scene(State(step=1))
    >>> s["side"], len(s["before"]), len(s["after"])
    ('left', 6, 6)
    """
    steps = clipping.sutherland_hodgman_steps(state.polygon, BOX_MIN, BOX_MAX)
    k = min(max(int(state.step), 0), len(steps))
    polygons = [np.asarray(state.polygon, float)] + [poly for _, poly in steps]
    counts = [len(p) for p in polygons]
    if k == 0:
        side, line, note = None, None, (
            f"<b>The input polygon</b> has {counts[0]} vertices. Step through the four sides: "
            "each pass keeps the part of the polygon on the window's side of one line.")
    else:
        side = _SIDES[k - 1]
        line = 7
        note = (f"<b>Side {k}: {side}.</b> {counts[k - 1]} vertices in, {counts[k]} out: every "
                "edge that crosses the line contributes its intersection point, every vertex "
                "inside is kept.")
        if counts[k] == 0:
            note += " Nothing is left: the polygon lies entirely outside this side."
        if k == 4 and counts[k]:
            area = 0.5 * abs(np.dot(polygons[4][:, 0], np.roll(polygons[4][:, 1], -1))
                             - np.dot(polygons[4][:, 1], np.roll(polygons[4][:, 0], -1)))
            note += f" The clipped polygon has area {fmt.number(area, 3)}."
    return {"steps": steps, "step": k, "before": polygons[max(k - 1, 0)], "after": polygons[k],
            "side": side, "side_line": None if side is None else np.array(_side_line(side)),
            "outside": None if side is None else _outside_region(side), "counts": counts,
            "text": pseudocode_html(PSEUDOCODE, line, note)}


def _closed(poly):
    return np.vstack([poly, poly[:1]]) if len(poly) else np.zeros((0, 2))


class SutherlandHodgmanExplorer(StepExplorer):
    """Drag the polygon's vertices; step through the four sides of the window.

    In a notebook, after ``%matplotlib widget``, end a cell with ``SutherlandHodgmanExplorer()``.

    Examples
    --------
    >>> explorer = SutherlandHodgmanExplorer()
    >>> explorer.step.value = 2                       # after the left and right sides
    >>> "right" in explorer.info.value
    True
    """

    summary = ("Sutherland-Hodgman visualizer (interactive): drag the polygon's vertices; it is "
               "clipped by one side of the window at a time.")

    def __init__(self, state=None):
        self.state = state or State()
        self.fig, ax = window_figure("Sutherland-Hodgman: one side at a time")
        self.outside = ax.fill([], [], color="#c62828", alpha=0.12, zorder=1)[0]
        (self.side_line,) = ax.plot([], [], color="#c62828", lw=2.5, zorder=3)
        (self.original,) = ax.plot([], [], "o--", color="0.5", lw=1, ms=8, mec="white", zorder=4)
        (self.before,) = ax.plot([], [], color="C0", lw=1, ls=":", zorder=4)
        self.after = ax.fill([], [], facecolor=(0.12, 0.47, 0.71, 0.35), edgecolor="C0", lw=2,
                             zorder=5)[0]
        (self.after_pts,) = ax.plot([], [], "o", color="C0", ms=5, zorder=6)
        self.numbers = [ax.text(0, 0, "", fontsize=_style.ANNOTATION, color="C0", zorder=7)
                        for _ in range(12)]
        self.blitter = draw.Blitter(self.fig, [self.outside, self.side_line, self.original,
                                               self.before, self.after, self.after_pts,
                                               *self.numbers])
        self._wire(ax, self.state.polygon, info_width="440px")

    def _scene(self):
        return scene(self.state)

    def _step_count(self):
        return 5                                   # the input, then after each of the 4 sides

    def _move(self, index, xy):
        self.state.polygon = self.drag.points.copy()

    def _draw(self, s):
        self.original.set_data(*_closed(np.asarray(self.state.polygon)).T)
        if s["side"] is None:
            self.outside.set_xy(np.zeros((0, 2)))
            self.side_line.set_data([], [])
            self.before.set_data([], [])
        else:
            self.outside.set_xy(s["outside"])
            self.side_line.set_data(*s["side_line"].T)
            self.before.set_data(*_closed(s["before"]).T)
        after = s["after"]
        self.after.set_xy(after if len(after) else np.zeros((0, 2)))
        self.after_pts.set_data(*(after.T if len(after) else ([], [])))
        for k, label in enumerate(self.numbers):
            if k < len(after) and s["step"] > 0:
                label.set_position(after[k] + [0.07, 0.07])
                label.set_text(str(k + 1))
            else:
                label.set_text("")
        self.info.value = s["text"]
