"""Chapter 18 (lesson section 2): isolines by marching squares."""

import numpy as np

from .._validate import as_array, as_choice, as_scalar, as_vector
from ._common import _grid, _spacing

__all__ = ["SQUARE_SADDLES_CENTRE_ABOVE", "SQUARE_TABLE", "asymptotic_decider", "isolines",
    "join_segments", "marching_squares", "marching_squares_cases", "saddle_centre_above"]


# ---------------------------------------------------------------------------------------------
# Marching squares
# ---------------------------------------------------------------------------------------------
# A cell's corners and edges, counter-clockwise (x right, y up):
#
#     3 ---- e2 ---- 2        corner 0: field[i, j]       edge 0: corner 0 - corner 1
#     |              |        corner 1: field[i, j+1]     edge 1: corner 1 - corner 2
#    e3              e1       corner 2: field[i+1, j+1]   edge 2: corner 2 - corner 3
#     |              |        corner 3: field[i+1, j]     edge 3: corner 3 - corner 0
#     0 ---- e0 ---- 1
#
# case index = sum of 2^k over the corners k that are above the level (f >= level).

#: Marching squares: for each case 0-15, the isoline segments as (from edge, to edge), each
#: oriented with the above corners on its left. Saddles 5 and 10 as when the centre is below.
SQUARE_TABLE = (
    (),                    # 0  all below: no isoline
    ((0, 3),),             # 1  corner 0 above: cut it off
    ((1, 0),),             # 2  corner 1 above
    ((1, 3),),             # 3  bottom row above: a horizontal line
    ((2, 1),),             # 4  corner 2 above
    ((0, 3), (2, 1)),      # 5  saddle (0 and 2 above), centre below: two corners cut off
    ((2, 0),),             # 6  right column above: a vertical line
    ((2, 3),),             # 7  only corner 3 below
    ((3, 2),),             # 8  corner 3 above
    ((0, 2),),             # 9  left column above
    ((1, 0), (3, 2)),      # 10 saddle (1 and 3 above), centre below
    ((1, 2),),             # 11 only corner 2 below
    ((3, 1),),             # 12 top row above
    ((0, 1),),             # 13 only corner 1 below
    ((3, 0),),             # 14 only corner 0 below
    (),                    # 15 all above: no isoline
)

#: The saddle cases when the centre (the mean of the four corners) is above the level: the two
#: above corners are joined through the centre and the two below corners are cut off.
SQUARE_SADDLES_CENTRE_ABOVE = {5: ((0, 1), (2, 3)), 10: ((3, 0), (1, 2))}


def _square_lookup():
    """(32, 2, 2) array: [case + 16 * centre_above] -> two (from, to) edge pairs, -1 = none."""
    table = np.full((32, 2, 2), -1, dtype=np.intp)
    for case, segments in enumerate(SQUARE_TABLE):
        for above in (0, 1):
            segs = SQUARE_SADDLES_CENTRE_ABOVE.get(case, segments) if above else segments
            for k, seg in enumerate(segs):
                table[case + 16 * above, k] = seg
    return table


_SQUARE_LOOKUP = _square_lookup()


def _square_cases(f, level):
    above = (f >= level).astype(np.uint8)
    return (above[:-1, :-1] | (above[:-1, 1:] << 1) | (above[1:, 1:] << 2)
            | (above[1:, :-1] << 3))


def marching_squares_cases(field, level):
    """The case index 0-15 of every cell: bit k is set when corner k is above the level.

    Corner 0 is ``field[i, j]`` (bottom left), 1 is ``field[i, j+1]``, 2 ``field[i+1, j+1]``,
    3 ``field[i+1, j]``, counter-clockwise; "above" means ``value >= level``.

    Parameters
    ----------
    field : array_like, shape (ny, nx)
    level : float

    Returns
    -------
    ndarray of int, shape (ny - 1, nx - 1)
        ``cases[i, j]`` for the cell between rows i, i+1 and columns j, j+1.

    Examples
    --------
    >>> marching_squares_cases([[0, 2, 0], [2, 0, 2]], 1)
    array([[10,  5]])
    """
    f = _grid(field, "field", 2)
    return _square_cases(f, as_scalar(level, "level")).astype(np.intp)


