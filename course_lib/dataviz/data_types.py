r"""Chapter 10.3, data aspects: levels of measurement and the dimensionality of a data set.

**Levels of measurement** (Stevens' scales). What may be done with the values of an attribute
depends on what the numbers (or names) mean, not on how they are stored:

========  ============  =================================  ==================================
level     kind          operations that mean something     statistics it permits (adds)
========  ============  =================================  ==================================
nominal   qualitative   =, != (same category or not)       count, mode
ordinal   qualitative   + order <, >                       median, percentiles
interval  quantitative  + differences -, +                 mean, standard deviation
ratio     quantitative  + ratios /, x (a true zero)        geometric and harmonic mean,
                                                           coefficient of variation
========  ============  =================================  ==================================

Each level keeps everything of the levels above it. A level is also defined by the changes of
unit that leave its meaningful statements true (its *admissible transformations*): any
relabelling for nominal data, any increasing function for ordinal, :math:`x \mapsto ax + b`
(:math:`a > 0`) for interval, :math:`x \mapsto ax` for ratio. That is why "20 °C is twice as
warm as 10 °C" means nothing: in Fahrenheit, an admissible change for interval data, the same
temperatures are 68 °F and 50 °F.

**Dimensionality.** A data set samples a function :math:`f: D \subset \mathbb{R}^d \to V`:
:math:`d` is the dimension of the **domain** (the independent variables: 1 for a time series,
2 for an image or a map, 3 for a volume) and the values are **scalars**, **vectors** (as many
components as the domain has axes: a velocity, a gradient), **tensors** (a square matrix per
point: stress, diffusion) or **multivariate** (several unrelated variables per point:
temperature, pressure and humidity).
"""
from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_whole

__all__ = [
    "ATTRIBUTE_EXAMPLES",
    "LEVELS",
    "MeasurementLevel",
    "OPERATIONS",
    "STATISTICS",
    "VALUE_KINDS",
    "Dimensionality",
    "data_dimensionality",
    "is_admissible_transform",
    "measurement_level",
    "permits",
]

#: The four levels, from the weakest to the strongest.
_LEVEL_NAMES = ("nominal", "ordinal", "interval", "ratio")

#: The operations on two values, with the symbols they may also be named by.
OPERATIONS = ("equality", "order", "difference", "ratio")
_OPERATION_SYMBOLS = {"=": "equality", "==": "equality", "!=": "equality", "<": "order",
                      ">": "order", "-": "difference", "+": "difference", "/": "ratio",
                      "*": "ratio"}

#: The summary statistics, each with the weakest level at which it means something.
STATISTICS = ("count", "mode", "median", "percentile", "mean", "standard deviation",
              "geometric mean", "harmonic mean", "coefficient of variation")

_WEAKEST = {"equality": "nominal", "count": "nominal", "mode": "nominal",
            "order": "ordinal", "median": "ordinal", "percentile": "ordinal",
            "difference": "interval", "mean": "interval", "standard deviation": "interval",
            "ratio": "ratio", "geometric mean": "ratio", "harmonic mean": "ratio",
            "coefficient of variation": "ratio"}


class MeasurementLevel(NamedTuple):
    """One row of the table of levels of measurement.

    Attributes
    ----------
    name : str
        ``"nominal"``, ``"ordinal"``, ``"interval"`` or ``"ratio"``.
    kind : str
        ``"qualitative"`` (categories) or ``"quantitative"`` (amounts).
    operations : tuple of str
        The operations of :data:`OPERATIONS` that mean something on this level.
    statistics : tuple of str
        The statistics of :data:`STATISTICS` that mean something on this level.
    transformations : str
        The changes of the values that keep every meaningful statement true.
    examples : tuple of str
        A few attributes on this level.

    Examples
    --------
    >>> LEVELS["interval"].operations
    ('equality', 'order', 'difference')
    """

    name: str
    kind: str
    operations: tuple
    statistics: tuple
    transformations: str
    examples: tuple


