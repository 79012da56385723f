r"""Chapter 5 exercises: BSP trees by hand (a plan of segments seen from above).

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.

Conventions (those of :mod:`course_lib.visibility.bsp2d`): the front of a segment
:math:`a \to b` is its left side, :math:`s(p) = (b - a) \times (p - a) > 0`; the segments become
partitions in alphabetical order (in each subtree, the first one present); a cut segment ``c``
gives ``c1`` (the part containing its start :math:`a`) and ``c2``.
"""

import numpy as np

from ...visibility import bsp2d_back_to_front, build_bsp_2d
from ..core import UNANSWERED, Feedback, Mistake, Worked, data_note, pick
from . import _Listed, _unanswered

__all__ = [
    "BSPBuildTree",
    "BSPPaintOrder",
]


def _cross_side(a, b, p):
    """s(p) of the line a -> b, exact for whole numbers (plain Python)."""
    return (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])


def _draw_plan(rng, count):
    """`count` segments of whole coordinates in [0, 8]^2, no end point on another's line."""
    while True:
        segs = []
        for _ in range(count):
            a = [int(v) for v in rng.integers(0, 9, 2)]
            b = [int(v) for v in rng.integers(0, 9, 2)]
            if a != b and 2 <= abs(a[0] - b[0]) + abs(a[1] - b[1]) <= 7:
                segs.append((a, b))
        if len(segs) != count:
            continue
        clean = all(_cross_side(*segs[i], p) != 0 for i in range(count) for j in range(count)
                    if i != j for p in segs[j])
        if clean:
            return segs


def _nice_cuts(tree):
    """Whether every cut point has coordinates in halves (a crossing found by hand)."""
    ends = np.array([[f.start, f.end] for f in tree.fragments])
    return bool(np.allclose(ends * 2, np.round(ends * 2), atol=1e-9))


def _fmt_point(p):
    return "(" + ", ".join(f"{float(v):g}" for v in p) + ")"


def _hand_build(segs, labels, mode="right"):
    """The tree built step by step in plain Python, with the words of each step.

    `mode`: ``"right"``; ``"unsplit"`` (a straddling segment goes whole to the side of its
    midpoint); ``"parts last"`` (the parts of a cut segment go to the end of their list).
    Returns (children dict, steps).
    """
    items = [(labels[k], k, tuple(map(float, s[0])), tuple(map(float, s[1])))
             for k, s in enumerate(segs)]
    children, steps = {}, []

    def build(items):
        if not items:
            return None
        (name, src, _, _), rest = items[0], items[1:]
        a, b = (tuple(map(float, q)) for q in segs[src])     # the same line as the part
        front, back, words = [], [], []
        for it in rest:
            s0, s1 = _cross_side(a, b, it[2]), _cross_side(a, b, it[3])
            if s0 > 0 and s1 > 0 or (s0 >= 0 and s1 >= 0):
                front.append(it)
                words.append(f"{it[0]}: front ($s = {s0:g}, {s1:g}$)")
            elif s0 <= 0 and s1 <= 0:
                back.append(it)
                words.append(f"{it[0]}: back ($s = {s0:g}, {s1:g}$)")
            elif mode == "unsplit":
                (front if s0 + s1 > 0 else back).append(it)
                words.append(f"{it[0]}: straddles, kept whole")
            else:
                t = s0 / (s0 - s1)
                x = tuple(p + t * (q - p) for p, q in zip(it[2], it[3]))
                base = it[0] + ("." if it[0] != labels[it[1]] else "")
                p1, p2 = (base + "1", it[1], it[2], x), (base + "2", it[1], x, it[3])
                (front if s0 > 0 else back).append(p1)
                (back if s0 > 0 else front).append(p2)
                words.append(f"{it[0]}: **straddles** ($s = {s0:g}, {s1:g}$), cut at "
                             f"${_fmt_point(x)}$ into {p1[0]} "
                             f"({'front' if s0 > 0 else 'back'}) and {p2[0]} "
                             f"({'back' if s0 > 0 else 'front'})")
        if mode == "parts last":
            key = (lambda it: (it[0] != labels[it[1]], it[1], it[0]))
        else:
            key = (lambda it: (it[1], it[0]))
        front.sort(key=key)
        back.sort(key=key)
        steps.append(f"Node **{name}** (the line of {labels[src]}, through ${_fmt_point(a)}$ and "
                     f"${_fmt_point(b)}$): "
                     + ("; ".join(words) if words else "no segments left") + ".")
        f_child, b_child = build(front), build(back)
        children[name] = (f_child, b_child)
        return name

    build(items)
    return {k: children[k] for k in _preorder_of(children, items[0][0])}, steps


