"""Chapter 4 exercises: The textbook's P_PER.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import numpy as np

from ... import transforms as tf
from ... import viewing
from ..core import DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import _POINT_3, PointAnswer, _num, _vec

__all__ = [
    "SimplePerspectivePoint",
]


class SimplePerspectivePoint(PointAnswer, DrawnExercise):
    r"""Project a point with the textbook's :math:`P_{PER}` onto the plane :math:`z = d`.

    The centre of projection is the origin; :math:`P_{PER}` gives the homogeneous point
    :math:`(xd, yd, zd, z)`, and dividing by :math:`w = z` gives :math:`(xd/z,\ yd/z,\ d)`.

    Attributes: ``d`` (distance of the plane from the centre), ``p`` (the point).

    Examples
    --------
    >>> ex = SimplePerspectivePoint(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> x, y, z = ex.p
    >>> ex.check([x * ex.d, y * ex.d, z * ex.d]).diagnosis      # the divide is missing
    'no divide'
    >>> ex.check([x * ex.d, y * ex.d, z * ex.d, z]).diagnosis   # homogeneous, not divided
    'no divide'
    >>> ex.check(...).status, ex.check("p").status
    ('unanswered', 'invalid')
    """

    title = "Perspective projection with P_PER"
    projective_point = True
    what = "the projected point"

    def draw(self, rng):
        self.d = float(pick(rng, (1, 2, 3, 4)))
        z = float(pick(rng, (2, 3, 4, 5, 6, 8)))
        x, y = small_ints(rng, 2, -6, 6)
        self.p = np.array([x, y, z])
        self.expected = tf.apply(viewing.simple_perspective(self.d), self.p)

    def acceptable(self):
        return bool(self.p[0] or self.p[1])       # a point on the axis projects onto the axis

    def mistakes(self):
        x, y, z = self.p
        d = self.d
        return [
            Mistake([x * d, y * d, z * d], r"You multiplied by $P_{PER}$ but stopped before the "
                    r"homogeneous divide. The result $(xd, yd, zd, z)$ has $w = z$; divide by it "
                    r"to get the point: $(xd/z,\ yd/z,\ d)$. The division by depth is what makes "
                    r"far things small.", "no divide"),
            Mistake([x * z / d, y * z / d, d], r"The ratio is upside down. By similar triangles "
                    r"the image is to the plane's distance as the point is to its depth: "
                    r"$x'/d = x/z$, so $x' = x\,d/z$.", "ratio upside down"),
            Mistake([x * d / z, y * d / z, z], r"$x$ and $y$ are right, but the projected point "
                    r"lies on the plane of projection, so its third coordinate is $d$: "
                    r"$zd / z = d$ after the divide.", "kept z"),
        ] + [Mistake(value, r"You divided by $-z$, as the OpenGL camera does (its last row "
                     r"$(0, 0, -1, 0)$ gives $w = -z_e$ for an eye looking down $-z$): that "
                     r"projects onto the plane $z = -d$ on the other side of the centre, and "
                     r"flips the image. $P_{PER}$'s last row is $(0, 0, 1, 0)$, so $w = z$: the "
                     r"image $(xd/z,\ yd/z,\ d)$ keeps the signs of $x$ and $y$ (here $z$ and "
                     r"$d$ are positive).", "divided by -z")
             for value in ([-x * d / z, -y * d / z, -d], [-x * d / z, -y * d / z, d])]

    def hints(self):
        x, y, z = self.p
        d = self.d
        return [
            r"Multiply the homogeneous point $(x, y, z, 1)$ by $P_{PER}$, then divide the first "
            r"three coordinates by the fourth, $w$.",
            rf"$P_{{PER}}\,(x, y, z, 1) = (xd,\ yd,\ zd,\ z) = ({_num(x * d)}, {_num(y * d)}, "
            rf"{_num(z * d)}, {_num(z)})$: here $w = z = {_num(z)}$.",
            rf"Divide by ${_num(z)}$: $x' = {_num(x * d)} / {_num(z)}$, "
            rf"$y' = {_num(y * d)} / {_num(z)}$, and $z' = {_num(z * d)} / {_num(z)} = "
            rf"{_num(d)}$, the plane.",
        ]

    def worked(self):
        x, y, z = self.p
        d = self.d
        image = np.array([x * d, y * d, z * d, z])
        point = image[:3] / image[3]
        return Worked([
            rf"In homogeneous coordinates $p = ({_num(x)}, {_num(y)}, {_num(z)}, 1)$; "
            rf"$P_{{PER}}\,p = (xd, yd, zd, z) = {_vec(image)}$.",
            rf"The homogeneous divide by $w = z = {_num(z)}$: $({_num(x * d)} / {_num(z)},\ "
            rf"{_num(y * d)} / {_num(z)},\ {_num(z * d)} / {_num(z)}) = {_vec(point)}$.",
            rf"The image lies on the plane $z = d = {_num(d)}$, at $x' = x\,d/z$, "
            r"$y' = y\,d/z$ (similar triangles).",
        ], point)

    def statement(self):
        return (
            rf"The centre of projection is the origin and the plane of projection is $z = d$ "
            rf"with $d = {_num(self.d)}$. Project the point $p = {_vec(self.p)}$ with the "
            r"textbook's matrix $P_{PER} = \begin{bmatrix} d & 0 & 0 & 0 \\ 0 & d & 0 & 0 \\ "
            r"0 & 0 & d & 0 \\ 0 & 0 & 1 & 0 \end{bmatrix}$, followed by the homogeneous "
            r"divide. Where does $p$ land?" "\n\n" + _POINT_3 + "\n\n" + data_note("d", "p"))
