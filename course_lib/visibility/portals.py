"""Chapter 5, occlusion culling from a region (lesson section 4.2): cells, portals, PVS."""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_points, as_scalar, as_vector

__all__ = ["FloorPlan", "PointVisibility", "cell_of", "example_floor_plan", "floor_plan", "pvs",
    "stabbing_line", "visible_from_point", "walls"]


# ---------------------------------------------------------------------------------------------
# From-region occlusion culling: cells, portals and potentially visible sets
# ---------------------------------------------------------------------------------------------

class FloorPlan(NamedTuple):
    """A 2D floor plan of rectangular cells joined by portals (:func:`floor_plan`).

    Attributes
    ----------
    cells : ndarray, shape (n, 4)
        ``(xmin, ymin, xmax, ymax)`` per cell.
    portals : ndarray, shape (m, 2, 2)
        Each portal's two endpoints, on the wall shared by its two cells.
    links : ndarray of int, shape (m, 2)
        The two cells each portal joins.

    Examples
    --------
    >>> plan = example_floor_plan()
    >>> plan.cells.shape, plan.portals.shape, plan.links.shape
    ((9, 4), (8, 2, 2), (8, 2))
    """
    cells: np.ndarray
    portals: np.ndarray
    links: np.ndarray


def floor_plan(cells, portals, links):
    """Check and bundle a floor plan of axis-aligned rectangular cells and door portals.

    Every cell boundary is wall except where a portal opens it. A portal is a segment lying on
    the wall shared by the two cells it links (vertical or horizontal), inside both cells' sides.

    Parameters
    ----------
    cells : array_like, shape (n, 4)
        ``(xmin, ymin, xmax, ymax)`` per cell; cells must not overlap.
    portals : array_like, shape (m, 2, 2)
        Segments ``[[x0, y0], [x1, y1]]``.
    links : array_like of int, shape (m, 2)
        The two cells each portal joins.

    Returns
    -------
    FloorPlan

    Raises
    ------
    ValueError
        For empty or malformed cells, overlapping cells, or a portal not on its cells' shared
        wall.

    Examples
    --------
    Two rooms side by side with a door in the middle of their shared wall:

    >>> plan = floor_plan([[0, 0, 2, 2], [2, 0, 4, 2]], [[[2, 0.5], [2, 1.5]]], [[0, 1]])
    >>> pvs(plan).tolist()
    [[True, True], [True, True]]
    """
    c = as_array(cells, "cells")
    if c.ndim != 2 or c.shape[1] != 4 or len(c) == 0:
        raise ValueError(f"cells must be an (n, 4) array of (xmin, ymin, xmax, ymax), n >= 1, "
                         f"got shape {c.shape}")
    if np.any(c[:, 2] <= c[:, 0]) or np.any(c[:, 3] <= c[:, 1]):
        raise ValueError("cells must have xmin < xmax and ymin < ymax")
    ox = (np.minimum(c[:, None, 2], c[None, :, 2]) - np.maximum(c[:, None, 0], c[None, :, 0]))
    oy = (np.minimum(c[:, None, 3], c[None, :, 3]) - np.maximum(c[:, None, 1], c[None, :, 1]))
    overlap = (ox > 0) & (oy > 0)
    np.fill_diagonal(overlap, False)
    if overlap.any():
        i, j = np.argwhere(overlap)[0]
        raise ValueError(f"cells {i} and {j} overlap")
    p = as_array(portals, "portals")
    if p.size == 0:
        p = p.reshape(0, 2, 2)
    if p.ndim != 3 or p.shape[1:] != (2, 2):
        raise ValueError(f"portals must be an (m, 2, 2) array of segments, got shape {p.shape}")
    lk = np.asarray(links)
    if lk.size == 0:
        lk = lk.reshape(0, 2).astype(np.intp)
    if lk.shape != (len(p), 2) or not np.issubdtype(lk.dtype, np.integer):
        raise ValueError(f"links must be an ({len(p)}, 2) integer array, got shape {lk.shape}")
    if len(lk) and (lk.min() < 0 or lk.max() >= len(c) or np.any(lk[:, 0] == lk[:, 1])):
        raise ValueError("links must join two different existing cells")
    tol = 1e-9 * max(1.0, float(np.abs(c).max()))
    for k, ((a, b), seg) in enumerate(zip(lk, p)):
        ca, cb = c[a], c[b]
        if abs(seg[0, 0] - seg[1, 0]) <= tol and abs(seg[0, 1] - seg[1, 1]) > tol:
            axis = 0                          # vertical portal, x constant
        elif abs(seg[0, 1] - seg[1, 1]) <= tol and abs(seg[0, 0] - seg[1, 0]) > tol:
            axis = 1
        else:
            raise ValueError(f"portal {k} must be a vertical or horizontal segment of non-zero "
                             f"length, got {seg.tolist()}")
        x = seg[0, axis]
        on_wall = ((abs(ca[axis + 2] - x) <= tol and abs(cb[axis] - x) <= tol)
                   or (abs(cb[axis + 2] - x) <= tol and abs(ca[axis] - x) <= tol))
        o = 1 - axis
        lo, hi = seg[:, o].min(), seg[:, o].max()
        within = all(cell[o] - tol <= lo and hi <= cell[o + 2] + tol for cell in (ca, cb))
        if not (on_wall and within):
            raise ValueError(f"portal {k} does not lie on the wall shared by cells {a} and {b}")
    return FloorPlan(c, p, lk.astype(np.intp))


