r"""Interpolating curves: drag 5-7 points and compare the curves that pass through them.

The methods: the single polynomial through all the points (it wiggles), the piecewise Hermite
cubic with tangents you set by dragging their handles, the C2 cubic spline with natural or
clamped ends (the clamped end tangents are draggable), and the cardinal spline whose tension
``s`` scales the Catmull-Rom tangents (``s = 0.5`` is Catmull-Rom). The parameterisation menu
sets the parameter values :math:`t_i` (uniform, chord length, centripetal). Each tangent is shown
as a handle at :math:`P_i + \frac{\bar h}{3} T_i` (:math:`\bar h` the mean parameter step: where
a Bézier control point of the segment would sit). The curvature comb draws the curvature as
spikes along the normal.
"""
from dataclasses import dataclass, field

import numpy as np

from .. import draw, format as fmt
from ..curves import interpolating as ip
from . import _style
from ._base import Explorer, beside, bind, checkbox, labelled, panel, slider
from ._drag import DraggablePoints

__all__ = ["InterpolationExplorer", "METHODS", "State", "scene"]

METHODS = ("polynomial", "Hermite", "natural spline", "clamped spline", "cardinal")
LIMITS = (-0.5, 6.5)
PER_SEGMENT = 40
COMB_EVERY = 3
COMB_SCALE = 0.3
COMB_MAX = 1.2


def _default_points():
    return np.array([[0.3, 1.0], [1.2, 3.6], [2.4, 4.6], [3.2, 2.0], [4.6, 1.4], [5.4, 4.2],
                     [6.1, 5.6]])


def _default_offsets():
    p = _default_points()
    return ip.cardinal_tangents(p, 0.5) / 3.0         # Catmull-Rom tangents, uniform (h = 1)


def _default_ends():
    return np.array([[0.0, 1.2], [0.6, 0.6]])


@dataclass
class State:
    """The points, the method, its parameters and what to show.

    ``points`` holds 7 positions, the first ``count`` are used. ``offsets`` are the Hermite
    handles (handle minus point, per point), ``end_offsets`` the two clamped-end handles.

    Examples
    --------
    >>> State().method, State().count, State().points.shape
    ('natural spline', 6, (7, 2))
    """

    points: np.ndarray = field(default_factory=_default_points)
    count: int = 6
    method: str = "natural spline"
    params: str = "chord"
    tension: float = 0.5
    offsets: np.ndarray = field(default_factory=_default_offsets)
    end_offsets: np.ndarray = field(default_factory=_default_ends)
    show_comb: bool = False


def _tangents(state, p, nodes, scale):
    """Exact tangents at the points for the Hermite-based methods (None for the polynomial)."""
    if state.method == "Hermite":
        return state.offsets[:len(p)] / scale
    if state.method == "natural spline":
        return ip.spline_tangents(p, nodes, "natural")
    if state.method == "clamped spline":
        return ip.spline_tangents(p, nodes, "clamped", state.end_offsets / scale)
    if state.method == "cardinal":
        return ip.cardinal_tangents(p, state.tension, nodes)
    return None


