"""Chapter 12 exercises: Interpolated shading.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import shading
from ..core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note,
                    is_unanswered, pick)
from . import _material_words, _n4, _num, _Parts, _unit

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

#: Situations: (question, right method, {wrong method: why it is wrong}, clue, fillings). A
#: question may hold placeholders such as ``<object>``; ``fillings`` lists the settings that
#: replace them (each a tuple of (placeholder, text) pairs), and a seed draws one of them.
_SITUATIONS = (
    (r"A coarse <object> is made of large triangles. The light and the viewer are placed so "
     r"that the mirror direction would meet the eye in the **middle** of one large triangle, "
     r"while at its three vertices $R \cdot V$ is small (no highlight there). Which method "
     r"shows the highlight inside that triangle?",
     "phong",
     {"flat": r": one normal for the whole triangle, so at best the whole triangle lights up "
              r"uniformly (or not at all); a small highlight in its middle cannot appear.",
      "gouraud": r": the colour inside is a blend of the three vertex colours, and none of "
                 r"them has a highlight; a blend of dim colours is dim. The highlight is lost "
                 r"(a highlight that *does* reach a vertex is smeared over the neighbouring "
                 r"triangles instead)."},
     r"The highlight lies *between* the vertices, where no vertex evaluation sees it: only a "
     r"method that evaluates the model inside the triangle can find it.",
     ((("<object>", "sphere"),), (("<object>", "cylinder"),), (("<object>", "torus"),))),
    (r"A rotating, low-polygon <object> is shaded with a sharp highlight. As it turns, the "
     r"highlight flickers, changes shape, follows the triangle edges and jumps from vertex to "
     r"vertex. Which method produces this artefact?",
     "gouraud",
     {"flat": r" does show facets, but its highlight is a whole triangle lighting up at once, "
              r"not a blob that follows the edges and jumps between vertices.",
      "phong": r" evaluates the highlight at every pixel, so it stays round and moves smoothly; "
               r"it is the cure for this artefact, not its cause."},
     r"A highlight that jumps from vertex to vertex is seen only where the model is "
     r"evaluated: at the vertices. In between, the colours are blended.",
     ((("<object>", "model"),), (("<object>", "spaceship"),), (("<object>", "helmet"),))),
    (r"The illumination model may be evaluated only at the **vertices** (per-vertex lighting "
     r"in hardware), yet the colour must vary continuously across the edges of a smooth, "
     r"curved surface. Which method fits?",
     "gouraud",
     {"flat": r" gives each polygon a single colour, so the colour jumps at every edge "
              r"(facets show), and it evaluates per polygon rather than per vertex.",
      "phong": r" needs an evaluation of the model at every **pixel**, which the constraint "
               r"rules out."},
     r"Evaluating only at the vertices rules out one method; a continuous colour across the "
     r"edges rules out another.", ((),)),
    (r"An old fixed-function pipeline (OpenGL 1.x with `glShadeModel(GL_SMOOTH)`) evaluates "
     r"the lighting at the vertices and lets the rasteriser blend the resulting colours across "
     r"each triangle. Which method is that?",
     "gouraud",
     {"flat": r" is `GL_FLAT`: one colour (that of one vertex) for the whole triangle, no "
              r"blending.",
      "phong": r" interpolates the normals and evaluates per pixel, which a rasteriser that "
               r"only blends colours cannot do."},
     r"What does the rasteriser interpolate here, colours or normals? Where is the model "
     r"evaluated?", ((),)),
    (r"A cut gemstone, a genuinely faceted object, should be drawn with every face in one "
     r"uniform colour, at the lowest cost. Which method?",
     "flat",
     {"gouraud": r" with averaged vertex normals smooths over the edges that should stay sharp "
                 r"and costs an evaluation per vertex plus an interpolation per pixel.",
      "phong": r" costs an evaluation per pixel and, with averaged normals, rounds the facets "
               r"off; a face of one uniform colour needs one evaluation only."},
     r"One uniform colour per face needs one evaluation per face, with the face's own normal.",
     ((),)),
    (r"With a distant light and a distant viewer, which method makes every triangle of a "
     r"curved <object> mesh a single uniform colour, so that the mesh looks faceted (and Mach "
     r"bands accentuate the edges)?",
     "flat",
     {"gouraud": r" interpolates vertex colours, so the colour changes continuously across "
                 r"edges: no facets (only a slope change at the edges).",
      "phong": r" interpolates the normals, so the shading varies smoothly across each triangle "
               r"and across its edges."},
     r"A single colour per triangle means nothing is interpolated across it: one normal, one "
     r"evaluation.", ((("<object>", "sphere"),), (("<object>", "vase"),))),
    (r"A <surface> is modelled as a single large quad (two triangles). A spotlight throws a "
     r"small bright disc onto its middle, and all four corners lie outside the light cone. "
     r"Which method shows the bright disc?",
     "phong",
     {"flat": r" uses one normal and one evaluation for the whole polygon: the disc is either "
              r"missing or fills the whole face.",
      "gouraud": r" blends the four corner colours, and every corner misses the spotlight: the "
                 r"blend is dark and the disc vanishes."},
     r"At the four corners the spotlight adds nothing. Which method evaluates the lighting at "
     r"the pixels in between?",
     ((("<surface>", "floor"),), (("<surface>", "wall"),), (("<surface>", "table top"),))),
    (r"A shiny <object> with the shininess exponent $n = <n>$ is drawn from a coarse mesh. Its "
     r"small, round highlight must glide smoothly over the surface as the light moves. Which "
     r"method?",
     "phong",
     {"flat": r" lights whole triangles at once: the highlight would jump from facet to facet.",
      "gouraud": r" evaluates at the vertices only: the highlight flickers, takes the shape of "
                 r"the triangles and jumps from vertex to vertex as it moves."},
     r"With a large exponent the highlight is smaller than a triangle: it must be evaluated "
     r"where it is, not guessed from the vertices.",
     tuple(((("<object>", obj), ("<n>", n)) for obj in ("teapot", "billiard ball", "car body")
            for n in ("50", "100", "200")))),
    (r"In a shader program the vertex shader passes the normal on, the rasteriser "
     r"interpolates it across the triangle, and the fragment shader normalises it and "
     r"evaluates the illumination model for each pixel. Which of the three classical methods "
     r"is this?",
     "phong",
     {"flat": r" interpolates nothing: one normal and one colour per triangle.",
      "gouraud": r" would evaluate the model in the vertex shader and let the rasteriser "
                 r"interpolate the resulting **colours**."},
     r"Note what is interpolated (the normal, not a colour) and where the model is evaluated "
     r"(for each fragment).", ((),)),
    (r"A matte <object> (purely diffuse, no highlights) is finely tessellated. It must look "
     r"smooth, without visible facets, at the lowest cost that achieves that. Which method?",
     "gouraud",
     {"flat": r" shows every facet: each triangle gets one colour, which jumps at every edge.",
      "phong": r" would look smooth too, but evaluates the model at every pixel: far more work "
               r"than a matte surface without highlights needs."},
     r"Diffuse light varies slowly, and a fine mesh samples it densely: blending colours "
     r"computed at the vertices is enough.",
     ((("<object>", "statue"),), (("<object>", "terrain"),), (("<object>", "vase"),))),
    (r"Which method needs the most evaluations of the illumination model for a triangle that "
     r"covers many pixels, and why is that the price of correct highlights?",
     "phong",
     {"flat": r" evaluates the model once per polygon: the cheapest of the three.",
      "gouraud": r" evaluates it once per vertex, three times per triangle, and only blends "
                 r"colours per pixel."},
     r"Count the evaluations of one triangle: once per polygon, once per vertex (three), or "
     r"once per covered pixel?", ((),)),
    (r"On a smooth <object> the colour is continuous across every edge, yet the highlight is "
     r"shaped like a star or a polygon with its corners on the mesh vertices, and Mach bands "
     r"appear where the slope of the shading changes at the edges. Which method shows this?",
     "gouraud",
     {"flat": r" would show discontinuous colours: a visible jump at every edge.",
      "phong": r" gives a round highlight whatever the shape of the triangles, because it "
               r"evaluates the model at every pixel."},
     r"Continuous colours but a highlight shaped by the mesh: the colours were computed at the "
     r"vertices and blended.", ((("<object>", "sphere"),), (("<object>", "torus"),))),
    (r"Of the methods that make a curved, tessellated surface look smooth (no jump in colour "
     r"across the edges), which one is cheaper?",
     "gouraud",
     {"flat": r" is cheaper still, but not smooth: the colour jumps at every edge.",
      "phong": r" is smooth as well, but evaluates the model at every pixel, which costs more "
               r"than an evaluation per vertex."},
     r"Two methods give continuous shading; compare where each of them evaluates the model.",
     ((),)),
    (r"A <object> is made of flat faces that meet at sharp edges. It is lit by a distant light "
     r"and seen by a distant viewer, so $N$, $L$ and $V$, and with them the colour, are the "
     r"same all over each face. Which method draws it correctly at the lowest cost?",
     "flat",
     {"gouraud": r" with vertex normals averaged over the faces rounds the sharp edges off; "
                 r"with each face's own normal at its vertices it gives the same picture at a "
                 r"higher cost (three evaluations per triangle and a blend per pixel).",
      "phong": r" costs an evaluation per pixel to find, on each face, the colour that one "
               r"evaluation already gives."},
     r"If the colour is the same over a whole face, how many evaluations does a face need?",
     ((("<object>", "cube"),), (("<object>", "pyramid"),), (("<object>", "prism"),))),
    (r"A scene of <count> million triangles, nearly all of them smaller than a pixel, is "
     r"previewed at interactive rates. Inside a triangle that covers at most one pixel there "
     r"is nothing to interpolate. Which method is the cheapest while looking as good as the "
     r"others here?",
     "flat",
     {"gouraud": r" evaluates three times per triangle (at its vertices) for a triangle that "
                 r"covers one pixel: three times the work for the same picture.",
      "phong": r" evaluates once per covered pixel and interpolates normals: no fewer "
               r"evaluations than one per triangle here, and more work per triangle."},
     r"When a triangle covers one pixel, count the evaluations per triangle of each method.",
     ((("<count>", "10"),), (("<count>", "20"),), (("<count>", "50"),))),
    (r"A stylised low-poly game wants every face of its models to show as a clearly visible "
     r"facet of one uniform colour. Which method?",
     "flat",
     {"gouraud": r" blends the colours across the edges, which hides the facets the game wants "
                 r"to show.",
      "phong": r" interpolates the normals, which hides the facets, and costs an evaluation "
               r"per pixel."},
     r"A uniform colour per face: one normal per face and one evaluation.", ((),)),
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

    Sixteen situations, several of them in a few settings (the object, the exponent, the
    number of triangles). Every wrong choice is answered with why that method does not fit;
    the diagnosis is ``"chose <method>"``.

    Attributes: ``situation`` (the question), ``methods`` (the three names).

    Examples
    --------
    >>> ex = ShadingMethodChoice(seed=0)
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
        question, self.expected, self._why, self._clue, fillings = pick(rng, _SITUATIONS)
        for placeholder, text in pick(rng, fillings):
            question = question.replace(placeholder, text)
        self.situation = question

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
        rows = "\n".join(f"| `'{name}'` | {meaning} |"
                         for name, meaning in SHADING_METHODS.items())
        return (
            self.situation + "\n\n| method | what it does |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** one of the strings `'flat'`, `'gouraud'` or `'phong'`." "\n\n"
            + data_note("situation", "methods"))

    def hints(self):
        first = sorted(self._why)[0]
        return [r"Ask two questions of each method: **where** is the illumination model "
                r"evaluated (once per polygon, at each vertex, or at each pixel), and **what** "
                r"is interpolated across the triangle (nothing, colours, or normals)?",
                self._clue,
                f"Rule one method out: {_NAMES[first]}{self._why[first]}"]

    def worked(self):
        steps = [f"The key to this situation: {self._clue}"]
        for name in sorted(self._why):
            steps.append(f"{_NAMES[name]}{self._why[name]} So not `{name!r}`.")
        left = [name for name in SHADING_METHODS if name not in self._why]
        steps.append(f"What is left: {_WHY[left[0]]}, which is what this situation needs.")
        return Worked(steps, left[0])


def _in_plane(deg):
    """The unit vector in the xz plane at `deg` degrees from +z towards +x."""
    t = math.radians(deg)
    return np.array([math.sin(t), 0.0, math.cos(t)])


def _deg(x):
    """An angle in degrees as LaTeX, bracketed when negative."""
    text = rf"{_num(x)}^\circ"
    return f"({text})" if x < 0 else text


def _minus(x):
    """`` - x`` for an angle in degrees, as LaTeX (``- (-45°)`` for a negative one)."""
    return rf" - {_deg(x)}"


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

    def _at(self, deg, name):
        """The intensity for the unit normal at `deg` degrees, worked with angles: (text, value).

        In the xz plane the unit vectors at the angles x and y have the dot product
        cos(x - y), and the mirror image of L (at l) about the normal at a is at 2a - l.
        """
        nl = math.cos(math.radians(deg - self.l_deg))
        head = (rf"{name} (normal at ${_num(deg)}^\circ$): $N \cdot L = \cos({_num(deg)}^\circ"
                rf"{_minus(self.l_deg)}) = {_n4(nl)}$")
        if nl <= 1e-12:
            return head + r" $\le 0$: no light reaches it, $I = 0$.", 0.0
        r_deg = 2 * deg - self.l_deg
        rv = math.cos(math.radians(r_deg - self.v_deg))
        specular = self.ks * max(rv, 0.0) ** self.n
        value = self.kd * nl + specular
        power = rf"{_n4(rv)}^{{{self.n}}}" if rv > 0 else r"0"
        clamp = "" if rv > 0 else r" (a negative $R \cdot V$ is clamped to 0)"
        return (head + rf"; $R$ is at $2 \cdot {_deg(deg)}{_minus(self.l_deg)} = "
                rf"{_num(r_deg)}^\circ$, $R \cdot V = \cos({_num(r_deg)}^\circ"
                rf"{_minus(self.v_deg)}) = {_n4(rv)}${clamp}; $I = {_num(self.kd)} \cdot "
                rf"{_n4(nl)} + {_num(self.ks)} \cdot {power} = {_n4(value)}$."), value

    def hints(self):
        _, ia = self._at(self.a_deg, "A")
        _, ib = self._at(self.b_deg, "B")
        mid = (self.a_deg + self.b_deg) / 2
        return [r"Gouraud shading evaluates the model at the **vertices** and interpolates the "
                r"intensities; Phong shading interpolates the **normals**, renormalises, and "
                r"evaluates the model at the point itself.",
                r"All vectors lie in one plane: the unit vectors at the angles $x$ and $y$ have "
                r"$\cos(x - y)$ as dot product, the mirror image of $L$ about a normal at the "
                rf"angle $a$ lies at $2a - l$, and the renormalised mean of $N_A$ and $N_B$ is "
                rf"the unit normal at ${_num(mid)}^\circ$.",
                rf"At the vertices $I_A = {_n4(ia)}$ and $I_B = {_n4(ib)}$; for Phong, evaluate "
                rf"the model once more with the normal at ${_num(mid)}^\circ$."]

    def worked(self):
        a_text, ia = self._at(self.a_deg, "Vertex A")
        b_text, ib = self._at(self.b_deg, "Vertex B")
        mid = (self.a_deg + self.b_deg) / 2
        m_text, im = self._at(mid, "The midpoint")
        gouraud = (ia + ib) / 2
        return Worked([
            r"Everything lies in the xz plane: two unit vectors at the angles $x$ and $y$ have "
            r"the dot product $\cos(x - y)$, and the mirror direction $R$ of $L$ (at the angle "
            r"$l$) about a normal at the angle $a$ lies at $2a - l$.",
            a_text, b_text,
            rf"Gouraud: blend the vertex intensities, $\tfrac12 (I_A + I_B) = \tfrac12 "
            rf"({_n4(ia)} + {_n4(ib)}) = {_n4(gouraud)}$.",
            rf"Phong: the renormalised mean $(N_A + N_B)/\lVert N_A + N_B \rVert$ of two unit "
            rf"normals is the unit normal halfway between them, at ${_num(mid)}^\circ$. "
            + m_text,
        ], [gouraud, im])
