"""Chapter 5 exercises: Cohen-Sutherland.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

from fractions import Fraction

import numpy as np

from ... import clipping
from ..core import (APART, DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked,
                    data_note, gap, latex_fraction, latex_vector, pick, read_floats)
from . import (ON_SIDE, THROUGH_CORNER, _Boundary, _boundary_segment, _box_words, _clip_words,
               _draw_box_2d, _Listed, _off_bound_point, _on_bound, _onto_bound,
               _quick_code, _same_segment, _segment_cases, _unanswered, _vec)

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


#: The sides named by the bits 0 to 5 of an outcode.
_SIDES = ("left", "right", "bottom", "top", "near", "far")


def _sides_of(code):
    """The names of the sides an outcode's bits stand for, lowest bit first."""
    return [side for k, side in enumerate(_SIDES) if int(code) >> k & 1]


def _code_words(code, dim):
    """An outcode as LaTeX-free words: ``1001 (left, top)`` or ``0000 (inside)``."""
    return f"{_bits(code, dim)} ({', '.join(_sides_of(code)) or 'inside'})"


def _code_by_hand(point, lo, hi):
    """The outcode of `point`, side by side (strict inequalities), and the reasons, as LaTeX.

    Returns (code, reasons, on): `reasons` names each side the point is beyond with the
    comparison that puts it there, `on` each side whose line the point lies on.
    """
    code, reasons, on = 0, [], []
    for k, axis in enumerate("xyz"[:len(point)]):
        v = float(point[k])
        if v < lo[k]:
            code += 1 << 2 * k
            reasons.append(rf"${axis} = {latex_fraction(v)} < {latex_fraction(lo[k])}$: "
                           rf"{_SIDES[2 * k]} ({1 << 2 * k})")
        elif v > hi[k]:
            code += 1 << 2 * k + 1
            reasons.append(rf"${axis} = {latex_fraction(v)} > {latex_fraction(hi[k])}$: "
                           rf"{_SIDES[2 * k + 1]} ({1 << 2 * k + 1})")
        if v == lo[k] or v == hi[k]:
            on.append(rf"${axis} = {latex_fraction(v)}$, on the {_SIDES[2 * k + (v == hi[k])]} "
                      r"side's " + ("line" if len(point) == 2 else "plane"))
    return code, reasons, on


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
        elif isinstance(item, (int, np.integer, float, np.floating)) \
                and not isinstance(item, (bool, np.bool_)):
            if not float(item).is_integer():
                return Feedback("invalid", f"{item!r} is not a whole number; give {form}.",
                                "unreadable")
            codes.append(int(item))
        else:
            return Feedback("invalid", f"Give {form}.", "unreadable")
    for code in codes:
        if not 0 <= code < 2 ** (2 * dim):
            return Feedback("wrong", f"{code} is no outcode: in {dim}D an outcode has "
                            f"{2 * dim} bits, a whole number from 0 to {2 ** (2 * dim) - 1} (the "
                            "sum of the values of the sides the point is beyond).",
                            "not an outcode")
    return codes


