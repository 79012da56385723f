"""Chapter 5 exercises: Liang-Barsky.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import math

import numpy as np

from fractions import Fraction

from ... import clipping
from ..core import (DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked,
                    data_note, diagnose_matrix, diagnose_parts, latex_fraction, latex_vector,
                    parts_separated, pick, read_floats, tolerance)
from . import (ON_SIDE, PARALLEL, THROUGH_CORNER, THROUGH_EDGE, _Boundary, _boundary_segment,
               _box_words, _clip_words, _draw_box_2d, _equal_answers, _Listed, _same_segment,
               _segment_cases, _unanswered, _vec)
from .cohen_sutherland import _segment_feedback

__all__ = [
    "LiangBarskyClip3D",
    "LiangBarskyInterval",
    "LiangBarskyTable",
]


_SIDES_2D = ("left", "right", "bottom", "top")
_SIDES = ("left", "right", "bottom", "top", "near", "far")


def _lb_table(p0, p1, lo, hi):
    """Rows (p_k, q_k, t_k) for the sides in the order left, right, bottom, top (near, far)."""
    _, steps = clipping.liang_barsky_steps(p0, p1, lo, hi)
    rows = [[s["p"], s["q"], math.nan if s["t"] is None else s["t"]] for s in steps]
    delta = np.asarray(p1, float) - p0
    for bit in range(len(rows), 2 * len(lo)):   # the sides after an early rejection
        axis = bit // 2
        p = -delta[axis] if bit % 2 == 0 else delta[axis]
        q = p0[axis] - lo[axis] if bit % 2 == 0 else hi[axis] - p0[axis]
        rows.append([p, q, q / p if p else math.nan])
    return np.array(rows)


def _lb_interval(table, swap=False, clamp=True, pick=(max, min)):
    """(t_in, t_out) from a (p, q, t) table; `swap` exchanges entering and leaving."""
    entering = [t for p, q, t in table if (p < 0) != swap and p != 0]
    leaving = [t for p, q, t in table if (p > 0) != swap and p != 0]
    first, second = pick
    t_in = first(entering) if entering else 0.0
    t_out = second(leaving) if leaving else 1.0
    if clamp:
        t_in, t_out = max(0.0, t_in), min(1.0, t_out)
    return t_in, t_out


def _draw_lb_segment(rng, lo, hi, wanted):
    """A segment of whole end points, not parallel to a side, with the boundary case wanted."""
    while True:
        p0, p1 = _boundary_segment(rng, lo, hi, wanted)
        if np.all(p0 != p1):
            return p0, p1


def _rows_by_hand(p0, p1, lo, hi):
    """Liang-Barsky's table worked by hand in fractions: one row per side.

    Each row: (side, p, q, t or None); p, q, t are Fractions.
    """
    a = [Fraction(float(v)) for v in p0]
    d = [Fraction(float(b)) - x for x, b in zip(a, p1)]
    rows = []
    for k in range(len(a)):
        for upper in (False, True):
            p = d[k] if upper else -d[k]
            q = Fraction(float(hi[k])) - a[k] if upper else a[k] - Fraction(float(lo[k]))
            rows.append((_SIDES[2 * k + upper], p, q, q / p if p else None))
    return rows


def _frac(x):
    return latex_fraction(float(x))


def _paren(x):
    """A number as LaTeX, in parentheses when negative (after a minus sign)."""
    return f"({_frac(x)})" if x < 0 else _frac(x)


def _row_words(side, p, q, t, p0, lo, hi):
    """One row of the table as LaTeX: how p and q are formed, t, and what it means."""
    k = _SIDES.index(side)
    axis, upper = "xyz"[k // 2], k % 2
    if upper:
        how = (rf"$p = \Delta {axis} = {_frac(p)}$, $q = {axis}_{{max}} - {axis}_0 = "
               rf"{_frac(hi[k // 2])} - {_paren(p0[k // 2])} = {_frac(q)}$")
    else:
        how = (rf"$p = -\Delta {axis} = {_frac(p)}$, $q = {axis}_0 - {axis}_{{min}} = "
               rf"{_frac(p0[k // 2])} - {_paren(lo[k // 2])} = {_frac(q)}$")
    if t is None:
        kind = ("parallel, inside that side" if q >= 0 else
                "parallel and **outside** that side: the segment is rejected")
        return rf"{side}: {how}: $p = 0$, {kind}."
    kind = "entering" if p < 0 else "leaving"
    return rf"{side}: {how}, $t = q / p = {_frac(t)}$ ({kind})."


def _boundary_words(rows, p0, p1, lo, hi, kinds):
    """Sentences on the boundary case a segment has, among `kinds` (none for an ordinary one)."""
    out = []
    for side, p, q, t in rows if ON_SIDE in kinds else ():
        if t == 0:
            out.append(rf"$q = 0$ for the {side} side: $p_0$ lies on that side's line, so "
                       r"$t = 0$ (this is the boundary case; $t_{in}$ starts at 0 anyway).")
        elif t == 1:
            out.append(rf"$q = p$ for the {side} side: $p_1$ lies on that side's line, so "
                       r"$t = 1$ (this is the boundary case; $t_{out}$ starts at 1 anyway).")
    ts = [t for _, p, _, t in rows if t is not None and 0 < t < 1]
    ties = sorted({t for t in ts if ts.count(t) > 1})
    cases = _segment_cases(p0, p1, lo, hi)
    if ties and any(c in kinds and c in cases for c in (THROUGH_CORNER, THROUGH_EDGE)):
        point = [Fraction(float(a)) + ties[0] * (Fraction(float(b)) - Fraction(float(a)))
                 for a, b in zip(p0, p1)]
        where = "a corner of the rectangle" if len(p0) == 2 else "an edge (or corner) of the box"
        out.append(rf"Two sides have the same $t = {_frac(ties[0])}$: the segment passes "
                   rf"exactly through ${latex_vector([float(v) for v in point])}$, on {where} "
                   r"(this is the boundary case; the largest entering and smallest leaving $t$ "
                   r"are found as always).")
    if PARALLEL in kinds and any(t is None for *_, t in rows):
        out.append(r"The segment is parallel to two sides ($p = 0$ for them): they give no "
                   r"$t$, only the test $q \ge 0$ (this is the boundary case).")
    return out


def _interval_by_hand(rows):
    """(t_in, t_out, entering ts, leaving ts, parallel outside) from rows of fractions."""
    entering = [t for _, p, _, t in rows if t is not None and p < 0]
    leaving = [t for _, p, _, t in rows if t is not None and p > 0]
    outside = any(t is None and q < 0 for _, _, q, t in rows)
    return max([Fraction(0)] + entering), min([Fraction(1)] + leaving), entering, leaving, \
        outside


def _interval_words(t_in, t_out, entering, leaving):
    def listed(ts):
        return ", ".join(f"${_frac(t)}$" for t in ts) or "none"
    return (rf"Entering ($p < 0$): {listed(entering)}; "
            rf"$t_{{in}} = \max(0, \dots) = {_frac(t_in)}$. Leaving ($p > 0$): "
            rf"{listed(leaving)}; $t_{{out}} = \min(1, \dots) = {_frac(t_out)}$.")


class LiangBarskyTable(_Boundary, DrawnExercise):
    r"""Liang-Barsky's :math:`p_k`, :math:`q_k` and :math:`t_k = q_k / p_k` for the four sides.

    With :math:`\Delta = p_1 - p_0`: left :math:`(-\Delta x,\ x_0 - x_{min})`, right
    :math:`(\Delta x,\ x_{max} - x_0)`, bottom :math:`(-\Delta y,\ y_0 - y_{min})`, top
    :math:`(\Delta y,\ y_{max} - y_0)`.

    In about 15 % of the seeds an end point lies on the line of a side on purpose, so that a
    :math:`q_k` is 0 (:math:`t_k = 0`) or equals :math:`p_k` (:math:`t_k = 1`):
    ``boundary == "point on a side"``; None otherwise, and then no end point is on a side's line.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``, ``boundary``.

    Examples
    --------
    >>> ex = LiangBarskyTable(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected * [-1, 1, -1]).diagnosis
    'sign of p'
    """

    title = "Liang-Barsky: the table of p, q and t"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        self.p0, self.p1 = _draw_lb_segment(rng, self.box_min, self.box_max, self._wanted)
        self.expected = _lb_table(self.p0, self.p1, self.box_min, self.box_max)

    def boundary_cases(self):
        return [c for c in _segment_cases(self.p0, self.p1, self.box_min, self.box_max)
                if c == ON_SIDE]

    def acceptable(self):
        return self.boundary_fits()

    def mistakes(self):
        e = self.expected
        return [
            Mistake(e * [-1, 1, -1], r"The signs of $p_k$ are the wrong way round. Inside means "
                    r"$p_k\,t \le q_k$ for every side; for the left side "
                    r"$x_0 + t\,\Delta x \ge x_{min}$ becomes $-\Delta x\,t \le x_0 - x_{min}$, "
                    r"so $p_{left} = -\Delta x$ and $p_{right} = +\Delta x$. The sign of $p_k$ "
                    r"then says whether the line enters ($p_k < 0$) or leaves ($p_k > 0$).",
                    "sign of p"),
            Mistake(e * [1, -1, -1], r"The signs of $q_k$ are the wrong way round: $q_k$ is "
                    r"the distance of $p_0$ from the side, positive when $p_0$ is on the inside: "
                    r"$q_{left} = x_0 - x_{min}$, $q_{right} = x_{max} - x_0$.", "sign of q"),
            Mistake(e * [-1, -1, 1], r"Both $p_k$ and $q_k$ have the wrong sign (the $t_k$ "
                    r"happen to be right). Write each side as $p_k\,t \le q_k$ with the inside "
                    r"on the $\le$ side: $p_{left} = -\Delta x$, $q_{left} = x_0 - x_{min}$. "
                    r"With the signs flipped, entering and leaving would be confused.",
                    "p and q negated"),
        ]

    def _check(self, answer):
        if _unanswered(answer):
            return Feedback("unanswered", UNANSWERED)
        value = read_floats(answer)
        if value is None or value.shape != (4, 3):
            return Feedback("invalid", "Give a 4 x 3 array: one row per side (left, right, "
                            "bottom, top), the columns p, q, t.", "unreadable")
        fb = diagnose_matrix(value, self.expected, self._mistakes, what="the table",
                             transform=False)
        if fb.diagnosis not in ("sign", "entries differ"):
            return fb
        off = np.abs(value - self.expected) > tolerance(self.expected)
        cells = ", ".join(f"{'pqt'[j]} of {_SIDES_2D[i]}" for i, j in np.argwhere(off))
        lead = ("Right sizes, but these entries have the wrong sign:" if fb.diagnosis == "sign"
                else "These entries are off:")
        return Feedback("wrong", rf"{lead} {cells}. Each side reads $p_k\,t \le q_k$; "
                        r"$t_k = q_k / p_k$.", fb.diagnosis)

    def hints(self):
        side, p, q, t = _rows_by_hand(self.p0, self.p1, self.box_min, self.box_max)[0]
        delta = self.p1 - self.p0
        return [
            r"Write the segment as $p(t) = p_0 + t\,\Delta$ with $\Delta = p_1 - p_0$. Each "
            r"side's condition for being inside, e.g. $x(t) \ge x_{min}$, becomes one "
            r"inequality $p_k\,t \le q_k$.",
            r"Left: $p = -\Delta x$, $q = x_0 - x_{min}$; right: $p = \Delta x$, "
            r"$q = x_{max} - x_0$; bottom and top likewise with $y$. Then $t_k = q_k / p_k$.",
            rf"Here $\Delta = {_vec(delta)}$; the left row is $p = {_frac(p)}$, "
            rf"$q = {_frac(q)}$, $t = {_frac(t)}$.",
        ]

    def worked(self):
        lo, hi = self.box_min, self.box_max
        rows = _rows_by_hand(self.p0, self.p1, lo, hi)
        steps = [rf"$\Delta = p_1 - p_0 = {_vec(self.p1)} - {_vec(self.p0)} = "
                 rf"{_vec(self.p1 - self.p0)}$; each side reads $p_k\,t \le q_k$."]
        steps += [_row_words(*row, self.p0, lo, hi) for row in rows]
        steps += _boundary_words(rows, self.p0, self.p1, lo, hi, self.boundary_kinds)
        return Worked(steps, np.array([[float(p), float(q), float(t)] for _, p, q, t in rows]))

    def statement(self):
        return (
            _clip_words(self) + rf". The segment runs from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$, $p(t) = p_0 + t\,(p_1 - p_0)$. For Liang-Barsky, write "
            r"each side as $p_k\,t \le q_k$ (inside on the $\le$ side) and give $p_k$, $q_k$ "
            r"and $t_k = q_k / p_k$ for the four sides." "\n\n"
            r"**Answer:** a $4 \times 3$ numpy array, rows in the order left, right, bottom, "
            r"top; columns $p_k$, $q_k$, $t_k$. " + DECIMALS + "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))


class LiangBarskyInterval(_Boundary, DrawnExercise):
    r"""Liang-Barsky's :math:`t_{in}` and :math:`t_{out}` for a segment that stays visible.

    :math:`t_{in} = \max(0, t_k \text{ for } p_k < 0)`,
    :math:`t_{out} = \min(1, t_k \text{ for } p_k > 0)`.

    In about 15 % of the seeds the variant is a boundary case on purpose, named by
    ``boundary``: an end point on the line of a side (``"point on a side"``: a :math:`t_k` is 0
    or 1), or a segment through a corner (``"through a corner"``: two sides share one
    :math:`t_k`); None otherwise, and then there is neither.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``, ``boundary``.

    Examples
    --------
    >>> ex = LiangBarskyInterval(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).status
    'wrong'
    """

    title = "Liang-Barsky: entering and leaving"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        self.p0, self.p1 = _draw_lb_segment(rng, self.box_min, self.box_max, self._wanted)
        self._table = _lb_table(self.p0, self.p1, self.box_min, self.box_max)
        self.expected = np.array(_lb_interval(self._table))

    boundary_kinds = (ON_SIDE, THROUGH_CORNER)

    def boundary_cases(self):
        return [c for c in _segment_cases(self.p0, self.p1, self.box_min, self.box_max)
                if c in self.boundary_kinds]

    def acceptable(self):
        t_in, t_out = self.expected
        return t_out - t_in > 0.05 and (t_in > 0 or t_out < 1) and self.boundary_fits()

    def _variants(self):
        return {
            "entering/leaving swapped": (_lb_interval(self._table, swap=True),
                                         r"Entering and leaving are swapped. Where $p_k < 0$ "
                                         r"the line goes from outside to inside that side "
                                         r"(entering: raise $t_{in}$); where $p_k > 0$ it goes "
                                         r"out (leaving: lower $t_{out}$)."),
            "not clamped": (_lb_interval(self._table, clamp=False), r"Start from "
                            r"$[t_{in}, t_{out}] = [0, 1]$: the segment ends at $t = 0$ and "
                            r"$t = 1$, so a crossing outside that range does not count, "
                            r"$t_{in} = \max(0, \dots)$ and $t_{out} = \min(1, \dots)$."),
            "min and max swapped": (_lb_interval(self._table, pick=(min, max)), r"The segment "
                                    r"is inside only after it has entered **every** side, so "
                                    r"$t_{in}$ is the **largest** entering $t_k$, and it must "
                                    r"leave at the first leaving crossing, so $t_{out}$ is the "
                                    r"**smallest** leaving $t_k$."),
        }

    def _parts(self):
        variants = self._variants()
        return [(name, float(self.expected[i]),
                 [Mistake(v[i], text, key) for key, (v, text) in variants.items()
                  if abs(v[i] - self.expected[i]) > SAME])
                for i, name in enumerate((r"$t_{in}$", r"$t_{out}$"))]

    def mistakes(self):
        return [Mistake(v, text, key) for key, (v, text) in self._variants().items()]

    def separated(self, mistakes):
        return parts_separated(self._parts(), same=None)

    def _check(self, answer):
        return diagnose_parts(answer, self._parts(), "your interval", "`[t_in, t_out]`.",
                              r"Tabulate $p_k$, $q_k$, $t_k = q_k / p_k$ for the four sides; "
                              r"$t_{in}$ is the largest of 0 and the entering $t_k$ "
                              r"($p_k < 0$), $t_{out}$ the smallest of 1 and the leaving ones.")

    def hints(self):
        rows = _rows_by_hand(self.p0, self.p1, self.box_min, self.box_max)
        _, _, entering, leaving, _ = _interval_by_hand(rows)
        return [
            r"Tabulate $p_k$, $q_k$ and $t_k = q_k / p_k$ for the four sides (the inside of "
            r"each side is $p_k\,t \le q_k$). A side with $p_k < 0$ is entered at $t_k$, one "
            r"with $p_k > 0$ is left at $t_k$.",
            r"The segment is inside after it has entered every side and before it leaves any: "
            r"$t_{in} = \max(0, \text{entering } t_k)$ and "
            r"$t_{out} = \min(1, \text{leaving } t_k)$; the 0 and 1 keep it within the "
            r"segment.",
            r"Here the entering $t_k$ are " + ", ".join(f"${_frac(t)}$" for t in entering)
            + r" and the leaving ones " + ", ".join(f"${_frac(t)}$" for t in leaving) + ".",
        ]

    def worked(self):
        lo, hi = self.box_min, self.box_max
        rows = _rows_by_hand(self.p0, self.p1, lo, hi)
        t_in, t_out, entering, leaving, _ = _interval_by_hand(rows)
        steps = [rf"$\Delta = p_1 - p_0 = {_vec(self.p1 - self.p0)}$; per side $p_k$, $q_k$, "
                 r"$t_k = q_k / p_k$:"]
        steps += [_row_words(*row, self.p0, lo, hi) for row in rows]
        steps += _boundary_words(rows, self.p0, self.p1, lo, hi, self.boundary_kinds)
        steps.append(_interval_words(t_in, t_out, entering, leaving))
        return Worked(steps, [float(t_in), float(t_out)])

    def statement(self):
        return (
            _clip_words(self) + rf". Clip the segment from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$, $p(t) = p_0 + t\,(p_1 - p_0)$ with $0 \le t \le 1$, "
            r"with Liang-Barsky: what are $t_{in}$ and $t_{out}$ after all four sides? (Part "
            r"of this segment is visible.)" "\n\n"
            r"**Answer:** a list of 2 numbers `[t_in, t_out]`. " + DECIMALS + "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))


class LiangBarskyClip3D(_Boundary, _Listed):
    r"""Liang-Barsky in 3D: the clipped segment, or ``'rejected'``.

    In about 15 % of the seeds the variant is a boundary case on purpose, named by
    ``boundary``: an end point on the plane of a side (``"point on a side"``), a segment
    through an edge or corner of the box (``"through an edge or corner"``), or one parallel
    to two sides, :math:`p_k = 0` (``"parallel to a side"``); None otherwise, and then there is
    none of these.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``, ``boundary``.

    Examples
    --------
    >>> ex = LiangBarskyClip3D(seed=8)
    >>> answer = "rejected" if ex.expected is None else ex.expected
    >>> ex.check(answer).status
    'correct'
    """

    title = "Liang-Barsky in 3D"
    answer_form = "custom"

    def draw(self, rng):
        self._want_rejected = bool(rng.random() < 0.3)
        self.box_min = rng.integers(-2, 1, size=3).astype(float)
        self.box_max = self.box_min + float(pick(rng, (2, 4)))
        while True:
            self.p0, self.p1 = _boundary_segment(rng, self.box_min, self.box_max,
                                                 self._wanted, margin=2)
            if np.count_nonzero(self.p1 - self.p0) >= 2:
                break
        result = clipping.liang_barsky(self.p0, self.p1, self.box_min, self.box_max)
        self.expected = None if result is None else np.array(result)
        codes = clipping.outcode([self.p0, self.p1], self.box_min, self.box_max)
        self._trivial = bool(codes[0] & codes[1]) or not (codes[0] | codes[1])
        self._table = _lb_table(self.p0, self.p1, self.box_min, self.box_max)

    def _segment(self, t_in, t_out):
        """The segment from t_in to t_out, or "rejected" when the interval is empty."""
        if t_in > t_out + 1e-12:
            return "rejected"
        return np.array([self.p0 + t_in * (self.p1 - self.p0),
                         self.p0 + t_out * (self.p1 - self.p0)])

    def _parallel_outside(self):
        return any(p == 0 and q < 0 for p, q, _ in self._table)

    boundary_kinds = (ON_SIDE, THROUGH_EDGE, PARALLEL)

    def boundary_cases(self):
        return _segment_cases(self.p0, self.p1, self.box_min, self.box_max)

    def acceptable(self):
        if self._trivial or (self.expected is None) != self._want_rejected:
            return False
        return (self.expected is None or not _same_segment(self.expected[0], self.expected[1])) \
            and self.boundary_fits()

    def mistakes(self):
        swapped = "rejected" if self._parallel_outside() else \
            self._segment(*_lb_interval(self._table, swap=True))
        unclamped = "rejected" if self._parallel_outside() else \
            self._segment(*_lb_interval(self._table, clamp=False))
        t_in, t_out = _lb_interval(self._table)
        unchecked = np.array([self.p0 + t_in * (self.p1 - self.p0),
                              self.p0 + t_out * (self.p1 - self.p0)])
        return [
            Mistake(unchecked, r"Nothing of this segment is inside: check the interval before you "
                    r"compute points. When $t_{in} > t_{out}$ (the segment leaves some side before "
                    r"it has entered all the others), or when a side parallel to the segment has "
                    r"$p_k = 0$ and $q_k < 0$, the segment is rejected.",
                    "empty interval not noticed", numeric=False),
            Mistake(swapped, r"Entering and leaving are swapped: a side with $p_k < 0$ is entered "
                    r"(it raises $t_{in}$), one with $p_k > 0$ is left (it lowers $t_{out}$). In "
                    r"3D there are six sides; $p_k$ and $q_k$ for near and far are built from $z$ "
                    r"like those for left and right from $x$.",
                    "entering/leaving swapped", numeric=False),
            Mistake(unclamped, r"The end points lie beyond the original segment: start from "
                    r"$[t_{in}, t_{out}] = [0, 1]$, so that crossings before $p_0$ or after $p_1$ "
                    r"do not count.", "not clamped", numeric=False),
        ]

    def separated(self, mistakes):
        live = [m.value for m in mistakes if not _equal_answers(m.value, self.expected)]
        return bool(live) and all(not _equal_answers(a, b) for i, a in enumerate(live)
                                  for b in live[i + 1:])

    def _check(self, answer):
        return _segment_feedback(answer, self.expected, self._mistakes, 3,
                                 r"Per side: $p_k$, $q_k$, $t_k = q_k / p_k$; "
                                 r"$t_{in} = \max(0, t_k : p_k < 0)$, "
                                 r"$t_{out} = \min(1, t_k : p_k > 0)$; the segment is rejected "
                                 r"if $t_{in} > t_{out}$.")

    def hints(self):
        rows = _rows_by_hand(self.p0, self.p1, self.box_min, self.box_max)
        _, _, entering, leaving, outside = _interval_by_hand(rows)
        last = (rf"Here $\Delta = {_vec(self.p1 - self.p0)}$; the entering $t_k$ are "
                + (", ".join(f"${_frac(t)}$" for t in entering) or "none")
                + r" and the leaving ones "
                + (", ".join(f"${_frac(t)}$" for t in leaving) or "none") + ".")
        parallel = [side for side, p, q, t in rows if t is None]
        if parallel:
            last += (rf" The {' and '.join(parallel)} sides are parallel to the segment "
                     r"($p_k = 0$): check their $q_k$.")
        return [
            r"Liang-Barsky in 3D has six sides: left, right, bottom, top as in 2D, and near "
            r"$z \ge z_{min}$, far $z \le z_{max}$, whose $p_k$ and $q_k$ are built from $z$ "
            r"as those of left and right are from $x$.",
            r"Tabulate $p_k$, $q_k$, $t_k = q_k / p_k$; $p_k < 0$ enters (raises $t_{in}$), "
            r"$p_k > 0$ leaves (lowers $t_{out}$), $p_k = 0$ with $q_k < 0$ rejects at once. "
            r"Start from $[0, 1]$; the segment is rejected if $t_{in} > t_{out}$ at the end.",
            last,
        ]

    def worked(self):
        lo, hi = self.box_min, self.box_max
        rows = _rows_by_hand(self.p0, self.p1, lo, hi)
        t_in, t_out, entering, leaving, outside = _interval_by_hand(rows)
        steps = [rf"$\Delta = p_1 - p_0 = {_vec(self.p1 - self.p0)}$; per side $p_k$, $q_k$, "
                 r"$t_k = q_k / p_k$:"]
        steps += [_row_words(*row, self.p0, lo, hi) for row in rows]
        steps += _boundary_words(rows, self.p0, self.p1, lo, hi, self.boundary_kinds)
        if outside:
            steps.append(r"A parallel side with $q_k < 0$: the segment lies entirely outside "
                         r"it, so it is **rejected**.")
            return Worked(steps, "rejected")
        steps.append(_interval_words(t_in, t_out, entering, leaving))
        if t_in > t_out:
            steps.append(rf"$t_{{in}} = {_frac(t_in)} > t_{{out}} = {_frac(t_out)}$: the "
                         r"segment leaves a side before it has entered all the others, so it "
                         r"is **rejected**.")
            return Worked(steps, "rejected")
        a = [Fraction(float(v)) for v in self.p0]
        d = [Fraction(float(b)) - x for x, b in zip(a, self.p1)]
        ends = [[x + t * dx for x, dx in zip(a, d)] for t in (t_in, t_out)]
        answer = np.array([[float(v) for v in e] for e in ends])
        steps.append(rf"$p(t_{{in}}) = {latex_vector(answer[0])}$ and "
                     rf"$p(t_{{out}}) = {latex_vector(answer[1])}$.")
        return Worked(steps, answer)

    def statement(self):
        return (
            rf"The clip box is {_box_words(self.box_min, self.box_max)}. Clip the segment from "
            rf"$p_0 = {_vec(self.p0)}$ to $p_1 = {_vec(self.p1)}$ with the 3D Liang-Barsky "
            r"algorithm (six sides: left, right, bottom, top, near $z \ge z_{min}$, far "
            r"$z \le z_{max}$). What is left of it?" "\n\n"
            r"**Answer:** the clipped segment as two points `[[x0, y0, z0], [x1, y1, z1]]` "
            r"(the end nearer $p_0$ first, though either order is accepted), or the string "
            r"`'rejected'` if nothing is inside. " + DECIMALS + "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))
