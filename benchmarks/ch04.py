"""Chapter 4: projecting points against VTK's perspective transform, and the camera explorer."""
import numpy as np

from benchmarks import operation_row, widget_row


def operations(quick=False):
    from course_lib import transforms, viewing

    n = 2_000 if quick else 100_000
    repeat = 3 if quick else 25
    rng = np.random.default_rng(4)
    points = rng.uniform(-5, 5, size=(n, 3))
    m = (viewing.perspective(np.radians(60), 1.5, 0.5, 50.0)
         @ viewing.look_at([1.0, 2.0, 8.0], [0.0, -0.2, -1.0], [0.0, 1.0, 0.0]))
    from course_lib.draw import configure_offscreen_vtk

    configure_offscreen_vtk()
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk

    transform = vtk.vtkPerspectiveTransform()          # does the homogeneous divide too
    transform.SetMatrix(m.ravel().tolist())
    source = vtk.vtkPoints()
    source.SetData(numpy_to_vtk(points, deep=True))     # building the input is not timed
    target = vtk.vtkPoints()

    def vtk_reference():
        target.Reset()
        transform.TransformPoints(source, target)

    rows = [operation_row("project points (apply + divide)", n,
                          lambda: transforms.apply(m, points), vtk_reference,
                          "VTK vtkPerspectiveTransform", repeat)]
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch04_taxonomy

    return (ch04_taxonomy,)


def widgets(quick=False):
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from course_lib.widgets import camera

    repeat = 5 if quick else 40
    ex = camera.CameraExplorer()
    ex.fig.canvas.draw()
    row = widget_row("camera explorer (eye x slider)",
                     lambda i: setattr(ex.controls["eye_x"], "value", 4.5 - 0.1 * (i % 40)),
                     ex.fig.canvas.draw, repeat)
    plt.close(ex.fig)
    rows = [row]
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
