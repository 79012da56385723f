r"""Multidimensional data (textbook 10.7): example tables, parallel coordinates and their
point-line duality, scatterplot matrices, brushing, star glyphs and Chernoff faces.

A table of records is an ``(n, d)`` array (one row per record, one column per attribute) with
a tuple of ``d`` names beside it (:class:`Table`). Projection by principal components is in
:mod:`course_lib.dataviz.projection`.

**Parallel coordinates.** The ``d`` attributes become ``d`` vertical axes at ``x = 0, 1, ...,
d - 1`` (in the chosen order); each axis spans its attribute's own range, normalised to
``[0, 1]`` (flipped: ``1 - y``), and a record is the polyline through its ``d`` values.

**The point-line duality.** Between two adjacent axes at ``u = 0`` (attribute x) and ``u = 1``
(attribute y), the record ``(a, b)`` with normalised values ``a'``, ``b'`` is the segment of
the line ``v = a' + (b' - a') u``. For the points of a line ``y = m x + c`` the normalised
values obey ``b' = m' a' + c'`` with

.. math:: m' = m\,\frac{x_{max} - x_{min}}{y_{max} - y_{min}}, \qquad
          c' = \frac{m\,x_{min} + c - y_{min}}{y_{max} - y_{min}},

so every one of their lines passes through ``v = a' (1 + (m' - 1) u) + c' u``: at
``u = 1 / (1 - m')`` the term with ``a'`` vanishes, and all the lines meet at the one point

.. math:: \left(\frac{1}{1 - m'},\; \frac{c'}{1 - m'}\right) \qquad (m' \ne 1).

A negative ``m'`` puts the crossing between the axes (``0 < u < 1``); ``0 < m' < 1`` right of
the second axis, ``m' > 1`` left of the first; ``m' = 1`` gives parallel lines (the point is
at infinity).

Brushing: a brush is a range on one attribute (or a rectangle, a range on two); a record is
selected by a brush when all its ranges hold (bounds included), and brushes combine with AND
or OR into one boolean mask over the records.
"""
import numbers
from typing import NamedTuple

import numpy as np

from .._validate import as_choice, as_rng, as_scalar, as_whole
from ..colormaps import normalize

__all__ = ["CHERNOFF_FEATURES", "GALLERY", "PolylineRaster", "Table", "attribute_index",
           "brush_mask", "cars_table", "chernoff_face", "chernoff_parameters", "column_ranges",
           "combine_brushes", "correlation_gallery", "dual_line", "dual_point",
           "normalise_columns", "normalised_slope", "parallel_coordinates", "range_brush",
           "rasterize_polylines", "rectangle_brush", "scatterplot_matrix", "star_glyph",
           "weather_table"]


class Table(NamedTuple):
    """A table of records: the ``(n, d)`` values and the ``d`` attribute names.

    Examples
    --------
    >>> data, names = Table(np.zeros((3, 2)), ("x", "y"))
    >>> data.shape, names
    ((3, 2), ('x', 'y'))
    """

    data: np.ndarray
    names: tuple


# ---------------------------------------------------------------------------------------------
# Checks
# ---------------------------------------------------------------------------------------------

def _records(data, name="data", min_columns=1):
    """`data` as a float (n, d) table with n >= 1, d >= `min_columns`, no NaN, no infinity."""
    if isinstance(data, (str, bytes)) or data is None or data is Ellipsis:
        raise TypeError(f"{name} must be a table of numbers (n records x d attributes), "
                        f"got {type(data).__name__}")
    try:
        table = np.asarray(data, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a table of numbers (rows of equal length), got "
                        f"{type(data).__name__}") from None
    if table.ndim != 2 or table.shape[0] < 1 or table.shape[1] < min_columns:
        raise ValueError(f"{name} must be a 2D table with at least one record and "
                         f"{min_columns} attribute(s), shape (n, d); got shape {table.shape}")
    bad = ~np.isfinite(table)
    if bad.any():
        row, col = (int(i) for i in np.argwhere(bad)[0])
        what = "NaN (a missing value)" if np.isnan(table[row, col]) else "infinite"
        raise ValueError(f"{name} is {what} at record {row}, attribute {col} ({bad.sum()} "
                         "such entries): drop or fill incomplete records first")
    return table


def attribute_index(axis, d, names=None):
    """The column index of attribute `axis`: a whole number in ``0 .. d-1`` or a name.

    Parameters
    ----------
    axis : int or str
    d : int
        The number of attributes.
    names : sequence of str, optional
        The attribute names (needed to look a name up).

    Returns
    -------
    int

    Raises
    ------
    ValueError
        For a name that is not an attribute or an index out of range.
    TypeError
        For anything else (a bool, a float).

    Examples
    --------
    >>> attribute_index("weight", 3, ("mpg", "weight", "year")), attribute_index(2, 3)
    (1, 2)
    >>> attribute_index("wieght", 3, ("mpg", "weight", "year"))
    Traceback (most recent call last):
    ...
    ValueError: axis 'wieght' is not an attribute; the attributes are 'mpg', 'weight', 'year'
    """
    if isinstance(axis, str):
        known = tuple(names) if names is not None else ()
        if axis not in known:
            listed = ", ".join(map(repr, known)) if known else "unnamed (give an index)"
            raise ValueError(f"axis {axis!r} is not an attribute; the attributes are {listed}")
        return known.index(axis)
    if isinstance(axis, (bool, np.bool_)) or not isinstance(axis, numbers.Integral):
        raise TypeError(f"axis must be an attribute name or a whole-number index, got {axis!r}")
    if not 0 <= int(axis) < d:
        raise ValueError(f"axis {int(axis)} is out of range: the table has {d} attributes "
                         f"(indices 0 to {d - 1})")
    return int(axis)


