"""Chapter 5, hierarchical occlusion culling: the hierarchical z-buffer's rejection of 10,000
boxes (at most 2 x 2 texels each) against the full-resolution per-pixel test on the same 512 x 512
depth buffer (one numpy max per box, the reference), building the z-pyramid, and the HZB
explorer's update."""
import numpy as np

from benchmarks import operation_row


def _scene(size, rng):
    from course_lib import visibility

    n = 40
    tris = np.empty((n, 3, 3))
    tris[:, :, :2] = rng.uniform(0, size, (n, 1, 2)) + rng.uniform(-size / 4, size / 4, (n, 3, 2))
    tris[:, :, 2] = rng.uniform(0.1, 0.8, (n, 1))
    depth = visibility.zbuffer(tris, size, size).depth
    return np.where(np.isinf(depth), 0.9, depth)          # a far wall behind everything


def operations(quick=False):
    """HZB cull of many boxes vs the per-pixel test (same decisions where the HZB rejects), and
    the pyramid build vs skimage's block_reduce of every level."""
    from course_lib import visibility

    rows = []
    size = 128 if quick else 512
    rng = np.random.default_rng(0)
    depth = _scene(size, rng)
    count = 1_000 if quick else 10_000
    i0 = rng.integers(0, size, count)
    j0 = rng.integers(0, size, count)
    side = rng.integers(1, size // 8, count)
    rects = np.stack([i0, j0, np.minimum(i0 + side, size - 1),
                      np.minimum(j0 + side, size - 1)], axis=1)
    z = rng.uniform(0.5, 1.0, count)
    pyramid = visibility.z_pyramid(depth)
    hzb = visibility.hzb_cull(pyramid, rects, z)
    full = visibility.full_cull(depth, rects, z)
    assert not (hzb.rejected & ~full.rejected).any()
    name = (f"HZB rejection of {count:,} boxes on {size} x {size} "
            f"({hzb.texels.mean():.1f} texels/box vs {full.texels.mean():.0f} pixels/box; "
            f"rejects {hzb.rejected.sum()} of the {full.rejected.sum()} hidden)")
    rows.append(operation_row(name, count, lambda: visibility.hzb_cull(pyramid, rects, z),
                              lambda: visibility.full_cull(depth, rects, z),
                              "per-pixel test, one numpy max per box", 3 if quick else 10))
    try:
        from skimage.measure import block_reduce
    except ImportError:                                   # pragma: no cover
        return rows

    def reference():
        return [block_reduce(depth, (2 ** k, 2 ** k), np.max) for k in
                range(1, len(pyramid.levels))]

    rows.append(operation_row(f"z-pyramid of a {size} x {size} depth buffer", size * size,
                              lambda: visibility.z_pyramid(depth), reference,
                              "skimage block_reduce(np.max) per level", 3 if quick else 15))
    return rows


def widgets(quick=False):
    """Median update of the HZB explorer: moving the box, and changing the level."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import hzb

    repeat = 5 if quick else 40
    rows = []
    explorer = hzb.HZBExplorer()
    explorer.fig.canvas.draw()
    rows.append(widget_row("HZB explorer (box x slider)",
                           lambda i: setattr(explorer.x, "value", 5 + (i * 7) % 50),
                           explorer.fig.canvas.draw, repeat))
    rows.append(widget_row("HZB explorer (level slider)",
                           lambda i: setattr(explorer.level, "value", i % 7),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
