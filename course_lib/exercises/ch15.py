r"""Chapter 15 exercises: ray tracing, exam style.

Each class is one kind of exam question: where a ray first hits a sphere; where it hits a
triangle (the ray parameter and the barycentric coordinates, as in Möller-Trumbore); the mirror
direction of an incoming ray; the refracted direction by Snell's law; the critical angle of total
internal reflection; Schlick's Fresnel reflectance; whether a shadow ray is blocked and what the
point's intensity is then; the colour a chain of mirror bounces gives a pixel; how many rays a
pixel's ray tree holds; and what a bounding volume hierarchy saves. The ``seed`` draws numbers
that work out by hand: whole-number points, unit vectors with rational components such as
:math:`(\tfrac23, \tfrac23, \tfrac13)` or :math:`(0.6, 0.8, 0)`, barycentric coordinates in
quarters, angles that are multiples of 15 degrees.

The expected answers come from :mod:`course_lib.raytracing`. Each exercise names the slips it
anticipates (the far root of the quadratic, a direction taken as a unit vector when it is not,
:math:`u` and :math:`v` swapped, the Phong-model reflection formula applied to an incoming ray,
the ratio of refractive indices upside down, Brewster's angle for the critical angle, the
weights of a ray tree added instead of multiplied, the primary ray forgotten in a count, ...),
computes the answer each slip would give, and draws its numbers again until those answers differ
clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.raytracing`): a ray is :math:`o + t\,d`; :math:`d` is the
direction the ray *travels* (towards the surface), so the mirror direction is
:math:`r = d - 2 (d \cdot n)\, n`; refractive indices :math:`\eta_1` (the medium the ray comes
from) and :math:`\eta_2`; a triangle point is :math:`(1 - u - v)\, v_0 + u\, v_1 + v\, v_2`.
"""
import math

import numpy as np

from .. import format as fmt
from .. import raytracing as rt
from .core import (APART, DECIMALS, SAME, DrawnExercise, Mistake, PartsAnswer, data_note, pick)

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

#: Unit vectors with rational components (before permuting the axes and choosing signs).
_NICE_UNITS = ((1.0, 0.0, 0.0), (0.6, 0.8, 0.0), (2 / 3, 2 / 3, 1 / 3), (2 / 7, 3 / 7, 6 / 7))

_POINT_3 = "**Answer:** the point as a list of 3 numbers `[x, y, z]`. " + DECIMALS
_VECTOR_3 = "**Answer:** the vector as a list of 3 numbers `[x, y, z]`. " + DECIMALS
_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