def _level_row(name, kind, transformations, examples):
    rank = _LEVEL_NAMES.index(name)

    def allowed(names):
        return tuple(n for n in names if _LEVEL_NAMES.index(_WEAKEST[n]) <= rank)
    return MeasurementLevel(name, kind, allowed(OPERATIONS), allowed(STATISTICS),
                            transformations, examples)


#: The levels of measurement by name, weakest first: what each permits.
LEVELS = {
    "nominal": _level_row("nominal", "qualitative",
                    "any one-to-one relabelling (swap the names, renumber the codes)",
                    ("blood group", "postcode", "land-use class")),
    "ordinal": _level_row("ordinal", "qualitative",
                    "any strictly increasing function (only the order must survive)",
                    ("school grade A-F", "rank in a race", "rating from 'poor' to 'good'")),
    "interval": _level_row("interval", "quantitative",
                     "x -> a x + b with a > 0 (a new unit and a new zero)",
                     ("temperature in °C", "calendar year", "time of day")),
    "ratio": _level_row("ratio", "quantitative",
                  "x -> a x with a > 0 (a new unit only: the zero is fixed)",
                  ("temperature in K", "mass", "length", "a count")),
}

#: Attributes of real data sets: their level and why (the catalogue of the exercises).
ATTRIBUTE_EXAMPLES = {
    "postcode": ("nominal", "a code that names an area: the digits are labels, their "
                 "differences and averages mean nothing"),
    "telephone number": ("nominal", "a label: a larger number is no 'more' telephone"),
    "blood group (A, B, AB, O)": ("nominal", "categories without an order"),
    "land-use class": ("nominal", "categories (forest, water, city) without an order"),
    "player's shirt number": ("nominal", "a name written as a number"),
    "country of birth": ("nominal", "categories without an order"),
    "school grade (A to F)": ("ordinal", "ordered, but the steps between grades need not be "
                              "equal"),
    "finishing place in a race (1st, 2nd, ...)": ("ordinal", "ordered ranks; the gap between "
                                                  "1st and 2nd says nothing about times"),
    "answer on a scale 'disagree' to 'agree' (1 to 5)": (
        "ordinal", "ordered categories; the numbers 1-5 only say the order"),
    "pain level (none, mild, moderate, severe)": ("ordinal", "ordered categories"),
    "hurricane category (1 to 5)": ("ordinal", "ordered classes of wind speed with unequal "
                                    "ranges"),
    "hardness on the Mohs scale": ("ordinal", "a mineral scratches those below it; 10 is not "
                                   "twice as hard as 5"),
    "temperature in °C": ("interval", "differences are meaningful, but 0 °C is an arbitrary "
                          "zero: 20 °C is not twice as warm as 10 °C"),
    "temperature in °F": ("interval", "equal steps, arbitrary zero"),
    "calendar year": ("interval", "year differences mean something; year 0 is a convention, "
                      "so the year 2000 is not twice the year 1000"),
    "time of day on a 24-hour clock": ("interval", "differences of clock times are durations; "
                                       "midnight is no absence of time"),
    "longitude in degrees": ("interval", "differences are angles; the zero (Greenwich) is "
                             "a convention"),
    "temperature in kelvin": ("ratio", "0 K is the absence of thermal energy: 300 K is twice "
                              "150 K"),
    "mass in kg": ("ratio", "a true zero (no mass): 4 kg is twice 2 kg"),
    "height of a person in cm": ("ratio", "a true zero: ratios of heights mean something"),
    "number of children in a household": ("ratio", "a count, with a true zero"),
    "income in euros": ("ratio", "zero income is no income: ratios mean something"),
    "duration of a phone call in seconds": ("ratio", "a duration, with a true zero"),
    "rainfall in mm per year": ("ratio", "zero rainfall is no rain"),
    "wind speed in m/s": ("ratio", "zero speed is calm: 10 m/s is twice 5 m/s"),
}


