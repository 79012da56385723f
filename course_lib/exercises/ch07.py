r"""Chapter 7 exercises: Bézier, B-spline and NURBS curves and surfaces, exam style.

Each class is one kind of exam question: a Bézier point by de Casteljau's algorithm and one
level of its triangle, the Bernstein polynomials, the end tangent, subdivision and degree
elevation; a clamped knot vector, the B-spline basis functions by the Cox-de Boor recursion,
the support of one of them, the control points active at a parameter and a B-spline point by
de Boor's algorithm; a rational quadratic Bézier point, the circular arc as a rational quadratic,
the type of conic a set of weights gives; a point of a Bézier patch; and which properties hold
for which kind of curve or surface. The ``seed`` draws numbers that work out by hand: control
points with small whole coordinates, parameters among :math:`\tfrac14, \tfrac13, \tfrac12,
\tfrac23, \tfrac34`, whole-number knots.

The expected answers come from :mod:`course_lib.curves` and :mod:`course_lib.surfaces`. Each
exercise names the slips it anticipates (the binomial coefficient left out, :math:`t` and
:math:`1 - t` swapped, a forgotten division by the sum of the weighted basis functions, the
sine of the half angle, ...), computes the answer each slip would give, and draws its numbers
again until those answers differ clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.curves`): control points are the rows of an array; a
B-spline with the :math:`n + 1` control points :math:`P_0, \dots, P_n` and degree :math:`p` has
:math:`n + p + 2` knots and lives on :math:`[u_p, u_{n+1}]`; a fraction with a zero denominator
in the Cox-de Boor recursion counts as 0; weights are positive; the control grid of a patch is
indexed ``grid[i, j]``, ``i`` along :math:`u` and ``j`` along :math:`v`.
"""
import math
from fractions import Fraction

import numpy as np

from .. import curves, surfaces
from .. import format as fmt
from .core import (DECIMALS, UNANSWERED, UNEXPLAINED, DrawnExercise, Feedback, Mistake, close,
                   data_note, diagnose_matrix, diagnose_parts, has_placeholder, is_unanswered,
                   parts_separated, pick, read_names)

__all__ = [
    "EXERCISES",
    "PROPERTY_MENU",
    "ActiveControlPoints",
    "BSplinePoint",
    "BasisSupport",
    "BernsteinValues",
    "BezierEndTangent",
    "BezierSubdivision",
    "BezierSurfacePoint",
    "CircleArc",
    "ClampedKnotVector",
    "ConicType",
    "CoxDeBoorBasis",
    "CurveProperties",
    "DeCasteljauLevel",
    "DeCasteljauPoint",
    "DegreeElevation",
    "RationalBezierPoint",
]

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
# Bézier curves
# ---------------------------------------------------------------------------------------------

class DeCasteljauPoint(_Chapter7):
    r"""A point :math:`C(t)` of a quadratic or cubic Bézier curve, by de Casteljau's algorithm.

    :math:`P_i^r = (1 - t)\,P_i^{r-1} + t\,P_{i+1}^{r-1}`, and :math:`C(t) = P_0^n`; the same
    as :math:`\sum_i \binom{n}{i} t^i (1-t)^{n-i} P_i`.

    Attributes: ``P`` (the control points, one per row), ``n`` (the degree), ``t``.

    Examples
    --------
    >>> ex = DeCasteljauPoint(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> P, t = ex.P, ex.t
    >>> ex.check((1 - t) * P[0] + t * P[-1]).diagnosis       # the end points only
    'end points only'
    >>> ex.check(...).status, ex.check("C").status
    ('unanswered', 'invalid')
    """

    title = "A Bézier point by de Casteljau's algorithm"
    answer_form = "point"
    what = "the curve point"
    may_coincide = ("t swapped",)
    hint = (r"Run the triangle: $n$ rounds of $(1 - t)\,P_i + t\,P_{i+1}$ on neighbouring "
            r"points, each round one point fewer, until a single point is left.")

    def draw(self, rng):
        self.n = int(pick(rng, (2, 3)))
        self.P = _control_polygon(rng, self.n + 1)
        self.t = float(pick(rng, _T_VALUES))
        self.expected, levels = curves.de_casteljau(self.P, self.t, triangle=True)
        self._pair = levels[self.n - 1]

    def mistakes(self):
        P, t, n = self.P, self.t, self.n
        early = (r"That is one of the two points of the last-but-one level. De Casteljau's "
                 r"algorithm needs one more round: interpolate between the two, "
                 r"$C(t) = (1 - t)\,P_0^{n-1} + t\,P_1^{n-1}$.")
        return [
            Mistake(_bernstein_sum(P, t, binomial=False), r"You weighted the control points "
                    r"by $t^i (1 - t)^{n-i}$ without the binomial coefficients "
                    r"$\binom{n}{i}$; then the weights do not add up to 1. The Bernstein "
                    r"polynomials are $B_i^n(t) = \binom{n}{i} t^i (1 - t)^{n-i}$ (for a "
                    r"cubic the coefficients are 1, 3, 3, 1).", "no binomial"),
            Mistake(curves.de_casteljau(P, 1 - t), r"$t$ and $1 - t$ are swapped: you computed "
                    r"$C(1 - t)$, the point as far from the end as $C(t)$ is from the start. In "
                    r"each interpolation the **first** point gets the weight $1 - t$ and the "
                    r"second one $t$: $(1 - t)\,P_i + t\,P_{i+1}$ (at $t = 0$ you are at "
                    r"$P_0$).", "t swapped"),
            Mistake(self._pair[0], early, "stopped early"),
            Mistake(self._pair[1], early, "stopped early"),
            Mistake((1 - t) * P[0] + t * P[n], r"You interpolated between the first and the "
                    r"last control point only. The inner control points pull the curve away "
                    r"from that line: every control point has its weight $B_i^n(t)$ "
                    r"(de Casteljau: interpolate along every edge of the control polygon, "
                    r"then again, $n$ rounds in all).", "end points only"),
        ]

    def _judge(self, answer):
        value = _floats_or_none(answer)
        if value is not None and close(value, self._pair):
            return Feedback("wrong", r"You stopped one level early: these are the two points "
                            r"$P_0^{n-1}, P_1^{n-1}$ of the last-but-one level. One more round "
                            r"gives the curve point, $(1 - t)\,P_0^{n-1} + t\,P_1^{n-1}$.",
                            "stopped early")
        return super()._judge(answer)

    def statement(self):
        kind = "quadratic" if self.n == 2 else "cubic"
        return (
            rf"A {kind} Bézier curve has the control points {_points_words(self.P)}. Compute "
            rf"the point $C(t)$ for $t = {_frac(self.t)}$ by de Casteljau's algorithm: replace "
            r"each pair of neighbours $P_i, P_{i+1}$ by $(1 - t)\,P_i + t\,P_{i+1}$, and repeat "
            r"on the new points until one point is left." "\n\n" + _POINT_2 + "\n\n"
            + data_note("P", "n", "t"))


class DeCasteljauLevel(_Points):
    r"""One level :math:`P_0^r, \dots, P_{n-r}^r` of de Casteljau's triangle for a cubic.

    Attributes: ``P``, ``t``, ``r`` (the level: 1 or 2).

    Examples
    --------
    >>> ex = DeCasteljauLevel(seed=4)
    >>> ex.r, ex.check(ex.expected).status
    (2, 'correct')
    >>> P, t = ex.P, ex.t
    >>> ex.check((1 - t) * P[:-2] + t * P[2:]).diagnosis     # P_i and P_{i+2} blended directly
    'skipped a level'
    """

    title = "One level of de Casteljau's triangle"
    what = "the list of points"
    may_coincide = ("t swapped", "midpoints")
    hint = (r"Level $r$ comes from level $r - 1$: "
            r"$P_i^r = (1 - t)\,P_i^{r-1} + t\,P_{i+1}^{r-1}$, starting from the control "
            r"points, level 0.")

    def draw(self, rng):
        self.P = _control_polygon(rng, 4)
        self.t = float(pick(rng, _T_VALUES))
        self.r = int(pick(rng, (1, 2)))
        _, self._levels = curves.de_casteljau(self.P, self.t, triangle=True)
        self.expected = self._levels[self.r]

    def mistakes(self):
        P, t, r = self.P, self.t, self.r
        _, swapped = curves.de_casteljau(P, 1 - t, triangle=True)
        _, halves = curves.de_casteljau(P, 0.5, triangle=True)
        found = [
            Mistake(swapped[r], r"$t$ and $1 - t$ are swapped. The first point of each pair "
                    r"gets $1 - t$: $P_i^r = (1 - t)\,P_i^{r-1} + t\,P_{i+1}^{r-1}$, so for "
                    r"small $t$ the new points stay near the first point of their edge.",
                    "t swapped"),
            Mistake(halves[r], r"You took midpoints, as in the pictures drawn for "
                    r"$t = \tfrac12$. Each edge is cut in the ratio $t : (1 - t)$: "
                    r"$P_i^r = (1 - t)\,P_i^{r-1} + t\,P_{i+1}^{r-1}$ with the given $t$.",
                    "midpoints"),
        ]
        if r == 2:
            found.append(Mistake((1 - t) * P[:-2] + t * P[2:], r"You interpolated between "
                                 r"control points two apart, $(1 - t)\,P_i + t\,P_{i+2}$, "
                                 r"skipping level 1. Each level is built from the level just "
                                 r"before it: first $P_i^1$ from the control points, then "
                                 r"$P_i^2 = (1 - t)\,P_i^1 + t\,P_{i+1}^1$.", "skipped a level"))
        return found

    def _shape_feedback(self, value):
        for level, points in enumerate(self._levels):
            if level != self.r and close(value, points):
                return Feedback("wrong", f"These are the points of level {level}; the question "
                                f"asks for level {self.r}, which has {4 - self.r} points "
                                r"(each level has one point fewer than the one before).",
                                "wrong level")
        return None

    def statement(self):
        count = 4 - self.r
        return (
            rf"A cubic Bézier curve has the control points {_points_words(self.P)}. De "
            r"Casteljau's algorithm for $t = " + _frac(self.t) + r"$ builds the levels "
            r"$P_i^0 = P_i$ and $P_i^r = (1 - t)\,P_i^{r-1} + t\,P_{i+1}^{r-1}$. Give level "
            rf"$r = {self.r}$, the {count} points "
            + ", ".join(rf"$P_{{{i}}}^{{{self.r}}}$" for i in range(count)) + "." "\n\n"
            rf"**Answer:** a ${count} \times 2$ array, one point per row, in the order "
            rf"$P_0^{{{self.r}}}, P_1^{{{self.r}}}, \dots$. " + DECIMALS + "\n\n"
            + data_note("P", "t", "r"))


