r"""Chapter 10: normalisation, transfer functions and colour maps, with perceptual checks.

Visualization turns numbers into something the eye can read. Before a value can become a grey
level, a colour or an opacity, it is first brought to a common scale, then mapped through a
function the visualizer chooses:

* :func:`normalize`: the **linear normalisation** that maps the data range :math:`[a, b]`
  onto a target range :math:`[c, d]`,

  .. math:: n(v) = \frac{v - a}{b - a}\,(d - c) + c .

  Subtracting :math:`a` moves the smallest value to 0, dividing by :math:`b - a` brings the
  data to :math:`[0, 1]`, and scaling by :math:`d - c` and adding :math:`c` lands it on the
  target interval. A constant field (:math:`a = b`) has no spread to scale: we map it to the
  middle of the target range rather than divide by zero.
* :class:`TransferFunction`: a **transfer function** assigns each data value an output: an
  intensity (tone mapping), a colour, an opacity, or all of them (RGBA). Ours are
  piecewise-linear between control points (``kind="linear"``), or piecewise-constant
  (``kind="step"``, a *thresholding* or banding of the data); a point repeated twice in a
  linear function makes a jump. :func:`opacity_transfer` and :func:`color_transfer` check
  that opacities and colours lie in [0, 1]; :func:`rgba_transfer` joins a colour function
  and an opacity function into one RGBA function (exactly, on the union of their control
  points), and :func:`transfer_preset` has ready-made ones for CT-like volumes.
* :func:`apply_colormap`: a **colour map** is a transfer function from normalised values
  :math:`t \in [0, 1]` to colours, given here as :math:`n` control colours spaced evenly in
  :math:`t` and interpolated linearly in RGB. :data:`COLORMAP_NAMES` lists the maps shipped:
  the classic grey ramp, rainbow (the hue sweep blue - cyan - green - yellow - red of
  HSV), jet, hot (black - red - yellow - white), the diverging blue-white-red and cool-warm,
  and matplotlib's perceptually designed viridis, magma, inferno, plasma, cividis and turbo.
  Append ``"_r"`` to a name to reverse a map.

**Why the choice of colour map matters.** The eye reads *lightness* as magnitude far more
reliably than hue: hue has no natural order (is green more than yellow?), while darker-to-lighter
is read as less-to-more by everybody, and survives a black-and-white print and most forms of
colour blindness. A good map for ordered data has lightness that changes monotonically and
evenly along the map. The rainbow and jet maps do not: their lightness goes up and down (yellow
and cyan are much lighter than blue and red), which paints false edges into smooth data
(bands appear where the lightness jumps) and hides real features where it is flat.

The module measures this with the CIE colour spaces:

* :func:`srgb_to_linear`, :func:`srgb_to_xyz`, :func:`xyz_to_lab`, :func:`srgb_to_lab`:
  sRGB values are gamma-encoded; undoing the encoding gives linear light, a 3x3 matrix gives
  the CIE XYZ tristimulus values (D65 white), and a cube-root compression gives CIE L*a*b*,
  where :math:`L^*` (0 black .. 100 white) is perceived lightness and Euclidean distances
  approximate perceived colour differences.
* :func:`lightness` gives :math:`L^*` along a map, :func:`is_monotonic_lightness` the verdict,
  :func:`perceptual_steps` the colour difference :math:`\Delta E^*_{ab}` between neighbouring
  samples (even steps = perceptually uniform), :func:`luminance` and :func:`greyscale` what the
  map looks like printed in black and white.

Conventions
-----------
Colours are RGB triples of floats in [0, 1], **sRGB** (gamma-encoded, as stored in images and
shown by matplotlib), in the last axis of an array. Colour maps are ``(n, 3)`` arrays of control
colours at :math:`t_k = k / (n - 1)`.

**Missing data (NaN)** is common in measured fields. :func:`normalize` propagates NaN (a NaN
in gives a NaN out, and the range is taken over the other values); :func:`apply_colormap`
paints NaNs in a separate, conspicuous ``nan_color`` (magenta by default) so that holes in the
data stay visible instead of taking some colour of the map. Infinite values are rejected with
a ``ValueError``. Transfer functions, colour conversions and the volume algorithms of
:mod:`course_lib.scivis` reject NaN with a ``ValueError``.

The perceptual maps were sampled from matplotlib once, when this module was written: 64
control colours per map fitted by least squares to matplotlib's 256-entry tables and rounded to
4 decimals. At matplotlib's own sample points they agree within 3/255 per channel (less than
three steps of an 8-bit channel: 0.0101 for jet, whose kinks fall between control points, under
0.009 for the others; the root-mean-square difference is under 0.002); the grey, rainbow and
blue-white-red maps are exact, hot exact to 4 decimals.
"""
import numpy as np

from ._validate import as_array, as_scalar, as_vector

__all__ = [
    "COLORMAP_NAMES",
    "D65_WHITE",
    "TransferFunction",
    "apply_colormap",
    "color_transfer",
    "colormap",
    "delta_e",
    "greyscale",
    "is_monotonic_lightness",
    "lightness",
    "linear_to_srgb",
    "luminance",
    "normalize",
    "opacity_transfer",
    "perceptual_steps",
    "rgba_transfer",
    "sample_colormap",
    "srgb_to_lab",
    "srgb_to_linear",
    "srgb_to_xyz",
    "transfer_preset",
    "xyz_to_lab",
]


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _data_allowing_nan(value, name):
    """Like ``as_array`` but NaN is allowed (it marks missing data); infinity is not."""
    if isinstance(value, (str, bytes)) or value is None or value is Ellipsis:
        as_array(value, name)                       # raises the standard TypeError
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        as_array(value, name)
        raise
    if np.isinf(arr).any():
        raise ValueError(f"{name} must not contain infinite values (NaN is allowed and marks "
                         "missing data)")
    return arr


def _range(value, name, ordered):
    r = as_vector(value, name, 2)
    if ordered and r[0] > r[1]:
        raise ValueError(f"{name} must be (low, high) with low <= high, got ({r[0]:g}, {r[1]:g})")
    return r


def _data_range(data, in_range):
    if in_range is not None:
        return _range(in_range, "in_range", ordered=True)
    finite = data[~np.isnan(data)]
    if finite.size == 0:
        raise ValueError("data has no values to take the range from (it is empty or all NaN): "
                         "pass in_range=(low, high)")
    return np.array([finite.min(), finite.max()])


def _unit_interval(arr, name, what):
    bad = (arr < 0) | (arr > 1)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        raise ValueError(f"{name} must lie in [0, 1] ({what}), got {arr[index]:g} at index "
                         f"{index if len(index) > 1 else index[0]}")
    return arr


def _rgb(value, name="rgb"):
    rgb = as_array(value, name)
    if rgb.ndim == 0 or rgb.shape[-1] != 3:
        raise ValueError(f"{name} must have 3 components (r, g, b) in the last axis, got shape "
                         f"{rgb.shape}")
    if ((rgb < -1e-9) | (rgb > 1 + 1e-9)).any():
        _unit_interval(rgb, name, "sRGB components")
    return np.clip(rgb, 0.0, 1.0)


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


