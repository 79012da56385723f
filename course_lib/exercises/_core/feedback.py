"""The verdict on an answer: :class:`Feedback`, the anticipated :class:`Mistake` and the
diagnoses that say what is wrong (a matrix, a vector, a number, several numbers, names).

Part of :mod:`course_lib.exercises.core`, which imports everything from here.
"""
import math

import numpy as np

from ... import format as fmt

__all__ = [
    "SIGNIFICANT",
    "Feedback",
    "agrees",
    "rounding_of",
    "tolerance",
    "Mistake",
    "close",
    "diagnose_matrix",
    "diagnose_number",
    "diagnose_parts",
    "diagnose_vector",
    "has_placeholder",
    "hinted",
    "is_unanswered",
    "read_floats",
    "read_names",
]


#: The course's tolerance policy, written once (:func:`tolerance`, :func:`agrees`): a real number
#: is right when it agrees with the exact value to SIGNIFICANT significant digits (half a unit
#: of the last digit, plus 0.1 % for rounding on the way), or to 3 decimals for numbers below 1
#: (ATOL). Whole numbers (counts, indices, outcodes) are compared exactly.
SIGNIFICANT = 3
#: The smallest tolerance: answers computed by hand to 3 decimals pass.
ATOL = 2e-3
#: Whole numbers are compared exactly, up to this much float noise (5.0000000001 from numpy).
WHOLE_SLACK = 1e-6
#: The share of the exact value an answer rounded to too few digits may be off and still be
#: called "close" rather than wrong.
CLOSE_SHARE = 0.05


def _unit(x):
    """One unit of the SIGNIFICANT-th significant digit of `x` (0 for 0); the same on every CPU.

    Python formats floats exactly, so the decade is decided without a logarithm.
    """
    if x == 0 or not math.isfinite(x):
        return 0.0
    exponent = int(f"{abs(x):.{SIGNIFICANT - 1}e}".split("e")[1])
    return 10.0 ** (exponent - SIGNIFICANT + 1)


def tolerance(expected, floor=ATOL):
    """How far an answer may be from each entry of `expected` and still be right.

    Half a unit of the third significant digit, plus 0.1 % of the value for rounding on the
    way, and at least `floor` (3 decimals for small numbers).

    Parameters
    ----------
    expected : float or array_like
    floor : float

    Returns
    -------
    numpy.ndarray
        One tolerance per entry, of the shape of `expected`.

    Examples
    --------
    >>> [round(float(t), 4) for t in tolerance([368.896, 12.345, 0.4567, 0.0])]
    [0.8689, 0.0623, 0.002, 0.002]
    """
    e = np.abs(np.asarray(expected, dtype=float))
    units = np.array([_unit(float(x)) for x in e.ravel()]).reshape(e.shape)
    return np.maximum(floor, 0.5 * units + 1e-3 * e)


def agrees(value, expected, whole=False, floor=ATOL):
    """Whether `value` is right for `expected` by the course's policy (see :data:`SIGNIFICANT`).

    Parameters
    ----------
    value, expected : float or array_like
    whole : bool
        Whole numbers: exactly equal (``5.0`` is the whole number 5).
    floor : float
        The smallest tolerance (see :func:`tolerance`).

    Examples
    --------
    >>> agrees(369, 368.896), agrees(368, 368.896), agrees([12.3, 0.457], [12.345, 0.4567])
    (True, False, True)
    >>> agrees(5.0, 5, whole=True), agrees(4, 5, whole=True), agrees([1, 2], [1, 2, 3])
    (True, False, False)
    """
    a, b = np.asarray(value, dtype=float), np.asarray(expected, dtype=float)
    if a.shape != b.shape:
        return False
    if whole:
        return bool(np.all(np.abs(a - b) <= WHOLE_SLACK))
    return bool(np.all(np.abs(a - b) <= tolerance(b, floor)))


#: The numbers of decimals an answer may be rounded to: to hundreds down to 6 decimals.
_DECIMALS = range(-2, 7)


