"""Chapter 5, hidden-surface elimination (lesson section 5): scan conversion and the z-buffer."""

import math
from typing import NamedTuple

import numpy as np

from .. import transforms, viewing
from .._validate import as_array, as_mesh, as_points, as_whole
from .._raycore import as_triangles as _triangles
from ._common import _camera

__all__ = ["ZBuffer", "ZBufferStep", "render_depth", "triangle_coverage", "zbuffer",
    "zbuffer_steps"]


# ---------------------------------------------------------------------------------------------
# Rasterization and the z-buffer
# ---------------------------------------------------------------------------------------------

class ZBuffer(NamedTuple):
    """The result of :func:`zbuffer`: buffers of shape (height, width), row 0 at the bottom.

    Attributes
    ----------
    depth : ndarray of float
        Depth of the visible fragment, ``inf`` where nothing was drawn.
    ids : ndarray of int
        Index of the visible triangle, -1 for background.
    image : ndarray or None
        Interpolated per-vertex values (shape (height, width) or (height, width, k)), or None.
    fragments : int
        Pixels covered by some triangle, summed over all triangles (the rasterization work).
    writes : int
        Fragments that passed the depth test and were written (overdraw = writes - covered pixels).

    Examples
    --------
    The centres (i + 0.5, j + 0.5) strictly below the hypotenuse x + y = 4 have i + j < 3:

    >>> zb = zbuffer([[[0, 0, 0.5], [4, 0, 0.5], [0, 4, 0.5]]], 4, 4)
    >>> zb.fragments, zb.writes, int((zb.ids == 0).sum())
    (6, 6, 6)
    """
    depth: np.ndarray
    ids: np.ndarray
    image: object
    fragments: int
    writes: int


class ZBufferStep(NamedTuple):
    """One step of :func:`zbuffer_steps`: the buffers after triangle `index` was drawn.

    Attributes
    ----------
    index : int
        The triangle just rasterized.
    covered : ndarray of bool, shape (height, width)
        Pixels whose centre it covers (inside the depth range [0, 1]).
    written : ndarray of bool, shape (height, width)
        The covered pixels where it was nearer than what the buffer held: the ones overwritten.
    depth, ids : ndarray, shape (height, width)
        Copies of the buffers after this step.

    Examples
    --------
    The second (farther) triangle covers 10 pixels but wins only the 6 the first left empty:

    >>> tris = [[[0, 0, 0.5], [4, 0, 0.5], [0, 4, 0.5]], [[0, 0, 0.7], [4, 0, 0.7], [4, 4, 0.7]]]
    >>> [(int(s.covered.sum()), int(s.written.sum())) for s in zbuffer_steps(tris, 4, 4)]
    [(6, 6), (10, 6)]
    """
    index: int
    covered: np.ndarray
    written: np.ndarray
    depth: np.ndarray
    ids: np.ndarray


def _orient(ax, ay, bx, by, px, py):
    """Twice the signed area of (a, b, p), positive when p is left of a -> b.

    Written as (a - p) x (b - p): swapping a and b gives exactly the negated floating-point
    value, so two triangles sharing an edge see the same pixel centre on opposite sides of it,
    bit for bit. That is what makes the fill rule watertight.
    """
    return (ax - px) * (by - py) - (ay - py) * (bx - px)


_EMPTY = (np.zeros(0, np.intp), np.zeros(0, np.intp), np.zeros((0, 3)))


def _raster(tri, width, height):
    """Pixels covered by one screen triangle: (rows, cols, barycentric weights (n, 3))."""
    (x0, y0), (x1, y1), (x2, y2) = tri[:, :2].tolist()       # Python floats: same IEEE maths
    x, y = (x0, x1, x2), (y0, y1, y2)
    area = _orient(x0, y0, x1, y1, x2, y2)
    if area == 0 or not math.isfinite(area):
        return _EMPTY
    ccw = (0, 1, 2) if area > 0 else (0, 2, 1)
    # bounding box of pixel centres, one pixel of slack (the edge tests decide exactly)
    i0 = max(math.floor(max(min(x), -1.0) - 0.5), 0)
    i1 = min(math.ceil(min(max(x), width + 1.0) - 0.5), width - 1)
    j0 = max(math.floor(max(min(y), -1.0) - 0.5), 0)
    j1 = min(math.ceil(min(max(y), height + 1.0) - 0.5), height - 1)
    if i0 > i1 or j0 > j1:
        return _EMPTY
    cx = np.arange(i0, i1 + 1) + 0.5
    cy = (np.arange(j0, j1 + 1) + 0.5)[:, None]
    weights = [None, None, None]
    inside = None
    for k in range(3):                     # the edge a -> b opposite vertex ccw[k]
        a, b = ccw[(k + 1) % 3], ccw[(k + 2) % 3]
        e = _orient(x[a], y[a], x[b], y[b], cx, cy)
        dx, dy = x[b] - x[a], y[b] - y[a]
        top_left = dy < 0 or (dy == 0 and dx < 0)
        test = (e >= 0) if top_left else (e > 0)
        inside = test if inside is None else inside & test
        weights[ccw[k]] = e
    rows, cols = np.nonzero(inside)
    bary = np.empty((len(rows), 3))
    for k in range(3):
        bary[:, k] = weights[k][rows, cols]
    bary /= abs(area)
    return rows + j0, cols + i0, bary


