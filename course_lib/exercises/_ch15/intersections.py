"""Chapter 15 exercises: where a ray hits a sphere or a triangle.

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.
"""
import math

import numpy as np

from ... import raytracing as rt
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick
from . import _NICE_UNITS, _POINT_3, _Parts, _num, _vec

__all__ = [
    "RaySphereHit",
    "RayTriangleHit",
]


# ---------------------------------------------------------------------------------------------
# Intersections
# ---------------------------------------------------------------------------------------------

class RaySphereHit(DrawnExercise):
    r"""The point where a ray :math:`o + t\,d` first hits a sphere.

    Substituting the ray into :math:`\lVert p - c \rVert^2 = r^2` gives
    :math:`a t^2 + b t + c' = 0` with :math:`a = d \cdot d`, :math:`b = 2\, d \cdot (o - c)`,
    :math:`c' = \lVert o - c \rVert^2 - r^2`; the smaller positive root is the hit. The
    direction :math:`d` has whole-number components and is *not* a unit vector.

    Attributes: ``o``, ``d`` (the ray), ``center``, ``radius``.

    Examples
    --------
    >>> ex = RaySphereHit(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.o + ex.t_far * ex.d).diagnosis
    'far root'
    >>> ex.check(...).status, ex.check("P").status
    ('unanswered', 'invalid')
    """

    title = "A ray hits a sphere"
    answer_form = "point"
    what = "the hit point"
    advice = (r"Solve $a t^2 + b t + c' = 0$ with $a = d \cdot d$, $b = 2\, d \cdot (o - c)$, "
              r"$c' = \lVert o - c \rVert^2 - r^2$; take the smaller root (the ray enters there) "
              r"and put it into $o + t\,d$.")

    def draw(self, rng):
        self.radius = float(pick(rng, (3.0, 5.0, 7.0)))
        self.center = rng.integers(-2, 3, size=3).astype(float)
        units = {3.0: (_NICE_UNITS[0], _NICE_UNITS[2]), 5.0: (_NICE_UNITS[0], _NICE_UNITS[1]),
                 7.0: (_NICE_UNITS[0], _NICE_UNITS[3])}[self.radius]
        normal = np.array(pick(rng, units))[rng.permutation(3)] * rng.choice([-1.0, 1.0], 3)
        hit = self.center + self.radius * normal
        self.d = rng.integers(-2, 3, size=3).astype(float)
        self._t = float(pick(rng, (1.0, 2.0)))
        self.o = hit - self._t * self.d
        self._normal = normal
        self.expected = hit

    def acceptable(self):
        d, o, c, r = self.d, self.o, self.center, self.radius
        if not d.any() or d @ self._normal > -0.3 * np.linalg.norm(d) or d @ d == 1:
            return False
        if np.linalg.norm(o - c) <= r + 0.5:
            return False
        hits = rt.intersect_sphere(o, d, c, r)
        if not np.allclose(o + float(hits.t) * d, self.expected):
            return False
        a, b, c2 = d @ d, 2 * d @ (o - c), (o - c) @ (o - c) - r * r
        self.t_far = c2 / (a * self._t)
        return True

    def mistakes(self):
        o, d, c, r = self.o, self.d, self.center, self.radius
        b, c2 = 2 * d @ (o - c), (o - c) @ (o - c) - r * r
        unit_roots = np.roots([1.0, b, c2])
        found = [
            Mistake(o + self.t_far * d, r"That is where the ray **leaves** the sphere (the "
                    r"larger root). Coming from outside, the ray enters at the smaller root "
                    r"$t = \frac{-b - \sqrt{b^2 - 4ac'}}{2a}$, which is the visible surface.",
                    "far root"),
            Mistake(o - self.t_far * d, r"The sign of $b$ is wrong: with $f = c - o$ instead "
                    r"of $o - c$ both roots change sign, and the smaller one is then behind the "
                    r"ray's origin. Use $b = 2\, d \cdot (o - c)$.", "sign of b"),
        ]
        if np.isreal(unit_roots).all():
            t_unit = float(np.min(unit_roots.real))
            found.append(Mistake(o + t_unit * d, r"You took $a = 1$, as if $d$ were a unit "
                                 r"vector; it is not. Either use $a = d \cdot d = "
                                 + _num(d @ d) + r"$, or normalize $d$ first (then $t$ is a "
                                 r"distance).", "a = 1"))
        return found

    def statement(self):
        return (
            rf"A ray starts at $o = {_vec(self.o)}$ with direction $d = {_vec(self.d)}$ (not a "
            rf"unit vector). A sphere has centre $c = {_vec(self.center)}$ and radius "
            rf"$r = {_num(self.radius)}$. Find the point where the ray first hits the sphere."
            "\n\n" + _POINT_3 + "\n\n" + data_note("o", "d", "center", "radius"))

    def _quadratic(self):
        """f = o - c and the coefficients a, b, c' of the quadratic in t."""
        f = self.o - self.center
        return f, float(self.d @ self.d), 2 * float(self.d @ f), float(f @ f) - self.radius ** 2

    def hints(self):
        f, a, b, c2 = self._quadratic()
        return [
            r"Put the ray into the sphere's equation: $\lVert o + t\,d - c \rVert^2 = r^2$ is a "
            r"quadratic $a t^2 + b t + c' = 0$ in the ray parameter $t$.",
            rf"With $f = o - c = {_vec(f)}$: $a = d \cdot d = {_num(a)}$ (not 1, $d$ is no unit "
            rf"vector), $b = 2\, d \cdot f = {_num(b)}$ and $c' = f \cdot f - r^2 = {_num(c2)}$.",
            rf"The discriminant is $b^2 - 4ac' = {_num(b * b - 4 * a * c2)}$. The ray starts "
            r"outside, so the smaller root $t = \frac{-b - \sqrt{b^2 - 4ac'}}{2a}$ is where it "
            r"enters; put that $t$ into $o + t\,d$.",
        ]

    def worked(self):
        f, a, b, c2 = self._quadratic()
        disc = b * b - 4 * a * c2
        root = math.sqrt(disc)
        t_in, t_out = (-b - root) / (2 * a), (-b + root) / (2 * a)
        point = self.o + t_in * self.d
        return Worked([
            rf"Substitute $p = o + t\,d$ into $\lVert p - c \rVert^2 = r^2$. With "
            rf"$f = o - c = {_vec(f)}$ it reads $a t^2 + b t + c' = 0$ with "
            rf"$a = d \cdot d = {_num(a)}$, $b = 2\, d \cdot f = {_num(b)}$, "
            rf"$c' = f \cdot f - r^2 = {_num(f @ f)} - {_num(self.radius ** 2)} = {_num(c2)}$.",
            rf"Discriminant: $b^2 - 4ac' = {_num(b * b)} - {_num(4 * a * c2)} = {_num(disc)}$, "
            rf"whose square root is ${_num(root)}$: two hits.",
            rf"Roots: $t = \frac{{{_num(-b)} \mp {_num(root)}}}{{{_num(2 * a)}}}$, so "
            rf"$t_1 = {_num(t_in)}$ (the ray enters) and $t_2 = {_num(t_out)}$ (it leaves). "
            r"Both are positive, the origin is outside the sphere: the first hit is $t_1$.",
            rf"The hit point: $o + t_1 d = {_vec(self.o)} + {_num(t_in)} \cdot {_vec(self.d)} = "
            rf"{_vec(point)}$. Check: its distance from $c$ is "
            rf"${_num(np.linalg.norm(point - self.center))} = r$.",
        ], point)


