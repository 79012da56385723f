"""What the chapter 4 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch04`.
"""

from ... import format as fmt
from .._ch03 import PointAnswer, _par, _snap  # noqa: F401  (points read alike in ch03, ch04)
from ..core import DECIMALS


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

_vec = fmt.vector_latex
_num = fmt.number
_mat = fmt.matrix_latex


def _signs(rng, n):
    return rng.choice([-1.0, 1.0], size=n)


def _deg(angle_deg):
    return rf"{angle_deg}^\circ"


_MATRIX_4 = "**Answer:** the $4 \\times 4$ matrix as a numpy array. " + DECIMALS
_POINT_3 = ("**Answer:** the point as a list of 3 numbers `[x, y, z]` (ordinary coordinates; a "
            "homogeneous `[x, y, z, 1]` is accepted too). " + DECIMALS)

