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
]
