"""Exam-style exercises: per-chapter generators and checkers, and the notebook builder.

``from course_lib.exercises import ch03`` gives chapter 3's exercises; each is a class taking a
``seed``. The shared machinery (feedback, diagnoses) is in :mod:`course_lib.exercises.core`;
:mod:`course_lib.exercises.build` makes ``exercises/`` from ``solutions/``.
"""
from .core import Exercise, Feedback, Mistake, diagnose_matrix, diagnose_number, diagnose_vector

__all__ = ["Exercise", "Feedback", "Mistake", "diagnose_matrix", "diagnose_number",
           "diagnose_vector"]
