r"""Chapter 5: hidden-surface elimination and occlusion culling.

Culling throws away work that cannot change the picture; hidden-surface elimination (HSE) decides,
for what is left, which surface each pixel shows. This module implements the chapter's
algorithms on small, inspectable data, so that a notebook can draw every intermediate step.

**Hidden-surface elimination** (all three give the same picture, up to pixels whose centre lies
exactly on an edge):

* :func:`zbuffer` / :func:`render_depth`: the **z-buffer** (image precision). Rasterize the
  triangles in any order; a pixel keeps the fragment with the smallest depth seen so far.
  :func:`zbuffer_steps` replays it one triangle at a time.
* :func:`ray_cast` / :func:`ray_cast_image`: **ray casting**. One ray per pixel, each tested
  against the primitives; the nearest hit wins. :class:`BVH` is a bounding-volume hierarchy
  that skips most of those tests.
* :func:`build_bsp`, :func:`bsp_back_to_front`, :func:`painter_image`: the **painter's
  algorithm** (object precision ordering, then overwrite without a depth buffer), with the
  order from a **binary space partitioning (BSP) tree**; :func:`depth_sort` is the naive order
  that sorts by depth and :func:`painter_counterexample` shows where it breaks.

**Occlusion culling** (discard whole objects that are certainly hidden, before any of the above):

* from a point: :func:`shadow_frustum`, :func:`occlusion_cull`, :func:`occluder_solid_angle`,
  :func:`rank_occluders`;
* from a region: a 2D floor plan of cells and portals (:class:`FloorPlan`,
  :func:`example_floor_plan`), the stabbing-line test :func:`stabbing_line`, the potentially
  visible set :func:`pvs`, and :func:`visible_from_point` for one viewer.

Conventions
-----------
Screen triangles are in **viewport coordinates**, as :func:`course_lib.viewing.viewport` makes
them: pixel x to the right, pixel y **up**, depth z in [0, 1] growing away from the viewer
(near plane 0, far plane 1). Pixel ``(row j, column i)`` covers the square
:math:`[i, i+1] \times [j, j+1]` and is sampled at its centre :math:`(i + \tfrac12, j +
\tfrac12)`. **Row 0 is the bottom row**, so images are shown with
``plt.imshow(ids, origin="lower", extent=(0, width, 0, height))`` (without ``origin="lower"``
the picture is upside down). The depth buffer starts at ``+inf`` ("nothing drawn"), the id
buffer at -1 (background).

Efficiency issues
-----------------
Write :math:`P` for the number of primitives (triangles) and :math:`p` for the number of pixels.

* **Ray casting** tests every ray against every primitive: :math:`p \cdot P` ray-triangle tests,
  whatever the scene looks like. It parallelizes trivially (every ray is independent), but for a
  300 x 300 image of a 20,000-triangle model that is 1.8 billion tests. Bounding volumes are the
  cure: wrap groups of primitives in boxes, nest the boxes into a hierarchy, and skip a whole
  group when its box is missed or lies behind a hit already found. A ray then meets about
  :math:`O(\log P)` boxes and only a handful of triangles; the hierarchy costs
  :math:`O(P \log P)` to build, once, for a static scene. :func:`ray_cast` counts the tests so
  the difference can be seen, not just timed.
* **The z-buffer** visits each primitive once, :math:`O(P)`, and spends time proportional to the
  pixels it covers: the total is :math:`O(P + p \cdot d)` with :math:`d` the *depth complexity*
  (how many surfaces cover a pixel, on average). It needs :math:`O(p)` extra memory, one depth
  per pixel, and no sorting; order does not matter for correctness, only for how often a pixel
  is overwritten (front-to-back order wastes the fewest writes). Hardware does exactly this.
  Its weak points: limited depth precision (depth after the perspective divide is crowded near
  the far plane), and every hidden fragment is still rasterized.
* **The painter's algorithm** needs no depth memory but a correct back-to-front order. Sorting by
  depth costs :math:`O(P \log P)` per frame and is simply wrong for interpenetrating or
  cyclically overlapping polygons. A BSP tree gives a correct order for *every* viewpoint:
  it is built once, :math:`O(P \log P)` for good splits and up to :math:`O(P^2)` fragments for
  bad ones (splitting is why the choice of partition plane matters), and each frame costs one
  :math:`O(P')` traversal over the :math:`P'` fragments, with a single dot product per node.
  Every fragment is drawn, hidden or not: maximum overdraw.
* **Occlusion culling** shrinks :math:`P` before any of these run. From a point, each frame
  tests the :math:`n` objects' bounding volumes against the shadow frusta of :math:`k` chosen
  occluders: :math:`O(n k)` cheap plane tests, worth it when the culled objects are expensive
  (many triangles each). Few, large occluders give most of the benefit, hence
  :func:`rank_occluders`. From a region, the expensive part (the potentially visible set of each
  cell, by following stabbable portal sequences) is computed once offline; at run time the
  renderer looks up one row of a cells x cells boolean matrix, :math:`O(1)` per cell, at the
  price of :math:`O(\text{cells}^2)` bits of storage. Both are *conservative*: they may draw
  something hidden, never drop something visible; the z-buffer then finishes the job exactly.
"""
import math
from typing import NamedTuple

import numpy as np

from . import transforms, viewing
from ._validate import as_array, as_matrix, as_points, as_scalar, as_vector

__all__ = [
    "BSPNode",
    "BSPTree",
    "BVH",
    "FloorPlan",
    "Hits",
    "Painted",
    "PointVisibility",
    "RayCastImage",
    "Scene",
    "ZBuffer",
    "ZBufferStep",
    "build_bsp",
    "bsp_back_to_front",
    "cell_of",
    "depth_sort",
    "example_floor_plan",
    "floor_plan",
    "occluder_solid_angle",
    "occlusion_cull",
    "painter_counterexample",
    "painter_image",
    "pvs",
    "random_scene",
    "rank_occluders",
    "ray_cast",
    "ray_cast_image",
    "ray_triangle",
    "render_depth",
    "render_painter",
    "shadow_frustum",
    "split_polygon",
    "stabbing_line",
    "triangle_coverage",
    "visible_from_point",
    "walls",
    "zbuffer",
    "zbuffer_steps",
]


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _pixels(value, name):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number of pixels, got a bool")
    v = as_scalar(value, name)
    if v <= 0 or v != int(v):
        raise ValueError(f"{name} must be a positive whole number of pixels, got {value!r}")
    return int(v)


def _triangles(value, name, dim=3):
    t = as_array(value, name)
    if t.shape == (3, dim):
        t = t[None]
    if t.ndim != 3 or t.shape[1:] != (3, dim):
        raise ValueError(f"{name} must be an array of triangles of shape (m, 3, {dim}) "
                         f"(m triangles, 3 vertices, {dim} coordinates), got shape {t.shape}")
    if len(t) == 0:
        raise ValueError(f"{name} must contain at least one triangle, got an empty array")
    return t


def _faces(faces, n_vertices):
    f = np.asarray(faces)
    if f.ndim == 1 and f.shape == (3,):
        f = f[None]
    if f.ndim != 2 or f.shape[1] != 3 or not (np.issubdtype(f.dtype, np.integer) or f.size == 0):
        raise ValueError(f"faces must be an (m, 3) array of vertex indices (triangles only), "
                         f"got shape {f.shape} and type {f.dtype}")
    if len(f) == 0:
        raise ValueError("faces must contain at least one triangle, got an empty array")
    if f.min() < 0 or f.max() >= n_vertices:
        bad = int(f.max() if f.max() >= n_vertices else f.min())
        raise ValueError(f"faces refers to vertex {bad} but there are {n_vertices} vertices")
    return f.astype(np.intp)


def _mesh(vertices, faces):
    v = as_points(vertices, "vertices", dims=3)
    if v.ndim != 2 or len(v) == 0:
        raise ValueError(f"vertices must be an (n, 3) array with n >= 1, got shape {v.shape}")
    return v, _faces(faces, len(v))


def _camera(view, projection):
    return as_matrix(view, "view", 4), as_matrix(projection, "projection", 4)


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
    return _raster(tri, _pixels(width, "width"), _pixels(height, "height"))


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
    width, height = _pixels(width, "width"), _pixels(height, "height")
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
    v, f = _mesh(vertices, faces)
    view, projection = _camera(view, projection)
    width, height = _pixels(width, "width"), _pixels(height, "height")
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


