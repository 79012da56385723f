r"""BSP explorer: a plan of segments, its BSP tree, and the painter's order from an eye.

Left, the plan seen from above: each segment with its label and a tick on its front (left)
side, the eye, and the fragments painted so far numbered in drawing order. Right, the tree
(:func:`course_lib.visibility.build_bsp_2d`): nodes as labelled boxes, the front child drawn to
the left of the back child, the node being painted highlighted. Move the eye and the order
(:func:`course_lib.visibility.bsp2d_back_to_front`) changes; change the build order and the tree
and its cuts change; step through the painting one fragment at a time.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw
from ..visibility import bsp2d_back_to_front, build_bsp_2d
from . import _style
from ._base import Explorer, bind, labelled, panel, slider

__all__ = ["BSPExplorer", "ORDERS", "PRESETS", "PSEUDOCODE", "State", "scene"]

#: The plans (segments a -> b; the front is on the left).
PRESETS = {
    "lesson": [[[0, 2], [6, 2]], [[2, 0], [2, 4]], [[4, 3], [5, 5]], [[5, 0], [3, 1]]],
    "room": [[[1, 1], [7, 1]], [[7, 6], [1, 6]], [[5.5, 0], [5.5, 3]], [[2, 4], [6, 3]],
             [[6, 5], [5, 8]], [[0, 7], [3, 4]]],
    "pinwheel": [[[1, 3], [6, 3]], [[5, 1], [5, 7]], [[7, 5], [2, 5]], [[3, 7], [3, 1]],
                 [[3.5, 4.5], [4.5, 3.5]]],
}
#: The build orders offered: how the partitions are taken.
ORDERS = ("given order", "reversed order", "rotated by one", "fewest splits")
_MAX = 16                  # artists pooled for nodes and fragments
#: The traversal, as the explorer's panel shows it (the branch taken at the node being painted
#: is highlighted).
PSEUDOCODE = ("paint(node):",
              "  if node is empty: return",
              "  if s(eye) >= 0 (eye in front of node's line):",
              "    paint(node.back); draw node; paint(node.front)",
              "  else (eye behind):",
              "    paint(node.front); draw node; paint(node.back)")
_EDGE = "#555555"


@dataclass
class State:
    """The plan, the build order, the eye and how many fragments are painted.

    Examples
    --------
    >>> State().preset, State().order, State().step
    ('room', 'given order', 4)
    """

    preset: str = "room"
    order: str = "given order"
    eye_x: float = 0.5
    eye_y: float = 3.0
    step: int = 4


def _tree_for(preset, order):
    segs = np.asarray(PRESETS[preset], dtype=float)
    n = len(segs)
    if order == "fewest splits":
        return build_bsp_2d(segs, choose="fewest_splits")
    perm = {"given order": list(range(n)), "reversed order": list(range(n))[::-1],
            "rotated by one": list(range(1, n)) + [0]}[order]
    return build_bsp_2d(segs, order=perm)


def _layout(tree):
    """Node positions: x by in-order rank (front child on the left), y by depth."""
    pos, edges, rank = {}, [], [0]

    def visit(node, depth):
        if node is None:
            return
        visit(node.front, depth + 1)
        pos[node.label] = (rank[0], -depth)
        rank[0] += 1
        visit(node.back, depth + 1)
        for kind, child in (("f", node.front), ("b", node.back)):
            if child is not None:
                edges.append((node.label, child.label, kind))

    visit(tree.root, 0)
    return pos, edges


def scene(state):
    """Pure part: the tree, the order from the eye and what the step shows.

    Returns
    -------
    dict
        ``tree`` (BSPTree2D), ``order`` (fragment labels back to front), ``steps`` (the node
        decisions), ``fragments`` (k, 2, 2) in drawing order, ``painted`` (how many are
        painted), ``current`` (the node label being painted, or None), ``positions`` (node ->
        (x, y) in the tree panel), ``edges`` ((parent, child, "f"/"b")), ``line`` (the line of
        :data:`PSEUDOCODE` taken at the current node, or None), ``text``.

    Examples
    --------
    >>> s = scene(State(preset="lesson", eye_x=1, eye_y=4, step=2))
    >>> s["order"], s["current"]
    (['d', 'b1', 'a', 'c', 'b2'], 'b1')
    """
    if state.preset not in PRESETS:
        raise ValueError(f"preset must be one of {', '.join(PRESETS)}, got {state.preset!r}")
    if state.order not in ORDERS:
        raise ValueError(f"order must be one of {', '.join(ORDERS)}, got {state.order!r}")
    tree = _tree_for(state.preset, state.order)
    out = bsp2d_back_to_front(tree, [state.eye_x, state.eye_y])
    k = int(np.clip(state.step, 0, len(out.labels)))
    frags = np.array([[f.start, f.end] for f in out.fragments])
    node_of = {}
    for st in out.steps:
        for lab in st.node.split("+"):
            node_of[lab] = st.node
    current = node_of[out.labels[k - 1]] if k else None
    pos, edges = _layout(tree)
    step = next((st for st in out.steps if st.node == current), None)
    decision = step.text if step else ""
    line = None if step is None else (3 if step.side >= 0 else 5)
    text = (f"Tree: {tree.n_nodes} nodes, {len(tree.fragments)} fragments from "
            f"{len(tree.labels)} segments ({tree.n_splits} cut), depth {tree.depth}. "
            f"Back to front from the eye ({state.eye_x:g}, {state.eye_y:g}): "
            + " → ".join(f"<b>{lab}</b>" if i < k else lab for i, lab in enumerate(out.labels))
            + (f". Step {k}: painting {out.labels[k - 1]}; at node {current}: {decision}."
               if k else ". Step 0: nothing painted yet."))
    return {"tree": tree, "order": out.labels, "steps": out.steps, "fragments": frags,
            "painted": k, "current": current, "positions": pos, "edges": edges, "line": line,
            "text": text}


def _front_ticks(frags):
    """A short tick at the middle of each fragment, on its front (left) side."""
    mid = frags.mean(axis=1)
    d = frags[:, 1] - frags[:, 0]
    n = np.c_[-d[:, 1], d[:, 0]] / np.hypot(d[:, 0], d[:, 1])[:, None]
    return np.stack([mid, mid + 0.35 * n], axis=1)


class BSPExplorer(Explorer):
    """Build a BSP tree of a plan and paint it back to front from an eye you move.

    In a notebook, after ``%matplotlib widget``, end a cell with ``BSPExplorer()``.

    Examples
    --------
    >>> ex = BSPExplorer()
    >>> ex.preset.value = "lesson"
    >>> ex.eye_x.value = 4.0
    >>> ex.eye_y.value = 1.0
    >>> scene(ex.state)["order"]
    ['b2', 'c', 'a', 'b1', 'd']
    """

    summary = ("BSP explorer (interactive): a plan of segments with their front sides, the BSP "
               "tree built in a chosen order, and the painter's back-to-front order from a "
               "movable eye, stepped one fragment at a time.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection

        self.state = state or State()
        self.fig = draw.figure(figsize=(7.0, 3.4))
        plan = self.fig.add_axes((0.07, 0.13, 0.42, 0.78))
        plan.set(xlim=(-1, 9), ylim=(-1, 9), aspect="equal", xlabel="x", ylabel="y")
        plan.set_title("plan (ticks: front side)", fontsize=_style.TITLE)
        plan.grid(True, color="#e8e8e8", lw=0.5)
        tree_ax = self.fig.add_axes((0.53, 0.02, 0.46, 0.9))
        tree_ax.axis("off")
        tree_ax.set_title("BSP tree (f = front, b = back)", fontsize=_style.TITLE)
        self.tree_ax = tree_ax
        self.segments = LineCollection([], linewidths=2.5)
        self.ticks = LineCollection([], colors="#777777", linewidths=1.0)
        plan.add_collection(self.segments)
        plan.add_collection(self.ticks)
        (self.eye,) = plan.plot([], [], "o", color="#c62828", ms=8, zorder=5)
        self.names = [plan.text(0, 0, "", fontsize=_style.ANNOTATION, ha="center",
                                va="center", color="#222222") for _ in range(_MAX)]
        self.edges = LineCollection([], colors=_EDGE, linewidths=1.0)
        tree_ax.add_collection(self.edges)
        self.edge_names = [tree_ax.text(0, 0, "", fontsize=_style.ANNOTATION - 1,
                                        color=_EDGE, ha="center", va="center")
                           for _ in range(_MAX)]
        self.nodes = [tree_ax.text(0, 0, "", fontsize=_style.ANNOTATION, ha="center",
                                   va="center", bbox=dict(boxstyle="round,pad=0.3", fc="white",
                                                          ec="#333333"))
                      for _ in range(_MAX)]
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.segments, self.ticks, self.eye, self.edges,
                                               *self.names, *self.edge_names, *self.nodes])
        self.preset = labelled(w.Dropdown, "plan", options=list(PRESETS), value=self.state.preset)
        self.order = labelled(w.Dropdown, "build order", options=list(ORDERS),
                              value=self.state.order)
        self.eye_x = slider("eye x", self.state.eye_x, -1, 9, 0.25)
        self.eye_y = slider("eye y", self.state.eye_y, -1, 9, 0.25)
        first = scene(self.state)
        self.step = slider("painted", self.state.step, 0, len(first["order"]), 1,
                           kind=w.IntSlider)
        bind(self.state, {"preset": self.preset, "order": self.order, "eye_x": self.eye_x,
                          "eye_y": self.eye_y, "step": self.step}, self.update)
        self.info = panel(width="660px")
        self.code = panel(width="370px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([w.VBox([self.preset, self.order, self.code]),
                                      w.VBox([self.eye_x, self.eye_y, self.step])]),
                              self.info])
        self._last = None
        self._draw(scene(self.state))

    def update(self):
        """Rebuild the tree if the plan or order changed, repaint the plan and the tree."""
        s = scene(self.state)
        n = len(s["order"])
        if self.step.max != n:
            with self.step.hold_sync():
                self.step.max = n
                self.step.value = min(self.step.value, n)
            self.state.step = self.step.value
            s = scene(self.state)
        self._draw(s)
        self.blitter.update()

    def _draw(self, s):
        frags, k, order = s["fragments"], s["painted"], s["order"]
        colours = [(*draw_colour(i), 1.0) if i < k else (0.72, 0.72, 0.72, 1.0)
                   for i in range(len(frags))]
        self.segments.set_segments(list(frags))
        self.segments.set_colors(colours)
        self.segments.set_linewidths([3.0 if i < k else 1.8 for i in range(len(frags))])
        self.ticks.set_segments(list(_front_ticks(frags)))
        self.eye.set_data([self.state.eye_x], [self.state.eye_y])
        mid = frags.mean(axis=1)
        d = frags[:, 1] - frags[:, 0]
        right = np.c_[d[:, 1], -d[:, 0]] / np.hypot(d[:, 0], d[:, 1])[:, None]
        for i, t in enumerate(self.names):
            if i < len(order):
                t.set_position(mid[i] + 0.45 * right[i])
                t.set_text(f"{order[i]} ({i + 1})" if i < k else order[i])
                t.set_visible(True)
            else:
                t.set_visible(False)
        pos, edges = s["positions"], s["edges"]
        xs = [p[0] for p in pos.values()]
        ys = [p[1] for p in pos.values()]
        span_x, span_y = max(max(xs), 1), max(-min(ys), 1)
        to_ax = {lab: (0.06 + 0.88 * x / span_x, 0.9 - 0.8 * (-y) / span_y)
                 for lab, (x, y) in pos.items()}
        self.tree_ax.set(xlim=(0, 1), ylim=(0, 1))
        self.edges.set_segments([[to_ax[a], to_ax[b]] for a, b, _ in edges])
        for i, t in enumerate(self.edge_names):
            if i < len(edges):
                a, b, kind = edges[i]
                t.set_position(0.5 * (np.array(to_ax[a]) + np.array(to_ax[b])) + [0.0, 0.02])
                t.set_text(kind)
                t.set_visible(True)
            else:
                t.set_visible(False)
        labels = list(pos)
        for i, t in enumerate(self.nodes):
            if i < len(labels):
                lab = labels[i]
                t.set_position(to_ax[lab])
                t.set_text(lab)
                t.get_bbox_patch().set_facecolor("#ffd54f" if lab == s["current"] else "white")
                t.set_visible(True)
            else:
                t.set_visible(False)
        self.info.value = s["text"]
        self.code.value = "<pre style='margin: 0; font-size: 11px'>" + "\n".join(
            f"<span style='background: #ffd54f'>{text}</span>" if i == s["line"] else text
            for i, text in enumerate(PSEUDOCODE)) + "</pre>"


def draw_colour(i):
    """The colour of the i-th painted fragment (a perceptually ordered ramp, early = dark).

    Examples
    --------
    >>> len(draw_colour(0))
    3
    """
    import matplotlib

    return matplotlib.colormaps["viridis"](0.15 + 0.7 * (i % 8) / 7)[:3]
