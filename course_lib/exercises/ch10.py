r"""Chapter 10 exercises: normalisation, transfer functions and colour maps, exam style.

Each class is one kind of exam question: normalise values from one range onto another and undo
it; evaluate a piecewise-linear transfer function and a step (thresholding) function; design an
opacity transfer function for a band of values; look a value up in a colour map; compute the
perceived lightness :math:`L^*` of a colour; tell from their lightness curves which colour maps
can show an ordered quantity; and choose the kind of colour map (sequential, diverging,
qualitative) that a kind of data needs. The ``seed`` draws numbers that work out by hand: whole
data ranges, values that fall on fifths or quarters of a colour-map interval, colour components in
steps of 0.2.

The expected answers come from :mod:`course_lib.colormaps`. Each exercise names the slips it
anticipates (the offset :math:`c` of the target range forgotten, a division by :math:`b`
instead of :math:`b - a`, a step function read where a linear one was meant, :math:`n` instead
of :math:`n - 1` intervals in a colour map, lightness computed from gamma-encoded values, ...),
computes the answer each slip would give, and draws its numbers again until those answers differ
clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.colormaps`): colours are sRGB triples in [0, 1]; a colour
map of :math:`n` control colours places them at :math:`t_k = k / (n - 1)` and interpolates
linearly in RGB; a transfer function keeps its end values outside its control points; a step
function takes the value :math:`v_i` on :math:`[s_i, s_{i+1})`.
"""
import numpy as np

from .. import colormaps as cm
from .. import format as fmt
from .core import (DECIMALS, UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, agrees,
                   data_note, has_placeholder, pick, read_floats, read_names)

__all__ = [
    "EXERCISES",
    "MAP_KINDS",
    "SCENARIOS",
    "ChooseMapKind",
    "ColormapLookup",
    "Denormalize",
    "DesignOpacity",
    "LightnessOfColour",
    "MonotonicMaps",
    "NormalizeValues",
    "ThresholdBands",
    "TransferValues",
]

_num = fmt.number
_vec = fmt.vector_latex


def _paren(x):
    """A number for a formula: in parentheses when it is negative (``v - (-10)``)."""
    return f"({_num(x)})" if x < 0 else _num(x)


def _values_words(values):
    return ", ".join(f"${_num(v)}$" for v in values)


class _Chapter10(DrawnExercise):
    """The chapter's base: answers are lists of values, not directions, and never True/False
    (see ``DrawnExercise.vector_like`` and ``reject_bool``)."""

    vector_like = False
    reject_bool = True


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


# ---------------------------------------------------------------------------------------------
# Transfer functions
# ---------------------------------------------------------------------------------------------

_LEVELS = (0.0, 0.2, 0.4, 0.5, 0.6, 0.8, 1.0)


def _nearest_values(points, values, samples):
    idx = np.abs(np.asarray(samples)[:, None] - np.asarray(points)[None, :]).argmin(axis=1)
    return np.asarray(values)[idx]


def _extrapolated(points, values, samples):
    s = np.asarray(samples, dtype=float)
    out = np.interp(s, points, values)
    lo, hi = s < points[0], s > points[-1]
    slope0 = (values[1] - values[0]) / (points[1] - points[0])
    slope1 = (values[-1] - values[-2]) / (points[-1] - points[-2])
    out[lo] = values[0] + (s[lo] - points[0]) * slope0
    out[hi] = values[-1] + (s[hi] - points[-1]) * slope1
    return out


def _table(points, values, name="s", value_name="f(s)"):
    return (f"| ${name}$ | " + " | ".join(f"${_num(p)}$" for p in points) + " |\n"
            + "|---" * (len(points) + 1) + "|\n"
            + f"| ${value_name}$ | " + " | ".join(f"${_num(v)}$" for v in values) + " |")


