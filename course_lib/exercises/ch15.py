r"""Chapter 15 exercises: ray tracing, exam style.

Each class is one kind of exam question: where a ray first hits a sphere; where it hits a
triangle (the ray parameter and the barycentric coordinates, as in Möller-Trumbore); the mirror
direction of an incoming ray; the refracted direction by Snell's law; the critical angle of total
internal reflection; Schlick's Fresnel reflectance; whether a shadow ray is blocked and what the
point's intensity is then; the colour a chain of mirror bounces gives a pixel; how many rays a
pixel's ray tree holds; and what a bounding volume hierarchy saves. The ``seed`` draws numbers
that work out by hand: whole-number points, unit vectors with rational components such as
:math:`(\tfrac23, \tfrac23, \tfrac13)` or :math:`(0.6, 0.8, 0)`, barycentric coordinates in
eighths, angles of refraction that are multiples of 15 degrees, refractive indices of real
media. Counts (rays, levels, tests) are whole numbers, compared exactly; every real answer is
right to 3 significant digits (the course's one tolerance policy). A few variants are boundary
cases on purpose (a ray through a triangle's edge), labelled by an attribute ``boundary``.

The expected answers come from :mod:`course_lib.raytracing`. Each exercise names the slips it
anticipates (the far root of the quadratic, a direction taken as a unit vector when it is not,
:math:`u` and :math:`v` swapped, the Phong-model reflection formula applied to an incoming ray,
the ratio of refractive indices upside down, the angle's degrees fed to a cosine that takes
radians, Brewster's angle for the critical angle, the weights of a ray tree added instead of
multiplied, the primary ray forgotten in a count, ...),
computes the answer each slip would give, and draws its numbers again until those answers differ
clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`). Every exercise offers ``hint()`` (three
hints, from the idea to this variant's numbers) and ``solution()`` (this variant worked out).

Conventions (those of :mod:`course_lib.raytracing`): a ray is :math:`o + t\,d`; :math:`d` is the
direction the ray *travels* (towards the surface), so the mirror direction is
:math:`r = d - 2 (d \cdot n)\, n`; refractive indices :math:`\eta_1` (the medium the ray comes
from) and :math:`\eta_2`; a triangle point is :math:`(1 - u - v)\, v_0 + u\, v_1 + v\, v_2`.
"""
import math

import numpy as np

from .. import format as fmt
from .. import raytracing as rt
from .core import (APART, DECIMALS, SAME, DrawnExercise, Mistake, PartsAnswer, Worked, data_note,
                   latex_fraction, latex_vector, parts_separated, pick, well_separated)

__all__ = [
    "EXERCISES",
    "BVHSavings",
    "CriticalAngle",
    "MirrorChainColour",
    "RaySphereHit",
    "RayTreeCount",
    "RayTriangleHit",
    "ReflectedRay",
    "RefractedRay",
    "SchlickReflectance",
    "ShadowRay",
]

_vec = fmt.vector_latex
_num = fmt.number
_frac = latex_vector            # components as short decimals or simple fractions (2/3, 6/7)

#: Unit vectors with rational components (before permuting the axes and choosing signs).
_NICE_UNITS = ((1.0, 0.0, 0.0), (0.6, 0.8, 0.0), (2 / 3, 2 / 3, 1 / 3), (2 / 7, 3 / 7, 6 / 7))

_POINT_3 = "**Answer:** the point as a list of 3 numbers `[x, y, z]`. " + DECIMALS
_VECTOR_3 = "**Answer:** the vector as a list of 3 numbers `[x, y, z]`. " + DECIMALS
_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


def _nice_unit(rng):
    v = np.array(pick(rng, _NICE_UNITS))[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0


def _is_count(x):
    return isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_))


def _parts_apart(parts):
    """Whether the slips of a multi-part answer can be told apart, number by number.

    Real parts as :func:`~course_lib.exercises.core.parts_separated` has it; a whole-number part
    (its expected value an ``int``: a count, compared exactly) only needs slips that differ
    from each other, since any other whole number is a different answer.

    Examples
    --------
    >>> _parts_apart([("n", 127, [Mistake(126, "", "a"), Mistake(128, "", "b")])])
    True
    >>> _parts_apart([("n", 127, [Mistake(126, "", "a"), Mistake(126, "", "b")])])
    False
    """
    if not parts_separated([part for part in parts if not _is_count(part[1])]):
        return False
    for _, expected, mistakes in parts:
        if not _is_count(expected):
            continue
        live = [m for m in mistakes if float(m.value) != expected]
        for i, a in enumerate(live):
            if any(b.key != a.key and float(b.value) == float(a.value) for b in live[i + 1:]):
                return False
    return True


class _Parts(PartsAnswer, DrawnExercise):
    """An answer made of several numbers, each with slips of their own (see PartsAnswer); the
    parts that are counts (``int``) are whole numbers, compared exactly."""

    def separated(self, mistakes):
        self._parts = self.parts()
        return _parts_apart(self._parts)


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


# ---------------------------------------------------------------------------------------------
# Reflection and refraction
# ---------------------------------------------------------------------------------------------

