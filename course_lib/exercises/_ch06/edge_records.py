"""Chapter 6 exercises: Winged edge and half edge.

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

import numpy as np

from ... import mesh
from ..core import UNANSWERED, Feedback, Mistake, Worked, data_note, has_placeholder, pick
from . import _face_latex, _faces_words, _Parts, _Record, _small_mesh

__all__ = [
    "HalfEdgeWalk",
    "OneRing",
    "WingedEdgeRecord",
]


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
    noun = "face or edge"
    form_hint = ("Give 6 whole numbers `[left_face, right_face, left_prev, left_next, "
                 "right_prev, right_next]`, or a dict with those keys.")
    advice = (r"Find the face that lists start then end (the left face) and the one that lists "
            r"end then start (the right face). Around each face, counter-clockwise, the "
            r"*prev* wing is the edge just before $e$ and the *next* wing the edge just after.")

    def draw(self, rng):
        self.shape, vertices, self.faces = _small_mesh(rng, ("tetrahedron", "square pyramid",
                                                             "triangular prism",
                                                             "octahedron"))
        w = mesh.WingedEdgeMesh.from_faces(vertices, self.faces)
        self.edges = [tuple(int(x) for x in row) for row in w.edges()]
        self.e = int(rng.integers(len(self.edges)))
        self.low, self.high = 0, len(self.edges) - 1
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

    def _around(self, u, w):
        """The face that walks u -> w, and the vertices just before u and just after w in it."""
        for k, f in enumerate(self.faces):
            n = len(f)
            for i in range(n):
                if f[i] == u and f[(i + 1) % n] == w:
                    return k, f[i - 1], f[(i + 2) % n]
        raise ValueError(f"no face walks {u} -> {w}")

    def hints(self):
        a, b = self.edges[self.e]
        lf, _, _ = self._around(a, b)
        rf, _, _ = self._around(b, a)
        return [
            r"The **left** face of an edge walks it from start to end (it lists the start "
            r"vertex, then the end vertex); the **right** face walks it from end to start. "
            r"*prev* and *next* are the edges just before and just after the edge on each "
            r"face's counter-clockwise walk.",
            rf"Find the face in which ${a}$ is followed by ${b}$ (cyclically) and the one in "
            rf"which ${b}$ is followed by ${a}$. In each, read the vertex before and the vertex "
            r"after the edge, and look the two neighbouring edges up in the edge list (their "
            r"direction there does not matter).",
            rf"The left face is {_face_latex(lf, self.faces[lf])} (it lists ${a}, {b}$) and "
            rf"the right face {_face_latex(rf, self.faces[rf])} (it lists ${b}, {a}$).",
        ]

    def worked(self):
        a, b = self.edges[self.e]
        index = {frozenset(pair): k for k, pair in enumerate(self.edges)}
        lf, x, y = self._around(a, b)
        rf, u, w = self._around(b, a)
        lp, ln = index[frozenset((x, a))], index[frozenset((b, y))]
        rp, rn = index[frozenset((u, b))], index[frozenset((a, w))]
        return Worked([
            rf"$e_{{{self.e}}}$ runs from ${a}$ to ${b}$. The face that lists ${a}$ then ${b}$ "
            rf"is its left face, {_face_latex(lf, self.faces[lf])}; the face that lists "
            rf"${b}$ then ${a}$ is its right face, {_face_latex(rf, self.faces[rf])}.",
            rf"Around $f_{{{lf}}}$: ${x} \to {a} \to {b} \to {y}$. Before the edge comes "
            rf"$\{{{x}, {a}\}} = e_{{{lp}}}$ (left prev), after it "
            rf"$\{{{b}, {y}\}} = e_{{{ln}}}$ (left next).",
            rf"Around $f_{{{rf}}}$, which walks the edge from ${b}$ to ${a}$: "
            rf"${u} \to {b} \to {a} \to {w}$. Before it comes $\{{{u}, {b}\}} = e_{{{rp}}}$ "
            rf"(right prev), after it $\{{{a}, {w}\}} = e_{{{rn}}}$ (right next).",
        ], [lf, rf, lp, ln, rp, rn])

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
    advice = (r"Work from the inside out: apply the innermost function to $h$ first, read the "
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
        self.expected = np.array([g, int(self.table.target[g])])

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
            ("the half-edge g", g,
             [Mistake(reverse, inside_out, "inside out"),
              Mistake(swapped, next_prev, "next and prev swapped")]),
            ("its target vertex", int(m.target[g]),
             [Mistake(m.origin[g], r"That is the **origin** of $g$, the vertex it leaves. Its "
                      r"target is where it arrives: the origin of `next(g)` (or of "
                      r"`twin(g)`).", "origin, not target"),
              Mistake(m.target[reverse], inside_out, "inside out"),
              Mistake(m.target[swapped], next_prev, "next and prev swapped")]),
        ]

    def hints(self):
        first = self.ops[0]
        step = int(getattr(self.table, first)[self.h])
        return [
            r"A composition is read from the inside out: in "
            r"$\operatorname{twin}(\operatorname{next}(h))$ you apply `next` first, then "
            r"`twin`.",
            r"Each function is a column of the table: in the row of the current half-edge, "
            r"read the column of the function to apply; that gives the row to go to next. The "
            r"target of a half-edge is the origin of its `next` (or of its `twin`).",
            rf"The innermost function here is `{first}`: "
            rf"$\operatorname{{{first}}}({self.h}) = {step}$. Go on "
            rf"from row {step}.",
        ]

    def worked(self):
        m = self.table
        columns = {"next": m.next, "prev": m.prev, "twin": m.twin}
        h = self.h
        steps = [rf"Read $g = {self.expression()}$ from the inside out: "
                 + ", then ".join(f"`{op}`" for op in self.ops) + "."]
        for op in self.ops:
            after = int(columns[op][h])
            steps.append(rf"Row {h}, column `{op}`: $\operatorname{{{op}}}({h}) = {after}$.")
            h = after
        following = int(m.next[h])
        target = int(m.origin[following])
        steps.append(rf"So $g = {h}$. Its target is the origin of $\operatorname{{next}}({h}) = "
                     rf"{following}$, which is vertex ${target}$.")
        return Worked(steps, [h, target])

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
    noun = "vertex"
    advice = (r"Repeat $h \leftarrow \operatorname{twin}(\operatorname{prev}(h))$ until you are "
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

    def _turns(self):
        """[(h, its target, prev(h), twin(prev(h)))] once around v, from the given h."""
        m, h, rows = self.table, self.h, []
        while True:
            p = int(m.prev[h])
            after = int(m.twin[p])
            rows.append((h, int(m.origin[m.next[h]]), p, after))
            h = after
            if h == self.h:
                return rows

    def hints(self):
        h, target, p, after = self._turns()[0]
        second = self._turns()[1][1]
        return [
            r"The half-edges leaving $v$, taken counter-clockwise, come one after the other "
            r"by $h \leftarrow \operatorname{twin}(\operatorname{prev}(h))$; the target of "
            r"each of them is one neighbour of $v$.",
            r"`prev(h)` is the half-edge that enters $v$ on the face of $h$; its `twin` leaves "
            r"$v$ on the next face counter-clockwise. The target of a half-edge is the origin "
            r"of its `next`. Stop when you are back at the first half-edge.",
            rf"First neighbour: the target of $h = {h}$ is ${target}$. Then "
            rf"$\operatorname{{prev}}({h}) = {p}$ and $\operatorname{{twin}}({p}) = {after}$, "
            rf"whose target ${second}$ is the second neighbour.",
        ]

    def worked(self):
        rows = self._turns()
        steps = [rf"Start with $h = {self.h}$, which leaves $v = {self.v}$; write down the "
                 r"target of each half-edge (the origin of its `next`) and turn with "
                 r"$h \leftarrow \operatorname{twin}(\operatorname{prev}(h))$."]
        for h, target, p, after in rows:
            steps.append(rf"$h = {h}$: target ${target}$; $\operatorname{{prev}}({h}) = {p}$, "
                         rf"$\operatorname{{twin}}({p}) = {after}$"
                         + (" (back at the start)." if after == self.h else "."))
        ring = [target for _, target, _, _ in rows]
        steps.append(r"The neighbours, counter-clockwise from the target of $h$: "
                     + ", ".join(f"${t}$" for t in ring) + ".")
        return Worked(steps, ring)

    def statement(self):
        return (
            rf"The half-edge table of a closed mesh (a {self.shape}, faces "
            rf"{_faces_words(self.faces)}) is:" "\n\n" + _half_edge_table(self.table) + "\n\n"
            rf"Half-edge $h = {self.h}$ leaves vertex $v = {self.v}$. Find the neighbours of "
            rf"$v$ in counter-clockwise order (seen from outside), starting with the target of "
            r"$h$, by repeating $h \leftarrow \operatorname{twin}(\operatorname{prev}(h))$."
            "\n\n" r"**Answer:** the list of the neighbours' vertex indices, in that order."
            "\n\n" + data_note("table", "v", "h"))