# ---------------------------------------------------------------------------------------------
# Transfer functions
# ---------------------------------------------------------------------------------------------

class TransferFunction:
    r"""A piecewise-linear (or step) transfer function given by control points.

    ``kind="linear"``: between consecutive points :math:`s_i < s_{i+1}` the output is the linear
    interpolation

    .. math:: f(s) = v_i + \frac{s - s_i}{s_{i+1} - s_i}\,(v_{i+1} - v_i),

    and outside :math:`[s_0, s_{n-1}]` it stays at the end values. A point given twice,
    :math:`s_i = s_{i+1}`, makes a jump from :math:`v_i` to :math:`v_{i+1}`; at the jump itself the
    function takes the value after it (it is continuous from the right).

    ``kind="step"``: the output is :math:`v_i` on :math:`[s_i, s_{i+1})` (and :math:`v_0` below
    :math:`s_0`, :math:`v_{n-1}` from :math:`s_{n-1}` on): a thresholding of the data into bands.

    Each control value may be a number (an intensity or an opacity) or a vector of k <= 4
    numbers (a colour, or colour and opacity, RGBA). Evaluation is vectorized: any array of
    scalars gives an array of outputs.

    Parameters
    ----------
    points : array_like, shape (n,)
        The scalar values :math:`s_i`, n >= 2; non-decreasing for "linear" (each at most
        twice), strictly increasing for "step".
    values : array_like, shape (n,) or (n, k)
        The outputs :math:`v_i` at the points.
    kind : {"linear", "step"}

    Attributes
    ----------
    points, values : ndarray
        Copies of the control points and values as given.
    kind : str
    channels : int
        Number of output components (1 for a scalar function).

    Raises
    ------
    ValueError
        For fewer than 2 points, points out of order, a point repeated three times, values of
        the wrong length, an unknown kind, or NaN anywhere.

    Examples
    --------
    A tone ramp that is black below 100, white above 300:

    >>> ramp = TransferFunction([100, 300], [0.0, 1.0])
    >>> ramp([50, 100, 200, 250, 400])
    array([0.  , 0.  , 0.5 , 0.75, 1.  ])

    A threshold: 0 below 0.5, 1 from 0.5 on (a step function, or a linear one with a jump):

    >>> TransferFunction([0, 0.5], [0, 1], kind="step")([0.2, 0.5, 0.9])
    array([0., 1., 1.])
    >>> TransferFunction([0, 0.5, 0.5, 1], [0, 0, 1, 1])([0.2, 0.5, 0.9])
    array([0., 1., 1.])

    A colour function (scalar -> RGB):

    >>> TransferFunction([0, 1], [[0, 0, 1], [1, 0, 0]])(0.25)
    array([0.25, 0.  , 0.75])
    """

    def __init__(self, points, values, kind="linear"):
        if kind not in ("linear", "step"):
            raise ValueError(f'kind must be "linear" or "step", got {kind!r}')
        p = as_array(points, "points")
        if p.ndim != 1 or len(p) < 2:
            raise ValueError(f"points must be a 1-D list of at least 2 scalar values, got shape "
                             f"{p.shape}")
        v = as_array(values, "values")
        if v.ndim not in (1, 2) or len(v) != len(p) or (v.ndim == 2 and not 1 <= v.shape[1] <= 4):
            raise ValueError(f"values must have one entry per point: shape ({len(p)},) or "
                             f"({len(p)}, k) with k <= 4, got shape {v.shape}")
        gaps = np.diff(p)
        if kind == "step" and (gaps <= 0).any():
            i = int(np.argmax(gaps <= 0))
            raise ValueError(f"points of a step function must be strictly increasing, but "
                             f"points[{i + 1}] = {p[i + 1]:g} follows {p[i]:g}")
        if (gaps < 0).any():
            i = int(np.argmax(gaps < 0))
            raise ValueError(f"points must be non-decreasing, but points[{i + 1}] = {p[i + 1]:g} "
                             f"follows {p[i]:g}")
        if ((gaps[:-1] == 0) & (gaps[1:] == 0)).any():
            i = int(np.argmax((gaps[:-1] == 0) & (gaps[1:] == 0)))
            raise ValueError(f"points may repeat a value at most twice (a jump), but {p[i]:g} "
                             "appears three times")
        self.points, self.values, self.kind = p.copy(), v.copy(), kind
        self.channels = 1 if v.ndim == 1 else v.shape[1]
        table = v if v.ndim == 2 else v[:, None]
        if kind == "step":                       # as a linear function with a jump at each point
            self._x = np.repeat(p, 2)[1:]
            self._y = np.repeat(table, 2, axis=0)[:-1]
        else:
            self._x, self._y = p, table
        # for evaluation: one constant segment added at each end, so that every scalar falls in
        # a segment of positive length (the segments of zero length are the jumps)
        span = max(1.0, float(p[-1] - p[0]))
        self._xe = np.concatenate([[self._x[0] - span], self._x, [self._x[-1] + span]])
        self._ye = np.concatenate([self._y[:1], self._y, self._y[-1:]])
        dx = np.diff(self._xe)
        self._inv_dx = np.divide(1.0, dx, out=np.zeros_like(dx), where=dx > 0)
        self._dy = np.diff(self._ye, axis=0)

    def _evaluate(self, s, side):
        """Values at s (1-D); side="right" is the function, side="left" its left limit.

        With side="right" the segment i holds x_i <= s < x_{i+1}, with side="left"
        x_i < s <= x_{i+1}: either way a segment of positive length (jumps are skipped).
        """
        xe = self._xe
        s = np.clip(s, xe[0], xe[-1])
        i = np.clip(np.searchsorted(xe, s, side=side) - 1, 0, len(xe) - 2)
        t = (s - xe[i]) * self._inv_dx[i]
        return self._ye[i] + t[:, None] * self._dy[i]

    def __call__(self, scalars):
        s = as_array(scalars, "scalars")
        out = self._evaluate(s.ravel(), "right")
        if self.values.ndim == 1:
            return out[:, 0].reshape(s.shape)
        return out.reshape(s.shape + (self.channels,))

    def lookup_table(self, n=256, in_range=None):
        """The function tabulated at n evenly spaced scalars: a lookup table, shape (n, k) or (n,).

        Parameters
        ----------
        n : int
            Number of entries, >= 2.
        in_range : (float, float), optional
            The scalar interval to tabulate; default from the first to the last control point.

        Examples
        --------
        >>> TransferFunction([0, 1], [0, 1]).lookup_table(5)
        array([0.  , 0.25, 0.5 , 0.75, 1.  ])
        """
        n = _count(n, "n", 2)
        lo, hi = (self.points[0], self.points[-1]) if in_range is None else \
            _range(in_range, "in_range", ordered=True)
        return self(np.linspace(lo, hi, n))

    def __repr__(self):
        return (f"TransferFunction(points={self.points.tolist()}, values={self.values.tolist()}, "
                f"kind={self.kind!r})")


