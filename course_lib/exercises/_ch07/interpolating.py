r"""Chapter 7 exercises: interpolating curves (Hermite cubics, Catmull-Rom, cubic splines).

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.

Conventions (those of :mod:`course_lib.curves.interpolating`): the Hermite basis
:math:`H_0 = 2u^3 - 3u^2 + 1`, :math:`H_1 = -2u^3 + 3u^2`, :math:`H_2 = u^3 - 2u^2 + u`,
:math:`H_3 = u^3 - u^2` weighs :math:`P_0, P_1, T_0, T_1`; tangents are derivatives with respect
to the global parameter, so a segment of length :math:`h` uses :math:`h T_0, h T_1`; Catmull-Rom
has :math:`T_i = (P_{i+1} - P_{i-1})/2` for uniform parameters.
"""

import numpy as np

from ...curves import interpolating as ip
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _Chapter7, _control_polygon, _frac, _num, _points_words, _vec

__all__ = [
    "CatmullRomPoint",
    "CatmullRomTangent",
    "HermitePoint",
    "SplineSecondDerivatives",
]

_POINT = "**Answer:** the point as a list of 2 numbers `[x, y]`. " + DECIMALS
_VECTOR = "**Answer:** the tangent as a list of 2 numbers `[x, y]`. " + DECIMALS


def _hermite_weights(u):
    """H0..H3 at u, written out (not taken from the library)."""
    return np.array([2 * u ** 3 - 3 * u ** 2 + 1, -2 * u ** 3 + 3 * u ** 2,
                     u ** 3 - 2 * u ** 2 + u, u ** 3 - u ** 2])


def _combine(h, p0, p1, t0, t1):
    return h[0] * np.asarray(p0) + h[1] * np.asarray(p1) + h[2] * np.asarray(t0) \
        + h[3] * np.asarray(t1)


def _basis_words(u):
    h = [_num(v, 6) for v in _hermite_weights(u)]
    return (rf"At $u = {_frac(u)}$: $H_0 = 2u^3 - 3u^2 + 1 = {h[0]}$, "
            rf"$H_1 = -2u^3 + 3u^2 = {h[1]}$, $H_2 = u^3 - 2u^2 + u = {h[2]}$, "
            rf"$H_3 = u^3 - u^2 = {h[3]}$ (check: $H_0 + H_1 = 1$).")


