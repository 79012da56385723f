r"""Chapter 3 exercises: transformations (2D and 3D) and quaternions, exam style.

Each class is one kind of exam question. Its ``seed`` draws numbers that are easy to work with by
hand: angles that are multiples of 15 or 30 degrees, small whole translations and points, axes
with whole lengths such as :math:`(1, 2, 2)` (length 3) or :math:`(0, 3, 4)` (length 5), and
quaternions with rational components. The question's numbers are attributes of the exercise
object (``ex.theta``, ``ex.d``, ...), so that a worked solution can read them for any seed.

The expected answers are computed with :mod:`course_lib.transforms` and
:mod:`course_lib.quaternions`. Every exercise anticipates the typical mistakes of its topic (the
product in the wrong order, a transposed matrix, the full angle in a quaternion, ...) and names
them in the feedback. The numbers are drawn again until every anticipated mistake gives an answer
that differs clearly from the right one and from the other mistakes, so a diagnosis is never
ambiguous (:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions: column vectors (:math:`p' = M p`), angles positive counter-clockwise, quaternions
scalar first :math:`(s, x, y, z)`.
"""
import math

import numpy as np

from .. import format as fmt
from .. import quaternions as quat
from .. import transforms as tf
from .core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, data_note, gap,
                   is_unanswered, pick, read_floats, small_ints)

__all__ = [
    "EXERCISES",
    "AxisAngleOfMatrix",
    "ComposeMatrix2D",
    "ComposeRotationsWithQuaternions",
    "InverseOfComposite",
    "MatrixToQuaternion",
    "MirrorAboutLine",
    "QuaternionFromAxisAngle",
    "QuaternionProduct",
    "QuaternionToMatrix",
    "RotateAboutPoint",
    "RotatePointWithQuaternion",
    "RotationAboutArbitraryAxis",
    "ShearImage",
    "ShearInverse",
    "ShearedBoxVolume",
    "SlerpMidpoint",
]

# ---------------------------------------------------------------------------------------------
# Numbers that are pleasant by hand
# ---------------------------------------------------------------------------------------------

#: Angles in degrees for 2D rotations.
_ANGLES_2D = (30, 45, 60, 90, 120, 135, 150, -30, -45, -60, -90, -120)
#: Angles in degrees for 3D rotations (180 included: quaternions with s = 0).
_ANGLES_3D = (60, 90, 120, 180, -60, -90, -120)
#: Integer directions with whole lengths 3, 5, 7, 9 and 9.
_NICE_AXES = ((1, 2, 2), (0, 3, 4), (2, 3, 6), (1, 4, 8), (4, 4, 7))
#: Integer 4-vectors with whole lengths: divided by the length they are unit quaternions with
#: rational components, whose rotation matrices have rational entries.
_NICE_QUATERNIONS = (
    ((1, 1, 1, 1), 2), ((1, 2, 2, 0), 3), ((0, 0, 3, 4), 5), ((1, 2, 2, 4), 5),
    ((1, 1, 3, 5), 6), ((2, 3, 6, 0), 7), ((1, 4, 4, 4), 7), ((2, 4, 5, 6), 9),
    ((2, 2, 3, 8), 9), ((1, 1, 7, 7), 10), ((1, 3, 3, 9), 10),
)
_SHEARS = {
    # name: (matrix function, the coordinate that drives the shear, the two it shifts)
    "xy": (tf.shear_xy, "z", ("x", "y")),
    "xz": (tf.shear_xz, "y", ("x", "z")),
    "yz": (tf.shear_yz, "x", ("y", "z")),
}

_vec = fmt.vector_latex


def _signs(rng, n):
    return rng.choice([-1.0, 1.0], size=n)


def _nice_axis(rng):
    """A whole-number direction with a whole length, permuted and with random signs."""
    return rng.permutation(np.array(pick(rng, _NICE_AXES), dtype=float)) * _signs(rng, 3)


def _nice_quaternion(rng, zero_scalar=False):
    """Whole numbers ``v`` and their length ``n``: ``v / n`` is a unit quaternion.

    With `zero_scalar` the scalar part is 0 (a turn by 180 degrees).
    """
    if zero_scalar:
        ints, n = pick(rng, [entry for entry in _NICE_QUATERNIONS if 0 in entry[0]])
        rest = list(ints)
        rest.remove(0)
        v = np.concatenate([[0.0], rng.permutation(np.array(rest, dtype=float))])
    else:
        ints, n = pick(rng, _NICE_QUATERNIONS)
        v = rng.permutation(np.array(ints, dtype=float))
    return v * _signs(rng, 4), n


def _deg(angle_deg):
    return rf"{angle_deg}^\circ"


def _fraction_vector(ints, n):
    r"""LaTeX of ``ints / n`` as ``\tfrac{1}{n}(a, b, ...)``."""
    ints = [int(round(x)) for x in ints]
    body = "(" + r",\ ".join(str(i) for i in ints) + ")"
    return body if n == 1 else rf"\tfrac{{1}}{{{n}}}\,{body}"


def _fraction_matrix(m, n2):
    r"""LaTeX of the matrix `m` as ``\frac{1}{n2}`` times a whole-number matrix."""
    whole = np.rint(np.asarray(m) * n2)
    return rf"\frac{{1}}{{{n2}}}{fmt.matrix_latex(whole)}"


_MATRIX_3 = ("**Answer:** the homogeneous $3 \\times 3$ matrix as a numpy array, "
             "`np.array([[...], [...], [...]])`. " + DECIMALS)
_MATRIX_4 = ("**Answer:** the homogeneous $4 \\times 4$ matrix as a numpy array. " + DECIMALS)
_POINT_3 = ("**Answer:** the image point as a list of 3 numbers `[x, y, z]`. " + DECIMALS)
_QUATERNION = ("**Answer:** a list of 4 numbers, **scalar first**: `[s, x, y, z]`. " + DECIMALS)


# ---------------------------------------------------------------------------------------------
# 2D composition, inverses and mirroring
# ---------------------------------------------------------------------------------------------

_SCALES_2D = (2.0, 3.0, 0.5, -1.0, -2.0)


