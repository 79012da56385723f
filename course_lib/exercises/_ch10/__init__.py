"""What the chapter 10 exercises share: the base class and the wording helpers.

The exercises are in one module per topic of this package (normalisation, transfer functions,
colour maps, kinds of colour map); import them from :mod:`course_lib.exercises.ch10`.
"""
from ... import format as fmt
from ..core import DrawnExercise

_num = fmt.number
_vec = fmt.vector_latex


def _paren(x):
    """A number for a formula: in parentheses when it is negative (``v - (-10)``)."""
    return f"({_num(x)})" if x < 0 else _num(x)


def _values_words(values):
    return ", ".join(f"${_num(v)}$" for v in values)


class _Chapter10(DrawnExercise):
    """The chapter's base: answers are lists of values, not directions, and never True/False
    (see ``DrawnExercise.vector_like`` and ``reject_bool``)."""

    vector_like = False
    reject_bool = True