def example_floor_plan():
    """A U-shaped row of 9 rooms: a corridor along the bottom, up the right, back along the top.

    Rooms are 2 x 2 with 1-wide doors in the middle of the shared walls::

        8 - 7 - 6 - 5          (y from 4 to 6)
                    |
                    4          (y from 2 to 4)
                    |
        0 - 1 - 2 - 3          (y from 0 to 2)

    Along a straight row every room sees every other; around one corner only rooms near it see
    each other (1 sees 4, 0 does not); around two corners nothing is visible (0 and 8, 2 and 6).

    Returns
    -------
    FloorPlan

    Examples
    --------
    >>> plan = example_floor_plan()
    >>> V = pvs(plan)
    >>> bool(V[0, 3]), bool(V[1, 4]), bool(V[0, 4]), bool(V[0, 8]), bool(V[2, 6])
    (True, True, False, False, False)
    """
    cells = [[0, 0, 2, 2], [2, 0, 4, 2], [4, 0, 6, 2], [6, 0, 8, 2], [6, 2, 8, 4],
             [6, 4, 8, 6], [4, 4, 6, 6], [2, 4, 4, 6], [0, 4, 2, 6]]
    portals = [[[2, 0.5], [2, 1.5]], [[4, 0.5], [4, 1.5]], [[6, 0.5], [6, 1.5]],
               [[6.5, 2], [7.5, 2]], [[6.5, 4], [7.5, 4]], [[6, 4.5], [6, 5.5]],
               [[4, 4.5], [4, 5.5]], [[2, 4.5], [2, 5.5]]]
    links = [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [6, 7], [7, 8]]
    return floor_plan(cells, portals, links)


def _as_plan(plan):
    if not isinstance(plan, FloorPlan):
        raise TypeError(f"plan must be a FloorPlan (see floor_plan()), got "
                        f"{type(plan).__name__}")
    return plan


def walls(plan):
    """The wall segments of a floor plan: every cell side minus the portals on it.

    A wall shared by two cells of equal extent is listed once; partly shared walls may appear
    twice (harmless for drawing and intersection tests).

    Parameters
    ----------
    plan : FloorPlan

    Returns
    -------
    ndarray, shape (w, 2, 2)

    Raises
    ------
    TypeError
        If `plan` is not a FloorPlan.

    Examples
    --------
    >>> plan = floor_plan([[0, 0, 2, 2], [2, 0, 4, 2]], [[[2, 0.5], [2, 1.5]]], [[0, 1]])
    >>> len(walls(plan))          # 3 + 3 outer sides, the shared wall in 2 pieces
    8
    """
    plan = _as_plan(plan)
    out, seen = [], set()
    for k, (x0, y0, x1, y1) in enumerate(plan.cells):
        sides = [(0, x0, y0, y1), (0, x1, y0, y1), (1, y0, x0, x1), (1, y1, x0, x1)]
        mine = [m for m in range(len(plan.links)) if k in plan.links[m]]
        for axis, at, lo, hi in sides:
            gaps = []
            for m in mine:
                seg = plan.portals[m]
                if abs(seg[0, axis] - at) < 1e-12 and abs(seg[1, axis] - at) < 1e-12:
                    gaps.append(tuple(sorted(seg[:, 1 - axis])))
            pieces, start = [], lo
            for g0, g1 in sorted(gaps):
                if g0 > start:
                    pieces.append((start, g0))
                start = max(start, g1)
            if hi > start:
                pieces.append((start, hi))
            for a, b in pieces:
                seg = [[at, a], [at, b]] if axis == 0 else [[a, at], [b, at]]
                key = tuple(np.round(np.ravel(seg), 12))
                if key not in seen:
                    seen.add(key)
                    out.append(seg)
    return np.array(out, dtype=float).reshape(-1, 2, 2)


