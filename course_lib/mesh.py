r"""Chapter 6: polygonal models, winged-edge and half-edge meshes, and QEM simplification.

A polygonal model is a list of points (the **geometry**) plus a list of faces, each a cycle of
point indices (the **connectivity** or topology). The face list alone answers "which vertices
does face 7 have?" at once, but "which faces touch vertex 3?" or "what is across this edge?" need
a search through all faces. The edge-based structures of this module store those neighbour
relations explicitly, so that every local question costs a few pointer steps.

Properties of polygonal models
------------------------------
* **Manifold** (a 2-manifold, possibly with boundary): every small neighbourhood of the surface
  looks like a disc, or a half-disc on the boundary. For a mesh this means two combinatorial
  rules: an **edge** has one or two faces (never three, like the pages of a book), and the faces
  around a **vertex** form one single fan, closed (interior vertex) or open (boundary vertex).
  Two fans that touch only at a vertex form a *bow tie*: a non-manifold vertex.
* **Closed** (watertight): every edge has exactly two faces; no boundary. An edge with one face
  is a boundary edge; boundary edges link up into **boundary loops** (the rims of the holes).
* **Orientable, consistently oriented**: each face lists its vertices counter-clockwise seen
  from outside, so its normal :math:`(p_1 - p_0) \times (p_2 - p_0)` points outwards (right-hand
  rule). Then two faces sharing an edge run along it in *opposite* directions. Two faces running
  the same way along a shared edge mean inconsistent winding (one of them is flipped).
* **Euler-Poincare formula**: for a connected, orientable polygonal surface with :math:`g`
  handles (its **genus**) and :math:`b` boundary loops,

  .. math:: \chi = V - E + F = 2 - 2g - b.

  A sphere or a cube has :math:`\chi = 2` (:math:`g = 0`), a torus :math:`\chi = 0` (:math:`g = 1`),
  a double torus :math:`\chi = -2` (:math:`g = 2`), a disc :math:`\chi = 1` (:math:`g = 0`,
  :math:`b = 1`). The number does not depend on how finely the surface is meshed: it is a
  topological invariant. For several components the :math:`\chi` of the components add up;
  :meth:`HalfEdgeMesh.genus` applies the formula to each component separately.

Data structures
---------------
* **Winged edge** (:class:`WingedEdgeMesh`, Baumgart's structure). The edge is the central record:
  its two end vertices (start, end), the faces on its left and on its right, and four "wings":
  the previous and next edge around the left face and around the right face. Each vertex and each
  face stores one incident edge. An edge has no direction of its own that agrees with both faces,
  so every traversal asks "is the face I walk around on the left or the right of this edge?"
  before it picks a wing: that case analysis is the price of storing an undirected edge.
* **Half edge** (:class:`HalfEdgeMesh`, also called the doubly connected edge list). Every edge is
  split into two directed **half-edges**, one per side, each owned by one face. A half-edge
  stores its origin vertex, its twin (the opposite half-edge, on the neighbouring face), the next
  and previous half-edges around its face, and its face. The half-edges of a face form a cycle in
  the face's (counter-clockwise) order; twins run in opposite directions. Each vertex stores one
  outgoing half-edge and each face one of its half-edges. No case analysis is needed:
  ``twin(prev(h))`` always turns one step counter-clockwise around the origin of ``h``.

  The boundary is represented by **boundary half-edges**: the missing twins of boundary edges,
  with face -1, linked by ``next``/``prev`` into one cycle per boundary loop. Their direction is
  opposite to that of the faces, so a boundary loop runs clockwise seen from outside (the outer
  rim of a disc in the xy-plane with normals +z runs clockwise seen from +z).

The storage cost per edge: winged edge 8 integers (2 vertices, 2 faces, 4 edges); half edge
2 x 5 integers (origin, twin, next, prev, face; ``prev`` is optional, it saves walking around a
face). Both answer the local queries (faces of a vertex, one-ring, edges of a face, faces of an
edge) in time proportional to the size of the answer.

Iterative edge collapse
-----------------------
An **edge collapse** :math:`(v_1, v_2) \to \bar v` merges the two end points of an edge into one
vertex at a new position :math:`\bar v`: the two faces of the edge disappear (one on a boundary
edge), every other face of :math:`v_2` is re-attached to :math:`v_1`. Simplification repeats the
cheapest collapse until the face count reaches the target, with the candidate edges in a
**priority queue** ordered by cost; after a collapse only the edges around the new vertex get new
costs (old queue entries are recognised as stale and skipped: *lazy deletion*).

The **quadric error metric** (Garland and Heckbert, 1997) measures the cost. A face lies in the
plane :math:`p = (a, b, c, d)` with :math:`ax + by + cz + d = 0` and :math:`a^2 + b^2 + c^2 = 1`;
the squared distance of a point :math:`v = (x, y, z, 1)` from it is :math:`(p^T v)^2 = v^T K_p v`
with the **fundamental quadric** :math:`K_p = p p^T` (4 x 4). Each vertex sums the quadrics of
its faces, :math:`Q_i = \sum_{p \ni v_i} K_p`: :math:`v^T Q_i v` is the sum of squared distances
of :math:`v` to the planes around vertex :math:`i`, zero at the vertex itself. Collapsing an edge
adds the two quadrics, :math:`\bar Q = Q_1 + Q_2`, and the best position minimizes
:math:`\bar v^T \bar Q \bar v`: with :math:`\bar Q = \begin{pmatrix} A & b \\ b^T & c
\end{pmatrix}` the gradient vanishes where :math:`A \bar v = -b` (a 3 x 3 linear system). When
:math:`A` is singular or badly conditioned (flat or cylindrical neighbourhoods: the minimum is a
whole plane or line) the best of :math:`v_1`, :math:`v_2` and the midpoint is taken instead. The
cost of the edge is :math:`\bar v^T \bar Q \bar v`; the merged vertex keeps :math:`\bar Q`, so the
error of later collapses still refers to the planes of the *original* surface.

A collapse is **rejected** when it would break the mesh: (i) the *link condition*: the end points
must have exactly two common neighbours, the vertices opposite the edge (otherwise the collapse
pinches the surface into a non-manifold one or folds two faces onto each other); (ii) a
surviving face around the edge would turn its normal by more than ``max_angle`` (90 degrees by
default: a fold-over) or become degenerate; (iii) a vertex would be left with fewer than three
neighbours (a tetrahedron cannot lose more faces). **Boundaries are kept exactly**: a boundary
edge is never collapsed, a boundary vertex never moves (an interior edge with one boundary end
point collapses onto that end point) and an interior edge joining two boundary vertices is
rejected (it would pinch the surface). Closed meshes stay closed, and a hole keeps its rim.
"""
import heapq
import numbers
from operator import add
from typing import NamedTuple

import numpy as np

from . import shapes
from ._validate import as_array, as_points, as_scalar

__all__ = [
    "Collapse",
    "HalfEdgeMesh",
    "MeshProblem",
    "Simplified",
    "SimplificationRecord",
    "WingedEdgeMesh",
    "bow_tie",
    "collapse_cost",
    "cube",
    "disc",
    "double_torus",
    "face_areas",
    "face_normals",
    "face_planes",
    "icosphere",
    "mesh_problems",
    "optimal_position",
    "plane_quadric",
    "simplify_qem",
    "tetrahedron",
    "three_faces_on_an_edge",
    "torus",
    "vertex_quadrics",
]

# The 3x3 block A of a quadric counts as singular when det(A) <= _SINGULAR * trace(A)**3. For a
# positive semi-definite A with eigenvalues l1 <= l2 <= l3 this is l1 l2 l3 <= 1e-10 (l1+l2+l3)^3,
# i.e. roughly l1 l2 / l3^2 below 3e-9: a flat (l1, l2 ~ 0) or cylindrical (l1 ~ 0) patch.
_SINGULAR = 1e-10


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _vertices(vertices):
    v = as_points(vertices, "vertices", dims=3)
    if v.ndim != 2:
        raise ValueError(f"vertices must be an (n, 3) array of points, got shape {v.shape}")
    return v


def _is_int_array(a):
    return np.issubdtype(a.dtype, np.integer) and not np.issubdtype(a.dtype, np.bool_)


def _face_table(faces):
    """Flatten a face list: (corners, starts) with face f = corners[starts[f]:starts[f + 1]].

    Accepts an (m, k) integer array (all faces with k vertices) or a sequence of integer
    sequences of any lengths (polygons).
    """
    if isinstance(faces, (str, bytes)) or faces is None or faces is Ellipsis:
        raise TypeError("faces must be a list of faces, each a list of vertex indices, got "
                        f"{'None' if faces is None else 'a ' + type(faces).__name__}")
    arr = None
    if isinstance(faces, np.ndarray):
        arr = faces
    else:
        try:
            arr = np.asarray(faces)
        except (TypeError, ValueError):        # ragged: polygons of different sizes
            arr = None
        if arr is not None and arr.dtype == object:
            arr = None
    if arr is not None and arr.ndim == 2 and arr.size:
        if not _is_int_array(arr):
            raise TypeError(f"faces must hold integer vertex indices, got an array of {arr.dtype}")
        m, k = arr.shape
        return arr.astype(np.int64).ravel(), np.arange(m + 1, dtype=np.int64) * k
    if arr is not None and arr.size == 0:
        raise ValueError("faces must contain at least one face, got none")
    if arr is not None and arr.ndim == 1 and _is_int_array(arr):
        raise ValueError(f"faces must be a list of faces, got one flat list of indices "
                         f"{arr.tolist()[:8]}{'...' if arr.size > 8 else ''}; for a single face "
                         "write [[a, b, c]]")
    if arr is not None and arr.ndim > 2:
        raise ValueError(f"faces must be an (m, k) array or a list of vertex-index lists, "
                         f"got shape {arr.shape}")
    try:
        items = list(faces)
    except TypeError:
        raise TypeError(f"faces must be a list of faces, got a {type(faces).__name__}") from None
    rows = []
    for i, f in enumerate(items):
        a = np.asarray(f) if not isinstance(f, (str, bytes)) else np.asarray([])
        if a.ndim != 1 or (a.size and not _is_int_array(a)):
            raise TypeError(f"face {i} must be a list of integer vertex indices, got {f!r}")
        rows.append(a.astype(np.int64))
    if not rows:
        raise ValueError("faces must contain at least one face, got none")
    sizes = np.array([len(r) for r in rows], dtype=np.int64)
    return np.concatenate(rows), np.concatenate([[0], np.cumsum(sizes)])


def _index(value, count, name, what):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be an integer {what} index, got {value!r}")
    value = int(value)
    if not 0 <= value < count:
        raise ValueError(f"{name} must be a {what} index from 0 to {count - 1}, got {value}")
    return value


def _count(value, name, minimum=0):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name} must be a whole number, got {value!r}")
    if value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return int(value)


def _as_positive(value, name):
    v = as_scalar(value, name)
    if v <= 0:
        raise ValueError(f"{name} must be positive, got {value!r}")
    return v


# ---------------------------------------------------------------------------------------------
# Building the connectivity: one pass over the face list, with clear reports of bad input
# ---------------------------------------------------------------------------------------------

class MeshProblem(NamedTuple):
    """One reason why a face list is not a consistently oriented manifold mesh.

    Attributes
    ----------
    kind : str
        ``"too few vertices"``, ``"missing vertex"``, ``"degenerate face"``,
        ``"non-manifold edge"``, ``"inconsistent winding"`` or ``"non-manifold vertex"``.
    message : str
        A sentence for the student (the text of the ValueError the builders raise).
    vertices : tuple of int
        The vertices involved (the edge's two end points, or the single vertex).
    faces : tuple of int
        The faces involved.

    Examples
    --------
    >>> [p.kind for p in mesh_problems(*bow_tie())]
    ['non-manifold vertex']
    """
    kind: str
    message: str
    vertices: tuple
    faces: tuple


