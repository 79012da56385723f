"""Exercises: the seeded :class:`Exercise`, the :class:`DrawnExercise` drawn until its anticipated
mistakes are distinct (:func:`gap`, :func:`well_separated`) and checked by answer form, and the
:class:`PartsAnswer` of several numbers.

Part of :mod:`course_lib.exercises.core`, which imports everything from here.
"""
import math
import zlib

import numpy as np

from ... import format as fmt
from .feedback import (UNEXPLAINED, Feedback, _has_bool, _is_whole, _multiple, _off,
                       _rounded_feedback, agrees, as_vector, diagnose_matrix,
                       diagnose_number, diagnose_parts, diagnose_vector, hinted, read_floats,
                       rounding_of, tolerance)
from .guidance import Guidance, _record, recorded_check

__all__ = [
    "DrawnExercise",
    "Exercise",
    "PartsAnswer",
    "gap",
    "parts_separated",
    "well_separated",
]


#: When the variants are drawn, answers closer than SAME count as the same answer, and every
#: anticipated mistake must be at least APART from the right answer and from the other mistakes
#: (a distance within SAME of APART counts as APART: nice numbers are often exactly APART apart,
#: and the last bit of a computed distance depends on the CPU's BLAS and SIMD kernels, which must
#: not decide which variant a seed gives).
SAME, APART = 1e-9, 0.05
#: How many draws a :class:`DrawnExercise` tries before it gives up.
MAX_DRAWS = 500


class Exercise:
    """Base class of an exercise: a seeded question, its expected answer and its check.

    A subclass sets ``title`` and implements ``setup(rng)`` (draw the question's numbers and
    compute the expected answer with ``course_lib``), ``statement()`` (Markdown with LaTeX) and
    ``check(answer)`` (usually one call of a ``diagnose_*`` function with the anticipated
    mistakes). Display the exercise to read the question. An exam question with anticipated
    mistakes is best written as a :class:`DrawnExercise`, which does the drawing and checking.

    Parameters
    ----------
    seed : int, optional
        Chooses the variant; the same seed always gives the same question. Each exercise class
        draws from a stream of its own, salted by the class name, so that the exercises of a
        notebook that share one ``SEED`` do not share their numbers.

    Examples
    --------
    >>> class Double(Exercise):
    ...     title = "Double a number"
    ...     def setup(self, rng):
    ...         self.x = int(rng.integers(1, 10))
    ...         self.expected = 2 * self.x
    ...     def statement(self):
    ...         return f"What is $2 \\times {self.x}$?"
    ...     def check(self, answer):
    ...         return diagnose_number(answer, self.expected)
    >>> ex = Double(seed=3)
    >>> ex.check(ex.expected).status, ex.check(...).status
    ('correct', 'unanswered')
    """

    title = "Exercise"

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "check" in cls.__dict__:           # every check is counted (and recorded) once
            cls.check = recorded_check(cls.__dict__["check"])

    def __init__(self, seed=0):
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
            raise TypeError(f"seed must be an integer, got {type(seed).__name__}")
        self.seed = int(seed)
        salt = zlib.crc32(type(self).__name__.encode())
        self.setup(np.random.default_rng([self.seed, salt]))
        #: How many answers were checked, and how many hints were shown, in this session.
        self.attempts = 0
        self.hints_shown = 0

    # -- help on request -----------------------------------------------------------------------

    def hints(self):
        """The hints of this variant, from a nudge to nearly the answer (Markdown, 3 or more)."""
        raise NotImplementedError(f"{type(self).__name__} has no hints yet")

    def worked(self):
        """The worked solution of this variant: a :class:`Worked` (steps and final answer)."""
        raise NotImplementedError(f"{type(self).__name__} has no worked solution yet")

    def hint(self):
        """Show the next hint (one more each call); recorded in the progress file.

        Returns
        -------
        Guidance
            Markdown: ``Hint k of n`` and the hint, or a note when every hint was shown.
        """
        try:
            hints = list(self.hints())
        except NotImplementedError:
            return Guidance("This exercise has no hints yet: reread the lesson's section.")
        n, k = len(hints), self.hints_shown
        if k >= n:
            return Guidance(f"**No more hints:** all {n} were shown. `ex.solution()` works this "
                            "variant out step by step.")
        self.hints_shown = k + 1
        _record(self, "hint", n=k + 1)
        more = ("Call `hint()` again for the next one." if k + 1 < n else
                "That was the last hint; `solution()` works this variant out.")
        return Guidance(f"**Hint {k + 1} of {n}.** {hints[k]}\n\n*{more}*")

    def solution(self, reveal=False):
        """The worked solution of this variant, once an answer was checked (or with `reveal`).

        Parameters
        ----------
        reveal : bool
            Show it even before a first attempt.

        Returns
        -------
        Worked or Guidance
        """
        if not self.attempts and not reveal:
            return Guidance("**Try it first:** check an answer of your own (even a rough one), "
                            "then call `solution()` again; `hint()` helps on the way. "
                            "(`solution(reveal=True)` shows it now.)")
        worked = self.worked()
        worked.title = f"Worked solution: {self.title} (variant {self.seed})"
        _record(self, "solution", attempts=self.attempts)
        return worked

    def _attempted(self, feedback):
        """Count a checked answer, record it, and offer help after a wrong one."""
        if feedback.status == "unanswered":
            return
        self.attempts += 1
        _record(self, "attempt", status=feedback.status, diagnosis=feedback.diagnosis,
                credit=feedback.credit, hints=self.hints_shown)
        if feedback.status in ("wrong", "invalid") and feedback.footer is None:
            feedback.footer = ("Stuck? `hint()` gives a hint, `solution()` works this variant "
                               "out step by step.")

    def setup(self, rng):
        """Draw the numbers of the question from `rng` and compute the expected answer."""
        raise NotImplementedError

    def statement(self):
        """The question, as Markdown with LaTeX."""
        raise NotImplementedError

    def check(self, answer):
        """Judge `answer`; return a :class:`Feedback`."""
        raise NotImplementedError

    def _repr_markdown_(self):
        return f"**{self.title}** *(variant {self.seed})*\n\n{self.statement()}"

    def __repr__(self):
        return f"{type(self).__name__}(seed={self.seed})"


