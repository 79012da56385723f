"""Chapter 6 (lesson section 4.1): the winged-edge data structure and its local queries."""

import numpy as np

from ._common import _index
from .half_edge import HalfEdgeMesh, _walk_loops
from ._topology import _Topology

__all__ = ["WingedEdgeMesh"]


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
    >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import cube
        >>> WingedEdgeMesh.from_faces(*cube())
        WingedEdgeMesh(V=8, E=12, F=6, boundary loops=0)
        """
        return cls.from_half_edges(HalfEdgeMesh.from_faces(vertices, faces))

    @classmethod
    def from_half_edges(cls, mesh):
        """The winged-edge table of a :class:`HalfEdgeMesh` (edge e = row e of its ``edges()``).

        Examples
        --------
        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import disc
        >>> WingedEdgeMesh.from_faces(*disc(rings=1, segments=6)).vertex_one_ring(1)
        [2, 0, 6]
        """
        return [int(self.end[e] if self.start[e] == v else self.start[e])
                for e in self.vertex_edges(v)]

    def vertex_faces(self, v):
        """The faces around vertex `v`, counter-clockwise (as :meth:`HalfEdgeMesh.vertex_faces`).

        Examples
        --------
        >>> from course_lib.mesh import disc
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
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import tetrahedron
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
        >>> from course_lib.mesh import disc
        >>> WingedEdgeMesh.from_faces(*disc(rings=1, segments=6)).boundary_loops()
        [[2, 1, 6, 5, 4, 3]]
        """
        loops = _walk_loops(np.flatnonzero(self.right_face < 0), self.right_next)
        return loops if edges else [[int(self.end[e]) for e in loop] for loop in loops]

    def to_faces(self):
        """The face list again, walking each face's edges (list of lists; array if all same size).

        Examples
        --------
        >>> from course_lib.mesh import tetrahedron
        >>> WingedEdgeMesh.from_faces(*tetrahedron()).to_faces().tolist()
        [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
        """
        faces = [self.face_vertices(f) for f in range(len(self.face_edge))]
        if len({len(f) for f in faces}) == 1:
            return np.array(faces, dtype=np.int64)
        return faces
