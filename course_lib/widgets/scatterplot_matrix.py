r"""A scatterplot matrix linked to parallel coordinates by brushing (textbook 10.7).

:class:`ScatterplotMatrixExplorer` draws a table as a scatterplot matrix (one panel per pair of
attributes, histograms or names on the diagonal); drag a rectangle in a panel to brush two
attributes at once. It reads and writes the :class:`~course_lib.widgets.parallel_coordinates.Selection`
of a :class:`~course_lib.widgets.parallel_coordinates.ParallelCoordinatesExplorer`:
:func:`link` shows the two side by side (:class:`LinkedExplorers`), and a brush in either
highlights the same records in both.

As in parallel coordinates, the panels are one image: the grey layer of all records is cached
and a brush recounts only the selected layer and blits it.
"""
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from .. import draw
from .._validate import as_choice
from ..dataviz import multidim as md
from . import _style
from ._base import Explorer
from .parallel_coordinates import GREY, HIGHLIGHT, ParallelCoordinatesExplorer, Selection, dataset

__all__ = ["LinkedExplorers", "ScatterplotMatrixExplorer", "SplomState", "link", "splom_scene"]

SPLOM_SIDE = 330                   # pixels across the scatterplot matrix image by default
MARGIN = 0.06                      # of a panel, around its points
BINS = 12                          # histogram bins on the matrix's diagonal


# ---------------------------------------------------------------------------------------------
# Scatterplot matrix: the pure part
# ---------------------------------------------------------------------------------------------

@dataclass
class SplomState:
    """The shared selection, the diagonal (histograms or names) and the size of the image
    (pixels across; each of the d panels gets ``side // d``).

    Examples
    --------
    >>> SplomState().diagonal
    'histogram'
    """

    selection: Selection = field(default_factory=Selection)
    diagonal: str = "histogram"
    side: int = SPLOM_SIDE


@lru_cache(maxsize=8)
def _splom_pixels(name, size):
    """For every record and off-diagonal panel, the flat pixel index of its dot (a 2 x 2
    square for small tables, one pixel for large ones), and each record's histogram bins."""
    table = dataset(name)
    n, d = table.data.shape
    y = md.normalise_columns(table.data)
    pix = np.clip(np.floor((MARGIN + (1 - 2 * MARGIN) * y) * size), 0, size - 1).astype(np.int64)
    side = d * size
    splat = [(0, 0)] if n > 2000 else [(i, j) for i in range(3) for j in range(3)]
    index = []
    for r in range(d):
        for c in range(d):
            if r != c:
                row = (d - 1 - r) * size + pix[:, r]          # image row 0 at the bottom
                col = c * size + pix[:, c]
                for dr, dc in splat:
                    index.append(np.minimum(row + dr, side - 1) * side
                                 + np.minimum(col + dc, side - 1))
    bins = np.minimum((y * BINS).astype(np.int64), BINS - 1)     # (n, d)
    return np.stack(index, axis=1), bins


def _histogram_layer(image_counts, bins, weights, d, size, colour_mask):
    """Paint histogram bars into `colour_mask` (bool, side x side) for the diagonal panels."""
    inner = size * (1 - 2 * MARGIN)
    for k in range(d):
        counts = np.bincount(bins[:, k], weights=weights, minlength=BINS)
        top = image_counts[k]
        heights = np.zeros(BINS) if top == 0 else counts / top * inner
        x0, y0 = k * size, (d - 1 - k) * size
        edges = (x0 + MARGIN * size + inner * np.arange(BINS + 1) / BINS).astype(int)
        for b in range(BINS):
            h = int(round(heights[b]))
            if h > 0:
                base = int(y0 + MARGIN * size)
                colour_mask[base:base + h, edges[b]:max(edges[b + 1] - 1, edges[b] + 1)] = True


