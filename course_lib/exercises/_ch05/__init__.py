"""What the chapter 5 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch05`.
"""

import math
from fractions import Fraction

import numpy as np

from ... import format as fmt
from ..core import UNANSWERED, DrawnExercise, Feedback, agrees, is_unanswered, pick


_vec = fmt.vector_latex
_num = fmt.number


# ---------------------------------------------------------------------------------------------
# Reading answers that are not plain arrays
# ---------------------------------------------------------------------------------------------

def _unanswered(answer):
    return is_unanswered(answer) or (isinstance(answer, (list, tuple))
                                     and any(a is Ellipsis for a in answer))


def _read_index_set(answer, n, what):
    """The whole numbers of the answer as a set (or a boolean mask of length n), or a Feedback.

    ``3.0`` is the index 3; True, 0.5 and text are refused. Numbers outside ``range(n)`` are
    kept: :func:`_set_feedback` tells that they name nothing.
    """
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
        if not float(item).is_integer():
            return Feedback("invalid", f"{item!r} is not a whole number: the indices are 0 to "
                            f"{n - 1}.", "unreadable")
        found.add(int(item))
    return found


def _names(indices):
    return ", ".join(str(i) for i in sorted(indices)) or "none"


def _set_feedback(answer, expected, mistakes, n, what, hint, right):
    """Judge a set of indices; `mistakes` are Mistakes with sets as values; `right` praises.

    Beyond the anticipated mistakes: every index one too large ("counted from 1"), an index
    outside ``range(n)`` ("out of range"), otherwise the indices missing and those too many.
    """
    value = _read_index_set(answer, n, what)
    if isinstance(value, Feedback):
        return value
    if value == expected:
        return Feedback("correct", right)
    for mistake in mistakes:
        if value == mistake.value and mistake.value != expected:
            return Feedback("wrong", mistake.explanation, mistake.key)
    if expected and value == {i + 1 for i in expected}:
        return Feedback("wrong", "Every index is one too large: the numbering starts at **0**. "
                        + hint, "counted from 1")
    outside = sorted(i for i in value if not 0 <= i < n)
    if outside:
        return Feedback("wrong", f"There is no {outside[0]} here: the numbers run from 0 to "
                        f"{n - 1}. " + hint, "out of range")
    missing, extra = sorted(expected - value), sorted(value - expected)
    parts = []
    if extra:
        parts.append(f"{_names(extra)} should not be in your list")
    if missing:
        parts.append(f"{_names(missing)} {'is' if len(missing) == 1 else 'are'} missing")
    return Feedback("wrong", f"Not quite: {' and '.join(parts)}. {hint}", "indices differ")


