"""The concept questions of chapter 4 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(4, "ch04-projective-preserves",
        "Which property does a perspective (projective) map preserve?",
        ("Ratios of distances along a line", "Not kept: equal steps along a rail look shorter "
         "further away, because each point is divided by its own depth."),
        ("Parallelism", "Parallel lines that are not parallel to the image plane meet at a "
         "vanishing point."),
        ("Straight lines, and the cross ratio of four collinear points",
         "A projective map sends lines to lines, and the cross ratio of four points on a line "
         "is the one ratio it keeps."),
        ("Angles", "Angles are not kept even by affine maps, let alone projective ones."),
        correct=2),
    _tf(4, "ch04-perspective-ratios",
        "The midpoint of a 3D segment projects, under a perspective projection, to the midpoint "
        "of the projected segment.", False,
        "Not in general: the end nearer the eye is magnified more (division by its depth), so "
        "the projected midpoint moves towards the far end. It is right only when both ends have "
        "the same depth.",
        "Right: perspective does not preserve ratios along a line. This is why attributes must "
        "be interpolated perspective-correctly (interpolate $a/w$ and $1/w$)."),
    _tf(4, "ch04-affine-cross-ratio",
        "Every affine map also preserves the cross ratio of four collinear points.", True,
        "An affine map preserves ordinary ratios along a line, and the cross ratio is a ratio of "
        "such ratios; affine maps are a special case of projective ones.",
        "It does preserve it: affine maps keep ratios along a line, hence also the cross ratio "
        "built from them."),
    _mc(4, "ch04-parallel-vs-perspective",
        "What distinguishes a parallel projection from a perspective projection?",
        ("The centre of projection is at infinity, so the projectors are parallel",
         "With the centre infinitely far away, all projecting lines share one direction; sizes "
         "no longer depend on the distance to the viewer."),
        ("It needs a homogeneous divide by $z$", "That is the perspective projection; a "
         "parallel projection leaves $w = 1$."),
        ("Its projectors always hit the plane at an oblique angle",
         "Orthographic projection is parallel with projectors perpendicular to the plane; only "
         "oblique projection uses slanted ones."),
        ("It makes distant objects smaller", "That is foreshortening, the mark of perspective."),
        correct=0),
    _mc(4, "ch04-oblique",
        "What is an oblique projection?",
        ("A perspective projection with a tilted image plane", "It has no centre of projection "
         "at a finite distance: it is parallel."),
        ("A parallel projection whose direction is not perpendicular to the projection plane",
         "Cavalier and cabinet views are examples: the plane faces the viewer, and depth shows "
         "as a slanted offset."),
        ("An orthographic projection onto one of the coordinate planes",
         "That is orthographic: its direction is the plane's normal."),
        ("A projection that keeps the $z$ coordinate unchanged", "An oblique projection onto "
         "the $xy$-plane shifts $x$ and $y$ by amounts proportional to $z$ and sets $z$ to 0."),
        correct=1),
    _mc(4, "ch04-ecs-axes",
        "Given the view direction $\\vec g$ and the up vector $\\vec{up}$ (not necessarily "
        "perpendicular to $\\vec g$), how are the eye-space axes found?",
        ("$z_e = \\vec g$, $x_e = \\vec g \\times \\vec{up}$, $y_e = \\vec{up}$",
         "The eye looks down $-z_e$, so $z_e$ is $-\\vec g$; and $\\vec{up}$ need not be "
         "perpendicular to the view direction, so it cannot be used as $y_e$ directly."),
        ("$z_e = -\\hat g$, $x_e = \\vec{up} \\times z_e$ normalized, $y_e = z_e \\times x_e$",
         "This gives a right-handed orthonormal frame in which the eye looks down $-z_e$; $y_e$ "
         "is the part of $\\vec{up}$ perpendicular to the view direction."),
        ("$x_e = \\vec{up}$, $y_e = \\vec g$, $z_e = x_e \\times y_e$", "The up vector "
         "becomes the vertical axis, not the horizontal one, and again it need not be "
         "perpendicular to $\\vec g$."),
        ("The eye axes are always the world axes; only the origin moves", "The camera may "
         "look in any direction: the axes rotate with it."),
        correct=1),
    _tf(4, "ch04-perspective-depth-nonlinear",
        "After a perspective projection matrix and the homogeneous divide, the depth value in "
        "canonical screen space is a linear function of the eye-space depth $z_e$.", False,
        "It is not: it has the form $a + b/z_e$, so it is spread very unevenly (most of the "
        "range goes to depths near the near plane). It is still monotonic, which is all the "
        "z-buffer needs.",
        "Right: the stored depth is $a + b / z_e$, a monotonic but non-linear function; this is "
        "why a near plane very close to the eye wastes z-buffer precision."),
    _mc(4, "ch04-fov",
        "A symmetric perspective view volume has vertical field of view $\\theta$, aspect ratio "
        "$a$ (width/height) and near plane at distance $n$. What is its top $t$ at the near "
        "plane?",
        ("$t = n \\tan\\theta$", "The full angle $\\theta$ spans from bottom to top; the top "
         "edge is only half of it above the axis."),
        ("$t = a\\, n \\tan\\tfrac\\theta2$", "The aspect ratio gives the right edge "
         "$r = a\\,t$, not the top."),
        ("$t = n \\sin\\tfrac\\theta2$", "The half height is the side opposite the half angle "
         "in a right triangle whose adjacent side is $n$: that is a tangent."),
        ("$t = n \\tan\\tfrac\\theta2$", "Half the field of view lies above the viewing axis, "
         "and at distance $n$ the opposite side is $n\\tan\\tfrac\\theta2$; then $b = -t$, "
         "$r = a\\,t$, $l = -r$."),
        correct=3),
    _tf(4, "ch04-clip-before-divide",
        "Clipping against the view volume is done in homogeneous clip coordinates, before the "
        "division by $w$.", True,
        "Before the divide the view volume is $-w \\le x, y, z \\le w$ and clipping is linear; "
        "points behind the eye have $w < 0$ and would be folded in front of it by the divide.",
        "It is done before: after dividing, points behind the eye would be mirrored into the "
        "view (their $w$ is negative) and could no longer be told apart."),
    _mc(4, "ch04-viewport",
        "The viewport transformation maps canonical screen space $[-1, 1]^2$ to the window "
        "$[x_{min}, x_{max}] \\times [y_{min}, y_{max}]$. What is it?",
        ("A rotation followed by a projection", "Nothing rotates: the two rectangles are axis "
         "aligned."),
        ("A scaling by half the window size and a translation to the window centre",
         "$x_v = \\tfrac{x_{max} - x_{min}}2 x + \\tfrac{x_{max} + x_{min}}2$ and likewise for "
         "$y$ (depth uses its own range, not the $y$ range)."),
        ("A perspective divide", "The divide happened before; the viewport map is affine."),
        ("A scaling by the full window size, without translation", "$[-1, 1]$ is 2 wide, so "
         "the factor is half the window size, and the centre $0$ must move to the window "
         "centre."),
        correct=1),
    _mc(4, "ch04-two-point-perspective",
        "A box stands on the ground and is photographed by a camera whose direction of view is "
        "horizontal but not along an edge of the box. How many principal vanishing points does "
        "the picture have?",
        ("One", "One vanishing point needs the image plane parallel to a face of the box, i.e. "
         "the camera looking along an edge direction."),
        ("Two", "The vertical edges are parallel to the (vertical) image plane and stay "
         "parallel; the two horizontal edge directions both cut the plane and each meet at "
         "a vanishing point on the horizon."),
        ("Three", "A third vanishing point appears only when the camera tilts up or down, so "
         "that the vertical edges also cut the image plane."),
        ("None: parallel edges stay parallel", "That holds for parallel projections; in a "
         "perspective one, edges not parallel to the image plane converge."),
        correct=1),
    _tf(4, "ch04-isometric-true-length",
        "In an isometric projection every edge of an axis-aligned cube is drawn at its true "
        "length.", False,
        "Right: the view direction makes the same angle with the three axes, so all three are "
        "shortened by the same factor $\\sqrt{2/3} \\approx 0.816$ (an isometric *drawing* "
        "scales them back up to 1 by convention).",
        "Every axis is inclined to the image plane, so each is foreshortened, by the same factor "
        "$\\sqrt{2/3} \\approx 0.816$; only a hand-made isometric *drawing* uses full lengths."),
    _mc(4, "ch04-cabinet",
        "In a cabinet projection, how is a unit length along the depth axis (perpendicular to "
        "the plane of projection) drawn?",
        ("At full length, at an angle such as 45°", "That is the cavalier projection: the "
         "projectors make 45° with the plane."),
        ("At half length, at an angle such as 30° or 45°", "The projectors make the angle "
         "$\\arctan 2 \\approx 63.4°$ with the plane, so depth is drawn halved, which looks "
         "more natural than the cavalier's full length."),
        ("Not at all: depth collapses to a point", "That is an orthographic front view "
         "(multiview): the projectors run along the depth axis."),
        ("Shorter the farther it is from the plane", "Shrinking with distance is perspective; "
         "every oblique projection is parallel and draws all depth edges alike."),
        correct=1),
    _tf(4, "ch04-vanishing-point-homogeneous",
        "The vanishing point of a direction $\\vec d$ under a projection matrix $M$ is "
        "obtained by applying $M$ to the homogeneous point $(\\vec d, 0)$ and dividing by the "
        "resulting $w$.", True,
        "Right: $(\\vec d, 0)$ is the point at infinity shared by all lines of direction "
        "$\\vec d$, the limit of $p + t\\vec d$; when the resulting $w$ is 0 the direction is "
        "parallel to the image plane and there is no vanishing point.",
        "It is true: the lines $p + t\\vec d$ all tend to the point at infinity "
        "$(\\vec d, 0)$ and their images to its image (no vanishing point when its $w$ is 0)."),
    _mc(4, "ch04-orthographic-vs-oblique",
        "Two parallel projections have the same plane of projection. What tells an "
        "orthographic from an oblique one?",
        ("Whether parallel lines stay parallel", "Both keep parallel lines parallel: every "
         "parallel projection is affine."),
        ("Whether the projectors are perpendicular to the plane of projection",
         "Orthographic: perpendicular; oblique: at another angle, which is why a face "
         "parallel to the plane keeps its shape in both but depth is drawn slanted only in "
         "the oblique one."),
        ("Whether there is a centre of projection", "Neither has one at a finite distance: "
         "that distinguishes perspective from parallel projections."),
        ("Whether the box is rotated", "Rotating the object changes an orthographic view from "
         "multiview to axonometric, not into an oblique projection."),
        correct=1),
]
