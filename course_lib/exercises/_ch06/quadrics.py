"""Chapter 6 exercises: Quadric error metric.

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import format as fmt
from ... import mesh
from ..core import (DECIMALS, SAME, DrawnExercise, Feedback, Mistake, Worked, close, data_note,
                    diagnose_matrix, diagnose_parts, parts_separated, read_floats)

__all__ = [
    "CollapseCost",
    "OptimalPosition",
    "VertexQuadric",
]


_num = fmt.number
_vec = fmt.vector_latex


#: Normals with whole coordinates: the axes, and two-axis diagonals (length sqrt 2).
_NORMALS = tuple(np.array(n, dtype=float) for n in
                 ([1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1],
                  [1, 1, 0], [1, -1, 0], [1, 0, 1], [0, 1, 1], [0, 1, -1], [-1, 0, 1]))


def _plane_words(n, p):
    """The plane through p with normal n (whole numbers) as an equation ``x + y = 3``."""
    names = ("x", "y", "z")
    terms = []
    for c, name in zip(n, names):
        if c:
            sign = ("- " if c < 0 else "+ ") if terms else ("-" if c < 0 else "")
            terms.append(f"{sign}{name}" if abs(c) == 1 else f"{sign}{_num(abs(c))}{name}")
    return " ".join(terms) + f" = {_num(float(np.dot(n, p)))}"


def _unit_plane(n, p):
    n = np.asarray(n, dtype=float)
    u = n / np.linalg.norm(n)
    return np.append(u, -float(u @ p))


def _draw_planes(rng, point, count, need_diagonal=False):
    """`count` planes through `point`, with distinct normals from _NORMALS (whole numbers)."""
    while True:
        picks = rng.choice(len(_NORMALS), size=count, replace=False)
        normals = [_NORMALS[i] for i in picks]
        if need_diagonal and all(np.abs(n).sum() == 1 for n in normals):
            continue
        if len({tuple(np.abs(n)) for n in normals}) == count:     # no two parallel
            return normals


def _quadric(planes):
    return sum(mesh.plane_quadric(p) for p in planes)


def _root(square):
    """The length of a whole-number normal from its squared length, as LaTeX: 1 or sqrt 2."""
    square = int(round(square))
    root = math.isqrt(square)
    return str(root) if root * root == square else rf"\sqrt{{{square}}}"


def _normalised_step(k, n, point):
    """One plane normalised by hand: the step's text and the plane p = (a, b, c, d)."""
    n = np.asarray(n, dtype=float)
    square = float(n @ n)
    offset = -float(n @ point)
    p = np.append(n, offset) / math.sqrt(square)
    root = _root(square)
    scaled = (rf"(n, d) = {_vec(p)}$ (already normalised)" if root == "1" else
              rf"\tfrac{{1}}{{{root}}}\,{_vec(np.append(n, offset))} = {_vec(p)}$")
    text = (rf"Plane {k}, ${_plane_words(n, point)}$: $n = {_vec(n)}$, $|n| = {root}$, "
            rf"$d = -n \cdot v = {_num(offset)}$, so $p_{k} = " + scaled + ".")
    return text, p