def _level_name(level, name="level"):
    if isinstance(level, MeasurementLevel):
        return level.name
    return as_choice(level.strip().lower() if isinstance(level, str) else level, name,
                     _LEVEL_NAMES)


def permits(level, what):
    """Whether an operation or a statistic means something for data of a level of measurement.

    Parameters
    ----------
    level : str or MeasurementLevel
        ``"nominal"``, ``"ordinal"``, ``"interval"`` or ``"ratio"``.
    what : str
        An operation of :data:`OPERATIONS` (or its symbol ``=``, ``<``, ``-``, ``/``...) or a
        statistic of :data:`STATISTICS` (``"mean"``, ``"median"``...).

    Returns
    -------
    bool

    Raises
    ------
    ValueError
        For an unknown level, operation or statistic.

    Examples
    --------
    >>> permits("ordinal", "median"), permits("ordinal", "mean")
    (True, False)
    >>> permits("interval", "/")            # 20 °C is not "twice" 10 °C
    False
    >>> permits("ratio", "geometric mean")
    True
    >>> permits("nominal", "variance")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: what must be an operation ('equality', 'order', ... got 'variance'
    """
    name = _level_name(level)
    key = what.strip().lower() if isinstance(what, str) else what
    key = _OPERATION_SYMBOLS.get(key, key) if isinstance(key, str) else key
    if not isinstance(key, str) or key not in _WEAKEST:
        raise ValueError("what must be an operation ("
                         + ", ".join(map(repr, OPERATIONS)) + " or a symbol =, <, -, /) or a "
                         "statistic (" + ", ".join(map(repr, STATISTICS)) + f"), got {what!r}")
    return _LEVEL_NAMES.index(name) >= _LEVEL_NAMES.index(_WEAKEST[key])


def measurement_level(*, ordered, equal_intervals=False, true_zero=False):
    """The level of measurement of an attribute, from three questions about its values.

    1. Do the values have an order (is one more or better than another)? No: **nominal**.
    2. Are equal differences equal amounts (is 3 to 5 as much as 7 to 9)? No: **ordinal**.
    3. Is zero a true zero (none of the quantity), so that ratios mean something? No:
       **interval**; yes: **ratio**.

    Parameters
    ----------
    ordered, equal_intervals, true_zero : bool
        The answers to the three questions.

    Returns
    -------
    str

    Raises
    ------
    TypeError
        For an answer that is not a bool.
    ValueError
        For answers that contradict each other (equal intervals without an order, a true zero
        without equal intervals).

    Examples
    --------
    >>> measurement_level(ordered=True, equal_intervals=True)       # °C
    'interval'
    >>> measurement_level(ordered=True, equal_intervals=True, true_zero=True)   # kelvin
    'ratio'
    >>> measurement_level(ordered=False)                            # postcodes
    'nominal'
    >>> measurement_level(ordered=False, equal_intervals=True)
    Traceback (most recent call last):
    ...
    ValueError: equal_intervals=True needs ordered=True: values without an order have no differences to compare
    """
    for name, value in (("ordered", ordered), ("equal_intervals", equal_intervals),
                        ("true_zero", true_zero)):
        if not isinstance(value, (bool, np.bool_)):
            raise TypeError(f"{name} must be True or False, got {value!r}")
    if equal_intervals and not ordered:
        raise ValueError("equal_intervals=True needs ordered=True: values without an order have "
                         "no differences to compare")
    if true_zero and not equal_intervals:
        raise ValueError("true_zero=True needs equal_intervals=True: a zero only makes ratios "
                         "meaningful when differences are amounts")
    if not ordered:
        return "nominal"
    if not equal_intervals:
        return "ordinal"
    return "ratio" if true_zero else "interval"