class BernsteinValues(_Chapter7):
    r"""All Bernstein polynomials :math:`B_0^n(t), \dots, B_n^n(t)` at one parameter value.

    :math:`B_i^n(t) = \binom{n}{i} t^i (1 - t)^{n-i}`; they add up to 1.

    Attributes: ``n`` (the degree), ``t``.

    Examples
    --------
    >>> ex = BernsteinValues(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> i = np.arange(ex.n + 1)
    >>> ex.check(ex.t ** i * (1 - ex.t) ** (ex.n - i)).diagnosis
    'no binomial'
    """

    title = "Bernstein polynomials"
    answer_form = "vector"
    what = "the list of values"
    may_coincide = ("powers swapped",)

    def draw(self, rng):
        self.n = int(pick(rng, (2, 3, 4)))
        self.t = float(pick(rng, _T_VALUES))
        self.expected = curves.bernstein(self.n, None, self.t)

    def mistakes(self):
        n, t = self.n, self.t
        i = np.arange(n + 1)
        binom = np.array([math.comb(n, k) for k in i], dtype=float)
        return [
            Mistake(t ** i * (1 - t) ** (n - i), r"The binomial coefficients are missing: "
                    r"$B_i^n(t) = \binom{n}{i}\, t^i (1 - t)^{n-i}$. Without them the values do "
                    r"not add up to 1 (they come from expanding $(t + (1 - t))^n = 1$).",
                    "no binomial"),
            Mistake(binom * t ** (n - i) * (1 - t) ** i, r"The powers are swapped: $t$ carries "
                    r"the exponent $i$ and $1 - t$ the exponent $n - i$, so $B_0^n(t) = "
                    r"(1 - t)^n$ is the one that is 1 at $t = 0$. You computed "
                    r"$B_i^n(1 - t) = B_{n-i}^n(t)$, the list in reverse order.",
                    "powers swapped"),
        ]

    def _judge(self, answer):
        fb = super()._judge(answer)
        value = _floats_or_none(answer)
        if fb.status == "wrong" and fb.diagnosis in UNEXPLAINED and value is not None:
            total = float(np.sum(value))
            if abs(total - 1) > 1e-3:
                return Feedback("wrong", f"{fb.message} Your values add up to "
                                f"{_num(total)}, but the Bernstein polynomials of one degree "
                                r"always add up to 1: check each "
                                r"$\binom{n}{i}\, t^i (1 - t)^{n-i}$.", fb.diagnosis)
            return Feedback("wrong", f"{fb.message} Check each "
                            r"$\binom{n}{i}\, t^i (1 - t)^{n-i}$.", fb.diagnosis)
        return fb

    def statement(self):
        n = self.n
        return (
            rf"Compute the values of all Bernstein polynomials of degree $n = {n}$, "
            r"$B_i^n(t) = \binom{n}{i}\, t^i (1 - t)^{n-i}$, at $t = " + _frac(self.t) + "$."
            "\n\n" rf"**Answer:** a list of {n + 1} numbers "
            rf"`[B_0, B_1, ..., B_{n}]` (the value of $B_i^{n}$ at position $i$). "
            + DECIMALS + "\n\n" + data_note("n", "t"))


class BezierEndTangent(_Chapter7):
    r"""The derivative :math:`C'(0) = n\,(P_1 - P_0)` or :math:`C'(1) = n\,(P_n - P_{n-1})`.

    Attributes: ``P``, ``n``, ``end`` (0 or 1: which end).

    Examples
    --------
    >>> ex = BezierEndTangent(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected / ex.n).diagnosis                # the edge itself
    'missing factor n'
    """

    title = "The tangent at an end of a Bézier curve"
    answer_form = "vector"
    vector_like = True
    what = "the derivative"
    hint = (r"Differentiate $\sum_i B_i^n(t) P_i$: at $t = 0$ only $P_0$ and $P_1$ survive, "
            r"$C'(0) = n\,(P_1 - P_0)$, and at $t = 1$, $C'(1) = n\,(P_n - P_{n-1})$.")

    def draw(self, rng):
        self.n = int(pick(rng, (2, 3)))
        self.P = _control_polygon(rng, self.n + 1)
        self.end = int(pick(rng, (0, 1)))
        self.expected = curves.bezier_derivative(self.P, float(self.end))

    def mistakes(self):
        P, n = self.P, self.n
        edge = P[1] - P[0] if self.end == 0 else P[n] - P[n - 1]
        other = n * (P[n] - P[n - 1]) if self.end == 0 else n * (P[1] - P[0])
        found = [
            Mistake(edge, r"The direction is right, but the length is not: the derivative is "
                    r"the edge of the control polygon times the degree $n$, e.g. "
                    r"$C'(0) = n\,(P_1 - P_0)$ (differentiating $\binom{n}{1} t (1-t)^{n-1}$ "
                    r"brings out the $n$).", "missing factor n"),
            Mistake(-n * edge, r"The vector points backwards. The derivative points in the "
                    r"direction of travel, from the end point into the curve at $t = 0$ "
                    r"($n\,(P_1 - P_0)$) and from $P_{n-1}$ to $P_n$ at $t = 1$ "
                    r"($n\,(P_n - P_{n-1})$).", "reversed"),
            Mistake(-edge, r"Two slips: the vector points backwards and the factor $n$ is "
                    r"missing. The derivative at the start is $C'(0) = n\,(P_1 - P_0)$, at the "
                    r"end $C'(1) = n\,(P_n - P_{n-1})$: the degree times the edge, in the "
                    r"direction of travel.", "reversed, missing n"),
            Mistake(other, r"That is the derivative at the other end of the curve. At "
                    r"$t = 0$ the first edge counts, $n\,(P_1 - P_0)$; at $t = 1$ the last one, "
                    r"$n\,(P_n - P_{n-1})$.", "wrong end"),
        ]
        length = float(np.linalg.norm(self.expected))
        found.append(Mistake(self.expected / length, r"You normalised the vector. The question "
                             r"asks for the derivative $C'(t)$ itself, whose length is the "
                             r"speed of the parametrisation: $n$ times the length of the edge.",
                             "normalised"))
        return found

    def statement(self):
        kind = "quadratic" if self.n == 2 else "cubic"
        at = "start" if self.end == 0 else "end"
        return (
            rf"A {kind} Bézier curve has the control points {_points_words(self.P)}. Give the "
            rf"derivative $C'({self.end})$, the tangent vector at the {at} of the curve "
            r"(not normalised)." "\n\n"
            r"**Answer:** the vector as a list of 2 numbers `[dx, dy]`. " + DECIMALS + "\n\n"
            + data_note("P", "n", "end"))


class BezierSubdivision(_Points):
    r"""Subdivision at :math:`t`: the control points of the left part, :math:`P_0^0, \dots, P_0^n`.

    The first points of the levels of de Casteljau's triangle are the control polygon of the
    curve on :math:`[0, t]`.

    Attributes: ``P``, ``n``, ``t``.

    Examples
    --------
    >>> ex = BezierSubdivision(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'reversed order'
    """

    title = "Subdividing a Bézier curve"
    what = "the left control polygon"
    may_coincide = ("t swapped",)
    hint = (r"Run de Casteljau's triangle for $t$ and take the **first** point of every level: "
            r"$P_0^0 = P_0, P_0^1, \dots, P_0^n = C(t)$.")

    def draw(self, rng):
        self.n = int(pick(rng, (2, 3)))
        self.P = _control_polygon(rng, self.n + 1)
        self.t = float(pick(rng, _T_VALUES))
        self.expected, self._right = curves.bezier_subdivide(self.P, self.t)

    def mistakes(self):
        right_words = (r"These are the control points of the **right** part (the curve on "
                       r"$[t, 1]$), made of the *last* points of the levels. The left part, on "
                       r"$[0, t]$, starts at $P_0$: take the *first* point of each level, "
                       r"$P_0^0, P_0^1, \dots, P_0^n$.")
        return [
            Mistake(self._right, right_words, "right part"),
            Mistake(self._right[::-1], right_words, "right part"),
            Mistake(self.expected[::-1], r"The points are right but in reverse order. The "
                    r"left part runs from $P_0$ (at $t = 0$) to $C(t)$: list them as "
                    r"$P_0^0, P_0^1, \dots, P_0^n$.", "reversed order"),
            Mistake(curves.bezier_subdivide(self.P, 1 - self.t)[0], r"$t$ and $1 - t$ are "
                    r"swapped in the interpolations: each new point is "
                    r"$(1 - t)\,P_i + t\,P_{i+1}$, the first point weighted by $1 - t$.",
                    "t swapped"),
        ]

    def statement(self):
        kind = "quadratic" if self.n == 2 else "cubic"
        n = self.n
        return (
            rf"A {kind} Bézier curve has the control points {_points_words(self.P)}. It is "
            r"split at $t = " + _frac(self.t) + r"$ into two Bézier curves of the same degree. "
            r"Give the control points of the **left** part, the one that traces the original "
            r"curve for parameters from 0 to $t$." "\n\n"
            rf"**Answer:** a ${n + 1} \times 2$ array, one control point per row, starting with "
            r"the one at the start of the curve. " + DECIMALS + "\n\n"
            + data_note("P", "n", "t"))


