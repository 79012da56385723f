r"""Projection of multidimensional data by principal component analysis (textbook 10.7).

Given a table of ``n`` records with ``d`` attributes, PCA looks for the orthonormal directions
along which the records spread most:

1. **Centre** the records, :math:`\tilde X = X - \bar x` (optionally also divide each column by
   its standard deviation: *standardise*, so that attributes in large units do not dominate).
2. The **covariance matrix** :math:`C = \tilde X^T \tilde X / (n - 1)` (``ddof=1``, the
   sample covariance, as ``numpy.cov``; ``ddof=0`` divides by ``n``).
3. The variance of the records along a unit vector :math:`w` is :math:`w^T C w`; maximising it
   under :math:`w^T w = 1` (a Lagrange multiplier) gives :math:`C w = \lambda w`: the
   directions are the **eigenvectors** of :math:`C`, the variance along each its eigenvalue.
4. Sort the eigenvalues :math:`\lambda_1 \ge \lambda_2 \ge \dots`; the first ``k`` eigenvectors
   (the columns of :math:`W_k`) span the best ``k``-dimensional view, and a record's
   coordinates in it are :math:`y = W_k^T (x - \bar x)`.
5. The **explained variance ratio** of component ``j`` is :math:`\lambda_j / \sum_i \lambda_i`.

An eigenvector is defined up to its sign: here each is turned so that its component of largest
magnitude is positive (the first such component on a tie), which makes the result the same on
every machine and comparable with a hand calculation.
"""
from typing import NamedTuple

import numpy as np

from .._validate import as_whole
from .multidim import _records

__all__ = ["PCAResult", "centre_records", "covariance_matrix", "pca", "pca_project",
           "principal_axes"]


class PCAResult(NamedTuple):
    """What :func:`pca` found.

    Attributes
    ----------
    mean : ndarray, shape (d,)
        The column means that were subtracted.
    scale : ndarray, shape (d,)
        The column standard deviations divided by (ones when not standardised).
    eigenvalues : ndarray, shape (d,)
        The variances along the principal axes, largest first.
    components : ndarray, shape (d, k)
        The first ``k`` principal axes as unit **columns** (``W_k``).
    explained_variance_ratio : ndarray, shape (d,)
        ``eigenvalues / eigenvalues.sum()``.
    scores : ndarray, shape (n, k)
        The records' coordinates in the principal axes, ``(X - mean) / scale @ W_k``.

    Examples
    --------
    >>> r = pca([[0, 0], [2, 2], [4, 4]], k=1)
    >>> r.components.ravel().round(4).tolist(), r.scores.ravel().round(4).tolist()
    ([0.7071, 0.7071], [-2.8284, 0.0, 2.8284])
    """

    mean: np.ndarray
    scale: np.ndarray
    eigenvalues: np.ndarray
    components: np.ndarray
    explained_variance_ratio: np.ndarray
    scores: np.ndarray


def _ddof(ddof, n):
    ddof = as_whole(ddof, "ddof", 0)
    if n - ddof <= 0:
        raise ValueError(f"ddof = {ddof} needs more than {ddof} records, got {n}")
    return ddof


def centre_records(data, standardise=False, ddof=1):
    r"""Subtract the column means (and with `standardise` divide by the standard deviations).

    Parameters
    ----------
    data : array_like, shape (n, d)
    standardise : bool
        Also divide each attribute by its standard deviation (``ddof`` as given).
    ddof : int
        1: divide the sum of squares by ``n - 1`` (sample), 0: by ``n``.

    Returns
    -------
    (centred, mean, scale) : ndarray (n, d), ndarray (d,), ndarray (d,)

    Raises
    ------
    ValueError
        For a constant attribute when standardising (it has no spread to divide by).

    Examples
    --------
    >>> centred, mean, scale = centre_records([[1, 10], [3, 30]])
    >>> centred.tolist(), mean.tolist(), scale.tolist()
    ([[-1.0, -10.0], [1.0, 10.0]], [2.0, 20.0], [1.0, 1.0])
    >>> centre_records([[1, 10], [3, 30]], standardise=True)[0].round(4).tolist()
    [[-0.7071, -0.7071], [0.7071, 0.7071]]
    """
    table = _records(data)
    mean = table.mean(axis=0)
    centred = table - mean
    scale = np.ones(table.shape[1])
    if standardise:
        ddof = _ddof(ddof, len(table))
        scale = np.sqrt((centred ** 2).sum(axis=0) / (len(table) - ddof))
        flat = np.flatnonzero(scale <= 1e-12 * np.maximum(1.0, np.abs(mean)))
        if flat.size:
            raise ValueError(f"attribute {int(flat[0])} is constant: it has no spread to "
                             "standardise by (drop it first)")
        centred = centred / scale
    return centred, mean, scale