class TransferValues(_Chapter10):
    r"""Evaluate a piecewise-linear intensity transfer function at a few scalars.

    Between control points :math:`s_i < s_{i+1}` the value is interpolated linearly; outside the
    first and last control points it stays at the end value.

    Attributes: ``points``, ``values`` (the control points and their intensities), ``samples``.

    Examples
    --------
    >>> ex = TransferValues(seed=0)
    >>> ex.check(np.interp(ex.samples, ex.points, ex.values)).status
    'correct'
    >>> ex.check(cm.TransferFunction(ex.points, ex.values, "step")(ex.samples)).diagnosis
    'step'
    """

    title = "Evaluate a transfer function"
    answer_form = "vector"
    what = "the list of intensities"
    advice = (r"For each scalar find the two control points around it, "
            r"$s_i \le s \le s_{i+1}$, and interpolate: "
            r"$f(s) = f_i + \frac{s - s_i}{s_{i+1} - s_i}(f_{i+1} - f_i)$. Outside the control "
            r"points the end value holds.")

    def draw(self, rng):
        n = int(pick(rng, (3, 4)))
        self.points = np.sort(rng.choice(np.arange(1, 10), size=n, replace=False)) * 10.0
        while True:
            self.values = np.array([pick(rng, _LEVELS) for _ in range(n)])
            if np.all(np.diff(self.values) != 0):
                break
        inner = [s for s in np.arange(self.points[0] + 5, self.points[-1], 5.0)
                 if s not in self.points]
        outer = [s for s in (0.0, 5.0, 95.0, 100.0) if s < self.points[0] or s > self.points[-1]]
        chosen = list(rng.choice(inner, size=min(3, len(inner)), replace=False))
        self.samples = np.array(sorted(chosen + [float(pick(rng, outer))]))
        self.expected = cm.TransferFunction(self.points, self.values)(self.samples)

    def acceptable(self):
        return len(self.samples) == 4

    def mistakes(self):
        p, v, s = self.points, self.values, self.samples
        return [
            Mistake(cm.TransferFunction(p, v, "step")(s), r"You used the value of the control "
                    r"point below each scalar, as if the function were a step function. Between "
                    r"control points it changes linearly: interpolate.", "step"),
            Mistake(_nearest_values(p, v, s), r"You took the value of the nearest control "
                    r"point. The function is linear between control points: interpolate "
                    r"between the two around each scalar.", "nearest"),
            Mistake(_extrapolated(p, v, s), r"Outside the control points you continued the "
                    r"first or last segment. A transfer function keeps its end value there "
                    r"(it is clamped).", "extrapolated"),
            Mistake(np.interp(s, [p[0], p[-1]], [v[0], v[-1]]), r"You interpolated between "
                    r"the first and the last control point only. Every control point counts: "
                    r"find the segment $[s_i, s_{i+1}]$ that holds the scalar.", "ends only"),
        ]

    def _steps(self):
        """For each sample: (the words of its evaluation, the value)."""
        p, v = self.points, self.values
        found = []
        for s in self.samples:
            if s <= p[0] or s >= p[-1]:
                end = 0 if s <= p[0] else len(p) - 1
                side = "below the first" if end == 0 else "above the last"
                found.append((rf"$s = {_num(s)}$ lies {side} control point: the end value "
                              rf"$f = {_num(v[end])}$ holds.", float(v[end])))
                continue
            i = max(j for j in range(len(p) - 1) if p[j] <= s)
            frac = (s - p[i]) / (p[i + 1] - p[i])
            value = v[i] + frac * (v[i + 1] - v[i])
            found.append((rf"$s = {_num(s)}$ lies in $[{_num(p[i])}, {_num(p[i + 1])}]$: "
                          rf"$\frac{{{_num(s)} - {_num(p[i])}}}{{{_num(p[i + 1] - p[i])}}} = "
                          rf"{_num(frac, 4)}$ of the way, so $f = {_num(v[i])} + {_num(frac, 4)} "
                          rf"\cdot ({_num(v[i + 1] - v[i])}) = {_num(value, 4)}$.", value))
        return found

    def hints(self):
        p = self.points
        steps = self._steps()
        inside = [text for s, (text, _) in zip(self.samples, steps) if p[0] < s < p[-1]]
        outside = [s for s in self.samples if s < p[0] or s > p[-1]]
        return [
            r"The function is linear between neighbouring control points and keeps the end "
            r"values outside them (it is clamped, not extended).",
            r"For each scalar find the two control points around it, $s_i \le s \le s_{i+1}$, and "
            r"interpolate: $f(s) = f_i + \frac{s - s_i}{s_{i+1} - s_i}\,(f_{i+1} - f_i)$.",
            "For example " + inside[0] + rf" And $s = {_num(outside[0])}$ lies outside "
            rf"$[{_num(p[0])}, {_num(p[-1])}]$.",
        ]

    def worked(self):
        steps = self._steps()
        return Worked([text for text, _ in steps]
                      + ["The intensities, in the order of the scalars: "
                         + ", ".join(f"${_num(x, 4)}$" for _, x in steps) + "."],
                      np.array([x for _, x in steps]))

    def statement(self):
        return (
            r"An intensity transfer function $f$ is given by its control points (linear in "
            r"between, constant outside):" "\n\n" + _table(self.points, self.values) + "\n\n"
            r"What intensity does it give to the scalars " + _values_words(self.samples) + "?"
            "\n\n" r"**Answer:** a list of the 4 intensities, in the order given. " + DECIMALS
            + "\n\n" + data_note("points", "values", "samples"))


class ThresholdBands(_Chapter10):
    r"""Evaluate a step transfer function (a thresholding of the data into bands).

    The value is :math:`v_i` on :math:`[s_i, s_{i+1})`, :math:`v_0` below :math:`s_0` and the last
    value from the last threshold on: a scalar exactly at a threshold belongs to the band above.

    Attributes: ``points`` (thresholds), ``values``, ``samples``.

    Examples
    --------
    >>> ex = ThresholdBands(seed=0)
    >>> ex.check(cm.TransferFunction(ex.points, ex.values, "step")(ex.samples)).status
    'correct'
    >>> ex.check(cm.TransferFunction(ex.points, ex.values)(ex.samples)).diagnosis
    'interpolated'
    """

    title = "Thresholding with a step function"
    answer_form = "vector"
    what = "the list of values"
    advice = (r"For each scalar find the band $s_i \le s < s_{i+1}$ it falls in and take that "
            r"band's value $v_i$; no interpolation.")

    def draw(self, rng):
        n = 4
        self.points = np.sort(rng.choice(np.arange(1, 10), size=n, replace=False)) * 100.0
        while True:
            self.values = np.array([pick(rng, _LEVELS) for _ in range(n)])
            if np.all(np.diff(self.values) != 0):
                break
        at = float(pick(rng, self.points[1:]))
        others = [s for s in np.arange(50.0, 1000.0, 50.0) if s not in self.points]
        chosen = list(rng.choice(others, size=4, replace=False))
        self.samples = np.array(sorted(chosen + [at]))
        self.expected = cm.TransferFunction(self.points, self.values, "step")(self.samples)

    def mistakes(self):
        p, v, s = self.points, self.values, self.samples
        band = np.clip(np.searchsorted(p, s, side="left") - 1, 0, len(p) - 1)   # (s_i, s_{i+1}]
        upper = np.clip(np.searchsorted(p, s, side="right"), 0, len(p) - 1)
        return [
            Mistake(v[band], r"A scalar exactly at a threshold belongs to the band **above** "
                    r"it: the step function takes $v_i$ on $[s_i, s_{i+1})$, closed at the "
                    r"lower end.", "boundary below"),
            Mistake(v[upper], r"You took the value of the next band up. The value $v_i$ holds "
                    r"from the threshold $s_i$ up to (not including) $s_{i+1}$.", "next band"),
            Mistake(cm.TransferFunction(p, v)(s), r"You interpolated between the thresholds. "
                    r"A step function is constant on each band and jumps at the thresholds.",
                    "interpolated"),
        ]

    def _band(self, s):
        """The index i of the band [s_i, s_{i+1}) of scalar s (0 below the first threshold)."""
        below = [j for j, q in enumerate(self.points) if q <= s]
        return below[-1] if below else 0

    def hints(self):
        p, v = self.points, self.values
        on = [s for s in self.samples if s in set(p)][0]
        j = self._band(on)
        return [
            r"A step function does not interpolate: it is constant on each band and jumps at "
            r"the thresholds.",
            r"For each scalar find the band $s_i \le s < s_{i+1}$: the last threshold at or below "
            r"it. Below the first threshold the value is $v_0$; a scalar exactly on a threshold "
            r"belongs to the band **above** it.",
            rf"Here $s = {_num(on)}$ is exactly the threshold $s_{j}$: it gets "
            rf"$v_{j} = {_num(v[j])}$, not $v_{j - 1} = {_num(v[j - 1])}$.",
        ]

    def worked(self):
        p, v = self.points, self.values
        steps, out = [], []
        for s in self.samples:
            i = self._band(s)
            out.append(float(v[i]))
            if s < p[0]:
                where = rf"below the first threshold ${_num(p[0])}$"
            elif i == len(p) - 1:
                where = rf"at or above the last threshold $s_{i} = {_num(p[i])}$"
            else:
                where = rf"in $[s_{i}, s_{i + 1}) = [{_num(p[i])}, {_num(p[i + 1])})$"
            steps.append(rf"$s = {_num(s)}$ lies {where}: $f = v_{i} = {_num(v[i])}$.")
        return Worked(steps, np.array(out))

    def statement(self):
        return (
            r"A step transfer function classifies the data into bands: $f(s) = v_i$ for "
            r"$s_i \le s < s_{i+1}$, $f(s) = v_0$ below $s_0$ and $f(s) = v_3$ from $s_3$ on."
            "\n\n" + _table(self.points, self.values, "s_i", "v_i") + "\n\n"
            r"What does it give for the scalars " + _values_words(self.samples) + "?\n\n"
            r"**Answer:** a list of the 5 values, in the order given. " + DECIMALS + "\n\n"
            + data_note("points", "values", "samples"))