class DegreeElevation(_Points):
    r"""Degree elevation: the :math:`n + 2` control points of the same curve one degree up.

    :math:`Q_0 = P_0`, :math:`Q_{n+1} = P_n` and
    :math:`Q_i = \frac{i}{n+1} P_{i-1} + \left(1 - \frac{i}{n+1}\right) P_i`.

    Attributes: ``P``, ``n`` (the degree before elevation).

    Examples
    --------
    >>> ex = DegreeElevation(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> P = ex.P
    >>> midpoints = np.vstack([P[:1], (P[:-1] + P[1:]) / 2, P[-1:]])
    >>> ex.check(midpoints).diagnosis
    'midpoints'
    """

    title = "Degree elevation of a Bézier curve"
    what = "the new control polygon"
    hint = (r"Use $Q_i = \frac{i}{n+1}\,P_{i-1} + \left(1 - \frac{i}{n+1}\right) P_i$ for "
            r"$i = 0, \dots, n + 1$ (with $n$ the old degree).")

    def draw(self, rng):
        self.n = int(pick(rng, (2, 3)))
        self.P = _control_polygon(rng, self.n + 1)
        self.expected = curves.bezier_elevate(self.P)

    def _blend(self, a):
        P = self.P
        inner = a[:, None] * P[:-1] + (1 - a[:, None]) * P[1:]
        return np.vstack([P[:1], inner, P[-1:]])

    def mistakes(self):
        n = self.n
        a = np.arange(1, n + 1) / (n + 1)
        return [
            Mistake(self._blend(1 - a), r"The weights are swapped: $Q_i$ takes "
                    r"$\frac{i}{n+1}$ of the **previous** point $P_{i-1}$ and "
                    r"$1 - \frac{i}{n+1}$ of $P_i$. Check with $i = 1$: $Q_1$ must lie close "
                    r"to $P_0$, a fraction $\frac{1}{n+1}$ of the way towards $P_1$.",
                    "weights swapped"),
            Mistake(self._blend(np.full(n, 0.5)), r"Midpoints of the edges do not give the "
                    r"same curve (except for a line). The new points cut each edge in a "
                    r"different ratio: $Q_i = \frac{i}{n+1}\,P_{i-1} + \left(1 - "
                    r"\frac{i}{n+1}\right) P_i$.", "midpoints"),
            Mistake(self._blend(np.arange(1, n + 1) / n), r"You divided by the old degree "
                    r"$n$; the weights use the **new** degree $n + 1$: "
                    r"$Q_i = \frac{i}{n+1}\,P_{i-1} + \left(1 - \frac{i}{n+1}\right) P_i$.",
                    "divided by n"),
        ]

    def _shape_feedback(self, value):
        if value.shape == self.P.shape:
            return Feedback("wrong", f"You gave {len(value)} points, as many as the curve "
                            f"had. Raising the degree from {self.n} to {self.n + 1} needs one "
                            f"control point more: {self.n + 2} in all, the end points kept.",
                            "not elevated")
        return None

    def statement(self):
        n = self.n
        return (
            rf"A Bézier curve of degree {n} has the control points {_points_words(self.P)}. "
            rf"Write the same curve as a Bézier curve of degree {n + 1}: give its "
            rf"{n + 2} control points $Q_0, \dots, Q_{{{n + 1}}}$." "\n\n"
            rf"**Answer:** a ${n + 2} \times 2$ array, one control point per row, "
            r"$Q_0$ first. " + DECIMALS + "\n\n" + data_note("P", "n"))


# ---------------------------------------------------------------------------------------------
# B-splines
# ---------------------------------------------------------------------------------------------

class ClampedKnotVector(_Chapter7):
    r"""The clamped knot vector on :math:`[0, 1]` for a given number of control points and degree.

    :math:`p + 1` zeros, the :math:`N - p - 1` interior knots :math:`\frac{1}{N-p}, \dots,
    \frac{N-p-1}{N-p}`, :math:`p + 1` ones: :math:`N + p + 1` knots for :math:`N` control
    points.

    Attributes: ``n_control`` (N), ``p`` (the degree).

    Examples
    --------
    >>> ex = ClampedKnotVector(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[1:-1]).diagnosis               # p copies of each end knot
    'p copies at the ends'
    """

    title = "A clamped knot vector"
    answer_form = "custom"
    what = "the knot vector"

    def draw(self, rng):
        self.p = int(pick(rng, (2, 3)))
        self.n_control = self.p + int(pick(rng, (2, 3, 4)))
        self.expected = curves.clamped_knots(self.n_control, self.p)

    def _judge(self, answer):
        N, p = self.n_control, self.p
        want = N + p + 1
        if is_unanswered(answer):
            return Feedback("unanswered", UNANSWERED)
        value = _floats_or_none(answer)
        if value is None or value.ndim != 1 or len(value) < 2 or not np.isfinite(value).all():
            return Feedback("invalid", "Give the knot vector as a list of numbers, e.g. "
                            "`[0, 0, 0.5, 1, 1]`.", "unreadable")
        if close(value, self.expected):
            return Feedback("correct", f"The knot vector is right: {want} knots, the ends "
                            f"repeated {p + 1} times.")
        if np.any(np.diff(value) < -1e-9):
            return Feedback("wrong", "The knots must never decrease: a knot vector is a "
                            "non-decreasing sequence.", "decreasing")
        first = int(np.sum(np.isclose(value, value[0], atol=1e-9)))
        last = int(np.sum(np.isclose(value, value[-1], atol=1e-9)))
        count = (f" With {N} control points and degree {p} there are "
                 f"$N + p + 1 = {N} + {p} + 1 = {want}$ knots.")
        if first == p and last == p:
            return Feedback("wrong", f"The end knots appear {p} times each; a clamped knot "
                            f"vector repeats them $p + 1 = {p + 1}$ times. Then the first "
                            "basis function is 1 at the start (the curve begins at $P_0$) and "
                            "the last one is 1 at the end." + count, "p copies at the ends")
        if first == 1 and last == 1:
            return Feedback("wrong", "The end knots are not repeated: that is an unclamped "
                            f"(uniform) knot vector, whose curve starts and ends inside the "
                            f"control polygon. Clamping repeats each end knot $p + 1 = {p + 1}$ "
                            "times." + count, "not clamped")
        if first != p + 1 or last != p + 1:
            return Feedback("wrong", f"Your first knot appears {first} times and your last "
                            f"{last} times; a clamped knot vector repeats each end knot "
                            f"$p + 1 = {p + 1}$ times." + count, "end multiplicity")
        if len(value) == want - 1:
            return Feedback("wrong", f"You gave {len(value)} knots, one too few: the count is "
                            "the number of control points plus the degree plus one (with "
                            "control points $P_0, \\dots, P_n$: $n + p + 2$)." + count,
                            "one knot short")
        if len(value) == want + 1:
            return Feedback("wrong", f"You gave {len(value)} knots, one too many: the count is "
                            "the number of control points plus the degree plus one (with "
                            "control points $P_0, \\dots, P_n$: $n + p + 2$)." + count,
                            "one knot too many")
        if len(value) != want:
            return Feedback("wrong", f"You gave {len(value)} knots." + count, "wrong count")
        scale = value[-1] - value[0]
        if scale > 0 and close((value - value[0]) / scale, self.expected):
            return Feedback("wrong", "The pattern is right, but your knots run from "
                            f"{_num(value[0])} to {_num(value[-1])}, and the question asks for "
                            "the domain $[0, 1]$. (Shifting and scaling all knots alike gives "
                            "the same curve, an affine reparametrisation, but the answer asked "
                            "for is the one on $[0, 1]$: subtract the first knot and divide by "
                            "the length of the range.)", "not normalised")
        return Feedback("wrong", f"The ends are right but the interior knots are not: there "
                        f"are $N - p - 1 = {N - p - 1}$ of them, spaced evenly, "
                        f"$\\frac{{1}}{{{N - p}}}, \\dots, \\frac{{{N - p - 1}}}{{{N - p}}}$, "
                        "so that all knot spans have the same length.", "interior knots")

    def statement(self):
        N, p = self.n_control, self.p
        return (
            rf"A B-spline curve of degree $p = {p}$ has $N = {N}$ control points "
            rf"$P_0, \dots, P_{{{N - 1}}}$. Give its **clamped** knot vector on the domain "
            r"$[0, 1]$: the end knots repeated so that the curve starts at $P_0$ and ends at "
            rf"$P_{{{N - 1}}}$, and the interior knots evenly spaced." "\n\n"
            r"**Answer:** the knots as a list of numbers, in non-decreasing order. "
            + DECIMALS + "\n\n" + data_note("n_control", "p"))


