"""Chapter 14 (lesson section 5): procedural textures."""

import numpy as np

from .._validate import as_choice, as_points, as_positive, as_rng, as_scalar, as_vector, as_whole
from ._common import _dot

__all__ = ["checkerboard", "marble", "perlin_noise", "stripes", "turbulence", "value_noise",
    "wood"]


# ---------------------------------------------------------------------------------------------
# Procedural textures
# ---------------------------------------------------------------------------------------------

def _coords(points):
    p = as_points(points, "points", dims=(2, 3))
    return p


def checkerboard(points, squares=8):
    r"""A checkerboard: 0 or 1 by the parity of the square the point falls in.

    .. math:: T(P) = \left(\sum_k \lfloor s\, p_k \rfloor\right) \bmod 2

    In 2D (points (u, v)) an :math:`s \times s` board covers the unit square (it tiles
    seamlessly with ``wrap="repeat"`` when :math:`s` is even); in 3D it is a *solid* texture,
    a 3D grid of cubes that any surface can be cut out of, with no mapping and no seams.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    squares : float
        Squares per unit length, :math:`s > 0`.

    Returns
    -------
    ndarray, shape (...)
        0.0 or 1.0.

    Examples
    --------
    >>> from course_lib.texturing import uv_grid
    >>> checkerboard(uv_grid(4, 2), squares=2)
    array([[0., 0., 1., 1.],
           [1., 1., 0., 0.]])
    """
    p = _coords(points)
    s = as_positive(squares, "squares")
    return np.mod(np.floor(s * p).sum(axis=-1), 2.0)


def stripes(points, count=8, width=0.5, direction=None):
    r"""Parallel stripes: 1 on a fraction `width` of each period, 0 elsewhere.

    .. math:: s = P \cdot \hat d, \qquad T(P) = [\operatorname{fract}(n s) < w]

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    count : float
        Stripes per unit length along `direction`, :math:`n > 0`.
    width : float
        Duty cycle :math:`w` in [0, 1].
    direction : array_like, optional
        Across the stripes (default the first axis, u or x); normalized.

    Returns
    -------
    ndarray, shape (...)
        0.0 or 1.0.

    Examples
    --------
    >>> stripes([[0.05, 0.0], [0.1, 0.3], [0.2, 0.9]], count=4, width=0.5)
    array([1., 0., 1.])
    """
    p = _coords(points)
    n = as_positive(count, "count")
    w = as_scalar(width, "width")
    if not 0 <= w <= 1:
        raise ValueError(f"width must lie in [0, 1] (the stripes' share of a period), got {w:g}")
    if direction is None:
        s = p[..., 0]
    else:
        d = as_vector(direction, "direction", p.shape[-1])
        if not np.any(d):
            raise ValueError("direction must not be the zero vector")
        s = p @ (d / np.linalg.norm(d))
    frac = n * s - np.floor(n * s)
    return (frac < w).astype(float)


_PERIOD = 256


class _Lattice:
    """The seeded random tables of a lattice noise: a permutation, values and gradients."""

    def __init__(self, seed, dim):
        rng = as_rng(seed)
        self.perm = np.concatenate([rng.permutation(_PERIOD)] * 2)
        self.values = rng.uniform(-1.0, 1.0, _PERIOD)
        if dim == 2:
            angle = rng.uniform(0, 2 * np.pi, _PERIOD)
            self.gradients = np.stack([np.cos(angle), np.sin(angle)], axis=-1)
        else:
            g = rng.normal(size=(_PERIOD, 3))
            self.gradients = g / np.linalg.norm(g, axis=-1, keepdims=True)

    def hash(self, cells):
        """A pseudo-random index in [0, 256) for each integer lattice point (..., d)."""
        h = np.zeros(cells.shape[:-1], dtype=np.intp)
        for k in range(cells.shape[-1]):
            h = self.perm[(h + (cells[..., k] & (_PERIOD - 1))) & (_PERIOD - 1)]
        return h


