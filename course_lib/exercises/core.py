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
"""
import math
import zlib
from fractions import Fraction

import numpy as np

from .. import format as fmt

__all__ = [
    "DrawnExercise",
    "Exercise",
    "Feedback",
    "Mistake",
    "PartsAnswer",
    "close",
    "data_note",
    "diagnose_matrix",
    "diagnose_number",
    "diagnose_parts",
    "diagnose_vector",
    "gap",
    "has_placeholder",
    "hinted",
    "is_unanswered",
    "latex_fraction",
    "latex_vector",
    "parts_separated",
    "pick",
    "read_floats",
    "read_names",
    "small_ints",
    "well_separated",
]

#: Default absolute tolerance: answers computed by hand to 3 decimals pass.
ATOL = 2e-3
#: When the variants are drawn, answers closer than SAME count as the same answer, and every
#: anticipated mistake must be at least APART from the right answer and from the other mistakes
#: (a distance within SAME of APART counts as APART: nice numbers are often exactly APART apart,
#: and the last bit of a computed distance depends on the CPU's BLAS and SIMD kernels, which must
#: not decide which variant a seed gives).
SAME, APART = 1e-9, 0.05
#: How many draws a :class:`DrawnExercise` tries before it gives up.
MAX_DRAWS = 500
#: The note on precision that ends most statements.
DECIMALS = "Give at least 3 decimals (or let numpy compute them)."
#: What an unanswered exercise says.
UNANSWERED = "Replace the `...` with your answer and run the cell again."
#: The diagnoses that name no anticipated mistake (the generic ones of :func:`diagnose_matrix`,
#: :func:`diagnose_vector`, :func:`diagnose_number` and :func:`diagnose_parts`): a wrong answer
#: diagnosed so is followed by the exercise's ``hint`` (see :class:`DrawnExercise`).
UNEXPLAINED = frozenset({"components differ", "wrong length", "opposite sign", "entries differ",
                         "scaled", "sign", "transposed", "value differs"})


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
    numeric : bool
        Whether `value` is numbers (kept as a float array, compared within a tolerance). False
        for an answer compared as it is: a set of indices, a list of words or whole numbers, a
        segment or None.

    Examples
    --------
    >>> m = Mistake([[1, 0], [0, 1]], "You returned the identity.", "identity")
    >>> m.key
    'identity'
    >>> Mistake({0, 2}, "You listed the front faces.", "front faces", numeric=False).value
    {0, 2}
    """

    def __init__(self, value, explanation, key, numeric=True):
        self.value = np.asarray(value, dtype=float) if numeric else value
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


def _read(answer, what):
    """The answer as a float array, or a Feedback saying why it cannot be read."""
    if is_unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
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


def _multiple(value, of):
    """The multiple ``c * of`` that agrees with `value` in the largest entry of `of`.

    `of` itself when there is none (different shapes, or `of` is zero).
    """
    if value.shape != of.shape or not of.size:
        return of
    k = int(np.argmax(np.abs(of)))
    if abs(of.flat[k]) < 1e-12:
        return of
    return value.flat[k] / of.flat[k] * of


def _anticipated(value, mistakes, atol, expected, sign_free=False, projective=False):
    """The first anticipated mistake `value` matches.

    With `sign_free` a mistake's negative matches too; with `projective` any non-zero multiple
    of it (a projective matrix and its multiples are the same transformation). A mistake that
    gives the right answer (up to sign, or up to a factor) is passed over.
    """
    signs = (1.0, -1.0) if sign_free else (1.0,)
    value = np.asarray(value, dtype=float)
    for mistake in mistakes:
        if projective:
            wrong = _multiple(value, mistake.value)
            if _close(value, wrong, atol) and np.abs(wrong).max(initial=0.0) > 1e-9 \
                    and not _close(_multiple(mistake.value, expected), mistake.value, atol):
                return Feedback("wrong", mistake.explanation, mistake.key)
            continue
        for sign in signs:
            wrong = sign * mistake.value
            if _close(value, wrong, atol) and not _close(wrong, expected, atol) \
                    and not (sign_free and _close(wrong, -expected, atol)):
                return Feedback("wrong", mistake.explanation, mistake.key)
    return None


