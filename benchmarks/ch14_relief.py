"""Chapter 14, relief mapping: normal-mapped shading of a 512 x 512 image (decode an 8-bit
tangent-space map, TBN to object space, Blinn-Phong) against VTK's PBR renderer drawing a plane
with the same normal texture into a 512 x 512 off-screen window (render and read back; Mesa's
EGL here) and against shading the same pixels with their unperturbed normals; per-vertex
tangent frames against VTK's vtkPolyDataTangents on the same mesh; the relief explorer's
updates."""
import numpy as np

from benchmarks import operation_row


def _sphere_grid(nu, nv):
    from course_lib.texturing.mappings import inverse_spherical_map

    u, v = np.meshgrid(np.linspace(0.0, 1.0, nu), np.linspace(0.02, 0.98, nv))
    uv = np.stack([u.ravel(), v.ravel()], axis=1)
    verts = inverse_spherical_map(uv[:, 0], uv[:, 1])
    idx = np.arange(nu * nv).reshape(nv, nu)
    a, b, c, d = idx[:-1, :-1], idx[:-1, 1:], idx[1:, 1:], idx[1:, :-1]
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                            np.stack([a, c, d], -1).reshape(-1, 3)])
    return verts, faces, uv


def _vtk_tangents(verts, faces, uv):
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy

    poly = vtk.vtkPolyData()
    pts = vtk.vtkPoints()
    pts.SetData(numpy_to_vtk(verts.copy()))
    poly.SetPoints(pts)
    cells = vtk.vtkCellArray()
    conn = np.hstack([np.full((len(faces), 1), 3), faces]).astype(np.int64).ravel()
    cells.SetCells(len(faces), numpy_to_vtkIdTypeArray(conn, deep=True))
    poly.SetPolys(cells)
    poly.GetPointData().SetNormals(numpy_to_vtk(verts.copy()))
    poly.GetPointData().SetTCoords(numpy_to_vtk(uv.copy()))

    def run():
        f = vtk.vtkPolyDataTangents()
        f.SetInputData(poly)
        f.Update()
        return vtk_to_numpy(f.GetOutput().GetPointData().GetTangents())
    return run


def _vtk_pbr_frame(rgb8, size):
    """A callable rendering a unit plane with `rgb8` as its PBR normal texture, off screen."""
    from course_lib import draw

    draw.configure_offscreen_vtk()
    import pyvista as pv
    import vtk

    plane = pv.Plane(i_size=1, j_size=1, i_resolution=1, j_resolution=1)
    tangents = vtk.vtkPolyDataTangents()
    tangents.SetInputData(plane.triangulate().compute_normals())
    tangents.Update()
    plotter = pv.Plotter(off_screen=True, window_size=(size, size))
    actor = plotter.add_mesh(pv.wrap(tangents.GetOutput()), color="white", pbr=True,
                             metallic=0.0, roughness=0.5)
    actor.GetProperty().SetNormalTexture(pv.Texture(rgb8))
    plotter.camera_position = "xy"
    plotter.add_light(pv.Light(position=(1, 1, 2), light_type="scene light"))
    plotter.screenshot(return_img=True)

    def frame():
        plotter.render()
        return plotter.screenshot(return_img=True)
    return frame


def operations(quick=False):
    """Normal-mapped Blinn-Phong shading of a size x size image (the ratio is over plain
    Blinn-Phong of the same pixels: the price of decode + TBN), and per-vertex tangent frames of
    a UV sphere against vtkPolyDataTangents (same mesh, normals and texture coordinates)."""
    from course_lib.texturing import relief

    size = 128 if quick else 512
    repeat = 2 if quick else 7
    h = relief.bumps_height(size, count=8)
    rgb8 = np.round(255 * relief.normal_map_from_height(h, 0.02)).astype(np.uint8)
    c = (np.arange(size) + 0.5) / size
    theta = 2 * np.pi * (c - 0.5)
    t = np.broadcast_to(np.stack([np.cos(theta), 0 * theta, -np.sin(theta)], -1),
                        (size, size, 3))
    b = np.broadcast_to([0.0, 1.0, 0.0], (size, size, 3))
    n = np.cross(t, b)
    light = (0.4, 0.5, 0.75)

    def normal_mapped():
        nt = relief.decode_normals(rgb8)
        return relief.shade_normals(relief.tangent_to_object(nt, t, b, n), light,
                                    model="blinn-phong")

    rows = [operation_row(
        f"normal-mapped Blinn-Phong, {size}x{size} (decode 8-bit + TBN + shade; vs VTK's PBR "
        "normal texture on a plane, render + read back)", size * size, normal_mapped,
        _vtk_pbr_frame(rgb8, size), "VTK PBR off screen (EGL, Mesa)", repeat),
        operation_row(
        f"normal-mapped Blinn-Phong, {size}x{size} (vs shading the unperturbed normals: the "
        "price of decode + TBN)", size * size, normal_mapped,
        lambda: relief.shade_normals(n, light, model="blinn-phong"),
        "shade_normals of the flat normals", repeat)]
    nu, nv = (64, 32) if quick else (256, 128)
    verts, faces, uv = _sphere_grid(nu, nv)
    rows.append(operation_row(
        f"per-vertex tangent frames, UV sphere of {len(verts)} vertices (vs vtkPolyDataTangents)",
        len(verts), lambda: relief.vertex_tangent_frames(verts, faces, uv, normals=verts),
        _vtk_tangents(verts, faces, uv), "VTK vtkPolyDataTangents", repeat))
    return rows


def widgets(quick=False):
    """Median update of the relief explorer: the light slider (cached geometry, reshading only),
    the strength slider in bump mode, and the strength slider in displacement mode on the
    sphere (a new displaced grid splatted each time, nothing cached)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import relief

    repeat = 5 if quick else 40
    explorer = relief.ReliefExplorer()
    explorer.fig.canvas.draw()
    rows = [widget_row("relief explorer (light azimuth slider, bump on the sphere)",
                       lambda i: setattr(explorer.azimuth, "value", -170 + 7 * (i % 48)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("relief explorer (strength slider, bump)",
                       lambda i: setattr(explorer.strength, "value", 0.1 + 0.02 * (i % 40)),
                       explorer.fig.canvas.draw, repeat)]
    explorer.mode.value = "displacement"
    rows.append(widget_row("relief explorer (strength slider, true displacement)",
                           lambda i: setattr(explorer.strength, "value",
                                             0.12 + 0.02 * (i % 40)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
