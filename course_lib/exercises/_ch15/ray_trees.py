"""Chapter 15 exercises: shadow rays, mirror bounces and ray trees.

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.
"""
import math

import numpy as np

from ... import raytracing as rt
from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _Parts, _num, _vec

__all__ = [
    "MirrorChainColour",
    "RayTreeCount",
    "ShadowRay",
]


# ---------------------------------------------------------------------------------------------
# The ray tracer: shadows, recursion, ray trees, acceleration
# ---------------------------------------------------------------------------------------------

class ShadowRay(DrawnExercise):
    r"""A point on the floor, a point light and a ball that may be in the way: the intensity.

    The shadow ray from the point towards the light is blocked when it hits the ball before the
    light. Lit: :math:`I = k_a + k_d \max(N \cdot L, 0)` (a matte floor, :math:`I_a = I_l = 1`);
    in shadow only :math:`k_a` is left.

    Attributes: ``P`` (the point, on the floor :math:`y = 0`), ``light`` (its position),
    ``center``, ``radius`` (the ball), ``ka``, ``kd``; ``blocked`` (for the solutions).

    Examples
    --------
    >>> ex = ShadowRay(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(0.0).diagnosis
    'no ambient'
    """

    title = "A shadow ray"
    answer_form = "number"
    what = "the intensity"
    advice = (r"Cast the shadow ray $P + t\,L$ towards the light; if it hits the ball for a $t$ "
              r"between 0 and the distance to the light, only the ambient term $k_a$ is left. "
              r"Otherwise $I = k_a + k_d\, (N \cdot L)$ with $L$ normalized.")

    def draw(self, rng):
        self.P = np.array([float(rng.integers(-2, 3)), 0.0, float(rng.integers(-2, 3))])
        self.light = np.array([float(rng.integers(-3, 4)), float(rng.integers(3, 7)),
                               float(rng.integers(-3, 4))])
        s = float(pick(rng, (0.4, 0.5, 0.6)))
        off = np.zeros(3)
        if rng.random() < 0.5:
            off = rng.integers(-2, 3, size=3).astype(float)
        self.center = np.round(self.P + s * (self.light - self.P)) + off
        self.radius = float(pick(rng, (0.5, 1.0, 1.5)))
        self.ka = float(pick(rng, (0.1, 0.2)))
        self.kd = float(pick(rng, (0.5, 0.6, 0.7, 0.8)))
        to_light = self.light - self.P
        dist = float(np.linalg.norm(to_light))
        hit = rt.intersect_sphere(self.P, to_light / dist, self.center, self.radius)
        self.blocked = bool(float(hit.t) <= dist)
        self._cos = to_light[1] / dist
        self.expected = self.ka + (0.0 if self.blocked else self.kd * self._cos)

    def acceptable(self):
        gap_to_sphere = np.linalg.norm(self.P - self.center) - self.radius
        light_gap = np.linalg.norm(self.light - self.center) - self.radius
        if self.center[1] - self.radius < 0.5 or gap_to_sphere < 0.5 or light_gap < 0.5:
            return False
        # not a grazing case: the ray misses by a clear margin or passes well inside
        to_light = (self.light - self.P) / np.linalg.norm(self.light - self.P)
        f = self.center - self.P
        miss_distance = np.linalg.norm(f - (f @ to_light) * to_light)
        return abs(miss_distance - self.radius) > 0.3

    def mistakes(self):
        lit = self.ka + self.kd * self._cos
        unlit = (r"The ball is in the way: the shadow ray hits it before it reaches the light, "
                 r"so this light adds neither diffuse nor specular light. Only the ambient term "
                 r"$k_a$ is left.")
        found = [
            Mistake(0.0, r"A point in shadow is not black: the ambient term $k_a$ (light "
                    r"arriving indirectly) stays.", "no ambient"),
            Mistake(self.ka + self.kd * self._cos * np.linalg.norm(self.light - self.P),
                    r"$L$ was not normalized: $N \cdot L$ is a cosine only for unit vectors.",
                    "L not normalized"),
        ]
        if self.blocked:
            found.append(Mistake(lit, unlit, "ignored the shadow"))
        else:
            found.append(Mistake(self.ka, r"The shadow ray misses the ball (check the "
                                 r"discriminant, or the distance from the ball's centre to the "
                                 r"ray): the point is lit, $I = k_a + k_d\, (N \cdot L)$.",
                                 "false shadow"))
        return found

    def statement(self):
        return (
            rf"A matte floor (the plane $y = 0$, normal $(0, 1, 0)$, $k_a = {_num(self.ka)}$, "
            rf"$k_d = {_num(self.kd)}$, no specular term) is lit by a point light of intensity "
            rf"1 at ${_vec(self.light)}$ (ambient intensity $I_a = 1$). A ball of radius "
            rf"${_num(self.radius)}$ hangs at ${_vec(self.center)}$. What intensity does the "
            rf"ray tracer give the floor point $P = {_vec(self.P)}$? (Decide with a shadow ray "
            r"whether the ball blocks the light.)" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("P", "light", "center", "radius", "ka", "kd"))

    def _shadow(self):
        """L, its length, the unit L, and the shadow ray's quadratic: f, b, c', discriminant."""
        L = self.light - self.P
        dist = math.sqrt(float(L @ L))
        unit = L / dist
        f = self.P - self.center
        b = 2 * float(unit @ f)
        c2 = float(f @ f) - self.radius ** 2
        return L, dist, unit, f, b, c2, b * b - 4 * c2

    def hints(self):
        L, dist, unit, f, b, c2, disc = self._shadow()
        return [
            r"Cast a shadow ray from $P$ towards the light. If it hits the ball before it "
            r"reaches the light, only the ambient term $k_a$ is left; otherwise "
            r"$I = k_a + k_d\, (N \cdot L)$ with $L$ the **unit** vector towards the light.",
            rf"$L = \text{{light}} - P = {_vec(L)}$, of length ${_num(dist, 4)}$, so "
            rf"$\hat L = {_vec(unit, 4)}$ and $N \cdot \hat L = {_num(unit[1], 4)}$.",
            rf"The shadow ray $P + t\,\hat L$ against the ball: with $f = P - c = {_vec(f)}$, "
            rf"$b = 2\, \hat L \cdot f = {_num(b, 4)}$ and $c' = f \cdot f - r^2 = {_num(c2, 4)}$ "
            rf"the discriminant $b^2 - 4c'$ is ${_num(disc, 4)}$"
            + (r": negative, so the ray misses the ball." if disc < 0 else
               r": positive, so the ray's line meets the ball; check whether the roots lie "
               rf"between 0 and ${_num(dist, 4)}$."),
        ]

    def worked(self):
        L, dist, unit, f, b, c2, disc = self._shadow()
        cos = float(unit[1])
        steps = [
            rf"Towards the light: $L = {_vec(self.light)} - {_vec(self.P)} = {_vec(L)}$, "
            rf"$\lVert L \rVert = {_num(dist, 4)}$, $\hat L = {_vec(unit, 4)}$; with "
            rf"$N = (0, 1, 0)$, $N \cdot \hat L = {_num(cos, 4)}$.",
            rf"Shadow ray $P + t\,\hat L$ ($\hat L$ is a unit vector, so $a = 1$) against the "
            rf"ball: $f = P - c = {_vec(f)}$, $b = 2\, \hat L \cdot f = {_num(b, 4)}$, "
            rf"$c' = f \cdot f - r^2 = {_num(c2, 4)}$, discriminant "
            rf"$b^2 - 4c' = {_num(disc, 4)}$.",
        ]
        blocked = False
        if disc < 0:
            steps.append(r"The discriminant is negative: the shadow ray misses the ball, and "
                         r"the point is lit.")
        else:
            t1, t2 = (-b - math.sqrt(disc)) / 2, (-b + math.sqrt(disc)) / 2
            blocked = 0 < t1 < dist
            where = (rf"$0 < t_1 < {_num(dist, 4)}$: the ball is between the point and the "
                     r"light, the point is in shadow." if blocked else
                     r"both roots are negative: the ball is behind the point, which is lit."
                     if t2 < 0 else
                     rf"$t_1 > {_num(dist, 4)}$: the ball lies beyond the light, the point is "
                     r"lit.")
            steps.append(rf"Roots $t_1 = {_num(t1, 4)}$, $t_2 = {_num(t2, 4)}$; " + where)
        if blocked:
            intensity = self.ka
            steps.append(rf"In shadow only the ambient term is left: $I = k_a = "
                         rf"{_num(intensity)}$.")
        else:
            intensity = self.ka + self.kd * cos
            steps.append(rf"Lit: $I = k_a + k_d\, (N \cdot \hat L) = {_num(self.ka)} + "
                         rf"{_num(self.kd)} \cdot {_num(cos, 4)} = {_num(intensity, 4)}$.")
        return Worked(steps, intensity)