def saddle_centre_above(field, level):
    """The midpoint decider: is the mean of each cell's four corners above the level?

    Only the saddle cells (cases 5 and 10) use it: True joins their above corners through the
    centre (:data:`SQUARE_SADDLES_CENTRE_ABOVE`), False their below corners.

    Returns
    -------
    ndarray of bool, shape (ny - 1, nx - 1)

    Examples
    --------
    >>> saddle_centre_above([[0, 2], [3, 0]], 1), saddle_centre_above([[0, 2], [3, 0]], 1.5)
    (array([[ True]]), array([[False]]))
    """
    f = _grid(field, "field", 2)
    return _centres(f) >= as_scalar(level, "level")


def _centres(f):
    return 0.25 * (f[:-1, :-1] + f[:-1, 1:] + f[1:, 1:] + f[1:, :-1])


def asymptotic_decider(corners, level):
    r"""The asymptotic decider: the bilinear interpolant's value at its saddle point.

    Inside a cell with corner values :math:`f_0, f_1, f_2, f_3` (counter-clockwise from the
    bottom left, as everywhere in this module) the bilinear interpolant is
    :math:`f(s, t) = f_0 (1-s)(1-t) + f_1 s (1-t) + f_2 s t + f_3 (1-s) t`. Setting
    :math:`\partial f/\partial s = \partial f/\partial t = 0` gives its one critical point, a
    saddle, at :math:`s^* = (f_0 - f_3) / D`, :math:`t^* = (f_0 - f_1) / D` with
    :math:`D = f_0 + f_2 - f_1 - f_3`, where

    .. math:: f(s^*, t^*) = \frac{f_0 f_2 - f_1 f_3}{f_0 + f_2 - f_1 - f_3}

    (with :math:`a, b, c, d = f_{00}, f_{10}, f_{01}, f_{11}`: :math:`(ad - bc)/(a + d - b - c)`).
    If the saddle value is above the level (``>=``), the two above corners of a saddle cell are
    joined through the cell; otherwise the two below ones. Unlike the midpoint decider (the mean
    of the corners, :func:`saddle_centre_above`), this is what the bilinear field really does.

    Parameters
    ----------
    corners : array_like, shape (..., 4)
        :math:`f_0, f_1, f_2, f_3` of one cell or of many.
    level : float

    Returns
    -------
    saddle : float or ndarray, shape (...)
        The interpolant's value at its saddle point.
    above : bool or ndarray of bool, shape (...)
        ``saddle >= level``: the above corners are the ones joined.

    Raises
    ------
    ValueError
        For corners not of shape (..., 4), non-finite values, or a cell with
        :math:`f_0 + f_2 = f_1 + f_3`: its interpolant has no saddle point (it is never a
        marching-squares saddle, whose two diagonals lie on opposite sides of the level).

    Examples
    --------
    Corners 0, 4, 0, 10 at level 3: corners 1 and 3 are above (a saddle). The mean 3.5 says
    "join 1 and 3", the saddle value :math:`(0 - 40)/(0 - 14) = 2.857 < 3` says "keep them
    apart":

    >>> asymptotic_decider([0, 4, 0, 10], 3)
    (2.857142857142857, False)
    """
    f = as_array(corners, "corners")
    if f.ndim == 0 or f.shape[-1] != 4:
        raise ValueError(f"corners must have shape (..., 4): f0, f1, f2, f3 counter-clockwise "
                         f"from the bottom left, got shape {f.shape}")
    c = as_scalar(level, "level")
    den = f[..., 0] + f[..., 2] - f[..., 1] - f[..., 3]
    if np.any(den == 0):
        raise ValueError("corners: a cell with f0 + f2 == f1 + f3 has no saddle point (its "
                         "bilinear interpolant is a ruled surface without one); the decider "
                         "is only needed for saddle cells")
    saddle = (f[..., 0] * f[..., 2] - f[..., 1] * f[..., 3]) / den
    if saddle.ndim == 0:
        return float(saddle), bool(saddle >= c)
    return saddle, saddle >= c


def _saddle_values(f, mask):
    """The asymptotic decider's saddle values of the cells selected by `mask` (saddles)."""
    cells = np.stack([f[:-1, :-1][mask], f[:-1, 1:][mask], f[1:, 1:][mask], f[1:, :-1][mask]],
                     axis=-1)
    return asymptotic_decider(cells, 0.0)[0]


# edge -> (row offset, column offset) of its canonical start corner, and its direction
# (0: along x (columns), 1: along y (rows))
_SQ_EDGE_START = np.array([[0, 0], [0, 1], [1, 0], [0, 0]])
_SQ_EDGE_AXIS = np.array([0, 1, 0, 1])


