r"""Chapter 5: clipping in homogeneous coordinates (clip space), before the perspective divide.

A projection matrix maps the view volume onto the cube :math:`[-1, 1]^3` of NDC *after* the
divide by w. Multiplying :math:`-1 \le x/w \le 1` by w gives, for :math:`w > 0`, the six linear
conditions of clip space

.. math:: -w \le x \le w, \qquad -w \le y \le w, \qquad -w \le z \le w,

i.e. six *boundary functions* that are non-negative inside:

=======  =========================  ====  ==========
bit      side                       f_k   inside
=======  =========================  ====  ==========
0 (1)    left   :math:`x \ge -w`    w + x  f_k >= 0
1 (2)    right  :math:`x \le w`     w - x  f_k >= 0
2 (4)    bottom :math:`y \ge -w`    w + y  f_k >= 0
3 (8)    top    :math:`y \le w`     w - y  f_k >= 0
4 (16)   near   :math:`z \ge -w`    w + z  f_k >= 0
5 (32)   far    :math:`z \le w`     w - z  f_k >= 0
=======  =========================  ====  ==========

(the bit order of :data:`course_lib.clipping.BIT_NAMES`). Each f_k is *linear* in the
homogeneous point, so along a segment :math:`P(t) = P_0 + t (P_1 - P_0)` it is
:math:`f_k(t) = f_k(P_0) + t\,(f_k(P_1) - f_k(P_0))` and Liang-Barsky and Sutherland-Hodgman
work unchanged, with :math:`p_k = f_k(P_0) - f_k(P_1)` and :math:`q_k = f_k(P_0)`
(the condition :math:`p_k t \le q_k`). For :math:`w = 1` these are the familiar box pairs.

Why clip before the divide: a point behind the eye has :math:`w < 0`, and dividing by a negative
w mirrors it through the centre of the screen. A segment whose end points lie on both sides of
the eye plane (w changes sign) passes through :math:`w = 0`, where its image goes through
infinity: after the divide the straight NDC segment between the two divided end points is the
image of the *rest* of the line (the part through infinity), not of the segment
(:func:`clip_after_divide` shows the wrong result). No point with :math:`w \le 0` satisfies the
six conditions (they need :math:`w \ge |x|`), so clipping in clip space removes everything
behind the eye before anything is divided.
"""
import numpy as np

from . import clipping
from ._validate import as_points

__all__ = [
    "boundary_values",
    "clip_after_divide",
    "clip_outcode",
    "clip_polygon_homogeneous",
    "clip_polygon_homogeneous_steps",
    "clip_segment_homogeneous",
    "clip_segments_homogeneous",
    "clip_space_planes",
    "liang_barsky_table",
    "table_text",
]

