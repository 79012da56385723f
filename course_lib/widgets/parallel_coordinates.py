r"""Parallel coordinates and a scatterplot matrix, linked by brushing (textbook 10.7).

:class:`ParallelCoordinatesExplorer` draws a table as polylines over parallel axes
(:func:`course_lib.dataviz.parallel_coordinates`): brush a range on any axis by dragging
vertically on it (a click on an axis removes its brush) or with the range slider of the axis
chosen in the menu; reorder the axes (swap with the next), flip one, combine the brushes with
AND or OR. :class:`~course_lib.widgets.scatterplot_matrix.ScatterplotMatrixExplorer` draws the
same table as a scatterplot matrix; drag a rectangle in a panel to brush two attributes at once.
Both read and write one :class:`Selection` (the data set and its brushes): pass one explorer's
``selection`` to the other, or call :func:`course_lib.widgets.scatterplot_matrix.link`, and a
brush in either highlights the same records in both.

Drawing 10,000 polylines as line artists would cost far more than the ~40 ms an update may
take. The polylines are rasterised instead (:class:`course_lib.dataviz.PolylineRaster`): their
pixel spans are computed once per data set, axis order and flips; the grey layer of all records
is kept, and a brush recounts only the selected layer (two ``numpy.bincount`` calls), paints it
over the grey one and blits the result.
"""
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from .. import draw
from .._validate import as_choice
from ..dataviz import multidim as md
from . import _style
from ._base import Explorer, beside, checkbox, labelled, panel, slider

__all__ = ["DATASETS", "ParallelCoordinatesExplorer", "Selection", "State", "scene"]

#: The data sets of the menu: a generated cars table, the correlation gallery, 10,000 days.
DATASETS = ("cars (150)",) + tuple(f"correlation: {k}" for k in md.GALLERY) \
    + ("weather (10,000)",)
HOW = ("AND", "OR")
GREY = np.array([110, 110, 110], dtype=float)
HIGHLIGHT = np.array([31, 119, 180], dtype=float)         # matplotlib's C0
BRUSH_COLOUR = "#ff7f0e"
PC_SIZE = (440, 190)               # the polyline image (width, height) of a scene by default


@lru_cache(maxsize=None)
def dataset(name):
    """The :class:`course_lib.dataviz.Table` of a menu entry (generated once).

    Examples
    --------
    >>> dataset("cars (150)").names[0], dataset("weather (10,000)").data.shape
    ('mpg', (10000, 5))
    """
    as_choice(name, "dataset", DATASETS)
    if name.startswith("cars"):
        return md.cars_table(150, seed=0)
    if name.startswith("weather"):
        return md.weather_table(10_000, seed=0)
    return md.correlation_gallery(200, seed=0)[name.split(": ", 1)[1]]


def default_brushes(table):
    """The brushes a data set starts with: the top 40 % of attribute 0 and the lower half of
    attribute 1 (so that AND and OR differ), keyed ``("axis", k)``.

    Examples
    --------
    >>> b = default_brushes(md.Table(np.array([[0.0, 0.0], [10.0, 4.0]]), ("x", "y")))
    >>> b[("axis", 0)], b[("axis", 1)]
    ({0: (6.0, 10.0)}, {1: (0.0, 2.0)})
    """
    r = md.column_ranges(table.data)
    span = r[:, 1] - r[:, 0]
    return {("axis", 0): {0: (float(r[0, 0] + 0.6 * span[0]), float(r[0, 1]))},
            ("axis", 1): {1: (float(r[1, 0]), float(r[1, 0] + 0.5 * span[1]))}}


