"""Chapter 14 exercises: texture transformations and two-part mapping.

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import math

import numpy as np

from ... import transforms
from ...texturing import two_part_map
from ..core import Mistake, Worked, data_note, pick
from . import _UV, _Chapter14, _n4, _num, _vec

__all__ = ["TextureTransform", "TwoPartMapping"]


def _matrix(ku, kv, theta, order="tile first", about=(0.5, 0.5)):
    s = transforms.scale([ku, kv])
    r = transforms.rotate_about(theta, about)
    return r @ s if order == "tile first" else s @ r


class TextureTransform(_Chapter14):
    r"""The coordinates a texture matrix "tile k_u x k_v, then rotate by theta about the
    texture's centre" gives a point: :math:`M = T(c) R(\theta) T(-c)\, S(k_u, k_v)`.

    Attributes: ``ku``, ``kv``, ``degrees``, ``uv`` (the point's coordinates).

    Examples
    --------
    >>> ex = TextureTransform(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "A texture matrix"
    answer_form = "vector"
    what = "the transformed texture coordinates (u', v')"
    advice = (r"The first transformation to act stands rightmost: $M = R_c(\theta)\,S(k_u, k_v)$ "
              r"with $R_c(\theta) = T(c)\,R(\theta)\,T(-c)$, $c = (\tfrac12, \tfrac12)$; apply "
              r"it to $(u, v, 1)$.")

    def draw(self, rng):
        self.ku = float(pick(rng, (1, 2, 3, 4)))
        self.kv = float(pick(rng, (2, 3, 4)))
        self.degrees = float(pick(rng, (90, -90, 180)))
        self.uv = np.array([float(pick(rng, np.arange(0.1, 0.95, 0.1).round(1))),
                            float(pick(rng, np.arange(0.1, 0.95, 0.1).round(1)))])
        m = _matrix(self.ku, self.kv, math.radians(self.degrees))
        self.expected = (m @ [*self.uv, 1.0])[:2].round(12) + 0.0

    def acceptable(self):
        return self.ku != self.kv or self.degrees != 180

    def mistakes(self):
        th = math.radians(self.degrees)
        p = [*self.uv, 1.0]
        found = [
            Mistake((_matrix(self.ku, self.kv, th, "rotate first") @ p)[:2], r"The order is "
                    r"reversed: you rotated first and tiled afterwards, "
                    r"$S\,R_c$. With column vectors the transformation applied first stands "
                    r"**rightmost**: tile first, then rotate, is $M = R_c\,S$.",
                    "wrong order"),
            Mistake((np.linalg.inv(_matrix(self.ku, self.kv, th)) @ p)[:2], r"That is "
                    r"$M^{-1}(u, v)$: where the *picture's* feature at $(u, v)$ moves to. The "
                    r"sampler looks up $M (u, v)$, the coordinates themselves transformed (the "
                    r"picture moves the opposite way, by $M^{-1}$).", "inverse"),
            Mistake((_matrix(self.ku, self.kv, th, about=(0, 0)) @ p)[:2], r"You rotated "
                    r"about the origin $(0, 0)$, the texture's corner. About the centre: move "
                    r"$c$ to the origin, rotate, move back, $T(c)\,R(\theta)\,T(-c)$.",
                    "rotated about the origin"),
        ]
        if self.degrees != 180:
            found.append(Mistake((_matrix(self.ku, self.kv, -th) @ p)[:2], r"The rotation "
                                 r"turns the wrong way: a positive angle is counter-clockwise, "
                                 r"$(x, y) \mapsto (x\cos\theta - y\sin\theta,\ x\sin\theta + "
                                 r"y\cos\theta)$.", "rotation sign"))
        found.append(Mistake((_matrix(1 / self.ku, 1 / self.kv, th) @ p)[:2], r"Tiling "
                             r"$k$ times **multiplies** the coordinates by $k$ (they run over "
                             r"$[0, k]$ and the repeat wrap shows $k$ copies); dividing by $k$ "
                             r"would enlarge the picture instead.", "divided by the tiling"))
        return found

    def statement(self):
        return (
            rf"A texture matrix first tiles the texture ${_num(self.ku)} \times "
            rf"{_num(self.kv)}$ times (repeats in $u$ and $v$), then rotates the coordinates by "
            rf"${_num(self.degrees)}°$ about the texture's centre $c = (\tfrac12, \tfrac12)$. "
            rf"A surface point has texture coordinates $(u, v) = {_vec(self.uv)}$. Which "
            r"coordinates $(u', v')$ does the sampler look up (before the wrap mode)?"
            "\n\n" + _UV + "\n\n" + data_note("ku", "kv", "degrees", "uv"))

    def hints(self):
        u, v = self.uv
        return [r"Write $M = T(c)\,R(\theta)\,T(-c)\,S(k_u, k_v)$ (rightmost first) or do the "
                r"steps one at a time on the point.",
                rf"Tiling: $(k_u u, k_v v) = ({_num(self.ku * u)}, {_num(self.kv * v)})$.",
                r"Rotating about $c$: subtract $c$, rotate, add $c$ back."]

    def worked(self):
        u, v = self.uv
        su, sv = self.ku * u, self.kv * v
        th = math.radians(self.degrees)
        du, dv = su - 0.5, sv - 0.5
        c, s = round(math.cos(th), 12) + 0.0, round(math.sin(th), 12) + 0.0
        ru, rv = c * du - s * dv, s * du + c * dv
        return Worked([
            rf"Tile: $(u, v) \mapsto ({_num(self.ku)} \cdot {_num(u)}, {_num(self.kv)} \cdot "
            rf"{_num(v)}) = ({_n4(su)}, {_n4(sv)})$.",
            rf"Relative to the centre: $({_n4(du)}, {_n4(dv)})$; rotate by "
            rf"${_num(self.degrees)}°$ ($\cos = {_num(c)}$, $\sin = {_num(s)}$): "
            rf"$({_n4(ru)}, {_n4(rv)})$.",
            rf"Add the centre back: $(u', v') = ({_n4(ru + 0.5)}, {_n4(rv + 0.5)})$.",
        ], [ru + 0.5, rv + 0.5])


_METHOD_WORDS = {"normal": "on the ray from $P$ along the object's normal $N$",
                 "centroid": "on the ray from the object's centroid, the origin, through $P$ "
                             "(beyond $P$)",
                 "intermediate_normal": "whose own normal line passes through $P$ (the "
                                        "intermediate surface's normal method)"}


class TwoPartMapping(_Chapter14):
    r"""Two-part mapping with the cylinder: O-map the object point P to the cylinder (by the
    object's normal, the centroid's line or the cylinder's normal), then S-map it.

    The cylinder has radius :math:`s`, the y axis through the origin, and
    :math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`, :math:`v = (y + s)/2s`.

    Attributes: ``method``, ``radius``, ``P``, ``N`` (for ``"normal"``; not unit).

    Examples
    --------
    >>> ex = TwoPartMapping(seed=5)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Two-part mapping onto a cylinder"
    answer_form = "vector"
    what = "the texture coordinates (u, v)"
    may_coincide = ("atan instead of atan2",)
    advice = (r"First the O-mapping: find $Q$ on the cylinder $x^2 + z^2 = s^2$. Then the "
              r"S-mapping of $Q$: $u = \tfrac12 + \operatorname{atan2}(Q_x, Q_z)/2\pi$, "
              r"$v = (Q_y + s)/2s$.")

    def draw(self, rng):
        self.method = str(pick(rng, ("normal", "centroid", "intermediate_normal")))
        self.radius = 5.0
        qx, qz = pick(rng, ((3, 4), (4, 3), (-3, 4), (3, -4), (-4, -3), (4, -3), (-4, 3),
                            (0, 5), (5, 0), (-5, 0), (0, -5), (-3, -4)))
        if self.method == "normal":
            n = np.array(pick(rng, ((3, 0, 4), (4, 0, 3), (0, 0, 1), (1, 0, 0), (-3, 0, 4),
                                    (4, 0, -3), (-1, 0, 0), (0, 0, -1))), float)
            t = float(pick(rng, (1, 2, 3)))
            y = float(pick(rng, (-2, -1, 1, 2, 3)))
            self.N = n
            self.P = np.array([qx, y, qz], float) - t * n / np.linalg.norm(n)
        else:
            f = float(pick(rng, (0.2, 0.4, 0.5)))
            y = float(pick(rng, (-0.8, -0.4, 0.4, 0.6, 0.8, 1.2)))
            self.N = None
            self.P = np.array([qx * f, y, qz * f])
        self.P = self.P.round(10) + 0.0
        u, v = two_part_map([self.P], None if self.N is None else [self.N], "cylinder",
                            self.method, size=self.radius, centroid=(0, 0, 0))
        self.expected = np.array([float(u[0]), float(v[0])])

    def acceptable(self):
        p = self.P
        return bool(np.hypot(p[0], p[2]) < self.radius - 0.5 and np.isfinite(self.expected).all()
                    and abs(self.expected[1] - 0.5) > 0.02)

    def _q(self, method):
        s, p = self.radius, self.P
        if method == "intermediate_normal":
            return np.array([p[0], 0, p[2]]) * s / math.hypot(p[0], p[2]) + [0, p[1], 0]
        if method == "centroid":
            return p * s / math.hypot(p[0], p[2])
        n = self.N / np.linalg.norm(self.N)
        a, b, c = n[0] ** 2 + n[2] ** 2, p[0] * n[0] + p[2] * n[2], p[0] ** 2 + p[2] ** 2 - s * s
        return p + (-b + math.sqrt(b * b - a * c)) / a * n

    def _uv(self, q):
        return [0.5 + math.atan2(q[0], q[2]) / (2 * math.pi), (q[1] + self.radius) /
                (2 * self.radius)]

    def mistakes(self):
        q = self._q(self.method)
        u, v = self.expected
        found = [
            Mistake([v, u], r"$u$ and $v$ are swapped: $u$ goes around the axis, $v$ along "
                    r"it.", "u and v swapped"),
            Mistake([u, q[1] / (2 * self.radius)], r"$v$ is measured from the cylinder's "
                    r"middle: texture space starts at its bottom, $y = -s$, so "
                    r"$v = (Q_y + s)/2s$.", "v from the middle"),
        ]
        if q[2] != 0:
            found.append(Mistake([0.5 + math.atan(q[0] / q[2]) / (2 * math.pi), v],
                                 r"$\tan^{-1}(x/z)$ covers only half the circle; use "
                                 r"$\operatorname{atan2}(x, z)$.", "atan instead of atan2"))
        others = {"normal": "the object's normal", "centroid": "the centroid's line",
                  "intermediate_normal": "the cylinder's normal (radial projection)"}
        for m in ("centroid", "intermediate_normal"):
            if m != self.method:
                found.append(Mistake(self._uv(self._q(m)), rf"That O-maps by {others[m]}, not "
                                     rf"{others[self.method]}: the methods send $P$ to "
                                     r"different points $Q$ of the cylinder.",
                                     f"O-mapped by the {m.replace('_', ' ')}"))
        return found

    def statement(self):
        normal = (rf", with normal $N = {_vec(self.N)}$ (not normalized)" if self.N is not None
                  else "")
        return (
            rf"Two-part mapping with a cylinder as the intermediate surface: radius "
            rf"$s = {_num(self.radius)}$, axis the $y$ axis through the origin, S-mapping "
            r"$u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi$, $v = (y + s)/2s$ (the cylinder "
            rf"from $y = -s$ to $y = s$ covers $v \in [0, 1]$). The object point is "
            rf"$P = {_vec(self.P)}$" + normal + r". The O-mapping sends $P$ to the point $Q$ of the cylinder "
            + _METHOD_WORDS[self.method] + r". Give $(u, v)$."
            "\n\n" + _UV + "\n\n" + data_note("method", "radius", "P", "N"))

    def hints(self):
        return [r"O-mapping first: the point $Q$ must satisfy $Q_x^2 + Q_z^2 = s^2$.",
                {"normal": r"Solve $|P_{xz} + t N_{xz}|^2 = s^2$ for $t > 0$ (unit $N$).",
                 "centroid": r"$Q = \lambda P$ with $\lambda = s/\sqrt{P_x^2 + P_z^2}$: the "
                             r"height scales too.",
                 "intermediate_normal": r"The cylinder's normals are horizontal: keep $Q_y = "
                                        r"P_y$ and push $(P_x, P_z)$ out to radius $s$."}[
                    self.method],
                r"Then $u$ from $\operatorname{atan2}(Q_x, Q_z)$ and $v$ from $Q_y$."]

    def worked(self):
        q = self._q(self.method)
        u, v = self._uv(q)
        return Worked([
            rf"O-mapping ({self.method.replace('_', ' ')}): $Q = {_vec(q.round(4) + 0.0)}$, on "
            rf"the cylinder: $Q_x^2 + Q_z^2 = {_n4(q[0] ** 2 + q[2] ** 2)}$.",
            rf"$u = 0.5 + \operatorname{{atan2}}({_n4(q[0])}, {_n4(q[2])})/2\pi = {_n4(u)}$.",
            rf"$v = ({_n4(q[1])} + {_num(self.radius)})/{_num(2 * self.radius)} = {_n4(v)}$.",
        ], [u, v])