def gap(a, b, sign_free=False, projective=False):
    """The largest componentwise difference of two answers: how far apart they are.

    Parameters
    ----------
    a, b : array_like
    sign_free : bool
        Also compare `a` with ``-b`` and take the nearer (a quaternion and its negative are the
        same rotation).
    projective : bool
        Measure how far `a` is from every multiple of `b` (a projective matrix and its
        multiples are the same transformation): the multiple that agrees with `a` in the
        largest entry of `b` is compared.

    Returns
    -------
    float
        Infinite for answers of different shapes.

    Examples
    --------
    >>> gap([1, 2], [1, 2.5]), gap([1, 2], [1, 2, 3])
    (0.5, inf)
    >>> gap([0.5, -0.5], [-0.5, 0.5], sign_free=True)
    0.0
    >>> gap([2, 4], [-1, -2], projective=True)
    0.0
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return math.inf
    if a.size == 0:
        return 0.0
    if projective:
        return gap(a, _multiple(a, b))
    distance = float(np.abs(a - b).max())
    if sign_free:
        distance = min(distance, float(np.abs(a + b).max()))
    return distance


def _tolerances_apart(a, b, sign_free=False, projective=False):
    """How many tolerances of the policy (:func:`tolerance` of `b`) answer `a` is from `b`.

    The largest entry's ratio; infinite for different shapes.
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return math.inf
    if not a.size:
        return 0.0
    if projective:
        b = _multiple(a, b)
    ratio = float((np.abs(a - b) / tolerance(b)).max())
    if sign_free:
        ratio = min(ratio, float((np.abs(a + b) / tolerance(b)).max()))
    return ratio


#: An anticipated mistake must lie at least this many tolerances of the policy from the right
#: answer and from the other mistakes, so that a right answer to 3 significant digits is never
#: taken for a mistake, nor a mistake for the right answer.
TOLERANCES_APART = 2.0


