r"""Chapter 6 exercises: polygon meshes, their data structures and QEM simplification, exam style.

Each class is one kind of exam question: the counts of a closed mesh from Euler's formula, the
genus of a mesh with holes, the counts after a number of edge collapses; which of four kinds a
small face list is (closed manifold, manifold with boundary, non-manifold edge, non-manifold
vertex), which face of a closed mesh is flipped; a winged-edge record filled in from a face list,
a walk through a half-edge table and the one-ring of a vertex by the rotation
:math:`h \leftarrow \operatorname{twin}(\operatorname{prev}(h))`; a vertex quadric of
Garland and Heckbert's error metric, the cost of an edge collapse, and the optimal position of
the merged vertex. The ``seed`` draws numbers that work out by hand: small meshes (tetrahedron,
square pyramid, triangular prism, octahedron) with shuffled vertex labels, planes with simple
normals through points with whole coordinates.

The expected answers come from :mod:`course_lib.mesh`. Each exercise names the slips it
anticipates (the genus term or its factor 2 forgotten, the boundary loops ignored, left and
right face swapped, ``next`` and ``prev`` mixed up, the composition read the wrong way, a
clockwise turn, only the edges checked for manifoldness, an unnormalised plane, a forgotten
homogeneous 1, ...), computes the answer each slip would give, and draws its numbers again
until those answers differ clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.mesh`): faces list their vertices counter-clockwise seen
from outside; half-edge ``h`` of face ``f`` runs from a vertex of ``f`` to the next one;
edge ``e`` of a winged-edge table runs from ``start`` to ``end``, its **left** face walks it
from start to end and its **right** face from end to start; a plane is
:math:`(a, b, c, d)` with :math:`ax + by + cz + d = 0` and :math:`a^2 + b^2 + c^2 = 1`, and its
quadric is :math:`K_p = p p^T`.

The exercises live in :mod:`course_lib.exercises._ch06`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch06.euler import EdgeCollapseCounts, EulerCounts, GenusFromCounts
from ._ch06.manifolds import MESH_KINDS, FlippedFace, Manifoldness
from ._ch06.edge_records import HalfEdgeWalk, OneRing, WingedEdgeRecord
from ._ch06.quadrics import CollapseCost, OptimalPosition, VertexQuadric
from ._ch06.forms import BRepEulerRings, ChooseModelForm
from ._ch06.decimation import ClusterSurvivors, DecimationCriterion, HausdorffByHand
from ._ch06.lod import LODChoice, SplitRecord
from ._ch06 import _SMALL, _shuffled  # used by the tests

__all__ = [
    "EXERCISES",
    "MESH_KINDS",
    "CollapseCost",
    "EdgeCollapseCounts",
    "EulerCounts",
    "FlippedFace",
    "GenusFromCounts",
    "HalfEdgeWalk",
    "Manifoldness",
    "OneRing",
    "OptimalPosition",
    "VertexQuadric",
    "WingedEdgeRecord",
    # the newer sections: forms and B-reps, clustering and decimation, level of detail
    "BRepEulerRings",
    "ChooseModelForm",
    "ClusterSurvivors",
    "DecimationCriterion",
    "HausdorffByHand",
    "LODChoice",
    "SplitRecord",
]

#: The exercises of chapter 6, in the order of the solutions notebook.
EXERCISES = (
    EulerCounts,
    GenusFromCounts,
    EdgeCollapseCounts,
    Manifoldness,
    FlippedFace,
    WingedEdgeRecord,
    HalfEdgeWalk,
    OneRing,
    VertexQuadric,
    CollapseCost,
    OptimalPosition,
    # the forms of a model and boundary representations with rings
    BRepEulerRings,
    ChooseModelForm,
    # other simplification methods: vertex clustering, decimation, Hausdorff distance
    ClusterSurvivors,
    DecimationCriterion,
    HausdorffByHand,
    # level of detail: the screen-space error and progressive-mesh records
    LODChoice,
    SplitRecord,
)