#: Barycentric coordinates in eighths: inside the triangle (u, v > 0, u + v < 1) ...
_INSIDE = tuple((i / 8, j / 8) for i in range(1, 8) for j in range(1, 8) if i + j < 8)
#: ... and exactly on one of its edges (not at a vertex), by the edge's name.
_ON_EDGE = {
    "edge v0v1": tuple((i / 8, 0.0) for i in range(1, 8)),
    "edge v0v2": tuple((0.0, j / 8) for j in range(1, 8)),
    "edge v1v2": tuple((i / 8, 1 - i / 8) for i in range(1, 8)),
}
#: How often the ray is aimed exactly at an edge (a deliberate boundary case).
_EDGE_SHARE = 0.15


class RayTriangleHit(_Parts):
    r"""Where a ray hits a triangle: the ray parameter and the barycentric coordinates.

    Solve :math:`o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)` (three equations, three
    unknowns; Möller-Trumbore solves it by Cramer's rule); the ray hits when :math:`u, v \ge 0`,
    :math:`u + v \le 1` and :math:`t > 0`. In about 15 % of the variants the ray hits exactly on
    an edge (``boundary`` names it: ``"edge v0v1"`` where :math:`v = 0`, ``"edge v0v2"`` where
    :math:`u = 0`, ``"edge v1v2"`` where :math:`u + v = 1`; None inside): a hit on an edge counts,
    as the statement says.

    Attributes: ``o``, ``d``, ``V`` (the vertices :math:`v_0, v_1, v_2`, one per row),
    ``boundary``.

    Examples
    --------
    >>> ex = RayTriangleHit(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> t, u, v = ex.expected
    >>> ex.check([t, v, u]).diagnosis
    'u and v swapped'
    >>> ex.check([t, u, 1 - u - v]).diagnosis
    'weight of v0'
    >>> sorted({RayTriangleHit(seed=s).boundary or "inside" for s in range(40)})
    ['edge v0v1', 'edge v0v2', 'edge v1v2', 'inside']
    """

    title = "A ray hits a triangle"
    what = "your answer"
    form_hint = r"`[t, u, v]`."
    advice = (r"Write $o + t\,d = v_0 + u\,e_1 + v\,e_2$ with $e_1 = v_1 - v_0$, "
              r"$e_2 = v_2 - v_0$ as three linear equations in $t, u, v$ and solve them "
              r"(Cramer's rule, or `np.linalg.solve`).")

    def draw(self, rng):
        while True:
            V = rng.integers(-2, 3, size=(3, 3)).astype(float)
            if np.linalg.norm(np.cross(V[1] - V[0], V[2] - V[0])) > 1:
                break
        self.V = V
        self.boundary = None
        if rng.random() < _EDGE_SHARE:
            self.boundary = pick(rng, tuple(_ON_EDGE))
            u, v = pick(rng, _ON_EDGE[self.boundary])
        else:
            u, v = pick(rng, _INSIDE)
        point = (1 - u - v) * V[0] + u * V[1] + v * V[2]
        self.d = rng.integers(-2, 3, size=3).astype(float)
        t = float(pick(rng, (0.5, 1.0, 1.5, 2.0, 2.5, 3.0)))
        self.o = point - t * self.d
        self.expected = np.array([t, u, v])

    def acceptable(self):
        n = np.cross(self.V[1] - self.V[0], self.V[2] - self.V[0])
        if not self.d.any():
            return False
        if abs(self.d @ n) < 0.3 * np.linalg.norm(n) * np.linalg.norm(self.d) or \
                self.d @ self.d == 1:
            return False
        hits = rt.intersect_triangles(self.o, self.d, self.V[None], accelerate=False)
        return int(hits.ids) == 0 and np.allclose([hits.t, hits.u, hits.v], self.expected)

    def parts(self):
        t, u, v = self.expected
        w = 1 - u - v
        swapped = r"$u$ and $v$ are swapped: $u$ is the weight of $v_1$, $v$ that of $v_2$."
        v0_weight = (r"That is $1 - u - v$, the weight of $v_0$. In "
                     r"$(1 - u - v)\, v_0 + u\, v_1 + v\, v_2$, $u$ belongs to $v_1$ and $v$ to "
                     r"$v_2$.")
        return [
            ("t", t, [Mistake(t * np.linalg.norm(self.d), r"That is the *distance* "
                      r"$t \lVert d \rVert$ from $o$ to the hit. The ray parameter is the $t$ "
                      r"of $o + t\,d$; $d$ is not a unit vector here.", "distance")]),
            ("u", u, [Mistake(v, swapped, "u and v swapped"),
                      Mistake(w, v0_weight, "weight of v0")]),
            ("v", v, [Mistake(u, swapped, "u and v swapped"),
                      Mistake(w, v0_weight, "weight of v0")]),
        ]

    def statement(self):
        v0, v1, v2 = self.V
        return (
            rf"A ray starts at $o = {_vec(self.o)}$ with direction $d = {_vec(self.d)}$. A "
            rf"triangle has the vertices $v_0 = {_vec(v0)}$, $v_1 = {_vec(v1)}$, "
            rf"$v_2 = {_vec(v2)}$. The ray hits it at $o + t\,d = (1 - u - v)\, v_0 + u\, v_1 "
            r"+ v\, v_2$ (a hit exactly on an edge, where $u = 0$, $v = 0$ or $u + v = 1$, "
            r"counts as a hit). Find $t$, $u$ and $v$." "\n\n"
            r"**Answer:** a list of 3 numbers `[t, u, v]`. " + DECIMALS + "\n\n"
            + data_note("o", "d", "V"))

    def _solve(self):
        """The Möller-Trumbore quantities: e1, e2, s, p, det, q and t, u, v."""
        v0, v1, v2 = self.V
        e1, e2, s = v1 - v0, v2 - v0, self.o - v0
        p = np.cross(self.d, e2)
        det = float(e1 @ p)
        q = np.cross(s, e1)
        return e1, e2, s, p, det, q, float(e2 @ q) / det, float(s @ p) / det, \
            float(self.d @ q) / det

    def hints(self):
        e1, e2, s, p, det, q, t, u, v = self._solve()
        return [
            r"Write the hit point both ways, $o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)$: "
            r"three linear equations in the three unknowns $t$, $u$, $v$.",
            rf"Here $e_1 = v_1 - v_0 = {_vec(e1)}$, $e_2 = v_2 - v_0 = {_vec(e2)}$ and "
            rf"$s = o - v_0 = {_vec(s)}$; the system is $-t\,d + u\,e_1 + v\,e_2 = s$. Solve it "
            r"by Cramer's rule (Möller-Trumbore) or with `np.linalg.solve`.",
            rf"Möller-Trumbore: $p = d \times e_2 = {_vec(p)}$, $\det = e_1 \cdot p = "
            rf"{_num(det)}$, so $u = \frac{{s \cdot p}}{{\det}} = {_num(u)}$; then "
            rf"$q = s \times e_1 = {_vec(q)}$ gives $v = \frac{{d \cdot q}}{{\det}}$ and "
            r"$t = \frac{e_2 \cdot q}{\det}$.",
        ]

    def worked(self):
        e1, e2, s, p, det, q, t, u, v = self._solve()
        steps = [
            rf"Edges from $v_0$: $e_1 = v_1 - v_0 = {_vec(e1)}$, $e_2 = v_2 - v_0 = {_vec(e2)}$, "
            rf"and $s = o - v_0 = {_vec(s)}$. The equation $o + t\,d = v_0 + u\,e_1 + v\,e_2$ "
            r"becomes $-t\,d + u\,e_1 + v\,e_2 = s$.",
            rf"Möller-Trumbore (Cramer's rule written with cross products): "
            rf"$p = d \times e_2 = {_vec(p)}$ and $\det = e_1 \cdot p = {_num(det)}$ (not 0: the "
            r"ray is not parallel to the triangle's plane).",
            rf"$u = \frac{{s \cdot p}}{{\det}} = \frac{{{_num(s @ p)}}}{{{_num(det)}}} = "
            rf"{_num(u)}$. With $q = s \times e_1 = {_vec(q)}$: "
            rf"$v = \frac{{d \cdot q}}{{\det}} = \frac{{{_num(self.d @ q)}}}{{{_num(det)}}} = "
            rf"{_num(v)}$ and $t = \frac{{e_2 \cdot q}}{{\det}} = "
            rf"\frac{{{_num(e2 @ q)}}}{{{_num(det)}}} = {_num(t)}$.",
        ]
        inside = (rf"Check: $u = {_num(u)} \ge 0$, $v = {_num(v)} \ge 0$, "
                  rf"$u + v = {_num(u + v)} \le 1$ and $t = {_num(t)} > 0$: the ray hits the "
                  r"triangle.")
        edge = {"edge v0v1": r"$v = 0$: the point lies on the edge from $v_0$ to $v_1$",
                "edge v0v2": r"$u = 0$: the point lies on the edge from $v_0$ to $v_2$",
                "edge v1v2": r"$u + v = 1$: the point lies on the edge from $v_1$ to $v_2$"}
        if self.boundary is not None:
            inside += (rf" Here {edge[self.boundary]}, exactly on the boundary. The test allows "
                       r"equality ($u, v \ge 0$, $u + v \le 1$), so a hit on an edge counts; with "
                       r"strict inequalities rays through a shared edge would slip between two "
                       r"neighbouring triangles and leave holes in the mesh.")
        steps.append(inside)
        return Worked(steps, [t, u, v])