def _count(value, name, minimum):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    v = as_scalar(value, name)
    if v != int(v) or v < minimum:
        raise ValueError(f"{name} must be a whole number >= {minimum}, got {value!r}")
    return int(v)


def opacity_transfer(points, opacities, kind="linear"):
    """A scalar -> opacity transfer function; opacities must lie in [0, 1].

    Opacity 0 is fully transparent, 1 fully opaque. In volume rendering the opacity is that of a
    slab of unit thickness (see :func:`course_lib.scivis.volume_render`).

    Parameters
    ----------
    points : array_like, shape (n,)
        Control scalars (see :class:`TransferFunction`).
    opacities : array_like, shape (n,)
        Opacity at each point, in [0, 1].
    kind : {"linear", "step"}

    Returns
    -------
    TransferFunction
        With one channel.

    Raises
    ------
    ValueError
        For an opacity outside [0, 1], or as :class:`TransferFunction`.

    Examples
    --------
    >>> alpha = opacity_transfer([0.2, 0.6], [0.0, 0.8])
    >>> alpha([0.0, 0.4, 1.0])
    array([0. , 0.4, 0.8])
    >>> opacity_transfer([0, 1], [0, 1.5])
    Traceback (most recent call last):
    ...
    ValueError: opacities must lie in [0, 1] (0 transparent, 1 opaque), got 1.5 at index 1
    """
    a = as_array(opacities, "opacities")
    if a.ndim != 1:
        raise ValueError(f"opacities must be one number per point, shape (n,), got shape "
                         f"{a.shape}")
    _unit_interval(a, "opacities", "0 transparent, 1 opaque")
    return TransferFunction(points, a, kind)


def color_transfer(points, colors, kind="linear"):
    """A scalar -> RGB colour transfer function; colours are (r, g, b) in [0, 1].

    Parameters
    ----------
    points : array_like, shape (n,)
        Control scalars (see :class:`TransferFunction`).
    colors : array_like, shape (n, 3)
        Colour at each point.
    kind : {"linear", "step"}

    Returns
    -------
    TransferFunction
        With three channels.

    Examples
    --------
    >>> tf = color_transfer([0, 10], [[0, 0, 0], [1, 0.5, 0]])
    >>> tf(5)
    array([0.5 , 0.25, 0.  ])
    """
    c = as_array(colors, "colors")
    if c.ndim != 2 or c.shape[1] != 3:
        raise ValueError(f"colors must be one (r, g, b) colour per point, shape (n, 3), got "
                         f"shape {c.shape}")
    _unit_interval(c, "colors", "RGB components")
    return TransferFunction(points, c, kind)


def rgba_transfer(color, opacity, in_range=None):
    """Join a colour and an opacity transfer function into one scalar -> RGBA function.

    The result is exact, not resampled: both inputs are piecewise linear (steps are linear
    functions with jumps), so on the union of their control points (with a jump wherever
    either jumps) the joined function is piecewise linear too.

    Parameters
    ----------
    color : TransferFunction, str or array_like
        A transfer function with 3 channels (RGB) or 1 (grey, copied to r, g and b), or a colour
        map (a name from :data:`COLORMAP_NAMES` or an (n, 3) array of control colours) spread
        evenly over `in_range`.
    opacity : TransferFunction
        A one-channel function with values in [0, 1], e.g. from :func:`opacity_transfer`.
    in_range : (float, float), optional
        The scalar interval a colour map covers; default the span of the opacity's points.

    Returns
    -------
    TransferFunction
        Four channels (r, g, b, a); ``.lookup_table(n)`` gives an (n, 4) RGBA lookup table.

    Examples
    --------
    >>> rgba = rgba_transfer("grey", opacity_transfer([0, 0.5, 0.5, 1], [0, 0, 1, 1]))
    >>> rgba([0.25, 0.75])
    array([[0.25, 0.25, 0.25, 0.  ],
           [0.75, 0.75, 0.75, 1.  ]])
    >>> rgba.lookup_table(3).shape
    (3, 4)
    """
    if not isinstance(opacity, TransferFunction) or opacity.channels != 1:
        raise TypeError("opacity must be a one-channel TransferFunction (see opacity_transfer)")
    _unit_interval(opacity.values, "opacity values", "0 transparent, 1 opaque")
    if not isinstance(color, TransferFunction):
        lo, hi = (opacity.points[0], opacity.points[-1]) if in_range is None else \
            _range(in_range, "in_range", ordered=True)
        cmap = colormap(color)[:, :3]
        if hi == lo:
            raise ValueError("in_range must have low < high to spread a colour map over it")
        color = TransferFunction(np.linspace(lo, hi, len(cmap)), cmap)
    elif color.channels not in (1, 3):
        raise ValueError(f"color must have 3 channels (RGB) or 1 (grey), got {color.channels}")
    breaks = np.union1d(color._x, opacity._x)

    def both(side):
        c = color._evaluate(breaks, side)
        c = np.repeat(c, 3, axis=1) if c.shape[1] == 1 else c
        return np.concatenate([c, opacity._evaluate(breaks, side)], axis=1)

    left, right = both("left"), both("right")
    jump = (left != right).any(axis=1)
    jump[0] = False                              # nothing comes before the first point
    points = np.concatenate([breaks, breaks[jump]])
    values = np.concatenate([right, left[jump]])
    order = np.lexsort((np.concatenate([np.ones(len(breaks)), np.zeros(jump.sum())]), points))
    if len(breaks) == 1:                         # both functions constant: keep two points
        points, values, order = np.repeat(points, 2), np.repeat(values, 2, axis=0), [0, 1]
    return TransferFunction(points[order], values[order])


#: Control points of the ready-made transfer functions, over normalised scalars in [0, 1]:
#: (points, RGB colours, opacities). Opacities are per unit length (one voxel).
_PRESETS = {
    "ramp": ([0.0, 1.0], [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], [0.0, 1.0]),
    "skin": ([0.0, 0.12, 0.25, 0.33, 0.45, 0.6, 0.8, 1.0],
             [[0.0, 0.0, 0.0], [0.85, 0.55, 0.45], [0.95, 0.75, 0.65], [0.9, 0.7, 0.65],
              [0.8, 0.6, 0.6], [0.9, 0.85, 0.8], [1.0, 1.0, 0.95], [1.0, 0.2, 0.1]],
             [0.0, 0.0, 0.12, 0.0, 0.01, 0.0, 0.3, 0.8]),
    "bone": ([0.0, 0.55, 0.75, 0.9, 1.0],
             [[0.0, 0.0, 0.0], [0.8, 0.7, 0.6], [0.95, 0.92, 0.85], [1.0, 1.0, 1.0],
              [1.0, 0.3, 0.2]],
             [0.0, 0.0, 0.8, 0.8, 1.0]),
}


