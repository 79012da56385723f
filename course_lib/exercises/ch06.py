r"""Chapter 6 exercises: polygon meshes, their data structures and QEM simplification, exam style.

Each class is one kind of exam question: the counts of a closed mesh from Euler's formula, the
genus of a mesh with holes, the counts after a number of edge collapses; which of four kinds a
small face list is (closed manifold, manifold with boundary, non-manifold edge, non-manifold
vertex), which face of a closed mesh is flipped; a winged-edge record filled in from a face list,
a walk through a half-edge table and the one-ring of a vertex by the rotation
:math:`h \leftarrow \operatorname{twin}(\operatorname{prev}(h))`; a vertex quadric of
Garland and Heckbert's error metric, the cost of an edge collapse, and the optimal position of
the merged vertex. The ``seed`` draws numbers that work out by hand: small meshes (tetrahedron,
square pyramid, triangular prism, octahedron) with shuffled vertex labels, planes with simple
normals through points with whole coordinates.

The expected answers come from :mod:`course_lib.mesh`. Each exercise names the slips it
anticipates (the genus term or its factor 2 forgotten, the boundary loops ignored, left and
right face swapped, ``next`` and ``prev`` mixed up, the composition read the wrong way, a
clockwise turn, only the edges checked for manifoldness, an unnormalised plane, a forgotten
homogeneous 1, ...), computes the answer each slip would give, and draws its numbers again
until those answers differ clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.mesh`): faces list their vertices counter-clockwise seen
from outside; half-edge ``h`` of face ``f`` runs from a vertex of ``f`` to the next one;
edge ``e`` of a winged-edge table runs from ``start`` to ``end``, its **left** face walks it
from start to end and its **right** face from end to start; a plane is
:math:`(a, b, c, d)` with :math:`ax + by + cz + d = 0` and :math:`a^2 + b^2 + c^2 = 1`, and its
quadric is :math:`K_p = p p^T`.
"""
import math

import numpy as np

from .. import format as fmt
from .. import mesh
from .core import (DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, close, data_note,
                   diagnose_matrix, diagnose_parts, has_placeholder, parts_separated, pick,
                   read_floats)

__all__ = [
    "EXERCISES",
    "MESH_KINDS",
    "CollapseCost",
    "EdgeCollapseCounts",
    "EulerCounts",
    "FlippedFace",
    "GenusFromCounts",
    "HalfEdgeWalk",
    "Manifoldness",
    "OneRing",
    "OptimalPosition",
    "VertexQuadric",
    "WingedEdgeRecord",
]

_num = fmt.number
_vec = fmt.vector_latex


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

def _read_ints(answer, n, form, low=None, high=None):
    """A tuple of `n` whole numbers from the answer, or a Feedback saying why not."""
    if has_placeholder(answer, none_inside=True):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, (bool, np.bool_)):
        return Feedback("invalid", form, "unreadable")
    values = read_floats(answer)
    if values is None or values.size != n or (n > 1 and values.shape != (n,)):
        return Feedback("invalid", form, "unreadable")
    if isinstance(answer, (list, tuple)) and any(isinstance(a, (bool, np.bool_))
                                                 for a in answer):
        return Feedback("invalid", form, "unreadable")
    values = values.ravel()
    if not np.all(values == np.round(values)):
        return Feedback("invalid", "These are counts and indices: give whole numbers. " + form,
                        "unreadable")
    out = tuple(int(v) for v in values)
    if low is not None and any(v < low or v > high for v in out):
        return Feedback("invalid", f"Every number must lie between {low} and {high}. " + form,
                        "unreadable")
    return out


def _faces_words(faces):
    return ", ".join(rf"$f_{{{k}}} = ({', '.join(str(v) for v in f)})$"
                     for k, f in enumerate(faces))


#: Small closed meshes, faces counter-clockwise seen from outside.
_SMALL = {
    "tetrahedron": mesh.tetrahedron,
    "square pyramid": lambda: (
        np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [0, 0, 1.5]], dtype=float),
        [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]),
    "triangular prism": lambda: (
        np.array([[math.cos(a), math.sin(a), z] for z in (0.0, 1.0)
                  for a in (0.0, 2 * math.pi / 3, 4 * math.pi / 3)]),
        [[0, 2, 1], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [2, 0, 3, 5]]),
    "octahedron": lambda: (
        np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                 dtype=float),
        [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5],
         [0, 3, 5]]),
}


def _shuffled(rng, vertices, faces):
    """The same mesh with vertex labels permuted, faces reordered and each face rotated.

    The winding of every face is kept, so an outward mesh stays outward.
    """
    vertices = np.asarray(vertices, dtype=float)
    perm = rng.permutation(len(vertices))            # old label i becomes perm[i]
    new_vertices = np.empty_like(vertices)
    new_vertices[perm] = vertices
    out = []
    for f in [list(map(int, f)) for f in faces]:
        k = int(rng.integers(len(f)))
        out.append([int(perm[v]) for v in f[k:] + f[:k]])
    order = rng.permutation(len(out))
    return new_vertices, [out[i] for i in order]


def _small_mesh(rng, names):
    name = str(pick(rng, names))
    vertices, faces = _SMALL[name]()
    return (name, *_shuffled(rng, vertices, faces))


class _Parts(DrawnExercise):
    """An answer of a few numbers, each with its own slips (``_parts()``), see diagnose_parts."""

    answer_form = "custom"
    form_hint = ""

    def mistakes(self):
        return []

    def separated(self, mistakes):
        return parts_separated(self._parts())

    def _judge(self, answer):
        return diagnose_parts(answer, self._parts(), "your answer", self.form_hint, self.hint)