def _corner_links(starts):
    """Face of each corner, and the next / previous corner of the same face."""
    sizes = np.diff(starts)
    face_of = np.repeat(np.arange(len(sizes), dtype=np.int64), sizes)
    first = starts[:-1][face_of]
    local = np.arange(len(face_of), dtype=np.int64) - first
    size = sizes[face_of]
    return face_of, first + (local + 1) % size, first + (local - 1) % size


def _fans(corners, starts, v, corner_order=None):
    """The fans of faces around vertex v (faces connected through edges at v).

    Only for error messages. `corner_order` (``argsort(corners)``, computed once by the caller
    for many vertices) finds the corners at v by binary search instead of a scan.
    """
    if corner_order is None:
        corner_order = np.argsort(corners, kind="stable")
    lo, hi = np.searchsorted(corners[corner_order], [v, v + 1])
    at_v = corner_order[lo:hi]
    faces = sorted(set((np.searchsorted(starts, at_v, side="right") - 1).tolist()))
    parent = {f: f for f in faces}

    def root(f):
        while parent[f] != f:
            f = parent[f]
        return f
    by_neighbour = {}
    for f in faces:
        poly = corners[starts[f]:starts[f + 1]].tolist()
        i = poly.index(v)
        for w in (poly[i - 1], poly[(i + 1) % len(poly)]):
            if w in by_neighbour:
                parent[root(f)] = root(by_neighbour[w])
            else:
                by_neighbour[w] = f
    groups = {}
    for f in faces:
        groups.setdefault(root(f), []).append(f)
    return sorted(groups.values())


