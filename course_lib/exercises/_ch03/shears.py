"""Chapter 3 exercises: Shears.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import numpy as np

from ... import format as fmt
from ... import transforms as tf
from ..core import DECIMALS, DrawnExercise, Mistake, data_note, pick, small_ints
from . import _MATRIX_4, _POINT_3, _SHEARS, _vec

__all__ = [
    "ShearImage",
    "ShearInverse",
    "ShearedBoxVolume",
]


def _shear_words(kind, a="a", b="b"):
    driver, (first, second) = _SHEARS[kind][1], _SHEARS[kind][2]
    return (rf"$SH_{{{kind}}}({a}, {b})$ (it adds ${a}\,{driver}$ to ${first}$ and "
            rf"${b}\,{driver}$ to ${second}$, and leaves ${driver}$ unchanged)")


def _shear(kind, a, b):
    return _SHEARS[kind][0](a, b)


class ShearInverse(DrawnExercise):
    r"""The inverse of a 3D shear: the same shear with negated factors.

    Attributes: ``kind`` (``"xy"``, ``"xz"`` or ``"yz"``), ``a``, ``b``.

    Examples
    --------
    >>> ex = ShearInverse(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected.T).diagnosis
    'negated but transposed'
    >>> ex.check(np.linalg.inv(ex.expected)).diagnosis      # the shear itself
    'not negated'
    """

    title = "Inverse of a 3D shear"

    def draw(self, rng):
        self.kind = str(pick(rng, tuple(_SHEARS)))
        self.a, self.b = (float(v) for v in rng.choice([-3, -2, 2, 3], size=2))
        self.expected = tf.inverse(_shear(self.kind, self.a, self.b))

    def mistakes(self):
        H = _shear(self.kind, self.a, self.b)
        return [
            Mistake(H, r"This is the shear itself, not its inverse. A shear is undone by "
                    r"shearing back by the same amounts: negate both factors, "
                    r"$SH(a, b)^{-1} = SH(-a, -b)$.", "not negated"),
            Mistake(H.T, r"Transposing moves the factors to the wrong place (now another "
                    r"coordinate drives the shear) and keeps their sign. Only rotations are "
                    r"inverted by transposing; a shear is inverted by negating its factors in "
                    r"place.", "transposed"),
            Mistake(_shear(self.kind, -self.a, -self.b).T, r"The factors are negated, which is "
                    r"right, but they moved to the transposed positions: keep them where they "
                    r"are in $SH(a, b)$, so that the same coordinate drives the shear.",
                    "negated but transposed"),
            Mistake(_shear(self.kind, 1 / self.a, 1 / self.b), r"Reciprocals invert a "
                    r"*scaling*, not a shear. A shear adds a multiple of one coordinate; "
                    r"subtracting the same multiple undoes it, so negate the factors.",
                    "reciprocal"),
        ]

    def statement(self):
        return (
            rf"Consider the 3D shear {_shear_words(self.kind)}, with "
            rf"$a = {fmt.number(self.a)}$ and $b = {fmt.number(self.b)}$. Give the homogeneous "
            rf"matrix of its inverse, $SH_{{{self.kind}}}(a, b)^{{-1}}$." "\n\n" + _MATRIX_4
            + "\n\n" + data_note("kind", "a", "b"))


class ShearImage(DrawnExercise):
    r"""The image of a 3D point under a shear.

    Attributes: ``kind`` (``"xy"``, ``"xz"`` or ``"yz"``), ``a``, ``b``, ``p``.

    Examples
    --------
    >>> from course_lib import transforms as tf
    >>> ex = ShearImage(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> H = {"xy": tf.shear_xy, "xz": tf.shear_xz, "yz": tf.shear_yz}[ex.kind](ex.a, ex.b)
    >>> ex.check(tf.apply(H.T, ex.p)).diagnosis
    'transposed'
    """

    title = "Image of a point under a 3D shear"
    answer_form = "vector"
    what = "the image point"

    def draw(self, rng):
        self.kind = str(pick(rng, tuple(_SHEARS)))
        self.a, self.b = (float(v) for v in rng.choice([-3, -2, -1, 1, 2, 3], size=2))
        self.p = small_ints(rng, 3)
        self.expected = tf.apply(_shear(self.kind, self.a, self.b), self.p)

    def mistakes(self):
        H = _shear(self.kind, self.a, self.b)
        return [
            Mistake(tf.apply(H.T, self.p), r"You used the transposed shear matrix, so the wrong "
                    r"coordinate drove the shift. In the matrix of the shear the factors sit in "
                    r"the **column** of the driving coordinate: each shifted coordinate gets "
                    r"*factor times the driving coordinate* added.", "transposed"),
            Mistake(tf.apply(_shear(self.kind, -self.a, -self.b), self.p), r"You sheared the "
                    r"opposite way (factors negated): that is the inverse shear. Add the "
                    r"factor times the driving coordinate; do not subtract it.",
                    "opposite shear"),
        ]

    def statement(self):
        return (
            rf"The 3D shear {_shear_words(self.kind)} is applied with "
            rf"$a = {fmt.number(self.a)}$ and $b = {fmt.number(self.b)}$. Where does the point "
            rf"$p = {_vec(self.p)}$ go?" "\n\n" + _POINT_3 + "\n\n"
            + data_note("kind", "a", "b", "p"))


_BOX_SCALES = (1.0, 2.0, 3.0, 0.5, -1.0, -2.0)


class ShearedBoxVolume(DrawnExercise):
    r"""The volume of a box after a shear and a scaling: :math:`|\det M|` times the old volume.

    A shear has determinant 1 and keeps volumes; the scaling multiplies them by
    :math:`|s_x s_y s_z|` (a negative factor mirrors, and volumes are not negative).

    Attributes: ``w``, ``h``, ``l`` (edge lengths along x, y, z), ``kind``, ``a``, ``b``,
    ``sx``, ``sy``, ``sz``.

    Examples
    --------
    >>> ex = ShearedBoxVolume(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.w * ex.h * ex.l).diagnosis
    'scaling ignored'
    """

    title = "Volume after a shear and a scaling"
    answer_form = "number"
    what = "the volume"
    may_coincide = ("negative volume",)

    def draw(self, rng):
        self.w, self.h, self.l = (float(v) for v in rng.integers(1, 5, size=3))
        self.kind = str(pick(rng, tuple(_SHEARS)))
        self.a, self.b = (float(v) for v in rng.choice([-2, -1, 1, 2], size=2))
        self.sx, self.sy, self.sz = (float(v) for v in rng.choice(_BOX_SCALES, size=3))
        self.expected = self.w * self.h * self.l * abs(np.linalg.det(self._matrix()[:3, :3]))

    def _matrix(self):
        return tf.scale([self.sx, self.sy, self.sz]) @ _shear(self.kind, self.a, self.b)

    def mistakes(self):
        M = self._matrix()[:3, :3]
        edges = M * np.array([self.w, self.h, self.l])       # images of the three edges
        box = self.w * self.h * self.l
        return [
            Mistake(float(np.prod(np.linalg.norm(edges, axis=0))), r"You multiplied the lengths "
                    r"of the transformed edges. After a shear the box is a slanted "
                    r"parallelepiped whose edges are not perpendicular, so that product "
                    r"overestimates the volume. Use the determinant: the volume is multiplied by "
                    r"$|\det M|$, and a shear has determinant 1.", "edge lengths"),
            Mistake(box * float(np.prod([self.sx, self.sy, self.sz])), r"A volume cannot be "
                    r"negative. The negative scale factor mirrors the box (turning it "
                    r"inside out); the volume is multiplied by the *absolute value* of the "
                    r"determinant.", "negative volume"),
            Mistake(box, r"Right that the shear keeps the volume, but the scaling changes it: "
                    r"it multiplies volumes by $|s_x s_y s_z|$.", "scaling ignored"),
        ]

    def statement(self):
        return (
            rf"A box with edges of length $w = {fmt.number(self.w)}$, "
            rf"$h = {fmt.number(self.h)}$, $l = {fmt.number(self.l)}$ along x, y and z is first "
            rf"sheared by {_shear_words(self.kind)} with $a = {fmt.number(self.a)}$, "
            rf"$b = {fmt.number(self.b)}$, and then scaled by "
            rf"$S({fmt.number(self.sx)}, {fmt.number(self.sy)}, {fmt.number(self.sz)})$"
            + (" (a negative factor mirrors)" if min(self.sx, self.sy, self.sz) < 0 else "")
            + ". What is the volume of the resulting solid?\n\n"
            rf"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("w", "h", "l", "kind", "a", "b", "sx", "sy", "sz"))
