"""Chapter 6 (lesson section 5): iterative edge collapse with the quadric error metric."""

import heapq
from operator import add
from typing import NamedTuple

import numpy as np

from .._validate import as_scalar, as_whole
from ._common import _compact, _SINGULAR
from .geometry import collapse_cost, _cost10, _optimal, _UPPER, vertex_quadrics
from .half_edge import HalfEdgeMesh

__all__ = ["Collapse", "Simplified", "SimplificationRecord", "simplify_qem"]


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
    >>> from course_lib.mesh import icosphere
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
    >>> from course_lib.mesh import icosphere
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
        k = as_whole(k, "k", 0, integer_type=True, at_least=True)
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
        >>> from course_lib.mesh import icosphere
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
        >>> from course_lib.mesh import icosphere
        >>> rec = simplify_qem(*icosphere(2), target_faces=100).record
        >>> head = rec.queue_after(3, top=4)
        >>> [e.cost for e in head] == sorted(e.cost for e in head)
        True
        >>> bool(np.isclose(head[0].cost, rec.collapses[3].cost))   # the next collapse: cheapest
        True
        """
        top = as_whole(top, "top", 0, integer_type=True, at_least=True)
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
    >>> from course_lib.mesh import icosphere
    >>> out = simplify_qem(*icosphere(1), target_faces=40)
    >>> out.faces.shape, type(out.record).__name__
    ((40, 3), 'SimplificationRecord')
    """
    vertices: np.ndarray
    faces: np.ndarray
    record: SimplificationRecord


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

class _Edge:
    """A candidate collapse popped from the heap: `removed` merges into `kept` at `position`.

    `faces` are the edge's two faces, `opposite` their two corners off the edge, `entry` the
    heap entry (pushed back if the collapse is refused and the neighbourhood changes later).
    """
    __slots__ = ("entry", "cost", "kept", "removed", "position", "faces", "opposite")

    def __init__(self, entry, kept, removed, faces, opposite):
        self.entry, self.cost, self.position = entry, entry[0], entry[6]
        self.kept, self.removed, self.faces, self.opposite = kept, removed, faces, opposite