def _build(corners, starts, n, collect=False):
    """Half-edge arrays from a flat face table, or the problems that prevent building them.

    Returns ``(problems, arrays)``; `arrays` is None when there are problems. Without `collect`
    the first problem raises ValueError. Every step is a numpy pass (a sort of the edge keys is
    the most expensive one), so the time grows like the sort, O(H log H) for H half-edges.
    """
    problems = []

    def report(kind, message, verts, faces):
        if not collect:
            raise ValueError(message)
        problems.append(MeshProblem(kind, message, tuple(int(v) for v in verts),
                                    tuple(int(f) for f in faces)))

    sizes = np.diff(starts)
    for f in np.flatnonzero(sizes < 3):
        poly = corners[starts[f]:starts[f + 1]].tolist()
        report("too few vertices", f"face {f} has {len(poly)} vertices {poly}; a face needs at "
               "least 3", poly, [f])
    face_of, nxt, prv = _corner_links(starts)
    bad = np.flatnonzero((corners < 0) | (corners >= n))
    for c in bad:
        f = int(face_of[c])
        report("missing vertex", f"face {f} refers to vertex {int(corners[c])}, but there are "
               f"only {n} vertices (indices 0 to {n - 1})", [corners[c]], [f])
    if problems:
        return problems, None
    # a face visiting a vertex twice: sort the corners by (face, vertex), look for neighbours
    order = np.lexsort((corners, face_of))
    sv, sf = corners[order], face_of[order]
    dup = np.flatnonzero((sv[1:] == sv[:-1]) & (sf[1:] == sf[:-1]))
    for i in dup:
        f = int(sf[i])
        poly = corners[starts[f]:starts[f + 1]].tolist()
        report("degenerate face", f"face {f} is degenerate: it visits vertex {int(sv[i])} twice "
               f"{poly}; the vertices of a face must be distinct", [sv[i]], [f])
    if problems:
        return problems, None
    # undirected edge keys (min, max) -> group the half-edges of each edge by one sort
    o, t = corners, corners[nxt]
    key = np.minimum(o, t) * n + np.maximum(o, t)
    order = np.argsort(key, kind="stable")
    sk = key[order]
    gstart = np.flatnonzero(np.r_[True, sk[1:] != sk[:-1]])
    counts = np.diff(np.r_[gstart, len(sk)])
    for g in np.flatnonzero(counts > 2):
        hs = order[gstart[g]:gstart[g] + counts[g]]
        a, b = int(sk[gstart[g]] // n), int(sk[gstart[g]] % n)
        fs = sorted(face_of[hs].tolist())
        report("non-manifold edge", f"edge ({a}, {b}) is shared by {len(fs)} faces {fs}: a "
               "non-manifold edge (on a manifold surface an edge has one face on each side, two "
               "at most)", [a, b], fs)
    pairs = np.flatnonzero(counts == 2)
    ha, hb = order[gstart[pairs]], order[gstart[pairs] + 1]
    for i in np.flatnonzero(o[ha] == o[hb]):
        fa, fb = sorted((int(face_of[ha[i]]), int(face_of[hb[i]])))
        report("inconsistent winding", f"faces {fa} and {fb} both run along the edge "
               f"{int(o[ha[i]])} -> {int(t[ha[i]])} in the same direction: inconsistent winding "
               f"(orientation); reverse the vertex order of one of them",
               [o[ha[i]], t[ha[i]]], [fa, fb])
    if problems:
        return problems, None
    # twins: paired half-edges, and a new boundary half-edge for each unpaired one
    h0 = len(corners)
    single = order[gstart[counts == 1]]
    nb = len(single)
    bidx = np.arange(h0, h0 + nb, dtype=np.int64)
    twin = np.empty(h0 + nb, dtype=np.int64)
    twin[ha], twin[hb] = hb, ha
    twin[single], twin[bidx] = bidx, single
    border_origin = t[single]                 # the boundary half-edge runs target -> origin
    origin = np.concatenate([o, border_origin])
    face = np.concatenate([face_of, np.full(nb, -1, dtype=np.int64)])
    out_count = np.bincount(border_origin, minlength=n)
    corner_order = np.argsort(corners, kind="stable") if (out_count > 1).any() else None
    for v in np.flatnonzero(out_count > 1):
        fans = _fans(corners, starts, int(v), corner_order)
        report("non-manifold vertex", f"vertex {v} is non-manifold (a bow tie): the faces around "
               f"it form {len(fans)} separate fans {fans} that meet only at this vertex",
               [v], [f for fan in fans for f in fan])
    if problems:
        return problems, None
    out_border = np.full(n, -1, dtype=np.int64)
    out_border[border_origin] = bidx
    nxt_all = np.concatenate([nxt, out_border[o[single]]])
    prv_all = np.concatenate([prv, np.empty(nb, dtype=np.int64)])
    prv_all[nxt_all[bidx]] = bidx
    # one fan per vertex: the orbits of h -> twin(prev(h)) (a turn around the origin) must be
    # one per vertex. Label each half-edge with the smallest half-edge of its orbit by doubling.
    rot = twin[prv_all]
    label = np.arange(h0 + nb, dtype=np.int64)
    step = rot
    while True:
        new = np.minimum(label, label[step])
        if np.array_equal(new, label):
            break
        label, step = new, step[step]
    smallest = np.full(n, h0 + nb, dtype=np.int64)
    np.minimum.at(smallest, origin, label)
    for v in np.unique(origin[label != smallest[origin]]):
        fans = _fans(corners, starts, int(v))
        report("non-manifold vertex", f"vertex {v} is non-manifold: the faces around it form "
               f"{len(fans)} separate closed fans {fans} that meet only at this vertex",
               [v], [f for fan in fans for f in fan])
    if problems:
        return problems, None
    vertex_half_edge = np.full(n, h0, dtype=np.int64)
    np.minimum.at(vertex_half_edge, o, np.arange(h0))          # the first outgoing one ...
    vertex_half_edge[vertex_half_edge == h0] = -1               # (-1: no face uses it)
    vertex_half_edge[border_origin] = bidx                      # ... or the boundary one
    return [], (origin, twin, nxt_all, prv_all, face, vertex_half_edge, starts[:-1].copy(),
                sizes)


def mesh_problems(vertices, faces):
    """Everything that keeps a face list from being a consistently oriented manifold mesh.

    The builders :meth:`HalfEdgeMesh.from_faces` and :meth:`WingedEdgeMesh.from_faces` raise a
    ValueError with the first of these messages; this function lists them all instead, for a
    notebook that wants to show what is wrong. The checks run in stages (face sizes and indices,
    repeated vertices, edges, winding, vertex fans); a stage runs only when the earlier ones
    found nothing, because e.g. a vertex fan is not defined around a non-manifold edge.

    Degenerate faces: a face that repeats a vertex index is reported. A face with distinct
    vertices but zero area (collinear points) is *accepted*: connectivity is topology, and the
    half-edge structure is well defined for it. Use :func:`face_areas` to find such faces.

    Parameters
    ----------
    vertices : array_like, shape (n, 3), or int
        The points, or just their number.
    faces : (m, k) int array or list of int lists

    Returns
    -------
    list of MeshProblem
        Empty for a good mesh.

    Examples
    --------
    >>> mesh_problems(*tetrahedron())
    []
    >>> print(mesh_problems(*three_faces_on_an_edge())[0].message)
    edge (0, 1) is shared by 3 faces [0, 1, 2]: a non-manifold edge (on a manifold surface an edge has one face on each side, two at most)
    >>> print(mesh_problems(4, [[0, 1, 2], [0, 1, 3]])[0].message)
    faces 0 and 1 both run along the edge 0 -> 1 in the same direction: inconsistent winding (orientation); reverse the vertex order of one of them
    """
    if isinstance(vertices, numbers.Integral) and not isinstance(vertices, bool):
        n = _count(vertices, "vertices")
    else:
        n = len(_vertices(vertices))
    corners, starts = _face_table(faces)
    return _build(corners, starts, n, collect=True)[0]


# ---------------------------------------------------------------------------------------------
# Topology shared by both structures: Euler characteristic, genus, components
# ---------------------------------------------------------------------------------------------

def _components(n_nodes, pairs):
    """Connected-component labels (0..k-1, ordered by smallest member) of a graph, vectorized.

    Union-find by "hooking" roots onto smaller roots and pointer jumping (Shiloach-Vishkin).
    """
    parent = np.arange(n_nodes, dtype=np.int64)
    if len(pairs):
        u, v = pairs[:, 0], pairs[:, 1]
        while True:
            pu, pv = parent[u], parent[v]
            differ = pu != pv
            if not differ.any():
                break
            np.minimum.at(parent, np.maximum(pu, pv)[differ], np.minimum(pu, pv)[differ])
            while True:                               # jump until every node points at a root
                up = parent[parent]
                if np.array_equal(up, parent):
                    break
                parent = up
    return np.unique(parent, return_inverse=True)[1].astype(np.int64)


class _Topology:
    """Counts and invariants computed from the tables of either structure."""

    def _vertex_face_pairs(self):                     # (vertices, faces) of all corners
        raise NotImplementedError

    def _adjacent_faces(self):                        # (k, 2) faces sharing an interior edge
        raise NotImplementedError

    @property
    def n_vertices(self):
        """Number of vertices used by some face (unused points are not part of the surface)."""
        return int(np.count_nonzero(self._vertex_anchor() >= 0))

    @property
    def n_faces(self):
        return len(self._face_anchor())

    def euler_characteristic(self):
        r"""The Euler characteristic :math:`\chi = V - E + F`.

        Only vertices used by a face count. For a connected orientable surface of genus
        :math:`g` with :math:`b` boundary loops, :math:`\chi = 2 - 2g - b` (Euler-Poincare).

        Examples
        --------
        >>> [HalfEdgeMesh.from_faces(*m).euler_characteristic()
        ...  for m in (cube(), torus(), double_torus(), disc())]
        [2, 0, -2, 1]
        """
        return self.n_vertices - self.n_edges + self.n_faces

    def is_closed(self):
        """True when every edge has two faces (no boundary): the mesh is watertight.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*cube()).is_closed(), HalfEdgeMesh.from_faces(*disc()).is_closed()
        (True, False)
        """
        return len(self.boundary_loops()) == 0

    def is_manifold(self):
        """True: the builders accept only manifold, consistently oriented meshes.

        A manifold mesh is what these structures can represent at all (an edge with three faces
        has no single twin, a bow-tie vertex no single ring), so the builder checks it and
        raises a ValueError naming the problem; use :func:`mesh_problems` to test a face list
        without building. The method is here so that a notebook can ask the question.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*torus()).is_manifold()
        True
        """
        return True

    def boundary_components(self):
        """The number of boundary loops (holes).

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*disc()).boundary_components()
        1
        """
        return len(self.boundary_loops())

    def _face_components(self):
        return _components(self.n_faces, self._adjacent_faces())

    def connected_components(self):
        """The faces of each connected component (faces connected through shared edges).

        On a manifold mesh, faces that share a vertex are connected through edges around it, so
        this is also connectivity through vertices.

        Returns
        -------
        list of ndarray of int
            Face indices of each component, ordered by their smallest face index.

        Examples
        --------
        >>> v, f = tetrahedron()
        >>> two = HalfEdgeMesh.from_faces(np.vstack([v, v + 3]), np.vstack([f, f + 4]))
        >>> [c.tolist() for c in two.connected_components()]
        [[0, 1, 2, 3], [4, 5, 6, 7]]
        """
        labels = self._face_components()
        order = np.argsort(labels, kind="stable")
        cuts = np.flatnonzero(np.diff(labels[order])) + 1
        return np.split(order, cuts)

    def genus(self, per_component=False):
        r"""The genus (number of handles), from :math:`\chi = 2 - 2g - b` per component.

        For each connected component, :math:`g = (2 - \chi - b) / 2` with its own
        :math:`\chi = V - E + F` and boundary-loop count :math:`b`. For a closed component this
        is :math:`\chi = 2 - 2g`. The meshes built here are consistently oriented, hence
        orientable, so the formula applies.

        Parameters
        ----------
        per_component : bool, optional
            Return one genus per component (ordered as :meth:`connected_components`) instead of
            their sum.

        Returns
        -------
        int or ndarray of int

        Examples
        --------
        >>> [HalfEdgeMesh.from_faces(*m).genus() for m in (icosphere(1), torus(), double_torus())]
        [0, 1, 2]
        """
        labels = self._face_components()
        k = int(labels.max()) + 1
        verts, faces = self._vertex_face_pairs()
        vertex_comp = np.full(len(self._vertex_anchor()), -1, dtype=np.int64)
        vertex_comp[verts] = labels[faces]
        used = vertex_comp >= 0
        n_v = np.bincount(vertex_comp[used], minlength=k)
        n_e = np.bincount(vertex_comp[self.edges()[:, 0]], minlength=k)
        n_f = np.bincount(labels, minlength=k)
        loops = self.boundary_loops()
        n_b = np.bincount(np.array([vertex_comp[loop[0]] for loop in loops], dtype=np.int64),
                          minlength=k)
        g = (2 - (n_v - n_e + n_f) - n_b) // 2
        return g.astype(np.int64) if per_component else int(g.sum())


# ---------------------------------------------------------------------------------------------
# Half-edge mesh
# ---------------------------------------------------------------------------------------------

def _walk_loops(start_elements, successor):
    """The cycles of `successor` through `start_elements` (each element in one cycle, listed
    once): the boundary loops of a half-edge or winged-edge structure."""
    seen = np.zeros(len(successor), dtype=bool)
    loops = []
    for first in start_elements:
        if seen[first]:
            continue
        loop, k = [], int(first)
        while not seen[k]:
            seen[k] = True
            loop.append(k)
            k = int(successor[k])
        loops.append(loop)
    return loops


class HalfEdgeMesh(_Topology):
    """A polygon mesh as half-edges: every edge split into two directed halves, one per side.

    Build it with :meth:`from_faces`. All connectivity is in integer numpy arrays indexed by
    half-edge ``h`` (``0 <= h < n_half_edges``), vertex ``v`` or face ``f``:

    ========================  ======================================================
    ``origin[h]``             the vertex ``h`` leaves (``target`` is the one it enters)
    ``twin[h]``               the opposite half-edge (same edge, other direction)
    ``next[h]``, ``prev[h]``  the following / preceding half-edge around the same face
    ``face[h]``               the face on the left of ``h``, -1 for a boundary half-edge
    ``vertex_half_edge[v]``   one half-edge leaving ``v``: the boundary one for a boundary
                              vertex, -1 for a vertex no face uses
    ``face_half_edge[f]``     one half-edge of face ``f``
    ========================  ======================================================

    Numbering: the half-edges of the faces come first, in face order: half-edge
    ``face_half_edge[f] + i`` runs from the i-th to the (i+1)-th vertex of face ``f`` as it was
    given. The boundary half-edges follow, each boundary loop being a cycle of ``next``.

    Examples
    --------
    >>> m = HalfEdgeMesh.from_faces(*tetrahedron())
    >>> m.n_vertices, m.n_edges, m.n_faces, m.n_half_edges
    (4, 6, 4, 12)
    >>> h = 0
    >>> int(m.origin[h]), int(m.target[h]), int(m.face[h]), int(m.face[m.twin[h]])
    (0, 1, 0, 1)
    """

    def __init__(self, vertices, origin, twin, next, prev, face, vertex_half_edge,
                 face_half_edge, face_sizes=None):
        self.vertices = vertices
        self.origin, self.twin, self.next, self.prev, self.face = origin, twin, next, prev, face
        self.vertex_half_edge, self.face_half_edge = vertex_half_edge, face_half_edge
        self._face_sizes = face_sizes

    @classmethod
    def from_faces(cls, vertices, faces):
        """Build the half-edge structure of a polygon mesh given as a face list.

        One pass: half-edges are made per face corner, the two halves of each edge are matched
        by sorting the (min, max) vertex keys of all half-edges (no pairwise search), boundary
        half-edges are added for edges with one face and linked into loops through the boundary
        vertices. Time O(H log H) for H half-edges (the sort), all in numpy.

        Parameters
        ----------
        vertices : array_like, shape (n, 3)
        faces : (m, k) int array or list of int lists
            Polygons (any sizes >= 3), counter-clockwise seen from outside.

        Returns
        -------
        HalfEdgeMesh

        Raises
        ------
        ValueError
            For input that is not a consistently oriented manifold mesh, naming the culprit:
            a face with fewer than 3 vertices, an index of a missing vertex, a face repeating a
            vertex, an edge with three or more faces (its two vertices and the faces), two faces
            running along an edge in the same direction (inconsistent winding), a bow-tie vertex
            (two fans of faces meeting at one vertex). See :func:`mesh_problems`.
        TypeError
            For faces that are not integer indices.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*cube())                 # six quads
        HalfEdgeMesh(V=8, E=12, F=6, boundary loops=0)
        >>> HalfEdgeMesh.from_faces(*bow_tie())
        Traceback (most recent call last):
        ...
        ValueError: vertex 0 is non-manifold (a bow tie): the faces around it form 2 separate fans [[0], [1]] that meet only at this vertex
        """
        v = _vertices(vertices)
        corners, starts = _face_table(faces)
        arrays = _build(corners, starts, len(v))[1]
        return cls(v.copy(), *arrays)

    def __repr__(self):
        return (f"HalfEdgeMesh(V={self.n_vertices}, E={self.n_edges}, F={self.n_faces}, "
                f"boundary loops={self.boundary_components()})")

    # sizes and derived arrays ----------------------------------------------------------------

    @property
    def n_half_edges(self):
        """Number of half-edges, boundary ones included: twice the number of edges."""
        return len(self.origin)

    @property
    def n_edges(self):
        return len(self.origin) // 2

    @property
    def target(self):
        """The vertex each half-edge enters: ``origin[next[h]]`` (equally ``origin[twin[h]]``)."""
        return self.origin[self.next]

    def _vertex_anchor(self):
        return self.vertex_half_edge

    def _face_anchor(self):
        return self.face_half_edge

    def _vertex_face_pairs(self):
        inner = self.face >= 0
        return self.origin[inner], self.face[inner]

    def _adjacent_faces(self):
        h = np.flatnonzero((self.face >= 0) & (self.face[self.twin] >= 0))
        h = h[h < self.twin[h]]
        return np.column_stack([self.face[h], self.face[self.twin[h]]])

    def edges(self):
        """The edges as vertex pairs, one row per edge, ``(origin, target)`` of one half-edge.

        The half-edge chosen is the one with a face (the boundary one is never chosen), the
        smaller index when both have faces. Edge ``e`` here is edge ``e`` of the
        :class:`WingedEdgeMesh` built from the same faces.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*tetrahedron()).edges().tolist()
        [[0, 1], [1, 2], [2, 0], [0, 3], [3, 1], [2, 3]]
        """
        h = self._edge_half_edges()
        return np.column_stack([self.origin[h], self.origin[self.next[h]]])

    def _edge_half_edges(self):
        h = np.arange(len(self.origin))
        tw = self.twin
        keep = (self.face >= 0) & ((self.face[tw] < 0) | (h < tw))
        return np.flatnonzero(keep)

    # step functions, for a widget walking the structure ----------------------------------------

    def _h(self, h):
        return _index(h, len(self.origin), "h", "half-edge")

    def opposite(self, h):
        """The twin of half-edge `h`: the same edge walked the other way, on the other face.

        Examples
        --------
        >>> m = HalfEdgeMesh.from_faces(*tetrahedron())
        >>> m.opposite(m.opposite(5)) == 5
        True
        """
        return int(self.twin[self._h(h)])

    def next_half_edge(self, h):
        """The half-edge after `h` around its face (or its boundary loop).

        Examples
        --------
        >>> m = HalfEdgeMesh.from_faces(*tetrahedron())
        >>> [m.next_half_edge(0), m.next_half_edge(1), m.next_half_edge(2)]
        [1, 2, 0]
        """
        return int(self.next[self._h(h)])

    def previous_half_edge(self, h):
        """The half-edge before `h` around its face (or its boundary loop).

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*tetrahedron()).previous_half_edge(0)
        2
        """
        return int(self.prev[self._h(h)])

    def describe(self, h):
        """Everything stored about half-edge `h`, as a dict (for a widget's text panel).

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*tetrahedron()).describe(0)
        {'half_edge': 0, 'origin': 0, 'target': 1, 'face': 0, 'twin': 5, 'next': 1, 'prev': 2}
        """
        h = self._h(h)
        return {"half_edge": h, "origin": int(self.origin[h]),
                "target": int(self.origin[self.next[h]]), "face": int(self.face[h]),
                "twin": int(self.twin[h]), "next": int(self.next[h]), "prev": int(self.prev[h])}

    def find_half_edge(self, u, v):
        """The half-edge from vertex `u` to vertex `v`, or -1 when they are not neighbours.

        Examples
        --------
        >>> m = HalfEdgeMesh.from_faces(*tetrahedron())
        >>> h = m.find_half_edge(1, 0)
        >>> int(m.origin[h]), int(m.target[h])
        (1, 0)
        """
        n = len(self.vertex_half_edge)
        u, v = _index(u, n, "u", "vertex"), _index(v, n, "v", "vertex")
        for h in self.vertex_half_edges(u):
            if self.origin[self.next[h]] == v:
                return h
        return -1

    # traversals --------------------------------------------------------------------------------

    def _v(self, v):
        return _index(v, len(self.vertex_half_edge), "v", "vertex")

    def vertex_half_edges(self, v):
        """The half-edges leaving `v`, counter-clockwise seen from outside.

        One step is ``twin(prev(h))``: ``prev(h)`` enters ``v`` in the face of ``h``, and its
        twin leaves ``v`` along the next edge counter-clockwise. For a boundary vertex the list
        starts just after the boundary gap and ends with the boundary half-edge.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*disc(rings=1, segments=4)).vertex_half_edges(0)
        [0, 3, 6, 9]
        """
        h0 = int(self.vertex_half_edge[self._v(v)])
        if h0 < 0:
            return []
        if self.face[h0] < 0:
            h0 = int(self.twin[self.prev[h0]])
        out, h = [], h0
        for _ in range(len(self.origin)):
            out.append(h)
            h = int(self.twin[self.prev[h]])
            if h == h0:
                return out
        raise RuntimeError(f"the half-edges around vertex {v} do not form a cycle: the "
                           "structure is corrupt")

    def vertex_one_ring(self, v):
        """The neighbours of vertex `v`, counter-clockwise seen from outside.

        For an interior vertex the list is a cycle (the first follows the last). For a
        boundary vertex it is open: it starts and ends with the two boundary neighbours, and
        consecutive entries share a face.

        Examples
        --------
        The centre of a disc sees its ring counter-clockwise (the disc faces +z):

        >>> HalfEdgeMesh.from_faces(*disc(rings=1, segments=6)).vertex_one_ring(0)
        [1, 2, 3, 4, 5, 6]
        >>> HalfEdgeMesh.from_faces(*disc(rings=1, segments=6)).vertex_one_ring(1)
        [2, 0, 6]
        """
        return [int(self.origin[self.next[h]]) for h in self.vertex_half_edges(v)]

    def vertex_faces(self, v):
        """The faces around vertex `v`, counter-clockwise seen from outside.

        Face ``k`` lies between neighbours ``k`` and ``k + 1`` of :meth:`vertex_one_ring`.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*disc(rings=1, segments=6)).vertex_faces(1)
        [0, 5]
        """
        return [int(self.face[h]) for h in self.vertex_half_edges(v) if self.face[h] >= 0]

    def is_boundary_vertex(self, v):
        """True when vertex `v` lies on a boundary (its stored half-edge has no face)."""
        h = self.vertex_half_edge[self._v(v)]
        return bool(h >= 0 and self.face[h] < 0)

    def boundary_vertices(self):
        """Boolean mask of the boundary vertices, shape (n,)."""
        h = self.vertex_half_edge
        return (h >= 0) & (self.face[np.maximum(h, 0)] < 0)

    def face_half_edges(self, f):
        """The half-edges of face `f` in its (counter-clockwise) order, following ``next``.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*cube()).face_half_edges(1)
        [4, 5, 6, 7]
        """
        h0 = int(self.face_half_edge[_index(f, len(self.face_half_edge), "f", "face")])
        out, h = [], h0
        for _ in range(len(self.origin)):
            out.append(h)
            h = int(self.next[h])
            if h == h0:
                return out
        raise RuntimeError(f"the half-edges of face {f} do not form a cycle: the structure is "
                           "corrupt")

    def face_vertices(self, f):
        """The vertices of face `f`, counter-clockwise (the origins of its half-edges).

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*cube()).face_vertices(1)
        [4, 5, 7, 6]
        """
        return [int(self.origin[h]) for h in self.face_half_edges(f)]

    def face_neighbors(self, f):
        """The faces across the edges of face `f` (-1 across a boundary edge), in order.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*cube()).face_neighbors(1)
        [2, 5, 3, 4]
        """
        return [int(self.face[self.twin[h]]) for h in self.face_half_edges(f)]

    def edge_faces(self, h):
        """The two faces of the edge of half-edge `h`: ``(face(h), face(twin(h)))``; -1 = none.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*tetrahedron()).edge_faces(0)
        (0, 1)
        """
        h = self._h(h)
        return int(self.face[h]), int(self.face[self.twin[h]])

    def boundary_loops(self, half_edges=False):
        """The boundary loops, each a list of vertices (or boundary half-edges) along ``next``.

        The boundary half-edges run opposite to the faces beside them: the outer rim of a disc
        whose normal is +z comes out clockwise seen from +z.

        Parameters
        ----------
        half_edges : bool, optional
            List the boundary half-edges instead of their origin vertices.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*disc(rings=1, segments=6)).boundary_loops()
        [[2, 1, 6, 5, 4, 3]]
        """
        loops = _walk_loops(np.flatnonzero(self.face < 0), self.next)
        return loops if half_edges else [[int(self.origin[h]) for h in loop] for loop in loops]

    def to_faces(self):
        """The face list again, read from the structure by walking ``next`` around each face.

        Returns
        -------
        ndarray, shape (m, k), when all faces have k vertices; else a list of int lists.
        Each face starts at its ``face_half_edge``, so it equals the input face, same rotation.

        Examples
        --------
        >>> HalfEdgeMesh.from_faces(*tetrahedron()).to_faces().tolist()
        [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
        """
        sizes = self._face_sizes
        if sizes is not None and len(sizes) and (sizes == sizes[0]).all():
            h = self.face_half_edge.copy()
            out = np.empty((len(h), int(sizes[0])), dtype=np.int64)
            for i in range(int(sizes[0])):
                out[:, i] = self.origin[h]
                h = self.next[h]
            if np.array_equal(h, self.face_half_edge):
                return out
        return [self.face_vertices(f) for f in range(len(self.face_half_edge))]


# ---------------------------------------------------------------------------------------------
# Winged-edge mesh
# ---------------------------------------------------------------------------------------------

class WingedEdgeMesh(_Topology):
    """A polygon mesh as winged edges: one record per (undirected) edge.

    Build it with :meth:`from_faces`. Edge ``e`` runs from ``start[e]`` to ``end[e]``; the
    **left** face is the one that walks the edge from start to end (with counter-clockwise
    faces the face lies to the left of that direction), the **right** face walks it from end to
    start. The four wings are the neighbouring edges in those walks:

    ==============================  ============================================================
    ``start[e]``, ``end[e]``        the two vertices
    ``left_face[e]``                face walking start -> end (never -1)
    ``right_face[e]``               face walking end -> start, -1 for a boundary edge
    ``left_prev[e]``, ``left_next[e]``    the edges before / after ``e`` around the left face
    ``right_prev[e]``, ``right_next[e]``  the edges before / after ``e`` around the right face,
                                          for a boundary edge around its boundary loop
    ``vertex_edge[v]``              one edge at ``v`` (a boundary edge for a boundary vertex)
    ``face_edge[f]``                one edge of ``f``
    ==============================  ============================================================

    :meth:`records` gives the table as one dict per edge.

    Examples
    --------
    >>> w = WingedEdgeMesh.from_faces(*tetrahedron())
    >>> w.records()[0]
    {'edge': 0, 'start': 0, 'end': 1, 'left_face': 0, 'right_face': 1, 'left_prev': 2, 'left_next': 1, 'right_prev': 4, 'right_next': 3}
    """

    FIELDS = ("start", "end", "left_face", "right_face", "left_prev", "left_next", "right_prev",
              "right_next")

    def __init__(self, vertices, start, end, left_face, right_face, left_prev, left_next,
                 right_prev, right_next, vertex_edge, face_edge):
        self.vertices = vertices
        self.start, self.end = start, end
        self.left_face, self.right_face = left_face, right_face
        self.left_prev, self.left_next = left_prev, left_next
        self.right_prev, self.right_next = right_prev, right_next
        self.vertex_edge, self.face_edge = vertex_edge, face_edge

    @classmethod
    def from_faces(cls, vertices, faces):
        """Build the winged-edge table of a polygon mesh given as a face list.

        Same checks, same errors and the same O(H log H) time as
        :meth:`HalfEdgeMesh.from_faces` (it matches the edges the same way); each edge record
        is then read off its two half-edges.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*cube())
        WingedEdgeMesh(V=8, E=12, F=6, boundary loops=0)
        """
        return cls.from_half_edges(HalfEdgeMesh.from_faces(vertices, faces))

    @classmethod
    def from_half_edges(cls, mesh):
        """The winged-edge table of a :class:`HalfEdgeMesh` (edge e = row e of its ``edges()``).

        Examples
        --------
        >>> WingedEdgeMesh.from_half_edges(HalfEdgeMesh.from_faces(*disc())).n_edges
        176
        """
        rep = mesh._edge_half_edges()
        opp = mesh.twin[rep]
        edge_of = np.empty(len(mesh.origin), dtype=np.int64)
        edge_of[rep] = np.arange(len(rep))
        edge_of[opp] = np.arange(len(rep))
        vh = mesh.vertex_half_edge
        return cls(mesh.vertices, mesh.origin[rep], mesh.origin[opp], mesh.face[rep],
                   mesh.face[opp], edge_of[mesh.prev[rep]], edge_of[mesh.next[rep]],
                   edge_of[mesh.prev[opp]], edge_of[mesh.next[opp]],
                   np.where(vh >= 0, edge_of[np.maximum(vh, 0)], -1),
                   edge_of[mesh.face_half_edge])

    def __repr__(self):
        return (f"WingedEdgeMesh(V={self.n_vertices}, E={self.n_edges}, F={self.n_faces}, "
                f"boundary loops={self.boundary_components()})")

    def records(self):
        """The edge table, one dict per edge (keys ``edge`` and :attr:`FIELDS`).

        Examples
        --------
        >>> import pprint
        >>> pprint.pprint(WingedEdgeMesh.from_faces(*disc(rings=1, segments=3)).records()[:2],
        ...               sort_dicts=False)
        [{'edge': 0,
          'start': 0,
          'end': 1,
          'left_face': 0,
          'right_face': 2,
          'left_prev': 2,
          'left_next': 1,
          'right_prev': 5,
          'right_next': 4},
         {'edge': 1,
          'start': 1,
          'end': 2,
          'left_face': 0,
          'right_face': -1,
          'left_prev': 0,
          'left_next': 2,
          'right_prev': 3,
          'right_next': 5}]
        """
        cols = [getattr(self, name).tolist() for name in self.FIELDS]
        return [{"edge": e, **dict(zip(self.FIELDS, row))} for e, row in enumerate(zip(*cols))]

    @property
    def n_edges(self):
        return len(self.start)

    def _vertex_anchor(self):
        return self.vertex_edge

    def _face_anchor(self):
        return self.face_edge

    def _vertex_face_pairs(self):
        inner = self.right_face >= 0
        return (np.concatenate([self.start, self.end[inner]]),
                np.concatenate([self.left_face, self.right_face[inner]]))

    def _adjacent_faces(self):
        inner = self.right_face >= 0
        return np.column_stack([self.left_face[inner], self.right_face[inner]])

    def edges(self):
        """The edges as ``(start, end)`` vertex pairs, shape (E, 2)."""
        return np.column_stack([self.start, self.end])

    def find_edge(self, u, v):
        """The edge joining vertices `u` and `v` (either direction), or -1.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*tetrahedron()).find_edge(1, 0)
        0
        """
        n = len(self.vertex_edge)
        u, v = _index(u, n, "u", "vertex"), _index(v, n, "v", "vertex")
        for e in self.vertex_edges(u):
            if (self.end[e] if self.start[e] == u else self.start[e]) == v:
                return e
        return -1

    # traversals, with the left/right case analysis of the winged-edge structure ----------------

    def _turn(self, v, e):
        """From edge e at v, one step counter-clockwise around v: (next edge, face in between).

        Walking away from v along e, the face on our left is the one to cross next: the left
        face when v is the start of e, the right face when v is its end. The next edge is the
        one before e around that face (it enters v).
        """
        if self.start[e] == v:
            return int(self.left_prev[e]), int(self.left_face[e])
        return int(self.right_prev[e]), int(self.right_face[e])

    def vertex_edges(self, v):
        """The edges at vertex `v`, counter-clockwise seen from outside.

        For a boundary vertex the list starts just after the boundary gap and ends with the
        boundary edge whose right side (the hole) follows; compare
        :meth:`HalfEdgeMesh.vertex_half_edges`.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*disc(rings=1, segments=4)).vertex_edges(0)
        [0, 2, 4, 6]
        """
        v = _index(v, len(self.vertex_edge), "v", "vertex")
        e0 = int(self.vertex_edge[v])
        if e0 < 0:
            return []
        nxt, f = self._turn(v, e0)
        if f < 0:                                   # the gap follows e0: start after it
            e0 = nxt
        out, e = [], e0
        for _ in range(2 * len(self.start)):
            out.append(e)
            e = self._turn(v, e)[0]
            if e == e0:
                return out
        raise RuntimeError(f"the edges around vertex {v} do not form a cycle: the table is "
                           "corrupt")

    def vertex_one_ring(self, v):
        """The neighbours of vertex `v`, counter-clockwise (as :meth:`HalfEdgeMesh.vertex_one_ring`).

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*disc(rings=1, segments=6)).vertex_one_ring(1)
        [2, 0, 6]
        """
        return [int(self.end[e] if self.start[e] == v else self.start[e])
                for e in self.vertex_edges(v)]

    def vertex_faces(self, v):
        """The faces around vertex `v`, counter-clockwise (as :meth:`HalfEdgeMesh.vertex_faces`).

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*disc(rings=1, segments=6)).vertex_faces(0)
        [0, 1, 2, 3, 4, 5]
        """
        faces = [self._turn(v, e)[1] for e in self.vertex_edges(v)]
        return [f for f in faces if f >= 0]

    def is_boundary_vertex(self, v):
        """True when vertex `v` lies on a boundary."""
        e = self.vertex_edge[_index(v, len(self.vertex_edge), "v", "vertex")]
        return bool(e >= 0 and self.right_face[e] < 0)

    def boundary_vertices(self):
        """Boolean mask of the boundary vertices, shape (n,)."""
        e = self.vertex_edge
        return (e >= 0) & (self.right_face[np.maximum(e, 0)] < 0)

    def face_edges(self, f):
        """The edges of face `f` in its counter-clockwise order.

        At each edge: if ``f`` is its left face, go on with ``left_next``, else with
        ``right_next``.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*tetrahedron()).face_edges(1)
        [3, 4, 0]
        """
        f = _index(f, len(self.face_edge), "f", "face")
        e0 = int(self.face_edge[f])
        out, e = [], e0
        for _ in range(len(self.start)):
            out.append(e)
            e = int(self.left_next[e] if self.left_face[e] == f else self.right_next[e])
            if e == e0:
                return out
        raise RuntimeError(f"the edges of face {f} do not form a cycle: the table is corrupt")

    def face_vertices(self, f):
        """The vertices of face `f`, counter-clockwise: where the face's walk enters each edge.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*tetrahedron()).face_vertices(1)
        [0, 3, 1]
        """
        return [int(self.start[e] if self.left_face[e] == f else self.end[e])
                for e in self.face_edges(f)]

    def face_neighbors(self, f):
        """The faces across the edges of face `f` (-1 across a boundary edge), in order."""
        return [int(self.right_face[e] if self.left_face[e] == f else self.left_face[e])
                for e in self.face_edges(f)]

    def edge_faces(self, e):
        """The two faces of edge `e`: ``(left_face, right_face)``, -1 for a missing one.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*tetrahedron()).edge_faces(0)
        (0, 1)
        """
        e = _index(e, len(self.start), "e", "edge")
        return int(self.left_face[e]), int(self.right_face[e])

    def boundary_loops(self, edges=False):
        """The boundary loops as vertex lists (or edge lists), following ``right_next``.

        A boundary edge has its face on the left and the hole on the right; the right side of
        the edge is walked end -> start, so the loop lists ``end[e]`` of each edge: the same
        loops, in the same direction, as :meth:`HalfEdgeMesh.boundary_loops`.

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*disc(rings=1, segments=6)).boundary_loops()
        [[2, 1, 6, 5, 4, 3]]
        """
        loops = _walk_loops(np.flatnonzero(self.right_face < 0), self.right_next)
        return loops if edges else [[int(self.end[e]) for e in loop] for loop in loops]

    def to_faces(self):
        """The face list again, walking each face's edges (list of lists; array if all same size).

        Examples
        --------
        >>> WingedEdgeMesh.from_faces(*tetrahedron()).to_faces().tolist()
        [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
        """
        faces = [self.face_vertices(f) for f in range(len(self.face_edge))]
        if len({len(f) for f in faces}) == 1:
            return np.array(faces, dtype=np.int64)
        return faces


# ---------------------------------------------------------------------------------------------
# Procedural meshes
# ---------------------------------------------------------------------------------------------

def tetrahedron():
    """A regular tetrahedron inscribed in the unit sphere: 4 vertices, 4 outward triangles.

    Examples
    --------
    >>> v, f = tetrahedron()
    >>> v.shape, f.tolist()
    ((4, 3), [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    """
    v = np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float) / np.sqrt(3)
    return v, np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]], dtype=np.int64)