def _two_digits(x, d):
    """Whether `x` keeps 2 significant digits or more when given to `d` decimals."""
    return 10 * abs(x) * 10.0 ** d >= 10 - 1e-9


def _cut(x, y, d):
    """Whether `x` is `y` rounded, floored, ceiled or cut to `d` decimals."""
    step = 10.0 ** d
    return any(math.isclose(x, float(f(y * step)) / step, rel_tol=1e-9, abs_tol=1e-12)
               for f in (round, math.floor, math.ceil, math.trunc))


def rounding_of(value, expected, mistakes=()):
    """Whether `value` is `expected` rounded (or cut) to too few digits, entry by entry.

    Either the whole answer is rounded to one number of decimals that keeps 2 significant
    digits of its largest entry ([0.97, 0.01] for [0.974, 0.0087]), or each entry keeps 2
    significant digits at least (1.0 is no rounding of 1.047 worth calling close). An entry
    given exactly counts as rounded; at least one must differ, every one must be
    within :data:`CLOSE_SHARE` of the largest entry of `expected`, and an anticipated mistake
    that `value` matches exactly is not taken for a rounding.

    Examples
    --------
    >>> rounding_of(368, 368.896), rounding_of([0.71, 0.71, 0], [0.7071, 0.7071, 0])
    (True, True)
    >>> rounding_of(0, 0.3), rounding_of(2.5, 2.5)
    (False, False)
    """
    a, b = np.asarray(value, dtype=float), np.asarray(expected, dtype=float)
    if a.shape != b.shape or not a.size or np.array_equal(a, b):
        return False
    scale = float(np.abs(b).max())
    if scale == 0 or float(np.abs(a - b).max()) > CLOSE_SHARE * scale:
        return False
    pairs = [(x, y) for x, y in zip(a.ravel().tolist(), b.ravel().tolist())
             if abs(x - y) > 1e-12]               # the entries given otherwise than exactly
    # the whole answer to d decimals (its largest entry keeping 2 digits), or entry by entry
    uniform = any(_two_digits(scale, d) and all(_cut(x, y, d) for x, y in pairs)
                  for d in _DECIMALS)
    if not uniform and not all(any(_two_digits(y, d) and _cut(x, y, d) for d in _DECIMALS)
                               for x, y in pairs):
        return False
    for mistake in mistakes:
        try:
            wrong = np.asarray(mistake.value, dtype=float)
        except (TypeError, ValueError):        # a mistake that is no numbers ('rejected')
            continue
        if wrong.shape == a.shape and np.allclose(a, wrong, rtol=1e-9, atol=1e-12):
            return False
    return True


def _rounded_feedback(what):
    return Feedback("wrong", f"Close: {what} looks like the right value rounded to too few "
                    f"digits. Give at least {SIGNIFICANT} significant digits (or 3 decimals), and "
                    "keep the full precision in the intermediate steps.", "rounded")


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

    def __init__(self, status, message, diagnosis=None, credit=None):
        if status not in self._HEADINGS:
            raise ValueError(f"status must be one of {sorted(self._HEADINGS)}, got {status!r}")
        self.status = status
        self.message = message
        self.diagnosis = diagnosis or status
        #: The share of the marks this answer earns, 0 to 1: 1 when correct, the share of the
        #: parts that are right for an answer of several parts, else 0.
        self.credit = float(status == "correct") if credit is None else float(credit)
        #: A line shown under the verdict in a notebook (where to get help); not in `message`.
        self.footer = None

    def __bool__(self):
        return self.status == "correct"

    def __str__(self):
        return f"{self._HEADINGS[self.status]}: {self.message}"

    def __repr__(self):
        return str(self)

    def _repr_markdown_(self):
        text = f"{self._ICONS[self.status]} **{self._HEADINGS[self.status]}.** {self.message}"
        if 0 < self.credit < 1:
            text += f" *(Partial credit: {100 * self.credit:.0f}%.)*"
        return text + (f"\n\n*{self.footer}*" if self.footer else "")


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
    if _has_bool(answer):
        return Feedback("invalid", f"Your answer holds True or False; give {what} as numbers "
                        "(True is not the number 1 here).", "not a number")
    try:
        value = np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return Feedback("invalid", f"Your answer could not be read as {what}: use a list of "
                        "numbers, nested lists of equal length, or a numpy array.", "unreadable")
    if not np.isfinite(value).all():
        return Feedback("invalid", "Your answer contains NaN or infinity: a division by zero "
                        "somewhere?", "not finite")
    return value


