"""Chapter 14 exercises: Mappings.

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import texturing
from ..core import Mistake, Worked, data_note, pick
from . import _UV, _Chapter14, _factor, _n4, _num, _vec

__all__ = [
    "CylindricalMap",
    "PlanarMap",
    "SphericalMap",
]


#: Whole-number vectors of whole-number length: (x, y, z), |(x, y, z)|.
_INTEGER_VECTORS = (((0, 3, 4), 5), ((3, 0, 4), 5), ((0, 4, 3), 5), ((4, 0, 3), 5),
                    ((1, 2, 2), 3), ((2, 1, 2), 3), ((2, 2, 1), 3), ((2, 3, 6), 7),
                    ((3, 2, 6), 7), ((6, 2, 3), 7), ((2, 6, 3), 7), ((3, 6, 2), 7),
                    ((6, 3, 2), 7), ((2, 4, 4), 6), ((4, 4, 2), 6), ((4, 4, 7), 9),
                    ((1, 4, 8), 9), ((8, 4, 1), 9), ((4, 8, 1), 9))


def _integer_vector(rng):
    v, length = pick(rng, _INTEGER_VECTORS)
    v = np.array(v, dtype=float)[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0, float(length)


def _azimuth(x, z):
    return 0.5 + math.atan2(x, z) / (2 * math.pi)


class SphericalMap(_Chapter14):
    r"""Spherical texture coordinates :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`,
    :math:`v = \tfrac12 + \arcsin(y/r)/\pi` of a point, relative to the sphere's centre.

    Attributes: ``center``, ``P``, ``radius``.

    Examples
    --------
    >>> ex = SphericalMap(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'u and v swapped'
    """

    title = "Spherical mapping"
    answer_form = "vector"
    what = "the texture coordinates"
    may_coincide = ("atan instead of atan2",)
    advice = (r"With $d = P - C$ and $r = \lVert d \rVert$: "
            r"$u = \tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$, "
            r"$v = \tfrac12 + \arcsin(d_y/r)/\pi$ (angles in radians).")

    def draw(self, rng):
        self.center = (rng.integers(-2, 3, size=3).astype(float) if rng.random() < 0.6
                       else np.zeros(3))
        d, self.radius = _integer_vector(rng)
        self.P = self.center + d
        u, v = texturing.spherical_map(self.P, center=self.center)
        self.expected = np.array([float(u), float(v)])

    def acceptable(self):
        d = self.P - self.center
        return d[0] != 0 and d[1] != 0

    def mistakes(self):
        x, y, z = self.P - self.center
        r = self.radius
        theta, phi = math.atan2(x, z), math.asin(y / r)
        u, v = self.expected
        found = [
            Mistake([u, 0.5 + math.atan(y / math.hypot(x, y)) / math.pi], r"That is the "
                    r"course compendium's elevation, $\tan^{-1}(y/\sqrt{x^2 + y^2})$, which "
                    r"is wrong: the horizontal distance from the pole axis $y$ is "
                    r"$\sqrt{x^2 + z^2}$, so the elevation is $\arcsin(y/r) = "
                    r"\operatorname{atan2}(y, \sqrt{x^2 + z^2})$.", "compendium's elevation"),
            Mistake([v, u], r"$u$ and $v$ are swapped: $u$ is the **azimuth** around the pole "
                    r"axis $y$ (the longitude), $v$ the **elevation** (the latitude), from 0 "
                    r"at the south pole to 1 at the north pole.", "u and v swapped"),
            Mistake([theta, phi], r"These are the angles in radians. Texture coordinates are "
                    r"fractions of the full range: $u = \tfrac12 + \theta/2\pi$ (a full turn), "
                    r"$v = \tfrac12 + \varphi/\pi$ (pole to pole).", "angles, not (u, v)"),
            Mistake([theta / (2 * math.pi), phi / math.pi], r"The offset $\tfrac12$ is "
                    r"missing: the angles run over $(-\pi, \pi]$ and $[-\pi/2, \pi/2]$, and "
                    r"adding $\tfrac12$ after dividing brings them into $[0, 1]$.",
                    "no offset"),
        ]
        if z != 0:
            found.append(Mistake([0.5 + math.atan(x / z) / (2 * math.pi), v], r"You used "
                                 r"$\tan^{-1}(x/z)$, as the compendium writes. It cannot tell "
                                 r"$(x, z)$ from $(-x, -z)$ and only covers half the circle; "
                                 r"for $z < 0$ it lands on the wrong side. The two-argument "
                                 r"$\operatorname{atan2}(x, z)$ uses both signs.",
                                 "atan instead of atan2"))
        if np.any(self.center) and np.any(self.P):
            px, py, pz = self.P
            found.append(Mistake([_azimuth(px, pz), 0.5 + math.asin(py / np.linalg.norm(self.P))
                                  / math.pi], r"The centre was not subtracted: the angles are "
                                 r"measured from the sphere's centre, $d = P - C$.",
                                 "centre not subtracted"))
        return found

    def statement(self):
        return (
            rf"A sphere with centre $C = {_vec(self.center)}$ has the point "
            rf"$P = {_vec(self.P)}$ on its surface. Its texture is mapped with the pole on the "
            r"$y$ axis: for $d = P - C$ and $r = \lVert d \rVert$, the azimuth is measured in "
            r"the $xz$ plane from $+z$ towards $+x$, "
            r"$\theta = \operatorname{atan2}(d_x, d_z) \in (-\pi, \pi]$, and the elevation is "
            r"$\varphi = \arcsin(d_y / r) \in [-\pi/2, \pi/2]$; then "
            r"$u = \tfrac12 + \theta / 2\pi$ and $v = \tfrac12 + \varphi/\pi$. Compute the "
            r"texture coordinates of $P$." "\n\n" + _UV + "\n\n"
            + data_note("center", "P", "radius"))

    def hints(self):
        d = self.P - self.center
        r = float(np.sqrt(d @ d))
        theta = math.atan2(d[0], d[2])
        phi = math.asin(d[1] / r)
        return [r"Work relative to the centre, $d = P - C$: the azimuth "
                r"$\theta = \operatorname{atan2}(d_x, d_z)$ goes around the pole axis $y$, the "
                r"elevation $\varphi = \arcsin(d_y / r)$ from the equator up; then scale both "
                r"to $[0, 1]$.",
                rf"$d = {_vec(d)}$ and $r = \lVert d \rVert = {_num(r)}$.",
                rf"$\theta = \operatorname{{atan2}}({_num(d[0])}, {_num(d[2])}) = {_n4(theta)}$ "
                rf"and $\varphi = \arcsin({_num(d[1])}/{_num(r)}) = {_n4(phi)}$ (radians)."]

    def worked(self):
        d = np.asarray(self.P, dtype=float) - np.asarray(self.center, dtype=float)
        r = math.sqrt(float(d @ d))
        theta = math.atan2(d[0], d[2])
        phi = math.asin(d[1] / r)
        u = 0.5 + theta / (2 * math.pi)
        v = 0.5 + phi / math.pi
        quadrant = (r" ($d_z < 0$: atan2 puts the angle on the far side, beyond "
                    r"$\pm\pi/2$, where $\tan^{-1}(d_x/d_z)$ would not)" if d[2] < 0 else "")
        return Worked([
            rf"Relative to the centre: $d = P - C = {_vec(d)}$, of length "
            rf"$r = \sqrt{{{_num(d @ d)}}} = {_num(r)}$.",
            rf"Azimuth: $\theta = \operatorname{{atan2}}(d_x, d_z) = "
            rf"\operatorname{{atan2}}({_num(d[0])}, {_num(d[2])}) = {_n4(theta)}$" + quadrant
            + ".",
            rf"Elevation: $\varphi = \arcsin(d_y / r) = \arcsin({_num(d[1])}/{_num(r)}) = "
            rf"{_n4(phi)}$.",
            rf"$u = \tfrac12 + \theta / 2\pi = 0.5 + {_factor(theta)}/{_n4(2 * math.pi)} = "
            rf"{_n4(u)}$ and $v = \tfrac12 + \varphi / \pi = 0.5 + {_factor(phi)}/"
            rf"{_n4(math.pi)} = {_n4(v)}$.",
        ], [u, v])


class CylindricalMap(_Chapter14):
    r"""Cylindrical texture coordinates: :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`
    around the axis, :math:`v = y/h` along it, both relative to the base centre.

    Attributes: ``base`` (the centre of the cylinder's base), ``height``, ``P``.

    Examples
    --------
    >>> ex = CylindricalMap(seed=8)
    >>> ex.check(ex.expected).status
    'correct'
    >>> u, v = ex.expected
    >>> ex.check([u, v * ex.height]).diagnosis
    'v not divided by the height'
    """

    title = "Cylindrical mapping"
    answer_form = "vector"
    what = "the texture coordinates"
    may_coincide = ("atan instead of atan2",)
    advice = (r"With $d = P - C$: $u = \tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$ and "
            r"$v = d_y / h$.")

    def draw(self, rng):
        self.base = rng.integers(-2, 3, size=3).astype(float)
        self.height = float(pick(rng, (2, 4, 5, 8, 10)))
        x, z = (float(c) for c in rng.integers(-3, 4, size=2))
        y = float(rng.integers(1, 2 * self.height)) / 2
        self.P = self.base + np.array([x, y, z])
        u, v = texturing.cylindrical_map(self.P, center=self.base, height=self.height)
        self.expected = np.array([float(u), float(v)])

    def acceptable(self):
        x, _, z = self.P - self.base
        return x != 0 and z != 0

    def mistakes(self):
        x, y, z = self.P - self.base
        u, v = self.expected
        h = self.height
        found = [
            Mistake([_azimuth(z, x), v], r"You measured the angle from the $x$ axis, "
                    r"$\operatorname{atan2}(z, x)$. Here the azimuth starts at $+z$ "
                    r"($u = \tfrac12$) and turns towards $+x$: "
                    r"$\operatorname{atan2}(d_x, d_z)$.", "azimuth from the x axis"),
            Mistake([u, y], r"$v$ must be divided by the height of the cylinder: "
                    rf"$v = d_y / h$, so that the texture covers the cylinder once, from "
                    r"$v = 0$ at the base to $v = 1$ at the top.",
                    "v not divided by the height"),
            Mistake([v, u], r"$u$ and $v$ are swapped: $u$ goes **around** the axis, $v$ "
                    r"**along** it.", "u and v swapped"),
            Mistake([0.5 + math.atan(x / z) / (2 * math.pi), v], r"You used "
                    r"$\tan^{-1}(x/z)$: it only covers half the circle (it cannot tell "
                    r"$(x, z)$ from $(-x, -z)$). The two-argument "
                    r"$\operatorname{atan2}(x, z)$ uses both signs.", "atan instead of atan2"),
        ]
        if self.base[1] != 0:
            found.append(Mistake([u, self.P[1] / h], r"The height is measured from the "
                                 r"**base** of the cylinder: $v = (P_y - C_y)/h$.",
                                 "base not subtracted"))
        return found

    def statement(self):
        return (
            rf"A cylinder stands on the base centre $C = {_vec(self.base)}$ with its axis along "
            rf"$+y$ and the height $h = {_num(self.height)}$. Its texture is wrapped around it: "
            r"for $d = P - C$, $u = \tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$ (the angle "
            r"around the axis, measured from $+z$ towards $+x$) and $v = d_y / h$ (the height "
            rf"along the axis). Compute the texture coordinates of $P = {_vec(self.P)}$." "\n\n"
            + _UV + "\n\n" + data_note("base", "height", "P"))

    def hints(self):
        d = self.P - self.base
        theta = math.atan2(d[0], d[2])
        return [r"Relative to the base centre, $d = P - C$: $u$ is the angle **around** the "
                r"axis, $\tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$, and $v$ the height "
                r"**along** it as a fraction of the cylinder's height, $d_y / h$.",
                rf"$d = P - C = {_vec(d)}$.",
                rf"$\operatorname{{atan2}}({_num(d[0])}, {_num(d[2])}) = {_n4(theta)}$ radians, "
                rf"and $d_y / h = {_num(d[1])}/{_num(self.height)}$."]

    def worked(self):
        d = np.asarray(self.P, dtype=float) - np.asarray(self.base, dtype=float)
        theta = math.atan2(d[0], d[2])
        u = 0.5 + theta / (2 * math.pi)
        v = d[1] / self.height
        return Worked([
            rf"Relative to the base centre: $d = P - C = {_vec(d)}$.",
            rf"Around the axis: $\theta = \operatorname{{atan2}}(d_x, d_z) = "
            rf"\operatorname{{atan2}}({_num(d[0])}, {_num(d[2])}) = {_n4(theta)}$, so "
            rf"$u = 0.5 + {_factor(theta)}/{_n4(2 * math.pi)} = {_n4(u)}$.",
            rf"Along the axis: $v = d_y / h = {_num(d[1])}/{_num(self.height)} = {_n4(v)}$.",
        ], [u, v])


_AXIS_NAMES = {(1, 0, 0): "+x", (-1, 0, 0): "-x", (0, 1, 0): "+y", (0, -1, 0): "-y",
               (0, 0, 1): "+z", (0, 0, -1): "-z"}


class PlanarMap(_Chapter14):
    r"""Planar texture coordinates :math:`u = (P - O) \cdot e_u / s_u`,
    :math:`v = (P - O) \cdot e_v / s_v` with :math:`e_v = n \times e_u`.

    Attributes: ``origin``, ``normal``, ``u_axis``, ``size`` (:math:`(s_u, s_v)`), ``P``.

    Examples
    --------
    >>> ex = PlanarMap(seed=9)
    >>> ex.check(ex.expected).status
    'correct'
    >>> u, v = ex.expected
    >>> ex.check([u, -v]).diagnosis
    'v axis mirrored'
    """

    title = "Planar mapping"
    answer_form = "vector"
    what = "the texture coordinates"
    advice = (r"Subtract the origin, project onto $e_u$ and onto $e_v = n \times e_u$, divide by "
            r"the sizes.")

    def draw(self, rng):
        axes = np.eye(3)
        k, m = rng.choice(3, size=2, replace=False)
        self.normal = axes[k] * float(pick(rng, (-1, 1))) + 0.0
        self.u_axis = axes[m] * float(pick(rng, (-1, 1))) + 0.0
        self.origin = rng.integers(-2, 3, size=3).astype(float)
        self.size = np.array([float(pick(rng, (2, 4, 5))), float(pick(rng, (2, 4, 5)))])
        self.P = self.origin + rng.integers(-6, 7, size=3).astype(float)
        u, v = texturing.planar_map(self.P, origin=self.origin, normal=self.normal,
                                    u_axis=self.u_axis, size=self.size)
        self.expected = np.array([float(u), float(v)])

    def acceptable(self):
        return bool(np.all(np.abs(self.expected) > 0.05))

    def mistakes(self):
        d = self.P - self.origin
        e_v = np.cross(self.normal, self.u_axis)
        su, sv = self.size
        u, v = self.expected
        found = [
            Mistake([u, -v], r"The $v$ axis points the wrong way: $e_v = n \times e_u$ (in "
                    r"that order), so that $(e_u, e_v, n)$ is right-handed like "
                    r"$(x, y, z)$ and the texture is not mirrored seen from the side $n$ points "
                    r"to.", "v axis mirrored"),
            Mistake([d @ self.u_axis, d @ e_v], r"The sizes are missing: one copy of the "
                    r"texture covers $s_u \times s_v$ of the plane, so divide by $s_u$ and "
                    r"$s_v$.", "not divided by the size"),
            Mistake([self.P @ self.u_axis / su, self.P @ e_v / sv], r"The origin was not "
                    r"subtracted: $(u, v) = (0, 0)$ is at $O$, so measure $P - O$.",
                    "origin ignored"),
        ]
        if abs(self.normal[2]) != 1:
            found.append(Mistake([d[0] / su, d[1] / sv], r"You took the $x$ and $y$ "
                                 r"coordinates, as for a plane facing $z$. This plane faces "
                                 r"$n$: its texture axes are $e_u$ and $e_v = n \times e_u$.",
                                 "x and y taken"))
        return found

    def statement(self):
        n = _AXIS_NAMES[tuple(int(c) for c in self.normal)]
        eu = _AXIS_NAMES[tuple(int(c) for c in self.u_axis)]
        su, sv = self.size
        return (
            rf"A texture is projected onto the plane through $O = {_vec(self.origin)}$ with "
            rf"normal $n = {_vec(self.normal)}$ (pointing along ${n}$). The $u$ axis of the "
            rf"texture is $e_u = {_vec(self.u_axis)}$ (along ${eu}$), the $v$ axis is "
            r"$e_v = n \times e_u$, and one copy of the texture covers "
            rf"$s_u \times s_v = {_num(su)} \times {_num(sv)}$ of the plane, with its corner "
            r"$(u, v) = (0, 0)$ at $O$: $u = (P - O) \cdot e_u / s_u$, "
            r"$v = (P - O) \cdot e_v / s_v$. Compute the texture coordinates of "
            rf"$P = {_vec(self.P)}$." "\n\n" + _UV + "\n\n"
            + data_note("origin", "normal", "u_axis", "size", "P"))

    def _axes(self):
        n, e_u = np.asarray(self.normal, dtype=float), np.asarray(self.u_axis, dtype=float)
        e_v = np.array([n[1] * e_u[2] - n[2] * e_u[1], n[2] * e_u[0] - n[0] * e_u[2],
                        n[0] * e_u[1] - n[1] * e_u[0]]) + 0.0
        return n, e_u, e_v

    def hints(self):
        _, e_u, e_v = self._axes()
        d = self.P - self.origin
        return [r"Measure $P$ from the origin, $d = P - O$, and project it onto the two texture "
                r"axes: $u = d \cdot e_u / s_u$, $v = d \cdot e_v / s_v$, with "
                r"$e_v = n \times e_u$ (in that order).",
                rf"$e_v = n \times e_u = {_vec(self.normal)} \times {_vec(self.u_axis)} = "
                rf"{_vec(e_v)}$.",
                rf"$d = P - O = {_vec(d)}$: $d \cdot e_u = {_num(d @ e_u)}$ and "
                rf"$d \cdot e_v = {_num(d @ e_v)}$; divide by the sizes."]

    def worked(self):
        n, e_u, e_v = self._axes()
        d = np.asarray(self.P, dtype=float) - np.asarray(self.origin, dtype=float)
        su, sv = (float(x) for x in self.size)
        du, dv = float(d @ e_u), float(d @ e_v)
        u, v = du / su, dv / sv
        return Worked([
            rf"The $v$ axis: $e_v = n \times e_u = {_vec(n)} \times {_vec(e_u)} = {_vec(e_v)}$.",
            rf"From the origin: $d = P - O = {_vec(self.P)} - {_vec(self.origin)} = {_vec(d)}$.",
            rf"$u = d \cdot e_u / s_u = {_num(du)}/{_num(su)} = {_n4(u)}$ and "
            rf"$v = d \cdot e_v / s_v = {_num(dv)}/{_num(sv)} = {_n4(v)}$.",
        ], [u, v])
