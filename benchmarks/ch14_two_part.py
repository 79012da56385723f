"""Chapter 14, texture transformations and two-part mapping: two-part mapping of many points,
resampling a texture through a texture matrix against scipy.ndimage.affine_transform, and the
two-part mapping explorer's updates."""
from benchmarks import operation_row


def operations(quick=False):
    """Two-part mapping (sphere object points, box and cylinder intermediate surfaces, normal
    and reflected O-mappings) of n points against the direct spherical map of the same points
    (a lower bound: one S-mapping, no O-mapping), and a 512 x 512 texture resampled through a
    texture matrix (bilinear, repeat) against scipy.ndimage.affine_transform (order 1,
    grid-wrap) doing the same."""
    import numpy as np
    from scipy import ndimage

    from course_lib.texturing import spherical_map, texture_transforms as tt, two_part_map

    n = 20_000 if quick else 1_000_000
    repeat = 2 if quick else 5
    rng = np.random.default_rng(0)
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    p = 0.5 * d
    rows = []
    for surface, method in (("box", "normal"), ("cylinder", "normal"), ("sphere", "reflected")):
        rows.append(operation_row(
            f"two-part map, {surface} + {method}, {n} points (vs the direct spherical map)", n,
            lambda s=surface, m=method: two_part_map(p, d, s, m, size=1.5, eye=(0, 0, 5)),
            lambda: spherical_map(p), "course_lib spherical_map (no O-mapping)", repeat))
    size = 128 if quick else 512
    tex = rng.random((size, size))
    m = tt.texture_matrix(tiling=1.5, rotation=0.3, offset=(0.05, 0.1))
    to_uv = np.array([[0, 1 / size, 0.5 / size], [1 / size, 0, 0.5 / size], [0, 0, 1]])
    from_uv = np.array([[0, size, -0.5], [size, 0, -0.5], [0, 0, 1]])
    a = from_uv @ m @ to_uv
    rows.append(operation_row(
        f"transform_texture {size}x{size}, bilinear, repeat (vs scipy.ndimage.affine_transform)",
        size * size, lambda: tt.transform_texture(tex, m),
        lambda: ndimage.affine_transform(tex, a, order=1, mode="grid-wrap"),
        "scipy.ndimage.affine_transform order=1", repeat))
    return rows


def widgets(quick=False):
    """Median update of the two-part mapping explorer (rotation slider, O-mapping and surface
    menus); the objects' ray casts are cached before timing."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.texturing.two_part import METHODS, SURFACES
    from course_lib.widgets import two_part

    repeat = 5 if quick else 40
    explorer = two_part.TwoPartMappingExplorer()
    for obj in two_part.OBJECTS:
        two_part.geometry(obj)
    explorer.fig.canvas.draw()
    rows = [widget_row("two-part explorer (rotation slider)",
                       lambda i: setattr(explorer.rotation, "value", -180 + 5 * (i % 72)),
                       explorer.fig.canvas.draw, repeat),
            widget_row("two-part explorer (O-mapping menu)",
                       lambda i: setattr(explorer.method, "value", METHODS[i % 4]),
                       explorer.fig.canvas.draw, repeat),
            widget_row("two-part explorer (surface menu)",
                       lambda i: setattr(explorer.surface, "value", SURFACES[i % 4]),
                       explorer.fig.canvas.draw, repeat)]
    plt.close(explorer.fig)
    return rows