class ComposeMatrix2D(DrawnExercise):
    r"""Compose a scaling, a rotation and a translation into one 2D homogeneous matrix.

    The points are scaled by :math:`S(s_x, s_y)`, then rotated by :math:`\theta` about the
    origin, then translated by :math:`d`, so :math:`M = T(d)\,R(\theta)\,S(s_x, s_y)`: with column
    vectors the first step is the rightmost factor.

    Attributes: ``sx``, ``sy``, ``theta_deg``, ``theta`` (radians), ``d``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = ComposeMatrix2D(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> listed_order = tf.scale([ex.sx, ex.sy]) @ tf.rotate(ex.theta) @ tf.translate(ex.d)
    >>> ex.check(listed_order).diagnosis
    'wrong order'
    >>> ex.check(...).status, ex.check("M").status
    ('unanswered', 'invalid')
    """

    title = "Scale, rotate, translate: one 2D matrix"

    def draw(self, rng):
        self.sx, self.sy = (float(v) for v in rng.choice(_SCALES_2D, size=2, replace=False))
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.theta = math.radians(self.theta_deg)
        self.d = small_ints(rng, 2)
        self.expected = tf.compose(self._scale(), tf.rotate(self.theta), tf.translate(self.d))

    def _scale(self):
        return tf.scale([self.sx, self.sy])

    def mistakes(self):
        S, R, T = self._scale(), tf.rotate(self.theta), tf.translate(self.d)
        right = T @ R @ S
        bottom_row = np.eye(3)
        bottom_row[:2, :2] = right[:2, :2]
        bottom_row[2, :2] = self.d
        return [
            Mistake(S @ R @ T, r"You multiplied the matrices from left to right in the order the "
                    r"steps are listed, $S\,R\,T$. With column vectors ($p' = Mp$) the factor "
                    r"next to $p$ acts first, so the first step must stand **rightmost**: "
                    r"$M = T(d)\,R(\theta)\,S(s_x, s_y)$.", "wrong order"),
            Mistake(T @ S @ R, r"You rotated before scaling ($T\,S\,R$). The scaling is the first "
                    r"step, so $S$ is the rightmost factor: $M = T\,R\,S$. With unequal factors "
                    r"$s_x \neq s_y$ the two orders give different matrices.",
                    "scale and rotation swapped"),
            Mistake(T @ tf.rotate(-self.theta) @ S, r"Your rotation turns the wrong way. The "
                    r"first row of $R(\theta)$ is $(\cos\theta,\ -\sin\theta)$ and the second "
                    r"$(\sin\theta,\ \cos\theta)$, so that a positive angle turns "
                    r"counter-clockwise.", "angle sign"),
            Mistake(bottom_row, r"You put the translation in the bottom row. That is the "
                    r"row-vector convention ($p' = pM$); with column vectors, as in the "
                    r"textbook, the translation is the last **column** and the bottom row is "
                    r"$(0, 0, 1)$.", "translation in bottom row"),
            Mistake(right.T, r"Your matrix is transposed: the translation ended up in the bottom "
                    r"row and the rotation turns the other way. With column vectors the images "
                    r"of the axes are the columns and the translation is the last column.",
                    "transposed"),
        ]

    def statement(self):
        return (
            rf"A 2D shape is transformed in three steps: first it is scaled about the origin by "
            rf"$S(s_x, s_y)$ with $s_x = {fmt.number(self.sx)}$, $s_y = {fmt.number(self.sy)}$ "
            rf"(a negative factor mirrors), then rotated about the origin by "
            rf"$\theta = {_deg(self.theta_deg)}$ (counter-clockwise for a positive angle), and "
            rf"finally translated by $d = {_vec(self.d)}$." "\n\n"
            rf"Give the single matrix $M$ with $p' = M\,p$ that does all three steps." "\n\n"
            + _MATRIX_3 + "\n\n" + data_note("sx", "sy", "theta_deg", "theta", "d")
            + " (`.theta` is in radians.)")


class RotateAboutPoint(DrawnExercise):
    r"""The 2D rotation by :math:`\theta` about a point :math:`c`: :math:`T(c)\,R(\theta)\,T(-c)`.

    Attributes: ``theta_deg``, ``theta`` (radians), ``c``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = RotateAboutPoint(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(tf.rotate(ex.theta)).diagnosis
    'about origin'
    >>> swapped = tf.translate(-ex.c) @ tf.rotate(ex.theta) @ tf.translate(ex.c)
    >>> ex.check(swapped).diagnosis
    'wrong order'
    """

    title = "Rotation about a point (2D)"

    def draw(self, rng):
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.theta = math.radians(self.theta_deg)
        self.c = small_ints(rng, 2)
        self.expected = tf.rotate_about(self.theta, self.c)

    def mistakes(self):
        R, T_c, T_minus_c = tf.rotate(self.theta), tf.translate(self.c), tf.translate(-self.c)
        return [
            Mistake(T_minus_c @ R @ T_c, r"The translations are swapped: $T(-c)\,R\,T(c)$ "
                    r"rotates about $-c$. Read the product from the right: first $T(-c)$ moves "
                    r"$c$ to the origin, then $R$ rotates, then $T(c)$ moves it back, so "
                    r"$M = T(c)\,R(\theta)\,T(-c)$.", "wrong order"),
            Mistake(R, r"This rotates about the origin, not about $c$. Move $c$ to the origin "
                    r"first and back afterwards: $M = T(c)\,R(\theta)\,T(-c)$.", "about origin"),
            Mistake(T_c @ tf.rotate(-self.theta) @ T_minus_c, r"The fixed point is right but "
                    r"the rotation turns clockwise: in $R(\theta)$ the $-\sin\theta$ belongs in "
                    r"the first row.", "angle sign"),
            Mistake(R @ T_minus_c, r"You moved $c$ to the origin and rotated, but never moved "
                    r"it back: the last step $T(c)$ (leftmost factor) is missing.",
                    "missing T(c)"),
            Mistake(T_c @ R, r"You rotated about the origin and then translated by $c$: the "
                    r"first step $T(-c)$ (rightmost factor) is missing.", "missing T(-c)"),
        ]

    def statement(self):
        return (
            rf"Find the homogeneous matrix $M$ of the 2D rotation by "
            rf"$\theta = {_deg(self.theta_deg)}$ (counter-clockwise for a positive angle) about "
            rf"the point $c = {_vec(self.c)}$, so that $p' = M\,p$. The point $c$ must stay "
            rf"where it is." "\n\n" + _MATRIX_3 + "\n\n" + data_note("theta_deg", "theta", "c")
            + " (`.theta` is in radians.)")


_SCALES_INVERTIBLE = (2.0, 4.0, 0.5, -1.0, -2.0)


class InverseOfComposite(DrawnExercise):
    r"""The inverse of :math:`M = T(d)\,R(\theta)\,S(s_x, s_y)` in 2D.

    :math:`M^{-1} = S(1/s_x, 1/s_y)\,R(-\theta)\,T(-d)`: each factor is inverted and the order
    reversed.

    Attributes: ``sx``, ``sy``, ``theta_deg``, ``theta`` (radians), ``d``, ``M``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = InverseOfComposite(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> same_order = (tf.translate(-ex.d) @ tf.rotate(-ex.theta)
    ...               @ tf.scale([1 / ex.sx, 1 / ex.sy]))
    >>> ex.check(same_order).diagnosis
    'same order'
    >>> ex.check(ex.M.T).diagnosis
    'transposed only'
    """

    title = "Inverse of a composite 2D transformation"

    def draw(self, rng):
        self.sx, self.sy = (float(v) for v in rng.choice(_SCALES_INVERTIBLE, size=2,
                                                         replace=False))
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.theta = math.radians(self.theta_deg)
        self.d = small_ints(rng, 2)
        self.M = tf.translate(self.d) @ tf.rotate(self.theta) @ tf.scale([self.sx, self.sy])
        self.expected = tf.inverse(self.M)

    def mistakes(self):
        S_inv = tf.scale([1 / self.sx, 1 / self.sy])
        R_inv, T_inv = tf.rotate(-self.theta), tf.translate(-self.d)
        linear_inv = np.linalg.inv(self.M[:2, :2])
        negated_only = np.eye(3)
        negated_only[:2, :2] = linear_inv
        negated_only[:2, 2] = -self.d
        return [
            Mistake(T_inv @ R_inv @ S_inv, r"You inverted every factor but kept their order, "
                    r"$T^{-1} R^{-1} S^{-1}$. The inverse of a product reverses the order, "
                    r"$(ABC)^{-1} = C^{-1} B^{-1} A^{-1}$ (to undo the steps, undo the last one "
                    r"first): $M^{-1} = S^{-1}\,R(-\theta)\,T(-d)$.", "same order"),
            Mistake(self.M.T, r"Transposing inverts only a pure rotation (an orthogonal matrix). "
                    r"$M$ also scales and translates: invert each factor "
                    r"($S(1/s_x, 1/s_y)$, $R(-\theta)$, $T(-d)$) and multiply them in reverse "
                    r"order.", "transposed only"),
            Mistake(negated_only, r"The upper-left block is right, but the last column is not "
                    r"simply $-d$: the translation must be undone *before* the rotation and the "
                    r"scaling are, so the last column of $M^{-1}$ is $-A^{-1} d$, where $A$ is "
                    r"the upper-left $2 \times 2$ block of $M$.", "translation not transformed"),
            Mistake(tf.scale([self.sx, self.sy]) @ R_inv @ T_inv, r"The scaling is not "
                    r"inverted: the inverse of $S(s_x, s_y)$ is $S(1/s_x, 1/s_y)$.",
                    "scale not inverted"),
            Mistake(S_inv @ tf.rotate(self.theta) @ T_inv, r"The rotation is not inverted: the "
                    r"inverse of $R(\theta)$ is $R(-\theta) = R(\theta)^T$.",
                    "rotation not inverted"),
        ]

    def statement(self):
        return (
            rf"Let $M = T(d)\,R(\theta)\,S(s_x, s_y)$ with $d = {_vec(self.d)}$, "
            rf"$\theta = {_deg(self.theta_deg)}$, $s_x = {fmt.number(self.sx)}$ and "
            rf"$s_y = {fmt.number(self.sy)}$ (homogeneous 2D matrices, column vectors)." "\n\n"
            rf"Give $M^{{-1}}$, the matrix that undoes $M$. Build it from the inverses of the "
            rf"three factors rather than by a general matrix inversion." "\n\n" + _MATRIX_3
            + "\n\n" + data_note("sx", "sy", "theta_deg", "theta", "d", "M")
            + " (`.theta` is in radians; `.M` is the matrix $M$.)")


