r"""Chapter 15 (lesson section "Spatial subdivision"): a uniform grid with 3D-DDA, an octree and
a kd-tree, beside the BVH.

**Object versus space subdivision.** The BVH (:class:`course_lib.raytracing.BVH`) divides the
*objects*: every triangle is in exactly one leaf, but the boxes of siblings may overlap, so a ray
may have to look into both. The structures here divide *space*: the cells never overlap, so a ray
meets them in a well defined order along its length and can stop at the first cell that holds a
hit; the price is that a triangle crossing a cell wall is listed in every cell it touches.

* :class:`UniformGrid`: equal cells, :math:`\approx \lambda N` of them for :math:`N` triangles
  (about :math:`(\lambda N)^{1/3}` per axis), walked cell by cell by the **3D-DDA** of Amanatides
  and Woo: per axis the parameter ``t_max`` where the ray crosses the next cell wall, the
  parameter step ``t_delta`` between two walls, and the index step ``+1``/``-1``; each step moves
  along the axis whose ``t_max`` is smallest (the lowest axis on a tie).
* :class:`Octree`: a box split at its centre into 8 children, recursively, until a node holds at
  most ``leaf_size`` triangles or reaches ``max_depth``; traversal visits the children a ray
  enters in increasing entry parameter (front to back).
* :class:`KDTree`: one axis-aligned plane per node, at the **median** of the triangles' box
  centres along the node's longest axis (not SAH); traversal with the parameter
  :math:`t_{split}` where the ray crosses the plane: near child only, far child only, or near on
  :math:`[t_0, t_{split}]` then far on :math:`[t_{split}, t_1]`.

**Binning.** A triangle goes into every cell its **bounding box** overlaps (padded by a hair, so
rounding never loses a hit); the exact triangle-box test would list fewer cells, at a higher
build cost. **Mailboxing**: a triangle listed in several cells is tested once per ray (the
structure remembers, per triangle, the last ray that tested it). **Early exit**: a hit found in a
cell may lie *beyond* that cell (the triangle sticks out of it); the walk stops only when the
nearest hit so far is no farther than the exit parameter of the current cell.

All three return a :class:`SpatialHits` with the same ``t`` and ``ids`` as brute force
(:func:`course_lib._raycore.brute_force`) and the BVH, bit for bit (the same Möller-Trumbore
code, the same rule for equally near triangles: the lower index), and the work done. Traversal is
a loop in Python over each ray's cells (the triangle tests inside a cell are vectorized): clear,
not fast; the BVH's traversal is the vectorized one.
"""

import time
from typing import NamedTuple

import numpy as np

from .._raycore import (BVH, as_rays, moller_trumbore, slab, triangle_soa)
from .._validate import as_mesh, as_positive, as_whole

__all__ = ["KDTree", "Octree", "RayWalk", "SpatialHits", "StructureRow", "UniformGrid",
           "compare_structures"]


class SpatialHits(NamedTuple):
    """Nearest hits of rays found by a spatial structure, with the work it took.

    Attributes
    ----------
    t : ndarray, shape (p,)
        Ray parameter of the nearest hit (``inf`` for a miss).
    ids : ndarray of int, shape (p,)
        Index of the triangle hit (the lowest among equally near ones); -1 for a miss.
    triangle_tests : int
        Ray-triangle tests performed (all rays).
    cells_visited : int
        Cells (grid cells, tree leaves) the rays looked into (all rays).
    nodes_visited : int
        Tree nodes visited, inner nodes and leaves (equal to `cells_visited` for the grid).

    Examples
    --------
    >>> SpatialHits(np.array([1.0]), np.array([0]), 1, 1, 1).triangle_tests
    1
    """
    t: np.ndarray
    ids: np.ndarray
    triangle_tests: int
    cells_visited: int
    nodes_visited: int


# ---------------------------------------------------------------------------------------------
# Shared: the mesh, the box of a set of triangles, and the walk along ordered cells
# ---------------------------------------------------------------------------------------------

def _sp_mesh(vertices, faces):
    """Triangles (m, 3, 3) of a mesh; every triangle degenerate (no area) is an error."""
    v, f = as_mesh(vertices, faces)
    tris = v[f]
    area2 = np.linalg.norm(np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]), axis=1)
    if not np.any(area2 > 0):
        raise ValueError("the mesh is degenerate: every triangle has zero area (a ray can hit "
                         "nothing)")
    return tris


