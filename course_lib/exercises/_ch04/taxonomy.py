r"""Chapter 4 exercises: the taxonomy of planar projections and vanishing points.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here. The expected
answers come from :mod:`course_lib.projections` (and :mod:`course_lib.viewing`).
"""

import math

import numpy as np

from ... import projections, viewing
from ..core import DECIMALS, DrawnExercise, Feedback, Mistake, Worked, data_note, pick
from ..core import has_placeholder, UNANSWERED
from . import _POINT_3, PointAnswer, _mat, _num, _par, _snap, _vec

__all__ = [
    "AxonometricForeshortening",
    "CabinetMatrix",
    "CameraVanishingPoint",
    "ClassifyProjection",
    "PlaneProjectionPoint",
    "PrincipalVanishingCount",
]


def _pmat(m):
    return _mat(np.round(np.asarray(m, dtype=float), 4) + 0.0)


class CameraVanishingPoint(PointAnswer, DrawnExercise):
    r"""The vanishing point of a direction under a perspective projection onto a plane.

    The matrix :math:`M` projects from a centre :math:`c` onto a plane :math:`n \cdot x = h`
    (:func:`course_lib.projections.project_onto_plane`). The vanishing point of the direction
    :math:`u` is :math:`M (u, 0)` divided by its :math:`w = n \cdot u`.

    Attributes: ``matrix``, ``u`` (the direction), ``p0`` (a point of one of the lines),
    ``centre``, ``normal``, ``h``.

    Examples
    --------
    >>> ex = CameraVanishingPoint(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check((ex.matrix @ [*ex.u, 0])[:3]).diagnosis
    'no divide'
    """

    title = "A vanishing point under a projection matrix"
    what = "the vanishing point"

    def draw(self, rng):
        self.normal = np.array(pick(rng, [(0, 0, 1), (0, 1, 0), (1, 0, 0), (1, 1, 0), (0, 1, 1),
                                          (1, 0, 1)]), dtype=float)
        self.centre = rng.integers(-2, 3, size=3).astype(float)
        self.h = float(self.normal @ self.centre + pick(rng, (-4, -3, -2, 2, 3, 4)))
        self.u = rng.integers(-2, 3, size=3).astype(float)
        self.p0 = rng.integers(-3, 4, size=3).astype(float)
        m = np.zeros((4, 4))
        gap = self.h - self.normal @ self.centre
        m[:3, :3] = gap * np.eye(3) + np.outer(self.centre, self.normal)
        m[:3, 3] = -self.h * self.centre
        m[3, :3] = self.normal
        m[3, 3] = -self.normal @ self.centre
        self.matrix = m
        if abs(self.normal @ self.u) not in (1.0, 2.0, 4.0):
            self.expected = None
            return
        vp = projections.vanishing_point(projections.project_onto_plane(
            self.normal * self.h / (self.normal @ self.normal), self.normal, centre=self.centre),
            self.u)
        self.expected = None if vp is None else _snap(vp)

    def acceptable(self):
        w_point = self.matrix[3] @ np.append(self.p0, 1.0)
        w_dir1 = self.matrix[3] @ np.append(self.u, 1.0)
        return (self.expected is not None and abs(self.normal @ self.u) in (1.0, 2.0, 4.0)
                and w_point != 0 and w_dir1 != 0 and np.count_nonzero(self.u) >= 2)

    def mistakes(self):
        hom = self.matrix @ np.append(self.u, 0.0)
        as_point = self.matrix @ np.append(self.u, 1.0)
        image = self.matrix @ np.append(self.p0, 1.0)
        return [
            Mistake(hom[:3], r"You computed $M\,(u, 0)$ but did not divide by its last "
                    rf"coordinate $w = {_num(hom[3])}$: a homogeneous result is a point only "
                    r"after the divide.", "no divide"),
            Mistake(as_point[:3] / as_point[3], r"You gave the direction the homogeneous "
                    r"coordinate $w = 1$, which makes it the **point** $u$ (a position), not "
                    r"a direction. A direction is the point at infinity $(u, 0)$: $w = 0$.",
                    "w = 1 for the direction"),
            Mistake(image[:3] / image[3], r"That is the image of the point $p_0$, which depends "
                    r"on which line you take. The vanishing point is where the images of all "
                    r"the parallel lines meet: the image of their direction $(u, 0)$.",
                    "projected a point"),
        ]

    def statement(self):
        return (
            r"A perspective projection onto a plane (centre of projection $c$, the image points "
            r"lie on the plane) has the matrix" "\n\n"
            rf"$$M = {_pmat(self.matrix)}.$$" "\n\n"
            rf"A family of parallel lines has the direction $u = {_vec(self.u)}$; one of them "
            rf"passes through $p_0 = {_vec(self.p0)}$. Where do the images of these lines meet "
            r"(their vanishing point)?" "\n\n" + _POINT_3 + "\n\n"
            + data_note("matrix", "u", "p0"))

    def _steps(self):
        hom = self.matrix @ np.append(self.u, 0.0)
        return hom, hom[:3] / hom[3]

    def hints(self):
        hom, _ = self._steps()
        return [r"Far along the line $p_0 + t\,u$ the image stops depending on $p_0$: it tends "
                r"to the image of the point at infinity $(u, 0)$.",
                rf"$M\,(u, 0)$ uses only the first three columns of $M$: it is "
                rf"${_vec(hom)}$.",
                rf"Divide by the last coordinate $w = {_num(hom[3])}$."]

    def worked(self):
        hom, vp = self._steps()
        return Worked([
            rf"The direction as a point at infinity: $(u, 0) = {_vec(np.append(self.u, 0.0))}$ "
            r"($p_0$ does not matter).",
            rf"$M\,(u, 0) = {_vec(hom)}$ (the first three columns of $M$ times $u$).",
            rf"Divide by $w = {_num(hom[3])}$: the vanishing point is ${_vec(_snap(vp))}$.",
        ], _snap(vp))


