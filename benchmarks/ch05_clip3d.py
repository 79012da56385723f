"""Chapter 5, clipping in 3D and in clip space: Liang-Barsky in homogeneous coordinates on many
world segments (projected by the camera matrix, clipped against -w <= x, y, z <= w, mapped back)
against VTK clipping the same world segments by the six frustum planes (vtkClipPolyData, one
plane after another), and the updates of the 3D clipping explorer (step control)
and of the clip-before-or-after-the-divide explorer."""
import numpy as np

from benchmarks import operation_row


def _segments(count, seed=0):
    """World segments around a camera, about a fifth of them crossing the eye plane."""
    from course_lib import viewing

    rng = np.random.default_rng(seed)
    camera = (viewing.perspective(np.radians(50), 1.2, 1.0, 10.0)
              @ viewing.look_at([0.5, -0.3, 4.0], [-0.1, 0.05, -1.0], [0.0, 1.0, 0.0]))
    a = rng.uniform(-3, 3, (count, 3))
    b = rng.uniform(-3, 3, (count, 3))
    b[: count // 5, 2] += 5.0                      # behind the eye (it sits at z = 4)
    return camera, a, b


def _vtk_lines(a, b):
    import vtk
    from vtk.util import numpy_support

    points = vtk.vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(
        np.column_stack([a, b]).reshape(-1, 3)), deep=True))
    n = len(a)
    cells = np.column_stack([np.full(n, 2), 2 * np.arange(n), 2 * np.arange(n) + 1]).ravel()
    lines = vtk.vtkCellArray()
    lines.SetCells(n, numpy_support.numpy_to_vtkIdTypeArray(cells.astype(np.int64), deep=True))
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetLines(lines)
    return poly


def operations(quick=False):
    """Clip-space Liang-Barsky on n segments (project, clip, map back) vs VTK's plane clipping."""
    import vtk

    from course_lib import clip_space, clipping

    count = 10_000 if quick else 100_000
    camera, a, b = _segments(count)
    inverse = np.linalg.inv(camera)
    ones = np.ones((count, 1))
    planes = clipping.view_volume_planes(camera)
    poly = _vtk_lines(a, b)

    def ours():
        q0, q1, t, visible = clip_space.clip_segments_homogeneous(
            np.hstack([a, ones]) @ camera.T, np.hstack([b, ones]) @ camera.T)
        back = np.stack([q0[visible], q1[visible]]) @ inverse.T        # to world coordinates
        return back[..., :3] / back[..., 3:]

    def reference():
        data = poly
        for _, n, c in planes:
            plane = vtk.vtkPlane()
            plane.SetNormal(*map(float, n))
            plane.SetOrigin(*map(float, n * c / (n @ n)))
            clip = vtk.vtkClipPolyData()
            clip.SetInputData(data)
            clip.SetClipFunction(plane)
            clip.InsideOutOn()
            clip.Update()
            data = clip.GetOutput()
        return data

    return [operation_row(f"clip {count:,} segments to a view frustum (clip space, mapped back)",
                          count, ours, reference,
                          "VTK vtkClipPolyData by the six frustum planes",
                          3 if quick else 10)]


def widgets(quick=False):
    """Median update of the 3D clipping explorer (step control) and of the
    clip-before-or-after-the-divide explorer (B's depth slider)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import clipping3d

    repeat = 5 if quick else 40
    explorer = clipping3d.ClippingExplorer3D()
    explorer.fig.canvas.draw()
    # (its turn slider is measured by benchmarks/ch05.py)
    rows = [widget_row("3D clipping explorer (step control)",
                       lambda i: setattr(explorer.step, "value", i % 7),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)

    from course_lib.widgets import homogeneous_clip

    explorer = homogeneous_clip.HomogeneousClipExplorer()
    explorer.fig.canvas.draw()
    rows.append(widget_row("clip before/after the divide explorer (B: z slider)",
                           lambda i: setattr(explorer.b_z, "value", round(-7.5 + 0.5 * (i % 22),
                                                                          1)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