def _nice_unit(rng):
    v = np.array(pick(rng, _NICE_UNITS))[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0


class _Parts(PartsAnswer, DrawnExercise):
    """An answer made of several numbers, each with slips of its own (see PartsAnswer)."""


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


class RayTriangleHit(_Parts):
    r"""Where a ray hits a triangle: the ray parameter and the barycentric coordinates.

    Solve :math:`o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)` (three equations, three
    unknowns; Möller-Trumbore solves it by Cramer's rule); the ray hits when :math:`u, v \ge 0`,
    :math:`u + v \le 1` and :math:`t > 0`.

    Attributes: ``o``, ``d``, ``V`` (the vertices :math:`v_0, v_1, v_2`, one per row).

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
        u, v = pick(rng, ((0.5, 0.25), (0.25, 0.5), (0.25, 0.75), (0.75, 0.25), (0.5, 0.0),
                          (0.0, 0.5), (0.125, 0.5), (0.5, 0.125)))
        point = (1 - u - v) * V[0] + u * V[1] + v * V[2]
        self.d = rng.integers(-2, 3, size=3).astype(float)
        t = float(pick(rng, (1.0, 2.0, 3.0)))
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
            r"+ v\, v_2$. Find $t$, $u$ and $v$." "\n\n"
            r"**Answer:** a list of 3 numbers `[t, u, v]`. " + DECIMALS + "\n\n"
            + data_note("o", "d", "V"))


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
        ]

    def statement(self):
        return (
            rf"A ray travels in the unit direction $d = {_vec(self.d)}$ and hits a mirror whose "
            rf"normal is $n = {_vec(self.n)}$ (not of unit length). In which direction does the "
            r"reflected ray leave?" "\n\n" + _VECTOR_3 + "\n\n" + data_note("d", "n"))


_MEDIA = {1.0: "air", 1.5: "glass", 1.33: "water", 2.0: "a dense glass", 1.2: "a plastic"}


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
    advice = (r"Snell: $\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2$. The refracted ray stays in the "
            r"plane of $d$ and $n$, on the other side of the surface, at the angle $\theta_2$ "
            r"from $-n$; or use $t = \eta\, d + (\eta c_1 - c_2)\, n$ with "
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


class CriticalAngle(DrawnExercise):
    r"""The critical angle :math:`\theta_c = \arcsin(\eta_2 / \eta_1)` of total internal reflection.

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
    advice = (r"At the critical angle the refracted ray grazes the surface, $\theta_2 = 90^\circ$: "
            r"$\eta_1 \sin\theta_c = \eta_2$.")

    def draw(self, rng):
        self.eta1, self.eta2 = pick(rng, ((1.5, 1.0), (1.33, 1.0), (2.42, 1.0), (1.5, 1.33),
                                          (2.0, 1.0), (1.8, 1.5)))
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
        m1, m2 = _MEDIA.get(self.eta1, "a dense crystal"), _MEDIA[self.eta2]
        return (
            rf"Light travels inside {m1} ($\eta_1 = {_num(self.eta1)}$) towards its boundary "
            rf"with {m2} ($\eta_2 = {_num(self.eta2)}$). Beyond which angle of incidence "
            r"(measured from the normal) is it totally reflected?" "\n\n"
            r"**Answer:** the angle in degrees. " + DECIMALS + "\n\n"
            + data_note("eta1", "eta2"))


class SchlickReflectance(DrawnExercise):
    r"""Schlick's approximation :math:`F = R_0 + (1 - R_0)(1 - \cos\theta)^5` for a ray from air.

    Attributes: ``eta1`` (1, air), ``eta2``, ``angle`` (of incidence, degrees).

    Examples
    --------
    >>> ex = SchlickReflectance(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(((ex.eta1 - ex.eta2) / (ex.eta1 + ex.eta2)) ** 2).diagnosis
    'R0 only'
    """

    title = "Fresnel reflectance by Schlick's approximation"
    answer_form = "number"
    what = "the reflectance F"
    advice = (r"$R_0 = \left(\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}\right)^2$ is the reflectance "
            r"head on; $F = R_0 + (1 - R_0)(1 - \cos\theta)^5$ with $\theta$ the angle of "
            r"incidence.")

    def draw(self, rng):
        self.eta1 = 1.0
        self.eta2 = float(pick(rng, (1.5, 1.33, 2.0, 2.42)))
        self.angle = float(pick(rng, (70, 75, 80, 85)))
        self.expected = float(rt.schlick(math.cos(math.radians(self.angle)), self.eta1,
                                         self.eta2))

    def mistakes(self):
        e1, e2 = self.eta1, self.eta2
        r0 = ((e1 - e2) / (e1 + e2)) ** 2
        c = math.cos(math.radians(self.angle))
        root = abs(e1 - e2) / (e1 + e2)
        found = [
            Mistake(root + (1 - root) * (1 - c) ** 5,
                    r"$R_0$ is the *square* of $\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}$ "
                    r"(4 % for glass, not 20 %).", "R0 not squared"),
            Mistake(r0, r"That is $R_0$, the reflectance head on (using $\sin\theta$ instead of "
                    r"$\cos\theta$ in the formula gives nearly the same). At "
                    rf"${_num(self.angle)}^\circ$ much more light is reflected: add "
                    r"$(1 - R_0)(1 - \cos\theta)^5$.", "R0 only"),
        ]
        forgot = r0 + (1 - c) ** 5
        if abs(forgot - self.expected) >= APART - SAME:    # R0 (1 - c)^5 is small for low R0
            found.append(Mistake(forgot, r"The factor $(1 - R_0)$ is missing: "
                                 r"$F = R_0 + (1 - R_0)(1 - \cos\theta)^5$, so that $F = 1$ "
                                 r"at grazing incidence.", "no (1 - R0)"))
        return found

    def statement(self):
        return (
            rf"A ray in air ($\eta_1 = 1$) hits a flat surface of a material with refractive "
            rf"index $\eta_2 = {_num(self.eta2)}$ at ${_num(self.angle)}^\circ$ from the normal. "
            r"What fraction of the light is reflected, by Schlick's approximation?" "\n\n"
            + _ONE_NUMBER + "\n\n" + data_note("eta1", "eta2", "angle"))


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


class RayTreeCount(_Parts):
    r"""How many rays the ray tree of one pixel holds, with and without transparency.

    Every ray hits a surface that is reflective (and, in the glass variant, transparent too):
    a mirror scene gives a chain of :math:`d + 1` rays, a glass scene a full binary tree of
    :math:`2^{d+1} - 1` rays; each hit casts one shadow ray per light.

    Attributes: ``depth``, ``lights``, ``glass`` (True: every surface reflects and refracts).

    Examples
    --------
    >>> ex = RayTreeCount(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> rays, shadows = ex.expected
    >>> ex.check([rays - 1, shadows]).diagnosis
    'primary forgotten'
    """

    title = "Counting the rays of a ray tree"
    form_hint = r"`[reflected/refracted/primary rays, shadow rays]`."
    advice = (r"Draw the tree: the primary ray at level 0; every ray of level $k < d$ has one "
            r"child (mirror) or two (glass: reflected and refracted). Every node is a hit, and "
            r"every hit casts one shadow ray per light.")

    def draw(self, rng):
        self.depth = int(pick(rng, (2, 3, 4, 5)))
        self.lights = int(pick(rng, (1, 2, 3)))
        self.glass = bool(rng.random() < 0.6)
        nodes = 2 ** (self.depth + 1) - 1 if self.glass else self.depth + 1
        self.expected = np.array([float(nodes), float(nodes * self.lights)])

    def parts(self):
        d, k = self.depth, self.lights
        nodes = self.expected[0]
        primary = (r"The primary ray counts too: it is the root of the tree.")
        found_rays = [Mistake(nodes - 1, primary, "primary forgotten")]
        if self.glass:
            found_rays += [
                Mistake(2.0 ** d, r"That is only the last level ($2^d$ rays). The tree holds "
                        r"every level $0, \dots, d$: $1 + 2 + \dots + 2^d = 2^{d+1} - 1$.",
                        "last level only"),
                Mistake(d + 1.0, r"Each hit on glass spawns *two* rays, a reflected and a "
                        r"refracted one: the tree doubles at every level.", "chain"),
            ]
        else:
            found_rays.append(Mistake(2.0 ** (d + 1) - 1, r"A mirror that is not transparent "
                                      r"spawns only a reflected ray: the tree is a chain.",
                                      "binary tree"))
        return [
            ("the traced rays", nodes, found_rays),
            ("the shadow rays", nodes * k, [
                Mistake(float(k), r"Every hit casts shadow rays, not only the primary one: "
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
            r"**Answer:** a list of 2 numbers `[traced rays, shadow rays]`." "\n\n"
            + data_note("depth", "lights", "glass"))


class BVHSavings(_Parts):
    r"""What a bounding volume hierarchy saves for one ray.

    A balanced BVH over :math:`P = k\, 2^m` triangles with :math:`k` per leaf has depth
    :math:`m`; a ray that goes down a single path tests the two child boxes at each of the
    :math:`m` inner levels (:math:`2m` box tests) and the :math:`k` triangles of one leaf,
    instead of :math:`P` triangles by brute force.

    Attributes: ``triangles`` (P), ``leaf_size`` (k).

    Examples
    --------
    >>> ex = BVHSavings(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> depth, boxes, tris, factor = ex.expected
    >>> ex.check([np.log2(ex.triangles), boxes, tris, factor]).diagnosis
    'leaf size ignored'
    """

    title = "What a BVH saves"
    form_hint = r"`[depth, box tests, triangle tests, factor]`."
    advice = (r"Depth: halve $P$ until $k$ triangles are left, $m = \log_2(P/k)$. Box tests: 2 per "
            r"inner level. Factor: $P$ divided by (box tests + triangle tests).")

    def draw(self, rng):
        self.leaf_size = int(pick(rng, (2, 4, 8)))
        m = int(pick(rng, (10, 12, 14, 16)))
        self.triangles = self.leaf_size * 2 ** m
        boxes, tris = 2 * m, self.leaf_size
        self.expected = np.array([float(m), float(boxes), float(tris),
                                  self.triangles / (boxes + tris)])

    def parts(self):
        m, boxes, tris, factor = self.expected
        p, k = self.triangles, self.leaf_size
        return [
            ("the depth", m, [Mistake(math.log2(p), r"The hierarchy stops splitting when a "
                                      r"node holds $k$ triangles: $m = \log_2(P/k)$, not "
                                      r"$\log_2 P$.", "leaf size ignored")]),
            ("the box tests", boxes, [Mistake(m, r"At every inner node the ray is tested "
                                              r"against **both** children's boxes: 2 per "
                                              r"level.", "one box per level")]),
            ("the triangle tests", tris, [Mistake(float(p), r"That is brute force. In the "
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
            r"**Answer:** a list of 4 numbers `[depth, box tests, triangle tests, factor]`. "
            + DECIMALS + "\n\n" + data_note("triangles", "leaf_size"))


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