# ---------------------------------------------------------------------------------------------
# Ray casting
# ---------------------------------------------------------------------------------------------

class Hits(NamedTuple):
    """The nearest hits of :func:`ray_cast`, with the work it took.

    Attributes
    ----------
    t : ndarray, shape (p,)
        Ray parameter of the nearest hit, the hit point being ``origin + t * direction``
        (the distance when the directions are unit vectors); ``inf`` on a miss.
    ids : ndarray of int, shape (p,)
        Index of the triangle hit, -1 on a miss.
    triangle_tests : int
        Ray-triangle intersection tests performed (``p * P`` for brute force).
    box_tests : int
        Ray-box tests performed (0 for brute force).

    Examples
    --------
    >>> hits = ray_cast([0, 0, 5], [0, 0, -1], [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]]])
    >>> hits.t.tolist(), hits.ids.tolist(), hits.triangle_tests
    ([5.0], [0], 1)
    """
    t: np.ndarray
    ids: np.ndarray
    triangle_tests: int
    box_tests: int


def _moller_trumbore(o, d, v0, e1, e2):
    """(t, u, v) of rays (o, d) against triangles (v0, e1, e2), t = inf on a miss.

    All arguments broadcast (last axis 3); see :func:`_moller_trumbore_soa`.
    """
    return _moller_trumbore_soa((o[..., 0], o[..., 1], o[..., 2]),
                                (d[..., 0], d[..., 1], d[..., 2]),
                                (v0[..., 0], v0[..., 1], v0[..., 2], e1[..., 0], e1[..., 1],
                                 e1[..., 2], e2[..., 0], e2[..., 1], e2[..., 2]))


def _moller_trumbore_soa(o, d, tri):
    """(t, u, v) of rays against triangles, component by component; t = inf on a miss.

    `o` and `d` are sequences of 3 arrays (x, y, z), `tri` a sequence of 9 arrays
    (v0, e1 = v1 - v0, e2 = v2 - v0); all broadcast. Written out per component so that each
    (ray, triangle) pair goes through the same floating-point operations whatever the batching:
    brute force and a BVH then agree bit for bit (also used by :mod:`course_lib.raytracing`).
    """
    dx, dy, dz = d[0], d[1], d[2]
    ax, ay, az = tri[3], tri[4], tri[5]
    bx, by, bz = tri[6], tri[7], tri[8]
    px, py, pz = dy * bz - dz * by, dz * bx - dx * bz, dx * by - dy * bx       # d x e2
    det = ax * px + ay * py + az * pz
    tx, ty, tz = o[0] - tri[0], o[1] - tri[1], o[2] - tri[2]                    # s = o - v0
    qx, qy, qz = ty * az - tz * ay, tz * ax - tx * az, tx * ay - ty * ax       # s x e1
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        inv = 1.0 / det
        u = (tx * px + ty * py + tz * pz) * inv
        v = (dx * qx + dy * qy + dz * qz) * inv
        t = (bx * qx + by * qy + bz * qz) * inv
        hit = (det != 0) & (u >= 0) & (v >= 0) & (u + v <= 1)
    return np.where(hit, t, np.inf), u, v


def _rays(origins, directions):
    o = as_points(origins, "origins", dims=3)
    d = as_points(directions, "directions", dims=3)
    if o.ndim > 2 or d.ndim > 2:
        raise ValueError(f"origins and directions must be (p, 3) arrays or single points, got "
                         f"shapes {o.shape} and {d.shape}")
    try:
        o, d = np.broadcast_arrays(np.atleast_2d(o), np.atleast_2d(d))
    except ValueError:
        raise ValueError(f"origins ({o.shape}) and directions ({d.shape}) must hold the same "
                         "number of rays, or one of them a single one") from None
    if len(o) == 0:
        raise ValueError("origins and directions must contain at least one ray")
    if np.any(np.abs(d).max(axis=1) == 0):
        raise ValueError("directions must not contain the zero vector: a ray needs a direction")
    return np.ascontiguousarray(o), np.ascontiguousarray(d)


def _t_range(t_min, t_max):
    t_min = as_scalar(t_min, "t_min")
    t_max = np.inf if np.isscalar(t_max) and np.isposinf(t_max) else as_scalar(t_max, "t_max")
    if t_max < t_min:
        raise ValueError(f"t_max must not be below t_min (got t_min = {t_min}, t_max = {t_max})")
    return t_min, t_max


def ray_triangle(origins, directions, triangle):
    r"""Möller-Trumbore ray-triangle intersection: ray parameter and barycentric coordinates.

    Solve :math:`o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)` for :math:`(t, u, v)` by
    Cramer's rule with :math:`e_1 = v_1 - v_0`, :math:`e_2 = v_2 - v_0`, :math:`s = o - v_0`:

    .. math:: \begin{bmatrix} t \\ u \\ v \end{bmatrix} = \frac{1}{(d \times e_2) \cdot e_1}
              \begin{bmatrix} (s \times e_1) \cdot e_2 \\ (d \times e_2) \cdot s \\
              (s \times e_1) \cdot d \end{bmatrix}

    The ray hits when :math:`u, v \ge 0` and :math:`u + v \le 1` (the point is inside the
    triangle) and the determinant is not 0 (the ray is not parallel to its plane). Both sides of
    the triangle are hit (no back-face culling). About 30 multiplications, no square root.

    Parameters
    ----------
    origins, directions : array_like, shape (p, 3) or (3,)
    triangle : array_like, shape (3, 3)

    Returns
    -------
    t, u, v : ndarray, shape (p,)
        ``t`` is ``inf`` where the ray's line misses (negative ``t``, behind the origin, is
        reported: filter it as needed).

    Raises
    ------
    ValueError
        For malformed rays or triangle, or a zero direction.

    Examples
    --------
    >>> t, u, v = ray_triangle([0.25, 0.25, 2], [0, 0, -1], [[0, 0, 0], [1, 0, 0], [0, 1, 0]])
    >>> t.tolist(), u.tolist(), v.tolist()
    ([2.0], [0.25], [0.25])
    """
    o, d = _rays(origins, directions)
    tri = _triangles(triangle, "triangle")
    if len(tri) != 1:
        raise ValueError(f"triangle must be a single triangle of shape (3, 3), got {tri.shape}")
    tri = tri[0]
    return _moller_trumbore(o, d, tri[0], tri[1] - tri[0], tri[2] - tri[0])