class ReflectedRay(DrawnExercise):
    r"""The mirror direction :math:`r = d - 2 (d \cdot \hat n)\, \hat n` of an incoming ray.

    The normal has whole-number components and is not of unit length.

    Attributes: ``d`` (the ray's direction, unit, towards the surface), ``n`` (the normal).

    Examples
    --------
    >>> ex = ReflectedRay(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> n = ex.n / np.linalg.norm(ex.n)
    >>> ex.check(2 * (n @ ex.d) * n - ex.d).diagnosis
    'Phong formula'
    >>> ex.check(ex.d + 2 * (n @ ex.d) * n).diagnosis
    'plus sign'
    """

    title = "The reflected ray"
    answer_form = "vector"
    what = "the reflected direction"
    advice = (r"Normalize the normal, then $r = d - 2 (d \cdot \hat n)\, \hat n$. Check: "
              r"$r \cdot \hat n = -d \cdot \hat n$ (it leaves at the angle it came in).")

    def draw(self, rng):
        self.n = pick(rng, ((0.0, 2.0, 0.0), (3.0, 4.0, 0.0), (1.0, 2.0, 2.0), (0.0, 0.0, 3.0),
                            (2.0, 3.0, 6.0)))
        self.n = np.array(self.n)[rng.permutation(3)] * rng.choice([-1.0, 1.0], 3) + 0.0
        self.d = _nice_unit(rng)
        if self.d @ self.n > 0:
            self.d = -self.d
        self.expected = rt.reflect_direction(self.d, self.n)

    def acceptable(self):
        return -0.95 < self.d @ self.n / np.linalg.norm(self.n) < -0.2

    def mistakes(self):
        d, N = self.d, self.n
        n = N / np.linalg.norm(N)
        k = float(d @ n)
        return [
            Mistake(2 * k * n - d, r"That is $2 (n \cdot d)\, n - d$, the Phong model's "
                    r"$R = 2 (N \cdot L) N - L$ with $d$ put in for $L$. But $L$ points *away* "
                    r"from the surface and $d$ *towards* it ($L = -d$): the formula for a ray is "
                    r"$r = d - 2 (d \cdot n)\, n$. Your vector points back into the surface.",
                    "Phong formula"),
            Mistake(d - 2 * float(d @ N) * N, r"The normal was not normalized: the term "
                    r"$2 (d \cdot n)\, n$ grows with $\lVert n \rVert^2$. Divide $n$ by its "
                    rf"length ({_num(np.linalg.norm(N))}) first.", "n not normalized"),
            Mistake(d - k * n, r"You subtracted the normal part of $d$ only once: that gives "
                    r"the ray sliding *along* the surface. Reflection reverses the normal part, "
                    r"so it is subtracted twice: $r = d - 2 (d \cdot n)\, n$.", "factor 2"),
            Mistake(d + 2 * k * n, r"You *added* $2 (d \cdot \hat n)\, \hat n$: since "
                    r"$d \cdot \hat n < 0$ that pushes the ray further into the mirror (its "
                    r"normal part is tripled instead of reversed). The term is subtracted: "
                    r"$r = d - 2 (d \cdot \hat n)\, \hat n$. Which way $\hat n$ points does not "
                    r"matter, it appears twice; the minus sign does.", "plus sign"),
        ]

    def statement(self):
        return (
            rf"A ray travels in the unit direction $d = {_vec(self.d)}$ and hits a mirror whose "
            rf"normal is $n = {_vec(self.n)}$ (not of unit length). In which direction does the "
            r"reflected ray leave?" "\n\n" + _VECTOR_3 + "\n\n" + data_note("d", "n"))

    def _unit_normal(self):
        length = math.sqrt(float(self.n @ self.n))
        n = self.n / length
        return length, n, float(self.d @ n)

    def hints(self):
        length, n, k = self._unit_normal()
        return [
            r"A mirror keeps the part of $d$ along the surface and reverses the part along the "
            r"normal: $r = d - 2 (d \cdot \hat n)\, \hat n$, with $\hat n$ of **unit** length.",
            rf"$\lVert n \rVert = {_num(length)}$, so $\hat n = {_frac(n)}$, and "
            rf"$d \cdot \hat n = {latex_fraction(k)}$ (negative: the ray travels towards the "
            r"surface).",
            rf"$2 (d \cdot \hat n)\, \hat n = {_frac(2 * k * n)}$: subtract it from $d$ (the "
            r"direction $\hat n$ points in does not matter, the minus sign does).",
        ]

    def worked(self):
        length, n, k = self._unit_normal()
        r = self.d - 2 * k * n
        return Worked([
            rf"Normalize the normal: $\lVert n \rVert = \sqrt{{{_num(self.n @ self.n)}}} = "
            rf"{_num(length)}$, $\hat n = n / {_num(length)} = {_frac(n)}$.",
            rf"The normal part of $d$: $d \cdot \hat n = {latex_fraction(k)}$, so "
            rf"$2 (d \cdot \hat n)\, \hat n = {latex_fraction(2 * k)} \cdot {_frac(n)} = "
            rf"{_frac(2 * k * n)}$.",
            rf"Reverse it: $r = d - 2 (d \cdot \hat n)\, \hat n = {_frac(self.d)} - "
            rf"{_frac(2 * k * n)} = {_frac(r)}$.",
            rf"Check: $r \cdot \hat n = {latex_fraction(r @ n)} = -(d \cdot \hat n)$ (it leaves "
            rf"at the angle it came in) and $\lVert r \rVert = {_num(np.linalg.norm(r))}$.",
        ], r)


#: Media by their refractive index.
_MEDIA = {1.0: "air", 1.2: "a plastic", 1.31: "ice", 1.33: "water", 1.36: "ethanol",
          1.46: "quartz glass", 1.47: "glycerol", 1.49: "acrylic", 1.5: "glass",
          1.52: "crown glass", 1.58: "polycarbonate", 1.62: "flint glass", 1.77: "sapphire",
          1.8: "a dense flint glass", 2.0: "a dense glass", 2.15: "cubic zirconia",
          2.42: "diamond", 2.65: "moissanite"}
#: The media light may be inside of, and outside of, for total internal reflection.
_DENSE = (1.31, 1.33, 1.36, 1.46, 1.47, 1.49, 1.5, 1.52, 1.58, 1.62, 1.77, 1.8, 2.0, 2.15,
          2.42, 2.65)
_OUTSIDE = (1.0, 1.33, 1.46, 1.5)