def splom_scene(state):
    """Pure part of the scatterplot matrix: one RGB image of all its panels, the rectangle
    brush, the names.

    Panel ``(row, col)`` plots attribute ``col`` across and attribute ``row`` up, and occupies
    ``[col, col + 1] x [d - 1 - row, d - row]`` of the display; the points are the normalised
    values (:func:`course_lib.dataviz.scatterplot_matrix`), inset by a margin.

    Returns
    -------
    dict
        ``image`` (side, side, 3) uint8 with row 0 at the bottom, ``counts`` and
        ``selected_counts`` (dots per pixel), ``d``, ``names``, ``mask``, ``rect`` (None or
        ``(x0, y0, x1, y1)`` in display units), ``title``.

    Examples
    --------
    >>> s = splom_scene(SplomState())
    >>> s["image"].shape, s["d"]
    ((330, 330, 3), 6)
    """
    sel = state.selection
    table = sel.table
    n, d = table.data.shape
    size = max(8, int(state.side) // d)
    as_choice(state.diagonal, "diagonal", ("histogram", "names"))
    index, bins = _splom_pixels(sel.dataset, size)
    side = d * size
    mask = sel.mask()
    counts = np.bincount(index.ravel(), minlength=side * side).reshape(side, side)
    chosen = np.bincount(index[mask].ravel(), minlength=side * side).reshape(side, side)
    dots = np.float32(min(1.0, 300.0 / n))
    a = np.exp(-dots * counts.astype(np.float32))[..., None]       # 1 - opacity of the grey
    b = np.exp(-3 * dots * chosen.astype(np.float32))[..., None]   # and of the colour
    grey, colour = (GREY + 80).astype(np.float32), HIGHLIGHT.astype(np.float32)
    image = ((np.float32(255) - grey) * a + grey - colour) * b + colour
    if state.diagonal == "histogram":
        tallest = [int(np.bincount(bins[:, k], minlength=BINS).max()) for k in range(d)]
        everything = np.zeros((side, side), bool)
        picked = np.zeros((side, side), bool)
        _histogram_layer(tallest, bins, None, d, size, everything)
        _histogram_layer(tallest, bins, mask.astype(float), d, size, picked)
        image[everything] = GREY + 90
        image[picked] = HIGHLIGHT
    rect = None
    brush = sel.brushes.get(("rect",))
    if brush and len(brush) == 2:
        ranges = md.column_ranges(table.data)
        (cx, (xlo, xhi)), (ry, (ylo, yhi)) = _rect_axes(brush)

        def place(attr, value, offset):
            lo, hi = ranges[attr]
            f = (value - lo) / (hi - lo) if hi > lo else 0.5
            return offset + MARGIN + (1 - 2 * MARGIN) * min(max(f, 0.0), 1.0)

        rect = (place(cx, xlo, cx), place(ry, ylo, d - 1 - ry),
                place(cx, xhi, cx), place(ry, yhi, d - 1 - ry))
    selected = int(mask.sum())
    return {"image": image.astype(np.uint8), "counts": counts, "selected_counts": chosen,
            "d": d, "names": table.names, "mask": mask, "rect": rect,
            "title": f"{selected:,} of {n:,} selected"}


def _rect_axes(brush):
    """The (x attribute, range) and (y attribute, range) of a rectangle brush (stored in that
    order: dicts keep their insertion order)."""
    items = list(brush.items())
    return items[0], items[1]


# ---------------------------------------------------------------------------------------------
# The explorers
# ---------------------------------------------------------------------------------------------


class ScatterplotMatrixExplorer(Explorer):
    """A scatterplot matrix of a table, histograms (or names) on the diagonal; drag a
    rectangle in a panel to brush its two attributes (a click removes it).

    Parameters
    ----------
    selection : Selection, optional
        Share it with a :class:`ParallelCoordinatesExplorer` to link the two.

    Examples
    --------
    >>> pc = ParallelCoordinatesExplorer()
    >>> splom = ScatterplotMatrixExplorer(pc.selection)
    >>> pc.clear.click()
    >>> int(splom.current["mask"].sum())
    150
    """

    summary = ("Scatterplot matrix explorer (interactive): one scatter plot per pair of "
               "attributes, histograms on the diagonal; drag a rectangle to brush two "
               "attributes; linked to parallel coordinates through a shared selection.")

    def __init__(self, selection=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection
        from matplotlib.patches import Rectangle

        self.selection = selection or Selection()
        self.state = SplomState(selection=self.selection)
        self._drag = None
        self.fig = draw.figure(figsize=(4.3, 4.3))
        self.ax = self.fig.add_axes((0.1, 0.1, 0.86, 0.84))
        self.ax.set_xticks([])
        self.ax.set_yticks([])
        for spine in self.ax.spines.values():
            spine.set_visible(False)
        bbox = self.ax.get_window_extent()
        self.state.side = max(32, int(min(bbox.width, bbox.height)))
        self.image = self.ax.imshow(np.zeros((2, 2, 3), np.uint8), origin="lower",
                                    interpolation="nearest", aspect="auto", zorder=1)
        self.grid = LineCollection([], colors="0.55", linewidths=0.8, zorder=3)
        self.ax.add_collection(self.grid)
        self.rect = Rectangle((0, 0), 0, 0, fill=False, ec="#d62728", lw=1.5, ls="--",
                              zorder=4, visible=False)
        self.ax.add_patch(self.rect)
        self.title = self.ax.set_title("", fontsize=_style.TITLE)
        self.labels = []
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image, self.rect, self.title])
        self.diagonal = w.ToggleButtons(options=("histogram", "names"),
                                        value=self.state.diagonal, description="diagonal",
                                        style={"button_width": _style.button_width("histogram")})
        self.diagonal.observe(self._on_diagonal, names="value")
        self.controls = w.VBox([self.diagonal])
        self.widget = w.VBox([self.fig.canvas, self.diagonal])
        canvas = self.fig.canvas
        self._cids = [canvas.mpl_connect("button_press_event", self._on_press),
                      canvas.mpl_connect("motion_notify_event", self._on_motion),
                      canvas.mpl_connect("button_release_event", self._on_release)]
        self.selection.subscribe(self._on_selection)
        self._static(splom_scene(self.state))

    def _on_diagonal(self, change):
        self.state.diagonal = change["new"]
        self._static(splom_scene(self.state))

    def _on_selection(self, what):
        if what == "dataset":
            self._static(splom_scene(self.state))
        else:
            self.update()

    # --- the mouse: a rectangle in a panel ---------------------------------------------------
    def _panel_at(self, x, y):
        d = self.current["d"]
        c, r = int(np.floor(x)), d - 1 - int(np.floor(y))
        if 0 <= c < d and 0 <= r < d and r != c:
            return r, c
        return None

    def _value(self, attr, position, offset):
        lo, hi = md.column_ranges(self.selection.table.data)[attr]
        f = (position - offset - MARGIN) / (1 - 2 * MARGIN)
        return lo + min(max(f, 0.0), 1.0) * (hi - lo)

    def brush_rectangle(self, panel, start, end, final=False):
        """Brush the rectangle from `start` to `end` (display units) in panel ``(row, col)``
        (what a drag does; a click, ``start == end``, removes the rectangle)."""
        r, c = panel
        d = self.current["d"]
        xs = sorted(self._value(c, v, c) for v in (start[0], end[0]))
        ys = sorted(self._value(r, v, d - 1 - r) for v in (start[1], end[1]))
        lo_c, hi_c = md.column_ranges(self.selection.table.data)[c]
        lo_r, hi_r = md.column_ranges(self.selection.table.data)[r]
        if xs[1] - xs[0] < 0.01 * (hi_c - lo_c) or ys[1] - ys[0] < 0.01 * (hi_r - lo_r):
            if final:
                self.selection.set_brush(("rect",), None)
            return
        self.selection.set_brush(("rect",), {c: tuple(xs), r: tuple(ys)})

    def _on_press(self, event):
        if event.inaxes is not self.ax or event.button != 1 or event.xdata is None:
            return
        panel = self._panel_at(event.xdata, event.ydata)
        if panel is not None:
            self._drag = (panel, (float(event.xdata), float(event.ydata)))

    def _on_motion(self, event):
        if self._drag is None or event.inaxes is not self.ax or event.xdata is None:
            return
        self.brush_rectangle(self._drag[0], self._drag[1], (event.xdata, event.ydata))

    def _on_release(self, event):
        if self._drag is None:
            return
        panel, start = self._drag
        self._drag = None
        end = ((event.xdata, event.ydata) if event.inaxes is self.ax and event.xdata is not None
               else start)
        self.brush_rectangle(panel, start, end, final=True)

    def mouse_gestures(self):
        """A rectangle dragged in the bottom-left panel (the last attribute against the first).

        Examples
        --------
        >>> [g["kind"] for g in ScatterplotMatrixExplorer().mouse_gestures()]
        ['drag']
        """
        return super().mouse_gestures() + [{
            "kind": "drag", "what": "a rectangle in the bottom-left panel",
            "start": self._canvas_fraction(self.ax, (0.25, 0.2)),
            "end": self._canvas_fraction(self.ax, (0.75, 0.7))}]

    # --- drawing -------------------------------------------------------------------------------
    def update(self):
        """Recount the selected dots and redraw the image (blitted)."""
        self._draw(splom_scene(self.state))
        self.blitter.update()

    def _static(self, s):
        d = s["d"]
        self.image.set_extent((0, d, 0, d))
        self.ax.set(xlim=(0, d), ylim=(0, d))
        self.grid.set_segments([[(k, 0), (k, d)] for k in range(d + 1)]
                               + [[(0, k), (d, k)] for k in range(d + 1)])
        for text in self.labels:
            text.remove()
        names = s["names"]
        if self.state.diagonal == "names":
            self.labels = [self.ax.text(k + 0.5, d - k - 0.5, name, ha="center", va="center",
                                        fontsize=_style.ANNOTATION, fontweight="bold", zorder=5)
                           for k, name in enumerate(names)]
        else:
            self.labels = [self.ax.text(k + 0.5, d - k - 0.04, name, ha="center", va="top",
                                        fontsize=7, zorder=5,
                                        bbox={"boxstyle": "round,pad=0.1", "fc": "white",
                                              "ec": "none", "alpha": 0.75})
                           for k, name in enumerate(names)]
        # outside the image, below the moving layers: a blit need not draw them again
        self.labels += [self.ax.text(k + 0.5, -0.04, name, ha="center", va="top", fontsize=7,
                                     zorder=0.5) for k, name in enumerate(names)]
        self.labels += [self.ax.text(-0.04, d - k - 0.5, name, ha="right", va="center",
                                     fontsize=7, rotation=90, zorder=0.5)
                        for k, name in enumerate(names)]
        self._draw(s)
        self.blitter.forget_background()
        self.fig.canvas.draw_idle()

    def _draw(self, s):
        self.current = s
        self.image.set_data(s["image"])
        if s["rect"] is None:
            self.rect.set_visible(False)
        else:
            x0, y0, x1, y1 = s["rect"]
            self.rect.set_bounds(x0, y0, x1 - x0, y1 - y0)
            self.rect.set_visible(True)
        self.title.set_text(s["title"])


