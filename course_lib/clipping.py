r"""Chapter 5: back-face culling and clipping (Cohen-Sutherland, Liang-Barsky, Sutherland-Hodgman).

All clipping functions work in 2D (a rectangle) and in 3D (a box), with the clip region given
by its corners ``box_min`` and ``box_max``; a point on the boundary counts as inside. In the
viewing pipeline the box is the canonical cube :math:`[-1, 1]^3` of CSS (or, before the
homogeneous divide, :math:`-w \le x, y, z \le w`). Each algorithm comes three ways:

* ``name(p0, p1, box_min, box_max)``: one segment -> the clipped segment ``(q0, q1)``, or
  ``None`` when nothing is left;
* ``name_many(p0, p1, box_min, box_max)``: many segments at once (arrays of shape ``(n, d)``)
  -> ``(q0, q1, visible)``;
* ``name_steps(...)``: the same result with the algorithm's intermediate states, for the
  step-by-step visualizers.

**Outcodes.** :func:`outcode` gives each point one bit per side of the box it lies beyond:

====  =========  ==============
bit   value      meaning
====  =========  ==============
0     1          x < x_min (left)
1     2          x > x_max (right)
2     4          y < y_min (bottom)
3     8          y > y_max (top)
4     16         z < z_min (near, in CSS)
5     32         z > z_max (far, in CSS)
====  =========  ==============

(4 bits in 2D, 6 in 3D.)
"""
import warnings

import numpy as np

from ._validate import as_array, as_matrix, as_points, as_vector, broadcast_stacks
from .mesh.geometry import face_cross_products   # re-exported: Newell's sum, not unit length

__all__ = [
    "BIT_NAMES",
    "back_faces",
    "box_planes",
    "clip_segment",
    "clip_polygon",
    "clip_polygon_steps",
    "cohen_sutherland",
    "cohen_sutherland_many",
    "cohen_sutherland_steps",
    "describe_outcode",
    "face_cross_products",
    "is_back_face",
    "liang_barsky",
    "liang_barsky_many",
    "liang_barsky_steps",
    "outcode",
    "sutherland_hodgman",
    "sutherland_hodgman_steps",
    "view_volume_planes",
]

BIT_NAMES = ("left", "right", "bottom", "top", "near", "far")
"""The side of the box each outcode bit stands for, bit 0 first."""


# ---------------------------------------------------------------------------------------------
# Back-face culling
# ---------------------------------------------------------------------------------------------

def is_back_face(normal, view_vector):
    r"""Whether faces with outward `normal` turn their back to a viewer looking along `view_vector`.

    The view vector points from the eye *towards* the face. The face is seen from the front when
    its outward normal points back at the eye, i.e. at an angle above 90° to the view vector:

    .. math:: \text{back face} \iff \mathbf n \cdot \mathbf v \ge 0

    (Faces seen exactly edge-on, :math:`\mathbf n \cdot \mathbf v = 0`, cover no pixels and are
    culled too.) The course compendium states the test with :math:`\hat v \cdot \hat n < 0` for
    a back face while also defining :math:`\hat v` as pointing from the eye to the face: with
    that direction the sign is the other way round; it holds for a view vector pointing from
    the face to the eye.

    Parameters
    ----------
    normal : array_like, shape (..., 3)
        Outward face normals (any length).
    view_vector : array_like, shape (..., 3)
        From the eye to (a point of) each face; broadcasts against `normal`.

    Returns
    -------
    bool or ndarray of bool, shape (...)

    Examples
    --------
    >>> is_back_face([0, 0, 1], [0, 0, -1])     # normal towards a viewer looking down -z
    False
    >>> is_back_face([[0, 0, -1], [1, 0, 0]], [0, 0, -1]).tolist()   # facing away; edge-on
    [True, True]
    """
    n = as_points(normal, "normal", dims=3)
    v = as_points(view_vector, "view_vector", dims=3)
    broadcast_stacks(normal=(n, 1), view_vector=(v, 1))
    result = np.einsum("...i,...i->...", n, v) >= 0
    return bool(result) if result.ndim == 0 else result


