"""Chapter 12, screen-space ambient occlusion: SSAO of a depth buffer against the ray-traced AO
of the same view with the same samples per pixel, and the SSAO explorer's slider updates."""
from benchmarks import operation_row


def operations(quick=False):
    """SSAO of a size x size G-buffer (16 samples, 4 x 4 blur) against casting 16 cosine-weighted
    rays per pixel through a BVH (:func:`course_lib.shading.ray_traced_occlusion`) for the same
    view; the ratio is SSAO's time over the ray tracer's (the G-buffer is built once, outside
    the timing, as a renderer has it from drawing the frame)."""
    from course_lib import shading, visibility

    size = 64 if quick else 256
    repeat = 2 if quick else 5
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, size, size)
    bvh = visibility.BVH(scene.vertices[scene.faces])
    rows = [operation_row(
        f"SSAO of a {size}x{size} G-buffer, 16 samples (vs ray-traced AO, 16 rays per pixel)",
        size * size,
        lambda: shading.ssao(gb.positions, gb.normals, scene.projection, gb.mask, radius=0.5,
                             samples=16, seed=0),
        lambda: shading.ray_traced_occlusion(gb, bvh, samples=16, seed=0).visibility(0.5),
        "ray-traced AO, same view, BVH", repeat)]
    rows.append(operation_row(
        f"G-buffer of the test scene, {size}x{size} (vs one ray cast per pixel)", size * size,
        lambda: shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection,
                                 size, size),
        lambda: visibility.ray_cast_image(scene.vertices, scene.faces, scene.view,
                                          scene.projection, size, size),
        "ray_cast_image, BVH", repeat))
    return rows


def widgets(quick=False):
    """Median update of the SSAO explorer (radius and samples sliders, range-check switch); its
    G-buffer and ray distances are computed once, before timing."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import ssao

    repeat = 5 if quick else 40
    explorer = ssao.SSAOExplorer()
    explorer.fig.canvas.draw()
    rows = [widget_row("SSAO explorer (radius slider)",
                       lambda i: setattr(explorer.radius, "value", 0.2 + 0.05 * (i % 20)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("SSAO explorer (samples slider)",
                       lambda i: setattr(explorer.samples, "value", 4 + (i % 28)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("SSAO explorer (range-check switch)",
                       lambda i: setattr(explorer.range_check, "value", bool(i % 2)),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
