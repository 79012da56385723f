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
    # Distributed ray tracing (issue 22)
    _mc(15, "ch15-distributed-noise",
        "A distributed ray tracer averages $N$ independent random samples per pixel. By what "
        "factor does the noise (the standard deviation of a pixel) fall when $N$ is "
        "quadrupled?",
        ("By a factor of 4", "That would be an error falling like $1/N$; the standard deviation of a mean of "
         "$N$ independent samples falls like $1/\\sqrt{N}$."),
        ("By a factor of 2", "The standard deviation of the mean is $\\sigma/\\sqrt{N}$: four times the "
         "samples halve the noise (stratified samples do somewhat better)."),
        ("By a factor of 16", "Far too optimistic: no Monte Carlo estimate improves like $1/N^2$."),
        ("It does not fall: random samples always stay noisy", "The noise does fall, only "
         "slowly: like $1/\\sqrt{N}$."),
        correct=1),
    _mc(15, "ch15-distributed-dof",
        "In distributed ray tracing, depth of field comes from spreading the camera rays "
        "over...",
        ("the light source's area", "That gives soft shadows (a penumbra), not focus blur."),
        ("the lens aperture, all rays of a pixel meeting again on the plane in focus",
         "Points on the focal plane are hit by all of a pixel's rays (sharp); nearer or "
         "further points are spread over a circle of confusion."),
        ("the time the shutter is open", "That gives motion blur of moving objects only."),
        ("the pixel's area", "That is antialiasing: a blur of at most one pixel, the same at "
         "every depth."),
        correct=1),
    _tf(15, "ch15-distributed-cost",
        "Rendering soft shadows, glossy reflection, depth of field and motion blur together "
        "with 16 samples for each effect needs $16^4 = 65536$ rays per pixel.", False,
        "Cook's trick: each of the 16 paths of a pixel gets its own lens point, time, light "
        "point and reflection direction (each dimension stratified and shuffled), so 16 paths "
        "estimate all the integrals at once.",
        "Right: the dimensions are sampled together, one sample of each per path, not as a "
        "product grid."),
    # Quadrics and implicit surfaces
    _mc(15, "ch15-cylinder-normal",
        "A ray hits the cylinder $x^2 + y^2 = r^2$ (axis $z$) at the point $p = (x, y, z)$. "
        "What is the outward unit normal there?",
        ("$(x, y, z) / \\|p\\|$", "That is the sphere's normal: it tilts up or down with $z$, "
         "but the cylinder's equation has no $z$ term."),
        ("$(x/r,\\ y/r,\\ 0)$", "The gradient of $x^2 + y^2 - r^2$ is $(2x, 2y, 0)$: "
         "horizontal, away from the axis, of length $2r$."),
        ("$(0, 0, 1)$", "That is the axis direction, tangent to the side wall (it is the normal "
         "of the top cap)."),
        ("$(x, y, 0)$", "The right direction, but its length is $r$: a normal for shading must be "
         "a unit vector."),
        correct=1),
    _tf(15, "ch15-quadric-a-direction-only",
        "For a ray $o + t\\,d$ and a quadric $\\tilde x^T Q \\tilde x = 0$, the coefficient "
        "$a$ of $t^2$ depends only on the direction $d$, not on the origin $o$.", True,
        "$a = \\tilde d^T Q \\tilde d$ with $\\tilde d = (d, 0)$: only the $t^2$ terms, made of "
        "$d$ alone. $a = 0$ (a ray along a cylinder's axis or a cone's side) leaves a linear "
        "equation.",
        "It is true: the origin enters $b$ and $c$ only."),
    _tf(15, "ch15-implicit-sampling",
        "Marching along a ray with a fixed step and looking for a change of sign of $f$ finds "
        "every intersection with an implicit surface $f = 0$.", False,
        "A part thinner than one step can lie between two samples of the same sign, and a "
        "tangent touch never changes sign: both are missed. The step must be smaller than the "
        "thinnest feature (or bounded by a Lipschitz constant, as in sphere tracing).",
        "Right: sampling can miss thin parts and grazing touches."),
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
