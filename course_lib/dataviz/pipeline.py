r"""The visualization pipeline and the methods of scientific exploration (textbook 10.1, 10.2).

A visualization turns numbers into a picture in four stages, each taking the previous one's
output:

1. **data acquisition** (or simulation): measure or compute the raw values;
2. **filtering and enrichment**: clean them (outliers, noise, gaps), resample and interpolate,
   derive new quantities (gradients, vorticity), normalise; the result is still *data*;
3. **mapping**: turn the data into something that can be drawn, geometry (isolines,
   isosurfaces, glyphs, streamlines, bars) with visual attributes (colour, opacity, size);
4. **rendering**: turn that geometry into an image: camera and projection, hidden surfaces,
   lighting and shading, compositing.

This module holds the stages (:data:`STAGES`, :data:`STAGE_INFO`), a catalogue of actions
with the stage each belongs to and why (:data:`ACTIONS`, :func:`pipeline_stage`,
:func:`misplaced_actions`), the three uses of a visualization (:data:`USES`), Shneiderman's
mantra *overview first, zoom and filter, then details on demand* (:data:`MANTRA`,
:func:`mantra_step`), and the small algorithms of a worked pipeline: a median filter, a
hill-shading renderer, an overview of a long series that keeps its extremes
(:func:`minmax_decimate`) and the whole pipeline on one example field
(:func:`pipeline_example`).
"""
from collections import namedtuple

import numpy as np

from .. import colormaps, scivis
from .._validate import as_array, as_choice, as_positive, as_scalar, as_whole

__all__ = [
    "ACTIONS",
    "MANTRA",
    "MANTRA_INTERACTIONS",
    "STAGES",
    "STAGE_INFO",
    "USES",
    "Stage",
    "Use",
    "canonical_stage",
    "hillshade",
    "mantra_step",
    "median_filter",
    "minmax_decimate",
    "misplaced_actions",
    "pipeline_example",
    "pipeline_stage",
    "visualization_use",
]


# ---------------------------------------------------------------------------------------------
# The stages
# ---------------------------------------------------------------------------------------------

#: The stages of the visualization pipeline, in the order the data pass through them.
STAGES = ("data acquisition", "filtering and enrichment", "mapping", "rendering")


class Stage(namedtuple("Stage", "name takes gives what examples")):
    """One stage of the pipeline: its name, what it takes and gives, what it does, examples.

    Examples
    --------
    >>> STAGE_INFO["mapping"].gives
    'geometry with visual attributes (points, lines, surfaces, glyphs; colour, opacity, size)'
    """

    __slots__ = ()


#: What each stage takes, gives and does.
STAGE_INFO = {
    "data acquisition": Stage(
        "data acquisition", "the phenomenon (a patient, the weather, a simulation model)",
        "raw data: values on a grid or at scattered points, with noise, outliers and gaps",
        "Measure (scanners, sensors, satellites, surveys) or compute (simulations) the values "
        "to be shown.",
        ("scan a patient", "run a simulation", "record a sensor's time series")),
    "filtering and enrichment": Stage(
        "filtering and enrichment", "raw data",
        "prepared data: cleaned, resampled, with derived quantities, normalised",
        "Remove outliers and noise, fill gaps by interpolation, resample onto the grid the "
        "next stage needs, compute derived quantities (gradient, vorticity), select the "
        "region of interest and normalise. Data in, data out: nothing is visual yet.",
        ("remove outliers", "smooth", "resample", "compute the gradient magnitude",
         "normalise")),
    "mapping": Stage(
        "mapping", "prepared data",
        "geometry with visual attributes (points, lines, surfaces, glyphs; colour, opacity, "
        "size)",
        "Decide how data become something drawable: which geometry (isolines, isosurfaces, "
        "glyphs, streamlines, bars) and which visual attributes (colour, opacity, size, "
        "shape) encode which values. The heart of visualization: here a picture becomes "
        "faithful or misleading.",
        ("choose a colour map", "extract an isosurface", "place glyphs",
         "design an opacity transfer function")),
    "rendering": Stage(
        "rendering", "geometry with visual attributes",
        "an image (pixels)",
        "Turn the geometry into pixels: viewpoint and projection, hidden-surface removal, "
        "lighting and shading, compositing of transparent samples, anti-aliasing. The "
        "computer-graphics part of the pipeline (the rest of this course).",
        ("set the camera", "shade the surface", "ray cast the volume")),
}