class HermitePoint(_Chapter7):
    r"""A point of one segment of a piecewise Hermite curve, on :math:`[a, a + h]`.

    :math:`u = (t - a)/h`, :math:`C = H_0 P_0 + H_1 P_1 + h H_2 T_0 + h H_3 T_1` (the tangents
    are derivatives with respect to :math:`t`, so they are scaled by the segment's length).

    Attributes: ``P0``, ``P1``, ``T0``, ``T1``, ``a``, ``h``, ``t``, ``u``.

    Examples
    --------
    >>> ex = HermitePoint(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> H = _hermite_weights(ex.u)
    >>> ex.check(_combine(H, ex.P0, ex.P1, ex.T0, ex.T1)).diagnosis
    'tangents not scaled'
    """

    title = "A point of a Hermite segment by hand"
    answer_form = "point"
    what = "the curve point"
    advice = (r"Find the local parameter $u = (t - a)/h$, the four Hermite basis values at $u$, "
              r"and add $H_0 P_0 + H_1 P_1 + h H_2 T_0 + h H_3 T_1$.")

    def draw(self, rng):
        self.P0, self.P1 = rng.integers(0, 7, size=(2, 2)).astype(float)
        self.T0 = rng.integers(-3, 4, size=2).astype(float)
        self.T1 = rng.integers(-3, 4, size=2).astype(float)
        self.h = float(pick(rng, (0.5, 2.0, 3.0, 4.0)))
        self.a = float(pick(rng, (0.0, 1.0, 2.0, 3.0)))
        self.u = float(pick(rng, (0.25, 0.5, 0.75)))
        self.t = self.a + self.u * self.h
        self.expected = ip.hermite_curve([self.P0, self.P1], [self.T0, self.T1], self.t,
                                         [self.a, self.a + self.h])

    def acceptable(self):
        return (not np.array_equal(self.P0, self.P1) and np.any(self.T0 != 0)
                and np.any(self.T1 != 0) and not np.array_equal(self.T0, self.T1))

    def mistakes(self):
        H, h = _hermite_weights(self.u), self.h
        P0, P1, T0, T1 = self.P0, self.P1, self.T0, self.T1
        return [
            Mistake(_combine(H, P0, P1, T0, T1), r"The tangents were not scaled by the segment's "
                    rf"length $h = {_num(h)}$. They are derivatives with respect to $t$, and "
                    r"$dt/du = h$: in the local parameter $u$ the tangents are $h T_0$ and "
                    r"$h T_1$.", "tangents not scaled"),
            Mistake(_combine(H, P0, P1, h * T1, h * T0), r"The tangent weights are swapped: "
                    r"$H_2 = u^3 - 2u^2 + u$ belongs to the start tangent $T_0$ (its "
                    r"derivative is 1 at $u = 0$) and $H_3 = u^3 - u^2$ to the end tangent "
                    r"$T_1$.", "basis swapped"),
            Mistake(_combine(H, P1, P0, h * T0, h * T1), r"The point weights are swapped: "
                    r"$H_0 = 2u^3 - 3u^2 + 1$ is 1 at $u = 0$, so it weighs the start point "
                    r"$P_0$; $H_1$ weighs $P_1$.", "points swapped"),
            Mistake(_combine(H, P0, P1, T0 / h, T1 / h), r"You divided the tangents by $h$; "
                    r"the chain rule multiplies: $dC/du = (dC/dt)(dt/du) = h\,T$.",
                    "tangents divided by h"),
        ]

    def hints(self):
        return [rf"The local parameter is $u = (t - a)/h = ({_num(self.t)} - {_num(self.a)})/"
                rf"{_num(self.h)} = {_frac(self.u)}$.",
                r"$H_0 = 2u^3 - 3u^2 + 1$, $H_1 = -2u^3 + 3u^2$ weigh the points; "
                r"$H_2 = u^3 - 2u^2 + u$, $H_3 = u^3 - u^2$ weigh the tangents.",
                rf"The tangents are per unit of $t$: in $u$ they become $h T_0 = "
                rf"{_vec(self.h * self.T0)}$ and $h T_1 = {_vec(self.h * self.T1)}$."]

    def worked(self):
        H, h = _hermite_weights(self.u), self.h
        c = _combine(H, self.P0, self.P1, h * self.T0, h * self.T1)
        return Worked([
            rf"Local parameter: $u = ({_num(self.t)} - {_num(self.a)})/{_num(h)} = "
            rf"{_frac(self.u)}$.",
            _basis_words(self.u),
            rf"Scaled tangents: $h T_0 = {_vec(h * self.T0)}$, $h T_1 = {_vec(h * self.T1)}$.",
            rf"$C = {_num(H[0], 6)}\,{_vec(self.P0)} + {_num(H[1], 6)}\,{_vec(self.P1)} + "
            rf"{_num(H[2], 6)}\,{_vec(h * self.T0)} + ({_num(H[3], 6)})\,{_vec(h * self.T1)} = "
            rf"{_vec(c)}$.",
        ], c)

    def statement(self):
        return (
            rf"One segment of a piecewise Hermite curve runs over $t \in [{_num(self.a)}, "
            rf"{_num(self.a + self.h)}]$ from $P_0 = {_vec(self.P0)}$ to $P_1 = {_vec(self.P1)}$, "
            rf"with tangents (derivatives $dC/dt$) $T_0 = {_vec(self.T0)}$ at the start and "
            rf"$T_1 = {_vec(self.T1)}$ at the end. Compute the curve point at "
            rf"$t = {_num(self.t)}$." "\n\n" + _POINT + "\n\n"
            + data_note("P0", "P1", "T0", "T1", "a", "h", "t"))


