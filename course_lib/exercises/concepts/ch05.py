"""The concept questions of chapter 5 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(5, "ch05-backface-sign",
        "A closed opaque mesh has outward normals $\\vec n$. With $\\vec v$ the vector **from "
        "the eye to a point of a face**, when is the face a back face?",
        ("When $\\vec v \\cdot \\vec n < 0$", "Then the normal points towards the eye: the face "
         "is turned to the viewer (a front face). The sign is often stated the wrong way round."),
        ("When $\\vec v \\cdot \\vec n = 1$", "The test is about the sign of the dot product, "
         "not its size."),
        ("When $\\vec v \\cdot \\vec n > 0$", "The normal points away from the eye, along the "
         "line of sight: the face shows its back and is hidden by the front of the same closed "
         "object."),
        ("When $\\vec v \\times \\vec n = \\vec 0$", "Parallel vectors mean the face is seen "
         "straight on or straight from behind; the cross product cannot tell which."),
        correct=2),
    _tf(5, "ch05-backface-enough",
        "For a single closed convex object, back-face culling alone solves hidden-surface "
        "removal.", True,
        "On a convex closed object every front face is fully visible and every back face is "
        "hidden, and no two front faces overlap on screen.",
        "For one convex closed object it does suffice; for non-convex objects or several "
        "objects, front faces can hide each other and a z-buffer (or similar) is needed."),
    _tf(5, "ch05-backface-open",
        "Back-face culling can safely be used on an open surface such as a single sheet of "
        "paper.", False,
        "It cannot: the back of an open surface can be seen directly (nothing of the same "
        "object hides it), so culling would make it disappear.",
        "Right: culling relies on the object being closed and opaque, so that the front of the "
        "object always covers its back."),
    _mc(5, "ch05-cohen-sutherland",
        "In Cohen-Sutherland line clipping the end points get outcodes $c_1$ and $c_2$. What "
        "can be concluded when $c_1 \\wedge c_2 \\ne 0$ (bitwise AND)?",
        ("The segment lies entirely inside the window", "That is the case $c_1 \\vee c_2 = 0$: "
         "both end points inside."),
        ("The segment crosses the window and must be clipped", "When the AND is zero and the OR "
         "is not, it *may* cross: it has to be clipped to find out."),
        ("The segment lies entirely outside: reject it", "Both end points are on the outer side "
         "of the same boundary line (plane), so the whole segment is too."),
        ("Nothing: the outcodes must be recomputed", "The AND test is exactly the trivial "
         "reject test; no recomputation is needed."),
        correct=2),
    _tf(5, "ch05-cs-or-nonzero",
        "If the AND of the two outcodes is zero, the segment intersects the clipping window.",
        False,
        "Not necessarily: a segment from just above the window to just right of it can pass "
        "outside the corner, though its end points lie outside different boundaries. Such "
        "segments are clipped step by step and rejected later.",
        "Right: a zero AND only rules out the trivial rejection; a segment can still pass by a "
        "corner of the window."),
    _mc(5, "ch05-which-clipper",
        "Which algorithm clips a **polygon** against a convex clip region, one boundary at a "
        "time, producing a new polygon?",
        ("Liang-Barsky", "Liang-Barsky clips a line segment, using its parametric form and the "
         "entering/leaving parameters."),
        ("Cohen-Sutherland", "Cohen-Sutherland clips line segments using outcodes."),
        ("Ray casting", "Ray casting finds the nearest surface per pixel; it does not clip."),
        ("Sutherland-Hodgman", "It passes the polygon's vertex list through one clipper per "
         "boundary (plane), each emitting the inside vertices and the crossing points."),
        correct=3),
    _mc(5, "ch05-liang-barsky",
        "What does Liang-Barsky compute for the segment $p(t) = p_0 + t(p_1 - p_0)$, "
        "$t \\in [0, 1]$?",
        ("The largest entering parameter $t_E$ and the smallest leaving parameter $t_L$; the "
         "segment is rejected when $t_E > t_L$", "Each boundary gives one inequality in $t$; the "
         "visible part is $[t_E, t_L]$ (starting from $[0, 1]$)."),
        ("The outcodes of the two end points", "That is Cohen-Sutherland."),
        ("The smallest entering and the largest leaving parameter", "The other way round: the "
         "segment is inside only after it has entered through *all* boundaries (largest entry) "
         "and before it leaves through *any* (smallest exit)."),
        ("The intersection of the segment with each polygon edge", "That is closer to "
         "Sutherland-Hodgman's per-edge work; Liang-Barsky clips against an axis-aligned box."),
        correct=0),
    _tf(5, "ch05-occlusion-conservative",
        "Occlusion culling is conservative: it may keep primitives that turn out hidden, but it "
        "never removes a visible one.", True,
        "Culling only discards what is certainly hidden; whatever it leaves is resolved by the "
        "z-buffer, so an extra primitive costs time but never a wrong picture.",
        "It must be conservative: removing a visible primitive would leave a hole in the image, "
        "while keeping a hidden one only costs time."),
    _mc(5, "ch05-zbuffer",
        "Which statement about the z-buffer algorithm is right?",
        ("It needs the polygons sorted by depth", "It does not: each pixel keeps the nearest "
         "depth so far, so polygons can come in any order."),
        ("Its cost grows with the number of primitives and pixels covered, and it needs one "
         "depth value of memory per pixel", "It processes each primitive once, compares depth "
         "per covered pixel, and stores a depth buffer next to the colour buffer."),
        ("It handles transparent surfaces correctly in any order", "It keeps one surface per "
         "pixel; transparency needs sorting or special techniques."),
        ("It works in object space with exact precision", "It works in image space, with a "
         "depth resolution limited by the buffer's bits (z-fighting)."),
        correct=1),
    _mc(5, "ch05-raycasting-cost",
        "Brute-force ray casting for hidden-surface elimination tests every pixel's ray against "
        "every primitive. With $p$ pixels and $P$ primitives its cost is:",
        ("$O(p + P)$", "Every ray meets every primitive: the costs multiply, they do not add."),
        ("$O(p \\log P)$", "That needs an acceleration structure (a BVH, a grid) which brute "
         "force does not have."),
        ("$O(pP)$", "One intersection test per pixel and primitive; it is, however, trivially "
         "parallel across pixels."),
        ("$O(P^2)$", "Primitives are not tested against each other."),
        correct=2),
    _tf(5, "ch05-painter-cycles",
        "The painter's algorithm (draw back to front) can fail for polygons that overlap each "
        "other cyclically.", True,
        "Three polygons can each lie partly in front of the next; no drawing order is right, "
        "and polygons must be split (as a BSP tree does).",
        "It can fail: cyclic overlap has no valid back-to-front order, so polygons must be "
        "split first."),
    # hierarchical occlusion culling: the z-pyramid, occlusion queries, occlusion maps
    _tf(5, "ch05-hzb-conservative",
        "The hierarchical z-buffer may reject a bounding box that the full per-pixel depth test "
        "would show as partly visible.", False,
        "It cannot: each coarse texel holds the farthest depth of the pixels below it, so a box "
        "behind every covering texel is behind every pixel of its rectangle. The reverse "
        "mistake does happen: it may keep a box that is in fact hidden.",
        "Right: the test is conservative. A texel's value is the maximum of its pixels, so "
        "passing the coarse test implies passing the per-pixel one; only hidden boxes are ever "
        "rejected (some hidden ones are kept)."),
    _mc(5, "ch05-zpyramid-reduction",
        "A texel of the next level of a z-pyramid (hierarchical z-buffer) stores, of the 2 x 2 "
        "texels below it:",
        ("the average depth", "An average promises nothing about each pixel: a box behind the "
         "average may still be in front of a pixel that is farther."),
        ("the nearest (smallest) depth", "A box behind the nearest depth may still be in front "
         "of the other three texels: rejecting it would be wrong."),
        ("the farthest (largest) depth", "Then 'behind the texel' means behind every pixel it "
         "covers, which makes the rejection test safe."),
        ("the depth of the last texel drawn", "Drawing order does not matter to the pyramid; it "
         "summarizes the depth buffer as it is."),
        correct=2),
    _mc(5, "ch05-occlusion-query-cost",
        "What makes hardware occlusion queries (draw the bounding box, count the samples that "
        "pass the depth test) expensive if used naively?",
        ("Counting the samples needs a second depth buffer", "The query uses the ordinary depth "
         "buffer with depth and colour writes off; it adds a counter, not a buffer."),
        ("The result comes back only after the GPU has drawn the proxy: waiting for it stalls "
         "the CPU and starves the GPU", "This latency is why renderers issue queries early, "
         "use last frame's answers (temporal coherence) or test hierarchies of boxes."),
        ("The query must read every pixel of the screen", "It rasterizes only the proxy's "
         "pixels; a small box costs little fill."),
        ("It works only when objects are drawn back to front", "The opposite: front-to-back "
         "order fills the depth buffer with near occluders first, so later queries find them; "
         "back to front nothing is ever hidden yet."),
        correct=1),
    _mc(5, "ch05-hom-approximate",
        "Hierarchical occlusion maps cull a box when the covering texels' opacity is at least "
        "a threshold (say 0.9) and the box is behind the depth estimate. Why is this "
        "approximate culling?",
        ("Because the opacity pyramid takes the maximum of 2 x 2 texels", "It averages: a texel "
         "is the fraction of its pixels covered by occluders."),
        ("Because a texel that is 90 % covered may let the box show through the other 10 %",
         "With a threshold below 1 a box seen through small gaps can be culled: a few pixels "
         "may be wrong, traded for more culling."),
        ("Because the depth test uses the box's farthest depth", "It uses the box's nearest "
         "depth against the farthest occluder depth of the tile: that part is conservative."),
        ("Because the occluders are drawn at lower resolution than the screen", "A coarser "
         "map costs accuracy in what counts as covered, but the approximation the threshold "
         "introduces is the one asked about."),
        correct=1),

    # Issue 21: BSP trees by hand (course_lib.visibility.bsp2d)
    _mc(5, "ch05-bsp-traversal",
        "The eye lies in front of the partition line of a BSP node. In which order does the "
        "painter's traversal draw what is stored at and below that node?",
        ("The front subtree, the node, then the back subtree", "That is front to back: the "
         "subtree on the eye's side is drawn first and then painted over by the far side."),
        ("The back subtree, the node, then the front subtree", "The far side first: nothing in "
         "the back half-plane can hide the node or the front half-plane from this eye."),
        ("The node, then the back subtree, then the front subtree", "The node may hide parts of "
         "the back subtree, so it must be drawn after it, not before."),
        ("The nearer of the two subtrees by distance to its first segment", "No distances are "
         "compared: one sign test of the eye against the node's line decides."),
        correct=1),
    _tf(5, "ch05-bsp-any-viewpoint",
        "A BSP tree built once for a static plan gives a correct back-to-front order from every "
        "eye position; only the traversal (one side test per node) changes when the eye moves.",
        True,
        "The tree depends on the segments only; the eye enters only through the side test at "
        "each node, so moving the eye reorders the traversal without rebuilding.",
        "It is true: the tree is view-independent, and the eye only decides, node by node, "
        "which subtree is painted first."),
    _tf(5, "ch05-bsp-root-whole",
        "When a BSP tree takes its partitions in a given order, the first segment of that order "
        "is never split.", True,
        "It becomes the root's partition before any other line exists, and a segment is only "
        "cut by the lines of nodes above it.",
        "It is true: the root's segment is the partition itself and is stored whole; only "
        "segments placed below a partition can be cut by its line."),
    _mc(5, "ch05-clip-space-why",
        "Why is clipping done in clip space, against $-w \\le x, y, z \\le w$, before the "
        "perspective divide, rather than against the cube $[-1, 1]^3$ after it?",
        ("It only saves time: clipping after the divide gives the same picture", "Not when a "
         "segment has one end behind the eye ($w < 0$): there the two routes give different "
         "segments, and only clipping before the divide is right."),
        ("A segment with an end behind the eye ($w < 0$) passes through $w = 0$; dividing first "
         "sends that end through infinity to the mirrored side, and the divided segment is the "
         "image of the wrong part of the line", "Right: before the divide the six conditions "
         "are linear in $(x, y, z, w)$ and remove everything with $w \\le 0$ exactly."),
        ("The perspective projection does not map straight lines to straight lines", "It does, "
         "for points in front of the eye; the trouble is only the points behind it."),
        ("The NDC cube is not convex, so Liang-Barsky cannot be used after the divide", "The "
         "cube is convex; Liang-Barsky works there for segments entirely in front of the eye."),
        correct=1),
    _tf(5, "ch05-clip-space-w-negative",
        "A homogeneous point with $w < 0$ can satisfy all of $-w \\le x, y, z \\le w$.", False,
        "It cannot: $-w \\le x \\le w$ needs $w \\ge |x| \\ge 0$, so every point behind the "
        "eye gets a non-zero outcode and is clipped away without any division.",
        "Right: $-w \\le x \\le w$ forces $w \\ge |x| \\ge 0$."),
    _tf(5, "ch05-clip-space-t-world",
        "The parameter $t$ at which Liang-Barsky clips a segment in clip space is also the "
        "parameter of the clipped point on the segment in world coordinates.", True,
        "The projection and view matrices are linear maps of homogeneous coordinates, so "
        "$M(P_0 + t(P_1 - P_0)) = MP_0 + t(MP_1 - MP_0)$: the same $t$ (after the divide, "
        "in NDC, it is not, since the divide is not linear).",
        "It is: $M$ is linear on homogeneous coordinates, so the clip-space segment is the "
        "image of the world segment with the same parameter (only the NDC parameter differs)."),
]