def _square_points(f, level, rows, cols, edges):
    """Crossing points (row, col index coordinates) on cell edges, computed per *grid* edge.

    The grid edge is always interpolated from its lower-index end, so two cells sharing an edge
    get bit-identical points (which lets :func:`join_segments` chain them exactly).
    """
    r0 = rows + _SQ_EDGE_START[edges, 0]
    c0 = cols + _SQ_EDGE_START[edges, 1]
    along_y = _SQ_EDGE_AXIS[edges] == 1
    r1, c1 = r0 + along_y, c0 + ~along_y
    f0, f1 = f[r0, c0], f[r1, c1]
    t = (level - f0) / (f1 - f0)
    return np.stack([r0 + t * along_y, c0 + t * ~along_y], axis=-1)


def marching_squares(field, level, spacing=(1.0, 1.0), origin=(0.0, 0.0), saddles="midpoint",
                     cells=None, decider="midpoint"):
    r"""Isoline segments of a 2D field by marching squares.

    For each cell: the case index (:func:`marching_squares_cases`), the table
    :data:`SQUARE_TABLE` (saddles 5 and 10 resolved by the midpoint decider,
    :func:`saddle_centre_above`), and on each crossed edge the point of linear interpolation
    :math:`p = p_0 + t (p_1 - p_0)`, :math:`t = (c - f_0) / (f_1 - f_0)`.

    Parameters
    ----------
    field : array_like, shape (ny, nx)
        ``field[i, j]`` is the sample at :math:`x = x_0 + j \Delta x`, :math:`y = y_0 + i \Delta y`.
    level : float
        The isovalue c. A level outside the data range gives no segments (not an error).
    spacing : (float, float)
        :math:`(\Delta x, \Delta y)`, positive.
    origin : (float, float)
        :math:`(x_0, y_0)`, the position of ``field[0, 0]``.
    saddles : {"midpoint", "decider", "opposite"}
        How a saddle cell (case 5 or 10) pairs its four crossings: ``"midpoint"`` (the old
        name, kept) or ``"decider"``: as the `decider` says; ``"opposite"`` the other way, the
        reading the decider rejects (the same four points, joined the other way round: what
        the isoline would look like had the decider answered differently).
    cells : array_like of bool, shape (ny - 1, nx - 1), optional
        March only the cells where this is True (default all), e.g. the saddle cells
        ``np.isin(marching_squares_cases(field, level), (5, 10))``.
    decider : {"midpoint", "asymptotic"}
        What stands for the value at a saddle cell's centre: the mean of its four corners
        (:func:`saddle_centre_above`, the default) or the bilinear interpolant's saddle value
        (:func:`asymptotic_decider`, which agrees with the bilinear field's own isoline).

    Returns
    -------
    ndarray, shape (m, 2, 2)
        m segments, each (start, end) as (x, y) points, oriented with higher values on the left.
        Cells are visited row by row; a segment ends where the next one of its isoline may
        start, with bit-identical coordinates (see :func:`join_segments`). A sample exactly at
        the level counts as above; where the isoline passes exactly through a sample, the
        zero-length pieces this makes are left out.

    Raises
    ------
    ValueError
        For a field that is not 2D with at least 2 x 2 samples, NaN in the field, a
        non-positive spacing, an unknown `saddles` or `decider`, or a `cells` mask of the
        wrong shape.

    Examples
    --------
    One cell with only its bottom-left corner above 1: the isoline cuts that corner off, from
    the bottom edge to the left edge (the corner on the left of the direction of travel):

    >>> marching_squares([[2, 0], [0, 0]], 1)
    array([[[0.5, 0. ],
            [0. , 0.5]]])

    A saddle cell, corners 0 and 2 above 1 (case 5), mean 1.5 >= 1: the midpoint decider joins
    them through the centre (edge 0 to edge 1, edge 2 to edge 3); the rejected reading cuts
    corners 0 and 2 off separately (edge 0 to edge 3, edge 2 to edge 1):

    >>> marching_squares([[3, 0], [0, 3]], 1.0, saddles="opposite")
    array([[[0.66666667, 0.        ],
            [0.        , 0.66666667]],
    <BLANKLINE>
           [[0.33333333, 1.        ],
            [1.        , 0.33333333]]])
    """
    f = _grid(field, "field", 2)
    c = as_scalar(level, "level")
    dx, dy = _spacing(spacing, 2)
    x0, y0 = as_vector(origin, "origin", 2)
    as_choice(saddles, "saddles", ("midpoint", "decider", "opposite"))
    as_choice(decider, "decider", ("midpoint", "asymptotic"))
    cases = _square_cases(f, c).astype(np.intp)
    saddle = (cases == 5) | (cases == 10)
    ext = cases.copy()
    if saddle.any():
        centre = _centres(f)[saddle] if decider == "midpoint" else _saddle_values(f, saddle)
        centre_above = centre >= c
        ext[saddle] += 16 * (~centre_above if saddles == "opposite" else centre_above)
    segs = _SQUARE_LOOKUP[ext]                            # (ny-1, nx-1, 2, 2)
    if cells is not None:
        marched = np.asarray(cells)
        if marched.shape != cases.shape or marched.dtype != bool:
            raise ValueError(f"cells must be a boolean mask of shape {cases.shape} (one value "
                             f"per cell), got shape {marched.shape} and type {marched.dtype}")
        segs = np.where(marched[..., None, None], segs, -1)
    rows, cols, slot = np.nonzero(segs[..., 0] >= 0)
    edges = segs[rows, cols, slot]                        # (m, 2): from edge, to edge
    start = _square_points(f, c, rows, cols, edges[:, 0])
    end = _square_points(f, c, rows, cols, edges[:, 1])
    # an isoline through a sample itself gives zero-length pieces next to it: drop them
    keep = (start != end).any(axis=1)
    ij = np.stack([start[keep], end[keep]], axis=1)       # (m, 2, (row, col))
    return np.stack([x0 + ij[..., 1] * dx, y0 + ij[..., 0] * dy], axis=-1)


