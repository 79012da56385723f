r"""Surface explorer: a Bézier, B-spline or NURBS patch in 3D with its control net.

A tensor-product patch :math:`S(u, v) = \sum_i \sum_j B_i(u) B_j(v) P_{ij}` (Bernstein or
B-spline basis functions; with weights, the rational form) is drawn with pyvista, off screen,
together with its control net and iso-parameter lines (curves of constant u or v). Sliders pick
one control point and move it, or change its weight; the camera turns with two more sliders.
Moving a point of a Bézier patch changes the whole patch; of a B-spline patch only the part over
the point's support.
"""
from dataclasses import dataclass

import numpy as np

from .. import curves, draw, surfaces
from .._validate import as_choice
from . import _style
from ._base import PlotterExplorer, align, beside, bind, labelled, panel, slider

__all__ = ["KINDS", "State", "SurfaceExplorer", "control_grid", "scene"]

KINDS = ("Bézier", "B-spline", "NURBS")
SIZE = 8                                   # control points per direction
SAMPLES = 36
DEGREE = 2


def control_grid():
    """The patch's starting control grid: a gentle wave over [-1.5, 1.5]^2, shape (8, 8, 3).

    Examples
    --------
    >>> control_grid().shape
    (8, 8, 3)
    """
    x = np.linspace(-1.5, 1.5, SIZE)
    xx, yy = np.meshgrid(x, x, indexing="ij")
    zz = 0.35 * np.sin(1.6 * xx) * np.cos(1.3 * yy)
    return np.stack([xx, yy, zz], axis=-1)


@dataclass
class State:
    """The patch type, the selected control point and how far it is lifted, its weight, the
    camera.

    Examples
    --------
    >>> State().kind
    'B-spline'
    """

    kind: str = "B-spline"
    i: int = 3
    j: int = 4
    lift: float = 1.0
    weight: float = 1.0
    azimuth: float = 30.0
    elevation: float = 25.0


def scene(state):
    """Pure part: the control grid with the selected point lifted, the patch and its iso lines.

    Returns
    -------
    dict
        ``grid`` (8x8x3 control points), ``weights`` (8x8), ``surface`` (SAMPLES x SAMPLES x 3),
        ``iso_u`` and ``iso_v`` (iso-parameter lines), ``selected`` (the point), ``changed``
        (bool SAMPLES x SAMPLES: where the patch differs from the unlifted one) and ``text``.

    Examples
    --------
    >>> bez = scene(State(kind="Bézier"))
    >>> bsp = scene(State(kind="B-spline"))
    >>> inner = (slice(1, -1), slice(1, -1))         # the boundary curves ignore inner points
    >>> bool(bez["changed"][inner].all()), bool(bsp["changed"][inner].all())   # global vs local
    (True, False)
    """
    as_choice(state.kind, "kind", KINDS)
    base = control_grid()
    grid = base.copy()
    grid[state.i, state.j, 2] += state.lift
    weights = np.ones((SIZE, SIZE))
    if state.kind == "NURBS":
        weights[state.i, state.j] = state.weight
    u = np.linspace(0.0, 1.0, SAMPLES)
    knots = curves.clamped_knots(SIZE, DEGREE)

    def evaluate(g, us, vs):
        if state.kind == "Bézier":
            return surfaces.bezier_surface(g, us, vs)
        if state.kind == "B-spline":
            return surfaces.bspline_surface(g, knots, knots, DEGREE, DEGREE, us, vs)
        return surfaces.nurbs_surface(g, weights, knots, knots, DEGREE, DEGREE, us, vs)

    surface = evaluate(grid, u, u)
    before = evaluate(base, u, u)
    changed = np.linalg.norm(surface - before, axis=-1) > 0     # exactly 0 outside the support
    iso_u, iso_v = surfaces.isoparametric_lines(lambda a, b: evaluate(grid, a, b), 7, 7,
                                                samples=40)
    if state.kind == "Bézier":
        reach = "the whole patch: every Bernstein basis function is non-zero inside (0, 1)"
    else:
        lo_u, hi_u = knots[state.i], knots[state.i + DEGREE + 1]
        lo_v, hi_v = knots[state.j], knots[state.j + DEGREE + 1]
        reach = (f"only u in [{lo_u:.2f}, {hi_u:.2f}) × v in [{lo_v:.2f}, {hi_v:.2f}): the "
                 f"support of B_{state.i}(u) B_{state.j}(v) — local control")
    text = (f"{state.kind} patch of degree {DEGREE if state.kind != 'Bézier' else SIZE - 1} × "
            f"{DEGREE if state.kind != 'Bézier' else SIZE - 1}, {SIZE} × {SIZE} control points. "
            f"Lifting P[{state.i}, {state.j}] moves {reach} "
            f"({100 * changed.mean():.0f} % of the sampled patch moved).")
    if state.kind == "NURBS":
        text += (f" Its weight {state.weight:.2f} "
                 + ("pulls the patch towards it." if state.weight > 1 else
                    "pushes the patch away from it." if state.weight < 1 else "is neutral."))
    return {"grid": grid, "weights": weights, "surface": surface, "iso_u": iso_u,
            "iso_v": iso_v, "selected": grid[state.i, state.j], "changed": changed,
            "text": text}


