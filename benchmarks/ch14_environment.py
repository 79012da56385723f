"""Chapter 14, environment mapping: cube-map and sphere-map look-ups of many directions against
scipy's bilinear interpolation after the same face selection or sphere-map formula written
plainly in numpy, and the environment-mapping explorer's updates per control."""
import itertools

import numpy as np

from benchmarks import operation_row


def _reference_cube(cube, d, order=1):
    """The reference cube-map look-up: the OpenGL face table written plainly in numpy (the
    major axis by argmax, s_c, t_c, m_a picked per face), then ``scipy.ndimage.map_coordinates``
    (order 1 = bilinear, 0 = nearest; mode "nearest" = clamped to the face's edge texels) on
    each face and channel."""
    from scipy import ndimage

    n = cube.shape[1]
    axis = np.argmax(np.abs(d), axis=1)
    rows = np.arange(len(d))
    ma = d[rows, axis]
    face = 2 * axis + (ma < 0)
    x, y, z = d[:, 0], d[:, 1], d[:, 2]
    sc = np.choose(face, [-z, z, x, x, x, -x])
    tc = np.choose(face, [-y, -y, z, -z, -y, -y])
    am = np.abs(ma)
    s, t = 0.5 * (sc / am + 1), 0.5 * (tc / am + 1)
    out = np.empty((len(d), cube.shape[3]))
    for f in range(6):
        m = face == f
        coords = np.stack([t[m] * n - 0.5, s[m] * n - 0.5])
        for c in range(cube.shape[3]):
            out[m, c] = ndimage.map_coordinates(cube[f, :, :, c], coords, order=order,
                                                mode="nearest")
    return out


def _reference_sphere(sphere_map, r):
    """The reference sphere-map look-up: normalise, s = r_x/m + 1/2, t = r_y/m + 1/2 with
    m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2) in numpy, then ``map_coordinates`` (bilinear,
    clamped) per channel."""
    from scipy import ndimage

    r = r / np.linalg.norm(r, axis=1)[:, None]
    m = 2 * np.sqrt(r[:, 0] ** 2 + r[:, 1] ** 2 + (r[:, 2] + 1) ** 2)
    h, w = sphere_map.shape[:2]
    coords = np.stack([(r[:, 1] / m + 0.5) * h - 0.5, (r[:, 0] / m + 0.5) * w - 0.5])
    return np.stack([ndimage.map_coordinates(sphere_map[..., c], coords, order=1,
                                             mode="nearest")
                     for c in range(sphere_map.shape[2])], axis=-1)


def operations(quick=False):
    """A million (quick: 20,000) random directions looked up in an RGB cube map of 6 x 256 x 256
    texels (quick: 6 x 64 x 64; the sphere map 128 x 128) (direction -> face, s, t -> bilinear sample: :func:`course_lib.texturing.
    sample_cube_map`) and in an RGB sphere map of 512 x 512 (:func:`course_lib.texturing.
    sample_sphere_map`). The references do the same work with the formulas written plainly in
    numpy and scipy's ``map_coordinates`` for the bilinear filtering (per face and channel for
    the cube); the results are checked equal before timing."""
    from course_lib.texturing import environment as env

    n = 20_000 if quick else 1_000_000
    repeat = 3 if quick else 7
    rng = np.random.default_rng(14)
    d = rng.normal(size=(n, 3))
    face, side = (64, 128) if quick else (256, 512)
    cube = env.cube_map_from_function(env.sky_environment, face)
    sphere = env.sphere_map_from_function(env.sky_environment, side)
    ours_cube = env.sample_cube_map(cube, d)
    assert np.allclose(ours_cube, _reference_cube(cube, d))
    same = np.all(env.sample_cube_map(cube, d, "nearest") == _reference_cube(cube, d, 0), axis=1)
    assert same.mean() > 0.999                       # ties at texel borders may round apart
    d_sphere = d[d[:, 2] > -0.999]                   # away from the singular direction
    assert np.allclose(env.sample_sphere_map(sphere, d_sphere),
                       _reference_sphere(sphere, d_sphere))
    return [
        operation_row(f"cube-map look-ups, RGB 6x{face}x{face}, bilinear ({n:,} directions)", n,
                      lambda: env.sample_cube_map(cube, d),
                      lambda: _reference_cube(cube, d),
                      "numpy face table + scipy map_coordinates per face and channel", repeat),
        operation_row(f"cube-map look-ups, RGB 6x{face}x{face}, nearest ({n:,} directions)", n,
                      lambda: env.sample_cube_map(cube, d, "nearest"),
                      lambda: _reference_cube(cube, d, 0),
                      "numpy face table + scipy map_coordinates, order 0", repeat),
        operation_row(f"sphere-map look-ups, RGB {side}x{side}, bilinear ({n:,} directions)", n,
                      lambda: env.sample_sphere_map(sphere, d),
                      lambda: _reference_sphere(sphere, d),
                      "numpy (s, t) formula + scipy map_coordinates per channel", repeat),
    ]


