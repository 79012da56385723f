"""Chapter 15 exercises: where a ray hits a finite cylinder, and which of two disks it hits.

Part of :mod:`course_lib.exercises.ch15`, which imports every exercise from here.
"""
import math

import numpy as np

from ... import raytracing as rt
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _Parts, _num, _vec

__all__ = [
    "RayCylinderHit",
    "RayDiskHit",
]

#: Directions of the normal in the xy plane (then scaled by the radius) and the radii that make
#: the hit point whole numbers.
_CYLINDER_NORMALS = {(1.0, 0.0): (2.0, 3.0, 4.0), (0.6, 0.8): (5.0,)}


def _first_positive_root(a, b, c):
    """The smallest root > 0 of a t^2 + b t + c (None if there is none)."""
    if a == 0:
        return -c / b if b != 0 and -c / b > 0 else None
    disc = b * b - 4 * a * c
    if disc < 0:
        return None
    roots = sorted(((-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)))
    good = [t for t in roots if t > 1e-9]
    return good[0] if good else None


class RayCylinderHit(_Parts):
    r"""Where a ray first hits an open cylinder :math:`x^2 + y^2 = r^2`, :math:`0 \le z \le h`,
    and the outward normal there.

    Only :math:`x` and :math:`y` enter the equation, so :math:`a = d_x^2 + d_y^2`, :math:`b = 2
    (o_x d_x + o_y d_y)`, :math:`c = o_x^2 + o_y^2 - r^2`; a root counts only if its point's
    height lies in :math:`[0, h]`, otherwise the other root is tried (``kind = "open end"``:
    the ray comes in through the open top and hits the inner wall at the far root). The normal
    is the gradient :math:`(2x, 2y, 0)` normalised: :math:`(x/r, y/r, 0)`.

    Attributes: ``o``, ``d`` (the ray), ``radius``, ``height``, ``kind`` ("outside" or
    "open end").

    Examples
    --------
    >>> ex = RayCylinderHit(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> sorted({RayCylinderHit(seed=s).kind for s in range(12)})
    ['open end', 'outside']
    """

    title = "A ray hits a cylinder"
    what = "your answer"
    form_hint = r"`[t, n_x, n_y, n_z]`."
    advice = (r"Put the ray into $x^2 + y^2 = r^2$ only (z is free): $a = d_x^2 + d_y^2$, "
              r"$b = 2(o_x d_x + o_y d_y)$, $c = o_x^2 + o_y^2 - r^2$. Take the smaller root "
              r"whose point has $0 \le z \le h$; the normal is $(x, y, 0)/r$.")

    def draw(self, rng):
        if not hasattr(self, "kind"):            # chosen once per seed: redraws keep it
            self.kind = "open end" if rng.random() < 0.45 else "outside"
        nxy = pick(rng, tuple(_CYLINDER_NORMALS))
        self.radius = float(pick(rng, _CYLINDER_NORMALS[nxy]))
        nxy = np.array(nxy)[rng.permutation(2)] * rng.choice([-1.0, 1.0], 2)
        self.height = float(pick(rng, (4.0, 6.0, 8.0)))
        z = float(rng.integers(1, int(self.height)))
        self.normal = np.array([nxy[0], nxy[1], 0.0]) + 0.0
        self.point = np.array([self.radius * nxy[0], self.radius * nxy[1], z]) + 0.0
        self.d = rng.integers(-3, 4, size=3).astype(float)
        self.t = float(pick(rng, (1.0, 2.0)) if self.kind == "outside" else pick(rng, (2.0, 3.0)))
        self.o = self.point - self.t * self.d
        self.expected = np.r_[self.t, self.normal]

    def _quadratic(self):
        o, d = self.o, self.d
        return (float(d[0] ** 2 + d[1] ** 2), float(2 * (o[0] * d[0] + o[1] * d[1])),
                float(o[0] ** 2 + o[1] ** 2 - self.radius ** 2))

    def _roots(self):
        a, b, c = self._quadratic()
        root = math.sqrt(b * b - 4 * a * c)
        return (-b - root) / (2 * a), (-b + root) / (2 * a)

    def acceptable(self):
        d, o = self.d, self.o
        dxy = d[0] * self.normal[0] + d[1] * self.normal[1]
        if d @ d == 1 or d[0] ** 2 + d[1] ** 2 == 0:
            return False
        if self.kind == "outside":
            if dxy > -0.3 * math.hypot(d[0], d[1]):
                return False
        else:
            if dxy < 0.3 * math.hypot(d[0], d[1]) or d[2] >= 0:
                return False
        if o[0] ** 2 + o[1] ** 2 <= (self.radius + 0.5) ** 2:
            return False
        near, far = self._roots()
        z_near = o[2] + near * d[2]
        if self.kind == "open end" and not (z_near > self.height + 0.5 and near > 0):
            return False
        if self.kind == "outside" and not 0 < near:
            return False
        hits = rt.intersect_quadric(o, d, rt.quadric_matrix("cylinder", radius=self.radius),
                                    clip=(0.0, self.height))
        return bool(np.isclose(float(hits.t), self.t)) and np.allclose(hits.normals, self.normal)

    def parts(self):
        near, far = self._roots()
        a, b, c = self._quadratic()
        o = self.o
        t_slips = []
        if self.kind == "outside":
            t_slips.append(Mistake(far, r"That is the **far** root, where the ray leaves the "
                                   r"cylinder. From outside, the ray enters at the smaller root.",
                                   "far root"))
        else:
            t_slips.append(Mistake(near, rf"At the smaller root the point's height is "
                                   rf"$z = {_num(o[2] + near * self.d[2])} > h$: it lies on the "
                                   r"infinite cylinder, above the finite one. Test the height "
                                   r"and, if it fails, try the other root.", "height test"))
        for key, (aa, bb, cc), text in (
                ("a = d.d", (self.d @ self.d, b, c),
                 r"You took $a = d \cdot d$, with $d_z^2$ in it, as for a sphere. The "
                 r"cylinder's equation has no $z$: $a = d_x^2 + d_y^2$."),
                ("a = 1", (1.0, b, c), r"You took $a = 1$, as if $d$ were a unit vector in the "
                 r"xy plane; it is not: $a = d_x^2 + d_y^2$."),
                ("sphere equation", (self.d @ self.d, 2 * o @ self.d, o @ o - self.radius ** 2),
                 r"You put $z$ into the equation, as for a sphere $x^2 + y^2 + z^2 = r^2$. The "
                 r"cylinder's equation has no $z$: only $x$ and $y$ enter $a$, $b$, $c$.")):
            t_bad = _first_positive_root(float(aa), float(bb), float(cc))
            if t_bad is not None:
                t_slips.append(Mistake(t_bad, text, key))
        p = self.point
        full = p / np.linalg.norm(p)
        z_text = (r"Your normal has a $z$ component: you normalised the point $(x, y, z)$, as "
                  r"for a sphere centred at the origin. The gradient of $x^2 + y^2 - r^2$ is "
                  r"$(2x, 2y, 0)$: the normal is horizontal.")
        raw_text = (r"That is $(x, y, 0)$ not divided by its length $r$: a normal must be a unit "
                    r"vector.")
        parts = [("t", self.t, t_slips)]
        for k, axis in enumerate("xyz"):
            slips = [Mistake(full[k], z_text, "normal with z")]
            if k < 2:
                slips.append(Mistake(p[k], raw_text, "not normalised"))
            if self.kind == "open end" and k < 2:
                slips.append(Mistake(-self.normal[k], r"That normal points to the axis (it faces "
                                     r"the ray, which hits the inner wall). The question asks for "
                                     r"the outward normal, away from the axis.", "inward normal"))
            parts.append((f"n_{axis}", self.normal[k], slips))
        return parts

    def statement(self):
        return (
            rf"An open cylinder (a tube without lids) has the axis $z$, radius "
            rf"$r = {_num(self.radius)}$ and runs from $z = 0$ to $z = h = {_num(self.height)}$: "
            rf"$x^2 + y^2 = r^2$, $0 \le z \le h$. A ray starts at $o = {_vec(self.o)}$ with "
            rf"direction $d = {_vec(self.d)}$ (not a unit vector). Find the ray parameter $t$ "
            r"of the first hit with the tube and the outward unit normal $n$ (pointing away from "
            "the axis) there.\n\n"
            r"**Answer:** a list of 4 numbers `[t, n_x, n_y, n_z]`. " + DECIMALS + "\n\n"
            + data_note("o", "d", "radius", "height"))

    def hints(self):
        a, b, c = self._quadratic()
        return [
            r"The cylinder's equation has no $z$: put $x = o_x + t d_x$, $y = o_y + t d_y$ into "
            r"$x^2 + y^2 = r^2$, a quadratic $a t^2 + b t + c = 0$.",
            rf"$a = d_x^2 + d_y^2 = {_num(a)}$, $b = 2(o_x d_x + o_y d_y) = {_num(b)}$, "
            rf"$c = o_x^2 + o_y^2 - r^2 = {_num(c)}$.",
            r"Take the smaller root; if its point's height $o_z + t d_z$ is outside $[0, h]$, "
            r"take the larger one. The normal is the gradient $(2x, 2y, 0)$ normalised: "
            r"$(x/r, y/r, 0)$.",
        ]

    def worked(self):
        a, b, c = self._quadratic()
        near, far = self._roots()
        disc = b * b - 4 * a * c
        o, d = self.o, self.d
        zn, zf = o[2] + near * d[2], o[2] + far * d[2]
        steps = [
            rf"Substitute $x = {_num(o[0])} + {_num(d[0])} t$, $y = {_num(o[1])} + "
            rf"{_num(d[1])} t$ into $x^2 + y^2 = {_num(self.radius ** 2)}$: "
            rf"$a = d_x^2 + d_y^2 = {_num(a)}$, $b = 2(o_x d_x + o_y d_y) = {_num(b)}$, "
            rf"$c = o_x^2 + o_y^2 - r^2 = {_num(c)}$.",
            rf"Discriminant $b^2 - 4ac = {_num(disc)}$, so $t = \frac{{{_num(-b)} \mp "
            rf"{_num(math.sqrt(disc))}}}{{{_num(2 * a)}}}$: $t_1 = {_num(near)}$ and "
            rf"$t_2 = {_num(far)}$.",
            rf"Heights: $z(t_1) = {_num(o[2])} + {_num(near)} \cdot {_num(d[2])} = {_num(zn)}$ "
            rf"and $z(t_2) = {_num(zf)}$. "
            + (rf"$t_1$ lies in $[0, {_num(self.height)}]$: the ray enters the tube there, "
               r"$t = t_1$." if self.kind == "outside" else
               rf"$z(t_1)$ is above $h = {_num(self.height)}$ (the ray passes over the rim), "
               r"$z(t_2)$ is within: the ray enters through the open top and hits the inner "
               r"wall, $t = t_2$."),
            rf"The point $o + t d = {_vec(self.point)}$; the gradient $(2x, 2y, 0)$ normalised "
            rf"is $n = (x/r, y/r, 0) = {_vec(self.normal)}$.",
        ]
        return Worked(steps, list(self.expected))