def _brush_interval(value, name):
    """A brush range (low, high), finite, low < high."""
    try:
        low, high = (float(v) for v in value)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair of numbers (low, high), got {value!r}") from None
    if not (np.isfinite(low) and np.isfinite(high)):
        raise ValueError(f"{name} must be finite, got ({low:g}, {high:g})")
    if low > high:
        raise ValueError(f"{name} is reversed: low {low:g} > high {high:g}; give it as "
                         "(low, high)")
    if low == high:
        raise ValueError(f"{name} is empty: low = high = {low:g}; a brush needs low < high")
    return low, high


def _ranges_for(table, ranges):
    """Per-attribute (low, high), shape (d, 2): the table's own or the given ones."""
    d = table.shape[1]
    if ranges is None:
        return column_ranges(table)
    r = np.asarray(ranges, dtype=float)
    if r.shape != (d, 2) or not np.isfinite(r).all() or (r[:, 0] > r[:, 1]).any():
        raise ValueError(f"ranges must be {d} finite pairs (low, high) with low <= high, "
                         f"shape ({d}, 2); got {np.asarray(ranges).shape}")
    return r


# ---------------------------------------------------------------------------------------------
# Example data (generated, seeded)
# ---------------------------------------------------------------------------------------------

#: The relations of the correlation gallery.
GALLERY = ("positive", "negative", "none", "clusters", "non-linear")


def correlation_gallery(n=200, seed=0):
    """Five two-attribute tables showing typical relations between x and y.

    ``positive`` (correlation about 0.9), ``negative`` (about -0.9), ``none`` (independent),
    ``clusters`` (three groups) and ``non-linear`` (y = x^2 plus noise: a strong relation with
    a correlation near 0).

    Parameters
    ----------
    n : int
        Records per table (at least 3).
    seed : int or numpy.random.Generator

    Returns
    -------
    dict
        Name (:data:`GALLERY`) -> :class:`Table` with names ``("x", "y")``.

    Examples
    --------
    >>> gallery = correlation_gallery(500)
    >>> r = {k: np.corrcoef(t.data.T)[0, 1] for k, t in gallery.items()}
    >>> bool(r["positive"] > 0.8), bool(r["negative"] < -0.8), bool(abs(r["non-linear"]) < 0.2)
    (True, True, True)
    """
    n = as_whole(n, "n", 3)
    rng = as_rng(seed)
    x = rng.normal(size=n)
    e = rng.normal(size=n)
    centres = np.array([[-2.0, -1.0], [0.5, 2.0], [2.5, -0.5]])
    group = np.arange(n) % 3
    u = rng.uniform(-1, 1, size=n)
    tables = {
        "positive": np.column_stack([x, 0.9 * x + 0.4 * e]),
        "negative": np.column_stack([x, -0.9 * x + 0.4 * e]),
        "none": np.column_stack([x, e]),
        "clusters": centres[group] + 0.45 * rng.normal(size=(n, 2)),
        "non-linear": np.column_stack([u, u * u + 0.06 * e]),
    }
    return {k: Table(v, ("x", "y")) for k, v in tables.items()}


def cars_table(n=150, seed=0):
    """A generated table of cars with six named attributes, in the spirit of the classic data.

    Attributes: ``mpg`` (miles per gallon), ``cylinders`` (4, 6 or 8), ``horsepower``,
    ``weight`` (kg), ``acceleration`` (seconds from 0 to 100 km/h) and ``year`` (70-82).
    Heavier cars have more cylinders and horsepower and a lower mpg; more horsepower means
    faster acceleration (fewer seconds); later years a higher mpg.

    Parameters
    ----------
    n : int
        Number of cars (at least 3).
    seed : int or numpy.random.Generator

    Returns
    -------
    Table

    Examples
    --------
    >>> cars = cars_table()
    >>> cars.data.shape, cars.names[:3]
    ((150, 6), ('mpg', 'cylinders', 'horsepower'))
    >>> r = np.corrcoef(cars.data.T)
    >>> bool(r[0, 3] < -0.7), bool(r[2, 3] > 0.7), bool(r[2, 4] < -0.5)
    (True, True, True)
    """
    n = as_whole(n, "n", 3)
    rng = as_rng(seed)
    cylinders = rng.choice([4.0, 6.0, 8.0], size=n, p=[0.5, 0.25, 0.25])
    year = rng.integers(70, 83, size=n).astype(float)
    weight = np.round(700 + 150 * cylinders + rng.normal(0, 110, n), -1)
    horsepower = np.round(0.06 * weight + 9 * cylinders - 25 + rng.normal(0, 9, n))
    mpg = np.round(np.clip(58 - 0.018 * weight - 0.07 * horsepower + 0.55 * (year - 76)
                           + rng.normal(0, 2.0, n), 9, None), 1)
    acceleration = np.round(24 - 0.055 * horsepower + rng.normal(0, 1.0, n), 1)
    data = np.column_stack([mpg, cylinders, horsepower, weight, acceleration, year])
    return Table(data, ("mpg", "cylinders", "horsepower", "weight", "acceleration", "year"))


