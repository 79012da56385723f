"""The question bank: every chapter's concept questions, per chapter and as one list.

Part of :mod:`course_lib.exercises.concepts`; each chapter's questions are in its module
``concepts/chNN.py``.
"""
import numpy as np

from . import ch03, ch04, ch05, ch06, ch07, ch10, ch12, ch14, ch15, ch18

__all__ = ["QUESTIONS", "questions"]

_ALL = [q for module in (ch03, ch04, ch05, ch06, ch07, ch10, ch12, ch14, ch15, ch18)
        for q in module.QUESTIONS]

#: {chapter: tuple of ConceptQuestion}, in the order of the chapters' modules.
QUESTIONS = {}
for _q in _ALL:
    QUESTIONS.setdefault(_q.chapter, [])
    QUESTIONS[_q.chapter].append(_q)
QUESTIONS = {ch: tuple(QUESTIONS.get(ch, ())) for ch in (3, 4, 5, 6, 7, 10, 12, 14, 15, 18)}
del _q


def questions(chapter=None):
    """The concept questions of one chapter, or of every chapter, as a list.

    Parameters
    ----------
    chapter : int, optional
        One of the keys of :data:`QUESTIONS`; all chapters in order when omitted.

    Returns
    -------
    list of ConceptQuestion

    Raises
    ------
    ValueError
        For a chapter without concept questions.

    Examples
    --------
    >>> len(questions(7)) >= 8, len(questions()) == sum(map(len, QUESTIONS.values()))
    (True, True)
    """
    if chapter is None:
        return [q for ch in sorted(QUESTIONS) for q in QUESTIONS[ch]]
    if isinstance(chapter, bool) or not isinstance(chapter, (int, np.integer)) \
            or int(chapter) not in QUESTIONS:
        raise ValueError(f"chapter must be one of {sorted(QUESTIONS)}, got {chapter!r}")
    return list(QUESTIONS[int(chapter)])