def scene(state):
    """Pure part: the curve through the points, the tangent handles, the curvature comb, text.

    Returns
    -------
    dict
        ``points`` (n x 2), ``nodes`` (the parameter values), ``curve`` (samples, the points
        among them: ``curve[::PER_SEGMENT] == points``), ``tangents`` (at the points),
        ``handles`` (n x 2; at the points for the polynomial, whose tangents are not chosen
        but follow), ``draggable`` (indices of the handles that can be dragged),
        ``comb`` (polyline with NaN breaks: spikes of length COMB_SCALE x curvature, at most
        COMB_MAX, on the outside of the bend), ``overshoot`` (how far the curve leaves the points'
        bounding box) and ``text``.

    Examples
    --------
    >>> s = scene(State(method="polynomial", params="uniform"))
    >>> s["curve"].shape, bool(np.allclose(s["curve"][::PER_SEGMENT], s["points"]))
    ((201, 2), True)
    """
    p = np.asarray(state.points, dtype=float)[:int(state.count)]
    n = len(p) - 1
    nodes = ip.parameterize(p, state.params)
    scale = (nodes[-1] - nodes[0]) / n / 3.0
    u = np.linspace(0.0, 1.0, PER_SEGMENT + 1)[:-1]
    t = np.concatenate([nodes[:-1, None] + u * np.diff(nodes)[:, None], nodes[-1:, None]],
                       axis=None)
    tangents = _tangents(state, p, nodes, scale)
    if tangents is None:
        curve = ip.polynomial_curve(p, t, nodes)
        tangents = ip.lagrange_basis(nodes, nodes + 1e-6) @ p - p
        tangents = tangents / 1e-6                       # forward difference: display only
    else:
        curve = ip.hermite_curve(p, tangents, t, nodes)
    handles = p + scale * tangents if state.method != "polynomial" else p.copy()
    draggable = {"Hermite": np.arange(n + 1), "clamped spline": np.array([0, n])}.get(
        state.method, np.zeros(0, int))
    d1 = np.gradient(curve, t, axis=0)
    d2 = np.gradient(d1, t, axis=0)
    speed = np.maximum(np.linalg.norm(d1, axis=1), 1e-12)
    kappa = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / speed ** 3
    normal = np.column_stack([-d1[:, 1], d1[:, 0]]) / speed[:, None]
    k = slice(0, None, COMB_EVERY)
    spike = np.clip(COMB_SCALE * kappa[k], -COMB_MAX, COMB_MAX)
    tips = curve[k] - spike[:, None] * normal[k]
    comb = np.stack([curve[k], tips, np.full_like(tips, np.nan)], axis=1).reshape(-1, 2)
    lo, hi = p.min(axis=0), p.max(axis=0)
    overshoot = float(np.max(np.maximum(curve - hi, lo - curve)))
    hit = ip.passes_through(curve, p, atol=1e-9)
    what = {"polynomial": f"one polynomial of degree {n} through all {n + 1} points (no "
                          "tangents to choose; with many points it swings between them)",
            "Hermite": "a Hermite cubic per segment: point and tangent given at both ends "
                       "(drag the handles); C1",
            "natural spline": "the C2 cubic spline with zero second derivative at both ends: "
                              "every tangent comes out of one tridiagonal system",
            "clamped spline": "the C2 cubic spline with given end tangents (drag the two end "
                              "handles); the inner tangents solve the system",
            "cardinal": f"tangents from the neighbours, T_i = 2s × (parabola slope), s = "
                        f"{fmt.number(state.tension, 2)}"
                        + (" (Catmull-Rom)" if abs(state.tension - 0.5) < 1e-9 else "")
                        + "; local, C1"}[state.method]
    text = (f"<b>{state.method}</b>, {state.params} parameters t = "
            + ", ".join(fmt.number(v, 2) for v in nodes) + f": {what}. Passes through "
            f"{int(hit.sum())} of {n + 1} points (interpolation). It leaves the points' "
            f"bounding box by {fmt.number(max(overshoot, 0.0), 2)}; largest |curvature| "
            f"{fmt.number(float(np.abs(kappa).max()), 2)}.")
    return {"points": p, "nodes": nodes, "curve": curve, "tangents": tangents,
            "handles": handles, "draggable": draggable, "comb": comb,
            "overshoot": overshoot, "scale": scale, "text": text}


