r"""Chapter 4 exercises: projections and the viewing transformation, exam style.

Each class is one kind of exam question about the road from world coordinates to pixels:
the textbook's simple projections (:math:`P_{PER}`, :math:`P_{OBLI}`, cavalier and cabinet), the
eye coordinate system and the WCS -> ECS matrix, the perspective and orthographic ECS -> CSS
matrices with the homogeneous divide, the viewport, and what a perspective projection keeps
(cross ratios, vanishing points). The ``seed`` draws numbers that work out by hand: camera frames
whose axes have rational components (rows such as :math:`\tfrac13(1, 2, 2)`), fields of view of
60, 90 or 120 degrees, near and far planes that give short decimals, small whole points.

The expected answers come from :mod:`course_lib.viewing` (and :mod:`course_lib.transforms`). Each
exercise names the slips it anticipates (the compendium's perspective matrix, the angle in
degrees, a forgotten homogeneous divide, the y axis flipped, ...), computes the answer each slip
would give, and draws its numbers again until those answers differ clearly from the right one and
from each other, so that a diagnosis is never ambiguous
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.viewing`): column vectors :math:`p' = M p`; the eye looks
down :math:`-z_e`; ``near`` and ``far`` are positive distances in front of the eye; the near plane
goes to :math:`z = -1` and the far plane to :math:`z = +1` in CSS; ``gaze`` is a direction, not a
point.
"""
import math

import numpy as np

from .. import format as fmt
from .. import transforms as tf
from .. import viewing
from .core import (APART, DECIMALS, SAME, DrawnExercise, Mistake, data_note, diagnose_parts,
                   pick, small_ints)

__all__ = [
    "EXERCISES",
    "CavalierCabinet",
    "CrossRatioUnderProjection",
    "CssDepth",
    "EyeCoordinateAxes",
    "LookAtMatrix",
    "ObliqueProjection",
    "OrthographicMatrix",
    "PerspectiveDivide",
    "PerspectiveMatrix",
    "PointToEyeCoordinates",
    "SimplePerspectivePoint",
    "VanishingPoint",
    "ViewportMatrix",
    "ViewportPixel",
]

# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

_vec = fmt.vector_latex
_num = fmt.number


def _signs(rng, n):
    return rng.choice([-1.0, 1.0], size=n)


def _deg(angle_deg):
    return rf"{angle_deg}^\circ"


_MATRIX_4 = "**Answer:** the $4 \\times 4$ matrix as a numpy array. " + DECIMALS
_POINT_3 = ("**Answer:** the point as a list of 3 numbers `[x, y, z]` (ordinary coordinates; a "
            "homogeneous `[x, y, z, 1]` is accepted too). " + DECIMALS)


# ---------------------------------------------------------------------------------------------
# The textbook's P_PER
# ---------------------------------------------------------------------------------------------

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


# ---------------------------------------------------------------------------------------------
# WCS -> ECS
# ---------------------------------------------------------------------------------------------

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
        self.expected = viewing.look_at(self.eye, self.gaze, self.up)[:3, :3]

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
        self.expected = viewing.look_at(self.eye, self.gaze, self.up)

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

    def statement(self):
        return (
            _camera_words(self.eye, self.gaze, self.up) + " " + _ECS_CONVENTION + "\n\n"
            r"Give the homogeneous matrix $M_{WCS \to ECS}$ that takes world coordinates to eye "
            r"coordinates ($p_{ECS} = M\,p_{WCS}$)." "\n\n" + _MATRIX_4 + "\n\n"
            + data_note("eye", "gaze", "up"))


class PointToEyeCoordinates(DrawnExercise):
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
    answer_form = "point"
    what = "the point in eye coordinates"

    def draw(self, rng):
        self.eye, self.gaze, self.up = _camera(rng)
        self.p = small_ints(rng, 3)
        M = viewing.look_at(self.eye, self.gaze, self.up)
        self.expected_axes = M[:3, :3]
        self.expected = tf.apply(M, self.p)

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

    def statement(self):
        return (
            _camera_words(self.eye, self.gaze, self.up) + " " + _ECS_CONVENTION + "\n\n"
            rf"What are the eye coordinates of the world point $p = {_vec(self.p)}$?" "\n\n"
            + _POINT_3 + "\n\n" + data_note("eye", "gaze", "up", "p"))