class CatmullRomTangent(_Chapter7):
    r"""The Catmull-Rom tangent at an inner point: :math:`T_i = (P_{i+1} - P_{i-1})/2`.

    Attributes: ``P`` (three consecutive points :math:`P_{i-1}, P_i, P_{i+1}`), ``i``.

    Examples
    --------
    >>> ex = CatmullRomTangent(seed=2)
    >>> ex.check((ex.P[2] - ex.P[0]) / 2).status
    'correct'
    >>> ex.check(ex.P[2] - ex.P[0]).diagnosis
    'forgot the 1/2'
    """

    title = "A Catmull-Rom tangent"
    answer_form = "vector"
    what = "the tangent"
    advice = r"Catmull-Rom: the tangent at $P_i$ is half the chord of its two neighbours."

    def draw(self, rng):
        self.P = _control_polygon(rng, 3, 0, 6)
        self.i = int(pick(rng, (1, 2, 3, 4)))
        self.expected = ip.cardinal_tangents(self.P, 0.5, "uniform")[1]

    def mistakes(self):
        a, b, c = self.P
        return [
            Mistake(c - a, r"The factor $\tfrac12$ is missing. $P_{i+1} - P_{i-1}$ spans two "
                    r"parameter steps; the tangent (per step) is half of it.", "forgot the 1/2"),
            Mistake(c - b, r"That is the forward difference $P_{i+1} - P_i$. Catmull-Rom uses "
                    r"both neighbours, $(P_{i+1} - P_{i-1})/2$ (a central difference), so the "
                    r"tangent is parallel to the chord of the neighbours.", "forward difference"),
            Mistake(b - a, r"That is the backward difference $P_i - P_{i-1}$. Catmull-Rom uses "
                    r"both neighbours: $(P_{i+1} - P_{i-1})/2$.", "backward difference"),
            Mistake((a - c) / 2, r"The sign is reversed: the tangent points the way the curve "
                    r"runs, from $P_{i-1}$ towards $P_{i+1}$: $(P_{i+1} - P_{i-1})/2$.",
                    "reversed"),
        ]

    def hints(self):
        return [r"A Catmull-Rom spline is a piecewise Hermite curve whose tangents are estimated "
                r"from the neighbours.",
                r"For uniform parameters, $T_i = \tfrac12 (P_{i+1} - P_{i-1})$: it does not "
                r"use $P_i$ itself.",
                rf"$P_{{{self.i + 1}}} - P_{{{self.i - 1}}} = {_vec(self.P[2] - self.P[0])}$."]

    def worked(self):
        a, b, c = self.P
        i = self.i
        return Worked([
            rf"The neighbours of $P_{{{i}}}$ are $P_{{{i - 1}}} = {_vec(a)}$ and "
            rf"$P_{{{i + 1}}} = {_vec(c)}$.",
            rf"Their difference: $P_{{{i + 1}}} - P_{{{i - 1}}} = {_vec(c - a)}$ (two "
            r"parameter steps).",
            rf"Half of it: $T_{{{i}}} = {_vec((c - a) / 2)}$.",
        ], (c - a) / 2)

    def statement(self):
        i = self.i
        names = ", ".join(rf"$P_{{{i + k - 1}}} = {_vec(p)}$" for k, p in enumerate(self.P))
        return (rf"Three consecutive points of a Catmull-Rom spline with uniform parameters "
                rf"($t_j = j$) are {names}. What is the tangent $T_{{{i}}}$ of the curve at "
                rf"$P_{{{i}}}$?" "\n\n" + _VECTOR + "\n\n" + data_note("P", "i"))