class VertexQuadric(DrawnExercise):
    r"""The quadric :math:`Q = \sum_p p p^T` of a vertex from the planes of its faces.

    Each plane is first normalised to :math:`(a, b, c, d)` with unit normal and
    :math:`d = -n \cdot x_0` for a point :math:`x_0` on it.

    Attributes: ``point`` (the vertex), ``normals`` (whole-number normals of the planes, not
    normalised), ``planes`` (the normalised :math:`(a, b, c, d)`, for checking your own).

    Examples
    --------
    >>> ex = VertexQuadric(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> raw = [np.append(n, -n @ ex.point) for n in ex.normals]     # not normalised
    >>> ex.check(sum(np.outer(p, p) for p in raw)).diagnosis
    'not normalised'
    """

    title = "A vertex quadric"
    what = "the quadric Q"
    transform = False
    advice = (r"Normalise each plane: divide $(a, b, c)$ and $d$ by $\sqrt{a^2 + b^2 + c^2}$; "
            r"then $K_p = p\,p^T$ for $p = (a, b, c, d)$, and $Q$ is the sum of the $K_p$.")

    def draw(self, rng):
        self.point = rng.integers(-2, 3, size=3).astype(float)
        self.normals = _draw_planes(rng, self.point, 3, need_diagonal=True)
        self.planes = np.array([_unit_plane(n, self.point) for n in self.normals])
        self.expected = _quadric(self.planes)

    def acceptable(self):
        return np.count_nonzero(self.point) >= 2

    def mistakes(self):
        raw = [np.append(n, -float(n @ self.point)) for n in self.normals]
        flipped = self.planes * np.array([1, 1, 1, -1])
        total = self.planes.sum(axis=0)
        return [
            Mistake(_quadric(raw), r"You did not normalise the planes. $p^T v$ is the "
                    r"distance of $v$ from the plane only when $a^2 + b^2 + c^2 = 1$: divide "
                    r"the equation by the length of its normal first (here "
                    r"$\sqrt 2$ for the slanted planes).", "not normalised"),
            Mistake(_quadric(flipped), r"The sign of $d$ is wrong. Write the plane as "
                    r"$ax + by + cz + d = 0$: for $n \cdot x = c_0$ that is $d = -c_0$. Check "
                    r"with the vertex: $p^T (x, y, z, 1)$ must be 0 there.", "sign of d"),
            Mistake(np.outer(total, total), r"You added the planes first and then took one "
                    r"outer product. The quadric is the sum of the outer products, "
                    r"$Q = \sum_p p\,p^T$, so that $v^T Q v = \sum_p (p^T v)^2$, a sum of "
                    r"squared distances; $(\sum_p p)(\sum_p p)^T$ squares a sum instead.",
                    "summed planes first"),
        ]

    def hints(self):
        planes = ", ".join(rf"$p_{k} = {_vec(p)}$" for k, p in enumerate(self.planes, 1))
        return [
            r"Each plane through the vertex contributes its fundamental error quadric "
            r"$K_p = p\,p^T$, with $p = (a, b, c, d)$ **normalised** ($a^2 + b^2 + c^2 = 1$); "
            r"the vertex quadric is their sum.",
            r"Normalise each equation $n \cdot x = c_0$ by dividing by $|n|$; then "
            r"$d = -c_0 / |n|$ (check: $p^T (v, 1) = 0$ at the vertex). Entry $(i, j)$ of "
            r"$p\,p^T$ is $p_i p_j$.",
            rf"Here the normalised planes are {planes}.",
        ]

    def worked(self):
        steps, rows = [], []
        for k, n in enumerate(self.normals, 1):
            text, p = _normalised_step(k, n, self.point)
            steps.append(text)
            rows.append(p)
        quadrics = [np.outer(p, p) for p in rows]
        steps.append(r"The outer products $K_k = p_k\,p_k^T$: "
                     + ", ".join(rf"$K_{k} = {_matrix_latex(K)}$"
                                 for k, K in enumerate(quadrics, 1)) + ".")
        Q = quadrics[0] + quadrics[1] + quadrics[2]
        steps.append(rf"Their sum: $Q = K_1 + K_2 + K_3 = {_matrix_latex(Q)}$.")
        return Worked(steps, Q)

    def _judge(self, answer):
        value = read_floats(answer)
        if value is not None and value.shape == (3, 3) and close(value,
                                                                 self.expected[:3, :3]):
            return Feedback("wrong", r"That is only the $3 \times 3$ block $A$ (the normals' "
                            r"part). The quadric is $4 \times 4$: $p = (a, b, c, d)$ has four "
                            r"entries, and the last row and column carry $d$.", "3x3 block")
        return diagnose_matrix(answer, self.expected, self._mistakes, what=self.what,
                               transform=False)

    def statement(self):
        planes = ", ".join(rf"${_plane_words(n, self.point)}$" for n in self.normals)
        return (
            rf"Three faces meet at the vertex $v = {_vec(self.point)}$; they lie in the planes "
            + planes + r". Compute the vertex's quadric "
            r"$Q = \sum_p K_p = \sum_p p\,p^T$ with each plane written as "
            r"$p = (a, b, c, d)$, $ax + by + cz + d = 0$, $a^2 + b^2 + c^2 = 1$." "\n\n"
            r"**Answer:** the $4 \times 4$ matrix $Q$ (a nested list or numpy array). "
            + DECIMALS + "\n\n" + data_note("point", "normals") + " (`.normals` are the "
            "whole-number normals of the equations above, not normalised.)")


