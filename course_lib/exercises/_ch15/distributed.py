"""Chapter 15 exercises: distributed (stochastic) ray tracing.

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.
"""

from ..core import (UNANSWERED, DrawnExercise, Feedback, Mistake, Worked, data_note,
                    is_unanswered, pick)
from . import _ONE_NUMBER, _num

__all__ = ["DistributedDomainChoice", "SoftShadowShare"]

#: What a distributed effect spreads its rays over: the answer strings.
DOMAINS = {
    "pixel": "positions inside the pixel's area",
    "light": "points on the area light",
    "reflection": "directions in a lobe around the mirror direction",
    "lens": "points on the lens aperture",
    "time": "instants while the shutter is open",
}

_EFFECT = {
    "pixel": "**antialiasing** (rays spread over the pixel's area)",
    "light": "**soft shadows** (shadow rays spread over the light's area)",
    "reflection": "**glossy reflection** (reflected rays spread over a lobe of directions)",
    "lens": "**depth of field** (camera rays spread over the lens aperture)",
    "time": "**motion blur** (rays spread over the shutter interval)",
}

_NOT = {
    "pixel": r"Spreading rays over the **pixel area** averages what lies inside one pixel: it "
             r"smooths staircase edges and small detail, a blur of at most one pixel. It cannot "
             r"blur something over many pixels.",
    "light": r"Spreading shadow rays over the **light's area** softens shadow edges only; it "
             r"changes nothing about what the camera or a mirror sees directly.",
    "reflection": r"Spreading reflected rays over a **lobe of directions** blurs what a surface "
                  r"reflects; it has no effect on shadows, on the camera's focus, or on matte "
                  r"objects.",
    "lens": r"Spreading camera rays over the **lens aperture** blurs objects by their distance "
            r"from the plane in focus; it blurs everything at that depth the same way, moving "
            r"or not, and does not touch shadows.",
    "time": r"Spreading rays over **time** blurs only what moves while the shutter is open; "
            r"still objects stay sharp.",
}

#: (situation, answer, clue); {X} placeholders filled from the options.
_SITUATIONS = (
    ("A lamp with a large frosted globe hangs above a table; the shadow of a {cup} on the table "
     "is sharp near the {cup}'s base and gets fuzzier further from it.", "light",
     "the fuzzy band is a penumbra: from there only part of the lamp's globe is hidden"),
    ("Under an overcast sky (a light source as large as the sky) a {cup} casts only a faint, "
     "blurry shadow without a hard edge.", "light",
     "the sky is a huge light source, so almost every point sees part of it: a wide penumbra"),
    ("A renderer replaces a point light by a rectangular ceiling panel, and the hard black "
     "shadow below a {cup} turns into a dark core with a soft rim.", "light",
     "a dark core (umbra) and a soft rim (penumbra) come from hiding part of an area light"),
    ("A {metal} reflects the window as a blurred bright patch instead of a sharp image of the "
     "window frame.", "reflection",
     "a rough surface scatters the reflected light into a lobe around the mirror direction"),
    ("On a polished wooden floor the reflection of a {cup} is sharp where the {cup} touches "
     "the floor and smears out further away.", "reflection",
     "the reflected rays spread in a cone; the further they travel the wider their footprint"),
    ("A renderer must show the difference between a chrome and a {metal} sphere in a room "
     "otherwise identical.", "reflection",
     "chrome is a perfect mirror, the other reflects a blurred image: a lobe of directions"),
    ("A portrait photo: the face is sharp, the {background} behind it is a soft blur, although "
     "nothing moved.", "lens",
     "blur that grows with the distance from the plane in focus is the lens aperture at work"),
    ("A macro shot of an insect: only a thin slice of the {background} at the insect's distance "
     "is sharp, everything nearer or further is blurred.", "lens",
     "a thin sharp slice of depth is a shallow depth of field: a wide aperture"),
    ("A rendered camera is refocused from a near {cup} to the far {background}: now the "
     "{cup} is blurred and the {background} sharp.", "lens",
     "what is sharp depends on the focal distance: the thin-lens camera"),
    ("A photo of a {mover}: it appears smeared along its path while the street behind it is "
     "crisp.", "time",
     "only the moving object is blurred, along its motion: the shutter was open for a while"),
    ("An animation looks jerky (strobing) when a {mover} crosses the screen quickly; film "
     "footage of the same motion looks smooth.", "time",
     "film averages each frame over the time the shutter is open; a pinhole render freezes one "
     "instant"),
    ("A spinning {wheel} is rendered with its spokes blurred into a disk while the frame "
     "holding it stays sharp.", "time",
     "the spokes move during the exposure, the frame does not"),
    ("The thin {wire} of a {mover} rendered at one ray per pixel breaks into a dotted line "
     "that flickers from frame to frame.", "pixel",
     "detail thinner than a pixel is missed or hit by the single ray at the pixel's centre"),
    ("A checkerboard floor that stretches to the horizon shows wavy moiré patterns far away "
     "in a one-ray-per-pixel render.", "pixel",
     "many checks fall into one distant pixel: the pixel must average its whole area"),
    ("The edges of a {cup} against the sky look like staircases in a one-ray-per-pixel "
     "render.", "pixel",
     "a staircase edge: each pixel is all or nothing instead of partly covered"),
)

