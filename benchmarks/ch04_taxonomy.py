"""Chapter 4, the taxonomy of projections: vanishing points of many directions (the image of
(d, 0)) against projecting far points p + t d with plain numpy, classifying projection matrices,
and the projection-class explorer's update."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """Vanishing points of many directions vs far points; classify_projection per matrix."""
    from course_lib import projections, viewing

    rows = []
    count = 10_000 if quick else 100_000
    rng = np.random.default_rng(0)
    dirs = rng.normal(size=(count, 3))
    M = viewing.perspective(np.radians(60), 1.5, 0.5, 100.0) @ viewing.look_at(
        [2, -5, 1.5], [-0.3, 1, -0.2], [0, 0, 1])
    p = rng.normal(size=3)

    def far_points():                          # the reference: p + 1e9 d, projected and divided
        h = np.c_[p + 1e9 * dirs, np.ones(count)] @ M.T
        return h[:, :3] / h[:, 3:]

    rows.append(operation_row(f"vanishing points of {count:,} directions", count,
                              lambda: projections.vanishing_point(M, dirs), far_points,
                              "projecting far points p + 1e9 d (numpy)", 3 if quick else 15))
    mats = [projections.isometric(), projections.cabinet(), projections.perspective_view(0.5, 0.3),
            projections.multiview("top")]

    def classify():
        return [projections.classify_projection(m)["name"] for m in mats]

    def svd_only():                            # the reference: the centre of projection by SVD
        return [np.linalg.svd(m)[2][-1] for m in mats]

    rows.append(operation_row("classify 4 projection matrices", 4, classify, svd_only,
                              "one numpy SVD per matrix", 3 if quick else 30))
    return rows


def widgets(quick=False):
    """Median update of the projection-class explorer (azimuth and elevation sliders)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets.projection_class import ProjectionClassExplorer

    repeat = 5 if quick else 40
    explorer = ProjectionClassExplorer()
    explorer.fig.canvas.draw()
    rows = [widget_row("projection-class explorer (azimuth slider)",
                       lambda i: setattr(explorer.azimuth, "value", float(-170 + 7 * (i % 48))),
                       explorer.fig.canvas.draw, repeat),
            widget_row("projection-class explorer (elevation slider)",
                       lambda i: setattr(explorer.elevation, "value", float(-60 + 5 * (i % 24))),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
