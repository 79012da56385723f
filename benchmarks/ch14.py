"""Chapter 14: texture sampling against scipy.ndimage.map_coordinates, and the topic files of
the chapter: two-part mapping and texture transforms (ch14_two_part), environment maps
(ch14_environment), relief mapping (ch14_relief) and texture hierarchies (ch14_hierarchies)."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    from scipy import ndimage

    from course_lib import texturing

    n = 20_000 if quick else 1_000_000
    repeat = 3 if quick else 11
    rng = np.random.default_rng(14)
    grey = rng.uniform(0, 1, (1024, 1024))
    rgb = rng.uniform(0, 1, (512, 512, 3))
    u, v = rng.uniform(-0.5, 1.5, n), rng.uniform(-0.5, 1.5, n)

    def coords(texture):
        """Our texel-centre convention in scipy's array coordinates (row, column)."""
        h, w = texture.shape[:2]
        return np.stack([v * h - 0.5, u * w - 0.5])

    c_grey, c_rgb = coords(grey), coords(rgb)       # conversion not timed: scipy's input
    sci = "scipy map_coordinates"
    return [
        operation_row("bilinear sampling, grey 1024x1024, repeat", n,
                      lambda: texturing.bilinear_sample(grey, u, v, "repeat"),
                      lambda: ndimage.map_coordinates(grey, c_grey, order=1, mode="grid-wrap"),
                      sci + " (order=1)", repeat),
        operation_row("bilinear sampling, RGB 512x512, clamp", n,
                      lambda: texturing.bilinear_sample(rgb, u, v, "clamp"),
                      lambda: [ndimage.map_coordinates(rgb[..., c], c_rgb, order=1,
                                                       mode="nearest") for c in range(3)],
                      sci + " (order=1, per channel)", repeat),
        operation_row("nearest sampling, grey 1024x1024, repeat", n,
                      lambda: texturing.nearest_sample(grey, u, v, "repeat"),
                      lambda: ndimage.map_coordinates(grey, c_grey, order=0, mode="grid-wrap"),
                      sci + " (order=0)", repeat),
    ] + [row for topic in _topics() for row in topic.operations(quick)]


def _topics():
    from benchmarks import ch14_environment, ch14_hierarchies, ch14_relief, ch14_two_part

    return (ch14_two_part, ch14_environment, ch14_relief, ch14_hierarchies)


def widgets(quick=False):
    """Median update of the barycentric explorer (dragging P) and of the texture explorer
    (turning the view: a pyvista render off screen and its JPEG; changing the texture's
    frequency: the texture, its magnified picture and the filtering panel recomputed)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import barycentric, texture

    repeat = 5 if quick else 40
    rows = []
    explorer = barycentric.BarycentricExplorer()
    explorer.fig.canvas.draw()
    start = explorer.state.point.copy()
    explorer.drag.press(*start)

    def move(i):
        explorer.drag.move(start[0] + 0.8 * np.cos(0.3 * i), start[1] + 0.8 * np.sin(0.3 * i))
    rows.append(widget_row("barycentric explorer (drag P)", move, explorer.fig.canvas.draw,
                           repeat))
    plt.close(explorer.fig)
    explorer = texture.TextureExplorer()
    rows.append(widget_row("texture explorer (view azimuth slider, pyvista off screen)",
                           lambda i: setattr(explorer.azimuth, "value", -60.0 + 2 * (i % 60)),
                           lambda: explorer.png(), repeat))
    rows.append(widget_row("texture explorer (frequency slider: texture and filtering)",
                           lambda i: setattr(explorer.frequency, "value", 2.0 + i % 24),
                           lambda: explorer.png(), repeat))
    explorer.plotter.close()
    plt.close(explorer.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
