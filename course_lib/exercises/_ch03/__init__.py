"""What the chapter 3 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch03`.
"""

import numpy as np

from ... import format as fmt
from ... import transforms as tf
from ..core import DECIMALS, pick


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