def face_normals(vertices, faces):
    """Deprecated: :func:`face_cross_products`, which this chapter called ``face_normals``.

    Not unit length (twice the area vector), unlike :func:`course_lib.mesh.face_normals`, the
    library's face normal; warns (``DeprecationWarning``) and returns
    ``face_cross_products(vertices, faces)``, for (m, k) faces as before.
    """
    v = as_points(vertices, "vertices", dims=3)
    f = _faces(faces, len(v))
    warnings.warn("clipping.face_normals is deprecated: it returns face_cross_products (normal "
                  "times twice the area), not unit normals; call clipping.face_cross_products, "
                  "or mesh.face_normals for unit normals", DeprecationWarning, stacklevel=2)
    return _cross_products(v, f)


def _cross_products(v, f):
    return face_cross_products(v, f) if len(f) else np.zeros((0, 3))   # (0, k) faces: none


def back_faces(vertices, faces, eye=None, direction=None):
    r"""Back-face culling of a whole mesh: a boolean mask, True for the faces to cull.

    Give either the `eye` position (perspective: the view vector differs per face, from the eye
    to the face's first vertex) or a constant view `direction` (a parallel projection).

    After the projection, in CSS, the projectors are parallel to z and the viewer looks along
    +z (depth grows away from the viewer). But the projection also mirrors z (CSS is
    left-handed), which reverses every face's winding: normals computed from CSS coordinates
    point *inwards*. So for a mesh in CSS use ``direction=(0, 0, -1)``, which amounts to the
    renderer's usual test: a face is seen from the front when its projected vertices run
    counter-clockwise on the screen.

    Only valid for closed, opaque meshes with consistently oriented faces: through a hole or a
    transparent face one would see the back faces.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, k)
        Counter-clockwise seen from outside.
    eye : array_like, shape (3,), optional
    direction : array_like, shape (3,), optional

    Returns
    -------
    ndarray of bool, shape (m,)

    Raises
    ------
    ValueError
        Unless exactly one of `eye` and `direction` is given.

    Examples
    --------
    >>> cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)
    >>> quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    >>> back_faces(cube, quads, eye=[0.5, 0.5, 5]).tolist()      # only the top (z = 1) is seen
    [True, True, True, True, True, False]
    """
    if (eye is None) == (direction is None):
        raise ValueError("give exactly one of eye (a position) and direction (a view vector)")
    v = as_points(vertices, "vertices", dims=3)
    f = _faces(faces, len(v))
    normals = _cross_products(v, f)
    if eye is not None:
        view = v[f[:, 0]] - as_vector(eye, "eye", 3)
    else:
        view = as_vector(direction, "direction", 3)
    return is_back_face(normals, view)


def _faces(faces, n_vertices):
    try:
        f = np.asarray(faces)
    except ValueError:
        raise ValueError("faces must all have the same number of vertices (an (m, k) array); "
                         "split mixed meshes into triangles") from None
    if f.ndim != 2 or f.shape[1] < 3 or not np.issubdtype(f.dtype, np.integer):
        raise ValueError(f"faces must be an (m, k) array of vertex indices with k >= 3, "
                         f"got shape {f.shape} and type {f.dtype}")
    if f.size and (f.min() < 0 or f.max() >= n_vertices):
        raise ValueError(f"faces refers to vertex {int(f.max() if f.max() >= n_vertices else f.min())}"
                         f" but there are {n_vertices} vertices")
    return f


# ---------------------------------------------------------------------------------------------
# The clip region
# ---------------------------------------------------------------------------------------------

def _box(box_min, box_max):
    lo = as_vector(box_min, "box_min", (2, 3))
    hi = as_vector(box_max, "box_max", (2, 3))
    if lo.shape != hi.shape:
        raise ValueError(f"box_min has {lo.size} coordinates but box_max has {hi.size}")
    if np.any(lo >= hi):
        axis = "xyz"[int(np.argmax(lo >= hi))]
        raise ValueError(f"box_min must be below box_max on every axis, but on {axis} "
                         f"box_min = {lo[int(np.argmax(lo >= hi))]} >= box_max = "
                         f"{hi[int(np.argmax(lo >= hi))]}")
    return lo, hi


