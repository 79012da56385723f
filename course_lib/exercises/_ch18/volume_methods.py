"""Chapter 18 exercises: central-difference normals and the order of splats.

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import numpy as np

from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _Chapter18, _num, _vec

__all__ = ["CentralDifferenceNormal", "SplatOrder"]

_AXES = "xyz"


class CentralDifferenceNormal(_Chapter18):
    r"""The unit normal at a voxel from central differences of its six neighbours.

    :math:`g_x = (f(x+h) - f(x-h)) / 2h` and likewise for y and z; the isosurface normal that
    points out of the region :math:`f \ge c` (towards lower values) is
    :math:`\mathbf n = -\mathbf g / |\mathbf g|`.

    Attributes: ``centre`` (the voxel's value), ``plus``, ``minus`` (the neighbours at +h and
    -h along x, y, z), ``h`` (the spacing).

    Examples
    --------
    >>> ex = CentralDifferenceNormal(seed=0)
    >>> g = (ex.plus - ex.minus) / (2 * ex.h)
    >>> ex.check(-g / np.linalg.norm(g)).status
    'correct'
    >>> ex.check(g / np.linalg.norm(g)).diagnosis
    'sign'
    """

    title = "A normal from central differences"
    answer_form = "vector"
    what = "the unit normal"
    advice = (r"Per axis $g = (f_+ - f_-)/2h$; then $\mathbf n = -\mathbf g/|\mathbf g|$ "
              r"(towards lower values, out of the region $f \ge c$).")

    def draw(self, rng):
        self.h = float(pick(rng, (0.25, 2.0)))
        self.centre = float(rng.integers(3, 8))
        while True:
            self.plus = self.centre + rng.integers(-3, 4, size=3).astype(float)
            self.minus = self.centre + rng.integers(-3, 4, size=3).astype(float)
            g = (self.plus - self.minus) / (2 * self.h)
            fwd = (self.plus - self.centre) / self.h
            if np.count_nonzero(g) >= 2 and np.linalg.norm(fwd) > 0:
                break
        self.expected = -g / np.linalg.norm(g)

    def mistakes(self):
        g = (self.plus - self.minus) / (2 * self.h)
        fwd = (self.plus - self.centre) / self.h
        return [
            Mistake(-fwd / np.linalg.norm(fwd), r"You took forward differences "
                    r"$(f_+ - f_0)/h$. Central differences $(f_+ - f_-)/2h$ use both neighbours "
                    r"and are second-order accurate (the voxel's own value does not enter).",
                    "forward difference"),
            Mistake(-(self.plus - self.minus), r"You forgot to divide by $2h$ and to "
                    r"normalise: the normal is a unit vector, $-\mathbf g/|\mathbf g|$.",
                    "forgot /2h"),
            Mistake(-g, r"That is $-\mathbf g$ itself: the normal must be normalised to length "
                    r"1, $-\mathbf g/|\mathbf g|$.", "not normalised"),
            Mistake(g / np.linalg.norm(g), r"Wrong sign: the gradient points towards *higher* "
                    r"values, into the region $f \ge c$; the outward normal is "
                    r"$-\mathbf g/|\mathbf g|$.", "sign"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {a} | {_num(m)} | {_num(p)} |"
                         for a, m, p in zip(_AXES, self.minus, self.plus))
        return (
            rf"A voxel of a volume with spacing $h = {_num(self.h)}$ has the value "
            rf"${_num(self.centre)}$; its six neighbours are" "\n\n"
            r"| axis | value at $-h$ | value at $+h$ |" "\n|---|---|---|\n" + rows + "\n\n"
            r"Estimate the gradient by **central differences** and give the unit normal of the "
            r"isosurface through this voxel that points **towards lower values** (out of the "
            r"region $f \ge c$)." "\n\n"
            r"**Answer:** a list of 3 numbers (x, y, z). " + DECIMALS + "\n\n"
            + data_note("centre", "plus", "minus", "h"))

    def hints(self):
        g = (self.plus - self.minus) / (2 * self.h)
        return [
            r"Central difference along each axis: $g = (f_+ - f_-)/(2h)$.",
            rf"Here $\mathbf g = {_vec(g)}$, of length ${_num(np.linalg.norm(g), 4)}$.",
            r"The gradient points to higher values; the outward normal is its negative, "
            r"divided by its length.",
        ]

    def worked(self):
        g = (self.plus - self.minus) / (2 * self.h)
        steps = [rf"$g_{a} = ({_num(p)} - {_num(m)}) / (2 \cdot {_num(self.h)}) = {_num(gi)}$"
                 for a, p, m, gi in zip(_AXES, self.plus, self.minus, g)]
        length = float(np.linalg.norm(g))
        n = -g / length
        steps.append(rf"$|\mathbf g| = {_num(length, 4)}$, so $\mathbf n = -\mathbf g / "
                     rf"|\mathbf g| = {_vec(np.round(n, 4))}$.")
        return Worked(steps, n)


class SplatOrder(_Chapter18):
    r"""Composite three splats at one pixel in the right depth order.

    The eye looks along the direction ``view``; a splat whose centre :math:`p` has a smaller
    :math:`p \cdot \mathbf d` is nearer the eye. Front to back,
    :math:`C \leftarrow C + (1 - A)\,\alpha_i c_i`, :math:`A \leftarrow A + (1 - A)\,\alpha_i`.
    The answer is the final grey level C.

    Attributes: ``centres`` (3 x 3), ``view``, ``colors``, ``alphas`` (in the listed order).

    Examples
    --------
    >>> ex = SplatOrder(seed=0)
    >>> order = np.argsort(ex.centres @ ex.view, kind="stable")
    >>> C = A = 0.0
    >>> for i in order:
    ...     C, A = C + (1 - A) * ex.alphas[i] * ex.colors[i], A + (1 - A) * ex.alphas[i]
    >>> ex.check(C).status
    'correct'
    """

    title = "The order of splats"
    answer_form = "number"
    what = "the grey level C"
    advice = (r"Sort the splats by $p \cdot \mathbf d$ (smallest first: nearest the eye) and "
              r"composite front to back.")

    def _composite(self, order):
        C = A = 0.0
        for i in order:
            C, A = C + (1 - A) * self.alphas[i] * self.colors[i], A + (1 - A) * self.alphas[i]
        return C

    def draw(self, rng):
        axis = int(rng.integers(3))
        sign = float(pick(rng, (-1.0, 1.0)))
        self.view = np.zeros(3)
        self.view[axis] = sign
        depths = rng.permutation(np.arange(-3, 4))[:3].astype(float)
        self.centres = rng.integers(-3, 4, size=(3, 3)).astype(float)
        self.centres[:, axis] = depths
        self.colors = np.array([pick(rng, (0.2, 0.4, 0.6, 0.8, 1.0)) for _ in range(3)])
        self.alphas = np.array([pick(rng, (0.3, 0.5, 0.6, 0.8)) for _ in range(3)])
        self.order = np.argsort(self.centres @ self.view, kind="stable")
        self.expected = self._composite(self.order)

    def acceptable(self):
        order = list(self.order)
        return order != [0, 1, 2] and order != [2, 1, 0]

    def mistakes(self):
        return [
            Mistake(self._composite(self.order[::-1]), r"You composited the farthest splat "
                    r"first with the front-to-back formula (or the nearest first with the "
                    r"back-to-front *over* operator): the eye looks along $\mathbf d$, so the "
                    r"splat with the **smallest** $p \cdot \mathbf d$ is in front.", "reversed"),
            Mistake(self._composite([0, 1, 2]), r"You composited the splats in the order "
                    r"listed. Splatting must sort them by depth along the view direction first.",
                    "as listed"),
            Mistake(float(self.alphas @ self.colors), r"You summed $\alpha_i c_i$ without the "
                    r"transparency $1 - A$ in front of each splat.", "no transparency"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {i} | {_vec(p)} | {_num(c)} | {_num(a)} |" for i, (p, c, a) in
                         enumerate(zip(self.centres, self.colors, self.alphas)))
        return (
            rf"The eye looks along the direction $\mathbf d = {_vec(self.view)}$ "
            r"(orthographic). Three splats cover the same pixel:" "\n\n"
            r"| splat | centre $p$ | grey $c$ | opacity $\alpha$ |" "\n|---|---|---|---|\n"
            + rows + "\n\n"
            r"Composite them in the right order (front to back: "
            r"$C \leftarrow C + (1 - A)\,\alpha_i c_i$, $A \leftarrow A + (1 - A)\,\alpha_i$, "
            r"from $C = A = 0$). What is the final $C$?" "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n"
            + data_note("centres", "view", "colors", "alphas"))

    def hints(self):
        depth = self.centres @ self.view
        return [
            r"Nearest the eye is the smallest $p \cdot \mathbf d$ (the eye looks along "
            r"$\mathbf d$).",
            "Depths: " + ", ".join(rf"splat {i}: ${_num(d)}$" for i, d in enumerate(depth))
            + rf"; front to back: {', '.join(str(int(i)) for i in self.order)}.",
            r"Composite in that order; $A$ does not depend on the order, $C$ does.",
        ]

    def worked(self):
        depth = self.centres @ self.view
        steps = [r"Depths $p \cdot \mathbf d$: " + ", ".join(
            rf"splat {i}: ${_num(d)}$" for i, d in enumerate(depth))
            + rf". Front to back: {', '.join(str(int(i)) for i in self.order)}."]
        C = A = 0.0
        for i in self.order:
            a, c = float(self.alphas[i]), float(self.colors[i])
            C_new, A_new = C + (1 - A) * a * c, A + (1 - A) * a
            steps.append(rf"Splat {int(i)}: $C = {_num(C, 4)} + {_num(1 - A, 4)} \cdot {_num(a)}"
                         rf" \cdot {_num(c)} = {_num(C_new, 4)}$, $A = {_num(A_new, 4)}$.")
            C, A = C_new, A_new
        return Worked(steps, C)
