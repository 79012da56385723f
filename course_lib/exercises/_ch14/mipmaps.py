"""Chapter 14 exercises: Mipmaps and procedural textures.

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import functools
import math

import numpy as np

from ... import texturing
from ..core import DECIMALS, Mistake, data_note, latex_fraction, pick
from . import _Chapter14, _Parts, _vec

__all__ = [
    "Checkerboard",
    "MipLevel",
]


_frac = functools.partial(latex_fraction, max_denominator=1024)


_TRIPLES = ((3, 4, 5), (4, 3, 5), (6, 8, 10), (8, 6, 10), (5, 12, 13), (12, 5, 13), (0, 4, 4),
            (6, 0, 6), (0, 8, 8), (8, 15, 17), (15, 8, 17), (2, 0, 2), (0, 3, 3))


class MipLevel(_Parts):
    r"""The texel footprint :math:`\rho`, the mipmap level :math:`\lambda = \log_2 \rho`, and
    the size of level :math:`k`.

    :math:`\rho = \max\left(\sqrt{(W u_x)^2 + (H v_x)^2}, \sqrt{(W u_y)^2 + (H v_y)^2}\right)`
    from the derivatives of the texture coordinates along the screen's x and y; level
    :math:`k` of a :math:`W \times H` texture is :math:`W/2^k \times H/2^k`.

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


def _board_coordinate(rng, squares):
    """A coordinate p in [-1, 1] whose s p has the fractional part 0.2, 0.4, 0.6 or 0.8."""
    whole = int(rng.integers(-squares, squares))
    return (whole + float(pick(rng, (0.2, 0.4, 0.6, 0.8)))) / squares


class Checkerboard(_Chapter14):
    r"""A procedural checkerboard, :math:`T(P) = \left(\sum_k \lfloor s\, p_k \rfloor\right)
    \bmod 2`, at four points (2D texture coordinates or a 3D solid texture).

    Attributes: ``squares`` (s), ``points`` (one point per row, 2 or 3 coordinates).

    Examples
    --------
    >>> ex = Checkerboard(seed=11)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(np.floor(ex.points).sum(axis=1) % 2).diagnosis
    'squares ignored'
    """

    title = "A checkerboard texture"
    answer_form = "vector"
    what = "the list of values"
    advice = (r"For each point: multiply each coordinate by $s$, round **down** "
            r"($\lfloor -0.4 \rfloor = -1$), add, and take the remainder modulo 2.")

    def draw(self, rng):
        self.squares = int(pick(rng, (2, 4, 8)))
        dim = int(pick(rng, (2, 3)))
        self.points = np.array([[_board_coordinate(rng, self.squares) for _ in range(dim)]
                                for _ in range(4)])
        self.expected = texturing.checkerboard(self.points, squares=self.squares)

    def acceptable(self):
        return 0 < self.expected.sum() < 4 and np.any(self.points < 0)

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
        ]

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
            r"**Answer:** a list of 4 numbers, each 0 or 1, in the order of the points." "\n\n"
            + data_note("squares", "points"))
