r"""Chapter 18 exercises: isolines, isosurfaces, volume rendering and streamlines, exam style.

Each class is one kind of exam question: the case index of a marching-squares cell, the points
where the isoline crosses its edges, and the resolution of an ambiguous (saddle) cell by the
midpoint decider; the number of triangles a marching-cubes case produces; compositing samples
along a ray front to back by hand, the sample at which early ray termination stops, and the
opacity correction for another step size; a maximum intensity projection of a tiny volume; one
step of the classic Runge-Kutta method (RK4) and the outward drift of Euler's method on a
circular flow. The ``seed`` draws numbers that work out by hand: whole corner values, opacities
in tenths and twentieths, small whole matrices. Case indices and counts are whole numbers,
compared exactly; every real answer is right to 3 significant digits (the course's one
tolerance policy). A few variants are boundary cases on purpose (a corner value equal to the
level), labelled by an attribute ``boundary``.

The expected answers come from :mod:`course_lib.scivis`. Each exercise names the slips it
anticipates (the corners numbered clockwise, the below corners counted, midpoints instead of
interpolated points, :math:`1 - A` forgotten in the compositing, the RK4 weights replaced by an
average, ...), computes the answer each slip would give, and draws its numbers again until those
answers differ clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`). Every exercise offers ``hint()`` (three
hints, from the idea to this variant's numbers) and ``solution()`` (this variant worked out).

Conventions (those of :mod:`course_lib.scivis`): a corner is *above* when its value is at least
the level; the corners of a square cell are numbered counter-clockwise from the bottom left
(0 bottom left, 1 bottom right, 2 top right, 3 top left) and its edges from the bottom
(edge k runs from corner k to corner k + 1); a cube's corners and edges are
:data:`~course_lib.scivis.CUBE_CORNERS` and :data:`~course_lib.scivis.CUBE_EDGES`; samples along
a ray are listed front (nearest the eye) first.
"""
import itertools
import math

import numpy as np

from .. import format as fmt
from .. import scivis
from .core import (APART, DECIMALS, SAME, TOLERANCES_APART, UNANSWERED, DrawnExercise, Feedback,
                   Mistake, Worked, agrees, data_note, has_placeholder, pick, read_floats,
                   rounding_of, tolerance)

__all__ = [
    "CompositeFrontToBack",
    "CubeTriangleCount",
    "EXERCISES",
    "EarlyTermination",
    "EulerDrift",
    "MaxIntensityProjection",
    "OpacityCorrection",
    "RK4Step",
    "SaddleResolution",
    "SquareCaseIndex",
    "SquareCrossings",
]

_num = fmt.number
_vec = fmt.vector_latex


class _Chapter18(DrawnExercise):
    """The chapter's base: answers are points or pairs of numbers, not directions, and never
    True/False (see ``DrawnExercise.vector_like`` and ``reject_bool``)."""

    vector_like = False
    reject_bool = True


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


# ---------------------------------------------------------------------------------------------
# Marching cubes
# ---------------------------------------------------------------------------------------------

def _loops(case):
    """The number of separate polygons (loops) of a case: components of its crossed edges."""
    triangles = scivis.cube_triangles(case)
    parent = list(range(13))

    def find(a):
        while parent[a] != a:
            a = parent[a]
        return a

    for tri in triangles:
        for a, b in zip(tri, tri[1:]):
            parent[find(int(a))] = find(int(b))
    return len({find(int(e)) for e in np.unique(triangles)})


def _crossed_edges(case):
    above = [(case >> k) & 1 for k in range(8)]
    return sum(above[a] != above[b] for a, b in scivis.CUBE_EDGES)


_CORNER_TABLE = ("| corner | " + " | ".join(str(k) for k in range(8)) + " |\n"
                 + "|---" * 9 + "|\n"
                 + "| $(x, y, z)$ | " + " | ".join(
                     f"$({x}, {y}, {z})$" for x, y, z in scivis.CUBE_CORNERS) + " |")