def transfer_preset(name, in_range=(0.0, 1.0)):
    """A ready-made RGBA transfer function for CT-like volumes: "ramp", "skin" or "bone".

    The presets are designed for data normalised to [0, 1] as in
    :func:`course_lib.scivis.example_volume` ``("ct")`` (air 0, soft tissue 0.25, brain 0.4,
    bone 0.8, contrast agent 1):

    * ``"ramp"``: grey level and opacity both rising linearly from 0 to 1 (an X-ray-like look);
    * ``"skin"``: the soft tissue around 0.25 skin-coloured and translucent (opacity up to 0.12
      per voxel), brain faint, bone white at 0.3, the densest values red and nearly opaque;
    * ``"bone"``: everything below 0.55 transparent, bone off-white and opaque, the densest
      values red.

    Parameters
    ----------
    name : {"ramp", "skin", "bone"}
    in_range : (float, float)
        The data interval the preset's [0, 1] is stretched onto (so raw data need not be
        normalised first).

    Returns
    -------
    TransferFunction
        Four channels (r, g, b, opacity).

    Examples
    --------
    >>> bone = transfer_preset("bone")
    >>> bone([0.3, 0.8])[:, 3]
    array([0. , 0.8])
    >>> transfer_preset("ramp", in_range=(0, 1000))(500)
    array([0.5, 0.5, 0.5, 0.5])
    """
    if name not in _PRESETS:
        raise ValueError(f"name must be one of {sorted(_PRESETS)}, got {name!r}")
    lo, hi = _range(in_range, "in_range", ordered=True)
    if hi == lo:
        raise ValueError("in_range must have low < high")
    points, colors, alphas = _PRESETS[name]
    values = np.concatenate([np.array(colors), np.array(alphas)[:, None]], axis=1)
    return TransferFunction(lo + (hi - lo) * np.array(points), values)


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
    return _lookup(colormap(cmap), np.linspace(0.0, 1.0, _count(n, "n", 2)))


def apply_colormap(data, cmap="viridis", in_range=None, opacity=None,
                   nan_color=(1.0, 0.0, 1.0)):
    """Colour data through a colour map: normalise to [0, 1], then look the colours up.

    Each value v becomes :math:`t = (v - a) / (b - a)` (:func:`normalize`, clipped to [0, 1]) and
    the colour at t is interpolated linearly between the two neighbouring control colours: with
    n control colours at :math:`t_k = k / (n - 1)`, position :math:`p = t (n - 1)`,
    :math:`k = \\lfloor p \\rfloor`, :math:`f = p - k`, colour :math:`(1 - f) C_k + f C_{k+1}`.
    Values below a get the first colour, above b the last.

    Parameters
    ----------
    data : array_like
        Scalar values, any shape. NaN (missing data) is painted in `nan_color`.
    cmap : str or array_like
        A name from :data:`COLORMAP_NAMES` or control colours (see :func:`colormap`).
    in_range : (float, float), optional
        The data interval [a, b] spanned by the map; default the data's min and max.
    opacity : float or TransferFunction, optional
        If given, an alpha channel is added: a constant in [0, 1], or a one-channel transfer
        function of the (raw) data values.
    nan_color : (r, g, b) or (r, g, b, a)
        The colour of NaN values; magenta by default, which none of the shipped maps uses.

    Returns
    -------
    ndarray, shape data.shape + (3,) or data.shape + (4,)
        RGB, or RGBA when `opacity` is given or `cmap` has an alpha column.

    Examples
    --------
    >>> apply_colormap([0, 5, 10], "grey")
    array([[0. , 0. , 0. ],
           [0.5, 0.5, 0.5],
           [1. , 1. , 1. ]])
    >>> apply_colormap([0.0, np.nan, 1.0], "bwr")
    array([[0., 0., 1.],
           [1., 0., 1.],
           [1., 0., 0.]])
    >>> apply_colormap([0.5], "bwr", in_range=(0, 1), opacity=0.3)
    array([[1. , 1. , 1. , 0.3]])
    """
    values = _data_allowing_nan(data, "data")
    colors = colormap(cmap)
    missing = np.isnan(values)
    if missing.all():
        t = np.zeros(values.shape)
    else:
        t = np.nan_to_num(normalize(values, in_range, (0.0, 1.0), clip=True), nan=0.0)
    rgb = _lookup(colors, np.asarray(t, dtype=float))
    if opacity is not None:
        if isinstance(opacity, TransferFunction):
            if opacity.channels != 1:
                raise ValueError("opacity must be a one-channel TransferFunction")
            alpha = opacity(np.where(missing, 0.0, values))
            alpha = np.clip(alpha, 0.0, 1.0)
        else:
            a = as_scalar(opacity, "opacity")
            if not 0 <= a <= 1:
                raise ValueError(f"opacity must lie in [0, 1] (0 transparent, 1 opaque), got "
                                 f"{a:g}")
            alpha = np.full(values.shape, a)
        rgb = np.concatenate([rgb[..., :3], alpha[..., None]], axis=-1)
    if missing.any():
        bad = _unit_interval(as_array(nan_color, "nan_color"), "nan_color", "colour components")
        if bad.shape not in ((3,), (4,)):
            raise ValueError(f"nan_color must be (r, g, b) or (r, g, b, a), got shape "
                             f"{bad.shape}")
        if rgb.shape[-1] == 4 and len(bad) == 3:
            bad = np.append(bad, 1.0)
        rgb[missing] = bad[:rgb.shape[-1]]
    return rgb


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
    return srgb_to_linear(_rgb(rgb)) @ _SRGB_TO_XYZ.T


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
    return srgb_to_linear(_rgb(rgb)) @ _SRGB_TO_XYZ[1]


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


# ---------------------------------------------------------------------------------------------
# Colour map data
# ---------------------------------------------------------------------------------------------
# The perceptual maps, turbo, jet and hot below: 64 control colours each, fitted once by least
# squares to matplotlib 3.11's 256-entry tables (viridis, magma, inferno and plasma by van der
# Walt and Smith, cividis by Nunez et al., turbo by Mikhailov) and rounded to 4 decimals.

