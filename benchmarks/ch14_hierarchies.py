"""Chapter 14, texture hierarchies: building a mip pyramid against scikit-image's pyramids,
and the level map of a view (quad differences) against numpy's gradient; no explorer (the
section's figures are static)."""
from benchmarks import operation_row


def operations(quick=False):
    """The mip pyramid of a size x size RGB texture (:func:`course_lib.texturing.mipmap`, 2 x 2
    box filter) against two chains of scikit-image halvings down to 1 x 1: ``pyramid_reduce``
    (Gaussian smoothing then resampling: more work per level, what scikit-image offers as "the"
    pyramid) and ``downscale_local_mean`` (the same 2 x 2 box filter as ours); and the level
    map of a size x size view of a receding floor (:func:`course_lib.texturing.level_map`,
    2 x 2 quad differences) against the same level from ``np.gradient``'s central differences
    with :func:`texel_footprint` and :func:`mip_level`."""
    import numpy as np
    from skimage.transform import downscale_local_mean, pyramid_reduce

    from course_lib import texturing

    size = 256 if quick else 2048
    view_size = 128 if quick else 512
    repeat = 2 if quick else 5
    texture = np.random.default_rng(0).random((size, size, 3))

    def skimage_reduce():
        levels = [texture]
        while max(levels[-1].shape[:2]) > 1:
            levels.append(pyramid_reduce(levels[-1], downscale=2, channel_axis=-1))
        return levels

    def skimage_box():
        levels = [texture]
        while max(levels[-1].shape[:2]) > 1:
            levels.append(downscale_local_mean(levels[-1], (2, 2, 1)))
        return levels

    assert len(skimage_box()) == len(texturing.mipmap(texture))
    rows = [operation_row(f"mip pyramid of a {size}x{size} RGB texture (vs pyramid_reduce chain)",
                          size * size, lambda: texturing.mipmap(texture), skimage_reduce,
                          "skimage pyramid_reduce (Gaussian)", repeat),
            operation_row(f"mip pyramid of a {size}x{size} RGB texture (vs box-filter chain)",
                          size * size, lambda: texturing.mipmap(texture), skimage_box,
                          "skimage downscale_local_mean", repeat)]
    view = texturing.receding_plane(view_size, view_size)
    shape = (1024, 1024)

    def gradient_levels():
        du_dy, du_dx = np.gradient(view.u)
        dv_dy, dv_dx = np.gradient(view.v)
        return texturing.mip_level(texturing.texel_footprint(shape, du_dx, dv_dx, du_dy, dv_dy))

    rows.append(operation_row(f"level map of a {view_size}x{view_size} view (quad differences)",
                              view_size * view_size,
                              lambda: texturing.level_map(shape, view.u, view.v),
                              gradient_levels, "np.gradient + texel_footprint", repeat))
    return rows


def widgets(quick=False):
    """No explorer in this section: its figures are static."""
    return []
