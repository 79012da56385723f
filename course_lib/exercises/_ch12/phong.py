"""Chapter 12 exercises: The terms of the Phong model.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import shading
from ..core import (DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, close,
                    data_note, gap, is_unanswered, pick, read_floats, rounding_of,
                    well_separated)
from . import (_DOWN, _DOWN_RV, _ONE_NUMBER, _UP, _UP_DOT, _UP_NH, _UP_RV, _Boundary, _dot, _frac,
               _frame, _integer_vector, _length, _material_words, _n4, _nice_unit, _num, _pair,
               _unit, _vec)

__all__ = [
    "BlinnPhongHighlight",
    "DiffuseTerm",
    "DistanceAttenuation",
    "PhongTotal",
    "SeveralLights",
    "SpecularTerm",
]


def _matte(kd):
    return shading.Material(ka=0.0, kd=kd, ks=0.0, shininess=1.0)


#: The boundary case of the exercises where a light may be behind the surface.
BEHIND = "light behind the surface"


class DiffuseTerm(_Boundary, DrawnExercise):
    r"""The diffuse term :math:`I_d = k_d I_l \max(N \cdot L, 0)` (Lambert's cosine law).

    Two kinds of variant: ``kind == "position"`` gives the surface point ``P``, its unit normal
    ``N`` and the position ``Q`` of a point light (so :math:`L` must be normalised);
    ``kind == "angle"`` gives the angle of incidence ``theta_deg`` between :math:`N` and
    :math:`L`, in degrees. In the boundary variant (``boundary == "light behind the
    surface"``, about 15 % of the seeds) :math:`N \cdot L < 0` and the answer is 0; otherwise
    ``boundary`` is None and the light is in front of the surface.

    Attributes: ``kind``, ``kd``, ``Il``, ``boundary``, and ``P``, ``N``, ``Q`` or
    ``theta_deg``.

    Examples
    --------
    >>> ex = DiffuseTerm(seed=3)
    >>> ex.kind, ex.boundary, ex.check(ex.expected).status
    ('position', None, 'correct')
    >>> ex.check(ex.kd * ex.Il * (ex.N @ (ex.Q - ex.P))).diagnosis
    'L not normalised'
    >>> ex = DiffuseTerm(seed=6)
    >>> ex.kind, ex.check(ex.kd * ex.Il * np.cos(ex.theta_deg)).diagnosis
    ('angle', 'degrees')
    >>> behind = next(DiffuseTerm(seed=s) for s in range(50) if DiffuseTerm(seed=s).boundary)
    >>> behind.boundary, behind.expected, behind.check(0).status
    ('light behind the surface', 0.0, 'correct')
    """

    title = "The diffuse term"
    answer_form = "number"
    what = "the diffuse intensity"
    may_coincide = ("sine",)
    boundary_cases = (BEHIND,)
    advice = (r"Use $I_d = k_d\, I_l \max(N \cdot L, 0)$ with the **unit** vector $L$ from the "
              r"point towards the light; $N \cdot L = \cos\theta$, the cosine of the angle of "
              r"incidence measured from the normal.")

    def draw(self, rng):
        self.kd = float(pick(rng, (0.4, 0.5, 0.6, 0.8)))
        self.Il = float(pick(rng, (1.0, 1.5, 2.0, 0.5)))
        if rng.random() < 0.4:
            self.kind = "angle"
            self.theta_deg = int(pick(rng, (105, 120, 135, 150, 165) if self.boundary else
                                      (15, 30, 45, 60, 75)))
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
            if (self.N @ d < 0) != bool(self.boundary):     # the light on the side asked for
                d = -d
            self.Q = self.P + d
            light = shading.point_light(self.Q, self.Il)
            self.expected = float(shading.phong(self.P, self.N, self.N, light,
                                                _matte(self.kd)).diffuse[0])

    def acceptable(self):
        if self.kind == "angle":
            return True
        cos = float(self.N @ (self.Q - self.P)) / self._distance
        return -0.99 < cos < -0.15 if self.boundary else 0.15 < cos < 0.99

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

    def _cosine(self):
        """N . L as a student works it out: (the steps, the value)."""
        if self.kind == "angle":
            cos = math.cos(self.theta_deg * math.pi / 180)
            return [rf"The angle of incidence is given: $N \cdot L = \cos\theta = "
                    rf"\cos {self.theta_deg}^\circ = {_n4(cos)}$ (in radians, "
                    rf"${self.theta_deg}^\circ = {self.theta_deg}\pi/180 = "
                    rf"{_n4(self.theta_deg * math.pi / 180)}$)."], cos
        d = np.asarray(self.Q, dtype=float) - np.asarray(self.P, dtype=float)
        distance = math.sqrt(float(d @ d))
        L = d / distance
        return [rf"$L$ points from the surface point to the light: $Q - P = {_vec(d)}$, of "
                rf"length ${_length(d)}$, so $L = (Q - P) / {_num(distance)} = {_vec(L)}$.",
                rf"$N \cdot L = {_dot(self.N, L)}$."], float(np.asarray(self.N) @ L)

    def hints(self):
        _, cos = self._cosine()
        if self.kind == "angle":
            second = (rf"$N \cdot L$ is the cosine of the given angle, $\cos {self.theta_deg}"
                      r"^\circ$: the angle is in **degrees** (`np.cos` wants radians, "
                      rf"${self.theta_deg}^\circ = {self.theta_deg}\pi/180$).")
        else:
            d = self.Q - self.P
            second = (r"$L$ is the **unit** vector from the point towards the light, "
                      rf"$L = (Q - P)/\lVert Q - P \rVert$: here $Q - P = {_vec(d)}$, of length "
                      rf"{_num(self._distance)}.")
        if cos < 0:
            third = (rf"Here $N \cdot L = {_frac(cos)}$, a negative cosine: where is the light? "
                     r"What does $\max(N \cdot L, 0)$ make of it?")
        else:
            third = (rf"Here $N \cdot L = {_frac(cos)}$; multiply it by "
                     rf"$k_d I_l = {_num(self.kd)} \cdot {_num(self.Il)}$.")
        return [r"Lambert's cosine law: $I_d = k_d\, I_l \max(N \cdot L, 0)$, where "
                r"$N \cdot L$ is the cosine of the angle between the normal and the direction "
                r"towards the light.", second, third]

    def worked(self):
        steps, cos = self._cosine()
        if cos < 0:
            steps.append(rf"**The boundary case:** $N \cdot L = {_n4(cos)} < 0$, the light is "
                         r"behind the surface. The clamp gives $\max(N \cdot L, 0) = 0$: the "
                         r"point gets no direct light (without the clamp the light would "
                         r"*remove* light).")
        clamped = max(cos, 0.0)
        value = self.kd * self.Il * clamped
        steps.append(rf"$I_d = k_d\, I_l \max(N \cdot L, 0) = {_num(self.kd)} \cdot "
                     rf"{_num(self.Il)} \cdot {_n4(clamped)} = {_n4(value)}$.")
        return Worked(steps, value)


def _rv(N, L, V):
    """R . V for unit N, L, V."""
    R = 2 * (N @ L) * N - L
    return float(R @ V)


#: The boundary case of the exercises where the viewer may see no highlight.
AWAY = "viewer away from the mirror direction"


class SpecularTerm(_Boundary, DrawnExercise):
    r"""The specular term :math:`I_s = k_s I_l \max(R \cdot V, 0)^n` of the Phong model.

    In the boundary variant (``boundary == "viewer away from the mirror direction"``, about
    15 % of the seeds) :math:`R \cdot V < 0` and the answer is 0; otherwise ``boundary`` is
    None and the viewer sees a clear highlight.

    Attributes: ``N``, ``L``, ``V`` (unit vectors), ``ks``, ``Il``, ``n`` (the exponent),
    ``boundary``.

    Examples
    --------
    >>> ex = SpecularTerm(seed=3)
    >>> ex.boundary, ex.check(ex.expected).status
    (None, 'correct')
    >>> ex.check(ex.ks * ex.Il * (ex.N @ ex.L) ** ex.n).diagnosis
    'N·L instead of R·V'
    >>> away = next(SpecularTerm(seed=s) for s in range(50) if SpecularTerm(seed=s).boundary)
    >>> away.boundary, away.expected
    ('viewer away from the mirror direction', 0.0)
    """

    title = "The specular term"
    answer_form = "number"
    what = "the specular intensity"
    boundary_cases = (AWAY,)
    #: With R . V < 0 these slips give the right answer, 0, as well.
    may_coincide = ("no exponent", "exponent on the coefficient")
    advice = (r"Reflect first, $R = 2 (N \cdot L) N - L$, then $I_s = k_s\, I_l \max(R \cdot V, "
              r"0)^n$: only the cosine is raised to the power $n$.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        rv = _UP_RV                     # directions with a clear highlight, or clearly none
        ok = (_UP_DOT < 0.99) & (((rv > -0.9) & (rv < -0.3)) if self.boundary else (rv > 0.5))
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

    def hints(self):
        nl = float(self.N @ self.L)
        R = 2 * nl * self.N - self.L
        rv = float(R @ self.V)
        if rv < 0:
            third = (rf"$R \cdot V = {_frac(rv)}$ is negative: the viewer is more than "
                     r"$90^\circ$ away from the mirror direction. What does the clamp make of "
                     r"it, before the power?")
        else:
            third = (rf"$R \cdot V = {_frac(rv)}$: raise it (only it) to the power "
                     rf"$n = {self.n}$, then scale by $k_s I_l = {_num(self.ks)} \cdot "
                     rf"{_num(self.Il)}$.")
        return [r"The specular term is $I_s = k_s\, I_l \max(R \cdot V, 0)^n$, where $R$ is the "
                r"mirror direction of $L$ about the normal: $R = 2 (N \cdot L) N - L$.",
                rf"Reflect first: $N \cdot L = {_frac(nl)}$, so "
                rf"$R = {_frac(2 * nl)}\, N - L = {_vec(R)}$.", third]

    def worked(self):
        N, L, V = (np.asarray(x, dtype=float) for x in (self.N, self.L, self.V))
        nl = float(N @ L)
        R = 2 * nl * N - L
        rv = float(R @ V)
        steps = [rf"$N \cdot L = {_dot(N, L)}$.",
                 rf"The mirror direction: $R = 2 (N \cdot L) N - L = {_frac(2 * nl)} \cdot "
                 rf"{_vec(N)} - {_vec(L)} = {_vec(R)}$.",
                 rf"$R \cdot V = {_dot(R, V)}$."]
        clamped = max(rv, 0.0)
        value = self.ks * self.Il * clamped ** self.n
        if rv < 0:
            steps.append(r"**The boundary case:** $R \cdot V < 0$, the viewer is more than "
                         r"$90^\circ$ from the mirror direction and sees no highlight: "
                         r"$\max(R \cdot V, 0)^n = 0^n = 0$ (clamp *before* the power: an even "
                         r"power would turn the negative cosine positive).")
        else:
            steps.append(rf"$\max(R \cdot V, 0)^n = {_n4(clamped)}^{{{self.n}}} = "
                         rf"{_n4(clamped ** self.n)}$.")
        steps.append(rf"$I_s = k_s\, I_l \max(R \cdot V, 0)^n = {_num(self.ks)} \cdot "
                     rf"{_num(self.Il)} \cdot {_n4(clamped ** self.n)} = {_n4(value)}$.")
        return Worked(steps, value)


class PhongTotal(_Boundary, DrawnExercise):
    r"""The whole Phong intensity :math:`I = I_e + I_a k_a + k_d I_l \max(N \cdot L, 0)
    + k_s I_l \max(R \cdot V, 0)^n` for one grey light.

    Two boundary variants, together in about 16 % of the seeds: ``boundary == "viewer away
    from the mirror direction"`` (:math:`R \cdot V < 0`, no highlight) and ``boundary ==
    "light behind the surface"`` (:math:`N \cdot L < 0`: neither diffuse nor specular
    light); otherwise ``boundary`` is None and both light terms count.

    Attributes: ``N``, ``L``, ``V``, ``Ie``, ``Ia``, ``ka``, ``kd``, ``ks``, ``n``, ``Il``,
    ``boundary``.

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
    boundary_cases = (AWAY, BEHIND)
    boundary_share = 0.16
    advice = (r"Add the four terms: the emission $I_e$, the ambient $I_a k_a$, the diffuse "
              r"$k_d I_l \max(N \cdot L, 0)$ and the specular $k_s I_l \max(R \cdot V, 0)^n$ "
              r"with $R = 2 (N \cdot L) N - L$; both light terms are 0 when $N \cdot L \le 0$.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        while True:                     # the case asked for, with a clear effect of each slip
            self.kd = float(pick(rng, (0.4, 0.5, 0.6)))
            self.ks = float(pick(rng, (0.2, 0.3, 0.4)))
            self.Il = float(pick(rng, (1.0, 0.8, 1.5)))
            self.n = int(pick(rng, (2, 3, 4, 5)))
            ok = self._clear_case()
            if ok.any():
                break
        first = _DOWN if self.boundary == BEHIND else _UP
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
        behind = self.boundary == BEHIND
        first = _DOWN if behind else _UP
        rv = _DOWN_RV if behind else _UP_RV
        nl = first[:, 2, None] + 0 * rv
        highlight = self.ks * self.Il * np.abs(rv) ** self.n
        if self.boundary is None:
            return (nl > 0.2) & (rv > 0.3)
        if self.boundary == AWAY:
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

    def _terms(self):
        """N . L, R, R . V, the constant part and the two light terms, as on paper."""
        N, L, V = (np.asarray(x, dtype=float) for x in (self.N, self.L, self.V))
        nl = float(N @ L)
        R = 2 * nl * N - L
        rv = float(R @ V)
        constant = self.Ie + self.Ia * self.ka
        diffuse = self.kd * self.Il * nl if nl > 0 else 0.0
        specular = self.ks * self.Il * max(rv, 0.0) ** self.n if nl > 0 else 0.0
        return nl, R, rv, constant, diffuse, specular

    def hints(self):
        nl, R, rv, constant, diffuse, specular = self._terms()
        if nl <= 0:
            third = (rf"$N \cdot L = {_frac(nl)} < 0$: the light is behind the surface. Which "
                     r"of the four terms are left?")
        elif rv < 0:
            third = (rf"$R = {_vec(R)}$ and $R \cdot V = {_frac(rv)} < 0$: what is the "
                     rf"specular term then? The diffuse term is $I_d = {_n4(diffuse)}$.")
        else:
            third = (rf"$R = {_vec(R)}$ and $R \cdot V = {_frac(rv)}$: "
                     rf"$I_d = {_n4(diffuse)}$ and $I_s = {_n4(specular)}$.")
        return [r"Four terms add up: $I = I_e + I_a k_a + k_d I_l \max(N \cdot L, 0) + k_s I_l "
                r"\max(R \cdot V, 0)^n$ with $R = 2 (N \cdot L) N - L$; both light terms are 0 "
                r"when the light is behind the surface.",
                rf"The terms that do not depend on the light: $I_e + I_a k_a = "
                rf"{_num(self.Ie)} + {_num(self.Ia)} \cdot {_num(self.ka)} = {_num(constant)}$. "
                rf"For the light terms, $N \cdot L = {_frac(nl)}$.", third]

    def worked(self):
        nl, R, rv, constant, diffuse, specular = self._terms()
        steps = [rf"Emission and ambient: $I_e + I_a k_a = {_num(self.Ie)} + {_num(self.Ia)} "
                 rf"\cdot {_num(self.ka)} = {_num(constant)}$.",
                 rf"$N \cdot L = {_dot(self.N, self.L)}$."]
        if nl <= 0:
            steps.append(r"**The boundary case:** $N \cdot L < 0$, the light is behind the "
                         r"surface: it adds neither diffuse nor specular light, "
                         r"$I_d = I_s = 0$ (even though $R \cdot V = "
                         rf"{_frac(rv)} > 0$ here: a highlight on the dark side would be "
                         r"wrong).")
        else:
            steps += [rf"Diffuse: $I_d = k_d I_l\, (N \cdot L) = {_num(self.kd)} \cdot "
                      rf"{_num(self.Il)} \cdot {_frac(nl)} = {_n4(diffuse)}$.",
                      rf"Mirror direction: $R = 2 (N \cdot L) N - L = {_vec(R)}$, and "
                      rf"$R \cdot V = {_dot(R, self.V)}$."]
            if rv < 0:
                steps.append(r"**The boundary case:** $R \cdot V < 0$, the viewer is more than "
                             r"$90^\circ$ from the mirror direction: no highlight, "
                             r"$I_s = k_s I_l \max(R \cdot V, 0)^n = 0$.")
            else:
                steps.append(rf"Specular: $I_s = k_s I_l\, (R \cdot V)^n = {_num(self.ks)} "
                             rf"\cdot {_num(self.Il)} \cdot {_n4(rv)}^{{{self.n}}} = "
                             rf"{_n4(specular)}$.")
        total = constant + diffuse + specular
        steps.append(rf"$I = {_num(constant)} + {_n4(diffuse)} + {_n4(specular)} = "
                     rf"{_n4(total)}$.")
        return Worked(steps, total)


#: The boundary case of Blinn-Phong: the halfway vector points into the surface.
BELOW = "halfway vector below the surface"
#: L below the surface (rows), V above it (columns): L . V and N . H for N = +z.
_DOWN_UP_DOT = _DOWN @ _UP.T
_DOWN_UP_NH = (_DOWN[:, 2, None] + _UP[None, :, 2]) / np.sqrt(np.maximum(2 + 2 * _DOWN_UP_DOT,
                                                                         1e-12))


class BlinnPhongHighlight(_Boundary, DrawnExercise):
    r"""Blinn-Phong: the halfway vector :math:`H = (L + V)/\lVert L + V \rVert` and
    :math:`\max(N \cdot H, 0)^n`.

    The answer has two parts, the vector :math:`H` and the number :math:`s`; each is judged
    against the slips anticipated for it. In the boundary variant (``boundary == "halfway
    vector below the surface"``, about 15 % of the seeds) the light is behind the surface and
    :math:`N \cdot H < 0`, so :math:`s = 0`; otherwise ``boundary`` is None.

    Attributes: ``N``, ``L``, ``V`` (unit vectors), ``n`` (the exponent), ``boundary``.

    Examples
    --------
    >>> ex = BlinnPhongHighlight(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> s = ex.L + ex.V
    >>> ex.check([*s, (ex.N @ s) ** ex.n]).diagnosis
    'H not normalised'
    >>> ex.check([1, 2, 3, ...]).status, ex.check([1, 2]).status
    ('unanswered', 'invalid')
    >>> below = next(BlinnPhongHighlight(seed=k) for k in range(50)
    ...              if BlinnPhongHighlight(seed=k).boundary)
    >>> below.boundary, float(below.expected[3])
    ('halfway vector below the surface', 0.0)
    """

    title = "Blinn-Phong's halfway vector"
    answer_form = "custom"
    boundary_cases = (BELOW,)
    advice = (r"$H = (L + V) / \lVert L + V \rVert$ is the unit vector half-way between $L$ "
              r"and $V$; then $s = \max(N \cdot H, 0)^n$.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        self.n = int(pick(rng, (4, 5, 8, 10, 16, 20)))
        if self.boundary:               # light from below, H clearly into the surface
            first = _DOWN
            ok = (_DOWN_UP_DOT > -0.6) & (_DOWN_UP_DOT < 0.6) & (_DOWN_UP_NH < -0.1)
        else:                           # L, V apart; a visible highlight
            first = _UP
            ok = (_UP_DOT < 0.6) & (_UP_NH ** self.n > 0.1)
        if not ok.any():
            self.expected = None
            return
        L, V = _pair(rng, first, _UP, ok)
        self.L, self.V = _frame(L, axis), _frame(V, axis)
        H = shading.halfway(self.L, self.V)
        s = max(float(self.N @ H), 0.0) ** self.n
        self.expected = np.array([*H, s])

    def acceptable(self):
        return self.expected is not None

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
        if self.boundary:
            nh = float(N @ self.expected[:3])
            even = (" (with an even exponent the power even turned it positive)"
                    if n % 2 == 0 else "")
            values = [Mistake([nh ** n], r"Here $N \cdot H < 0$: the halfway vector points "
                              r"into the surface (the light is behind it), and there is no "
                              r"highlight. Clamp before the power, $\max(N \cdot H, 0)^n = 0$"
                              + even + ".", "no clamp")] if abs(nh) ** n > 0.06 else []
        else:
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
        rounded = [name for name, expected, found in self._parts
                   if name in wrong and rounding_of(pieces[name], expected, found)]
        if rounded:
            return Feedback("wrong", f"Close: {' and '.join(rounded)} look rounded to too few "
                            f"digits; give at least 3 significant digits.{summary}", "rounded")
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

    def hints(self):
        total = self.L + self.V
        H = total / np.linalg.norm(total)
        nh = float(self.N @ H)
        if nh < 0:
            third = (rf"$H = {_vec(H)}$ and $N \cdot H = {_n4(nh)}$: negative, the halfway "
                     r"vector points into the surface. What does the clamp give?")
        else:
            third = (rf"$H = {_vec(H)}$ and $N \cdot H = {_n4(nh)}$: raise it to the power "
                     rf"$n = {self.n}$.")
        return [r"The halfway vector is the **unit** bisector of $L$ and $V$: "
                r"$H = (L + V)/\lVert L + V \rVert$; the highlight factor is then "
                r"$s = \max(N \cdot H, 0)^n$ (no reflected vector needed).",
                rf"$L + V = {_vec(total)}$, of length ${_length(total)}$.", third]

    def worked(self):
        N, L, V = (np.asarray(x, dtype=float) for x in (self.N, self.L, self.V))
        total = L + V
        length = float(np.sqrt(total @ total))
        H = total / length
        nh = float(N @ H)
        steps = [rf"$L + V = {_vec(L)} + {_vec(V)} = {_vec(total)}$.",
                 rf"Its length: $\lVert L + V \rVert = {_length(total)}$, so "
                 rf"$H = (L + V) / {_n4(length)} = {_vec(H)}$.",
                 rf"$N \cdot H = {_dot(N, H)}$."]
        s = max(nh, 0.0) ** self.n
        if nh < 0:
            steps.append(r"**The boundary case:** $N \cdot H < 0$: the halfway vector points "
                         r"into the surface, because the light is behind it ($N \cdot L = "
                         rf"{_frac(N @ L)}$). The clamp gives $s = \max(N \cdot H, 0)^n = 0$: "
                         r"no highlight.")
        else:
            steps.append(rf"$s = \max(N \cdot H, 0)^n = {_n4(nh)}^{{{self.n}}} = {_n4(s)}$.")
        return Worked(steps, [*H, s])


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
    advice = (r"Compute the distance $d = \lVert Q - P \rVert$, then "
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

    def _distance(self):
        d = np.asarray(self.Q, dtype=float) - np.asarray(self.P, dtype=float)
        return d, math.sqrt(float(d @ d))

    def hints(self):
        d, dist = self._distance()
        a, b, c = self.a, self.b, self.c
        denominator = a + b * dist + c * dist * dist
        return [r"The light arriving is $f_{att}(d)\, I_l$ with "
                r"$f_{att}(d) = 1/(a + b d + c d^2)$, where $d$ is the distance between the "
                r"light and the surface point.",
                rf"$Q - P = {_vec(d)}$, so $d = {_length(d)}$.",
                rf"$a + b d + c d^2 = {_num(a)} + {_num(b)} \cdot {_num(dist)} + {_num(c)} \cdot "
                rf"{_num(dist)}^2 = {_n4(denominator)}$; divide $I_l$ by it."]

    def worked(self):
        d, dist = self._distance()
        denominator = self.a + self.b * dist + self.c * dist ** 2
        f = 1 / denominator
        value = self.Il * f
        return Worked([
            rf"The distance: $Q - P = {_vec(d)}$, $d = \lVert Q - P \rVert = {_length(d)}$.",
            rf"$a + b d + c d^2 = {_num(self.a)} + {_num(self.b)} \cdot {_num(dist)} + "
            rf"{_num(self.c)} \cdot {_num(dist ** 2)} = {_n4(denominator)}$, so "
            rf"$f_{{att}}(d) = 1 / {_n4(denominator)} = {_n4(f)}$.",
            rf"$f_{{att}}(d)\, I_l = {_n4(f)} \cdot {_num(self.Il)} = {_n4(value)}$.",
        ], value)


class SeveralLights(_Boundary, DrawnExercise):
    r"""A matte surface lit by several distant lights: :math:`I = I_a k_a + k_d \sum_l I_l
    \max(N \cdot L_l, 0)`.

    In the boundary variant (``boundary == "light behind the surface"``, about 15 % of the
    seeds) one of the lights (never the first) is behind the surface and adds nothing;
    otherwise ``boundary`` is None and every light is in front.

    Attributes: ``N``, ``Ls`` (one unit vector per row), ``Is`` (their intensities), ``Ia``,
    ``ka``, ``kd``, ``boundary``.

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
    boundary_cases = (BEHIND,)
    advice = (r"Each light adds its own diffuse term $k_d I_l \max(N \cdot L_l, 0)$; the ambient "
              r"term $I_a k_a$ is added once.")

    def draw(self, rng):
        axis = int(rng.integers(3))
        m = int(pick(rng, (2, 3)))
        self.N = _frame([0.0, 0.0, 1.0], axis)
        ups = [1.0] * m
        if self.boundary:
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

    def _cosines(self):
        return [float(np.asarray(L, dtype=float) @ np.asarray(self.N, dtype=float))
                for L in self.Ls]

    def hints(self):
        cos = self._cosines()
        listed = ", ".join(rf"$N \cdot L_{k + 1} = {_frac(c)}$" for k, c in enumerate(cos))
        terms = [float(I) * max(c, 0.0) for I, c in zip(self.Is, cos)]
        behind = [k + 1 for k, c in enumerate(cos) if c <= 0]
        note = (f" (light {behind[0]} is behind the surface: what does it add?)" if behind
                else "")
        return [r"Light adds up: $I = I_a k_a + k_d \sum_l I_l \max(N \cdot L_l, 0)$. Each "
                r"light brings its own diffuse term; the ambient term is added **once**.",
                rf"The cosines: {listed}{note}.",
                r"The lit sum is $\sum_l I_l \max(N \cdot L_l, 0) = "
                + " + ".join(_n4(t) for t in terms) + rf" = {_n4(sum(terms))}$, and the ambient "
                rf"term is $I_a k_a = {_num(self.Ia * self.ka)}$."]

    def worked(self):
        cos = self._cosines()
        steps = []
        terms = []
        for k, (L, I, c) in enumerate(zip(self.Ls, self.Is, cos), 1):
            term = float(I) * max(c, 0.0)
            terms.append(term)
            if c <= 0:
                steps.append(rf"Light {k}: $N \cdot L_{k} = {_dot(self.N, L)} < 0$. **The "
                             r"boundary case:** this light is behind the surface and adds "
                             r"nothing, $\max(N \cdot L, 0) = 0$ (a negative term would "
                             r"*remove* light).")
            else:
                steps.append(rf"Light {k}: $N \cdot L_{k} = {_dot(self.N, L)}$, so "
                             rf"$I_{k} \max(N \cdot L_{k}, 0) = {_num(I)} \cdot {_frac(c)} = "
                             rf"{_n4(term)}$.")
        lit = sum(terms)
        ambient = self.Ia * self.ka
        value = ambient + self.kd * lit
        steps.append(rf"The ambient term, once: $I_a k_a = {_num(self.Ia)} \cdot {_num(self.ka)}"
                     rf" = {_num(ambient)}$.")
        steps.append(rf"$I = I_a k_a + k_d \sum_l I_l \max(N \cdot L_l, 0) = {_num(ambient)} + "
                     rf"{_num(self.kd)} \cdot {_n4(lit)} = {_n4(value)}$.")
        return Worked(steps, value)