class CubeTriangleCount(_Chapter18):
    r"""How many triangles a marching-cubes case produces (cases without ambiguous faces).

    The isosurface crosses the edges between an above and a below corner; the crossings of each
    connected group form a polygon of :math:`m` vertices, cut into :math:`m - 2` triangles.

    Attributes: ``above`` (the corners above the level), ``case`` (the index).

    Examples
    --------
    >>> ex = CubeTriangleCount(seed=0)
    >>> ex.check(len(scivis.cube_triangles(ex.case))).status
    'correct'
    >>> ex.check(_crossed_edges(ex.case)).diagnosis       # the crossed edges: the vertices
    'vertices'
    """

    title = "Triangles of a marching-cubes case"
    answer_form = "number"
    what = "the number of triangles"
    may_coincide = ("one polygon", "corners", "one per polygon")
    advice = (r"Find the edges with one end above and one below; they group into polygons around "
              r"the above corners; a polygon with $m$ vertices gives $m - 2$ triangles.")

    def draw(self, rng):
        k = int(pick(rng, (1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 7)))
        self.above = tuple(sorted(int(i) for i in rng.choice(8, size=k, replace=False)))
        self.case = sum(1 << c for c in self.above)
        self.expected = len(scivis.cube_triangles(self.case))

    def acceptable(self):
        return scivis._ambiguous_faces(self.case) == 0

    def mistakes(self):
        edges, loops = _crossed_edges(self.case), _loops(self.case)
        return [
            Mistake(edges, r"That is the number of crossed edges, i.e. of **vertices**. The "
                    r"vertices form polygons; a polygon with $m$ vertices is cut into $m - 2$ "
                    r"triangles.", "vertices"),
            Mistake(edges - 2, r"You treated all the crossings as one polygon. Here they form "
                    rf"{loops} separate polygons (the above corners fall into {loops} groups "
                    r"that share no cube edge): each polygon of $m$ vertices gives $m - 2$ "
                    r"triangles.", "one polygon"),
            Mistake(len(self.above), r"The number of above corners is not the number of "
                    r"triangles: count the crossed edges (vertices), group them into polygons, "
                    r"and cut each polygon of $m$ vertices into $m - 2$ triangles.", "corners"),
            Mistake(loops, r"One triangle per polygon is only right for triangles. A polygon "
                    r"with $m$ vertices needs $m - 2$ triangles.", "one per polygon"),
        ]

    def statement(self):
        listed = (f"Corner {self.above[0]} is" if len(self.above) == 1 else
                  "Corners " + ", ".join(str(c) for c in self.above[:-1])
                  + f" and {self.above[-1]} are")
        return (
            r"A cube of a volume has its corners numbered as in the table (offsets from corner "
            r"0):" "\n\n" + _CORNER_TABLE + "\n\n"
            rf"{listed} above the isovalue, the others below. How many "
            r"triangles does marching cubes make in this cube? (No face of this cube is "
            r"ambiguous, so there is only one way to triangulate it.)" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("above", "case"))

    def _polygons(self):
        """The crossed edges (as corner pairs) and the polygons they form: on every face of the
        cube the two crossed edges (no face is ambiguous) are joined by one segment, and the
        segments close up into polygons. Each polygon is a list of corner pairs."""
        up = set(self.above)
        edges = [(int(a), int(b)) for a, b in scivis.CUBE_EDGES if (a in up) != (b in up)]
        corners = scivis.CUBE_CORNERS
        group = {e: e for e in edges}

        def root(e):
            while group[e] != e:
                e = group[e]
            return e

        for axis in range(3):
            for side in (0, 1):
                face = {k for k in range(8) if corners[k][axis] == side}
                on_face = [e for e in edges if set(e) <= face]
                if on_face:                      # exactly two: one segment across the face
                    group[root(on_face[0])] = root(on_face[1])
        polygons = {}
        for e in edges:
            polygons.setdefault(root(e), []).append(e)
        return edges, list(polygons.values())

    def hints(self):
        edges, polygons = self._polygons()
        return [
            r"Marching cubes puts one vertex on every edge whose two corners lie on different "
            r"sides of the isovalue; on every face the crossings are joined by a segment, the "
            r"segments close up into polygons, and a polygon with $m$ vertices is cut into "
            r"$m - 2$ triangles.",
            rf"Here {len(edges)} edges are crossed (corner pairs "
            + ", ".join(f"{a}-{b}" for a, b in edges) + r"): that many vertices.",
            (rf"The vertices form {len(polygons)} separate polygons, with "
             + " and ".join(str(len(p)) for p in polygons) + r" vertices; each gives $m - 2$ "
             r"triangles." if len(polygons) > 1 else
             rf"The vertices form one polygon with {len(polygons[0])} vertices: it gives "
             r"$m - 2$ triangles."),
        ]

    def worked(self):
        edges, polygons = self._polygons()
        counts = [len(p) - 2 for p in polygons]
        total = sum(counts)
        listed = "; ".join(
            f"polygon {i + 1} through the edges " + ", ".join(f"{a}-{b}" for a, b in p)
            + rf" ($m = {len(p)}$: ${len(p)} - 2 = {len(p) - 2}$ triangle"
            + ("s" if len(p) != 3 else "") + ")" for i, p in enumerate(polygons))
        return Worked([
            rf"The corners above are {', '.join(str(c) for c in self.above)}. A vertex lies on "
            rf"every edge from an above to a below corner: {len(edges)} edges, "
            + ", ".join(f"{a}-{b}" for a, b in edges) + ".",
            r"On each face of the cube that has crossings, exactly two of its edges are crossed "
            r"(no face is ambiguous), and a segment joins them; following the segments from face "
            r"to face closes the polygons: " + listed + ".",
            (rf"In all ${' + '.join(str(c) for c in counts)} = {total}$ triangles."
             if len(counts) > 1 else
             rf"So marching cubes makes {total} triangle{'s' if total != 1 else ''} in this "
             r"cube."),
        ], total)


# ---------------------------------------------------------------------------------------------
# Volume rendering
# ---------------------------------------------------------------------------------------------

_TENTHS = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0)


def _samples_table(colors, alphas):
    return ("| sample $i$ | " + " | ".join(str(i) for i in range(len(alphas))) + " |\n"
            + "|---" * (len(alphas) + 1) + "|\n"
            + "| grey level $c_i$ | " + " | ".join(_num(c) for c in colors) + " |\n"
            + r"| opacity $\alpha_i$ | " + " | ".join(_num(a) for a in alphas) + " |")


