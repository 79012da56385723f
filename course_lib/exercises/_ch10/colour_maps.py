"""Chapter 10 exercises: colour maps and lightness.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import numpy as np

from ... import colormaps as cm
from ..core import DECIMALS, Feedback, Mistake, Worked, data_note, pick, read_names
from . import _Chapter10, _num, _paren, _vec

__all__ = [
    "ColormapLookup",
    "LightnessOfColour",
    "MonotonicMaps",
]


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
