"""Chapter 4 exercises: ECS -> CSS.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import format as fmt
from ... import transforms as tf
from ... import viewing
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick
from . import _MATRIX_4, _POINT_3, PointAnswer, _deg, _mat, _num, _par, _snap, _vec

__all__ = [
    "CssDepth",
    "OrthographicMatrix",
    "PerspectiveDivide",
    "PerspectiveMatrix",
]


def _swapped_text(n, f):
    """What a student is told who swapped near and far in a projection matrix."""
    return (rf"You swapped near and far: $n$ is the distance of the **near** plane, the smaller "
            rf"one (here $n = {_num(n)}$, $f = {_num(f)}$). With the two exchanged both entries "
            r"of the depth row change sign, and the near plane would go to $z = +1$, the far "
            r"one to $-1$. Check: $z_e = -n$ must give $-1$.")


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
        self.expected = _snap(viewing.perspective(self.fov, self.aspect, self.near, self.far))

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
        found.append(Mistake(_frustum_formula(a * t * f / n, t * f / n, f, n),
                             _swapped_text(n, f), "near and far swapped"))
        return found

    def _numbers(self):
        n, f = self.near, self.far
        tan = math.tan(math.radians(self.fov_deg / 2))
        t = n * tan
        r = t * self.aspect
        return n, f, tan, t, r

    def hints(self):
        n, f, tan, t, r = self._numbers()
        return [
            r"The near plane's window has half-height $t = n \tan\frac{\theta}{2}$ and "
            r"half-width $r = t \cdot aspect$; the matrix is $\begin{bmatrix} n/r & 0 & 0 & 0 "
            r"\\ 0 & n/t & 0 & 0 \\ 0 & 0 & -\frac{f+n}{f-n} & -\frac{2fn}{f-n} \\ 0 & 0 & -1 "
            r"& 0 \end{bmatrix}$.",
            rf"Half the field of view is ${_num(self.fov_deg / 2)}^\circ$, "
            rf"$\tan {_num(self.fov_deg / 2)}^\circ = {_num(tan)}$: $t = {_num(t)}$ and "
            rf"$r = {_num(r)}$, so $n/r = {_num(n / r)}$ and $n/t = {_num(n / t)}$.",
            rf"The depth row: $-\frac{{f+n}}{{f-n}} = {_num(-(f + n) / (f - n))}$ and "
            rf"$-\frac{{2fn}}{{f-n}} = {_num(-2 * f * n / (f - n))}$; the last row "
            r"$(0, 0, -1, 0)$ makes $w = -z_e$.",
        ]

    def worked(self):
        n, f, tan, t, r = self._numbers()
        P = np.zeros((4, 4))
        P[0, 0], P[1, 1] = n / r, n / t
        P[2, 2], P[2, 3] = -(f + n) / (f - n), -2 * f * n / (f - n)
        P[3, 2] = -1.0
        return Worked([
            rf"$t = n \tan\frac{{\theta}}{{2}} = {_num(n)} \tan {_num(self.fov_deg / 2)}^\circ "
            rf"= {_num(t)}$ and $r = t \cdot aspect = {_num(t)} \cdot {_num(self.aspect)} = "
            rf"{_num(r)}$.",
            rf"$n/r = {_num(n / r)}$ and $n/t = {_num(n / t)}$.",
            rf"Depth: $-\frac{{f+n}}{{f-n}} = -\frac{{{_num(f + n)}}}{{{_num(f - n)}}} = "
            rf"{_num(P[2, 2])}$, $-\frac{{2fn}}{{f-n}} = -\frac{{{_num(2 * f * n)}}}"
            rf"{{{_num(f - n)}}} = {_num(P[2, 3])}$ (then $z_e = -n \to -1$ and "
            r"$z_e = -f \to +1$).",
            rf"With the last row $(0, 0, -1, 0)$: $M = {_mat(P)}$.",
        ], P)

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


class PerspectiveDivide(PointAnswer, DrawnExercise):
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
        self.expected = _snap(tf.apply(self.M, self.p))

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

    def _clip(self):
        """The clip coordinates, row by row."""
        h = np.append(np.asarray(self.p, dtype=float), 1.0)
        return np.array([float(row @ h) for row in self.M])

    def hints(self):
        clip = self._clip()
        return [
            r"Two steps: multiply, $(x_c, y_c, z_c, w_c) = M\,(x, y, z, 1)$, then divide the "
            r"first three by $w_c$ (the homogeneous divide).",
            rf"The last row of $M$ is $(0, 0, -1, 0)$, so $w_c = -z_e = {_num(clip[3])}$, the "
            r"distance of the point in front of the eye.",
            rf"Here $M\,p = {_vec(clip)}$; divide by ${_num(clip[3])}$.",
        ]

    def worked(self):
        clip = self._clip()
        x, y, z = self.p
        css = clip[:3] / clip[3]
        M = self.M
        return Worked([
            rf"Append $w = 1$: $p = {_vec(np.append(self.p, 1.0))}$.",
            rf"Row by row: $x_c = {_num(M[0, 0])} \cdot {_par(x)} + {_num(M[0, 2])} \cdot "
            rf"{_par(z)} = {_num(clip[0])}$, $y_c = {_num(M[1, 1])} \cdot {_par(y)} + "
            rf"{_num(M[1, 2])} \cdot {_par(z)} = {_num(clip[1])}$, $z_c = {_num(M[2, 2])} "
            rf"\cdot {_par(z)} + {_par(M[2, 3])} = {_num(clip[2])}$, $w_c = -z = "
            rf"{_num(clip[3])}$.",
            rf"Divide by $w_c = {_num(clip[3])}$: $p_{{CSS}} = {_vec(css)}$ (inside the cube "
            r"$[-1, 1]^3$, as a visible point must be).",
        ], css)

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
        # depths f - n of 2, 4, 5, 8, 10, 16, 20: (f+n)/(f-n) and 2fn/(f-n) are short decimals
        n = float(pick(rng, (1, 2, 3, 4, 5)))
        f = n + float(pick(rng, (2, 4, 5, 8, 10, 16, 20)))
        self.near, self.far = n, f
        self.distance = float(rng.integers(int(n) + 1, int(f)))
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

    def hints(self):
        n, f, D = self.near, self.far, self.distance
        a, b = (f + n) / (f - n), 2 * f * n / (f - n)
        return [
            r"The depth row of the perspective matrix is $(0, 0, -\frac{f+n}{f-n}, "
            r"-\frac{2fn}{f-n})$ and its last row $(0, 0, -1, 0)$: compute $z_c$ and $w_c$ for "
            r"$z_e = -D$, then divide.",
            rf"Here $\frac{{f+n}}{{f-n}} = {_num(a)}$ and $\frac{{2fn}}{{f-n}} = {_num(b)}$, so "
            rf"$z_c = {_num(a)}\,D - {_num(b)}$ and $w_c = D = {_num(D)}$.",
            rf"$z_c = {_num(a * D - b)}$; divide by $w_c = {_num(D)}$ (the result is not linear "
            r"in $D$: the far half of the frustum is squeezed near $+1$).",
        ]

    def worked(self):
        n, f, D = self.near, self.far, self.distance
        a, b = (f + n) / (f - n), 2 * f * n / (f - n)
        z_clip = -a * (-D) - b
        z_css = z_clip / D
        return Worked([
            rf"$z_e = -D = {_num(-D)}$; the depth row gives $z_c = -\frac{{f+n}}{{f-n}}\,z_e - "
            rf"\frac{{2fn}}{{f-n}}$ with $\frac{{f+n}}{{f-n}} = \frac{{{_num(f + n)}}}"
            rf"{{{_num(f - n)}}} = {_num(a)}$ and $\frac{{2fn}}{{f-n}} = "
            rf"\frac{{{_num(2 * f * n)}}}{{{_num(f - n)}}} = {_num(b)}$.",
            rf"$z_c = {_num(a)} \cdot {_num(D)} - {_num(b)} = {_num(z_clip)}$ and "
            rf"$w_c = -z_e = {_num(D)}$.",
            rf"$z_{{CSS}} = z_c / w_c = {_num(z_clip)} / {_num(D)} = {_num(z_css, 4)}$.",
        ], z_css)

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
        swapped = self.expected.copy()                 # n and f exchanged in the depth row
        swapped[2, 2:] = [2 / (f - n), (f + n) / (f - n)]
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
            Mistake(swapped,
                    _swapped_text(n, f), "near and far swapped"),
        ]

    def hints(self):
        l, r, b, t, n, f = self.left, self.right, self.bottom, self.top, self.near, self.far
        return [
            r"Scale and translate each axis on its own so that the box becomes $[-1, 1]^3$: "
            r"$x_e = l \to -1$, $x_e = r \to +1$, and likewise for $y_e$; in depth "
            r"$z_e = -n \to -1$ and $z_e = -f \to +1$.",
            rf"For $x$: the factor is $\frac{{2}}{{r-l}} = {_num(2 / (r - l))}$ and the shift "
            rf"$-\frac{{r+l}}{{r-l}} = {_num(-(r + l) / (r - l))}$; for $y$: "
            rf"${_num(2 / (t - b))}$ and ${_num(-(t + b) / (t - b))}$.",
            rf"Depth runs the other way (the box is at negative $z_e$): the factor is "
            rf"$-\frac{{2}}{{f-n}} = {_num(-2 / (f - n))}$ and the shift "
            rf"$-\frac{{f+n}}{{f-n}} = {_num(-(f + n) / (f - n))}$.",
        ]

    def worked(self):
        l, r, b, t, n, f = self.left, self.right, self.bottom, self.top, self.near, self.far
        M = np.diag([2 / (r - l), 2 / (t - b), -2 / (f - n), 1.0])
        M[:3, 3] = [-(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n)]
        return Worked([
            rf"$x$: $\frac{{2}}{{r-l}} = \frac{{2}}{{{_num(r - l)}}} = {_num(M[0, 0])}$, "
            rf"shift $-\frac{{r+l}}{{r-l}} = {_num(M[0, 3])}$ (then $l \to -1$, $r \to 1$).",
            rf"$y$: $\frac{{2}}{{t-b}} = \frac{{2}}{{{_num(t - b)}}} = {_num(M[1, 1])}$, shift "
            rf"$-\frac{{t+b}}{{t-b}} = {_num(M[1, 3])}$.",
            rf"Depth: the box spans $z_e$ from ${_num(-f)}$ to ${_num(-n)}$; "
            rf"$-\frac{{2}}{{f-n}} = {_num(M[2, 2])}$ and $-\frac{{f+n}}{{f-n}} = "
            rf"{_num(M[2, 3])}$ send $z_e = -n$ to $-1$ and $z_e = -f$ to $+1$.",
            rf"$M = {_mat(M)}$.",
        ], M)

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