def _structured_points(array):
    """Points of an (a, b, 3) array in the order pyvista's StructuredGrid stores them."""
    return np.column_stack([array[..., k].ravel(order="F") for k in range(3)])


def _polyline_cells(lines):
    """A pyvista `lines` array for a stack of polylines of equal length, shape (k, m, 3)."""
    k, m = lines.shape[:2]
    ids = np.arange(k * m).reshape(k, m)
    return np.column_stack([np.full(k, m), ids]).ravel()


class SurfaceExplorer(PlotterExplorer):
    """Pick a control point and lift it, change its weight, switch the patch type, turn the view.

    The picture is rendered by pyvista off screen and shown on a matplotlib canvas
    (:meth:`PlotterExplorer.screen`), so it works wherever the notebook runs (no GPU or display
    needed).

    Examples
    --------
    >>> explorer = SurfaceExplorer()
    >>> explorer.kind.value = "Bézier"
    >>> "whole patch" in explorer.info.value, explorer.png()[:4]
    (True, b'\\x89PNG')
    """

    summary = ("Surface explorer (interactive): a Bézier / B-spline / NURBS patch with its control "
               "net and iso-parameter lines; lift a control point, change its weight.")

    def __init__(self, state=None):
        import ipywidgets as w

        draw.configure_offscreen_vtk()
        import pyvista as pv

        self.state = state or State()
        s = scene(self.state)
        self.plotter = draw.offscreen_plotter(440, 360)
        self.patch = pv.StructuredGrid(*[s["surface"][..., k] for k in range(3)])
        self.patch["moved"] = s["changed"].ravel(order="F").astype(float)
        self.plotter.add_mesh(self.patch, scalars="moved", cmap=["#f5a623", "#4a90d9"],
                              clim=(0, 1), smooth_shading=True, show_scalar_bar=False,
                              opacity=0.9)
        self.net = pv.StructuredGrid(*[s["grid"][..., k] for k in range(3)])
        self.plotter.add_mesh(self.net, style="wireframe", color="#404040", line_width=1.5)
        self.points = pv.PolyData(s["grid"].reshape(-1, 3))
        self.plotter.add_mesh(self.points, color="#333333", point_size=8,
                              render_points_as_spheres=True)
        self.marker = pv.PolyData(s["selected"][None])
        self.plotter.add_mesh(self.marker, color="#d0021b", point_size=16,
                              render_points_as_spheres=True)
        lines = np.concatenate([s["iso_u"], s["iso_v"]])
        self.iso = pv.PolyData(lines.reshape(-1, 3), lines=_polyline_cells(lines))
        self.plotter.add_mesh(self.iso, color="#595959", line_width=1)
        self._set_camera()
        screen = self.screen()
        self.kind = w.ToggleButtons(options=KINDS, value=self.state.kind,
                                    style={"button_width": _style.button_width(*KINDS)})
        self.i = slider("point i", self.state.i, 0, SIZE - 1, 1, kind=w.IntSlider)
        self.j = slider("point j", self.state.j, 0, SIZE - 1, 1, kind=w.IntSlider)
        self.lift = slider("lift z", self.state.lift, -1.5, 1.5, 0.05)
        self.weight = labelled(w.FloatLogSlider, "weight", value=self.state.weight, base=10,
                               min=-1, max=1, step=0.02)
        self.azimuth = slider("view azimuth °", self.state.azimuth, -180, 180, 2)
        self.elevation = slider("view elevation °", self.state.elevation, -10, 80, 2)
        self.turned_by = (self.azimuth, self.elevation)    # and a drag across the view
        align([self.i, self.j, self.lift, self.weight, self.azimuth, self.elevation])
        bind(self.state, {"kind": self.kind, "i": self.i, "j": self.j, "lift": self.lift,
                          "weight": self.weight, "azimuth": self.azimuth,
                          "elevation": self.elevation}, self._on_change)
        self.info = panel(width="360px")
        self.widget = beside(screen, w.VBox([self.kind, self.i, self.j, self.lift,
                                                 self.weight, self.azimuth, self.elevation,
                                                 self.info]), align="flex-start")
        self.weight.disabled = self.state.kind != "NURBS"
        self._draw(s)

    def _set_camera(self):
        """Place the camera on a sphere around the patch at the state's azimuth and elevation."""
        a, e = np.radians([self.state.azimuth - 90.0, self.state.elevation])
        eye = 6.5 * np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
        self.plotter.camera_position = [tuple(eye), (0.0, 0.0, 0.2), (0.0, 0.0, 1.0)]

    def _on_change(self):
        self.weight.disabled = self.state.kind != "NURBS"    # only a rational patch has weights
        self.update()

    def update(self):
        """Recompute the scene, move the pyvista meshes and render a new picture."""
        self._draw(scene(self.state))

    def _draw(self, s):
        self.patch.points = _structured_points(s["surface"])
        self.patch["moved"] = s["changed"].ravel(order="F").astype(float)
        self.net.points = _structured_points(s["grid"])
        self.points.points = s["grid"].reshape(-1, 3)
        self.marker.points = s["selected"][None]
        lines = np.concatenate([s["iso_u"], s["iso_v"]])
        self.iso.points = lines.reshape(-1, 3)
        self._set_camera()
        self.show()
        self.info.value = s["text"] + (" Blue: the part of the patch the lift moved.")