_MIRROR_ANGLES = (30, 45, 60, 120, 135, 150)


class MirrorAboutLine(DrawnExercise):
    r"""Mirroring about a line through :math:`c` at angle :math:`\varphi` to the x axis (2D).

    .. math:: M = T(c)\,R(\varphi)\,S(1, -1)\,R(-\varphi)\,T(-c)

    Move the line onto the x axis, mirror about the x axis, move it back.

    Attributes: ``phi_deg``, ``phi`` (radians), ``c``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = MirrorAboutLine(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> R, S = tf.rotate(ex.phi), tf.mirror("x")
    >>> ex.check(R @ S @ R.T).diagnosis
    'line through origin'
    """

    title = "Mirroring about a line (2D)"

    def draw(self, rng):
        self.phi_deg = int(pick(rng, _MIRROR_ANGLES))
        self.phi = math.radians(self.phi_deg)
        self.c = small_ints(rng, 2)
        self.expected = self._mirror(self.c, self.phi)

    @staticmethod
    def _mirror(c, phi):
        return (tf.translate(c) @ tf.rotate(phi) @ tf.mirror("x") @ tf.rotate(-phi)
                @ tf.translate(-np.asarray(c)))

    def mistakes(self):
        S = tf.mirror("x")
        T_c, T_minus_c = tf.translate(self.c), tf.translate(-self.c)
        R, R_inv = tf.rotate(self.phi), tf.rotate(-self.phi)
        return [
            Mistake(R @ S @ R_inv, r"This mirrors about the parallel line through the origin. "
                    r"The line passes through $c$: move $c$ to the origin first ($T(-c)$, "
                    r"rightmost) and back at the end ($T(c)$, leftmost).",
                    "line through origin"),
            Mistake(T_c @ R_inv @ S @ R @ T_minus_c, r"The two rotations are swapped, so you "
                    r"mirrored about the line at angle $-\varphi$. To bring the line onto the "
                    r"x axis rotate by $-\varphi$ first (right of $S$), and turn it back with "
                    r"$R(\varphi)$ afterwards (left of $S$).", "rotations swapped"),
            Mistake(T_minus_c @ R @ S @ R_inv @ T_c, r"The two translations are swapped: the "
                    r"first step (rightmost factor) must be $T(-c)$, which brings $c$ to the "
                    r"origin.", "translations swapped"),
            Mistake(T_c @ S @ T_minus_c, r"This mirrors about the horizontal line through $c$: "
                    r"the line is tilted by $\varphi$, so it must be turned onto the x axis "
                    r"($R(-\varphi)$) before mirroring and turned back ($R(\varphi)$) after.",
                    "no rotation"),
        ]

    def statement(self):
        return (
            rf"The line $\ell$ passes through the point $c = {_vec(self.c)}$ and makes the angle "
            rf"$\varphi = {_deg(self.phi_deg)}$ with the positive x axis. Give the homogeneous "
            rf"matrix $M$ of the mirroring (reflection) about $\ell$, so that $p' = M\,p$. "
            rf"Mirroring about the x axis is the scaling $S(1, -1)$." "\n\n" + _MATRIX_3
            + "\n\n" + data_note("phi_deg", "phi", "c") + " (`.phi` is in radians.)")


# ---------------------------------------------------------------------------------------------
# Shears
# ---------------------------------------------------------------------------------------------

def _shear_words(kind, a="a", b="b"):
    driver, (first, second) = _SHEARS[kind][1], _SHEARS[kind][2]
    return (rf"$SH_{{{kind}}}({a}, {b})$ (it adds ${a}\,{driver}$ to ${first}$ and "
            rf"${b}\,{driver}$ to ${second}$, and leaves ${driver}$ unchanged)")


def _shear(kind, a, b):
    return _SHEARS[kind][0](a, b)


class ShearInverse(DrawnExercise):
    r"""The inverse of a 3D shear: the same shear with negated factors.

    Attributes: ``kind`` (``"xy"``, ``"xz"`` or ``"yz"``), ``a``, ``b``.

    Examples
    --------
    >>> ex = ShearInverse(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected.T).diagnosis
    'negated but transposed'
    >>> ex.check(np.linalg.inv(ex.expected)).diagnosis      # the shear itself
    'not negated'
    """

    title = "Inverse of a 3D shear"

    def draw(self, rng):
        self.kind = str(pick(rng, tuple(_SHEARS)))
        self.a, self.b = (float(v) for v in rng.choice([-3, -2, 2, 3], size=2))
        self.expected = tf.inverse(_shear(self.kind, self.a, self.b))

    def mistakes(self):
        H = _shear(self.kind, self.a, self.b)
        return [
            Mistake(H, r"This is the shear itself, not its inverse. A shear is undone by "
                    r"shearing back by the same amounts: negate both factors, "
                    r"$SH(a, b)^{-1} = SH(-a, -b)$.", "not negated"),
            Mistake(H.T, r"Transposing moves the factors to the wrong place (now another "
                    r"coordinate drives the shear) and keeps their sign. Only rotations are "
                    r"inverted by transposing; a shear is inverted by negating its factors in "
                    r"place.", "transposed"),
            Mistake(_shear(self.kind, -self.a, -self.b).T, r"The factors are negated, which is "
                    r"right, but they moved to the transposed positions: keep them where they "
                    r"are in $SH(a, b)$, so that the same coordinate drives the shear.",
                    "negated but transposed"),
            Mistake(_shear(self.kind, 1 / self.a, 1 / self.b), r"Reciprocals invert a "
                    r"*scaling*, not a shear. A shear adds a multiple of one coordinate; "
                    r"subtracting the same multiple undoes it, so negate the factors.",
                    "reciprocal"),
        ]

    def statement(self):
        return (
            rf"Consider the 3D shear {_shear_words(self.kind)}, with "
            rf"$a = {fmt.number(self.a)}$ and $b = {fmt.number(self.b)}$. Give the homogeneous "
            rf"matrix of its inverse, $SH_{{{self.kind}}}(a, b)^{{-1}}$." "\n\n" + _MATRIX_4
            + "\n\n" + data_note("kind", "a", "b"))