def _read_control_points(answer):
    """A TransferFunction from a student's control points, or a Feedback."""
    if isinstance(answer, cm.TransferFunction):
        if answer.channels != 1:
            return Feedback("invalid", "Your transfer function has several channels; give an "
                            "opacity function (one number per control point).", "unreadable")
        return answer
    if has_placeholder(answer):
        return Feedback("unanswered", UNANSWERED)
    form = ("Give the control points as a list of `(scalar, opacity)` pairs, e.g. "
            "`[(10, 0), (20, 0.5), ...]`, or as a `TransferFunction`.")
    value = read_floats(answer)
    if value is None or value.ndim != 2:
        return Feedback("invalid", form, "unreadable")
    if value.shape[0] == 2 and value.shape[1] > 2:
        value = value.T                              # [points, values] given as two rows
    if value.shape[1] != 2 or len(value) < 2:
        return Feedback("invalid", form, "unreadable")
    value = value[np.argsort(value[:, 0], kind="stable")]
    if ((value[:, 1] < 0) | (value[:, 1] > 1)).any():
        return Feedback("invalid", "An opacity must lie in [0, 1] (0 transparent, 1 opaque).",
                        "opacity out of range")
    try:
        return cm.TransferFunction(value[:, 0], value[:, 1])
    except ValueError as exc:
        return Feedback("invalid", f"These control points do not define a function: {exc}.",
                        "unreadable")


