r"""Chapter 12 (lesson section 7.1): ambient occlusion in screen space (SSAO).

Ray-traced ambient occlusion (:func:`course_lib.shading.ambient_occlusion`) casts rays into the
scene. Screen-space ambient occlusion replaces the scene by what the z-buffer already holds
after drawing a frame: per pixel the visible surface's position and normal (the *G-buffer*,
:func:`g_buffer`). For each pixel :math:`P` with normal :math:`N`, a kernel of :math:`k`
points :math:`Q_i = P + R\, s_i\, \omega_i` in the hemisphere of radius :math:`R` above
:math:`P` is projected to the screen; a sample counts as occluded when the surface stored at
its pixel is in front of it by more than a `bias`. The visibility is one minus the occluded
fraction (:func:`ssao`).

**What it estimates.** The kernel directions :math:`\omega_i` are cosine-weighted (density
:math:`\cos\theta/\pi`), as the ray tracer's. If the ray from :math:`P` along :math:`\omega`
first meets a solid object at distance :math:`t(\omega)`, the point at distance :math:`sR`
along it lies inside that object exactly when :math:`t(\omega) < sR`; SSAO sees "inside" as
"behind the stored surface". So, as long as every occluder is solid and visible to the camera,

* ``falloff="linear"`` (lengths :math:`s` uniform in (0, 1]) estimates
  :math:`1 - \frac{1}{\pi}\int_\Omega (1 - t(\omega)/R)_+ \cos\theta\, d\omega`: the
  ray-traced AO with each occluder weighted by :math:`1 - t/R` (near occluders count fully,
  those at the radius not at all);
* ``falloff="none"`` (all :math:`s = 1`) estimates the ray-traced AO with a hard distance limit
  :math:`R`, ``ambient_occlusion(..., max_distance=R)``.

:class:`RayTracedOcclusion` computes both ray-traced counterparts for the same view. Where
the assumption fails, the artefacts of SSAO appear: the space behind every visible surface is
taken as solid (a floor behind a floating object is darkened by it, *haloing*, unless the
*range check* ignores stored surfaces further than :math:`R` in depth from :math:`P`), geometry
off-screen or hidden behind the front surface is missed, and the stored depth is sampled at
pixel centres (without a bias a flat tilted surface occludes itself).
"""

from typing import NamedTuple

import numpy as np

from .. import viewing, visibility
from .._validate import as_array, as_choice, as_matrix, as_positive, as_rng, as_scalar, as_whole
from ._common import _dot
from .interpolated import barycentric_buffers, face_normals
from .occlusion import _tangent_frame, cosine_sample_hemisphere

__all__ = ["GBuffer", "RayTracedOcclusion", "SSAOScene", "box_blur", "g_buffer",
           "positions_from_depth", "ray_traced_occlusion", "ssao", "ssao_kernel",
           "ssao_test_scene"]


class GBuffer(NamedTuple):
    """The result of :func:`g_buffer`: per-pixel buffers of shape (height, width), row 0 at the
    bottom (as the z-buffer's).

    Attributes
    ----------
    positions : ndarray, shape (height, width, 3)
        View-space (eye) coordinates of the visible surface point at the pixel centre (the
        camera looks along -z, so the depth is ``-positions[..., 2]``); 0 where not covered.
    normals : ndarray, shape (height, width, 3)
        View-space unit normals, turned towards the camera; 0 where not covered.
    mask : ndarray of bool, shape (height, width)
        The covered pixels.
    depth : ndarray, shape (height, width)
        The z-buffer's viewport depth in [0, 1], inf where not covered.
    world_positions, world_normals : ndarray, shape (height, width, 3)
        The same point and normal in world coordinates (for the ray-traced comparison).
    ids : ndarray of int, shape (height, width)
        The visible face, -1 where not covered.

    Examples
    --------
    >>> scene = ssao_test_scene()
    >>> gb = g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 16, 16)
    >>> gb.positions.shape, bool(gb.mask.any()), bool((gb.positions[gb.mask, 2] < 0).all())
    ((16, 16, 3), True, True)
    """
    positions: np.ndarray
    normals: np.ndarray
    mask: np.ndarray
    depth: np.ndarray
    world_positions: np.ndarray
    world_normals: np.ndarray
    ids: np.ndarray


