"""Chapter 6, level of detail: a level rebuilt from the progressive mesh (vertex splits and
collapses from the current level) against re-running simplify_qem to that face count, the
screen-space error of many objects against the full projection, and the LOD explorer's update."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """Progressive mesh vs re-simplification (same meshes, exactly), and the screen-space error
    in closed form vs projecting two points through course_lib.viewing."""
    from course_lib import mesh, transforms, viewing

    rows = []
    v, f = mesh.icosphere(3 if quick else 4)
    scale = 1 + 0.15 * np.sin(3 * v[:, 0]) * np.sin(4 * v[:, 1]) * np.sin(2 * v[:, 2] + 1)
    v = v * scale[:, None]
    base = len(f) // 16
    pm = mesh.ProgressiveMesh(v, f, base_faces=base)
    targets = [len(f) // 2, len(f) // 4, len(f) // 8, len(f) // 3]
    state = {"i": 0}

    def ours():                                      # walk from the previous level
        state["i"] += 1
        return pm.mesh(targets[state["i"] % len(targets)])

    def reference():
        return mesh.simplify_qem(v, f, targets[state["i"] % len(targets)], record=False)[:2]

    rows.append(operation_row(f"a level of a {len(f)}-face mesh from its progressive mesh",
                              len(f), ours, reference, "re-running simplify_qem to that count",
                              3 if quick else 10))

    count = 10_000 if quick else 1_000_000
    rng = np.random.default_rng(0)
    eps = rng.uniform(0.001, 0.1, count)
    d = rng.uniform(1, 100, count)
    fov, H = np.radians(45), 1080
    P = viewing.perspective(fov, 1.0, 0.1, 1000.0)
    V = viewing.viewport(0, 0, H, H)
    M = V @ P

    def projected():
        low = transforms.apply(M, np.column_stack([np.zeros(count), np.zeros(count), -d]))
        high = transforms.apply(M, np.column_stack([np.zeros(count), eps, -d]))
        return high[:, 1] - low[:, 1]

    rows.append(operation_row(f"screen-space error of {count:,} objects", count,
                              lambda: mesh.screen_space_error(eps, d, fov, H), projected,
                              "projecting two points (viewing.perspective + viewport)",
                              3 if quick else 15))
    return rows


def widgets(quick=False):
    """Median update of the LOD explorer: the distance slider (a level choice, a geomorph in
    the transition bands, the mesh re-projected) and the tolerance slider."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import lod

    repeat = 5 if quick else 40
    rows = []
    explorer = lod.LODExplorer()
    explorer.fig.canvas.draw()
    distances = np.geomspace(10, 400, 23)
    rows.append(widget_row("LOD explorer (distance slider)",
                           lambda i: setattr(explorer.distance, "value",
                                             float(distances[i % len(distances)])),
                           explorer.fig.canvas.draw, repeat))
    rows.append(widget_row("LOD explorer (tolerance slider)",
                           lambda i: setattr(explorer.tolerance, "value", 0.5 + 0.5 * (i % 15)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
