r"""Chapter 15 (lesson section after 15.8): distributed (stochastic) ray tracing.

Whitted's tracer shoots **one** ray where the real picture is an **integral**: a pixel is an
area, a light has an area, a rough surface reflects into a cone of directions, a lens has an
aperture, a shutter stays open for a while. Cook, Porter and Carpenter's *distributed ray
tracing* (1984) replaces each of those single rays by many rays **spread over the domain** and
averages them: a Monte Carlo estimate of the integral, whose noise falls like
:math:`1/\sqrt{N}` with :math:`N` samples (faster with *stratified* samples, one in each cell of
a grid over the domain).

=========================  ==================================  ===========================
spread over                gives                               here
=========================  ==================================  ===========================
the pixel's area           antialiasing                        :func:`stratified`
the light's area (a disk)  soft shadows with a penumbra        :func:`soft_shadow`
reflection directions      glossy reflection                   :func:`sample_lobe`
the lens aperture          depth of field (thin lens)          :func:`lens_rays`
the shutter interval       motion blur                         ``shutter``, ``motion``
=========================  ==================================  ===========================

All of them at once cost no more rays than any one of them: each of a pixel's :math:`N`
samples gets its own pixel position, lens point, time, light point and reflection direction,
each dimension stratified separately and the strata shuffled between dimensions (Cook's trick),
so :math:`N` paths per pixel estimate the whole multi-dimensional integral
(:func:`render_distributed`).

Conventions are those of :mod:`course_lib.raytracing` (row 0 of an image at the bottom, unit
directions, colours clamped to [0, 1] only at the end). Randomness is always seeded (default
seed 0): the same seed gives the same image.
"""

from math import isqrt

import numpy as np

from .. import shading, viewing
from .._validate import as_positive, as_rng, as_scalar, as_vector, as_whole
from ._common import DEFAULT_EPSILON, _dot
from .camera import Camera, CameraRays
from .hits import _Compiled
from .intersections import _before, _first_root, _sphere_roots
from .optics import _refract, _schlick
from .scene import Sphere

__all__ = ["lens_rays", "progressive", "render_distributed", "sample_disk", "sample_lobe",
           "soft_shadow", "stratified", "trace_distributed"]


# ---------------------------------------------------------------------------------------------
# Checks
# ---------------------------------------------------------------------------------------------

def _drt_nonnegative(value, name, what):
    x = as_scalar(value, name)
    if not x >= 0:
        raise ValueError(f"{name} must be >= 0 ({what}), got {x:g}")
    return x


def _drt_exponent(value, name, what):
    """A Phong exponent: >= 0, or +inf (a perfect mirror)."""
    if isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(
            value, (bool, np.bool_)) and value == np.inf:
        return np.inf
    return _drt_nonnegative(value, name, what)


def _drt_uv(value, name):
    uv = np.asarray(value, dtype=float)
    if uv.ndim < 1 or uv.shape[-1] != 2:
        raise ValueError(f"{name} must have shape (..., 2): points of the unit square, got shape "
                         f"{uv.shape}")
    if not np.all((uv >= 0) & (uv <= 1)):
        raise ValueError(f"{name} must lie in the unit square [0, 1] x [0, 1]")
    return uv


# ---------------------------------------------------------------------------------------------
# Sampling
# ---------------------------------------------------------------------------------------------

def stratified(n, seed=0, sets=None):
    r"""`n` stratified (jittered) sample points in the unit square, in random order.

    A perfect square :math:`n = k^2` gives one uniformly random point in each cell of a
    :math:`k \times k` grid (*jittered* sampling); any other `n` gives *N-rooks* (Latin
    hypercube) samples: one point in each of the `n` columns and each of the `n` rows. Either way
    no region of the square is left empty or sampled twice, which lowers the variance of a
    Monte Carlo average compared with `n` independent uniform points. The points are returned
    in a random order so that stratified sets for different dimensions (pixel, lens, light) can
    be paired index by index without correlating them.

    Parameters
    ----------
    n : int
        Points per set, at least 1.
    seed : int, numpy.random.Generator or None, optional
    sets : int or None, optional
        Independent sets to draw (None: one set, returned without the set axis).

    Returns
    -------
    ndarray, shape (n, 2) or (sets, n, 2)

    Examples
    --------
    >>> p = stratified(4, seed=1)
    >>> sorted(map(tuple, np.floor(p * 2).astype(int).tolist()))   # one per quarter
    [(0, 0), (0, 1), (1, 0), (1, 1)]
    """
    n = as_whole(n, "n", 1)
    m = 1 if sets is None else as_whole(sets, "sets", 1)
    rng = as_rng(seed)
    k = isqrt(n)
    if k * k == n:
        a, b = np.divmod(np.arange(n), k)
        cells = np.broadcast_to(np.stack([b, a], axis=-1), (m, n, 2))
        points = (cells + rng.random((m, n, 2))) / k
        order = rng.permuted(np.tile(np.arange(n), (m, 1)), axis=1)
        points = np.take_along_axis(points, order[..., None], axis=1)
    else:
        ranks = np.stack([rng.permuted(np.tile(np.arange(n), (m, 1)), axis=1)
                          for _ in range(2)], axis=-1)
        points = (ranks + rng.random((m, n, 2))) / n
    return points[0] if sets is None else points


