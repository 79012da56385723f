"""Chapter 10, multidimensional data (10.7): brushing, the parallel-coordinates layout, the
rasterised polyline layer and PCA against references, and the linked explorers' brush updates
on 10,000 records.

* the brush mask (two brushes, one a rectangle, combined with OR) against the bare numpy
  comparisons (no input checks);
* the parallel-coordinates layout (normalise each column, reorder, flip one) against the bare
  numpy min-max formula;
* the highlighted layer of the explorer: recounting the raster of the selected polylines
  (:class:`course_lib.dataviz.PolylineRaster`) against drawing the same polylines as one
  matplotlib ``LineCollection`` on an Agg canvas of the same size (what the raster replaces);
* PCA (covariance, eigen-decomposition, projection) against numpy's SVD of the centred data
  (and scikit-learn's ``PCA`` when it is installed).
"""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    from course_lib.dataviz import multidim as md
    from course_lib.dataviz import projection as pj

    repeat = 3 if quick else 15
    table = md.weather_table(10_000, seed=0)
    data, names = table.data, table.names
    n = len(data)
    brushes = [{"temperature": (10.0, 25.0)}, {"humidity": (60.0, 90.0), "rain": (2.0, 20.0)}]

    def bare_mask():
        t, h, r = data[:, 0], data[:, 1], data[:, 4]
        return ((t >= 10) & (t <= 25)) | ((h >= 60) & (h <= 90) & (r >= 2) & (r <= 20))

    rows = [operation_row("brush mask, 2 brushes (a range, a rectangle), OR", n,
                          lambda: md.brush_mask(data, brushes, "or", names), bare_mask,
                          "bare numpy comparisons", repeat)]

    def bare_layout():
        lo, hi = data.min(axis=0), data.max(axis=0)
        y = (data - lo) / (hi - lo)
        y[:, 1] = 1 - y[:, 1]
        y = y[:, [4, 0, 1, 2, 3]]
        return np.stack([np.broadcast_to(np.arange(5.0), y.shape), y], axis=-1)

    rows.append(operation_row("parallel-coordinates layout (order + flip), 5 axes", n,
                              lambda: md.parallel_coordinates(data, [4, 0, 1, 2, 3], [1]),
                              bare_layout, "bare numpy min-max formula", repeat))

    lines = md.parallel_coordinates(data) / [4.0, 1.0]
    width, height = 440, 190
    raster = md.PolylineRaster(lines, width, height, extent=(0, 1, 0, 1))
    mask = bare_mask()

    def agg_lines():
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.collections import LineCollection
        from matplotlib.figure import Figure

        fig = Figure(figsize=(width / 100, height / 100), dpi=100)
        canvas = FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set(xlim=(0, 1), ylim=(0, 1))
        ax.add_collection(LineCollection(lines[mask], linewidths=0.5, colors="C0", alpha=0.05))
        canvas.draw()
        return canvas.buffer_rgba()

    rows.append(operation_row(f"selected polyline layer, {int(mask.sum()):,} of {n:,} "
                              f"records, {width}x{height} px", n,
                              lambda: raster.counts(mask), agg_lines,
                              "matplotlib LineCollection drawn by Agg", repeat))

    rng = np.random.default_rng(4)
    big = rng.normal(size=(n, 8)) @ rng.normal(size=(8, 8))

    def svd_pca():
        centred = big - big.mean(axis=0)
        _, s, vt = np.linalg.svd(centred, full_matrices=False)
        return centred @ vt[:2].T, s ** 2 / (n - 1)

    rows.append(operation_row("principal components (PCA), 8 attributes, 2 components", n,
                              lambda: pj.pca(big, k=2), svd_pca, "numpy SVD of the centred data",
                              repeat))
    try:
        from sklearn.decomposition import PCA
    except ImportError:
        return rows
    rows.append(operation_row("principal components (PCA), 8 attributes, 2 components", n,
                              lambda: pj.pca(big, k=2),
                              lambda: PCA(n_components=2, svd_solver="full").fit_transform(big),
                              "scikit-learn PCA", repeat))
    return rows


def widgets(quick=False):
    """Median update of each explorer while a brush is dragged on 10,000 records (the
    polyline layer recounted and blitted; the matrix's dots recounted and blitted), and of the
    linked pair, where one drag updates both."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import parallel_coordinates as pcw
    from course_lib.widgets import scatterplot_matrix as smw

    repeat = 5 if quick else 40
    rows = []
    pc = pcw.ParallelCoordinatesExplorer()
    pc.dataset.value = "weather (10,000)"
    pc.fig.canvas.draw()
    rows.append(widget_row("parallel coordinates explorer (brush drag, 10,000 records)",
                           lambda i: pc.brush_drag(1, 0.1 + 0.01 * (i % 30), 0.7),
                           pc.fig.canvas.draw, repeat, target_ms=40.0))
    splom = smw.ScatterplotMatrixExplorer()
    splom.selection.set_dataset("weather (10,000)")
    splom.fig.canvas.draw()
    rows.append(widget_row("scatterplot matrix explorer (rectangle drag, 10,000 records)",
                           lambda i: splom.brush_rectangle((4, 0), (0.2, 0.2),
                                                           (0.5 + 0.01 * (i % 30), 0.8)),
                           splom.fig.canvas.draw, repeat, target_ms=40.0))
    both = smw.link()
    both.pc.dataset.value = "weather (10,000)"
    both.pc.fig.canvas.draw()
    both.splom.fig.canvas.draw()
    rows.append(widget_row("linked explorers (brush drag, 10,000 records, both redrawn)",
                           lambda i: both.pc.brush_drag(1, 0.1 + 0.01 * (i % 30), 0.7),
                           lambda: (both.pc.fig.canvas.draw(), both.splom.fig.canvas.draw()),
                           repeat, target_ms=40.0))
    for figure in (pc.fig, splom.fig, both.pc.fig, both.splom.fig):
        plt.close(figure)
    return rows
