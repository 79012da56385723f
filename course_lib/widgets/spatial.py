r"""Spatial subdivision explorer: one ray through a uniform grid, a quadtree (octree), a kd-tree
or a BVH, seen from above.

The scene is 24 segments in the square :math:`[0, 10]^2`; each is a thin vertical wall (two
triangles from :math:`z = -0.05` to :math:`0.05`) and the ray runs in the plane
:math:`z = -0.025`. The structures are the 3D ones of :mod:`course_lib.raytracing.spatial` (and
the :class:`~course_lib.raytracing.BVH`) built over those walls, drawn from above: the grid has
one layer of cells in z, so it is a 2D grid; the octree halves x and y only (``axes=(0, 1)``),
a quadtree; the kd-tree's planes are all vertical. The walk is the library's own
(:meth:`~course_lib.raytracing.UniformGrid.walk`); only the BVH's is written out here (front to
back, boxes beyond the nearest hit skipped), since the BVH's traversal is vectorized.

The picture: the cells (or boxes) the ray looks into, filled and numbered in order (yellow to
blue); the structure's other cells outlined in grey; the segments tested in orange (the others
dark grey); the hit as a red dot. The text gives the counts.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from .._raycore import BVH, moller_trumbore, slab, triangle_soa
from .._validate import as_choice
from ..raytracing.spatial import KDTree, Octree, UniformGrid
from . import _style
from ._base import Explorer, bind, labelled, panel, slider

__all__ = ["STRUCTURES", "SpatialExplorer", "State", "scene", "segments"]

STRUCTURES = ("grid", "quadtree", "kd-tree", "BVH")
SIZE = 160                     # pixels of the picture
VIEW = 10.0                    # the picture covers [0, VIEW]^2
Z_RAY = -0.025
MAX_NUMBERS = 16


@dataclass
class State:
    """The structure, the ray (origin, angle) and the structure's size parameter.

    Examples
    --------
    >>> State().structure, State().resolution
    ('grid', 8)
    """

    structure: str = "grid"
    ox: float = 0.5
    oy: float = 2.0
    angle_deg: float = 20.0
    resolution: int = 8
    leaf_size: int = 2


@lru_cache(maxsize=1)
def _segments():
    rng = np.random.default_rng(15)
    centre = rng.uniform(1.0, 9.0, (24, 2))
    angle = rng.uniform(0, np.pi, 24)
    half = rng.uniform(0.3, 1.0, 24)[:, None]
    u = np.column_stack([np.cos(angle), np.sin(angle)])
    return np.stack([centre - half * u, centre + half * u], axis=1)


def segments():
    """The explorer's scene: 24 segments (24, 2, 2) in the square [0, 10]^2.

    Examples
    --------
    >>> s = segments()
    >>> s.shape, bool(s.min() > 0 and s.max() < 10)
    ((24, 2, 2), True)
    """
    return _segments().copy()


@lru_cache(maxsize=1)
def _walls():
    """Each segment as a vertical wall of two triangles: vertices (96, 3), faces (48, 3)."""
    seg = _segments()
    a, b = seg[:, 0], seg[:, 1]
    lo, hi = -0.05, 0.05
    verts = np.concatenate([np.column_stack([a, np.full(24, lo)]),
                            np.column_stack([b, np.full(24, lo)]),
                            np.column_stack([b, np.full(24, hi)]),
                            np.column_stack([a, np.full(24, hi)])])
    s = np.arange(24)
    faces = np.empty((48, 3), dtype=np.intp)
    faces[0::2] = np.column_stack([s, s + 24, s + 48])
    faces[1::2] = np.column_stack([s, s + 48, s + 72])
    return verts, faces


@lru_cache(maxsize=64)
def _structure(name, resolution, leaf_size):
    v, f = _walls()
    if name == "grid":
        return UniformGrid(v, f, resolution=[resolution, resolution, 1])
    if name == "quadtree":
        return Octree(v, f, max_depth=8, leaf_size=leaf_size, axes=(0, 1))
    if name == "kd-tree":
        return KDTree(v, f, max_depth=16, leaf_size=leaf_size)
    return BVH(v[f], leaf_size=leaf_size)


@lru_cache(maxsize=64)
def _bvh_parts(resolution, leaf_size):
    bvh = _structure("BVH", resolution, leaf_size)
    return triangle_soa(bvh.triangles), bvh.leaves


@lru_cache(maxsize=64)
def _static(name, resolution, leaf_size):
    """The picture's static layer: the structure's cells outlined in grey (read-only)."""
    s = _structure(name, resolution, leaf_size)
    img = np.ones((SIZE, SIZE, 3))
    grey = np.array([0.8, 0.8, 0.8])
    if name == "BVH":
        for n in np.nonzero(s.children[:, 0] < 0)[0]:
            _outline(img, s.lo[n], s.hi[n], grey)
    elif name == "grid":
        size = (s.hi - s.lo) / s.resolution
        for i in range(resolution + 1):
            x = s.lo + i * size
            _outline(img, np.array([x[0], s.lo[1]]), np.array([x[0], s.hi[1]]), grey)
            _outline(img, np.array([s.lo[0], x[1]]), np.array([s.hi[0], x[1]]), grey)
    else:
        leaves = np.nonzero(s.children[:, 0] < 0)[0]
        for n in leaves:
            _outline(img, s.node_lo[n], s.node_hi[n], grey)
    img.setflags(write=False)
    return img


def _bvh_walk(bvh, o, d, soa, leaves):
    """Front-to-back walk of the BVH for one ray: visited nodes (node, t_in), the triangles
    tested, the nearest hit (t, triangle)."""
    best_t, best_id = np.inf, -1
    visited, tested = [], []
    near, far = slab(bvh.lo, bvh.hi, o, d)
    t_in = np.maximum(near.max(axis=1), 0.0)
    t_out = far.min(axis=1)
    stack = [0] if t_in[0] <= t_out[0] else []
    while stack:
        n = stack.pop()
        if t_in[n] > best_t:                          # beyond the nearest hit: skipped
            continue
        visited.append(n)
        left, right = bvh.children[n]
        if left < 0:
            ids = leaves[n]
            tested.append(ids)
            t, _, _ = moller_trumbore(o, d, soa[:, ids])
            t = np.where(t >= 0, t, np.inf)
            k = int(np.argmin(t))
            if t[k] < best_t:
                best_t, best_id = float(t[k]), int(ids[k])
            continue
        kids = [c for c in (left, right) if t_in[c] <= t_out[c]]
        kids.sort(key=lambda c: -t_in[c])             # the nearer child popped first
        stack.extend(kids)
    return visited, tested, best_t, best_id


def _to_px(x):
    return np.clip((np.asarray(x) / VIEW * SIZE).astype(int), 0, SIZE - 1)


def _outline(img, lo, hi, colour):
    x0, y0 = _to_px(lo[:2])
    x1, y1 = _to_px(hi[:2])
    img[y0:y1 + 1, x0] = colour
    img[y0:y1 + 1, x1] = colour
    img[y0, x0:x1 + 1] = colour
    img[y1, x0:x1 + 1] = colour


def _fill(img, lo, hi, colour):
    x0, y0 = _to_px(lo[:2])
    x1, y1 = _to_px(hi[:2])
    img[y0:y1 + 1, x0:x1 + 1] = colour


def _ramp(k, n):
    a = k / max(n - 1, 1)
    return (1 - a) * np.array([1.0, 0.93, 0.6]) + a * np.array([0.62, 0.78, 0.98])


def scene(state):
    """Pure part: the picture, the cells visited in order, the segments tested, the hit, text.

    Returns
    -------
    dict
        ``image`` (SIZE, SIZE, 3) opaque RGB (row 0 at the bottom); ``boxes`` the (lo, hi) xy
        boxes of the cells/nodes visited, in order; ``entry`` their entry parameters (the grid
        and the trees); ``tested`` the segments tested (sorted); ``hit`` the segment hit (-1)
        and ``t``; ``origin``, ``direction`` (2D); ``end`` the ray's drawn end; ``text``.

    Examples
    --------
    >>> s = scene(State(structure="grid", ox=0.5, oy=5.0, angle_deg=0.0))
    >>> s["image"].shape, len(s["boxes"]) >= 1
    ((160, 160, 3), True)
    """
    name = as_choice(state.structure, "structure", STRUCTURES)
    res, leaf = int(state.resolution), int(state.leaf_size)
    if not 1 <= res <= 64 or not 1 <= leaf <= 64:
        raise ValueError(f"resolution and leaf_size must be in 1..64, got {res}, {leaf}")
    a = np.radians(float(state.angle_deg))
    o2 = np.array([float(state.ox), float(state.oy)])
    d2 = np.array([np.cos(a), np.sin(a)])
    o = np.array([o2[0], o2[1], Z_RAY])
    d = np.array([d2[0], d2[1], 0.0])
    s = _structure(name, res, leaf)
    img = _static(name, res, leaf).copy()
    if name == "BVH":
        visited, tested, t, hit = _bvh_walk(s, o, d, *_bvh_parts(res, leaf))
        boxes = [(s.lo[n][:2], s.hi[n][:2]) for n in visited]
        entry = np.zeros(0)
        for k, n in enumerate(visited):
            if s.children[n, 0] < 0:
                _fill(img, s.lo[n], s.hi[n], _ramp(k, len(visited)))
        for k, n in enumerate(visited):
            _outline(img, s.lo[n], s.hi[n], np.array([0.25, 0.35, 0.6]))
        cells_word, n_nodes = "boxes", len(visited)
    else:
        w = s.walk(o, d)
        tested, t, hit = w.tested, w.t, w.id
        entry = w.t_enter
        if name == "grid":
            size = (s.hi - s.lo) / s.resolution
            ij = np.array(w.cells, dtype=float).reshape(-1, 3)
            boxes = [(s.lo[:2] + c[:2] * size[:2], s.lo[:2] + (c[:2] + 1) * size[:2])
                     for c in ij]
        else:
            boxes = [(s.node_lo[n][:2], s.node_hi[n][:2]) for n in w.cells]
        for k, (lo, hi) in enumerate(boxes):
            _fill(img, lo, hi, _ramp(k, len(boxes)))
        for lo, hi in boxes:
            _outline(img, lo, hi, np.array([0.25, 0.35, 0.6]))
        cells_word = "cells" if name == "grid" else "leaves"
        n_nodes = w.nodes_visited
    tested_tris = np.concatenate(tested) if tested else np.zeros(0, dtype=np.intp)
    tested_segs = np.unique(tested_tris // 2)
    hit_seg = hit // 2 if hit >= 0 else -1
    # where the ray ends in the picture: at the hit, or at the view's border
    with np.errstate(divide="ignore"):
        span = [((VIEW if c > 0 else 0.0) - p) / c for p, c in zip(o2, d2) if c != 0]
    t_view = max(min(span), 0.0)
    t_end = t if np.isfinite(t) else t_view
    text = (f"<b>{name}</b>: the ray looked into <b>{len(boxes)}</b> {cells_word}"
            + (f" ({n_nodes} tree nodes visited)" if name in ("quadtree", "kd-tree") else "")
            + f" and made <b>{len(tested_tris)}</b> triangle tests (brute force: 48); "
            f"segments tested: {', '.join(map(str, tested_segs)) or 'none'}. "
            + (f"Hit: segment {hit_seg} at t = {t:.3f}." if hit >= 0 else "No hit."))
    return {"image": img, "boxes": boxes, "entry": entry, "tested": tested_segs,
            "tested_triangles": int(len(tested_tris)), "hit": int(hit_seg), "t": float(t),
            "origin": o2, "direction": d2, "end": o2 + t_end * d2, "text": text}


class SpatialExplorer(Explorer):
    """Structure menu, ray origin and angle, grid resolution and leaf size: the cells one ray
    visits, in order, the segments it tests and its hit.

    In a notebook, after ``%matplotlib widget``, end a cell with ``SpatialExplorer()``.

    Examples
    --------
    >>> explorer = SpatialExplorer()
    >>> explorer.structure.value = "kd-tree"
    >>> "kd-tree" in explorer.info.value
    True
    """

    summary = ("Spatial subdivision explorer (interactive): one ray through a uniform grid, a "
               "quadtree, a kd-tree or a BVH over 24 segments, seen from above: the cells "
               "visited in order, the segments tested and the hit.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(4.0, 4.0))
        ax = self.fig.add_axes([0.06, 0.06, 0.9, 0.88])
        self.image = ax.imshow(s["image"], origin="lower", extent=(0, VIEW, 0, VIEW),
                               interpolation="nearest")
        ax.set(xlim=(0, VIEW), ylim=(0, VIEW))
        ax.set_xticks([])
        ax.set_yticks([])
        self.segments = LineCollection(_segments(), linewidths=2.0, colors="0.25")
        ax.add_collection(self.segments)
        (self.ray,) = ax.plot([], [], color="#c62828", lw=1.3)
        (self.origin,) = ax.plot([], [], "o", color="#c62828", ms=4)
        (self.hit,) = ax.plot([], [], "o", color="#c62828", ms=7, mec="k")
        self.numbers = [ax.text(0, 0, "", fontsize=7, ha="center", va="center", color="0.1")
                        for _ in range(MAX_NUMBERS)]
        self.title = ax.set_title("", fontsize=_style.LABEL)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image, self.segments, self.ray,
                                               self.origin, self.hit, self.title]
                                    + self.numbers)
        self.structure = labelled(w.Dropdown, "structure", options=list(STRUCTURES),
                                  value=self.state.structure)
        self.ox = slider("origin x", self.state.ox, 0.0, 10.0, 0.1)
        self.oy = slider("origin y", self.state.oy, 0.0, 10.0, 0.1)
        self.angle = slider("angle °", self.state.angle_deg, -180.0, 180.0, 1.0)
        self.resolution = slider("grid cells", self.state.resolution, 1, 32, 1,
                                 kind=w.IntSlider)
        self.leaf_size = slider("leaf size", self.state.leaf_size, 1, 8, 1, kind=w.IntSlider)
        bind(self.state, {"structure": self.structure, "ox": self.ox, "oy": self.oy,
                          "angle_deg": self.angle, "resolution": self.resolution,
                          "leaf_size": self.leaf_size}, self.update)
        self.info = panel(width="420px")
        controls = w.VBox([self.structure, self.ox, self.oy, self.angle, self.resolution,
                           self.leaf_size])
        self._enable()
        self.widget = w.VBox([w.HBox([self.fig.canvas, controls]), self.info])
        self._draw(s)

    def update(self):
        """Recompute the walk (the structures are cached) and redraw."""
        self._enable()
        self._draw(scene(self.state))
        self.blitter.update()

    def _enable(self):
        # the grid has cells and no leaves; the trees have leaves and no grid cells
        self.resolution.disabled = self.state.structure != "grid"
        self.leaf_size.disabled = self.state.structure == "grid"

    def _draw(self, s):
        self.image.set_data(s["image"])
        colours = np.tile([0.25, 0.25, 0.25, 1.0], (24, 1))
        colours[s["tested"]] = [0.95, 0.55, 0.1, 1.0]
        self.segments.set_color(colours)
        o, e = s["origin"], s["end"]
        self.ray.set_data([o[0], e[0]], [o[1], e[1]])
        self.origin.set_data([o[0]], [o[1]])
        if s["hit"] >= 0:
            self.hit.set_data([e[0]], [e[1]])
        else:
            self.hit.set_data([], [])
        for k, label in enumerate(self.numbers):
            if k < len(s["boxes"]):
                lo, hi = s["boxes"][k]
                label.set_position(((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2))
                label.set_text(str(k + 1))
            else:
                label.set_text("")
        self.title.set_text(f"{self.state.structure}: {len(s['boxes'])} visited, "
                            f"{s['tested_triangles']} triangle tests")
        self.info.value = s["text"]
