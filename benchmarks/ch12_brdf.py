"""Chapter 12, BRDFs: the reflectance quadrature against scipy's dblquad, BRDF evaluation
against the bare numpy formula, and the BRDF explorer's slider updates."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """Reflectance of a Phong lobe (our Gauss-Legendre pieces vs adaptive ``dblquad``) and the
    evaluation of a normalised Phong BRDF on N direction pairs (with input checks vs the bare
    formula)."""
    from scipy.integrate import dblquad

    from course_lib import shading

    rows = []
    n_exp, theta = 50.0, np.radians(30)
    l = np.array([np.sin(theta), 0.0, np.cos(theta)])
    z = np.array([0.0, 0.0, 1.0])

    def f(a, v, n):
        return shading.phong_brdf(a, v, n, 1.0, n_exp, "normalized")

    def ours():
        return shading.hemispherical_reflectance(f, l, z, shininess=n_exp)

    def reference():
        def integrand(t, p):
            v = np.array([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)])
            r = 2 * (l @ z) * z - l
            return (n_exp + 2) / (2 * np.pi) * max(r @ v, 0.0) ** n_exp * np.cos(t) * np.sin(t)
        return dblquad(integrand, -np.pi, np.pi, 0, np.pi / 2, epsabs=1e-9, epsrel=1e-9)[0]

    rows.append(operation_row(f"reflectance of a Phong lobe (n = {n_exp:g}, 30°), quadrature",
                              1, ours, reference, "scipy dblquad (plain integrand)",
                              2 if quick else 5))

    count = 10_000 if quick else 1_000_000
    rng = np.random.default_rng(0)
    ls = rng.normal(size=(count, 3))
    ls[:, 2] = np.abs(ls[:, 2])
    vs = rng.normal(size=(count, 3))
    vs[:, 2] = np.abs(vs[:, 2])

    def bare():
        lu = ls / np.linalg.norm(ls, axis=1, keepdims=True)
        vu = vs / np.linalg.norm(vs, axis=1, keepdims=True)
        r = 2 * lu[:, 2:3] * z - lu
        return 0.5 * (n_exp + 2) / (2 * np.pi) * np.clip(np.sum(r * vu, axis=1), 0, 1) ** n_exp

    rows.append(operation_row(f"normalised Phong BRDF on {count:,} direction pairs", count,
                              lambda: shading.phong_brdf(ls, vs, z, 0.5, n_exp), bare,
                              "bare numpy formula (no input checks)", 3 if quick else 15))
    return rows


def widgets(quick=False):
    """Median update of the BRDF explorer: the incidence slider (a new reflectance quadrature
    at every step: the worst case) and the k_s slider (the reflectance is cached)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import brdf

    repeat = 5 if quick else 40
    rows = []
    explorer = brdf.BRDFExplorer()
    explorer.fig.canvas.draw()
    brdf.lobe_reflectance.cache_clear()
    rows.append(widget_row("BRDF explorer (incidence slider, uncached reflectance)",
                           lambda i: setattr(explorer.theta, "value", float((7 * i) % 89)),
                           explorer.fig.canvas.draw, repeat))
    rows.append(widget_row("BRDF explorer (k_s slider)",
                           lambda i: setattr(explorer.ks, "value", 0.2 + 0.02 * (i % 30)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