def _brute_force(o, d, v0, e1, e2, t_min, t_max):
    p, n = len(o), len(v0)
    best_t = np.full(p, np.inf)
    best_id = np.full(p, -1, dtype=np.intp)
    chunk = max(1, (1 << 18) // p)
    rows = np.arange(p)
    for s in range(0, n, chunk):
        t = _moller_trumbore(o[:, None], d[:, None], v0[None, s:s + chunk], e1[None, s:s + chunk],
                             e2[None, s:s + chunk])[0]
        t[(t < t_min) | (t > t_max)] = np.inf
        j = np.argmin(t, axis=1)                  # the lowest index among equal distances
        tj = t[rows, j]
        better = tj < best_t
        best_t[better] = tj[better]
        best_id[better] = j[better] + s
    return Hits(best_t, best_id, p * n, 0)


def _lower_part(key, k):
    """Boolean mask of the `k` smallest entries of `key`, ties going to the lower positions.

    O(n), like ``np.argpartition``, but deterministic: argpartition leaves ties at the k-th
    value in whatever order numpy's CPU-specific kernel produces (its AVX-512, AVX2 and
    baseline kernels differ), which changed the BVH and its test counts from one machine to the
    next. Here only the k-th *value* comes from ``np.partition``, the same on every machine.
    """
    kth = np.partition(key, k)[k]
    left = key < kth
    short = k - np.count_nonzero(left)
    if short:                                   # ties at the k-th value: the first ones go left
        left[np.flatnonzero(key == kth)[:short]] = True
    return left


class BVH:
    r"""A bounding-volume hierarchy of axis-aligned boxes over triangles, for ray casting.

    **Build** (once, :math:`O(P \log P)`): put all triangles in the root; split a node's
    triangles at the median of their box centres along the axis where those centres spread
    most (equal centres: the lower triangle index goes left, so the tree is the same on every
    machine); recurse until at most `leaf_size` triangles remain. Every node stores the box
    bounding its triangles (padded by a hair so rounding never loses a hit).

    **Traversal** (per ray): a ray that misses a node's box, or reaches it only beyond the
    nearest hit found so far, skips the whole subtree; otherwise the nearer child is visited
    first, so that hits found early prune the rest. Rays are processed together as a packet (a
    numpy array of ray indices per node), so the Python loop runs over nodes, not rays. The
    result equals brute force exactly (same nearest triangle, same distance bit for bit, the
    lowest index among equal distances); only the number of tests differs.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
    leaf_size : int, optional
        Most triangles per leaf (default 4).

    Attributes
    ----------
    triangles : ndarray, shape (m, 3, 3)
    lo, hi : ndarray, shape (nodes, 3)
        The nodes' boxes (node 0 is the root).
    children : ndarray of int, shape (nodes, 2)
        Left and right child, -1 for leaves.
    depth : int
        Levels below the root.

    Raises
    ------
    ValueError
        For malformed triangles or a leaf size below 1.

    Examples
    --------
    >>> import numpy as np
    >>> rng = np.random.default_rng(0)
    >>> tris = rng.uniform(-1, 1, (1000, 1, 3)) + 0.05 * rng.normal(size=(1000, 3, 3))
    >>> bvh = BVH(tris)
    >>> o = np.array([[0.0, 0.0, 5.0]]); d = np.array([[0.01, 0.02, -1.0]])
    >>> fast, slow = bvh.cast(o, d), ray_cast(o, d, tris)
    >>> bool(fast.ids[0] == slow.ids[0] and fast.t[0] == slow.t[0])
    True
    >>> fast.triangle_tests < slow.triangle_tests // 20
    True
    """

    def __init__(self, triangles, leaf_size=4):
        tris = _triangles(triangles, "triangles")
        leaf_size = _pixels(leaf_size, "leaf_size")
        self.triangles = tris
        self._v0 = np.ascontiguousarray(tris[:, 0])
        self._e1 = tris[:, 1] - tris[:, 0]
        self._e2 = tris[:, 2] - tris[:, 0]
        tmin, tmax = tris.min(axis=1), tris.max(axis=1)
        centre = (tmin + tmax) / 2
        pad = 1e-9 * max(float(np.abs(tris).max()), 1e-300)
        order = np.arange(len(tris))
        lo, hi, children, axes, spans = [], [], [], [], []

        def new_node():
            lo.append(None), hi.append(None), children.append([-1, -1]), axes.append(0)
            spans.append((0, 0))
            return len(lo) - 1

        depth = 0
        stack = [(new_node(), 0, len(tris), 0)]
        while stack:
            node, s, e, level = stack.pop()
            depth = max(depth, level)
            idx = order[s:e]
            lo[node] = tmin[idx].min(axis=0) - pad
            hi[node] = tmax[idx].max(axis=0) + pad
            if e - s <= leaf_size:
                order[s:e] = np.sort(idx)           # lowest index first within a leaf
                spans[node] = (s, e)
                continue
            c = centre[idx]
            axis = int(np.argmax(c.max(axis=0) - c.min(axis=0)))
            mid = (s + e) // 2
            # idx is in ascending triangle index (each side keeps its order), so equal
            # centres send the lower triangle index left
            lower = _lower_part(c[:, axis], mid - s)
            order[s:mid], order[mid:e] = idx[lower], idx[~lower]
            left, right = new_node(), new_node()
            children[node] = [left, right]
            axes[node] = axis
            stack.append((right, mid, e, level + 1))
            stack.append((left, s, mid, level + 1))
        self.lo, self.hi = np.array(lo), np.array(hi)
        self.children = np.array(children, dtype=np.intp)
        self._axes = np.array(axes)
        self._spans = np.array(spans, dtype=np.intp)
        self._order = order
        self.depth = depth

    def __repr__(self):
        return (f"BVH({len(self.triangles)} triangles, {len(self.lo)} nodes, "
                f"depth {self.depth})")

    def cast(self, origins, directions, t_min=0.0, t_max=np.inf):
        """Nearest hits of many rays: as :func:`ray_cast` with ``accelerate=True``.

        Parameters
        ----------
        origins, directions : array_like, shape (p, 3) or (3,)
        t_min, t_max : float, optional
            Only hits with ``t_min <= t <= t_max`` count.

        Returns
        -------
        Hits

        Examples
        --------
        >>> bvh = BVH([[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]])
        >>> bvh.cast([[0, 0, 5], [0, 0, -5]], [0, 0, -1]).ids.tolist()
        [1, -1]
        """
        o, d = _rays(origins, directions)
        t_min, t_max = _t_range(t_min, t_max)
        return self._cast(o, d, t_min, t_max)

    def _cast(self, o, d, t_min, t_max):
        p = len(o)
        best_t = np.full(p, np.inf)
        best_id = np.full(p, -1, dtype=np.intp)
        tri_tests = box_tests = 0
        stack = [(0, np.arange(p))]
        while stack:
            node, rays = stack.pop()
            box_tests += len(rays)
            ro, rd = o[rays], d[rays]
            with np.errstate(divide="ignore", invalid="ignore"):
                t1 = (self.lo[node] - ro) / rd
                t2 = (self.hi[node] - ro) / rd
            near, far = np.minimum(t1, t2), np.maximum(t1, t2)
            parallel = rd == 0                          # inside the slab: all t; else none
            within = (ro >= self.lo[node]) & (ro <= self.hi[node])
            near = np.where(parallel, np.where(within, -np.inf, np.inf), near)
            far = np.where(parallel, np.where(within, np.inf, -np.inf), far)
            t_in, t_out = near.max(axis=1), far.min(axis=1)
            ok = (t_in <= t_out) & (t_out >= t_min) & (t_in <= np.minimum(best_t[rays], t_max))
            rays = rays[ok]
            if len(rays) == 0:
                continue
            left, right = self.children[node]
            if left < 0:
                s, e = self._spans[node]
                ids = self._order[s:e]
                t = _moller_trumbore(o[rays][:, None], d[rays][:, None], self._v0[ids][None],
                                     self._e1[ids][None], self._e2[ids][None])[0]
                t[(t < t_min) | (t > t_max)] = np.inf
                tri_tests += len(rays) * len(ids)
                j = np.argmin(t, axis=1)
                tj, idj = t[np.arange(len(rays)), j], ids[j]
                cur_t, cur_id = best_t[rays], best_id[rays]
                better = (tj < cur_t) | ((tj == cur_t) & (idj < cur_id) & np.isfinite(tj))
                best_t[rays[better]] = tj[better]
                best_id[rays[better]] = idj[better]
                continue
            # visit the child nearer to the packet first (pushed last)
            if d[rays, self._axes[node]].sum() >= 0:
                stack += [(right, rays), (left, rays)]
            else:
                stack += [(left, rays), (right, rays)]
        return Hits(best_t, best_id, tri_tests, box_tests)


def ray_cast(origins, directions, triangles, t_min=0.0, t_max=np.inf, accelerate=False):
    r"""Ray casting: the nearest triangle along each ray.

    Brute force tests every ray against every triangle (:func:`ray_triangle`) and keeps the
    smallest :math:`t` in :math:`[t_{min}, t_{max}]`: exactly :math:`p \cdot P` tests for
    :math:`p` rays and :math:`P` triangles, the textbook's :math:`O(pP)`. Vectorized over rays
    and blocks of triangles. With ``accelerate=True`` a :class:`BVH` is built first (or pass a
    ready-made :class:`BVH` as `triangles` to reuse it across frames) and most tests are skipped;
    the answer is identical. Equal distances go to the lower triangle index.

    Parameters
    ----------
    origins, directions : array_like, shape (p, 3) or (3,)
        The rays ``origin + t * direction``; one origin (or direction) is shared by all rays.
    triangles : array_like, shape (m, 3, 3), or BVH
    t_min, t_max : float, optional
        Only hits with ``t_min <= t <= t_max`` count (default: in front of the origin).
    accelerate : bool, optional
        Use a bounding-volume hierarchy.

    Returns
    -------
    Hits
        ``t``, ``ids``, and the numbers of ``triangle_tests`` and ``box_tests`` performed.

    Raises
    ------
    ValueError
        For malformed or empty rays or triangles, a zero direction, or ``t_max < t_min``.

    Examples
    --------
    Two parallel triangles; the ray from above hits the upper one at distance 3:

    >>> tris = [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]]
    >>> hits = ray_cast([[0, 0, 5], [9, 9, 5]], [0, 0, -1], tris)
    >>> hits.t.tolist(), hits.ids.tolist(), hits.triangle_tests      # 2 rays x 2 triangles
    ([3.0, inf], [1, -1], 4)
    """
    o, d = _rays(origins, directions)
    t_min, t_max = _t_range(t_min, t_max)
    if isinstance(triangles, BVH):
        return triangles._cast(o, d, t_min, t_max)
    if accelerate:
        return BVH(triangles)._cast(o, d, t_min, t_max)
    tris = _triangles(triangles, "triangles")
    return _brute_force(o, d, tris[:, 0], tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0],
                        t_min, t_max)


