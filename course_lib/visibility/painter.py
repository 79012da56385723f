"""Chapter 5, hidden-surface elimination (lesson section 5): the painter's algorithm, depth sort,
BSP trees.
"""

from typing import NamedTuple

import numpy as np

from .. import transforms, viewing
from .._validate import (as_choice, as_matrix, as_mesh, as_points, as_rng, as_scalar, as_vector,
    as_whole)
from .._raycore import as_triangles as _triangles
from ._common import _camera
from .z_buffer import _ordered_pair, _raster, _screen_triangles

__all__ = ["BSPNode", "BSPTree", "Painted", "TriangleScene", "build_bsp", "bsp_back_to_front",
    "depth_sort", "painter_counterexample", "painter_image", "random_scene", "render_painter",
    "split_polygon"]


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
    as_choice(choose, "choose", ("first", "fewest_splits"))
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
    as_choice(key, "key", ("farthest", "centroid"))
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
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
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
    >>> from course_lib.visibility import render_depth
    >>> scene = painter_counterexample("interpenetrating")
    >>> args = scene.vertices, scene.faces, scene.view, scene.projection, 32, 32
    >>> zb = render_depth(*args)
    >>> bsp, naive = render_painter(*args), render_painter(*args, order="depth_sort")
    >>> int((bsp.ids != zb.ids).sum()) < 5, int((naive.ids != zb.ids).sum()) > 20
    (True, True)
    """
    v, f = as_mesh(vertices, faces)
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


class TriangleScene(NamedTuple):
    """A small test scene for hidden-surface elimination: triangles and a camera.

    What :func:`render_depth`, :func:`ray_cast_image` and :func:`render_painter` take, unpacked
    (``render_depth(*scene, width, height)``). Not the ray tracer's scene of objects, materials
    and lights (:class:`course_lib.raytracing.Scene`). ``visibility.Scene`` is this class under
    its old name.

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


Scene = TriangleScene       # the old name (not in __all__): the same class


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
    TriangleScene
        The camera looks at the origin from (0, 0, 5).

    Raises
    ------
    ValueError
        For an unknown kind.

    Examples
    --------
    >>> from course_lib.visibility import render_depth
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
    return TriangleScene(verts, faces, *_default_camera())


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
    TriangleScene

    Raises
    ------
    ValueError
        For a non-positive number of triangles.

    Examples
    --------
    >>> from course_lib.visibility import ray_cast_image, render_depth
    >>> s = random_scene(50, seed=0)
    >>> zb = render_depth(*s, 32, 32)
    >>> rc = ray_cast_image(*s, 32, 32)
    >>> float((zb.ids == rc.ids).mean()) > 0.97
    True
    """
    n = as_whole(n_triangles, "n_triangles", 1)
    size = as_scalar(size, "size")
    rng = as_rng(seed)
    centres = rng.uniform(-1, 1, (n, 1, 3))
    verts = (centres + rng.uniform(-size, size, (n, 3, 3))).reshape(-1, 3)
    return TriangleScene(verts, np.arange(3 * n).reshape(n, 3), *_default_camera())
