"""Chapter 5, BSP trees of segments (course_lib.visibility.bsp2d): building a tree of a few
hundred segments against the 3D tree of the same segments extruded into vertical quads, the
back-to-front traversal against a depth sort (numpy lexsort by distance, correct only where no
two segments overlap awkwardly), and the BSP explorer's update."""
import numpy as np

from benchmarks import operation_row


def _segments(count, seed=0):
    rng = np.random.default_rng(seed)
    a = rng.uniform(-20, 20, (count, 2))
    ang = rng.uniform(0, 2 * np.pi, count)
    return np.stack([a, a + rng.uniform(0.5, 2, count)[:, None]
                     * np.c_[np.cos(ang), np.sin(ang)]], axis=1)


def _extruded(segs):
    tris = []
    for a, b in segs:
        a0, a1, b0, b1 = [np.append(p, z) for p, z in ((a, 0), (a, 1), (b, 0), (b, 1))]
        tris += [[a0, a1, b1], [a0, b1, b0]]
    return np.array(tris)


def operations(quick=False):
    """Build: 2D tree vs the 3D build_bsp on extruded quads; traverse: the tree's order vs a
    numpy lexsort of the fragments by distance from the eye."""
    from course_lib import visibility as vis

    count = 100 if quick else 300
    segs = _segments(count)
    tris = _extruded(segs)
    rows = [operation_row(f"2D BSP tree of {count} segments (given order)", count,
                          lambda: vis.build_bsp_2d(segs), lambda: vis.build_bsp(tris),
                          f"visibility.build_bsp of the {2 * count} extruded triangles",
                          3 if quick else 10)]
    tree = vis.build_bsp_2d(segs)
    frags = np.array([[f.start, f.end] for f in tree.fragments])
    eye = np.array([0.5, 0.25])

    def depth_sort():
        dist = np.linalg.norm(frags - eye, axis=2)
        return np.lexsort((np.arange(len(frags)), -dist.min(axis=1), -dist.max(axis=1)))

    rows.append(operation_row(f"back-to-front traversal of {len(frags)} fragments", len(frags),
                              lambda: vis.bsp2d_back_to_front(tree, eye), depth_sort,
                              "numpy lexsort by distance (a depth sort)", 5 if quick else 30))
    return rows


def widgets(quick=False):
    """Median update of the BSP explorer: the eye slider (new traversal) and the step slider."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import bsp

    repeat = 5 if quick else 40
    explorer = bsp.BSPExplorer()
    explorer.fig.canvas.draw()
    rows = [widget_row("BSP explorer (eye x slider)",
                       lambda i: setattr(explorer.eye_x, "value", -1 + 0.5 * (i % 21)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("BSP explorer (painting step)",
                       lambda i: setattr(explorer.step, "value", i % 6),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