class RayCastImage(NamedTuple):
    """The result of :func:`ray_cast_image`: one ray per pixel, row 0 at the bottom.

    Attributes
    ----------
    depth : ndarray, shape (height, width)
        Viewport depth in [0, 1] of the visible surface, as the z-buffer stores it; inf on
        background.
    ids : ndarray of int, shape (height, width)
        Index of the visible face, -1 for background.
    triangle_tests, box_tests : int
        The work done (see :class:`Hits`).

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> tri = [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]
    >>> ray_cast_image(tri, [[0, 1, 2]], V, P, 4, 4, accelerate=False).triangle_tests  # 16 x 1
    16
    """
    depth: np.ndarray
    ids: np.ndarray
    triangle_tests: int
    box_tests: int


def _pixel_rays(pv, width, height):
    """World rays through the pixel centres, from the near plane (t = 0) to the far (t = 1)."""
    i = (np.arange(width) + 0.5) * 2 / width - 1
    j = (np.arange(height) + 0.5) * 2 / height - 1
    x, y = np.meshgrid(i, j)
    inv = np.linalg.inv(pv)
    near = transforms.apply(inv, np.stack([x, y, -np.ones_like(x)], axis=-1).reshape(-1, 3))
    far = transforms.apply(inv, np.stack([x, y, np.ones_like(x)], axis=-1).reshape(-1, 3))
    return near, far - near


def ray_cast_image(vertices, faces, view, projection, width, height, accelerate=True):
    r"""Hidden-surface elimination by ray casting: the visible face at each pixel centre.

    For every pixel the ray through its centre is built by undoing the viewing pipeline
    (the inverse of `projection` @ `view` applied to the pixel's points on the near and far
    planes), so the ray covers exactly the view volume's depth range, as the z-buffer's clipping
    does. The nearest hit is found by :func:`ray_cast` and its depth mapped back to the
    viewport's [0, 1]. The result agrees with :func:`render_depth` (ids, and depths to rounding)
    at every pixel whose centre does not lie on an edge.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    view, projection : array_like, shape (4, 4)
    width, height : int
    accelerate : bool, optional
        Use a :class:`BVH` (default True; False shows the brute-force cost).

    Returns
    -------
    RayCastImage

    Raises
    ------
    ValueError
        For malformed input or a singular camera.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> square = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    >>> faces = [[0, 1, 2], [0, 2, 3]]
    >>> rc = ray_cast_image(square, faces, V, P, 8, 8, accelerate=False)
    >>> zb = render_depth(square, faces, V, P, 8, 8)
    >>> bool(np.all(rc.ids == zb.ids)), bool(np.allclose(rc.depth[2:6, 2:6], zb.depth[2:6, 2:6]))
    (True, True)
    """
    v, f = _mesh(vertices, faces)
    view, projection = _camera(view, projection)
    width, height = _pixels(width, "width"), _pixels(height, "height")
    pv = projection @ view
    if abs(np.linalg.det(pv)) < 1e-300:
        raise ValueError("projection @ view is singular: the camera cannot be inverted into rays")
    origins, directions = _pixel_rays(pv, width, height)
    hits = ray_cast(origins, directions, v[f], t_min=0.0, t_max=1.0, accelerate=accelerate)
    depth = np.full(len(origins), np.inf)
    hit = hits.ids >= 0
    points = origins[hit] + hits.t[hit, None] * directions[hit]
    depth[hit] = (transforms.apply(pv, points)[:, 2] + 1) / 2
    return RayCastImage(depth.reshape(height, width), hits.ids.reshape(height, width),
                        hits.triangle_tests, hits.box_tests)


# ---------------------------------------------------------------------------------------------
# The painter's algorithm: depth sort and BSP trees
# ---------------------------------------------------------------------------------------------

def _plane_of(poly):
    """Unit normal (Newell's method) and offset of a planar polygon, or None if degenerate."""
    nxt = np.roll(poly, -1, axis=0)
    normal = np.cross(poly, nxt).sum(axis=0)
    length = np.linalg.norm(normal)
    if length == 0 or not np.isfinite(length):
        return None
    normal = normal / length
    return normal, float(normal @ poly.mean(axis=0))


def split_polygon(polygon, normal, offset, eps=1e-12):
    r"""Split a convex polygon by the plane :math:`n \cdot x = c` into a front and a back part.

    With :math:`s_i = n \cdot v_i - c` (positive in front), walk the edges: a vertex goes to the
    side(s) it is on (both if :math:`|s_i| \le \varepsilon`), and an edge whose ends are
    strictly on opposite sides adds its crossing point :math:`v_i + \frac{s_i}{s_i - s_j}
    (v_j - v_i)` to both parts. This is the step a BSP tree performs for every polygon that
    straddles a partition plane.

    Parameters
    ----------
    polygon : array_like, shape (k, 3)
        A convex planar polygon, k >= 3.
    normal : array_like, shape (3,)
    offset : float
    eps : float, optional
        Distance within which a vertex counts as on the plane.

    Returns
    -------
    front, back : ndarray of shape (k', 3), or None
        The parts in front of and behind the plane (None where there is none).

    Raises
    ------
    ValueError
        For a polygon with fewer than 3 vertices or a malformed plane.

    Examples
    --------
    >>> front, back = split_polygon([[-1, 0, 0], [1, 0, 0], [1, 1, 0], [-1, 1, 0]], [1, 0, 0], 0)
    >>> front.tolist()
    [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]
    >>> back.tolist()
    [[-1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 1.0, 0.0]]
    """
    poly = as_points(polygon, "polygon", dims=3)
    if poly.ndim != 2 or len(poly) < 3:
        raise ValueError(f"polygon must have at least 3 vertices, shape (k, 3), got {poly.shape}")
    return _split(poly, as_vector(normal, "normal", 3), as_scalar(offset, "offset"),
                  as_scalar(eps, "eps"))


def _split(poly, n, c, eps):
    s = poly @ n - c
    side = np.where(s > eps, 1, np.where(s < -eps, -1, 0))
    front, back = [], []
    k = len(poly)
    for i in range(k):
        j = (i + 1) % k
        if side[i] >= 0:
            front.append(poly[i])
        if side[i] <= 0:
            back.append(poly[i])
        if side[i] * side[j] < 0:
            (p, sp), (q, sq) = _ordered_pair(poly[i], s[i], poly[j], s[j])
            x = p + sp / (sp - sq) * (q - p)
            front.append(x)
            back.append(x)
    front = np.array(front) if len(front) >= 3 and (side > 0).any() else None
    back = np.array(back) if len(back) >= 3 and (side < 0).any() else None
    return front, back


class BSPNode:
    """A node of a BSP tree: a partition plane, the polygons lying in it, and two subtrees.

    Attributes
    ----------
    normal : ndarray, shape (3,)
        Unit normal of the plane; its side ``normal . x > offset`` is the *front*.
    offset : float
    polygons : list of ndarray (k, 3)
        The polygons in the plane (the one that defined it and any coplanar ones).
    ids : list of int
        The source triangle of each.
    front, back : BSPNode or None

    Examples
    --------
    >>> tree = build_bsp([[[0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    >>> tree.root.normal.tolist(), tree.root.offset, tree.root.front is None
    ([0.0, 0.0, 1.0], 0.0, True)
    """
    __slots__ = ("normal", "offset", "polygons", "ids", "front", "back")

    def __init__(self, normal, offset):
        self.normal, self.offset = normal, offset
        self.polygons, self.ids = [], []
        self.front = self.back = None

    def __repr__(self):
        return (f"BSPNode(normal={np.round(self.normal, 3).tolist()}, offset={self.offset:.3g}, "
                f"{len(self.polygons)} polygon(s))")


