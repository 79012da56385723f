r"""Chapter 18 exercises: unsteady flow (which line a picture shows, a pathline step against a
streamline step) and line integral convolution (one pixel's value by hand).

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import numpy as np

from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, data_note,
                    has_placeholder, pick)
from . import _Chapter18, _num, _vec

__all__ = [
    "FLOW_LINE_SCENARIOS",
    "FlowLineKind",
    "LICPixel",
    "PathlineEulerSteps",
]

LINE_KINDS = ("streamline", "pathline", "streakline", "timeline")

#: (scenario, the line it shows): six or more for each kind of line.
FLOW_LINE_SCENARIOS = (
    ("Dye flows without a break from a fixed nozzle in a water tunnel whose pump speeds up and "
     "slows down; you photograph the coloured filament at one instant.", "streakline"),
    ("Smoke rises from a chimney on a gusty day; a photo shows the whole plume at once.",
     "streakline"),
    ("A wind-tunnel rake releases smoke continuously from one hole while the model wing "
     "oscillates; a snapshot of the smoke trail from that hole is taken.", "streakline"),
    ("A hydrogen-bubble wire is pulsed again and again at the same point; the picture joins all "
     "the bubbles that have come from that point so far.", "streakline"),
    ("Ink drips steadily from a pen held still in a stirred cup of tea; you look at the ink "
     "trail at one moment.", "streakline"),
    ("Sparks stream from a fixed grinding wheel into a swirling draught; a short-exposure photo "
     "shows where all the sparks released so far are now.", "streakline"),
    ("One neutrally buoyant balloon is released and tracked by GPS for a day; its recorded "
     "track is drawn on the map.", "pathline"),
    ("A single glowing particle is filmed with a long camera exposure as it moves through a "
     "time-varying flow.", "pathline"),
    ("An ocean drifter buoy reports its position every hour for a month; the positions are "
     "joined in order of time.", "pathline"),
    ("In particle tracking velocimetry, one tagged tracer is followed frame by frame and its "
     "positions are joined into a curve.", "pathline"),
    ("A leaf dropped into a river is followed by a drone, which records where it has been.",
     "pathline"),
    ("A simulation integrates dx/dt = v(x, t) from one seed point, advancing the time of the "
     "field along with the particle.", "pathline"),
    ("A row of hydrogen bubbles is released at one instant from a straight wire across a "
     "channel; a photo some time later shows the deformed row.", "timeline"),
    ("Twenty floats are dropped at the same moment along a straight line across a lake; an "
     "hour later the floats are joined in their original order.", "timeline"),
    ("A line of dye is painted across a flow at one instant and the painted line is filmed "
     "while it stretches and folds.", "timeline"),
    ("A simulation places particles along a segment at t0, advects all of them to t1 and draws "
     "them joined in the order they started.", "timeline"),
    ("At the start of a race, a straight row of rubber ducks is tipped into a stream at once; "
     "later the ducks are photographed from above and joined in their starting order.",
     "timeline"),
    ("Skaters stand shoulder to shoulder on a line and all start gliding with the current at "
     "the same whistle; a drone later joins them in order.", "timeline"),
    ("A simulation freezes the velocity field at t = 3 s and draws the curve that is tangent "
     "to the frozen velocity everywhere, through a chosen point.", "streamline"),
    ("From one snapshot of a PIV measurement, the software draws curves that follow the "
     "measured velocity arrows of that instant.", "streamline"),
    ("A weather map of one instant draws curves tangent to the wind arrows of that instant.",
     "streamline"),
    ("The integration dx/ds = v(x, t*) is carried out with the time t* held fixed.",
     "streamline"),
    ("Short iron-filing-like dashes are joined into curves along the velocity arrows of a "
     "single computed frame.", "streamline"),
    ("A student takes the flow of one time step of a simulation and integrates RK4 curves "
     "from seed points through that frozen field.", "streamline"),
)

_WHAT = {
    "streamline": "a curve tangent to the velocity of **one instant** (the field frozen in "
                  "time): no particle has to travel along it",
    "pathline": "the trajectory of **one particle** over a time interval",
    "streakline": "the particles released **one after the other from one fixed point**, seen "
                  "at one instant (dye, smoke)",
    "timeline": "a set of particles released **all at the same instant** along a line, seen "
                "later (the line moves and deforms)",
}
_CUE = {
    "streamline": "the velocity of a single instant is followed (time frozen)",
    "pathline": "one and the same particle is followed through time",
    "streakline": "particles keep being released from one fixed point and are seen together",
    "timeline": "many particles start together along a line at one instant",
}
_ALIASES = {"stream line": "streamline", "path line": "pathline", "streak line": "streakline",
            "time line": "timeline", "trajectory": "pathline", "particle path": "pathline",
            "streak": "streakline", "streamlines": "streamline", "pathlines": "pathline",
            "streaklines": "streakline", "timelines": "timeline"}


class FlowLineKind(_Chapter18):
    r"""Which line of an unsteady flow a picture shows: streamline, pathline, streakline or
    timeline.

    Attributes: ``scenario`` (in words), ``menu`` (the four lines).

    Examples
    --------
    >>> ex = FlowLineKind(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [k for k in ex.menu if k != ex.expected][0]
    >>> ex.check(wrong).diagnosis == f"{wrong} instead of {ex.expected}"
    True
    """

    title = "Which line does it show?"
    answer_form = "custom"
    menu = LINE_KINDS

    def draw(self, rng):
        self.scenario, self.expected = pick(rng, FLOW_LINE_SCENARIOS)

    def separated(self, mistakes):
        return True

    def _kind(self, answer):
        """The menu entry a string names, or None."""
        if not isinstance(answer, str):
            return None
        key = " ".join(answer.strip().lower().replace("-", " ").split())
        key = _ALIASES.get(key, key)
        return key if key in self.menu else None

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        key = self._kind(answer)
        if key is None:
            return Feedback("invalid", "Answer with one of the strings "
                            + ", ".join(f"`'{k}'`" for k in self.menu) + ".", "unreadable")
        if key == self.expected:
            return Feedback("correct", f"Right: {_CUE[key]}, so it is a **{key}**, "
                            f"{_WHAT[key]}.")
        return Feedback("wrong", f"A {key} would be {_WHAT[key]}. Here {_CUE[self.expected]}: "
                        f"a **{self.expected}**. (In a steady flow streamline, pathline and "
                        "streakline coincide, but this flow changes with time.)",
                        f"{key} instead of {self.expected}")

    def statement(self):
        return (
            "In a time-dependent flow four different lines can be drawn: **streamlines**, "
            "**pathlines**, **streaklines** and **timelines**. Which one does this show?\n\n"
            f"> {self.scenario}\n\n"
            r"**Answer:** one of the strings `'streamline'`, `'pathline'`, `'streakline'`, "
            r"`'timeline'`." "\n\n" + data_note("scenario", "menu"))

    def hints(self):
        return [
            "Ask what is followed: the velocity of one instant, one particle through time, or "
            "many particles seen together at one instant.",
            "Many particles at one instant: did they all leave one fixed point one after the "
            "other (streakline), or did they all start at the same moment along a line "
            "(timeline)?",
            "One particle followed through time is a pathline; a curve along the arrows of a "
            "single frozen instant is a streamline.",
        ]

    def worked(self):
        kind = self.expected
        return Worked([f"The scenario: {self.scenario}",
                       f"What is followed: {_CUE[kind]}.",
                       f"That is a **{kind}**: {_WHAT[kind]}."], kind)


# ---------------------------------------------------------------------------------------------
# A pathline step against a streamline step
# ---------------------------------------------------------------------------------------------

def _term(coef, var, first):
    """One term of a linear expression as LaTeX (" + 2t", "-y"), or "" for a zero coefficient."""
    if coef == 0:
        return ""
    size = "" if abs(coef) == 1 else _num(abs(coef))
    sign = "-" if coef < 0 else ("" if first else "+")
    return (sign if first else f" {sign} ") + size + var


def _expr(pairs):
    text = ""
    for coef, var in pairs:
        text += _term(coef, var, not text)
    return text or "0"


class PathlineEulerSteps(_Chapter18):
    r"""Two Euler steps of a **pathline** in a time-dependent field, where the time advances
    with the particle: :math:`p_{n+1} = p_n + h\,v(p_n, t_n)`, :math:`t_{n+1} = t_n + h`.

    The field is :math:`v(x, y, t) = (a y + b t,\ c x + d t)`. Keeping the time at
    :math:`t_0` for both steps traces the **streamline** of the frozen field instead.

    Attributes: ``a``, ``b``, ``c``, ``d`` (the field's coefficients), ``p`` (the start point),
    ``t0``, ``h``.

    Examples
    --------
    >>> ex = PathlineEulerSteps(seed=2)
    >>> v = lambda q, t: np.array([ex.a * q[1] + ex.b * t, ex.c * q[0] + ex.d * t])
    >>> p1 = ex.p + ex.h * v(ex.p, ex.t0)
    >>> ex.check(p1 + ex.h * v(p1, ex.t0 + ex.h)).status
    'correct'
    >>> ex.check(p1 + ex.h * v(p1, ex.t0)).diagnosis
    'frozen time'
    """

    title = "A pathline step is not a streamline step"
    answer_form = "point"
    what = "the particle's position"
    advice = (r"Step 1: $p_1 = p_0 + h\,v(p_0, t_0)$. Step 2 uses the new position **and the "
              r"new time**: $p_2 = p_1 + h\,v(p_1, t_0 + h)$.")

    def draw(self, rng):
        self.a, self.c = (float(pick(rng, (-2, -1, 1, 2))) for _ in range(2))
        self.b, self.d = (float(pick(rng, (-2, -1, 0, 1, 2))) for _ in range(2))
        self.p = rng.integers(-2, 3, size=2).astype(float)
        self.t0 = float(pick(rng, (0, 1, 2)))
        self.h = float(pick(rng, (0.5, 0.25)))
        p1 = self.p + self.h * self._v(self.p, self.t0)
        self.expected = p1 + self.h * self._v(p1, self.t0 + self.h)

    def _v(self, q, t):
        q = np.asarray(q, dtype=float)
        return np.stack([self.a * q[..., 1] + self.b * t, self.c * q[..., 0] + self.d * t],
                        axis=-1)

    def acceptable(self):
        return (self.b, self.d) != (0.0, 0.0) and bool(self.p.any())

    def mistakes(self):
        v, p, h, t0 = self._v, self.p, self.h, self.t0
        p1 = p + h * v(p, t0)
        q1 = p + h * v(p, t0 + h)
        return [
            Mistake(p1 + h * v(p1, t0), r"You kept the time at $t_0$ in the second step: that "
                    r"is the **streamline** of the field frozen at $t_0$. A particle carries "
                    r"its clock along; its second step reads the field at $t_0 + h$.",
                    "frozen time"),
            Mistake(q1 + h * v(q1, t0 + 2 * h), r"You advanced the time too early: the first "
                    r"step uses the field at $t_0$ (where and when the particle starts), the "
                    r"second at $t_0 + h$.", "time ahead"),
            Mistake(p1, r"That is the position after one step; the question asks for two.",
                    "one step"),
            Mistake(p1 + h * v(p, t0 + h), r"In the second step you read the velocity at the "
                    r"old position $p_0$. Euler's step uses the velocity where the particle "
                    r"is now: $v(p_1, t_0 + h)$.", "old position"),
        ]

    def statement(self):
        vx = _expr([(self.a, "y"), (self.b, "t")])
        vy = _expr([(self.c, "x"), (self.d, "t")])
        return (
            rf"A 2D flow changes with time: $v(x, y, t) = ({vx},\ {vy})$. A particle is at "
            rf"$p_0 = {_vec(self.p)}$ at time $t_0 = {_num(self.t0)}$. Trace its **pathline** "
            rf"with two steps of Euler's method of size $h = {_num(self.h)}$ (the time advances "
            r"by $h$ at each step). Where is the particle after the two steps?" "\n\n"
            r"**Answer:** the point as a list of 2 numbers `[x, y]`. " + DECIMALS + "\n\n"
            + data_note("a", "b", "c", "d", "p", "t0", "h"))

    def _steps(self):
        p, h, t0 = self.p, self.h, self.t0
        v0 = np.array([self.a * p[1] + self.b * t0, self.c * p[0] + self.d * t0])
        p1 = p + h * v0
        t1 = t0 + h
        v1 = np.array([self.a * p1[1] + self.b * t1, self.c * p1[0] + self.d * t1])
        frozen = np.array([self.a * p1[1] + self.b * t0, self.c * p1[0] + self.d * t0])
        return v0, p1, t1, v1, p1 + h * v1, frozen

    def hints(self):
        v0, p1, t1, v1, p2, frozen = self._steps()
        return [
            r"A pathline follows one particle, so the field is read where the particle is "
            r"**and when** it is there: $p_{n+1} = p_n + h\,v(p_n, t_n)$, $t_{n+1} = t_n + h$.",
            rf"Step 1: $v(p_0, t_0) = {_vec(v0, 4)}$, so $p_1 = {_vec(p1, 4)}$ at time "
            rf"$t_1 = {_num(t1)}$.",
            rf"Step 2 reads $v(p_1, t_1)$, not $v(p_1, t_0) = {_vec(frozen, 4)}$ (that one "
            r"would trace the streamline of the frozen field).",
        ]

    def worked(self):
        v0, p1, t1, v1, p2, frozen = self._steps()
        return Worked([
            rf"Step 1 at $t_0 = {_num(self.t0)}$: $v(p_0, t_0) = {_vec(v0, 4)}$, "
            rf"$p_1 = p_0 + h\,v = {_vec(self.p)} + {_num(self.h)} \cdot {_vec(v0, 4)} = "
            rf"{_vec(p1, 4)}$.",
            rf"The clock moves on: $t_1 = t_0 + h = {_num(t1)}$.",
            rf"Step 2: $v(p_1, t_1) = {_vec(v1, 4)}$, $p_2 = {_vec(p1, 4)} + {_num(self.h)} "
            rf"\cdot {_vec(v1, 4)} = {_vec(p2, 4)}$.",
            rf"(The streamline of the field frozen at $t_0$ would use $v(p_1, t_0) = "
            rf"{_vec(frozen, 4)}$ and end at {_vec(p1 + self.h * frozen, 4)}: a different "
            r"curve, because the field changes with time.)",
        ], p2)


# ---------------------------------------------------------------------------------------------
# LIC: one pixel by hand
# ---------------------------------------------------------------------------------------------

class LICPixel(_Chapter18):
    r"""The line integral convolution value of one pixel from the noise met along its
    streamline.

    The streamline through the pixel was traced with steps of one pixel, :math:`m` steps
    forwards and :math:`m` backwards; the table lists the noise at each step :math:`k`
    (:math:`k = 0` is the pixel itself), "outside" where the trace had left the image. With a
    kernel of half-length :math:`L` (in steps), the value is the weighted average of the
    samples with :math:`|k| \le L` that are inside: a **box** kernel weights them equally, the
    **Hann** kernel :math:`w_k = \tfrac12 (1 + \cos(\pi k / L))`.

    Attributes: ``offsets`` (k), ``noise`` (NaN outside), ``L``, ``kernel``.

    Examples
    --------
    >>> ex = LICPixel(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "A LIC pixel by hand"
    answer_form = "number"
    what = "the LIC value"
    advice = (r"Keep the samples with $|k| \le L$ that are inside the image, weight them by the "
              r"kernel, and divide by the sum of the weights used.")

    def draw(self, rng):
        self.kernel = str(pick(rng, ("box", "box", "hann")))
        self.L = 2 if self.kernel == "hann" else int(pick(rng, (2, 3)))
        m = self.L + int(pick(rng, (1, 2)))
        self.offsets = np.arange(-m, m + 1)
        self.noise = rng.integers(0, 11, size=2 * m + 1) / 10.0
        cut = int(pick(rng, (0, 0, 1, 2)))           # steps lost at one end (border)
        if cut:
            side = pick(rng, (-1, 1))
            lost = self.offsets * side > self.L - cut
            self.noise[lost] = np.nan
        self.expected = self._value(self.L, self.kernel)

    def _weights(self, L, kernel):
        k = self.offsets
        if kernel == "box":
            w = (np.abs(k) <= L).astype(float)
        else:
            w = np.where(np.abs(k) <= L, 0.5 * (1 + np.cos(np.pi * k / L)), 0.0)
        return w

    def _value(self, L, kernel, keep=None, renormalise=True):
        w = self._weights(L, kernel)
        if keep is not None:
            w = w * keep
        inside = np.isfinite(self.noise)
        used = w * inside
        total = float(np.sum(used * np.nan_to_num(self.noise)))
        return total / float(used.sum() if renormalise else w.sum())

    def acceptable(self):
        return bool(np.isfinite(self.noise[self.offsets == 0]).all())

    def mistakes(self):
        k = self.offsets
        found = [
            Mistake(self._value(int(np.abs(k).max()), "box"),
                    r"You averaged every listed sample, also those beyond the kernel: only "
                    r"$|k| \le L$ count (the trace was longer than the kernel).",
                    "whole trace"),
            Mistake(self._value(self.L, self.kernel, keep=(k >= 0)), r"You used only the "
                    r"forward half. LIC traces the streamline **both ways**, "
                    r"$k = -L, \dots, L$.", "forward only"),
            Mistake(self._value(self.L, self.kernel, keep=(k != 0)), r"The pixel's own noise "
                    r"($k = 0$) belongs to the average too.", "centre left out"),
        ]
        if np.isnan(self.noise[np.abs(k) <= self.L]).any():
            found.append(Mistake(self._value(self.L, self.kernel, renormalise=False),
                                 r"Samples outside the image do not exist: divide by the "
                                 r"weights of the samples you used, not by the whole kernel's "
                                 r"(else border pixels turn dark).", "not renormalised"))
        if self.kernel == "hann":
            found.append(Mistake(self._value(self.L, "box"), r"That is the box kernel. The "
                                 r"Hann kernel weights the samples by "
                                 r"$\tfrac12 (1 + \cos(\pi k / L))$: 1 at the centre, 0.5 "
                                 r"at $|k| = 1$ and 0 at $|k| = 2$ here.", "box instead of hann"))
        return found

    def _table(self):
        cells = [("outside" if np.isnan(n) else _num(n)) for n in self.noise]
        head = " | ".join(str(int(k)) for k in self.offsets)
        return ("| step k | " + head + " |\n|---|" + "---|" * len(self.offsets) + "\n"
                "| noise | " + " | ".join(cells) + " |")

    def statement(self):
        kernel = (r"a **box** kernel (equal weights)" if self.kernel == "box" else
                  r"the **Hann** kernel $w_k = \tfrac12 (1 + \cos(\pi k / L))$")
        return (
            r"Line integral convolution: the streamline through a pixel was traced with steps "
            r"of one pixel, forwards ($k > 0$) and backwards ($k < 0$); the table gives the "
            r"noise value met at each step ($k = 0$ is the pixel itself; *outside*: the trace "
            r"had left the image)." "\n\n" + self._table() + "\n\n"
            rf"With {kernel} of half-length $L = {self.L}$ steps, normalised by the weights of "
            r"the samples that exist, what is the pixel's LIC value?" "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("offsets", "noise", "L", "kernel"))

    def _used(self):
        k = self.offsets
        rows = [(int(kk), float(n), float(w)) for kk, n, w in
                zip(k, self.noise, self._weights(self.L, self.kernel))
                if abs(kk) <= self.L and np.isfinite(n) and w > 0]
        return rows

    def hints(self):
        rows = self._used()
        return [
            r"LIC averages the noise along the streamline through the pixel, both ways, as far "
            r"as the kernel reaches: $|k| \le L$.",
            "The samples that count: " + ", ".join(f"$k = {k}$: {_num(n)}" for k, n, _ in rows)
            + " (steps outside the image are skipped).",
            (r"Box: add them and divide by how many there are." if self.kernel == "box" else
             r"Hann with $L = 2$: weights $0, \tfrac12, 1, \tfrac12, 0$ for $k = -2..2$; "
             r"divide by the sum of the weights used."),
        ]

    def worked(self):
        rows = self._used()
        total = sum(w * n for _, n, w in rows)
        weight = sum(w for _, _, w in rows)
        value = total / weight
        if self.kernel == "box":
            terms = " + ".join(_num(n) for _, n, _ in rows)
            step2 = rf"Sum: ${terms} = {_num(total, 4)}$ over {len(rows)} samples."
        else:
            terms = " + ".join(rf"{_num(w)} \cdot {_num(n)}" for _, n, w in rows)
            step2 = (rf"Weighted sum: ${terms} = {_num(total, 4)}$; weights used: "
                     rf"${_num(weight, 4)}$.")
        return Worked([
            rf"Samples with $|k| \le {self.L}$ that exist: "
            + ", ".join(f"$k = {k}$ ({_num(n)})" for k, n, _ in rows) + ".",
            step2,
            rf"LIC value: ${_num(total, 4)} / {_num(weight, 4)} = {_num(value, 4)}$.",
        ], value)
