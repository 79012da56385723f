"""Chapter 12 exercises: Ambient occlusion.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import shading
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _n4, _num

__all__ = [
    "AmbientOcclusionSamples",
    "AmbientOcclusionWall",
]


def _rays(numbers):
    """"ray 3" or "rays 1, 2, 5"."""
    return ("ray " if len(numbers) == 1 else "rays ") + ", ".join(map(str, numbers))


class AmbientOcclusionSamples(DrawnExercise):
    r"""Ambient occlusion estimated from cosine-weighted sample rays: the fraction unblocked.

    A ray is blocked when it hits something within the maximum distance :math:`D`. With
    cosine-weighted directions the estimate is simply the number of unblocked rays over the
    number of rays: the cosine is already in the sampling.

    Attributes: ``cos_theta`` (each ray's cosine with the normal), ``hits`` (the distance of
    its first hit, ``inf`` for a miss), ``D``.

    Examples
    --------
    >>> ex = AmbientOcclusionSamples(seed=10)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(1 - ex.expected).diagnosis
    'occlusion instead of visibility'
    """

    title = "Ambient occlusion from sample rays"
    answer_form = "number"
    what = "the ambient-occlusion factor"
    advice = (r"Count the rays that are **not** blocked (no hit, or a hit beyond $D$) and divide "
            r"by the number of rays.")

    def draw(self, rng):
        k = int(rng.integers(6, 17))
        self.D = float(pick(rng, (1.0, 2.0)))
        kinds = rng.choice(3, size=k, p=[0.4, 0.35, 0.25])       # miss, near hit, far hit
        near = rng.choice(np.arange(0.1, 1.0, 0.1).round(1), size=k) * self.D
        far = self.D + rng.choice(np.arange(0.5, 3.0, 0.5), size=k)
        self.hits = np.where(kinds == 0, np.inf, np.where(kinds == 1, near, far))
        # as in a crease: the rays near the horizon (small cosine) are the ones that hit
        steep = rng.choice(np.arange(0.5, 1.0, 0.1).round(1), size=k)
        flat = rng.choice(np.arange(0.1, 0.6, 0.1).round(1), size=k)
        self.cos_theta = np.where(kinds == 0, steep, flat)
        self._open = (self.hits > self.D).astype(float)
        self.expected = float(self._open.mean())

    def acceptable(self):
        return 0 < self.expected < 1 and np.any(np.isfinite(self.hits) & (self.hits > self.D))

    def mistakes(self):
        v, c = self._open, self.cos_theta
        twice = (r"The cosine was counted twice. The directions were drawn with density "
                 r"$\cos\theta / \pi$, so the cosine of $\frac{1}{\pi}\int v \cos\theta\, "
                 r"d\omega$ is already in the sampling: each ray counts 1 (open) or 0 "
                 r"(blocked), and the estimate is their plain average.")
        return [
            Mistake(1 - self.expected, r"That is the fraction of **blocked** rays, the "
                    r"occlusion. The factor that multiplies the ambient term is the open "
                    r"fraction (1 on an open plane, smaller in creases).",
                    "occlusion instead of visibility"),
            Mistake(float(v @ c / c.sum()), twice, "cosine twice"),
            Mistake(float(v @ c / len(c)), twice, "cosine twice"),
            Mistake(float(np.isinf(self.hits).mean()), r"Hits further away than the maximum "
                    r"distance $D$ do not occlude: only nearby geometry darkens a point (a "
                    r"distant wall should not). Count those rays as open.",
                    "maximum distance ignored"),
            Mistake(self.expected / math.pi, r"No factor $1/\pi$ here: with cosine-weighted "
                    r"sampling the $1/\pi$ of the integral cancels against the density, and "
                    r"the estimate is just the fraction of open rays (1 for an open plane).",
                    "divided by pi"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {i + 1} | {_num(c)} | "
                         + ("no hit" if np.isinf(h) else _num(h)) + " |"
                         for i, (c, h) in enumerate(zip(self.cos_theta, self.hits)))
        return (
            rf"To estimate the ambient occlusion of a point, {len(self.hits)} rays were shot "
            r"from it into the hemisphere above its surface, in directions drawn with the "
            r"cosine-weighted density $\cos\theta/\pi$ ($\theta$ the angle from the normal). "
            r"For each ray the table gives $\cos\theta$ and the distance of the first object it "
            rf"hits. Only objects within the maximum distance $D = {_num(self.D)}$ occlude." "\n\n"
            "| ray | $\\cos\\theta$ | first hit at distance |\n|---|---|---|\n" + rows + "\n\n"
            r"Give the ambient-occlusion factor $AO$ that multiplies the ambient term "
            r"(1 = fully open, 0 = fully occluded)." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("cos_theta", "hits", "D") + " (`.hits` holds `inf` for no hit.)")

    def _open_rays(self):
        """The numbers (from 1) of the rays that escape: no hit, or a hit beyond D."""
        return [k for k, h in enumerate(self.hits, 1) if not h <= self.D]

    def hints(self):
        open_rays = self._open_rays()
        return [r"With cosine-weighted directions the estimate of "
                r"$\frac{1}{\pi}\int v \cos\theta\, d\omega$ is the plain **fraction** of rays "
                r"that escape: the cosine is already in how the directions were drawn.",
                rf"A ray is blocked only by a hit **within** $D = {_num(self.D)}$; a ray with no "
                r"hit, or whose first hit is further away, escapes. The $\cos\theta$ column is "
                r"not needed.",
                rf"Escaping: {_rays(open_rays)}; that is {len(open_rays)} of "
                rf"{len(self.hits)}."]

    def worked(self):
        open_rays = self._open_rays()
        blocked = [k for k in range(1, len(self.hits) + 1) if k not in open_rays]
        value = len(open_rays) / len(self.hits)
        return Worked([
            r"The directions were drawn with the density $\cos\theta/\pi$, so each ray counts "
            r"1 (it escapes) or 0 (it is blocked): no cosine weights, no $1/\pi$.",
            rf"Blocked, by a hit within $D = {_num(self.D)}$: {_rays(blocked)}. Escaping (no "
            rf"hit, or a hit beyond $D$): {_rays(open_rays)}.",
            rf"$AO = {len(open_rays)} / {len(self.hits)} = {_n4(value)}$.",
        ], value)


#: (a, h): the distance to the wall (or the trench's half-width) and the height. Whole numbers
#: up to 8 without a common factor, and Pythagorean pairs, whose a / sqrt(a^2 + h^2) is a
#: simple fraction. Pairs whose slips cannot be told apart are not drawn.
_SIDES = tuple((a, h) for a in range(1, 9) for h in range(1, 9) if math.gcd(a, h) == 1) + (
    (6, 8), (8, 6), (9, 12), (12, 9), (5, 12), (12, 5), (8, 15), (15, 8), (7, 24), (24, 7))


class AmbientOcclusionWall(DrawnExercise):
    r"""Closed-form ambient occlusion next to a wall, :math:`\tfrac12 (1 + a/\sqrt{a^2 + h^2})`,
    or in the middle of a trench, :math:`a/\sqrt{a^2 + h^2}`.

    Under cosine-weighted sampling, the directions whose angle from the normal, projected onto
    the vertical plane across the wall, is at least :math:`\beta` make up the fraction
    :math:`(1 - \sin\beta)/2`; the wall seen from the point spans the projected angles from
    :math:`\beta_0 = \arctan(a/h)` down to the horizon.

    Attributes: ``kind`` (``"wall"`` or ``"trench"``), ``a`` (distance to the wall, or the
    trench's half-width), ``h`` (the height of the wall or the depth of the trench).

    Examples
    --------
    >>> ex = AmbientOcclusionWall(seed=2)
    >>> ex.kind, ex.check(ex.expected).status
    ('wall', 'correct')
    >>> ex.check(1 - ex.expected).diagnosis
    'occlusion instead of visibility'
    """

    title = "Ambient occlusion next to a wall"
    answer_form = "number"
    what = "the ambient-occlusion factor"
    #: For a = h, swapping them changes nothing.
    may_coincide = ("a and h swapped",)
    advice = (r"The top edge of the wall is seen at $\beta_0 = \arctan(a/h)$ from the normal, "
            r"$\sin\beta_0 = a/\sqrt{a^2 + h^2}$; the wall blocks the directions beyond it, "
            r"the fraction $(1 - \sin\beta_0)/2$.")

    def draw(self, rng):
        self.kind = str(pick(rng, ("wall", "wall", "trench")))
        self.a, self.h = (float(x) for x in pick(rng, _SIDES))
        self.expected = shading.ambient_occlusion_closed_form(self.kind, self.a, self.h)

    def mistakes(self):
        a, h = self.a, self.h
        s = a / math.hypot(a, h)
        walls = 1 if self.kind == "wall" else 2
        uniform = 1 - walls * math.atan(h / a) / math.pi
        found = [
            Mistake(1 - self.expected, r"That is the **occluded** fraction. The ambient-"
                    r"occlusion factor is the open fraction, the part of the cosine-weighted "
                    r"hemisphere that sees the sky.", "occlusion instead of visibility"),
            Mistake(1 - walls * (1 - h / math.hypot(a, h)) / 2,
                    r"$a$ and $h$ are swapped. The top edge of the wall is seen at the angle "
                    r"$\beta_0$ from the **normal** (vertical) with $\tan\beta_0 = a/h$ (the "
                    r"horizontal distance over the height), so $\sin\beta_0 = a/\sqrt{a^2 + "
                    r"h^2}$.", "a and h swapped"),
            Mistake(uniform, r"You measured the blocked part by its angle, "
                    r"$\arctan(h/a)$ out of $\pi$. Ambient occlusion weights directions by "
                    r"$\cos\theta$: directions near the horizon, which the wall blocks first, "
                    r"count little. The weighted fraction beyond the projected angle "
                    r"$\beta$ is $(1 - \sin\beta)/2$.", "angles, not cosine-weighted"),
        ]
        if self.kind == "wall":
            found.append(Mistake(s, r"That is the value for a **trench**, with walls on both "
                                 r"sides. One wall blocks only the directions on its side: "
                                 r"$(1 - \sin\beta_0)/2$ of them, so "
                                 r"$AO = 1 - \frac{1 - \sin\beta_0}{2} = "
                                 r"\frac{1 + \sin\beta_0}{2}$.", "two walls"))
        else:
            found.append(Mistake((1 + s) / 2, r"That is the value for **one** wall. The trench "
                                 r"has a wall on each side, and each blocks "
                                 r"$(1 - \sin\beta_0)/2$: $AO = 1 - (1 - \sin\beta_0) = "
                                 r"\sin\beta_0$.", "one wall"))
        return found

    def statement(self):
        if self.kind == "wall":
            scene = (
                rf"A point lies on a flat floor at the distance $a = {_num(self.a)}$ from the "
                rf"foot of a vertical wall of height $h = {_num(self.h)}$, infinitely long in "
                r"both directions along the floor.")
        else:
            scene = (
                r"A point lies in the middle of the flat floor of a trench, infinitely long, "
                rf"with vertical walls of depth $h = {_num(self.h)}$ on both sides at the "
                rf"distance $a = {_num(self.a)}$ from the point (the trench is $2a$ wide).")
        return (
            scene + r" Nothing else is in the scene, and rays of any length count. Compute the "
            r"cosine-weighted ambient-occlusion factor "
            r"$AO = \frac{1}{\pi}\int_\Omega v(\omega) \cos\theta\, d\omega$ of the point "
            r"($v = 1$ for a direction that escapes, 0 for one that hits a wall)." "\n\n"
            r"Useful fact: among cosine-weighted directions, those whose angle from the normal, "
            r"projected onto the vertical plane across the wall(s), lies beyond $\beta$ on one "
            r"side make up the fraction $(1 - \sin\beta)/2$." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("kind", "a", "h"))

    def hints(self):
        a, h = self.a, self.h
        hyp = math.hypot(a, h)
        sin0 = a / hyp
        walls = ("the wall blocks" if self.kind == "wall" else
                 "each of the two walls blocks")
        return [r"Find the angle $\beta_0$ from the normal (vertical) at which the top edge of "
                r"the wall is seen; the useful fact then gives the cosine-weighted share of the "
                r"directions beyond it, $(1 - \sin\beta_0)/2$, which the wall blocks.",
                rf"$\tan\beta_0 = a/h$ (horizontal distance over height), so "
                rf"$\sin\beta_0 = a/\sqrt{{a^2 + h^2}} = {_num(a)}/\sqrt{{{_num(a * a + h * h)}}}"
                rf" = {_n4(sin0)}$.",
                rf"So {walls} $(1 - {_n4(sin0)})/2 = {_n4((1 - sin0) / 2)}$ of the "
                r"cosine-weighted hemisphere; $AO$ is what is left."]

    def worked(self):
        a, h = float(self.a), float(self.h)
        hyp = math.sqrt(a * a + h * h)
        sin0 = a / hyp
        blocked = (1 - sin0) / 2
        walls = 1 if self.kind == "wall" else 2
        value = 1 - walls * blocked
        steps = [rf"The top edge of the wall is seen at the angle $\beta_0$ from the normal with "
                 rf"$\tan\beta_0 = a/h = {_num(a)}/{_num(h)}$, so $\sin\beta_0 = "
                 rf"a/\sqrt{{a^2 + h^2}} = {_num(a)}/{_n4(hyp)} = {_n4(sin0)}$.",
                 r"One wall blocks the directions beyond $\beta_0$ on its side: the share "
                 rf"$(1 - \sin\beta_0)/2 = (1 - {_n4(sin0)})/2 = {_n4(blocked)}$."]
        if walls == 1:
            steps.append(rf"$AO = 1 - {_n4(blocked)} = {_n4(value)}$, which is "
                         r"$\tfrac12 (1 + \sin\beta_0)$.")
        else:
            steps.append(rf"The trench has two walls: $AO = 1 - 2 \cdot {_n4(blocked)} = "
                         rf"{_n4(value)}$, which is $\sin\beta_0$ itself.")
        return Worked(steps, value)
