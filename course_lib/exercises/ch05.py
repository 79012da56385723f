r"""Chapter 5 exercises: back-face culling, clipping and hidden-surface elimination, exam style.

Each class is one kind of exam question: the back-face test, Cohen-Sutherland outcodes, its
trivial accept/reject test, the clipped segment and the number of intersections it computes,
Liang-Barsky's :math:`p_k, q_k, t_k` table, its :math:`[t_{in}, t_{out}]` interval and the clipped
segment in 3D, Sutherland-Hodgman against one side and against a whole rectangle, the z-buffer on
a 4 x 4 grid, the painter's algorithm (its order, and where it goes wrong) and the cost of ray
casting with and without bounding volumes. The ``seed`` draws small whole numbers, so that every
intersection is a short fraction and every grid can be filled in by hand.

The clipping answers come from :mod:`course_lib.clipping`. The z-buffer, the painter's algorithm
and the ray counts are computed by the small closed-form functions of this module (barycentric
coordinates at pixel centres, a sort, a product), so that the exercises stand on their own.
Every exercise names the slips it anticipates (the compendium's sign in the back-face test, a
reversed bit order, entering and leaving swapped, a missing intersection vertex, a missing depth
test, ...) and draws its numbers again until each slip gives an answer of its own.

Conventions (those of :mod:`course_lib.clipping`): a point on the boundary of the clip region is
inside; outcode bits left = 1, right = 2, bottom = 4, top = 8, near = 16, far = 32; the back-face
test uses the view vector from the eye to the face.
"""
import math

import numpy as np

from .. import clipping
from .. import format as fmt
from .core import (APART, DECIMALS, SAME, UNANSWERED, DrawnExercise, Feedback, Mistake, data_note,
                   diagnose_matrix, diagnose_parts, gap, is_unanswered, parts_separated, pick,
                   read_floats, small_ints)

__all__ = [
    "EXERCISES",
    "BackFaceCulling",
    "CohenSutherlandClip",
    "CohenSutherlandDecision",
    "CohenSutherlandIntersections",
    "LiangBarskyClip3D",
    "LiangBarskyInterval",
    "LiangBarskyTable",
    "Outcodes",
    "PainterFailure",
    "PaintersOrder",
    "RayCastingCount",
    "SutherlandHodgmanArea",
    "SutherlandHodgmanOneSide",
    "ZBufferIds",
    "ZBufferWrites",
]


_vec = fmt.vector_latex
_num = fmt.number


# ---------------------------------------------------------------------------------------------
# Reading answers that are not plain arrays
# ---------------------------------------------------------------------------------------------

def _unanswered(answer):
    return is_unanswered(answer) or (isinstance(answer, (list, tuple))
                                     and any(a is Ellipsis for a in answer))


def _read_index_set(answer, n, what):
    """A set of indices in ``range(n)`` (or a boolean mask of length n), or a Feedback."""
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, (str, bytes, dict)):
        return Feedback("invalid", f"Give {what} as a list of whole numbers, e.g. `[0, 3]` "
                        "(`[]` if there are none).", "unreadable")
    try:
        items = list(answer)
    except TypeError:
        items = [answer]
    if items and len(items) == n and all(isinstance(v, (bool, np.bool_)) for v in items):
        return {i for i, v in enumerate(items) if v}
    found = set()
    for item in items:
        if isinstance(item, (bool, np.bool_)) or not isinstance(item, (int, np.integer, float,
                                                                      np.floating)):
            return Feedback("invalid", f"Give {what} as a list of whole numbers, e.g. `[0, 3]` "
                            "(`[]` if there are none).", "unreadable")
        if not float(item).is_integer() or not 0 <= item < n:
            return Feedback("invalid", f"{item!r} is not one of the indices 0 to {n - 1}.",
                            "unreadable")
        found.add(int(item))
    return found


def _names(indices):
    return ", ".join(str(i) for i in sorted(indices)) or "none"


def _set_feedback(answer, expected, mistakes, n, what, hint, right):
    """Judge a set of indices; `mistakes` are Mistakes with sets as values; `right` praises."""
    value = _read_index_set(answer, n, what)
    if isinstance(value, Feedback):
        return value
    if value == expected:
        return Feedback("correct", right)
    for mistake in mistakes:
        if value == mistake.value and mistake.value != expected:
            return Feedback("wrong", mistake.explanation, mistake.key)
    missing, extra = sorted(expected - value), sorted(value - expected)
    parts = []
    if extra:
        parts.append(f"{_names(extra)} should not be in your list")
    if missing:
        parts.append(f"{_names(missing)} {'is' if len(missing) == 1 else 'are'} missing")
    return Feedback("wrong", f"Not quite: {' and '.join(parts)}. {hint}", "indices differ")


def _cyclic_match(a, b, atol=2e-3):
    """Whether the vertex lists `a` and `b` are the same cycle (any starting vertex)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return False
    return any(np.allclose(np.roll(a, s, axis=0), b, rtol=1e-3, atol=atol)
               for s in range(len(a)))


def _cross2(a, b):
    """The z component of the cross product of 2D vectors (broadcasting)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _shoelace(polygon):
    p = np.asarray(polygon, dtype=float)
    if len(p) < 3:
        return 0.0
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(float(x @ np.roll(y, -1) - y @ np.roll(x, -1)))