class InterpolationExplorer(Explorer):
    """Drag the points (and the tangent handles of the Hermite and clamped curves); choose the
    method, the parameterisation, the tension and the number of points.

    In a notebook, after ``%matplotlib widget``, end a cell with ``InterpolationExplorer()``.

    Examples
    --------
    >>> explorer = InterpolationExplorer()
    >>> explorer.method.value = "polynomial"
    >>> explorer.drag.press(*explorer.state.points[0]); explorer.drag.move(1.0, 1.0)
    >>> explorer.state.points[0].tolist()
    [1.0, 1.0]
    """

    summary = ("Interpolating curves (interactive): drag the points and tangent handles; the "
               "polynomial, Hermite, natural and clamped splines and cardinal / Catmull-Rom "
               "splines with uniform, chord-length or centripetal parameters.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(4.6, 4.6))
        ax = self.fig.add_subplot()
        self.fig.subplots_adjust(left=0.1, right=0.98, bottom=0.08, top=0.94)
        draw.setup_axes_2d(ax, LIMITS, title="A curve through the points")
        self.ax = ax
        (self.comb,) = ax.plot([], [], color="#ef9a9a", lw=0.8, zorder=2, label="curvature comb")
        (self.polygon,) = ax.plot([], [], ":", color="0.6", lw=1, zorder=2)
        (self.curve,) = ax.plot([], [], color="C0", lw=2.2, zorder=4, label="curve")
        (self.arms,) = ax.plot([], [], color="C2", lw=1.2, zorder=5, label="tangent handles")
        (self.handles,) = ax.plot([], [], "s", color="C2", ms=6, zorder=6)
        (self.controls,) = ax.plot([], [], "o", color="0.2", ms=8, mec="white", zorder=7)
        _style.legend(ax, loc="lower right", handlelength=1.5, borderpad=0.3, labelspacing=0.25)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.comb, self.polygon, self.curve, self.arms,
                                               self.handles, self.controls])
        self._scene = scene(self.state)
        self.drag = DraggablePoints(ax, self.state.points[:self.state.count], self._on_drag,
                                    on_release=self.update)
        self.handle_drag = DraggablePoints(ax, self._scene["handles"][self._scene["draggable"]],
                                           self._on_handle, radius=9.0)
        self.method = w.ToggleButtons(options=METHODS, value=self.state.method,
                                      layout=w.Layout(width="330px"),
                                      style={"button_width": _style.button_width(*METHODS)})
        self.params = labelled(w.Dropdown, "parameters", options=list(ip.PARAMETERIZATIONS),
                               value=self.state.params)
        self.tension = slider("tension s", self.state.tension, 0.0, 1.5, 0.05)
        self.count = slider("points", self.state.count, 5, 7, 1, kind=w.IntSlider)
        self.comb_box = checkbox("curvature comb", self.state.show_comb)
        bind(self.state, {"method": self.method, "params": self.params,
                          "tension": self.tension, "count": self.count,
                          "show_comb": self.comb_box}, self._on_control)
        self.info = panel(width="330px")
        controls = w.VBox([self.method, self.params, self.tension, self.count, self.comb_box,
                           self.info])
        self.widget = beside(self.fig.canvas, controls)
        self._draw(self._scene)

    # --- events -----------------------------------------------------------------------------
    def _on_control(self):
        self.drag.set_points(self.state.points[:self.state.count])
        self.update()

    def _on_drag(self, index, xy):
        self.state.points[index] = xy
        self.update()

    def _on_handle(self, index, xy):
        s = self._scene
        i = int(s["draggable"][index])
        offset = np.asarray(xy, dtype=float) - s["points"][i]
        if self.state.method == "Hermite":
            self.state.offsets[i] = offset
        else:
            self.state.end_offsets[0 if i == 0 else 1] = offset
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self._scene = s
        p = s["points"]
        self.controls.set_data(*p.T)
        self.polygon.set_data(*p.T)
        self.curve.set_data(*s["curve"].T)
        arms = np.stack([p, s["handles"], np.full_like(p, np.nan)], axis=1).reshape(-1, 2)
        self.arms.set_data(*arms.T)
        self.handles.set_data(*s["handles"][s["draggable"]].T)
        if self.handle_drag.active is None:
            self.handle_drag.set_points(s["handles"][s["draggable"]])
        self.comb.set_data(*(s["comb"].T if self.state.show_comb else ([], [])))
        self.tension.disabled = self.state.method != "cardinal"      # only it has a tension
        self.info.value = s["text"]