class RefractedRay(DrawnExercise):
    r"""The refracted direction by Snell's law, :math:`t = \eta d + (\eta c_1 - c_2)\, n`.

    :math:`\eta = \eta_1 / \eta_2`, :math:`c_1 = -d \cdot n`,
    :math:`c_2 = \sqrt{1 - \eta^2 (1 - c_1^2)}`; the surface is the plane :math:`y = 0` with
    normal :math:`(0, 1, 0)` and the ray comes from above at a multiple of 15 degrees.

    Attributes: ``d`` (unit), ``n``, ``eta1``, ``eta2``, ``angle`` (of incidence, degrees).

    Examples
    --------
    >>> ex = RefractedRay(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(rt.refract_direction(ex.d, ex.n, ex.eta2, ex.eta1)[0]).diagnosis
    'ratio upside down'
    """

    title = "The refracted ray (Snell's law)"
    answer_form = "vector"
    what = "the refracted direction"
    advice = (r"Snell: $\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2$. The refracted ray stays in "
              r"the plane of $d$ and $n$, on the other side of the surface, at the angle "
              r"$\theta_2$ from $-n$; or use $t = \eta\, d + (\eta c_1 - c_2)\, n$ with "
              r"$\eta = \eta_1/\eta_2$.")

    def draw(self, rng):
        self.eta1, self.eta2 = pick(rng, ((1.0, 1.5), (1.0, 1.33), (1.5, 1.0), (1.33, 1.0),
                                          (1.0, 2.0), (1.5, 1.2)))
        self.angle = float(pick(rng, (15, 30, 45, 60)))
        a = math.radians(self.angle)
        phi = float(pick(rng, (0, 90, 180, 270)))
        horizontal = np.array([math.cos(math.radians(phi)), 0.0, math.sin(math.radians(phi))])
        self.d = np.round(math.sin(a) * horizontal + [0.0, -math.cos(a), 0.0], 15) + 0.0
        self.n = np.array([0.0, 1.0, 0.0])
        t, self._tir = rt.refract_direction(self.d, self.n, self.eta1, self.eta2)
        self.expected = t

    def acceptable(self):
        return not bool(self._tir)

    def mistakes(self):
        d, n = self.d, self.n
        found = []
        upside, tir = rt.refract_direction(d, n, self.eta2, self.eta1)
        if not tir:
            found.append(Mistake(upside, r"The ratio of the indices is upside down: "
                                 r"$\eta = \eta_1 / \eta_2$, the index of the medium the ray "
                                 r"**comes from** over the one it enters. Going into a denser "
                                 r"medium the ray bends *towards* the normal.",
                                 "ratio upside down"))
        found += [
            Mistake(rt.reflect_direction(d, n), r"That is the reflected ray. The refracted ray "
                    r"goes *through* the surface (its $y$ component keeps the sign of $d$'s).",
                    "reflected"),
            Mistake(d, r"That is the incoming direction unchanged: it holds only when "
                    r"$\eta_1 = \eta_2$. Snell's law bends the ray: "
                    r"$\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2$.", "not bent"),
        ]
        return found

    def statement(self):
        m1, m2 = _MEDIA[self.eta1], _MEDIA[self.eta2]
        return (
            rf"A ray in {m1} ($\eta_1 = {_num(self.eta1)}$) travels in the unit direction "
            rf"$d = {_vec(self.d)}$ (at ${_num(self.angle)}^\circ$ from the normal) and hits the "
            rf"flat surface $y = 0$ of {m2} ($\eta_2 = {_num(self.eta2)}$); the surface normal "
            rf"is $n = {_vec(self.n)}$. Give the unit direction of the refracted ray." "\n\n"
            + _VECTOR_3 + "\n\n" + data_note("d", "n", "eta1", "eta2", "angle"))

    def _snell(self):
        """eta, c1 = cos(theta1), sin^2(theta2) and c2 = cos(theta2)."""
        eta = self.eta1 / self.eta2
        c1 = -float(self.d @ self.n)
        sin2 = eta * eta * (1 - c1 * c1)
        return eta, c1, sin2, math.sqrt(1 - sin2)

    def hints(self):
        eta, c1, sin2, c2 = self._snell()
        return [
            r"Snell's law, $\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2$, in vector form: "
            r"$t = \eta\, d + (\eta c_1 - c_2)\, n$ with $\eta = \eta_1 / \eta_2$, "
            r"$c_1 = -d \cdot n = \cos\theta_1$ and $c_2 = \cos\theta_2$.",
            rf"Here $\eta = {_num(self.eta1)} / {_num(self.eta2)} = {_num(eta, 4)}$ and "
            rf"$c_1 = -d \cdot n = {_num(c1, 4)}$ (the cosine of ${_num(self.angle)}^\circ$).",
            rf"$\sin^2\theta_2 = \eta^2 (1 - c_1^2) = {_num(sin2, 4)}$, so "
            rf"$c_2 = \sqrt{{1 - \sin^2\theta_2}} = {_num(c2, 4)}$; now put $\eta$, $c_1$ and "
            r"$c_2$ into $t = \eta\, d + (\eta c_1 - c_2)\, n$.",
        ]

    def worked(self):
        eta, c1, sin2, c2 = self._snell()
        k = eta * c1 - c2
        t = eta * self.d + k * self.n
        return Worked([
            rf"The ratio of the indices, from the ray's medium to the other one: "
            rf"$\eta = \eta_1 / \eta_2 = {_num(self.eta1)} / {_num(self.eta2)} = {_num(eta, 4)}$; "
            rf"the cosine of incidence $c_1 = -d \cdot n = {_num(c1, 4)}$.",
            rf"Snell: $\sin^2\theta_2 = \eta^2 (1 - c_1^2) = {_num(eta * eta, 4)} \cdot "
            rf"{_num(1 - c1 * c1, 4)} = {_num(sin2, 4)}$ (below 1: no total internal "
            rf"reflection), $c_2 = \sqrt{{1 - {_num(sin2, 4)}}} = {_num(c2, 4)}$; "
            rf"$\theta_2 = {_num(math.degrees(math.acos(c2)), 2)}^\circ$.",
            rf"$t = \eta\, d + (\eta c_1 - c_2)\, n = {_num(eta, 4)} \cdot {_vec(self.d, 4)} "
            rf"+ ({_num(k, 4)}) \cdot {_vec(self.n)} = {_vec(t, 4)}$, a unit vector that goes on "
            r"into the second medium ($t_y < 0$).",
        ], t)


