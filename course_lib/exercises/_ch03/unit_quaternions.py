"""Chapter 3 exercises: Quaternions.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import math
from typing import NamedTuple

import numpy as np

from ... import format as fmt
from ... import quaternions as quat
from ..core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, agrees,
                    as_vector, data_note, is_unanswered, pick, read_floats, rounding_of,
                    small_ints)
from . import (_BOOL_TEXT, _POINT_3, _QUATERNION, PointAnswer, _bar, _cos_sin, _deg,
               _degrees_text, _fraction_matrix, _fraction_vector, _hamilton, _holds_bool, _mat,
               _nice_axis, _nice_quaternion, _num, _par, _snap, _vec)

__all__ = [
    "AxisAngleOfMatrix",
    "ComposeRotationsWithQuaternions",
    "MatrixToQuaternion",
    "QuaternionFromAxisAngle",
    "QuaternionProduct",
    "QuaternionToMatrix",
    "RotatePointWithQuaternion",
    "SlerpMidpoint",
]


_QUATERNION_ANGLES = (30, 45, 60, 90, 120, 135, 150, 180, 240, 270, 300)


def _scalar_last(q):
    return np.roll(np.asarray(q, dtype=float), -1)


def _half_angle_degrees_text(angle_deg, what):
    """What a student is told who fed the half angle's degrees to cos and sin as radians."""
    half = angle_deg / 2
    c, _ = _cos_sin(half)
    return (rf"You fed the half angle in degrees, ${_num(half)}$, to $\cos$ and $\sin$, which "
            rf"expect radians ($\cos({_num(half)}\,\mathrm{{rad}}) = {_num(math.cos(half))}$, "
            rf"whereas $\cos {_num(half)}^\circ = {_num(c)}$): {what} by {_num(angle_deg)} "
            r"radians instead of degrees. Convert first with `np.radians` (or use the attribute "
            r"in radians).")


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
    may_coincide = ("conjugate",)          # a turn by 180 degrees is its own inverse

    def draw(self, rng):
        self.axis = _nice_axis(rng)
        self.theta_deg = int(pick(rng, _QUATERNION_ANGLES))
        self.theta = math.radians(self.theta_deg)
        self.expected = _snap(quat.from_axis_angle(self.axis, self.theta))

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
            Mistake(quat.conjugate(self.expected), r"That is the conjugate "
                    r"$\bar q = (\cos\frac{\theta}{2}, -\sin\frac{\theta}{2}\,\hat n)$, the "
                    r"rotation by $-\theta$ (clockwise seen from the tip of $u$). For a "
                    r"counter-clockwise turn by $+\theta$ the vector part points **along** the "
                    r"axis: $+\sin\frac{\theta}{2}\,\hat n$.", "conjugate"),
        ]

    def _numbers(self):
        length = float(np.linalg.norm(self.axis))
        c, s = _cos_sin(self.theta_deg / 2)
        return length, self.axis / length, c, s

    def hints(self):
        length, n, c, s = self._numbers()
        return [
            r"A unit quaternion holds **half** the angle and the **unit** axis: "
            r"$q = (\cos\frac{\theta}{2},\ \sin\frac{\theta}{2}\,\hat n)$.",
            rf"$u$ has length ${_num(length)}$, so $\hat n = u / {_num(length)} = {_vec(n)}$; "
            rf"half the angle is $\frac{{\theta}}{{2}} = {_num(self.theta_deg / 2)}^\circ$.",
            rf"$\cos {_num(self.theta_deg / 2)}^\circ = {_num(c)}$ is the scalar part, and the "
            rf"vector part is $\sin {_num(self.theta_deg / 2)}^\circ = {_num(s)}$ times "
            r"$\hat n$.",
        ]

    def worked(self):
        length, n, c, s = self._numbers()
        q = np.concatenate([[c], s * n])
        return Worked([
            rf"Normalize the axis: $\lVert u \rVert = {_num(length)}$, "
            rf"$\hat n = {_vec(n)}$.",
            rf"Half the angle: $\frac{{\theta}}{{2}} = {_num(self.theta_deg / 2)}^\circ$, with "
            rf"cosine ${_num(c)}$ and sine ${_num(s)}$.",
            rf"$q = (\cos\frac{{\theta}}{{2}},\ \sin\frac{{\theta}}{{2}}\,\hat n) = "
            rf"{_vec(q)}$ (length 1; $-q$ is the same rotation).",
        ], q)

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

    def _parts(self):
        s1, v1 = float(self.q1[0]), np.asarray(self.q1[1:], dtype=float)
        s2, v2 = float(self.q2[0]), np.asarray(self.q2[1:], dtype=float)
        return s1, v1, s2, v2, float(v1 @ v2), np.cross(v1, v2)

    def hints(self):
        s1, v1, s2, v2, dot, cross = self._parts()
        return [
            r"Write each quaternion as a scalar and a vector, $q = (s, v)$; then "
            r"$q_1 q_2 = (s_1 s_2 - v_1 \cdot v_2,\ s_1 v_2 + s_2 v_1 + v_1 \times v_2)$.",
            rf"Here $s_1 = {_num(s1)}$, $v_1 = {_vec(v1)}$, $s_2 = {_num(s2)}$, "
            rf"$v_2 = {_vec(v2)}$, and $v_1 \cdot v_2 = {_num(dot)}$: the scalar part is "
            rf"${_num(s1 * s2)} - {_par(dot)}$.",
            rf"The cross product, in this order, is $v_1 \times v_2 = {_vec(cross)}$; add it to "
            rf"$s_1 v_2 + s_2 v_1 = {_vec(s1 * v2 + s2 * v1)}$.",
        ]

    def worked(self):
        s1, v1, s2, v2, dot, cross = self._parts()
        scalar = s1 * s2 - dot
        vector = s1 * v2 + s2 * v1 + cross
        return Worked([
            rf"$q_1 = ({_num(s1)}, {_vec(v1)})$ and $q_2 = ({_num(s2)}, {_vec(v2)})$ as "
            r"(scalar, vector).",
            rf"Scalar part: $s_1 s_2 - v_1 \cdot v_2 = {_num(s1 * s2)} - ({_num(dot)}) = "
            rf"{_num(scalar)}$.",
            rf"Vector part: $s_1 v_2 + s_2 v_1 + v_1 \times v_2 = {_vec(s1 * v2)} + "
            rf"{_vec(s2 * v1)} + {_vec(cross)} = {_vec(vector)}$.",
            rf"$q_1 q_2 = {_vec(np.concatenate([[scalar], vector]))}$.",
        ], np.concatenate([[scalar], vector]))

    def statement(self):
        return (
            rf"Compute the quaternion product $q_1\,q_2$ of $q_1 = {_quaternion_text(self.q1)}$ "
            rf"and $q_2 = {_quaternion_text(self.q2)}$, both written scalar first "
            rf"$(s, x, y, z)$. They are not unit quaternions; do not normalize anything." "\n\n"
            r"**Answer:** a list of 4 numbers, **scalar first**: `[s, x, y, z]`." + "\n\n"
            + data_note("q1", "q2"))