class CompositeFrontToBack(_Chapter18):
    r"""Composite grey samples along a ray front to back, by hand.

    :math:`C \leftarrow C + (1 - A)\,\alpha_i c_i`, :math:`A \leftarrow A + (1 - A)\,\alpha_i`,
    from :math:`C = A = 0`, sample 0 (the front) first.

    Attributes: ``colors`` (grey levels), ``alphas`` (opacities).

    Examples
    --------
    >>> ex = CompositeFrontToBack(seed=0)
    >>> C, A = scivis.composite(ex.colors, ex.alphas)
    >>> ex.check([C, A]).status
    'correct'
    >>> ex.check(list(scivis.composite(ex.colors[::-1], ex.alphas[::-1]))).diagnosis
    'back first'
    """

    title = "Compositing front to back"
    answer_form = "vector"
    what = "$[C, A]$"
    advice = (r"Keep two running numbers, starting at $C = A = 0$; for each sample from the front "
              r"add $(1 - A)\,\alpha_i c_i$ to $C$ (what still shines through times the "
              r"sample's contribution), then $(1 - A)\,\alpha_i$ to $A$.")

    def draw(self, rng):
        self.colors = np.array([pick(rng, _TENTHS) for _ in range(3)])
        self.alphas = np.array([pick(rng, (0.2, 0.4, 0.5, 0.6, 0.8)) for _ in range(3)])
        C, A = scivis.composite(self.colors, self.alphas)
        self.expected = np.array([C, A])

    def mistakes(self):
        c, a = self.colors, self.alphas
        C, A = 0.0, 0.0
        for ci, ai in zip(c, a):                       # alpha forgotten in the colour
            C, A = C + (1 - A) * ci, A + (1 - A) * ai
        return [
            Mistake(list(scivis.composite(c[::-1], a[::-1])), r"You composited with the last "
                    r"sample in front (or used the back-to-front *over* formula in the order "
                    r"given, which treats sample 0 as the back). Sample 0 is nearest the eye: it "
                    r"hides what lies behind it.", "back first"),
            Mistake([C, A], r"You added $(1 - A)\,c_i$ to the colour, without the sample's "
                    r"opacity. A sample contributes its colour *weighted by how opaque it is*: "
                    r"$(1 - A)\,\alpha_i c_i$.", "alpha forgotten"),
            Mistake([float(a @ c), float(a.sum())], r"You summed $\alpha_i c_i$ and "
                    r"$\alpha_i$ without the transparency factor $1 - A$: samples behind "
                    r"others are only seen through them, so each contribution is multiplied by "
                    r"what still shines through, $1 - A$ (and $A$ can never exceed 1).",
                    "no transparency"),
        ]

    def statement(self):
        return (
            r"A ray meets three samples, listed from the front (nearest the eye):" "\n\n"
            + _samples_table(self.colors, self.alphas) + "\n\n"
            r"Composite them **front to back**: start with $C = 0$, $A = 0$ and for "
            r"$i = 0, 1, 2$ set $C \leftarrow C + (1 - A)\,\alpha_i c_i$ and "
            r"$A \leftarrow A + (1 - A)\,\alpha_i$. What are the final $C$ and $A$?" "\n\n"
            r"**Answer:** a list of 2 numbers `[C, A]`. " + DECIMALS + "\n\n"
            + data_note("colors", "alphas"))

    def _running(self):
        """(C, A) after each sample, front first."""
        C = A = 0.0
        out = []
        for c, a in zip(self.colors, self.alphas):
            C, A = C + (1 - A) * float(a) * float(c), A + (1 - A) * float(a)
            out.append((C, A))
        return out

    def hints(self):
        (C0, A0), (C1, A1), _ = self._running()
        a, c = self.alphas, self.colors
        return [
            r"Front to back: keep the colour $C$ and the opacity $A$ gathered so far; a sample "
            r"is seen only through what is still transparent, $1 - A$: "
            r"$C \leftarrow C + (1 - A)\,\alpha_i c_i$, $A \leftarrow A + (1 - A)\,\alpha_i$.",
            rf"Sample 0 meets a clear ray ($A = 0$): $C = {_num(a[0])} \cdot {_num(c[0])} = "
            rf"{_num(C0, 4)}$ and $A = {_num(A0, 4)}$.",
            rf"Sample 1 is seen through $1 - A = {_num(1 - A0, 4)}$: $C = {_num(C0, 4)} + "
            rf"{_num(1 - A0, 4)} \cdot {_num(a[1])} \cdot {_num(c[1])} = {_num(C1, 4)}$, "
            rf"$A = {_num(A0, 4)} + {_num(1 - A0, 4)} \cdot {_num(a[1])} = {_num(A1, 4)}$; "
            r"sample 2 in the same way.",
        ]

    def worked(self):
        steps = [r"Start with $C = 0$, $A = 0$, and take the samples from the front."]
        C = A = 0.0
        for i, (c, a) in enumerate(zip(self.colors, self.alphas)):
            left = 1 - A
            C_new, A_new = C + left * float(a) * float(c), A + left * float(a)
            steps.append(rf"Sample {i} ($c_{i} = {_num(c)}$, $\alpha_{i} = {_num(a)}$), seen "
                         rf"through $1 - A = {_num(left, 4)}$: $C = {_num(C, 4)} + "
                         rf"{_num(left, 4)} \cdot {_num(a)} \cdot {_num(c)} = {_num(C_new, 4)}$, "
                         rf"$A = {_num(A, 4)} + {_num(left, 4)} \cdot {_num(a)} = "
                         rf"{_num(A_new, 4)}$.")
            C, A = C_new, A_new
        return Worked(steps, [C, A])