def _segments(p0, p1, dim, single):
    a = as_points(p0, "p0", dims=dim)
    b = as_points(p1, "p1", dims=dim)
    if single and (a.ndim != 1 or b.ndim != 1):
        raise ValueError(f"p0 and p1 must be single points here (shape ({dim},)); use the "
                         "_many function for arrays of segments")
    if a.shape != b.shape:
        raise ValueError(f"p0 has shape {a.shape} but p1 has shape {b.shape}: one start and one "
                         "end point per segment")
    return a, b


def outcode(points, box_min, box_max):
    """The Cohen-Sutherland region code of each point (see the module's table of bits).

    Parameters
    ----------
    points : array_like, shape (..., d)
        With d = 2 (4 bits) or d = 3 (6 bits), matching the box.
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    int or ndarray of int, shape (...)
        0 for points inside the box or on its boundary.

    Raises
    ------
    ValueError
        If ``box_min >= box_max`` on some axis, or the dimensions do not match.

    Examples
    --------
    >>> outcode([[0.5, 0.5], [-1, 2], [3, 0.5]], [0, 0], [1, 1]).tolist()   # inside, left+top, right
    [0, 9, 2]
    """
    lo, hi = _box(box_min, box_max)
    p = as_points(points, "points", dims=len(lo))
    code = np.zeros(p.shape[:-1], dtype=np.int64)
    for k in range(len(lo)):
        code |= (p[..., k] < lo[k]) << (2 * k)
        code |= (p[..., k] > hi[k]) << (2 * k + 1)
    return int(code) if code.ndim == 0 else code


def describe_outcode(code, dim=2):
    """An outcode as bits (the highest first) and the sides it names.

    Examples
    --------
    >>> describe_outcode(9)
    '1001 (top, left)'
    >>> describe_outcode(0, dim=3)
    '000000 (inside)'
    """
    if dim not in (2, 3):
        raise ValueError(f"dim must be 2 or 3, got {dim!r}")
    if isinstance(code, bool) or not isinstance(code, (int, np.integer)) \
            or not 0 <= int(code) < 4 ** dim:
        raise ValueError(f"code must be an outcode of {2 * dim} bits (an integer from 0 to "
                         f"{4 ** dim - 1}), got {code!r}")
    bits = format(int(code), f"0{2 * dim}b")
    sides = [BIT_NAMES[k] for k in range(2 * dim - 1, -1, -1) if int(code) >> k & 1]
    return f"{bits} ({', '.join(sides) if sides else 'inside'})"


# ---------------------------------------------------------------------------------------------
# Cohen-Sutherland
# ---------------------------------------------------------------------------------------------

def _cut(p, q, axis, value):
    """The point of segment p-q where coordinate `axis` equals `value` (exactly)."""
    t = (value - p[axis]) / (q[axis] - p[axis])
    point = p + t * (q - p)
    point[axis] = value
    return point


def cohen_sutherland_steps(p0, p1, box_min, box_max):
    r"""Cohen-Sutherland line clipping, with every iteration recorded.

    Each iteration computes both endpoints' outcodes :math:`c_0, c_1`:

    * :math:`c_0 \lor c_1 = 0`: both inside: **accept** the segment as it is;
    * :math:`c_0 \land c_1 \ne 0`: both beyond the same side: **reject** it;
    * otherwise take an endpoint that is outside, take one side its code names (the lowest bit),
      and replace the endpoint by the segment's intersection with that side's line (plane).

    Every clip removes a bit from an endpoint's code for good, so there are at most 4 (2D) or
    6 (3D) clips.

    Parameters
    ----------
    p0, p1 : array_like, shape (d,)
        The segment's end points, d = 2 or 3.
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    result : tuple of two ndarrays, or None
        The clipped segment, or None if it lies outside.
    steps : list of dict
        One per iteration: ``p0``, ``p1``, ``code0``, ``code1`` (at the start of the iteration),
        ``action`` (``"accept"``, ``"reject"`` or ``"clip"``) and, for a clip, ``endpoint``
        (0 or 1), ``side`` (a name from :data:`BIT_NAMES`) and ``new_point``.

    Examples
    --------
    >>> result, steps = cohen_sutherland_steps([-1, 0.5], [2, 0.5], [0, 0], [1, 1])
    >>> [(s["action"], s.get("side")) for s in steps]
    [('clip', 'left'), ('clip', 'right'), ('accept', None)]
    >>> result
    (array([0. , 0.5]), array([1. , 0.5]))
    """
    lo, hi = _box(box_min, box_max)
    a, b = _segments(p0, p1, len(lo), single=True)
    a, b = a.copy(), b.copy()
    steps = []
    while True:
        c0, c1 = outcode(a, lo, hi), outcode(b, lo, hi)
        step = {"p0": a.copy(), "p1": b.copy(), "code0": c0, "code1": c1}
        steps.append(step)
        if c0 | c1 == 0:
            step["action"] = "accept"
            return (a, b), steps
        if c0 & c1:
            step["action"] = "reject"
            return None, steps
        endpoint = 0 if c0 else 1
        code = c0 if c0 else c1
        bit = (code & -code).bit_length() - 1          # the lowest set bit
        axis, limit = bit // 2, (lo, hi)[bit % 2][bit // 2]
        new = _cut(a, b, axis, limit)
        step.update(action="clip", endpoint=endpoint, side=BIT_NAMES[bit], new_point=new.copy())
        if endpoint == 0:
            a = new
        else:
            b = new


