"""Chapter 5 exercises: The z-buffer.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import numpy as np

from ... import format as fmt
from ..core import (UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note, pick,
                    read_floats)
from . import _cross2, _num, _unanswered

__all__ = [
    "ZBufferIds",
    "ZBufferWrites",
]


_GRID = 4


_CENTRES = np.array([[i + 0.5, j + 0.5] for j in range(_GRID) for i in range(_GRID)])


def _barycentric(triangle, points):
    """Barycentric coordinates of `points` (rows x, y) in the 2D triangle: shape (n, 3)."""
    a, b, c = np.asarray(triangle, dtype=float)
    area = _cross2(b - a, c - a)
    l1 = _cross2(c - b, points - b) / area
    l2 = _cross2(a - c, points - c) / area
    return np.stack([l1, l2, 1 - l1 - l2], axis=-1)


def _fragments(triangles):
    """Per triangle, the pixels it covers and the depth there: {(i, j): depth}.

    Pixel (i, j) has its centre at (i + 0.5, j + 0.5); it is covered when the centre is inside
    the triangle; the depth is interpolated linearly with barycentric coordinates.
    """
    result = []
    for tri in triangles:
        tri = np.asarray(tri, dtype=float)
        lam = _barycentric(tri[:, :2], _CENTRES)
        depth = lam @ tri[:, 2]
        result.append({(int(x), int(y)): float(z) for (x, y), z, inside
                       in zip(_CENTRES, depth, np.all(lam >= 0, axis=1)) if inside})
    return result


def _zbuffer(fragments, size=_GRID, keep="nearest"):
    """Draw the fragments in order; returns (ids[j][i], depth[j][i], number of writes)."""
    ids = -np.ones((size, size), dtype=int)
    depth = np.full((size, size), 1.0 if keep == "nearest" else -np.inf)
    writes = 0
    for k, covered in enumerate(fragments):
        for (i, j), z in covered.items():
            if keep == "last" or (keep == "nearest" and z < depth[j, i]) or \
                    (keep == "farthest" and z > depth[j, i]):
                ids[j, i], depth[j, i] = k, z
                writes += 1
    return ids, depth, writes


def _draw_triangle(rng):
    """A triangle (x, y, depth per vertex) covering 3 or more pixel centres, none on an edge."""
    while True:
        xy = rng.integers(-1, _GRID + 2, size=(3, 2)).astype(float)
        if abs(_cross2(xy[1] - xy[0], xy[2] - xy[0])) < 4:
            continue
        lam = _barycentric(xy, _CENTRES)
        if np.any(np.abs(lam) < 1e-9) or np.count_nonzero(np.all(lam >= 0, axis=1)) < 3:
            continue
        depth = rng.integers(1, 10, size=(3, 1)) / 10
        return np.hstack([xy, depth])


def _draw_scene(rng, count):
    """`count` triangles whose coverage and depth comparisons are unambiguous."""
    while True:
        triangles = [_draw_triangle(rng) for _ in range(count)]
        fragments = _fragments(triangles)
        if all(abs(fragments[a][pixel] - fragments[b][pixel]) >= 0.02
               for a in range(count) for b in range(a + 1, count)
               for pixel in set(fragments[a]) & set(fragments[b])):
            return triangles


def _cover_by_hand(triangle):
    """{(i, j): depth} of the pixel centres inside `triangle`, as a student computes them.

    The barycentric coordinates of a centre P are the areas of the triangles P V1 V2, P V2 V0
    (and the rest) over the area of V0 V1 V2, written out as cross products; P is inside when
    all three are >= 0, and its depth is the weighted sum of the vertices' depths. (The worked
    solutions' own computation.)
    """
    (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = (tuple(float(v) for v in row)
                                                 for row in triangle)
    area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
    covered = {}
    for j in range(_GRID):
        for i in range(_GRID):
            x, y = i + 0.5, j + 0.5
            l0 = ((x1 - x) * (y2 - y) - (x2 - x) * (y1 - y)) / area
            l1 = ((x2 - x) * (y0 - y) - (x0 - x) * (y2 - y)) / area
            l2 = 1 - l0 - l1
            if min(l0, l1, l2) >= 0:
                covered[(i, j)] = l0 * z0 + l1 * z1 + l2 * z2
    return covered


def _coverage_words(k, covered):
    return (rf"Triangle {k} covers {len(covered)} pixel centres; the depths there are "
            + ", ".join(rf"$({i}, {j})$: {_num(z)}" for (i, j), z in sorted(covered.items()))
            + ".")


def _overlaps(covers):
    """{pixel: [(triangle, depth)]} for the pixels that two or more triangles cover."""
    table = {}
    for k, covered in enumerate(covers):
        for pixel, z in covered.items():
            table.setdefault(pixel, []).append((k, z))
    return {pixel: here for pixel, here in sorted(table.items()) if len(here) > 1}


def _counts_words(covers):
    first, *rest = [len(c) for c in covers]
    return (f"Triangle 0 covers {first} pixel centres, "
            + ", ".join(f"triangle {k} {n}" for k, n in enumerate(rest, 1)))


def _pixels_words(pixels):
    return ", ".join(f"$({i}, {j})$" for i, j in pixels) or "none"


def _scene_table(triangles):
    rows = []
    for k, tri in enumerate(triangles):
        cells = " | ".join(rf"$({_num(x)}, {_num(y)})$, depth ${_num(z)}$" for x, y, z in tri)
        rows.append(f"| {k} | {cells} |")
    return ("| triangle (drawn in this order) | vertex 1 | vertex 2 | vertex 3 |\n"
            "|---|---|---|---|\n" + "\n".join(rows))


_ZBUFFER_RULES = (
    r"The screen has $4 \times 4$ pixels; pixel $(i, j)$, $i, j \in \{0, 1, 2, 3\}$, has its "
    r"centre at $(i + 0.5, j + 0.5)$, and a triangle covers the pixel when it contains the "
    r"centre. The depth at a pixel is interpolated linearly from the vertices' depths "
    r"(barycentric coordinates at the centre). The z-buffer starts at $1$ everywhere (the far "
    r"plane) and the id buffer at $-1$ (background); a fragment is written when its depth is "
    r"**less** than the stored one (nearer the viewer).")


class ZBufferIds(DrawnExercise):
    r"""The id buffer after drawing a few triangles with a depth test on a 4 x 4 grid.

    Attributes: ``triangles`` (one (3, 3) array per triangle: x, y, depth of each vertex).

    Examples
    --------
    >>> ex = ZBufferIds(seed=11)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(np.flipud(ex.expected)).diagnosis
    'rows upside down'
    """

    title = "The z-buffer on a tiny screen"
    answer_form = "custom"

    def draw(self, rng):
        self.triangles = _draw_scene(rng, int(pick(rng, (2, 3))))
        self._fragments = _fragments(self.triangles)
        self.expected = _zbuffer(self._fragments)[0]

    def mistakes(self):
        e = self.expected
        return [
            Mistake(_zbuffer(self._fragments, keep="last")[0], r"You let the last triangle "
                    r"drawn win everywhere, as if there were no depth test. A fragment is "
                    r"written only if its depth is less than the depth already stored at that "
                    r"pixel.", "no depth test"),
            Mistake(_zbuffer(self._fragments, keep="farthest")[0], r"The depth test is the "
                    r"wrong way round: the **smaller** depth is nearer the viewer (depth grows "
                    r"away from the eye in CSS and in the depth buffer), so it wins.",
                    "depth test reversed"),
            Mistake(np.flipud(e), r"Your rows are upside down: `ids[j][i]` is the pixel in "
                    r"column $i$ and row $j$ **counted from the bottom** ($y = j + 0.5$), so "
                    r"the first row of the array is the bottom row of the picture.",
                    "rows upside down"),
            Mistake(e.T, r"Rows and columns are swapped: `ids[j][i]` holds pixel $(i, j)$, so "
                    r"each row of the array is one value of $y$.", "transposed"),
            Mistake(np.where(e >= 0, e + 1, -1), r"The triangles are numbered from **0** (the "
                    r"first one drawn is triangle 0), and the background is $-1$.",
                    "numbered from 1"),
        ]

    def hints(self):
        covers = [_cover_by_hand(t) for t in self.triangles]
        return [
            r"At each pixel the id buffer ends with the triangle that is **nearest** (smallest "
            r"depth) among those covering the pixel centre, and $-1$ where none does.",
            r"For each triangle find the pixel centres $(i + 0.5, j + 0.5)$ inside it (all "
            r"three barycentric coordinates $\ge 0$) and its depth there, "
            r"$\lambda_0 z_0 + \lambda_1 z_1 + \lambda_2 z_2$; where triangles overlap, "
            r"compare their depths.",
            rf"{_counts_words(covers)}; they overlap at {_pixels_words(_overlaps(covers))}.",
        ]

    def worked(self):
        covers = [_cover_by_hand(t) for t in self.triangles]
        steps = [_coverage_words(k, c) for k, c in enumerate(covers)]
        ids = -np.ones((_GRID, _GRID), dtype=int)
        nearest = np.ones((_GRID, _GRID))             # the far plane
        for k, covered in enumerate(covers):
            for (i, j), z in covered.items():
                if z < nearest[j, i]:
                    ids[j, i], nearest[j, i] = k, z
        overlaps = _overlaps(covers)
        if overlaps:
            steps.append(r"Where triangles overlap the smaller depth wins: "
                         + "; ".join(rf"$({i}, {j})$: " + ", ".join(
                             f"{k} at {_num(z)}" for k, z in here) + rf" $\Rightarrow$ "
                             rf"{min(here, key=lambda kz: kz[1])[0]}"
                             for (i, j), here in overlaps.items()) + ".")
        steps.append(r"The id buffer, row $j = 0$ (the bottom of the picture) first: "
                     rf"${fmt.matrix_latex(ids, 0)}$.")
        return Worked(steps, ids)

    def _check(self, answer):
        if _unanswered(answer):
            return Feedback("unanswered", UNANSWERED)
        value = read_floats(answer)
        if value is None or value.shape != (_GRID, _GRID) or \
                not np.all(value == np.round(value)):
            return Feedback("invalid", "Give a 4 x 4 array of whole numbers: the triangle "
                            "numbers, and -1 for the background.", "unreadable")
        if np.array_equal(value, self.expected):
            return Feedback("correct", "The id buffer is right.")
        for mistake in self._mistakes:
            if np.array_equal(value, mistake.value):
                return Feedback("wrong", mistake.explanation, mistake.key)
        off = [(int(i), int(j)) for j, i in np.argwhere(value != self.expected)]
        return Feedback("wrong", f"{len(off)} pixels are off, e.g. pixel (i, j) = {off[0]}. "
                        "Check which triangles cover its centre and compare their depths "
                        "there.", "pixels differ")

    def statement(self):
        return (
            r"A few triangles, already in screen coordinates with a depth per vertex, are drawn "
            r"with the z-buffer algorithm:" "\n\n" + _scene_table(self.triangles) + "\n\n"
            + _ZBUFFER_RULES + " What does the id buffer hold at the end?\n\n"
            r"**Answer:** a $4 \times 4$ array `ids` of whole numbers with `ids[j][i]` the "
            r"triangle seen at pixel $(i, j)$ ($-1$ for the background). Row `j = 0` is the "
            r"**bottom** row of the picture, so printing the array shows the image upside "
            r"down." "\n\n" + data_note("triangles"))


class ZBufferWrites(DrawnExercise):
    r"""How many fragments pass the depth test (and are written) on a 4 x 4 grid.

    Attributes: ``triangles``.

    Examples
    --------
    >>> ex = ZBufferWrites(seed=12)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.total_fragments).diagnosis
    'counted all fragments'
    """

    title = "The z-buffer: how many writes?"
    answer_form = "number"
    what = "the number of writes"

    def draw(self, rng):
        self.triangles = _draw_scene(rng, 3)
        fragments = _fragments(self.triangles)
        ids, _, writes = _zbuffer(fragments)
        self.total_fragments = sum(len(f) for f in fragments)
        self.visible_pixels = int(np.count_nonzero(ids >= 0))
        self.expected = writes

    def mistakes(self):
        return [
            Mistake(self.visible_pixels, r"That is the number of pixels covered in the final "
                    r"picture. A pixel can be written more than once: first by a farther "
                    r"triangle, then again by a nearer one drawn later.",
                    "counted final pixels"),
            Mistake(self.total_fragments, r"That counts every fragment, but a fragment that is "
                    r"farther than what the buffer already holds fails the depth test and is "
                    r"not written.", "counted all fragments"),
            Mistake(self.total_fragments - self.expected, r"You counted the fragments that "
                    r"**fail** the depth test; the question asks for those that pass it (and "
                    r"are written).", "counted the failures"),
        ]

    off_by_one = (r"Off by one: go through the fragments once more, triangle by triangle; a "
                  r"fragment is written when its depth is **less** than the one stored at that "
                  r"moment.")

    def hints(self):
        covers = [_cover_by_hand(t) for t in self.triangles]
        return [
            r"A fragment is written when its depth is less than the one stored at that "
            r"moment. The drawing order matters, and a pixel can be written more than once.",
            r"The first triangle's fragments are all written (the buffer holds 1 everywhere). "
            r"For each later triangle compare, at each of its pixels, with the depth the "
            r"triangles before it left there.",
            rf"{_counts_words(covers)} ({sum(len(c) for c in covers)} fragments); they "
            rf"overlap at {_pixels_words(_overlaps(covers))}.",
        ]

    def worked(self):
        covers = [_cover_by_hand(t) for t in self.triangles]
        steps = [_coverage_words(k, c) for k, c in enumerate(covers)]
        stored, writes = {}, 0
        for k, covered in enumerate(covers):
            passed, failed = [], []
            for pixel, z in sorted(covered.items()):
                if z < stored.get(pixel, 1.0):
                    passed.append(pixel)
                    stored[pixel] = z
                else:
                    failed.append((pixel, z))
            writes += len(passed)
            text = rf"Drawing triangle {k}: {len(passed)} of its {len(covered)} fragments pass"
            if failed:
                text += (" (it fails at " + ", ".join(
                    rf"$({i}, {j})$, {_num(z)} against the stored {_num(stored[(i, j)])}"
                    for (i, j), z in failed) + ")")
            steps.append(text + ".")
        steps.append(rf"In all {writes} writes.")
        return Worked(steps, writes)

    def statement(self):
        return (
            r"Three triangles, already in screen coordinates with a depth per vertex, are "
            r"drawn in this order with the z-buffer algorithm:" "\n\n"
            + _scene_table(self.triangles) + "\n\n" + _ZBUFFER_RULES + "\n\n"
            r"How many fragments pass the depth test, i.e. how many times is a value written "
            r"into the z-buffer (counting every write, also those overwritten later)?" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("triangles"))