class EarlyTermination(_Chapter18):
    r"""After how many samples early ray termination stops a ray.

    The accumulated opacity :math:`A_k = 1 - \prod_{i < k} (1 - \alpha_i)` after :math:`k`
    samples; the ray stops after the first :math:`k` with :math:`A_k \ge` the threshold.

    Attributes: ``alphas``, ``threshold``.

    Examples
    --------
    >>> ex = EarlyTermination(seed=0)
    >>> A = 1 - np.cumprod(1 - ex.alphas)
    >>> ex.check(int(np.argmax(A >= ex.threshold)) + 1).status
    'correct'
    """

    title = "Early ray termination"
    answer_form = "number"
    what = "the number of samples"
    advice = (r"Track $A \leftarrow A + (1 - A)\,\alpha_i$ (or the transparency "
              r"$T = 1 - A$, multiplied by $1 - \alpha_i$ at each sample) and stop as soon as "
              r"$A$ reaches the threshold.")

    def draw(self, rng):
        self.alphas = np.array([pick(rng, (0.2, 0.3, 0.4, 0.5, 0.6, 0.7)) for _ in range(10)])
        self.threshold = float(pick(rng, (0.9, 0.95)))
        _, A = scivis.composite(np.zeros(10), self.alphas, cumulative=True)
        reached = A >= self.threshold - 1e-9         # 1 - 0.1 may come out as 0.8999...
        self.expected = int(np.argmax(reached)) + 1 if reached.any() else 0

    def acceptable(self):
        return 3 <= self.expected <= 9

    def mistakes(self):
        total = np.cumsum(self.alphas)
        summed = int(np.argmax(total >= self.threshold - 1e-9)) + 1
        return [
            Mistake(summed, r"You added up the opacities. Each sample only covers the part that "
                    r"is still transparent: $A \leftarrow A + (1 - A)\,\alpha_i$, so $A$ grows "
                    r"more and more slowly and never passes 1.", "summed opacities"),
            Mistake(self.expected - 1, r"One sample too few: check $A$ after each sample, "
                    r"including the last one you count; the ray stops only once $A$ has "
                    r"reached the threshold.", "off by one"),
            Mistake(self.expected + 1, r"One sample too many: the ray stops right after the "
                    r"sample that brings $A$ to the threshold; that sample is the last one "
                    r"composited.", "off by one"),
        ]

    def statement(self):
        alphas = ", ".join(_num(a) for a in self.alphas)
        return (
            r"A ray is composited front to back with early ray termination: it stops as soon as "
            rf"the accumulated opacity $A$ reaches ${_num(self.threshold)}$. Its samples have the "
            rf"opacities (from the front) ${alphas}$. How many samples are composited before "
            r"it stops (counting the one that reaches the threshold)?" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("alphas", "threshold"))

    def _opacities(self):
        """The accumulated opacity after each sample, up to the one that reaches the threshold
        (rounded to 12 decimals: 1 - 0.1 is 0.9 here, not 0.8999...)."""
        out, transparency = [], 1.0
        for a in self.alphas:
            transparency *= 1 - float(a)
            out.append(round(1 - transparency, 12))
            if out[-1] >= self.threshold:
                break
        return out

    def hints(self):
        A = self._opacities()
        return [
            r"Track the transparency left, $T = 1 - A$: each sample multiplies it by "
            r"$1 - \alpha_i$ (the same as $A \leftarrow A + (1 - A)\,\alpha_i$). The ray stops "
            r"after the sample at which $A$ reaches the threshold.",
            rf"$A \ge {_num(self.threshold)}$ means $T \le {_num(1 - self.threshold)}$. After "
            rf"the first two samples $T = (1 - {_num(self.alphas[0])})(1 - "
            rf"{_num(self.alphas[1])}) = {_num(1 - A[1], 4)}$, $A = {_num(A[1], 4)}$.",
            rf"After {len(A) - 1} samples $A = {_num(A[-2], 4)}$, still below "
            rf"${_num(self.threshold)}$; look at the next sample.",
        ]

    def worked(self):
        A = self._opacities()
        rows = ", ".join(rf"$A_{k} = {_num(x, 4)}$" for k, x in enumerate(A, 1))
        count = len(A)
        steps = [
            r"Composite the opacities front to back: $A_k = A_{k-1} + (1 - A_{k-1})\,\alpha_k$, "
            r"or, with the transparency, $1 - A_k = (1 - A_{k-1})(1 - \alpha_k)$, from "
            r"$A_0 = 0$.",
            rf"Sample by sample ($\alpha = {', '.join(_num(a) for a in self.alphas[:count])}$): "
            + rows + ".",
            rf"$A_{{{count - 1}}} = {_num(A[-2], 4)} < {_num(self.threshold)}$ but "
            rf"$A_{{{count}}} = {_num(A[-1], 4)} \ge {_num(self.threshold)}$"
            + (r" (exactly the threshold: reaching it counts)" if A[-1] == self.threshold
               else "") + rf": the ray stops after {count} samples.",
        ]
        return Worked(steps, count)


