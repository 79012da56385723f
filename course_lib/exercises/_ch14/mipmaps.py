"""Chapter 14 exercises: Mipmaps and procedural textures.

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import functools
import math

import numpy as np

from ... import texturing
from ..core import DECIMALS, Feedback, Mistake, Worked, data_note, latex_fraction, pick
from . import _Chapter14, _n4, _num, _Parts, _vec

__all__ = [
    "Checkerboard",
    "MipLevel",
]


_frac = functools.partial(latex_fraction, max_denominator=1024)


def _signed(x):
    """A fraction of a product, bracketed when negative."""
    text = _frac(x)
    return f"({text})" if text.startswith("-") else text


_TRIPLES = ((3, 4, 5), (4, 3, 5), (6, 8, 10), (8, 6, 10), (5, 12, 13), (12, 5, 13), (0, 4, 4),
            (6, 0, 6), (0, 8, 8), (8, 15, 17), (15, 8, 17), (2, 0, 2), (0, 3, 3))


class MipLevel(_Parts):
    r"""The texel footprint :math:`\rho`, the mipmap level :math:`\lambda = \log_2 \rho`, and
    the size of level :math:`k`.

    :math:`\rho = \max\left(\sqrt{(W u_x)^2 + (H v_x)^2}, \sqrt{(W u_y)^2 + (H v_y)^2}\right)`
    from the derivatives of the texture coordinates along the screen's x and y; level
    :math:`k` of a :math:`W \times H` texture is :math:`W/2^k \times H/2^k`: whole numbers,
    compared exactly (``64.0`` is 64, and 63 is wrong).

    Attributes: ``width``, ``height`` (W, H), ``du_dx``, ``dv_dx``, ``du_dy``, ``dv_dy``,
    ``k``.

    Examples
    --------
    >>> ex = MipLevel(seed=10)
    >>> ex.check(ex.expected).status
    'correct'
    >>> rho, lam, w, h = ex.expected
    >>> ex.check([rho, np.log(rho), w, h]).diagnosis
    'natural logarithm'
    >>> ex.check([rho, lam, w + 1, h]).status, ex.check([rho, lam, float(w), h]).status
    ('wrong', 'correct')
    """

    title = "Mipmap level and size"
    form_hint = "`[rho, lambda, width_k, height_k]`."
    advice = (r"$\rho$ is the longer of the two screen steps measured in texels, "
            r"$\lambda = \log_2 \rho$, and each level halves both sides.")

    def draw(self, rng):
        self.width = int(pick(rng, (128, 256, 512)))
        self.height = int(pick(rng, (self.width, self.width // 2)))
        first, second = pick(rng, _TRIPLES), pick(rng, _TRIPLES)
        signs = rng.choice([-1.0, 1.0], size=4)
        self.du_dx = signs[0] * first[0] / self.width
        self.dv_dx = signs[1] * first[1] / self.height
        self.du_dy = signs[2] * second[0] / self.width
        self.dv_dy = signs[3] * second[1] / self.height
        self.k = int(pick(rng, (1, 2, 3)))
        rho = float(texturing.texel_footprint((self.height, self.width), self.du_dx,
                                              self.dv_dx, self.du_dy, self.dv_dy))
        lam = float(texturing.mip_level(rho))
        level = texturing.mipmap(np.zeros((self.height, self.width)))[self.k]
        self.expected = np.array([rho, lam, float(level.shape[1]), float(level.shape[0])])
        self._steps = (first, second)

    def acceptable(self):
        (a1, b1, c1), (a2, b2, c2) = self._steps
        return c1 != c2 and self.expected[0] > 2

    def parts(self):
        rho, lam, w, h = self.expected
        w, h = int(w), int(h)                 # whole numbers: compared exactly
        (a1, b1, c1), (a2, b2, c2) = self._steps
        k, W, H = self.k, self.width, self.height
        footprint = [
            Mistake(max(a1 + b1, a2 + b2), r"You added the two texel distances. A step on the "
                    r"screen moves $W u_x$ texels across and $H v_x$ texels up: its length is "
                    r"$\sqrt{(W u_x)^2 + (H v_x)^2}$ (Pythagoras).", "lengths added"),
            Mistake(min(c1, c2), r"That is the **shorter** of the two screen steps. The level "
                    r"must avoid aliasing along the direction where the texture is squeezed "
                    r"most, so take the **longer** one: $\rho = \max(\dots)$.",
                    "min instead of max"),
            Mistake(max(math.hypot(self.du_dx, self.dv_dx), math.hypot(self.du_dy, self.dv_dy)),
                    r"The derivatives are in texture coordinates (fractions of the texture); "
                    r"multiply $u$'s by $W$ and $v$'s by $H$ to count **texels** per pixel.",
                    "not in texels"),
        ]
        level = [
            Mistake(math.log(rho), r"That is the natural logarithm. Each level halves the "
                    r"texture, so the level is the number of halvings: $\log_2 \rho$ "
                    r"(`np.log2`).", "natural logarithm"),
            Mistake(math.log10(rho), r"That is $\log_{10}$. Each level halves the texture, so "
                    r"the level is $\log_2 \rho$ (`np.log2`).", "log10"),
            Mistake(lam / 2, r"The factor $\tfrac12$ belongs to the form with the **squared** "
                    r"footprint, $\lambda = \tfrac12 \log_2 \rho^2$. With $\rho$ itself, "
                    r"$\lambda = \log_2 \rho$.", "half the logarithm"),
            Mistake(lam + 1, r"Off by one: level 0 is the full texture, where one texel is one "
                    r"pixel ($\rho = 1$, $\log_2 1 = 0$); do not add 1.", "off by one"),
        ]
        size = (r"Level $k$ is the texture halved $k$ times: $W / 2^k \times H / 2^k$ "
                r"(level 0 is the texture itself).")
        sides = []
        for name, side, value in (("the width of level k", W, w), ("the height of level k",
                                                                    H, h)):
            sides.append((name, value, [
                Mistake(side / 2 ** (k + 1), size, "off by one level"),
                Mistake(side / 2 ** (k - 1), size, "off by one level"),
                Mistake(side / 4 ** k, r"Each level halves each **side** (and so quarters "
                        r"the number of texels): $W / 2^k$, not $W / 4^k$.", "quartered")]))
        return [("the footprint rho", rho, footprint), ("the level lambda", lam, level)] + sides

    def statement(self):
        W, H = self.width, self.height
        return (
            rf"A ${W} \times {H}$ texture (width $W = {W}$, height $H = {H}$) is drawn on a "
            r"surface. Moving one pixel along the screen's $x$ changes the texture coordinates "
            rf"by $u_x = {_frac(self.du_dx)}$, $v_x = {_frac(self.dv_dx)}$; moving one pixel "
            rf"along $y$ by $u_y = {_frac(self.du_dy)}$, $v_y = {_frac(self.dv_dy)}$. Compute"
            "\n\n"
            r"1. the footprint $\rho$, the number of texels one pixel spans: "
            r"$\rho = \max\left(\sqrt{(W u_x)^2 + (H v_x)^2},\ \sqrt{(W u_y)^2 + (H v_y)^2}"
            r"\right)$;" "\n"
            r"2. the mipmap level $\lambda$ at which one texel is about one pixel;" "\n"
            rf"3. the width and the height of mipmap level $k = {self.k}$ (level 0 is the "
            r"texture itself)." "\n\n"
            r"**Answer:** a list of 4 numbers `[rho, lambda, width_k, height_k]`. " + DECIMALS
            + "\n\n" + data_note("width", "height", "du_dx", "dv_dx", "du_dy", "dv_dy", "k"))

    def _texel_steps(self):
        W, H = self.width, self.height
        x = (W * self.du_dx, H * self.dv_dx)
        y = (W * self.du_dy, H * self.dv_dy)
        return x, y, math.sqrt(x[0] ** 2 + x[1] ** 2), math.sqrt(y[0] ** 2 + y[1] ** 2)

    def hints(self):
        x, y, lx, ly = self._texel_steps()
        return [r"Count in texels: one pixel step along $x$ moves $(W u_x, H v_x)$ texels, one "
                r"along $y$ moves $(W u_y, H v_y)$. $\rho$ is the longer of the two steps, "
                r"$\lambda = \log_2 \rho$, and each mipmap level halves both sides.",
                rf"Here the steps are $({_num(x[0])}, {_num(x[1])})$ and "
                rf"$({_num(y[0])}, {_num(y[1])})$ texels.",
                rf"Their lengths are {_num(lx)} and {_num(ly)}; level $k = {self.k}$ of the "
                rf"texture is ${self.width}/2^{{{self.k}}} \times {self.height}/2^{{{self.k}}}$."]

    def worked(self):
        x, y, lx, ly = self._texel_steps()
        rho = max(lx, ly)
        lam = math.log(rho) / math.log(2)
        w, h = self.width // 2 ** self.k, self.height // 2 ** self.k
        W, H = self.width, self.height
        return Worked([
            rf"Along $x$: $(W u_x, H v_x) = ({W} \cdot {_signed(self.du_dx)},\ {H} \cdot "
            rf"{_signed(self.dv_dx)}) = ({_num(x[0])}, {_num(x[1])})$ texels, of length "
            rf"$\sqrt{{{_num(x[0] ** 2 + x[1] ** 2)}}} = {_num(lx)}$.",
            rf"Along $y$: $(W u_y, H v_y) = ({W} \cdot {_signed(self.du_dy)},\ {H} \cdot "
            rf"{_signed(self.dv_dy)}) = ({_num(y[0])}, {_num(y[1])})$ texels, of length "
            rf"$\sqrt{{{_num(y[0] ** 2 + y[1] ** 2)}}} = {_num(ly)}$.",
            rf"The footprint is the longer step: $\rho = \max({_num(lx)}, {_num(ly)}) = "
            rf"{_num(rho)}$.",
            rf"The level: $\lambda = \log_2 \rho = \ln {_num(rho)} / \ln 2 = {_n4(lam)}$.",
            rf"Level $k = {self.k}$: ${W}/2^{{{self.k}}} \times {H}/2^{{{self.k}}} = "
            rf"{w} \times {h}$.",
        ], [rho, lam, w, h])


def _board_coordinate(rng, squares):
    """A coordinate p in [-1, 1] whose s p has the fractional part 0.2, 0.4, 0.6 or 0.8."""
    whole = int(rng.integers(-squares, squares))
    return (whole + float(pick(rng, (0.2, 0.4, 0.6, 0.8)))) / squares


#: How many points the checkerboard is evaluated at.
_BOARD_POINTS = 6


class Checkerboard(_Chapter14):
    r"""A procedural checkerboard, :math:`T(P) = \left(\sum_k \lfloor s\, p_k \rfloor\right)
    \bmod 2`, at six points (2D texture coordinates or a 3D solid texture).

    The values are whole numbers, 0 or 1, compared exactly (``1.0`` is 1); a wrong value is
    named by its point.

    Attributes: ``squares`` (s), ``points`` (one point per row, 2 or 3 coordinates).

    Examples
    --------
    >>> ex = Checkerboard(seed=11)
    >>> ex.check(ex.expected).status, ex.check(ex.expected.astype(float)).status
    ('correct', 'correct')
    >>> ex.check(np.floor(ex.points).sum(axis=1) % 2).diagnosis
    'squares ignored'
    >>> flipped = ex.expected.copy()
    >>> flipped[0] = 1 - flipped[0]
    >>> ex.check(flipped).diagnosis
    'components differ'
    """

    title = "A checkerboard texture"
    answer_form = "vector"
    what = "the list of values"
    #: When every sum is 0 or 1 already, forgetting the modulo changes nothing.
    may_coincide = ("no modulo",)
    advice = (r"For each point: multiply each coordinate by $s$, round **down** "
              r"($\lfloor -0.4 \rfloor = -1$), add, and take the remainder modulo 2.")

    def draw(self, rng):
        self.squares = int(pick(rng, (2, 4, 8)))
        dim = int(pick(rng, (2, 3)))
        self.points = np.array([[_board_coordinate(rng, self.squares) for _ in range(dim)]
                                for _ in range(_BOARD_POINTS)])
        self.expected = np.round(texturing.checkerboard(self.points,
                                                        squares=self.squares)).astype(int)

    def acceptable(self):
        return 0 < self.expected.sum() < _BOARD_POINTS and np.any(self.points < 0)

    def mistakes(self):
        s, p = self.squares, self.points
        return [
            Mistake(np.round(s * p).sum(axis=1) % 2, r"You rounded to the nearest whole "
                    r"number. A square runs from one whole number to the next, so the square "
                    r"that contains $s\,p$ is $\lfloor s\,p \rfloor$: round **down**.",
                    "rounded"),
            Mistake(np.trunc(s * p).sum(axis=1) % 2, r"You truncated toward zero (as `int()` "
                    r"does). For negative coordinates that rounds **up** and merges the two "
                    r"squares next to 0 into one double-width square; use "
                    r"$\lfloor s\,p \rfloor$ (`np.floor`).", "truncated toward zero"),
            Mistake(np.floor(p).sum(axis=1) % 2, r"The scale $s$ is missing: with "
                    r"$\lfloor p \rfloor$ the squares are 1 unit wide. $s$ squares per unit "
                    r"means $\lfloor s\,p \rfloor$.", "squares ignored"),
            Mistake(np.floor(s * p).sum(axis=1), r"These are the sums "
                    r"$\sum_k \lfloor s\, p_k \rfloor$ themselves: the colour is their "
                    r"remainder **modulo 2** (0 for an even sum, 1 for an odd one, also for a "
                    r"negative sum: $-3 \bmod 2 = 1$).", "no modulo"),
        ]

    def _judge(self, answer):
        """Whole numbers are compared exactly; a wrong value is named by its point."""
        feedback = super()._judge(answer)
        if feedback.diagnosis not in ("off by one", "not whole"):
            return feedback
        value = np.ravel(np.asarray(answer, dtype=float))
        off = [int(k) for k in np.flatnonzero(value != self.expected)]
        if np.all(np.isin(value, (0, 1))):        # a colour off by one is the other colour
            return Feedback("wrong", f"The values at the points {off} (counted from 0) should "
                            "be the other colour.", "components differ")
        return Feedback("wrong", r"Each value is 0 or 1: the remainder modulo 2 of the whole "
                        r"number $\sum_k \lfloor s\, p_k \rfloor$ (nothing is averaged or "
                        f"interpolated). Check the points {off} (counted from 0).",
                        "not 0 or 1")

    def statement(self):
        dim = self.points.shape[1]
        kind = ("texture coordinates $(u, v)$" if dim == 2 else
                "points $(x, y, z)$ of a **solid** texture (the board is a 3D grid of cubes)")
        rows = "\n".join(rf"| {k} | ${_vec(p)}$ |" for k, p in enumerate(self.points))
        return (
            r"A procedural checkerboard with $s = " + str(self.squares) + r"$ squares per unit "
            r"length gives the point $P = (p_1, p_2, \dots)$ the value "
            r"$T(P) = \left(\sum_k \lfloor s\, p_k \rfloor\right) \bmod 2$ (0 or 1). Evaluate "
            rf"it at these {kind}:" "\n\n| point | coordinates |\n|---|---|\n" + rows + "\n\n"
            rf"**Answer:** a list of {_BOARD_POINTS} whole numbers, each 0 or 1, in the order "
            r"of the points." "\n\n" + data_note("squares", "points"))

    def hints(self):
        s = self.squares
        first = self.points[0]
        scaled = s * first
        floors = [math.floor(x) for x in scaled]
        return [r"For each point: scale each coordinate by $s$, round it **down** to the number "
                r"of its square, add those numbers, and keep the remainder modulo 2.",
                r"Round down also for negative numbers: $\lfloor -0.4 \rfloor = -1$, not 0 "
                r"(`int()` and rounding to the nearest are both wrong here).",
                rf"Point 0: $s\,p = {_vec(scaled)}$, rounded down "
                rf"${_vec(floors)}$, their sum ${sum(floors)}$, and ${sum(floors)} \bmod 2 = "
                rf"{sum(floors) % 2}$. The other points likewise."]

    def worked(self):
        s = self.squares
        steps, values = [], []
        for k, p in enumerate(self.points):
            floors = [math.floor(s * x) for x in p]
            total = sum(floors)
            values.append(total % 2)
            steps.append(rf"Point {k}: $s\,p = {_vec(s * p)}$, "
                         r"$\lfloor s\,p \rfloor = " + _vec(floors) + rf"$, sum ${total}$, "
                         rf"${total} \bmod 2 = {total % 2}$.")
        return Worked(steps, values)