class CriticalAngle(DrawnExercise):
    r"""The critical angle :math:`\theta_c = \arcsin(\eta_2 / \eta_1)` of total internal
    reflection.

    Attributes: ``eta1`` (inside, the denser medium), ``eta2`` (outside).

    Examples
    --------
    >>> ex = CriticalAngle(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(math.degrees(math.atan(ex.eta2 / ex.eta1))).diagnosis
    'Brewster'
    """

    title = "The critical angle"
    answer_form = "number"
    what = "the critical angle"
    advice = (r"At the critical angle the refracted ray grazes the surface, "
              r"$\theta_2 = 90^\circ$: $\eta_1 \sin\theta_c = \eta_2$.")

    def draw(self, rng):
        self.eta2 = float(pick(rng, _OUTSIDE))
        self.eta1 = float(pick(rng, tuple(e for e in _DENSE if self.eta2 / e <= 0.95)))
        self.expected = math.degrees(math.asin(self.eta2 / self.eta1))

    def mistakes(self):
        ratio = self.eta2 / self.eta1
        return [
            Mistake(math.degrees(math.acos(ratio)), r"That is $\arccos(\eta_2/\eta_1)$, the "
                    r"angle measured from the *surface*. Angles of incidence are measured from "
                    r"the normal: $\sin\theta_c = \eta_2/\eta_1$.", "arccos"),
            Mistake(math.degrees(math.atan(ratio)), r"That is Brewster's angle, "
                    r"$\arctan(\eta_2/\eta_1)$, where reflected light is fully polarized. Total "
                    r"internal reflection starts where Snell's law asks for "
                    r"$\sin\theta_2 > 1$: $\sin\theta_c = \eta_2/\eta_1$.", "Brewster"),
            Mistake(math.asin(ratio), r"That is the angle in radians; the question asks for "
                    r"degrees.", "radians"),
        ]

    def statement(self):
        m1, m2 = _MEDIA[self.eta1], _MEDIA[self.eta2]
        return (
            rf"Light travels inside {m1} ($\eta_1 = {_num(self.eta1)}$) towards its boundary "
            rf"with {m2} ($\eta_2 = {_num(self.eta2)}$). Beyond which angle of incidence "
            r"(measured from the normal) is it totally reflected?" "\n\n"
            r"**Answer:** the angle in degrees. " + DECIMALS + "\n\n"
            + data_note("eta1", "eta2"))

    def hints(self):
        ratio = self.eta2 / self.eta1
        return [
            r"At the critical angle the refracted ray just grazes the surface: put "
            r"$\theta_2 = 90^\circ$ into Snell's law $\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2$.",
            rf"With $\sin 90^\circ = 1$: $\sin\theta_c = \eta_2 / \eta_1 = {_num(self.eta2)} / "
            rf"{_num(self.eta1)} = {_num(ratio, 4)}$.",
            rf"$\arcsin({_num(ratio, 4)}) = {_num(math.asin(ratio), 4)}$ rad; the answer is asked "
            r"in degrees (multiply by $180/\pi$).",
        ]

    def worked(self):
        ratio = self.eta2 / self.eta1
        radians = math.asin(ratio)
        degrees = radians * 180 / math.pi
        return Worked([
            r"Beyond the critical angle Snell's law has no solution; at the critical angle "
            r"the refracted ray runs along the surface, $\theta_2 = 90^\circ$: "
            r"$\eta_1 \sin\theta_c = \eta_2 \sin 90^\circ = \eta_2$.",
            rf"$\sin\theta_c = \eta_2 / \eta_1 = {_num(self.eta2)} / {_num(self.eta1)} = "
            rf"{_num(ratio, 4)}$.",
            rf"$\theta_c = \arcsin({_num(ratio, 4)}) = {_num(radians, 4)}$ rad $= "
            rf"{_num(radians, 4)} \cdot 180^\circ / \pi = {_num(degrees, 2)}^\circ$.",
        ], degrees)


_SCHLICK_INDICES = (1.33, 1.46, 1.5, 1.62, 1.77, 2.0, 2.15, 2.42, 2.65)