class Outcodes(_Boundary, _Listed):
    r"""The Cohen-Sutherland outcodes of a few points (2D rectangle or 3D box).

    Bit values: left 1, right 2, bottom 4, top 8 (near 16, far 32 in 3D); a point on the
    boundary is inside. The codes may be given as whole numbers (``9`` or ``9.0``) or as bit
    strings (``'1001'``).

    In about 15 % of the seeds one point lies on the line (plane) of a side, a coordinate equal
    to a bound, on purpose: ``boundary`` is then ``"point on a side"`` (else None), and no
    other variant has a point there.

    Attributes: ``dim``, ``box_min``, ``box_max``, ``points``, ``boundary``.

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
        points = [_off_bound_point(rng, self.box_min, self.box_max, 2) for _ in range(5)]
        if self._wanted:
            k = int(rng.integers(len(points)))
            points[k] = _onto_bound(rng, points[k], self.box_min, self.box_max)
        self.points = np.array(points)
        self.expected = [int(c) for c in clipping.outcode(self.points, self.box_min,
                                                          self.box_max)]

    def boundary_cases(self):
        return [ON_SIDE] if _on_bound(self.points, self.box_min, self.box_max) else []

    def _on_boundary(self):
        return [int(sum((p[k] == self.box_min[k]) << (2 * k) | (p[k] == self.box_max[k])
                        << (2 * k + 1) for k in range(self.dim))) for p in self.points]

    def acceptable(self):
        counts = [bin(c).count("1") for c in self.expected]
        z_bits = any(c >> 4 for c in self.expected)
        return (max(counts) >= 2 and 0 in self.expected and (self.dim == 2 or z_bits)
                and len(set(self.expected)) >= 4 and self.boundary_fits())

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
        first = off[0]
        wrong = codes[first] ^ self.expected[first]
        sides = ", ".join(_sides_of(wrong))
        return Feedback("wrong", f"The outcodes of the points {off} (counted from 0) are off; "
                        f"in that of point {first} the bits of {sides} are wrong. For each side "
                        "compare one coordinate with the box: a bit is set when the point is "
                        "strictly beyond that side.", "codes differ")

    def _bit_table(self):
        bits = ("left 1 ($x < x_{min}$), right 2 ($x > x_{max}$), bottom 4 ($y < y_{min}$), "
                "top 8 ($y > y_{max}$)")
        if self.dim == 3:
            bits += ", near 16 ($z < z_{min}$), far 32 ($z > z_{max}$)"
        return bits

    def hints(self):
        lo, hi = self.box_min, self.box_max
        code, reasons, on = _code_by_hand(self.points[0], lo, hi)
        last = (rf"Point 0, ${_vec(self.points[0])}$: "
                + ("; ".join(reasons) if reasons else "beyond no side") + rf", so its code is "
                rf"{code} (`'{_bits(code, self.dim)}'`).")
        if self.boundary:
            k = next(i for i, p in enumerate(self.points) if _code_by_hand(p, lo, hi)[2])
            where = _code_by_hand(self.points[k], lo, hi)[2][0]
            last += (rf" Note that point 0 has {where}, which is not beyond that side." if k == 0
                     else rf" Careful with point {k}: it has {where}.")
        return [
            r"An outcode has one bit per side of the clip region; a bit is set when the point "
            r"lies **strictly** beyond that side. Bit values: " + self._bit_table() + ".",
            r"For each point compare each coordinate with the two bounds of its axis and add "
            r"up the values of the sides the point is beyond. A coordinate equal to a bound is "
            r"not beyond it: a point on the boundary is inside.",
            last,
        ]

    def worked(self):
        lo, hi = self.box_min, self.box_max
        steps = [r"Bits: " + self._bit_table() + r"; a point on a side's line is not beyond "
                 r"it (strict inequalities)."]
        codes = []
        for i, p in enumerate(self.points):
            code, reasons, on = _code_by_hand(p, lo, hi)
            codes.append(code)
            text = rf"Point {i}, ${_vec(p)}$: " + ("; ".join(reasons) if reasons else
                                                   "beyond no side")
            if on:
                text += ("; " + "; ".join(on) + r", which counts as inside: no bit for that "
                         r"side (this is the boundary case)")
            steps.append(text + rf". Code ${code}$ = `'{_bits(code, self.dim)}'`.")
        return Worked(steps, codes)

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


class CohenSutherlandDecision(_Boundary, _Listed):
    r"""Cohen-Sutherland's first test for a few segments: accept, reject or clip.

    With the outcodes :math:`c_0, c_1` of the end points: accept if :math:`c_0 \lor c_1 = 0`,
    reject if :math:`c_0 \land c_1 \ne 0`, clip otherwise, even when the segment turns out to
    miss the rectangle. The five segments are one to accept, one to reject, one that misses
    the rectangle with its end points beyond different sides, one that crosses it with both
    end points outside, and one more (half inside, or another to accept or reject).

    In about 15 % of the seeds one end point lies on the line of a side on purpose
    (``boundary == "point on a side"``, else None); no other variant has one there.

    Attributes: ``box_min``, ``box_max``, ``segments`` (shape (5, 2, 2)), ``boundary``.

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
    #: How many random segments are tried for one of a kind before the variant is redrawn.
    TRIES = 400

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        kinds = ["accept", "reject", "trick", "crossing",
                 str(pick(rng, ("half", "half", "accept", "reject")))]
        on_side = int(rng.integers(len(kinds))) if self._wanted else None
        found = [self._segment_of_kind(rng, kind, k == on_side) for k, kind in enumerate(kinds)]
        if any(f is None for f in found):
            self.segments, self._kinds, self.expected = None, kinds, None
            return
        order = rng.permutation(len(kinds))
        self.segments = np.array([found[i] for i in order])
        self._kinds = [kinds[i] for i in order]
        self.expected = [self._decision(k) for k in self._kinds]

    def _segment_of_kind(self, rng, kind, on_side):
        """A segment of the kind wanted (none if TRIES draws find none); with `on_side` one of
        its end points lies on the line of a side, otherwise neither does."""
        lo, hi = self.box_min, self.box_max
        for _ in range(self.TRIES):
            p0 = _off_bound_point(rng, lo, hi, 3)
            p1 = _off_bound_point(rng, lo, hi, 3)
            if on_side:
                p0 = _onto_bound(rng, p0, lo, hi)
                if rng.random() < 0.5:
                    p0, p1 = p1, p0
            if np.array_equal(p0, p1) or self._touches_corner(p0, p1):
                continue
            if _segment_kind(p0, p1, lo, hi) != kind:
                continue
            if kind in ("half", "crossing"):        # clearly visible, not just touching
                q0, q1 = clipping.liang_barsky(p0, p1, lo, hi)
                if np.linalg.norm(q1 - q0) < 0.5:
                    continue
            return p0, p1
        return None

    def boundary_cases(self):
        return [ON_SIDE] if _on_bound(self.segments, self.box_min, self.box_max) else []

    def acceptable(self):
        return self.segments is not None and self.boundary_fits()

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

    def _codes(self):
        lo, hi = self.box_min, self.box_max
        return [(_code_by_hand(a, lo, hi), _code_by_hand(b, lo, hi)) for a, b in self.segments]

    def hints(self):
        listed = "; ".join(rf"segment {i}: `{_bits(c0, 2)}`, `{_bits(c1, 2)}`"
                           for i, ((c0, _, _), (c1, _, _)) in enumerate(self._codes()))
        return [
            r"The first test looks only at the outcodes $c_0, c_1$ of the two end points: "
            r"accept when $c_0 \lor c_1 = 0$ (both inside), reject when $c_0 \land c_1 \ne 0$ "
            r"(both beyond one and the same side), clip otherwise.",
            r"Compute both outcodes of each segment (left 1, right 2, bottom 4, top 8, each bit "
            r"set when the point is strictly beyond that side), then their bitwise OR and AND. "
            r"Both end points outside is not enough to reject.",
            rf"The outcodes $(c_0, c_1)$ are: {listed}.",
        ]

    def worked(self):
        steps = [_clip_words(self) + r". For each segment: the outcodes $c_0, c_1$; accept if "
                 r"$c_0 \lor c_1 = 0$, reject if $c_0 \land c_1 \ne 0$, otherwise clip."]
        decisions = []
        for i, ((c0, _, on0), (c1, _, on1)) in enumerate(self._codes()):
            either, both = c0 | c1, c0 & c1
            decision = "accept" if not either else "reject" if both else "clip"
            decisions.append(decision)
            text = (rf"Segment {i}: $c_0 = {_bits(c0, 2)}$, $c_1 = {_bits(c1, 2)}$; "
                    rf"$c_0 \lor c_1 = {_bits(either, 2)}$, $c_0 \land c_1 = {_bits(both, 2)}$: "
                    rf"**{decision}**.")
            for end, on in ((0, on0), (1, on1)):
                if on:
                    text += (rf" ($p_{end}$ has {on[0]}: it is not beyond that side, so that "
                             r"bit is 0; this is the boundary case.)")
            steps.append(text)
        return Worked(steps, decisions)

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