class Selection:
    """The data set and the brushes that linked explorers share.

    A brush is stored under a key: ``("axis", k)`` for a range on attribute ``k`` (parallel
    coordinates), ``("rect",)`` for the rectangle of the scatterplot matrix; its value maps
    attributes to ``(low, high)`` in data units. Every change calls the subscribed callbacks
    with a word saying what changed (``"dataset"``, ``"brush"``).

    Examples
    --------
    >>> sel = Selection("correlation: positive")
    >>> sel.set_brush(("axis", 0), None); sel.set_brush(("axis", 1), None)
    >>> int(sel.mask().sum())
    200
    >>> sel.set_brush(("rect",), {0: (0.0, 5.0), 1: (0.0, 5.0)})
    >>> bool(sel.mask().sum() < 200)
    True
    """

    def __init__(self, name=DATASETS[0]):
        self.listeners = []
        self.how = "AND"
        self._load(name)

    def _load(self, name):
        self.dataset = as_choice(name, "dataset", DATASETS)
        self.table = dataset(name)
        self.brushes = default_brushes(self.table)
        self._mask = None

    @property
    def names(self):
        """The attribute names of the data set."""
        return self.table.names

    def subscribe(self, callback):
        """Call ``callback(what)`` after every change."""
        self.listeners.append(callback)

    def _changed(self, what):
        self._mask = None
        for callback in list(self.listeners):
            callback(what)

    def set_dataset(self, name):
        """Show another data set, with its default brushes."""
        self._load(name)
        self._changed("dataset")

    def set_brush(self, key, ranges):
        """Set (or with None or ``{}`` remove) the brush under `key`."""
        if ranges:
            self.brushes[key] = {int(k): (float(lo), float(hi)) for k, (lo, hi) in ranges.items()}
        else:
            self.brushes.pop(key, None)
        self._changed("brush")

    def set_how(self, how):
        """Combine the brushes with ``"AND"`` or ``"OR"``."""
        self.how = as_choice(how, "how", HOW)
        self._changed("brush")

    def clear(self):
        """Remove every brush."""
        self.brushes = {}
        self._changed("brush")

    def mask(self):
        """The selected records (:func:`course_lib.dataviz.brush_mask`), cached."""
        if self._mask is None:
            self._mask = md.brush_mask(self.table.data, list(self.brushes.values()),
                                       self.how.lower())
        return self._mask

    def describe(self):
        """The brushes in words, and how many records they select (HTML)."""
        names, parts = self.names, []
        for key in sorted(self.brushes, key=str):
            ranges = " and ".join(f"{names[k]} ∈ [{lo:.4g}, {hi:.4g}]"
                                  for k, (lo, hi) in sorted(self.brushes[key].items()))
            parts.append(f"({ranges})" if len(self.brushes[key]) > 1 else ranges)
        chosen = int(self.mask().sum())
        n = len(self.table.data)
        if not parts:
            return f"No brush: all {n:,} records are selected."
        return (f" <b>{self.how}</b> ".join(parts)
                + f": <b>{chosen:,}</b> of {n:,} records selected.")


# ---------------------------------------------------------------------------------------------
# Parallel coordinates: the pure part
# ---------------------------------------------------------------------------------------------

@dataclass
class State:
    """The shared selection, the axis order, the flipped attributes, the attribute the
    controls act on, and the size of the polyline image.

    Examples
    --------
    >>> s = State()
    >>> s.selection.dataset, s.order, s.axis
    ('cars (150)', [0, 1, 2, 3, 4, 5], 0)
    """

    selection: Selection = field(default_factory=Selection)
    order: list = None
    flipped: list = None
    axis: int = 0
    image_size: tuple = PC_SIZE

    def __post_init__(self):
        d = len(self.selection.names)
        if self.order is None or sorted(self.order) != list(range(d)):
            self.order = list(range(d))
        if self.flipped is None or len(self.flipped) != d:
            self.flipped = [False] * d
        if not 0 <= self.axis < d:
            self.axis = 0


@lru_cache(maxsize=8)
def _pc_raster(name, order, flipped, size):
    table = dataset(name)
    lines = md.parallel_coordinates(table.data, order=order,
                                    flip=[k for k in range(len(order)) if flipped[k]])
    lines[..., 0] /= len(order) - 1
    return lines, md.PolylineRaster(lines, size[0], size[1], extent=(0.0, 1.0, 0.0, 1.0))


def _layer(counts, colour, gain):
    """RGBA uint8 image of a count image: the colour, opacity 1 - exp(-gain * count)."""
    alpha = 1.0 - np.exp(-gain * counts)
    out = np.empty(counts.shape + (4,), dtype=np.uint8)
    out[..., :3] = colour.astype(np.uint8)
    out[..., 3] = (255 * alpha).astype(np.uint8)
    return out


