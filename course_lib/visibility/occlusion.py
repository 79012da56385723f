"""Chapter 5, occlusion culling from a point (lesson section 4.1): occluders and their shadows."""

import numpy as np

from .._validate import as_array, as_vector, as_whole
from .painter import _plane_of

__all__ = ["occluder_solid_angle", "occlusion_cull", "rank_occluders", "shadow_frustum"]


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
        order = order[:as_whole(k, "k", 1)]
    return order