class BSPTree(NamedTuple):
    """A BSP tree with its statistics (:func:`build_bsp`).

    Attributes
    ----------
    root : BSPNode
    n_nodes : int
    n_polygons : int
        Polygons stored (input triangles plus the extra fragments made by splitting).
    n_splits : int
        Polygons cut in two during the build.
    depth : int
        Longest root-to-leaf path (number of nodes).

    Examples
    --------
    >>> tree = build_bsp([[[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]])
    >>> tree.n_nodes, tree.n_polygons, tree.n_splits, tree.depth
    (2, 2, 0, 2)
    """
    root: BSPNode
    n_nodes: int
    n_polygons: int
    n_splits: int
    depth: int


def build_bsp(triangles, choose="first", eps=None):
    r"""Build a binary space partitioning tree of triangles (the preprocessing of the painter's
    algorithm).

    Take one polygon's plane as the partition plane of the node; every other polygon lies in
    front of it, behind it, in it (it is stored in the node), or straddles it (it is split by
    :func:`split_polygon` and each part goes its way). Recurse on the front and back lists.
    The result depends on the choice of planes: ``"first"`` takes the first polygon of each list
    (as the textbook's outline does); ``"fewest_splits"`` tries up to 8 candidates per node and
    keeps the plane that cuts the fewest others, giving fewer fragments for a little more build
    time. Building is done once for a static scene: :math:`O(P \log P)` for balanced, few-split
    trees, up to :math:`O(P^2)` fragments in bad cases. A closed convex object is the classic
    unbalanced case: every face has all the others behind it, so the tree degenerates into a
    chain of depth :math:`P` (no splits, but :math:`O(P^2)` classification work; about 0.8 s for
    2,000 triangles here). Degenerate (zero-area) triangles cover no pixel and are left out.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
        World coordinates.
    choose : {"first", "fewest_splits"}, optional
    eps : float, optional
        Distance within which a point counts as on a plane (default: 1e-9 times the scene's
        size).

    Returns
    -------
    BSPTree

    Raises
    ------
    ValueError
        For malformed triangles or an unknown `choose`.

    Examples
    --------
    The plane of the first (vertical) triangle cuts the second (horizontal) one in two:

    >>> tree = build_bsp([[[0, -1, -1], [0, 1, -1], [0, 0, 1]],
    ...                   [[-1, -1, 0], [1, -1, 0], [0, 1, 0]]])
    >>> tree.n_polygons, tree.n_splits
    (3, 1)
    """
    tris = _triangles(triangles, "triangles")
    if choose not in ("first", "fewest_splits"):
        raise ValueError(f"choose must be 'first' or 'fewest_splits', got {choose!r}")
    scale = max(float(np.abs(tris).max()), 1e-300)
    eps = 1e-9 * scale if eps is None else as_scalar(eps, "eps")
    planes = [_plane_of(t) for t in tris]
    keep = [i for i, pl in enumerate(planes) if pl is not None]
    if not keep:
        raise ValueError("triangles are all degenerate (zero area): there is nothing to draw")
    n_nodes = n_polygons = n_splits = depth = 0
    root = None
    stack = [(None, None, [tris[i] for i in keep], keep, 1)]
    while stack:
        parent, branch, polys, ids, level = stack.pop()
        depth = max(depth, level)
        verts = np.concatenate(polys)
        starts = np.cumsum([0] + [len(p) for p in polys[:-1]])

        def classify(plane):
            s = verts @ plane[0] - plane[1]
            return np.minimum.reduceat(s, starts), np.maximum.reduceat(s, starts)

        k = 0
        if choose == "fewest_splits" and len(polys) > 2:
            cuts = []
            for cand in range(min(8, len(polys))):
                smin, smax = classify(_plane_of(polys[cand]))
                cuts.append(int(np.sum((smin < -eps) & (smax > eps))))
            k = int(np.argmin(cuts))
        n, c = _plane_of(polys[k])
        node = BSPNode(n, c)
        n_nodes += 1
        if parent is None:
            root = node
        else:
            setattr(parent, branch, node)
        smin, smax = classify((n, c))
        on = (smin >= -eps) & (smax <= eps)
        on[k] = True
        in_front = ~on & (smin >= -eps)
        behind = ~on & ~in_front & (smax <= eps)
        node.polygons = [polys[i] for i in np.flatnonzero(on)]
        node.ids = [ids[i] for i in np.flatnonzero(on)]
        n_polygons += len(node.polygons)
        front = [polys[i] for i in np.flatnonzero(in_front)]
        front_ids = [ids[i] for i in np.flatnonzero(in_front)]
        back = [polys[i] for i in np.flatnonzero(behind)]
        back_ids = [ids[i] for i in np.flatnonzero(behind)]
        for i in np.flatnonzero(~(on | in_front | behind)):
            f_part, b_part = _split(polys[i], n, c, eps)
            n_splits += 1
            for part, lst, lst_ids in ((f_part, front, front_ids), (b_part, back, back_ids)):
                if part is not None and _plane_of(part) is not None:
                    lst.append(part)
                    lst_ids.append(ids[i])
        if back:
            stack.append((node, "back", back, back_ids, level + 1))
        if front:
            stack.append((node, "front", front, front_ids, level + 1))
    return BSPTree(root, n_nodes, n_polygons, n_splits, depth)


def bsp_back_to_front(tree, eye):
    r"""Traverse a BSP tree back to front as seen from `eye`: the painter's drawing order.

    At each node, the subtree on the *other* side of the partition plane from the eye cannot
    hide anything on the eye's side, so it is drawn first, then the node's own polygons, then
    the subtree on the eye's side:

    .. code-block:: text

        if eye in front of plane:  draw(back);  draw(node polygons);  draw(front)
        else:                      draw(front); draw(node polygons);  draw(back)

    One dot product per node: :math:`O(P')` per frame for :math:`P'` stored polygons, valid for
    any eye position without rebuilding the tree.

    Parameters
    ----------
    tree : BSPTree or BSPNode
    eye : array_like, shape (3,) or (4,)
        The centre of projection; a homogeneous ``(x, y, z, 0)`` is a viewer at infinity in
        that direction (a parallel projection, direction pointing *towards* the viewer).

    Returns
    -------
    polygons : list of ndarray (k, 3)
        Farthest first.
    ids : ndarray of int
        The source triangle of each polygon.

    Raises
    ------
    ValueError
        For a malformed eye.

    Examples
    --------
    >>> tree = build_bsp([[[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0, 1], [1, 0, 1], [0, 1, 1]]])
    >>> bsp_back_to_front(tree, [0, 0, 5])[1].tolist()      # from above: z = 0 first
    [0, 1]
    >>> bsp_back_to_front(tree, [0, 0, -5])[1].tolist()     # from below: z = 1 first
    [1, 0]
    """
    e = as_vector(eye, "eye", (3, 4))
    e = np.append(e, 1.0) if len(e) == 3 else e
    root = tree.root if isinstance(tree, BSPTree) else tree
    polys, ids = [], []
    stack = [(False, root)]
    while stack:
        emit, node = stack.pop()
        if node is None:
            continue
        if emit:
            polys.extend(node.polygons)
            ids.extend(node.ids)
            continue
        in_front = float(node.normal @ e[:3] - node.offset * e[3]) > 0
        far, near = (node.back, node.front) if in_front else (node.front, node.back)
        stack += [(False, near), (True, node), (False, far)]
    return polys, np.array(ids, dtype=np.intp)