class DesignOpacity(_Chapter10):
    r"""Design an opacity transfer function that shows one band of values (a tissue).

    Values in :math:`[l, h]` get opacity :math:`\alpha`, values outside :math:`[l - w, h + w]`
    are transparent, with linear ramps in between: the control points
    :math:`(l - w, 0), (l, \alpha), (h, \alpha), (h + w, 0)`. Any control points that define the
    same function are right (extra points on the lines, the range ends added, a
    ``TransferFunction`` object); the function is compared on a fine grid over the data range.

    Attributes: ``data_range``, ``low``, ``high``, ``width``, ``alpha``; ``grid`` (the scalars
    the function is compared at).

    Examples
    --------
    >>> ex = DesignOpacity(seed=0)
    >>> l, h, w, a = ex.low, ex.high, ex.width, ex.alpha
    >>> ex.check([(l - w, 0), (l, a), (h, a), (h + w, 0)]).status
    'correct'
    >>> ex.check(cm.opacity_transfer([l - w, l, h, h + w], [0, a, a, 0])).status
    'correct'
    >>> ex.check([(l, 0), (l, a), (h, a), (h, 0)]).diagnosis
    'no ramps'
    >>> ex.check([(0, 0.5), (1, 2)]).status
    'invalid'
    """

    title = "Design an opacity transfer function"
    answer_form = "custom"
    what = "your transfer function"

    def draw(self, rng):
        scale = float(pick(rng, (1, 10)))
        self.data_range = (0.0, 100.0 * scale)
        self.width = float(pick(rng, (5, 10))) * scale
        self.low = float(pick(rng, (30, 40, 50))) * scale
        self.high = self.low + float(pick(rng, (20, 30))) * scale
        self.alpha = float(pick(rng, (0.2, 0.3, 0.4, 0.5, 0.6, 0.8)))
        self.grid = np.linspace(*self.data_range, 401)
        self.expected = self._function([self.low - self.width, self.low, self.high,
                                        self.high + self.width], [0, self.alpha, self.alpha, 0])

    def _function(self, points, values):
        return cm.TransferFunction(points, values)(self.grid)

    def mistakes(self):
        lo, hi, w, a = self.low, self.high, self.width, self.alpha
        return [
            Mistake(self._function([lo, lo + w, hi - w, hi], [0, a, a, 0]), r"Your ramps lie "
                    r"inside the band: values just inside $[l, h]$ are not fully shown. The band "
                    r"itself must have opacity $\alpha$; the ramps go outside it, from $l - w$ to "
                    r"$l$ and from $h$ to $h + w$.", "ramps inside"),
            Mistake(self._function([lo, lo, hi, hi], [0, a, a, 0]), r"Your function jumps at "
                    r"the band's edges. Sudden jumps in opacity paint hard artificial edges into "
                    r"a volume rendering; the question asks for linear ramps of width $w$ outside "
                    r"the band.", "no ramps"),
            Mistake(self._function([lo - w, lo, hi, hi + w], [0, 1, 1, 0]), r"The band is fully "
                    r"opaque: it should have opacity $\alpha$, so that it stays translucent and "
                    r"what lies behind it shows through.", "full opacity"),
            Mistake(self._function([lo - w, lo, hi, hi + w], [a, 0, 0, a]), r"Your function is "
                    r"upside down: it hides the band and shows everything else. The band gets "
                    r"opacity $\alpha$, values far from it 0.", "inverted"),
        ]

    def _check(self, answer):
        tf = _read_control_points(answer)
        if isinstance(tf, Feedback):
            return tf
        got = tf(self.grid)
        if agrees(got, self.expected):              # the course's policy, at every grid point
            return Feedback("correct", "Your transfer function is right: it shows the band "
                            "with the asked opacity and fades out over the ramps.")
        for mistake in self._mistakes:
            if agrees(got, mistake.value):
                return Feedback("wrong", mistake.explanation, mistake.key)
        k = int(np.argmax(np.abs(got - self.expected)))
        return Feedback(
            "wrong", f"At $s = {_num(self.grid[k])}$ your function gives opacity "
            f"${_num(got[k])}$ but it should be ${_num(self.expected[k])}$. Sketch the "
            r"function first: 0 up to $l - w$, rising linearly to $\alpha$ at $l$, flat until "
            r"$h$, falling to 0 at $h + w$; its control points are the four corners.",
            "function differs")

    def hints(self):
        lo, hi, w, a = self.low, self.high, self.width, self.alpha
        return [
            r"Sketch the function first: 0, a ramp up, flat at $\alpha$ over the band, a ramp "
            r"down, 0 again. Its control points are the four corners of that shape.",
            r"The band itself must be fully at $\alpha$, so the ramps lie **outside** it: "
            r"from $l - w$ up to $l$, and from $h$ down to $h + w$.",
            rf"Here the first corner is $(l - w, 0) = ({_num(lo - w)}, 0)$, and the flat top "
            rf"runs from $s = {_num(lo)}$ to $s = {_num(hi)}$ at opacity ${_num(a)}$.",
        ]

    def worked(self):
        lo, hi, w, a = self.low, self.high, self.width, self.alpha
        points = [(lo - w, 0.0), (lo, a), (hi, a), (hi + w, 0.0)]
        return Worked([
            rf"Transparent up to $l - w = {_num(lo)} - {_num(w)} = {_num(lo - w)}$: the control "
            rf"point $({_num(lo - w)}, 0)$ (the function keeps 0 below it).",
            rf"A linear ramp up to the band's start: $({_num(lo)}, {_num(a)})$; flat at "
            rf"$\alpha = {_num(a)}$ to its end: $({_num(hi)}, {_num(a)})$.",
            rf"A ramp down to $h + w = {_num(hi + w)}$: $({_num(hi + w)}, 0)$, and 0 above it.",
        ], points)

    def statement(self):
        lo, hi, w = self.low, self.high, self.width
        return (
            rf"A CT volume holds values in $[{_num(self.data_range[0])}, "
            rf"{_num(self.data_range[1])}]$. A tissue has the values $[l, h] = [{_num(lo)}, "
            rf"{_num(hi)}]$. Design a piecewise-linear opacity transfer function that gives the "
            rf"tissue the opacity $\alpha = {_num(self.alpha)}$, makes every value below "
            rf"$l - w$ or above $h + w$ (with $w = {_num(w)}$) fully transparent, and changes "
            r"linearly in between (soft edges)." "\n\n"
            r"**Answer:** the control points as a list of `(scalar, opacity)` pairs in "
            r"increasing order of the scalar, e.g. `[(10, 0), (20, 0.5), (30, 0)]` (outside its "
            r"first and last points the function keeps its end values), or a "
            r"`TransferFunction`. Any control points that give the same function are right."
            "\n\n" + data_note("low", "high", "width", "alpha", "data_range"))


# ---------------------------------------------------------------------------------------------
# Colour maps
# ---------------------------------------------------------------------------------------------

#: Small colour maps whose control colours are easy to work with by hand.
_SMALL_MAPS = {
    "rainbow": np.array([[0, 0, 1], [0, 1, 1], [0, 1, 0], [1, 1, 0], [1, 0, 0]], float),
    "blue-white-red": np.array([[0, 0, 1], [1, 1, 1], [1, 0, 0]], float),
    "heat": np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]], float),
}
_COLOUR_NAMES = {(0, 0, 1): "blue", (0, 1, 1): "cyan", (0, 1, 0): "green", (1, 1, 0): "yellow",
                 (1, 0, 0): "red", (1, 1, 1): "white", (0, 0, 0): "black"}