def _box_words(lo, hi):
    axes = "xyz"
    return ", ".join(rf"${_num(a)} \le {axes[k]} \le {_num(b)}$"
                     for k, (a, b) in enumerate(zip(lo, hi)))


def _ints_between(rng, low, high, size=None):
    """Whole numbers from `low` to `high` inclusive (bounds may be float arrays), as floats."""
    low = np.asarray(low).astype(int)
    high = np.asarray(high).astype(int)
    return rng.integers(low, high + 1, size=size).astype(float)


def _quick_code(p, lo, hi):
    """The outcode of one point in plain Python: for the fast pre-selection of variants only."""
    code = 0
    for k in range(len(p)):
        code |= (1 << 2 * k) * (p[k] < lo[k]) | (1 << 2 * k + 1) * (p[k] > hi[k])
    return code


def _draw_box_2d(rng):
    lo = np.array([float(rng.integers(-2, 2)), float(rng.integers(-2, 2))])
    hi = lo + np.array([float(pick(rng, (4, 5, 6))), float(pick(rng, (3, 4, 5)))])
    return lo, hi


def _clip_words(ex):
    return rf"The clip rectangle is {_box_words(ex.box_min, ex.box_max)}"


class _Listed(DrawnExercise):
    """An exercise whose answer is a list, a set or a segment rather than an array.

    Its ``mistakes()`` are Mistakes with ``numeric=False`` (their values are sets, lists,
    segments or ``"rejected"``); those equal to the right answer in this variant are dropped.
    """

    answer_form = "custom"

    def keep(self, mistakes):
        return [m for m in mistakes if not _equal_answers(m.value, self.expected)]


def _equal_answers(a, b):
    """Whether two answers of a listed exercise are the same (sets, lists, segments, None).

    A segment rejected as a whole is None, or the word ``"rejected"`` a student types.
    """
    a, b = (None if isinstance(x, str) else x for x in (a, b))
    if isinstance(a, np.ndarray) and isinstance(b, np.ndarray):
        return _same_segment(a, b)
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return False
    return a == b


# ---------------------------------------------------------------------------------------------
# Back-face culling
# ---------------------------------------------------------------------------------------------

class BackFaceCulling(_Listed):
    r"""Which faces does back-face culling remove, seen from an eye in perspective?

    Face :math:`i` (a point :math:`P_i` and an outward normal :math:`n_i`) is a back face when
    :math:`n_i \cdot (P_i - E) \ge 0`: the view vector runs from the eye to the face and differs
    from face to face in a perspective view.

    Attributes: ``eye``, ``gaze``, ``points``, ``normals``.

    Examples
    --------
    >>> ex = BackFaceCulling(seed=1)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> front = set(range(len(ex.points))) - ex.expected
    >>> ex.check(sorted(front)).diagnosis
    'compendium sign'
    >>> ex.check(...).status, ex.check("all").status
    ('unanswered', 'invalid')
    """

    title = "Back-face culling in perspective"
    answer_form = "custom"

    def draw(self, rng):
        while True:
            self.eye = rng.integers(-5, 6, size=3).astype(float)
            if np.linalg.norm(self.eye) >= 4:
                break
        self.gaze = -self.eye
        self.points = rng.integers(-2, 3, size=(5, 3)).astype(float)
        self.normals = np.array([small_ints(rng, 3, -1, 1) for _ in range(5)])
        self._dots = np.einsum("ij,ij->i", self.normals, self.points - self.eye)
        mask = clipping.is_back_face(self.normals, self.points - self.eye)
        self.expected = {int(i) for i in np.flatnonzero(mask)}

    def _constant(self):
        return {int(i) for i in np.flatnonzero(self.normals @ self.gaze >= 0)}

    def acceptable(self):
        everything = set(range(len(self.points)))
        front = everything - self.expected
        constant = self._constant()
        return (np.all(self._dots != 0) and 0 < len(self.expected) < len(self.points)
                and np.all(self.normals @ self.gaze != 0)
                and constant != self.expected and constant != front)

    def mistakes(self):
        front = set(range(len(self.points))) - self.expected
        return [
            Mistake(front, r"You kept the back faces and culled the front ones. With the view "
                    r"vector $v = P - E$ pointing **from the eye to the face**, a face turns its "
                    r"back when $n \cdot v \ge 0$ (the normal points away from the eye). The "
                    r"compendium's $v \cdot n < 0$ holds for a view vector pointing from the face "
                    r"to the eye.", "compendium sign", numeric=False),
            Mistake(self._constant(), r"You used the same view vector (the gaze direction) for "
                    r"every face, which is right for a parallel projection only. In perspective "
                    r"the view vector runs from the eye to each face, $v_i = P_i - E$, and faces "
                    r"near the edge of the view can flip.",
                    "constant view direction", numeric=False),
        ]

    def separated(self, mistakes):
        return True

    def _check(self, answer):
        return _set_feedback(answer, self.expected, self._mistakes, len(self.points),
                             "the back faces",
                             r"For each face compute $n_i \cdot (P_i - E)$; the back faces are "
                             r"those where it is $\ge 0$.",
                             "Exactly these faces turn their backs to the eye.")

    def statement(self):
        rows = "\n".join(rf"| {i} | ${_vec(p)}$ | ${_vec(n)}$ |"
                         for i, (p, n) in enumerate(zip(self.points, self.normals)))
        return (
            rf"A perspective camera at the eye $E = {_vec(self.eye)}$ looks towards the origin "
            rf"(gaze direction $g = {_vec(self.gaze)}$) at a closed, opaque mesh. Five of its "
            r"faces are given by a point $P_i$ on the face and the face's outward normal "
            r"$n_i$:" "\n\n| face | point $P_i$ | outward normal $n_i$ |\n|---|---|---|\n"
            + rows + "\n\n"
            r"Which of these faces does back-face culling remove?" "\n\n"
            r"**Answer:** the list of the indices of the back faces, e.g. `[0, 3]` (`[]` if "
            r"there are none; the order does not matter)." "\n\n"
            + data_note("eye", "gaze", "points", "normals"))