def cube(triangulated=False):
    """The cube [-1, 1]^3: 8 vertices and 6 outward quads (or 12 triangles).

    Vertex ``i`` has coordinates ``x = +1`` if bit 0 of ``i`` is set, ``y`` from bit 1, ``z``
    from bit 2 (else -1).

    Parameters
    ----------
    triangulated : bool, optional
        Split each quad ``(a, b, c, d)`` into ``(a, b, c)`` and ``(a, c, d)``.

    Returns
    -------
    vertices : ndarray, shape (8, 3)
    faces : ndarray of int, shape (6, 4) or (12, 3)
        Counter-clockwise seen from outside.

    Examples
    --------
    >>> v, f = cube()
    >>> f.tolist()
    [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    >>> cube(triangulated=True)[1].shape
    (12, 3)
    """
    i = np.arange(8)
    v = np.column_stack([i & 1, (i >> 1) & 1, (i >> 2) & 1]).astype(float) * 2 - 1
    quads = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2],
                      [1, 3, 7, 5]], dtype=np.int64)
    return v, (_split_quads(quads) if triangulated else quads)


def _split_quads(quads):
    """Each quad (a, b, c, d) -> triangles (a, b, c), (a, c, d), kept together per quad."""
    return np.stack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]], axis=1).reshape(-1, 3)


