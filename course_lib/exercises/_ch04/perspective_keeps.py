"""Chapter 4 exercises: What perspective keeps.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import numpy as np

from ... import transforms as tf
from ... import viewing
from ..core import (APART, DECIMALS, SAME, DrawnExercise, Mistake, Worked, data_note,
                    diagnose_parts, pick, small_ints)
from . import PointAnswer, _num, _par, _snap, _vec

__all__ = [
    "CrossRatioUnderProjection",
    "VanishingPoint",
]


def _project(d, p):
    return np.asarray(viewing.simple_perspective(d) @ np.append(p, 1.0))


class CrossRatioUnderProjection(DrawnExercise):
    r"""A ratio of distances changes under perspective projection; the cross ratio does not.

    Four collinear points A, B, C, D (in this order) are projected by :math:`P_{PER}`. The
    answer is :math:`AB/BC` before and after, and the cross ratio
    :math:`(A, B; C, D) = \frac{AC \cdot BD}{BC \cdot AD}` before and after.

    Attributes: ``d``, ``A``, ``B``, ``C``, ``D``.

    Examples
    --------
    >>> ex = CrossRatioUnderProjection(seed=13)
    >>> ex.check(ex.expected).status
    'correct'
    >>> r, r_after, cr, cr_after = ex.expected
    >>> ex.check([r, r, cr, cr_after]).diagnosis          # the ratio does not survive
    'ratio assumed preserved'
    """

    title = "What a perspective projection keeps"
    answer_form = "custom"

    def draw(self, rng):
        # the ratio after the projection depends on the steps and on how fast the depth grows
        # (start z against u_z), the cross ratio on the steps only
        self.d = float(pick(rng, (1, 2, 4)))
        start = np.array([*rng.integers(-2, 3, size=2), pick(rng, (1, 2, 3))], dtype=float)
        ux, uy = small_ints(rng, 2, -2, 2)
        u = np.array([ux, uy, float(pick(rng, (1, 2, 3)))])
        steps = np.sort(rng.choice(7, size=4, replace=False)).astype(float)
        self.A, self.B, self.C, self.D = (start + s * u for s in steps)
        images = [tf.apply(viewing.simple_perspective(self.d), p) for p in self._points()]
        self._usable = min(np.linalg.norm(q - p) for p, q in zip(images, images[1:])) > 0.1
        if not self._usable:            # the line passes (almost) through the eye
            return
        ratio = (steps[1] - steps[0]) / (steps[2] - steps[1])
        a, b, c, _ = images
        ratio_after = float(np.linalg.norm(b - a) / np.linalg.norm(c - b))
        self.expected = np.array([ratio, ratio_after, viewing.cross_ratio(*self._points()),
                                  viewing.cross_ratio(*images)])

    def acceptable(self):
        return self._usable

    def _points(self):
        return self.A, self.B, self.C, self.D

    def _parts(self):
        r, r_after, cr, cr_after = self.expected
        inverted = (r"You computed $BC/AB$; the question asks for $AB/BC$ (the first distance "
                    r"over the second).")
        reciprocal = (r"You computed the reciprocal of the cross ratio. With the definition "
                      r"used here, $(A, B; C, D) = \frac{AC \cdot BD}{BC \cdot AD}$.")
        return [
            ("the ratio before", r, [Mistake(1 / r, inverted, "ratio inverted")]),
            ("the ratio after", r_after, [
                Mistake(r, r"The ratio of distances along a line is **not** kept by a "
                        r"perspective projection (it is kept by affine maps only). Project the "
                        r"three points (divide by $z$) and measure again: the part farther from "
                        r"the eye shrinks more.", "ratio assumed preserved"),
                Mistake(1 / r_after, inverted, "ratio inverted")]),
            ("the cross ratio before", cr, [Mistake(1 / cr, reciprocal,
                                                    "cross ratio inverted")]),
            ("the cross ratio after", cr_after, [Mistake(1 / cr_after, reciprocal,
                                                         "cross ratio inverted")]),
        ]

    def mistakes(self):
        r, r_after, cr, cr_after = self.expected
        return [Mistake([1 / r, 1 / r_after, cr, cr], "", "ratio inverted"),
                Mistake([r, r, cr, cr], "", "ratio assumed preserved"),
                Mistake([r, r_after, 1 / cr, 1 / cr], "", "cross ratio inverted")]

    def separated(self, mistakes):
        r, r_after, cr, _ = self.expected
        values = [r, 1 / r, r_after, 1 / r_after]
        # APART up to rounding (SAME) is apart: the last bit must not pick the variant
        apart = all(abs(a - b) >= APART - SAME for i, a in enumerate(values)
                    for b in values[i + 1:])
        return apart and abs(cr - 1 / cr) >= APART - SAME

    def _check(self, answer):
        return diagnose_parts(answer, self._parts(), "your answer",
                              "`[AB/BC, A'B'/B'C', cross ratio before, cross ratio after]`.",
                              r"Project each point, $(x, y, z) \to (xd/z,\ yd/z,\ d)$, then "
                              r"measure the distances between the images.")

    def _by_hand(self):
        """The images and the four numbers, worked out as on paper."""
        points = self._points()
        images = [self.d * np.asarray(p) / p[2] for p in points]

        def dist(p, q):
            return float(np.linalg.norm(np.asarray(q) - np.asarray(p)))

        def cross(a, b, c, e):
            return dist(a, c) * dist(b, e) / (dist(b, c) * dist(a, e))

        a, b, c, e = points
        ia, ib, ic, ie = images
        values = np.array([dist(a, b) / dist(b, c), dist(ia, ib) / dist(ib, ic),
                           cross(a, b, c, e), cross(ia, ib, ic, ie)])
        return images, values, dist

    def hints(self):
        images, values, dist = self._by_hand()
        return [
            r"Project each point with $P_{PER}$ and the divide, $(x, y, z) \to "
            r"(xd/z,\ yd/z,\ d)$, then measure ordinary distances before and after.",
            rf"The images are $A' = {_vec(images[0])}$, $B' = {_vec(images[1])}$, "
            rf"$C' = {_vec(images[2])}$, $D' = {_vec(images[3])}$.",
            rf"Before: $AB/BC = {_num(values[0])}$; after, $A'B' = "
            rf"{_num(dist(images[0], images[1]))}$ and $B'C' = {_num(dist(images[1], images[2]))}$"
            r". The cross ratio uses four distances: $AC, BD, BC, AD$.",
        ]

    def worked(self):
        images, values, dist = self._by_hand()
        A, B, C, D = self._points()
        iA, iB, iC, iD = images
        return Worked([
            rf"Images ($\times d / z$): $A' = {_vec(iA)}$, $B' = {_vec(iB)}$, "
            rf"$C' = {_vec(iC)}$, $D' = {_vec(iD)}$.",
            rf"$AB/BC = {_num(dist(A, B))} / {_num(dist(B, C))} = {_num(values[0])}$; "
            rf"$A'B'/B'C' = {_num(dist(iA, iB))} / {_num(dist(iB, iC))} = {_num(values[1])}$: "
            r"the ratio changes.",
            rf"$(A, B; C, D) = \frac{{AC \cdot BD}}{{BC \cdot AD}} = \frac{{{_num(dist(A, C))} "
            rf"\cdot {_num(dist(B, D))}}}{{{_num(dist(B, C))} \cdot {_num(dist(A, D))}}} = "
            rf"{_num(values[2])}$.",
            rf"$(A', B'; C', D') = \frac{{{_num(dist(iA, iC))} \cdot {_num(dist(iB, iD))}}}"
            rf"{{{_num(dist(iB, iC))} \cdot {_num(dist(iA, iD))}}} = {_num(values[3])}$: the "
            r"cross ratio survives.",
        ], list(values))

    def statement(self):
        return (
            rf"The points $A = {_vec(self.A)}$, $B = {_vec(self.B)}$, $C = {_vec(self.C)}$ and "
            rf"$D = {_vec(self.D)}$ lie on one line, in this order. They are projected with "
            r"$P_{PER}$ (centre of projection at the origin) onto the plane "
            rf"$z = d$, $d = {_num(self.d)}$, giving $A', B', C', D'$." "\n\n"
            r"Compute (1) the ratio $AB/BC$, (2) the ratio $A'B'/B'C'$ of the images, (3) the "
            r"cross ratio $(A, B; C, D) = \frac{AC \cdot BD}{BC \cdot AD}$ and (4) the cross "
            r"ratio $(A', B'; C', D')$ of the images. Which of the two properties survives the "
            r"projection?" "\n\n"
            r"**Answer:** a list of 4 numbers `[AB/BC, A'B'/B'C', cross_before, cross_after]` "
            r"(distances are ordinary, positive lengths). " + DECIMALS + "\n\n"
            + data_note("d", "A", "B", "C", "D"))


class VanishingPoint(PointAnswer, DrawnExercise):
    r"""The vanishing point of a family of parallel lines under :math:`P_{PER}`.

    The image of :math:`p_0 + s\,u` tends to :math:`d\,(u_x / u_z,\ u_y / u_z,\ 1)` as
    :math:`s \to \infty`: the projection of the direction (the point at infinity
    :math:`(u, 0)`).

    Attributes: ``d``, ``u`` (the common direction), ``p0`` (a point of one of the lines).

    Examples
    --------
    >>> ex = VanishingPoint(seed=14)
    >>> ex.check(ex.expected).status
    'correct'
    >>> p = ex.p0
    >>> ex.check(ex.d * p / p[2]).diagnosis               # the image of a point, not the limit
    'projected a point'
    """

    title = "A vanishing point"
    projective_point = True
    what = "the vanishing point"

    def draw(self, rng):
        self.d = float(pick(rng, (1, 2, 3, 4)))
        ux, uy = small_ints(rng, 2, -3, 3)
        self.u = np.array([ux, uy, float(pick(rng, (-3, -2, -1, 1, 2, 3)))])
        self.p0 = np.array([*rng.integers(-3, 4, size=2), pick(rng, (1, 2, 3, 4))],
                           dtype=float)
        homogeneous = viewing.simple_perspective(self.d) @ np.append(self.u, 0.0)
        self.expected = _snap(homogeneous[:3] / homogeneous[3])

    def mistakes(self):
        ux, uy, uz = self.u
        found = [
            Mistake(self.d * self.p0 / self.p0[2], r"That is the image of the point $p_0$, "
                    r"which depends on the line. The vanishing point is where the images of "
                    r"all these lines meet: the limit of the image of $p_0 + s\,u$ as $s$ "
                    r"grows, $d\,(u_x/u_z,\ u_y/u_z,\ 1)$; it depends only on the direction.",
                    "projected a point"),
            Mistake(self.d * self.u, r"You multiplied the direction by $P_{PER}$ but did not "
                    r"divide by $w = u_z$. The direction is the point at infinity "
                    r"$(u_x, u_y, u_z, 0)$; its image $(d u_x, d u_y, d u_z, u_z)$ still needs "
                    r"the homogeneous divide.", "no divide"),
        ]
        if self.d != 1:
            found.append(Mistake(self.u / uz, r"You divided by $u_z$ but forgot the plane's "
                                 r"distance: the vanishing point lies on the plane $z = d$, at "
                                 r"$d\,(u_x/u_z,\ u_y/u_z,\ 1)$.", "forgot d"))
        if ux and uy:
            found.append(Mistake([self.d * uz / ux, self.d * uz / uy, self.d], r"The ratios "
                                 r"are upside down: divide by the depth component, "
                                 r"$x = d\,u_x / u_z$.", "ratio upside down"))
        return found

    def statement(self):
        return (
            rf"A family of parallel lines has the common direction $u = {_vec(self.u)}$; one "
            rf"of them passes through $p_0 = {_vec(self.p0)}$. The lines are projected with "
            r"$P_{PER}$: centre of projection at the origin, plane of projection "
            rf"$z = d$ with $d = {_num(self.d)}$. Their images meet in one point of the plane, "
            r"the vanishing point. Where is it?" "\n\n"
            r"**Answer:** the vanishing point as a list of 3 numbers `[x, y, z]` (a point of "
            r"the plane $z = d$). " + DECIMALS + "\n\n" + data_note("d", "u", "p0"))

    def hints(self):
        ux, uy, uz = self.u
        return [
            r"Far along a line $p_0 + s\,u$ the image stops depending on $p_0$: it tends to the "
            r"image of the direction, the point at infinity $(u_x, u_y, u_z, 0)$.",
            rf"$P_{{PER}}\,(u, 0) = (d\,u_x,\ d\,u_y,\ d\,u_z,\ u_z) = "
            rf"{_vec(self.d * np.append(self.u, 0.0) + np.array([0, 0, 0, uz]))}$: it still "
            r"needs the homogeneous divide by $w = u_z$.",
            rf"Divide by $u_z = {_num(uz)}$: $x = d\,u_x/u_z = {_num(self.d)} \cdot "
            rf"{_par(ux)} / {_par(uz)}$, and likewise $y$; $z = d$.",
        ]

    def worked(self):
        ux, uy, uz = self.u
        d = self.d
        image = np.array([d * ux, d * uy, d * uz, uz])
        point = image[:3] / image[3]
        return Worked([
            rf"The common direction as the point at infinity: $(u, 0) = "
            rf"{_vec(np.append(self.u, 0.0))}$ (the point $p_0$ does not matter).",
            rf"$P_{{PER}}\,(u, 0) = (d\,u_x, d\,u_y, d\,u_z, u_z) = {_vec(image)}$.",
            rf"Divide by $w = u_z = {_num(uz)}$: the vanishing point is ${_vec(point)}$, on the "
            rf"plane $z = d = {_num(d)}$.",
        ], point)