def _fade(t):
    """Perlin's quintic 6t^5 - 15t^4 + 10t^3: 0 and 1 at the ends, zero slope and curvature."""
    return t * t * t * (t * (t * 6 - 15) + 10)


def _lattice_noise(points, seed, gradient):
    p = _coords(points)
    dim = p.shape[-1]
    lattice = _Lattice(seed, dim)
    base = np.floor(p)
    frac = p - base
    cell = base.astype(np.int64)
    fade = _fade(frac)
    result = np.zeros(p.shape[:-1])
    for corner in np.ndindex(*(2,) * dim):
        offset = np.array(corner)
        idx = lattice.hash(cell + offset)
        if gradient:
            contribution = _dot(lattice.gradients[idx], frac - offset)
        else:
            contribution = lattice.values[idx]
        weight = np.prod(np.where(offset == 1, fade, 1 - fade), axis=-1)
        result = result + weight * contribution
    return result


def value_noise(points, seed=0):
    r"""Value noise: random values at the integer lattice points, smoothly interpolated.

    Each lattice point gets a pseudo-random value in [-1, 1] (a seeded permutation table hashes
    its integer coordinates), and the values of the cell's :math:`2^d` corners are blended with
    the weights :math:`f(t) = 6t^5 - 15t^4 + 10t^3` per axis (smooth: no creases at the cell
    borders). Band-limited to about one feature per cell, but the lattice shows as blobs;
    :func:`perlin_noise` looks less grid-like. Periodic with period 256 in every coordinate.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    seed : int or numpy.random.Generator
        The same seed gives the same noise.

    Returns
    -------
    ndarray, shape (...)
        In [-1, 1]; equal to the lattice value at integer points.

    Examples
    --------
    >>> n = value_noise(np.random.default_rng(0).uniform(0, 50, (10_000, 2)), seed=1)
    >>> bool(n.min() >= -1 and n.max() <= 1)
    True
    >>> bool(np.allclose(value_noise([3.2, 4.7], seed=1), value_noise([3.2 + 256, 4.7], seed=1)))
    True
    """
    return _lattice_noise(points, seed, gradient=False)


def perlin_noise(points, seed=0):
    r"""Perlin (gradient) noise in 2D or 3D.

    Each integer lattice point :math:`c` gets a pseudo-random unit gradient :math:`g_c`; a point
    :math:`P` in a cell blends the corners' linear ramps :math:`g_c \cdot (P - c)` with the
    weights :math:`f(t) = 6t^5 - 15t^4 + 10t^3` per axis (Perlin's improved fade):

    .. math:: N(P) = \sum_{c \in \text{corners}} \Big(\prod_k w_k(c)\Big)\, g_c \cdot (P - c)

    So the noise is **zero at every lattice point** (all ramps vanish there) and has the
    gradient :math:`g_c` there: its features are about one cell apart, without the blobby grid
    of :func:`value_noise`. :math:`|N| \le \sqrt{d}/2` (0.71 in 2D, 0.87 in 3D): the ramps are
    at most the distance to the corner, and the weighted distance is largest at the cell
    centre. Periodic with period 256.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    seed : int or numpy.random.Generator

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> perlin_noise([[0, 0], [3, 7], [-2, 5]], seed=4)
    array([0., 0., 0.])
    >>> float(perlin_noise([0.5, 0.5], seed=4)) != 0
    True
    """
    return _lattice_noise(points, seed, gradient=True)


