r"""Chapter 14 exercises: texture sampling, barycentric coordinates, mappings, mipmaps, exam style.

Each class is one kind of exam question: the nearest texel and a bilinear sample of a small
texture; the texel a repeating, clamping or mirroring texture uses for a coordinate outside
[0, 1]; the barycentric coordinates of a point, inside or outside its triangle, and a colour
interpolated with them; perspective-correct interpolation of texture coordinates; the
spherical, cylindrical and planar texture coordinates of a point; the texel footprint, the
mipmap level and the size of a level; and a checkerboard. The ``seed`` draws numbers that work
out by hand: 4 x 4 textures of small whole numbers, coordinates that are multiples of 0.05,
triangles with whole-number corners, points at whole-number distances from a centre.

The expected answers come from :mod:`course_lib.texturing`. Each exercise names the slips it
anticipates (the half-texel offset forgotten, rows and columns swapped, rows counted from the
top of the picture, unsigned areas, :math:`\tan^{-1}(x/z)` instead of
:math:`\operatorname{atan2}`, the course compendium's :math:`\sqrt{x^2 + y^2}`, linear instead
of perspective-correct interpolation, the wrong logarithm, ...), computes the answer each slip
would give, and draws its numbers again until those answers differ clearly from the right one
and from each other (:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.texturing`): texel ``(i, j)`` is row ``i``, column
``j`` of the array and covers :math:`u \in [j/W, (j+1)/W]`, :math:`v \in [i/H, (i+1)/H]`; its
centre is at :math:`((j + \tfrac12)/W, (i + \tfrac12)/H)`; row 0 is at :math:`v = 0`, the
*bottom* of the picture. The spherical map with the pole on :math:`y` is
:math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`, :math:`v = \tfrac12 + \arcsin(y/r)/\pi`
(the compendium's formulas corrected); barycentric coordinates are ratios of **signed** areas.
"""
import functools
import math

import numpy as np

from .. import format as fmt
from .. import texturing
from .core import (ATOL, DECIMALS, DrawnExercise, Feedback, Mistake, PartsAnswer, data_note,
                   hinted, latex_fraction, latex_vector, pick)

__all__ = [
    "EXERCISES",
    "BarycentricCoordinates",
    "BilinearSample",
    "Checkerboard",
    "CylindricalMap",
    "InterpolateColour",
    "MipLevel",
    "NearestSample",
    "PerspectiveCorrect",
    "PlanarMap",
    "SphericalMap",
    "WrapModes",
]

_num = fmt.number
_frac = functools.partial(latex_fraction, max_denominator=1024)
_vec = functools.partial(latex_vector, max_denominator=1024)

#: Diagnoses of the generic fallbacks in core (no anticipated mistake matched).
_GENERIC = {"components differ", "wrong length", "opposite sign", "value differs"}

#: Whole-number vectors of whole-number length: (x, y, z), |(x, y, z)|.
_INTEGER_VECTORS = (((0, 3, 4), 5), ((3, 0, 4), 5), ((0, 4, 3), 5), ((4, 0, 3), 5),
                    ((1, 2, 2), 3), ((2, 1, 2), 3), ((2, 2, 1), 3), ((2, 3, 6), 7),
                    ((3, 2, 6), 7), ((6, 2, 3), 7), ((2, 6, 3), 7), ((3, 6, 2), 7),
                    ((6, 3, 2), 7), ((2, 4, 4), 6), ((4, 4, 2), 6), ((4, 4, 7), 9),
                    ((1, 4, 8), 9), ((8, 4, 1), 9), ((4, 8, 1), 9))


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

def _floats_or_none(answer):
    try:
        return np.asarray(answer, dtype=float)
    except (TypeError, ValueError):
        return None


def _texture_table(T):
    """A texture as a Markdown table drawn like the picture: the top row (largest v) first."""
    h, w = T.shape
    header = "| | " + " | ".join(f"$j = {j}$" for j in range(w)) + " |"
    rule = "|---" * (w + 1) + "|"
    rows = []
    for i in range(h - 1, -1, -1):
        where = " (top)" if i == h - 1 else " (bottom)" if i == 0 else ""
        rows.append(f"| $i = {i}${where} | " + " | ".join(_num(x) for x in T[i]) + " |")
    return "\n".join([header, rule] + rows)


