r"""Chapter 15 exercises: spatial subdivision by hand (a 2D-DDA walk, a quadtree walk).

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.

Both exercises are the 2D versions of :mod:`course_lib.raytracing.spatial`: the grid of unit
cells walked by the DDA of Amanatides and Woo (at a tie, the ray passing exactly through a grid
corner, the x step is taken first, as in :class:`~course_lib.raytracing.UniformGrid`), and a
quadtree whose leaves a ray meets front to back (as :class:`~course_lib.raytracing.Octree`).
Exact arithmetic (fractions) throughout.
"""
import math
from fractions import Fraction as F

from ..core import UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note, \
    is_unanswered, pick

__all__ = [
    "GridDDACells",
    "QuadtreeRayCells",
]


def _fr(x):
    """A fraction as short text: 3/4, 2, -1/2."""
    x = F(x)
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def _sp_dda(o, d, n, start=None, tie="x", advance=True):
    """The 2D-DDA over an n x n grid of unit cells: the cells, and the steps as text.

    `start` forces the first cell (a slip), `tie` the axis stepped first at a tie, `advance`
    False forgets to add t_delta after a step (a slip)."""
    cell = [math.floor(o[0]), math.floor(o[1])] if start is None else list(start)
    step = [1 if c > 0 else -1 for c in d]
    t_delta = [F(1) / abs(c) for c in d]
    t_max = [(F(cell[k] + (step[k] > 0)) - o[k]) / d[k] for k in range(2)]
    cells = [tuple(cell)]
    lines = []
    while True:
        if t_max[0] < t_max[1] or (t_max[0] == t_max[1] and tie == "x"):
            a = 0
        else:
            a = 1
        lines.append((tuple(t_max), a))
        cell[a] += step[a]
        if not 0 <= cell[a] < n or len(cells) > 4 * n:
            break
        cells.append(tuple(cell))
        if advance:
            t_max[a] += t_delta[a]
    return cells, lines, step, t_delta


def _sp_under_line(o, d, n):
    """The slip 'cells under the line': one cell per column (per row if the ray is steeper),
    the one the line passes through at the column's centre."""
    major = 0 if abs(d[0]) >= abs(d[1]) else 1
    minor = 1 - major
    i = math.floor(o[major])
    out = []
    step = 1 if d[major] > 0 else -1
    while 0 <= i < n:
        t = (F(i) + F(1, 2) - o[major]) / d[major]
        j = math.floor(o[minor] + t * d[minor])
        if not 0 <= j < n:
            break
        out.append((i, j) if major == 0 else (j, i))
        i += step
    return out


def _read_cells(answer):
    """A list of cells [[i, j], ...] (whole numbers), or a Feedback."""
    form = "Give the cells in order as a list of [i, j] pairs, e.g. `[[0, 1], [1, 1], [1, 2]]`."
    if is_unanswered(answer) or (isinstance(answer, (list, tuple)) and any(
            a is Ellipsis for a in answer)):
        return Feedback("unanswered", UNANSWERED)
    if not isinstance(answer, (list, tuple)) or not answer:
        return Feedback("invalid", form, "unreadable")
    out = []
    for c in answer:
        if not isinstance(c, (list, tuple)) or len(c) != 2:
            return Feedback("invalid", form, "unreadable")
        pair = []
        for x in c:
            if isinstance(x, bool) or not isinstance(x, (int, float)) or x != int(x):
                return Feedback("invalid", form, "unreadable")
            pair.append(int(x))
        out.append(tuple(pair))
    return out


def _read_labels15(answer):
    form = 'Give the leaf labels in order, e.g. `["A", "C", "D"]` or `"A C D"`.'
    if is_unanswered(answer) or (isinstance(answer, (list, tuple)) and any(
            a is Ellipsis for a in answer)):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, str):
        answer = answer.replace(",", " ").split()
    if not isinstance(answer, (list, tuple)) or not answer or not all(
            isinstance(a, str) for a in answer):
        return Feedback("invalid", form, "unreadable")
    return [a.strip().upper() for a in answer]