class CoxDeBoorBasis(_Chapter7):
    r"""All B-spline basis functions :math:`N_{i,p}(t)` at one t, by the Cox-de Boor recursion.

    Attributes: ``knots``, ``p``, ``n_control``, ``t``.

    Examples
    --------
    >>> ex = CoxDeBoorBasis(seed=8)
    >>> ex.check(ex.expected).status
    'correct'
    >>> shifted = np.append(ex.expected[1:], 0)              # N_{i+1,p} written as N_{i,p}
    >>> ex.check(shifted).diagnosis
    'index shift'
    >>> with np.errstate(all="ignore"):
    ...     broken = ex.expected * np.array(0.0) / 0.0         # NaN: a 0/0 left in
    >>> ex.check(broken).diagnosis
    'zero denominator'
    """

    title = "B-spline basis functions by Cox-de Boor"
    answer_form = "vector"
    what = "the list of values"
    hint = (r"Start with $N_{i,0}(t) = 1$ on the span that contains $t$ and 0 elsewhere, then "
            r"apply the recursion degree by degree; at every degree the values add up to 1 "
            r"inside the domain.")

    def draw(self, rng):
        self.p = int(pick(rng, (1, 2, 2, 3)))
        self.n_control = self.p + int(pick(rng, (2, 3)))
        self.knots = _integer_knots(rng, self.n_control, self.p)
        self.t = _inside_span(rng, self.knots, self.p)
        self.expected = curves.bspline_basis(self.knots, self.p, self.t)
        self._lower = _cox_de_boor_levels(self.knots, self.p, self.t)[self.p - 1]

    def mistakes(self):
        e = self.expected
        shift = (r"Your values are in the wrong places: the index is off by one. "
                 r"$N_{i,p}$ is non-zero on $[u_i, u_{i+p+1})$, so at $t$ in the span "
                 r"$[u_k, u_{k+1})$ the non-zero ones are $N_{k-p,p}, \dots, N_{k,p}$; "
                 r"position $i$ of the list holds $N_{i,p}(t)$, counted from 0.")
        even = curves.bspline_basis(_even_knots(self.knots, self.p), self.p, self.t)
        return [
            Mistake(np.append(e[1:], 0.0), shift, "index shift"),
            Mistake(np.insert(e[:-1], 0, 0.0), shift, "index shift"),
            Mistake(even, r"These are the values for evenly spaced knots (a uniform knot "
                    r"vector over the same domain). The recursion must use the given knots, "
                    r"repeated end knots included: $u_i$ in the formula is entry $i$ of "
                    r"$U$, counted from 0.", "uniform knots"),
        ]

    def _judge(self, answer):
        value = _floats_or_none(answer)
        if value is not None and value.shape == self.expected.shape \
                and not np.isfinite(value).all():
            return Feedback("wrong", r"Your list contains NaN or infinity: a fraction with a "
                            r"zero denominator was evaluated. Repeated knots make "
                            r"$u_{i+p} - u_i = 0$; in the Cox-de Boor recursion such a term "
                            r"counts as 0 (its basis function of lower degree vanishes "
                            r"anyway). Skip those terms.", "zero denominator")
        if value is not None and close(value, self._lower):
            return Feedback("wrong", rf"These are the {len(value)} functions of degree "
                            rf"$p - 1 = {self.p - 1}$. One more round of the recursion gives "
                            rf"the {self.n_control} functions of degree {self.p}.",
                            "one degree short")
        return super()._judge(answer)

    def statement(self):
        p, N = self.p, self.n_control
        return (
            rf"A B-spline of degree $p = {p}$ with $N = {N}$ control points has "
            + _knots_words(self.knots) + r" (entries $u_0, u_1, \dots$, counted from 0). "
            r"The basis functions follow the Cox-de Boor recursion" "\n\n"
            r"$$N_{i,0}(t) = \begin{cases} 1 & u_i \le t < u_{i+1} \\ 0 & \text{otherwise}"
            r"\end{cases}, \qquad N_{i,r}(t) = \frac{t - u_i}{u_{i+r} - u_i}\,N_{i,r-1}(t) + "
            r"\frac{u_{i+r+1} - t}{u_{i+r+1} - u_{i+1}}\,N_{i+1,r-1}(t),$$" "\n\n"
            r"where a fraction with a zero denominator counts as 0. Compute "
            rf"$N_{{0,{p}}}(t), \dots, N_{{{N - 1},{p}}}(t)$ at $t = {_num(self.t)}$." "\n\n"
            rf"**Answer:** a list of {N} numbers, $N_{{i,{p}}}(t)$ at position $i$. "
            + DECIMALS + "\n\n" + data_note("knots", "p", "n_control", "t"))


class BasisSupport(_Chapter7):
    r"""The support :math:`[u_i, u_{i+p+1}]` of one B-spline basis function :math:`N_{i,p}`.

    Attributes: ``knots``, ``p``, ``i``.

    Examples
    --------
    >>> ex = BasisSupport(seed=9)
    >>> ex.check(ex.expected).status
    'correct'
    >>> u, i, p = ex.knots, ex.i, ex.p
    >>> ex.check([u[i], u[i + p]]).diagnosis
    'one span short'
    """

    title = "Where a basis function is non-zero"
    answer_form = "vector"
    what = "the interval"
    hint = (r"$N_{i,p}$ is built from $N_{i,0}, \dots, N_{i+p,0}$, the indicators of the "
            r"$p + 1$ spans from $u_i$ to $u_{i+p+1}$.")

    def draw(self, rng):
        self.p = int(pick(rng, (1, 2, 3)))
        n_control = self.p + int(pick(rng, (3, 4)))
        self.knots = _integer_knots(rng, n_control, self.p)
        self.i = int(rng.integers(0, n_control))
        u, i, p = self.knots, self.i, self.p
        self.expected = np.array([u[i], u[i + p + 1]])

    def acceptable(self):
        u, i, p = self.knots, self.i, self.p
        return u[i] != u[0] or u[i + p + 1] != u[-1]        # not the whole domain

    def mistakes(self):
        u, i, p = self.knots, self.i, self.p
        found = [
            Mistake([u[i], u[i + p]], r"One span short: $N_{i,p}$ covers $p + 1$ knot spans, "
                    r"from $u_i$ to $u_{i+p+1}$ (a function of degree 0 covers one span, each "
                    r"degree adds one).", "one span short"),
            Mistake([i, i + p + 1], r"You gave the knot **indices**; the interval is made of "
                    r"the knot **values** $u_i$ and $u_{i+p+1}$ (look them up in $U$, counting "
                    r"from 0).", "indices, not knots"),
        ]
        if i + p + 2 < len(u):
            found.append(Mistake([u[i], u[i + p + 2]], r"One span too many: $N_{i,p}$ covers "
                                 r"$p + 1$ knot spans, from $u_i$ to $u_{i+p+1}$.",
                                 "one span too many"))
        if i >= p:
            found.append(Mistake([u[i - p], u[i + 1]], r"That interval ends at $u_{i+1}$: it "
                                 r"is where the basis functions active on the span "
                                 r"$[u_i, u_{i+1})$ live, counted backwards. $N_{i,p}$ itself "
                                 r"starts at $u_i$ and reaches forward to $u_{i+p+1}$.",
                                 "backwards"))
        return found

    def statement(self):
        p, i = self.p, self.i
        return (
            rf"A B-spline of degree $p = {p}$ has " + _knots_words(self.knots)
            + r" (entries $u_0, u_1, \dots$, counted from 0). On which interval is the basis "
            rf"function $N_{{{i},{p}}}$ non-zero? Give the interval's start and end "
            r"(the closure of the set where it is non-zero)." "\n\n"
            r"**Answer:** a list of 2 numbers `[start, end]`." "\n\n"
            + data_note("knots", "p", "i"))


def _read_indices(answer, n):
    """A set of indices 0..n-1 from a list of whole numbers, or a Feedback."""
    if has_placeholder(answer):
        return Feedback("unanswered", UNANSWERED)
    form = "Give the indices as a list of whole numbers, e.g. `[1, 2, 3]`."
    if isinstance(answer, (str, bytes, dict)):
        return Feedback("invalid", form, "unreadable")
    try:
        items = list(np.asarray(answer, dtype=object).ravel()) \
            if isinstance(answer, np.ndarray) else list(answer)
    except TypeError:
        return Feedback("invalid", form, "unreadable")
    found = set()
    for item in items:
        if isinstance(item, (bool, np.bool_)) or not isinstance(
                item, (int, np.integer, float, np.floating)):
            return Feedback("invalid", form, "unreadable")
        if not float(item).is_integer() or not 0 <= item < n:
            return Feedback("invalid", f"{item!r} is not one of the indices 0 to {n - 1}.",
                            "unreadable")
        found.add(int(item))
    return found


def _listed(indices):
    return ", ".join(str(i) for i in sorted(indices)) or "none"