def g_buffer(vertices, faces, view, projection, width, height):
    r"""Rasterize a mesh once into a G-buffer: view-space position and normal per pixel.

    Built on :func:`course_lib.shading.barycentric_buffers` (the chapter-5 z-buffer): the
    perspective-correct barycentric weights of each pixel centre in its visible triangle
    interpolate the triangle's corners to the world point :math:`P`, which `view` takes to eye
    space. The normal is the visible face's normal (flat), turned towards the eye, and taken to
    eye space by the inverse transpose of `view`'s 3 x 3 part.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    view, projection : array_like, shape (4, 4)
        E.g. :func:`course_lib.viewing.look_at` and :func:`course_lib.viewing.perspective`.
    width, height : int

    Returns
    -------
    GBuffer

    Raises
    ------
    ValueError
        For malformed input.

    Examples
    --------
    A square facing the camera at distance 3: every covered pixel is at depth 3 with normal +z.

    >>> V = viewing.look_at([0, 0, 3], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> square = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    >>> gb = g_buffer(square, [[0, 1, 2], [0, 2, 3]], V, P, 8, 8)
    >>> np.allclose(gb.positions[gb.mask, 2], -3), gb.normals[4, 4].tolist()
    (True, [0.0, 0.0, 1.0])
    """
    buffers = barycentric_buffers(vertices, faces, view, projection, width, height)
    v = np.asarray(vertices, dtype=float)
    f = np.asarray(faces, dtype=np.intp)
    view = as_matrix(view, "view", (4,))
    mask = buffers.drawn
    world = np.zeros(mask.shape + (3,))
    world[mask] = np.einsum("pk,pkc->pc", buffers.drawn_weights, v[buffers.drawn_vertices])
    fn = face_normals(v, f)
    nw = np.zeros(mask.shape + (3,))
    nw[mask] = fn[buffers.ids[mask]]
    eye = np.linalg.inv(view)[:3, 3]
    flip = _dot(nw, eye - world) < 0
    nw[flip] *= -1
    pos = np.zeros_like(world)
    pos[mask] = world[mask] @ view[:3, :3].T + view[:3, 3]
    nv = np.zeros_like(nw)
    nv[mask] = nw[mask] @ np.linalg.inv(view[:3, :3])          # rows: (M^-T n)^T = n^T M^-1
    nv[mask] /= np.sqrt(_dot(nv[mask], nv[mask]))[:, None]
    return GBuffer(pos, nv, mask, buffers.depth, world, nw, buffers.ids)


