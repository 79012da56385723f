"""Chapter 18 exercises: marching squares (case index, edge crossings, saddle cells).

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import itertools

import numpy as np

from ... import scivis
from ..core import (APART, DECIMALS, SAME, TOLERANCES_APART, UNANSWERED, Feedback, Mistake, Worked,
                    agrees, data_note, has_placeholder, pick, read_floats, rounding_of, tolerance)
from . import _Chapter18, _num

__all__ = [
    "SaddleResolution",
    "SquareCaseIndex",
    "SquareCrossings",
]


# ---------------------------------------------------------------------------------------------
# Marching squares
# ---------------------------------------------------------------------------------------------

_CELL_PICTURE = (
    "```\n"
    "  3 ---- e2 ---- 2\n"
    "  |              |\n"
    " e3              e1\n"
    "  |              |\n"
    "  0 ---- e0 ---- 1\n"
    "```\n"
)


def _cell_field(f):
    """The 2 x 2 field (rows y) of the corner values f0..f3 (counter-clockwise from the bottom
    left)."""
    return np.array([[f[0], f[1]], [f[3], f[2]]], dtype=float)


def _corner_words(f):
    return ", ".join(f"$f_{k} = {_num(v)}$" for k, v in enumerate(f))


def _case(f, level, strict=False):
    above = [(v > level) if strict else (v >= level) for v in f]
    return sum(1 << k for k, a in enumerate(above) if a)


#: Corner k's place in the cell, for the statements and solutions.
_CORNER_PLACE = ("bottom left", "bottom right", "top right", "top left")
#: How often a corner value equals the level exactly (a deliberate boundary case).
_TIE_SHARE = 0.13


class SquareCaseIndex(_Chapter18):
    r"""Classify a marching-squares cell: its case index 0-15.

    Bit k of the index is set when corner k is above the level (:math:`f_k \ge c`); corners
    counter-clockwise from the bottom left. In about 15 % of the variants a corner value equals
    the level exactly (``boundary == "corner on the level"``, None otherwise): it counts as
    above, as the statement's :math:`f_k \ge c` says and the worked solution points out. The
    index is a whole number, compared exactly.

    Attributes: ``corners`` (:math:`f_0, \dots, f_3`), ``level``, ``boundary``.

    Examples
    --------
    >>> ex = SquareCaseIndex(seed=0)
    >>> ex.check(sum(2 ** k for k, f in enumerate(ex.corners) if f >= ex.level)).status
    'correct'
    >>> ex.check(15 - ex.expected).diagnosis
    'below counted'
    >>> ex.check(float(ex.expected)).status, ex.check(ex.expected + 1).status
    ('correct', 'wrong')
    """

    title = "The case of a marching-squares cell"
    answer_form = "number"
    what = "the case index"
    #: a cell symmetric under a slip gives the right index with it (then the slip is right)
    may_coincide = ("strict", "clockwise", "reversed bits")
    advice = (r"Mark each corner with 1 if $f_k \ge c$, else 0, and add up $2^k$ over the marked "
              r"corners $k$.")

    def draw(self, rng):
        self.corners = rng.integers(0, 10, size=4).astype(float)
        self.boundary = None
        if rng.random() < _TIE_SHARE:
            self.level = float(pick(rng, (2, 3, 4, 5, 6, 7)))
            self.corners[int(rng.integers(4))] = self.level
            self.boundary = "corner on the level"
        else:
            self.level = float(pick(rng, (2, 3, 4, 5, 6, 7))) + 0.5
        self.expected = int(scivis.marching_squares_cases(_cell_field(self.corners),
                                                          self.level)[0, 0])

    def acceptable(self):
        return self.expected not in (0, 15)

    def mistakes(self):
        bits = [(self.expected >> k) & 1 for k in range(4)]
        below = 15 - self.expected
        reversed_bits = 8 * bits[0] + 4 * bits[1] + 2 * bits[2] + bits[3]
        reversed_why = (r"corner 0 is the lowest bit ($2^0 = 1$), corner 3 the highest "
                        r"($2^3 = 8$).")
        found = [
            Mistake(below, r"You set the bits of the corners **below** the level. Bit $k$ "
                    r"stands for corner $k$ being above: $f_k \ge c$."
                    + (r" (Reading the bits the wrong way round gives the same number here: "
                       + reversed_why + ")" if reversed_bits == below else ""), "below counted"),
            Mistake(bits[0] + 2 * bits[3] + 4 * bits[2] + 8 * bits[1], r"You numbered the "
                    r"corners clockwise. They go counter-clockwise from the bottom left: 0 bottom "
                    r"left, 1 bottom right, 2 top right, 3 top left.", "clockwise"),
            Mistake(_case(self.corners, self.level, strict=True), r"A corner whose value equals "
                    r"the level counts as **above** ($f_k \ge c$), not below.", "strict"),
        ]
        if reversed_bits != below:        # for 3, 5, 10 and 12 the two slips agree
            found.append(Mistake(reversed_bits, r"You read the bits the wrong way round: "
                                 + reversed_why, "reversed bits"))
        return found

    def statement(self):
        return (
            r"A cell of a 2D scalar field has the corner values " + _corner_words(self.corners)
            + r" (corners counted counter-clockwise from the bottom left)." "\n\n"
            + _CELL_PICTURE + "\n"
            rf"What is its marching-squares case index for the level $c = {_num(self.level)}$? "
            r"Bit $k$ of the index ($2^k$) is set when corner $k$ is above the level, "
            r"$f_k \ge c$." "\n\n"
            r"**Answer:** one whole number from 0 to 15." "\n\n" + data_note("corners", "level"))

    def _bits(self):
        return [1 if f >= self.level else 0 for f in self.corners]

    def hints(self):
        bits = self._bits()
        above = [k for k in range(4) if bits[k]]
        return [
            r"Compare each corner with the level: corner $k$ is *above* when $f_k \ge c$ (a "
            r"value equal to $c$ counts as above), and then contributes $2^k$ to the index.",
            r"The weights follow the corner numbers, counter-clockwise from the bottom left: "
            r"corner 0 (bottom left) $\to 1$, corner 1 (bottom right) $\to 2$, corner 2 (top "
            r"right) $\to 4$, corner 3 (top left) $\to 8$.",
            rf"Here the corners with $f_k \ge {_num(self.level)}$ are "
            + ", ".join(f"{k} ($f_{k} = {_num(self.corners[k])}$)" for k in above)
            + "; add up their weights.",
        ]

    def worked(self):
        bits = self._bits()
        index = sum(b * 2 ** k for k, b in enumerate(bits))
        signs = [r"\ge" if b else "<" for b in bits]
        compare = ", ".join(
            rf"$f_{k} = {_num(f)} {sign} {_num(self.level)}$ (bit {k}: {b})"
            for k, (f, b, sign) in enumerate(zip(self.corners, bits, signs)))
        steps = [rf"Compare every corner with $c = {_num(self.level)}$: {compare}."]
        if self.boundary is not None:
            ties = [k for k in range(4) if self.corners[k] == self.level]
            steps.append(
                "Corner " + " and ".join(str(k) for k in ties)
                + rf" lies exactly on the level, $f = c = {_num(self.level)}$: the rule "
                r"$f_k \ge c$ counts it as **above** (bit 1). Any fixed rule would do, as long "
                r"as every cell uses the same one, so that neighbouring cells agree on the shared "
                r"corner and the isoline has no gaps.")
        steps.append(r"Add $2^k$ over the corners above: $"
                     + " + ".join(f"{b} \\cdot {2 ** k}" for k, b in enumerate(bits))
                     + rf" = {index}$ (binary {''.join(str(b) for b in reversed(bits))}, "
                     r"corner 3 first).")
        return Worked(steps, index)


def _orderings(points):
    """`points` (one per row) in every order."""
    points = np.asarray(points, dtype=float)
    return [points[list(perm)] for perm in itertools.permutations(range(len(points)))]


def _same_points(a, b):
    """Whether the points `a` agree with the points `b`, in some order, by the course's policy."""
    a = np.asarray(a, dtype=float)
    return any(agrees(a, q) for q in _orderings(b))


