r"""Chapter 18 exercises: vector-field topology (the class of a critical point from its
Jacobian) and one integration step in a gridded field (bilinear interpolation of the velocity).

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import numpy as np

from ... import format as fmt
from ...scivis import topology
from ..core import (DECIMALS, UNANSWERED, Feedback, Mistake, Worked, data_note,
                    has_placeholder, pick)
from . import _Chapter18, _num, _vec

__all__ = [
    "ClassifyCriticalPoint",
    "GriddedFieldStep",
]

# ---------------------------------------------------------------------------------------------
# The class of a critical point
# ---------------------------------------------------------------------------------------------

_TOPO_CLASSES = topology.CRITICAL_CLASSES
_TOPO_TARGETS = ("saddle", "attracting node", "repelling node", "attracting focus",
                 "repelling focus", "centre")


def _topo_slip(given, right, disc):
    """The diagnosis key of answering `given` when the class is `right`."""
    if given == "degenerate":
        return "degenerate"
    if right == "saddle":
        return "saddle missed"
    if given == "saddle":
        return "not a saddle"
    if given.endswith("node") and disc < 0:
        return "node for complex"
    if not given.endswith("node") and disc >= 0:
        return "focus for real"
    if "centre" in (given, right):
        return "centre vs focus"
    return "attracting vs repelling"


def _affine(a, b, e):
    """LaTeX of a x + b y + e with whole coefficients."""
    text = ""
    for coef, var in ((a, "x"), (b, "y"), (e, "")):
        if coef == 0:
            continue
        size = _num(abs(coef)) if (abs(coef) != 1 or not var) else ""
        sign = "-" if coef < 0 else ("+" if text else "")
        text += (f" {sign} " if text else sign) + size + var
    return text or "0"


class ClassifyCriticalPoint(_Chapter18):
    r"""The class of the critical point of an affine field, from the eigenvalues of its Jacobian.

    :math:`v(x, y) = J\,(x, y)^T + c`: the Jacobian is J everywhere; with
    :math:`\tau = \operatorname{tr} J`, :math:`\Delta = \det J`, the eigenvalues are
    :math:`\tfrac12(\tau \pm \sqrt{\tau^2 - 4\Delta})`: :math:`\Delta < 0` saddle; complex
    (negative discriminant) focus or centre; real of one sign node; the sign of :math:`\tau`
    says attracting or repelling.

    Attributes: ``J`` (2 x 2), ``c`` (the constant term), ``point`` (the critical point).

    Examples
    --------
    >>> ex = ClassifyCriticalPoint(seed=0)
    >>> ex.check(topology.classify_critical_point(ex.J).kind).status
    'correct'
    >>> ClassifyCriticalPoint(seed=0).check("degenerate").diagnosis
    'degenerate'
    """

    title = "Classify a critical point"
    answer_form = "custom"
    what = "the class"
    advice = (r"Compute the trace $\tau$, the determinant $\Delta$ and the discriminant "
              r"$\tau^2 - 4\Delta$ of the Jacobian: $\Delta < 0$ saddle; discriminant $< 0$ "
              r"focus (centre if $\tau = 0$); otherwise node; $\tau < 0$ attracting.")

    def draw(self, rng):
        target = pick(rng, _TOPO_TARGETS)
        for _ in range(500):
            j = rng.integers(-3, 4, size=(2, 2)).astype(float)
            if target == "centre":
                j[1, 1] = -j[0, 0]
            if topology.classify_critical_point(j).kind == target:
                break
        self.J = j
        self.point = rng.integers(-2, 3, size=2).astype(float)
        self.c = -(j @ self.point)
        cl = topology.classify_critical_point(j)
        self.expected = cl.kind
        self.eigenvalues = cl.eigenvalues

    def _numbers(self):
        j = self.J
        tr = float(j[0, 0] + j[1, 1])
        det = float(j[0, 0] * j[1, 1] - j[0, 1] * j[1, 0])
        return tr, det, tr * tr - 4 * det

    def _why(self, given):
        tr, det, disc = self._numbers()
        key = _topo_slip(given, self.expected, disc)
        facts = (rf"Here $\tau = {_num(tr)}$, $\Delta = {_num(det)}$, "
                 rf"$\tau^2 - 4\Delta = {_num(disc)}$. ")
        text = {
            "degenerate": r"Degenerate means a zero eigenvalue, $\Delta = 0$; here the "
                          r"determinant is not zero, so the point is isolated and the "
                          r"eigenvalues decide a proper class.",
            "saddle missed": r"The determinant is negative: the eigenvalues are real with "
                             r"opposite signs (their product is $\Delta < 0$), which makes a "
                             r"**saddle**, whatever the trace.",
            "not a saddle": r"A saddle needs eigenvalues of opposite signs, i.e. $\Delta < 0$; "
                            r"here $\Delta > 0$.",
            "node for complex": r"The discriminant is negative: the eigenvalues are a complex "
                                r"pair, so the flow turns around the point (a focus, or a "
                                r"centre if the real part is 0), it is not a node.",
            "focus for real": r"The discriminant is not negative: the eigenvalues are real, the "
                              r"flow does not turn around the point, so it is a node, not a "
                              r"focus or centre.",
            "centre vs focus": r"A centre has purely imaginary eigenvalues ($\tau = 0$); a "
                               r"non-zero trace makes the spiral tighten or widen: a focus. "
                               r"Look at the trace.",
            "attracting vs repelling": r"The sign is the trace's (the sum of the eigenvalues, "
                                       r"or twice their real part): negative attracts, positive "
                                       r"repels.",
        }[key]
        return facts + text, key

    def mistakes(self):
        return [Mistake(c, self._why(c)[0], self._why(c)[1], numeric=False)
                for c in _TOPO_CLASSES if c != self.expected]

    def separated(self, mistakes):
        return True

    def keep(self, mistakes):
        return mistakes

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        if not isinstance(answer, str):
            return Feedback("invalid", "Give the class as one name (a string) from the list.",
                            "unreadable")
        given = " ".join(answer.strip().lower().replace("_", " ").replace("-", " ").split())
        given = {"center": "centre", "attracting spiral": "attracting focus",
                 "repelling spiral": "repelling focus", "spiral sink": "attracting focus",
                 "spiral source": "repelling focus", "sink": "attracting node",
                 "source": "repelling node", "stable node": "attracting node",
                 "unstable node": "repelling node", "stable focus": "attracting focus",
                 "unstable focus": "repelling focus"}.get(given, given)
        if given not in _TOPO_CLASSES:
            return Feedback("invalid", f"{answer!r} is not one of the classes: "
                            + ", ".join(f"`'{c}'`" for c in _TOPO_CLASSES) + ".", "unreadable")
        if given == self.expected:
            return Feedback("correct", f"Right: {self.expected}.")
        text, key = self._why(given)
        return Feedback("wrong", text, key)

    def statement(self):
        (a, b), (c, d) = self.J
        return (
            rf"The velocity field $v(x, y) = ({_affine(a, b, self.c[0])},\ "
            rf"{_affine(c, d, self.c[1])})$ has one critical point, at "
            rf"${_vec(self.point)}$ (check: $v = 0$ there). Classify it from the eigenvalues of "
            r"the Jacobian." "\n\n"
            r"**Answer:** one of the strings " + ", ".join(f"`'{k}'`" for k in _TOPO_CLASSES)
            + ".\n\n" + data_note("J", "c", "point"))

    def hints(self):
        tr, det, disc = self._numbers()
        return [
            r"The Jacobian of an affine field is its matrix of coefficients: "
            r"$J = \begin{bmatrix} \partial u/\partial x & \partial u/\partial y \\ "
            r"\partial v/\partial x & \partial v/\partial y \end{bmatrix}$, the same everywhere.",
            rf"$J = {fmt.matrix_latex(self.J)}$: trace $\tau = {_num(tr)}$, determinant "
            rf"$\Delta = {_num(det)}$.",
            rf"The discriminant $\tau^2 - 4\Delta = {_num(disc)}$: negative means complex "
            r"eigenvalues (focus or centre), otherwise real ones (node, or saddle if "
            r"$\Delta < 0$).",
        ]

    def worked(self):
        tr, det, disc = self._numbers()
        lam = self.eigenvalues
        if disc >= 0:
            ev = rf"$\lambda = {_num(lam[0].real, 4)}$ and ${_num(lam[1].real, 4)}$ (real)"
        else:
            ev = (rf"$\lambda = {_num(tr / 2, 4)} \pm {_num(abs(lam[0].imag), 4)}\,i$ "
                  r"(a complex pair)")
        return Worked([
            rf"The Jacobian is the matrix of the linear part: $J = {fmt.matrix_latex(self.J)}$.",
            rf"$\tau = {_num(tr)}$, $\Delta = {_num(det)}$, "
            rf"$\tau^2 - 4\Delta = {_num(disc)}$, so "
            r"$\lambda = \tfrac12(\tau \pm \sqrt{\tau^2 - 4\Delta})$ gives " + ev + ".",
            topology.classify_critical_point(self.J).reason.capitalize()
            + f": a **{self.expected}**.",
        ], self.expected)


# ---------------------------------------------------------------------------------------------
# One step in a gridded field
# ---------------------------------------------------------------------------------------------

_FRACTIONS = (0.2, 0.25, 0.4, 0.6, 0.75, 0.8)


class GriddedFieldStep(_Chapter18):
    r"""One Euler or midpoint (RK2) step in a gridded field, the velocity interpolated
    bilinearly inside the cell.

    At local coordinates :math:`s = (x - x_0)/\Delta`, :math:`t = (y - y_0)/\Delta`:
    :math:`v = (1-s)(1-t)v_{00} + s(1-t)v_{10} + (1-s)t\,v_{01} + st\,v_{11}`; Euler
    :math:`p' = p + h\,v(p)`, RK2 :math:`p' = p + h\,v(p + \tfrac h2 v(p))`.

    Attributes: ``corners`` (dict "00", "10", "01", "11" -> velocity), ``x0``, ``y0``,
    ``spacing``, ``p``, ``h``, ``method``.

    Examples
    --------
    >>> ex = GriddedFieldStep(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(ex.p + ex.h * ex.corners["00"]).status
    'wrong'
    """

    title = "A step in a gridded field"
    answer_form = "point"
    what = "the new point"
    advice = (r"Find the local coordinates $s, t$ of the point in its cell, weight each corner "
              r"by the area of the opposite sub-rectangle ($s$ goes with the corners on the "
              r"right, $t$ with those on top), then step: $p + h\,v$.")

    def draw(self, rng):
        self.spacing = float(pick(rng, (1.0, 0.5, 2.0)))
        self.x0, self.y0 = (float(v) * self.spacing for v in rng.integers(-2, 3, size=2))
        vs = rng.integers(-3, 4, size=(4, 2)).astype(float)
        self.corners = dict(zip(("00", "10", "01", "11"), vs))
        self.s = float(pick(rng, _FRACTIONS))
        self.t = float(pick(rng, _FRACTIONS))
        self.p = np.array([self.x0 + self.s * self.spacing, self.y0 + self.t * self.spacing])
        self.h = float(pick(rng, (0.1, 0.2, 0.25, 0.5)))
        self.method = pick(rng, ("euler", "euler", "rk2"))
        self._grid = (np.array([[vs[0], vs[1]], [vs[2], vs[3]]]))
        self.expected = self._step(self._interp)

    def _interp(self, q):
        """Bilinear velocity at q (inside the cell)."""
        return topology.bilinear_velocity(self._grid[..., 0], self._grid[..., 1], q[0], q[1],
                                          self.spacing, (self.x0, self.y0))

    def _local(self, q):
        return (q[0] - self.x0) / self.spacing, (q[1] - self.y0) / self.spacing

    def _weights_v(self, s, t):
        c = self.corners
        return ((1 - s) * (1 - t) * c["00"] + s * (1 - t) * c["10"] + (1 - s) * t * c["01"]
                + s * t * c["11"])

    def _step(self, velocity, h=None):
        h = self.h if h is None else h
        k1 = velocity(self.p)
        if self.method == "euler":
            return self.p + h * k1
        return self.p + h * velocity(self.p + 0.5 * h * k1)

    def acceptable(self):
        if self.method == "rk2":
            mid = self.p + 0.5 * self.h * self._interp(self.p)
            s, t = self._local(mid)
            if not (0 <= s <= 1 and 0 <= t <= 1):
                return False
        return bool(np.abs(self._interp(self.p)).max() > 0.4)

    def mistakes(self):
        def nearest(q):
            s, t = np.clip(self._local(q), 0, 1)
            return self.corners[f"{int(s > 0.5)}{int(t > 0.5)}"]

        def swapped(q):
            s, t = self._local(q)
            return self._weights_v(t, s)

        def mirrored(q):
            s, t = self._local(q)
            return self._weights_v(1 - s, 1 - t)

        out = [
            Mistake(self._step(nearest), r"You used the velocity of the **nearest node**; in a "
                    r"gridded field the velocity between the nodes is the bilinear blend of the "
                    r"four corners.", "nearest node"),
            Mistake(self._step(swapped), r"You **swapped the weights**: $s$ (the fraction "
                    r"along x) weights the right-hand corners $v_{10}, v_{11}$, and $t$ (along y) "
                    r"the top ones $v_{01}, v_{11}$.", "swapped weights"),
            Mistake(self._step(mirrored), r"Each corner's weight is the area of the "
                    r"sub-rectangle **opposite** it: $v_{00}$ gets $(1-s)(1-t)$, not $st$. You "
                    r"gave each corner its own rectangle's weight.", "mirrored weights"),
            Mistake(self._step(lambda q: self.corners["00"]), r"You used the velocity at the "
                    r"cell's **lower-left corner** $v_{00}$ for the whole cell; interpolate the "
                    r"four corners at the point.", "wrong corner"),
            Mistake(self.p + (self.expected - self.p) / self.h, r"You forgot the **step size**: "
                    r"the point "
                    r"moves by $h\,v$, not by $v$.", "no h"),
        ]
        if self.method == "rk2":
            out.append(Mistake(self.p + self.h * self._interp(self.p), r"That is an **Euler** "
                               r"step, with the velocity at the start; the midpoint method takes "
                               r"the velocity half a step ahead, $v(p + \tfrac h2 v(p))$.",
                               "euler"))
        return out

    def statement(self):
        c = self.corners
        d = self.spacing
        name = ("one **Euler** step, $p' = p + h\\,v(p)$" if self.method == "euler" else
                "one **midpoint (RK2)** step, $p' = p + h\\,v(p + \\tfrac h2 v(p))$")
        return (
            rf"A 2D velocity field is given on a grid of spacing $\Delta = {_num(d)}$. The cell "
            rf"$[{_num(self.x0)}, {_num(self.x0 + d)}] \times [{_num(self.y0)}, "
            rf"{_num(self.y0 + d)}]$ has the corner velocities "
            rf"$v_{{00}} = {_vec(c['00'])}$ at $({_num(self.x0)}, {_num(self.y0)})$, "
            rf"$v_{{10}} = {_vec(c['10'])}$ at $({_num(self.x0 + d)}, {_num(self.y0)})$, "
            rf"$v_{{01}} = {_vec(c['01'])}$ at $({_num(self.x0)}, {_num(self.y0 + d)})$ and "
            rf"$v_{{11}} = {_vec(c['11'])}$ at $({_num(self.x0 + d)}, {_num(self.y0 + d)})$. "
            rf"Interpolating the velocity bilinearly, trace a streamline from "
            rf"$p = {_vec(self.p)}$ with {name}, $h = {_num(self.h)}$." "\n\n"
            r"**Answer:** the point $p'$ as a list of 2 numbers `[x, y]`. " + DECIMALS + "\n\n"
            + data_note("corners", "x0", "y0", "spacing", "p", "h", "method"))

    def _lines(self, q, name):
        """The interpolation at q, in words and numbers."""
        s, t = self._local(q)
        w = ((1 - s) * (1 - t), s * (1 - t), (1 - s) * t, s * t)
        v = self._interp(q)
        return (rf"At ${name} = {_vec(q, 4)}$: $s = {_num(s, 4)}$, $t = {_num(t, 4)}$; weights "
                rf"$v_{{00}}$: {_num(w[0], 4)}, $v_{{10}}$: {_num(w[1], 4)}, $v_{{01}}$: "
                rf"{_num(w[2], 4)}, $v_{{11}}$: {_num(w[3], 4)}, so $v({name}) = {_vec(v, 4)}$.")

    def hints(self):
        s, t = self._local(self.p)
        return [
            r"Bilinear interpolation: $v = (1-s)(1-t)\,v_{00} + s(1-t)\,v_{10} + (1-s)\,t\,v_{01} "
            r"+ s\,t\,v_{11}$, with $s, t$ the point's fractions across the cell.",
            rf"$s = (x - x_0)/\Delta = {_num(s)}$ and $t = (y - y_0)/\Delta = {_num(t)}$.",
            rf"Then move: $p' = p + h\,v$ with $h = {_num(self.h)}$"
            + (r", using the velocity at the midpoint $p + \tfrac h2 v(p)$." if
               self.method == "rk2" else "."),
        ]

    def worked(self):
        steps = [self._lines(self.p, "p")]
        v = self._interp(self.p)
        if self.method == "rk2":
            mid = self.p + 0.5 * self.h * v
            steps.append(rf"Half a step: $p + \tfrac h2 v(p) = {_vec(mid, 4)}$.")
            steps.append(self._lines(mid, "m"))
            v = self._interp(mid)
        new = self.p + self.h * v
        steps.append(rf"$p' = p + h\,v = {_vec(self.p)} + {_num(self.h)} \cdot {_vec(v, 4)} = "
                     rf"{_vec(new, 4)}$.")
        return Worked(steps, new)
