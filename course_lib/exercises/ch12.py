r"""Chapter 12 exercises: local illumination, interpolated shading, ambient occlusion, exam style.

Each class is one kind of exam question: the mirror direction :math:`R`; the diffuse, the
specular and the whole Phong intensity of a point under a grey light; Blinn-Phong's halfway
vector and highlight; the attenuation of a point light with distance; a matte surface under
several lights; which interpolated shading method (flat, Gouraud, Phong) suits a situation, and
Gouraud against Phong shading at the midpoint of an edge; ambient occlusion from a list of
sample rays, and its closed form next to a wall or in a trench. The ``seed`` draws numbers that
work out by hand: unit vectors with rational components such as :math:`(\tfrac23, \tfrac13,
\tfrac23)` or :math:`(0.6, 0, 0.8)`, distances that are whole numbers, small exponents, angles
that are multiples of 15 degrees.

The expected answers come from :mod:`course_lib.shading`. Each exercise names the slips it
anticipates (the incoming-direction reflection formula with the wrong sign, a normal left
unnormalised, a negative cosine not clamped, the exponent put on the coefficient, the ambient or
the emission term forgotten, :math:`1/d` for the attenuation, ...), computes the answer each slip
would give, and draws its numbers again until those answers differ clearly from the right one
and from each other (:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.shading` and the textbook): :math:`N, L, V, R` are unit
vectors that start at the surface point and point *away* from it (:math:`L` towards the light,
:math:`V` towards the viewer), :math:`R = 2 (N \cdot L) N - L`; a light with
:math:`N \cdot L \le 0` adds neither diffuse nor specular light; a point light at distance
:math:`d` is weakened by :math:`f_{att}(d) = 1 / (a + b d + c d^2)`; all lights here are grey
(one intensity for all three channels), so every intensity is one number.
"""
import math

import numpy as np

from .. import format as fmt
from .. import shading
from .core import (DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, PartsAnswer, close,
                   data_note, gap, is_unanswered, latex_fraction, latex_vector, pick, read_floats,
                   well_separated)

__all__ = [
    "EXERCISES",
    "SHADING_METHODS",
    "AmbientOcclusionSamples",
    "AmbientOcclusionWall",
    "BlinnPhongHighlight",
    "DiffuseTerm",
    "DistanceAttenuation",
    "GouraudVersusPhong",
    "PhongTotal",
    "ReflectionVector",
    "SeveralLights",
    "ShadingMethodChoice",
    "SpecularTerm",
]

_num = fmt.number
_frac = latex_fraction
_vec = latex_vector

#: Unit vectors with rational components, the last one "up" (along the normal).
_UNIT_PATTERNS = ((0.0, 0.0, 1.0), (0.6, 0.0, 0.8), (0.8, 0.0, 0.6), (0.0, 0.6, 0.8),
                  (0.0, 0.8, 0.6), (2 / 3, 1 / 3, 2 / 3), (1 / 3, 2 / 3, 2 / 3),
                  (2 / 3, 2 / 3, 1 / 3), (2 / 7, 3 / 7, 6 / 7), (3 / 7, 2 / 7, 6 / 7),
                  (6 / 7, 2 / 7, 3 / 7), (2 / 7, 6 / 7, 3 / 7), (3 / 7, 6 / 7, 2 / 7),
                  (6 / 7, 3 / 7, 2 / 7))

#: Whole-number vectors of whole-number length: (x, y, z), |(x, y, z)|.
_INTEGER_VECTORS = (((0, 0, 2), 2), ((0, 0, 3), 3), ((0, 3, 4), 5), ((3, 0, 4), 5),
                    ((0, 4, 3), 5), ((4, 0, 3), 5), ((1, 2, 2), 3), ((2, 1, 2), 3),
                    ((2, 2, 1), 3), ((2, 3, 6), 7), ((3, 2, 6), 7), ((6, 2, 3), 7),
                    ((2, 6, 3), 7), ((2, 4, 4), 6), ((4, 4, 2), 6), ((4, 4, 7), 9),
                    ((1, 4, 8), 9), ((8, 4, 1), 9))


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


_AXES = ([1, 2, 0], [2, 0, 1], [0, 1, 2])


def _frame(v, axis):
    """Local coordinates (x, y, z) -> world, local z going to world axis `axis` (cyclically)."""
    return np.asarray(v, dtype=float)[..., _AXES[axis]]


def _all_units():
    """Every unit vector of _UNIT_PATTERNS with x and y swapped or not, of any signs (z > 0)."""
    found = set()
    for x, y, z in _UNIT_PATTERNS:
        for a, b in ((x, y), (y, x)):
            for sa in (-1.0, 1.0):
                for sb in (-1.0, 1.0):
                    found.add((a * sa + 0.0, b * sb + 0.0, z))
    return np.array(sorted(found))


#: The nice unit vectors above the surface (local frame, normal +z), and below it.
_UP = _all_units()
_DOWN = _UP * np.array([1.0, 1.0, -1.0])


def _reflection_table(first, second):
    """R . V for L in the rows of `first`, V in the rows of `second`, N = +z."""
    return 2 * first[:, 2, None] * second[None, :, 2] - first @ second.T


_UP_DOT = _UP @ _UP.T
_UP_RV = _reflection_table(_UP, _UP)
_DOWN_RV = _reflection_table(_DOWN, _UP)
_UP_NH = (_UP[:, 2, None] + _UP[None, :, 2]) / np.sqrt(2 + 2 * _UP_DOT)


def _nice_unit(rng, up=1.0):
    """One of the nice unit vectors, its z of the sign of `up` (local frame)."""
    return _UP[int(rng.integers(len(_UP)))] * np.array([1.0, 1.0, up])


def _pair(rng, first, second, ok):
    """A row of `first` and a row of `second` for which the matrix `ok` holds, at random."""
    i, j = np.nonzero(ok)
    k = int(rng.integers(len(i)))
    return first[i[k]], second[j[k]]


