"""Chapter 3 exercises: quaternions and rotation matrices, both ways, and the axis and angle.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import format as fmt
from ... import quaternions as quat
from ..core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, agrees,
                    as_vector, data_note, is_unanswered, read_floats, rounding_of)
from . import (_BOOL_TEXT, _QUATERNION, _SCALAR_LAST_TEXT, _fraction_matrix, _fraction_vector,
               _holds_bool, _mat, _nice_quaternion, _num, _scalar_last, _snap, _vec)

__all__ = [
    "AxisAngleOfMatrix",
    "MatrixToQuaternion",
    "QuaternionToMatrix",
]


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


class AxisAngle(tuple):
    """An axis and an angle in radians: the tuple ``(axis, angle)``, built from such a pair.

    Numpy holds it as an array of two objects (a plain tuple of a vector and a number is ragged,
    which numpy refuses to hold at all); as numbers it cannot be read.

    Examples
    --------
    >>> axis, angle = AxisAngle((np.array([0.0, 0.0, 1.0]), 0.5))
    >>> float(angle), np.asarray(AxisAngle((axis, angle))).shape
    (0.5, (2,))
    >>> AxisAngle(([1, 0, 0], 2.0))
    ([1, 0, 0], 2.0)
    """

    def __new__(cls, pair):
        axis, angle = pair
        return super().__new__(cls, (axis, angle))

    def __array__(self, dtype=None, copy=None):
        pair = np.empty(2, dtype=object)
        pair[0], pair[1] = self
        return pair if dtype is None else pair.astype(dtype)


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
        self.expected = AxisAngle((_snap(axis), float(angle)))

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
        ], AxisAngle((axis, theta)), shown=rf"$\hat n = {_vec(axis, 4)}$, "
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
