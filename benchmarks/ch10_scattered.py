"""Chapter 10, scattered data: interpolating n scattered samples of Franke's function onto an
m x m grid with course_lib.dataviz against scipy, and the scattered-data explorer's updates.

* nearest neighbour (buckets and a radius search) against ``griddata(method="nearest")``
  (a k-d tree);
* linear on the Delaunay triangulation (our Bowyer-Watson in numpy, then bucketed point
  location) against ``griddata(method="linear")`` (Qhull, compiled);
* Shepard's inverse-distance weighting, global (n x m^2 distances, in chunks) and local
  (radius search): scipy has no Shepard, so the reference is ``griddata`` linear on the same
  data and grid, the usual alternative;
* radial basis functions, local (each query fitted to its 50 nearest samples, the small systems
  solved in batches) against ``RBFInterpolator(neighbors=50)`` with the same kernel, shape and
  polynomial; and global on the largest size we accept (a dense n x n system) against
  ``RBFInterpolator`` without neighbours, which solves the same system.
"""
import numpy as np

from benchmarks import operation_row


def _franke(p):
    x, y = p[:, 0], p[:, 1]
    return (0.75 * np.exp(-((9 * x - 2) ** 2 + (9 * y - 2) ** 2) / 4)
            + 0.75 * np.exp(-(9 * x + 1) ** 2 / 49 - (9 * y + 1) / 10)
            + 0.5 * np.exp(-((9 * x - 7) ** 2 + (9 * y - 3) ** 2) / 4)
            - 0.2 * np.exp(-(9 * x - 4) ** 2 - (9 * y - 7) ** 2))


def operations(quick=False):
    """Scattered-data interpolation of n samples onto an m x m grid: 10,000 samples and
    100 x 100 (quick: 2,000 and 50 x 50)."""
    from scipy.interpolate import RBFInterpolator, griddata
    from scipy.spatial import Delaunay

    from course_lib.dataviz import scattered

    n, m = (2_000, 50) if quick else (10_000, 100)
    repeat = 1 if quick else 3
    rng = np.random.default_rng(10)
    points = rng.uniform(size=(n, 2))
    values = _franke(points)
    axis = np.linspace(0, 1, m)
    grid = np.stack(np.meshgrid(axis, axis), axis=-1).reshape(-1, 2)
    size = f"{n:,} samples -> {m}x{m} grid"
    linear_ref = (lambda: griddata(points, values, grid, method="linear"))
    rows = [
        operation_row(f"nearest neighbour, {size}", n,
                      lambda: scattered.nearest_interpolate(points, values, grid),
                      lambda: griddata(points, values, grid, method="nearest"),
                      "scipy griddata nearest (k-d tree)", repeat),
        operation_row(f"Delaunay triangulation of {n:,} points (Bowyer-Watson)", n,
                      lambda: scattered.delaunay_triangulation(points),
                      lambda: Delaunay(points), "scipy Delaunay (Qhull)", repeat),
        operation_row(f"linear on the Delaunay triangulation, {size}", n,
                      lambda: scattered.linear_interpolate(points, values, grid,
                                                           outside=np.nan),
                      linear_ref, "scipy griddata linear (Qhull)", repeat),
        operation_row(f"Shepard global, p = 2, {size}", n,
                      lambda: scattered.shepard_interpolate(points, values, grid, power=2),
                      linear_ref, "scipy griddata linear (no Shepard in scipy)", repeat),
    ]
    radius = 3.0 / np.sqrt(n)                          # about 28 samples within the radius
    rows.append(operation_row(
        f"Shepard local (radius {radius:.3f}), {size}", n,
        lambda: scattered.shepard_interpolate(points, values, grid, power=2, radius=radius),
        linear_ref, "scipy griddata linear (no Shepard in scipy)", repeat))
    eps = 0.5 * np.sqrt(n)                             # bumps about two sample spacings wide
    rows.append(operation_row(
        f"RBF local, Gaussian, 50 neighbours, {size}", n,
        lambda: scattered.rbf_interpolate(points, values, grid, "gaussian", eps, degree=0,
                                          neighbors=50),
        lambda: RBFInterpolator(points, values, kernel="gaussian", epsilon=eps, degree=0,
                                neighbors=50)(grid),
        "scipy RBFInterpolator(neighbors=50)", repeat))
    centres = 500 if quick else scattered.MAX_GLOBAL_RBF_CENTRES
    sub, sub_values = points[:centres], values[:centres]
    rows.append(operation_row(
        f"RBF global, thin-plate spline, {centres:,} centres -> {m}x{m} grid", centres,
        lambda: scattered.rbf_interpolate(sub, sub_values, grid, "thin_plate_spline"),
        lambda: RBFInterpolator(sub, sub_values, kernel="thin_plate_spline")(grid),
        "scipy RBFInterpolator (dense system)", repeat))
    return rows


def widgets(quick=False):
    """Median update of the scattered-data explorer for a setting not seen before (its cache
    cleared before every move: the worst case; a slider moved back is a cache hit)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import scattered as explorer_module

    repeat = 5 if quick else 40
    explorer = explorer_module.ScatteredDataExplorer()
    explorer.fig.canvas.draw()

    def fresh(control, value):
        explorer_module._field.cache_clear()
        explorer_module._edges.cache_clear()
        explorer_module._triangulation.cache_clear()
        control.value = value

    rows = [widget_row("scattered-data explorer (Shepard power slider, 60 samples)",
                       lambda i: fresh(explorer.power, 0.5 + 0.5 * (i % 16)),
                       explorer.fig.canvas.draw, repeat)]
    explorer.method.value = "RBF"
    rows.append(widget_row("scattered-data explorer (RBF shape slider, 60 samples)",
                           lambda i: fresh(explorer.epsilon, 3.0 + 0.5 * (i % 30)),
                           explorer.fig.canvas.draw, repeat))
    explorer.method.value = "linear"
    rows.append(widget_row("scattered-data explorer (samples slider, linear: new Delaunay)",
                           lambda i: fresh(explorer.n_points, 100 + 5 * (i % 20)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