def _over_white(*layers):
    """RGBA uint8 layers painted in order over white: one opaque RGB uint8 image.

    The explorer shows this instead of two translucent images: matplotlib drew the translucent
    highlight differently when blitting and when saving the figure (9 % of the pixels of the
    live frame differed from the stored picture); an opaque image reads the same in both.
    """
    out = np.full(layers[0].shape[:2] + (3,), 255.0)
    for layer in layers:
        alpha = layer[..., 3:] / 255.0
        out += alpha * (layer[..., :3] - out)
    return np.rint(out).astype(np.uint8)


def _gains(n):
    """How dark one record's line is: lighter when there are many."""
    return min(0.6, 25.0 / n), min(1.6, 120.0 / n)


def scene(state):
    """Pure part: the polylines, the grey and the highlighted layer, the brushes, the text.

    Returns
    -------
    dict
        ``lines`` (n, d, 2) in display units (axis ``k`` at ``x = k / (d - 1)``), ``mask``,
        ``counts`` and ``selected_counts`` (the raster of all and of the selected records),
        ``base`` and ``selected`` (RGBA images over ``[0, 1]^2``), ``axis_x``, ``labels``,
        ``low_labels`` and ``high_labels`` (the value at the bottom and top of each axis),
        ``boxes`` (brush ranges drawn on an axis: ``(x, y_low, y_high, kind)``), ``title``,
        ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["lines"].shape, s["labels"][:2], int(s["mask"].sum()) == int(s["title"].split()[0])
    ((150, 6, 2), ('mpg', 'cylinders'), True)
    """
    sel = state.selection
    table = sel.table
    n, d = table.data.shape
    order, flipped = tuple(state.order), tuple(bool(f) for f in state.flipped)
    lines, raster = _pc_raster(sel.dataset, order, flipped, tuple(state.image_size))
    mask = sel.mask()
    counts = raster.counts()
    chosen = raster.counts(mask)
    grey, bright = _gains(n)
    ranges = md.column_ranges(table.data)
    position = {attr: k / (d - 1) for k, attr in enumerate(order)}

    def height(attr, value):
        lo, hi = ranges[attr]
        f = (value - lo) / (hi - lo) if hi > lo else 0.5
        f = min(max(f, 0.0), 1.0)
        return 1.0 - f if flipped[attr] else f

    boxes = []
    for key, brush in sorted(sel.brushes.items(), key=lambda kv: str(kv[0])):
        for attr, (lo, hi) in sorted(brush.items()):
            a, b = sorted((height(attr, lo), height(attr, hi)))
            boxes.append((position[attr], a, b, key[0]))
    ends = [(f"{ranges[a][0]:.4g}", f"{ranges[a][1]:.4g}") for a in order]
    low_labels = tuple(hi if flipped[a] else lo for a, (lo, hi) in zip(order, ends))
    high_labels = tuple(lo if flipped[a] else hi for a, (lo, hi) in zip(order, ends))
    selected = int(mask.sum())
    joined = f" ({sel.how})" if len(sel.brushes) > 1 else ""
    title = f"{selected:,} of {n:,} records selected{joined}"
    names = table.names
    text = (f"<b>{sel.dataset}</b>: {n:,} records, {d} attributes. Axis order: "
            + " | ".join(("↕" if flipped[a] else "") + names[a] for a in order)
            + ". " + sel.describe())
    return {"lines": lines, "mask": mask, "counts": counts, "selected_counts": chosen,
            "base": _layer(counts, GREY, grey), "selected": _layer(chosen, HIGHLIGHT, bright),
            "axis_x": np.arange(d) / (d - 1), "labels": tuple(names[a] for a in order),
            "low_labels": low_labels, "high_labels": high_labels, "boxes": boxes,
            "title": title, "text": text}