def weather_table(n=10_000, seed=0):
    """A large generated table: daily weather of a station in three regimes (dry and hot,
    mild and wet, cold), five attributes.

    Attributes: ``temperature`` (°C), ``humidity`` (%), ``pressure`` (hPa), ``wind`` (m/s),
    ``rain`` (mm, never negative). Within the data humidity and rain rise together, and
    pressure falls as wind and rain rise.

    Parameters
    ----------
    n : int
        Number of days (at least 3).
    seed : int or numpy.random.Generator

    Returns
    -------
    Table

    Examples
    --------
    >>> t = weather_table(3000)
    >>> t.data.shape, t.names[-1], bool(t.data[:, 4].min() >= 0)
    ((3000, 5), 'rain', True)
    """
    n = as_whole(n, "n", 3)
    rng = as_rng(seed)
    regime = rng.choice(3, size=n, p=[0.35, 0.4, 0.25])
    means = np.array([[27.0, 35.0, 1020.0, 3.0], [15.0, 75.0, 1005.0, 6.0],
                      [-2.0, 60.0, 1015.0, 4.5]])
    spread = np.array([[3.0, 8.0, 4.0, 1.5], [3.0, 9.0, 6.0, 2.5], [3.5, 10.0, 5.0, 2.0]])
    base = means[regime] + spread[regime] * rng.normal(size=(n, 4))
    base[:, 1] = np.clip(base[:, 1], 5, 100)
    base[:, 3] = np.abs(base[:, 3])
    wet = (base[:, 1] - 55) / 10 + (1010 - base[:, 2]) / 8
    rain = np.round(np.clip(4 * wet + rng.normal(0, 2, n), 0, None), 1)
    data = np.column_stack([np.round(base, 1), rain])
    return Table(data, ("temperature", "humidity", "pressure", "wind", "rain"))


# ---------------------------------------------------------------------------------------------
# Parallel coordinates and the duality
# ---------------------------------------------------------------------------------------------

def column_ranges(data):
    """The (minimum, maximum) of every attribute: shape ``(d, 2)``.

    Examples
    --------
    >>> column_ranges([[1, 10], [3, 30], [2, 20]]).tolist()
    [[1.0, 3.0], [10.0, 30.0]]
    """
    table = _records(data)
    return np.column_stack([table.min(axis=0), table.max(axis=0)])


def normalise_columns(data, ranges=None):
    r"""Each attribute mapped linearly onto ``[0, 1]`` by its own range (chapter 10's
    normalisation, :func:`course_lib.colormaps.normalize`, column by column).

    .. math:: x'_{ik} = \frac{x_{ik} - \min_k}{\max_k - \min_k}

    Parameters
    ----------
    data : array_like, shape (n, d)
    ranges : array_like, shape (d, 2), optional
        The (low, high) of each attribute; default its minimum and maximum. Values outside are
        clipped. A constant attribute maps to 0.5.

    Returns
    -------
    ndarray, shape (n, d)

    Examples
    --------
    >>> normalise_columns([[1, 10], [3, 30], [2, 20]])
    array([[0. , 0. ],
           [1. , 1. ],
           [0.5, 0.5]])
    """
    table = _records(data)
    r = _ranges_for(table, ranges)
    return np.column_stack([normalize(table[:, k], in_range=tuple(r[k]))
                            for k in range(table.shape[1])])


def parallel_coordinates(data, order=None, flip=(), ranges=None, names=None):
    """The polylines of parallel coordinates: one per record, one vertex per axis.

    The attribute ``order[k]`` is drawn on the vertical axis at ``x = k``; its values are
    normalised to ``[0, 1]`` on their own range (:func:`normalise_columns`), and an attribute
    in `flip` is drawn upside down, ``y = 1 - y``.

    Parameters
    ----------
    data : array_like, shape (n, d)
    order : sequence, optional
        A permutation of the attributes (indices or names), left to right. Default: as stored.
    flip : sequence
        Attributes (indices or names) whose axis is flipped.
    ranges : array_like, shape (d, 2), optional
        The range of each attribute (in stored order); default its minimum and maximum.
    names : sequence of str, optional
        The attribute names, to give `order` and `flip` by name.

    Returns
    -------
    ndarray, shape (n, d, 2)
        ``[i, k]`` is the vertex ``(k, y)`` of record ``i`` on the ``k``-th axis.

    Examples
    --------
    >>> lines = parallel_coordinates([[1, 10], [3, 30], [2, 20]], order=[1, 0], flip=[0])
    >>> lines[0].tolist()          # record 0: y = 0 on axis 0 (attribute 1), 1 - 0 on axis 1
    [[0.0, 0.0], [1.0, 1.0]]
    """
    table = _records(data)
    d = table.shape[1]
    if order is None:
        perm = list(range(d))
    else:
        perm = [attribute_index(a, d, names) for a in order]
        if sorted(perm) != list(range(d)):
            raise ValueError(f"order must list each of the {d} attributes exactly once, got "
                             f"{list(order)!r}")
    flipped = {attribute_index(a, d, names) for a in flip}
    y = normalise_columns(table, ranges)
    for k in flipped:
        y[:, k] = 1.0 - y[:, k]
    y = y[:, perm]
    x = np.broadcast_to(np.arange(d, dtype=float), y.shape)
    return np.stack([x, y], axis=-1)


