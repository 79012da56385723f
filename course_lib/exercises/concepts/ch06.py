"""The concept questions of chapter 6 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(6, "ch06-manifold-edge",
        "In a closed 2-manifold polygon mesh, how many faces share each edge?",
        ("Exactly two", "Around every point the surface looks like a disk, so an edge has one "
         "face on each side; a boundary edge (one face) only appears on a surface with a "
         "boundary."),
        ("At least two", "Three or more faces at an edge (a 'fin') make the mesh non-manifold: "
         "no disk-shaped neighbourhood around the edge."),
        ("One or two", "One face means a boundary edge: the mesh would not be closed."),
        ("Any number, as long as the faces are triangles", "The face type does not matter; "
         "the count does."),
        correct=0),
    _tf(6, "ch06-euler-sphere",
        "Every closed polyhedral mesh that is topologically a sphere satisfies "
        "$V - E + F = 2$.", True,
        "A cube gives $8 - 12 + 6 = 2$, a tetrahedron $4 - 6 + 4 = 2$: the Euler "
        "characteristic depends only on the topology, not on the tessellation.",
        "It does hold for all of them (cube, tetrahedron, any triangulated sphere)."),
    _mc(6, "ch06-euler-genus",
        "A closed orientable manifold mesh has genus $g$ (number of handles, a torus has 1). "
        "What is $V - E + F$?",
        ("$2 + 2g$", "The sign is wrong: each handle *lowers* the Euler characteristic by 2."),
        ("$2 - g$", "Each handle lowers it by 2, not by 1."),
        ("$2 - 2g$", "A sphere gives 2, a torus 0, a two-holed torus $-2$."),
        ("Always 2", "Only for genus 0; a torus gives 0."),
        correct=2),
    _tf(6, "ch06-closed-triangle-count",
        "In a closed triangle mesh that is a 2-manifold, $3F = 2E$.", True,
        "Each triangle has 3 edges and each edge is shared by exactly 2 triangles, so counting "
        "edge-face incidences gives $3F = 2E$.",
        "It holds: 3 edges per triangle, 2 triangles per edge."),
    _mc(6, "ch06-halfedge-stores",
        "What does a half-edge typically store?",
        ("Its two end vertices, both faces and four neighbouring edges",
         "That is a winged edge; a half-edge keeps only one side of the edge."),
        ("Only the coordinates of its end points", "Then no neighbourhood could be walked "
         "without a search."),
        ("A list of all faces of the mesh", "That would cost $O(F)$ per edge."),
        ("The vertex it points to (or starts from), its face, the next half-edge around that "
         "face, and its twin", "With these the one-ring of a vertex or the loop of a face is "
         "walked in constant time per step: next, twin, next, ..."),
        correct=3),
    _tf(6, "ch06-halfedge-twin",
        "In a half-edge mesh, the twin of the twin of a half-edge is the half-edge itself.", True,
        "Each edge is split into two oppositely oriented halves that point to each other.",
        "It is: twin is an involution, the two halves of one edge refer to each other."),
    _tf(6, "ch06-halfedge-nonmanifold",
        "A plain half-edge structure can represent an edge shared by three faces.", False,
        "It cannot: an edge has exactly two halves, one per side, so a third face has no "
        "half-edge to use. Half-edge meshes are limited to (possibly bounded) manifolds.",
        "Right: two halves per edge means at most two faces per edge: non-manifold edges do "
        "not fit."),
    _mc(6, "ch06-edge-collapse",
        "Iterative edge collapse with the quadric error metric (QEM): which edge is collapsed "
        "next?",
        ("The longest edge", "Length alone ignores the shape: a long edge on a flat region "
         "can be removed cheaply, a short one on a sharp feature cannot."),
        ("The edge whose collapse adds the least error, i.e. the smallest quadric cost",
         "Edges sit in a priority queue keyed by the error of the best new vertex position; "
         "after each collapse the costs of the neighbouring edges are updated."),
        ("The edge furthest from the viewer", "View-dependent simplification exists, but QEM "
         "ranks edges by geometric error."),
        ("A random edge", "Random collapses destroy features; QEM orders them by cost."),
        correct=1),
    _mc(6, "ch06-qem-meaning",
        "What does the quadric of a vertex measure in QEM simplification?",
        ("The sum of squared distances from a point to the planes of the faces around the "
         "original vertex", "The quadric $Q$ is a sum of plane terms; $v^T Q v$ is that sum of "
         "squared distances, and minimizing it gives the new vertex position."),
        ("The curvature of the surface", "It is related, but it measures squared distances to "
         "planes, not curvature directly."),
        ("The number of faces around the vertex", "That is the valence."),
        ("The length of the collapsed edge", "The cost is a distance to planes, not the edge "
         "length."),
        correct=0),
    _tf(6, "ch06-volume-needs-closed",
        "A solid (volume) representation can be built only for an object whose surface is "
        "closed.", True,
        "Inside and outside are only defined when the surface encloses a region.",
        "It is needed: an open surface does not separate inside from outside."),
    _tf(6, "ch06-clustering-topology",
        "Vertex clustering on a uniform grid always keeps the genus of the model.", False,
        "It does not: a hole or a gap smaller than a cell has all its rim vertices merged into "
        "a few representatives, so the hole closes (or thin parts merge); the result need not "
        "even be manifold.",
        "Right: the grid ignores the topology, holes smaller than a cell close."),
    _tf(6, "ch06-decimation-subset",
        "After vertex decimation (removing vertices and re-triangulating the holes) every vertex "
        "of the simplified mesh is a vertex of the original mesh.", True,
        "It is: decimation deletes vertices and never moves or creates one (unlike a full-edge "
        "collapse, which puts the merged vertex at a new, optimised position).",
        "Right: the survivors are a subset of the original vertices, at their places."),
    _mc(6, "ch06-hausdorff-one-sided",
        "A small patch A lies exactly on a large surface B. Which is true?",
        ("d(A -> B) = 0 but d(B -> A) is large, so the Hausdorff distance is large",
         "Every point of A is on B (distance 0), but points of B far from the patch are far "
         "from A; the Hausdorff distance takes the larger of the two."),
        ("Both one-sided distances are 0", "Only d(A -> B) is 0: the far parts of B have no "
         "point of A near them."),
        ("The Hausdorff distance is 0 because A is on B", "That is the one-sided distance from "
         "A; the symmetric distance also looks from B."),
        ("d(A -> B) is large and d(B -> A) = 0", "The other way round: A's points are on B."),
        correct=0),
    _mc(6, "ch06-half-edge-collapse",
        "What distinguishes a half-edge collapse u -> w from a full-edge collapse (u, w) -> v?",
        ("u moves onto w: no new position, so its quadric cost is never below the full "
         "collapse's optimum", "The full collapse minimises the cost over all positions, w is "
         "one of them; in exchange the half-edge collapse keeps the original vertices (good "
         "for progressive meshes and vertex buffers)."),
        ("It removes one face instead of two", "Both remove the two faces of the edge (one on a "
         "boundary)."),
        ("It only works on boundary edges", "It works on any edge; QEM's boundary rule is a "
         "half-edge collapse onto the boundary vertex."),
        ("It is always cheaper than the full collapse", "It can only cost as much or more: its "
         "position is one of the positions the full collapse chooses among."),
        correct=0),
]
