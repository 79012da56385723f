"""Chapter 12 exercises: Interpolated shading.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import shading
from ..core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, data_note,
                    is_unanswered, pick)
from . import _material_words, _num, _Parts, _unit

__all__ = [
    "SHADING_METHODS",
    "GouraudVersusPhong",
    "ShadingMethodChoice",
]


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
    advice = (r"Gouraud: evaluate $I = k_d \max(N \cdot L, 0) + k_s \max(R \cdot V, 0)^n$ at "
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