class _Chapter14(DrawnExercise):
    """The chapter's base: an answer that no anticipated slip explains gets ``hint``.

    Core's vector diagnosis reads a wrong answer of the right direction as "right direction,
    wrong length"; for texture coordinates and lists of values that means nothing, so it is
    replaced by the components that are off.
    """

    hint = ""

    def _check(self, answer):
        return hinted(self._judge(answer), self.hint, _GENERIC)

    def _judge(self, answer):
        feedback = super()._check(answer)
        if feedback.diagnosis == "wrong length":
            expected = np.ravel(self.expected)
            value = np.ravel(_floats_or_none(answer))
            off = [int(i) for i in np.flatnonzero(~np.isclose(value, expected, rtol=1e-3,
                                                                atol=ATOL))]
            feedback = Feedback("wrong", f"Components {off} (counted from 0) of {self.what} "
                                "are off.", "components differ")
        return feedback


class _Parts(PartsAnswer, _Chapter14):
    """An answer made of several numbers, each with slips of its own (see PartsAnswer)."""

    def _judge(self, answer):
        return self.judge_parts(answer)


_ONE_NUMBER = "**Answer:** one number. " + DECIMALS
_UV = "**Answer:** a list of 2 numbers `[u, v]`. " + DECIMALS
_TEXELS = (r"Texel $(i, j)$ (row $i$, column $j$) covers $u \in [j/W, (j+1)/W]$ and "
           r"$v \in [i/H, (i+1)/H]$; row 0 is at $v = 0$, the **bottom** of the picture.")


# ---------------------------------------------------------------------------------------------
# Sampling
# ---------------------------------------------------------------------------------------------

#: Coordinates whose u W (W = 4) is never a whole or a half number, and rounds to at most 3.
_NEAREST_UV = (0.05, 0.1, 0.15, 0.2, 0.3, 0.35, 0.4, 0.45, 0.55, 0.6, 0.65, 0.7, 0.8, 0.85)


