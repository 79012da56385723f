"""Chapter 12 exercises: The terms of the Phong model.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import shading
from ..core import (DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, close, data_note,
                    gap, is_unanswered, pick, read_floats, well_separated)
from . import (_DOWN, _DOWN_RV, _ONE_NUMBER, _UP, _UP_DOT, _UP_NH, _UP_RV, _frame, _integer_vector,
               _material_words, _nice_unit, _num, _pair, _unit, _vec)

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
    advice = (r"Use $I_d = k_d\, I_l \max(N \cdot L, 0)$ with the **unit** vector $L$ from the "
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
    advice = (r"Reflect first, $R = 2 (N \cdot L) N - L$, then $I_s = k_s\, I_l \max(R \cdot V, "
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
    advice = (r"Add the four terms: the emission $I_e$, the ambient $I_a k_a$, the diffuse "
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
    advice = (r"$H = (L + V) / \lVert L + V \rVert$ is the unit vector half-way between $L$ "
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
    advice = (r"Each light adds its own diffuse term $k_d I_l \max(N \cdot L_l, 0)$; the ambient "
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
