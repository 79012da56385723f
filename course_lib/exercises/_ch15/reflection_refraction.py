"""Chapter 15 exercises: reflection, refraction and the Fresnel reflectance.

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.
"""
import math

import numpy as np

from ... import raytracing as rt
from ..core import (APART, DECIMALS, SAME, DrawnExercise, Mistake, Worked, data_note,
                    latex_fraction, pick, well_separated)
from . import _ONE_NUMBER, _VECTOR_3, _frac, _nice_unit, _num, _vec

__all__ = [
    "CriticalAngle",
    "ReflectedRay",
    "RefractedRay",
    "SchlickReflectance",
]


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
