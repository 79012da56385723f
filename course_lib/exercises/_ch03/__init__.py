"""What the chapter 3 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch03`.
"""

import math

import numpy as np

from ... import format as fmt
from ... import transforms as tf
from ..core import DECIMALS, Feedback, pick


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
_POINT_3 = ("**Answer:** the image point as a list of 3 numbers `[x, y, z]` (a homogeneous "
            "`[x, y, z, 1]` is accepted too). " + DECIMALS)
_QUATERNION = ("**Answer:** a list of 4 numbers, **scalar first**: `[s, x, y, z]`. " + DECIMALS)


# ---------------------------------------------------------------------------------------------
# Answers: points read the same in every form
# ---------------------------------------------------------------------------------------------

def _holds_bool(answer, depth=0):
    """Whether `answer` is, or holds, a bool (True must not be read as the number 1)."""
    if isinstance(answer, (bool, np.bool_)):
        return True
    if isinstance(answer, np.ndarray):
        return answer.dtype == bool or (answer.dtype == object and any(
            _holds_bool(item, depth + 1) for item in answer.ravel()))
    if isinstance(answer, (list, tuple)) and depth < 4:
        return any(_holds_bool(item, depth + 1) for item in answer)
    return False


def _flat(answer, sizes):
    """A column ``(k, 1)`` or row ``(1, k)`` answer as the flat vector of its `k` entries.

    Only for `k` in `sizes`; anything else is returned as it is. The entries are not converted
    (a True inside stays a True, to be refused).

    Examples
    --------
    >>> _flat([[1], [2], [3]], (3, 4)), _flat([[1, 2, 3, 1]], (3, 4)), _flat([1, 2], (3,))
    ([1, 2, 3], [1, 2, 3, 1], [1, 2])
    >>> _flat(np.ones((3, 1)), (3,)).shape
    (3,)
    """
    if isinstance(answer, np.ndarray):
        if answer.ndim == 2 and 1 in answer.shape and answer.size in sizes:
            return answer.reshape(answer.size)
        return answer
    if not isinstance(answer, (list, tuple)):
        return answer
    if len(answer) in sizes and all(
            isinstance(item, (list, tuple, np.ndarray)) and np.shape(item) == (1,)
            for item in answer):
        return [item[0] for item in answer]
    if len(answer) == 1 and isinstance(answer[0], (list, tuple, np.ndarray)) \
            and np.ndim(answer[0]) == 1 and len(answer[0]) in sizes:
        return list(answer[0])
    return answer


#: What a True or False given as a number is told.
_BOOL_TEXT = ("Your answer holds True or False; give numbers (True is not the number 1 here).")


class PointAnswer:
    """Mixin (before :class:`DrawnExercise`): the answer is a point.

    It is read the same in every form: a list or an array of its coordinates, a row or a
    column, or homogeneous with :math:`w = 1`; True and False are refused as numbers. A point
    has no direction to be "right but too long": a wrong one is told which coordinates are off.
    """

    answer_form = "point"
    vector_like = False

    def _judge(self, answer):
        if _holds_bool(answer):
            return Feedback("invalid", _BOOL_TEXT, "not a number")
        n = len(self.expected)
        return super()._judge(_flat(answer, (n, n + 1)))


def _snap(values):
    """`values` as floats with the rounding noise of exact zeros (1e-17) set to 0.

    A right answer rounded by hand must read as rounded, entry by entry, and 0 is no rounding
    of 3e-17.
    """
    values = np.array(values, dtype=float)
    values[np.abs(values) < 1e-12] = 0.0
    return values


# ---------------------------------------------------------------------------------------------
# The arithmetic of the worked solutions (written out, independent of course_lib)
# ---------------------------------------------------------------------------------------------

_num = fmt.number
_mat = fmt.matrix_latex


def _par(x):
    """A number for a product or a difference: in parentheses when it is negative."""
    text = _num(x)
    return f"({text})" if text.startswith("-") else text


def _cos_sin(angle_deg):
    """cos and sin of an angle in degrees, with exact zeros (cos 90 degrees is 0, not 6e-17)."""
    theta = math.radians(angle_deg)
    c, s = math.cos(theta), math.sin(theta)
    return (0.0 if abs(c) < 1e-12 else c), (0.0 if abs(s) < 1e-12 else s)


def _rot2(c, s):
    """The homogeneous 2D rotation with the given cosine and sine."""
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _affine2(block, column):
    """The homogeneous 2D matrix with the 2x2 `block` and the translation `column`."""
    m = np.eye(3)
    m[:2, :2] = block
    m[:2, 2] = column
    return m


def _hamilton(p, q):
    """The Hamilton product p q of scalar-first quaternions, by the (s, v) formula."""
    s1, v1 = float(p[0]), np.asarray(p[1:], dtype=float)
    s2, v2 = float(q[0]), np.asarray(q[1:], dtype=float)
    return np.concatenate([[s1 * s2 - v1 @ v2], s1 * v2 + s2 * v1 + np.cross(v1, v2)])


def _bar(q):
    """The conjugate of a quaternion: the vector part negated."""
    return np.asarray(q, dtype=float) * np.array([1.0, -1.0, -1.0, -1.0])


def _rodrigues(unit_axis, c, s, v):
    """`v` rotated about the unit axis by the angle with cosine `c` and sine `s`."""
    k = np.asarray(unit_axis, dtype=float)
    v = np.asarray(v, dtype=float)
    return c * v + s * np.cross(k, v) + (1 - c) * (k @ v) * k


def _degrees_text(angle_deg, name=r"\theta"):
    """What a student is told who took the cosine and sine of the angle's degrees as radians."""
    c, s = _cos_sin(angle_deg)
    return (rf"Your rotation uses $\cos$ and $\sin$ of the number {angle_deg} taken as "
            rf"**radians** (e.g. $\cos({angle_deg}\,\mathrm{{rad}}) = "
            rf"{_num(math.cos(angle_deg))}$), whereas ${name} = {angle_deg}^\circ$ has "
            rf"$\cos {name} = {_num(c)}$ and $\sin {name} = {_num(s)}$. `np.cos` and `np.sin` "
            r"expect radians: convert first with `np.radians` (or use the attribute given in "
            r"radians), or set your calculator to degrees.")


def _rotation_words(angle_deg, name=r"\theta"):
    c, s = _cos_sin(angle_deg)
    return rf"$\cos {name} = {_num(c)}$, $\sin {name} = {_num(s)}$"


def _scalar_last(q):
    return np.roll(np.asarray(q, dtype=float), -1)


_SCALAR_LAST_TEXT = (r"You wrote the scalar part last, $(x, y, z, s)$ (scipy's order). The "
                     r"textbook and this course write it first: $q = (s, x, y, z)$.")
