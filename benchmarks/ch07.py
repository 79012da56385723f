"""Chapter 7: Bézier, B-spline and NURBS evaluation against scipy, geomdl and `bezier`.

geomdl is pure Python (one parameter value at a time), so its rows use fewer repeats; the
`bezier` package and geomdl are test-only references (installed with the test extras).
The topic files of the chapter follow: continuity, curvature and the matrix form
(ch07_continuity), interpolating curves against scipy (ch07_interpolating).
"""
import numpy as np

from benchmarks import median_time, operation_row


def _row(name, size, ours, reference, reference_name, repeat, reference_repeat):
    """operation_row with fewer repeats for a slow reference (one warm-up run each)."""
    t_ours = median_time(ours, repeat)
    t_ref = median_time(reference, reference_repeat, warmup=1)
    return {"operation": name, "size": size, "ours_ms": 1e3 * t_ours,
            "reference": reference_name, "reference_ms": 1e3 * t_ref, "ratio": t_ours / t_ref}


def operations(quick=False):
    import bezier
    from geomdl import BSpline as GeomdlBSpline
    from geomdl import NURBS as GeomdlNURBS
    from scipy.interpolate import BSpline, NdBSpline

    from course_lib import curves, surfaces

    m = 500 if quick else 10_000                 # parameter values along a curve
    side = 10 if quick else 100                  # surface grid side
    repeat = 3 if quick else 25
    slow_repeat = 1 if quick else 3
    rng = np.random.default_rng(2026)

    # B-spline curve: 20 control points in 3D, degree 3, clamped knots
    points = rng.normal(size=(20, 3))
    knots = curves.clamped_knots(20, 3)
    t = np.linspace(0.0, 1.0, m)
    geomdl_curve = GeomdlBSpline.Curve()
    geomdl_curve.degree = 3
    geomdl_curve.ctrlpts = points.tolist()
    geomdl_curve.knotvector = knots.tolist()
    t_list = t.tolist()

    # NURBS curve (homogeneous coordinates in scipy)
    weights = rng.uniform(0.5, 2.0, 20)
    homogeneous = np.c_[points * weights[:, None], weights]

    def scipy_nurbs():
        h = BSpline(knots, homogeneous, 3, extrapolate=False)(t)
        return h[:, :3] / h[:, 3:]

    # Bézier curve of degree 7
    nodes = rng.normal(size=(8, 3))
    bezier_curve = bezier.Curve(nodes.T, degree=7)

    # NURBS surface: a 10 x 10 control grid, bicubic, on a side x side grid of (u, v)
    grid = surfaces.wave_grid(10, 10)
    grid_weights = rng.uniform(0.5, 2.0, (10, 10))
    kn = curves.clamped_knots(10, 3)
    uv = np.linspace(0.0, 1.0, side)
    h_grid = np.concatenate([grid * grid_weights[..., None], grid_weights[..., None]], axis=-1)
    nd = NdBSpline((kn, kn), h_grid, (3, 3), extrapolate=False)
    xi = np.stack(np.meshgrid(uv, uv, indexing="ij"), axis=-1)

    def scipy_nurbs_surface():
        h = nd(xi)
        return h[..., :3] / h[..., 3:]

    geomdl_surface = GeomdlNURBS.Surface()
    geomdl_surface.degree_u = geomdl_surface.degree_v = 3
    geomdl_surface.ctrlpts_size_u = geomdl_surface.ctrlpts_size_v = 10
    geomdl_surface.ctrlptsw = h_grid.reshape(-1, 4).tolist()
    geomdl_surface.knotvector_u = geomdl_surface.knotvector_v = kn.tolist()
    geomdl_surface.sample_size = side             # evaluate() recomputes the side x side grid

    rows = [
        operation_row("B-spline curve (20 points 3D, degree 3)", m,
                      lambda: curves.bspline(points, knots, 3, t),
                      lambda: BSpline(knots, points, 3, extrapolate=False)(t), "scipy BSpline",
                      repeat),
        _row("B-spline curve (20 points 3D, degree 3)", m,
             lambda: curves.bspline(points, knots, 3, t),
             lambda: geomdl_curve.evaluate_list(t_list), "geomdl evaluate_list", repeat,
             slow_repeat),
        operation_row("NURBS curve (20 points 3D, degree 3)", m,
                      lambda: curves.nurbs(points, weights, knots, 3, t), scipy_nurbs,
                      "scipy BSpline, homogeneous", repeat),
        operation_row("Bezier curve (degree 7, 3D)", m, lambda: curves.bezier(nodes, t),
                      lambda: bezier_curve.evaluate_multi(t), "bezier evaluate_multi", repeat),
        operation_row("NURBS surface (10x10 bicubic) on a grid", side * side,
                      lambda: surfaces.nurbs_surface(grid, grid_weights, kn, kn, 3, 3, uv, uv),
                      scipy_nurbs_surface, "scipy NdBSpline, homogeneous", repeat),
        _row("NURBS surface (10x10 bicubic) on a grid", side * side,
             lambda: surfaces.nurbs_surface(grid, grid_weights, kn, kn, 3, 3, uv, uv),
             geomdl_surface.evaluate, "geomdl evaluate", repeat, slow_repeat),
    ]
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch07_continuity, ch07_interpolating

    return (ch07_continuity, ch07_interpolating,)


def widgets(quick=False):
    """Median update of each editor while the student drags (10 control points, 200 samples
    for the Bézier editor; 10 points and 300 samples for the B-spline one; target 30 ms)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import bezier, bspline, surface

    repeat = 5 if quick else 40
    rows = []
    for name, explorer in (("Bézier editor, 10 points (drag)", bezier.BezierExplorer()),
                           ("B-spline / NURBS editor, 10 points (drag)",
                            bspline.BSplineExplorer())):
        while len(explorer.state.points) < 10:
            explorer.add_point()
        explorer.fig.canvas.draw()
        start = explorer.state.points[4].copy()
        explorer.drag.press(*start)

        def move(i, explorer=explorer, start=start):
            explorer.drag.move(start[0] + 0.4 * np.cos(0.3 * i), start[1] + 0.4 * np.sin(0.3 * i))
        rows.append(widget_row(name, move, explorer.fig.canvas.draw, repeat, target_ms=30.0))
        plt.close(explorer.fig)
    explorer = surface.SurfaceExplorer()
    rows.append(widget_row("surface explorer (lift slider, pyvista off screen)",
                           lambda i: setattr(explorer.lift, "value", -1.0 + 0.05 * (i % 40)),
                           lambda: explorer.png(), repeat))
    explorer.plotter.close()
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