def well_separated(expected, mistakes, may_coincide=(), sign_free=False, projective=False):
    """True when every anticipated mistake can be told apart from the answer and the others.

    A mistake whose key is in `may_coincide` may give exactly the right answer in some variants
    (then it is simply right); otherwise each mistake must differ from the right answer by at
    least ``APART`` (0.05, far more than the rounding of a hand computation; exactly 0.05 up to
    rounding is enough, so that the CPU's last bit never decides), and the mistakes of different
    keys must differ from each other by as much. Distances are measured by
    :func:`gap`, with the same `sign_free` and `projective` (for two mistakes: either way round).

    Parameters
    ----------
    expected : array_like
    mistakes : sequence of Mistake
    may_coincide : collection of str
    sign_free, projective : bool

    Returns
    -------
    bool

    Examples
    --------
    >>> from course_lib.exercises.core import Mistake
    >>> right = [1.0, 2.0]
    >>> well_separated(right, [Mistake([2, 1], "Swapped.", "swapped")])
    True
    >>> well_separated(right, [Mistake([1, 2.01], "Rounded.", "rounded")])
    False
    >>> well_separated(right, [Mistake(right, "Same here.", "same")], may_coincide=("same",))
    True
    """
    def apart(a, b):
        if projective:
            distance = min(gap(a, b, projective=True), gap(b, a, projective=True))
            ratio = min(_tolerances_apart(a, b, projective=True),
                        _tolerances_apart(b, a, projective=True))
        else:
            distance = gap(a, b, sign_free)
            ratio = min(_tolerances_apart(a, b, sign_free), _tolerances_apart(b, a, sign_free))
        return distance >= APART - SAME and ratio >= TOLERANCES_APART

    live = []
    for mistake in mistakes:
        distance = gap(mistake.value, expected, sign_free, projective)
        if distance <= SAME and mistake.key in may_coincide:
            continue
        if distance < APART - SAME or _tolerances_apart(
                mistake.value, expected, sign_free, projective) < TOLERANCES_APART:
            return False
        live.append(mistake)
    for i, mistake in enumerate(live):
        for other in live[i + 1:]:
            if other.key != mistake.key and not apart(mistake.value, other.value):
                return False
    return True


def _as_point(answer, dim, projective):
    """A point answer given with a homogeneous coordinate, reduced to `dim` numbers.

    Returns the answer to compare (unchanged when it has `dim` entries or cannot be read), or a
    Feedback when it is homogeneous with :math:`w \\ne 1`.
    """
    if _has_bool(answer):
        return Feedback("invalid", "Your answer holds True or False; give the point as numbers.",
                        "not a number")
    arr = read_floats(answer)
    if arr is not None:
        arr = as_vector(arr, dim + 1)
    if arr is None or arr.shape != (dim + 1,):
        return answer
    w = float(arr[-1])
    if math.isclose(w, 1.0, abs_tol=1e-3):
        return arr[:-1]
    if projective and abs(w) > 1e-12:
        return Feedback("wrong", f"You gave homogeneous coordinates with $w = {fmt.number(w)}$. "
                        r"The point they stand for is found by the **homogeneous divide**: "
                        r"divide the other coordinates by $w$ (then $w$ becomes 1).", "no divide")
    return Feedback("invalid", f"Give the point as {dim} numbers (ordinary coordinates).",
                    "wrong shape")


