"""Chapter 10, the pipeline and good plots: banking to 45 degrees (our safeguarded Newton
iteration against scipy's brentq on the same equation), the median filter of the pipeline
example against scipy.ndimage, the min/max overview of a long series against a plain loop, and
the graphical-integrity explorer's updates."""
import numpy as np

from benchmarks import operation_row


def operations(quick=False):
    """Banking a long polyline by the average orientation (ours vs ``scipy.optimize.brentq``
    on the plain mean-angle equation), the 3 x 3 median filter (ours, numpy windows, vs
    ``scipy.ndimage.median_filter``), and the min/max decimation of a long series (ours,
    vectorised, vs a Python loop over the bins)."""
    from scipy import ndimage
    from scipy.optimize import brentq

    from course_lib import dataviz

    rows = []
    count = 10_000 if quick else 1_000_000
    rng = np.random.default_rng(0)
    x = np.arange(count, dtype=float)
    y = np.cumsum(rng.normal(size=count)) + 20 * np.sin(x / 500)

    def reference():
        dx = np.abs(np.diff(x)) / np.ptp(x)
        dy = np.abs(np.diff(y)) / np.ptp(y)
        return np.exp(brentq(lambda u: np.arctan2(np.exp(u) * dy, dx).mean() - np.pi / 4,
                             -40, 40, xtol=1e-12))

    rows.append(operation_row(f"bank to 45° (average orientation), {count:,} segments",
                              count, lambda: dataviz.bank_to_45(x, y), reference,
                              "scipy brentq (plain mean-angle equation)", 3 if quick else 7))
    size = 64 if quick else 512
    image = rng.normal(size=(size, size))
    rows.append(operation_row(f"median filter 3x3 of a {size}x{size} field", size * size,
                              lambda: dataviz.median_filter(image, 3),
                              lambda: ndimage.median_filter(image, 3, mode="nearest"),
                              "scipy.ndimage.median_filter", 3 if quick else 7))
    bins = 500

    def loop():
        out = []
        n = len(y)
        for k in range(bins):
            part = y[k * n // bins:(k + 1) * n // bins]
            out += [part.min(), part.max()]
        return out

    rows.append(operation_row(f"min/max overview of {count:,} samples in {bins} bins", count,
                              lambda: dataviz.minmax_decimate(y, bins), loop,
                              "Python loop over the bins", 3 if quick else 7))
    return rows


def widgets(quick=False):
    """Median update of the graphical-integrity explorer: the baseline slider (truncated axis)
    and the distortion menu (all four pictures in turn)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import integrity

    repeat = 5 if quick else 40
    rows = []
    explorer = integrity.GraphicalIntegrityExplorer()
    explorer.fig.canvas.draw()
    rows.append(widget_row("graphical-integrity explorer (baseline slider)",
                           lambda i: setattr(explorer.baseline, "value", float(5 + i % 30)),
                           explorer.fig.canvas.draw, repeat))
    names = list(integrity.DISTORTIONS)
    rows.append(widget_row("graphical-integrity explorer (distortion menu)",
                           lambda i: setattr(explorer.distortion, "value", names[i % 4]),
                           explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