def cohen_sutherland(p0, p1, box_min, box_max):
    """Clip one segment to a box with Cohen-Sutherland (see :func:`cohen_sutherland_steps`).

    Parameters
    ----------
    p0, p1 : array_like, shape (d,)
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    tuple of two ndarrays, or None

    Examples
    --------
    >>> cohen_sutherland([-1, -1], [2, 2], [0, 0], [1, 1])
    (array([0., 0.]), array([1., 1.]))
    >>> cohen_sutherland([2, 0], [2, 1], [0, 0], [1, 1]) is None
    True
    """
    return cohen_sutherland_steps(p0, p1, box_min, box_max)[0]


def cohen_sutherland_many(p0, p1, box_min, box_max):
    """Cohen-Sutherland on many segments at once (all iterations vectorized).

    Parameters
    ----------
    p0, p1 : array_like, shape (n, d)
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    q0, q1 : ndarray, shape (n, d)
        The clipped end points (the input end points where a segment is rejected).
    visible : ndarray of bool, shape (n,)
        False where the whole segment is outside.

    Any stack of segments works, shape (..., d); the results have the same leading shape.

    Examples
    --------
    >>> q0, q1, visible = cohen_sutherland_many([[-1, 0.5], [2, 2]], [[2, 0.5], [3, 3]],
    ...                                         [0, 0], [1, 1])
    >>> visible.tolist(), q0[0].tolist(), q1[0].tolist()
    ([True, False], [0.0, 0.5], [1.0, 0.5])
    """
    lo, hi = _box(box_min, box_max)
    first_points, second_points = _segments(p0, p1, len(lo), single=False)
    shape = first_points.shape
    a = first_points.reshape(-1, len(lo)).copy()
    b = second_points.reshape(-1, len(lo)).copy()
    c0, c1 = outcode(a, lo, hi), outcode(b, lo, hi)
    bounds = np.concatenate([lo[:, None], hi[:, None]], axis=1).ravel()   # per bit: the limit
    for _ in range(2 * 2 * len(lo) + 1):
        active = ((c0 | c1) != 0) & ((c0 & c1) == 0)
        if not active.any():
            break
        idx = np.flatnonzero(active)
        first = c0[idx] != 0                           # clip p0 first while it is outside
        code = np.where(first, c0[idx], c1[idx])
        bit = np.log2(code & -code).astype(int)
        axis = bit // 2
        limit = bounds[bit]
        p, q = np.where(first[:, None], a[idx], b[idx]), np.where(first[:, None], b[idx], a[idx])
        rows = np.arange(len(idx))
        t = (limit - p[rows, axis]) / (q[rows, axis] - p[rows, axis])
        new = p + t[:, None] * (q - p)
        new[rows, axis] = limit
        a[idx[first]] = new[first]
        b[idx[~first]] = new[~first]
        c0[idx] = np.where(first, outcode(new, lo, hi), c0[idx])
        c1[idx] = np.where(first, c1[idx], outcode(new, lo, hi))
    visible = (c0 | c1) == 0
    a[~visible] = first_points.reshape(-1, len(lo))[~visible]
    b[~visible] = second_points.reshape(-1, len(lo))[~visible]
    return a.reshape(shape), b.reshape(shape), visible.reshape(shape[:-1])