def _pair_ranges(x_range, y_range):
    xr = np.asarray(x_range, dtype=float)
    yr = np.asarray(y_range, dtype=float)
    for r, name in ((xr, "x_range"), (yr, "y_range")):
        if r.shape != (2,) or not np.isfinite(r).all() or not r[0] < r[1]:
            raise ValueError(f"{name} must be (low, high) with low < high, got "
                             f"{np.asarray(r).tolist()}")
    return xr, yr


def dual_line(points, x_range=(0.0, 1.0), y_range=(0.0, 1.0)):
    r"""The line that a 2D point becomes between two adjacent parallel axes.

    The x axis is at ``u = 0``, the y axis at ``u = 1``; the point ``(a, b)``, normalised to
    ``a' = (a - x_min)/(x_max - x_min)`` and ``b'`` likewise, is the line
    ``v = a' + (b' - a') u``.

    Parameters
    ----------
    points : array_like, shape (2,) or (n, 2)
    x_range, y_range : (float, float)
        The ranges the two axes span (low < high).

    Returns
    -------
    (slope, intercept) : floats or arrays of shape (n,)

    Examples
    --------
    >>> dual_line([2.0, 30.0], x_range=(0, 4), y_range=(0, 40))
    (0.25, 0.5)
    """
    p = np.asarray(points, dtype=float)
    if p.shape[-1:] != (2,) or p.ndim > 2 or not np.isfinite(p).all():
        raise ValueError(f"points must be finite (x, y) pairs, shape (2,) or (n, 2); got "
                         f"shape {p.shape}")
    xr, yr = _pair_ranges(x_range, y_range)
    a = (p[..., 0] - xr[0]) / (xr[1] - xr[0])
    b = (p[..., 1] - yr[0]) / (yr[1] - yr[0])
    if p.ndim == 1:
        return float(b - a), float(a)
    return b - a, a


def normalised_slope(m, x_range=(0.0, 1.0), y_range=(0.0, 1.0)):
    r"""The slope of ``y = m x + c`` in normalised units: ``m' = m (x_max - x_min) /
    (y_max - y_min)``.

    Examples
    --------
    >>> normalised_slope(-2.0, x_range=(0, 10), y_range=(0, 40))
    -0.5
    """
    xr, yr = _pair_ranges(x_range, y_range)
    return float(as_scalar(m, "m") * (xr[1] - xr[0]) / (yr[1] - yr[0]))


def dual_point(m, c, x_range=(0.0, 1.0), y_range=(0.0, 1.0)):
    r"""Where the parallel-coordinate lines of all the points of ``y = m x + c`` meet.

    With the x axis at ``u = 0`` and the y axis at ``u = 1``, normalised slope ``m'`` and
    intercept ``c' = (m x_min + c - y_min)/(y_max - y_min)``, the lines meet at

    .. math:: \left(\frac{1}{1 - m'},\; \frac{c'}{1 - m'}\right).

    Parameters
    ----------
    m, c : float
        Slope and intercept in data units.
    x_range, y_range : (float, float)
        The ranges the two axes span.

    Returns
    -------
    (u, v) : (float, float)

    Raises
    ------
    ValueError
        For ``m' = 1``: the lines are parallel and never meet (the point is at infinity).

    Examples
    --------
    >>> dual_point(-1.0, 1.0)          # y = 1 - x on [0, 1]^2: lines cross in the middle
    (0.5, 0.5)
    >>> dual_point(0.5, 0.0, x_range=(0, 4), y_range=(0, 4))
    (2.0, 0.0)
    """
    m, c = as_scalar(m, "m"), as_scalar(c, "c")
    xr, yr = _pair_ranges(x_range, y_range)
    mn = normalised_slope(m, xr, yr)
    cn = (m * xr[0] + c - yr[0]) / (yr[1] - yr[0])
    if abs(1.0 - mn) < 1e-12:
        raise ValueError("the normalised slope m' is 1: the lines of the points are parallel "
                         "and meet only at infinity")
    return float(1.0 / (1.0 - mn)), float(cn / (1.0 - mn))


