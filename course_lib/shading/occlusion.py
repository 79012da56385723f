"""Chapter 12 (lesson section 7): ambient occlusion, sampled by rays and in closed form."""

from typing import NamedTuple

import numpy as np

from .. import visibility
from .._validate import (as_array, as_points, as_positive, as_rng, as_scalar, as_vector,
    as_whole, broadcast_stacks)
from ._common import _dot, _unit

__all__ = ["AmbientOcclusion", "HeightField", "ambient_occlusion",
    "ambient_occlusion_closed_form", "cosine_sample_hemisphere"]


# ---------------------------------------------------------------------------------------------
# Ambient occlusion
# ---------------------------------------------------------------------------------------------

def _tangent_frame(n):
    """Two unit tangents b1, b2 with (b1, b2, n) right-handed and orthonormal, for unit n.

    The branch-free construction of Duff et al. (2017), robust for every n including -z.
    """
    sign = np.where(n[..., 2] >= 0, 1.0, -1.0)
    a = -1.0 / (sign + n[..., 2])
    b = n[..., 0] * n[..., 1] * a
    b1 = np.stack([1 + sign * n[..., 0] ** 2 * a, sign * b, -sign * n[..., 0]], axis=-1)
    b2 = np.stack([b, sign + n[..., 1] ** 2 * a, -n[..., 1]], axis=-1)
    return b1, b2


def cosine_sample_hemisphere(normals, samples, seed=None):
    r"""Random unit directions above each normal, with density :math:`\cos\theta / \pi`.

    Malley's method: a point uniform in the unit disk, :math:`(r\cos\phi, r\sin\phi)` with
    :math:`r = \sqrt{\xi_1}`, :math:`\phi = 2\pi\xi_2`, lifted onto the hemisphere,
    :math:`z = \sqrt{1 - r^2}` (projecting a cosine-weighted hemisphere onto its base gives a
    uniform disk), then turned into the frame of the normal.

    Parameters
    ----------
    normals : array_like, shape (..., 3)
        Not zero (normalized here).
    samples : int
        Directions per normal, k >= 1.
    seed : int, numpy.random.Generator or None

    Returns
    -------
    ndarray, shape (..., k, 3)
        Unit vectors with positive dot product with their normal.

    Raises
    ------
    ValueError
        For zero normals or a sample count below 1.

    Examples
    --------
    The mean of cos(theta) under this density is 2/3:

    >>> d = cosine_sample_hemisphere([0, 0, 1], 200_000, seed=1)
    >>> d.shape, bool(abs(d[:, 2].mean() - 2 / 3) < 0.005), bool((d[:, 2] >= 0).all())
    ((200000, 3), True, True)
    """
    n = _unit(normals, "normals")
    k = as_whole(samples, "samples", 1)
    xi = as_rng(seed).random(n.shape[:-1] + (k, 2))
    r = np.sqrt(xi[..., 0])
    phi = 2 * np.pi * xi[..., 1]
    z = np.sqrt(np.maximum(0.0, 1.0 - xi[..., 0]))
    b1, b2 = _tangent_frame(n)
    return ((r * np.cos(phi))[..., None] * b1[..., None, :]
            + (r * np.sin(phi))[..., None] * b2[..., None, :] + z[..., None] * n[..., None, :])