#: Other names of the stages a student may type, mapped to the names of :data:`STAGES`.
_STAGE_ALIASES = {
    "acquisition": "data acquisition", "data": "data acquisition",
    "simulation": "data acquisition", "data acquisition / simulation": "data acquisition",
    "data acquisition or simulation": "data acquisition", "acquire": "data acquisition",
    "filtering": "filtering and enrichment", "filter": "filtering and enrichment",
    "enrichment": "filtering and enrichment", "filtering/enrichment": "filtering and enrichment",
    "filtering & enrichment": "filtering and enrichment",
    "filter and enrich": "filtering and enrichment", "preprocessing": "filtering and enrichment",
    "map": "mapping", "visualization mapping": "mapping", "render": "rendering",
}


def canonical_stage(name):
    """The pipeline stage a typed name stands for (case, spaces and common aliases forgiven).

    Parameters
    ----------
    name : str
        A stage name: one of :data:`STAGES` or an alias (``"filtering"``, ``"acquisition"``,
        ``"render"``...).

    Returns
    -------
    str
        One of :data:`STAGES`.

    Raises
    ------
    TypeError
        If `name` is not a string.
    ValueError
        If it names no stage; the message lists the stages.

    Examples
    --------
    >>> canonical_stage(" Filtering ")
    'filtering and enrichment'
    >>> canonical_stage("shading")
    Traceback (most recent call last):
    ...
    ValueError: stage must be one of 'data acquisition', 'filtering and enrichment', 'mapping', 'rendering', got 'shading'
    """
    if not isinstance(name, str):
        raise TypeError(f"stage must be a string naming a pipeline stage, got "
                        f"{type(name).__name__}")
    key = " ".join(name.strip().lower().split())
    key = _STAGE_ALIASES.get(key, key)
    return key if key in STAGES else as_choice(name, "stage", STAGES)


# ---------------------------------------------------------------------------------------------
# The catalogue of actions
# ---------------------------------------------------------------------------------------------

_ACQ, _FILT, _MAP, _REND = STAGES

