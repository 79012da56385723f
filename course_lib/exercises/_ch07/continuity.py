r"""Chapter 7 exercises: continuity at a join of two curve segments, and the matrix form of cubics.

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.
"""

import numpy as np

from ... import curves
from ..core import Mistake, Worked, data_note, pick
from . import _POINT_2, _Chapter7, _frac, _num, _points_words, _vec

__all__ = [
    "C1JoinPoint",
    "JoinContinuityCheck",
    "MatrixFormPoint",
]

_PAIR = ("**Answer:** the list `[C, G]` of two whole numbers: the highest $k \\le 2$ with "
         "$C^k$ and the highest $k \\le 2$ with $G^k$ (use $-1$ if the segments do not even "
         "meet).")


def _cross_z(a, b):
    return float(a[0] * b[1] - a[1] * b[0])


class JoinContinuityCheck(_Chapter7):
    r"""The highest :math:`C^k` and :math:`G^k` (k <= 2) of the join of two cubic Bézier curves.

    With :math:`A(1) = P_3 = Q_0 = B(0)`: :math:`A'(1) = 3(P_3 - P_2)`,
    :math:`B'(0) = 3(Q_1 - Q_0)`, :math:`A''(1) = 6(P_3 - 2P_2 + P_1)`,
    :math:`B''(0) = 6(Q_2 - 2Q_1 + Q_0)`. C1/C2: equal derivatives; G1: tangents in the same
    direction; G2: also equal curvature :math:`\kappa = |x'y'' - y'x''| / |P'|^3` on the same
    side (same sign of the cross product).

    Attributes: ``P``, ``Q`` (the two control polygons), ``kind`` (how the join was built).

    Examples
    --------
    >>> ex = JoinContinuityCheck(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(...).status, ex.check("C1").status
    ('unanswered', 'invalid')
    """

    title = "The continuity of a join"
    answer_form = "vector"
    what = "the pair [C, G]"
    advice = (r"Compare the end derivatives: equal first derivatives give C1 (equal second ones "
              r"C2); tangents in the same direction (any length) give G1, and equal curvature "
              r"on the same side G2. C^k with a non-zero tangent implies G^k.")

    _KINDS = ("cusp", "G1", "C1", "G2", "C1G2", "C2")

    def draw(self, rng):
        if not hasattr(self, "kind"):                  # the kind is drawn once, then kept
            self.kind = str(pick(rng, self._KINDS))
        while True:
            P = rng.integers(0, 4, size=(4, 2)).astype(float)
            d = P[3] - P[2]
            a = P[3] - 2 * P[2] + P[1]
            if np.abs(d).sum() > 0 and abs(_cross_z(d, a)) > 0 and np.abs(d).max() <= 2:
                break
        beta = {"cusp": float(pick(rng, (-1, -2))), "G1": float(pick(rng, (2, 3))),
                "C1": 1.0, "G2": 2.0, "C1G2": 1.0, "C2": 1.0}[self.kind]
        gamma = int(pick(rng, (-1, 1, 2)))
        if self.kind in ("G2", "C1G2"):
            b = beta * beta * a + gamma * d                         # beta constraints
        elif self.kind == "C2":
            b = a
        else:                                                        # curvature breaks
            b = a + rng.integers(-2, 3, size=2)
        Q0 = P[3]
        Q1 = Q0 + beta * d
        Q2 = 2 * Q1 - Q0 + b
        Q3 = Q2 + rng.integers(-2, 3, size=2)
        self.P = P
        self.Q = np.array([Q0, Q1, Q2, Q3])
        join = curves.join_continuity(self.P, self.Q)
        self.expected = np.array([join.C, join.G], float)

    def acceptable(self):
        if np.abs(self.Q).max() > 15 or np.allclose(self.Q[3], self.Q[2]):
            return False
        c, g = self.expected
        wanted = {"cusp": (0, 0), "G1": (0, 1), "C1": (1, 1), "G2": (0, 2), "C1G2": (1, 2),
                  "C2": (2, 2)}[self.kind]
        return (c, g) == wanted

    def mistakes(self):
        c, g = self.expected
        found = []
        if c < g:
            found.append(Mistake([g, g], r"The tangents point the same way, but their "
                                 r"**lengths** differ ($B'(0) \ne A'(1)$): that is geometric "
                                 r"continuity only. $C^k$ needs the derivative vectors "
                                 r"themselves equal, speed included; $G^k$ only the shape.",
                                 "G taken for C"))
        if self.kind == "cusp":
            found.append(Mistake([0, 1], r"The tangents lie on one line but point in "
                                 r"**opposite** directions: the curve turns back at the join "
                                 r"(a cusp). G1 needs the unit tangents equal, "
                                 r"$\beta_1 > 0$ in $B'(0) = \beta_1 A'(1)$.",
                                 "opposite tangent accepted"))
        if c >= 1:
            found.append(Mistake([c, 0], r"C^k with a non-zero tangent implies G^k: equal "
                                 r"derivative vectors have equal directions (G1) and, with "
                                 r"equal second derivatives too, equal curvature (G2). "
                                 r"G is always at least C here.", "C without G"))
        if g == 1:
            found.append(Mistake([c, 2], r"Parallel tangents give G1, not yet G2: G2 also "
                                 r"needs the same curvature on both sides (and on the same "
                                 r"side of the tangent). Compute "
                                 r"$\kappa = |x'y'' - y'x''| / |P'|^3$ at both ends.",
                                 "curvature not checked"))
        return found

    def _derivs(self):
        P, Q = self.P, self.Q
        return (3 * (P[3] - P[2]), 3 * (Q[1] - Q[0]), 6 * (P[3] - 2 * P[2] + P[1]),
                6 * (Q[2] - 2 * Q[1] + Q[0]))

    def hints(self):
        a1, b1, a2, b2 = self._derivs()
        return [r"At the join: $A'(1) = 3(P_3 - P_2)$, $B'(0) = 3(Q_1 - Q_0)$, "
                r"$A''(1) = 6(P_3 - 2P_2 + P_1)$, $B''(0) = 6(Q_2 - 2Q_1 + Q_0)$.",
                rf"Here $A'(1) = {_vec(a1)}$ and $B'(0) = {_vec(b1)}$: equal (C1)? The same "
                r"direction with a positive factor (G1)?",
                rf"$A''(1) = {_vec(a2)}$, $B''(0) = {_vec(b2)}$. For G2 compare the signed "
                r"curvatures $(x'y'' - y'x'') / |P'|^3$ of both ends."]

    def worked(self):
        a1, b1, a2, b2 = self._derivs()
        ka = _cross_z(a1, a2) / np.linalg.norm(a1) ** 3
        kb = _cross_z(b1, b2) / np.linalg.norm(b1) ** 3
        ratio = float(b1 @ a1 / (a1 @ a1))
        c = (2 if np.allclose(a2, b2) else 1) if np.allclose(a1, b1) else 0
        g = max(c, (2 if abs(ka - kb) < 1e-9 else 1)
                if ratio > 0 and abs(_cross_z(a1, b1)) < 1e-9 else 0)
        steps = [rf"$Q_0 = P_3 = {_vec(self.P[3])}$: the segments meet (C0).",
                 rf"$A'(1) = 3(P_3 - P_2) = {_vec(a1)}$, $B'(0) = 3(Q_1 - Q_0) = {_vec(b1)}$ "
                 rf"$= {_num(ratio)}\,A'(1)$: "
                 + ("equal, so C1 (and G1)." if c >= 1 else
                    "the same direction, different length: G1 but not C1." if g >= 1 else
                    "opposite directions: a cusp, not even G1."),
                 rf"$A''(1) = 6(P_3 - 2P_2 + P_1) = {_vec(a2)}$, "
                 rf"$B''(0) = 6(Q_2 - 2Q_1 + Q_0) = {_vec(b2)}$"
                 + (": equal, so C2." if c == 2 else " (not equal: not C2)." if c == 1
                    else "."),
                 rf"Signed curvatures $(x'y'' - y'x'')/|P'|^3$: $\kappa_A = {_num(ka, 4)}$, "
                 rf"$\kappa_B = {_num(kb, 4)}$"
                 + (" (equal: G2)." if g == 2 else " (different: not G2)." if g == 1
                    else " (G2 needs G1 first)."),
                 rf"So the join is $C^{c}$ and $G^{g}$: the answer is [{c}, {g}]."]
        return Worked(steps, np.array([c, g], float))

    def statement(self):
        return (rf"A cubic Bézier segment $A$ has the control points {_points_words(self.P)}; "
                rf"the next segment $B$ has {_points_words(self.Q, 'Q')}. Both run over "
                r"$t \in [0, 1]$. What are the highest parametric continuity $C^k$ and the "
                r"highest geometric continuity $G^k$ ($k \le 2$) of their join?" "\n\n"
                + _PAIR + "\n\n" + data_note("P", "Q"))