class HeightField(NamedTuple):
    r"""A terrain :math:`z = h(x, y)`: heights on a regular grid, bilinear in between.

    ``heights[i, j]`` is the height at :math:`x = x_0 + j\,(x_1 - x_0)/(n_x - 1)`,
    :math:`y = y_0 + i\,(y_1 - y_0)/(n_y - 1)` (row 0 at :math:`y_0`, as an image shown with
    ``origin="lower"``). Outside the extent there is nothing (rays leave the terrain). Used as
    an occluder by :func:`ambient_occlusion`, which marches rays over it.

    Attributes
    ----------
    heights : ndarray, shape (ny, nx)
        At least 2 x 2.
    extent : tuple of float
        ``(x0, x1, y0, y1)``.

    Examples
    --------
    >>> field = HeightField(np.array([[0.0, 1.0], [2.0, 3.0]]), (0, 1, 0, 1))
    >>> field.height([0.5, 1.0], [0.5, 0.0]).tolist()
    [1.5, 1.0]
    >>> field.points().shape, field.normals()[0, 0].round(4).tolist()
    ((2, 2, 3), [-0.4082, -0.8165, 0.4082])
    """
    heights: np.ndarray
    extent: tuple

    def _grid(self):
        h = as_array(self.heights, "heights")
        if h.ndim != 2 or min(h.shape) < 2:
            raise ValueError(f"heights must be a 2D grid of at least 2 x 2, got shape {h.shape}")
        x0, x1, y0, y1 = as_vector(self.extent, "extent", 4)
        if not (x1 > x0 and y1 > y0):
            raise ValueError(f"extent must be (x0, x1, y0, y1) with x1 > x0 and y1 > y0, got "
                             f"{tuple(self.extent)}")
        return h, x0, x1, y0, y1

    def height(self, x, y):
        """Bilinearly interpolated height at (x, y); -inf outside the extent."""
        h, x0, x1, y0, y1 = self._grid()
        x, y = np.broadcast_arrays(as_array(x, "x"), as_array(y, "y"))
        ny, nx = h.shape
        gx = (x - x0) / (x1 - x0) * (nx - 1)
        gy = (y - y0) / (y1 - y0) * (ny - 1)
        inside = (gx >= 0) & (gx <= nx - 1) & (gy >= 0) & (gy <= ny - 1)
        j = np.clip(np.floor(gx).astype(np.intp), 0, nx - 2)
        i = np.clip(np.floor(gy).astype(np.intp), 0, ny - 2)
        fx, fy = np.clip(gx - j, 0, 1), np.clip(gy - i, 0, 1)
        z = ((1 - fy) * ((1 - fx) * h[i, j] + fx * h[i, j + 1])
             + fy * ((1 - fx) * h[i + 1, j] + fx * h[i + 1, j + 1]))
        return np.where(inside, z, -np.inf)

    def points(self):
        """The grid points, shape (ny, nx, 3)."""
        h, x0, x1, y0, y1 = self._grid()
        ny, nx = h.shape
        x, y = np.meshgrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, ny))
        return np.stack([x, y, h], axis=-1)

    def normals(self):
        r"""Unit normals at the grid points, :math:`(-h_x, -h_y, 1)` normalized (central
        differences inside, one-sided at the border)."""
        h, x0, x1, y0, y1 = self._grid()
        ny, nx = h.shape
        hy, hx = np.gradient(h, (y1 - y0) / (ny - 1), (x1 - x0) / (nx - 1))
        n = np.stack([-hx, -hy, np.ones_like(h)], axis=-1)
        return n / np.sqrt(_dot(n, n))[..., None]


def _march(field, o, d, t_max, step):
    """True where the ray o + t d (unit d) passes below the height field for some t <= t_max."""
    h, x0, x1, y0, y1 = field._grid()
    top = float(h.max())
    occluded = np.zeros(len(o), dtype=bool)
    # where each ray leaves the box [x0, x1] x [y0, y1] x [-inf, top]
    with np.errstate(divide="ignore", invalid="ignore"):
        exits = [np.where(d[:, 0] > 0, (x1 - o[:, 0]) / d[:, 0],
                          np.where(d[:, 0] < 0, (x0 - o[:, 0]) / d[:, 0], np.inf)),
                 np.where(d[:, 1] > 0, (y1 - o[:, 1]) / d[:, 1],
                          np.where(d[:, 1] < 0, (y0 - o[:, 1]) / d[:, 1], np.inf)),
                 np.where(d[:, 2] > 0, (top - o[:, 2]) / d[:, 2], np.inf)]
    end = np.minimum(np.minimum.reduce(exits), t_max)
    active = np.nonzero(end >= step)[0]
    t = step
    while len(active):
        p = o[active] + t * d[active]
        below = p[:, 2] < field.height(p[:, 0], p[:, 1])
        occluded[active[below]] = True
        active = active[~below & (end[active] >= t + step)]
        t += step
    return occluded


