r"""Chapter 14 exercises: environment mapping (the cube-map face and (s, t) of a direction, the
sphere-map coordinates of a reflection vector, the reflected view ray and the face it reads).

Part of :mod:`course_lib.exercises.ch14`, which imports every exercise from here. The expected
answers come from :mod:`course_lib.texturing.environment`; the statements, hints, mistakes and
worked solutions use the OpenGL table written out below (:data:`TABLE`), and the worked
solutions compute their answers with their own arithmetic.

A cube-map face may be given as its number 0..5 (+X, -X, +Y, -Y, +Z, -Z, OpenGL's order) or as
its name, a string such as ``"-X"`` (also ``"X-"``, ``"negx"``, ``"negative x"``).
"""

import math

import numpy as np

from ...texturing import environment
from ..core import (DECIMALS, SIGNIFICANT, UNANSWERED, Feedback, Mistake, Worked, agrees,
                    data_note, has_placeholder, pick, rounding_of)
from . import _Chapter14, _n4, _num, _vec

__all__ = ["CubeMapFace", "EnvironmentReflection", "SphereMapCoordinates"]

#: The faces in OpenGL's order: face k is FACES[k].
FACES = ("+X", "-X", "+Y", "-Y", "+Z", "-Z")
#: The OpenGL specification's cube-map table, face -> ((sign, axis) of s_c, (sign, axis) of t_c);
#: m_a is the component of the face's own axis (k // 2).
TABLE = {0: ((-1, 2), (-1, 1)), 1: ((1, 2), (-1, 1)), 2: ((1, 0), (1, 2)),
         3: ((1, 0), (-1, 2)), 4: ((1, 0), (-1, 1)), 5: ((-1, 0), (-1, 1))}
_AXES = "xyz"
#: The share of the seeds of :class:`CubeMapFace` whose direction points at a cube edge (a tie).
BOUNDARY_SHARE = 0.15
#: The boundary case of :class:`CubeMapFace`, as its ``boundary`` attribute names it.
TIE = "tie between two axes"
#: How far the largest component of a reflection vector must lead the next (a clear face); off
#: the simple fractions the components take, so that no rounding decides a variant.
_MARGIN = 0.0987


# ---------------------------------------------------------------------------------------------
# Helpers: the table by hand, face names, reading an answer with a face in it
# ---------------------------------------------------------------------------------------------

def _row_latex(face, which):
    """``-r_z``: the table's entry s_c (which = 0) or t_c (which = 1) of `face`."""
    sign, axis = TABLE[face][which]
    return ("-" if sign < 0 else "+") + f"r_{_AXES[axis]}"


def _substituted(face, which, r):
    """``-r_z = -(-2) = 2``: the table's entry of `face` with the component of `r` put in."""
    sign, axis = TABLE[face][which]
    value = float(r[axis])
    shown = f"({_num(value)})" if value < 0 else _num(value)
    if sign > 0:
        return f"r_{_AXES[axis]} = {_num(value)}"
    return f"-r_{_AXES[axis]} = -{shown} = {_num(-value)}"


def _table_markdown():
    rows = ["| face | number | $s_c$ | $t_c$ | $m_a$ |", "|---|---|---|---|---|"]
    for k, name in enumerate(FACES):
        rows.append(f"| {name} | {k} | ${_row_latex(k, 0)}$ | ${_row_latex(k, 1)}$ | "
                    f"$r_{_AXES[k // 2]}$ |")
    return "\n".join(rows)


def _major(r):
    """The face of the largest |r_i| (ties: x before y before z), by hand."""
    a = [abs(float(x)) for x in r]
    axis = 0 if a[0] >= a[1] and a[0] >= a[2] else (1 if a[1] >= a[2] else 2)
    return 2 * axis + (1 if r[axis] < 0 else 0)