def _preorder_of(children, root):
    out, stack = [], [root]
    while stack:
        k = stack.pop()
        if k is None:
            continue
        out.append(k)
        stack += [children[k][1], children[k][0]]
    return out


def _table(segs, labels):
    return ("| segment | start $a$ | end $b$ |\n|---|---|---|\n" + "\n".join(
        f"| {n} | ${_fmt_point(a)}$ | ${_fmt_point(b)}$ |" for n, (a, b) in zip(labels, segs)))


_RULES = (r"The front of a segment $a \to b$ is its **left** side (walking from $a$ to $b$): "
          r"$s(p) = (b_x - a_x)(p_y - a_y) - (b_y - a_y)(p_x - a_x) > 0$. A segment cut by a "
          r"partition line is split into parts named by their order from its start: `c1` (the "
          r"part containing $a$) and `c2`.")


def _read_children(answer):
    """A dict label -> (front, back) with None for an empty child, or a Feedback."""
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    form = ('Give a dict with one entry per node: `{"a": ("b2", "b1"), "b2": (None, "c"), ...}`, '
            "each node's label mapped to its (front child, back child), None where there is none.")
    if not isinstance(answer, dict):
        return Feedback("invalid", form, "unreadable")
    out = {}
    for k, v in answer.items():
        if not isinstance(k, str) or not isinstance(v, (tuple, list)) or len(v) != 2:
            return Feedback("invalid", form, "unreadable")
        pair = []
        for c in v:
            if c is None or c in ("", "-"):
                pair.append(None)
            elif isinstance(c, str):
                pair.append(c.strip())
            else:
                return Feedback("invalid", form, "unreadable")
        out[k.strip()] = tuple(pair)
    return out


