"""Chapter 3, normals and frames: transform_normals of many normals against trimesh (which
recomputes face normals from the transformed faces) and against plain numpy (the inverse
transpose and a normalisation written out), a world-to-frame matrix against numpy.linalg.inv,
and the normals explorer's update."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """transform_normals vs trimesh's face normals of the transformed mesh and vs numpy."""
    import trimesh

    from course_lib import frames, transforms

    rows = []
    M = (transforms.translate([1, 2, 3]) @ transforms.rotate_axis([1, 2, 2], 0.7)
         @ transforms.shear_xy(0.5, 0.2) @ transforms.scale([2, 1, 0.5]))
    mesh = trimesh.creation.icosphere(subdivisions=5 if quick else 7)   # 20k / 328k faces
    normals = mesh.face_normals.copy()
    count = len(normals)

    def recomputed():
        moved = trimesh.Trimesh(mesh.vertices @ M[:3, :3].T + M[:3, 3], mesh.faces,
                                process=False)
        return moved.face_normals

    rows.append(operation_row(f"transform_normals of {count:,} face normals", count,
                              lambda: frames.transform_normals(normals, M), recomputed,
                              "trimesh: transform the mesh, recompute face_normals",
                              3 if quick else 10))

    count = 10_000 if quick else 100_000
    n = np.random.default_rng(0).normal(size=(count, 3))

    def plain():
        out = n @ np.linalg.inv(M[:3, :3])
        return out / np.linalg.norm(out, axis=1, keepdims=True)

    rows.append(operation_row(f"transform_normals of {count:,} normals", count,
                              lambda: frames.transform_normals(n, M), plain,
                              "numpy: n @ inv(A), then normalise", 5 if quick else 30))
    o, axes = [1.0, 2.0, 3.0], M[:3, :3].T
    rows.append(operation_row("world_to_frame of a 3D frame (general axes)", 1,
                              lambda: frames.world_to_frame(o, axes),
                              lambda: np.linalg.inv(frames.frame_matrix(o, axes)),
                              "numpy.linalg.inv of frame_matrix", 20 if quick else 200))
    return rows


def widgets(quick=False):
    """Median update of the normals explorer (the shear slider and the s_x slider)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import normals

    repeat = 5 if quick else 40
    explorer = normals.NormalsExplorer()
    explorer.fig.canvas.draw()
    rows = [widget_row("normals explorer (shear slider)",
                       lambda i: setattr(explorer.shear, "value", -1.0 + 0.1 * (i % 21)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("normals explorer (s_x slider)",
                       lambda i: setattr(explorer.sx, "value", 0.5 + 0.1 * (i % 21)),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