def _exact_enough(steps, lo, hi):
    """Whether every intersection of Cohen-Sutherland's steps is on a bound exactly or clearly
    off it.

    The steps are computed in floating point: a cut that should land exactly on a corner can
    come out a hair beyond the other side, and then one more (needless) cut follows. Variants
    where that could happen are not drawn, so the float steps are those of exact arithmetic.
    """
    for step in steps:
        point = step.get("new_point")
        if point is None:
            continue
        for k, v in enumerate(point):
            for bound in (lo[k], hi[k]):
                if v != bound and abs(v - bound) < 1e-9:
                    return False
    return True


def _frac_code(point, lo, hi):
    """The outcode of a point of fractions (strict inequalities)."""
    code = 0
    for k, v in enumerate(point):
        code |= (v < lo[k]) << 2 * k | (v > hi[k]) << 2 * k + 1
    return code


def _passes_by_hand(p0, p1, lo, hi):
    """Cohen-Sutherland worked by hand, in exact fractions: (the segment or None, the passes).

    Each pass is a dict: ``codes`` (c0, c1), ``action`` (accept, reject, clip) and, for a
    clip, ``end`` (the end point moved), ``side``, ``axis``, ``value`` (the side's line), ``t``
    (from the moved end point towards the other) and ``point`` (the intersection).
    """
    ends = [[Fraction(float(v)) for v in p0], [Fraction(float(v)) for v in p1]]
    lo = [Fraction(float(v)) for v in lo]
    hi = [Fraction(float(v)) for v in hi]
    passes = []
    while True:
        codes = (_frac_code(ends[0], lo, hi), _frac_code(ends[1], lo, hi))
        step = {"codes": codes}
        passes.append(step)
        if not codes[0] | codes[1]:
            step["action"] = "accept"
            return [list(e) for e in ends], passes
        if codes[0] & codes[1]:
            step["action"] = "reject"
            return None, passes
        end = 0 if codes[0] else 1
        bit = (codes[end] & -codes[end]).bit_length() - 1
        axis, value = bit // 2, (lo, hi)[bit % 2][bit // 2]
        a, b = ends[end], ends[1 - end]
        t = (value - a[axis]) / (b[axis] - a[axis])
        point = [x + t * (y - x) for x, y in zip(a, b)]
        step.update(action="clip", end=end, side=_SIDES[bit], axis=axis, value=value, t=t,
                    start=list(a), towards=list(b), point=point)
        ends[end] = point