#: Actions of a visualization project: action -> (its stage, why it belongs there).
ACTIONS = {
    # data acquisition
    "scan a patient with a CT scanner": (
        _ACQ, "the scanner produces the raw densities; nothing exists to filter before it"),
    "run a fluid-flow simulation": (
        _ACQ, "a simulation computes the raw values, just as a sensor measures them"),
    "record a time series with a sensor": (
        _ACQ, "recording produces the raw values the later stages work on"),
    "measure temperatures at weather stations": (
        _ACQ, "measuring produces the raw values (scattered points, with errors)"),
    "download satellite images of the region": (
        _ACQ, "getting the raw measurements is acquisition, whoever measured them"),
    "sample a function on a grid": (
        _ACQ, "evaluating the function produces the raw values: a simulation in small"),
    # filtering and enrichment
    "remove outliers": (
        _FILT, "it cleans the data: values in, fewer (or corrected) values out; nothing "
               "visual is decided"),
    "apply a median filter": (
        _FILT, "a median filter replaces each value by the median of its neighbours: data in, "
               "data out, cleaner"),
    "smooth the data with a Gaussian filter": (
        _FILT, "smoothing changes the values (less noise), not how they look"),
    "resample onto a regular grid": (
        _FILT, "resampling gives the same field on other sample points: still data"),
    "interpolate the missing values": (
        _FILT, "filling gaps by interpolation produces data where there were none; it does "
               "not draw anything"),
    "compute the gradient magnitude": (
        _FILT, "a derived quantity is enrichment: a new scalar field computed from the data, "
               "not yet a picture"),
    "compute the vorticity of the flow": (
        _FILT, "vorticity is a derived quantity: new data computed from the velocity field"),
    "normalise the values to [0, 1]": (
        _FILT, "normalising rescales the data; choosing the colours for [0, 1] comes later, "
               "in mapping"),
    "crop the data to the region of interest": (
        _FILT, "selecting a subset of the data is filtering"),
    "convert the temperatures from kelvin to degrees Celsius": (
        _FILT, "a change of units transforms the data, not the picture"),
    "average the repeated measurements": (
        _FILT, "averaging reduces noise: data in, data out"),
    # mapping
    "choose a colour map": (
        _MAP, "a colour map decides which colour encodes which value: a visual attribute, "
              "the typical mapping decision"),
    "extract an isosurface": (
        _MAP, "marching cubes turns a scalar field into geometry (triangles) to be drawn: "
              "data to visual primitives"),
    "design an opacity transfer function": (
        _MAP, "opacity is a visual attribute given to each data value; the renderer only "
              "uses it later"),
    "place arrow glyphs on the flow field": (
        _MAP, "glyphs are geometry whose direction and length encode the vectors"),
    "trace streamlines through the velocity field": (
        _MAP, "streamlines are lines built from the data to be drawn: geometry encoding the "
              "flow"),
    "compute contour lines at chosen levels": (
        _MAP, "isolines are geometry made from the data (marching squares), to be drawn"),
    "encode the category of each point by a shape": (
        _MAP, "choosing which visual variable shows which attribute is mapping"),
    "make bar lengths proportional to the yearly values": (
        _MAP, "deciding that a value is shown by a length is the mapping of data to a "
              "visual attribute"),
    "map the terrain height to the height of a 3D surface": (
        _MAP, "turning values into geometry (a height field surface) is mapping"),
    # rendering
    "ray cast the volume": (
        _REND, "ray casting turns the mapped colours and opacities into pixels: rendering"),
    "set up the camera and the viewpoint": (
        _REND, "viewing and projection decide which pixels the geometry lands on"),
    "apply Phong shading to the isosurface": (
        _REND, "shading computes the pixel colours of geometry under lights: rendering"),
    "composite the samples along each ray": (
        _REND, "compositing blends the mapped colours and opacities into a pixel"),
    "rasterise the triangles with a z-buffer": (
        _REND, "rasterisation and hidden-surface removal produce the image"),
    "place the light sources": (
        _REND, "lights belong to shading, which the renderer computes"),
    "anti-alias the final image": (
        _REND, "anti-aliasing works on the pixels of the image being rendered"),
}


def _catalogue_key(action):
    if not isinstance(action, str):
        raise TypeError(f"action must be a string, got {type(action).__name__}")
    return " ".join(action.strip().lower().split())


_ACTION_KEYS = {_catalogue_key(a): a for a in ACTIONS}


def pipeline_stage(action):
    """The pipeline stage an action of :data:`ACTIONS` belongs to.

    Parameters
    ----------
    action : str
        One of the actions of :data:`ACTIONS` (case and extra spaces are forgiven).

    Returns
    -------
    str
        One of :data:`STAGES`.

    Raises
    ------
    TypeError
        If `action` is not a string.
    ValueError
        For an action that is not in the catalogue; the message lists the known ones.

    Examples
    --------
    >>> pipeline_stage("Remove outliers")
    'filtering and enrichment'
    >>> pipeline_stage("extract an isosurface"), pipeline_stage("ray cast the volume")
    ('mapping', 'rendering')
    >>> pipeline_stage("paint it")                                   # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: action 'paint it' is not in the catalogue; the known actions are: ...
    """
    key = _catalogue_key(action)
    if key not in _ACTION_KEYS:
        known = "; ".join(f"'{a}'" for a in ACTIONS)
        raise ValueError(f"action {action!r} is not in the catalogue; the known actions are: "
                         f"{known}")
    return ACTIONS[_ACTION_KEYS[key]][0]


