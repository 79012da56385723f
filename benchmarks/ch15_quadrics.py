"""Chapter 15, quadrics: 1M rays against a cylinder by the general quadric (the 4x4 matrix and
the stable quadratic) against the same cylinder written out in numpy (x^2 + y^2 = r^2, no
matrix), and against trimesh's ray-mesh intersector on a cylinder mesh (fewer rays: it is far
slower); the implicit-surface marcher on a torus; and the quadric explorer's update."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """intersect_quadric / intersect_implicit against closed-form numpy and trimesh."""
    import trimesh
    from trimesh.ray.ray_triangle import RayMeshIntersector

    from course_lib import raytracing as rt

    rows = []
    count = 20_000 if quick else 1_000_000
    rng = np.random.default_rng(0)
    o = np.column_stack([np.full(count, 5.0), rng.uniform(-1.2, 1.2, count),
                         rng.uniform(-0.9, 0.9, count)])
    d = np.column_stack([-np.ones(count), rng.normal(size=count) * 0.05,
                         rng.normal(size=count) * 0.05])
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    Q = rt.quadric_matrix("cylinder", radius=1.0)

    def closed_form():
        a = d[:, 0] ** 2 + d[:, 1] ** 2
        b = 2 * (o[:, 0] * d[:, 0] + o[:, 1] * d[:, 1])
        c = o[:, 0] ** 2 + o[:, 1] ** 2 - 1.0
        disc = b * b - 4 * a * c
        with np.errstate(invalid="ignore"):
            t = (-b - np.sqrt(disc)) / (2 * a)
        return np.where(disc >= 0, t, np.inf)

    rows.append(operation_row(f"{count:,} rays against a cylinder (general quadric Q)", count,
                              lambda: rt.intersect_quadric(o, d, Q, clip=(-1, 1)), closed_form,
                              "the cylinder's quadratic typed in numpy (no clip, no normals)",
                              3 if quick else 7))
    few = 2_000 if quick else 20_000
    mesh = trimesh.creation.cylinder(radius=1.0, height=2.0, sections=128)
    intersector = RayMeshIntersector(mesh)
    rows.append(operation_row(f"{few:,} rays against a closed cylinder (quadric + two disks)",
                              few, lambda: rt.intersect_cylinder(o[:few], d[:few], 1.0, (-1, 1)),
                              lambda: intersector.intersects_location(o[:few], d[:few]),
                              "trimesh RayMeshIntersector on a 128-sided cylinder mesh",
                              3 if quick else 5))
    torus = rt.torus_function(2.0, 0.5)
    m = 2_000 if quick else 20_000
    oo = np.column_stack([np.full(m, -5.0), rng.uniform(-2.4, 2.4, m), rng.uniform(-0.4, 0.4, m)])
    dd = np.tile([1.0, 0.0, 0.0], (m, 1))

    def quartic_roots():                  # the torus quartic solved per ray by numpy.roots
        out = np.empty(m)
        for k in range(m):
            od, o2 = oo[k] @ dd[k], oo[k] @ oo[k]
            s = np.array([1.0, 2 * od, o2 + 3.75])
            q = np.array([1.0, 2 * oo[k, 0], oo[k, 0] ** 2 + oo[k, 1] ** 2])
            r = np.roots(np.polysub(np.polymul(s, s), 16 * np.r_[0, 0, q]))
            r = r[(np.abs(r.imag) < 1e-9) & (r.real >= 0)].real
            out[k] = r.min() if len(r) else np.inf
        return out

    rows.append(operation_row(f"{m:,} rays against a torus (sampling + bisection)", m,
                              lambda: rt.intersect_implicit(oo, dd, torus, t_max=12, steps=200),
                              quartic_roots, "numpy.roots of each ray's quartic (a Python loop)",
                              2 if quick else 3))
    return rows


def widgets(quick=False):
    """Median update of the quadric explorer: the radius slider (a 96x96 ray cast and the f(t)
    curve) and the pixel slider."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import quadric

    repeat = 5 if quick else 40
    explorer = quadric.QuadricExplorer()
    explorer.fig.canvas.draw()
    radii = np.linspace(0.3, 1.4, 23)
    rows = [widget_row("quadric explorer (radius slider)",
                       lambda i: setattr(explorer.radius, "value", float(radii[i % 23])),
                       explorer.fig.canvas.draw, repeat),
            widget_row("quadric explorer (pixel row slider)",
                       lambda i: setattr(explorer.row, "value", 20 + (i % 50)),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
