"""Chapter 18 exercises: volume rendering (compositing, early ray termination, opacity).

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import numpy as np

from ... import scivis
from ..core import DECIMALS, Mistake, Worked, data_note, pick
from . import _Chapter18, _num, _vec

__all__ = [
    "CompositeFrontToBack",
    "EarlyTermination",
    "MaxIntensityProjection",
    "OpacityCorrection",
]


# ---------------------------------------------------------------------------------------------
# Volume rendering
# ---------------------------------------------------------------------------------------------

_TENTHS = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0)


def _samples_table(colors, alphas):
    return ("| sample $i$ | " + " | ".join(str(i) for i in range(len(alphas))) + " |\n"
            + "|---" * (len(alphas) + 1) + "|\n"
            + "| grey level $c_i$ | " + " | ".join(_num(c) for c in colors) + " |\n"
            + r"| opacity $\alpha_i$ | " + " | ".join(_num(a) for a in alphas) + " |")


class CompositeFrontToBack(_Chapter18):
    r"""Composite grey samples along a ray front to back, by hand.

    :math:`C \leftarrow C + (1 - A)\,\alpha_i c_i`, :math:`A \leftarrow A + (1 - A)\,\alpha_i`,
    from :math:`C = A = 0`, sample 0 (the front) first.

    Attributes: ``colors`` (grey levels), ``alphas`` (opacities).

    Examples
    --------
    >>> ex = CompositeFrontToBack(seed=0)
    >>> C, A = scivis.composite(ex.colors, ex.alphas)
    >>> ex.check([C, A]).status
    'correct'
    >>> ex.check(list(scivis.composite(ex.colors[::-1], ex.alphas[::-1]))).diagnosis
    'back first'
    """

    title = "Compositing front to back"
    answer_form = "vector"
    what = "$[C, A]$"
    advice = (r"Keep two running numbers, starting at $C = A = 0$; for each sample from the front "
              r"add $(1 - A)\,\alpha_i c_i$ to $C$ (what still shines through times the "
              r"sample's contribution), then $(1 - A)\,\alpha_i$ to $A$.")

    def draw(self, rng):
        self.colors = np.array([pick(rng, _TENTHS) for _ in range(3)])
        self.alphas = np.array([pick(rng, (0.2, 0.4, 0.5, 0.6, 0.8)) for _ in range(3)])
        C, A = scivis.composite(self.colors, self.alphas)
        self.expected = np.array([C, A])

    def mistakes(self):
        c, a = self.colors, self.alphas
        C, A = 0.0, 0.0
        for ci, ai in zip(c, a):                       # alpha forgotten in the colour
            C, A = C + (1 - A) * ci, A + (1 - A) * ai
        return [
            Mistake(list(scivis.composite(c[::-1], a[::-1])), r"You composited with the last "
                    r"sample in front (or used the back-to-front *over* formula in the order "
                    r"given, which treats sample 0 as the back). Sample 0 is nearest the eye: it "
                    r"hides what lies behind it.", "back first"),
            Mistake([C, A], r"You added $(1 - A)\,c_i$ to the colour, without the sample's "
                    r"opacity. A sample contributes its colour *weighted by how opaque it is*: "
                    r"$(1 - A)\,\alpha_i c_i$.", "alpha forgotten"),
            Mistake([float(a @ c), float(a.sum())], r"You summed $\alpha_i c_i$ and "
                    r"$\alpha_i$ without the transparency factor $1 - A$: samples behind "
                    r"others are only seen through them, so each contribution is multiplied by "
                    r"what still shines through, $1 - A$ (and $A$ can never exceed 1).",
                    "no transparency"),
        ]

    def statement(self):
        return (
            r"A ray meets three samples, listed from the front (nearest the eye):" "\n\n"
            + _samples_table(self.colors, self.alphas) + "\n\n"
            r"Composite them **front to back**: start with $C = 0$, $A = 0$ and for "
            r"$i = 0, 1, 2$ set $C \leftarrow C + (1 - A)\,\alpha_i c_i$ and "
            r"$A \leftarrow A + (1 - A)\,\alpha_i$. What are the final $C$ and $A$?" "\n\n"
            r"**Answer:** a list of 2 numbers `[C, A]`. " + DECIMALS + "\n\n"
            + data_note("colors", "alphas"))

    def _running(self):
        """(C, A) after each sample, front first."""
        C = A = 0.0
        out = []
        for c, a in zip(self.colors, self.alphas):
            C, A = C + (1 - A) * float(a) * float(c), A + (1 - A) * float(a)
            out.append((C, A))
        return out

    def hints(self):
        (C0, A0), (C1, A1), _ = self._running()
        a, c = self.alphas, self.colors
        return [
            r"Front to back: keep the colour $C$ and the opacity $A$ gathered so far; a sample "
            r"is seen only through what is still transparent, $1 - A$: "
            r"$C \leftarrow C + (1 - A)\,\alpha_i c_i$, $A \leftarrow A + (1 - A)\,\alpha_i$.",
            rf"Sample 0 meets a clear ray ($A = 0$): $C = {_num(a[0])} \cdot {_num(c[0])} = "
            rf"{_num(C0, 4)}$ and $A = {_num(A0, 4)}$.",
            rf"Sample 1 is seen through $1 - A = {_num(1 - A0, 4)}$: $C = {_num(C0, 4)} + "
            rf"{_num(1 - A0, 4)} \cdot {_num(a[1])} \cdot {_num(c[1])} = {_num(C1, 4)}$, "
            rf"$A = {_num(A0, 4)} + {_num(1 - A0, 4)} \cdot {_num(a[1])} = {_num(A1, 4)}$; "
            r"sample 2 in the same way.",
        ]

    def worked(self):
        steps = [r"Start with $C = 0$, $A = 0$, and take the samples from the front."]
        C = A = 0.0
        for i, (c, a) in enumerate(zip(self.colors, self.alphas)):
            left = 1 - A
            C_new, A_new = C + left * float(a) * float(c), A + left * float(a)
            steps.append(rf"Sample {i} ($c_{i} = {_num(c)}$, $\alpha_{i} = {_num(a)}$), seen "
                         rf"through $1 - A = {_num(left, 4)}$: $C = {_num(C, 4)} + "
                         rf"{_num(left, 4)} \cdot {_num(a)} \cdot {_num(c)} = {_num(C_new, 4)}$, "
                         rf"$A = {_num(A, 4)} + {_num(left, 4)} \cdot {_num(a)} = "
                         rf"{_num(A_new, 4)}$.")
            C, A = C_new, A_new
        return Worked(steps, [C, A])


class EarlyTermination(_Chapter18):
    r"""After how many samples early ray termination stops a ray.

    The accumulated opacity :math:`A_k = 1 - \prod_{i < k} (1 - \alpha_i)` after :math:`k`
    samples; the ray stops after the first :math:`k` with :math:`A_k \ge` the threshold.

    Attributes: ``alphas``, ``threshold``.

    Examples
    --------
    >>> ex = EarlyTermination(seed=0)
    >>> A = 1 - np.cumprod(1 - ex.alphas)
    >>> ex.check(int(np.argmax(A >= ex.threshold)) + 1).status
    'correct'
    """

    title = "Early ray termination"
    answer_form = "number"
    what = "the number of samples"
    advice = (r"Track $A \leftarrow A + (1 - A)\,\alpha_i$ (or the transparency "
              r"$T = 1 - A$, multiplied by $1 - \alpha_i$ at each sample) and stop as soon as "
              r"$A$ reaches the threshold.")

    def draw(self, rng):
        self.alphas = np.array([pick(rng, (0.2, 0.3, 0.4, 0.5, 0.6, 0.7)) for _ in range(10)])
        self.threshold = float(pick(rng, (0.9, 0.95)))
        _, A = scivis.composite(np.zeros(10), self.alphas, cumulative=True)
        reached = A >= self.threshold - 1e-9         # 1 - 0.1 may come out as 0.8999...
        self.expected = int(np.argmax(reached)) + 1 if reached.any() else 0

    def acceptable(self):
        return 3 <= self.expected <= 9

    def mistakes(self):
        total = np.cumsum(self.alphas)
        summed = int(np.argmax(total >= self.threshold - 1e-9)) + 1
        return [
            Mistake(summed, r"You added up the opacities. Each sample only covers the part that "
                    r"is still transparent: $A \leftarrow A + (1 - A)\,\alpha_i$, so $A$ grows "
                    r"more and more slowly and never passes 1.", "summed opacities"),
            Mistake(self.expected - 1, r"One sample too few: check $A$ after each sample, "
                    r"including the last one you count; the ray stops only once $A$ has "
                    r"reached the threshold.", "off by one"),
            Mistake(self.expected + 1, r"One sample too many: the ray stops right after the "
                    r"sample that brings $A$ to the threshold; that sample is the last one "
                    r"composited.", "off by one"),
        ]

    def statement(self):
        alphas = ", ".join(_num(a) for a in self.alphas)
        return (
            r"A ray is composited front to back with early ray termination: it stops as soon as "
            rf"the accumulated opacity $A$ reaches ${_num(self.threshold)}$. Its samples have the "
            rf"opacities (from the front) ${alphas}$. How many samples are composited before "
            r"it stops (counting the one that reaches the threshold)?" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("alphas", "threshold"))

    def _opacities(self):
        """The accumulated opacity after each sample, up to the one that reaches the threshold
        (rounded to 12 decimals: 1 - 0.1 is 0.9 here, not 0.8999...)."""
        out, transparency = [], 1.0
        for a in self.alphas:
            transparency *= 1 - float(a)
            out.append(round(1 - transparency, 12))
            if out[-1] >= self.threshold:
                break
        return out

    def hints(self):
        A = self._opacities()
        return [
            r"Track the transparency left, $T = 1 - A$: each sample multiplies it by "
            r"$1 - \alpha_i$ (the same as $A \leftarrow A + (1 - A)\,\alpha_i$). The ray stops "
            r"after the sample at which $A$ reaches the threshold.",
            rf"$A \ge {_num(self.threshold)}$ means $T \le {_num(1 - self.threshold)}$. After "
            rf"the first two samples $T = (1 - {_num(self.alphas[0])})(1 - "
            rf"{_num(self.alphas[1])}) = {_num(1 - A[1], 4)}$, $A = {_num(A[1], 4)}$.",
            rf"After {len(A) - 1} samples $A = {_num(A[-2], 4)}$, still below "
            rf"${_num(self.threshold)}$; look at the next sample.",
        ]

    def worked(self):
        A = self._opacities()
        rows = ", ".join(rf"$A_{k} = {_num(x, 4)}$" for k, x in enumerate(A, 1))
        count = len(A)
        steps = [
            r"Composite the opacities front to back: $A_k = A_{k-1} + (1 - A_{k-1})\,\alpha_k$, "
            r"or, with the transparency, $1 - A_k = (1 - A_{k-1})(1 - \alpha_k)$, from "
            r"$A_0 = 0$.",
            rf"Sample by sample ($\alpha = {', '.join(_num(a) for a in self.alphas[:count])}$): "
            + rows + ".",
            rf"$A_{{{count - 1}}} = {_num(A[-2], 4)} < {_num(self.threshold)}$ but "
            rf"$A_{{{count}}} = {_num(A[-1], 4)} \ge {_num(self.threshold)}$"
            + (r" (exactly the threshold: reaching it counts)" if A[-1] == self.threshold
               else "") + rf": the ray stops after {count} samples.",
        ]
        return Worked(steps, count)


class OpacityCorrection(_Chapter18):
    r"""The opacity of a sample for a new step size: :math:`\alpha' = 1 - (1 - \alpha)^{\Delta}`.

    A transfer function gives the opacity :math:`\alpha` of a slab of unit thickness; light
    through a slab of thickness :math:`\Delta` keeps the fraction :math:`(1 - \alpha)^\Delta`.

    Attributes: ``alpha``, ``step``.

    Examples
    --------
    >>> ex = OpacityCorrection(seed=0)
    >>> ex.check(1 - (1 - ex.alpha) ** ex.step).status
    'correct'
    >>> ex.check(ex.alpha * ex.step).diagnosis
    'linear'
    """

    title = "Opacity correction for the step size"
    answer_form = "number"
    what = "the corrected opacity"
    advice = (r"Transparencies multiply: a slab of thickness $\Delta$ lets "
              r"$(1 - \alpha)^{\Delta}$ through, so its opacity is $1 - (1 - \alpha)^{\Delta}$.")

    def draw(self, rng):
        self.alpha = float(pick(rng, (0.2, 0.25, 0.3, 0.35, 0.4, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8,
                                      0.85, 0.9, 0.95)))
        self.step = float(pick(rng, (0.25, 0.5, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0)))
        self.expected = 1 - (1 - self.alpha) ** self.step

    def mistakes(self):
        a, d = self.alpha, self.step
        return [
            Mistake(a * d, r"You scaled the opacity linearly with the step. Opacity does not "
                    r"add up: two slabs of opacity 0.5 let $0.5 \cdot 0.5 = 0.25$ through, "
                    r"opacity 0.75, not 1. The transparencies multiply: "
                    r"$1 - (1 - \alpha)^{\Delta}$.", "linear"),
            Mistake(a ** d, r"You raised the opacity to the power $\Delta$. It is the "
                    r"**transparency** $1 - \alpha$ that is multiplied per unit length: "
                    r"$\alpha' = 1 - (1 - \alpha)^{\Delta}$.", "power of alpha"),
            Mistake((1 - a) ** d, r"That is the transparency $(1 - \alpha)^{\Delta}$ of the "
                    r"slab, the light that gets through. The opacity is one minus it.",
                    "transparency"),
            Mistake(1 - (1 - a) ** (1 / d), r"You used the exponent $1/\Delta$. A slab "
                    r"$\Delta$ units thick is like $\Delta$ unit slabs in a row: exponent "
                    r"$\Delta$.", "inverse step"),
        ]

    def statement(self):
        return (
            rf"A transfer function gives the opacity $\alpha = {_num(self.alpha)}$ per unit "
            r"length (one voxel). A ray caster samples the volume every "
            rf"$\Delta = {_num(self.step)}$ voxels. Which opacity must each sample get so that "
            r"the picture does not depend on the step size?" "\n\n"
            r"**Answer:** one number. " + DECIMALS + "\n\n" + data_note("alpha", "step"))

    def hints(self):
        kept = 1 - self.alpha
        return [
            r"Opacities do not add up, transparencies multiply: light through two slabs in a "
            r"row is what the first lets through times what the second lets through.",
            rf"One voxel of material lets $1 - \alpha = {_num(kept)}$ of the light through; a "
            rf"sample that stands for $\Delta = {_num(self.step)}$ voxels lets "
            rf"$(1 - \alpha)^{{\Delta}} = {_num(kept)}^{{{_num(self.step)}}}$ through.",
            rf"${_num(kept)}^{{{_num(self.step)}}} = {_num(kept ** self.step, 4)}$; the opacity "
            r"of the sample is what it does **not** let through.",
        ]

    def worked(self):
        kept = 1 - self.alpha
        through = kept ** self.step
        corrected = 1 - through
        return Worked([
            rf"Per voxel the transparency is $1 - \alpha = 1 - {_num(self.alpha)} = "
            rf"{_num(kept)}$; transparencies multiply along the ray.",
            rf"A step of $\Delta = {_num(self.step)}$ voxels: "
            rf"$(1 - \alpha)^{{\Delta}} = {_num(kept)}^{{{_num(self.step)}}} = "
            rf"{_num(through, 4)}$ of the light gets through.",
            rf"$\alpha' = 1 - (1 - \alpha)^{{\Delta}} = 1 - {_num(through, 4)} = "
            rf"{_num(corrected, 4)}$ ("
            + ("more" if self.step > 1 else "less") + r" than $\alpha$: the step is "
            + ("longer" if self.step > 1 else "shorter") + r" than a voxel).",
        ], corrected)


_AXES = {0: "z", 1: "y", 2: "x"}


class MaxIntensityProjection(_Chapter18):
    r"""A maximum intensity projection of a tiny 3 x 3 x 3 volume along one axis.

    The volume is ``volume[k, j, i]``, the sample at :math:`(x, y, z) = (i, j, k)`; rays
    parallel to an axis keep the largest sample: ``volume.max(axis)``.

    Attributes: ``volume``, ``axis`` (the array axis the rays run along), ``axis_name``.

    Examples
    --------
    >>> ex = MaxIntensityProjection(seed=0)
    >>> ex.check(ex.volume.max(axis=ex.axis)).status
    'correct'
    >>> ex.check(ex.volume.sum(axis=ex.axis)).diagnosis
    'sum'
    """

    title = "Maximum intensity projection"
    answer_form = "matrix"
    what = "the projected image"
    transform = False
    advice = r"Along each ray (fix the two other indices) keep the largest of the three samples."

    def draw(self, rng):
        self.volume = rng.integers(0, 10, size=(3, 3, 3)).astype(float)
        self.axis = int(pick(rng, (0, 1, 2)))
        self.axis_name = _AXES[self.axis]
        self.expected = self.volume.max(axis=self.axis)

    def mistakes(self):
        v, ax = self.volume, self.axis
        return [
            *(Mistake(v.max(axis=other), rf"You projected along the {_AXES[other]} axis (array "
                      rf"axis {other}). The rays run along {self.axis_name}, array axis {ax}: "
                      rf"take the maximum over index {'kji'[ax]}.", "wrong axis")
              for other in (0, 1, 2) if other != ax),
            Mistake(v.sum(axis=ax), r"You summed the samples along each ray: that is an "
                    r"X-ray-like projection (an average up to a factor). MIP keeps only the "
                    r"largest sample, so the brightest structure shows at full intensity.",
                    "sum"),
            Mistake(v.mean(axis=ax), r"You averaged the samples along each ray. MIP keeps the "
                    r"largest sample: a bright vessel stays bright however thin it is.", "mean"),
            Mistake(v.min(axis=ax), r"You took the smallest sample: MIP takes the **maximum**.",
                    "min"),
        ]

    def statement(self):
        slices = "\n\n".join(
            rf"$k = {k}$ ($z = {k}$): " + ", ".join(
                rf"row $j = {j}$: ${_vec(self.volume[k, j])}$" for j in range(3))
            for k in range(3))
        return (
            r"A tiny volume holds the samples `volume[k][j][i]` at $(x, y, z) = (i, j, k)$ "
            r"(each row lists $i = 0, 1, 2$):" "\n\n" + slices + "\n\n"
            rf"Compute its maximum intensity projection with rays parallel to the "
            rf"**{self.axis_name} axis** (array axis {self.axis})." "\n\n"
            r"**Answer:** the image as a 3 x 3 array whose rows and columns follow the two "
            r"remaining array axes in their order (so `volume.max(axis=...)` has the right "
            r"layout)." "\n\n" + data_note("volume", "axis"))

    def _layout(self):
        """The names of the two array axes left (rows, columns of the image)."""
        left = [i for i in range(3) if i != self.axis]
        return ["kji"[i] for i in left]

    def _ray(self, r, c):
        """The three samples along the ray of pixel (r, c)."""
        index = [r, c]
        index.insert(self.axis, slice(None))
        return [float(x) for x in self.volume[tuple(index)]]

    def hints(self):
        rows, cols = self._layout()
        ray = self._ray(0, 0)
        return [
            r"A maximum intensity projection keeps, along each ray, only the **largest** sample "
            r"(no sum, no average).",
            rf"Rays parallel to the {self.axis_name} axis run over the index "
            rf"${'kji'[self.axis]}$ (array axis {self.axis}); the image pixel $[{rows}][{cols}]$ "
            rf"is the maximum of the three samples with those ${rows}$ and ${cols}$.",
            rf"For example pixel $[0][0]$: the samples ${', '.join(_num(x) for x in ray)}$ along "
            rf"its ray, so it gets ${_num(max(ray))}$.",
        ]

    def worked(self):
        rows, cols = self._layout()
        image = [[max(self._ray(r, c)) for c in range(3)] for r in range(3)]
        steps = [rf"The rays run along array axis {self.axis} (index ${'kji'[self.axis]}$); the "
                 rf"image's rows follow ${rows}$ and its columns ${cols}$."]
        for r in range(3):
            steps.append(rf"Row ${rows} = {r}$: " + ", ".join(
                rf"$\max({', '.join(_num(x) for x in self._ray(r, c))}) = {_num(image[r][c])}$"
                for c in range(3)) + ".")
        return Worked(steps, image)