class ShearImage(DrawnExercise):
    r"""The image of a 3D point under a shear.

    Attributes: ``kind`` (``"xy"``, ``"xz"`` or ``"yz"``), ``a``, ``b``, ``p``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = ShearImage(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> H = {"xy": tf.shear_xy, "xz": tf.shear_xz, "yz": tf.shear_yz}[ex.kind](ex.a, ex.b)
    >>> ex.check(tf.apply(H.T, ex.p)).diagnosis
    'transposed'
    """

    title = "Image of a point under a 3D shear"
    answer_form = "vector"
    what = "the image point"

    def draw(self, rng):
        self.kind = str(pick(rng, tuple(_SHEARS)))
        self.a, self.b = (float(v) for v in rng.choice([-3, -2, -1, 1, 2, 3], size=2))
        self.p = small_ints(rng, 3)
        self.expected = tf.apply(_shear(self.kind, self.a, self.b), self.p)

    def mistakes(self):
        H = _shear(self.kind, self.a, self.b)
        return [
            Mistake(tf.apply(H.T, self.p), r"You used the transposed shear matrix, so the wrong "
                    r"coordinate drove the shift. In the matrix of the shear the factors sit in "
                    r"the **column** of the driving coordinate: each shifted coordinate gets "
                    r"*factor times the driving coordinate* added.", "transposed"),
            Mistake(tf.apply(_shear(self.kind, -self.a, -self.b), self.p), r"You sheared the "
                    r"opposite way (factors negated): that is the inverse shear. Add the "
                    r"factor times the driving coordinate; do not subtract it.",
                    "opposite shear"),
        ]

    def statement(self):
        return (
            rf"The 3D shear {_shear_words(self.kind)} is applied with "
            rf"$a = {fmt.number(self.a)}$ and $b = {fmt.number(self.b)}$. Where does the point "
            rf"$p = {_vec(self.p)}$ go?" "\n\n" + _POINT_3 + "\n\n"
            + data_note("kind", "a", "b", "p"))


_BOX_SCALES = (1.0, 2.0, 3.0, 0.5, -1.0, -2.0)


