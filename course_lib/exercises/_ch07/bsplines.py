"""Chapter 7 exercises: B-splines.

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.
"""

import numpy as np

from ... import curves
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, close, data_note,
                    has_placeholder, is_unanswered, pick)
from . import (_POINT_2, _Chapter7, _control_polygon, _cox_de_boor_levels, _de_boor_by_hand,
               _even_knots, _floats_or_none, _frac, _inside_span, _integer_knots, _knots_words,
               _num, _points_words, _span_of, _span_words, _vec)

__all__ = [
    "ActiveControlPoints",
    "BSplinePoint",
    "BasisSupport",
    "ClampedKnotVector",
    "CoxDeBoorBasis",
]


class ClampedKnotVector(_Chapter7):
    r"""The clamped knot vector on :math:`[0, 1]` for a given number of control points and degree.

    :math:`p + 1` zeros, the :math:`N - p - 1` interior knots :math:`\frac{1}{N-p}, \dots,
    \frac{N-p-1}{N-p}`, :math:`p + 1` ones: :math:`N + p + 1` knots for :math:`N` control
    points. Degrees 1 to 5, with 2 to 9 knot spans.

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
        self.p = int(pick(rng, (1, 2, 3, 4, 5)))
        self.n_control = self.p + int(pick(rng, (2, 3, 4, 5, 6, 7, 8, 9)))
        self.expected = curves.clamped_knots(self.n_control, self.p)

    def hints(self):
        N, p = self.n_control, self.p
        m = N - p
        knots = "knot" if m == 2 else "knots"
        return [
            rf"Count first: $N$ control points and degree $p$ need $N + p + 1 = {N} + {p} + 1 "
            rf"= {N + p + 1}$ knots.",
            rf"Clamping repeats each end knot $p + 1 = {p + 1}$ times: {p + 1} zeros at the "
            rf"start and {p + 1} ones at the end.",
            rf"That leaves $N - p - 1 = {m - 1}$ interior {knots}, spaced evenly: the "
            rf"$N - p = {m}$ knot spans of $[0, 1]$ each have length ${_frac(1 / m)}$.",
        ]

    def worked(self):
        N, p = self.n_control, self.p
        m = N - p
        interior = [j / m for j in range(1, m)]
        knots = [0.0] * (p + 1) + interior + [1.0] * (p + 1)
        return Worked([
            rf"The number of knots: $N + p + 1 = {N} + {p} + 1 = {N + p + 1}$.",
            rf"The ends, repeated $p + 1 = {p + 1}$ times: {p + 1} zeros and {p + 1} ones, "
            rf"{2 * (p + 1)} knots.",
            rf"The remaining $N - p - 1 = {m - 1}$ interior knot{'s' if m > 2 else ''} split "
            rf"$[0, 1]$ into $N - p = {m}$ equal spans: $\frac{{j}}{{{m}}}$ for "
            rf"$j = 1, \dots, {m - 1}$, i.e. " + ", ".join(f"${_frac(x)}$" for x in interior)
            + ".",
            r"Together, in order: $U = (" + r",\ ".join(_frac(x) for x in knots) + ")$.",
        ], np.array(knots))

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
        first = int(np.sum(value == value[0]))             # the multiplicities of the ends
        last = int(np.sum(value == value[-1]))
        count = (f" With {N} control points and degree {p} there are "
                 f"$N + p + 1 = {N} + {p} + 1 = {want}$ knots.")
        if first == p and last == p:
            times = "once" if p == 1 else f"{p} times"
            return Feedback("wrong", f"The end knots appear {times} each; a clamped knot "
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
    advice = (r"Start with $N_{i,0}(t) = 1$ on the span that contains $t$ and 0 elsewhere, then "
            r"apply the recursion degree by degree; at every degree the values add up to 1 "
            r"inside the domain.")

    def draw(self, rng):
        self.p = int(pick(rng, (1, 2, 2, 3)))
        self.n_control = self.p + int(pick(rng, (2, 3)))
        self.knots = _integer_knots(rng, self.n_control, self.p)
        self.t = _inside_span(rng, self.knots, self.p)
        self.expected = curves.bspline_basis(self.knots, self.p, self.t)
        self._lower = _cox_de_boor_levels(self.knots, self.p, self.t)[self.p - 1]

    def _triangle(self):
        """The non-zero basis functions of each degree at t, as the recursion gives them:
        a list (degree 0 first) of {i: (value, the LaTeX of its computation)}."""
        u, p, t = self.knots, self.p, self.t
        k = _span_of(u, t)
        levels = [{k: (1.0, "1")}]
        for r in range(1, p + 1):
            prev, level = levels[-1], {}
            for i in range(k - r, k + 1):
                value, names, numbers = 0.0, [], []
                if i in prev:                        # (t - u_i) / (u_{i+r} - u_i) N_{i,r-1}
                    f = rf"\frac{{{_num(t - u[i])}}}{{{_num(u[i + r] - u[i])}}}"
                    value += (t - u[i]) / (u[i + r] - u[i]) * prev[i][0]
                    names.append(rf"{f}\,N_{{{i},{r - 1}}}")
                    numbers.append(rf"{f} \cdot {_num(prev[i][0], 4)}")
                if i + 1 in prev:                    # (u_{i+r+1} - t) / (...) N_{i+1,r-1}
                    g = (rf"\frac{{{_num(u[i + r + 1] - t)}}}"
                         rf"{{{_num(u[i + r + 1] - u[i + 1])}}}")
                    value += ((u[i + r + 1] - t) / (u[i + r + 1] - u[i + 1])
                              * prev[i + 1][0])
                    names.append(rf"{g}\,N_{{{i + 1},{r - 1}}}")
                    numbers.append(rf"{g} \cdot {_num(prev[i + 1][0], 4)}")
                level[i] = (value, " + ".join(names) + " = " + " + ".join(numbers))
            levels.append(level)
        return k, levels

    @staticmethod
    def _level_text(level, r):
        return ", ".join(rf"$N_{{{i},{r}}}(t) = {_num(v, 4)}$" for i, (v, _) in level.items())

    def hints(self):
        p, t = self.p, self.t
        k, levels = self._triangle()
        if p == 1:
            last = (rf"Degree 0 gives only $N_{{{k},0}}(t) = 1$, so degree 1 has two non-zero "
                    rf"values: $N_{{{k - 1},1}}(t) = \frac{{u_{{{k + 1}}} - t}}"
                    rf"{{u_{{{k + 1}}} - u_{{{k}}}}}$ and $N_{{{k},1}}(t) = "
                    rf"\frac{{t - u_{{{k}}}}}{{u_{{{k + 1}}} - u_{{{k}}}}}$.")
        else:
            last = (rf"At degree {p - 1} the non-zero values are "
                    + self._level_text(levels[p - 1], p - 1)
                    + rf"; one more round of the recursion gives degree {p}.")
        return [
            r"Start at degree 0: exactly one $N_{i,0}(t)$ is 1, the one of the knot span "
            r"$[u_i, u_{i+1})$ that contains $t$. Each degree up spreads the value over one more "
            r"function, and at every degree the values add up to 1.",
            _span_words(self.knots, k, t) + rf": $N_{{{k},0}}(t) = 1$, and at degree $p = {p}$ "
            rf"only $N_{{{k - p},{p}}}, \dots, N_{{{k},{p}}}$ can be non-zero; the others are "
            r"0 without any computation. A fraction whose denominator is 0 counts as 0.",
            last,
        ]

    def worked(self):
        p, t, N = self.p, self.t, self.n_control
        k, levels = self._triangle()
        steps = [_span_words(self.knots, k, t) + rf": degree 0 is $N_{{{k},0}}(t) = 1$ "
                 "and 0 for every other $i$."]
        for r in range(1, p + 1):
            steps.append(rf"Degree {r}: only $N_{{{k - r},{r}}}, \dots, N_{{{k},{r}}}$ can be "
                         "non-zero; the terms with a zero factor are left out. "
                         + "; ".join(rf"$N_{{{i},{r}}}(t) = {text} = {_num(v, 4)}$"
                                     for i, (v, text) in levels[r].items()) + ".")
        values = np.zeros(N)
        for i, (v, _) in levels[p].items():
            values[i] = v
        steps.append(rf"All {N} values, $N_{{i,{p}}}(t)$ at position $i$ (0 outside "
                     rf"$i = {k - p}, \dots, {k}$); they add up to "
                     rf"${_num(values.sum(), 4)}$.")
        return Worked(steps, values)

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

    The knots are whole numbers, and so are the two ends: they are compared exactly (``3.0`` is
    the whole number 3).

    Attributes: ``knots``, ``p``, ``i``.

    Examples
    --------
    >>> ex = BasisSupport(seed=9)
    >>> ex.check(ex.expected).status, ex.check(ex.expected.astype(float)).status
    ('correct', 'correct')
    >>> u, i, p = ex.knots, ex.i, ex.p
    >>> ex.check([u[i], u[i + p]]).diagnosis
    'one span short'
    """

    title = "Where a basis function is non-zero"
    answer_form = "vector"
    what = "the interval"
    advice = (r"$N_{i,p}$ is built from $N_{i,0}, \dots, N_{i+p,0}$, the indicators of the "
            r"$p + 1$ spans from $u_i$ to $u_{i+p+1}$.")

    def draw(self, rng):
        self.p = int(pick(rng, (1, 2, 3)))
        n_control = self.p + int(pick(rng, (3, 4, 5, 6)))
        self.knots = _integer_knots(rng, n_control, self.p, gaps=(1, 1, 2, 3))
        self.i = int(rng.integers(0, n_control))
        u, i, p = self.knots, self.i, self.p
        self.expected = np.array([u[i], u[i + p + 1]]).astype(int)     # whole: compared exactly

    def hints(self):
        u, i, p = self.knots, self.i, self.p
        return [
            r"$N_{i,p}$ is built from the degree-0 functions $N_{i,0}, \dots, N_{i+p,0}$, the "
            r"indicators of $p + 1$ consecutive knot spans: that is where it can be non-zero.",
            rf"So $N_{{i,p}}$ lives on $[u_i, u_{{i+p+1}})$; here the end index is "
            rf"$i + p + 1 = {i} + {p} + 1 = {i + p + 1}$.",
            rf"Look the knots up in $U$, counting from 0: $u_{{{i}}} = {_num(u[i])}$; the end is "
            rf"entry {i + p + 1}.",
        ]

    def worked(self):
        u, i, p = self.knots, self.i, self.p
        start, end = u[i], u[i + p + 1]
        return Worked([
            rf"$N_{{{i},{p}}}$ is made of $N_{{{i},0}}, \dots, N_{{{i + p},0}}$: it is non-zero "
            rf"on the $p + 1 = {p + 1}$ knot spans from $u_{{{i}}}$ to "
            rf"$u_{{i+p+1}} = u_{{{i + p + 1}}}$.",
            rf"In $U$ (counted from 0): $u_{{{i}}} = {_num(start)}$ and "
            rf"$u_{{{i + p + 1}}} = {_num(end)}$.",
            rf"The support is $[{_num(start)}, {_num(end)}]$.",
        ], [int(start), int(end)])

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
    there (local control). The indices are whole numbers, compared exactly (``3.0`` is 3); the
    span one too low or one too high (:math:`k \mp 1`) is diagnosed as ``"span k-1"`` or
    ``"span k+1"``.

    Attributes: ``knots``, ``p``, ``n_control``, ``t``, ``span`` (k).

    Examples
    --------
    >>> ex = ActiveControlPoints(seed=10)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> ex.check(list(range(ex.n_control))).diagnosis
    'global control'
    >>> k, p = ex.span, ex.p
    >>> ex.check([float(i) for i in range(k - p, k + 1)]).status
    'correct'
    >>> ex.check(list(range(k - p - 1, k))).diagnosis          # P_{k-p-1}, ..., P_{k-1}
    'span k-1'
    >>> ex = ActiveControlPoints(seed=13)
    >>> k, p = ex.span, ex.p
    >>> ex.check(list(range(k - p + 1, k + 2))).diagnosis      # P_{k-p+1}, ..., P_{k+1}
    'span k+1'
    >>> ex.check(...).status, ex.check("all").status
    ('unanswered', 'invalid')
    """

    title = "Which control points matter at t"
    answer_form = "custom"

    def draw(self, rng):
        self.p = int(pick(rng, (1, 2, 3)))
        self.n_control = self.p + int(pick(rng, (3, 4, 5, 6, 7)))
        self.knots = _integer_knots(rng, self.n_control, self.p)
        self.t = _inside_span(rng, self.knots, self.p)
        self.span = curves.find_span(self.knots, self.p, self.t)
        k, p = self.span, self.p
        self.expected = set(range(k - p, k + 1))

    def hints(self):
        p, t = self.p, self.t
        k = _span_of(self.knots, t)
        return [
            r"Local control: $N_{i,p}$ is non-zero only on $[u_i, u_{i+p+1})$, so at one $t$ "
            rf"just $p + 1 = {p + 1}$ basis functions, and so {p + 1} control points, are "
            "active.",
            r"Find the knot span $[u_k, u_{k+1})$ that contains $t$, with $u_k \le t < u_{k+1}$ "
            r"(counting the knots from 0; with repeated knots take the last $k$ with "
            r"$u_k \le t$). The active control points are then $P_{k-p}, \dots, P_k$.",
            _span_words(self.knots, k, t) + ".",
        ]

    def worked(self):
        p, t = self.p, self.t
        k = _span_of(self.knots, t)
        active = list(range(k - p, k + 1))
        return Worked([
            _span_words(self.knots, k, t) + ".",
            rf"The non-zero basis functions there are $N_{{k-p,p}}, \dots, N_{{k,p}}$, "
            rf"with $k - p = {k - p}$; so the {p + 1} active control points are "
            + ", ".join(f"$P_{{{i}}}$" for i in active) + ".",
        ], active)

    def mistakes(self):
        k, p, N = self.span, self.p, self.n_control
        u, t = self.knots, self.t
        where = (rf"Here $u_{{{k}}} = {_num(u[k])} \le t = {_num(t)} < u_{{{k + 1}}} = "
                 rf"{_num(u[k + 1])}$, so $k = {k}$ and the active control points are "
                 rf"$P_{{{k - p}}}, \dots, P_{{{k}}}$.")
        span_up = (r"You took the knot span one too far, $k + 1$: the control points "
                   r"$P_{k-p+1}, \dots, P_{k+1}$. The span of $t$ is $[u_k, u_{k+1})$ with "
                   r"$u_k \le t$, counting the knots from 0 (naming the span by its right end, "
                   r"or counting from 1, gives $k + 1$). " + where)
        span_down = (r"You took the knot span one too low, $k - 1$: the control points "
                     r"$P_{k-p-1}, \dots, P_{k-1}$. That span, $[u_{k-1}, u_k)$, ends before "
                     r"$t$; the span of $t$ starts at the **last** knot at or below $t$ and "
                     r"ends at the first knot above it. " + where)
        few = (r"One control point is missing: a B-spline of degree $p$ has $p + 1$ active "
               r"control points on every knot span, $P_{k-p}, \dots, P_k$ for the span "
               r"$[u_k, u_{k+1})$.")
        many = (r"One control point too many: exactly $p + 1$ control points act on a knot "
                r"span, $P_{k-p}, \dots, P_k$ for $t \in [u_k, u_{k+1})$.")
        candidates = [
            Mistake(set(range(k - p + 1, k + 2)), span_up, "span k+1", numeric=False),
            Mistake(set(range(k - p - 1, k)), span_down, "span k-1", numeric=False),
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

    The slips anticipated include a knot span off by one: de Boor's algorithm run on the span
    :math:`k - 1` or :math:`k + 1` instead of :math:`k` (``"span k-1"``, ``"span k+1"``: the
    polynomial piece of the neighbouring span, extrapolated to t), and the right weights put on
    the control points :math:`P_{k-p+1}, \dots, P_{k+1}` (or :math:`P_{k-p-1}, \dots,
    P_{k-1}`), ``"points shifted"``.

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
    advice = (r"Find the span $[u_k, u_{k+1})$ of $t$, start from $P_{k-p}, \dots, P_k$ and "
            r"blend $p$ times with $\alpha_i = \frac{t - u_i}{u_{i+p+1-r} - u_i}$ (or add up "
            r"$N_{i,p}(t)\,P_i$ with the Cox-de Boor values).")

    def draw(self, rng):
        self.p = int(pick(rng, (2, 2, 3)))
        n_control = self.p + int(pick(rng, (2, 3)))
        self.P = _control_polygon(rng, n_control)
        self.knots = _integer_knots(rng, n_control, self.p)
        self.t = _inside_span(rng, self.knots, self.p)
        self.expected = curves.bspline(self.P, self.knots, self.p, self.t)

    def _de_boor_steps(self, levels):
        """The worked solution's lines for de Boor's levels (from :func:`_de_boor_by_hand`)."""
        u, p, t = self.knots, self.p, self.t
        steps = []
        for r, level in enumerate(levels[1:], start=1):
            parts = []
            for i, alpha, point in level:
                parts.append(rf"$\alpha_{{{i}}} = \frac{{{_num(t)} - {_num(u[i])}}}"
                             rf"{{{_num(u[i + p + 1 - r])} - {_num(u[i])}}} = "
                             rf"{_frac(alpha)}$, $d_{{{i}}}^{{{r}}} = {_vec(point)}$")
            steps.append(rf"Level {r} ($\alpha_i = \frac{{t - u_i}}{{u_{{i+{p + 1 - r}}} - "
                         r"u_i}$, $d_i^r = (1 - \alpha_i)\,d_{i-1}^{r-1} + \alpha_i\,"
                         r"d_i^{r-1}$): " + "; ".join(parts) + ".")
        return steps

    def hints(self):
        P, u, p, t = self.P, self.knots, self.p, self.t
        k = _span_of(u, t)
        levels = _de_boor_by_hand(P, u, p, t, k)
        start = ", ".join(rf"$P_{{{i}}} = {_vec(P[i])}$" for i in range(k - p, k + 1))
        first = "; ".join(rf"$\alpha_{{{i}}} = {_frac(alpha)}$, $d_{{{i}}}^1 = {_vec(point)}$"
                          for i, alpha, point in levels[1])
        return [
            r"Only $p + 1$ control points act at $t$: find the knot span $[u_k, u_{k+1})$ that "
            r"contains $t$ and start de Boor's algorithm from $P_{k-p}, \dots, P_k$.",
            _span_words(u, k, t) + f"; start from {start}. At level $r$ blend neighbours, "
            r"$d_i^r = (1 - \alpha_i)\,d_{i-1}^{r-1} + \alpha_i\,d_i^{r-1}$ for "
            r"$i = k - p + r, \dots, k$, with $\alpha_i = \frac{t - u_i}{u_{i+p+1-r} - u_i}$.",
            "Level 1 here: " + first + (". With $p = 1$ that is already the point." if p == 1
                                        else f". {p - 1} more level{'s' if p > 2 else ''} "
                                        "to go, each one point shorter."),
        ]

    def worked(self):
        P, u, p, t = self.P, self.knots, self.p, self.t
        k = _span_of(u, t)
        levels = _de_boor_by_hand(P, u, p, t, k)
        steps = [_span_words(u, k, t) + rf": the active control points are "
                 rf"$d_i^0 = P_i$ for $i = {k - p}, \dots, {k}$: "
                 + ", ".join(rf"${_vec(point)}$" for _, _, point in levels[0]) + "."]
        steps += self._de_boor_steps(levels)
        point = levels[p][0][2]
        steps.append(rf"The last level has one point: $C({_num(t)}) = d_{{{k}}}^{{{p}}} = "
                     rf"{_vec(point)}$.")
        return Worked(steps, point)

    def mistakes(self):
        P, u, p, t = self.P, self.knots, self.p, self.t
        n_control = len(P)
        a, b = u[p], u[n_control]
        k = curves.find_span(u, p, t)
        local = (t - u[k]) / (u[k + 1] - u[k])
        found = []
        where = (rf"The span of $t$ is $[u_k, u_{{k+1}})$ with $u_k \le t < u_{{k+1}}$, counting "
                 rf"the knots from 0: here $u_{{{k}}} = {_num(u[k])} \le {_num(t)} < "
                 rf"u_{{{k + 1}}} = {_num(u[k + 1])}$, so $k = {k}$ and de Boor's algorithm "
                 rf"starts from $P_{{{k - p}}}, \dots, P_{{{k}}}$.")
        for other, key, words in ((k + 1, "span k+1", "one too far, $k + 1$"),
                                  (k - 1, "span k-1", "one too low, $k - 1$")):
            if not p <= other < n_control:
                continue
            levels = _de_boor_by_hand(P, u, p, t, other)
            if levels is None:                      # an empty span: nobody computes that
                continue
            found.append(Mistake(levels[p][0][2], rf"You ran de Boor's algorithm on the knot "
                                 rf"span {words}: its control points and ratios belong to the "
                                 r"neighbouring polynomial piece, which you evaluated outside "
                                 r"its own span (one of your $\alpha_i$ was then below 0 or "
                                 r"above 1: a sure sign of the wrong span). " + where, key))
        weights = curves.bspline_basis(u, p, t)
        for shift in (1, -1):
            if 0 <= k - p + shift and k + shift < n_control:
                moved = weights[k - p:k + 1] @ P[k - p + shift:k + 1 + shift]
                found.append(Mistake(moved, r"Your weights are right, but they sit on the wrong "
                                     r"control points, shifted by one: $N_{i,p}(t)$ belongs to "
                                     r"$P_i$ itself. " + where, "points shifted"))
        return found + [
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