def depth_sort(triangles, view, key="farthest"):
    r"""The naive painter's order: sort triangles by depth, farthest first.

    Depth is the distance in front of the eye, :math:`-z_e` after `view`. With
    ``key="farthest"`` each triangle is represented by its farthest vertex (the first step of
    Newell, Newell and Sancha's algorithm), with ``"centroid"`` by its centre. Sorting costs
    :math:`O(P \log P)` per frame. A single number per triangle cannot capture "is in front of",
    which is not even a consistent order for interpenetrating or cyclically overlapping
    triangles (see :func:`painter_counterexample`); the full algorithm adds overlap tests and
    splitting, and a BSP tree (:func:`build_bsp`) solves it once for all viewpoints.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
        World coordinates.
    view : array_like, shape (4, 4)
        WCS -> ECS matrix (:func:`course_lib.viewing.look_at`).
    key : {"farthest", "centroid"}, optional

    Returns
    -------
    ndarray of int, shape (m,)
        Triangle indices, farthest first (ties keep the input order).

    Raises
    ------
    ValueError
        For malformed input or an unknown key.

    Examples
    --------
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])
    >>> near = [[0, 0, 1], [1, 0, 1], [0, 1, 1]]; far = [[0, 0, -1], [1, 0, -1], [0, 1, -1]]
    >>> depth_sort([near, far], V).tolist()
    [1, 0]
    """
    tris = _triangles(triangles, "triangles")
    view = as_matrix(view, "view", 4)
    if key not in ("farthest", "centroid"):
        raise ValueError(f"key must be 'farthest' or 'centroid', got {key!r}")
    dist = -transforms.apply(view, tris.reshape(-1, 3))[:, 2].reshape(-1, 3)
    k = dist.max(axis=1) if key == "farthest" else dist.mean(axis=1)
    return np.argsort(-k, kind="stable")


class Painted(NamedTuple):
    """The result of :func:`painter_image`.

    Attributes
    ----------
    ids : ndarray of int, shape (height, width)
        The source triangle painted last at each pixel, -1 for background (row 0 at the bottom).
    fragments : int
        Pixels painted in total: every one is written, hidden or not (the overdraw cost).

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.orthographic(-1, 1, -1, 1, 1, 5)
    >>> out = painter_image([np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]])], [7],
    ...                     V, P, 2, 2)
    >>> out.ids.tolist(), out.fragments
    ([[7, 7], [7, 7]], 4)
    """
    ids: np.ndarray
    fragments: int


def painter_image(polygons, ids, view, projection, width, height):
    r"""The painter's algorithm: rasterize polygons in the given order, each over the last.

    No depth buffer: a later polygon simply overwrites earlier ones, so the order must be back
    to front (:func:`bsp_back_to_front`, or the flawed :func:`depth_sort`). Each convex polygon
    is cut into a fan of triangles, taken through the viewing pipeline like
    :func:`render_depth` (near plane clipped in homogeneous coordinates, far plane per pixel),
    and rasterized with the same fill rule.

    Parameters
    ----------
    polygons : sequence of array_like (k, 3)
        Convex planar polygons in world coordinates, in drawing order.
    ids : sequence of int
        A label per polygon, written into the image (e.g. its source triangle).
    view, projection : array_like, shape (4, 4)
    width, height : int

    Returns
    -------
    Painted

    Raises
    ------
    ValueError
        For a polygon with fewer than 3 vertices, a length mismatch, or malformed camera/size.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import viewing
    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.orthographic(-1, 1, -1, 1, 1, 5)
    >>> big = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]])
    >>> painter_image([big, 0.5 * big], [0, 1], V, P, 4, 4).ids     # the small one on top
    array([[0, 0, 0, 0],
           [0, 1, 1, 0],
           [0, 1, 1, 0],
           [0, 0, 0, 0]])
    """
    view, projection = _camera(view, projection)
    width, height = _pixels(width, "width"), _pixels(height, "height")
    labels = np.asarray(ids) if len(polygons) else np.zeros(0, dtype=np.intp)
    if labels.ndim != 1 or len(labels) != len(polygons) or not np.issubdtype(labels.dtype,
                                                                              np.integer):
        raise ValueError(f"ids must be one integer per polygon ({len(polygons)}), got "
                         f"shape {labels.shape}")
    tris, owner = [], []
    for k, poly in enumerate(polygons):
        p = as_points(poly, f"polygons[{k}]", dims=3)
        if p.ndim != 2 or len(p) < 3:
            raise ValueError(f"polygons[{k}] must have at least 3 vertices, got shape {p.shape}")
        for i in range(1, len(p) - 1):
            tris.append([p[0], p[i], p[i + 1]])
            owner.append(k)
    image = np.full((height, width), -1, dtype=labels.dtype if len(labels) else np.intp)
    if not tris:
        return Painted(image, 0)
    screen, src, _, _ = _screen_triangles(np.array(tris), projection @ view, width, height)
    owner = np.array(owner)[src]
    fragments = 0
    for tri, k in zip(screen, owner):           # src is sorted: the drawing order survives
        rows, cols, bary = _raster(tri, width, height)
        z = bary @ tri[:, 2]
        keep = (z >= 0.0) & (z <= 1.0)
        image[rows[keep], cols[keep]] = labels[k]
        fragments += int(keep.sum())
    return Painted(image, fragments)


def _centre_of_projection(pv):
    """The eye of a camera as a homogeneous point: (E, 1), or (direction to viewer, 0)."""
    _, _, vt = np.linalg.svd(pv[[0, 1, 3]])
    cop = vt[-1]
    if abs(cop[3]) > 1e-12 * np.abs(cop[:3]).max():
        return np.append(cop[:3] / cop[3], 1.0)
    inv = np.linalg.inv(pv)
    towards = transforms.apply(inv, [0, 0, -1]) - transforms.apply(inv, [0, 0, 0])
    return np.append(towards, 0.0)


def render_painter(vertices, faces, view, projection, width, height, order="bsp",
                   choose="first"):
    """Render a mesh with the painter's algorithm, ordered by a BSP tree or by depth sorting.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    view, projection : array_like, shape (4, 4)
    width, height : int
    order : {"bsp", "depth_sort"}, optional
        ``"bsp"``: :func:`build_bsp` then :func:`bsp_back_to_front` from the camera's centre of
        projection (correct); ``"depth_sort"``: :func:`depth_sort` (fails on cyclic overlap and
        interpenetration).
    choose : {"first", "fewest_splits"}, optional
        The BSP's choice of partition planes.

    Returns
    -------
    Painted
        ``ids`` index `faces`.

    Raises
    ------
    ValueError
        For malformed input or an unknown `order`.

    Examples
    --------
    >>> scene = painter_counterexample("interpenetrating")
    >>> args = scene.vertices, scene.faces, scene.view, scene.projection, 32, 32
    >>> zb = render_depth(*args)
    >>> bsp, naive = render_painter(*args), render_painter(*args, order="depth_sort")
    >>> int((bsp.ids != zb.ids).sum()) < 5, int((naive.ids != zb.ids).sum()) > 20
    (True, True)
    """
    v, f = _mesh(vertices, faces)
    view, projection = _camera(view, projection)
    tris = v[f]
    if order == "bsp":
        polys, ids = bsp_back_to_front(build_bsp(tris, choose=choose),
                                       _centre_of_projection(projection @ view))
    elif order == "depth_sort":
        ids = depth_sort(tris, view)
        polys = list(tris[ids])
    else:
        raise ValueError(f"order must be 'bsp' or 'depth_sort', got {order!r}")
    return painter_image(polys, ids, view, projection, width, height)


class Scene(NamedTuple):
    """A small test scene: a triangle mesh and a camera.

    Attributes
    ----------
    vertices : ndarray, shape (n, 3)
    faces : ndarray of int, shape (m, 3)
    view, projection : ndarray, shape (4, 4)

    Examples
    --------
    >>> s = random_scene(5, seed=1)
    >>> s.vertices.shape, s.faces.shape, s.view.shape
    ((15, 3), (5, 3), (4, 4))
    """
    vertices: np.ndarray
    faces: np.ndarray
    view: np.ndarray
    projection: np.ndarray


def _default_camera(eye=(0.0, 0.0, 5.0)):
    view = viewing.look_at(eye, -np.asarray(eye, float), [0, 1, 0])
    return view, viewing.perspective(np.radians(50), 1.0, 1.0, 20.0)