class ShearedBoxVolume(DrawnExercise):
    r"""The volume of a box after a shear and a scaling: :math:`|\det M|` times the old volume.

    A shear has determinant 1 and keeps volumes; the scaling multiplies them by
    :math:`|s_x s_y s_z|` (a negative factor mirrors, and volumes are not negative).

    Attributes: ``w``, ``h``, ``l`` (edge lengths along x, y, z), ``kind``, ``a``, ``b``,
    ``sx``, ``sy``, ``sz``.

    Examples
    --------
    >>> ex = ShearedBoxVolume(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.w * ex.h * ex.l).diagnosis
    'scaling ignored'
    """

    title = "Volume after a shear and a scaling"
    answer_form = "number"
    what = "the volume"
    may_coincide = ("negative volume",)

    def draw(self, rng):
        self.w, self.h, self.l = (float(v) for v in rng.integers(1, 5, size=3))
        self.kind = str(pick(rng, tuple(_SHEARS)))
        self.a, self.b = (float(v) for v in rng.choice([-2, -1, 1, 2], size=2))
        self.sx, self.sy, self.sz = (float(v) for v in rng.choice(_BOX_SCALES, size=3))
        self.expected = self.w * self.h * self.l * abs(np.linalg.det(self._matrix()[:3, :3]))

    def _matrix(self):
        return tf.scale([self.sx, self.sy, self.sz]) @ _shear(self.kind, self.a, self.b)

    def mistakes(self):
        M = self._matrix()[:3, :3]
        edges = M * np.array([self.w, self.h, self.l])       # images of the three edges
        box = self.w * self.h * self.l
        return [
            Mistake(float(np.prod(np.linalg.norm(edges, axis=0))), r"You multiplied the lengths "
                    r"of the transformed edges. After a shear the box is a slanted "
                    r"parallelepiped whose edges are not perpendicular, so that product "
                    r"overestimates the volume. Use the determinant: the volume is multiplied by "
                    r"$|\det M|$, and a shear has determinant 1.", "edge lengths"),
            Mistake(box * float(np.prod([self.sx, self.sy, self.sz])), r"A volume cannot be "
                    r"negative. The negative scale factor mirrors the box (turning it "
                    r"inside out); the volume is multiplied by the *absolute value* of the "
                    r"determinant.", "negative volume"),
            Mistake(box, r"Right that the shear keeps the volume, but the scaling changes it: "
                    r"it multiplies volumes by $|s_x s_y s_z|$.", "scaling ignored"),
        ]

    def statement(self):
        return (
            rf"A box with edges of length $w = {fmt.number(self.w)}$, "
            rf"$h = {fmt.number(self.h)}$, $l = {fmt.number(self.l)}$ along x, y and z is first "
            rf"sheared by {_shear_words(self.kind)} with $a = {fmt.number(self.a)}$, "
            rf"$b = {fmt.number(self.b)}$, and then scaled by "
            rf"$S({fmt.number(self.sx)}, {fmt.number(self.sy)}, {fmt.number(self.sz)})$"
            + (" (a negative factor mirrors)" if min(self.sx, self.sy, self.sz) < 0 else "")
            + ". What is the volume of the resulting solid?\n\n"
            rf"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("w", "h", "l", "kind", "a", "b", "sx", "sy", "sz"))


# ---------------------------------------------------------------------------------------------
# 3D rotation about an arbitrary axis
# ---------------------------------------------------------------------------------------------

class RotationAboutArbitraryAxis(DrawnExercise):
    r"""Rotate a point about the line through :math:`a` with direction :math:`u`.

    The rotation is :math:`T(a)\,R_u(\theta)\,T(-a)`, where :math:`R_u(\theta)` rotates about the
    parallel axis through the origin (Rodrigues' formula, or the textbook's product of elementary
    rotations).

    Attributes: ``a`` (a point of the axis), ``u`` (its direction, not of unit length),
    ``theta_deg``, ``theta`` (radians), ``p`` (the point to rotate).

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = RotationAboutArbitraryAxis(seed=8)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(tf.apply(tf.rotate_axis(ex.u, ex.theta), ex.p)).diagnosis
    'axis through origin'
    """

    title = "Rotation about an arbitrary axis (3D)"
    answer_form = "vector"
    what = "the rotated point"

    def draw(self, rng):
        self.a = small_ints(rng, 3, -2, 2)
        self.u = _nice_axis(rng)
        self.theta_deg = int(pick(rng, _ANGLES_3D))
        self.theta = math.radians(self.theta_deg)
        self.p = small_ints(rng, 3, -2, 2)
        self.expected = tf.apply(tf.rotate_axis(self.u, self.theta, self.a), self.p)

    def mistakes(self):
        R = tf.rotate_axis(self.u, self.theta)
        return [
            Mistake(tf.apply(R, self.p), r"You rotated about the parallel axis through the "
                    r"origin. The axis passes through $a$: translate by $-a$ first, rotate, "
                    r"then translate back by $a$, i.e. $p' = a + R\,(p - a)$.",
                    "axis through origin"),
            Mistake(tf.apply(tf.rotate_axis(self.u, -self.theta, self.a), self.p), r"The "
                    r"rotation turns the wrong way (by $-\theta$). Positive angles are "
                    r"counter-clockwise when you look from the tip of $u$ back towards the axis; "
                    r"check the signs of the $\sin\theta$ terms (in Rodrigues' formula, "
                    r"$+\sin\theta\,(\hat u \times v)$).", "angle sign"),
            Mistake(tf.apply(R, self.p - self.a), r"You translated by $-a$ and rotated, but did "
                    r"not translate back by $+a$ at the end.", "missing T(a)"),
            Mistake(tf.apply(R, self.p) + self.a, r"You rotated and translated by $+a$, but "
                    r"forgot to translate by $-a$ first: $p' = a + R\,(p - a)$.",
                    "missing T(-a)"),
        ]

    def statement(self):
        return (
            rf"The axis of a rotation is the line through $a = {_vec(self.a)}$ with direction "
            rf"$u = {_vec(self.u)}$ (not of unit length). Rotate the point "
            rf"$p = {_vec(self.p)}$ by $\theta = {_deg(self.theta_deg)}$ about this axis "
            rf"(counter-clockwise when seen from the tip of $u$ looking back along the "
            rf"axis)." "\n\n"
            + _POINT_3 + "\n\n" + data_note("a", "u", "theta_deg", "theta", "p")
            + " (`.theta` is in radians.)")


# ---------------------------------------------------------------------------------------------
# Quaternions
# ---------------------------------------------------------------------------------------------

_QUATERNION_ANGLES = (30, 45, 60, 90, 120, 135, 150, 180, 240, 270, 300)


def _scalar_last(q):
    return np.roll(np.asarray(q, dtype=float), -1)


_SCALAR_LAST_TEXT = (r"You wrote the scalar part last, $(x, y, z, s)$ (scipy's order). The "
                     r"textbook and this course write it first: $q = (s, x, y, z)$.")


class QuaternionFromAxisAngle(DrawnExercise):
    r"""The unit quaternion of a rotation: :math:`(\cos\frac\theta2, \sin\frac\theta2\,\hat n)`.

    Attributes: ``axis`` (not of unit length), ``theta_deg``, ``theta`` (radians).

    Examples
    --------
    >>> ex = QuaternionFromAxisAngle(seed=9)
    >>> ex.check(ex.expected).status, ex.check(-ex.expected).status
    ('correct', 'correct')
    >>> half = ex.theta / 2
    >>> raw_axis = np.concatenate([[np.cos(half)], np.sin(half) * ex.axis])
    >>> ex.check(raw_axis).diagnosis
    'axis not normalized'
    """

    title = "Quaternion from axis and angle"
    answer_form = "quaternion"
    what = "the quaternion"

    def draw(self, rng):
        self.axis = _nice_axis(rng)
        self.theta_deg = int(pick(rng, _QUATERNION_ANGLES))
        self.theta = math.radians(self.theta_deg)
        self.expected = quat.from_axis_angle(self.axis, self.theta)

    def _unit_axis(self):
        return self.axis / np.linalg.norm(self.axis)

    def mistakes(self):
        n, half = self._unit_axis(), self.theta / 2
        half_deg = self.theta_deg / 2
        return [
            Mistake(np.concatenate([[math.cos(half)], math.sin(half) * self.axis]), r"The axis "
                    r"is not normalized: the vector part must be $\sin\frac{\theta}{2}\,\hat n$ "
                    r"with the **unit** vector $\hat n = u / \lVert u \rVert$. Otherwise $q$ is "
                    r"not a unit quaternion, and $q\,p\,\bar q$ would also scale the point.",
                    "axis not normalized"),
            Mistake(np.concatenate([[math.cos(self.theta)], math.sin(self.theta) * n]), r"You "
                    r"used the full angle. A quaternion holds **half** the angle, "
                    r"$q = (\cos\frac{\theta}{2}, \sin\frac{\theta}{2}\,\hat n)$, because "
                    r"$q\,p\,\bar q$ applies it twice, once from each side.", "full angle"),
            Mistake(_scalar_last(self.expected), _SCALAR_LAST_TEXT, "scalar last"),
            Mistake(np.concatenate([[math.cos(half_deg)], math.sin(half_deg) * n]), r"You fed "
                    r"the angle in degrees to $\cos$ and $\sin$, which expect radians: use "
                    r"`np.radians(theta_deg)` (or the attribute `.theta`).", "degrees"),
            Mistake(np.concatenate([[math.sin(half)], math.cos(half) * n]), r"Sine and cosine "
                    r"are swapped: the scalar part is $\cos\frac{\theta}{2}$ and the vector part "
                    r"$\sin\frac{\theta}{2}\,\hat n$ (a rotation by 0 must give $(1, 0, 0, 0)$).",
                    "sin and cos swapped"),
        ]

    def statement(self):
        return (
            rf"Give the unit quaternion $q$ of the rotation by $\theta = {_deg(self.theta_deg)}$ "
            rf"about the axis through the origin with direction $u = {_vec(self.axis)}$ (not of "
            rf"unit length)." "\n\n" + _QUATERNION
            + r" Both $q$ and $-q$ are accepted: they describe the same rotation." + "\n\n"
            + data_note("axis", "theta_deg", "theta") + " (`.theta` is in radians.)")


def _quaternion_text(q):
    return _vec(q)


class QuaternionProduct(DrawnExercise):
    r"""The Hamilton product of two quaternions with whole-number components.

    .. math:: (s_1, v_1)(s_2, v_2) = (s_1 s_2 - v_1 \cdot v_2,\ s_1 v_2 + s_2 v_1 + v_1 \times v_2)

    Attributes: ``q1``, ``q2`` (scalar first).

    Examples
    --------
    >>> from course_lib import quaternions as quat
    >>> ex = QuaternionProduct(seed=10)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(quat.multiply(ex.q2, ex.q1)).diagnosis
    'wrong order'
    >>> ex.check(ex.q1 * ex.q2).diagnosis
    'component-wise'
    """

    title = "Product of two quaternions"
    answer_form = "vector"
    what = "the product"

    def draw(self, rng):
        self.q1 = small_ints(rng, 4, -2, 3)
        self.q2 = small_ints(rng, 4, -2, 3)
        self.expected = quat.multiply(self.q1, self.q2)

    def mistakes(self):
        s1, v1 = self.q1[0], self.q1[1:]
        s2, v2 = self.q2[0], self.q2[1:]
        plus_dot = np.concatenate([[s1 * s2 + v1 @ v2], self.expected[1:]])
        return [
            Mistake(quat.multiply(self.q2, self.q1), r"You computed $q_2\,q_1$: the cross "
                    r"product has the wrong sign. The Hamilton product is not commutative; in "
                    r"$q_1 q_2$ the vector part is $s_1 v_2 + s_2 v_1 + v_1 \times v_2$, with "
                    r"$v_1$ first in the cross product.", "wrong order"),
            Mistake(self.q1 * self.q2, r"You multiplied component by component. Quaternions "
                    r"multiply like $i^2 = j^2 = k^2 = ijk = -1$: "
                    r"$q_1 q_2 = (s_1 s_2 - v_1 \cdot v_2,\ s_1 v_2 + s_2 v_1 + v_1 \times v_2)$.",
                    "component-wise"),
            Mistake(_scalar_last(self.expected), _SCALAR_LAST_TEXT, "scalar last"),
            Mistake(plus_dot, r"The vector part is right but the scalar part is not: it is "
                    r"$s_1 s_2 - v_1 \cdot v_2$ (minus, because $i^2 = j^2 = k^2 = -1$).",
                    "scalar sign"),
        ]

    def statement(self):
        return (
            rf"Compute the quaternion product $q_1\,q_2$ of $q_1 = {_quaternion_text(self.q1)}$ "
            rf"and $q_2 = {_quaternion_text(self.q2)}$, both written scalar first "
            rf"$(s, x, y, z)$. They are not unit quaternions; do not normalize anything." "\n\n"
            r"**Answer:** a list of 4 numbers, **scalar first**: `[s, x, y, z]`." + "\n\n"
            + data_note("q1", "q2"))


_ROTATION_ANGLES = (60, 90, 120, 180, 240, -90)


class RotatePointWithQuaternion(DrawnExercise):
    r"""Rotate a point with :math:`p' = q\,p\,\bar q`, given the axis and angle.

    Attributes: ``axis`` (not of unit length), ``theta_deg``, ``theta`` (radians), ``p``.

    Examples
    --------
    >>> from course_lib import quaternions as quat
    >>> ex = RotatePointWithQuaternion(seed=11)
    >>> ex.check(ex.expected).status
    'correct'
    >>> q = quat.from_axis_angle(ex.axis, ex.theta)
    >>> ex.check(quat.rotate(quat.conjugate(q), ex.p)).diagnosis      # q-bar p q
    'other way'
    """

    title = "Rotate a point with a quaternion"
    answer_form = "vector"
    what = "the rotated point"

    def draw(self, rng):
        self.axis = _nice_axis(rng)
        self.theta_deg = int(pick(rng, _ROTATION_ANGLES))
        self.theta = math.radians(self.theta_deg)
        self.p = small_ints(rng, 3, -2, 2)
        self.expected = quat.rotate(quat.from_axis_angle(self.axis, self.theta), self.p)

    def mistakes(self):
        half = self.theta / 2
        raw = np.concatenate([[math.cos(half)], math.sin(half) * self.axis])
        pure = np.concatenate([[0.0], self.p])
        q = quat.from_axis_angle(self.axis, self.theta)
        return [
            Mistake(quat.rotate(quat.from_axis_angle(self.axis, -self.theta), self.p), r"The "
                    r"point turned the wrong way: you computed $\bar q\,p\,q$ (or used "
                    r"$-\theta$). The rotation by $+\theta$ is $p' = q\,p\,\bar q$ with "
                    r"$q = (\cos\frac{\theta}{2}, \sin\frac{\theta}{2}\,\hat n)$.", "other way"),
            Mistake(quat.rotate(quat.from_axis_angle(self.axis, 2 * self.theta), self.p), r"The "
                    r"point turned by $2\theta$: you built $q$ with the full angle. Use "
                    r"$\cos\frac{\theta}{2}$ and $\sin\frac{\theta}{2}$; the two products in "
                    r"$q\,p\,\bar q$ each contribute half the turn.", "full angle"),
            Mistake(quat.multiply(quat.multiply(raw, pure), quat.conjugate(raw))[1:], r"The axis "
                    r"was not normalized, so $q$ is not a unit quaternion and $q\,p\,\bar q$ "
                    r"also scaled the point by $\lVert q \rVert^2$. Divide the axis by its "
                    r"length before building $q$.", "axis not normalized"),
            Mistake(quat.multiply(q, pure)[1:], r"You stopped after $q\,p$. The rotation is the "
                    r"*sandwich* $q\,p\,\bar q$: multiply by the conjugate on the right as well, "
                    r"and read the point from the vector part (the scalar part is 0).",
                    "missing conjugate"),
        ]

    def statement(self):
        return (
            rf"Using quaternions, rotate the point $p = {_vec(self.p)}$ by "
            rf"$\theta = {_deg(self.theta_deg)}$ about the axis through the origin with "
            rf"direction $u = {_vec(self.axis)}$ (not of unit length): build the unit "
            rf"quaternion $q$ and compute $p' = q\,p\,\bar q$, with $p$ written as the pure "
            rf"quaternion $(0, p)$." "\n\n" + _POINT_3 + "\n\n"
            + data_note("axis", "theta_deg", "theta", "p") + " (`.theta` is in radians.)")


def _as_rotation_block(answer):
    """A 4x4 homogeneous rotation given where a 3x3 one is asked, as its 3x3 block."""
    arr = read_floats(answer)
    if arr is not None and arr.shape == (4, 4) and np.allclose(arr[3], [0, 0, 0, 1]) \
            and np.allclose(arr[:3, 3], 0):
        return arr[:3, :3]
    return answer


class QuaternionToMatrix(DrawnExercise):
    r"""The rotation matrix of a unit quaternion with rational components.

    The top-left entry is :math:`1 - 2y^2 - 2z^2` (the compendium prints :math:`1 - 2y^2`).

    Attributes: ``q`` (scalar first, unit length).

    Examples
    --------
    >>> ex = QuaternionToMatrix(seed=12)
    >>> ex.check(ex.expected).status
    'correct'
    >>> s, x, y, z = ex.q
    >>> printed = ex.expected.copy()
    >>> printed[0, 0] = 1 - 2 * y**2
    >>> ex.check(printed).diagnosis
    'compendium top-left'
    >>> ex.check(ex.expected.T).diagnosis
    'transposed'
    """

    title = "Rotation matrix of a quaternion"

    def draw(self, rng):
        self.ints, self.n = _nice_quaternion(rng)
        self.q = self.ints / self.n
        self.expected = quat.to_matrix(self.q)

    def mistakes(self):
        y = self.q[2]
        printed = self.expected.copy()
        printed[0, 0] = 1 - 2 * y * y
        return [
            Mistake(printed, r"Only the top-left entry is off: it is $1 - 2y^2 - 2z^2$. (The "
                    r"compendium prints $1 - 2y^2$, a misprint: compare with the other two "
                    r"diagonal entries, which each subtract two squares.)", "compendium top-left"),
            Mistake(self.expected.T, r"Your matrix is transposed, which is the rotation the "
                    r"other way (the rotation of $\bar q$). Check the signs of the $s$ terms: "
                    r"the first row is $(1 - 2y^2 - 2z^2,\ 2xy - 2sz,\ 2xz + 2sy)$.",
                    "transposed"),
            Mistake((np.eye(3) + self.expected) / 2, r"Every factor 2 of the formula is "
                    r"missing (e.g. $1 - y^2 - z^2$ instead of $1 - 2y^2 - 2z^2$, $xy - sz$ "
                    r"instead of $2xy - 2sz$).", "factor 2 missing"),
        ]

    def _check(self, answer):
        return super()._check(_as_rotation_block(answer))

    def statement(self):
        return (
            rf"Give the $3 \times 3$ rotation matrix $R$ of the unit quaternion "
            rf"$q = {_fraction_vector(self.ints, self.n)}$ (scalar first, $(s, x, y, z)$), the "
            rf"matrix with $R\,p = q\,p\,\bar q$ for every point $p$." "\n\n"
            r"**Answer:** the $3 \times 3$ matrix as a numpy array. " + DECIMALS + "\n\n"
            + data_note("q"))


_MATRIX_HINT = (r"Careful: if $s$ turns out to be 0 (a turn by $180^\circ$), a recipe that "
                r"divides by $s$ fails; find the largest of $s^2, x^2, y^2, z^2$ from the "
                r"diagonal first and divide by that component instead.")


class MatrixToQuaternion(DrawnExercise):
    r"""The unit quaternion of a rotation matrix, including turns by 180 degrees (:math:`s = 0`).

    About a third of the seeds give a turn by 180 degrees, where the recipe
    :math:`x = (m_{21} - m_{12}) / 4s` divides by zero.

    Attributes: ``R`` (3x3 rotation matrix).

    Examples
    --------
    >>> ex = MatrixToQuaternion(seed=13)
    >>> ex.check(ex.expected).status, ex.check(-ex.expected).status
    ('correct', 'correct')
    >>> ex.check(np.roll(ex.expected, -1)).diagnosis
    'scalar last'
    >>> half_turn = MatrixToQuaternion(seed=2)        # a turn by 180 degrees: s = 0
    >>> half_turn.half_turn, float(half_turn.expected[0])
    (True, 0.0)
    >>> half_turn.check([np.nan] * 4).diagnosis      # the recipe that divides by s
    'division by zero'
    """

    title = "Quaternion of a rotation matrix"
    answer_form = "quaternion"
    what = "the quaternion"
    may_coincide = ("conjugate",)

    def draw(self, rng):
        self.half_turn = bool(rng.random() < 1 / 3)
        ints, n = _nice_quaternion(rng, zero_scalar=self.half_turn)
        while not self.half_turn and ints[0] == 0:
            ints, n = _nice_quaternion(rng)
        if ints[0] < 0:
            ints = -ints
        self.R = quat.to_matrix(ints / n)
        self._ints, self._n2 = ints, n * n
        self.expected = quat.from_matrix(self.R)

    def mistakes(self):
        found = [
            Mistake(quat.conjugate(self.expected), r"You found the conjugate $\bar q$, the "
                    r"rotation the other way (as if from $R^T$). The differences are "
                    r"$4sx = m_{21} - m_{12}$, $4sy = m_{02} - m_{20}$, "
                    r"$4sz = m_{10} - m_{01}$ (row, column, counted from 0).", "conjugate"),
            Mistake(_scalar_last(self.expected), _SCALAR_LAST_TEXT, "scalar last"),
        ]
        if not self.half_turn:
            s, v = self.expected[0], self.expected[1:]
            found.append(Mistake(np.concatenate([[s], 2 * v]), r"The vector part is twice too "
                                 r"long: $m_{21} - m_{12} = 4sx$, so divide by $4s$, not $2s$.",
                                 "divided by 2s"))
        return found

    def _check(self, answer):
        if self.half_turn and _has_nan_or_inf(answer):
            return Feedback("invalid", r"Your answer contains NaN or infinity. This matrix is "
                            r"a turn by $180^\circ$, so $s = \frac12\sqrt{1 + m_{00} + m_{11} "
                            r"+ m_{22}} = 0$ and the recipe that divides by $4s$ breaks down. "
                            r"Use the diagonal: $4x^2 = 1 + m_{00} - m_{11} - m_{22}$ (and "
                            r"likewise for $y$, $z$); take the largest, then e.g. "
                            r"$y = (m_{01} + m_{10}) / 4x$.", "division by zero")
        return super()._check(answer)

    def statement(self):
        return (
            rf"Give a unit quaternion $q$ of the rotation matrix" "\n\n"
            rf"$$R = {_fraction_matrix(self.R, self._n2)}.$$" "\n\n" + _MATRIX_HINT + "\n\n"
            + _QUATERNION + r" Both $q$ and $-q$ are accepted: they describe the same rotation."
            + "\n\n" + data_note("R"))


def _has_nan_or_inf(answer):
    """Whether `answer` reads as numbers of which some are NaN or infinite."""
    if is_unanswered(answer) or isinstance(answer, (str, bytes, dict)):
        return False
    try:
        arr = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return False
    return not np.isfinite(arr).all()


def _same_rotation(q1, q2, atol=2e-3):
    """Whether the quaternions are the same rotation (equal up to sign)."""
    return gap(q1, q2, sign_free=True) <= atol


def _axis_angle_quaternion(axis, angle):
    half = angle / 2
    return np.concatenate([[math.cos(half)], math.sin(half) * axis])


class AxisAngleOfMatrix(DrawnExercise):
    r"""Axis and angle of a rotation matrix; the answer is the tuple ``(axis, angle_radians)``.

    Any description of the same rotation is right: ``(-axis, -angle)``, or the angle plus a
    whole number of turns. The answer is judged by the rotation it describes.

    Attributes: ``R`` (3x3 rotation matrix).

    Examples
    --------
    >>> ex = AxisAngleOfMatrix(seed=14)
    >>> axis, angle = ex.expected
    >>> ex.check((axis, angle)).status, ex.check((-axis, -angle)).status
    ('correct', 'correct')
    >>> ex.check((axis, np.degrees(angle))).diagnosis
    'degrees'
    >>> ex.check((-axis, angle)).diagnosis
    'opposite rotation'
    >>> ex.check((3 * axis, angle)).diagnosis
    'not normalized'
    >>> ex.check((axis, ...)).status, ex.check({"axis": axis}).status
    ('unanswered', 'invalid')
    """

    title = "Axis and angle of a rotation matrix"
    answer_form = "custom"

    def draw(self, rng):
        ints, n = _nice_quaternion(rng)
        self._ints = ints
        if ints[0] < 0:
            ints = -ints
        self.q = ints / n
        self.R = quat.to_matrix(self.q)
        self._n2 = n * n
        axis, angle = quat.to_axis_angle(self.q)
        self.expected = (axis, float(angle))

    def acceptable(self):
        return self._ints[0] != 0 and bool(np.any(self._ints[1:]))

    def _check(self, answer):
        """Judge ``answer = (axis, angle_radians)`` by the rotation it describes."""
        parsed = _read_axis_angle(answer)
        if isinstance(parsed, Feedback):
            return parsed
        axis, angle = parsed
        length = float(np.linalg.norm(axis))
        if length < 1e-9:
            return Feedback("invalid", "Your axis is the zero vector, which has no direction.",
                            "zero axis")
        unit = axis / length
        if _same_rotation(_axis_angle_quaternion(unit, angle), self.q):
            if abs(length - 1) > 2e-3:
                return Feedback("wrong", f"Right direction and angle, but your axis has length "
                                f"{fmt.number(length)}: give a unit vector (divide the axis by "
                                "its length).", "not normalized")
            return Feedback("correct", "The axis and the angle are right (they describe the "
                            "rotation of $R$).")
        if _same_rotation(_axis_angle_quaternion(unit, math.radians(angle)), self.q):
            return Feedback("wrong", f"Your angle is in degrees; give it in radians "
                            f"({fmt.number(angle)}° = {fmt.number(math.radians(angle))} rad).",
                            "degrees")
        if _same_rotation(_axis_angle_quaternion(unit, -angle), self.q):
            return Feedback("wrong", r"You describe the inverse rotation: the axis is reversed "
                            r"(or the angle has the wrong sign). The vector of differences "
                            r"$(m_{21} - m_{12},\ m_{02} - m_{20},\ m_{10} - m_{01})$ (indices "
                            r"row, column, counted from 0) equals $2 \sin\theta\,\hat n$: it "
                            r"points along the axis, in the direction from which the turn looks "
                            r"counter-clockwise.", "opposite rotation")
        expected_axis, expected_angle = self.expected
        if abs(abs(float(unit @ expected_axis)) - 1) < 2e-3:
            return Feedback("wrong", r"The axis is right but the angle is not. From the trace: "
                            r"$\cos\theta = (m_{00} + m_{11} + m_{22} - 1) / 2$.",
                            "angle differs")
        turns = (abs(angle) - expected_angle) / (2 * math.pi)
        if abs(turns - round(turns)) < 1e-3:
            return Feedback("wrong", r"The angle is right but the axis is not. The axis is along "
                            r"$(m_{21} - m_{12},\ m_{02} - m_{20},\ m_{10} - m_{01})$ (row, "
                            r"column, counted from 0); it is the vector that $R$ leaves "
                            r"unchanged, $R\,\hat n = \hat n$.", "axis differs")
        return Feedback("wrong", r"Neither the axis nor the angle is right. The angle follows "
                        r"from the trace, $\cos\theta = (\operatorname{tr} R - 1)/2$, and the "
                        r"axis is along $(m_{21} - m_{12},\ m_{02} - m_{20},\ m_{10} - m_{01})$.",
                        "both differ")

    def statement(self):
        return (
            rf"The matrix" "\n\n" rf"$$R = {_fraction_matrix(self.R, self._n2)}$$" "\n\n"
            rf"is a rotation about "
            rf"an axis through the origin. Find a unit vector $\hat n$ along its axis and the "
            rf"angle $\theta$ of the rotation (counter-clockwise when seen from the tip of "
            rf"$\hat n$)." "\n\n"
            r"**Answer:** a tuple `(axis, angle)`: `axis` a list of 3 numbers of unit length, "
            r"`angle` in **radians**. Any description of the same rotation is accepted (e.g. "
            r"$(-\hat n, -\theta)$). " + DECIMALS + "\n\n" + data_note("R"))


def _read_axis_angle(answer):
    """``(axis, angle)`` as a float vector and a float, or a Feedback saying why not."""
    if is_unanswered(answer) or (isinstance(answer, (tuple, list)) and len(answer) == 2
                                 and any(is_unanswered(part) for part in answer)):
        return Feedback("unanswered", UNANSWERED)
    if not isinstance(answer, (tuple, list)) or len(answer) != 2:
        return Feedback("invalid", "Give a tuple of two things, `(axis, angle)`: the axis as 3 "
                        "numbers and the angle in radians as one number.", "unreadable")
    axis, angle = (read_floats(part) for part in answer)
    if axis is None or axis.shape != (3,):
        return Feedback("invalid", "The axis (first item) should be 3 numbers, e.g. "
                        "`[0.6, 0, 0.8]`.", "unreadable")
    if angle is None or angle.size != 1:
        return Feedback("invalid", "The angle (second item) should be one number, in radians.",
                        "unreadable")
    return axis, float(angle.ravel()[0])


_COMPOSE_ANGLES = (60, 90, 120, 180, -90)
_COORDINATE_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}