class CatmullRomPoint(_Chapter7):
    r"""A point of the Catmull-Rom segment from :math:`P_1` to :math:`P_2` (uniform parameters).

    :math:`C(u) = H_0 P_1 + H_1 P_2 + H_2 T_1 + H_3 T_2`, :math:`T_1 = (P_2 - P_0)/2`,
    :math:`T_2 = (P_3 - P_1)/2`.

    Attributes: ``P`` (four points), ``u``.

    Examples
    --------
    >>> ex = CatmullRomPoint(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> P, H = ex.P, _hermite_weights(ex.u)
    >>> ex.check(_combine(H, P[1], P[2], P[2] - P[0], P[3] - P[1])).diagnosis
    'forgot the 1/2'
    """

    title = "A point of a Catmull-Rom segment"
    answer_form = "point"
    what = "the curve point"
    advice = (r"First the two tangents $T_1 = (P_2 - P_0)/2$, $T_2 = (P_3 - P_1)/2$, then the "
              r"Hermite cubic from $P_1$ to $P_2$ at $u$.")

    def draw(self, rng):
        self.P = _control_polygon(rng, 4, 0, 6)
        self.u = float(pick(rng, (0.25, 0.5, 0.75)))
        self.expected = ip.catmull_rom(self.P, 1.0 + self.u, "uniform")

    def mistakes(self):
        P, H = self.P, _hermite_weights(self.u)
        return [
            Mistake(_combine(H, P[1], P[2], P[2] - P[0], P[3] - P[1]), r"The tangents lack the "
                    r"factor $\tfrac12$: $T_1 = (P_2 - P_0)/2$, because $P_2 - P_0$ spans two "
                    r"parameter steps.", "forgot the 1/2"),
            Mistake(_combine(H, P[1], P[2], P[2] - P[1], P[3] - P[2]), r"You used forward "
                    r"differences $P_{i+1} - P_i$ as tangents. Catmull-Rom's tangent at $P_i$ "
                    r"is the central difference $(P_{i+1} - P_{i-1})/2$.", "forward difference"),
            Mistake(_combine(H, P[1], P[2], (P[3] - P[1]) / 2, (P[2] - P[0]) / 2),
                    r"The tangents are swapped: $H_2$ weighs the tangent at the start $P_1$, "
                    r"$T_1 = (P_2 - P_0)/2$; $H_3$ the one at the end $P_2$.", "basis swapped"),
            Mistake(_combine(H, P[0], P[3], (P[2] - P[0]) / 2, (P[3] - P[1]) / 2),
                    r"The segment runs between the two middle points $P_1$ and $P_2$; $P_0$ and "
                    r"$P_3$ only shape the tangents.", "outer points"),
        ]

    def hints(self):
        P = self.P
        return [r"The segment is the Hermite cubic from $P_1$ to $P_2$; $P_0$ and $P_3$ only "
                r"give the tangents.",
                rf"$T_1 = (P_2 - P_0)/2 = {_vec((P[2] - P[0]) / 2)}$, "
                rf"$T_2 = (P_3 - P_1)/2 = {_vec((P[3] - P[1]) / 2)}$.",
                r"Hermite: $C = H_0 P_1 + H_1 P_2 + H_2 T_1 + H_3 T_2$ with "
                r"$H_2 = u^3 - 2u^2 + u$, $H_3 = u^3 - u^2$."]

    def worked(self):
        P, H = self.P, _hermite_weights(self.u)
        t1, t2 = (P[2] - P[0]) / 2, (P[3] - P[1]) / 2
        c = _combine(H, P[1], P[2], t1, t2)
        return Worked([
            rf"Tangents: $T_1 = ({_vec(P[2])} - {_vec(P[0])})/2 = {_vec(t1)}$, "
            rf"$T_2 = ({_vec(P[3])} - {_vec(P[1])})/2 = {_vec(t2)}$.",
            _basis_words(self.u),
            rf"$C = {_num(H[0], 6)}\,{_vec(P[1])} + {_num(H[1], 6)}\,{_vec(P[2])} + "
            rf"{_num(H[2], 6)}\,{_vec(t1)} + ({_num(H[3], 6)})\,{_vec(t2)} = "
            rf"{_vec(c)}$.",
        ], c)

    def statement(self):
        return (rf"A Catmull-Rom spline with uniform parameters passes through "
                rf"{_points_words(self.P)}. Compute the point of the segment from $P_1$ to "
                rf"$P_2$ at local parameter $u = {_frac(self.u)}$." "\n\n" + _POINT + "\n\n"
                + data_note("P", "u"))