def _pixel_exact_limits(ax, span, margin):
    """Set `ax`'s limits so that the unit square [0, 1]^2, where the rasters are drawn, covers
    a whole number of screen pixels from a pixel boundary: each raster pixel is then one
    screen pixel (a raster a fraction of a pixel narrower than its place on screen has one
    column doubled somewhere, which breaks a thin line).
    `span` is the data width and height the axes show, `margin` what lies left of and below
    the square. Returns the raster's size (columns, rows)."""
    bbox = ax.get_window_extent()
    size = []
    for lo_px, extent_px, s, m, setter in ((bbox.x0, bbox.width, span[0], margin[0], ax.set_xlim),
                                           (bbox.y0, bbox.height, span[1], margin[1], ax.set_ylim)):
        n = max(16, int(extent_px / s))
        start = np.ceil(lo_px + m * extent_px / s)          # the pixel boundary of 0
        low = -(start - lo_px) / n                          # data value at the axes' edge
        setter(low, low + extent_px / n)
        size.append(n)
    return tuple(size)


class ParallelCoordinatesExplorer(Explorer):
    """Parallel coordinates of a table with brushing on every axis, axis reordering and
    flipping; selected records in colour, the others grey.

    Drag vertically on an axis to brush a range of it (a click on an axis removes its brush).
    In a notebook, after ``%matplotlib widget``, end a cell with
    ``ParallelCoordinatesExplorer()``.

    Parameters
    ----------
    selection : Selection, optional
        Share it with a :class:`ScatterplotMatrixExplorer` to link the two.

    Examples
    --------
    >>> explorer = ParallelCoordinatesExplorer()
    >>> before = int(explorer.current["mask"].sum())
    >>> explorer.how.value = "OR"
    >>> int(explorer.current["mask"].sum()) > before
    True
    """

    summary = ("Parallel coordinates explorer (interactive): every record a polyline over one "
               "vertical axis per attribute; brush ranges on the axes (AND / OR), reorder and "
               "flip the axes; the selected records in colour, the others grey.")

    def __init__(self, selection=None):
        import ipywidgets as w

        self.selection = selection or Selection()
        self.state = State(selection=self.selection)
        self._syncing = False
        self._drag = None
        self.fig = draw.figure(figsize=(5.3, 3.0))
        self.ax = self.fig.add_axes((0.02, 0.07, 0.96, 0.82))
        self.ax.axis("off")
        # limits: x in [-0.07, 1.07], y in [-0.1, 1.1], adjusted to whole pixels
        self.state.image_size = _pixel_exact_limits(self.ax, (1.14, 1.2), (0.07, 0.1))
        # the grey layer and the selected one, painted together into one opaque image (_draw)
        self.highlight = self.ax.imshow(np.zeros((2, 2, 3), np.uint8), extent=(0.0, 1.0, 0.0, 1.0),
                                        origin="lower", aspect="auto", interpolation="nearest",
                                        zorder=2)
        from matplotlib.collections import LineCollection, PolyCollection

        self.axis_lines = LineCollection([], colors="0.15", linewidths=1.0, zorder=3)
        self.ax.add_collection(self.axis_lines)
        self.brush_boxes = PolyCollection([], facecolors=BRUSH_COLOUR, edgecolors=BRUSH_COLOUR,
                                          alpha=0.35, linewidths=1.0, zorder=4)
        self.rect_boxes = PolyCollection([], facecolors="none", edgecolors="#d62728",
                                         linestyles="--", linewidths=1.2, zorder=4)
        self.ax.add_collection(self.brush_boxes)
        self.ax.add_collection(self.rect_boxes)
        (self.current_axis,) = self.ax.plot([], [], color=BRUSH_COLOUR, lw=3.5, alpha=0.8,
                                            zorder=2.5, solid_capstyle="butt")
        self.title = self.ax.set_title("", fontsize=_style.TITLE)
        self.names, self.lows, self.highs = [], [], []
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.highlight, self.current_axis,
                                               self.brush_boxes, self.rect_boxes, self.title])

        self.dataset = labelled(w.Dropdown, "data set", options=DATASETS,
                                value=self.selection.dataset)
        self.axis_menu = labelled(w.Dropdown, "brush axis", options=self._axis_options(),
                                  value=0)
        self.range = slider("range (0 = min, 1 = max)", self._slider_value(0), 0, 1, 0.01,
                            kind=w.FloatRangeSlider)
        self.flip = checkbox("flip this axis", False)
        self.swap = w.Button(description="swap with next axis",
                             layout=w.Layout(width=_style.button_width("swap with next axis")))
        self.how = w.ToggleButtons(options=HOW, value=self.selection.how, description="combine",
                                   style={"button_width": _style.button_width(*HOW)})
        self.clear = w.Button(description="clear brushes",
                              layout=w.Layout(width=_style.button_width("clear brushes")))
        self.dataset.observe(self._on_dataset, names="value")
        self.axis_menu.observe(self._on_axis, names="value")
        self.range.observe(self._on_range, names="value")
        self.flip.observe(self._on_flip, names="value")
        self.swap.on_click(self._on_swap)
        self.how.observe(self._on_how, names="value")
        self.clear.on_click(lambda _: self.selection.clear())
        self.info = panel(width="600px")
        self.controls = w.VBox([self.dataset, self.axis_menu, self.range,
                                w.HBox([self.flip, self.swap]), self.how, self.clear])
        self.widget = w.VBox([beside(self.fig.canvas, self.controls), self.info])
        canvas = self.fig.canvas
        self._cids = [canvas.mpl_connect("button_press_event", self._on_press),
                      canvas.mpl_connect("motion_notify_event", self._on_motion),
                      canvas.mpl_connect("button_release_event", self._on_release)]
        self.selection.subscribe(self._on_selection)
        self._static(scene(self.state))

    # --- helpers -------------------------------------------------------------------------------
    def _axis_options(self):
        return [(name, k) for k, name in enumerate(self.selection.names)]

    def _slider_value(self, attr):
        brush = self.selection.brushes.get(("axis", attr))
        if not brush:
            return (0.0, 1.0)
        lo, hi = md.column_ranges(self.selection.table.data)[attr]
        a, b = brush[attr]
        span = hi - lo if hi > lo else 1.0
        return (round(min(max((a - lo) / span, 0), 1), 2), round(min(max((b - lo) / span, 0), 1), 2))

    def _sync_controls(self):
        """Show the chosen axis's brush and flip in the controls, without acting on them."""
        self._syncing = True
        try:
            attr = self.state.axis
            if self.axis_menu.value != attr:
                self.axis_menu.value = attr
            value = self._slider_value(attr)
            if tuple(self.range.value) != value:
                self.range.value = value
            self.flip.value = bool(self.state.flipped[attr])
            self.how.value = self.selection.how
        finally:
            self._syncing = False

    # --- control handlers ------------------------------------------------------------------
    def _on_dataset(self, change):
        if not self._syncing:
            self.selection.set_dataset(change["new"])

    def _on_axis(self, change):
        if self._syncing or change["new"] is None:
            return
        self.state.axis = int(change["new"])
        self._sync_controls()
        self.update()

    def _on_range(self, change):
        if self._syncing:
            return
        attr = self.state.axis
        lo, hi = (float(v) for v in change["new"])
        if hi - lo < 1e-9 or (lo <= 0 and hi >= 1):
            self.selection.set_brush(("axis", attr), None)
            return
        r_lo, r_hi = md.column_ranges(self.selection.table.data)[attr]
        span = r_hi - r_lo if r_hi > r_lo else 1.0
        self.selection.set_brush(("axis", attr), {attr: (r_lo + lo * span, r_lo + hi * span)})

    def _on_flip(self, change):
        if self._syncing:
            return
        self.state.flipped[self.state.axis] = bool(change["new"])
        self._static(scene(self.state))

    def _on_swap(self, _=None):
        order = self.state.order
        k = order.index(self.state.axis)
        j = (k + 1) % len(order)
        order[k], order[j] = order[j], order[k]
        self._static(scene(self.state))

    def _on_how(self, change):
        if not self._syncing:
            self.selection.set_how(change["new"])

    def _on_selection(self, what):
        if what == "dataset":
            self.state = State(selection=self.selection, image_size=self.state.image_size)
            self._syncing = True
            try:
                self.dataset.value = self.selection.dataset
                self.axis_menu.options = self._axis_options()
            finally:
                self._syncing = False
            self._sync_controls()
            self._static(scene(self.state))
        else:
            self._sync_controls()
            self.update()

    # --- the mouse: brushing on an axis ------------------------------------------------------
    def _axis_at(self, x):
        d = len(self.state.order)
        k = int(round(x * (d - 1)))
        if 0 <= k < d and abs(x - k / (d - 1)) <= 0.3 / (d - 1):
            return self.state.order[k]
        return None

    def brush_drag(self, attr, y0, y1, final=False):
        """Brush attribute `attr` between the display heights `y0` and `y1` (what a drag along
        its axis does; ``y0 == y1`` removes the brush)."""
        table = self.selection.table
        lo, hi = md.column_ranges(table.data)[attr]
        a, b = sorted((min(max(y0, 0.0), 1.0), min(max(y1, 0.0), 1.0)))
        if self.state.flipped[attr]:
            a, b = 1.0 - b, 1.0 - a
        self.state.axis = attr
        if b - a < 0.005:
            if final:
                self.selection.set_brush(("axis", attr), None)
            return
        self.selection.set_brush(("axis", attr), {attr: (lo + a * (hi - lo), lo + b * (hi - lo))})

    def _on_press(self, event):
        if event.inaxes is not self.ax or event.button != 1 or event.xdata is None:
            return
        attr = self._axis_at(event.xdata)
        if attr is not None:
            self._drag = (attr, float(event.ydata))

    def _on_motion(self, event):
        if self._drag is None or event.inaxes is not self.ax or event.ydata is None:
            return
        self.brush_drag(self._drag[0], self._drag[1], float(event.ydata))

    def _on_release(self, event):
        if self._drag is None:
            return
        attr, y0 = self._drag
        self._drag = None
        y1 = float(event.ydata) if event.inaxes is self.ax and event.ydata is not None else y0
        self.brush_drag(attr, y0, y1, final=True)

    def mouse_gestures(self):
        """A vertical drag along the first axis (brushes that range of its attribute).

        Examples
        --------
        >>> [g["kind"] for g in ParallelCoordinatesExplorer().mouse_gestures()]
        ['drag']
        """
        return super().mouse_gestures() + [{
            "kind": "drag", "what": "brush along the first axis",
            "start": self._canvas_fraction(self.ax, (0.0, 0.15)),
            "end": self._canvas_fraction(self.ax, (0.0, 0.65))}]

    # --- drawing -------------------------------------------------------------------------------
    def update(self):
        """Recount the highlighted layer and redraw the moving artists (blitted)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _static(self, s):
        """Order, flips or data set changed: redraw the grey layer, axes and labels fully."""
        self.axis_lines.set_segments([[(x, 0), (x, 1)] for x in s["axis_x"]])
        for text in self.names + self.lows + self.highs:
            text.remove()
        flipped = [self.state.flipped[a] for a in self.state.order]
        # below the moving layers (zorder 1.5): outside the image, so nothing covers them,
        # and a blit need not draw them again
        self.names = [self.ax.text(x, 1.06, ("↕ " if f else "") + name, ha="center",
                                   va="bottom", fontsize=_style.ANNOTATION, zorder=1.5)
                      for x, name, f in zip(s["axis_x"], s["labels"], flipped)]
        self.lows = [self.ax.text(x, -0.03, t, ha="center", va="top", fontsize=7, color="0.3",
                                  zorder=1.5)
                     for x, t in zip(s["axis_x"], s["low_labels"])]
        self.highs = [self.ax.text(x, 1.01, t, ha="center", va="bottom", fontsize=7,
                                   color="0.3", zorder=1.5) for x, t in zip(s["axis_x"], s["high_labels"])]
        self._draw(s)
        self.blitter.forget_background()
        self.fig.canvas.draw_idle()

    def _draw(self, s):
        self.current = s
        self.highlight.set_data(_over_white(s["base"], s["selected"]))
        boxes = [b for b in s["boxes"] if b[3] == "axis"]
        rects = [b for b in s["boxes"] if b[3] != "axis"]
        half = 0.018
        self.brush_boxes.set_verts([[(x - half, a), (x + half, a), (x + half, b), (x - half, b)]
                                    for x, a, b, _ in boxes])
        self.rect_boxes.set_verts([[(x - 1.6 * half, a), (x + 1.6 * half, a),
                                    (x + 1.6 * half, b), (x - 1.6 * half, b)]
                                   for x, a, b, _ in rects])
        x = s["axis_x"][self.state.order.index(self.state.axis)]
        self.current_axis.set_data([x, x], [-0.02, 1.02])
        self.title.set_text(s["title"])
        self.info.value = s["text"]
