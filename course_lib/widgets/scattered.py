r"""Scattered-data explorer: interpolate samples of a known function by nearest neighbour,
linear on the Delaunay triangulation, Shepard's inverse-distance weighting or radial basis
functions, and see the error.

The function is Franke's test function on the unit square, the classic benchmark for
scattered-data interpolation (two bumps, a ridge and a dip). It is sampled at the first
``n`` points of a fixed seeded sequence of uniform random points (more points add to the old
ones), and the interpolant is evaluated on a GRID x GRID grid
(:func:`course_lib.dataviz.resample_to_grid`). Left: the interpolant, with the samples; middle:
the true function; right: the error, interpolant minus truth, with its RMS and maximum over
the grid (for the linear method over the part of the grid inside the convex hull, the only
part where it has values; outside it is left blank, and the triangulation is drawn).

Results are cached per setting, so moving a slider back is instant; a new setting costs one
interpolation of 6,400 grid points (a few to 25 milliseconds). A global RBF whose system is
too ill-conditioned to solve (a small shape parameter with many points) is reported in the
text, and its field left blank.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from .._validate import as_choice
from ..dataviz import scattered
from . import _style
from ._base import Explorer, align, bind, labelled, panel, slider

__all__ = ["GRID", "KERNELS", "MAX_POINTS", "METHODS", "ScatteredDataExplorer", "State",
           "franke", "sample_points", "scene"]

GRID = 80
MAX_POINTS = 200
SEED = 7
#: The methods as the menu names them, and the library's name of each.
METHODS = {"nearest": "nearest", "linear": "linear", "Shepard": "shepard", "RBF": "rbf"}
#: The kernels as the menu names them, and the library's name of each.
KERNELS = {"Gaussian": "gaussian", "multiquadric": "multiquadric",
           "inverse multiquadric": "inverse_multiquadric", "thin-plate spline": "thin_plate_spline"}
ERROR_RANGE = 0.25


def franke(x, y):
    """Franke's test function on the unit square (values about -0.2 to 1.2).

    Examples
    --------
    >>> round(float(franke(0.0, 0.0)), 6)
    0.766421
    """
    return (0.75 * np.exp(-((9 * x - 2) ** 2 + (9 * y - 2) ** 2) / 4)
            + 0.75 * np.exp(-(9 * x + 1) ** 2 / 49 - (9 * y + 1) / 10)
            + 0.5 * np.exp(-((9 * x - 7) ** 2 + (9 * y - 3) ** 2) / 4)
            - 0.2 * np.exp(-(9 * x - 4) ** 2 - (9 * y - 7) ** 2))


def sample_points(n):
    """The first `n` sample positions and Franke's values there (a fixed seeded sequence).

    Examples
    --------
    >>> p, f = sample_points(5)
    >>> p.shape, f.shape, bool(np.allclose(f, franke(p[:, 0], p[:, 1])))
    ((5, 2), (5,), True)
    """
    p = np.random.default_rng(SEED).uniform(size=(MAX_POINTS, 2))[:int(n)]
    return p, franke(p[:, 0], p[:, 1])


@lru_cache(maxsize=1)
def _truth():
    axis = np.linspace(0.0, 1.0, GRID)
    X, Y = np.meshgrid(axis, axis)
    return franke(X, Y)


@lru_cache(maxsize=64)
def _triangulation(n):
    """The Delaunay triangulation of the first n samples (read-only)."""
    tris = scattered.delaunay_triangulation(sample_points(n)[0])
    tris.setflags(write=False)
    return tris


@lru_cache(maxsize=64)
def _edges(n):
    """The edges of the Delaunay triangulation of the first n samples, as segments."""
    p, _ = sample_points(n)
    tris = _triangulation(n)
    pairs = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    pairs = np.unique(pairs, axis=0)
    return p[pairs]


@dataclass
class State:
    """The method and its parameters, and the number of samples.

    Examples
    --------
    >>> State().method, State().n_points, State().kernel
    ('Shepard', 60, 'Gaussian')
    """

    method: str = "Shepard"
    n_points: int = 60
    power: float = 2.0
    kernel: str = "Gaussian"
    epsilon: float = 4.0


@lru_cache(maxsize=128)
def _field(method, n, power, kernel, epsilon):
    """The interpolant on the grid (read-only), or the error message of an unsolvable RBF."""
    p, f = sample_points(n)
    options = {"linear": {"outside": np.nan, "triangles": _triangulation(n)},
               "shepard": {"power": power},
               "rbf": {"kernel": kernel, "epsilon": epsilon}}.get(method, {})
    try:
        values, _ = scattered.resample_to_grid(p, f, (GRID, GRID), (0, 1, 0, 1), method,
                                               **options)
    except ValueError as error:
        return str(error)
    values.setflags(write=False)
    return values


def _key(state):
    method = METHODS[as_choice(state.method, "method", tuple(METHODS))]
    kernel = KERNELS[as_choice(state.kernel, "kernel", tuple(KERNELS))]
    n = int(state.n_points)
    if not 3 <= n <= MAX_POINTS:
        raise ValueError(f"n_points must be between 3 and {MAX_POINTS}, got {n}")
    power = float(state.power) if method == "shepard" else 0.0
    used_kernel = kernel if method == "rbf" else ""
    eps = float(state.epsilon) if method == "rbf" and kernel != "thin_plate_spline" else 1.0
    return method, n, power, used_kernel, eps


def _describe(method, power, kernel, eps):
    if method == "shepard":
        return f"Shepard, p = {power:g}"
    if method == "rbf":
        name = next(k for k, v in KERNELS.items() if v == kernel)
        return f"RBF, {name}" + ("" if kernel == "thin_plate_spline" else f", ε = {eps:g}")
    return {"nearest": "nearest neighbour", "linear": "linear (Delaunay)"}[method]


def scene(state):
    """Pure part: the interpolated field, the truth, the error and its statistics, the text.

    Examples
    --------
    >>> s = scene(State(method="nearest", n_points=20))
    >>> s["field"].shape, s["points"].shape, s["rms"] > 0
    ((80, 80), (20, 2), True)
    >>> s = scene(State(method="linear", n_points=30))
    >>> 0 < s["coverage"] < 1                # blank outside the convex hull
    True
    """
    method, n, power, kernel, eps = _key(state)
    points, _ = sample_points(n)
    truth = _truth()
    result = _field(method, n, power, kernel, eps)
    label = _describe(method, power, kernel, eps)
    if isinstance(result, str):
        field = np.full_like(truth, np.nan)
        error = field
        text = (f"<b>{label}</b>, {n} points: <span style='color:#c62828'>{result}.</span>")
        return {"field": field, "truth": truth, "error": error, "points": points,
                "edges": np.zeros((0, 2, 2)), "rms": np.nan, "max": np.nan, "coverage": 0.0, "title": label + ": no solution",
                "text": text, "solved": False}
    field = np.asarray(result)
    error = field - truth
    valid = ~np.isnan(error)
    rms = float(np.sqrt(np.mean(error[valid] ** 2)))
    worst = float(np.abs(error[valid]).max())
    coverage = float(valid.mean())
    where = ("" if coverage == 1 else
             f" (over the {100 * coverage:.0f} % of the grid inside the convex hull; no values "
             "outside it)")
    notes = {
        "nearest": "constant on each sample's Voronoi cell: jumps at the cell borders.",
        "linear": "a plane in each Delaunay triangle: continuous, creased along the edges.",
        "shepard": ("weights 1/d<sup>p</sup>, normalised: never beyond the data's range; "
                    + ("cusps at the samples (p ≤ 1)." if power <= 1 else
                       "flat spots at the samples; large p looks like nearest neighbour.")),
        "rbf": ("a sum of radial bumps from a linear system: smooth, may overshoot; small ε "
                "gives wide bumps and a nearly singular system."
                if kernel != "thin_plate_spline" else
                "r² log r plus a plane: the smoothest surface through the samples; ε has no "
                "effect."),
    }
    text = (f"<b>{label}</b>, {n} points: RMS error <b>{rms:.4f}</b>, max error "
            f"<b>{worst:.4f}</b>{where}. {notes[method].capitalize()}")
    edges = _edges(n) if method == "linear" else np.zeros((0, 2, 2))
    return {"field": field, "truth": truth, "error": error, "points": points,
            "edges": edges, "rms": rms,
            "max": worst, "coverage": coverage, "title": f"{label}, {n} points", "text": text,
            "solved": True}


class ScatteredDataExplorer(Explorer):
    """Method menu, Shepard's power, the RBF kernel and shape, the number of samples: the
    interpolant, the true function and the error.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ScatteredDataExplorer()``.

    Examples
    --------
    >>> explorer = ScatteredDataExplorer()
    >>> explorer.method.value = "RBF"
    >>> explorer.kernel.disabled, explorer.power.disabled
    (False, True)
    """

    summary = ("Scattered-data explorer (interactive): samples of Franke's function "
               "interpolated by nearest neighbour, linear on the Delaunay triangulation, "
               "Shepard's inverse-distance weighting or radial basis functions, with the true "
               "function and the error field (RMS and maximum).")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(8.6, 3.2))
        extent = (0, 1, 0, 1)
        low, high = float(s["truth"].min()), float(s["truth"].max())
        axes = [self.fig.add_axes((0.03 + 0.325 * k, 0.08, 0.25, 0.72)) for k in range(3)]
        self.image = axes[0].imshow(s["field"], origin="lower", extent=extent, cmap="viridis",
                                    vmin=low, vmax=high, interpolation="nearest")
        self.truth_image = axes[1].imshow(s["truth"], origin="lower", extent=extent,
                                          cmap="viridis", vmin=low, vmax=high)
        self.error_image = axes[2].imshow(s["error"], origin="lower", extent=extent,
                                          cmap="RdBu_r", vmin=-ERROR_RANGE, vmax=ERROR_RANGE,
                                          interpolation="nearest")
        self.edges = LineCollection(s["edges"], colors="white", linewidths=0.5, alpha=0.6)
        axes[0].add_collection(self.edges)
        self.samples = axes[0].scatter(*s["points"].T, s=7, c="white", edgecolors="black",
                                       linewidths=0.5)
        self.error_samples = axes[2].scatter(*s["points"].T, s=3, c="black")
        self.title = axes[0].set_title(s["title"])
        axes[1].set_title("true function (Franke)")
        self.error_title = axes[2].set_title("")
        for ax in axes:
            ax.set(xticks=[0, 1], yticks=[0, 1])
        for k, image in ((1, self.truth_image), (2, self.error_image)):
            bar = self.fig.add_axes((0.03 + 0.325 * k + 0.255, 0.08, 0.012, 0.72))
            self.fig.colorbar(image, cax=bar)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image, self.error_image, self.edges,
                                               self.samples,
                                               self.error_samples, self.title,
                                               self.error_title])
        self.method = w.ToggleButtons(options=tuple(METHODS), value=self.state.method,
                                      style={"button_width": _style.button_width(*METHODS)})
        self.n_points = slider("samples n", self.state.n_points, 10, MAX_POINTS, 5,
                               kind=w.IntSlider)
        self.power = slider("Shepard power p", self.state.power, 0.5, 8.0, 0.5)
        self.kernel = labelled(w.Dropdown, "RBF kernel", options=tuple(KERNELS),
                               value=self.state.kernel)
        self.epsilon = slider("RBF shape ε", self.state.epsilon, 0.5, 20.0, 0.5)
        align([self.n_points, self.power])
        align([self.kernel, self.epsilon])
        bind(self.state, {"method": self.method, "n_points": self.n_points,
                          "power": self.power, "kernel": self.kernel,
                          "epsilon": self.epsilon}, self.update)
        self.info = panel(width="780px")
        self.widget = w.VBox([self.fig.canvas, self.method,
                              w.HBox([w.VBox([self.n_points, self.power]),
                                      w.VBox([self.kernel, self.epsilon])],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute the scene (cached per setting) and redraw the moving artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        method = METHODS[self.state.method]
        self.power.disabled = method != "shepard"
        self.kernel.disabled = method != "rbf"
        self.epsilon.disabled = method != "rbf" or KERNELS[self.state.kernel] == \
            "thin_plate_spline"
        self.image.set_data(s["field"])
        self.error_image.set_data(s["error"])
        self.edges.set_segments(s["edges"])
        self.samples.set_offsets(s["points"])
        self.error_samples.set_offsets(s["points"])
        self.title.set_text(s["title"])
        self.error_title.set_text(f"error: RMS {s['rms']:.3f}, max {s['max']:.3f}"
                                  if s["solved"] else "error: no solution")
        self.info.value = s["text"]