_ROTATION_ANGLES = (60, 90, 120, 180, 240, -90)


class RotatePointWithQuaternion(PointAnswer, DrawnExercise):
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
    what = "the rotated point"

    def draw(self, rng):
        self.axis = _nice_axis(rng)
        self.theta_deg = int(pick(rng, _ROTATION_ANGLES))
        self.theta = math.radians(self.theta_deg)
        self.p = small_ints(rng, 3, -2, 2)
        self.expected = _snap(quat.rotate(quat.from_axis_angle(self.axis, self.theta), self.p))

    def mistakes(self):
        half = self.theta / 2
        raw = np.concatenate([[math.cos(half)], math.sin(half) * self.axis])
        pure = np.concatenate([[0.0], self.p])
        q = quat.from_axis_angle(self.axis, self.theta)
        return [
            Mistake(quat.rotate(quat.from_axis_angle(self.axis, -self.theta), self.p), r"The "
                    r"point turned the wrong way, by $-\theta$: you used the conjugate where "
                    r"$q$ belongs, computing $\bar q\,p\,q$ (or built $q$ with "
                    r"$-\sin\frac{\theta}{2}$). The rotation by $+\theta$ is "
                    r"$p' = q\,p\,\bar q$ with "
                    r"$q = (\cos\frac{\theta}{2}, +\sin\frac{\theta}{2}\,\hat n)$ on the left.",
                    "other way"),
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
            Mistake(quat.rotate(quat.from_axis_angle(self.axis, self.theta_deg), self.p),
                    _half_angle_degrees_text(self.theta_deg, "the point turned"), "degrees"),
        ]

    def _quaternion(self):
        length = float(np.linalg.norm(self.axis))
        n = self.axis / length
        c, s = _cos_sin(self.theta_deg / 2)
        return length, n, np.concatenate([[c], s * n])

    def hints(self):
        length, n, q = self._quaternion()
        qp = _hamilton(q, np.concatenate([[0.0], self.p]))
        return [
            r"Build the unit quaternion $q = (\cos\frac{\theta}{2},\ \sin\frac{\theta}{2}"
            r"\,\hat n)$, write the point as $(0, p)$, and compute two Hamilton products: "
            r"$(q\,p)\,\bar q$.",
            rf"$\hat n = u / {_num(length)} = {_vec(n)}$ and "
            rf"$\frac{{\theta}}{{2}} = {_num(self.theta_deg / 2)}^\circ$, so "
            rf"$q = {_vec(q)}$ and $\bar q = {_vec(_bar(q))}$.",
            rf"The first product is $q\,p = {_vec(qp)}$; multiply it by $\bar q$ on the "
            r"right, and read the point from the vector part (the scalar part comes out 0).",
        ]

    def worked(self):
        length, n, q = self._quaternion()
        pure = np.concatenate([[0.0], self.p])
        qp = _hamilton(q, pure)
        result = _hamilton(qp, _bar(q))
        return Worked([
            rf"$\hat n = u / {_num(length)} = {_vec(n)}$; $\frac{{\theta}}{{2}} = "
            rf"{_num(self.theta_deg / 2)}^\circ$, so $q = {_vec(q)}$ and "
            rf"$\bar q = {_vec(_bar(q))}$.",
            rf"With $p = (0, {_vec(self.p)})$: $q\,p = (-v \cdot p,\ s\,p + v \times p) = "
            rf"{_vec(qp)}$, where $(s, v) = q$.",
            rf"$(q\,p)\,\bar q = {_vec(result)}$: the scalar part is 0, as it must be for a "
            r"point.",
            rf"The rotated point is the vector part, $p' = {_vec(result[1:])}$.",
        ], result[1:])

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
        self.expected = _snap(quat.to_matrix(self.q))

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

    def _matrix_by_hand(self):
        s, x, y, z = (float(v) for v in self.q)
        return np.array([
            [1 - 2 * y * y - 2 * z * z, 2 * x * y - 2 * s * z, 2 * x * z + 2 * s * y],
            [2 * x * y + 2 * s * z, 1 - 2 * x * x - 2 * z * z, 2 * y * z - 2 * s * x],
            [2 * x * z - 2 * s * y, 2 * y * z + 2 * s * x, 1 - 2 * x * x - 2 * y * y]])

    def hints(self):
        s, x, y, z = self.q
        R = self._matrix_by_hand()
        return [
            r"Use the matrix of $q = (s, x, y, z)$: its first row is "
            r"$(1 - 2y^2 - 2z^2,\ 2xy - 2sz,\ 2xz + 2sy)$, and the others follow by cycling "
            r"$x \to y \to z \to x$ (each diagonal entry subtracts two squares).",
            rf"Here $s = {_num(s)}$, $x = {_num(x)}$, $y = {_num(y)}$, $z = {_num(z)}$: every "
            rf"entry is a whole number over $n^2 = {self.n * self.n}$, which is easier to keep "
            r"exact by hand.",
            rf"The diagonal is $({_num(R[0, 0])}, {_num(R[1, 1])}, {_num(R[2, 2])})$; for the "
            rf"others, e.g. $2xy - 2sz = {_num(R[0, 1])}$ and $2xy + 2sz = {_num(R[1, 0])}$.",
        ]

    def worked(self):
        s, x, y, z = (float(v) for v in self.q)
        R = self._matrix_by_hand()
        n2 = self.n * self.n
        return Worked([
            rf"$q = {_fraction_vector(self.ints, self.n)}$: $s = {_num(s)}$, $x = {_num(x)}$, "
            rf"$y = {_num(y)}$, $z = {_num(z)}$.",
            rf"Diagonal: $1 - 2y^2 - 2z^2 = {_num(R[0, 0])}$, $1 - 2x^2 - 2z^2 = "
            rf"{_num(R[1, 1])}$, $1 - 2x^2 - 2y^2 = {_num(R[2, 2])}$.",
            rf"Off the diagonal: $2xy \mp 2sz = {_num(R[0, 1])}, {_num(R[1, 0])}$; "
            rf"$2xz \pm 2sy = {_num(R[0, 2])}, {_num(R[2, 0])}$; $2yz \mp 2sx = "
            rf"{_num(R[1, 2])}, {_num(R[2, 1])}$ (upper entry first).",
            rf"$R = {_fraction_matrix(R, n2)} = {_mat(R)}$.",
        ], R)

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

    def _squares(self):
        """4s^2, 4x^2, 4y^2, 4z^2 from the diagonal, and the index of the largest."""
        (m00, _, _), (_, m11, _), (_, _, m22) = self.R
        four = [1 + m00 + m11 + m22, 1 + m00 - m11 - m22, 1 - m00 + m11 - m22,
                1 - m00 - m11 + m22]
        return four, int(np.argmax(four))

    def hints(self):
        four, big = self._squares()
        name = "sxyz"[big]
        return [
            r"The diagonal gives the squares: $4s^2 = 1 + m_{00} + m_{11} + m_{22}$, "
            r"$4x^2 = 1 + m_{00} - m_{11} - m_{22}$, and likewise $4y^2$, $4z^2$. The entries "
            r"off the diagonal give the products: $4sx = m_{21} - m_{12}$, "
            r"$4xy = m_{01} + m_{10}$, ...",
            rf"Here $(4s^2, 4x^2, 4y^2, 4z^2) = ({', '.join(_num(v) for v in four)})$. Start "
            rf"from the largest, ${name}$, so that you never divide by 0 (or by a tiny "
            r"number).",
            rf"${name} = \tfrac12\sqrt{{{_num(four[big])}}} = {_num(math.sqrt(four[big]) / 2)}$;"
            rf" divide the three sums or differences that contain ${name}$ by $4{name}$ to get "
            r"the other components.",
        ]

    def worked(self):
        four, big = self._squares()
        m = self.R
        name = "sxyz"[big]
        value = math.sqrt(four[big]) / 2
        # the six products, 4 times: (s, x), (s, y), (s, z), (x, y), (x, z), (y, z)
        products = {(0, 1): m[2, 1] - m[1, 2], (0, 2): m[0, 2] - m[2, 0],
                    (0, 3): m[1, 0] - m[0, 1], (1, 2): m[0, 1] + m[1, 0],
                    (1, 3): m[0, 2] + m[2, 0], (2, 3): m[1, 2] + m[2, 1]}
        q = np.zeros(4)
        q[big] = value
        lines = []
        for other in range(4):
            if other == big:
                continue
            four_product = products[tuple(sorted((big, other)))]
            q[other] = four_product / (4 * value)
            lines.append(rf"${'sxyz'[other]} = {_num(four_product)} / (4 \cdot {_num(value)}) "
                         rf"= {_num(q[other])}$")
        return Worked([
            rf"From the diagonal: $(4s^2, 4x^2, 4y^2, 4z^2) = "
            rf"({', '.join(_num(v) for v in four)})$.",
            rf"The largest is $4{name}^2$: ${name} = \tfrac12\sqrt{{{_num(four[big])}}} = "
            rf"{_num(value)}$ (the sign of $q$ is free; take it positive)."
            + (r" Here $s = 0$: a turn by $180^\circ$, where the recipe that divides by $s$ "
               r"fails." if self.half_turn else ""),
            r"The off-diagonal entries: $4sx = m_{21} - m_{12}$, $4sy = m_{02} - m_{20}$, "
            r"$4sz = m_{10} - m_{01}$, $4xy = m_{01} + m_{10}$, $4xz = m_{02} + m_{20}$, "
            rf"$4yz = m_{{12}} + m_{{21}}$. Divided by $4{name}$: " + ", ".join(lines) + ".",
            rf"$q = {_vec(q)}$ (scalar first).",
        ], q)

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