class ColormapLookup(_Chapter10):
    r"""The colour a data value gets from a small colour map.

    Normalise :math:`t = (v - a)/(b - a)`; with :math:`n` control colours at
    :math:`t_k = k / (n - 1)`, position :math:`p = t (n - 1)`, :math:`k = \lfloor p \rfloor`,
    :math:`f = p - k`: colour :math:`(1 - f) C_k + f C_{k+1}`.

    Attributes: ``name``, ``colors`` (the control colours, rows), ``value``, ``in_range``.

    Examples
    --------
    >>> ex = ColormapLookup(seed=0)
    >>> ex.check(cm.apply_colormap(ex.value, ex.colors, in_range=ex.in_range)).status
    'correct'
    >>> ex.check(cm.apply_colormap(ex.value, ex.colors[::-1], in_range=ex.in_range)).diagnosis
    'reversed'
    """

    title = "Look a value up in a colour map"
    answer_form = "vector"
    what = "the colour"
    may_coincide = ("forgot a",)
    advice = (r"Normalise first, $t = \frac{v - a}{b - a}$; then $p = t\,(n - 1)$ tells between "
            r"which two control colours you are ($k = \lfloor p \rfloor$) and how far "
            r"($f = p - k$): the colour is $(1 - f)\,C_k + f\,C_{k+1}$, channel by channel.")

    def draw(self, rng):
        self.name = str(pick(rng, tuple(_SMALL_MAPS)))
        self.colors = _SMALL_MAPS[self.name]
        n = len(self.colors)
        a = float(pick(rng, (-20, 0, 10, 50)))
        span = float((n - 1) * pick(rng, (20, 40, 100, 200)))
        self.in_range = (a, a + span)
        k = int(rng.integers(0, n - 1))
        f = float(pick(rng, (0.2, 0.25, 0.4, 0.5, 0.6, 0.75, 0.8)))
        step = span / (n - 1)                        # the data range of one interval
        self.value = a + k * step + float(round(f * step))      # a whole number
        self.expected = cm.apply_colormap(self.value, self.colors, in_range=self.in_range)

    def mistakes(self):
        (a, b), c, n = self.in_range, self.colors, len(self.colors)
        t = (self.value - a) / (b - a)
        p = t * (n - 1)
        return [
            Mistake(c[int(np.floor(p))], r"You took the control colour just below instead of "
                    r"interpolating. Colours between control points are mixed linearly: "
                    r"$(1 - f)\,C_k + f\,C_{k+1}$ with $f = p - k$.", "no interpolation"),
            Mistake(cm.apply_colormap(min(t * n / (n - 1), 1.0), c, in_range=(0, 1)),
                    rf"You multiplied $t$ by $n = {n}$. The {n} control colours split $[0, 1]$ "
                    rf"into $n - 1 = {n - 1}$ intervals, so the position is $p = t\,(n - 1)$.",
                    "n intervals"),
            Mistake(cm.apply_colormap(self.value, c[::-1], in_range=self.in_range), r"You read "
                    r"the map backwards: its first colour belongs to the smallest value $a$ "
                    r"($t = 0$), its last colour to $b$.", "reversed"),
            Mistake(cm.apply_colormap(min(max(self.value / b, 0.0), 1.0), c, in_range=(0, 1)),
                    r"You normalised by $v / b$ and forgot to subtract $a$: $t = "
                    r"\frac{v - a}{b - a}$.", "forgot a"),
        ]

    def _position(self):
        (a, b), n = self.in_range, len(self.colors)
        t = (self.value - a) / (b - a)
        p = t * (n - 1)
        k = min(int(np.floor(p)), n - 2)
        return t, p, k, p - k

    def hints(self):
        (a, b), n = self.in_range, len(self.colors)
        t, p, k, f = self._position()
        return [
            r"Two steps: normalise the value onto the map's parameter, "
            r"$t = \frac{v - a}{b - a} \in [0, 1]$; then find where $t$ falls between the "
            r"control colours.",
            rf"With $n = {n}$ control colours at $t_k = \frac{{k}}{{{n - 1}}}$, the position is "
            r"$p = t\,(n - 1)$: it lies between $C_k$ and $C_{k+1}$ with $k = \lfloor p \rfloor$, "
            r"a fraction $f = p - k$ of the way; mix $(1 - f)\,C_k + f\,C_{k+1}$.",
            rf"Here $t = \frac{{{_num(self.value)} - {_paren(a)}}}{{{_num(b - a)}}} = "
            rf"{_num(t, 4)}$ and $p = {_num(t, 4)} \cdot {n - 1} = {_num(p, 4)}$: between "
            rf"$C_{k} = {_vec(self.colors[k])}$ and $C_{k + 1} = {_vec(self.colors[k + 1])}$, "
            rf"$f = {_num(f, 4)}$.",
        ]

    def worked(self):
        (a, b), n = self.in_range, len(self.colors)
        t, p, k, f = self._position()
        c0, c1 = self.colors[k], self.colors[k + 1]
        colour = (1 - f) * c0 + f * c1
        return Worked([
            rf"Normalise: $t = \frac{{{_num(self.value)} - {_paren(a)}}}{{{_num(b)} - "
            rf"{_paren(a)}}} = {_num(t, 4)}$.",
            rf"The position among the {n} control colours: $p = t\,(n - 1) = {_num(t, 4)} \cdot "
            rf"{n - 1} = {_num(p, 4)}$, so $k = {k}$ and $f = {_num(f, 4)}$.",
            rf"Mix channel by channel: $(1 - f)\,C_{k} + f\,C_{k + 1} = {_num(1 - f, 4)}\,"
            rf"{_vec(c0)} + {_num(f, 4)}\,{_vec(c1)} = {_vec(colour)}$.",
        ], colour)

    def statement(self):
        names = ", ".join(f"$C_{k} = {_vec(c)}$ ({_COLOUR_NAMES[tuple(int(x) for x in c)]})"
                          for k, c in enumerate(self.colors))
        (a, b) = self.in_range
        return (
            rf"The colour map *{self.name}* has {len(self.colors)} control colours (RGB), "
            rf"evenly spaced over $t \in [0, 1]$ and interpolated linearly: " + names + r". It "
            rf"is spread over the data range $[a, b] = [{_num(a)}, {_num(b)}]$. Which colour does "
            rf"the value $v = {_num(self.value)}$ get?" "\n\n"
            r"**Answer:** the colour as a list of 3 numbers `[r, g, b]` in [0, 1]. " + DECIMALS
            + "\n\n" + data_note("colors", "value", "in_range"))


_COMPONENTS = (0.0, 0.2, 0.4, 0.6, 0.8, 1.0)


def _lin(c):
    c = np.asarray(c, dtype=float)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def _lstar(y):
    return 116 * np.cbrt(y) - 16 if y > (6 / 29) ** 3 else y * (29 / 3) ** 3


_WEIGHTS = np.array([0.2126, 0.7152, 0.0722])