# ---------------------------------------------------------------------------------------------
# ECS -> CSS
# ---------------------------------------------------------------------------------------------

def _frustum_formula(r, t, n, f):
    """The symmetric perspective matrix written out (no checks: any r, t of any sign)."""
    return np.array([[n / r, 0, 0, 0], [0, n / t, 0, 0],
                     [0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)], [0, 0, -1, 0]], float)


class PerspectiveMatrix(DrawnExercise):
    r"""The perspective ECS -> CSS matrix from a field of view, an aspect ratio, near and far.

    :math:`t = n \tan\frac{\theta}{2}`, :math:`r = t \cdot aspect`, and

    .. math:: M = \begin{bmatrix} n/r & 0 & 0 & 0 \\ 0 & n/t & 0 & 0 \\
              0 & 0 & -\frac{f+n}{f-n} & -\frac{2fn}{f-n} \\ 0 & 0 & -1 & 0 \end{bmatrix}

    Any non-zero multiple is accepted (the textbook's signed form is :math:`-M`).

    Attributes: ``fov_deg``, ``fov`` (radians), ``aspect``, ``near``, ``far``.

    Examples
    --------
    >>> ex = PerspectiveMatrix(seed=5)
    >>> ex.check(ex.expected).status, ex.check(-ex.expected).status
    ('correct', 'correct')
    >>> last_row = ex.expected.copy()
    >>> last_row[3, 2] = 1
    >>> ex.check(last_row).diagnosis
    'last row sign'
    """

    title = "The perspective projection matrix"
    homogeneous_scale = True

    def draw(self, rng):
        self.fov_deg = int(pick(rng, (60, 90, 120)))
        self.fov = math.radians(self.fov_deg)
        self.aspect = float(pick(rng, (1.0, 1.5, 2.0)))
        self.near = float(pick(rng, (1, 2)))
        self.far = float(pick(rng, (3, 4, 5, 10, 11)))
        self.expected = viewing.perspective(self.fov, self.aspect, self.near, self.far)

    def mistakes(self):
        n, f, a = self.near, self.far, self.aspect
        t = n * math.tan(self.fov / 2)
        compendium = np.array([[1 / (a * t), 0, 0, 0], [0, 1 / t, 0, 0],
                               [0, 0, 2 / (f - n), -2 * n * f / (f - n)], [0, 0, 1, 0]])
        signs = np.array([[n / (a * t), 0, 0, 0], [0, n / t, 0, 0],
                          [0, 0, (f + n) / (f - n), -2 * f * n / (f - n)], [0, 0, 1, 0]])
        last_row = self.expected.copy()
        last_row[3, 2] = 1.0
        t_deg = n * math.tan(self.fov_deg / 2)
        found = [
            Mistake(compendium, r"This is the compendium's matrix, which has two misprints: the "
                    r"first two diagonal entries lack the factor $n$ ($\frac{2n}{r-l}$, "
                    r"$\frac{2n}{t-b}$), and the depth row needs $\frac{f+n}{f-n}$ where it "
                    r"prints $\frac{2}{f-n}$. Check a matrix by sending the corners of the near "
                    r"window to $(\pm 1, \pm 1, -1)$.", "compendium matrix"),
            Mistake(signs, r"The signs do not fit together: you used the textbook's form, made "
                    r"for the **signed** planes $z_e = n_s = -\text{near}$ and "
                    r"$z_e = f_s = -\text{far}$, with the positive distances (or the other way "
                    r"round). Either plug $n_s = -n$, $f_s = -f$ into the textbook's matrix, or "
                    r"use the form with $-\frac{f+n}{f-n}$, $-\frac{2fn}{f-n}$ and $-1$ in the "
                    r"last row.", "near/far signs"),
            Mistake(last_row, r"The last row must be $(0, 0, -1, 0)$: it makes $w = -z_e$, the "
                    r"(positive) distance in front of the eye, which the homogeneous divide then "
                    r"divides by.", "last row sign"),
            Mistake(_frustum_formula(a * t_deg, t_deg, n, f), r"You fed the angle in degrees to "
                    r"$\tan$, which expects radians: use `np.radians(fov_deg)` (or the "
                    r"attribute `.fov`).", "degrees"),
        ]
        if self.fov_deg != 90:
            t_full = n * math.tan(self.fov)
            found.append(Mistake(_frustum_formula(a * t_full, t_full, n, f), r"You used the "
                                 r"whole field of view: the window's half-height is "
                                 r"$t = n \tan\frac{\theta}{2}$, with **half** the angle (the "
                                 r"angle spans from the bottom edge to the top edge).",
                                 "full angle"))
        if self.aspect != 1:
            found.append(Mistake(_frustum_formula(t / a, t, n, f), r"The aspect ratio is "
                                 r"width over height, so the window is wider than tall: "
                                 r"$r = t \cdot aspect$ (you divided).", "aspect inverted"))
        return found

    def statement(self):
        return (
            r"A perspective camera has the vertical field of view "
            rf"$\theta = {_deg(self.fov_deg)}$, the aspect ratio (width / height) "
            rf"${_num(self.aspect)}$, and its near and far planes at the distances "
            rf"$n = {_num(self.near)}$ and $f = {_num(self.far)}$ in front of the eye (the eye "
            r"looks down $-z_e$, so these planes are $z_e = -n$ and $z_e = -f$). Give the "
            r"matrix $M_{ECS \to CSS}$ that maps this view volume onto the cube $[-1, 1]^3$ "
            r"after the homogeneous divide, with the near plane going to $z = -1$ and the far "
            r"plane to $z = +1$." "\n\n" + _MATRIX_4 + r" Any non-zero multiple of the matrix "
            r"is accepted (it is the same projective transformation)." "\n\n"
            + data_note("fov_deg", "fov", "aspect", "near", "far") + " (`.fov` is in radians.)")


