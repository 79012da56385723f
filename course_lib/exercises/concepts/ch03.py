"""The concept questions of chapter 3 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(3, "ch03-affine-preserves",
        "Which property does **every** affine map of the plane preserve?",
        ("Lengths of segments", "A shear or a non-uniform scaling changes lengths; only rigid "
         "motions keep them."),
        ("Ratios of lengths along one line", "An affine map sends $(1-t)A + tB$ to "
         "$(1-t)A' + tB'$, so a point that divides a segment in the ratio $t : 1-t$ still does "
         "after the map; in particular midpoints go to midpoints."),
        ("Angles between lines", "A shear turns a right angle into an oblique one; angles are "
         "kept by similarities only."),
        ("Areas", "A scaling by 2 in both directions multiplies every area by 4; an affine map "
         "multiplies areas by $|\\det A|$, which is 1 only for some maps."),
        correct=1),
    _tf(3, "ch03-affine-parallel",
        "An affine transformation maps parallel lines to parallel lines.", True,
        "Two parallel lines $p + t\\vec d$ and $q + t\\vec d$ become $Ap + \\vec t + tA\\vec d$ "
        "and $Aq + \\vec t + tA\\vec d$: the same direction $A\\vec d$, so they stay parallel.",
        "They do stay parallel: both images have the direction $A\\vec d$. It is the "
        "*perspective* projection that makes parallel lines meet at a vanishing point."),
    _mc(3, "ch03-translation-linear",
        "Why does computer graphics use $4 \\times 4$ homogeneous matrices for 3D points?",
        ("Because rotations cannot be written as $3 \\times 3$ matrices",
         "Rotations, scalings and shears are all linear and fit in a $3 \\times 3$ matrix."),
        ("To make the matrices invertible",
         "A $3 \\times 3$ rotation or scaling matrix is invertible already; the extra row does "
         "not change invertibility."),
        ("To store the colour of the point in the fourth coordinate",
         "The fourth coordinate $w$ is not a colour: it is 1 for points and 0 for directions."),
        ("Because a translation is not linear, but becomes a matrix product with the extra "
         "coordinate", "A translation moves the origin, so no $3 \\times 3$ matrix does it; with "
         "$w = 1$ the last column adds the displacement, and every affine map (and the "
         "projections) composes by matrix products."),
        correct=3),
    _tf(3, "ch03-compose-commute",
        "Rotating and then translating a point gives the same result as translating and then "
        "rotating it.", False,
        "Not in general: $R\\,T \\ne T\\,R$. Rotating first leaves the displacement unchanged, "
        "translating first makes the rotation swing the displacement around the origin too.",
        "Right: matrix products do not commute, so the order matters. $T R$ rotates about the "
        "origin and then moves; $R T$ moves and then rotates the moved point about the origin."),
    _mc(3, "ch03-inverse-rotation",
        "What is the inverse of a rotation matrix $R$?",
        ("$R^T$, its transpose", "A rotation matrix is orthogonal (its columns are orthonormal), "
         "so $R^T R = I$: the transpose undoes it, as does rotating by $-\\theta$."),
        ("$-R$", "Not in general: $(-R)R = -R^2$, which is not the identity. In 3D it never is "
         "($-R^2$ has determinant $-1$; $-R$ is a rotation combined with a point reflection "
         "through the origin). In 2D a turn by $\\pm 90°$ has $R^2 = -I$, so there $-R$ happens "
         "to be the inverse, because it equals $R^T$; the transpose is the rule that always "
         "works."),
        ("$R$ itself", "Only rotations by $0$ or by $\\pi$ are their own inverse."),
        ("It has none: rotations are not invertible", "Every rotation is invertible: rotate back "
         "by the opposite angle."),
        correct=0),
    _tf(3, "ch03-quat-double-cover",
        "The unit quaternions $q$ and $-q$ represent the same rotation.", True,
        "In $q\\,p\\,\\bar q$ the two signs cancel: $(-q)\\,p\\,(-\\bar q) = q\\,p\\,\\bar q$. "
        "Geometrically, $-q$ is the rotation by $2\\pi - \\theta$ about $-\\hat n$, which is the "
        "same rotation.",
        "They do: the sign cancels in $q\\,p\\,\\bar q$ (unit quaternions cover each rotation "
        "twice)."),
    _mc(3, "ch03-quat-half-angle",
        "Which unit quaternion rotates by the angle $\\theta$ about the unit axis $\\hat n$?",
        ("$(\\cos\\theta,\\ \\sin\\theta\\,\\hat n)$", "This is the classic slip: it rotates "
         "by $2\\theta$, because $q$ acts twice in $q\\,p\\,\\bar q$."),
        ("$(\\sin\\tfrac\\theta2,\\ \\cos\\tfrac\\theta2\\,\\hat n)$", "Sine and cosine are "
         "swapped: with $\\theta = 0$ this is not the identity quaternion $(1, \\vec 0)$."),
        ("$(\\cos\\tfrac\\theta2,\\ \\sin\\tfrac\\theta2\\,\\hat n)$", "The half angle is used "
         "because the sandwich $q\\,p\\,\\bar q$ applies $q$ twice; for $\\theta = 0$ it gives "
         "the identity $(1, \\vec 0)$."),
        ("$(\\theta,\\ \\hat n)$", "That is the axis-angle pair, not a unit quaternion (its "
         "length is not 1)."),
        correct=2),
    _tf(3, "ch03-quat-commute",
        "Quaternion multiplication is commutative: $q_1 q_2 = q_2 q_1$.", False,
        "It is not: the vector part of the product contains $\\vec v_1 \\times \\vec v_2$, which "
        "changes sign when the factors are swapped, just as rotations about different axes do "
        "not commute.",
        "Right: the cross product in the vector part flips sign with the order, so "
        "$q_1 q_2 \\ne q_2 q_1$ in general (they agree when the vector parts are parallel)."),
    _mc(3, "ch03-quat-matrix-entry",
        "In the rotation matrix of the unit quaternion $(s, x, y, z)$, what is the top-left "
        "entry?",
        ("$1 - 2y^2$", "A term is missing (this typo circulates in old notes): for a rotation "
         "about $z$ by $\\theta$ the entry must be $\\cos\\theta$, and $1 - 2y^2 = 1$ there."),
        ("$1 - 2x^2 - 2y^2$", "That is the bottom-right entry $r_{22}$, the one that involves "
         "the two axes other than $z$."),
        ("$s^2 + x^2 + y^2 + z^2$", "That is the squared length, 1 for every unit quaternion: "
         "the entry would always be 1."),
        ("$1 - 2y^2 - 2z^2$", "For a rotation about $z$ by $\\theta$, $z = \\sin\\tfrac\\theta2$ "
         "and the entry is $1 - 2\\sin^2\\tfrac\\theta2 = \\cos\\theta$, as it must be."),
        correct=3),
    _mc(3, "ch03-quat-advantage",
        "Which is a real advantage of unit quaternions over rotation matrices?",
        ("Rotating a single point costs fewer multiplications",
         "It costs more: the sandwich $q\\,p\\,\\bar q$ needs two quaternion products (even "
         "optimized, about twice the 9 multiplications of a $3 \\times 3$ matrix times a "
         "vector); convert to a matrix to rotate many points."),
        ("Composing two rotations is cheaper and the result is easy to renormalize; they "
         "interpolate smoothly (slerp)", "A quaternion product takes 16 multiplications against "
         "27 for a $3 \\times 3$ matrix product, rounding errors are removed by dividing by the "
         "length, and slerp interpolates at constant angular speed."),
        ("They also represent translations", "A unit quaternion only rotates; a translation "
         "still needs a vector or a homogeneous matrix."),
        ("Their product is commutative", "It is not: $q_1 q_2 \\ne q_2 q_1$ in general."),
        correct=1),
    # Issue 21: normals, change of frame, homogeneous w != 1, mirroring about a plane
    _mc(3, "ch03-normal-matrix",
        "A mesh is transformed by an affine map with linear part $A$. Which matrix gives the "
        "transformed normals (up to length)?",
        ("$A$ itself", "$A$ maps tangents; with a non-uniform scale or a shear $A\\,n$ leans "
         "off the surface (stretch a circle into an ellipse: $A\\,n$ no longer points along the "
         "ellipse's gradient)."),
        ("$A^{-1}$", "The inverse alone is wrong too: only for a symmetric $A$ (a pure scale) "
         "does it equal the inverse transpose."),
        ("$(A^{-1})^T$, the inverse transpose", "For every tangent $t \\perp n$: "
         "$(A^{-T} n) \\cdot (A t) = n^T A^{-1} A\\, t = n \\cdot t = 0$, so $A^{-T} n$ stays "
         "perpendicular to the transformed surface. Renormalise afterwards."),
        ("The full $4 \\times 4$ matrix applied to $(n, 1)$", "A normal is a direction: the "
         "translation must not act on it ($w = 0$), and the linear part still needs the "
         "inverse transpose."),
        correct=2),
    _tf(3, "ch03-normal-uniform-scale",
        "If $A$ is a rotation times a **uniform** scale, transforming normals with $A$ itself "
        "gives the right directions.", True,
        "Then $A^T A = k^2 I$, so $A^{-T} = A / k^2$: the same directions, only the length "
        "differs (renormalise). Non-uniform scales and shears are what break $A\\,n$.",
        "It does work: $A^T A = k^2 I$ gives $A^{-T} = A / k^2$, a positive multiple of $A$, "
        "so $A\\,n$ has the right direction; only its length changes."),
    _mc(3, "ch03-world-to-frame",
        "A frame has origin $o$ and orthonormal axes $u, v, w$ (the columns of $R$). Which "
        "matrix takes world coordinates to frame coordinates?",
        ("$\\begin{bmatrix} R & o \\\\ 0 & 1 \\end{bmatrix}$", "That is the frame-to-world "
         "matrix: it maps the frame's coordinates $(a, b, c)$ to $o + a u + b v + c w$."),
        ("$\\begin{bmatrix} R^T & -R^T o \\\\ 0 & 1 \\end{bmatrix}$", "The inverse of the "
         "frame-to-world matrix: a coordinate is the dot product of an axis with $p - o$, "
         "$R^T (p - o) = R^T p - R^T o$; for orthonormal axes $R^{-1} = R^T$."),
        ("$\\begin{bmatrix} R^T & -o \\\\ 0 & 1 \\end{bmatrix}$", "The translation column "
         "must be rotated too: $R^T (p - o)$ gives $-R^T o$, not $-o$."),
        ("$\\begin{bmatrix} R & -o \\\\ 0 & 1 \\end{bmatrix}$", "It neither inverts the "
         "rotation ($R$ instead of $R^T$) nor rotates the origin term."),
        correct=1),
    _tf(3, "ch03-homogeneous-multiple",
        "The 2D homogeneous matrix $\\begin{bmatrix} 0 & -3 & 0 \\\\ 3 & 0 & 0 \\\\ 0 & 0 & 3 "
        "\\end{bmatrix}$ is a rotation by $90^\\circ$, not a scaling by 3.", True,
        "It maps $(x, y, 1)$ to $(-3y, 3x, 3)$, the same point as $(-y, x, 1)$: dividing by "
        "$w = 3$ leaves $R(90^\\circ)$. (Read as a 3D linear map it would be a rotation about "
        "$z$ times a uniform scale 3.)",
        "It is a rotation: $(x, y, 1) \\mapsto (-3y, 3x, 3) \\equiv (-y, x, 1)$. Every entry, "
        "$w$ included, is multiplied by 3, and a homogeneous point does not change when all "
        "its coordinates are multiplied by the same non-zero number."),
    _mc(3, "ch03-mirror-plane",
        "Which matrix mirrors 3D space about the plane through the origin with **unit** normal "
        "$n$?",
        ("$I - n n^T$", "That projects onto the plane: it removes the normal component once, "
         "and is singular."),
        ("$I - 2 n n^T$", "It removes the normal component twice, flipping its sign, and keeps "
         "the plane's vectors: a Householder reflection, symmetric and orthogonal with "
         "determinant $-1$, its own inverse."),
        ("$2 n n^T - I$", "That is the mirror about the **line** along $n$ (a half turn about "
         "it in 3D): it keeps $n$ and negates the plane's vectors."),
        ("$-I$", "That is the point reflection through the origin: it negates every "
         "vector, the plane's ones too."),
        correct=1),
]
