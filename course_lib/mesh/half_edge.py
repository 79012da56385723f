"""Chapter 6 (lesson section 4.2): the half-edge data structure and its local queries."""

import numpy as np

from ._common import _face_table, _index, _vertices
from .connectivity import _build
from ._topology import _Topology

__all__ = ["HalfEdgeMesh"]


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
    >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import bow_tie, cube
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
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import tetrahedron
        >>> m = HalfEdgeMesh.from_faces(*tetrahedron())
        >>> m.opposite(m.opposite(5)) == 5
        True
        """
        return int(self.twin[self._h(h)])

    def next_half_edge(self, h):
        """The half-edge after `h` around its face (or its boundary loop).

        Examples
        --------
        >>> from course_lib.mesh import tetrahedron
        >>> m = HalfEdgeMesh.from_faces(*tetrahedron())
        >>> [m.next_half_edge(0), m.next_half_edge(1), m.next_half_edge(2)]
        [1, 2, 0]
        """
        return int(self.next[self._h(h)])

    def previous_half_edge(self, h):
        """The half-edge before `h` around its face (or its boundary loop).

        Examples
        --------
        >>> from course_lib.mesh import tetrahedron
        >>> HalfEdgeMesh.from_faces(*tetrahedron()).previous_half_edge(0)
        2
        """
        return int(self.prev[self._h(h)])

    def describe(self, h):
        """Everything stored about half-edge `h`, as a dict (for a widget's text panel).

        Examples
        --------
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import disc
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

        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import cube
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
        >>> from course_lib.mesh import cube
        >>> HalfEdgeMesh.from_faces(*cube()).face_vertices(1)
        [4, 5, 7, 6]
        """
        return [int(self.origin[h]) for h in self.face_half_edges(f)]

    def face_neighbors(self, f):
        """The faces across the edges of face `f` (-1 across a boundary edge), in order.

        Examples
        --------
        >>> from course_lib.mesh import cube
        >>> HalfEdgeMesh.from_faces(*cube()).face_neighbors(1)
        [2, 5, 3, 4]
        """
        return [int(self.face[self.twin[h]]) for h in self.face_half_edges(f)]

    def edge_faces(self, h):
        """The two faces of the edge of half-edge `h`: ``(face(h), face(twin(h)))``; -1 = none.

        Examples
        --------
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import tetrahedron
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