#: (near, far) pairs whose depth entries (f+n)/(f-n) and 2fn/(f-n) are short decimals.
_NEAR_FAR = ((1, 3), (1, 5), (2, 6), (1, 9), (2, 10), (3, 9), (1, 2))


class PerspectiveDivide(DrawnExercise):
    r"""A point of eye space through a perspective matrix and the homogeneous divide.

    :math:`(x_c, y_c, z_c, w_c) = M\,(x, y, z, 1)` with :math:`w_c = -z`, then
    :math:`(x_c, y_c, z_c) / w_c`.

    Attributes: ``M`` (the matrix), ``left``, ``right``, ``bottom``, ``top``, ``near``, ``far``
    (the frustum it comes from), ``p`` (the point in eye coordinates).

    Examples
    --------
    >>> ex = PerspectiveDivide(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> clip = ex.M @ np.append(ex.p, 1)
    >>> ex.check(clip[:3]).diagnosis, ex.check(clip).diagnosis
    ('no divide', 'no divide')
    """

    title = "A point through the perspective matrix"
    answer_form = "point"
    projective_point = True
    what = "the point in CSS"

    def draw(self, rng):
        n, f = (float(v) for v in pick(rng, _NEAR_FAR))
        self.near, self.far = n, f
        self.right = n * float(pick(rng, (0.5, 1, 2)))
        self.top = n * float(pick(rng, (0.5, 1, 2)))
        self.left, self.bottom = -self.right, -self.top
        self.M = viewing.frustum(self.left, self.right, self.bottom, self.top, n, f)
        depth = float(rng.integers(int(n), int(f) + 1))
        reach_x = int(self.right * depth / n)
        reach_y = int(self.top * depth / n)
        x = float(rng.integers(-reach_x, reach_x + 1))
        y = float(rng.integers(-reach_y, reach_y + 1))
        self.p = np.array([x, y, -depth])
        self.expected = tf.apply(self.M, self.p)

    def acceptable(self):
        return bool(self.p[0] or self.p[1])

    def mistakes(self):
        clip = self.M @ np.append(self.p, 1.0)
        return [
            Mistake(clip[:3], r"These are the clip coordinates $M\,p$, before the homogeneous "
                    r"divide. Divide $x_c, y_c, z_c$ by $w_c = -z_e$ (the fourth coordinate) to "
                    r"get the point in CSS.", "no divide"),
            Mistake(clip[:3] / self.p[2], r"You divided by $z_e$, but the fourth coordinate is "
                    r"$w_c = -z_e$ (the last row of the matrix is $(0, 0, -1, 0)$): every sign "
                    r"came out wrong.", "divided by z_e"),
            Mistake(np.array([clip[0] / clip[3], clip[1] / clip[3], clip[2]]), r"$x$ and $y$ are "
                    r"right, but depth must be divided by $w_c$ too: $z_{CSS} = z_c / w_c$ "
                    r"(it is this division that makes depth in CSS non-linear).",
                    "depth not divided"),
        ]

    def statement(self):
        return (
            r"The perspective matrix of a camera (for the frustum with "
            rf"$l = {_num(self.left)}$, $r = {_num(self.right)}$, $b = {_num(self.bottom)}$, "
            rf"$t = {_num(self.top)}$ on the near plane, near $n = {_num(self.near)}$, far "
            rf"$f = {_num(self.far)}$) is" "\n\n" rf"$$M = {fmt.matrix_latex(self.M)}.$$" "\n\n"
            rf"Where does the point $p = {_vec(self.p)}$ (eye coordinates) land in canonical "
            r"screen space?" "\n\n" + _POINT_3 + "\n\n"
            + data_note("M", "left", "right", "bottom", "top", "near", "far", "p"))