def _sp_bounds(tris):
    """The triangles' boxes (m, 3) lo and hi, padded by a hair, and the scene box."""
    pad = 1e-9 * max(float(np.abs(tris).max()), 1.0)
    lo, hi = tris.min(axis=1) - pad, tris.max(axis=1) + pad
    box_lo, box_hi = lo.min(axis=0), hi.max(axis=0)
    return lo, hi, box_lo, box_hi


class _SpatialBase:
    """The walk every structure shares: cells in front-to-back order, mailboxing, early exit."""

    def __init__(self, vertices, faces):
        self.triangles = _sp_mesh(vertices, faces)
        self._soa = triangle_soa(self.triangles)
        self._tri_lo, self._tri_hi, self.lo, self.hi = _sp_bounds(self.triangles)

    def _cells(self, o, d):                          # pragma: no cover - each class has one
        raise NotImplementedError

    def traverse(self, origin, direction):
        """The cells one ray passes through, in the order it enters them (no early exit).

        Parameters
        ----------
        origin, direction : array_like, shape (3,)

        Returns
        -------
        cells : list
            The cells: (i, j, k) index triples for the grid, leaf node numbers for the trees.
        t_enter, t_exit : ndarray
            Where the ray enters and leaves each cell (``t_enter`` increasing).

        Examples
        --------
        >>> g = UniformGrid([[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 2]],
        ...                 [[0, 1, 2], [0, 1, 3]], resolution=2)
        >>> g.traverse([-1, 0.5, 0.5], [1, 0, 0])[0]
        [(0, 0, 0), (1, 0, 0)]
        """
        o, d, lead = as_rays(origin, direction)
        if len(o) != 1:
            raise ValueError(f"traverse takes one ray (origin and direction of shape (3,)), "
                             f"got {len(o)} rays")
        out = [(c, a, b) for c, a, b, _ in self._cells(o[0], d[0])]
        cells = [c for c, _, _ in out]
        return (cells, np.array([a for _, a, _ in out]), np.array([b for _, _, b in out]))

    def intersect(self, origins, directions, mailbox=True):
        """The nearest triangle hit by each ray, walking the cells front to back.

        Parameters
        ----------
        origins, directions : array_like, shape (p, 3) or (3,)
        mailbox : bool, optional
            Test a triangle listed in several cells once per ray (default). Off, it is tested
            again in every cell: the same hits, more tests.

        Returns
        -------
        SpatialHits

        Raises
        ------
        ValueError
            For malformed rays or zero directions.

        Examples
        --------
        >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2], [1, 0, 2], [0, 1, 2]]
        >>> hits = KDTree(v, [[0, 1, 2], [3, 4, 5]]).intersect([[0.2, 0.2, 5]], [0, 0, -1])
        >>> hits.t.tolist(), hits.ids.tolist()
        ([3.0], [1])
        """
        o, d, lead = as_rays(origins, directions)
        p, m = len(o), len(self.triangles)
        t_best, id_best = np.full(p, np.inf), np.full(p, -1, dtype=np.intp)
        stamp = np.full(m, -1, dtype=np.intp)        # the mailboxes: last ray that tested it
        tests = cells = nodes = 0
        for r in range(p):
            t_best[r], id_best[r], walked, tested = self._walk(o[r], d[r], stamp, r, mailbox)
            cells += len(walked)
            tests += sum(len(ids) for ids in tested)
            nodes += self._last_nodes
        return SpatialHits(t_best.reshape(lead), id_best.reshape(lead), int(tests), int(cells),
                           int(nodes))

    def _walk(self, o_r, d_r, stamp, r, mailbox):
        """One ray: (t, id, the cells (cell, t_in, t_out) looked into, the triangles tested in
        each)."""
        best_t, best_id = np.inf, -1
        walked, tested = [], []
        for cell, t_in, t_out, ids in self._cells(o_r, d_r):
            if mailbox:
                ids = ids[stamp[ids] != r]
                stamp[ids] = r
            walked.append((cell, t_in, t_out))
            tested.append(ids)
            if len(ids):
                t, _, _ = moller_trumbore(o_r, d_r, self._soa[:, ids])
                t = np.where(t >= 0, t, np.inf)
                k = int(np.argmin(t))              # first among equal t; ids are ascending
                tk, ik = float(t[k]), int(ids[k])
                if tk < best_t or (tk == best_t and ik < best_id and tk < np.inf):
                    best_t, best_id = tk, ik
            if best_t <= t_out:                      # the hit lies in this cell: done
                break
        return best_t, best_id, walked, tested

    def walk(self, origin, direction, mailbox=True):
        """What :meth:`intersect` does for one ray, step by step (for drawings and lessons).

        Parameters
        ----------
        origin, direction : array_like, shape (3,)
        mailbox : bool, optional

        Returns
        -------
        RayWalk

        Examples
        --------
        >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 2], [1, 0, 2], [0, 1, 2]]
        >>> w = UniformGrid(v, [[0, 1, 2], [3, 4, 5]], resolution=[1, 1, 4]).walk(
        ...     [0.2, 0.2, 5], [0, 0, -1])
        >>> w.cells, [ids.tolist() for ids in w.tested], w.t, w.id
        ([(0, 0, 3)], [[1]], 3.0, 1)
        """
        o, d, _ = as_rays(origin, direction)
        if len(o) != 1:
            raise ValueError(f"walk takes one ray (origin and direction of shape (3,)), got "
                             f"{len(o)} rays")
        stamp = np.full(len(self.triangles), -1, dtype=np.intp)
        t, i, walked, tested = self._walk(o[0], d[0], stamp, 0, mailbox)
        return RayWalk([c for c, _, _ in walked], np.array([a for _, a, _ in walked]),
                       np.array([b for _, _, b in walked]), tested, float(t), int(i),
                       self._last_nodes)