def _judge_sequence(value, expected, mistakes, unit, advice):
    if value == expected:
        return Feedback("correct", f"Those are the {unit}s the ray visits, in order.")
    for m in mistakes:
        if value == m.value:
            return Feedback("wrong", m.explanation, m.key)
    if set(value) == set(expected):
        return Feedback("wrong", f"The right {unit}s, in the wrong order: list them as the ray "
                        "meets them, by increasing entry parameter t (front to back).",
                        "not front to back")
    if set(value) > set(expected):
        return Feedback("wrong", f"You listed {unit}s the ray never enters: a {unit} is visited "
                        "only if the ray crosses its box over a stretch of positive length.",
                        "cells the ray misses")
    if set(value) < set(expected):
        return Feedback("wrong", f"Some {unit}s the ray crosses are missing: every {unit} along "
                        "the ray up to where it leaves the grid must be visited (the nearest "
                        "hit could be in any of them).", "cells missing")
    return Feedback("wrong", advice, "sequence differs")


class GridDDACells(DrawnExercise):
    r"""The cells a ray visits in a small 2D grid, in order, by the DDA.

    The grid has :math:`n \times n` unit cells, cell :math:`(i, j)` covering
    :math:`[i, i+1] \times [j, j+1]`; the ray starts inside it. The answer is the list of cells
    the ray visits until it leaves the grid (at a tie, a grid corner, the x step first).

    Attributes: ``n``, ``origin``, ``direction`` (exact: quarters and small whole numbers).

    Examples
    --------
    >>> ex = GridDDACells(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'not front to back'
    """

    title = "The cells of a grid a ray visits (DDA)"
    answer_form = "custom"

    def draw(self, rng):
        self.n = int(pick(rng, (4, 5)))
        q = [F(int(v), 4) for v in rng.integers(1, 4 * self.n, 2)]
        self.origin = (q[0], q[1])
        dx, dy = (int(pick(rng, (1, 2, 3))) * int(pick(rng, (-1, 1))) for _ in range(2))
        self.direction = (F(dx), F(dy))
        self.expected, self._lines, self._step, self._t_delta = _sp_dda(
            self.origin, self.direction, self.n)

    def acceptable(self):
        o, cells = self.origin, self.expected
        on_wall = any(x.denominator == 1 for x in o)
        steps_x = len({c[0] for c in cells}) >= 2
        steps_y = len({c[1] for c in cells}) >= 2
        d, n = self.direction, self.n
        edge_tie = any(tm[0] == tm[1] and any(o[k] + tm[0] * d[k] in (0, n) for k in range(2))
                       for tm, _ in self._lines)     # no tie on the grid's border
        return (not on_wall and steps_x and steps_y and 4 <= len(cells) <= 9 and not edge_tie
                and len(_sp_under_line(o, self.direction, self.n)) >= 2
                and any(x - math.floor(x) >= F(1, 2) for x in o))

    def _start_rounded(self):
        return tuple(int(math.floor(x + F(1, 2))) for x in self.origin)

    def mistakes(self):
        o, d, n = self.origin, self.direction, self.n
        out = [
            Mistake(_sp_dda(o, d, n, tie="y")[0], r"At a tie the ray passes exactly through a "
                    r"grid corner, and the rule here steps **x first** (then y): the cell "
                    r"beside the corner in x comes before the diagonal one.",
                    "wrong axis at a tie", numeric=False),
            Mistake(_sp_dda(o, d, n, advance=False)[0], r"After a step along an axis, that "
                    r"axis's $t_{max}$ must grow by $t_\Delta = 1/|d|$ (the next wall is one "
                    r"cell further); without it the same axis stays the smallest and the walk "
                    r"runs straight along it.", "forgot t_delta", numeric=False),
            Mistake(_sp_dda(o, d, n, start=self._start_rounded())[0], r"The walk starts in "
                    r"the cell that **contains** the origin: $i = \lfloor x \rfloor$, "
                    r"$j = \lfloor y \rfloor$ (rounded down, not to the nearest whole number).",
                    "wrong start cell", numeric=False),
            Mistake(_sp_under_line(o, d, n), r"That is one cell per column, the cells "
                    r"'under the line' as a line-drawing algorithm picks them. A ray must visit "
                    r"**every** cell it crosses, also those it only clips at a corner, or it "
                    r"may miss the nearest hit.", "cells under the line", numeric=False),
        ]
        return out

    def keep(self, mistakes):
        return [m for m in mistakes if m.value != self.expected]

    def separated(self, mistakes):
        values = [tuple(m.value) for m in self.keep(mistakes)] + [tuple(self.expected)]
        return len(set(values)) == len(values) and len(self.keep(mistakes)) >= 3

    def _check(self, answer):
        value = _read_cells(answer)
        if isinstance(value, Feedback):
            return value
        return _judge_sequence(value, self.expected, self._mistakes, "cell",
                               "Not the DDA's walk. Start in the cell holding the origin, "
                               "compute t_max and t_delta per axis, and repeatedly step the axis "
                               "with the smaller t_max, adding its t_delta.")

    def statement(self):
        (ox, oy), (dx, dy) = self.origin, self.direction
        return (
            rf"A 2D grid of ${self.n} \times {self.n}$ unit cells covers "
            rf"$[0, {self.n}] \times [0, {self.n}]$; cell $(i, j)$ is "
            r"$[i, i+1] \times [j, j+1]$. A ray starts at "
            rf"$o = ({_fr(ox)}, {_fr(oy)})$ with direction $d = ({_fr(dx)}, {_fr(dy)})$. "
            r"Walk it through the grid with the DDA of Amanatides and Woo (per axis: the "
            r"parameter $t_{max}$ of the next wall, the step $t_\Delta$ between walls, the "
            r"index step $\pm 1$; at a tie step x first) and list the cells it visits, in "
            r"order, until it leaves the grid." "\n\n"
            r"**Answer:** a list of `[i, j]` pairs, e.g. `[[0, 1], [1, 1], [1, 2]]`." "\n\n"
            + data_note("n", "origin", "direction"))

    def hints(self):
        c0 = self.expected[0]
        tm = self._lines[0][0]
        return [
            r"Start in the cell holding the origin: $(\lfloor o_x \rfloor, \lfloor o_y "
            rf"\rfloor) = {c0}$.",
            rf"$t_\Delta = (1/|d_x|, 1/|d_y|) = ({_fr(self._t_delta[0])}, "
            rf"{_fr(self._t_delta[1])})$; the first walls are crossed at $t_{{max}} = "
            rf"({_fr(tm[0])}, {_fr(tm[1])})$.",
            r"Repeat: step the axis with the smaller $t_{max}$ (x at a tie), add its "
            r"$t_\Delta$; stop when the index leaves $0 \ldots n-1$.",
        ]

    def worked(self):
        c0 = self.expected[0]
        steps = [rf"Start cell $(\lfloor {_fr(self.origin[0])} \rfloor, \lfloor "
                 rf"{_fr(self.origin[1])} \rfloor) = {c0}$; steps $({self._step[0]:+d}, "
                 rf"{self._step[1]:+d})$, $t_\Delta = ({_fr(self._t_delta[0])}, "
                 rf"{_fr(self._t_delta[1])})$."]
        cells = self.expected
        for k, (tm, a) in enumerate(self._lines):
            axis = "xy"[a]
            where = (f"to cell {cells[k + 1]}" if k + 1 < len(cells)
                     else "out of the grid: stop")
            steps.append(rf"$t_{{max}} = ({_fr(tm[0])}, {_fr(tm[1])})$: the smaller is {axis}"
                         + (" (a tie: x first)" if tm[0] == tm[1] else "")
                         + f", step {axis} {where}.")
        steps.append("Cells in order: " + ", ".join(str(c) for c in cells) + ".")
        return Worked(steps, [list(c) for c in cells])


