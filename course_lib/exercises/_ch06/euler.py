"""Chapter 6 exercises: Euler's formula.

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

import numpy as np

from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _paren, _Parts

__all__ = [
    "EdgeCollapseCounts",
    "EulerCounts",
    "GenusFromCounts",
]


class EulerCounts(_Parts):
    r"""The numbers of edges and faces of a closed triangle or quad mesh of a given genus.

    With :math:`k` vertices per face every edge lies on two faces, so :math:`kF = 2E`; with
    :math:`V - E + F = 2 - 2g` this gives :math:`F = \frac{2(V - \chi)}{k - 2}` and
    :math:`E = \frac{k}{2} F`.

    Attributes: ``V``, ``genus``, ``k`` (vertices per face, 3 or 4).

    Examples
    --------
    >>> ex = EulerCounts(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> chi = 2                                              # the genus forgotten
    >>> F = 2 * (ex.V - chi) // (ex.k - 2)
    >>> ex.check([ex.k * F // 2, F]).diagnosis
    'genus ignored'
    >>> ex.check(...).status, ex.check("E").status
    ('unanswered', 'invalid')
    """

    title = "Euler's formula: count the edges and faces"
    form_hint = "`[E, F]`, two whole numbers."
    may_coincide = ("genus ignored",)
    advice = (r"Use two equations: Euler's $V - E + F = 2 - 2g$ and the edge count "
            r"$kF = 2E$ (each face has $k$ edges, each edge lies on 2 faces).")

    def draw(self, rng):
        self.k = int(pick(rng, (3, 4)))
        self.genus = int(pick(rng, (0, 1, 1, 2, 3)))
        self.V = int(rng.integers(12, 41))
        self.expected = np.array([round(c) for c in self._counts(2 - 2 * self.genus)])

    def _counts(self, chi, edges_per_face=None):
        k, V = self.k, self.V
        if edges_per_face is None:                           # kF = 2E
            F = 2 * (V - chi) / (k - 2)
            return k * F / 2, F
        F = (V - chi) / (k - 1)                              # E = kF: shared edges counted twice
        return k * F, F

    def _parts(self):
        g = self.genus
        slips = {
            "genus ignored": (self._counts(2), r"You used $V - E + F = 2$, which holds for a "
                              r"sphere-like mesh only. A surface with $g$ handles has "
                              rf"$\chi = V - E + F = 2 - 2g$, here $2 - 2 \cdot {g} = "
                              rf"{2 - 2 * g}$."),
            "no factor 2": (self._counts(2 - g), r"You used $\chi = 2 - g$. Each handle lowers "
                            r"the Euler characteristic by **2**: $\chi = 2 - 2g$ (a torus has "
                            r"$\chi = 0$, not 1)."),
            "wrong sign": (self._counts(2 + 2 * g), r"The genus enters with a minus sign: "
                           r"$\chi = 2 - 2g$. Handles make $\chi$ smaller (torus 0, double "
                           r"torus $-2$), never larger than the sphere's 2."),
            "edges counted per face": (self._counts(2 - 2 * g, edges_per_face=True),
                                       rf"You counted $E = {self.k}F$, every edge once per "
                                       r"face. On a closed mesh each edge lies on **two** "
                                       rf"faces, so ${self.k}F = 2E$."),
        }
        E, F = self.expected
        return [("the number of edges E", int(E),
                 [Mistake(v[0], text, key) for key, (v, text) in slips.items()]),
                ("the number of faces F", int(F),
                 [Mistake(v[1], text, key) for key, (v, text) in slips.items()])]

    def hints(self):
        k, V, g = self.k, self.V, self.genus
        chi = 2 - 2 * g
        factor = r"\tfrac{1}{2}" if k == 3 else "1"
        return [
            r"Two equations tie $V$, $E$ and $F$ together: Euler's formula "
            r"$V - E + F = \chi = 2 - 2g$ for a closed orientable surface of genus $g$, and a "
            r"count of the pairs (face, edge of that face).",
            rf"Each face has ${k}$ edges and each edge lies on exactly 2 faces, so ${k}F = 2E$, "
            rf"that is $E = \tfrac{{{k}}}{{2}}F$. Put this into Euler's formula and solve for "
            r"$F$ first.",
            rf"Here $\chi = 2 - 2 \cdot {g} = {chi}$, and with $E = \tfrac{{{k}}}{{2}}F$ "
            rf"Euler's formula becomes $(\tfrac{{{k}}}{{2}} - 1)\,F = V - \chi$, that is "
            rf"${factor}\,F = {V - chi}$.",
        ]

    def worked(self):
        k, V, g = self.k, self.V, self.genus
        chi = 2 - 2 * g
        rest = V - chi
        F = 2 * rest // (k - 2)
        E = k * F // 2
        return Worked([
            rf"A closed orientable surface of genus $g = {g}$ has Euler characteristic "
            rf"$\chi = 2 - 2g = {chi}$.",
            rf"Count the pairs (face, edge): each of the $F$ faces has ${k}$ edges, and each "
            rf"edge is counted twice (it lies on 2 faces), so ${k}F = 2E$ and "
            rf"$E = \tfrac{{{k}}}{{2}}F$.",
            rf"Substitute into $V - E + F = \chi$: $V - (\tfrac{{{k}}}{{2}} - 1)F = \chi$, so "
            rf"$F = \dfrac{{V - \chi}}{{{k}/2 - 1}} = \dfrac{{{V} - {_paren(chi)}}}{{{k}/2 - 1}} = "
            rf"\dfrac{{{rest}}}{{{k}/2 - 1}} = {F}$.",
            rf"Then $E = \tfrac{{{k}}}{{2}} \cdot {F} = {E}$. Check: "
            rf"${V} - {E} + {F} = {V - E + F} = \chi$.",
        ], [E, F])

    def statement(self):
        kind = "triangle" if self.k == 3 else "quadrilateral"
        handles = {0: "no handles (it is topologically a sphere)", 1: "one handle (a torus)",
                   2: "two handles (a double torus)", 3: "three handles"}[self.genus]
        return (
            rf"A closed, connected, orientable mesh made only of {kind}s has genus "
            rf"$g = {self.genus}$, {handles}, and $V = {self.V}$ vertices. How many edges and "
            r"faces does it have?" "\n\n"
            r"**Answer:** a list of 2 whole numbers `[E, F]`." "\n\n"
            + data_note("V", "genus", "k") + " (`.k` is the number of vertices per face.)")


class GenusFromCounts(DrawnExercise):
    r"""The genus of a connected orientable mesh from its counts and its boundary loops.

    :math:`V - E + F = 2 - 2g - b`, so :math:`g = \frac{2 - b - (V - E + F)}{2}`.

    Attributes: ``V``, ``E``, ``F``, ``b`` (boundary loops), ``boundary_edges``.

    Examples
    --------
    >>> ex = GenusFromCounts(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> chi = ex.V - ex.E + ex.F
    >>> ex.check(2 - ex.b - chi).diagnosis                   # not halved
    'no half'
    """

    title = "Find the genus"
    answer_form = "number"
    what = "the genus"
    may_coincide = ("boundary ignored", "no half", "wrong sign")
    advice = (r"Compute $\chi = V - E + F$, then solve $\chi = 2 - 2g - b$ for $g$: "
            r"$g = (2 - b - \chi) / 2$.")

    def draw(self, rng):
        self.genus = int(pick(rng, (0, 1, 1, 2, 2, 3)))
        self.b = int(pick(rng, (0, 1, 1, 2, 3)))
        self.V = int(rng.integers(20, 61))
        loops = [int(rng.integers(3, 9)) for _ in range(self.b)]
        self.boundary_edges = int(sum(loops))
        chi = 2 - 2 * self.genus - self.b
        # a triangle mesh: 3F = 2E - E_b, with V - E + F = chi
        self.E = 3 * (self.V - chi) - self.boundary_edges
        self.F = 2 * (self.V - chi) - self.boundary_edges
        self.expected = self.genus

    def acceptable(self):
        return self.boundary_edges <= self.V // 2 and self.F > 0

    def mistakes(self):
        chi, b = self.V - self.E + self.F, self.b
        return [
            Mistake((2 - chi) / 2, r"You left out the boundary. Every boundary loop (hole) "
                    r"lowers $\chi$ by one, like a disc cut out of the surface: "
                    rf"$\chi = 2 - 2g - b$ with $b = {b}$ here.", "boundary ignored"),
            Mistake(2 - b - chi, r"You forgot to halve: $\chi = 2 - 2g - b$ gives "
                    r"$2g = 2 - b - \chi$, so $g$ is **half** of that (each handle costs 2).",
                    "no half"),
            Mistake((chi - 2 + b) / 2, r"The sign is wrong: a genus is never negative. From "
                    r"$\chi = 2 - 2g - b$, $g = (2 - b - \chi) / 2$.", "wrong sign"),
            Mistake((2 - b - (self.V + self.E - self.F)) / 2, r"You computed $\chi$ with the "
                    r"wrong signs. The Euler characteristic alternates: "
                    r"$\chi = V - E + F$ (vertices plus, edges minus, faces plus).",
                    "chi signs"),
        ]

    off_by_one = (r"Off by one: compute $\chi = V - E + F$ once more, and remember that each "
                  r"handle lowers $\chi$ by 2 and each boundary loop by 1.")

    def hints(self):
        chi = self.V - self.E + self.F
        return [
            r"Euler's formula extends to surfaces with holes: a connected orientable surface "
            r"with $g$ handles and $b$ boundary loops has $V - E + F = 2 - 2g - b$.",
            r"Compute the Euler characteristic $\chi = V - E + F$ from the three counts, then "
            r"solve $\chi = 2 - 2g - b$ for $g$.",
            rf"Here $\chi = {self.V} - {self.E} + {self.F} = {chi}$ and $b = {self.b}$, so "
            rf"$2g = 2 - b - \chi = {2 - self.b - chi}$.",
        ]

    def worked(self):
        V, E, F, b = self.V, self.E, self.F, self.b
        chi = V - E + F
        twice = 2 - b - chi
        g = twice // 2
        return Worked([
            rf"The Euler characteristic: $\chi = V - E + F = {V} - {E} + {F} = {chi}$.",
            rf"For a connected orientable surface with $g$ handles and $b$ boundary loops, "
            rf"$\chi = 2 - 2g - b$; here $b = {b}$"
            + (" (the mesh is closed)." if b == 0 else "."),
            rf"So $2g = 2 - b - \chi = 2 - {b} - {_paren(chi)} = {twice}$ and $g = {g}$.",
        ], g)

    def statement(self):
        loops = {0: "no boundary (it is closed)", 1: "one boundary loop (one hole)"}.get(
            self.b, f"{self.b} boundary loops (holes)")
        return (
            rf"A connected, orientable triangle mesh has $V = {self.V}$ vertices, "
            rf"$E = {self.E}$ edges and $F = {self.F}$ faces, and {loops}. What is its genus "
            r"$g$ (the number of handles)?" "\n\n"
            r"**Answer:** one whole number." "\n\n"
            + data_note("V", "E", "F", "b"))


class EdgeCollapseCounts(_Parts):
    r"""The counts of a triangle mesh after interior and boundary edge collapses.

    Collapsing an interior edge removes 1 vertex, 3 edges (the edge and one of the two other
    edges of each of its two faces) and 2 faces; a boundary edge has one face: 1 vertex, 2
    edges, 1 face. Either way :math:`V - E + F` stays the same.

    Attributes: ``V``, ``E``, ``F``, ``n_interior``, ``n_boundary``.

    Examples
    --------
    >>> ex = EdgeCollapseCounts(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> n = ex.n_interior + ex.n_boundary                    # one edge per collapse
    >>> V, E, F = ex.expected
    >>> ex.check([V, ex.E - n, F]).diagnosis
    'one edge per collapse'
    """

    title = "Counts after edge collapses"
    form_hint = "`[V, E, F]`, three whole numbers."
    may_coincide = ("boundary as interior",)
    advice = (r"An interior edge collapse removes 1 vertex, 3 edges and 2 faces; a boundary edge "
            r"collapse 1 vertex, 2 edges and 1 face. Check: $V - E + F$ does not change.")

    def draw(self, rng):
        self.V = int(rng.integers(30, 200))
        b = int(pick(rng, (0, 1, 2)))
        boundary = int(rng.integers(6, 13)) if b else 0
        chi = 2 - 2 * int(pick(rng, (0, 1))) - b
        self.E = 3 * (self.V - chi) - boundary
        self.F = 2 * (self.V - chi) - boundary
        self.n_interior = int(rng.integers(2, 9))
        self.n_boundary = int(rng.integers(1, 4)) if b else 0
        i, j = self.n_interior, self.n_boundary
        self.expected = np.array([self.V - i - j, self.E - 3 * i - 2 * j, self.F - 2 * i - j])

    def _parts(self):
        i, j = self.n_interior, self.n_boundary
        V, E, F = self.V, self.E, self.F
        one_edge = (r"A collapse removes more than the collapsed edge: each face of the edge "
                    r"degenerates and two of its edges fall onto each other, so one more edge "
                    r"per face disappears. Interior edge: 3 edges, boundary edge: 2.")
        one_face = (r"An interior edge has **two** faces, and both degenerate to a line when the "
                    r"edge shrinks to a point: 2 faces per interior collapse (1 for a boundary "
                    r"edge, which has one face).")
        like_interior = (r"You counted the boundary collapses like interior ones. A boundary "
                         r"edge has a single face: its collapse removes 1 vertex, 2 edges and "
                         r"1 face.")
        no_vertex = (r"Every collapse merges the two end points into one vertex: 1 vertex fewer "
                     r"per collapse.")
        return [
            ("the number of vertices V", V - i - j,
             [Mistake(V - 2 * (i + j), r"A collapse merges two vertices into **one** new "
                      r"vertex: the count drops by 1, not 2.", "two vertices removed"),
              Mistake(V, no_vertex, "no vertex removed")]),
            ("the number of edges E", E - 3 * i - 2 * j,
             [Mistake(E - i - j, one_edge, "one edge per collapse"),
              Mistake(E - 3 * (i + j), like_interior, "boundary as interior")]),
            ("the number of faces F", F - 2 * i - j,
             [Mistake(F - i - j, one_face, "one face per collapse"),
              Mistake(F - 2 * (i + j), like_interior, "boundary as interior")]),
        ]

    def hints(self):
        i, j = self.n_interior, self.n_boundary
        last = (rf"Here the {i} interior collapses remove {i} vertices, {3 * i} edges and "
                rf"{2 * i} faces")
        if j:
            last += rf"; the {j} boundary collapses remove {j}, {2 * j} and {j} more."
        else:
            last += "."
        return [
            r"Picture one collapse: the edge shrinks to a point, its two end points merge into "
            r"one vertex, and every face on the edge degenerates into a line and disappears.",
            r"Count what one collapse removes: an interior edge (two faces) takes 1 vertex, 3 "
            r"edges (itself and one of the two other edges of each face) and 2 faces; a "
            r"boundary edge (one face) 1 vertex, 2 edges and 1 face. Multiply by the numbers of "
            r"collapses.",
            last,
        ]

    def worked(self):
        i, j = self.n_interior, self.n_boundary
        V, E, F = self.V - i - j, self.E - 3 * i - 2 * j, self.F - 2 * i - j
        steps = [
            rf"Each of the {i} interior collapses removes 1 vertex, 3 edges (the edge, and on "
            r"each of its 2 faces one of the other two edges, which falls onto the third) and "
            rf"2 faces: $-{i}$ vertices, $-{3 * i}$ edges, $-{2 * i}$ faces.",
        ]
        if j:
            steps.append(rf"Each of the {j} boundary collapses removes 1 vertex, 2 edges and 1 "
                         rf"face (a boundary edge has one face): $-{j}$, $-{2 * j}$, $-{j}$.")
        steps += [
            rf"$V = {self.V} - {i + j} = {V}$, $E = {self.E} - {3 * i + 2 * j} = {E}$, "
            rf"$F = {self.F} - {2 * i + j} = {F}$.",
            rf"Check: $V - E + F = {V - E + F}$, the same as before "
            rf"(${self.V} - {self.E} + {self.F} = {self.V - self.E + self.F}$): a legal "
            r"collapse does not change the topology.",
        ]
        return Worked(steps, [V, E, F])

    def statement(self):
        if self.n_boundary:
            what = (rf"{self.n_interior} interior edges and then {self.n_boundary} boundary "
                    r"edges (edges with a single face)")
        else:
            what = rf"{self.n_interior} interior edges (the mesh is closed)"
        return (
            rf"A triangle mesh has $V = {self.V}$, $E = {self.E}$, $F = {self.F}$. A "
            rf"simplification collapses, one after the other, {what}; every collapse is legal "
            r"(the mesh stays a manifold, no face flips). What are $V$, $E$ and $F$ afterwards?"
            "\n\n" r"**Answer:** a list of 3 whole numbers `[V, E, F]`." "\n\n"
            + data_note("V", "E", "F", "n_interior", "n_boundary"))
