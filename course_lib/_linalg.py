"""Small vector helpers shared by the algorithm modules (numpy only)."""
import numpy as np


def dot(a, b):
    """Dot products over the last axis, broadcasting the leading ones: ``sum(a * b, axis=-1)``.

    Examples
    --------
    >>> dot(np.array([[1.0, 2, 3], [0, 1, 0]]), np.array([1.0, 1, 1]))
    array([6., 1.])
    """
    return np.einsum("...i,...i->...", a, b)
