"""Chapter 5, hidden-surface elimination (lesson section 5): ray casting, brute force and with a
BVH.

The rays, Möller-Trumbore, brute force and the :class:`BVH` itself live in
:mod:`course_lib._raycore`, shared with chapter 15's ray tracer; this file is chapter 5's view
of them: :func:`ray_triangle`, :func:`ray_cast` (which counts the tests) and ray casting a whole
image.
"""

from typing import NamedTuple

import numpy as np

from .. import transforms
from .._raycore import (BVH, Hits, as_rays, as_t_max, as_t_min, as_triangles, brute_force,
                        moller_trumbore, triangle_soa)
from .._validate import as_mesh, as_whole
from ._common import _camera

__all__ = ["BVH", "Hits", "RayCastImage", "ray_cast", "ray_cast_image", "ray_triangle"]


# ---------------------------------------------------------------------------------------------
# Ray casting
# ---------------------------------------------------------------------------------------------

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
    o, d, _ = as_rays(origins, directions, flat=True)
    tri = as_triangles(triangle, "triangle")
    if len(tri) != 1:
        raise ValueError(f"triangle must be a single triangle of shape (3, 3), got {tri.shape}")
    return moller_trumbore(o.T, d.T, triangle_soa(tri)[:, 0])


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
    o, d, _ = as_rays(origins, directions, flat=True)
    t_min = as_t_min(t_min, nonnegative=False)
    t_max = as_t_max(t_max, t_min)
    if isinstance(triangles, BVH):
        return triangles._cast(o, d, t_min, t_max)
    if accelerate:
        return BVH(triangles)._cast(o, d, t_min, t_max)
    tris = as_triangles(triangles)
    t, ids, _, _, tests, _ = brute_force(o, d, triangle_soa(tris), t_min, np.full(len(o), t_max))
    return Hits(t, ids, tests, 0)


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
    >>> from course_lib.visibility import render_depth
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
    v, f = as_mesh(vertices, faces)
    view, projection = _camera(view, projection)
    width, height = as_whole(width, "width", 1), as_whole(height, "height", 1)
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