# ---------------------------------------------------------------------------------------------
# The quadtree walk
# ---------------------------------------------------------------------------------------------

def _sp_quadtree(rng):
    """A quadtree over [0, 8]^2: leaves (label, x0, y0, size) in depth-first order (children
    SW, SE, NW, NE) and the inner nodes (x0, y0, size, children)."""
    leaves, inner = [], []

    def node(x0, y0, size, depth):
        split = depth == 0 or (size > 1 and rng.random() < (0.55 if depth == 1 else 0.3))
        if not split:
            leaves.append((x0, y0, size))
            return ("leaf", len(leaves) - 1)
        h = size // 2
        kids = [node(x0 + h * (c % 2), y0 + h * (c // 2), h, depth + 1) for c in range(4)]
        inner.append((x0, y0, size, kids))
        return ("inner", len(inner) - 1)

    root = node(0, 0, 8, 0)
    labels = [chr(ord("A") + k) for k in range(len(leaves))]
    return [(labels[k],) + leaves[k] for k in range(len(leaves))], inner, root


def _sp_enter(o, d, x0, y0, size):
    """(t_in, t_out) of the ray (t >= 0) in the square, exact; None if not crossed."""
    t_in, t_out = F(0), None
    for k, lo in ((0, x0), (1, y0)):
        a, b = (F(lo) - o[k]) / d[k], (F(lo + size) - o[k]) / d[k]
        a, b = min(a, b), max(a, b)
        t_in = max(t_in, a)
        t_out = b if t_out is None else min(t_out, b)
    return (t_in, t_out) if t_in < t_out else None


class QuadtreeRayCells(DrawnExercise):
    r"""The leaves of a quadtree a ray visits, in order (front to back).

    The quadtree covers :math:`[0, 8]^2`; its leaves are given as labelled squares. The answer
    is the list of leaf labels in the order the ray enters them (by increasing entry parameter
    :math:`t`), the ray starting at its origin (:math:`t \ge 0`).

    Attributes: ``leaves`` (label, x0, y0, size), ``origin``, ``direction``.

    Examples
    --------
    >>> ex = QuadtreeRayCells(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(sorted(ex.expected)).diagnosis
    'tree order, not front to back'
    """

    title = "The quadtree leaves a ray visits"
    answer_form = "custom"

    def draw(self, rng):
        self.leaves, self._inner, self._root = _sp_quadtree(rng)
        if rng.random() < 0.5:                        # from outside, left or below
            side = int(rng.integers(0, 2))
            t = F(int(rng.integers(1, 16)), 2)
            self.origin = (F(-1), t) if side == 0 else (t, F(-1))
        else:
            self.origin = tuple(F(int(v), 2) + F(1, 4) for v in rng.integers(0, 16, 2))
        dx = int(pick(rng, (1, 2, 3))) * int(pick(rng, (-1, 1)))
        dy = int(pick(rng, (1, 2, 3))) * int(pick(rng, (-1, 1)))
        if self.origin[0] == -1:
            dx = abs(dx)
        if self.origin[1] == -1:
            dy = abs(dy)
        self.direction = (F(dx), F(dy))
        crossed = []
        self._corner = False
        for label, x0, y0, s in self.leaves:
            e = _sp_enter(self.origin, self.direction, x0, y0, s)
            if e is not None:
                crossed.append((e[0], label))
            elif self._touches(x0, y0, s):
                self._corner = True
        self._times = sorted(crossed)
        self.expected = [label for _, label in self._times]

    def _touches(self, x0, y0, s):
        """Whether the ray touches the square's closure only at a point (a corner)."""
        o, d = self.origin, self.direction
        for cx in (x0, x0 + s):
            for cy in (y0, y0 + s):
                t = (F(cx) - o[0]) / d[0]
                if t >= 0 and o[1] + t * d[1] == cy:
                    return True
        return False

    def acceptable(self):
        times = [t for t, _ in self._times]
        return (not self._corner and 4 <= len(self.expected) <= 8 and len(set(times)) == len(
            times) and len(self.leaves) <= 16)

    def mistakes(self):
        ordered = sorted(self.expected, key=lambda s: s)
        return [
            Mistake(ordered, r"That is the tree's fixed (depth-first) order of the leaves, not "
                    r"the ray's: at each node visit the children the ray enters **by "
                    r"increasing entry parameter** $t$, which depends on the ray's direction.",
                    "tree order, not front to back", numeric=False),
            Mistake(self.expected[::-1], r"That is back to front. The walk goes from the ray's "
                    r"origin outwards, so that it can stop at the first leaf holding a hit.",
                    "back to front", numeric=False),
        ]

    def keep(self, mistakes):
        return [m for m in mistakes if m.value != self.expected]

    def separated(self, mistakes):
        values = [tuple(m.value) for m in mistakes] + [tuple(self.expected)]
        return len(set(values)) == len(values)

    def _check(self, answer):
        value = _read_labels15(answer)
        if isinstance(value, Feedback):
            return value
        return _judge_sequence(value, self.expected, self._mistakes, "leaf",
                               "Not the leaves along the ray. For each leaf the ray enters, "
                               "compute its entry t with the slab test and sort by it.")

    def statement(self):
        rows = "\n".join(f"| {lab} | [{x0}, {x0 + s}] | [{y0}, {y0 + s}] |"
                         for lab, x0, y0, s in self.leaves)
        (ox, oy), (dx, dy) = self.origin, self.direction
        return (
            r"A quadtree over the square $[0, 8] \times [0, 8]$ has these leaves:" "\n\n"
            "| leaf | x range | y range |\n|---|---|---|\n" + rows + "\n\n"
            rf"A ray starts at $o = ({_fr(ox)}, {_fr(oy)})$ with direction "
            rf"$d = ({_fr(dx)}, {_fr(dy)})$ ($t \ge 0$). Which leaves does a front-to-back "
            r"traversal visit, in order (without stopping at a hit)?" "\n\n"
            r'**Answer:** the list of leaf labels in order, e.g. `["A", "C", "D"]`.' "\n\n"
            + data_note("leaves", "origin", "direction"))

    def hints(self):
        first = self._times[0]
        return [
            r"A leaf is visited when the ray crosses its square: with the slab test, "
            r"$t_{in} = \max(t_x^{near}, t_y^{near}, 0) < t_{out} = \min(t_x^{far}, t_y^{far})$.",
            rf"The first leaf is {first[1]}, entered at $t = {_fr(first[0])}$.",
            r"Front to back means by increasing $t_{in}$ (at every node, the children in the "
            r"order the ray enters them).",
        ]

    def worked(self):
        o, d = self.origin, self.direction
        steps = []
        x0, y0, size, kids = self._inner[self._root[1]]

        def visit(x0, y0, size, kids):
            entered = []
            for kind, k in kids:
                box = (self.leaves[k][1:] if kind == "leaf" else self._inner[k][:3])
                e = _sp_enter(o, d, *box)
                if e is not None:
                    name = self.leaves[k][0] if kind == "leaf" else (
                        f"node [{box[0]}, {box[0] + box[2]}]x[{box[1]}, {box[1] + box[2]}]")
                    entered.append((e[0], e[1], name, kind, k))
            entered.sort(key=lambda x: x[0])
            steps.append(f"Node [{x0}, {x0 + size}]x[{y0}, {y0 + size}]: the ray enters "
                         + ", ".join(rf"{n} ($t \in [{_fr(a)}, {_fr(b)}]$)"
                                     for a, b, n, _, _ in entered) + ", in this order.")
            for _, _, _, kind, k in entered:
                if kind == "inner":
                    visit(*self._inner[k])

        visit(x0, y0, size, kids)
        steps.append("Leaves in order: " + ", ".join(self.expected) + ".")
        return Worked(steps, list(self.expected))