class ActiveControlPoints(_Chapter7):
    r"""The control points that shape a B-spline curve at t: :math:`P_{k-p}, \dots, P_k`.

    With :math:`t \in [u_k, u_{k+1})`, only :math:`N_{k-p,p}, \dots, N_{k,p}` are non-zero
    there (local control).

    Attributes: ``knots``, ``p``, ``n_control``, ``t``.

    Examples
    --------
    >>> ex = ActiveControlPoints(seed=10)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> ex.check(list(range(ex.n_control))).diagnosis
    'global control'
    >>> ex.check(...).status, ex.check("all").status
    ('unanswered', 'invalid')
    """

    title = "Which control points matter at t"
    answer_form = "custom"

    def draw(self, rng):
        self.p = int(pick(rng, (1, 2, 3)))
        self.n_control = self.p + int(pick(rng, (3, 4, 5)))
        self.knots = _integer_knots(rng, self.n_control, self.p)
        self.t = _inside_span(rng, self.knots, self.p)
        self.span = curves.find_span(self.knots, self.p, self.t)
        k, p = self.span, self.p
        self.expected = set(range(k - p, k + 1))

    def mistakes(self):
        k, p, N = self.span, self.p, self.n_control
        shifted = (r"Off by one: with $t$ in the span $[u_k, u_{k+1})$ the active control "
                   r"points are $P_{k-p}, \dots, P_k$ (the basis function $N_{i,p}$ is "
                   r"non-zero on $[u_i, u_{i+p+1})$, so it covers the span $k$ exactly when "
                   r"$k - p \le i \le k$).")
        few = (r"One control point is missing: a B-spline of degree $p$ has $p + 1$ active "
               r"control points on every knot span, $P_{k-p}, \dots, P_k$ for the span "
               r"$[u_k, u_{k+1})$.")
        many = (r"One control point too many: exactly $p + 1$ control points act on a knot "
                r"span, $P_{k-p}, \dots, P_k$ for $t \in [u_k, u_{k+1})$.")
        candidates = [
            Mistake(set(range(k - p + 1, k + 2)), shifted, "off by one", numeric=False),
            Mistake(set(range(k - p - 1, k)), shifted, "off by one", numeric=False),
            Mistake(set(range(k - p + 1, k + 1)), few, "one too few", numeric=False),
            Mistake(set(range(k - p, k)), few, "one too few", numeric=False),
            Mistake(set(range(k - p - 1, k + 1)), many, "one too many", numeric=False),
            Mistake(set(range(k - p, k + 2)), many, "one too many", numeric=False),
            Mistake(set(range(N)), r"That is every control point: the Bézier way of thinking "
                    r"(pseudo-local control). A B-spline has **local** control: each basis "
                    r"function is non-zero on $p + 1$ spans only, so at one $t$ just $p + 1$ "
                    r"control points act, $P_{k-p}, \dots, P_k$ for $t \in [u_k, u_{k+1})$.",
                    "global control", numeric=False),
        ]
        return [m for m in candidates if min(m.value) >= 0 and max(m.value) < N]

    def keep(self, mistakes):
        return [m for m in mistakes if m.value != self.expected]

    def separated(self, mistakes):
        return len(self.expected) < self.n_control

    def _judge(self, answer):
        value = _read_indices(answer, self.n_control)
        if isinstance(value, Feedback):
            return value
        if value == self.expected:
            return Feedback("correct", f"Exactly these {self.p + 1} control points shape the "
                            "curve at this t.")
        for mistake in self._mistakes:
            if value == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        missing, extra = sorted(self.expected - value), sorted(value - self.expected)
        parts = []
        if extra:
            parts.append(f"{_listed(extra)} should not be in it")
        if missing:
            parts.append(f"{_listed(missing)} {'is' if len(missing) == 1 else 'are'} missing")
        return Feedback("wrong", f"Your list is not right yet: {', and '.join(parts)}. Find "
                        r"the span "
                        r"$[u_k, u_{k+1})$ that contains $t$; the active control points are "
                        r"$P_{k-p}, \dots, P_k$.", "indices differ")

    def statement(self):
        p, N = self.p, self.n_control
        return (
            rf"A B-spline curve of degree $p = {p}$ has $N = {N}$ control points "
            rf"$P_0, \dots, P_{{{N - 1}}}$ and " + _knots_words(self.knots)
            + r" (entries $u_0, u_1, \dots$, counted from 0). Which control points influence "
            rf"the curve point $C(t)$ at $t = {_num(self.t)}$, i.e. which $P_i$ have "
            r"$N_{i,p}(t) \ne 0$?" "\n\n"
            r"**Answer:** the list of their indices $i$, e.g. `[1, 2, 3]` (the order does not "
            r"matter)." "\n\n" + data_note("knots", "p", "n_control", "t"))


class BSplinePoint(_Chapter7):
    r"""A point of a B-spline curve with whole-number knots, by de Boor's algorithm.

    Attributes: ``P``, ``knots``, ``p``, ``t``.

    Examples
    --------
    >>> ex = BSplinePoint(seed=11)
    >>> ex.check(ex.expected).status
    'correct'
    >>> a, b = ex.knots[ex.p], ex.knots[len(ex.P)]
    >>> ex.check(curves.bezier(ex.P, (ex.t - a) / (b - a))).diagnosis
    'Bézier curve'
    """

    title = "A B-spline point by de Boor's algorithm"
    answer_form = "point"
    what = "the curve point"
    hint = (r"Find the span $[u_k, u_{k+1})$ of $t$, start from $P_{k-p}, \dots, P_k$ and "
            r"blend $p$ times with $\alpha_i = \frac{t - u_i}{u_{i+p+1-r} - u_i}$ (or add up "
            r"$N_{i,p}(t)\,P_i$ with the Cox-de Boor values).")

    def draw(self, rng):
        self.p = int(pick(rng, (2, 2, 3)))
        n_control = self.p + int(pick(rng, (2, 3)))
        self.P = _control_polygon(rng, n_control)
        self.knots = _integer_knots(rng, n_control, self.p)
        self.t = _inside_span(rng, self.knots, self.p)
        self.expected = curves.bspline(self.P, self.knots, self.p, self.t)

    def mistakes(self):
        P, u, p, t = self.P, self.knots, self.p, self.t
        n_control = len(P)
        a, b = u[p], u[n_control]
        k = curves.find_span(u, p, t)
        local = (t - u[k]) / (u[k + 1] - u[k])
        return [
            Mistake(curves.bezier(P, (t - a) / (b - a)), r"You evaluated the Bézier curve of "
                    r"all the control points (at the same fraction of the domain). A B-spline "
                    r"blends them with the B-spline basis functions of its knots, not with "
                    r"Bernstein polynomials, and only $p + 1$ of them act at each $t$.",
                    "Bézier curve"),
            Mistake(curves.bspline(P, _even_knots(u, p), p, t), r"This is the point for evenly "
                    r"spaced knots (a uniform knot vector over the same domain). Use the given "
                    r"knots, repeated end knots included, in the ratios "
                    r"$\alpha = \frac{t - u_i}{u_{i+p+1-r} - u_i}$.", "uniform knots"),
            Mistake(curves.bezier(P[k - p:k + 1], local), r"You took the right $p + 1$ "
                    r"control points but blended them like a Bézier curve, with the local "
                    r"parameter of the span. That works only for a knot vector like "
                    r"$(0, \dots, 0, 1, \dots, 1)$; in general de Boor's ratios "
                    r"$\alpha_i = \frac{t - u_i}{u_{i+p+1-r} - u_i}$ change from point to "
                    r"point and from level to level.", "local Bézier"),
        ]

    def statement(self):
        p, N = self.p, len(self.P)
        return (
            rf"A B-spline curve of degree $p = {p}$ has the control points "
            f"{_points_words(self.P)} and " + _knots_words(self.knots)
            + r" (entries $u_0, u_1, \dots$, counted from 0). Compute the curve point "
            rf"$C(t) = \sum_{{i=0}}^{{{N - 1}}} N_{{i,{p}}}(t)\,P_i$ at $t = {_num(self.t)}$ "
            r"(by de Boor's algorithm, or with the basis functions)." "\n\n" + _POINT_2
            + "\n\n" + data_note("P", "knots", "p", "t"))


# ---------------------------------------------------------------------------------------------
# Rational curves
# ---------------------------------------------------------------------------------------------

class RationalBezierPoint(_Chapter7):
    r"""A point of a rational quadratic Bézier curve with given weights.

    :math:`C(t) = \frac{\sum_i B_i^2(t)\, w_i P_i}{\sum_i B_i^2(t)\, w_i}`.

    Attributes: ``P``, ``w`` (the weights), ``t``.

    Examples
    --------
    >>> ex = RationalBezierPoint(seed=12)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(curves.bezier(ex.P, ex.t)).diagnosis         # weights left out
    'weights ignored'
    """

    title = "A point of a rational Bézier curve"
    answer_form = "point"
    what = "the curve point"
    hint = (r"Weight each control point, $w_i P_i$, blend with the Bernstein polynomials, and "
            r"divide by $\sum_i B_i^2(t)\, w_i$, the same blend of the weights alone.")

    def draw(self, rng):
        self.P = _control_polygon(rng, 3)
        self.w = np.array([float(pick(rng, (1, 1, 2))), float(pick(rng, (0.5, 2, 3, 4))),
                           float(pick(rng, (1, 1, 2)))])
        self.t = float(pick(rng, _T_VALUES))
        self.expected = curves.rational_bezier(self.P, self.w, self.t)

    def mistakes(self):
        P, w, t = self.P, self.w, self.t
        b = curves.bernstein(2, None, t)
        numerator = (b * w) @ P
        return [
            Mistake(numerator, r"You forgot the division. The weighted blend "
                    r"$\sum_i B_i^2(t)\, w_i P_i$ is the homogeneous point; divide it by "
                    r"$\sum_i B_i^2(t)\, w_i$, so that the blending functions add up to 1 "
                    r"again.", "no division"),
            Mistake((b @ P) / (b @ w), r"You weighted the denominator only. The weights go "
                    r"into both sums: $\frac{\sum_i B_i^2(t)\, w_i P_i}"
                    r"{\sum_i B_i^2(t)\, w_i}$.", "numerator unweighted"),
            Mistake(numerator / w.sum(), r"You divided by the sum of the weights, "
                    r"$\sum_i w_i$. The denominator is the weights blended like the points, "
                    r"$\sum_i B_i^2(t)\, w_i$, which depends on $t$.",
                    "divided by the sum of weights"),
            Mistake(b @ P, r"That is the ordinary (non-rational) Bézier curve: the weights are "
                    r"left out. A weight above 1 pulls the curve towards its control point: "
                    r"$C(t) = \frac{\sum_i B_i^2(t)\, w_i P_i}{\sum_i B_i^2(t)\, w_i}$.",
                    "weights ignored"),
        ]

    def statement(self):
        return (
            rf"A rational quadratic Bézier curve has the control points "
            rf"{_points_words(self.P)} with the weights $w_0 = {_num(self.w[0])}$, "
            rf"$w_1 = {_num(self.w[1])}$, $w_2 = {_num(self.w[2])}$:" "\n\n"
            r"$$C(t) = \frac{\sum_{i=0}^{2} B_i^2(t)\, w_i P_i}{\sum_{i=0}^{2} B_i^2(t)\, w_i}.$$"
            "\n\n" rf"Compute the point $C(t)$ at $t = {_frac(self.t)}$." "\n\n" + _POINT_2
            + "\n\n" + data_note("P", "w", "t"))