def _matrix_latex(Q):
    return fmt.matrix_latex(np.round(Q, 10) + 0.0)


class _TwoVertices(DrawnExercise):
    """An edge (v1, v2), each end with two planes through it; the quadrics Q1, Q2."""

    #: How far v2 may lie from v1, per coordinate.
    reach = 2

    def _draw_edge(self, rng):
        self.v1 = rng.integers(-2, 3, size=3).astype(float)
        self.v2 = self.v1 + rng.integers(-self.reach, self.reach + 1, size=3).astype(float)
        self.normals1 = _draw_planes(rng, self.v1, 2)
        self.normals2 = _draw_planes(rng, self.v2, 2)
        self.planes = np.array([_unit_plane(n, self.v1) for n in self.normals1]
                               + [_unit_plane(n, self.v2) for n in self.normals2])
        self.Q1 = _quadric(self.planes[:2])
        self.Q2 = _quadric(self.planes[2:])

    def _edge_words(self):
        return (rf"The edge from $v_1 = {_vec(self.v1)}$ to $v_2 = {_vec(self.v2)}$ is a "
                r"candidate for collapse. The vertex quadrics are" "\n\n"
                rf"$$Q_1 = {_matrix_latex(self.Q1)}, \qquad Q_2 = {_matrix_latex(self.Q2)}$$"
                "\n\n" r"(each the sum of $p\,p^T$ over two planes through its vertex).")


def _cost(Q, x):
    h = np.append(np.asarray(x, dtype=float), 1.0)
    return float(h @ Q @ h)