def _drt_stratified_1d(n, m, rng):
    """m shuffled sets of n stratified numbers in [0, 1)."""
    order = rng.permuted(np.tile(np.arange(n), (m, 1)), axis=1)
    return (order + rng.random((m, n))) / n


def sample_disk(uv, radius=1.0):
    r"""Map points of the unit square onto a disk of radius `radius`, uniformly by area.

    Shirley and Chiu's *concentric* map sends the square :math:`[-1,1]^2` (after
    :math:`a = 2u - 1`, :math:`b = 2v - 1`) ring by ring onto the disk: the square's boundary
    of half-width :math:`r` onto the circle of radius :math:`r`, so areas are preserved up to the
    constant :math:`\pi/4` and a stratified set of the square stays stratified on the disk
    (the naive :math:`(\sqrt{u}, 2\pi v)` map squeezes the strata).

    Parameters
    ----------
    uv : array_like, shape (..., 2)
        Points of the unit square (e.g. from :func:`stratified`).
    radius : float, optional
        The disk's radius (>= 0).

    Returns
    -------
    ndarray, shape (..., 2)
        Points of the disk centred at the origin.

    Examples
    --------
    >>> sample_disk([[0.5, 0.5], [1.0, 0.5], [0.5, 1.0]], radius=2.0).round(12) + 0.0
    array([[0., 0.],
           [2., 0.],
           [0., 2.]])
    """
    uv = _drt_uv(uv, "uv")
    r0 = _drt_nonnegative(radius, "radius", "the disk's radius")
    a, b = 2.0 * uv[..., 0] - 1.0, 2.0 * uv[..., 1] - 1.0
    wide = np.abs(a) > np.abs(b)
    r = np.where(wide, a, b)
    with np.errstate(divide="ignore", invalid="ignore"):
        phi = np.where(wide, np.pi / 4 * b / a, np.pi / 2 - np.pi / 4 * a / b)
    phi = np.where(r == 0, 0.0, phi)
    return r0 * np.stack([r * np.cos(phi), r * np.sin(phi)], axis=-1)


