"""Chapter 10 exercises: transfer functions.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import numpy as np

from ... import colormaps as cm
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, agrees, data_note,
                    has_placeholder, pick, read_floats)
from . import _Chapter10, _num, _values_words

__all__ = [
    "DesignOpacity",
    "ThresholdBands",
    "TransferValues",
]


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
