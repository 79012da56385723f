r"""Graphical integrity and good plots (textbook 10.4): the lie factor, the data-ink ratio,
banking to 45 degrees, and the visual variables that suit each kind of data.

* **The lie factor** (Tufte): how much a graphic exaggerates a change,

  .. math:: \text{lie factor} = \frac{\text{size of the effect shown in the graphic}}
                                      {\text{size of the effect in the data}},
            \qquad \text{effect} = \frac{|\text{second} - \text{first}|}{|\text{first}|}.

  1 is honest; Tufte calls values below 0.95 or above 1.05 substantial distortion.
  :func:`lie_factor` computes it from two data values and their two drawn sizes;
  :func:`drawn_sizes` gives the size the eye compares under an encoding (a bar's length from
  a possibly truncated baseline, a circle whose radius or area follows the value, an icon
  scaled in both dimensions, a cube scaled in three, bars in perspective), and
  :func:`encoding_lie_factor` the two together.
* **The data-ink ratio** (Tufte): the share of a graphic's ink that shows data
  (:func:`data_ink_ratio`, :func:`ink_budget`).
* **Banking to 45 degrees** (Cleveland): the aspect ratio of a line chart is chosen so that
  its line segments are, on average, at 45 degrees, where changes of slope are judged best
  (:func:`bank_to_45`, :func:`segment_orientations`).
* **Visual variables** (Bertin): position, size, shape, value (lightness), colour hue,
  orientation and texture, their properties, and how well each shows nominal, ordinal and
  quantitative data, ranked after Mackinlay (:data:`VISUAL_VARIABLES`,
  :func:`visual_variables_for`, :func:`suitability`).

Aspect ratios are height / width of the plot's data rectangle, as in Cleveland's work.
"""
from collections import namedtuple

import numpy as np

from .._validate import as_array, as_choice, as_positive, as_scalar

__all__ = [
    "DATA_LEVELS",
    "ENCODINGS",
    "QUALITIES",
    "VISUAL_VARIABLES",
    "VariableProperties",
    "bank_to_45",
    "data_ink_ratio",
    "drawn_sizes",
    "encoding_lie_factor",
    "ink_budget",
    "lie_factor",
    "relative_change",
    "segment_orientations",
    "suitability",
    "visual_variable_name",
    "visual_variables_for",
]


# ---------------------------------------------------------------------------------------------
# The lie factor
# ---------------------------------------------------------------------------------------------

def _lie_pairs(value, name):
    """`value` as a float array of shape (..., 2): first and second values."""
    v = as_array(value, name)
    if v.ndim == 0 or v.shape[-1] != 2:
        raise ValueError(f"{name} must be a pair (first, second) of numbers, or pairs in the "
                         f"last axis (shape (..., 2)), got shape {v.shape}")
    return v


def relative_change(first, second):
    r"""The size of an effect: the relative change :math:`|\text{second} - \text{first}| /
    |\text{first}|`.

    Parameters
    ----------
    first, second : float or array_like
        The value before and after (broadcast together).

    Returns
    -------
    float or ndarray
        0.25 means a change of 25 %.

    Raises
    ------
    ValueError
        If `first` is 0 (a change relative to nothing has no size), or for non-finite input.

    Examples
    --------
    >>> relative_change(40, 50)
    0.25
    >>> relative_change([10, 8], [5, 10]).tolist()
    [0.5, 0.25]
    """
    a, b = as_array(first, "first"), as_array(second, "second")
    if np.any(a == 0):
        raise ValueError("first must not be 0: a change relative to 0 has no size")
    change = np.abs(b - a) / np.abs(a)
    return float(change) if change.ndim == 0 else change


