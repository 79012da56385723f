r"""The exercise machinery shared by every chapter: exercises, feedback and diagnoses.

An exercise is a class whose constructor takes a ``seed``: the seed draws the numbers of the
question, so a student gets a fresh variant by changing it. Displaying the exercise shows the
question; ``check(answer)`` compares the answer with the expected one, computed by
``course_lib``, and returns a :class:`Feedback` that says *what* is wrong: transposed, wrong sign,
wrong order of multiplication, not normalized, degrees instead of radians... An empty answer
(``...`` or ``None``) gives "not answered yet" and never raises, so an exercise notebook runs
from top to bottom.

The diagnoses try, in order: the shape; exact agreement; the mistakes the exercise names
(each computed from the question, e.g. the product in the wrong order); generic mistakes
(transposed, inverse, scaled, opposite sign, a few entries of the wrong sign); and otherwise
which entries are off.

Most exam questions are :class:`DrawnExercise` subclasses: they draw the question's numbers
again until every anticipated mistake gives an answer of its own (distinct from the right one
and from the other mistakes, see :func:`well_separated`), so that a diagnosis is never
ambiguous, and they check an answer by its form (a matrix, a vector, a quaternion, a number, a
point, or a form of their own). :func:`pick`, :func:`small_ints` and :func:`data_note` help to
draw numbers that are pleasant by hand and to write the statement.

**The tolerance policy** is written once, in :func:`tolerance` and :func:`agrees`, and every
diagnosis uses it: a real answer is right to 3 significant digits (or 3 decimals below 1);
whole numbers (counts, indices, outcodes; ``5.0`` is the whole number 5, ``True`` is not 1)
are compared exactly, with an "off by one" diagnosis; an answer that is the right one rounded
to too few digits (:func:`rounding_of`) is told "close: give more digits" before any other
diagnosis; a column vector ``(n, 1)`` reads as the vector it is.

**Help on request** (:mod:`._core.guidance`): every exercise has ``hint()`` (the next of at
least three hints) and ``solution()`` (the steps of the student's own variant, a
:class:`Worked`), and every check, hint and solution seen is recorded in the progress file
when recording is on (in a notebook). A subclass writes ``hints()`` and ``worked()``.

The machinery lives in :mod:`course_lib.exercises._core`, one module per topic:
``feedback`` (:class:`Feedback`, :class:`Mistake`, the tolerance policy and the diagnoses),
``drawn`` (:class:`Exercise`, :class:`DrawnExercise`, :class:`PartsAnswer` and how the variants
are drawn), ``guidance`` (hints, worked solutions, recording) and ``writing`` (pleasant numbers
and the statement's wording); import it from here.
"""
from ._core.feedback import (ATOL, SIGNIFICANT, UNANSWERED, UNEXPLAINED, Feedback, Mistake,
                             agrees, as_vector, close, diagnose_matrix, diagnose_number,
                             diagnose_parts, diagnose_vector, has_placeholder, hinted,
                             is_unanswered, read_floats, read_names, rounding_of, tolerance)
from ._core.drawn import (APART, MAX_DRAWS, SAME, TOLERANCES_APART, DrawnExercise, Exercise,
                          PartsAnswer, gap, parts_separated, well_separated)
from ._core.guidance import Guidance, Worked, exercise_key, quietly
from ._core.writing import DECIMALS, data_note, latex_fraction, latex_vector, pick, small_ints

__all__ = [
    "DrawnExercise",
    "Exercise",
    "Feedback",
    "Guidance",
    "Mistake",
    "PartsAnswer",
    "Worked",
    "agrees",
    "as_vector",
    "close",
    "data_note",
    "diagnose_matrix",
    "diagnose_number",
    "diagnose_parts",
    "diagnose_vector",
    "exercise_key",
    "gap",
    "has_placeholder",
    "hinted",
    "is_unanswered",
    "latex_fraction",
    "latex_vector",
    "parts_separated",
    "pick",
    "quietly",
    "read_floats",
    "read_names",
    "rounding_of",
    "small_ints",
    "tolerance",
    "well_separated",
]
