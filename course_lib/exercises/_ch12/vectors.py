"""Chapter 12 exercises: The vectors of the model.

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import numpy as np

from ... import shading
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note
from . import _dot, _frac, _frame, _integer_vector, _length, _nice_unit, _num, _vec

__all__ = [
    "ReflectionVector",
]


class ReflectionVector(DrawnExercise):
    r"""The mirror direction :math:`R = 2 (\hat N \cdot L)\, \hat N - L` of a unit vector L.

    The normal is given with whole-number components and is not of unit length: it must be
    normalised first.

    Attributes: ``N`` (the normal, not normalised), ``L`` (unit, towards the light).

    Examples
    --------
    >>> ex = ReflectionVector(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    >>> n = ex.N / np.linalg.norm(ex.N)
    >>> ex.check(ex.L - 2 * (n @ ex.L) * n).diagnosis          # the ray-tracing form, misread
    'incoming formula'
    >>> ex.check(2 * (ex.N @ ex.L) * ex.N - ex.L).diagnosis
    'N not normalised'
    >>> ex.check(...).status, ex.check("R").status
    ('unanswered', 'invalid')
    """

    title = "The mirror direction R"
    answer_form = "vector"
    what = "the vector R"
    advice = (r"Normalise the normal first, $\hat N = N / \lVert N \rVert$, then "
            r"$R = 2 (\hat N \cdot L)\, \hat N - L$. Check: $R$ is a unit vector and "
            r"$\hat N \cdot R = \hat N \cdot L$.")

    def draw(self, rng):
        self.N, self._length = _integer_vector(rng)
        n = self.N / self._length
        self.L = _frame(_nice_unit(rng), int(rng.integers(3)))
        if n @ self.L < 0:
            self.L = -self.L
        self.expected = shading.reflect(self.L, self.N)

    def acceptable(self):
        n = self.N / self._length
        return 0.2 < n @ self.L < 0.95

    def mistakes(self):
        N, L = self.N, self.L
        n = N / np.linalg.norm(N)
        d = float(n @ L)
        return [
            Mistake(L - 2 * d * n, r"That is $L - 2 (N \cdot L) N$, the reflection formula for "
                    r"an **incoming** direction $D$ (a ray travelling *towards* the surface), "
                    r"$D - 2 (N \cdot D) N$, with $L$ put in for $D$. But $L$ points *away* from "
                    r"the surface, $D = -L$; putting that in gives "
                    r"$-L + 2 (N \cdot L) N$. Your vector is $-R$: it points into the surface.",
                    "incoming formula"),
            Mistake(2 * float(N @ L) * N - L, r"The normal was not normalised. The formula "
                    r"$R = 2 (N \cdot L) N - L$ assumes $\lVert N \rVert = 1$: with a longer "
                    r"$N$ the term $2 (N \cdot L) N$ grows with $\lVert N \rVert^2$. Divide $N$ "
                    rf"by its length ({_num(np.linalg.norm(N))}) first.", "N not normalised"),
            Mistake(d * n, r"That is $(N \cdot L)\, N$, the projection of $L$ onto the normal: "
                    r"the midpoint between $L$ and $R$. The mirror image goes as far past that "
                    r"point again: $R = 2 (N \cdot L) N - L$.", "projection only"),
            Mistake(2 * d * n + L, r"The sign of $L$ is wrong: $R = 2 (N \cdot L) N - L$. "
                    r"Going from $L$ to its mirror image you *subtract* the part of $L$ across "
                    r"the normal; adding $L$ gives a vector that is not even of unit length.",
                    "plus L"),
        ]

    def statement(self):
        return (
            rf"A surface point has the normal $N = {_vec(self.N)}$ (not of unit length). The "
            rf"unit vector towards the light is $L = {_vec(self.L)}$. Compute the mirror "
            r"direction $R$ of $L$ about the normal, the direction in which the light is "
            r"reflected, with the convention that $N$, $L$ and $R$ all point away from the "
            r"surface." "\n\n"
            r"**Answer:** the vector as a list of 3 numbers `[x, y, z]`. " + DECIMALS + "\n\n"
            + data_note("N", "L"))

    def hints(self):
        n = self.N / self._length
        d = float(n @ self.L)
        return [
            r"The mirror image of $L$ about the normal is $R = 2 (\hat N \cdot L)\, \hat N - L$: "
            r"twice the part of $L$ along the normal, minus $L$. The formula needs a **unit** "
            r"normal $\hat N$.",
            rf"$N$ is not of unit length: $\lVert N \rVert = {_length(self.N)}$, so "
            rf"$\hat N = N / {_num(self._length)} = {_vec(n)}$.",
            rf"Here $\hat N \cdot L = {_frac(d)}$, so $R = {_frac(2 * d)}\, \hat N - L$. "
            r"Check your result: $R$ has length 1, and $\hat N \cdot R = \hat N \cdot L$.",
        ]

    def worked(self):
        N, L = np.asarray(self.N, dtype=float), np.asarray(self.L, dtype=float)
        length = float(np.sqrt(N @ N))
        n = N / length
        d = float(n @ L)
        twice = 2 * d * n
        R = twice - L
        return Worked([
            rf"Normalise the normal: $\lVert N \rVert = {_length(N)}$, so "
            rf"$\hat N = N / {_num(length)} = {_vec(n)}$.",
            rf"$\hat N \cdot L = {_dot(n, L)}$.",
            rf"$2 (\hat N \cdot L)\, \hat N = {_frac(2 * d)} \cdot {_vec(n)} = {_vec(twice)}$.",
            rf"$R = 2 (\hat N \cdot L)\, \hat N - L = {_vec(twice)} - {_vec(L)} = {_vec(R)}$. "
            rf"Check: $\lVert R \rVert = {_num(np.sqrt(R @ R), 4)}$ and "
            rf"$\hat N \cdot R = {_num(n @ R, 4)} = \hat N \cdot L$.",
        ], R)
