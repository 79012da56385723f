r"""Chapter 5 exercises: clipping in homogeneous coordinates (clip space, before the divide).

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.

The clip-space view volume is :math:`-w \le x, y, z \le w`; the six boundary functions
:math:`f = (w + x, w - x, w + y, w - y, w + z, w - z)` are non-negative inside (bits left = 1,
right = 2, bottom = 4, top = 8, near = 16, far = 32, as :mod:`course_lib.clipping`). Along
:math:`P(t) = P_0 + t (P_1 - P_0)` Liang-Barsky uses :math:`p_k = f_k(P_0) - f_k(P_1)`,
:math:`q_k = f_k(P_0)`. Expected answers come from :mod:`course_lib.clip_space`.
"""

import numpy as np

from ... import clip_space, clipping
from ..core import (UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note,
                    latex_fraction, latex_vector, pick, read_floats)
from . import _cyclic_match

__all__ = [
    "ClipSpaceExitPoint",
    "ClipSpaceLiangBarskyPairs",
    "ClipSpaceOutcode",
    "ClipSpaceSutherlandHodgman",
]

_SIDES = clipping.BIT_NAMES
_F_NAMES = ("w + x", "w - x", "w + y", "w - y", "w + z", "w - z")


def _f_values(p):
    """The six boundary functions of one homogeneous point, as plain floats (typed out)."""
    x, y, z, w = (float(c) for c in p)
    return [w + x, w - x, w + y, w - y, w + z, w - z]


def _code_of(bits):
    return int(sum(1 << k for k, b in enumerate(bits) if b))


def _swap_pairs(code):
    """Left and right (bottom and top, near and far) exchanged."""
    out = 0
    for k in range(6):
        if code >> k & 1:
            out |= 1 << (k ^ 1)
    return out


def _reversed_bits(code):
    return int(format(code, "06b")[::-1], 2)


def _point_tex(p):
    return latex_vector(p)