# ---------------------------------------------------------------------------------------------
# Cohen-Sutherland
# ---------------------------------------------------------------------------------------------

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


def _same_segment(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return bool(np.allclose(a, b, rtol=1e-3, atol=2e-3)
                or np.allclose(a[::-1], b, rtol=1e-3, atol=2e-3))


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


# ---------------------------------------------------------------------------------------------
# Liang-Barsky
# ---------------------------------------------------------------------------------------------

_SIDES_2D = ("left", "right", "bottom", "top")


def _lb_table(p0, p1, lo, hi):
    """Rows (p_k, q_k, t_k) for the sides in the order left, right, bottom, top (near, far)."""
    _, steps = clipping.liang_barsky_steps(p0, p1, lo, hi)
    rows = [[s["p"], s["q"], math.nan if s["t"] is None else s["t"]] for s in steps]
    delta = np.asarray(p1, float) - p0
    for bit in range(len(rows), 2 * len(lo)):   # the sides after an early rejection
        axis = bit // 2
        p = -delta[axis] if bit % 2 == 0 else delta[axis]
        q = p0[axis] - lo[axis] if bit % 2 == 0 else hi[axis] - p0[axis]
        rows.append([p, q, q / p if p else math.nan])
    return np.array(rows)


def _lb_interval(table, swap=False, clamp=True, pick=(max, min)):
    """(t_in, t_out) from a (p, q, t) table; `swap` exchanges entering and leaving."""
    entering = [t for p, q, t in table if (p < 0) != swap and p != 0]
    leaving = [t for p, q, t in table if (p > 0) != swap and p != 0]
    first, second = pick
    t_in = first(entering) if entering else 0.0
    t_out = second(leaving) if leaving else 1.0
    if clamp:
        t_in, t_out = max(0.0, t_in), min(1.0, t_out)
    return t_in, t_out


def _draw_lb_segment(rng, lo, hi):
    while True:
        p0 = _ints_between(rng, lo - 3, hi + 3)
        p1 = _ints_between(rng, lo - 3, hi + 3)
        if np.all(p0 != p1):
            return p0, p1


class LiangBarskyTable(DrawnExercise):
    r"""Liang-Barsky's :math:`p_k`, :math:`q_k` and :math:`t_k = q_k / p_k` for the four sides.

    With :math:`\Delta = p_1 - p_0`: left :math:`(-\Delta x,\ x_0 - x_{min})`, right
    :math:`(\Delta x,\ x_{max} - x_0)`, bottom :math:`(-\Delta y,\ y_0 - y_{min})`, top
    :math:`(\Delta y,\ y_{max} - y_0)`.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``.

    Examples
    --------
    >>> ex = LiangBarskyTable(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected * [-1, 1, -1]).diagnosis
    'sign of p'
    """

    title = "Liang-Barsky: the table of p, q and t"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        self.p0, self.p1 = _draw_lb_segment(rng, self.box_min, self.box_max)
        self.expected = _lb_table(self.p0, self.p1, self.box_min, self.box_max)

    def mistakes(self):
        e = self.expected
        return [
            Mistake(e * [-1, 1, -1], r"The signs of $p_k$ are the wrong way round. Inside means "
                    r"$p_k\,t \le q_k$ for every side; for the left side "
                    r"$x_0 + t\,\Delta x \ge x_{min}$ becomes $-\Delta x\,t \le x_0 - x_{min}$, "
                    r"so $p_{left} = -\Delta x$ and $p_{right} = +\Delta x$. The sign of $p_k$ "
                    r"then says whether the line enters ($p_k < 0$) or leaves ($p_k > 0$).",
                    "sign of p"),
            Mistake(e * [1, -1, -1], r"The signs of $q_k$ are the wrong way round: $q_k$ is "
                    r"the distance of $p_0$ from the side, positive when $p_0$ is on the inside: "
                    r"$q_{left} = x_0 - x_{min}$, $q_{right} = x_{max} - x_0$.", "sign of q"),
            Mistake(e * [-1, -1, 1], r"Both $p_k$ and $q_k$ have the wrong sign (the $t_k$ "
                    r"happen to be right). Write each side as $p_k\,t \le q_k$ with the inside "
                    r"on the $\le$ side: $p_{left} = -\Delta x$, $q_{left} = x_0 - x_{min}$. "
                    r"With the signs flipped, entering and leaving would be confused.",
                    "p and q negated"),
        ]

    def _check(self, answer):
        if _unanswered(answer):
            return Feedback("unanswered", UNANSWERED)
        value = read_floats(answer)
        if value is None or value.shape != (4, 3):
            return Feedback("invalid", "Give a 4 x 3 array: one row per side (left, right, "
                            "bottom, top), the columns p, q, t.", "unreadable")
        fb = diagnose_matrix(value, self.expected, self._mistakes, what="the table",
                             transform=False)
        if fb.diagnosis not in ("sign", "entries differ"):
            return fb
        off = ~np.isclose(value, self.expected, rtol=1e-3, atol=2e-3)
        cells = ", ".join(f"{'pqt'[j]} of {_SIDES_2D[i]}" for i, j in np.argwhere(off))
        lead = ("Right sizes, but these entries have the wrong sign:" if fb.diagnosis == "sign"
                else "These entries are off:")
        return Feedback("wrong", rf"{lead} {cells}. Each side reads $p_k\,t \le q_k$; "
                        r"$t_k = q_k / p_k$.", fb.diagnosis)

    def statement(self):
        return (
            _clip_words(self) + rf". The segment runs from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$, $p(t) = p_0 + t\,(p_1 - p_0)$. For Liang-Barsky, write "
            r"each side as $p_k\,t \le q_k$ (inside on the $\le$ side) and give $p_k$, $q_k$ "
            r"and $t_k = q_k / p_k$ for the four sides." "\n\n"
            r"**Answer:** a $4 \times 3$ numpy array, rows in the order left, right, bottom, "
            r"top; columns $p_k$, $q_k$, $t_k$. " + DECIMALS + "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))


class LiangBarskyInterval(DrawnExercise):
    r"""Liang-Barsky's :math:`t_{in}` and :math:`t_{out}` for a segment that stays visible.

    :math:`t_{in} = \max(0, t_k \text{ for } p_k < 0)`,
    :math:`t_{out} = \min(1, t_k \text{ for } p_k > 0)`.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``.

    Examples
    --------
    >>> ex = LiangBarskyInterval(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).status
    'wrong'
    """

    title = "Liang-Barsky: entering and leaving"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        self.p0, self.p1 = _draw_lb_segment(rng, self.box_min, self.box_max)
        self._table = _lb_table(self.p0, self.p1, self.box_min, self.box_max)
        self.expected = np.array(_lb_interval(self._table))

    def acceptable(self):
        t_in, t_out = self.expected
        return t_out - t_in > 0.05 and (t_in > 0 or t_out < 1)

    def _variants(self):
        return {
            "entering/leaving swapped": (_lb_interval(self._table, swap=True),
                                         r"Entering and leaving are swapped. Where $p_k < 0$ "
                                         r"the line goes from outside to inside that side "
                                         r"(entering: raise $t_{in}$); where $p_k > 0$ it goes "
                                         r"out (leaving: lower $t_{out}$)."),
            "not clamped": (_lb_interval(self._table, clamp=False), r"Start from "
                            r"$[t_{in}, t_{out}] = [0, 1]$: the segment ends at $t = 0$ and "
                            r"$t = 1$, so a crossing outside that range does not count, "
                            r"$t_{in} = \max(0, \dots)$ and $t_{out} = \min(1, \dots)$."),
            "min and max swapped": (_lb_interval(self._table, pick=(min, max)), r"The segment "
                                    r"is inside only after it has entered **every** side, so "
                                    r"$t_{in}$ is the **largest** entering $t_k$, and it must "
                                    r"leave at the first leaving crossing, so $t_{out}$ is the "
                                    r"**smallest** leaving $t_k$."),
        }

    def _parts(self):
        variants = self._variants()
        return [(name, float(self.expected[i]),
                 [Mistake(v[i], text, key) for key, (v, text) in variants.items()
                  if abs(v[i] - self.expected[i]) > SAME])
                for i, name in enumerate((r"$t_{in}$", r"$t_{out}$"))]

    def mistakes(self):
        return [Mistake(v, text, key) for key, (v, text) in self._variants().items()]

    def separated(self, mistakes):
        return parts_separated(self._parts(), same=None)

    def _check(self, answer):
        return diagnose_parts(answer, self._parts(), "your interval", "`[t_in, t_out]`.",
                              r"Tabulate $p_k$, $q_k$, $t_k = q_k / p_k$ for the four sides; "
                              r"$t_{in}$ is the largest of 0 and the entering $t_k$ "
                              r"($p_k < 0$), $t_{out}$ the smallest of 1 and the leaving ones.")

    def statement(self):
        return (
            _clip_words(self) + rf". Clip the segment from $p_0 = {_vec(self.p0)}$ to "
            rf"$p_1 = {_vec(self.p1)}$, $p(t) = p_0 + t\,(p_1 - p_0)$ with $0 \le t \le 1$, "
            r"with Liang-Barsky: what are $t_{in}$ and $t_{out}$ after all four sides? (Part "
            r"of this segment is visible.)" "\n\n"
            r"**Answer:** a list of 2 numbers `[t_in, t_out]`. " + DECIMALS + "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))


class LiangBarskyClip3D(_Listed):
    r"""Liang-Barsky in 3D: the clipped segment, or ``'rejected'``.

    Attributes: ``box_min``, ``box_max``, ``p0``, ``p1``.

    Examples
    --------
    >>> ex = LiangBarskyClip3D(seed=8)
    >>> answer = "rejected" if ex.expected is None else ex.expected
    >>> ex.check(answer).status
    'correct'
    """

    title = "Liang-Barsky in 3D"
    answer_form = "custom"

    def draw(self, rng):
        self._want_rejected = bool(rng.random() < 0.3)
        self.box_min = rng.integers(-2, 1, size=3).astype(float)
        self.box_max = self.box_min + float(pick(rng, (2, 4)))
        while True:
            self.p0 = _ints_between(rng, self.box_min - 2, self.box_max + 2)
            self.p1 = _ints_between(rng, self.box_min - 2, self.box_max + 2)
            if np.count_nonzero(self.p1 - self.p0) >= 2:
                break
        result = clipping.liang_barsky(self.p0, self.p1, self.box_min, self.box_max)
        self.expected = None if result is None else np.array(result)
        codes = clipping.outcode([self.p0, self.p1], self.box_min, self.box_max)
        self._trivial = bool(codes[0] & codes[1]) or not (codes[0] | codes[1])
        self._table = _lb_table(self.p0, self.p1, self.box_min, self.box_max)

    def _segment(self, t_in, t_out):
        """The segment from t_in to t_out, or "rejected" when the interval is empty."""
        if t_in > t_out + 1e-12:
            return "rejected"
        return np.array([self.p0 + t_in * (self.p1 - self.p0),
                         self.p0 + t_out * (self.p1 - self.p0)])

    def _parallel_outside(self):
        return any(p == 0 and q < 0 for p, q, _ in self._table)

    def acceptable(self):
        if self._trivial or (self.expected is None) != self._want_rejected:
            return False
        return self.expected is None or not _same_segment(self.expected[0], self.expected[1])

    def mistakes(self):
        swapped = "rejected" if self._parallel_outside() else \
            self._segment(*_lb_interval(self._table, swap=True))
        unclamped = "rejected" if self._parallel_outside() else \
            self._segment(*_lb_interval(self._table, clamp=False))
        t_in, t_out = _lb_interval(self._table)
        unchecked = np.array([self.p0 + t_in * (self.p1 - self.p0),
                              self.p0 + t_out * (self.p1 - self.p0)])
        return [
            Mistake(unchecked, r"Nothing of this segment is inside: check the interval before you "
                    r"compute points. When $t_{in} > t_{out}$ (the segment leaves some side before "
                    r"it has entered all the others), or when a side parallel to the segment has "
                    r"$p_k = 0$ and $q_k < 0$, the segment is rejected.",
                    "empty interval not noticed", numeric=False),
            Mistake(swapped, r"Entering and leaving are swapped: a side with $p_k < 0$ is entered "
                    r"(it raises $t_{in}$), one with $p_k > 0$ is left (it lowers $t_{out}$). In "
                    r"3D there are six sides; $p_k$ and $q_k$ for near and far are built from $z$ "
                    r"like those for left and right from $x$.",
                    "entering/leaving swapped", numeric=False),
            Mistake(unclamped, r"The end points lie beyond the original segment: start from "
                    r"$[t_{in}, t_{out}] = [0, 1]$, so that crossings before $p_0$ or after $p_1$ "
                    r"do not count.", "not clamped", numeric=False),
        ]

    def separated(self, mistakes):
        live = [m.value for m in mistakes if not _equal_answers(m.value, self.expected)]
        return bool(live) and all(not _equal_answers(a, b) for i, a in enumerate(live)
                                  for b in live[i + 1:])

    def _check(self, answer):
        return _segment_feedback(answer, self.expected, self._mistakes, 3,
                                 r"Per side: $p_k$, $q_k$, $t_k = q_k / p_k$; "
                                 r"$t_{in} = \max(0, t_k : p_k < 0)$, "
                                 r"$t_{out} = \min(1, t_k : p_k > 0)$; the segment is rejected "
                                 r"if $t_{in} > t_{out}$.")

    def statement(self):
        return (
            rf"The clip box is {_box_words(self.box_min, self.box_max)}. Clip the segment from "
            rf"$p_0 = {_vec(self.p0)}$ to $p_1 = {_vec(self.p1)}$ with the 3D Liang-Barsky "
            r"algorithm (six sides: left, right, bottom, top, near $z \ge z_{min}$, far "
            r"$z \le z_{max}$). What is left of it?" "\n\n"
            r"**Answer:** the clipped segment as two points `[[x0, y0, z0], [x1, y1, z1]]` "
            r"(the end nearer $p_0$ first, though either order is accepted), or the string "
            r"`'rejected'` if nothing is inside. " + DECIMALS + "\n\n"
            + data_note("box_min", "box_max", "p0", "p1"))


# ---------------------------------------------------------------------------------------------
# Sutherland-Hodgman
# ---------------------------------------------------------------------------------------------

#: For each side: the coordinate it bounds and whether the inside is below (<=) the value.
_SIDE_PLANES = {"left": (0, False), "right": (0, True), "bottom": (1, False), "top": (1, True)}


def _side_plane(side, value):
    axis, upper = _SIDE_PLANES[side]
    normal = np.zeros(2)
    normal[axis] = 1.0 if upper else -1.0
    return normal, (value if upper else -value)


def _read_polygon(answer):
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    value = read_floats(answer)
    if value is None or value.ndim != 2 or value.shape[1] != 2:
        return Feedback("invalid", "Give the polygon as a list of points `[[x, y], ...]`.",
                        "unreadable")
    return value


_CONVEX_SHAPES = (
    ((0, 0), (4, 0), (2, 4)), ((0, 0), (4, 1), (1, 4)), ((0, 0), (5, 2), (2, 4)),
    ((0, 0), (4, 0), (4, 3), (0, 3)), ((0, 0), (3, -1), (5, 2), (1, 4)),
    ((0, 0), (4, 2), (2, 5), (-1, 3)),
)


class SutherlandHodgmanOneSide(DrawnExercise):
    r"""Clip a polygon by one side of the clip rectangle with Sutherland-Hodgman's four rules.

    For each edge :math:`S \to E` (in order, the last back to the first): in-in gives E, in-out
    gives the intersection I, out-in gives I then E, out-out gives nothing.

    Attributes: ``polygon``, ``side``, ``value``.

    Examples
    --------
    >>> ex = SutherlandHodgmanOneSide(seed=9)
    >>> ex.check(ex.expected).status, ex.check(np.roll(ex.expected, 1, axis=0)).status
    ('correct', 'correct')
    >>> ex.check(ex.expected[::-1]).diagnosis
    'reversed order'
    """

    title = "Sutherland-Hodgman against one side"
    answer_form = "custom"

    def draw(self, rng):
        shape = np.array(pick(rng, _CONVEX_SHAPES), dtype=float)
        if rng.random() < 0.5:
            shape = shape * [-1, 1]
            shape = shape[::-1]                         # keep it counter-clockwise
        shape = np.roll(shape, int(rng.integers(len(shape))), axis=0)
        self.polygon = shape + rng.integers(-2, 3, size=2)
        self.side = str(pick(rng, tuple(_SIDE_PLANES)))
        axis = _SIDE_PLANES[self.side][0]
        low, high = self.polygon[:, axis].min(), self.polygon[:, axis].max()
        self.value = float(rng.integers(int(low), int(high) + 1))
        self.expected = clipping.clip_polygon(self.polygon, [_side_plane(self.side, self.value)])

    def _inside(self):
        axis, upper = _SIDE_PLANES[self.side]
        return self.polygon[:, axis] <= self.value if upper else \
            self.polygon[:, axis] >= self.value

    def acceptable(self):
        axis = _SIDE_PLANES[self.side][0]
        inside = self._inside()
        return (not np.any(self.polygon[:, axis] == self.value) and inside.any()
                and not inside.all())

    def _intersections(self):
        """Indices in `expected` of the intersection points (not vertices of the polygon)."""
        return [i for i, p in enumerate(self.expected)
                if not np.any(np.all(np.isclose(self.polygon, p), axis=1))]

    def mistakes(self):
        found = []
        for i in self._intersections():
            found.append(Mistake(np.delete(self.expected, i, axis=0), r"An intersection "
                                 r"vertex is missing. Each edge that crosses the boundary "
                                 r"contributes its intersection point I: an edge going out "
                                 r"(in $\to$ out) outputs I, an edge coming back in "
                                 r"(out $\to$ in) outputs I and then E.",
                                 "missing intersection vertex"))
        found.append(Mistake(self.expected[::-1], r"Your vertices run the other way round. "
                             r"Keep the polygon's orientation: go through the edges "
                             r"$v_0 \to v_1$, $v_1 \to v_2$, ... in order and append the "
                             r"output of each edge.", "reversed order"))
        axis, upper = _SIDE_PLANES[self.side]
        normal, offset = _side_plane(self.side, self.value)
        found.append(Mistake(clipping.clip_polygon(self.polygon, [(-normal, -offset)]),
                             r"You kept the part **outside** the clip rectangle. The inside of "
                             r"the " + self.side + r" side is $" + "xy"[axis]
                             + (r" \le " if upper else r" \ge ") + _num(self.value) + "$.",
                             "kept the outside part"))
        k = len(self.expected)
        for i in self._intersections():
            after = (i + 1) % k
            if not any(np.allclose(self.expected[after], q) for q in self.polygon):
                continue
            prev_out = not self._inside()[self._index_of(self.expected[after]) - 1]
            if prev_out:                                # I then E from an out -> in edge
                swapped = self.expected.copy()
                swapped[[i, after]] = swapped[[after, i]]
                found.append(Mistake(swapped, r"For an edge coming back in (S outside, E "
                                     r"inside) the output is first the intersection I, then "
                                     r"E: the polygon follows the boundary to I before it "
                                     r"reaches E.", "out-in order"))
        return found

    def _index_of(self, point):
        return int(np.flatnonzero(np.all(np.isclose(self.polygon, point), axis=1))[0])

    def separated(self, mistakes):
        values = [m.value for m in mistakes]
        if any(_cyclic_match(v, self.expected) for v in values):
            return False
        return all(not _cyclic_match(a.value, b.value) for i, a in enumerate(mistakes)
                   for b in mistakes[i + 1:] if a.key != b.key)

    def _check(self, answer):
        value = _read_polygon(answer)
        if isinstance(value, Feedback):
            return value
        if _cyclic_match(value, self.expected):
            return Feedback("correct", "The clipped polygon is right (the starting vertex does "
                            "not matter).")
        for mistake in self._mistakes:
            if _cyclic_match(value, mistake.value):
                return Feedback("wrong", mistake.explanation, mistake.key)
        if len(value) != len(self.expected):
            return Feedback("wrong", f"Your polygon has {len(value)} vertices; the clipped one "
                            f"has {len(self.expected)}. Go through every edge and apply the four "
                            "rules (in-in: E; in-out: I; out-in: I, E; out-out: nothing).",
                            "vertex count differs")
        return Feedback("wrong", "The vertices are not right yet. Apply the four rules to every "
                        "edge in order, including the closing edge from the last vertex back to "
                        "the first.", "vertices differ")

    def statement(self):
        axis, upper = _SIDE_PLANES[self.side]
        relation = r"\le" if upper else r"\ge"
        rule = f"${'xy'[axis]} {relation} {_num(self.value)}$"
        return (
            r"The polygon with the vertices (in this order, counter-clockwise) "
            + ", ".join(rf"$v_{i} = {_vec(p)}$" for i, p in enumerate(self.polygon))
            + rf" is clipped against the **{self.side}** side of the clip rectangle only, "
            rf"whose inside is {rule}. Run Sutherland-Hodgman: for the edges "
            r"$v_0 \to v_1$, $v_1 \to v_2$, ..., and finally the closing edge back to $v_0$, "
            r"output the vertices given by the four rules (in-in: E; in-out: I; out-in: I then "
            r"E; out-out: nothing)." "\n\n"
            r"**Answer:** the output vertices in order, as a list of points `[[x, y], ...]`. "
            r"Any starting vertex is accepted, but the order around the polygon matters. "
            + DECIMALS + "\n\n" + data_note("polygon", "side", "value"))


class SutherlandHodgmanArea(DrawnExercise):
    r"""The vertex count and area of a triangle clipped to a rectangle (a corner is cut in).

    Attributes: ``triangle``, ``box_min``, ``box_max``.

    Examples
    --------
    >>> ex = SutherlandHodgmanArea(seed=10)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check([ex.expected[0], ex.triangle_area]).diagnosis
    'unclipped area'
    """

    title = "Sutherland-Hodgman: the clipped triangle"
    answer_form = "custom"

    def draw(self, rng):
        self.box_min, self.box_max = _draw_box_2d(rng)
        lo, hi = self.box_min, self.box_max
        corners = np.array([[x, y] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])])
        while True:                     # a triangle that covers a corner of the rectangle
            self.triangle = _ints_between(rng, lo - 3, hi + 3, size=(3, 2))
            edges = [_cross2(self.triangle[(i + 1) % 3] - self.triangle[i],
                             corners - self.triangle[i]) for i in range(3)]
            if np.any(np.all(np.array(edges) > 0, axis=0) | np.all(np.array(edges) < 0, axis=0)):
                break
        cross = _cross2(self.triangle[1] - self.triangle[0],
                        self.triangle[2] - self.triangle[0])
        if cross < 0:
            self.triangle = self.triangle[::-1].copy()
        self.triangle_area = _shoelace(self.triangle)
        self.clipped = clipping.sutherland_hodgman(self.triangle, lo, hi)
        self.expected = np.array([float(len(self.clipped)), _shoelace(self.clipped)])

    def _corners(self):
        lo, hi = self.box_min, self.box_max
        corners = [np.array([x, y]) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
        return [i for i, p in enumerate(self.clipped)
                if any(np.allclose(p, c) for c in corners)]

    def acceptable(self):
        lo, hi = self.box_min, self.box_max
        t = self.triangle
        if self.triangle_area < 3 or len(self.clipped) < 4:
            return False
        on_lines = np.isin(t[:, 0], [lo[0], hi[0]]) | np.isin(t[:, 1], [lo[1], hi[1]])
        if on_lines.any():                      # a vertex on a side's line: degenerate cases
            return False
        corners = [np.array([x, y]) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])]
        for i in range(3):                      # no edge through a corner of the rectangle
            a, b = t[i], t[(i + 1) % 3]
            if any(abs(_cross2(b - a, c - a)) < 1e-9 for c in corners):
                return False
        return bool(self._corners()) and len(np.unique(np.round(self.clipped, 9), axis=0)) \
            == len(self.clipped)

    def _parts(self):
        n, area = self.expected
        keep = np.delete(self.clipped, self._corners(), axis=0)
        without = Mistake(_shoelace(keep), r"The rectangle's corner is missing. Where the "
                          r"triangle covers a corner of the clip rectangle, the clipped polygon "
                          r"runs along two sides and turns at that corner, so the corner is a "
                          r"vertex too (Sutherland-Hodgman produces it when it clips by the "
                          r"second of the two sides).", "box corner missing")
        return [
            ("the number of vertices", n, [Mistake(len(keep), without.explanation,
                                                   without.key)]),
            ("the area", area, [
                without,
                Mistake(self.triangle_area, r"That is the area of the whole triangle; only the "
                        r"part inside the rectangle is left after clipping.", "unclipped area"),
            ]),
        ]

    def mistakes(self):
        keep = np.delete(self.clipped, self._corners(), axis=0)
        return [Mistake([len(keep), _shoelace(keep)], "", "box corner missing"),
                Mistake([self.expected[0], self.triangle_area], "", "unclipped area")]

    def separated(self, mistakes):
        return parts_separated(self._parts(), same=None)

    def _check(self, answer):
        return diagnose_parts(answer, self._parts(), "your answer",
                              "`[number_of_vertices, area]`.",
                              "Clip by one side at a time, then compute the area of the final "
                              "polygon with the shoelace formula.")

    def statement(self):
        return (
            rf"The triangle ${_vec(self.triangle[0])}$, ${_vec(self.triangle[1])}$, "
            rf"${_vec(self.triangle[2])}$ is clipped to the rectangle "
            rf"{_box_words(self.box_min, self.box_max)} with Sutherland-Hodgman (against the "
            r"left, right, bottom and top sides in turn). How many vertices does the clipped "
            r"polygon have, and what is its area? (Draw it.)" "\n\n"
            r"**Answer:** a list of 2 numbers `[number_of_vertices, area]`. " + DECIMALS
            + "\n\n" + data_note("triangle", "box_min", "box_max"))