def _cyclic_match(a, b):
    """Whether answer `a` and the vertex list `b` are the same cycle (any starting vertex), by
    the course's tolerance policy."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return False
    return any(agrees(np.roll(a, s, axis=0), b) for s in range(len(a)))


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


# ---------------------------------------------------------------------------------------------
# Boundary cases, drawn on purpose
# ---------------------------------------------------------------------------------------------

#: The share of the seeds whose variant is a boundary case on purpose; the others have none.
BOUNDARY_SHARE = 0.15
#: The boundary cases, as the ``boundary`` attribute names them. A point on a side: one of its
#: coordinates equals a bound (:math:`x = x_{min}`, ...), so it lies on the line (plane) of a
#: side, where the strict tests of the outcodes and the :math:`t_k` of Liang-Barsky decide.
ON_SIDE = "point on a side"
#: The segment passes exactly through a corner of the rectangle (two sides at one t).
THROUGH_CORNER = "through a corner"
#: In 3D: the segment passes exactly through an edge or a corner of the box.
THROUGH_EDGE = "through an edge or corner"
#: The segment is parallel to two sides (one coordinate does not change): :math:`p_k = 0`.
PARALLEL = "parallel to a side"


class _Boundary:
    """Mixin (put it first): a share of the seeds gives a boundary case on purpose.

    Before the variant is drawn, ``setup`` decides, with probability :data:`BOUNDARY_SHARE`,
    whether this seed is a boundary case and which one of ``boundary_kinds``
    (``self._wanted``; None for an ordinary variant). ``draw`` builds the variant to suit, and
    ``boundary_fits()`` (which ``acceptable`` calls) keeps it only if ``boundary_cases()``, the
    cases it really has, are exactly the one wanted, or none for an ordinary variant. The
    attribute ``boundary`` names the case (None for an ordinary variant).
    """

    boundary_kinds = (ON_SIDE,)
    boundary = None

    def setup(self, rng):
        wanted = rng.random() < BOUNDARY_SHARE
        self._wanted = str(pick(rng, self.boundary_kinds)) if wanted else None
        super().setup(rng)

    def boundary_cases(self):
        """The boundary cases the drawn variant has (a list of the names above)."""
        raise NotImplementedError

    def boundary_fits(self):
        self.boundary = self._wanted
        return self.boundary_cases() == ([] if self._wanted is None else [self._wanted])


def _off_bound_point(rng, lo, hi, margin):
    """A point of whole coordinates from ``lo - margin`` to ``hi + margin``, none on a bound."""
    return np.array([float(pick(rng, [v for v in range(int(a) - margin, int(b) + margin + 1)
                                      if v not in (a, b)])) for a, b in zip(lo, hi)])


def _onto_bound(rng, point, lo, hi):
    """`point` with one coordinate moved onto a bound of its axis (a point on a side)."""
    point = np.array(point, dtype=float)
    k = int(rng.integers(len(point)))
    point[k] = (lo, hi)[int(rng.integers(2))][k]
    return point


def _on_bound(points, lo, hi):
    """Whether a coordinate of one of the points equals a bound (a point on a side's line)."""
    p = np.asarray(points, dtype=float)
    return bool(np.any((p == lo) | (p == hi)))


def _through_corner(p0, p1, lo, hi):
    """Whether the segment passes, strictly between its end points, through a point of the
    box's boundary that lies on two sides at once (a corner in 2D, an edge or corner in 3D).

    Exact: the coordinates are whole numbers, so the crossings are compared as fractions.
    """
    p0 = [Fraction(float(v)) for v in p0]
    d = [Fraction(float(b)) - a for a, b in zip(p0, p1)]
    lo = [Fraction(float(v)) for v in lo]
    hi = [Fraction(float(v)) for v in hi]
    for i, di in enumerate(d):
        if di == 0:
            continue
        for bound in (lo[i], hi[i]):
            t = (bound - p0[i]) / di
            if not 0 < t < 1:
                continue
            point = [a + t * b for a, b in zip(p0, d)]
            inside = all(lo[k] <= point[k] <= hi[k] for k in range(len(point)))
            if inside and any(point[k] in (lo[k], hi[k]) for k in range(len(point)) if k != i):
                return True
    return False


def _segment_cases(p0, p1, lo, hi):
    """The boundary cases of a segment: on a side, through a corner (edge), parallel."""
    found = []
    if _on_bound([p0, p1], lo, hi):
        found.append(ON_SIDE)
    if _through_corner(p0, p1, lo, hi):
        found.append(THROUGH_CORNER if len(p0) == 2 else THROUGH_EDGE)
    if np.any(np.asarray(p1, dtype=float) == p0):
        found.append(PARALLEL)
    return found


def _through_corner_segment(rng, p0, lo, hi, reach=3):
    """An end point p1 of whole coordinates such that p0 -> p1 passes through a corner."""
    corners = [np.array(c, dtype=float) for c in
               np.array(np.meshgrid(*zip(lo, hi))).reshape(len(lo), -1).T]
    corner = pick(rng, corners)
    u = corner - p0
    g = math.gcd(*(int(abs(v)) for v in u)) or 1
    return corner + int(rng.integers(1, reach + 1)) * u / g


def _boundary_segment(rng, lo, hi, wanted, margin=3, point=None):
    """Two end points of whole coordinates, within `margin` of the box.

    Without `wanted` neither lies on the line (plane) of a side; with it, the boundary case it
    names: ON_SIDE one end point on a side's line, THROUGH_CORNER (THROUGH_EDGE) a segment
    through a corner of the box, PARALLEL one coordinate the same at both ends. `point` draws
    one end point (by default :func:`_off_bound_point`).
    """
    draw = point or (lambda: _off_bound_point(rng, lo, hi, margin))
    while True:
        p0, p1 = draw(), draw()
        if wanted == ON_SIDE:
            p0 = _onto_bound(rng, p0, lo, hi)
            if rng.random() < 0.5:
                p0, p1 = p1, p0
        elif wanted in (THROUGH_CORNER, THROUGH_EDGE):
            p1 = _through_corner_segment(rng, p0, lo, hi)
        elif wanted == PARALLEL:
            k = int(rng.integers(len(p0)))
            p1[k] = p0[k]
        if np.all(p1 >= lo - margin - 2) and np.all(p1 <= hi + margin + 2):
            return p0, p1


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
    """Whether answer `a` is segment `b`, either way round, by the course's tolerance policy."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return agrees(a, b) or (a.shape == b.shape and agrees(a[::-1], b))
