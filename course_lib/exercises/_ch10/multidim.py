r"""Chapter 10 exercises: multidimensional data (textbook 10.7).

Reading correlations from parallel coordinates; the point-line duality (a point's line, and
where the lines of the points of a line meet); which records a brush selects; the vertex of a
star glyph. (Principal component analysis by hand is in :mod:`.pca`.)

Conventions (those of :mod:`course_lib.dataviz`): an axis of parallel coordinates spans its
attribute's range normalised to [0, 1]; between two adjacent axes the first is at ``u = 0``,
the second at ``u = 1``.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import math

import numpy as np

from ...dataviz import multidim as md
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, data_note,
                    has_placeholder, is_unanswered, pick)
from . import _Chapter10, _num, _paren

__all__ = [
    "BrushSelection",
    "DualLine",
    "DualPoint",
    "ReadParallelCoordinates",
    "StarGlyphVertex",
]


def _n4(x):
    return _num(x, 4)


# ---------------------------------------------------------------------------------------------
# Reading correlations from parallel coordinates
# ---------------------------------------------------------------------------------------------

_RELATIONS = ("positive", "negative", "none")
_SYNONYMS = {"positive": "positive", "+": "positive", "negative": "negative", "-": "negative",
             "none": "none", "no": "none", "uncorrelated": "none", "zero": "none"}


def _crossings(a, b):
    """How many pairs of lines cross between two axes with the heights `a` and `b`."""
    n = len(a)
    return sum(1 for i in range(n) for k in range(i + 1, n) if (a[i] - a[k]) * (b[i] - b[k]) < 0)


def _verdict(crossings, pairs):
    """The relation the crossings show: (nearly) none positive, (nearly) all negative."""
    if crossings <= pairs // 5:
        return "positive"
    if crossings >= pairs - pairs // 5:
        return "negative"
    return "none"


def _top_down(heights):
    """The records (numbered from 1) from the top of an axis to its bottom."""
    return ", ".join(str(int(i) + 1) for i in np.argsort(-np.asarray(heights), kind="stable"))


class ReadParallelCoordinates(_Chapter10):
    r"""Read the correlation of each pair of adjacent axes from the polylines of parallel
    coordinates.

    Between two adjacent axes, two records' lines cross exactly when the records are in the
    opposite order on the two attributes. No (or nearly no) crossings: a positive correlation;
    (nearly) all pairs crossing, at one point between the axes: negative; about half: none.

    Attributes: ``names`` (the four axes), ``heights`` (5 records x 4 axes, each in [0, 1]).

    Examples
    --------
    >>> ex = ReadParallelCoordinates(seed=0)
    >>> ex.check(list(ex.expected)).status
    'correct'
    >>> swap = {"positive": "negative", "negative": "positive", "none": "none"}
    >>> ex.check([swap[w] for w in ex.expected]).diagnosis
    'crossings read as positive'
    >>> ex.check("positive").status
    'invalid'
    """

    title = "Read a parallel-coordinates plot"
    answer_form = "custom"

    def draw(self, rng):
        self.names = ("A", "B", "C", "D")
        kinds = [str(k) for k in rng.choice(_RELATIONS, size=3)]

        def levels():                 # 5 heights in tenths, the lowest 0 and the highest 1
            inner = np.sort(rng.choice(np.arange(1, 10), 3, replace=False)) / 10
            return np.r_[0.0, inner, 1.0]

        columns = [levels()[rng.permutation(5)]]
        for kind in kinds:
            previous = columns[-1]
            rank = np.argsort(np.argsort(previous, kind="stable"), kind="stable")
            while True:
                if kind == "none":
                    new = rng.permutation(5)
                else:
                    new = rank.copy() if kind == "positive" else 4 - rank
                    if rng.uniform() < 0.5:                 # one pair out of line
                        r = int(rng.integers(0, 4))
                        a, b = np.flatnonzero(new == r)[0], np.flatnonzero(new == r + 1)[0]
                        new[a], new[b] = r + 1, r
                column = levels()[new]
                if _verdict(_crossings(previous, column), 10) == kind:
                    break
            columns.append(column)
        self.heights = np.column_stack(columns)
        self.expected = tuple(self._verdicts())

    def _verdicts(self):
        h = self.heights
        return [_verdict(_crossings(h[:, j], h[:, j + 1]), 10) for j in range(3)]

    def acceptable(self):
        return any(k != "none" for k in self.expected)

    def separated(self, mistakes):
        return True

    def _swapped(self):
        swap = {"positive": "negative", "negative": "positive", "none": "none"}
        return tuple(swap[k] for k in self.expected)

    def _pair(self, j):
        return f"{self.names[j]}–{self.names[j + 1]}"

    def _reason(self, j):
        h = self.heights
        count = _crossings(h[:, j], h[:, j + 1])
        verdict = self.expected[j]
        why = {"positive": "the records keep (nearly) their order: high with high, low with low",
               "negative": "the order (nearly) reverses: the lines meet near one point between "
                           "the axes",
               "none": "about half of the pairs swap: the order on one axis says little about "
                       "the other"}[verdict]
        return (f"{self._pair(j)}: top to bottom the records are {_top_down(h[:, j])} on "
                f"{self.names[j]} and {_top_down(h[:, j + 1])} on {self.names[j + 1]}; "
                f"{count} of the 10 pairs of lines cross, so **{verdict}** ({why}).")

    def hints(self):
        h = self.heights
        return [
            "Look at one pair of adjacent axes at a time. Two lines cross between the axes "
            "exactly when the two records are in opposite order on the two attributes.",
            "With 5 records there are 10 pairs of lines. No or one crossing: positive; nine or "
            "ten (the lines squeeze through one point between the axes): negative; about half: "
            "no correlation.",
            f"For {self._pair(0)}: the records top to bottom are {_top_down(h[:, 0])} on "
            f"{self.names[0]} and {_top_down(h[:, 1])} on {self.names[1]}. Count the pairs "
            "whose order differs.",
        ]

    def worked(self):
        return Worked([self._reason(j) for j in range(3)], list(self._verdicts()))

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        form = ("Answer with a list of 3 words, one per pair of adjacent axes (A–B, B–C, C–D), "
                "each `'positive'`, `'negative'` or `'none'`.")
        if isinstance(answer, (str, bytes, dict)) or not isinstance(answer, (list, tuple)) \
                or len(answer) != 3 or not all(isinstance(a, str) for a in answer):
            return Feedback("invalid", form, "unreadable")
        words = [_SYNONYMS.get(a.strip().lower()) for a in answer]
        if None in words:
            return Feedback("invalid", form, "unreadable")
        if tuple(words) == self.expected:
            return Feedback("correct", "Right: " + " ".join(self._reason(j) for j in range(3)))
        if tuple(words) == self._swapped():
            return Feedback("wrong", "You read crossing lines as a positive correlation and "
                            "parallel lines as a negative one: it is the other way round. If "
                            "high values go with high values, each record's line runs from "
                            "high to high and the lines stay side by side; a negative relation "
                            "sends the highest record to the bottom, so all lines cross "
                            "between the axes.", "crossings read as positive")
        j = next(j for j in range(3) if words[j] != self.expected[j])
        return Feedback("wrong", f"Not for every pair. {self._reason(j)}",
                        f"{self._pair(j)}: {words[j]} instead of {self.expected[j]}")

    def statement(self):
        rows = "\n".join(f"| {i + 1} | " + " | ".join(_num(v, 2) for v in row) + " |"
                         for i, row in enumerate(self.heights))
        return (
            r"A parallel-coordinates plot shows 5 records on four parallel vertical axes A, B, "
            r"C, D (in this order, each normalised to its own range: 0 at the bottom, 1 at the "
            r"top). The table gives the height at which each record's polyline meets each "
            r"axis." "\n\n| record | A | B | C | D |\n|---|---|---|---|---|\n" + rows + "\n\n"
            r"For each pair of **adjacent** axes (A–B, B–C, C–D), is the correlation between "
            r"the two attributes positive, negative, or is there none?" "\n\n"
            r"**Answer:** a list of 3 words, e.g. `['positive', 'none', 'negative']`." "\n\n"
            + data_note("names", "heights"))


# ---------------------------------------------------------------------------------------------
# The point-line duality
# ---------------------------------------------------------------------------------------------

_RANGES = ((0, 10), (0, 20), (0, 40), (0, 50), (0, 100), (10, 30), (20, 60), (-10, 30),
           (100, 300), (-20, 20))
_FRACTIONS = (0.0, 0.2, 0.25, 0.4, 0.5, 0.6, 0.75, 0.8, 1.0)


def _axes_words(x_range, y_range):
    return (rf"The x axis stands at $u = 0$ and spans $[{_num(x_range[0])}, "
            rf"{_num(x_range[1])}]$ (bottom to top), the y axis at $u = 1$ and spans "
            rf"$[{_num(y_range[0])}, {_num(y_range[1])}]$; each is normalised to heights "
            r"$v \in [0, 1]$.")


class DualLine(_Chapter10):
    r"""The line a 2D point becomes between two adjacent parallel axes.

    With ``a' = (a - x_min)/(x_max - x_min)`` and ``b'`` likewise, the record ``(a, b)`` is
    the segment of :math:`v(u) = a' + (b' - a')\,u` from ``(0, a')`` to ``(1, b')``.

    Attributes: ``x_range``, ``y_range`` (the axes' spans), ``point`` (a, b).

    Examples
    --------
    >>> ex = DualLine(seed=3)
    >>> ex.check(list(md.dual_line(ex.point, ex.x_range, ex.y_range))).status
    'correct'
    >>> a, b = ex.point
    >>> ex.check([b - a, a]).diagnosis
    'not normalised'
    """

    title = "A point as a line in parallel coordinates"
    answer_form = "vector"
    what = "the slope and intercept"
    may_coincide = ("divided by the maximum",)
    advice = (r"Normalise each value on its own axis, $a' = \frac{a - x_{min}}{x_{max} - "
              r"x_{min}}$, $b'$ likewise; the line from $(0, a')$ to $(1, b')$ is "
              r"$v = a' + (b' - a')u$.")

    def draw(self, rng):
        self.x_range = tuple(float(v) for v in pick(rng, _RANGES))
        self.y_range = tuple(float(v) for v in pick(rng, _RANGES))
        fa, fb = (float(v) for v in rng.choice(_FRACTIONS, 2, replace=False))
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        self.point = (xl + fa * (xh - xl), yl + fb * (yh - yl))
        self.expected = np.array(md.dual_line(self.point, self.x_range, self.y_range))

    def _normalised(self):
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        a, b = self.point
        return (a - xl) / (xh - xl), (b - yl) / (yh - yl)

    def mistakes(self):
        a, b = self.point
        an, bn = self._normalised()
        found = [
            Mistake([b - a, a], r"You used the raw values $a$ and $b$. Each axis has its own "
                    r"range: normalise first, $a' = (a - x_{min})/(x_{max} - x_{min})$ and "
                    r"$b' = (b - y_{min})/(y_{max} - y_{min})$, then $v = a' + (b' - a')u$.",
                    "not normalised"),
            Mistake([an - bn, bn], r"The axes are swapped: at $u = 0$ the line meets the "
                    r"**x** axis at height $a'$, at $u = 1$ the y axis at $b'$; so the "
                    r"intercept is $a'$ and the slope $b' - a'$.", "axes swapped"),
        ]
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        if (xl != 0 or yl != 0) and xh != 0 and yh != 0:
            found.append(Mistake([b / yh - a / xh, a / xh], r"You divided by the maximum of "
                                 r"each range instead of its width: subtract the minimum first, "
                                 r"$a' = (a - x_{min})/(x_{max} - x_{min})$.",
                                 "divided by the maximum"))
        return found

    def hints(self):
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        a, b = self.point
        an, _ = self._normalised()
        return [
            r"A record is drawn by marking its x value on the left axis and its y value on the "
            r"right one and joining the two marks: find the two heights.",
            rf"The height on the x axis: $a' = ({_num(a)} - {_paren(xl)}) / ({_num(xh)} - "
            rf"{_paren(xl)}) = {_n4(an)}$; do the same for $b = {_num(b)}$ on $[{_num(yl)}, "
            rf"{_num(yh)}]$.",
            r"The line through $(0, a')$ and $(1, b')$ has intercept $a'$ and slope "
            r"$b' - a'$.",
        ]

    def worked(self):
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        a, b = self.point
        an = (a - xl) / (xh - xl)
        bn = (b - yl) / (yh - yl)
        return Worked([
            rf"On the x axis: $a' = \frac{{{_num(a)} - {_paren(xl)}}}{{{_num(xh)} - "
            rf"{_paren(xl)}}} = {_n4(an)}$.",
            rf"On the y axis: $b' = \frac{{{_num(b)} - {_paren(yl)}}}{{{_num(yh)} - "
            rf"{_paren(yl)}}} = {_n4(bn)}$.",
            rf"The line from $(0, {_n4(an)})$ to $(1, {_n4(bn)})$: $v = {_n4(an)} + "
            rf"({_n4(bn)} - {_n4(an)})\,u$, slope ${_n4(bn - an)}$, intercept ${_n4(an)}$.",
        ], np.array([bn - an, an]))

    def statement(self):
        a, b = self.point
        return (
            r"Two adjacent axes of a parallel-coordinates plot show the attributes x and y. "
            + _axes_words(self.x_range, self.y_range)
            + rf" The record $(x, y) = ({_num(a)}, {_num(b)})$ becomes a segment between the "
            r"axes. Write it as the line $v(u) = p + q\,u$ in the $(u, v)$ plane of the plot."
            "\n\n"
            r"**Answer:** the list `[q, p]` (slope, then intercept). " + DECIMALS + "\n\n"
            + data_note("x_range", "y_range", "point"))


_SLOPES = (-3.0, -2.0, -1.0, -0.5, -1 / 3, 1 / 3, 0.5, 2.0, 3.0)
_INTERCEPTS = (0.0, 0.2, 0.25, 0.4, 0.5, 0.6, 0.75)


class DualPoint(_Chapter10):
    r"""Where the parallel-coordinate lines of the points of ``y = m x + c`` meet.

    In normalised units the relation is ``b' = m' a' + c'`` with ``m' = m (x_max - x_min) /
    (y_max - y_min)`` and ``c' = (m x_min + c - y_min)/(y_max - y_min)``; the lines
    ``v = a' + (b' - a') u`` all pass through :math:`(1/(1 - m'),\ c'/(1 - m'))`.

    Attributes: ``x_range``, ``y_range``, ``m``, ``c``.

    Examples
    --------
    >>> ex = DualPoint(seed=1)
    >>> ex.check(list(md.dual_point(ex.m, ex.c, ex.x_range, ex.y_range))).status
    'correct'
    """

    title = "Where the lines of a linear relation meet"
    answer_form = "vector"
    what = "the point (u, v)"
    advice = (r"Write the relation in normalised units, $b' = m' a' + c'$; the line of a point "
              r"is $v = a' + (m' a' + c' - a') u$, and it no longer depends on $a'$ where "
              r"$1 + (m' - 1)u = 0$.")

    def draw(self, rng):
        while True:
            self.x_range = tuple(float(v) for v in pick(rng, _RANGES))
            self.y_range = tuple(float(v) for v in pick(rng, _RANGES))
            mn = float(pick(rng, _SLOPES))
            cn = float(pick(rng, _INTERCEPTS))
            (xl, xh), (yl, yh) = self.x_range, self.y_range
            m = mn * (yh - yl) / (xh - xl)
            if abs(m - round(m, 2)) < 1e-9 and abs(m) <= 20:
                break
        self.m = round(m, 2)
        self.c = round(cn * (yh - yl) + yl - self.m * xl, 6)
        self.expected = np.array(md.dual_point(self.m, self.c, self.x_range, self.y_range))

    def _normalised(self):
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        mn = self.m * (xh - xl) / (yh - yl)
        cn = (self.m * xl + self.c - yl) / (yh - yl)
        return mn, cn

    def acceptable(self):
        mn, _ = self._normalised()
        return abs(self.m - mn) > 0.2 and abs(self.m - 1) > 0.2

    def mistakes(self):
        mn, cn = self._normalised()
        found = [
            Mistake([1 / (1 - self.m), cn / (1 - self.m)], r"You used the slope $m$ in data "
                    r"units. The plot normalises each axis to its own range, so the slope that "
                    r"counts is $m' = m\,(x_{max} - x_{min})/(y_{max} - y_{min})$.",
                    "slope not normalised"),
            Mistake([1 / (1 - mn), self.c / (1 - mn)], r"The height uses $c$ in data units; "
                    r"it must be the normalised intercept $c' = (m\,x_{min} + c - y_{min})/"
                    r"(y_{max} - y_{min})$, the height at which the point $x = x_{min}$ of the "
                    r"relation meets the y axis.", "intercept not normalised"),
        ]
        if abs(1 + mn) > 0.2:
            found.append(Mistake([1 / (1 + mn), cn / (1 + mn)], r"A sign slipped: the lines "
                                 r"$v = a'(1 + (m' - 1)u) + c'u$ lose their dependence on $a'$ "
                                 r"where $1 + (m' - 1)u = 0$, that is $u = 1/(1 - m')$.",
                                 "sign of the slope"))
        return found

    def hints(self):
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        mn, cn = self._normalised()
        return [
            r"Every point $(a, b)$ of the relation is a line $v = a' + (b' - a')u$ between the "
            r"axes. Find the one point all of these lines share.",
            rf"In normalised units $b' = m' a' + c'$ with $m' = {_num(self.m)} \cdot "
            rf"{_num(xh - xl)} / {_num(yh - yl)} = {_n4(mn)}$ and $c' = ({_num(self.m)} \cdot "
            rf"{_paren(xl)} + {_paren(self.c)} - {_paren(yl)}) / {_num(yh - yl)} = {_n4(cn)}$.",
            r"Substitute: $v = a'\,(1 + (m' - 1)u) + c' u$. At $u = 1/(1 - m')$ the bracket "
            r"vanishes and $v = c' u$ for every $a'$.",
        ]

    def worked(self):
        (xl, xh), (yl, yh) = self.x_range, self.y_range
        mn = self.m * (xh - xl) / (yh - yl)
        cn = (self.m * xl + self.c - yl) / (yh - yl)
        u = 1 / (1 - mn)
        v = cn * u
        where = ("between the axes: a negative correlation" if 0 < u < 1 else
                 "right of the y axis" if u > 1 else "left of the x axis")
        return Worked([
            rf"Normalised slope: $m' = m\,\frac{{x_{{max}} - x_{{min}}}}{{y_{{max}} - "
            rf"y_{{min}}}} = {_num(self.m)} \cdot \frac{{{_num(xh - xl)}}}{{{_num(yh - yl)}}} "
            rf"= {_n4(mn)}$.",
            rf"Normalised intercept: $c' = \frac{{m\,x_{{min}} + c - y_{{min}}}}{{y_{{max}} - "
            rf"y_{{min}}}} = {_n4(cn)}$.",
            rf"$u = \frac{{1}}{{1 - m'}} = {_n4(u)}$ ({where}), $v = c' u = {_n4(v)}$.",
        ], np.array([u, v]))

    def statement(self):
        return (
            r"Many records $(x, y)$ lie on the straight line $y = "
            rf"{_num(self.m)}\,x {'+' if self.c >= 0 else '-'} {_num(abs(self.c))}$. They are "
            r"drawn in parallel coordinates on two adjacent axes with **fixed** ranges (not "
            r"the data's own minimum and maximum). " + _axes_words(self.x_range, self.y_range)
            + r" All their lines pass through one point $(u, v)$ of the plot. Where?" "\n\n"
            r"**Answer:** the list `[u, v]`. " + DECIMALS + "\n\n"
            + data_note("x_range", "y_range", "m", "c"))


# ---------------------------------------------------------------------------------------------
# Brushing
# ---------------------------------------------------------------------------------------------

_TABLES = (
    (("mpg", "horsepower", "weight"), ((12, 40, 2), (60, 200, 10), (800, 2000, 100))),
    (("temperature", "humidity", "wind"), ((-5, 35, 5), (20, 100, 10), (0, 20, 2))),
    (("height", "weight", "age"), ((150, 200, 5), (50, 110, 5), (18, 70, 4))),
    (("price", "area", "rooms"), ((100, 500, 25), (40, 200, 10), (1, 8, 1))),
)


def _record_set(answer, n):
    """The record numbers (1 to n) of an answer as a set, or a Feedback."""
    if is_unanswered(answer) or (isinstance(answer, (list, tuple))
                                 and any(a is Ellipsis for a in answer)):
        return Feedback("unanswered", UNANSWERED)
    form = ("Give the record numbers as a list of whole numbers, e.g. `[2, 5]` (`[]` if none "
            "is selected).")
    if isinstance(answer, (str, bytes, dict)):
        return Feedback("invalid", form, "unreadable")
    try:
        items = list(answer)
    except TypeError:
        items = [answer]
    found = set()
    for item in items:
        if isinstance(item, (bool, np.bool_)) or not isinstance(
                item, (int, np.integer, float, np.floating)) or not math.isfinite(item) \
                or not float(item).is_integer():
            return Feedback("invalid", form, "unreadable")
        found.add(int(item))
    return found


class BrushSelection(_Chapter10):
    r"""Which records two brushes select, combined with AND or OR.

    A brush on an attribute selects the records whose value lies in its range, bounds
    included; two brushes combine with AND (in both) or OR (in either).

    Attributes: ``names`` (the attributes), ``table`` (8 records x 3 values), ``brushes``
    (two ``(attribute, low, high)``), ``how`` ("AND" or "OR").

    Examples
    --------
    >>> ex = BrushSelection(seed=2)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> ex.check(sorted(set(range(1, 9)) - ex.expected)).diagnosis
    'complement'
    """

    title = "Which records does the brush select?"
    answer_form = "custom"

    def draw(self, rng):
        self.names, specs = pick(rng, _TABLES)
        columns = []
        for low, high, step in specs:
            grid = np.arange(low, high + step / 2, step)
            columns.append(rng.choice(grid, size=8))
        self.table = np.column_stack(columns).astype(float)
        first, second = (int(k) for k in rng.choice(3, 2, replace=False))
        self.brushes = []
        for k in (first, second):
            values = np.unique(self.table[:, k])
            i = int(rng.integers(0, max(1, len(values) - 2)))
            j = int(rng.integers(i + 1, min(len(values), i + 4)))
            self.brushes.append((self.names[k], float(values[i]), float(values[j])))
        self.how = str(pick(rng, ("AND", "OR")))
        self.expected = self._select(self.how)

    def _masks(self, strict=False):
        out = []
        for name, lo, hi in self.brushes:
            column = self.table[:, self.names.index(name)]
            out.append((column > lo) & (column < hi) if strict else (column >= lo) & (column <= hi))
        return out

    def _select(self, how, strict=False):
        a, b = self._masks(strict)
        mask = (a & b) if how == "AND" else (a | b)
        return {int(i) + 1 for i in np.flatnonzero(mask)}

    def mistakes(self):
        other = "OR" if self.how == "AND" else "AND"
        return [
            Mistake(self._select(other), f"That is the {other} of the two brushes. With "
                    f"{self.how} a record must be "
                    + ("inside **both** ranges." if self.how == "AND" else
                       "inside **at least one** of the ranges.")
                    + " Tick each record's two conditions and combine them as asked.",
                    "AND and OR swapped", numeric=False),
            Mistake(self._select(self.how, strict=True), "A record whose value equals a bound "
                    "of a brush is inside it: the ranges include their ends (low ≤ value ≤ "
                    "high).", "bounds excluded", numeric=False),
            Mistake(set(range(1, 9)) - self.expected, "Those are the records the brushes do "
                    "**not** select: the brush highlights the records inside it.",
                    "complement", numeric=False),
        ]

    def acceptable(self):
        if not 0 < len(self.expected) < 8:
            return False
        values = [m.value for m in self.mistakes()]
        return all(v != self.expected for v in values) and len({frozenset(v) for v in values}) \
            == len(values)

    def separated(self, mistakes):
        return True

    def keep(self, mistakes):
        return list(mistakes)

    def _check(self, answer):
        value = _record_set(answer, 8)
        if isinstance(value, Feedback):
            return value
        if value == self.expected:
            return Feedback("correct", f"Right: records {_listed(self.expected)}.")
        for mistake in self._mistakes:
            if value == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        outside = sorted(i for i in value if not 1 <= i <= 8)
        if outside:
            return Feedback("wrong", f"There is no record {outside[0]}: they are numbered 1 to 8.",
                            "out of range")
        missing, extra = sorted(self.expected - value), sorted(value - self.expected)
        parts = ([f"{_listed(extra)} should not be selected"] if extra else []) \
            + ([f"{_listed(missing)} {'is' if len(missing) == 1 else 'are'} missing"]
               if missing else [])
        return Feedback("wrong", "Not quite: " + " and ".join(parts) + ". Check each record's "
                        "value against both ranges (ends included).", "records differ")

    def _brush_words(self, k):
        name, lo, hi = self.brushes[k]
        return rf"${_num(lo)} \le \text{{{name}}} \le {_num(hi)}$"

    def hints(self):
        a, b = self._masks()
        first = [int(i) + 1 for i in np.flatnonzero(a)]
        return [
            "Go through the records one by one and tick, for each brush, whether the record's "
            "value lies in its range (the ends count as inside).",
            f"Brush 1 ({self._brush_words(0)}) holds records {_listed(first)}.",
            f"Now brush 2, then combine: {self.how} keeps a record "
            + ("only if both ticks are there." if self.how == "AND" else
               "if at least one tick is there."),
        ]

    def worked(self):
        a, b = self._masks()
        one = {int(i) + 1 for i in np.flatnonzero(a)}
        two = {int(i) + 1 for i in np.flatnonzero(b)}
        result = (one & two) if self.how == "AND" else (one | two)
        return Worked([
            f"Brush 1, {self._brush_words(0)}: records {_listed(one)}.",
            f"Brush 2, {self._brush_words(1)}: records {_listed(two)}.",
            f"{self.how}: " + ("the records in both lists" if self.how == "AND" else
                                "the records in either list") + f": {_listed(result)}.",
        ], sorted(result))

    def statement(self):
        header = "| record | " + " | ".join(self.names) + " |"
        rule = "|---" * 4 + "|"
        rows = "\n".join(f"| {i + 1} | " + " | ".join(_num(v) for v in row) + " |"
                         for i, row in enumerate(self.table))
        return (
            r"A table of 8 records is shown in linked views. Two brushes are drawn: brush 1 "
            rf"selects {self._brush_words(0)} and brush 2 selects {self._brush_words(1)} "
            rf"(ends included). They are combined with **{self.how}**." "\n\n"
            + header + "\n" + rule + "\n" + rows + "\n\n"
            r"Which records are highlighted?" "\n\n"
            r"**Answer:** the list of their record numbers, e.g. `[2, 5]` (`[]` if none; the "
            r"order does not matter)." "\n\n" + data_note("names", "table", "brushes", "how"))


def _listed(numbers):
    return ", ".join(str(i) for i in sorted(numbers)) or "none"


# ---------------------------------------------------------------------------------------------
# Star glyphs
# ---------------------------------------------------------------------------------------------

_GLYPH_NAMES = ("price", "speed", "comfort", "range", "safety", "space", "noise", "weight")
_GLYPH_RANGES = ((0, 10), (0, 200), (20, 60), (100, 500), (1, 5), (0, 40), (50, 90), (10, 30))


class StarGlyphVertex(_Chapter10):
    r"""The vertex of one spoke of a star glyph.

    Spoke ``k`` (counted from 0) points at the angle :math:`90^\circ + 360^\circ k/d`
    (counter-clockwise from straight up); its vertex lies at the distance of the record's
    value normalised on the attribute's range: :math:`P_k = v'_k(\cos\theta_k, \sin\theta_k)`.

    Attributes: ``names``, ``ranges`` (the attributes' ranges), ``record`` (the values),
    ``spoke`` (the attribute asked for, counted from 1).

    Examples
    --------
    >>> ex = StarGlyphVertex(seed=0)
    >>> v = md.normalise_columns([ex.record], ranges=ex.ranges)[0]
    >>> ex.check(md.star_glyph(v)[ex.spoke - 1]).status
    'correct'
    """

    title = "A vertex of a star glyph"
    answer_form = "vector"
    what = "the vertex"
    advice = (r"Normalise the value on its attribute's range, find the spoke's angle "
              r"($90^\circ$ plus the spoke's share of $360^\circ$, counter-clockwise) and take "
              r"$v'(\cos\theta, \sin\theta)$.")

    def draw(self, rng):
        d = int(pick(rng, (4, 6, 8)))
        chosen = np.sort(rng.choice(len(_GLYPH_NAMES), d, replace=False))
        self.names = tuple(_GLYPH_NAMES[i] for i in chosen)
        self.ranges = np.array([_GLYPH_RANGES[i] for i in chosen], dtype=float)
        fractions = rng.choice(_FRACTIONS[1:], d)
        self.record = self.ranges[:, 0] + fractions * (self.ranges[:, 1] - self.ranges[:, 0])
        k = int(rng.choice([j for j in range(1, d) if 2 * j != d]))
        self.spoke = k + 1
        v = md.normalise_columns([self.record], ranges=self.ranges)[0]
        self.expected = md.star_glyph(v)[k]

    def _angle(self, clockwise=False, start=90.0):
        d, k = len(self.names), self.spoke - 1
        return math.radians(start + (-1 if clockwise else 1) * 360.0 * k / d)

    def mistakes(self):
        k = self.spoke - 1
        lo, hi = self.ranges[k]
        x = self.record[k]
        v = (x - lo) / (hi - lo)
        t = self._angle()
        direction = np.array([math.cos(t), math.sin(t)])
        found = [
            Mistake(x * direction, r"You used the raw value as the length. A star glyph draws "
                    r"every attribute on the same scale: normalise the value on its range "
                    r"first, $v' = (x - x_{min})/(x_{max} - x_{min})$.", "not normalised"),
            Mistake(v * np.array([math.cos(self._angle(True)), math.sin(self._angle(True))]),
                    r"You went round clockwise. The spokes follow each other "
                    r"counter-clockwise (the mathematical direction of positive angles), "
                    r"starting straight up.", "clockwise"),
            Mistake(v * np.array([math.cos(self._angle(start=0)), math.sin(self._angle(start=0))]),
                    r"You started at the positive x axis. Spoke 1 points straight up, at "
                    r"$90^\circ$; add the spoke's share of $360^\circ$ to that.",
                    "started at the x axis"),
            Mistake(v * direction[::-1], r"Sine and cosine are swapped: the x coordinate is "
                    r"$v'\cos\theta$ and the y coordinate $v'\sin\theta$.", "sin and cos swapped"),
        ]
        if lo != 0 and hi != 0:
            found.append(Mistake(x / hi * direction, r"You divided by the maximum instead of "
                                 r"the width of the range: subtract the minimum first.",
                                 "divided by the maximum"))
        return found

    def hints(self):
        d, k = len(self.names), self.spoke - 1
        lo, hi = self.ranges[k]
        return [
            "A star glyph has one spoke per attribute, all of length 1 for the largest "
            "possible value; the record's value on each spoke is normalised to [0, 1].",
            rf"Normalise: $v' = ({_num(self.record[k])} - {_paren(lo)}) / ({_num(hi)} - "
            rf"{_paren(lo)}) = {_n4((self.record[k] - lo) / (hi - lo))}$.",
            rf"Spoke {self.spoke} of {d} points at $90^\circ + {k} \cdot 360^\circ / {d} = "
            rf"{_num(90 + 360 * k / d)}^\circ$.",
        ]

    def worked(self):
        d, k = len(self.names), self.spoke - 1
        lo, hi = self.ranges[k]
        v = (self.record[k] - lo) / (hi - lo)
        deg = 90 + 360 * k / d
        t = math.radians(deg)
        point = np.array([v * math.cos(t), v * math.sin(t)])
        return Worked([
            rf"{self.names[k]}: $v' = \frac{{{_num(self.record[k])} - {_paren(lo)}}}"
            rf"{{{_num(hi)} - {_paren(lo)}}} = {_n4(v)}$.",
            rf"Its spoke is number {self.spoke} of {d}: $\theta = 90^\circ + {k} \cdot "
            rf"\frac{{360^\circ}}{{{d}}} = {_num(deg)}^\circ$.",
            rf"$P = {_n4(v)}\,(\cos {_num(deg)}^\circ, \sin {_num(deg)}^\circ) = "
            rf"({_n4(point[0])}, {_n4(point[1])})$.",
        ], point)

    def statement(self):
        rows = "\n".join(f"| {j + 1} | {name} | [{_num(lo)}, {_num(hi)}] | {_num(x)} |"
                         for j, (name, (lo, hi), x) in enumerate(zip(self.names, self.ranges,
                                                                      self.record)))
        return (
            rf"A star glyph shows a record with {len(self.names)} attributes: one spoke per "
            r"attribute, all of length 1, spoke 1 pointing straight up and the others following "
            r"**counter-clockwise** at equal angles. On each spoke the record's value is marked "
            r"at its distance from the centre, normalised on the attribute's range (the range's "
            r"minimum at the centre, its maximum at the tip)." "\n\n"
            "| spoke | attribute | range | value |\n|---|---|---|---|\n" + rows + "\n\n"
            rf"Where is the glyph's vertex on spoke {self.spoke} ({self.names[self.spoke - 1]}), "
            r"with the glyph's centre at the origin, x to the right and y up?" "\n\n"
            r"**Answer:** the point `[x, y]`. " + DECIMALS + "\n\n"
            + data_note("names", "ranges", "record", "spoke"))