class ComposeRotationsWithQuaternions(DrawnExercise):
    r"""Two rotations one after the other as one quaternion: first :math:`q_1`, then :math:`q_2`.

    The combined rotation is :math:`q_2\,q_1`, because
    :math:`q_2 (q_1 p \bar q_1) \bar q_2 = (q_2 q_1)\,p\,\overline{(q_2 q_1)}`.

    Attributes: ``axis1``, ``theta1_deg``, ``theta1``, ``axis2``, ``theta2_deg``, ``theta2``
    (angles also in radians).

    Examples
    --------
    >>> from course_lib import quaternions as quat
    >>> ex = ComposeRotationsWithQuaternions(seed=15)
    >>> ex.check(ex.expected).status
    'correct'
    >>> q1 = quat.from_axis_angle(ex.axis1, ex.theta1)
    >>> q2 = quat.from_axis_angle(ex.axis2, ex.theta2)
    >>> ex.check(quat.multiply(q1, q2)).diagnosis
    'wrong order'
    """

    title = "Two rotations as one quaternion"
    answer_form = "quaternion"
    what = "the quaternion"

    def draw(self, rng):
        name1, name2 = rng.choice(list(_COORDINATE_AXES), size=2, replace=False)
        self.axis1_name, self.axis2_name = str(name1), str(name2)
        self.axis1 = np.array(_COORDINATE_AXES[self.axis1_name])
        self.axis2 = np.array(_COORDINATE_AXES[self.axis2_name])
        self.theta1_deg = int(pick(rng, _COMPOSE_ANGLES))
        self.theta2_deg = int(pick(rng, _COMPOSE_ANGLES))
        self.theta1 = math.radians(self.theta1_deg)
        self.theta2 = math.radians(self.theta2_deg)
        self.expected = quat.multiply(*self._quaternions()[::-1])

    def _quaternions(self, factor=1.0):
        return (quat.from_axis_angle(self.axis1, factor * self.theta1),
                quat.from_axis_angle(self.axis2, factor * self.theta2))

    def mistakes(self):
        q1, q2 = self._quaternions()
        full1, full2 = self._quaternions(2.0)
        return [
            Mistake(quat.multiply(q1, q2), r"You computed $q_1\,q_2$, which rotates by $q_2$ "
                    r"first. Applying $q_1$ and then $q_2$ gives "
                    r"$q_2 (q_1 p \bar q_1) \bar q_2 = (q_2 q_1)\, p\, \overline{q_2 q_1}$: the "
                    r"rotation applied first stands on the right, as with matrices.",
                    "wrong order"),
            Mistake(_scalar_last(self.expected), _SCALAR_LAST_TEXT, "scalar last"),
            Mistake(quat.multiply(full2, full1), r"The order is right, but you built $q_1$ and "
                    r"$q_2$ with the full angles: each quaternion holds half its angle, "
                    r"$(\cos\frac{\theta}{2}, \sin\frac{\theta}{2}\,\hat n)$.", "full angle"),
        ]

    def statement(self):
        return (
            rf"A body is first rotated by $\theta_1 = {_deg(self.theta1_deg)}$ about the "
            rf"{self.axis1_name} axis (quaternion $q_1$), and then by "
            rf"$\theta_2 = {_deg(self.theta2_deg)}$ about the {self.axis2_name} axis "
            rf"(quaternion $q_2$); both axes are fixed in space and pass through the origin. "
            rf"Give the single unit quaternion $q$ of the combined rotation." "\n\n" + _QUATERNION
            + r" Both $q$ and $-q$ are accepted." + "\n\n"
            + data_note("axis1", "theta1_deg", "theta1", "axis2", "theta2_deg", "theta2")
            + " (`.theta1`, `.theta2` are in radians.)")


