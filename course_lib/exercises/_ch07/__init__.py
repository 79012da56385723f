"""What the chapter 7 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch07`.
"""

import math
from fractions import Fraction

import numpy as np

from ... import format as fmt
from ..core import DECIMALS, DrawnExercise, diagnose_matrix, is_unanswered, pick


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

_vec = fmt.vector_latex
_num = fmt.number

#: Parameter values that are pleasant by hand.
_T_VALUES = (0.25, 1 / 3, 0.5, 2 / 3, 0.75)


def _frac(x):
    r"""A number as LaTeX, as a fraction when it is a simple one (``\tfrac{1}{3}``)."""
    f = Fraction(float(x)).limit_denominator(16)
    if abs(float(f) - float(x)) > 1e-12 or f.denominator == 1:
        return _num(x)
    sign = "-" if f < 0 else ""
    return rf"{sign}\tfrac{{{abs(f.numerator)}}}{{{f.denominator}}}"


def _points_words(points, name="P"):
    return ", ".join(rf"${name}_{{{i}}} = {_vec(p)}$" for i, p in enumerate(points))


def _control_polygon(rng, n_points, low=0, high=4):
    """`n_points` 2D points with whole coordinates, neighbours distinct, not all on a line."""
    while True:
        p = rng.integers(low, high + 1, size=(n_points, 2)).astype(float)
        edges = np.diff(p, axis=0)
        if np.all(np.abs(edges).sum(axis=1) > 0) and np.linalg.matrix_rank(p - p[0]) == 2:
            return p


def _floats_or_none(answer):
    """The answer as a float array (NaN and infinity allowed), or None if it is no array."""
    if is_unanswered(answer) or isinstance(answer, (str, bytes, dict, set)):
        return None
    try:
        return np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return None


def _bernstein_sum(P, t, binomial=True):
    """sum_i c_i t^i (1 - t)^(n - i) P_i, with c_i the binomial coefficients or 1."""
    n = len(P) - 1
    c = [math.comb(n, i) if binomial else 1 for i in range(n + 1)]
    return sum(c[i] * t ** i * (1 - t) ** (n - i) * np.asarray(P[i], float)
               for i in range(n + 1))


def _integer_knots(rng, n_control, degree, gaps=(1, 1, 2)):
    """A clamped knot vector with whole-number knots: ends repeated degree + 1 times."""
    interior = n_control - degree - 1
    breaks = np.cumsum([0] + [int(pick(rng, gaps)) for _ in range(interior + 1)])
    return np.concatenate([np.zeros(degree), breaks, np.full(degree, breaks[-1])]).astype(float)


def _inside_span(rng, knots, degree):
    """A parameter strictly inside a non-empty knot span of the domain, a multiple of 1/4."""
    n_control = len(knots) - degree - 1
    spans = [k for k in range(degree, n_control) if knots[k + 1] > knots[k]]
    k = int(pick(rng, spans))
    a, b = knots[k], knots[k + 1]
    options = [a + q / 4 for q in range(1, int(4 * (b - a)))]
    return float(pick(rng, options))


def _even_knots(knots, degree):
    """Equally spaced knots over the same domain as `knots` (no repeated end knots)."""
    n_control = len(knots) - degree - 1
    a, b = knots[degree], knots[n_control]
    return a + (np.arange(len(knots)) - degree) * (b - a) / (n_control - degree)


def _cox_de_boor_levels(knots, degree, t):
    """All N_{i,r}(t) for r = 0..degree (0/0 := 0), t strictly inside a knot span."""
    u = np.asarray(knots, dtype=float)
    level = np.array([1.0 if u[i] <= t < u[i + 1] else 0.0 for i in range(len(u) - 1)])
    levels = [level]
    for r in range(1, degree + 1):
        new = np.zeros(len(level) - 1)
        for i in range(len(new)):
            left = u[i + r] - u[i]
            right = u[i + r + 1] - u[i + 1]
            if left > 0:
                new[i] += (t - u[i]) / left * level[i]
            if right > 0:
                new[i] += (u[i + r + 1] - t) / right * level[i + 1]
        level = new
        levels.append(level)
    return levels