class LightnessOfColour(_Chapter10):
    r"""The perceived lightness :math:`L^*` of an sRGB colour.

    Undo the gamma encoding channel by channel, weigh the linear channels into the relative
    luminance :math:`Y = 0.2126 R + 0.7152 G + 0.0722 B`, and compress:
    :math:`L^* = 116\, Y^{1/3} - 16` (the CIE 1976 lightness, white :math:`Y_n = 1`).

    Attributes: ``rgb``.

    Examples
    --------
    >>> ex = LightnessOfColour(seed=0)
    >>> ex.check(float(cm.srgb_to_lab(ex.rgb)[0])).status
    'correct'
    >>> ex.check(100 * float(cm.luminance(ex.rgb))).diagnosis
    'luminance, not lightness'
    """

    title = "Lightness of a colour"
    answer_form = "number"
    what = r"$L^*$"
    advice = (r"Three steps: linearise each channel, weigh them into $Y$, then "
            r"$L^* = 116\,Y^{1/3} - 16$.")

    def draw(self, rng):
        self.rgb = np.array([pick(rng, _COMPONENTS) for _ in range(3)])
        self.expected = float(cm.srgb_to_lab(self.rgb)[0])

    def acceptable(self):
        return 10 < self.expected < 95

    def mistakes(self):
        lin = _lin(self.rgb)
        y = float(_WEIGHTS @ lin)
        return [
            Mistake(_lstar(float(_WEIGHTS @ self.rgb)), r"You weighed the stored (gamma-encoded) "
                    r"values. sRGB values are not proportional to light: undo the encoding "
                    r"first, $c_{lin} = \left(\frac{c + 0.055}{1.055}\right)^{2.4}$ (or "
                    r"$c / 12.92$ for small $c$).", "not linearised"),
            Mistake(_lstar(float(lin.mean())), r"You averaged the three channels. The eye is "
                    r"far more sensitive to green than to blue: weigh them, "
                    r"$Y = 0.2126 R + 0.7152 G + 0.0722 B$.", "channel mean"),
            Mistake(100 * y, r"That is the relative luminance $Y$ (times 100), which is "
                    r"proportional to light, not to perceived lightness. Compress it: "
                    r"$L^* = 116\,Y^{1/3} - 16$.", "luminance, not lightness"),
            Mistake(116 * np.cbrt(y), r"You forgot the $-16$: $L^* = 116\,Y^{1/3} - 16$, so "
                    r"that black has $L^* = 0$ and white $L^* = 100$.", "forgot 16"),
        ]

    def _linear(self):
        """The linear channels, each by the sRGB formula."""
        return np.array([c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
                         for c in self.rgb])

    def hints(self):
        lin = self._linear()
        y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]
        c = int(np.argmax(self.rgb))                     # the brightest channel, as an example
        name = ("red", "green", "blue")[c]
        return [
            r"Three steps: undo the gamma encoding of each channel, weigh the linear channels "
            r"into the relative luminance $Y$, and compress $Y$ into $L^*$.",
            rf"The linear channels here are $(R, G, B)_{{lin}} = {_vec(lin, 4)}$ (for example "
            rf"$\left(\frac{{{_num(self.rgb[c])} + 0.055}}{{1.055}}\right)^{{2.4}} = "
            rf"{_num(lin[c], 4)}$ for {name}).",
            rf"$Y = 0.2126 \cdot {_num(lin[0], 4)} + 0.7152 \cdot {_num(lin[1], 4)} + 0.0722 "
            rf"\cdot {_num(lin[2], 4)} = {_num(y, 4)}$; now $L^* = 116\,Y^{{1/3}} - 16$.",
        ]

    def worked(self):
        lin = self._linear()
        y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]
        lightness = 116 * y ** (1 / 3) - 16
        return Worked([
            rf"Linearise each channel of ${_vec(self.rgb)}$: "
            + ", ".join(rf"${_num(c)} \to {_num(x, 4)}$" for c, x in zip(self.rgb, lin))
            + r" (with $c_{lin} = \left(\frac{c + 0.055}{1.055}\right)^{2.4}$, or $c / 12.92$ "
            r"for small $c$).",
            rf"The relative luminance: $Y = 0.2126 \cdot {_num(lin[0], 4)} + 0.7152 \cdot "
            rf"{_num(lin[1], 4)} + 0.0722 \cdot {_num(lin[2], 4)} = {_num(y, 4)}$.",
            rf"The lightness: $L^* = 116 \cdot {_num(y, 4)}^{{1/3}} - 16 = 116 \cdot "
            rf"{_num(y ** (1 / 3), 4)} - 16 = {_num(lightness, 2)}$.",
        ], lightness)

    def statement(self):
        return (
            rf"What is the CIE lightness $L^*$ of the sRGB colour $(r, g, b) = {_vec(self.rgb)}$? "
            r"Linearise each channel with $c_{lin} = c / 12.92$ for $c \le 0.04045$ and "
            r"$c_{lin} = \left(\frac{c + 0.055}{1.055}\right)^{2.4}$ otherwise; the relative "
            r"luminance is $Y = 0.2126\,R_{lin} + 0.7152\,G_{lin} + 0.0722\,B_{lin}$; and "
            r"$L^* = 116\,Y^{1/3} - 16$ (for $Y > 0.0089$)." "\n\n"
            r"**Answer:** one number between 0 and 100. Give at least 2 decimals (or let numpy "
            r"compute it)." "\n\n" + data_note("rgb"))


#: The colour maps of the lightness question.
_LIGHTNESS_MENU = tuple(cm.COLORMAP_NAMES)
_DIVERGING = {"bwr", "coolwarm"}
_SAMPLES = 9


def _monotonic(values):
    d = np.diff(values)
    return bool((d >= 0).all() or (d <= 0).all())


def _read_names(answer, menu):
    form = ("Give a list of map names from the table, e.g. `['viridis', 'grey']` (`[]` if none "
            "qualifies).")
    return read_names(answer, menu, form, "is not in the table. The maps are:")


