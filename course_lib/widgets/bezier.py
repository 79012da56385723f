r"""Bézier editor: drag the control points; see the curve, its control polygon and convex hull,
de Casteljau's construction and the tangent at t; subdivide the curve and elevate its degree.

Every point of a Bézier curve is a repeated linear interpolation of its control points
(de Casteljau): at parameter t each edge of the control polygon is cut in the ratio t : 1 - t,
the new points form a polygon with one edge fewer, and so on until one point is left — the
curve point. The last two points of the construction span the tangent. The buttons split the
curve at t into two Bézier curves (their control polygons are the two sides of the triangle of
intermediate points) and raise its degree by one (one more control point, the same curve).
"""
from dataclasses import dataclass, field

import numpy as np

from .. import curves, draw, format as fmt
from . import _style
from ._base import Explorer, beside, bind, checkbox, panel, slider
from ._drag import DraggablePoints

__all__ = ["BezierExplorer", "MAX_POINTS", "State", "convex_hull", "scene"]

MAX_POINTS = 12
SAMPLES = 200
LIMITS = (-0.5, 5.5)
LEVEL_COLORS = ("#9e9e9e", "#43a047", "#1e88e5", "#8e24aa", "#fb8c00", "#00897b", "#6d4c41",
                "#3949ab", "#c0ca33", "#d81b60", "#5e35b1")


def _default_points():
    return np.array([[0.4, 0.6], [1.0, 3.8], [3.2, 4.6], [4.6, 1.2]])


@dataclass
class State:
    """The control points, the parameter t and what to show.

    Examples
    --------
    >>> State().points.shape, State().t
    ((4, 2), 0.4)
    """

    points: np.ndarray = field(default_factory=_default_points)
    t: float = 0.4
    show_hull: bool = True
    show_construction: bool = True


def convex_hull(points):
    """The convex hull of 2D points, counter-clockwise (Andrew's monotone chain).

    Examples
    --------
    >>> convex_hull([[0, 0], [2, 0], [1, 1], [2, 2], [0, 2]]).tolist()
    [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]
    """
    pts = sorted(map(tuple, np.asarray(points, dtype=float)))
    if len(pts) <= 2:
        return np.array(pts)

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower, upper = [], []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return np.array(lower[:-1] + upper[:-1])


def scene(state):
    """Pure part: the curve, its hull, de Casteljau's triangle and the tangent at t.

    Returns
    -------
    dict
        ``curve`` (SAMPLES x 2), ``hull`` (its vertices, closed), ``levels`` (de Casteljau's
        intermediate polygons at t, from the control polygon down to the point), ``point``,
        ``tangent`` (unit vector), ``tangent_line`` (2x2, for drawing), ``degree`` and ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["degree"], len(s["levels"]), s["curve"].shape
    (3, 4, (200, 2))
    """
    p = np.asarray(state.points, dtype=float)
    t = float(state.t)
    curve = curves.bezier(p, np.linspace(0.0, 1.0, SAMPLES))
    point, levels = curves.de_casteljau(p, t, triangle=True)
    tangent = curves.bezier_tangent(p, t)
    hull = convex_hull(p)
    n = len(p) - 1
    weights = curves.bernstein(n, None, t)
    text = (f"Degree {n} ({n + 1} control points). At t = {fmt.number(t, 2)} the curve point "
            f"is ({fmt.number(point[0], 3)}, {fmt.number(point[1], 3)}) = "
            + " + ".join(f"{fmt.number(w, 3)}·P{i}" for i, w in enumerate(weights))
            + ": the Bernstein weights are all ≥ 0 and add up to 1, so the point is a convex "
            "combination of the control points and lies in their convex hull.")
    return {"curve": curve, "hull": np.vstack([hull, hull[:1]]), "levels": levels,
            "point": point, "tangent": tangent,
            "tangent_line": np.array([point - 0.9 * tangent, point + 0.9 * tangent]),
            "degree": n, "text": text}


