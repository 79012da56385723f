"""Chapter 7 exercises: Surfaces.

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.
"""

import numpy as np

from ... import curves, surfaces
from ..core import Mistake, Worked, data_note, pick
from . import _POINT_3, _T_VALUES, _Chapter7, _frac, _num, _vec

__all__ = [
    "BezierSurfacePoint",
]


class BezierSurfacePoint(_Chapter7):
    r"""A point :math:`S(u, v) = \sum_i \sum_j B_i^m(u)\, B_j^n(v)\, P_{ij}` of a Bézier patch.

    Attributes: ``grid`` (shape (m + 1, n + 1, 3), ``grid[i, j]`` is :math:`P_{ij}`), ``m``,
    ``n`` (the degrees in u and v), ``u``, ``v``.

    Examples
    --------
    >>> ex = BezierSurfacePoint(seed=15)
    >>> ex.check(ex.expected).status
    'correct'
    >>> bu = curves.bernstein(ex.m, None, ex.u)
    >>> ex.check(bu @ ex.grid[:, 0]).diagnosis               # the boundary curve v = 0 only
    'one direction only'
    """

    title = "A point of a Bézier patch"
    answer_form = "point"
    what = "the surface point"
    advice = (r"Blend in both directions: $S(u, v) = \sum_i \sum_j B_i^m(u)\, B_j^n(v)\, "
            r"P_{ij}$, e.g. first the curve points $\sum_j B_j^n(v) P_{ij}$ of each row, then "
            r"blend those with $B_i^m(u)$.")

    def draw(self, rng):
        self.m, self.n = pick(rng, ((1, 1), (1, 2), (2, 1), (2, 2)))
        m, n = self.m, self.n
        x, y = np.meshgrid(np.arange(m + 1) * (2 // m), np.arange(n + 1) * (2 // n),
                           indexing="ij")
        z = rng.integers(-2, 4, size=(m + 1, n + 1))
        self.grid = np.stack([x, y, z], axis=-1).astype(float)
        self.u, self.v = (float(pick(rng, _T_VALUES)) for _ in range(2))
        self.expected = surfaces.bezier_surface(self.grid, self.u, self.v)

    def acceptable(self):
        return self.u != self.v and len(np.unique(self.grid[..., 2])) > 1

    def mistakes(self):
        g, m, n, u, v = self.grid, self.m, self.n, self.u, self.v
        bu, bv = curves.bernstein(m, None, u), curves.bernstein(n, None, v)
        swapped = curves.bernstein(m, None, v) @ np.einsum("ijd,j->id", g,
                                                           curves.bernstein(n, None, u))
        one_way = (r"You blended in one direction only, along a boundary curve of the patch. "
                   r"A tensor-product patch blends in both: each control point gets the "
                   r"weight $B_i^m(u)\, B_j^n(v)$, and all $(m+1)(n+1)$ of them count.")
        found = [
            Mistake(swapped, r"$u$ and $v$ are swapped. The first index of $P_{ij}$ runs along "
                    r"$u$ and goes with $B_i^m(u)$; the second runs along $v$ and goes with "
                    r"$B_j^n(v)$.", "u and v swapped"),
            Mistake(bu @ g[:, 0], one_way, "one direction only"),
            Mistake(bv @ g[0], one_way, "one direction only"),
        ]
        if max(m, n) > 1:
            corners = g[[0, -1]][:, [0, -1]]
            bilinear = np.array([1 - u, u]) @ np.einsum("ijd,j->id", corners,
                                                        np.array([1 - v, v]))
            found.append(Mistake(bilinear, r"You interpolated the four corner points only "
                                 r"(bilinearly). The inner control points pull on the surface "
                                 r"too: use all of them with the weights "
                                 r"$B_i^m(u)\, B_j^n(v)$ of the patch's degrees.",
                                 "corners only"))
        return found

    @staticmethod
    def _bernstein(n, t):
        """B_0^n(t), ..., B_n^n(t) for n = 1 or 2, by the formulas."""
        if n == 1:
            return np.array([1 - t, t])
        return np.array([(1 - t) ** 2, 2 * t * (1 - t), t ** 2])

    def hints(self):
        m, n, u, v = self.m, self.n, self.u, self.v
        bu, bv = self._bernstein(m, u), self._bernstein(n, v)
        rows = [bv @ self.grid[i] for i in range(m + 1)]
        return [
            r"A tensor-product patch: $P_{ij}$ gets the weight $B_i^m(u)\, B_j^n(v)$. Work in two "
            r"rounds: first blend along $v$ within each row $i$, then blend the results along "
            r"$u$.",
            rf"Here $B^{m}(u) = {_vec(bu, 4)}$ at $u = {_frac(u)}$ and $B^{n}(v) = "
            rf"{_vec(bv, 4)}$ at $v = {_frac(v)}$.",
            r"Row by row, $Q_i = \sum_j B_j^n(v)\, P_{ij}$: "
            + ", ".join(rf"$Q_{i} = {_vec(q)}$" for i, q in enumerate(rows))
            + r". Now $S(u, v) = \sum_i B_i^m(u)\, Q_i$.",
        ]

    def worked(self):
        m, n, u, v = self.m, self.n, self.u, self.v
        bu, bv = self._bernstein(m, u), self._bernstein(n, v)
        rows = [sum(bv[j] * self.grid[i, j] for j in range(n + 1)) for i in range(m + 1)]
        point = sum(bu[i] * rows[i] for i in range(m + 1))
        return Worked([
            rf"The Bernstein values: $B^{m}({_frac(u)}) = {_vec(bu, 4)}$ (degree {m} in $u$), "
            rf"$B^{n}({_frac(v)}) = {_vec(bv, 4)}$ (degree {n} in $v$).",
            r"Blend each row along $v$, $Q_i = \sum_j B_j^n(v)\, P_{ij}$: "
            + "; ".join(rf"$Q_{i} = {_vec(q)}$" for i, q in enumerate(rows)) + ".",
            r"Blend the rows along $u$: $S = " + " + ".join(
                rf"{_num(bu[i], 4)}\,Q_{i}" for i in range(m + 1)) + rf" = {_vec(point)}$.",
        ], point)

    def statement(self):
        m, n = self.m, self.n
        rows = "\n".join("| " + f"$i = {i}$ | "
                         + " | ".join(f"${_vec(self.grid[i, j])}$" for j in range(n + 1))
                         + " |" for i in range(m + 1))
        header = "| | " + " | ".join(f"$j = {j}$" for j in range(n + 1)) + " |"
        rule = "|---" * (n + 2) + "|"
        kind = {1: "linear", 2: "quadratic"}
        return (
            rf"A Bézier patch of degree {m} in $u$ and {n} in $v$ ({kind[m]} in $u$, "
            rf"{kind[n]} in $v$) has the control points $P_{{ij}}$ (row $i$ along $u$, column "
            r"$j$ along $v$):" "\n\n" + header + "\n" + rule + "\n" + rows + "\n\n"
            r"Compute the surface point "
            r"$S(u, v) = \sum_i \sum_j B_i^m(u)\, B_j^n(v)\, P_{ij}$ at "
            rf"$u = {_frac(self.u)}$, $v = {_frac(self.v)}$." "\n\n" + _POINT_3 + " "
            r"(`.grid[i, j]` is $P_{ij}$.)" "\n\n" + data_note("grid", "m", "n", "u", "v"))
