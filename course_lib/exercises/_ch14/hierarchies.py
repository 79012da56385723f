"""Chapter 14 exercises: texture hierarchies (what a mip pyramid and a clipmap cost).

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here. The level
of a pixel from the screen-space derivatives of (u, v) is asked by
:class:`~course_lib.exercises._ch14.mipmaps.MipLevel` already.
"""

from ... import texturing
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _num, _Parts

__all__ = [
    "ClipmapMemory",
    "PyramidMemory",
]

_MIB = 2 ** 20


def _int(x):
    """A whole number with thin spaces between thousands, for LaTeX."""
    return f"{int(x):,}".replace(",", r"\,")


class PyramidMemory(_Parts):
    r"""The bytes of the full mip chain of a :math:`W \times H` RGBA8 texture, exact and by the
    :math:`\tfrac43` bound.

    Exactly: the sum of :math:`4 \cdot w_l h_l` bytes over the levels down to 1 x 1 (a whole
    number, compared exactly); the bound: :math:`\tfrac43 \cdot 4 W H` (the geometric series
    :math:`1 + \tfrac14 + \tfrac1{16} + \dots`).

    Attributes: ``width``, ``height`` (W, H, powers of two).

    Examples
    --------
    >>> ex = PyramidMemory(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> exact, bound = ex.expected
    >>> ex.check([exact - 4, bound]).diagnosis
    'forgot the 1x1 level'
    >>> ex.check([exact, 2 * 4 * ex.width * ex.height]).diagnosis
    'halves instead of quarters'
    """

    title = "The memory of a mip pyramid"
    form_hint = "`[exact_bytes, bound_bytes]`."
    advice = (r"Each level has half the width and half the height, so a **quarter** of the "
              r"texels; sum $4 w_l h_l$ bytes over every level down to and including $1 \times 1$ "
              r"for the exact count, and $\tfrac43 \cdot 4 W H$ for the bound.")

    def draw(self, rng):
        self.width = int(pick(rng, (64, 128, 256, 512, 1024, 2048)))
        self.height = int(pick(rng, (self.width, self.width // 2, self.width // 4)))
        m = texturing.pyramid_memory((self.height, self.width), channels=4)
        self._memory = m
        self.expected = [m.total, float(m.bound)]

    def parts(self):
        m = self._memory
        W, H = self.width, self.height
        base = 4 * W * H
        n_levels = len(m.shapes)
        halves = 4 * sum(W * H / 2 ** k for k in range(n_levels))
        exact = [
            Mistake(m.total - 4, r"The chain ends with the $1 \times 1$ level (4 bytes), "
                    r"and you left it out: count every level down to and including $1 \times 1$.",
                    "forgot the 1x1 level"),
            Mistake(base, r"That is level 0 alone. The pyramid adds every halved level: "
                    r"$W/2 \times H/2$, $W/4 \times H/4$, ... down to $1 \times 1$.",
                    "base only"),
            Mistake(halves, r"Halving both sides **quarters** the texels, so each level has "
                    r"$\tfrac14$ of the one before, not $\tfrac12$.",
                    "halves instead of quarters"),
            Mistake(m.total // 4, r"That is the number of texels. Each RGBA8 texel takes 4 "
                    r"bytes (4 channels of 1 byte).", "texels, not bytes"),
        ]
        bound = [
            Mistake(2.0 * base, r"$1 + \tfrac12 + \tfrac14 + \dots = 2$ is the series of a 1D "
                    r"texture. In 2D each level has a **quarter** of the texels: "
                    r"$1 + \tfrac14 + \tfrac1{16} + \dots = \tfrac43$.",
                    "halves instead of quarters"),
            Mistake(float(base), r"That is level 0 alone; the bound is $\tfrac43$ of it.",
                    "base only"),
            Mistake(base * 8 / 7, r"$\tfrac87$ is the bound of a **volume** (3D) texture, "
                    r"whose levels have an eighth of the texels. In 2D it is $\tfrac43$.",
                    "the 3D bound"),
            Mistake(W * H * 4 / 3, r"That counts texels; multiply by the 4 bytes of an RGBA8 "
                    r"texel.", "texels, not bytes"),
        ]
        return [("the exact bytes", m.total, exact), ("the bound", float(m.bound), bound)]

    def statement(self):
        W, H = self.width, self.height
        return (
            rf"A ${W} \times {H}$ texture in RGBA8 (4 channels of 1 byte) gets its full "
            r"mipmap chain (each level halves both sides, with the floor rule, down to "
            r"$1 \times 1$). Compute" "\n\n"
            r"1. the exact number of bytes of the whole pyramid (level 0 included);" "\n"
            r"2. the upper estimate from the geometric series, $\tfrac43$ of level 0's bytes."
            "\n\n" r"**Answer:** a list of 2 numbers `[exact_bytes, bound_bytes]` (the first "
            r"a whole number). " + DECIMALS + "\n\n" + data_note("width", "height"))

    def hints(self):
        W, H = self.width, self.height
        return [r"List the levels: $W \times H$, $W/2 \times H/2$, ... Once one side reaches 1 "
                r"it stays 1 and only the other halves, down to $1 \times 1$.",
                rf"Level 0 has ${_int(W * H)}$ texels, ${_int(4 * W * H)}$ bytes; each next "
                r"level has a quarter of the texels (until a side is 1).",
                r"The bound: $4WH (1 + \tfrac14 + \tfrac1{16} + \dots) = \tfrac43 \cdot 4WH$."]

    def worked(self):
        m = self._memory
        sizes = ", ".join(rf"{w} \times {h}" for h, w in m.shapes)
        texels = " + ".join(_int(b // 4) for b in m.level_bytes)
        return Worked([
            rf"The levels: ${sizes}$ ({len(m.shapes)} levels).",
            rf"Texels: ${texels} = {_int(m.total // 4)}$.",
            rf"Bytes: $4 \cdot {_int(m.total // 4)} = {_int(m.total)}$.",
            rf"The bound: $\tfrac43 \cdot 4 \cdot {self.width} \cdot {self.height} = "
            rf"\tfrac43 \cdot {_int(m.base)} = {_num(m.bound)}$"
            + (r" (the exact count is just below it)." if m.total < m.bound else
               r" (the exact count is a few bytes above it: once the short side is 1 the "
               r"last levels only halve).")
        ], [m.total, float(m.bound)])


class ClipmapMemory(_Parts):
    r"""Which levels of a clipmap are clipped, its memory and the full pyramid's.

    A :math:`2^n \times 2^n` RGBA8 texture with clip size :math:`c = 2^m`: the levels wider
    than :math:`c` (there are :math:`n - m`) keep a :math:`c \times c` window each, the rest
    (side :math:`c` and smaller) are kept whole. Memory in MiB (:math:`2^{20}` bytes).

    Attributes: ``size`` (the texture's side :math:`2^n`), ``clip`` (c).

    Examples
    --------
    >>> ex = ClipmapMemory(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> count, clip_mib, full_mib = ex.expected
    >>> ex.check([count + 1, clip_mib, full_mib]).diagnosis
    'the level of side c counted as clipped'
    >>> ex.check([count, full_mib, full_mib]).diagnosis
    'no clipping'
    """

    title = "The memory of a clipmap"
    form_hint = "`[clipped_levels, clipmap_MiB, full_MiB]`."
    advice = (r"Levels wider than $c$ keep $c^2$ texels each; the levels of side $c$ and below "
              r"are whole (together about $\tfrac43 c^2$); 4 bytes per texel, $2^{20}$ bytes "
              r"per MiB. The full pyramid is about $\tfrac43$ of level 0.")

    def draw(self, rng):
        self.size = int(pick(rng, (2048, 4096, 8192, 16384, 32768, 65536, 131072)))
        self.clip = int(pick(rng, (128, 256, 512, 1024)))
        layout = texturing.clipmap((self.size, self.size), self.clip)
        self._layout = layout
        self.expected = [int(layout.clipped.sum()), 4 * layout.resident_texels / _MIB,
                         4 * layout.full_texels / _MIB]

    def acceptable(self):
        return self.size // self.clip >= 8

    def parts(self):
        count, clip_mib, full_mib = self.expected
        c, N = self.clip, self.size
        window = 4 * c * c / _MIB
        levels = [
            Mistake(count + 1, r"The level of side exactly $c$ fits in its window: it is kept "
                    r"whole, not clipped. Only the levels **wider** than $c$ are clipped.",
                    "the level of side c counted as clipped"),
            Mistake(len(self._layout.shapes), r"Only the levels wider than the clip size are "
                    r"clipped; the small ones (side $c$ and below) are kept whole.",
                    "every level"),
        ]
        memory = [
            Mistake(count * window, r"The whole levels (side $c$ and smaller) are resident "
                    r"too: add their $c^2 + c^2/4 + \dots \approx \tfrac43 c^2$ texels.",
                    "tail forgotten"),
            Mistake(full_mib, r"That is the full pyramid: a clipmap keeps only a "
                    r"$c \times c$ window of every level wider than $c$.", "no clipping"),
            Mistake((count + 1) * window, r"The levels of side $c$ and below together hold "
                    r"$\tfrac43 c^2$ texels, not $c^2$: add the smaller levels too.",
                    "tail as one window"),
        ]
        full = [
            Mistake(4 * N * N / _MIB, r"That is level 0 alone; the pyramid is $\tfrac43$ of it.",
                    "base only"),
            Mistake(8 * N * N / _MIB, r"Each level has a **quarter** of the texels of the one "
                    r"before, so the pyramid is $\tfrac43$ of level 0, not twice.",
                    "halves instead of quarters"),
        ]
        return [("the number of clipped levels", count, levels),
                ("the clipmap's memory", clip_mib, memory),
                ("the full pyramid's memory", full_mib, full)]

    def statement(self):
        N, c = self.size, self.clip
        return (
            rf"A ${N} \times {N}$ RGBA8 texture (4 bytes per texel) is served by a clipmap with "
            rf"clip size $c = {c}$: every mipmap level keeps at most a ${c} \times {c}$ window "
            r"of texels around the viewer; smaller levels are kept whole. Compute" "\n\n"
            r"1. how many levels are clipped (only a window resident);" "\n"
            r"2. the clipmap's memory in MiB ($1\ \text{MiB} = 2^{20}$ bytes);" "\n"
            r"3. the memory of the full mip pyramid in MiB." "\n\n"
            r"**Answer:** a list of 3 numbers `[clipped_levels, clipmap_MiB, full_MiB]`. "
            + DECIMALS + "\n\n" + data_note("size", "clip"))

    def hints(self):
        N, c = self.size, self.clip
        return [rf"The levels have sides ${N}, {N // 2}, \dots, 1$; those wider than ${c}$ are "
                r"clipped.",
                rf"A clipped level holds ${c}^2$ texels, ${_num(4 * c * c / _MIB)}$ MiB; the "
                rf"whole levels ${c}^2 + ({c // 2})^2 + \dots + 1^2$ texels.",
                r"The full pyramid: $\tfrac{4^{n+1} - 1}{3}$ texels for a $2^n \times 2^n$ "
                r"texture."]

    def worked(self):
        N, c = self.size, self.clip
        count, clip_mib, full_mib = self.expected
        lay = self._layout
        tail = lay.resident_texels - count * c * c
        return Worked([
            rf"Levels wider than ${c}$: ${N}, \dots, {2 * c}$, that is {count} levels.",
            rf"They hold ${count} \cdot {c}^2 = {_int(count * c * c)}$ texels; the whole levels "
            rf"(${c}$ down to 1) ${_int(tail)}$ texels.",
            rf"Clipmap: $4 \cdot {_int(lay.resident_texels)} / 2^{{20}} = {_num(clip_mib)}$ MiB.",
            rf"Full pyramid: $4 \cdot {_int(lay.full_texels)} / 2^{{20}} = {_num(full_mib)}$ "
            rf"MiB, {_num(full_mib / clip_mib)} times as much.",
        ], [count, clip_mib, full_mib])
