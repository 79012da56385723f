"""Chapter 10: normalisation, transfer functions, colour maps and CIE L* against references.

* normalisation against matplotlib's ``colors.Normalize`` (the same linear map, clipped);
* a piecewise-linear transfer function (8 control points, RGBA) against ``numpy.interp``
  called once per channel;
* colour mapping (normalise, then look the colour up) against matplotlib's
  ``Colormap.__call__`` on the normalised data (a 256-entry table, nearest entry: less work);
* sRGB -> CIE L*a*b* against scikit-image's ``color.rgb2lab``;
* the transfer-function editor's preview compositing (rays sampled once, classification by a
  lookup table, all rays composited at once) against ray casting the same view from scratch
  with ``course_lib.scivis.volume_render``: the ratio is what sampling once saves;
* and the topic files of the chapter's other sections: the pipeline and graphical integrity
  (ch10_integrity), scattered data (ch10_scattered), multidimensional data (ch10_multidim).
"""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    import matplotlib
    from matplotlib import colors as mcolors
    from skimage import color as skcolor

    from course_lib import colormaps, scivis
    from course_lib.widgets import transfer_function as tfw

    repeat = 3 if quick else 15
    n = 10_000 if quick else 1_000_000
    rng = np.random.default_rng(10)
    data = rng.normal(size=n)
    rows = [operation_row("normalize to [0, 1]", n, lambda: colormaps.normalize(data),
                          lambda: mcolors.Normalize(clip=True)(data),
                          "matplotlib Normalize", repeat)]

    skin = colormaps.transfer_preset("skin")
    u = rng.uniform(size=n)
    rows.append(operation_row(
        "transfer function, 8 points, RGBA", n, lambda: skin(u),
        lambda: np.stack([np.interp(u, skin.points, skin.values[:, c]) for c in range(4)],
                         axis=-1), "numpy interp (per channel)", repeat))

    viridis = matplotlib.colormaps["viridis"]
    rows.append(operation_row(
        "apply_colormap viridis", n, lambda: colormaps.apply_colormap(data, "viridis"),
        lambda: viridis(mcolors.Normalize()(data)), "matplotlib Colormap(Normalize)", repeat))

    rgb = rng.uniform(size=(n // 10, 3))
    rows.append(operation_row("sRGB -> CIE L*a*b*", n // 10,
                              lambda: colormaps.srgb_to_lab(rgb),
                              lambda: skcolor.rgb2lab(rgb), "skimage rgb2lab", repeat))

    ct = tfw.example_data("ct")
    rays = tfw.RaySamples(ct, -30.0, 10.0)
    voxel = min(ct.spacing)
    rows.append(operation_row(
        "editor preview: composite cached rays 48x48 (CT 48^3)", int(rays.inside.sum()),
        lambda: rays.composite(skin),
        lambda: scivis.volume_render(
            ct.values, skin, rotation=scivis.view_rotation(*np.radians([-30.0, 10.0])),
            image_size=tfw.PREVIEW_SIZE, step=voxel * tfw.PREVIEW_STEP, spacing=ct.spacing,
            origin=ct.origin, extent=tfw.EXTENT, unit_length=voxel, early_termination=None),
        "scivis.volume_render (same view, from scratch)", repeat))
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch10_integrity, ch10_multidim, ch10_scattered

    return (ch10_integrity, ch10_scattered, ch10_multidim)


def widgets(quick=False):
    """Median update of the transfer-function editor while a control point is dragged (target
    50 ms), when it is dropped (a full 96 x 96 ray cast), and of the colour-map explorer when
    the map changes."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import colormap, transfer_function

    repeat = 5 if quick else 40
    rows = []
    editor = transfer_function.TransferFunctionExplorer()
    editor.fig.canvas.draw()
    x, y = editor.drag.points[6]
    editor.drag.press(x, y)

    def drag(i):
        editor.drag.move(x + 0.04 * np.sin(0.5 * i), 0.3 + 0.25 * np.cos(0.37 * i))

    rows.append(widget_row("transfer-function editor: drag a control point", drag,
                           editor.fig.canvas.draw, repeat))

    def drop(i):                       # each drop a new function: no cached render
        editor.drag.press(*editor.drag.points[6])
        editor.drag.move(x, 0.2 + 0.01 * (i % 60))
        editor.drag.release()

    rows.append(widget_row("transfer-function editor: drop (full ray cast 96x96)", drop,
                           editor.fig.canvas.draw, max(3, repeat // 4), target_ms=500.0))
    plt.close(editor.fig)

    explorer = colormap.ColormapExplorer()
    explorer.fig.canvas.draw()
    names = ("viridis", "jet", "rainbow", "grey", "magma", "coolwarm")
    rows.append(widget_row("colour-map explorer: change the map",
                           lambda i: setattr(explorer.name, "value", names[i % len(names)]),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
