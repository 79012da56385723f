"""Chapter 5 exercises: Cohen-Sutherland.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import numpy as np

from ... import clipping
from ..core import (APART, DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, data_note,
                    gap, pick, read_floats)
from . import (_box_words, _clip_words, _draw_box_2d, _ints_between, _Listed, _quick_code,
               _same_segment, _unanswered, _vec)

__all__ = [
    "CohenSutherlandClip",
    "CohenSutherlandDecision",
    "CohenSutherlandIntersections",
    "Outcodes",
]


def _bits(code, dim):
    return format(int(code), f"0{2 * dim}b")


def _reverse_bits(code, dim):
    return int(_bits(code, dim)[::-1], 2)


def _swap_sides(code):
    """The outcode with left/right, bottom/top and near/far exchanged."""
    low = code & 0b010101
    high = code & 0b101010
    return (low << 1) | (high >> 1)


def _read_codes(answer, n, dim):
    """A list of n outcodes given as integers or bit strings, or a Feedback."""
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    form = (f"a list of {n} outcodes, each an integer (`9`) or a bit string of "
            f"{2 * dim} bits (`'{_bits(9, dim)}'`)")
    if isinstance(answer, (str, bytes, dict)) or not hasattr(answer, "__len__") \
            or len(answer) != n:
        return Feedback("invalid", f"Give {form}.", "unreadable")
    codes = []
    for item in answer:
        if isinstance(item, str):
            text = item.strip().replace(" ", "").replace("_", "")
            text = text[2:] if text.lower().startswith("0b") else text
            if not text or set(text) - {"0", "1"}:
                return Feedback("invalid", f"{item!r} is not a bit string; give {form}.",
                                "unreadable")
            if len(text) > 2 * dim:
                return Feedback("invalid", f"{item!r} has {len(text)} bits, but in {dim}D an "
                                f"outcode has {2 * dim} (one per side of the "
                                f"{'rectangle' if dim == 2 else 'box'}).", "too many bits")
            codes.append(int(text, 2))
        elif isinstance(item, (int, np.integer)) and not isinstance(item, (bool, np.bool_)):
            if not 0 <= item < 2 ** (2 * dim):
                return Feedback("invalid", f"{item} is not a {2 * dim}-bit outcode.",
                                "too many bits")
            codes.append(int(item))
        else:
            return Feedback("invalid", f"Give {form}.", "unreadable")
    return codes


class Outcodes(_Listed):
    r"""The Cohen-Sutherland outcodes of a few points (2D rectangle or 3D box).

    Bit values: left 1, right 2, bottom 4, top 8 (near 16, far 32 in 3D); a point on the
    boundary is inside.

    Attributes: ``dim``, ``box_min``, ``box_max``, ``points``.

    Examples
    --------
    >>> ex = Outcodes(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> as_bits = [format(c, f"0{2 * ex.dim}b") for c in ex.expected]
    >>> ex.check(as_bits).status
    'correct'
    >>> ex.check([b[::-1] for b in as_bits]).diagnosis
    'bit order reversed'
    """

    title = "Outcodes"
    answer_form = "custom"

    def draw(self, rng):
        self.dim = int(pick(rng, (2, 3)))
        self.box_min = rng.integers(-2, 1, size=self.dim).astype(float)
        self.box_max = self.box_min + rng.integers(3, 5, size=self.dim)
        self.points = _ints_between(rng, self.box_min - 2, self.box_max + 2,
                                    size=(5, self.dim))
        self.expected = [int(c) for c in clipping.outcode(self.points, self.box_min,
                                                          self.box_max)]

    def _on_boundary(self):
        return [int(sum((p[k] == self.box_min[k]) << (2 * k) | (p[k] == self.box_max[k])
                        << (2 * k + 1) for k in range(self.dim))) for p in self.points]

    def acceptable(self):
        counts = [bin(c).count("1") for c in self.expected]
        z_bits = any(c >> 4 for c in self.expected)
        return (max(counts) >= 2 and 0 in self.expected and (self.dim == 2 or z_bits)
                and len(set(self.expected)) >= 4)

    def mistakes(self):
        dim = self.dim
        found = [
            Mistake([_reverse_bits(c, dim) for c in self.expected], r"The bits are in the "
                    r"reverse order. Bit 0 (the **rightmost** bit, value 1) is left, then right "
                    r"(2), bottom (4), top (8)" + (r", near (16), far (32)" if dim == 3 else "")
                    + r"; written as a bit string the leftmost bit is "
                    + rf"{'far' if dim == 3 else 'top'}.", "bit order reversed", numeric=False),
            Mistake([_swap_sides(c) for c in self.expected], r"Left and right (and bottom and "
                    r"top" + (", near and far" if dim == 3 else "") + r") are swapped: the lower "
                    r"bit of each pair is the **minimum** side, e.g. left = 1 for $x < x_{min}$, "
                    r"right = 2 for $x > x_{max}$.", "min and max swapped", numeric=False),
        ]
        boundary = self._on_boundary()
        if any(boundary):
            found.append(Mistake([c | b for c, b in zip(self.expected, boundary)], r"A point on "
                                 r"the boundary is **inside**: a bit is set only for "
                                 r"$x < x_{min}$, $x > x_{max}$ and so on (strict inequalities).",
                                 "boundary counts as outside", numeric=False))
        if dim == 3:
            found.append(Mistake([c & 0b1111 for c in self.expected], r"The near and far bits are "
                                 r"missing: in 3D the outcode has 6 bits, near (16) for "
                                 r"$z < z_{min}$ and far (32) for $z > z_{max}$.",
                                 "z bits missing", numeric=False))
        return [m for m in found if m.value != self.expected]

    def separated(self, mistakes):
        values = [tuple(m.value) for m in mistakes]
        return len(set(values)) == len(values)

    def _check(self, answer):
        codes = _read_codes(answer, len(self.points), self.dim)
        if isinstance(codes, Feedback):
            return codes
        if codes == self.expected:
            return Feedback("correct", "All the outcodes are right.")
        for mistake in self._mistakes:
            if codes == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        off = [i for i, (a, b) in enumerate(zip(codes, self.expected)) if a != b]
        return Feedback("wrong", f"The outcodes of the points {off} (counted from 0) are off. "
                        "For each side compare one coordinate with the box: a bit is set when "
                        "the point is strictly beyond that side.", "codes differ")

    def statement(self):
        rows = "\n".join(rf"| {i} | ${_vec(p)}$ |" for i, p in enumerate(self.points))
        bits = ("left = 1 ($x < x_{min}$), right = 2 ($x > x_{max}$), bottom = 4 "
                "($y < y_{min}$), top = 8 ($y > y_{max}$)")
        if self.dim == 3:
            bits += ", near = 16 ($z < z_{min}$), far = 32 ($z > z_{max}$)"
        region = "rectangle" if self.dim == 2 else "box"
        return (
            rf"The clip {region} is {_box_words(self.box_min, self.box_max)}. Give the "
            rf"Cohen-Sutherland outcode of each point:" "\n\n| point | coordinates |\n|---|---|\n"
            + rows + "\n\n"
            rf"The bits are {bits}; a point on the boundary is inside." "\n\n"
            rf"**Answer:** a list of 5 outcodes, each either an integer (e.g. `9`) or a string "
            rf"of {2 * self.dim} bits with the highest bit first (e.g. "
            rf"`'{_bits(9, self.dim)}'`)." "\n\n" + data_note("dim", "box_min", "box_max",
                                                              "points"))


def _read_decisions(answer, n):
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    form = f"a list of {n} words, each `'accept'`, `'reject'` or `'clip'`"
    if isinstance(answer, (str, bytes, dict)) or not hasattr(answer, "__len__") \
            or len(answer) != n:
        return Feedback("invalid", f"Give {form}.", "unreadable")
    words = []
    for item in answer:
        if not isinstance(item, str):
            return Feedback("invalid", f"Give {form}.", "unreadable")
        text = item.strip().lower()
        if text.startswith(("acc", "trivially acc", "trivial acc")):
            words.append("accept")
        elif text.startswith(("rej", "trivially rej", "trivial rej")):
            words.append("reject")
        elif text.startswith(("clip", "subdiv", "split")):
            words.append("clip")
        else:
            return Feedback("invalid", f"{item!r} is none of 'accept', 'reject', 'clip'.",
                            "unreadable")
    return words


def _segment_kind(p0, p1, lo, hi):
    c0, c1 = clipping.outcode([p0, p1], lo, hi)
    if c0 | c1 == 0:
        return "accept"
    if c0 & c1:
        return "reject"
    if c0 and c1:
        return "trick" if clipping.liang_barsky(p0, p1, lo, hi) is None else "crossing"
    return "half"


class CohenSutherlandDecision(_Listed):
    r"""Cohen-Sutherland's first test for a few segments: accept, reject or clip.

    With the outcodes :math:`c_0, c_1` of the end points: accept if :math:`c_0 \lor c_1 = 0`,
    reject if :math:`c_0 \land c_1 \ne 0`, clip otherwise, even when the segment turns out to
    miss the rectangle.

    Attributes: ``box_min``, ``box_max``, ``segments`` (shape (5, 2, 2)).

    Examples
    --------
    >>> ex = CohenSutherlandDecision(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(["accept"] * 5).status
    'wrong'
    """

    title = "Cohen-Sutherland: accept, reject or clip?"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        lo, hi = self.box_min, self.box_max
        wanted = ["accept", "reject", "half", "trick", "crossing"]
        found = {}
        while len(found) < len(wanted):
            p0 = _ints_between(rng, lo - 3, hi + 3)
            p1 = _ints_between(rng, lo - 3, hi + 3)
            if np.array_equal(p0, p1):
                continue
            c0, c1 = _quick_code(p0, lo, hi), _quick_code(p1, lo, hi)
            quick = "accept" if not c0 | c1 else "reject" if c0 & c1 else \
                "half" if not (c0 and c1) else "both out"
            if quick in found or (quick == "both out" and "trick" in found
                                  and "crossing" in found):
                continue
            kind = _segment_kind(p0, p1, lo, hi)
            if kind in ("half", "crossing"):        # clearly visible, not just touching
                q0, q1 = clipping.liang_barsky(p0, p1, lo, hi)
                if np.linalg.norm(q1 - q0) < 0.5:
                    continue
            if kind not in found and not self._touches_corner(p0, p1):
                found[kind] = (p0, p1)
        order = rng.permutation(len(wanted))
        self.segments = np.array([found[wanted[i]] for i in order])
        self._kinds = [wanted[i] for i in order]
        self.expected = [self._decision(k) for k in self._kinds]

    def _touches_corner(self, p0, p1):
        """Whether the segment's line passes within a hair of a corner (ambiguous by eye)."""
        d = p1 - p0
        for x in (self.box_min[0], self.box_max[0]):
            for y in (self.box_min[1], self.box_max[1]):
                if abs(d[0] * (y - p0[1]) - d[1] * (x - p0[0])) < 1e-9:
                    return True
        return False

    @staticmethod
    def _decision(kind):
        return {"accept": "accept", "reject": "reject"}.get(kind, "clip")

    def mistakes(self):
        both_outside = [k if k in ("accept", "reject", "half") else "reject"
                        for k in self._kinds]
        swapped = ["accept" if k != "reject" else "reject" for k in self._kinds]
        final = ["reject" if k == "trick" else self._decision(k) for k in self._kinds]
        return [
            Mistake([self._decision(k) if k != "half" else "clip" for k in both_outside], r"Both "
                    r"end points outside does not mean the segment is outside: it can cross the "
                    r"rectangle. The trivial reject needs both end points beyond the **same** "
                    r"side, $c_0 \land c_1 \ne 0$; otherwise the segment must be clipped.",
                    "both endpoints outside", numeric=False),
            Mistake(swapped, r"The tests are swapped. Accept when **no** bit is set in either "
                    r"code, $c_0 \lor c_1 = 0$; reject when some bit is set in **both**, "
                    r"$c_0 \land c_1 \ne 0$; anything else needs clipping.",
                    "and/or swapped", numeric=False),
            Mistake(final, r"You judged the segments by what is finally left of them. The first "
                    r"test only looks at the outcodes: a segment with $c_0 \land c_1 = 0$ goes to "
                    r"clipping even if it turns out to miss the rectangle (it is rejected later, "
                    r"after an intersection has been computed).",
                    "final result instead of the test", numeric=False),
        ]

    def separated(self, mistakes):
        values = [tuple(m.value) for m in mistakes] + [tuple(self.expected)]
        return len(set(values)) == len(values)

    def _check(self, answer):
        words = _read_decisions(answer, len(self.segments))
        if isinstance(words, Feedback):
            return words
        if words == self.expected:
            return Feedback("correct", "All five decisions are right.")
        for mistake in self._mistakes:
            if words == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        off = [i for i, (a, b) in enumerate(zip(words, self.expected)) if a != b]
        return Feedback("wrong", f"The decisions for the segments {off} (counted from 0) are "
                        r"off. Compute both outcodes; accept if $c_0 \lor c_1 = 0$, reject if "
                        r"$c_0 \land c_1 \ne 0$, clip otherwise.", "decisions differ")

    def statement(self):
        rows = "\n".join(rf"| {i} | ${_vec(a)}$ | ${_vec(b)}$ |"
                         for i, (a, b) in enumerate(self.segments))
        return (
            _clip_words(self) + ". For each segment, what does the first test of "
            r"Cohen-Sutherland decide: **trivially accept** it, **trivially reject** it, or "
            r"**clip** it (compute an intersection and test again)?" "\n\n"
            "| segment | $p_0$ | $p_1$ |\n|---|---|---|\n" + rows + "\n\n"
            r"**Answer:** a list of 5 words, each `'accept'`, `'reject'` or `'clip'`, in the "
            r"order of the segments." "\n\n" + data_note("box_min", "box_max", "segments"))


def _cut(p, q, axis, value):
    t = (value - p[axis]) / (q[axis] - p[axis])
    point = p + t * (q - p)
    point[axis] = value
    return point


def _read_segment(answer, dim):
    """A segment as a (2, dim) array, the string "rejected", or a Feedback."""
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, str):
        if answer.strip().lower() in ("rejected", "reject", "none", "outside", "empty"):
            return "rejected"
        return Feedback("invalid", "Give the segment as two points, or the string "
                        "`'rejected'` if nothing is left.", "unreadable")
    if isinstance(answer, (list, tuple)) and len(answer) == 0:
        return "rejected"
    value = read_floats(answer)
    if value is None or value.shape != (2, dim):
        return Feedback("invalid", f"Give the clipped segment as two points, "
                        f"`[[{', '.join('x y z'.split()[:dim])}], [...]]` (shape (2, {dim})).",
                        "unreadable")
    return value


def _segment_feedback(answer, expected, mistakes, dim, hint):
    """Judge a clipped segment (either end first) or 'rejected'; mistakes: Mistakes of either."""
    value = _read_segment(answer, dim)
    if isinstance(value, Feedback):
        return value
    if isinstance(value, str) and expected is None:
        return Feedback("correct", "Right: nothing of the segment is inside.")
    if not isinstance(value, str) and expected is not None and _same_segment(value, expected):
        return Feedback("correct", "The clipped segment is right.")
    for mistake in mistakes:
        wrong = mistake.value
        if isinstance(wrong, str) or wrong is None:
            if isinstance(value, str) and expected is not None:
                return Feedback("wrong", mistake.explanation, mistake.key)
        elif not isinstance(value, str) and _same_segment(value, wrong):
            return Feedback("wrong", mistake.explanation, mistake.key)
    if isinstance(value, str):
        return Feedback("wrong", "Part of this segment is inside the clip region, so something "
                        "is left. " + hint, "rejected a visible segment")
    if expected is None:
        return Feedback("wrong", "Nothing of this segment is inside the clip region: the "
                        "answer is `'rejected'`. " + hint, "kept an invisible segment")
    return Feedback("wrong", "The end points are not right yet. " + hint, "points differ")


class CohenSutherlandClip(_Listed):
    r"""The segment Cohen-Sutherland leaves of a segment with an end point in a corner region.

    An end point beyond two sides may need two intersections: the first one can still lie
    outside the rectangle.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``.

    Examples
    --------
    >>> ex = CohenSutherlandClip(seed=4)
    >>> q0, q1 = ex.expected
    >>> ex.check([q0, q1]).status, ex.check([q1, q0]).status
    ('correct', 'correct')
    >>> clamped = np.clip([ex.p0, ex.p1], ex.box_min, ex.box_max)
    >>> ex.check(clamped).diagnosis
    'clamped'
    """

    title = "Cohen-Sutherland: the clipped segment"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        lo, hi = self.box_min, self.box_max
        while True:                     # one end point in a corner region, not trivially rejected
            self.p0 = _ints_between(rng, lo - 3, hi + 3)
            self.p1 = _ints_between(rng, lo - 3, hi + 3)
            c0, c1 = _quick_code(self.p0, lo, hi), _quick_code(self.p1, lo, hi)
            if not c0 & c1 and max(bin(c0).count("1"), bin(c1).count("1")) == 2:
                break
        result, self._steps = clipping.cohen_sutherland_steps(self.p0, self.p1, lo, hi)
        self.expected = None if result is None else np.array(result)

    def _one_clip_each(self):
        lo, hi = self.box_min, self.box_max
        ends = []
        for p, q in ((self.p0, self.p1), (self.p1, self.p0)):
            code = clipping.outcode(p, lo, hi)
            if code:
                bit = (code & -code).bit_length() - 1
                p = _cut(p, q, bit // 2, (lo, hi)[bit % 2][bit // 2])
            ends.append(p)
        return np.array(ends)

    def acceptable(self):
        if self.expected is None or len(self._steps) < 3 \
                or np.linalg.norm(self.expected[1] - self.expected[0]) < 0.5:
            return False
        one_each = self._one_clip_each()
        return not _same_segment(one_each, self.expected)

    def mistakes(self):
        clamped = np.clip([self.p0, self.p1], self.box_min, self.box_max)
        return [
            Mistake(self._one_clip_each(), r"One end point needs a second intersection: after the "
                    r"first cut its new outcode is still not 0 (it is beyond another side). Repeat "
                    r"the test with the new outcodes until the segment is accepted or rejected.",
                    "one clip per endpoint", numeric=False),
            Mistake(clamped, r"You moved each end point onto the rectangle coordinate by "
                    r"coordinate (clamping). That changes the segment's direction: the new end "
                    r"points must lie on the **segment**, at its intersection with a side's line, "
                    r"$y = y_0 + (x_{side} - x_0)\,\frac{y_1 - y_0}{x_1 - x_0}$.",
                    "clamped", numeric=False),
            Mistake(np.array([self.p0, self.p1]), r"That is the segment you started with; part of "
                    r"it lies outside the rectangle and has to be cut off.",
                    "not clipped", numeric=False),
        ]

    def separated(self, mistakes):
        values = [m.value for m in mistakes] + [self.expected]
        return all(not _same_segment(a, b) for i, a in enumerate(values)
                   for b in values[i + 1:])

    def _check(self, answer):
        return _segment_feedback(answer, self.expected, self._mistakes, 2,
                                 "Cut at the side named by the lowest bit of an outside end "
                                 "point's code, then recompute the codes and test again.")

    def statement(self):
        return (
            _clip_words(self) + rf". Clip the segment from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$ with the Cohen-Sutherland algorithm. Which segment "
            r"remains?" "\n\n"
            r"**Answer:** the clipped segment as two points `[[x0, y0], [x1, y1]]` (either end "
            r"first). " + DECIMALS + "\n\n" + data_note("box_min", "box_max", "p0", "p1"))


class CohenSutherlandIntersections(DrawnExercise):
    r"""How many intersections Cohen-Sutherland computes for one segment.

    Each pass computes both outcodes; unless it accepts or rejects, it moves one outside end
    point (:math:`p_0` first while it is outside) to the side of its lowest set bit. The answer
    is the number of such moves.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``.

    Examples
    --------
    >>> ex = CohenSutherlandIntersections(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected + 1).diagnosis
    'counted the final test'
    """

    title = "Cohen-Sutherland: how many intersections?"
    answer_form = "number"
    what = "the number of intersections"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        lo, hi = self.box_min, self.box_max
        self.p0, self.p1 = (_corner_biased_point(rng, lo, hi) for _ in range(2))
        self._steps = [] if np.array_equal(self.p0, self.p1) else \
            clipping.cohen_sutherland_steps(self.p0, self.p1, lo, hi)[1]
        self.expected = float(sum(s["action"] == "clip" for s in self._steps))

    def acceptable(self):
        return self.expected >= 1 and self._steps[-1]["action"] in ("accept", "reject")

    def mistakes(self):
        c0, c1 = self._steps[0]["code0"], self._steps[0]["code1"]
        return [
            Mistake(self.expected + 1, r"You counted the passes of the loop, including the "
                    r"last one, which only tests (accepts or rejects) and computes no "
                    r"intersection.", "counted the final test"),
            Mistake(float(bool(c0)) + float(bool(c1)), r"It is not one intersection per "
                    r"outside end point: an end point in a corner region may need two (the "
                    r"first cut can land outside the rectangle, beyond the other side), and a "
                    r"segment can also be rejected after a cut.", "one per endpoint"),
            Mistake(float(bin(c0).count("1") + bin(c1).count("1")), r"It is not one "
                    r"intersection per set bit: after a cut the codes are computed afresh, and "
                    r"a cut can clear two bits at once (or the segment is rejected before every "
                    r"bit is used).", "one per bit"),
        ]

    def separated(self, mistakes):
        return bool(_distinct_only(self.expected, mistakes))

    def keep(self, mistakes):
        return _distinct_only(self.expected, mistakes)

    def _check(self, answer):
        fb = super()._check(answer)
        if fb.diagnosis == "value differs":
            fb = Feedback("wrong", r"Not that number. Follow the algorithm pass by pass: "
                          r"compute both outcodes; if $c_0 \lor c_1 = 0$ accept, if "
                          r"$c_0 \land c_1 \ne 0$ reject, otherwise cut once (and count it) and "
                          r"start the next pass with the new end point.", "value differs")
        return fb

    def statement(self):
        return (
            _clip_words(self) + rf". The segment from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$ is clipped with Cohen-Sutherland. In each pass the "
            r"algorithm computes both outcodes, then accepts, rejects, or replaces one outside "
            r"end point by an intersection with a side: $p_0$ while it is outside, otherwise "
            r"$p_1$, and the side of the **lowest** set bit (left, right, bottom, top in this "
            r"order). How many intersection points does it compute before it accepts or "
            r"rejects?" "\n\n" r"**Answer:** one whole number." "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))


def _corner_biased_point(rng, lo, hi):
    """A whole point that is often in a corner region (beyond two sides) of the rectangle."""
    point = []
    for low, high in zip(lo, hi):
        where = pick(rng, ("below", "inside", "above", "below", "above"))
        if where == "below":
            point.append(float(rng.integers(low - 3, low)))
        elif where == "above":
            point.append(float(rng.integers(high + 1, high + 4)))
        else:
            point.append(float(rng.integers(low, high + 1)))
    return np.array(point)


def _distinct_only(expected, mistakes):
    """The mistakes whose value differs from the answer; slips giving the same value are merged.

    Two slips that lead to the same wrong answer cannot be told apart, so the feedback for that
    answer explains both (under the key of the first).
    """
    kept = []
    for m in mistakes:
        if gap(m.value, expected) < APART - SAME:         # APART up to rounding is apart
            continue
        twin = next((k for k in kept if gap(k.value, m.value) < APART - SAME), None)
        if twin is None:
            kept.append(Mistake(m.value, m.explanation, m.key))
        else:
            twin.explanation = (f"Two slips lead to this number. {twin.explanation} Or: "
                                f"{m.explanation}")
    return kept
