"""Z-buffer trace: a few triangles drawn into a small depth buffer, one triangle per step.

The left grid shows which triangle each pixel holds (its id buffer), the right one the depth
buffer. At each step the pixels the current triangle covers are outlined, and those where it is
nearer than what the buffer held (and therefore overwrites) are marked. A menu changes the
drawing order: the final buffers never change, the number of overwrites does.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, visibility
from . import _style
from ._base import Explorer, bind, labelled, panel, slider
from ._drag import pseudocode_html

__all__ = ["ORDERS", "PSEUDOCODE", "State", "TRIANGLES", "ZBufferExplorer", "scene"]

WIDTH, HEIGHT = 12, 9
TRIANGLES = np.array([
    [[0.5, 0.5, 0.7], [9.5, 1.0, 0.7], [2.0, 8.5, 0.7]],      # 0: far, flat
    [[3.0, 2.0, 0.2], [11.5, 3.5, 0.6], [6.0, 8.8, 0.6]],     # 1: tilted: near at its left corner
    [[5.0, 0.2, 0.4], [11.8, 0.5, 0.4], [11.0, 6.0, 0.4]],    # 2: in the middle
    [[0.2, 4.0, 0.9], [7.0, 5.5, 0.1], [1.0, 8.8, 0.9]],      # 3: a steep one
])
"""Four screen triangles: pixel x, pixel y (row 0 at the bottom), depth in [0, 1]."""
ORDERS = {"as listed (0, 1, 2, 3)": [0, 1, 2, 3], "reversed (3, 2, 1, 0)": [3, 2, 1, 0],
          "front to back (by nearest vertex)": None}
COLORS = np.array([[0.55, 0.7, 0.95], [0.95, 0.6, 0.25], [0.45, 0.8, 0.45], [0.85, 0.45, 0.75]])
PSEUDOCODE = [
    "for every pixel: depth = ∞, id = background",
    "for each triangle T (in the chosen order):",
    "    for each pixel whose centre lies inside T:",
    "        z = T's depth at the centre (interpolated)",
    "        if z < depth[pixel]:",
    "            depth[pixel] = z;  id[pixel] = T",
]


@dataclass
class State:
    """The drawing order and the number of triangles drawn so far (the explorer opens half
    way, after two triangles, so both buffers show something and the order matters).

    Examples
    --------
    >>> State().step
    2
    """

    order: str = "as listed (0, 1, 2, 3)"
    step: int = 2


def _order(name):
    if ORDERS[name] is not None:
        return list(ORDERS[name])
    return [int(k) for k in np.argsort(TRIANGLES[:, :, 2].min(axis=1), kind="stable")]


def scene(state):
    """Pure part: the buffers after `step` triangles, and the explanation.

    Returns
    -------
    dict
        ``order`` (triangle indices in drawing order), ``step``, ``ids`` and ``depth`` (after
        the step; ``inf`` / -1 on background), ``colors`` (an RGB image of the id buffer),
        ``covered`` and ``written`` (boolean masks of the current triangle, or None at step 0),
        ``current`` (its index or None), ``writes`` (overwrites so far, per triangle),
        ``text``.

    Examples
    --------
    >>> s = scene(State(step=4))
    >>> s["ids"].shape, sorted(set(s["ids"].ravel().tolist()))
    ((9, 12), [-1, 0, 1, 2, 3])
    """
    order = _order(state.order)
    k = min(max(int(state.step), 0), len(order))
    ids = np.full((HEIGHT, WIDTH), -1)
    depth = np.full((HEIGHT, WIDTH), np.inf)
    covered = written = None
    writes = []
    if k:
        steps = list(visibility.zbuffer_steps(TRIANGLES[order[:k]], WIDTH, HEIGHT))
        last = steps[-1]
        depth = last.depth
        ids = np.where(last.ids >= 0, np.array(order)[np.maximum(last.ids, 0)], -1)
        covered, written = last.covered, last.written
        writes = [int(s.written.sum()) for s in steps]
    colors = np.ones((HEIGHT, WIDTH, 3))
    colors[ids >= 0] = COLORS[ids[ids >= 0]]
    if k == 0:
        line = 0
        note = ("<b>Start.</b> Every pixel's depth is ∞ (nothing drawn yet), its id the "
                "background.")
    else:
        current = order[k - 1]
        n_cov, n_wr = int(covered.sum()), int(written.sum())
        line = 5 if n_wr else 4
        note = (f"<b>Step {k}: triangle {current}.</b> Its interior covers {n_cov} pixel "
                f"centres; it is nearer than the buffer at {n_wr} of them and writes there, and "
                f"loses at the other {n_cov - n_wr}. Writes so far: {sum(writes)}.")
        if k == len(order):
            visible = int((ids >= 0).sum())
            note += (f" All triangles drawn. At least {visible} writes are needed, one per "
                     f"pixel that shows a triangle; the other {sum(writes) - visible} wrote "
                     "pixels that a nearer triangle took later (wasted work). Change the order: "
                     "the final buffers stay the same, the waste does not.")
    return {"order": order, "step": k, "ids": ids, "depth": depth, "colors": colors,
            "covered": covered, "written": written,
            "current": order[k - 1] if k else None, "writes": writes,
            "text": pseudocode_html(PSEUDOCODE, line, note)}


class ZBufferExplorer(Explorer):
    """Step through the z-buffer algorithm on four triangles; change the drawing order.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ZBufferExplorer()``.

    Examples
    --------
    >>> explorer = ZBufferExplorer()
    >>> explorer.step.value = 3
    >>> "triangle 2" in explorer.info.value
    True
    """

    summary = ("Z-buffer trace (interactive): four triangles drawn one at a time into a "
               "12 x 9 depth buffer; the covered and overwritten pixels of each step.")

    def __init__(self, state=None):
        import ipywidgets as w
        import matplotlib
        from matplotlib.collections import LineCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(8.4, 3.5))
        grid = self.fig.add_gridspec(1, 2, left=0.05, right=0.92, bottom=0.12, top=0.9,
                                     wspace=0.15)
        extent = (0, WIDTH, 0, HEIGHT)
        ids_ax = self.fig.add_subplot(grid[0])
        self.ids_image = ids_ax.imshow(s["colors"], origin="lower", extent=extent,
                                       interpolation="nearest")
        depth_ax = self.fig.add_subplot(grid[1])
        cmap = matplotlib.colormaps["viridis"].with_extremes(bad="white")
        self.depth_image = depth_ax.imshow(np.ma.masked_invalid(s["depth"]), origin="lower",
                                           extent=extent, cmap=cmap, vmin=0, vmax=1,
                                           interpolation="nearest")
        self.fig.colorbar(self.depth_image, ax=depth_ax, fraction=0.04, pad=0.02,
                          label="depth (0 near, 1 far)")
        self.marks = []
        for ax, title in ((ids_ax, "id buffer: which triangle each pixel shows"),
                          (depth_ax, "depth buffer")):
            # the pixel grid, over the buffers (an axis grid would lie under the images)
            edges = [[(x, 0), (x, HEIGHT)] for x in range(WIDTH + 1)] + \
                    [[(0, y), (WIDTH, y)] for y in range(HEIGHT + 1)]
            ax.add_collection(LineCollection(edges, colors="0.8", linewidths=0.5, zorder=1.5))
            ax.set_title(title)
            for k, tri in enumerate(TRIANGLES):
                closed = np.vstack([tri[:, :2], tri[:1, :2]])
                ax.plot(*closed.T, color=COLORS[k] * 0.7, lw=1.2)
                ax.text(*tri[:, :2].mean(axis=0), str(k), color=COLORS[k] * 0.5,
                        fontsize=_style.LABEL,
                        ha="center", va="center", weight="bold")
            (covered,) = ax.plot([], [], "s", mfc="none", mec="0.15", ms=9, mew=1.2)
            (written,) = ax.plot([], [], "x", color="0.1", ms=5)
            self.marks.append((covered, written))
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.ids_image, self.depth_image,
                                               *[m for pair in self.marks for m in pair]])
        self.order = labelled(w.Dropdown, "order", options=list(ORDERS), value=self.state.order)
        self.step = slider("triangles", self.state.step, 0, len(TRIANGLES), 1, kind=w.IntSlider)
        bind(self.state, {"order": self.order, "step": self.step}, self.update)
        self.info = panel(width="800px")
        legend = panel("□ pixels the current triangle covers &nbsp; × pixels it overwrites")
        self.widget = w.VBox([w.HBox([self.order, self.step],
                                     layout=w.Layout(flex_flow="row wrap", grid_gap="0 12px")),
                              self.fig.canvas, legend,
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.ids_image.set_data(s["colors"])
        self.depth_image.set_data(np.ma.masked_invalid(s["depth"]))
        for covered, written in self.marks:
            for line, mask in ((covered, s["covered"]), (written, s["written"])):
                if mask is None:
                    line.set_data([], [])
                else:
                    rows, cols = np.nonzero(mask)
                    line.set_data(cols + 0.5, rows + 0.5)
        self.info.value = s["text"]