class BSPBuildTree(_Listed):
    r"""Build a 2D BSP tree by hand, splitting where a partition line cuts a segment.

    Four or five segments with whole coordinates; they become partitions in alphabetical order.
    The answer gives each node's front and back child, which fixes the tree, the cuts and the
    names of the parts.

    Attributes: ``segments`` (rows ``[a, b]``), ``labels``.

    Examples
    --------
    >>> ex = BSPBuildTree(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> swapped = {k: (b, f) for k, (f, b) in ex.expected.items()}
    >>> ex.check(swapped).diagnosis
    'front and back swapped'
    """

    title = "Build a BSP tree of segments"

    def draw(self, rng):
        count = int(pick(rng, (4, 5)))
        self.labels = list("abcde"[:count])
        self.segments = np.array(_draw_plan(rng, count), dtype=float)
        self.tree = build_bsp_2d(self.segments, labels=self.labels)
        self.n_splits = self.tree.n_splits
        self.expected = self.tree.children()

    def acceptable(self):
        return 1 <= self.n_splits <= 2 and _nice_cuts(self.tree)

    def mistakes(self):
        segs = self.segments.astype(int).tolist()
        return [
            Mistake({k: (b, f) for k, (f, b) in self.expected.items()}, r"Every front child is "
                    r"where the back child should be. The front of $a \to b$ is its **left** "
                    r"side: $s(p) = (b - a) \times (p - a) > 0$. Walk from $a$ to $b$: what is on "
                    r"your left hand is in front.", "front and back swapped", numeric=False),
            Mistake(_hand_build(segs, self.labels, "unsplit")[0], r"A segment whose end points "
                    r"lie on **opposite** sides of a partition line must be cut at the crossing "
                    r"into two parts (`c1` from its start, `c2`), each sent to its own side; you "
                    r"kept it whole.", "not split", numeric=False),
            Mistake(_hand_build(segs, self.labels, "parts last")[0], r"The parts of a cut segment "
                    r"keep their segment's place in the order: in a subtree, the partition is the "
                    r"segment (or part) that comes first **alphabetically**, not the ones that "
                    r"were not cut.", "parts put last", numeric=False),
        ]

    def separated(self, mistakes):
        values = [repr(sorted(m.value.items())) for m in mistakes]
        values.append(repr(sorted(self.expected.items())))
        return len(set(values)) == len(values)

    def _check(self, answer):
        value = _read_children(answer)
        if isinstance(value, Feedback):
            return value
        if value == self.expected:
            return Feedback("correct", "The tree is right: every node with its front and back "
                            "child.")
        for mistake in self._mistakes:
            if value == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        if set(value) != set(self.expected):
            return Feedback("wrong", "Your tree does not have the right nodes: it should have "
                            f"{len(self.expected)} (the segments plus one more per cut). Check "
                            "each segment's end points against each partition line.", "wrong nodes")
        bad = [k for k in self.expected if value[k] != self.expected[k]]
        return Feedback("wrong", f"The nodes are right but the children of {', '.join(bad)} are "
                        "not. At each node, sort the remaining segments (parts) by the sign of "
                        "s at their end points.", "children differ")

    def statement(self):
        n = len(self.labels)
        return (
            f"A plan seen from above holds {n} segments:\n\n" + _table(
                self.segments.astype(int).tolist(), self.labels) + "\n\n" + _RULES + " The "
            r"segments become partitions in **alphabetical order**: the root is `a`, and in each "
            r"subtree the partition is the first segment (or part) present." "\n\n"
            r"Build the BSP tree. **Answer:** a dict mapping each node's label to its (front "
            r"child, back child), None for an empty child, e.g. "
            r'`{"a": ("b2", "b1"), "b2": (None, "c"), "c": (None, None), ...}`.' "\n\n"
            + data_note("segments", "labels"))

    def hints(self):
        a, b = self.segments[0]
        return [
            r"Start at the root `a`: for every other segment compute $s$ at both end points "
            r"with respect to the line of `a`. Same signs: that side; opposite signs: cut it.",
            rf"For `a` from ${_fmt_point(a)}$ to ${_fmt_point(b)}$, "
            rf"$s(p) = {b[0] - a[0]:g}\,(p_y - {a[1]:g}) - {b[1] - a[1]:g}\,(p_x - {a[0]:g})$; "
            r"positive is front.",
            f"In this plan {self.n_splits} segment(s) must be cut. Then repeat in the front "
            "list and in the back list, each with its first segment as the partition.",
        ]

    def worked(self):
        children, steps = _hand_build(self.segments.astype(int).tolist(), self.labels)
        steps.append("The tree, each node with its (front, back) children: " + ", ".join(
            f"{k}: ({f}, {b})" for k, (f, b) in children.items()) + ".")
        return Worked(steps, children)


def _read_labels(answer, n):
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    form = f'Give the {n} fragment labels in drawing order, e.g. `["d", "b1", "a", "c", "b2"]`.'
    if isinstance(answer, str):
        answer = answer.replace(",", " ").split()
    if not isinstance(answer, (list, tuple)) or not all(isinstance(a, str) for a in answer):
        return Feedback("invalid", form, "unreadable")
    return [a.strip() for a in answer]


def _slip_order(node, eye, mode, root_side=None):
    """Back-to-front with a slip: ``"root only"`` (the root's side used everywhere),
    ``"node first"`` (node, far subtree, near subtree)."""
    if node is None:
        return []
    side = node.normal @ eye - node.offset >= 0 if root_side is None else root_side
    if mode == "root only" and root_side is None:
        root_side = side
    far, near = (node.back, node.front) if side else (node.front, node.back)
    here = [f.label for f in node.fragments]
    a = _slip_order(far, eye, mode, root_side)
    c = _slip_order(near, eye, mode, root_side)
    return here + a + c if mode == "node first" else a + here + c