# ---------------------------------------------------------------------------------------------
# Liang-Barsky
# ---------------------------------------------------------------------------------------------

def liang_barsky_steps(p0, p1, box_min, box_max):
    r"""Liang-Barsky line clipping, with the t interval after each boundary.

    The segment is :math:`p(t) = p_0 + t\,\Delta`, :math:`\Delta = p_1 - p_0`,
    :math:`0 \le t \le 1`. Being inside the box is a set of inequalities
    :math:`p_k\, t \le q_k`, one per side:

    ===========  ================  ====================
    side         :math:`p_k`       :math:`q_k`
    ===========  ================  ====================
    left         :math:`-\Delta x` :math:`x_0 - x_{min}`
    right        :math:`\Delta x`  :math:`x_{max} - x_0`
    bottom, top  likewise in y     likewise in y
    near, far    likewise in z     likewise in z
    ===========  ================  ====================

    With :math:`p_k < 0` the line *enters* the half-space at :math:`t = q_k / p_k`, raising
    :math:`t_{in}`; with :math:`p_k > 0` it *leaves* it, lowering :math:`t_{out}`; with
    :math:`p_k = 0` it is parallel to the side, inside if :math:`q_k \ge 0` and rejected
    otherwise. Starting from :math:`[t_{in}, t_{out}] = [0, 1]`, the segment survives if the
    interval is not empty at the end, as :math:`[p(t_{in}), p(t_{out})]`. No intersection point
    is computed until the end, which is why the method beats Cohen-Sutherland.

    Parameters
    ----------
    p0, p1 : array_like, shape (d,)
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    result : tuple of two ndarrays, or None
    steps : list of dict
        One per side, in the order left, right, bottom, top (near, far): ``side``, ``p``, ``q``,
        ``t`` (None when parallel), ``kind`` (``"entering"``, ``"leaving"``,
        ``"parallel inside"`` or ``"parallel outside"``), and ``t_in``, ``t_out`` after the side.
        It stops at the first side that empties the interval.

    Examples
    --------
    >>> result, steps = liang_barsky_steps([-1, 0.5], [3, 0.5], [0, 0], [2, 1])
    >>> [(s["side"], s["kind"], s["t"]) for s in steps]       # doctest: +NORMALIZE_WHITESPACE
    [('left', 'entering', 0.25), ('right', 'leaving', 0.75),
     ('bottom', 'parallel inside', None), ('top', 'parallel inside', None)]
    >>> result
    (array([0. , 0.5]), array([2. , 0.5]))
    """
    lo, hi = _box(box_min, box_max)
    a, b = _segments(p0, p1, len(lo), single=True)
    delta = b - a
    t_in, t_out = 0.0, 1.0
    steps = []
    for bit in range(2 * len(lo)):
        axis = bit // 2
        if bit % 2 == 0:
            p, q = -delta[axis], a[axis] - lo[axis]
        else:
            p, q = delta[axis], hi[axis] - a[axis]
        step = {"side": BIT_NAMES[bit], "p": float(p), "q": float(q), "t": None}
        if p == 0:
            step["kind"] = "parallel inside" if q >= 0 else "parallel outside"
            if q < 0:
                t_in, t_out = 1.0, 0.0
        else:
            t = q / p
            step["t"] = float(t)
            if p < 0:
                step["kind"] = "entering"
                t_in = max(t_in, t)
            else:
                step["kind"] = "leaving"
                t_out = min(t_out, t)
        step["t_in"], step["t_out"] = float(t_in), float(t_out)
        steps.append(step)
        if t_in > t_out:
            return None, steps
    # t = 0 and t = 1 give the end points themselves (a + 1.0 * (b - a) may differ in the last bit)
    start = a if t_in == 0 else a + t_in * delta
    end = b if t_out == 1 else a + t_out * delta
    return (start, end), steps


