"""Chapter 5 exercises: hierarchical occlusion culling (z-pyramid, HZB test, occlusion queries,
hierarchical occlusion maps).

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here. The answers are
worked out with :mod:`course_lib.visibility.hierarchical`; the anticipated slips by small numpy
expressions next to them.
"""

import numpy as np

from ... import visibility
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _num

__all__ = [
    "HOMOpacity",
    "HZBRejection",
    "OcclusionQueryCount",
    "ZPyramidNextLevel",
]


def _depth_cell(v):
    return r"$\infty$" if np.isinf(v) else _num(float(v))


def _grid_md(a, cell=_depth_cell):
    """A Markdown table of a buffer: row j = top row printed first, columns i = 0, 1, ..."""
    h, w = a.shape
    head = "| row j \\ column i | " + " | ".join(str(i) for i in range(w)) + " |\n"
    head += "|---" * (w + 1) + "|\n"
    rows = "".join(f"| **{j}** | " + " | ".join(cell(v) for v in a[j]) + " |\n"
                   for j in range(h - 1, -1, -1))
    return head + rows


def _mat(a):
    return "[" + ", ".join("[" + ", ".join(_num(float(v)) for v in row) + "]" for row in a) + "]"


class ZPyramidNextLevel(DrawnExercise):
    r"""Level 1 of the z-pyramid of a 4 x 4 depth buffer: the farthest depth of each 2 x 2 block.

    Attributes: ``depth`` (4 x 4, row 0 at the bottom; ``depth[j, i]``).

    Examples
    --------
    >>> ex = ZPyramidNextLevel(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.depth.reshape(2, 2, 2, 2).min(axis=(1, 3))).diagnosis
    'min instead of max'
    """

    title = "The next level of a z-pyramid"
    answer_form = "matrix"
    transform = False
    what = "level 1 of the pyramid"
    advice = ("Each texel of level 1 is the **largest** (farthest) depth of the 2 x 2 pixels "
              "below it: texel (row r, column c) covers rows 2r, 2r+1 and columns 2c, 2c+1.")

    def draw(self, rng):
        self.depth = rng.integers(1, 10, (4, 4)) / 10.0
        self.expected = visibility.z_pyramid(self.depth).levels[1]

    def acceptable(self):
        blocks = self.depth.reshape(2, 2, 2, 2)
        return bool((blocks.max(axis=(1, 3)) > blocks.min(axis=(1, 3))).all())

    def mistakes(self):
        blocks = self.depth.reshape(2, 2, 2, 2)
        return [
            Mistake(blocks.min(axis=(1, 3)), "You kept the **nearest** depth of each block. "
                    "The pyramid must be conservative: a texel promises that nothing in its "
                    "block is farther than its value, so it stores the maximum.",
                    "min instead of max"),
            Mistake(blocks.mean(axis=(1, 3)), "You averaged each block, as an occlusion map "
                    "(or a mipmap) does. An average says nothing certain about every pixel "
                    "below: a box behind the average can still be in front of the farthest "
                    "pixel. The z-pyramid keeps the maximum.", "average instead of max"),
            Mistake(self.expected[::-1], "The maxima are right but the rows are upside down: "
                    "row 0 is the bottom row of the table (its last printed row), and the "
                    "answer's first row is level 1's row 0.", "rows upside down"),
        ]

    def statement(self):
        return ("A 4 x 4 depth buffer (depth 0 near, 1 far; row 0 at the bottom):\n\n"
                + _grid_md(self.depth) + "\nGive **level 1** of its z-pyramid (hierarchical "
                "z-buffer) as a 2 x 2 matrix `[[row 0], [row 1]]`, row 0 first (the bottom "
                "row, as in `depth[j, i]`).\n\n**Answer:** a 2 x 2 matrix of numbers, e.g. "
                "`[[0.5, 0.7], [0.9, 0.2]]`.\n\n" + data_note("depth"))

    def hints(self):
        d = self.depth
        return ["A coarser texel must be safe to compare against: no pixel below it may be "
                "farther than its value. Which reduction of 4 numbers guarantees that?",
                "Texel (r, c) covers pixels (rows 2r, 2r+1; columns 2c, 2c+1). Texel (0, 0): "
                f"the pixels {_num(d[0, 0])}, {_num(d[0, 1])}, {_num(d[1, 0])}, "
                f"{_num(d[1, 1])}.",
                f"Texel (0, 0) is the maximum of those four, {_num(d[:2, :2].max())}; do the "
                "same for the other three blocks, and list row 0 (the bottom) first."]

    def worked(self):
        d = self.depth
        steps = []
        out = np.empty((2, 2))
        for r in range(2):
            for c in range(2):
                block = d[2 * r:2 * r + 2, 2 * c:2 * c + 2].ravel()
                out[r, c] = block.max()
                steps.append(f"Texel (row {r}, column {c}) covers rows {2 * r}, {2 * r + 1} and "
                             f"columns {2 * c}, {2 * c + 1}: "
                             f"max({', '.join(_num(float(v)) for v in block)}) = "
                             f"{_num(out[r, c])}.")
        steps.append(f"Level 1 = {_mat(out)} (row 0 first).")
        return Worked(steps, out)