def _drt_frame(w):
    """Two unit vectors perpendicular to each unit vector w (..., 3) and to each other."""
    helper = np.where((np.abs(w[..., 0]) < 0.9)[..., None], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    a = np.cross(w, helper)
    a /= np.sqrt(_dot(a, a))[..., None]
    return a, np.cross(w, a)


def sample_lobe(axis, exponent, uv):
    r"""Directions around `axis` distributed like a Phong lobe :math:`\cos^n\alpha`.

    The density over the sphere of directions is :math:`p(\omega) = \frac{n+1}{2\pi}
    \cos^n\alpha` (:math:`\alpha` the angle from the axis, :math:`\cos\alpha > 0`); inverting its
    cumulative distribution gives :math:`\cos\alpha = (1-u)^{1/(n+1)}`, :math:`\phi = 2\pi v`.
    The mean cosine is :math:`(n+1)/(n+2)`: a large exponent keeps the directions near the axis
    (a nearly perfect mirror), a small one spreads them (a rough, glossy surface); :math:`n = 0`
    is uniform over the hemisphere.

    Parameters
    ----------
    axis : array_like, shape (3,) or (..., 3)
        The lobe's axis (normalized here), e.g. the mirror direction.
    exponent : float
        :math:`n \ge 0` (``inf``: every direction equals the axis).
    uv : array_like, shape (..., 2)
        Points of the unit square; broadcast against `axis`.

    Returns
    -------
    ndarray, shape (..., 3)
        Unit vectors.

    Examples
    --------
    >>> sample_lobe([0, 0, 1], 10.0, [[0.0, 0.3]]).round(12)       # u = 0: along the axis
    array([[0., 0., 1.]])
    """
    n = _drt_exponent(exponent, "exponent", "a Phong exponent; inf for a perfect mirror")
    w = np.asarray(axis, dtype=float)
    if w.ndim < 1 or w.shape[-1] != 3:
        raise ValueError(f"axis must have shape (..., 3), got shape {w.shape}")
    length = np.sqrt(_dot(w, w))
    if np.any(length == 0) or not np.all(np.isfinite(w)):
        raise ValueError("axis must be finite and non-zero: the lobe needs a direction")
    uv = _drt_uv(uv, "uv")
    w = np.broadcast_to(w / length[..., None], np.broadcast_shapes(w.shape, uv.shape[:-1] + (3,)))
    cos_a = np.ones(w.shape[:-1]) if np.isinf(n) else (1.0 - uv[..., 0]) ** (1.0 / (n + 1.0))
    cos_a = np.broadcast_to(cos_a, w.shape[:-1])
    sin_a = np.sqrt(np.clip(1.0 - cos_a * cos_a, 0.0, None))
    phi = 2.0 * np.pi * np.broadcast_to(uv[..., 1], w.shape[:-1])
    a, b = _drt_frame(w)
    return ((sin_a * np.cos(phi))[..., None] * a + (sin_a * np.sin(phi))[..., None] * b
            + cos_a[..., None] * w)


# ---------------------------------------------------------------------------------------------
# The thin-lens camera: pixel area and lens aperture
# ---------------------------------------------------------------------------------------------

def lens_rays(camera, samples=16, aperture=0.0, focal_distance=1.0, seed=0, antialias=True):
    r"""Camera rays of a thin lens: many per pixel, spread over the pixel and the aperture.

    A pinhole camera (:func:`camera_rays`) sends every ray through the eye, so everything is
    sharp. A **thin lens** of radius `aperture` (:math:`a`) focused at the distance
    `focal_distance` (:math:`f`, measured along the gaze) brings all the rays through one image
    point together again on the *focal plane*: the ray of a pixel sample starts at a random
    point :math:`L = e + a(s\,x_e + t\,y_e)` of the lens disk (:func:`sample_disk`) and passes
    through the point :math:`F` where the pinhole ray of that sample meets the focal plane.
    A surface point at depth :math:`z \ne f` is therefore seen through a whole disk of rays:
    their spread at depth :math:`z` has radius :math:`a|z - f|/f`, and on the image plane (at
    distance 1) its **circle of confusion** has diameter

    .. math:: c = \frac{2a\,|z - f|}{f\,z}.

    With ``antialias=True`` the sample positions are :func:`stratified` over the pixel area
    (antialiasing); with False all rays pass through the pixel centre.

    Parameters
    ----------
    camera : Camera
    samples : int, optional
        Rays per pixel (>= 1, any number).
    aperture : float, optional
        The lens radius (>= 0; 0 is the pinhole camera).
    focal_distance : float, optional
        Distance of the plane in focus, along the gaze (> 0).
    seed : int, numpy.random.Generator or None, optional
    antialias : bool, optional

    Returns
    -------
    CameraRays
        ``origins`` (on the lens) and unit ``directions``, shape (height, width, samples, 3),
        row 0 at the bottom.

    Examples
    --------
    With no aperture and no antialiasing every sample is the pinhole ray of the pixel centre:

    >>> cam = Camera([0, 0, 5], [0, 0, -1], [0, 1, 0], np.radians(60), 4, 3)
    >>> rays = lens_rays(cam, samples=3, antialias=False)
    >>> bool(np.allclose(rays.directions, cam.rays().directions))
    True
    """
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a Camera, got {type(camera).__name__}")
    n = as_whole(samples, "samples", 1)
    a = _drt_nonnegative(aperture, "aperture", "the lens radius; 0 for a pinhole camera")
    f = as_positive(focal_distance, "focal_distance", "the distance of the plane in focus")
    rng = as_rng(seed)
    w, h = camera.width, camera.height
    if antialias:
        s = stratified(n, rng, sets=h * w).reshape(h, w, n, 2)
    else:
        s = np.full((h, w, n, 2), 0.5)
    proj = viewing.perspective(camera.fov_y, w / h, 1.0, 2.0)
    axes = viewing.look_at(camera.eye, camera.gaze, camera.up)[:3, :3]
    x = (np.arange(w)[None, :, None] + s[..., 0]) * (2.0 / w) - 1.0
    y = (np.arange(h)[:, None, None] + s[..., 1]) * (2.0 / h) - 1.0
    d = (x / proj[0, 0])[..., None] * axes[0] + (y / proj[1, 1])[..., None] * axes[1] - axes[2]
    origins = np.broadcast_to(camera.eye, d.shape).copy()
    if a > 0:
        lens = sample_disk(stratified(n, rng, sets=h * w).reshape(h, w, n, 2), a)
        focus = origins + f * d                  # d has depth 1 along the gaze
        origins = origins + lens[..., :1] * axes[0] + lens[..., 1:] * axes[1]
        d = focus - origins
    d /= np.sqrt(_dot(d, d))[..., None]
    return CameraRays(origins, d)


# ---------------------------------------------------------------------------------------------
# The scene with moving spheres, area lights
# ---------------------------------------------------------------------------------------------

class _DrtScene:
    """A compiled scene (hits._Compiled) whose moving spheres are intersected at each ray's
    time: centre(t) = centre + velocity * t."""

    def __init__(self, scene, motion):
        self.c = _Compiled(scene)
        self.moving = []
        if motion is None:
            motion = {}
        if not isinstance(motion, dict):
            raise TypeError(f"motion must be a dict {{object index: velocity}} or None, got "
                            f"{type(motion).__name__}")
        for k in sorted(motion):
            if not isinstance(k, (int, np.integer)) or not 0 <= k < len(scene.objects):
                raise ValueError(f"motion keys must be indices of scene.objects (0.."
                                 f"{len(scene.objects) - 1}), got {k!r}")
            if not isinstance(scene.objects[k], Sphere):
                raise ValueError(f"motion: only spheres can move, scene.objects[{k}] is a "
                                 f"{type(scene.objects[k]).__name__}")
            v = as_vector(motion[k], f"motion[{k}]", 3)
            self.moving.append((int(k), scene.objects[k].center, scene.objects[k].radius, v))
        still = {k for k, _, _, _ in self.moving}
        self.c.spheres = [s for s in self.c.spheres if s[0] not in still]

    def nearest(self, o, d, times):
        t, obj, tri, u, v = self.c.nearest(o, d)
        for k, c0, r, vel in self.moving:
            tk = _first_root(*_sphere_roots(o, d, c0 + times[:, None] * vel, r), 0.0)
            closer = tk < t
            t[closer], obj[closer] = tk[closer], k
        return t, obj, tri, u, v

    def surface(self, o, d, t, obj, tri, u, v, times):
        p, ng, ns, mat = self.c.surface(o, d, t, obj, tri, u, v)
        for k, c0, r, vel in self.moving:
            at = obj == k
            if at.any():
                nk = (p[at] - c0 - times[at, None] * vel) / r
                ng[at] = nk
                ns[at] = nk
        return p, ng, ns, mat

    def transmission(self, o, d, t_max, times):
        trans = self.c.transmission(o, d, t_max)
        for k, c0, r, vel in self.moving:
            blocked = _before(_first_root(*_sphere_roots(o, d, c0 + times[:, None] * vel, r),
                                          0.0), t_max)
            trans[blocked] *= self.c.transparency_of[k]
        return trans


def _drt_light_points(light, points, radius, light_normal, uv):
    """A sampled point of the disk light for each shaded point."""
    centre = light.position
    if radius == 0:
        return np.broadcast_to(centre, points.shape)
    if light_normal is None:
        w = points - centre
        w = w / np.where(_dot(w, w) > 0, np.sqrt(_dot(w, w)), 1.0)[:, None]
    else:
        w = np.broadcast_to(light_normal, points.shape)
    a, b = _drt_frame(w)
    disk = sample_disk(uv, radius)
    return centre + disk[:, :1] * a + disk[:, 1:] * b


def _drt_light_options(light_radius, light_normal):
    r = _drt_nonnegative(light_radius, "light_radius", "the disk light's radius; 0 for a point "
                         "light")
    if light_normal is not None:
        light_normal = as_vector(light_normal, "light_normal", 3)
        length = np.linalg.norm(light_normal)
        if length == 0:
            raise ValueError("light_normal must not be the zero vector")
        light_normal = light_normal / length
    return r, light_normal


def soft_shadow(scene, points, light=0, light_radius=0.5, samples=64, seed=0,
                light_normal=None, epsilon=DEFAULT_EPSILON):
    r"""The fraction of a disk light visible from each point: the soft-shadow integral.

    The point light ``scene.lights[light]`` is widened into a disk of radius `light_radius`
    centred at its position, facing each point (``light_normal=None``: the disk a spherical
    light shows) or with a fixed normal. `samples` shadow rays go from the point to
    :func:`stratified` points of the disk (:func:`sample_disk`); the answer is the mean of their
    transmissions (1 unblocked, 0 blocked, the product of the transparencies crossed
    otherwise), a Monte Carlo estimate of the visible fraction of the light's area:

    .. math:: V(P) = \frac{1}{\pi R^2}\int_{\text{disk}} v(P, Q)\, dA_Q
              \approx \frac{1}{N}\sum_{i=1}^N v(P, Q_i).

    0 is the umbra, 1 full light, between them the penumbra. A point light (radius 0) gives
    only 0 or 1: Whitted's hard shadow.

    Parameters
    ----------
    scene : Scene
    points : array_like, shape (..., 3)
        Where to look from (shadow rays start ``epsilon`` towards the light).
    light : int, optional
        Index of a point light of the scene.
    light_radius : float, optional
    samples : int, optional
        Shadow rays per point (>= 1).
    seed : int, numpy.random.Generator or None, optional
    light_normal : array_like, shape (3,), or None, optional
    epsilon : float, optional

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    A unit disk light 2 above the ground, and a sphere of radius 1/4 halfway: from right
    below, the sphere hides a disk of radius :math:`2\tan(\arcsin\frac14)` of the light, the
    fraction :math:`4/15` of its area, so :math:`11/15` is visible.

    >>> from course_lib.raytracing import Scene, Sphere
    >>> scene = Scene([Sphere([0, 1, 0], 0.25)], shading.point_light([0, 2, 0]))
    >>> v = soft_shadow(scene, [0, 0, 0], light_radius=1.0, light_normal=[0, 1, 0], samples=4096)
    >>> bool(abs(v - 11 / 15) < 0.01)
    True
    """
    drt = _DrtScene(scene, None)
    lights = scene.lights
    k = as_whole(light, "light", 0)
    if k >= len(lights) or lights[k].position is None:
        raise ValueError(f"light must be the index of a point light of the scene (it has "
                         f"{len(lights)} lights), got {k}")
    r, normal = _drt_light_options(light_radius, light_normal)
    n = as_whole(samples, "samples", 1)
    eps = as_positive(epsilon, "epsilon")
    p = np.asarray(points, dtype=float)
    if p.ndim < 1 or p.shape[-1] != 3 or not np.all(np.isfinite(p)):
        raise ValueError(f"points must be finite with shape (..., 3), got shape {p.shape}")
    lead = p.shape[:-1]
    p = np.repeat(p.reshape(-1, 3), n, axis=0)
    uv = stratified(n, as_rng(seed), sets=len(p) // n).reshape(-1, 2)
    target = _drt_light_points(lights[k], p, r, normal, uv)
    to = target - p
    dist = np.sqrt(_dot(to, to))
    to = to / np.where(dist > 0, dist, 1.0)[:, None]
    vis = drt.transmission(p + eps * to, to, dist - eps, np.zeros(len(p)))
    return vis.reshape(lead + (n,)).mean(axis=-1)


# ---------------------------------------------------------------------------------------------
# The distributed tracer
# ---------------------------------------------------------------------------------------------

def _drt_trace(drt, o, d, times, rng, light_uv, gloss_uv, radius, normal, gloss, depth, eps):
    """Colours (n, 3) of rays: Whitted's generations with one sampled shadow ray per light and
    one sampled (glossy) reflected ray per hit. light_uv, gloss_uv: (n, 2) samples for the
    first hits (deeper ones draw fresh uniform samples)."""
    c = drt.c
    n = len(o)
    colour = np.zeros((n, 3))
    pixel = np.arange(n)
    weight = np.ones(n)
    for level in range(depth + 1):
        tk = times[pixel]
        t, obj, tri, u, v = drt.nearest(o, d, tk)
        local = np.empty((len(o), 3))
        local[:] = c.background
        rows = np.nonzero(obj >= 0)[0]
        children = []
        if rows.size:
            dd, tr = d[rows], tk[rows]
            p, ng, ns, mat = drt.surface(o[rows], dd, t[rows], obj[rows], tri[rows], u[rows],
                                         v[rows], tr)
            nf = np.where((_dot(ns, dd) > 0)[:, None], -ns, ns)
            ngf = np.where((_dot(ng, dd) > 0)[:, None], -ng, ng)
            visibility = np.ones((len(rows), len(c.lights)))
            luv = light_uv[pixel[rows]] if level == 0 else rng.random((len(rows), 2))
            for j, light in enumerate(c.lights):
                if light.position is None:        # a directional light stays hard
                    target_dir = np.broadcast_to(light.direction, p.shape)
                    dist = np.full(len(p), np.inf)
                    centre_dir = target_dir
                else:
                    target = _drt_light_points(light, p, radius, normal, luv)
                    target_dir = target - p
                    dist = np.sqrt(_dot(target_dir, target_dir))
                    target_dir = target_dir / np.where(dist > 0, dist, 1.0)[:, None]
                    centre_dir = light.position - p
                cast = np.nonzero(_dot(nf, centre_dir) > 0)[0]
                visibility[cast, j] = drt.transmission(
                    p[cast] + eps * ngf[cast], np.ascontiguousarray(target_dir[cast]),
                    dist[cast], tr[cast])
            terms = shading.phong(p, nf, -dd, c.lights, shading.material_per_point(c.phongs, mat),
                                  ambient=c.ambient, light_visibility=visibility, two_sided=True)
            local[rows] = terms.total
            if level < depth:
                kr, kt, ior = c.kr[mat], c.kt[mat], c.ior[mat]
                d_dot_n = _dot(dd, nf)
                entering = _dot(dd, ng) < 0
                eta1 = np.where(entering, 1.0, ior)
                eta2 = np.where(entering, ior, 1.0)
                fres = np.zeros(len(rows))
                clear = kt > 0
                if clear.any():
                    fres[clear] = _schlick(np.clip(-d_dot_n[clear], 0.0, 1.0), eta1[clear],
                                           eta2[clear])
                f_reflect, f_refract = kr + kt * fres, kt * (1.0 - fres)
                r = np.nonzero(f_reflect > 0)[0]
                if r.size:
                    mirror = dd[r] - 2.0 * d_dot_n[r, None] * nf[r]
                    if gloss is not None:
                        guv = gloss_uv[pixel[rows[r]]] if level == 0 else rng.random((r.size, 2))
                        mirror = sample_lobe(mirror, gloss, guv)
                        below = _dot(mirror, ngf[r])
                        mirror = np.where((below < 0)[:, None],
                                          mirror - 2.0 * below[:, None] * ngf[r], mirror)
                    mirror /= np.sqrt(_dot(mirror, mirror))[:, None]
                    children.append((rows[r], p[r] + eps * ngf[r], mirror, f_reflect[r]))
                r = np.nonzero(f_refract > 0)[0]
                if r.size:
                    direction, _ = _refract(dd[r], nf[r], eta1[r], eta2[r])
                    children.append((rows[r], p[r] - eps * ngf[r], direction, f_refract[r]))
        contribution = weight[:, None] * local
        for ch in range(3):
            colour[:, ch] += np.bincount(pixel, contribution[:, ch], minlength=n)
        if not children:
            break
        pixel = np.concatenate([pixel[rows_] for rows_, _, _, _ in children])
        weight = np.concatenate([weight[rows_] * f for rows_, _, _, f in children])
        o = np.concatenate([oo for _, oo, _, _ in children])
        d = np.concatenate([dd for _, _, dd, _ in children])
    return colour


def _drt_options(scene, light_radius, light_normal, gloss, shutter, motion, max_depth,
                 epsilon):
    drt = _DrtScene(scene, motion)
    r, normal = _drt_light_options(light_radius, light_normal)
    g = None if gloss is None else _drt_exponent(gloss, "gloss", "a Phong exponent; None or "
                                                 "inf for a perfect mirror")
    if g is not None and np.isinf(g):
        g = None
    s = _drt_nonnegative(shutter, "shutter", "how long the shutter stays open")
    depth = as_whole(max_depth, "max_depth", 0)
    eps = as_positive(epsilon, "epsilon", "the offset of secondary rays")
    return drt, r, normal, g, s, depth, eps


def trace_distributed(scene, origins, directions, times=None, light_radius=0.0,
                      light_normal=None, gloss=None, motion=None, max_depth=3, seed=0,
                      epsilon=DEFAULT_EPSILON):
    r"""The colour seen along each ray by the distributed tracer (unclamped RGB).

    Whitted's recursion (:func:`render`) with its single rays replaced by sampled ones: at each
    hit one shadow ray per light goes to a random point of the light's disk (radius
    `light_radius`), and the reflected ray is drawn from a Phong lobe of exponent `gloss`
    around the mirror direction (:func:`sample_lobe`; a direction that falls below the surface
    is mirrored back above it). Refraction stays perfect. Each ray carries a time (`times`):
    the spheres listed in `motion` are intersected at their position at that time. One call
    gives one sample of each integral; averaging many rays estimates them.

    Parameters
    ----------
    scene : Scene
    origins, directions : array_like, shape (n, 3)
        The rays (directions normalized here).
    times : array_like, shape (n,), optional
        Each ray's time (default 0).
    light_radius, light_normal
        The disk lights (see :func:`soft_shadow`).
    gloss : float or None, optional
        Phong exponent of the reflection lobe (None: perfect mirrors).
    motion : dict or None, optional
        ``{index of a Sphere in scene.objects: velocity}``: its centre at time t is
        ``center + t * velocity``.
    max_depth, epsilon
        As for :func:`render`.
    seed : int, numpy.random.Generator or None, optional

    Returns
    -------
    ndarray, shape (n, 3)

    Examples
    --------
    A grey sphere moving right by 2 over the time [0, 1], seen along the z axis through its
    start position: the ray hits it while its centre is within 1 of the axis, half the time.

    >>> from course_lib.raytracing import Scene, Sphere
    >>> scene = Scene([Sphere([0, 0, 0], 1.0)], ambient=1.0)      # ka = 0.1: grey 0.1
    >>> n = 1000
    >>> colours = trace_distributed(scene, np.tile([0, 0, 5], (n, 1)), np.tile([0, 0, -1], (n, 1)),
    ...                             times=(np.arange(n) + 0.5) / n, motion={0: [2, 0, 0]})
    >>> float(colours[:, 0].mean().round(3))
    0.05
    """
    drt, r, normal, g, _, depth, eps = _drt_options(scene, light_radius, light_normal, gloss,
                                                    0.0, motion, max_depth, epsilon)
    o = np.asarray(origins, dtype=float)
    d = np.asarray(directions, dtype=float)
    if o.ndim != 2 or o.shape[1] != 3 or d.shape != o.shape:
        raise ValueError(f"origins and directions must both have shape (n, 3), got {o.shape} "
                         f"and {d.shape}")
    length = np.sqrt(_dot(d, d))
    if not (np.all(np.isfinite(o)) and np.all(np.isfinite(d))) or np.any(length == 0):
        raise ValueError("origins and directions must be finite, directions non-zero")
    tm = np.zeros(len(o)) if times is None else np.asarray(times, dtype=float)
    if tm.shape != (len(o),) or not np.all(np.isfinite(tm)):
        raise ValueError(f"times must be finite with shape ({len(o)},), got shape {tm.shape}")
    rng = as_rng(seed)
    uv = rng.random((2, len(o), 2))
    return _drt_trace(drt, o, d / length[:, None], tm, rng, uv[0], uv[1], r, normal, g, depth,
                      eps)


def _drt_render(scene, camera, samples, light_radius, aperture, focal_distance, gloss, shutter,
                motion, max_depth, rng, light_normal, antialias, epsilon):
    """The unclamped mean image (h, w, 3) and the number of camera rays."""
    drt, r, normal, g, s, depth, eps = _drt_options(scene, light_radius, light_normal, gloss,
                                                    shutter, motion, max_depth, epsilon)
    camera = scene.camera if camera is None else camera
    if camera is None:
        raise ValueError("camera must be a Camera (the scene has none: pass one)")
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a Camera, got {type(camera).__name__}")
    n = as_whole(samples, "samples", 1)
    if focal_distance is None:                    # autofocus on the centre of the picture
        t = drt.c.nearest(camera.eye[None], (camera.gaze / np.linalg.norm(camera.gaze))[None])[0]
        focal_distance = float(t[0]) if np.isfinite(t[0]) else 1.0
    rays = lens_rays(camera, n, aperture, focal_distance, rng, antialias)
    h, w = camera.height, camera.width
    m = h * w
    times = s * _drt_stratified_1d(n, m, rng).reshape(-1)
    light_uv = stratified(n, rng, sets=m).reshape(-1, 2)
    gloss_uv = stratified(n, rng, sets=m).reshape(-1, 2)
    colour = _drt_trace(drt, rays.origins.reshape(-1, 3), rays.directions.reshape(-1, 3), times,
                        rng, light_uv, gloss_uv, r, normal, g, depth, eps)
    return colour.reshape(h, w, n, 3).mean(axis=2), m * n


def render_distributed(scene, camera=None, samples=16, light_radius=0.0, aperture=0.0,
                       focal_distance=None, gloss=None, shutter=0.0, motion=None, max_depth=3,
                       seed=0, light_normal=None, antialias=True, epsilon=DEFAULT_EPSILON):
    r"""Distributed ray tracing of a scene: an image (height, width, 3) in [0, 1].

    Each pixel averages `samples` paths (:func:`trace_distributed`). Path :math:`i` of a pixel
    gets the :math:`i`-th point of five independently shuffled stratified sets: a position in
    the pixel (antialiasing), a point of the lens (depth of field, :func:`lens_rays`), a time in
    ``[0, shutter)`` (motion blur), a point of each disk light (soft shadows) and a direction
    of the reflection lobe (glossy reflection). With every option at its default and
    ``antialias=False`` it reduces to Whitted's :func:`render`.

    Parameters
    ----------
    scene : Scene
    camera : Camera, optional
        Default: the scene's camera.
    samples : int, optional
        Paths per pixel (>= 1).
    light_radius : float, optional
        Radius of the disk that replaces every point light (0: hard shadows).
    aperture : float, optional
        Lens radius (0: a pinhole, everything sharp).
    focal_distance : float or None, optional
        Distance in focus along the gaze (> 0); None focuses on the surface at the centre of
        the picture.
    gloss : float or None, optional
        Phong exponent of glossy reflection (None: perfect mirrors).
    shutter : float, optional
        How long the shutter stays open (>= 0); moving spheres (`motion`) blur over it.
    motion : dict or None, optional
        ``{sphere index: velocity}``.
    max_depth : int, optional
    seed : int, numpy.random.Generator or None, optional
        The same seed gives the same image.
    light_normal : array_like or None, optional
        See :func:`soft_shadow`.
    antialias : bool, optional
        Spread the samples over the pixel area (False: through the pixel centre).
    epsilon : float, optional

    Returns
    -------
    ndarray, shape (height, width, 3)
        Row 0 at the bottom.

    Raises
    ------
    ValueError
        For ``samples < 1``, a negative radius, aperture, gloss or shutter, a focal distance
        <= 0, a bad `motion` entry, or no camera.
    TypeError
        For a scene or camera of the wrong type, or a bad seed.

    Examples
    --------
    >>> from course_lib.raytracing import example_scene, render
    >>> scene = example_scene("spheres", 16, 12)
    >>> image = render_distributed(scene, samples=4, light_radius=0.5, seed=1)
    >>> image.shape, bool(np.array_equal(image, render_distributed(scene, samples=4,
    ...                                                            light_radius=0.5, seed=1)))
    ((12, 16, 3), True)
    >>> bool(np.allclose(render_distributed(scene, samples=1, antialias=False), render(scene)))
    True
    """
    image, _ = _drt_render(scene, camera, samples, light_radius, aperture, focal_distance, gloss,
                           shutter, motion, max_depth, as_rng(seed), light_normal, antialias,
                           epsilon)
    return np.clip(image, 0.0, 1.0)


def progressive(scene, camera=None, batch=4, batches=8, seed=0, **options):
    r"""Progressive rendering: yield the running average after each batch of samples.

    The first image (after `batch` samples per pixel) comes quickly and is noisy; each further
    batch of :func:`render_distributed` samples is averaged in, so the noise falls like
    :math:`1/\sqrt{\text{samples so far}}`. This is how an interactive renderer refines the
    picture while the view rests.

    Parameters
    ----------
    scene : Scene
    camera : Camera, optional
    batch : int, optional
        Samples per pixel added by each step (>= 1).
    batches : int, optional
        Steps (>= 1).
    seed : int, numpy.random.Generator or None, optional
    **options
        Passed to :func:`render_distributed` (``light_radius``, ``aperture``, ...).

    Yields
    ------
    ndarray, shape (height, width, 3)
        The average of the first ``k * batch`` samples, clamped to [0, 1].

    Examples
    --------
    >>> from course_lib.raytracing import example_scene
    >>> images = list(progressive(example_scene("spheres", 8, 6), batch=2, batches=3,
    ...                           light_radius=0.5))
    >>> len(images), images[-1].shape
    (3, (6, 8, 3))
    """
    b = as_whole(batch, "batch", 1)
    nb = as_whole(batches, "batches", 1)
    rng = as_rng(seed)
    args = dict(light_radius=0.0, aperture=0.0, focal_distance=None, gloss=None, shutter=0.0,
                motion=None, max_depth=3, light_normal=None, antialias=True,
                epsilon=DEFAULT_EPSILON)
    unknown = sorted(set(options) - set(args))
    if unknown:
        raise TypeError(f"progressive got unknown options {unknown}; expected some of "
                        f"{sorted(args)}")
    args.update(options)
    total = None
    for k in range(nb):
        image, _ = _drt_render(scene, camera, b, args["light_radius"], args["aperture"],
                               args["focal_distance"], args["gloss"], args["shutter"],
                               args["motion"], args["max_depth"], rng, args["light_normal"],
                               args["antialias"], args["epsilon"])
        total = image if total is None else total + image
        yield np.clip(total / (k + 1), 0.0, 1.0)
