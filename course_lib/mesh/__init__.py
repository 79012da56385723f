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
pinches the surface into a non-manifold one or folds two faces onto each other); (ii) the
*valence*: a vertex would be left with fewer than three neighbours (a tetrahedron cannot lose
more faces); (iii) the *fold test*: a surviving face around the edge would turn its normal by
more than ``max_angle`` (90 degrees by default: a fold-over) or become degenerate. The checks
run in this order, and a refusal is counted under the first that fails. **Boundaries are kept exactly**: a boundary
edge is never collapsed, a boundary vertex never moves (an interior edge with one boundary end
point collapses onto that end point) and an interior edge joining two boundary vertices is
rejected (it would pinch the surface). Closed meshes stay closed, and a hole keeps its rim.

Files
-----

``connectivity.py``
    Chapter 6 (lesson section 1): the connectivity of a face list, with clear reports of bad
    input.
``_topology.py``
    Chapter 6 (lesson sections 2, 3): manifold, orientable, Euler-Poincare, genus, components.
``half_edge.py``
    Chapter 6 (lesson section 4.2): the half-edge data structure and its local queries.
``winged_edge.py``
    Chapter 6 (lesson section 4.1): the winged-edge data structure and its local queries.
``procedural.py``
    Chapter 6: the example meshes of the lesson and the tests (closed, with a boundary, and not
    manifold).
``geometry.py``
    Chapter 6 (lesson section 5): face normals, areas, planes and the fundamental quadrics.
``simplify.py``
    Chapter 6 (lesson section 5): iterative edge collapse with the quadric error metric.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from .connectivity import (MeshProblem, mesh_problems)
from .half_edge import (HalfEdgeMesh)
from .winged_edge import (WingedEdgeMesh)
from .procedural import (bow_tie, cube, disc, double_torus, icosphere, tetrahedron,
    three_faces_on_an_edge, torus)
from .geometry import (collapse_cost, face_areas, face_cross_products, face_normals, face_planes,
    optimal_position, plane_quadric, vertex_quadrics)
from .simplify import (Collapse, Simplified, SimplificationRecord, simplify_qem, _target10)

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
    "face_cross_products",
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

# the forms of a model and boundary representations; clustering, vertex decimation, error
# measures; levels of detail and progressive meshes (each module declares its __all__)
from . import brep, clustering, decimation, distances, forms, lod  # noqa: E402
from .forms import *  # noqa: E402,F401,F403
from .brep import *  # noqa: E402,F401,F403
from .clustering import *  # noqa: E402,F401,F403
from .decimation import *  # noqa: E402,F401,F403
from .distances import *  # noqa: E402,F401,F403
from .lod import *  # noqa: E402,F401,F403

__all__ = sorted(__all__ + forms.__all__ + brep.__all__ + clustering.__all__
                 + decimation.__all__ + distances.__all__ + lod.__all__)