def lie_factor(data, shown):
    r"""Tufte's lie factor: the effect shown in the graphic over the effect in the data.

    .. math:: L = \frac{|s_2 - s_1| / |s_1|}{|d_2 - d_1| / |d_1|}

    for data values :math:`d_1, d_2` and the sizes :math:`s_1, s_2` that the graphic draws
    for them (the lengths, areas or volumes a reader compares). :math:`L = 1` is honest;
    :math:`L > 1` exaggerates the change, :math:`L < 1` understates it.

    Parameters
    ----------
    data : array_like, shape (2,) or (..., 2)
        The first and the second data value (pairs in the last axis).
    shown : array_like, same shape
        The drawn sizes of the two values.

    Returns
    -------
    float or ndarray

    Raises
    ------
    ValueError
        For shapes that are not pairs or differ, a first value of 0 (data or drawing), or
        data whose two values are equal (no effect to exaggerate).

    Examples
    --------
    >>> lie_factor([40, 50], [10, 20])     # bars on an axis starting at 30: +100 % for +25 %
    4.0
    >>> lie_factor([1, 2], [1, 4])         # circles with radius ~ value: areas 1 and 4
    3.0
    """
    d, s = _lie_pairs(data, "data"), _lie_pairs(shown, "shown")
    if d.shape != s.shape:
        raise ValueError(f"data and shown must have the same shape, got {d.shape} and "
                         f"{s.shape}")
    if np.any(d[..., 0] == 0) or np.any(s[..., 0] == 0):
        raise ValueError("the first value of data and of shown must not be 0: a change "
                         "relative to 0 has no size")
    effect_data = np.abs(d[..., 1] - d[..., 0]) / np.abs(d[..., 0])
    if np.any(effect_data == 0):
        raise ValueError("the two data values are equal: there is no effect, so the lie "
                         "factor (a ratio of effects) is undefined")
    effect_shown = np.abs(s[..., 1] - s[..., 0]) / np.abs(s[..., 0])
    out = effect_shown / effect_data
    return float(out) if out.ndim == 0 else out


#: The encodings of :func:`drawn_sizes` and what the eye compares in each.
ENCODINGS = {
    "bar": "the length of a bar drawn from the axis' baseline (truncated if the baseline "
           "is not 0)",
    "area": "the area of a circle (or square) whose area is proportional to the value: "
            "honest",
    "radius": "the area of a circle whose radius is proportional to the value",
    "icon": "the area of a picture scaled in both dimensions by the value",
    "volume": "the volume of a cube (a 3D icon) scaled in all three dimensions by the value",
    "perspective": "the drawn height of 3D bars seen in perspective, the later bars nearer "
                   "the viewer (bar k at distance 1 + recession (n - 1 - k))",
}


def drawn_sizes(values, encoding, baseline=0.0, recession=0.5):
    r"""The size the eye compares for each value when drawn with an encoding.

    * ``"bar"``: the length :math:`v - b` above the baseline :math:`b`;
    * ``"area"``: :math:`v` (area proportional to the value);
    * ``"radius"``, ``"icon"``: :math:`v^2` (radius or side proportional to the value, so the
      area grows with its square; the constant :math:`\pi` cancels in the lie factor);
    * ``"volume"``: :math:`v^3`;
    * ``"perspective"``: :math:`(v - b) / (1 + r\,(n - 1 - k))` for the :math:`k`-th of
      :math:`n` bars, the last one nearest the viewer (distance 1), each one before it
      :math:`r` further away; a drawn length shrinks with the distance.

    Parameters
    ----------
    values : array_like, shape (n,)
        The data values, in the order drawn.
    encoding : str
        One of :data:`ENCODINGS`.
    baseline : float
        Where the bars start (``"bar"`` and ``"perspective"``); every value must be at or
        above it.
    recession : float
        The extra distance of each earlier bar (``"perspective"``), >= 0.

    Returns
    -------
    ndarray, shape (n,)

    Raises
    ------
    ValueError
        For an unknown encoding, values below the baseline, negative values for the area
        encodings, or a negative recession.

    Examples
    --------
    >>> drawn_sizes([40, 50], "bar", baseline=30).tolist()
    [10.0, 20.0]
    >>> drawn_sizes([1, 2, 3], "icon").tolist()
    [1.0, 4.0, 9.0]
    >>> drawn_sizes([10, 10], "perspective", recession=1.0).tolist()
    [5.0, 10.0]
    """
    v = as_array(values, "values")
    if v.ndim != 1 or v.size == 0:
        raise ValueError(f"values must be a non-empty 1D array, got shape {v.shape}")
    as_choice(encoding, "encoding", tuple(ENCODINGS))
    b = as_scalar(baseline, "baseline")
    if encoding in ("bar", "perspective"):
        if np.any(v < b):
            raise ValueError(f"every value must be at or above the baseline {b:g} to be "
                             f"drawn as a bar from it, got the minimum {v.min():g}")
        length = v - b
        if encoding == "bar":
            return length
        r = as_scalar(recession, "recession")
        if r < 0:
            raise ValueError(f"recession must be >= 0, got {r:g}")
        distance = 1.0 + r * (v.size - 1 - np.arange(v.size))
        return length / distance
    if np.any(v < 0):
        raise ValueError(f"values must be >= 0 for the encoding {encoding!r} (a size cannot "
                         f"be negative), got the minimum {v.min():g}")
    power = {"area": 1, "radius": 2, "icon": 2, "volume": 3}[encoding]
    return v ** power