def positions_from_depth(depth, projection):
    r"""View-space points of a depth buffer: what a real SSAO pass reads instead of positions.

    A GPU keeps only the z-buffer's depth :math:`d \in [0, 1]` per pixel (chapter 5). The point
    behind pixel :math:`(i, j)` of a :math:`w \times h` image is recovered by undoing the
    viewport and the projection: its normalised device coordinates are
    :math:`x = 2(j + \tfrac12)/w - 1`, :math:`y = 2(i + \tfrac12)/h - 1`, :math:`z = 2d - 1`,
    and :math:`(x_e, y_e, z_e, w_e)^T = P^{-1} (x, y, z, 1)^T`, divided by :math:`w_e`.

    Parameters
    ----------
    depth : array_like, shape (h, w)
        Viewport depth in [0, 1], ``inf`` where nothing is drawn (the z-buffer's background).
    projection : array_like, shape (4, 4)
        The camera's projection (eye -> clip coordinates), invertible.

    Returns
    -------
    positions : ndarray, shape (h, w, 3)
        View-space points (0 where nothing is drawn).
    mask : ndarray of bool, shape (h, w)
        The pixels where something is drawn.

    Raises
    ------
    ValueError
        For NaN in `depth` (mark empty pixels with inf), depths outside [0, 1], a malformed
        or singular projection.

    Examples
    --------
    A square facing the camera 3 units away: every covered pixel comes back at z = -3.

    >>> P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    >>> square = [[-1, -1, -3], [1, -1, -3], [1, 1, -3], [-1, 1, -3]]
    >>> gb = g_buffer(square, [[0, 1, 2], [0, 2, 3]], np.eye(4), P, 8, 8)
    >>> pos, mask = positions_from_depth(gb.depth, P)
    >>> bool(np.array_equal(mask, gb.mask)), bool(np.allclose(pos[mask, 2], -3))
    (True, True)
    """
    d = np.asarray(depth, dtype=float)
    if d.ndim != 2 or min(d.shape) < 1:
        raise ValueError(f"depth must be a 2D buffer (height, width), got shape {d.shape}")
    if np.isnan(d).any():
        i, j = np.argwhere(np.isnan(d))[0]
        raise ValueError(f"depth must not contain NaN (at row {i}, column {j}): mark pixels "
                         "where nothing is drawn with inf, as the z-buffer does")
    mask = np.isfinite(d)
    if np.any(d[mask] < -1e-12) or np.any(d[mask] > 1 + 1e-12) or np.isneginf(d).any():
        raise ValueError("depth must lie in [0, 1] (viewport depth; inf where nothing is drawn)")
    proj = as_matrix(projection, "projection", (4,))
    if abs(np.linalg.det(proj)) < 1e-300:
        raise ValueError("projection must be invertible to recover points from depths")
    h, w = d.shape
    x = 2 * (np.arange(w) + 0.5) / w - 1
    y = 2 * (np.arange(h) + 0.5) / h - 1
    xx, yy = np.meshgrid(x, y)
    ndc = np.stack([xx, yy, 2 * np.where(mask, d, 0.5) - 1, np.ones_like(xx)], axis=-1)
    eye = ndc @ np.linalg.inv(proj).T
    pos = eye[..., :3] / eye[..., 3:]
    pos[~mask] = 0.0
    return pos, mask


def ssao_kernel(samples, falloff="linear", seed=None):
    r"""The SSAO kernel: `samples` points in the unit hemisphere above +z (tangent space).

    Directions are cosine-weighted (Malley's method, as
    :func:`course_lib.shading.cosine_sample_hemisphere`); lengths are stratified uniform in
    (0, 1] for ``falloff="linear"``, all 1 for ``"none"`` (see the module docstring for what
    each estimates).

    Parameters
    ----------
    samples : int
        At least 1.
    falloff : {"linear", "none"}
    seed : int, numpy.random.Generator or None

    Returns
    -------
    ndarray, shape (samples, 3)

    Examples
    --------
    >>> kernel = ssao_kernel(8, seed=0)
    >>> kernel.shape, bool((kernel[:, 2] > 0).all()), bool((np.linalg.norm(kernel, axis=1) <= 1).all())
    ((8, 3), True, True)
    """
    k = as_whole(samples, "samples", 1)
    falloff = as_choice(falloff, "falloff", ("linear", "none"))
    rng = as_rng(seed)
    dirs = cosine_sample_hemisphere([0.0, 0.0, 1.0], k, rng)
    if falloff == "none":
        return dirs
    lengths = (rng.permutation(k) + 1.0 - rng.random(k)) / k      # stratified, in (0, 1]
    return dirs * lengths[:, None]