class DrawnExercise(Exercise):
    r"""An exercise drawn until its anticipated mistakes are distinct, checked by answer form.

    ``setup`` calls ``draw(rng)`` until the variant is ``acceptable()`` and the mistakes it
    anticipates are :func:`well_separated` (each gives an answer of its own, distinct from the
    right one and from the others), so that a diagnosis is never ambiguous; it gives up with a
    RuntimeError after ``MAX_DRAWS`` draws. The mistakes of the accepted variant (those that
    differ from the right answer, see ``keep``) are computed once and reused by every ``check``.

    A subclass sets ``title`` and implements ``draw(rng)`` (set the question's attributes and
    ``self.expected``), ``mistakes()`` (the :class:`Mistake`\ s computed from the question) and
    ``statement()``; optionally ``acceptable()``, and for a form of its own ``_judge(answer)``
    (the verdict, to which ``check`` adds the ``hint``) or ``_check(answer)`` (the whole
    feedback, without the hint). ``check`` never raises: an answer the checker cannot handle is
    reported as unreadable.

    Attributes
    ----------
    answer_form : {"matrix", "vector", "quaternion", "number", "point", "custom"}
        How an answer is judged: :func:`diagnose_matrix`; :func:`diagnose_vector`; a unit
        quaternion (``q`` and ``-q`` are both right, and so are the negatives of the
        mistakes); :func:`diagnose_number`; a point, also accepted as a homogeneous vector with
        ``w = 1``; or the subclass's ``_check``.
    what : str
        How the feedback names the answer (``"the matrix"``).
    may_coincide : tuple of str
        Keys of mistakes that may give the right answer in some variants (then they are simply
        right) instead of forcing a new draw.
    homogeneous_scale : bool
        Matrix form: any non-zero multiple of the answer is right, and any non-zero multiple of
        a mistake is that mistake (a projective matrix).
    projective_point : bool
        Point form: a homogeneous answer with ``w != 1`` is named as a forgotten homogeneous
        divide.
    advice : str
        How to get the answer right: it ends the feedback on a wrong answer that no anticipated
        mistake explains (a diagnosis in ``UNEXPLAINED``). Empty: nothing is added.
    off_by_one : str
        What a whole-number answer one off is told, in this exercise's words (empty: the
        core's "off by one" wording).
    vector_like : bool
        Vector and point forms: whether "right direction, wrong length" means something (a
        direction, a tangent). False for a point or a list of values: such an answer is told
        which components are off instead.
    reject_bool : bool
        Whether ``True`` or ``False`` is refused as an answer instead of being read as 1 or 0.

    Examples
    --------
    >>> from course_lib.exercises.core import Mistake
    >>> class Double(DrawnExercise):
    ...     title = "Double a number"
    ...     answer_form = "number"
    ...     what = "the double"
    ...     def draw(self, rng):
    ...         self.x = int(rng.integers(1, 10))
    ...         self.expected = 2 * self.x
    ...     def mistakes(self):
    ...         return [Mistake(self.x + 2, "You added 2 instead of doubling.", "added")]
    ...     def statement(self):
    ...         return f"What is $2 \\times {self.x}$?"
    >>> ex = Double(seed=1)
    >>> ex.x != 2               # 2 + 2 = 2 * 2: that variant is never drawn
    True
    >>> ex.check(2 * ex.x).status, ex.check(ex.x + 2).diagnosis, ex.check(...).status
    ('correct', 'added', 'unanswered')
    """

    answer_form = "matrix"
    what = "the matrix"
    may_coincide = ()
    homogeneous_scale = False
    projective_point = False
    #: The answer is a transformation matrix (False: a table, a list of points...): chooses the
    #: wording of the generic diagnoses of :func:`diagnose_matrix`.
    transform = True
    advice = ""
    off_by_one = ""
    vector_like = True
    reject_bool = False

    def setup(self, rng):
        """Draw variants from `rng` until one is acceptable with well-separated mistakes."""
        for _ in range(MAX_DRAWS):
            self.draw(rng)
            if not self.acceptable():
                continue
            mistakes = self.mistakes()
            if self.separated(mistakes):
                self._mistakes = self.keep(mistakes)
                return
        raise RuntimeError(f"{type(self).__name__}: found no variant whose anticipated mistakes "
                           "are distinct")

    def draw(self, rng):
        """Draw the numbers of the question and compute ``self.expected``."""
        raise NotImplementedError

    def acceptable(self):
        """Whether the drawn variant is usable (beyond the separation of the mistakes)."""
        return True

    def mistakes(self):
        """The anticipated wrong answers, computed from the question."""
        return []

    def _gap(self, a, b):
        return gap(a, b, sign_free=self.answer_form == "quaternion",
                   projective=self.homogeneous_scale)

    def keep(self, mistakes):
        """The mistakes worth checking in this variant (those that differ from the answer)."""
        return [m for m in mistakes if self._gap(m.value, self.expected) > SAME]

    def separated(self, mistakes):
        """Whether the anticipated mistakes can be told apart (see :func:`well_separated`)."""
        return well_separated(self.expected, mistakes, self.may_coincide,
                              sign_free=self.answer_form == "quaternion",
                              projective=self.homogeneous_scale)

    def _rounded(self, answer):
        """The "close: give more digits" verdict when `answer` is the expected one rounded to
        too few digits (and matches no anticipated mistake); None otherwise. Tried before any
        other diagnosis of a form of the exercise's own (the ``diagnose_*`` functions of the
        other forms make the same check themselves)."""
        expected = getattr(self, "expected", None)
        if self.answer_form != "custom" or expected is None or _is_whole(expected) \
                or _has_bool(answer) or hasattr(self, "_parts"):  # parts: judged one by one
            return None
        value, right = read_floats(answer), read_floats(expected)
        if value is None or right is None or right.dtype.kind != "f":
            return None
        value = as_vector(value, right.size) if right.ndim == 1 else value
        if value.shape != right.shape or agrees(value, right):
            return None
        if rounding_of(value, right, getattr(self, "_mistakes", ())):
            return _rounded_feedback(self.what)
        return None

    def check(self, answer):
        """Judge `answer` and say what is wrong with it; never raises.

        Parameters
        ----------
        answer : object
            The student's answer in the form the statement asks for.

        Returns
        -------
        Feedback
        """
        try:
            rounded = self._rounded(answer)          # a Feedback is falsy unless correct
            return rounded if rounded is not None else self._check(answer)
        except Exception as exc:          # a checker must never stop the notebook
            return Feedback("invalid", f"Your answer could not be checked ({exc}); give it in "
                            "the form the question asks for.", "unreadable")

    def _check(self, answer):
        """The verdict of ``_judge``, with the ``hint`` when no anticipated mistake explains it."""
        return hinted(self._judge(answer), self.advice, UNEXPLAINED)

    def _judge(self, answer):
        """The verdict on `answer` by its form (see ``answer_form``)."""
        if self.reject_bool and isinstance(answer, (bool, np.bool_)):
            return Feedback("invalid", "Your answer is True or False; give a number.",
                            "not a number")
        feedback = self._by_form(answer)
        if feedback.diagnosis == "off by one" and self.off_by_one:
            feedback = Feedback("wrong", self.off_by_one, "off by one")
        if feedback.diagnosis == "wrong length" and not self.vector_like:
            expected = np.ravel(self.expected)
            value = np.ravel(read_floats(answer))[:len(expected)]
            off = [int(i) for i in np.flatnonzero(_off(value, expected))]
            feedback = Feedback("wrong", f"Components {off} (counted from 0) of {self.what} "
                                "are off.", "components differ")
        return feedback

    def _by_form(self, answer):
        form, mistakes = self.answer_form, self._mistakes
        if form == "matrix":
            return diagnose_matrix(answer, self.expected, mistakes, what=self.what,
                                   homogeneous_scale=self.homogeneous_scale,
                                   transform=self.transform)
        if form == "vector":
            return diagnose_vector(answer, self.expected, mistakes, what=self.what)
        if form == "quaternion":
            return diagnose_vector(answer, self.expected, mistakes, what=self.what, unit=True,
                                   sign_free=True)
        if form == "number":
            return diagnose_number(answer, self.expected, mistakes, what=self.what)
        if form == "point":
            reduced = _as_point(answer, len(self.expected), self.projective_point)
            if isinstance(reduced, Feedback):
                return reduced
            return diagnose_vector(reduced, self.expected, mistakes, what=self.what)
        raise NotImplementedError(f"{type(self).__name__}: answer_form {form!r} needs a _check")


