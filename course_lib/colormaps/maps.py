"""Chapter 10 (lesson section 4): colour maps: look-up, reversal, building from control colours."""

import numpy as np

from .._validate import as_array, as_whole
from ._common import _unit_interval
from ._data import COLORMAP_NAMES, _COLORMAPS

__all__ = ["colormap", "sample_colormap"]


# ---------------------------------------------------------------------------------------------
# Colour maps
# ---------------------------------------------------------------------------------------------

def colormap(cmap):
    """The control colours of a colour map, shape (n, 3) (or (n, 4) with alpha).

    Parameters
    ----------
    cmap : str or array_like
        A name from :data:`COLORMAP_NAMES` (``"_r"`` appended reverses it), or an (n, 3) or
        (n, 4) array of n >= 2 colours in [0, 1], placed evenly at t = k / (n - 1).

    Returns
    -------
    ndarray
        A copy of the control colours.

    Raises
    ------
    ValueError
        For an unknown name or a malformed array.

    Examples
    --------
    >>> colormap("rainbow")
    array([[0., 0., 1.],
           [0., 1., 1.],
           [0., 1., 0.],
           [1., 1., 0.],
           [1., 0., 0.]])
    >>> colormap("grey_r")[0]
    array([1., 1., 1.])
    """
    if isinstance(cmap, str):
        base, reverse = (cmap[:-2], True) if cmap.endswith("_r") else (cmap, False)
        base = {"gray": "grey", "heat": "hot"}.get(base, base)
        if base not in _COLORMAPS:
            raise ValueError(f"cmap must be one of {', '.join(COLORMAP_NAMES)} (optionally with "
                             f"'_r'), got {cmap!r}")
        colors = _COLORMAPS[base]
        return (colors[::-1] if reverse else colors).copy()
    colors = as_array(cmap, "cmap")
    if colors.ndim != 2 or colors.shape[1] not in (3, 4) or len(colors) < 2:
        raise ValueError(f"cmap must be a name or an (n, 3) / (n, 4) array of n >= 2 colours, "
                         f"got shape {colors.shape}")
    return _unit_interval(colors, "cmap", "colour components").copy()


def _lookup(colors, t):
    """Linear interpolation of evenly spaced control colours at t in [0, 1] (any shape)."""
    n = len(colors)
    pos = np.clip(t, 0.0, 1.0) * (n - 1)
    i = np.minimum(pos.astype(np.intp), n - 2)
    f = (pos - i)[..., None]
    return (1 - f) * colors[i] + f * colors[i + 1]


def sample_colormap(cmap, n=256):
    """n colours evenly spaced along a colour map (t = 0 .. 1), shape (n, 3).

    Parameters
    ----------
    cmap : str or array_like
        See :func:`colormap`.
    n : int
        Number of samples, >= 2.

    Examples
    --------
    >>> sample_colormap("bwr", 5)
    array([[0. , 0. , 1. ],
           [0.5, 0.5, 1. ],
           [1. , 1. , 1. ],
           [1. , 0.5, 0.5],
           [1. , 0. , 0. ]])
    """
    return _lookup(colormap(cmap), np.linspace(0.0, 1.0, as_whole(n, "n", 2)))