_VIRIDIS = np.array([
    [0.2671, 0.0046, 0.3295], [0.2728, 0.0255, 0.3535], [0.2772, 0.0511, 0.3763],
    [0.2805, 0.0744, 0.3980], [0.2825, 0.0960, 0.4184], [0.2833, 0.1169, 0.4373],
    [0.2829, 0.1374, 0.4547], [0.2813, 0.1575, 0.4706], [0.2786, 0.1774, 0.4848],
    [0.2748, 0.1970, 0.4974], [0.2701, 0.2164, 0.5084], [0.2644, 0.2354, 0.5179],
    [0.2581, 0.2542, 0.5259], [0.2511, 0.2726, 0.5326], [0.2438, 0.2907, 0.5382],
    [0.2361, 0.3083, 0.5427], [0.2283, 0.3256, 0.5464], [0.2204, 0.3425, 0.5493],
    [0.2127, 0.3591, 0.5517], [0.2051, 0.3754, 0.5535], [0.1977, 0.3914, 0.5550],
    [0.1906, 0.4071, 0.5561], [0.1838, 0.4226, 0.5570], [0.1773, 0.4379, 0.5576],
    [0.1709, 0.4531, 0.5580], [0.1648, 0.4681, 0.5582], [0.1588, 0.4831, 0.5581],
    [0.1529, 0.4981, 0.5577], [0.1471, 0.5130, 0.5570], [0.1414, 0.5279, 0.5559],
    [0.1358, 0.5427, 0.5543], [0.1305, 0.5577, 0.5522], [0.1258, 0.5726, 0.5495],
    [0.1220, 0.5875, 0.5461], [0.1197, 0.6024, 0.5419], [0.1194, 0.6173, 0.5369],
    [0.1218, 0.6321, 0.5309], [0.1273, 0.6469, 0.5240], [0.1365, 0.6616, 0.5161],
    [0.1493, 0.6761, 0.5070], [0.1657, 0.6905, 0.4968], [0.1853, 0.7047, 0.4855],
    [0.2078, 0.7187, 0.4730], [0.2329, 0.7324, 0.4592], [0.2604, 0.7458, 0.4442],
    [0.2898, 0.7589, 0.4279], [0.3212, 0.7715, 0.4104], [0.3542, 0.7838, 0.3916],
    [0.3888, 0.7955, 0.3715], [0.4248, 0.8067, 0.3502], [0.4621, 0.8174, 0.3277],
    [0.5007, 0.8275, 0.3039], [0.5402, 0.8369, 0.2790], [0.5808, 0.8457, 0.2531],
    [0.6221, 0.8539, 0.2263], [0.6641, 0.8614, 0.1989], [0.7064, 0.8683, 0.1714],
    [0.7489, 0.8746, 0.1448], [0.7913, 0.8804, 0.1208], [0.8334, 0.8858, 0.1024],
    [0.8748, 0.8910, 0.0942], [0.9154, 0.8960, 0.0994], [0.9549, 0.9010, 0.1172],
    [0.9933, 0.9061, 0.1436],
])

_MAGMA = np.array([
    [0.0013, 0.0003, 0.0129], [0.0057, 0.0047, 0.0368], [0.0137, 0.0118, 0.0695],
    [0.0249, 0.0209, 0.1017], [0.0402, 0.0315, 0.1350], [0.0576, 0.0429, 0.1694],
    [0.0754, 0.0528, 0.2051], [0.0944, 0.0607, 0.2422], [0.1149, 0.0661, 0.2804],
    [0.1373, 0.0688, 0.3191], [0.1618, 0.0684, 0.3573], [0.1882, 0.0653, 0.3927],
    [0.2156, 0.0614, 0.4231], [0.2430, 0.0591, 0.4470], [0.2699, 0.0604, 0.4648],
    [0.2960, 0.0654, 0.4778], [0.3215, 0.0731, 0.4872], [0.3465, 0.0824, 0.4940],
    [0.3713, 0.0924, 0.4990], [0.3959, 0.1027, 0.5027], [0.4205, 0.1128, 0.5053],
    [0.4452, 0.1227, 0.5070], [0.4699, 0.1324, 0.5079], [0.4948, 0.1417, 0.5080],
    [0.5199, 0.1507, 0.5075], [0.5452, 0.1595, 0.5061], [0.5707, 0.1680, 0.5040],
    [0.5963, 0.1763, 0.5011], [0.6221, 0.1845, 0.4973], [0.6481, 0.1927, 0.4925],
    [0.6741, 0.2010, 0.4868], [0.7002, 0.2095, 0.4801], [0.7262, 0.2183, 0.4723],
    [0.7520, 0.2277, 0.4636], [0.7776, 0.2378, 0.4538], [0.8028, 0.2488, 0.4431],
    [0.8273, 0.2612, 0.4315], [0.8509, 0.2751, 0.4193], [0.8733, 0.2909, 0.4068],
    [0.8942, 0.3089, 0.3944], [0.9131, 0.3293, 0.3827], [0.9299, 0.3523, 0.3726],
    [0.9442, 0.3775, 0.3649], [0.9562, 0.4046, 0.3603], [0.9659, 0.4331, 0.3593],
    [0.9738, 0.4625, 0.3618], [0.9800, 0.4924, 0.3679], [0.9850, 0.5225, 0.3771],
    [0.9888, 0.5526, 0.3891], [0.9918, 0.5826, 0.4035], [0.9941, 0.6125, 0.4201],
    [0.9957, 0.6422, 0.4385], [0.9967, 0.6717, 0.4585], [0.9973, 0.7012, 0.4799],
    [0.9974, 0.7305, 0.5026], [0.9971, 0.7597, 0.5264], [0.9965, 0.7888, 0.5513],
    [0.9955, 0.8178, 0.5772], [0.9943, 0.8468, 0.6040], [0.9929, 0.8758, 0.6317],
    [0.9914, 0.9047, 0.6602], [0.9898, 0.9337, 0.6895], [0.9884, 0.9625, 0.7193],
    [0.9871, 0.9914, 0.7495],
])

_INFERNO = np.array([
    [0.0013, 0.0003, 0.0128], [0.0058, 0.0045, 0.0382], [0.0139, 0.0113, 0.0728],
    [0.0259, 0.0196, 0.1070], [0.0429, 0.0286, 0.1428], [0.0624, 0.0372, 0.1798],
    [0.0833, 0.0440, 0.2180], [0.1063, 0.0475, 0.2567], [0.1316, 0.0474, 0.2945],
    [0.1587, 0.0443, 0.3292], [0.1867, 0.0397, 0.3587], [0.2147, 0.0365, 0.3817],
    [0.2422, 0.0365, 0.3989], [0.2689, 0.0402, 0.4113], [0.2951, 0.0467, 0.4201],
    [0.3208, 0.0549, 0.4262], [0.3463, 0.0640, 0.4302], [0.3716, 0.0735, 0.4324],
    [0.3968, 0.0829, 0.4333], [0.4220, 0.0923, 0.4328], [0.4471, 0.1015, 0.4312],
    [0.4723, 0.1106, 0.4284], [0.4976, 0.1195, 0.4245], [0.5228, 0.1284, 0.4195],
    [0.5480, 0.1372, 0.4134], [0.5733, 0.1462, 0.4061], [0.5984, 0.1554, 0.3977],
    [0.6235, 0.1648, 0.3882], [0.6483, 0.1747, 0.3775], [0.6729, 0.1851, 0.3658],
    [0.6972, 0.1962, 0.3531], [0.7211, 0.2080, 0.3393], [0.7445, 0.2207, 0.3247],
    [0.7672, 0.2345, 0.3092], [0.7893, 0.2493, 0.2930], [0.8106, 0.2653, 0.2761],
    [0.8310, 0.2825, 0.2587], [0.8504, 0.3010, 0.2407], [0.8687, 0.3208, 0.2224],
    [0.8858, 0.3417, 0.2037], [0.9017, 0.3639, 0.1846], [0.9164, 0.3871, 0.1652],
    [0.9297, 0.4114, 0.1454], [0.9418, 0.4366, 0.1252], [0.9524, 0.4627, 0.1046],
    [0.9617, 0.4896, 0.0835], [0.9696, 0.5172, 0.0625], [0.9761, 0.5454, 0.0420],
    [0.9813, 0.5742, 0.0268], [0.9850, 0.6035, 0.0226], [0.9872, 0.6333, 0.0311],
    [0.9881, 0.6634, 0.0539], [0.9874, 0.6939, 0.0833], [0.9853, 0.7248, 0.1164],
    [0.9818, 0.7558, 0.1526], [0.9768, 0.7870, 0.1918], [0.9704, 0.8183, 0.2346],
    [0.9631, 0.8493, 0.2816], [0.9553, 0.8799, 0.3337], [0.9486, 0.9093, 0.3919],
    [0.9457, 0.9365, 0.4560], [0.9507, 0.9604, 0.5229], [0.9654, 0.9807, 0.5870],
    [0.9880, 0.9985, 0.6452],
])

