"""Chapter 12 exercises: ambient occlusion in screen space (SSAO).

Part of :mod:`course_lib.exercises.ch12`, which imports every exercise from here.
"""

import math

import numpy as np

from ..core import DrawnExercise, Mistake, Worked, data_note, pick
from . import _ONE_NUMBER, _n4, _num

__all__ = [
    "SSAOPixel",
    "SSAOSampleCount",
]


def _samples(numbers):
    """"sample 3" or "samples 1, 2, 5" (or "none")."""
    if not numbers:
        return "none"
    return ("sample " if len(numbers) == 1 else "samples ") + ", ".join(map(str, numbers))


def ssao_occluded(d_sample, d_stored, d_pixel, bias, radius, use_bias=True, range_check=True,
                  reversed_=False):
    """Which kernel samples count as occluded (depths are distances from the camera)."""
    b = bias if use_bias else 0.0
    if reversed_:
        hit = d_stored > d_sample + b
    else:
        hit = d_stored < d_sample - b
    if range_check:
        hit &= np.abs(d_stored - d_pixel) <= radius
    return hit


class SSAOPixel(DrawnExercise):
    r"""The SSAO value of one pixel from a table of kernel samples.

    Each sample has its own depth (distance from the camera along the view axis) and the depth
    stored in the depth buffer at the pixel it projects to. It is occluded when the stored
    surface is in front of it by more than the bias, :math:`d_S < d_Q - b`, unless the range
    check rejects the occluder, :math:`|d_S - d_P| > R`. The answer is the visibility
    :math:`1 - \text{occluded}/k`.

    Attributes: ``d_pixel`` (the pixel's own depth :math:`d_P`), ``d_sample``, ``d_stored``
    (per sample), ``bias``, ``radius``.

    Examples
    --------
    >>> ex = SSAOPixel(seed=4)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check(1 - ex.expected).diagnosis
    'occlusion instead of visibility'
    """

    title = "The SSAO value of a pixel"
    answer_form = "number"
    what = "the SSAO visibility of the pixel"
    advice = (r"For each sample compare the stored depth $d_S$ with the sample's depth $d_Q$: "
              r"occluded if $d_S < d_Q - b$ and $|d_S - d_P| \le R$. The answer is "
              r"1 − (occluded samples)/(samples).")

    def draw(self, rng):
        self.radius = float(pick(rng, (0.5, 1.0)))
        self.bias = float(pick(rng, (0.1, 0.2)))
        self.d_pixel = float(pick(rng, np.arange(4.0, 8.5, 0.5)))
        k = int(rng.integers(6, 9))
        # kinds: 0 open (stored behind), 1 occluded, 2 within the bias, 3 far in front (halo)
        kinds = np.r_[[0, 1, 2, 3], rng.choice(4, size=k - 4, p=[0.35, 0.35, 0.1, 0.2])]
        kinds = kinds[rng.permutation(k)]
        steps = np.arange(-0.4, 0.45, 0.05) * self.radius / 0.5
        d_q = self.d_pixel + rng.choice(steps, size=k)
        d_s = np.empty(k)
        for i, kind in enumerate(kinds):
            if kind == 0:
                d_s[i] = d_q[i] + float(pick(rng, (0.3, 0.5, 1.0, 2.0)))
            elif kind == 1:
                d_s[i] = d_q[i] - self.bias - float(pick(rng, (0.05, 0.1, 0.15)))
            elif kind == 2:
                d_s[i] = d_q[i] - self.bias / 2
            else:
                d_s[i] = self.d_pixel - self.radius - float(pick(rng, (0.5, 1.0, 1.5, 2.5)))
        self.d_sample = np.round(d_q, 3)
        self.d_stored = np.round(d_s, 3)
        self._occluded = ssao_occluded(self.d_sample, self.d_stored, self.d_pixel, self.bias,
                                       self.radius)
        self.expected = float(1 - self._occluded.mean())

    def acceptable(self):
        d_q, d_s = self.d_sample, self.d_stored
        # no comparison within rounding of its threshold, every sample on the screen's near side
        margins = np.r_[np.abs(d_s - (d_q - self.bias)), np.abs(d_s - d_q),
                        np.abs(np.abs(d_s - self.d_pixel) - self.radius),
                        np.abs(d_s - (d_q + self.bias))]
        return bool(margins.min() > 0.02 and d_s.min() > 0.5 and 0 < self.expected < 1)

    def _variants(self):
        args = (self.d_sample, self.d_stored, self.d_pixel, self.bias, self.radius)
        return {
            "bias ignored": ssao_occluded(*args, use_bias=False),
            "range check ignored": ssao_occluded(*args, range_check=False),
            "comparison reversed": ssao_occluded(*args, reversed_=True),
        }

    def mistakes(self):
        k = len(self.d_sample)
        v = self._variants()
        return [
            Mistake(float(self._occluded.mean()), r"That is the occluded fraction. SSAO "
                    r"returns the **visibility** that multiplies the ambient term: 1 minus "
                    r"the occluded fraction (1 on an open floor).",
                    "occlusion instead of visibility"),
            Mistake(float(1 - v["bias ignored"].sum() / k), r"The bias was left out. A "
                    r"sample counts as occluded only if the stored surface is in front of it "
                    r"by **more than** the bias, $d_S < d_Q - b$: samples just above a surface "
                    r"would otherwise be hidden by that surface itself (self-occlusion).",
                    "bias ignored"),
            Mistake(float(1 - v["range check ignored"].sum() / k), r"The range check was "
                    r"left out. A stored surface whose depth differs from the pixel's own by "
                    r"more than the radius, $|d_S - d_P| > R$, is a different object far in "
                    r"front (or behind); it cannot be within the hemisphere of radius $R$ and "
                    r"is ignored (without this, halos appear around objects).",
                    "range check ignored"),
            Mistake(float(1 - v["comparison reversed"].sum() / k), r"The comparison is the "
                    r"wrong way round. Depths are distances from the camera: a sample is hidden "
                    r"when the stored surface is **nearer** the camera than the sample, "
                    r"$d_S < d_Q - b$, not further.", "comparison reversed"),
        ]

    def statement(self):
        rows = "\n".join(rf"| {i + 1} | {_num(q)} | {_num(s)} |"
                         for i, (q, s) in enumerate(zip(self.d_sample, self.d_stored)))
        return (
            rf"A pixel's visible surface point $P$ has depth $d_P = {_num(self.d_pixel)}$ "
            r"(distance from the camera along the view direction). SSAO placed "
            rf"{len(self.d_sample)} kernel samples $Q_i$ in the hemisphere of radius "
            rf"$R = {_num(self.radius)}$ above $P$ and projected each to the screen. The table "
            r"gives each sample's depth $d_Q$ and the depth $d_S$ stored in the depth buffer at "
            r"the pixel the sample projects to." "\n\n"
            "| sample | $d_Q$ | stored $d_S$ |\n|---|---|---|\n" + rows + "\n\n"
            rf"The bias is $b = {_num(self.bias)}$, and the range check is on: an occluder "
            r"whose stored depth differs from $d_P$ by more than $R$ is ignored. Give the SSAO "
            r"visibility of the pixel (1 = open, 0 = fully occluded), before any blur."
            "\n\n" + _ONE_NUMBER + "\n\n"
            + data_note("d_pixel", "d_sample", "d_stored", "bias", "radius"))

    def _lists(self):
        d_q, d_s = self.d_sample, self.d_stored
        front = [i + 1 for i in range(len(d_q)) if d_s[i] < d_q[i] - self.bias]
        near_bias = [i + 1 for i in range(len(d_q)) if d_q[i] - self.bias <= d_s[i] < d_q[i]]
        far = [i for i in front if abs(d_s[i - 1] - self.d_pixel) > self.radius]
        occluded = [i for i in front if i not in far]
        return front, near_bias, far, occluded

    def hints(self):
        front, near_bias, far, occluded = self._lists()
        return [r"Depths are distances from the camera: a sample is behind the stored surface "
                r"(hidden, occluded) when $d_S$ is **smaller** than $d_Q$, by more than the "
                rf"bias $b = {_num(self.bias)}$.",
                rf"In front by more than the bias: {_samples(front)}. Within the bias only "
                rf"(not occluded): {_samples(near_bias)}.",
                rf"Range check $|d_S - {_num(self.d_pixel)}| \le {_num(self.radius)}$: it "
                rf"rejects {_samples(far)}; what is left are the occluded samples."]

    def worked(self):
        front, near_bias, far, occluded = self._lists()
        k = len(self.d_sample)
        value = 1 - len(occluded) / k
        return Worked([
            rf"Stored surface in front of the sample by more than $b = {_num(self.bias)}$ "
            rf"($d_S < d_Q - b$): {_samples(front)}. Within the bias only, not occluded: "
            rf"{_samples(near_bias)}.",
            rf"Range check: $|d_S - d_P| > R = {_num(self.radius)}$ for {_samples(far)}, a "
            r"surface far in front of $P$, ignored.",
            rf"Occluded: {_samples(occluded)}, that is {len(occluded)} of {k}; visibility "
            rf"$= 1 - {len(occluded)}/{k} = {_n4(value)}$.",
        ], value)


