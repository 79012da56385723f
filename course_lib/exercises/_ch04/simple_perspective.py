"""Chapter 4 exercises: The textbook's P_PER.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import numpy as np

from ... import transforms as tf
from ... import viewing
from ..core import DrawnExercise, Mistake, data_note, pick, small_ints
from . import _POINT_3, _num, _vec

__all__ = [
    "SimplePerspectivePoint",
]


class SimplePerspectivePoint(DrawnExercise):
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
    answer_form = "point"
    projective_point = True
    what = "the projected point"

    def draw(self, rng):
        self.d = float(pick(rng, (1, 2, 3, 4)))
        z = float(pick(rng, (2, 3, 4, 5, 6, 8)))
        x, y = small_ints(rng, 2, -6, 6)
        self.p = np.array([x, y, z])
        self.expected = tf.apply(viewing.simple_perspective(self.d), self.p)

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
        ]

    def statement(self):
        return (
            rf"The centre of projection is the origin and the plane of projection is $z = d$ "
            rf"with $d = {_num(self.d)}$. Project the point $p = {_vec(self.p)}$ with the "
            r"textbook's matrix $P_{PER} = \begin{bmatrix} d & 0 & 0 & 0 \\ 0 & d & 0 & 0 \\ "
            r"0 & 0 & d & 0 \\ 0 & 0 & 1 & 0 \end{bmatrix}$, followed by the homogeneous "
            r"divide. Where does $p$ land?" "\n\n" + _POINT_3 + "\n\n" + data_note("d", "p"))