def _paren(x):
    """A number as LaTeX, in parentheses when negative (after a minus sign)."""
    return f"({latex_fraction(float(x))})" if x < 0 else latex_fraction(float(x))


def _vec_exact(point):
    return latex_vector([float(v) for v in point])


def _worked_passes(ex):
    """``(ends, passes, steps)`` of a 2D Cohen-Sutherland exercise `ex`, worked by hand: the
    clipped ends, the passes, and the steps of a worked solution up to the last pass."""
    lo, hi = ex.box_min, ex.box_max
    ends, passes = _passes_by_hand(ex.p0, ex.p1, lo, hi)
    steps = [_clip_words(ex) + rf"; the segment runs from $p_0 = {_vec(ex.p0)}$ to "
             rf"$p_1 = {_vec(ex.p1)}$."]
    steps += _ends_on_side(ex.p0, ex.p1, lo, hi)
    steps += [_pass_words(k, step, lo, hi) for k, step in enumerate(passes, 1)]
    return ends, passes, steps


def _pass_words(k, step, lo, hi):
    """The text of one pass of :func:`_passes_by_hand`."""
    c0, c1 = step["codes"]
    head = (rf"Pass {k}: $c_0 = {_bits(c0, 2)}$, $c_1 = {_bits(c1, 2)}$")
    if step["action"] == "accept":
        return head + r": $c_0 \lor c_1 = 0$, **accept**."
    if step["action"] == "reject":
        return head + (rf": $c_0 \land c_1 = {_bits(c0 & c1, 2)} \ne 0$ (both beyond the "
                       rf"{', '.join(_sides_of(c0 & c1))} side), **reject**: nothing is left.")
    e, axis, a, b = step["end"], step["axis"], step["start"], step["towards"]
    name = "xy"[axis]
    text = (head + rf": neither test decides. $p_{e}$ is outside; the lowest bit of its code "
            rf"is {step['side']}: cut with ${name} = {latex_fraction(float(step['value']))}$, "
            rf"$t = \frac{{{latex_fraction(float(step['value']))} - {_paren(a[axis])}}}"
            rf"{{{latex_fraction(float(b[axis]))} - {_paren(a[axis])}}} = "
            rf"{latex_fraction(float(step['t']))}$, "
            rf"new $p_{e} = {_vec_exact(step['point'])}$ (1 intersection).")
    on = [k for k, v in enumerate(step["point"]) if v in (lo[k], hi[k])]
    if len(on) >= 2:
        text += (r" The cut lands exactly on a corner of the rectangle, on two sides at once; a "
                 r"point on the boundary is inside, so its code is 0 (this is the boundary "
                 r"case).")
    return text


def _ends_on_side(p0, p1, lo, hi):
    """Sentences for the end points that lie on the line of a side (the boundary case)."""
    out = []
    for e, p in ((0, p0), (1, p1)):
        _, _, on = _code_by_hand(p, lo, hi)
        if on:
            out.append(rf"$p_{e} = {_vec(p)}$ has {on[0]}: it is not beyond that side (the test "
                       r"is strict), so that bit is 0. This is the boundary case.")
    return out