class PolylineRaster:
    """Polylines over shared, increasing x positions, rasterised into a count image.

    Pixel column ``j`` covers ``[x_j, x_{j+1}]`` of the extent; a polyline covers, in that
    column, every row between its heights at the column's two edges (and at a vertex inside
    it), so steep segments leave no gaps. The spans are computed once; :meth:`counts` then
    adds up any subset of the polylines with two ``numpy.bincount`` calls (a difference image
    summed down the columns), which is what keeps brushing 10,000 records fast.

    Parameters
    ----------
    polylines : array_like, shape (n, m, 2)
        Vertex ``k`` of every polyline has the same x (strictly increasing in ``k``), as in
        :func:`parallel_coordinates`.
    width, height : int
        The image size in pixels.
    extent : (x0, x1, y0, y1), optional
        The region the image covers; default ``(x_first, x_last, 0, 1)``. Row 0 is at ``y0``
        (draw with ``origin="lower"``).

    Examples
    --------
    >>> raster = PolylineRaster([[[0, 0], [1, 1]], [[0, 1], [1, 1]]], 4, 4)
    >>> raster.counts()[::-1]                 # top row first
    array([[1, 1, 1, 2],
           [0, 0, 1, 0],
           [0, 1, 0, 0],
           [1, 0, 0, 0]])
    >>> raster.counts([False, True]).sum()    # the flat line at the top only
    np.int64(4)
    """

    def __init__(self, polylines, width, height, extent=None):
        p = np.asarray(polylines, dtype=float)
        if p.ndim != 3 or p.shape[-1] != 2 or p.shape[0] < 1 or p.shape[1] < 2 \
                or not np.isfinite(p).all():
            raise ValueError(f"polylines must be finite, shape (n, m, 2) with m >= 2; got "
                             f"shape {p.shape}")
        xs = p[0, :, 0]
        if not np.all(p[:, :, 0] == xs) or not np.all(np.diff(xs) > 0):
            raise ValueError("polylines must share their x positions, strictly increasing")
        self.width = as_whole(width, "width", 1)
        self.height = as_whole(height, "height", 1)
        x0, x1, y0, y1 = (float(v) for v in (extent or (xs[0], xs[-1], 0.0, 1.0)))
        if not (x1 > x0 and y1 > y0):
            raise ValueError(f"extent must be (x0, x1, y0, y1) with x0 < x1, y0 < y1, got "
                             f"{extent!r}")
        self.n = p.shape[0]
        w, h = self.width, self.height
        edges = x0 + (x1 - x0) * np.arange(w + 1) / w
        cols = np.flatnonzero((edges[1:] > xs[0]) & (edges[:-1] < xs[-1]))
        # the heights at the (clipped) edges of those columns, in pixel units, segment by
        # segment (float32: a fraction of a pixel is all the precision needed)
        ex = np.clip(edges[cols[0]:cols[-1] + 2], xs[0], xs[-1])
        seg = np.clip(np.searchsorted(xs, ex, side="right") - 1, 0, len(xs) - 2)
        t = ((ex - xs[seg]) / (xs[seg + 1] - xs[seg])).astype(np.float32)
        ys = ((p[:, :, 1] - y0) * (h / (y1 - y0))).astype(np.float32)
        y_edge = np.empty((self.n, len(ex)), dtype=np.float32)
        for k in range(len(xs) - 1):
            at = np.flatnonzero(seg == k)
            y_edge[:, at] = ys[:, k:k + 1] + (ys[:, k + 1] - ys[:, k])[:, None] * t[at]
        y_low = np.minimum(y_edge[:, :-1], y_edge[:, 1:])
        y_high = np.maximum(y_edge[:, :-1], y_edge[:, 1:])
        v_col = np.clip(np.floor((xs - x0) / (x1 - x0) * w).astype(int), 0, w - 1) - cols[0]
        for k, c in enumerate(v_col):                 # a kink inside a column
            if 0 <= c < len(cols):
                np.minimum(y_low[:, c], ys[:, k], out=y_low[:, c])
                np.maximum(y_high[:, c], ys[:, k], out=y_high[:, c])
        # rows [low, high): a line that ends on a row's lower edge does not enter that row
        lo = np.clip(np.floor(y_low, out=y_low), 0, h - 1, out=y_low).astype(np.int32)
        y_high -= np.float32(1e-3)
        hi = np.clip(np.floor(y_high, out=y_high), 0, h - 1, out=y_high).astype(np.int32)
        np.maximum(hi, lo, out=hi)
        cols32 = cols.astype(np.int32)
        self.starts = lo * np.int32(w) + cols32
        self.ends = (hi + 1) * np.int32(w) + cols32
        self._total = None

    def _sum(self, starts, ends):
        size = (self.height + 1) * self.width
        diff = (np.bincount(starts.ravel(), minlength=size)
                - np.bincount(ends.ravel(), minlength=size))
        return np.cumsum(diff.reshape(self.height + 1, self.width), axis=0)[:-1]

    def counts(self, mask=None):
        """How many of the polylines (all, or those where `mask` is True) cover each pixel.

        Parameters
        ----------
        mask : array_like of bool, shape (n,), optional

        Returns
        -------
        ndarray of int, shape (height, width)
        """
        if self._total is None:
            self._total = self._sum(self.starts, self.ends)
        if mask is None:
            return self._total.copy()
        keep = np.asarray(mask)
        if keep.shape != (self.n,) or keep.dtype != bool:
            raise ValueError(f"mask must be {self.n} booleans, got shape {keep.shape} of "
                             f"{keep.dtype}")
        chosen = int(np.count_nonzero(keep))
        if chosen > self.n // 2:                    # fewer to add up: subtract the others
            rest = ~keep
            return self._total - self._sum(self.starts[rest], self.ends[rest])
        return self._sum(self.starts[keep], self.ends[keep])