class BezierExplorer(Explorer):
    """Drag the control points; t slider; add, remove, subdivide and elevate buttons.

    In a notebook, after ``%matplotlib widget``, end a cell with ``BezierExplorer()``.

    Examples
    --------
    >>> explorer = BezierExplorer()
    >>> explorer.elevate()                       # degree 3 -> 4, same curve
    >>> len(explorer.state.points)
    5
    >>> explorer.drag.press(*explorer.state.points[0]); explorer.drag.move(1.0, 1.0)
    >>> explorer.state.points[0].tolist()
    [1.0, 1.0]
    """

    summary = ("Bézier editor (interactive): drag the control points; the curve, control polygon "
               "and convex hull, de Casteljau's construction and the tangent at t, subdivision "
               "and degree elevation.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(5.0, 5.0))
        ax = self.fig.add_subplot()
        self.fig.subplots_adjust(left=0.1, right=0.98, bottom=0.08, top=0.94)
        draw.setup_axes_2d(ax, LIMITS, title="Bézier curve and de Casteljau at t")
        self.ax = ax
        self.hull = ax.fill([], [], color="#e3f2fd", zorder=0, label="convex hull")[0]
        (self.polygon,) = ax.plot([], [], "--", color="0.45", lw=1, zorder=2,
                                  label="control polygon")
        self.levels = [ax.plot([], [], "o-", color=c, lw=1, ms=3.5, zorder=3)[0]
                       for c in LEVEL_COLORS[1:MAX_POINTS]]
        (self.curve,) = ax.plot([], [], color="C0", lw=2.5, zorder=4, label="curve")
        (self.halves,) = ax.plot([], [], color="C1", lw=2.5, zorder=4)
        (self.tangent,) = ax.plot([], [], color="C3", lw=1.5, zorder=5, label="tangent at t")
        (self.point,) = ax.plot([], [], "o", color="C3", ms=8, zorder=6)
        (self.controls,) = ax.plot([], [], "o", color="0.2", ms=9, mec="white", zorder=7)
        self.labels = [ax.text(0, 0, "", fontsize=_style.ANNOTATION, color="0.25", zorder=8)
                       for _ in range(MAX_POINTS)]
        _style.legend(ax, loc="lower center", ncol=2, handlelength=1.5, columnspacing=1.0,
                      borderpad=0.3, labelspacing=0.25)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.hull, self.polygon, *self.levels,
                                               self.curve, self.halves, self.tangent,
                                               self.point, self.controls, *self.labels])
        self.drag = DraggablePoints(ax, self.state.points, self._on_drag,
                                    on_release=self.update)
        self.t = slider("t", self.state.t, 0, 1, 0.01)
        buttons = []
        for label, action in (("add point", self.add_point), ("remove point", self.remove_point),
                              ("subdivide at t", self.subdivide),
                              ("elevate degree", self.elevate)):
            button = w.Button(description=label, layout=w.Layout(
                width=_style.button_width("subdivide at t", "elevate degree")))
            button.on_click(lambda _, action=action: action())
            buttons.append(button)
        self.hull_box = checkbox("convex hull", self.state.show_hull)
        self.construction_box = checkbox("de Casteljau", self.state.show_construction)
        bind(self.state, {"t": self.t, "show_hull": self.hull_box,
                          "show_construction": self.construction_box}, self.update)
        self.info = panel(width="330px")
        controls = w.VBox([self.t, w.HBox(buttons[:2]), w.HBox(buttons[2:]),
                           w.HBox([self.hull_box, self.construction_box],
                                  layout=w.Layout(grid_gap="0 16px")), self.info])
        self.widget = beside(self.fig.canvas, controls)
        self._split = None
        self._draw(scene(self.state))

    # --- editing ----------------------------------------------------------------------------
    def _set_points(self, points):
        self.state.points = np.array(points, dtype=float)
        self.drag.set_points(self.state.points)
        self._split = None
        self.update()

    def add_point(self):
        """Append a control point (up to MAX_POINTS), beyond the last one."""
        p = self.state.points
        if len(p) >= MAX_POINTS:
            return
        new = np.clip(p[-1] + (p[-1] - p[-2]) * 0.5, *LIMITS)
        self._set_points(np.vstack([p, new]))

    def remove_point(self):
        """Remove the last control point (at least 2 stay)."""
        if len(self.state.points) > 2:
            self._set_points(self.state.points[:-1])

    def elevate(self):
        """Degree elevation: one more control point, the same curve."""
        if len(self.state.points) < MAX_POINTS:
            self._set_points(curves.bezier_elevate(self.state.points))

    def subdivide(self):
        """Split at t: show the two halves' control polygons; keep the left half's points."""
        left, right = curves.bezier_subdivide(self.state.points, self.state.t)
        self.state.points = left
        self.drag.set_points(left)
        self._split = right
        self.update()

    # --- events -----------------------------------------------------------------------------
    def _on_drag(self, index, xy):
        self.state.points = self.drag.points.copy()
        self._split = None
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        p = self.state.points
        self.hull.set_xy(s["hull"] if self.state.show_hull else np.zeros((0, 2)))
        self.polygon.set_data(*p.T)
        self.controls.set_data(*p.T)
        dragging = self.drag.active
        for k, label in enumerate(self.labels):          # while dragging, only the dragged
            if k < len(p) and dragging in (None, k):      # point keeps its label: text is the
                label.set_position(p[k] + [0.08, 0.1])    # costliest artist to redraw
                label.set_text(f"P{k}")
            else:
                label.set_text("")
        for k, line in enumerate(self.levels):
            level = k + 1
            if self.state.show_construction and level < len(s["levels"]) - 0:
                line.set_data(*s["levels"][level].T)
            else:
                line.set_data([], [])
        self.curve.set_data(*s["curve"].T)
        if self._split is not None:
            other = curves.bezier(self._split, np.linspace(0, 1, SAMPLES))
            self.halves.set_data(*np.vstack([other, [[np.nan, np.nan]], self._split]).T)
        else:
            self.halves.set_data([], [])
        self.point.set_data([s["point"][0]], [s["point"][1]])
        self.tangent.set_data(*s["tangent_line"].T)
        text = s["text"]
        if self._split is not None:
            text += (" <b>Subdivided</b> at t: the blue curve is now the left half with its own "
                     "control points (draggable); the orange curve and polygon are the right half.")
        self.info.value = text
