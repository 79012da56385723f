"""Chapter 10 exercises: normalisation.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import numpy as np

from ... import colormaps as cm
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _Chapter10, _num, _paren, _values_words

__all__ = [
    "Denormalize",
    "NormalizeValues",
]


# ---------------------------------------------------------------------------------------------
# Normalisation
# ---------------------------------------------------------------------------------------------

_IN_RANGES = ((0, 200), (20, 60), (-10, 30), (100, 300), (-40, 40), (10, 90), (50, 250))
_OUT_RANGES = ((0, 255), (0, 1), (-1, 1), (0, 100), (10, 20), (1, 5), (-50, 50))

_FORMULA = r"$n(v) = \dfrac{v - a}{b - a}\,(d - c) + c$"


class NormalizeValues(_Chapter10):
    r"""Normalise a few data values from the range [a, b] onto the range [c, d].

    .. math:: n(v) = \frac{v - a}{b - a}\,(d - c) + c

    Attributes: ``values``, ``in_range`` (a, b), ``out_range`` (c, d).

    Examples
    --------
    >>> ex = NormalizeValues(seed=1)
    >>> (a, b), (c, d) = ex.in_range, ex.out_range
    >>> ex.check((ex.values - a) / (b - a) * (d - c) + c).status
    'correct'
    >>> ex.check(cm.normalize(ex.values, out_range=ex.out_range)).diagnosis
    'data range'
    >>> ex.check(...).status, ex.check("0.5").status
    ('unanswered', 'invalid')
    """

    title = "Normalise data to a new range"
    answer_form = "vector"
    what = "the list of normalised values"
    may_coincide = ("no offset", "unit interval", "no shift")
    advice = (r"Go step by step for each value: subtract $a$, divide by $b - a$ (now it is in "
            r"$[0, 1]$), multiply by $d - c$, add $c$.")

    def draw(self, rng):
        a, b = pick(rng, _IN_RANGES)
        c, d = pick(rng, _OUT_RANGES)
        self.in_range, self.out_range = (float(a), float(b)), (float(c), float(d))
        k = rng.choice(np.arange(1, 8), size=4, replace=False)
        self.values = np.sort(a + (b - a) * k / 8.0)
        self.expected = cm.normalize(self.values, self.in_range, self.out_range)

    def mistakes(self):
        (a, b), (c, d), v = self.in_range, self.out_range, self.values
        t = (v - a) / (b - a)
        return [
            Mistake(t * (d - c), r"You forgot to add $c$ at the end: your values run from 0 to "
                    r"$d - c$ instead of from $c$ to $d$. After stretching by $d - c$, shift by "
                    r"$c$.", "no offset"),
            Mistake(t, r"You stopped at $[0, 1]$: $\frac{v - a}{b - a}$ is only the first half "
                    r"of the job. Stretch it by $d - c$ and add $c$ to land on $[c, d]$.",
                    "unit interval"),
            Mistake((v - a) / b * (d - c) + c, r"You divided by $b$ instead of by the width of "
                    r"the data range, $b - a$: then $v = b$ does not map to $d$.", "divided by b"),
            Mistake(v / (b - a) * (d - c) + c, r"You forgot to subtract $a$ first: the smallest "
                    r"value $a$ must map to $c$, so the formula starts with $v - a$.",
                    "no shift"),
            Mistake(cm.normalize(v, None, self.out_range), r"You took the range from the four "
                    r"values themselves (their minimum and maximum). The question gives the data "
                    r"range $[a, b]$: use it, so that values from different data sets with the "
                    r"same range are comparable.", "data range"),
            Mistake((v - c) / (d - c) * (b - a) + a, r"You swapped the two ranges: you mapped "
                    r"$[c, d]$ onto $[a, b]$. The data live in $[a, b]$; subtract $a$ and divide "
                    r"by $b - a$.", "ranges swapped"),
        ]

    def hints(self):
        (a, b), (c, d), v = self.in_range, self.out_range, self.values
        scale = (d - c) / (b - a)
        t0 = (v[0] - a) / (b - a)
        return [
            r"Map in two stages: first onto $[0, 1]$ with $\frac{v - a}{b - a}$, then onto "
            r"$[c, d]$: stretch by $d - c$ and shift by $c$.",
            rf"Here $b - a = {_num(b - a)}$ and $d - c = {_num(d - c)}$, so each value becomes "
            rf"$(v - {_paren(a)}) \cdot \frac{{{_num(d - c)}}}{{{_num(b - a)}}} + {_paren(c)}$, "
            rf"a factor of ${_num(scale, 4)}$.",
            rf"The first value: $\frac{{{_num(v[0])} - {_paren(a)}}}{{{_num(b - a)}}} = "
            rf"{_num(t0, 4)}$, then ${_num(t0, 4)} \cdot {_num(d - c)} + {_paren(c)} = "
            rf"{_num(t0 * (d - c) + c, 4)}$.",
        ]

    def worked(self):
        (a, b), (c, d), v = self.in_range, self.out_range, self.values
        steps = [rf"The widths: $b - a = {_num(b)} - {_paren(a)} = {_num(b - a)}$ and "
                 rf"$d - c = {_num(d)} - {_paren(c)} = {_num(d - c)}$."]
        out = []
        for x in v:
            t = (x - a) / (b - a)
            out.append(t * (d - c) + c)
            steps.append(rf"$v = {_num(x)}$: $\frac{{{_num(x)} - {_paren(a)}}}{{{_num(b - a)}}} "
                         rf"= {_num(t, 4)}$, and ${_num(t, 4)} \cdot {_num(d - c)} + "
                         rf"{_paren(c)} = {_num(out[-1], 4)}$.")
        return Worked(steps, np.array(out))

    def statement(self):
        (a, b), (c, d) = self.in_range, self.out_range
        return (
            rf"A sensor measures values in the range $[a, b] = [{_num(a)}, {_num(b)}]$. For "
            rf"display they are mapped linearly onto $[c, d] = [{_num(c)}, {_num(d)}]$ with "
            + _FORMULA + r". Normalise the measured values "
            + _values_words(self.values) + ".\n\n"
            r"**Answer:** a list of the 4 normalised values, in the order given. " + DECIMALS
            + "\n\n" + data_note("values", "in_range", "out_range"))


#: Where the displayed value sits in its range: fractions that give pleasant numbers (for the
#: grey levels 0..255: whole levels, multiples of 17).
_FRACTIONS = (0.125, 0.2, 0.25, 0.375, 0.4, 0.6, 0.625, 0.75, 0.8, 0.875)
_GREY_FRACTIONS = (0.2, 1 / 3, 0.4, 0.6, 2 / 3, 0.8)


class Denormalize(_Chapter10):
    r"""Undo a normalisation: the data value behind a displayed (normalised) value.

    Solve :math:`g = \frac{v - a}{b - a}(d - c) + c` for :math:`v`:
    :math:`v = a + \frac{g - c}{d - c}(b - a)`.

    Attributes: ``g`` (the displayed value), ``in_range`` (a, b), ``out_range`` (c, d).

    Examples
    --------
    >>> ex = Denormalize(seed=2)
    >>> (a, b), (c, d) = ex.in_range, ex.out_range
    >>> ex.check(a + (ex.g - c) / (d - c) * (b - a)).status
    'correct'
    >>> ex.check((ex.g - a) / (b - a) * (d - c) + c).diagnosis
    'forward formula'
    """

    title = "From a displayed value back to the data"
    answer_form = "number"
    what = "the data value"
    may_coincide = ("ignored c",)
    advice = (r"Undo the steps of the normalisation in reverse order: subtract $c$, divide by "
            r"$d - c$, multiply by $b - a$, add $a$.")

    def draw(self, rng):
        a, b = pick(rng, _IN_RANGES)
        c, d = pick(rng, _OUT_RANGES)
        self.in_range, self.out_range = (float(a), float(b)), (float(c), float(d))
        t = float(pick(rng, _GREY_FRACTIONS if d == 255 else _FRACTIONS))
        self.g = c + t * (d - c)
        self.expected = a + t * (b - a)

    def mistakes(self):
        (a, b), (c, d), g = self.in_range, self.out_range, self.g
        found = [
            Mistake((g - a) / (b - a) * (d - c) + c, r"You applied the normalisation formula "
                    r"again instead of inverting it. The displayed value $g$ lives in $[c, d]$; "
                    r"solve $g = \frac{v - a}{b - a}(d - c) + c$ for $v$.", "forward formula"),
            Mistake((g - c) / (d - c) * (b - a), r"You forgot to add $a$ back: the fraction "
                    r"$\frac{g - c}{d - c}$ times $b - a$ is the distance above $a$, not the "
                    r"value itself.", "no shift back"),
            Mistake(g / (d - c) * (b - a) + a, r"You forgot to subtract $c$ first: the "
                    r"display range starts at $c$, so $g - c$ is how far up it the value is.",
                    "ignored c"),
        ]
        if d == 255:
            found.append(Mistake(g / 256 * (b - a) + a, r"You divided by 256, the number of "
                                 r"grey levels. The levels run from 0 to 255, so the range has "
                                 r"width $d - c = 255$.", "256 levels"))
        return found

    def hints(self):
        (a, b), (c, d), g = self.in_range, self.out_range, self.g
        return [
            r"Undo the normalisation: solve $g = \frac{v - a}{b - a}(d - c) + c$ for $v$, doing "
            r"its steps backwards (subtract $c$, divide by $d - c$, multiply by $b - a$, add "
            r"$a$).",
            r"That gives $v = a + \frac{g - c}{d - c}\,(b - a)$: the fraction of the way up the "
            r"display range is the same fraction of the way up the data range.",
            rf"Here $\frac{{g - c}}{{d - c}} = \frac{{{_num(g)} - {_paren(c)}}}{{{_num(d - c)}}} "
            rf"= {_num((g - c) / (d - c), 4)}$ and $b - a = {_num(b - a)}$.",
        ]

    def worked(self):
        (a, b), (c, d), g = self.in_range, self.out_range, self.g
        fraction = (g - c) / (d - c)
        v = a + fraction * (b - a)
        return Worked([
            r"Solve $g = \frac{v - a}{b - a}(d - c) + c$ for $v$: "
            r"$v = a + \frac{g - c}{d - c}\,(b - a)$.",
            rf"The fraction of the display range: $\frac{{{_num(g)} - {_paren(c)}}}"
            rf"{{{_num(d)} - {_paren(c)}}} = {_num(fraction, 4)}$.",
            rf"The same fraction of the data range, from $a$: $v = {_num(a)} + "
            rf"{_num(fraction, 4)} \cdot {_num(b - a)} = {_num(v, 4)}$.",
        ], v)

    def statement(self):
        (a, b), (c, d) = self.in_range, self.out_range
        return (
            rf"Data in the range $[a, b] = [{_num(a)}, {_num(b)}]$ were mapped onto "
            rf"$[c, d] = [{_num(c)}, {_num(d)}]$ by " + _FORMULA + r". A pixel shows the "
            rf"value $g = {_num(self.g)}$. Which data value $v$ does it stand for?" "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("g", "in_range", "out_range"))