def is_admissible_transform(level, before, after, rtol=1e-9):
    r"""Whether a change of the values (``before[i] -> after[i]``) is admissible for a level.

    An admissible transformation keeps every meaningful statement about the data true:

    * nominal: one-to-one (equal values stay equal, different ones different);
    * ordinal: strictly increasing (the order survives);
    * interval: :math:`y = a x + b` with :math:`a > 0` (ratios of differences survive);
    * ratio: :math:`y = a x` with :math:`a > 0` (ratios of values survive).

    Parameters
    ----------
    level : str or MeasurementLevel
    before, after : array_like, shape (n,)
        Values and what the transformation makes of them (at least 2 distinct values for the
        quantitative levels).
    rtol : float
        Relative tolerance of the affine and proportional fits.

    Returns
    -------
    bool

    Raises
    ------
    ValueError
        For unequal lengths, NaN, or fewer than 2 distinct values.

    Examples
    --------
    >>> celsius = [0.0, 10.0, 20.0, 100.0]
    >>> fahrenheit = [32.0, 50.0, 68.0, 212.0]
    >>> is_admissible_transform("interval", celsius, fahrenheit)
    True
    >>> is_admissible_transform("ratio", celsius, fahrenheit)     # so °C is not a ratio scale
    False
    >>> is_admissible_transform("ordinal", [1, 2, 3], [1, 10, 11])
    True
    """
    name = _level_name(level)
    x = as_array(before, "before").ravel()
    y = as_array(after, "after").ravel()
    if x.shape != y.shape:
        raise ValueError(f"before and after must have the same length, got {x.size} and "
                         f"{y.size}")
    xs, first = np.unique(x, return_index=True)
    if xs.size < 2:
        raise ValueError("before must hold at least 2 distinct values to judge a "
                         "transformation")
    # a function: equal values before must stay equal after
    _, inverse = np.unique(x, return_inverse=True)
    scale = max(np.abs(y).max(), 1.0)
    if np.abs(y - y[first][inverse]).max() > rtol * scale:
        return False
    ys = y[first]
    if name == "nominal":
        return bool(np.unique(ys).size == ys.size)
    if name == "ordinal":
        return bool(np.all(np.diff(ys) > 0))
    if name == "interval":
        a = (ys[-1] - ys[0]) / (xs[-1] - xs[0])
        b = ys[0] - a * xs[0]
    else:
        a = ys[-1] / xs[-1] if xs[-1] != 0 else ys[0] / xs[0]
        b = 0.0
    return bool(a > 0 and np.abs(a * xs + b - ys).max() <= rtol * scale)


#: The kinds of values a data set can have at each point of its domain.
VALUE_KINDS = ("scalar", "vector", "tensor", "multivariate")


class Dimensionality(NamedTuple):
    """What :func:`data_dimensionality` finds: domain dimension, kind of value, components.

    Attributes
    ----------
    domain_dim : int
        The number of independent variables (1, 2 or 3).
    value_kind : str
        One of :data:`VALUE_KINDS`.
    components : int
        Numbers per point (1 for a scalar, d for a vector, d*d for a tensor, k variables).
    samples : int
        How many points of the domain are sampled.
    signature : str
        The function the data sample, e.g. ``"f: R^2 -> R^2"``.

    Examples
    --------
    >>> Dimensionality(2, "scalar", 1, 12, "f: R^2 -> R").signature
    'f: R^2 -> R'
    """

    domain_dim: int
    value_kind: str
    components: int
    samples: int
    signature: str