# ---------------------------------------------------------------------------------------------

_FORMS = {"bezier": "cubic Bézier", "hermite": "Hermite", "bspline": "uniform cubic B-spline",
          "catmull-rom": "Catmull-Rom"}
_GEOMETRY = {"bezier": r"G = [P_0, P_1, P_2, P_3]",
             "hermite": r"G = [P(0), P(1), P'(0), P'(1)]",
             "bspline": r"G = [P_0, P_1, P_2, P_3]",
             "catmull-rom": r"G = [P_0, P_1, P_2, P_3]"}


def _basis_matrix_latex(m, scale):
    rows = r" \\ ".join(" & ".join(_num(v * scale) for v in row) for row in m)
    front = "" if scale == 1 else rf"\tfrac{{1}}{{{scale}}}"
    return front + r"\begin{bmatrix}" + rows + r"\end{bmatrix}"


class MatrixFormPoint(_Chapter7):
    r"""A point :math:`P(t) = T\,M\,G` of a cubic in matrix form, with :math:`T = [t^3, t^2, t, 1]`.

    Attributes: ``form`` (``"bezier"``, ``"hermite"``, ``"bspline"`` or ``"catmull-rom"``),
    ``M`` (its basis matrix), ``G`` (the geometry, one row per quantity), ``t``.

    Examples
    --------
    >>> ex = MatrixFormPoint(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "A cubic in matrix form"
    answer_form = "point"
    what = "the curve point"
    advice = (r"Write the row $T = [t^3, t^2, t, 1]$, multiply it by $M$ (four blending "
              r"weights), then weight the rows of $G$ with them.")

    def draw(self, rng):
        self.form = str(pick(rng, tuple(_FORMS)))
        self.t = (0.5 if self.form in ("bspline", "catmull-rom")       # weights by hand: /48, /16
                  else float(pick(rng, (0.5, 0.25, 0.75))))
        self.M = curves.basis_matrix(self.form)
        self.G = rng.integers(-3, 5, size=(4, 2)).astype(float)
        self.expected = curves.cubic_matrix_eval(self.M, self.G, self.t)

    def acceptable(self):
        return np.linalg.matrix_rank(self.G - self.G[0]) == 2

    def mistakes(self):
        t = self.t
        T = np.array([t ** 3, t ** 2, t, 1.0])
        found = [Mistake(T[::-1] @ self.M @ self.G, r"The row $T$ is in the wrong order: "
                         r"with this $M$ it is $[t^3, t^2, t, 1]$ (highest power first); "
                         r"$[1, t, t^2, t^3]$ belongs to books whose matrix has its rows "
                         r"reversed.", "T reversed")]
        if not np.allclose(self.M, self.M.T):
            found.append(Mistake(T @ self.M.T @ self.G, r"$M$ is transposed: its **rows** "
                                 r"belong to the powers $t^3, t^2, t, 1$ and its **columns** "
                                 r"to the geometry quantities; $T M$ gives one weight per "
                                 r"row of $G$.", "M transposed"))
        if self.form == "hermite":
            swapped = self.G[[0, 2, 1, 3]]
            found.append(Mistake(T @ self.M @ swapped, r"The Hermite geometry is ordered "
                                 r"$[P(0), P(1), P'(0), P'(1)]$: both end points first, "
                                 r"then both tangents.", "Hermite order"))
        if self.form == "bspline":
            found.append(Mistake(T @ (6 * self.M) @ self.G, r"The factor $\tfrac16$ of the "
                                 r"B-spline matrix is missing: without it the weights add up "
                                 r"to 6, not 1.", "1/6 forgotten"))
        if self.form == "catmull-rom":
            found.append(Mistake(T @ (2 * self.M) @ self.G, r"The factor $\tfrac12$ of the "
                                 r"Catmull-Rom matrix is missing: without it the weights add "
                                 r"up to 2, not 1.", "1/2 forgotten"))
        return found

    def _scale(self):
        return {"bspline": 6, "catmull-rom": 2}.get(self.form, 1)

    def hints(self):
        t = self.t
        T = np.array([t ** 3, t ** 2, t, 1.0])
        w = T @ self.M
        return [rf"$T = [t^3, t^2, t, 1] = [{', '.join(_frac(v) for v in T)}]$.",
                r"Multiply the row by $M$: each weight is $T$ times one **column** of $M$. "
                rf"Here $T M = [{', '.join(_num(v, 4) for v in w)}]$.",
                r"The point is the sum of the rows of $G$ weighted by $T M$."]

    def worked(self):
        t = self.t
        T = np.array([t ** 3, t ** 2, t, 1.0])
        w = T @ self.M
        terms = " + ".join(rf"{_num(wi, 4)}\,{_vec(g)}" for wi, g in zip(w, self.G))
        return Worked([
            rf"$T = [{', '.join(_frac(v) for v in T)}]$ at $t = {_frac(t)}$.",
            rf"$T M = [{', '.join(_num(v, 4) for v in w)}]$ (the four blending weights"
            + (", summing to 1)." if self.form != "hermite" else ")."),
            rf"$P({_frac(t)}) = {terms} = {_vec(w @ self.G)}$."], w @ self.G)

    def statement(self):
        s = self._scale()
        return (rf"A {_FORMS[self.form]} segment in matrix form $P(t) = T\,M\,G$ with "
                rf"$T = [t^3, t^2, t, 1]$, $M = {_basis_matrix_latex(self.M, s)}$ and "
                rf"${_GEOMETRY[self.form]}$ with rows "
                + ", ".join(f"${_vec(g)}$" for g in self.G)
                + rf". Compute $P(t)$ for $t = {_frac(self.t)}$." "\n\n" + _POINT_2 + "\n\n"
                + data_note("form", "M", "G", "t"))


# ---------------------------------------------------------------------------------------------

class C1JoinPoint(_Chapter7):
    r"""Place :math:`Q_1` of the next Bézier segment for a C1 join in the global parameter.

    Segment A (degree n, control points :math:`P_0..P_n`) covers a parameter interval of
    length :math:`h_0`, segment B (degree m) the next one of length :math:`h_1`. C1 in the
    global parameter: :math:`\frac{n}{h_0}(P_n - P_{n-1}) = \frac{m}{h_1}(Q_1 - Q_0)`, so
    :math:`Q_1 = P_n + \frac{n\,h_1}{m\,h_0}(P_n - P_{n-1})`.

    Attributes: ``P``, ``n``, ``m``, ``h0``, ``h1``.

    Examples
    --------
    >>> ex = C1JoinPoint(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Control points for a C1 join"
    answer_form = "point"
    what = "the point Q1"
    may_coincide = ("degree ratio forgotten", "interval ratio forgotten", "ratio inverted")
    advice = (r"Equate the end derivatives in the global parameter: "
              r"$\frac{n}{h_0}(P_n - P_{n-1}) = \frac{m}{h_1}(Q_1 - Q_0)$ with $Q_0 = P_n$.")

    _PAIRS = ((3, 3), (3, 2), (2, 3), (3, 3), (2, 2), (3, 4), (4, 3))
    _INTERVALS = ((1, 1), (1, 2), (2, 1), (2, 3), (1, 1), (3, 2))

    def draw(self, rng):
        self.n, self.m = (int(v) for v in pick(rng, self._PAIRS))
        self.h0, self.h1 = (float(v) for v in pick(rng, self._INTERVALS))
        while True:
            self.P = rng.integers(0, 5, size=(self.n + 1, 2)).astype(float)
            if np.abs(self.P[-1] - self.P[-2]).sum() > 0:
                break
        self.expected = self._q1(self.n * self.h1 / (self.m * self.h0))

    def _q1(self, factor, sign=1.0):
        return self.P[-1] + sign * factor * (self.P[-1] - self.P[-2])

    def mistakes(self):
        n, m, h0, h1 = self.n, self.m, self.h0, self.h1
        return [
            Mistake(self._q1(n * h1 / (m * h0), -1.0), r"The step points backwards: "
                    r"$Q_1 = P_n + c\,(P_n - P_{n-1})$ continues **past** $P_n$, away from "
                    r"$P_{n-1}$; subtracting puts $Q_1$ back on $P_{n-1}$'s side and makes a "
                    r"cusp.", "wrong sign"),
            Mistake(self._q1(h1 / h0), r"The degrees were left out: a degree-$n$ Bézier "
                    r"curve has $A'(1) = n(P_n - P_{n-1})$, so the step scales by $n/m$ when "
                    r"the degrees differ.", "degree ratio forgotten"),
            Mistake(self._q1(n / m), r"The parameter interval lengths were left out: in the "
                    r"global parameter each segment's derivative is divided by its interval "
                    r"length, so the step scales by $h_1/h_0$.", "interval ratio forgotten"),
            Mistake(self._q1(m * h0 / (n * h1)), r"The ratio is upside down: "
                    r"$\frac{m}{h_1}(Q_1 - Q_0) = \frac{n}{h_0}(P_n - P_{n-1})$ gives the "
                    r"factor $\frac{n\,h_1}{m\,h_0}$.", "ratio inverted"),
        ]

    def hints(self):
        return [r"$Q_0 = P_n$ (C0). A degree-$n$ Bézier curve leaves its end with derivative "
                r"$n(P_n - P_{n-1})$ per unit of its own parameter.",
                r"Over an interval of length $h$ the global derivative is the local one "
                r"divided by $h$: set $\frac{n}{h_0}(P_n - P_{n-1}) = "
                r"\frac{m}{h_1}(Q_1 - Q_0)$.",
                rf"Here the factor is $\frac{{n h_1}}{{m h_0}} = \frac{{{self.n} \cdot "
                rf"{_num(self.h1)}}}{{{self.m} \cdot {_num(self.h0)}}}$."]

    def worked(self):
        n, m, h0, h1 = self.n, self.m, self.h0, self.h1
        d = self.P[-1] - self.P[-2]
        f = n * h1 / (m * h0)
        return Worked([
            rf"$Q_0 = P_{n} = {_vec(self.P[-1])}$ and $P_{n} - P_{n - 1} = {_vec(d)}$.",
            rf"C1 in the global parameter: $\frac{{{n}}}{{{_num(h0)}}}(P_{n} - P_{n - 1}) = "
            rf"\frac{{{m}}}{{{_num(h1)}}}(Q_1 - Q_0)$, so $Q_1 - Q_0 = "
            rf"\frac{{{n} \cdot {_num(h1)}}}{{{m} \cdot {_num(h0)}}}\,{_vec(d)} = "
            rf"{_num(f, 4)}\,{_vec(d)}$.",
            rf"$Q_1 = {_vec(self.P[-1])} + {_vec(f * d)} = {_vec(self.P[-1] + f * d)}$."],
            self.P[-1] + f * d)

    def statement(self):
        return (rf"A Bézier segment $A$ of degree {self.n} has the control points "
                rf"{_points_words(self.P)} and covers a parameter interval of length "
                rf"$h_0 = {_num(self.h0)}$ of the spline's global parameter. The next segment "
                rf"$B$ has degree {self.m} and covers the following interval, of length "
                rf"$h_1 = {_num(self.h1)}$. Where must $Q_1$, the second control point of "
                r"$B$, lie for the join to be $C^1$ in the global parameter?" "\n\n"
                + _POINT_2 + "\n\n"
                + data_note("P", "n", "m", "h0", "h1"))