def liang_barsky(p0, p1, box_min, box_max):
    """Clip one segment to a box with Liang-Barsky (see :func:`liang_barsky_steps`).

    Parameters
    ----------
    p0, p1 : array_like, shape (d,)
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    tuple of two ndarrays, or None

    Examples
    --------
    >>> liang_barsky([0.5, -1, 0.5], [0.5, 2, 0.5], [0, 0, 0], [1, 1, 1])
    (array([0.5, 0. , 0.5]), array([0.5, 1. , 0.5]))
    """
    return liang_barsky_steps(p0, p1, box_min, box_max)[0]


def liang_barsky_many(p0, p1, box_min, box_max):
    """Liang-Barsky on many segments at once.

    Parameters
    ----------
    p0, p1 : array_like, shape (n, d)
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    q0, q1 : ndarray, shape (n, d)
        The clipped end points (the input end points where a segment is rejected).
    visible : ndarray of bool, shape (n,)

    Examples
    --------
    >>> q0, q1, visible = liang_barsky_many([[-1, 0.5], [2, 2]], [[2, 0.5], [3, 3]],
    ...                                     [0, 0], [1, 1])
    >>> visible.tolist(), q1[0].tolist()
    ([True, False], [1.0, 0.5])
    """
    lo, hi = _box(box_min, box_max)
    a, b = _segments(p0, p1, len(lo), single=False)
    delta = b - a
    p = np.concatenate([-delta, delta], axis=-1)                   # (n, 2d): mins, then maxes
    q = np.concatenate([a - lo, hi - a], axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = q / p
    entering = p < 0
    leaving = p > 0
    t_in = np.max(np.where(entering, t, 0.0), axis=-1, initial=0.0)
    t_out = np.min(np.where(leaving, t, 1.0), axis=-1, initial=1.0)
    parallel_out = np.any((p == 0) & (q < 0), axis=-1)
    visible = (t_in <= t_out) & ~parallel_out
    start = np.where((t_in == 0)[..., None] | ~visible[..., None], a, a + t_in[..., None] * delta)
    end = np.where((t_out == 1)[..., None] | ~visible[..., None], b, a + t_out[..., None] * delta)
    return start, end, visible


# ---------------------------------------------------------------------------------------------
# Sutherland-Hodgman
# ---------------------------------------------------------------------------------------------

def box_planes(box_min, box_max):
    r"""The sides of a box as half-spaces :math:`\mathbf n \cdot \mathbf x \le c`, named.

    Returns
    -------
    list of (str, ndarray, float)
        ``(side, normal, offset)`` in the order of :data:`BIT_NAMES`.

    Examples
    --------
    >>> [(name, n.tolist(), c) for name, n, c in box_planes([0, 0], [2, 1])][:2]
    [('left', [-1.0, -0.0], -0.0), ('right', [1.0, 0.0], 2.0)]
    """
    lo, hi = _box(box_min, box_max)
    planes = []
    for k in range(len(lo)):
        e = np.zeros(len(lo))
        e[k] = 1.0
        planes.append((BIT_NAMES[2 * k], -e, float(-lo[k])))
        planes.append((BIT_NAMES[2 * k + 1], e, float(hi[k])))
    return planes


def view_volume_planes(matrix):
    r"""The 6 half-spaces whose intersection a projection matrix maps onto :math:`[-1, 1]^3`.

    A point is inside the view volume when its clip coordinates satisfy
    :math:`-w \le x, y, z \le w`. With the matrix rows :math:`r_1 \dots r_4` these are the
    linear conditions :math:`(r_4 \pm r_k) \cdot p \ge 0`, each a plane of the space *before*
    the matrix (for a perspective matrix, the frustum's sides in eye coordinates; for
    ``projection @ view``, in world coordinates).

    Parameters
    ----------
    matrix : array_like, shape (4, 4)

    Returns
    -------
    list of (str, ndarray, float)
        ``(side, normal, offset)`` with inside :math:`\mathbf n \cdot \mathbf x \le c`, in the
        order left, right, bottom, top, near, far.

    Examples
    --------
    >>> from course_lib.viewing import perspective
    >>> planes = view_volume_planes(perspective(np.radians(90), 1, 1, 10))
    >>> [(name, np.round(n / np.linalg.norm(n), 3).tolist()) for name, n, c in planes][4:]
    [('near', [0.0, 0.0, 1.0]), ('far', [0.0, 0.0, -1.0])]
    """
    m = as_array(matrix, "matrix")
    if m.shape != (4, 4):
        raise ValueError(f"matrix must be 4x4, got shape {m.shape}")
    planes = []
    for k in range(3):
        for sign, name in ((1.0, BIT_NAMES[2 * k]), (-1.0, BIT_NAMES[2 * k + 1])):
            row = m[3] + sign * m[k]                   # row . (p, 1) >= 0 inside
            planes.append((name, -row[:3], float(row[3])))
    return planes


def clip_segment(p0, p1, planes):
    r"""Clip a segment to a convex region given by half-spaces (Cyrus-Beck).

    Liang-Barsky's idea for any convex region: with :math:`f_i = \mathbf n \cdot p_i - c`
    (negative inside), a plane the segment crosses cuts it at :math:`t = f_0 / (f_0 - f_1)`;
    where :math:`p_0` is outside that is an entering point (raise :math:`t_{in}`), where
    :math:`p_1` is outside a leaving point (lower :math:`t_{out}`). Used for view frusta, which
    are not boxes.

    Parameters
    ----------
    p0, p1 : array_like, shape (d,)
    planes : sequence of (normal, offset) or (name, normal, offset)
        Half-spaces :math:`\mathbf n \cdot \mathbf x \le c` (e.g. :func:`view_volume_planes`).

    Returns
    -------
    tuple of two ndarrays, or None

    Examples
    --------
    >>> clip_segment([-2, 0], [2, 0], [([1, 0], 1), ([-1, 0], 1)])    # |x| <= 1
    (array([-1.,  0.]), array([1., 0.]))
    """
    a = as_points(p0, "p0", dims=(2, 3))
    b = as_points(p1, "p1", dims=(2, 3))
    if a.shape != b.shape or a.ndim != 1:
        raise ValueError("p0 and p1 must be two points of the same dimension")
    t_in, t_out = 0.0, 1.0
    for plane in planes:
        normal, offset = plane[-2:]
        n = as_vector(normal, "normal", a.size)
        f0, f1 = float(n @ a - offset), float(n @ b - offset)
        if f0 > 0 and f1 > 0:
            return None
        if f0 > 0:
            t_in = max(t_in, f0 / (f0 - f1))
        elif f1 > 0:
            t_out = min(t_out, f0 / (f0 - f1))
        if t_in > t_out:
            return None
    return a + t_in * (b - a), a + t_out * (b - a)


def _polygon(polygon, dims):
    poly = as_points(polygon, "polygon", dims=dims)
    if poly.ndim != 2 or len(poly) < 3:
        raise ValueError(f"polygon must have at least 3 vertices (shape (m, d), m >= 3), got "
                         f"shape {poly.shape}")
    return poly


def clip_polygon_steps(polygon, planes):
    r"""Sutherland-Hodgman against a list of half-spaces, with the polygon after each.

    The polygon is clipped by one plane at a time. For each edge :math:`S \to E` of the current
    polygon (in order, the last vertex back to the first):

    ==================  ====================================
    S, E                output
    ==================  ====================================
    in, in              E
    in, out             the intersection I
    out, in             I, then E
    out, out            nothing
    ==================  ====================================

    The output of one plane is the input of the next. The clip region must be convex (an
    intersection of half-spaces); the polygon need not be. A non-convex polygon cut into
    several pieces comes out as one polygon whose pieces are joined by edges running along the
    boundary (they enclose no area).

    Parameters
    ----------
    polygon : array_like, shape (m, d)
        The vertices in order, m >= 3, d = 2 or 3.
    planes : sequence of (normal, offset) or (name, normal, offset)
        Half-spaces :math:`\mathbf n \cdot \mathbf x \le c`.

    Returns
    -------
    list of (str, ndarray)
        The plane's name (or its index) and the polygon after it, shape (k, d), k possibly 0.

    Raises
    ------
    ValueError
        For a polygon with fewer than 3 vertices, or a plane of another dimension.

    Examples
    --------
    >>> square = [[0, 0], [2, 0], [2, 2], [0, 2]]
    >>> [(name, len(poly)) for name, poly in clip_polygon_steps(square, [([1, 0], 1), ([0, 1], 1)])]
    [('0', 4), ('1', 4)]
    """
    poly = _polygon(polygon, (2, 3))
    steps = []
    for index, plane in enumerate(planes):
        name, normal, offset = plane if len(plane) == 3 else (str(index), *plane)
        n = as_vector(normal, "normal", poly.shape[1])
        c = float(offset)
        if len(poly):
            poly = _clip_by_plane(poly, n, c)
        steps.append((name, poly))
    return steps


def _cut_edge(s_point, e_point, s_side, e_side):
    """Where the edge S -> E crosses the plane (signed distances s_side, e_side of opposite sign)."""
    t = s_side / (s_side - e_side)
    return s_point + t * (e_point - s_point)


def _clip_by_plane(poly, normal, offset):
    """One Sutherland-Hodgman pass: the four cases for each edge S -> E, as in the table.

    A plain loop over the edges: for the polygons of a lesson (tens of vertices) it is faster
    than a vectorized version, whose many small numpy calls cost more than the loop.
    """
    side = poly @ normal - offset                       # <= 0 inside
    inside = side <= 0
    out = []
    count = len(poly)
    for i in range(count):
        j = (i + 1) % count
        if inside[i] and inside[j]:                     # in, in: E
            out.append(poly[j])
        elif inside[i]:                                 # in, out: I (unless S itself lies on
            if side[i] < 0:                             # the plane: then I = S, already out)
                out.append(_cut_edge(poly[i], poly[j], side[i], side[j]))
        elif inside[j]:                                 # out, in: I, then E (I = E when E
            if side[j] < 0:                             # lies on the plane: E only)
                out.append(_cut_edge(poly[i], poly[j], side[i], side[j]))
            out.append(poly[j])
    return np.array(out, dtype=float).reshape(-1, poly.shape[1])


def clip_polygon(polygon, planes):
    """Sutherland-Hodgman against a list of half-spaces (see :func:`clip_polygon_steps`).

    Parameters
    ----------
    polygon : array_like, shape (m, d)
    planes : sequence of (normal, offset) or (name, normal, offset)
        Half-spaces n . x <= offset.

    Returns
    -------
    ndarray, shape (k, d)

    Examples
    --------
    >>> clip_polygon([[0, 0], [2, 0], [0, 2]], [([1, 0], 1)])     # keep x <= 1
    array([[1., 0.],
           [1., 1.],
           [0., 2.],
           [0., 0.]])
    """
    return clip_polygon_steps(polygon, planes)[-1][1] if len(planes) else _polygon(polygon,
                                                                                   (2, 3))


def sutherland_hodgman_steps(polygon, box_min, box_max):
    """Sutherland-Hodgman against a box, with the polygon after each side.

    Parameters
    ----------
    polygon : array_like, shape (m, d)
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    list of (str, ndarray)
        The side's name and the polygon after it.

    Examples
    --------
    >>> steps = sutherland_hodgman_steps([[-1, -1], [3, -1], [1, 3]], [0, 0], [2, 2])
    >>> [(name, len(poly)) for name, poly in steps]
    [('left', 4), ('right', 5), ('bottom', 5), ('top', 6)]
    """
    lo, hi = _box(box_min, box_max)
    _polygon(polygon, len(lo))
    return clip_polygon_steps(polygon, box_planes(lo, hi))


def sutherland_hodgman(polygon, box_min, box_max):
    """Clip a polygon to a box with Sutherland-Hodgman.

    Parameters
    ----------
    polygon : array_like, shape (m, d)
        m >= 3 vertices in order; d = 2 or 3 (a planar polygon in 3D).
    box_min, box_max : array_like, shape (d,)

    Returns
    -------
    ndarray, shape (k, d)
        The clipped polygon (k = 0 when nothing is left).

    Examples
    --------
    >>> sutherland_hodgman([[-1, 0.5], [3, 0.5], [1, 3]], [0, 0], [2, 2]).round(3).tolist()
    [[1.8, 2.0], [0.2, 2.0], [0.0, 1.75], [0.0, 0.5], [2.0, 0.5], [2.0, 1.75]]
    """
    return sutherland_hodgman_steps(polygon, box_min, box_max)[-1][1]