def _conic_point(p0, p1, p2, w, t):
    """The rational quadratic with weights (1, w, 1) at t, for any w (no checks)."""
    b = np.array([(1 - t) ** 2, 2 * t * (1 - t) * w, t ** 2])
    return (b[0] * p0 + b[1] * p1 + b[2] * p2) / b.sum()


class CircleArc(_Chapter7):
    r"""A circular arc as a rational quadratic Bézier curve: its middle weight and midpoint.

    For an arc of opening angle :math:`\theta`, with :math:`P_1` where the end tangents meet,
    the weights :math:`(1, \cos\frac{\theta}{2}, 1)` give exactly the arc; :math:`C(\frac12)`
    is the arc's midpoint.

    Attributes: ``center``, ``radius``, ``theta_deg``, ``theta`` (radians), ``alpha_deg`` (the
    start angle), ``P0``, ``P1``, ``P2``.

    Examples
    --------
    >>> ex = CircleArc(seed=13)
    >>> ex.check(ex.expected).status
    'correct'
    >>> w, x, y = ex.expected
    >>> ex.check([np.cos(ex.theta), x, y]).diagnosis          # the whole angle
    'full angle'
    """

    title = "The circle as a rational quadratic"
    answer_form = "custom"

    def draw(self, rng):
        self.theta_deg = int(pick(rng, (60, 90, 120)))
        self.theta = math.radians(self.theta_deg)
        self.radius = float(pick(rng, (1, 2, 3)))
        self.center = rng.integers(-2, 3, size=2).astype(float)
        middle = int(pick(rng, (0, 90, 180, 270)))
        self.alpha_deg = middle - self.theta_deg // 2
        a, half = math.radians(self.alpha_deg), self.theta / 2
        c, r = self.center, self.radius

        def on_circle(angle, distance=r):
            return np.round(c + distance * np.array([math.cos(angle), math.sin(angle)]), 15)

        self.P0 = on_circle(a)
        self.P2 = on_circle(a + self.theta)
        self.P1 = on_circle(a + half, r / math.cos(half))
        w = math.cos(half)
        point = curves.rational_quadratic_conic(self.P0, self.P1, self.P2, w, 0.5)
        self.expected = np.array([w, *point])

    def _parts(self):
        w, x, y = self.expected
        half = self.theta / 2
        slips = {
            "sin": (math.sin(half), r"You used the sine. For an arc of opening angle "
                    r"$\theta$ the middle weight is $w = \cos\frac{\theta}{2}$, the cosine of "
                    r"the angle between the chord $P_0P_2$ and the tangent at $P_0$ (it is "
                    r"also $\lvert MP_0 \rvert / \lvert MP_1 \rvert$, centre $M$)."),
            "full angle": (math.cos(self.theta), r"You used the whole opening angle. The "
                           r"weight is the cosine of **half** of it, "
                           r"$w = \cos\frac{\theta}{2}$ (for a quarter circle "
                           r"$\cos 45^\circ = \frac{\sqrt2}{2}$)."),
            "degrees": (math.cos(math.degrees(half)), r"You fed degrees to a cosine that "
                        r"expects radians: use `np.cos(np.radians(...))`, or the attribute "
                        r"`.theta`, which is in radians."),
            "parabola": (1.0, r"With $w = 1$ the curve is an ordinary quadratic Bézier curve, "
                         r"an arc of a **parabola**; it cannot be a circle. A circle needs "
                         r"$w = \cos\frac{\theta}{2} < 1$ (an ellipse-type weight)."),
        }
        if self.theta_deg == 90:
            del slips["sin"]                 # sin 45° = cos 45°: no slip to see
        no_division = (r"You forgot the division by $\sum_i B_i^2(\tfrac12)\, w_i = "
                       r"\frac{1 + w}{2}$: $C(\tfrac12) = \frac{P_0 + 2w P_1 + P_2}{2 + 2w}$.")
        point_slips = {key: _conic_point(self.P0, self.P1, self.P2, value, 0.5)
                       for key, (value, _) in slips.items()}
        numerator = (self.P0 + 2 * w * self.P1 + self.P2) / 4
        parts = [("the weight w", w, [Mistake(value, text, key)
                                      for key, (value, text) in slips.items()])]
        for axis, name in enumerate(("x", "y")):
            mistakes = [Mistake(point_slips[key][axis], "The point is computed with that "
                                "weight. " + text, key) for key, (_, text) in slips.items()]
            mistakes.append(Mistake(numerator[axis], no_division, "no division"))
            parts.append((f"{name} of C(1/2)", [x, y][axis], mistakes))
        return parts

    def mistakes(self):
        return []

    def separated(self, mistakes):
        return parts_separated(self._parts())

    def _judge(self, answer):
        return diagnose_parts(answer, self._parts(), "your answer", "`[w, x, y]`.",
                              r"Use $w = \cos\frac{\theta}{2}$ and "
                              r"$C(\tfrac12) = \frac{P_0 + 2w P_1 + P_2}{2 + 2w}$; the result "
                              r"must lie on the circle, half-way along the arc.")

    def statement(self):
        c, r = self.center, self.radius
        a, th = self.alpha_deg, self.theta_deg
        return (
            rf"An arc of the circle with centre $M = {_vec(c)}$ and radius $r = {_num(r)}$ runs "
            rf"counter-clockwise from the angle ${a}^\circ$ to ${a + th}^\circ$: its opening "
            rf"angle is $\theta = {th}^\circ$. Its end points are $P_0 = {_vec(self.P0)}$ and "
            rf"$P_2 = {_vec(self.P2)}$, and the tangents there meet at "
            rf"$P_1 = {_vec(self.P1)}$ (rounded; the attributes hold exact values). The arc is "
            r"the rational quadratic Bézier curve with control points $P_0, P_1, P_2$ and the "
            r"weights $(1, w, 1)$." "\n\n"
            r"Give (1) the weight $w$ that makes the curve exactly this arc, and (2) the curve "
            r"point $C(\tfrac12)$." "\n\n"
            r"**Answer:** a list of 3 numbers `[w, x, y]`, with $(x, y) = C(\tfrac12)$. "
            + DECIMALS + "\n\n"
            + data_note("center", "radius", "theta_deg", "theta", "alpha_deg", "P0", "P1", "P2")
            + " (`.theta` is in radians.)")


_CONICS = ("ellipse", "parabola", "hyperbola")
_END_WEIGHTS = ((1, 1), (1, 4), (4, 1), (2, 2), (2, 8), (8, 2), (0.5, 2), (2, 0.5), (4, 4),
                (1, 1))
_MIDDLE_WEIGHTS = (0.5, 1, 1.5, 2, 3, 4)


def _read_conics(answer, n):
    """A list of n conic names from the answer, or a Feedback."""
    if has_placeholder(answer):
        return Feedback("unanswered", UNANSWERED)
    form = (f"Give a list of {n} strings, each `'ellipse'`, `'parabola'` or `'hyperbola'`, "
            "e.g. `['ellipse', 'hyperbola', 'parabola']`.")
    if isinstance(answer, (str, bytes)) or not isinstance(answer, (list, tuple, np.ndarray)) \
            or len(answer) != n:
        return Feedback("invalid", form, "unreadable")
    names = []
    for item in answer:
        if not isinstance(item, str):
            return Feedback("invalid", form, "unreadable")
        name = item.strip().lower()
        name = {"ellipses": "ellipse", "parabolas": "parabola", "parabolae": "parabola",
                "hyperbolas": "hyperbola", "hyperbolae": "hyperbola"}.get(name, name)
        if name == "circle":
            return Feedback("invalid", "Answer with the type of conic: a circle is an ellipse "
                            "(and these arcs are not circles in general). " + form,
                            "unreadable")
        if name not in _CONICS:
            return Feedback("invalid", f"{item!r} is not one of the three conic types. " + form,
                            "unreadable")
        names.append(name)
    return names


