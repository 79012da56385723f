r"""B-spline / NURBS editor: drag the control points, choose the degree and the knot vector,
weigh the selected point, and watch its basis function and the part of the curve it controls.

A B-spline curve :math:`C(t) = \sum_i N_{i,p}(t) P_i` is a blend of its control points with the
basis functions of degree p defined by the knot vector. :math:`N_{i,p}` is non-zero only on
:math:`[u_i, u_{i+p+1})`, so moving :math:`P_i` changes only that stretch of the curve (local
control), drawn in orange. With weights the curve is a NURBS,
:math:`C(t) = \sum_i R_i(t) P_i` with :math:`R_i = w_i N_{i,p} / \sum_j w_j N_{j,p}`; raising a
weight pulls the curve towards its point.
"""
from dataclasses import dataclass, field

import numpy as np

from .. import curves, draw, format as fmt
from . import _style
from ._base import Explorer, align, beside, labelled, panel, slider
from ._drag import DraggablePoints

__all__ = ["BSplineExplorer", "KNOT_PRESETS", "State", "knot_vector", "scene"]

MAX_POINTS = 12
SAMPLES = 300
LIMITS = (-0.5, 6.5)
KNOT_PRESETS = ("clamped", "uniform", "repeated interior", "custom")


def _default_points():
    return np.array([[0.5, 0.8], [1.0, 4.2], [2.6, 5.6], [3.4, 1.2], [4.6, 0.9], [5.2, 4.6],
                     [6.0, 5.4]])


@dataclass
class State:
    """Control points, weights, degree, knot vector choice and the selected point.

    Examples
    --------
    >>> s = State()
    >>> len(s.points), s.degree, s.knots
    (7, 3, 'clamped')
    """

    points: np.ndarray = field(default_factory=_default_points)
    weights: np.ndarray = field(default_factory=lambda: np.ones(7))
    degree: int = 3
    knots: str = "clamped"
    custom_knots: tuple = ()
    selected: int = 1


def knot_vector(kind, n_control, degree, custom=()):
    """The knot vector of a preset (or the custom one), for `n_control` points of `degree`.

    ``"repeated interior"`` is the clamped vector with the middle interior knot repeated
    `degree` times: the curve then passes through a control point there, with a corner.

    Examples
    --------
    >>> knot_vector("repeated interior", 7, 3).tolist()
    [0.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0]
    """
    if kind == "clamped":
        return curves.clamped_knots(n_control, degree)
    if kind == "uniform":
        return curves.uniform_knots(n_control, degree)
    if kind == "repeated interior":
        interior = n_control - degree - 1
        repeats = min(degree, interior)
        spread = interior - repeats                     # the other interior knots, spread out
        candidates = np.linspace(0.0, 1.0, spread + 3)[1:-1]
        others = np.delete(candidates, np.argmin(np.abs(candidates - 0.5)))   # none at 0.5
        inside = np.sort(np.concatenate([others, np.full(repeats, 0.5)]))
        return np.concatenate([np.zeros(degree + 1), inside, np.ones(degree + 1)])
    if kind == "custom":
        return np.asarray(custom, dtype=float)
    raise ValueError(f"kind must be one of {KNOT_PRESETS}, got {kind!r}")


def scene(state):
    """Pure part: the curve, its basis functions, the selected point's span, or an error.

    Returns
    -------
    dict
        ``error`` (a message when the knot vector does not fit, else None), ``knots``,
        ``domain``, ``t`` (SAMPLES parameters), ``curve``, ``basis`` (SAMPLES x n, the rational
        basis R_i when weights differ from 1), ``support`` (the selected point's
        :math:`[u_k, u_{k+p+1})` clipped to the domain), ``affected`` (the curve over it) and
        ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["error"] is None, s["basis"].shape, bool(np.allclose(s["basis"].sum(axis=1), 1))
    (True, (300, 7), True)
    """
    p = np.asarray(state.points, dtype=float)
    w = np.asarray(state.weights, dtype=float)
    n = len(p)
    try:
        knots = knot_vector(state.knots, n, state.degree, state.custom_knots)
        a, b = curves.domain(knots, state.degree)
        t = np.linspace(a, b, SAMPLES)
        curve = curves.nurbs(p, w, knots, state.degree, t)
        basis = curves.bspline_basis(knots, state.degree, t)
    except ValueError as error:
        return {"error": str(error)}
    rational = basis * w
    rational /= rational.sum(axis=1, keepdims=True)
    k = int(state.selected)
    lo, hi = max(knots[k], a), min(knots[k + state.degree + 1], b)
    inside = (t >= lo) & (t <= hi)
    weighted = not np.allclose(w, 1.0)
    text = (f"Degree {state.degree}, {n} control points, so {n + state.degree + 1} knots: "
            f"[{', '.join(fmt.number(u, 3) for u in knots)}]; the curve is defined for "
            f"t in [{fmt.number(a, 3)}, {fmt.number(b, 3)}]. P{k} (weight "
            f"{fmt.number(w[k], 2)}) influences only t in [u{k}, u{k + state.degree + 1}) = "
            f"[{fmt.number(knots[k], 3)}, {fmt.number(knots[k + state.degree + 1], 3)}) "
            "— the orange part of the curve.")
    text += (" The weights are not all 1: this is a NURBS curve and the plot shows the rational "
             "basis R_i = w_i N_i / Σ w_j N_j." if weighted else
             " All weights are 1: a plain B-spline, and the plot shows the basis N_i.")
    return {"error": None, "knots": knots, "domain": (a, b), "t": t, "curve": curve,
            "basis": rational, "support": (lo, hi), "affected": curve[inside], "text": text}