def turbulence(points, octaves=4, seed=0, lacunarity=2.0, gain=0.5, noise="perlin"):
    r"""Turbulence: a sum of octaves of the absolute value of noise.

    .. math:: T(P) = \sum_{o=0}^{O-1} g^o \, \lvert N(\ell^o P) \rvert

    Each octave doubles the frequency (lacunarity :math:`\ell = 2`) and halves the amplitude
    (gain :math:`g = 1/2`), a fractal (1/f) spectrum; the absolute value creates the sharp
    creases that look like turbulent flow, veins or flames.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    octaves : int
    seed : int or numpy.random.Generator
    lacunarity, gain : float
    noise : {"perlin", "value"}

    Returns
    -------
    ndarray, shape (...)
        Non-negative; at most :math:`\max|N| \sum_o g^o`.

    Examples
    --------
    >>> from course_lib.texturing import uv_grid
    >>> t = turbulence(uv_grid(32, 32) * 4, octaves=3)
    >>> t.shape, bool(t.min() >= 0)
    ((32, 32), True)
    """
    p = _coords(points)
    o = as_whole(octaves, "octaves", 1)
    lac, g = as_positive(lacunarity, "lacunarity"), as_positive(gain, "gain")
    as_choice(noise, "noise", ("perlin", "value"))
    # one lattice for every octave: the same as perlin_noise(points, seed) for an integer seed
    lattice_seed = seed if isinstance(seed, (int, np.integer)) else as_rng(seed).integers(2**63)
    total = np.zeros(p.shape[:-1])
    for k in range(o):
        total = total + g**k * np.abs(_lattice_noise(p * lac**k, lattice_seed,
                                                     gradient=noise == "perlin"))
    return total


def marble(points, frequency=2.0, strength=4.0, octaves=4, seed=0):
    r"""Marble: sine stripes along the first coordinate, bent by turbulence.

    .. math:: T(P) = \tfrac12\left[1 + \sin\big(2\pi f\, p_0 + a\, \mathrm{turbulence}(P)\big)
              \right] \in [0, 1]

    Without turbulence (:math:`a = 0`) these are straight soft stripes; the turbulence
    displaces them into veins. Use as a grey value or to blend two colours.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    frequency : float
        Stripes per unit length :math:`f`.
    strength : float
        Turbulence amplitude :math:`a`.
    octaves : int
    seed : int or numpy.random.Generator

    Returns
    -------
    ndarray, shape (...)
        In [0, 1].

    Examples
    --------
    >>> from course_lib.texturing import uv_grid
    >>> m = marble(uv_grid(16, 16), seed=2)
    >>> bool(m.min() >= 0 and m.max() <= 1)
    True
    >>> bool(np.allclose(marble([[0.125, 0.3]], frequency=2, strength=0), 1.0))   # a crest
    True
    """
    p = _coords(points)
    f, a = as_scalar(frequency, "frequency"), as_scalar(strength, "strength")
    t = turbulence(p, octaves, seed) if a != 0 else 0.0
    return 0.5 * (1 + np.sin(2 * np.pi * f * p[..., 0] + a * t))


def wood(points, rings=8.0, strength=0.3, octaves=2, seed=0, center=(0.0, 0.0)):
    r"""Wood: concentric rings around an axis, wobbled by turbulence.

    .. math:: r = \lVert (p_0, p_1) - c \rVert, \qquad
              T(P) = \operatorname{fract}\big(k\, r + a\,\mathrm{turbulence}(P)\big) \in [0, 1)

    In 2D the rings are around the point `center`; in 3D around the line through it parallel
    to the third axis (the trunk), so a solid block of "wood" can be cut by any surface.

    Parameters
    ----------
    points : array_like, shape (..., 2) or (..., 3)
    rings : float
        Rings per unit radius :math:`k`.
    strength : float
        Turbulence amplitude :math:`a`.
    octaves : int
    seed : int or numpy.random.Generator
    center : array_like, shape (2,)

    Returns
    -------
    ndarray, shape (...)
        In [0, 1).

    Examples
    --------
    >>> wood([[0.3, 0.4], [0.0, 0.5]], rings=3, strength=0)     # r = 0.5: fract(1.5)
    array([0.5, 0.5])
    """
    p = _coords(points)
    k, a = as_scalar(rings, "rings"), as_scalar(strength, "strength")
    c = as_vector(center, "center", 2)
    r = np.hypot(p[..., 0] - c[0], p[..., 1] - c[1])
    x = k * r + (a * turbulence(p, octaves, seed) if a != 0 else 0.0)
    return x - np.floor(x)