def box_blur(image, mask, size=4):
    r"""Average `image` over a `size` x `size` window, over the covered pixels of `mask` only.

    The window of pixel (i, j) is rows and columns ``i - size // 2`` to
    ``i - size // 2 + size - 1`` (for the SSAO noise tile of 4: -2..1); uncovered pixels neither
    contribute nor change (they keep their value). A constant image stays constant.

    Parameters
    ----------
    image : array_like, shape (h, w)
    mask : array_like of bool, shape (h, w)
    size : int
        At least 1 (1: no blur).

    Returns
    -------
    ndarray, shape (h, w)

    Examples
    --------
    >>> float(box_blur(np.array([[0.0, 1.0], [1.0, 0.0]]), np.ones((2, 2), bool), 2)[1, 1])
    0.5
    """
    img = as_array(image, "image")
    m = np.asarray(mask, dtype=bool)
    if img.ndim != 2 or m.shape != img.shape:
        raise ValueError(f"image must be 2D and mask of its shape, got {img.shape} and {m.shape}")
    s = as_whole(size, "size", 1)
    lo = s // 2
    hi = s - 1 - lo
    h, w = img.shape
    num = np.pad(np.where(m, img, 0.0), ((lo, hi), (lo, hi)))
    den = np.pad(m.astype(float), ((lo, hi), (lo, hi)))
    total = np.zeros((h, w))
    count = np.zeros((h, w))
    for di in range(s):
        for dj in range(s):
            total += num[di:di + h, dj:dj + w]
            count += den[di:di + h, dj:dj + w]
    return np.where(m & (count > 0), total / np.maximum(count, 1), img)


def _check_buffers(positions, normals, mask):
    pos = as_array(positions, "positions")
    if pos.ndim != 3 or pos.shape[2] != 3:
        raise ValueError(f"positions must be an image of view-space points, shape (h, w, 3), "
                         f"got {pos.shape}")
    nrm = as_array(normals, "normals")
    if nrm.shape != pos.shape:
        raise ValueError(f"normals must have the shape of positions {pos.shape}, got {nrm.shape}")
    m = np.ones(pos.shape[:2], dtype=bool) if mask is None else np.asarray(mask)
    if m.shape != pos.shape[:2] or m.dtype != bool:
        raise ValueError(f"mask must be booleans of shape {pos.shape[:2]}, got {m.dtype} "
                         f"{m.shape}")
    length = np.sqrt(_dot(nrm, nrm))
    if np.any(m & (length == 0)):
        i, j = np.argwhere(m & (length == 0))[0]
        raise ValueError(f"normals must not be zero at covered pixels (at pixel ({i}, {j})): a "
                         "zero vector has no direction")
    if np.any(m & (pos[..., 2] >= 0)):
        raise ValueError("positions must be in front of the camera (view-space z < 0) at "
                         "covered pixels")
    return pos, np.where(m[..., None], nrm / np.where(length == 0, 1, length)[..., None], 0), m


