"""Chapter 18 exercises: streamlines (a step of RK4, the drift of Euler's method).

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import math

import numpy as np

from ... import format as fmt
from ... import scivis
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _Chapter18, _num, _vec

__all__ = [
    "EulerDrift",
    "RK4Step",
]


# ---------------------------------------------------------------------------------------------
# Streamlines
# ---------------------------------------------------------------------------------------------

def _linear(a, b):
    """The expression a x + b y with whole coefficients, as LaTeX ("2x - y", "-x", "0")."""
    text = ""
    for coef, var in ((a, "x"), (b, "y")):
        if coef == 0:
            continue
        size = "" if abs(coef) == 1 else _num(abs(coef))
        sign = "-" if coef < 0 else ("+" if text else "")
        text += (f" {sign} " if text else sign) + size + var
    return text or "0"


def _at(q):
    """The field at the point q, as LaTeX: v(x, y)."""
    return "v" + _vec(q, 4)


class RK4Step(_Chapter18):
    r"""One step of the classic Runge-Kutta method (RK4) in a linear velocity field.

    :math:`v(p) = M p`; :math:`k_1 = v(p)`, :math:`k_2 = v(p + \tfrac h2 k_1)`,
    :math:`k_3 = v(p + \tfrac h2 k_2)`, :math:`k_4 = v(p + h k_3)`,
    :math:`p' = p + \tfrac h6 (k_1 + 2k_2 + 2k_3 + k_4)`.

    Attributes: ``M`` (the 2 x 2 matrix of the field), ``p`` (the start point), ``h``.

    Examples
    --------
    >>> ex = RK4Step(seed=0)
    >>> v = lambda q: ex.M @ q
    >>> k1 = v(ex.p); k2 = v(ex.p + ex.h / 2 * k1); k3 = v(ex.p + ex.h / 2 * k2)
    >>> k4 = v(ex.p + ex.h * k3)
    >>> ex.check(ex.p + ex.h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)).status
    'correct'
    >>> ex.check(ex.p + ex.h * k1).diagnosis
    'euler'
    """

    title = "One RK4 step"
    answer_form = "point"
    what = "the new point"
    may_coincide = ("no h",)
    advice = (r"Compute the four slopes one after the other, each from the previous one "
              r"($k_2$ and $k_3$ half a step ahead, $k_4$ a full step), then take the weighted "
              r"average $\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$ times $h$.")

    def draw(self, rng):
        self.M = rng.integers(-2, 3, size=(2, 2)).astype(float)
        self.p = rng.integers(-2, 3, size=2).astype(float)
        self.h = 0.5
        self.expected = scivis.streamline(self._v, self.p, self.h, n_steps=1, method="rk4")[1]

    def _v(self, q):
        return np.asarray(q, dtype=float) @ self.M.T

    def acceptable(self):
        return np.linalg.matrix_rank(self.M) == 2 and bool(self.p.any()) and bool(
            np.isfinite(self.expected).all())

    def mistakes(self):
        v, p, h = self._v, self.p, self.h
        k1 = v(p)
        k2 = v(p + h / 2 * k1)
        k3 = v(p + h / 2 * k2)
        k4 = v(p + h * k3)
        f2 = v(p + h * k1)
        f3 = v(p + h * f2)
        f4 = v(p + h * f3)
        return [
            Mistake(p + h * k1, r"That is one **Euler** step, $p + h\,k_1$: it follows the "
                    r"slope at the start only. RK4 also samples the field half a step and a full "
                    r"step ahead and averages four slopes.", "euler"),
            Mistake(p + h * k2, r"That is the **midpoint** method (RK2), $p + h\,k_2$. RK4 goes "
                    r"on: $k_3 = v(p + \tfrac h2 k_2)$, $k_4 = v(p + h\,k_3)$, and averages "
                    r"$\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$.", "rk2"),
            Mistake(p + h / 4 * (k1 + k2 + k3 + k4), r"You averaged the four slopes with equal "
                    r"weights. The middle slopes count twice: $\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$ "
                    r"(Simpson's rule).", "equal weights"),
            Mistake(p + h / 6 * (k1 + 2 * f2 + 2 * f3 + f4), r"You evaluated $k_2$ and $k_3$ a "
                    r"full step ahead. They are taken at the half step: "
                    r"$k_2 = v(p + \tfrac h2 k_1)$, $k_3 = v(p + \tfrac h2 k_2)$.",
                    "full steps"),
            Mistake(p + (k1 + 2 * k2 + 2 * k3 + k4) / 6, r"You forgot to multiply the averaged "
                    r"slope by the step $h$: $p' = p + \frac h6 (k_1 + 2k_2 + 2k_3 + k_4)$.",
                    "no h"),
        ]

    def statement(self):
        (a, b), (c, d) = self.M
        return (
            rf"A 2D velocity field is $v(x, y) = ({_linear(a, b)},\ {_linear(c, d)})$, i.e. "
            rf"$v(p) = M p$ with $M = {fmt.matrix_latex(self.M)}$. Trace a "
            rf"streamline from $p = {_vec(self.p)}$ with one step of the classic Runge-Kutta "
            rf"method (RK4) of size $h = {_num(self.h)}$: $k_1 = v(p)$, "
            r"$k_2 = v(p + \tfrac h2 k_1)$, $k_3 = v(p + \tfrac h2 k_2)$, $k_4 = v(p + h\,k_3)$, "
            r"$p' = p + \tfrac h6 (k_1 + 2k_2 + 2k_3 + k_4)$." "\n\n"
            r"**Answer:** the point $p'$ as a list of 2 numbers `[x, y]`. " + DECIMALS + "\n\n"
            + data_note("M", "p", "h"))

    def _slopes(self):
        """The points where the field is sampled and the four slopes, v(q) = M q by hand."""
        M, p, h = self.M, self.p, self.h

        def v(q):
            return np.array([M[0, 0] * q[0] + M[0, 1] * q[1], M[1, 0] * q[0] + M[1, 1] * q[1]])

        k1 = v(p)
        q2 = p + h / 2 * k1
        k2 = v(q2)
        q3 = p + h / 2 * k2
        k3 = v(q3)
        q4 = p + h * k3
        k4 = v(q4)
        return (k1, q2, k2, q3, k3, q4, k4)

    def hints(self):
        k1, q2, k2, q3, k3, q4, k4 = self._slopes()
        return [
            r"RK4 samples the field four times: at the start ($k_1$), twice half a step ahead "
            r"($k_2$ from $k_1$, $k_3$ from $k_2$) and once a full step ahead ($k_4$ from $k_3$), "
            r"then moves by $h$ times the weighted mean $\frac16 (k_1 + 2k_2 + 2k_3 + k_4)$.",
            rf"$k_1 = v(p) = M p = {_vec(k1, 4)}$; the half step goes to "
            rf"$p + \tfrac h2 k_1 = {_vec(q2, 4)}$.",
            rf"$k_2 = {_at(q2)} = {_vec(k2, 4)}$, then "
            rf"$k_3 = v(p + \tfrac h2 k_2) = {_at(q3)} = {_vec(k3, 4)}$.",
        ]

    def worked(self):
        k1, q2, k2, q3, k3, q4, k4 = self._slopes()
        mean = (k1 + 2 * k2 + 2 * k3 + k4) / 6
        new = self.p + self.h * mean
        return Worked([
            rf"$k_1 = v(p) = M {_vec(self.p)} = {_vec(k1, 4)}$.",
            rf"$k_2 = v(p + \tfrac h2 k_1) = {_at(q2)} = {_vec(k2, 4)}$.",
            rf"$k_3 = v(p + \tfrac h2 k_2) = {_at(q3)} = {_vec(k3, 4)}$.",
            rf"$k_4 = v(p + h\,k_3) = {_at(q4)} = {_vec(k4, 4)}$.",
            rf"Weighted mean: $\frac16 (k_1 + 2k_2 + 2k_3 + k_4) = {_vec(mean, 4)}$, so "
            rf"$p' = p + h \cdot {_vec(mean, 4)} = {_vec(self.p)} + {_num(self.h)} \cdot "
            rf"{_vec(mean, 4)} = {_vec(new, 4)}$.",
        ], new)


class EulerDrift(_Chapter18):
    r"""How far Euler's method drifts outwards on the circular flow :math:`v = (-y, x)`.

    One Euler step moves along the tangent, :math:`|p + h\,v(p)| = |p| \sqrt{1 + h^2}`, so after
    :math:`n` steps the radius is :math:`r_0 (1 + h^2)^{n/2}` instead of :math:`r_0`.

    Attributes: ``r0``, ``h``, ``n``.

    Examples
    --------
    >>> ex = EulerDrift(seed=0)
    >>> ex.check(ex.r0 * (1 + ex.h ** 2) ** (ex.n / 2)).status
    'correct'
    >>> ex.check(ex.r0).diagnosis
    'no drift'
    """

    title = "Euler's drift on a circular flow"
    answer_form = "number"
    what = "the radius"
    advice = (r"Each Euler step is perpendicular to the radius and $h\,r$ long: Pythagoras gives "
              r"the new radius $r\sqrt{1 + h^2}$; repeat $n$ times.")

    def draw(self, rng):
        self.r0 = float(pick(rng, (1, 2, 3, 4, 5)))
        self.h = float(pick(rng, (0.1, 0.2, 0.25, 0.3, 0.4, 0.5)))
        self.n = int(rng.integers(3, 13))
        line = scivis.streamline(scivis.example_vector_field("vortex"), [self.r0, 0.0], self.h,
                                 n_steps=self.n, method="euler")
        self.expected = float(np.linalg.norm(line[-1]))

    def mistakes(self):
        r, h, n = self.r0, self.h, self.n
        return [
            Mistake(r, r"On the exact streamline the radius stays $r_0$, but Euler's method "
                    r"does not follow it: each step goes along the tangent and ends outside "
                    r"the circle.", "no drift"),
            Mistake(r * np.sqrt(1 + h * h), rf"That is the radius after one step; the "
                    rf"question asks for $n = {n}$. Each step multiplies the radius by "
                    r"$\sqrt{1 + h^2}$ again.", "one step"),
            Mistake(r * (1 + h * h) ** n, r"You forgot the square root: a step of length "
                    r"$h\,r$ at right angles to the radius gives $r\sqrt{1 + h^2}$ "
                    r"(Pythagoras), not $r (1 + h^2)$.", "no root"),
            Mistake(r * (1 + h) ** n, r"The step is at right angles to the radius, not along "
                    r"it: the radius grows by the factor $\sqrt{1 + h^2}$, not $1 + h$.",
                    "radial step"),
        ]

    def statement(self):
        return (
            r"The velocity field $v(x, y) = (-y, x)$ turns around the origin: its streamlines "
            rf"are circles. Starting at $({_num(self.r0)}, 0)$, a streamline is traced with "
            rf"$n = {self.n}$ steps of **Euler's method**, $p \leftarrow p + h\,v(p)$, with "
            rf"$h = {_num(self.h)}$. How far from the origin is the last point?" "\n\n"
            r"**Answer:** one number (the radius). " + DECIMALS + "\n\n"
            + data_note("r0", "h", "n"))

    def hints(self):
        factor = math.sqrt(1 + self.h ** 2)
        return [
            r"At $p$ the velocity $v(p) = (-y, x)$ is perpendicular to $p$ and as long as $p$: "
            r"an Euler step goes along the tangent, a distance $h\,\lVert p \rVert$.",
            rf"Pythagoras: one step takes the radius from $r$ to $r\sqrt{{1 + h^2}} = "
            rf"r\sqrt{{{_num(1 + self.h ** 2, 4)}}} = {_num(factor, 4)}\, r$.",
            rf"Each of the {self.n} steps multiplies the radius by that factor again: "
            rf"$r_{{{self.n}}} = {_num(self.r0)} \cdot {_num(factor, 4)}^{{{self.n}}}$.",
        ]

    def worked(self):
        factor = math.sqrt(1 + self.h ** 2)
        radius = self.r0 * factor ** self.n
        return Worked([
            rf"A step from $p$ moves by $h\,v(p)$, perpendicular to $p$ (as $v \cdot p = -yx + "
            rf"xy = 0$) and of length $h\,\lVert p \rVert$: by Pythagoras the new radius is "
            rf"$\lVert p \rVert \sqrt{{1 + h^2}} = \sqrt{{1 + {_num(self.h ** 2, 4)}}}\, "
            rf"\lVert p \rVert = {_num(factor, 5)}\, \lVert p \rVert$.",
            rf"After $n = {self.n}$ steps: $r = r_0 (1 + h^2)^{{n/2}} = {_num(self.r0)} \cdot "
            rf"{_num(factor, 5)}^{{{self.n}}} = {_num(radius, 4)}$, "
            rf"{_num(100 * (factor ** self.n - 1), 1)} % outside the true circle of radius "
            rf"{_num(self.r0)}.",
        ], radius)