_PLASMA = np.array([
    [0.0515, 0.0297, 0.5282], [0.0978, 0.0250, 0.5476], [0.1334, 0.0221, 0.5638],
    [0.1654, 0.0201, 0.5781], [0.1948, 0.0183, 0.5910], [0.2229, 0.0164, 0.6028],
    [0.2500, 0.0143, 0.6137], [0.2764, 0.0119, 0.6236], [0.3023, 0.0093, 0.6325],
    [0.3279, 0.0066, 0.6404], [0.3531, 0.0041, 0.6471], [0.3781, 0.0019, 0.6526],
    [0.4029, 0.0006, 0.6568], [0.4274, 0.0006, 0.6594], [0.4517, 0.0023, 0.6604],
    [0.4757, 0.0063, 0.6598], [0.4993, 0.0133, 0.6574], [0.5226, 0.0236, 0.6533],
    [0.5454, 0.0382, 0.6474], [0.5677, 0.0554, 0.6398], [0.5895, 0.0726, 0.6306],
    [0.6107, 0.0902, 0.6200], [0.6313, 0.1079, 0.6082], [0.6513, 0.1257, 0.5954],
    [0.6706, 0.1436, 0.5817], [0.6892, 0.1616, 0.5675], [0.7073, 0.1795, 0.5528],
    [0.7247, 0.1974, 0.5379], [0.7416, 0.2153, 0.5230], [0.7579, 0.2332, 0.5081],
    [0.7736, 0.2511, 0.4932], [0.7889, 0.2690, 0.4786], [0.8038, 0.2869, 0.4641],
    [0.8182, 0.3049, 0.4498], [0.8322, 0.3229, 0.4357], [0.8457, 0.3410, 0.4217],
    [0.8589, 0.3593, 0.4079], [0.8716, 0.3777, 0.3942], [0.8839, 0.3962, 0.3805],
    [0.8958, 0.4150, 0.3669], [0.9071, 0.4341, 0.3533], [0.9180, 0.4534, 0.3397],
    [0.9284, 0.4729, 0.3261], [0.9382, 0.4929, 0.3124], [0.9473, 0.5132, 0.2987],
    [0.9558, 0.5338, 0.2850], [0.9636, 0.5548, 0.2713], [0.9707, 0.5763, 0.2575],
    [0.9769, 0.5981, 0.2438], [0.9823, 0.6204, 0.2302], [0.9868, 0.6431, 0.2167],
    [0.9903, 0.6662, 0.2034], [0.9929, 0.6898, 0.1906], [0.9943, 0.7138, 0.1785],
    [0.9946, 0.7382, 0.1673], [0.9937, 0.7631, 0.1576], [0.9916, 0.7884, 0.1497],
    [0.9880, 0.8141, 0.1444], [0.9831, 0.8402, 0.1421], [0.9767, 0.8667, 0.1430],
    [0.9689, 0.8936, 0.1468], [0.9596, 0.9207, 0.1515], [0.9491, 0.9481, 0.1544],
    [0.9397, 0.9752, 0.1342],
])

_CIVIDIS = np.array([
    [0.0000, 0.1351, 0.3047], [-0.0000, 0.1471, 0.3307], [0.0001, 0.1583, 0.3581],
    [0.0000, 0.1684, 0.3868], [0.0010, 0.1796, 0.4167], [0.0000, 0.1895, 0.4419],
    [0.0179, 0.1991, 0.4412], [0.0755, 0.2103, 0.4387], [0.1062, 0.2214, 0.4355],
    [0.1338, 0.2326, 0.4325], [0.1570, 0.2438, 0.4298], [0.1783, 0.2549, 0.4275],
    [0.1979, 0.2659, 0.4256], [0.2163, 0.2770, 0.4243], [0.2338, 0.2879, 0.4233],
    [0.2506, 0.2989, 0.4228], [0.2668, 0.3099, 0.4228], [0.2825, 0.3209, 0.4231],
    [0.2979, 0.3319, 0.4239], [0.3130, 0.3429, 0.4251], [0.3277, 0.3539, 0.4266],
    [0.3423, 0.3649, 0.4285], [0.3566, 0.3760, 0.4308], [0.3708, 0.3871, 0.4335],
    [0.3848, 0.3983, 0.4366], [0.3987, 0.4095, 0.4400], [0.4124, 0.4208, 0.4438],
    [0.4261, 0.4321, 0.4480], [0.4396, 0.4435, 0.4527], [0.4530, 0.4550, 0.4581],
    [0.4663, 0.4665, 0.4641], [0.4797, 0.4781, 0.4696], [0.4941, 0.4897, 0.4717],
    [0.5089, 0.5014, 0.4726], [0.5239, 0.5132, 0.4727], [0.5390, 0.5250, 0.4723],
    [0.5543, 0.5370, 0.4713], [0.5697, 0.5490, 0.4697], [0.5852, 0.5611, 0.4678],
    [0.6008, 0.5733, 0.4652], [0.6165, 0.5856, 0.4623], [0.6323, 0.5980, 0.4588],
    [0.6482, 0.6105, 0.4548], [0.6642, 0.6232, 0.4504], [0.6803, 0.6359, 0.4454],
    [0.6965, 0.6488, 0.4399], [0.7129, 0.6618, 0.4338], [0.7293, 0.6749, 0.4271],
    [0.7458, 0.6881, 0.4198], [0.7625, 0.7015, 0.4120], [0.7792, 0.7150, 0.4034],
    [0.7961, 0.7286, 0.3941], [0.8131, 0.7424, 0.3840], [0.8302, 0.7564, 0.3729],
    [0.8474, 0.7704, 0.3611], [0.8648, 0.7847, 0.3480], [0.8823, 0.7991, 0.3339],
    [0.8999, 0.8136, 0.3183], [0.9178, 0.8283, 0.3011], [0.9358, 0.8431, 0.2821],
    [0.9541, 0.8581, 0.2603], [0.9724, 0.8733, 0.2364], [0.9927, 0.8879, 0.2038],
    [0.9964, 0.9091, 0.2156],
])