class MirrorChainColour(DrawnExercise):
    r"""The pixel intensity of a primary ray and its reflections, down to a depth limit.

    :math:`I = I_0 + k_{r,0} (I_1 + k_{r,1} (I_2 + \dots))`: every bounce's local intensity is
    weighted by the product of the reflectivities on the way; the recursion stops after
    ``depth`` reflections.

    Attributes: ``local`` (the local intensities :math:`I_0, I_1, \dots` of the surfaces the ray
    meets in turn), ``kr`` (their reflectivities), ``depth``.

    Examples
    --------
    >>> ex = MirrorChainColour(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(sum(ex.local[:ex.depth + 1])).diagnosis
    'no weights'
    """

    title = "The colour of a chain of reflections"
    answer_form = "number"
    what = "the pixel intensity"
    advice = (r"Work from the deepest ray back: $I_k = I_{local,k} + k_{r,k}\, I_{k+1}$, with "
              r"nothing beyond the depth limit.")

    def draw(self, rng):
        n = 4
        self.local = np.array([float(pick(rng, (0.1, 0.2, 0.3, 0.4, 0.5, 0.6))) for _ in range(n)])
        self.kr = np.array([float(pick(rng, (0.2, 0.25, 0.5, 0.75, 0.8))) for _ in range(n)])
        self.depth = int(pick(rng, (1, 2)))
        self.expected = self._total(self.depth, multiply=True)

    def _total(self, depth, multiply=True):
        total, weight = 0.0, 1.0
        for k in range(depth + 1):
            total += weight * self.local[k]
            weight = weight * self.kr[k] if multiply else self.kr[k]
        return total

    def mistakes(self):
        return [
            Mistake(sum(self.local[:self.depth + 1]), r"Every reflected intensity must be "
                    r"weighted by the reflectivities of the mirrors it came through: "
                    r"$I_0 + k_{r,0} I_1 + k_{r,0} k_{r,1} I_2 + \dots$", "no weights"),
            Mistake(self._total(self.depth, multiply=False), r"The weights multiply along the "
                    r"path: light seen after two bounces is weakened by *both* mirrors, "
                    r"$k_{r,0} k_{r,1}$, not only by the last one.", "weights not multiplied"),
            Mistake(self._total(self.depth + 1), r"You traced one reflection too many. With "
                    r"depth limit $d$ the primary ray and $d$ reflected rays are traced; the "
                    r"next one is not.", "one too deep"),
            Mistake(self._total(self.depth - 1), r"One reflection is missing: with depth limit "
                    r"$d$ the primary ray is followed by $d$ reflected rays.", "one too shallow"),
        ]

    def statement(self):
        rows = " | ".join(["surface"] + [str(k) for k in range(len(self.local))])
        return (
            r"A primary ray hits surface 0; its reflected ray hits surface 1, whose reflected "
            r"ray hits surface 2, and so on. The local (Phong) intensity $I_k$ at each hit and "
            r"the reflectivity $k_{r,k}$ of each surface are:" "\n\n"
            f"| {rows} |\n|" + "---|" * (len(self.local) + 1) + "\n"
            "| $I_k$ | " + " | ".join(_num(x) for x in self.local) + " |\n"
            "| $k_{r,k}$ | " + " | ".join(_num(x) for x in self.kr) + " |\n\n"
            rf"The ray tracer's recursion depth limit is {self.depth} (the primary ray and at "
            rf"most {self.depth} reflected rays). What intensity does the pixel get? (No "
            r"refraction, no clamping.)" "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("local", "kr", "depth"))

    def _backwards(self):
        """The intensities I_k seen along ray k, from the deepest traced ray back to the pixel."""
        seen = {self.depth: float(self.local[self.depth])}
        for k in range(self.depth - 1, -1, -1):
            seen[k] = float(self.local[k]) + float(self.kr[k]) * seen[k + 1]
        return seen

    def hints(self):
        d = self.depth
        seen = self._backwards()
        return [
            r"Each hit returns its local intensity plus its reflectivity times what the "
            r"reflected ray brings back: $I_k = I_{local,k} + k_{r,k}\, I_{k+1}$. Work from the "
            r"deepest ray back to the pixel.",
            rf"With depth limit {d} the rays to surfaces 0 to {d} are traced; the ray to "
            rf"surface {d} is the last, so it brings back only its local intensity, "
            rf"${_num(self.local[d])}$ (surface {d + 1} is never reached).",
            rf"One level up: $I_{{{d - 1}}} = {_num(self.local[d - 1])} + "
            rf"{_num(self.kr[d - 1])} \cdot {_num(self.local[d])} = {_num(seen[d - 1], 4)}$"
            + (r"; one more level gives the pixel." if d > 1 else r": that is the pixel."),
        ]

    def worked(self):
        d = self.depth
        seen = self._backwards()
        reflected = ("1 reflected ray (to surface 1)" if d == 1 else
                     f"{d} reflected rays (to surfaces 1 to {d})")
        steps = [rf"The depth limit {d} means the primary ray (to surface 0) and {reflected} "
                 rf"are traced. The deepest one brings back its local intensity only: "
                 rf"$I_{d} = {_num(self.local[d])}$."]
        for k in range(d - 1, -1, -1):
            steps.append(rf"$I_{k} = I_{{local,{k}}} + k_{{r,{k}}}\, I_{k + 1} = "
                         rf"{_num(self.local[k])} + {_num(self.kr[k])} \cdot "
                         rf"{_num(seen[k + 1], 4)} = {_num(seen[k], 4)}$.")
        steps.append(rf"The pixel gets $I_0 = {_num(seen[0], 4)}$ (the reflectivity "
                     rf"$k_{{r,{d}}}$ of the last surface is never used: nothing is traced beyond "
                     r"it).")
        return Worked(steps, seen[0])


class RayTreeCount(_Parts):
    r"""How many rays the ray tree of one pixel holds, with and without transparency.

    Every ray hits a surface that is reflective (and, in the glass variant, transparent too):
    a mirror scene gives a chain of :math:`d + 1` rays, a glass scene a full binary tree of
    :math:`2^{d+1} - 1` rays; each hit casts one shadow ray per light. Both counts are whole
    numbers, compared exactly.

    Attributes: ``depth``, ``lights``, ``glass`` (True: every surface reflects and refracts).

    Examples
    --------
    >>> ex = RayTreeCount(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> rays, shadows = ex.expected
    >>> ex.check([rays - 1, shadows]).diagnosis
    'primary forgotten'
    >>> ex.check([float(rays), float(shadows)]).status, ex.check([rays, shadows + 1]).status
    ('correct', 'wrong')
    """

    title = "Counting the rays of a ray tree"
    form_hint = r"`[reflected/refracted/primary rays, shadow rays]`."
    advice = (r"Draw the tree: the primary ray at level 0; every ray of level $k < d$ has one "
              r"child (mirror) or two (glass: reflected and refracted). Every node is a hit, and "
              r"every hit casts one shadow ray per light.")

    def draw(self, rng):
        self.depth = int(pick(rng, (2, 3, 4, 5, 6)))
        self.lights = int(pick(rng, (1, 2, 3, 4)))
        self.glass = bool(rng.random() < 0.5)
        nodes = 2 ** (self.depth + 1) - 1 if self.glass else self.depth + 1
        self.expected = np.array([nodes, nodes * self.lights])

    def parts(self):
        d, k = self.depth, self.lights
        nodes = int(self.expected[0])
        primary = (r"The primary ray counts too: it is the root of the tree.")
        found_rays = [Mistake(nodes - 1, primary, "primary forgotten")]
        if self.glass:
            found_rays += [
                Mistake(2 ** d, r"That is only the last level ($2^d$ rays). The tree holds "
                        r"every level $0, \dots, d$: $1 + 2 + \dots + 2^d = 2^{d+1} - 1$.",
                        "last level only"),
                Mistake(d + 1, r"Each hit on glass spawns *two* rays, a reflected and a "
                        r"refracted one: the tree doubles at every level.", "chain"),
            ]
        else:
            found_rays.append(Mistake(2 ** (d + 1) - 1, r"A mirror that is not transparent "
                                      r"spawns only a reflected ray: the tree is a chain.",
                                      "binary tree"))
        return [
            ("the traced rays", nodes, found_rays),
            ("the shadow rays", nodes * k, [
                Mistake(k, r"Every hit casts shadow rays, not only the primary one: "
                        r"one per light at every node of the tree.", "shadows of primary only"),
                Mistake(nodes, r"One shadow ray per hit *and per light*.", "one per hit"),
            ]),
        ]

    def statement(self):
        scene = ("every surface is glass that both reflects and refracts (so every hit spawns a "
                 "reflected and a refracted ray)" if self.glass else
                 "every surface is an opaque mirror (every hit spawns a reflected ray)")
        return (
            rf"In a closed room {scene}, and every ray hits some surface. The scene has "
            rf"{self.lights} point light{'s' if self.lights > 1 else ''}, and every hit casts "
            rf"one shadow ray per light. The recursion depth limit is {self.depth} (the primary "
            r"ray is at depth 0). For one pixel, how many primary, reflected and refracted rays "
            r"are traced together, and how many shadow rays?" "\n\n"
            r"**Answer:** a list of 2 whole numbers `[traced rays, shadow rays]`." "\n\n"
            + data_note("depth", "lights", "glass"))

    def _levels(self):
        """How many rays each level 0..depth of the tree holds."""
        return [2 ** level if self.glass else 1 for level in range(self.depth + 1)]

    def hints(self):
        levels = self._levels()
        kind = ("two children (a reflected and a refracted ray)" if self.glass else
                "one child (its reflected ray)")
        return [
            r"Draw the ray tree: the primary ray is the root (depth 0), every ray that hits "
            r"a surface below the depth limit spawns new rays, and every node is one hit.",
            rf"Here every ray of depth below {self.depth} has {kind}, so the levels "
            rf"$0, 1, \dots, {self.depth}$ hold " + ", ".join(str(n) for n in levels[:3])
            + r", $\dots$ rays.",
            rf"Add the levels up ({' + '.join(str(n) for n in levels)}); then each of those hits "
            rf"casts {self.lights} shadow ray{'s' if self.lights > 1 else ''}, one per light.",
        ]

    def worked(self):
        levels = self._levels()
        rays = sum(levels)
        shadows = rays * self.lights
        spawn = ("a reflected and a refracted ray, so level $k$ holds $2^k$ rays" if self.glass
                 else "only a reflected ray, so every level holds one ray")
        return Worked([
            rf"The tree has the levels $0$ (the primary ray) to {self.depth} (the depth limit). "
            rf"Every hit spawns {spawn}: " + ", ".join(
                f"level {k}: {n}" for k, n in enumerate(levels)) + ".",
            rf"Traced rays: ${' + '.join(str(n) for n in levels)} = {rays}"
            + (rf" = 2^{{{self.depth + 1}}} - 1$." if self.glass else "$."),
            rf"Every one of the {rays} hits casts one shadow ray per light: "
            rf"${rays} \cdot {self.lights} = {shadows}$ shadow rays.",
        ], [rays, shadows])