class HZBRejection(DrawnExercise):
    r"""Which of four boxes the hierarchical z-buffer rejects, given levels 1 and 2 of an 8 x 8
    buffer's z-pyramid.

    The level is the finest at which the box's rectangle spans at most 2 x 2 texels; the box is
    rejected when its nearest depth is larger than the largest covering texel.

    Attributes: ``level1`` (4 x 4), ``level2`` (2 x 2), ``rects`` (4 rows ``(i0, j0, i1, j1)``,
    pixels of the 8 x 8 screen, inclusive), ``z_near``, ``z_far`` (per box).

    Examples
    --------
    >>> ex = HZBRejection(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Does the hierarchical z-buffer reject the box?"
    answer_form = "vector"
    vector_like = False
    what = "the list of decisions"
    advice = ("For each box: the level k where its rectangle spans at most 2 texels each way "
              "(texel column = i // 2^k), the largest of those texels, and reject (1) only if "
              "the box's **nearest** depth is larger.")

    def draw(self, rng):
        depth = rng.integers(2, 10, (8, 8)) / 10.0
        # a near occluder over part of the screen, so that some boxes are hidden
        a, b = int(rng.integers(0, 2)), int(rng.integers(0, 2))
        depth[2 * a:2 * a + 6, 2 * b:2 * b + 6] = rng.integers(1, 4, (6, 6)) / 10.0
        pyr = visibility.z_pyramid(depth)
        self.level1, self.level2 = pyr.levels[1], pyr.levels[2]
        rects = []
        for _ in range(4):
            w, h = int(rng.integers(1, 6)), int(rng.integers(3, 6))
            if rng.random() < 0.5:
                w, h = h, w
            i0, j0 = int(rng.integers(0, 9 - w)), int(rng.integers(0, 9 - h))
            rects.append((i0, j0, i0 + w - 1, j0 + h - 1))
        self.rects = np.array(rects)
        self.z_near = rng.integers(2, 9, 4) / 10.0
        self.z_far = np.minimum(self.z_near + rng.integers(1, 4, 4) / 10.0, 1.0)
        self._pyr = pyr
        self.expected = visibility.hzb_cull(pyr, self.rects, self.z_near).rejected * 1.0

    def _texels(self, k, rect, divide=True):
        lv = self._pyr.levels[k]
        i0, j0, i1, j1 = rect
        if divide:
            return lv[j0 >> k:(j1 >> k) + 1, i0 >> k:(i1 >> k) + 1]
        n = lv.shape[0] - 1
        return lv[min(j0, n):min(j1, n) + 1, min(i0, n):min(i1, n) + 1]

    def _levels(self):
        return visibility.hzb_level(self.rects)

    def acceptable(self):
        levels = self._levels()
        maxima = np.array([self._texels(k, r).max() for k, r in zip(levels, self.rects)])
        mins = np.array([self._texels(k, r).min() for k, r in zip(levels, self.rects)])
        # no ties, both decisions present
        return bool((levels >= 1).all() and (maxima != self.z_near).all()
                    and (mins != self.z_near).all() and (maxima != self.z_far).all()
                    and 0 < self.expected.sum() < 4)

    def mistakes(self):
        levels = self._levels()
        tex = [self._texels(k, r) for k, r in zip(levels, self.rects)]
        undivided = [self._texels(k, r, divide=False) for k, r in zip(levels, self.rects)]
        return [
            Mistake(np.array([z > t.min() for z, t in zip(self.z_near, tex)]) * 1.0,
                    "You compared with the **nearest** covering texel. The box is hidden only "
                    "if it is behind everything in front of it: compare with the largest "
                    "(farthest) texel.", "compared with the min"),
            Mistake(np.array([z > t.max() for z, t in zip(self.z_far, tex)]) * 1.0,
                    "You used the box's **far** depth. A box whose far side is behind the "
                    "texels may still poke out in front; the safe test uses its nearest "
                    "depth.", "used the far depth"),
            Mistake(np.array([z > t.max() for z, t in zip(self.z_near, undivided)]) * 1.0,
                    "You used the pixel coordinates as texel indices. At level k texel column "
                    "= i // 2^k (and row = j // 2^k).", "coordinates not divided"),
        ]

    def statement(self):
        rows = "\n".join(f"| {n} | columns {r[0]} to {r[2]}, rows {r[1]} to {r[3]} | "
                         f"{_num(float(zn))} | {_num(float(zf))} |"
                         for n, (r, zn, zf) in enumerate(zip(self.rects, self.z_near,
                                                             self.z_far)))
        return ("The z-pyramid of an 8 x 8 depth buffer (depth 0 near, 1 far; max of 2 x 2 "
                "texels; row 0 at the bottom). Level 1 (4 x 4, each texel 2 x 2 pixels):\n\n"
                + _grid_md(self.level1) + "\nLevel 2 (2 x 2, each texel 4 x 4 pixels):\n\n"
                + _grid_md(self.level2) + "\nFour boxes, by their screen rectangles (pixels, "
                "inclusive) and depth range:\n\n| box | rectangle | nearest depth | farthest "
                "depth |\n|---|---|---|---|\n" + rows + "\n\nThe hierarchical test reads the "
                "finest level at which the rectangle spans at most 2 texels in each direction. "
                "Give a list of 4 numbers: 1 if the test rejects the box, 0 if the box must be "
                "drawn.\n\n**Answer:** a list of 4 numbers, 0 or 1, e.g. `[1, 0, 0, 1]`.\n\n"
                + data_note("level1", "level2", "rects", "z_near", "z_far"))

    def hints(self):
        r = self.rects[0]
        return ["At level k, pixel column i falls in texel column i // 2^k. Find the smallest k "
                "where the first and last column (and row) are at most 1 texel apart.",
                f"Box 0, columns {r[0]}–{r[2]}, rows {r[1]}–{r[3]}: level "
                f"{int(self._levels()[0])}.",
                "Take the largest covering texel; reject only if the box's nearest depth is "
                "larger."]

    def worked(self):
        steps, out = [], []
        for n, (k, r, z) in enumerate(zip(self._levels(), self.rects, self.z_near)):
            t = self._texels(k, r)
            rej = bool(z > t.max())
            out.append(1.0 * rej)
            steps.append(
                f"Box {n}: columns {r[0]}–{r[2]} → texel columns {r[0] >> k}–{r[2] >> k}, rows "
                f"{r[1]}–{r[3]} → texel rows {r[1] >> k}–{r[3] >> k} at level {k} (at level "
                f"{k - 1} it would span more than 2). Texels: "
                f"{', '.join(_num(float(v)) for v in t.ravel())}; largest {_num(float(t.max()))}. "
                f"Nearest depth {_num(float(z))} {'>' if rej else '≤'} {_num(float(t.max()))}: "
                f"{'rejected (1)' if rej else 'drawn (0)'}.")
        return Worked(steps, np.array(out))


class OcclusionQueryCount(DrawnExercise):
    r"""The result of an occlusion query: the samples of a proxy rectangle that pass the depth
    test ``z < stored``.

    Attributes: ``depth`` (4 x 5, row 0 at the bottom; ``inf`` = nothing drawn), ``rect``
    ``(i0, j0, i1, j1)`` inclusive, ``z`` (the proxy's depth).

    Examples
    --------
    >>> ex = OcclusionQueryCount(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The result of an occlusion query"
    answer_form = "number"
    what = "the query result"
    advice = "Count the pixels of the rectangle whose stored depth is strictly larger than z."

    def draw(self, rng):
        self.depth = rng.integers(1, 10, (4, 5)) / 10.0
        self.depth[rng.random((4, 5)) < 0.15] = np.inf
        w, h = int(rng.integers(2, 5)), int(rng.integers(2, 4))
        i0, j0 = int(rng.integers(0, 6 - w)), int(rng.integers(0, 5 - h))
        self.rect = (i0, j0, i0 + w - 1, j0 + h - 1)
        self.z = float(pick(rng, (0.3, 0.4, 0.5, 0.6, 0.7)))
        self.expected = visibility.occlusion_query(self.depth, self.rect, self.z)

    def _block(self):
        i0, j0, i1, j1 = self.rect
        return self.depth[j0:j1 + 1, i0:i1 + 1]

    def acceptable(self):
        b = self._block()
        return bool((b == self.z).any() and np.isinf(b).any() and 0 < self.expected < b.size)

    def mistakes(self):
        b = self._block()
        return [
            Mistake(int((b <= self.z).sum()), "You counted the hidden samples. The query "
                    "counts the samples that **pass** the depth test (nearer than what is "
                    "stored): those would be visible.", "counted hidden samples"),
            Mistake(int((self.z <= b).sum()), "You let equal depths pass. The usual depth test "
                    "is strict, z < stored: a sample at the same depth as the stored one does "
                    "not pass.", "<= instead of <"),
            Mistake(int((self.z < b[np.isfinite(b)]).sum()), "You skipped the empty pixels "
                    "(∞). Nothing was drawn there, so every sample passes: the proxy is "
                    "visible through the hole.", "empty pixels skipped"),
            Mistake(int(b.size), "That is every pixel of the rectangle: the query counts only "
                    "the samples nearer than the stored depth.", "whole rectangle"),
        ]

    def statement(self):
        i0, j0, i1, j1 = self.rect
        return ("The depth buffer so far (0 near, 1 far; ∞ = nothing drawn; row 0 at the "
                "bottom):\n\n" + _grid_md(self.depth) + f"\nAn occlusion query draws the "
                f"front face of a bounding box: the rectangle of columns {i0} to {i1} and rows "
                f"{j0} to {j1}, all at depth z = {_num(self.z)}, with the depth test `z < "
                "stored` and depth writes off. What number does the query return?\n\n"
                "**Answer:** one whole number.\n\n" + data_note("depth", "rect", "z"))

    def hints(self):
        b = self._block()
        return ["The query counts the proxy's samples that pass the depth test, i.e. that would "
                "be visible if drawn.",
                f"The rectangle holds {b.size} pixels; in how many is the stored depth "
                f"strictly larger than {_num(self.z)} (∞ counts as larger)?",
                f"{int((b == self.z).sum())} pixel(s) hold exactly {_num(self.z)}: they do not "
                "pass a strict test."]

    def worked(self):
        b = self._block()
        j0 = self.rect[1]
        steps = []
        for r in range(b.shape[0]):
            passing = int((self.z < b[r]).sum())
            steps.append(f"Row {j0 + r}: stored {', '.join(_depth_cell(v) for v in b[r])}; "
                         f"greater than {_num(self.z)}: {passing}.")
        total = int((self.z < b).sum())
        steps.append(f"Samples passing: {total} of {b.size}.")
        return Worked(steps, total)


class HOMOpacity(DrawnExercise):
    r"""The opacity of a level-2 texel of a hierarchical occlusion map, from an 8 x 8 coverage
    map (occluders white = 1 on black = 0), and whether it passes a threshold.

    Attributes: ``coverage`` (8 x 8 of 0/1, row 0 at the bottom), ``texel`` (row, column) at
    level 2, ``threshold``.

    Examples
    --------
    >>> ex = HOMOpacity(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(1.0).diagnosis
    'max instead of average'
    """

    title = "An opacity in a hierarchical occlusion map"
    answer_form = "number"
    what = "the opacity"
    advice = ("Each level averages 2 x 2 texels, so a level-2 texel is the fraction of its "
              "4 x 4 pixels covered by occluders.")

    def draw(self, rng):
        cov = (rng.random((8, 8)) < rng.uniform(0.55, 0.95)).astype(float)
        self.coverage = cov
        self.texel = (int(rng.integers(0, 2)), int(rng.integers(0, 2)))
        self.threshold = float(pick(rng, (0.75, 0.8, 0.85, 0.9)))
        pyr = visibility.occlusion_map_pyramid(cov)
        self._level1 = pyr.levels[1]
        self.expected = float(pyr.levels[2][self.texel])

    def _block(self, texel=None):
        r, c = texel or self.texel
        return self.coverage[4 * r:4 * r + 4, 4 * c:4 * c + 4]

    def acceptable(self):
        return 0 < self.expected < 1

    def mistakes(self):
        b = self._block()
        r, c = self.texel
        l1 = self._level1[2 * r:2 * r + 2, 2 * c:2 * c + 2]
        return [
            Mistake(float(b.max()), "You took the maximum, as the z-pyramid does. An "
                    "occlusion map **averages**: the texel says how much of its area the "
                    "occluders cover.", "max instead of average"),
            Mistake(float((l1 > 0).mean()), "You treated each level-1 texel as covered when "
                    "any of its pixels is (a max at the first step). Average at both levels.",
                    "max at level 1"),
            Mistake(float(b.sum()), "That is the number of covered pixels; the opacity is the "
                    "fraction, divided by the 16 pixels of the texel.", "count, not fraction"),
            Mistake(float(self._block((1 - r, c)).mean()), "That is the texel of the other "
                    "row: row 0 is the bottom row of the map.", "rows upside down"),
        ]

    def statement(self):
        r, c = self.texel
        grid = _grid_md(self.coverage, lambda v: str(int(v)))
        return ("Occluders rendered white (1) on black (0) into an 8 x 8 coverage map (row 0 "
                "at the bottom):\n\n" + grid + "\nThe hierarchical occlusion map builds each "
                "level from 2 x 2 texels of the level below. What is the opacity of the "
                f"**level-2** texel in row {r}, column {c} (it covers pixel rows {4 * r}–"
                f"{4 * r + 3} and columns {4 * c}–{4 * c + 3})? (Then ask yourself: does it "
                f"pass the opacity threshold {_num(self.threshold)}?)\n\n**Answer:** one "
                "number (the fraction, e.g. 0.5625).\n\n"
                + data_note("coverage", "texel", "threshold"))

    def hints(self):
        r, c = self.texel
        return ["The occlusion map averages (a box filter); the z-pyramid takes the max.",
                f"Level 1 over that texel: {_mat(self._level1[2 * r:2 * r + 2, 2 * c:2 * c + 2])}"
                " (each the mean of 2 x 2 pixels).",
                "The level-2 texel is the mean of those four: the covered fraction of its 16 "
                "pixels."]

    def worked(self):
        r, c = self.texel
        l1 = self._level1[2 * r:2 * r + 2, 2 * c:2 * c + 2]
        value = float(l1.mean())
        n = int(self._block().sum())
        passes = value >= self.threshold
        return Worked([
            f"Level 1 over the texel (means of 2 x 2 pixels): {_mat(l1)}.",
            f"Level 2: the mean of those four = {_num(value)} (= {n} covered pixels / 16).",
            f"Threshold {_num(self.threshold)}: {'passes' if passes else 'fails'} "
            f"({_num(value)} {'≥' if passes else '<'} {_num(self.threshold)}); a box inside "
            f"this texel {'may be culled if it is also behind the depth estimate' if passes else 'is not culled by this texel'}.",
        ], value)