class AxisAngle(NamedTuple):
    """An axis and an angle in radians: a tuple ``(axis, angle)``; numpy reads it as the four
    numbers ``(n_x, n_y, n_z, angle)``.

    Examples
    --------
    >>> axis, angle = AxisAngle(np.array([0.0, 0.0, 1.0]), 0.5)
    >>> float(angle), np.asarray(AxisAngle(axis, angle)).tolist()
    (0.5, [0.0, 0.0, 1.0, 0.5])
    """

    axis: np.ndarray
    angle: float

    def __array__(self, dtype=None, copy=None):
        return np.append(np.asarray(self.axis, dtype=float), float(self.angle)).astype(
            dtype or float)


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
        self.expected = AxisAngle(_snap(axis), float(angle))

    def acceptable(self):
        return self._ints[0] != 0 and bool(np.any(self._ints[1:]))

    def _check(self, answer):
        """Judge ``answer = (axis, angle_radians)`` by the course's tolerance policy.

        The description is first turned to the side of the expected axis (``(-n, -theta)`` is
        ``(n, theta)``) and a whole turn is taken off the angle; then the axis and the angle are
        compared with :func:`agrees`.
        """
        parsed = _read_axis_angle(answer)
        if isinstance(parsed, Feedback):
            return parsed
        axis, angle = parsed
        length = float(np.linalg.norm(axis))
        if length < 1e-9:
            return Feedback("invalid", "Your axis is the zero vector, which has no direction.",
                            "zero axis")
        n, theta = self.expected
        if axis @ n < 0:                               # the same rotation, described from -n
            axis, angle = -axis, -angle
        unit = axis / length
        turned = angle - 2 * math.pi * round(angle / (2 * math.pi)) \
            if abs(angle) <= 3 * math.pi + 0.01 else angle           # degrees are not turns
        direction = agrees(unit, n)
        if direction and agrees(turned, theta) and agrees(length, 1.0):
            return Feedback("correct", "The axis and the angle are right (they describe the "
                            "rotation of $R$).")
        if rounding_of(np.append(axis, turned), np.append(n, theta)):
            return Feedback("wrong", "Close: your axis and angle look like the right ones "
                            "rounded to too few digits. Give at least 3 significant digits (or 3 "
                            "decimals), and keep the full precision in the intermediate steps.",
                            "rounded")
        if direction and agrees(turned, theta):
            return Feedback("wrong", f"Right direction and angle, but your axis has length "
                            f"{fmt.number(length)}: give a unit vector (divide the axis by its "
                            "length).", "not normalized")
        if direction and agrees(math.radians(angle), theta):
            return Feedback("wrong", f"Your angle is in degrees; give it in radians "
                            f"({fmt.number(angle)}° = {fmt.number(math.radians(angle))} rad).",
                            "degrees")
        if direction and agrees(-turned, theta):
            return Feedback("wrong", r"You describe the inverse rotation: the axis is reversed "
                            r"(or the angle has the wrong sign). The vector of differences "
                            r"$(m_{21} - m_{12},\ m_{02} - m_{20},\ m_{10} - m_{01})$ (indices "
                            r"row, column, counted from 0) equals $2 \sin\theta\,\hat n$: it "
                            r"points along the axis, in the direction from which the turn looks "
                            r"counter-clockwise.", "opposite rotation")
        if direction:
            return Feedback("wrong", r"The axis is right but the angle is not. From the trace: "
                            r"$\cos\theta = (m_{00} + m_{11} + m_{22} - 1) / 2$.",
                            "angle differs")
        if agrees(abs(turned), theta):
            return Feedback("wrong", r"The angle is right but the axis is not. The axis is along "
                            r"$(m_{21} - m_{12},\ m_{02} - m_{20},\ m_{10} - m_{01})$ (row, "
                            r"column, counted from 0); it is the vector that $R$ leaves "
                            r"unchanged, $R\,\hat n = \hat n$.", "axis differs")
        return Feedback("wrong", r"Neither the axis nor the angle is right. The angle follows "
                        r"from the trace, $\cos\theta = (\operatorname{tr} R - 1)/2$, and the "
                        r"axis is along $(m_{21} - m_{12},\ m_{02} - m_{20},\ m_{10} - m_{01})$.",
                        "both differ")

    def _numbers(self):
        m = self.R
        trace = float(m[0, 0] + m[1, 1] + m[2, 2])
        cos_theta = (trace - 1) / 2
        differences = np.array([m[2, 1] - m[1, 2], m[0, 2] - m[2, 0], m[1, 0] - m[0, 1]])
        return trace, cos_theta, differences

    def hints(self):
        trace, cos_theta, differences = self._numbers()
        return [
            r"Two facts about a rotation matrix: its trace is $1 + 2\cos\theta$, and its "
            r"antisymmetric part points along the axis: $(m_{21} - m_{12},\ m_{02} - m_{20},\ "
            r"m_{10} - m_{01}) = 2\sin\theta\,\hat n$.",
            rf"Here the trace is ${_num(trace)}$, so $\cos\theta = {_num(cos_theta)}$ and "
            rf"$\theta = \arccos({_num(cos_theta)}) = {_num(math.acos(cos_theta))}$ rad (between "
            r"0 and $\pi$, so $\sin\theta > 0$).",
            rf"The differences are ${_vec(differences)}$, of length $2\sin\theta = "
            rf"{_num(float(np.linalg.norm(differences)))}$: divide by it to get $\hat n$.",
        ]

    def worked(self):
        trace, cos_theta, differences = self._numbers()
        theta = math.acos(cos_theta)
        axis = differences / (2 * math.sin(theta))
        return Worked([
            rf"Trace: ${_num(self.R[0, 0])} + {_num(self.R[1, 1])} + {_num(self.R[2, 2])} = "
            rf"{_num(trace)} = 1 + 2\cos\theta$, so $\cos\theta = {_num(cos_theta)}$.",
            rf"$\theta = \arccos({_num(cos_theta)}) = {_num(theta, 4)}$ rad "
            rf"(${_num(math.degrees(theta), 2)}^\circ$).",
            rf"$(m_{{21}} - m_{{12}},\ m_{{02}} - m_{{20}},\ m_{{10}} - m_{{01}}) = "
            rf"{_vec(differences)} = 2\sin\theta\,\hat n$ with $2\sin\theta = "
            rf"{_num(2 * math.sin(theta))}$.",
            rf"$\hat n = {_vec(axis)}$ (length 1), $\theta = {_num(theta, 4)}$ rad.",
        ], AxisAngle(axis, theta), shown=rf"$\hat n = {_vec(axis, 4)}$, "
           rf"$\theta = {_num(theta, 4)}$ rad")

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
    """``(axis, angle)`` as a float vector and a float, or a Feedback saying why not.

    The axis may be a row or a column; True and False are refused as numbers.
    """
    if is_unanswered(answer) or (isinstance(answer, (tuple, list)) and len(answer) == 2
                                 and any(is_unanswered(part) for part in answer)):
        return Feedback("unanswered", UNANSWERED)
    if not isinstance(answer, (tuple, list)) or len(answer) != 2:
        return Feedback("invalid", "Give a tuple of two things, `(axis, angle)`: the axis as 3 "
                        "numbers and the angle in radians as one number.", "unreadable")
    if _holds_bool(answer):
        return Feedback("invalid", _BOOL_TEXT, "not a number")
    axis, angle = (read_floats(part) for part in answer)
    if axis is not None:
        axis = as_vector(axis, 3)
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
        self.expected = _snap(quat.multiply(*self._quaternions()[::-1]))

    def _quaternions(self, factor=1.0):
        return (quat.from_axis_angle(self.axis1, factor * self.theta1),
                quat.from_axis_angle(self.axis2, factor * self.theta2))

    def mistakes(self):
        q1, q2 = self._quaternions()
        full1, full2 = self._quaternions(2.0)
        found = [
            Mistake(quat.multiply(q1, q2), r"You computed $q_1\,q_2$, which rotates by $q_2$ "
                    r"first. Applying $q_1$ and then $q_2$ gives "
                    r"$q_2 (q_1 p \bar q_1) \bar q_2 = (q_2 q_1)\, p\, \overline{q_2 q_1}$: the "
                    r"rotation applied first stands on the right, as with matrices.",
                    "wrong order"),
            Mistake(_scalar_last(self.expected), _SCALAR_LAST_TEXT, "scalar last"),
            Mistake(quat.multiply(full2, full1), r"The order is right, but you built $q_1$ and "
                    r"$q_2$ with the full angles: each quaternion holds half its angle, "
                    r"$(\cos\frac{\theta}{2}, \sin\frac{\theta}{2}\,\hat n)$.", "full angle"),
            Mistake(quat.multiply(quat.from_axis_angle(self.axis2, self.theta2_deg),
                                  quat.from_axis_angle(self.axis1, self.theta1_deg)),
                    rf"You fed the half angles in degrees "
                    rf"(${_num(self.theta1_deg / 2)}$ and ${_num(self.theta2_deg / 2)}$) to "
                    r"$\cos$ and $\sin$, which expect radians, so each factor turns by its "
                    r"angle's number of *radians*. Convert first with `np.radians` (or use "
                    r"`.theta1` and `.theta2`, which are in radians).", "degrees"),
        ]
        if 180 not in (self.theta1_deg, self.theta2_deg):
            # with a half turn the two conjugates give the rotation of q1 q2 ("wrong order")
            found.append(Mistake(
                quat.multiply(quat.conjugate(q2), quat.conjugate(q1)), r"The order is right, "
                r"but both factors are conjugates, $\bar q_2\,\bar q_1$: each turns by "
                r"$-\theta_i$. For a counter-clockwise turn by $+\theta$ about an axis the vector "
                r"part is $+\sin\frac{\theta}{2}$ times the axis, e.g. "
                r"$(\cos\frac{\theta}{2}, \sin\frac{\theta}{2}, 0, 0)$ about x.", "conjugate"))
        return found

    def _factors(self):
        c1, s1 = _cos_sin(self.theta1_deg / 2)
        c2, s2 = _cos_sin(self.theta2_deg / 2)
        q1 = np.concatenate([[c1], s1 * self.axis1])
        q2 = np.concatenate([[c2], s2 * self.axis2])
        return q1, q2

    def hints(self):
        q1, q2 = self._factors()
        return [
            r"Rotating by $q_1$ and then by $q_2$ is $q_2 (q_1 p \bar q_1) \bar q_2 = "
            r"(q_2 q_1)\,p\,\overline{(q_2 q_1)}$: the first rotation stands on the **right**, "
            r"$q = q_2\,q_1$.",
            rf"Each factor holds half its angle: $q_1 = (\cos\frac{{\theta_1}}{{2}}, "
            rf"\sin\frac{{\theta_1}}{{2}}\,e_{self.axis1_name}) = {_vec(q1)}$ and "
            rf"$q_2 = {_vec(q2)}$.",
            rf"With $q_2 = (s_2, v_2)$, $q_1 = (s_1, v_1)$: $q = (s_2 s_1 - v_2 \cdot v_1,\ "
            rf"s_2 v_1 + s_1 v_2 + v_2 \times v_1)$; here $v_2 \times v_1 = "
            rf"{_vec(np.cross(q2[1:], q1[1:]))}$.",
        ]

    def worked(self):
        q1, q2 = self._factors()
        s1, v1, s2, v2 = q1[0], q1[1:], q2[0], q2[1:]
        scalar = s2 * s1 - v2 @ v1
        vector = s2 * v1 + s1 * v2 + np.cross(v2, v1)
        q = np.concatenate([[scalar], vector])
        return Worked([
            rf"$q_1 = {_vec(q1)}$ (half of ${_num(self.theta1_deg)}^\circ$ about "
            rf"{self.axis1_name}) and $q_2 = {_vec(q2)}$ (half of "
            rf"${_num(self.theta2_deg)}^\circ$ about {self.axis2_name}).",
            r"$q_1$ acts first, so it stands on the right: $q = q_2\,q_1$.",
            rf"Scalar part: $s_2 s_1 - v_2 \cdot v_1 = {_num(s2 * s1)} - ({_num(v2 @ v1)}) = "
            rf"{_num(scalar)}$.",
            rf"Vector part: $s_2 v_1 + s_1 v_2 + v_2 \times v_1 = {_vec(s2 * v1)} + "
            rf"{_vec(s1 * v2)} + {_vec(np.cross(v2, v1))} = {_vec(vector)}$.",
            rf"$q = {_vec(q)}$.",
        ], q)

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
        self.expected = _snap(quat.slerp(self.q0, self.q1, 0.5))

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
        # no component so small that 2 decimals keep none of its digits (nor the angle tiny)
        small = np.abs(self.expected)
        return 0.1 < abs(float(self.q0 @ self.q1)) < 0.95 \
            and not np.any((small > 0) & (small < 0.012))

    def _numbers(self):
        dot = float(self.q0 @ self.q1)
        near = self.q1 if dot >= 0 else -self.q1
        omega = math.acos(abs(dot))
        weight = math.sin(omega / 2) / math.sin(omega)
        return dot, near, omega, weight

    def hints(self):
        dot, near, omega, weight = self._numbers()
        flip = (rf"Here $q_0 \cdot q_1 = {_num(dot)} < 0$: use $-q_1 = {_vec(near)}$ instead, "
                r"the same orientation but nearer." if dot < 0 else
                rf"Here $q_0 \cdot q_1 = {_num(dot)} > 0$: $q_1$ is already on the near side.")
        return [
            r"Slerp: $q(t) = \frac{\sin((1-t)\Omega)\,q_0 + \sin(t\Omega)\,q_1}{\sin\Omega}$ "
            r"with $\cos\Omega = q_0 \cdot q_1$. First make sure you go the short way: if "
            r"$q_0 \cdot q_1 < 0$, replace $q_1$ by $-q_1$.",
            flip,
            rf"$\Omega = \arccos {_num(abs(dot))} = {_num(omega)}$ rad; at $t = \tfrac12$ both "
            rf"weights are $\sin(\Omega/2)/\sin\Omega = {_num(weight)}$, so the answer is "
            r"the sum of $q_0$ and the nearer of $\pm q_1$, scaled to length 1.",
        ]

    def worked(self):
        dot, near, omega, weight = self._numbers()
        total = self.q0 + near
        q = weight * total
        return Worked([
            rf"$q_0 \cdot q_1 = {_num(dot)}$"
            + (r" $< 0$: go the short way with $-q_1$." if dot < 0 else r" $> 0$: keep $q_1$.")
            + rf" So $q_1' = {_vec(near)}$.",
            rf"$\cos\Omega = {_num(abs(dot))}$, $\Omega = {_num(omega)}$ rad.",
            rf"At $t = \tfrac12$ both weights are $\frac{{\sin(\Omega/2)}}{{\sin\Omega}} = "
            rf"{_num(weight)}$: $q = {_num(weight)}\,(q_0 + q_1') = {_num(weight)} \cdot "
            rf"{_vec(total)}$.",
            rf"$q = {_vec(q)}$ (length 1, as slerp keeps it).",
        ], q)

    def statement(self):
        return (
            rf"Two orientations are given by the unit quaternions "
            rf"$q_0 = {_fraction_vector(self._ints0, self._n0)}$ and "
            rf"$q_1 = {_fraction_vector(self._ints1, self._n1)}$ (scalar first). Give the "
            rf"orientation halfway between them by spherical linear interpolation (slerp) at "
            rf"$t = \tfrac12$, the way an animation system would turn a body from $q_0$ to "
            rf"$q_1$." "\n\n" + _QUATERNION + r" Both $q$ and $-q$ are accepted." + "\n\n"
            + data_note("q0", "q1"))