def join_segments(segments):
    """Chain segments head to tail into polylines.

    A segment whose start point equals (exactly) the end point of another continues it. This
    is how :func:`marching_squares` output becomes whole isolines: its segments are oriented
    consistently and neighbouring cells compute shared points identically.

    Parameters
    ----------
    segments : array_like, shape (m, 2, d)

    Returns
    -------
    list of ndarray, each shape (k, d)
        The polylines, longest first; a closed one repeats its first point at the end.

    Examples
    --------
    >>> lines = join_segments([[[1, 0], [1, 1]], [[0, 0], [1, 0]], [[1, 1], [0, 0]]])
    >>> lines[0]
    array([[1., 0.],
           [1., 1.],
           [0., 0.],
           [1., 0.]])
    """
    segs = as_array(segments, "segments")
    if segs.size == 0:
        return []
    if segs.ndim != 3 or segs.shape[1] != 2 or segs.shape[2] not in (2, 3):
        raise ValueError(f"segments must have shape (m, 2, 2) or (m, 2, 3), got shape "
                         f"{segs.shape}")
    segs = segs + 0.0                                     # -0.0 and 0.0 are the same point
    starts = {p.tobytes(): k for k, p in enumerate(segs[:, 0])}
    nxt = np.array([starts.get(p.tobytes(), -1) for p in segs[:, 1]])
    has_prev = np.zeros(len(segs), bool)
    has_prev[nxt[nxt >= 0]] = True
    used = np.zeros(len(segs), bool)
    lines = []
    # open chains first (they start at a segment nothing leads into), then the closed loops
    for first in list(np.flatnonzero(~has_prev)) + list(range(len(segs))):
        if used[first]:
            continue
        chain, k = [first], nxt[first]
        used[first] = True
        while k >= 0 and not used[k]:
            chain.append(k)
            used[k] = True
            k = nxt[k]
        lines.append(np.concatenate([segs[chain, 0], segs[chain[-1:], 1]]))
    lines.sort(key=len, reverse=True)
    return lines


def isolines(field, level, spacing=(1.0, 1.0), origin=(0.0, 0.0), decider="midpoint"):
    """The isolines of a 2D field as polylines: :func:`marching_squares` + :func:`join_segments`.

    `decider` ("midpoint" or "asymptotic") resolves the saddle cells, as in
    :func:`marching_squares`.

    Returns
    -------
    list of ndarray, each shape (k, 2)
        (x, y) polylines, higher values on the left; closed ones end with their first point.

    Examples
    --------
    >>> from course_lib.scivis import example_field_2d
    >>> f = example_field_2d("circle", size=41)
    >>> lines = isolines(f.values, 0.6, f.spacing, f.origin)
    >>> len(lines), bool(np.allclose(lines[0][0], lines[0][-1]))
    (1, True)
    """
    return join_segments(marching_squares(field, level, spacing, origin, decider=decider))