def encoding_lie_factor(values, encoding, baseline=0.0, recession=0.5):
    """The lie factor of an encoding between the first and the last value of `values`.

    :func:`lie_factor` of the data ``(values[0], values[-1])`` and the sizes
    :func:`drawn_sizes` draws for them.

    Parameters
    ----------
    values : array_like, shape (n,), n >= 2
    encoding, baseline, recession
        As for :func:`drawn_sizes`.

    Returns
    -------
    float

    Examples
    --------
    >>> encoding_lie_factor([40, 45, 50], "bar", baseline=30)      # 40 / (40 - 30)
    4.0
    >>> encoding_lie_factor([2, 3], "radius")                      # (1 + e)^2 - 1 over e
    2.5
    >>> encoding_lie_factor([2, 3], "area")
    1.0
    """
    v = as_array(values, "values")
    if v.ndim != 1 or v.size < 2:
        raise ValueError(f"values must be a 1D array of at least 2 values, got shape {v.shape}")
    sizes = drawn_sizes(v, encoding, baseline, recession)
    return lie_factor([v[0], v[-1]], [sizes[0], sizes[-1]])


# ---------------------------------------------------------------------------------------------
# The data-ink ratio
# ---------------------------------------------------------------------------------------------

def _ink_amount(value, name):
    """An amount of ink: a count of set pixels of a mask, or a non-negative number."""
    arr = np.asarray(value)
    if arr.dtype == bool:
        return float(np.count_nonzero(arr)), arr
    amount = as_scalar(value, name)
    if amount < 0:
        raise ValueError(f"{name} must be >= 0 (an amount of ink), got {amount:g}")
    return amount, None


def data_ink_ratio(data_ink, total_ink):
    r"""Tufte's data-ink ratio: the share of the ink of a graphic that shows the data.

    .. math:: \text{data-ink ratio} = \frac{\text{data ink}}{\text{total ink}}
              = 1 - \text{the share that could be erased without losing data}.

    Ink can be given as amounts (pixel counts, element counts, areas) or as boolean masks of
    a rasterised chart (True where that ink is), whose set pixels are counted.

    Parameters
    ----------
    data_ink : float or array_like of bool
        The ink that encodes data (bars, points, the data line).
    total_ink : float or array_like of bool
        All the ink of the graphic (data ink included): frame, grid, labels, fills,
        decoration.

    Returns
    -------
    float
        In [0, 1].

    Raises
    ------
    ValueError
        For negative amounts, no ink at all, more data ink than total ink, or masks of
        different shapes or with data pixels outside the total.

    Examples
    --------
    >>> data_ink_ratio(300, 1200)
    0.25
    >>> total = np.array([True, True, True, True, False])     # masks of 5 pixels
    >>> data_ink_ratio(np.array([True, True, True, False, False]), total)
    0.75
    """
    d, d_mask = _ink_amount(data_ink, "data_ink")
    t, t_mask = _ink_amount(total_ink, "total_ink")
    if (d_mask is None) != (t_mask is None):
        raise TypeError("data_ink and total_ink must both be amounts or both be boolean masks")
    if d_mask is not None:
        if d_mask.shape != t_mask.shape:
            raise ValueError(f"the masks must have the same shape, got {d_mask.shape} and "
                             f"{t_mask.shape}")
        if np.any(d_mask & ~t_mask):
            raise ValueError("data_ink has pixels outside total_ink: the total includes the "
                             "data ink")
    if t == 0:
        raise ValueError("total_ink is 0: a graphic without ink has no data-ink ratio")
    if d > t:
        raise ValueError(f"data_ink ({d:g}) cannot exceed total_ink ({t:g}): the total "
                         "includes the data ink")
    return d / t