def widgets(quick=False):
    """Median update of the environment-mapping explorer per control: the view sliders (a new
    view is a cache miss: the object's hits and reflections recomputed, then the look-ups),
    the offset slider in the traced mode (the wall hits recomputed), the map and environment
    menus (another map: a full redraw, included) and a click (a new picked pixel)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import environment as W

    repeat = 5 if quick else 40
    ex = W.EnvironmentMapExplorer()

    def fresh(control, values):
        """Set `control` to the next of `values` at every call (warm-up runs included), so
        that a view is never one the cache still holds."""
        calls = itertools.count()
        return lambda i: setattr(control, "value", values[next(calls) % len(values)])
    azimuths = [-175.0 + 5 * k for k in range(71)]
    elevations = [-80.0 + 5 * k for k in range(33)]       # 33 views > the cache's 32
    draw = ex.fig.canvas.draw
    draw()
    rows = [widget_row("environment explorer (azimuth slider, sphere, cube map)",
                       fresh(ex.azimuth, azimuths), draw, repeat),
            widget_row("environment explorer (elevation slider, sphere, cube map)",
                       fresh(ex.elevation, elevations), draw, repeat)]

    def menu(control, options):
        def change(i):
            control.value = options[i % len(options)]
            draw()                                    # another map: the full redraw counts
        return change
    rows.append(widget_row("environment explorer (map menu, with its full redraw)",
                           menu(ex.kind, W.KINDS), draw, repeat))
    rows.append(widget_row("environment explorer (environment menu, with its full redraw)",
                           menu(ex.environment, ("room", "sky", "axes")), draw, repeat))
    rows.append(widget_row("environment explorer (click on the picture)",
                           lambda i: _click(ex, 10 + 3 * (i % 36), 64.0), draw, repeat))
    ex.kind.value = "cube"
    ex.shape.value = "torus"
    rows.append(widget_row("environment explorer (azimuth slider, torus: sphere tracing)",
                           fresh(ex.azimuth, azimuths[1:]), draw, repeat))
    ex.reflection.value = "traced"
    rows.append(widget_row("environment explorer (offset slider, torus ray traced in the room)",
                           fresh(ex.offset, [-2.5 + 0.25 * k for k in range(21)]), draw,
                           repeat))
    ex.elevation.value = 12.0                       # views not seen before: nothing cached
    rows.append(widget_row("environment explorer (azimuth slider, torus traced: 2nd bounces)",
                           fresh(ex.azimuth, azimuths[::-1]), draw, repeat))
    plt.close(ex.fig)
    return rows


def _click(explorer, x, y):
    """A click on the explorer's picture at data position (x, y), as the mouse sends it."""
    from matplotlib.backend_bases import MouseEvent

    ax = explorer.ax_image
    px, py = ax.transData.transform((x, y))
    event = MouseEvent("button_press_event", ax.figure.canvas, px, py, button=1)
    ax.figure.canvas.callbacks.process("button_press_event", event)
