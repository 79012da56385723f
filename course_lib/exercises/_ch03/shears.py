"""Chapter 3 exercises: Shears.

Part of :mod:`course_lib.exercises.ch03`, which imports every exercise from here.
"""

import numpy as np

from ... import format as fmt
from ... import transforms as tf
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import _MATRIX_4, _POINT_3, _SHEARS, PointAnswer, _mat, _num, _par, _vec

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


_INDEX = {"x": 0, "y": 1, "z": 2}


def _layout(kind):
    """The driving coordinate and the two shifted ones, as names and as indices."""
    driver, (first, second) = _SHEARS[kind][1], _SHEARS[kind][2]
    return driver, first, second, _INDEX[driver], _INDEX[first], _INDEX[second]


def _shear_by_hand(kind, a, b):
    """The homogeneous shear matrix written out: the factors in the driver's column."""
    _, _, _, k, i, j = _layout(kind)
    m = np.eye(4)
    m[i, k], m[j, k] = a, b
    return m


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
        self.a, self.b = (float(v) for v in rng.choice([-4, -3, -2, -0.5, 0.5, 2, 3, 4], size=2))
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

    def hints(self):
        driver, first, second, k, i, j = _layout(self.kind)
        return [
            r"A shear adds multiples of one coordinate to the others. To undo it, subtract the "
            r"same multiples: shear by the negated factors.",
            rf"In $SH_{{{self.kind}}}$ the coordinate ${driver}$ drives the shear: the factors "
            rf"stand in the ${driver}$ column (column {k}, counted from 0), in the rows of "
            rf"${first}$ and ${second}$. The inverse keeps them there.",
            rf"So the inverse is the identity with ${_num(-self.a)}$ in row {i}, column {k}, and "
            rf"${_num(-self.b)}$ in row {j}, column {k}.",
        ]

    def worked(self):
        driver, first, second, k, i, j = _layout(self.kind)
        H = _shear_by_hand(self.kind, self.a, self.b)
        H_inv = _shear_by_hand(self.kind, -self.a, -self.b)
        return Worked([
            rf"$SH_{{{self.kind}}}(a, b)$ adds $a\,{driver}$ to ${first}$ and $b\,{driver}$ to "
            rf"${second}$: $SH = {_mat(H)}$.",
            rf"${driver}$ does not change, so subtracting $a\,{driver}$ and $b\,{driver}$ "
            rf"again undoes the shear: $SH(a, b)^{{-1}} = SH(-a, -b)$, with "
            rf"$-a = {_num(-self.a)}$ and $-b = {_num(-self.b)}$ in the same places.",
            rf"$SH^{{-1}} = {_mat(H_inv)}$. Check: $SH^{{-1}}\,SH = I$ (the factors add up to "
            r"0).",
        ], H_inv)

    def statement(self):
        return (
            rf"Consider the 3D shear {_shear_words(self.kind)}, with "
            rf"$a = {fmt.number(self.a)}$ and $b = {fmt.number(self.b)}$. Give the homogeneous "
            rf"matrix of its inverse, $SH_{{{self.kind}}}(a, b)^{{-1}}$." "\n\n" + _MATRIX_4
            + "\n\n" + data_note("kind", "a", "b"))


class ShearImage(PointAnswer, DrawnExercise):
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

    def hints(self):
        driver, first, second, k, i, j = _layout(self.kind)
        value = self.p[k]
        return [
            rf"A shear changes some coordinates by multiples of another one. Here ${driver}$ "
            rf"drives: ${first}$ gains $a\,{driver}$, ${second}$ gains $b\,{driver}$, and "
            rf"${driver}$ itself stays.",
            rf"The driving coordinate of $p$ is ${driver} = {_num(value)}$, so ${first}$ gains "
            rf"${_par(self.a)} \cdot {_par(value)} = {_num(self.a * value)}$ and ${second}$ "
            rf"gains ${_par(self.b)} \cdot {_par(value)} = {_num(self.b * value)}$.",
            rf"Nearly there: ${first}' = {_num(self.p[i])} + {_par(self.a * value)}$ and "
            rf"${second}' = {_num(self.p[j])} + {_par(self.b * value)}$; "
            rf"${driver}' = {_num(value)}$.",
        ]

    def worked(self):
        driver, first, second, k, i, j = _layout(self.kind)
        image = np.array(self.p, dtype=float)
        image[i] = self.p[i] + self.a * self.p[k]
        image[j] = self.p[j] + self.b * self.p[k]
        return Worked([
            rf"$SH_{{{self.kind}}}(a, b)$ adds $a\,{driver}$ to ${first}$ and $b\,{driver}$ "
            rf"to ${second}$; ${driver}$ stays. The matrix is "
            rf"${_mat(_shear_by_hand(self.kind, self.a, self.b))}$.",
            rf"$p = {_vec(self.p)}$ has ${driver} = {_num(self.p[k])}$: "
            rf"${first}' = {_num(self.p[i])} + ({_num(self.a)})({_num(self.p[k])}) = "
            rf"{_num(image[i])}$ and ${second}' = {_num(self.p[j])} + ({_num(self.b)})"
            rf"({_num(self.p[k])}) = {_num(image[j])}$.",
            rf"The image is $p' = {_vec(image)}$.",
        ], image)

    def statement(self):
        return (
            rf"The 3D shear {_shear_words(self.kind)} is applied with "
            rf"$a = {fmt.number(self.a)}$ and $b = {fmt.number(self.b)}$. Where does the point "
            rf"$p = {_vec(self.p)}$ go?" "\n\n" + _POINT_3 + "\n\n"
            + data_note("kind", "a", "b", "p"))


_BOX_SCALES = (1.0, 2.0, 3.0, 0.5, 1.5, -1.0, -2.0, -0.5)


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
        self.w, self.h, self.l = (float(v) for v in rng.integers(1, 6, size=3))
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

    def hints(self):
        det = self.sx * self.sy * self.sz
        return [
            r"A linear map multiplies every volume by $|\det M|$, and the determinant of a "
            r"product is the product of the determinants: $\det(S\,SH) = \det S \cdot "
            r"\det SH$.",
            r"A shear's matrix is triangular (after ordering the coordinates) with ones on the "
            r"diagonal, so $\det SH = 1$: the shear slants the box but keeps its volume. "
            rf"The scaling has $\det S = s_x s_y s_z = {_num(det)}$.",
            rf"The box starts with volume $w\,h\,l = {_num(self.w * self.h * self.l)}$; "
            rf"multiply it by $|\det S| = {_num(abs(det))}$.",
        ]

    def worked(self):
        box = self.w * self.h * self.l
        det = self.sx * self.sy * self.sz
        volume = box * abs(det) * 1.0
        return Worked([
            rf"The box has volume $w\,h\,l = {_num(self.w)} \cdot {_num(self.h)} \cdot "
            rf"{_num(self.l)} = {_num(box)}$.",
            r"The shear has determinant 1 (ones on the diagonal, the factors on one side of it), "
            r"so it keeps volumes.",
            rf"The scaling has $\det S = ({_num(self.sx)})({_num(self.sy)})({_num(self.sz)}) "
            rf"= {_num(det)}$; a volume is multiplied by the absolute value, "
            rf"${_num(abs(det))}$.",
            rf"Volume: ${_num(box)} \cdot {_num(abs(det))} = {_num(volume)}$.",
        ], volume)

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