class MonotonicMaps(_Chapter10):
    r"""Which colour maps, judged by their lightness curves, can show an ordered quantity?

    A map for ordered data needs a lightness :math:`L^*` that only rises (or only falls) along
    it. The statement tabulates :math:`L^*` at 9 points of four maps; the answer is the set of
    the monotonic ones. Diagnosis ``"extra: <name>"`` or ``"missing: <name>"`` for the first
    wrong map in the table's order.

    Attributes: ``maps`` (the names), ``lightness`` (one row of 9 values of :math:`L^*` per map).

    Examples
    --------
    >>> ex = MonotonicMaps(seed=0)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> ex.check(list(ex.maps)).diagnosis.startswith("extra: ")
    True
    >>> ex.check("viridis").status
    'invalid'
    """

    title = "Which maps show order?"
    answer_form = "custom"

    def draw(self, rng):
        idx = rng.choice(len(_LIGHTNESS_MENU), size=4, replace=False)
        self.maps = tuple(_LIGHTNESS_MENU[i] for i in sorted(idx))
        self.lightness = np.array([np.round(cm.lightness(m, _SAMPLES), 1) for m in self.maps])
        self.expected = {m for m, row in zip(self.maps, self.lightness) if _monotonic(row)}

    def acceptable(self):
        verdicts = {m for m in self.maps if cm.is_monotonic_lightness(m)}
        return verdicts == self.expected and 0 < len(self.expected) < 4

    def separated(self, mistakes):
        return True

    def _reason(self, name):
        row = self.lightness[self.maps.index(name)]
        if name in self.expected:
            way = "rises" if row[-1] > row[0] else "falls"
            return (rf"**{name}**: its $L^*$ {way} at every step, from ${_num(row[0], 1)}$ to "
                    rf"${_num(row[-1], 1)}$, so darker and lighter read as less and more: it "
                    "qualifies.")
        d = np.diff(row)
        up = d[np.flatnonzero(d)[0]] > 0                 # the first direction of change
        turn = int(np.argmax(d < 0 if up else d > 0))    # the first step the other way
        ways = ("rises", "falls") if up else ("falls", "rises")
        text = (rf"**{name}**: its $L^*$ {ways[0]} from ${_num(row[0], 1)}$ to "
                rf"${_num(row[turn], 1)}$ and then {ways[1]} to ${_num(row[turn + 1], 1)}$: not "
                r"monotonic. Equal steps of lightness then do not mean equal steps of the data, "
                r"and bands appear where the lightness turns.")
        if name in _DIVERGING:
            text += (" It is a *diverging* map, lightest in the middle: right for data with a "
                     "meaningful centre, not for a plain ordered quantity.")
        return text

    def hints(self):
        first = self.maps[0]
        return [
            r"Ordered data need a lightness $L^*$ that only rises or only falls along the map: "
            r"the eye (and a black-and-white print) reads order from lightness, not from hue.",
            r"Go along each row and look at the differences between neighbouring values: if "
            r"their sign changes even once, the lightness turns and the map fails.",
            "For example " + self._reason(first) + " Judge the other three the same way.",
        ]

    def worked(self):
        steps, chosen = [], []
        for name, row in zip(self.maps, self.lightness):
            d = np.diff(row)
            rises, falls = bool(np.all(d >= 0)), bool(np.all(d <= 0))
            if rises or falls:
                chosen.append(name)
            steps.append(("Suitable. " if rises or falls else "Not suitable. ")
                         + self._reason(name))
        return Worked(steps, sorted(chosen))

    def _check(self, answer):
        names = _read_names(answer, self.maps)
        if isinstance(names, Feedback):
            return names
        if names == self.expected:
            return Feedback("correct", f"Exactly these {len(names)} maps have a monotonic "
                            "lightness.")
        wrong = [m for m in self.maps if (m in names) != (m in self.expected)]
        first = wrong[0]
        key = ("missing: " if first in self.expected else "extra: ") + first
        return Feedback("wrong", " ".join(self._reason(m) for m in wrong), key)

    def statement(self):
        header = "| map | " + " | ".join(f"$t = {_num(k / 8)}$" for k in range(_SAMPLES)) + " |"
        rule = "|---" * (_SAMPLES + 1) + "|"
        rows = "\n".join(f"| `{m}` | " + " | ".join(_num(v, 1) for v in row) + " |"
                         for m, row in zip(self.maps, self.lightness))
        return (
            r"The table gives the perceived lightness $L^*$ (0 black, 100 white) at nine evenly "
            r"spaced points $t$ along four colour maps. Which of them are suitable for showing "
            r"an ordered quantity (such as a density) so that darker and lighter read as less "
            r"and more, in colour and in a black-and-white print?" "\n\n"
            + header + "\n" + rule + "\n" + rows + "\n\n"
            r"**Answer:** the list of the names of the suitable maps, e.g. `['grey']` (the "
            r"order does not matter)." "\n\n" + data_note("maps", "lightness"))


#: The kinds of colour map.
MAP_KINDS = ("sequential", "diverging", "qualitative")

#: The data sets of the question: (what is shown, the kind of map it needs, what its values are,
#: whether they are ordered, their meaningful centre or None), typed out one by one.
_SCENARIO_TABLE = (
    # sequential: ordered, no special value in between
    ("the yearly rainfall in millimetres over a country", "sequential",
     "amounts from no rain to a lot of rain", True, None),
    ("the population density of the districts of a city", "sequential",
     "densities from nearly empty to crowded", True, None),
    ("the density of a CT scan, from air to bone", "sequential",
     "densities from air (low) to bone (high)", True, None),
    ("the wind speed over an ocean", "sequential", "speeds from calm to storm", True, None),
    ("the concentration of a pollutant in a river", "sequential",
     "concentrations from clean water to heavily polluted", True, None),
    ("the altitude of the terrain in a mountain range, all of it far above sea level",
     "sequential", "heights from the valleys to the peaks", True, None),
    ("the age of the trees in a forest, in years", "sequential",
     "ages from saplings to old trees", True, None),
    ("the number of visitors per day of each page of a website", "sequential",
     "counts from a few visitors to very many", True, None),
    ("the depth of the water in a lake", "sequential",
     "depths from the shallow shore to the deepest point", True, None),
    ("the brightness measured by each pixel of a camera sensor", "sequential",
     "intensities from dark to bright", True, None),
    ("the average household income of each district of a city", "sequential",
     "incomes from low to high", True, None),
    ("the traffic on each street of a city, in cars per hour", "sequential",
     "counts from empty streets to jams", True, None),
    # diverging: ordered, with a meaningful centre
    ("the temperature anomaly: this year's temperature minus the 30-year average",
     "diverging", "deviations, warmer or colder than usual", True, "0, the long-term average"),
    ("the election margin: the share of party A minus the share of party B, per district",
     "diverging", "margins for A or for B", True, "0, a tie"),
    ("correlation coefficients between -1 and 1 in a matrix", "diverging",
     "correlations, negative or positive", True, "0, no correlation"),
    ("the profit or loss of each branch of a company", "diverging",
     "results, gains or losses", True, "0, breaking even"),
    ("the change of the population of each district since the last census, in per cent",
     "diverging", "changes, growth or shrinkage", True, "0 %, no change"),
    ("the difference between a simulated and a measured temperature in each grid cell",
     "diverging", "errors, too warm or too cold", True, "0, perfect agreement"),
    ("the elevation relative to sea level on a map of a coast, from the sea floor to the hills",
     "diverging", "heights above and depths below the sea", True, "0, sea level"),
    ("the vorticity of a flow: positive for counter-clockwise, negative for clockwise rotation",
     "diverging", "rotations one way or the other", True, "0, no rotation"),
    ("the deviation of each pupil's test score from the class average", "diverging",
     "deviations above or below the average", True, "0, exactly the average"),
    ("the net migration of each region: the people moving in minus the people moving out",
     "diverging", "balances, gains or losses of people", True, "0, as many in as out"),
    ("the change of the thickness of a glacier since 1990, in metres", "diverging",
     "changes, thinner or thicker", True, "0, no change"),
    ("the electric potential around a positive and a negative charge (zero far away)",
     "diverging", "potentials, positive or negative", True, "0, the potential far away"),
    # qualitative: names, no order
    ("the land use of each parcel: forest, farmland, water, city", "qualitative",
     "names of land uses", False, None),
    ("the labels of a segmented scan: bone, muscle, fat, air", "qualitative",
     "names of tissues", False, None),
    ("the cluster number (1 to 6) that a clustering algorithm gave each point", "qualitative",
     "cluster numbers, mere names: cluster 4 is not 'more' than cluster 2", False, None),
    ("the political party that won each district", "qualitative", "names of parties", False, None),
    ("the soil type of each field: clay, sand, loam, peat", "qualitative",
     "names of soil types", False, None),
    ("the language spoken most at home in each region", "qualitative",
     "names of languages", False, None),
    ("the species of each tree in the tree register of a park", "qualitative",
     "names of species", False, None),
    ("the material of each part of a machine: steel, aluminium, plastic, rubber", "qualitative",
     "names of materials", False, None),
    ("the blood group of each patient of a study: A, B, AB or O", "qualitative",
     "names of blood groups", False, None),
    ("the company that runs each mobile phone mast", "qualitative", "names of companies",
     False, None),
    ("the country of origin of each parcel in a shipment", "qualitative",
     "names of countries", False, None),
    ("the make of each car in a car park", "qualitative", "names of car makes", False, None),
)