def _has_bool(answer, depth=0):
    """Whether `answer` is, or holds, a bool (``True`` would be read as the number 1)."""
    if isinstance(answer, (bool, np.bool_)):
        return True
    if isinstance(answer, np.ndarray):
        return answer.dtype == bool
    if isinstance(answer, (list, tuple)) and depth < 4:
        return any(_has_bool(item, depth + 1) for item in answer)
    return False


def as_vector(value, n):
    """A column ``(n, 1)`` or row ``(1, n)`` array read as the vector of `n` entries it is.

    Examples
    --------
    >>> import numpy as np
    >>> as_vector(np.ones((3, 1)), 3).shape, as_vector(np.ones((2, 2)), 4).shape
    ((3,), (2, 2))
    """
    if value.shape in ((n, 1), (1, n)):
        return value.reshape(n)
    return value


def _cap(text):
    """`text` with its first letter upper-cased (str.capitalize would lower-case the rest)."""
    return text[:1].upper() + text[1:]


def _close(a, b, atol):
    """The course's tolerance policy (:func:`agrees`), with `atol` as the smallest tolerance."""
    return agrees(a, b, floor=atol)


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
    if rounding_of(value, expected, mistakes):
        return _rounded_feedback(what)
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


def _off(value, expected, atol=ATOL):
    """Which entries of `value` are off `expected` by the tolerance policy (a bool array)."""
    return np.abs(value - expected) > tolerance(expected, atol)


def _entrywise(value, expected, atol, what, transform=True):
    off = _off(value, expected, atol)
    sign_only = off & ~_off(value, -expected, atol)
    cells = [tuple(int(i) for i in idx) for idx in np.argwhere(off)]
    listed = ", ".join(str(c) for c in cells[:6]) + (" ..." if len(cells) > 6 else "")
    if off.sum() == sign_only.sum():
        hint = (": check the direction of each rotation (where does the $-\\sin\\theta$ go?), "
                "the side each axis points to and the sign of each displacement or offset."
                if transform else ".")
        return Feedback("wrong", f"Right magnitudes but the wrong sign in entries {listed} (row, "
                        "column, counted from 0)" + hint, "sign")
    worst = max(cells, key=lambda c: abs(value[c] - expected[c]))
    return Feedback("wrong", f"{len(cells)} of {value.size} entries of {what} are off, at "
                    f"{listed} (row, column, counted from 0); the largest difference is "
                    f"{fmt.number(abs(value[worst] - expected[worst]))} at {worst}.",
                    "entries differ")


def diagnose_vector(answer, expected, mistakes=(), atol=ATOL, what="the vector",
                    unit=False, sign_free=False, whole=None):
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
    whole : bool or None
        Whole numbers (indices, counts), compared exactly; None: when `expected` is of an
        integer type.

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
    if whole is None:                    # a direction or a quaternion is never a count
        whole = _is_whole(expected) and not (unit or sign_free)
    expected = np.asarray(expected, dtype=float)
    value = _read(answer, what)
    if isinstance(value, Feedback):
        return value
    value = as_vector(value, expected.size) if expected.ndim == 1 else value
    if value.shape != expected.shape:
        return Feedback("invalid", f"{_cap(what)} should have {expected.size} "
                        f"components, yours has shape {value.shape}.", "wrong shape")
    if whole:
        return _whole_vector(value, expected, mistakes, what)
    if _close(value, expected, atol):
        return Feedback("correct", f"{_cap(what)} is right.")
    if sign_free and _close(value, -expected, atol):
        return Feedback("correct", f"{_cap(what)} is right (it is the negative of the "
                        "reference answer, which represents the same thing).")
    if rounding_of(value, expected, mistakes) or (
            sign_free and rounding_of(value, -expected, mistakes)):
        return _rounded_feedback(what)
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
    off = [int(i) for i in np.flatnonzero(_off(value, expected, atol))]
    return Feedback("wrong", f"Components {off} (counted from 0) of {what} are off.",
                    "components differ")


