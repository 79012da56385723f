"""Chapter 6 exercises: boundary representations with rings, and choosing the form of a model.

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

from ..core import (UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note,
                    has_placeholder, pick)
from . import _paren

__all__ = ["BRepEulerRings", "ChooseModelForm"]

#: The words for the prismatic holes and pockets, by their number of sides.
_HOLE_NAMES = {3: "triangular", 4: "square", 6: "hexagonal"}


def _feature_counts(p, through):
    """What a p-sided hole (through) or pocket (blind) cut into one face adds to the counts
    (V, E, F, R, S, H) of a solid."""
    if through:
        return (2 * p, 3 * p, p, 2, 0, 1)
    return (2 * p, 3 * p, p + 1, 1, 0, 0)


class BRepEulerRings(DrawnExercise):
    r"""A missing count of a solid with rings: :math:`V - E + F - R = 2(S - H)`.

    The solid is a box with prismatic through-holes and blind pockets cut into its top face,
    and possibly separate boxes next to it. Either the number of through-holes :math:`H` is
    asked (from :math:`V, E, F, R, S`) or the number of edges :math:`E` (from the description
    and :math:`V, F, R, S, H`).

    Attributes: ``ask`` (``"H"`` or ``"E"``), ``sides``, ``n_through``, ``n_pocket``,
    ``n_boxes``, and the counts ``V``, ``E``, ``F``, ``R``, ``S``, ``H``.

    Examples
    --------
    >>> ex = BRepEulerRings(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.ask, ex.R                                             # the rings as boundary loops
    ('E', 2)
    >>> ex.check(ex.V + ex.F + ex.R - 2 * (ex.S - ex.H)).diagnosis
    'rings as boundary loops'
    """

    title = "Euler-Poincaré with rings: the missing count"
    answer_form = "number"
    what = "the count"
    advice = (r"Count the rings $R$ (inner loops of faces: a through-hole makes two, a pocket "
              r"one) and the shells $S$, then use $V - E + F - R = 2(S - H)$.")

    def draw(self, rng):
        self.ask = str(pick(rng, ("H", "E")))
        self.sides = int(pick(rng, (3, 4, 4, 6)))
        self.n_through = int(rng.integers(0, 4))
        self.n_pocket = int(rng.integers(0, 3))
        self.n_boxes = int(pick(rng, (1, 1, 2, 3)))
        counts = [8, 12, 6, 0, 1, 0]
        for n, through in ((self.n_through, True), (self.n_pocket, False)):
            extra = _feature_counts(self.sides, through)
            counts = [c + n * e for c, e in zip(counts, extra)]
        k = self.n_boxes - 1
        counts = [c + k * e for c, e in zip(counts, (8, 12, 6, 0, 1, 0))]
        self.V, self.E, self.F, self.R, self.S, self.H = (int(c) for c in counts)
        self.expected = self.H if self.ask == "H" else self.E

    def acceptable(self):
        return self.n_through + self.n_pocket >= 1 and len(self._slips()) >= 2

    def _slips(self):
        """The anticipated wrong answers: key -> value."""
        V, E, F, R, S, H = self.V, self.E, self.F, self.R, self.S, self.H
        if self.ask == "H":
            chi = V - E + F - R
            out = {"rings forgotten": S - (V - E + F) / 2,
                   "rings as boundary loops": S - (V - E + F + R) / 2,
                   "not halved": S - chi}
            if S > 1:
                out["one shell"] = 1 - chi / 2
        else:
            out = {"rings forgotten": V + F - 2 * (S - H),
                   "rings as boundary loops": V + F + R - 2 * (S - H),
                   "holes ignored": V + F - R - 2 * S}
            if S > 1:
                out["one shell"] = V + F - R - 2 * (1 - H)
        return {k: v for k, v in out.items() if float(v).is_integer()}

    def mistakes(self):
        R, S = self.R, self.S
        text = {
            "rings forgotten": (r"You left out the rings. A face with a hole in it has an "
                                r"inner loop, and each one counts: "
                                rf"$V - E + F - R = 2(S - H)$ with $R = {R}$ here. The mesh "
                                r"formula $V - E + F = 2 - 2g$ holds only when every face is a "
                                r"disc."),
            "rings as boundary loops": (r"You treated the rings like the boundary loops $b$ of "
                                        r"an open mesh ($V - E + F = 2 - 2g - b$). A solid "
                                        r"has no boundary; its rings enter with a minus sign on "
                                        rf"the left: $V - E + F - R = 2(S - H)$, $R = {R}$."),
            "not halved": (r"You forgot to halve: $V - E + F - R = 2(S - H)$ gives "
                           r"$S - H = (V - E + F - R)/2$; each through-hole costs 2."),
            "one shell": (rf"The solid has $S = {S}$ shells (separate pieces), not one: each "
                          r"separate piece adds 2 to the right side $2(S - H)$."),
            "holes ignored": (r"You used $H = 0$, but the through-holes count: a hole that "
                              r"goes right through is a handle, and the right side is "
                              rf"$2(S - H) = 2({S} - {self.H})$."),
        }
        return [Mistake(v, text[k], k) for k, v in self._slips().items()]

    def hints(self):
        return [
            r"For a solid whose faces may have holes (rings, inner loops) the Euler-Poincaré "
            r"formula is $V - E + F - R = 2(S - H)$: $R$ rings, $S$ shells, $H$ through-holes.",
            r"A through-hole leaves a ring in the face where it enters and one where it leaves "
            r"(2 rings); a blind pocket leaves one ring and no hole. Every separate piece is a "
            r"shell.",
            (rf"Here $R = {self.R}$ and $S = {self.S}$; put the known counts into the formula "
             + ("and solve for $H$." if self.ask == "H" else "and solve for $E$.")),
        ]

    def worked(self):
        V, E, F, R, S, H = self.V, self.E, self.F, self.R, self.S, self.H
        steps = [r"The formula for a solid with rings: $V - E + F - R = 2(S - H)$."]
        if self.ask == "H":
            chi = V - E + F - R
            steps += [
                rf"Left side: ${V} - {E} + {F} - {R} = {chi}$.",
                rf"So $S - H = {chi}/2 = {chi // 2}$ and $H = S - {_paren(chi // 2)} = "
                rf"{S} - {_paren(chi // 2)} = {H}$.",
                rf"Check: $2(S - H) = 2({S} - {H}) = {2 * (S - H)} = {chi}$. Rings without "
                r"holes are blind pockets: each ring of a pocket lowers the left side by 1 "
                r"but adds no hole.",
            ]
            return Worked(steps, H)
        steps += [
            rf"Rings: {self.n_through} through-hole(s) $\times 2$ + {self.n_pocket} "
            rf"pocket(s) $\times 1$ = {R}; shells $S = {S}$; holes $H = {H}$.",
            rf"Solve for $E$: $E = V + F - R - 2(S - H) = {V} + {F} - {R} - 2({S} - {H}) = {E}$.",
            rf"Check by counting: each {self.sides}-sided hole or pocket adds "
            rf"$3 \cdot {self.sides} = {3 * self.sides}$ edges (two rims and the vertical "
            rf"edges) to the 12 of each box: $12 \cdot {self.n_boxes} + "
            rf"{3 * self.sides} \cdot {self.n_through + self.n_pocket} = {E}$.",
        ]
        return Worked(steps, E)

    def statement(self):
        shape = _HOLE_NAMES[self.sides]
        parts = []
        if self.n_through:
            parts.append(f"{self.n_through} {shape} hole(s) drilled right through, from the top "
                         "face to the bottom face")
        if self.n_pocket:
            parts.append(f"{self.n_pocket} {shape} blind pocket(s) milled into the top face "
                         "(they do not come out at the bottom)")
        others = {1: "", 2: " Next to it lies one more plain box, not touching it.",
                  3: " Next to it lie two more plain boxes, touching neither it nor each other."}
        if self.ask == "H":
            return (
                r"A CAD kernel reports the counts of a solid made of one or more boxes, with "
                rf"{shape} holes or pockets: $V = {self.V}$, $E = {self.E}$, $F = {self.F}$, "
                rf"$R = {self.R}$ rings (inner loops) and $S = {self.S}$ shell(s). How many "
                r"through-holes $H$ does it have?" "\n\n"
                r"**Answer:** one whole number." "\n\n" + data_note("V", "E", "F", "R", "S"))
        return (
            r"A box has " + " and ".join(parts) + "." + others[self.n_boxes]
            + rf" The B-rep has $V = {self.V}$ vertices and $F = {self.F}$ faces. How many "
            r"edges $E$ does it have? (Find $R$, $S$ and $H$ from the description.)" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("V", "F", "n_through",
                                                                "n_pocket", "n_boxes"))


# ---------------------------------------------------------------------------------------------
# Choosing the form of a model
# ---------------------------------------------------------------------------------------------

#: Each need: the right form, and why the plausible wrong forms fail it.
_FORM_NEEDS = {
    "realtime": ("mesh", {
        "implicit": "a GPU rasterizes triangles; an implicit surface must first be found by "
                    "ray marching or polygonized every frame, far too slow on a phone",
        "parametric": "the patches would have to be tessellated into triangles anyway before "
                      "the GPU can draw them",
        "voxels": "a detailed character needs a fine grid (memory cubic in the resolution), "
                  "and voxels still need a conversion to be drawn",
        "point cloud": "points have no faces: the surface has holes between them and cannot "
                       "be shaded or textured as a surface",
        "csg": "a Boolean tree must be evaluated (ray casting or conversion) before anything "
               "is drawn; no GPU draws a CSG tree directly"}),
    "scan": ("point cloud", {
        "mesh": "the scanner gives no connectivity: building faces (surface reconstruction) is "
                "a later step of the pipeline, not what the device delivers",
        "csg": "nobody knows which primitives make up a scanned statue: there is no tree to "
               "build",
        "parametric": "fitting smooth patches to the samples is a later reconstruction step",
        "implicit": "a signed function must first be fitted to the samples (e.g. Poisson "
                    "reconstruction): that is a conversion, not the raw data"}),
    "volume": ("voxels", {
        "mesh": "a mesh stores only a boundary surface; the density values inside the body "
                "would be lost",
        "point cloud": "samples on a surface carry nothing about the inside",
        "brep": "a boundary representation stores faces and edges only, not values inside",
        "parametric": "patches describe surfaces, not a value at every point of a volume"}),
    "booleans": ("csg", {
        "mesh": "a mesh stores only the result: changing the hole means recomputing the "
                "Boolean on triangles, and the design history is lost",
        "voxels": "Booleans on cells are easy but the cylinders become staircases, and the "
                  "exact diameter is lost",
        "point cloud": "no inside, no faces: holes cannot be subtracted",
        "parametric": "patches have no inside test, so subtracting a cylinder needs trimming "
                      "curves computed by hand"}),
    "freeform": ("parametric", {
        "mesh": "a mesh is flat pieces: its smoothness is only as good as the tessellation, "
                "and dragging one vertex makes a dent, not a smooth change",
        "voxels": "a grid approximates the body by cells: no smooth surface, and a fine one is "
                  "huge",
        "csg": "spheres, boxes and cylinders combined by Booleans cannot make a free-form "
               "panel",
        "point cloud": "samples cannot be evaluated at an arbitrary (u, v) and have no "
                       "smoothness at all"}),
    "inside": ("implicit", {
        "mesh": "an inside test on a mesh needs a ray cast counting crossings through many "
                "triangles per point",
        "parametric": "a patch has no inside test: the closest point must be found by an "
                      "iterative search",
        "point cloud": "points have no inside at all",
        "voxels": "the cells give a staircase approximation of the smooth shape, and a fine "
                  "grid costs cubic memory"}),
    "topology": ("brep", {
        "mesh": "a triangle mesh cuts every face into triangles: the exact faces and their "
                "holes (rings) are lost",
        "csg": "a CSG tree stores how the solid was built, not its faces and edges: they must "
               "be computed by boundary evaluation",
        "voxels": "cells have no faces and edges at all, and the geometry is approximate",
        "implicit": "a single function gives no faces, edges or adjacencies"}),
}

_SCENARIOS = (
    ("realtime", "a game character drawn 60 times a second on a phone's GPU"),
    ("realtime", "the terrain of a flight simulator, drawn by the graphics card with "
                 "several levels of detail"),
    ("scan", "the raw output of a laser scanner that has just scanned a marble statue"),
    ("scan", "one sweep of the LiDAR sensor on a self-driving car"),
    ("volume", "a CT scan of a patient's head, with a density value inside the whole head"),
    ("volume", "the temperature inside a furnace, computed at every point by a simulation"),
    ("booleans", "a machined bracket: a block minus three drilled holes, where the engineer "
                 "will later change the diameter of one hole"),
    ("booleans", "a chess piece built from spheres, cylinders and cones joined by unions and "
                 "differences, edited by changing a primitive"),
    ("freeform", "a car's body panel designed as smooth free-form surfaces by dragging control "
                 "points"),
    ("freeform", "a ship's hull that a cutting machine must evaluate at any parameter point "
                 "(u, v), smooth everywhere"),
    ("inside", "a physics engine that tests thousands of particles per frame for being inside "
               "a smooth blob-shaped obstacle"),
    ("inside", "metaballs (blobs) that merge smoothly into each other in an animation"),
    ("topology", "a CAD kernel that exports exact faces and edges, with the holes in faces as "
                 "inner loops, for a machining program"),
    ("topology", "a solid modeller that must answer exactly which faces meet at each edge of "
                 "a designed part"),
)


class ChooseModelForm(DrawnExercise):
    """Which form of a model suits a task, and why the others fail it.

    Four forms are offered, the right one and three plausible wrong ones; a wrong choice is
    told why it fails this task. Diagnosis ``"said <form>"``.

    Attributes: ``task``, ``need``, ``menu``.

    Examples
    --------
    >>> ex = ChooseModelForm(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> other = next(m for m in ex.menu if m != ex.expected)
    >>> ex.check(other).diagnosis == "said " + other
    True
    >>> ex.check("teapot").status, ex.check(...).status
    ('invalid', 'unanswered')
    """

    title = "Choose the form of a model"
    answer_form = "custom"

    def draw(self, rng):
        self.need, self.task = _SCENARIOS[int(rng.integers(len(_SCENARIOS)))]
        right, wrong = _FORM_NEEDS[self.need]
        names = sorted(wrong)
        chosen = rng.choice(len(names), size=3, replace=False)
        menu = [right] + [names[int(k)] for k in chosen]
        order = rng.permutation(4)
        self.menu = tuple(menu[int(k)] for k in order)
        self.expected = right

    def separated(self, mistakes):
        return True

    def _judge(self, answer):
        if has_placeholder(answer, none_inside=True):
            return Feedback("unanswered", UNANSWERED)
        form = "Give one of the names " + ", ".join(f"`'{k}'`" for k in self.menu) + "."
        if isinstance(answer, (list, tuple)) and len(answer) == 1:
            answer = answer[0]
        if not isinstance(answer, str):
            return Feedback("invalid", form, "unreadable")
        name = " ".join(answer.strip().lower().replace("_", " ").replace("-", " ").split())
        name = {"b rep": "brep", "pointcloud": "point cloud", "polygon mesh": "mesh",
                "voxel": "voxels", "implicit surface": "implicit",
                "parametric patch": "parametric"}.get(name, name)
        if name not in self.menu:
            return Feedback("invalid", f"{answer!r} is not on the menu. " + form, "unreadable")
        right, wrong = _FORM_NEEDS[self.need]
        if name == right:
            return Feedback("correct", f"Yes: a {right} fits {self.task}.")
        return Feedback("wrong", f"Not a {name}: {wrong[name]}.", f"said {name}")

    def hints(self):
        return [
            "Ask what the task needs most: drawing fast on a GPU, the raw data of a device, "
            "values inside a volume, Boolean editing with a history, smooth free-form "
            "surfaces, a cheap inside test, or exact faces and edges.",
            "Then cross out each form that fails that need: which cannot be drawn directly, "
            "which has no inside, which only approximates?",
            f"The task here is {self.task}.",
        ]

    def worked(self):
        right, wrong = _FORM_NEEDS[self.need]
        steps = [f"The task: {self.task}."]
        for name in self.menu:
            if name != right:
                steps.append(f"Not a {name}: {wrong[name]}.")
        steps.append(f"That leaves the {right}: {_FORM_WHY[self.need]}.")
        return Worked(steps, right)

    def statement(self):
        return (
            rf"Which form of model suits **{self.task}**? Choose one of "
            + ", ".join(f"`'{m}'`" for m in self.menu) + "." "\n\n"
            r"**Answer:** one name, as a string." "\n\n" + data_note("task", "menu"))


_FORM_WHY = {
    "realtime": "triangles are what the GPU rasterizes, with the detail where it is needed",
    "scan": "a scanner measures points on the surface (often with normals) and nothing else",
    "volume": "a grid stores a value in every cell, inside as well as on the surface",
    "booleans": "the tree keeps the primitives and operations, so a hole's size stays one "
                "number to edit",
    "freeform": "control points give smooth surfaces that are evaluated at any (u, v)",
    "inside": "one evaluation of the sign of f answers the inside test, and blends are a "
              "formula",
    "topology": "faces with outer and inner loops, edges and vertices with their adjacency, "
                "all exact",
}
