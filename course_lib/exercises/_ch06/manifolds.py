"""Chapter 6 exercises: Manifoldness and orientation.

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

from ... import mesh
from ..core import (UNANSWERED, DrawnExercise, Feedback, Worked, data_note, has_placeholder,
                    pick)
from . import _SMALL, _cycle, _face_latex, _faces_words, _read_ints, _small_mesh

__all__ = [
    "MESH_KINDS",
    "FlippedFace",
    "Manifoldness",
]


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


def _fans_by_walk(faces, v):
    """The fans of faces around vertex `v`, found as a student does: start at a face, step to
    every face across an edge at `v`, until no new face is reached; then start a new fan.

    (The worked solutions' own search, independent of the checker's :func:`_fans`.)
    """
    left = [k for k, f in enumerate(faces) if v in f]
    edges = [{frozenset(e) for e in _cycle(f)} for f in faces]
    fans = []
    while left:
        fan = [left.pop(0)]
        todo = list(fan)
        while todo:
            k = todo.pop()
            for edge in edges[k]:
                if v not in edge:
                    continue
                for j in [j for j in left if edge in edges[j]]:
                    left.remove(j)
                    fan.append(j)
                    todo.append(j)
        fans.append(sorted(fan))
    return fans


def _face_set(ks):
    return "{" + ", ".join(f"$f_{{{k}}}$" for k in ks) + "}"


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

    def hints(self):
        table = _edge_faces(self.faces)
        crowded = sorted(e for e, fs in table.items() if len(fs) > 2)
        border = sorted(e for e, fs in table.items() if len(fs) == 1)
        if crowded:
            a, b = crowded[0]
            last = (rf"Look at the edge $({a}, {b})$: count the faces in which ${a}$ and ${b}$ "
                    r"follow each other.")
        else:
            start = ("No edge has more than two faces here" if border else
                     "Every edge has exactly two faces here")
            if border:
                start += (rf", and {len(border)} have only one (e.g. "
                          rf"$({border[0][0]}, {border[0][1]})$)")
            pinched = [v for v in sorted({v for f in self.faces for v in f})
                       if len(_fans_by_walk(self.faces, v)) > 1]
            probe = pinched[0] if pinched else min(v for f in self.faces for v in f)
            around = [k for k, f in enumerate(self.faces) if probe in f]
            last = (start + rf". Now the vertices: vertex ${probe}$, for one, lies on the "
                    rf"faces {_face_set(around)}; can you walk between all of them across "
                    rf"edges at ${probe}$?")
        return [
            r"Two tests decide: how many faces lie on each **edge** (1: a boundary edge, 2: "
            r"fine, 3 or more: non-manifold), and whether the faces around each **vertex** "
            r"form a single fan.",
            r"List every edge as an unordered pair of vertices with the faces it lies on. If "
            r"no edge has 3 faces, go round each vertex: the faces at the vertex that share an "
            r"edge through it belong to the same fan; two or more separate fans pinch the "
            r"surface at that vertex.",
            last,
        ]

    def worked(self):
        table = {}
        for k, f in enumerate(self.faces):
            for a, b in _cycle(f):
                table.setdefault((min(a, b), max(a, b)), []).append(k)
        crowded = {e: fs for e, fs in sorted(table.items()) if len(fs) > 2}
        border = sorted(e for e, fs in table.items() if len(fs) == 1)
        two = sum(len(fs) == 2 for fs in table.values())
        listing = "; ".join(rf"$({a}, {b})$: " + ", ".join(f"$f_{{{k}}}$" for k in fs)
                            for (a, b), fs in sorted(table.items()))
        edges = rf"Of the {len(table)} edges, {two} lie on two faces"
        if border:
            edges += rf", {len(border)} on only one face (the boundary: {_pairs_words(border)})"
        for (a, b), fs in crowded.items():
            edges += rf", and $({a}, {b})$ lies on {len(fs)} faces"
        steps = [rf"Each edge with the faces it lies on: {listing}.", edges + "."]
        if crowded:
            kind = "non-manifold edge"
            steps.append(r"An edge with three or more faces is already non-manifold (like "
                         r"pages on the spine of a book); the vertices need not be checked.")
        else:
            pinched = {}
            for v in sorted({v for f in self.faces for v in f}):
                fans = _fans_by_walk(self.faces, v)
                if len(fans) > 1:
                    pinched[v] = fans
            if pinched:
                kind = "non-manifold vertex"
                v, fans = next(iter(pinched.items()))
                steps.append(rf"Around vertex ${v}$ the faces form {len(fans)} fans, "
                             + " and ".join(_face_set(fan) for fan in fans) + rf", that "
                             rf"share no edge at ${v}$: they touch only at that vertex, so "
                             r"the surface is pinched there.")
            else:
                kind = "manifold with boundary" if border else "closed manifold"
                steps.append(r"Around every vertex the faces form a single fan (walking "
                             r"across the edges at the vertex reaches all of its faces)"
                             + (", open at the boundary vertices." if border else "."))
        steps.append(rf"So the face list is a **{kind}**: {MESH_KINDS[kind]}.")
        return Worked(steps, kind)

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
        self.expected = self.flipped
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
                           f"{n - 1}.", 0, n - 1, noun="face")
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

    def _twice(self):
        """{(a, b): [faces]} for the directed edges that two faces list in the same direction."""
        directed = {}
        for k, f in enumerate(self.faces):
            for a, b in _cycle(f):
                directed.setdefault((a, b), []).append(k)
        return {e: ks for e, ks in sorted(directed.items()) if len(ks) > 1}

    def hints(self):
        twice = self._twice()
        shown = ", ".join(rf"$({a} \to {b})$" for a, b in twice)
        return [
            r"With a consistent winding, two faces that share an edge run along it in "
            r"**opposite** directions: if one face lists $(a, b)$ in that order, the face "
            r"across the edge lists $(b, a)$.",
            r"Write down the directed edges of every face (consecutive vertices, and the last "
            r"back to the first). A directed edge that occurs in two faces marks a clash "
            r"between them. One flipped face clashes with **every** one of its neighbours.",
            rf"The directed edges that occur twice are {shown}. Which face takes part in all "
            r"of these clashes?",
        ]

    def worked(self):
        twice = self._twice()
        common = set(range(len(self.faces)))
        for ks in twice.values():
            common &= set(ks)
        k = min(common)
        others = sorted({j for ks in twice.values() for j in ks} - {k})
        listed = "; ".join(rf"$({a} \to {b})$ in " + " and ".join(f"$f_{{{j}}}$" for j in ks)
                           for (a, b), ks in twice.items())
        return Worked([
            r"List the directed edges of each face. On a consistently wound mesh every "
            r"directed edge occurs once: the face across it lists it the other way round.",
            rf"These directed edges occur twice: {listed}.",
            rf"{_face_latex(k, self.faces[k])} is in every clash: all its "
            rf"{len(self.faces[k])} edges run the same way as in the neighbour across them, "
            r"while each of its neighbours ("
            + ", ".join(f"$f_{{{j}}}$" for j in others) + r") clashes with it only. "
            rf"Reversing $f_{{{k}}}$ removes every clash, so $f_{{{k}}}$ is the flipped face.",
        ], k)

    def statement(self):
        return (
            rf"The faces of a closed mesh (a {self.shape}) are {_faces_words(self.faces)}. "
            r"All but one of them list their vertices counter-clockwise seen from outside; "
            r"one face lists them the other way round. Which one?" "\n\n"
            r"**Answer:** the index $k$ of the flipped face $f_k$, one whole number." "\n\n"
            + data_note("faces"))