class _Collapser:
    """The state of :func:`simplify_qem` and its steps, one method each.

    The state is kept in plain Python lists and sets (a handful of numbers change per collapse,
    where Python floats are faster than numpy calls; see ``geometry._UPPER``): per vertex its
    position, its quadric (10 numbers), the set of its faces and of its neighbours (the one-ring),
    whether it is on the boundary, alive, and a version counting its changes; per face its three
    corners and whether it is alive; the heap of candidate edges and the refused ones.

    A heap entry is ``(cost, counter, u, w, version of u, version of w, position)``: the unique
    counter breaks ties between equal costs by the order the entries were made, and the versions
    recognise a stale entry (an end point changed since it was pushed: lazy deletion).
    """

    def __init__(self, mesh, tri, cos_limit, record):
        """Steps 1 and 2: the quadrics, the connectivity as sets, every edge in the heap."""
        pos = mesh.vertices.copy()
        n, m = len(pos), len(tri)
        Q = vertex_quadrics(pos, tri)
        self.faces = F = tri.tolist()
        self.faces_at = vfaces = [set() for _ in range(n)]
        for f, (a, b, c) in enumerate(F):
            vfaces[a].add(f)
            vfaces[b].add(f)
            vfaces[c].add(f)
        boundary = mesh.boundary_vertices()
        self.on_border = boundary.tolist()
        self.version = [0] * n
        self.alive = [True] * n
        self.face_alive = [True] * m
        self.n_faces = m
        extent = float(np.ptp(pos, axis=0).max()) if n else 1.0
        self.eps2 = (1e-12 * max(extent, 1e-150) ** 2) ** 2  # squared |normal|, degenerate face
        self.cos_limit = cos_limit
        self.record = record
        self.rejections = {"link condition": 0, "flipped face": 0, "valence": 0}
        self.collapses = []
        edges = mesh.edges()
        self.heap = self._every_edge(edges, boundary, pos, Q)
        self.counter = len(self.heap)
        self.positions = pos.tolist()
        self.quadrics = Q[:, _UPPER[0], _UPPER[1]].tolist()
        self.refused = {}                  # edge key -> heap entry refused, retried after changes
        self.refused_at = [set() for _ in range(n)]
        self.ring = nbr = [set() for _ in range(n)]       # the one-ring of each vertex
        for a, b in edges.tolist():
            nbr[a].add(b)
            nbr[b].add(a)

    @staticmethod
    def _every_edge(edges, boundary, pos, Q):
        """The first heap: every edge with its optimal position and cost, all at once (numpy);
        later a few edges per collapse get the same maths in Python floats (:meth:`requeue`)."""
        e = edges[~(boundary[edges[:, 0]] & boundary[edges[:, 1]])]   # boundary edges, chords
        a, b = e[:, 0], e[:, 1]
        x, cost = _optimal(Q[a] + Q[b], pos[a], pos[b])
        fix_a, fix_b = boundary[a], boundary[b]             # a boundary end point stays put
        x[fix_a], x[fix_b] = pos[a[fix_a]], pos[b[fix_b]]
        fixed = fix_a | fix_b
        cost[fixed] = np.maximum(collapse_cost(Q[a[fixed]] + Q[b[fixed]], x[fixed]), 0.0)
        heap = [(c, i, u, w, 0, 0, p) for i, (c, u, w, p)
                in enumerate(zip(cost.tolist(), a.tolist(), b.tolist(), x.tolist()))]
        heapq.heapify(heap)
        return heap

    def pop_cheapest(self):
        """Pop heap entries until one is a live edge; return it as an :class:`_Edge` (a boundary
        end point is `kept`), or None when the heap runs empty. Skipped: stale entries (an end
        point merged or changed since the entry was pushed: lazy deletion), no longer edges."""
        heap, alive, version, on_border = self.heap, self.alive, self.version, self.on_border
        faces_at, F = self.faces_at, self.faces
        while heap:
            entry = heapq.heappop(heap)
            _, _, u, w, vu, vw, _ = entry
            if not (alive[u] and alive[w]) or version[u] != vu or version[w] != vw:
                continue                                        # stale entry
            if on_border[w]:
                u, w = w, u                                     # keep the boundary vertex
            if on_border[w]:
                continue                      # two boundary end points: never queued anyway
            shared = faces_at[u] & faces_at[w]
            if len(shared) != 2:
                continue                                        # no longer an edge
            f1, f2 = shared
            return _Edge(entry, u, w, shared, {*F[f1], *F[f2]} - {u, w})
        return None

    def link_condition_holds(self, edge):
        """The end points' common neighbours are exactly the two vertices opposite the edge
        (else the collapse pinches the surface into a non-manifold one)."""
        return self.ring[edge.kept] & self.ring[edge.removed] == edge.opposite

    def valence_ok(self, edge):
        """Every vertex keeps at least 3 neighbours (a boundary vertex at least 2): the merged
        vertex, and the two opposite vertices, which each lose one."""
        nbr, on_border = self.ring, self.on_border
        return not (len(nbr[edge.kept]) + len(nbr[edge.removed]) - 4 < 3 or
                    any(len(nbr[x]) - 1 < (2 if on_border[x] else 3) for x in edge.opposite))

    def folds(self, edge, position):
        """Would moving both end points to `position` turn the normal of a surviving face
        around them by more than max_angle (or make it degenerate)?

        Each face has exactly one moving corner m; with the other two b, c (in the face's
        order after m) the normal is (c - b) x (m - b), before and after the move.
        """
        u, w = edge.kept, edge.removed
        F, P, eps2, cos_limit = self.faces, self.positions, self.eps2, self.cos_limit
        px, py, pz = position
        for f in (self.faces_at[u] | self.faces_at[w]) - edge.faces:
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

    def refuse(self, edge, why):
        """Count the refusal and keep the entry, to retry once the neighbourhood changes."""
        self.rejections[why] += 1
        u, w = edge.kept, edge.removed
        key = (u, w) if u < w else (w, u)
        self.refused[key] = edge.entry
        self.refused_at[u].add(key)
        self.refused_at[w].add(key)

    def collapse(self, edge, position):
        r"""Merge `removed` into `kept` at `position`: the edge's two faces vanish, the other
        faces of `removed` are re-attached to `kept`, the one-rings are merged, the quadrics
        added (:math:`Q_{kept} \leftarrow Q_1 + Q_2`) and both versions bumped."""
        u, w, shared = edge.kept, edge.removed, edge.faces
        F, vfaces, nbr = self.faces, self.faces_at, self.ring
        for f in shared:
            self.face_alive[f] = False
            for x in F[f]:
                vfaces[x].discard(f)
        for f in vfaces[w]:
            face = F[f]
            face[face.index(w)] = u
            vfaces[u].add(f)
        vfaces[w] = set()
        ring_u = nbr[u]
        for x in nbr[w]:
            if x != u:
                nbr[x].discard(w)
                nbr[x].add(u)
        ring_u |= nbr[w]
        ring_u.discard(u)
        ring_u.discard(w)
        nbr[w] = set()
        self.alive[w] = False
        self.positions[u] = position
        Q10 = self.quadrics
        Q10[u] = list(map(add, Q10[u], Q10[w]))
        self.version[u] += 1
        self.version[w] += 1
        self.n_faces -= 2
        if self.record:
            self.collapses.append(Collapse(u, w, np.array(position), edge.cost,
                                           tuple(sorted(shared))))

    def requeue(self, v):
        """Push the edges at `v` with their new costs (the optimal position of
        :math:`Q_v + Q_x`, or the boundary end point), and the refused edges near `v` again."""
        version, P, Q10, on_border, heap = self.version, self.positions, self.quadrics, \
            self.on_border, self.heap
        ring, counter = self.ring[v], self.counter
        vu, pu, border_u, qu = version[v], P[v], on_border[v], Q10[v]
        for x in ring:
            if border_u or on_border[x]:
                if border_u and on_border[x]:
                    continue
                fixed = pu if border_u else P[x]
                c = max(_cost10(list(map(add, qu, Q10[x])), *fixed), 0.0)
                heapq.heappush(heap, (c, counter, v, x, vu, version[x], fixed))
            else:
                px, c = _target10(list(map(add, qu, Q10[x])), pu, P[x])
                heapq.heappush(heap, (c, counter, v, x, vu, version[x], px))
            counter += 1
        self.counter = counter
        refused, refused_at = self.refused, self.refused_at
        for x in (*ring, v):                   # refused edges near v may be fine now
            keys = refused_at[x]
            if keys:
                for key in keys:
                    item = refused.pop(key, None)
                    if item is not None:
                        heapq.heappush(heap, item)
                keys.clear()

    def stop_reason(self, target):
        """Why the loop stopped, as :attr:`SimplificationRecord.stop_reason` says it."""
        m, n_faces = len(self.faces), self.n_faces
        if n_faces <= target:
            return (f"reached the target: {n_faces} faces (target {target})" if m > target else
                    f"nothing to do: the mesh has {m} faces, target {target}")
        return (f"stopped at {n_faces} faces (target {target}): no edge left whose collapse "
                f"keeps the mesh manifold, unfolded and its boundary intact "
                f"({sum(self.rejections.values())} collapses refused)")

    def compacted(self):
        """The surviving vertices and faces, in their original order (:func:`_compact`)."""
        pos = np.array(self.positions, dtype=float).reshape(-1, 3)
        F, alive = self.faces, self.face_alive
        return _compact(pos, np.array([F[f] for f in range(len(F)) if alive[f]],
                                      dtype=np.int64).reshape(-1, 3))