def parts_separated(parts, same=SAME, apart=APART):
    """Whether, number by number, the anticipated slips of a multi-part answer can be told apart.

    Parameters
    ----------
    parts : sequence of (label, expected, mistakes)
        As for :func:`diagnose_parts`: each number's right value and its anticipated
        :class:`Mistake` values.
    same : float or None
        A slip within `same` of the right value of a number is no slip for that number and is
        passed over. None: no slip may give the right value (it must be `apart` from it).
    apart : float
        How far every remaining slip must be from the right value and from the slips of
        other keys.

    Returns
    -------
    bool

    Examples
    --------
    >>> from course_lib.exercises.core import Mistake
    >>> parts_separated([("x", 1.0, [Mistake(2.0, "", "a"), Mistake(3.0, "", "b")])])
    True
    >>> parts_separated([("x", 1.0, [Mistake(2.0, "", "a"), Mistake(2.01, "", "b")])])
    False
    >>> right_too = [("x", 1.0, [Mistake(1.0, "", "a")])]
    >>> parts_separated(right_too), parts_separated(right_too, same=None)
    (True, False)
    """
    def far(x, y, whole):                        # exactly `apart`, up to rounding, is apart
        d = abs(float(x) - float(y))
        if whole:                                 # whole numbers are compared exactly
            return d >= 1 - SAME
        return d >= apart - SAME and d >= TOLERANCES_APART * float(
            min(tolerance(x), tolerance(y)))

    for _, expected, mistakes in parts:
        whole = _is_whole(expected)
        live = []
        for m in mistakes:
            d = abs(float(m.value) - float(expected))
            if same is not None and d <= same:
                continue
            if not far(m.value, expected, whole):
                return False
            live.append(m)
        for i, a in enumerate(live):
            for b in live[i + 1:]:
                if a.key != b.key and not far(a.value, b.value, whole):
                    return False
    return True


