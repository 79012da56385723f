"""What the chapter 5 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch05`.
"""

import numpy as np

from ... import format as fmt
from ..core import UNANSWERED, DrawnExercise, Feedback, is_unanswered, pick


_vec = fmt.vector_latex
_num = fmt.number


# ---------------------------------------------------------------------------------------------
# Reading answers that are not plain arrays
# ---------------------------------------------------------------------------------------------

def _unanswered(answer):
    return is_unanswered(answer) or (isinstance(answer, (list, tuple))
                                     and any(a is Ellipsis for a in answer))


def _read_index_set(answer, n, what):
    """A set of indices in ``range(n)`` (or a boolean mask of length n), or a Feedback."""
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, (str, bytes, dict)):
        return Feedback("invalid", f"Give {what} as a list of whole numbers, e.g. `[0, 3]` "
                        "(`[]` if there are none).", "unreadable")
    try:
        items = list(answer)
    except TypeError:
        items = [answer]
    if items and len(items) == n and all(isinstance(v, (bool, np.bool_)) for v in items):
        return {i for i, v in enumerate(items) if v}
    found = set()
    for item in items:
        if isinstance(item, (bool, np.bool_)) or not isinstance(item, (int, np.integer, float,
                                                                      np.floating)):
            return Feedback("invalid", f"Give {what} as a list of whole numbers, e.g. `[0, 3]` "
                            "(`[]` if there are none).", "unreadable")
        if not float(item).is_integer() or not 0 <= item < n:
            return Feedback("invalid", f"{item!r} is not one of the indices 0 to {n - 1}.",
                            "unreadable")
        found.add(int(item))
    return found


def _names(indices):
    return ", ".join(str(i) for i in sorted(indices)) or "none"


def _set_feedback(answer, expected, mistakes, n, what, hint, right):
    """Judge a set of indices; `mistakes` are Mistakes with sets as values; `right` praises."""
    value = _read_index_set(answer, n, what)
    if isinstance(value, Feedback):
        return value
    if value == expected:
        return Feedback("correct", right)
    for mistake in mistakes:
        if value == mistake.value and mistake.value != expected:
            return Feedback("wrong", mistake.explanation, mistake.key)
    missing, extra = sorted(expected - value), sorted(value - expected)
    parts = []
    if extra:
        parts.append(f"{_names(extra)} should not be in your list")
    if missing:
        parts.append(f"{_names(missing)} {'is' if len(missing) == 1 else 'are'} missing")
    return Feedback("wrong", f"Not quite: {' and '.join(parts)}. {hint}", "indices differ")


def _cyclic_match(a, b, atol=2e-3):
    """Whether the vertex lists `a` and `b` are the same cycle (any starting vertex)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return False
    return any(np.allclose(np.roll(a, s, axis=0), b, rtol=1e-3, atol=atol)
               for s in range(len(a)))


def _cross2(a, b):
    """The z component of the cross product of 2D vectors (broadcasting)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _shoelace(polygon):
    p = np.asarray(polygon, dtype=float)
    if len(p) < 3:
        return 0.0
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(float(x @ np.roll(y, -1) - y @ np.roll(x, -1)))


def _box_words(lo, hi):
    axes = "xyz"
    return ", ".join(rf"${_num(a)} \le {axes[k]} \le {_num(b)}$"
                     for k, (a, b) in enumerate(zip(lo, hi)))


def _ints_between(rng, low, high, size=None):
    """Whole numbers from `low` to `high` inclusive (bounds may be float arrays), as floats."""
    low = np.asarray(low).astype(int)
    high = np.asarray(high).astype(int)
    return rng.integers(low, high + 1, size=size).astype(float)


def _quick_code(p, lo, hi):
    """The outcode of one point in plain Python: for the fast pre-selection of variants only."""
    code = 0
    for k in range(len(p)):
        code |= (1 << 2 * k) * (p[k] < lo[k]) | (1 << 2 * k + 1) * (p[k] > hi[k])
    return code


def _draw_box_2d(rng):
    lo = np.array([float(rng.integers(-2, 2)), float(rng.integers(-2, 2))])
    hi = lo + np.array([float(pick(rng, (4, 5, 6))), float(pick(rng, (3, 4, 5)))])
    return lo, hi


def _clip_words(ex):
    return rf"The clip rectangle is {_box_words(ex.box_min, ex.box_max)}"


class _Listed(DrawnExercise):
    """An exercise whose answer is a list, a set or a segment rather than an array.

    Its ``mistakes()`` are Mistakes with ``numeric=False`` (their values are sets, lists,
    segments or ``"rejected"``); those equal to the right answer in this variant are dropped.
    """

    answer_form = "custom"

    def keep(self, mistakes):
        return [m for m in mistakes if not _equal_answers(m.value, self.expected)]


def _equal_answers(a, b):
    """Whether two answers of a listed exercise are the same (sets, lists, segments, None).

    A segment rejected as a whole is None, or the word ``"rejected"`` a student types.
    """
    a, b = (None if isinstance(x, str) else x for x in (a, b))
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        return _same_segment(a, b)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return False
    return a == b


# ---------------------------------------------------------------------------------------------
# Cohen-Sutherland
# ---------------------------------------------------------------------------------------------

def _same_segment(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return bool(np.allclose(a, b, rtol=1e-3, atol=2e-3)
                or np.allclose(a[::-1], b, rtol=1e-3, atol=2e-3))
