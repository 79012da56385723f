r"""Chapter 10 exercises: data aspects (levels of measurement, grids) and scattered data.

Five kinds of exam question on section 10.3: the level of measurement of a table's attributes;
the kind of grid a described data set lives on; the memory a grid of each kind needs; Shepard's
inverse-distance weighting by hand; nearest-neighbour against linear interpolation at a point
of a small triangulation. The expected answers come from :mod:`course_lib.dataviz`.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import math

import numpy as np

from ...dataviz import data_types, grids, scattered
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, data_note,
                    has_placeholder, pick)
from . import _Chapter10, _num

__all__ = [
    "GRID_SCENARIOS",
    "ChooseGridKind",
    "ClassifyLevels",
    "GridMemory",
    "NearestVsLinear",
    "ShepardByHand",
]

_ONE_NUMBER = "**Answer:** one number. " + DECIMALS


# ---------------------------------------------------------------------------------------------
# Levels of measurement
# ---------------------------------------------------------------------------------------------

#: The tempting wrong level of each catalogued attribute, and the slip it is: group key ->
#: (wrong level, why it is wrong, the attributes of the group).
_LEVEL_SLIPS = {
    "labels read as numbers": (
        "interval", "its digits are a label, not an amount: a larger code is not more of "
        "anything, and the difference or the average of two codes means nothing. Codes that "
        "only name things are **nominal**, whatever symbols they are written with",
        ("postcode", "telephone number", "player's shirt number")),
    "order invented": (
        "ordinal", "these categories have no order (any order of listing them is a convention, "
        "like the alphabet); only equal or not equal means something: **nominal**",
        ("blood group (A, B, AB, O)", "land-use class", "country of birth")),
    "order ignored": (
        "nominal", "the categories are words, but they are ordered (better, worse; more, "
        "less), so the median and 'at least' questions mean something: **ordinal**",
        ("school grade (A to F)", "pain level (none, mild, moderate, severe)")),
    "ranks read as amounts": (
        "interval", "the numbers only give an order; nothing says the steps between them are "
        "equal (the gap between 1st and 2nd place, or between 'agree' and 'strongly agree', "
        "is not a fixed amount), so differences and means are not meaningful: **ordinal**",
        ("finishing place in a race (1st, 2nd, ...)",
         "answer on a scale 'disagree' to 'agree' (1 to 5)", "hurricane category (1 to 5)",
         "hardness on the Mohs scale")),
    "no true zero": (
        "ratio", "its zero is a convention, not the absence of the quantity, so ratios mean "
        "nothing (20 °C is not twice as warm as 10 °C: in °F they are 68 and 50); differences "
        "do mean something: **interval**",
        ("temperature in °C", "temperature in °F", "calendar year",
         "time of day on a 24-hour clock", "longitude in degrees")),
    "true zero missed": (
        "interval", "zero means none of the quantity, so ratios are meaningful too (twice as "
        "much): **ratio**, the strongest level",
        ("temperature in kelvin", "mass in kg", "height of a person in cm",
         "number of children in a household", "income in euros",
         "duration of a phone call in seconds", "rainfall in mm per year",
         "wind speed in m/s")),
}
_SLIP_OF = {attr: (key, wrong, why) for key, (wrong, why, attrs) in _LEVEL_SLIPS.items()
            for attr in attrs}
#: The answers to the three questions for each level (ordered, equal intervals, true zero).
_PROPERTIES = {"nominal": (False, False, False), "ordinal": (True, False, False),
               "interval": (True, True, False), "ratio": (True, True, True)}


def _yes(flag):
    return "yes" if flag else "no"


class ClassifyLevels(_Chapter10):
    r"""The level of measurement (nominal, ordinal, interval, ratio) of four attributes.

    The answer is the list of the four levels in the table's order. Each attribute comes from a
    different group of typical slips (codes read as numbers, an order invented or ignored, ranks
    read as amounts, a zero that is no true zero, a true zero missed); a single wrong level is
    diagnosed by its group's name, several by ``"several levels wrong"``.

    Attributes: ``attributes`` (the four names), ``menu`` (the levels).

    Examples
    --------
    >>> ex = ClassifyLevels(seed=0)
    >>> ex.check(list(ex.expected)).status
    'correct'
    >>> wrong = list(ex.expected)
    >>> key, level, _ = _SLIP_OF[ex.attributes[0]]
    >>> wrong[0] = level
    >>> ex.check(wrong).diagnosis == key
    True
    >>> ex.check(["nominal"]).status
    'invalid'
    """

    title = "Levels of measurement"
    answer_form = "custom"
    menu = tuple(data_types.LEVELS)

    def draw(self, rng):
        groups = list(_LEVEL_SLIPS)
        chosen = [groups[i] for i in rng.choice(len(groups), size=4, replace=False)]
        self.attributes = tuple(pick(rng, _LEVEL_SLIPS[g][2]) for g in chosen)
        self.expected = [data_types.ATTRIBUTE_EXAMPLES[a][0] for a in self.attributes]

    def acceptable(self):
        return len(set(self.expected)) >= 3

    def separated(self, mistakes):
        return True

    def _read(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        form = (f"Give a list of {len(self.attributes)} levels in the table's order, each one "
                "of " + ", ".join(f"`'{m}'`" for m in self.menu) + ".")
        if isinstance(answer, (str, bytes, dict)) or not isinstance(answer, (list, tuple)) \
                or len(answer) != len(self.attributes) \
                or not all(isinstance(a, str) for a in answer):
            return Feedback("invalid", form, "unreadable")
        levels = [a.strip().lower() for a in answer]
        unknown = [a for a in levels if a not in self.menu]
        if unknown:
            return Feedback("invalid", f"{unknown[0]!r} is not a level. " + form, "unreadable")
        return levels

    def _why(self, attribute, level):
        """Why `attribute` is not at `level` (its anticipated slip or the general reason)."""
        right, reason = data_types.ATTRIBUTE_EXAMPLES[attribute]
        key, wrong, why = _SLIP_OF[attribute]
        if level == wrong:
            return key, f"**{attribute}** is not {level}: {why}."
        return "wrong level", (f"**{attribute}** is not {level} but **{right}**: {reason}.")

    def _check(self, answer):
        levels = self._read(answer)
        if isinstance(levels, Feedback):
            return levels
        wrong = [k for k, (a, b) in enumerate(zip(levels, self.expected)) if a != b]
        if not wrong:
            return Feedback("correct", "All four levels are right.")
        reasons = [self._why(self.attributes[k], levels[k]) for k in wrong]
        credit = 1 - len(wrong) / len(self.attributes)
        key = reasons[0][0] if len(wrong) == 1 else "several levels wrong"
        return Feedback("wrong", " ".join(text for _, text in reasons), key, credit=credit)

    def hints(self):
        first = self.attributes[0]
        return [
            r"Ask three questions of each attribute: (1) do its values have an order? "
            r"(2) are equal differences equal amounts? (3) is zero a true zero, the absence "
            r"of the quantity? Each 'no' stops you at nominal, ordinal or interval.",
            r"The classic traps: numbers that are only labels (codes), ranks written as "
            r"numbers, and scales whose zero is a convention (°C, calendar years).",
            f"For example '{first}': {data_types.ATTRIBUTE_EXAMPLES[first][1]}. Now the "
            "others.",
        ]

    def worked(self):
        steps, answer = [], []
        for attribute in self.attributes:
            level, reason = data_types.ATTRIBUTE_EXAMPLES[attribute]
            ordered, intervals, zero = _PROPERTIES[level]
            found = data_types.measurement_level(ordered=ordered, equal_intervals=intervals,
                                                 true_zero=zero)
            asked = [f"ordered? {_yes(ordered)}"]
            if ordered:
                asked.append(f"equal intervals? {_yes(intervals)}")
            if intervals:
                asked.append(f"true zero? {_yes(zero)}")
            steps.append(f"**{attribute}**: " + "; ".join(asked) + f" ({reason}): "
                         f"**{found}**.")
            answer.append(found)
        return Worked(steps, answer)

    def statement(self):
        rows = "\n".join(f"| {k + 1} | {a} |" for k, a in enumerate(self.attributes))
        return (
            r"A data set has the four attributes below. Give the **level of measurement** of "
            r"each: *nominal* (categories), *ordinal* (ordered categories), *interval* "
            r"(meaningful differences, arbitrary zero) or *ratio* (meaningful ratios, a true "
            r"zero)." "\n\n| | attribute |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** a list of four strings in the table's order, e.g. "
            r"`['nominal', 'ordinal', 'ratio', 'interval']`." "\n\n"
            + data_note("attributes", "menu"))


# ---------------------------------------------------------------------------------------------
# Kinds of grid
# ---------------------------------------------------------------------------------------------

#: Data sets and their grids: (description, kind, explicit cells?, a lattice?, axis-parallel
#: lines?, even spacing along each axis?), typed out one by one.
_GRID_TABLE = (
    ("a CT scan of 512 x 512 x 300 voxels, 0.5 mm apart within a slice and 1 mm between "
     "slices", "uniform", False, True, True, True),
    ("a digital photograph of 4000 x 3000 pixels", "uniform", False, True, True, True),
    ("a room's temperature simulated at the points of a 50 x 50 x 20 lattice, 10 cm apart",
     "uniform", False, True, True, True),
    ("a satellite image resampled to pixels of 30 m x 30 m", "uniform", False, True, True,
     True),
    ("a climate model's output every 1° of longitude and every 1° of latitude, stored as the "
     "first corner, the step and the number of steps", "uniform", False, True, True, True),
    ("a wind-tunnel simulation on straight, axis-parallel grid lines that are packed closely "
     "near the wing and spread out far from it", "rectilinear", False, True, True, False),
    ("an ocean model on a regular 0.25° horizontal raster with 40 depth levels, a few metres "
     "apart near the surface and hundreds of metres apart at depth", "rectilinear", False,
     True, True, False),
    ("measurements of a material at the times 0, 1, 2, 5, 10 and 30 minutes and the "
     "temperatures 20, 40, 80 and 160 °C, every time with every temperature", "rectilinear",
     False, True, True, False),
    ("a weather model on a 1 km horizontal raster with 30 vertical levels at heights that "
     "grow with altitude", "rectilinear", False, True, True, False),
    ("the flow around a cylinder computed on a polar lattice of rings and rays, the x and y "
     "coordinates of every node stored", "curvilinear", False, True, False, False),
    ("a terrain-following atmosphere model: an i, j, k lattice whose lowest layer is bent to "
     "hug the mountains, every node with its own position", "curvilinear", False, True, False,
     False),
    ("blood flow in a bent artery, computed on a structured i, j, k lattice bent along the "
     "vessel", "curvilinear", False, True, False, False),
    ("an ocean model whose lattice is bent to follow the coastline, with the coordinates of "
     "each node stored", "curvilinear", False, True, False, False),
    ("a finite-element model of a bracket made of tetrahedra, each listed by the indices of its "
     "four corners", "unstructured", True, False, False, False),
    ("a triangle mesh of a scanned statue with a temperature at each vertex, the triangles "
     "listed by their corners", "unstructured", True, False, False, False),
    ("a car-crash simulation on a mixture of hexahedra and tetrahedra listed cell by cell",
     "unstructured", True, False, False, False),
    ("a terrain stored as a triangulated irregular network (TIN): height samples and the "
     "triangles between them", "unstructured", True, False, False, False),
    ("a simulation on triangles refined around a crack, small near it and large far away, "
     "each triangle given by its corner indices", "unstructured", True, False, False, False),
    ("air-quality readings from 120 stations spread over a city, each with its coordinates",
     "scattered", False, False, False, False),
    ("depths sounded by a ship along its zigzag course, each with its GPS position",
     "scattered", False, False, False, False),
    ("ore concentrations measured in boreholes drilled wherever access allowed",
     "scattered", False, False, False, False),
    ("bird counts reported by volunteers, each with the GPS position of the sighting",
     "scattered", False, False, False, False),
    ("the readings of rain gauges in gardens across a region, with their addresses geocoded",
     "scattered", False, False, False, False),
)

#: Data sets and the kind of grid each lives on.
GRID_SCENARIOS = tuple((text, kind) for text, kind, *_ in _GRID_TABLE)
_GRID_FACTS = {text: facts for text, _, *facts in _GRID_TABLE}
_KIND_WORDS = {
    "uniform": "a uniform grid stores only an origin, a spacing and a count per axis: every "
               "sample on evenly spaced, axis-parallel lines",
    "rectilinear": "a rectilinear grid has axis-parallel lines whose spacing varies along an "
                   "axis: one coordinate array per axis",
    "curvilinear": "a curvilinear grid keeps the i, j(, k) lattice (neighbours are implicit) "
                   "but bends it: a position per sample",
    "unstructured": "an unstructured grid lists its cells explicitly, each by the indices of "
                    "its corners",
    "scattered": "scattered data have positions only, with no cells and no lattice",
}


class ChooseGridKind(_Chapter10):
    r"""Which kind of grid (uniform, rectilinear, curvilinear, unstructured, scattered) a
    described data set lives on.

    Attributes: ``scenario`` (the data set, in words), ``menu`` (:data:`grids.GRID_KINDS`).

    Examples
    --------
    >>> ex = ChooseGridKind(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [k for k in ex.menu if k != ex.expected][0]
    >>> ex.check(wrong).diagnosis == f"{wrong} instead of {ex.expected}"
    True
    """

    title = "Which kind of grid?"
    answer_form = "custom"
    menu = grids.GRID_KINDS

    def draw(self, rng):
        self.scenario, self.expected = pick(rng, GRID_SCENARIOS)

    def separated(self, mistakes):
        return True

    def hints(self):
        return [
            r"Go from the most regular kind to the least: is there a lattice (every sample "
            r"has its i, j(, k) neighbours without a list)? If so, are its lines straight and "
            r"parallel to the axes? If so, are they evenly spaced?",
            r"Without a lattice: are cells listed (triangles, tetrahedra with their corner "
            r"indices)? Then it is unstructured; with positions only, scattered.",
            f"Here: {self.scenario}. What is stored, and what would you need to store to "
            "know every sample's position?",
        ]

    def worked(self):
        cells, lattice, parallel, even = _GRID_FACTS[self.scenario]
        steps = [f"The data: {self.scenario}. Ask what must be stored to know where every "
                 "sample is and which samples are neighbours."]
        if not lattice:
            steps.append("Is there a lattice of samples (neighbours implicit)? No.")
            kind = "unstructured" if cells else "scattered"
            steps.append("Are cells listed explicitly? "
                         + ("Yes: the corner indices of every cell." if cells else
                            "No: positions only, nothing says which samples are neighbours."))
        else:
            steps.append("Is there a lattice of samples (neighbours implicit)? Yes.")
            if not parallel:
                kind = "curvilinear"
                steps.append("Are its lines straight and axis-parallel? No: it is bent, so "
                             "every sample needs its own position.")
            else:
                kind = "uniform" if even else "rectilinear"
                steps.append("Are its lines straight and axis-parallel? Yes. Evenly spaced "
                             "along each axis? " + (
                                 "Yes (a spacing per axis is enough, even if the axes "
                                 "differ)." if even else
                                 "No: the spacing varies, so each axis needs its list of "
                                 "coordinates."))
        steps.append(f"So the answer is **{kind}**: {_KIND_WORDS[kind]}.")
        return Worked(steps, kind)

    def _check(self, answer):
        kind, unreadable = self._menu_choice(answer)
        if unreadable is not None:          # (a Feedback is falsy unless correct)
            return unreadable
        if kind == self.expected:
            return Feedback("correct", f"Right: {_KIND_WORDS[kind]}.")
        return Feedback("wrong", f"Not {kind}: {_KIND_WORDS[kind]}. Here, "
                        f"{_KIND_WORDS[self.expected]}.", f"{kind} instead of {self.expected}")

    def statement(self):
        return (
            rf"A data set: **{self.scenario}**. On which kind of grid does it live: "
            r"*uniform*, *rectilinear*, *curvilinear*, *unstructured* or *scattered*?" "\n\n"
            r"**Answer:** one of the strings `'uniform'`, `'rectilinear'`, `'curvilinear'`, "
            r"`'unstructured'`, `'scattered'`." "\n\n" + data_note("scenario", "menu"))


# ---------------------------------------------------------------------------------------------
# Memory per kind of grid
# ---------------------------------------------------------------------------------------------

_SHAPES_2D = ((100, 200), (50, 40), (20, 30), (200, 100), (60, 50), (10, 25))
_SHAPES_3D = ((20, 50, 40), (10, 20, 30), (30, 30, 40), (64, 64, 32))


class GridMemory(_Chapter10):
    r"""How many bytes a data set takes on a grid of a given kind (geometry, topology, values).

    Conventions (stated in the question, those of :func:`course_lib.dataviz.grid_memory`):
    every number, a coordinate, a count, an index or a value, takes the same number of bytes;
    uniform: origin and spacing per axis and the counts; rectilinear: one coordinate per sample
    along each axis and the counts; curvilinear: d coordinates per sample and the counts;
    unstructured: d coordinates per sample and the corner indices of the cells of the same
    lattice split into triangles (2 per quad) or tetrahedra (6 per hexahedron); scattered:
    d coordinates per sample.

    Attributes: ``kind``, ``shape`` (samples per axis, ``(ny, nx)`` or ``(nz, ny, nx)``),
    ``components`` (numbers per sample), ``bytes_per_number``.

    Examples
    --------
    >>> ex = GridMemory(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Memory of a grid"
    answer_form = "number"
    what = "the number of bytes"
    advice = (r"Count the numbers stored: geometry (what gives the positions), topology (the "
              r"counts, or the cells' corner indices), values ($N$ times the components); "
              r"then multiply by the bytes per number.")

    def draw(self, rng):
        self.kind = str(pick(rng, grids.GRID_KINDS))
        self.shape = tuple(pick(rng, _SHAPES_3D if rng.random() < 0.35 else _SHAPES_2D))
        self.components = int(pick(rng, (1, 1, 2, 3)))
        self.bytes_per_number = int(pick(rng, (4, 8)))
        m = grids.grid_memory(self.kind, self.shape, self.components,
                              bytes_per_number=self.bytes_per_number)
        self.expected = int(m["bytes"])

    def _counts(self):
        d = len(self.shape)
        n = math.prod(self.shape)
        cells = math.prod(s - 1 for s in self.shape)
        return d, n, cells

    def mistakes(self):
        d, n, cells = self._counts()
        b, k = self.bytes_per_number, self.components
        m = grids.grid_memory(self.kind, self.shape, k)
        geometry, topology, values = m["geometry"], m["topology"], m["values"]
        found = [
            Mistake(b * (geometry + topology), "The values are missing: every sample also "
                    f"stores its {k} number(s), {n} x {k} = {n * k} numbers.",
                    "values forgotten"),
            Mistake(geometry + topology + values, "That is the count of *numbers*; the "
                    f"question asks for bytes: multiply by {b}.", "numbers, not bytes"),
        ]
        if k > 1:
            found.append(Mistake(b * (geometry + topology + n), f"Each sample has {k} "
                                 "components: the values take N x components numbers.",
                                 "components forgotten"))
        if self.kind == "rectilinear":
            found.append(Mistake(b * (d * n + d + values), "A rectilinear grid stores one "
                                 "coordinate array per axis (nx + ny (+ nz) numbers), not a "
                                 "position per sample: that is a curvilinear grid.",
                                 "positions per sample"))
            found.append(Mistake(b * (2 * d + d + values), "Only a uniform grid gets away with "
                                 "an origin and a spacing: the rectilinear spacing varies, so "
                                 "every coordinate along each axis is stored.",
                                 "stored as uniform"))
        if self.kind in ("curvilinear", "unstructured", "scattered"):
            found.append(Mistake(b * (n + topology + values), f"Every sample needs all {d} of "
                                 "its coordinates, not one number.", "one coordinate per "
                                 "sample"))
        if self.kind == "unstructured":
            per, corners = (2, 3) if d == 2 else (6, 4)
            found.append(Mistake(b * (geometry + per * n * corners + values), "The lattice of "
                                 f"{' x '.join(map(str, self.shape))} samples has "
                                 f"{' x '.join(str(s - 1) for s in self.shape)} cells (one "
                                 "fewer than samples along each axis), not one per sample.",
                                 "cells miscounted"))
            found.append(Mistake(b * (geometry + cells * corners + values), "Each quad "
                                 "(hexahedron) of the lattice becomes "
                                 f"{per} {'triangles' if d == 2 else 'tetrahedra'}, "
                                 "not one.", "one cell per quad"))
        if self.kind == "uniform":
            found.append(Mistake(b * (d * n + values), "A uniform grid does not store its "
                                 "positions: origin, spacing and counts describe them all.",
                                 "positions stored"))
        return found

    def statement(self):
        d = len(self.shape)
        dims = r" \times ".join(str(s) for s in self.shape[::-1])
        what = ("a scalar" if self.components == 1 else
                f"{self.components} numbers (a vector or {self.components} variables)")
        return (
            rf"A data set has ${dims}$ samples ({'x by y' if d == 2 else 'x by y by z'}), "
            rf"each with {what}. It is stored on a **{self.kind}** grid, and every number "
            rf"(a coordinate, a count, an index or a value) takes {self.bytes_per_number} "
            r"bytes. Count, as in the lesson: a uniform grid stores an origin and a spacing per "
            r"axis and the sample count per axis; a rectilinear grid one coordinate per "
            r"sample along each axis and the counts; a curvilinear grid all coordinates of "
            r"every sample and the counts; an unstructured grid all coordinates of every "
            r"sample and the corner indices of the cells of the same lattice split into "
            r"triangles (2 per quad) or tetrahedra (6 per hexahedron); scattered data all "
            r"coordinates of every sample. How many bytes in total?" "\n\n"
            r"**Answer:** one whole number (bytes)." "\n\n"
            + data_note("kind", "shape", "components", "bytes_per_number"))

    def hints(self):
        d, n, cells = self._counts()
        product = " \\cdot ".join(map(str, self.shape))
        return [
            r"Split it in three: geometry (where the samples are), topology (how they "
            r"connect) and values; then multiply the count of numbers by the bytes per number.",
            rf"There are $N = {product} = {n}$ samples, so the "
            rf"values take ${n} \cdot {self.components}$ numbers.",
            "For a " + self.kind + " grid: " + grids.GRID_DESCRIPTIONS[self.kind][0] + "; "
            "topology: " + grids.GRID_DESCRIPTIONS[self.kind][1] + ".",
        ]

    def worked(self):
        d, n, cells = self._counts()
        k, b = self.components, self.bytes_per_number
        product = " \\cdot ".join(map(str, self.shape))
        steps = [rf"Samples: $N = {product} = {n}$; values "
                 rf"$N \cdot {k} = {n * k}$ numbers."]
        if self.kind == "uniform":
            geometry, topology = 2 * d, d
            steps.append(rf"Geometry: origin and spacing, ${d} + {d} = {geometry}$ numbers; "
                         rf"topology: the {d} counts.")
        elif self.kind == "rectilinear":
            geometry, topology = sum(self.shape), d
            steps.append(rf"Geometry: one coordinate array per axis, "
                         rf"${' + '.join(map(str, self.shape[::-1]))} = {geometry}$ numbers; "
                         rf"topology: the {d} counts.")
        elif self.kind == "curvilinear":
            geometry, topology = d * n, d
            steps.append(rf"Geometry: ${d}$ coordinates per sample, ${d} \cdot {n} = "
                         rf"{geometry}$; topology: the {d} counts (the lattice is implicit).")
        elif self.kind == "scattered":
            geometry, topology = d * n, 0
            steps.append(rf"Geometry: ${d} \cdot {n} = {geometry}$ coordinates; no topology.")
        else:
            per, corners = (2, 3) if d == 2 else (6, 4)
            shape = " \\cdot ".join(str(s - 1) for s in self.shape)
            geometry, topology = d * n, per * cells * corners
            steps.append(rf"Geometry: ${d} \cdot {n} = {geometry}$ coordinates. Cells of the "
                         rf"lattice: ${shape} = {cells}$, each split into {per} "
                         rf"{'triangles' if d == 2 else 'tetrahedra'} of {corners} corner "
                         rf"indices: ${cells} \cdot {per} \cdot {corners} = {topology}$.")
        total = geometry + topology + n * k
        steps.append(rf"Total: ${geometry} + {topology} + {n * k} = {total}$ numbers, times "
                     rf"{b} bytes: ${total * b}$ bytes.")
        return Worked(steps, total * b)


# ---------------------------------------------------------------------------------------------
# Shepard's method by hand
# ---------------------------------------------------------------------------------------------

#: Offsets from the query point with whole lengths: (dx, dy, distance).
_OFFSETS = ((1, 0, 1), (0, 1, 1), (-1, 0, 1), (0, -1, 1), (2, 0, 2), (0, -2, 2), (-2, 0, 2),
            (0, 2, 2), (3, 4, 5), (-4, 3, 5), (4, -3, 5), (-3, -4, 5), (4, 0, 4), (0, -4, 4),
            (-4, 0, 4), (0, 4, 4), (6, 8, 10), (-8, 6, 10))


def _shepard(distances, values, power):
    w = [1.0 / d ** power for d in distances]
    return sum(wi * f for wi, f in zip(w, values)) / sum(w)


class ShepardByHand(_Chapter10):
    r"""Shepard's inverse-distance weighting at one point, by hand.

    :math:`s(x) = \sum_i w_i f_i / \sum_i w_i` with :math:`w_i = 1/d_i^p`, for 3 or 4 samples
    at whole-number distances from the query point.

    Attributes: ``points`` (the samples' positions), ``values``, ``query``, ``power``.

    Examples
    --------
    >>> ex = ShepardByHand(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(float(np.mean(ex.values))).diagnosis
    'plain mean'
    """

    title = "Shepard's method by hand"
    answer_form = "number"
    what = "the interpolated value"
    advice = (r"Weights $w_i = 1/d_i^p$ from the distances to the query point, then "
              r"$s = \sum w_i f_i / \sum w_i$.")

    def draw(self, rng):
        k = int(pick(rng, (3, 3, 4)))
        idx = rng.choice(len(_OFFSETS), size=k, replace=False)
        offsets = np.array([_OFFSETS[i][:2] for i in idx])
        self._d = [float(_OFFSETS[i][2]) for i in idx]
        self.query = np.array([int(rng.integers(-3, 4)), int(rng.integers(-3, 4))])
        self.points = self.query + offsets
        self.values = rng.integers(0, 11, size=k).astype(float)
        self.power = float(pick(rng, (1, 2)))
        self.expected = float(scattered.shepard_interpolate(self.points, self.values,
                                                            [self.query], self.power)[0])

    def acceptable(self):
        d = sorted(self._d)
        return (len(np.unique(self.points, axis=0)) == len(self.points) and d[0] < d[1]
                and np.ptp(self.values) >= 3)

    def mistakes(self):
        d, f, p = self._d, list(self.values), self.power
        found = [
            Mistake(sum(v / di ** p for v, di in zip(f, d)), r"The weights were not "
                    r"normalised: divide $\sum w_i f_i$ by $\sum w_i$, so that the weights sum "
                    r"to 1 (otherwise the result is not even in the range of the values).",
                    "not normalised"),
            Mistake(_shepard([1 / di for di in d], f, p), r"Those are weights that grow with "
                    r"the distance: the weight is the **inverse** distance to the power p, "
                    r"$1/d_i^p$, so that near samples count most.", "distance, not inverse"),
            Mistake(float(np.mean(f)), r"That is the plain mean of the values: Shepard weights "
                    r"each one by $1/d_i^p$.", "plain mean"),
            Mistake(f[int(np.argmin(d))], r"That is the nearest sample's value (the limit of a "
                    r"very large p); with this p all samples contribute.", "nearest only"),
        ]
        if p == 2:
            found.append(Mistake(_shepard(d, f, 1), r"The power is missing: with $p = 2$ the "
                                 r"weights are $1/d_i^2$.", "power forgotten"))
            found.append(Mistake(_shepard(d, f, 4), r"The distances were squared twice: "
                                 r"$d_i^2$ is already the squared distance, and $p = 2$ asks "
                                 r"for $1/d_i^2$, not $1/(d_i^2)^2$.", "squared twice"))
        else:
            found.append(Mistake(_shepard(d, f, 2), r"With $p = 1$ the weights are $1/d_i$, "
                                 r"not the inverse squared distance.", "power 2 used"))
        return found

    def statement(self):
        rows = "\n".join(rf"| {i + 1} | $({int(x)}, {int(y)})$ | {_num(v)} |"
                         for i, ((x, y), v) in enumerate(zip(self.points, self.values)))
        qx, qy = (int(c) for c in self.query)
        return (
            r"Scattered samples $f_i$ at the points $x_i$:" "\n\n"
            "| i | $x_i$ | $f_i$ |\n|---|---|---|\n" + rows + "\n\n"
            rf"Interpolate at $x = ({qx}, {qy})$ with Shepard's method (global inverse-"
            rf"distance weighting) with power $p = {int(self.power)}$: $w_i = 1/d_i^p$, "
            r"$d_i = \lVert x - x_i \rVert$." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("points", "values", "query", "power"))

    def _distance_text(self, i):
        dx, dy = (int(c) for c in self.points[i] - self.query)
        sq = [f"({c})^2" if c < 0 else f"{c}^2" for c in (dx, dy)]
        return rf"d_{i + 1} = \sqrt{{{sq[0]} + {sq[1]}}} = {int(self._d[i])}"

    def hints(self):
        return [
            r"First the distances from the query point to every sample; they are whole "
            r"numbers here.",
            r"Then the weights $w_i = 1/d_i^p$: near samples get large weights.",
            rf"${self._distance_text(0)}$, so $w_1 = 1/{int(self._d[0])}^{int(self.power)}$. "
            r"Now the others, then $\sum w_i f_i / \sum w_i$.",
        ]

    def worked(self):
        p = int(self.power)
        w = [1.0 / di ** p for di in self._d]
        sw = sum(w)
        swf = sum(wi * f for wi, f in zip(w, self.values))
        steps = [
            "Distances: $" + ", ".join(self._distance_text(i) for i in range(len(w))) + "$.",
            rf"Weights $1/d_i^{p}$: $" + ", ".join(f"{_num(x, 4)}" for x in w) + "$; sum "
            rf"${_num(sw, 4)}$.",
            r"$\sum w_i f_i = " + " + ".join(rf"{_num(x, 4)} \cdot {_num(f)}"
                                             for x, f in zip(w, self.values))
            + rf" = {_num(swf, 4)}$.",
            rf"$s = {_num(swf, 4)} / {_num(sw, 4)} = {_num(swf / sw, 4)}$.",
        ]
        return Worked(steps, swf / sw)


# ---------------------------------------------------------------------------------------------
# Nearest neighbour against linear on a triangulation
# ---------------------------------------------------------------------------------------------

def _barycentric(p, a, b, c):
    """Barycentric coordinates of p in (a, b, c), by signed areas (plain arithmetic)."""
    def area(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])
    whole = area(a, b, c)
    return area(p, b, c) / whole, area(a, p, c) / whole, area(a, b, p) / whole


class NearestVsLinear(_Chapter10):
    r"""The nearest-neighbour and the linear value at a point of a small triangulation.

    Four samples at the corners of a rectangle, split into two triangles by a diagonal; the
    query point lies inside one of them. The answer is ``[nearest, linear]``.

    Attributes: ``points`` (the samples A, B, C, D), ``values``, ``triangles`` (the corner
    indices of the two triangles), ``query``.

    Examples
    --------
    >>> ex = NearestVsLinear(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'order swapped'
    """

    title = "Nearest neighbour or linear?"
    answer_form = "vector"
    what = "[nearest, linear]"
    advice = (r"Nearest: the value of the closest sample. Linear: find the triangle that holds "
              r"the point, its barycentric coordinates $\lambda$ (each the area of the "
              r"sub-triangle opposite a corner over the whole area), and $\sum \lambda_i f_i$.")

    def draw(self, rng):
        x0, y0 = int(rng.integers(-2, 3)), int(rng.integers(-2, 3))
        a, b = int(pick(rng, (2, 4, 5, 10))), int(pick(rng, (2, 4, 5)))
        self.points = np.array([[x0, y0], [x0 + a, y0], [x0 + a, y0 + b], [x0, y0 + b]],
                               dtype=float)
        self.values = rng.integers(0, 21, size=4).astype(float)
        if rng.random() < 0.5:
            self.triangles = np.array([[0, 1, 3], [1, 2, 3]])       # diagonal B-D
        else:
            self.triangles = np.array([[0, 1, 2], [0, 2, 3]])       # diagonal A-C
        i, j = int(rng.integers(1, 4 * a)), int(rng.integers(1, 4 * b))
        self.query = np.array([x0 + i / 4, y0 + j / 4])           # on a quarter lattice
        tri = self.triangles
        nearest = float(scattered.nearest_interpolate(self.points, self.values,
                                                      [self.query])[0])
        linear = float(scattered.linear_interpolate(self.points, self.values, [self.query],
                                                    triangles=tri)[0])
        self.expected = np.array([nearest, linear])

    def _inside(self):
        """The index of the triangle holding the query, and its barycentric coordinates."""
        for t, tri in enumerate(self.triangles):
            lam = _barycentric(self.query, *self.points[tri])
            if min(lam) >= 0:
                return t, lam
        raise AssertionError("the query point lies outside the triangulation")

    def acceptable(self):
        lo, hi = self.points.min(axis=0), self.points.max(axis=0)
        if not np.all((self.query > lo) & (self.query < hi)):
            return False
        d = np.sort(np.hypot(*(self.points - self.query).T))
        t, lam = self._inside()
        return bool(d[1] - d[0] > 0.2 and min(lam) > 0.05 and np.ptp(self.values) >= 4)

    def mistakes(self):
        t, lam = self._inside()
        tri, other = self.triangles[t], self.triangles[1 - t]
        near, lin = self.expected
        f = self.values
        wrong_plane = float(np.dot(_barycentric(self.query, *self.points[other]), f[other]))
        shifted = float(lam[2] * f[tri[0]] + lam[0] * f[tri[1]] + lam[1] * f[tri[2]])
        return [
            Mistake([lin, near], "The two values are swapped: the answer is "
                    "[nearest, linear].", "order swapped"),
            Mistake([near, float(np.mean(f[tri]))], "The linear value is not the plain mean "
                    "of the triangle's corners: each corner is weighted by its barycentric "
                    "coordinate, larger for the corners near the point.", "plain average"),
            Mistake([near, wrong_plane], "That is the plane of the *other* triangle, "
                    "extended: the point lies in triangle "
                    + "".join("ABCD"[i] for i in tri) + ", whose corners alone decide "
                    "the value.", "wrong triangle"),
            Mistake([near, shifted], "The weights went to the wrong corners: a corner's "
                    "weight is the area of the sub-triangle **opposite** it (the one that "
                    "does not touch it), divided by the whole area.", "weights on the wrong "
                    "corners"),
        ]

    def statement(self):
        names = "ABCD"
        rows = "\n".join(rf"| {names[i]} | $({_num(x)}, {_num(y)})$ | {_num(v)} |"
                         for i, ((x, y), v) in enumerate(zip(self.points, self.values)))
        tris = " and ".join("".join(names[i] for i in t) for t in self.triangles)
        qx, qy = self.query
        return (
            r"Four samples, triangulated into the triangles " + tris + ":\n\n"
            "| sample | position | value |\n|---|---|---|\n" + rows + "\n\n"
            rf"At the point $x = ({_num(qx)}, {_num(qy)})$, what value does "
            r"**nearest-neighbour** interpolation give, and what value does **linear** "
            r"interpolation on this triangulation give?" "\n\n"
            r"**Answer:** a list `[nearest, linear]`. " + DECIMALS + "\n\n"
            + data_note("points", "values", "triangles", "query"))

    def hints(self):
        t, _ = self._inside()
        names = "".join("ABCD"[i] for i in self.triangles[t])
        return [
            r"Two different answers: nearest neighbour copies one sample's value; linear "
            r"interpolation blends the three corners of the triangle that holds the point.",
            r"For nearest, compare the distances from the point to all four samples.",
            rf"The point lies in triangle {names}. Its barycentric coordinates are the areas "
            r"of the three sub-triangles formed with the point, each opposite one corner, "
            r"divided by the triangle's area.",
        ]

    def worked(self):
        names = "ABCD"
        d = np.hypot(*(self.points - self.query).T)
        k = int(np.argmin(d))
        t, lam = self._inside()
        tri = self.triangles[t]
        value = sum(l * self.values[i] for l, i in zip(lam, tri))
        corner = "".join(names[i] for i in tri)
        steps = [
            "Distances to A, B, C, D: " + ", ".join(_num(x, 3) for x in d) + f"; the nearest "
            f"is {names[k]}, so nearest gives ${_num(self.values[k])}$.",
            f"The point lies in triangle {corner} (all three barycentric coordinates are "
            "non-negative there).",
            "Barycentric coordinates (sub-triangle area over triangle area): "
            + ", ".join(rf"$\lambda_{names[i]} = {_num(l, 4)}$" for l, i in zip(lam, tri))
            + ".",
            "Linear: $" + " + ".join(rf"{_num(l, 4)} \cdot {_num(self.values[i])}"
                                     for l, i in zip(lam, tri)) + rf" = {_num(value, 4)}$.",
        ]
        return Worked(steps, [float(self.values[k]), float(value)])