def ssao(positions, normals, projection, mask=None, radius=0.5, samples=16, bias=0.025,
         range_check=True, blur=4, falloff="linear", noise_size=4, seed=None, kernel=None):
    r"""Screen-space ambient occlusion of a G-buffer: visibility in [0, 1] per pixel.

    For each covered pixel with view-space point :math:`P` and normal :math:`N`:

    1. the kernel (:func:`ssao_kernel`, tangent space) is turned into the frame
       :math:`(T, B, N)`, rotated about :math:`N` by the angle of the pixel in a tiled
       `noise_size` x `noise_size` pattern of random angles (so that neighbouring pixels use
       different samples; the blur then averages a tile), and scaled by `radius`:
       :math:`Q_i = P + R\,(k_x T + k_y B + k_z N)`;
    2. each :math:`Q_i` is projected by `projection` to its pixel (the one whose square contains
       it); off-screen samples, and samples landing on uncovered pixels, are not occluded;
    3. the stored point :math:`S` there occludes when it is in front of :math:`Q_i` by more
       than `bias`: :math:`z_S > z_{Q_i} + \text{bias}` (view-space z, the camera looks along
       -z);
    4. range check: an occluder whose depth differs from :math:`P`'s by more than `radius`
       (:math:`|z_S - z_P| > R`) is ignored;
    5. visibility :math:`= 1 - \text{occluded}/k`, then :func:`box_blur` of size `blur` over
       covered pixels.

    Cost: :math:`k` projections and depth look-ups per pixel, whatever the scene's size.

    The depth is looked up at pixel centres, so a sample just above a surface tilted to the
    view can land on a pixel whose stored point is nearer than the sample: the `bias` must
    exceed the change of depth across about half a pixel there, or flat surfaces darken
    themselves.

    Parameters
    ----------
    positions : array_like, shape (h, w, 3)
        View-space points (:attr:`GBuffer.positions`), finite everywhere (use `mask` for the
        background, not NaN).
    normals : array_like, shape (h, w, 3)
        View-space normals, not zero at covered pixels.
    projection : array_like, shape (4, 4)
        The camera's projection (eye -> clip coordinates).
    mask : array_like of bool, shape (h, w), optional
        Covered pixels (default all).
    radius : float
        :math:`R > 0`, view-space units.
    samples : int
        :math:`k \ge 1` (ignored if `kernel` is given).
    bias : float
        At least 0.
    range_check : bool
    blur : int
        Box-blur size (1: none).
    falloff : {"linear", "none"}
        Kernel lengths (see :func:`ssao_kernel`).
    noise_size : int
        Side of the tile of rotation angles (1: no rotation).
    seed : int, numpy.random.Generator or None
    kernel : array_like, shape (k, 3), optional
        A given kernel (tangent space, z along the normal, inside the unit hemisphere).

    Returns
    -------
    ndarray, shape (h, w)
        1 where uncovered.

    Raises
    ------
    ValueError
        For NaN positions, zero normals, mismatched shapes, non-positive radius or samples,
        negative bias.

    Examples
    --------
    A flat floor seen at an angle is open: SSAO is exactly 1 with a small bias.

    >>> V = viewing.look_at([0, 2, 3], [0, -2, -3], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(50), 1.0, 0.5, 20.0)
    >>> floor = [[-9, 0, -9], [9, 0, -9], [9, 0, 9], [-9, 0, 9]]
    >>> gb = g_buffer(floor, [[0, 1, 2], [0, 2, 3]], V, P, 32, 32)
    >>> float(ssao(gb.positions, gb.normals, P, gb.mask, radius=0.5, seed=0).min())
    1.0
    """
    pos, nrm, m = _check_buffers(positions, normals, mask)
    proj = as_matrix(projection, "projection", (4,))
    r = as_positive(radius, "radius", "the kernel's radius")
    b = as_scalar(bias, "bias")
    if b < 0:
        raise ValueError(f"bias must be non-negative, got {b}")
    rng = as_rng(seed)
    if kernel is None:
        ker = ssao_kernel(samples, falloff, rng)
    else:
        ker = as_array(kernel, "kernel")
        if ker.ndim != 2 or ker.shape[1] != 3 or len(ker) == 0:
            raise ValueError(f"kernel must be points of shape (k, 3), got {ker.shape}")
    ns = as_whole(noise_size, "noise_size", 1)
    blur = as_whole(blur, "blur", 1)
    h, w = m.shape
    vis = np.ones((h, w))
    idx = np.nonzero(m)
    if len(idx[0]) == 0:
        return vis
    p, n = pos[idx], nrm[idx]
    t, bt = _tangent_frame(n)
    angles = 2 * np.pi * rng.random((ns, ns)) if ns > 1 else np.zeros((1, 1))
    a = angles[idx[0] % ns, idx[1] % ns][:, None]
    t, bt = np.cos(a) * t + np.sin(a) * bt, -np.sin(a) * t + np.cos(a) * bt
    # clip x, y, w and view z are linear in Q = P + R (kx T + ky B + kz N): project P, T, B
    # and N once, then each sample is three multiply-adds
    lin = np.array([proj[0, :3], proj[1, :3], proj[3, :3], [0.0, 0.0, 1.0]])
    shift = np.array([proj[0, 3], proj[1, 3], proj[3, 3], 0.0])
    base = p @ lin.T + shift
    pt, pb, pn = t @ lin.T, bt @ lin.T, n @ lin.T
    z_stored = pos[..., 2].ravel()
    covered = m.ravel()
    occluded = np.zeros(len(p))
    for kx, ky, kz in ker:
        cx, cy, cw, qz = (base + (r * kx) * pt + (r * ky) * pb + (r * kz) * pn).T
        with np.errstate(divide="ignore", invalid="ignore"):
            col = np.floor((cx / cw + 1) * (w / 2))
            row = np.floor((cy / cw + 1) * (h / 2))
        inside = (cw > 0) & (col >= 0) & (col < w) & (row >= 0) & (row < h)
        flat = np.where(inside, row * w + col, 0).astype(np.intp)
        sz = z_stored[flat]
        hit = inside & covered[flat] & (sz > qz + b)
        if range_check:
            hit &= np.abs(sz - p[:, 2]) <= r
        occluded += hit
    vis[idx] = 1.0 - occluded / len(ker)
    return box_blur(vis, m, blur) if blur > 1 else vis