def misplaced_actions(assignment):
    """The actions placed in the wrong stage, each with its right stage and the reason.

    Parameters
    ----------
    assignment : dict or sequence of (str, str)
        Action -> the stage it was placed in (stage names may be aliases, see
        :func:`canonical_stage`).

    Returns
    -------
    list of (str, str, str, str)
        ``(action, stage given, right stage, why)`` for each misplaced action, in the order
        given; empty when every action is in its stage.

    Raises
    ------
    ValueError, TypeError
        For an unknown action or stage.

    Examples
    --------
    >>> misplaced_actions({"choose a colour map": "rendering", "remove outliers": "filtering"})
    ... # doctest: +NORMALIZE_WHITESPACE
    [('choose a colour map', 'rendering', 'mapping', 'a colour map decides which colour
      encodes which value: a visual attribute, the typical mapping decision')]
    """
    pairs = assignment.items() if isinstance(assignment, dict) else assignment
    found = []
    for action, stage in pairs:
        right = pipeline_stage(action)
        given = canonical_stage(stage)
        if given != right:
            name = _ACTION_KEYS[_catalogue_key(action)]
            found.append((name, given, right, ACTIONS[name][1]))
    return found


# ---------------------------------------------------------------------------------------------
# The uses of a visualization and Shneiderman's mantra (10.2)
# ---------------------------------------------------------------------------------------------

class Use(namedtuple("Use", "name question audience needs example")):
    """One use of a visualization: the question it serves, for whom, and what it needs.

    Examples
    --------
    >>> USES["presentation"].audience
    'others, who have not seen the data'
    """

    __slots__ = ()


#: The three uses of a visualization (textbook 10.2) and what each needs.
USES = {
    "exploratory": Use(
        "exploratory", "What is in the data? (no hypothesis yet)",
        "the analyst, searching",
        ("speed and interactivity: many views quickly", "an overview of everything, then "
         "zooming and filtering (Shneiderman's mantra)", "linked views, brushing; rough looks "
         "are fine"),
        "browsing a new simulation's output for anything unexpected"),
    "confirmatory": Use(
        "confirmatory", "Is this hypothesis true? (analysis of a known question)",
        "the analyst and peers, checking",
        ("accuracy: readable values, common scales and the same ranges across views",
         "controlled comparisons (side by side, small multiples)",
         "uncertainty and the data's limits shown"),
        "checking whether the treated patients' tumours shrank more than the untreated ones"),
    "presentation": Use(
        "presentation", "How do I show others what I found?",
        "others, who have not seen the data",
        ("one clear message, annotated", "graphical integrity: no distortion, honest axes",
         "polish and little clutter (a high data-ink ratio); static is fine"),
        "the figure in a paper or the slide of a talk"),
}


def visualization_use(name):
    """What a use of a visualization (exploratory, confirmatory, presentation) needs.

    Parameters
    ----------
    name : str
        ``"exploratory"``, ``"confirmatory"`` (also ``"analysis"``) or ``"presentation"``.

    Returns
    -------
    Use

    Raises
    ------
    ValueError
        For another name; the message lists the uses.

    Examples
    --------
    >>> visualization_use("analysis").name
    'confirmatory'
    >>> visualization_use("exploratory").needs[0]
    'speed and interactivity: many views quickly'
    """
    key = _catalogue_key(name) if isinstance(name, str) else name
    key = {"analysis": "confirmatory", "confirmatory analysis": "confirmatory",
           "exploration": "exploratory", "exploratory analysis": "exploratory",
           "explanatory": "presentation"}.get(key, key)
    return USES[as_choice(key, "use", tuple(USES))]


#: Shneiderman's mantra, "overview first, zoom and filter, then details on demand": the steps
#: of an exploration in order, each as (step, what it does).
MANTRA = (
    ("overview", "see the whole data set at once, reduced to fit the screen, to find where "
                 "to look"),
    ("zoom and filter", "narrow the view to the items of interest: zoom into a region, hide "
                        "the items that do not match a condition"),
    ("details on demand", "ask for the exact values of one item or a small group, only when "
                          "needed (a tooltip, a click, a table)"),
)