def _is_whole(expected):
    """Whether `expected` is given as whole numbers (Python or numpy integers, not bools)."""
    if isinstance(expected, (bool, np.bool_)):
        return False
    if isinstance(expected, (int, np.integer)):
        return True
    if isinstance(expected, np.ndarray):
        return expected.dtype.kind in "iu"
    if isinstance(expected, (list, tuple)) and expected:
        return all(_is_whole(item) for item in expected)
    return False


def _not_whole(value, what):
    """A Feedback for an answer that is no whole number where one is expected, else None."""
    flat = np.ravel(value)
    fractional = flat[np.abs(flat - np.round(flat)) > WHOLE_SLACK]
    if not fractional.size:
        return None
    shown = fmt.number(float(fractional[0]), 4)
    return Feedback("wrong", f"{_cap(what)} is made of whole numbers (counts, indices or "
                    f"codes), and yours has a fractional part ({shown}): "
                    "count or index again; nothing here is averaged or interpolated.", "not whole")


def _whole_vector(value, expected, mistakes, what):
    """Whole numbers compared exactly, with the anticipated mistakes and an off-by-one check."""
    if agrees(value, expected, whole=True):
        return Feedback("correct", f"{_cap(what)} is right.")
    for mistake in mistakes:
        if agrees(value, mistake.value, whole=True) \
                and not agrees(mistake.value, expected, whole=True):
            return Feedback("wrong", mistake.explanation, mistake.key)
    bad = _not_whole(value, what)
    if bad is not None:
        return bad
    value = np.round(value)
    diff = value - expected
    off = [int(i) for i in np.flatnonzero(diff)]
    if value.size == 1:
        if abs(float(diff[0])) == 1:
            return Feedback("wrong", f"{_cap(what)} is off by one: count again, and check "
                            "whether the first and last ones are included (and whether counting "
                            "starts at 0 or 1).", "off by one")
        return Feedback("wrong", f"{_cap(what)} should be different: yours is "
                        f"{int(value[0])}.", "value differs")
    if np.all(np.abs(diff[diff != 0]) == 1):
        return Feedback("wrong", f"Off by one in components {off} (counted from 0) of {what}: "
                        "count again, and check whether the first and last ones are included "
                        "(and whether counting starts at 0 or 1).", "off by one")
    return Feedback("wrong", f"Components {off} (counted from 0) of {what} are off.",
                    "components differ")


