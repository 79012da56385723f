"""Chapter 12: Phong shading against VTK's renderer, ambient occlusion's cost per ray, and the
topic files of the chapter: radiometry (ch12_radiometry), BRDFs (ch12_brdf) and screen-space
ambient occlusion against the ray-traced AO of the same view (ch12_ssao)."""
import numpy as np

from benchmarks import operation_row


def _sphere_normals(size):
    """Per-pixel normals of an orthographic view of the unit sphere (the background gets +z)."""
    s = (np.arange(size) + 0.5) / size * 2 - 1
    x, y = np.meshgrid(s, s)
    z = np.sqrt(np.maximum(0.0, 1 - x**2 - y**2))
    return np.stack([x, y, z], axis=-1)


def _vtk_sphere_render(size, segments, rings):
    """A pyvista plotter showing a Phong-shaded sphere at size x size, and its render call.

    On this machine VTK renders through Mesa's EGL/llvmpipe: a GPU-less *software* OpenGL
    render of the same image size, which is the honest comparison for a numpy shader (with a GPU
    the reference would be orders of magnitude faster). The timed call renders the frame and
    reads the pixels back (otherwise the driver may defer the work).
    """
    from course_lib.draw import configure_offscreen_vtk

    configure_offscreen_vtk()
    import pyvista as pv

    plotter = pv.Plotter(off_screen=True, window_size=(size, size))
    sphere = pv.Sphere(radius=1.0, theta_resolution=segments, phi_resolution=rings)
    plotter.add_mesh(sphere, color="white", smooth_shading=True, interpolation="phong",
                     ambient=0.1, diffuse=0.6, specular=0.3, specular_power=20)
    plotter.remove_all_lights()
    plotter.add_light(pv.Light(position=(1.0, 1.0, 2.0), light_type="scene light",
                               positional=False))
    plotter.camera_position = [(0, 0, 5), (0, 0, 0), (0, 1, 0)]
    plotter.render()

    def render():
        plotter.render()
        return plotter.screenshot(return_img=True)

    return plotter, render


def operations(quick=False):
    from course_lib import shading, shapes, viewing, visibility

    size = 64 if quick else 512
    repeat = 3 if quick else 15
    rows = []
    normals = _sphere_normals(size)
    light = shading.directional_light([1.0, 1.0, 2.0])
    material = shading.Material(ka=0.1, kd=0.6, ks=0.3, shininess=20)
    plotter, vtk_render = _vtk_sphere_render(size, 96, 48)
    ref = "VTK/pyvista render, software GL"
    rows.append(operation_row(f"Phong lighting of {size}x{size} pixels (normals given)",
                              size * size,
                              lambda: shading.phong(None, normals, [0.0, 0.0, 1.0], light,
                                                    material),
                              vtk_render, ref, repeat))
    # the whole pipeline: z-buffer of a 96 x 48 sphere mesh, interpolated normals, Phong per pixel
    v, f = shading.uv_sphere(segments=24 if quick else 96, rings=12 if quick else 48)
    view = viewing.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])
    proj = viewing.perspective(np.radians(30), 1.0, 1.0, 10.0)
    rows.append(operation_row(f"render a {len(f)}-triangle sphere, Phong shading, {size}x{size}",
                              size * size,
                              lambda: shading.render_shaded(v, f, view, proj, size, size, light,
                                                            material, normals=v),
                              vtk_render, ref, 2 if quick else 3))
    plotter.close()

    # Ambient occlusion: a torus on a floor, points on the floor, k rays each. The reference is
    # our own brute-force ray casting of exactly the same rays (course_lib.visibility.ray_cast
    # without a BVH): no installed library casts batches of rays against triangles without
    # compiled extras (trimesh needs rtree or embree, pyvista's multi_ray_trace needs embree),
    # so the row shows what the bounding-volume hierarchy buys. Both are reported per 1,000
    # ray samples.
    tv, tf = shapes.torus(major=1.0, minor=0.4, segments=16 if quick else 48,
                          rings=8 if quick else 24)
    floor = np.array([[[-5, -5, -0.4], [5, -5, -0.4], [5, 5, -0.4]],
                      [[-5, -5, -0.4], [5, 5, -0.4], [-5, 5, -0.4]]])
    scene = np.concatenate([tv[tf], floor])
    bvh = visibility.BVH(scene)
    rng = np.random.default_rng(12)
    n_points, k = (20, 16) if quick else (200, 64)
    points = np.column_stack([rng.uniform(-2, 2, (n_points, 2)), np.full(n_points, -0.4)])
    up = np.array([0.0, 0.0, 1.0])
    dirs = shading.cosine_sample_hemisphere(np.broadcast_to(up, points.shape), k, seed=1)
    origins = np.repeat(points + 1e-6 * up, k, axis=0)
    row = operation_row(f"ambient occlusion, {len(scene)} triangles (BVH), per 1,000 rays",
                        1000,
                        lambda: shading.ambient_occlusion(points, up, bvh, samples=k, seed=1),
                        lambda: visibility.ray_cast(origins, dirs.reshape(-1, 3), scene),
                        "visibility.ray_cast brute force", 3 if quick else 5)
    scale = 1000 / (n_points * k)
    row["ours_ms"] *= scale
    row["reference_ms"] *= scale
    rows.append(row)
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch12_brdf, ch12_radiometry, ch12_ssao

    return (ch12_radiometry, ch12_brdf, ch12_ssao)


def widgets(quick=False):
    """Median update of the Phong explorer (a material slider and the light's azimuth: the
    sphere, its three terms and the three interpolated shadings) and of the ambient-occlusion
    explorer (the ray-count slider; its rays are cast once per scene, before timing)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import occlusion, phong

    repeat = 5 if quick else 40
    rows = []
    explorer = phong.PhongExplorer()
    explorer.fig.canvas.draw()
    rows.append(widget_row("Phong explorer (k_s slider)",
                           lambda i: setattr(explorer.ks, "value", 0.2 + 0.02 * (i % 30)),
                           explorer.fig.canvas.draw, repeat))
    rows.append(widget_row("Phong explorer (light azimuth slider)",
                           lambda i: setattr(explorer.azimuth, "value", -60.0 + 3 * (i % 40)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    explorer = occlusion.OcclusionExplorer()
    explorer.fig.canvas.draw()
    rows.append(widget_row("ambient-occlusion explorer (rays slider)",
                           lambda i: setattr(explorer.samples, "value", 2 + 7 * (i % 36)),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