#: The names of the classes, the answer menu of :class:`ClassifyProjection`.
CLASSES = ("one-point perspective", "two-point perspective", "three-point perspective",
           "multiview", "isometric", "dimetric", "trimetric", "cavalier", "cabinet",
           "general oblique")
_FAMILY = {**{c: "perspective" for c in CLASSES[:3]},
           **{c: "orthographic" for c in CLASSES[3:7]},
           **{c: "oblique" for c in CLASSES[7:]}}


def confusion(given, right):
    """The diagnosis key of answering the class `given` when it is `right`.

    Examples
    --------
    >>> confusion("isometric", "cavalier")
    'orthographic for oblique'
    """
    fg, fr = _FAMILY[given], _FAMILY[right]
    if fg != fr:
        return f"{fg} for {fr}"
    if fr == "perspective":
        return "vanishing points miscounted"
    if fr == "oblique":
        return "depth length misread"
    if "multiview" in (given, right):
        return "multiview confused"
    return "foreshortening misread"


class ClassifyProjection(DrawnExercise):
    r"""Name the class of a projection from its 4x4 matrix.

    The last row says perspective (its x, y, z entries are not all zero; each world axis with a
    non-zero entry recedes to a vanishing point) or parallel; a parallel projection with
    orthogonal rows of equal length is orthographic (the column lengths are the
    foreshortening factors of the axes), otherwise oblique (the length of the image of a unit
    of depth).

    Attributes: ``matrix``, ``kind`` (the right class).

    Examples
    --------
    >>> ex = ClassifyProjection(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = next(c for c in CLASSES if c != ex.expected)
    >>> ex.check(wrong).diagnosis == confusion(wrong, ex.expected)
    True
    """

    title = "Classify a projection from its matrix"
    answer_form = "custom"
    what = "the class"

    def draw(self, rng):
        family = pick(rng, ("perspective", "perspective", "orthographic", "orthographic",
                            "oblique"))
        if family == "perspective":
            d = float(pick(rng, (1, 2, 3)))
            n = np.zeros(3)
            count = int(pick(rng, (1, 2, 3)))
            axes = rng.choice(3, size=count, replace=False)
            n[axes] = rng.choice([-2.0, -1.0, 1.0, 2.0], size=count)
            self.matrix = np.zeros((4, 4))
            self.matrix[:3, :3] = d * np.eye(3)
            self.matrix[3, :3] = n
        elif family == "orthographic":
            az, el = pick(rng, [(45, 35.26438968275466), (45, 20), (45, 60), (30, 0), (0, 90),
                                (90, 0), (0, 0), (45, -35.26438968275466), (-45, 15),
                                (30, 30), (60, 20), (15, 45), (135, 35.26438968275466)])
            self.matrix = projections.axonometric(math.radians(az), math.radians(el))
        else:
            k = float(pick(rng, (1.0, 0.5, 0.75, 0.25)))
            phi = math.radians(float(pick(rng, (30, 45, 60, 150))))
            self.matrix = viewing.oblique([k * math.cos(phi), k * math.sin(phi), 1.0])
        self.matrix = _snap(self.matrix)
        name = projections.classify_projection(self.matrix)["name"]
        self.expected = {"orthographic multiview": "multiview", "oblique cavalier": "cavalier",
                         "oblique cabinet": "cabinet", "oblique (general)": "general oblique"
                         }.get(name, name)
        self.kind = self.expected

    def mistakes(self):
        return [Mistake(c, self._why(c), confusion(c, self.expected), numeric=False)
                for c in CLASSES if c != self.expected]

    def separated(self, mistakes):
        return True

    def keep(self, mistakes):
        return mistakes

    def _facts(self):
        m = self.matrix
        last = m[3, :3]
        rows = m[:2, :3]
        return last, rows, np.linalg.norm(rows, axis=0)

    def _why(self, given):
        last, rows, cols = self._facts()
        right = self.expected
        fg, fr = _FAMILY[given], _FAMILY[right]
        if fr == "perspective":
            k = int(np.count_nonzero(last))
            text = (rf"The last row $({_num(last[0])}, {_num(last[1])}, {_num(last[2])}, "
                    rf"{_num(self.matrix[3, 3])})$ makes $w$ depend on the point: a perspective "
                    r"projection. ")
            if fg == "perspective":
                text += (rf"Each axis with a non-zero entry in it recedes to a vanishing point "
                         rf"(its direction has $w \ne 0$): {k} of them, not "
                         rf"{CLASSES.index(given) + 1}.")
            return text
        if fg == "perspective":
            return (r"The last row is $(0, 0, 0, 1)$: $w = 1$ for every point, there is no "
                    r"divide that shrinks distant things, so the projection is parallel and "
                    r"has no vanishing points.")
        dot = float(rows[0] @ rows[1])
        l0, l1 = np.linalg.norm(rows, axis=1)
        if fr == "oblique":
            text = (rf"The first two rows have the dot product {_num(dot)} and the lengths "
                    rf"{_num(l0)} and {_num(l1)}: not orthonormal, so the projectors are not "
                    r"perpendicular to the plane (oblique). ")
            if fg == "oblique":
                k = float(np.linalg.norm(rows[:, 2]))
                text += (rf"A unit step along z is drawn with length $\sqrt{{{_num(rows[0, 2])}"
                         rf"^2 + {_num(rows[1, 2])}^2}} = {_num(k)}$: 1 is cavalier, 1/2 "
                         r"cabinet, anything else general oblique.")
            return text
        if fg == "oblique":
            return (rf"The first two rows are orthogonal (dot product {_num(dot)}) and of equal "
                    rf"length ({_num(l0)}): the projectors are perpendicular to the plane, an "
                    r"orthographic projection, not an oblique one.")
        return (rf"It is orthographic (orthonormal rows). The foreshortening factors are the "
                rf"lengths of the columns of the first two rows: x {_num(cols[0])}, y "
                rf"{_num(cols[1])}, z {_num(cols[2])}. One zero: multiview; three equal: "
                r"isometric; two equal: dimetric; none: trimetric.")

    def _check(self, answer):
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        if not isinstance(answer, str):
            return Feedback("invalid", "Give the class as one name (a string) from the list.",
                            "unreadable")
        given = " ".join(answer.strip().lower().replace("_", " ").split())
        given = {"oblique": "general oblique", "orthographic multiview": "multiview",
                 "one point perspective": "one-point perspective",
                 "two point perspective": "two-point perspective",
                 "three point perspective": "three-point perspective"}.get(given, given)
        if given not in CLASSES:
            return Feedback("invalid", f"{answer!r} is not one of the classes: "
                            + ", ".join(f"`{c}`" for c in CLASSES) + ".", "unreadable")
        if given == self.expected:
            return Feedback("correct", f"Right: {self.expected}.")
        return Feedback("wrong", self._why(given), confusion(given, self.expected))

    def statement(self):
        return (
            r"A projection has the matrix (column vectors, $p' = M p$; the image is the first "
            r"two coordinates after the homogeneous divide; entries rounded to 4 decimals)"
            "\n\n" rf"$$M = {_pmat(self.matrix)}.$$" "\n\n"
            r"Which class of planar geometric projection is it, for a box whose edges run "
            r"along the world axes?" "\n\n"
            r"**Answer:** one of the strings " + ", ".join(f"`'{c}'`" for c in CLASSES) + "."
            "\n\n" + data_note("matrix"))

    def hints(self):
        last, rows, cols = self._facts()
        return [r"Look at the last row first: does $w$ depend on $x, y, z$ (perspective) or is "
                r"it constant (parallel)?",
                rf"The last row is $({_num(last[0])}, {_num(last[1])}, {_num(last[2])}, "
                rf"{_num(self.matrix[3, 3])})$. For a parallel projection compare the first "
                r"two rows: orthogonal and of equal length means orthographic.",
                rf"The lengths of the columns of the first two rows (the images of the unit "
                rf"axes) are {_num(cols[0])}, {_num(cols[1])}, {_num(cols[2])}; for a "
                r"perspective count the non-zero entries of the last row."]

    def worked(self):
        last, rows, cols = self._facts()
        steps = [rf"Last row: $({_num(last[0])}, {_num(last[1])}, {_num(last[2])}, "
                 rf"{_num(self.matrix[3, 3])})$."]
        if np.any(last):
            k = int(np.count_nonzero(last))
            answer = CLASSES[k - 1]
            steps.append(rf"$w$ depends on the point: perspective. The axes with a non-zero "
                         rf"entry recede: {k} of them, so {answer}.")
            return Worked(steps, answer)
        dot = float(rows[0] @ rows[1])
        l0, l1 = np.linalg.norm(rows, axis=1)
        steps.append(rf"Parallel ($w = 1$). Rows 1 and 2: dot product {_num(dot)}, lengths "
                     rf"{_num(l0)} and {_num(l1)}.")
        if abs(dot) < 1e-9 and abs(l0 - l1) < 1e-9:
            zero = np.isclose(cols, 0, atol=1e-9)
            eq = [abs(cols[i] - cols[j]) < 1e-6 for i, j in ((0, 1), (0, 2), (1, 2))]
            answer = ("multiview" if zero.any() else "isometric" if all(eq)
                      else "dimetric" if any(eq) else "trimetric")
            steps.append(rf"Orthonormal: orthographic. Column lengths (foreshortening of x, y, "
                         rf"z): {_num(cols[0])}, {_num(cols[1])}, {_num(cols[2])}, so "
                         rf"{answer}.")
            return Worked(steps, answer)
        k = float(np.linalg.norm(rows[:, 2]))
        answer = ("cavalier" if abs(k - 1) < 1e-9 else "cabinet" if abs(k - 0.5) < 1e-9
                  else "general oblique")
        steps.append(rf"Not orthonormal: oblique. A unit of depth is drawn with length "
                     rf"{_num(k)}, so {answer}.")
        return Worked(steps, answer)