_AXIS_SIGN = tuple((k // 2, 1.0 if k % 2 == 0 else -1.0) for k in range(6))   # f = w + s x_axis


def _clip_points(value, name):
    """Homogeneous points, shape (..., 4), none of them the zero vector."""
    p = as_points(value, name, dims=4)
    if np.any(np.all(p == 0, axis=-1)):
        raise ValueError(f"{name} contains the zero vector (0, 0, 0, 0), which is no "
                         "homogeneous point")
    return p


def boundary_values(points_h):
    r"""The six clip-space boundary functions :math:`f_k` of homogeneous points (>= 0 inside).

    In the order left, right, bottom, top, near, far:
    :math:`(w + x, w - x, w + y, w - y, w + z, w - z)`.

    Parameters
    ----------
    points_h : array_like, shape (..., 4)
        Clip coordinates (x, y, z, w).

    Returns
    -------
    ndarray, shape (..., 6)

    Raises
    ------
    ValueError
        For points without 4 coordinates or the zero vector.

    Examples
    --------
    >>> boundary_values([1, 2, -3, 2]).tolist()
    [3.0, 1.0, 4.0, 0.0, -1.0, 5.0]
    """
    p = _clip_points(points_h, "points_h")
    w = p[..., 3:4]
    xyz = np.repeat(p[..., :3], 2, axis=-1)              # x x y y z z
    return w + np.array([1.0, -1.0] * 3) * xyz


def clip_outcode(points_h):
    r"""The 6-bit outcode of homogeneous points against :math:`-w \le x, y, z \le w`.

    Bit k is set when :math:`f_k < 0` (see the module's table): bit 0 for
    :math:`x < -w` (left), bit 1 for :math:`x > w` (right), ... bit 5 for :math:`z > w` (far),
    as :data:`course_lib.clipping.BIT_NAMES`. No division: the test works for :math:`w \le 0`
    too, where a point always gets a non-zero code (it is behind the eye or at infinity). For
    :math:`w > 0` the code equals :func:`course_lib.clipping.outcode` of the divided point
    against :math:`[-1, 1]^3`.

    Parameters
    ----------
    points_h : array_like, shape (..., 4)

    Returns
    -------
    int or ndarray of int, shape (...)

    Examples
    --------
    >>> clip_outcode([[0.5, 0, 0, 1], [3, 0, 0, 2], [0, 0, 0, -1]]).tolist()
    [0, 2, 63]
    """
    f = boundary_values(points_h)
    code = ((f < 0) << np.arange(6)).sum(axis=-1).astype(np.int64)
    return int(code) if code.ndim == 0 else code


def clip_space_planes():
    r"""The six clip-space half-spaces as ``(name, normal, offset)``, inside :math:`n \cdot P \le 0`.

    Planes through the origin of 4D homogeneous space: the normal of side k is
    :math:`-\nabla f_k`, e.g. left :math:`(-1, 0, 0, -1)`, right :math:`(1, 0, 0, -1)`.

    Returns
    -------
    list of (str, ndarray of shape (4,), float)

    Examples
    --------
    >>> [(name, n.tolist()) for name, n, c in clip_space_planes()][:2]
    [('left', [-1.0, 0.0, 0.0, -1.0]), ('right', [1.0, 0.0, 0.0, -1.0])]
    """
    planes = []
    for k, (axis, sign) in enumerate(_AXIS_SIGN):
        n = np.zeros(4)
        n[axis], n[3] = -sign, -1.0
        planes.append((clipping.BIT_NAMES[k], n, 0.0))
    return planes


def _lb_rows(f0, f1):
    """Liang-Barsky over six boundary-function values at the two ends: rows and the interval."""
    t_in, t_out = 0.0, 1.0
    rows = []
    for k in range(6):
        p, q = float(f0[k] - f1[k]), float(f0[k])
        row = {"side": clipping.BIT_NAMES[k], "p": p, "q": q, "t": None}
        if p == 0:
            row["kind"] = "parallel inside" if q >= 0 else "parallel outside"
            if q < 0:
                t_in, t_out = 1.0, 0.0
        else:
            t = q / p
            row["t"] = t
            if p < 0:
                row["kind"] = "entering"
                t_in = max(t_in, t)
            else:
                row["kind"] = "leaving"
                t_out = min(t_out, t)
        row["t_in"], row["t_out"] = float(t_in), float(t_out)
        rows.append(row)
    return rows, t_in, t_out


def clip_segment_homogeneous(p0_h, p1_h):
    r"""Liang-Barsky in clip space: the segment :math:`P_0 P_1` against :math:`-w \le x,y,z \le w`.

    For each side :math:`p_k = f_k(P_0) - f_k(P_1)`, :math:`q_k = f_k(P_0)`
    (left: :math:`p = -(\Delta w + \Delta x)`, :math:`q = w_0 + x_0`; right:
    :math:`p = \Delta x - \Delta w`, :math:`q = w_0 - x_0`; ...). :math:`p_k < 0` enters
    (:math:`t_{in} = \max(t_{in}, q_k/p_k)`), :math:`p_k > 0` leaves
    (:math:`t_{out} = \min(t_{out}, q_k/p_k)`), :math:`p_k = 0, q_k < 0` rejects. Unlike
    :func:`course_lib.clipping.liang_barsky_steps` all six rows are computed (a table to fill in
    by hand), even after the interval became empty.

    Because the projection is linear in homogeneous coordinates, t is also the parameter of the
    segment *before* the projection (in eye or world coordinates).

    Parameters
    ----------
    p0_h, p1_h : array_like, shape (4,)
        The end points in clip coordinates; a w of either sign is allowed (one end may have
        w = 0, a point at infinity), but not both.

    Returns
    -------
    dict
        ``t_in``, ``t_out``; ``rows``: six dicts (``side``, ``p``, ``q``, ``t`` or None,
        ``kind``, and the running ``t_in``, ``t_out``); ``clipped``: the clipped end points
        (two homogeneous 4-vectors) or None when nothing is left; ``codes``: the two outcodes.

    Raises
    ------
    ValueError
        For end points without 4 coordinates, the zero vector, or w = 0 at both ends.

    Examples
    --------
    >>> r = clip_segment_homogeneous([-2, 0, 0, 1], [2, 0, 0, 1])
    >>> r["t_in"], r["t_out"], r["clipped"][0].tolist()
    (0.25, 0.75, [-1.0, 0.0, 0.0, 1.0])
    >>> r = clip_segment_homogeneous([0, 0, 0, 1], [0, 0, 0, -1])   # through w = 0
    >>> r["t_out"], r["clipped"][1].tolist()                      # stops at the eye plane
    (0.5, [0.0, 0.0, 0.0, 0.0])
    """
    a = _clip_points(p0_h, "p0_h")
    b = _clip_points(p1_h, "p1_h")
    if a.shape != (4,) or b.shape != (4,):
        raise ValueError(f"p0_h and p1_h must be single homogeneous points (shape (4,)), got "
                         f"shapes {a.shape} and {b.shape}")
    if a[3] == 0 and b[3] == 0:
        raise ValueError("p0_h and p1_h both have w = 0: the segment lies at infinity and "
                         "nothing of it can be seen")
    f0, f1 = boundary_values(a), boundary_values(b)
    rows, t_in, t_out = _lb_rows(f0, f1)
    clipped = None
    if t_in <= t_out:
        start = a if t_in == 0 else a + t_in * (b - a)
        end = b if t_out == 1 else a + t_out * (b - a)
        clipped = (start, end)
    return {"t_in": float(t_in), "t_out": float(t_out), "rows": rows, "clipped": clipped,
            "codes": (clip_outcode(a), clip_outcode(b))}


def clip_segments_homogeneous(p0_h, p1_h):
    r"""Liang-Barsky in clip space for many segments at once (vectorized).

    The same rule as :func:`clip_segment_homogeneous`: with the boundary functions
    :math:`f_k` at both ends, :math:`t_{in} = \max(0, \max_{p_k < 0} q_k/p_k)`,
    :math:`t_{out} = \min(1, \min_{p_k > 0} q_k/p_k)`, rejected when :math:`t_{in} > t_{out}`
    or some :math:`p_k = 0` with :math:`q_k < 0`.

    Parameters
    ----------
    p0_h, p1_h : array_like, shape (n, 4)

    Returns
    -------
    q0, q1 : ndarray, shape (n, 4)
        The clipped end points in clip coordinates (the input ones where rejected).
    t : ndarray, shape (n, 2)
        ``t_in``, ``t_out`` of each segment.
    visible : ndarray of bool, shape (n,)

    Raises
    ------
    ValueError
        For other shapes, the zero vector, or a segment with w = 0 at both ends.

    Examples
    --------
    >>> q0, q1, t, visible = clip_segments_homogeneous([[-2, 0, 0, 1], [0, 0, 0, -1]],
    ...                                                [[2, 0, 0, 1], [0, 0, 0.5, -2]])
    >>> t[0].tolist(), visible.tolist()
    ([0.25, 0.75], [True, False])
    """
    a = _clip_points(p0_h, "p0_h")
    b = _clip_points(p1_h, "p1_h")
    if a.ndim != 2 or a.shape != b.shape:
        raise ValueError(f"p0_h and p1_h must both have shape (n, 4), got {a.shape} and "
                         f"{b.shape}")
    if np.any((a[:, 3] == 0) & (b[:, 3] == 0)):
        bad = int(np.flatnonzero((a[:, 3] == 0) & (b[:, 3] == 0))[0])
        raise ValueError(f"segment {bad} has w = 0 at both ends (it lies at infinity)")
    f0, f1 = boundary_values(a), boundary_values(b)
    p, q = f0 - f1, f0
    with np.errstate(divide="ignore", invalid="ignore"):
        t = q / p
    t_in = np.max(np.where(p < 0, t, 0.0), axis=-1, initial=0.0)
    t_out = np.min(np.where(p > 0, t, 1.0), axis=-1, initial=1.0)
    visible = (t_in <= t_out) & ~np.any((p == 0) & (q < 0), axis=-1)
    d = b - a
    q0 = np.where((t_in == 0)[:, None] | ~visible[:, None], a, a + t_in[:, None] * d)
    q1 = np.where((t_out == 1)[:, None] | ~visible[:, None], b, a + t_out[:, None] * d)
    return q0, q1, np.column_stack([t_in, t_out]), visible


def liang_barsky_table(p0, p1, box_min=(-1, -1, -1), box_max=(1, 1, 1)):
    r"""Liang-Barsky's six rows :math:`(p_k, q_k, t_k)` for a 3D segment and a box, all six.

    :math:`p = -\Delta x, q = x_0 - x_{min}` (left), :math:`p = \Delta x, q = x_{max} - x_0`
    (right), likewise in y and z. The same rows as :func:`course_lib.clipping.liang_barsky_steps`
    (which stops at the first side that empties the interval), continued to all six sides.

    Parameters
    ----------
    p0, p1 : array_like, shape (3,)
    box_min, box_max : array_like, shape (3,), optional
        The canonical cube :math:`[-1, 1]^3` by default.

    Returns
    -------
    list of dict
        ``side``, ``p``, ``q``, ``t`` (None when p = 0), ``kind``, running ``t_in``, ``t_out``.

    Examples
    --------
    >>> rows = liang_barsky_table([-2, 0, 0], [2, 0, 0])
    >>> [(r["side"], r["p"], r["q"], r["t"]) for r in rows][:2]
    [('left', -4.0, -1.0, 0.25), ('right', 4.0, 3.0, 0.75)]
    """
    lo, hi = clipping._box(box_min, box_max)
    if lo.size != 3:
        raise ValueError(f"box_min and box_max must have 3 coordinates, got {lo.size}")
    a, b = clipping._segments(p0, p1, 3, single=True)
    f0 = np.stack([a - lo, hi - a], axis=-1).ravel()      # x - xmin, xmax - x, ...
    f1 = np.stack([b - lo, hi - b], axis=-1).ravel()
    return _lb_rows(f0, f1)[0]


def table_text(rows, decimals=3):
    """Liang-Barsky rows as a plain-text table (side, p, q, t, kind, t_in, t_out).

    Parameters
    ----------
    rows : list of dict
        From :func:`liang_barsky_table` or ``clip_segment_homogeneous(...)["rows"]``.
    decimals : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> print(table_text(liang_barsky_table([-2, 0, 0], [2, 0, 0])).splitlines()[1])
    left       -4      -1   0.25  entering          0.25      1
    """
    from . import format as fmt

    head = f"{'side':6} {'p':>6} {'q':>7} {'t':>6}  {'kind':16} {'t_in':>5} {'t_out':>6}"
    lines = [head]
    for r in rows:
        t = "-" if r["t"] is None else fmt.number(r["t"], decimals)
        lines.append(f"{r['side']:6} {fmt.number(r['p'], decimals):>6} "
                     f"{fmt.number(r['q'], decimals):>7} {t:>6}  {r['kind']:16} "
                     f"{fmt.number(r['t_in'], decimals):>5} {fmt.number(r['t_out'], decimals):>6}")
    return "\n".join(lines)


def clip_polygon_homogeneous_steps(poly_h):
    r"""Sutherland-Hodgman in clip space, one plane at a time (left, right, ..., far).

    Each pass keeps the part with :math:`f_k \ge 0`; an edge S -> E that crosses the plane is
    cut at :math:`t = f_k(S) / (f_k(S) - f_k(E))`, linear interpolation of all four homogeneous
    coordinates (exact, since f_k is linear). Vertices behind the eye (w < 0) are removed by the
    passes with no division anywhere.

    Parameters
    ----------
    poly_h : array_like, shape (m, 4)
        The polygon's vertices in clip coordinates, m >= 3.

    Returns
    -------
    list of (str, ndarray of shape (k, 4))
        The side's name and the polygon after it (k may be 0).

    Examples
    --------
    >>> tri = [[-2, 0, 0, 1], [2, 0, 0, 1], [0, 0.5, 0, 1]]
    >>> [(name, len(poly)) for name, poly in clip_polygon_homogeneous_steps(tri)][:2]
    [('left', 4), ('right', 5)]
    """
    poly = _clip_points(poly_h, "poly_h")
    if poly.ndim != 2 or len(poly) < 3:
        raise ValueError(f"poly_h must have at least 3 vertices (shape (m, 4), m >= 3), got "
                         f"shape {poly.shape}")
    steps = []
    for name, normal, offset in clip_space_planes():
        if len(poly):
            poly = clipping._clip_by_plane(poly, normal, offset)
        steps.append((name, poly))
    return steps


def clip_polygon_homogeneous(poly_h):
    """Clip a polygon in clip coordinates to the view volume (see the ``_steps`` version).

    Parameters
    ----------
    poly_h : array_like, shape (m, 4)

    Returns
    -------
    ndarray, shape (k, 4)

    Examples
    --------
    >>> clip_polygon_homogeneous([[0, 0, 0, -1], [0.5, 0, 0, -1], [0, 0.5, 0, -1]]).shape
    (0, 4)
    """
    return clip_polygon_homogeneous_steps(poly_h)[-1][1]


def clip_after_divide(p0_h, p1_h):
    r"""The mistake: divide by w first, then clip the NDC segment to :math:`[-1, 1]^3`.

    Right whenever both end points have :math:`w > 0`. When w changes sign along the segment
    (one end behind the eye) the straight segment between the divided end points is the image
    of the *other* part of the line, through infinity: the result keeps pieces that are not on
    the segment at all, or drops the visible piece ("wrap-around").

    Parameters
    ----------
    p0_h, p1_h : array_like, shape (4,)
        End points in clip coordinates, both with :math:`w \ne 0`.

    Returns
    -------
    dict
        ``ndc``: the two divided end points (2x3); ``clipped``: the NDC segment kept by this
        wrong route (2x3) or None; ``crosses_eye_plane``: whether w changes sign (the divide
        goes wrong); ``correct``: the right result (clip in clip space, then divide; 2x3) or
        None.

    Raises
    ------
    ValueError
        For bad shapes or w = 0 at an end point (it cannot be divided).

    Examples
    --------
    >>> r = clip_after_divide([0, 0, 0.5, 1], [2, 0, 0.5, -1])     # second end behind the eye
    >>> r["ndc"][1].tolist(), r["crosses_eye_plane"]              # mirrored through the centre
    ([-2.0, 0.0, -0.5], True)
    >>> r["clipped"][1].tolist(), r["correct"][1].tolist()        # wrong side vs the right one
    ([-1.0, 0.0, 0.0], [1.0, 0.0, 1.0])
    """
    a = _clip_points(p0_h, "p0_h")
    b = _clip_points(p1_h, "p1_h")
    if a.shape != (4,) or b.shape != (4,):
        raise ValueError(f"p0_h and p1_h must be single homogeneous points (shape (4,)), got "
                         f"shapes {a.shape} and {b.shape}")
    for name, p in (("p0_h", a), ("p1_h", b)):
        if p[3] == 0:
            raise ValueError(f"{name} has w = 0 (a point at infinity): it cannot be divided; "
                             "clip in clip space instead")
    ndc = np.array([a[:3] / a[3], b[:3] / b[3]]) + 0.0      # no -0.0
    kept = clipping.liang_barsky(ndc[0], ndc[1], -np.ones(3), np.ones(3))
    right = clip_segment_homogeneous(a, b)["clipped"]
    correct = None
    if right is not None:
        ends = np.array(right)
        if np.all(ends[:, 3] > 0):
            correct = ends[:, :3] / ends[:, 3:]
        else:                                   # only the point (0, 0, 0, 0)-limit survives
            correct = None
    return {"ndc": ndc, "clipped": None if kept is None else np.array(kept),
            "crosses_eye_plane": bool(a[3] * b[3] < 0),
            "correct": correct}