class AmbientOcclusion(NamedTuple):
    r"""The result of :func:`ambient_occlusion`.

    Attributes
    ----------
    visibility : ndarray, shape (...)
        The estimated cosine-weighted unoccluded fraction in [0, 1] (1 = open sky).
    std_error : ndarray, shape (...)
        Its estimated standard error :math:`\sqrt{\widehat{AO}(1 - \widehat{AO})/k}`.
    rays : int
        Rays cast (points x samples).
    triangle_tests : int
        Ray-triangle tests performed (the cost).

    Examples
    --------
    >>> ao = ambient_occlusion([[0, 0, 0]], [[0, 0, 1]], samples=16, seed=0)
    >>> ao.visibility.tolist(), ao.rays
    ([1.0], 16)
    """
    visibility: np.ndarray
    std_error: np.ndarray
    rays: int
    triangle_tests: int


def ambient_occlusion(points, normals, scene=None, samples=64, max_distance=np.inf, seed=None,
                      height_field=None, accelerate=True, offset=None, step=None):
    r"""Ambient occlusion by Monte Carlo hemisphere sampling: the open fraction above each point.

    For each point, `samples` directions are drawn with density :math:`\cos\theta/\pi`
    (:func:`cosine_sample_hemisphere`) and a ray cast in each; a ray is blocked when it hits the
    `scene` (or passes below the `height_field`) within `max_distance`. The estimate is the
    fraction of rays that are *not* blocked,

    .. math:: \widehat{AO} = \frac{1}{k}\sum_{i=1}^k v(P, \omega_i) \approx
              \frac{1}{\pi}\int_\Omega v(P, \omega)\cos\theta\, d\omega

    unbiased, with variance :math:`AO(1-AO)/k \le 1/(4k)` (standard error :math:`\le
    1/(2\sqrt k)`). A finite `max_distance` counts only nearby geometry (the usual choice:
    distant walls should not darken a point), which also makes rays cheaper.

    Cost: one ray per sample, :math:`k` per point; each ray costs :math:`P` triangle tests by
    brute force or about :math:`O(\log P)` with a bounding-volume hierarchy
    (:class:`course_lib.visibility.BVH`, the default `accelerate`). Height fields are marched
    in steps of `step` (half a grid cell by default): cost proportional to the ray's length in
    cells; thin features narrower than a step can be missed.

    Rays start at :math:`P + \epsilon N` (`offset` :math:`\epsilon`) so that the surface the
    point lies on does not block its own rays; :math:`\epsilon` is a bias (geometry closer
    than it is missed), keep it far below the scene's features.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    normals : array_like, shape (..., 3)
        The surface normals at the points (normalized here; not zero).
    scene : array_like, shape (m, 3, 3), or course_lib.visibility.BVH, optional
        Occluding triangles (both sides block). Pass a ready BVH to reuse it.
    samples : int
        Rays per point, :math:`k`.
    max_distance : float
        Only hits within this distance occlude (default: any distance).
    seed : int, numpy.random.Generator or None
    height_field : HeightField, optional
        A terrain that occludes as well.
    accelerate : bool
        Build a BVH over `scene` (ignored for a BVH; brute force otherwise).
    offset : float, optional
        How far above the surface (along the normal) the rays start; default
        :math:`10^{-6} (1 + \max \lVert P \rVert_\infty)`, a little above the rounding
        error of the points' coordinates.
    step : float, optional
        Marching step for the height field.

    Returns
    -------
    AmbientOcclusion
        ``visibility`` (shape of the points' leading axes), ``std_error``, ``rays``,
        ``triangle_tests``.

    Raises
    ------
    ValueError
        For zero normals, NaN input, a sample count below 1, a non-positive `max_distance`,
        or a malformed scene.

    Examples
    --------
    A point on the floor in the corner of two tall walls sees a quarter of the (cosine-weighted)
    sky: only directions with both dx > 0 and dy > 0 escape.

    >>> big = 1e3
    >>> walls = [[[-1, -big, 0], [-1, big, 0], [-1, 0, big]],      # the wall x = -1
    ...          [[-big, -1, 0], [big, -1, 0], [0, -1, big]]]      # the wall y = -1
    >>> ao = ambient_occlusion([0, 0, 0], [0, 0, 1], walls, samples=20_000, seed=3)
    >>> bool(abs(ao.visibility - 0.25) < 4 * ao.std_error)
    True
    """
    p = as_points(points, "points", dims=3)
    n = _unit(normals, "normals")
    lead = broadcast_stacks(points=(p, 1), normals=(n, 1))
    p = np.broadcast_to(p, lead + (3,)).reshape(-1, 3)
    n = np.broadcast_to(n, lead + (3,)).reshape(-1, 3)
    k = as_whole(samples, "samples", 1)
    t_max = np.inf if np.isscalar(max_distance) and np.isposinf(max_distance) \
        else as_scalar(max_distance, "max_distance")
    if t_max <= 0:
        raise ValueError(f"max_distance must be positive, got {t_max}")
    if height_field is not None and not isinstance(height_field, HeightField):
        raise TypeError(f"height_field must be a HeightField, got {type(height_field).__name__}")
    if len(p) == 0:
        empty = np.zeros(lead)
        return AmbientOcclusion(empty + 1.0, empty, 0, 0)
    dirs = cosine_sample_hemisphere(n, k, seed)                        # (P, k, 3)
    eps = 1e-6 * (1.0 + float(np.abs(p).max())) if offset is None else as_scalar(offset,
                                                                                  "offset")
    if eps < 0:
        raise ValueError(f"offset must be non-negative, got {eps}")
    if isinstance(scene, visibility.BVH):
        pass
    elif scene is not None:
        scene = as_array(scene, "scene")
        if scene.shape == (3, 3):
            scene = scene[None]
        if scene.ndim != 3 or scene.shape[1:] != (3, 3):
            raise ValueError(f"scene must be triangles of shape (m, 3, 3) or a BVH, got shape "
                             f"{scene.shape}")
        if len(scene) == 0:
            scene = None
        elif accelerate:
            scene = visibility.BVH(scene)
    origins = np.repeat(p + eps * n, k, axis=0)
    d = dirs.reshape(-1, 3)
    blocked = np.zeros(len(d), dtype=bool)
    tests = 0
    if scene is not None:
        hits = visibility.ray_cast(origins, d, scene, t_min=0.0, t_max=t_max)
        blocked |= hits.ids >= 0
        tests = hits.triangle_tests
    if height_field is not None:
        hmin = height_field._grid()
        cell = min((hmin[2] - hmin[1]) / (hmin[0].shape[1] - 1),
                   (hmin[4] - hmin[3]) / (hmin[0].shape[0] - 1))
        s = 0.5 * cell if step is None else as_positive(step, "step")
        rest = ~blocked
        if rest.any():
            blocked[rest] = _march(height_field, origins[rest], d[rest], t_max, s)
    vis = 1.0 - blocked.reshape(-1, k).mean(axis=1)
    err = np.sqrt(vis * (1 - vis) / k)
    return AmbientOcclusion(vis.reshape(lead), err.reshape(lead), len(d), tests)


