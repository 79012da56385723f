"""Chapter 10 (lesson sections 3, 6): transfer functions from data values to colour and opacity,
and applying a colour map with an opacity to data.
"""

import numpy as np

from .._validate import as_array, as_choice, as_scalar, as_whole
from ._common import _data_allowing_nan, _range, _unit_interval
from .maps import colormap, _lookup
from .normalisation import normalize

__all__ = ["TransferFunction", "apply_colormap", "color_transfer", "opacity_transfer",
    "rgba_transfer", "transfer_preset"]


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
        as_choice(kind, "kind", ("linear", "step"))
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
        n = as_whole(n, "n", 2)
        lo, hi = (self.points[0], self.points[-1]) if in_range is None else \
            _range(in_range, "in_range", ordered=True)
        return self(np.linspace(lo, hi, n))

    def __repr__(self):
        return (f"TransferFunction(points={self.points.tolist()}, values={self.values.tolist()}, "
                f"kind={self.kind!r})")


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
    as_choice(name, "name", sorted(_PRESETS))
    lo, hi = _range(in_range, "in_range", ordered=True)
    if hi == lo:
        raise ValueError("in_range must have low < high")
    points, colors, alphas = _PRESETS[name]
    values = np.concatenate([np.array(colors), np.array(alphas)[:, None]], axis=1)
    return TransferFunction(lo + (hi - lo) * np.array(points), values)


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
