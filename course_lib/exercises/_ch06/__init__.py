"""What the chapter 6 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch06`.
"""

import math

import numpy as np

from ... import mesh
from ..core import (UNANSWERED, DrawnExercise, Feedback, diagnose_parts, has_placeholder,
                    parts_separated, pick, read_floats)


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

def _read_ints(answer, n, form, low=None, high=None, noun="index"):
    """A tuple of `n` whole numbers from the answer, or a Feedback saying why not.

    ``5.0`` is the whole number 5; True, 5.5 and text are refused ("invalid"). A whole number
    outside ``low..high`` is read, and wrong ("out of range"): it names no `noun` of the mesh.

    Examples
    --------
    >>> _read_ints([2.0, 3], 2, "Two numbers.", 0, 5)
    (2, 3)
    >>> _read_ints([2.5, 3], 2, "Two numbers.").status, _read_ints([True, 3], 2, "").status
    ('invalid', 'invalid')
    >>> _read_ints([6, 3], 2, "Two numbers.", 0, 5).diagnosis
    'out of range'
    """
    if has_placeholder(answer, none_inside=True):
        return Feedback("unanswered", UNANSWERED)
    if isinstance(answer, (bool, np.bool_)):
        return Feedback("invalid", form, "unreadable")
    values = read_floats(answer)
    if values is None or values.size != n or (n > 1 and values.shape != (n,)):
        return Feedback("invalid", form, "unreadable")
    if isinstance(answer, (list, tuple)) and any(isinstance(a, (bool, np.bool_))
                                                 for a in answer):
        return Feedback("invalid", form, "unreadable")
    values = values.ravel()
    if not np.all(values == np.round(values)):
        return Feedback("invalid", "These are counts and indices: give whole numbers. " + form,
                        "unreadable")
    out = tuple(int(v) for v in values)
    outside = _out_of_range(out, low, high, noun)      # a Feedback, which is False: no `or`
    return out if outside is None else outside


def _out_of_range(values, low, high, noun):
    """A "wrong" Feedback naming a number of `values` outside ``low..high``, else None."""
    if low is None:
        return None
    bad = [v for v in values if v < low or v > high]
    if not bad:
        return None
    return Feedback("wrong", f"There is no {noun} {bad[0]} here: the {noun} numbers run from "
                    f"{low} to {high} (counted from 0).", "out of range")


def _paren(x):
    """A whole number as text, in parentheses when negative (to follow a minus sign)."""
    return f"({x})" if x < 0 else str(x)


def _cycle(face):
    """The directed edges of a face, in its order: [(v0, v1), (v1, v2), ..., (vk, v0)]."""
    return list(zip(face, face[1:] + face[:1]))


def _face_latex(k, face):
    return rf"$f_{{{k}}} = ({', '.join(str(v) for v in face)})$"


def _faces_words(faces):
    return ", ".join(rf"$f_{{{k}}} = ({', '.join(str(v) for v in f)})$"
                     for k, f in enumerate(faces))


#: Small closed meshes, faces counter-clockwise seen from outside.
_SMALL = {
    "tetrahedron": mesh.tetrahedron,
    "square pyramid": lambda: (
        np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [0, 0, 1.5]], dtype=float),
        [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]),
    "triangular prism": lambda: (
        np.array([[math.cos(a), math.sin(a), z] for z in (0.0, 1.0)
                  for a in (0.0, 2 * math.pi / 3, 4 * math.pi / 3)]),
        [[0, 2, 1], [3, 4, 5], [0, 1, 4, 3], [1, 2, 5, 4], [2, 0, 3, 5]]),
    "octahedron": lambda: (
        np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
                 dtype=float),
        [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5],
         [0, 3, 5]]),
}


def _shuffled(rng, vertices, faces):
    """The same mesh with vertex labels permuted, faces reordered and each face rotated.

    The winding of every face is kept, so an outward mesh stays outward.
    """
    vertices = np.asarray(vertices, dtype=float)
    perm = rng.permutation(len(vertices))            # old label i becomes perm[i]
    new_vertices = np.empty_like(vertices)
    new_vertices[perm] = vertices
    out = []
    for f in [list(map(int, f)) for f in faces]:
        k = int(rng.integers(len(f)))
        out.append([int(perm[v]) for v in f[k:] + f[:k]])
    order = rng.permutation(len(out))
    return new_vertices, [out[i] for i in order]


def _small_mesh(rng, names):
    name = str(pick(rng, names))
    vertices, faces = _SMALL[name]()
    return (name, *_shuffled(rng, vertices, faces))


class _Parts(DrawnExercise):
    """An answer of a few numbers, each with its own slips (``_parts()``), see diagnose_parts."""

    answer_form = "custom"
    form_hint = ""

    def mistakes(self):
        return []

    def separated(self, mistakes):
        return parts_separated(self._parts())

    def _check(self, answer):          # diagnose_parts ends with the hint: not hinted again
        return diagnose_parts(answer, self._parts(), "your answer", self.form_hint, self.advice)


class _Record(DrawnExercise):
    """An answer that is a short tuple of whole numbers, matched whole against the slips.

    ``self.expected`` is a tuple; ``mistakes()`` returns Mistakes whose values are tuples
    (``numeric=False``). ``fields`` names the numbers, for the feedback on an unexplained
    answer. ``5.0`` reads as 5. An answer no slip explains is told, in this order: every entry
    one too large ("counted from 1"), a number outside ``low..high`` ("out of range", naming
    the ``noun``), the entries off by one ("off by one"), or which entries differ ("entries
    differ", followed by the exercise's advice).
    """

    answer_form = "custom"
    fields = ()
    low, high = None, None
    #: What the numbers are, for an answer out of ``low..high``.
    noun = "index"

    def keep(self, mistakes):
        return [m for m in mistakes if m.value != self.expected]

    def separated(self, mistakes):
        seen = {}
        for m in mistakes:
            if m.value == self.expected:
                return False
            if seen.setdefault(m.value, m.key) != m.key:
                return False
        return True

    def _read(self, answer):
        return _read_ints(answer, len(self.fields), self.form_hint)

    def _judge(self, answer):
        value = self._read(answer)
        if isinstance(value, Feedback):
            return value
        if value == self.expected:
            return Feedback("correct", f"All {len(self.fields)} entries are right.")
        for mistake in self._mistakes:
            if value == mistake.value:
                return Feedback("wrong", mistake.explanation, mistake.key)
        off = [name for name, a, b in zip(self.fields, value, self.expected) if a != b]
        if all(a == b + 1 for a, b in zip(value, self.expected)):
            return Feedback("wrong", "Every entry is one too large: the numbers here count from "
                            "**0** (the first face, edge or vertex is number 0).",
                            "counted from 1")
        outside = _out_of_range(value, self.low, self.high, self.noun)
        if outside is not None:
            return outside
        if all(abs(a - b) == 1 for a, b in zip(value, self.expected) if a != b):
            return Feedback("wrong", "Off by one in " + ", ".join(off) + ": read the row "
                            "again, and count from 0.", "off by one")
        # the advice follows (DrawnExercise adds it to an unexplained verdict): not added here
        return Feedback("wrong", "Not right yet: " + ", ".join(off) + ".", "entries differ")