def simplify_qem(vertices, faces, target_faces, record=True, max_angle=np.pi / 2):
    r"""Simplify a triangle mesh by iterative edge collapse with the quadric error metric.

    1. Build the half-edge structure (this checks the input: a manifold, consistently oriented
       triangle mesh) and the vertex quadrics :math:`Q_i = \sum K_p` (:func:`vertex_quadrics`).
    2. For every edge, the position :math:`\bar v` minimizing :math:`\bar v^T (Q_1 + Q_2) \bar v`
       and that cost (:func:`optimal_position`); all edges go into a heap.
    3. Pop the cheapest edge. Skip it if it is stale (an end point changed since it was pushed:
       lazy deletion). Refuse it if the collapse would break the mesh, checked in this order
       (the first failure names the refusal in :attr:`SimplificationRecord.rejections`): the
       link condition, a vertex left with fewer than 3 neighbours (valence), a face normal
       turning by more than `max_angle` or a face becoming degenerate (fold); the boundary
       rules are kept throughout (see the module notes). Refused edges are retried once their
       neighbourhood changes. Else collapse it: vertex ``removed`` merges into ``kept`` at
       :math:`\bar v`, the two faces of the edge vanish, :math:`Q_{kept} \leftarrow Q_1 + Q_2`;
       then requeue: the edges at ``kept`` get new costs.
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
    >>> from course_lib.mesh import icosphere
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
    target = as_whole(target_faces, "target_faces", 0, integer_type=True, at_least=True)
    angle = as_scalar(max_angle, "max_angle")
    if not 0 < angle <= np.pi:
        raise ValueError(f"max_angle must be in (0, pi] radians, got {max_angle!r}")
    qem = _Collapser(mesh, tri, float(np.cos(angle)), record)     # steps 1 and 2
    while qem.n_faces > target:                                   # step 3, until step 4
        edge = qem.pop_cheapest()                                 # skips the stale entries
        if edge is None:                                          # no edge left
            break
        if not qem.link_condition_holds(edge):
            qem.refuse(edge, "link condition")
        elif not qem.valence_ok(edge):
            qem.refuse(edge, "valence")
        elif qem.folds(edge, edge.position):
            qem.refuse(edge, "flipped face")
        else:
            qem.collapse(edge, edge.position)
            qem.requeue(edge.kept)
    out_v, out_f = qem.compacted()
    rec = SimplificationRecord(mesh.vertices.copy(), tri, qem.collapses, target,
                               qem.stop_reason(target), qem.rejections)
    return Simplified(out_v, out_f, rec)