def ink_budget(elements):
    """The ink of a chart's elements summed: data ink, non-data ink, the ratio, what to erase.

    Parameters
    ----------
    elements : dict
        Element name -> ``(ink, is_data)``: its amount of ink (>= 0) and whether it encodes
        data.

    Returns
    -------
    dict
        ``"data"``, ``"non_data"``, ``"total"``, ``"ratio"`` (:func:`data_ink_ratio`) and
        ``"erasable"``: the non-data elements, most ink first (ties by name).

    Raises
    ------
    ValueError, TypeError
        For an element that is not a pair (ink, is_data), negative ink, or no ink at all.

    Examples
    --------
    >>> b = ink_budget({"bars": (300, True), "grid": (500, False), "frame": (200, False)})
    >>> b["ratio"], b["erasable"]
    (0.3, ['grid', 'frame'])
    """
    if not isinstance(elements, dict) or not elements:
        raise TypeError("elements must be a non-empty dict: name -> (ink, is_data)")
    data = other = 0.0
    erasable = []
    for name, entry in elements.items():
        if not isinstance(entry, (tuple, list)) or len(entry) != 2 \
                or not isinstance(entry[1], (bool, np.bool_)):
            raise TypeError(f"elements[{name!r}] must be a pair (ink, is_data) with is_data "
                            f"True or False, got {entry!r}")
        ink = _ink_amount(entry[0], f"the ink of {name!r}")[0]
        if entry[1]:
            data += ink
        else:
            other += ink
            erasable.append((-ink, str(name)))
    return {"data": data, "non_data": other, "total": data + other,
            "ratio": data_ink_ratio(data, data + other),
            "erasable": [name for _, name in sorted(erasable)]}


# ---------------------------------------------------------------------------------------------
# Banking to 45 degrees
# ---------------------------------------------------------------------------------------------

def _polyline_slopes(x, y):
    """The absolute slopes of the segments in a unit square of the data ranges (inf for
    vertical ones); segments of length 0 are dropped."""
    x, y = as_array(x, "x"), as_array(y, "y")
    if x.ndim != 1 or x.shape != y.shape or x.size < 2:
        raise ValueError(f"x and y must be 1D arrays of the same length >= 2, got shapes "
                         f"{x.shape} and {y.shape}")
    rx, ry = np.ptp(x), np.ptp(y)
    if rx == 0 or ry == 0:
        raise ValueError("x and y must each vary: a line with no horizontal or no vertical "
                         "extent has no aspect ratio to choose")
    dx, dy = np.abs(np.diff(x)) / rx, np.abs(np.diff(y)) / ry
    keep = (dx > 0) | (dy > 0)
    dx, dy = dx[keep], dy[keep]
    with np.errstate(divide="ignore"):
        return np.where(dx > 0, dy / np.where(dx > 0, dx, 1.0), np.inf)


def segment_orientations(x, y, aspect):
    r"""The absolute orientations on screen of the segments of a polyline, in radians.

    The data rectangle (the ranges of x and y) is drawn `aspect` times as high as it is wide,
    so a segment of slope :math:`s_i = (\Delta y_i / R_y) / (\Delta x_i / R_x)` in the unit
    square appears at the angle :math:`\theta_i = \arctan(\alpha\,|s_i|)`.

    Parameters
    ----------
    x, y : array_like, shape (n,)
        The vertices, n >= 2; segments of length 0 are ignored.
    aspect : float
        Height / width of the plot (> 0).

    Returns
    -------
    ndarray
        Angles in :math:`[0, \pi/2]`, one per segment.

    Examples
    --------
    >>> np.degrees(segment_orientations([0, 1, 2], [0, 2, 1], 1.0)).round(2).tolist()
    [63.43, 45.0]
    >>> np.degrees(segment_orientations([0, 1, 2], [0, 2, 1], 0.5)).round(2).tolist()
    [45.0, 26.57]
    """
    alpha = as_positive(aspect, "aspect", "height / width of the plot")
    s = _polyline_slopes(x, y)
    return np.arctan(alpha * s)


