r"""Help on request: step-by-step hints, the worked solution of the student's own variant, and
the record of every attempt.

Every exercise offers

- ``ex.hint()``: the next of its hints (at least three, from a nudge to nearly the answer, with
  this variant's numbers where they help), one per call;
- ``ex.solution()``: the steps of *this* variant, with its numbers, ending in the value the
  checker expects; offered once the student has tried (``ex.solution(reveal=True)`` shows it
  anyway).

A subclass provides them by implementing ``hints()`` (a list of Markdown strings) and
``worked()`` (a :class:`Worked`: the steps and the final answer, computed by the steps'
own arithmetic from the question's numbers, never copied from ``self.expected``, so that the
tests comparing it with the checker's answer can fail).

Each check, hint and solution shown is recorded in the progress file
(:func:`course_lib.progress.record_event`) when recording is on: inside a notebook by default,
never in a mock exam's questions (:func:`quietly`; the exam keeps its own record). Recording
never raises: a progress file that cannot be written gives one warning.

Part of :mod:`course_lib.exercises.core`, which imports everything from here.
"""
import contextlib
import contextvars
import functools
import re
import warnings

import numpy as np

from ... import format as fmt

__all__ = ["Guidance", "Worked", "exercise_key", "quietly", "recorded_check"]

#: While set, checks, hints and solutions are not recorded (a mock exam's questions).
_QUIET = contextvars.ContextVar("course_exercises_quiet", default=False)
#: The exercise modules' names: ``course_lib.exercises.ch05`` or ``..._ch05.cohen_sutherland``.
_CHAPTER = re.compile(r"(?:^|\.)_?ch(\d\d)(?:\.|$)")


@contextlib.contextmanager
def quietly():
    """Within this block, checks, hints and solutions are not recorded in the progress file.

    Examples
    --------
    >>> with quietly():
    ...     pass
    """
    token = _QUIET.set(True)
    try:
        yield
    finally:
        _QUIET.reset(token)


def exercise_key(cls):
    """The stable name of an exercise class: ``"ch05.Outcodes"`` (as the mock exam names it).

    Examples
    --------
    >>> from course_lib.exercises import ch05
    >>> exercise_key(ch05.Outcodes)
    'ch05.Outcodes'
    """
    match = _CHAPTER.search(cls.__module__)
    prefix = f"ch{match.group(1)}" if match else cls.__module__.rsplit(".", 1)[-1]
    return f"{prefix}.{cls.__name__}"


class Guidance:
    """A piece of help shown in the notebook: Markdown (a hint, a note) with a plain-text form.

    Examples
    --------
    >>> print(Guidance("**Hint 1 of 3.** Normalise first."))
    Hint 1 of 3. Normalise first.
    """

    def __init__(self, markdown):
        self.markdown = markdown

    def _repr_markdown_(self):
        return self.markdown

    def __str__(self):
        return self.markdown.replace("**", "")

    __repr__ = __str__


def _answer_markdown(value):
    """The final answer of a worked solution, as Markdown."""
    if isinstance(value, str):
        return f"`{value!r}`"
    if value is None:
        return "`None`"
    if isinstance(value, (set, frozenset)):
        return "`" + repr(sorted(value, key=repr)) + "`"
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return f"`{value!r}`"
    if arr.ndim == 0:
        return f"${fmt.number(float(arr), 4)}$"
    if arr.ndim == 1:
        return f"${fmt.vector_latex(arr, 4)}$"
    if arr.ndim == 2:
        return f"${fmt.matrix_latex(arr, 4)}$"
    return f"`{np.asarray(value).tolist()!r}`"


class Worked:
    r"""The worked solution of one variant: its steps and the answer they arrive at.

    Parameters
    ----------
    steps : sequence of str
        Markdown (LaTeX inside), one step each, with the variant's numbers.
    answer : object
        The final answer, in a form the exercise's ``check`` accepts; computed by the steps'
        arithmetic.
    shown : str, optional
        How to show the answer (Markdown); by default it is formatted from `answer`.

    Examples
    --------
    >>> w = Worked(["Add: $2 + 3 = 5$."], 5)
    >>> w.answer, w.steps
    (5, ['Add: $2 + 3 = 5$.'])
    >>> print(w.markdown())
    1. Add: $2 + 3 = 5$.
    <BLANKLINE>
    **Answer:** $5$
    """

    def __init__(self, steps, answer, shown=None):
        steps = [steps] if isinstance(steps, str) else list(steps)
        if not steps or not all(isinstance(s, str) and s.strip() for s in steps):
            raise ValueError("steps must be a non-empty list of non-empty strings")
        self.steps = steps
        self.answer = answer
        self.shown = shown
        #: A heading (set by ``Exercise.solution``: which exercise and variant), or None.
        self.title = None

    def markdown(self):
        """The heading, the steps as a numbered list, then the answer."""
        lines = [f"{k}. {step}" for k, step in enumerate(self.steps, 1)]
        shown = self.shown if self.shown is not None else _answer_markdown(self.answer)
        head = f"**{self.title}**\n\n" if self.title else ""
        return head + "\n".join(lines) + f"\n\n**Answer:** {shown}"

    def _repr_markdown_(self):
        return self.markdown()

    def __repr__(self):
        return f"Worked({len(self.steps)} steps, answer={self.answer!r})"


def _record(exercise, kind, **fields):
    """Record an event of `exercise` in the progress file, if recording is on; never raises."""
    if _QUIET.get():
        return
    try:
        from ... import progress
        if not progress.recording():
            return
        progress.record_event(kind, key=exercise_key(type(exercise)), seed=exercise.seed,
                              **fields)
    except Exception as exc:                  # help must never stop the notebook
        if not getattr(_record, "warned", False):
            _record.warned = True
            warnings.warn(f"Your attempts could not be recorded in the progress file ({exc}); "
                          "the exercises still work.", RuntimeWarning, stacklevel=3)


def recorded_check(check):
    """Wrap an exercise's ``check`` so that each outermost call is counted and recorded.

    A ``check`` that calls another (``super().check``) is recorded once. Every subclass of
    :class:`Exercise` that defines ``check`` gets it wrapped so (``__init_subclass__``).

    Examples
    --------
    >>> from course_lib.exercises import ch05
    >>> ex = ch05.RayCastingCount(seed=1)
    >>> _ = ex.check(-1)
    >>> ex.attempts, getattr(type(ex).check, "_recorded", False)
    (1, True)
    """
    if getattr(check, "_recorded", False):
        return check

    @functools.wraps(check)
    def wrapper(self, answer):
        depth = self.__dict__.get("_check_depth", 0)
        self._check_depth = depth + 1
        try:
            feedback = check(self, answer)
        finally:
            self._check_depth = depth
        if depth == 0:
            self._attempted(feedback)
        return feedback

    wrapper._recorded = True
    return wrapper