def _on_face(r, face, signed_ma=False):
    """(s_c, t_c, m_a, s, t) of direction `r` read on `face` by the table."""
    (ss, sa), (ts, ta) = TABLE[face]
    sc, tc, ma = ss * float(r[sa]), ts * float(r[ta]), float(r[face // 2])
    d = ma if signed_ma else abs(ma)
    return sc, tc, ma, (sc / d + 1) / 2, (tc / d + 1) / 2


def _triple(r, face, signed_ma=False):
    _, _, _, s, t = _on_face(r, face, signed_ma)
    return [float(face), s, t]


def _unique_largest(values, margin=0.0):
    v = sorted((float(x) for x in values), reverse=True)
    return v[0] - v[1] > margin


def _spellings(name):
    """``"+X"``, ``"X+"``, ``"POSX"``, ``"POSITIVEX"``: the forms a face name is read in."""
    sign, axis = name[0], name[1]
    return (name, axis + sign, ("POS" if sign == "+" else "NEG") + axis,
            ("POSITIVE" if sign == "+" else "NEGATIVE") + axis)


_NAMES = {form: k for k, name in enumerate(FACES) for form in _spellings(name)}


def face_from_name(text):
    """The number 0..5 of a face name (``"+X"``, ``"x-"``, ``"negz"``, ``"positive y"``), or None.

    Examples
    --------
    >>> face_from_name("-X"), face_from_name(" y+ "), face_from_name("negative z")
    (1, 2, 5)
    >>> face_from_name("X") is None
    True
    """
    key = text.strip().upper().replace("\u2212", "-")
    for junk in ("GL_TEXTURE_CUBE_MAP_", " ", "_", "FACE"):
        key = key.replace(junk, "")
    return _NAMES.get(key)


def _real(x):
    return (isinstance(x, (int, float, np.integer, np.floating))
            and not isinstance(x, (bool, np.bool_)))


def _read_face_answer(answer, n, at, form):
    """An answer of `n` entries whose entry `at` is a face: (face, the other numbers) or a
    Feedback ("unanswered" or "invalid") saying why it cannot be read.

    The face is a whole number 0..5 or a face name; the other entries are finite numbers. A
    string such as ``"-X, 0.25, 0.5"`` is read too (the exam's text field).
    """
    if has_placeholder(answer, none_inside=True):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, str):
        items = answer.strip().strip("[]()").replace(",", " ").split()
        parsed = []
        for k, item in enumerate(items):
            item = item.strip("'\"")
            try:
                parsed.append(item if k == at and face_from_name(item) is not None
                              else float(item))
            except ValueError:
                return Feedback("invalid", f"Cannot read {item!r}. " + form, "unreadable")
        answer = parsed
    elif isinstance(answer, np.ndarray):
        if answer.dtype == bool or answer.dtype.kind not in "iuf" or answer.size != n:
            return Feedback("invalid", form, "unreadable")
        answer = answer.ravel().tolist()
    elif not isinstance(answer, (list, tuple)):
        return Feedback("invalid", form, "unreadable")
    if len(answer) != n:
        return Feedback("invalid", f"Give {n} entries. " + form, "unreadable")
    face, values = None, []
    for k, item in enumerate(answer):
        if k == at:
            if isinstance(item, str):
                face = face_from_name(item)
                if face is None:
                    return Feedback("invalid", f"{item!r} is not a face: the faces are "
                                    + ", ".join(f'"{f}"' for f in FACES)
                                    + " (or their numbers 0 to 5).", "not a face")
                continue
            if not _real(item) or not math.isfinite(float(item)):
                return Feedback("invalid", "The face must be a number 0 to 5 or a name such as "
                                '"+X". ' + form, "not a face")
            if float(item) != round(float(item)) or not 0 <= float(item) <= 5:
                return Feedback("invalid", f"{_num(float(item))} is not a face number: the "
                                "faces +X, -X, +Y, -Y, +Z, -Z are numbered 0 to 5.",
                                "not a face")
            face = int(round(float(item)))
        else:
            if not _real(item):
                return Feedback("invalid", "Give the coordinates as numbers. " + form,
                                "not a number")
            if not math.isfinite(float(item)):
                return Feedback("invalid", "Your answer contains NaN or infinity: a division "
                                "by zero somewhere?", "not finite")
            values.append(float(item))
    return face, np.array(values)


def _face_words(face):
    return f"{FACES[face]} (face {face})"


def _rounded_parts(what):
    return Feedback("wrong", f"Close: {what} look like the right values rounded to too few "
                    f"digits. Give at least {SIGNIFICANT} significant digits (or 3 decimals).",
                    "rounded")


# ---------------------------------------------------------------------------------------------
# The face and (s, t) of a direction
# ---------------------------------------------------------------------------------------------

class CubeMapFace(_Chapter14):
    r"""The cube-map face and :math:`(s, t)` that a direction reads (OpenGL's table).

    The face is the axis of the largest :math:`|r_i|` with its sign; :math:`s_c, t_c` come from
    that face's row of the table and :math:`s = (s_c/|m_a| + 1)/2`,
    :math:`t = (t_c/|m_a| + 1)/2`. In about 15 % of the seeds two components tie for the
    largest magnitude (the direction points at a cube edge): ``boundary`` is then
    ``"tie between two axes"`` (else None), and the face is the first of x, y, z, as in
    :func:`course_lib.texturing.environment.cube_face_coordinates` (OpenGL leaves ties to the
    implementation).

    Attributes: ``direction`` (3 whole numbers), ``boundary``.

    Examples
    --------
    >>> ex = CubeMapFace(seed=0)
    >>> ex.direction, ex.expected
    (array([ 4., -2.,  1.]), array([0.   , 0.375, 0.75 ]))
    >>> ex.check(["+X", 0.375, 0.75]).status, ex.check([0, 0.75, 0.375]).diagnosis
    ('correct', 's and t swapped')
    >>> ex.check([0, -0.25, 0.5]).diagnosis
    'not mapped to [0, 1]'
    """

    title = "A cube-map look-up"
    answer_form = "custom"
    what = "the face and (s, t)"
    boundary_kinds = (TIE,)
    boundary = None
    may_coincide = ("sc sign", "tc sign", "not mapped to [0, 1]", "s and t swapped")
    advice = (r"The face is the axis of the component of largest **magnitude**, with that "
              r"component's sign; read $s_c$, $t_c$ from that face's row and map them: "
              r"$s = (s_c/|m_a| + 1)/2$, $t = (t_c/|m_a| + 1)/2$.")
    _FORM = ('**Answer:** a list `[face, s, t]`: the face as its number 0 to 5 or its name as '
             'a string (`"+X"`, `"-X"`, ...), then $s$ and $t$.')

    def setup(self, rng):
        self._wanted = bool(rng.random() < BOUNDARY_SHARE)
        super().setup(rng)

    def draw(self, rng):
        r = np.zeros(3)
        if self._wanted:                               # two components tie: a cube edge
            big = int(pick(rng, (2, 3, 4)))
            i, j = pick(rng, ((0, 1), (0, 2), (1, 2)))
            r[i], r[j] = big * pick(rng, (-1, 1)), big * pick(rng, (-1, 1))
            k = 3 - i - j
            r[k] = int(rng.integers(-big + 1, big))
        else:
            big = int(pick(rng, (2, 3, 4, 5)))
            axis = int(rng.integers(3))
            r = rng.integers(-big + 1, big, size=3).astype(float)
            r[axis] = big * pick(rng, (-1, 1))
        self.direction = r + 0.0
        self.boundary = TIE if self._wanted else None
        face, s, t = environment.cube_face_coordinates(self.direction)
        self.expected = np.array([float(face), float(s), float(t)])

    def acceptable(self):
        a = np.abs(self.direction)
        ties = int(np.sum(a == a.max()))
        if ties != (2 if self._wanted else 1):
            return False
        signed = self._signed_face()          # the slip's face must have a non-zero m_a
        return signed is None or (_unique_largest(self.direction)
                                  and self.direction[signed // 2] != 0)

    def _signed_face(self):
        """The face a student picks by the largest *signed* component (None: the right one)."""
        axis = int(np.argmax(self.direction))
        face = 2 * axis + (1 if self.direction[axis] < 0 else 0)
        return None if face == int(self.expected[0]) else face

    def _tie_face(self):
        a = np.abs(self.direction)
        axes = [k for k in range(3) if a[k] == a.max()]
        k = axes[1]
        return 2 * k + (1 if self.direction[k] < 0 else 0)

    def mistakes(self):
        r = self.direction
        face = int(self.expected[0])
        sc, tc, ma, s, t = _on_face(r, face)
        name = FACES[face]
        found = [
            Mistake([face, 1 - s, t], rf"The sign of $s_c$ is wrong: face {name}'s row of the "
                    rf"table gives $s_c = {_row_latex(face, 0)} = {_num(sc)}$. Each face has "
                    r"its own signs, fixed by how the specification orients that face's "
                    r"image; take both from the face's own row.", "sc sign"),
            Mistake([face, s, 1 - t], rf"The sign of $t_c$ is wrong: face {name}'s row of the "
                    rf"table gives $t_c = {_row_latex(face, 1)} = {_num(tc)}$. Each face has "
                    r"its own signs; take both from the face's own row.", "tc sign"),
            Mistake([face, sc / abs(ma), tc / abs(ma)], r"$s_c/|m_a|$ and $t_c/|m_a|$ lie in "
                    r"$[-1, 1]$, but texture coordinates lie in $[0, 1]$: map them with "
                    r"$s = (s_c/|m_a| + 1)/2$, $t = (t_c/|m_a| + 1)/2$.",
                    "not mapped to [0, 1]"),
            Mistake([face, t, s], r"$s$ and $t$ are swapped: $s$ comes from $s_c$ (the "
                    r"table's first column), $t$ from $t_c$.", "s and t swapped"),
        ]
        other = face ^ 1
        found.append(Mistake(_triple(r, other), rf"The face has the wrong sign: "
                             rf"$r_{_AXES[face // 2]} = {_num(ma)}$ is "
                             rf"{'negative' if ma < 0 else 'positive'}, so the direction "
                             rf"leaves the cube through {name}, not {FACES[other]}.",
                             "face sign"))
        if ma < 0:
            found.append(Mistake(_triple(r, face, signed_ma=True), rf"You divided by "
                                 rf"$m_a = {_num(ma)}$ with its sign, which flips both "
                                 rf"coordinates. The formula divides by $|m_a| = "
                                 rf"{_num(abs(ma))}$ (the sign of $m_a$ only chose the face).",
                                 "divided by signed m_a"))
        signed = self._signed_face()
        if signed is not None:
            k = int(np.argmax(np.abs(r)))
            found.append(Mistake(_triple(r, signed), rf"The face is the axis of the component "
                                 rf"of largest **magnitude**, not of largest value: "
                                 rf"$|r_{_AXES[k]}| = {_num(abs(r[k]))}$ beats "
                                 rf"$r_{_AXES[signed // 2]} = {_num(r[signed // 2])}$, so "
                                 rf"the face is {name} (a negative component gives a − face).",
                                 "largest signed component"))
        if self.boundary is not None:
            tie = self._tie_face()
            found.append(Mistake(_triple(r, tie), rf"That is the same direction read on face "
                                 rf"{FACES[tie]}: two components tie, so the direction points "
                                 r"at an edge of the cube, and both faces give the same point "
                                 r"of their shared edge. OpenGL leaves the choice to the "
                                 r"implementation; the question asks for the rule x before y "
                                 rf"before z, which gives {name}.", "tie order"))
        return found

    def statement(self):
        tie = ""
        if self.boundary is not None:
            tie = (r" **Boundary case:** two components have the same largest magnitude, so "
                   r"the direction points at an edge of the cube. The OpenGL specification "
                   r"leaves the choice of face to the implementation (both faces show the same "
                   r"point of their shared edge); here take the first axis in the order "
                   r"x, y, z, as `course_lib` does.")
        return (
            r"A cube map is looked up with the direction "
            rf"$r = (r_x, r_y, r_z) = {_vec(self.direction)}$ (not normalised). The face is "
            r"the direction's major axis, the component $m_a$ of largest magnitude, with its "
            r"sign; OpenGL's table gives the two other coordinates $s_c$, $t_c$ of each face, "
            r"and $s = (s_c/|m_a| + 1)/2$, $t = (t_c/|m_a| + 1)/2$." + tie + "\n\n"
            + _table_markdown() + "\n\n"
            r"Which face does the direction read, and at which $(s, t)$?" "\n\n"
            + self._FORM + " " + DECIMALS + "\n\n" + data_note("direction", "boundary"))

    def hints(self):
        r = self.direction
        a = ", ".join(rf"|r_{_AXES[k]}| = {_num(abs(r[k]))}" for k in range(3))
        face = _major(r)
        return [r"The face is decided by the component of largest **magnitude** $|r_i|$ (not "
                r"the largest value); its sign picks the + or − face.",
                rf"Here ${a}$" + (r" (a tie: take the first of x, y, z)" if self.boundary
                                  else "") + rf": the face is {_face_words(face)}, "
                rf"$m_a = {_num(r[face // 2])}$.",
                rf"Row {FACES[face]}: $s_c = {_row_latex(face, 0)}$, "
                rf"$t_c = {_row_latex(face, 1)}$; divide by $|m_a|$, add 1, halve."]

    def worked(self):
        r = self.direction
        a = [abs(float(x)) for x in r]
        axis = 0 if a[0] >= a[1] and a[0] >= a[2] else (1 if a[1] >= a[2] else 2)
        ma = float(r[axis])
        face = 2 * axis + (1 if ma < 0 else 0)
        (ss, sa), (ts, ta) = TABLE[face]
        sc, tc = ss * float(r[sa]), ts * float(r[ta])
        s, t = (sc / abs(ma) + 1) / 2, (tc / abs(ma) + 1) / 2
        mags = ", ".join(rf"|r_{_AXES[k]}| = {_num(a[k])}" for k in range(3))
        first = (rf"Magnitudes ${mags}$: the largest is $|r_{_AXES[axis]}|$, and "
                 rf"$r_{_AXES[axis]} = {_num(ma)}$ is {'negative' if ma < 0 else 'positive'}: "
                 rf"face {_face_words(face)}, $m_a = {_num(ma)}$.")
        steps = [first]
        if self.boundary is not None:
            k = [j for j in range(3) if a[j] == max(a)][1]
            other = 2 * k + (1 if r[k] < 0 else 0)
            _, _, _, s2, t2 = _on_face(r, other)
            steps.append(rf"**Boundary case:** $|r_{_AXES[axis]}| = |r_{_AXES[k]}|$, a tie: "
                         r"the direction points at an edge of the cube. OpenGL leaves the "
                         r"choice to the implementation; the rule x before y before z picks "
                         rf"{FACES[face]}. Face {FACES[other]} would give "
                         rf"$(s, t) = ({_n4(s2)}, {_n4(t2)})$, the same point of the shared "
                         r"edge (one coordinate is 0 or 1 on both).")
        steps += [
            rf"Row {FACES[face]} of the table: $s_c = {_substituted(face, 0, r)}$, "
            rf"$t_c = {_substituted(face, 1, r)}$.",
            rf"$s = ({_num(sc)}/{_num(abs(ma))} + 1)/2 = {_n4(s)}$, "
            rf"$t = ({_num(tc)}/{_num(abs(ma))} + 1)/2 = {_n4(t)}$: the answer is "
            rf"$[{face}, {_n4(s)}, {_n4(t)}]$ (face {FACES[face]}).",
        ]
        return Worked(steps, [face, s, t])

    def _judge(self, answer):
        read = _read_face_answer(answer, 3, 0, self._FORM)
        if isinstance(read, Feedback):
            return read
        face, st = read
        right = int(self.expected[0])
        if face == right and agrees(st, self.expected[1:]):
            return Feedback("correct", f"Face {FACES[face]} and (s, t) are right.")
        for m in self._mistakes:
            if face == int(m.value[0]) and agrees(st, m.value[1:]):
                return Feedback("wrong", m.explanation, m.key)
        if face == right:
            if rounding_of(st, self.expected[1:], [Mistake(m.value[1:], "", m.key)
                                                   for m in self._mistakes]):
                return _rounded_parts("$s$ and $t$")
            off = [n for n, v, e in zip("st", st, self.expected[1:]) if not agrees(v, e)]
            return Feedback("wrong", f"The face {FACES[face]} is right, but "
                            + " and ".join(f"${n}$" for n in off)
                            + (" is" if len(off) == 1 else " are") + " off.",
                            "components differ")
        for m in self._mistakes:                  # a slip that decides the face
            if m.key in ("face sign", "largest signed component", "tie order") \
                    and face == int(m.value[0]):
                return Feedback("wrong", m.explanation, m.key)
        return Feedback("wrong", f"The face is not {FACES[face]}.", "value differs")


# ---------------------------------------------------------------------------------------------
# Sphere maps
# ---------------------------------------------------------------------------------------------

#: Unit vectors with simple fractions: signed permutations of (0, 0, 1), (0, 3, 4)/5,
#: (1, 2, 2)/3 and (2, 3, 6)/7.
_UNITS = tuple(sorted({tuple(float(s * x) / d for s, x in zip(signs, perm))
                       for base, d in (((0, 0, 1), 1), ((0, 3, 4), 5), ((1, 2, 2), 3),
                                       ((2, 3, 6), 7))
                       for perm in {(base[i], base[j], base[k])
                                    for i, j, k in ((0, 1, 2), (0, 2, 1), (1, 0, 2),
                                                    (1, 2, 0), (2, 0, 1), (2, 1, 0))}
                       for signs in ((sx, sy, sz) for sx in (1, -1) for sy in (1, -1)
                                     for sz in (1, -1))}))


def _sphere_st(r, plus_one=True, two=True, half=True):
    """(s, t) of the sphere map for the vector r used as given (by hand)."""
    x, y, z = (float(v) for v in r)
    m = (2 if two else 1) * math.sqrt(x * x + y * y + (z + (1 if plus_one else 0)) ** 2)
    h = 0.5 if half else 0.0
    return [x / m + h, y / m + h]


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / math.sqrt(float(v @ v))


def _reflect(i, n):
    """I - 2 (N.I) N with N normalised here, by hand."""
    n = _unit(n)
    return np.asarray(i, dtype=float) - 2 * float(n @ i) * n


class SphereMapCoordinates(_Chapter14):
    r"""The sphere-map coordinates :math:`(s, t)` of an eye-space reflection vector.

    :math:`m = 2\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}` for the **unit** reflection vector
    :math:`r`, :math:`s = r_x/m + \tfrac12`, :math:`t = r_y/m + \tfrac12` (OpenGL's
    ``GL_SPHERE_MAP``, the viewer looking along :math:`-z`). Either the reflection vector is
    given (whole numbers, not of unit length: normalise first, as
    :func:`course_lib.texturing.environment.sphere_map_coordinates` does), or the view
    direction :math:`I` and the normal :math:`N` (unit vectors) are given and
    :math:`R = I - 2(N \cdot I)N` comes first.

    Attributes: ``kind`` (``"reflection"`` or ``"view"``), ``R`` (for ``"reflection"``),
    ``I`` and ``N`` (for ``"view"``).

    Examples
    --------
    >>> ex = SphereMapCoordinates(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> s, t = ex.expected
    >>> ex.check([t, s]).diagnosis
    's and t swapped'
    """

    title = "Sphere-map coordinates"
    answer_form = "vector"
    what = "(s, t)"
    advice = (r"Normalise $R$, then $m = 2\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}$, "
              r"$s = r_x/m + \tfrac12$, $t = r_y/m + \tfrac12$.")

    def draw(self, rng):
        self.kind = str(pick(rng, ("reflection", "reflection", "view")))
        if self.kind == "reflection":
            self.R = rng.integers(-3, 4, size=3).astype(float) + 0.0
            self.I = self.N = None
            r = self.R
        else:
            straight = rng.random() < 0.35            # the classic case: along -z
            self.I = np.array((0.0, 0.0, -1.0) if straight else
                              pick(rng, [u for u in _UNITS if u[2] < 0]))
            self.N = np.array(pick(rng, _UNITS))
            self.R = None
            r = environment.reflect_view(self.I, self.N)
        self._r = r
        if not np.any(r):
            self.expected = np.zeros(2)
            return
        s, t = environment.sphere_map_coordinates(r)
        self.expected = np.array([float(s), float(t)])

    def _unit_r(self):
        return _unit(self._r)

    def acceptable(self):
        if not np.any(self._r):
            return False
        r = self._unit_r()
        # far from the singular point r = (0, 0, -1), and s apart from t (thresholds off the
        # simple fractions the numbers take, so that no last bit decides a variant)
        if r[2] < -0.9013 or abs(r[0] - r[1]) < 0.0987:
            return False
        if self.kind == "reflection":
            return float(self.R @ self.R) > 1 and np.count_nonzero(self.R) >= 2
        n_dot_i = float(self.N @ self.I)
        return n_dot_i < -0.1013 and r[2] < 0.9013 and not np.allclose(np.abs(self.N), [0, 0, 1])

    def mistakes(self):
        r = self._unit_r()
        s, t = self.expected
        found = [
            Mistake(_sphere_st(r, plus_one=False), r"The $+1$ on $r_z$ is missing: "
                    r"$m = 2\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}$. (Without it $m = 2$ for every "
                    r"unit $r$.) The $+1$ is the direction to the viewer, $(0, 0, 1)$: the "
                    r"mirror ball's normal that reflects the view ray into $r$ is halfway "
                    r"between $r$ and it, $(r + \hat z)/|r + \hat z|$.", "no +1 on r_z"),
            Mistake(_sphere_st(r, two=False), r"The factor 2 in $m$ is missing: "
                    r"$m = 2\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}$. The ball's normal "
                    r"$(r_x, r_y, r_z + 1)/(m/2)$ has $x$ and $y$ in $[-1, 1]$, and "
                    r"$s = n_x/2 + \tfrac12$ squeezes them into the disc of radius $\tfrac12$.",
                    "no factor 2"),
            Mistake(_sphere_st(r, half=False), r"The $+\tfrac12$ is missing: $r_x/m$ and "
                    r"$r_y/m$ lie in $[-\tfrac12, \tfrac12]$; texture coordinates are "
                    r"$s = r_x/m + \tfrac12$, $t = r_y/m + \tfrac12$, the disc centred at "
                    r"$(\tfrac12, \tfrac12)$.", "no +1/2"),
            Mistake([t, s], r"$s$ and $t$ are swapped: $s$ goes with $r_x$, $t$ with $r_y$.",
                    "s and t swapped"),
        ]
        if self.kind == "reflection":
            found.append(Mistake(_sphere_st(self.R), rf"$R$ was not normalised: "
                                 rf"$|R| = {_n4(math.sqrt(self.R @ self.R))}$, and the formula "
                                 r"for $m$ holds for a **unit** vector (the $+1$ is added to a "
                                 r"component of length at most 1). Divide $R$ by its length "
                                 r"first.", "R not normalised"))
        else:
            found.append(Mistake(_sphere_st(-r), r"That is the sphere map of $-R$: "
                                 r"$2(N \cdot I)N - I$ is the mirror direction for a vector "
                                 r"$L$ pointing **away** from the surface (Phong's $R$). The "
                                 r"view direction $I$ travels towards the surface, so "
                                 r"$R = I - 2(N \cdot I)N$.", "reflection sign"))
        return found

    def statement(self):
        if self.kind == "reflection":
            given = (rf"A mirror-like object is shaded with a sphere map. At a pixel the "
                     rf"eye-space reflection vector is $R = {_vec(self.R)}$ (not normalised).")
        else:
            given = (rf"A mirror-like object is shaded with a sphere map. At a pixel the view "
                     rf"direction (from the eye towards the surface, in eye space) is "
                     rf"$I = {_vec(self.I)}$ and the unit normal is $N = {_vec(self.N)}$; "
                     r"first find the reflection vector $R$ of the view ray.")
        return (
            given + r" The sphere map is OpenGL's (`GL_SPHERE_MAP`): the picture of a small "
            r"mirror ball seen from far away by a viewer looking along $-z$ in eye space, "
            r"the disc of radius $\tfrac12$ around $(\tfrac12, \tfrac12)$ of the texture. "
            r"At which texture coordinates $(s, t)$ is the map read?" "\n\n"
            r"**Answer:** a list of 2 numbers `[s, t]`. " + DECIMALS + "\n\n"
            + data_note("kind", "R", "I", "N"))

    def hints(self):
        first = (r"The formula takes a **unit** reflection vector: divide $R$ by "
                 rf"$|R| = {_n4(math.sqrt(self.R @ self.R))}$ first." if self.kind == "reflection"
                 else rf"First $R = I - 2(N \cdot I)N$ with $N \cdot I = "
                      rf"{_n4(float(self.N @ self.I))}$ (both are unit vectors, so $R$ is one).")
        return [first,
                r"$m = 2\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}$: twice the length of $r + (0, 0, 1)$, "
                r"the sum of the reflection and the direction to the viewer.",
                r"$s = r_x/m + \tfrac12$, $t = r_y/m + \tfrac12$."]

    def worked(self):
        if self.kind == "reflection":
            R = np.asarray(self.R, dtype=float)
            length = math.sqrt(float(R @ R))
            r = R / length
            first = (rf"$|R| = \sqrt{{{_num(float(R @ R))}}} = {_n4(length)}$, so the unit "
                     rf"reflection vector is $r = R/|R| = ({_n4(r[0])}, {_n4(r[1])}, "
                     rf"{_n4(r[2])})$.")
        else:
            i, n = np.asarray(self.I, dtype=float), np.asarray(self.N, dtype=float)
            d = float(n @ i)
            r = i - 2 * d * n
            first = (rf"$N \cdot I = {_n4(d)}$, so $r = I - 2(N \cdot I)N = {_vec(i)} - "
                     rf"2 \cdot ({_n4(d)})\,{_vec(n)} = ({_n4(r[0])}, {_n4(r[1])}, "
                     rf"{_n4(r[2])})$ (a unit vector, as $I$ and $N$ are).")
        inside = r[0] ** 2 + r[1] ** 2 + (r[2] + 1) ** 2
        m = 2 * math.sqrt(inside)
        s, t = r[0] / m + 0.5, r[1] / m + 0.5
        return Worked([
            first,
            rf"$m = 2\sqrt{{r_x^2 + r_y^2 + (r_z + 1)^2}} = 2\sqrt{{{_n4(inside)}}} = "
            rf"{_n4(m)}$.",
            rf"$s = {_n4(r[0])}/{_n4(m)} + 0.5 = {_n4(s)}$, "
            rf"$t = {_n4(r[1])}/{_n4(m)} + 0.5 = {_n4(t)}$.",
        ], [s, t])


# ---------------------------------------------------------------------------------------------
# The reflected view ray and the cube face it reads
# ---------------------------------------------------------------------------------------------

class EnvironmentReflection(_Chapter14):
    r"""The reflected view ray :math:`R = I - 2(\hat N \cdot I)\hat N` of a mirror, and the
    cube-map face it reads.

    :math:`I` is a unit view direction (towards the surface), :math:`N` a normal of whole
    numbers, not of unit length. The answer is :math:`[R_x, R_y, R_z, \text{face}]`, the face
    as its number 0..5 or its name.

    Attributes: ``I``, ``N``.

    Examples
    --------
    >>> ex = EnvironmentReflection(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> rx, ry, rz, face = ex.expected
    >>> ex.check([rx, ry, rz, FACES[int(face)]]).status
    'correct'
    >>> ex.check([-rx, -ry, -rz, int(face) ^ 1]).diagnosis
    'reflection sign'
    """

    title = "A mirror reads the cube map"
    answer_form = "custom"
    what = "R and the face"
    advice = (r"Normalise $N$, then $R = I - 2(\hat N \cdot I)\hat N$ (I travels towards the "
              r"surface); the face is the axis of $R$'s component of largest magnitude, with "
              r"its sign.")
    _FORM = ('**Answer:** a list `[R_x, R_y, R_z, face]`: the reflection vector, then the face '
             'as its number 0 to 5 or its name as a string (`"+X"`, `"-X"`, ...).')

    def draw(self, rng):
        self.I = np.array(pick(rng, _UNITS))
        self.N = rng.integers(-2, 3, size=3).astype(float) + 0.0
        if float(self.N @ self.N) < 2 or float(self.N @ self.I) >= 0:
            self.expected = None
            return
        r = environment.reflect_view(self.I, self.N)
        face, _, _ = environment.cube_face_coordinates(r)
        self.expected = np.array([*(float(x) for x in r), float(face)])

    def acceptable(self):
        if self.expected is None:
            return False
        n_dot_i = float(_unit(self.N) @ self.I)
        if n_dot_i > -0.1487:             # no grazing rays (thresholds off simple fractions)
            return False
        for r, _, _ in self._vectors().values():
            if not _unique_largest(np.abs(r), _MARGIN):
                return False
        r = self.expected[:3]
        return _unique_largest(np.abs(r), _MARGIN) and _unique_largest(r, _MARGIN)

    def _vectors(self):
        """Reflection vectors of the slips: key -> (vector, explanation, key)."""
        i, n = np.asarray(self.I, dtype=float), np.asarray(self.N, dtype=float)
        nn = float(n @ n)
        unit = n / math.sqrt(nn)
        d = float(unit @ i)
        return {
            "reflection sign": (2 * d * unit - i, r"That is $-R$: $R = 2(N \cdot L)N - L$ is "
                                r"the mirror direction of a vector $L$ pointing **away** from "
                                r"the surface (Phong's $R$). The view ray $I$ travels towards "
                                r"the surface, so $R = I - 2(\hat N \cdot I)\hat N$.",
                                "reflection sign"),
            "N not normalised": (i - 2 * float(n @ i) * n, rf"$N$ was not normalised: "
                                 rf"$|N|^2 = {_num(nn)}$, so $2(N \cdot I)N$ is {_num(nn)} "
                                 r"times too long. Use $\hat N = N/|N|$, or divide by "
                                 r"$|N|^2$: $R = I - 2\,\dfrac{N \cdot I}{N \cdot N}\,N$.",
                                 "N not normalised"),
            "N normalised once": (i - 2 * d * n, r"$N$ was normalised in one of its two places "
                                  r"only: in $R = I - 2(\hat N \cdot I)\hat N$ both factors are "
                                  r"the unit normal, so the term is divided by $|N|$ twice "
                                  r"($|N|^2$ in all).", "N normalised once"),
            "factor 2 missing": (i - d * unit, r"The factor 2 is missing: "
                                 r"$I - (\hat N \cdot I)\hat N$ only removes the normal part of "
                                 r"$I$ (the ray would slide along the surface); reflecting "
                                 r"**reverses** it, which takes twice that.", "factor 2 missing"),
        }

    def mistakes(self):
        r, face = self.expected[:3], int(self.expected[3])
        found = [Mistake([*v, float(_major(v))], text, key)
                 for v, text, key in self._vectors().values()]
        k = face // 2
        found.append(Mistake([*r, float(face ^ 1)], rf"$R$ is right, but the face has the "
                             rf"wrong sign: $R_{_AXES[k]} = {_n4(r[k])}$ is "
                             rf"{'negative' if r[k] < 0 else 'positive'}, so $R$ leaves the "
                             rf"cube through {FACES[face]}.", "face sign"))
        j = int(np.argmax(r))                                # the largest *value*
        signed = 2 * j + (1 if r[j] < 0 else 0)
        if signed != face:
            found.append(Mistake([*r, float(signed)], rf"$R$ is right, but the face is the "
                                 rf"axis of the component of largest **magnitude**, "
                                 rf"$|R_{_AXES[k]}| = {_n4(abs(r[k]))}$, not of largest value: "
                                 rf"the face is {FACES[face]}.", "largest signed component"))
        return found

    def statement(self):
        return (
            r"A mirror-like surface is shaded with a cube map. The view ray reaches a surface "
            rf"point with the unit direction $I = {_vec(self.I)}$ (from the eye towards the "
            rf"surface); the surface normal there is $N = {_vec(self.N)}$ (not normalised). "
            r"Compute the reflected direction $R$ (of unit length, like $I$) and the face of "
            r"the cube map it reads: the axis of its component of largest magnitude with that "
            r"component's sign, the faces being numbered +X, −X, +Y, −Y, +Z, −Z = 0, ..., 5."
            "\n\n" + self._FORM + " " + DECIMALS + "\n\n" + data_note("I", "N"))

    def hints(self):
        n = np.asarray(self.N, dtype=float)
        nn = float(n @ n)
        return [r"The view ray travels **towards** the surface, so its mirror image is "
                r"$R = I - 2(\hat N \cdot I)\hat N$ with the **unit** normal $\hat N$.",
                rf"$|N| = \sqrt{{{_num(nn)}}}$ and $N \cdot I = {_n4(float(n @ self.I))}$, so "
                rf"$\hat N \cdot I = {_n4(float(n @ self.I) / math.sqrt(nn))}$.",
                r"Then the face: the largest $|R_i|$ decides the axis, the sign of $R_i$ the "
                r"+ or − face."]

    def worked(self):
        i, n = np.asarray(self.I, dtype=float), np.asarray(self.N, dtype=float)
        nn = float(n @ n)
        ni = float(n @ i)
        r = i - 2 * ni / nn * n
        a = [abs(float(x)) for x in r]
        axis = 0 if a[0] >= a[1] and a[0] >= a[2] else (1 if a[1] >= a[2] else 2)
        face = 2 * axis + (1 if r[axis] < 0 else 0)
        return Worked([
            rf"$N \cdot I = {_n4(ni)}$ and $N \cdot N = {_num(nn)}$; with the unit normal, "
            rf"$2(\hat N \cdot I)\hat N = 2\,\dfrac{{N \cdot I}}{{N \cdot N}}\,N = "
            rf"{_n4(2 * ni / nn)}\,{_vec(n)}$.",
            rf"$R = I - 2(\hat N \cdot I)\hat N = ({_n4(r[0])}, {_n4(r[1])}, {_n4(r[2])})$ "
            rf"(check: $|R| = {_n4(math.sqrt(float(r @ r)))}$).",
            rf"The largest magnitude is $|R_{_AXES[axis]}| = {_n4(a[axis])}$, and "
            rf"$R_{_AXES[axis]}$ is {'negative' if r[axis] < 0 else 'positive'}: face "
            rf"{_face_words(face)}.",
        ], [float(r[0]), float(r[1]), float(r[2]), face])

    def _judge(self, answer):
        read = _read_face_answer(answer, 4, 3, self._FORM)
        if isinstance(read, Feedback):
            return read
        face, r = read
        right_r, right = self.expected[:3], int(self.expected[3])
        if face == right and agrees(r, right_r):
            return Feedback("correct", f"R and the face {FACES[face]} are right.")
        for m in self._mistakes:
            if face == int(m.value[3]) and agrees(r, m.value[:3]):
                return Feedback("wrong", m.explanation, m.key)
        if not agrees(r, right_r):
            for m in self._mistakes:                     # a slip in R, whatever the face
                if m.key in self._vectors() and agrees(r, m.value[:3]):
                    return Feedback("wrong", m.explanation, m.key)
            if rounding_of(r, right_r, [Mistake(m.value[:3], "", m.key)
                                        for m in self._mistakes]):
                return _rounded_parts("the components of $R$")
            length = float(np.linalg.norm(r))
            if length > 1e-9 and agrees(r / length, right_r):
                return Feedback("wrong", f"$R$ points the right way but has the length "
                                f"{_num(length)}: the mirror image of a unit $I$ is a unit "
                                "vector.", "wrong length")
            return Feedback("wrong", "$R$ is off.", "components differ")
        return Feedback("wrong", f"$R$ is right, but the face is not {FACES[face]}.",
                        "value differs")
