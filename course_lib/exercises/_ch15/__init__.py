"""What the chapter 15 exercises share: the answer forms, nice unit vectors and the base class
of the answers in several parts.

The exercises are in one module per topic of this package (intersections, reflection and
refraction, shadows and ray trees, acceleration); import them from
:mod:`course_lib.exercises.ch15`.
"""
import numpy as np

from ... import format as fmt
from ..core import DECIMALS, DrawnExercise, PartsAnswer, latex_vector, parts_separated, pick

_vec = fmt.vector_latex
_num = fmt.number
_frac = latex_vector            # components as short decimals or simple fractions (2/3, 6/7)

#: Unit vectors with rational components (before permuting the axes and choosing signs).
_NICE_UNITS = ((1.0, 0.0, 0.0), (0.6, 0.8, 0.0), (2 / 3, 2 / 3, 1 / 3), (2 / 7, 3 / 7, 6 / 7))

_POINT_3 = "**Answer:** the point as a list of 3 numbers `[x, y, z]`. " + DECIMALS
_VECTOR_3 = "**Answer:** the vector as a list of 3 numbers `[x, y, z]`. " + DECIMALS
_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


def _nice_unit(rng):
    v = np.array(pick(rng, _NICE_UNITS))[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0


def _is_count(x):
    return isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_))


def _parts_apart(parts):
    """Whether the slips of a multi-part answer can be told apart, number by number.

    Real parts as :func:`~course_lib.exercises.core.parts_separated` has it; a whole-number part
    (its expected value an ``int``: a count, compared exactly) only needs slips that differ
    from each other, since any other whole number is a different answer.

    Examples
    --------
    >>> from course_lib.exercises.core import Mistake
    >>> _parts_apart([("n", 127, [Mistake(126, "", "a"), Mistake(128, "", "b")])])
    True
    >>> _parts_apart([("n", 127, [Mistake(126, "", "a"), Mistake(126, "", "b")])])
    False
    """
    if not parts_separated([part for part in parts if not _is_count(part[1])]):
        return False
    for _, expected, mistakes in parts:
        if not _is_count(expected):
            continue
        live = [m for m in mistakes if float(m.value) != expected]
        for i, a in enumerate(live):
            if any(b.key != a.key and float(b.value) == float(a.value) for b in live[i + 1:]):
                return False
    return True


class _Parts(PartsAnswer, DrawnExercise):
    """An answer made of several numbers, each with slips of their own (see PartsAnswer); the
    parts that are counts (``int``) are whole numbers, compared exactly."""

    def separated(self, mistakes):
        self._parts = self.parts()
        return _parts_apart(self._parts)