def _midpoint_subdivide(v, f):
    """Split each triangle into four at its edge midpoints (shared midpoints made once)."""
    e = np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]])
    keys = np.sort(e, axis=1)
    unique, inverse = np.unique(keys, axis=0, return_inverse=True)
    mid = (len(v) + inverse.ravel()).reshape(3, -1)
    ab, bc, ca = mid
    a, b, c = f.T
    faces = np.stack([np.stack([a, ab, ca], -1), np.stack([b, bc, ab], -1),
                      np.stack([c, ca, bc], -1), np.stack([ab, bc, ca], -1)], axis=1)
    return np.vstack([v, v[unique].mean(axis=1)]), faces.reshape(-1, 3)


def icosphere(subdivisions=0, radius=1.0):
    """A sphere meshed by subdividing an icosahedron: 20 * 4**subdivisions outward triangles.

    Each step splits every triangle into four at its edge midpoints and pushes the new vertices
    onto the sphere. ``subdivisions=6`` gives 81,920 faces and 40,962 vertices.

    Parameters
    ----------
    subdivisions : int, optional
        0 is the icosahedron itself.
    radius : float, optional

    Returns
    -------
    vertices : ndarray, shape (10 * 4**s + 2, 3)
    faces : ndarray of int, shape (20 * 4**s, 3)

    Examples
    --------
    >>> [icosphere(s)[1].shape[0] for s in range(3)]
    [20, 80, 320]
    """
    s = _count(subdivisions, "subdivisions")
    if s > 8:
        raise ValueError(f"subdivisions must be at most 8 (20 * 4**8 = 1,310,720 faces), got {s}")
    r = _as_positive(radius, "radius")
    t = (1 + np.sqrt(5)) / 2
    v = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t],
                  [0, -1, -t], [0, 1, -t], [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]])
    f = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9],
                  [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2],
                  [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11], [6, 2, 10],
                  [8, 6, 7], [9, 8, 1]], dtype=np.int64)
    for _ in range(s):
        v, f = _midpoint_subdivide(v, f)
    return r * v / np.linalg.norm(v, axis=1, keepdims=True), f


def torus(major=1.0, minor=0.4, segments=24, rings=12):
    """A closed torus (genus 1) around the z axis: see :func:`course_lib.shapes.torus`.

    Examples
    --------
    >>> HalfEdgeMesh.from_faces(*torus()).genus()
    1
    """
    return shapes.torus(_as_positive(major, "major"), _as_positive(minor, "minor"),
                        _count(segments, "segments", 3), _count(rings, "rings", 3))