def diagnose_matrix(answer, expected, mistakes=(), atol=ATOL, what="the matrix",
                    homogeneous_scale=False, transform=True):
    r"""Compare a matrix answer with the expected one and explain the difference.

    Checks, in order: readable and of the right shape (a 3x3 given where a homogeneous 4x4 is
    expected is named as such); correct; one of the anticipated `mistakes`; transposed; the
    inverse; a multiple of the expected matrix; the opposite sign; a few entries with the wrong
    sign; otherwise the entries that differ.

    The generic feedback assumes a transformation matrix (column vectors, rotations,
    translations). For other arrays (a table of numbers, an id buffer) pass ``transform=False``:
    the feedback then speaks of rows, columns and entries only, and the inverse and the
    homogeneous shape are not suggested.

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
        Accept any non-zero multiple of `expected` (projective matrices, chapter 4), and
        recognise any non-zero multiple of an anticipated mistake as that mistake.
    transform : bool
        Whether the matrix is a transformation (the default); False for other arrays.

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
    >>> table = np.array([[1.0, 2.0], [3.0, 4.0]])
    >>> print(diagnose_matrix(table.T, table, what="the table", transform=False))
    Not yet: The table is transposed: rows and columns are swapped.
    """
    expected = np.asarray(expected, dtype=float)
    value = _read(answer, what)
    if isinstance(value, Feedback):
        return value
    if value.shape != expected.shape:
        n = expected.shape[0]
        hint = ""
        if transform and value.ndim == 2 and value.shape == (n - 1, n - 1):
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
    found = _anticipated(value, mistakes, atol, expected, projective=homogeneous_scale)
    if found is not None:
        return found
    n = expected.shape[-1]
    if expected.ndim == 2 and expected.shape[0] == n and _close(value, expected.T, atol):
        why = (" With column vectors ($p' = Mp$) the images of the axes are the *columns*, and "
               "a translation sits in the last *column*." if transform else "")
        return Feedback("wrong", f"{_cap(what)} is transposed: rows and columns are swapped."
                        + why, "transposed")
    if transform and expected.ndim == 2 and expected.shape[0] == n:
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
        mine = "Your matrix" if transform else _cap(what)
        return Feedback("wrong", f"{mine} is {fmt.number(ratio)} times the right one: "
                        "a factor is missing or doubled somewhere.", "scaled")
    return _entrywise(value, expected, atol, what, transform)


def _common_ratio(value, expected):
    """The c with value = c * expected, if there is one (else None)."""
    scale = np.abs(expected).max()
    if scale == 0:
        return None
    k = np.argmax(np.abs(expected))
    ratio = value.flat[k] / expected.flat[k]
    return ratio if np.allclose(value, ratio * expected, rtol=1e-3, atol=1e-6) else None


def _entrywise(value, expected, atol, what, transform=True):
    off = ~np.isclose(value, expected, rtol=1e-3, atol=atol)
    sign_only = off & np.isclose(value, -expected, rtol=1e-3, atol=atol)
    cells = [tuple(int(i) for i in idx) for idx in np.argwhere(off)]
    listed = ", ".join(str(c) for c in cells[:6]) + (" ..." if len(cells) > 6 else "")
    if off.sum() == sign_only.sum():
        hint = (": check the direction of each rotation (where does the $-\\sin\\theta$ go?) "
                "and the sign of each displacement." if transform else ".")
        return Feedback("wrong", f"Right magnitudes but the wrong sign in entries {listed} (row, "
                        "column, counted from 0)" + hint, "sign")
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

    def __init__(self, seed=0):
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
            raise TypeError(f"seed must be an integer, got {type(seed).__name__}")
        self.seed = int(seed)
        salt = zlib.crc32(type(self).__name__.encode())
        self.setup(np.random.default_rng([self.seed, salt]))

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