def triangle_coverage(triangle, width, height):
    r"""The pixels whose centres a screen triangle covers, with their barycentric coordinates.

    A pixel centre :math:`p` is inside when it lies on the inner side of all three edges. The
    side is the sign of the edge function :math:`E_{ab}(p) = (a - p) \times (b - p)` (twice the
    signed area of :math:`a, b, p`) with the triangle turned counter-clockwise. A centre exactly
    *on* an edge belongs to the triangle only if that edge is a **left** edge (going down, for a
    counter-clockwise triangle with y up) or a **top** edge (horizontal, going left, i.e. with
    the interior below it). Two triangles sharing an edge run along it in opposite directions,
    so exactly one of them owns the centres on it: no pixel is drawn twice and none is missed
    (a watertight mesh rasterizes to a watertight image).

    The barycentric coordinates are the normalized edge functions
    :math:`\lambda_k = E_{\text{opposite } k}(p) / E_{01}(v_2)`; any per-vertex quantity that is
    an affine function on the screen interpolates as :math:`\sum_k \lambda_k q_k`.

    Parameters
    ----------
    triangle : array_like, shape (3, 2) or (3, 3)
        Vertices in viewport coordinates (pixel x, pixel y, optional depth), either orientation.
    width, height : int
        The image size in pixels.

    Returns
    -------
    rows, cols : ndarray of int, shape (n,)
        The covered pixels (row 0 at the bottom).
    barycentric : ndarray, shape (n, 3)
        The weights of the three vertices at each covered pixel centre (summing to 1).

    Raises
    ------
    ValueError
        For a triangle that is not 3 points of 2 or 3 coordinates, or a non-positive size.

    Examples
    --------
    The two halves of the square [1, 3] x [1, 3] share its diagonal, which passes through the
    centres (1.5, 1.5) and (2.5, 2.5); each centre goes to exactly one half:

    >>> a = triangle_coverage([[1, 1], [3, 1], [3, 3]], 4, 4)
    >>> b = triangle_coverage([[1, 1], [3, 3], [1, 3]], 4, 4)
    >>> sorted(zip(a[0].tolist(), a[1].tolist())), sorted(zip(b[0].tolist(), b[1].tolist()))
    ([(1, 1), (1, 2), (2, 2)], [(2, 1)])

    (The lower-right half owns the diagonal: for it, the diagonal runs downwards, a left edge.)
    """
    tri = as_points(triangle, "triangle", dims=(2, 3))
    if tri.shape[0] != 3 or tri.ndim != 2:
        raise ValueError(f"triangle must be 3 points, shape (3, 2) or (3, 3), got shape "
                         f"{tri.shape}")
    return _raster(tri, as_whole(width, "width", 1), as_whole(height, "height", 1))


def _check_values(values, m, name="values"):
    if values is None:
        return None, None
    vals = as_array(values, name)
    if vals.ndim not in (2, 3) or vals.shape[:2] != (m, 3):
        raise ValueError(f"{name} must hold one value (shape (m, 3)) or one vector (shape "
                         f"(m, 3, k)) per vertex of the {m} triangles, got shape {vals.shape}")
    scalar = vals.ndim == 2
    return (vals[..., None] if scalar else vals), scalar