class NearestSample(_Chapter14):
    r"""Nearest-texel lookup in a 4 x 4 texture: :math:`T[\lfloor vH \rfloor, \lfloor uW
    \rfloor]`.

    The texture's values are all different, so the value tells which texel was used.

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
    hint = (r"Column $j = \lfloor u W \rfloor$, row $i = \lfloor v H \rfloor$, and row 0 is "
            r"the bottom row of the picture.")

    def draw(self, rng):
        self.texture = rng.permutation(16).reshape(4, 4).astype(float)
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
    hint = (r"With $x = uW - \tfrac12$, $y = vH - \tfrac12$: $j = \lfloor x \rfloor$, "
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

    Attributes: ``width`` (W), ``u``.

    Examples
    --------
    >>> ex = WrapModes(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.u, ex.width, ex.expected
    (-0.85, 8, array([1., 0., 6.]))
    >>> ex.check([int(ex.u * ex.width) % ex.width, 0, 6]).diagnosis
    'truncated toward zero'
    """

    title = "Wrap modes: repeat, clamp, mirror"
    form_hint = "`[j_repeat, j_clamp, j_mirror]`, three whole numbers."
    hint = (r"Compute $uW$ and round it **down**; then wrap that index into $0, \dots, W - 1$ "
            r"the way each mode says.")

    def draw(self, rng):
        self.width = int(pick(rng, (4, 5, 8)))
        self.u = _outside_u(rng, self.width)
        row = np.arange(self.width, dtype=float)[None, :]
        self.expected = np.array([float(texturing.nearest_sample(row, self.u, 0.5, wrap=mode))
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


# ---------------------------------------------------------------------------------------------
# Barycentric coordinates and interpolation
# ---------------------------------------------------------------------------------------------

def _area(p, q, r):
    """The signed area of the triangle p, q, r (positive counter-clockwise)."""
    p, q, r = (np.asarray(x, dtype=float) for x in (p, q, r))
    return 0.5 * ((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
                  - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))


def _triangle(rng):
    """Three whole-number corners in [0, 6]^2 of a triangle of area at least 4."""
    while True:
        A, B, C = rng.integers(0, 7, size=(3, 2)).astype(float)
        if abs(_area(A, B, C)) >= 4:
            return A, B, C


_PERMUTATIONS = ((0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0))


class BarycentricCoordinates(_Chapter14):
    r"""Barycentric coordinates of a point by signed areas, inside or outside the triangle.

    :math:`\lambda_A = A(P, B, C)/A(A, B, C)`, :math:`\lambda_B = A(A, P, C)/A(A, B, C)`,
    :math:`\lambda_C = A(A, B, P)/A(A, B, C)`; outside the triangle one or two are negative.

    Attributes: ``A``, ``B``, ``C`` (the corners), ``P``.

    Examples
    --------
    >>> ex = BarycentricCoordinates(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'wrong vertex order'
    """

    title = "Barycentric coordinates"
    answer_form = "vector"
    what = "the list of coordinates"
    may_coincide = ("wrong vertex order", "unsigned areas")
    hint = (r"Each $\lambda$ is the signed area of the triangle in which $P$ replaces that "
            r"vertex, over the signed area of $ABC$; the three add up to 1, and "
            r"$\lambda_A A + \lambda_B B + \lambda_C C = P$.")

    def draw(self, rng):
        self.A, self.B, self.C = _triangle(rng)
        self.P = rng.integers(-1, 8, size=2).astype(float)
        self.expected = texturing.barycentric(self.P, self.A, self.B, self.C)

    def acceptable(self):
        return bool(np.all(np.abs(self.expected) > 0.05))

    def mistakes(self):
        A, B, C, P = self.A, self.B, self.C, self.P
        areas = np.array([_area(P, B, C), _area(A, P, C), _area(A, B, P)])
        total = _area(A, B, C)
        lam = self.expected
        order = (r"The weights are in the wrong order. The weight of a vertex is the area of "
                 r"the triangle **opposite** it, the one in which $P$ takes that vertex's "
                 r"place: $\lambda_A = A(P, B, C)/A(A, B, C)$ (it is 1 at $A$ itself).")
        found = [Mistake(lam[list(p)], order, "wrong vertex order") for p in _PERMUTATIONS]
        unsigned = (r"The areas must be **signed**. For a point outside the triangle the "
                    r"sub-triangle on the far side of an edge turns the other way round, and "
                    r"its negative area is what makes the weights add up to 1 and reproduce "
                    r"$P = \lambda_A A + \lambda_B B + \lambda_C C$ (a negative weight tells "
                    r"that $P$ lies beyond the opposite edge).")
        found += [Mistake(np.abs(areas) / abs(total), unsigned, "unsigned areas"),
                  Mistake(np.abs(areas) / np.abs(areas).sum(), unsigned, "unsigned areas")]
        divide = (r"These are the areas themselves: divide each by the area of the whole "
                  rf"triangle, $A(A, B, C) = {_num(total)}$, so that the weights add up to 1.")
        found += [Mistake(areas, divide, "not divided by the total area"),
                  Mistake(2 * areas, divide, "not divided by the total area")]
        return found

    def statement(self):
        return (
            rf"A triangle has the corners $A = {_vec(self.A)}$, $B = {_vec(self.B)}$, "
            rf"$C = {_vec(self.C)}$. Compute the barycentric coordinates "
            r"$(\lambda_A, \lambda_B, \lambda_C)$ of the point "
            rf"$P = {_vec(self.P)}$ from signed areas "
            r"($A(P, Q, R) = \tfrac12 [(Q - P) \times (R - P)]$, positive when $P, Q, R$ run "
            r"counter-clockwise). The point may lie outside the triangle." "\n\n"
            r"**Answer:** a list of 3 numbers `[lambda_A, lambda_B, lambda_C]`. " + DECIMALS
            + "\n\n" + data_note("A", "B", "C", "P"))


#: The whole-number points of [0, 6]^2.
_GRID = np.stack(np.meshgrid(np.arange(7.0), np.arange(7.0)), -1).reshape(-1, 2)
_CHANNELS = (0.0, 0.2, 0.4, 0.5, 0.6, 0.8, 1.0)


class InterpolateColour(_Chapter14):
    r"""A colour interpolated inside a triangle: :math:`c = \lambda_A c_A + \lambda_B c_B +
    \lambda_C c_C`.

    Attributes: ``A``, ``B``, ``C`` (corners), ``P`` (inside), ``colours`` (one RGB row per
    corner: A, B, C).

    Examples
    --------
    >>> ex = InterpolateColour(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.colours.mean(axis=0)).diagnosis
    'plain average'
    """

    title = "Interpolating a colour"
    answer_form = "vector"
    what = "the colour"
    may_coincide = ("wrong vertex order",)
    hint = (r"Compute the barycentric coordinates of $P$ (signed areas over the whole area), "
            r"then $c = \lambda_A c_A + \lambda_B c_B + \lambda_C c_C$, channel by channel.")

    def draw(self, rng):
        while True:                     # a triangle with whole-number points well inside
            self.A, self.B, self.C = _triangle(rng)
            total = _area(self.A, self.B, self.C)
            smallest = np.minimum.reduce([_area(_GRID, self.B, self.C),
                                          _area(self.A, _GRID, self.C),
                                          _area(self.A, self.B, _GRID)]) / total
            inside = _GRID[smallest > 0.05]
            if len(inside):
                break
        self.P = inside[int(rng.integers(len(inside)))]
        self.colours = rng.choice(_CHANNELS, size=(3, 3))
        self._weights = texturing.barycentric(self.P, self.A, self.B, self.C)
        self.expected = texturing.barycentric_interpolate(self.colours, self._weights)

    def acceptable(self):
        largest, second = np.sort(self._weights)[::-1][:2]
        return bool(np.all(self._weights > 0.05)) and largest - second > 0.05 \
            and len({tuple(c) for c in self.colours}) == 3

    def mistakes(self):
        A, B, C, P, lam, c = self.A, self.B, self.C, self.P, self._weights, self.colours
        areas = np.array([_area(P, B, C), _area(A, P, C), _area(A, B, P)])
        order = (r"The weights went to the wrong corners. The weight of a corner is the area of "
                 r"the triangle **opposite** it ($P$ in that corner's place): "
                 r"$\lambda_A = A(P, B, C)/A(A, B, C)$; it is 1 when $P$ is at $A$.")
        found = [Mistake(lam[list(p)] @ c, order, "wrong vertex order") for p in _PERMUTATIONS]
        found += [
            Mistake(c.mean(axis=0), r"That is the plain average of the three colours, the "
                    r"colour at the **centroid** only. Elsewhere each corner's colour counts "
                    r"with its barycentric weight.", "plain average"),
            Mistake(areas @ c, r"The weights must be divided by the area of the whole triangle "
                    rf"({_num(_area(A, B, C))}): then they add up to 1 and a grey stays grey.",
                    "not divided by the total area"),
            Mistake(c[int(np.argmax(lam))], r"That is the colour of the nearest corner (the "
                    r"one with the largest weight), as flat or nearest-neighbour shading would "
                    r"give. Interpolation blends all three colours.", "nearest corner"),
        ]
        return found

    def statement(self):
        rows = "\n".join(rf"| {name} | ${_vec(p)}$ | ${_vec(col)}$ |" for name, p, col in
                         zip("ABC", (self.A, self.B, self.C), self.colours))
        return (
            r"A triangle has a colour (red, green, blue) at each corner:" "\n\n"
            "| corner | position | colour |\n|---|---|---|\n" + rows + "\n\n"
            rf"Interpolate the colour at the point $P = {_vec(self.P)}$ inside the triangle "
            r"with barycentric coordinates (ratios of signed areas)." "\n\n"
            r"**Answer:** the colour as a list of 3 numbers `[r, g, b]`. " + DECIMALS + "\n\n"
            + data_note("A", "B", "C", "P", "colours") + " (`.colours[k]` is the colour of "
            "corner A, B, C for k = 0, 1, 2.)")


_SCREEN_WEIGHTS = ((0.5, 0.5, 0.0), (0.25, 0.25, 0.5), (0.5, 0.25, 0.25), (0.25, 0.5, 0.25),
                   (0.2, 0.3, 0.5), (0.6, 0.2, 0.2), (0.4, 0.4, 0.2), (0.5, 0.0, 0.5),
                   (0.0, 0.5, 0.5), (0.2, 0.4, 0.4))
_CORNERS = ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0))