# ---------------------------------------------------------------------------------------------
# Exercises drawn until their anticipated mistakes are distinct
# ---------------------------------------------------------------------------------------------

def read_floats(value):
    """`value` as a finite float array, or None when it cannot be read.

    Placeholders, text, dicts and sets are not read; neither are ragged lists or answers with
    NaN or infinity.

    Parameters
    ----------
    value : object

    Returns
    -------
    numpy.ndarray or None

    Examples
    --------
    >>> read_floats([[1, 2], [3, 4]]).shape
    (2, 2)
    >>> read_floats("1, 2") is None, read_floats([1, float("nan")]) is None, read_floats(...)
    (True, True, None)
    """
    if value is None or value is Ellipsis or isinstance(value, (str, bytes, dict, set)):
        return None
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        return None
    return arr if np.isfinite(arr).all() else None


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
            return min(gap(a, b, projective=True), gap(b, a, projective=True))
        return gap(a, b, sign_free)

    live = []
    for mistake in mistakes:
        distance = gap(mistake.value, expected, sign_free, projective)
        if distance <= SAME and mistake.key in may_coincide:
            continue
        if distance < APART - SAME:
            return False
        live.append(mistake)
    for i, mistake in enumerate(live):
        for other in live[i + 1:]:
            if other.key != mistake.key and apart(mistake.value, other.value) < APART - SAME:
                return False
    return True


def diagnose_parts(answer, parts, what, form_hint, hint=""):
    r"""Judge an answer made of several numbers, each with its own anticipated mistakes.

    Parameters
    ----------
    answer : object
    parts : list of (str, float, list of Mistake)
        The name of each number, its expected value and the slips anticipated for it.
    what : str
        How the feedback names the whole answer.
    form_hint : str
        What to type, for an answer that cannot be read.
    hint : str
        How to get the numbers right, for wrong numbers that match no anticipated slip.

    Returns
    -------
    Feedback
        Correct when every number is right; otherwise the explanation of the first anticipated
        slip found (its key is the diagnosis), followed by the list of the numbers that are right
        and wrong.

    Examples
    --------
    >>> parts = [("the sum", 5.0, []),
    ...          ("the product", 6.0, [Mistake(5.0, "That is the sum.", "added")])]
    >>> diagnose_parts([5, 6], parts, "your answer", "`[sum, product]`").status
    'correct'
    >>> print(diagnose_parts([5, 5], parts, "your answer", "`[sum, product]`"))
    Not yet: *The product:* That is the sum. Right: the sum. Not yet: the product.
    >>> diagnose_parts([5, ...], parts, "your answer", "`[sum, product]`").status
    'unanswered'
    """
    if is_unanswered(answer) or (isinstance(answer, (list, tuple))
                                 and any(is_unanswered(a) for a in answer)):
        return Feedback("unanswered", UNANSWERED)
    values = read_floats(answer)
    if values is None or values.shape != (len(parts),):
        return Feedback("invalid", f"{_cap(what)} should be {len(parts)} numbers: {form_hint}",
                        "unreadable")
    wrong, found = [], None
    for value, (name, expected, mistakes) in zip(values, parts):
        if math.isclose(value, expected, rel_tol=1e-3, abs_tol=ATOL):
            continue
        wrong.append(name)
        if found is None:
            for mistake in mistakes:
                if _close(value, mistake.value, ATOL) and not _close(mistake.value, expected,
                                                                     ATOL):
                    found = (name, mistake)
                    break
    if not wrong:
        return Feedback("correct", f"All {len(parts)} numbers are right.")
    right = [name for name, _, _ in parts if name not in wrong]
    summary = (f" Right: {', '.join(right)}." if right else "") + \
        f" Not yet: {', '.join(wrong)}."
    if found is not None:
        name, mistake = found
        return Feedback("wrong", f"*{_cap(name)}:* {mistake.explanation}" + summary,
                        mistake.key)
    return Feedback("wrong", f"Some of your numbers are off.{summary} {hint}".rstrip(),
                    "value differs")