_TURBO = np.array([
    [0.1901, 0.0718, 0.2327], [0.2090, 0.1186, 0.3482], [0.2255, 0.1647, 0.4541],
    [0.2398, 0.2100, 0.5509], [0.2518, 0.2545, 0.6384], [0.2614, 0.2983, 0.7167],
    [0.2688, 0.3413, 0.7859], [0.2739, 0.3836, 0.8457], [0.2766, 0.4251, 0.8964],
    [0.2771, 0.4659, 0.9378], [0.2754, 0.5059, 0.9701], [0.2707, 0.5452, 0.9926],
    [0.2568, 0.5852, 1.0000], [0.2356, 0.6255, 0.9941], [0.2095, 0.6655, 0.9769],
    [0.1812, 0.7047, 0.9504], [0.1531, 0.7427, 0.9167], [0.1276, 0.7789, 0.8780],
    [0.1073, 0.8129, 0.8364], [0.0947, 0.8441, 0.7939], [0.0921, 0.8721, 0.7524],
    [0.1023, 0.8962, 0.7151], [0.1267, 0.9174, 0.6764], [0.1634, 0.9367, 0.6306],
    [0.2099, 0.9538, 0.5804], [0.2640, 0.9685, 0.5274], [0.3234, 0.9806, 0.4733],
    [0.3856, 0.9899, 0.4200], [0.4485, 0.9962, 0.3690], [0.5096, 0.9992, 0.3223],
    [0.5666, 0.9988, 0.2816], [0.6171, 0.9948, 0.2486], [0.6595, 0.9869, 0.2250],
    [0.7011, 0.9745, 0.2108], [0.7424, 0.9580, 0.2039], [0.7825, 0.9379, 0.2029],
    [0.8209, 0.9145, 0.2061], [0.8569, 0.8884, 0.2118], [0.8899, 0.8598, 0.2186],
    [0.9194, 0.8293, 0.2246], [0.9447, 0.7972, 0.2283], [0.9653, 0.7639, 0.2281],
    [0.9804, 0.7302, 0.2220], [0.9903, 0.6938, 0.2105], [0.9958, 0.6527, 0.1956],
    [0.9970, 0.6084, 0.1779], [0.9943, 0.5617, 0.1583], [0.9878, 0.5139, 0.1376],
    [0.9778, 0.4658, 0.1167], [0.9646, 0.4184, 0.0962], [0.9484, 0.3729, 0.0772],
    [0.9293, 0.3301, 0.0603], [0.9078, 0.2913, 0.0464], [0.8839, 0.2570, 0.0362],
    [0.8571, 0.2249, 0.0275], [0.8272, 0.1944, 0.0202], [0.7943, 0.1658, 0.0142],
    [0.7585, 0.1390, 0.0096], [0.7196, 0.1139, 0.0063], [0.6776, 0.0907, 0.0044],
    [0.6327, 0.0693, 0.0039], [0.5848, 0.0496, 0.0047], [0.5338, 0.0317, 0.0069],
    [0.4798, 0.0157, 0.0105],
])

_JET = np.array([
    [-0.0000, 0.0000, 0.5000], [0.0000, -0.0000, 0.5721], [-0.0000, 0.0000, 0.6443],
    [0.0000, -0.0000, 0.7164], [-0.0000, 0.0000, 0.7886], [0.0000, 0.0000, 0.8606],
    [-0.0000, 0.0003, 0.9335], [0.0000, 0.0000, 1.0000], [-0.0000, 0.0043, 0.9992],
    [0.0000, 0.0724, 1.0000], [-0.0000, 0.1346, 0.9999], [0.0000, 0.1985, 1.0000],
    [-0.0000, 0.2619, 1.0000], [0.0000, 0.3254, 1.0000], [-0.0000, 0.3889, 1.0000],
    [0.0000, 0.4524, 1.0000], [-0.0000, 0.5159, 1.0000], [0.0000, 0.5794, 1.0000],
    [-0.0000, 0.6429, 0.9999], [0.0000, 0.7064, 1.0000], [-0.0000, 0.7698, 0.9990],
    [0.0002, 0.8336, 1.0000], [0.0000, 0.8959, 0.9738], [0.0482, 0.9641, 0.9182],
    [0.1000, 1.0000, 0.8681], [0.1510, 0.9986, 0.8166], [0.2023, 1.0000, 0.7655],
    [0.2535, 0.9999, 0.7143], [0.3047, 1.0000, 0.6631], [0.3559, 1.0000, 0.6119],
    [0.4071, 1.0000, 0.5607], [0.4583, 1.0000, 0.5095], [0.5095, 1.0000, 0.4583],
    [0.5607, 1.0000, 0.4071], [0.6119, 1.0000, 0.3559], [0.6631, 1.0000, 0.3047],
    [0.7143, 1.0000, 0.2535], [0.7655, 0.9999, 0.2023], [0.8166, 1.0000, 0.1510],
    [0.8681, 0.9988, 0.1000], [0.9182, 1.0000, 0.0482], [0.9738, 0.9631, 0.0000],
    [1.0000, 0.9005, 0.0002], [0.9990, 0.8426, -0.0000], [1.0000, 0.7836, 0.0000],
    [0.9999, 0.7249, -0.0000], [1.0000, 0.6661, 0.0000], [1.0000, 0.6073, -0.0000],
    [1.0000, 0.5485, 0.0000], [1.0000, 0.4897, -0.0000], [1.0000, 0.4309, 0.0000],
    [1.0000, 0.3721, -0.0000], [1.0000, 0.3134, 0.0000], [0.9999, 0.2545, -0.0000],
    [1.0000, 0.1959, 0.0000], [0.9992, 0.1366, -0.0000], [1.0000, 0.0797, 0.0000],
    [0.9335, 0.0141, -0.0000], [0.8606, 0.0000, 0.0000], [0.7886, 0.0009, -0.0000],
    [0.7164, 0.0000, 0.0000], [0.6443, 0.0001, -0.0000], [0.5721, -0.0000, 0.0000],
    [0.5000, 0.0000, -0.0000],
])

