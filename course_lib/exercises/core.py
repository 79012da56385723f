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
"""
import math

import numpy as np

from .. import format as fmt

__all__ = [
    "Exercise",
    "Feedback",
    "Mistake",
    "diagnose_matrix",
    "diagnose_number",
    "diagnose_vector",
    "is_unanswered",
]

#: Default absolute tolerance: answers computed by hand to 3 decimals pass.
ATOL = 2e-3


class Feedback:
    """The verdict on an answer: ``status`` plus a message written for the student.

    ``status`` is one of ``"correct"``, ``"wrong"``, ``"unanswered"`` or ``"invalid"`` (the
    answer could not be read, e.g. a string or the wrong shape). ``bool(feedback)`` is True only
    for a correct answer; ``feedback.diagnosis`` is a short key of the mistake found (such as
    ``"transposed"``), for tests and statistics.

    Examples
    --------
    >>> fb = Feedback("wrong", "Your matrix is transposed.", diagnosis="transposed")
    >>> bool(fb), fb.diagnosis
    (False, 'transposed')
    >>> print(fb)
    Not yet: Your matrix is transposed.
    """

    _HEADINGS = {"correct": "Correct", "wrong": "Not yet", "unanswered": "Not answered yet",
                 "invalid": "Cannot read your answer"}
    _ICONS = {"correct": "\u2705", "wrong": "\u274c", "unanswered": "\u270f\ufe0f",
              "invalid": "\u26a0\ufe0f"}

    def __init__(self, status, message, diagnosis=None):
        if status not in self._HEADINGS:
            raise ValueError(f"status must be one of {sorted(self._HEADINGS)}, got {status!r}")
        self.status = status
        self.message = message
        self.diagnosis = diagnosis or status

    def __bool__(self):
        return self.status == "correct"

    def __str__(self):
        return f"{self._HEADINGS[self.status]}: {self.message}"

    def __repr__(self):
        return str(self)

    def _repr_markdown_(self):
        return f"{self._ICONS[self.status]} **{self._HEADINGS[self.status]}.** {self.message}"


class Mistake:
    """A typical wrong answer an exercise anticipates: the value it would give and why.

    Parameters
    ----------
    value : array_like or float
        The answer that this mistake produces, computed from the question.
    explanation : str
        What the student did and what to do instead (Markdown, may contain LaTeX).
    key : str
        A short name of the mistake (``"wrong order"``), reported as ``Feedback.diagnosis``.

    Examples
    --------
    >>> m = Mistake([[1, 0], [0, 1]], "You returned the identity.", "identity")
    >>> m.key
    'identity'
    """

    def __init__(self, value, explanation, key):
        self.value = np.asarray(value, dtype=float)
        self.explanation = explanation
        self.key = key


def is_unanswered(answer):
    """True for the placeholders an exercise starts with: ``...`` and ``None``.

    Examples
    --------
    >>> is_unanswered(...), is_unanswered(None), is_unanswered(0)
    (True, True, False)
    """
    return answer is None or answer is Ellipsis


_UNANSWERED = ("Replace the `...` with your answer and run the cell again.")


def _read(answer, what):
    """The answer as a float array, or a Feedback saying why it cannot be read."""
    if is_unanswered(answer):
        return Feedback("unanswered", _UNANSWERED)
    if isinstance(answer, (str, bytes)):
        return Feedback("invalid", f"Your answer is text ({answer!r}); give {what} as numbers.",
                        "not a number")
    try:
        value = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return Feedback("invalid", f"Your answer could not be read as {what}: use a list of "
                        "numbers, nested lists of equal length, or a numpy array.", "unreadable")
    if not np.isfinite(value).all():
        return Feedback("invalid", "Your answer contains NaN or infinity: a division by zero "
                        "somewhere?", "not finite")
    return value


def _cap(text):
    """`text` with its first letter upper-cased (str.capitalize would lower-case the rest)."""
    return text[:1].upper() + text[1:]


def _close(a, b, atol):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=1e-3, atol=atol))


def _anticipated(value, mistakes, atol, expected, sign_free=False):
    """The first anticipated mistake `value` matches (or its negative, when `sign_free`)."""
    signs = (1.0, -1.0) if sign_free else (1.0,)
    for mistake in mistakes:
        for sign in signs:
            wrong = sign * mistake.value
            if _close(value, wrong, atol) and not _close(wrong, expected, atol) \
                    and not (sign_free and _close(wrong, -expected, atol)):
                return Feedback("wrong", mistake.explanation, mistake.key)
    return None


def diagnose_matrix(answer, expected, mistakes=(), atol=ATOL, what="the matrix",
                    homogeneous_scale=False):
    r"""Compare a matrix answer with the expected one and explain the difference.

    Checks, in order: readable and of the right shape (a 3x3 given where a homogeneous 4x4 is
    expected is named as such); correct; one of the anticipated `mistakes`; transposed; the
    inverse; a multiple of the expected matrix; the opposite sign; a few entries with the wrong
    sign; otherwise the entries that differ.

    Parameters
    ----------
    answer : array_like or None
    expected : array_like
    mistakes : sequence of Mistake
        Wrong answers anticipated by the exercise, tried before the generic ones.
    atol : float
        Absolute tolerance per entry (relative tolerance 1e-3 on top).
    what : str
        How the feedback names the answer.
    homogeneous_scale : bool
        Accept any non-zero multiple of `expected` (projective matrices, chapter 4).

    Returns
    -------
    Feedback

    Examples
    --------
    >>> import numpy as np
    >>> R = np.array([[0.0, -1.0], [1.0, 0.0]])
    >>> diagnose_matrix(R.T, R).diagnosis
    'transposed'
    >>> bool(diagnose_matrix(R, R)), diagnose_matrix(..., R).status
    (True, 'unanswered')
    """
    expected = np.asarray(expected, dtype=float)
    value = _read(answer, what)
    if isinstance(value, Feedback):
        return value
    if value.shape != expected.shape:
        n = expected.shape[0]
        hint = ""
        if value.ndim == 2 and value.shape == (n - 1, n - 1):
            hint = (f" You gave a {n - 1}x{n - 1} matrix; the question asks for the homogeneous "
                    f"{n}x{n} one (the extra row and column carry the translation).")
        return Feedback("invalid", f"{_cap(what)} should have shape {expected.shape}, "
                        f"yours has shape {value.shape}.{hint}", "wrong shape")
    if _close(value, expected, atol):
        return Feedback("correct", f"{_cap(what)} is right.")
    if homogeneous_scale:
        ratio = _common_ratio(value, expected)
        if ratio is not None and abs(ratio) > 1e-9:
            return Feedback("correct", f"{_cap(what)} is right: it is {fmt.number(ratio)} "
                            "times the reference matrix, and any non-zero multiple of a "
                            "projective matrix is the same transformation.")
    found = _anticipated(value, mistakes, atol, expected)
    if found is not None:
        return found
    n = expected.shape[-1]
    if expected.ndim == 2 and expected.shape[0] == n and _close(value, expected.T, atol):
        return Feedback("wrong", f"{_cap(what)} is transposed: rows and columns are "
                        "swapped. With column vectors ($p' = Mp$) the images of the axes are the "
                        "*columns*, and a translation sits in the last *column*.", "transposed")
    if expected.ndim == 2 and expected.shape[0] == n:
        try:
            inv = np.linalg.inv(expected)
        except np.linalg.LinAlgError:
            inv = None
        if inv is not None and _close(value, inv, atol):
            return Feedback("wrong", f"This is the inverse of {what}: it undoes the "
                            "transformation asked for. Check the direction (signs of angles and "
                            "displacements).", "inverse")
    ratio = _common_ratio(value, expected)
    if ratio is not None and not math.isclose(ratio, 1.0, rel_tol=1e-3):
        if math.isclose(ratio, -1.0, rel_tol=1e-3):
            return Feedback("wrong", "Every entry has the wrong sign.", "opposite sign")
        return Feedback("wrong", f"Your matrix is {fmt.number(ratio)} times the right one: "
                        "a factor is missing or doubled somewhere.", "scaled")
    return _entrywise(value, expected, atol, what)


def _common_ratio(value, expected):
    """The c with value = c * expected, if there is one (else None)."""
    scale = np.abs(expected).max()
    if scale == 0:
        return None
    k = np.argmax(np.abs(expected))
    ratio = value.flat[k] / expected.flat[k]
    return ratio if np.allclose(value, ratio * expected, rtol=1e-3, atol=1e-6) else None


def _entrywise(value, expected, atol, what):
    off = ~np.isclose(value, expected, rtol=1e-3, atol=atol)
    sign_only = off & np.isclose(value, -expected, rtol=1e-3, atol=atol)
    cells = [tuple(int(i) for i in idx) for idx in np.argwhere(off)]
    listed = ", ".join(str(c) for c in cells[:6]) + (" ..." if len(cells) > 6 else "")
    if off.sum() == sign_only.sum():
        return Feedback("wrong", f"Right magnitudes but the wrong sign in entries {listed} (row, "
                        "column, counted from 0): check the direction of each rotation (where "
                        "does the $-\\sin\\theta$ go?) and the sign of each displacement.",
                        "sign")
    worst = max(cells, key=lambda c: abs(value[c] - expected[c]))
    return Feedback("wrong", f"{len(cells)} of {value.size} entries of {what} are off, at "
                    f"{listed} (row, column, counted from 0); the largest difference is "
                    f"{fmt.number(abs(value[worst] - expected[worst]))} at {worst}.",
                    "entries differ")


def diagnose_vector(answer, expected, mistakes=(), atol=ATOL, what="the vector",
                    unit=False, sign_free=False):
    r"""Compare a vector (a point, a direction, a quaternion) with the expected one.

    Checks, in order: readable and the right length; correct (or its negative when
    `sign_free`, for quaternions and axes); the anticipated `mistakes`; not of unit length
    when `unit`; right direction but wrong length; the opposite vector; which components are off.

    Parameters
    ----------
    answer : array_like or None
    expected : array_like, shape (n,)
    mistakes : sequence of Mistake
    atol : float
    what : str
        How the feedback names the answer.
    unit : bool
        The answer must have length 1.
    sign_free : bool
        ``-expected`` is also right (a quaternion and its negative are the same rotation); the
        negatives of the anticipated mistakes are recognised too.

    Returns
    -------
    Feedback

    Examples
    --------
    >>> diagnose_vector([0, 0, 2], [0, 0, 1], unit=True).diagnosis
    'not normalized'
    >>> bool(diagnose_vector([0, 0, -1], [0, 0, 1], sign_free=True))
    True
    """
    expected = np.asarray(expected, dtype=float)
    value = _read(answer, what)
    if isinstance(value, Feedback):
        return value
    if value.shape != expected.shape:
        return Feedback("invalid", f"{_cap(what)} should have {expected.size} "
                        f"components, yours has shape {value.shape}.", "wrong shape")
    if _close(value, expected, atol):
        return Feedback("correct", f"{_cap(what)} is right.")
    if sign_free and _close(value, -expected, atol):
        return Feedback("correct", f"{_cap(what)} is right (it is the negative of the "
                        "reference answer, which represents the same thing).")
    found = _anticipated(value, mistakes, atol, expected, sign_free)
    if found is not None:
        return found
    length = float(np.linalg.norm(value))
    target = float(np.linalg.norm(expected))
    if length > 1e-9 and target > 1e-9:
        direction_ok = _close(value / length, expected / target, atol)
        if sign_free:
            direction_ok = direction_ok or _close(value / length, -expected / target, atol)
        if direction_ok:
            if unit:
                return Feedback("wrong", f"Right direction, but {what} has length "
                                f"{fmt.number(length)}: it must be a unit vector (divide by its "
                                "length).", "not normalized")
            return Feedback("wrong", f"Right direction, but the length is {fmt.number(length)} "
                            f"instead of {fmt.number(target)}.", "wrong length")
    if _close(value, -expected, atol):
        return Feedback("wrong", f"{_cap(what)} points the opposite way: every "
                        "component has the wrong sign.", "opposite sign")
    off = [int(i) for i in np.flatnonzero(~np.isclose(value, expected, rtol=1e-3, atol=atol))]
    return Feedback("wrong", f"Components {off} (counted from 0) of {what} are off.",
                    "components differ")


def diagnose_number(answer, expected, mistakes=(), atol=ATOL, what="the number",
                    angle=False):
    r"""Compare a single number with the expected one.

    With ``angle=True`` the answer is an angle in radians: an answer in degrees, or differing
    by a full turn, is recognised.

    Parameters
    ----------
    answer : float or None
    expected : float
    mistakes : sequence of Mistake
    atol : float
    what : str
    angle : bool

    Returns
    -------
    Feedback

    Examples
    --------
    >>> import math
    >>> diagnose_number(90, math.pi / 2, angle=True).diagnosis
    'degrees'
    """
    value = _read(answer, what)
    if isinstance(value, Feedback):
        return value
    if value.size != 1:
        return Feedback("invalid", f"{_cap(what)} should be a single number, yours has "
                        f"shape {value.shape}.", "wrong shape")
    value = float(value.ravel()[0])
    expected = float(expected)
    if math.isclose(value, expected, rel_tol=1e-3, abs_tol=atol):
        return Feedback("correct", f"{_cap(what)} is right.")
    found = _anticipated(np.asarray(value), mistakes, atol, np.asarray(expected))
    if found is not None:
        return found
    if angle:
        if math.isclose(math.radians(value), expected, rel_tol=1e-3, abs_tol=atol):
            return Feedback("wrong", f"That is {what} in degrees; give it in radians "
                            f"({fmt.number(value)}° = {fmt.number(math.radians(value))} rad).",
                            "degrees")
        turns = (value - expected) / (2 * math.pi)
        if abs(turns - round(turns)) < 1e-3 and round(turns) != 0:
            return Feedback("correct", f"{_cap(what)} is right up to a whole number of "
                            "turns, which is the same rotation.")
    if math.isclose(value, -expected, rel_tol=1e-3, abs_tol=atol):
        return Feedback("wrong", "Right size, wrong sign.", "opposite sign")
    return Feedback("wrong", f"{_cap(what)} should be different: yours is "
                    f"{fmt.number(value, 4)}.", "value differs")


class Exercise:
    """Base class of an exercise: a seeded question, its expected answer and its check.

    A subclass sets ``title`` and implements ``setup(rng)`` (draw the question's numbers and
    compute the expected answer with ``course_lib``), ``statement()`` (Markdown with LaTeX) and
    ``check(answer)`` (usually one call of a ``diagnose_*`` function with the anticipated
    mistakes). Display the exercise to read the question.

    Parameters
    ----------
    seed : int, optional
        Chooses the variant; the same seed always gives the same question.

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

    def __init__(self, seed=0):
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
            raise TypeError(f"seed must be an integer, got {type(seed).__name__}")
        self.seed = int(seed)
        self.setup(np.random.default_rng(self.seed))

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