def double_torus(major=1.0, minor=0.4, segments=24, rings=12, gap=None):
    r"""A closed double torus (genus 2, :math:`\chi = -2`): two tori joined by a short tube.

    Torus A (centre :math:`(-d, 0, 0)`) loses a rectangular patch of its grid on the outer
    equator facing +x; torus B is A turned by 180 degrees about the z axis (a rotation, so the
    orientation is kept), with its hole facing -x. A tube of triangles joins the two hole rims
    point by point (the grid point at angle :math:`u` on A to the one at :math:`-u` on B, the
    mirror image across the plane x = 0). Cutting a disc out of a surface lowers
    :math:`\chi` by 1 (the disc's :math:`\chi = 1`; its rim, a circle, has :math:`\chi = 0`),
    and gluing in a tube (an annulus, :math:`\chi = 0`) along two circles changes nothing, so
    :math:`\chi = (0 - 1) + (0 - 1) + 0 = -2`: genus 2.

    Parameters
    ----------
    major, minor : float, optional
        Radii of each torus.
    segments, rings : int, optional
        Grid of each torus (at least 6 and 4).
    gap : float, optional
        The distance between the two tori, ``minor / 2`` by default.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    faces : ndarray of int, shape (m, 3)
        Outward triangles.

    Examples
    --------
    >>> m = HalfEdgeMesh.from_faces(*double_torus())
    >>> m.euler_characteristic(), m.genus(), m.is_closed()
    (-2, 2, True)
    """
    major, minor = _as_positive(major, "major"), _as_positive(minor, "minor")
    s, r = _count(segments, "segments", 6), _count(rings, "rings", 4)
    gap = minor / 2 if gap is None else _as_positive(gap, "gap")
    if minor >= major:
        raise ValueError(f"minor must be smaller than major (a ring torus), got {minor} >= {major}")
    v, f = shapes.torus(major, minor, s, r)
    d = major + minor + gap / 2
    hs, hr = max(1, s // 12), max(1, r // 12)
    # the cells of the hole: grid cells (i, j) with i in [-hs, hs), j in [-hr, hr) (mod s, r)
    cell = np.arange(s * r)
    ci, cj = cell // r, cell % r
    hole = (((ci + hs) % s) < 2 * hs) & (((cj + hr) % r) < 2 * hr)
    keep = np.concatenate([~hole, ~hole])           # torus faces: [a, b, c] block, [a, c, d]
    f = f[keep]
    rim = ([(i, -hr) for i in range(-hs, hs)] + [(hs, j) for j in range(-hr, hr)] +
           [(i, hr) for i in range(hs, -hs, -1)] + [(-hs, j) for j in range(hr, -hr, -1)])
    loop_a = np.array([(i % s) * r + j % r for i, j in rim])
    loop_b = np.array([(-i % s) * r + j % r for i, j in rim]) + s * r
    va = v + [-d, 0, 0]
    vb = va * [-1, -1, 1]
    n_tube = 2
    rings_v = [va[loop_a] + (vb[loop_b - s * r] - va[loop_a]) * (k / (n_tube + 1))
               for k in range(1, n_tube + 1)]
    base = 2 * s * r
    ids = [loop_a] + [base + k * len(rim) + np.arange(len(rim)) for k in range(n_tube)] + [loop_b]
    # orient the tube against A's faces along the rim: A must not walk loop_a[0] -> loop_a[1]
    a0, a1 = loop_a[0], loop_a[1]
    walks = ((f == a0) & (np.roll(f, -1, axis=1) == a1)).any()
    quads = []
    for k in range(n_tube + 1):
        p, q = ids[k], ids[k + 1]
        quads.append(np.column_stack([p, np.roll(p, -1), np.roll(q, -1), q]))
    quads = np.vstack(quads)
    if walks:
        quads = quads[:, ::-1]
    faces = np.vstack([f, f + s * r, _split_quads(quads)])
    return _compact(np.vstack([va, vb, *rings_v]), faces)    # drop the grid points of the holes


def disc(rings=4, segments=16, radius=1.0):
    """A flat disc in the plane z = 0 (one boundary loop), triangles facing +z.

    Vertex 0 is the centre; ring ``k = 1..rings`` (radius ``k / rings * radius``) holds the
    vertices ``1 + (k - 1) * segments + i`` at angles ``2 pi i / segments``. The first
    ``segments`` faces are the fan around the centre, face ``i`` being
    ``(0, 1 + i, 1 + (i + 1) % segments)``.

    Returns
    -------
    vertices : ndarray, shape (1 + rings * segments, 3)
    faces : ndarray of int, shape ((2 * rings - 1) * segments, 3)

    Examples
    --------
    >>> v, f = disc(rings=1, segments=4)
    >>> f.tolist()
    [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    >>> m = HalfEdgeMesh.from_faces(*disc())
    >>> m.euler_characteristic(), m.boundary_components()
    (1, 1)
    """
    k, s = _count(rings, "rings", 1), _count(segments, "segments", 3)
    rad = _as_positive(radius, "radius")
    angle = 2 * np.pi * np.arange(s) / s
    radii = rad * np.arange(1, k + 1) / k
    ring_pts = np.stack([radii[:, None] * np.cos(angle), radii[:, None] * np.sin(angle),
                         np.zeros((k, s))], axis=-1).reshape(-1, 3)
    v = np.vstack([[0.0, 0.0, 0.0], ring_pts])
    i = np.arange(s)
    faces = [np.column_stack([np.zeros(s, dtype=np.int64), 1 + i, 1 + (i + 1) % s])]
    for ring in range(k - 1):
        a = 1 + ring * s + i
        b = 1 + ring * s + (i + 1) % s
        c, d = b + s, a + s
        faces.append(np.column_stack([a, d, c]))
        faces.append(np.column_stack([a, c, b]))
    return v, np.vstack(faces).astype(np.int64)


def three_faces_on_an_edge():
    """Three triangles sharing the edge (0, 1), like the pages of a book: a non-manifold edge.

    Examples
    --------
    >>> HalfEdgeMesh.from_faces(*three_faces_on_an_edge())
    Traceback (most recent call last):
    ...
    ValueError: edge (0, 1) is shared by 3 faces [0, 1, 2]: a non-manifold edge (on a manifold surface an edge has one face on each side, two at most)
    """
    v = np.array([[0, 0, 0], [1, 0, 0], [0.5, 1, 0], [0.5, -0.5, 0.87], [0.5, -0.5, -0.87]])
    return v, np.array([[0, 1, 2], [1, 0, 3], [1, 0, 4]], dtype=np.int64)


def bow_tie():
    """Two triangles that share only vertex 0: a bow tie, the classic non-manifold vertex.

    Examples
    --------
    >>> [p.vertices for p in mesh_problems(*bow_tie())]
    [(0,)]
    """
    v = np.array([[0, 0, 0], [1, -0.5, 0], [1, 0.5, 0], [-1, 0.5, 0], [-1, -0.5, 0]])
    return v, np.array([[0, 1, 2], [0, 3, 4]], dtype=np.int64)


# ---------------------------------------------------------------------------------------------
# Normals, areas, planes and quadrics
# ---------------------------------------------------------------------------------------------

def _area_vectors(vertices, faces):
    """Half the sum of p_i x p_(i+1) around each face (Newell): normal * area."""
    v = _vertices(vertices)
    corners, starts = _face_table(faces)
    if corners.min() < 0 or corners.max() >= len(v):
        bad = int(corners.max() if corners.max() >= len(v) else corners.min())
        raise ValueError(f"faces refers to vertex {bad}, but there are only {len(v)} vertices")
    if (np.diff(starts) < 3).any():
        f = int(np.flatnonzero(np.diff(starts) < 3)[0])
        raise ValueError(f"face {f} has fewer than 3 vertices")
    _, nxt, _ = _corner_links(starts)
    p, q = v[corners], v[corners[nxt]]
    return 0.5 * np.add.reduceat(np.cross(p, q), starts[:-1], axis=0)


def face_normals(vertices, faces):
    r"""Unit normals of the faces, by the right-hand rule (outwards for counter-clockwise faces).

    For a triangle :math:`n = (p_1 - p_0) \times (p_2 - p_0) / \lVert \cdot \rVert`; for a
    polygon Newell's sum :math:`\tfrac12 \sum_i p_i \times p_{i+1}` (its area vector). A face of
    zero area gets the zero vector.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : (m, k) int array or list of int lists

    Returns
    -------
    ndarray, shape (m, 3)

    Examples
    --------
    >>> face_normals(*cube())[:2]
    array([[ 0.,  0., -1.],
           [ 0.,  0.,  1.]])
    """
    a = _area_vectors(vertices, faces)
    length = np.linalg.norm(a, axis=1, keepdims=True)
    return np.divide(a, length, out=np.zeros_like(a), where=length > 0)


def face_areas(vertices, faces):
    r"""Areas of the faces: :math:`\lVert \tfrac12 \sum_i p_i \times p_{i+1} \rVert` (planar faces).

    Examples
    --------
    >>> face_areas(*cube())
    array([4., 4., 4., 4., 4., 4.])
    >>> face_areas([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 2]])   # collinear: zero area
    array([0.])
    """
    return np.linalg.norm(_area_vectors(vertices, faces), axis=1)


def face_planes(vertices, faces):
    r"""The plane :math:`(a, b, c, d)` of each face, :math:`ax + by + cz + d = 0`, unit normal.

    :math:`(a, b, c)` is the unit normal :math:`n` and :math:`d = -n \cdot \bar p` with
    :math:`\bar p` the mean of the face's vertices. Zero-area faces get the zero row.

    Returns
    -------
    ndarray, shape (m, 4)

    Examples
    --------
    >>> face_planes([[0, 0, 2], [1, 0, 2], [0, 1, 2]], [[0, 1, 2]])
    array([[ 0.,  0.,  1., -2.]])
    """
    v = _vertices(vertices)
    n = face_normals(v, faces)
    corners, starts = _face_table(faces)
    centre = np.add.reduceat(v[corners], starts[:-1], axis=0) / np.diff(starts)[:, None]
    return np.column_stack([n, -(n * centre).sum(axis=1)])


def plane_quadric(plane):
    r"""The fundamental error quadric :math:`K_p = p p^T` of a plane :math:`p = (a, b, c, d)`.

    For :math:`v = (x, y, z, 1)`, :math:`v^T K_p v = (p \cdot v)^2`, the squared distance of the
    point from the plane when :math:`(a, b, c)` is a unit vector. Vectorized over leading axes.

    Examples
    --------
    >>> plane_quadric([0, 0, 1, -2])
    array([[ 0.,  0.,  0.,  0.],
           [ 0.,  0.,  0.,  0.],
           [ 0.,  0.,  1., -2.],
           [ 0.,  0., -2.,  4.]])
    """
    p = as_points(plane, "plane", dims=4)
    return p[..., :, None] * p[..., None, :] + 0.0          # + 0.0: no negative zeros


def vertex_quadrics(vertices, faces):
    r"""The quadric :math:`Q_i = \sum_{p \ni v_i} K_p` of every vertex (Garland-Heckbert).

    The sum over the planes of the faces around vertex :math:`i` (unweighted, as in the
    original paper); :math:`v^T Q_i v` is the sum of squared distances of :math:`v` from those
    planes, zero at the vertex itself.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : (m, k) int array or list of int lists

    Returns
    -------
    ndarray, shape (n, 4, 4)
        Symmetric; zero for a vertex no face uses.

    Examples
    --------
    A corner of the cube has three faces: the planes x = -1, y = -1, z = -1.

    >>> Q = vertex_quadrics(*cube())
    >>> Q[0]
    array([[1., 0., 0., 1.],
           [0., 1., 0., 1.],
           [0., 0., 1., 1.],
           [1., 1., 1., 3.]])
    >>> float(collapse_cost(Q[0], [-1, -1, -1])), float(collapse_cost(Q[0], [1, -1, -1]))
    (0.0, 4.0)
    """
    v = _vertices(vertices)
    k = plane_quadric(face_planes(v, faces))
    corners, starts = _face_table(faces)
    face_of = np.repeat(np.arange(len(starts) - 1), np.diff(starts))
    q = np.zeros((len(v), 16))
    np.add.at(q, corners, k.reshape(-1, 16)[face_of])
    return q.reshape(-1, 4, 4)


def collapse_cost(Q, v):
    r"""The quadric error :math:`\bar v^T Q \bar v` of position `v`, :math:`\bar v = (v, 1)`.

    Vectorized: `Q` of shape (..., 4, 4) and `v` of shape (..., 3) broadcast.

    Examples
    --------
    The quadric of the plane z = 2 at the point (5, 5, 5): distance 3, cost 9.

    >>> float(collapse_cost(plane_quadric([0, 0, 1, -2]), [5, 5, 5]))
    9.0
    """
    q = as_array(Q, "Q")
    if q.ndim < 2 or q.shape[-2:] != (4, 4):
        raise ValueError(f"Q must be a 4x4 quadric (shape (..., 4, 4)), got shape {q.shape}")
    p = as_points(v, "v", dims=3)
    h = np.concatenate([p, np.ones(p.shape[:-1] + (1,))], axis=-1)
    return np.einsum("...i,...ij,...j->...", h, q, h)


def _solvable(a):
    """Which symmetric 3x3 quadric blocks (..., 3, 3) are safely invertible (see _SINGULAR).

    The determinant by cofactors, in the arithmetic of _target10 rather than LAPACK's (whose
    last bit depends on the CPU's kernel), so that a block near the threshold is judged alike
    on every machine and alike in the batch and in the loop of simplify_qem.
    """
    q0, q1, q2, q4, q5, q7 = (a[..., i, j] for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2),
                                                        (2, 2)))
    det = q0 * (q4 * q7 - q5 * q5) + q1 * (q2 * q5 - q1 * q7) + q2 * (q1 * q5 - q2 * q4)
    trace = q0 + q4 + q7
    return (trace > 0) & (det > _SINGULAR * trace * trace * trace)


def _optimal(Qe, p1, p2):
    """Batched best positions and costs: solve A v = -b, or the best of p1, p2, midpoint.

    _target10 for many edges, operation for operation (cofactors, no LAPACK or BLAS): the
    results are the same bits on every machine, and the same as the loop's. That matters:
    simplify_qem's heap orders the edges by these costs, and on a symmetric mesh many are
    equal up to the last bit, which LAPACK's and BLAS's CPU-specific kernels round differently.
    """
    q = Qe[:, _UPPER[0], _UPPER[1]]                     # the 10 distinct entries, as Q10
    ok = _solvable(Qe[:, :3, :3])
    x = np.empty_like(p1)
    if ok.any():
        q0, q1, q2, q3, q4, q5, q6, q7, q8, _ = q[ok].T
        c00, c01, c02 = q4 * q7 - q5 * q5, q2 * q5 - q1 * q7, q1 * q5 - q2 * q4
        c11, c12, c22 = q0 * q7 - q2 * q2, q1 * q2 - q0 * q5, q0 * q4 - q1 * q1
        det = q0 * c00 + q1 * c01 + q2 * c02
        r0, r1, r2 = -q3 / det, -q6 / det, -q8 / det
        x[ok] = np.stack([c00 * r0 + c01 * r1 + c02 * r2, c01 * r0 + c11 * r1 + c12 * r2,
                          c02 * r0 + c12 * r1 + c22 * r2], axis=1)
    bad = ~ok
    if bad.any():
        cand = np.stack([p1[bad], p2[bad], (p1[bad] + p2[bad]) / 2], axis=1)      # (k, 3, 3)
        c = _cost10(q[bad].T[:, :, None], cand[..., 0], cand[..., 1], cand[..., 2])
        x[bad] = cand[np.arange(len(cand)), np.argmin(c, axis=1)]   # ties: the first, as min
    cost = _cost10(q.T, x[:, 0], x[:, 1], x[:, 2])
    return x, np.where(cost > 0, cost, 0.0)