def _as_point(answer, dim, projective):
    """A point answer given with a homogeneous coordinate, reduced to `dim` numbers.

    Returns the answer to compare (unchanged when it has `dim` entries or cannot be read), or a
    Feedback when it is homogeneous with :math:`w \\ne 1`.
    """
    arr = read_floats(answer)
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
    hint : str
        How to get the answer right: it ends the feedback on a wrong answer that no anticipated
        mistake explains (a diagnosis in ``UNEXPLAINED``). Empty: nothing is added.
    vector_like : bool
        Vector and point forms: whether "right direction, wrong length" means something (a
        direction, a tangent). False for a point or a list of values: such an answer is told
        which components are off instead.
    reject_bool : bool
        Whether ``True`` or ``False`` is refused as an answer instead of being read as 1 or 0.

    Examples
    --------
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
    hint = ""
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
            return self._check(answer)
        except Exception as exc:          # a checker must never stop the notebook
            return Feedback("invalid", f"Your answer could not be checked ({exc}); give it in "
                            "the form the question asks for.", "unreadable")

    def _check(self, answer):
        """The verdict of ``_judge``, with the ``hint`` when no anticipated mistake explains it."""
        return hinted(self._judge(answer), self.hint, UNEXPLAINED)

    def _judge(self, answer):
        """The verdict on `answer` by its form (see ``answer_form``)."""
        if self.reject_bool and isinstance(answer, (bool, np.bool_)):
            return Feedback("invalid", "Your answer is True or False; give a number.",
                            "not a number")
        feedback = self._by_form(answer)
        if feedback.diagnosis == "wrong length" and not self.vector_like:
            expected = np.ravel(self.expected)
            value = np.ravel(read_floats(answer))[:len(expected)]
            off = [int(i) for i in np.flatnonzero(~np.isclose(value, expected, rtol=1e-3,
                                                                atol=ATOL))]
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


# ---------------------------------------------------------------------------------------------
# Numbers that are pleasant by hand, and the statement's last line
# ---------------------------------------------------------------------------------------------

def pick(rng, options):
    """One element of the sequence `options`, drawn with `rng`.

    Unlike ``rng.choice`` it keeps the element as it is (a tuple stays a tuple).

    Examples
    --------
    >>> import numpy as np
    >>> pick(np.random.default_rng(0), [(1, 2), (3, 4)]) in [(1, 2), (3, 4)]
    True
    """
    return options[int(rng.integers(len(options)))]


def small_ints(rng, n, low=-3, high=3):
    """A non-zero vector of `n` whole numbers in [low, high], as floats.

    Examples
    --------
    >>> import numpy as np
    >>> v = small_ints(np.random.default_rng(0), 3)
    >>> v.shape, bool(v.any()), bool(np.all(np.abs(v) <= 3)), bool(np.all(v == np.round(v)))
    ((3,), True, True, True)
    """
    while True:
        v = rng.integers(low, high + 1, size=n).astype(float)
        if np.any(v):
            return v