def _zbuffer_run(tris, width, height, vals=None, w=None, background=0.0):
    """The z-buffer loop shared by zbuffer and zbuffer_steps: yields after each triangle."""
    depth = np.full((height, width), np.inf)
    ids = np.full((height, width), -1, dtype=np.intp)
    image = None if vals is None else np.full((height, width, vals.shape[-1]), float(background))
    state = {"depth": depth, "ids": ids, "image": image, "fragments": 0, "writes": 0}
    for index in range(len(tris)):
        rows, cols, bary = _raster(tris[index], width, height)
        z = bary @ tris[index, :, 2]
        keep = (z >= 0.0) & (z <= 1.0)          # per-pixel near/far clipping
        rows, cols, bary, z = rows[keep], cols[keep], bary[keep], z[keep]
        nearer = z < depth[rows, cols]          # ties: the earlier triangle stays
        wr, wc = rows[nearer], cols[nearer]
        depth[wr, wc] = z[nearer]
        ids[wr, wc] = index
        if image is not None and len(wr):
            b = bary[nearer]
            if w is not None:                   # perspective-correct: interpolate q/w and 1/w
                b = b / w[index]
                b = b / b.sum(axis=1, keepdims=True)
            image[wr, wc] = b @ vals[index]
        state["fragments"] += len(rows)
        state["writes"] += len(wr)
        yield index, (rows, cols), (wr, wc), state


def _zbuffer_inputs(triangles, width, height, values, w):
    tris = _triangles(triangles, "triangles")
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
    vals, scalar = _check_values(values, len(tris))
    if w is not None:
        w = as_array(w, "w")
        if w.shape != (len(tris), 3) or np.any(w <= 0):
            raise ValueError(f"w must be the positive clip-space w of each vertex, shape "
                             f"({len(tris)}, 3), got shape {w.shape}")
    return tris, width, height, vals, scalar, w


def zbuffer(triangles, width, height, values=None, w=None, background=0.0):
    r"""The z-buffer algorithm: depth and id buffers of screen triangles, drawn in any order.

    For each triangle, for each pixel centre it covers (:func:`triangle_coverage`), the depth
    :math:`z = \sum_k \lambda_k z_k` is compared with the depth buffer; if nearer, it replaces
    the buffer's depth and the pixel's triangle id. Fragments outside the depth range [0, 1]
    are dropped (per-pixel near and far clipping). On equal depths the triangle drawn first
    keeps the pixel.

    **Why linear interpolation of depth is right here.** The perspective divide maps planes to
    planes, so a triangle's points after the divide still lie on a plane in (x, y, z) screen
    space, and on a plane z is an affine function of x and y: interpolating the vertices' screen
    depths with screen-space barycentric weights is exact. (Eye-space depth :math:`z_e` is *not*
    affine on the screen: it is :math:`1/z_e` that is.) Other vertex values (colours, texture
    coordinates) live in eye space; pass the vertices' clip-space `w` to interpolate them
    perspective-correctly, as :math:`\sum \lambda_k q_k / w_k \,/\, \sum \lambda_k / w_k`.

    Cost: each triangle once, :math:`O(P)`, plus work proportional to the pixels it covers;
    memory :math:`O(p)` for the two buffers. Triangles are looped over in Python; the pixels of
    each triangle's bounding box are processed at once with numpy.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
        Triangles in viewport coordinates: pixel x, pixel y (row 0 at the bottom), depth in
        [0, 1] (0 near, 1 far), e.g. from :func:`course_lib.viewing.to_screen`.
    width, height : int
        Image size in pixels.
    values : array_like, shape (m, 3) or (m, 3, k), optional
        A value or a vector (e.g. an RGB colour) per vertex, interpolated to every visible pixel.
    w : array_like, shape (m, 3), optional
        The vertices' clip-space w (their distance in front of the eye for a perspective
        camera): makes the interpolation of `values` perspective-correct.
    background : float, optional
        The value of `image` where nothing is drawn (default 0).

    Returns
    -------
    ZBuffer
        ``depth`` (``inf`` on background) and ``ids`` (-1 on background), shape
        (height, width); ``image`` with the interpolated values or None; and the counts
        ``fragments`` and ``writes``. Show with ``plt.imshow(zb.ids, origin="lower")``.

    Raises
    ------
    ValueError
        For triangles not of shape (m, 3, 3), no triangles, non-finite coordinates, or a width
        or height that is not a positive whole number.

    Examples
    --------
    A far triangle, then a near one over its right part (the top-right pixel's centre
    (3.5, 1.5) lies outside both):

    >>> tris = [[[0, 0, 0.8], [4, 0, 0.8], [0, 4, 0.8]], [[2, 0, 0.3], [4, 0, 0.3], [2, 4, 0.3]]]
    >>> zb = zbuffer(tris, 4, 2)
    >>> zb.ids                     # row 0 (the bottom) printed first
    array([[ 0,  0,  1,  1],
           [ 0,  0,  1, -1]])
    >>> zb.depth
    array([[0.8, 0.8, 0.3, 0.3],
           [0.8, 0.8, 0.3, inf]])
    """
    tris, width, height, vals, scalar, w = _zbuffer_inputs(triangles, width, height, values, w)
    state = None
    for *_, state in _zbuffer_run(tris, width, height, vals, w, background):
        pass
    image = state["image"]
    if image is not None and scalar:
        image = image[..., 0]
    return ZBuffer(state["depth"], state["ids"], image, state["fragments"], state["writes"])