def _points_apart(a, b):
    """Whether two lists of points differ clearly in every order: by APART (up to rounding)
    and by TOLERANCES_APART tolerances of the course's policy."""
    a = np.asarray(a, dtype=float)
    for q in _orderings(b):
        d = np.abs(a - q)
        if d.max() < APART - SAME or min(float((d / tolerance(q)).max()),
                                         float((d / tolerance(a)).max())) < TOLERANCES_APART:
            return False
    return True


def _pair_gap(a, b):
    """Distance between two unordered lists of points (the better of the orderings)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return np.inf
    return min(float(np.abs(a - q).max()) for q in _orderings(b))


class SquareCrossings(_Chapter18):
    r"""Where the isoline crosses the edges of a marching-squares cell (linear interpolation).

    On an edge from corner :math:`p_0` (value :math:`f_0`) to :math:`p_1` (value :math:`f_1`)
    with one end above and one below, :math:`p = p_0 + t (p_1 - p_0)`,
    :math:`t = (c - f_0)/(f_1 - f_0)`. The answer is the two crossing points in either order,
    right to 3 significant digits (the course's one tolerance policy).

    Attributes: ``corners``, ``level``, ``cell`` (the (x, y) of corner 0; the cell is a unit
    square).

    Examples
    --------
    >>> ex = SquareCrossings(seed=0)
    >>> ex.check(ex.expected[::-1]).status
    'correct'
    >>> ex.check(np.round(ex.expected)).status
    'wrong'
    >>> ex.check([[float(f"{x:.3g}") for x in p] for p in ex.expected]).status
    'correct'
    """

    title = "Where the isoline crosses a cell"
    answer_form = "custom"
    what = "the two crossing points"

    def draw(self, rng):
        self.corners = rng.integers(1, 10, size=4).astype(float)
        self.level = float(pick(rng, (2, 3, 4, 5, 6, 7))) + 0.5
        self.cell = rng.integers(0, 5, size=2).astype(float)
        self.expected = scivis.marching_squares(_cell_field(self.corners), self.level,
                                                origin=self.cell).reshape(-1, 2)

    def acceptable(self):
        return _case(self.corners, self.level) not in (0, 5, 10, 15)

    def _crossed(self):
        f, c = self.corners, self.level
        return [e for e in range(4) if (f[e] >= c) != (f[(e + 1) % 4] >= c)]

    def _points(self, t_of):
        pos = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float) + self.cell
        f = self.corners
        return np.array([pos[e] + t_of(f[e], f[(e + 1) % 4]) * (pos[(e + 1) % 4] - pos[e])
                         for e in self._crossed()])

    def mistakes(self):
        c = self.level
        return [
            Mistake(self._points(lambda f0, f1: 0.5), r"You took the midpoints of the crossed "
                    r"edges. That gives the right topology but a jagged line: interpolate, "
                    r"$t = \frac{c - f_0}{f_1 - f_0}$, so the point sits nearer the corner whose "
                    r"value is closer to $c$.", "midpoints"),
            Mistake(self._points(lambda f0, f1: 1 - (c - f0) / (f1 - f0)), r"You measured $t$ "
                    r"from the wrong end of the edge: with $t = \frac{c - f_0}{f_1 - f_0}$ the "
                    r"point is $p_0 + t\,(p_1 - p_0)$, starting at the corner whose value is "
                    r"$f_0$.", "wrong end"),
            Mistake(self._points(lambda f0, f1: (c - f0) / f1), r"You divided by $f_1$ instead "
                    r"of the difference $f_1 - f_0$: $t$ is the fraction of the change along the "
                    r"edge, $t = \frac{c - f_0}{f_1 - f_0}$.", "divided by f1"),
        ]

    def separated(self, mistakes):
        live = self.keep(mistakes)
        return all(_points_apart(m.value, self.expected) for m in live) and all(
            a.key == b.key or _points_apart(a.value, b.value)
            for a, b in itertools.combinations(live, 2))

    def keep(self, mistakes):
        return [m for m in mistakes if _pair_gap(m.value, self.expected) > SAME]

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        value = read_floats(answer)
        if value is None or value.shape != (2, 2):
            return Feedback("invalid", "Give the two points as a list of two `[x, y]` pairs, "
                            "e.g. `[[1.5, 2], [2, 2.25]]`.", "unreadable")
        if _same_points(value, self.expected):
            return Feedback("correct", "Both crossing points are right.")
        slips = [Mistake(q, m.explanation, m.key) for m in self._mistakes
                 for q in _orderings(m.value)]              # a slip given exactly is no rounding
        if any(rounding_of(value, q, slips) for q in _orderings(self.expected)):
            return Feedback("wrong", "Close: your points look like the right ones rounded to too "
                            "few digits. Give at least 3 significant digits, and keep the full "
                            "precision in the intermediate steps.", "rounded")
        for m in self._mistakes:
            if _same_points(value, m.value):
                return Feedback("wrong", m.explanation, m.key)
        right = sum(any(agrees(p, q) for q in self.expected) for p in value)
        edges = " and ".join(f"e{e}" for e in self._crossed())
        return Feedback("wrong", f"{right} of your 2 points {'is' if right == 1 else 'are'} "
                        f"right. The isoline crosses the edges whose ends lie on different sides "
                        f"of the level (here {edges}); on each, "
                        r"$p = p_0 + \frac{c - f_0}{f_1 - f_0}\,(p_1 - p_0)$.", "points differ")

    def statement(self):
        x, y = self.cell
        return (
            rf"A unit cell of a 2D field has its corner 0 at $(x, y) = ({_num(x)}, {_num(y)})$, "
            rf"so its corners are 0 at $({_num(x)}, {_num(y)})$, 1 at $({_num(x + 1)}, "
            rf"{_num(y)})$, 2 at $({_num(x + 1)}, {_num(y + 1)})$ and 3 at $({_num(x)}, "
            rf"{_num(y + 1)})$, with the values " + _corner_words(self.corners) + ".\n\n"
            + _CELL_PICTURE + "\n"
            rf"The isoline $f = {_num(self.level)}$ crosses two edges of the cell. Where? Use "
            r"linear interpolation along each edge." "\n\n"
            r"**Answer:** the two points as a list `[[x1, y1], [x2, y2]]`, in either order. "
            + DECIMALS + "\n\n" + data_note("corners", "level", "cell"))

    def _corner_at(self, k):
        return self.cell + np.array([[0, 0], [1, 0], [1, 1], [0, 1]][k], dtype=float)

    def _crossing(self, e):
        """Edge e's ends, values, t and the crossing point."""
        a, b = e, (e + 1) % 4
        p0, p1 = self._corner_at(a), self._corner_at(b)
        f0, f1 = float(self.corners[a]), float(self.corners[b])
        t = (self.level - f0) / (f1 - f0)
        return a, b, p0, p1, f0, f1, t, p0 + t * (p1 - p0)

    def hints(self):
        e1, e2 = self._crossed()
        a, b, p0, p1, f0, f1, t, _ = self._crossing(e1)
        ends = "; ".join(rf"$e_{e}$ from corner {e} ($f = {_num(self.corners[e])}$) to corner "
                         rf"{(e + 1) % 4} ($f = {_num(self.corners[(e + 1) % 4])}$)"
                         for e in (e1, e2))
        return [
            r"The isoline crosses the edges whose two corners lie on different sides of the "
            r"level; on each, the value changes linearly, so find the fraction "
            r"$t = \frac{c - f_0}{f_1 - f_0}$ of the way from one corner to the other.",
            rf"With $c = {_num(self.level)}$ the crossed edges are {ends}.",
            rf"On $e_{e1}$: $t = \frac{{{_num(self.level)} - {_num(f0)}}}{{{_num(f1)} - "
            rf"{_num(f0)}}} = {_num(t, 4)}$, measured from corner {a} at $({_num(p0[0])}, "
            rf"{_num(p0[1])})$ towards corner {b} at $({_num(p1[0])}, {_num(p1[1])})$.",
        ]

    def worked(self):
        steps = [rf"Corners above $c = {_num(self.level)}$: "
                 + ", ".join(str(k) for k in range(4) if self.corners[k] >= self.level)
                 + r"; the isoline crosses the edges between an above and a below corner: "
                 + " and ".join(f"$e_{e}$" for e in self._crossed()) + "."]
        points = []
        for e in self._crossed():
            a, b, p0, p1, f0, f1, t, point = self._crossing(e)
            points.append(point.tolist())
            steps.append(
                rf"$e_{e}$, from corner {a} $({_num(p0[0])}, {_num(p0[1])})$, $f_0 = {_num(f0)}$, "
                rf"to corner {b} $({_num(p1[0])}, {_num(p1[1])})$, $f_1 = {_num(f1)}$: "
                rf"$t = \frac{{{_num(self.level)} - {_num(f0)}}}{{{_num(f1)} - {_num(f0)}}} = "
                rf"{_num(t, 4)}$, $p = p_0 + t\,(p_1 - p_0) = ({_num(point[0], 4)}, "
                rf"{_num(point[1], 4)})$.")
        shown = "`[" + ", ".join(f"[{_num(x, 4)}, {_num(y, 4)}]" for x, y in points) + "]`"
        return Worked(steps, points, shown=shown)


def _read_edge_pairs(answer):
    """A set of two frozensets of edges from a list of two edge pairs, or a Feedback."""
    if has_placeholder(answer) or (isinstance(answer, (list, tuple)) and any(
            isinstance(a, (list, tuple)) and any(b is Ellipsis for b in a) for a in answer)):
        return Feedback("unanswered", UNANSWERED)
    form = ("Give the two segments as a list of two pairs of edge numbers, e.g. "
            "`[(0, 1), (2, 3)]`.")
    if isinstance(answer, (str, bytes, dict, set)):
        return Feedback("invalid", form, "unreadable")
    value = read_floats(answer)
    if value is None or value.shape != (2, 2):
        return Feedback("invalid", form, "unreadable")
    if not np.all(value == np.round(value)) or value.min() < 0 or value.max() > 3:
        return Feedback("invalid", "Edges are numbered 0 to 3 (e0 bottom, e1 right, e2 top, "
                        "e3 left).", "unreadable")
    pairs = {frozenset(int(e) for e in row) for row in value}
    if len(pairs) != 2 or any(len(p) != 2 for p in pairs) or len(set().union(*pairs)) != 4:
        return Feedback("invalid", "Each of the four edges is crossed once, so the two segments "
                        "together use every edge exactly once.", "unreadable")
    return pairs


def _pairs_of(segments):
    return {frozenset(seg) for seg in segments}


def _typed(pairs):
    """Edge pairs as a student types them: a sorted list of sorted pairs."""
    return sorted(tuple(sorted(pair)) for pair in pairs)


class SaddleResolution(_Chapter18):
    r"""Resolve an ambiguous marching-squares cell (case 5 or 10) with the midpoint decider.

    The centre value is taken as the mean of the four corners; if it is above the level, the
    two above corners are connected through the cell (the segments cut off the two below
    corners), otherwise the two below corners are connected.

    The two resolutions come up equally often (``centre_above`` is drawn first), with whole
    corner values around a level that varies.

    Attributes: ``corners``, ``level``; ``centre`` (the mean), ``centre_above``, ``case``.

    Examples
    --------
    >>> sum(SaddleResolution(seed=s).centre_above for s in range(100)) in range(35, 66)
    True
    >>> ex = SaddleResolution(seed=0)
    >>> ex.check([sorted(p) for p in ex.expected]).status
    'correct'
    >>> ex.check([(0, 2), (1, 3)]).diagnosis
    'crossing'
    """

    title = "An ambiguous cell: the midpoint decider"
    answer_form = "custom"
    what = "the segments"

    def draw(self, rng):
        self.case = int(pick(rng, (5, 10)))
        # the resolution is chosen first, so that both come up equally often
        self.centre_above = bool(rng.random() < 0.5)
        up = (0, 2) if self.case == 5 else (1, 3)
        down = (1, 3) if self.case == 5 else (0, 2)
        self.level = float(rng.integers(3, 9)) + 0.5
        below_top = int(self.level - 0.5)                    # whole corners: below <= c - 0.5
        while True:
            f = np.zeros(4)
            f[list(up)] = rng.integers(below_top + 1, below_top + 8, size=2)
            f[list(down)] = rng.integers(max(0, below_top - 6), below_top + 1, size=2)
            mean = float(f.mean())
            if abs(mean - self.level) >= 0.25 and (mean >= self.level) == self.centre_above:
                break
        self.corners = f
        self.centre = mean
        above = scivis.saddle_centre_above(_cell_field(f), self.level)[0, 0]
        table = scivis.SQUARE_SADDLES_CENTRE_ABOVE if above else dict(
            enumerate(scivis.SQUARE_TABLE))
        self.expected = _pairs_of(table[self.case])

    def acceptable(self):
        return abs(self.centre - self.level) >= 0.25 and _case(self.corners, self.level) == \
            self.case

    def mistakes(self):
        other = (_pairs_of(scivis.SQUARE_TABLE[self.case])
                 if self.expected != _pairs_of(scivis.SQUARE_TABLE[self.case])
                 else _pairs_of(scivis.SQUARE_SADDLES_CENTRE_ABOVE[self.case]))
        side = "above" if self.centre >= self.level else "below"
        joined = "above" if side == "above" else "below"
        return [
            Mistake(_typed(other), rf"The midpoint decider says otherwise: the centre value is "
                    rf"the mean of the corners, ${_num(self.centre)}$, which is **{side}** the "
                    rf"level ${_num(self.level)}$. So the centre belongs to the {joined} corners, "
                    rf"and the two {joined} corners are connected through the cell; the segments "
                    r"cut off the other two corners.", "other resolution", numeric=False),
            Mistake([(0, 2), (1, 3)], r"Your two segments cross each other in the middle of the "
                    r"cell. An isoline never crosses itself: each segment must separate one "
                    r"corner (or two neighbouring corners) from the rest, so it joins two "
                    r"neighbouring edges here.", "crossing", numeric=False),
        ]

    def keep(self, mistakes):
        return [m for m in mistakes if _pairs_of(m.value) != self.expected]

    def separated(self, mistakes):
        return True

    def _check(self, answer):
        pairs = _read_edge_pairs(answer)
        if isinstance(pairs, Feedback):
            return pairs
        if pairs == self.expected:
            return Feedback("correct", f"Right: the centre value {_num(self.centre)} decides "
                            "how the corners are joined.")
        for mistake in self._mistakes:
            if pairs == _pairs_of(mistake.value):
                return Feedback("wrong", mistake.explanation, mistake.key)
        # the three ways to pair four edges are all covered above; kept as a safe default
        return Feedback("wrong", "These segments do not resolve the saddle.", "other")

    def statement(self):
        return (
            r"A cell has the corner values " + _corner_words(self.corners) + r" (corners "
            r"counter-clockwise from the bottom left, edge $e_k$ from corner $k$ to corner "
            r"$k + 1$)." "\n\n" + _CELL_PICTURE + "\n"
            rf"For the level $c = {_num(self.level)}$ two opposite corners are above and two "
            r"below: an ambiguous saddle, crossed on all four edges. Resolve it with the "
            r"**midpoint decider** (the mean of the four corners stands for the value at the "
            r"centre): which edges are joined by the two isoline segments?" "\n\n"
            r"**Answer:** a list of two pairs of edge numbers, e.g. `[(0, 1), (2, 3)]` (any "
            r"order)." "\n\n" + data_note("corners", "level"))

    def _sides(self):
        """The above and below corners, whether the mean is above, and the corners cut off."""
        above = [k for k in range(4) if self.corners[k] >= self.level]
        below = [k for k in range(4) if self.corners[k] < self.level]
        mean = sum(float(f) for f in self.corners) / 4
        centre_above = mean >= self.level
        return above, below, mean, centre_above, (below if centre_above else above)

    def hints(self):
        above, below, mean, centre_above, cut = self._sides()
        side, joined = ("above", above) if centre_above else ("below", below)
        return [
            r"A saddle's four crossings can be joined in two ways. The midpoint decider "
            r"estimates the value at the centre of the cell by the mean of the four corners: "
            r"the centre belongs to the side (above or below the level) that the mean is on.",
            rf"The mean is $({' + '.join(_num(f) for f in self.corners)}) / 4 = {_num(mean)}$, "
            rf"{side} the level ${_num(self.level)}$: the centre joins the {side} corners "
            rf"{joined[0]} and {joined[1]}.",
            rf"With the {side} corners connected through the middle, each segment cuts off one of "
            rf"the other two corners, {cut[0]} and {cut[1]}; cutting off corner $k$ joins the two "
            r"edges that meet there, $e_{k-1}$ and $e_k$ (edge $e_k$ runs from corner $k$ to "
            r"$k + 1$).",
        ]

    def worked(self):
        above, below, mean, centre_above, cut = self._sides()
        side, joined = ("above", above) if centre_above else ("below", below)
        segments = [tuple(sorted(((k - 1) % 4, k))) for k in cut]
        return Worked([
            rf"Corners {above[0]} and {above[1]} are above $c = {_num(self.level)}$, corners "
            rf"{below[0]} and {below[1]} below: diagonally opposite, a saddle (case "
            rf"{sum(2 ** k for k in above)}), crossed on all four edges.",
            rf"Midpoint decider: the centre value is the mean "
            rf"$({' + '.join(_num(f) for f in self.corners)}) / 4 = {_num(mean)} "
            + (r"\ge" if centre_above else "<") + rf" {_num(self.level)}$: the centre is "
            rf"{side} the level, so the {side} corners {joined[0]} and {joined[1]} are connected "
            r"through the middle of the cell.",
            rf"The two segments then cut off corners {cut[0]} and {cut[1]}. Corner $k$ lies "
            r"between the edges $e_{k-1}$ and $e_k$ (corner 0 between $e_3$ and $e_0$), so the "
            r"segments join " + " and ".join(rf"$e_{a}$ with $e_{b}$" for a, b in segments) + ".",
        ], segments, shown=f"`{segments!r}`")
