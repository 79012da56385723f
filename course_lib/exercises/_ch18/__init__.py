"""What the chapter 18 exercises share: the base class and the number helpers.

The exercises are in one module per topic of this package (marching squares, marching cubes,
volume rendering, streamlines); import them from :mod:`course_lib.exercises.ch18`.
"""
from ... import format as fmt
from ..core import DrawnExercise

_num = fmt.number
_vec = fmt.vector_latex


class _Chapter18(DrawnExercise):
    """The chapter's base: answers are points or pairs of numbers, not directions, and never
    True/False (see ``DrawnExercise.vector_like`` and ``reject_bool``)."""

    vector_like = False
    reject_bool = True
