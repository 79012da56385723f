"""Chapter 5 exercises: Back-face culling.

Part of :mod:`course_lib.exercises.ch05`, which imports every exercise from here.
"""

import numpy as np

from ... import clipping
from ..core import Mistake, Worked, data_note, small_ints
from . import _Listed, _num, _set_feedback, _vec

__all__ = [
    "BackFaceCulling",
]


class BackFaceCulling(_Listed):
    r"""Which faces does back-face culling remove, seen from an eye in perspective?

    Face :math:`i` (a point :math:`P_i` and an outward normal :math:`n_i`) is a back face when
    :math:`n_i \cdot (P_i - E) \ge 0`: the view vector runs from the eye to the face and differs
    from face to face in a perspective view.

    Attributes: ``eye``, ``gaze``, ``points``, ``normals``.

    Examples
    --------
    >>> ex = BackFaceCulling(seed=1)
    >>> ex.check(sorted(ex.expected)).status
    'correct'
    >>> front = set(range(len(ex.points))) - ex.expected
    >>> ex.check(sorted(front)).diagnosis
    'compendium sign'
    >>> ex.check(...).status, ex.check("all").status
    ('unanswered', 'invalid')
    """

    title = "Back-face culling in perspective"
    answer_form = "custom"

    def draw(self, rng):
        while True:
            self.eye = rng.integers(-5, 6, size=3).astype(float)
            if np.linalg.norm(self.eye) >= 4:
                break
        self.gaze = -self.eye
        self.points = rng.integers(-2, 3, size=(5, 3)).astype(float)
        self.normals = np.array([small_ints(rng, 3, -1, 1) for _ in range(5)])
        self._dots = np.einsum("ij,ij->i", self.normals, self.points - self.eye)
        mask = clipping.is_back_face(self.normals, self.points - self.eye)
        self.expected = {int(i) for i in np.flatnonzero(mask)}

    def _constant(self):
        return {int(i) for i in np.flatnonzero(self.normals @ self.gaze >= 0)}

    def acceptable(self):
        everything = set(range(len(self.points)))
        front = everything - self.expected
        constant = self._constant()
        return (np.all(self._dots != 0) and 0 < len(self.expected) < len(self.points)
                and np.all(self.normals @ self.gaze != 0)
                and constant != self.expected and constant != front)

    def mistakes(self):
        front = set(range(len(self.points))) - self.expected
        return [
            Mistake(front, r"You kept the back faces and culled the front ones. With the view "
                    r"vector $v = P - E$ pointing **from the eye to the face**, a face turns its "
                    r"back when $n \cdot v \ge 0$ (the normal points away from the eye). The "
                    r"compendium's $v \cdot n < 0$ holds for a view vector pointing from the face "
                    r"to the eye.", "compendium sign", numeric=False),
            Mistake(self._constant(), r"You used the same view vector (the gaze direction) for "
                    r"every face, which is right for a parallel projection only. In perspective "
                    r"the view vector runs from the eye to each face, $v_i = P_i - E$, and faces "
                    r"near the edge of the view can flip.",
                    "constant view direction", numeric=False),
        ]

    def separated(self, mistakes):
        return True

    def _check(self, answer):
        return _set_feedback(answer, self.expected, self._mistakes, len(self.points),
                             "the back faces",
                             r"For each face compute $n_i \cdot (P_i - E)$; the back faces are "
                             r"those where it is $\ge 0$.",
                             "Exactly these faces turn their backs to the eye.")

    def _view(self, i):
        """The view vector of face i, from the eye to its point, and the dot product."""
        v = self.points[i] - self.eye
        return v, float(self.normals[i] @ v)

    def hints(self):
        v, dot = self._view(0)
        return [
            r"A face turns its back to the eye when its outward normal points away from the "
            r"eye: with the view vector $v_i = P_i - E$ from the eye **to** the face, it is a "
            r"back face when $n_i \cdot v_i \ge 0$.",
            r"In perspective the view vector differs from face to face: compute "
            r"$P_i - E$ for each face (not the gaze direction $g$), then the dot product with "
            r"its normal, and keep the faces where it is $\ge 0$.",
            rf"Face 0: $P_0 - E = {_vec(v)}$ and $n_0 \cdot (P_0 - E) = {_num(dot)}$, so it "
            rf"is a {'back' if dot >= 0 else 'front'} face. The other four likewise.",
        ]

    def worked(self):
        steps, back = [], []
        for i in range(len(self.points)):
            v, dot = self._view(i)
            verdict = "back face (culled)" if dot >= 0 else "front face (kept)"
            steps.append(rf"Face {i}: $v_{i} = P_{i} - E = {_vec(self.points[i])} - "
                         rf"{_vec(self.eye)} = {_vec(v)}$, $n_{i} \cdot v_{i} = "
                         rf"{_vec(self.normals[i])} \cdot {_vec(v)} = {_num(dot)}$: {verdict}.")
            if dot >= 0:
                back.append(i)
        steps.append(r"Back-face culling removes the faces with $n_i \cdot v_i \ge 0$: "
                     + ", ".join(str(i) for i in back) + ".")
        return Worked(steps, back)

    def statement(self):
        rows = "\n".join(rf"| {i} | ${_vec(p)}$ | ${_vec(n)}$ |"
                         for i, (p, n) in enumerate(zip(self.points, self.normals)))
        return (
            rf"A perspective camera at the eye $E = {_vec(self.eye)}$ looks towards the origin "
            rf"(gaze direction $g = {_vec(self.gaze)}$) at a closed, opaque mesh. Five of its "
            r"faces are given by a point $P_i$ on the face and the face's outward normal "
            r"$n_i$:" "\n\n| face | point $P_i$ | outward normal $n_i$ |\n|---|---|---|\n"
            + rows + "\n\n"
            r"Which of these faces does back-face culling remove?" "\n\n"
            r"**Answer:** the list of the indices of the back faces, e.g. `[0, 3]` (`[]` if "
            r"there are none; the order does not matter)." "\n\n"
            + data_note("eye", "gaze", "points", "normals"))