def optimal_position(Q, p1=None, p2=None):
    r"""The position minimizing :math:`\bar v^T Q \bar v`, and its cost.

    With :math:`Q = \begin{pmatrix} A & b \\ b^T & c \end{pmatrix}` the minimum is where
    :math:`A v = -b`. When :math:`A` is singular or badly conditioned (the planes do not pin
    down a point: :math:`\det A \le 10^{-10} (\operatorname{tr} A)^3`, which for the positive
    semi-definite :math:`A` means :math:`\lambda_1 \lambda_2 \lambda_3 \le 10^{-10}
    (\lambda_1 + \lambda_2 + \lambda_3)^3`) the best of `p1`, `p2` and their midpoint is
    returned, as Garland and Heckbert do.

    Parameters
    ----------
    Q : array_like, shape (4, 4)
    p1, p2 : array_like, shape (3,), optional
        The end points of the edge, needed only for a singular `Q`.

    Returns
    -------
    position : ndarray, shape (3,)
    cost : float

    Raises
    ------
    ValueError
        When `Q` is singular and no end points are given.

    Examples
    --------
    Three planes meeting at a cube corner pin down the corner itself, at cost 0:

    >>> Q = vertex_quadrics(*cube())[7]
    >>> x, cost = optimal_position(Q)
    >>> x.tolist(), cost
    ([1.0, 1.0, 1.0], 0.0)
    >>> optimal_position(plane_quadric([0, 0, 1, 0]), [0, 0, 1], [2, 0, 3])
    (array([0., 0., 1.]), 1.0)
    """
    q = as_array(Q, "Q")
    if q.shape != (4, 4):
        raise ValueError(f"Q must be a 4x4 quadric, got shape {q.shape}")
    q = (q + q.T) / 2           # the form v^T Q v only sees the symmetric part (a quadric is)
    if p1 is None or p2 is None:
        if not _solvable(q[:3, :3]):
            raise ValueError("Q is singular (its planes meet in a line or a plane, not a point): "
                             "give the edge's end points p1 and p2 to choose among")
        p1 = p2 = np.zeros(3)
    p1 = as_points(p1, "p1", dims=3).reshape(1, 3)
    p2 = as_points(p2, "p2", dims=3).reshape(1, 3)
    x, cost = _optimal(q[None], p1, p2)
    return x[0], float(cost[0])


# ---------------------------------------------------------------------------------------------
# Iterative edge collapse with the quadric error metric
# ---------------------------------------------------------------------------------------------

class Collapse(NamedTuple):
    """One edge collapse: vertex `removed` merged into vertex `kept`, which moves to `position`.

    Attributes
    ----------
    kept, removed : int
        The edge's end points, as indices of the *original* vertex array.
    position : ndarray, shape (3,)
        The new position of `kept`.
    cost : float
        The quadric error of the collapse.
    faces_removed : tuple of int
        The two faces of the edge (indices of the original face array).

    Examples
    --------
    >>> first = simplify_qem(*icosphere(1), target_faces=70).record.collapses[0]
    >>> len(first.faces_removed), first.position.shape, first.cost >= 0
    (2, (3,), True)
    """
    kept: int
    removed: int
    position: np.ndarray
    cost: float
    faces_removed: tuple


class SimplificationRecord:
    """The history of :func:`simplify_qem`: replay the collapses one at a time.

    Attributes
    ----------
    vertices, faces : ndarray
        The input mesh.
    collapses : list of Collapse
        In the order they were made.
    target_faces : int
    stop_reason : str
        Why the simplification stopped (target reached, or no valid collapse left).
    rejections : dict
        How many candidate collapses were refused, by reason: ``"link condition"`` (the
        collapse would make the mesh non-manifold), ``"flipped face"`` (a face would fold over
        or degenerate), ``"valence"`` (a vertex would keep fewer than 3 neighbours). Edges
        between two boundary vertices are never queued (boundaries are kept).

    Examples
    --------
    >>> out = simplify_qem(*icosphere(2), target_faces=100)
    >>> rec = out.record
    >>> len(rec), rec.face_counts()[:3].tolist(), int(rec.face_counts()[-1])
    (110, [320, 318, 316], 100)
    >>> v, f = rec.mesh_after(len(rec))
    >>> np.array_equal(f, out.faces) and np.allclose(v, out.vertices)
    True
    """

    def __init__(self, vertices, faces, collapses, target_faces, stop_reason, rejections):
        self.vertices, self.faces = vertices, faces
        self.collapses = collapses
        self.target_faces, self.stop_reason, self.rejections = target_faces, stop_reason, rejections

    def __len__(self):
        return len(self.collapses)

    def __repr__(self):
        return (f"SimplificationRecord({len(self.faces)} -> {self.face_counts()[-1]} faces in "
                f"{len(self)} collapses; {self.stop_reason})")

    def face_counts(self):
        """The number of faces after k collapses, k = 0 .. len(self): shape (len + 1,)."""
        removed = np.array([len(c.faces_removed) for c in self.collapses], dtype=np.int64)
        return len(self.faces) - np.concatenate([[0], np.cumsum(removed)])

    def steps_for(self, n_faces):
        """The smallest number of collapses after which at most `n_faces` faces are left."""
        counts = self.face_counts()
        below = np.flatnonzero(counts <= n_faces)
        return int(below[0]) if len(below) else len(self)

    def mesh_after(self, k):
        """The mesh after the first `k` collapses, compacted as :func:`simplify_qem` returns it.

        Surviving faces keep their original order; surviving vertices too.

        Returns
        -------
        vertices : ndarray, shape (n', 3)
        faces : ndarray of int, shape (m', 3)
        """
        rep, pos, dead = self._replay(k)
        return _compact(pos, rep[self.faces[~dead]])

    def _replay(self, k):
        """After `k` collapses: each original vertex's surviving representative, the positions
        (original indexing) and which original faces are gone."""
        k = _count(k, "k")
        if k > len(self):
            raise ValueError(f"k must be at most the number of collapses {len(self)}, got {k}")
        rep = np.arange(len(self.vertices))
        pos = self.vertices.copy()
        dead = np.zeros(len(self.faces), dtype=bool)
        for c in self.collapses[:k]:
            rep[c.removed] = c.kept
            pos[c.kept] = c.position
            dead[list(c.faces_removed)] = True
        while True:
            up = rep[rep]
            if np.array_equal(up, rep):
                break
            rep = up
        return rep, pos, dead

    def _quadrics_after(self, rep):
        """Each surviving vertex's quadric: the sum of the original quadrics merged into it."""
        if getattr(self, "_Q0", None) is None:
            self._Q0 = vertex_quadrics(self.vertices, self.faces).reshape(-1, 16)
        n = len(self.vertices)
        return np.stack([np.bincount(rep, self._Q0[:, i], minlength=n) for i in range(16)],
                        axis=1).reshape(n, 4, 4)

    def errors_after(self, k):
        r"""The error :math:`\sqrt{\bar v^T Q \bar v}` of each vertex of :meth:`mesh_after` ``(k)``.

        :math:`Q` is the sum of the original quadrics of all the vertices merged into this one,
        so the value is the root of the summed squared distances of the vertex to the planes of
        the *original* faces around them (0 for the untouched vertices of a smooth input).

        Returns
        -------
        ndarray, shape (n',)
            One value per vertex of ``mesh_after(k)``, in the same order.

        Examples
        --------
        >>> rec = simplify_qem(*icosphere(2), target_faces=100).record
        >>> float(rec.errors_after(0).max()) < 1e-6, float(rec.errors_after(len(rec)).max()) > 0.1
        (True, True)
        """
        rep, pos, dead = self._replay(k)
        keep = np.unique(rep[self.faces[~dead]])
        cost = collapse_cost(self._quadrics_after(rep)[keep], pos[keep])
        return np.sqrt(np.maximum(cost, 0.0))

    def queue_after(self, k, top=5):
        """The cheapest candidate collapses after `k` collapses: the top of the priority queue.

        Every edge of ``mesh_after(k)`` whose end points are not both on the boundary, with its
        current optimal position and cost (:func:`optimal_position` of :math:`Q_1 + Q_2`; a
        boundary end point stays where it is), cheapest first. These are the live entries of
        :func:`simplify_qem`'s heap at that moment; the next collapse made is the first of them
        that passes the validity checks.

        Parameters
        ----------
        k : int
            Number of collapses already made (0 .. ``len(self)``).
        top : int, optional
            How many entries to return.

        Returns
        -------
        list of Collapse
            ``kept`` / ``removed`` as original vertex indices (``kept`` is the boundary end point
            if there is one), ``faces_removed`` the edge's faces (original indices).

        Examples
        --------
        >>> rec = simplify_qem(*icosphere(2), target_faces=100).record
        >>> head = rec.queue_after(3, top=4)
        >>> [e.cost for e in head] == sorted(e.cost for e in head)
        True
        >>> bool(np.isclose(head[0].cost, rec.collapses[3].cost))   # the next collapse: cheapest
        True
        """
        top = _count(top, "top")
        rep, pos, dead = self._replay(k)
        alive = np.flatnonzero(~dead)
        faces = rep[self.faces[alive]]
        if not hasattr(self, "_border"):
            self._border = HalfEdgeMesh.from_faces(self.vertices, self.faces).boundary_vertices()
        border = self._border
        ends = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]),
                       axis=1)
        owner = np.tile(alive, 3)
        order = np.lexsort((ends[:, 1], ends[:, 0]))
        ends, owner = ends[order], owner[order]
        first = np.r_[True, np.any(ends[1:] != ends[:-1], axis=1)]
        group = np.cumsum(first) - 1
        edges = ends[first]
        edge_faces = [[] for _ in range(len(edges))]
        for g, f in zip(group.tolist(), owner.tolist()):
            edge_faces[g].append(f)
        a, b = edges[:, 0], edges[:, 1]
        keep = ~(border[a] & border[b])
        a, b = a[keep], b[keep]
        edge_faces = [t for t, ok in zip(edge_faces, keep) if ok]
        swap = border[b]                                   # the boundary end point is kept
        a, b = np.where(swap, b, a), np.where(swap, a, b)
        Q = self._quadrics_after(rep)
        Qe = Q[a] + Q[b]
        x, cost = _optimal(Qe, pos[a], pos[b])
        fixed = border[a]
        x[fixed] = pos[a[fixed]]
        cost[fixed] = np.maximum(collapse_cost(Qe[fixed], x[fixed]), 0.0)
        best = np.argsort(cost, kind="stable")[:top]
        return [Collapse(int(a[i]), int(b[i]), x[i], float(cost[i]), tuple(sorted(edge_faces[i])))
                for i in best]

    def meshes_at(self, face_counts):
        """The meshes at the requested face counts (each after :meth:`steps_for` collapses)."""
        return [self.mesh_after(self.steps_for(n)) for n in face_counts]


class Simplified(NamedTuple):
    """What :func:`simplify_qem` returns: the simplified mesh (compacted) and its record.

    Examples
    --------
    >>> out = simplify_qem(*icosphere(1), target_faces=40)
    >>> out.faces.shape, type(out.record).__name__
    ((40, 3), 'SimplificationRecord')
    """
    vertices: np.ndarray
    faces: np.ndarray
    record: SimplificationRecord


def _compact(vertices, faces):
    used = np.zeros(len(vertices), dtype=bool)
    used[faces] = True
    new_index = np.cumsum(used) - 1
    return vertices[used], new_index[faces].astype(np.int64)


# The loop of simplify_qem works on a handful of numbers per step, where plain Python floats are
# faster than numpy calls. A symmetric quadric is kept as its 10 distinct entries
# (q00, q01, q02, q03, q11, q12, q13, q22, q23, q33).
_UPPER = (np.array([0, 0, 0, 0, 1, 1, 1, 2, 2, 3]), np.array([0, 1, 2, 3, 1, 2, 3, 2, 3, 3]))


def _cost10(q, x, y, z):
    """v^T Q v for v = (x, y, z, 1), Q given by its 10 distinct entries."""
    q0, q1, q2, q3, q4, q5, q6, q7, q8, q9 = q
    return (x * (q0 * x + 2 * (q1 * y + q2 * z + q3)) + y * (q4 * y + 2 * (q5 * z + q6)) +
            z * (q7 * z + 2 * q8) + q9)


