r"""Colour-map explorer: a colour map on data, its lightness curve and its greyscale print.

Pick a map (:data:`course_lib.colormaps.COLORMAP_NAMES`) and a data set. The left picture is
the data coloured by the map, the right one the same picture printed in black and white
(:func:`course_lib.colormaps.greyscale`: the grey of equal luminance). Below, the perceived
lightness :math:`L^*` (CIE 1976, 0 black .. 100 white) along the map, drawn in the map's own
colours, over the colour strip and its greyscale print.

A map for ordered data should have a lightness that rises (or falls) steadily: then "lighter"
reads as "more", the picture has no edges the data does not have, and it survives a greyscale
print. Rainbow and jet fail all three: their lightness climbs to yellow and cyan and drops
again, which draws bright bands into smooth data and prints values far apart in the same grey.
Viridis, cividis and their family were designed to rise evenly.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import colormaps, draw, scivis
from . import _style
from ._base import Explorer, align, beside, bind, checkbox, labelled, panel

__all__ = ["DATASETS", "State", "ColormapExplorer", "example_data", "print_ambiguity",
           "scene"]

DATASETS = ("smooth ramp", "hills", "ripple")
SAMPLES = 256
SIZE = 128


@dataclass
class State:
    """The colour map, whether it is reversed, and the data set.

    Examples
    --------
    >>> State().name, State().data
    ('jet', 'smooth ramp')
    """

    name: str = "jet"
    reverse: bool = False
    data: str = "smooth ramp"


@lru_cache(maxsize=None)
def example_data(kind="smooth ramp"):
    """The explorer's data, 128 x 128 on [-1, 1]^2, normalised to [0, 1].

    ``"smooth ramp"`` rises linearly from left to right with a low, wide bump in the middle:
    nothing in it has an edge. ``"hills"`` and ``"ripple"`` come from
    :func:`course_lib.scivis.example_field_2d`.

    Examples
    --------
    >>> f = example_data("smooth ramp")
    >>> f.shape, float(f.min()), float(f.max())
    ((128, 128), 0.0, 1.0)
    """
    if kind == "smooth ramp":
        x, y = np.meshgrid(np.linspace(-1, 1, SIZE), np.linspace(-1, 1, SIZE))
        values = x + 0.35 * np.exp(-(x ** 2 + y ** 2) / 0.18)
    elif kind in DATASETS:
        values = scivis.example_field_2d(kind, size=SIZE).values
    else:
        raise ValueError(f"kind must be one of {DATASETS}, got {kind!r}")
    out = colormaps.normalize(values)
    out.flags.writeable = False
    return out


def print_ambiguity(cmap, n=SAMPLES, distance=0.1, tolerance=0.01):
    """The fraction of a map's values whose greyscale print matches that of a distant value.

    A value t counts as ambiguous when some t' with :math:`|t - t'| \\ge` `distance` prints in
    a grey within `tolerance` of t's (greys from 0 black to 1 white): in a black-and-white print
    the two cannot be told apart. A map whose grey rises monotonically has no ambiguous values
    once `tolerance` is below the grey difference over `distance`.

    Parameters
    ----------
    cmap : str or array_like
        A colour map (see :func:`course_lib.colormaps.colormap`).
    n : int
        Samples along the map.
    distance, tolerance : float

    Returns
    -------
    float
        In [0, 1].

    Examples
    --------
    >>> print_ambiguity("viridis"), print_ambiguity("grey")
    (0.0, 0.0)
    >>> print_ambiguity("jet") > 0.5
    True
    """
    t = np.linspace(0.0, 1.0, n)
    g = colormaps.greyscale(colormaps.sample_colormap(cmap, n))
    far = np.abs(t[:, None] - t[None, :]) >= distance
    same = np.abs(g[:, None] - g[None, :]) < tolerance
    return float((far & same).any(axis=1).mean())


@lru_cache(maxsize=None)
def _analysis(name):
    """The perceptual analysis of a map (it does not depend on the data): cached per name."""
    return (colormaps.sample_colormap(name, SAMPLES), colormaps.lightness(name, SAMPLES),
            colormaps.is_monotonic_lightness(name, SAMPLES, tolerance=0.5),
            colormaps.perceptual_steps(name, 64), print_ambiguity(name))


def scene(state):
    """Pure part: the data in colour and in grey, the lightness curve and the verdicts.

    Returns
    -------
    dict
        ``cmap`` (the name, with "_r" when reversed), ``rgb`` (128 x 128 x 3), ``grey``
        (128 x 128: the greyscale print), ``t`` (256 positions along the map), ``colors``
        (256 x 3), ``lightness`` (L* at t), ``grey_strip`` (the greys at t), ``monotonic``
        (bool), ``steps`` (the colour differences Delta E between 64 neighbouring samples),
        ``ambiguity`` (:func:`print_ambiguity`) and ``text``.

    Examples
    --------
    >>> s = scene(State(name="viridis"))
    >>> s["rgb"].shape, s["monotonic"], s["ambiguity"]
    ((128, 128, 3), True, 0.0)
    >>> scene(State(name="rainbow"))["monotonic"]
    False
    """
    name = state.name + ("_r" if state.reverse else "")
    data = example_data(state.data)
    rgb = colormaps.apply_colormap(data, name, in_range=(0.0, 1.0))
    grey = colormaps.greyscale(rgb)
    t = np.linspace(0.0, 1.0, SAMPLES)
    colors, lightness, monotonic, steps, ambiguity = _analysis(name)
    turns = int(np.sum(np.diff(np.sign(np.diff(lightness[::4]))) != 0))
    verdict = ("<b style='color:#2e7d32'>monotonic</b>: lighter always means more (or always "
               "less)" if monotonic else
               f"<b style='color:#c62828'>not monotonic</b>: it changes direction {turns} "
               "time(s), so equal lightness stands for different values")
    text = (f"<b>{name}</b>: L* runs from {lightness[0]:.0f} to {lightness[-1]:.0f}, between "
            f"{lightness.min():.0f} and {lightness.max():.0f}; {verdict}. Colour steps between "
            f"64 neighbouring samples: ΔE = {steps.mean():.1f} on average, varying by "
            f"{100 * steps.std() / steps.mean():.0f} % (even steps, a small percentage, make a "
            "perceptually uniform map). In a greyscale print "
            f"{100 * ambiguity:.0f} % of the values share their grey with a value at least 0.1 "
            "away.")
    return {"cmap": name, "rgb": rgb, "grey": grey, "t": t, "colors": colors,
            "lightness": lightness, "grey_strip": colormaps.greyscale(colors),
            "monotonic": monotonic, "steps": steps, "ambiguity": ambiguity, "text": text}


class ColormapExplorer(Explorer):
    """Pick a colour map and a data set; see the map on the data, in print and its lightness.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ColormapExplorer()``.

    Examples
    --------
    >>> explorer = ColormapExplorer()
    >>> explorer.name.value = "viridis"
    >>> "monotonic" in explorer.info.value, explorer.state.name
    (True, 'viridis')
    """

    summary = ("Colour-map explorer (interactive): a colour map on data, its greyscale print and "
               "its lightness curve L*: rainbow and jet against viridis and friends.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(5.8, 4.9))
        grid = self.fig.add_gridspec(4, 2, height_ratios=(3.0, 2.1, 0.28, 0.28), left=0.11,
                                     right=0.98, bottom=0.1, top=0.95, hspace=0.35,
                                     wspace=0.12)
        extent = (-1, 1, -1, 1)
        color_ax = self.fig.add_subplot(grid[0, 0])
        self.color_image = color_ax.imshow(s["rgb"], origin="lower", extent=extent)
        color_ax.set_title("the data in colour")
        grey_ax = self.fig.add_subplot(grid[0, 1])
        self.grey_image = grey_ax.imshow(s["grey"], origin="lower", extent=extent,
                                         cmap="gray", vmin=0, vmax=1)
        grey_ax.set_title("printed in greyscale")
        for ax in (color_ax, grey_ax):
            ax.set(xticks=[], yticks=[])
        ax = self.fig.add_subplot(grid[1, :])
        ax.set(xlim=(0, 1), ylim=(0, 100), ylabel="lightness L*", yticks=[0, 50, 100])
        ax.tick_params(labelbottom=False)
        ax.grid(True, color="0.92")
        grey_l = colormaps.lightness("grey", SAMPLES)
        ax.set_title("lightness L* along the map, in the map's own colours")
        ax.plot(s["t"], grey_l, "--", color="0.55", lw=1, label="grey ramp (for reference)")
        self.line = LineCollection([], linewidths=4)
        ax.add_collection(self.line)
        _style.legend(ax, loc="upper left", borderpad=0.3, handlelength=1.5)
        strip_ax = self.fig.add_subplot(grid[2, :], sharex=ax)
        self.strip = strip_ax.imshow(s["colors"][None], aspect="auto", extent=(0, 1, 0, 1))
        strip_ax.set(yticks=[])
        strip_ax.tick_params(labelbottom=False)
        grey_strip_ax = self.fig.add_subplot(grid[3, :], sharex=ax)
        self.grey_strip = grey_strip_ax.imshow(s["grey_strip"][None], aspect="auto",
                                               extent=(0, 1, 0, 1), cmap="gray", vmin=0, vmax=1)
        grey_strip_ax.set(yticks=[], xlabel="position t along the map (normalised data value)")
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.color_image, self.grey_image, self.line,
                                               self.strip, self.grey_strip])
        self.name = labelled(w.Dropdown, "map", options=colormaps.COLORMAP_NAMES,
                             value=self.state.name)
        self.reverse = checkbox("reversed", self.state.reverse)
        self.data = labelled(w.Dropdown, "data", options=DATASETS, value=self.state.data)
        align([self.name, self.data])
        bind(self.state, {"name": self.name, "reverse": self.reverse, "data": self.data},
             self.update)
        self.info = panel(width="300px")
        controls = w.VBox([self.name, self.reverse, self.data, self.info])
        self.widget = beside(self.fig.canvas, controls, align="flex-start")
        self._draw(s)

    def update(self):
        """Recompute the scene and update the drawn artists (blitting)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.color_image.set_data(s["rgb"])
        self.grey_image.set_data(s["grey"])
        points = np.column_stack([s["t"], s["lightness"]])
        self.line.set_segments(np.stack([points[:-1], points[1:]], axis=1))
        self.line.set_colors(s["colors"][:-1])
        self.strip.set_data(s["colors"][None])
        self.grey_strip.set_data(s["grey_strip"][None])
        self.info.value = s["text"]