class SlerpMidpoint(DrawnExercise):
    r"""The orientation halfway between two unit quaternions by slerp (:math:`t = 1/2`).

    At :math:`t = 1/2` both slerp weights equal :math:`\sin(\Omega/2)/\sin\Omega`, so the result
    is :math:`(q_0 + q_1) / \lVert q_0 + q_1 \rVert`, after replacing :math:`q_1` by
    :math:`-q_1` when :math:`q_0 \cdot q_1 < 0` (the shorter way round).

    Attributes: ``q0``, ``q1`` (unit, scalar first).

    Examples
    --------
    >>> ex = SlerpMidpoint(seed=0)
    >>> float(ex.q0 @ ex.q1) < 0            # this variant needs the shorter arc
    True
    >>> ex.check(ex.expected).status
    'correct'
    >>> plain = (ex.q0 + ex.q1) / np.linalg.norm(ex.q0 + ex.q1)
    >>> ex.check(plain).diagnosis
    'longer arc'
    """

    title = "Halfway between two orientations (slerp)"
    answer_form = "quaternion"
    what = "the quaternion"

    def draw(self, rng):
        ints0, n0 = _nice_quaternion(rng)
        ints1, n1 = _nice_quaternion(rng)
        self._ints0, self._n0, self._ints1, self._n1 = ints0, n0, ints1, n1
        self.q0, self.q1 = ints0 / n0, ints1 / n1
        self.expected = quat.slerp(self.q0, self.q1, 0.5)

    def mistakes(self):
        dot = float(self.q0 @ self.q1)
        near = self.q1 if dot >= 0 else -self.q1
        found = [Mistake((self.q0 + near) / 2, r"Right direction, but the average "
                         r"$(q_0 + q_1)/2$ is shorter than 1. Slerp stays on the unit sphere: "
                         r"divide by the length, $(q_0 + q_1) / \lVert q_0 + q_1 \rVert$.",
                         "not normalized")]
        if dot < 0:
            plain = self.q0 + self.q1
            found.append(Mistake(plain / np.linalg.norm(plain), r"You went the long way round. "
                                 r"Here $q_0 \cdot q_1 < 0$: $q_1$ and $-q_1$ are the same "
                                 r"orientation, and $-q_1$ is the nearer one. Replace $q_1$ by "
                                 r"$-q_1$ before interpolating.", "longer arc"))
        return found

    def acceptable(self):
        return 0.1 < abs(float(self.q0 @ self.q1)) < 0.95

    def statement(self):
        return (
            rf"Two orientations are given by the unit quaternions "
            rf"$q_0 = {_fraction_vector(self._ints0, self._n0)}$ and "
            rf"$q_1 = {_fraction_vector(self._ints1, self._n1)}$ (scalar first). Give the "
            rf"orientation halfway between them by spherical linear interpolation (slerp) at "
            rf"$t = \tfrac12$, the way an animation system would turn a body from $q_0$ to "
            rf"$q_1$." "\n\n" + _QUATERNION + r" Both $q$ and $-q$ are accepted." + "\n\n"
            + data_note("q0", "q1"))


#: The exercises of chapter 3, in the order of the solutions notebook.
EXERCISES = (
    ComposeMatrix2D,
    RotateAboutPoint,
    InverseOfComposite,
    MirrorAboutLine,
    ShearInverse,
    ShearImage,
    ShearedBoxVolume,
    RotationAboutArbitraryAxis,
    QuaternionFromAxisAngle,
    QuaternionProduct,
    RotatePointWithQuaternion,
    QuaternionToMatrix,
    MatrixToQuaternion,
    AxisAngleOfMatrix,
    ComposeRotationsWithQuaternions,
    SlerpMidpoint,
)