def _solve_moments(y, end, slopes=(0.0, 0.0), middle=4.0):
    """The second derivatives of the uniform (h = 1) cubic spline through y, by a dense solve."""
    n = len(y)
    a = np.zeros((n, n))
    r = np.zeros(n)
    for i in range(1, n - 1):
        a[i, i - 1:i + 2] = 1.0, middle, 1.0
        r[i] = 6.0 * (y[i + 1] - 2 * y[i] + y[i - 1])
    if end == "natural":
        a[0, 0] = a[-1, -1] = 1.0
    else:
        a[0, :2] = 2.0, 1.0
        a[-1, -2:] = 1.0, 2.0
        r[0] = 6.0 * (y[1] - y[0] - slopes[0])
        r[-1] = 6.0 * (slopes[1] - (y[-1] - y[-2]))
    return a, r, np.linalg.solve(a, r)


class SplineSecondDerivatives(_Chapter7):
    r"""The second derivatives :math:`M_i` of a cubic spline through 3 or 4 values (t_i = i).

    Interior rows :math:`M_{i-1} + 4 M_i + M_{i+1} = 6 (y_{i+1} - 2 y_i + y_{i-1})`; natural
    ends :math:`M_0 = M_n = 0`; clamped ends :math:`2 M_0 + M_1 = 6 (y_1 - y_0 - s_0)`,
    :math:`M_{n-1} + 2 M_n = 6 (s_n - (y_n - y_{n-1}))`.

    Attributes: ``y`` (the values), ``end`` ("natural" or "clamped"), ``slopes`` (the clamped
    end slopes :math:`s_0, s_n`).

    Examples
    --------
    >>> ex = SplineSecondDerivatives(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(-np.asarray(ex.expected)).diagnosis
    'right-hand side reversed'
    """

    title = "Setting up and solving a cubic spline's system"
    answer_form = "vector"
    what = "the list of second derivatives"

    advice = (r"Write one equation per point: the end rows from the end condition, the inner "
              r"rows $M_{i-1} + 4M_i + M_{i+1} = 6(y_{i+1} - 2y_i + y_{i-1})$; then solve.")

    def draw(self, rng):
        self.end = str(pick(rng, ("natural", "natural", "clamped")))
        n = 3 if self.end == "clamped" else int(pick(rng, (3, 4)))
        self.y = rng.integers(0, 6, size=n).astype(float)
        self.slopes = rng.integers(-2, 3, size=2).astype(float)
        points = self.y[:, None]
        if self.end == "natural":
            self.expected = ip.spline_tangents(points, "uniform", "natural", second=True)[:, 0]
        else:
            self.expected = ip.spline_tangents(points, "uniform", "clamped",
                                               self.slopes[:, None], second=True)[:, 0]

    def acceptable(self):
        return np.any(np.abs(self.expected) > 0.1)

    def mistakes(self):
        y = self.y
        other = "clamped" if self.end == "natural" else "natural"
        slopes = (0.0, 0.0) if self.end == "natural" else self.slopes
        wrong_end = _solve_moments(y, other, slopes)[2]
        why_end = (r"You used the clamped end rows ($2M_0 + M_1 = 6(y_1 - y_0 - s_0)$, with "
                   r"zero slopes) but the spline is **natural**: its end rows are simply "
                   r"$M_0 = 0$ and $M_n = 0$." if self.end == "natural" else
                   r"You used the natural end rows $M_0 = M_n = 0$, but the spline is "
                   r"**clamped**: its end rows come from the given end slopes, "
                   r"$2M_0 + M_1 = 6(y_1 - y_0 - s_0)$ and $M_{n-1} + 2M_n = 6(s_n - "
                   r"(y_n - y_{n-1}))$.")
        return [
            Mistake(wrong_end, why_end, "natural/clamped rows swapped"),
            Mistake(self.expected / 6, r"The factor 6 on the right-hand side is missing: "
                    r"$M_{i-1} + 4M_i + M_{i+1} = 6(y_{i+1} - 2y_i + y_{i-1})$ (it comes from "
                    r"matching the first derivatives, which carry $h/6$).", "forgot the 6"),
            Mistake(-self.expected, r"The right-hand side has the wrong sign: it is the "
                    r"difference of slopes **after minus before**, $(y_{i+1} - y_i) - "
                    r"(y_i - y_{i-1})$.", "right-hand side reversed"),
            Mistake(_solve_moments(y, self.end, self.slopes, middle=2.0)[2],
                    r"The diagonal of the inner rows is $2(h_{i-1} + h_i) = 4$ for unit steps, "
                    r"not 2.", "diagonal 2"),
        ]

    def hints(self):
        n = len(self.y) - 1
        ends = (r"$M_0 = 0$ and $M_{%d} = 0$" % n if self.end == "natural" else
                rf"$2M_0 + M_1 = 6(y_1 - y_0 - s_0)$ and $M_{{{n - 1}}} + 2M_{{{n}}} = "
                rf"6(s_{{{n}}} - (y_{{{n}}} - y_{{{n - 1}}}))$")
        return [r"One unknown $M_i = S''(t_i)$ per point, one equation per point.",
                r"Inner rows (unit steps): $M_{i-1} + 4M_i + M_{i+1} = "
                r"6(y_{i+1} - 2y_i + y_{i-1})$.",
                rf"End rows ({self.end}): {ends}."]

    def worked(self):
        a, r, m = _solve_moments(self.y, self.end, self.slopes)
        rows = []
        for i in range(len(self.y)):
            lhs = " + ".join(rf"{_num(a[i, j])}M_{{{j}}}" for j in range(len(self.y))
                             if a[i, j] != 0)
            rows.append(rf"${lhs} = {_num(r[i])}$")
        steps = [r"The system, one row per point: " + "; ".join(rows) + "."]
        if self.end == "natural" and len(self.y) == 3:
            steps.append(rf"With $M_0 = M_2 = 0$ the middle row gives $4M_1 = {_num(r[1])}$, "
                         rf"$M_1 = {_num(m[1])}$.")
        elif self.end == "natural":
            steps.append(rf"With $M_0 = M_3 = 0$: $4M_1 + M_2 = {_num(r[1])}$, "
                         rf"$M_1 + 4M_2 = {_num(r[2])}$; so $M_1 = (4\cdot{_num(r[1])} - "
                         rf"{_num(r[2])})/15 = {_num(m[1])}$ and $M_2 = (4\cdot{_num(r[2])} - "
                         rf"{_num(r[1])})/15 = {_num(m[2])}$.")
        else:
            steps.append(rf"From the end rows $M_0 = ({_num(r[0])} - M_1)/2$ and "
                         rf"$M_2 = ({_num(r[2])} - M_1)/2$; into the middle row: "
                         rf"$3M_1 = {_num(r[1])} - ({_num(r[0])} + {_num(r[2])})/2$, "
                         rf"$M_1 = {_num(m[1])}$, then $M_0 = {_num(m[0])}$, $M_2 = {_num(m[2])}$.")
        steps.append(r"$M = (" + ", ".join(_num(v) for v in m) + ")$.")
        return Worked(steps, m)

    def statement(self):
        n = len(self.y)
        values = ", ".join(rf"$y_{{{i}}} = {_num(v)}$" for i, v in enumerate(self.y))
        ends = ("**natural** ends ($S'' = 0$ at both ends)" if self.end == "natural" else
                rf"**clamped** ends with slopes $S'(0) = {_num(self.slopes[0])}$ and "
                rf"$S'({n - 1}) = {_num(self.slopes[1])}$")
        return (rf"A cubic spline $S(t)$ interpolates {values} at $t_i = i$, with {ends}. "
                r"Set up the tridiagonal system for the second derivatives "
                r"$M_i = S''(t_i)$ and solve it." "\n\n"
                rf"**Answer:** the list $[M_0, \dots, M_{{{n - 1}}}]$. " + DECIMALS + "\n\n"
                + data_note("y", "end", "slopes"))