class OpacityCorrection(_Chapter18):
    r"""The opacity of a sample for a new step size: :math:`\alpha' = 1 - (1 - \alpha)^{\Delta}`.

    A transfer function gives the opacity :math:`\alpha` of a slab of unit thickness; light
    through a slab of thickness :math:`\Delta` keeps the fraction :math:`(1 - \alpha)^\Delta`.

    Attributes: ``alpha``, ``step``.

    Examples
    --------
    >>> ex = OpacityCorrection(seed=0)
    >>> ex.check(1 - (1 - ex.alpha) ** ex.step).status
    'correct'
    >>> ex.check(ex.alpha * ex.step).diagnosis
    'linear'
    """

    title = "Opacity correction for the step size"
    answer_form = "number"
    what = "the corrected opacity"
    advice = (r"Transparencies multiply: a slab of thickness $\Delta$ lets "
              r"$(1 - \alpha)^{\Delta}$ through, so its opacity is $1 - (1 - \alpha)^{\Delta}$.")

    def draw(self, rng):
        self.alpha = float(pick(rng, (0.2, 0.25, 0.3, 0.35, 0.4, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8,
                                      0.85, 0.9, 0.95)))
        self.step = float(pick(rng, (0.25, 0.5, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0)))
        self.expected = 1 - (1 - self.alpha) ** self.step

    def mistakes(self):
        a, d = self.alpha, self.step
        return [
            Mistake(a * d, r"You scaled the opacity linearly with the step. Opacity does not "
                    r"add up: two slabs of opacity 0.5 let $0.5 \cdot 0.5 = 0.25$ through, "
                    r"opacity 0.75, not 1. The transparencies multiply: "
                    r"$1 - (1 - \alpha)^{\Delta}$.", "linear"),
            Mistake(a ** d, r"You raised the opacity to the power $\Delta$. It is the "
                    r"**transparency** $1 - \alpha$ that is multiplied per unit length: "
                    r"$\alpha' = 1 - (1 - \alpha)^{\Delta}$.", "power of alpha"),
            Mistake((1 - a) ** d, r"That is the transparency $(1 - \alpha)^{\Delta}$ of the "
                    r"slab, the light that gets through. The opacity is one minus it.",
                    "transparency"),
            Mistake(1 - (1 - a) ** (1 / d), r"You used the exponent $1/\Delta$. A slab "
                    r"$\Delta$ units thick is like $\Delta$ unit slabs in a row: exponent "
                    r"$\Delta$.", "inverse step"),
        ]

    def statement(self):
        return (
            rf"A transfer function gives the opacity $\alpha = {_num(self.alpha)}$ per unit "
            r"length (one voxel). A ray caster samples the volume every "
            rf"$\Delta = {_num(self.step)}$ voxels. Which opacity must each sample get so that "
            r"the picture does not depend on the step size?" "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n" + data_note("alpha", "step"))

    def hints(self):
        kept = 1 - self.alpha
        return [
            r"Opacities do not add up, transparencies multiply: light through two slabs in a "
            r"row is what the first lets through times what the second lets through.",
            rf"One voxel of material lets $1 - \alpha = {_num(kept)}$ of the light through; a "
            rf"sample that stands for $\Delta = {_num(self.step)}$ voxels lets "
            rf"$(1 - \alpha)^{{\Delta}} = {_num(kept)}^{{{_num(self.step)}}}$ through.",
            rf"${_num(kept)}^{{{_num(self.step)}}} = {_num(kept ** self.step, 4)}$; the opacity "
            r"of the sample is what it does **not** let through.",
        ]

    def worked(self):
        kept = 1 - self.alpha
        through = kept ** self.step
        corrected = 1 - through
        return Worked([
            rf"Per voxel the transparency is $1 - \alpha = 1 - {_num(self.alpha)} = "
            rf"{_num(kept)}$; transparencies multiply along the ray.",
            rf"A step of $\Delta = {_num(self.step)}$ voxels: "
            rf"$(1 - \alpha)^{{\Delta}} = {_num(kept)}^{{{_num(self.step)}}} = "
            rf"{_num(through, 4)}$ of the light gets through.",
            rf"$\alpha' = 1 - (1 - \alpha)^{{\Delta}} = 1 - {_num(through, 4)} = "
            rf"{_num(corrected, 4)}$ ("
            + ("more" if self.step > 1 else "less") + r" than $\alpha$: the step is "
            + ("longer" if self.step > 1 else "shorter") + r" than a voxel).",
        ], corrected)


_AXES = {0: "z", 1: "y", 2: "x"}


