"""Chapter 5 exercises: Ray casting.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import numpy as np

from ..core import (DrawnExercise, Mistake, Worked, data_note, diagnose_parts, parts_separated,
                    pick)

__all__ = [
    "RayCastingCount",
]


class RayCastingCount(DrawnExercise):
    r"""Counting intersection tests in ray casting, with and without bounding spheres.

    Brute force tests every ray against every triangle: :math:`p \cdot \sum P_i`. With one
    bounding sphere per object, every ray is tested against every sphere (:math:`p \cdot m`)
    and only the :math:`k_i` rays that hit sphere :math:`i` against its :math:`P_i` triangles.
    The three counts are whole numbers, compared exactly (one test short is off by one).

    Attributes: ``width``, ``height``, ``triangles`` (:math:`P_i`), ``hits`` (:math:`k_i`).

    Examples
    --------
    >>> ex = RayCastingCount(seed=15)
    >>> ex.check(ex.expected).status
    'correct'
    >>> brute, with_bv, spheres = ex.expected
    >>> ex.check([brute, with_bv, len(ex.triangles)]).diagnosis
    'one test per object'
    """

    title = "The cost of ray casting"
    answer_form = "custom"

    def draw(self, rng):
        self.width, self.height = (int(v) for v in pick(rng, ((200, 100), (320, 240),
                                                              (100, 100), (400, 300))))
        m = int(pick(rng, (2, 3)))
        self.triangles = [int(pick(rng, (200, 500, 1000, 2000))) for _ in range(m)]
        pixels = self.width * self.height
        self.hits = [int(rng.integers(3, 31)) * pixels // 100 for _ in range(m)]
        self.expected = np.array([pixels * sum(self.triangles),
                                  sum(k * t for k, t in zip(self.hits, self.triangles)),
                                  pixels * m])

    def _parts(self):
        brute, with_bv, spheres = (int(v) for v in self.expected)
        pixels = self.width * self.height
        return [
            ("the tests without bounding volumes", brute, [
                Mistake(pixels + sum(self.triangles), r"Every ray is tested against every "
                        r"triangle: that is $p \cdot P$ tests (a product), not $p + P$.",
                        "added instead of multiplied")]),
            ("the ray-triangle tests with bounding spheres", with_bv, [
                Mistake(sum(self.hits) * sum(self.triangles), r"A ray that hits one sphere "
                        r"is tested only against the triangles **inside that sphere**: "
                        r"$\sum_i k_i P_i$, not $(\sum_i k_i)(\sum_i P_i)$.",
                        "all triangles per hit ray")]),
            ("the ray-sphere tests", spheres, [
                Mistake(len(self.triangles), r"Each sphere is tested by **every** ray (the "
                        r"test is what decides whether the ray can skip the object), so "
                        r"there are $p \cdot m$ ray-sphere tests, not $m$.",
                        "one test per object")]),
        ]

    def mistakes(self):
        brute, with_bv, spheres = self.expected
        pixels = self.width * self.height
        return [Mistake([pixels + sum(self.triangles), with_bv, spheres], "",
                        "added instead of multiplied"),
                Mistake([brute, sum(self.hits) * sum(self.triangles), spheres], "",
                        "all triangles per hit ray"),
                Mistake([brute, with_bv, len(self.triangles)], "", "one test per object")]

    def separated(self, mistakes):
        return parts_separated(self._parts(), same=None)

    def _check(self, answer):
        return diagnose_parts(answer, self._parts(), "your counts",
                              "`[without_bv, ray_triangle_with_bv, ray_sphere]`.",
                              r"Count tests per ray and multiply by the number of rays "
                              r"$p = w \cdot h$.")

    def hints(self):
        p, m = self.width * self.height, len(self.triangles)
        terms = " + ".join(rf"{k} \cdot {t}" for k, t in zip(self.hits, self.triangles))
        return [
            r"Count the tests one ray makes, then multiply by the number of rays: one per "
            r"pixel, $p = w \cdot h$.",
            r"Brute force tests every ray against every triangle: $p \sum_i P_i$. With "
            r"bounding spheres every ray is tested against each of the $m$ spheres "
            r"($p \cdot m$ ray-sphere tests), and only the $k_i$ rays that hit sphere $i$ are "
            r"tested against its $P_i$ triangles: $\sum_i k_i P_i$.",
            rf"Here $p = {self.width} \cdot {self.height} = {p}$, "
            rf"$\sum_i P_i = {sum(self.triangles)}$, $m = {m}$, and "
            rf"$\sum_i k_i P_i = {terms}$.",
        ]

    def worked(self):
        p = self.width * self.height
        total = sum(self.triangles)
        brute = p * total
        products = [k * t for k, t in zip(self.hits, self.triangles)]
        with_bv = sum(products)
        spheres = p * len(self.triangles)
        return Worked([
            rf"One ray per pixel: $p = {self.width} \cdot {self.height} = {p}$ rays.",
            rf"(a) Brute force: every ray against all "
            rf"$\sum_i P_i = {' + '.join(str(t) for t in self.triangles)} = {total}$ "
            rf"triangles: ${p} \cdot {total} = {brute}$ tests.",
            r"(b) With bounding spheres, object $i$'s triangles are tested only by the "
            r"$k_i$ rays that hit its sphere: $\sum_i k_i P_i = "
            + " + ".join(rf"{k} \cdot {t}" for k, t in zip(self.hits, self.triangles))
            + " = " + " + ".join(str(v) for v in products) + rf" = {with_bv}$.",
            rf"(c) Every ray is tested against each of the {len(self.triangles)} spheres: "
            rf"${p} \cdot {len(self.triangles)} = {spheres}$ ray-sphere tests.",
        ], [brute, with_bv, spheres])

    def statement(self):
        rows = "\n".join(f"| {i} | {t} | {k} |"
                         for i, (t, k) in enumerate(zip(self.triangles, self.hits)))
        pixels = self.width * self.height
        return (
            rf"An image of ${self.width} \times {self.height}$ pixels is rendered by ray "
            r"casting, one ray per pixel. The scene has the objects below, made of triangles; "
            r"each object is wrapped in a bounding sphere, and the last column says how many "
            r"of the rays hit that sphere." "\n\n"
            "| object | triangles $P_i$ | rays hitting its sphere $k_i$ |\n|---|---|---|\n"
            + rows + "\n\n"
            r"(a) How many ray-triangle tests does brute-force ray casting make (every ray "
            r"against every triangle)? (b) With the bounding spheres, how many ray-triangle "
            r"tests are made? (c) And how many ray-sphere tests?" "\n\n"
            rf"**Answer:** a list of 3 whole numbers `[a, b, c]` (there are $p = {pixels}$ "
            r"rays)." "\n\n" + data_note("width", "height", "triangles", "hits"))
