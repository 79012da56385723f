"""Chapter 4 exercises: Parallel projections onto the xy plane.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import transforms as tf
from ... import viewing
from ..core import DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import _POINT_3, PointAnswer, _deg, _num, _par, _snap, _vec

__all__ = [
    "CavalierCabinet",
    "ObliqueProjection",
]


class ObliqueProjection(PointAnswer, DrawnExercise):
    r"""Project a point along a direction of projection onto the plane :math:`z = 0`.

    :math:`p' = p - \frac{z}{DOP_z} DOP`, the textbook's :math:`P_{OBLI}`.

    Attributes: ``dop``, ``p``.

    Examples
    --------
    >>> ex = ObliqueProjection(seed=9)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check([ex.p[0], ex.p[1], 0]).diagnosis
    'orthographic'
    """

    title = "Oblique projection of a point"
    what = "the projected point"

    def draw(self, rng):
        dx, dy = small_ints(rng, 2, -2, 2)
        dz = float(pick(rng, (-2, -1, 1, 2)))
        self.dop = np.array([dx, dy, dz])
        x, y = rng.integers(-3, 4, size=2).astype(float)
        z = float(pick(rng, (-4, -2, 2, 4)))
        self.p = np.array([x, y, z])
        self.expected = tf.apply(viewing.oblique(self.dop), self.p)

    def mistakes(self):
        x, y, z = self.p
        dx, dy, dz = self.dop
        reversed_shift = (r"The shift goes the wrong way: you moved the point by "
                          r"$+\frac{z}{DOP_z} DOP$. It slides along $DOP$ until its $z$ is 0: "
                          r"$z + t\,DOP_z = 0$ gives $t = -\frac{z}{DOP_z}$, so "
                          r"$p' = p - \frac{z}{DOP_z} DOP$ (check that your image has $z = 0$).")
        found = [
            Mistake([x + z * dx / dz, y + z * dy / dz, 0], reversed_shift, "shift reversed"),
            Mistake([x + z * dx / dz, y + z * dy / dz, 2 * z], reversed_shift, "shift reversed"),
            Mistake([x, y, 0], r"That is the orthographic projection (straight down the z "
                    r"axis). Here the projectors are parallel to $DOP$, which is not "
                    r"perpendicular to the plane: $x' = x - z\,\frac{DOP_x}{DOP_z}$, "
                    r"$y' = y - z\,\frac{DOP_y}{DOP_z}$.", "orthographic"),
            Mistake([x - z * dx / dz, y - z * dy / dz, z], r"$x'$ and $y'$ are right, but the "
                    r"image lies on the plane of projection, so $z' = 0$ (the third row of "
                    r"$P_{OBLI}$ is zero).", "kept z"),
        ]
        if abs(dz) != 1:
            found.append(Mistake([x - z * dx, y - z * dy, 0], r"You forgot to divide by "
                                 r"$DOP_z$: the point moves by $t\,DOP$ with $t = z / DOP_z$, "
                                 r"the multiple of $DOP$ that cancels its z coordinate.",
                                 "not divided by DOP_z"))
        return found

    def statement(self):
        return (
            rf"A parallel projection onto the plane $z = 0$ has the direction of projection "
            rf"$DOP = {_vec(self.dop)}$ (not perpendicular to the plane: an oblique "
            rf"projection). Where does the point $p = {_vec(self.p)}$ land?" "\n\n"
            + _POINT_3 + "\n\n" + data_note("dop", "p"))

    def hints(self):
        x, y, z = self.p
        dx, dy, dz = self.dop
        t = -z / dz
        return [
            r"Every point slides along the direction of projection until it reaches the plane: "
            r"$p' = p + t\,DOP$, with $t$ chosen so that the $z$ coordinate becomes 0.",
            rf"$z + t\,DOP_z = 0$: here ${_num(z)} + t \cdot {_par(dz)} = 0$, so "
            rf"$t = {_num(t)}$.",
            rf"$t\,DOP = {_vec(t * self.dop)}$; add it to $p = {_vec(self.p)}$ (the $z$ "
            r"coordinate must come out 0).",
        ]

    def worked(self):
        x, y, z = self.p
        dx, dy, dz = self.dop
        t = -z / dz
        image = np.array([x + t * dx, y + t * dy, z + t * dz])
        return Worked([
            rf"The projector through $p$ is $p + t\,DOP$; it meets $z = 0$ where "
            rf"${_num(z)} + t \cdot {_par(dz)} = 0$, i.e. $t = -z/DOP_z = {_num(t)}$.",
            rf"$p' = {_vec(self.p)} + {_par(t)} \cdot {_vec(self.dop)} = {_vec(image)}$.",
            rf"The same with $P_{{OBLI}}$: $x' = x - z\,\frac{{DOP_x}}{{DOP_z}} = "
            rf"{_num(image[0])}$, $y' = y - z\,\frac{{DOP_y}}{{DOP_z}} = {_num(image[1])}$, "
            r"$z' = 0$.",
        ], image)


class CavalierCabinet(PointAnswer, DrawnExercise):
    r"""A point in a cavalier or cabinet drawing.

    The unit vector along +z is drawn at the angle :math:`\alpha` to the x axis with length
    :math:`L` (1 for cavalier, 1/2 for cabinet): :math:`(x + L z \cos\alpha,\
    y + L z \sin\alpha,\ 0)`. It is :math:`P_{OBLI}` with
    :math:`DOP = (-L\cos\alpha, -L\sin\alpha, 1)`.

    Attributes: ``kind`` (``"cavalier"`` or ``"cabinet"``), ``alpha_deg``, ``alpha``
    (radians), ``length`` (L), ``p``.

    Examples
    --------
    >>> ex = CavalierCabinet(seed=10)
    >>> ex.kind, ex.check(ex.expected).status
    ('cabinet', 'correct')
    >>> x, y, z = ex.p
    >>> a = ex.alpha
    >>> ex.check([x + z * np.cos(a), y + z * np.sin(a), 0]).diagnosis   # full length
    'depth factor'
    """

    title = "Cavalier and cabinet projections"
    what = "the projected point"

    def draw(self, rng):
        self.kind = str(pick(rng, ("cavalier", "cabinet")))
        self.length = 1.0 if self.kind == "cavalier" else 0.5
        self.alpha_deg = int(pick(rng, (30, 45, 60)))
        self.alpha = math.radians(self.alpha_deg)
        x, y = rng.integers(-3, 4, size=2).astype(float)
        z = float(pick(rng, (-4, -2, 2, 4)))
        self.p = np.array([x, y, z])
        L, a = self.length, self.alpha
        self.dop = np.array([-L * math.cos(a), -L * math.sin(a), 1.0])
        self.expected = _snap(tf.apply(viewing.oblique(self.dop), self.p))

    def _image(self, length, angle, sign=1.0):
        x, y, z = self.p
        return [x + sign * length * z * math.cos(angle), y + sign * length * z * math.sin(angle),
                0.0]

    def mistakes(self):
        L, a = self.length, self.alpha
        other = 1.5 - L
        found = [
            Mistake(self._image(other, a), (r"You drew depth at full length: in a **cabinet** "
                    r"projection a unit of depth is drawn at half length, $L = \tfrac12$ (which "
                    r"looks more natural than cavalier's $L = 1$).") if self.kind == "cabinet"
                    else (r"You halved the depth: in a **cavalier** projection a unit of depth "
                          r"is drawn at full length, $L = 1$ (the projectors make $45^\circ$ "
                          r"with the plane); the half length belongs to the cabinet "
                          r"projection."), "depth factor"),
            Mistake(self._image(L, a, -1.0), r"The depth went the wrong way: a point with "
                    r"positive $z$ moves by $+L z\,(\cos\alpha, \sin\alpha)$ in the drawing.",
                    "receding direction reversed"),
            Mistake([self.p[0], self.p[1], 0], r"That drops $z$ altogether (orthographic "
                    r"projection). In an oblique drawing depth shows as a shift of "
                    r"$L z\,(\cos\alpha, \sin\alpha)$.", "orthographic"),
        ]
        if self.alpha_deg != 45:
            found.append(Mistake(self._image(L, math.pi / 2 - a), r"Sine and cosine are "
                                 r"swapped: the angle $\alpha$ is measured from the x axis, so "
                                 r"the shift is $L z\,(\cos\alpha, \sin\alpha)$.",
                                 "sin/cos swapped"))
        return found

    def statement(self):
        half = r"half length, $L = \tfrac12$" if self.kind == "cabinet" \
            else r"full length, $L = 1$"
        return (
            rf"In a **{self.kind}** projection onto the plane $z = 0$, the unit vector along "
            rf"$+z$ is drawn as a segment at the angle $\alpha = {_deg(self.alpha_deg)}$ above "
            rf"the positive x axis, at {half}. (It is the oblique projection with "
            r"$DOP = (-L\cos\alpha, -L\sin\alpha, 1)$.) Where does the point "
            rf"$p = {_vec(self.p)}$ land?" "\n\n" + _POINT_3 + "\n\n"
            + data_note("kind", "alpha_deg", "alpha", "length", "p")
            + " (`.alpha` is in radians.)")

    def _shift(self):
        a = math.radians(self.alpha_deg)
        c, s = math.cos(a), math.sin(a)
        z = self.p[2]
        return c, s, np.array([self.length * z * c, self.length * z * s])

    def hints(self):
        c, s, shift = self._shift()
        return [
            r"In an oblique drawing $x$ and $y$ stay, and depth shows as a shift: a point at "
            r"depth $z$ moves by $L\,z\,(\cos\alpha, \sin\alpha)$, the drawn image of $z$ "
            r"units along $+z$.",
            rf"A {self.kind} projection draws depth at $L = {_num(self.length)}$; here "
            rf"$\alpha = {_deg(self.alpha_deg)}$, $\cos\alpha = {_num(c)}$, "
            rf"$\sin\alpha = {_num(s)}$, and $z = {_num(self.p[2])}$.",
            rf"The shift is $L\,z\,(\cos\alpha, \sin\alpha) = {_vec(shift)}$; add it to "
            rf"$(x, y) = ({_num(self.p[0])}, {_num(self.p[1])})$ and set $z' = 0$.",
        ]

    def worked(self):
        c, s, shift = self._shift()
        image = np.array([self.p[0] + shift[0], self.p[1] + shift[1], 0.0])
        return Worked([
            rf"{self.kind.capitalize()}: $L = {_num(self.length)}$; $\alpha = "
            rf"{_deg(self.alpha_deg)}$ gives $(\cos\alpha, \sin\alpha) = ({_num(c)}, "
            rf"{_num(s)})$.",
            rf"Depth $z = {_num(self.p[2])}$ is drawn as the shift $L\,z\,(\cos\alpha, "
            rf"\sin\alpha) = {_num(self.length * self.p[2])} \cdot ({_num(c)}, {_num(s)}) = "
            rf"{_vec(shift)}$.",
            rf"$p' = ({_num(self.p[0])} + {_par(shift[0])},\ {_num(self.p[1])} + "
            rf"{_par(shift[1])},\ 0) = {_vec(image)}$.",
        ], image)