class MaxIntensityProjection(_Chapter18):
    r"""A maximum intensity projection of a tiny 3 x 3 x 3 volume along one axis.

    The volume is ``volume[k, j, i]``, the sample at :math:`(x, y, z) = (i, j, k)`; rays
    parallel to an axis keep the largest sample: ``volume.max(axis)``.

    Attributes: ``volume``, ``axis`` (the array axis the rays run along), ``axis_name``.

    Examples
    --------
    >>> ex = MaxIntensityProjection(seed=0)
    >>> ex.check(ex.volume.max(axis=ex.axis)).status
    'correct'
    >>> ex.check(ex.volume.sum(axis=ex.axis)).diagnosis
    'sum'
    """

    title = "Maximum intensity projection"
    answer_form = "matrix"
    what = "the projected image"
    transform = False
    advice = r"Along each ray (fix the two other indices) keep the largest of the three samples."

    def draw(self, rng):
        self.volume = rng.integers(0, 10, size=(3, 3, 3)).astype(float)
        self.axis = int(pick(rng, (0, 1, 2)))
        self.axis_name = _AXES[self.axis]
        self.expected = self.volume.max(axis=self.axis)

    def mistakes(self):
        v, ax = self.volume, self.axis
        return [
            *(Mistake(v.max(axis=other), rf"You projected along the {_AXES[other]} axis (array "
                      rf"axis {other}). The rays run along {self.axis_name}, array axis {ax}: "
                      rf"take the maximum over index {'kji'[ax]}.", "wrong axis")
              for other in (0, 1, 2) if other != ax),
            Mistake(v.sum(axis=ax), r"You summed the samples along each ray: that is an "
                    r"X-ray-like projection (an average up to a factor). MIP keeps only the "
                    r"largest sample, so the brightest structure shows at full intensity.",
                    "sum"),
            Mistake(v.mean(axis=ax), r"You averaged the samples along each ray. MIP keeps the "
                    r"largest sample: a bright vessel stays bright however thin it is.", "mean"),
            Mistake(v.min(axis=ax), r"You took the smallest sample: MIP takes the **maximum**.",
                    "min"),
        ]

    def statement(self):
        slices = "\n\n".join(
            rf"$k = {k}$ ($z = {k}$): " + ", ".join(
                rf"row $j = {j}$: ${_vec(self.volume[k, j])}$" for j in range(3))
            for k in range(3))
        return (
            r"A tiny volume holds the samples `volume[k][j][i]` at $(x, y, z) = (i, j, k)$ "
            r"(each row lists $i = 0, 1, 2$):" "\n\n" + slices + "\n\n"
            rf"Compute its maximum intensity projection with rays parallel to the "
            rf"**{self.axis_name} axis** (array axis {self.axis})." "\n\n"
            r"**Answer:** the image as a 3 x 3 array whose rows and columns follow the two "
            r"remaining array axes in their order (so `volume.max(axis=...)` has the right "
            r"layout)." "\n\n" + data_note("volume", "axis"))

    def _layout(self):
        """The names of the two array axes left (rows, columns of the image)."""
        left = [i for i in range(3) if i != self.axis]
        return ["kji"[i] for i in left]

    def _ray(self, r, c):
        """The three samples along the ray of pixel (r, c)."""
        index = [r, c]
        index.insert(self.axis, slice(None))
        return [float(x) for x in self.volume[tuple(index)]]

    def hints(self):
        rows, cols = self._layout()
        ray = self._ray(0, 0)
        return [
            r"A maximum intensity projection keeps, along each ray, only the **largest** sample "
            r"(no sum, no average).",
            rf"Rays parallel to the {self.axis_name} axis run over the index "
            rf"${'kji'[self.axis]}$ (array axis {self.axis}); the image pixel $[{rows}][{cols}]$ "
            rf"is the maximum of the three samples with those ${rows}$ and ${cols}$.",
            rf"For example pixel $[0][0]$: the samples ${', '.join(_num(x) for x in ray)}$ along "
            rf"its ray, so it gets ${_num(max(ray))}$.",
        ]

    def worked(self):
        rows, cols = self._layout()
        image = [[max(self._ray(r, c)) for c in range(3)] for r in range(3)]
        steps = [rf"The rays run along array axis {self.axis} (index ${'kji'[self.axis]}$); the "
                 rf"image's rows follow ${rows}$ and its columns ${cols}$."]
        for r in range(3):
            steps.append(rf"Row ${rows} = {r}$: " + ", ".join(
                rf"$\max({', '.join(_num(x) for x in self._ray(r, c))}) = {_num(image[r][c])}$"
                for c in range(3)) + ".")
        return Worked(steps, image)


# ---------------------------------------------------------------------------------------------
# Streamlines
# ---------------------------------------------------------------------------------------------

def _linear(a, b):
    """The expression a x + b y with whole coefficients, as LaTeX ("2x - y", "-x", "0")."""
    text = ""
    for coef, var in ((a, "x"), (b, "y")):
        if coef == 0:
            continue
        size = "" if abs(coef) == 1 else _num(abs(coef))
        sign = "-" if coef < 0 else ("+" if text else "")
        text += (f" {sign} " if text else sign) + size + var
    return text or "0"


def _at(q):
    """The field at the point q, as LaTeX: v(x, y)."""
    return "v" + _vec(q, 4)


