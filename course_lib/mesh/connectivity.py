"""Chapter 6 (lesson section 1): the connectivity of a face list, with clear reports of bad input.
"""

import numbers
from typing import NamedTuple

import numpy as np

from .._validate import as_whole
from ._common import _face_table, _vertices

__all__ = ["MeshProblem", "mesh_problems"]


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
    >>> from course_lib.mesh import bow_tie
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
    >>> from course_lib.mesh import tetrahedron, three_faces_on_an_edge
    >>> mesh_problems(*tetrahedron())
    []
    >>> print(mesh_problems(*three_faces_on_an_edge())[0].message)
    edge (0, 1) is shared by 3 faces [0, 1, 2]: a non-manifold edge (on a manifold surface an edge has one face on each side, two at most)
    >>> print(mesh_problems(4, [[0, 1, 2], [0, 1, 3]])[0].message)
    faces 0 and 1 both run along the edge 0 -> 1 in the same direction: inconsistent winding (orientation); reverse the vertex order of one of them
    """
    if isinstance(vertices, numbers.Integral) and not isinstance(vertices, bool):
        n = as_whole(vertices, "vertices", 0, integer_type=True, at_least=True)
    else:
        n = len(_vertices(vertices))
    corners, starts = _face_table(faces)
    return _build(corners, starts, n, collect=True)[0]