def zbuffer_steps(triangles, width, height):
    """The z-buffer one triangle at a time, for a step-by-step visualizer.

    Same algorithm and arguments as :func:`zbuffer`; after each triangle it yields which pixels
    the triangle covered, which of them it won (nearer than the buffer), and copies of the
    buffers. Drawing the triangles in a different order changes the steps and the number of
    overwrites, never the final buffers (except between exactly equal depths).

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
        Triangles in viewport coordinates.
    width, height : int

    Yields
    ------
    ZBufferStep
        ``index``, ``covered`` and ``written`` masks, and the ``depth`` and ``ids`` buffers.

    Raises
    ------
    ValueError
        As :func:`zbuffer`.

    Examples
    --------
    >>> tris = [[[0, 0, 0.3], [2, 0, 0.3], [0, 2, 0.3]], [[0, 0, 0.6], [2, 0, 0.6], [2, 2, 0.6]]]
    >>> steps = list(zbuffer_steps(tris, 2, 2))
    >>> [s.ids.tolist() for s in steps]     # the second one loses the pixel both cover
    [[[0, -1], [-1, -1]], [[0, 1], [-1, 1]]]
    """
    tris, width, height, *_ = _zbuffer_inputs(triangles, width, height, None, None)

    def steps():
        for index, (rows, cols), (wr, wc), state in _zbuffer_run(tris, width, height):
            covered = np.zeros((height, width), dtype=bool)
            covered[rows, cols] = True
            written = np.zeros((height, width), dtype=bool)
            written[wr, wc] = True
            yield ZBufferStep(index, covered, written, state["depth"].copy(), state["ids"].copy())
    return steps()


def _lexi_first(p, q):
    """Order two points lexicographically so that an edge's clip point is computed the same way
    from both triangles that share it (bit-identical vertices keep the fill rule watertight)."""
    for a, b in zip(p, q):
        if a != b:
            return (p, q) if a < b else (q, p)
    return p, q


def _clip_near(clip, attrs):
    """Clip homogeneous triangles (m, 3, 4) against the near plane z + w >= 0.

    Returns the triangles (k, 3, 4), the index of the source triangle of each, and the clipped
    attributes (k, 3, a) or None. Triangles entirely in front are kept as they are.
    """
    dist = clip[..., 2] + clip[..., 3]
    inside = dist >= 0
    all_in, any_in = inside.all(axis=1), inside.any(axis=1)
    keep = np.nonzero(all_in)[0]
    out_tris, out_src, out_attr = [clip[keep]], [keep], [None if attrs is None else attrs[keep]]
    for t in np.nonzero(any_in & ~all_in)[0]:
        verts = clip[t] if attrs is None else np.concatenate([clip[t], attrs[t]], axis=1)
        poly = []
        for i in range(3):
            j = (i + 1) % 3
            if inside[t, i]:
                poly.append(verts[i])
            if inside[t, i] != inside[t, j]:
                (p, dp), (q, dq) = _ordered_pair(verts[i], dist[t, i], verts[j], dist[t, j])
                poly.append(p + dp / (dp - dq) * (q - p))
        fan = np.array([[poly[0], poly[k], poly[k + 1]] for k in range(1, len(poly) - 1)])
        out_tris.append(fan[..., :4])
        out_src.append(np.full(len(fan), t))
        if attrs is not None:
            out_attr.append(fan[..., 4:])
    tris = np.concatenate(out_tris).reshape(-1, 3, 4)
    src = np.concatenate(out_src).astype(np.intp)
    attr = None if attrs is None else np.concatenate(out_attr).reshape(len(tris), 3, -1)
    return tris, src, attr