class SchlickReflectance(DrawnExercise):
    r"""Schlick's approximation :math:`F = R_0 + (1 - R_0)(1 - \cos\theta)^5` for a ray from air.

    Attributes: ``eta1`` (1, air), ``eta2``, ``angle`` (of incidence, whole degrees).

    Examples
    --------
    >>> ex = SchlickReflectance(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(((ex.eta1 - ex.eta2) / (ex.eta1 + ex.eta2)) ** 2).diagnosis
    'R0 only'
    >>> r0 = ((ex.eta1 - ex.eta2) / (ex.eta1 + ex.eta2)) ** 2
    >>> ex.check(r0 + (1 - r0) * (1 - math.cos(ex.angle)) ** 5).diagnosis  # angle in radians
    'degrees'
    """

    title = "Fresnel reflectance by Schlick's approximation"
    answer_form = "number"
    what = "the reflectance F"
    advice = (r"$R_0 = \left(\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}\right)^2$ is the reflectance "
              r"head on; $F = R_0 + (1 - R_0)(1 - \cos\theta)^5$ with $\theta$ the angle of "
              r"incidence.")

    def draw(self, rng):
        self.eta1 = 1.0
        self.eta2 = float(pick(rng, _SCHLICK_INDICES))
        self.angle = float(rng.integers(64, 90))
        self.expected = float(rt.schlick(math.cos(math.radians(self.angle)), self.eta1,
                                         self.eta2))

    def mistakes(self):
        e1, e2 = self.eta1, self.eta2
        r0 = ((e1 - e2) / (e1 + e2)) ** 2
        c = math.cos(math.radians(self.angle))
        root = abs(e1 - e2) / (e1 + e2)
        as_radians = math.cos(self.angle)
        found = [
            Mistake(root + (1 - root) * (1 - c) ** 5,
                    r"$R_0$ is the *square* of $\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}$ "
                    r"(4 % for glass, not 20 %).", "R0 not squared"),
            Mistake(r0, r"That is $R_0$, the reflectance head on (using $\sin\theta$ instead of "
                    r"$\cos\theta$ in the formula, or the cosine of the angle's number taken as "
                    r"radians, gives nearly the same). At "
                    rf"${_num(self.angle)}^\circ$ much more light is reflected: add "
                    r"$(1 - R_0)(1 - \cos\theta)^5$.", "R0 only"),
        ]
        # np.cos of the degrees: distinct from the others for most angles; near a whole number
        # of turns (cos ~ 1) it gives about R0, which "R0 only" then explains
        in_radians = Mistake(r0 + (1 - r0) * (1 - as_radians) ** 5, rf"You took the cosine of "
                             rf"${_num(self.angle)}$ **radians**: `np.cos({_num(self.angle)})` = "
                             rf"${_num(as_radians, 4)}$, but $\cos {_num(self.angle)}^\circ = "
                             rf"{_num(c, 4)}$. numpy's (and `math`'s) trigonometric functions "
                             rf"take radians: convert first, "
                             rf"`np.cos(np.radians({_num(self.angle)}))`. "
                             r"(A reflectance is never outside $[0, 1]$.)", "degrees")
        if well_separated(self.expected, found + [in_radians]):
            found.append(in_radians)
        forgot = r0 + (1 - c) ** 5
        if abs(forgot - self.expected) >= APART - SAME:    # R0 (1 - c)^5 is small for low R0
            found.append(Mistake(forgot, r"The factor $(1 - R_0)$ is missing: "
                                 r"$F = R_0 + (1 - R_0)(1 - \cos\theta)^5$, so that $F = 1$ "
                                 r"at grazing incidence.", "no (1 - R0)"))
        return found

    def statement(self):
        return (
            rf"A ray in air ($\eta_1 = 1$) hits a flat surface of {_MEDIA[self.eta2]} (refractive "
            rf"index $\eta_2 = {_num(self.eta2)}$) at ${_num(self.angle)}^\circ$ from the normal. "
            r"What fraction of the light is reflected, by Schlick's approximation?" "\n\n"
            + _ONE_NUMBER + "\n\n" + data_note("eta1", "eta2", "angle"))

    def _terms(self):
        quotient = (self.eta1 - self.eta2) / (self.eta1 + self.eta2)
        c = math.cos(self.angle * math.pi / 180)
        return quotient, quotient ** 2, c, (1 - c) ** 5

    def hints(self):
        quotient, r0, c, grazing = self._terms()
        return [
            r"Schlick: $F = R_0 + (1 - R_0)(1 - \cos\theta)^5$, where "
            r"$R_0 = \left(\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}\right)^2$ is the reflectance "
            r"head on and $\theta$ the angle of incidence.",
            rf"$R_0 = \left(\frac{{1 - {_num(self.eta2)}}}{{1 + {_num(self.eta2)}}}\right)^2 = "
            rf"({_num(quotient, 4)})^2 = {_num(r0, 4)}$.",
            rf"$\cos {_num(self.angle)}^\circ = {_num(c, 4)}$ (in numpy: "
            rf"`np.cos(np.radians({_num(self.angle)}))`), so $(1 - \cos\theta)^5 = "
            rf"{_num(grazing, 4)}$.",
        ]

    def worked(self):
        quotient, r0, c, grazing = self._terms()
        f = r0 + (1 - r0) * grazing
        return Worked([
            rf"Head on: $R_0 = \left(\frac{{\eta_1 - \eta_2}}{{\eta_1 + \eta_2}}\right)^2 = "
            rf"\left(\frac{{{_num(self.eta1 - self.eta2)}}}{{{_num(self.eta1 + self.eta2)}}}"
            rf"\right)^2 = ({_num(quotient, 4)})^2 = {_num(r0, 4)}$.",
            rf"The angle: $\cos {_num(self.angle)}^\circ = {_num(c, 4)}$ (degrees: "
            rf"`np.cos(np.radians({_num(self.angle)}))`), $1 - \cos\theta = {_num(1 - c, 4)}$, "
            rf"$(1 - \cos\theta)^5 = {_num(grazing, 4)}$.",
            rf"$F = R_0 + (1 - R_0)(1 - \cos\theta)^5 = {_num(r0, 4)} + {_num(1 - r0, 4)} \cdot "
            rf"{_num(grazing, 4)} = {_num(f, 4)}$: at this flat angle about "
            rf"{_num(100 * f, 0)} % of the light is reflected, against {_num(100 * r0, 1)} % "
            r"head on.",
        ], f)


# ---------------------------------------------------------------------------------------------
# The ray tracer: shadows, recursion, ray trees, acceleration
# ---------------------------------------------------------------------------------------------