class CohenSutherlandClip(_Boundary, _Listed):
    r"""The segment Cohen-Sutherland leaves of a segment with an end point in a corner region.

    An end point beyond two sides may need two intersections: the first one can still lie
    outside the rectangle.

    In about 15 % of the seeds the variant is a boundary case on purpose, named by
    ``boundary``: an end point on the line of a side (``"point on a side"``), or a segment
    through a corner of the rectangle (``"through a corner"``); None otherwise, and then there
    is neither.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``, ``boundary``.

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
            self.p0, self.p1 = _boundary_segment(rng, lo, hi, self._wanted)
            c0, c1 = _quick_code(self.p0, lo, hi), _quick_code(self.p1, lo, hi)
            if not c0 & c1 and max(bin(c0).count("1"), bin(c1).count("1")) == 2:
                break
        result, self._steps = clipping.cohen_sutherland_steps(self.p0, self.p1, lo, hi)
        self.expected = None if result is None else np.array(result)

    boundary_kinds = (ON_SIDE, THROUGH_CORNER)

    def boundary_cases(self):
        return [c for c in _segment_cases(self.p0, self.p1, self.box_min, self.box_max)
                if c in self.boundary_kinds]

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
        return (not _same_segment(one_each, self.expected) and self.boundary_fits()
                and _exact_enough(self._steps, self.box_min, self.box_max))

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

    def hints(self):
        lo, hi = self.box_min, self.box_max
        _, passes = _passes_by_hand(self.p0, self.p1, lo, hi)
        first = passes[0]
        return [
            r"Cohen-Sutherland repeats one pass until it can accept or reject: compute both "
            r"outcodes; accept if $c_0 \lor c_1 = 0$, reject if $c_0 \land c_1 \ne 0$; "
            r"otherwise replace an outside end point by the intersection with the side of the "
            r"lowest bit of its code.",
            r"The intersection with a side's line, e.g. $x = x_{side}$, lies at "
            r"$t = \frac{x_{side} - x_a}{x_b - x_a}$ from the moved end point $a$ towards the "
            r"other one $b$: $a + t\,(b - a)$. After each cut compute the new code again: an "
            r"end point in a corner region may need a second cut.",
            rf"First pass: $c_0 = {_bits(first['codes'][0], 2)}$, "
            rf"$c_1 = {_bits(first['codes'][1], 2)}$; the first cut is with the "
            rf"{first['side']} side and gives $p_{first['end']} = "
            rf"{_vec_exact(first['point'])}$. {len(passes) - 1} cuts in all.",
        ]

    def worked(self):
        ends, passes, steps = _worked_passes(self)
        answer = np.array([[float(v) for v in e] for e in ends])
        steps.append(rf"What remains runs from ${latex_vector(answer[0])}$ to "
                     rf"${latex_vector(answer[1])}$.")
        return Worked(steps, answer)

    def statement(self):
        return (
            _clip_words(self) + rf". Clip the segment from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$ with the Cohen-Sutherland algorithm. Which segment "
            r"remains?" "\n\n"
            r"**Answer:** the clipped segment as two points `[[x0, y0], [x1, y1]]` (either end "
            r"first). " + DECIMALS + "\n\n" + data_note("box_min", "box_max", "p0", "p1"))


class CohenSutherlandIntersections(_Boundary, DrawnExercise):
    r"""How many intersections Cohen-Sutherland computes for one segment.

    Each pass computes both outcodes; unless it accepts or rejects, it moves one outside end
    point (:math:`p_0` first while it is outside) to the side of its lowest set bit. The answer
    is the number of such moves, a whole number (1 to 4), compared exactly.

    In about 15 % of the seeds the variant is a boundary case on purpose, named by
    ``boundary``: an end point on the line of a side (``"point on a side"``), or a segment
    through a corner, where one cut clears two bits (``"through a corner"``); None otherwise.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``, ``boundary``.

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
    off_by_one = (r"Off by one: follow the passes again. Each pass that neither accepts nor "
                  r"rejects computes exactly one intersection; the last pass, which accepts or "
                  r"rejects, computes none.")

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        lo, hi = self.box_min, self.box_max
        self.p0, self.p1 = _boundary_segment(rng, lo, hi, self._wanted,
                                             point=lambda: _corner_biased_point(rng, lo, hi))
        self._steps = [] if np.array_equal(self.p0, self.p1) else \
            clipping.cohen_sutherland_steps(self.p0, self.p1, lo, hi)[1]
        self.expected = sum(s["action"] == "clip" for s in self._steps)
        # segments whose number of set bits tells nothing apart (it equals the answer, the
        # answer + 1 or the outside end points) are most of the random ones: keep only a share
        self._plain_kept = bool(rng.random() < self.PLAIN_SHARE)

    #: The share of the drawn segments kept although counting the bits would give the same
    #: number as the answer or as another slip.
    PLAIN_SHARE = 0.3

    def _telling(self):
        """Whether counting the set bits gives a wrong answer of its own (see mistakes)."""
        c0, c1 = self._steps[0]["code0"], self._steps[0]["code1"]
        bits = bin(c0).count("1") + bin(c1).count("1")
        return bits not in (self.expected, self.expected + 1, bool(c0) + bool(c1))

    boundary_kinds = (ON_SIDE, THROUGH_CORNER)

    def boundary_cases(self):
        return [c for c in _segment_cases(self.p0, self.p1, self.box_min, self.box_max)
                if c in self.boundary_kinds]

    def acceptable(self):
        return (self.expected >= 1 and self._steps[-1]["action"] in ("accept", "reject")
                and (self._plain_kept or self._telling())
                and _exact_enough(self._steps, self.box_min, self.box_max)
                and self.boundary_fits())

    def mistakes(self):
        c0, c1 = self._steps[0]["code0"], self._steps[0]["code1"]
        return [
            Mistake(self.expected + 1, r"You counted the passes of the loop, including the "
                    r"last one, which only tests (accepts or rejects) and computes no "
                    r"intersection.", "counted the final test"),
            Mistake(int(bool(c0)) + int(bool(c1)), r"It is not one intersection per "
                    r"outside end point: an end point in a corner region may need two (the "
                    r"first cut can land outside the rectangle, beyond the other side), and a "
                    r"segment can also be rejected after a cut.", "one per endpoint"),
            Mistake(bin(c0).count("1") + bin(c1).count("1"), r"It is not one "
                    r"intersection per set bit: after a cut the codes are computed afresh, and "
                    r"a cut can clear two bits at once (or the segment is rejected before every "
                    r"bit is used).", "one per bit"),
        ]

    def separated(self, mistakes):
        return bool(_distinct_only(self.expected, mistakes))

    def keep(self, mistakes):
        return _distinct_only(self.expected, mistakes)

    def _judge(self, answer):
        fb = super()._judge(answer)
        if fb.diagnosis == "value differs":
            fb = Feedback("wrong", r"Not that number. Follow the algorithm pass by pass: "
                          r"compute both outcodes; if $c_0 \lor c_1 = 0$ accept, if "
                          r"$c_0 \land c_1 \ne 0$ reject, otherwise cut once (and count it) and "
                          r"start the next pass with the new end point.", "value differs")
        return fb

    def hints(self):
        _, passes = _passes_by_hand(self.p0, self.p1, self.box_min, self.box_max)
        first = passes[0]
        return [
            r"Each pass of Cohen-Sutherland computes both outcodes and then accepts, rejects, "
            r"or computes **one** intersection (it moves one outside end point onto the line "
            r"of a side). Count the passes that cut.",
            r"Move $p_0$ while it is outside, otherwise $p_1$, to the side of the lowest set bit "
            r"of its code; compute the new code and start the next pass. Stop at accept "
            r"($c_0 \lor c_1 = 0$) or reject ($c_0 \land c_1 \ne 0$).",
            rf"First pass: $c_0 = {_bits(first['codes'][0], 2)}$, "
            rf"$c_1 = {_bits(first['codes'][1], 2)}$, so the first cut is with the "
            rf"{first['side']} side and moves $p_{first['end']}$ to "
            rf"${_vec_exact(first['point'])}$.",
        ]

    def worked(self):
        _, passes, steps = _worked_passes(self)
        cuts = sum(step["action"] == "clip" for step in passes)
        steps.append(rf"{len(passes)} passes, of which the last only tests: **{cuts}** "
                     r"intersections.")
        return Worked(steps, cuts)

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
    """A whole point that is often in a corner region (beyond two sides) of the rectangle, and
    never on the line of a side."""
    point = []
    for low, high in zip(lo, hi):
        where = pick(rng, ("below", "inside", "above", "below", "above"))
        if where == "below":
            point.append(float(rng.integers(low - 3, low)))
        elif where == "above":
            point.append(float(rng.integers(high + 1, high + 4)))
        else:                                           # strictly inside: no side's line
            point.append(float(rng.integers(low + 1, high)))
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