def _integer_vector(rng):
    """A whole-number vector of whole-number length, its axes permuted, random signs."""
    v, length = pick(rng, _INTEGER_VECTORS)
    v = np.array(v, dtype=float)[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0, float(length)


def _material_words(**coefficients):
    return ", ".join(rf"${name} = {_num(value)}$" for name, value in coefficients.items())


class _Parts(PartsAnswer, DrawnExercise):
    """An answer made of several numbers, each with slips of its own (see PartsAnswer)."""

    def _judge(self, answer):
        return self.judge_parts(answer)


_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


# ---------------------------------------------------------------------------------------------
# The vectors of the model
# ---------------------------------------------------------------------------------------------

class ReflectionVector(DrawnExercise):
    r"""The mirror direction :math:`R = 2 (\hat N \cdot L)\, \hat N - L` of a unit vector L.

    The normal is given with whole-number components and is not of unit length: it must be
    normalised first.

    Attributes: ``N`` (the normal, not normalised), ``L`` (unit, towards the light).

    Examples
    --------
    >>> ex = ReflectionVector(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> n = ex.N / np.linalg.norm(ex.N)
    >>> ex.check(ex.L - 2 * (n @ ex.L) * n).diagnosis          # the ray-tracing form, misread
    'incoming formula'
    >>> ex.check(2 * (ex.N @ ex.L) * ex.N - ex.L).diagnosis
    'N not normalised'
    >>> ex.check(...).status, ex.check("R").status
    ('unanswered', 'invalid')
    """

    title = "The mirror direction R"
    answer_form = "vector"
    what = "the vector R"
    hint = (r"Normalise the normal first, $\hat N = N / \lVert N \rVert$, then "
            r"$R = 2 (\hat N \cdot L)\, \hat N - L$. Check: $R$ is a unit vector and "
            r"$\hat N \cdot R = \hat N \cdot L$.")

    def draw(self, rng):
        self.N, self._length = _integer_vector(rng)
        n = self.N / self._length
        self.L = _frame(_nice_unit(rng), int(rng.integers(3)))
        if n @ self.L < 0:
            self.L = -self.L
        self.expected = shading.reflect(self.L, self.N)

    def acceptable(self):
        n = self.N / self._length
        return 0.2 < n @ self.L < 0.95

    def mistakes(self):
        N, L = self.N, self.L
        n = N / np.linalg.norm(N)
        d = float(n @ L)
        return [
            Mistake(L - 2 * d * n, r"That is $L - 2 (N \cdot L) N$, the reflection formula for "
                    r"an **incoming** direction $D$ (a ray travelling *towards* the surface), "
                    r"$D - 2 (N \cdot D) N$, with $L$ put in for $D$. But $L$ points *away* from "
                    r"the surface, $D = -L$; putting that in gives "
                    r"$-L + 2 (N \cdot L) N$. Your vector is $-R$: it points into the surface.",
                    "incoming formula"),
            Mistake(2 * float(N @ L) * N - L, r"The normal was not normalised. The formula "
                    r"$R = 2 (N \cdot L) N - L$ assumes $\lVert N \rVert = 1$: with a longer "
                    r"$N$ the term $2 (N \cdot L) N$ grows with $\lVert N \rVert^2$. Divide $N$ "
                    rf"by its length ({_num(np.linalg.norm(N))}) first.", "N not normalised"),
            Mistake(d * n, r"That is $(N \cdot L)\, N$, the projection of $L$ onto the normal: "
                    r"the midpoint between $L$ and $R$. The mirror image goes as far past that "
                    r"point again: $R = 2 (N \cdot L) N - L$.", "projection only"),
            Mistake(2 * d * n + L, r"The sign of $L$ is wrong: $R = 2 (N \cdot L) N - L$. "
                    r"Going from $L$ to its mirror image you *subtract* the part of $L$ across "
                    r"the normal; adding $L$ gives a vector that is not even of unit length.",
                    "plus L"),
        ]

    def statement(self):
        return (
            rf"A surface point has the normal $N = {_vec(self.N)}$ (not of unit length). The "
            rf"unit vector towards the light is $L = {_vec(self.L)}$. Compute the mirror "
            r"direction $R$ of $L$ about the normal, the direction in which the light is "
            r"reflected, with the convention that $N$, $L$ and $R$ all point away from the "
            r"surface." "\n\n"
            r"**Answer:** the vector as a list of 3 numbers `[x, y, z]`. " + DECIMALS + "\n\n"
            + data_note("N", "L"))


# ---------------------------------------------------------------------------------------------
# The terms of the Phong model
# ---------------------------------------------------------------------------------------------

def _matte(kd):
    return shading.Material(ka=0.0, kd=kd, ks=0.0, shininess=1.0)


class DiffuseTerm(DrawnExercise):
    r"""The diffuse term :math:`I_d = k_d I_l \max(N \cdot L, 0)` (Lambert's cosine law).

    Two kinds of variant: ``kind == "position"`` gives the surface point ``P``, its unit normal
    ``N`` and the position ``Q`` of a point light (so :math:`L` must be normalised);
    ``kind == "angle"`` gives the angle of incidence ``theta_deg`` between :math:`N` and
    :math:`L`, in degrees. In some variants the light is behind the surface.

    Attributes: ``kind``, ``kd``, ``Il``, and ``P``, ``N``, ``Q`` or ``theta_deg``.

    Examples
    --------
    >>> ex = DiffuseTerm(seed=3)
    >>> ex.kind, ex.check(ex.expected).status
    ('position', 'correct')
    >>> ex.check(ex.kd * ex.Il * (ex.N @ (ex.Q - ex.P))).diagnosis
    'L not normalised'
    >>> ex = DiffuseTerm(seed=0)
    >>> ex.kind, ex.check(ex.kd * ex.Il * np.cos(ex.theta_deg)).diagnosis
    ('angle', 'degrees')
    """

    title = "The diffuse term"
    answer_form = "number"
    what = "the diffuse intensity"
    may_coincide = ("sine",)
    hint = (r"Use $I_d = k_d\, I_l \max(N \cdot L, 0)$ with the **unit** vector $L$ from the "
            r"point towards the light; $N \cdot L = \cos\theta$, the cosine of the angle of "
            r"incidence measured from the normal.")

    def draw(self, rng):
        self.kd = float(pick(rng, (0.4, 0.5, 0.6, 0.8)))
        self.Il = float(pick(rng, (1.0, 1.5, 2.0, 0.5)))
        if rng.random() < 0.4:
            self.kind = "angle"
            self.theta_deg = int(pick(rng, (30, 45, 60, 75, 120, 135, 150)))
            t = math.radians(self.theta_deg)
            light = shading.directional_light([math.sin(t), 0.0, math.cos(t)], self.Il)
            self.expected = float(shading.phong(None, [0, 0, 1], [0, 0, 1], light,
                                                _matte(self.kd)).diffuse[0])
        else:
            self.kind = "position"
            axis = int(rng.integers(3))
            self.N = _frame(_nice_unit(rng) if rng.random() < 0.5 else [0, 0, 1.0], axis)
            self.P = rng.integers(-2, 3, size=3).astype(float)
            d, self._distance = _integer_vector(rng)
            self.Q = self.P + d
            light = shading.point_light(self.Q, self.Il)
            self.expected = float(shading.phong(self.P, self.N, self.N, light,
                                                _matte(self.kd)).diffuse[0])

    def acceptable(self):
        if self.kind == "angle":
            return True
        cos = float(self.N @ (self.Q - self.P)) / self._distance
        return 0.15 < abs(cos) < 0.99

    def mistakes(self):
        kd, Il = self.kd, self.Il
        behind = (r"The light is **behind** the surface: $N \cdot L < 0$, so the point gets no "
                  r"direct light at all and $I_d = 0$. A negative cosine must be clamped, "
                  r"$\max(N \cdot L, 0)$; without it a light behind the surface would *remove* "
                  r"light.")
        if self.kind == "angle":
            t = math.radians(self.theta_deg)
            found = [
                Mistake(kd * Il * math.cos(self.theta_deg), r"You took the cosine of "
                        rf"{self.theta_deg} **radians**: the angle is in degrees. Convert it "
                        r"first (`np.cos(np.radians(theta))`), or recall "
                        r"$\cos 60^\circ = \tfrac12$, $\cos 45^\circ = \tfrac{\sqrt2}{2}$, "
                        r"$\cos 30^\circ = \tfrac{\sqrt3}{2}$.", "degrees"),
                Mistake(kd * Il * math.sin(t), r"You used the sine. Lambert's law uses the "
                        r"cosine of the angle between the light direction and the **normal** "
                        r"(light straight from above, $\theta = 0$, gives the most light).",
                        "sine"),
            ]
            if math.cos(t) < 0:
                found.append(Mistake(kd * Il * math.cos(t), behind, "no clamp"))
            return found
        n_l = float(self.N @ (self.Q - self.P)) / self._distance
        found = [Mistake(kd * Il * max(-n_l, 0.0), r"You took $L$ from the light to the point. "
                         r"In the illumination model $L$ starts at the surface point and points "
                         r"**towards** the light: $L = (Q - P) / \lVert Q - P \rVert$.",
                         "L reversed")]
        if n_l > 0:
            found.append(Mistake(kd * Il * n_l * self._distance, r"$L$ was not normalised: "
                                 r"$N \cdot L$ is the cosine of the angle of incidence only for "
                                 r"unit vectors. Divide $Q - P$ by its length "
                                 rf"({_num(self._distance)}) first.", "L not normalised"))
        else:
            found += [Mistake(kd * Il * n_l, behind, "no clamp"),
                      Mistake(kd * Il * n_l * self._distance, behind, "no clamp")]
        return found

    def statement(self):
        if self.kind == "angle":
            setting = (
                rf"A matte surface with diffuse coefficient $k_d = {_num(self.kd)}$ is lit by "
                rf"a distant light of intensity $I_l = {_num(self.Il)}$. The direction towards "
                rf"the light makes the angle $\theta = {self.theta_deg}^\circ$ with the surface "
                r"normal.")
            names = ("kind", "kd", "Il", "theta_deg")
        else:
            setting = (
                rf"A matte surface with diffuse coefficient $k_d = {_num(self.kd)}$ has, at "
                rf"the point $P = {_vec(self.P)}$, the unit normal $N = {_vec(self.N)}$. A "
                rf"point light of intensity $I_l = {_num(self.Il)}$ (no attenuation) is at "
                rf"$Q = {_vec(self.Q)}$.")
            names = ("kind", "kd", "Il", "P", "N", "Q")
        return (setting + r" Compute the diffuse term $I_d$ of the Phong model at the point."
                "\n\n" + _ONE_NUMBER + "\n\n" + data_note(*names))


def _rv(N, L, V):
    """R . V for unit N, L, V."""
    R = 2 * (N @ L) * N - L
    return float(R @ V)


class SpecularTerm(DrawnExercise):
    r"""The specular term :math:`I_s = k_s I_l \max(R \cdot V, 0)^n` of the Phong model.

    Attributes: ``N``, ``L``, ``V`` (unit vectors), ``ks``, ``Il``, ``n`` (the exponent).

    Examples
    --------
    >>> ex = SpecularTerm(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.ks * ex.Il * (ex.N @ ex.L) ** ex.n).diagnosis
    'N·L instead of R·V'
    """

    title = "The specular term"
    answer_form = "number"
    what = "the specular intensity"
    hint = (r"Reflect first, $R = 2 (N \cdot L) N - L$, then $I_s = k_s\, I_l \max(R \cdot V, "
            r"0)^n$: only the cosine is raised to the power $n$.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        rv = _UP_RV                     # directions with a clear highlight, or clearly none
        ok = (_UP_DOT < 0.99) & ((rv > 0.5) | ((rv > -0.9) & (rv < -0.3)))
        L, V = _pair(rng, _UP, _UP, ok)
        self.L, self.V = _frame(L, axis), _frame(V, axis)
        self.ks = float(pick(rng, (0.5, 0.6, 0.8)))
        self.Il = float(pick(rng, (1.0, 2.0)))
        self.n = int(pick(rng, (2, 3, 4, 5)))
        light = shading.directional_light(self.L, self.Il)
        material = shading.Material(ka=0.0, kd=0.0, ks=self.ks, shininess=self.n)
        self.expected = float(shading.phong(None, self.N, self.V, light, material).specular[0])

    def mistakes(self):
        N, L, V, ks, Il, n = self.N, self.L, self.V, self.ks, self.Il, self.n
        rv = _rv(N, L, V)
        c = max(rv, 0.0)
        coefficient = (r"The exponent belongs to the cosine alone: $k_s\, I_l\, (R \cdot V)^n$. "
                       r"Raising $k_s$ (or $I_l$) to the power $n$ as well makes the highlight "
                       r"far too dim; the coefficients only scale it.")
        found = [
            Mistake(ks * Il * max(float(N @ L), 0.0) ** n, r"You used $N \cdot L$, the cosine of "
                    r"the diffuse term. The specular term measures how close the viewer is to "
                    r"the **mirror direction**: first $R = 2 (N \cdot L) N - L$, then "
                    r"$(R \cdot V)^n$.", "N·L instead of R·V"),
            Mistake(ks * Il * c, r"The exponent is missing: $I_s = k_s\, I_l \max(R \cdot V, "
                    r"0)^n$. The power $n$ (the shininess) is what makes the highlight small "
                    r"and sharp.", "no exponent"),
            Mistake(Il * (ks * c) ** n, coefficient, "exponent on the coefficient"),
            Mistake((ks * Il * c) ** n, coefficient, "exponent on the coefficient"),
        ]
        if rv < 0:
            even = (" With an even exponent the power even turned it positive." if n % 2 == 0
                    else "")
            found.append(Mistake(ks * Il * rv ** n, r"Here $R \cdot V < 0$: the viewer is more "
                                 r"than $90^\circ$ away from the mirror direction and sees no "
                                 r"highlight at all. Clamp the cosine before the power, "
                                 r"$\max(R \cdot V, 0)^n = 0$." + even, "no clamp"))
        return found

    def statement(self):
        return (
            rf"At a surface point with unit normal $N = {_vec(self.N)}$, the unit vector "
            rf"towards a distant light of intensity $I_l = {_num(self.Il)}$ is "
            rf"$L = {_vec(self.L)}$ and the unit vector towards the viewer is "
            rf"$V = {_vec(self.V)}$. The material has the specular coefficient "
            rf"$k_s = {_num(self.ks)}$ and the shininess exponent $n = {self.n}$. Compute the "
            r"specular term $I_s$ of the Phong model." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("N", "L", "V", "ks", "Il", "n"))


class PhongTotal(DrawnExercise):
    r"""The whole Phong intensity :math:`I = I_e + I_a k_a + k_d I_l \max(N \cdot L, 0)
    + k_s I_l \max(R \cdot V, 0)^n` for one grey light.

    In some variants :math:`R \cdot V < 0` (no highlight) or the light is behind the surface
    (neither diffuse nor specular light).

    Attributes: ``N``, ``L``, ``V``, ``Ie``, ``Ia``, ``ka``, ``kd``, ``ks``, ``n``, ``Il``.

    Examples
    --------
    >>> ex = PhongTotal(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected - ex.Ia * ex.ka).diagnosis
    'no ambient'
    >>> ex.check(ex.expected - ex.Ie).diagnosis
    'no emission'
    """

    title = "The Phong illumination model"
    answer_form = "number"
    what = "the intensity"
    hint = (r"Add the four terms: the emission $I_e$, the ambient $I_a k_a$, the diffuse "
            r"$k_d I_l \max(N \cdot L, 0)$ and the specular $k_s I_l \max(R \cdot V, 0)^n$ "
            r"with $R = 2 (N \cdot L) N - L$; both light terms are 0 when $N \cdot L \le 0$.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        self.case = str(pick(rng, ("lit",) * 5 + ("no highlight",) * 3 + ("behind",) * 2))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        while True:                     # the case asked for, with a clear effect of each slip
            self.kd = float(pick(rng, (0.4, 0.5, 0.6)))
            self.ks = float(pick(rng, (0.2, 0.3, 0.4)))
            self.Il = float(pick(rng, (1.0, 0.8, 1.5)))
            self.n = int(pick(rng, (2, 3, 4, 5)))
            ok = self._clear_case()
            if ok.any():
                break
        first = _DOWN if self.case == "behind" else _UP
        L, V = _pair(rng, first, _UP, ok)
        self.L, self.V = _frame(L, axis), _frame(V, axis)
        while True:                     # ambient and emission of clearly different sizes
            self.Ie = float(pick(rng, (0.1, 0.2, 0.3)))
            self.Ia = float(pick(rng, (0.5, 1.0)))
            self.ka = float(pick(rng, (0.1, 0.2, 0.3)))
            if abs(self.Ia * self.ka - self.Ie) >= 0.1:
                break
        material = shading.Material(ka=self.ka, kd=self.kd, ks=self.ks, shininess=self.n,
                                    emission=self.Ie)
        light = shading.directional_light(self.L, self.Il)
        self.expected = float(shading.phong(None, self.N, self.V, light, material,
                                            ambient=self.Ia).total[0])

    def _clear_case(self):
        """Which pairs (L from the rows, V from the columns of the table) fit the case."""
        first = _DOWN if self.case == "behind" else _UP
        rv = _DOWN_RV if self.case == "behind" else _UP_RV
        nl = first[:, 2, None] + 0 * rv
        highlight = self.ks * self.Il * np.abs(rv) ** self.n
        if self.case == "lit":
            return (nl > 0.2) & (rv > 0.3)
        if self.case == "no highlight":
            return (nl > 0.2) & (rv < 0) & (highlight > 0.06)
        unclamped = self.Il * (self.kd * nl + self.ks * rv ** self.n)
        return ((nl < -0.2) & (rv > 0) & (highlight > 0.06) & (np.abs(unclamped) > 0.06)
                & (np.abs(unclamped - highlight) > 0.06))

    def mistakes(self):
        nl, rv = float(self.N @ self.L), _rv(self.N, self.L, self.V)
        I, amb = self.expected, self.Ia * self.ka
        found = [
            Mistake(I - amb, r"The ambient term is missing: $I_g = I_a k_a$ stands for all the "
                    r"light that arrives indirectly, bounced off other surfaces. It is added "
                    r"whatever the light sources do.", "no ambient"),
            Mistake(I - self.Ie, r"The emission $I_e$ is missing: the light the surface gives "
                    r"off itself is added to what it reflects.", "no emission"),
            Mistake(I - amb + self.Ia, r"The ambient term is $I_a k_a$: the ambient light "
                    r"$I_a$ times the material's ambient coefficient $k_a$ (you added $I_a$ "
                    r"alone).", "ka forgotten"),
        ]
        raw = self.Ie + amb + self.Il * (self.kd * nl + self.ks * rv ** self.n)
        if nl < 0 or rv < 0:
            found.append(Mistake(raw, r"A cosine is negative and was used as it is. Clamp "
                                 r"each one at 0: $\max(N \cdot L, 0)$ (a light behind the "
                                 r"surface adds nothing) and $\max(R \cdot V, 0)$ (a viewer more "
                                 r"than $90^\circ$ from the mirror direction sees no highlight).",
                                 "no clamp"))
        if nl < 0:
            found.append(Mistake(self.Ie + amb + self.Il * self.ks * max(rv, 0.0) ** self.n,
                                 r"The light is behind the surface ($N \cdot L < 0$), so it "
                                 r"adds no specular light either, even though $R \cdot V > 0$ "
                                 r"here: a highlight on the dark side would be wrong. Test "
                                 r"$N \cdot L > 0$ before adding either light term.",
                                 "specular on the dark side"))
        return found

    def statement(self):
        return (
            rf"A surface point has the unit normal $N = {_vec(self.N)}$; the unit vector "
            rf"towards a distant grey light of intensity $I_l = {_num(self.Il)}$ is "
            rf"$L = {_vec(self.L)}$ and the unit vector towards the viewer is "
            rf"$V = {_vec(self.V)}$. The ambient light has intensity $I_a = {_num(self.Ia)}$. "
            "The material has "
            + _material_words(I_e=self.Ie, k_a=self.ka, k_d=self.kd, k_s=self.ks, n=self.n)
            + r" (emission, ambient, diffuse and specular coefficients, shininess)." "\n\n"
            r"Compute the intensity $I = I_e + I_g + I_d + I_s$ that the Phong model gives "
            r"at this point." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("N", "L", "V", "Ie", "Ia", "ka", "kd", "ks", "n", "Il"))


class BlinnPhongHighlight(DrawnExercise):
    r"""Blinn-Phong: the halfway vector :math:`H = (L + V)/\lVert L + V \rVert` and
    :math:`(N \cdot H)^n`.

    The answer has two parts, the vector :math:`H` and the number :math:`s`; each is judged
    against the slips anticipated for it.

    Attributes: ``N``, ``L``, ``V`` (unit vectors), ``n`` (the exponent).

    Examples
    --------
    >>> ex = BlinnPhongHighlight(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> s = ex.L + ex.V
    >>> ex.check([*s, (ex.N @ s) ** ex.n]).diagnosis
    'H not normalised'
    >>> ex.check([1, 2, 3, ...]).status, ex.check([1, 2]).status
    ('unanswered', 'invalid')
    """

    title = "Blinn-Phong's halfway vector"
    answer_form = "custom"
    hint = (r"$H = (L + V) / \lVert L + V \rVert$ is the unit vector half-way between $L$ "
            r"and $V$; then $s = \max(N \cdot H, 0)^n$.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        self.n = int(pick(rng, (4, 5, 8, 10, 16, 20)))
        ok = (_UP_DOT < 0.6) & (_UP_NH ** self.n > 0.1)    # L, V apart; a visible highlight
        L, V = _pair(rng, _UP, _UP, ok)
        self.L, self.V = _frame(L, axis), _frame(V, axis)
        H = shading.halfway(self.L, self.V)
        light = shading.directional_light(self.L)
        material = shading.Material(ka=0.0, kd=0.0, ks=1.0, shininess=self.n)
        s = float(shading.blinn_phong(None, self.N, self.V, light, material).specular[0])
        self.expected = np.array([*H, s])

    def _groups(self):
        """(name, expected, mistakes) for the vector H and for the number s."""
        N, L, V, n = self.N, self.L, self.V, self.n
        total = L + V
        d = _unit(L - V)
        raw = (r"$H$ must be a unit vector: divide $L + V$ by its length "
               rf"({_num(np.linalg.norm(total))}). Averaging, $(L + V)/2$, is not enough: the "
               r"average of two different unit vectors is shorter than 1.")
        diff = (r"The halfway vector comes from the **sum** $L + V$: it bisects the angle "
                r"between the direction to the light and the direction to the viewer (it is "
                r"the normal a mirror would need to send the light into the eye). "
                r"$L - V$ is perpendicular to that bisector.")
        R = 2 * (N @ L) * N - L
        values = [Mistake([float(N @ total) ** n], raw, "H not normalised"),
                  Mistake([float(N @ total / 2) ** n], raw, "H not normalised"),
                  Mistake([max(float(R @ V), 0.0) ** n], r"That is Phong's $(R \cdot V)^n$. "
                          r"Blinn-Phong replaces it by $(N \cdot H)^n$, which needs no "
                          r"reflected vector (and, with the same $n$, gives a wider "
                          r"highlight).", "Phong's R·V")]
        values += [Mistake([float(N @ (sign * d)) ** n], diff, "L - V") for sign in (1, -1)
                   if float(N @ (sign * d)) > 0]
        return [("the halfway vector H", self.expected[:3],
                 [Mistake(total, raw, "H not normalised"),
                  Mistake(total / 2, raw, "H not normalised"),
                  Mistake(d, diff, "L - V"), Mistake(-d, diff, "L - V")]),
                ("the value s", self.expected[3:], values)]

    def separated(self, mistakes):
        self._parts = self._groups()
        for _, expected, found in self._parts:
            live = [m for m in found if gap(m.value, expected) > SAME]
            if not well_separated(expected, live):
                return False
        return True

    def _judge(self, answer):
        if is_unanswered(answer) or (isinstance(answer, (list, tuple))
                                     and any(is_unanswered(a) for a in answer)):
            return Feedback("unanswered", UNANSWERED)
        values = read_floats(answer)
        if values is None or values.shape != (4,):
            return Feedback("invalid", "Your answer should be 4 numbers: `[Hx, Hy, Hz, s]` "
                            r"with $s = (N \cdot H)^n$.", "unreadable")
        pieces = {"the halfway vector H": values[:3], "the value s": values[3:]}
        wrong = [name for name, expected, _ in self._parts
                 if not close(pieces[name], expected)]
        if not wrong:
            return Feedback("correct", "The halfway vector and the highlight are right.")
        right = [name for name, _, _ in self._parts if name not in wrong]
        summary = (f" Right: {', '.join(right)}." if right else "") + \
            f" Not yet: {', '.join(wrong)}."
        for name, expected, found in self._parts:
            if name in wrong:
                for m in found:
                    if close(pieces[name], m.value) and not close(m.value, expected):
                        return Feedback("wrong", f"*{name[0].upper()}{name[1:]}:* "
                                        f"{m.explanation}{summary}", m.key)
        length = float(np.linalg.norm(values[:3]))
        if "the halfway vector H" in wrong and abs(length - 1) > 1e-3:
            return Feedback("wrong", f"Your H has length {_num(length)}; the halfway vector is "
                            f"a unit vector.{summary}", "value differs")
        return Feedback("wrong", f"Some of your numbers are off.{summary}", "value differs")

    def statement(self):
        return (
            rf"At a surface point with unit normal $N = {_vec(self.N)}$, the unit vector "
            rf"towards the light is $L = {_vec(self.L)}$ and the unit vector towards the viewer "
            rf"is $V = {_vec(self.V)}$. The Blinn-Phong model replaces Phong's "
            r"$(R \cdot V)^n$ by $(N \cdot H)^n$ with the halfway vector $H$. Compute $H$ and "
            rf"$s = \max(N \cdot H, 0)^n$ for $n = {self.n}$." "\n\n"
            r"**Answer:** a list of 4 numbers `[Hx, Hy, Hz, s]`. " + DECIMALS + "\n\n"
            + data_note("N", "L", "V", "n"))


class DistanceAttenuation(DrawnExercise):
    r"""The light of a point light reaching a point: :math:`f_{att}(d)\, I_l`,
    :math:`f_{att}(d) = 1/(a + b d + c d^2)`.

    Attributes: ``P`` (the surface point), ``Q`` (the light), ``Il``, ``a``, ``b``, ``c``.

    Examples
    --------
    >>> ex = DistanceAttenuation(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> d = np.linalg.norm(ex.Q - ex.P)
    >>> ex.check(ex.Il / d).diagnosis
    '1/d'
    """

    title = "Attenuation with distance"
    answer_form = "number"
    what = "the arriving intensity"
    hint = (r"Compute the distance $d = \lVert Q - P \rVert$, then "
            r"$f_{att}(d) = \frac{1}{a + b d + c d^2}$ and multiply by $I_l$.")

    def draw(self, rng):
        self.P = rng.integers(-2, 3, size=3).astype(float)
        d, self._d = _integer_vector(rng)
        self.Q = self.P + d
        self.a = float(pick(rng, (1.0, 1.0, 0.5)))
        self.b = float(pick(rng, (0.0, 0.1, 0.2, 0.25, 0.5)))
        self.c = float(pick(rng, (0.01, 0.02, 0.04, 0.05, 0.1, 0.25)))
        self.Il = float(pick(rng, (1.0, 2.0, 5.0, 10.0)))
        self.expected = self.Il * float(shading.attenuation(self._d, self.a, self.b, self.c))

    def mistakes(self):
        a, b, c, d, Il = self.a, self.b, self.c, self._d, self.Il
        return [
            Mistake(Il / d, r"$1/d$ is not the attenuation used here: the model divides by "
                    r"the whole polynomial $a + b d + c d^2$ (its constant term keeps a light "
                    r"close by from becoming infinitely bright, the quadratic term is the "
                    r"physical inverse-square law).", "1/d"),
            Mistake(Il / d ** 2, r"That is the pure inverse-square law $1/d^2$. The model "
                    r"softens it with a constant and a linear term: "
                    r"$f_{att} = 1/(a + b d + c d^2)$, with the given $a, b, c$.",
                    "inverse square only"),
            Mistake(Il / (a + b * d + c * d), r"The quadratic term is $c\,d^2$: the distance "
                    r"must be squared there.", "d not squared"),
            Mistake(Il / (a + b * d + (c * d) ** 2), r"Only the distance is squared in the "
                    r"quadratic term: $c\,d^2$, not $(c\,d)^2$.", "c squared"),
            Mistake(Il / (a + b * d ** 2 + c * d ** 4), r"You put the **squared** distance in "
                    r"for $d$: $(Q - P) \cdot (Q - P) = d^2$; take its square root first.",
                    "squared distance as d"),
            Mistake(Il * (a + b * d + c * d * d), r"The intensity is **divided** by "
                    r"$a + b d + c d^2$: a light further away gives less light, not more.",
                    "multiplied"),
        ]

    def statement(self):
        return (
            rf"A point light of intensity $I_l = {_num(self.Il)}$ is at $Q = {_vec(self.Q)}$; "
            r"its light is attenuated with the distance $d$ by "
            r"$f_{att}(d) = \frac{1}{a + b d + c d^2}$ with "
            + _material_words(a=self.a, b=self.b, c=self.c) + ". How much light, "
            rf"$f_{{att}}(d)\, I_l$, arrives at the surface point $P = {_vec(self.P)}$?" "\n\n"
            + _ONE_NUMBER + "\n\n" + data_note("P", "Q", "Il", "a", "b", "c"))


class SeveralLights(DrawnExercise):
    r"""A matte surface lit by several distant lights: :math:`I = I_a k_a + k_d \sum_l I_l
    \max(N \cdot L_l, 0)`.

    Attributes: ``N``, ``Ls`` (one unit vector per row), ``Is`` (their intensities), ``Ia``,
    ``ka``, ``kd``.

    Examples
    --------
    >>> ex = SeveralLights(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected + (len(ex.Is) - 1) * ex.Ia * ex.ka).diagnosis
    'ambient per light'
    """

    title = "Several lights"
    answer_form = "number"
    what = "the intensity"
    hint = (r"Each light adds its own diffuse term $k_d I_l \max(N \cdot L_l, 0)$; the ambient "
            r"term $I_a k_a$ is added once.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        m = int(pick(rng, (2, 3)))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        ups = [1.0] * m
        if rng.random() < 0.6:
            ups[int(rng.integers(1, m))] = -1.0
        self.Ls = np.array([_frame(_nice_unit(rng, up=u), axis) for u in ups])
        self.Is = np.array([float(pick(rng, (0.5, 1.0, 1.5, 2.0))) for _ in range(m)])
        self.Ia = float(pick(rng, (0.2, 0.5, 1.0)))
        self.ka = float(pick(rng, (0.1, 0.2, 0.3)))
        self.kd = float(pick(rng, (0.4, 0.5, 0.6, 0.8)))
        lights = [shading.directional_light(L, I) for L, I in zip(self.Ls, self.Is)]
        material = shading.Material(ka=self.ka, kd=self.kd, ks=0.0, shininess=1.0)
        self.expected = float(shading.phong(None, self.N, self.N, lights, material,
                                            ambient=self.Ia).total[0])

    def acceptable(self):
        cos = self.Ls @ self.N
        return bool(np.all(np.abs(cos) > 0.2))

    def mistakes(self):
        cos = self.Ls @ self.N
        amb, kd, m = self.Ia * self.ka, self.kd, len(self.Is)
        lit = self.Is * np.maximum(cos, 0.0)
        found = [
            Mistake(self.expected + (m - 1) * amb, r"The ambient term was added once per "
                    r"light. It does not come from the light sources: $I_a k_a$ is added once, "
                    r"and only the diffuse (and specular) terms are summed over the lights.",
                    "ambient per light"),
            Mistake(amb + kd * lit.sum() / m, r"You averaged the lights. Light adds up: two "
                    r"lamps make a point brighter than one, so the contributions are "
                    r"**summed** (the result may exceed 1; it is clipped only for display).",
                    "averaged"),
            Mistake(amb + kd * lit[0], r"Only the first light is counted. Every light whose "
                    r"$N \cdot L_l > 0$ adds its own term $k_d I_l (N \cdot L_l)$.",
                    "one light only"),
        ]
        if np.any(self.Is != 1):
            found.append(Mistake(amb + kd * np.maximum(cos, 0.0).sum(), r"The intensities "
                                 r"$I_l$ of the lights are missing: each diffuse term is "
                                 r"$k_d\, I_l \max(N \cdot L_l, 0)$.", "intensities ignored"))
        if np.any(cos < 0):
            found.append(Mistake(amb + kd * float(self.Is @ cos), r"A light behind the "
                                 r"surface ($N \cdot L_l < 0$) was counted with its negative "
                                 r"cosine, so it *removed* light. It adds nothing: clamp, "
                                 r"$\max(N \cdot L_l, 0)$.", "no clamp"))
        return found

    def statement(self):
        rows = "\n".join(rf"| {k + 1} | ${_vec(L)}$ | {_num(I)} |"
                         for k, (L, I) in enumerate(zip(self.Ls, self.Is)))
        return (
            rf"A matte surface ($k_d = {_num(self.kd)}$, $k_a = {_num(self.ka)}$, no specular "
            rf"reflection) has the unit normal $N = {_vec(self.N)}$ at a point. The ambient "
            rf"light is $I_a = {_num(self.Ia)}$, and {len(self.Is)} distant lights shine on "
            r"the scene:" "\n\n| light | unit vector $L_l$ towards it | intensity $I_l$ |\n"
            "|---|---|---|\n" + rows + "\n\n"
            r"Compute the intensity of the point according to the Phong model (ambient plus "
            r"diffuse terms)." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("N", "Ls", "Is", "Ia", "ka", "kd") + " (`.Ls[k]`, `.Is[k]` are light "
            "k + 1.)")


# ---------------------------------------------------------------------------------------------
# Interpolated shading
# ---------------------------------------------------------------------------------------------

#: The three interpolated shading methods and what each one interpolates.
SHADING_METHODS = {
    "flat": "one evaluation of the illumination model per polygon, with the face normal",
    "gouraud": "evaluate at the vertices (with vertex normals), interpolate the colours",
    "phong": "interpolate the normals, evaluate at every pixel with the renormalised normal",
}

_NAMES = {"flat": "**Flat shading**", "gouraud": "**Gouraud shading**",
          "phong": "**Phong shading**"}

_WHY = {
    "flat": r"**Flat shading** evaluates the model once per polygon with the face normal and "
            r"paints the whole polygon in that one colour",
    "gouraud": r"**Gouraud shading** evaluates the model only at the vertices and interpolates "
               r"the resulting colours across the polygon",
    "phong": r"**Phong shading** interpolates the normals across the polygon and evaluates the "
             r"model at every pixel with the renormalised normal",
}

#: Situations: (question, right method, {wrong method: why it is wrong}).
_SITUATIONS = (
    (r"A coarse sphere is made of large triangles. The light and the viewer are placed so "
     r"that the mirror direction would meet the eye in the **middle** of one large triangle, "
     r"while at its three vertices $R \cdot V$ is small (no highlight there). Which method "
     r"shows the highlight inside that triangle?",
     "phong",
     {"flat": r": one normal for the whole triangle, so at best the whole triangle lights up "
              r"uniformly (or not at all); a small highlight in its middle cannot appear.",
      "gouraud": r": the colour inside is a blend of the three vertex colours, and none of "
                 r"them has a highlight; a blend of dim colours is dim. The highlight is lost "
                 r"(a highlight that *does* reach a vertex is smeared over the neighbouring "
                 r"triangles instead)."}),
    (r"A rotating, low-polygon model is shaded with a sharp highlight. As it turns, the "
     r"highlight flickers, changes shape, follows the triangle edges and jumps from vertex to "
     r"vertex. Which method produces this artefact?",
     "gouraud",
     {"flat": r" does show facets, but its highlight is a whole triangle lighting up at once, "
              r"not a blob that follows the edges and jumps between vertices.",
      "phong": r" evaluates the highlight at every pixel, so it stays round and moves smoothly; "
               r"it is the cure for this artefact, not its cause."}),
    (r"The illumination model may be evaluated only at the **vertices** (per-vertex lighting "
     r"in hardware), yet the colour must vary continuously across the edges of a smooth, "
     r"curved surface. Which method fits?",
     "gouraud",
     {"flat": r" gives each polygon a single colour, so the colour jumps at every edge "
              r"(facets show), and it evaluates per polygon rather than per vertex.",
      "phong": r" needs an evaluation of the model at every **pixel**, which the constraint "
               r"rules out."}),
    (r"A cut gemstone, a genuinely faceted object, should be drawn with every face in one "
     r"uniform colour, at the lowest cost. Which method?",
     "flat",
     {"gouraud": r" with averaged vertex normals smooths over the edges that should stay sharp "
                 r"and costs an evaluation per vertex plus an interpolation per pixel.",
      "phong": r" costs an evaluation per pixel and, with averaged normals, rounds the facets "
               r"off; a face of one uniform colour needs one evaluation only."}),
    (r"Which method needs the most evaluations of the illumination model for a triangle that "
     r"covers many pixels, and why is that the price of correct highlights?",
     "phong",
     {"flat": r" evaluates the model once per polygon: the cheapest of the three.",
      "gouraud": r" evaluates it once per vertex, three times per triangle, and only blends "
                 r"colours per pixel."}),
    (r"With a distant light and a distant viewer, which method makes every triangle of a "
     r"curved mesh a single uniform colour, so that the mesh looks faceted (and Mach bands "
     r"accentuate the edges)?",
     "flat",
     {"gouraud": r" interpolates vertex colours, so the colour changes continuously across "
                 r"edges: no facets (only a slope change at the edges).",
      "phong": r" interpolates the normals, so the shading varies smoothly across each triangle "
               r"and across its edges."}),
)


def _read_method(answer):
    """One method name from the answer, or a Feedback."""
    form = "Give one of the strings `'flat'`, `'gouraud'` or `'phong'`."
    if is_unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    if not isinstance(answer, str):
        return Feedback("invalid", form, "unreadable")
    name = answer.strip().lower().removesuffix(" shading").strip()
    if name not in SHADING_METHODS:
        return Feedback("invalid", f"{answer!r} is not one of the three methods. " + form,
                        "unreadable")
    return name


class ShadingMethodChoice(DrawnExercise):
    r"""Which interpolated shading method (flat, Gouraud, Phong) fits a situation.

    Every wrong choice is answered with why that method does not fit; the diagnosis is
    ``"chose <method>"``.

    Attributes: ``situation`` (the question), ``methods`` (the three names).

    Examples
    --------
    >>> ex = ShadingMethodChoice(seed=8)
    >>> ex.expected
    'phong'
    >>> ex.check("Phong").status, ex.check("gouraud").diagnosis
    ('correct', 'chose gouraud')
    >>> ex.check("toon").status
    'invalid'
    """

    title = "Flat, Gouraud or Phong shading?"
    answer_form = "custom"
    methods = tuple(SHADING_METHODS)

    def draw(self, rng):
        self.situation, self.expected, self._why = pick(rng, _SITUATIONS)

    def separated(self, mistakes):
        return True

    def _judge(self, answer):
        name = _read_method(answer)
        if isinstance(name, Feedback):
            return name
        if name == self.expected:
            return Feedback("correct", f"{_WHY[name]}: that is what this situation needs.")
        return Feedback("wrong", f"{_NAMES[name]}{self._why[name]} The right choice: "
                        f"{_WHY[self.expected]}.", f"chose {name}")

    def statement(self):
        rows = "\n".join(f"| `'{name}'` | {meaning} |" for name, meaning in SHADING_METHODS.items())
        return (
            self.situation + "\n\n| method | what it does |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** one of the strings `'flat'`, `'gouraud'` or `'phong'`." "\n\n"
            + data_note("situation", "methods"))


def _in_plane(deg):
    """The unit vector in the xz plane at `deg` degrees from +z towards +x."""
    t = math.radians(deg)
    return np.array([math.sin(t), 0.0, math.cos(t)])


def _angle_words(deg):
    return rf"(\sin({deg}^\circ),\ 0,\ \cos({deg}^\circ))"


class GouraudVersusPhong(_Parts):
    r"""The intensity at the midpoint of an edge, by Gouraud and by Phong shading.

    Gouraud blends the two vertex intensities, :math:`\tfrac12 (I_A + I_B)`; Phong shading
    evaluates the model with the renormalised mean normal
    :math:`(N_A + N_B)/\lVert N_A + N_B \rVert`. All vectors lie in the xz plane, given by
    their angles from the z axis.

    Attributes: ``a_deg``, ``b_deg`` (the vertex normals' angles), ``l_deg``, ``v_deg``
    (those of L and V), ``NA``, ``NB``, ``L``, ``V`` (the unit vectors), ``kd``, ``ks``, ``n``.

    Examples
    --------
    >>> ex = GouraudVersusPhong(seed=9)
    >>> ex.check(ex.expected).status
    'correct'
    >>> g, p = ex.expected
    >>> ex.check([p, p]).diagnosis
    'normals interpolated'
    >>> ex.check([g, g]).diagnosis
    'colours interpolated'
    """

    title = "Gouraud against Phong shading"
    form_hint = "`[I_gouraud, I_phong]`."
    hint = (r"Gouraud: evaluate $I = k_d \max(N \cdot L, 0) + k_s \max(R \cdot V, 0)^n$ at "
            r"$A$ and at $B$ and average. Phong: average the normals, normalise, evaluate once.")

    def draw(self, rng):
        while True:                     # a highlight near the midpoint that Gouraud misses
            self.a_deg, self.b_deg = (int(x) for x in np.sort(
                rng.choice(np.arange(-60, 61, 15), 2, replace=False)))
            self.l_deg = int(pick(rng, (-45, -30, -15, 0, 15, 30, 45)))
            self.v_deg = int(pick(rng, (-45, -30, -15, 0, 15, 30, 45)))
            self.kd = float(pick(rng, (0.4, 0.5, 0.6)))
            self.ks = float(pick(rng, (0.3, 0.4, 0.5)))
            self.n = int(pick(rng, (2, 4, 8, 10)))
            self.NA, self.NB = _in_plane(self.a_deg), _in_plane(self.b_deg)
            self.L, self.V = _in_plane(self.l_deg), _in_plane(self.v_deg)
            g = (self._raw(self.NA) + self._raw(self.NB)) / 2
            p = self._raw(_unit(self.NA + self.NB))
            flat = self._raw((self.NA + self.NB) / 2)
            if self.b_deg - self.a_deg >= 30 and p - g > 0.08 \
                    and min(abs(flat - g), abs(flat - p)) > 0.06:
                break
        material = shading.Material(ka=0.0, kd=self.kd, ks=self.ks, shininess=self.n)
        light = shading.directional_light(self.L)
        vertices = shading.phong(None, [self.NA, self.NB], self.V, light, material).total[:, 0]
        middle = shading.phong(None, self.NA + self.NB, self.V, light, material).total[0]
        self.expected = np.array([vertices.mean(), float(middle)])

    def _raw(self, N):
        """kd max(N.L, 0) + ks max(R.V, 0)^n with N used as it is (not normalised)."""
        nl = float(N @ self.L)
        if nl <= 0:
            return 0.0
        R = 2 * nl * N - self.L
        return self.kd * nl + self.ks * max(float(R @ self.V), 0.0) ** self.n

    def parts(self):
        g, p = self.expected
        return [
            ("the Gouraud intensity", g, [
                Mistake(p, r"That is Phong shading: you interpolated the **normals**. Gouraud "
                        r"shading evaluates the model at the two vertices and interpolates the "
                        r"**intensities**: $\tfrac12 (I_A + I_B)$.", "normals interpolated")]),
            ("the Phong intensity", p, [
                Mistake(g, r"That is Gouraud shading: you averaged the vertex intensities. "
                        r"Phong shading averages the **normals**, renormalises, and evaluates "
                        r"the model there, which is how it finds a highlight between the "
                        r"vertices.", "colours interpolated"),
                Mistake(self._raw((self.NA + self.NB) / 2), r"The averaged normal was not "
                        r"renormalised. The mean of two different unit vectors is shorter than "
                        r"1 (here "
                        rf"{_num(np.linalg.norm((self.NA + self.NB) / 2))}), which dims the "
                        r"diffuse term and bends $R$; divide it by its length.",
                        "not renormalised")]),
        ]

    def statement(self):
        return (
            r"An edge of a triangle mesh runs from vertex $A$ to vertex $B$. All vectors here "
            r"lie in the xz plane and are given by their angle from the z axis (towards +x): "
            rf"the vertex normals are $N_A = {_angle_words(self.a_deg)}$ and "
            rf"$N_B = {_angle_words(self.b_deg)}$, the unit vector towards a distant light "
            rf"(intensity 1) is $L = {_angle_words(self.l_deg)}$ and the unit vector towards a "
            rf"distant viewer is $V = {_angle_words(self.v_deg)}$. The surface reflects "
            r"$I = k_d \max(N \cdot L, 0) + k_s \max(R \cdot V, 0)^n$ with "
            + _material_words(k_d=self.kd, k_s=self.ks, n=self.n) + " (no ambient, no "
            "emission).\n\n"
            r"Compute the intensity at the **midpoint** of the edge (1) with Gouraud shading "
            r"and (2) with Phong shading." "\n\n"
            r"**Answer:** a list of 2 numbers `[I_gouraud, I_phong]`. " + DECIMALS + "\n\n"
            + data_note("a_deg", "b_deg", "l_deg", "v_deg", "NA", "NB", "L", "V", "kd", "ks",
                        "n"))


# ---------------------------------------------------------------------------------------------
# Ambient occlusion
# ---------------------------------------------------------------------------------------------

class AmbientOcclusionSamples(DrawnExercise):
    r"""Ambient occlusion estimated from cosine-weighted sample rays: the fraction unblocked.

    A ray is blocked when it hits something within the maximum distance :math:`D`. With
    cosine-weighted directions the estimate is simply the number of unblocked rays over the
    number of rays: the cosine is already in the sampling.

    Attributes: ``cos_theta`` (each ray's cosine with the normal), ``hits`` (the distance of
    its first hit, ``inf`` for a miss), ``D``.

    Examples
    --------
    >>> ex = AmbientOcclusionSamples(seed=10)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(1 - ex.expected).diagnosis
    'occlusion instead of visibility'
    """

    title = "Ambient occlusion from sample rays"
    answer_form = "number"
    what = "the ambient-occlusion factor"
    hint = (r"Count the rays that are **not** blocked (no hit, or a hit beyond $D$) and divide "
            r"by the number of rays.")

    def draw(self, rng):
        k = int(pick(rng, (8, 10, 12)))
        self.D = float(pick(rng, (1.0, 2.0)))
        kinds = rng.choice(3, size=k, p=[0.4, 0.35, 0.25])       # miss, near hit, far hit
        near = rng.choice(np.arange(0.1, 1.0, 0.1).round(1), size=k) * self.D
        far = self.D + rng.choice(np.arange(0.5, 3.0, 0.5), size=k)
        self.hits = np.where(kinds == 0, np.inf, np.where(kinds == 1, near, far))
        # as in a crease: the rays near the horizon (small cosine) are the ones that hit
        steep = rng.choice(np.arange(0.5, 1.0, 0.1).round(1), size=k)
        flat = rng.choice(np.arange(0.1, 0.6, 0.1).round(1), size=k)
        self.cos_theta = np.where(kinds == 0, steep, flat)
        self._open = (self.hits > self.D).astype(float)
        self.expected = float(self._open.mean())

    def acceptable(self):
        return 0 < self.expected < 1 and np.any(np.isfinite(self.hits) & (self.hits > self.D))

    def mistakes(self):
        v, c = self._open, self.cos_theta
        twice = (r"The cosine was counted twice. The directions were drawn with density "
                 r"$\cos\theta / \pi$, so the cosine of $\frac{1}{\pi}\int v \cos\theta\, "
                 r"d\omega$ is already in the sampling: each ray counts 1 (open) or 0 "
                 r"(blocked), and the estimate is their plain average.")
        return [
            Mistake(1 - self.expected, r"That is the fraction of **blocked** rays, the "
                    r"occlusion. The factor that multiplies the ambient term is the open "
                    r"fraction (1 on an open plane, smaller in creases).",
                    "occlusion instead of visibility"),
            Mistake(float(v @ c / c.sum()), twice, "cosine twice"),
            Mistake(float(v @ c / len(c)), twice, "cosine twice"),
            Mistake(float(np.isinf(self.hits).mean()), r"Hits further away than the maximum "
                    r"distance $D$ do not occlude: only nearby geometry darkens a point (a "
                    r"distant wall should not). Count those rays as open.",
                    "maximum distance ignored"),
            Mistake(self.expected / math.pi, r"No factor $1/\pi$ here: with cosine-weighted "
                    r"sampling the $1/\pi$ of the integral cancels against the density, and "
                    r"the estimate is just the fraction of open rays (1 for an open plane).",
                    "divided by pi"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {i + 1} | {_num(c)} | "
                         + ("no hit" if np.isinf(h) else _num(h)) + " |"
                         for i, (c, h) in enumerate(zip(self.cos_theta, self.hits)))
        return (
            rf"To estimate the ambient occlusion of a point, {len(self.hits)} rays were shot "
            r"from it into the hemisphere above its surface, in directions drawn with the "
            r"cosine-weighted density $\cos\theta/\pi$ ($\theta$ the angle from the normal). "
            r"For each ray the table gives $\cos\theta$ and the distance of the first object it "
            rf"hits. Only objects within the maximum distance $D = {_num(self.D)}$ occlude." "\n\n"
            "| ray | $\\cos\\theta$ | first hit at distance |\n|---|---|---|\n" + rows + "\n\n"
            r"Give the ambient-occlusion factor $AO$ that multiplies the ambient term "
            r"(1 = fully open, 0 = fully occluded)." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("cos_theta", "hits", "D") + " (`.hits` holds `inf` for no hit.)")


_SIDES = ((3, 4), (4, 3), (5, 12), (12, 5), (6, 8), (8, 6), (1, 1), (2, 2), (8, 15), (15, 8))


class AmbientOcclusionWall(DrawnExercise):
    r"""Closed-form ambient occlusion next to a wall, :math:`\tfrac12 (1 + a/\sqrt{a^2 + h^2})`,
    or in the middle of a trench, :math:`a/\sqrt{a^2 + h^2}`.

    Under cosine-weighted sampling, the directions whose angle from the normal, projected onto
    the vertical plane across the wall, is at least :math:`\beta` make up the fraction
    :math:`(1 - \sin\beta)/2`; the wall seen from the point spans the projected angles from
    :math:`\beta_0 = \arctan(a/h)` down to the horizon.

    Attributes: ``kind`` (``"wall"`` or ``"trench"``), ``a`` (distance to the wall, or the
    trench's half-width), ``h`` (the height of the wall or the depth of the trench).

    Examples
    --------
    >>> ex = AmbientOcclusionWall(seed=11)
    >>> ex.kind, ex.check(ex.expected).status
    ('wall', 'correct')
    >>> ex.check(1 - ex.expected).diagnosis
    'occlusion instead of visibility'
    """

    title = "Ambient occlusion next to a wall"
    answer_form = "number"
    what = "the ambient-occlusion factor"
    hint = (r"The top edge of the wall is seen at $\beta_0 = \arctan(a/h)$ from the normal, "
            r"$\sin\beta_0 = a/\sqrt{a^2 + h^2}$; the wall blocks the directions beyond it, "
            r"the fraction $(1 - \sin\beta_0)/2$.")

    def draw(self, rng):
        self.kind = str(pick(rng, ("wall", "wall", "trench")))
        self.a, self.h = (float(x) for x in pick(rng, _SIDES))
        self.expected = shading.ambient_occlusion_closed_form(self.kind, self.a, self.h)

    def mistakes(self):
        a, h = self.a, self.h
        s = a / math.hypot(a, h)
        walls = 1 if self.kind == "wall" else 2
        uniform = 1 - walls * math.atan(h / a) / math.pi
        found = [
            Mistake(1 - self.expected, r"That is the **occluded** fraction. The ambient-"
                    r"occlusion factor is the open fraction, the part of the cosine-weighted "
                    r"hemisphere that sees the sky.", "occlusion instead of visibility"),
            Mistake(1 - walls * (1 - h / math.hypot(a, h)) / 2,
                    r"$a$ and $h$ are swapped. The top edge of the wall is seen at the angle "
                    r"$\beta_0$ from the **normal** (vertical) with $\tan\beta_0 = a/h$ (the "
                    r"horizontal distance over the height), so $\sin\beta_0 = a/\sqrt{a^2 + "
                    r"h^2}$.", "a and h swapped"),
            Mistake(uniform, r"You measured the blocked part by its angle, "
                    r"$\arctan(h/a)$ out of $\pi$. Ambient occlusion weights directions by "
                    r"$\cos\theta$: directions near the horizon, which the wall blocks first, "
                    r"count little. The weighted fraction beyond the projected angle "
                    r"$\beta$ is $(1 - \sin\beta)/2$.", "angles, not cosine-weighted"),
        ]
        if self.kind == "wall":
            found.append(Mistake(s, r"That is the value for a **trench**, with walls on both "
                                 r"sides. One wall blocks only the directions on its side: "
                                 r"$(1 - \sin\beta_0)/2$ of them, so "
                                 r"$AO = 1 - \frac{1 - \sin\beta_0}{2} = "
                                 r"\frac{1 + \sin\beta_0}{2}$.", "two walls"))
        else:
            found.append(Mistake((1 + s) / 2, r"That is the value for **one** wall. The trench "
                                 r"has a wall on each side, and each blocks "
                                 r"$(1 - \sin\beta_0)/2$: $AO = 1 - (1 - \sin\beta_0) = "
                                 r"\sin\beta_0$.", "one wall"))
        return found

    def statement(self):
        if self.kind == "wall":
            scene = (
                rf"A point lies on a flat floor at the distance $a = {_num(self.a)}$ from the "
                rf"foot of a vertical wall of height $h = {_num(self.h)}$, infinitely long in "
                r"both directions along the floor.")
        else:
            scene = (
                r"A point lies in the middle of the flat floor of a trench, infinitely long, "
                rf"with vertical walls of depth $h = {_num(self.h)}$ on both sides at the "
                rf"distance $a = {_num(self.a)}$ from the point (the trench is $2a$ wide).")
        return (
            scene + r" Nothing else is in the scene, and rays of any length count. Compute the "
            r"cosine-weighted ambient-occlusion factor "
            r"$AO = \frac{1}{\pi}\int_\Omega v(\omega) \cos\theta\, d\omega$ of the point "
            r"($v = 1$ for a direction that escapes, 0 for one that hits a wall)." "\n\n"
            r"Useful fact: among cosine-weighted directions, those whose angle from the normal, "
            r"projected onto the vertical plane across the wall(s), lies beyond $\beta$ on one "
            r"side make up the fraction $(1 - \sin\beta)/2$." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("kind", "a", "h"))


#: The exercises of chapter 12, in the order of the solutions notebook.
EXERCISES = (
    ReflectionVector,
    DiffuseTerm,
    SpecularTerm,
    PhongTotal,
    BlinnPhongHighlight,
    DistanceAttenuation,
    SeveralLights,
    ShadingMethodChoice,
    GouraudVersusPhong,
    AmbientOcclusionSamples,
    AmbientOcclusionWall,
)
