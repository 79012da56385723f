"""Chapter 3 exercises: 3D rotation about an arbitrary axis.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import transforms as tf
from ..core import DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import (_ANGLES_3D, _POINT_3, PointAnswer, _cos_sin, _deg, _degrees_text, _nice_axis,
               _num, _rodrigues, _rotation_words, _snap, _vec)

__all__ = [
    "RotationAboutArbitraryAxis",
]


class RotationAboutArbitraryAxis(PointAnswer, DrawnExercise):
    r"""Rotate a point about the line through :math:`a` with direction :math:`u`.

    The rotation is :math:`T(a)\,R_u(\theta)\,T(-a)`, where :math:`R_u(\theta)` rotates about the
    parallel axis through the origin (Rodrigues' formula, or the textbook's product of elementary
    rotations).

    Attributes: ``a`` (a point of the axis), ``u`` (its direction, not of unit length),
    ``theta_deg``, ``theta`` (radians), ``p`` (the point to rotate).

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = RotationAboutArbitraryAxis(seed=8)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(tf.apply(tf.rotate_axis(ex.u, ex.theta), ex.p)).diagnosis
    'axis through origin'
    """

    title = "Rotation about an arbitrary axis (3D)"
    what = "the rotated point"

    def draw(self, rng):
        self.a = small_ints(rng, 3, -2, 2)
        self.u = _nice_axis(rng)
        self.theta_deg = int(pick(rng, _ANGLES_3D))
        self.theta = math.radians(self.theta_deg)
        self.p = small_ints(rng, 3, -2, 2)
        self.expected = _snap(tf.apply(tf.rotate_axis(self.u, self.theta, self.a), self.p))

    def mistakes(self):
        R = tf.rotate_axis(self.u, self.theta)
        return [
            Mistake(tf.apply(R, self.p), r"You rotated about the parallel axis through the "
                    r"origin. The axis passes through $a$: translate by $-a$ first, rotate, "
                    r"then translate back by $a$, i.e. $p' = a + R\,(p - a)$.",
                    "axis through origin"),
            Mistake(tf.apply(tf.rotate_axis(self.u, -self.theta, self.a), self.p), r"The "
                    r"rotation turns the wrong way (by $-\theta$). Positive angles are "
                    r"counter-clockwise when you look from the tip of $u$ back towards the axis; "
                    r"check the signs of the $\sin\theta$ terms (in Rodrigues' formula, "
                    r"$+\sin\theta\,(\hat u \times v)$).", "angle sign"),
            Mistake(tf.apply(R, self.p - self.a), r"You translated by $-a$ and rotated, but did "
                    r"not translate back by $+a$ at the end.", "missing T(a)"),
            Mistake(tf.apply(R, self.p) + self.a, r"You rotated and translated by $+a$, but "
                    r"forgot to translate by $-a$ first: $p' = a + R\,(p - a)$.",
                    "missing T(-a)"),
            Mistake(tf.apply(tf.rotate_axis(self.u, self.theta_deg, self.a), self.p),
                    _degrees_text(self.theta_deg), "degrees"),
        ]

    def _steps(self):
        """The numbers of the worked solution: unit axis, p - a, its parts, the rotated one."""
        length = float(np.linalg.norm(self.u))
        k = self.u / length
        v = self.p - self.a
        c, s = _cos_sin(self.theta_deg)
        return length, k, v, float(k @ v), np.cross(k, v), c, s

    def hints(self):
        length, k, v, along, across, c, s = self._steps()
        return [
            r"The axis does not pass through the origin. Move it there, rotate about the "
            r"parallel axis through the origin, and move back: $p' = a + R_{\hat u}(\theta)\,"
            r"(p - a)$.",
            rf"The unit axis is $\hat u = u / {_num(length)} = {_vec(k)}$ and "
            rf"$v = p - a = {_vec(v)}$. Rodrigues' formula: $R\,v = \cos\theta\,v + "
            r"\sin\theta\,(\hat u \times v) + (1 - \cos\theta)(\hat u \cdot v)\,\hat u$.",
            rf"Here {_rotation_words(self.theta_deg)}, $\hat u \cdot v = {_num(along)}$ and "
            rf"$\hat u \times v = {_vec(across)}$. Add $a$ back at the end.",
        ]

    def worked(self):
        length, k, v, along, across, c, s = self._steps()
        rotated = _rodrigues(k, c, s, v)
        image = self.a + rotated
        return Worked([
            rf"$\lVert u \rVert = {_num(length)}$, so $\hat u = {_vec(k)}$.",
            rf"$T(-a)$: $v = p - a = {_vec(self.p)} - {_vec(self.a)} = {_vec(v)}$.",
            rf"With {_rotation_words(self.theta_deg)}: $\hat u \cdot v = {_num(along)}$ and "
            rf"$\hat u \times v = {_vec(across)}$.",
            rf"Rodrigues: $R\,v = {_num(c)}\,v + {_num(s)}\,(\hat u \times v) + "
            rf"{_num(1 - c)} \cdot {_num(along)}\,\hat u = {_vec(rotated)}$.",
            rf"$T(a)$: $p' = a + R\,v = {_vec(image)}$.",
        ], image)

    def statement(self):
        return (
            rf"The axis of a rotation is the line through $a = {_vec(self.a)}$ with direction "
            rf"$u = {_vec(self.u)}$ (not of unit length). Rotate the point "
            rf"$p = {_vec(self.p)}$ by $\theta = {_deg(self.theta_deg)}$ about this axis "
            rf"(counter-clockwise when seen from the tip of $u$ looking back along the "
            rf"axis)." "\n\n"
            + _POINT_3 + "\n\n" + data_note("a", "u", "theta_deg", "theta", "p")
            + " (`.theta` is in radians.)")