def covariance_matrix(data, ddof=1):
    r"""The covariance matrix of the attributes, :math:`C = \tilde X^T \tilde X / (n -
    \mathrm{ddof})` with :math:`\tilde X` the centred records.

    Parameters
    ----------
    data : array_like, shape (n, d)
    ddof : int
        1 (default): the sample covariance, divided by ``n - 1`` as ``numpy.cov``; 0: by ``n``.

    Returns
    -------
    ndarray, shape (d, d)

    Examples
    --------
    >>> covariance_matrix([[1, 2], [3, 6], [5, 10]]).tolist()
    [[4.0, 8.0], [8.0, 16.0]]
    >>> covariance_matrix([[1, 2], [3, 6], [5, 10]], ddof=0).round(4).tolist()
    [[2.6667, 5.3333], [5.3333, 10.6667]]
    """
    table = _records(data)
    ddof = _ddof(ddof, len(table))
    centred = table - table.mean(axis=0)
    c = centred.T @ centred / (len(table) - ddof)
    return 0.5 * (c + c.T)


def principal_axes(cov):
    """Eigenvalues (largest first) and unit eigenvectors (columns) of a covariance matrix.

    Each eigenvector's component of largest magnitude is made positive (the first one within
    rounding on a tie), so the result is deterministic; eigenvalues that rounding made slightly
    negative are set to 0.

    Parameters
    ----------
    cov : array_like, shape (d, d)
        Symmetric, positive semi-definite.

    Returns
    -------
    (eigenvalues, vectors) : ndarray (d,), ndarray (d, d)
        ``cov @ vectors[:, j] == eigenvalues[j] * vectors[:, j]``.

    Examples
    --------
    >>> values, vectors = principal_axes([[2.0, 1.0], [1.0, 2.0]])
    >>> values.tolist(), vectors.round(4).tolist()
    ([3.0, 1.0], [[0.7071, 0.7071], [0.7071, -0.7071]])
    """
    c = np.asarray(cov, dtype=float)
    if c.ndim != 2 or c.shape[0] != c.shape[1] or c.shape[0] < 1 or not np.isfinite(c).all():
        raise ValueError(f"cov must be a finite square matrix, got shape {c.shape}")
    size = max(1.0, float(np.abs(c).max()))
    if not np.allclose(c, c.T, atol=1e-9 * size):
        raise ValueError("cov must be symmetric (a covariance matrix is)")
    values, vectors = np.linalg.eigh(0.5 * (c + c.T))
    if values.min() < -1e-9 * size:
        raise ValueError(f"cov must be positive semi-definite (a covariance matrix is); it has "
                         f"the eigenvalue {values.min():g}")
    order = np.argsort(-values, kind="stable")
    values = np.clip(values[order], 0.0, None)
    vectors = vectors[:, order]
    magnitude = np.abs(vectors)
    lead = np.argmax(magnitude >= magnitude.max(axis=0) - 1e-9, axis=0)
    signs = np.sign(vectors[lead, np.arange(len(values))])
    return values, vectors * np.where(signs == 0, 1.0, signs)


def pca(data, k=None, standardise=False, ddof=1):
    r"""Principal component analysis: centre, covariance, eigen-decomposition, projection.

    Parameters
    ----------
    data : array_like, shape (n, d)
    k : int, optional
        How many components to keep (1 to d); default all.
    standardise : bool
        Divide each attribute by its standard deviation first (PCA of the correlation matrix).
    ddof : int
        1 (default): covariance over ``n - 1``; 0: over ``n``. The axes and the explained
        ratios do not depend on it, the eigenvalues do.

    Returns
    -------
    PCAResult

    Examples
    --------
    >>> r = pca([[1, 1], [2, 3], [3, 2], [4, 4], [5, 5]], k=1)
    >>> r.eigenvalues.round(4).tolist(), r.explained_variance_ratio.round(4).tolist()
    ([4.75, 0.25], [0.95, 0.05])
    >>> r.scores.ravel().round(4).tolist()
    [-2.8284, -0.7071, -0.7071, 1.4142, 2.8284]
    """
    centred, mean, scale = centre_records(data, standardise, ddof)
    n, d = centred.shape
    k = d if k is None else as_whole(k, "k", 1)
    if k > d:
        raise ValueError(f"k must be at most the number of attributes, {d}; got {k}")
    values, vectors = principal_axes(covariance_matrix(centred, ddof))
    total = values.sum()
    ratio = values / total if total > 0 else np.full(d, 1.0 / d)
    w = vectors[:, :k]
    return PCAResult(mean, scale, values, w, ratio, centred @ w)


def pca_project(data, result):
    """The coordinates of (new) records in the principal axes of a :func:`pca` result,
    ``((x - mean) / scale) @ W_k``.

    Examples
    --------
    >>> r = pca([[0, 0], [2, 2], [4, 4]], k=1)
    >>> pca_project([[3, 3], [1, 3]], r).ravel().round(4).tolist()
    [1.4142, 0.0]
    """
    table = _records(data)
    if table.shape[1] != len(result.mean):
        raise ValueError(f"data must have the {len(result.mean)} attributes of the PCA, got "
                         f"{table.shape[1]}")
    return ((table - result.mean) / result.scale) @ result.components