def data_note(*names):
    """The note that ends a statement: where the question's numbers are, as attributes.

    Examples
    --------
    >>> print(data_note("theta", "d"))
    *The numbers of this question are the attributes `.theta`, `.d` of the exercise object.*
    """
    listed = ", ".join(f"`.{name}`" for name in names)
    return f"*The numbers of this question are the attributes {listed} of the exercise object.*"


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
    >>> parts_separated([("x", 1.0, [Mistake(2.0, "", "a"), Mistake(3.0, "", "b")])])
    True
    >>> parts_separated([("x", 1.0, [Mistake(2.0, "", "a"), Mistake(2.01, "", "b")])])
    False
    >>> right_too = [("x", 1.0, [Mistake(1.0, "", "a")])]
    >>> parts_separated(right_too), parts_separated(right_too, same=None)
    (True, False)
    """
    for _, expected, mistakes in parts:
        live = []
        for m in mistakes:
            d = abs(float(m.value) - float(expected))
            if same is not None and d <= same:
                continue
            if d < apart - SAME:                  # exactly `apart`, up to rounding, is apart
                return False
            live.append(m)
        for i, a in enumerate(live):
            for b in live[i + 1:]:
                if a.key != b.key and abs(float(a.value) - float(b.value)) < apart - SAME:
                    return False
    return True


def hinted(feedback, hint, generic):
    """`feedback` with `hint` appended when no anticipated mistake explained a wrong answer.

    Parameters
    ----------
    feedback : Feedback
    hint : str or None
        What to add (how to get the answer right); nothing is added when it is empty.
    generic : set of str
        The diagnoses that name no anticipated slip (such as ``"components differ"``).

    Returns
    -------
    Feedback

    Examples
    --------
    >>> fb = Feedback("wrong", "Not this.", "value differs")
    >>> hinted(fb, "Divide by the length.", {"value differs"}).message
    'Not this. Divide by the length.'
    >>> hinted(Feedback("wrong", "Transposed.", "transposed"), "Divide.", {"value differs"}).message
    'Transposed.'
    """
    if hint and feedback.status == "wrong" and feedback.diagnosis in generic:
        return Feedback("wrong", f"{feedback.message} {hint}", feedback.diagnosis)
    return feedback


def close(a, b, atol=ATOL, rtol=1e-3):
    """Whether two answers have the same shape and agree within the tolerances.

    Parameters
    ----------
    a, b : array_like
    atol, rtol : float
        Absolute and relative tolerance, as for :func:`numpy.allclose`.

    Returns
    -------
    bool

    Examples
    --------
    >>> close([1, 2], [1, 2.001]), close([1, 2], [1, 2.1]), close([1, 2], [1, 2, 3])
    (True, False, False)
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=rtol, atol=atol))


def has_placeholder(answer, none_inside=False):
    """True for a placeholder answer, or a list or tuple with a ``...`` in it.

    Parameters
    ----------
    answer : object
    none_inside : bool
        Also count a None inside the list or tuple as a placeholder.

    Returns
    -------
    bool

    Examples
    --------
    >>> has_placeholder(...), has_placeholder([1, ...]), has_placeholder([1, 2])
    (True, True, False)
    >>> has_placeholder([1, None]), has_placeholder([1, None], none_inside=True)
    (False, True)
    """
    if is_unanswered(answer):
        return True
    if not isinstance(answer, (list, tuple)):
        return False
    inside = is_unanswered if none_inside else (lambda a: a is Ellipsis)
    return any(inside(a) for a in answer)


