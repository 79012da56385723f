r"""Chapter 3 exercises: normals, change of frame, scaling about a point, w != 1, mirrors.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here. The expected
answers come from :mod:`course_lib.frames`.
"""

import math

import numpy as np

from ... import frames as fr
from ... import transforms as tf
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import (_ANGLES_2D, _MATRIX_3, _MATRIX_4, PointAnswer, _cos_sin, _deg, _mat, _num,
               _par, _vec)

__all__ = [
    "FrameCoordinates",
    "HomogeneousRotationAngle",
    "MirrorAboutPlane",
    "NormalUnderShear",
    "ScaleAboutPoint",
]


def _unit_of(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


# ---------------------------------------------------------------------------------------------
# Normals
# ---------------------------------------------------------------------------------------------

class NormalUnderShear(DrawnExercise):
    r"""The unit normal of a line after a 2D map with a shear: :math:`n' \propto A^{-T} n`.

    Attributes: ``M`` (3x3 homogeneous), ``A`` (its 2x2 linear part), ``n``.

    Examples
    --------
    >>> import numpy as np
    >>> ex = NormalUnderShear(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> naive = ex.A @ ex.n
    >>> ex.check(naive / np.linalg.norm(naive)).diagnosis
    'used M'
    """

    title = "Transforming a normal (2D)"
    answer_form = "vector"
    what = "the unit normal"

    def draw(self, rng):
        a, d = (float(v) for v in rng.choice([1.0, 2.0, 3.0, 4.0], size=2))
        b = float(pick(rng, (-2.0, -1.0, 1.0, 2.0)))
        self.A = np.array([[a, b], [0.0, d]]) if rng.random() < 0.5 else \
            np.array([[a, 0.0], [b, d]])
        self.M = np.eye(3)
        self.M[:2, :2] = self.A
        self.M[:2, 2] = small_ints(rng, 2)
        self.n = small_ints(rng, 2, -2, 2)
        self.expected = fr.transform_normals(self.n, self.M)

    def acceptable(self):
        return bool(np.all(self.n != 0))

    def mistakes(self):
        A, n = self.A, self.n
        inv_t = np.linalg.inv(A).T
        return [
            Mistake(_unit_of(A @ n), r"You transformed the normal with the matrix itself, "
                    r"$A\,n$. That is right for tangents, not for normals: with a shear or a "
                    r"non-uniform scale $A\,n$ is no longer perpendicular to the transformed "
                    r"line. Use the inverse transpose $A^{-T} n$, which keeps "
                    r"$n' \cdot (A t) = n^T A^{-1} A t = 0$.", "used M"),
            Mistake(_unit_of(np.linalg.inv(A) @ n), r"You used the inverse $A^{-1} n$ but "
                    r"forgot to transpose it. The normal matrix is $(A^{-1})^T$: in "
                    r"$n'^T (A t) = 0$ the inverse has to act from the left on $n^T$, which is "
                    r"the transpose acting on $n$.", "inverse not transposed"),
            Mistake(_unit_of(A.T @ n), r"You transposed $A$ but did not invert it. The normal "
                    r"matrix is the inverse **and** the transpose: $A^{-T} n$.",
                    "transposed only"),
            Mistake(inv_t @ n, r"The direction is right, but the question asks for a **unit** "
                    r"normal: the inverse transpose changes lengths, so divide $A^{-T} n$ by "
                    r"its length.", "not normalised"),
        ]

    may_coincide = ("not normalised",)

    def _steps(self):
        (a, b), (c, d) = self.A
        det = a * d - b * c
        inv = np.array([[d, -b], [-c, a]]) / det
        inv_t = inv.T
        raw = inv_t @ self.n
        return det, inv, inv_t, raw

    def hints(self):
        det, inv, inv_t, raw = self._steps()
        return [
            r"Normals do not transform with $A$: they transform with the inverse transpose "
            r"$A^{-T}$ of the linear part (the translation does not act on directions).",
            rf"$\det A = {_num(det)}$, so $A^{{-1}} = {_mat(inv)}$ and "
            rf"$A^{{-T}} = {_mat(inv_t)}$.",
            rf"$A^{{-T}} n = {_vec(raw)}$; divide by its length.",
        ]

    def worked(self):
        det, inv, inv_t, raw = self._steps()
        length = float(np.linalg.norm(raw))
        unit = raw / length
        return Worked([
            rf"The linear part of $M$ is $A = {_mat(self.A)}$; the translation "
            rf"${_vec(self.M[:2, 2])}$ does not act on a normal (a direction).",
            rf"$\det A = {_num(det)}$, $A^{{-1}} = \frac{{1}}{{\det A}}"
            rf"\begin{{bmatrix}} d & -b \\ -c & a \end{{bmatrix}} = {_mat(inv)}$, "
            rf"so $A^{{-T}} = {_mat(inv_t)}$.",
            rf"$A^{{-T}} n = {_mat(inv_t)} {_vec(self.n, column=True)} = {_vec(raw)}$.",
            rf"Its length is ${_num(length)}$, so $n' = {_vec(unit)}$. Check: $n'$ is "
            r"perpendicular to $A\,t$ for the line's tangent $t \perp n$.",
        ], unit)

    def statement(self):
        return (
            rf"A line in the plane has the normal $n = {_vec(self.n)}$. The whole plane is "
            rf"transformed by the homogeneous matrix $M = {_mat(self.M)}$ (a shear and a "
            r"scale, then a translation)." "\n\n"
            r"Give the **unit** normal $n'$ of the transformed line, on the side where the "
            r"points that $n$ pointed to end up." "\n\n"
            r"**Answer:** a list of 2 numbers `[x, y]`. " + DECIMALS + "\n\n"
            + data_note("M", "A", "n"))


# ---------------------------------------------------------------------------------------------
# Change of frame
# ---------------------------------------------------------------------------------------------

#: Unit vectors with rational components (first axes of a frame; the second is turned by 90).
_UNIT_AXES = ((1, 0), (0, 1), (-1, 0), (0, -1), (0.6, 0.8), (0.8, 0.6), (-0.6, 0.8),
              (0.8, -0.6), (-0.8, -0.6), (0.6, -0.8))


class FrameCoordinates(PointAnswer, DrawnExercise):
    r"""The coordinates of a point in a new 2D frame: :math:`p_F = R^T (p - o)`.

    The frame has origin :math:`o` and orthonormal axes :math:`u, v` (:math:`v` is :math:`u`
    turned by :math:`+90^\circ`); the world-to-frame matrix is
    :math:`\begin{bmatrix} R^T & -R^T o \\ 0 & 1 \end{bmatrix}` with :math:`R = [u\ v]`.

    Attributes: ``o``, ``u``, ``v``, ``p``.

    Examples
    --------
    >>> import numpy as np
    >>> ex = FrameCoordinates(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> R = np.column_stack([ex.u, ex.v])
    >>> ex.check(ex.o + R @ ex.p).diagnosis
    'frame to world'
    """

    title = "Coordinates in a new frame (2D)"
    what = "the frame coordinates"

    def draw(self, rng):
        self.u = np.array(pick(rng, _UNIT_AXES), dtype=float)
        self.v = np.array([-self.u[1], self.u[0]])
        self.o = small_ints(rng, 2)
        self.p = small_ints(rng, 2, -4, 4)
        self.expected = tf.apply(fr.world_to_frame(self.o, [self.u, self.v]), self.p)

    def acceptable(self):
        return bool(np.any(self.p != self.o))

    def mistakes(self):
        R = np.column_stack([self.u, self.v])
        return [
            Mistake(self.o + R @ self.p, r"You used the frame-to-world matrix "
                    r"$F = \begin{bmatrix} R & o \\ 0 & 1 \end{bmatrix}$: it takes frame "
                    r"coordinates to world ones. The question goes the other way, world to "
                    r"frame, so use its inverse $\begin{bmatrix} R^T & -R^T o \\ 0 & 1 "
                    r"\end{bmatrix}$.", "frame to world"),
            Mistake(R @ (self.p - self.o), r"You multiplied by $R$ (the axes as columns) "
                    r"instead of $R^T$ (the axes as rows). A frame coordinate is a dot "
                    r"product with an axis, $u \cdot (p - o)$, so the axes are the **rows** "
                    r"of the world-to-frame matrix.", "transposed"),
            Mistake(R.T @ self.p, r"You forgot the origin: $R^T p$ measures $p$ from the "
                    r"world origin. Subtract the frame's origin first: $R^T (p - o)$.",
                    "forgot origin"),
            Mistake(R.T @ self.p - self.o, r"You subtracted $o$ after rotating: the "
                    r"translation column of the world-to-frame matrix is $-R^T o$, not $-o$ "
                    r"(compute $R^T (p - o)$).", "origin not rotated"),
        ]

    def hints(self):
        d = self.p - self.o
        return [
            r"Move to the frame's origin, then measure along each axis: the frame "
            r"coordinates are $(u \cdot (p - o),\ v \cdot (p - o))$.",
            rf"The point seen from the frame's origin is $p - o = {_vec(d)}$.",
            r"Since $u$ and $v$ are orthonormal, $R^{-1} = R^T$ (axes as rows): no matrix "
            r"inversion is needed.",
        ]

    def worked(self):
        d = self.p - self.o
        a, b = float(self.u @ d), float(self.v @ d)
        W = np.eye(3)
        W[0, :2], W[1, :2] = self.u, self.v
        W[:2, 2] = [-(self.u @ self.o), -(self.v @ self.o)]
        return Worked([
            rf"The world-to-frame matrix has the axes as rows and $-R^T o$ as last column: "
            rf"$W = {_mat(W)}$.",
            rf"Equivalently, $p - o = {_vec(self.p)} - {_vec(self.o)} = {_vec(d)}$.",
            rf"$u \cdot (p - o) = {_par(self.u[0])} \cdot {_par(d[0])} + {_par(self.u[1])} "
            rf"\cdot {_par(d[1])} = {_num(a)}$ and $v \cdot (p - o) = {_par(self.v[0])} \cdot "
            rf"{_par(d[0])} + {_par(self.v[1])} \cdot {_par(d[1])} = {_num(b)}$.",
            rf"So $p_F = ({_num(a)}, {_num(b)})$. Check: $o + {_par(a)}\,u + {_par(b)}\,v = "
            rf"{_vec(self.p)}$.",
        ], np.array([a, b]))

    def statement(self):
        return (
            rf"A 2D frame has its origin at $o = {_vec(self.o)}$ and the orthonormal axes "
            rf"$u = {_vec(self.u)}$, $v = {_vec(self.v)}$ (world coordinates)." "\n\n"
            rf"What are the coordinates of the world point $p = {_vec(self.p)}$ in this "
            r"frame, i.e. the numbers $(a, b)$ with $p = o + a\,u + b\,v$?" "\n\n"
            r"**Answer:** a list of 2 numbers `[a, b]` (a homogeneous `[a, b, 1]` is "
            r"accepted too). " + DECIMALS + "\n\n" + data_note("o", "u", "v", "p"))


# ---------------------------------------------------------------------------------------------
# Scaling about a point
# ---------------------------------------------------------------------------------------------

_FACTORS = (2.0, 3.0, 0.5, -1.0)


class ScaleAboutPoint(DrawnExercise):
    r"""Scaling about a point :math:`c` in 2D: :math:`T(c)\,S(s_x, s_y)\,T(-c)`.

    Attributes: ``sx``, ``sy``, ``c``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = ScaleAboutPoint(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(tf.scale([ex.sx, ex.sy])).diagnosis
    'about origin'
    """

    title = "Scaling about a point (2D)"

    def draw(self, rng):
        self.sx, self.sy = (float(v) for v in rng.choice(_FACTORS, size=2, replace=False))
        self.c = small_ints(rng, 2)
        self.expected = fr.scale_about(self.c, [self.sx, self.sy])

    def acceptable(self):
        return bool(np.all(self.c != 0))

    def mistakes(self):
        S, Tc, Tm = tf.scale([self.sx, self.sy]), tf.translate(self.c), tf.translate(-self.c)
        return [
            Mistake(Tm @ S @ Tc, r"The translations are swapped: $T(-c)\,S\,T(c)$ scales "
                    r"about $-c$. Read from the right: $T(-c)$ first moves $c$ to the origin, "
                    r"$S$ scales there, $T(c)$ moves back: $M = T(c)\,S\,T(-c)$.",
                    "wrong order"),
            Mistake(S, r"This scales about the origin, so $c$ moves. Move $c$ to the origin "
                    r"first and back afterwards: $M = T(c)\,S\,T(-c)$.", "about origin"),
            Mistake(S @ Tm, r"You moved $c$ to the origin and scaled, but never moved it "
                    r"back: the leftmost factor $T(c)$ is missing.", "missing T(c)"),
            Mistake(Tc @ S, r"You scaled about the origin and then translated by $c$: the "
                    r"first step $T(-c)$ (rightmost factor) is missing.", "missing T(-c)"),
        ]

    def _column(self):
        return self.c - np.array([self.sx, self.sy]) * self.c

    def hints(self):
        return [
            r"Only a scaling about the origin has a diagonal matrix. Move $c$ to the origin, "
            r"scale, move back: $M = T(c)\,S\,T(-c)$ (the first step stands rightmost).",
            r"For any point $M p = c + S (p - c) = S p + (c - S c)$: the upper-left block is "
            r"that of $S$, the last column is $c - S c$.",
            rf"Here $S c = {_vec(np.array([self.sx, self.sy]) * self.c)}$, so the last column "
            rf"is ${_vec(self._column())}$.",
        ]

    def worked(self):
        sc = np.array([self.sx, self.sy]) * self.c
        col = self._column()
        M = np.diag([self.sx, self.sy, 1.0])
        M[:2, 2] = col
        return Worked([
            r"$M = T(c)\,S\,T(-c)$, so $M p = c + S\,(p - c) = S\,p + (c - S\,c)$.",
            rf"$S c = ({_par(self.sx)} \cdot {_par(self.c[0])},\ {_par(self.sy)} \cdot "
            rf"{_par(self.c[1])}) = {_vec(sc)}$.",
            rf"$c - S c = {_vec(self.c)} - {_vec(sc)} = {_vec(col)}$.",
            rf"$M = {_mat(M)}$. Check: $M$ sends $c = {_vec(self.c)}$ to itself.",
        ], M)

    def statement(self):
        return (
            rf"Find the homogeneous matrix $M$ that scales the plane by $s_x = "
            rf"{_num(self.sx)}$ along x and $s_y = {_num(self.sy)}$ along y (a negative factor "
            rf"mirrors) **about the point** $c = {_vec(self.c)}$, which must stay where it is, "
            r"so that $p' = M\,p$." "\n\n" + _MATRIX_3 + "\n\n" + data_note("sx", "sy", "c"))


# ---------------------------------------------------------------------------------------------
# Homogeneous matrices with w != 1
# ---------------------------------------------------------------------------------------------

_W = (2.0, 3.0, 4.0, 5.0, -2.0, -3.0)


def _wrap(angle_deg):
    """An angle in degrees in (-180, 180]."""
    a = (angle_deg + 180.0) % 360.0 - 180.0
    return 180.0 if a == -180.0 else a


class HomogeneousRotationAngle(DrawnExercise):
    r"""Is :math:`w\,R(\theta)` (with the bottom-right entry :math:`w`) a rotation? Its angle.

    A homogeneous matrix and its non-zero multiples are the same map, so dividing by
    :math:`w` leaves :math:`R(\theta)`: a rotation, not a scale.

    Attributes: ``M``, ``w``, ``theta_deg``.

    Examples
    --------
    >>> ex = HomogeneousRotationAngle(seed=4)
    >>> ex.check(ex.theta_deg).status
    'correct'
    >>> ex.check(0).diagnosis
    'called a scale'
    """

    title = "A homogeneous matrix with w ≠ 1: rotation?"
    answer_form = "number"
    what = "the angle"

    def draw(self, rng):
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.w = float(pick(rng, _W))
        c, s = _cos_sin(self.theta_deg)
        self.M = self.w * np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        self.expected = fr.describe_linear(self.M).angle_deg

    def mistakes(self):
        out = [
            Mistake(0.0, r"You called it a scaling by $w$. But $w$ is the homogeneous "
                    r"coordinate: $(x, y, w)$ and $(x/w, y/w, 1)$ are the same point, so "
                    r"dividing the whole matrix by $w$ changes nothing, and what is left is an "
                    r"orthonormal block with determinant $+1$: a rotation.", "called a scale"),
            Mistake(-float(self.theta_deg), r"Your angle has the wrong sign: after dividing by "
                    r"$w$ the block is $\begin{bmatrix} \cos\theta & -\sin\theta \\ \sin\theta "
                    r"& \cos\theta \end{bmatrix}$, so $\sin\theta$ is the **lower-left** entry.",
                    "angle sign"),
            Mistake(math.radians(self.theta_deg), r"That is the angle in radians; the "
                    r"question asks for degrees.", "radians"),
        ]
        if self.w < 0:
            out.append(Mistake(_wrap(self.theta_deg + 180.0), r"You read the angle from the "
                               r"entries without dividing by $w < 0$: that flips both "
                               r"$\cos$ and $\sin$, a half turn too many. Divide the whole "
                               r"matrix by $w$ first.", "w not divided"))
        return out

    def hints(self):
        return [
            r"A homogeneous matrix and any non-zero multiple of it do the same thing to points "
            r"(each image point is divided by its last coordinate).",
            rf"Divide $M$ by its bottom-right entry $w = {_num(self.w)}$.",
            r"Then read $\cos\theta$ (upper-left) and $\sin\theta$ (lower-left) of the "
            r"rotation block.",
        ]

    def worked(self):
        c, s = _cos_sin(self.theta_deg)
        R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
        return Worked([
            rf"$M = {_mat(self.M)}$ has $w = {_num(self.w)}$ in the corner. Divide the whole "
            rf"matrix by it (the same map): $M / w = {_mat(R)}$.",
            r"The $2 \times 2$ block is orthonormal (unit columns, perpendicular) with "
            r"determinant $\cos^2\theta + \sin^2\theta = 1$: a rotation about the origin, not a "
            r"scaling.",
            rf"$\cos\theta = {_num(c)}$, $\sin\theta = {_num(s)}$, so "
            rf"$\theta = {_deg(self.theta_deg)}$.",
        ], float(self.theta_deg))

    def statement(self):
        return (
            rf"A 2D homogeneous matrix is $M = {_mat(self.M)}$. Someone says it is a scaling "
            rf"by ${_num(self.w)}$. Is it? Work out what $M$ does to a point $(x, y, 1)$." "\n\n"
            r"If $M$ is a rotation about the origin, give its angle $\theta$ in **degrees**, in "
            r"$(-180^\circ, 180^\circ]$, counter-clockwise positive; if it is only a scaling, "
            r"answer 0." "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n" + data_note("M", "w"))


# ---------------------------------------------------------------------------------------------
# Mirroring about a plane
# ---------------------------------------------------------------------------------------------

_PLANE_NORMALS = ((1, 2, 2), (2, 1, 2), (2, 2, 1), (0, 3, 4), (4, 0, 3), (3, 4, 0))


class MirrorAboutPlane(DrawnExercise):
    r"""Mirroring about the plane :math:`m \cdot p = k` (3D):
    :math:`\begin{bmatrix} I - 2 n n^T & 2 d\, n \\ 0 & 1 \end{bmatrix}` with the unit normal
    :math:`n = m / |m|` and the distance :math:`d = k / |m|` of the plane from the origin.

    Attributes: ``m`` (whole-number normal), ``k``, ``length`` (:math:`|m|`).

    Examples
    --------
    >>> import numpy as np
    >>> ex = MirrorAboutPlane(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> moved = ex.expected.copy(); moved[:3, 3] = 0
    >>> ex.check(moved).diagnosis
    'through origin'
    """

    title = "Mirroring about a plane (3D)"

    def draw(self, rng):
        self.m = rng.permutation(np.array(pick(rng, _PLANE_NORMALS), dtype=float))
        self.m *= rng.choice([-1.0, 1.0], size=3)
        self.m[self.m == 0] = 0.0
        self.length = float(np.linalg.norm(self.m))
        self.k = float(pick(rng, (-2.0, -1.0, 1.0, 2.0))) * self.length
        self.expected = fr.mirror_plane(self.k / self.length ** 2 * self.m, self.m)

    def mistakes(self):
        L, k = self.length, self.k
        n = self.m / L
        H = np.eye(3) - 2 * np.outer(n, n)

        def affine(block, column):
            out = np.eye(4)
            out[:3, :3], out[:3, 3] = block, column
            return out

        raw = np.eye(3) - 2 * np.outer(self.m, self.m)
        return [
            Mistake(affine(raw, 2 * k * self.m), r"You used the normal as given, without "
                    r"dividing it by its length. $I - 2 n n^T$ is a mirror only for a **unit** "
                    r"$n$; use $n = m / |m|$.", "not normalised"),
            Mistake(affine(np.eye(3) - np.outer(n, n), (k / L) * n), r"That is the "
                    r"projection onto the plane ($I - n n^T$): it removes the normal "
                    r"component once. A mirror removes it twice, $I - 2 n n^T$.",
                    "projection"),
            Mistake(affine(H, np.zeros(3)), r"This mirrors about the parallel plane through "
                    r"the origin. The plane is at distance $d = k / |m|$ from it, so the last "
                    r"column is $2 d\, n$.", "through origin"),
            Mistake(affine(H, -2 * (k / L) * n), r"The translation has the wrong sign: a point "
                    r"$p$ of the plane must stay put, $H p + t = p$ with $H p = p - 2 d\, n$, "
                    r"so $t = +2 d\, n$.", "translation sign"),
        ]

    def _numbers(self):
        L = self.length
        n = self.m / L
        d = self.k / L
        return n, d, np.eye(3) - 2 * np.outer(n, n), 2 * d * n

    def hints(self):
        n, d, H, t = self._numbers()
        return [
            r"Mirror about a plane through the origin with the Householder matrix "
            r"$H = I - 2 n n^T$ ($n$ a unit normal), then account for the plane's offset.",
            rf"$|m| = {_num(self.length)}$, so $n = {_vec(n)}$ and the plane is "
            rf"$n \cdot p = d$ with $d = {_num(d)}$.",
            rf"A point $p$ maps to $p - 2 (n \cdot p - d)\, n = H p + 2 d\, n$: the last "
            rf"column is $2 d\, n = {_vec(t)}$.",
        ]

    def worked(self):
        n, d, H, t = self._numbers()
        L2 = int(round(self.length ** 2))
        M = np.eye(4)
        M[:3, :3], M[:3, 3] = H, t
        return Worked([
            rf"Unit normal: $n = m / |m| = {_vec(self.m)} / {_num(self.length)}$; the plane "
            rf"$m \cdot p = {_num(self.k)}$ is $n \cdot p = d$ with $d = {_num(d)}$.",
            rf"$2 n n^T = \frac{{2}}{{{L2}}} {_mat(np.outer(self.m, self.m))}$, so "
            rf"$H = I - 2 n n^T = {_mat(H)}$.",
            rf"$p' = p - 2 (n \cdot p - d)\, n = H p + 2 d\, n$, and $2 d\, n = {_vec(t)}$.",
            rf"$M = {_mat(M)}$. Check: $M M = I$, and the plane's point $d\,n$ stays put.",
        ], M)

    def statement(self):
        terms = ""
        for v, x in zip((int(v) for v in self.m), "xyz"):
            if v == 0:
                continue
            coefficient = "" if abs(v) == 1 else str(abs(v))
            sign = ("-" if v < 0 else "") if not terms else (" - " if v < 0 else " + ")
            terms += f"{sign}{coefficient}{x}"
        return (
            rf"Give the homogeneous $4 \times 4$ matrix $M$ that mirrors 3D space about the "
            rf"plane ${terms} = {_num(self.k)}$, so that $p' = M\,p$." "\n\n"
            + _MATRIX_4 + "\n\n" + data_note("m", "k", "length"))
