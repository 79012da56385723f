"""Chapter 18: contours, isosurfaces, ray casting and streamlines against reference libraries.

* marching squares and marching cubes: scikit-image (``measure.find_contours``,
  ``measure.marching_cubes``, Lewiner's method, its default) on the same field and level;
* volume ray casting has no reference library that does the same work without a GPU. The row
  compares it with scipy's compiled ``ndimage.map_coordinates`` doing *only* the trilinear
  interpolation of as many samples as the ray caster took (random points inside the volume,
  sorted in memory order so that the reads are as cache-friendly as along rays): the ratio is
  the price of our numpy marching, transfer functions and compositing over bare compiled
  interpolation. The target is
  an absolute one, 2 s for a 128^3 volume to a 256 x 256 image; it is in the row's name;
* maximum intensity projection with one ray per voxel column against ``volume.max(axis=0)``,
  which computes the same image;
* streamlines (RK4, fixed step, all seeds at once) against scipy's ``solve_ivp`` (adaptive
  RK45) integrating all seeds as one system over the same time span.
"""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    from scipy.integrate import solve_ivp
    from scipy.ndimage import map_coordinates
    from skimage import measure

    from course_lib import scivis

    repeat = 3 if quick else 15
    rows = []

    # marching squares: a 2D field with many closed isolines
    n2 = 64 if quick else 512
    ripple = scivis.example_field_2d("ripple", size=n2)
    rows.append(operation_row(
        "marching squares: segments (ripple field)", n2 * n2,
        lambda: scivis.marching_squares(ripple.values, 0.1),
        lambda: measure.find_contours(ripple.values, 0.1), "skimage find_contours", repeat))
    rows.append(operation_row(
        "marching squares: joined isolines (ripple field)", n2 * n2,
        lambda: scivis.isolines(ripple.values, 0.1),
        lambda: measure.find_contours(ripple.values, 0.1), "skimage find_contours", repeat))

    # marching cubes: two blobs and the CT phantom's skull, 64^3 and 128^3
    for size in ((16,) if quick else (64, 128)):
        for kind in ("blobs", "ct"):
            vol = scivis.example_volume(kind, size=size)
            rows.append(operation_row(
                f"marching cubes ({kind}, {size}^3)", size ** 3,
                lambda vol=vol: scivis.marching_cubes(vol.values, vol.level, vol.spacing),
                lambda vol=vol: measure.marching_cubes(vol.values, vol.level,
                                                       spacing=vol.spacing),
                "skimage marching_cubes (lewiner)", repeat))

    # volume ray casting: CT phantom, "skin" transfer function, a turned view
    size, image = (16, (32, 32)) if quick else (128, (256, 256))
    ct = scivis.example_volume("ct", size=size)
    render_args = dict(transfer="skin", rotation=scivis.view_rotation(0.5, -0.3),
                       image_size=image, spacing=ct.spacing, origin=ct.origin, extent="sphere")
    samples = scivis.volume_render(ct.values, **render_args).samples
    points = np.random.default_rng(18).uniform(0, size - 1, (3, samples))
    points = points[:, np.lexsort(points[::-1])]     # in memory order, as coherent as rays
    rows.append(operation_row(
        f"volume ray casting {size}^3 -> {image[0]}x{image[1]} (target < 2 s)", samples,
        lambda: scivis.volume_render(ct.values, **render_args),
        lambda: map_coordinates(ct.values, points, order=1),
        "scipy map_coordinates (same samples, no compositing)", 3 if quick else 5))

    # maximum intensity projection, one ray per voxel column
    rows.append(operation_row(
        f"maximum intensity projection {size}^3, step 1 voxel", size ** 3,
        lambda: scivis.mip(ct.values, step=ct.spacing[2], spacing=ct.spacing),
        lambda: ct.values.max(axis=0), "numpy max along z", repeat))

    # streamlines: many seeds in a spiral flow
    seeds_n, steps, h = (50, 20, 0.05) if quick else (1000, 200, 0.05)
    spiral = scivis.example_vector_field("spiral")
    seeds = np.random.default_rng(19).uniform(-1, 1, (seeds_n, 2))

    def scipy_lines():
        def rhs(t, y):
            return spiral(y.reshape(-1, 2)).ravel()
        return solve_ivp(rhs, (0, h * steps), seeds.ravel(), method="RK45",
                         t_eval=h * np.arange(steps + 1), rtol=1e-6, atol=1e-9)

    rows.append(operation_row(
        f"streamlines RK4, {steps} steps", seeds_n,
        lambda: scivis.streamline(spiral, seeds, h, steps, method="rk4"), scipy_lines,
        "scipy solve_ivp (RK45, one system)", repeat))
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch18_volume, ch18_topology, ch18_unsteady

    return (ch18_volume, ch18_topology, ch18_unsteady,)


def widgets(quick=False):
    """Median update of each chapter-18 explorer as a student moves its main control: the
    isovalue slider (marching squares on a 12 x 12 field with cases, saddles and the fine
    reference isoline; marching cubes on a 32^3 volume rendered by pyvista off screen) and
    the step slider of the streamline explorer (3 seeds, RK4, steps 0.04 to 0.5 over 2 pi)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import isovalue, streamlines

    repeat = 5 if quick else 40
    rows = []
    explorer = isovalue.IsolineExplorer()
    explorer.fig.canvas.draw()
    lo, hi = explorer.level.min, explorer.level.max
    rows.append(widget_row(
        "isoline explorer (isovalue slider, 12x12 field)",
        lambda i: setattr(explorer.level, "value", lo + (hi - lo) * (0.1 + 0.02 * (i % 40))),
        explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)

    explorer = isovalue.IsosurfaceExplorer()
    rows.append(widget_row(
        "isosurface explorer (isovalue slider, 32^3 blobs, pyvista off screen)",
        lambda i: setattr(explorer.level, "value", 0.25 + 0.01 * (i % 40)),
        lambda: explorer.png(), repeat))
    explorer.plotter.close()

    explorer = streamlines.StreamlineExplorer()
    explorer.method.value = "rk4"
    explorer.fig.canvas.draw()
    rows.append(widget_row(
        "streamline explorer (step slider, RK4, 3 seeds)",
        lambda i: setattr(explorer.step, "value", 0.04 + 0.46 * ((i % 20) / 19)),
        explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
