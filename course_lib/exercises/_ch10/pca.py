r"""Chapter 10 exercises: principal component analysis of a small 2D table by hand
(textbook 10.7): the covariance matrix and its eigenvalues; the first component and a record's
coordinate on it.

Conventions (those of :mod:`course_lib.dataviz.projection`): the covariance divides by
``n - 1``; an eigenvector's component of largest magnitude is positive (the first one on a
tie).

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import functools
import math

import numpy as np

from ...dataviz import projection as pj
from ..core import DECIMALS, Mistake, PartsAnswer, Worked, data_note
from . import _Chapter10, _num, _paren

__all__ = [
    "CovarianceEigen",
    "ProjectRecord",
]


def _n4(x):
    return _num(x, 4)


# ---------------------------------------------------------------------------------------------
# PCA by hand
# ---------------------------------------------------------------------------------------------

@functools.lru_cache(maxsize=1)
def _nice_tables():
    """Centred 5-record tables of small whole numbers whose sample covariance (over n - 1 = 4)
    has whole entries, a non-zero off-diagonal entry and whole, distinct, positive
    eigenvalues (the discriminant a perfect square)."""
    rng = np.random.default_rng(2024)
    z = rng.integers(-3, 4, size=(400_000, 4, 2))
    z = np.concatenate([z, -z.sum(axis=1, keepdims=True)], axis=1)
    z = z[(np.abs(z[:, 4]) <= 3).all(axis=1)]
    s = np.einsum("nki,nkj->nij", z, z)
    keep = (s % 4 == 0).all(axis=(1, 2)) & (s[:, 0, 1] != 0)
    z, c = z[keep], s[keep] // 4
    a, b, d = c[:, 0, 0], c[:, 0, 1], c[:, 1, 1]
    disc = (a - d) ** 2 + 4 * b * b
    root = np.round(np.sqrt(disc)).astype(np.int64)
    keep = (root * root == disc) & ((a + d + root) % 2 == 0) & (a * d - b * b > 0)
    z = z[keep]
    # distinct tables only, in a fixed order
    flat = np.unique(z.reshape(len(z), -1), axis=0)
    return flat.reshape(-1, 5, 2)


class _PCATable(PartsAnswer, _Chapter10):
    """What the two PCA exercises share: a small table with nice numbers."""

    form_hint = ""

    def _draw_table(self, rng):
        tables = _nice_tables()
        z = tables[int(rng.integers(len(tables)))]
        mean = rng.integers(4, 10, size=2)
        self.data = (z + mean).astype(float)
        self.n = len(self.data)

    def _stats(self):
        mean = self.data.mean(axis=0)
        z = self.data - mean
        c = z.T @ z / (self.n - 1)
        values, vectors = pj.principal_axes(c)
        return mean, z, c, values, vectors

    def _table_words(self):
        rows = "\n".join(f"| {i + 1} | {_num(x)} | {_num(y)} |"
                         for i, (x, y) in enumerate(self.data))
        return "| record | x | y |\n|---|---|---|\n" + rows


class CovarianceEigen(_PCATable):
    r"""The sample covariance matrix of a small 2D table and its eigenvalues.

    :math:`C = \frac{1}{n-1}\sum_i (x_i - \bar x)(x_i - \bar x)^T`, and the eigenvalues of
    :math:`\begin{bmatrix} a & b \\ b & c\end{bmatrix}` are
    :math:`\frac{a + c}{2} \pm \sqrt{\left(\frac{a - c}{2}\right)^2 + b^2}`.

    Attributes: ``data`` (5 records x 2).

    Examples
    --------
    >>> ex = CovarianceEigen(seed=0)
    >>> c = np.cov(ex.data.T)
    >>> ex.check([c[0, 0], c[0, 1], c[1, 1], *np.linalg.eigvalsh(c)[::-1]]).status
    'correct'
    >>> c = np.cov(ex.data.T, ddof=0)
    >>> ex.check([c[0, 0], c[0, 1], c[1, 1], *np.linalg.eigvalsh(c)[::-1]]).diagnosis
    'divided by n'
    """

    title = "PCA by hand: the covariance and its eigenvalues"
    what = "your five numbers"
    form_hint = "`[c_xx, c_xy, c_yy, lambda_1, lambda_2]`."
    advice = (r"Subtract the means, sum the products $(x_i - \bar x)^2$, $(x_i - \bar x)(y_i - "
              r"\bar y)$, $(y_i - \bar y)^2$, divide by $n - 1 = 4$; then solve "
              r"$\lambda^2 - (a + c)\lambda + (ac - b^2) = 0$.")

    def draw(self, rng):
        self._draw_table(rng)
        _, _, c, values, _ = self._stats()
        self.expected = np.array([c[0, 0], c[0, 1], c[1, 1], values[0], values[1]])

    def parts(self):
        n = self.n
        _, z, c, values, _ = self._stats()
        by_n = c * (n - 1) / n
        raw = self.data.T @ self.data / (n - 1)
        raw_values = np.linalg.eigvalsh(raw)[::-1]
        not_centred = (r"The means were not subtracted: a covariance measures the spread "
                       r"**about the mean**, $\frac{1}{n-1}\sum (x_i - \bar x)(y_i - \bar y)$; "
                       r"without centring the numbers grow with the distance of the data from "
                       r"the origin.")
        by_n_text = (r"You divided by $n = 5$. The sample covariance of this course divides by "
                     r"$n - 1 = 4$ (as `numpy.cov` does): the mean was estimated from the same "
                     r"records, which uses up one degree of freedom.")
        entry = [("c_xx", 0, 0), ("c_xy", 0, 1), ("c_yy", 1, 1)]
        out = []
        for label, i, j in entry:
            out.append((label, c[i, j], [Mistake(by_n[i, j], by_n_text, "divided by n"),
                                         Mistake(raw[i, j], not_centred, "not centred")]))
        swapped = (r"The eigenvalues are listed largest first: $\lambda_1 \ge \lambda_2$ "
                   r"($\lambda_1$ is the variance along the first principal axis).")
        out.append(("lambda_1", values[0], [
            Mistake(values[0] * (n - 1) / n, by_n_text, "divided by n"),
            Mistake(raw_values[0], not_centred, "not centred"),
            Mistake(values[1], swapped, "eigenvalues swapped")]))
        out.append(("lambda_2", values[1], [
            Mistake(values[1] * (n - 1) / n, by_n_text, "divided by n"),
            Mistake(raw_values[1], not_centred, "not centred"),
            Mistake(values[0], swapped, "eigenvalues swapped")]))
        return out

    def hints(self):
        mean = self.data.mean(axis=0)
        return [
            r"First the means $\bar x$, $\bar y$; then the centred values $x_i - \bar x$, "
            r"$y_i - \bar y$ (whole numbers here).",
            rf"$\bar x = {_num(mean[0])}$, $\bar y = {_num(mean[1])}$. Sum the squares and the "
            r"products of the centred values and divide by $n - 1 = 4$.",
            r"For $C = \begin{bmatrix} a & b \\ b & c \end{bmatrix}$ the eigenvalues solve "
            r"$\lambda^2 - (a + c)\lambda + (ac - b^2) = 0$: "
            r"$\lambda = \frac{a + c}{2} \pm \sqrt{\left(\frac{a - c}{2}\right)^2 + b^2}$.",
        ]

    def worked(self):
        mean = self.data.mean(axis=0)
        z = self.data - mean
        sxx, sxy, syy = float(z[:, 0] @ z[:, 0]), float(z[:, 0] @ z[:, 1]), float(z[:, 1] @ z[:, 1])
        a, b, c = sxx / 4, sxy / 4, syy / 4
        half = (a + c) / 2
        root = math.sqrt(((a - c) / 2) ** 2 + b * b)
        centred = ", ".join(f"({_num(u)}, {_num(v)})" for u, v in z)
        return Worked([
            rf"Means: $\bar x = {_num(mean[0])}$, $\bar y = {_num(mean[1])}$; centred records "
            rf"{centred}.",
            rf"Sums: $\sum \tilde x^2 = {_num(sxx)}$, $\sum \tilde x \tilde y = {_num(sxy)}$, "
            rf"$\sum \tilde y^2 = {_num(syy)}$; divided by $n - 1 = 4$: $c_{{xx}} = {_num(a)}$, "
            rf"$c_{{xy}} = {_num(b)}$, $c_{{yy}} = {_num(c)}$.",
            rf"$\lambda = \frac{{{_num(a)} + {_num(c)}}}{{2}} \pm \sqrt{{\left("
            rf"\frac{{{_num(a)} - {_num(c)}}}{{2}}\right)^2 + {_paren(b)}^2}} = {_num(half)} "
            rf"\pm {_n4(root)}$: $\lambda_1 = {_n4(half + root)}$, $\lambda_2 = "
            rf"{_n4(half - root)}$.",
        ], np.array([a, b, c, half + root, half - root]))

    def statement(self):
        return (
            r"Principal component analysis of the small table below starts with its covariance "
            r"matrix. Use the **sample** covariance, which divides by $n - 1$: "
            r"$C = \frac{1}{n - 1}\sum_i (p_i - \bar p)(p_i - \bar p)^T$ with $p_i = (x_i, "
            r"y_i)$." "\n\n" + self._table_words() + "\n\n"
            r"Compute the entries $c_{xx}$, $c_{xy}$, $c_{yy}$ of $C$ and its eigenvalues "
            r"$\lambda_1 \ge \lambda_2$ (the variances along the principal axes)." "\n\n"
            r"**Answer:** the list `[c_xx, c_xy, c_yy, lambda_1, lambda_2]`. " + DECIMALS
            + "\n\n" + data_note("data"))


class ProjectRecord(_PCATable):
    r"""The first principal component of a small 2D table and a record's coordinate on it.

    For :math:`C = \begin{bmatrix} a & b \\ b & c\end{bmatrix}` the eigenvector of
    :math:`\lambda_1` is :math:`(b, \lambda_1 - a)` normalised (turned so that its component of
    largest magnitude is positive); a record's coordinate is :math:`w_1 \cdot (p - \bar p)`.

    Attributes: ``data`` (5 records x 2), ``cov`` (its sample covariance), ``record`` (the
    record asked for, counted from 1).

    Examples
    --------
    >>> ex = ProjectRecord(seed=0)
    >>> r = pj.pca(ex.data, k=1)
    >>> ex.check([*r.components[:, 0], r.scores[ex.record - 1, 0]]).status
    'correct'
    """

    title = "PCA by hand: the first component and a projection"
    what = "your three numbers"
    form_hint = "`[w_x, w_y, t]`."
    advice = (r"Take $\lambda_1$, solve $(C - \lambda_1 I)w = 0$ (e.g. $w \propto (b, \lambda_1 "
              r"- a)$), divide by its length, fix the sign, and project the centred record: "
              r"$t = w \cdot (p - \bar p)$.")

    def draw(self, rng):
        self._draw_table(rng)
        mean, z, c, values, vectors = self._stats()
        self.cov = c
        self.record = int(rng.integers(1, self.n + 1))
        w = vectors[:, 0]
        self.expected = np.array([w[0], w[1], float(z[self.record - 1] @ w)])

    def acceptable(self):
        mean, z, _, _, vectors = self._stats()
        return abs(float(z[self.record - 1] @ vectors[:, 0])) > 0.3 \
            and abs(float(self.data[self.record - 1] @ vectors[:, 0])
                    - float(z[self.record - 1] @ vectors[:, 0])) > 0.3

    def _unnormalised(self):
        mean, z, c, values, _ = self._stats()
        v = np.array([c[0, 1], values[0] - c[0, 0]])
        magnitude = np.abs(v)
        lead = int(np.argmax(magnitude >= magnitude.max() - 1e-9))
        return v if v[lead] > 0 else -v

    def parts(self):
        mean, z, c, values, vectors = self._stats()
        w1, w2 = vectors[:, 0], vectors[:, 1]
        p = z[self.record - 1]
        u = self._unnormalised()
        second = (r"That is the **second** principal axis, the eigenvector of the smaller "
                  r"eigenvalue $\lambda_2$. The first component belongs to $\lambda_1$, the "
                  r"direction of the largest variance.")
        unit = (r"The eigenvector was not normalised: a principal axis is a **unit** vector "
                r"(divide $(b, \lambda_1 - a)$ by its length), otherwise the coordinates are "
                r"stretched.")
        sign = (r"The sign: an eigenvector may be flipped, so the question fixes it: the "
                r"component of largest magnitude is positive (the first one on a tie). Flip "
                r"your vector, and the coordinate with it.")
        centre = (r"The record was not centred: PCA projects $p - \bar p$, the record's offset "
                  r"from the mean, $t = w_1 \cdot (p - \bar p)$.")
        return [
            ("w_x", w1[0], [Mistake(w2[0], second, "second eigenvector"),
                            Mistake(u[0], unit, "not normalised"),
                            Mistake(-w1[0], sign, "sign")]),
            ("w_y", w1[1], [Mistake(w2[1], second, "second eigenvector"),
                            Mistake(u[1], unit, "not normalised"),
                            Mistake(-w1[1], sign, "sign")]),
            ("t", float(p @ w1), [Mistake(float(p @ w2), second, "second eigenvector"),
                                  Mistake(float(p @ u), unit, "not normalised"),
                                  Mistake(-float(p @ w1), sign, "sign"),
                                  Mistake(float(self.data[self.record - 1] @ w1), centre,
                                          "not centred")]),
        ]

    def hints(self):
        _, _, c, values, _ = self._stats()
        return [
            r"The first component is the unit eigenvector of the larger eigenvalue "
            r"$\lambda_1$ of $C$.",
            rf"Here $\lambda_1 = {_n4(values[0])}$. From the first row of "
            r"$(C - \lambda_1 I)w = 0$: $(a - \lambda_1)w_x + b\,w_y = 0$, so "
            r"$w \propto (b, \lambda_1 - a)$ = "
            rf"$({_num(c[0, 1])}, {_n4(values[0] - c[0, 0])})$.",
            r"Normalise it, make its largest component positive, and project the record "
            r"after subtracting the means.",
        ]

    def worked(self):
        mean, z, c, values, _ = self._stats()
        a, b, cc = c[0, 0], c[0, 1], c[1, 1]
        lam = (a + cc) / 2 + math.sqrt(((a - cc) / 2) ** 2 + b * b)
        v = np.array([b, lam - a])
        w = v / math.hypot(*v)
        magnitude = np.abs(w)
        lead = int(np.argmax(magnitude >= magnitude.max() - 1e-9))
        flipped = w[lead] < 0
        if flipped:
            w = -w
        p = self.data[self.record - 1] - mean
        t = float(p @ w)
        return Worked([
            rf"$\lambda_1 = \frac{{a + c}}{{2}} + \sqrt{{\left(\frac{{a - c}}{{2}}\right)^2 + "
            rf"b^2}} = {_n4(lam)}$ with $a = {_num(a)}$, $b = {_num(b)}$, $c = {_num(cc)}$.",
            rf"$w \propto (b, \lambda_1 - a) = ({_num(b)}, {_n4(lam - a)})$, length "
            rf"${_n4(math.hypot(*v))}$: $w_1 = ({_n4(w[0])}, {_n4(w[1])})$"
            + (" (flipped so that its largest component is positive)." if flipped else "."),
            rf"Record {self.record} centred: $p - \bar p = ({_num(p[0])}, {_num(p[1])})$; "
            rf"$t = {_n4(w[0])} \cdot {_paren(p[0])} + {_n4(w[1])} \cdot {_paren(p[1])} = "
            rf"{_n4(t)}$.",
        ], np.array([w[0], w[1], t]))

    def statement(self):
        c = self.cov
        return (
            r"The small table below has the sample covariance matrix (over $n - 1$) "
            rf"$C = \begin{{bmatrix}} {_num(c[0, 0])} & {_num(c[0, 1])} \\ {_num(c[1, 0])} & "
            rf"{_num(c[1, 1])} \end{{bmatrix}}$." "\n\n" + self._table_words() + "\n\n"
            r"Give the first principal component $w_1$ (the unit eigenvector of the larger "
            r"eigenvalue, turned so that its component of largest magnitude is positive) and "
            rf"the coordinate $t$ of record {self.record} on it (the record projected onto the "
            r"first principal axis, after centring)." "\n\n"
            r"**Answer:** the list `[w_x, w_y, t]`. " + DECIMALS + "\n\n"
            + data_note("data", "cov", "record"))
