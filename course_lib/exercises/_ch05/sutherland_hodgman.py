"""Chapter 5 exercises: Sutherland-Hodgman.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import numpy as np

from ... import clipping
from ..core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note,
                    diagnose_parts, latex_fraction, latex_vector, parts_separated, pick,
                    read_floats)
from . import (_box_words, _cross2, _cyclic_match, _draw_box_2d, _ints_between, _num, _shoelace,
               _unanswered, _vec)

__all__ = [
    "SutherlandHodgmanArea",
    "SutherlandHodgmanOneSide",
]


#: For each side: the coordinate it bounds and whether the inside is below (<=) the value.
_SIDE_PLANES = {"left": (0, False), "right": (0, True), "bottom": (1, False), "top": (1, True)}


def _side_plane(side, value):
    axis, upper = _SIDE_PLANES[side]
    normal = np.zeros(2)
    normal[axis] = 1.0 if upper else -1.0
    return normal, (value if upper else -value)


def _inside_words(side, value):
    axis, upper = _SIDE_PLANES[side]
    relation = r"\le" if upper else r"\ge"
    return rf"${'xy'[axis]} {relation} {_num(value)}$"


def _clip_by_hand(polygon, side, value, names=None):
    """One stage of Sutherland-Hodgman worked by hand: (the output vertices, one step per edge).

    `names` are the vertices' names in the text (``v_0``, ...); by default their coordinates.
    """
    axis, upper = _SIDE_PLANES[side]
    polygon = [np.asarray(p, dtype=float) for p in polygon]
    n = len(polygon)
    names = names or [latex_vector(p) for p in polygon]

    def inside(p):
        return p[axis] <= value if upper else p[axis] >= value

    out, lines = [], []
    for i in range(n):
        S, E = polygon[i], polygon[(i + 1) % n]
        s_in, e_in = inside(S), inside(E)
        edge = rf"${names[i]} \to {names[(i + 1) % n]}$"
        if s_in != e_in:
            t = (value - S[axis]) / (E[axis] - S[axis])
            hit = S + t * (E - S)
            hit[axis] = value
            crossing = (rf"crosses ${'xy'[axis]} = {_num(value)}$ at "
                        rf"$t = {latex_fraction(t)}$, $I = {latex_vector(hit)}$")
        if s_in and e_in:
            out.append(E)
            lines.append(rf"{edge}: in $\to$ in, output $E = {latex_vector(E)}$.")
        elif s_in:
            out.append(hit)
            lines.append(rf"{edge}: in $\to$ out, {crossing}: output $I$.")
        elif e_in:
            out.extend([hit, E])
            lines.append(rf"{edge}: out $\to$ in, {crossing}: output $I$, then "
                         rf"$E = {latex_vector(E)}$.")
        else:
            lines.append(rf"{edge}: out $\to$ out, nothing.")
    return out, lines


def _polygon_words(points):
    return ", ".join(f"${latex_vector(p)}$" for p in points)


def _read_polygon(answer):
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    value = read_floats(answer)
    if value is None or value.ndim != 2 or value.shape[1] != 2:
        return Feedback("invalid", "Give the polygon as a list of points `[[x, y], ...]`.",
                        "unreadable")
    return value


_CONVEX_SHAPES = (
    ((0, 0), (4, 0), (2, 4)), ((0, 0), (4, 1), (1, 4)), ((0, 0), (5, 2), (2, 4)),
    ((0, 0), (4, 0), (4, 3), (0, 3)), ((0, 0), (3, -1), (5, 2), (1, 4)),
    ((0, 0), (4, 2), (2, 5), (-1, 3)),
)


class SutherlandHodgmanOneSide(DrawnExercise):
    r"""Clip a polygon by one side of the clip rectangle with Sutherland-Hodgman's four rules.

    For each edge :math:`S \to E` (in order, the last back to the first): in-in gives E, in-out
    gives the intersection I, out-in gives I then E, out-out gives nothing.

    Attributes: ``polygon``, ``side``, ``value``.

    Examples
    --------
    >>> ex = SutherlandHodgmanOneSide(seed=9)
    >>> ex.check(ex.expected).status, ex.check(np.roll(ex.expected, 1, axis=0)).status
    ('correct', 'correct')
    >>> ex.check(ex.expected[::-1]).diagnosis
    'reversed order'
    """

    title = "Sutherland-Hodgman against one side"
    answer_form = "custom"

    def draw(self, rng):
        shape = np.array(pick(rng, _CONVEX_SHAPES), dtype=float)
        if rng.random() < 0.5:
            shape = shape * [-1, 1]
            shape = shape[::-1]                         # keep it counter-clockwise
        shape = np.roll(shape, int(rng.integers(len(shape))), axis=0)
        self.polygon = shape + rng.integers(-2, 3, size=2)
        self.side = str(pick(rng, tuple(_SIDE_PLANES)))
        axis = _SIDE_PLANES[self.side][0]
        low, high = self.polygon[:, axis].min(), self.polygon[:, axis].max()
        self.value = float(rng.integers(int(low), int(high) + 1))
        self.expected = clipping.clip_polygon(self.polygon, [_side_plane(self.side, self.value)])

    def _inside(self):
        axis, upper = _SIDE_PLANES[self.side]
        return self.polygon[:, axis] <= self.value if upper else \
            self.polygon[:, axis] >= self.value

    def acceptable(self):
        axis = _SIDE_PLANES[self.side][0]
        inside = self._inside()
        return (not np.any(self.polygon[:, axis] == self.value) and inside.any()
                and not inside.all())

    def _intersections(self):
        """Indices in `expected` of the intersection points (not vertices of the polygon)."""
        return [i for i, p in enumerate(self.expected)
                if not np.any(np.all(np.isclose(self.polygon, p), axis=1))]

    def mistakes(self):
        found = []
        for i in self._intersections():
            found.append(Mistake(np.delete(self.expected, i, axis=0), r"An intersection "
                                 r"vertex is missing. Each edge that crosses the boundary "
                                 r"contributes its intersection point I: an edge going out "
                                 r"(in $\to$ out) outputs I, an edge coming back in "
                                 r"(out $\to$ in) outputs I and then E.",
                                 "missing intersection vertex"))
        found.append(Mistake(self.expected[::-1], r"Your vertices run the other way round. "
                             r"Keep the polygon's orientation: go through the edges "
                             r"$v_0 \to v_1$, $v_1 \to v_2$, ... in order and append the "
                             r"output of each edge.", "reversed order"))
        axis, upper = _SIDE_PLANES[self.side]
        normal, offset = _side_plane(self.side, self.value)
        found.append(Mistake(clipping.clip_polygon(self.polygon, [(-normal, -offset)]),
                             r"You kept the part **outside** the clip rectangle. The inside of "
                             r"the " + self.side + r" side is $" + "xy"[axis]
                             + (r" \le " if upper else r" \ge ") + _num(self.value) + "$.",
                             "kept the outside part"))
        k = len(self.expected)
        for i in self._intersections():
            after = (i + 1) % k
            if not any(np.allclose(self.expected[after], q) for q in self.polygon):
                continue
            prev_out = not self._inside()[self._index_of(self.expected[after]) - 1]
            if prev_out:                                # I then E from an out -> in edge
                swapped = self.expected.copy()
                swapped[[i, after]] = swapped[[after, i]]
                found.append(Mistake(swapped, r"For an edge coming back in (S outside, E "
                                     r"inside) the output is first the intersection I, then "
                                     r"E: the polygon follows the boundary to I before it "
                                     r"reaches E.", "out-in order"))
        return found

    def _index_of(self, point):
        return int(np.flatnonzero(np.all(np.isclose(self.polygon, point), axis=1))[0])

    def separated(self, mistakes):
        values = [m.value for m in mistakes]
        if any(_cyclic_match(v, self.expected) for v in values):
            return False
        return all(not _cyclic_match(a.value, b.value) for i, a in enumerate(mistakes)
                   for b in mistakes[i + 1:] if a.key != b.key)

    def _check(self, answer):
        value = _read_polygon(answer)
        if isinstance(value, Feedback):
            return value
        if _cyclic_match(value, self.expected):
            return Feedback("correct", "The clipped polygon is right (the starting vertex does "
                            "not matter).")
        for mistake in self._mistakes:
            if _cyclic_match(value, mistake.value):
                return Feedback("wrong", mistake.explanation, mistake.key)
        if len(value) != len(self.expected):
            return Feedback("wrong", f"Your polygon has {len(value)} vertices; the clipped one "
                            f"has {len(self.expected)}. Go through every edge and apply the four "
                            "rules (in-in: E; in-out: I; out-in: I, E; out-out: nothing).",
                            "vertex count differs")
        return Feedback("wrong", "The vertices are not right yet. Apply the four rules to every "
                        "edge in order, including the closing edge from the last vertex back to "
                        "the first.", "vertices differ")

    def hints(self):
        inside = self._inside()
        n = len(self.polygon)
        ins = ", ".join(f"$v_{i}$" for i in range(n) if inside[i])
        crossing = " and ".join(rf"$v_{i} \to v_{(i + 1) % n}$" for i in range(n)
                                if inside[i] != inside[(i + 1) % n])
        return [
            r"Sutherland-Hodgman walks the edges $S \to E$ in order (the last one back to the "
            r"first) and outputs, per edge: in $\to$ in: $E$; in $\to$ out: the intersection "
            r"$I$; out $\to$ in: $I$, then $E$; out $\to$ out: nothing.",
            rf"Inside is {_inside_words(self.side, self.value)}. Classify each vertex; on an "
            r"edge that crosses the line, $I = S + t\,(E - S)$ with $t$ chosen so that $I$ "
            r"lies on the line.",
            rf"Inside: {ins}; the edges that cross the line are {crossing}.",
        ]

    def worked(self):
        n = len(self.polygon)
        out, lines = _clip_by_hand(self.polygon, self.side, self.value,
                                   names=[f"v_{i}" for i in range(n)])
        steps = [rf"Inside is {_inside_words(self.side, self.value)}; the vertices: "
                 + ", ".join(rf"$v_{i} = {_vec(p)}$ ({'in' if ok else 'out'})"
                             for i, (p, ok) in enumerate(zip(self.polygon, self._inside())))
                 + "."]
        steps += lines
        steps.append(rf"The output, in order: {_polygon_words(out)}.")
        return Worked(steps, np.array(out))

    def statement(self):
        axis, upper = _SIDE_PLANES[self.side]
        relation = r"\le" if upper else r"\ge"
        rule = f"${'xy'[axis]} {relation} {_num(self.value)}$"
        return (
            r"The polygon with the vertices (in this order, counter-clockwise) "
            + ", ".join(rf"$v_{i} = {_vec(p)}$" for i, p in enumerate(self.polygon))
            + rf" is clipped against the **{self.side}** side of the clip rectangle only, "
            rf"whose inside is {rule}. Run Sutherland-Hodgman: for the edges "
            r"$v_0 \to v_1$, $v_1 \to v_2$, ..., and finally the closing edge back to $v_0$, "
            r"output the vertices given by the four rules (in-in: E; in-out: I; out-in: I then "
            r"E; out-out: nothing)." "\n\n"
            r"**Answer:** the output vertices in order, as a list of points `[[x, y], ...]`. "
            r"Any starting vertex is accepted, but the order around the polygon matters. "
            + DECIMALS + "\n\n" + data_note("polygon", "side", "value"))


class SutherlandHodgmanArea(DrawnExercise):
    r"""The vertex count and area of a triangle clipped to a rectangle (a corner is cut in).

    Attributes: ``triangle``, ``box_min``, ``box_max``.

    Examples
    --------
    >>> ex = SutherlandHodgmanArea(seed=10)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check([ex.expected[0], ex.triangle_area]).diagnosis
    'unclipped area'
    """

    title = "Sutherland-Hodgman: the clipped triangle"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        lo, hi = self.box_min, self.box_max
        corners = np.array([[x, y] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])])
        while True:                     # a triangle that covers a corner of the rectangle
            self.triangle = _ints_between(rng, lo - 3, hi + 3, size=(3, 2))
            edges = [_cross2(self.triangle[(i + 1) % 3] - self.triangle[i],
                             corners - self.triangle[i]) for i in range(3)]
            if np.any(np.all(np.array(edges) > 0, axis=0) | np.all(np.array(edges) < 0, axis=0)):
                break
        cross = _cross2(self.triangle[1] - self.triangle[0],
                        self.triangle[2] - self.triangle[0])
        if cross < 0:
            self.triangle = self.triangle[::-1].copy()
        self.triangle_area = _shoelace(self.triangle)
        self.clipped = clipping.sutherland_hodgman(self.triangle, lo, hi)
        self.expected = np.array([float(len(self.clipped)), _shoelace(self.clipped)])

    def _corners(self):
        lo, hi = self.box_min, self.box_max
        corners = [np.array([x, y]) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
        return [i for i, p in enumerate(self.clipped)
                if any(np.allclose(p, c) for c in corners)]

    def acceptable(self):
        lo, hi = self.box_min, self.box_max
        t = self.triangle
        if self.triangle_area < 3 or len(self.clipped) < 4:
            return False
        on_lines = np.isin(t[:, 0], [lo[0], hi[0]]) | np.isin(t[:, 1], [lo[1], hi[1]])
        if on_lines.any():                      # a vertex on a side's line: degenerate cases
            return False
        corners = [np.array([x, y]) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
        for i in range(3):                      # no edge through a corner of the rectangle
            a, b = t[i], t[(i + 1) % 3]
            if any(abs(_cross2(b - a, c - a)) < 1e-9 for c in corners):
                return False
        return bool(self._corners()) and len(np.unique(np.round(self.clipped, 9), axis=0)) \
            == len(self.clipped)

    def _parts(self):
        n, area = int(self.expected[0]), float(self.expected[1])
        keep = np.delete(self.clipped, self._corners(), axis=0)
        without = Mistake(_shoelace(keep), r"The rectangle's corner is missing. Where the "
                          r"triangle covers a corner of the clip rectangle, the clipped polygon "
                          r"runs along two sides and turns at that corner, so the corner is a "
                          r"vertex too (Sutherland-Hodgman produces it when it clips by the "
                          r"second of the two sides).", "box corner missing")
        return [
            ("the number of vertices", n, [Mistake(len(keep), without.explanation,
                                                   without.key)]),
            ("the area", area, [
                without,
                Mistake(self.triangle_area, r"That is the area of the whole triangle; only the "
                        r"part inside the rectangle is left after clipping.", "unclipped area"),
            ]),
        ]

    def mistakes(self):
        keep = np.delete(self.clipped, self._corners(), axis=0)
        return [Mistake([len(keep), _shoelace(keep)], "", "box corner missing"),
                Mistake([self.expected[0], self.triangle_area], "", "unclipped area")]

    def separated(self, mistakes):
        return parts_separated(self._parts(), same=None)

    def _check(self, answer):
        return diagnose_parts(answer, self._parts(), "your answer",
                              "`[number_of_vertices, area]`.",
                              "Clip by one side at a time, then compute the area of the final "
                              "polygon with the shoelace formula.")

    def _stages(self):
        lo, hi = self.box_min, self.box_max
        return (("left", lo[0]), ("right", hi[0]), ("bottom", lo[1]), ("top", hi[1]))

    def hints(self):
        corners = ", ".join(f"${latex_vector(self.clipped[i])}$" for i in self._corners())
        return [
            r"Clip the triangle against the four sides one after the other (left, right, "
            r"bottom, top); each stage applies the four rules of Sutherland-Hodgman to the "
            r"polygon the previous stage gave.",
            r"Where the triangle covers a corner of the rectangle, the clipped polygon runs "
            r"along two sides and turns at the corner, which becomes a vertex. The area of "
            r"the final polygon: $A = \frac{1}{2}\left|\sum_i (x_i y_{i+1} - x_{i+1} y_i)"
            r"\right|$.",
            rf"The rectangle's corner {corners} lies inside the triangle and is a vertex of "
            r"the clipped polygon.",
        ]

    def worked(self):
        polygon = [np.asarray(p, dtype=float) for p in self.triangle]
        steps = []
        for side, value in self._stages():
            polygon, lines = _clip_by_hand(polygon, side, value)
            steps.append(rf"Against the {side} side (inside "
                         rf"{_inside_words(side, value)}): " + " ".join(lines)
                         + rf" Result: {_polygon_words(polygon)}.")
        n = len(polygon)
        terms = [polygon[i][0] * polygon[(i + 1) % n][1] - polygon[(i + 1) % n][0]
                 * polygon[i][1] for i in range(n)]
        area = abs(sum(terms)) / 2
        steps.append(rf"The clipped polygon has {n} vertices. Shoelace: the terms "
                     r"$x_i y_{i+1} - x_{i+1} y_i$ are "
                     + ", ".join(f"${latex_fraction(t)}$" for t in terms)
                     + rf"; their sum is ${latex_fraction(sum(terms))}$, so "
                     rf"$A = {latex_fraction(area)} \approx {_num(area, 4)}$.")
        return Worked(steps, [n, area])

    def statement(self):
        return (
            rf"The triangle ${_vec(self.triangle[0])}$, ${_vec(self.triangle[1])}$, "
            rf"${_vec(self.triangle[2])}$ is clipped to the rectangle "
            rf"{_box_words(self.box_min, self.box_max)} with Sutherland-Hodgman (against the "
            r"left, right, bottom and top sides in turn). How many vertices does the clipped "
            r"polygon have, and what is its area? (Draw it.)" "\n\n"
            r"**Answer:** a list of 2 numbers `[number_of_vertices, area]`. " + DECIMALS
            + "\n\n" + data_note("triangle", "box_min", "box_max"))
