"""One concept question: :class:`ConceptQuestion`, and how the question bank writes one.

Part of :mod:`course_lib.exercises.concepts`.
"""
from dataclasses import dataclass

import numpy as np

from ..core import UNANSWERED, Feedback, is_unanswered

__all__ = ["KINDS", "TRUE_FALSE", "ConceptQuestion"]

#: The kinds of concept question.
KINDS = ("multiple choice", "true/false")
#: The options of every true/false question, in this order.
TRUE_FALSE = ("True", "False")
_LETTERS = "abcdefghijklmnopqrstuvwxyz"
_TRUE_WORDS = {"true": 0, "t": 0, "false": 1, "f": 1}


@dataclass(frozen=True)
class ConceptQuestion:
    r"""One multiple-choice or true/false question, with an explanation for every option.

    Parameters
    ----------
    chapter : int
        The chapter the question belongs to.
    key : str
        A unique, stable identifier, such as ``"ch07-bezier-convex-hull"``.
    kind : {"multiple choice", "true/false"}
    prompt : str
        The question (Markdown, may contain LaTeX).
    options : tuple of str
        The options, distinct; ``("True", "False")`` for a true/false question.
    correct : int
        The index of the right option (counted from 0).
    explanations : tuple of str
        One per option: why that option is right or wrong.

    Raises
    ------
    ValueError, TypeError
        When the fields are inconsistent (an explanation missing, options repeated, ``correct``
        out of range, a true/false question whose options are not ``("True", "False")``).

    Examples
    --------
    >>> q = ConceptQuestion(
    ...     chapter=3, key="demo-identity", kind="true/false",
    ...     prompt="The identity matrix is a rotation.", options=("True", "False"),
    ...     correct=0, explanations=("It rotates by angle 0.", "Angle 0 is a rotation too."))
    >>> q.check(True).status, q.check("t").status, q.check("b").status
    ('correct', 'correct', 'wrong')
    >>> q.check(...).status, q.check("maybe").status
    ('unanswered', 'invalid')
    >>> print(q.check(False))
    Not yet: *(b) False* is not right: Angle 0 is a rotation too. The right answer is *(a) True*: It rotates by angle 0.
    """

    chapter: int
    key: str
    kind: str
    prompt: str
    options: tuple
    correct: int
    explanations: tuple

    def __post_init__(self):
        if isinstance(self.chapter, bool) or not isinstance(self.chapter, (int, np.integer)):
            raise TypeError(f"chapter must be an integer, got {self.chapter!r}")
        if not isinstance(self.key, str) or not self.key:
            raise TypeError(f"key must be a non-empty string, got {self.key!r}")
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {self.kind!r}")
        object.__setattr__(self, "options", tuple(self.options))
        object.__setattr__(self, "explanations", tuple(self.explanations))
        if not all(isinstance(o, str) and o.strip() for o in self.options):
            raise TypeError(f"{self.key}: options must be non-empty strings")
        if self.kind == "true/false" and self.options != TRUE_FALSE:
            raise ValueError(f"{self.key}: a true/false question has the options {TRUE_FALSE}")
        if not 2 <= len(self.options) <= len(_LETTERS):
            raise ValueError(f"{self.key}: options must hold 2 to 26 options")
        if len({_norm(o) for o in self.options}) != len(self.options):
            raise ValueError(f"{self.key}: options must be distinct")
        if len(self.explanations) != len(self.options) or not all(
                isinstance(e, str) and e.strip() for e in self.explanations):
            raise ValueError(f"{self.key}: explanations must hold one non-empty string per "
                             "option")
        if isinstance(self.correct, bool) or not isinstance(self.correct, (int, np.integer)) \
                or not 0 <= self.correct < len(self.options):
            raise ValueError(f"{self.key}: correct must be an option index in "
                             f"0..{len(self.options) - 1}, got {self.correct!r}")

    # -- reading an answer -------------------------------------------------------------------

    @property
    def letters(self):
        """The letters of the options: ``("a", "b", ...)``."""
        return tuple(_LETTERS[:len(self.options)])

    def _label(self, i):
        return f"*({_LETTERS[i]}) {self.options[i]}*"

    def accepted_forms(self):
        """A sentence saying which answers this question understands (Markdown)."""
        n = len(self.options)
        forms = (f"the letter of an option (`\"a\"` to `\"{_LETTERS[n - 1]}\"`), its index "
                 f"counted from 0 (`0` to `{n - 1}`), or its text")
        if self.kind == "true/false":
            forms = ("`True` or `False` (also `\"true\"`, `\"t\"`, `\"false\"`, `\"f\"`), "
                     + forms)
        return f"Answer with {forms}."

    def read(self, answer):
        """The option index `answer` stands for, or None when it cannot be read.

        Examples
        --------
        >>> from course_lib.exercises.concepts import QUESTIONS
        >>> q = QUESTIONS[7][0]
        >>> q.read(q.letters[1].upper()) == q.read(1) == q.read(q.options[1]) == 1
        True
        >>> q.read("zz") is None, q.read(2.5) is None
        (True, True)
        """
        n = len(self.options)
        if isinstance(answer, (bool, np.bool_)):
            if self.kind != "true/false":
                return None
            return 0 if answer else 1
        if isinstance(answer, (int, np.integer, float, np.floating)):
            if float(answer).is_integer() and 0 <= answer < n:
                return int(answer)
            # a number that is not an index may be an option's text ("15" cases)
            text = f"{float(answer):g}"
            return next((i for i, o in enumerate(self.options) if _norm(o) == text), None)
        if not isinstance(answer, str):
            return None
        text = _norm(answer)
        if self.kind == "true/false" and text in _TRUE_WORDS:
            return _TRUE_WORDS[text]
        for i, option in enumerate(self.options):
            if text == _norm(option):
                return i
        letter = text.strip("()").rstrip(").")
        if len(letter) == 1 and letter in _LETTERS[:n]:
            return _LETTERS.index(letter)
        return None

    def check(self, answer):
        """Judge `answer`; never raises.

        Parameters
        ----------
        answer : int, str or bool
            An option's index (from 0), letter or text; ``True``/``False`` for a true/false
            question.

        Returns
        -------
        Feedback
            Correct: the right option's explanation. Wrong: the chosen option's explanation
            (why it is wrong) and the right one's; the diagnosis is ``"option <letter>"``.

        Examples
        --------
        >>> from course_lib.exercises.concepts import QUESTIONS
        >>> q = QUESTIONS[3][0]
        >>> q.check(q.correct).status, q.check(None).status, q.check([1]).status
        ('correct', 'unanswered', 'invalid')
        """
        if is_unanswered(answer):
            return Feedback("unanswered", UNANSWERED)
        try:
            i = self.read(answer)
        except Exception:                   # a checker must never stop the notebook
            i = None
        if i is None:
            return Feedback("invalid", f"Cannot tell which option {answer!r} means. "
                            + self.accepted_forms(), "unreadable")
        right = self.correct
        if i == right:
            return Feedback("correct", f"{self._label(right)}: {self.explanations[right]}")
        return Feedback("wrong", f"{self._label(i)} is not right: {self.explanations[i]} "
                        f"The right answer is {self._label(right)}: "
                        f"{self.explanations[right]}", f"option {_LETTERS[i]}")

    # -- display -----------------------------------------------------------------------------

    def markdown(self):
        """The question with its lettered options, as Markdown.

        Examples
        --------
        >>> from course_lib.exercises.concepts import QUESTIONS
        >>> print(QUESTIONS[7][0].markdown().splitlines()[0])  # doctest: +ELLIPSIS
        **Chapter 7, ...
        """
        head = "true or false?" if self.kind == "true/false" else "multiple choice"
        lines = [f"**Chapter {self.chapter}, {head}** `{self.key}`", "", self.prompt, ""]
        lines += [f"- **({letter})** {option}" for letter, option in
                  zip(self.letters, self.options)]
        return "\n".join(lines)

    def _repr_markdown_(self):
        return self.markdown()

    def show(self):
        """Display the question in a notebook (print it elsewhere); returns None."""
        try:
            from IPython.display import Markdown, display
        except ImportError:                 # pragma: no cover - IPython is a dependency
            print(self.markdown())
        else:
            display(Markdown(self.markdown()))

    def __repr__(self):
        return f"ConceptQuestion({self.key!r})"


def _norm(text):
    """`text` lower-cased with runs of white space made single, for comparing answers."""
    return " ".join(str(text).split()).lower()


# ---------------------------------------------------------------------------------------------
# Writing the questions
# ---------------------------------------------------------------------------------------------

def _mc(chapter, key, prompt, *options_and_why, correct):
    """A multiple-choice question from (option, explanation) pairs."""
    options = tuple(o for o, _ in options_and_why)
    why = tuple(w for _, w in options_and_why)
    return ConceptQuestion(chapter, key, "multiple choice", prompt, options, correct, why)


def _tf(chapter, key, statement, truth, if_true, if_false):
    """A true/false question: `if_true` explains the option True, `if_false` the option False."""
    return ConceptQuestion(chapter, key, "true/false", statement, TRUE_FALSE,
                           0 if truth else 1, (if_true, if_false))
