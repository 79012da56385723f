"""Chapter 6 exercises: vertex clustering, the vertex decimation criterion, Hausdorff distance.

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

import numpy as np

from ... import format as fmt
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick

__all__ = ["ClusterSurvivors", "DecimationCriterion", "HausdorffByHand"]

_num = fmt.number
_ONE = "**Answer:** one number. " + DECIMALS


def _n4(x):
    return fmt.number(x, 4)


def _pt(p):
    return "(" + ", ".join(_num(float(c)) for c in p) + ")"


class ClusterSurvivors(DrawnExercise):
    r"""Vertex clustering of a small 2D mesh by hand: how many triangles survive.

    The grid has cells of size ``h`` from the origin: vertex :math:`(x, y)` lies in cell
    :math:`(\lfloor x/h \rfloor, \lfloor y/h \rfloor)`. A triangle with two corners in one cell
    degenerates and is dropped; triangles that become the same triangle are kept once.

    Attributes: ``points`` (k x 2), ``triangles`` (m x 3 vertex indices), ``h``.

    Examples
    --------
    >>> ex = ClusterSurvivors(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Which triangles survive vertex clustering"
    answer_form = "number"
    what = "the number of triangles"
    advice = (r"Find each vertex's cell $(\lfloor x/h \rfloor, \lfloor y/h \rfloor)$, rewrite "
              r"each triangle with its corners' cells, drop those with a repeated cell, and "
              r"count the distinct cell triples.")

    def draw(self, rng):
        self.h = float(pick(rng, (1.0, 2.0)))
        k = int(rng.integers(7, 10))
        cells = rng.integers(0, 3, size=(k, 2))
        offs = rng.integers(1, 4, size=(k, 2)) / 4
        self.points = (cells + offs) * self.h
        m = int(rng.integers(6, 9))
        tris = set()
        while len(tris) < m:
            t = tuple(sorted(rng.choice(k, size=3, replace=False).tolist()))
            tris.add(t)
        self.triangles = np.array(sorted(tris))
        self._solve()

    def _solve(self):
        self.cells = np.floor(self.points / self.h).astype(int)
        key = self.cells[:, 0] * 10 + self.cells[:, 1]
        g = key[self.triangles]
        self._degenerate = (g[:, 0] == g[:, 1]) | (g[:, 1] == g[:, 2]) | (g[:, 0] == g[:, 2])
        self._groups = [tuple(sorted(r)) for r in g.tolist()]
        good = {t for t, d in zip(self._groups, self._degenerate) if not d}
        self.expected = len(good)

    def acceptable(self):
        return len(np.unique(self.points, axis=0)) == len(self.points) and \
            1 <= self.expected < len(self.triangles) - 1 and self._degenerate.any() and \
            len({t for t, d in zip(self._groups, self._degenerate) if not d}) < \
            int((~self._degenerate).sum())

    def mistakes(self):
        m = len(self.triangles)
        return [
            Mistake(int((~self._degenerate).sum()), r"Two triangles that end on the same three "
                    r"cells become the same triangle: keep it once (duplicates removed).",
                    "duplicates kept"),
            Mistake(len(set(self._groups)), r"A triangle with two corners in one cell "
                    r"collapses into an edge or a point: it is dropped, not kept.",
                    "degenerate kept"),
            Mistake(m, r"Clustering removes triangles: those with two corners in one cell, and "
                    r"the repeats.", "nothing removed"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {i} | {_pt(p)} |" for i, p in enumerate(self.points))
        tris = ", ".join("(" + ", ".join(map(str, t)) + ")" for t in self.triangles.tolist())
        return (rf"A grid of square cells of size $h = {_num(self.h)}$ starts at the origin. "
                r"Vertex clustering merges the vertices of each cell into one." "\n\n"
                "| vertex | position |\n|---|---|\n" + rows + "\n\n"
                rf"The triangles are {tris}. How many triangles does the clustered mesh have?"
                "\n\n**Answer:** a whole number.\n\n" + data_note("points", "triangles", "h"))

    def hints(self):
        return [r"Cell of a vertex: $(\lfloor x/h \rfloor, \lfloor y/h \rfloor)$.",
                r"Rewrite every triangle with its corners' cells; a cell repeated inside one "
                r"triangle makes it degenerate.",
                r"Among the others, count each set of three cells once."]

    def worked(self):
        cells = ", ".join(f"{i}: ({c[0]}, {c[1]})" for i, c in enumerate(self.cells.tolist()))
        lines = []
        for t, grp, d in zip(self.triangles.tolist(), self._groups, self._degenerate):
            cs = [tuple(self.cells[i].tolist()) for i in t]
            lines.append(f"({', '.join(map(str, t))}) → {', '.join(map(str, cs))}"
                         + (" degenerate" if d else ""))
        return Worked([f"Cells: {cells}.", "Triangles: " + "; ".join(lines) + ".",
                       f"Distinct non-degenerate triangles: {self.expected}."], self.expected)


class DecimationCriterion(DrawnExercise):
    r"""The vertex decimation criterion: distance to the area-weighted average plane.

    The star of vertex :math:`v` has triangles :math:`(v, a_i, a_{i+1})` of areas :math:`A_i`
    and centroids :math:`c_i`; the average plane passes through
    :math:`\bar x = \sum A_i c_i / \sum A_i` with the unit area-weighted normal :math:`n`
    (given, rounded); the criterion is :math:`|n \cdot (v - \bar x)|`.

    Attributes: ``v``, ``ring`` (the neighbours in order), ``areas`` and ``normal`` (rounded,
    as given).

    Examples
    --------
    >>> ex = DecimationCriterion(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The decimation criterion of a vertex"
    answer_form = "number"
    what = "the distance"
    advice = (r"Centroids $c_i = (v + a_i + a_{i+1})/3$, their area-weighted mean $\bar x$, "
              r"then $|n \cdot (v - \bar x)|$.")

    def draw(self, rng):
        # five neighbours (with four, Newell's normal is perpendicular to both diagonals of the
        # quadrilateral and the weighting would never matter)
        k = 5
        dirs = np.array([[2, 0], [1, 2], [-1, 2], [-2, 0], [-1, -2], [1, -2]], dtype=float)
        dirs = np.delete(dirs, int(rng.integers(6)), axis=0)
        r = rng.choice([0.5, 1.0, 2.0], size=k)
        z = rng.integers(-2, 3, size=k).astype(float)
        self.ring = np.column_stack([dirs * r[:, None], z])
        self.v = np.array([float(pick(rng, (-0.5, 0.0, 0.5))), float(pick(rng, (-0.5, 0.5))),
                           float(pick(rng, (1.0, 1.5, 2.0, -1.0)))])
        nxt = np.roll(self.ring, -1, axis=0)
        cross = np.cross(self.ring - self.v, nxt - self.v)
        self.areas = np.round(0.5 * np.linalg.norm(cross, axis=1), 2)
        N = cross.sum(axis=0)
        self.normal = np.round(N / np.linalg.norm(N), 3)
        self._c = (self.v + self.ring + nxt) / 3
        self._x = (self.areas[:, None] * self._c).sum(axis=0) / self.areas.sum()
        self.expected = float(abs(self.normal @ (self.v - self._x)))

    def acceptable(self):
        unweighted = abs(self.normal @ (self.v - self._c.mean(axis=0)))
        return self.expected > 0.05 and abs(self.expected - unweighted) > 0.05

    def mistakes(self):
        n = self.normal
        return [
            Mistake(float(abs(n @ (self.v - self._c.mean(axis=0)))), r"The centroids were "
                    r"averaged without weights. Each triangle counts with its **area**: a "
                    r"large triangle moves the average plane more than a sliver.", "unweighted"),
            Mistake(float(np.linalg.norm(self.ring - self.v, axis=1).min()), r"That is the "
                    r"distance to the nearest neighbour. The criterion measures how far $v$ is "
                    r"from the surface that replaces it: its distance to the average plane.",
                    "distance to a neighbour"),
            Mistake(float(abs(n @ (self.v - self.ring.mean(axis=0)))), r"The plane goes "
                    r"through the area-weighted mean of the triangles' **centroids** (which "
                    r"include $v$ itself), not through the mean of the neighbours.",
                    "mean of neighbours"),
        ]

    def statement(self):
        rows = "\n".join(rf"| $a_{i}$ | {_pt(a)} | $A_{i} = {_num(A)}$ |"
                         for i, (a, A) in enumerate(zip(self.ring, self.areas)))
        return (rf"Vertex $v = {_pt(self.v)}$ has the neighbours $a_0 \ldots a_4$ in order; "
                r"its star is the triangles $(v, a_i, a_{i+1})$ (indices mod 5), with areas "
                r"$A_i$ (rounded, use these)." "\n\n| neighbour | position | area of "
                r"$(v, a_i, a_{i+1})$ |" "\n|---|---|---|\n" + rows + "\n\n"
                rf"The unit area-weighted normal of the star is $n = {_pt(self.normal)}$ "
                r"(rounded, use it). Give the vertex decimation criterion of $v$: its distance "
                r"to the average plane." "\n\n" + _ONE + "\n\n"
                + data_note("v", "ring", "areas", "normal"))

    def hints(self):
        return [r"Centroid of triangle $i$: $c_i = (v + a_i + a_{i+1})/3$.",
                r"$\bar x = \sum A_i c_i / \sum A_i$ (a point: three coordinates).",
                r"The distance to the plane through $\bar x$ with unit normal $n$: "
                r"$|n \cdot (v - \bar x)|$."]

    def worked(self):
        cs = ", ".join(_pt(np.round(c, 4)) for c in self._c)
        x = (self.areas[:, None] * self._c).sum(axis=0) / self.areas.sum()
        d = float(abs(self.normal @ (self.v - x)))
        return Worked([f"Centroids: {cs}.",
                       rf"$\bar x = \sum A_i c_i / {_num(float(self.areas.sum()))} = "
                       rf"{_pt(np.round(x, 4))}$.",
                       rf"$v - \bar x = {_pt(np.round(self.v - x, 4))}$; "
                       rf"$d = |n \cdot (v - \bar x)| = {_n4(d)}$."], d)


def _directed(A, B):
    d = np.linalg.norm(A[:, None] - B[None], axis=2)
    return float(d.min(axis=1).max())


class HausdorffByHand(DrawnExercise):
    r"""The symmetric Hausdorff distance of two small point sets in the plane.

    :math:`d_H(A, B) = \max(\max_a \min_b |a - b|, \max_b \min_a |a - b|)`.

    Attributes: ``A``, ``B`` (points as rows).

    Examples
    --------
    >>> ex = HausdorffByHand(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The Hausdorff distance of two point sets"
    answer_form = "number"
    what = "the Hausdorff distance"
    advice = (r"For every point its nearest point of the other set; the largest of these "
              r"distances, over both sets.")

    def draw(self, rng):
        self.A = rng.integers(0, 6, size=(int(rng.integers(3, 5)), 2)).astype(float)
        self.B = rng.integers(0, 6, size=(int(rng.integers(3, 5)), 2)).astype(float)
        self._ab, self._ba = _directed(self.A, self.B), _directed(self.B, self.A)
        self.expected = max(self._ab, self._ba)

    def acceptable(self):
        d = np.linalg.norm(self.A[:, None] - self.B[None], axis=2)
        return (len(np.unique(self.A, axis=0)) == len(self.A) and
                len(np.unique(self.B, axis=0)) == len(self.B) and d.min() > 0 and
                abs(self._ab - self._ba) > 0.1)

    def mistakes(self):
        d = np.linalg.norm(self.A[:, None] - self.B[None], axis=2)
        small = min(self._ab, self._ba)
        return [
            Mistake(small, r"That is only one of the two one-sided distances (the smaller). "
                    r"The Hausdorff distance is the larger of $d(A \to B)$ and "
                    r"$d(B \to A)$: a point of either set far from the other counts.",
                    "one-sided only"),
            Mistake(float(d.min()), r"That is the smallest distance between the sets. Each "
                    r"point's distance to the other set is a minimum, but the Hausdorff "
                    r"distance is the **maximum** of these.", "min instead of max"),
            Mistake(float(d.max()), r"That is the largest distance between any two points. "
                    r"First take each point's **nearest** point of the other set.",
                    "max of all pairs"),
        ]

    def statement(self):
        a = ", ".join(_pt(p) for p in self.A)
        b = ", ".join(_pt(p) for p in self.B)
        return (rf"$A = \{{{a}\}}$ and $B = \{{{b}\}}$. Give the (symmetric) Hausdorff "
                r"distance $d_H(A, B)$." "\n\n" + _ONE + "\n\n" + data_note("A", "B"))

    def hints(self):
        return [r"$d(A \to B)$: for each $a$ the distance to its nearest $b$; take the largest.",
                r"$d(B \to A)$ the same way, from $B$.",
                r"$d_H$ is the larger of the two."]

    def worked(self):
        steps = []
        for name, P, Q in (("A", self.A, self.B), ("B", self.B, self.A)):
            d = np.linalg.norm(P[:, None] - Q[None], axis=2).min(axis=1)
            parts = ", ".join(f"{_pt(p)}: {_n4(x)}" for p, x in zip(P, d))
            other = "B" if name == "A" else "A"
            steps.append(rf"Nearest distances from {name} to {other}: {parts}; "
                         rf"$d({name} \to {other}) = {_n4(float(d.max()))}$.")
        ab = float(np.linalg.norm(self.A[:, None] - self.B[None], axis=2).min(axis=1).max())
        ba = float(np.linalg.norm(self.B[:, None] - self.A[None], axis=2).min(axis=1).max())
        value = max(ab, ba)
        steps.append(rf"$d_H = \max({_n4(ab)}, {_n4(ba)}) = {_n4(value)}$.")
        return Worked(steps, value)