class ConicType(_Chapter7):
    r"""Which conic three rational quadratic arcs lie on, from their weights.

    The arc with weights :math:`(w_0, w_1, w_2)` is the same curve as the one with
    :math:`(1, w, 1)`, :math:`w = w_1 / \sqrt{w_0 w_2}`: an ellipse for :math:`w < 1`, a
    parabola for :math:`w = 1`, a hyperbola for :math:`w > 1`.

    Attributes: ``weights`` (one row of three weights per arc).

    Examples
    --------
    >>> ex = ConicType(seed=14)
    >>> ex.check(ex.expected).status
    'correct'
    >>> swap = {"ellipse": "hyperbola", "hyperbola": "ellipse", "parabola": "parabola"}
    >>> ex.check([swap[name] for name in ex.expected]).diagnosis
    'ellipse and hyperbola swapped'
    >>> ex.check(...).status, ex.check("ellipse").status
    ('unanswered', 'invalid')
    """

    title = "Which conic?"
    answer_form = "custom"

    def draw(self, rng):
        rows = []
        for _ in range(3):
            w0, w2 = pick(rng, _END_WEIGHTS)
            rows.append([float(w0), float(pick(rng, _MIDDLE_WEIGHTS)), float(w2)])
        self.weights = np.array(rows)
        self.expected = [curves.conic_type(w1 / math.sqrt(w0 * w2))
                         for w0, w1, w2 in self.weights]

    def acceptable(self):
        alone = [curves.conic_type(w1) for _, w1, _ in self.weights]
        return len(set(self.expected)) >= 2 and alone != self.expected

    def mistakes(self):
        swap = {"ellipse": "hyperbola", "hyperbola": "ellipse", "parabola": "parabola"}
        return [
            Mistake([curves.conic_type(w1) for _, w1, _ in self.weights], r"You judged each arc by "
                    r"its middle weight alone. The rule $w < 1$ / $w = 1$ / $w > 1$ holds for the "
                    r"standard form with end weights 1. Bring each arc to that form first: the "
                    r"curve does not change when all weights are multiplied by $c$, nor when they "
                    r"become $(w_0, c\,w_1, c^2 w_2)$, so the number that decides is "
                    r"$w = \frac{w_1}{\sqrt{w_0 w_2}}$.", "middle weight alone", numeric=False),
            Mistake([swap[name] for name in self.expected], r"Ellipse and hyperbola are swapped. A "
                    r"small middle weight lets the curve stay away from $P_1$, closing it up: "
                    r"$w < 1$ gives an ellipse; a large one pulls the curve towards $P_1$ and "
                    r"open: $w > 1$ gives a hyperbola (with $w = \frac{w_1}{\sqrt{w_0 w_2}}$).",
                    "ellipse and hyperbola swapped", numeric=False),
        ]

    def keep(self, mistakes):
        return [m for m in mistakes if m.value != self.expected]

    def separated(self, mistakes):
        values = [tuple(m.value) for m in mistakes]
        return tuple(self.expected) not in values and len(set(values)) == len(values)

    def _judge(self, answer):
        names = _read_conics(answer, len(self.weights))
        if isinstance(names, Feedback):
            return names
        if names == self.expected:
            return Feedback("correct", "All three conic types are right.")
        for mistake in self._mistakes:
            if names == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        bad = [str(k + 1) for k, (a, b) in enumerate(zip(names, self.expected)) if a != b]
        which = f"Arc {bad[0]} is" if len(bad) == 1 else f"Arcs {', '.join(bad)} are"
        return Feedback("wrong", f"{which} not right yet. For each arc compute "
                        r"$w = \frac{w_1}{\sqrt{w_0 w_2}}$ and compare it with 1.",
                        "types differ")

    def statement(self):
        rows = "\n".join(rf"| {k + 1} | {_num(w0)} | {_num(w1)} | {_num(w2)} |"
                         for k, (w0, w1, w2) in enumerate(self.weights))
        return (
            r"Three rational quadratic Bézier arcs have these weights (the control points do "
            r"not matter, as long as they are not on a line):" "\n\n"
            r"| arc | $w_0$ | $w_1$ | $w_2$ |" "\n|---|---|---|---|\n" + rows + "\n\n"
            r"With the weights $(1, w, 1)$ such an arc is part of an ellipse for $w < 1$, of a "
            r"parabola for $w = 1$ and of a hyperbola for $w > 1$. Multiplying all three "
            r"weights by the same positive number does not change the curve, and neither does "
            r"changing them to $(w_0,\ c\,w_1,\ c^2 w_2)$ for any $c > 0$ (a change of "
            r"parameter). Which conic does each arc lie on?" "\n\n"
            r"**Answer:** a list of 3 strings, each `'ellipse'`, `'parabola'` or "
            r"`'hyperbola'`, in the order of the arcs." "\n\n" + data_note("weights"))


# ---------------------------------------------------------------------------------------------
# Surfaces
# ---------------------------------------------------------------------------------------------