# ---------------------------------------------------------------------------------------------
# The z-buffer
# ---------------------------------------------------------------------------------------------

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
        ]

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
        self.total_fragments = float(sum(len(f) for f in fragments))
        self.visible_pixels = float(np.count_nonzero(ids >= 0))
        self.expected = float(writes)

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

    def statement(self):
        return (
            r"Three triangles, already in screen coordinates with a depth per vertex, are "
            r"drawn in this order with the z-buffer algorithm:" "\n\n"
            + _scene_table(self.triangles) + "\n\n" + _ZBUFFER_RULES + "\n\n"
            r"How many fragments pass the depth test, i.e. how many times is a value written "
            r"into the z-buffer (counting every write, also those overwritten later)?" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("triangles"))


# ---------------------------------------------------------------------------------------------
# The painter's algorithm
# ---------------------------------------------------------------------------------------------

def _read_order(answer, n):
    if _unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    value = read_floats(answer)
    if value is None or value.shape != (n,) or sorted(value.tolist()) != list(range(n)):
        return Feedback("invalid", f"Give the order as a list of the {n} polygon numbers "
                        f"0 to {n - 1}, each once.", "unreadable")
    return [int(v) for v in value]


class PaintersOrder(_Listed):
    r"""The painter's (depth-sort) drawing order: the farthest polygon first.

    Each polygon is keyed by its farthest vertex (the smallest :math:`z_e`, the eye looking down
    :math:`-z_e`) and the polygons are drawn from the farthest to the nearest.

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
        self.depths = [-np.sort(rng.choice(np.arange(1, 16), size=3, replace=False))[::-1]
                       .astype(float) for _ in range(4)]
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
        order = _read_order(answer, len(self.depths))
        if isinstance(order, Feedback):
            return order
        if order == self.expected:
            return Feedback("correct", "The drawing order is right.")
        for mistake in self._mistakes:
            if order == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        return Feedback("wrong", r"Not the depth-sort order. For each polygon find its "
                        r"farthest vertex (smallest $z_e$); draw the polygon whose farthest "
                        r"vertex is farthest first.", "order differs")

    def statement(self):
        rows = "\n".join(rf"| {k} | " + ", ".join(_num(z) for z in d) + " |"
                         for k, d in enumerate(self.depths))
        return (
            r"Four polygons are to be drawn with the painter's algorithm (depth sort). The eye "
            r"looks down $-z_e$; the $z_e$ coordinates of each polygon's vertices are:" "\n\n"
            "| polygon | $z_e$ of its vertices |\n|---|---|\n" + rows + "\n\n"
            r"Each polygon is keyed by its **farthest** vertex, and the polygons are drawn from "
            r"the farthest to the nearest. In which order are they drawn?" "\n\n"
            r"**Answer:** the list of the 4 polygon numbers in drawing order, e.g. "
            r"`[2, 0, 3, 1]`." "\n\n" + data_note("depths"))


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


# ---------------------------------------------------------------------------------------------
# Ray casting
# ---------------------------------------------------------------------------------------------

class RayCastingCount(DrawnExercise):
    r"""Counting intersection tests in ray casting, with and without bounding spheres.

    Brute force tests every ray against every triangle: :math:`p \cdot \sum P_i`. With one
    bounding sphere per object, every ray is tested against every sphere (:math:`p \cdot m`)
    and only the :math:`k_i` rays that hit sphere :math:`i` against its :math:`P_i` triangles.

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
        self.expected = np.array([float(pixels * sum(self.triangles)),
                                  float(sum(k * t for k, t in zip(self.hits, self.triangles))),
                                  float(pixels * m)])

    def _parts(self):
        brute, with_bv, spheres = self.expected
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


#: The exercises of chapter 5, in the order of the solutions notebook.
EXERCISES = (
    BackFaceCulling,
    Outcodes,
    CohenSutherlandDecision,
    CohenSutherlandClip,
    CohenSutherlandIntersections,
    LiangBarskyTable,
    LiangBarskyInterval,
    LiangBarskyClip3D,
    SutherlandHodgmanOneSide,
    SutherlandHodgmanArea,
    ZBufferIds,
    ZBufferWrites,
    PaintersOrder,
    PainterFailure,
    RayCastingCount,
)