_BANKING = ("average", "median")


def bank_to_45(x, y, method="average"):
    r"""The aspect ratio (height / width) that banks a line chart to 45 degrees (Cleveland).

    Slopes are judged best near 45 degrees: a chart too flat hides rises and falls, one too
    tall makes every segment look equally steep. With the slopes :math:`s_i` of the segments
    in the unit square of the data ranges (see :func:`segment_orientations`):

    * ``"median"``: the median absolute slope on screen is 1,
      :math:`\alpha = 1 / \operatorname{median}_i |s_i|` (closed form);
    * ``"average"``: the average absolute orientation is 45 degrees,
      :math:`\frac{1}{n} \sum_i \arctan(\alpha |s_i|) = \pi/4`, solved numerically (the left
      side grows with :math:`\alpha`; Newton's method on :math:`\ln \alpha`, safeguarded by
      bisection). Steep and flat segments both count, not only the middle one.

    Parameters
    ----------
    x, y : array_like, shape (n,)
        The polyline, n >= 2.
    method : {"average", "median"}

    Returns
    -------
    float
        The aspect ratio :math:`\alpha` = height / width of the data rectangle.

    Raises
    ------
    ValueError
        When no aspect ratio reaches 45 degrees: with the median, if half or more of the
        segments are flat or vertical; with the average, if half or more are flat, or half
        or more vertical.

    Examples
    --------
    >>> x = [0, 1, 2, 3]
    >>> bank_to_45(x, [0, 3, 1, 2], "median")       # slopes 3, 2, 1 in the unit square
    0.5
    >>> a = bank_to_45(x, [0, 3, 1, 2])
    >>> round(float(np.degrees(segment_orientations(x, [0, 3, 1, 2], a).mean())), 9)
    45.0
    """
    as_choice(method, "method", _BANKING)
    s = _polyline_slopes(x, y)
    n = s.size
    flat, steep = np.count_nonzero(s == 0), np.count_nonzero(np.isinf(s))
    if method == "median":
        m = float(np.median(s))
        if m == 0 or np.isinf(m):
            raise ValueError("the median slope is " + ("0" if m == 0 else "infinite")
                             + ": half or more of the segments are "
                             + ("flat" if m == 0 else "vertical")
                             + ", so no aspect ratio gives them 45 degrees")
        return 1.0 / m
    if 2 * flat >= n or 2 * steep >= n:
        raise ValueError("half or more of the segments are " + ("flat" if 2 * flat >= n
                                                                 else "vertical")
                         + ": their average orientation cannot reach 45 degrees at any "
                           "aspect ratio")
    finite = s[np.isfinite(s) & (s > 0)]
    target = n * np.pi / 4 - steep * np.pi / 2

    def excess(u):
        t = np.exp(u) * finite
        return float(np.arctan(t).sum() - target), float((t / (1 + t * t)).sum())

    # a bracket in ln(alpha): at alpha = 1 / max s every term < pi/4, at 1 / min s every > pi/4
    lo, hi = -np.log(finite.max()) - 1.0, -np.log(finite.min()) + 1.0
    while excess(lo)[0] > 0:
        lo -= 10.0
    while excess(hi)[0] < 0:
        hi += 10.0
    u = float(np.clip(-np.log(np.median(finite)), lo, hi))
    for _ in range(100):
        value, slope = excess(u)
        if value > 0:
            hi = u
        else:
            lo = u
        step = value / slope if slope > 0 else np.inf
        if abs(step) <= 1e-13 * max(1.0, abs(u)):       # converged (Newton's last step)
            u -= step
            break
        nxt = u - step
        if not lo < nxt < hi:                             # outside the bracket: bisect
            nxt = 0.5 * (lo + hi)
        if hi - lo < 1e-15 * max(1.0, abs(u)):
            u = nxt
            break
        u = nxt
    return float(np.exp(u))