def diagnose_number(answer, expected, mistakes=(), atol=ATOL, what="the number",
                    angle=False, whole=None):
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
    whole : bool or None
        A whole number (a count, an index), compared exactly, with an off-by-one diagnosis;
        ``5.0`` is the whole number 5. None: when `expected` is an integer.

    Returns
    -------
    Feedback

    Examples
    --------
    >>> import math
    >>> diagnose_number(90, math.pi / 2, angle=True).diagnosis
    'degrees'
    >>> diagnose_number(6, 7).diagnosis, diagnose_number(7.0, 7).status
    ('off by one', 'correct')
    >>> diagnose_number(368, 368.896).diagnosis
    'rounded'
    """
    whole = _is_whole(expected) if whole is None else whole
    value = _read(answer, what)
    if isinstance(value, Feedback):
        return value
    if value.size != 1:
        return Feedback("invalid", f"{_cap(what)} should be a single number, yours has "
                        f"shape {value.shape}.", "wrong shape")
    if whole:
        return _whole_vector(value.reshape(1), np.asarray([float(expected)]), [
            Mistake(np.reshape(m.value, 1), m.explanation, m.key) for m in mistakes], what)
    value = float(value.ravel()[0])
    expected = float(expected)
    if agrees(value, expected, floor=atol):
        return Feedback("correct", f"{_cap(what)} is right.")
    if rounding_of(value, expected, mistakes):
        return _rounded_feedback(what)
    found = _anticipated(np.asarray(value), mistakes, atol, np.asarray(expected))
    if found is not None:
        return found
    if angle:
        if agrees(math.radians(value), expected, floor=atol):
            return Feedback("wrong", f"That is {what} in degrees; give it in radians "
                            f"({fmt.number(value)}° = {fmt.number(math.radians(value))} rad).",
                            "degrees")
        turns = (value - expected) / (2 * math.pi)
        if abs(turns - round(turns)) < 1e-3 and round(turns) != 0:
            return Feedback("correct", f"{_cap(what)} is right up to a whole number of "
                            "turns, which is the same rotation.")
    if agrees(value, -expected, floor=atol):
        return Feedback("wrong", "Right size, wrong sign.", "opposite sign")
    return Feedback("wrong", f"{_cap(what)} should be different: yours is "
                    f"{fmt.number(value, 4)}.", "value differs")


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
    if _has_bool(answer):
        return Feedback("invalid", f"{_cap(what)} holds True or False; give numbers: "
                        f"{form_hint}", "not a number")
    values = read_floats(answer)
    if values is not None:
        values = as_vector(values, len(parts))
    if values is None or values.shape != (len(parts),):
        return Feedback("invalid", f"{_cap(what)} should be {len(parts)} numbers: {form_hint}",
                        "unreadable")
    wrong, found, rounded = [], None, []
    for value, (name, expected, mistakes) in zip(values, parts):
        whole = _is_whole(expected)
        if agrees(value, expected, whole=whole):
            continue
        wrong.append(name)
        if not whole and rounding_of(value, expected, mistakes):
            rounded.append(name)
            continue
        if found is None:
            for mistake in mistakes:
                if agrees(value, mistake.value, whole=whole) \
                        and not agrees(mistake.value, expected, whole=whole):
                    found = (name, mistake)
                    break
            else:
                if whole and value == round(value) and abs(value - float(expected)) == 1:
                    found = (name, Mistake(value, "Off by one: count again, and check whether "
                                           "the first and last ones are included.",
                                           "off by one"))
    if not wrong:
        return Feedback("correct", f"All {len(parts)} numbers are right.")
    right = [name for name, _, _ in parts if name not in wrong]
    credit = len(right) / len(parts)
    summary = (f" Right: {', '.join(right)}." if right else "") + \
        f" Not yet: {', '.join(wrong)}."
    if found is not None:
        name, mistake = found
        return Feedback("wrong", f"*{_cap(name)}:* {mistake.explanation}" + summary,
                        mistake.key, credit=credit)
    if rounded:
        verb = "looks" if len(rounded) == 1 else "look"
        return Feedback("wrong", f"Close: {', '.join(rounded)} {verb} "
                        f"rounded to too few digits; give at least {SIGNIFICANT} significant "
                        f"digits.{summary}", "rounded", credit=credit)
    return Feedback("wrong", f"Some of your numbers are off.{summary} {hint}".rstrip(),
                    "value differs", credit=credit)


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


def close(a, b, atol=ATOL):
    """Whether answer `a` has the shape of `b` and agrees with it by the tolerance policy.

    The same as :func:`agrees` (the course's one policy), for reals.

    Parameters
    ----------
    a, b : array_like
    atol : float
        The smallest tolerance (see :func:`tolerance`).

    Returns
    -------
    bool

    Examples
    --------
    >>> close([1, 2], [1, 2.001]), close([1, 2], [1, 2.1]), close([1, 2], [1, 2, 3])
    (True, False, False)
    """
    return agrees(a, b, floor=atol)


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
