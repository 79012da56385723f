"""Chapter 6 exercises: level of detail (screen-space error, progressive-mesh records).

Part of :mod:`course_lib.exercises.ch06`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import format as fmt
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _Parts

__all__ = [
    "LODChoice",
    "SplitRecord",
]

_num = fmt.number

#: Geometric errors of the levels (object units), finest first, before a common factor.
_ERROR_PATTERNS = ((0, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1),
                   (0, 0.001, 0.003, 0.008, 0.02, 0.04, 0.1),
                   (0, 0.004, 0.01, 0.025, 0.06, 0.15),
                   (0, 0.002, 0.006, 0.012, 0.03, 0.08, 0.2))


def _lod_coarsest(errors, limit):
    """The largest index i with errors[i] <= limit (errors non-decreasing, errors[0] = 0)."""
    return int(np.flatnonzero(np.asarray(errors) <= limit * (1 + 1e-12))[-1])


class LODChoice(DrawnExercise):
    r"""Choose a discrete level of detail from the screen-space error.

    Level :math:`i` has geometric error :math:`\varepsilon_i`; seen at distance :math:`d`
    through a perspective camera of vertical field of view :math:`\theta` on a viewport
    :math:`H` pixels high it covers :math:`\varepsilon_i H / (2 d \tan(\theta/2))` pixels. The
    answer is the coarsest level within the tolerance :math:`\tau`, equivalently the coarsest
    with :math:`\varepsilon_i \le 2 d \tau \tan(\theta/2) / H`.

    Attributes: ``errors``, ``faces`` (per level, finest first), ``distance``, ``fov_deg``,
    ``height``, ``tolerance``.

    Examples
    --------
    >>> ex = LODChoice(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(0).diagnosis
    'finest instead of coarsest'
    """

    title = "Choose the level of detail"
    answer_form = "number"
    what = "the level"
    advice = (r"Turn the pixel tolerance into an object-space one, "
              r"$\varepsilon_{max} = 2 d \tau \tan(\theta/2)/H$, and take the coarsest level "
              r"(largest index) with $\varepsilon_i \le \varepsilon_{max}$.")

    def draw(self, rng):
        pattern = np.array(pick(rng, _ERROR_PATTERNS))
        self.errors = pattern * float(pick(rng, (1, 2, 5)))
        top = int(pick(rng, (20000, 32000, 50000)))
        self.faces = [top // 2 ** i for i in range(len(self.errors))]
        self.fov_deg = float(pick(rng, (40, 50, 60, 70, 80)))
        self.height = int(pick(rng, (600, 720, 800, 900, 1000, 1080, 1200)))
        self.tolerance = float(pick(rng, (0.5, 1.0, 1.0, 2.0)))
        self.distance = float(pick(rng, np.arange(5, 105, 5)))
        self.expected = _lod_coarsest(self.errors, self._limit(2, math.tan(self._half())))

    def _half(self):
        return math.radians(self.fov_deg) / 2

    def _limit(self, factor, tangent):
        """The largest acceptable geometric error, eps H / (factor d tan) <= tau solved."""
        return factor * self.distance * self.tolerance * tangent / self.height

    def acceptable(self):
        e = self.errors[1:]
        limits = [self._limit(2, math.tan(self._half())), self._limit(2, math.tan(2 * self._half())),
                  self._limit(1, math.tan(self._half()))]
        ratios = np.concatenate([e / lim for lim in limits])
        return bool(1 <= self.expected <= len(self.errors) - 2
                    and np.abs(ratios - 1).min() > 0.06)

    def mistakes(self):
        found = [
            Mistake(_lod_coarsest(self.errors, self._limit(2, math.tan(2 * self._half()))),
                    r"You used $\tan\theta$ of the whole field of view. The view volume's "
                    r"half-height at distance $d$ is $d\tan(\theta/2)$, and it covers **half** "
                    r"the viewport, $H/2$ pixels: the half-angle goes with the half-height.",
                    "tan of the full angle"),
            Mistake(_lod_coarsest(self.errors, self._limit(1, math.tan(self._half()))),
                    r"You mapped the half-height $d\tan(\theta/2)$ onto the full viewport "
                    r"height $H$. It covers only half of it, $H/2$ pixels: "
                    r"$\varepsilon_{screen} = \varepsilon\,(H/2)/(d\tan(\theta/2))$.",
                    "full viewport"),
            Mistake(0, r"Level 0 (the original) always passes, but it is the most expensive. "
                    r"LOD picks the **coarsest** level (fewest faces) whose screen-space error "
                    r"is still within the tolerance.", "finest instead of coarsest"),
        ]
        if self.expected + 1 < len(self.errors):
            found.append(Mistake(self.expected + 1, r"That level is one too coarse: its "
                                 r"screen-space error is above the tolerance (check "
                                 r"$\varepsilon_i \le \varepsilon_{max}$, not the other way "
                                 r"round).", "first level above the tolerance"))
        return found

    def statement(self):
        rows = "\n".join(f"| {i} | {n} | {_num(e, 4)} |"
                         for i, (n, e) in enumerate(zip(self.faces, self.errors)))
        return (
            r"A model has these discrete levels of detail (level 0 the original), each with "
            r"its geometric error $\varepsilon$ in metres:" "\n\n"
            "| level | faces | $\\varepsilon$ (m) |\n|---|---|---|\n" + rows + "\n\n"
            rf"It is seen at distance $d = {_num(self.distance)}$ m by a perspective camera "
            rf"with vertical field of view $\theta = {_num(self.fov_deg)}°$, on a viewport "
            rf"$H = {self.height}$ pixels high. The renderer accepts a screen-space error of "
            rf"$\tau = {_num(self.tolerance)}$ pixel(s). Which level does it draw?" "\n\n"
            r"**Answer:** one number, the level's index." "\n\n"
            + data_note("errors", "faces", "distance", "fov_deg", "height", "tolerance"))

    def hints(self):
        t = math.tan(self._half())
        return [r"A length $\varepsilon$ at distance $d$ covers "
                r"$\varepsilon\,(H/2)/(d\tan(\theta/2))$ pixels: the half-height of the view "
                r"volume, $d\tan(\theta/2)$, fills half the viewport.",
                rf"Here $\tan({_num(self.fov_deg / 2)}°) = {_num(t, 4)}$; solve "
                r"$\varepsilon_{screen} \le \tau$ for $\varepsilon$.",
                r"Among the levels with $\varepsilon_i \le \varepsilon_{max}$ take the one with "
                r"the largest index (fewest faces)."]

    def worked(self):
        t = math.tan(self._half())
        limit = self._limit(2, t)
        k = self.expected
        px = [e * self.height / (2 * self.distance * t) for e in self.errors]
        return Worked([
            rf"$\tan(\theta/2) = \tan({_num(self.fov_deg / 2)}°) = {_num(t, 4)}$.",
            rf"Largest acceptable error: $\varepsilon_{{max}} = 2 d \tau \tan(\theta/2)/H = "
            rf"2 \cdot {_num(self.distance)} \cdot {_num(self.tolerance)} \cdot {_num(t, 4)}"
            rf"/{self.height} = {_num(limit, 5)}$ m.",
            rf"Level {k}: $\varepsilon = {_num(self.errors[k], 4)} \le {_num(limit, 5)}$, "
            rf"{_num(px[k], 2)} px; level {k + 1}: $\varepsilon = "
            rf"{_num(self.errors[k + 1], 4)} > {_num(limit, 5)}$, {_num(px[k + 1], 2)} px.",
            rf"The coarsest acceptable level is {k} ({self.faces[k]} faces).",
        ], k)


class SplitRecord(_Parts):
    r"""Read a progressive mesh: the collapse record backwards as vertex splits.

    A simplification made collapses 1..K (collapse k merged vertex ``removed`` into ``kept``
    and deleted 2 faces, or 1 for an edge on the boundary). The progressive mesh is the base
    mesh (after all K collapses) and the vertex splits in reverse order: split j undoes
    collapse :math:`K - j + 1`, restoring its removed vertex and its faces.

    Attributes: ``kept``, ``removed``, ``faces_removed`` (per collapse, in order), ``V0``,
    ``F0`` (the base mesh), ``j`` (the number of splits applied).

    Examples
    --------
    >>> ex = SplitRecord(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> v, V, F = ex.expected
    >>> ex.check([ex.removed[ex.j - 1], V, F]).diagnosis
    'record read forwards'
    """

    title = "Read a progressive mesh"
    form_hint = "`[vertex, V, F]`, three whole numbers."
    advice = (r"Split 1 undoes the **last** collapse, split 2 the one before, and so on: split "
              r"$j$ undoes collapse $K - j + 1$. Each split adds back 1 vertex and the faces "
              r"that collapse removed.")

    def draw(self, rng):
        K = int(rng.integers(6, 9))
        n = int(rng.integers(30, 80))
        order = rng.permutation(n)
        self.removed = [int(x) for x in order[:K]]
        alive = [int(x) for x in order[K:]]
        # a kept vertex is alive at its collapse: not removed earlier (later ones are alive)
        self.kept = []
        for k in range(K):
            pool = alive + self.removed[k + 1:]
            self.kept.append(int(pool[int(rng.integers(len(pool)))]))
        self.faces_removed = [int(pick(rng, (2, 2, 1))) for _ in range(K)]
        self.V0 = n - K
        self.F0 = 2 * self.V0 - int(rng.integers(8, 15))
        self.j = int(rng.integers(2, K - 1))
        self.expected = np.array(self._answer(), dtype=float)

    def _last(self):
        """The collapses undone by the first j splits, in the order they are undone."""
        K = len(self.removed)
        return list(range(K - 1, K - 1 - self.j, -1))

    def _answer(self):
        undone = self._last()
        return (self.removed[undone[-1]], self.V0 + self.j,
                self.F0 + sum(self.faces_removed[k] for k in undone))

    def acceptable(self):
        undone = self._last()
        return 1 in [self.faces_removed[k] for k in undone]

    def _parts(self):
        undone = self._last()
        last = undone[-1]
        added = sum(self.faces_removed[k] for k in undone)
        forward = sum(self.faces_removed[:self.j])
        return [
            ("the vertex restored", self.removed[last],
             [Mistake(self.removed[self.j - 1], r"You read the record forwards. A progressive "
                      r"mesh starts from the **coarsest** mesh, so its first split undoes the "
                      r"**last** collapse: split $j$ undoes collapse $K - j + 1$.",
                      "record read forwards"),
              Mistake(self.kept[last], r"That is the vertex that splits (the collapse's kept "
                      r"vertex, which stays in the mesh). The split restores the other end "
                      r"point, the vertex the collapse removed.", "kept instead of removed")]),
            ("the number of vertices V", self.V0 + self.j,
             [Mistake(self.V0 - self.j, r"A vertex split adds a vertex (it undoes a collapse, "
                      r"which removed one): $V = V_0 + j$.", "vertices subtracted"),
              Mistake(self.V0 + 2 * self.j, r"A split turns one vertex into two: one vertex "
                      r"more per split, not two.", "two vertices per split")]),
            ("the number of faces F", self.F0 + added,
             [Mistake(self.F0 + 2 * self.j, r"Not every split adds two faces: a collapse on "
                      r"the boundary removed only one (a boundary edge has one face), so its "
                      r"split adds back one. Use the record's face column.",
                      "two faces per split"),
              Mistake(self.F0 + forward, r"You added the faces of the first collapses. The "
                      r"first splits undo the **last** collapses: add the faces of collapses "
                      r"$K, K-1, \dots, K-j+1$.", "faces read forwards"),
              Mistake(self.F0 - added, r"A split adds faces back (it undoes a collapse, which "
                      r"removed them).", "faces subtracted")]),
        ]

    def statement(self):
        rows = "\n".join(f"| {k + 1} | {a} | {b} | {c} |" for k, (a, b, c) in
                         enumerate(zip(self.kept, self.removed, self.faces_removed)))
        K = len(self.removed)
        return (
            rf"An edge-collapse simplification made these {K} collapses, in this order "
            r"(collapse $k$ merged vertex *removed* into vertex *kept*):" "\n\n"
            "| collapse | kept | removed | faces removed |\n|---|---|---|---|\n" + rows + "\n\n"
            rf"The final mesh, the base mesh of a progressive mesh, has $V_0 = {self.V0}$ "
            rf"vertices and $F_0 = {self.F0}$ faces. The progressive mesh applies the vertex "
            rf"splits to it one by one. After the first {self.j} splits: which vertex did split "
            rf"number {self.j} restore, and how many vertices $V$ and faces $F$ does the mesh "
            r"have?" "\n\n" r"**Answer:** a list of 3 whole numbers `[vertex, V, F]`." "\n\n"
            + data_note("kept", "removed", "faces_removed", "V0", "F0", "j"))

    def hints(self):
        K = len(self.removed)
        return [r"The progressive mesh starts from the coarsest mesh: the record is read "
                r"backwards, each vertex split undoing one collapse.",
                rf"Split 1 undoes collapse {K}, split 2 collapse {K - 1}, ...: split {self.j} "
                rf"undoes collapse {K - self.j + 1}.",
                r"Each split adds 1 vertex and as many faces as its collapse removed."]

    def worked(self):
        K = len(self.removed)
        undone = self._last()
        vertex, V, F = self._answer()
        adds = " + ".join(str(self.faces_removed[k]) for k in undone)
        return Worked([
            rf"The splits undo the collapses backwards: splits 1..{self.j} undo collapses "
            + ", ".join(str(k + 1) for k in undone) + ".",
            rf"Split {self.j} undoes collapse {K - self.j + 1}, which merged vertex "
            rf"{self.removed[undone[-1]]} into {self.kept[undone[-1]]}: it restores vertex "
            rf"{vertex}.",
            rf"Vertices: $V = {self.V0} + {self.j} = {V}$ (one per split).",
            rf"Faces: $F = {self.F0} + ({adds}) = {F}$ (a boundary collapse removed one face).",
        ], [vertex, V, F])