class RK4Step(_Chapter18):
    r"""One step of the classic Runge-Kutta method (RK4) in a linear velocity field.

    :math:`v(p) = M p`; :math:`k_1 = v(p)`, :math:`k_2 = v(p + \tfrac h2 k_1)`,
    :math:`k_3 = v(p + \tfrac h2 k_2)`, :math:`k_4 = v(p + h k_3)`,
    :math:`p' = p + \tfrac h6 (k_1 + 2k_2 + 2k_3 + k_4)`.

    Attributes: ``M`` (the 2 x 2 matrix of the field), ``p`` (the start point), ``h``.

    Examples
    --------
    >>> ex = RK4Step(seed=0)
    >>> v = lambda q: ex.M @ q
    >>> k1 = v(ex.p); k2 = v(ex.p + ex.h / 2 * k1); k3 = v(ex.p + ex.h / 2 * k2)
    >>> k4 = v(ex.p + ex.h * k3)
    >>> ex.check(ex.p + ex.h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)).status
    'correct'
    >>> ex.check(ex.p + ex.h * k1).diagnosis
    'euler'
    """

    title = "One RK4 step"
    answer_form = "point"
    what = "the new point"
    may_coincide = ("no h",)
    advice = (r"Compute the four slopes one after the other, each from the previous one "
              r"($k_2$ and $k_3$ half a step ahead, $k_4$ a full step), then take the weighted "
              r"average $\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$ times $h$.")

    def draw(self, rng):
        self.M = rng.integers(-2, 3, size=(2, 2)).astype(float)
        self.p = rng.integers(-2, 3, size=2).astype(float)
        self.h = 0.5
        self.expected = scivis.streamline(self._v, self.p, self.h, n_steps=1, method="rk4")[1]

    def _v(self, q):
        return np.asarray(q, dtype=float) @ self.M.T

    def acceptable(self):
        return np.linalg.matrix_rank(self.M) == 2 and bool(self.p.any()) and bool(
            np.isfinite(self.expected).all())

    def mistakes(self):
        v, p, h = self._v, self.p, self.h
        k1 = v(p)
        k2 = v(p + h / 2 * k1)
        k3 = v(p + h / 2 * k2)
        k4 = v(p + h * k3)
        f2 = v(p + h * k1)
        f3 = v(p + h * f2)
        f4 = v(p + h * f3)
        return [
            Mistake(p + h * k1, r"That is one **Euler** step, $p + h\,k_1$: it follows the "
                    r"slope at the start only. RK4 also samples the field half a step and a full "
                    r"step ahead and averages four slopes.", "euler"),
            Mistake(p + h * k2, r"That is the **midpoint** method (RK2), $p + h\,k_2$. RK4 goes "
                    r"on: $k_3 = v(p + \tfrac h2 k_2)$, $k_4 = v(p + h\,k_3)$, and averages "
                    r"$\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$.", "rk2"),
            Mistake(p + h / 4 * (k1 + k2 + k3 + k4), r"You averaged the four slopes with equal "
                    r"weights. The middle slopes count twice: $\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$ "
                    r"(Simpson's rule).", "equal weights"),
            Mistake(p + h / 6 * (k1 + 2 * f2 + 2 * f3 + f4), r"You evaluated $k_2$ and $k_3$ a "
                    r"full step ahead. They are taken at the half step: "
                    r"$k_2 = v(p + \tfrac h2 k_1)$, $k_3 = v(p + \tfrac h2 k_2)$.",
                    "full steps"),
            Mistake(p + (k1 + 2 * k2 + 2 * k3 + k4) / 6, r"You forgot to multiply the averaged "
                    r"slope by the step $h$: $p' = p + \frac h6 (k_1 + 2k_2 + 2k_3 + k_4)$.",
                    "no h"),
        ]

    def statement(self):
        (a, b), (c, d) = self.M
        return (
            rf"A 2D velocity field is $v(x, y) = ({_linear(a, b)},\ {_linear(c, d)})$, i.e. "
            rf"$v(p) = M p$ with $M = {fmt.matrix_latex(self.M)}$. Trace a "
            rf"streamline from $p = {_vec(self.p)}$ with one step of the classic Runge-Kutta "
            rf"method (RK4) of size $h = {_num(self.h)}$: $k_1 = v(p)$, "
            r"$k_2 = v(p + \tfrac h2 k_1)$, $k_3 = v(p + \tfrac h2 k_2)$, $k_4 = v(p + h\,k_3)$, "
            r"$p' = p + \tfrac h6 (k_1 + 2k_2 + 2k_3 + k_4)$." "\n\n"
            r"**Answer:** the point $p'$ as a list of 2 numbers `[x, y]`. " + DECIMALS + "\n\n"
            + data_note("M", "p", "h"))

    def _slopes(self):
        """The points where the field is sampled and the four slopes, v(q) = M q by hand."""
        M, p, h = self.M, self.p, self.h

        def v(q):
            return np.array([M[0, 0] * q[0] + M[0, 1] * q[1], M[1, 0] * q[0] + M[1, 1] * q[1]])

        k1 = v(p)
        q2 = p + h / 2 * k1
        k2 = v(q2)
        q3 = p + h / 2 * k2
        k3 = v(q3)
        q4 = p + h * k3
        k4 = v(q4)
        return (k1, q2, k2, q3, k3, q4, k4)

    def hints(self):
        k1, q2, k2, q3, k3, q4, k4 = self._slopes()
        return [
            r"RK4 samples the field four times: at the start ($k_1$), twice half a step ahead "
            r"($k_2$ from $k_1$, $k_3$ from $k_2$) and once a full step ahead ($k_4$ from $k_3$), "
            r"then moves by $h$ times the weighted mean $\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$.",
            rf"$k_1 = v(p) = M p = {_vec(k1, 4)}$; the half step goes to "
            rf"$p + \tfrac h2 k_1 = {_vec(q2, 4)}$.",
            rf"$k_2 = {_at(q2)} = {_vec(k2, 4)}$, then "
            rf"$k_3 = v(p + \tfrac h2 k_2) = {_at(q3)} = {_vec(k3, 4)}$.",
        ]

    def worked(self):
        k1, q2, k2, q3, k3, q4, k4 = self._slopes()
        mean = (k1 + 2 * k2 + 2 * k3 + k4) / 6
        new = self.p + self.h * mean
        return Worked([
            rf"$k_1 = v(p) = M {_vec(self.p)} = {_vec(k1, 4)}$.",
            rf"$k_2 = v(p + \tfrac h2 k_1) = {_at(q2)} = {_vec(k2, 4)}$.",
            rf"$k_3 = v(p + \tfrac h2 k_2) = {_at(q3)} = {_vec(k3, 4)}$.",
            rf"$k_4 = v(p + h\,k_3) = {_at(q4)} = {_vec(k4, 4)}$.",
            rf"Weighted mean: $\frac16 (k_1 + 2k_2 + 2k_3 + k_4) = {_vec(mean, 4)}$, so "
            rf"$p' = p + h \cdot {_vec(mean, 4)} = {_vec(self.p)} + {_num(self.h)} \cdot "
            rf"{_vec(mean, 4)} = {_vec(new, 4)}$.",
        ], new)


