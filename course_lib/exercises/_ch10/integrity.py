"""Chapter 10 exercises: principles of good plots (textbook 10.4): the lie factor, the data-ink
ratio, banking to 45 degrees and the choice of a visual variable.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import numpy as np

from ... import format as fmt
from ...dataviz import integrity as gi
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, data_note,
                    has_placeholder, pick)
from . import _Chapter10

__all__ = [
    "VARIABLE_SCENARIOS",
    "BankingAspect",
    "ChooseVisualVariable",
    "DataInkRatio",
    "LieFactor",
]

_num = fmt.number
_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


def _n4(x):
    return fmt.number(float(x), 4)


def _and(names):
    """"a", "a and b", "a, b and c"."""
    names = list(names)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


# ---------------------------------------------------------------------------------------------
# The lie factor
# ---------------------------------------------------------------------------------------------

#: The graphics of the lie-factor question: kind -> (what is drawn, the power of the size).
_LIE_KINDS = {
    "truncated": "bars on a value axis that starts at a baseline above 0",
    "circle": "circles whose radius is proportional to the value",
    "icon": "icons (a picture of a coin) whose width and height are both proportional to the "
            "value",
    "cube": "cubes drawn in 3D whose edge is proportional to the value",
}
_POWER = {"truncated": 1, "circle": 2, "icon": 2, "cube": 3}


class LieFactor(_Chapter10):
    r"""Tufte's lie factor of a graphic that shows two yearly values.

    The effect of a change is :math:`|\text{second} - \text{first}| / |\text{first}|`; the lie
    factor is the effect the graphic shows (in the lengths of truncated bars, in the areas of
    circles or icons, in the volumes of cubes) over the effect in the data.

    Attributes: ``kind`` (``"truncated"``, ``"circle"``, ``"icon"``, ``"cube"``), ``years``,
    ``values`` (the two data values), ``baseline`` (where the bars start; 0 for the others).

    Examples
    --------
    >>> ex = LieFactor(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(1.0).status
    'wrong'
    """

    title = "The lie factor of a graphic"
    answer_form = "number"
    what = "the lie factor"
    advice = (r"Lie factor = (relative change of the drawn sizes) / (relative change of the "
              r"data), each relative change being $|\text{second} - \text{first}| / "
              r"\text{first}$; the drawn size is the length, area or volume the reader sees.")

    _PAIRS = ((20, 25), (40, 50), (40, 60), (50, 60), (50, 75), (80, 100), (20, 30), (60, 75),
              (25, 30), (100, 120), (10, 15), (30, 45), (80, 120), (50, 40), (60, 45),
              (100, 80), (40, 30), (120, 150), (200, 250), (16, 20))

    def draw(self, rng):
        self.kind = str(pick(rng, tuple(_LIE_KINDS)))
        v1, v2 = pick(rng, self._PAIRS)
        self.values = (float(v1), float(v2))
        year = int(rng.integers(2005, 2020))
        self.years = (year, year + int(pick(rng, (1, 2, 5))))
        if self.kind == "truncated":
            low = min(v1, v2)
            options = [b for b in (5, 10, 15, 20, 25, 30, 40, 50, 60, 75, 80, 90, 100)
                       if b < low and b >= 0.3 * low]
            self.baseline = float(pick(rng, options)) if options else 0.0
        else:
            self.baseline = 0.0
        self.expected = float(gi.encoding_lie_factor(
            list(self.values), {"truncated": "bar", "circle": "radius", "icon": "icon",
                                "cube": "volume"}[self.kind], baseline=self.baseline))

    def acceptable(self):
        return self.kind != "truncated" or self.baseline > 0

    def _sizes(self):
        v1, v2 = self.values
        if self.kind == "truncated":
            return v1 - self.baseline, v2 - self.baseline
        p = _POWER[self.kind]
        return v1 ** p, v2 ** p

    def mistakes(self):
        v1, v2 = self.values
        s1, s2 = self._sizes()
        e = abs(v2 - v1) / v1
        found = [
            Mistake((s2 / s1) / (v2 / v1), r"You divided the **ratios** second/first. The lie "
                    r"factor compares **relative changes**: $|\text{second} - \text{first}| / "
                    r"\text{first}$ for the drawing over the same for the data.",
                    "ratio instead of relative change"),
            Mistake(e / (abs(s2 - s1) / s1), r"That is the effect in the data over the effect "
                    r"shown: the lie factor is the other way round, shown over data (above 1 "
                    r"when the graphic exaggerates).", "inverted"),
            Mistake((abs(s2 - s1) / s2) / (abs(v2 - v1) / v2), r"You took the changes relative "
                    r"to the **second** value. The effect of a change is measured from where it "
                    r"starts: relative to the first (earlier) value.",
                    "relative to the second value"),
        ]
        if self.kind == "truncated":
            found.append(Mistake(1.0, r"You measured the bars from 0. On a truncated axis the "
                                 r"bars start at the baseline, so their drawn lengths are "
                                 r"value − baseline: that is what the reader compares.",
                                 "bars from 0"))
        else:
            found.append(Mistake(1.0, r"You compared the values as if they were drawn "
                                 r"honestly. Scaling "
                                 + ("the radius" if self.kind == "circle" else "every side")
                                 + r" by the value scales the "
                                 + ("volume" if self.kind == "cube" else "area")
                                 + r" the reader sees by the value's "
                                 + ("cube" if self.kind == "cube" else "square") + ".",
                                 "size not raised to a power"))
        if self.kind == "cube":
            found.append(Mistake(abs((v2 / v1) ** 2 - 1) / e, r"You used the area of a face "
                                 r"($\text{edge}^2$). A cube drawn in 3D is read as a "
                                 r"volume: its size grows with the **cube** of the edge.",
                                 "area instead of volume"))
        return found

    def statement(self):
        (y1, y2), (v1, v2) = self.years, self.values
        what = _LIE_KINDS[self.kind]
        base = (rf" The value axis starts at ${_num(self.baseline)}$, and the bars are drawn "
                r"from there." if self.kind == "truncated" else "")
        return (
            rf"A graphic shows the value ${_num(v1)}$ of {y1} and the value ${_num(v2)}$ of "
            rf"{y2} as {what}.{base} What is the lie factor of the graphic (Tufte: the size "
            r"of the effect shown in the graphic divided by the size of the effect in the "
            r"data)? Readers compare the sizes they see: the lengths of bars, the areas of "
            r"flat shapes, the volumes of solids." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("kind", "years", "values", "baseline"))

    def hints(self):
        v1, v2 = self.values
        size = {"truncated": "the bar's length above the baseline, value − baseline",
                "circle": r"the circle's area, $\pi r^2$, so value$^2$ (π cancels)",
                "icon": "the icon's area, width × height, so value$^2$",
                "cube": "the cube's volume, edge$^3$, so value$^3$"}[self.kind]
        return [
            r"The effect of a change is $|\text{second} - \text{first}| / \text{first}$. "
            r"Compute it once for the data and once for the sizes drawn.",
            f"The size the reader compares here is {size}.",
            rf"Data effect: $|{_num(v2)} - {_num(v1)}| / {_num(v1)} = "
            rf"{_n4(abs(v2 - v1) / v1)}$. Now the drawn sizes, then divide shown by data.",
        ]

    def worked(self):
        v1, v2 = self.values
        e_data = abs(v2 - v1) / v1
        if self.kind == "truncated":
            b = self.baseline
            s1, s2 = v1 - b, v2 - b
            sizes = (rf"The bars are drawn from ${_num(b)}$: lengths "
                     rf"${_num(v1)} - {_num(b)} = {_num(s1)}$ and "
                     rf"${_num(v2)} - {_num(b)} = {_num(s2)}$.")
        else:
            p = _POWER[self.kind]
            s1, s2 = v1 ** p, v2 ** p
            word = {1: "", 2: "area", 3: "volume"}[p]
            sizes = (rf"The reader compares the {word}: proportional to value$^{p}$, "
                     rf"${_num(v1)}^{p} = {_num(s1)}$ and ${_num(v2)}^{p} = {_num(s2)}$.")
        e_shown = abs(s2 - s1) / s1
        answer = e_shown / e_data
        return Worked([
            rf"Effect in the data: $|{_num(v2)} - {_num(v1)}| / {_num(v1)} = {_n4(e_data)}$.",
            sizes,
            rf"Effect shown: $|{_num(s2)} - {_num(s1)}| / {_num(s1)} = {_n4(e_shown)}$.",
            rf"Lie factor $= {_n4(e_shown)} / {_n4(e_data)} = {_n4(answer)}$"
            + (" (honest would be 1)." if abs(answer - 1) > 1e-9 else "."),
        ], answer)


# ---------------------------------------------------------------------------------------------
# The data-ink ratio
# ---------------------------------------------------------------------------------------------

#: Chart elements: name -> whether it is data ink.
_DATA_ELEMENTS = ("the bars (their front faces)", "the data line", "the data points")
_OTHER_ELEMENTS = ("the grid lines", "the frame around the plot", "the background fill",
                   "the drop shadows", "the decorative picture behind the bars",
                   "the tick marks", "the axis lines", "the legend box")
_SIDES = "the 3D side and top faces of the bars"


class DataInkRatio(_Chapter10):
    r"""Tufte's data-ink ratio of a chart from the ink of its elements, or after erasing some.

    Data ink is the ink that shows the data values (bars, a data line, points); the rest
    (grid, frame, fills, shadows, 3D faces, decoration) could be erased without losing data.

    Attributes: ``elements`` (name -> ink, in cm² of printed ink), ``data`` (the names of the
    data-ink elements), ``erase`` (the elements a designer erases; empty: the chart as it is).

    Examples
    --------
    >>> ex = DataInkRatio(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The data-ink ratio"
    answer_form = "number"
    what = "the data-ink ratio"
    advice = (r"Data-ink ratio = (ink of the elements that show data values) / (all the ink "
              r"left in the chart).")

    def draw(self, rng):
        data_name = str(pick(rng, _DATA_ELEMENTS))
        k = int(rng.integers(3, 5))
        others = [str(o) for o in rng.choice(_OTHER_ELEMENTS, size=k, replace=False)]
        if data_name.startswith("the bars") and rng.random() < 0.6:
            others[int(rng.integers(k))] = _SIDES
        amounts = rng.choice(np.arange(2, 21) * 5, size=k + 1, replace=False)
        self.elements = {data_name: float(amounts[0])}
        self.elements.update({o: float(a) for o, a in zip(others, amounts[1:])})
        self.data = (data_name,)
        if rng.random() < 0.5:
            n_erase = int(rng.integers(1, k))
            chosen = rng.choice(others, size=n_erase, replace=False)
            self.erase = tuple(o for o in others if o in set(chosen.tolist()))
        else:
            self.erase = ()
        budget = gi.ink_budget({name: (ink, name in self.data) for name, ink in
                                self.elements.items() if name not in self.erase})
        self.expected = float(budget["ratio"])

    def _totals(self):
        d = sum(self.elements[n] for n in self.data)
        kept = sum(ink for n, ink in self.elements.items() if n not in self.erase)
        return d, kept

    def mistakes(self):
        d, t = self._totals()
        found = [
            Mistake(d / (t - d), r"You divided the data ink by the **non-data** ink. The ratio "
                    r"is data ink over the **total** ink (data ink included), so it lies "
                    r"between 0 and 1.", "over non-data ink"),
            Mistake(1 - d / t, r"That is the share of **non-data** ink (what could be "
                    r"erased). The data-ink ratio is the share of the ink that shows data.",
                    "non-data share"),
        ]
        if _SIDES in self.elements and _SIDES not in self.erase:
            s = self.elements[_SIDES]
            found.append(Mistake((d + s) / t, r"You counted the 3D side and top faces as data "
                                 r"ink. They repeat the bar's height without adding any "
                                 r"value: non-data ink (erasing them loses nothing).",
                                 "3D faces counted as data"))
        if self.erase:
            total = sum(self.elements.values())
            found.append(Mistake(d / total, r"You kept the erased elements in the total. After "
                                 r"erasing, the total ink is only what is left.",
                                 "erased ink still counted"))
        return found

    def statement(self):
        rows = "\n".join(f"| {name} | {_num(ink)} |" for name, ink in self.elements.items())
        task = ("What is the data-ink ratio of the chart?" if not self.erase else
                "A designer erases " + _and(self.erase) + ". What is the data-ink ratio of the "
                "chart afterwards?")
        return (
            "A chart is printed with the amounts of ink below (in cm²). Count as **data ink** "
            "only the ink that shows the data values (the bars' front faces, a data line, data "
            "points); everything else is non-data ink.\n\n"
            "| element | ink (cm²) |\n|---|---|\n" + rows + "\n\n" + task + "\n\n"
            + _ONE_NUMBER + "\n\n" + data_note("elements", "data", "erase"))

    def hints(self):
        d, t = self._totals()
        return [
            "Data-ink ratio = data ink / total ink. Which element shows the data values "
            "themselves? Everything else could be erased without losing a value.",
            f"The data ink is {self.data[0]}: {_num(d)} cm². Only the bars' front faces, a "
            "data line or points count; 3D faces, shadows and fills do not.",
            ("Add up all the ink that is left after erasing; " if self.erase else
             "Add up all the ink of the chart; ") + "that is the denominator.",
        ]

    def worked(self):
        d = sum(self.elements[n] for n in self.data)
        kept = [(n, ink) for n, ink in self.elements.items() if n not in self.erase]
        total = sum(ink for _, ink in kept)
        steps = [f"Data ink: {self.data[0]}, ${_num(d)}$ cm²."]
        if self.erase:
            steps.append("Erased: " + _and(self.erase) + "; their ink leaves the total.")
        steps.append("Total ink left: $" + " + ".join(_num(ink) for _, ink in kept)
                     + f" = {_num(total)}$ cm².")
        answer = d / total
        steps.append(rf"Data-ink ratio $= {_num(d)} / {_num(total)} = {_n4(answer)}$.")
        return Worked(steps, answer)


# ---------------------------------------------------------------------------------------------
# Banking to 45 degrees
# ---------------------------------------------------------------------------------------------

class BankingAspect(_Chapter10):
    r"""The aspect ratio (height / width) that banks a small line chart to 45 degrees by the
    median absolute slope (Cleveland).

    With the data rectangle of ranges :math:`R_x, R_y` drawn :math:`\alpha` times as high as
    wide, a segment appears with slope :math:`\alpha\, s_i`, where
    :math:`s_i = (|\Delta y_i| / R_y) / (|\Delta x_i| / R_x)`; banking makes the median of
    these 1: :math:`\alpha = 1 / \operatorname{median}_i s_i`.

    Attributes: ``x`` (years), ``y`` (values).

    Examples
    --------
    >>> ex = BankingAspect(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Banking to 45 degrees"
    answer_form = "number"
    what = "the aspect ratio"
    advice = (r"Divide every $|\Delta y|$ by the y range and every $\Delta x$ by the x range; "
              r"the slopes $s_i$ of the segments in that unit square have a median $m$, and "
              r"the aspect ratio (height / width) is $1/m$.")

    def draw(self, rng):
        n_seg = int(pick(rng, (5, 7)))
        step = int(pick(rng, (1, 2)))
        start = int(rng.integers(1990, 2016))
        self.x = start + step * np.arange(n_seg + 1)
        scale = int(pick(rng, (1, 2, 5, 10)))
        while True:
            moves = rng.integers(1, 7, size=n_seg) * rng.choice([-1, 1], size=n_seg)
            y = np.concatenate([[0], np.cumsum(moves)])
            if np.ptp(y) >= 3:
                break
        base = int(rng.integers(2, 20)) * scale * 5
        self.y = (base + scale * (y - y.min())).astype(float)
        self.x = self.x.astype(float)
        self.expected = float(gi.bank_to_45(self.x, self.y, "median"))

    def acceptable(self):
        a = self.expected
        # a median that is a plain fraction, and a result that is not too extreme
        return 0.1 <= a <= 10 and abs(a * 100 - round(a * 100)) < 1e-9

    def _slopes(self):
        rx, ry = np.ptp(self.x), np.ptp(self.y)
        return (np.abs(np.diff(self.y)) / ry) / (np.abs(np.diff(self.x)) / rx)

    def mistakes(self):
        s = self._slopes()
        raw = np.abs(np.diff(self.y)) / np.abs(np.diff(self.x))
        signed = (np.diff(self.y) / np.ptp(self.y)) / (np.diff(self.x) / np.ptp(self.x))
        found = [
            Mistake(float(np.median(s)), r"That is width / height. Banking makes the median "
                    r"slope 1 on screen: $\alpha\,m = 1$, so the aspect ratio height / width is "
                    r"$1/m$.", "width over height"),
            Mistake(1 / float(np.median(raw)), r"You used the raw slopes $\Delta y / \Delta x$ in "
                    r"data units. The slope on screen depends on how the ranges are drawn: "
                    r"divide $\Delta y$ by the y range and $\Delta x$ by the x range first.",
                    "ranges not used"),
            Mistake(1 / float(np.mean(s)), r"You used the mean slope. This banking uses the "
                    r"**median** of the absolute slopes (one very steep segment would dominate "
                    r"a mean).", "mean instead of median"),
        ]
        m = float(np.median(signed))
        if m != 0:
            found.append(Mistake(1 / abs(m), r"You took the median of the **signed** slopes. "
                                 r"Banking uses the absolute slopes: a fall is as steep as a "
                                 r"rise.", "signed slopes"))
        return found

    def statement(self):
        rows = " | ".join(_num(v) for v in self.y)
        head = " | ".join(str(int(v)) for v in self.x)
        return (
            r"A line chart connects these yearly values by straight segments:" "\n\n"
            f"| year | {head} |\n|---|" + "---|" * len(self.x) + f"\n| value | {rows} |\n\n"
            r"The plot's data rectangle spans exactly the ranges of the years and of the "
            r"values. Bank the chart to 45° by the **median absolute slope**: which aspect "
            r"ratio $\alpha$ = height / width of the data rectangle makes the median of the "
            r"segments' absolute slopes on screen equal to 1?" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("x", "y"))

    def hints(self):
        rx, ry = np.ptp(self.x), np.ptp(self.y)
        return [
            r"On screen the data rectangle is $\alpha$ times as high as wide, so a segment's "
            r"slope is $\alpha \cdot s_i$ with $s_i = (|\Delta y_i| / R_y) / "
            r"(\Delta x_i / R_x)$, its slope in the unit square.",
            rf"Here $R_x = {_num(rx)}$ and $R_y = {_num(ry)}$. Compute the {len(self.x) - 1} "
            r"values $s_i$ and take their median $m$.",
            r"The median slope on screen is $\alpha m$; set it to 1.",
        ]

    def worked(self):
        rx, ry = np.ptp(self.x), np.ptp(self.y)
        dx, dy = np.abs(np.diff(self.x)), np.abs(np.diff(self.y))
        s = (dy / ry) / (dx / rx)
        m = float(np.median(s))
        answer = 1.0 / m
        return Worked([
            rf"Ranges: $R_x = {_num(rx)}$, $R_y = {_num(ry)}$; $|\Delta y|$ = "
            + ", ".join(_num(v) for v in dy) + r", $\Delta x$ = " + _num(dx[0]) + ".",
            r"Slopes in the unit square $s_i = (|\Delta y_i| / R_y)(R_x / \Delta x_i)$: "
            + ", ".join(_n4(v) for v in s) + ".",
            rf"Median: $m = {_n4(m)}$ (sorted: "
            + ", ".join(_n4(v) for v in np.sort(s, kind="stable")) + ").",
            rf"$\alpha\,m = 1$: $\alpha = 1 / {_n4(m)} = {_n4(answer)}$.",
        ], answer)


# ---------------------------------------------------------------------------------------------
# Choosing a visual variable
# ---------------------------------------------------------------------------------------------

#: Data attributes to show when position is already taken: (where the marks are drawn, the
#: attribute, its level of measurement).
VARIABLE_SCENARIOS = (
    ("districts on a map", "the party that won each district", "nominal"),
    ("trees drawn as points on a map of a park", "the species of each tree", "nominal"),
    ("countries in a scatterplot of income against life expectancy",
     "the continent of each country", "nominal"),
    ("patients in a scatterplot of age against blood pressure",
     "the blood group of each patient", "nominal"),
    ("parcels on a map", "the land use of each parcel: forest, field, water or town",
     "nominal"),
    ("cars in a scatterplot of price against fuel use", "the brand of each car", "nominal"),
    ("software projects in a scatterplot of size against age",
     "the programming language of each project", "nominal"),
    ("faults on a geological map", "the type of each fault", "nominal"),
    ("pupils in a scatterplot of hours studied against absences",
     "the grade of each pupil, from A to F", "ordinal"),
    ("districts on a flood map", "the risk level of each district: low, medium, high, severe",
     "ordinal"),
    ("shops on a city map", "the customer satisfaction of each shop, from very unhappy to "
     "very happy", "ordinal"),
    ("storm tracks on a map", "the hurricane category of each storm, 1 to 5", "ordinal"),
    ("people in a scatterplot of age against income",
     "the highest education level of each person", "ordinal"),
    ("air-quality stations on a map", "the air-quality class of each station: good, "
     "moderate, poor, very poor", "ordinal"),
    ("restaurants on a city map", "the star rating of each restaurant, 1 to 5 stars",
     "ordinal"),
    ("hotels on a map of a coast", "the class of each hotel: budget, standard, superior, "
     "luxury", "ordinal"),
    ("cities on a map", "the population of each city", "quantitative"),
    ("weather stations on a map", "the rainfall measured at each station, in mm",
     "quantitative"),
    ("players in a scatterplot of age against salary", "the number of goals of each player",
     "quantitative"),
    ("countries in a scatterplot of income against life expectancy",
     "the population of each country", "quantitative"),
    ("airports on a map", "the number of passengers of each airport per year",
     "quantitative"),
    ("earthquakes on a map", "the energy released by each earthquake", "quantitative"),
    ("patients in a scatterplot of age against blood pressure", "the weight of each patient",
     "quantitative"),
    ("shops on a city map", "the yearly sales of each shop, in euros", "quantitative"),
)

_LEVEL_WORDS = {"nominal": "categories without any order",
                "ordinal": "ordered classes, without meaningful differences or ratios",
                "quantitative": "amounts, whose differences and ratios mean something"}


def _menu_for(level, rng):
    """The right variable and three distractors that are clearly worse for `level` (none whose
    place against the right one is disputed between Bertin and Mackinlay)."""
    if level == "quantitative":
        right, pool = "size", ["value", "texture", "colour hue", "shape"]
    elif level == "ordinal":
        right, pool = "value", ["size", "texture", "orientation", "colour hue", "shape"]
    else:
        right = str(pick(rng, ("colour hue", "shape")))
        pool = ["value", "size", "orientation"] + (["texture"] if right == "colour hue"
                                                   else [])
    distractors = [str(v) for v in rng.choice(pool, size=3, replace=False)]
    menu = [right] + distractors
    order = rng.permutation(4)
    return right, tuple(menu[i] for i in order)


class ChooseVisualVariable(_Chapter10):
    r"""Choose the visual variable that suits a data attribute, when position is taken.

    Attributes: ``where`` (what the marks are and where they are drawn), ``attribute`` (what to
    show), ``level`` (nominal, ordinal or quantitative), ``menu`` (four of Bertin's visual
    variables; exactly one clearly suits the level). A wrong choice is diagnosed as
    ``"<variable> for <level> data"`` and told why it misleads.

    Examples
    --------
    >>> ex = ChooseVisualVariable(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [v for v in ex.menu if v != ex.expected][0]
    >>> ex.check(wrong).diagnosis == f"{wrong} for {ex.level} data"
    True
    """

    title = "Choose a visual variable"
    answer_form = "custom"

    def draw(self, rng):
        self.where, self.attribute, self.level = pick(rng, VARIABLE_SCENARIOS)
        self.expected, self.menu = _menu_for(self.level, rng)

    def separated(self, mistakes):
        return True

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        form = "Answer with one of the strings " + ", ".join(f"`'{v}'`" for v in self.menu) + "."
        if not isinstance(answer, str):
            return Feedback("invalid", form, "unreadable")
        try:
            chosen = gi.visual_variable_name(answer)
        except ValueError:
            return Feedback("invalid", form, "unreadable")
        quality, why = gi.suitability(chosen, self.level)
        if chosen not in self.menu:
            return Feedback("invalid", f"“{chosen}” is not among the choices. " + form,
                            "unreadable")
        right_why = gi.suitability(self.expected, self.level)[1]
        if chosen == self.expected:
            return Feedback("correct", f"Right: {self.attribute} is {self.level} data, and "
                            f"{chosen} suits it: {right_why}.")
        return Feedback("wrong", f"{self.attribute[0].upper() + self.attribute[1:]} is "
                        f"{self.level} data ({_LEVEL_WORDS[self.level]}). {chosen.capitalize()} "
                        f"is {quality} for it: {why}. Better: {self.expected}, {right_why}.",
                        f"{chosen} for {self.level} data")

    def statement(self):
        options = ", ".join(f"`'{v}'`" for v in self.menu)
        return (
            rf"You draw {self.where}, so position is already taken. You also want to show "
            rf"**{self.attribute}**. Which of Bertin's visual variables {options} suits this "
            r"attribute best (think of the kind of data first: nominal, ordinal or "
            r"quantitative)?"
            + (" (*Value* is Bertin's word for lightness, light to dark.)" if "value" in
               self.menu else "") + "\n\n"
            r"**Answer:** one of the strings " + options + ".\n\n"
            + data_note("where", "attribute", "menu"))

    def hints(self):
        return [
            "First decide the kind of data: categories without order (nominal), ordered "
            "classes (ordinal), or amounts (quantitative).",
            "Then ask which variables the eye reads as ordered (size, lightness, texture "
            "density) and which only as different (hue, shape, orientation); and which show "
            "amounts (size).",
            f"{self.attribute[0].upper() + self.attribute[1:]}: these are "
            f"{_LEVEL_WORDS[self.level]}.",
        ]

    def worked(self):
        rows = gi.visual_variables_for(self.level)
        ranked = [v for v, _, _ in rows if v in self.menu]
        best = ranked[0]
        quality = {v: q for v, q, _ in rows}
        return Worked([
            f"{self.attribute[0].upper() + self.attribute[1:]} is **{self.level}** data: "
            f"{_LEVEL_WORDS[self.level]}.",
            "How the choices suit it: " + "; ".join(f"{v}: {quality[v]}" for v in ranked) + ".",
            f"The best is **{best}**: {gi.suitability(best, self.level)[1]}.",
        ], best)