def rasterize_polylines(polylines, width, height, extent=None, mask=None):
    """Count image of polylines (see :class:`PolylineRaster`): a density picture of
    parallel coordinates when the records are too many to draw one by one.

    Examples
    --------
    >>> lines = parallel_coordinates([[0, 0], [1, 1], [1, 0]])
    >>> rasterize_polylines(lines, 3, 2)[::-1]
    array([[2, 2, 1],
           [1, 2, 2]])
    """
    return PolylineRaster(polylines, width, height, extent).counts(mask)


# ---------------------------------------------------------------------------------------------
# Scatterplot matrix
# ---------------------------------------------------------------------------------------------

def scatterplot_matrix(data, names=None, bins=10, diagonal="histogram", ranges=None):
    """The panels of a scatterplot matrix: ``d x d``, row-major, attribute ``row`` up and
    attribute ``col`` across.

    Off the diagonal a panel is a scatter plot of the normalised values ``(x_col, x_row)``; on
    the diagonal a histogram of the attribute (``bins`` equal bins over its range) or just its
    name.

    Parameters
    ----------
    data : array_like, shape (n, d)
    names : sequence of str, optional
        Default ``"x0", "x1", ...``.
    bins : int
    diagonal : {"histogram", "names"}
    ranges : array_like, shape (d, 2), optional

    Returns
    -------
    list of dict
        ``d * d`` panels with keys ``row``, ``col``, ``kind`` ("scatter", "histogram",
        "name"), ``name`` (the attribute's, on the diagonal) and either ``points`` (n, 2) or
        ``counts`` (bins,) and ``edges`` (bins + 1,) in data units.

    Examples
    --------
    >>> panels = scatterplot_matrix([[0, 9], [1, 7], [2, 5]], ("a", "b"), bins=2)
    >>> [p["kind"] for p in panels]
    ['histogram', 'scatter', 'scatter', 'histogram']
    >>> panels[1]["points"].tolist()       # row 0, col 1: b across, a up
    [[1.0, 0.0], [0.5, 0.5], [0.0, 1.0]]
    >>> panels[0]["counts"].tolist()
    [1, 2]
    """
    table = _records(data)
    d = table.shape[1]
    names = tuple(names) if names is not None else tuple(f"x{k}" for k in range(d))
    if len(names) != d:
        raise ValueError(f"names must give {d} names, got {len(names)}")
    bins = as_whole(bins, "bins", 1)
    as_choice(diagonal, "diagonal", ("histogram", "names"))
    r = _ranges_for(table, ranges)
    y = normalise_columns(table, r)
    panels = []
    for row in range(d):
        for col in range(d):
            panel = {"row": row, "col": col}
            if row != col:
                panel.update(kind="scatter", points=np.column_stack([y[:, col], y[:, row]]))
            elif diagonal == "names":
                panel.update(kind="name", name=names[row])
            else:
                lo, hi = r[row]
                hi = hi if hi > lo else lo + 1.0
                counts, edges = np.histogram(table[:, row], bins=bins, range=(lo, hi))
                panel.update(kind="histogram", name=names[row], counts=counts, edges=edges)
            panels.append(panel)
    return panels


# ---------------------------------------------------------------------------------------------
# Brushing
# ---------------------------------------------------------------------------------------------

def range_brush(data, axis, low, high, names=None):
    """The records whose attribute `axis` lies in ``[low, high]`` (bounds included).

    Parameters
    ----------
    data : array_like, shape (n, d)
    axis : int or str
        The attribute (index, or name with `names`).
    low, high : float
        The range, ``low < high`` (in the attribute's units).
    names : sequence of str, optional

    Returns
    -------
    ndarray of bool, shape (n,)

    Raises
    ------
    ValueError
        For a missing attribute, an empty (``low == high``) or reversed range, NaN in data.

    Examples
    --------
    >>> range_brush([[1, 5], [2, 6], [3, 7]], "b", 5.5, 7, names=("a", "b")).tolist()
    [False, True, True]
    >>> range_brush([[1, 5]], 0, 3, 2)
    Traceback (most recent call last):
    ...
    ValueError: range of axis 0 is reversed: low 3 > high 2; give it as (low, high)
    """
    table = _records(data)
    k = attribute_index(axis, table.shape[1], names)
    lo, hi = _brush_interval((low, high), f"range of axis {axis!r}" if isinstance(axis, str)
                       else f"range of axis {k}")
    column = table[:, k]
    return (column >= lo) & (column <= hi)