class PartsAnswer:
    r"""Mixin for a :class:`DrawnExercise` whose answer is several numbers with slips of their own.

    Put it before the exercise base class. A subclass implements ``parts()``: a list of
    (name, expected value, list of :class:`Mistake`), as for :func:`diagnose_parts`; the parts
    are computed when a variant is drawn (the variant is kept only if
    :func:`parts_separated`), and ``judge_parts(answer)`` gives the feedback: the mixin's
    ``_check``. ``what`` names the whole answer and ``form_hint`` says what to type;
    ``self.advice`` (how to get the numbers right) ends the feedback on unexplained numbers, once
    (:func:`diagnose_parts` adds it, so this ``_check`` does not hint the verdict again).

    Examples
    --------
    >>> from course_lib.exercises.core import Mistake
    >>> class SumProduct(PartsAnswer, DrawnExercise):
    ...     title = "Sum and product"
    ...     advice = ""
    ...     def draw(self, rng):
    ...         self.a, self.b = int(rng.integers(2, 6)), int(rng.integers(7, 10))
    ...     def parts(self):
    ...         s, p = self.a + self.b, self.a * self.b
    ...         return [("the sum", s, []),
    ...                 ("the product", p, [Mistake(s, "That is the sum.", "added")])]
    ...     def statement(self):
    ...         return f"Give the sum and the product of {self.a} and {self.b}."
    >>> ex = SumProduct(seed=0)
    >>> s = ex.a + ex.b
    >>> ex.check([s, ex.a * ex.b]).status, ex.check([s, s]).diagnosis
    ('correct', 'added')
    """

    answer_form = "custom"
    what = "your answer"
    form_hint = ""

    def parts(self):
        """The numbers of the answer: a list of (name, expected value, list of Mistake)."""
        raise NotImplementedError

    def separated(self, mistakes):
        """Compute the parts of the drawn variant; whether their slips can be told apart."""
        self._parts = self.parts()
        return parts_separated(self._parts)

    def judge_parts(self, answer):
        """The feedback on `answer` by :func:`diagnose_parts`."""
        return diagnose_parts(answer, self._parts, self.what, self.form_hint, self.advice)

    _check = judge_parts
