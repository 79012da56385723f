"""Chapter 7, interpolating curves: the C2 spline (Thomas algorithm + Hermite evaluation) against
scipy's CubicSpline, the piecewise Hermite curve against CubicHermiteSpline, Catmull-Rom against
CubicHermiteSpline with the same tangents, and the interpolation explorer's updates."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """Fit + evaluate a natural spline through N points (N samples), a Hermite curve and a
    Catmull-Rom spline on N points, ours against scipy.interpolate."""
    from scipy.interpolate import CubicHermiteSpline, CubicSpline

    from course_lib.curves import interpolating as ip

    count = 10_000 if quick else 100_000
    rng = np.random.default_rng(0)
    points = np.cumsum(rng.normal(size=(count, 2)), axis=0)
    nodes = ip.parameterize(points, "chord")
    t = np.linspace(nodes[0], nodes[-1], count)
    tangents = rng.normal(size=points.shape)
    repeat = 3 if quick else 10
    rows = [
        operation_row(f"natural cubic spline through {count:,} points, fit + {count:,} samples",
                      count, lambda: ip.cubic_spline(points, t, nodes, "natural"),
                      lambda: CubicSpline(nodes, points, bc_type="natural")(t),
                      "scipy CubicSpline (natural)", repeat),
        operation_row(f"not-a-knot cubic spline through {count:,} points, fit + {count:,} "
                      "samples", count, lambda: ip.cubic_spline(points, t, nodes, "not-a-knot"),
                      lambda: CubicSpline(nodes, points, bc_type="not-a-knot")(t),
                      "scipy CubicSpline (not-a-knot)", repeat),
        operation_row(f"piecewise Hermite curve, {count:,} points, {count:,} samples", count,
                      lambda: ip.hermite_curve(points, tangents, t, nodes),
                      lambda: CubicHermiteSpline(nodes, points, tangents)(t),
                      "scipy CubicHermiteSpline", repeat),
        operation_row(f"Catmull-Rom (centripetal), {count:,} points, {count:,} samples", count,
                      lambda: ip.catmull_rom(points, t, nodes),
                      lambda: CubicHermiteSpline(nodes, points,
                                                 ip.cardinal_tangents(points, 0.5, nodes))(t),
                      "scipy CubicHermiteSpline with our tangents", repeat),
    ]
    return rows


def widgets(quick=False):
    """Median update of the interpolation explorer: dragging a point (natural spline and the
    polynomial) and the tension slider of the cardinal spline."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import interpolation

    repeat = 5 if quick else 40
    rows = []
    for method in ("natural spline", "polynomial"):
        explorer = interpolation.InterpolationExplorer(
            interpolation.State(method=method, count=7, show_comb=True))
        explorer.fig.canvas.draw()
        start = explorer.state.points[3].copy()
        explorer.drag.press(*start)

        def move(i, explorer=explorer, start=start):
            explorer.drag.move(start[0] + 0.4 * np.cos(0.3 * i), start[1] + 0.4 * np.sin(0.3 * i))
        rows.append(widget_row(f"interpolation explorer, {method}, 7 points (drag)", move,
                               explorer.fig.canvas.draw, repeat, target_ms=40.0))
        plt.close(explorer.fig)
    explorer = interpolation.InterpolationExplorer(interpolation.State(method="cardinal"))
    explorer.fig.canvas.draw()
    rows.append(widget_row("interpolation explorer, cardinal (tension slider)",
                           lambda i: setattr(explorer.tension, "value", 0.05 * (i % 30)),
                           explorer.fig.canvas.draw, repeat, target_ms=40.0))
    plt.close(explorer.fig)
    return rows
