"""Chapter 15 exercises: what a bounding volume hierarchy saves.

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.
"""
import math

import numpy as np

from ..core import Mistake, Worked, data_note, pick
from . import _Parts, _num

__all__ = [
    "BVHSavings",
]


class BVHSavings(_Parts):
    r"""What a bounding volume hierarchy saves for one ray.

    A balanced BVH over :math:`P = k\, 2^m` triangles with :math:`k` per leaf has depth
    :math:`m`; a ray that goes down a single path tests the two child boxes at each of the
    :math:`m` inner levels (:math:`2m` box tests) and the :math:`k` triangles of one leaf,
    instead of :math:`P` triangles by brute force. The depth and the two counts are whole
    numbers (compared exactly); the factor is a ratio, right to 3 significant digits.

    Attributes: ``triangles`` (P), ``leaf_size`` (k).

    Examples
    --------
    >>> ex = BVHSavings(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> depth, boxes, tris, factor = ex.expected
    >>> ex.check([np.log2(ex.triangles), boxes, tris, factor]).diagnosis
    'leaf size ignored'
    >>> ex.check([depth + 1, boxes, tris, factor]).diagnosis
    'off by one'
    """

    title = "What a BVH saves"
    form_hint = r"`[depth, box tests, triangle tests, factor]`."
    advice = (r"Depth: halve $P$ until $k$ triangles are left, $m = \log_2(P/k)$. Box tests: 2 "
              r"per inner level. Factor: $P$ divided by (box tests + triangle tests).")

    def draw(self, rng):
        self.leaf_size = int(pick(rng, (2, 4, 8, 16)))
        m = int(rng.integers(8, 21))
        self.triangles = self.leaf_size * 2 ** m
        boxes, tris = 2 * m, self.leaf_size
        self.expected = np.array([m, boxes, tris, self.triangles / (boxes + tris)])

    def parts(self):
        m, boxes, tris = (int(x) for x in self.expected[:3])
        factor = float(self.expected[3])
        p, k = self.triangles, self.leaf_size
        return [
            ("the depth", m, [Mistake(math.log2(p), r"The hierarchy stops splitting when a "
                                      r"node holds $k$ triangles: $m = \log_2(P/k)$, not "
                                      r"$\log_2 P$.", "leaf size ignored")]),
            ("the box tests", boxes, [Mistake(m, r"At every inner node the ray is tested "
                                              r"against **both** children's boxes: 2 per "
                                              r"level.", "one box per level")]),
            ("the triangle tests", tris, [Mistake(p, r"That is brute force. In the "
                                                  r"BVH only the leaf's triangles are tested.",
                                                  "brute force")]),
            ("the factor", factor, [Mistake(p / tris, r"Box tests cost work too: divide $P$ "
                                            r"by box tests *plus* triangle tests.",
                                            "boxes free")]),
        ]

    def statement(self):
        return (
            r"A mesh of $P = " + f"{self.triangles:,}".replace(",", "{,}") + r"$ triangles gets"
            r" a balanced bounding volume "
            rf"hierarchy: every inner node splits its triangles in two equal halves, and a "
            rf"leaf holds $k = {self.leaf_size}$ triangles. A ray goes down a single path from "
            r"the root to one leaf: at every inner node it is tested against the boxes of "
            r"both children, and at the leaf against its triangles. Give (1) the depth of the "
            r"hierarchy (levels below the root), (2) the number of box tests, (3) the number of "
            r"triangle tests, and (4) how many times fewer tests (boxes and triangles together) "
            r"this is than the $P$ triangle tests of brute force." "\n\n"
            r"**Answer:** a list of 4 numbers `[depth, box tests, triangle tests, factor]`: "
            r"three whole numbers and the factor (at least 3 significant digits)." "\n\n"
            + data_note("triangles", "leaf_size"))

    def _depth(self):
        """The number of halvings from P triangles down to a leaf of k."""
        depth, count = 0, self.triangles
        while count > self.leaf_size:
            count //= 2
            depth += 1
        return depth

    def hints(self):
        p, k = self.triangles, self.leaf_size
        m = self._depth()
        return [
            r"Every level of the hierarchy halves the number of triangles per node, down to "
            r"$k$ in a leaf: the depth $m$ solves $P / 2^m = k$.",
            rf"$P / k = {p // k:,}".replace(",", "{,}") + rf" = 2^{{{m}}}$, so the depth is "
            rf"$m = {m}$; the ray goes through {m} inner nodes, testing 2 boxes at each.",
            rf"That is $2 \cdot {m} = {2 * m}$ box tests and {k} triangle tests, "
            rf"{2 * m + k} tests in all; the factor is $P$ divided by that.",
        ]

    def worked(self):
        p, k = self.triangles, self.leaf_size
        m = self._depth()
        boxes, tris = 2 * m, k
        factor = p / (boxes + tris)
        big = f"{p:,}".replace(",", "{,}")
        return Worked([
            rf"Depth: each level halves the triangles per node until $k = {k}$ are left: "
            rf"$P / k = {big} / {k} = " + f"{p // k:,}".replace(",", "{,}")
            + rf" = 2^{{{m}}}$, so $m = \log_2(P/k) = {m}$.",
            rf"Box tests: 2 children's boxes at each of the {m} inner levels, $2 \cdot {m} = "
            rf"{boxes}$. Triangle tests: the {tris} triangles of the one leaf reached.",
            rf"Factor: brute force tests all $P = {big}$ triangles; the BVH does "
            rf"${boxes} + {tris} = {boxes + tris}$ tests, so "
            rf"$\frac{{{big}}}{{{boxes + tris}}} = {_num(factor, 2)}$ times fewer.",
        ], [m, boxes, tris, factor])