# ---------------------------------------------------------------------------------------------
# Visual variables (Bertin) and the data they suit (after Mackinlay)
# ---------------------------------------------------------------------------------------------

#: The levels of measurement a visual variable is judged for. (Interval and ratio data are
#: both quantitative here.)
DATA_LEVELS = ("nominal", "ordinal", "quantitative")
#: How well a variable shows a level of data, best first.
QUALITIES = ("best", "good", "fair", "poor", "misleading")


class VariableProperties(namedtuple("VariableProperties",
                                    "selective associative ordered quantitative steps")):
    """Bertin's properties of a visual variable.

    ``selective``: the marks of one value can be picked out at a glance; ``associative``: the
    marks of one value group together without the variable dominating others; ``ordered``:
    its values are seen in an order; ``quantitative``: ratios of values can be read;
    ``steps``: about how many values can be told apart.

    Examples
    --------
    >>> VISUAL_VARIABLES["colour hue"].ordered
    False
    """

    __slots__ = ()


#: Bertin's seven visual variables and their properties (steps: a rough usable number).
VISUAL_VARIABLES = {
    "position": VariableProperties(True, True, True, True, "many"),
    "size": VariableProperties(True, False, True, True, "about 5-20"),
    "shape": VariableProperties(False, True, False, False, "many, but slow to search"),
    "value": VariableProperties(True, False, True, False, "about 7-10"),
    "colour hue": VariableProperties(True, True, False, False, "about 7-10"),
    "orientation": VariableProperties(True, True, False, False, "about 4"),
    "texture": VariableProperties(True, True, True, False, "about 5"),
}

#: level -> variable -> (quality, why), the rows ordered best first.
_SUITABILITY = {
    "quantitative": {
        "position": ("best", "positions on a common scale are read most accurately of all "
                             "encodings (Cleveland and McGill), and differences and ratios "
                             "both show"),
        "size": ("good", "a length shows order and ratios; areas and volumes are judged less "
                         "accurately (underestimated), so scale the area, not the radius, "
                         "with the value"),
        "orientation": ("fair", "angles and slopes can carry a magnitude over a small range "
                                "(up to 90 degrees), but are read with bias"),
        "value": ("poor", "lightness shows which is more, but no ratios, and a patch looks "
                          "lighter or darker depending on its surroundings"),
        "texture": ("poor", "the density of a pattern gives a coarse order, no amounts"),
        "colour hue": ("misleading", "hue has no perceived order: a rainbow of hues makes "
                                     "readers guess the order and see bands that the data do "
                                     "not have"),
        "shape": ("misleading", "shapes have no order and no magnitude: the reader cannot tell "
                                "which is larger, let alone by how much"),
    },
    "ordinal": {
        "position": ("best", "an order along an axis is read at once and exactly, even for "
                             "many ranks"),
        "value": ("good", "lightness has a natural order everyone reads the same way, light to "
                          "dark, and survives a grey print"),
        "size": ("fair", "sizes are ordered, but they also suggest amounts and ratios that "
                         "ordinal data do not have"),
        "texture": ("fair", "a pattern from sparse to dense is ordered, if coarsely"),
        "orientation": ("poor", "directions are told apart, but which comes first is not "
                                "obvious"),
        "colour hue": ("misleading", "hues have no agreed order: low, medium and high in red, "
                                     "green and blue must be looked up in the legend"),
        "shape": ("misleading", "shapes have no order: the ranking disappears"),
    },
    "nominal": {
        "position": ("best", "separate regions (groups along an axis, small multiples) show "
                             "categories most clearly"),
        "colour hue": ("good", "distinct hues separate categories at a glance without "
                               "implying an order (up to about 8-10 of them)"),
        "shape": ("good", "distinct shapes name categories without implying an order, though "
                          "they are slower to pick out than hues"),
        "texture": ("fair", "distinct patterns (dots, hatching) separate a few categories, "
                            "e.g. in a grey print"),
        "orientation": ("fair", "a few directions (about 4) separate categories"),
        "value": ("misleading", "lightness implies an order: the darker category looks like "
                                "more, which categories do not have"),
        "size": ("misleading", "size implies an order and amounts: the bigger category looks "
                               "more important"),
    },
}

