"""Chapter 3 exercises: 2D composition, inverses and mirroring.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import format as fmt
from ... import transforms as tf
from ..core import DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import (_ANGLES_2D, _MATRIX_3, _affine2, _cos_sin, _deg, _degrees_text, _mat, _num,
               _par, _rot2, _rotation_words, _vec)

__all__ = [
    "ComposeMatrix2D",
    "InverseOfComposite",
    "MirrorAboutLine",
    "RotateAboutPoint",
]


_SCALES_2D = (2.0, 3.0, 0.5, -1.0, -2.0)


def _scaled_rotation(c, s, sx, sy):
    """The 2x2 block of R(theta) S(sx, sy): the columns of the rotation scaled."""
    return np.array([[c * sx, -s * sy], [s * sx, c * sy]])


class ComposeMatrix2D(DrawnExercise):
    r"""Compose a scaling, a rotation and a translation into one 2D homogeneous matrix.

    The points are scaled by :math:`S(s_x, s_y)`, then rotated by :math:`\theta` about the
    origin, then translated by :math:`d`, so :math:`M = T(d)\,R(\theta)\,S(s_x, s_y)`: with column
    vectors the first step is the rightmost factor.

    Attributes: ``sx``, ``sy``, ``theta_deg``, ``theta`` (radians), ``d``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = ComposeMatrix2D(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> listed_order = tf.scale([ex.sx, ex.sy]) @ tf.rotate(ex.theta) @ tf.translate(ex.d)
    >>> ex.check(listed_order).diagnosis
    'wrong order'
    >>> ex.check(...).status, ex.check("M").status
    ('unanswered', 'invalid')
    """

    title = "Scale, rotate, translate: one 2D matrix"

    def draw(self, rng):
        self.sx, self.sy = (float(v) for v in rng.choice(_SCALES_2D, size=2, replace=False))
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.theta = math.radians(self.theta_deg)
        self.d = small_ints(rng, 2)
        self.expected = tf.compose(self._scale(), tf.rotate(self.theta), tf.translate(self.d))

    def _scale(self):
        return tf.scale([self.sx, self.sy])

    def mistakes(self):
        S, R, T = self._scale(), tf.rotate(self.theta), tf.translate(self.d)
        right = T @ R @ S
        bottom_row = np.eye(3)
        bottom_row[:2, :2] = right[:2, :2]
        bottom_row[2, :2] = self.d
        return [
            Mistake(S @ R @ T, r"You multiplied the matrices from left to right in the order the "
                    r"steps are listed, $S\,R\,T$. With column vectors ($p' = Mp$) the factor "
                    r"next to $p$ acts first, so the first step must stand **rightmost**: "
                    r"$M = T(d)\,R(\theta)\,S(s_x, s_y)$.", "wrong order"),
            Mistake(T @ S @ R, r"You rotated before scaling ($T\,S\,R$). The scaling is the first "
                    r"step, so $S$ is the rightmost factor: $M = T\,R\,S$. With unequal factors "
                    r"$s_x \neq s_y$ the two orders give different matrices.",
                    "scale and rotation swapped"),
            Mistake(T @ tf.rotate(-self.theta) @ S, r"Your rotation turns the wrong way. The "
                    r"first row of $R(\theta)$ is $(\cos\theta,\ -\sin\theta)$ and the second "
                    r"$(\sin\theta,\ \cos\theta)$, so that a positive angle turns "
                    r"counter-clockwise.", "angle sign"),
            Mistake(bottom_row, r"You put the translation in the bottom row. That is the "
                    r"row-vector convention ($p' = pM$); with column vectors, as in the "
                    r"textbook, the translation is the last **column** and the bottom row is "
                    r"$(0, 0, 1)$.", "translation in bottom row"),
            Mistake(right.T, r"Your matrix is transposed: the translation ended up in the bottom "
                    r"row and the rotation turns the other way. With column vectors the images "
                    r"of the axes are the columns and the translation is the last column.",
                    "transposed"),
            Mistake(T @ tf.rotate(self.theta_deg) @ S, _degrees_text(self.theta_deg), "degrees"),
        ]

    def hints(self):
        c, s = _cos_sin(self.theta_deg)
        block = _scaled_rotation(c, s, self.sx, self.sy)
        return [
            r"With column vectors ($p' = M\,p$) the matrix next to $p$ acts first, so the step "
            r"done first stands **rightmost**: $M = T(d)\,R(\theta)\,S(s_x, s_y)$.",
            rf"Here {_rotation_words(self.theta_deg)}. Multiplying $R(\theta)$ on the right by "
            r"the diagonal $S$ multiplies its first column by $s_x$ and its second by $s_y$.",
            rf"The upper-left $2 \times 2$ block of $M$ is $R\,S = {_mat(block)}$. The "
            r"translation comes last, so nothing acts on it: the last column is "
            rf"$({_num(self.d[0])}, {_num(self.d[1])}, 1)$.",
        ]

    def worked(self):
        c, s = _cos_sin(self.theta_deg)
        S = np.diag([self.sx, self.sy, 1.0])
        R = _rot2(c, s)
        RS = R * np.array([self.sx, self.sy, 1.0])          # the columns of R, scaled
        M = RS.copy()
        M[:2, 2] = self.d                                    # T(d) (R S): d in the last column
        return Worked([
            r"The first step stands rightmost: $M = T(d)\,R(\theta)\,S(s_x, s_y)$.",
            rf"$S = {_mat(S)}$ and, with {_rotation_words(self.theta_deg)}, "
            rf"$R(\theta) = {_mat(R)}$.",
            rf"$R\,S$ scales the columns of $R$ by $s_x = {_num(self.sx)}$ and "
            rf"$s_y = {_num(self.sy)}$: $R\,S = {_mat(RS)}$.",
            rf"$T(d)$ on the left puts $d = {_vec(self.d)}$ into the last column and leaves the "
            rf"rest: $M = T(d)\,(R\,S) = {_mat(M)}$.",
        ], M)

    def statement(self):
        return (
            rf"A 2D shape is transformed in three steps: first it is scaled about the origin by "
            rf"$S(s_x, s_y)$ with $s_x = {fmt.number(self.sx)}$, $s_y = {fmt.number(self.sy)}$ "
            rf"(a negative factor mirrors), then rotated about the origin by "
            rf"$\theta = {_deg(self.theta_deg)}$ (counter-clockwise for a positive angle), and "
            rf"finally translated by $d = {_vec(self.d)}$." "\n\n"
            rf"Give the single matrix $M$ with $p' = M\,p$ that does all three steps." "\n\n"
            + _MATRIX_3 + "\n\n" + data_note("sx", "sy", "theta_deg", "theta", "d")
            + " (`.theta` is in radians.)")


class RotateAboutPoint(DrawnExercise):
    r"""The 2D rotation by :math:`\theta` about a point :math:`c`: :math:`T(c)\,R(\theta)\,T(-c)`.

    Attributes: ``theta_deg``, ``theta`` (radians), ``c``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = RotateAboutPoint(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(tf.rotate(ex.theta)).diagnosis
    'about origin'
    >>> swapped = tf.translate(-ex.c) @ tf.rotate(ex.theta) @ tf.translate(ex.c)
    >>> ex.check(swapped).diagnosis
    'wrong order'
    """

    title = "Rotation about a point (2D)"

    def draw(self, rng):
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.theta = math.radians(self.theta_deg)
        self.c = small_ints(rng, 2)
        self.expected = tf.rotate_about(self.theta, self.c)

    def mistakes(self):
        R, T_c, T_minus_c = tf.rotate(self.theta), tf.translate(self.c), tf.translate(-self.c)
        return [
            Mistake(T_minus_c @ R @ T_c, r"The translations are swapped: $T(-c)\,R\,T(c)$ "
                    r"rotates about $-c$. Read the product from the right: first $T(-c)$ moves "
                    r"$c$ to the origin, then $R$ rotates, then $T(c)$ moves it back, so "
                    r"$M = T(c)\,R(\theta)\,T(-c)$.", "wrong order"),
            Mistake(R, r"This rotates about the origin, not about $c$. Move $c$ to the origin "
                    r"first and back afterwards: $M = T(c)\,R(\theta)\,T(-c)$.", "about origin"),
            Mistake(T_c @ tf.rotate(-self.theta) @ T_minus_c, r"The fixed point is right but "
                    r"the rotation turns clockwise: in $R(\theta)$ the $-\sin\theta$ belongs in "
                    r"the first row.", "angle sign"),
            Mistake(R @ T_minus_c, r"You moved $c$ to the origin and rotated, but never moved "
                    r"it back: the last step $T(c)$ (leftmost factor) is missing.",
                    "missing T(c)"),
            Mistake(T_c @ R, r"You rotated about the origin and then translated by $c$: the "
                    r"first step $T(-c)$ (rightmost factor) is missing.", "missing T(-c)"),
            Mistake(tf.rotate_about(self.theta_deg, self.c), _degrees_text(self.theta_deg),
                    "degrees"),
        ]

    def _fixed_column(self):
        """R c and the last column c - R c, by hand."""
        c, s = _cos_sin(self.theta_deg)
        cx, cy = self.c
        rc = np.array([c * cx - s * cy, s * cx + c * cy])
        return rc, np.asarray(self.c, dtype=float) - rc

    def hints(self):
        rc, column = self._fixed_column()
        return [
            r"Only a rotation about the origin has a simple matrix. Move $c$ to the origin, "
            r"rotate, and move it back: $M = T(c)\,R(\theta)\,T(-c)$ (the first step is the "
            r"rightmost factor).",
            rf"The upper-left $2 \times 2$ block of $M$ is that of $R(\theta)$, with "
            rf"{_rotation_words(self.theta_deg)}; only the last column needs work: it is "
            r"$c - R\,c$, which keeps $c$ where it is.",
            rf"Here $R\,c = {_vec(rc)}$, so the last column is $c - R\,c = {_vec(column)}$.",
        ]

    def worked(self):
        c, s = _cos_sin(self.theta_deg)
        rc, column = self._fixed_column()
        M = _affine2([[c, -s], [s, c]], column)
        return Worked([
            r"$M = T(c)\,R(\theta)\,T(-c)$: for any point, $M\,p = c + R\,(p - c) = "
            r"R\,p + (c - R\,c)$. So the upper-left block is that of $R$, and the last column "
            r"is $c - R\,c$.",
            rf"{_rotation_words(self.theta_deg)}, so the block is "
            rf"$\begin{{bmatrix}} {_num(c)} & {_num(-s)} \\ {_num(s)} & {_num(c)} "
            r"\end{bmatrix}$.",
            rf"$R\,c = ({_par(c)} \cdot {_par(self.c[0])} - {_par(s)} \cdot "
            rf"{_par(self.c[1])},\ {_par(s)} \cdot {_par(self.c[0])} + {_par(c)} \cdot "
            rf"{_par(self.c[1])}) = {_vec(rc)}$, and $c - R\,c = {_vec(column)}$.",
            rf"$M = {_mat(M)}$. Check: $M$ sends $c = {_vec(self.c)}$ to itself.",
        ], M)

    def statement(self):
        return (
            rf"Find the homogeneous matrix $M$ of the 2D rotation by "
            rf"$\theta = {_deg(self.theta_deg)}$ (counter-clockwise for a positive angle) about "
            rf"the point $c = {_vec(self.c)}$, so that $p' = M\,p$. The point $c$ must stay "
            rf"where it is." "\n\n" + _MATRIX_3 + "\n\n" + data_note("theta_deg", "theta", "c")
            + " (`.theta` is in radians.)")


_SCALES_INVERTIBLE = (2.0, 4.0, 0.5, -1.0, -2.0)


class InverseOfComposite(DrawnExercise):
    r"""The inverse of :math:`M = T(d)\,R(\theta)\,S(s_x, s_y)` in 2D.

    :math:`M^{-1} = S(1/s_x, 1/s_y)\,R(-\theta)\,T(-d)`: each factor is inverted and the order
    reversed.

    Attributes: ``sx``, ``sy``, ``theta_deg``, ``theta`` (radians), ``d``, ``M``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = InverseOfComposite(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> same_order = (tf.translate(-ex.d) @ tf.rotate(-ex.theta)
    ...               @ tf.scale([1 / ex.sx, 1 / ex.sy]))
    >>> ex.check(same_order).diagnosis
    'same order'
    >>> ex.check(ex.M.T).diagnosis
    'transposed only'
    """

    title = "Inverse of a composite 2D transformation"

    def draw(self, rng):
        self.sx, self.sy = (float(v) for v in rng.choice(_SCALES_INVERTIBLE, size=2,
                                                         replace=False))
        self.theta_deg = int(pick(rng, _ANGLES_2D))
        self.theta = math.radians(self.theta_deg)
        self.d = small_ints(rng, 2)
        self.M = tf.translate(self.d) @ tf.rotate(self.theta) @ tf.scale([self.sx, self.sy])
        self.expected = tf.inverse(self.M)

    def mistakes(self):
        S_inv = tf.scale([1 / self.sx, 1 / self.sy])
        R_inv, T_inv = tf.rotate(-self.theta), tf.translate(-self.d)
        linear_inv = np.linalg.inv(self.M[:2, :2])
        negated_only = np.eye(3)
        negated_only[:2, :2] = linear_inv
        negated_only[:2, 2] = -self.d
        return [
            Mistake(T_inv @ R_inv @ S_inv, r"You inverted every factor but kept their order, "
                    r"$T^{-1} R^{-1} S^{-1}$. The inverse of a product reverses the order, "
                    r"$(ABC)^{-1} = C^{-1} B^{-1} A^{-1}$ (to undo the steps, undo the last one "
                    r"first): $M^{-1} = S^{-1}\,R(-\theta)\,T(-d)$.", "same order"),
            Mistake(self.M.T, r"Transposing inverts only a pure rotation (an orthogonal matrix). "
                    r"$M$ also scales and translates: invert each factor "
                    r"($S(1/s_x, 1/s_y)$, $R(-\theta)$, $T(-d)$) and multiply them in reverse "
                    r"order.", "transposed only"),
            Mistake(negated_only, r"The upper-left block is right, but the last column is not "
                    r"simply $-d$: the translation must be undone *before* the rotation and the "
                    r"scaling are, so the last column of $M^{-1}$ is $-A^{-1} d$, where $A$ is "
                    r"the upper-left $2 \times 2$ block of $M$.", "translation not transformed"),
            Mistake(tf.scale([self.sx, self.sy]) @ R_inv @ T_inv, r"The scaling is not "
                    r"inverted: the inverse of $S(s_x, s_y)$ is $S(1/s_x, 1/s_y)$.",
                    "scale not inverted"),
            Mistake(S_inv @ tf.rotate(self.theta) @ T_inv, r"The rotation is not inverted: the "
                    r"inverse of $R(\theta)$ is $R(-\theta) = R(\theta)^T$.",
                    "rotation not inverted"),
            Mistake(S_inv @ tf.rotate(-self.theta_deg) @ T_inv, _degrees_text(self.theta_deg),
                    "degrees"),
        ]

    def _inverse_block(self):
        """S(1/sx, 1/sy) R(-theta): the rows of R(-theta) divided by sx and sy."""
        c, s = _cos_sin(self.theta_deg)
        return np.array([[c / self.sx, s / self.sx], [-s / self.sy, c / self.sy]])

    def hints(self):
        block = self._inverse_block()
        return [
            r"To undo three steps, undo the last one first: "
            r"$(T\,R\,S)^{-1} = S^{-1}\,R^{-1}\,T^{-1}$. Invert each factor and reverse the "
            r"order.",
            rf"$S^{{-1}} = S({_num(1 / self.sx)}, {_num(1 / self.sy)})$, "
            rf"$R^{{-1}} = R(-\theta) = R(\theta)^T$ with {_rotation_words(self.theta_deg)}, "
            rf"and $T^{{-1}} = T({_vec(-np.asarray(self.d))})$.",
            rf"The upper-left block of $M^{{-1}}$ is $S^{{-1}} R(-\theta) = {_mat(block)}$; the "
            r"last column is that block times $-d$ (the translation is undone first, then "
            r"turned and scaled).",
        ]

    def worked(self):
        c, s = _cos_sin(self.theta_deg)
        block = self._inverse_block()
        column = block @ (-np.asarray(self.d, dtype=float))
        M_inv = _affine2(block, column)
        return Worked([
            r"$M^{-1} = S(s_x, s_y)^{-1}\,R(\theta)^{-1}\,T(d)^{-1} = "
            r"S(1/s_x, 1/s_y)\,R(-\theta)\,T(-d)$.",
            rf"$R(-\theta) = \begin{{bmatrix}} {_num(c)} & {_num(s)} \\ {_num(-s)} & "
            rf"{_num(c)} \end{{bmatrix}}$ (the transpose of $R(\theta)$); $S^{{-1}}$ divides "
            rf"its first row by $s_x = {_num(self.sx)}$ and its second by "
            rf"$s_y = {_num(self.sy)}$: ${_mat(block)}$.",
            rf"$T(-d)$ acts first, so the last column is this block times "
            rf"$-d = {_vec(-np.asarray(self.d))}$: ${_vec(column)}$.",
            rf"$M^{{-1}} = {_mat(M_inv)}$. Check: $M^{{-1}} M = I$.",
        ], M_inv)

    def statement(self):
        return (
            rf"Let $M = T(d)\,R(\theta)\,S(s_x, s_y)$ with $d = {_vec(self.d)}$, "
            rf"$\theta = {_deg(self.theta_deg)}$, $s_x = {fmt.number(self.sx)}$ and "
            rf"$s_y = {fmt.number(self.sy)}$ (homogeneous 2D matrices, column vectors)." "\n\n"
            rf"Give $M^{{-1}}$, the matrix that undoes $M$. Build it from the inverses of the "
            rf"three factors rather than by a general matrix inversion." "\n\n" + _MATRIX_3
            + "\n\n" + data_note("sx", "sy", "theta_deg", "theta", "d", "M")
            + " (`.theta` is in radians; `.M` is the matrix $M$.)")


_MIRROR_ANGLES = (30, 45, 60, 120, 135, 150)


class MirrorAboutLine(DrawnExercise):
    r"""Mirroring about a line through :math:`c` at angle :math:`\varphi` to the x axis (2D).

    .. math:: M = T(c)\,R(\varphi)\,S(1, -1)\,R(-\varphi)\,T(-c)

    Move the line onto the x axis, mirror about the x axis, move it back.

    Attributes: ``phi_deg``, ``phi`` (radians), ``c``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = MirrorAboutLine(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> R, S = tf.rotate(ex.phi), tf.mirror("x")
    >>> ex.check(R @ S @ R.T).diagnosis
    'line through origin'
    """

    title = "Mirroring about a line (2D)"

    def draw(self, rng):
        self.phi_deg = int(pick(rng, _MIRROR_ANGLES))
        self.phi = math.radians(self.phi_deg)
        self.c = small_ints(rng, 2)
        self.expected = self._mirror(self.c, self.phi)

    @staticmethod
    def _mirror(c, phi):
        return (tf.translate(c) @ tf.rotate(phi) @ tf.mirror("x") @ tf.rotate(-phi)
                @ tf.translate(-np.asarray(c)))

    def mistakes(self):
        S = tf.mirror("x")
        T_c, T_minus_c = tf.translate(self.c), tf.translate(-self.c)
        R, R_inv = tf.rotate(self.phi), tf.rotate(-self.phi)
        return [
            Mistake(R @ S @ R_inv, r"This mirrors about the parallel line through the origin. "
                    r"The line passes through $c$: move $c$ to the origin first ($T(-c)$, "
                    r"rightmost) and back at the end ($T(c)$, leftmost).",
                    "line through origin"),
            Mistake(T_c @ R_inv @ S @ R @ T_minus_c, r"The two rotations are swapped, so you "
                    r"mirrored about the line at angle $-\varphi$. To bring the line onto the "
                    r"x axis rotate by $-\varphi$ first (right of $S$), and turn it back with "
                    r"$R(\varphi)$ afterwards (left of $S$).", "rotations swapped"),
            Mistake(T_minus_c @ R @ S @ R_inv @ T_c, r"The two translations are swapped: the "
                    r"first step (rightmost factor) must be $T(-c)$, which brings $c$ to the "
                    r"origin.", "translations swapped"),
            Mistake(T_c @ S @ T_minus_c, r"This mirrors about the horizontal line through $c$: "
                    r"the line is tilted by $\varphi$, so it must be turned onto the x axis "
                    r"($R(-\varphi)$) before mirroring and turned back ($R(\varphi)$) after.",
                    "no rotation"),
            Mistake(self._mirror(self.c, self.phi_deg),
                    _degrees_text(self.phi_deg, r"\varphi"), "degrees"),
        ]

    def _block(self):
        """R(phi) S(1, -1) R(-phi) = [[cos 2phi, sin 2phi], [sin 2phi, -cos 2phi]]."""
        c2, s2 = _cos_sin(2 * self.phi_deg)
        return np.array([[c2, s2], [s2, -c2]]), c2, s2

    def hints(self):
        L, c2, s2 = self._block()
        column = np.asarray(self.c, dtype=float) - L @ self.c
        return [
            r"Mirroring about the x axis is easy, $S(1, -1)$. Move the line onto the x axis "
            r"(first $T(-c)$, then $R(-\varphi)$), mirror, and move it back: "
            r"$M = T(c)\,R(\varphi)\,S(1, -1)\,R(-\varphi)\,T(-c)$.",
            r"The middle part is the mirroring about the parallel line through the origin, "
            r"$R(\varphi)\,S(1,-1)\,R(-\varphi) = \begin{bmatrix} \cos 2\varphi & "
            rf"\sin 2\varphi \\ \sin 2\varphi & -\cos 2\varphi \end{{bmatrix}}$; here "
            rf"$2\varphi = {2 * self.phi_deg}^\circ$, $\cos 2\varphi = {_num(c2)}$, "
            rf"$\sin 2\varphi = {_num(s2)}$.",
            rf"The points of the line stay where they are, so the last column is $c - L\,c$ "
            rf"with that block $L$: here ${_vec(column)}$.",
        ]

    def worked(self):
        L, c2, s2 = self._block()
        Lc = L @ np.asarray(self.c, dtype=float)
        column = np.asarray(self.c, dtype=float) - Lc
        M = _affine2(L, column)
        return Worked([
            r"$M = T(c)\,R(\varphi)\,S(1, -1)\,R(-\varphi)\,T(-c)$, so "
            r"$M\,p = c + L\,(p - c)$ with $L = R(\varphi)\,S(1,-1)\,R(-\varphi)$.",
            r"Multiplying out, $L = \begin{bmatrix} \cos^2\varphi - \sin^2\varphi & "
            r"2 \sin\varphi\cos\varphi \\ 2 \sin\varphi\cos\varphi & "
            r"\sin^2\varphi - \cos^2\varphi \end{bmatrix} = \begin{bmatrix} \cos 2\varphi "
            r"& \sin 2\varphi \\ \sin 2\varphi & -\cos 2\varphi \end{bmatrix}$; with "
            rf"$2\varphi = {2 * self.phi_deg}^\circ$: $L = {_mat(L)}$.",
            rf"$L\,c = {_vec(Lc)}$, so the last column is $c - L\,c = {_vec(column)}$.",
            rf"$M = {_mat(M)}$. Check: $M\,c = c$, and $M\,M = I$ (mirroring twice changes "
            r"nothing).",
        ], M)

    def statement(self):
        return (
            rf"The line $\ell$ passes through the point $c = {_vec(self.c)}$ and makes the angle "
            rf"$\varphi = {_deg(self.phi_deg)}$ with the positive x axis. Give the homogeneous "
            rf"matrix $M$ of the mirroring (reflection) about $\ell$, so that $p' = M\,p$. "
            rf"Mirroring about the x axis is the scaling $S(1, -1)$." "\n\n" + _MATRIX_3
            + "\n\n" + data_note("phi_deg", "phi", "c") + " (`.phi` is in radians.)")
