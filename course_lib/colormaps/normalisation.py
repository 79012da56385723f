"""Chapter 10 (lesson section 2): normalising data values onto [0, 1]."""

import numpy as np

from ._common import _data_allowing_nan, _data_range, _range

__all__ = ["normalize"]


# ---------------------------------------------------------------------------------------------
# Normalisation
# ---------------------------------------------------------------------------------------------

def normalize(data, in_range=None, out_range=(0.0, 1.0), clip=True):
    r"""Map data linearly from ``in_range`` = [a, b] onto ``out_range`` = [c, d].

    .. math:: n(v) = \frac{v - a}{b - a}\,(d - c) + c

    This is the normalisation formula of chapter 10: shift the minimum to 0, divide by the
    spread to reach [0, 1], then stretch and shift onto the target interval.

    Parameters
    ----------
    data : array_like
        The values. NaN marks missing data and is **propagated**: it stays NaN in the result and
        is ignored when the range is taken from the data.
    in_range : (float, float), optional
        The data interval [a, b], a <= b. Default: the data's own minimum and maximum (NaNs
        ignored).
    out_range : (float, float)
        The target interval [c, d]; c > d is allowed and flips the scale.
    clip : bool
        If True (the default), values outside [a, b] are first clipped to it, so the result
        lies in [c, d]. If False, the same straight line extends beyond the interval.

    Returns
    -------
    ndarray or float
        The normalised values, same shape as `data` (a float for a single number).
        **Constant data** (a = b) has no spread: every value maps to the middle (c + d) / 2.

    Raises
    ------
    ValueError
        For infinite values, all-NaN or empty data without an explicit `in_range`, or
        ``in_range`` with low > high.

    Examples
    --------
    >>> normalize([10, 15, 20])
    array([0. , 0.5, 1. ])
    >>> normalize([0, 50, 150], in_range=(0, 100), out_range=(-1, 1))
    array([-1.,  0.,  1.])
    >>> normalize([0, 50, 150], in_range=(0, 100), out_range=(-1, 1), clip=False)
    array([-1.,  0.,  2.])
    >>> normalize([3, 3, np.nan])
    array([0.5, 0.5, nan])
    """
    values = _data_allowing_nan(data, "data")
    a, b = _data_range(values, in_range)
    c, d = _range(out_range, "out_range", ordered=False)
    if clip:
        values = np.clip(values, a, b)            # NaN passes through np.clip unchanged
    if b == a:
        out = np.where(np.isnan(values), np.nan, 0.5 * (c + d))
    else:
        out = (values - a) / (b - a) * (d - c) + c
    return out if out.ndim else float(out)
