"""Chapter 14 exercises: Barycentric coordinates and interpolation.

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import numpy as np

from ... import texturing
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _UV, _Chapter14, _factor, _n4, _num, _vec

__all__ = [
    "BarycentricCoordinates",
    "InterpolateColour",
    "PerspectiveCorrect",
]


def _area(p, q, r):
    """The signed area of the triangle p, q, r (positive counter-clockwise)."""
    p, q, r = (np.asarray(x, dtype=float) for x in (p, q, r))
    return 0.5 * ((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
                  - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))


def _triangle(rng):
    """Three whole-number corners in [0, 6]^2 of a triangle of area at least 4."""
    while True:
        A, B, C = rng.integers(0, 7, size=(3, 2)).astype(float)
        if abs(_area(A, B, C)) >= 4:
            return A, B, C


def _area_steps(p, q, r, name):
    r"""The signed area of p, q, r worked out: (LaTeX, value).

    :math:`\tfrac12 [(q_x - p_x)(r_y - p_y) - (q_y - p_y)(r_x - p_x)]`.
    """
    a, b = q[0] - p[0], r[1] - p[1]
    c, d = q[1] - p[1], r[0] - p[0]
    value = 0.5 * (a * b - c * d)
    return (rf"$A({name}) = \tfrac12 [{_factor(a)} \cdot {_factor(b)} - {_factor(c)} \cdot "
            rf"{_factor(d)}] = {_num(value)}$"), value


def _weights_steps(A, B, C, P):
    """The barycentric coordinates of P by signed areas, worked out: (steps, weights)."""
    A, B, C, P = (np.asarray(x, dtype=float) for x in (A, B, C, P))
    total_text, total = _area_steps(A, B, C, "A, B, C")
    texts, areas = [], []
    for corners, name in (((P, B, C), "P, B, C"), ((A, P, C), "A, P, C"),
                          ((A, B, P), "A, B, P")):
        text, value = _area_steps(*corners, name)
        texts.append(text)
        areas.append(value)
    weights = np.array(areas) / total
    steps = [r"The whole triangle, with $A(P, Q, R) = \tfrac12 [(Q_x - P_x)(R_y - P_y) - "
             rf"(Q_y - P_y)(R_x - P_x)]$: {total_text}.",
             "Each corner's sub-triangle, with $P$ in that corner's place: "
             + ", ".join(texts) + ".",
             r"Divide by the whole area: $(\lambda_A, \lambda_B, \lambda_C) = ("
             + r",\ ".join(f"{_num(a)}/{_factor(total)}" for a in areas) + ") = ("
             + r",\ ".join(_n4(w) for w in weights) + rf")$; they add up to "
             rf"{_n4(weights.sum())}."]
    return steps, weights, areas, total


_PERMUTATIONS = ((0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0))


class BarycentricCoordinates(_Chapter14):
    r"""Barycentric coordinates of a point by signed areas, inside or outside the triangle.

    :math:`\lambda_A = A(P, B, C)/A(A, B, C)`, :math:`\lambda_B = A(A, P, C)/A(A, B, C)`,
    :math:`\lambda_C = A(A, B, P)/A(A, B, C)`; outside the triangle one or two are negative.

    Attributes: ``A``, ``B``, ``C`` (the corners), ``P``.

    Examples
    --------
    >>> ex = BarycentricCoordinates(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.expected[::-1]).diagnosis
    'wrong vertex order'
    """

    title = "Barycentric coordinates"
    answer_form = "vector"
    what = "the list of coordinates"
    may_coincide = ("wrong vertex order", "unsigned areas")
    advice = (r"Each $\lambda$ is the signed area of the triangle in which $P$ replaces that "
            r"vertex, over the signed area of $ABC$; the three add up to 1, and "
            r"$\lambda_A A + \lambda_B B + \lambda_C C = P$.")

    def draw(self, rng):
        self.A, self.B, self.C = _triangle(rng)
        self.P = rng.integers(-1, 8, size=2).astype(float)
        self.expected = texturing.barycentric(self.P, self.A, self.B, self.C)

    def acceptable(self):
        return bool(np.all(np.abs(self.expected) > 0.05))

    def mistakes(self):
        A, B, C, P = self.A, self.B, self.C, self.P
        areas = np.array([_area(P, B, C), _area(A, P, C), _area(A, B, P)])
        total = _area(A, B, C)
        lam = self.expected
        order = (r"The weights are in the wrong order. The weight of a vertex is the area of "
                 r"the triangle **opposite** it, the one in which $P$ takes that vertex's "
                 r"place: $\lambda_A = A(P, B, C)/A(A, B, C)$ (it is 1 at $A$ itself).")
        found = [Mistake(lam[list(p)], order, "wrong vertex order") for p in _PERMUTATIONS]
        unsigned = (r"The areas must be **signed**. For a point outside the triangle the "
                    r"sub-triangle on the far side of an edge turns the other way round, and "
                    r"its negative area is what makes the weights add up to 1 and reproduce "
                    r"$P = \lambda_A A + \lambda_B B + \lambda_C C$ (a negative weight tells "
                    r"that $P$ lies beyond the opposite edge).")
        found += [Mistake(np.abs(areas) / abs(total), unsigned, "unsigned areas"),
                  Mistake(np.abs(areas) / np.abs(areas).sum(), unsigned, "unsigned areas")]
        divide = (r"These are the areas themselves: divide each by the area of the whole "
                  rf"triangle, $A(A, B, C) = {_num(total)}$, so that the weights add up to 1.")
        found += [Mistake(areas, divide, "not divided by the total area"),
                  Mistake(2 * areas, divide, "not divided by the total area")]
        return found

    def statement(self):
        return (
            rf"A triangle has the corners $A = {_vec(self.A)}$, $B = {_vec(self.B)}$, "
            rf"$C = {_vec(self.C)}$. Compute the barycentric coordinates "
            r"$(\lambda_A, \lambda_B, \lambda_C)$ of the point "
            rf"$P = {_vec(self.P)}$ from signed areas "
            r"($A(P, Q, R) = \tfrac12 [(Q - P) \times (R - P)]$, positive when $P, Q, R$ run "
            r"counter-clockwise). The point may lie outside the triangle." "\n\n"
            r"**Answer:** a list of 3 numbers `[lambda_A, lambda_B, lambda_C]`. " + DECIMALS
            + "\n\n" + data_note("A", "B", "C", "P"))

    def hints(self):
        steps, weights, areas, total = _weights_steps(self.A, self.B, self.C, self.P)
        return [r"Each coordinate is a ratio of **signed** areas: $\lambda_A = A(P, B, C) / "
                r"A(A, B, C)$, where $P$ takes the place of $A$ (and likewise for $B$ and "
                r"$C$). A negative area, and weight, means $P$ lies beyond the opposite edge.",
                rf"The whole triangle has the signed area $A(A, B, C) = {_num(total)}$.",
                r"The three sub-triangles: $A(P, B, C) = " + _num(areas[0]) + "$, "
                rf"$A(A, P, C) = {_num(areas[1])}$, $A(A, B, P) = {_num(areas[2])}$; divide "
                r"each by the whole area."]

    def worked(self):
        steps, weights, _, _ = _weights_steps(self.A, self.B, self.C, self.P)
        outside = [name for name, w in zip("ABC", weights) if w < 0]
        if outside:
            steps.append(r"A negative weight ($\lambda_" + r"$, $\lambda_".join(outside)
                         + r"$) says that $P$ lies outside the triangle, beyond the edge "
                         r"opposite that corner.")
        return Worked(steps, weights)


#: The whole-number points of [0, 6]^2.
_GRID = np.stack(np.meshgrid(np.arange(7.0), np.arange(7.0)), -1).reshape(-1, 2)
_CHANNELS = (0.0, 0.2, 0.4, 0.5, 0.6, 0.8, 1.0)


class InterpolateColour(_Chapter14):
    r"""A colour interpolated inside a triangle: :math:`c = \lambda_A c_A + \lambda_B c_B +
    \lambda_C c_C`.

    Attributes: ``A``, ``B``, ``C`` (corners), ``P`` (inside), ``colours`` (one RGB row per
    corner: A, B, C).

    Examples
    --------
    >>> ex = InterpolateColour(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.colours.mean(axis=0)).diagnosis
    'plain average'
    """

    title = "Interpolating a colour"
    answer_form = "vector"
    what = "the colour"
    may_coincide = ("wrong vertex order",)
    advice = (r"Compute the barycentric coordinates of $P$ (signed areas over the whole area), "
            r"then $c = \lambda_A c_A + \lambda_B c_B + \lambda_C c_C$, channel by channel.")

    def draw(self, rng):
        while True:                     # a triangle with whole-number points well inside
            self.A, self.B, self.C = _triangle(rng)
            total = _area(self.A, self.B, self.C)
            smallest = np.minimum.reduce([_area(_GRID, self.B, self.C),
                                          _area(self.A, _GRID, self.C),
                                          _area(self.A, self.B, _GRID)]) / total
            inside = _GRID[smallest > 0.05]
            if len(inside):
                break
        self.P = inside[int(rng.integers(len(inside)))]
        self.colours = rng.choice(_CHANNELS, size=(3, 3))
        self._weights = texturing.barycentric(self.P, self.A, self.B, self.C)
        self.expected = texturing.barycentric_interpolate(self.colours, self._weights)

    def acceptable(self):
        largest, second = np.sort(self._weights)[::-1][:2]
        return bool(np.all(self._weights > 0.05)) and largest - second > 0.05 \
            and len({tuple(c) for c in self.colours}) == 3

    def mistakes(self):
        A, B, C, P, lam, c = self.A, self.B, self.C, self.P, self._weights, self.colours
        areas = np.array([_area(P, B, C), _area(A, P, C), _area(A, B, P)])
        order = (r"The weights went to the wrong corners. The weight of a corner is the area of "
                 r"the triangle **opposite** it ($P$ in that corner's place): "
                 r"$\lambda_A = A(P, B, C)/A(A, B, C)$; it is 1 when $P$ is at $A$.")
        found = [Mistake(lam[list(p)] @ c, order, "wrong vertex order") for p in _PERMUTATIONS]
        found += [
            Mistake(c.mean(axis=0), r"That is the plain average of the three colours, the "
                    r"colour at the **centroid** only. Elsewhere each corner's colour counts "
                    r"with its barycentric weight.", "plain average"),
            Mistake(areas @ c, r"The weights must be divided by the area of the whole triangle "
                    rf"({_num(_area(A, B, C))}): then they add up to 1 and a grey stays grey.",
                    "not divided by the total area"),
            Mistake(c[int(np.argmax(lam))], r"That is the colour of the nearest corner (the "
                    r"one with the largest weight), as flat or nearest-neighbour shading would "
                    r"give. Interpolation blends all three colours.", "nearest corner"),
        ]
        return found

    def statement(self):
        rows = "\n".join(rf"| {name} | ${_vec(p)}$ | ${_vec(col)}$ |" for name, p, col in
                         zip("ABC", (self.A, self.B, self.C), self.colours))
        return (
            r"A triangle has a colour (red, green, blue) at each corner:" "\n\n"
            "| corner | position | colour |\n|---|---|---|\n" + rows + "\n\n"
            rf"Interpolate the colour at the point $P = {_vec(self.P)}$ inside the triangle "
            r"with barycentric coordinates (ratios of signed areas)." "\n\n"
            r"**Answer:** the colour as a list of 3 numbers `[r, g, b]`. " + DECIMALS + "\n\n"
            + data_note("A", "B", "C", "P", "colours") + " (`.colours[k]` is the colour of "
            "corner A, B, C for k = 0, 1, 2.)")

    def hints(self):
        _, weights, _, _ = _weights_steps(self.A, self.B, self.C, self.P)
        return [r"First the barycentric coordinates of $P$ (signed areas over the whole area), "
                r"then blend the corners' colours with them, channel by channel: "
                r"$c = \lambda_A c_A + \lambda_B c_B + \lambda_C c_C$.",
                rf"The whole triangle has the signed area "
                rf"$A(A, B, C) = {_num(_area(self.A, self.B, self.C))}$; each weight is a "
                r"sub-triangle's area over it.",
                r"$(\lambda_A, \lambda_B, \lambda_C) = ("
                + r",\ ".join(_n4(w) for w in weights) + ")$."]

    def worked(self):
        steps, weights, _, _ = _weights_steps(self.A, self.B, self.C, self.P)
        colours = np.asarray(self.colours, dtype=float)
        colour = weights[0] * colours[0] + weights[1] * colours[1] + weights[2] * colours[2]
        for k, channel in enumerate(("red", "green", "blue")):
            products = " + ".join(rf"{_n4(w)} \cdot {_num(c[k])}"
                                  for w, c in zip(weights, colours))
            steps.append(rf"{channel.capitalize()}: ${products} = {_n4(colour[k])}$.")
        return Worked(steps, colour)


_SCREEN_WEIGHTS = ((0.5, 0.5, 0.0), (0.25, 0.25, 0.5), (0.5, 0.25, 0.25), (0.25, 0.5, 0.25),
                   (0.2, 0.3, 0.5), (0.6, 0.2, 0.2), (0.4, 0.4, 0.2), (0.5, 0.0, 0.5),
                   (0.0, 0.5, 0.5), (0.2, 0.4, 0.4))
_CORNERS = ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0))


class PerspectiveCorrect(_Chapter14):
    r"""Perspective-correct interpolation of texture coordinates:
    :math:`q = \frac{\sum \lambda_k q_k / w_k}{\sum \lambda_k / w_k}`.

    Attributes: ``weights`` (the screen-space barycentric weights of the pixel), ``w`` (the
    vertices' clip-space w), ``uv`` (one row of texture coordinates per vertex).

    Examples
    --------
    >>> ex = PerspectiveCorrect(seed=6)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.weights @ ex.uv).diagnosis
    'linear in screen space'
    """

    title = "Perspective-correct texture coordinates"
    answer_form = "vector"
    what = "the texture coordinates"
    advice = (r"Interpolate $q/w$ and $1/w$ linearly with the screen weights and divide: "
            r"$q = \frac{\sum_k \lambda_k q_k / w_k}{\sum_k \lambda_k / w_k}$.")

    def draw(self, rng):
        self.weights = np.array(pick(rng, _SCREEN_WEIGHTS))
        self.w = rng.integers(1, 5, size=3).astype(float)
        self.uv = np.array([_CORNERS[k] for k in rng.choice(4, size=3, replace=False)])
        self.expected = texturing.perspective_interpolate(self.uv, self.weights, self.w)

    def acceptable(self):
        return len(set(self.w)) > 1

    def mistakes(self):
        lam, w, q = self.weights, self.w, self.uv
        return [
            Mistake(lam @ q, r"You interpolated linearly in screen space. The perspective "
                    r"divide squeezes the far part of the triangle, so equal steps on the "
                    r"screen are unequal steps on the triangle. What *is* linear on the screen "
                    r"is $q/w$ and $1/w$: interpolate both and divide, "
                    r"$q = \frac{\sum \lambda_k q_k/w_k}{\sum \lambda_k/w_k}$.",
                    "linear in screen space"),
            Mistake((lam * w) @ q / (lam @ w), r"You weighted by $w$ instead of $1/w$: a "
                    r"far vertex (large $w$) must count **less** on the screen, where it "
                    r"looks small. Use $\lambda_k / w_k$.", "multiplied by w"),
            Mistake((lam / w) @ q, r"The division by $\sum_k \lambda_k / w_k$ is missing: "
                    r"$\sum \lambda_k q_k / w_k$ is $q/w$ at the pixel, not $q$.",
                    "no division by the sum"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {k} | {_num(self.w[k])} | ${_vec(self.uv[k])}$ |"
                         for k in range(3))
        lam = self.weights
        return (
            r"A pixel lies inside a projected triangle; its screen-space barycentric "
            rf"coordinates are $(\lambda_0, \lambda_1, \lambda_2) = {_vec(lam)}$. The triangle's "
            r"vertices have these clip-space $w$ (for a perspective camera, the depth in front "
            r"of the eye) and texture coordinates:" "\n\n"
            "| vertex | $w$ | $(u, v)$ |\n|---|---|---|\n" + rows + "\n\n"
            r"Which texture coordinates $(u, v)$ does **perspective-correct** interpolation "
            r"give at the pixel?" "\n\n" + _UV + "\n\n" + data_note("weights", "w", "uv")
            + " (`.uv[k]` belongs to vertex k.)")

    def hints(self):
        lam, w = self.weights, self.w
        over = lam / w
        return [r"On the screen, $q/w$ and $1/w$ vary linearly, $q$ itself does not: "
                r"interpolate $q/w$ and $1/w$ with the screen weights, then divide, "
                r"$q = \frac{\sum_k \lambda_k q_k / w_k}{\sum_k \lambda_k / w_k}$.",
                r"The weights over the depths: $\lambda_k / w_k = "
                + r",\ ".join(f"{_num(a)}/{_num(b)}" for a, b in zip(lam, w)) + " = "
                + r",\ ".join(_n4(x) for x in over) + "$.",
                rf"$\sum_k \lambda_k / w_k = {_n4(over.sum())}$, and "
                rf"$\sum_k \lambda_k q_k / w_k = {_vec(over @ self.uv)}$: divide."]

    def worked(self):
        lam, w = np.asarray(self.weights, dtype=float), np.asarray(self.w, dtype=float)
        uv = np.asarray(self.uv, dtype=float)
        over = [lam[k] / w[k] for k in range(3)]
        one_over_w = over[0] + over[1] + over[2]
        q_over_w = over[0] * uv[0] + over[1] * uv[1] + over[2] * uv[2]
        q = q_over_w / one_over_w
        return Worked([
            r"Divide each screen weight by its vertex's $w$: $\lambda_k / w_k = "
            + r",\ ".join(f"{_num(a)}/{_num(b)}" for a, b in zip(lam, w)) + " = "
            + r",\ ".join(_n4(x) for x in over) + "$.",
            rf"$1/w$ at the pixel: $\sum_k \lambda_k / w_k = {_n4(one_over_w)}$.",
            r"$q/w$ at the pixel: $\sum_k (\lambda_k / w_k)\, q_k = "
            + " + ".join(rf"{_n4(x)} \cdot {_vec(u)}" for x, u in zip(over, uv))
            + rf" = {_vec(q_over_w)}$.",
            rf"$q = \dfrac{{{_vec(q_over_w)}}}{{{_n4(one_over_w)}}} = "
            rf"({_n4(q[0])},\ {_n4(q[1])})$.",
        ], q)
