"""Chapter 3 exercises: quaternions from axes and angles, their products, slerp.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import quaternions as quat
from ..core import DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import (_POINT_3, _QUATERNION, _SCALAR_LAST_TEXT, PointAnswer, _bar, _cos_sin, _deg,
               _fraction_vector, _hamilton, _nice_axis, _nice_quaternion, _num, _par,
               _scalar_last, _snap, _vec)

__all__ = [
    "ComposeRotationsWithQuaternions",
    "QuaternionFromAxisAngle",
    "QuaternionProduct",
    "RotatePointWithQuaternion",
    "SlerpMidpoint",
]


_QUATERNION_ANGLES = (30, 45, 60, 90, 120, 135, 150, 180, 240, 270, 300)


def _half_angle_degrees_text(angle_deg, what):
    """What a student is told who fed the half angle's degrees to cos and sin as radians."""
    half = angle_deg / 2
    c, _ = _cos_sin(half)
    return (rf"You fed the half angle in degrees, ${_num(half)}$, to $\cos$ and $\sin$, which "
            rf"expect radians ($\cos({_num(half)}\,\mathrm{{rad}}) = {_num(math.cos(half))}$, "
            rf"whereas $\cos {_num(half)}^\circ = {_num(c)}$): {what} by {_num(angle_deg)} "
            r"radians instead of degrees. Convert first with `np.radians` (or use the attribute "
            r"in radians).")


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
