"""Chapter 10 (lesson section 5): sRGB, linear RGB, CIE XYZ, CIE L*a*b* and colour differences."""

import numpy as np

from .._validate import as_array, as_rgb, as_scalar, as_vector
from ._common import _unit_interval
from .maps import sample_colormap

__all__ = ["D65_WHITE", "delta_e", "greyscale", "is_monotonic_lightness", "lightness",
    "linear_to_srgb", "luminance", "perceptual_steps", "srgb_to_lab", "srgb_to_linear",
    "srgb_to_xyz", "xyz_to_lab"]


# ---------------------------------------------------------------------------------------------
# Colour science: sRGB -> linear RGB -> CIE XYZ -> CIE L*a*b*
# ---------------------------------------------------------------------------------------------

#: The sRGB (linear) -> CIE XYZ matrix for the D65 white point (IEC 61966-2-1, with the
#: 7-digit coefficients derived from the primaries' chromaticities).
_SRGB_TO_XYZ = np.array([[0.4124564, 0.3575761, 0.1804375],
                         [0.2126729, 0.7151522, 0.0721750],
                         [0.0193339, 0.1191920, 0.9503041]])

#: The reference white (X_n, Y_n, Z_n) of D65, about (0.95047, 1, 1.08883): the XYZ of sRGB
#: white (1, 1, 1), so that white has exactly L* = 100, a* = b* = 0.
D65_WHITE = _SRGB_TO_XYZ.sum(axis=1)


def srgb_to_linear(rgb):
    r"""Undo the sRGB gamma encoding: stored values -> linear light (IEC 61966-2-1).

    .. math:: c_{lin} = \begin{cases} c / 12.92 & c \le 0.04045 \\
              \left(\frac{c + 0.055}{1.055}\right)^{2.4} & \text{otherwise} \end{cases}

    Examples
    --------
    >>> srgb_to_linear([0.0, 0.5, 1.0]).round(4)
    array([0.   , 0.214, 1.   ])
    """
    c = as_array(rgb, "rgb")
    if ((c < -1e-9) | (c > 1 + 1e-9)).any():
        _unit_interval(c, "rgb", "sRGB components")
    c = np.clip(c, 0.0, 1.0)
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def linear_to_srgb(linear):
    r"""Apply the sRGB gamma encoding: linear light -> stored values (inverse of
    :func:`srgb_to_linear`).

    .. math:: c = \begin{cases} 12.92\, c_{lin} & c_{lin} \le 0.0031308 \\
              1.055\, c_{lin}^{1/2.4} - 0.055 & \text{otherwise} \end{cases}

    Examples
    --------
    >>> float(linear_to_srgb(0.214041).round(4))
    0.5
    """
    c = as_array(linear, "linear")
    if ((c < -1e-9) | (c > 1 + 1e-9)).any():
        _unit_interval(c, "linear", "linear light")
    c = np.clip(c, 0.0, 1.0)
    return np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)


def srgb_to_xyz(rgb):
    r"""sRGB colours -> CIE XYZ tristimulus values (D65, Y of white = 1).

    Linearize each channel (:func:`srgb_to_linear`), then
    :math:`(X, Y, Z)^T = M\,(r, g, b)^T_{lin}` with the sRGB matrix M.

    Parameters
    ----------
    rgb : array_like, shape (..., 3)
        sRGB components in [0, 1].

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> srgb_to_xyz([1, 1, 1])
    array([0.95047  , 1.0000001, 1.08883  ])
    """
    return srgb_to_linear(as_rgb(rgb, "rgb", grey=False)) @ _SRGB_TO_XYZ.T


def xyz_to_lab(xyz, white=D65_WHITE):
    r"""CIE XYZ -> CIE L*a*b* (CIE 1976) relative to a reference white.

    .. math::
        L^* = 116 f(Y/Y_n) - 16,\quad a^* = 500\,[f(X/X_n) - f(Y/Y_n)],\quad
        b^* = 200\,[f(Y/Y_n) - f(Z/Z_n)],

    with :math:`f(u) = u^{1/3}` for :math:`u > (6/29)^3` and the straight line
    :math:`f(u) = u / (3 (6/29)^2) + 4/29` below it (avoiding the infinite slope of the cube root
    at 0).

    Examples
    --------
    >>> xyz_to_lab(D65_WHITE)
    array([100.,   0.,   0.])
    """
    xyz = as_array(xyz, "xyz")
    if xyz.ndim == 0 or xyz.shape[-1] != 3:
        raise ValueError(f"xyz must have 3 components in the last axis, got shape {xyz.shape}")
    u = xyz / as_vector(white, "white", 3)
    delta = 6.0 / 29.0
    f = np.where(u > delta ** 3, np.cbrt(u), u / (3 * delta ** 2) + 4.0 / 29.0)
    return np.stack([116 * f[..., 1] - 16, 500 * (f[..., 0] - f[..., 1]),
                     200 * (f[..., 1] - f[..., 2])], axis=-1)


