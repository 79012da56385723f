"""Chapter 14 exercises: Sampling.

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import texturing
from ..core import Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _TEXELS, _Chapter14, _factor, _n4, _num, _Parts, _texture_table

__all__ = [
    "BilinearSample",
    "NearestSample",
    "WrapModes",
]


#: Coordinates whose u W (W = 4) is never a whole or a half number, and rounds to at most 3.
_NEAREST_UV = (0.05, 0.1, 0.15, 0.2, 0.3, 0.35, 0.4, 0.45, 0.55, 0.6, 0.65, 0.7, 0.8, 0.85)


class NearestSample(_Chapter14):
    r"""Nearest-texel lookup in a 4 x 4 texture: :math:`T[\lfloor vH \rfloor, \lfloor uW
    \rfloor]`.

    The texture's values are 16 different whole numbers below 100, so the value tells which
    texel was used.

    Attributes: ``texture`` (4 x 4, row 0 at v = 0), ``u``, ``v``.

    Examples
    --------
    >>> ex = NearestSample(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> i, j = int(ex.v * 4), int(ex.u * 4)
    >>> ex.check(ex.texture[3 - i, j]).diagnosis
    'rows counted from the top'
    >>> ex.check(ex.texture[j, i]).diagnosis
    'row and column swapped'
    """

    title = "The nearest texel"
    answer_form = "number"
    what = "the sampled value"
    advice = (r"Column $j = \lfloor u W \rfloor$, row $i = \lfloor v H \rfloor$, and row 0 is "
            r"the bottom row of the picture.")

    def draw(self, rng):
        self.texture = rng.choice(100, size=16, replace=False).reshape(4, 4).astype(float)
        self.u = float(pick(rng, _NEAREST_UV))
        self.v = float(pick(rng, _NEAREST_UV))
        self.expected = float(texturing.nearest_sample(self.texture, self.u, self.v))

    def mistakes(self):
        T, u, v = self.texture, self.u, self.v
        i, j = math.floor(v * 4), math.floor(u * 4)
        return [
            Mistake(T[round(v * 4), round(u * 4)], r"You rounded $uW$ and $vH$ to the nearest "
                    r"whole number. Texel $j$ covers $[j/W, (j+1)/W]$, so the texel that "
                    r"contains $u$ is $\lfloor uW \rfloor$: round **down**. (Rounding would be "
                    r"right for coordinates measured from texel centres, $uW - \tfrac12$.)",
                    "rounded"),
            Mistake(T[j, i], r"Row and column are swapped: $u$ runs along a row (it picks "
                    r"the **column** $j = \lfloor uW \rfloor$) and $v$ picks the **row** "
                    r"$i = \lfloor vH \rfloor$; the array is indexed `T[i, j]`.",
                    "row and column swapped"),
            Mistake(T[3 - i, j], r"You counted the rows from the top of the table. Row 0 is "
                    r"at $v = 0$, the **bottom** of the picture (as in OpenGL); the table shows "
                    r"the picture with its top row first, so row 0 is its last line.",
                    "rows counted from the top"),
        ]

    def statement(self):
        return (
            r"A $4 \times 4$ grey texture ($W = H = 4$) holds these values, drawn as the "
            r"picture looks (top row first):" "\n\n" + _texture_table(self.texture) + "\n\n"
            + _TEXELS + r" Which value does **nearest-texel** sampling return at "
            rf"$(u, v) = ({_num(self.u)}, {_num(self.v)})$?" "\n\n"
            r"**Answer:** one number, the texel's value. `.texture[i, j]` is texel $(i, j)$."
            "\n\n" + data_note("texture", "u", "v"))

    def hints(self):
        uw, vh = self.u * 4, self.v * 4
        j, i = math.floor(uw), math.floor(vh)
        return [r"Nearest-texel sampling returns the texel that **contains** $(u, v)$: column "
                r"$j = \lfloor uW \rfloor$, row $i = \lfloor vH \rfloor$ (round down).",
                rf"$uW = {_num(self.u)} \cdot 4 = {_num(uw)}$ and $vH = {_num(self.v)} \cdot 4 = "
                rf"{_num(vh)}$.",
                rf"So $j = {j}$ and $i = {i}$. Row 0 is the **bottom** row of the picture: row "
                rf"{i} is line {4 - i} of the table, counted from the top."]

    def worked(self):
        T = np.asarray(self.texture)
        uw, vh = self.u * T.shape[1], self.v * T.shape[0]
        j, i = math.floor(uw), math.floor(vh)
        value = float(T[i, j])
        return Worked([
            rf"Column: $uW = {_num(self.u)} \cdot {T.shape[1]} = {_num(uw)}$, so "
            rf"$j = \lfloor {_num(uw)} \rfloor = {j}$.",
            rf"Row: $vH = {_num(self.v)} \cdot {T.shape[0]} = {_num(vh)}$, so "
            rf"$i = \lfloor {_num(vh)} \rfloor = {i}$.",
            rf"Texel $(i, j) = ({i}, {j})$: row {i} from the bottom (line {T.shape[0] - i} of the "
            rf"table, which starts with the top row), column {j}: the value "
            rf"${_num(value)}$.",
        ], value)


#: Coordinates whose array position u W - 1/2 (W = 4) lies strictly inside [0, 3], off-centre.
_BILINEAR_UV = (0.2, 0.3, 0.35, 0.4, 0.45, 0.55, 0.6, 0.65, 0.7)


class BilinearSample(_Chapter14):
    r"""Bilinear filtering of a 4 x 4 texture at :math:`(u, v)`, with texel centres at
    :math:`((j + \tfrac12)/W, (i + \tfrac12)/H)`.

    :math:`x = uW - \tfrac12`, :math:`y = vH - \tfrac12`; blend the four texels around
    :math:`(x, y)` with the weights :math:`\alpha = x - \lfloor x \rfloor`,
    :math:`\beta = y - \lfloor y \rfloor`.

    Attributes: ``texture`` (4 x 4, row 0 at v = 0), ``u``, ``v``.

    Examples
    --------
    >>> ex = BilinearSample(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> from course_lib import texturing
    >>> ex.check(texturing.nearest_sample(ex.texture, ex.u, ex.v)).diagnosis
    'nearest'
    >>> ex.check(texturing.bilinear_sample(ex.texture, ex.u + 0.125, ex.v + 0.125)).diagnosis
    'no half-texel offset'
    """

    title = "A bilinear texture sample"
    answer_form = "number"
    what = "the sampled value"
    advice = (r"With $x = uW - \tfrac12$, $y = vH - \tfrac12$: $j = \lfloor x \rfloor$, "
            r"$i = \lfloor y \rfloor$, $\alpha = x - j$, $\beta = y - i$, then "
            r"$(1-\beta)[(1-\alpha)t_{i,j} + \alpha t_{i,j+1}] + "
            r"\beta[(1-\alpha)t_{i+1,j} + \alpha t_{i+1,j+1}]$.")

    def draw(self, rng):
        self.texture = rng.integers(0, 10, size=(4, 4)).astype(float)
        self.u = float(pick(rng, _BILINEAR_UV))
        self.v = float(pick(rng, _BILINEAR_UV))
        self.expected = float(texturing.bilinear_sample(self.texture, self.u, self.v))

    def mistakes(self):
        T, u, v = self.texture, self.u, self.v
        x, y = u * 4 - 0.5, v * 4 - 0.5
        j, i = math.floor(x), math.floor(y)
        a, b = x - j, y - i
        reversed_weights = ((b * ((a * T[i, j] + (1 - a) * T[i, j + 1])))
                            + (1 - b) * (a * T[i + 1, j] + (1 - a) * T[i + 1, j + 1]))
        return [
            Mistake(texturing.bilinear_sample(T, u + 0.125, v + 0.125), r"The half-texel "
                    r"offset is missing: you used $x = uW$, $y = vH$. Texel values sit at the "
                    r"texel **centres**, $((j + \tfrac12)/W, (i + \tfrac12)/H)$, so the "
                    r"position in texel units is $x = uW - \tfrac12$, $y = vH - \tfrac12$.",
                    "no half-texel offset"),
            Mistake(texturing.bilinear_sample(T.T, u, v), r"Rows and columns are swapped: "
                    r"$u$ moves along a row (through the columns $j$), $v$ through the rows "
                    r"$i$; texel $(i, j)$ is `T[i, j]`.", "u and v swapped"),
            Mistake(texturing.nearest_sample(T, u, v), r"That is the nearest texel. Bilinear "
                    r"filtering blends the **four** texels whose centres surround the point, "
                    r"weighted by how close it is to each.", "nearest"),
            Mistake(reversed_weights, r"The weights are reversed: the fraction "
                    r"$\alpha = x - j$ is how far the point has moved **towards** column "
                    r"$j + 1$, so $t_{i,j+1}$ gets $\alpha$ and $t_{i,j}$ gets $1 - \alpha$ "
                    r"(and likewise $\beta$ for the rows).", "weights reversed"),
            Mistake(texturing.bilinear_sample(T[::-1], u, v), r"You counted the rows from the "
                    r"top of the table. Row 0 is at $v = 0$, the **bottom** of the picture; the "
                    r"table shows the top row first.", "rows counted from the top"),
        ]

    def statement(self):
        return (
            r"A $4 \times 4$ grey texture ($W = H = 4$) holds these values, drawn as the "
            r"picture looks (top row first):" "\n\n" + _texture_table(self.texture) + "\n\n"
            + _TEXELS + r" Each texel's value belongs to its **centre**, "
            r"$((j + \tfrac12)/W, (i + \tfrac12)/H)$. Compute the **bilinearly** filtered "
            rf"value at $(u, v) = ({_num(self.u)}, {_num(self.v)})$." "\n\n" + _ONE_NUMBER
            + " `.texture[i, j]` is texel $(i, j)$.\n\n" + data_note("texture", "u", "v"))

    def _setup_numbers(self):
        """x, y, j, i, alpha, beta as a student finds them."""
        x, y = self.u * 4 - 0.5, self.v * 4 - 0.5
        j, i = math.floor(x), math.floor(y)
        return x, y, j, i, x - j, y - i

    def hints(self):
        x, y, j, i, a, b = self._setup_numbers()
        T = self.texture
        return [r"The values sit at the texel **centres**: go to texel units measured from the "
                r"centres, $x = uW - \tfrac12$, $y = vH - \tfrac12$, and blend the four texels "
                r"around $(x, y)$, first along a row, then between the rows.",
                rf"Here $x = {_num(x)}$ and $y = {_num(y)}$: columns $j = {j}, {j + 1}$ with "
                rf"the weight $\alpha = {_num(a)}$ towards column {j + 1}, rows "
                rf"$i = {i}, {i + 1}$ with $\beta = {_num(b)}$ towards row {i + 1}.",
                rf"The four texels: $t_{{{i},{j}}} = {_num(T[i, j])}$, "
                rf"$t_{{{i},{j + 1}}} = {_num(T[i, j + 1])}$, $t_{{{i + 1},{j}}} = "
                rf"{_num(T[i + 1, j])}$, $t_{{{i + 1},{j + 1}}} = {_num(T[i + 1, j + 1])}$ "
                r"(rows counted from the bottom)."]

    def worked(self):
        x, y, j, i, a, b = self._setup_numbers()
        T = np.asarray(self.texture, dtype=float)
        low = (1 - a) * T[i, j] + a * T[i, j + 1]
        high = (1 - a) * T[i + 1, j] + a * T[i + 1, j + 1]
        value = (1 - b) * low + b * high
        return Worked([
            rf"In texel units from the centres: $x = uW - \tfrac12 = {_num(self.u)} \cdot 4 - "
            rf"0.5 = {_num(x)}$, $y = vH - \tfrac12 = {_num(self.v)} \cdot 4 - 0.5 = "
            rf"{_num(y)}$.",
            rf"$j = \lfloor x \rfloor = {j}$, $\alpha = x - j = {_num(a)}$; "
            rf"$i = \lfloor y \rfloor = {i}$, $\beta = y - i = {_num(b)}$.",
            rf"Row {i}: $(1 - \alpha)\, t_{{{i},{j}}} + \alpha\, t_{{{i},{j + 1}}} = "
            rf"{_num(1 - a)} \cdot {_num(T[i, j])} + {_num(a)} \cdot {_num(T[i, j + 1])} = "
            rf"{_n4(low)}$.",
            rf"Row {i + 1}: $(1 - \alpha)\, t_{{{i + 1},{j}}} + \alpha\, t_{{{i + 1},{j + 1}}} = "
            rf"{_num(1 - a)} \cdot {_num(T[i + 1, j])} + {_num(a)} \cdot "
            rf"{_num(T[i + 1, j + 1])} = {_n4(high)}$.",
            rf"Between the rows: $(1 - \beta) \cdot {_n4(low)} + \beta \cdot {_n4(high)} = "
            rf"{_num(1 - b)} \cdot {_n4(low)} + {_num(b)} \cdot {_n4(high)} = {_n4(value)}$.",
        ], value)


def _outside_u(rng, width):
    """A u outside [0, 1], a multiple of 0.05, with u W and frac(u) W not whole numbers."""
    while True:
        u = float(pick(rng, (-1, 1))) * float(rng.integers(2, 59)) / 20
        if -2 < u < 0 or 1 < u < 3:
            frac = u - math.floor(u)
            if min(abs(x - round(x)) for x in (u * width, frac * width)) > 1e-6:
                return round(u, 2)


class WrapModes(_Parts):
    r"""The column a texture of width W uses for a u outside [0, 1], under each wrap mode.

    Repeat: :math:`j = \lfloor uW \rfloor \bmod W`; clamp: :math:`j` clamped to
    :math:`[0, W - 1]`; mirror: copy :math:`k = \lfloor u \rfloor`, the repeat column for even
    :math:`k`, mirrored (:math:`W - 1 - j`) for odd :math:`k`.

    The three columns are whole numbers, compared exactly (``3.0`` is the column 3, and a
    column one off is diagnosed as such).

    Attributes: ``width`` (W), ``u``.

    Examples
    --------
    >>> ex = WrapModes(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.u, ex.width, ex.expected
    (-0.85, 8, array([1, 0, 6]))
    >>> ex.check([int(ex.u * ex.width) % ex.width, 0, 6]).diagnosis
    'truncated toward zero'
    >>> ex.check([1.0, 0.0, 6.0]).status, ex.check([1, 1, 6]).diagnosis
    ('correct', 'off by one')
    """

    title = "Wrap modes: repeat, clamp, mirror"
    form_hint = "`[j_repeat, j_clamp, j_mirror]`, three whole numbers."
    advice = (r"Compute $uW$ and round it **down**; then wrap that index into $0, \dots, W - 1$ "
            r"the way each mode says.")

    def draw(self, rng):
        self.width = int(pick(rng, (4, 5, 6, 8, 10)))
        self.u = _outside_u(rng, self.width)
        row = np.arange(self.width, dtype=float)[None, :]
        self.expected = np.array([round(float(texturing.nearest_sample(row, self.u, 0.5,
                                                                       wrap=mode)))
                                  for mode in ("repeat", "clamp", "mirror")])

    def acceptable(self):
        return len(set(self.expected)) >= 2

    def parts(self):
        u, W = self.u, self.width
        repeat, clamp, mirror = self.expected
        rep = [Mistake(int(u * W) % W, r"You truncated $uW$ toward zero (as `int()` does). For "
                       r"a negative $u$ that rounds **up**; the texel that contains $u$ is "
                       r"$\lfloor uW \rfloor$ (e.g. $\lfloor -1.4 \rfloor = -2$), and only then "
                       r"is the index wrapped, $j \bmod W$ (which is never negative).",
                       "truncated toward zero"),
               Mistake(math.floor((abs(u) % 1) * W), r"You dropped the sign of $u$. Repeating "
                       r"keeps the fractional part $u - \lfloor u \rfloor$, which for "
                       r"$u = -0.3$ is $0.7$, not $0.3$: the texture continues to the left with "
                       r"its **right** end.", "sign dropped")]
        cla = []
        if u > 1:
            cla.append(Mistake(W, r"Clamping applies to the texel **index**: $u > 1$ gives "
                               r"the last column, $W - 1$ (and $u < 0$ the first, 0). Clamping "
                               r"$u$ to $[0, 1]$ and then taking $\lfloor uW \rfloor$ gives $W$ "
                               r"at $u = 1$, one past the edge.", "one past the edge"))
        copy = math.floor(u)
        wrong_copy = W - 1 - repeat if copy % 2 == 0 else repeat
        mir = [Mistake(wrong_copy, r"The wrong copies are mirrored. Copy "
                       r"$k = \lfloor u \rfloor$ of the texture is mirrored when $k$ is "
                       rf"**odd**; here $k = {copy}$, so the column is "
                       + ("the repeat column" if copy % 2 == 0 else r"$W - 1 - j$") + ".",
                       "wrong copies mirrored")]
        if copy % 2:
            mir.append(Mistake(W - repeat, r"Off by one in the mirror image: the columns "
                               r"$0, \dots, W - 1$ reversed are $W - 1 - j$, not $W - j$.",
                               "mirrored off by one"))
        return [("the repeat column", repeat, rep), ("the clamp column", clamp, cla),
                ("the mirror column", mirror, mir)]

    def statement(self):
        W = self.width
        return (
            rf"A texture is $W = {W}$ texels wide; column $j$ covers $u \in [j/W, (j+1)/W]$. "
            rf"Nearest-texel sampling at $u = {_num(self.u)}$ (outside $[0, 1]$) first takes "
            r"$\lfloor uW \rfloor$ and then brings the index into $0, \dots, W - 1$ by the "
            r"texture's wrap mode:" "\n\n"
            r"- **repeat** (`GL_REPEAT`): the texture is tiled; the index is taken modulo $W$."
            "\n"
            r"- **clamp** (`GL_CLAMP_TO_EDGE`): indices beyond the edge use the edge texel."
            "\n"
            r"- **mirror** (`GL_MIRRORED_REPEAT`): the texture is tiled with every other copy "
            r"mirrored; copy $k = \lfloor u \rfloor$ is mirrored when $k$ is odd, copy 0 "
            r"is the texture itself." "\n\n"
            r"Which column $j$ does each mode use?" "\n\n"
            r"**Answer:** a list of 3 whole numbers `[j_repeat, j_clamp, j_mirror]`." "\n\n"
            + data_note("width", "u"))

    def _steps(self):
        """j0 = floor(u W), the copy k = floor(u), and the three columns."""
        W = self.width
        j0 = math.floor(self.u * W)
        repeat = j0 - W * math.floor(j0 / W)
        clamp = min(max(j0, 0), W - 1)
        copy = math.floor(self.u)
        mirror = W - 1 - repeat if copy % 2 else repeat
        return j0, copy, repeat, clamp, mirror

    def hints(self):
        j0, copy, repeat, _, _ = self._steps()
        W = self.width
        parity = "odd: this copy is mirrored" if copy % 2 else "even: this copy is not mirrored"
        return [r"First find the texel index the coordinate falls in, "
                r"$j_0 = \lfloor uW \rfloor$ (round **down**, also for a negative $u$); then "
                r"each mode brings $j_0$ into $0, \dots, W - 1$ in its own way.",
                rf"$uW = {_num(self.u)} \cdot {W} = {_num(self.u * W)}$, so "
                rf"$j_0 = {j0}$.",
                rf"Repeat: ${j0} \bmod {W} = {repeat}$ (the remainder is never negative). "
                rf"Mirror: copy $k = \lfloor u \rfloor = {copy}$ is {parity}."]

    def worked(self):
        j0, copy, repeat, clamp, mirror = self._steps()
        W = self.width
        if copy % 2:
            mirrored = (rf"$k = {copy}$ is odd, so this copy is mirrored: "
                        rf"$W - 1 - {repeat} = {mirror}$.")
        else:
            mirrored = (rf"$k = {copy}$ is even, so this copy is not mirrored: the repeat "
                        rf"column, {mirror}.")
        edge = "0 (the first column)" if j0 < 0 else f"{W - 1} (the last column)"
        return Worked([
            rf"The texel index: $uW = {_num(self.u)} \cdot {W} = {_num(self.u * W)}$, "
            rf"$j_0 = \lfloor {_num(self.u * W)} \rfloor = {j0}$.",
            rf"Repeat: $j_0 \bmod W = {j0} - {W} \cdot {_factor(math.floor(j0 / W), 0)} = "
            rf"{repeat}$ (subtract the multiple of $W$ that leaves a remainder in "
            rf"$0, \dots, {W - 1}$).",
            rf"Clamp: $j_0 = {j0}$ lies beyond the edge, so the edge texel is used: {edge}.",
            rf"Mirror: the copy is $k = \lfloor u \rfloor = {copy}$. " + mirrored,
        ], [repeat, clamp, mirror])