class SSAOSampleCount(DrawnExercise):
    r"""How many kernel samples SSAO needs for a given noise level.

    Each sample is a 0/1 variable (occluded or not), so a k-sample estimate of a visibility
    :math:`p` has standard error :math:`\sqrt{p(1-p)/k}`, at most :math:`1/(2\sqrt k)` (at
    :math:`p = 1/2`). A blur over an :math:`n \times n` tile averages :math:`n^2` pixels whose
    kernels are rotated differently, about :math:`n^2 k` samples.

    Attributes: ``kind`` (``"worst"``, ``"known"`` or ``"blur"``), ``sigma`` (the standard error
    wanted), ``p`` (the visibility, for ``"known"``), ``n`` (the blur size, for ``"blur"``).

    Examples
    --------
    >>> ex = SSAOSampleCount(seed=1)
    >>> ex.check(ex.expected).status
    'correct'
    """

    title = "Samples for a noise level"
    answer_form = "number"
    what = "the smallest number of samples"
    advice = (r"The standard error of an average of $k$ 0/1 samples is $\sqrt{p(1-p)/k}$; solve "
              r"$\sqrt{p(1-p)/k} \le \sigma$ for the smallest whole $k$.")

    _SIGMAS = (0.025, 0.05, 0.0625, 0.1, 0.125, 0.2, 0.04, 0.08)

    def draw(self, rng):
        self.kind = str(pick(rng, ("worst", "known", "blur")))
        self.sigma = float(pick(rng, self._SIGMAS))
        self.p = float(pick(rng, (0.9, 0.8, 0.75, 0.6))) if self.kind == "known" else 0.5
        self.n = int(pick(rng, (2, 4))) if self.kind == "blur" else 1
        self.expected = float(self._count(self.p * (1 - self.p), self.n))

    def _count(self, variance, n):
        # smallest whole k with variance / (k n^2) <= sigma^2 (a tiny tolerance for rounding)
        return max(1, math.ceil(variance / (self.sigma ** 2 * n * n) - 1e-9))

    def acceptable(self):
        return self.expected >= 2

    def mistakes(self):
        found = [
            Mistake(float(math.ceil(1 / (2 * self.sigma) - 1e-9)) if self.kind != "known"
                    else float(math.ceil(math.sqrt(self.p * (1 - self.p)) / self.sigma - 1e-9)),
                    r"The square root was not undone: the error falls like $1/\sqrt k$, so "
                    r"halving it takes **four** times the samples, $k = p(1-p)/\sigma^2$.",
                    "no square"),
            Mistake(float(self._count(1.0, self.n)), r"The variance of a 0/1 sample is "
                    r"$p(1-p)$, at most $1/4$, not 1: the standard error is at most "
                    r"$1/(2\sqrt k)$.", "variance 1"),
        ]
        if self.kind == "known":
            found.append(Mistake(float(self._count(0.25, 1)), r"The worst case $p(1-p) = 1/4$ "
                                 r"was used, but here the visibility is known: its variance "
                                 r"$p(1-p)$ is smaller, and so is $k$.", "worst case used"))
        if self.kind == "blur":
            found.append(Mistake(float(self._count(0.25, 1)), r"The blur was left out: "
                                 rf"averaging the {self.n}×{self.n} tile combines "
                                 rf"{self.n * self.n} differently rotated kernels, so each "
                                 r"pixel needs $n^2$ times fewer samples.", "blur ignored"))
        exact = self.p * (1 - self.p) / (self.sigma ** 2 * self.n ** 2)
        if abs(exact - round(exact)) > 1e-6:
            found.append(Mistake(float(math.floor(exact)), r"Rounded down: with fewer samples "
                                 r"than the bound the error is above $\sigma$; take the next "
                                 r"whole number up.", "rounded down"))
        return found

    def statement(self):
        if self.kind == "worst":
            setting = (r"The visibility of the pixels is not known in advance, so plan for the "
                       r"worst case.")
        elif self.kind == "known":
            setting = rf"Consider pixels whose true visibility is $p = {_num(self.p)}$."
        else:
            setting = (rf"The result is blurred with a {self.n}×{self.n} box (the size of the "
                       r"noise tile of kernel rotations); count the blurred pixel's estimate "
                       r"as an average of all the samples of the tile, taken as independent, "
                       r"and plan for the worst case.")
        return (
            r"Each SSAO kernel sample of a pixel is a 0/1 variable (occluded or not), and the "
            r"pixel's visibility is the average of its $k$ samples. " + setting
            + rf" What is the smallest number $k$ of samples per pixel for which the standard "
            rf"error of the estimate is at most $\sigma = {_num(self.sigma)}$?" "\n\n"
            + _ONE_NUMBER + "\n\n" + data_note("kind", "sigma", "p", "n"))

    def hints(self):
        var = self.p * (1 - self.p)
        return [r"A 0/1 variable with mean $p$ has variance $p(1-p)$; the average of $m$ "
                r"independent ones has standard error $\sqrt{p(1-p)/m}$.",
                (r"Worst case: $p(1-p)$ is largest at $p = 1/2$, where it is $1/4$."
                 if self.kind != "known" else
                 rf"Here $p(1-p) = {_num(self.p)} \cdot {_num(1 - self.p)} = {_n4(var)}$."),
                (rf"The blurred value averages $m = {self.n * self.n} k$ samples. "
                 if self.kind == "blur" else r"Here $m = k$. ")
                + r"Solve $p(1-p)/m \le \sigma^2$ and round **up**."]

    def worked(self):
        var = self.p * (1 - self.p)
        m = self.n * self.n
        exact = var / (self.sigma ** 2 * m)
        times = "k" if m == 1 else f"({m}k)"
        dot = "" if m == 1 else f"{m} \\cdot "
        steps = [rf"Variance of one sample: $p(1-p) = {_n4(var)}$"
                 + (" (worst case $p = 1/2$)." if self.kind != "known" else "."),
                 rf"Standard error $\sqrt{{{_n4(var)}/{times}}} \le "
                 rf"{_num(self.sigma)}$ $\iff$ $k \ge {_n4(var)}/"
                 rf"({dot}{_num(self.sigma)}^2) = {_n4(exact)}$.",
                 rf"Smallest whole number: $k = {int(self.expected)}$."]
        return Worked(steps, self.expected)
