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
    # the forms of a model and boundary representations with rings
    _mc(6, "ch06-brep-euler-rings",
        "A block has one square hole drilled right through it. Its B-rep has $V = 16$, "
        "$E = 24$, $F = 10$ and one shell. Which counts satisfy the Euler-Poincaré formula "
        "$V - E + F - R = 2(S - H)$?",
        ("$R = 0$, $H = 1$", "The hole leaves an inner loop (ring) in the top face and one "
         "in the bottom face: $16 - 24 + 10 - 0 = 2 \\ne 0$."),
        ("$R = 2$, $H = 1$", "Two rings (top and bottom mouth of the hole) and one "
         "through-hole: $16 - 24 + 10 - 2 = 0 = 2(1 - 1)$."),
        ("$R = 1$, $H = 1$", "A through-hole opens in two faces, so it makes two rings, "
         "not one; and $16 - 24 + 10 - 1 = 1$ is odd, never $2(S - H)$."),
        ("$R = 2$, $H = 0$", "With $H = 0$ the right side is 2, but the left side is 0: the "
         "hole goes through, it is a handle."),
        correct=1),
    _tf(6, "ch06-pocket-no-hole",
        "A blind pocket milled into the top face of a block adds a ring but no through-hole.",
        True,
        "The pocket's rim is an inner loop of the top face ($R = 1$), its floor closes it: the "
        "block stays of genus 0, e.g. $16 - 24 + 11 - 1 = 2 = 2(1 - 0)$.",
        "It does: the pocket has a floor, so nothing goes through; only the rim of its mouth "
        "is a ring."),
    _mc(6, "ch06-form-inside-test",
        "For which form of a model is 'is this point inside the solid?' a single cheap "
        "evaluation?",
        ("A polygon mesh", "A mesh needs a ray cast that counts crossings with its triangles."),
        ("A point cloud", "Points on a surface have no inside at all."),
        ("A parametric patch", "A patch $p(u, v)$ is easy to evaluate but has no inside test: "
         "the nearest point must be searched for."),
        ("An implicit surface or a CSG tree of them", "The sign of $f(p)$ answers it; for CSG "
         "union is min, intersection max, difference $\\max(a, -b)$ of the signed values."),
        correct=3),
    _tf(6, "ch06-voxel-memory",
        "Doubling the resolution of a voxel grid doubles its memory.", False,
        "It multiplies it by $2^3 = 8$: the grid has $n^3$ cells.",
        "Right: $n^3$ cells, so twice the resolution costs 8 times the memory."),
    _mc(6, "ch06-lod-screen-error",
        "An LOD level has geometric error $\\varepsilon$. Seen at distance $d$ through a "
        "perspective camera with vertical field of view $\\theta$ on a viewport $H$ pixels "
        "high, how many pixels does that error cover?",
        ("$\\varepsilon H / (2 d \\tan(\\theta/2))$", "The half-height $d\\tan(\\theta/2)$ "
         "of the view volume at distance $d$ fills half the viewport, $H/2$ pixels."),
        ("$\\varepsilon H / (d \\tan(\\theta/2))$", "Twice too large: the half-height maps "
         "to half the viewport, not to all of it."),
        ("$\\varepsilon H / (2 d \\tan\\theta)$", "The half-height goes with the half-angle: "
         "$\\tan\\theta$ of the full angle is not the half-height per unit distance."),
        ("$\\varepsilon H d / (2 \\tan(\\theta/2))$", "An error further away looks smaller, "
         "so $d$ divides; it does not multiply."),
        correct=0),
    _mc(6, "ch06-lod-which-level",
        "Given a pixel tolerance, which discrete level does a renderer draw?",
        ("The finest level whose screen-space error is within the tolerance", "The finest "
         "level (the original, error 0) always passes: drawing it defeats the purpose of LOD."),
        ("The coarsest level whose screen-space error is within the tolerance", "The cheapest "
         "level that still looks right: fewer faces, no visible difference."),
        ("The level whose face count is closest to the number of pixels covered", "Face "
         "counts are not compared with pixels; the error in pixels is."),
        ("The coarsest level whose geometric error is below the tolerance in pixels",
         "A geometric error is a length in object units; it must be projected to pixels "
         "(it depends on the distance) before it is compared with a pixel tolerance."),
        correct=1),
    _tf(6, "ch06-lod-pm-exact",
        "A progressive mesh built from an edge-collapse record (the base mesh plus the vertex "
        "splits in reverse order) reproduces exactly the mesh the simplification had at every "
        "intermediate face count.", True,
        "Each vertex split is the exact inverse of its collapse (it restores the vertex, its "
        "position, the faces and their corners), so undoing the last collapses one by one "
        "walks back through the same meshes.",
        "It does: a split stores everything its collapse changed, so nothing is approximated."),
    _mc(6, "ch06-lod-geomorph",
        "What does a geomorph do when a progressive mesh switches between two levels?",
        ("It moves each vertex of the finer level from the position of the vertex that stands "
         "for it in the coarser level to its own position, over a few frames", "So the surface "
         "changes continuously: no sudden jump (popping) at the switch."),
        ("It blends the two levels' rendered images with transparency", "That is a "
         "cross-fade between images (alpha blending), which draws both levels, not a geomorph."),
        ("It switches instantly but only when the object is off screen", "That hides the "
         "switch; a geomorph makes it smooth while it is visible."),
        ("It adds the faces of the finer level one at a time in random order", "Faces appear "
         "through vertex splits in the record's order; a geomorph interpolates positions."),
        correct=0),
    _tf(6, "ch06-lod-hysteresis",
        "Hysteresis in LOD selection uses slightly different switch distances for going "
        "coarser and going finer, to stop a level from flickering when the viewer hovers "
        "near a switch distance.", True,
        "With one threshold, small movements back and forth across it switch levels every "
        "frame; a band between the two thresholds keeps the current level.",
        "It is true: the two thresholds form a band in which the level does not change."),
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