_HOT = np.array([
    [0.0416, -0.0000, -0.0000], [0.0833, -0.0000, -0.0000], [0.1249, -0.0000, 0.0000],
    [0.1666, 0.0000, 0.0000], [0.2083, 0.0000, 0.0000], [0.2499, 0.0000, -0.0000],
    [0.2916, -0.0000, -0.0000], [0.3333, 0.0000, 0.0000], [0.3750, -0.0000, 0.0000],
    [0.4166, 0.0000, 0.0000], [0.4583, -0.0000, 0.0000], [0.5000, 0.0000, 0.0000],
    [0.5416, -0.0000, 0.0000], [0.5833, 0.0000, 0.0000], [0.6250, -0.0000, 0.0000],
    [0.6666, 0.0000, 0.0000], [0.7083, -0.0000, 0.0000], [0.7500, 0.0000, 0.0000],
    [0.7917, -0.0000, 0.0000], [0.8333, 0.0000, 0.0000], [0.8750, -0.0000, 0.0000],
    [0.9167, 0.0000, 0.0000], [0.9583, -0.0000, -0.0000], [1.0000, 0.0000, -0.0000],
    [1.0000, 0.0417, -0.0000], [1.0000, 0.0833, -0.0000], [1.0000, 0.1250, -0.0000],
    [1.0000, 0.1667, -0.0000], [1.0000, 0.2083, -0.0000], [1.0000, 0.2500, -0.0000],
    [1.0000, 0.2917, -0.0000], [1.0000, 0.3333, -0.0000], [1.0000, 0.3750, 0.0000],
    [1.0000, 0.4167, -0.0000], [1.0000, 0.4583, 0.0000], [1.0000, 0.5000, -0.0000],
    [1.0000, 0.5417, 0.0000], [1.0000, 0.5833, -0.0000], [1.0000, 0.6250, 0.0000],
    [1.0000, 0.6667, -0.0000], [1.0000, 0.7083, 0.0000], [1.0000, 0.7500, -0.0000],
    [1.0000, 0.7917, 0.0000], [1.0000, 0.8333, -0.0000], [1.0000, 0.8750, 0.0000],
    [1.0000, 0.9167, -0.0000], [1.0000, 0.9583, 0.0000], [1.0000, 1.0000, -0.0000],
    [1.0000, 1.0000, 0.0625], [1.0000, 1.0000, 0.1250], [1.0000, 1.0000, 0.1875],
    [1.0000, 1.0000, 0.2500], [1.0000, 1.0000, 0.3125], [1.0000, 1.0000, 0.3750],
    [1.0000, 1.0000, 0.4375], [1.0000, 1.0000, 0.5000], [1.0000, 1.0000, 0.5625],
    [1.0000, 1.0000, 0.6250], [1.0000, 1.0000, 0.6875], [1.0000, 1.0000, 0.7500],
    [1.0000, 1.0000, 0.8125], [1.0000, 1.0000, 0.8750], [1.0000, 1.0000, 0.9375],
    [1.0000, 1.0000, 1.0000],
])

_COOLWARM = np.array([
    [0.2298, 0.2987, 0.7537], [0.2483, 0.3263, 0.7780], [0.2668, 0.3540, 0.8022],
    [0.2859, 0.3811, 0.8243], [0.3051, 0.4082, 0.8463], [0.3249, 0.4347, 0.8659],
    [0.3447, 0.4612, 0.8854], [0.3651, 0.4869, 0.9024], [0.3856, 0.5126, 0.9193],
    [0.4066, 0.5373, 0.9335], [0.4277, 0.5619, 0.9476], [0.4492, 0.5854, 0.9589],
    [0.4707, 0.6088, 0.9699], [0.4926, 0.6310, 0.9782], [0.5144, 0.6529, 0.9862],
    [0.5365, 0.6735, 0.9914], [0.5584, 0.6938, 0.9962], [0.5805, 0.7126, 0.9983],
    [0.6024, 0.7311, 0.9998], [0.6242, 0.7480, 0.9988], [0.6459, 0.7644, 0.9971],
    [0.6673, 0.7793, 0.9931], [0.6885, 0.7935, 0.9882], [0.7093, 0.8061, 0.9811],
    [0.7297, 0.8180, 0.9730], [0.7497, 0.8283, 0.9630], [0.7692, 0.8377, 0.9519],
    [0.7881, 0.8455, 0.9390], [0.8065, 0.8523, 0.9251], [0.8242, 0.8576, 0.9095],
    [0.8412, 0.8614, 0.8927], [0.8573, 0.8649, 0.8748], [0.8735, 0.8621, 0.8544],
    [0.8904, 0.8528, 0.8315], [0.9050, 0.8433, 0.8085], [0.9185, 0.8323, 0.7848],
    [0.9301, 0.8200, 0.7609], [0.9405, 0.8065, 0.7366], [0.9490, 0.7916, 0.7121],
    [0.9563, 0.7759, 0.6873], [0.9617, 0.7586, 0.6624], [0.9660, 0.7405, 0.6374],
    [0.9683, 0.7209, 0.6123], [0.9697, 0.7007, 0.5872], [0.9690, 0.6790, 0.5622],
    [0.9675, 0.6568, 0.5373], [0.9637, 0.6331, 0.5126], [0.9593, 0.6090, 0.4879],
    [0.9526, 0.5834, 0.4637], [0.9454, 0.5575, 0.4395], [0.9359, 0.5302, 0.4159],
    [0.9260, 0.5026, 0.3923], [0.9137, 0.4735, 0.3695], [0.9012, 0.4443, 0.3467],
    [0.8863, 0.4133, 0.3248], [0.8712, 0.3823, 0.3029], [0.8538, 0.3492, 0.2821],
    [0.8364, 0.3161, 0.2612], [0.8167, 0.2799, 0.2414], [0.7969, 0.2438, 0.2217],
    [0.7751, 0.2012, 0.2032], [0.7532, 0.1591, 0.1847], [0.7295, 0.0876, 0.1674],
    [0.7057, 0.0155, 0.1502],
])

_GREY = np.array([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
# the HSV hue sweep from blue (240 degrees) down to red (0) at full saturation and value: HSV is
# piecewise linear in RGB between the 60-degree hues, so these 5 colours give it exactly
_RAINBOW = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 1.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0],
                     [1.0, 0.0, 0.0]])
_BWR = np.array([[0.0, 0.0, 1.0], [1.0, 1.0, 1.0], [1.0, 0.0, 0.0]])

_COLORMAPS = {
    "grey": _GREY, "rainbow": _RAINBOW, "jet": _JET, "turbo": _TURBO, "hot": _HOT, "bwr": _BWR,
    "coolwarm": _COOLWARM, "viridis": _VIRIDIS, "magma": _MAGMA, "inferno": _INFERNO,
    "plasma": _PLASMA, "cividis": _CIVIDIS,
}
for _colors in _COLORMAPS.values():
    _colors.flags.writeable = False

#: The names :func:`colormap` knows ("gray" and "heat" are accepted as aliases of "grey" and
#: "hot"; any name may end in "_r" for the reversed map).
COLORMAP_NAMES = tuple(_COLORMAPS)
