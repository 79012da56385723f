"""Exam-style exercises: per-chapter generators and checkers, and the notebook builder.

``from course_lib.exercises import ch03`` gives chapter 3's exercises; each is a class taking a
``seed``. ``mock_exam(seed)`` draws a mixed exam over every chapter (numeric exercises and the
concept questions of :mod:`course_lib.exercises.concepts`). The shared machinery (feedback, diagnoses) is in :mod:`course_lib.exercises.core`;
:mod:`course_lib.exercises.build` makes ``exercises/`` from ``solutions/``.
"""
from .core import Exercise, Feedback, Mistake, diagnose_matrix, diagnose_number, diagnose_vector
from .mock import mock_exam

__all__ = ["Exercise", "Feedback", "Mistake", "diagnose_matrix", "diagnose_number",
           "diagnose_vector", "mock_exam"]
