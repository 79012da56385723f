"""Tests of the BSP-tree exercises (course_lib/exercises/_ch05/bsp.py), on tests/exercise_harness.py.

The right answers and the anticipated mistakes are recomputed here with exact fractions and an
own recursion (not with course_lib.visibility.bsp2d): the front of a -> b is where
(b - a) x (p - a) > 0, partitions are taken alphabetically (parts keep their segment's place),
a cut segment c gives c1 (from its start) and c2.
"""
from fractions import Fraction
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from course_lib.exercises._ch05 import bsp as module

ch05 = SimpleNamespace(EXERCISES=[module.BSPBuildTree, module.BSPPaintOrder],
                       BSPBuildTree=module.BSPBuildTree, BSPPaintOrder=module.BSPPaintOrder)


def side(line, p):
    (ax, ay), (bx, by) = line
    return (bx - ax) * (p[1] - ay) - (by - ay) * (p[0] - ax)


def build(ex, unsplit=False, parts_last=False):
    """Nodes as dicts {name, line, front, back}; exact arithmetic."""
    segs = [[tuple(Fraction(int(v)) for v in p) for p in s] for s in ex.segments]
    items = [(ex.labels[k], k, segs[k][0], segs[k][1]) for k in range(len(segs))]

    def rec(items):
        if not items:
            return None
        name, src, _, _ = items[0]
        line = segs[src]
        front, back = [], []
        for it in items[1:]:
            s0, s1 = side(line, it[2]), side(line, it[3])
            if s0 >= 0 and s1 >= 0:
                front.append(it)
            elif s0 <= 0 and s1 <= 0:
                back.append(it)
            elif unsplit:
                (front if s0 + s1 > 0 else back).append(it)
            else:
                t = s0 / (s0 - s1)
                x = tuple(p + t * (q - p) for p, q in zip(it[2], it[3]))
                sep = "" if it[0] == ex.labels[it[1]] else "."
                first, second = (it[0] + sep + "1", it[1], it[2], x), (it[0] + sep + "2", it[1], x,
                                                                       it[3])
                (front if s0 > 0 else back).append(first)
                (back if s0 > 0 else front).append(second)
        def key(it):
            return ((it[0] != ex.labels[it[1]]) if parts_last else False, it[1], it[0])
        return {"name": name, "line": line, "front": rec(sorted(front, key=key)),
                "back": rec(sorted(back, key=key))}

    return rec(items)


def children(node, out=None):
    out = {} if out is None else out
    if node:
        out[node["name"]] = tuple(c["name"] if c else None for c in (node["front"], node["back"]))
        children(node["front"], out)
        children(node["back"], out)
    return out


def build_tree(ex):
    right = children(build(ex))
    return right, {
        "front and back swapped": {k: (b, f) for k, (f, b) in right.items()},
        "not split": children(build(ex, unsplit=True)),
        "parts put last": children(build(ex, parts_last=True)),
    }


def paint(node, eye, mode="right", fixed=None):
    if node is None:
        return []
    front = side(node["line"], eye) > 0 if fixed is None else fixed
    if mode == "root" and fixed is None:
        fixed = front
    far, near = (node["back"], node["front"]) if front else (node["front"], node["back"])
    a, c = paint(far, eye, mode, fixed), paint(near, eye, mode, fixed)
    return [node["name"]] + a + c if mode == "node first" else a + [node["name"]] + c


def paint_order(ex):
    root = build(ex)
    eye = [Fraction(int(v)) for v in ex.eye]
    right = paint(root, eye)
    return right, {"front to back": right[::-1], "side decided at the root only":
                   paint(root, eye, "root"), "node before its far subtree":
                   paint(root, eye, "node first")}


SPECS = {"BSPBuildTree": (build_tree, "tree"), "BSPPaintOrder": (paint_order, "order")}
GARBAGE = {"tree": ["a b", [1, 2], {"a": 3}, {"a": ("b",)}, {1: ("b", None)}, {"a": (1, None)}],
           "order": [[1, 2], 3.5, {"a": 1}, [["a"]], ["a", 2]]}
exercises = harness.variants(ch05)


def same(a, b, form=None):
    return a == b


globals().update(harness.common_tests(ch05, SPECS, GARBAGE, exercises, at_least=2,
                                      distinct=(20, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        spellings = [right]
        if form == "tree":
            spellings.append({k: list(v) for k, v in right.items()})
            spellings.append({k: tuple("-" if c is None else c for c in v)
                              for k, v in right.items()})
        else:
            spellings += [tuple(right), " ".join(right), ", ".join(right)]
        harness.assert_accepted(ex, spellings)


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(40)):
        worked = ex.worked()
        assert worked.answer == solve(ex)[0] and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


def test_every_variant_cuts_a_segment_at_nice_numbers():
    for ex in exercises("BSPBuildTree"):
        assert any(k[-1].isdigit() for k in solve_keys(ex))
        for seg in ex.segments:
            assert seg.min() >= 0 and seg.max() <= 8


def solve_keys(ex):
    return build_tree(ex)[0].keys()


def test_other_wrong_answers_are_named():
    ex = module.BSPBuildTree(seed=3)
    right, _ = build_tree(ex)
    fewer = dict(list(right.items())[:-1])
    assert ex.check(fewer).diagnosis == "wrong nodes"
    ex = module.BSPPaintOrder(seed=3)
    right, _ = paint_order(ex)
    assert ex.check(right[:-1]).diagnosis == "not the fragments"
