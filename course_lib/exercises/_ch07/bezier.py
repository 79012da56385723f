"""Chapter 7 exercises: Bézier curves.

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import curves
from ..core import (DECIMALS, UNEXPLAINED, Feedback, Mistake, Worked, agrees, close, data_note,
                    latex_fraction, pick)
from . import (_POINT_2, _T_VALUES, _bernstein_sum, _casteljau_by_hand, _Chapter7,
               _control_polygon, _floats_or_none, _frac, _level_words, _num, _Points,
               _points_words, _vec)

__all__ = [
    "BernsteinValues",
    "BezierEndTangent",
    "BezierSubdivision",
    "DeCasteljauLevel",
    "DeCasteljauPoint",
    "DegreeElevation",
]


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
    advice = (r"Run the triangle: $n$ rounds of $(1 - t)\,P_i + t\,P_{i+1}$ on neighbouring "
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

    def hints(self):
        n, t = self.n, self.t
        levels = _casteljau_by_hand(self.P, t)
        return [
            r"De Casteljau's algorithm repeats one move: replace two neighbouring points $A, B$ "
            rf"by $(1 - t)\,A + t\,B$. With {n + 1} control points it takes $n = {n}$ rounds, "
            r"each round one point fewer.",
            rf"Here $t = {_frac(t)}$: each new point is ${_frac(1 - t)}$ of the first point plus "
            rf"${_frac(t)}$ of the second. The first round starts with "
            rf"$P_0^1 = {_frac(1 - t)}\,P_0 + {_frac(t)}\,P_1 = {_vec(levels[1][0])}$.",
            rf"The last-but-one level is $P_0^{{{n - 1}}} = {_vec(levels[n - 1][0])}$, "
            rf"$P_1^{{{n - 1}}} = {_vec(levels[n - 1][1])}$: one more interpolation between "
            r"them gives $C(t)$.",
        ]

    def worked(self):
        n, t = self.n, self.t
        levels = _casteljau_by_hand(self.P, t)
        steps = [rf"Level 0 is the control points, {_points_words(self.P)}. Each new point is "
                 rf"$(1 - t)\,P_i + t\,P_{{i+1}}$ with $1 - t = {_frac(1 - t)}$ and "
                 rf"$t = {_frac(t)}$."]
        steps += [_level_words(levels, r, t) for r in range(1, n + 1)]
        steps.append(rf"One point is left: $C({_frac(t)}) = P_0^{{{n}}} = "
                     rf"{_vec(levels[n][0])}$.")
        return Worked(steps, levels[n][0])

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
    advice = (r"Level $r$ comes from level $r - 1$: "
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

    def hints(self):
        t, r = self.t, self.r
        levels = _casteljau_by_hand(self.P, t)
        first = levels[1]
        if r == 1:
            last = (rf"Level 1 so far: $P_0^1 = {_vec(first[0])}$, $P_1^1 = {_vec(first[1])}$; "
                    r"the third point comes from $P_2$ and $P_3$ the same way.")
        else:
            last = (rf"Level 1 is $P_0^1 = {_vec(first[0])}$, $P_1^1 = {_vec(first[1])}$, "
                    rf"$P_2^1 = {_vec(first[2])}$; blend its neighbours once more for level 2.")
        return [
            r"Each level comes from the one just before it by blending neighbours, "
            r"$P_i^r = (1 - t)\,P_i^{r-1} + t\,P_{i+1}^{r-1}$. Level 0 is the control points, "
            r"and each level has one point fewer.",
            rf"Here $1 - t = {_frac(1 - t)}$ and $t = {_frac(t)}$, so the first point of level "
            rf"1 is $P_0^1 = {_frac(1 - t)}\,{_vec(self.P[0])} + {_frac(t)}\,{_vec(self.P[1])} "
            rf"= {_vec(first[0])}$.",
            last,
        ]

    def worked(self):
        t, r = self.t, self.r
        levels = _casteljau_by_hand(self.P, t)
        steps = [rf"Level 0 is the control points, {_points_words(self.P)}; "
                 rf"$1 - t = {_frac(1 - t)}$, $t = {_frac(t)}$."]
        steps += [_level_words(levels, level, t) for level in range(1, r + 1)]
        steps.append(rf"Level {r} has {4 - r} points, one per row of the answer.")
        return Worked(steps, levels[r])

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


#: The parameters of the Bernstein question: tenths, quarters and thirds.
_BERNSTEIN_T = (0.1, 0.2, 0.25, 0.3, 1 / 3, 0.4, 0.5, 0.6, 2 / 3, 0.7, 0.75, 0.8, 0.9)


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
        self.n = int(pick(rng, (2, 3, 4, 5)))
        self.t = float(pick(rng, _BERNSTEIN_T))
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
            if not agrees(total, 1.0):
                return Feedback("wrong", f"{fb.message} Your values add up to "
                                f"{_num(total)}, but the Bernstein polynomials of one degree "
                                r"always add up to 1: check each "
                                r"$\binom{n}{i}\, t^i (1 - t)^{n-i}$.", fb.diagnosis)
            return Feedback("wrong", f"{fb.message} Check each "
                            r"$\binom{n}{i}\, t^i (1 - t)^{n-i}$.", fb.diagnosis)
        return fb

    def hints(self):
        n, t = self.n, self.t
        row = ", ".join(str(math.comb(n, i)) for i in range(n + 1))
        s, c = latex_fraction(t), latex_fraction(1 - t)
        return [
            r"Each value is $B_i^n(t) = \binom{n}{i}\, t^i (1 - t)^{n-i}$. The binomial "
            rf"coefficients of degree {n} are {row} (row {n} of Pascal's triangle).",
            rf"Here $t = {s}$ and $1 - t = {c}$. The two ends are the plain powers: "
            rf"$B_0^{n}(t) = (1 - t)^{n} = {_num((1 - t) ** n, 4)}$ and "
            rf"$B_{n}^{n}(t) = t^{n} = {_num(t ** n, 4)}$.",
            rf"Next, $B_1^{n}(t) = {n} \cdot {s} \cdot ({c})^{{{n - 1}}} = "
            rf"{_num(n * t * (1 - t) ** (n - 1), 4)}$. When you have all {n + 1} values, check "
            r"that they add up to 1.",
        ]

    def worked(self):
        n, t = self.n, self.t
        s, c = latex_fraction(t), latex_fraction(1 - t)
        values = []
        steps = [rf"With $n = {n}$, $t = {s}$ and $1 - t = {c}$, compute "
                 r"$\binom{n}{i}\, t^i (1 - t)^{n-i}$ for each $i$."]
        for i in range(n + 1):
            value = math.comb(n, i) * t ** i * (1 - t) ** (n - i)
            values.append(value)
            steps.append(rf"$B_{i}^{n} = {math.comb(n, i)} \cdot ({s})^{{{i}}} \cdot "
                         rf"({c})^{{{n - i}}} = {_num(value, 4)}$.")
        steps.append(rf"Check: the values add up to ${_num(sum(values), 4)}$.")
        return Worked(steps, np.array(values))

    def statement(self):
        n = self.n
        return (
            rf"Compute the values of all Bernstein polynomials of degree $n = {n}$, "
            r"$B_i^n(t) = \binom{n}{i}\, t^i (1 - t)^{n-i}$, at $t = "
            + latex_fraction(self.t) + "$."
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
    advice = (r"Differentiate $\sum_i B_i^n(t) P_i$: at $t = 0$ only $P_0$ and $P_1$ survive, "
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

    def _edge(self):
        P, n = self.P, self.n
        if self.end == 0:
            return "P_1 - P_0", P[1], P[0]
        return f"P_{n} - P_{n - 1}", P[n], P[n - 1]

    def hints(self):
        name, a, b = self._edge()
        return [
            r"At an end, the derivative of a Bézier curve depends only on the end point and its "
            r"neighbour: $C'(0) = n\,(P_1 - P_0)$ and $C'(1) = n\,(P_n - P_{n-1})$.",
            rf"Here you need $C'({self.end})$, so the edge is ${name} = {_vec(a)} - {_vec(b)} = "
            rf"{_vec(a - b)}$, in the direction of travel.",
            rf"The curve has degree $n = {self.n}$ ({self.n + 1} control points): multiply the "
            r"edge by it, and do not normalise.",
        ]

    def worked(self):
        name, a, b = self._edge()
        edge = a - b
        derivative = self.n * edge
        at = "start" if self.end == 0 else "end"
        return Worked([
            rf"The {at} of the curve is $t = {self.end}$; there $C'({self.end}) = n\,({name})$ "
            rf"with $n = {self.n}$.",
            rf"The edge: ${name} = {_vec(a)} - {_vec(b)} = {_vec(edge)}$.",
            rf"Times the degree: $C'({self.end}) = {self.n} \cdot {_vec(edge)} = "
            rf"{_vec(derivative)}$.",
        ], derivative)

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
    advice = (r"Run de Casteljau's triangle for $t$ and take the **first** point of every level: "
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

    def hints(self):
        n, t = self.n, self.t
        levels = _casteljau_by_hand(self.P, t)
        if n == 3:
            last = (rf"The left polygon runs from $P_0 = {_vec(self.P[0])}$ to the curve point "
                    rf"$C(t) = P_0^3 = {_vec(levels[3][0])}$; its inner points are $P_0^1$ "
                    r"and $P_0^2$, the first points of levels 1 and 2.")
        else:
            last = (rf"The left polygon runs from $P_0 = {_vec(self.P[0])}$ to the curve point "
                    rf"$C(t) = P_0^2 = {_vec(levels[2][0])}$, with $P_0^1$ in between.")
        return [
            r"Subdividing is de Casteljau's triangle read along one edge: the control points of "
            r"the left part are the **first** points of the levels, "
            r"$P_0^0, P_0^1, \dots, P_0^n$.",
            rf"Run the triangle for $t = {_frac(t)}$: each new point is "
            rf"${_frac(1 - t)}$ of the first plus ${_frac(t)}$ of the second; level 1 starts "
            rf"with $P_0^1 = {_vec(levels[1][0])}$.",
            last,
        ]

    def worked(self):
        n, t = self.n, self.t
        levels = _casteljau_by_hand(self.P, t)
        steps = [rf"Run de Casteljau's triangle for $t = {_frac(t)}$ on {_points_words(self.P)}."]
        steps += [_level_words(levels, r, t) for r in range(1, n + 1)]
        left = np.array([level[0] for level in levels])
        steps.append(r"The left part's control points are the first point of each level: "
                     + ", ".join(rf"$P_0^{{{r}}} = {_vec(p)}$" for r, p in enumerate(left))
                     + ".")
        return Worked(steps, left)

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
    advice = (r"Use $Q_i = \frac{i}{n+1}\,P_{i-1} + \left(1 - \frac{i}{n+1}\right) P_i$ for "
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

    def hints(self):
        n, P = self.n, self.P
        weights = ", ".join(f"${_frac(i / (n + 1))}$" for i in range(1, n + 1))
        q1 = P[0] / (n + 1) + n / (n + 1) * P[1]
        return [
            r"Raising the degree keeps the curve and its end points and adds one control point: "
            r"$Q_0 = P_0$, $Q_{n+1} = P_n$, and in between "
            r"$Q_i = \frac{i}{n+1}\,P_{i-1} + \left(1 - \frac{i}{n+1}\right) P_i$.",
            rf"Here $n = {n}$, so the weights $\frac{{i}}{{n+1}}$ of the previous point are "
            rf"{weights} for $i = 1, \dots, {n}$.",
            rf"For example $Q_1 = {_frac(1 / (n + 1))}\,{_vec(P[0])} + "
            rf"{_frac(n / (n + 1))}\,{_vec(P[1])} = {_vec(q1)}$.",
        ]

    def worked(self):
        n, P = self.n, self.P
        Q = [P[0]]
        steps = [rf"The curve has degree $n = {n}$; the new one has $n + 1 = {n + 1}$ and "
                 rf"{n + 2} control points. The ends stay: $Q_0 = P_0 = {_vec(P[0])}$, "
                 rf"$Q_{{{n + 1}}} = P_{{{n}}} = {_vec(P[n])}$."]
        inner = []
        for i in range(1, n + 1):
            a = i / (n + 1)
            q = a * P[i - 1] + (1 - a) * P[i]
            Q.append(q)
            inner.append(rf"$Q_{i} = {_frac(a)}\,{_vec(P[i - 1])} + "
                         rf"{_frac(1 - a)}\,{_vec(P[i])} = {_vec(q)}$")
        Q.append(P[n])
        steps.append("In between: " + "; ".join(inner) + ".")
        steps.append(r"In order, $Q_0, \dots, Q_{" + str(n + 1) + "}$: "
                     + ", ".join(f"${_vec(q)}$" for q in Q) + ".")
        return Worked(steps, np.array(Q))

    def statement(self):
        n = self.n
        return (
            rf"A Bézier curve of degree {n} has the control points {_points_words(self.P)}. "
            rf"Write the same curve as a Bézier curve of degree {n + 1}: give its "
            rf"{n + 2} control points $Q_0, \dots, Q_{{{n + 1}}}$." "\n\n"
            rf"**Answer:** a ${n + 2} \times 2$ array, one control point per row, "
            r"$Q_0$ first. " + DECIMALS + "\n\n" + data_note("P", "n"))