_FILL = {"{cup}": ("cup", "vase", "teapot", "chair"),
         "{metal}": ("brushed-steel kettle", "satin aluminium pan", "frosted-steel sphere"),
         "{background}": ("garden", "bookshelf", "crowd"),
         "{mover}": ("cyclist", "train", "thrown ball"),
         "{wheel}": ("bicycle wheel", "cart wheel", "wagon wheel"),
         "{wire}": ("spokes", "cable", "antenna")}


def _read_domain(answer):
    form = ("Give one of the strings " + ", ".join(f"`'{k}'`" for k in DOMAINS) + ".")
    if is_unanswered(answer):
        return Feedback("unanswered", UNANSWERED)
    if not isinstance(answer, str):
        return Feedback("invalid", form, "unreadable")
    name = answer.strip().lower()
    name = {"area": "pixel", "aperture": "lens", "shutter": "time", "directions": "reflection",
            "gloss": "reflection"}.get(name, name)
    if name not in DOMAINS:
        return Feedback("invalid", f"{answer!r} is not one of the five domains. " + form,
                        "unreadable")
    return name


class DistributedDomainChoice(DrawnExercise):
    r"""Which domain a distributed ray tracer must spread its rays over to show an effect.

    Fifteen situations (three per effect) with a few settings each; the answer is one of
    ``'pixel'`` (antialiasing), ``'light'`` (soft shadows), ``'reflection'`` (glossy
    reflection), ``'lens'`` (depth of field) or ``'time'`` (motion blur). Every wrong choice is
    answered with what that domain does instead; the diagnosis is ``"chose <domain>"``.

    Attributes: ``situation`` (the question), ``domains`` (the five names).

    Examples
    --------
    >>> ex = DistributedDomainChoice(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = "time" if ex.expected != "time" else "lens"
    >>> ex.check(wrong).diagnosis == f"chose {wrong}"
    True
    >>> ex.check("camera").status
    'invalid'
    """

    title = "What does the pixel integrate over?"
    answer_form = "custom"
    domains = tuple(DOMAINS)

    def draw(self, rng):
        text, self.expected, self._clue = pick(rng, _SITUATIONS)
        for key, options in _FILL.items():
            if key in text:
                text = text.replace(key, str(pick(rng, options)))
        self.situation = text

    def separated(self, mistakes):
        return True

    def _judge(self, answer):
        name = _read_domain(answer)
        if isinstance(name, Feedback):
            return name
        if name == self.expected:
            return Feedback("correct", f"Yes: {_EFFECT[name]}.")
        return Feedback("wrong", f"{_NOT[name]} The effect here is {_EFFECT[self.expected]}: "
                        f"{self._clue}.", f"chose {name}")

    def statement(self):
        rows = "\n".join(f"| `'{k}'` | {v} |" for k, v in DOMAINS.items())
        return (
            self.situation + "\n\nA Whitted ray tracer cannot show this. Over which domain must "
            "a distributed ray tracer spread its rays (and average them) to reproduce it?"
            "\n\n| answer | rays spread over |\n|---|---|\n" + rows + "\n\n"
            "**Answer:** one of the strings " + ", ".join(f"`'{k}'`" for k in DOMAINS) + ".\n\n"
            + data_note("situation", "domains"))

    def hints(self):
        other = sorted(k for k in DOMAINS if k != self.expected)[0]
        return [r"Each distributed effect replaces one ray by many: ask which single ray of "
                r"Whitted's tracer stands for something that really has an extent (an area, "
                r"a range of directions, an interval of time).",
                f"The clue: {self._clue}.",
                f"Rule one out: {_NOT[other]}"]

    def worked(self):
        steps = [f"What we see: {self._clue}."]
        for name in sorted(DOMAINS):
            if name != self.expected:
                steps.append(f"{_NOT[name]} So not `'{name}'`.")
        steps.append(f"What is left: {_EFFECT[self.expected]}, answer `'{self.expected}'`.")
        return Worked(steps, self.expected)