def srgb_to_lab(rgb):
    """sRGB colours in [0, 1] -> CIE L*a*b* (D65): :func:`srgb_to_xyz` then :func:`xyz_to_lab`.

    Examples
    --------
    >>> srgb_to_lab([[1, 1, 1], [0.5, 0.5, 0.5], [1, 0, 0]]).round(2)
    array([[100.  ,  -0.  ,   0.  ],
           [ 53.39,  -0.  ,   0.  ],
           [ 53.24,  80.09,  67.2 ]])
    """
    return xyz_to_lab(srgb_to_xyz(rgb), white=D65_WHITE)


def luminance(rgb):
    """Relative luminance Y of sRGB colours (0 black, 1 white): the middle row of the XYZ matrix.

    .. math:: Y = 0.2126\\,r_{lin} + 0.7152\\,g_{lin} + 0.0722\\,b_{lin}

    Green contributes most and blue least, which is why pure blue looks dark and yellow light.

    Examples
    --------
    >>> luminance([[1, 1, 0], [0, 0, 1]]).round(4)
    array([0.9278, 0.0722])
    """
    return srgb_to_linear(as_rgb(rgb, "rgb", grey=False)) @ _SRGB_TO_XYZ[1]


def greyscale(rgb):
    """The sRGB grey level with the same luminance: how a colour prints in black and white.

    ``greyscale(c)`` is the value g such that the grey (g, g, g) has the luminance of c
    (:func:`luminance`, re-encoded with :func:`linear_to_srgb`).

    Examples
    --------
    >>> greyscale([[1, 0, 0], [0.5, 0.5, 0.5]]).round(4)
    array([0.4985, 0.5   ])
    """
    return linear_to_srgb(np.clip(luminance(rgb), 0.0, 1.0))


def delta_e(lab1, lab2):
    r"""The CIE 1976 colour difference :math:`\Delta E^*_{ab}`: Euclidean distance in L*a*b*.

    A difference of about 2.3 is just noticeable.

    Examples
    --------
    >>> float(delta_e([50, 0, 0], [53, 4, 0]))
    5.0
    """
    a, b = as_array(lab1, "lab1"), as_array(lab2, "lab2")
    if a.shape[-1:] != (3,) or b.shape[-1:] != (3,):
        raise ValueError(f"lab1 and lab2 must have 3 components (L*, a*, b*) in the last axis, "
                         f"got shapes {a.shape} and {b.shape}")
    return np.sqrt(((a - b) ** 2).sum(axis=-1))


def lightness(cmap, n=256):
    """Perceived lightness L* (0 black .. 100 white) at n points along a colour map.

    Examples
    --------
    >>> lightness("grey", 3).round(2)
    array([  0.  ,  53.39, 100.  ])
    """
    return srgb_to_lab(sample_colormap(cmap, n)[:, :3])[:, 0]


def is_monotonic_lightness(cmap, n=256, tolerance=0.0):
    """Whether L* only rises, or only falls, along a colour map (within `tolerance`).

    Monotonic lightness is what makes a map readable as "more" and "less". Diverging maps
    (bwr, coolwarm) rise to white and fall again on purpose; rainbow, jet and turbo do it
    several times, which is the problem.

    Parameters
    ----------
    cmap : str or array_like
        See :func:`colormap`.
    n : int
        Number of samples along the map.
    tolerance : float
        How far L* may fall back below the highest value reached so far (or rise above the
        lowest, for a falling map) and still count as monotonic; 0: not at all.

    Examples
    --------
    >>> is_monotonic_lightness("viridis"), is_monotonic_lightness("rainbow")
    (True, False)
    """
    L = lightness(cmap, n)
    tol = as_scalar(tolerance, "tolerance")
    rises = (L >= np.maximum.accumulate(L) - tol).all()
    falls = (L <= np.minimum.accumulate(L) + tol).all()
    return bool(rises or falls)


def perceptual_steps(cmap, n=64):
    """Colour differences Delta E*ab between neighbouring samples of a map, shape (n - 1,).

    A perceptually uniform map has (nearly) equal steps: equal data differences look equally
    different everywhere along it. Compare ``steps.std() / steps.mean()`` between maps.

    Examples
    --------
    >>> steps = perceptual_steps("grey", 5)
    >>> steps.round(1)
    array([27. , 26.4, 24. , 22.6])
    """
    lab = srgb_to_lab(sample_colormap(cmap, n)[:, :3])
    return delta_e(lab[1:], lab[:-1])