class EulerDrift(_Chapter18):
    r"""How far Euler's method drifts outwards on the circular flow :math:`v = (-y, x)`.

    One Euler step moves along the tangent, :math:`|p + h\,v(p)| = |p| \sqrt{1 + h^2}`, so after
    :math:`n` steps the radius is :math:`r_0 (1 + h^2)^{n/2}` instead of :math:`r_0`.

    Attributes: ``r0``, ``h``, ``n``.

    Examples
    --------
    >>> ex = EulerDrift(seed=0)
    >>> ex.check(ex.r0 * (1 + ex.h ** 2) ** (ex.n / 2)).status
    'correct'
    >>> ex.check(ex.r0).diagnosis
    'no drift'
    """

    title = "Euler's drift on a circular flow"
    answer_form = "number"
    what = "the radius"
    advice = (r"Each Euler step is perpendicular to the radius and $h\,r$ long: Pythagoras gives "
              r"the new radius $r\sqrt{1 + h^2}$; repeat $n$ times.")

    def draw(self, rng):
        self.r0 = float(pick(rng, (1, 2, 3, 4, 5)))
        self.h = float(pick(rng, (0.1, 0.2, 0.25, 0.3, 0.4, 0.5)))
        self.n = int(rng.integers(3, 13))
        line = scivis.streamline(scivis.example_vector_field("vortex"), [self.r0, 0.0], self.h,
                                 n_steps=self.n, method="euler")
        self.expected = float(np.linalg.norm(line[-1]))

    def mistakes(self):
        r, h, n = self.r0, self.h, self.n
        return [
            Mistake(r, r"On the exact streamline the radius stays $r_0$, but Euler's method "
                    r"does not follow it: each step goes along the tangent and ends outside "
                    r"the circle.", "no drift"),
            Mistake(r * np.sqrt(1 + h * h), rf"That is the radius after one step; the "
                    rf"question asks for $n = {n}$. Each step multiplies the radius by "
                    r"$\sqrt{1 + h^2}$ again.", "one step"),
            Mistake(r * (1 + h * h) ** n, r"You forgot the square root: a step of length "
                    r"$h\,r$ at right angles to the radius gives $r\sqrt{1 + h^2}$ "
                    r"(Pythagoras), not $r (1 + h^2)$.", "no root"),
            Mistake(r * (1 + h) ** n, r"The step is at right angles to the radius, not along "
                    r"it: the radius grows by the factor $\sqrt{1 + h^2}$, not $1 + h$.",
                    "radial step"),
        ]

    def statement(self):
        return (
            r"The velocity field $v(x, y) = (-y, x)$ turns around the origin: its streamlines "
            rf"are circles. Starting at $({_num(self.r0)}, 0)$, a streamline is traced with "
            rf"$n = {self.n}$ steps of **Euler's method**, $p \leftarrow p + h\,v(p)$, with "
            rf"$h = {_num(self.h)}$. How far from the origin is the last point?" "\n\n"
            r"**Answer:** one number (the radius). " + DECIMALS + "\n\n"
            + data_note("r0", "h", "n"))

    def hints(self):
        factor = math.sqrt(1 + self.h ** 2)
        return [
            r"At $p$ the velocity $v(p) = (-y, x)$ is perpendicular to $p$ and as long as $p$: "
            r"an Euler step goes along the tangent, a distance $h\,\lVert p \rVert$.",
            rf"Pythagoras: one step takes the radius from $r$ to $r\sqrt{{1 + h^2}} = "
            rf"r\sqrt{{{_num(1 + self.h ** 2, 4)}}} = {_num(factor, 4)}\, r$.",
            rf"Each of the {self.n} steps multiplies the radius by that factor again: "
            rf"$r_{{{self.n}}} = {_num(self.r0)} \cdot {_num(factor, 4)}^{{{self.n}}}$.",
        ]

    def worked(self):
        factor = math.sqrt(1 + self.h ** 2)
        radius = self.r0 * factor ** self.n
        return Worked([
            rf"A step from $p$ moves by $h\,v(p)$, perpendicular to $p$ (as $v \cdot p = -yx + "
            rf"xy = 0$) and of length $h\,\lVert p \rVert$: by Pythagoras the new radius is "
            rf"$\lVert p \rVert \sqrt{{1 + h^2}} = \sqrt{{1 + {_num(self.h ** 2, 4)}}}\, "
            rf"\lVert p \rVert = {_num(factor, 5)}\, \lVert p \rVert$.",
            rf"After $n = {self.n}$ steps: $r = r_0 (1 + h^2)^{{n/2}} = {_num(self.r0)} \cdot "
            rf"{_num(factor, 5)}^{{{self.n}}} = {_num(radius, 4)}$, "
            rf"{_num(100 * (factor ** self.n - 1), 1)} % outside the true circle of radius "
            rf"{_num(self.r0)}.",
        ], radius)


#: The exercises of chapter 18, in the order of the solutions notebook.
EXERCISES = (
    SquareCaseIndex,
    SquareCrossings,
    SaddleResolution,
    CubeTriangleCount,
    CompositeFrontToBack,
    EarlyTermination,
    OpacityCorrection,
    MaxIntensityProjection,
    RK4Step,
    EulerDrift,
)