def _target10(q, p1, p2):
    """_optimal for one edge, in Python floats: (position, cost)."""
    q0, q1, q2, q3, q4, q5, q6, q7, q8, q9 = q
    c00 = q4 * q7 - q5 * q5
    c01 = q2 * q5 - q1 * q7
    c02 = q1 * q5 - q2 * q4
    det = q0 * c00 + q1 * c01 + q2 * c02
    trace = q0 + q4 + q7
    if trace > 0 and det > _SINGULAR * trace * trace * trace:
        c11 = q0 * q7 - q2 * q2
        c12 = q1 * q2 - q0 * q5
        c22 = q0 * q4 - q1 * q1
        r0, r1, r2 = -q3 / det, -q6 / det, -q8 / det
        x = c00 * r0 + c01 * r1 + c02 * r2
        y = c01 * r0 + c11 * r1 + c12 * r2
        z = c02 * r0 + c12 * r1 + c22 * r2
        cost = (x * (q0 * x + 2 * (q1 * y + q2 * z + q3)) + y * (q4 * y + 2 * (q5 * z + q6)) +
                z * (q7 * z + 2 * q8) + q9)
        return [x, y, z], (cost if cost > 0 else 0.0)
    mid = [(p1[0] + p2[0]) / 2, (p1[1] + p2[1]) / 2, (p1[2] + p2[2]) / 2]
    best = min((_cost10(q, *c), i) for i, c in enumerate((p1, p2, mid)))
    return list((p1, p2, mid)[best[1]]), max(best[0], 0.0)


def simplify_qem(vertices, faces, target_faces, record=True, max_angle=np.pi / 2):
    r"""Simplify a triangle mesh by iterative edge collapse with the quadric error metric.

    1. Build the half-edge structure (this checks the input: a manifold, consistently oriented
       triangle mesh) and the vertex quadrics :math:`Q_i = \sum K_p` (:func:`vertex_quadrics`).
    2. For every edge, the position :math:`\bar v` minimizing :math:`\bar v^T (Q_1 + Q_2) \bar v`
       and that cost (:func:`optimal_position`); all edges go into a heap.
    3. Pop the cheapest edge. Skip it if it is stale (an end point changed since it was pushed:
       lazy deletion); refuse it if the collapse would break the mesh (the link condition,
       a face normal turning by more than `max_angle` or a face becoming degenerate, a vertex
       left with fewer than 3 neighbours, the boundary rules; see the module notes); refused
       edges are retried once their neighbourhood changes. Else collapse it: vertex
       ``removed`` merges into ``kept`` at :math:`\bar v`, the two faces of the edge vanish,
       :math:`Q_{kept} \leftarrow Q_1 + Q_2`, and the edges at ``kept`` get new costs.
    4. Stop at `target_faces` faces (or one fewer: a collapse removes two) or when no edge can
       be collapsed.

    Only the neighbourhood of the collapsed edge is touched per step (faces per vertex are kept
    as sets), so the work per collapse does not grow with the mesh.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
        A manifold, consistently oriented triangle mesh (boundaries allowed).
    target_faces : int
        The number of faces to reach.
    record : bool, optional
        Keep the list of collapses (for :meth:`SimplificationRecord.mesh_after`).
    max_angle : float, optional
        The largest turn (radians) of a face normal a single collapse may cause.

    Returns
    -------
    Simplified
        ``(vertices, faces, record)``: the compacted mesh (surviving vertices and faces in
        their original order) and the :class:`SimplificationRecord` (its ``stop_reason`` says
        why it stopped; without `record` its list of collapses is empty).

    Raises
    ------
    ValueError
        For a non-triangle, non-manifold or inconsistently oriented mesh, a negative target or
        an angle outside (0, pi].

    Examples
    --------
    >>> v, f, rec = simplify_qem(*icosphere(3), target_faces=200)
    >>> len(f), HalfEdgeMesh.from_faces(v, f).genus()
    (200, 0)
    >>> rec.stop_reason
    'reached the target: 200 faces (target 200)'
    """
    mesh = HalfEdgeMesh.from_faces(vertices, faces)
    tri = mesh.to_faces()
    if not isinstance(tri, np.ndarray) or tri.shape[1] != 3:
        raise ValueError("simplify_qem needs a triangle mesh (faces of 3 vertices); split the "
                         "polygons into triangles first")
    target = _count(target_faces, "target_faces")
    angle = as_scalar(max_angle, "max_angle")
    if not 0 < angle <= np.pi:
        raise ValueError(f"max_angle must be in (0, pi] radians, got {max_angle!r}")
    cos_limit = float(np.cos(angle))
    pos = mesh.vertices.copy()
    n, m = len(pos), len(tri)
    Q = vertex_quadrics(pos, tri)
    F = tri.tolist()
    vfaces = [set() for _ in range(n)]
    for f, (a, b, c) in enumerate(F):
        vfaces[a].add(f)
        vfaces[b].add(f)
        vfaces[c].add(f)
    boundary = mesh.boundary_vertices()
    on_border = boundary.tolist()
    version = [0] * n
    alive = [True] * n
    face_alive = [True] * m
    extent = float(np.ptp(pos, axis=0).max()) if n else 1.0
    eps2 = (1e-12 * max(extent, 1e-150) ** 2) ** 2     # squared |normal| of a degenerate face
    rejections = {"link condition": 0, "flipped face": 0, "valence": 0}
    collapses = []

    # all edges at once (numpy), then per collapse a few edges (Python floats, same maths)
    e = mesh.edges()
    e = e[~(boundary[e[:, 0]] & boundary[e[:, 1]])]     # boundary edges and chords never go
    a, b = e[:, 0], e[:, 1]
    x, cost = _optimal(Q[a] + Q[b], pos[a], pos[b])
    fix_a, fix_b = boundary[a], boundary[b]             # a boundary end point stays put
    x[fix_a], x[fix_b] = pos[a[fix_a]], pos[b[fix_b]]
    fixed = fix_a | fix_b
    cost[fixed] = np.maximum(collapse_cost(Q[a[fixed]] + Q[b[fixed]], x[fixed]), 0.0)
    heap = [(c, i, u, w, 0, 0, p) for i, (c, u, w, p)
            in enumerate(zip(cost.tolist(), a.tolist(), b.tolist(), x.tolist()))]
    heapq.heapify(heap)
    counter = len(heap)
    P = pos.tolist()
    Q10 = Q[:, _UPPER[0], _UPPER[1]].tolist()
    rejected = {}                      # edge key -> heap entry refused, retried after changes
    rejected_at = [set() for _ in range(n)]
    nbr = [set() for _ in range(n)]    # the one-ring of each vertex, kept up to date
    for a, b in mesh.edges().tolist():
        nbr[a].add(b)
        nbr[b].add(a)

    def refuse(entry, u, w, why):
        rejections[why] += 1
        key = (u, w) if u < w else (w, u)
        rejected[key] = entry
        rejected_at[u].add(key)
        rejected_at[w].add(key)

    def folds(u, w, p, faces):
        """Would moving u and w to p turn a face normal by more than max_angle (or degenerate)?

        Each face has exactly one moving corner m; with the other two b, c (in the face's
        order after m) the normal is (c - b) x (m - b), before and after the move.
        """
        px, py, pz = p
        for f in faces:
            a, b, c = F[f]
            if a == u or a == w:
                m, b, c = P[a], P[b], P[c]
            elif b == u or b == w:
                m, b, c = P[b], P[c], P[a]
            else:
                m, b, c = P[c], P[a], P[b]
            bx, by, bz = b
            ex, ey, ez = c[0] - bx, c[1] - by, c[2] - bz
            mx, my, mz = m[0] - bx, m[1] - by, m[2] - bz
            ox, oy, oz = ey * mz - ez * my, ez * mx - ex * mz, ex * my - ey * mx
            mx, my, mz = px - bx, py - by, pz - bz
            nx, ny, nz = ey * mz - ez * my, ez * mx - ex * mz, ex * my - ey * mx
            len_new = nx * nx + ny * ny + nz * nz
            if len_new <= eps2:
                return True
            len_old = ox * ox + oy * oy + oz * oz
            if len_old > eps2 and (ox * nx + oy * ny + oz * nz <=
                                   cos_limit * (len_old * len_new) ** 0.5):
                return True
        return False

    n_faces = m
    while n_faces > target and heap:
        entry = heapq.heappop(heap)
        cost, _, u, w, vu, vw, p = entry
        if not (alive[u] and alive[w]) or version[u] != vu or version[w] != vw:
            continue                                            # stale entry
        if on_border[w]:
            u, w = w, u                                         # keep the boundary vertex
        if on_border[w]:
            continue                          # two boundary end points: never queued anyway
        shared = vfaces[u] & vfaces[w]
        if len(shared) != 2:
            continue                                            # no longer an edge
        ring_u, ring_w = nbr[u], nbr[w]
        common = ring_u & ring_w
        f1, f2 = shared
        opposite = {*F[f1], *F[f2]} - {u, w}
        if common != opposite:
            refuse(entry, u, w, "link condition")
            continue
        if (len(ring_u) + len(ring_w) - 4 < 3 or
                any(len(nbr[x]) - 1 < (2 if on_border[x] else 3) for x in opposite)):
            refuse(entry, u, w, "valence")
            continue
        if folds(u, w, p, (vfaces[u] | vfaces[w]) - shared):
            refuse(entry, u, w, "flipped face")
            continue
        # the collapse: w merges into u
        for f in shared:
            face_alive[f] = False
            for x in F[f]:
                vfaces[x].discard(f)
        for f in vfaces[w]:
            face = F[f]
            face[face.index(w)] = u
            vfaces[u].add(f)
        vfaces[w] = set()
        for x in ring_w:
            if x != u:
                nbr[x].discard(w)
                nbr[x].add(u)
        ring_u |= ring_w
        ring_u.discard(u)
        ring_u.discard(w)
        nbr[w] = set()
        alive[w] = False
        P[u] = p
        qu = Q10[u] = list(map(add, Q10[u], Q10[w]))
        version[u] += 1
        version[w] += 1
        n_faces -= 2
        if record:
            collapses.append(Collapse(u, w, np.array(p), cost, tuple(sorted(shared))))
        vu, pu, border_u = version[u], P[u], on_border[u]
        for x in ring_u:                                        # new costs of the edges at u
            if border_u or on_border[x]:
                if border_u and on_border[x]:
                    continue
                fixed = pu if border_u else P[x]
                c = max(_cost10(list(map(add, qu, Q10[x])), *fixed), 0.0)
                heapq.heappush(heap, (c, counter, u, x, vu, version[x], fixed))
            else:
                px, c = _target10(list(map(add, qu, Q10[x])), pu, P[x])
                heapq.heappush(heap, (c, counter, u, x, vu, version[x], px))
            counter += 1
        for x in (*ring_u, u):                 # refused edges near u may be fine now
            keys = rejected_at[x]
            if keys:
                for key in keys:
                    item = rejected.pop(key, None)
                    if item is not None:
                        heapq.heappush(heap, item)
                keys.clear()
    pos = np.array(P, dtype=float).reshape(-1, 3)
    if n_faces <= target:
        reason = (f"reached the target: {n_faces} faces (target {target})" if m > target else
                  f"nothing to do: the mesh has {m} faces, target {target}")
    else:
        reason = (f"stopped at {n_faces} faces (target {target}): no edge left whose collapse "
                  f"keeps the mesh manifold, unfolded and its boundary intact "
                  f"({sum(rejections.values())} collapses refused)")
    out_v, out_f = _compact(pos, np.array([F[f] for f in range(m) if face_alive[f]],
                                          dtype=np.int64).reshape(-1, 3))
    rec = SimplificationRecord(mesh.vertices.copy(), tri, collapses, target, reason, rejections)
    return Simplified(out_v, out_f, rec)