def _knots_words(knots):
    return (r"the knot vector $U = (" + r",\ ".join(_num(u) for u in knots) + ")$")


class _Chapter7(DrawnExercise):
    """The chapter's base: most answers are points or lists of values, not directions.

    "Right direction, wrong length" means something for a tangent vector (``vector_like =
    True``) but not for a point or a list of values (see ``DrawnExercise.vector_like``).
    """

    vector_like = False


class _Points(_Chapter7):
    """An answer that is a list of points (an array with one point per row)."""

    answer_form = "custom"
    what = "the list of control points"

    def _shape_feedback(self, value):
        """A Feedback for an answer of another shape that the exercise recognises, or None."""
        return None

    def _judge(self, answer):
        value = _floats_or_none(answer)
        if value is not None and value.shape != np.shape(self.expected) \
                and np.isfinite(value).all():
            found = self._shape_feedback(value)
            if found is not None:
                return found
        return diagnose_matrix(answer, self.expected, self._mistakes, what=self.what,
                               transform=False)


_POINT_2 = ("**Answer:** the point as a list of 2 numbers `[x, y]`. " + DECIMALS)
_POINT_3 = ("**Answer:** the point as a list of 3 numbers `[x, y, z]`. " + DECIMALS)


# ---------------------------------------------------------------------------------------------
# Worked solutions: the arithmetic a student writes down, done here step by step
# ---------------------------------------------------------------------------------------------

def _casteljau_by_hand(P, t):
    """The levels of de Casteljau's triangle, level 0 first, by repeated interpolation.

    Each level is ``(1 - t) * previous[:-1] + t * previous[1:]``: what the worked solutions
    show, written out here rather than taken from :mod:`course_lib.curves`.
    """
    levels = [np.asarray(P, dtype=float)]
    while len(levels[-1]) > 1:
        prev = levels[-1]
        levels.append(np.array([(1 - t) * prev[i] + t * prev[i + 1]
                                for i in range(len(prev) - 1)]))
    return levels


def _level_words(levels, r, t):
    r"""One step of a worked solution: how level `r` of the triangle comes from level r - 1."""
    prev, new = levels[r - 1], levels[r]
    one_minus = _frac(1 - t)
    terms = [rf"$P_{{{i}}}^{{{r}}} = {one_minus}\,{_vec(prev[i])} + {_frac(t)}\,"
             rf"{_vec(prev[i + 1])} = {_vec(new[i])}$" for i in range(len(new))]
    return f"Level {r}: " + "; ".join(terms) + "."


def _span_of(knots, t):
    """The index k with u_k <= t < u_{k+1} (the last such k when knots repeat), by counting."""
    return max(k for k in range(len(knots) - 1) if knots[k] <= t < knots[k + 1])


def _span_words(knots, k, t):
    r"""The sentence that locates t in its knot span, for hints and worked solutions."""
    return (rf"$t = {_num(t)}$ lies in the span $[u_{{{k}}}, u_{{{k + 1}}}) = "
            rf"[{_num(knots[k])}, {_num(knots[k + 1])})$, so $k = {k}$")


def _de_boor_by_hand(P, knots, p, t, k):
    """De Boor's algorithm started on span `k` (also a wrong one: then the piece of span k is
    extrapolated to t), as a list of levels; each level is a list of (i, alpha, point).

    Level 0 is the control points :math:`P_{k-p}, \\dots, P_k` (alpha None). Returns None when
    a ratio has a zero denominator (span `k` is empty).
    """
    u = np.asarray(knots, dtype=float)
    d = {i: np.asarray(P[i], dtype=float) for i in range(k - p, k + 1)}
    levels = [[(i, None, d[i]) for i in range(k - p, k + 1)]]
    for r in range(1, p + 1):
        level = []
        new = {}
        for i in range(k - p + r, k + 1):
            width = u[i + p + 1 - r] - u[i]
            if width == 0:
                return None
            alpha = (t - u[i]) / width
            new[i] = (1 - alpha) * d[i - 1] + alpha * d[i]
            level.append((i, alpha, new[i]))
        d.update(new)
        levels.append(level)
    return levels