class PerspectiveCorrect(_Chapter14):
    r"""Perspective-correct interpolation of texture coordinates:
    :math:`q = \frac{\sum \lambda_k q_k / w_k}{\sum \lambda_k / w_k}`.

    Attributes: ``weights`` (the screen-space barycentric weights of the pixel), ``w`` (the
    vertices' clip-space w), ``uv`` (one row of texture coordinates per vertex).

    Examples
    --------
    >>> ex = PerspectiveCorrect(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.weights @ ex.uv).diagnosis
    'linear in screen space'
    """

    title = "Perspective-correct texture coordinates"
    answer_form = "vector"
    what = "the texture coordinates"
    hint = (r"Interpolate $q/w$ and $1/w$ linearly with the screen weights and divide: "
            r"$q = \frac{\sum_k \lambda_k q_k / w_k}{\sum_k \lambda_k / w_k}$.")

    def draw(self, rng):
        self.weights = np.array(pick(rng, _SCREEN_WEIGHTS))
        self.w = rng.integers(1, 5, size=3).astype(float)
        self.uv = np.array([_CORNERS[k] for k in rng.choice(4, size=3, replace=False)])
        self.expected = texturing.perspective_interpolate(self.uv, self.weights, self.w)

    def acceptable(self):
        return len(set(self.w)) > 1

    def mistakes(self):
        lam, w, q = self.weights, self.w, self.uv
        return [
            Mistake(lam @ q, r"You interpolated linearly in screen space. The perspective "
                    r"divide squeezes the far part of the triangle, so equal steps on the "
                    r"screen are unequal steps on the triangle. What *is* linear on the screen "
                    r"is $q/w$ and $1/w$: interpolate both and divide, "
                    r"$q = \frac{\sum \lambda_k q_k/w_k}{\sum \lambda_k/w_k}$.",
                    "linear in screen space"),
            Mistake((lam * w) @ q / (lam @ w), r"You weighted by $w$ instead of $1/w$: a "
                    r"far vertex (large $w$) must count **less** on the screen, where it "
                    r"looks small. Use $\lambda_k / w_k$.", "multiplied by w"),
            Mistake((lam / w) @ q, r"The division by $\sum_k \lambda_k / w_k$ is missing: "
                    r"$\sum \lambda_k q_k / w_k$ is $q/w$ at the pixel, not $q$.",
                    "no division by the sum"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {k} | {_num(self.w[k])} | ${_vec(self.uv[k])}$ |"
                         for k in range(3))
        lam = self.weights
        return (
            r"A pixel lies inside a projected triangle; its screen-space barycentric "
            rf"coordinates are $(\lambda_0, \lambda_1, \lambda_2) = {_vec(lam)}$. The triangle's "
            r"vertices have these clip-space $w$ (for a perspective camera, the depth in front "
            r"of the eye) and texture coordinates:" "\n\n"
            "| vertex | $w$ | $(u, v)$ |\n|---|---|---|\n" + rows + "\n\n"
            r"Which texture coordinates $(u, v)$ does **perspective-correct** interpolation "
            r"give at the pixel?" "\n\n" + _UV + "\n\n" + data_note("weights", "w", "uv")
            + " (`.uv[k]` belongs to vertex k.)")


# ---------------------------------------------------------------------------------------------
# Mappings
# ---------------------------------------------------------------------------------------------

def _integer_vector(rng):
    v, length = pick(rng, _INTEGER_VECTORS)
    v = np.array(v, dtype=float)[rng.permutation(3)] * rng.choice([-1.0, 1.0], size=3)
    return v + 0.0, float(length)


def _azimuth(x, z):
    return 0.5 + math.atan2(x, z) / (2 * math.pi)


class SphericalMap(_Chapter14):
    r"""Spherical texture coordinates :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`,
    :math:`v = \tfrac12 + \arcsin(y/r)/\pi` of a point, relative to the sphere's centre.

    Attributes: ``center``, ``P``, ``radius``.

    Examples
    --------
    >>> ex = SphericalMap(seed=7)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'u and v swapped'
    """

    title = "Spherical mapping"
    answer_form = "vector"
    what = "the texture coordinates"
    may_coincide = ("atan instead of atan2",)
    hint = (r"With $d = P - C$ and $r = \lVert d \rVert$: "
            r"$u = \tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$, "
            r"$v = \tfrac12 + \arcsin(d_y/r)/\pi$ (angles in radians).")

    def draw(self, rng):
        self.center = (rng.integers(-2, 3, size=3).astype(float) if rng.random() < 0.6
                       else np.zeros(3))
        d, self.radius = _integer_vector(rng)
        self.P = self.center + d
        u, v = texturing.spherical_map(self.P, center=self.center)
        self.expected = np.array([float(u), float(v)])

    def acceptable(self):
        d = self.P - self.center
        return d[0] != 0 and d[1] != 0

    def mistakes(self):
        x, y, z = self.P - self.center
        r = self.radius
        theta, phi = math.atan2(x, z), math.asin(y / r)
        u, v = self.expected
        found = [
            Mistake([u, 0.5 + math.atan(y / math.hypot(x, y)) / math.pi], r"That is the "
                    r"course compendium's elevation, $\tan^{-1}(y/\sqrt{x^2 + y^2})$, which "
                    r"is wrong: the horizontal distance from the pole axis $y$ is "
                    r"$\sqrt{x^2 + z^2}$, so the elevation is $\arcsin(y/r) = "
                    r"\operatorname{atan2}(y, \sqrt{x^2 + z^2})$.", "compendium's elevation"),
            Mistake([v, u], r"$u$ and $v$ are swapped: $u$ is the **azimuth** around the pole "
                    r"axis $y$ (the longitude), $v$ the **elevation** (the latitude), from 0 "
                    r"at the south pole to 1 at the north pole.", "u and v swapped"),
            Mistake([theta, phi], r"These are the angles in radians. Texture coordinates are "
                    r"fractions of the full range: $u = \tfrac12 + \theta/2\pi$ (a full turn), "
                    r"$v = \tfrac12 + \varphi/\pi$ (pole to pole).", "angles, not (u, v)"),
            Mistake([theta / (2 * math.pi), phi / math.pi], r"The offset $\tfrac12$ is "
                    r"missing: the angles run over $(-\pi, \pi]$ and $[-\pi/2, \pi/2]$, and "
                    r"adding $\tfrac12$ after dividing brings them into $[0, 1]$.",
                    "no offset"),
        ]
        if z != 0:
            found.append(Mistake([0.5 + math.atan(x / z) / (2 * math.pi), v], r"You used "
                                 r"$\tan^{-1}(x/z)$, as the compendium writes. It cannot tell "
                                 r"$(x, z)$ from $(-x, -z)$ and only covers half the circle; "
                                 r"for $z < 0$ it lands on the wrong side. The two-argument "
                                 r"$\operatorname{atan2}(x, z)$ uses both signs.",
                                 "atan instead of atan2"))
        if np.any(self.center) and np.any(self.P):
            px, py, pz = self.P
            found.append(Mistake([_azimuth(px, pz), 0.5 + math.asin(py / np.linalg.norm(self.P))
                                  / math.pi], r"The centre was not subtracted: the angles are "
                                 r"measured from the sphere's centre, $d = P - C$.",
                                 "centre not subtracted"))
        return found

    def statement(self):
        return (
            rf"A sphere with centre $C = {_vec(self.center)}$ has the point "
            rf"$P = {_vec(self.P)}$ on its surface. Its texture is mapped with the pole on the "
            r"$y$ axis: for $d = P - C$ and $r = \lVert d \rVert$, the azimuth is measured in "
            r"the $xz$ plane from $+z$ towards $+x$, "
            r"$\theta = \operatorname{atan2}(d_x, d_z) \in (-\pi, \pi]$, and the elevation is "
            r"$\varphi = \arcsin(d_y / r) \in [-\pi/2, \pi/2]$; then "
            r"$u = \tfrac12 + \theta / 2\pi$ and $v = \tfrac12 + \varphi/\pi$. Compute the "
            r"texture coordinates of $P$." "\n\n" + _UV + "\n\n"
            + data_note("center", "P", "radius"))


class CylindricalMap(_Chapter14):
    r"""Cylindrical texture coordinates: :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`
    around the axis, :math:`v = y/h` along it, both relative to the base centre.

    Attributes: ``base`` (the centre of the cylinder's base), ``height``, ``P``.

    Examples
    --------
    >>> ex = CylindricalMap(seed=8)
    >>> ex.check(ex.expected).status
    'correct'
    >>> u, v = ex.expected
    >>> ex.check([u, v * ex.height]).diagnosis
    'v not divided by the height'
    """

    title = "Cylindrical mapping"
    answer_form = "vector"
    what = "the texture coordinates"
    may_coincide = ("atan instead of atan2",)
    hint = (r"With $d = P - C$: $u = \tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$ and "
            r"$v = d_y / h$.")

    def draw(self, rng):
        self.base = rng.integers(-2, 3, size=3).astype(float)
        self.height = float(pick(rng, (2, 4, 5, 8, 10)))
        x, z = (float(c) for c in rng.integers(-3, 4, size=2))
        y = float(rng.integers(1, 2 * self.height)) / 2
        self.P = self.base + np.array([x, y, z])
        u, v = texturing.cylindrical_map(self.P, center=self.base, height=self.height)
        self.expected = np.array([float(u), float(v)])

    def acceptable(self):
        x, _, z = self.P - self.base
        return x != 0 and z != 0

    def mistakes(self):
        x, y, z = self.P - self.base
        u, v = self.expected
        h = self.height
        found = [
            Mistake([_azimuth(z, x), v], r"You measured the angle from the $x$ axis, "
                    r"$\operatorname{atan2}(z, x)$. Here the azimuth starts at $+z$ "
                    r"($u = \tfrac12$) and turns towards $+x$: "
                    r"$\operatorname{atan2}(d_x, d_z)$.", "azimuth from the x axis"),
            Mistake([u, y], r"$v$ must be divided by the height of the cylinder: "
                    rf"$v = d_y / h$, so that the texture covers the cylinder once, from "
                    r"$v = 0$ at the base to $v = 1$ at the top.",
                    "v not divided by the height"),
            Mistake([v, u], r"$u$ and $v$ are swapped: $u$ goes **around** the axis, $v$ "
                    r"**along** it.", "u and v swapped"),
            Mistake([0.5 + math.atan(x / z) / (2 * math.pi), v], r"You used "
                    r"$\tan^{-1}(x/z)$: it only covers half the circle (it cannot tell "
                    r"$(x, z)$ from $(-x, -z)$). The two-argument "
                    r"$\operatorname{atan2}(x, z)$ uses both signs.", "atan instead of atan2"),
        ]
        if self.base[1] != 0:
            found.append(Mistake([u, self.P[1] / h], r"The height is measured from the "
                                 r"**base** of the cylinder: $v = (P_y - C_y)/h$.",
                                 "base not subtracted"))
        return found

    def statement(self):
        return (
            rf"A cylinder stands on the base centre $C = {_vec(self.base)}$ with its axis along "
            rf"$+y$ and the height $h = {_num(self.height)}$. Its texture is wrapped around it: "
            r"for $d = P - C$, $u = \tfrac12 + \operatorname{atan2}(d_x, d_z)/2\pi$ (the angle "
            r"around the axis, measured from $+z$ towards $+x$) and $v = d_y / h$ (the height "
            rf"along the axis). Compute the texture coordinates of $P = {_vec(self.P)}$." "\n\n"
            + _UV + "\n\n" + data_note("base", "height", "P"))


_AXIS_NAMES = {(1, 0, 0): "+x", (-1, 0, 0): "-x", (0, 1, 0): "+y", (0, -1, 0): "-y",
               (0, 0, 1): "+z", (0, 0, -1): "-z"}


class PlanarMap(_Chapter14):
    r"""Planar texture coordinates :math:`u = (P - O) \cdot e_u / s_u`,
    :math:`v = (P - O) \cdot e_v / s_v` with :math:`e_v = n \times e_u`.

    Attributes: ``origin``, ``normal``, ``u_axis``, ``size`` (:math:`(s_u, s_v)`), ``P``.

    Examples
    --------
    >>> ex = PlanarMap(seed=9)
    >>> ex.check(ex.expected).status
    'correct'
    >>> u, v = ex.expected
    >>> ex.check([u, -v]).diagnosis
    'v axis mirrored'
    """

    title = "Planar mapping"
    answer_form = "vector"
    what = "the texture coordinates"
    hint = (r"Subtract the origin, project onto $e_u$ and onto $e_v = n \times e_u$, divide by "
            r"the sizes.")

    def draw(self, rng):
        axes = np.eye(3)
        k, m = rng.choice(3, size=2, replace=False)
        self.normal = axes[k] * float(pick(rng, (-1, 1))) + 0.0
        self.u_axis = axes[m] * float(pick(rng, (-1, 1))) + 0.0
        self.origin = rng.integers(-2, 3, size=3).astype(float)
        self.size = np.array([float(pick(rng, (2, 4, 5))), float(pick(rng, (2, 4, 5)))])
        self.P = self.origin + rng.integers(-6, 7, size=3).astype(float)
        u, v = texturing.planar_map(self.P, origin=self.origin, normal=self.normal,
                                    u_axis=self.u_axis, size=self.size)
        self.expected = np.array([float(u), float(v)])

    def acceptable(self):
        return bool(np.all(np.abs(self.expected) > 0.05))

    def mistakes(self):
        d = self.P - self.origin
        e_v = np.cross(self.normal, self.u_axis)
        su, sv = self.size
        u, v = self.expected
        found = [
            Mistake([u, -v], r"The $v$ axis points the wrong way: $e_v = n \times e_u$ (in "
                    r"that order), so that $(e_u, e_v, n)$ is right-handed like "
                    r"$(x, y, z)$ and the texture is not mirrored seen from the side $n$ points "
                    r"to.", "v axis mirrored"),
            Mistake([d @ self.u_axis, d @ e_v], r"The sizes are missing: one copy of the "
                    r"texture covers $s_u \times s_v$ of the plane, so divide by $s_u$ and "
                    r"$s_v$.", "not divided by the size"),
            Mistake([self.P @ self.u_axis / su, self.P @ e_v / sv], r"The origin was not "
                    r"subtracted: $(u, v) = (0, 0)$ is at $O$, so measure $P - O$.",
                    "origin ignored"),
        ]
        if abs(self.normal[2]) != 1:
            found.append(Mistake([d[0] / su, d[1] / sv], r"You took the $x$ and $y$ "
                                 r"coordinates, as for a plane facing $z$. This plane faces "
                                 r"$n$: its texture axes are $e_u$ and $e_v = n \times e_u$.",
                                 "x and y taken"))
        return found

    def statement(self):
        n = _AXIS_NAMES[tuple(int(c) for c in self.normal)]
        eu = _AXIS_NAMES[tuple(int(c) for c in self.u_axis)]
        su, sv = self.size
        return (
            rf"A texture is projected onto the plane through $O = {_vec(self.origin)}$ with "
            rf"normal $n = {_vec(self.normal)}$ (pointing along ${n}$). The $u$ axis of the "
            rf"texture is $e_u = {_vec(self.u_axis)}$ (along ${eu}$), the $v$ axis is "
            r"$e_v = n \times e_u$, and one copy of the texture covers "
            rf"$s_u \times s_v = {_num(su)} \times {_num(sv)}$ of the plane, with its corner "
            r"$(u, v) = (0, 0)$ at $O$: $u = (P - O) \cdot e_u / s_u$, "
            r"$v = (P - O) \cdot e_v / s_v$. Compute the texture coordinates of "
            rf"$P = {_vec(self.P)}$." "\n\n" + _UV + "\n\n"
            + data_note("origin", "normal", "u_axis", "size", "P"))


# ---------------------------------------------------------------------------------------------
# Mipmaps and procedural textures
# ---------------------------------------------------------------------------------------------

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
    hint = (r"$\rho$ is the longer of the two screen steps measured in texels, "
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
    hint = (r"For each point: multiply each coordinate by $s$, round **down** "
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


#: The exercises of chapter 14, in the order of the solutions notebook.
EXERCISES = (
    NearestSample,
    BilinearSample,
    WrapModes,
    BarycentricCoordinates,
    InterpolateColour,
    PerspectiveCorrect,
    SphericalMap,
    CylindricalMap,
    PlanarMap,
    MipLevel,
    Checkerboard,
)
