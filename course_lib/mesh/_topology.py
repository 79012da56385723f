"""Chapter 6 (lesson sections 2, 3): manifold, orientable, Euler-Poincare, genus, components."""

import numpy as np


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
        >>> from course_lib.mesh import HalfEdgeMesh, cube, disc, double_torus, torus
        >>> [HalfEdgeMesh.from_faces(*m).euler_characteristic()
        ...  for m in (cube(), torus(), double_torus(), disc())]
        [2, 0, -2, 1]
        """
        return self.n_vertices - self.n_edges + self.n_faces

    def is_closed(self):
        """True when every edge has two faces (no boundary): the mesh is watertight.

        Examples
        --------
        >>> from course_lib.mesh import HalfEdgeMesh, cube, disc
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
        >>> from course_lib.mesh import HalfEdgeMesh, torus
        >>> HalfEdgeMesh.from_faces(*torus()).is_manifold()
        True
        """
        return True

    def boundary_components(self):
        """The number of boundary loops (holes).

        Examples
        --------
        >>> from course_lib.mesh import HalfEdgeMesh, disc
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
        >>> from course_lib.mesh import HalfEdgeMesh, tetrahedron
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
        >>> from course_lib.mesh import HalfEdgeMesh, double_torus, icosphere, torus
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
