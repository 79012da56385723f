"""Chapter 4 exercises: WCS -> ECS.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import transforms as tf
from ... import viewing
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick, small_ints
from . import _MATRIX_4, _POINT_3, PointAnswer, _mat, _num, _signs, _snap, _vec

__all__ = [
    "EyeCoordinateAxes",
    "LookAtMatrix",
    "PointToEyeCoordinates",
]


#: Rational orthonormal bases: (common denominator, whole-number rows). Permuting and negating
#: their coordinates gives camera frames whose axes work out exactly by hand.
_ORTHO_BASES = (
    (1, ((1, 0, 0), (0, 1, 0), (0, 0, 1))),
    (3, ((1, 2, 2), (2, 1, -2), (2, -2, 1))),
    (5, ((0, 3, 4), (0, 4, -3), (5, 0, 0))),
    (7, ((2, 3, 6), (3, -6, 2), (6, 2, -3))),
)


def _camera(rng):
    """An eye, a gaze direction and an up vector (not perpendicular to the gaze), all whole.

    Returns ``(eye, gaze, up)``; the ECS axes they define have rational components.
    """
    n, rows = pick(rng, _ORTHO_BASES)
    basis = np.array(rows, dtype=float)
    basis = basis[:, rng.permutation(3)] * _signs(rng, 3)          # permute the coordinates
    basis = basis[rng.permutation(3)] * _signs(rng, 3)[:, None]    # and the axes
    x_e, y_e = basis[0] / n, basis[1] / n
    z_e = np.cross(x_e, y_e)                                       # right-handed
    gaze = -z_e * n * (2 if n == 1 else 1)
    c = float(pick(rng, (-2, -1, 1, 2)))
    up = n * y_e + c * n * z_e
    up = up / math.gcd(*(int(round(abs(v))) for v in up))
    eye = small_ints(rng, 3)
    return eye, np.round(gaze), np.round(up)


def _frame_rows(gaze, up):
    """The ECS axes (rows x_e, y_e, z_e) from a gaze direction and an up vector."""
    z = -np.asarray(gaze, float) / np.linalg.norm(gaze)
    x = np.cross(up, z)
    x = x / np.linalg.norm(x)
    return np.array([x, np.cross(z, x), z])


def _homogeneous(rotation, translation):
    m = np.eye(4)
    m[:3, :3] = rotation
    m[:3, 3] = translation
    return m


def _raw_rows(gaze, up):
    """The ECS axes computed without any normalization."""
    z = -np.asarray(gaze, float)
    x = np.cross(up, z)
    return np.array([x, np.cross(z, x), z])


def _camera_words(eye, gaze, up):
    return (rf"A camera sits at the eye point $E = {_vec(eye)}$ and looks in the direction "
            rf"$g = {_vec(gaze)}$ (a direction, not a point it looks at); its up vector is "
            rf"$up = {_vec(up)}$, which is not perpendicular to $g$.")


class _Axes:
    """The ECS axes of a camera worked out by hand, with the numbers a student writes down."""

    def __init__(self, gaze, up):
        self.gaze_length = float(np.linalg.norm(gaze))
        self.z = -np.asarray(gaze, dtype=float) / self.gaze_length
        self.up_cross_z = np.cross(up, self.z)
        self.cross_length = float(np.linalg.norm(self.up_cross_z))
        self.x = self.up_cross_z / self.cross_length
        self.y = np.cross(self.z, self.x)
        self.rows = np.array([self.x, self.y, self.z])

    def steps(self, gaze, up):
        return [
            rf"$\lVert g \rVert = {_num(self.gaze_length)}$, so "
            rf"$z_e = -g / \lVert g \rVert = {_vec(self.z)}$ (it points back at the viewer).",
            rf"$up \times z_e = {_vec(up)} \times {_vec(self.z)} = {_vec(self.up_cross_z)}$, of "
            rf"length ${_num(self.cross_length)}$: $x_e = {_vec(self.x)}$.",
            rf"$y_e = z_e \times x_e = {_vec(self.y)}$ (already of unit length, and "
            r"perpendicular to the gaze although $up$ is not).",
        ]

    def hints(self, gaze, up):
        return [
            r"Build the axes in this order: $z_e = -g / \lVert g \rVert$ (backwards, towards the "
            r"viewer), $x_e = up \times z_e$ normalized (to the right), and "
            r"$y_e = z_e \times x_e$ (the direction of the part of $up$ across the gaze).",
            rf"Here $\lVert g \rVert = {_num(self.gaze_length)}$, so $z_e = {_vec(self.z)}$; and "
            rf"$up \times z_e = {_vec(self.up_cross_z)}$, of length "
            rf"${_num(self.cross_length)}$.",
            rf"So $x_e = {_vec(self.x)}$; the last axis is the cross product "
            r"$z_e \times x_e$ (no need to normalize it).",
        ]


_ECS_CONVENTION = (r"The eye coordinate system has $x_e$ to the right, $y_e$ up and $z_e$ "
                   r"pointing **towards the viewer** (the camera looks down $-z_e$): "
                   r"$z_e = -\frac{g}{\lVert g \rVert}$, "
                   r"$x_e = \frac{up \times z_e}{\lVert up \times z_e \rVert}$, "
                   r"$y_e = z_e \times x_e$.")


class EyeCoordinateAxes(DrawnExercise):
    r"""The unit axes :math:`x_e, y_e, z_e` of the eye coordinate system, in world coordinates.

    :math:`z_e = -g / \lVert g \rVert`, :math:`x_e = up \times z_e` normalized, and
    :math:`y_e = z_e \times x_e` (already of unit length, and perpendicular to the gaze even
    though `up` is not).

    Attributes: ``eye``, ``gaze``, ``up``.

    Examples
    --------
    >>> ex = EyeCoordinateAxes(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> x_e, y_e, z_e = ex.expected
    >>> ex.check([x_e, ex.up / np.linalg.norm(ex.up), z_e]).diagnosis
    'up not orthogonalized'
    >>> ex.check(ex.expected.T).diagnosis                 # axes written as columns
    'transposed'
    """

    title = "The axes of the eye coordinate system"
    what = "the matrix of axes"
    may_coincide = ("not normalized",)

    def draw(self, rng):
        self.eye, self.gaze, self.up = _camera(rng)
        self.expected = _snap(viewing.look_at(self.eye, self.gaze, self.up)[:3, :3])

    def mistakes(self):
        x, y, z = self.expected
        up_hat = self.up / np.linalg.norm(self.up)
        return [
            Mistake([-x, y, -z], r"Your $z_e$ points along the gaze. The camera looks down "
                    r"$-z_e$, so $z_e$ points back towards the viewer: $z_e = -g/\lVert g "
                    r"\rVert$. (Flipping $z_e$ also flipped $x_e$.)", "z_e along gaze"),
            Mistake([x, up_hat, z], r"You took $y_e$ to be the normalized up vector, but $up$ "
                    r"is not perpendicular to $g$, so that $y_e$ is not perpendicular to $z_e$. "
                    r"Only $up$'s part across the gaze counts: compute $x_e$ first, then "
                    r"$y_e = z_e \times x_e$.", "up not orthogonalized"),
            Mistake(_raw_rows(self.gaze, self.up), r"The directions are right but the axes are "
                    r"not unit vectors: divide $z_e = -g$ and $x_e = up \times z_e$ by their "
                    r"lengths before using them (then $y_e = z_e \times x_e$ has length 1 by "
                    r"itself).", "not normalized"),
            Mistake([-x, -y, z], r"The cross product is in the wrong order: "
                    r"$z_e \times up = -(up \times z_e)$. With $x_e = up \times z_e$ (and "
                    r"$y_e = z_e \times x_e$) the frame is right-handed, $x_e \times y_e = z_e$, "
                    r"and $x_e$ points to the right.", "cross product order"),
            Mistake(self.expected.T, r"You wrote the axes as the **columns** of the matrix; the "
                    r"question asks for them as its rows, $[x_e;\ y_e;\ z_e]$ (which is the "
                    r"rotation part of $M_{WCS \to ECS}$).", "transposed"),
        ]

    def hints(self):
        return _Axes(self.gaze, self.up).hints(self.gaze, self.up)

    def worked(self):
        axes = _Axes(self.gaze, self.up)
        return Worked(axes.steps(self.gaze, self.up) + [
            rf"The matrix with the axes as rows: ${_mat(axes.rows)}$."], axes.rows)

    def statement(self):
        return (
            _camera_words(self.eye, self.gaze, self.up) + " " + _ECS_CONVENTION + "\n\n"
            r"Compute the unit vectors $x_e$, $y_e$, $z_e$ (in world coordinates)." "\n\n"
            r"**Answer:** a $3 \times 3$ numpy array whose **rows** are $x_e$, $y_e$, $z_e$: "
            r"`np.array([x_e, y_e, z_e])`. " + DECIMALS + "\n\n"
            + data_note("eye", "gaze", "up"))


class LookAtMatrix(DrawnExercise):
    r"""The WCS -> ECS matrix :math:`M = R\,T(-E)` of a camera at `eye` looking along `gaze`.

    The rows of :math:`R` are the ECS axes; the last column is
    :math:`(-x_e \cdot E,\ -y_e \cdot E,\ -z_e \cdot E)`.

    Attributes: ``eye``, ``gaze``, ``up``.

    Examples
    --------
    >>> ex = LookAtMatrix(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong_order = ex.expected.copy()
    >>> wrong_order[:3, 3] = -ex.eye                      # T(-E) R instead of R T(-E)
    >>> ex.check(wrong_order).diagnosis
    'wrong order'
    """

    title = "The viewing matrix WCS to ECS"
    may_coincide = ("not normalized",)

    def draw(self, rng):
        self.eye, self.gaze, self.up = _camera(rng)
        self.expected = _snap(viewing.look_at(self.eye, self.gaze, self.up))

    def _target_mistake(self):
        """The matrix of a student who took the gaze for the point looked at (or None)."""
        target_dir = self.gaze - self.eye
        if np.linalg.norm(np.cross(target_dir, self.up)) < 1e-9:
            return None
        rows = _frame_rows(target_dir, self.up)
        return _homogeneous(rows, -rows @ self.eye)

    def mistakes(self):
        R, E = self.expected[:3, :3], self.eye
        flipped = R * np.array([[-1.0], [1.0], [-1.0]])
        raw = _raw_rows(self.gaze, self.up)
        found = [
            Mistake(_homogeneous(R, -E), r"The translation is not rotated: you built "
                    r"$T(-E)\,R$, which rotates first. First move the eye to the origin, then "
                    r"turn the axes: $M = R\,T(-E)$, whose last column is $-R\,E = "
                    r"(-x_e \cdot E,\ -y_e \cdot E,\ -z_e \cdot E)$.", "wrong order"),
            Mistake(_homogeneous(R, R @ E), r"The translation has the wrong sign: the eye must "
                    r"move to the origin, so translate by $-E$: the last column is $-R\,E$.",
                    "translation sign"),
            Mistake(_homogeneous(R.T, -R.T @ E), r"You put the ECS axes in the **columns**. That "
                    r"matrix turns the eye's axes into the world's; the viewing matrix does the "
                    r"opposite, so the axes are its **rows** (the inverse of a rotation is its "
                    r"transpose).", "axes in columns"),
            Mistake(_homogeneous(flipped, -flipped @ E), r"Your $z_e$ points along the gaze; it "
                    r"must point back at the viewer, $z_e = -g / \lVert g \rVert$ (the camera "
                    r"looks down $-z_e$).", "z_e along gaze"),
            Mistake(_homogeneous(raw, -raw @ E), r"The axes are not normalized: divide $z_e$ and "
                    r"$x_e$ by their lengths, otherwise the matrix also scales the scene.",
                    "not normalized"),
        ]
        target = self._target_mistake()
        if target is not None:
            found.append(Mistake(target, r"You treated $g$ as the point the camera looks at and "
                                 r"used $g - E$ as the direction of view. Here $g$ is already "
                                 r"the direction: $z_e = -g / \lVert g \rVert$.",
                                 "gaze as target"))
        return found

    def hints(self):
        axes = _Axes(self.gaze, self.up)
        return [
            r"First move the eye to the origin, then turn the world's axes onto the eye's: "
            r"$M = R\,T(-E)$, where the **rows** of $R$ are $x_e$, $y_e$, $z_e$.",
            axes.hints(self.gaze, self.up)[1] + rf" Then $x_e = {_vec(axes.x)}$ and "
            rf"$y_e = z_e \times x_e = {_vec(axes.y)}$.",
            r"The last column is $-R\,E = (-x_e \cdot E,\ -y_e \cdot E,\ -z_e \cdot E)$; "
            rf"here $x_e \cdot E = {_num(axes.x @ self.eye)}$.",
        ]

    def worked(self):
        axes = _Axes(self.gaze, self.up)
        column = -(axes.rows @ self.eye)
        M = np.eye(4)
        M[:3, :3] = axes.rows
        M[:3, 3] = column
        return Worked(axes.steps(self.gaze, self.up) + [
            rf"$M = R\,T(-E)$: the rows of $R$ are the axes, and the last column is "
            rf"$-R\,E = (-x_e \cdot E,\ -y_e \cdot E,\ -z_e \cdot E) = {_vec(column)}$ with "
            rf"$E = {_vec(self.eye)}$.",
            rf"$M = {_mat(M)}$. Check: $M$ sends the eye $E$ to the origin.",
        ], M)

    def statement(self):
        return (
            _camera_words(self.eye, self.gaze, self.up) + " " + _ECS_CONVENTION + "\n\n"
            r"Give the homogeneous matrix $M_{WCS \to ECS}$ that takes world coordinates to eye "
            r"coordinates ($p_{ECS} = M\,p_{WCS}$)." "\n\n" + _MATRIX_4 + "\n\n"
            + data_note("eye", "gaze", "up"))


class PointToEyeCoordinates(PointAnswer, DrawnExercise):
    r"""The eye coordinates of a world point: :math:`(x_e, y_e, z_e) \cdot (p - E)`.

    Attributes: ``eye``, ``gaze``, ``up``, ``p``.

    Examples
    --------
    >>> ex = PointToEyeCoordinates(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> R = ex.expected_axes
    >>> ex.check(R @ ex.p).diagnosis                        # the eye was not moved to the origin
    'not translated'
    """

    title = "A world point in eye coordinates"
    what = "the point in eye coordinates"

    def draw(self, rng):
        self.eye, self.gaze, self.up = _camera(rng)
        self.p = small_ints(rng, 3)
        M = viewing.look_at(self.eye, self.gaze, self.up)
        self.expected_axes = M[:3, :3]
        self.expected = _snap(tf.apply(M, self.p))

    def mistakes(self):
        R, E, p = self.expected_axes, self.eye, self.p
        flipped = R * np.array([[-1.0], [1.0], [-1.0]])
        return [
            Mistake(R @ p, r"You rotated $p$ but did not move the eye to the origin first. Eye "
                    r"coordinates are measured from $E$: $p_{ECS} = R\,(p - E)$, i.e. "
                    r"$(x_e \cdot (p - E),\ y_e \cdot (p - E),\ z_e \cdot (p - E))$.",
                    "not translated"),
            Mistake(R @ p - E, r"You subtracted $E$ after rotating. The eye's position is given "
                    r"in world coordinates, so subtract it first: $R\,(p - E)$.",
                    "translated after rotating"),
            Mistake(flipped @ (p - E), r"Your $z_e$ (and with it $x_e$) points the wrong way: "
                    r"$z_e = -g/\lVert g \rVert$ points back at the viewer, so points in front "
                    r"of the camera get a *negative* $z_e$ coordinate.", "z_e along gaze"),
            Mistake(R.T @ (p - E), r"You used the ECS axes as the columns of the matrix. The "
                    r"coordinates of $p - E$ along the axes are the dot products with "
                    r"$x_e, y_e, z_e$, so the axes are the **rows**.", "axes in columns"),
        ]

    def hints(self):
        axes = _Axes(self.gaze, self.up)
        v = self.p - self.eye
        return [
            r"Eye coordinates are measured from the eye along the eye's axes: "
            r"$p_{ECS} = (x_e \cdot (p - E),\ y_e \cdot (p - E),\ z_e \cdot (p - E))$.",
            axes.hints(self.gaze, self.up)[1] + rf" Then $x_e = {_vec(axes.x)}$ and "
            rf"$y_e = z_e \times x_e = {_vec(axes.y)}$.",
            rf"$p - E = {_vec(v)}$: take its dot product with each axis (a point in front of "
            r"the camera gets a negative $z_e$ coordinate).",
        ]

    def worked(self):
        axes = _Axes(self.gaze, self.up)
        v = self.p - self.eye
        coords = np.array([axes.x @ v, axes.y @ v, axes.z @ v])
        return Worked(axes.steps(self.gaze, self.up) + [
            rf"Move the eye to the origin: $p - E = {_vec(self.p)} - {_vec(self.eye)} = "
            rf"{_vec(v)}$.",
            rf"Its coordinates along the axes: $x_e \cdot (p - E) = {_num(coords[0])}$, "
            rf"$y_e \cdot (p - E) = {_num(coords[1])}$, $z_e \cdot (p - E) = "
            rf"{_num(coords[2])}$.",
            rf"$p_{{ECS}} = {_vec(coords)}$.",
        ], coords)

    def statement(self):
        return (
            _camera_words(self.eye, self.gaze, self.up) + " " + _ECS_CONVENTION + "\n\n"
            rf"What are the eye coordinates of the world point $p = {_vec(self.p)}$?" "\n\n"
            + _POINT_3 + "\n\n" + data_note("eye", "gaze", "up", "p"))