class RayDiskHit(DrawnExercise):
    r"""Which of two disks a ray hits first, and at which :math:`t`.

    A disk is its plane :math:`(p - c) \cdot n = 0` plus the test :math:`\lVert p - c \rVert
    \le r`. The ray meets plane A as well, but either outside disk A's radius (``kind =
    "outside"``) or behind the ray's origin (``kind = "behind"``); the answer is the :math:`t`
    of the hit with disk B, :math:`t = \frac{(c_B - o) \cdot n_B}{d \cdot n_B}`.

    Attributes: ``o``, ``d``, ``centers``, ``normals``, ``radii`` (disks A, B), ``kind``.

    Examples
    --------
    >>> ex = RayDiskHit(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(-ex.expected).diagnosis
    'sign of the distance'
    """

    title = "A ray and two disks"
    answer_form = "number"
    what = "the ray parameter of the first hit"
    advice = (r"For each disk: $t = \frac{(c - o) \cdot n}{d \cdot n}$, keep it if $t > 0$ and "
              r"the point $o + t d$ lies within the radius of the centre; the answer is the "
              r"smallest such $t$.")

    def draw(self, rng):
        if not hasattr(self, "kind"):            # chosen once per seed: redraws keep it
            self.kind = "behind" if rng.random() < 0.4 else "outside"
        axes = rng.permutation(3)
        n = np.zeros((2, 3))
        n[0, axes[0]] = rng.choice([-1.0, 1.0])
        n[1, axes[1]] = rng.choice([-1.0, 1.0])
        self.normals = n
        self.d = rng.integers(-3, 4, size=3).astype(float)
        self.radii = np.array([float(pick(rng, (1.0, 2.0))), float(pick(rng, (2.0, 3.0)))])
        t_b = float(pick(rng, (2.0, 3.0, 4.0)))
        c_b = rng.integers(-3, 4, size=3).astype(float)
        off_b = rng.integers(-1, 2, size=3).astype(float)
        off_b[axes[1]] = 0.0
        p_b = c_b + off_b
        self.o = p_b - t_b * self.d
        if self.kind == "outside":
            t_a = float(pick(rng, (0.5, 1.0, 1.5)))
            off_a = rng.choice([-2.0, 2.0, 3.0, -3.0], size=3)
        else:
            t_a = float(pick(rng, (-1.0, -2.0, -0.5)))
            off_a = rng.integers(-1, 2, size=3).astype(float) * 0.5
        off_a[axes[0]] = 0.0
        p_a = self.o + t_a * self.d
        self.centers = np.array([p_a - off_a, c_b])
        self.t_a, self.t_b = t_a, t_b
        self.expected = t_b

    def acceptable(self):
        d, n = self.d, self.normals
        if d @ d == 1 or abs(d @ n[0]) < 1 or abs(d @ n[1]) < 2:
            return False
        p_a = self.o + self.t_a * d
        dist_a = np.linalg.norm(p_a - self.centers[0])
        if self.kind == "outside" and dist_a < self.radii[0] + 0.5:
            return False
        if self.kind == "behind" and dist_a > self.radii[0] - 0.2:
            return False
        if np.linalg.norm(self.o + self.t_b * d - self.centers[1]) > self.radii[1] - 0.2:
            return False
        ts = [float(rt.intersect_disk(self.o, d, c, nn, r).t)
              for c, nn, r in zip(self.centers, n, self.radii)]
        return bool(np.isinf(ts[0]) and np.isclose(ts[1], self.t_b))

    def mistakes(self):
        n, o, c = self.normals, self.o, self.centers
        found = [Mistake(-self.t_b, r"The sign of the plane distance is wrong: with "
                         r"$(o - c) \cdot n$ in the numerator $t$ changes sign. It is "
                         r"$t = \frac{(c - o) \cdot n}{d \cdot n}$.", "sign of the distance"),
                 Mistake(float((c[1] - o) @ n[1]), r"You did not divide by $d \cdot n$: "
                         r"$(c - o) \cdot n$ is the distance to the plane along $n$, not along "
                         r"the ray, and $d$ is not a unit vector.", "no division by d.n")]
        if self.kind == "outside":
            found.append(Mistake(self.t_a, r"The ray meets the **plane** of disk A there, but "
                                 r"that point is farther from A's centre than its radius: not a "
                                 r"hit. Test $\lVert p - c \rVert \le r$.", "outside the radius"))
        else:
            found.append(Mistake(self.t_a, r"That $t$ is negative: the plane of disk A lies "
                                 r"behind the ray's origin. Only hits with $t > 0$ count.",
                                 "behind the origin"))
            found.append(Mistake(abs(self.t_a), r"That is $|t|$ of disk A's hit, which lies "
                                 r"behind the origin ($t < 0$): a ray only looks forwards.",
                                 "behind the origin"))
        return found

    def statement(self):
        (ca, cb), (na, nb), (ra, rb) = self.centers, self.normals, self.radii
        return (
            rf"A ray starts at $o = {_vec(self.o)}$ with direction $d = {_vec(self.d)}$ (not a "
            rf"unit vector). Disk A has centre $c_A = {_vec(ca)}$, normal $n_A = {_vec(na)}$ and "
            rf"radius $r_A = {_num(ra)}$; disk B has centre $c_B = {_vec(cb)}$, normal "
            rf"$n_B = {_vec(nb)}$ and radius $r_B = {_num(rb)}$. Find the ray parameter $t$ of "
            r"the first disk the ray hits." "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("o", "d", "centers", "normals", "radii"))

    def _plane(self, k):
        c, n = self.centers[k], self.normals[k]
        num, den = float((c - self.o) @ n), float(self.d @ n)
        t = num / den
        p = self.o + t * self.d
        return num, den, t, p, float(np.linalg.norm(p - c))

    def hints(self):
        return [
            r"A disk is a plane plus a radius test: first $t = \frac{(c - o) \cdot n}{d \cdot n}$,"
            r" then $p = o + t d$ must satisfy $\lVert p - c \rVert \le r$, and $t > 0$.",
            rf"Disk A: $(c_A - o) \cdot n_A = {_num(self._plane(0)[0])}$, "
            rf"$d \cdot n_A = {_num(self._plane(0)[1])}$; disk B: "
            rf"$(c_B - o) \cdot n_B = {_num(self._plane(1)[0])}$, "
            rf"$d \cdot n_B = {_num(self._plane(1)[1])}$.",
            r"Check each candidate: is it in front of the origin, and is its point within the "
            r"disk? The answer is the smallest $t$ that passes both.",
        ]

    def worked(self):
        steps = []
        for k, name in enumerate("AB"):
            num, den, t, p, dist = self._plane(k)
            verdict = (rf"$t = {_num(t)} < 0$: behind the origin, no hit." if t <= 0 else
                       rf"$\lVert p - c_{name} \rVert = {_num(dist)} > r_{name} = "
                       rf"{_num(self.radii[k])}$: outside the disk, no hit."
                       if dist > self.radii[k] else
                       rf"$\lVert p - c_{name} \rVert = {_num(dist)} \le r_{name} = "
                       rf"{_num(self.radii[k])}$ and $t > 0$: a hit.")
            steps.append(rf"Disk {name}: $t = \frac{{(c_{name} - o) \cdot n_{name}}}{{d \cdot "
                         rf"n_{name}}} = \frac{{{_num(num)}}}{{{_num(den)}}} = {_num(t)}$, "
                         rf"point $p = o + t d = {_vec(p)}$. " + verdict)
        steps.append(rf"Only disk B is hit: $t = {_num(self.t_b)}$.")
        return Worked(steps, self.t_b)
