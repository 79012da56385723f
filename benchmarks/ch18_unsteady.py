"""Chapter 18, unsteady flow and LIC: line integral convolution of a 256 x 256 field against a
straightforward per-pixel Python loop (timed on a subset of the pixels and scaled to the whole
image: the loop over all of them would take minutes), changing the kernel length from the
cached traces (prefix sums) against tracing again, pathlines of many particles against
scipy.integrate.solve_ivp, and the explorers' updates.

No LIC library is installed to compare with (no ``licpy``); VTK's ``vtkImageDataLIC2D`` and
``vtkSurfaceLICMapper`` need an OpenGL context and are not used headless here."""
import math

import numpy as np

from benchmarks import median_time, operation_row


def _loop_lic(u, v, noise, pixels, length, step):
    """The textbook algorithm pixel by pixel: trace both ways (midpoint steps, bilinear
    velocity, unit speed), read the noise at the pixel containing each point, box average."""
    ny, nx = u.shape

    def velocity(x, y):
        x = min(max(x, 0.0), nx - 1.0)
        y = min(max(y, 0.0), ny - 1.0)
        i0, j0 = min(int(y), ny - 2), min(int(x), nx - 2)
        fy, fx = y - i0, x - j0
        out = []
        for comp in (u, v):
            a = comp[i0, j0] + fx * (comp[i0, j0 + 1] - comp[i0, j0])
            b = comp[i0 + 1, j0] + fx * (comp[i0 + 1, j0 + 1] - comp[i0 + 1, j0])
            out.append(a + fy * (b - a))
        s = math.hypot(*out)
        return (out[0] / s, out[1] / s) if s > 1e-9 else None

    n = int(length / step)
    result = []
    for i, j in pixels:
        total, count = noise[i, j], 1
        for sign in (1, -1):
            x, y = float(j), float(i)
            h = sign * step
            for _ in range(n):
                d1 = velocity(x, y)
                if d1 is None:
                    break
                d2 = velocity(x + 0.5 * h * d1[0], y + 0.5 * h * d1[1])
                if d2 is None:
                    break
                x, y = x + h * d2[0], y + h * d2[1]
                if not (-0.5 <= x < nx - 0.5 and -0.5 <= y < ny - 0.5):
                    break
                total += noise[int(math.floor(y + 0.5)), int(math.floor(x + 0.5))]
                count += 1
        result.append(total / count)
    return np.array(result)


def operations(quick=False):
    """LIC vs a per-pixel loop (scaled), a new kernel length from cached traces vs tracing
    again, pathlines vs solve_ivp."""
    from scipy.integrate import solve_ivp

    from course_lib.scivis import LICTraces, lic, unsteady

    rows = []
    n = 128 if quick else 256
    yy, xx = np.mgrid[0:n, 0:n] - (n - 1) / 2
    u, v = -yy - 0.2 * xx, xx - 0.2 * yy
    noise = np.random.default_rng(0).random((n, n))
    length, step = 10.0, 0.5
    subset = [(i, j) for i in range(0, n, n // 4) for j in range(0, n, 1 if quick else 2)]
    ours = lic(u, v, noise, kernel_length=length, step=step)
    check = _loop_lic(u, v, noise, subset[:200], length, step)
    assert np.allclose(check, [ours[i, j] for i, j in subset[:200]], atol=1e-9)
    t_ours = median_time(lambda: lic(u, v, noise, kernel_length=length, step=step),
                         2 if quick else 5, warmup=1)
    t_loop = median_time(lambda: _loop_lic(u, v, noise, subset, length, step), 1, warmup=0)
    scaled = t_loop * n * n / len(subset)
    rows.append({"operation": f"LIC of a {n}x{n} spiral field, L = {length:g} px, step "
                              f"{step:g}", "size": n * n, "ours_ms": 1e3 * t_ours,
                 "reference": f"per-pixel Python loop (timed on {len(subset)} pixels, scaled "
                              f"to {n * n})",
                 "reference_ms": 1e3 * scaled, "ratio": t_ours / scaled})

    traces = LICTraces(u, v, noise, max_length=20.0, step=step)
    lengths = [3.0, 7.5, 12.0, 18.5]
    state = {"i": 0}

    def from_cache():
        state["i"] += 1
        return traces.image(lengths[state["i"] % 4])

    rows.append(operation_row(f"a new kernel length for the {n}x{n} LIC (cached traces, "
                              "prefix sums)", n * n, from_cache,
                              lambda: lic(u, v, noise, kernel_length=lengths[state["i"] % 4],
                                          step=step),
                              "lic() tracing again", 3 if quick else 10))

    field = unsteady.double_gyre()
    k = 50 if quick else 200
    seeds = np.random.default_rng(1).uniform([0.1, 0.1], [1.9, 0.9], size=(k, 2))

    def rhs(t, y):
        return field(y.reshape(-1, 2), t).ravel()

    def reference():
        return solve_ivp(rhs, (0.0, 10.0), seeds.ravel(), method="RK45", rtol=1e-8,
                         atol=1e-10).y[:, -1].reshape(-1, 2)

    mine = unsteady.pathline(field, seeds, 0.0, 10.0, n_steps=200)[:, -1]
    assert np.abs(mine - reference()).max() < 1e-5
    rows.append(operation_row(f"pathlines of {k} particles in the double gyre, t = 0..10 "
                              "(RK4, 200 steps)", k,
                              lambda: unsteady.pathline(field, seeds, 0.0, 10.0, n_steps=200),
                              reference, "scipy solve_ivp RK45 (rtol 1e-8), all particles as "
                              "one system", 3 if quick else 10))
    return rows


def widgets(quick=False):
    """Median updates: the unsteady-flow explorer's time and release sliders, the LIC
    explorer's kernel slider (cached traces) and its colour switch."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets.lic import LICExplorer
    from course_lib.widgets.unsteady_flow import UnsteadyFlowExplorer

    repeat = 5 if quick else 40
    rows = []
    ex = UnsteadyFlowExplorer()
    ex.fig.canvas.draw()
    rows.append(widget_row("unsteady-flow explorer (time slider)",
                           lambda i: setattr(ex.time, "value", 0.05 + 0.9 * ((i * 7) % 20) / 20),
                           ex.fig.canvas.draw, repeat))
    rows.append(widget_row("unsteady-flow explorer (release x slider)",
                           lambda i: setattr(ex.release_x, "value",
                                             0.1 + 0.8 * ((i * 3) % 17) / 17),
                           ex.fig.canvas.draw, repeat))
    plt.close(ex.fig)
    ex = LICExplorer()
    ex.fig.canvas.draw()
    rows.append(widget_row("LIC explorer (kernel length slider, 128x128)",
                           lambda i: setattr(ex.length, "value", 1.0 + (i * 5) % 23),
                           ex.fig.canvas.draw, repeat))
    rows.append(widget_row("LIC explorer (colour by speed)",
                           lambda i: setattr(ex.colour, "value", i % 2 == 0),
                           ex.fig.canvas.draw, repeat))
    plt.close(ex.fig)
    return rows
