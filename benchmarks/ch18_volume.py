"""Chapter 18, volume rendering beyond ray casting: texture slicing, splatting and shear-warp
of a 128^3 volume against the course's ray casting and against VTK's
vtkFixedPointVolumeRayCastMapper (off screen, EGL; the reference library), the same transfer
function, image size and sampling step; and the update of the volume-comparison explorer."""
import os

import numpy as np

from benchmarks import operation_row


def _vtk_renderer(values, spacing, size):
    """A callable that renders `values` with VTK's fixed-point ray caster off screen."""
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import vtk
    from vtk.util import numpy_support

    lo, hi = float(values.min()), float(values.max())
    image = vtk.vtkImageData()
    image.SetDimensions(*values.shape[::-1])
    image.SetSpacing(*spacing)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(
        ((values - lo) / (hi - lo)).astype(np.float32).ravel(), deep=True))
    mapper = vtk.vtkFixedPointVolumeRayCastMapper()
    mapper.SetInputData(image)
    mapper.AutoAdjustSampleDistancesOff()          # else it coarsens the step to hit a frame rate
    mapper.SetSampleDistance(0.5 * min(spacing))   # the course's default step: half a voxel
    colour, opacity = vtk.vtkColorTransferFunction(), vtk.vtkPiecewiseFunction()
    colour.AddRGBPoint(0.0, 0, 0, 0)
    colour.AddRGBPoint(1.0, 1, 1, 1)
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(1.0, 1.0)                    # the "ramp" preset
    prop = vtk.vtkVolumeProperty()
    prop.SetColor(colour)
    prop.SetScalarOpacity(opacity)
    prop.SetInterpolationTypeToLinear()
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtk.vtkRenderer()
    renderer.AddVolume(volume)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(size, size)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    state = {"k": 0}

    def render():
        state["k"] += 1
        camera.Azimuth(1.0)                       # a new view each time: no cached frame
        window.Render()
    render()
    return render


def operations(quick=False):
    """Ray casting, slicing and splatting of the CT phantom, 128^3 (48^3 quick), image
    128^2 (64^2): ours against VTK's fixed-point ray caster, and slicing and splatting against
    the course's own ray casting."""
    from course_lib import scivis

    n = 48 if quick else 128
    px = 64 if quick else 128
    repeat = 2 if quick else 3
    ct = scivis.example_volume("ct", size=n)
    geo = dict(rotation=scivis.view_rotation(0.5, -0.3), image_size=(px, px),
               spacing=ct.spacing, origin=ct.origin, extent="sphere")
    def ray():
        return scivis.volume_render(ct.values, "ramp", early_termination=None, **geo)

    def sl():
        return scivis.slice_render(ct.values, "ramp", **geo)

    def sp():
        return scivis.splat_render(ct.values, "ramp", **geo)

    def sw():
        return scivis.shear_warp(ct.values, "ramp", **geo)

    rows = []
    try:
        vtk_render = _vtk_renderer(ct.values, ct.spacing, px)
    except Exception as error:                    # pragma: no cover - no GL on this machine
        vtk_render = None
        print(f"VTK off screen unavailable ({error}); comparing with ray casting only")
    label = f"{n}^3 volume to a {px}^2 image"
    if vtk_render is not None:
        ref = "VTK vtkFixedPointVolumeRayCastMapper (off screen)"
        rows.append(operation_row(f"ray casting, {label}", n ** 3, ray, vtk_render, ref, repeat))
        rows.append(operation_row(f"view-aligned slicing, {label}", n ** 3, sl, vtk_render, ref,
                                  repeat))
        rows.append(operation_row(f"splatting, {label}", n ** 3, sp, vtk_render, ref, repeat))
    rows.append(operation_row(f"slicing vs ray casting, {label}", n ** 3, sl, ray,
                              "the course's volume_render (no early termination)", repeat))
    rows.append(operation_row(f"splatting vs ray casting, {label}", n ** 3, sp, ray,
                              "the course's volume_render (no early termination)", repeat))
    rows.append(operation_row(f"shear-warp vs ray casting, {label}", n ** 3, sw, ray,
                              "the course's volume_render (no early termination)", repeat))
    return rows


def widgets(quick=False):
    """Median update of the comparison explorer: the slices slider (only the slicing
    re-rendered; the cache cleared each time) and the view slider (all three)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import volume_compare as vc

    repeat = 4 if quick else 20
    explorer = vc.VolumeCompareExplorer()
    explorer.fig.canvas.draw()
    counts = [16, 24, 32, 40, 56, 64, 72, 80]

    def move_slices(i):
        vc.render.cache_clear()
        explorer.slices.value = counts[i % len(counts)]

    def move_view(i):
        vc.render.cache_clear()
        explorer.azimuth.value = float(-180 + 15 * (i % 24))

    rows = [widget_row("volume comparison (slices slider)", move_slices,
                       explorer.fig.canvas.draw, repeat),
            widget_row("volume comparison (view slider, all three re-rendered)", move_view,
                       explorer.fig.canvas.draw, repeat, target_ms=300.0)]
    plt.close(explorer.fig)
    return rows
