"""What the chapter 12 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch12`.
"""

import math

import numpy as np

from ... import format as fmt
from ..core import DECIMALS, DrawnExercise, PartsAnswer, latex_fraction, latex_vector, pick


_num = fmt.number
_frac = latex_fraction
_vec = latex_vector

#: Unit vectors with rational components, the last one "up" (along the normal).
_UNIT_PATTERNS = ((0.0, 0.0, 1.0), (0.6, 0.0, 0.8), (0.8, 0.0, 0.6), (0.0, 0.6, 0.8),
                  (0.0, 0.8, 0.6), (2 / 3, 1 / 3, 2 / 3), (1 / 3, 2 / 3, 2 / 3),
                  (2 / 3, 2 / 3, 1 / 3), (2 / 7, 3 / 7, 6 / 7), (3 / 7, 2 / 7, 6 / 7),
                  (6 / 7, 2 / 7, 3 / 7), (2 / 7, 6 / 7, 3 / 7), (3 / 7, 6 / 7, 2 / 7),
                  (6 / 7, 3 / 7, 2 / 7))

#: Whole-number vectors of whole-number length: (x, y, z), |(x, y, z)|.
_INTEGER_VECTORS = (((0, 0, 2), 2), ((0, 0, 3), 3), ((0, 3, 4), 5), ((3, 0, 4), 5),
                    ((0, 4, 3), 5), ((4, 0, 3), 5), ((1, 2, 2), 3), ((2, 1, 2), 3),
                    ((2, 2, 1), 3), ((2, 3, 6), 7), ((3, 2, 6), 7), ((6, 2, 3), 7),
                    ((2, 6, 3), 7), ((2, 4, 4), 6), ((4, 4, 2), 6), ((4, 4, 7), 9),
                    ((1, 4, 8), 9), ((8, 4, 1), 9))


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


_AXES = ([1, 2, 0], [2, 0, 1], [0, 1, 2])


def _frame(v, axis):
    """Local coordinates (x, y, z) -> world, local z going to world axis `axis` (cyclically)."""
    return np.asarray(v, dtype=float)[..., _AXES[axis]]


def _all_units():
    """Every unit vector of _UNIT_PATTERNS with x and y swapped or not, of any signs (z > 0)."""
    found = set()
    for x, y, z in _UNIT_PATTERNS:
        for a, b in ((x, y), (y, x)):
            for sa in (-1.0, 1.0):
                for sb in (-1.0, 1.0):
                    found.add((a * sa + 0.0, b * sb + 0.0, z))
    return np.array(sorted(found))


#: The nice unit vectors above the surface (local frame, normal +z), and below it.
_UP = _all_units()
_DOWN = _UP * np.array([1.0, 1.0, -1.0])


def _reflection_table(first, second):
    """R . V for L in the rows of `first`, V in the rows of `second`, N = +z."""
    return 2 * first[:, 2, None] * second[None, :, 2] - first @ second.T


_UP_DOT = _UP @ _UP.T
_UP_RV = _reflection_table(_UP, _UP)
_DOWN_RV = _reflection_table(_DOWN, _UP)
_UP_NH = (_UP[:, 2, None] + _UP[None, :, 2]) / np.sqrt(2 + 2 * _UP_DOT)


def _nice_unit(rng, up=1.0):
    """One of the nice unit vectors, its z of the sign of `up` (local frame)."""
    return _UP[int(rng.integers(len(_UP)))] * np.array([1.0, 1.0, up])


def _pair(rng, first, second, ok):
    """A row of `first` and a row of `second` for which the matrix `ok` holds, at random."""
    i, j = np.nonzero(ok)
    k = int(rng.integers(len(i)))
    return first[i[k]], second[j[k]]


def _integer_vector(rng):
    """A whole-number vector of whole-number length, its axes permuted, random signs."""
    v, length = pick(rng, _INTEGER_VECTORS)
    v = np.array(v, dtype=float)[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0, float(length)


def _material_words(**coefficients):
    return ", ".join(rf"${name} = {_num(value)}$" for name, value in coefficients.items())


class _Parts(PartsAnswer, DrawnExercise):
    """An answer made of several numbers, each with slips of its own (see PartsAnswer)."""


_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


# ---------------------------------------------------------------------------------------------
# Boundary cases
# ---------------------------------------------------------------------------------------------

#: The share of the seeds that draw an exercise's boundary case (a cosine clamped at 0, a light
#: behind the surface): a case to know, not the common one.
BOUNDARY_SHARE = 0.15


class _Boundary:
    """Mixin, put before the exercise base: a labelled boundary variant in a share of the seeds.

    ``boundary_cases`` names the cases. ``self.boundary`` is drawn once per seed, before the
    numbers: one of the cases in about ``boundary_share`` of the seeds, else None; ``draw``
    then draws the numbers of that case (the drawing loop may draw them several times, but
    never changes the case, so the share is exactly the one asked for).
    """

    boundary = None
    boundary_cases = ()
    boundary_share = BOUNDARY_SHARE

    def setup(self, rng):
        self.boundary = (pick(rng, self.boundary_cases) if rng.random() < self.boundary_share
                         else None)
        super().setup(rng)


# ---------------------------------------------------------------------------------------------
# Worked solutions
# ---------------------------------------------------------------------------------------------

def _n4(x):
    """A number of a worked step: 4 decimals, without trailing zeros."""
    return fmt.number(x, 4)


def _factor(x):
    """A number inside a product: a simple fraction or a short decimal, negatives bracketed."""
    text = _frac(x)
    return f"({text})" if text.startswith("-") else text


def _dot(a, b):
    r"""The dot product written out for a worked step: ``(a1)(b1) + ... = value`` in LaTeX.

    Products with a zero factor are left out.

    Examples
    --------
    >>> print(_dot([0.6, 0, 0.8], [0, 1, 1]))
    0.8 \cdot 1 = 0.8
    >>> print(_dot([0.6, 0, 0.8], [-1, 0, 0.5]))
    0.6 \cdot (-1) + 0.8 \cdot 0.5 = -0.2
    """
    terms = [rf"{_factor(x)} \cdot {_factor(y)}" for x, y in zip(np.ravel(a), np.ravel(b))
             if abs(x) > 1e-12 and abs(y) > 1e-12]
    value = float(np.dot(np.ravel(a), np.ravel(b)))
    if not terms:
        return "0"
    return " + ".join(terms) + f" = {_frac(value)}"


def _length(v):
    r"""``\sqrt{s} = value`` for the length of `v`, with ``s`` the sum of the squares."""
    s = float(np.dot(v, v))
    return rf"\sqrt{{{_frac(s)}}} = {_frac(math.sqrt(s))}"