class CollapseCost(_TwoVertices):
    r"""The quadric error of collapsing an edge to its midpoint: :math:`\bar v^T (Q_1 + Q_2) \bar v`.

    Attributes: ``v1``, ``v2``, ``Q1``, ``Q2``.

    Examples
    --------
    >>> ex = CollapseCost(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> mid = (ex.v1 + ex.v2) / 2
    >>> ex.check(mid @ (ex.Q1 + ex.Q2)[:3, :3] @ mid).diagnosis       # w = 0
    'no homogeneous 1'
    """

    title = "The cost of an edge collapse"
    answer_form = "number"
    what = "the cost"
    reach = 3
    advice = (r"Add the quadrics, $\bar Q = Q_1 + Q_2$, write the midpoint with a 1 appended, "
            r"$\bar v = (x, y, z, 1)$, and compute $\bar v^T \bar Q \bar v$.")

    def draw(self, rng):
        self._draw_edge(rng)
        self.mid = (self.v1 + self.v2) / 2
        self.expected = _cost(self.Q1 + self.Q2, self.mid)

    def acceptable(self):
        return np.abs(self.v2 - self.v1).sum() >= 2 and self.expected > 0.4

    def mistakes(self):
        Q, mid = self.Q1 + self.Q2, self.mid
        return [
            Mistake(float(mid @ Q[:3, :3] @ mid), r"You left out the homogeneous coordinate: "
                    r"$\bar v = (x, y, z, \mathbf{1})$. Without the 1 the $d$ terms of the "
                    r"planes (the last row and column of $Q$) drop out, as if every plane went "
                    r"through the origin.", "no homogeneous 1"),
            Mistake(_cost(self.Q1, mid), r"You used $Q_1$ only. The merged vertex must stay "
                    r"close to the planes of **both** end points: $\bar Q = Q_1 + Q_2$.",
                    "one quadric"),
            Mistake(_cost(self.Q2, mid), r"You used $Q_2$ only. The merged vertex must stay "
                    r"close to the planes of **both** end points: $\bar Q = Q_1 + Q_2$.",
                    "one quadric"),
            Mistake(_cost(Q, mid) / 2, r"You averaged the quadrics. Garland and Heckbert add "
                    r"them, $\bar Q = Q_1 + Q_2$: the cost is the *sum* of the squared "
                    r"distances to all the planes.", "averaged"),
            Mistake(math.sqrt(_cost(Q, mid)), r"That is the square root. The quadric error "
                    r"$\bar v^T \bar Q \bar v$ is a sum of **squared** distances; leave it "
                    r"squared.", "square root"),
        ]

    def hints(self):
        Q = self.Q1 + self.Q2
        h = np.append((self.v1 + self.v2) / 2, 1.0)
        return [
            r"The error of the merged vertex at $\bar v$ is $\bar v^T \bar Q \bar v$, with "
            r"$\bar Q = Q_1 + Q_2$ (the planes of both end points) and $\bar v$ in "
            r"homogeneous coordinates.",
            r"Take the midpoint $\frac{1}{2}(v_1 + v_2)$, append a 1, multiply "
            r"$\bar Q \bar v$ first and then take the dot product of $\bar v$ with that "
            r"vector.",
            rf"Here $\bar v = {_vec(h)}$ and $\bar Q \bar v = {_vec(Q @ h)}$.",
        ]

    def worked(self):
        Q = self.Q1 + self.Q2
        mid = (self.v1 + self.v2) / 2
        h = np.append(mid, 1.0)
        Qh = Q @ h
        cost = float(h @ Qh)
        return Worked([
            rf"Add the quadrics: $\bar Q = Q_1 + Q_2 = {_matrix_latex(Q)}$.",
            rf"The midpoint: $\frac{{1}}{{2}}(v_1 + v_2) = {_vec(mid)}$, in homogeneous "
            rf"coordinates $\bar v = {_vec(h)}$.",
            rf"$\bar Q \bar v = {_vec(Qh)}$.",
            rf"$\bar v^T (\bar Q \bar v) = {_num(cost, 4)}$: the sum of the squared distances "
            r"of the midpoint to the four planes.",
        ], cost)

    def statement(self):
        return (
            self._edge_words() + "\n\n"
            r"Compute the cost $\bar v^T (Q_1 + Q_2)\, \bar v$ of collapsing the edge to its "
            r"midpoint $\bar v$ (in homogeneous coordinates)." "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("v1", "v2", "Q1", "Q2"))


class OptimalPosition(_TwoVertices):
    r"""The position that minimizes the quadric error of a collapse, and its cost.

    With :math:`\bar Q = Q_1 + Q_2 = \begin{pmatrix} A & b \\ b^T & c \end{pmatrix}` the
    gradient vanishes where :math:`A \bar v = -b`; the cost there is :math:`c + b^T \bar v`.

    Attributes: ``v1``, ``v2``, ``Q1``, ``Q2``.

    Examples
    --------
    >>> ex = OptimalPosition(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> Q = ex.Q1 + ex.Q2
    >>> x = np.linalg.solve(Q[:3, :3], Q[:3, 3])                      # A v = +b
    >>> h = np.append(x, 1)
    >>> ex.check([*x, h @ Q @ h]).diagnosis
    'sign of b'
    """

    title = "The optimal position of the merged vertex"
    answer_form = "custom"
    advice = (r"Split $\bar Q = Q_1 + Q_2$ into the $3 \times 3$ block $A$, the column $b$ "
            r"(first three entries of the last column) and the corner $c$; solve "
            r"$A\,\bar v = -b$; the cost is $(\bar v, 1)^T \bar Q\, (\bar v, 1)$.")

    def draw(self, rng):
        self._draw_edge(rng)
        Q = self.Q1 + self.Q2
        A = Q[:3, :3]
        if abs(np.linalg.det(A)) < 0.2:
            self.expected = None
            return
        x = np.linalg.solve(A, -Q[:3, 3])
        self.expected = np.array([*x, _cost(Q, x)])

    def acceptable(self):
        if self.expected is None:
            return False
        x, cost = self.expected[:3], self.expected[3]
        # bounds up to rounding (SAME): a cost of exactly 0.1 must not pass or fail by the last
        # bit, which depends on the CPU's LAPACK/BLAS kernels
        return (cost > 0.1 - SAME and np.abs(x).max() <= 6 + SAME
                and not close(x, self.v1) and not close(x, self.v2))

    def _parts(self):
        Q = self.Q1 + self.Q2
        x = self.expected[:3]
        wrong_sign = np.linalg.solve(Q[:3, :3], Q[:3, 3])
        mid = (self.v1 + self.v2) / 2
        sign = (r"The sign is wrong: setting the gradient of $\bar v^T \bar Q \bar v$ to zero "
                r"gives $2(A\bar v + b) = 0$, so $A\,\bar v = -b$.")
        midpoint = (r"That is the midpoint of the edge, the fallback for a singular $A$. Here "
                    r"$A$ is invertible, and the best position solves $A\,\bar v = -b$; it "
                    r"need not lie on the edge.")
        parts = []
        for k, name in enumerate(("x", "y", "z")):
            parts.append((f"{name} of the position", float(x[k]),
                          [Mistake(wrong_sign[k], sign, "sign of b"),
                           Mistake(mid[k], midpoint, "midpoint")]))
        parts.append(("the cost", float(self.expected[3]),
                      [Mistake(_cost(Q, wrong_sign), sign, "sign of b"),
                       Mistake(_cost(Q, mid), midpoint, "midpoint"),
                       Mistake(float(x @ Q[:3, :3] @ x), r"The cost needs the homogeneous 1: "
                               r"$(\bar v, 1)^T \bar Q\, (\bar v, 1) = \bar v^T A \bar v + "
                               r"2 b^T \bar v + c$; without it the plane offsets drop out.",
                               "no homogeneous 1")]))
        return parts

    def separated(self, mistakes):
        parts = self._parts()
        if not parts_separated(parts):
            return False
        # the position's slips must show in at least one coordinate
        for key in ("sign of b", "midpoint"):
            if all(abs(float(m.value) - exp) <= SAME for _, exp, ms in parts[:3]
                   for m in ms if m.key == key):
                return False
        return True

    def hints(self):
        Q = self.Q1 + self.Q2
        return [
            r"Write the error as $f(\bar v) = \bar v^T A \bar v + 2 b^T \bar v + c$ with "
            r"$\bar Q = Q_1 + Q_2 = \begin{pmatrix} A & b \\ b^T & c \end{pmatrix}$; at the "
            r"minimum its gradient $2(A\bar v + b)$ vanishes.",
            r"Solve the $3 \times 3$ system $A\,\bar v = -b$; the smallest error is then "
            r"$f(\bar v) = c + b^T \bar v$ (because $\bar v^T A \bar v = -b^T \bar v$ there).",
            rf"Here $A = {_matrix_latex(Q[:3, :3])}$, $b = {_vec(Q[:3, 3])}$ and "
            rf"$c = {_num(Q[3, 3])}$.",
        ]

    def worked(self):
        Q = self.Q1 + self.Q2
        A, b, c = Q[:3, :3], Q[:3, 3], float(Q[3, 3])
        x = np.linalg.solve(A, -b)
        cost = c + float(b @ x)
        return Worked([
            rf"$\bar Q = Q_1 + Q_2 = {_matrix_latex(Q)}$: $A$ is its upper-left "
            rf"$3 \times 3$ block, $b = {_vec(b)}$ the first three entries of its last column, "
            rf"$c = {_num(c)}$.",
            rf"Setting the gradient of $\bar v^T A \bar v + 2 b^T \bar v + c$ to zero gives "
            rf"$A\,\bar v = -b$: ${_matrix_latex(A)}\,\bar v = {_vec(-b)}$.",
            rf"$A$ is invertible (its determinant is {_num(float(np.linalg.det(A)), 4)}); "
            rf"solving gives $\bar v = {_vec(x, 4)}$.",
            rf"The error there: $c + b^T \bar v = {_num(c)} + ({_num(float(b @ x), 4)}) = "
            rf"{_num(cost, 4)}$.",
        ], [*x, cost])

    def mistakes(self):
        return []

    def _check(self, answer):          # diagnose_parts ends with the hint: not hinted again
        return diagnose_parts(answer, self._parts(), "your answer", "`[x, y, z, cost]`.",
                              self.advice)

    def statement(self):
        return (
            self._edge_words() + "\n\n"
            r"Find the position $\bar v$ that minimizes the error "
            r"$(\bar v, 1)^T (Q_1 + Q_2)\, (\bar v, 1)$ of the merged vertex, and that "
            r"smallest error." "\n\n"
            r"**Answer:** a list of 4 numbers `[x, y, z, cost]`. " + DECIMALS + "\n\n"
            + data_note("v1", "v2", "Q1", "Q2"))