class RayWalk(NamedTuple):
    """One ray's walk through a spatial structure (:meth:`UniformGrid.walk` and the trees').

    Attributes
    ----------
    cells : list
        The cells looked into, in order ((i, j, k) for the grid, leaf numbers for the trees).
    t_enter, t_exit : ndarray
        Where the ray enters and leaves each of them.
    tested : list of ndarray
        The triangles tested in each cell (after mailboxing).
    t : float
        The nearest hit (``inf``: none).
    id : int
        Its triangle (-1: none).
    nodes_visited : int
        Tree nodes visited (the grid: cells).

    Examples
    --------
    >>> RayWalk([], np.zeros(0), np.zeros(0), [], np.inf, -1, 0).id
    -1
    """
    cells: list
    t_enter: np.ndarray
    t_exit: np.ndarray
    tested: list
    t: float
    id: int
    nodes_visited: int


# ---------------------------------------------------------------------------------------------
# The uniform grid and the 3D-DDA
# ---------------------------------------------------------------------------------------------

class UniformGrid(_SpatialBase):
    r"""A uniform grid of equal cells over a triangle mesh, walked by the 3D-DDA.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    resolution : int or sequence of 3 ints, optional
        Cells per axis. Default: the rule of thumb :math:`n_k = \text{round}(e_k\,
        (\lambda N / V)^{1/3})` with :math:`\lambda = 3` (about :math:`3N` cells, cubic as far
        as the box allows; :math:`e_k` the box's extents, :math:`V` its volume).
    cell_size : float, optional
        The edge of a (cubic) cell instead of `resolution` (not both).

    Attributes
    ----------
    resolution : ndarray of int, shape (3,)
    cell : ndarray, shape (3,)
        The cell's edge lengths.
    lo, hi : ndarray, shape (3,)
        The grid's box (the scene's box).

    Raises
    ------
    ValueError
        For a resolution < 1, a cell size <= 0, both given, or an empty/degenerate mesh.

    Examples
    --------
    >>> g = UniformGrid([[0, 0, 0], [4, 0, 0], [0, 4, 0]], [[0, 1, 2]], resolution=[4, 4, 1])
    >>> g.resolution.tolist(), g.cell_triangles((3, 3, 0)).tolist()
    ([4, 4, 1], [0])
    """

    def __init__(self, vertices, faces, resolution=None, cell_size=None):
        super().__init__(vertices, faces)
        m = len(self.triangles)
        ext = self.hi - self.lo
        if resolution is not None and cell_size is not None:
            raise ValueError("give resolution or cell_size, not both")
        if cell_size is not None:
            h = as_positive(cell_size, "cell_size", "the edge of a grid cell")
            res = np.maximum(np.ceil(ext / h - 1e-9), 1).astype(int)
        elif resolution is not None:
            r = np.atleast_1d(np.asarray(resolution, dtype=object))
            if r.shape not in [(1,), (3,)]:
                raise ValueError(f"resolution must be one whole number or three, got shape "
                                 f"{r.shape}")
            res = np.array([as_whole(x, "resolution", 1) for x in r] * (3 // len(r)))
        else:
            e = np.maximum(ext, 1e-3 * ext.max())
            scale = np.cbrt(3.0 * m / np.prod(e))
            res = np.clip(np.round(e * scale), 1, 256).astype(int)
        self.resolution = res
        self.cell = ext / res
        # binning by bounding box: the index ranges of cells each triangle's box overlaps
        first = np.clip(np.floor((self._tri_lo - self.lo) / self.cell), 0, res - 1).astype(int)
        last = np.clip(np.floor((self._tri_hi - self.lo) / self.cell), 0, res - 1).astype(int)
        span = last - first + 1
        count = span.prod(axis=1)
        tri = np.repeat(np.arange(m), count)
        local = np.arange(count.sum()) - np.repeat(np.cumsum(count) - count, count)
        sy, sz = span[tri, 1], span[tri, 2]
        i = first[tri, 0] + local // (sy * sz)
        j = first[tri, 1] + (local // sz) % sy
        k = first[tri, 2] + local % sz
        flat = (i * res[1] + j) * res[2] + k
        order = np.lexsort((tri, flat))                 # by cell, then by triangle index
        self._cell_tris = tri[order]
        self._cell_start = np.searchsorted(flat[order], np.arange(res.prod() + 1))
        self.references = int(len(tri))
        self._last_nodes = 0

    def __repr__(self):
        return (f"UniformGrid({len(self.triangles)} triangles, resolution "
                f"{tuple(int(r) for r in self.resolution)}, {self.references} references)")

    def cell_triangles(self, cell):
        """The triangles listed in cell (i, j, k), ascending.

        Examples
        --------
        >>> g = UniformGrid([[0, 0, 0], [4, 0, 0], [0, 4, 0]], [[0, 1, 2]], resolution=4)
        >>> g.cell_triangles((0, 0, 0)).tolist()
        [0]
        """
        i, j, k = (int(c) for c in cell)
        f = (i * self.resolution[1] + j) * self.resolution[2] + k
        return self._cell_tris[self._cell_start[f]:self._cell_start[f + 1]]

    def _cells(self, o, d):
        r"""The 3D-DDA: yield (cell, t_enter, t_exit, triangles) front to back."""
        self._last_nodes = 0
        near, far = slab(self.lo, self.hi, o, d)
        t0, t1 = max(float(near.max()), 0.0), float(far.min())
        if t0 > t1:
            return
        res, cell = self.resolution, self.cell
        p = o + t0 * d
        idx = np.clip(np.floor((p - self.lo) / cell), 0, res - 1).astype(int)
        step = np.where(d > 0, 1, -1)
        with np.errstate(divide="ignore"):
            inv = 1.0 / np.abs(d)
            t_delta = cell * inv                                 # inf for d_k = 0
            wall = self.lo + (idx + (step > 0)) * cell           # the next wall per axis
            t_max = np.where(d != 0, (wall - o) / np.where(d != 0, d, 1.0), np.inf)
        i = [int(x) for x in idx]
        t_max, t_delta = [float(x) for x in t_max], [float(x) for x in t_delta]
        st = [int(x) for x in step]
        t_enter = t0
        while True:
            a = 0 if t_max[0] <= t_max[1] and t_max[0] <= t_max[2] else (
                1 if t_max[1] <= t_max[2] else 2)            # smallest t_max, lowest on a tie
            t_exit = min(t_max[a], t1)
            self._last_nodes += 1
            f = (i[0] * res[1] + i[1]) * res[2] + i[2]
            yield (tuple(i), t_enter, t_exit,
                   self._cell_tris[self._cell_start[f]:self._cell_start[f + 1]])
            if t_max[a] >= t1:
                return
            i[a] += st[a]
            if not 0 <= i[a] < res[a]:
                return
            t_enter = t_max[a]
            t_max[a] += t_delta[a]


# ---------------------------------------------------------------------------------------------
# Trees: the octree and the kd-tree (nodes in flat lists)
# ---------------------------------------------------------------------------------------------

def _sp_depth(max_depth):
    return as_whole(max_depth, "max_depth", 0)


class Octree(_SpatialBase):
    """An octree over a triangle mesh: boxes split at their centre into 8 children.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    max_depth : int, optional
        The deepest level (0: the root is the only cell).
    leaf_size : int, optional
        A node with at most this many triangles is not split.
    axes : sequence of int, optional
        The axes halved at each level: all three (an octree, 8 children), or two (a quadtree
        in that plane, 4 children; the explorer's top view uses (0, 1)).

    Attributes
    ----------
    node_lo, node_hi : ndarray, shape (nodes, 3)
        The nodes' boxes.
    children : ndarray of int, shape (nodes, 8) (2 ** len(axes) in general)
        The children's node numbers (child ``4x + 2y + z`` is the upper half along x when
        ``x = 1``, ...); -1 for a leaf.
    depth : int

    Raises
    ------
    ValueError
        For max_depth < 0, leaf_size < 1, bad axes, or an empty/degenerate mesh.

    Examples
    --------
    >>> tree = Octree([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],
    ...               [[0, 1, 2], [0, 1, 3], [0, 2, 3]], max_depth=1, leaf_size=1)
    >>> len(tree.children), tree.depth
    (9, 1)
    """

    def __init__(self, vertices, faces, max_depth=8, leaf_size=8, axes=(0, 1, 2)):
        super().__init__(vertices, faces)
        self.max_depth = _sp_depth(max_depth)
        try:
            axes = sorted({int(a) for a in axes})
        except (TypeError, ValueError):
            axes = []
        if not axes or not set(axes) <= {0, 1, 2}:
            raise ValueError("axes must be a non-empty subset of (0, 1, 2) (the axes halved at "
                             "each level)")
        self.axes = tuple(axes)
        n_kids = 2 ** len(axes)
        split_axis = np.isin(np.arange(3), self.axes)
        self.leaf_size = as_whole(leaf_size, "leaf_size", 1)
        lo_list, hi_list, kids, tri_list = [self.lo], [self.hi], [None], [np.arange(
            len(self.triangles))]
        frontier, depth = [0], 0
        while frontier and depth < self.max_depth:
            nxt = []
            for n in frontier:
                ids = tri_list[n]
                if len(ids) <= self.leaf_size:
                    continue
                lo, hi = lo_list[n], hi_list[n]
                mid = np.where(split_axis, (lo + hi) / 2, hi)     # unsplit axes: whole
                kids[n] = []
                for c in range(n_kids):
                    bits = np.zeros(3, dtype=bool)
                    for b, a in enumerate(self.axes[::-1]):
                        bits[a] = (c >> b) & 1
                    clo, chi = np.where(bits, mid, lo), np.where(bits, hi, mid)
                    inside = np.all((self._tri_lo[ids] <= chi) & (self._tri_hi[ids] >= clo),
                                    axis=1)
                    kids[n].append(len(lo_list))
                    nxt.append(len(lo_list))
                    lo_list.append(clo)
                    hi_list.append(chi)
                    kids.append(None)
                    tri_list.append(ids[inside])
                tri_list[n] = ids[:0]
            if nxt:
                depth += 1
            frontier = nxt
        self.depth = depth
        self.node_lo, self.node_hi = np.array(lo_list), np.array(hi_list)
        self.children = np.array([k if k is not None else [-1] * n_kids for k in kids], dtype=np.intp)
        self._tris_of = tri_list
        self._last_nodes = 0

    def __repr__(self):
        return (f"Octree({len(self.triangles)} triangles, {len(self.children)} nodes, depth "
                f"{self.depth}, leaf size {self.leaf_size})")

    def _cells(self, o, d):
        """Leaves front to back: the children a ray enters, by increasing entry parameter."""
        self._last_nodes = 0
        near, far = slab(self.lo, self.hi, o, d)
        t0, t1 = max(float(near.max()), 0.0), float(far.min())
        if t0 > t1:
            return
        stack = [(0, t0, t1)]
        while stack:
            n, a_t, b_t = stack.pop()
            self._last_nodes += 1
            kids = self.children[n]
            if kids[0] < 0:
                yield int(n), a_t, b_t, self._tris_of[n]
                continue
            near, far = slab(self.node_lo[kids], self.node_hi[kids], o, d)   # the 8 children
            t_in = np.maximum(near.max(axis=1), 0.0)
            t_out = far.min(axis=1)
            entered = np.nonzero(t_in < t_out)[0]                # a stretch of positive length
            order = entered[np.argsort(t_in[entered], kind="stable")]
            stack.extend((int(kids[c]), float(t_in[c]), float(t_out[c])) for c in order[::-1])


class KDTree(_SpatialBase):
    r"""A kd-tree over a triangle mesh: one axis-aligned splitting plane per node.

    The plane is perpendicular to the node box's longest axis, at the **median** of the box
    centres of the node's triangles (a median split, not the surface area heuristic); a triangle
    whose box straddles the plane goes to both children. A node stops splitting at `leaf_size`
    triangles, at `max_depth`, or when a split would leave all its triangles on both sides.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    max_depth : int, optional
    leaf_size : int, optional

    Attributes
    ----------
    axis, split : ndarray
        Per node, the splitting axis and plane position (-1 and 0 for a leaf).
    children : ndarray of int, shape (nodes, 2)
        Below and above the plane; -1 for a leaf.
    node_lo, node_hi : ndarray, shape (nodes, 3)
    depth : int

    Raises
    ------
    ValueError
        For max_depth < 0, leaf_size < 1, or an empty/degenerate mesh.

    Examples
    --------
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [3, 0, 0], [4, 0, 0], [3, 1, 0]]
    >>> tree = KDTree(v, [[0, 1, 2], [3, 4, 5]], leaf_size=1)
    >>> int(tree.axis[0]), float(tree.split[0])      # x, between the centres 0.5 and 3.5
    (0, 2.0)
    """

    def __init__(self, vertices, faces, max_depth=20, leaf_size=8):
        super().__init__(vertices, faces)
        self.max_depth = _sp_depth(max_depth)
        self.leaf_size = as_whole(leaf_size, "leaf_size", 1)
        centre = (self._tri_lo + self._tri_hi) / 2
        lo_l, hi_l, axis_l, split_l, kids_l, tris_l = [], [], [], [], [], []
        stack = [(np.arange(len(self.triangles)), self.lo, self.hi, 0)]
        depth = 0
        while stack:
            ids, lo, hi, level = stack.pop()

            lo_l.append(lo)
            hi_l.append(hi)
            depth = max(depth, level)
            a, s = -1, 0.0
            below = above = None
            if len(ids) > self.leaf_size and level < self.max_depth:
                a = int(np.argmax(hi - lo))
                s = float(np.median(centre[ids, a]))
                s = min(max(s, lo[a]), hi[a])
                below = ids[self._tri_lo[ids, a] <= s]
                above = ids[self._tri_hi[ids, a] >= s]
                if len(below) == len(ids) and len(above) == len(ids):
                    a, s = -1, 0.0                       # a useless split: make a leaf
            axis_l.append(a)
            split_l.append(s)
            kids_l.append([-1, -1])
            tris_l.append(ids if a < 0 else ids[:0])
            if a >= 0:
                hb, la = hi.copy(), lo.copy()
                hb[a], la[a] = s, s
                stack.append((above, la, hi, level + 1))
                stack.append((below, lo, hb, level + 1))     # below: numbered right after n
        # fill in the children: depth-first order puts the below child right after its parent
        # and the above child after the whole below subtree
        self.node_lo, self.node_hi = np.array(lo_l), np.array(hi_l)
        self.axis, self.split = np.array(axis_l, dtype=np.intp), np.array(split_l)
        self._tris_of = tris_l
        self.children = self._link(np.array(axis_l))
        self.depth = depth
        self._last_nodes = 0

    @staticmethod
    def _link(axis):
        """Children of nodes stored in depth-first (below first) order."""
        n = len(axis)
        children = np.full((n, 2), -1, dtype=np.intp)
        # the size of each subtree, from the end backwards
        size = np.ones(n, dtype=np.intp)
        for i in range(n - 1, -1, -1):
            if axis[i] >= 0:
                b = i + 1
                children[i] = b, b + size[b]
                size[i] = 1 + size[b] + size[b + size[b]]
        return children

    def __repr__(self):
        return (f"KDTree({len(self.triangles)} triangles, {len(self.axis)} nodes, depth "
                f"{self.depth}, leaf size {self.leaf_size})")

    def _cells(self, o, d):
        """Leaves front to back with t_split: near child, then the far one if the ray gets
        there."""
        self._last_nodes = 0
        near, far = slab(self.lo, self.hi, o, d)
        t0, t1 = max(float(near.max()), 0.0), float(far.min())
        if t0 > t1:
            return
        stack = [(0, t0, t1)]
        while stack:
            n, a_t, b_t = stack.pop()
            self._last_nodes += 1
            a = self.axis[n]
            if a < 0:
                yield int(n), a_t, b_t, self._tris_of[n]
                continue
            s = self.split[n]
            below, above = self.children[n]
            first, second = (below, above) if (o[a] < s or (o[a] == s and d[a] <= 0)) \
                else (above, below)
            if d[a] == 0:
                stack.append((first, a_t, b_t))
                continue
            t_split = (s - o[a]) / d[a]
            if t_split >= b_t or t_split < 0:
                stack.append((first, a_t, b_t))               # never reaches the plane
            elif t_split <= a_t:
                stack.append((second, a_t, b_t))              # crossed it before the box
            else:
                stack.append((second, t_split, b_t))
                stack.append((first, a_t, t_split))           # near first (popped first)


# ---------------------------------------------------------------------------------------------
# The comparison table
# ---------------------------------------------------------------------------------------------

class StructureRow(NamedTuple):
    """One row of :func:`compare_structures`.

    Attributes
    ----------
    name : str
    build_ms : float
        Build time in milliseconds.
    cells_per_ray : float
        Cells or leaves looked into per ray (for the BVH: box tests per ray).
    tests_per_ray : float
        Ray-triangle tests per ray.
    us_per_ray : float
        Time per ray in microseconds.
    agrees : bool
        The hits (t, triangle) equal brute force's.

    Examples
    --------
    >>> StructureRow("grid", 1.0, 3.0, 4.0, 50.0, True).tests_per_ray
    4.0
    """
    name: str
    build_ms: float
    cells_per_ray: float
    tests_per_ray: float
    us_per_ray: float
    agrees: bool


def compare_structures(vertices, faces, origins, directions, structures=("grid", "octree",
                       "kdtree", "bvh"), leaf_size=8):
    """Build each structure on the same mesh and shoot the same rays: the comparison table.

    Parameters
    ----------
    vertices, faces : array_like
        The mesh.
    origins, directions : array_like, shape (p, 3)
    structures : sequence of str
        Among "grid", "octree", "kdtree", "bvh", "brute" (brute force).
    leaf_size : int
        For the trees and the BVH.

    Returns
    -------
    list of StructureRow
        Times are measured (they vary from run to run); the counts do not.

    Examples
    --------
    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> rows = compare_structures(v, [[0, 1, 2], [0, 1, 3]], [[0.2, 0.2, 5]], [0, 0, -1],
    ...                           ("grid", "brute"))
    >>> [(r.name, r.tests_per_ray, r.agrees) for r in rows]
    [('grid', 2.0, True), ('brute', 2.0, True)]
    """
    tris = _sp_mesh(vertices, faces)
    o, d, _ = as_rays(origins, directions, flat=True)
    from .._raycore import brute_force
    soa = triangle_soa(tris)
    ref = brute_force(o, d, soa, 0.0, np.full(len(o), np.inf))
    known = {"grid", "octree", "kdtree", "bvh", "brute"}
    rows = []
    p = len(o)
    for name in structures:
        if name not in known:
            raise ValueError(f"structures must be among {sorted(known)}, got {name!r}")
        start = time.perf_counter()
        if name == "grid":
            s = UniformGrid(vertices, faces)
        elif name == "octree":
            s = Octree(vertices, faces, leaf_size=leaf_size)
        elif name == "kdtree":
            s = KDTree(vertices, faces, leaf_size=leaf_size)
        elif name == "bvh":
            s = BVH(tris, leaf_size=leaf_size)
        build = time.perf_counter() - start if name != "brute" else 0.0
        start = time.perf_counter()
        if name == "brute":
            t, ids, _, _, tests, cells = brute_force(o, d, soa, 0.0, np.full(p, np.inf))
        elif name == "bvh":
            h = s.intersect(o, d)
            t, ids, tests, cells = h.t, h.ids, h.triangle_tests, h.box_tests
        else:
            h = s.intersect(o, d)
            t, ids, tests, cells = h.t, h.ids, h.triangle_tests, h.cells_visited
        run = time.perf_counter() - start
        agrees = bool(np.array_equal(t, ref[0]) and np.array_equal(ids, ref[1]))
        rows.append(StructureRow(name, 1e3 * build, cells / p, tests / p, 1e6 * run / p, agrees))
    return rows