class BezierSurfacePoint(_Chapter7):
    r"""A point :math:`S(u, v) = \sum_i \sum_j B_i^m(u)\, B_j^n(v)\, P_{ij}` of a Bézier patch.

    Attributes: ``grid`` (shape (m + 1, n + 1, 3), ``grid[i, j]`` is :math:`P_{ij}`), ``m``,
    ``n`` (the degrees in u and v), ``u``, ``v``.

    Examples
    --------
    >>> ex = BezierSurfacePoint(seed=15)
    >>> ex.check(ex.expected).status
    'correct'
    >>> bu = curves.bernstein(ex.m, None, ex.u)
    >>> ex.check(bu @ ex.grid[:, 0]).diagnosis               # the boundary curve v = 0 only
    'one direction only'
    """

    title = "A point of a Bézier patch"
    answer_form = "point"
    what = "the surface point"
    hint = (r"Blend in both directions: $S(u, v) = \sum_i \sum_j B_i^m(u)\, B_j^n(v)\, "
            r"P_{ij}$, e.g. first the curve points $\sum_j B_j^n(v) P_{ij}$ of each row, then "
            r"blend those with $B_i^m(u)$.")

    def draw(self, rng):
        self.m, self.n = pick(rng, ((1, 1), (1, 2), (2, 1), (2, 2)))
        m, n = self.m, self.n
        x, y = np.meshgrid(np.arange(m + 1) * (2 // m), np.arange(n + 1) * (2 // n),
                           indexing="ij")
        z = rng.integers(-2, 4, size=(m + 1, n + 1))
        self.grid = np.stack([x, y, z], axis=-1).astype(float)
        self.u, self.v = (float(pick(rng, _T_VALUES)) for _ in range(2))
        self.expected = surfaces.bezier_surface(self.grid, self.u, self.v)

    def acceptable(self):
        return self.u != self.v and len(np.unique(self.grid[..., 2])) > 1

    def mistakes(self):
        g, m, n, u, v = self.grid, self.m, self.n, self.u, self.v
        bu, bv = curves.bernstein(m, None, u), curves.bernstein(n, None, v)
        swapped = curves.bernstein(m, None, v) @ np.einsum("ijd,j->id", g,
                                                           curves.bernstein(n, None, u))
        one_way = (r"You blended in one direction only, along a boundary curve of the patch. "
                   r"A tensor-product patch blends in both: each control point gets the "
                   r"weight $B_i^m(u)\, B_j^n(v)$, and all $(m+1)(n+1)$ of them count.")
        found = [
            Mistake(swapped, r"$u$ and $v$ are swapped. The first index of $P_{ij}$ runs along "
                    r"$u$ and goes with $B_i^m(u)$; the second runs along $v$ and goes with "
                    r"$B_j^n(v)$.", "u and v swapped"),
            Mistake(bu @ g[:, 0], one_way, "one direction only"),
            Mistake(bv @ g[0], one_way, "one direction only"),
        ]
        if max(m, n) > 1:
            corners = g[[0, -1]][:, [0, -1]]
            bilinear = np.array([1 - u, u]) @ np.einsum("ijd,j->id", corners,
                                                        np.array([1 - v, v]))
            found.append(Mistake(bilinear, r"You interpolated the four corner points only "
                                 r"(bilinearly). The inner control points pull on the surface "
                                 r"too: use all of them with the weights "
                                 r"$B_i^m(u)\, B_j^n(v)$ of the patch's degrees.",
                                 "corners only"))
        return found

    def statement(self):
        m, n = self.m, self.n
        rows = "\n".join("| " + f"$i = {i}$ | "
                         + " | ".join(f"${_vec(self.grid[i, j])}$" for j in range(n + 1))
                         + " |" for i in range(m + 1))
        header = "| | " + " | ".join(f"$j = {j}$" for j in range(n + 1)) + " |"
        rule = "|---" * (n + 2) + "|"
        kind = {1: "linear", 2: "quadratic"}
        return (
            rf"A Bézier patch of degree {m} in $u$ and {n} in $v$ ({kind[m]} in $u$, "
            rf"{kind[n]} in $v$) has the control points $P_{{ij}}$ (row $i$ along $u$, column "
            r"$j$ along $v$):" "\n\n" + header + "\n" + rule + "\n" + rows + "\n\n"
            r"Compute the surface point "
            r"$S(u, v) = \sum_i \sum_j B_i^m(u)\, B_j^n(v)\, P_{ij}$ at "
            rf"$u = {_frac(self.u)}$, $v = {_frac(self.v)}$." "\n\n" + _POINT_3 + " "
            r"(`.grid[i, j]` is $P_{ij}$.)" "\n\n" + data_note("grid", "m", "n", "u", "v"))


# ---------------------------------------------------------------------------------------------
# Properties
# ---------------------------------------------------------------------------------------------

#: The menu of properties: name -> what it means.
PROPERTY_MENU = {
    "convex hull": "every point lies in the convex hull of the control points",
    "strong convex hull": "each polynomial piece lies in the convex hull of only the control "
                          "points active on it (p + 1 of them per direction)",
    "local control": "moving one control point changes only a limited part of the "
                     "curve (surface)",
    "pseudo-local control": "moving one control point changes the whole curve (surface), "
                            "most strongly near that point",
    "affine invariance": "transforming the control points by an affine map transforms the "
                         "curve (surface) by the same map",
    "projective invariance": "the same for projective maps (perspective projections)",
    "variation diminishing": "no line (plane) crosses the curve more often than it crosses "
                             "the control polygon",
    "endpoint interpolation": "the curve passes through its first and last control points "
                              "(the surface through its four corner control points)",
    "exact conics": "can represent circles (for surfaces: spheres, cylinders) exactly",
    "independent degree": "the degree can be chosen independently of the number of control "
                          "points",
}

_KINDS = ("Bézier curve", "B-spline curve", "rational Bézier curve", "NURBS curve",
          "Bézier surface", "B-spline surface", "NURBS surface")


def _properties_of(kind):
    """The properties from PROPERTY_MENU that hold for `kind` (clamped knots, weights > 0)."""
    spline = "B-spline" in kind or "NURBS" in kind
    rational = "rational" in kind or "NURBS" in kind
    surface = kind.endswith("surface")
    holds = {"convex hull", "affine invariance", "endpoint interpolation"}
    if spline:
        holds |= {"strong convex hull", "local control", "independent degree"}
    else:
        holds.add("pseudo-local control")
    if rational:
        holds |= {"projective invariance", "exact conics"}
    if not surface:
        holds.add("variation diminishing")
    return holds


#: Why each property of the menu holds or fails for a type: {name: (if it holds, if it fails)}.
#: ``{thing}`` stands for "curve" or "surface"; a property that holds for every type has one
#: sentence for both.
_PROPERTY_REASONS = {
    "convex hull": 2 * (
        r"**Convex hull** holds for every type here: the blending functions are "
        r"non-negative (weights positive) and add up to 1, so each point is a convex "
        r"combination of the control points.",),
    "affine invariance": 2 * (
        r"**Affine invariance** holds for every type here: the blending functions add "
        r"up to 1, so mapping the control points by an affine map maps every point of "
        r"the {thing} by it.",),
    "endpoint interpolation": 2 * (
        r"**Endpoint interpolation** holds: the first and last blending functions are "
        r"1 at the ends (for B-splines thanks to the clamped knots), so the curve starts "
        r"and ends at the end control points, and a patch passes through its corners.",),
    "strong convex hull": (
        r"**Strong convex hull** holds for B-splines and NURBS: "
        r"on one knot span only $p + 1$ basis functions are non-zero, so each piece "
        r"lies in the hull of those few control points.",
        r"**Strong convex hull** is a B-spline property (each piece "
        r"in the hull of its $p + 1$ active points). A Bézier {thing}"
        r" is a single piece whose blending functions involve all control points: it "
        r"has the ordinary convex hull property only."),
    "local control": (
        r"**Local control** holds for B-splines and NURBS: "
        r"$N_{i,p}$ is zero outside $[u_i, u_{i+p+1})$, so moving $P_i$ changes only "
        r"that part.",
        r"**Local control** is B-spline only. Every Bernstein polynomial "
        r"is non-zero on the whole open interval $(0, 1)$, so moving one control point of "
        r"a Bézier {thing} moves every point except the ends: pseudo-local "
        r"control."),
    "independent degree": (
        r"**Independent degree** holds for B-splines and NURBS: "
        r"more control points mean more knots and pieces, while the degree $p$ "
        r"stays whatever you choose.",
        r"**Independent degree** is B-spline only: a Bézier {thing}"
        r" with $n + 1$ control points (per direction) has degree $n$, so more points "
        r"mean a higher degree."),
    "pseudo-local control": (
        r"**Pseudo-local control** holds for Bézier types: moving $P_i$ moves "
        r"every point of the {thing} (all Bernstein polynomials are positive inside "
        r"the domain), most near the parameter $i / n$.",
        r"**Pseudo-local control** describes Bézier types, whose every point moves "
        r"when one control point moves. B-splines and NURBS have true **local** "
        r"control instead."),
    "projective invariance": (
        r"**Projective invariance** holds for rational types: transform the "
        r"homogeneous control points $(w_i P_i, w_i)$ and the new last coordinates "
        r"are the new weights.",
        r"**Projective invariance** needs weights, i.e. a rational type. A "
        r"perspective map divides by a coordinate that changes along the "
        r"{thing}; a polynomial {thing} has no weights to absorb it, so it is only "
        r"affinely invariant."),
    "exact conics": (
        r"**Exact conics** hold for rational types: with weights "
        r"$(1, \cos\frac{\theta}{2}, 1)$ a quadratic arc is exactly a circular arc, "
        r"and NURBS surfaces give exact spheres and cylinders.",
        r"**Exact conics** need weights: a circle has no polynomial parametrisation, so "
        r"a non-rational {thing} can only approximate it."),
    "variation diminishing": (
        r"**Variation diminishing** holds for every curve type here (with positive "
        r"weights): a line crosses the curve at most as often as the control polygon.",
        r"**Variation diminishing** does not carry over to surfaces: there is no "
        r"counterpart of it for tensor-product patches."),
}


def _property_reason(name, kind, holds):
    """Why property `name` holds (holds=True) or fails for `kind`: a sentence for feedback."""
    if_holds, if_fails = _PROPERTY_REASONS[name]
    thing = "surface" if kind.endswith("surface") else "curve"
    return (if_holds if holds else if_fails).replace("{thing}", thing)


def _normalise_property(text):
    name = " ".join(text.strip().lower().replace("-", " ").replace("_", " ").split())
    name = name.removesuffix(" property")
    name = name.replace("pseudo local", "pseudo-local")
    aliases = {"end point interpolation": "endpoint interpolation",
               "endpoints interpolation": "endpoint interpolation",
               "affine": "affine invariance", "projective": "projective invariance",
               "conics": "exact conics", "local": "local control"}
    return aliases.get(name, name)


class CurveProperties(_Chapter7):
    r"""Which of the listed properties hold for a given kind of curve or surface.

    The answer is a set of names from :data:`PROPERTY_MENU`; each property missing or wrongly
    claimed is explained. Its diagnosis is ``"missing: <name>"`` or ``"extra: <name>"`` for
    the first such property in menu order.

    Attributes: ``kind`` (e.g. ``"NURBS curve"``), ``menu`` (the property names).

    Examples
    --------
    >>> ex = CurveProperties(seed=2)
    >>> ex.kind
    'Bézier surface'
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> ex.check(sorted(ex.expected | {"variation diminishing"})).diagnosis
    'extra: variation diminishing'
    >>> ex.check(["convex hull", "smoothness"]).status
    'invalid'
    """

    title = "Which properties hold?"
    answer_form = "custom"
    menu = tuple(PROPERTY_MENU)

    def draw(self, rng):
        self.kind = str(pick(rng, _KINDS))
        self.expected = _properties_of(self.kind)

    def separated(self, mistakes):
        return True

    def _read(self, answer):
        form = ("Give a list of property names from the menu, e.g. "
                "`['convex hull', 'affine invariance']` (`[]` if none holds).")
        return read_names(answer, self.menu, form, "is not on the menu. The names are:",
                          _normalise_property)

    def _judge(self, answer):
        names = self._read(answer)
        if isinstance(names, Feedback):
            return names
        if names == self.expected:
            return Feedback("correct", f"Exactly these {len(names)} properties hold for a "
                            f"{self.kind}.")
        wrong = [name for name in self.menu if (name in names) != (name in self.expected)]
        first = wrong[0]
        key = ("missing: " if first in self.expected else "extra: ") + first
        missing = [n for n in wrong if n in self.expected]
        extra = [n for n in wrong if n not in self.expected]
        summary = []
        if missing:
            summary.append("Missing: " + ", ".join(f"`{n}`" for n in missing))
        if extra:
            summary.append(("should" if missing else "Should") + " not be there: "
                           + ", ".join(f"`{n}`" for n in extra))
        reasons = " ".join(_property_reason(n, self.kind, n in self.expected) for n in wrong)
        return Feedback("wrong", f"{'; '.join(summary)}. {reasons}", key)

    def statement(self):
        rows = "\n".join(f"| `{name}` | {meaning} |" for name, meaning in PROPERTY_MENU.items())
        article = "an" if self.kind[0] in "AEIOU" else "a"
        return (
            rf"Which of the following properties hold for {article} **{self.kind}**? "
            r"B-splines and NURBS have clamped knot vectors, rational types have positive "
            r"weights, and each B-spline has more control points than its degree plus one." "\n\n"
            "| name | meaning |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** the list of the names of all properties that hold, e.g. "
            r"`['convex hull', 'affine invariance']` (the order does not matter)." "\n\n"
            + data_note("kind", "menu"))


#: The exercises of chapter 7, in the order of the solutions notebook.
EXERCISES = (
    DeCasteljauPoint,
    DeCasteljauLevel,
    BernsteinValues,
    BezierEndTangent,
    BezierSubdivision,
    DegreeElevation,
    ClampedKnotVector,
    CoxDeBoorBasis,
    BasisSupport,
    ActiveControlPoints,
    BSplinePoint,
    RationalBezierPoint,
    CircleArc,
    ConicType,
    BezierSurfacePoint,
    CurveProperties,
)