def _ordered_pair(p, dp, q, dq):
    first, _ = _lexi_first(tuple(p), tuple(q))
    return ((p, dp), (q, dq)) if first == tuple(p) else ((q, dq), (p, dp))


def _screen_triangles(world_tris, pv, width, height, attrs=None):
    """World triangles -> clip space -> near clipping -> divide -> viewport.

    Returns screen triangles (k, 3, 3), their source indices, clip w (k, 3) and attributes.
    """
    hom = transforms.to_homogeneous(world_tris.reshape(-1, 3)) @ pv.T
    tris, src, attr = _clip_near(hom.reshape(-1, 3, 4), attrs)
    if len(tris) == 0:
        return np.zeros((0, 3, 3)), src, np.zeros((0, 3)), attr
    ndc = transforms.from_homogeneous(tris.reshape(-1, 4))
    screen = transforms.apply(viewing.viewport(0, 0, width, height), ndc).reshape(-1, 3, 3)
    return screen, src, tris[..., 3], attr


def render_depth(vertices, faces, view, projection, width, height, values=None,
                 cull_back_faces=False):
    r"""Render a triangle mesh with the z-buffer through the whole viewing pipeline.

    Each vertex goes WCS -> ECS (`view`, e.g. :func:`course_lib.viewing.look_at`) -> clip
    space (`projection`, e.g. :func:`course_lib.viewing.perspective`); triangles are clipped
    against the near plane in homogeneous coordinates (:math:`z_c + w_c \ge 0`, so that parts
    behind the eye never reach the divide), divided by :math:`w`, mapped to pixels by
    :func:`course_lib.viewing.viewport` with depth in [0, 1], and drawn by :func:`zbuffer`.
    The far plane and the sides are clipped per pixel.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        World coordinates.
    faces : array_like of int, shape (m, 3)
        Triangles as vertex indices (counter-clockwise seen from outside if
        `cull_back_faces`).
    view, projection : array_like, shape (4, 4)
    width, height : int
        Image size in pixels.
    values : array_like, shape (n,) or (n, k), optional
        Per-vertex values (e.g. colours), interpolated perspective-correctly.
    cull_back_faces : bool, optional
        Drop triangles that appear clockwise on the screen (back faces of a closed mesh).

    Returns
    -------
    ZBuffer
        As :func:`zbuffer`, with ``ids`` indexing `faces`.

    Raises
    ------
    ValueError
        For malformed vertices, faces or matrices, or a non-positive image size.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> square = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    >>> zb = render_depth(square, [[0, 1, 2], [0, 2, 3]], V, P, 8, 8)
    >>> np.unique(zb.ids).tolist(), round(float(zb.depth[4, 4]), 6)    # depth of z_e = -3
    ([-1, 0, 1], 0.740741)
    """
    v, f = as_mesh(vertices, faces)
    view, projection = _camera(view, projection)
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
    attrs, scalar = None, False
    if values is not None:
        vals = as_array(values, "values")
        if vals.ndim not in (1, 2) or vals.shape[0] != len(v):
            raise ValueError(f"values must hold one value (shape (n,)) or one vector (shape "
                             f"(n, k)) per vertex of the {len(v)} vertices, got {vals.shape}")
        scalar = vals.ndim == 1
        attrs = (vals[:, None] if scalar else vals)[f]
    screen, src, w, attrs = _screen_triangles(v[f], projection @ view, width, height, attrs)
    if cull_back_faces and len(screen):
        x, y = screen[..., 0], screen[..., 1]
        front = _orient(x[:, 0], y[:, 0], x[:, 1], y[:, 1], x[:, 2], y[:, 2]) > 0
        screen, src, w = screen[front], src[front], w[front]
        attrs = None if attrs is None else attrs[front]
    if len(screen) == 0:
        depth = np.full((height, width), np.inf)
        ids = np.full((height, width), -1, dtype=np.intp)
        image = None
        if attrs is not None:
            k = 1 if scalar else np.shape(values)[1]
            image = np.zeros((height, width) if scalar else (height, width, k))
        return ZBuffer(depth, ids, image, 0, 0)
    state = None
    for *_, state in _zbuffer_run(screen, width, height, attrs, w if attrs is not None else None):
        pass
    ids = state["ids"]
    ids = np.where(ids >= 0, src[np.maximum(ids, 0)], -1)
    image = state["image"]
    if image is not None and scalar:
        image = image[..., 0]
    return ZBuffer(state["depth"], ids, image, state["fragments"], state["writes"])
