"""Chapter 7 exercises: Rational curves.

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import curves
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, data_note, diagnose_parts,
                    has_placeholder, parts_separated, pick)
from . import _POINT_2, _T_VALUES, _Chapter7, _control_polygon, _frac, _num, _points_words, _vec

__all__ = [
    "CircleArc",
    "ConicType",
    "RationalBezierPoint",
]


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
    advice = (r"Weight each control point, $w_i P_i$, blend with the Bernstein polynomials, and "
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

    def _blend(self):
        """The Bernstein values at t and the products B_i w_i, by hand."""
        t = self.t
        b = np.array([(1 - t) ** 2, 2 * t * (1 - t), t ** 2])
        return b, b * self.w

    def hints(self):
        b, bw = self._blend()
        return [
            r"A rational Bézier point is a weighted average of the control points: each "
            r"$P_i$ gets the weight $B_i^2(t)\, w_i$, and you divide by the sum of those "
            r"weights, $\sum_i B_i^2(t)\, w_i$.",
            rf"At $t = {_frac(self.t)}$ the Bernstein values are $((1 - t)^2,\ 2t(1 - t),\ t^2) "
            rf"= {_vec(b, 4)}$; times the weights $w = {_vec(self.w)}$ they become "
            rf"${_vec(bw, 4)}$.",
            rf"The denominator is $\sum_i B_i^2(t)\, w_i = {_num(bw.sum(), 4)}$; the numerator "
            rf"is $\sum_i B_i^2(t)\, w_i P_i$ with these same numbers.",
        ]

    def worked(self):
        b, bw = self._blend()
        numerator = bw[0] * self.P[0] + bw[1] * self.P[1] + bw[2] * self.P[2]
        denominator = bw.sum()
        point = numerator / denominator
        return Worked([
            rf"The Bernstein polynomials at $t = {_frac(self.t)}$: $B_0^2 = (1 - t)^2 = "
            rf"{_num(b[0], 4)}$, $B_1^2 = 2t(1 - t) = {_num(b[1], 4)}$, $B_2^2 = t^2 = "
            rf"{_num(b[2], 4)}$.",
            rf"Times the weights: $B_i^2 w_i = {_vec(bw, 4)}$; their sum, the denominator, is "
            rf"${_num(denominator, 4)}$.",
            rf"The numerator: ${_num(bw[0], 4)}\,{_vec(self.P[0])} + {_num(bw[1], 4)}\,"
            rf"{_vec(self.P[1])} + {_num(bw[2], 4)}\,{_vec(self.P[2])} = "
            rf"{_vec(numerator, 4)}$.",
            rf"Divide: $C({_frac(self.t)}) = {_vec(numerator, 4)} / {_num(denominator, 4)} = "
            rf"{_vec(point)}$.",
        ], point)

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

    def hints(self):
        th, half = self.theta_deg, self.theta_deg / 2
        w = math.cos(math.radians(half))
        return [
            r"With $P_1$ where the end tangents meet, the circular arc has the weights "
            r"$(1, w, 1)$ with $w = \cos\frac{\theta}{2}$, the cosine of half the opening angle.",
            rf"Here $\theta = {th}^\circ$, so $w = \cos {_num(half)}^\circ = {_num(w, 4)}$. At "
            r"$t = \tfrac12$ every Bernstein polynomial of degree 2 is known: "
            r"$(\tfrac14, \tfrac12, \tfrac14)$.",
            r"So $C(\tfrac12) = \frac{\frac14 P_0 + \frac12 w P_1 + \frac14 P_2}"
            r"{\frac14 + \frac12 w + \frac14} = \frac{P_0 + 2w P_1 + P_2}{2 + 2w}$; here the "
            rf"denominator is $2 + 2w = {_num(2 + 2 * w, 4)}$. Check: the point lies on the "
            rf"circle, at the angle ${_num(self.alpha_deg + half)}^\circ$.",
        ]

    def worked(self):
        half = self.theta_deg / 2
        w = math.cos(math.radians(half))
        numerator = self.P0 + 2 * w * self.P1 + self.P2
        point = numerator / (2 + 2 * w)
        distance = float(np.linalg.norm(point - self.center))
        return Worked([
            rf"The middle weight: $w = \cos\frac{{\theta}}{{2}} = \cos {_num(half)}^\circ = "
            rf"{_num(w, 4)}$.",
            r"At $t = \tfrac12$: $C(\tfrac12) = \frac{P_0 + 2w P_1 + P_2}{2 + 2w}$. The "
            rf"numerator is ${_vec(self.P0)} + {_num(2 * w, 4)}\,{_vec(self.P1)} + "
            rf"{_vec(self.P2)} = {_vec(numerator, 4)}$, the denominator "
            rf"$2 + 2w = {_num(2 + 2 * w, 4)}$.",
            rf"$C(\tfrac12) = {_vec(point)}$. Check: its distance from $M$ is "
            rf"${_num(distance)}$, the radius.",
        ], [w, float(point[0]), float(point[1])])

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
            Mistake([curves.conic_type(w1) for _, w1, _ in self.weights],
                    r"You judged each arc by "
                    r"its middle weight alone. The rule $w < 1$ / $w = 1$ / $w > 1$ holds for the "
                    r"standard form with end weights 1. Bring each arc to that form first: the "
                    r"curve does not change when all weights are multiplied by $c$, nor when they "
                    r"become $(w_0, c\,w_1, c^2 w_2)$, so the number that decides is "
                    r"$w = \frac{w_1}{\sqrt{w_0 w_2}}$.", "middle weight alone", numeric=False),
            Mistake([swap[name] for name in self.expected],
                    r"Ellipse and hyperbola are swapped. A "
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

    @staticmethod
    def _invariant(row):
        w0, w1, w2 = (float(x) for x in row)
        return w0, w1, w2, w1 / math.sqrt(w0 * w2)

    def hints(self):
        w0, w1, w2, w = self._invariant(self.weights[0])
        return [
            r"The rule $w < 1$ ellipse, $w = 1$ parabola, $w > 1$ hyperbola is for the "
            r"standard form $(1, w, 1)$. Bring each arc to that form first, using the two "
            r"changes of the weights that keep the curve.",
            r"Divide all weights by $w_0$, then use $c = \sqrt{w_0 / w_2}$ to make the last one "
            r"1: the number that decides is $w = \frac{w_1}{\sqrt{w_0 w_2}}$ (compare "
            r"$w_1^2$ with $w_0 w_2$ to avoid the root).",
            rf"Arc 1: $w = \frac{{{_num(w1)}}}{{\sqrt{{{_num(w0)} \cdot {_num(w2)}}}}} = "
            rf"{_num(w, 4)}$. Do the same for arcs 2 and 3.",
        ]

    def worked(self):
        steps, names = [], []
        for k, row in enumerate(self.weights, start=1):
            w0, w1, w2, w = self._invariant(row)
            square, product = w1 * w1, w0 * w2       # exact for these weights
            name = ("ellipse" if square < product else "parabola" if square == product
                    else "hyperbola")
            sign = "<" if square < product else "=" if square == product else ">"
            names.append(name)
            steps.append(rf"Arc {k}: $w = \frac{{{_num(w1)}}}{{\sqrt{{{_num(w0)} \cdot "
                         rf"{_num(w2)}}}}} = {_num(w, 4)}$ (${_num(square)} {sign} "
                         rf"{_num(product)}$): $w {sign} 1$, an arc of "
                         rf"{'an' if name == 'ellipse' else 'a'} **{name}**.")
        steps.append(r"The middle weight alone would not do: only "
                     r"$\frac{w_1}{\sqrt{w_0 w_2}}$ stays the same under the changes of weights "
                     r"that keep the curve.")
        return Worked(steps, names)

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