class LinkedExplorers(Explorer):
    """A parallel-coordinates explorer and a scatterplot matrix side by side, sharing one
    :class:`Selection`: a brush in either highlights the same records in both.

    Parameters
    ----------
    pc : ParallelCoordinatesExplorer, optional
        A new one if not given.
    splom : ScatterplotMatrixExplorer, optional
        A new one sharing `pc`'s selection if not given; a given one must share it.

    Examples
    --------
    >>> both = link()
    >>> both.splom.selection is both.pc.selection
    True
    >>> both.png()[:4]
    b'\\x89PNG'
    """

    summary = ("Linked brushing (interactive): parallel coordinates and a scatterplot matrix "
               "of the same records; a brush in either (a range on an axis, a rectangle in a "
               "panel) highlights the same records in both.")

    def __init__(self, pc=None, splom=None):
        import ipywidgets as w

        pc = pc or ParallelCoordinatesExplorer()
        if splom is None:
            splom = ScatterplotMatrixExplorer(pc.selection)
        elif splom.selection is not pc.selection:
            raise ValueError("splom must share pc's selection: build it as "
                             "ScatterplotMatrixExplorer(pc.selection), or leave it out")
        self.pc, self.splom = pc, splom
        self.fig = splom.fig                  # the last canvas: where the gestures happen
        self.blitter = None
        canvases = w.HBox([pc.fig.canvas, splom.fig.canvas],
                          layout=w.Layout(flex_flow="row wrap", align_items="center",
                                          grid_gap="0 12px"))
        for canvas in (pc.fig.canvas, splom.fig.canvas):
            canvas.layout.flex = "0 0 auto"
        self.widget = w.VBox([canvases, w.HBox([pc.controls, splom.controls],
                                               layout=w.Layout(flex_flow="row wrap",
                                                               grid_gap="0 24px")),
                              pc.info])

    def update(self):
        """Redraw both."""
        self.pc.update()
        self.splom.update()

    def mouse_gestures(self):
        """The scatterplot matrix's rectangle drag (its canvas is the view's last).

        Examples
        --------
        >>> [g["what"] for g in link().mouse_gestures()]
        ['a rectangle in the bottom-left panel']
        """
        return self.splom.mouse_gestures()

    def png(self, dpi=72):
        """Both figures side by side as one PNG."""
        import io

        from PIL import Image

        images = [Image.open(io.BytesIO(e.png(dpi))).convert("RGB") for e in (self.pc, self.splom)]
        out = Image.new("RGB", (sum(i.width for i in images) + 12,
                                max(i.height for i in images)), "white")
        out.paste(images[0], (0, 0))
        out.paste(images[1], (images[0].width + 12, 0))
        buffer = io.BytesIO()
        out.save(buffer, format="png")
        return buffer.getvalue()


def link(pc=None, splom=None):
    """Link a parallel-coordinates explorer and a scatterplot matrix through one selection
    (the scatterplot matrix takes the other's) and show them side by side.

    Examples
    --------
    >>> both = link()
    >>> both.pc.brush_drag(2, 0.0, 0.3, final=True)
    >>> int(both.splom.current["mask"].sum()) == int(both.pc.current["mask"].sum())
    True
    """
    return LinkedExplorers(pc, splom)