class ShadowRay(DrawnExercise):
    r"""A point on the floor, a point light and a ball that may be in the way: the intensity.

    The shadow ray from the point towards the light is blocked when it hits the ball before the
    light. Lit: :math:`I = k_a + k_d \max(N \cdot L, 0)` (a matte floor, :math:`I_a = I_l = 1`);
    in shadow only :math:`k_a` is left.

    Attributes: ``P`` (the point, on the floor :math:`y = 0`), ``light`` (its position),
    ``center``, ``radius`` (the ball), ``ka``, ``kd``; ``blocked`` (for the solutions).

    Examples
    --------
    >>> ex = ShadowRay(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(0.0).diagnosis
    'no ambient'
    """

    title = "A shadow ray"
    answer_form = "number"
    what = "the intensity"
    advice = (r"Cast the shadow ray $P + t\,L$ towards the light; if it hits the ball for a $t$ "
              r"between 0 and the distance to the light, only the ambient term $k_a$ is left. "
              r"Otherwise $I = k_a + k_d\, (N \cdot L)$ with $L$ normalized.")

    def draw(self, rng):
        self.P = np.array([float(rng.integers(-2, 3)), 0.0, float(rng.integers(-2, 3))])
        self.light = np.array([float(rng.integers(-3, 4)), float(rng.integers(3, 7)),
                               float(rng.integers(-3, 4))])
        s = float(pick(rng, (0.4, 0.5, 0.6)))
        off = np.zeros(3)
        if rng.random() < 0.5:
            off = rng.integers(-2, 3, size=3).astype(float)
        self.center = np.round(self.P + s * (self.light - self.P)) + off
        self.radius = float(pick(rng, (0.5, 1.0, 1.5)))
        self.ka = float(pick(rng, (0.1, 0.2)))
        self.kd = float(pick(rng, (0.5, 0.6, 0.7, 0.8)))
        to_light = self.light - self.P
        dist = float(np.linalg.norm(to_light))
        hit = rt.intersect_sphere(self.P, to_light / dist, self.center, self.radius)
        self.blocked = bool(float(hit.t) <= dist)
        self._cos = to_light[1] / dist
        self.expected = self.ka + (0.0 if self.blocked else self.kd * self._cos)

    def acceptable(self):
        gap_to_sphere = np.linalg.norm(self.P - self.center) - self.radius
        light_gap = np.linalg.norm(self.light - self.center) - self.radius
        if self.center[1] - self.radius < 0.5 or gap_to_sphere < 0.5 or light_gap < 0.5:
            return False
        # not a grazing case: the ray misses by a clear margin or passes well inside
        to_light = (self.light - self.P) / np.linalg.norm(self.light - self.P)
        f = self.center - self.P
        miss_distance = np.linalg.norm(f - (f @ to_light) * to_light)
        return abs(miss_distance - self.radius) > 0.3

    def mistakes(self):
        lit = self.ka + self.kd * self._cos
        unlit = (r"The ball is in the way: the shadow ray hits it before it reaches the light, "
                 r"so this light adds neither diffuse nor specular light. Only the ambient term "
                 r"$k_a$ is left.")
        found = [
            Mistake(0.0, r"A point in shadow is not black: the ambient term $k_a$ (light "
                    r"arriving indirectly) stays.", "no ambient"),
            Mistake(self.ka + self.kd * self._cos * np.linalg.norm(self.light - self.P),
                    r"$L$ was not normalized: $N \cdot L$ is a cosine only for unit vectors.",
                    "L not normalized"),
        ]
        if self.blocked:
            found.append(Mistake(lit, unlit, "ignored the shadow"))
        else:
            found.append(Mistake(self.ka, r"The shadow ray misses the ball (check the "
                                 r"discriminant, or the distance from the ball's centre to the "
                                 r"ray): the point is lit, $I = k_a + k_d\, (N \cdot L)$.",
                                 "false shadow"))
        return found

    def statement(self):
        return (
            rf"A matte floor (the plane $y = 0$, normal $(0, 1, 0)$, $k_a = {_num(self.ka)}$, "
            rf"$k_d = {_num(self.kd)}$, no specular term) is lit by a point light of intensity "
            rf"1 at ${_vec(self.light)}$ (ambient intensity $I_a = 1$). A ball of radius "
            rf"${_num(self.radius)}$ hangs at ${_vec(self.center)}$. What intensity does the "
            rf"ray tracer give the floor point $P = {_vec(self.P)}$? (Decide with a shadow ray "
            r"whether the ball blocks the light.)" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("P", "light", "center", "radius", "ka", "kd"))

    def _shadow(self):
        """L, its length, the unit L, and the shadow ray's quadratic: f, b, c', discriminant."""
        L = self.light - self.P
        dist = math.sqrt(float(L @ L))
        unit = L / dist
        f = self.P - self.center
        b = 2 * float(unit @ f)
        c2 = float(f @ f) - self.radius ** 2
        return L, dist, unit, f, b, c2, b * b - 4 * c2

    def hints(self):
        L, dist, unit, f, b, c2, disc = self._shadow()
        return [
            r"Cast a shadow ray from $P$ towards the light. If it hits the ball before it "
            r"reaches the light, only the ambient term $k_a$ is left; otherwise "
            r"$I = k_a + k_d\, (N \cdot L)$ with $L$ the **unit** vector towards the light.",
            rf"$L = \text{{light}} - P = {_vec(L)}$, of length ${_num(dist, 4)}$, so "
            rf"$\hat L = {_vec(unit, 4)}$ and $N \cdot \hat L = {_num(unit[1], 4)}$.",
            rf"The shadow ray $P + t\,\hat L$ against the ball: with $f = P - c = {_vec(f)}$, "
            rf"$b = 2\, \hat L \cdot f = {_num(b, 4)}$ and $c' = f \cdot f - r^2 = {_num(c2, 4)}$ "
            rf"the discriminant $b^2 - 4c'$ is ${_num(disc, 4)}$"
            + (r": negative, so the ray misses the ball." if disc < 0 else
               r": positive, so the ray's line meets the ball; check whether the roots lie "
               rf"between 0 and ${_num(dist, 4)}$."),
        ]

    def worked(self):
        L, dist, unit, f, b, c2, disc = self._shadow()
        cos = float(unit[1])
        steps = [
            rf"Towards the light: $L = {_vec(self.light)} - {_vec(self.P)} = {_vec(L)}$, "
            rf"$\lVert L \rVert = {_num(dist, 4)}$, $\hat L = {_vec(unit, 4)}$; with "
            rf"$N = (0, 1, 0)$, $N \cdot \hat L = {_num(cos, 4)}$.",
            rf"Shadow ray $P + t\,\hat L$ ($\hat L$ is a unit vector, so $a = 1$) against the "
            rf"ball: $f = P - c = {_vec(f)}$, $b = 2\, \hat L \cdot f = {_num(b, 4)}$, "
            rf"$c' = f \cdot f - r^2 = {_num(c2, 4)}$, discriminant "
            rf"$b^2 - 4c' = {_num(disc, 4)}$.",
        ]
        blocked = False
        if disc < 0:
            steps.append(r"The discriminant is negative: the shadow ray misses the ball, and "
                         r"the point is lit.")
        else:
            t1, t2 = (-b - math.sqrt(disc)) / 2, (-b + math.sqrt(disc)) / 2
            blocked = 0 < t1 < dist
            where = (rf"$0 < t_1 < {_num(dist, 4)}$: the ball is between the point and the "
                     r"light, the point is in shadow." if blocked else
                     r"both roots are negative: the ball is behind the point, which is lit."
                     if t2 < 0 else
                     rf"$t_1 > {_num(dist, 4)}$: the ball lies beyond the light, the point is "
                     r"lit.")
            steps.append(rf"Roots $t_1 = {_num(t1, 4)}$, $t_2 = {_num(t2, 4)}$; " + where)
        if blocked:
            intensity = self.ka
            steps.append(rf"In shadow only the ambient term is left: $I = k_a = "
                         rf"{_num(intensity)}$.")
        else:
            intensity = self.ka + self.kd * cos
            steps.append(rf"Lit: $I = k_a + k_d\, (N \cdot \hat L) = {_num(self.ka)} + "
                         rf"{_num(self.kd)} \cdot {_num(cos, 4)} = {_num(intensity, 4)}$.")
        return Worked(steps, intensity)