def _cross2(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def stabbing_line(left, right, tol=1e-9):
    r"""A line through a sequence of portals in 2D, or None if there is none.

    Orient each portal by the direction of travel through it (from the cell before to the cell
    after); its endpoints are then a *left* point :math:`L_i` and a *right* point :math:`R_i`.
    A directed line crosses every portal, in the direction of travel, exactly when it has all
    :math:`L_i` on its left and all :math:`R_i` on its right: a line *separating* the two point
    sets. (For convex cells the crossings then come in the right order by themselves.)

    For a direction :math:`d(\theta)` with left normal :math:`n`, such a line exists when
    :math:`g(\theta) = \min_i n \cdot L_i - \max_j n \cdot R_j \ge 0`, and the direction must
    cross each portal forwards, :math:`d \cdot t_i > 0`. :math:`g` is a minimum of sinusoids, so
    its maximum is reached at a direction through two endpoints, a direction perpendicular to
    some :math:`L_i - R_j`, or at the end of the allowed arc of directions: only those finitely
    many candidates are tried, vectorized. Cost :math:`O(k^3)` for :math:`k` portals. Touching
    an endpoint counts as passing (the test errs towards "visible": conservative).

    Parameters
    ----------
    left, right : array_like, shape (k, 2)
        The left and right endpoints of the portals, in order of travel.
    tol : float, optional
        Relative tolerance (times the points' extent).

    Returns
    -------
    (point, direction) : tuple of two ndarrays (2,), or None
        A point on a stabbing line and its unit direction (the most clearance found).

    Raises
    ------
    ValueError
        For malformed or mismatched point arrays.

    Examples
    --------
    Two doors at the same height can be seen through; shift the second one up by more than its
    width (and the walls 1 apart) and the first door is too narrow to see through both:

    >>> stabbing_line([[0, 1], [1, 1]], [[0, 0], [1, 0]]) is not None
    True
    >>> stabbing_line([[0, 1], [1, 1], [2, 1]], [[0, 0], [1, 0], [2, 0]]) is not None
    True
    >>> stabbing_line([[0, 1], [1, 1], [2, 4]], [[0, 0], [1, 0], [2, 3]]) is None
    True
    """
    L = as_points(left, "left", dims=2)
    R = as_points(right, "right", dims=2)
    if L.ndim != 2 or L.shape != R.shape or len(L) == 0:
        raise ValueError(f"left and right must both have shape (k, 2), k >= 1, got {L.shape} "
                         f"and {R.shape}")
    span = L - R
    travel = np.stack([span[:, 1], -span[:, 0]], axis=-1)     # L - R turned clockwise
    if np.any(np.abs(travel).max(axis=1) == 0):
        raise ValueError("each portal must have two distinct endpoints")
    travel /= np.linalg.norm(travel, axis=1, keepdims=True)
    pts = np.concatenate([L, R])
    diff = (pts[:, None] - pts[None]).reshape(-1, 2)
    lr = (L[:, None] - R[None]).reshape(-1, 2)
    perp = np.stack([lr[:, 1], -lr[:, 0]], axis=-1)
    perp = np.concatenate([perp, -perp])
    delta = 1e-7
    arc = []
    for s in (1, -1):
        ang = s * (np.pi / 2 - delta)
        rot = np.array([[np.cos(ang), -np.sin(ang)], [np.sin(ang), np.cos(ang)]])
        arc.append(travel @ rot.T)
    cand = np.concatenate([diff, -diff, perp, *arc, travel])
    length = np.linalg.norm(cand, axis=1)
    cand = cand[length > 0] / length[length > 0, None]
    forward = np.all(cand @ travel.T > 1e-12, axis=1)
    cand = cand[forward]
    if len(cand) == 0:
        return None
    n = np.stack([-cand[:, 1], cand[:, 0]], axis=-1)
    nl, nr = n @ L.T, n @ R.T
    g = nl.min(axis=1) - nr.max(axis=1)
    scale = max(float(np.abs(pts - pts.mean(axis=0)).max()), 1e-300)
    best = int(np.argmax(g))
    if g[best] < -tol * scale:
        return None
    c = (nl[best].min() + nr[best].max()) / 2
    return n[best] * c, cand[best]


def _portal_sides(plan, m, from_cell):
    """Left and right endpoints of portal m when crossing it out of `from_cell`."""
    seg = plan.portals[m]
    mid = seg.mean(axis=0)
    cell = plan.cells[from_cell]
    centre = np.array([(cell[0] + cell[2]) / 2, (cell[1] + cell[3]) / 2])
    along = seg[1] - seg[0]
    normal = np.array([along[1], -along[0]])
    if normal @ (mid - centre) < 0:
        normal = -normal                                     # travel: out of from_cell
    if _cross2(normal, seg[0] - mid) > 0:
        return seg[0], seg[1]
    return seg[1], seg[0]


def _neighbours(plan):
    adj = [[] for _ in range(len(plan.cells))]
    for m, (a, b) in enumerate(plan.links):
        adj[a].append((m, int(b)))
        adj[b].append((m, int(a)))
    return adj


def pvs(plan, return_witnesses=False):
    r"""The potentially visible set of every cell: a cells x cells boolean matrix.

    Cell B is potentially visible from cell A when some sight line leaves A and reaches B
    through walls' openings only, i.e. through a sequence of portals A -> ... -> B that a single
    line can stab (:func:`stabbing_line`). A depth-first search from each cell extends portal
    sequences one portal at a time and abandons a sequence as soon as it is no longer stabbable
    (a longer sequence can only be harder to stab). The matrix is computed once, offline; at run
    time the renderer draws only the cells in the current cell's row. It is reflexive and
    symmetric, and a cell always sees its neighbours through their shared portal.

    Conservative: lines touching a portal's endpoint count as passing, so a cell glimpsed only
    along a wall is included. Cost: in the worst case exponential in the number of cells (every
    path is followed); in practice the stabbing test prunes paths after a few portals.

    Parameters
    ----------
    plan : FloorPlan
    return_witnesses : bool, optional
        Also return, for each visible pair (A, B) with A != B, one portal path and stabbing line
        ``(cells, portals, (point, direction))``, for drawing.

    Returns
    -------
    visible : ndarray of bool, shape (n, n)
    witnesses : dict
        Only with `return_witnesses`.

    Raises
    ------
    TypeError
        If `plan` is not a FloorPlan.

    Examples
    --------
    >>> V = pvs(example_floor_plan())
    >>> np.nonzero(V[0])[0].tolist(), np.nonzero(V[3])[0].tolist()
    ([0, 1, 2, 3], [0, 1, 2, 3, 4, 5, 6])
    """
    plan = _as_plan(plan)
    n = len(plan.cells)
    adj = _neighbours(plan)
    visible = np.eye(n, dtype=bool)
    witnesses = {}
    for src in range(n):
        stack = [(src, (src,), (), np.zeros((0, 2)), np.zeros((0, 2)))]
        while stack:
            cell, path, ports, L, R = stack.pop()
            for m, nb in adj[cell]:
                if nb in path:
                    continue
                left, right = _portal_sides(plan, m, cell)
                L2, R2 = np.vstack([L, left]), np.vstack([R, right])
                line = stabbing_line(L2, R2)
                if line is None:
                    continue
                visible[src, nb] = True
                if return_witnesses and (src, nb) not in witnesses:
                    witnesses[src, nb] = (path + (nb,), ports + (m,), line)
                stack.append((nb, path + (nb,), ports + (m,), L2, R2))
    return (visible, witnesses) if return_witnesses else visible


def cell_of(plan, points):
    """The cell containing each point (-1 outside all cells; on a shared wall, the lower index).

    Parameters
    ----------
    plan : FloorPlan
    points : array_like, shape (..., 2)

    Returns
    -------
    ndarray of int, shape (...)

    Examples
    --------
    >>> cell_of(example_floor_plan(), [[1, 1], [7, 3], [3, 3]]).tolist()
    [0, 4, -1]
    """
    plan = _as_plan(plan)
    p = as_points(points, "points", dims=2)
    c = plan.cells
    inside = ((p[..., None, 0] >= c[:, 0]) & (p[..., None, 0] <= c[:, 2])
              & (p[..., None, 1] >= c[:, 1]) & (p[..., None, 1] <= c[:, 3]))
    return np.where(inside.any(axis=-1), np.argmax(inside, axis=-1), -1)


class PointVisibility(NamedTuple):
    """The result of :func:`visible_from_point`.

    Attributes
    ----------
    visible : ndarray of bool, shape (n,)
        Cells seen (at least partly) from the point.
    views : list of (int, tuple of int, ndarray (2,), ndarray (2,))
        For each portal path followed: the cell reached, the portals crossed, and the right
        and left bounding directions of the wedge of sight lines that reach it.

    Examples
    --------
    >>> vis = visible_from_point(example_floor_plan(), [1, 1])
    >>> vis.views[0][:2]
    (1, (0,))
    """
    visible: np.ndarray
    views: list


def _rotate2(v, angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])