class SoftShadowShare(DrawnExercise):
    r"""The intensity at a point lit by an area light, from the results of its shadow rays.

    :math:`N` shadow rays go to stratified points of a disk light; :math:`k` of them are
    blocked. The light's diffuse and specular terms at the point (what it would give if fully
    visible) sum to :math:`D`, the ambient term is :math:`A`. The intensity is
    :math:`I = A + D\,(N - k)/N`: the shadow rays estimate the visible fraction of the light,
    and only the light's own terms are scaled by it.

    Attributes: ``n`` (shadow rays), ``blocked`` (the indices of the blocked ones, from 1),
    ``ambient`` (:math:`A`), ``direct`` (:math:`D`), ``centre_blocked`` (whether the single
    shadow ray of a Whitted tracer, to the light's centre, is blocked).

    Examples
    --------
    >>> ex = SoftShadowShare(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> k, n = len(ex.blocked), ex.n
    >>> ex.check(ex.ambient + ex.direct * k / n).diagnosis
    'blocked share used'
    """

    title = "Soft shadow from shadow-ray results"
    answer_form = "number"
    what = "the intensity at the point"
    advice = (r"The shadow rays estimate the visible fraction of the light: "
              r"(unblocked rays)/(all rays). Scale only the light's own terms by it; the "
              r"ambient term is not shadowed.")

    def draw(self, rng):
        self.n = int(pick(rng, (8, 10, 16, 20, 25, 32)))
        k = int(rng.integers(1, self.n))
        self.blocked = sorted(int(i) + 1 for i in rng.choice(self.n, size=k, replace=False))
        self.ambient = float(pick(rng, (0.05, 0.1, 0.15, 0.2)))
        self.direct = float(pick(rng, (0.4, 0.5, 0.6, 0.8)))
        self.centre_blocked = bool(rng.random() < k / self.n)
        self.expected = self.ambient + self.direct * (self.n - k) / self.n

    def acceptable(self):
        k = len(self.blocked)
        return 0 < k < self.n and 2 * k != self.n

    def mistakes(self):
        k, n, a, d = len(self.blocked), self.n, self.ambient, self.direct
        whitted = a if self.centre_blocked else a + d
        return [
            Mistake(a + d * k / n, r"That scales the light by the share of **blocked** rays. "
                    r"The light that reaches the point is what the **unblocked** rays see: "
                    r"$(N - k)/N$.", "blocked share used"),
            Mistake((a + d) * (n - k) / n, r"The ambient term was shadowed too. Ambient light "
                    r"stands for light arriving from everywhere; shadow rays only decide how "
                    r"much of **this** light's diffuse and specular terms get through.",
                    "ambient shadowed"),
            Mistake(whitted, r"That is Whitted's answer with one shadow ray to the light's "
                    r"centre: all or nothing, a hard shadow. With an area light every shadow "
                    r"ray counts: the point sees a fraction of the light.", "one shadow ray"),
            Mistake(d * (n - k) / n, r"The ambient term was left out: it is added whatever the "
                    r"shadow rays say.", "ambient forgotten"),
        ]

    def statement(self):
        return (
            rf"A point on a floor is lit by a disk light. A distributed ray tracer sends "
            rf"$N = {self.n}$ shadow rays from the point to stratified points of the disk; "
            rf"rays {', '.join(map(str, self.blocked))} are blocked by an object in between "
            rf"(the others reach the light). The ray to the centre of the disk is "
            rf"{'blocked' if self.centre_blocked else 'not blocked'}. If the whole light "
            rf"were visible, its diffuse and specular terms at the point would add up to "
            rf"$D = {_num(self.direct)}$; the ambient term is $A = {_num(self.ambient)}$. "
            r"What intensity does the tracer compute for the point?" "\n\n" + _ONE_NUMBER
            + "\n\n" + data_note("n", "blocked", "ambient", "direct", "centre_blocked"))

    def hints(self):
        k = len(self.blocked)
        return [r"The shadow rays are a Monte Carlo estimate of the fraction of the light's "
                r"area visible from the point.",
                rf"{k} of the {self.n} rays are blocked, so {self.n - k} reach the light.",
                r"Only the light's terms $D$ are scaled by that fraction; add the ambient "
                rf"term $A = {_num(self.ambient)}$ unchanged."]

    def worked(self):
        k, n = len(self.blocked), self.n
        frac = (n - k) / n
        value = self.ambient + self.direct * frac
        return Worked([
            rf"Blocked: {k} of {n} rays, so {n - k} reach the light: visible fraction "
            rf"${n - k}/{n} = {_num(round(frac, 4))}$.",
            rf"The light's terms scaled: $D \cdot {n - k}/{n} = {_num(self.direct)} \cdot "
            rf"{_num(round(frac, 4))} = {_num(round(self.direct * frac, 4))}$.",
            rf"Plus the ambient term: $I = {_num(self.ambient)} + "
            rf"{_num(round(self.direct * frac, 4))} = {_num(round(value, 4))}$.",
        ], value)