#: Data sets and the kind of colour map each needs.
SCENARIOS = tuple((text, kind) for text, kind, *_ in _SCENARIO_TABLE)
#: What the values of each data set are, whether they are ordered, and their centre (or None).
_SCENARIO_VALUES = {text: values for text, _, *values in _SCENARIO_TABLE}

_KIND_REASONS = {
    "sequential": "ordered values from low to high with no special value in between: a "
                  "sequential map, one hue or a perceptual map like viridis, its lightness rising "
                  "with the value",
    "diverging": "values on both sides of a meaningful centre (zero, the average): a diverging "
                 "map, two hues that meet in a light neutral colour at the centre, so that the "
                 "sign and the size of the deviation both show",
    "qualitative": "categories without any order: a qualitative map, clearly different hues of "
                   "similar lightness, so that no category looks like 'more' than another",
}


class ChooseMapKind(_Chapter10):
    r"""Which kind of colour map (sequential, diverging, qualitative) a data set needs.

    Attributes: ``scenario`` (the data set, in words), ``menu`` (:data:`MAP_KINDS`).

    Examples
    --------
    >>> ex = ChooseMapKind(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [k for k in MAP_KINDS if k != ex.expected][0]
    >>> ex.check(wrong).diagnosis == f"{wrong} instead of {ex.expected}"
    True
    >>> ex.check("rainbow").status
    'invalid'
    """

    title = "Choose the kind of colour map"
    answer_form = "custom"
    menu = MAP_KINDS

    def draw(self, rng):
        self.scenario, self.expected = pick(rng, SCENARIOS)

    def separated(self, mistakes):
        return True

    def hints(self):
        values, _, _ = _SCENARIO_VALUES[self.scenario]
        return [
            r"Two questions decide: do the values have an order (less and more)? And if so, is "
            r"there a special value in the middle, such as 0 or an average, with deviations on "
            r"both sides?",
            r"Categories without order need a *qualitative* map; ordered values without a special "
            r"middle a *sequential* one; ordered values around a meaningful centre a "
            r"*diverging* one.",
            f"Here the values are {values}. Is there an order, and is one value in the middle "
            "special?",
        ]

    def worked(self):
        values, ordered, centre = _SCENARIO_VALUES[self.scenario]
        if not ordered:
            kind = "qualitative"
            steps = [f"The values are {values}: categories, with no order.",
                     "Without an order, no colour may look like more than another: "
                     "distinct hues of similar lightness."]
        else:
            kind = "diverging" if centre is not None else "sequential"
            middle = (f"Yes: {centre}, with deviations on both sides of it." if centre
                      else "No: no value in between is special; the values simply run from "
                      "low to high.")
            steps = [f"The values are {values}: they are ordered.",
                     "Is there a meaningful centre? " + middle]
        steps.append(f"So the answer is **{kind}**: {_KIND_REASONS[kind].split(': ', 1)[1]}.")
        return Worked(steps, kind)

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        if not isinstance(answer, str) or answer.strip().lower() not in self.menu:
            return Feedback("invalid", "Answer with one of the strings "
                            + ", ".join(f"`'{k}'`" for k in self.menu) + ".", "unreadable")
        kind = answer.strip().lower()
        if kind == self.expected:
            return Feedback("correct", f"Right: these are {_KIND_REASONS[kind]}.")
        return Feedback("wrong", f"A {kind} map is meant for {_KIND_REASONS[kind].split(':')[0]}."
                        f" These data are {_KIND_REASONS[self.expected]}.",
                        f"{kind} instead of {self.expected}")

    def statement(self):
        return (
            rf"You are to show **{self.scenario}** on a map or in an image. Which kind of colour "
            r"map suits these data: a *sequential* map (one direction, light to dark), a "
            r"*diverging* map (two directions from a neutral centre) or a *qualitative* map "
            r"(distinct colours without order)?" "\n\n"
            r"**Answer:** one of the strings `'sequential'`, `'diverging'`, `'qualitative'`."
            "\n\n" + data_note("scenario", "menu"))


#: The exercises of chapter 10, in the order of the solutions notebook.
EXERCISES = (
    NormalizeValues,
    Denormalize,
    TransferValues,
    ThresholdBands,
    DesignOpacity,
    ColormapLookup,
    LightnessOfColour,
    MonotonicMaps,
    ChooseMapKind,
)