def data_dimensionality(values, domain_dim=None, *, points=None, kind=None):
    """The dimension of a data set's domain and the kind of its values, from array shapes.

    Gridded data: ``values`` has ``domain_dim`` axes of samples followed by the value's own
    axes (none, one or two). Scattered data: ``points`` of shape (n, d) and ``values`` of
    shape (n, ...). The value's axes decide the kind:

    * none: a **scalar** per point;
    * one axis as long as the domain has dimensions: a **vector** (its components follow the
      domain's axes); of any other length k: **multivariate**, k separate variables;
    * two equal axes: a **tensor** (a square matrix per point).

    A trailing axis of length d may also be d separate variables (pass ``kind="multivariate"``),
    and three values on a 2D domain may be a 3D vector (``kind="vector"``): the shape alone
    cannot tell.

    Parameters
    ----------
    values : array_like
    domain_dim : int, optional
        1, 2 or 3; required for gridded data (the shape alone cannot tell a 3D scalar volume
        from a 2D field of 3-vectors).
    points : array_like, shape (n, d), optional
        The sample positions of scattered data; then ``domain_dim`` is d.
    kind : str, optional
        Override the kind read from the shape (one of :data:`VALUE_KINDS`).

    Returns
    -------
    Dimensionality

    Raises
    ------
    ValueError
        For a missing or inconsistent domain dimension, mismatched lengths, or value axes
        that fit no kind.

    Examples
    --------
    >>> data_dimensionality(np.zeros((64, 64)), 2).signature          # an image
    'f: R^2 -> R'
    >>> data_dimensionality(np.zeros((20, 30, 40, 3)), 3).value_kind   # a 3D flow field
    'vector'
    >>> d = data_dimensionality(np.zeros((500, 4)), points=np.zeros((500, 2)))
    >>> d.value_kind, d.components, d.samples
    ('multivariate', 4, 500)
    >>> data_dimensionality(np.zeros((10, 10, 3, 3)), 2).value_kind
    'tensor'
    """
    v = np.asarray(values)
    if points is not None:
        p = as_array(points, "points")
        if p.ndim != 2 or p.shape[1] not in (1, 2, 3):
            raise ValueError(f"points must have shape (n, d) with d = 1, 2 or 3, got shape "
                             f"{p.shape}")
        d = p.shape[1]
        if domain_dim is not None and as_whole(domain_dim, "domain_dim", 1) != d:
            raise ValueError(f"domain_dim ({domain_dim}) disagrees with the points' {d} "
                             "coordinates")
        if v.ndim == 0 or v.shape[0] != p.shape[0]:
            raise ValueError(f"values must have one row per point ({p.shape[0]}), got shape "
                             f"{v.shape}")
        samples, trailing = p.shape[0], v.shape[1:]
    else:
        if domain_dim is None:
            raise ValueError("domain_dim is needed for gridded data: the shape alone cannot "
                             "tell a 3D scalar volume (nz, ny, nx) from a 2D field of "
                             "3-vectors (ny, nx, 3); or pass the points of scattered data")
        d = as_whole(domain_dim, "domain_dim", 1)
        if d > 3:
            raise ValueError(f"domain_dim must be 1, 2 or 3, got {d}")
        if v.ndim < d:
            raise ValueError(f"values must have at least {d} axes of samples for a "
                             f"{d}D domain, got shape {v.shape}")
        samples, trailing = int(np.prod(v.shape[:d])), v.shape[d:]
    if len(trailing) == 0:
        found, comps = "scalar", 1
    elif len(trailing) == 1:
        comps = trailing[0]
        found = "vector" if comps == d else "multivariate"
    elif len(trailing) == 2 and trailing[0] == trailing[1]:
        found, comps = "tensor", trailing[0] * trailing[1]
    else:
        raise ValueError(f"the values' own axes {trailing} fit no kind: none (scalar), one "
                         "(vector or k variables) or two equal ones (a tensor)")
    if kind is not None:
        kind = as_choice(kind, "kind", VALUE_KINDS)
        fits = {"scalar": len(trailing) == 0, "vector": len(trailing) == 1,
                "multivariate": len(trailing) == 1, "tensor": found == "tensor"}
        if not fits[kind]:
            raise ValueError(f"kind={kind!r} does not fit values whose own axes are "
                             f"{trailing}")
        found = kind
    target = "R" if comps == 1 else (f"R^({trailing[0]}x{trailing[1]})" if found == "tensor"
                                     else f"R^{comps}")
    domain = "R" if d == 1 else f"R^{d}"
    return Dimensionality(d, found, int(comps), int(samples), f"f: {domain} -> {target}")