#: Interactions of an exploration and the step of the mantra each serves.
MANTRA_INTERACTIONS = {
    "show all the records as one scatterplot": "overview",
    "plot a whole year of measurements in one chart": "overview",
    "show a thumbnail map of the whole country": "overview",
    "zoom into one week of the time series": "zoom and filter",
    "hide the cities with fewer than 10,000 inhabitants": "zoom and filter",
    "drag a range slider to keep only the values between 20 and 30": "zoom and filter",
    "hover over a point to see its exact values": "details on demand",
    "click a bar to open the table of its records": "details on demand",
    "show the full record of the selected patient": "details on demand",
}


def mantra_step(interaction):
    """The step of Shneiderman's mantra an interaction of :data:`MANTRA_INTERACTIONS` serves.

    Parameters
    ----------
    interaction : str
        One of the interactions of :data:`MANTRA_INTERACTIONS`, or a step name itself.

    Returns
    -------
    str
        ``"overview"``, ``"zoom and filter"`` or ``"details on demand"``.

    Raises
    ------
    ValueError
        For an interaction not in the catalogue; the message lists the known ones.

    Examples
    --------
    >>> mantra_step("Hover over a point to see its exact values")
    'details on demand'
    >>> [step for step, _ in MANTRA]
    ['overview', 'zoom and filter', 'details on demand']
    """
    key = _catalogue_key(interaction)
    steps = tuple(step for step, _ in MANTRA)
    if key in steps:
        return key
    table = {_catalogue_key(k): v for k, v in MANTRA_INTERACTIONS.items()}
    if key not in table:
        known = "; ".join(f"'{k}'" for k in MANTRA_INTERACTIONS)
        raise ValueError(f"interaction {interaction!r} is not in the catalogue; the steps are "
                         f"{', '.join(map(repr, steps))} and the known interactions: {known}")
    return table[key]


