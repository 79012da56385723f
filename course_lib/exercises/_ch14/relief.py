"""Chapter 14 exercises: relief mapping (bump mapping, tangent frames, normal maps).

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here.
"""

import numpy as np

from ...texturing import relief
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _Chapter14, _n4, _num, _vec

__all__ = ["DecodeNormalTexel", "PerturbedNormal", "TangentFrame"]

_VECTOR = r"**Answer:** the vector as a list of 3 numbers `[x, y, z]`. " + DECIMALS


def _axis_frame(rng):
    """A right-handed orthonormal frame (T, B, N) of signed coordinate axes."""
    perm = rng.permutation(3)
    signs = rng.choice([-1.0, 1.0], size=3)
    m = np.eye(3)[perm] * signs[:, None]
    return m[0], m[1], np.cross(m[0], m[1])


def _unit(x):
    return x / np.linalg.norm(x)


class PerturbedNormal(_Chapter14):
    r"""The bump-mapped normal in a tangent frame: :math:`N' = \operatorname{normalize}(N -
    h_u T - h_v B)`.

    Attributes: ``T``, ``B``, ``N`` (an orthonormal frame of signed axes), ``h_u``, ``h_v``
    (the height map's derivatives, already scaled).

    Examples
    --------
    >>> ex = PerturbedNormal(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.N - ex.h_u * ex.T - ex.h_v * ex.B).diagnosis
    'not normalised'
    """

    title = "A bump-mapped normal"
    answer_form = "vector"
    what = "the perturbed unit normal N'"
    advice = (r"In an orthonormal tangent frame the bumped normal is "
              r"$N' = \operatorname{normalize}(N - h_u T - h_v B)$: it tilts *against* the "
              r"slope.")

    def draw(self, rng):
        self.T, self.B, self.N = _axis_frame(rng)
        self.h_u = float(pick(rng, (-1.0, -0.75, -0.5, 0.5, 0.75, 1.0, 1.5)))
        self.h_v = float(pick(rng, (-1.0, -0.5, -0.25, 0.25, 0.5, 1.0, 2.0)))
        self.expected = relief.bump_normal_tangent(self.N, self.T, self.B, self.h_u, self.h_v)

    def acceptable(self):
        return abs(self.h_u) != abs(self.h_v)

    def mistakes(self):
        n, t, b, hu, hv = self.N, self.T, self.B, self.h_u, self.h_v
        return [
            Mistake(n - hu * t - hv * b, r"Not normalised: $N - h_u T - h_v B$ is longer than "
                    r"1; shading needs a unit normal, so divide by its length.",
                    "not normalised"),
            Mistake(_unit(n + hu * t + hv * b), r"The signs are wrong: the normal tilts "
                    r"**against** the slope (a surface rising along $T$ faces back towards "
                    r"$-T$), $N' \propto N - h_u T - h_v B$.", "signs flipped"),
            Mistake(_unit(n - hv * t - hu * b), r"$h_u$ and $h_v$ are swapped: the slope "
                    r"along $u$ tilts the normal along $T = \partial P/\partial u$, the slope "
                    r"along $v$ along $B$.", "T and B swapped"),
            Mistake(_unit(n - hu * t + hv * b),
                    r"One sign is wrong: both derivative terms are subtracted, "
                    r"$N' \propto N - h_u T - h_v B$ (from $N \times B = -T$ and "
                    r"$N \times T = B$ in Blinn's formula).", "one sign wrong"),
        ]

    def statement(self):
        return (
            r"A surface point has the orthonormal tangent frame "
            rf"$T = {_vec(self.T)}$, $B = {_vec(self.B)}$, $N = {_vec(self.N)}$ "
            r"($T = \partial P/\partial u$, $B = \partial P/\partial v$ of unit length). Its "
            rf"bump map has the derivatives $h_u = {_num(self.h_u)}$, "
            rf"$h_v = {_num(self.h_v)}$ there (heights along $+N$). Compute the perturbed "
            r"unit normal $N'$ used for shading." "\n\n" + _VECTOR + "\n\n"
            + data_note("T", "B", "N", "h_u", "h_v"))

    def hints(self):
        return [r"Blinn: $N' = N + h_u (N \times P_v) - h_v (N \times P_u)$ for $|N| = 1$; "
                r"with $P_u = T$, $P_v = B$ orthonormal, $N \times B = -T$ and "
                r"$N \times T = B$.",
                r"So $N' \propto N - h_u T - h_v B$: tilt away from the uphill direction.",
                r"Add the three vectors component by component, then divide by the length."]

    def worked(self):
        raw = self.N - self.h_u * self.T - self.h_v * self.B
        length = float(np.linalg.norm(raw))
        return Worked([
            rf"$N - h_u T - h_v B = {_vec(self.N)} - {_num(self.h_u)}\,{_vec(self.T)} - "
            rf"{_num(self.h_v)}\,{_vec(self.B)} = {_vec(raw)}$.",
            rf"Its length is $\sqrt{{{_n4(raw @ raw)}}} = {_n4(length)}$.",
            rf"$N' = {_vec(raw / length)}$.",
        ], raw / length)