class BSPPaintOrder(_Listed):
    r"""The painter's order from a 2D BSP tree for a given eye point.

    The tree (built from four or five segments, with one or two cuts) is given; the answer is
    the list of fragment labels from the farthest to the nearest.

    Attributes: ``segments``, ``labels``, ``eye``, ``tree`` (the :class:`BSPTree2D`).

    Examples
    --------
    >>> ex = BSPPaintOrder(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'front to back'
    """

    title = "Back-to-front order from a BSP tree"

    def draw(self, rng):
        count = int(pick(rng, (4, 5)))
        self.labels = list("abcde"[:count])
        segs = _draw_plan(rng, count)
        self.segments = np.array(segs, dtype=float)
        self.tree = build_bsp_2d(self.segments, labels=self.labels)
        while True:
            eye = [int(v) for v in rng.integers(0, 9, 2)]
            if all(_cross_side(a, b, eye) != 0 for a, b in segs):
                break
        self.eye = np.array(eye, dtype=float)
        self.expected = bsp2d_back_to_front(self.tree, self.eye).labels

    def acceptable(self):
        return 1 <= self.tree.n_splits <= 2 and self.tree.depth >= 3 and _nice_cuts(self.tree)

    def mistakes(self):
        return [
            Mistake(self.expected[::-1], r"That is front to back: the nearest fragment first. The "
                    r"painter paints the **far** side of each partition first, so that the near "
                    r"side is painted over it.", "front to back", numeric=False),
            Mistake(_slip_order(self.tree.root, self.eye, "root only"), r"You decided the eye's "
                    r"side at the root only. Every node has its own line: compute $s$ of the eye "
                    r"again at **each** node and paint that node's far subtree first.",
                    "side decided at the root only", numeric=False),
            Mistake(_slip_order(self.tree.root, self.eye, "node first"), r"You painted each node "
                    r"before its far subtree. The order at a node is: far subtree, the node's own "
                    r"segment, then the near subtree (the node may hide the far side, never the "
                    r"other way round).", "node before its far subtree", numeric=False),
        ]

    def separated(self, mistakes):
        values = [tuple(m.value) for m in mistakes] + [tuple(self.expected)]
        return len(set(values)) == len(values)

    def _check(self, answer):
        value = _read_labels(answer, len(self.expected))
        if isinstance(value, Feedback):
            return value
        if value == self.expected:
            return Feedback("correct", "The painting order is right.")
        for mistake in self._mistakes:
            if value == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        if sorted(value) != sorted(self.expected):
            return Feedback("wrong", "Every fragment of the tree is painted exactly once: list "
                            "the labels " + ", ".join(sorted(self.expected)) + ", each once.",
                            "not the fragments")
        return Feedback("wrong", "Not the back-to-front order. At each node compute s of the eye "
                        "for its line, paint the subtree on the other side, the node, then the "
                        "subtree on the eye's side.", "order differs")

    def statement(self):
        return (
            "A BSP tree was built from these segments (partitions in alphabetical order):\n\n"
            + _table(self.segments.astype(int).tolist(), self.labels) + "\n\n" + _RULES
            + "\n\nThe tree (front child listed before the back child):\n\n```\n"
            + self.tree.describe() + "\n```\n\n"
            rf"The eye is at ${_fmt_point(self.eye)}$. In which order does the painter's "
            r"algorithm draw the fragments (back to front)?" "\n\n"
            r"**Answer:** the list of fragment labels in drawing order, e.g. "
            r'`["d", "b1", "a", "c", "b2"]`.' "\n\n" + data_note("segments", "eye"))

    def hints(self):
        root = self.tree.root
        a, b = self.segments[root.fragments[0].source]
        s = _cross_side(a, b, self.eye)
        return [
            r"At a node: if the eye is in front of its line, paint back subtree, node, front "
            r"subtree; if behind, front subtree, node, back subtree.",
            rf"At the root {root.label}: $s(e) = {s:g}$, so the eye is "
            + ("in front" if s > 0 else "behind") + ".",
            "Repeat the test at every node of the subtrees: each has its own line.",
        ]

    def worked(self):
        steps, order = [], []

        def visit(node):
            if node is None:
                return
            a, b = self.segments[node.fragments[0].source]
            s = _cross_side(a, b, self.eye)
            far, near = (node.back, node.front) if s > 0 else (node.front, node.back)
            steps.append(f"Node {node.label} (the line of {self.labels[node.fragments[0].source]}): "
                         f"$s(e) = {s:g}$, the eye is "
                         + ("in front" if s > 0 else "behind") + ": paint its "
                         + ("back" if s > 0 else "front") + " subtree, then "
                         + node.label + ", then its " + ("front" if s > 0 else "back")
                         + " subtree.")
            visit(far)
            order.extend(f.label for f in node.fragments)
            visit(near)

        visit(self.tree.root)
        steps.append("Drawing order: " + ", ".join(order) + ".")
        return Worked(steps, order)