class MirrorChainColour(DrawnExercise):
    r"""The pixel intensity of a primary ray and its reflections, down to a depth limit.

    :math:`I = I_0 + k_{r,0} (I_1 + k_{r,1} (I_2 + \dots))`: every bounce's local intensity is
    weighted by the product of the reflectivities on the way; the recursion stops after
    ``depth`` reflections.

    Attributes: ``local`` (the local intensities :math:`I_0, I_1, \dots` of the surfaces the ray
    meets in turn), ``kr`` (their reflectivities), ``depth``.

    Examples
    --------
    >>> ex = MirrorChainColour(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(sum(ex.local[:ex.depth + 1])).diagnosis
    'no weights'
    """

    title = "The colour of a chain of reflections"
    answer_form = "number"
    what = "the pixel intensity"
    advice = (r"Work from the deepest ray back: $I_k = I_{local,k} + k_{r,k}\, I_{k+1}$, with "
              r"nothing beyond the depth limit.")

    def draw(self, rng):
        n = 4
        self.local = np.array([float(pick(rng, (0.1, 0.2, 0.3, 0.4, 0.5, 0.6))) for _ in range(n)])
        self.kr = np.array([float(pick(rng, (0.2, 0.25, 0.5, 0.75, 0.8))) for _ in range(n)])
        self.depth = int(pick(rng, (1, 2)))
        self.expected = self._total(self.depth, multiply=True)

    def _total(self, depth, multiply=True):
        total, weight = 0.0, 1.0
        for k in range(depth + 1):
            total += weight * self.local[k]
            weight = weight * self.kr[k] if multiply else self.kr[k]
        return total

    def mistakes(self):
        return [
            Mistake(sum(self.local[:self.depth + 1]), r"Every reflected intensity must be "
                    r"weighted by the reflectivities of the mirrors it came through: "
                    r"$I_0 + k_{r,0} I_1 + k_{r,0} k_{r,1} I_2 + \dots$", "no weights"),
            Mistake(self._total(self.depth, multiply=False), r"The weights multiply along the "
                    r"path: light seen after two bounces is weakened by *both* mirrors, "
                    r"$k_{r,0} k_{r,1}$, not only by the last one.", "weights not multiplied"),
            Mistake(self._total(self.depth + 1), r"You traced one reflection too many. With "
                    r"depth limit $d$ the primary ray and $d$ reflected rays are traced; the "
                    r"next one is not.", "one too deep"),
            Mistake(self._total(self.depth - 1), r"One reflection is missing: with depth limit "
                    r"$d$ the primary ray is followed by $d$ reflected rays.", "one too shallow"),
        ]

    def statement(self):
        rows = " | ".join(["surface"] + [str(k) for k in range(len(self.local))])
        return (
            r"A primary ray hits surface 0; its reflected ray hits surface 1, whose reflected "
            r"ray hits surface 2, and so on. The local (Phong) intensity $I_k$ at each hit and "
            r"the reflectivity $k_{r,k}$ of each surface are:" "\n\n"
            f"| {rows} |\n|" + "---|" * (len(self.local) + 1) + "\n"
            "| $I_k$ | " + " | ".join(_num(x) for x in self.local) + " |\n"
            "| $k_{r,k}$ | " + " | ".join(_num(x) for x in self.kr) + " |\n\n"
            rf"The ray tracer's recursion depth limit is {self.depth} (the primary ray and at "
            rf"most {self.depth} reflected rays). What intensity does the pixel get? (No "
            r"refraction, no clamping.)" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("local", "kr", "depth"))

    def _backwards(self):
        """The intensities I_k seen along ray k, from the deepest traced ray back to the pixel."""
        seen = {self.depth: float(self.local[self.depth])}
        for k in range(self.depth - 1, -1, -1):
            seen[k] = float(self.local[k]) + float(self.kr[k]) * seen[k + 1]
        return seen

    def hints(self):
        d = self.depth
        seen = self._backwards()
        return [
            r"Each hit returns its local intensity plus its reflectivity times what the "
            r"reflected ray brings back: $I_k = I_{local,k} + k_{r,k}\, I_{k+1}$. Work from the "
            r"deepest ray back to the pixel.",
            rf"With depth limit {d} the rays to surfaces 0 to {d} are traced; the ray to "
            rf"surface {d} is the last, so it brings back only its local intensity, "
            rf"${_num(self.local[d])}$ (surface {d + 1} is never reached).",
            rf"One level up: $I_{{{d - 1}}} = {_num(self.local[d - 1])} + "
            rf"{_num(self.kr[d - 1])} \cdot {_num(self.local[d])} = {_num(seen[d - 1], 4)}$"
            + (r"; one more level gives the pixel." if d > 1 else r": that is the pixel."),
        ]

    def worked(self):
        d = self.depth
        seen = self._backwards()
        reflected = ("1 reflected ray (to surface 1)" if d == 1 else
                     f"{d} reflected rays (to surfaces 1 to {d})")
        steps = [rf"The depth limit {d} means the primary ray (to surface 0) and {reflected} "
                 rf"are traced. The deepest one brings back its local intensity only: "
                 rf"$I_{d} = {_num(self.local[d])}$."]
        for k in range(d - 1, -1, -1):
            steps.append(rf"$I_{k} = I_{{local,{k}}} + k_{{r,{k}}}\, I_{k + 1} = "
                         rf"{_num(self.local[k])} + {_num(self.kr[k])} \cdot "
                         rf"{_num(seen[k + 1], 4)} = {_num(seen[k], 4)}$.")
        steps.append(rf"The pixel gets $I_0 = {_num(seen[0], 4)}$ (the reflectivity "
                     rf"$k_{{r,{d}}}$ of the last surface is never used: nothing is traced beyond "
                     r"it).")
        return Worked(steps, seen[0])