def minmax_decimate(y, bins, x=None):
    """An overview of a long series: the smallest and the largest value of each of `bins` bins.

    Plotting a million samples on a few hundred pixels draws most of them on top of each
    other; keeping only every k-th sample (subsampling) loses the short spikes an overview
    must show. Keeping each bin's minimum and maximum, in the order they occur, draws the same
    picture as all the samples (the envelope of the curve) from ``2 * bins`` points.

    Parameters
    ----------
    y : array_like, shape (n,)
        The values.
    bins : int
        How many bins, ``1 <= bins <= n``; bin ``k`` holds the samples
        ``floor(k n / bins)`` up to ``floor((k + 1) n / bins) - 1``.
    x : array_like, shape (n,), optional
        Their positions (default ``0, 1, ..., n - 1``).

    Returns
    -------
    x_kept, y_kept : ndarray, shape (2 * bins,)
        Each bin's extreme values in the order they occur (both the same sample when the bin
        is constant or has one sample; ties take the first sample).

    Raises
    ------
    ValueError
        For a bad `y`, `x` of another length, or `bins` outside ``[1, n]``.

    Examples
    --------
    >>> xk, yk = minmax_decimate([0, 5, 1, 2, -3, 2, 0, 0], 2)
    >>> xk.tolist(), yk.tolist()
    ([0.0, 1.0, 4.0, 5.0], [0.0, 5.0, -3.0, 2.0])
    """
    y = as_array(y, "y")
    if y.ndim != 1 or y.size == 0:
        raise ValueError(f"y must be a non-empty 1D array of values, got shape {y.shape}")
    n = y.size
    x = np.arange(n, dtype=float) if x is None else as_array(x, "x")
    if x.shape != y.shape:
        raise ValueError(f"x must have the shape of y {y.shape}, got {x.shape}")
    bins = as_whole(bins, "bins", 1)
    if bins > n:
        raise ValueError(f"bins must be at most the number of samples ({n}), got {bins}")
    starts = (np.arange(bins) * n) // bins
    if n % bins == 0:                           # equal bins: a table, one row per bin
        rows = y.reshape(bins, n // bins)
        first_low = starts + np.argmin(rows, axis=1)     # argmin/argmax: the first on ties
        first_high = starts + np.argmax(rows, axis=1)
    else:
        counts = np.diff(np.append(starts, n))
        index = np.arange(n)
        lows = np.minimum.reduceat(y, starts)
        highs = np.maximum.reduceat(y, starts)
        at_low = np.where(y == np.repeat(lows, counts), index, n)
        at_high = np.where(y == np.repeat(highs, counts), index, n)
        first_low = np.minimum.reduceat(at_low, starts)
        first_high = np.minimum.reduceat(at_high, starts)
    pair = np.stack([np.minimum(first_low, first_high), np.maximum(first_low, first_high)], 1)
    kept = pair.ravel()
    return x[kept], y[kept]


# ---------------------------------------------------------------------------------------------
# A worked pipeline: acquisition, median filter, derived quantity, colour map, hill shading
# ---------------------------------------------------------------------------------------------

def median_filter(values, size=3):
    """Replace each value by the median of the ``size x size`` (x size...) window around it.

    A median ignores a few wild values in its window, so isolated spikes (outliers) vanish
    while edges stay sharp, unlike a mean (blur) that smears a spike over its neighbours.
    The border is handled by repeating the edge values.

    Parameters
    ----------
    values : array_like
        An array of any dimension (an image, a volume, a series).
    size : int
        The window's width along every axis, odd and >= 1.

    Returns
    -------
    ndarray
        Same shape as `values`.

    Raises
    ------
    ValueError
        For an even or non-positive `size`, or non-finite values.

    Examples
    --------
    >>> median_filter([1.0, 1.0, 9.0, 1.0, 2.0])          # the spike 9 is gone
    array([1., 1., 1., 2., 2.])
    >>> median_filter([[0, 0, 0], [0, 100, 0], [0, 0, 0]])
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 0.]])
    """
    v = as_array(values, "values")
    size = as_whole(size, "size", 1)
    if size % 2 == 0:
        raise ValueError(f"size must be odd (a window centred on each value), got {size}")
    if v.ndim == 0 or v.size == 0:
        raise ValueError(f"values must be a non-empty array, got shape {v.shape}")
    half = size // 2
    padded = np.pad(v, half, mode="edge")
    windows = np.lib.stride_tricks.sliding_window_view(padded, (size,) * v.ndim)
    flat = windows.reshape(v.shape + (-1,))
    return np.median(flat, axis=-1)


def hillshade(heights, azimuth=np.radians(135.0), elevation=np.radians(45.0), z_scale=1.0,
              spacing=(1.0, 1.0)):
    r"""Lambert shading of a height field lit by a distant light: a simple renderer.

    The height field :math:`z = h(x, y)` (rows are y, columns x) has the unnormalised
    normal :math:`(-s\,h_x, -s\,h_y, 1)` with the height scale :math:`s`; the slopes come
    from central differences (one-sided at the border). The light comes from the direction

    .. math:: l = (\cos e \cos a,\ \cos e \sin a,\ \sin e)

    (azimuth :math:`a` counter-clockwise from +x, elevation :math:`e` above the plane), and
    the shade is :math:`\max(0, n \cdot l)`.

    Parameters
    ----------
    heights : array_like, shape (ny, nx)
    azimuth, elevation : float
        The light's direction in radians.
    z_scale : float
        Exaggeration of the heights (> 0).
    spacing : (float, float)
        The grid steps (dx, dy).

    Returns
    -------
    ndarray, shape (ny, nx)
        Shades in [0, 1].

    Raises
    ------
    ValueError
        For a field that is not 2D with at least 2 x 2 samples, or a bad scale or spacing.

    Examples
    --------
    >>> flat = hillshade(np.zeros((3, 3)), elevation=np.radians(30))
    >>> bool(np.allclose(flat, 0.5))                    # sin 30 degrees
    True
    >>> facing = hillshade([[0, 1], [0, 1]], azimuth=np.pi, elevation=np.radians(45))
    >>> round(float(facing[0, 0]), 6)                   # a 45 degree slope facing the light
    1.0
    """
    h = as_array(heights, "heights")
    if h.ndim != 2 or min(h.shape) < 2:
        raise ValueError(f"heights must be a 2D field of at least 2 x 2 samples, got shape "
                         f"{h.shape}")
    a, e = as_scalar(azimuth, "azimuth"), as_scalar(elevation, "elevation")
    s = as_positive(z_scale, "z_scale")
    dx, dy = (as_positive(d, "spacing") for d in np.broadcast_to(
        as_array(spacing, "spacing"), (2,)))
    hy, hx = np.gradient(h, dy, dx)
    normals = np.stack([-s * hx, -s * hy, np.ones_like(h)], axis=-1)
    normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    light = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    return np.clip(normals @ light, 0.0, 1.0)


def pipeline_example(kind="hills", size=64, noise=0.03, spikes=0.02, seed=0,
                     cmap="viridis", relief=0.5):
    """The four stages of the pipeline on one example field, each stage's output kept.

    * **data acquisition**: the field :func:`course_lib.scivis.example_field_2d` "measured":
      Gaussian noise of `noise` times its range, and a fraction `spikes` of the samples
      replaced by wild values (a faulty sensor);
    * **filtering and enrichment**: a 3 x 3 :func:`median_filter` removes the spikes and
      most noise, the values are normalised to [0, 1], and the gradient magnitude is derived;
    * **mapping**: a colour map gives each value a colour, and the isolines at 0.5 are
      extracted (geometry);
    * **rendering**: the coloured surface, its heights exaggerated by `relief`, is lit by
      :func:`hillshade` (ambient 0.35).

    Parameters
    ----------
    kind : str
        An example field (``"hills"``, ``"ripple"``, ``"saddle"``, ``"circle"``).
    size : int
        Samples per side (>= 8).
    noise, spikes : float
        Noise level (a fraction of the range, >= 0) and the fraction of spikes (in [0, 0.2]).
    seed : int
        Seeds the noise.
    cmap : str
        A colour map of :mod:`course_lib.colormaps`.
    relief : float
        The height scale of the rendered relief (> 0); the normalised field spans [0, 1] over
        the square [-1, 1]^2.

    Returns
    -------
    dict
        ``"truth"``, ``"acquired"``, ``"filtered"`` (normalised), ``"gradient"`` (its
        magnitude), ``"mapped"`` (RGB, shape (size, size, 3)), ``"isolines"`` (list of (k, 2)
        polylines in [-1, 1]^2), ``"rendered"`` (RGB), ``"extent"`` (for ``imshow``).

    Examples
    --------
    >>> p = pipeline_example(size=32)
    >>> p["mapped"].shape, p["rendered"].shape
    ((32, 32, 3), (32, 32, 3))
    >>> bool(np.abs(p["acquired"] - p["truth"]).max() > 0.5)    # the spikes
    True
    """
    size = as_whole(size, "size", 8)
    noise = as_scalar(noise, "noise")
    spikes = as_scalar(spikes, "spikes")
    if noise < 0:
        raise ValueError(f"noise must be >= 0, got {noise:g}")
    if not 0 <= spikes <= 0.2:
        raise ValueError(f"spikes must be a fraction in [0, 0.2], got {spikes:g}")
    field = scivis.example_field_2d(kind, size)
    truth = field.values
    rng = np.random.default_rng(seed)
    span = float(truth.max() - truth.min()) or 1.0
    acquired = truth + rng.normal(0.0, noise * span, truth.shape)
    wild = rng.random(truth.shape) < spikes
    acquired[wild] = truth.max() + span * rng.uniform(0.5, 1.0, int(wild.sum()))
    cleaned = median_filter(acquired, 3)
    filtered = colormaps.normalize(cleaned)
    dx, dy = field.spacing
    grad = scivis.gradient(filtered, (dx, dy))
    magnitude = np.linalg.norm(grad, axis=-1)
    mapped = colormaps.apply_colormap(filtered, cmap, in_range=(0.0, 1.0))[..., :3]
    lines = scivis.isolines(filtered, 0.5, field.spacing, field.origin)
    shade = hillshade(filtered, z_scale=relief, spacing=(dx, dy))
    rendered = mapped * (0.35 + 0.65 * shade[..., None])
    lo = field.origin[0] - dx / 2
    return {"truth": truth, "acquired": acquired, "filtered": filtered, "gradient": magnitude,
            "mapped": mapped, "isolines": lines, "rendered": rendered,
            "extent": (lo, -lo, lo, -lo)}