def rectangle_brush(data, x_axis, y_axis, x_range, y_range, names=None):
    """The records inside a rectangle drawn on the scatter plot of two attributes: the AND of
    two range brushes.

    Examples
    --------
    >>> rectangle_brush([[1, 5], [2, 6], [3, 7]], 0, 1, (1.5, 3), (0, 6.5)).tolist()
    [False, True, False]
    """
    table = _records(data)
    return (range_brush(table, x_axis, *_brush_interval(x_range, "x_range"), names=names)
            & range_brush(table, y_axis, *_brush_interval(y_range, "y_range"), names=names))


def combine_brushes(masks, how="and"):
    """Combine the masks of several brushes: ``"and"`` (in every brush) or ``"or"`` (in any).

    Parameters
    ----------
    masks : sequence of boolean arrays of one length n
    how : {"and", "or"}

    Returns
    -------
    ndarray of bool

    Examples
    --------
    >>> a, b = [True, True, False], [True, False, False]
    >>> combine_brushes([a, b]).tolist(), combine_brushes([a, b], "or").tolist()
    ([True, False, False], [True, True, False])
    """
    how = as_choice(how.lower() if isinstance(how, str) else how, "how", ("and", "or"))
    arrays = [np.asarray(m) for m in masks]
    if not arrays:
        raise ValueError("masks must hold at least one mask")
    for m in arrays:
        if m.dtype != bool or m.shape != arrays[0].shape or m.ndim != 1:
            raise ValueError(f"masks must be boolean arrays of one length, got shapes "
                             f"{[a.shape for a in arrays]} of {[str(a.dtype) for a in arrays]}")
    stack = np.stack(arrays)
    return stack.all(axis=0) if how == "and" else stack.any(axis=0)


def brush_mask(data, brushes, how="and", names=None):
    """The records selected by several brushes combined with AND or OR.

    Parameters
    ----------
    data : array_like, shape (n, d)
    brushes : sequence of mappings
        Each brush maps attributes (index or name) to a range ``(low, high)``; a record is in
        the brush when all of them hold (one range: a brush on one axis; two: a rectangle).
    how : {"and", "or"}
        How the brushes combine.
    names : sequence of str, optional

    Returns
    -------
    ndarray of bool, shape (n,)
        With no brush at all, every record is selected.

    Examples
    --------
    >>> data = [[1, 5], [2, 6], [3, 7], [4, 8]]
    >>> brushes = [{"a": (1, 2)}, {"b": (7.5, 9)}]
    >>> brush_mask(data, brushes, names=("a", "b")).tolist()
    [False, False, False, False]
    >>> brush_mask(data, brushes, "or", names=("a", "b")).tolist()
    [True, True, False, True]
    """
    table = _records(data)
    masks = []
    for brush in brushes:
        if not hasattr(brush, "items") or not brush:
            raise TypeError(f"each brush must be a non-empty mapping {{axis: (low, high)}}, "
                            f"got {brush!r}")
        inside = np.ones(len(table), dtype=bool)
        for axis, interval in brush.items():
            low, high = _brush_interval(interval, f"range of axis {axis!r}")
            inside &= range_brush(table, axis, low, high, names=names)
        masks.append(inside)
    if not masks:
        as_choice(how.lower() if isinstance(how, str) else how, "how", ("and", "or"))
        return np.ones(len(table), dtype=bool)
    return combine_brushes(masks, how)


# ---------------------------------------------------------------------------------------------
# Glyphs
# ---------------------------------------------------------------------------------------------

def star_glyph(values, start_angle=np.pi / 2):
    r"""The polygon of a star plot: spoke ``k`` at angle ``start + 2 pi k / d`` (counter-
    clockwise), its vertex at the distance of the record's normalised value.

    .. math:: P_k = v_k\,(\cos\theta_k, \sin\theta_k), \qquad
              \theta_k = \theta_0 + \frac{2\pi k}{d}

    Parameters
    ----------
    values : array_like, shape (d,) or (n, d)
        Normalised values in ``[0, 1]`` (use :func:`normalise_columns` first), ``d >= 3``.
    start_angle : float
        Angle of the first spoke in radians; default straight up.

    Returns
    -------
    ndarray, shape (d, 2) or (n, d, 2)

    Examples
    --------
    >>> star_glyph([1.0, 0.5, 0.5, 0.0]).round(12).tolist()
    [[0.0, 1.0], [-0.5, 0.0], [-0.0, -0.5], [0.0, -0.0]]
    """
    v = np.asarray(values, dtype=float)
    if v.ndim not in (1, 2) or v.shape[-1] < 3 or not np.isfinite(v).all():
        raise ValueError(f"values must be finite, shape (d,) or (n, d) with d >= 3 spokes; "
                         f"got shape {v.shape}")
    if v.min() < -1e-12 or v.max() > 1 + 1e-12:
        raise ValueError(f"values must be normalised to [0, 1] (use normalise_columns), got "
                         f"values in [{v.min():g}, {v.max():g}]")
    d = v.shape[-1]
    theta = float(start_angle) + 2 * np.pi * np.arange(d) / d
    spokes = np.column_stack([np.cos(theta), np.sin(theta)])
    return v[..., None] * spokes