class RayTracedOcclusion(NamedTuple):
    r"""The result of :func:`ray_traced_occlusion`: each pixel's rays cast once, unlimited.

    A ray blocked within :math:`R` is one whose hit distance is below :math:`R`, so the AO for
    any radius comes from the stored distances without casting again (:meth:`visibility`).

    Attributes
    ----------
    distances : ndarray, shape (h, w, k)
        Hit distance of each ray (inf if it escapes; inf at uncovered pixels).
    mask : ndarray of bool, shape (h, w)
    rays : int

    Examples
    --------
    >>> ao = RayTracedOcclusion(np.array([[[0.2, 1.0, np.inf, 0.6]]]), np.ones((1, 1), bool), 4)
    >>> float(ao.visibility(0.5, "none")[0, 0]), float(ao.visibility(1.0, "linear")[0, 0])
    (0.75, 0.7)
    """
    distances: np.ndarray
    mask: np.ndarray
    rays: int

    def visibility(self, radius, falloff="linear"):
        r"""AO with distance limit `radius`: ``"none"``: the fraction of rays with
        :math:`t \ge R`; ``"linear"``: :math:`1 - \operatorname{mean}(1 - t/R)_+` (the
        quantity :func:`ssao` with the same falloff estimates)."""
        r = as_positive(radius, "radius")
        falloff = as_choice(falloff, "falloff", ("linear", "none"))
        t = self.distances
        weight = (t < r).astype(float) if falloff == "none" else np.clip(1 - t / r, 0, 1)
        vis = 1.0 - weight.mean(axis=-1)
        return np.where(self.mask, vis, 1.0)


def ray_traced_occlusion(gbuffer, triangles, samples=16, seed=None):
    r"""Cosine-weighted rays from every covered pixel's surface point, cast once with no limit.

    The rays start at the G-buffer's world point, a little above the surface along the normal
    (as :func:`course_lib.shading.ambient_occlusion`), and are intersected with `triangles`
    through a BVH (:func:`course_lib.visibility.ray_cast`). Keeping each ray's hit distance
    gives the ray-traced AO of the same view for every radius
    (:meth:`RayTracedOcclusion.visibility`); with ``falloff="none"`` it equals
    ``ambient_occlusion(points, normals, triangles, samples, max_distance=R)``.

    Parameters
    ----------
    gbuffer : GBuffer
    triangles : array_like, shape (m, 3, 3), or course_lib.visibility.BVH
        The scene in world coordinates.
    samples : int
        Rays per pixel, at least 1.
    seed : int, numpy.random.Generator or None

    Returns
    -------
    RayTracedOcclusion

    Examples
    --------
    >>> scene = ssao_test_scene()
    >>> gb = g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 8, 8)
    >>> rt = ray_traced_occlusion(gb, scene.vertices[scene.faces], samples=4, seed=0)
    >>> rt.distances.shape, bool((rt.visibility(0.5) <= 1).all())
    ((8, 8, 4), True)
    """
    if not isinstance(gbuffer, GBuffer):
        raise TypeError(f"gbuffer must be a GBuffer (from g_buffer), got "
                        f"{type(gbuffer).__name__}")
    k = as_whole(samples, "samples", 1)
    scene = triangles if isinstance(triangles, visibility.BVH) else \
        visibility.BVH(as_array(triangles, "triangles").reshape(-1, 3, 3))
    m = gbuffer.mask
    dist = np.full(m.shape + (k,), np.inf)
    p, n = gbuffer.world_positions[m], gbuffer.world_normals[m]
    if len(p):
        dirs = cosine_sample_hemisphere(n, k, seed).reshape(-1, 3)
        eps = 1e-6 * (1.0 + float(np.abs(p).max()))
        origins = np.repeat(p + eps * n, k, axis=0)
        hits = visibility.ray_cast(origins, dirs, scene, t_min=0.0)
        t = np.where(hits.ids >= 0, hits.t, np.inf)
        dist[m] = t.reshape(-1, k)
    return RayTracedOcclusion(dist, m, int(m.sum()) * k)