class RayTreeCount(_Parts):
    r"""How many rays the ray tree of one pixel holds, with and without transparency.

    Every ray hits a surface that is reflective (and, in the glass variant, transparent too):
    a mirror scene gives a chain of :math:`d + 1` rays, a glass scene a full binary tree of
    :math:`2^{d+1} - 1` rays; each hit casts one shadow ray per light. Both counts are whole
    numbers, compared exactly.

    Attributes: ``depth``, ``lights``, ``glass`` (True: every surface reflects and refracts).

    Examples
    --------
    >>> ex = RayTreeCount(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> rays, shadows = ex.expected
    >>> ex.check([rays - 1, shadows]).diagnosis
    'primary forgotten'
    >>> ex.check([float(rays), float(shadows)]).status, ex.check([rays, shadows + 1]).status
    ('correct', 'wrong')
    """

    title = "Counting the rays of a ray tree"
    form_hint = r"`[reflected/refracted/primary rays, shadow rays]`."
    advice = (r"Draw the tree: the primary ray at level 0; every ray of level $k < d$ has one "
              r"child (mirror) or two (glass: reflected and refracted). Every node is a hit, and "
              r"every hit casts one shadow ray per light.")

    def draw(self, rng):
        self.depth = int(pick(rng, (2, 3, 4, 5, 6)))
        self.lights = int(pick(rng, (1, 2, 3, 4)))
        self.glass = bool(rng.random() < 0.5)
        nodes = 2 ** (self.depth + 1) - 1 if self.glass else self.depth + 1
        self.expected = np.array([nodes, nodes * self.lights])

    def parts(self):
        d, k = self.depth, self.lights
        nodes = int(self.expected[0])
        primary = (r"The primary ray counts too: it is the root of the tree.")
        found_rays = [Mistake(nodes - 1, primary, "primary forgotten")]
        if self.glass:
            found_rays += [
                Mistake(2 ** d, r"That is only the last level ($2^d$ rays). The tree holds "
                        r"every level $0, \dots, d$: $1 + 2 + \dots + 2^d = 2^{d+1} - 1$.",
                        "last level only"),
                Mistake(d + 1, r"Each hit on glass spawns *two* rays, a reflected and a "
                        r"refracted one: the tree doubles at every level.", "chain"),
            ]
        else:
            found_rays.append(Mistake(2 ** (d + 1) - 1, r"A mirror that is not transparent "
                                      r"spawns only a reflected ray: the tree is a chain.",
                                      "binary tree"))
        return [
            ("the traced rays", nodes, found_rays),
            ("the shadow rays", nodes * k, [
                Mistake(k, r"Every hit casts shadow rays, not only the primary one: "
                        r"one per light at every node of the tree.", "shadows of primary only"),
                Mistake(nodes, r"One shadow ray per hit *and per light*.", "one per hit"),
            ]),
        ]

    def statement(self):
        scene = ("every surface is glass that both reflects and refracts (so every hit spawns a "
                 "reflected and a refracted ray)" if self.glass else
                 "every surface is an opaque mirror (every hit spawns a reflected ray)")
        return (
            rf"In a closed room {scene}, and every ray hits some surface. The scene has "
            rf"{self.lights} point light{'s' if self.lights > 1 else ''}, and every hit casts "
            rf"one shadow ray per light. The recursion depth limit is {self.depth} (the primary "
            r"ray is at depth 0). For one pixel, how many primary, reflected and refracted rays "
            r"are traced together, and how many shadow rays?" "\n\n"
            r"**Answer:** a list of 2 whole numbers `[traced rays, shadow rays]`." "\n\n"
            + data_note("depth", "lights", "glass"))

    def _levels(self):
        """How many rays each level 0..depth of the tree holds."""
        return [2 ** level if self.glass else 1 for level in range(self.depth + 1)]

    def hints(self):
        levels = self._levels()
        kind = ("two children (a reflected and a refracted ray)" if self.glass else
                "one child (its reflected ray)")
        return [
            r"Draw the ray tree: the primary ray is the root (depth 0), every ray that hits "
            r"a surface below the depth limit spawns new rays, and every node is one hit.",
            rf"Here every ray of depth below {self.depth} has {kind}, so the levels "
            rf"$0, 1, \dots, {self.depth}$ hold " + ", ".join(str(n) for n in levels[:3])
            + r", $\dots$ rays.",
            rf"Add the levels up ({' + '.join(str(n) for n in levels)}); then each of those hits "
            rf"casts {self.lights} shadow ray{'s' if self.lights > 1 else ''}, one per light.",
        ]

    def worked(self):
        levels = self._levels()
        rays = sum(levels)
        shadows = rays * self.lights
        spawn = ("a reflected and a refracted ray, so level $k$ holds $2^k$ rays" if self.glass
                 else "only a reflected ray, so every level holds one ray")
        return Worked([
            rf"The tree has the levels $0$ (the primary ray) to {self.depth} (the depth limit). "
            rf"Every hit spawns {spawn}: " + ", ".join(
                f"level {k}: {n}" for k, n in enumerate(levels)) + ".",
            rf"Traced rays: ${' + '.join(str(n) for n in levels)} = {rays}"
            + (rf" = 2^{{{self.depth + 1}}} - 1$." if self.glass else "$."),
            rf"Every one of the {rays} hits casts one shadow ray per light: "
            rf"${rays} \cdot {self.lights} = {shadows}$ shadow rays.",
        ], [rays, shadows])


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


EXERCISES = (
    RaySphereHit,
    RayTriangleHit,
    ReflectedRay,
    RefractedRay,
    CriticalAngle,
    SchlickReflectance,
    ShadowRay,
    MirrorChainColour,
    RayTreeCount,
    BVHSavings,
)