_ISO_DEG = math.degrees(math.atan(1 / math.sqrt(2)))


class AxonometricForeshortening(DrawnExercise):
    r"""Isometric angles and the foreshortening of an axis under an orthographic view.

    Seen along the unit direction :math:`v`, a segment of length :math:`L` along the unit axis
    :math:`a` is drawn with length :math:`L\sqrt{1 - (a \cdot v)^2}`. In the isometric view
    :math:`v \propto (1, \pm1, 1)`, every axis is foreshortened by :math:`\sqrt{2/3}`, and the
    view direction is :math:`\arctan(1/\sqrt 2) ≈ 35.26°` above the ground.

    Attributes: ``kind`` (``"elevation"``, ``"isometric"`` or ``"axonometric"``), ``length``,
    ``azimuth_deg``, ``elevation_deg``, ``axis`` (0, 1 or 2).

    Examples
    --------
    >>> ex = AxonometricForeshortening(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Foreshortening in an axonometric view"
    answer_form = "number"
    what = "the answer"

    def draw(self, rng):
        self.kind = str(pick(rng, ("elevation", "isometric", "isometric", "axonometric",
                                   "axonometric", "axonometric")))
        self.length = float(pick(rng, (2, 3, 4, 5, 6, 10)))
        self.axis = int(rng.integers(0, 3))
        if self.kind == "elevation":
            self.azimuth_deg, self.elevation_deg = 45.0, _ISO_DEG
            self.expected = _ISO_DEG
            return
        if self.kind == "isometric":
            self.azimuth_deg, self.elevation_deg = 45.0, _ISO_DEG
        else:
            self.azimuth_deg = float(pick(rng, (30, 60, 45, 15, 75)))
            self.elevation_deg = float(pick(rng, (15, 30, 45, 60)))
        m = projections.axonometric(math.radians(self.azimuth_deg),
                                    math.radians(self.elevation_deg))
        axes = np.eye(3)
        self.expected = float(self.length * projections.foreshortening(m, axes)[self.axis])

    def _dot(self):
        a, e = math.radians(self.azimuth_deg), math.radians(self.elevation_deg)
        v = (math.sin(a) * math.cos(e), -math.cos(a) * math.cos(e), math.sin(e))
        return v, v[self.axis]

    def mistakes(self):
        if self.kind == "elevation":
            return [
                Mistake(30.0, r"30° is the angle at which the drawn x and y axes rise from the "
                        r"horizontal in an isometric **drawing**, not the elevation of the "
                        r"view direction $(1, -1, 1)/\sqrt 3$.", "drawing angle"),
                Mistake(math.degrees(math.acos(1 / math.sqrt(3))), r"That is the angle "
                        r"between the view direction and the vertical axis, "
                        r"$\arccos(1/\sqrt 3)$; the elevation is measured from the ground: "
                        r"$\arcsin(1/\sqrt 3)$.", "angle from the vertical"),
                Mistake(math.atan(1 / math.sqrt(2)), r"That is the angle in radians; the "
                        r"question asks for degrees.", "radians"),
                Mistake(45.0, r"45° is the azimuth (the turn about the vertical axis); the "
                        r"elevation is $\arctan(1/\sqrt 2)$.", "azimuth instead"),
            ]
        _, dot = self._dot()
        L = self.length
        found = [
            Mistake(L, r"An orthographic projection shortens every edge that is not parallel to "
                    r"the plane: only an isometric *drawing* (a convention) uses full lengths. "
                    r"The factor is $\sqrt{1 - (a\cdot v)^2}$.", "true length"),
            Mistake(L * abs(dot), r"You took the component **along** the view direction, "
                    r"$|a \cdot v|$ (a cosine); the drawn part is the component across it, "
                    r"$\sqrt{1 - (a\cdot v)^2}$ (the sine).", "cos instead of sin"),
        ]
        if self.kind == "isometric":
            found.append(Mistake(L * math.sqrt(1.5), r"The factor is upside down: "
                                 r"$\sqrt{2/3} ≈ 0.816$ (less than 1: projections shorten), "
                                 r"not $\sqrt{3/2}$.", "factor inverted"))
            found.append(Mistake(L / math.sqrt(2), r"$1/\sqrt 2$ is the factor of a 45° "
                                 r"tilt; the isometric view direction makes the angle "
                                 r"$\arccos(1/\sqrt 3)$ with each axis, so the factor is "
                                 r"$\sqrt{1 - 1/3} = \sqrt{2/3}$.", "1/sqrt 2"))
        else:
            a, e = self.azimuth_deg, self.elevation_deg
            v_deg = (math.sin(a) * math.cos(e), -math.cos(a) * math.cos(e), math.sin(e))
            found.append(Mistake(L * math.sqrt(max(0.0, 1 - v_deg[self.axis] ** 2)),
                                 r"The sines and cosines were taken of the angles in radians "
                                 r"while they are degrees: convert first.", "degrees as radians"))
        return found

    def statement(self):
        axis = "xyz"[self.axis]
        if self.kind == "elevation":
            return (r"An isometric projection looks at the world along a direction that makes "
                    r"equal angles with the three axes, $v = (1, -1, 1)/\sqrt 3$ (z is up). "
                    r"How many degrees above the horizontal ground plane does the view "
                    r"direction rise (its elevation)?" "\n\n"
                    r"**Answer:** one number, in degrees. " + DECIMALS + "\n\n"
                    + data_note("kind"))
        view = (r"the isometric view (azimuth 45°, elevation $\arctan(1/\sqrt2)$, view "
                r"direction $v = (1, -1, 1)/\sqrt 3$)" if self.kind == "isometric" else
                rf"the view from azimuth {_num(self.azimuth_deg)}° and elevation "
                rf"{_num(self.elevation_deg)}°: the unit direction towards the viewer is "
                r"$v = (\sin a \cos e,\ -\cos a \cos e,\ \sin e)$")
        return (rf"An orthographic projection shows a box from {view} (z is up). An edge of "
                rf"the box of true length {_num(self.length)} runs along the {axis} axis. How "
                r"long is it drawn (the image uses the same unit as the world)?" "\n\n"
                r"**Answer:** one number. " + DECIMALS + "\n\n"
                + data_note("kind", "length", "azimuth_deg", "elevation_deg", "axis"))

    def hints(self):
        if self.kind == "elevation":
            return [r"The elevation $e$ satisfies $\sin e = v_z$ (the vertical component of the "
                    r"unit view direction).",
                    r"$v_z = 1/\sqrt 3 ≈ 0.5774$.",
                    r"$e = \arcsin(1/\sqrt3) = \arctan(1/\sqrt2)$; give it in degrees."]
        v, dot = self._dot()
        return [r"A unit vector $a$ seen along the unit direction $v$ keeps its part across "
                r"$v$: length $\sqrt{1 - (a\cdot v)^2}$.",
                rf"$v = ({_num(v[0])}, {_num(v[1])}, {_num(v[2])})$, so $a \cdot v = "
                rf"{_num(dot)}$ for the {'xyz'[self.axis]} axis.",
                rf"Multiply $\sqrt{{1 - {_par(dot)}^2}}$ by the length {_num(self.length)}."]

    def worked(self):
        if self.kind == "elevation":
            vz = 1 / math.sqrt(3)
            e = math.degrees(math.asin(vz))
            return Worked([r"The elevation $e$ of a unit direction has $\sin e = v_z$.",
                           rf"$v_z = 1/\sqrt3 = {_num(vz)}$, so $e = \arcsin({_num(vz)}) = "
                           rf"{_num(e)}°$ (also $\arctan(1/\sqrt2)$)."], e)
        v, dot = self._dot()
        factor = math.sqrt(1 - dot ** 2)
        return Worked([
            rf"$v = ({_num(v[0])}, {_num(v[1])}, {_num(v[2])})$; the {'xyz'[self.axis]} axis "
            rf"gives $a\cdot v = {_num(dot)}$.",
            rf"Foreshortening $\sqrt{{1 - {_par(dot)}^2}} = {_num(factor)}$"
            + (r" (isometric: $\sqrt{2/3}$ for every axis)." if self.kind == "isometric"
               else "."),
            rf"Drawn length ${_num(self.length)} \cdot {_num(factor)} = "
            rf"{_num(self.length * factor)}$.",
        ], self.length * factor)


class CabinetMatrix(DrawnExercise):
    r"""The matrix of a cabinet (or cavalier) projection onto the xy plane.

    A point one unit behind the plane, :math:`(0, 0, -1)`, is drawn at
    :math:`(k\cos\varphi,\ k\sin\varphi)`: :math:`k = 1/2` cabinet, :math:`k = 1` cavalier. The
    matrix is :math:`P_{OBLI}` with :math:`DOP = (k\cos\varphi, k\sin\varphi, 1)`:
    third column :math:`(-k\cos\varphi, -k\sin\varphi, 0, 0)`, third row zero.

    Attributes: ``kind`` (``"cabinet"`` or ``"cavalier"``), ``angle_deg``.

    Examples
    --------
    >>> ex = CabinetMatrix(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "The matrix of a cabinet or cavalier projection"
    answer_form = "matrix"
    transform = True

    def draw(self, rng):
        self.kind = str(pick(rng, ("cabinet", "cabinet", "cavalier")))
        self.angle_deg = float(pick(rng, (15, 30, 60, 75, 105, 120, 150, 165, 195, 210, 240, 255,
                                          285, 300, 330, 345)))
        k = 0.5 if self.kind == "cabinet" else 1.0
        phi = math.radians(self.angle_deg)
        self.expected = _snap(viewing.oblique([k * math.cos(phi), k * math.sin(phi), 1.0]))

    def _with(self, k, phi_deg, sign=-1.0, divide=True, keep=False):
        phi = math.radians(phi_deg)
        c, s = k * math.cos(phi), k * math.sin(phi)
        if not divide:
            norm = math.sqrt(c * c + s * s + 1)
            c, s = c / norm, s / norm
        m = np.eye(4)
        m[0, 2], m[1, 2] = sign * c, sign * s
        m[2, 2] = 1.0 if keep else 0.0
        return _snap(m)

    def mistakes(self):
        k = 0.5 if self.kind == "cabinet" else 1.0
        other = 1.0 if k == 0.5 else 0.5
        return [
            Mistake(self._with(other, self.angle_deg),
                    (r"That is the cavalier projection: depth at full length ($k = 1$). A "
                     r"cabinet projection draws a unit of depth at **half** length, $k = 1/2$.")
                    if self.kind == "cabinet" else
                    (r"That is the cabinet projection (depth at half length). A cavalier "
                     r"projection draws depth at full length, $k = 1$."), "wrong length"),
            Mistake(self._with(k, self.angle_deg, sign=1.0), r"The signs of the third column "
                    r"are flipped: a point **behind** the plane ($z = -1$) must move by "
                    r"$+k(\cos\varphi, \sin\varphi)$, so the entries are $-k\cos\varphi$ and "
                    r"$-k\sin\varphi$ (the shift is $-z$ times them).", "angle sign"),
            Mistake(self._with(k, self.angle_deg, divide=False), r"You normalised $DOP$ to unit "
                    r"length and used its x and y components directly. $P_{OBLI}$ needs "
                    r"$DOP_x/DOP_z$ and $DOP_y/DOP_z$: divide by the z component (here make it "
                    r"1).", "DOP not normalised in z"),
            Mistake(self._with(k, 90 - self.angle_deg), r"Sine and cosine are swapped: the "
                    r"angle is measured from the x axis, so the x entry uses $\cos\varphi$.",
                    "cos and sin swapped"),
            Mistake(self._with(k, self.angle_deg, keep=True), r"The third row must be zero: "
                    r"$P_{OBLI}$ puts every image point on the plane $z = 0$ (keeping $z$ makes "
                    r"it a shear, a different matrix).", "kept z"),
        ]

    def statement(self):
        return (rf"Give the $4 \times 4$ matrix of the **{self.kind}** projection onto the "
                r"plane $z = 0$ (column vectors, $p' = M p$) in which a unit of depth is drawn "
                rf"at the angle $\varphi = {_num(self.angle_deg)}°$ above the x axis: the point "
                rf"$(0, 0, -1)$, one unit behind the plane, lands at $(k\cos\varphi,\ "
                rf"k\sin\varphi,\ 0)$ with the {self.kind}'s $k$. Points of the plane stay "
                r"where they are." "\n\n"
                r"**Answer:** the $4 \times 4$ matrix as a numpy array. " + DECIMALS + "\n\n"
                + data_note("kind", "angle_deg"))

    def hints(self):
        k = 0.5 if self.kind == "cabinet" else 1.0
        return [r"Start from $P_{OBLI}$: the identity with a zero third row and the third "
                r"column $(-DOP_x/DOP_z,\ -DOP_y/DOP_z,\ 0,\ 0)$.",
                rf"The {self.kind} draws a unit of depth with length $k = {_num(k)}$.",
                rf"With $DOP = (k\cos\varphi, k\sin\varphi, 1)$: the entries are "
                rf"$-{_num(k)}\cos {_num(self.angle_deg)}°$ and "
                rf"$-{_num(k)}\sin {_num(self.angle_deg)}°$."]

    def worked(self):
        k = 0.5 if self.kind == "cabinet" else 1.0
        phi = math.radians(self.angle_deg)
        c, s = _snap([k * math.cos(phi), k * math.sin(phi)])
        m = np.eye(4)
        m[2, 2] = 0.0
        m[0, 2], m[1, 2] = -c, -s
        m = _snap(m)
        return Worked([
            rf"{self.kind.capitalize()}: $k = {_num(k)}$; $DOP = (k\cos\varphi, k\sin\varphi, "
            rf"1) = ({_num(c)}, {_num(s)}, 1)$.",
            rf"$P_{{OBLI}}$: $x' = x - z\,DOP_x$, $y' = y - z\,DOP_y$, $z' = 0$; the third "
            rf"column is $({_num(-c)}, {_num(-s)}, 0, 0)$.",
            rf"Check: $(0, 0, -1) \mapsto ({_num(c)}, {_num(s)}, 0)$. $M = {_mat(m)}$.",
        ], m)


class PrincipalVanishingCount(DrawnExercise):
    r"""How many principal vanishing points a box has in a perspective view.

    An edge direction :math:`a` has a vanishing point exactly when it is not parallel to the
    plane of projection, i.e. :math:`a \cdot g \ne 0` for the gaze :math:`g` (the plane's
    normal). The answer counts the box's three edge directions with :math:`a \cdot g \ne 0`.

    Attributes: ``axes`` (the box's edge directions, rows), ``eye``, ``gaze``.

    Examples
    --------
    >>> ex = PrincipalVanishingCount(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(3 - ex.expected).diagnosis
    'counted the parallel axes'
    """

    title = "The principal vanishing points of a box"
    answer_form = "number"
    what = "the number of principal vanishing points"
    may_coincide = ("eye position instead of gaze",)

    _BOXES = [np.eye(3), np.array([[1.0, 1, 0], [-1, 1, 0], [0, 0, 1]]),
              np.array([[1.0, 0, 1], [0, 1, 0], [-1, 0, 1]]),
              np.array([[2.0, 1, 0], [-1, 2, 0], [0, 0, 1]])]

    def draw(self, rng):
        self.axes = self._BOXES[int(rng.integers(len(self._BOXES)))]
        count = int(rng.integers(1, 4))
        chosen = rng.choice(3, size=count, replace=False)
        weights = rng.choice([-2.0, -1.0, 1.0, 2.0], size=count)
        self.gaze = _snap(weights @ self.axes[chosen])
        self.eye = rng.integers(-5, 6, size=3).astype(float)
        self.expected = None
        if not np.any(self.gaze) or np.linalg.norm(np.cross(self.gaze, [0, 0, 1])) == 0:
            return
        m = viewing.perspective(1.0, 1.0, 1.0, 50.0) @ viewing.look_at(self.eye, self.gaze,
                                                                        [0, 0, 1])
        vps = projections.principal_vanishing_points(m, self.axes)
        self.expected = int(sum(v is not None for v in vps))

    def acceptable(self):
        return self.expected is not None and np.any(self.eye)

    def mistakes(self):
        n = self.expected
        eye_count = int(np.count_nonzero(self.axes @ self.eye))
        return [
            Mistake(3 - n, r"You counted the axes **parallel** to the plane of projection "
                    r"($a \cdot g = 0$). Those edges stay parallel in the picture; the "
                    r"vanishing points belong to the other axes, $a \cdot g \ne 0$.",
                    "counted the parallel axes"),
            Mistake(eye_count, r"You tested the axes against the eye **position**; what "
                    r"matters is the orientation of the plane of projection, whose normal is "
                    r"the gaze direction $g$: count the axes with $a \cdot g \ne 0$.",
                    "eye position instead of gaze"),
        ]

    def statement(self):
        rows = ", ".join(_vec(a) for a in self.axes)
        return (rf"A box has its edges along the directions {rows}. A perspective camera at "
                rf"$E = {_vec(self.eye)}$ looks along the direction $g = {_vec(self.gaze)}$ "
                r"(z up; the plane of projection is perpendicular to $g$). How many principal "
                r"vanishing points does the box have in the picture (one-, two- or "
                r"three-point perspective)?" "\n\n"
                r"**Answer:** a whole number. " + "\n\n" + data_note("axes", "eye", "gaze"))

    def hints(self):
        dots = self.axes @ self.gaze
        return [r"Edges parallel to the plane of projection stay parallel: no vanishing "
                r"point. The plane is perpendicular to the gaze $g$.",
                r"So an edge direction $a$ has a vanishing point exactly when $a \cdot g \ne 0$.",
                rf"The dot products are {', '.join(_num(d) for d in dots)}."]

    def worked(self):
        dots = self.axes @ self.gaze
        n = int(np.count_nonzero(dots))
        return Worked([
            r"A direction $a$ vanishes at a point iff it is not parallel to the plane of "
            r"projection, whose normal is $g$: $a \cdot g \ne 0$.",
            "Dot products with $g$: " + ", ".join(
                rf"${_vec(a)} \cdot g = {_num(d)}$" for a, d in zip(self.axes, dots)) + ".",
            rf"{n} non-zero: {['no', 'one', 'two', 'three'][n]}-point perspective, "
            rf"$n = {n}$.",
        ], n)


class PlaneProjectionPoint(PointAnswer, DrawnExercise):
    r"""The image of a point under a perspective projection onto an arbitrary plane.

    The projector :math:`c + t(p - c)` meets the plane :math:`n \cdot x = h` at
    :math:`t = (h - n\cdot c) / n\cdot(p - c)`; the image is :math:`c + t(p - c)`
    (:func:`course_lib.projections.project_onto_plane`).

    Attributes: ``centre``, ``normal``, ``h``, ``p``.

    Examples
    --------
    >>> ex = PlaneProjectionPoint(seed=2)
    >>> ex.check(ex.expected).status
    'correct'
    >>> n = ex.normal
    >>> ex.check(ex.p - (n @ ex.p - ex.h) / (n @ n) * n).diagnosis
    'orthographic onto the plane'
    """

    title = "Perspective projection onto an arbitrary plane"
    what = "the image point"

    def draw(self, rng):
        self.normal = np.array(pick(rng, [(0, 0, 1), (0, 1, 0), (1, 0, 0), (1, 1, 0), (0, 1, 1),
                                          (1, 0, 1), (1, 1, 1)]), dtype=float)
        self.centre = rng.integers(-2, 3, size=3).astype(float)
        self.h = float(self.normal @ self.centre + pick(rng, (-4, -3, -2, 2, 3, 4)))
        self.p = rng.integers(-3, 4, size=3).astype(float)
        self.expected = None
        if abs(self.normal @ (self.p - self.centre)) not in (1.0, 2.0, 4.0):
            return
        m = projections.project_onto_plane(self.normal * self.h / (self.normal @ self.normal),
                                           self.normal, centre=self.centre)
        h = m @ np.append(self.p, 1.0)
        self.expected = _snap(h[:3] / h[3])

    def acceptable(self):
        if self.expected is None:
            return False
        along = abs(self.normal @ (self.p - self.centre))
        return bool(np.any(self.centre) and abs(self.normal @ self.p) > 0
                    and along != abs(self.h - self.normal @ self.centre))

    def mistakes(self):
        c, n, h, p = self.centre, self.normal, self.h, self.p
        gap, along = h - n @ c, n @ (p - c)
        return [
            Mistake(p - (n @ p - h) / (n @ n) * n, r"You dropped the point perpendicularly onto "
                    r"the plane (an orthographic projection). The projector of a perspective "
                    r"projection runs from the centre $c$ through $p$, not along the normal.",
                    "orthographic onto the plane"),
            Mistake(c + along / gap * (p - c), r"The parameter is upside down: the projector "
                    r"$c + t\,(p - c)$ meets the plane where $n\cdot c + t\,n\cdot(p - c) = h$, "
                    r"so $t = (h - n\cdot c) / n\cdot(p - c)$.", "t inverted"),
            Mistake(h / (n @ p) * p, r"You projected from the origin, as $P_{PER}$ does. Here "
                    r"the centre of projection is $c$: the projector is $c + t\,(p - c)$.",
                    "centre at the origin"),
            Mistake(c + gap * (p - c), r"You forgot to divide by $n \cdot (p - c)$, the "
                    r"homogeneous $w$ of the image: $t = (h - n\cdot c) / n\cdot(p - c)$.",
                    "no divide"),
        ]

    def statement(self):
        return (
            rf"A perspective projection has its centre of projection at $c = {_vec(self.centre)}$ "
            rf"and projects onto the plane $n \cdot x = h$ with $n = {_vec(self.normal)}$ and "
            rf"$h = {_num(self.h)}$. Where does the point $p = {_vec(self.p)}$ land on the "
            r"plane?" "\n\n" + _POINT_3 + "\n\n" + data_note("centre", "normal", "h", "p"))

    def hints(self):
        c, n, h, p = self.centre, self.normal, self.h, self.p
        return [r"Follow the projector $c + t\,(p - c)$ from the centre through $p$ until it "
                r"meets the plane.",
                rf"Put it into the plane's equation: $n\cdot c + t\,n\cdot(p - c) = h$, with "
                rf"$n\cdot c = {_num(n @ c)}$ and $n\cdot(p - c) = {_num(n @ (p - c))}$.",
                rf"So $t = ({_num(h)} - {_par(n @ c)}) / {_par(n @ (p - c))}$; the image is "
                r"$c + t\,(p - c)$."]

    def worked(self):
        c, n, h, p = self.centre, self.normal, self.h, self.p
        t = (h - n @ c) / (n @ (p - c))
        q = _snap(c + t * (p - c))
        return Worked([
            rf"Projector: $c + t\,(p - c)$ with $p - c = {_vec(p - c)}$.",
            rf"Plane: $n\cdot c + t\,n\cdot(p - c) = h$: ${_num(n @ c)} + t \cdot "
            rf"{_par(n @ (p - c))} = {_num(h)}$, so $t = {_num(t)}$.",
            rf"Image: $c + {_par(t)}\,(p - c) = {_vec(q)}$ (check: $n \cdot q = "
            rf"{_num(n @ q)} = h$).",
        ], q)


EXERCISES = (CameraVanishingPoint, ClassifyProjection, AxonometricForeshortening, CabinetMatrix,
             PrincipalVanishingCount, PlaneProjectionPoint)
