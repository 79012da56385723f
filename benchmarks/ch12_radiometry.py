"""Chapter 12, radiometry: exact polygon solid angles and polygon-light irradiance (closed forms,
vectorized over points) against scipy's dblquad of the same integrals, and the radiometry
explorer's slider updates."""
import numpy as np

from benchmarks import operation_row


def _quad_solid_angles(poly_origin, u, v, points):
    """The solid angle of the parallelogram origin + s u + t v seen from each point, by dblquad
    of |cos theta| / r^2 over its surface (one integral per point)."""
    from scipy.integrate import dblquad

    n = np.cross(u, v)
    jac = np.linalg.norm(n)
    n = n / jac
    out = []
    for p in points:
        def f(t, s, p=p):
            d = poly_origin + s * u + t * v - p
            r2 = d @ d
            return abs(d @ n) / (r2 * np.sqrt(r2))
        out.append(dblquad(f, 0, 1, 0, 1, epsabs=1e-10, epsrel=1e-8)[0] * jac)
    return np.array(out)


def _quad_irradiance(poly_origin, u, v, points, normal, radiance):
    """Irradiance from the parallelogram light (facing -z) at each point, by dblquad of
    L cos(theta_s) cos(theta_l) / r^2 over the light's area."""
    from scipy.integrate import dblquad

    nl = np.cross(u, v)
    jac = np.linalg.norm(nl)
    nl = nl / jac
    out = []
    for p in points:
        def f(t, s, p=p):
            d = poly_origin + s * u + t * v - p
            r2 = d @ d
            return radiance * max(d @ normal, 0) * max(-d @ nl, 0) / (r2 * r2)
        out.append(dblquad(f, 0, 1, 0, 1, epsabs=1e-10, epsrel=1e-8)[0] * jac)
    return np.array(out)


def operations(quick=False):
    from course_lib import shading

    n_points = 20 if quick else 200
    repeat = 3 if quick else 7
    rng = np.random.default_rng(4)
    points = np.column_stack([rng.uniform(-2, 2, (n_points, 2)), rng.uniform(-1.0, 0.5,
                                                                              n_points)])
    origin, u, v = np.array([-0.5, -0.5, 1.0]), np.array([0.0, 0.8, -0.2]), np.array([1.0, 0, 0.1])
    poly = np.array([origin, origin + u, origin + u + v, origin + v])
    up = np.array([0.0, 0.0, 1.0])
    rows = []
    ours = shading.polygon_solid_angle(poly, points)
    ref = _quad_solid_angles(origin, u, v, points)
    assert np.allclose(ours, ref, rtol=1e-6)
    rows.append(operation_row(f"exact solid angle of a quadrilateral from {n_points} points "
                              "(Van Oosterom-Strackee fan)", n_points,
                              lambda: shading.polygon_solid_angle(poly, points),
                              lambda: _quad_solid_angles(origin, u, v, points),
                              "scipy dblquad per point", repeat))
    ours = shading.polygon_light_irradiance(points, up, poly, 2.0)
    ref = _quad_irradiance(origin, u, v, points, up, 2.0)
    assert np.allclose(ours, ref, rtol=1e-5, atol=1e-9)
    rows.append(operation_row(f"irradiance from a polygon light at {n_points} points "
                              "(Lambert's contour formula, clipped)", n_points,
                              lambda: shading.polygon_light_irradiance(points, up, poly, 2.0),
                              lambda: _quad_irradiance(origin, u, v, points, up, 2.0),
                              "scipy dblquad per point", repeat))
    return rows


def widgets(quick=False):
    """Median update of the radiometry explorer: the light-height slider (the floor's
    irradiance map and the profile) and the patch-tilt slider (the patch and the info panel)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import radiometry

    repeat = 5 if quick else 40
    explorer = radiometry.RadiometryExplorer()
    explorer.fig.canvas.draw()
    rows = [widget_row("radiometry explorer (light height slider)",
                       lambda i: setattr(explorer.height, "value", 0.5 + 0.1 * (i % 35)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("radiometry explorer (patch tilt slider)",
                       lambda i: setattr(explorer.tilt, "value", float(2 * (i % 44))),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