def ambient_occlusion_closed_form(kind, distance=1.0, height=np.inf, max_distance=np.inf):
    r"""Exact cosine-weighted ambient occlusion of simple configurations (to check estimates).

    The key fact: under the density :math:`\cos\theta/\pi`, a direction's angle :math:`\beta`
    from the normal *projected onto a vertical plane* (:math:`\tan\beta = d_x / d_z`) has
    :math:`P(\beta \le b) = (1 + \sin b)/2` (for a uniform point in the disk, :math:`d_x` is
    uniform on each chord). So an infinitely long wall seen under the projected angles
    :math:`[\beta_1, \beta_2]` blocks :math:`(\sin\beta_2 - \sin\beta_1)/2` of the rays (the
    2D view factor). And :math:`\cos\theta` itself has density :math:`2\cos\theta`, so
    :math:`P(\cos\theta \ge c) = 1 - c^2`.

    * ``"plane"``: a point on an open plane: 1.
    * ``"wall"``: a point on the floor at `distance` :math:`a` from an infinitely long wall of
      `height` :math:`h`: the wall spans :math:`\beta \in [-\pi/2, -\arctan(a/h)]`, so
      :math:`AO = 1 - \tfrac12 (1 - a/\sqrt{a^2 + h^2}) = \tfrac12 (1 + a / \sqrt{a^2 + h^2})`
      (1/2 for an infinitely high wall).
    * ``"trench"``: the middle of the floor of an infinitely long trench of half-width
      :math:`a` (`distance`) and depth :math:`h`: two such walls,
      :math:`AO = a / \sqrt{a^2 + h^2}`.
    * ``"corner"``: a floor point in the corner of two perpendicular, infinitely high and long
      walls (the floor and two walls of a box): only :math:`d_x > 0, d_y > 0` escape, a quarter
      of the uniform disk: 1/4 (whatever the distances to the walls).
    * ``"ceiling"``: a point under an infinite parallel ceiling at `height` :math:`h`, counting
      hits within `max_distance` :math:`D`: a ray at angle :math:`\theta` hits at
      :math:`h/\cos\theta`, blocked when :math:`\cos\theta \ge h/D`:
      :math:`AO = (h/D)^2` for :math:`D > h`, else 1.

    Parameters
    ----------
    kind : {"plane", "wall", "trench", "corner", "ceiling"}
    distance : float
        :math:`a > 0` (wall, trench).
    height : float
        :math:`h > 0` (wall, trench, ceiling); may be inf for wall and trench.
    max_distance : float
        :math:`D` (ceiling).

    Returns
    -------
    float

    Raises
    ------
    ValueError
        For an unknown kind or non-positive sizes.

    Examples
    --------
    >>> ambient_occlusion_closed_form("wall", distance=1.0, height=np.sqrt(3))   # (1 + 1/2)/2
    0.75
    >>> ambient_occlusion_closed_form("trench", distance=1.0, height=np.inf)
    0.0
    >>> ambient_occlusion_closed_form("ceiling", height=1.0, max_distance=2.0)
    0.25
    """
    a = np.inf if np.isscalar(distance) and np.isposinf(distance) else as_scalar(distance,
                                                                                  "distance")
    h = np.inf if np.isscalar(height) and np.isposinf(height) else as_scalar(height, "height")
    big_d = (np.inf if np.isscalar(max_distance) and np.isposinf(max_distance)
             else as_scalar(max_distance, "max_distance"))
    if a <= 0 or h <= 0 or big_d <= 0:
        raise ValueError("distance, height and max_distance must be positive")
    if kind == "plane":
        return 1.0
    if kind == "corner":
        return 0.25
    if kind in ("wall", "trench"):
        ratio = 0.0 if np.isinf(h) else a / np.hypot(a, h)
        return float((1 + ratio) / 2 if kind == "wall" else ratio)
    if kind == "ceiling":
        if np.isinf(h):
            return 1.0
        return float((h / big_d) ** 2) if big_d > h else 1.0
    raise ValueError(f"kind must be 'plane', 'wall', 'trench', 'corner' or 'ceiling', got {kind!r}")
