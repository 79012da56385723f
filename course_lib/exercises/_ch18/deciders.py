"""Chapter 18 exercises: the asymptotic decider of an ambiguous marching-squares cell.

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import numpy as np

from ... import scivis
from ..core import DECIMALS, Mistake, Worked, data_note
from . import _Chapter18, _num

__all__ = ["AsymptoticDecider"]


def _joined(corners, level, value):
    """The pair of corners joined through the cell when the centre value is `value`."""
    above = [k for k in range(4) if corners[k] >= level]
    below = [k for k in range(4) if corners[k] < level]
    return above if value >= level else below


class AsymptoticDecider(_Chapter18):
    r"""The asymptotic decider by hand: the saddle value and the corners it joins.

    Corners :math:`f_0 \dots f_3` counter-clockwise from the bottom left; the bilinear
    interpolant's saddle value is :math:`(f_0 f_2 - f_1 f_3)/(f_0 + f_2 - f_1 - f_3)`; if it is
    at least the level the two above corners are joined through the cell, else the two below.
    In half the variants the midpoint decider (the mean) decides the other way (drawn first).

    Attributes: ``corners``, ``level``.

    Examples
    --------
    >>> ex = AsymptoticDecider(seed=0)
    >>> s, above = scivis.asymptotic_decider(ex.corners, ex.level)
    >>> ex.check(ex.expected).status
    'correct'
    >>> f = ex.corners
    >>> wrong = -s
    >>> ex.check([wrong] + _joined(f, ex.level, wrong)).diagnosis
    'numerator sign'
    """

    title = "An ambiguous cell: the asymptotic decider"
    answer_form = "vector"
    what = "[saddle value, corner, corner]"
    advice = (r"Compute $(f_0 f_2 - f_1 f_3)/(f_0 + f_2 - f_1 - f_3)$ (diagonal products), "
              r"compare it with the level, and join the two corners on the same side as it.")

    def draw(self, rng):
        case = int(rng.integers(2))
        up, down = ((0, 2), (1, 3)) if case == 0 else ((1, 3), (0, 2))
        disagree = bool(rng.random() < 0.5)          # drawn first: both kinds come up evenly
        for _ in range(2000):                        # some levels cannot disagree: redraw them
            self.level = float(rng.integers(2, 7)) + 0.5
            f = np.zeros(4)
            f[list(up)] = self.level + 0.5 + rng.integers(0, 7, size=2)
            f[list(down)] = self.level - 0.5 - rng.integers(0, self.level - 0.5 + 1e-9, size=2)
            self.corners = f
            if self.acceptable() and ((f.mean() >= self.level)
                                      != (self._saddle() >= self.level)) == disagree:
                break
        self.corners = f
        s, above = scivis.asymptotic_decider(f, self.level)
        self.expected = np.array([s] + _joined(f, self.level, s), dtype=float)

    def _saddle(self):
        f = self.corners
        return float((f[0] * f[2] - f[1] * f[3]) / (f[0] + f[2] - f[1] - f[3]))

    def acceptable(self):
        s, f = self._saddle(), self.corners
        return abs(s - self.level) >= 0.1 and abs(s) > 0.2 and abs(f.mean() - self.level) >= 0.1

    def mistakes(self):
        f, c = self.corners, self.level
        s = self.expected[0]
        mean = float(f.mean())
        other = [k for k in range(4) if k not in self.expected[1:]]
        return [
            Mistake([mean] + _joined(f, c, mean), r"You used the mean of the four corners (the "
                    r"midpoint decider). The asymptotic decider takes the value of the bilinear "
                    r"interpolant at its saddle point, $(f_0 f_2 - f_1 f_3)/(f_0 + f_2 - f_1 - "
                    r"f_3)$, which can lie on the other side of the level.", "mean"),
            Mistake([-s] + _joined(f, c, -s), r"The numerator's sign is flipped: the saddle "
                    r"value is $(f_0 f_2 - f_1 f_3)/(f_0 + f_2 - f_1 - f_3)$, products of the "
                    r"diagonals (0, 2) minus (1, 3), over the same difference of sums.",
                    "numerator sign"),
            Mistake([s] + other, r"Right saddle value, wrong pair: the corners joined through "
                    r"the cell are the two on the same side of the level as the saddle value "
                    rf"(it is {'at least' if s >= c else 'below'} the level here).",
                    "wrong pair"),
        ]

    def statement(self):
        f = self.corners
        return (
            rf"A marching-squares cell has the corner values $f_0 = {_num(f[0])}$, "
            rf"$f_1 = {_num(f[1])}$, $f_2 = {_num(f[2])}$, $f_3 = {_num(f[3])}$ (counter-"
            rf"clockwise from the bottom left) and the level is $c = {_num(self.level)}$: two "
            r"diagonal corners are above, two below, an ambiguous saddle. Resolve it with the "
            r"**asymptotic decider**: what is the value of the bilinear interpolant at its "
            r"saddle point, and which two corners are joined through the cell?" "\n\n"
            r"**Answer:** `[saddle value, corner, corner]`, smaller corner number first. "
            + DECIMALS + "\n\n" + data_note("corners", "level"))

    def hints(self):
        f = self.corners
        den = f[0] + f[2] - f[1] - f[3]
        return [
            r"The bilinear interpolant $f(s,t)$ has one critical point in the plane, a saddle; "
            r"setting both partial derivatives to zero gives its value "
            r"$(f_0 f_2 - f_1 f_3)/(f_0 + f_2 - f_1 - f_3)$.",
            rf"Here the numerator is ${_num(f[0])} \cdot {_num(f[2])} - {_num(f[1])} \cdot "
            rf"{_num(f[3])} = {_num(f[0] * f[2] - f[1] * f[3])}$ and the denominator "
            rf"${_num(den)}$.",
            r"If the saddle value is at least the level, the two above corners are joined "
            r"through the cell; otherwise the two below corners are.",
        ]

    def worked(self):
        f, c = self.corners, self.level
        num, den = f[0] * f[2] - f[1] * f[3], f[0] + f[2] - f[1] - f[3]
        s = num / den
        pair = _joined(f, c, s)
        above = [k for k in range(4) if f[k] >= c]
        mean = float(f.mean())
        return Worked([
            rf"Corners {above[0]} and {above[1]} are above $c = {_num(c)}$: a saddle.",
            rf"Saddle value: $\dfrac{{{_num(f[0])} \cdot {_num(f[2])} - {_num(f[1])} \cdot "
            rf"{_num(f[3])}}}{{{_num(f[0])} + {_num(f[2])} - {_num(f[1])} - {_num(f[3])}}} = "
            rf"\dfrac{{{_num(num)}}}{{{_num(den)}}} = {_num(s, 4)}$.",
            rf"${_num(s, 4)} " + (r"\ge" if s >= c else "<") + rf" {_num(c)}$: the "
            rf"{'above' if s >= c else 'below'} corners {pair[0]} and {pair[1]} are joined "
            rf"through the cell. (The mean {_num(mean, 4)} would say "
            rf"{'the same' if (mean >= c) == (s >= c) else 'the opposite'}.)",
        ], [s] + pair)