class TangentFrame(_Chapter14):
    r"""The tangent :math:`T = \partial P/\partial u` or bitangent :math:`B = \partial P/\partial
    v` of a triangle from its corners and texture coordinates (the 2x2 solve).

    Attributes: ``P`` (3 corners), ``UV`` (their texture coordinates), ``which``
    (``"T"`` or ``"B"``).

    Examples
    --------
    >>> ex = TangentFrame(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The tangent frame of a triangle"
    answer_form = "vector"
    what = "the vector"
    advice = (r"Solve $E_1 = \Delta u_1 T + \Delta v_1 B$, $E_2 = \Delta u_2 T + \Delta v_2 B$: "
              r"$T = (\Delta v_2 E_1 - \Delta v_1 E_2)/d$, "
              r"$B = (\Delta u_1 E_2 - \Delta u_2 E_1)/d$, "
              r"$d = \Delta u_1 \Delta v_2 - \Delta u_2 \Delta v_1$.")

    def draw(self, rng):
        self.which = str(pick(rng, ("T", "B")))
        t = b = np.zeros(3)
        while np.linalg.norm(np.cross(t, b)) < 0.5:       # T and B span a plane
            t = rng.integers(-2, 3, size=3).astype(float)
            b = rng.integers(-2, 3, size=3).astype(float)
        p0 = rng.integers(-2, 3, size=3).astype(float)
        duv = np.zeros((2, 2))
        while abs(np.linalg.det(duv)) < 0.1:               # a texture triangle of some area
            duv = np.array([[pick(rng, (0.5, 1.0, 0.25)), pick(rng, (0.0, 0.25, 0.5))],
                            [pick(rng, (0.0, -0.25, 0.25)), pick(rng, (0.5, 1.0))]])
        self.UV = np.round(np.array([[0.25, 0.0], [0.25, 0.0], [0.25, 0.0]])
                           + np.vstack([[0, 0], duv]), 4)
        self.P = np.vstack([p0, p0 + duv[0, 0] * t + duv[0, 1] * b,
                            p0 + duv[1, 0] * t + duv[1, 1] * b])
        self._tb = (t, b)
        tt, bb, _ = relief.triangle_tangent_frame(self.P, self.UV)
        self.expected = tt if self.which == "T" else bb

    def acceptable(self):
        t, b = self._tb
        d = self.UV[1:] - self.UV[0]
        det = d[0, 0] * d[1, 1] - d[1, 0] * d[0, 1]
        return (abs(det) > 0.1 and np.linalg.norm(np.cross(t, b)) > 0.5
                and np.abs(self.P).max() <= 6)

    def _parts(self):
        e1, e2 = self.P[1] - self.P[0], self.P[2] - self.P[0]
        (du1, dv1), (du2, dv2) = self.UV[1] - self.UV[0], self.UV[2] - self.UV[0]
        return e1, e2, du1, dv1, du2, dv2, du1 * dv2 - du2 * dv1

    def mistakes(self):
        e1, e2, du1, dv1, du2, dv2, d = self._parts()
        t = (dv2 * e1 - dv1 * e2) / d
        b = (du1 * e2 - du2 * e1) / d
        other = b if self.which == "T" else t
        found = [
            Mistake(other, r"That is the other vector of the frame: $T = \partial P/\partial u$ "
                    r"goes with $u$, $B = \partial P/\partial v$ with $v$.", "T and B swapped"),
            Mistake(-self.expected, r"The sign of the determinant was lost: divide by "
                    r"$d = \Delta u_1 \Delta v_2 - \Delta u_2 \Delta v_1$ with its sign (a "
                    r"mirrored texture has $d < 0$).", "determinant sign"),
            Mistake(_unit(self.expected), r"Normalised: the question asks for "
                    r"$\partial P/\partial u$ itself (its length is how far the surface moves "
                    r"per unit of texture coordinate).", "normalised"),
        ]
        if self.which == "T":
            found.append(Mistake((dv1 * e1 - dv2 * e2) / d,
                                 r"The coefficients are swapped inside the inverse: "
                                 r"$T = (\Delta v_2 E_1 - \Delta v_1 E_2)/d$.",
                                 "inverse coefficients swapped"))
        else:
            found.append(Mistake((du2 * e2 - du1 * e1) / d,
                                 r"The coefficients are swapped inside the inverse: "
                                 r"$B = (\Delta u_1 E_2 - \Delta u_2 E_1)/d$.",
                                 "inverse coefficients swapped"))
        return found

    def statement(self):
        name = (r"the tangent $T = \partial P/\partial u$" if self.which == "T"
                else r"the bitangent $B = \partial P/\partial v$")
        corners = ", ".join(rf"$P_{k} = {_vec(self.P[k])}$ with $(u, v) = "
                            rf"({_num(self.UV[k, 0])}, {_num(self.UV[k, 1])})$" for k in range(3))
        return (rf"A triangle has the corners {corners}. The texture coordinates vary "
                r"linearly over it, so $P = P_0 + (u - u_0) T + (v - v_0) B$ on the "
                rf"triangle. Compute {name} (not normalised)." "\n\n" + _VECTOR + "\n\n"
                + data_note("P", "UV", "which"))

    def hints(self):
        e1, e2, du1, dv1, du2, dv2, d = self._parts()
        return [rf"Edges $E_1 = P_1 - P_0 = {_vec(e1)}$, $E_2 = P_2 - P_0 = {_vec(e2)}$; "
                rf"$(\Delta u_1, \Delta v_1) = ({_num(du1)}, {_num(dv1)})$, "
                rf"$(\Delta u_2, \Delta v_2) = ({_num(du2)}, {_num(dv2)})$.",
                rf"$d = \Delta u_1 \Delta v_2 - \Delta u_2 \Delta v_1 = {_n4(d)}$.",
                self.advice]

    def worked(self):
        e1, e2, du1, dv1, du2, dv2, d = self._parts()
        if self.which == "T":
            answer = (dv2 * e1 - dv1 * e2) / d
            step = (rf"$T = (\Delta v_2 E_1 - \Delta v_1 E_2)/d = ({_num(dv2)}\,{_vec(e1)} - "
                    rf"{_num(dv1)}\,{_vec(e2)})/{_n4(d)} = {_vec(answer)}$.")
        else:
            answer = (du1 * e2 - du2 * e1) / d
            step = (rf"$B = (\Delta u_1 E_2 - \Delta u_2 E_1)/d = ({_num(du1)}\,{_vec(e2)} - "
                    rf"{_num(du2)}\,{_vec(e1)})/{_n4(d)} = {_vec(answer)}$.")
        return Worked([rf"$E_1 = {_vec(e1)}$, $E_2 = {_vec(e2)}$.",
                       rf"$d = {_num(du1)} \cdot {_num(dv2)} - {_num(du2)} \cdot {_num(dv1)} = "
                       rf"{_n4(d)}$.", step], answer)


class DecodeNormalTexel(_Chapter14):
    r"""An 8-bit normal-map texel to a tangent-space normal, then to object space with a TBN.

    :math:`n_t = \operatorname{normalize}(2\,c/255 - 1)`, :math:`n = n_{t,x} T + n_{t,y} B +
    n_{t,z} N`.

    Attributes: ``texel`` (3 integers 0..255), ``T``, ``B``, ``N`` (orthonormal, signed axes).

    Examples
    --------
    >>> ex = DecodeNormalTexel(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Decoding a normal-map texel"
    answer_form = "vector"
    what = "the object-space unit normal"
    advice = (r"Decode $n_t = 2 c/255 - 1$ (and renormalise), then "
              r"$n = n_{t,x} T + n_{t,y} B + n_{t,z} N$.")

    _NICE = ((0.6, 0.0, 0.8), (0.0, 0.6, 0.8), (-0.6, 0.0, 0.8), (0.0, -0.8, 0.6),
             (0.48, 0.6, 0.64), (-0.36, 0.48, 0.8), (0.8, 0.0, 0.6), (0.0, 0.28, 0.96))

    def draw(self, rng):
        nt = np.array(pick(rng, self._NICE), float)
        self.texel = np.round(255 * (nt + 1) / 2).astype(int)
        self.T, self.B, self.N = _axis_frame(rng)
        self._nt = relief.decode_normals(self.texel.astype(np.uint8))
        self.expected = relief.tangent_to_object(self._nt, self.T, self.B, self.N)

    def acceptable(self):
        return not np.allclose(self.N, [0, 0, 1])

    def mistakes(self):
        m = np.stack([self.T, self.B, self.N], axis=-1)
        c = self.texel / 255.0
        return [
            Mistake(self._nt, r"That is the tangent-space normal $n_t$: it still has to be "
                    r"taken to object space, $n = n_{t,x} T + n_{t,y} B + n_{t,z} N$.",
                    "tangent frame ignored"),
            Mistake(_unit(m.T @ self._nt), r"The TBN matrix was transposed: tangent to object "
                    r"space is $M n_t$ with $T, B, N$ as the **columns** of $M$ "
                    r"($M^T$ goes the other way).", "TBN transposed"),
            Mistake(_unit(m @ c), r"The texel was not decoded to $[-1, 1]$: colours store "
                    r"$c = (n + 1)/2$, so $n = 2c - 1$ (with $c$ = texel/255).",
                    "not decoded"),
        ]

    def statement(self):
        return (rf"A tangent-space normal map has the 8-bit texel (R, G, B) = "
                rf"({', '.join(str(int(x)) for x in self.texel)}) at a surface point whose "
                rf"orthonormal tangent frame is $T = {_vec(self.T)}$, $B = {_vec(self.B)}$, "
                rf"$N = {_vec(self.N)}$ (object space). The map stores $c = (n + 1)/2$ in "
                r"each channel. Compute the object-space unit normal." "\n\n" + _VECTOR
                + "\n\n" + data_note("texel", "T", "B", "N"))

    def hints(self):
        return [r"Divide by 255 and undo $c = (n+1)/2$: $n_t = 2c - 1$, then renormalise "
                r"(8 bits round).",
                rf"Here $n_t \approx {_vec(np.round(self._nt, 3))}$.",
                r"Object space: $n = n_{t,x} T + n_{t,y} B + n_{t,z} N$."]

    def worked(self):
        raw = 2 * self.texel / 255.0 - 1
        nt = raw / np.linalg.norm(raw)
        answer = nt[0] * self.T + nt[1] * self.B + nt[2] * self.N
        return Worked([
            rf"$2c/255 - 1 = {_vec(np.round(raw, 4))}$; renormalised "
            rf"$n_t = {_vec(np.round(nt, 4))}$.",
            rf"$n = {_n4(nt[0])}\,T + {_n4(nt[1])}\,B + {_n4(nt[2])}\,N = "
            rf"{_vec(np.round(answer, 4))}$.",
        ], answer)
