"""Tests of the spatial-subdivision exercises (course_lib/exercises/_ch15/spatial.py), on
tests/exercise_harness.py.

The right answers and the anticipated mistakes are recomputed here independently, with exact
fractions: the grid cells a ray crosses found by brute force (every cell tested with a slab test
typed below, kept when crossed over a positive length, sorted by entry t), with, where the ray
passes exactly through a grid corner, the cell beside the corner in x inserted (the x-first rule
at a tie); the quadtree leaves crossed, by the same brute force over the leaves. The slips are
rebuilt from their description (no t_delta: straight along the first axis stepped; start cell
rounded to nearest; one cell per column at the column's centre; the fixed tree order; reversed).
"""
import math
from fractions import Fraction as F
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from course_lib.exercises._ch15 import spatial as module

ch15 = SimpleNamespace(EXERCISES=[module.GridDDACells, module.QuadtreeRayCells],
                       GridDDACells=module.GridDDACells,
                       QuadtreeRayCells=module.QuadtreeRayCells)


def slab(o, d, x0, y0, size):
    t_in, t_out = F(0), F(10 ** 9)
    for k, lo in ((0, x0), (1, y0)):
        a, b = (F(lo) - o[k]) / d[k], (F(lo) + size - o[k]) / d[k]
        t_in, t_out = max(t_in, min(a, b)), min(t_out, max(a, b))
    return t_in, t_out


def crossed_cells(o, d, n):
    cells = []
    for i in range(n):
        for j in range(n):
            a, b = slab(o, d, i, j, 1)
            if a < b:
                cells.append((a, (i, j)))
    return [c for _, c in sorted(cells)]


def with_ties(cells, first):
    """Insert, between diagonal neighbours, the cell beside the corner along `first`."""
    out = [cells[0]]
    for a, b in zip(cells, cells[1:]):
        if a[0] != b[0] and a[1] != b[1]:
            out.append((b[0], a[1]) if first == "x" else (a[0], b[1]))
        out.append(b)
    return out


def grid(ex):
    o, d, n = ex.origin, ex.direction, ex.n
    cells = crossed_cells(o, d, n)
    right = with_ties(cells, "x")
    mistakes = {"wrong axis at a tie": with_ties(cells, "y")}
    # no t_delta: after the first step, the same axis forever
    t_x = (F(math.floor(o[0]) + (d[0] > 0)) - o[0]) / d[0]
    t_y = (F(math.floor(o[1]) + (d[1] > 0)) - o[1]) / d[1]
    axis = 0 if t_x <= t_y else 1
    c = [math.floor(o[0]), math.floor(o[1])]
    straight = [tuple(c)]
    while True:
        c[axis] += 1 if d[axis] > 0 else -1
        if not 0 <= c[axis] < n:
            break
        straight.append(tuple(c))
    mistakes["forgot t_delta"] = straight
    # start cell rounded to nearest: the DDA run from there
    c = [math.floor(x + F(1, 2)) for x in o]
    t = [(F(c[k] + (d[k] > 0)) - o[k]) / d[k] for k in range(2)]
    wrong = [tuple(c)]
    while True:
        a = 0 if t[0] <= t[1] else 1
        c[a] += 1 if d[a] > 0 else -1
        if not 0 <= c[a] < n or len(wrong) > 4 * n:
            break
        wrong.append(tuple(c))
        t[a] += 1 / abs(d[a])
    mistakes["wrong start cell"] = wrong
    # one cell per column (row) of the major axis, at its centre
    major = 0 if abs(d[0]) >= abs(d[1]) else 1
    under, i = [], math.floor(o[major])
    while 0 <= i < n:
        t = (i + F(1, 2) - o[major]) / d[major]
        j = math.floor(o[1 - major] + t * d[1 - major])
        if not 0 <= j < n:
            break
        under.append((i, j) if major == 0 else (j, i))
        i += 1 if d[major] > 0 else -1
    mistakes["cells under the line"] = under
    return right, {k: v for k, v in mistakes.items() if v != right}


def quadtree(ex):
    crossed = []
    for label, x0, y0, s in ex.leaves:
        a, b = slab(ex.origin, ex.direction, x0, y0, s)
        if a < b:
            crossed.append((a, label))
    right = [lab for _, lab in sorted(crossed)]
    missed = [lab for lab, *_ in ex.leaves if lab not in right]
    mistakes = {"tree order, not front to back": sorted(right), "back to front": right[::-1]}
    if missed:
        mistakes["cells the ray misses"] = right + [missed[0]]
    mistakes["cells missing"] = right[:-1]
    return right, {k: v for k, v in mistakes.items() if v != right}


SPECS = {"GridDDACells": (grid, "cells"), "QuadtreeRayCells": (quadtree, "labels")}
GARBAGE = {"cells": [[1, 2], 3.5, {"a": 1}, [[1.5, 2]], [[1, 2, 3]], [["a", 1]], [[True, 1]]],
           "labels": [[1, 2], 3.5, {"a": 1}, [["a"]], ["a", 2]]}
exercises = harness.variants(ch15)


def same(a, b, form=None):
    return [tuple(x) if isinstance(x, list) else x for x in a] == \
        [tuple(x) if isinstance(x, list) else x for x in b]


globals().update(harness.common_tests(ch15, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(20, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "cells":
            spellings = [right, [list(c) for c in right], [[float(i), float(j)] for i, j in right]]
        else:
            spellings = [right, tuple(right), " ".join(right), ", ".join(r.lower() for r in right)]
        harness.assert_accepted(ex, spellings)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(40)):
        worked = ex.worked()
        assert same(worked.answer, solve(ex)[0]) and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_some_grid_variants_have_a_tie_and_every_slip_appears():
    keys = set()
    for ex in exercises("GridDDACells", range(40)):
        keys |= set(grid(ex)[1])
    assert keys == {"wrong axis at a tie", "forgot t_delta", "wrong start cell",
                    "cells under the line"}


def test_subsets_and_supersets_are_named():
    ex = module.GridDDACells(seed=3)
    right = [list(c) for c in ex.expected]
    assert ex.check(right[:-1]).diagnosis == "cells missing"
    assert ex.check(right + [[right[-1][0], right[-1][1]]]).status == "wrong"
    assert ex.check(right[::-1]).diagnosis == "not front to back"
    assert ex.check(...).status == "unanswered"