class BSplineExplorer(Explorer):
    """Drag or click control points; degree, knot presets (or typed knots) and weight controls.

    In a notebook, after ``%matplotlib widget``, end a cell with ``BSplineExplorer()``.

    Examples
    --------
    >>> explorer = BSplineExplorer()
    >>> explorer.weight.value = 4.0              # the selected point's weight
    >>> "NURBS" in explorer.info.value
    True
    >>> explorer.knot_text.value = "0, 0, 0, 1"  # a knot vector that does not fit
    >>> "knots must have" in explorer.info.value
    True
    """

    summary = ("B-spline / NURBS editor (interactive): drag control points, change the degree, "
               "the knot vector and the weights; the basis functions and the selected point's "
               "span of influence.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(5.2, 6.2))
        grid = self.fig.add_gridspec(2, 1, height_ratios=(3.2, 1.3), left=0.1, right=0.97,
                                     bottom=0.07, top=0.95, hspace=0.25)
        ax = self.fig.add_subplot(grid[0])
        draw.setup_axes_2d(ax, LIMITS, title="B-spline / NURBS curve")
        (self.polygon,) = ax.plot([], [], "--", color="0.45", lw=1)
        (self.curve,) = ax.plot([], [], color="C0", lw=2.2)
        (self.affected,) = ax.plot([], [], color="C1", lw=4, alpha=0.8)
        (self.controls,) = ax.plot([], [], "o", color="0.2", ms=9, mec="white")
        (self.selected,) = ax.plot([], [], "o", color="C1", ms=13, mec="0.2", mew=1.5)
        self.labels = [ax.text(0, 0, "", fontsize=_style.ANNOTATION, color="0.25")
                       for _ in range(MAX_POINTS)]
        self.message = ax.text(3.0, 3.0, "", ha="center", va="center", color="#c62828",
                               fontsize=_style.ANNOTATION, wrap=True)
        basis_ax = self.fig.add_subplot(grid[1])
        basis_ax.set(ylim=(-0.05, 1.05), xlabel="t")
        basis_ax.set_title("basis functions (selected one thick)")
        _style.style_figure(self.fig)
        self.basis_ax = basis_ax
        self.basis = [basis_ax.plot([], [], lw=1.0, color="0.55")[0] for _ in range(MAX_POINTS)]
        self.span = basis_ax.axvspan(0, 0, color="C1", alpha=0.15)
        (self.knot_marks,) = basis_ax.plot([], [], "|", color="k", ms=10, mew=1.5)
        self.blitter = draw.Blitter(self.fig, [self.polygon, self.curve, self.affected,
                                               self.controls, self.selected, *self.labels,
                                               self.message, *self.basis, self.span,
                                               self.knot_marks])
        self.drag = DraggablePoints(ax, self.state.points, self._on_drag,
                                    on_press=self._on_pick, on_release=self.update)
        self.degree = slider("degree", self.state.degree, 1, 5, 1, kind=w.IntSlider)
        self.knots = labelled(w.Dropdown, "knots", options=KNOT_PRESETS, value=self.state.knots)
        self.knot_text = labelled(w.Text, "custom", continuous_update=False)
        self.point = slider("point", self.state.selected, 0, len(self.state.points) - 1, 1,
                            kind=w.IntSlider)
        self.weight = labelled(w.FloatLogSlider, "weight",
                               value=float(self.state.weights[self.state.selected]), base=10,
                               min=-1.3, max=1.0, step=0.01)
        align([self.degree, self.knots, self.knot_text, self.point, self.weight])
        button = w.Layout(width=_style.button_width("add point", "remove point"))
        add = w.Button(description="add point", layout=button)
        remove = w.Button(description="remove point", layout=button)
        add.on_click(lambda _: self.add_point())
        remove.on_click(lambda _: self.remove_point())
        for control in (self.degree, self.knots, self.point, self.weight):
            control.observe(self._on_control, names="value")
        self.knot_text.observe(self._on_knot_text, names="value")
        self.info = panel(width="330px")
        controls = w.VBox([self.degree, self.knots, self.knot_text, self.point, self.weight,
                           w.HBox([add, remove]), self.info])
        self.widget = beside(self.fig.canvas, controls)
        self._draw(scene(self.state))

    def knot_example(self):
        """A knot vector that fits the current points and degree, for the text field's hint:
        n + p + 1 knots, clamped, with the interior knots spread unevenly (t^1.5 of the even
        spacing, to three decimals), so that it differs from every preset.

        Examples
        --------
        >>> BSplineExplorer().knot_example()          # 7 points of degree 3: 11 knots
        '0,0,0,0,0.125,0.354,0.65,1,1,1,1'
        """
        knots = curves.clamped_knots(len(self.state.points), self.state.degree) ** 1.5
        return ",".join(f"{k:.3f}".rstrip("0").rstrip(".") for k in knots)

    # --- editing ----------------------------------------------------------------------------
    def add_point(self):
        """Append a control point (and its weight 1)."""
        p = self.state.points
        if len(p) >= MAX_POINTS:
            return
        new = np.clip(2 * p[-1] - p[-2], *LIMITS)
        self.state.points = np.vstack([p, new])
        self.state.weights = np.append(self.state.weights, 1.0)
        self._points_changed()

    def remove_point(self):
        """Remove the last control point (keeping more points than the degree)."""
        if len(self.state.points) > self.state.degree + 1:
            self.state.points = self.state.points[:-1]
            self.state.weights = self.state.weights[:-1]
            self._points_changed()

    def _points_changed(self):
        self.drag.set_points(self.state.points)
        with self.point.hold_sync():
            self.point.max = len(self.state.points) - 1
        self.state.selected = self.point.value
        self.update()

    # --- events -----------------------------------------------------------------------------
    def _on_pick(self, index):
        self.point.value = index                          # selects it (and updates the weight)

    def _on_drag(self, index, xy):
        self.state.points = self.drag.points.copy()
        self.update()

    def _on_control(self, change):
        if change["owner"] is self.point:
            self.state.selected = self.point.value
            self.weight.value = float(self.state.weights[self.state.selected])
        elif change["owner"] is self.weight:
            self.state.weights = self.state.weights.copy()
            self.state.weights[self.state.selected] = self.weight.value
        self.state.degree = self.degree.value
        self.state.knots = self.knots.value
        self.update()

    def _on_knot_text(self, change):
        try:
            values = tuple(float(x) for x in change["new"].replace(";", ",").split(",")
                           if x.strip())
        except ValueError:
            self.info.value = ("<span style='color:#c62828'>Type the knots as numbers separated "
                               "by commas.</span>")
            return
        self.state.custom_knots = values
        self.knots.value = "custom"
        self.state.knots = "custom"
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        n, degree = len(self.state.points), self.state.degree
        self.knot_text.placeholder = (f"type {n + degree + 1} knots (n + p + 1), "
                                      f"e.g. {self.knot_example()}")
        p = self.state.points
        k = self.state.selected
        self.polygon.set_data(*p.T)
        self.controls.set_data(*p.T)
        self.selected.set_data([p[k, 0]], [p[k, 1]])
        dragging = self.drag.active
        for i, label in enumerate(self.labels):           # while dragging, only the dragged
            shown = i < len(p) and dragging in (None, i)   # point keeps its label: text is the
            label.set_text(f"P{i}" if shown else "")       # costliest artist to redraw
            if shown:
                label.set_position(p[i] + [0.1, 0.12])
        if s["error"] is not None:
            self.message.set_text(s["error"])
            for artist in (self.curve, self.affected, self.knot_marks, *self.basis):
                artist.set_data([], [])
            self.info.value = f"<span style='color:#c62828'><b>{s['error']}</b></span>"
            return
        self.message.set_text("")
        self.curve.set_data(*s["curve"].T)
        self.affected.set_data(*(s["affected"].T if len(s["affected"]) else ([], [])))
        a, b = s["domain"]
        if self.basis_ax.get_xlim() != (a, b):
            self.basis_ax.set_xlim(a, b)
            self.blitter.forget_background()
        for i, line in enumerate(self.basis):
            if i < s["basis"].shape[1]:
                line.set_data(s["t"], s["basis"][:, i])
                line.set_linewidth(2.8 if i == k else 1.0)
                line.set_color("C1" if i == k else "0.55")
            else:
                line.set_data([], [])
        lo, hi = s["support"]
        self.span.set_x(lo)
        self.span.set_width(hi - lo)
        inside = s["knots"][(s["knots"] >= a) & (s["knots"] <= b)]
        self.knot_marks.set_data(inside, np.zeros_like(inside))
        self.info.value = s["text"]
