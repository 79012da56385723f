"""What the chapter 10 exercises share: the base class and the wording helpers.

The exercises are in one module per topic of this package (normalisation, transfer functions,
colour maps, kinds of colour map); import them from :mod:`course_lib.exercises.ch10`.
"""
from ... import format as fmt
from ..core import UNANSWERED, DrawnExercise, Feedback, has_placeholder

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

    def _menu_choice(self, answer, aliases=None):
        """The entry of ``self.menu`` a student's string names, as ``(key, None)``; or
        ``(None, feedback)`` for an unanswered or unreadable answer. Case and spaces around
        and between words do not matter; `aliases` maps other spellings to menu entries."""
        if has_placeholder(answer):
            return None, Feedback("unanswered", UNANSWERED)
        key = " ".join(answer.strip().lower().split()) if isinstance(answer, str) else None
        key = (aliases or {}).get(key, key)
        if key not in self.menu:
            return None, Feedback("invalid", "Answer with one of the strings "
                                  + ", ".join(f"`'{k}'`" for k in self.menu) + ".", "unreadable")
        return key, None
