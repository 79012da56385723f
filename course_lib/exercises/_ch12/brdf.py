"""Chapter 12 exercises: BRDFs (Lambert, the Phong lobe's normalisation, energy, Schlick).

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

from ...shading import brdf
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _n4, _num

__all__ = [
    "LambertRadiance",
    "LobeReflectance",
    "PhongNormalization",
    "SchlickFresnel",
]


class LambertRadiance(DrawnExercise):
    r"""Radiance reflected by a Lambertian surface under a point light:
    :math:`L_r = \frac{\rho}{\pi}\,\frac{I\cos\theta}{d^2}`.

    Attributes: ``albedo`` (:math:`\rho`), ``I`` (the light's intensity, W/sr), ``d`` (its
    distance), ``cos_theta`` (the cosine of the angle of incidence).

    Examples
    --------
    >>> ex = LambertRadiance(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected * math.pi).diagnosis
    'forgot 1/pi'
    """

    title = "Radiance of a Lambertian surface"
    answer_form = "number"
    what = "the reflected radiance"
    advice = (r"The BRDF is $f_r = \rho/\pi$, the irradiance $E = I\cos\theta/d^2$, and "
              r"$L_r = f_r\,E$.")

    def draw(self, rng):
        self.albedo = float(pick(rng, (0.2, 0.3, 0.4, 0.5, 0.6, 0.75, 0.8, 0.9)))
        self.I = float(pick(rng, (4.0, 5.0, 8.0, 10.0, 12.0, 20.0, 50.0)))
        self.d = float(pick(rng, (2.0, 3.0, 4.0, 5.0)))
        self.cos_theta = float(pick(rng, (0.5, 0.6, 0.8)))
        self.E = self.I * self.cos_theta / self.d ** 2
        self.expected = self.albedo / math.pi * self.E

    def mistakes(self):
        rho, I, d, c = self.albedo, self.I, self.d, self.cos_theta
        return [
            Mistake(rho * self.E, r"The factor $1/\pi$ is missing. A Lambertian BRDF is "
                    r"$\rho/\pi$, not $\rho$: the reflected radiance, integrated with "
                    r"$\cos\theta$ over the hemisphere, gives $\pi$ times itself, so only "
                    r"$\rho/\pi$ reflects the fraction $\rho$.", "forgot 1/pi"),
            Mistake(rho / (2 * math.pi) * self.E, r"You divided by $2\pi$, the solid angle of "
                    r"the hemisphere. The normalisation integral carries the cosine: "
                    r"$\int_\Omega\cos\theta\,d\omega = \pi$, so the BRDF is $\rho/\pi$.",
                    "1/(2 pi)"),
            Mistake(rho / math.pi * I / d ** 2, r"The cosine of the angle of incidence is "
                    r"missing: the irradiance of a point light is $E = I\cos\theta/d^2$ "
                    r"(Lambert's law: a tilted surface catches less light).",
                    "cosine forgotten"),
            Mistake(rho / math.pi * I * c / d, r"The distance must be squared: the irradiance "
                    r"falls as $1/d^2$ (inverse-square law).", "distance not squared"),
        ]

    def statement(self):
        return (
            rf"A matte (Lambertian) surface of albedo $\rho = {_num(self.albedo)}$ is lit by a "
            rf"point light of intensity $I = {_num(self.I)}$ W/sr at distance "
            rf"$d = {_num(self.d)}$ m; the light arrives at an angle $\theta$ from the normal "
            rf"with $\cos\theta = {_num(self.cos_theta)}$. Nothing else lights the surface." "\n\n"
            r"What radiance $L_r$ (W/(m² sr)) does the surface reflect towards a viewer? "
            r"(Does it depend on where the viewer is?)" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("albedo", "I", "d", "cos_theta"))

    def hints(self):
        return [r"Reflected radiance = BRDF $\times$ irradiance, $L_r = f_r\,E$, for one "
                r"point light.",
                r"The Lambertian BRDF is $f_r = \rho/\pi$ in 1/sr, the same for every viewer.",
                rf"$E = I\cos\theta/d^2 = {_num(self.I)}\cdot{_num(self.cos_theta)}/"
                rf"{_num(self.d)}^2 = {_n4(self.E)}$ W/m²."]

    def worked(self):
        return Worked([
            rf"BRDF: $f_r = \rho/\pi = {_num(self.albedo)}/\pi = "
            rf"{_n4(self.albedo / math.pi)}$ sr⁻¹ (every viewing direction).",
            rf"Irradiance: $E = I\cos\theta/d^2 = {_num(self.I)}\cdot{_num(self.cos_theta)}/"
            rf"{_num(self.d)}^2 = {_n4(self.E)}$ W/m².",
            rf"$L_r = f_r E = {_n4(self.albedo / math.pi)}\cdot{_n4(self.E)} = "
            rf"{_n4(self.expected)}$ W/(m² sr), the same from everywhere.",
        ], self.expected)


class PhongNormalization(DrawnExercise):
    r"""The constant :math:`C = (n+2)/(2\pi)` that makes the Phong lobe
    :math:`C\,k_s\cos^n\alpha` reflect :math:`k_s` at normal incidence.

    At normal incidence :math:`R = N`, :math:`\alpha = \theta_v`, and
    :math:`\int_\Omega\cos^n\theta\cos\theta\,d\omega = 2\pi/(n+2)`.

    Attributes: ``n`` (the exponent).

    Examples
    --------
    >>> ex = PhongNormalization(seed=0)
    >>> ex.check((ex.n + 2) / (2 * math.pi)).status
    'correct'
    >>> ex.check((ex.n + 1) / (2 * math.pi)).diagnosis
    'cos(theta) forgotten'
    """

    title = "Normalising a Phong lobe"
    answer_form = "number"
    what = "the normalisation constant"
    advice = (r"At normal incidence $\int_\Omega \cos^n\theta\cos\theta\,d\omega = 2\pi\int_0^1 "
              r"u^{n+1}\,du$ with $u = \cos\theta$; $C$ is one over it.")

    def draw(self, rng):
        self.n = int(pick(rng, (2, 3, 4, 5, 6, 8, 10, 14, 18, 20, 30, 48, 62, 98, 100, 198)))
        self.expected = float(brdf.phong_normalization(self.n))

    def mistakes(self):
        n = self.n
        return [
            Mistake((n + 1) / (2 * math.pi), r"You integrated $\cos^n\theta$ alone, giving "
                    r"$2\pi/(n+1)$. The reflectance weighs the outgoing radiance by the "
                    r"projected solid angle, $\cos\theta_v\,d\omega_v$: the integrand is "
                    r"$\cos^{n+1}\theta$.", "cos(theta) forgotten"),
            Mistake(1 / (2 * math.pi), r"The exponent matters: a sharper lobe (larger $n$) "
                    r"covers a smaller solid angle, so it must be taller to reflect the same "
                    r"energy. $1/(2\pi)$ is only the solid angle of the hemisphere.",
                    "exponent ignored"),
            Mistake((n + 2) / math.pi, r"The azimuth runs over $2\pi$, not $\pi$: "
                    r"$\int_0^{2\pi} d\phi \int_0^{\pi/2}\cos^{n+1}\theta\sin\theta\,d\theta = "
                    r"2\pi/(n+2)$.", "azimuth over pi"),
            Mistake(2 * math.pi / (n + 2), r"That is the integral itself, $2\pi/(n+2)$ (what "
                    r"the unnormalised lobe reflects). The constant must **undo** it: its "
                    r"reciprocal.", "integral, not its reciprocal"),
        ]

    def statement(self):
        return (
            rf"A specular lobe is modelled by the BRDF $f_r(l, v) = C\,k_s \cos^{{{self.n}}}"
            r"\alpha$, where $\alpha$ is the angle between the viewing direction and the mirror "
            r"direction of the light." "\n\n"
            r"Find the constant $C$ such that, for light arriving along the normal, the surface "
            r"reflects exactly the fraction $k_s$ of the incoming energy (its "
            r"directional-hemispherical reflectance is $k_s$)." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("n"))

    def hints(self):
        return [r"The reflectance is $\rho = \int_\Omega f_r\cos\theta_v\,d\omega_v$ with "
                r"$d\omega = \sin\theta\,d\theta\,d\phi$.",
                r"With light along the normal the mirror direction is the normal, so "
                r"$\alpha = \theta_v$ and the integrand is $C k_s\cos^{n+1}\theta\sin\theta$.",
                r"Substitute $u = \cos\theta$: $\int_0^{2\pi}\!\!\int_0^1 u^{n+1}\,du\,d\phi = "
                r"2\pi/(n+2)$."]

    def worked(self):
        n = self.n
        return Worked([
            r"$\rho = C k_s \int_0^{2\pi}\!\!\int_0^{\pi/2} \cos^{n}\theta\,\cos\theta\,"
            r"\sin\theta\,d\theta\,d\phi$ (at normal incidence $\alpha = \theta$).",
            rf"With $u = \cos\theta$: $2\pi\int_0^1 u^{{{n + 1}}}\,du = 2\pi/{n + 2} = "
            rf"{_n4(2 * math.pi / (n + 2))}$.",
            rf"$\rho = k_s$ needs $C = {n + 2}/(2\pi) = {_n4(self.expected)}$ sr⁻¹.",
        ], self.expected)


class LobeReflectance(DrawnExercise):
    r"""Reflectance at normal incidence of a diffuse + *unnormalised* Phong BRDF,
    :math:`f_r = k_d/\pi + k_s\cos^n\alpha`: :math:`\rho = k_d + 2\pi k_s/(n+2)`.

    Attributes: ``kd``, ``ks``, ``n``. The variants include lobes that reflect more than the
    light they receive (small n) and ones that lose most of it (large n).

    Examples
    --------
    >>> ex = LobeReflectance(seed=2)
    >>> ex.check(ex.kd + 2 * math.pi * ex.ks / (ex.n + 2)).status
    'correct'
    >>> ex.check(ex.kd + ex.ks).diagnosis
    'normalised lobe assumed'
    """

    title = "Energy of an unnormalised Phong BRDF"
    answer_form = "number"
    what = "the reflectance"
    advice = (r"Integrate each part against $\cos\theta_v\,d\omega_v$: the diffuse part gives "
              r"$k_d$, the lobe (at normal incidence) $2\pi k_s/(n+2)$.")

    def draw(self, rng):
        self.kd = float(pick(rng, (0.2, 0.3, 0.4, 0.5, 0.6)))
        self.ks = float(pick(rng, (0.1, 0.2, 0.3, 0.4, 0.5)))
        self.n = int(pick(rng, (1, 2, 3, 4, 6, 8, 10, 20, 30, 50, 100)))
        self.expected = self.kd + 2 * math.pi * self.ks / (self.n + 2)

    def mistakes(self):
        kd, ks, n = self.kd, self.ks, self.n
        return [
            Mistake(kd + ks, r"The lobe is **not** normalised: $k_s\cos^n\alpha$ reflects "
                    r"$2\pi k_s/(n+2)$, not $k_s$ (only the lobe times $(n+2)/(2\pi)$ "
                    r"reflects $k_s$).", "normalised lobe assumed"),
            Mistake(kd + 2 * math.pi * ks / (n + 1), r"The reflectance integral carries "
                    r"$\cos\theta_v$: $\int\cos^n\theta\cos\theta\,d\omega = 2\pi/(n+2)$, not "
                    r"$2\pi/(n+1)$.", "cos(theta) forgotten"),
            Mistake(kd / math.pi + 2 * math.pi * ks / (n + 2), r"The diffuse part $k_d/\pi$ is "
                    r"a BRDF value; integrated against $\cos\theta\,d\omega$ (which gives "
                    r"$\pi$) it reflects $k_d$.", "diffuse BRDF not integrated"),
            Mistake(kd + 2 * ks / (n + 2), r"The $\pi$ of the azimuth integral is missing: "
                    r"$\int_0^{2\pi}d\phi = 2\pi$, so the lobe reflects $2\pi k_s/(n+2)$.",
                    "lost the pi"),
        ]

    def statement(self):
        return (
            rf"A material uses the BRDF $f_r = k_d/\pi + k_s\cos^n\alpha$ with "
            rf"$k_d = {_num(self.kd)}$, $k_s = {_num(self.ks)}$ and $n = {self.n}$ "
            r"($\alpha$ the angle between the viewing direction and the mirror direction). "
            r"The specular lobe is **not** normalised." "\n\n"
            r"Light arrives along the normal. What fraction of its energy does the surface "
            r"reflect (the directional-hemispherical reflectance $\rho$)? Is the material "
            r"energy-conserving for this light?" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("kd", "ks", "n"))

    def hints(self):
        return [r"$\rho = \int_\Omega f_r\cos\theta_v\,d\omega_v$: integrate the two parts "
                r"separately.",
                r"Diffuse: $\frac{k_d}{\pi}\int_\Omega\cos\theta\,d\omega = \frac{k_d}{\pi}\pi "
                r"= k_d$.",
                r"Lobe at normal incidence ($\alpha = \theta_v$): $k_s\,2\pi\int_0^1 u^{n+1}du "
                r"= 2\pi k_s/(n+2)$."]

    def worked(self):
        lobe = 2 * math.pi * self.ks / (self.n + 2)
        verdict = ("more than 1: it creates energy, not plausible" if self.expected > 1 else
                   "at most 1: energy-conserving for this light")
        return Worked([
            rf"Diffuse part: $k_d = {_num(self.kd)}$.",
            rf"Lobe: $2\pi k_s/(n+2) = 2\pi\cdot{_num(self.ks)}/{self.n + 2} = {_n4(lobe)}$.",
            rf"$\rho = {_num(self.kd)} + {_n4(lobe)} = {_n4(self.expected)}$, {verdict}.",
        ], self.expected)


class SchlickFresnel(DrawnExercise):
    r"""Schlick's Fresnel factor :math:`F = F_0 + (1 - F_0)(1 - \cos\theta)^5`,
    :math:`F_0 = ((n_1 - n_2)/(n_1 + n_2))^2`, for light from air onto a dielectric.

    Attributes: ``n2`` (the dielectric's refractive index; air has 1), ``theta_deg``.

    Examples
    --------
    >>> ex = SchlickFresnel(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.f0).diagnosis
    'normal incidence only'
    """

    title = "Schlick's Fresnel approximation"
    answer_form = "number"
    what = "the Fresnel factor"
    advice = r"$F_0 = ((1 - n)/(1 + n))^2$, then $F = F_0 + (1 - F_0)(1 - \cos\theta)^5$."

    def draw(self, rng):
        self.n2 = float(pick(rng, (1.25, 1.33, 1.5, 1.6, 2.0, 2.4)))
        self.theta_deg = float(pick(rng, (60.0, 65.0, 70.0, 75.0, 80.0, 85.0)))
        self.cos_theta = math.cos(math.radians(self.theta_deg))
        self.f0 = float(brdf.schlick_f0(1.0, self.n2))
        self.expected = float(brdf.fresnel_schlick(self.cos_theta, self.f0))

    def mistakes(self):
        f0, c, n = self.f0, self.cos_theta, self.n2
        r = abs(1 - n) / (1 + n)
        return [
            Mistake(f0, r"That is $F_0$, the reflectance at normal incidence. At an angle the "
                    r"reflectance grows, towards 1 at grazing incidence: add "
                    r"$(1 - F_0)(1 - \cos\theta)^5$.", "normal incidence only"),
            Mistake(r + (1 - r) * (1 - c) ** 5, r"$F_0$ is the **square** of "
                    r"$(n_1 - n_2)/(n_1 + n_2)$ (a ratio of amplitudes squared gives a ratio "
                    r"of energies).", "F0 not squared"),
            Mistake(f0 + (1 - f0) * (1 - c), r"The angular term is $(1 - \cos\theta)^5$: "
                    r"the fifth power keeps $F$ close to $F_0$ over most angles and lets it "
                    r"rise steeply only near grazing incidence.", "fifth power forgotten"),
        ]

    def statement(self):
        return (
            rf"Light in air ($n_1 = 1$) falls on a smooth dielectric of refractive index "
            rf"$n_2 = {_num(self.n2)}$ at $\theta = {_num(self.theta_deg)}°$ from the normal." "\n\n"
            r"With Schlick's approximation, what fraction $F$ of the light is reflected?"
            "\n\n" + _ONE_NUMBER + "\n\n" + data_note("n2", "theta_deg"))

    def hints(self):
        return [r"Schlick: $F(\theta) = F_0 + (1 - F_0)(1 - \cos\theta)^5$.",
                r"$F_0 = \left(\frac{n_1 - n_2}{n_1 + n_2}\right)^2$ (0.04 for glass).",
                rf"$F_0 = {_n4(self.f0)}$ and $\cos\theta = {_n4(self.cos_theta)}$."]

    def worked(self):
        term = (1 - self.cos_theta) ** 5
        return Worked([
            rf"$F_0 = ((1 - {_num(self.n2)})/(1 + {_num(self.n2)}))^2 = {_n4(self.f0)}$.",
            rf"$(1 - \cos{_num(self.theta_deg)}°)^5 = (1 - {_n4(self.cos_theta)})^5 = "
            rf"{_n4(term)}$.",
            rf"$F = {_n4(self.f0)} + {_n4(1 - self.f0)}\cdot{_n4(term)} = "
            rf"{_n4(self.expected)}$.",
        ], self.expected)