def painter_counterexample(kind="cyclic"):
    r"""Scenes where sorting by depth gives the wrong picture but a BSP tree does not.

    * ``"cyclic"``: three long, tilted planks arranged like a pinwheel; each lies on top of the
      next one where they cross, so plank 0 is over 1, 1 over 2 and 2 over 0. "In front of" is
      a cycle: whatever order a sort picks, one crossing comes out wrong. No triangles
      intersect.
    * ``"interpenetrating"``: two triangles that pierce each other; each is in front over part
      of the other, so drawing either one whole first is wrong.

    The BSP tree splits polygons along partition planes, which breaks the cycle (and cuts the
    interpenetrating pair along their intersection), so its order is correct.

    Parameters
    ----------
    kind : {"cyclic", "interpenetrating"}

    Returns
    -------
    Scene
        The camera looks at the origin from (0, 0, 5).

    Raises
    ------
    ValueError
        For an unknown kind.

    Examples
    --------
    >>> s = painter_counterexample("cyclic")
    >>> zb = render_depth(*s, 48, 48)
    >>> naive, bsp = render_painter(*s, 48, 48, order="depth_sort"), render_painter(*s, 48, 48)
    >>> int((naive.ids != zb.ids).sum()) > 50, int((bsp.ids != zb.ids).sum()) < 5
    (True, True)
    """
    if kind == "cyclic":
        corners = [np.array([np.cos(a), np.sin(a)]) for a in np.radians([90, 210, 330])]
        half_edge, length, width, tilt = np.sqrt(3) / 2, 1.5, 0.3, 0.25
        verts = []
        for k in range(3):
            a, b = corners[k], corners[(k + 1) % 3]
            along = (b - a) / np.linalg.norm(b - a)
            across = np.array([-along[1], along[0]])
            mid = (a + b) / 2
            for s, w in ((-length, -width), (length, -width), (length, width), (-length, width)):
                xy = mid + s * along + w * across
                verts.append([xy[0], xy[1], tilt * s / half_edge])
        verts = np.array(verts)
        faces = np.array([[4 * k, 4 * k + 1, 4 * k + 2] for k in range(3)]
                         + [[4 * k, 4 * k + 2, 4 * k + 3] for k in range(3)])
        faces = faces[[0, 3, 1, 4, 2, 5]]
    elif kind == "interpenetrating":
        verts = np.array([[-1.5, -1.2, 0.0], [1.5, -1.2, 0.0], [0.0, 1.2, 0.0],
                          [-1.0, -1.4, -0.9], [1.0, -1.4, -0.9], [0.0, 1.4, 0.9]])
        faces = np.array([[0, 1, 2], [3, 4, 5]])
    else:
        raise ValueError(f"kind must be 'cyclic' or 'interpenetrating', got {kind!r}")
    return Scene(verts, faces, *_default_camera())


def random_scene(n_triangles, seed=None, size=0.8):
    """Random triangles around the cube [-1, 1]^3 seen from (0, 0, 5): for cross-checking HSE.

    Triangles may intersect and overlap in any way.

    Parameters
    ----------
    n_triangles : int
    seed : int or numpy.random.Generator, optional
    size : float, optional
        Each vertex lies within `size` of its triangle's centre in every coordinate.

    Returns
    -------
    Scene

    Raises
    ------
    ValueError
        For a non-positive number of triangles.

    Examples
    --------
    >>> s = random_scene(50, seed=0)
    >>> zb = render_depth(*s, 32, 32)
    >>> rc = ray_cast_image(*s, 32, 32)
    >>> float((zb.ids == rc.ids).mean()) > 0.97
    True
    """
    n = _pixels(n_triangles, "n_triangles")
    size = as_scalar(size, "size")
    rng = np.random.default_rng(seed)
    centres = rng.uniform(-1, 1, (n, 1, 3))
    verts = (centres + rng.uniform(-size, size, (n, 3, 3))).reshape(-1, 3)
    return Scene(verts, np.arange(3 * n).reshape(n, 3), *_default_camera())


# ---------------------------------------------------------------------------------------------
# From-point occlusion culling
# ---------------------------------------------------------------------------------------------

def _occluder(value, k):
    name = k if isinstance(k, str) else f"occluders[{k}]"
    occ = as_array(value, name)
    if occ.ndim != 2 or occ.shape[1] != 3 or len(occ) < 2:
        raise ValueError(f"{name} must be a box (shape (2, 3): min and max corner) or a "
                         f"convex polygon (shape (k, 3), k >= 3), got shape {occ.shape}")
    if len(occ) == 2 and np.any(occ[0] >= occ[1]):
        raise ValueError(f"{name} is a box whose min corner is not below its max corner "
                         f"in every coordinate: {occ.tolist()}")
    if len(occ) >= 3:
        plane = _plane_of(occ)
        if plane is None:
            raise ValueError(f"{name} is a degenerate polygon (zero area)")
        n, c = plane
        scale = np.abs(occ - occ.mean(axis=0)).max()
        if np.abs(occ @ n - c).max() > 1e-9 * scale:
            raise ValueError(f"{name} is not planar")
        edges = np.roll(occ, -1, axis=0) - occ
        turns = np.cross(edges, np.roll(edges, -1, axis=0)) @ n
        if np.any(turns < -1e-12 * scale ** 2):
            raise ValueError(f"{name} is not convex: split it into convex polygons")
    return occ


_BOX_FACES = [  # (axis, side 0=min/1=max) -> corner indices (bit 0: x, bit 1: y, bit 2: z)
    (axis, side, [c for c in range(8) if (c >> axis) & 1 == side])
    for axis in range(3) for side in (0, 1)]


def _box_corners(lo, hi):
    """Corners of boxes (..., 3) -> (..., 8, 3), corner c has bit k set for max in axis k."""
    bits = (np.arange(8)[:, None] >> np.arange(3)) & 1
    return np.where(bits.astype(bool), hi[..., None, :], lo[..., None, :])


def _unit_planes(normals, offsets):
    normals = np.asarray(normals, float)
    length = np.linalg.norm(normals, axis=1)
    return normals / length[:, None], np.asarray(offsets, float) / length


def shadow_frustum(eye, occluder):
    r"""The region hidden by one convex occluder, as half-spaces :math:`n \cdot x \le c`.

    For a convex polygon: the pyramid with apex at the eye through the polygon's edges (one plane
    through the eye and each edge), cut off by the polygon's own plane: the part beyond the
    occluder. A point inside all these half-spaces is seen along a ray that crosses the polygon
    first. For an axis-aligned box: the planes through the eye and each *silhouette* edge (an
    edge between a face turned towards the eye and one turned away), and the plane of each face
    turned towards the eye (a point beyond all of those is behind the box's front surface).

    The region is convex, so a bounding volume lies in it as soon as its corners do: that is the
    whole culling test (:func:`occlusion_cull`).

    Parameters
    ----------
    eye : array_like, shape (3,)
    occluder : array_like, shape (k, 3) or (2, 3)
        A convex planar polygon (k >= 3 vertices in order) or a box (min corner, max corner).

    Returns
    -------
    (normals, offsets) : ndarray (q, 3), ndarray (q,), or None
        Unit normals and offsets; None when the occluder hides nothing from this eye (the eye
        in the polygon's plane, or inside the box).

    Raises
    ------
    ValueError
        For a malformed, non-planar or non-convex occluder.

    Examples
    --------
    A unit square at z = 0 seen from z = 2 hides a pyramid below it:

    >>> planes = shadow_frustum([0, 0, 2], [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]])
    >>> n, c = planes
    >>> len(n), bool(np.all(n @ [0, 0, -1] <= c)), bool(np.all(n @ [0, 0, 1] <= c))
    (5, True, False)
    """
    return _shadow_planes(as_vector(eye, "eye", 3), _occluder(occluder, "occluder"))


def _shadow_planes(e, occ):
    if len(occ) == 2:
        lo, hi = occ
        if np.all(e >= lo) and np.all(e <= hi):
            return None
        corners = _box_corners(lo, hi)
        centre = (lo + hi) / 2
        front = {}
        normals, offsets = [], []
        for axis, side, _ in _BOX_FACES:
            faces_eye = e[axis] > hi[axis] if side else e[axis] < lo[axis]
            front[axis, side] = faces_eye
            if faces_eye:                               # beyond the face: n . x <= n . p
                n = np.zeros(3)
                n[axis] = 1.0 if side else -1.0         # the face's outward normal
                normals.append(n)
                offsets.append(n[axis] * (hi[axis] if side else lo[axis]))
        for axis in range(3):                           # edges along `axis`
            b, c = [a for a in range(3) if a != axis]
            for sb in (0, 1):
                for sc in (0, 1):
                    if front[b, sb] == front[c, sc]:
                        continue
                    ends = [cn for cn in range(8)
                            if (cn >> b) & 1 == sb and (cn >> c) & 1 == sc]
                    p, q = corners[ends[0]], corners[ends[1]]
                    n = np.cross(p - e, q - e)
                    if n @ (centre - e) > 0:
                        n = -n
                    normals.append(n)
                    offsets.append(n @ e)
        return _unit_planes(normals, offsets)
    n, c = _plane_of(occ)
    side = n @ e - c
    scale = np.abs(occ - e).max()
    if abs(side) <= 1e-12 * scale:
        return None
    if side < 0:
        n, c = -n, -c
    normals, offsets = [n], [c]                          # beyond the polygon: n . x <= c
    centroid = occ.mean(axis=0)
    for i in range(len(occ)):
        m = np.cross(occ[i] - e, occ[(i + 1) % len(occ)] - e)
        if m @ (centroid - e) > 0:
            m = -m
        normals.append(m)
        offsets.append(m @ e)
    return _unit_planes(normals, offsets)


