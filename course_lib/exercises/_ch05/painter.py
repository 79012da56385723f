"""Chapter 5 exercises: The painter's algorithm.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import numpy as np

from ..core import UNANSWERED, Feedback, Mistake, Worked, data_note, pick, read_floats
from . import _Listed, _num, _set_feedback, _unanswered

__all__ = [
    "PainterFailure",
    "PaintersOrder",
]


def _read_order(answer, n):
    """The answer as a list of n whole numbers (``2.0`` is 2), or a Feedback saying why not."""
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    form = f"Give the order as a list of the {n} polygon numbers 0 to {n - 1}, each once."
    if isinstance(answer, (list, tuple)) and any(isinstance(a, (bool, np.bool_))
                                                 for a in answer):
        return Feedback("invalid", form, "unreadable")
    value = read_floats(answer)
    if value is None or value.shape != (n,) or value.dtype == bool \
            or not np.all(value == np.round(value)):
        return Feedback("invalid", form, "unreadable")
    return [int(v) for v in value]


class PaintersOrder(_Listed):
    r"""The painter's (depth-sort) drawing order: the farthest polygon first.

    Each polygon is keyed by its farthest vertex (the smallest :math:`z_e`, the eye looking down
    :math:`-z_e`) and the polygons are drawn from the farthest to the nearest. Four or five
    polygons; the answer is their numbers (whole numbers, ``2.0`` reads as 2) in drawing order.

    Attributes: ``depths`` (per polygon, the :math:`z_e` of its vertices).

    Examples
    --------
    >>> ex = PaintersOrder(seed=13)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'nearest first'
    """

    title = "The painter's algorithm: drawing order"
    answer_form = "custom"

    def draw(self, rng):
        count = int(pick(rng, (4, 5)))
        self.depths = [-np.sort(rng.choice(np.arange(1, 16), size=3, replace=False))[::-1]
                       .astype(float) for _ in range(count)]
        farthest = [d.min() for d in self.depths]
        self.expected = [int(i) for i in np.argsort(farthest, kind="stable")]

    def mistakes(self):
        nearest = [d.max() for d in self.depths]
        mean = [d.mean() for d in self.depths]
        return [
            Mistake(self.expected[::-1], r"You drew the nearest polygon first; it would then be "
                    r"painted over by the farther ones. The painter paints the background first: "
                    r"from the farthest polygon to the nearest. The eye looks down $-z_e$, so the "
                    r"farthest point is the one with the **most negative** $z_e$.",
                    "nearest first", numeric=False),
            Mistake([int(i) for i in np.argsort(nearest, kind="stable")], r"You sorted by each "
                    r"polygon's nearest vertex. Depth sort keys each polygon by its **farthest** "
                    r"point (smallest $z_e$) and draws those first.",
                    "sorted by nearest vertex", numeric=False),
            Mistake([int(i) for i in np.argsort(mean, kind="stable")], r"You sorted by the average "
                    r"depth of the vertices. The depth sort described here keys each polygon by "
                    r"its **farthest** vertex (smallest $z_e$).",
                    "sorted by average depth", numeric=False),
        ]

    def _farthest(self):
        return [d.min() for d in self.depths]

    def acceptable(self):
        keys = [self._farthest(), [d.max() for d in self.depths],
                [d.mean() for d in self.depths]]
        return all(len(set(k)) == len(k) for k in keys)

    def separated(self, mistakes):
        values = [tuple(m.value) for m in mistakes]
        values.append(tuple(self.expected))
        return len(set(values)) == len(values)

    def _check(self, answer):
        n = len(self.depths)
        order = _read_order(answer, n)
        if isinstance(order, Feedback):
            return order
        if order == self.expected:
            return Feedback("correct", "The drawing order is right.")
        for mistake in self._mistakes:
            if order == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        if order == [k + 1 for k in self.expected]:
            return Feedback("wrong", rf"Right order, but the polygons are numbered from **0** "
                            rf"to {n - 1}, as in the table.", "counted from 1")
        if sorted(order) != list(range(n)):
            missing = sorted(set(range(n)) - set(order))
            return Feedback("wrong", rf"Every polygon is drawn exactly once: the order lists each "
                            rf"of the numbers 0 to {n - 1} once, and yours lacks "
                            + ", ".join(str(k) for k in missing) + ".", "not a permutation")
        return Feedback("wrong", r"Not the depth-sort order. For each polygon find its "
                        r"farthest vertex (smallest $z_e$); draw the polygon whose farthest "
                        r"vertex is farthest first.", "order differs")

    def statement(self):
        rows = "\n".join(rf"| {k} | " + ", ".join(_num(z) for z in d) + " |"
                         for k, d in enumerate(self.depths))
        n = len(self.depths)
        return (
            rf"{['Four', 'Five'][n - 4]} polygons are to be drawn with the painter's algorithm "
            r"(depth sort). The eye "
            r"looks down $-z_e$; the $z_e$ coordinates of each polygon's vertices are:" "\n\n"
            "| polygon | $z_e$ of its vertices |\n|---|---|\n" + rows + "\n\n"
            r"Each polygon is keyed by its **farthest** vertex, and the polygons are drawn from "
            r"the farthest to the nearest. In which order are they drawn?" "\n\n"
            rf"**Answer:** the list of the {n} polygon numbers in drawing order, e.g. "
            + ("`[2, 0, 3, 1]`." if n == 4 else "`[2, 0, 4, 3, 1]`.") + "\n\n"
            + data_note("depths"))

    def hints(self):
        keys = ", ".join(rf"polygon {k}: ${_num(d.min())}$" for k, d in enumerate(self.depths))
        return [
            r"Depth sort paints the background first: key each polygon by its **farthest** "
            r"vertex and draw from the farthest polygon to the nearest.",
            r"The eye looks down $-z_e$, so the farthest vertex of a polygon is the one with "
            r"the smallest (most negative) $z_e$. Sort the polygons by that key, smallest "
            r"first.",
            rf"The keys (the smallest $z_e$ of each polygon) are {keys}.",
        ]

    def worked(self):
        keys = [min(float(z) for z in d) for d in self.depths]
        order = sorted(range(len(keys)), key=lambda k: keys[k])
        return Worked([
            r"The eye looks down $-z_e$: the farthest vertex of a polygon has the smallest "
            r"$z_e$. The keys: " + ", ".join(rf"polygon {k}: $\min(" + ", ".join(
                _num(z) for z in d) + rf") = {_num(key)}$" for k, (d, key)
                in enumerate(zip(self.depths, keys))) + ".",
            r"Sorted from the farthest (smallest key) to the nearest: "
            + ", ".join(rf"{k} (${_num(keys[k])}$)" for k in order) + ".",
        ], order)


_STRIP = 8


def _strip_coverage(segments):
    """Per pixel of a 1D screen: {segment: depth} for the segments covering its centre."""
    pixels = []
    for i in range(_STRIP):
        x = i + 0.5
        here = {}
        for k, (x0, d0, x1, d1) in enumerate(segments):
            lo, hi = min(x0, x1), max(x0, x1)
            if lo < x < hi:
                here[k] = d0 + (x - x0) / (x1 - x0) * (d1 - d0)
        pixels.append(here)
    return pixels


def _paint(coverage, order):
    shown = [-1] * _STRIP
    for k in order:
        for i, here in enumerate(coverage):
            if k in here:
                shown[i] = k
    return shown


class PainterFailure(_Listed):
    r"""Where the painter's algorithm draws the wrong polygon (a side view, a 1D screen).

    Segments in the :math:`(x, \text{depth})` plane are sorted by their farthest end point and
    painted from the farthest; at some pixels a segment painted early is in front of one painted
    later, and depth sorting gets the picture wrong there.

    Attributes: ``segments`` (rows ``x0, depth0, x1, depth1``).

    Examples
    --------
    >>> ex = PainterFailure(seed=14)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> ex.check([]).diagnosis
    'no failure'
    """

    title = "Where the painter's algorithm fails"
    answer_form = "custom"

    def draw(self, rng):
        segments = []
        for _ in range(3):
            x0, x1 = np.sort(rng.choice(_STRIP + 1, size=2, replace=False))
            d0, d1 = rng.integers(1, 10, size=2)
            segments.append([float(x0), float(d0), float(x1), float(d1)])
        self.segments = np.array(segments)
        self._coverage = _strip_coverage(self.segments)
        far = np.maximum(self.segments[:, 1], self.segments[:, 3])
        self.order = [int(k) for k in np.argsort(-far, kind="stable")]
        self.correct = [min(here, key=here.get) if here else -1 for here in self._coverage]
        self.painted = _paint(self._coverage, self.order)
        self.expected = {i for i in range(_STRIP) if self.painted[i] != self.correct[i]}

    def acceptable(self):
        far = np.maximum(self.segments[:, 1], self.segments[:, 3])
        if len(set(far)) != 3 or not self.expected:
            return False
        for here in self._coverage:
            depths = sorted(here.values())
            if any(b - a < 0.05 for a, b in zip(depths, depths[1:])):
                return False
        return all(self.segments[k, 2] - self.segments[k, 0] >= 2 for k in range(3))

    def mistakes(self):
        overlaps = {i for i, here in enumerate(self._coverage) if len(here) >= 2}
        reversed_paint = _paint(self._coverage, self.order[::-1])
        return [
            Mistake(set(), r"Depth sorting does go wrong here. A polygon keyed by a far end point "
                    r"can still be **in front** of another one at some pixels (long, slanted "
                    r"polygons, or polygons that cross), and there the later one is painted over "
                    r"it. Compare, at every pixel, the segment painted last with the nearest one.",
                    "no failure", numeric=False),
            Mistake(overlaps, r"Not every pixel where segments overlap goes wrong: where the "
                    r"segment painted last is also the nearest, the picture is right. List only "
                    r"the pixels where the last-painted segment is not the nearest.",
                    "all overlaps", numeric=False),
            Mistake({i for i in range(_STRIP) if reversed_paint[i] != self.correct[i]}, r"You "
                    r"painted from the nearest segment to the farthest. The painter paints the "
                    r"farthest first (sorted by the farthest end point), so that nearer segments "
                    r"cover it.", "nearest first", numeric=False),
        ]

    def separated(self, mistakes):
        values = [frozenset(m.value) for m in mistakes] + [frozenset(self.expected)]
        return len(set(values)) == len(values)

    def _check(self, answer):
        return _set_feedback(answer, self.expected, self._mistakes, _STRIP,
                             "the pixels where the painter is wrong",
                             "At each pixel compare the segment painted last with the nearest "
                             "segment there.",
                             "The painter's picture is wrong at exactly these pixels.")

    def _by_hand(self):
        """The painting order, and per pixel the segments covering it with their depths."""
        far = [max(s[1], s[3]) for s in self.segments]
        order = sorted(range(len(far)), key=lambda k: -far[k])
        pixels = []
        for i in range(_STRIP):
            x = i + 0.5
            here = {}
            for k, (x0, d0, x1, d1) in enumerate(self.segments):
                if min(x0, x1) < x < max(x0, x1):
                    here[k] = d0 + (d1 - d0) * (x - x0) / (x1 - x0)
            pixels.append(here)
        return far, order, pixels

    def hints(self):
        far, order, pixels = self._by_hand()
        shared = [i for i, here in enumerate(pixels) if len(here) > 1]
        return [
            r"The painter's picture shows, at each pixel, the segment painted **last** among "
            r"those covering it; the true picture shows the **nearest** one. They differ where "
            r"a segment painted earlier is nearer.",
            r"Sort the segments by their farthest end point (the largest depth) and paint the "
            r"farthest first. Then, at each pixel covered by two or more segments, interpolate "
            r"their depths at $x = i + 0.5$ and compare.",
            r"The painting order is " + ", ".join(str(k) for k in order)
            + r"; the pixels covered by more than one segment are "
            + ", ".join(str(i) for i in shared) + ".",
        ]

    def worked(self):
        far, order, pixels = self._by_hand()
        steps = [r"Farthest end points: " + ", ".join(
            rf"segment {k}: ${_num(f)}$" for k, f in enumerate(far)) + r"; painted in the "
            r"order " + ", ".join(str(k) for k in order) + "."]
        wrong = []
        for i, here in enumerate(pixels):
            if len(here) < 2:
                continue
            last = [k for k in order if k in here][-1]
            nearest = min(here, key=here.get)
            depths = ", ".join(rf"{k} at ${_num(z)}$" for k, z in sorted(here.items()))
            verdict = ("right" if last == nearest else
                       rf"**wrong** (segment {nearest} is nearer)")
            steps.append(rf"Pixel {i} ($x = {_num(i + 0.5)}$): {depths}; painted last: "
                         rf"{last}: {verdict}.")
            if last != nearest:
                wrong.append(i)
        steps.append(r"Pixels covered by one segment or none are always right. The painter "
                     r"is wrong at the pixels " + ", ".join(str(i) for i in wrong) + ".")
        return Worked(steps, wrong)

    def statement(self):
        rows = "\n".join(rf"| {k} | $({_num(x0)}, {_num(d0)})$ | $({_num(x1)}, {_num(d1)})$ |"
                         for k, (x0, d0, x1, d1) in enumerate(self.segments))
        return (
            r"A side view: a screen of 8 pixels in a row, pixel $i$ with its centre at "
            r"$x = i + 0.5$, looks at polygons seen edge-on, that is, segments in the "
            r"$(x, \text{depth})$ plane (depth = distance from the viewer, projection "
            r"parallel to the depth axis). A segment covers a pixel when it spans the pixel's "
            r"centre; its depth there is interpolated linearly." "\n\n"
            "| segment | end point $(x, \\text{depth})$ | end point $(x, \\text{depth})$ |\n"
            "|---|---|---|\n" + rows + "\n\n"
            r"The painter's algorithm sorts the segments by their **farthest** end point and "
            r"paints the farthest first. At which pixels does its picture differ from the true "
            r"one (the nearest segment at each pixel)?" "\n\n"
            r"**Answer:** the list of those pixel numbers $i$, e.g. `[2, 3]` (the order does "
            r"not matter)." "\n\n" + data_note("segments"))
