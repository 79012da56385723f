"""Chapter 12 exercises: the Phong model with a light of separate ambient, diffuse and specular
colours.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import numpy as np

from ... import shading
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _Boundary, _n4, _num, _vec

__all__ = ["PhongLightColours"]

#: The boundary case: the light is behind the surface, only its ambient part is left.
BEHIND = "light behind the surface"

_SURFACES = ((0.8, 0.4, 0.2), (0.2, 0.6, 0.8), (0.6, 0.8, 0.2), (0.8, 0.2, 0.6),
             (0.4, 0.8, 0.6), (1.0, 0.6, 0.2))
_DIFFUSE_LIGHTS = ((1.0, 0.8, 0.6), (1.0, 1.0, 0.5), (0.6, 0.8, 1.0), (1.0, 0.5, 0.5),
                   (0.8, 1.0, 0.6))
_SPECULAR_LIGHTS = ((1.0, 1.0, 1.0), (0.5, 0.5, 1.0), (1.0, 1.0, 0.5), (0.5, 1.0, 0.5))
_AMBIENT_LIGHTS = ((0.1, 0.1, 0.1), (0.2, 0.2, 0.2), (0.1, 0.1, 0.2), (0.2, 0.1, 0.1))


def _colour_text(c):
    return "(" + ", ".join(_num(x) for x in np.ravel(c)) + ")"


class PhongLightColours(_Boundary, DrawnExercise):
    r"""The Phong colour of a point under one light with separate ambient, diffuse and specular
    colours: :math:`I = k_a I_{a} + k_d I_{d} (N \cdot L) + k_s I_{s} (R \cdot V)^n`, channel by
    channel.

    The material has the surface colour :math:`C` as its ambient and diffuse coefficients
    (:math:`k_a = k_d = C`) and a grey specular coefficient :math:`k_s` (a plastic: white
    highlights). The cosines are given. In the boundary variant (``boundary == "light behind
    the surface"``, about 15 % of the seeds) :math:`N \cdot L < 0`: the light adds neither
    diffuse nor specular light, but its ambient part still counts; otherwise ``boundary`` is
    None.

    Attributes: ``C`` (RGB), ``ks``, ``n``, ``Ia``, ``Id``, ``Is`` (the light's ambient, diffuse
    and specular colours, RGB), ``NL`` (:math:`N \cdot L`), ``RV`` (:math:`R \cdot V`),
    ``boundary``.

    Examples
    --------
    >>> ex = PhongLightColours(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = ex.C * ex.Ia + ex.C * ex.Id * max(ex.NL, 0) + ex.ks * ex.Id * max(ex.RV, 0) ** ex.n
    >>> ex.boundary is not None or ex.check(wrong).diagnosis == "diffuse colour in the highlight"
    True
    """

    title = "Phong with separate light colours"
    answer_form = "vector"
    what = "the colour"
    vector_like = False
    boundary_cases = (BEHIND,)
    advice = (r"Work channel by channel: $I = C \odot I_a + C \odot I_d\,\max(N \cdot L, 0) + "
              r"k_s\, I_s \max(R \cdot V, 0)^n$, each light colour feeding only its own term.")

    def draw(self, rng):
        self.C = np.array(pick(rng, _SURFACES))
        self.Id = np.array(pick(rng, _DIFFUSE_LIGHTS))
        self.Is = np.array(pick(rng, _SPECULAR_LIGHTS))
        self.Ia = np.array(pick(rng, _AMBIENT_LIGHTS))
        self.ks = float(pick(rng, (0.4, 0.5, 0.6)))
        self.n = int(pick(rng, (2, 3)))
        if self.boundary == BEHIND:
            self.NL = -float(pick(rng, (0.5, 0.6, 0.8)))
        else:
            self.NL = float(pick(rng, (0.5, 0.6, 0.8)))
        self.RV = float(pick(rng, (0.5, 0.6, 0.8)))
        # the expected colour from course_lib: a directional light with those colours, at the
        # angles the cosines give, in a frame where N = +z
        L = np.array([np.sqrt(1 - self.NL ** 2), 0.0, self.NL])
        R = 2 * self.NL * np.array([0.0, 0.0, 1.0]) - L
        # V at angle acos(RV) from R, turned about the axis normal to the plane of N and R
        axis = np.array([0.0, 1.0, 0.0])
        a = np.arccos(self.RV)
        V = R * np.cos(a) + np.cross(axis, R) * np.sin(a)
        if V[2] <= 0:
            V = R * np.cos(a) - np.cross(axis, R) * np.sin(a)
        self._geometry = (L, V)
        light = shading.directional_light(L, ambient=self.Ia, diffuse=self.Id, specular=self.Is)
        material = shading.Material(ka=self.C, kd=self.C, ks=self.ks, shininess=self.n)
        self.expected = shading.phong(None, [0.0, 0.0, 1.0], V, light, material,
                                      ambient=0.0).total

    def acceptable(self):
        L, V = self._geometry
        # the view must be above the surface, and R . V must come out as given
        R = 2 * L[2] * np.array([0.0, 0.0, 1.0]) - L
        return V[2] > 0.05 and abs(float(R @ V) - self.RV) < 1e-12 and \
            not np.allclose(self.Id, self.Is)

    def _terms(self, ambient=None, diffuse=None, specular=None, exponent=True, clamp=True,
               tint=False):
        ia = self.Ia if ambient is None else ambient
        idf = self.Id if diffuse is None else diffuse
        isp = self.Is if specular is None else specular
        nl = max(self.NL, 0.0) if clamp else self.NL
        lit = self.NL > 0 or not clamp
        spec = (max(self.RV, 0.0) ** (self.n if exponent else 1)) if lit else 0.0
        highlight = self.ks * isp * spec * (self.C if tint else 1.0)
        return self.C * ia + self.C * idf * nl + highlight

    def mistakes(self):
        no_ambient = [
            Mistake(self._terms(ambient=np.zeros(3)), r"The light's ambient colour $I_a$ is "
                    r"missing: it adds $k_a I_a = C \odot I_a$ whatever the angles, the light "
                    r"the lamp spreads around the room.", "no light ambient"),
        ]
        if self.boundary == BEHIND:
            found = [
                Mistake(np.zeros(3), r"The light is behind the surface, so its diffuse and "
                        r"specular terms are 0, but its **ambient** part stays: ambient light "
                        r"arrives from every direction, not along $L$.", "ambient dropped too"),
                Mistake(self._terms(clamp=False), r"$N \cdot L < 0$ was used as it is. A light "
                        r"behind the surface adds no diffuse light and no highlight: clamp, "
                        r"$\max(N \cdot L, 0) = 0$, and leave out the specular term.",
                        "no clamp"),
                Mistake(self.C * self.Ia + self.ks * self.Is * max(self.RV, 0.0) ** self.n,
                        r"A highlight on the dark side: with the light behind the surface "
                        r"($N \cdot L < 0$) the specular term is 0 too, even though "
                        r"$R \cdot V > 0$. Test $N \cdot L > 0$ before adding either light "
                        r"term.", "specular on the dark side"),
            ]
            return found
        found = no_ambient + [
            Mistake(self._terms(specular=self.Id), r"The highlight was given the light's "
                    r"**diffuse** colour. Each colour of the light feeds its own term: the "
                    r"specular term takes $I_s$.", "diffuse colour in the highlight"),
            Mistake(self._terms(diffuse=self.Is), r"The diffuse term was given the light's "
                    r"**specular** colour. The diffuse term takes $I_d$: "
                    r"$C \odot I_d\,(N \cdot L)$.", "specular colour in the diffuse term"),
            Mistake(self._terms(tint=True), r"The highlight was tinted by the surface colour "
                    r"$C$. This material's specular coefficient is the grey $k_s$ (a plastic): "
                    r"the highlight has the colour of the light's $I_s$, not of the surface.",
                    "highlight tinted"),
            Mistake(self._terms(exponent=False), r"The shininess exponent is missing: the "
                    r"specular factor is $(R \cdot V)^n$, not $R \cdot V$.", "no exponent"),
        ]
        return found

    def statement(self):
        return (
            rf"A point of a plastic surface of colour $C = {_colour_text(self.C)}$ (its ambient and "
            r"diffuse coefficients, $k_a = k_d = C$) with the grey specular coefficient "
            rf"$k_s = {_num(self.ks)}$ and shininess $n = {self.n}$ is lit by one distant light "
            r"that has separate colours for the three terms: ambient "
            rf"$I_a = {_colour_text(self.Ia)}$, diffuse $I_d = {_colour_text(self.Id)}$ and specular "
            rf"$I_s = {_colour_text(self.Is)}$. At the point, $N \cdot L = {_num(self.NL)}$ and "
            rf"$R \cdot V = {_num(self.RV)}$. There is no other light and no emission." "\n\n"
            r"Compute the colour $(I_R, I_G, I_B)$ that the Phong model gives at this point."
            "\n\n**Answer:** three numbers (R, G, B), unclamped; 3 significant digits are "
            "enough.\n\n" + data_note("C", "ks", "n", "Ia", "Id", "Is", "NL", "RV"))

    def hints(self):
        return [
            r"Each colour of the light feeds one term: $I = k_a \odot I_a + k_d \odot I_d\, "
            r"\max(N \cdot L, 0) + k_s I_s \max(R \cdot V, 0)^n$, channel by channel "
            r"($\odot$: multiply R with R, G with G, B with B).",
            rf"The ambient term is $C \odot I_a = {_colour_text(self.C)} \odot {_colour_text(self.Ia)} = "
            rf"{_vec(self.C * self.Ia)}$; it does not depend on the angles.",
            (r"$N \cdot L < 0$: the light is behind the surface. Which terms are left?"
             if self.NL <= 0 else
             rf"The diffuse factor is $N \cdot L = {_num(self.NL)}$, the specular factor "
             rf"$(R \cdot V)^n = {_num(self.RV)}^{self.n} = {_n4(self.RV ** self.n)}$."),
        ]

    def worked(self):
        amb = self.C * self.Ia
        steps = [rf"Ambient: $C \odot I_a = {_colour_text(self.C)} \odot {_colour_text(self.Ia)} = "
                 rf"{_vec(amb)}$ (the light's ambient part: no angle involved)."]
        if self.NL <= 0:
            steps.append(rf"**The boundary case:** $N \cdot L = {_num(self.NL)} < 0$, the "
                         r"light is behind the surface: no diffuse term and no highlight "
                         rf"(even though $R \cdot V = {_num(self.RV)}$). Only the ambient part "
                         r"is left.")
            total = amb
        else:
            dif = self.C * self.Id * self.NL
            spec = self.ks * self.Is * self.RV ** self.n
            steps += [rf"Diffuse: $C \odot I_d\,(N \cdot L) = {_colour_text(self.C)} \odot "
                      rf"{_colour_text(self.Id)} \cdot {_num(self.NL)} = {_vec(dif)}$.",
                      rf"Specular: $k_s I_s (R \cdot V)^n = {_num(self.ks)} \cdot "
                      rf"{_colour_text(self.Is)} \cdot {_num(self.RV)}^{self.n} = {_vec(spec)}$ "
                      r"(the light's specular colour, untouched by the surface colour).",
                      rf"Sum: $I = {_vec(amb + dif + spec)}$."]
            total = amb + dif + spec
        return Worked(steps, total)