class CssDepth(DrawnExercise):
    r"""The CSS depth of a point at distance :math:`D` in front of the eye.

    :math:`z_{CSS} = \frac{f+n}{f-n} - \frac{2fn}{(f-n)\,D}`: not linear in :math:`D`
    (half-way between the planes is much closer to :math:`+1` than to 0).

    Attributes: ``near``, ``far``, ``distance``.

    Examples
    --------
    >>> ex = CssDepth(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> n, f, D = ex.near, ex.far, ex.distance
    >>> ex.check(2 * (D - n) / (f - n) - 1).diagnosis
    'linear depth'
    """

    title = "Depth in canonical screen space"
    answer_form = "number"
    what = "the depth"

    def draw(self, rng):
        n, f = (float(v) for v in pick(rng, _NEAR_FAR))
        self.near, self.far = n, f
        self.distance = float(rng.integers(int(n), int(f) + 1))
        M = viewing.perspective(math.radians(90), 1.0, n, f)
        self.expected = float(tf.apply(M, [0.0, 0.0, -self.distance])[2])

    def acceptable(self):
        return self.near < self.distance < self.far

    def mistakes(self):
        n, f, D = self.near, self.far, self.distance
        return [
            Mistake(2 * (D - n) / (f - n) - 1, r"You spread depth evenly between the planes, as "
                    r"an orthographic projection does. After a perspective projection CSS depth "
                    r"is $z_c / w_c$ with $w_c = D$: "
                    r"$z_{CSS} = \frac{f+n}{f-n} - \frac{2fn}{(f-n)\,D}$, which crowds the far "
                    r"part of the frustum near $+1$.", "linear depth"),
            Mistake(-self.expected, r"The sign is reversed: the near plane goes to $-1$ and the "
                    r"far plane to $+1$ (depth grows away from the viewer in CSS).",
                    "reversed depth"),
            Mistake(((f + n) * D - 2 * f * n) / (f - n), r"That is $z_c$, before the homogeneous "
                    r"divide: divide it by $w_c = -z_e = D$.", "no divide"),
        ]

    def statement(self):
        return (
            rf"A perspective camera has its near plane at distance $n = {_num(self.near)}$ and "
            rf"its far plane at $f = {_num(self.far)}$ in front of the eye. A point lies on the "
            rf"line of sight at distance $D = {_num(self.distance)}$ in front of the eye "
            rf"(so $z_e = {_num(-self.distance)}$). After the perspective matrix and the "
            r"homogeneous divide (near plane $\to z = -1$, far plane $\to z = +1$), what is its "
            r"depth $z_{CSS}$?" "\n\n" r"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("near", "far", "distance"))


class OrthographicMatrix(DrawnExercise):
    r"""The orthographic ECS -> CSS matrix of a box: scale and translate onto :math:`[-1, 1]^3`.

    The box is :math:`[l, r] \times [b, t] \times [-f, -n]` in eye coordinates; the near face
    goes to :math:`z = -1`, so the depth row is :math:`(0, 0, -\frac{2}{f-n},
    -\frac{f+n}{f-n})`.

    Attributes: ``left``, ``right``, ``bottom``, ``top``, ``near``, ``far``.

    Examples
    --------
    >>> ex = OrthographicMatrix(seed=8)
    >>> ex.check(ex.expected).status
    'correct'
    >>> positive = ex.expected.copy()
    >>> positive[2, 2] = 2 / (ex.far - ex.near)           # the textbook's row with n, f > 0
    >>> ex.check(positive).diagnosis
    'near/far signs'
    """

    title = "The orthographic projection matrix"

    def draw(self, rng):
        self.left = float(rng.integers(-4, 1))
        self.right = float(rng.integers(1, 7))
        self.bottom = float(rng.integers(-4, 1))
        self.top = float(rng.integers(1, 5))
        self.near = float(pick(rng, (1, 2, 3)))
        self.far = self.near + float(pick(rng, (2, 4, 5, 8)))
        self.expected = viewing.orthographic(self.left, self.right, self.bottom, self.top,
                                             self.near, self.far)

    def mistakes(self):
        l, r, b, t, n, f = self.left, self.right, self.bottom, self.top, self.near, self.far
        positive = self.expected.copy()
        positive[2, 2] = 2 / (f - n)
        flipped = self.expected.copy()
        flipped[:3, 3] *= -1
        unscaled = self.expected.copy()
        unscaled[:3, 3] = [-(r + l) / 2, -(t + b) / 2, (f + n) / 2]
        return [
            Mistake(positive, r"The depth row has the wrong sign of $\frac{2}{f-n}$. The "
                    r"textbook's row $\frac{2}{f-n}$ is written for signed planes "
                    r"$z_e = n_s, f_s$ (negative numbers); with the positive distances the box "
                    r"is $-f \le z_e \le -n$, and sending $z_e = -n$ to $-1$ needs "
                    r"$-\frac{2}{f-n}$.", "near/far signs"),
            Mistake(flipped, r"The translation has the wrong sign: the centre of the box must go "
                    r"to the origin, so the last column is "
                    r"$\left(-\frac{r+l}{r-l},\ -\frac{t+b}{t-b},\ -\frac{f+n}{f-n}\right)$.",
                    "translation sign"),
            Mistake(unscaled, r"You moved the centre of the box to the origin but did not scale "
                    r"that translation: the matrix is $S\,T(-c)$, so the last column is the "
                    r"centre times the scale factors, e.g. $-\frac{r+l}{2} \cdot \frac{2}{r-l} "
                    r"= -\frac{r+l}{r-l}$.", "translation not scaled"),
        ]

    def statement(self):
        return (
            r"An orthographic (parallel) camera sees the box "
            rf"$l = {_num(self.left)} \le x_e \le r = {_num(self.right)}$, "
            rf"$b = {_num(self.bottom)} \le y_e \le t = {_num(self.top)}$, between the near and "
            rf"far planes at the distances $n = {_num(self.near)}$ and $f = {_num(self.far)}$ "
            rf"in front of the eye (that is, ${_num(-self.far)} \le z_e \le {_num(-self.near)}$"
            r"). Give the matrix $M_{ECS \to CSS}$ that maps this box onto the cube "
            r"$[-1, 1]^3$, the near face to $z = -1$ and the far face to $z = +1$." "\n\n"
            + _MATRIX_4 + "\n\n" + data_note("left", "right", "bottom", "top", "near", "far"))


# ---------------------------------------------------------------------------------------------
# Parallel projections onto the xy plane
# ---------------------------------------------------------------------------------------------

class ObliqueProjection(DrawnExercise):
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
    answer_form = "point"
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
        found = [
            Mistake([x + z * dx / dz, y + z * dy / dz, 0], r"The shift goes the wrong way. The "
                    r"point slides along the direction of projection until $z = 0$: "
                    r"$p - \frac{z}{DOP_z} DOP$; check that your image has $z = 0$ *and* lies "
                    r"on the line through $p$ with direction $DOP$.", "sign"),
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


class CavalierCabinet(DrawnExercise):
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
    answer_form = "point"
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
        self.expected = tf.apply(viewing.oblique(self.dop), self.p)

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


# ---------------------------------------------------------------------------------------------
# CSS -> VCS
# ---------------------------------------------------------------------------------------------

def _draw_viewport(ex, rng):
    ex.xmin = float(pick(rng, (0, 10, 20, 50, 100)))
    ex.ymin = float(pick(rng, (0, 20, 40, 60)))
    ex.xmax = ex.xmin + float(pick(rng, (320, 400, 640, 800)))
    ex.ymax = ex.ymin + float(pick(rng, (240, 300, 480, 600)))
    ex.zmin, ex.zmax = 0.0, 1.0


def _viewport_words(ex):
    return (rf"The viewport has its bottom-left corner at $(x_{{min}}, y_{{min}}) = "
            rf"({_num(ex.xmin)}, {_num(ex.ymin)})$ and its top-right corner at "
            rf"$(x_{{max}}, y_{{max}}) = ({_num(ex.xmax)}, {_num(ex.ymax)})$ (pixels, y up), "
            rf"and the depth range is $[z_{{min}}, z_{{max}}] = [{_num(ex.zmin)}, "
            rf"{_num(ex.zmax)}]$.")


class ViewportMatrix(DrawnExercise):
    r"""The CSS -> VCS matrix: scale by half the viewport's size, shift to its centre.

    Attributes: ``xmin``, ``ymin``, ``xmax``, ``ymax``, ``zmin``, ``zmax``.

    Examples
    --------
    >>> ex = ViewportMatrix(seed=11)
    >>> ex.check(ex.expected).status
    'correct'
    >>> printed = ex.expected.copy()
    >>> printed[2, 2] = (ex.ymax - ex.ymin) / 2           # the compendium's depth row
    >>> ex.check(printed).diagnosis
    'compendium depth row'
    """

    title = "The viewport matrix"

    def draw(self, rng):
        _draw_viewport(self, rng)
        self.expected = viewing.viewport(self.xmin, self.ymin, self.xmax, self.ymax, self.zmin,
                                         self.zmax)

    def mistakes(self):
        printed = self.expected.copy()
        printed[2, 2] = (self.ymax - self.ymin) / 2
        flipped = self.expected.copy()
        flipped[:3, 3] *= -1
        whole = self.expected.copy()
        whole[[0, 1, 2], [0, 1, 2]] *= 2
        y_down = self.expected.copy()
        y_down[1, 1] *= -1
        return [
            Mistake(printed, r"The depth row scales by $\frac{y_{max}-y_{min}}{2}$, as the "
                    r"compendium prints it; depth has its own range: the entry is "
                    r"$\frac{z_{max}-z_{min}}{2}$ (here it maps $[-1, 1]$ onto "
                    r"$[z_{min}, z_{max}]$).", "compendium depth row"),
            Mistake(flipped, r"The translations have the wrong sign: the centre of the cube "
                    r"(CSS 0) must go to the centre of the viewport, "
                    r"$\left(\frac{x_{max}+x_{min}}{2}, \frac{y_{max}+y_{min}}{2}, "
                    r"\frac{z_{max}+z_{min}}{2}\right)$.", "translation sign"),
            Mistake(whole, r"The scale factors are twice too large. The cube is 2 units wide "
                    r"($-1$ to $1$), so it is scaled by half the viewport's size: "
                    r"$\frac{x_{max}-x_{min}}{2}$ and so on.", "missing halves"),
            Mistake(y_down, r"You flipped y, as for an image whose rows are counted from the "
                    r"top. Here the viewport's y axis points up like CSS's, so the entry is "
                    r"$+\frac{y_{max}-y_{min}}{2}$.", "y flipped"),
        ]

    def statement(self):
        return (
            _viewport_words(self) + r" Give the matrix $M_{CSS \to VCS}$ that maps the cube "
            r"$[-1, 1]^3$ of canonical screen space onto the viewport and the depth range "
            r"($(-1, -1, -1)$ to the bottom-left corner at depth $z_{min}$)." "\n\n"
            + _MATRIX_4 + "\n\n"
            + data_note("xmin", "ymin", "xmax", "ymax", "zmin", "zmax"))


class ViewportPixel(DrawnExercise):
    r"""The viewport coordinates (pixel x, y and depth) of a point of canonical screen space.

    Attributes: ``xmin``, ``ymin``, ``xmax``, ``ymax``, ``zmin``, ``zmax``, ``q`` (the CSS point).

    Examples
    --------
    >>> ex = ViewportPixel(seed=12)
    >>> ex.check(ex.expected).status
    'correct'
    >>> x, y, z = ex.expected
    >>> ex.check([x, ex.ymin + ex.ymax - y, z]).diagnosis
    'y flipped'
    """

    title = "From CSS to the viewport"
    answer_form = "point"
    what = "the point in viewport coordinates"

    def draw(self, rng):
        _draw_viewport(self, rng)
        quarters = np.arange(-4, 5) / 4
        self.q = np.array([float(pick(rng, quarters)) for _ in range(3)])
        self.expected = tf.apply(viewing.viewport(self.xmin, self.ymin, self.xmax, self.ymax,
                                                  self.zmin, self.zmax), self.q)

    def mistakes(self):
        x, y, z = self.expected
        qx, qy, qz = self.q
        w, h = self.xmax - self.xmin, self.ymax - self.ymin
        return [
            Mistake([x, self.ymin + self.ymax - y, z], r"You flipped y, as if rows were counted "
                    r"from the top. The viewport's y axis points up, like CSS's: "
                    r"$y_v = \frac{y_{max}-y_{min}}{2}\,y + \frac{y_{max}+y_{min}}{2}$.",
                    "y flipped"),
            Mistake([x, y, h / 2 * qz + (self.zmin + self.zmax) / 2], r"Depth was scaled by "
                    r"half the viewport's *height*, as the compendium's matrix has it. Depth "
                    r"has its own range: $z_v = \frac{z_{max}-z_{min}}{2}\,z + "
                    r"\frac{z_{max}+z_{min}}{2}$.", "compendium depth row"),
            Mistake([x - self.xmin, y - self.ymin, z], r"The viewport does not start at pixel "
                    r"$(0, 0)$: add its corner, the translation is "
                    r"$\frac{x_{max}+x_{min}}{2}$, not $\frac{x_{max}-x_{min}}{2}$.",
                    "offset missing"),
            Mistake([w / 2 * qx + self.xmin, h / 2 * qy + self.ymin, z], r"CSS runs from $-1$ "
                    r"to $1$, so its centre 0 goes to the centre of the viewport: "
                    r"$x_v = x_{min} + \frac{w}{2}\,(x + 1)$ (you left out the $+1$).",
                    "centre shift missing"),
        ]

    def statement(self):
        return (
            _viewport_words(self) + rf" A point has the CSS coordinates $q = {_vec(self.q)}$. "
            r"Where does it land: which pixel coordinates $(x_v, y_v)$ and which depth $z_v$?"
            "\n\n" r"**Answer:** a list of 3 numbers `[x_v, y_v, z_v]`. " + DECIMALS + "\n\n"
            + data_note("xmin", "ymin", "xmax", "ymax", "zmin", "zmax", "q"))


# ---------------------------------------------------------------------------------------------
# What perspective keeps
# ---------------------------------------------------------------------------------------------

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
        self.d = float(pick(rng, (1, 2, 4)))
        start = np.array([*rng.integers(-2, 3, size=2), pick(rng, (1, 2))], dtype=float)
        ux, uy = small_ints(rng, 2, -2, 2)
        u = np.array([ux, uy, float(pick(rng, (1, 2)))])
        steps = np.sort(rng.choice(6, size=4, replace=False)).astype(float)
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


class VanishingPoint(DrawnExercise):
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
    answer_form = "point"
    projective_point = True
    what = "the vanishing point"

    def draw(self, rng):
        self.d = float(pick(rng, (1, 2, 3, 4)))
        ux, uy = small_ints(rng, 2, -3, 3)
        self.u = np.array([ux, uy, float(pick(rng, (-3, -2, -1, 1, 2, 3)))])
        self.p0 = np.array([*rng.integers(-3, 4, size=2), pick(rng, (1, 2, 3, 4))],
                           dtype=float)
        homogeneous = viewing.simple_perspective(self.d) @ np.append(self.u, 0.0)
        self.expected = homogeneous[:3] / homogeneous[3]

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


#: The exercises of chapter 4, in the order of the solutions notebook.
EXERCISES = (
    SimplePerspectivePoint,
    EyeCoordinateAxes,
    LookAtMatrix,
    PointToEyeCoordinates,
    PerspectiveMatrix,
    PerspectiveDivide,
    CssDepth,
    OrthographicMatrix,
    ObliqueProjection,
    CavalierCabinet,
    ViewportMatrix,
    ViewportPixel,
    CrossRatioUnderProjection,
    VanishingPoint,
)