class PartsAnswer:
    r"""Mixin for a :class:`DrawnExercise` whose answer is several numbers with slips of their own.

    Put it before the exercise base class. A subclass implements ``parts()``: a list of
    (name, expected value, list of :class:`Mistake`), as for :func:`diagnose_parts`; the parts
    are computed when a variant is drawn (the variant is kept only if
    :func:`parts_separated`), and ``judge_parts(answer)`` gives the feedback (call it from the
    exercise's ``_check``). ``what`` names the whole answer and ``form_hint`` says what to type;
    ``self.hint`` (how to get the numbers right) ends the feedback on unexplained numbers.

    Examples
    --------
    >>> class SumProduct(PartsAnswer, DrawnExercise):
    ...     title = "Sum and product"
    ...     hint = ""
    ...     def draw(self, rng):
    ...         self.a, self.b = int(rng.integers(2, 6)), int(rng.integers(7, 10))
    ...     def parts(self):
    ...         s, p = self.a + self.b, self.a * self.b
    ...         return [("the sum", s, []),
    ...                 ("the product", p, [Mistake(s, "That is the sum.", "added")])]
    ...     def statement(self):
    ...         return f"Give the sum and the product of {self.a} and {self.b}."
    ...     def _check(self, answer):
    ...         return self.judge_parts(answer)
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
        return diagnose_parts(answer, self._parts, self.what, self.form_hint, self.hint)


def latex_fraction(x, max_denominator=64):
    r"""A number as LaTeX: a short decimal when it has one, else a simple fraction (``\tfrac``).

    Parameters
    ----------
    x : float
    max_denominator : int
        The largest denominator a fraction may have; a number that is no such fraction (to
        1e-12) is written as a decimal.

    Returns
    -------
    str

    Examples
    --------
    >>> latex_fraction(0.25), latex_fraction(1 / 3), latex_fraction(-2 / 7)
    ('0.25', '\\tfrac{1}{3}', '-\\tfrac{2}{7}')
    >>> latex_fraction(1 / 127), latex_fraction(1 / 127, max_denominator=1024)
    ('0.008', '\\tfrac{1}{127}')
    """
    x = float(x)
    if abs(round(x, 3) - x) < 1e-12:
        return fmt.number(x)
    f = Fraction(x).limit_denominator(max_denominator)
    if abs(float(f) - x) > 1e-12:
        return fmt.number(x)
    sign = "-" if f < 0 else ""
    return rf"{sign}\tfrac{{{abs(f.numerator)}}}{{{f.denominator}}}"


def latex_vector(v, max_denominator=64):
    r"""A vector as LaTeX, its components as short decimals or simple fractions.

    Parameters
    ----------
    v : array_like
    max_denominator : int
        As for :func:`latex_fraction`.

    Returns
    -------
    str

    Examples
    --------
    >>> print(latex_vector([0.5, 1 / 3, 2]))
    (0.5,\ \tfrac{1}{3},\ 2)
    """
    return "(" + r",\ ".join(latex_fraction(x, max_denominator) for x in np.ravel(v)) + ")"


def read_names(answer, menu, form, not_listed, normalise=None):
    """An answer that is a list of names from a menu, as a set, or a Feedback saying why not.

    Parameters
    ----------
    answer : object
    menu : sequence of str
        The names that may be given (listed in the feedback on a name not in it).
    form : str
        What to type, for an answer that is no list of strings.
    not_listed : str
        What follows the quoted name that is not on the menu, up to the list of the names
        (e.g. ``"is not on the menu. The names are:"``).
    normalise : callable or None
        Turns a typed name into its menu spelling; None: strip and lower-case it.

    Returns
    -------
    set of str or Feedback
        "unanswered" for a placeholder, "invalid" (diagnosis ``"unreadable"``) otherwise.

    Examples
    --------
    >>> sorted(read_names(["Red ", "blue"], ("red", "blue"), "A list.", "is no colour:"))
    ['blue', 'red']
    >>> print(read_names(["green"], ("red", "blue"), "A list.", "is no colour:"))
    Cannot read your answer: 'green' is no colour: `red`, `blue`.
    >>> read_names("red", ("red",), "A list.", "is no colour:").message
    'A list.'
    """
    if has_placeholder(answer):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, (str, bytes, dict)) or not isinstance(
            answer, (list, tuple, set, frozenset, np.ndarray)):
        return Feedback("invalid", form, "unreadable")
    names = set()
    for item in answer:
        if not isinstance(item, str):
            return Feedback("invalid", form, "unreadable")
        name = item.strip().lower() if normalise is None else normalise(item)
        if name not in menu:
            return Feedback("invalid", f"{item!r} {not_listed} "
                            + ", ".join(f"`{n}`" for n in menu) + ".", "unreadable")
        names.add(name)
    return names