def _objects(objects):
    obj = as_array(objects, "objects")
    if obj.ndim == 3 and obj.shape[1:] == (2, 3):
        if np.any(obj[:, 0] > obj[:, 1]):
            raise ValueError("objects holds a box whose min corner exceeds its max corner")
        return obj, "boxes"
    if obj.ndim == 2 and obj.shape[1] == 4:
        if np.any(obj[:, 3] < 0):
            raise ValueError("objects holds a sphere with a negative radius")
        return obj, "spheres"
    raise ValueError(f"objects must be boxes, shape (n, 2, 3) (min and max corners), or "
                     f"spheres, shape (n, 4) (centre and radius), got shape {obj.shape}")


def occlusion_cull(eye, occluders, objects, return_index=False):
    r"""From-point occlusion culling: which objects are certainly hidden behind one occluder.

    An object is culled when its bounding volume lies entirely inside the
    :func:`shadow_frustum` of some occluder: all 8 corners of its box (or its whole sphere:
    :math:`n \cdot \text{centre} + r \le c` for every plane) on the hidden side of every plane.
    Because the shadow region is convex, that proves every point of the object hidden. The test
    is **conservative**: an object partly visible is never culled; an object hidden only by
    several occluders together (occluder fusion), or one piercing a polygon occluder, is not
    culled either, and is left to the z-buffer. A box occluder is solid: what lies inside it
    counts as hidden. Cost: :math:`O(n k)` plane tests for :math:`n` objects
    and :math:`k` occluders, per frame.

    Parameters
    ----------
    eye : array_like, shape (3,)
    occluders : sequence of array_like
        Convex polygons (k, 3) and/or boxes (2, 3), see :func:`shadow_frustum`.
    objects : array_like, shape (n, 2, 3) or (n, 4)
        Bounding boxes (min and max corner) or bounding spheres (centre x, y, z and radius).
    return_index : bool, optional
        Also return, per object, the occluder that hides it (-1 if visible).

    Returns
    -------
    culled : ndarray of bool, shape (n,)
    by : ndarray of int, shape (n,)
        Only with `return_index`.

    Raises
    ------
    ValueError
        For malformed occluders or objects.

    Examples
    --------
    A wall at z = 0 between the eye (z = 5) and three boxes: behind it, beside it, in front:

    >>> wall = [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]]
    >>> boxes = [[[-0.5, -0.5, -3], [0.5, 0.5, -2]], [[4, 4, -3], [5, 5, -2]],
    ...          [[-0.5, -0.5, 1], [0.5, 0.5, 2]]]
    >>> occlusion_cull([0, 0, 5], [wall], boxes).tolist()
    [True, False, False]
    """
    e = as_vector(eye, "eye", 3)
    occs = [_occluder(o, k) for k, o in enumerate(occluders)]
    obj, kind = _objects(objects)
    by = np.full(len(obj), -1, dtype=np.intp)
    scale = max(float(np.abs(obj).max()) if obj.size else 0.0, float(np.abs(e).max()), 1e-300)
    margin = 1e-12 * scale
    corners = _box_corners(obj[:, 0], obj[:, 1]) if kind == "boxes" else None
    for k, occ in enumerate(occs):
        planes = _shadow_planes(e, occ)
        if planes is None:
            continue
        n, c = planes
        if kind == "boxes":
            hidden = np.all(corners @ n.T - c <= -margin, axis=(1, 2))
        else:
            hidden = np.all(obj[:, :3] @ n.T - c + obj[:, 3:4] <= -margin, axis=1)
        by[hidden & (by < 0)] = k
    culled = by >= 0
    return (culled, by) if return_index else culled


def _solid_angle_triangles(a, b, c):
    """Solid angle of triangles (..., 3) seen from the origin (Van Oosterom and Strackee)."""
    la, lb, lc = (np.linalg.norm(x, axis=-1) for x in (a, b, c))
    numer = np.abs(np.einsum("...i,...i->...", a, np.cross(b, c)))
    denom = (la * lb * lc + np.einsum("...i,...i->...", a, b) * lc
             + np.einsum("...i,...i->...", a, c) * lb + np.einsum("...i,...i->...", b, c) * la)
    return 2 * np.arctan2(numer, denom)


def occluder_solid_angle(eye, occluders):
    r"""The solid angle each occluder covers as seen from the eye: how much it can hide.

    A good occluder covers a large part of the view: large and near. Its solid angle (the area of
    its projection onto the unit sphere around the eye, in steradians; :math:`4\pi` is
    everything) measures exactly that; for a small polygon at distance :math:`d` it is about
    :math:`A \cos\theta / d^2`. A convex polygon is cut into a fan of triangles, each measured
    with Van Oosterom and Strackee's formula

    .. math:: \tan\frac{\Omega}{2} = \frac{|a \cdot (b \times c)|}
              {|a||b||c| + (a \cdot b)|c| + (a \cdot c)|b| + (b \cdot c)|a|}

    (:math:`a, b, c` the vertices relative to the eye); a box sums its faces turned towards the
    eye.

    Parameters
    ----------
    eye : array_like, shape (3,)
    occluders : sequence of array_like
        Convex polygons (k, 3) and/or boxes (2, 3).

    Returns
    -------
    ndarray, shape (len(occluders),)
        Steradians (:math:`4\pi` for an eye inside a box).

    Raises
    ------
    ValueError
        For malformed occluders.

    Examples
    --------
    A face of a cube seen from the cube's centre covers a sixth of the sphere:

    >>> face = [[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]]
    >>> float(occluder_solid_angle([0, 0, 0], [face])[0] / (4 * np.pi)).__round__(12)
    0.166666666667
    """
    e = as_vector(eye, "eye", 3)
    out = []
    for k, o in enumerate(occluders):
        occ = _occluder(o, k)
        if len(occ) == 2:
            lo, hi = occ
            if np.all(e >= lo) and np.all(e <= hi):
                out.append(4 * np.pi)
                continue
            corners = _box_corners(lo, hi)
            total = 0.0
            for axis, side, idx in _BOX_FACES:
                if (e[axis] > hi[axis]) if side else (e[axis] < lo[axis]):
                    quad = corners[idx][[0, 1, 3, 2]] - e
                    total += float(_solid_angle_triangles(quad[0], quad[1:3], quad[2:4]).sum())
            out.append(total)
        else:
            rel = occ - e
            out.append(float(_solid_angle_triangles(rel[0], rel[1:-1], rel[2:]).sum()))
    return np.array(out)


def rank_occluders(eye, occluders, k=None):
    """The occluders ordered from best to worst by solid angle (:func:`occluder_solid_angle`).

    From-point culling tests every object against every chosen occluder, so a renderer keeps only
    the few best ones per frame.

    Parameters
    ----------
    eye : array_like, shape (3,)
    occluders : sequence of array_like
    k : int, optional
        Keep only the best `k`.

    Returns
    -------
    ndarray of int
        Occluder indices, largest solid angle first (ties: lower index first).

    Raises
    ------
    ValueError
        For malformed occluders or a non-positive `k`.

    Examples
    --------
    >>> small = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    >>> big_far = [[-3, -3, -5], [3, -3, -5], [3, 3, -5], [-3, 3, -5]]
    >>> rank_occluders([0, 0, 2], [small, big_far]).tolist()     # near beats big
    [0, 1]
    """
    omega = occluder_solid_angle(eye, occluders)
    order = np.argsort(-omega, kind="stable")
    if k is not None:
        order = order[:_pixels(k, "k")]
    return order


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
