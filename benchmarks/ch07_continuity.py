"""Chapter 7, curve basics: curvature combs against numpy finite differences of the curve, the
matrix form of cubic B-splines against scipy's BSpline, and the continuity explorer's drag."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """Curvature of a cubic Bézier curve at N parameters (hodographs vs central differences of
    ``bezier``), and N points of a uniform cubic B-spline span by T·M·G (vs scipy BSpline)."""
    from scipy.interpolate import BSpline

    from course_lib import curves

    rows = []
    count = 10_000 if quick else 1_000_000
    P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.0]])
    t = np.linspace(0.01, 0.99, count)

    def finite_differences():
        h = 1e-4
        a, b, c = curves.bezier(P, t - h), curves.bezier(P, t), curves.bezier(P, t + h)
        d1, d2 = (c - a) / (2 * h), (c - 2 * b + a) / h ** 2
        return np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.hypot(*d1.T) ** 3

    rows.append(operation_row(f"curvature of a cubic Bézier at {count:,} parameters", count,
                              lambda: curves.bezier_curvature(P, t), finite_differences,
                              "central differences of curves.bezier", 3 if quick else 10))
    G = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.0]])
    spline = BSpline(np.arange(8.0), G, 3)
    rows.append(operation_row(f"uniform cubic B-spline span by T·M·G, {count:,} points", count,
                              lambda: curves.cubic_matrix_eval("bspline", G, t),
                              lambda: spline(3.0 + t), "scipy BSpline", 3 if quick else 10))
    return rows


def widgets(quick=False):
    """Median update of the continuity explorer while a control point of the first segment is
    dragged with G2 imposed (the second segment's constrained points and both combs follow)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets.continuity import ContinuityExplorer

    repeat = 5 if quick else 40
    explorer = ContinuityExplorer()
    explorer.mode.value = "G2"
    explorer.fig.canvas.draw()
    start = explorer.state.P[2].copy()

    def move(i):
        explorer.drag.active = 2
        explorer.drag.move(*(start + [0.02 * (i % 20), -0.01 * (i % 20)]))

    rows = [widget_row("continuity explorer (drag P2, G2 imposed)", move,
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows


def run(quick=False):
    """Both tables, for a quick look: ``{"operations": [...], "widgets": [...]}``."""
    return {"operations": operations(quick), "widgets": widgets(quick)}