class ClipSpaceOutcode(DrawnExercise):
    r"""The 6-bit outcode of a homogeneous point in clip space, without dividing by w.

    Bit k is set when the point is beyond side k: :math:`x < -w` (left, 1), :math:`x > w`
    (right, 2), :math:`y < -w` (bottom, 4), :math:`y > w` (top, 8), :math:`z < -w` (near, 16),
    :math:`z > w` (far, 32). A third of the variants have :math:`w < 0` (behind the eye).

    Attributes: ``point`` (x, y, z, w).

    Examples
    --------
    >>> ex = ClipSpaceOutcode(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "An outcode in clip space"
    answer_form = "number"
    what = "the outcode"
    reject_bool = True
    advice = (r"Compare each coordinate with $\pm w$ (not with $\pm 1$): left $x < -w$ = 1, "
              r"right $x > w$ = 2, bottom $y < -w$ = 4, top $y > w$ = 8, near $z < -w$ = 16, "
              r"far $z > w$ = 32, and add the values of the bits that are set.")
    off_by_one = ("Your code is one off the right one. Check the left bit (value 1, x < -w) "
                  "first, then add the bit values again.")

    def draw(self, rng):
        w = float(pick(rng, (2, 3, 4, 5, -2, -3)))
        xyz = rng.integers(-6, 7, size=3).astype(float)
        self.point = np.array([*xyz, w])
        self.expected = clip_space.clip_outcode(self.point)

    def acceptable(self):
        x, y, z, w = self.point
        return bool(np.all(np.abs(self.point[:3]) != abs(w)))   # no point on a side

    def mistakes(self):
        x, y, z, w = self.point
        found = [
            Mistake(clipping.outcode(self.point[:3], -np.ones(3), np.ones(3)),
                    r"You compared the coordinates with $\pm 1$: that is the test in NDC, after "
                    r"the divide. In clip space the bounds move with the point: $-w \le x, y, "
                    r"z \le w$.", "compared with 1"),
            Mistake(_reversed_bits(self.expected), "The bit order is reversed: left is the "
                    "lowest bit (value 1) and far the highest (32), as in clipping.BIT_NAMES.",
                    "bit order reversed"),
            Mistake(_swap_pairs(self.expected), r"The two sides of each axis are swapped: "
                    r"$x < -w$ is beyond the **left** side (1), $x > w$ beyond the right (2).",
                    "sides swapped"),
        ]
        if w < 0:
            found.append(Mistake(
                clipping.outcode(self.point[:3] / w, -np.ones(3), np.ones(3)),
                r"You divided by $w$ first. With $w < 0$ the point is behind the eye; dividing "
                r"mirrors it through the centre and it may land inside the NDC cube. Test "
                r"$-w \le x \le w$ with the undivided coordinates: no point with $w < 0$ "
                r"passes (a bit is set on every axis).", "divided with w < 0"))
        return found

    def statement(self):
        return (rf"A vertex has clip coordinates $P = (x, y, z, w) = {_point_tex(self.point)}$. "
                r"Give its 6-bit outcode against the clip-space view volume "
                r"$-w \le x, y, z \le w$ as a whole number (left = 1, right = 2, bottom = 4, "
                r"top = 8, near = 16, far = 32; 0 when inside)." "\n\n"
                r"**Answer:** one whole number." "\n\n" + data_note("point"))

    def _bits(self):
        x, y, z, w = (float(c) for c in self.point)
        tests = [(x < -w, rf"x = {x:g} < -w = {-w:g}"), (x > w, rf"x = {x:g} > w = {w:g}"),
                 (y < -w, rf"y = {y:g} < -w = {-w:g}"), (y > w, rf"y = {y:g} > w = {w:g}"),
                 (z < -w, rf"z = {z:g} < -w = {-w:g}"), (z > w, rf"z = {z:g} > w = {w:g}")]
        return tests

    def hints(self):
        w = float(self.point[3])
        return [r"Do not divide: compare x, y and z with $-w$ and $w$ directly.",
                rf"Here $w = {w:g}$, so the bounds are $-w = {-w:g}$ and $w = {w:g}$"
                + (r" (note that $-w > w$: no coordinate can lie between them)." if w < 0
                   else "."),
                "Bit values: left 1, right 2, bottom 4, top 8, near 16, far 32; add those set."]

    def worked(self):
        tests = self._bits()
        lines = []
        for k, (flag, text) in enumerate(tests):
            lines.append(rf"{_SIDES[k]} (bit {1 << k}): ${text}$? "
                         + ("**yes**" if flag else "no"))
        code = _code_of(flag for flag, _ in tests)
        set_bits = [str(1 << k) for k, (flag, _) in enumerate(tests) if flag]
        return Worked([
            rf"Bounds: $-w = {-float(self.point[3]):g}$, $w = {float(self.point[3]):g}$; test "
            "each coordinate against them, no division.",
            "; ".join(lines) + ".",
            rf"Outcode $= {' + '.join(set_bits) if set_bits else '0'} = {code}$.",
        ], code)


class ClipSpaceLiangBarskyPairs(DrawnExercise):
    r"""Liang-Barsky's six :math:`(p_k, q_k)` pairs for a segment in clip space.

    :math:`p_k = f_k(P_0) - f_k(P_1)`, :math:`q_k = f_k(P_0)` with
    :math:`f = (w + x, w - x, w + y, w - y, w + z, w - z)`; the answer is a 6 x 2 table, rows
    left, right, bottom, top, near, far.

    Attributes: ``p0``, ``p1`` (homogeneous end points).

    Examples
    --------
    >>> ex = ClipSpaceLiangBarskyPairs(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Liang-Barsky's (p, q) pairs in clip space"
    answer_form = "matrix"
    transform = False
    what = "the table of (p_k, q_k)"
    advice = (r"Write $f_k$ for the six sides at both ends, $f = (w + x, w - x, w + y, w - y, "
              r"w + z, w - z)$; then $p_k = f_k(P_0) - f_k(P_1)$ and $q_k = f_k(P_0)$.")

    def draw(self, rng):
        w0 = float(pick(rng, (1, 2, 3)))
        w1 = float(pick(rng, (1, 2, 3, -1, -2)))
        self.p0 = np.array([*rng.integers(-4, 5, size=3), w0], dtype=float)
        self.p1 = np.array([*rng.integers(-4, 5, size=3), w1], dtype=float)
        rows = clip_space.clip_segment_homogeneous(self.p0, self.p1)["rows"]
        self.expected = np.array([[r["p"], r["q"]] for r in rows])

    def acceptable(self):
        # no parallel side (p = 0), and the segment is not entirely inside
        return bool(np.all(self.expected[:, 0] != 0) and np.any(self.expected[:, 0] > 0)
                    and self.p0[3] != self.p1[3])

    def mistakes(self):
        a = np.array(_f_values(self.p0))
        b = np.array(_f_values(self.p1))
        d = self.p1[:3] - self.p0[:3]
        boxed = np.array([[-d[0], self.p0[0] + 1], [d[0], 1 - self.p0[0]],
                          [-d[1], self.p0[1] + 1], [d[1], 1 - self.p0[1]],
                          [-d[2], self.p0[2] + 1], [d[2], 1 - self.p0[2]]])
        return [
            Mistake(np.column_stack([b - a, a]), r"Every $p_k$ has the wrong sign. From "
                    r"$f_k(t) = f_k(P_0) + t\,(f_k(P_1) - f_k(P_0)) \ge 0$ the condition is "
                    r"$p_k t \le q_k$ with $p_k = f_k(P_0) - f_k(P_1)$.", "sign of p"),
            Mistake(np.column_stack([a - b, b]), r"The $q_k$ are taken at the wrong end: "
                    r"$q_k = f_k(P_0)$, the value at $t = 0$ (at $P_0$), not at $P_1$.",
                    "q from the wrong end"),
            Mistake(boxed, r"These are the pairs of the box $[-1, 1]^3$, with $w$ left out "
                    r"(as if both ends had $w = 1$). In clip space the sides move with $w$: "
                    r"left is $w + x \ge 0$, so $p = -(\Delta x + \Delta w)$, "
                    r"$q = x_0 + w_0$.", "w ignored"),
        ]

    def statement(self):
        return (r"A segment runs from $P_0$ to $P_1$ in clip coordinates (x, y, z, w): "
                rf"$P_0 = {_point_tex(self.p0)}$, $P_1 = {_point_tex(self.p1)}$. For "
                r"Liang-Barsky against $-w \le x, y, z \le w$, write each side's condition as "
                r"$p_k t \le q_k$ along $P(t) = P_0 + t\,(P_1 - P_0)$. Give the six pairs "
                r"$(p_k, q_k)$ as a 6 x 2 table, rows left, right, bottom, top, near, far "
                r"(e.g. `[[p1, q1], [p2, q2], ...]`)." "\n\n"
                r"**Answer:** a 6 x 2 table of numbers (exact: whole numbers)." "\n\n"
                + data_note("p0", "p1"))

    def hints(self):
        return [r"Each side has a boundary function that is $\ge 0$ inside: left $w + x$, "
                r"right $w - x$, bottom $w + y$, top $w - y$, near $w + z$, far $w - z$.",
                r"It is linear in $t$: $f_k(t) = f_k(P_0) + t\,(f_k(P_1) - f_k(P_0))$.",
                r"So $f_k(t) \ge 0$ reads $p_k t \le q_k$ with $p_k = f_k(P_0) - f_k(P_1)$, "
                r"$q_k = f_k(P_0)$."]

    def worked(self):
        a, b = _f_values(self.p0), _f_values(self.p1)
        table = [[a[k] - b[k], a[k]] for k in range(6)]
        at0 = ", ".join(rf"{_F_NAMES[k]} = {a[k]:g}" for k in range(6))
        at1 = ", ".join(rf"{_F_NAMES[k]} = {b[k]:g}" for k in range(6))
        rows = "; ".join(rf"{_SIDES[k]}: $p = {a[k]:g} - ({b[k]:g}) = {a[k] - b[k]:g}$, "
                         rf"$q = {a[k]:g}$" for k in range(6))
        return Worked([
            rf"At $P_0$: {at0}.",
            rf"At $P_1$: {at1}.",
            rf"$p_k = f_k(P_0) - f_k(P_1)$, $q_k = f_k(P_0)$: {rows}.",
        ], np.array(table))


class ClipSpaceExitPoint(DrawnExercise):
    r"""Where a segment from inside the view volume to a point behind the eye leaves it (in NDC).

    :math:`P_0` is inside (:math:`w_0 > 0`), :math:`P_1` behind the eye (:math:`w_1 < 0`).
    Liang-Barsky in clip space gives :math:`t_{out}` (the smallest t of the leaving sides,
    :math:`p_k > 0`); the answer is :math:`P(t_{out})` divided by its w, three numbers.

    Attributes: ``p0``, ``p1`` (homogeneous end points).

    Examples
    --------
    >>> ex = ClipSpaceExitPoint(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The clipped end point, clipped before the divide"
    answer_form = "vector"
    vector_like = False
    what = "the clipped end point in NDC"
    advice = (r"Clip in clip space: $t_{out}$ is the smallest $t_k = q_k / p_k$ over the sides "
              r"with $p_k > 0$; evaluate $P(t_{out}) = P_0 + t_{out}(P_1 - P_0)$, then divide "
              r"its x, y, z by its w.")

    def draw(self, rng):
        w0 = float(pick(rng, (2, 3, 4)))
        inner = int(w0) - 1
        self.p0 = np.array([*rng.integers(-inner, inner + 1, size=3), w0], dtype=float)
        w1 = float(pick(rng, (-1, -2)))
        self.p1 = np.array([*rng.integers(-4, 5, size=3), w1], dtype=float)
        r = clip_space.clip_segment_homogeneous(self.p0, self.p1)
        end = r["clipped"][1]
        self._t_out = r["t_out"]
        self.expected = end[:3] / end[3]

    def _leaving(self):
        a, b = _f_values(self.p0), _f_values(self.p1)
        return [(k, a[k] / (a[k] - b[k])) for k in range(6) if a[k] - b[k] > 0]

    def acceptable(self):
        ts = sorted(t for _, t in self._leaving())
        # a unique exit side, well inside the segment
        return bool(len(ts) >= 2 and ts[1] - ts[0] > 0.02 and 0.05 < ts[0] < 0.95)

    def mistakes(self):
        d = self.p1 - self.p0
        second = sorted(t for _, t in self._leaving())[1]      # the next leaving side's t
        at_second = self.p0 + second * d
        after = clip_space.clip_after_divide(self.p0, self.p1)["clipped"]
        exit_h = self.p0 + self._t_out * d
        found = [
            Mistake(exit_h[:3], r"You stopped before the divide: the clipped point "
                    r"$P(t_{out})$ is in clip coordinates; divide x, y, z by its w to get NDC.",
                    "not divided"),
        ]
        if at_second[3] > 0:
            found.append(Mistake(at_second[:3] / at_second[3], r"The t of the wrong side: "
                                 r"the segment leaves the volume at the **smallest** $t_k$ of "
                                 r"the leaving sides ($t_{out} = \min$); past it the point is "
                                 r"already outside.", "t from the wrong plane"))
        if after is not None:
            found.append(Mistake(after[1], r"You divided first and clipped in NDC. $P_1$ has "
                                 r"$w < 0$: dividing mirrors it through the centre, and the "
                                 r"straight NDC segment to it is the image of the *other* part "
                                 r"of the line (through infinity). Clip in clip space, before "
                                 r"the divide.", "clipped after the divide"))
        return found

    def statement(self):
        return (r"A segment runs from $P_0$, inside the view volume, to $P_1$, behind the eye "
                r"($w < 0$), in clip coordinates (x, y, z, w): "
                rf"$P_0 = {_point_tex(self.p0)}$, $P_1 = {_point_tex(self.p1)}$. Clip it "
                r"against $-w \le x, y, z \le w$ and give the end point of the visible part "
                r"(the one that is not $P_0$) in NDC, i.e. after the perspective divide, as "
                r"three numbers." "\n\n"
                r"**Answer:** a list of 3 numbers `[x, y, z]`, to 3 decimals or more." "\n\n"
                + data_note("p0", "p1"))

    def hints(self):
        return [r"Clip before dividing: $P_1$ is behind the eye and must not be divided.",
                r"For each side $f_k \in \{w \pm x, w \pm y, w \pm z\}$: $p_k = f_k(P_0) - "
                r"f_k(P_1)$, $q_k = f_k(P_0)$. The leaving sides have $p_k > 0$.",
                r"$t_{out} = \min q_k / p_k$ over the leaving sides; then "
                r"$P(t_{out}) = P_0 + t_{out}(P_1 - P_0)$, divided by its w."]

    def worked(self):
        a, b = _f_values(self.p0), _f_values(self.p1)
        leaving = [(k, a[k], a[k] - b[k]) for k in range(6) if a[k] - b[k] > 0]
        listed = "; ".join(rf"{_SIDES[k]}: $t = {q:g}/{p:g} = {latex_fraction(q / p)}$"
                           for k, q, p in leaving)
        k_min, q_min, p_min = min(leaving, key=lambda item: item[1] / item[2])
        t = q_min / p_min
        point = [float(self.p0[i] + t * (self.p1[i] - self.p0[i])) for i in range(4)]
        ndc = np.array(point[:3]) / point[3]
        return Worked([
            r"Leaving sides ($p_k = f_k(P_0) - f_k(P_1) > 0$, $q_k = f_k(P_0)$): "
            + listed + ".",
            rf"$t_{{out}} = \min = {latex_fraction(t)}$ ({_SIDES[k_min]}); $t_{{in}} = 0$ "
            r"since $P_0$ is inside.",
            rf"$P(t_{{out}}) = P_0 + {latex_fraction(t)}\,(P_1 - P_0) = {latex_vector(point)}$.",
            rf"Divide by $w = {latex_fraction(point[3])}$: NDC point "
            rf"${latex_vector(ndc)}$.",
        ], ndc)


def _sh_words(points):
    return ", ".join(f"${latex_vector(p)}$" for p in points)


class ClipSpaceSutherlandHodgman(DrawnExercise):
    r"""Sutherland-Hodgman: a triangle in clip coordinates against one plane of the view volume.

    Inside is :math:`f_k \ge 0` for the side's boundary function (left :math:`w + x`, right
    :math:`w - x`, ..., far :math:`w - z`). An edge :math:`S \to E` that crosses the plane is cut
    at :math:`t = f_k(S) / (f_k(S) - f_k(E))`, all four coordinates interpolated; the answer is
    the output polygon as homogeneous 4-vectors. Some variants have a vertex behind the eye.

    Attributes: ``triangle`` (3 x 4), ``side`` (a name of ``clipping.BIT_NAMES``).

    Examples
    --------
    >>> ex = ClipSpaceSutherlandHodgman(seed=1)
    >>> ex.check(ex.expected).status, ex.check(np.roll(ex.expected, 1, axis=0)).status
    ('correct', 'correct')
    """

    title = "Sutherland-Hodgman in clip space, one plane"
    answer_form = "custom"
    what = "the clipped polygon"

    def draw(self, rng):
        self.side = str(pick(rng, _SIDES))
        self._k = _SIDES.index(self.side)
        ws = [float(pick(rng, (1, 2, 3, 4))) for _ in range(3)]
        if rng.random() < 0.3:
            ws[int(rng.integers(3))] = float(pick(rng, (-1, -2)))
        xyz = rng.integers(-4, 5, size=(3, 3)).astype(float)
        self.triangle = np.column_stack([xyz, ws])
        _, normal, offset = clip_space.clip_space_planes()[self._k]
        self.expected = clipping._clip_by_plane(self.triangle, normal, offset)

    def _f(self, p):
        return _f_values(p)[self._k]

    def acceptable(self):
        f = [self._f(p) for p in self.triangle]
        return bool(all(v != 0 for v in f) and any(v > 0 for v in f)
                    and any(v < 0 for v in f))

    def _intersections(self):
        return [i for i, p in enumerate(self.expected)
                if not np.any(np.all(np.isclose(self.triangle, p), axis=1))]

    def _divided_cut(self):
        """The polygon with every intersection found from t computed after the divide."""
        axis, sign = self._k // 2, (1.0 if self._k % 2 == 0 else -1.0)
        out = []
        n = len(self.triangle)
        for i in range(n):
            S, E = self.triangle[i], self.triangle[(i + 1) % n]
            fs, fe = self._f(S), self._f(E)
            if (fs >= 0) != (fe >= 0):
                if S[3] <= 0 or E[3] <= 0:
                    return None                  # cannot even be divided
                s, e = S[axis] / S[3], E[axis] / E[3]
                t = (-sign - s) / (e - s)        # where the NDC coordinate reaches -1 or +1
                cut = S + t * (E - S)
            if fs >= 0 and fe >= 0:
                out.append(E)
            elif fs >= 0:
                out.append(cut)
            elif fe >= 0:
                out.extend([cut, E])
        return np.array(out)

    def mistakes(self):
        found = [Mistake(np.delete(self.expected, i, axis=0), r"An intersection vertex is "
                         r"missing. Each edge that crosses the plane contributes its "
                         r"intersection I: in $\to$ out outputs I, out $\to$ in outputs I and "
                         r"then E.", "missing intersection vertex")
                 for i in self._intersections()]
        found.append(Mistake(self.expected[::-1], r"Your vertices run the other way round: go "
                             r"through the edges $v_0 \to v_1$, $v_1 \to v_2$, $v_2 \to v_0$ in "
                             r"order and append each edge's output.", "reversed order"))
        _, normal, offset = clip_space.clip_space_planes()[self._k]
        found.append(Mistake(clipping._clip_by_plane(self.triangle, -normal, -offset),
                             rf"You kept the part **outside**: the inside of the {self.side} "
                             rf"plane is ${_F_NAMES[self._k]} \ge 0$.", "kept the outside part"))
        divided = self._divided_cut()
        if divided is not None:
            found.append(Mistake(divided, r"The intersection's $t$ was found after the divide "
                                 r"(where $x/w$ reaches $\pm 1$ along the straight line between "
                                 r"the divided end points) and then used on the homogeneous "
                                 r"points. The divide is not linear, so that $t$ is another "
                                 r"point: use $t = f(S) / (f(S) - f(E))$ with the undivided "
                                 r"boundary function.", "t after the divide"))
        return found

    def separated(self, mistakes):
        if any(_cyclic_match(m.value, self.expected) for m in mistakes):
            return False
        return all(not _cyclic_match(a.value, b.value) for i, a in enumerate(mistakes)
                   for b in mistakes[i + 1:] if a.key != b.key)

    def _check(self, answer):
        if answer is ... or answer is None:
            return Feedback("unanswered", UNANSWERED)
        value = read_floats(answer)
        if value is None or value.ndim != 2 or value.shape[1] != 4:
            return Feedback("invalid", "Give the polygon as a list of homogeneous points "
                            "`[[x, y, z, w], ...]`.", "unreadable")
        if _cyclic_match(value, self.expected):
            return Feedback("correct", "The clipped polygon is right (the starting vertex does "
                            "not matter).")
        for mistake in self._mistakes:
            if _cyclic_match(value, mistake.value):
                return Feedback("wrong", mistake.explanation, mistake.key)
        if len(value) != len(self.expected):
            return Feedback("wrong", f"Your polygon has {len(value)} vertices; the clipped one "
                            f"has {len(self.expected)}. Apply the four rules to every edge "
                            "(in-in: E; in-out: I; out-in: I, E; out-out: nothing).",
                            "vertex count differs")
        return Feedback("wrong", "The vertices are not right yet. Classify each vertex by the "
                        "sign of the boundary function, and cut crossing edges at "
                        "t = f(S) / (f(S) - f(E)), interpolating all four coordinates.",
                        "vertices differ")

    def statement(self):
        return (r"A triangle has the clip coordinates (x, y, z, w) "
                + ", ".join(rf"$v_{i} = {_point_tex(p)}$" for i, p in enumerate(self.triangle))
                + rf". Clip it against the **{self.side}** plane of the view volume only, "
                rf"whose inside is ${_F_NAMES[self._k]} \ge 0$, with Sutherland-Hodgman (edges "
                r"$v_0 \to v_1$, $v_1 \to v_2$, $v_2 \to v_0$; in-in: E; in-out: I; out-in: I "
                r"then E; out-out: nothing), in clip space, before any divide." "\n\n"
                r"**Answer:** the output vertices in order, as homogeneous points "
                r"`[[x, y, z, w], ...]` (any starting vertex), to 3 decimals or more." "\n\n"
                + data_note("triangle", "side"))

    def hints(self):
        f = [self._f(p) for p in self.triangle]
        return [r"Inside the plane means its boundary function is $\ge 0$: here "
                rf"$f = {_F_NAMES[self._k]}$. Do not divide by w.",
                "The values at the vertices: "
                + ", ".join(rf"$f(v_{i}) = {v:g}$" for i, v in enumerate(f)) + ".",
                r"A crossing edge $S \to E$ is cut at $t = f(S)/(f(S) - f(E))$: "
                r"$I = S + t\,(E - S)$, all four coordinates."]

    def worked(self):
        f = [self._f(p) for p in self.triangle]
        tri = [np.array(p, dtype=float) for p in self.triangle]
        steps = [rf"Inside is $f = {_F_NAMES[self._k]} \ge 0$: "
                 + ", ".join(rf"$f(v_{i}) = {v:g}$ ({'in' if v >= 0 else 'out'})"
                             for i, v in enumerate(f)) + "."]
        out = []
        for i in range(3):
            j = (i + 1) % 3
            S, E, fs, fe = tri[i], tri[j], f[i], f[j]
            edge = rf"$v_{i} \to v_{j}$"
            if (fs >= 0) != (fe >= 0):
                t = fs / (fs - fe)
                cut = S + t * (E - S)
                crossing = (rf"$t = {fs:g}/({fs:g} - ({fe:g})) = {latex_fraction(t)}$, "
                            rf"$I = {latex_vector(cut)}$")
            if fs >= 0 and fe >= 0:
                out.append(E)
                steps.append(rf"{edge}: in $\to$ in, output $E = {latex_vector(E)}$.")
            elif fs >= 0:
                out.append(cut)
                steps.append(rf"{edge}: in $\to$ out, {crossing}: output $I$.")
            elif fe >= 0:
                out.extend([cut, E])
                steps.append(rf"{edge}: out $\to$ in, {crossing}: output $I$, then $E$.")
            else:
                steps.append(rf"{edge}: out $\to$ out, nothing.")
        steps.append(rf"The output, in order: {_sh_words(out)}.")
        return Worked(steps, np.array(out))