#: The facial features a Chernoff face can vary, each by a parameter in [0, 1].
CHERNOFF_FEATURES = ("face width", "face height", "eye size", "eye spacing", "brow slant",
                     "nose length", "mouth width", "mouth curve")


def chernoff_parameters(data, names=None, mapping=None, ranges=None):
    """Which attribute drives which facial feature, and each record's feature parameters.

    Parameters
    ----------
    data : array_like, shape (n, d)
    names : sequence of str, optional
    mapping : dict, optional
        Feature (one of :data:`CHERNOFF_FEATURES`) -> attribute (index or name). Default: the
        first ``min(d, 8)`` attributes drive the features in the order listed.
    ranges : array_like, shape (d, 2), optional
        The attribute ranges for the normalisation; default the data's own.

    Returns
    -------
    ndarray, shape (n, 8)
        The parameter of every feature in ``[0, 1]`` (the normalised attribute), 0.5 for a
        feature no attribute drives.

    Examples
    --------
    >>> p = chernoff_parameters([[0, 10], [1, 30]], ("a", "b"), {"mouth curve": "b"})
    >>> p[:, CHERNOFF_FEATURES.index("mouth curve")].tolist(), float(p[0, 0])
    ([0.0, 1.0], 0.5)
    """
    table = _records(data)
    d = table.shape[1]
    if mapping is None:
        mapping = {f: k for f, k in zip(CHERNOFF_FEATURES, range(d))}
    if not hasattr(mapping, "items"):
        raise TypeError(f"mapping must be a dict feature -> attribute, got {mapping!r}")
    y = normalise_columns(table, ranges)
    params = np.full((len(table), len(CHERNOFF_FEATURES)), 0.5)
    for feature, axis in mapping.items():
        as_choice(feature, "feature", CHERNOFF_FEATURES)
        params[:, CHERNOFF_FEATURES.index(feature)] = y[:, attribute_index(axis, d, names)]
    return params


def chernoff_face(params):
    """The outline of one Chernoff face as polylines, in a box about ``[-1, 1]^2``.

    Parameters
    ----------
    params : array_like, shape (8,)
        The feature parameters in ``[0, 1]``, ordered as :data:`CHERNOFF_FEATURES`.

    Returns
    -------
    dict
        Part name -> ``(k, 2)`` polyline: ``face``, ``left eye``, ``right eye``, ``left
        pupil``, ``right pupil``, ``left brow``, ``right brow``, ``nose``, ``mouth``.

    Examples
    --------
    >>> face = chernoff_face(np.full(8, 0.5))
    >>> sorted(face)[:3], face["mouth"].shape
    (['face', 'left brow', 'left eye'], (21, 2))
    >>> smile, frown = chernoff_face([.5] * 7 + [1.0]), chernoff_face([.5] * 7 + [0.0])
    >>> bool(smile["mouth"][10, 1] < smile["mouth"][0, 1]), bool(frown["mouth"][10, 1] > frown["mouth"][0, 1])
    (True, True)
    """
    p = np.asarray(params, dtype=float)
    if p.shape != (len(CHERNOFF_FEATURES),) or not np.isfinite(p).all() \
            or p.min() < 0 or p.max() > 1:
        raise ValueError(f"params must be {len(CHERNOFF_FEATURES)} numbers in [0, 1] (one per "
                         f"feature of CHERNOFF_FEATURES), got {np.asarray(params).tolist()!r}")
    width, height, eye, spacing, brow, nose, mouth_w, curve = p
    t = np.linspace(0, 2 * np.pi, 61)
    a, b = 0.6 + 0.35 * width, 0.75 + 0.25 * height
    parts = {"face": np.column_stack([a * np.cos(t), b * np.sin(t)])}
    ex, ey, er = (0.2 + 0.25 * spacing) * a, 0.3 * b, 0.06 + 0.12 * eye
    for side, s in (("left", -1), ("right", 1)):
        parts[f"{side} eye"] = np.column_stack([s * ex + er * np.cos(t), ey + 0.7 * er * np.sin(t)])
        parts[f"{side} pupil"] = np.column_stack([s * ex + 0.3 * er * np.cos(t),
                                                  ey + 0.3 * er * np.sin(t)])
        tilt = (brow - 0.5) * 0.3                     # outer end up for a high parameter
        parts[f"{side} brow"] = np.array([[s * (ex - 0.15), ey + er + 0.1 - tilt],
                                          [s * (ex + 0.15), ey + er + 0.1 + tilt]])
    length = 0.15 + 0.3 * nose
    parts["nose"] = np.array([[0.0, 0.1], [-0.06, 0.1 - length], [0.06, 0.1 - length],
                              [0.0, 0.1]])
    u = np.linspace(-1, 1, 21)
    half = (0.2 + 0.3 * mouth_w) * a
    bend = (curve - 0.5) * 0.4                        # > 0: the corners up, a smile
    parts["mouth"] = np.column_stack([half * u, -0.5 * b + bend * (u * u - 1)])
    return parts
