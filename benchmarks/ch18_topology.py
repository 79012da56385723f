"""Chapter 18, vector-field topology: the critical points of a 256 x 256 field (exact cell-wise
bilinear zeros) against Newton's method per candidate cell with scipy.optimize.fsolve, gridded
RK4 streamlines (all seeds advanced together) against scipy.integrate.solve_ivp on a
RegularGridInterpolator, and the flow-topology explorer's update."""
import numpy as np

from benchmarks import operation_row


def _wavy_field(n):
    """An n x n field on [0, 1]^2 with a few hundred critical points."""
    from course_lib.scivis.topology import gridded_field

    axis = np.linspace(0.0, 1.0, n)
    x, y = np.meshgrid(axis, axis)
    u = np.sin(60 * x + 1) * np.cos(47 * y) + 0.2 * np.sin(5 * y)
    v = np.cos(53 * x) * np.sin(61 * y + 0.5) - 0.1 * x
    return gridded_field(u, v, axis[1] - axis[0], (0.0, 0.0)), axis


def operations(quick=False):
    """Critical points: ours vs per-cell fsolve; streamlines: ours vs solve_ivp."""
    from scipy.integrate import solve_ivp
    from scipy.interpolate import RegularGridInterpolator
    from scipy.optimize import fsolve

    from course_lib.scivis.topology import critical_points, integrate_gridded

    rows = []
    n = 128 if quick else 256
    f, axis = _wavy_field(n)
    g = f.values
    h = axis[1] - axis[0]
    corners = np.stack([g[:-1, :-1], g[:-1, 1:], g[1:, :-1], g[1:, 1:]], axis=2)
    cand = np.argwhere(((corners.min(axis=2) <= 0) & (corners.max(axis=2) >= 0)).all(axis=-1))

    def newton_cells():
        found = []
        for j, i in cand:
            c00, c10, c01, c11 = g[j, i], g[j, i + 1], g[j + 1, i], g[j + 1, i + 1]

            def residual(st):
                s, t = st
                return (1 - s) * (1 - t) * c00 + s * (1 - t) * c10 + (1 - s) * t * c01 \
                    + s * t * c11
            st, _, ok, _ = fsolve(residual, [0.5, 0.5], full_output=True)
            if ok == 1 and (-1e-9 <= st).all() and (st <= 1 + 1e-9).all():
                found.append([axis[i] + h * st[0], axis[j] + h * st[1]])
        return found

    rows.append(operation_row(f"critical points of a {n} x {n} field "
                              f"({len(critical_points(f))} found)", n * n,
                              lambda: critical_points(f), newton_cells,
                              "scipy.optimize.fsolve (Newton) in each candidate cell",
                              3 if quick else 10))

    rng = np.random.default_rng(0)
    k = 10 if quick else 50
    seeds = rng.uniform(0.2, 0.8, (k, 2))
    step, steps = 0.002, 150
    interp = [RegularGridInterpolator((axis, axis), g[..., c]) for c in range(2)]

    def rhs(t, p):
        q = np.clip(p[::-1], 0.0, 1.0)[None]
        return [interp[0](q)[0], interp[1](q)[0]]

    def reference():
        return [solve_ivp(rhs, (0, step * steps), s, rtol=1e-6, atol=1e-9).y[:, -1]
                for s in seeds]

    rows.append(operation_row(f"{k} RK4 streamlines of {steps} steps in a {n} x {n} grid", k,
                              lambda: integrate_gridded(f, seeds, step, steps, "rk4"),
                              reference, "scipy solve_ivp (RK45) on RegularGridInterpolator",
                              3 if quick else 10))
    return rows


def widgets(quick=False):
    """Median update of the flow-topology explorer: a field parameter (new field, critical
    points, separatrices), the seed dragged (one gridded streamline) and the method."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets.flow_topology import FlowTopologyExplorer, State

    repeat = 5 if quick else 40
    rows = []
    ex = FlowTopologyExplorer(State(preset="linear", p=-1.0, q=1.25, seed=np.array([1.2, 0.6])))
    ex.fig.canvas.draw()
    dets = np.round(np.linspace(-1.5, 2.5, 41), 2)
    rows.append(widget_row("flow topology explorer (determinant slider)",
                           lambda i: setattr(ex.q, "value", float(dets[i % len(dets)])),
                           ex.fig.canvas.draw, repeat))
    ex.q.value = 1.25
    path = np.column_stack([np.linspace(-1.2, 1.2, 37), np.linspace(1.0, -1.0, 37)])

    def drag(i):
        ex.drag.press(*ex.drag.points[0])
        ex.drag.move(*path[i % len(path)])
        ex.drag.release()

    rows.append(widget_row("flow topology explorer (seed dragged)", drag, ex.fig.canvas.draw,
                           repeat))
    methods = ("euler", "rk2", "rk4")
    rows.append(widget_row("flow topology explorer (method)",
                           lambda i: setattr(ex.method, "value", methods[i % 3]),
                           ex.fig.canvas.draw, repeat))
    ex.preset.value = "saddle and two foci"
    ks = np.round(np.linspace(0.1, 1.4, 27), 2)
    rows.append(widget_row("flow topology explorer (Duffing stiffness)",
                           lambda i: setattr(ex.p, "value", float(ks[i % len(ks)])),
                           ex.fig.canvas.draw, repeat))
    plt.close(ex.fig)
    return rows