def visible_from_point(plan, point, direction=None, fov=None):
    r"""The cells visible from one point (optionally within a field of view), through portals.

    From the viewer's cell, each portal is seen under a wedge of directions, bounded by the rays
    to its right and left endpoints. Passing through a sequence of portals intersects their
    wedges; a cell is visible while the wedge leading into it is not empty. This is the run-time
    cousin of :func:`pvs` (cells-and-portals rendering): it needs no precomputation and gives a
    tighter set, but costs a traversal per frame.

    Parameters
    ----------
    plan : FloorPlan
    point : array_like, shape (2,)
        The viewer, inside some cell.
    direction : array_like, shape (2,), optional
        Viewing direction; with `fov`, only sight lines within ``fov / 2`` of it count.
    fov : float, optional
        Field of view in radians, in (0, pi).

    Returns
    -------
    PointVisibility

    Raises
    ------
    ValueError
        For a point outside all cells, or a field of view without a direction or outside
        (0, pi).

    Examples
    --------
    >>> plan = example_floor_plan()
    >>> np.nonzero(visible_from_point(plan, [1, 1]).visible)[0].tolist()
    [0, 1, 2, 3]
    >>> np.nonzero(visible_from_point(plan, [1, 1], [-1, 0], np.radians(60)).visible)[0].tolist()
    [0]
    """
    plan = _as_plan(plan)
    p = as_vector(point, "point", 2)
    start = int(cell_of(plan, p))
    if start < 0:
        raise ValueError(f"point {p.tolist()} is not inside any cell of the floor plan")
    wedge = None
    if (direction is None) != (fov is None):
        raise ValueError("give both direction and fov, or neither")
    if fov is not None:
        fov = as_scalar(fov, "fov")
        if not 0 < fov < np.pi:
            raise ValueError(f"fov must be an angle in radians between 0 and pi, got {fov}")
        d = as_vector(direction, "direction", 2)
        if not np.any(d):
            raise ValueError("direction must not be the zero vector")
        d = d / np.linalg.norm(d)
        wedge = (_rotate2(d, -fov / 2), _rotate2(d, fov / 2))
    adj = _neighbours(plan)
    visible = np.zeros(len(plan.cells), dtype=bool)
    visible[start] = True
    views = []
    stack = [(start, (start,), (), wedge)]
    while stack:
        cell, path, ports, w = stack.pop()
        for m, nb in adj[cell]:
            if nb in path:
                continue
            left, right = _portal_sides(plan, m, cell)
            a, b = left - p, right - p
            if _cross2(b, a) <= 0:                   # portal not facing the viewer
                continue
            if w is None:
                r, l = b, a
            else:
                r = b if _cross2(w[0], b) > 0 else w[0]       # the more counter-clockwise right
                l = a if _cross2(a, w[1]) > 0 else w[1]       # the more clockwise left
                bis = r / np.linalg.norm(r) + l / np.linalg.norm(l)
                inside_both = all(_cross2(x, bis) >= 0 and _cross2(bis, y) >= 0
                                  for x, y in ((w[0], w[1]), (b, a)))
                if _cross2(r, l) < 0 or not inside_both:
                    continue
            visible[nb] = True
            views.append((nb, ports + (m,), r, l))
            stack.append((nb, path + (nb,), ports + (m,), (r, l)))
    return PointVisibility(visible, views)