_LEVEL_ALIASES = {"categorical": "nominal", "interval": "quantitative",
                  "ratio": "quantitative", "numerical": "quantitative",
                  "numeric": "quantitative", "ordered": "ordinal"}
_VARIABLE_ALIASES = {"color hue": "colour hue", "hue": "colour hue", "colour": "colour hue",
                     "color": "colour hue", "lightness": "value", "brightness": "value",
                     "length": "size", "area": "size", "angle": "orientation",
                     "grain": "texture", "pattern": "texture"}


def _visual_level(level):
    if not isinstance(level, str):
        raise TypeError(f"level must be a string, got {type(level).__name__}")
    key = " ".join(level.strip().lower().split())
    key = _LEVEL_ALIASES.get(key, key)
    return key if key in DATA_LEVELS else as_choice(level, "level", DATA_LEVELS)


def visual_variable_name(variable):
    """The name of Bertin's visual variable that a typed name stands for (case, spaces and
    common other names forgiven: ``"hue"``, ``"lightness"``, ``"length"``, ``"angle"``...).

    Parameters
    ----------
    variable : str

    Returns
    -------
    str
        One of :data:`VISUAL_VARIABLES`.

    Raises
    ------
    TypeError, ValueError
        For a value that is no string, or names no visual variable (the message lists them).

    Examples
    --------
    >>> visual_variable_name(" Color "), visual_variable_name("lightness")
    ('colour hue', 'value')
    """
    if not isinstance(variable, str):
        raise TypeError(f"variable must be a string, got {type(variable).__name__}")
    key = " ".join(variable.strip().lower().split())
    key = _VARIABLE_ALIASES.get(key, key)
    return key if key in VISUAL_VARIABLES else as_choice(variable, "variable",
                                                         tuple(VISUAL_VARIABLES))


def visual_variables_for(level):
    """Bertin's visual variables ranked for a level of data, best first, with the reasons.

    The ranking follows Mackinlay's (1986) where his encodings map onto Bertin's variables
    (length and area onto size, density onto value, angle and slope onto orientation), and
    Bertin's properties where they settle a question: a variable without an order misleads
    for ordered data, an ordered one for categories.

    Parameters
    ----------
    level : str
        ``"nominal"``, ``"ordinal"`` or ``"quantitative"`` (also ``"categorical"``,
        ``"interval"``, ``"ratio"``).

    Returns
    -------
    list of (str, str, str)
        ``(variable, quality, why)``; the quality is one of :data:`QUALITIES`.

    Raises
    ------
    ValueError
        For an unknown level; the message lists the levels.

    Examples
    --------
    >>> [v for v, q, _ in visual_variables_for("quantitative")][:3]
    ['position', 'size', 'orientation']
    >>> [v for v, q, _ in visual_variables_for("categorical") if q == "misleading"]
    ['value', 'size']
    """
    table = _SUITABILITY[_visual_level(level)]
    return [(variable, quality, why) for variable, (quality, why) in table.items()]


def suitability(variable, level):
    """How well a visual variable shows a level of data, and why.

    Parameters
    ----------
    variable : str
        One of :data:`VISUAL_VARIABLES` (also ``"hue"``, ``"lightness"``, ``"length"``...).
    level : str
        As for :func:`visual_variables_for`.

    Returns
    -------
    (str, str)
        The quality (one of :data:`QUALITIES`) and the reason.

    Raises
    ------
    ValueError
        For an unknown variable or level.

    Examples
    --------
    >>> suitability("hue", "ordinal")[0]
    'misleading'
    >>> suitability("lightness", "ordinal")[0]
    'good'
    """
    return _SUITABILITY[_visual_level(level)][visual_variable_name(variable)]
