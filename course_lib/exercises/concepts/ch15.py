"""The concept questions of chapter 15 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(15, "ch15-shadow-ray",
        "In Whitted ray tracing, how is it decided whether a hit point is in shadow for a "
        "point light?",
        ("By the sign of $\\hat n \\cdot \\hat v$", "That says whether the surface faces the "
         "viewer."),
        ("By casting a shadow ray from the point towards the light and checking for a hit "
         "before the light", "If anything lies between, the light's diffuse and specular "
         "contributions are dropped (start slightly off the surface to avoid self-"
         "shadowing)."),
        ("By the depth in the z-buffer", "That is the shadow-map technique of rasterization."),
        ("By the distance to the camera", "Shadows depend on the light, not the camera."),
        correct=1),
    _tf(15, "ch15-whitted-diffuse",
        "Classic (Whitted) recursive ray tracing captures mirror reflections and refraction "
        "but not diffuse inter-reflection (colour bleeding).", True,
        "It spawns only the reflected and refracted rays; diffuse light bouncing between "
        "surfaces needs path tracing or radiosity.",
        "It is true: diffuse inter-reflection is left to the ambient term."),
    _mc(15, "ch15-tir",
        "A ray leaves glass ($n_1 = 1.5$) into air ($n_2 = 1$). When is there no refracted ray?",
        ("Never", "Going from dense to less dense, large angles have no solution of Snell's "
         "law."),
        ("When the angle of incidence exceeds $\\arcsin(n_2 / n_1) \\approx 41.8°$",
         "Snell's law would need $\\sin\\theta_t > 1$: total internal reflection."),
        ("When the angle of incidence is below $41.8°$", "Small angles refract normally."),
        ("Always: light cannot leave glass", "It can, below the critical angle."),
        correct=1),
    _mc(15, "ch15-reflect",
        "The mirror direction of the incoming direction $\\vec d$ at a surface with unit normal "
        "$\\hat n$ is:",
        ("$\\vec d + 2(\\vec d \\cdot \\hat n)\\hat n$", "The sign is wrong: this keeps the "
         "tangential component and triples the normal one ($(\\vec d \\cdot \\hat n)\\hat n$ "
         "becomes $3(\\vec d \\cdot \\hat n)\\hat n$), so the length changes too (unless "
         "$\\vec d$ runs along the surface)."),
        ("$\\vec d - (\\vec d \\cdot \\hat n)\\hat n$", "That removes the normal component: "
         "a projection onto the surface, not a reflection."),
        ("$\\hat n - \\vec d$", "Not a reflection; its length is not even kept."),
        ("$\\vec d - 2(\\vec d \\cdot \\hat n)\\hat n$", "The normal component changes sign, "
         "the tangential one stays: the length is kept."),
        correct=3),
    _tf(15, "ch15-sphere-quadratic",
        "Intersecting a ray $o + t\\vec d$ with a sphere leads to a quadratic equation in $t$; "
        "a negative discriminant means the ray misses.", True,
        "Substituting the ray into $\\|p - C\\|^2 = r^2$ (centre $C$, radius $r$) gives "
        "$at^2 + bt + c = 0$ with $a = \\vec d \\cdot \\vec d$, $b = 2\\,\\vec d \\cdot (o - C)$, "
        "$c = \\|o - C\\|^2 - r^2$; the nearest hit is the smallest positive root.",
        "It is so: no real root, no intersection."),
    _mc(15, "ch15-acceleration",
        "What does a bounding volume hierarchy (BVH) change in ray tracing?",
        ("It makes the image more accurate", "The image is the same; only the speed changes."),
        ("It reduces the intersection tests per ray from linear to roughly logarithmic in the "
         "number of primitives", "A ray skips every subtree whose box it misses."),
        ("It removes the need for shadow rays", "Shadow rays are still cast (and sped up too)."),
        ("It is needed for refraction", "Refraction works without it."),
        correct=1),
    _tf(15, "ch15-recursion-depth",
        "Recursive ray tracing needs a depth limit (or a contribution threshold), because two "
        "facing mirrors would reflect forever.", True,
        "Each reflection spawns another ray; stopping at a maximum depth or when the weight "
        "becomes negligible ends the recursion.",
        "It does: without a limit the recursion may not end."),
    _mc(15, "ch15-antialias",
        "How does a ray tracer reduce jagged edges (aliasing)?",
        ("By tracing several rays per pixel (supersampling, possibly jittered) and averaging",
         "Averaging estimates the pixel's area coverage instead of a single point sample."),
        ("By increasing the recursion depth", "Depth concerns reflections, not edges."),
        ("By using point lights", "Lights do not change the sampling of the pixel."),
        ("By mipmapping the scene", "Mipmaps filter textures, not geometric edges."),
        correct=0),
    _tf(15, "ch15-point-light-hard",
        "With point lights a ray tracer produces soft shadows with penumbrae.", False,
        "A point is either seen from the light or not: shadows are hard. Soft shadows need area "
        "lights sampled with several shadow rays.",
        "Right: a single shadow ray per point light gives hard shadow edges."),
    _mc(15, "ch15-primary-rays",
        "How many primary rays does a basic ray tracer cast?",
        ("One per light source", "Shadow rays go to lights; primary rays go through pixels."),
        ("One per primitive", "That is object-order thinking (rasterization)."),
        ("One per pixel, from the eye through the pixel centre", "Every pixel gets its colour "
         "from the nearest hit of its primary ray and the rays spawned there."),
        ("One for the whole image", "Each pixel needs its own ray."),
        correct=2),
    # Spatial subdivision (lesson section "Spatial subdivision: grids, octrees and kd-trees")
    _tf(15, "ch15-teapot-stadium",
        "A uniform grid copes well with a small, finely tessellated object in a huge, mostly "
        "empty scene (the 'teapot in a stadium'), because the number of cells follows the "
        "number of triangles.", False,
        "The cells are all the same size, chosen for the whole stadium: the teapot ends up in "
        "one or a few cells holding all its triangles, and a ray through it tests them all. "
        "Octrees and kd-trees adapt: they subdivide only where the triangles are.",
        "Right: a grid's resolution is the same everywhere, so a dense object in a large empty "
        "scene falls into a handful of crowded cells; adaptive structures (octree, kd-tree, "
        "BVH) subdivide where the geometry is."),
    _mc(15, "ch15-object-vs-space",
        "How does space subdivision (grid, octree, kd-tree) differ from object subdivision "
        "(a BVH)?",
        ("Space subdivision cuts space into cells that do not overlap, so a triangle crossing a "
         "cell wall is listed in several cells; a BVH puts each triangle in exactly one leaf, "
         "but sibling boxes may overlap",
         "That is the trade-off: ordered, disjoint cells (a ray can stop at the first cell "
         "holding a hit) against duplicated references, versus no duplicates but overlapping "
         "boxes a ray may have to look into both."),
        ("Space subdivision never tests a triangle twice for the same ray, even without "
         "mailboxing", "A triangle listed in several cells is met again in each of them: "
         "mailboxing exists to skip those repeated tests."),
        ("A BVH's boxes never overlap", "Sibling boxes of a BVH can overlap: they bound "
         "groups of objects, not disjoint regions of space."),
        ("Only a BVH can skip the empty parts of space", "Empty grid cells and empty tree "
         "leaves are skipped just as cheaply (no triangle to test)."),
        correct=0),
    _mc(15, "ch15-mailboxing",
        "What does mailboxing do in a grid or a kd-tree traversal?",
        ("It remembers, per triangle, the last ray tested against it, so that a triangle listed "
         "in several cells is tested only once per ray", "It saves repeated tests and never "
         "changes the hit found."),
        ("It stores the nearest hit of each cell so that rays need no triangle tests",
         "Hits depend on the ray: nothing per cell can replace the tests."),
        ("It sends the rays that hit the same cell together as a packet", "That is ray "
         "packeting, a different optimization."),
        ("It stops the traversal at the first triangle hit", "The first triangle hit is not "
         "necessarily the nearest: the walk stops only when the nearest hit so far lies inside "
         "the current cell."),
        correct=0),
    _tf(15, "ch15-grid-early-exit",
        "In a uniform grid, the first hit found while testing the triangles of a cell may be "
        "accepted at once, since the cells are visited front to back.", False,
        "A triangle listed in this cell may stick out of it and be hit beyond it, while a "
        "triangle in the next cell is hit earlier. The walk stops only when the nearest hit so "
        "far is no farther than where the ray leaves the current cell.",
        "Right: the hit must lie inside the current cell (t no larger than the cell's exit "
        "parameter) before the walk may stop."),
]