class SSAOScene(NamedTuple):
    """The result of :func:`ssao_test_scene`: a mesh and a camera.

    Attributes
    ----------
    vertices : ndarray, shape (n, 3)
    faces : ndarray of int, shape (m, 3)
    view, projection : ndarray, shape (4, 4)

    Examples
    --------
    >>> ssao_test_scene().faces.shape
    (28, 3)
    """
    vertices: np.ndarray
    faces: np.ndarray
    view: np.ndarray
    projection: np.ndarray


def _box_mesh(lo, hi):
    """The 8 corners and 12 triangles of an axis-aligned box."""
    x0, y0, z0 = lo
    x1, y1, z1 = hi
    v = np.array([[x, y, z] for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)], float)
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    f = [[a, b, c] for a, b, c, _ in quads] + [[a, c, d] for a, _, c, d in quads]
    return v, np.array(f)


def ssao_test_scene(aspect=1.0):
    """A scene with corners and an overhang: a floor, a back wall, a box and a shelf.

    World y is up. The floor is y = 0 (x and z in [-4, 4]), the back wall z = -2 (up to
    y = 3); a box [-2, -0.8] x [0, 1] x [-2, -1] stands in the corner of floor and wall; a
    shelf, the block [0.2, 2.2] x [0.35, 0.95] x [-2, -1.1], sticks out of the wall above the
    floor (an overhang with open space under it). The camera at (0.1, 1.6, 2.4) looks at
    (0.1, 0.45, -1.5) with a 55 degree vertical field of view, and sees the floor under the
    shelf.

    Parameters
    ----------
    aspect : float
        Width / height of the images to render.

    Returns
    -------
    SSAOScene

    Examples
    --------
    >>> scene = ssao_test_scene()
    >>> scene.vertices.shape, scene.view.shape
    ((24, 3), (4, 4))
    """
    floor = (np.array([[-4, 0, -2], [4, 0, -2], [4, 0, 4], [-4, 0, 4]], float),
             np.array([[0, 2, 1], [0, 3, 2]]))
    wall = (np.array([[-4, 0, -2], [4, 0, -2], [4, 3, -2], [-4, 3, -2]], float),
            np.array([[0, 1, 2], [0, 2, 3]]))
    parts = [floor, wall, _box_mesh((-2, 0, -2), (-0.8, 1, -1)),
             _box_mesh((0.2, 0.35, -2), (2.2, 0.95, -1.1))]
    verts, faces, base = [], [], 0
    for v, f in parts:
        verts.append(v)
        faces.append(f + base)
        base += len(v)
    eye = np.array([0.1, 1.6, 2.4])
    view = viewing.look_at(eye, np.array([0.1, 0.45, -1.5]) - eye, [0, 1, 0])
    projection = viewing.perspective(np.radians(55), as_positive(aspect, "aspect"), 0.5, 20.0)
    return SSAOScene(np.concatenate(verts), np.concatenate(faces), view, projection)
