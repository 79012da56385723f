"""Chapter 12 exercises: Radiometry (irradiance, solid angles, radiance and intensity).

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

from ... import shading
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _Boundary, _n4, _num

__all__ = [
    "PointLightIrradiance",
    "RadianceIntensity",
    "SolidAngle",
]

#: The boundary case of the point-light exercise.
BELOW = "light below the horizon"

#: (horizontal offset x, height h, distance d): Pythagorean triples, so cos(theta) = h / d.
_TRIPLES = ((3, 4, 5), (4, 3, 5), (6, 8, 10), (8, 6, 10), (5, 12, 13), (12, 5, 13),
            (9, 12, 15), (12, 9, 15), (0, 2, 2), (0, 3, 3), (0, 4, 4))


def _deg(x):
    return math.radians(x)


class PointLightIrradiance(_Boundary, DrawnExercise):
    r"""Irradiance from a point light, :math:`E = I\cos\theta / d^2` (inverse-square and cosine laws).

    Two kinds: ``kind == "angle"`` gives the distance ``d`` and the angle ``theta_deg`` between
    the normal and the direction to the light; ``kind == "position"`` gives a light at the
    height ``h`` above a horizontal floor and the horizontal offset ``x`` (so
    :math:`d = \sqrt{x^2 + h^2}` and :math:`\cos\theta = h/d`). In the boundary variant
    (``boundary == "light below the horizon"``, about 15 % of the seeds, angle kind only) the
    angle exceeds 90° and the answer is 0.

    Attributes: ``kind``, ``I`` (W/sr), ``boundary``, and ``d``, ``theta_deg`` or ``x``, ``h``.

    Examples
    --------
    >>> ex = PointLightIrradiance(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> below = next(PointLightIrradiance(seed=s) for s in range(60)
    ...              if PointLightIrradiance(seed=s).boundary)
    >>> below.expected, below.check(0).status
    (0.0, 'correct')
    """

    title = "Irradiance from a point light"
    answer_form = "number"
    what = "the irradiance"
    #: Straight overhead (theta = 0, x = 0) the cosine is 1 and the height is the distance.
    may_coincide = ("cosine forgotten", "height for distance")
    boundary_cases = (BELOW,)
    advice = (r"Use $E = I\cos\theta / d^2$: the intensity, times the cosine of the angle "
              r"between the surface normal and the direction to the light, over the **square** "
              r"of the distance; $E = 0$ when the light is below the horizon.")

    def draw(self, rng):
        self.I = float(pick(rng, (50, 100, 200, 250, 400, 500, 800)))
        if self.boundary or rng.random() < 0.5:
            self.kind = "angle"
            self.d = float(pick(rng, (2, 4, 5, 10)))
            self.theta_deg = int(pick(rng, (105, 120, 135, 150) if self.boundary
                                      else (30, 60, 0, 45)))
            t = _deg(self.theta_deg)
            light = [self.d * math.sin(t), 0.0, self.d * math.cos(t)]
        else:
            self.kind = "position"
            self.x, self.h, _ = (float(v) for v in pick(rng, _TRIPLES))
            light = [self.x, 0.0, self.h]
        self.expected = float(shading.point_light_irradiance([0, 0, 0], [0, 0, 1], light,
                                                             self.I).irradiance)

    def _geometry(self):
        """(cos theta, sin theta, d) as the student finds them."""
        if self.kind == "angle":
            t = _deg(self.theta_deg)
            return math.cos(t), math.sin(t), self.d
        d = math.hypot(self.x, self.h)
        return self.h / d, self.x / d, d

    def mistakes(self):
        cos, sin, d = self._geometry()
        I = self.I
        c = max(cos, 0.0)
        found = [] if cos <= 0 else [
            Mistake(I * c / d, r"That is $I\cos\theta/d$: the irradiance falls with the "
                    r"**square** of the distance. The flux of a solid angle spreads over an "
                    r"area that grows like $d^2$ (the solid angle of a patch is "
                    r"$A\cos\theta/d^2$).", "1/d instead of 1/d^2")]
        found += [
            Mistake(I / d ** 2, r"The cosine law is missing: a patch tilted away from the light "
                    r"catches less of its flux, $E = I\cos\theta/d^2$ with $\theta$ the angle "
                    r"between the normal and the direction to the light.", "cosine forgotten"),
            Mistake(I * max(sin, 0.0) / d ** 2, r"You used the sine. The angle is measured from "
                    r"the **normal**: a light straight overhead ($\theta = 0$) gives the most, "
                    r"$\cos 0 = 1$.", "sine for cosine"),
        ]
        if self.kind == "angle":
            found.append(Mistake(I * math.cos(self.theta_deg) / d ** 2, r"You took the cosine "
                                 rf"of {self.theta_deg} **radians**; the angle is in degrees "
                                 r"(`np.cos(np.radians(theta))`).", "degrees as radians"))
        else:
            found.append(Mistake(I * c / self.h ** 2, r"The distance to the light is not its "
                                 r"height: $d = \sqrt{x^2 + h^2}$, the length of the line from "
                                 r"the point to the light.", "height for distance"))
        if cos < 0:
            found.append(Mistake(I * cos / d ** 2, r"The light is **below** the surface's "
                                 r"horizon ($\theta > 90^\circ$): it does not reach the front "
                                 r"of the surface, so $E = 0$; the cosine is clamped, "
                                 r"$\max(\cos\theta, 0)$, never negative light.", "no clamp"))
        return found

    def statement(self):
        if self.kind == "angle":
            setting = (rf"An isotropic point light of intensity $I = {_num(self.I)}$ W/sr is "
                       rf"at the distance $d = {_num(self.d)}$ m from a surface point; the "
                       r"direction from the point to the light makes the angle "
                       rf"$\theta = {self.theta_deg}^\circ$ with the surface normal.")
            names = ("kind", "I", "d", "theta_deg")
        else:
            where = (r"lies directly below the light ($x = 0$)." if self.x == 0 else
                     rf"lies $x = {_num(self.x)}$ m away horizontally from the foot of the "
                     r"light.")
            setting = (rf"An isotropic point light of intensity $I = {_num(self.I)}$ W/sr hangs "
                       rf"$h = {_num(self.h)}$ m above a horizontal floor. A point on the floor "
                       + where)
            names = ("kind", "I", "x", "h")
        return (setting + r" Compute the irradiance $E$ at the point, in W/m²." "\n\n"
                + _ONE_NUMBER + "\n\n" + data_note(*names))

    def hints(self):
        cos, _, d = self._geometry()
        if self.kind == "angle":
            second = (rf"Here $d^2 = {_num(d * d)}$ and $\cos {self.theta_deg}^\circ = "
                      rf"{_n4(cos)}$ (degrees, not radians).")
        else:
            second = (rf"$d = \sqrt{{x^2 + h^2}} = \sqrt{{{_num(self.x ** 2 + self.h ** 2)}}} = "
                      rf"{_num(d)}$ and $\cos\theta = h/d = {_n4(cos)}$ (the normal is "
                      r"vertical).")
        third = ("What happens when the light is below the horizon, $\\cos\\theta < 0$?"
                 if cos < 0 else rf"$E = {_num(self.I)} \cdot {_n4(cos)} / {_num(d * d)}$.")
        return [r"Two laws: the **inverse-square law** (the flux of a solid angle spreads "
                r"over an area growing like $d^2$) and the **cosine law** (a tilted patch "
                r"catches less): $E = I\cos\theta/d^2$.", second, third]

    def worked(self):
        cos, _, d = self._geometry()
        steps = []
        if self.kind == "position":
            steps.append(rf"The distance: $d = \sqrt{{x^2 + h^2}} = \sqrt{{{_num(self.x ** 2)} + "
                         rf"{_num(self.h ** 2)}}} = {_num(d)}$ m; the normal is vertical, so "
                         rf"$\cos\theta = h/d = {_num(self.h)}/{_num(d)} = {_n4(cos)}$.")
        else:
            steps.append(rf"$\cos\theta = \cos {self.theta_deg}^\circ = {_n4(cos)}$ and "
                         rf"$d^2 = {_num(d * d)}$ m².")
        if cos < 0:
            steps.append(r"**The boundary case:** $\cos\theta < 0$, the light is below the "
                         r"horizon of the surface and does not reach its front: the cosine is "
                         r"clamped to 0.")
        c = max(cos, 0.0)
        value = self.I * c / d ** 2
        steps.append(rf"$E = I\max(\cos\theta, 0)/d^2 = {_num(self.I)} \cdot {_n4(c)} / "
                     rf"{_num(d * d)} = {_n4(value)}$ W/m².")
        return Worked(steps, value)


class SolidAngle(DrawnExercise):
    r"""A solid angle: a cone :math:`2\pi(1-\cos\alpha)`, a small patch :math:`A\cos\theta/d^2`,
    or a region :math:`(\phi_2-\phi_1)(\cos\theta_1-\cos\theta_2)` of the sphere.

    ``kind == "cone"``: the half-angle ``alpha_deg``; answer in sr. ``kind == "patch"``: the area
    ``A_cm2`` (cm²), the distance ``d`` (m) and the tilt ``theta_deg`` of the patch's normal from
    the line of sight; answer in **millisteradians**. ``kind == "region"``: polar angles
    ``theta1_deg``, ``theta2_deg`` and azimuths ``phi1_deg``, ``phi2_deg``; answer in sr.

    Examples
    --------
    >>> ex = SolidAngle(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> cone = next(SolidAngle(seed=s) for s in range(30) if SolidAngle(seed=s).kind == "cone")
    >>> a = math.radians(cone.alpha_deg)
    >>> cone.check(math.pi * a * a).diagnosis
    'small-angle formula'
    """

    title = "A solid angle"
    answer_form = "number"
    what = "the solid angle"
    #: A patch seen face-on (theta = 0) has cos(theta) = 1.
    may_coincide = ("cosine forgotten",)
    advice = (r"Integrate $d\omega = \sin\theta\,d\theta\,d\phi$: a cone of half-angle "
              r"$\alpha$ gives $2\pi(1 - \cos\alpha)$; a small patch gives "
              r"$A\cos\theta/d^2$.")

    def draw(self, rng):
        self.kind = str(pick(rng, ("cone", "patch", "region")))
        if self.kind == "cone":
            self.alpha_deg = int(pick(rng, (30, 45, 60, 90, 120, 20, 10)))
            self.expected = shading.cone_solid_angle(_deg(self.alpha_deg))
        elif self.kind == "patch":
            self.A_cm2 = float(pick(rng, (10, 20, 40, 50, 100)))
            self.d = float(pick(rng, (0.5, 2, 2.5, 4)))
            self.theta_deg = int(pick(rng, (0, 30, 60)))
            t = _deg(self.theta_deg)
            normal = [math.sin(t), 0.0, -math.cos(t)]
            self.expected = 1e3 * float(shading.patch_solid_angle(
                self.A_cm2 * 1e-4, normal, [0, 0, self.d], [0, 0, 0]))
        else:
            t1 = int(pick(rng, (0, 30, 60)))
            t2 = int(pick(rng, [t for t in (60, 90, 120, 180) if t > t1]))
            p1 = int(pick(rng, (0, 30, 90)))
            p2 = p1 + int(pick(rng, (90, 180, 360 - 90)))
            self.theta1_deg, self.theta2_deg, self.phi1_deg, self.phi2_deg = t1, t2, p1, p2
            self.expected = shading.spherical_region_solid_angle(_deg(t1), _deg(t2),
                                                                 _deg(p1), _deg(p2))

    def mistakes(self):
        if self.kind == "cone":
            a = _deg(self.alpha_deg)
            return [
                Mistake(math.pi * a * a, r"$\pi\alpha^2$ is the small-angle approximation (a "
                        r"flat disc of radius $\alpha$ on the sphere); it fails for wide cones. "
                        r"Integrate $\sin\theta$: $\Omega = 2\pi(1 - \cos\alpha)$.",
                        "small-angle formula"),
                Mistake(4 * math.pi * (1 - math.cos(a)), r"The azimuth runs over $2\pi$, not "
                        r"$4\pi$: $\Omega = \int_0^{2\pi}\!\int_0^\alpha \sin\theta\,d\theta\,"
                        r"d\phi = 2\pi(1 - \cos\alpha)$ (a hemisphere, $\alpha = 90^\circ$, is "
                        r"$2\pi$; the whole sphere $4\pi$).", "hemisphere confusion"),
                Mistake(2 * math.pi * (1 - math.cos(self.alpha_deg)), r"You took the cosine of "
                        rf"{self.alpha_deg} **radians**: convert the degrees first.",
                        "degrees as radians"),
                Mistake(2 * math.pi * (1 - math.sin(a)), r"$\int_0^\alpha \sin\theta\,d\theta = "
                        r"1 - \cos\alpha$, not $1 - \sin\alpha$.", "sine for cosine"),
            ]
        if self.kind == "patch":
            t = _deg(self.theta_deg)
            a = self.A_cm2 * 1e-4 * 1e3
            d = self.d
            found = [
                Mistake(a / d ** 2, r"The tilt is missing: a patch turned by $\theta$ from the "
                        r"line of sight looks smaller, by $\cos\theta$: $\Omega \approx "
                        r"A\cos\theta/d^2$.", "cosine forgotten"),
                Mistake(a * math.cos(t) / d, r"A solid angle is an area over the **square** "
                        r"of a distance (sr are m²/m²): divide by $d^2$.", "d instead of d^2"),
                Mistake(a * math.sin(t) / d ** 2, r"The projected area is $A\cos\theta$ "
                        r"with $\theta$ between the patch's normal and the line of sight.",
                        "sine for cosine"),
            ]
            if self.theta_deg:
                found.append(Mistake(a * math.cos(self.theta_deg) / d ** 2, r"You took the "
                                     rf"cosine of {self.theta_deg} **radians**: convert the "
                                     r"degrees first.", "degrees as radians"))
            return found
        t1, t2 = _deg(self.theta1_deg), _deg(self.theta2_deg)
        span = _deg(self.phi2_deg - self.phi1_deg)
        return [
            Mistake(span * (t2 - t1), r"$d\omega = \sin\theta\,d\theta\,d\phi$: the rows of "
                    r"the sphere shrink towards the poles, so integrate $\sin\theta$, not 1: "
                    r"$\int_{\theta_1}^{\theta_2}\sin\theta\,d\theta = \cos\theta_1 - "
                    r"\cos\theta_2$.", "sin theta forgotten"),
            Mistake(span * (math.sin(t2) - math.sin(t1)), r"The antiderivative of "
                    r"$\sin\theta$ is $-\cos\theta$: the region gives $(\phi_2 - \phi_1)"
                    r"(\cos\theta_1 - \cos\theta_2)$.", "sine for cosine"),
            Mistake(2 * math.pi * (math.cos(t1) - math.cos(t2)), r"The region spans only "
                    r"$\phi_2 - \phi_1$ of azimuth, not the full $2\pi$.", "full azimuth"),
        ]

    def statement(self):
        if self.kind == "cone":
            text = (r"A spotlight sends its light into a circular cone of half-angle "
                    rf"$\alpha = {self.alpha_deg}^\circ$ around its axis. Compute the solid "
                    r"angle of the cone, in steradians.")
            names = ("kind", "alpha_deg")
        elif self.kind == "patch":
            text = (rf"A small flat patch of area $A = {_num(self.A_cm2)}$ cm² is seen from a "
                    rf"point at the distance $d = {_num(self.d)}$ m; the patch's normal makes "
                    rf"the angle $\theta = {self.theta_deg}^\circ$ with the line of sight. "
                    r"Using the small-patch approximation, compute the solid angle it "
                    r"subtends, in **millisteradians** (1 msr = $10^{-3}$ sr; 1 cm² = "
                    r"$10^{-4}$ m²).")
            names = ("kind", "A_cm2", "d", "theta_deg")
        else:
            text = (r"In spherical coordinates ($\theta$ the polar angle from the $z$ axis, "
                    r"$\phi$ the azimuth) a region of directions is "
                    rf"${self.theta1_deg}^\circ \le \theta \le {self.theta2_deg}^\circ$, "
                    rf"${self.phi1_deg}^\circ \le \phi \le {self.phi2_deg}^\circ$. Compute its "
                    r"solid angle, in steradians.")
            names = ("kind", "theta1_deg", "theta2_deg", "phi1_deg", "phi2_deg")
        return text + "\n\n" + _ONE_NUMBER + "\n\n" + data_note(*names)

    def hints(self):
        first = (r"The element of solid angle in spherical coordinates is "
                 r"$d\omega = \sin\theta\,d\theta\,d\phi$: a patch of the unit sphere "
                 r"$d\theta$ high and $\sin\theta\,d\phi$ wide.")
        if self.kind == "cone":
            return [first, r"Integrate over $0 \le \phi < 2\pi$ and $0 \le \theta \le \alpha$.",
                    rf"$\Omega = 2\pi(1 - \cos {self.alpha_deg}^\circ)$."]
        if self.kind == "patch":
            return [first, r"A small patch far away covers $d\omega = A\cos\theta/d^2$: its "
                    r"area foreshortened by the tilt, over the squared distance.",
                    rf"In m²: $A = {_num(self.A_cm2)} \cdot 10^{{-4}}$; then multiply the "
                    r"steradians by 1000."]
        return [first, r"The two integrals separate: $\int d\phi$ times "
                r"$\int \sin\theta\,d\theta$.",
                r"$\Omega = (\phi_2 - \phi_1)(\cos\theta_1 - \cos\theta_2)$ with the azimuth span "
                r"in **radians**."]

    def worked(self):
        if self.kind == "cone":
            c = math.cos(_deg(self.alpha_deg))
            value = 2 * math.pi * (1 - c)
            return Worked([r"$\Omega = \int_0^{2\pi}\!\int_0^{\alpha}\sin\theta\,d\theta\,d\phi "
                           r"= 2\pi(1 - \cos\alpha)$.",
                           rf"$\cos {self.alpha_deg}^\circ = {_n4(c)}$, so $\Omega = 2\pi(1 - "
                           rf"{_n4(c)}) = {_n4(value)}$ sr."], value)
        if self.kind == "patch":
            c = math.cos(_deg(self.theta_deg))
            sr = self.A_cm2 * 1e-4 * c / self.d ** 2
            return Worked([rf"$A = {_num(self.A_cm2)}$ cm² $= {_num(self.A_cm2 * 1e-4, 4)}$ m², "
                           rf"$\cos {self.theta_deg}^\circ = {_n4(c)}$, $d^2 = "
                           rf"{_num(self.d ** 2)}$ m².",
                           rf"$\Omega \approx A\cos\theta/d^2 = {_num(sr, 7)}$ sr "
                           rf"$= {_n4(1e3 * sr)}$ msr."], 1e3 * sr)
        span = _deg(self.phi2_deg - self.phi1_deg)
        c1, c2 = math.cos(_deg(self.theta1_deg)), math.cos(_deg(self.theta2_deg))
        value = span * (c1 - c2)
        return Worked([rf"$\phi_2 - \phi_1 = {self.phi2_deg - self.phi1_deg}^\circ = "
                       rf"{_n4(span)}$ rad.",
                       rf"$\cos\theta_1 - \cos\theta_2 = {_n4(c1)} - ({_n4(c2)}) = "
                       rf"{_n4(c1 - c2)}$.",
                       rf"$\Omega = {_n4(span)} \cdot {_n4(c1 - c2)} = {_n4(value)}$ sr."],
                      value)


class RadianceIntensity(DrawnExercise):
    r"""Radiance, intensity and flux: :math:`I = L A\cos\theta`, :math:`I = \Phi/(4\pi)`,
    :math:`M = \pi L`.

    ``kind == "emitter"``: a small flat Lambertian emitter of radiance ``L`` and area ``A_cm2``
    (cm²), seen at ``theta_deg`` from its normal; the intensity in W/sr.
    ``kind == "isotropic"``: an isotropic point source of flux ``flux`` (W); its intensity.
    ``kind == "exitance"``: a Lambertian surface of radiance ``L``; its exitance in W/m².

    Examples
    --------
    >>> ex = RadianceIntensity(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> iso = next(RadianceIntensity(seed=s) for s in range(30)
    ...            if RadianceIntensity(seed=s).kind == "isotropic")
    >>> iso.check(iso.flux / (2 * math.pi)).diagnosis
    '2 pi instead of 4 pi'
    """

    title = "Radiance and intensity"
    answer_form = "number"
    what = "the answer"
    advice = (r"From the definitions: $I = d\Phi/d\omega$, $L = d^2\Phi/(dA\cos\theta\,"
              r"d\omega)$, so a small emitter has $I = L A\cos\theta$; an isotropic source "
              r"spreads $\Phi$ over $4\pi$ sr; a Lambertian surface emits $M = \pi L$.")

    def draw(self, rng):
        self.kind = str(pick(rng, ("emitter", "isotropic", "exitance")))
        if self.kind == "emitter":
            self.L = float(pick(rng, (500, 1000, 2000, 4000, 5000)))
            self.A_cm2 = float(pick(rng, (10, 20, 50, 100)))
            self.theta_deg = int(pick(rng, (0, 30, 60)))
            self.expected = shading.emitter_intensity(self.L, self.A_cm2 * 1e-4,
                                                      _deg(self.theta_deg))
        elif self.kind == "isotropic":
            self.flux = float(pick(rng, (60, 100, 400, 800, 1200, 40)))
            self.expected = shading.isotropic_intensity(self.flux)
        else:
            self.L = float(pick(rng, (2, 5, 10, 20, 50, 100)))
            self.expected = shading.lambertian_exitance(self.L)

    def mistakes(self):
        if self.kind == "emitter":
            la = self.L * self.A_cm2 * 1e-4
            t = _deg(self.theta_deg)
            found = [
                Mistake(math.pi * la * math.cos(t), r"No $\pi$ here: $\pi$ appears when the "
                        r"radiance is integrated over a hemisphere ($M = \pi L$). In one "
                        r"direction $I = L A\cos\theta$.", "pi factor"),
                Mistake(la * math.cos(t) / math.pi, r"No $1/\pi$ here: $I = L A\cos\theta$ "
                        r"comes straight from the definition of radiance.", "pi factor"),
            ]
            if self.theta_deg:
                found += [
                    Mistake(la, r"The emitter is seen at an angle: its projected area is "
                            r"$A\cos\theta$, so $I = L A\cos\theta$ (Lambert's law of "
                            r"emission).", "cosine forgotten"),
                    Mistake(la * math.sin(t), r"The projected area uses the cosine of the "
                            r"angle from the emitter's **normal**.", "sine for cosine")]
            return found
        if self.kind == "isotropic":
            f = self.flux
            return [
                Mistake(f / (2 * math.pi), r"An isotropic source sends light into the whole "
                        r"sphere, $4\pi$ sr, not a hemisphere ($2\pi$): $I = \Phi/(4\pi)$.",
                        "2 pi instead of 4 pi"),
                Mistake(f / math.pi, r"Divide the flux by the solid angle of the whole "
                        r"sphere, $4\pi$ sr; $\pi$ belongs to the cosine-weighted hemisphere.",
                        "pi factor"),
                Mistake(f, r"Intensity is flux **per steradian**: spread $\Phi$ over the "
                        r"$4\pi$ sr of the sphere.", "flux for intensity"),
            ]
        L = self.L
        return [
            Mistake(2 * math.pi * L, r"$2\pi$ is the solid angle of the hemisphere, but the "
                    r"exitance weights each direction by $\cos\theta$: "
                    r"$\int L\cos\theta\,d\omega = \pi L$.", "hemisphere confusion"),
            Mistake(4 * math.pi * L, r"A surface emits into one hemisphere, and each "
                    r"direction counts with $\cos\theta$: $M = \pi L$.", "2 pi instead of 4 pi"),
            Mistake(L, r"Radiance is per steradian and per projected area; the exitance adds "
                    r"up all directions: $M = \int L\cos\theta\,d\omega = \pi L$.",
                    "pi factor"),
        ]

    def statement(self):
        if self.kind == "emitter":
            text = (rf"A small flat Lambertian emitter of area $A = {_num(self.A_cm2)}$ cm² has "
                    rf"the uniform radiance $L = {_num(self.L)}$ W/(m² sr). Compute its radiant "
                    rf"intensity in a direction at $\theta = {self.theta_deg}^\circ$ from its "
                    r"normal, in W/sr (1 cm² = $10^{-4}$ m²).")
            names = ("kind", "L", "A_cm2", "theta_deg")
        elif self.kind == "isotropic":
            text = (rf"An isotropic point source emits the radiant flux $\Phi = {_num(self.flux)}$"
                    r" W evenly in all directions. Compute its radiant intensity $I$, in W/sr.")
            names = ("kind", "flux")
        else:
            text = (rf"A Lambertian surface emits the same radiance $L = {_num(self.L)}$ "
                    r"W/(m² sr) in every direction of its hemisphere. Compute its radiant "
                    r"exitance $M$ (the flux leaving per unit area), in W/m².")
            names = ("kind", "L")
        return text + "\n\n" + _ONE_NUMBER + "\n\n" + data_note(*names)

    def hints(self):
        if self.kind == "emitter":
            return [r"Radiance is flux per unit **projected** area and per unit solid angle; "
                    r"intensity is flux per unit solid angle.",
                    r"So the intensity is the radiance times the projected area, "
                    r"$I = L A\cos\theta$.",
                    rf"$A = {_num(self.A_cm2)} \cdot 10^{{-4}}$ m²; $\cos {self.theta_deg}^\circ"
                    rf" = {_n4(math.cos(_deg(self.theta_deg)))}$."]
        if self.kind == "isotropic":
            return [r"Intensity is flux per unit solid angle, $I = d\Phi/d\omega$.",
                    r"An isotropic source spreads its flux evenly over all directions.",
                    r"The whole sphere of directions is $4\pi$ sr."]
        return [r"The exitance adds up the flux in all directions of the hemisphere, each "
                r"weighted by $\cos\theta$: $M = \int L\cos\theta\,d\omega$.",
                r"$\int_0^{2\pi}\!\int_0^{\pi/2}\cos\theta\sin\theta\,d\theta\,d\phi = "
                r"2\pi\cdot\tfrac12$.",
                r"So $M = \pi L$, not $2\pi L$."]

    def worked(self):
        if self.kind == "emitter":
            c = math.cos(_deg(self.theta_deg))
            a = self.A_cm2 * 1e-4
            value = self.L * a * c
            return Worked([r"From $L = d^2\Phi/(dA\cos\theta\,d\omega)$ and "
                           r"$I = d\Phi/d\omega$: $I = L A\cos\theta$.",
                           rf"$I = {_num(self.L)} \cdot {_num(a, 4)} \cdot {_n4(c)} = "
                           rf"{_n4(value)}$ W/sr."], value)
        if self.kind == "isotropic":
            value = self.flux / (4 * math.pi)
            return Worked([r"The flux spreads evenly over the $4\pi$ sr of the sphere.",
                           rf"$I = \Phi/(4\pi) = {_num(self.flux)}/{_n4(4 * math.pi)} = "
                           rf"{_n4(value)}$ W/sr."], value)
        value = math.pi * self.L
        return Worked([r"$M = \int_{\text{hemisphere}} L\cos\theta\,d\omega = L\int_0^{2\pi}\!"
                       r"\int_0^{\pi/2}\cos\theta\sin\theta\,d\theta\,d\phi = \pi L$.",
                       rf"$M = \pi \cdot {_num(self.L)} = {_n4(value)}$ W/m²."], value)