class _Record(DrawnExercise):
    """An answer that is a short tuple of whole numbers, matched whole against the slips.

    ``self.expected`` is a tuple; ``mistakes()`` returns Mistakes whose values are tuples
    (``numeric=False``). ``fields`` names the numbers, for the feedback on an unexplained
    answer.
    """

    answer_form = "custom"
    fields = ()
    low, high = None, None

    def keep(self, mistakes):
        return [m for m in mistakes if m.value != self.expected]

    def separated(self, mistakes):
        seen = {}
        for m in mistakes:
            if m.value == self.expected:
                return False
            if seen.setdefault(m.value, m.key) != m.key:
                return False
        return True

    def _read(self, answer):
        return _read_ints(answer, len(self.fields), self.form_hint, self.low, self.high)

    def _judge(self, answer):
        value = self._read(answer)
        if isinstance(value, Feedback):
            return value
        if value == self.expected:
            return Feedback("correct", f"All {len(self.fields)} entries are right.")
        for mistake in self._mistakes:
            if value == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        off = [name for name, a, b in zip(self.fields, value, self.expected) if a != b]
        return Feedback("wrong", "Not right yet: " + ", ".join(off) + ". " + self.hint,
                        "entries differ")


# ---------------------------------------------------------------------------------------------
# Euler's formula
# ---------------------------------------------------------------------------------------------

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
    hint = (r"Use two equations: Euler's $V - E + F = 2 - 2g$ and the edge count "
            r"$kF = 2E$ (each face has $k$ edges, each edge lies on 2 faces).")

    def draw(self, rng):
        self.k = int(pick(rng, (3, 4)))
        self.genus = int(pick(rng, (0, 1, 1, 2, 3)))
        self.V = int(rng.integers(12, 41))
        self.expected = np.array(self._counts(2 - 2 * self.genus), dtype=float)

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
        return [("the number of edges E", float(E),
                 [Mistake(v[0], text, key) for key, (v, text) in slips.items()]),
                ("the number of faces F", float(F),
                 [Mistake(v[1], text, key) for key, (v, text) in slips.items()])]

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
    hint = (r"Compute $\chi = V - E + F$, then solve $\chi = 2 - 2g - b$ for $g$: "
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
        self.expected = float(self.genus)

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
    hint = (r"An interior edge collapse removes 1 vertex, 3 edges and 2 faces; a boundary edge "
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
        self.expected = np.array([self.V - i - j, self.E - 3 * i - 2 * j, self.F - 2 * i - j],
                                 dtype=float)

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


# ---------------------------------------------------------------------------------------------
# Manifoldness and orientation
# ---------------------------------------------------------------------------------------------

#: The kinds of face list :class:`Manifoldness` asks about: name -> what it means.
MESH_KINDS = {
    "closed manifold": "every edge has two faces, the faces around each vertex form one "
                       "closed fan",
    "manifold with boundary": "every edge has one or two faces (some only one), the faces "
                              "around each vertex form one fan (open at the boundary)",
    "non-manifold edge": "some edge has three or more faces",
    "non-manifold vertex": "every edge has at most two faces, but the faces around some vertex "
                           "form two or more fans that meet only at that vertex",
}


def _edge_faces(faces):
    """{(min, max): [faces]} of a face list."""
    table = {}
    for k, f in enumerate(faces):
        for a, b in zip(f, f[1:] + f[:1]):
            table.setdefault((min(a, b), max(a, b)), []).append(k)
    return table


def _fans(faces, v):
    """The fans of faces around vertex v: groups of faces linked through edges at v."""
    around = [k for k, f in enumerate(faces) if v in f]
    parent = {k: k for k in around}

    def root(k):
        while parent[k] != k:
            k = parent[k]
        return k

    table = _edge_faces(faces)
    for (a, b), fs in table.items():
        if v in (a, b):
            for other in fs[1:]:
                parent[root(other)] = root(fs[0])
    groups = {}
    for k in around:
        groups.setdefault(root(k), []).append(k)
    return sorted(groups.values())


def _kind_and_evidence(faces):
    """The MESH_KINDS name of a face list and the facts that prove it (a dict)."""
    table = _edge_faces(faces)
    crowded = {e: fs for e, fs in table.items() if len(fs) > 2}
    border = sorted(e for e, fs in table.items() if len(fs) == 1)
    pinched = {}
    for v in sorted({v for f in faces for v in f}):
        fans = _fans(faces, v)
        if len(fans) > 1:
            pinched[v] = fans
    evidence = {"crowded": crowded, "border": border, "pinched": pinched}
    if crowded:
        return "non-manifold edge", evidence
    if pinched:
        return "non-manifold vertex", evidence
    return ("manifold with boundary" if border else "closed manifold"), evidence


def _glued_tetrahedra(share):
    """Two tetrahedra sharing `share` vertices (1: a vertex, 2: an edge)."""
    a = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]
    if share == 1:                       # second copy: vertex 0 shared, 4, 5, 6 new
        m = {0: 0, 1: 4, 2: 5, 3: 6}
    else:                                # edge (0, 1) shared, 4, 5 new
        m = {0: 1, 1: 0, 2: 4, 3: 5}
    return a + [[m[v] for v in f] for f in a]


def _candidates():
    """(name, faces) of the small face lists Manifoldness draws from, by kind."""
    octa = _SMALL["octahedron"]()[1]
    pyramid = _SMALL["square pyramid"]()[1]
    prism = _SMALL["triangular prism"]()[1]
    tetra = mesh.tetrahedron()[1].tolist()
    return {
        "closed manifold": [octa, pyramid, prism, tetra],
        "manifold with boundary": [octa[1:], pyramid[1:], prism[2:], tetra[1:],
                                   [f for k, f in enumerate(octa) if k not in (0, 6)]],
        "non-manifold edge": [octa + [[0, 2, 6]], tetra + [[0, 1, 4]], _glued_tetrahedra(2),
                              pyramid + [[0, 1, 5]]],
        "non-manifold vertex": [_glued_tetrahedra(1), [[0, 1, 2], [0, 3, 4]],
                                octa[1:] + [[0, 6, 7]], pyramid + [[4, 5, 6]],
                                [f for k, f in enumerate(octa) if k not in (1, 3)]],
    }


def _pairs_words(edges):
    return ", ".join(f"({a}, {b})" for a, b in edges)


class Manifoldness(DrawnExercise):
    r"""Decide whether a small face list is a closed manifold, has a boundary, or is non-manifold.

    A manifold mesh has one or two faces per edge and one fan of faces around each vertex;
    it is closed when every edge has two faces. Two fans that meet only at a vertex (two
    tetrahedra touching at a corner, a bow tie) make that vertex non-manifold even though every
    edge is fine.

    Attributes: ``faces`` (a list of vertex lists), ``menu`` (the four names).

    Examples
    --------
    >>> ex = Manifoldness(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [k for k in ex.menu if k != ex.expected][0]
    >>> ex.check(wrong).status
    'wrong'
    >>> ex.check(...).status, ex.check("a doughnut").status
    ('unanswered', 'invalid')
    """

    title = "Manifold or not?"
    answer_form = "custom"
    menu = tuple(MESH_KINDS)

    def draw(self, rng):
        self._kind = kind = str(pick(rng, self.menu))
        faces = pick(rng, _candidates()[kind])
        n = max(max(f) for f in faces) + 1
        perm = rng.permutation(n)
        faces = [[int(perm[v]) for v in f] for f in faces]
        faces = [f[k:] + f[:k] for f, k in zip(faces, rng.integers(0, 3, size=len(faces)))]
        self.faces = [faces[i] for i in rng.permutation(len(faces))]
        self.expected, self.evidence = _kind_and_evidence(self.faces)

    def acceptable(self):
        return self.expected == self._kind

    def separated(self, mistakes):
        return True

    def _reason(self, said):
        """Why `said` is wrong for this face list."""
        ev, right = self.evidence, self.expected
        if right == "non-manifold edge":
            (a, b), fs = sorted(ev["crowded"].items())[0]
            return (rf"Look at the edge $({a}, {b})$: it lies on {len(fs)} faces "
                    rf"({', '.join(f'$f_{{{k}}}$' for k in fs)}), like pages on the spine of a "
                    r"book. On a manifold an edge has one face on each side, two at most, so "
                    r"this is a **non-manifold edge**.")
        if right == "non-manifold vertex":
            v, fans = sorted(ev["pinched"].items())[0]
            groups = " and ".join("{" + ", ".join(f"$f_{{{k}}}$" for k in fan) + "}"
                                  for fan in fans)
            start = ("Every edge is fine (one or two faces each), but that is not enough. "
                     if said != "non-manifold edge" else
                     "No edge has more than two faces, so no edge is non-manifold. ")
            return (start + rf"The faces around vertex ${v}$ form {len(fans)} separate fans, "
                    rf"{groups}, that touch only at ${v}$: near that vertex the surface does "
                    r"not look like one disc but like two cones tip to tip. That is a "
                    r"**non-manifold vertex**; check the fans around each vertex, not only "
                    r"the faces of each edge.")
        if right == "manifold with boundary":
            border = ev["border"]
            shown = _pairs_words(border[:4]) + (" ..." if len(border) > 4 else "")
            if said == "closed manifold":
                return (rf"It is not closed: {len(border)} edges have only one face, e.g. "
                        rf"{shown}. They form the rim of a hole. Every edge has one or two "
                        r"faces and every vertex one fan, so it is a **manifold with "
                        r"boundary**.")
            return (r"Nothing is non-manifold here: every edge has one or two faces and the "
                    r"faces around every vertex form a single fan (open at the boundary "
                    rf"vertices). The {len(border)} edges with one face ({shown}) are a "
                    r"boundary, which a manifold may have: a **manifold with boundary**.")
        why = {"manifold with boundary": r"There is no boundary: no edge has only one face "
                                         r"(a boundary edge is one with a single face). ",
               "non-manifold edge": r"No edge has three or more faces. ",
               "non-manifold vertex": r"No vertex is pinched: the faces around each vertex "
                                      r"form one single fan. "}[said]
        return (why + r"Every edge has exactly two faces and the faces around every vertex "
                r"form one closed fan: a **closed manifold**.")

    def _judge(self, answer):
        if has_placeholder(answer, none_inside=True):
            return Feedback("unanswered", UNANSWERED)
        form = "Give one of the names " + ", ".join(f"`'{k}'`" for k in self.menu) + "."
        if not isinstance(answer, str):
            return Feedback("invalid", form, "unreadable")
        name = " ".join(answer.strip().lower().replace("-", " ").replace("_", " ").split())
        name = name.replace("non manifold", "non-manifold")
        if name not in MESH_KINDS:
            return Feedback("invalid", f"{answer!r} is not on the menu. " + form, "unreadable")
        if name == self.expected:
            return Feedback("correct", f"It is a {name}: {MESH_KINDS[name]}.")
        return Feedback("wrong", self._reason(name), f"said {name}")

    def statement(self):
        rows = "\n".join(f"| `'{name}'` | {meaning} |" for name, meaning in MESH_KINDS.items())
        return (
            rf"A mesh has the {len(self.faces)} faces {_faces_words(self.faces)} (vertex "
            r"indices; the positions do not matter). Which of these kinds is it?" "\n\n"
            "| name | meaning |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** one of the four names, as a string." "\n\n"
            + data_note("faces", "menu"))


class FlippedFace(DrawnExercise):
    r"""Find the one face of a closed mesh whose vertices are listed the wrong way round.

    With consistent winding two faces sharing an edge walk it in opposite directions. The
    flipped face walks each of its edges in the same direction as its neighbour: it clashes
    with *all* its neighbours, each neighbour with one face only.

    Attributes: ``faces``, ``flipped`` (the index; also ``expected``).

    Examples
    --------
    >>> ex = FlippedFace(seed=4)
    >>> ex.check(ex.flipped).status
    'correct'
    >>> ex.check(ex.neighbours[0]).diagnosis
    'a neighbour'
    """

    title = "Which face is flipped?"
    answer_form = "custom"

    def draw(self, rng):
        self.shape, vertices, faces = _small_mesh(rng, ("square pyramid", "triangular prism",
                                                        "octahedron"))
        self.flipped = int(rng.integers(len(faces)))
        faces[self.flipped] = faces[self.flipped][::-1]
        self.faces = faces
        self.expected = float(self.flipped)
        table = _edge_faces(faces)
        self.neighbours = sorted({k for fs in table.values() if self.flipped in fs
                                  for k in fs if k != self.flipped})

    def separated(self, mistakes):
        return True

    def _clashes(self, k):
        """The faces that walk a shared edge of face k in the same direction as k."""
        directed = {}
        for j, f in enumerate(self.faces):
            for a, b in zip(f, f[1:] + f[:1]):
                directed.setdefault((a, b), []).append(j)
        out = set()
        f = self.faces[k]
        for a, b in zip(f, f[1:] + f[:1]):
            out |= {j for j in directed[(a, b)] if j != k}
        return sorted(out)

    def _judge(self, answer):
        n = len(self.faces)
        value = _read_ints(answer, 1, f"Give the index of the face, a whole number from 0 to "
                           f"{n - 1}.", 0, n - 1)
        if isinstance(value, Feedback):
            return value
        k = value[0]
        if k == self.flipped:
            return Feedback("correct", f"Face {k} walks every one of its edges the same way as "
                            "the neighbour across it; reversing it makes the winding "
                            "consistent.")
        if k in self.neighbours:
            return Feedback("wrong", rf"Face $f_{{{k}}}$ does clash with a neighbour, "
                            rf"$f_{{{self._clashes(k)[0]}}}$ (they walk their shared edge in "
                            r"the same direction), but only with that one; with its other "
                            r"neighbours it agrees. Reversing it would make more clashes. Look "
                            r"for the face that clashes with **all** of its neighbours.",
                            "a neighbour")
        return Feedback("wrong", rf"Face $f_{{{k}}}$ walks each of its edges in the opposite "
                        r"direction to the face across it: it agrees with all its neighbours. "
                        r"For each edge $(a, b)$ of a face, check that the neighbour lists it as "
                        r"$(b, a)$.", "consistent face")

    def statement(self):
        return (
            rf"The faces of a closed mesh (a {self.shape}) are {_faces_words(self.faces)}. "
            r"All but one of them list their vertices counter-clockwise seen from outside; "
            r"one face lists them the other way round. Which one?" "\n\n"
            r"**Answer:** the index $k$ of the flipped face $f_k$, one whole number." "\n\n"
            + data_note("faces"))


# ---------------------------------------------------------------------------------------------
# Winged edge and half edge
# ---------------------------------------------------------------------------------------------

_WING_FIELDS = ("left_face", "right_face", "left_prev", "left_next", "right_prev", "right_next")


class WingedEdgeRecord(_Record):
    r"""Fill in the winged-edge record of one edge of a small closed mesh.

    Edge :math:`e` runs from ``start`` to ``end``; its left face walks it start to end, its
    right face end to start. The wings are the edges before and after :math:`e` in each of those
    walks (counter-clockwise around each face).

    Attributes: ``faces``, ``edges`` (``edges[e] = (start, end)``), ``e``.

    Examples
    --------
    >>> ex = WingedEdgeRecord(seed=0)
    >>> ex.check(list(ex.expected)).status
    'correct'
    >>> lf, rf, lp, ln, rp, rn = ex.expected
    >>> ex.check([lf, rf, ln, lp, rn, rp]).diagnosis
    'prev and next swapped'
    >>> ex.check(dict(zip(ex.fields, ex.expected))).status
    'correct'
    """

    title = "Fill in a winged-edge record"
    fields = _WING_FIELDS
    form_hint = ("Give 6 whole numbers `[left_face, right_face, left_prev, left_next, "
                 "right_prev, right_next]`, or a dict with those keys.")
    hint = (r"Find the face that lists start then end (the left face) and the one that lists "
            r"end then start (the right face). Around each face, counter-clockwise, the "
            r"*prev* wing is the edge just before $e$ and the *next* wing the edge just after.")

    def draw(self, rng):
        self.shape, vertices, self.faces = _small_mesh(rng, ("tetrahedron", "square pyramid",
                                                             "triangular prism",
                                                             "octahedron"))
        w = mesh.WingedEdgeMesh.from_faces(vertices, self.faces)
        self.edges = [tuple(int(x) for x in row) for row in w.edges()]
        self.e = int(rng.integers(len(self.edges)))
        self.low, self.high = -1, len(self.edges) - 1
        record = w.records()[self.e]
        self.expected = tuple(int(record[k]) for k in _WING_FIELDS)

    def _read(self, answer):
        if isinstance(answer, dict):
            if has_placeholder(list(answer.values()), none_inside=True):
                return Feedback("unanswered", UNANSWERED)
            if set(answer) != set(_WING_FIELDS):
                return Feedback("invalid", self.form_hint, "unreadable")
            answer = [answer[k] for k in _WING_FIELDS]
        return super()._read(answer)

    def mistakes(self):
        lf, rf, lp, ln, rp, rn = self.expected
        return [
            Mistake((rf, lf, rp, rn, lp, ln), r"Left and right are swapped. The **left** face is "
                    r"the one that walks the edge from start to end (it lists start, then end); "
                    r"the right face walks it from end to start. Each face keeps its own two "
                    r"wings.",
                    "left and right swapped", numeric=False),
            Mistake((lf, rf, ln, lp, rn, rp), r"*prev* and *next* are swapped. Walk around each "
                    r"face counter-clockwise (the order its vertices are listed in): *prev* is the "
                    r"edge you come from just before $e$, *next* the edge you take just after it.",
                    "prev and next swapped", numeric=False),
            Mistake((lf, rf, lp, ln, rn, rp), r"The right wings are the wrong way round. The right "
                    r"face walks the edge from **end to start**: its *prev* edge ends at the end "
                    r"vertex, its *next* edge leaves from the start vertex.",
                    "right walk reversed", numeric=False),
            Mistake((lf, rf, rp, rn, lp, ln), r"The faces are right but the wings belong to the "
                    r"other face: the left wings are the edges before and after $e$ around the "
                    r"left face.", "wings of the other face", numeric=False),
        ]

    def statement(self):
        edges = ", ".join(rf"$e_{{{k}}}: {a} \to {b}$" for k, (a, b) in enumerate(self.edges))
        a, b = self.edges[self.e]
        return (
            rf"A closed mesh (a {self.shape}) has the faces {_faces_words(self.faces)}, each "
            r"counter-clockwise seen from outside, and the edges " + edges + r" (each from "
            r"its start to its end vertex)." "\n\n"
            rf"Fill in the winged-edge record of $e_{{{self.e}}}$ (from ${a}$ to ${b}$): its "
            r"left face (the face that walks it from start to end), its right face (walks "
            r"it from end to start), and the edges just before (*prev*) and just after "
            r"(*next*) it around the left face and around the right face." "\n\n"
            r"**Answer:** a list of 6 whole numbers (face and edge indices) "
            r"`[left_face, right_face, left_prev, left_next, right_prev, right_next]`, or a "
            r"dict with those keys." "\n\n" + data_note("faces", "edges", "e"))


def _half_edge_table(m):
    """A Markdown table of a HalfEdgeMesh: h, origin, twin, next, prev, face."""
    rows = "\n".join(f"| {h} | {m.origin[h]} | {m.twin[h]} | {m.next[h]} | {m.prev[h]} | "
                     f"{m.face[h]} |" for h in range(m.n_half_edges))
    return "| h | origin | twin | next | prev | face |\n|---|---|---|---|---|---|\n" + rows


_OPS = ("next", "prev", "twin")


class HalfEdgeWalk(_Parts):
    r"""Follow a composition of ``next``, ``prev`` and ``twin`` through a half-edge table.

    ``twin(next(h))`` means: first ``next``, then ``twin`` (the innermost call first). The
    target of a half-edge is the origin of its ``next`` (or of its ``twin``).

    Attributes: ``table`` (the HalfEdgeMesh), ``h``, ``ops`` (the operations in the order
    they are applied).

    Examples
    --------
    >>> ex = HalfEdgeWalk(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> g, target = ex.expected
    >>> ex.check([g, ex.table.origin[int(g)]]).diagnosis
    'origin, not target'
    """

    title = "Walk a half-edge structure"
    form_hint = "`[g, v]`: the half-edge reached and its target vertex, two whole numbers."
    may_coincide = ("inside out", "next and prev swapped")
    hint = (r"Work from the inside out: apply the innermost function to $h$ first, read the "
            r"result in the table, then apply the next function to that row.")

    def draw(self, rng):
        self.shape, vertices, faces = _small_mesh(rng, ("tetrahedron", "square pyramid",
                                                        "triangular prism"))
        self.faces = faces
        self.table = mesh.HalfEdgeMesh.from_faces(vertices, faces)
        while True:
            ops = [str(pick(rng, _OPS)) for _ in range(3)]
            if all({a, b} != {"next", "prev"} and not a == b == "twin"
                   for a, b in zip(ops, ops[1:])):
                break
        self.ops = ops
        self.h = int(rng.integers(self.table.n_half_edges))
        g = self._walk(ops)
        self.expected = np.array([g, int(self.table.target[g])], dtype=float)

    def _walk(self, ops, h=None):
        m, h = self.table, self.h if h is None else h
        arrays = {"next": m.next, "prev": m.prev, "twin": m.twin}
        for op in ops:
            h = int(arrays[op][h])
        return h

    def acceptable(self):
        return len(set(self.ops)) > 1 and self.ops != self.ops[::-1]

    def expression(self):
        """The walk as a composition, innermost first applied: ``twin(next(h))``."""
        text = "h"
        for op in self.ops:
            text = f"{op}({text})"
        return text

    def _parts(self):
        m = self.table
        swap = {"next": "prev", "prev": "next", "twin": "twin"}
        reverse = self._walk(self.ops[::-1])
        swapped = self._walk([swap[o] for o in self.ops])
        g = int(self.expected[0])
        inside_out = (rf"You applied the functions in the order they are written, left to "
                      rf"right. In ${self.expression()}$ the innermost one acts first: "
                      rf"{', then '.join(self.ops)}.")
        next_prev = (r"*next* and *prev* are mixed up: `next` is the following half-edge "
                     r"around the same face (counter-clockwise), `prev` the one before it; "
                     r"read the columns of the table with care.")
        return [
            ("the half-edge g", float(g),
             [Mistake(reverse, inside_out, "inside out"),
              Mistake(swapped, next_prev, "next and prev swapped")]),
            ("its target vertex", float(m.target[g]),
             [Mistake(m.origin[g], r"That is the **origin** of $g$, the vertex it leaves. Its "
                      r"target is where it arrives: the origin of `next(g)` (or of "
                      r"`twin(g)`).", "origin, not target"),
              Mistake(m.target[reverse], inside_out, "inside out"),
              Mistake(m.target[swapped], next_prev, "next and prev swapped")]),
        ]

    def statement(self):
        return (
            rf"The half-edge table of a closed mesh (a {self.shape}, faces "
            rf"{_faces_words(self.faces)}) is:" "\n\n" + _half_edge_table(self.table) + "\n\n"
            rf"Start at $h = {self.h}$ and evaluate $g = {self.expression()}$ (the innermost "
            r"function is applied first). Which half-edge is $g$, and which vertex does it "
            r"point to (its target)?" "\n\n"
            r"**Answer:** a list of 2 whole numbers `[g, v]`." "\n\n"
            + data_note("table", "h", "ops") + " (`.table.next[h]` etc. read the table.)")


class OneRing(_Record):
    r"""The one-ring of a vertex, counter-clockwise, by turning with twin(prev(h)).

    Starting from a half-edge :math:`h` that leaves :math:`v`,
    :math:`h \leftarrow \operatorname{twin}(\operatorname{prev}(h))` is the next half-edge
    leaving :math:`v` counter-clockwise; the targets of those half-edges are the one-ring.

    Attributes: ``table`` (the HalfEdgeMesh), ``v``, ``h`` (a half-edge leaving ``v``).

    Examples
    --------
    >>> ex = OneRing(seed=0)
    >>> ex.check(list(ex.expected)).status
    'correct'
    >>> first, *rest = ex.expected
    >>> ex.check([first] + rest[::-1]).diagnosis
    'clockwise'
    """

    title = "The one-ring of a vertex"
    hint = (r"Repeat $h \leftarrow \operatorname{twin}(\operatorname{prev}(h))$ until you are "
            r"back at the first half-edge, and write down the target of each $h$.")

    def draw(self, rng):
        self.shape, vertices, faces = _small_mesh(rng, ("square pyramid", "octahedron"))
        self.faces = faces
        self.table = m = mesh.HalfEdgeMesh.from_faces(vertices, faces)
        degrees = np.bincount(m.origin, minlength=m.n_vertices)
        self.v = int(pick(rng, np.flatnonzero(degrees == 4)))
        self.h = int(pick(rng, m.vertex_half_edges(self.v)))
        ring, h = [], self.h
        while True:
            ring.append(int(m.target[h]))
            h = int(m.twin[m.prev[h]])
            if h == self.h:
                break
        self.expected = tuple(ring)
        self.fields = tuple(f"neighbour {i}" for i in range(len(ring)))
        self.low, self.high = 0, m.n_vertices - 1
        self.form_hint = (f"Give the {len(ring)} neighbours as a list of vertex indices, "
                          "e.g. `[3, 1, 4, 2]`.")

    def mistakes(self):
        first, *rest = self.expected
        n = len(self.expected)
        found = [Mistake(tuple([first] + rest[::-1]), r"You went round **clockwise**. "
                         r"$\operatorname{next}(\operatorname{twin}(h))$ turns clockwise around "
                         r"the origin; $\operatorname{twin}(\operatorname{prev}(h))$ turns "
                         r"counter-clockwise: `prev(h)` enters $v$ along the face of $h$, and its "
                         r"twin leaves $v$ along the next edge counter-clockwise.",
                         "clockwise", numeric=False)]
        for k in range(1, n):
            found.append(Mistake(self.expected[k:] + self.expected[:k], r"Right neighbours in the "
                                 r"right order, but the list must start with the target of the "
                                 r"given half-edge $h$.", "wrong start", numeric=False))
        return found

    def separated(self, mistakes):
        return super().separated(mistakes) and len(set(self.expected)) == len(self.expected)

    def statement(self):
        return (
            rf"The half-edge table of a closed mesh (a {self.shape}, faces "
            rf"{_faces_words(self.faces)}) is:" "\n\n" + _half_edge_table(self.table) + "\n\n"
            rf"Half-edge $h = {self.h}$ leaves vertex $v = {self.v}$. Find the neighbours of "
            rf"$v$ in counter-clockwise order (seen from outside), starting with the target of "
            r"$h$, by repeating $h \leftarrow \operatorname{twin}(\operatorname{prev}(h))$."
            "\n\n" r"**Answer:** the list of the neighbours' vertex indices, in that order."
            "\n\n" + data_note("table", "v", "h"))


# ---------------------------------------------------------------------------------------------
# Quadric error metric
# ---------------------------------------------------------------------------------------------

#: Normals with whole coordinates: the axes, and two-axis diagonals (length sqrt 2).
_NORMALS = tuple(np.array(n, dtype=float) for n in
                 ([1, 0, 0], [0, 1, 0], [0, 0, 1], [-1, 0, 0], [0, -1, 0], [0, 0, -1],
                  [1, 1, 0], [1, -1, 0], [1, 0, 1], [0, 1, 1], [0, 1, -1], [-1, 0, 1]))


def _plane_words(n, p):
    """The plane through p with normal n (whole numbers) as an equation ``x + y = 3``."""
    names = ("x", "y", "z")
    terms = []
    for c, name in zip(n, names):
        if c:
            sign = ("- " if c < 0 else "+ ") if terms else ("-" if c < 0 else "")
            terms.append(f"{sign}{name}" if abs(c) == 1 else f"{sign}{_num(abs(c))}{name}")
    return " ".join(terms) + f" = {_num(float(np.dot(n, p)))}"


def _unit_plane(n, p):
    n = np.asarray(n, dtype=float)
    u = n / np.linalg.norm(n)
    return np.append(u, -float(u @ p))


def _draw_planes(rng, point, count, need_diagonal=False):
    """`count` planes through `point`, with distinct normals from _NORMALS (whole numbers)."""
    while True:
        picks = rng.choice(len(_NORMALS), size=count, replace=False)
        normals = [_NORMALS[i] for i in picks]
        if need_diagonal and all(np.abs(n).sum() == 1 for n in normals):
            continue
        if len({tuple(np.abs(n)) for n in normals}) == count:     # no two parallel
            return normals


def _quadric(planes):
    return sum(mesh.plane_quadric(p) for p in planes)


class VertexQuadric(DrawnExercise):
    r"""The quadric :math:`Q = \sum_p p p^T` of a vertex from the planes of its faces.

    Each plane is first normalised to :math:`(a, b, c, d)` with unit normal and
    :math:`d = -n \cdot x_0` for a point :math:`x_0` on it.

    Attributes: ``point`` (the vertex), ``normals`` (whole-number normals of the planes, not
    normalised), ``planes`` (the normalised :math:`(a, b, c, d)`, for checking your own).

    Examples
    --------
    >>> ex = VertexQuadric(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> raw = [np.append(n, -n @ ex.point) for n in ex.normals]     # not normalised
    >>> ex.check(sum(np.outer(p, p) for p in raw)).diagnosis
    'not normalised'
    """

    title = "A vertex quadric"
    what = "the quadric Q"
    transform = False
    hint = (r"Normalise each plane: divide $(a, b, c)$ and $d$ by $\sqrt{a^2 + b^2 + c^2}$; "
            r"then $K_p = p\,p^T$ for $p = (a, b, c, d)$, and $Q$ is the sum of the $K_p$.")

    def draw(self, rng):
        self.point = rng.integers(-2, 3, size=3).astype(float)
        self.normals = _draw_planes(rng, self.point, 3, need_diagonal=True)
        self.planes = np.array([_unit_plane(n, self.point) for n in self.normals])
        self.expected = _quadric(self.planes)

    def acceptable(self):
        return np.count_nonzero(self.point) >= 2

    def mistakes(self):
        raw = [np.append(n, -float(n @ self.point)) for n in self.normals]
        flipped = self.planes * np.array([1, 1, 1, -1])
        total = self.planes.sum(axis=0)
        return [
            Mistake(_quadric(raw), r"You did not normalise the planes. $p^T v$ is the "
                    r"distance of $v$ from the plane only when $a^2 + b^2 + c^2 = 1$: divide "
                    r"the equation by the length of its normal first (here "
                    r"$\sqrt 2$ for the slanted planes).", "not normalised"),
            Mistake(_quadric(flipped), r"The sign of $d$ is wrong. Write the plane as "
                    r"$ax + by + cz + d = 0$: for $n \cdot x = c_0$ that is $d = -c_0$. Check "
                    r"with the vertex: $p^T (x, y, z, 1)$ must be 0 there.", "sign of d"),
            Mistake(np.outer(total, total), r"You added the planes first and then took one "
                    r"outer product. The quadric is the sum of the outer products, "
                    r"$Q = \sum_p p\,p^T$, so that $v^T Q v = \sum_p (p^T v)^2$, a sum of "
                    r"squared distances; $(\sum_p p)(\sum_p p)^T$ squares a sum instead.",
                    "summed planes first"),
        ]

    def _judge(self, answer):
        value = read_floats(answer)
        if value is not None and value.shape == (3, 3) and close(value,
                                                                 self.expected[:3, :3]):
            return Feedback("wrong", r"That is only the $3 \times 3$ block $A$ (the normals' "
                            r"part). The quadric is $4 \times 4$: $p = (a, b, c, d)$ has four "
                            r"entries, and the last row and column carry $d$.", "3x3 block")
        return diagnose_matrix(answer, self.expected, self._mistakes, what=self.what,
                               transform=False)

    def statement(self):
        planes = ", ".join(rf"${_plane_words(n, self.point)}$" for n in self.normals)
        return (
            rf"Three faces meet at the vertex $v = {_vec(self.point)}$; they lie in the planes "
            + planes + r". Compute the vertex's quadric "
            r"$Q = \sum_p K_p = \sum_p p\,p^T$ with each plane written as "
            r"$p = (a, b, c, d)$, $ax + by + cz + d = 0$, $a^2 + b^2 + c^2 = 1$." "\n\n"
            r"**Answer:** the $4 \times 4$ matrix $Q$ (a nested list or numpy array). "
            + DECIMALS + "\n\n" + data_note("point", "normals") + " (`.normals` are the "
            "whole-number normals of the equations above, not normalised.)")


def _matrix_latex(Q):
    return fmt.matrix_latex(np.round(Q, 10) + 0.0)


class _TwoVertices(DrawnExercise):
    """An edge (v1, v2), each end with two planes through it; the quadrics Q1, Q2."""

    def _draw_edge(self, rng):
        self.v1 = rng.integers(-2, 3, size=3).astype(float)
        self.v2 = self.v1 + rng.integers(-2, 3, size=3).astype(float)
        self.normals1 = _draw_planes(rng, self.v1, 2)
        self.normals2 = _draw_planes(rng, self.v2, 2)
        self.planes = np.array([_unit_plane(n, self.v1) for n in self.normals1]
                               + [_unit_plane(n, self.v2) for n in self.normals2])
        self.Q1 = _quadric(self.planes[:2])
        self.Q2 = _quadric(self.planes[2:])

    def _edge_words(self):
        return (rf"The edge from $v_1 = {_vec(self.v1)}$ to $v_2 = {_vec(self.v2)}$ is a "
                r"candidate for collapse. The vertex quadrics are" "\n\n"
                rf"$$Q_1 = {_matrix_latex(self.Q1)}, \qquad Q_2 = {_matrix_latex(self.Q2)}$$"
                "\n\n" r"(each the sum of $p\,p^T$ over two planes through its vertex).")


def _cost(Q, x):
    h = np.append(np.asarray(x, dtype=float), 1.0)
    return float(h @ Q @ h)


class CollapseCost(_TwoVertices):
    r"""The quadric error of collapsing an edge to its midpoint: :math:`\bar v^T (Q_1 + Q_2) \bar v`.

    Attributes: ``v1``, ``v2``, ``Q1``, ``Q2``.

    Examples
    --------
    >>> ex = CollapseCost(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> mid = (ex.v1 + ex.v2) / 2
    >>> ex.check(mid @ (ex.Q1 + ex.Q2)[:3, :3] @ mid).diagnosis       # w = 0
    'no homogeneous 1'
    """

    title = "The cost of an edge collapse"
    answer_form = "number"
    what = "the cost"
    hint = (r"Add the quadrics, $\bar Q = Q_1 + Q_2$, write the midpoint with a 1 appended, "
            r"$\bar v = (x, y, z, 1)$, and compute $\bar v^T \bar Q \bar v$.")

    def draw(self, rng):
        self._draw_edge(rng)
        self.mid = (self.v1 + self.v2) / 2
        self.expected = _cost(self.Q1 + self.Q2, self.mid)

    def acceptable(self):
        return np.abs(self.v2 - self.v1).sum() >= 2 and self.expected > 0.4

    def mistakes(self):
        Q, mid = self.Q1 + self.Q2, self.mid
        return [
            Mistake(float(mid @ Q[:3, :3] @ mid), r"You left out the homogeneous coordinate: "
                    r"$\bar v = (x, y, z, \mathbf{1})$. Without the 1 the $d$ terms of the "
                    r"planes (the last row and column of $Q$) drop out, as if every plane went "
                    r"through the origin.", "no homogeneous 1"),
            Mistake(_cost(self.Q1, mid), r"You used $Q_1$ only. The merged vertex must stay "
                    r"close to the planes of **both** end points: $\bar Q = Q_1 + Q_2$.",
                    "one quadric"),
            Mistake(_cost(self.Q2, mid), r"You used $Q_2$ only. The merged vertex must stay "
                    r"close to the planes of **both** end points: $\bar Q = Q_1 + Q_2$.",
                    "one quadric"),
            Mistake(_cost(Q, mid) / 2, r"You averaged the quadrics. Garland and Heckbert add "
                    r"them, $\bar Q = Q_1 + Q_2$: the cost is the *sum* of the squared "
                    r"distances to all the planes.", "averaged"),
            Mistake(math.sqrt(_cost(Q, mid)), r"That is the square root. The quadric error "
                    r"$\bar v^T \bar Q \bar v$ is a sum of **squared** distances; leave it "
                    r"squared.", "square root"),
        ]

    def statement(self):
        return (
            self._edge_words() + "\n\n"
            r"Compute the cost $\bar v^T (Q_1 + Q_2)\, \bar v$ of collapsing the edge to its "
            r"midpoint $\bar v$ (in homogeneous coordinates)." "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("v1", "v2", "Q1", "Q2"))


class OptimalPosition(_TwoVertices):
    r"""The position that minimizes the quadric error of a collapse, and its cost.

    With :math:`\bar Q = Q_1 + Q_2 = \begin{pmatrix} A & b \\ b^T & c \end{pmatrix}` the
    gradient vanishes where :math:`A \bar v = -b`; the cost there is :math:`c + b^T \bar v`.

    Attributes: ``v1``, ``v2``, ``Q1``, ``Q2``.

    Examples
    --------
    >>> ex = OptimalPosition(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> Q = ex.Q1 + ex.Q2
    >>> x = np.linalg.solve(Q[:3, :3], Q[:3, 3])                      # A v = +b
    >>> h = np.append(x, 1)
    >>> ex.check([*x, h @ Q @ h]).diagnosis
    'sign of b'
    """

    title = "The optimal position of the merged vertex"
    answer_form = "custom"
    hint = (r"Split $\bar Q = Q_1 + Q_2$ into the $3 \times 3$ block $A$, the column $b$ "
            r"(first three entries of the last column) and the corner $c$; solve "
            r"$A\,\bar v = -b$; the cost is $(\bar v, 1)^T \bar Q\, (\bar v, 1)$.")

    def draw(self, rng):
        self._draw_edge(rng)
        Q = self.Q1 + self.Q2
        A = Q[:3, :3]
        if abs(np.linalg.det(A)) < 0.2:
            self.expected = None
            return
        x = np.linalg.solve(A, -Q[:3, 3])
        self.expected = np.array([*x, _cost(Q, x)])

    def acceptable(self):
        if self.expected is None:
            return False
        x, cost = self.expected[:3], self.expected[3]
        # bounds up to rounding (SAME): a cost of exactly 0.1 must not pass or fail by the last
        # bit, which depends on the CPU's LAPACK/BLAS kernels
        return (cost > 0.1 - SAME and np.abs(x).max() <= 6 + SAME
                and not close(x, self.v1) and not close(x, self.v2))

    def _parts(self):
        Q = self.Q1 + self.Q2
        x = self.expected[:3]
        wrong_sign = np.linalg.solve(Q[:3, :3], Q[:3, 3])
        mid = (self.v1 + self.v2) / 2
        sign = (r"The sign is wrong: setting the gradient of $\bar v^T \bar Q \bar v$ to zero "
                r"gives $2(A\bar v + b) = 0$, so $A\,\bar v = -b$.")
        midpoint = (r"That is the midpoint of the edge, the fallback for a singular $A$. Here "
                    r"$A$ is invertible, and the best position solves $A\,\bar v = -b$; it "
                    r"need not lie on the edge.")
        parts = []
        for k, name in enumerate(("x", "y", "z")):
            parts.append((f"{name} of the position", float(x[k]),
                          [Mistake(wrong_sign[k], sign, "sign of b"),
                           Mistake(mid[k], midpoint, "midpoint")]))
        parts.append(("the cost", float(self.expected[3]),
                      [Mistake(_cost(Q, wrong_sign), sign, "sign of b"),
                       Mistake(_cost(Q, mid), midpoint, "midpoint"),
                       Mistake(float(x @ Q[:3, :3] @ x), r"The cost needs the homogeneous 1: "
                               r"$(\bar v, 1)^T \bar Q\, (\bar v, 1) = \bar v^T A \bar v + "
                               r"2 b^T \bar v + c$; without it the plane offsets drop out.",
                               "no homogeneous 1")]))
        return parts

    def separated(self, mistakes):
        parts = self._parts()
        if not parts_separated(parts):
            return False
        # the position's slips must show in at least one coordinate
        for key in ("sign of b", "midpoint"):
            if all(abs(float(m.value) - exp) <= SAME for _, exp, ms in parts[:3]
                   for m in ms if m.key == key):
                return False
        return True

    def mistakes(self):
        return []

    def _judge(self, answer):
        return diagnose_parts(answer, self._parts(), "your answer", "`[x, y, z, cost]`.",
                              self.hint)

    def statement(self):
        return (
            self._edge_words() + "\n\n"
            r"Find the position $\bar v$ that minimizes the error "
            r"$(\bar v, 1)^T (Q_1 + Q_2)\, (\bar v, 1)$ of the merged vertex, and that "
            r"smallest error." "\n\n"
            r"**Answer:** a list of 4 numbers `[x, y, z, cost]`. " + DECIMALS + "\n\n"
            + data_note("v1", "v2", "Q1", "Q2"))


#: The exercises of chapter 6, in the order of the solutions notebook.
EXERCISES = (
    EulerCounts,
    GenusFromCounts,
    EdgeCollapseCounts,
    Manifoldness,
    FlippedFace,
    WingedEdgeRecord,
    HalfEdgeWalk,
    OneRing,
    VertexQuadric,
    CollapseCost,
    OptimalPosition,
)
