r"""Chapter 15: ray tracing: rays, intersections, Whitted's recursive ray tracer, a BVH.

**Ray casting versus ray tracing.** Ray *casting* (chapter 5) shoots one ray per pixel and asks
only "what is the nearest surface?". Ray *tracing* keeps going: at that surface it asks where
the light arriving there comes from, by shooting *more* rays. Turner Whitted's algorithm (1980),
the one this module implements, shoots three kinds of secondary rays from every hit point
:math:`P`:

* **shadow rays** towards each light source: if something lies between :math:`P` and the light,
  the point is in shadow for that light and gets neither its diffuse nor its specular light
  (only the ambient term is left). Shadows come for free, exact and sharp, from point and
  directional lights;
* a **reflected ray** in the mirror direction, when the surface is a mirror (reflectivity
  :math:`k_r > 0`);
* a **refracted (transmitted) ray** bent by Snell's law, when the surface is transparent
  (transparency :math:`k_t > 0`).

The colour seen along a ray is computed recursively,

.. math:: I(\text{ray}) = I_{local}(P) + k_r\, I(\text{reflected ray}) +
          k_t\, I(\text{refracted ray})

where :math:`I_{local}` is the Phong model (chapter 12, :func:`course_lib.shading.phong`) with
each light weighted by its shadow ray's answer. A ray that hits nothing returns the background
colour.

**The ray tree.** The rays spawned for one pixel form a binary tree (plus the shadow rays as
leaves): the primary ray is the root, each hit adds a reflected child and a refracted child.
A node's **weight** is the product of the :math:`k_r`'s and :math:`k_t`'s on the path from the
root, so the pixel colour is :math:`\sum_{\text{nodes}} \text{weight} \times I_{local}`: every
node contributes its local colour, scaled by how much of it reaches the eye.
:func:`trace_tree` builds this tree for one ray so that it can be drawn.

**Recursion depth.** A ray between two parallel mirrors would bounce forever, and a complete
tree of depth :math:`d` has :math:`2^{d+1} - 1` nodes. The recursion stops at ``max_depth``
(``max_depth=0``: primary rays only, i.e. ray casting with shadows), and optionally when a
ray's weight falls below ``min_weight`` (*adaptive depth control*: a ray that can change the
pixel by less than 1/255 is not worth tracing). What the last rays would have seen is simply
missing (black), which is why deep mirror-in-mirror views go dark.

**Reflection.** For a ray travelling in direction :math:`d` that hits a surface with unit
normal :math:`n`, the mirror direction is (:func:`reflect_direction`)

.. math:: r = d - 2 (d \cdot n)\, n

(the textbook's :math:`R = 2(N \cdot L)N - L` of the Phong model is the same formula for the
vector :math:`L = -d` pointing *away* from the surface; mixing up the two conventions flips
the ray into the surface).

**Refraction: Snell's law.** A ray passing from a medium of refractive index :math:`\eta_1`
into one of index :math:`\eta_2` bends so that

.. math:: \eta_1 \sin\theta_1 = \eta_2 \sin\theta_2

(:math:`\theta_1`, :math:`\theta_2` measured from the normal). With :math:`\eta =
\eta_1/\eta_2`, :math:`c_1 = \cos\theta_1 = -d \cdot n` (the normal facing the incoming ray)
and :math:`c_2 = \sqrt{1 - \eta^2 (1 - c_1^2)}` the transmitted direction is
(:func:`refract_direction`)

.. math:: t = \eta\, d + (\eta c_1 - c_2)\, n

**Total internal reflection.** Going from a denser to a thinner medium (:math:`\eta_1 >
\eta_2`, glass to air), :math:`\sin\theta_2 = \eta \sin\theta_1` exceeds 1 beyond the
**critical angle** :math:`\theta_c = \arcsin(\eta_2/\eta_1)` (41.8° for glass of index 1.5):
no refracted ray exists and *all* the light is reflected.

**Fresnel and Schlick.** How much light a dielectric (glass, water) reflects depends on the
angle: little head-on (4 % for glass), everything at grazing incidence. The exact Fresnel
equations (:func:`fresnel`) average the reflectances of the two polarizations; Schlick's
approximation (:func:`schlick`) is what renderers use:

.. math:: F(\theta) \approx R_0 + (1 - R_0)(1 - \cos\theta)^5, \qquad
          R_0 = \left(\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}\right)^2

(exact at normal incidence; for :math:`\eta_1 > \eta_2` the cosine of the *transmitted* angle
is used, and :math:`F = 1` beyond the critical angle). A transparent material of transparency
:math:`k_t` then sends :math:`k_t F` of the light along the reflected ray (on top of its own
:math:`k_r`) and :math:`k_t (1 - F)` along the refracted one: energy is conserved between the
two.

**Acceleration structures.** Every ray must find its nearest surface; tested against every
primitive that costs :math:`O(P)` per ray, and a ray tracer shoots millions of rays. A
**bounding volume hierarchy** (:class:`BVH`) wraps triangles in nested axis-aligned boxes; a
ray that misses a box (a cheap *slab test*, :func:`intersect_box`) skips everything inside, and
a box that starts beyond the nearest hit found so far is skipped as well. The cost per ray
drops to about :math:`O(\log P)` box tests and a handful of triangle tests. (Uniform grids,
octrees and kd-trees are the *spatial subdivision* alternatives: they partition space rather
than the objects.)

**Antialiasing by supersampling.** One ray through each pixel centre samples the picture at a
single point, so edges come out as staircases (aliasing). Shooting :math:`k \times k` rays per
pixel at sub-pixel positions and averaging their colours approximates the pixel's *area*
average. Regular sub-pixel grids still alias on regular patterns (a checkerboard in the
distance); *jittering* each sample randomly within its sub-pixel cell (stratified sampling)
turns that aliasing into much less objectionable noise.

**Where ray tracing is weak.** Whitted ray tracing handles only perfect mirrors, perfect
refraction and point-like lights: shadows are hard-edged, there is no light bounced from one
diffuse surface onto another (the ambient term stands in for it), and light focused through
glass (caustics) is missing. Here shadow rays pass through transparent objects attenuated by
:math:`k_t` (per object crossed, without bending): a cheap stand-in for those caustics.

Conventions
-----------
* **Rays** are :math:`o + t\,d`; :math:`t` is the distance when :math:`d` is a unit vector
  (the camera and the tracer always use unit directions). Intersection functions take many rays
  at once, shapes ``(..., 3)``, and return :math:`t = \infty` for a miss; only hits with
  :math:`t \ge t_{min}` count (default 0: in front of the origin).
* **Normals** returned by the intersection functions point *outwards* (away from a sphere's
  centre, along a plane's given normal, to the counter-clockwise side of a triangle). The tracer
  flips them to face the incoming ray before shading.
* **Camera and pixels** (:func:`camera_rays`): the camera of :func:`course_lib.viewing.look_at`
  and :func:`course_lib.viewing.perspective` (the eye looks along ``gaze``, ``fov_y`` is the
  vertical field of view). Pixel ``(row j, column i)`` covers :math:`[i, i+1] \times [j, j+1]`
  of the viewport and its ray passes through the centre :math:`(i + \tfrac12, j + \tfrac12)`,
  as in :func:`course_lib.visibility.ray_cast_image`. **Row 0 is the bottom row**: show an
  image with ``plt.imshow(image, origin="lower")``.
* **Epsilon offsets**: secondary rays start at :math:`P \pm \epsilon N` (``epsilon``, default
  :math:`10^{-4}`), on the side they travel to (reflected and shadow rays outside, refracted
  rays inside). Without the offset, rounding puts the hit point a hair below the surface and
  the new ray hits its own surface at :math:`t \approx 0`: dark speckles called *shadow acne*.
* **Colours** are RGB radiances; the image is the average of a pixel's samples **clamped** to
  [0, 1] per channel (no tone mapping: highlights and bright reflections saturate to white).
* **Media**: a refracted ray entering an object (against its outward normal) goes from index
  1 (air) to the material's ``ior``, and back when leaving; nested transparent objects are not
  tracked.
"""
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from . import shading, viewing
from ._validate import as_array, as_points, as_scalar, as_vector, broadcast_stacks
from .visibility import _moller_trumbore_soa as _moller_trumbore

__all__ = [
    "BVH",
    "BoxHits",
    "Camera",
    "CameraRays",
    "Material",
    "Mesh",
    "Plane",
    "RayCounts",
    "RayNode",
    "Scene",
    "SceneHits",
    "Sphere",
    "SurfaceHits",
    "TriangleHits",
    "camera_rays",
    "example_scene",
    "fresnel",
    "intersect_box",
    "intersect_plane",
    "intersect_scene",
    "intersect_sphere",
    "intersect_triangles",
    "reflect_direction",
    "refract_direction",
    "render",
    "schlick",
    "trace_tree",
]

DEFAULT_EPSILON = 1e-4


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


def _where(index, lead):
    """' (at index ...)' for a flat index into arrays of leading shape `lead`."""
    if not lead:
        return ""
    return f" (at index {tuple(int(i) for i in np.unravel_index(index, lead))})"


def _nonzero_vectors(v, name, lead):
    zero = ~np.any(v != 0, axis=-1)
    if zero.any():
        raise ValueError(f"{name} must not contain the zero vector"
                         f"{_where(int(np.argmax(zero.ravel())), lead)}: a ray needs a direction")


def _rays(origins, directions):
    """Origins and directions flattened to (p, 3), and the common leading shape."""
    o = as_points(origins, "origins", dims=3)
    d = as_points(directions, "directions", dims=3)
    lead = broadcast_stacks(origins=(o, 1), directions=(d, 1))
    o = np.ascontiguousarray(np.broadcast_to(o, lead + (3,)).reshape(-1, 3))
    d = np.ascontiguousarray(np.broadcast_to(d, lead + (3,)).reshape(-1, 3))
    _nonzero_vectors(d, "directions", lead)
    return o, d, lead


def _t_min(value):
    t = as_scalar(value, "t_min")
    if t < 0:
        raise ValueError(f"t_min must be >= 0 (hits behind the ray's origin are never wanted), "
                         f"got {t}")
    return t


def _t_max(value, t_min):
    if np.isscalar(value) and np.isposinf(value):
        return np.inf
    t = as_scalar(value, "t_max")
    if t < t_min:
        raise ValueError(f"t_max must not be below t_min (got t_min = {t_min}, t_max = {t})")
    return t


def _positive(value, name, what="positive"):
    v = as_scalar(value, name)
    if v <= 0:
        raise ValueError(f"{name} must be {what}, got {v}")
    return v


def _whole(value, name, minimum):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    v = as_scalar(value, name)
    if v < minimum or v != int(v):
        raise ValueError(f"{name} must be a whole number >= {minimum}, got {value!r}")
    return int(v)


def _indices(value, name):
    """Refractive indices: positive numbers (arrays allowed)."""
    eta = as_array(value, name)
    if np.any(eta <= 0):
        raise ValueError(f"{name} must be positive (a refractive index; 1 for vacuum or air, "
                         f"about 1.5 for glass), got {float(eta[eta <= 0].flat[0]):g}")
    return eta


def _unit_vectors(value, name):
    v = as_points(value, name, dims=3)
    length = np.sqrt(_dot(v, v))
    if np.any(length == 0):
        raise ValueError(f"{name} must not contain the zero vector"
                         f"{_where(int(np.argmin(length.ravel())), length.shape)}: it has no "
                         "direction")
    return v / length[..., None]


def _rgb(value, name):
    c = as_array(value, name)
    if c.ndim == 0:
        c = np.full(3, float(c))
    if c.shape != (3,):
        raise ValueError(f"{name} must be a number (grey) or an RGB triple, got shape {c.shape}")
    if np.any(c < 0):
        raise ValueError(f"{name} must not be negative, got {c.tolist()}")
    return c


# ---------------------------------------------------------------------------------------------
# Reflection, refraction, Fresnel
# ---------------------------------------------------------------------------------------------

def reflect_direction(d, n):
    r"""The mirror direction of a ray travelling along `d` that hits a surface of normal `n`.

    .. math:: r = d - 2\,(d \cdot n)\, n

    `d` is the *incoming* direction (the way the ray travels, towards the surface), the
    convention of ray tracers and GLSL's ``reflect``; the Phong model's :math:`R = 2 (N \cdot
    L) N - L` (:func:`course_lib.shading.reflect`) is the same formula for :math:`L = -d`. The
    side `n` points to does not matter (the formula is even in :math:`n`); `n` is normalized
    here and :math:`\lVert r \rVert = \lVert d \rVert`. The angle of reflection equals the angle
    of incidence: :math:`r \cdot n = -d \cdot n`.

    Parameters
    ----------
    d : array_like, shape (..., 3)
        Incoming directions (not zero).
    n : array_like, shape (..., 3)
        Surface normals (not zero); broadcasts against `d`.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For zero vectors, NaN, or shapes that do not broadcast.

    Examples
    --------
    A ray going down and to the right bounces off the floor up and to the right:

    >>> reflect_direction([1, -1, 0], [0, 1, 0])
    array([1., 1., 0.])
    """
    dv = as_points(d, "d", dims=3)
    _nonzero_vectors(dv.reshape(-1, 3), "d", dv.shape[:-1])
    nv = _unit_vectors(n, "n")
    broadcast_stacks(d=(dv, 1), n=(nv, 1))
    return dv - 2.0 * _dot(dv, nv)[..., None] * nv


def _refract(d, n, eta1, eta2):
    """Unit d, unit n facing d (d.n <= 0): (t, total internal reflection mask)."""
    eta = eta1 / eta2
    c1 = np.clip(-_dot(d, n), 0.0, 1.0)
    k = 1.0 - eta * eta * (1.0 - c1 * c1)
    tir = k < 0
    c2 = np.sqrt(np.maximum(k, 0.0))
    t = eta[..., None] * d + (eta * c1 - c2)[..., None] * n
    t = t / np.sqrt(_dot(t, t))[..., None]
    return np.where(tir[..., None], 0.0, t), tir


def refract_direction(d, n, eta1, eta2):
    r"""The refracted direction by Snell's law, and where there is total internal reflection.

    A ray travelling along `d` passes from a medium of refractive index :math:`\eta_1` into
    one of index :math:`\eta_2` (:math:`\eta_1 \sin\theta_1 = \eta_2 \sin\theta_2`). With
    :math:`n` turned to face the incoming ray, :math:`\eta = \eta_1 / \eta_2` and
    :math:`c_1 = -d \cdot n = \cos\theta_1`:

    .. math:: c_2 = \sqrt{1 - \eta^2 (1 - c_1^2)} = \cos\theta_2, \qquad
              t = \eta\, d + (\eta\, c_1 - c_2)\, n

    When :math:`1 - \eta^2 (1 - c_1^2) < 0`, i.e. :math:`\sin\theta_1 > \eta_2/\eta_1` (beyond
    the critical angle, possible only when :math:`\eta_1 > \eta_2`), there is no refracted ray:
    **total internal reflection**; the direction is then returned as the zero vector and the
    flag is True (all light goes along :func:`reflect_direction`).

    Parameters
    ----------
    d : array_like, shape (..., 3)
        Incoming directions (normalized here; not zero).
    n : array_like, shape (..., 3)
        Surface normals, on either side (normalized and turned towards the incoming ray here).
    eta1, eta2 : float or array_like, shape (...)
        Refractive indices of the media the ray leaves and enters (positive).

    Returns
    -------
    direction : ndarray, shape (..., 3)
        Unit refracted directions (zero where there is total internal reflection).
    total_internal : ndarray of bool, shape (...)
        True where the ray is totally internally reflected.

    Raises
    ------
    ValueError
        For zero vectors, NaN, non-positive refractive indices, or shapes that do not
        broadcast.

    Examples
    --------
    Into glass at 45 degrees: :math:`\sin\theta_2 = \sin 45^\circ / 1.5 = 0.4714`. Out of the
    glass at 45 degrees (beyond the critical angle of 41.8 degrees): reflected totally.

    >>> t, tir = refract_direction([1, -1, 0], [0, 1, 0], 1.0, 1.5)
    >>> t.round(4), tir
    (array([ 0.4714, -0.8819,  0.    ]), array(False))
    >>> refract_direction([1, -1, 0], [0, 1, 0], 1.5, 1.0)
    (array([0., 0., 0.]), array(True))
    """
    dv = _unit_vectors(d, "d")
    nv = _unit_vectors(n, "n")
    e1 = _indices(eta1, "eta1")
    e2 = _indices(eta2, "eta2")
    lead = broadcast_stacks(d=(dv, 1), n=(nv, 1), eta1=(e1, 0), eta2=(e2, 0))
    dv = np.broadcast_to(dv, lead + (3,))
    nv = np.broadcast_to(nv, lead + (3,))
    nv = np.where((_dot(dv, nv) > 0)[..., None], -nv, nv)
    t, tir = _refract(dv, nv, np.broadcast_to(e1, lead), np.broadcast_to(e2, lead))
    return t, np.asarray(tir)


def _cosines(cos_theta, eta1, eta2):
    c = as_array(cos_theta, "cos_theta")
    if np.any(c < -1e-12) or np.any(c > 1 + 1e-12):
        bad = c[(c < -1e-12) | (c > 1 + 1e-12)].flat[0]
        raise ValueError(f"cos_theta must lie in [0, 1] (the cosine of the angle between the ray "
                         f"and the normal facing it), got {bad:g}")
    e1 = _indices(eta1, "eta1")
    e2 = _indices(eta2, "eta2")
    lead = broadcast_stacks(cos_theta=(c, 0), eta1=(e1, 0), eta2=(e2, 0))
    return (np.broadcast_to(np.clip(c, 0.0, 1.0), lead), np.broadcast_to(e1, lead),
            np.broadcast_to(e2, lead))


def _transmitted_cosine(c1, eta1, eta2):
    """cos(theta_2) by Snell's law and the total-internal-reflection mask."""
    s2 = (eta1 / eta2) ** 2 * (1.0 - c1 * c1)
    return np.sqrt(np.maximum(1.0 - s2, 0.0)), s2 > 1.0


def _schlick(c1, eta1, eta2):
    r0 = ((eta1 - eta2) / (eta1 + eta2)) ** 2
    c2, tir = _transmitted_cosine(c1, eta1, eta2)
    c = np.where(eta1 > eta2, c2, c1)
    f = r0 + (1.0 - r0) * (1.0 - c) ** 5
    return np.where(tir, 1.0, np.where(eta1 == eta2, 0.0, f))


def schlick(cos_theta, eta1, eta2):
    r"""Schlick's approximation of the Fresnel reflectance of a dielectric interface.

    .. math:: F = R_0 + (1 - R_0)(1 - \cos\theta)^5, \qquad
              R_0 = \left(\frac{\eta_1 - \eta_2}{\eta_1 + \eta_2}\right)^2

    :math:`R_0` is the exact reflectance at normal incidence. For :math:`\eta_1 > \eta_2`
    (leaving the denser medium) :math:`\cos\theta` is the cosine of the *transmitted* angle,
    :math:`\sqrt{1 - (\eta_1/\eta_2)^2 \sin^2\theta_1}` (otherwise the approximation is poor
    near the critical angle), and :math:`F = 1` beyond the critical angle (total internal
    reflection). With :math:`\eta_1 = \eta_2` there is no interface and :math:`F = 0`. Compared
    with the exact :func:`fresnel`, the error is largest near grazing incidence (or, from
    inside, just below the critical angle): at most 0.036 for glass (:math:`\eta = 1.5`) and
    0.06 for water (1.33); the curve has the right shape: small and flat up to about 45°,
    rising steeply to 1 at grazing incidence.

    Parameters
    ----------
    cos_theta : float or array_like
        Cosine of the angle of incidence, in [0, 1] (:math:`-d \cdot n` for a unit ray
        direction and the normal facing the ray).
    eta1, eta2 : float or array_like
        Refractive indices of the medium the ray comes from and of the other one.

    Returns
    -------
    ndarray
        The fraction of light reflected, in [0, 1].

    Raises
    ------
    ValueError
        For a cosine outside [0, 1], non-positive indices or NaN.

    Examples
    --------
    Head-on, glass reflects 4 %; at grazing incidence everything; from inside beyond the
    critical angle everything:

    >>> schlick([1.0, 0.0], 1.0, 1.5).round(6)
    array([0.04, 1.  ])
    >>> float(schlick(np.cos(np.radians(60)), 1.5, 1.0))
    1.0
    """
    c, e1, e2 = _cosines(cos_theta, eta1, eta2)
    return _schlick(c, e1, e2)


def fresnel(cos_theta, eta1, eta2):
    r"""The exact Fresnel reflectance of unpolarized light (the average of both polarizations).

    With :math:`c_1 = \cos\theta_1` and :math:`c_2 = \cos\theta_2` from Snell's law,

    .. math:: r_s = \frac{\eta_1 c_1 - \eta_2 c_2}{\eta_1 c_1 + \eta_2 c_2}, \qquad
              r_p = \frac{\eta_2 c_1 - \eta_1 c_2}{\eta_2 c_1 + \eta_1 c_2}, \qquad
              F = \tfrac12 (r_s^2 + r_p^2)

    and :math:`F = 1` beyond the critical angle. The ray tracer uses the cheaper
    :func:`schlick`; this is the reference it approximates.

    Parameters
    ----------
    cos_theta : float or array_like
        Cosine of the angle of incidence, in [0, 1].
    eta1, eta2 : float or array_like
        Refractive indices of the medium the ray comes from and of the other one.

    Returns
    -------
    ndarray
        The reflected fraction, in [0, 1].

    Raises
    ------
    ValueError
        For a cosine outside [0, 1], non-positive indices or NaN.

    Examples
    --------
    >>> fresnel([1.0, np.cos(np.radians(60))], 1.0, 1.5).round(4)
    array([0.04  , 0.0892])
    """
    c1, e1, e2 = _cosines(cos_theta, eta1, eta2)
    c2, tir = _transmitted_cosine(c1, e1, e2)
    with np.errstate(invalid="ignore", divide="ignore"):
        rs = (e1 * c1 - e2 * c2) / (e1 * c1 + e2 * c2)
        rp = (e2 * c1 - e1 * c2) / (e2 * c1 + e1 * c2)
        f = 0.5 * (rs * rs + rp * rp)
    # 0/0 only at grazing incidence with eta1 = eta2: no interface, nothing reflected
    f = np.where(np.isfinite(f), f, 0.0)
    return np.where(tir, 1.0, f)


# ---------------------------------------------------------------------------------------------
# Ray-object intersections
# ---------------------------------------------------------------------------------------------

class SurfaceHits(NamedTuple):
    """Nearest hits of rays with one surface (:func:`intersect_sphere`, :func:`intersect_plane`).

    Attributes
    ----------
    t : ndarray, shape (...)
        Ray parameter of the hit (the distance for unit directions); ``inf`` for a miss.
    normals : ndarray, shape (..., 3)
        Unit *outward* normal at the hit point ``origin + t * direction``; zero for a miss.

    Examples
    --------
    >>> hits = intersect_sphere([[0, 0, 5], [3, 0, 5]], [0, 0, -1], [0, 0, 0], 1.0)
    >>> hits.t, hits.normals[0]
    (array([ 4., inf]), array([0., 0., 1.]))
    """
    t: np.ndarray
    normals: np.ndarray


def _sphere_roots(o, d, center, radius):
    r"""Both roots (t1 <= t2) of |o + t d - c|^2 = r^2 for rays (p, 3); inf where no root.

    The numerically stable form: b = d.(o - c), a = d.d, the discriminant written as
    a (r^2 - |l|^2) with l = (o - c) - (b/a) d the vector from the centre to the line's nearest
    point (no cancellation between b^2 and a c), and the two roots as q/a and c/q with
    q = -(b + sign(b) sqrt(disc)) (no cancellation between -b and sqrt(disc)).
    """
    f = o - center
    a = _dot(d, d)
    b = _dot(f, d)
    l = f - (b / a)[:, None] * d
    disc = a * (radius * radius - _dot(l, l))
    c = _dot(f, f) - radius * radius
    hit = disc >= 0
    q = -(b + np.copysign(np.sqrt(np.where(hit, disc, 0.0)), b))
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = q / a
        t2 = np.where(q != 0, c / q, t1)
    near, far = np.minimum(t1, t2), np.maximum(t1, t2)
    return np.where(hit, near, np.inf), np.where(hit, far, np.inf)


def _first_root(near, far, t_min):
    return np.where(near >= t_min, near, np.where(far >= t_min, far, np.inf))


def _before(t, t_max):
    """Hits at `t` that lie no farther than `t_max`. A miss is encoded as ``t = inf``, and a
    shadow ray towards a directional light has ``t_max = inf``: ``inf <= inf`` is true, so a
    plain comparison would let every missed object block such a ray."""
    return np.isfinite(t) & (t <= t_max)


def intersect_sphere(origins, directions, center, radius, t_min=0.0):
    r"""Ray-sphere intersection: the nearest hit at or beyond `t_min` of each ray.

    Substituting the ray :math:`o + t\,d` into the sphere :math:`\lVert p - c \rVert^2 = r^2`
    gives the quadratic

    .. math:: (d \cdot d)\, t^2 + 2\, (d \cdot f)\, t + (f \cdot f - r^2) = 0, \qquad f = o - c

    No real root (negative discriminant): a miss. Otherwise the ray enters at the smaller root
    and leaves at the larger one; the answer is the smallest root :math:`\ge t_{min}` (the far
    root for a ray starting inside the sphere). Both roots are computed in a numerically stable
    form (no cancellation for rays far from the sphere or grazing it). The outward normal at
    the hit is :math:`(p - c) / r`.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
        The rays (directions need not be unit vectors; then :math:`t` is in units of their
        length). One origin or one direction may be shared by all rays.
    center : array_like, shape (3,)
    radius : float
        Positive.
    t_min : float, optional
        Only hits with :math:`t \ge t_{min} \ge 0` count.

    Returns
    -------
    SurfaceHits
        ``t`` (``inf`` for a miss) and the outward unit ``normals`` (zero for a miss).

    Raises
    ------
    ValueError
        For zero directions, a non-positive radius, a negative `t_min`, NaN, or malformed
        shapes.

    Examples
    --------
    From outside (enters at t = 4) and from the centre (leaves at t = 1):

    >>> intersect_sphere([[0, 0, 5], [0, 0, 0]], [0, 0, -1], [0, 0, 0], 1.0).t
    array([4., 1.])
    """
    o, d, lead = _rays(origins, directions)
    c = as_vector(center, "center", 3)
    r = _positive(radius, "radius", "positive (the sphere's radius)")
    t_min = _t_min(t_min)
    t = _first_root(*_sphere_roots(o, d, c, r), t_min)
    hit = np.isfinite(t)
    normals = np.zeros_like(o)
    p = o[hit] + t[hit, None] * d[hit] - c
    normals[hit] = p / np.sqrt(_dot(p, p))[:, None]
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))


def _plane_t(o, d, point, normal, t_min):
    denom = d @ normal
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((point - o) @ normal) / denom
    return np.where((denom != 0) & (t >= t_min), t, np.inf)


def intersect_plane(origins, directions, point, normal, t_min=0.0):
    r"""Ray-plane intersection: :math:`t = \frac{(q - o) \cdot n}{d \cdot n}`.

    The plane passes through :math:`q` with normal :math:`n`: the points :math:`p` with
    :math:`(p - q) \cdot n = 0`. A ray parallel to the plane (:math:`d \cdot n = 0`) misses it
    (even when it lies in it), and a hit with :math:`t < t_{min}` (behind the origin) does not
    count. Both sides of the plane are hit.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    point : array_like, shape (3,)
        A point :math:`q` of the plane.
    normal : array_like, shape (3,)
        The plane's normal (normalized here; not zero). It is returned as the "outward" normal
        of every hit, whichever side the ray comes from.
    t_min : float, optional

    Returns
    -------
    SurfaceHits

    Raises
    ------
    ValueError
        For zero directions or normal, a negative `t_min`, NaN, or malformed shapes.

    Examples
    --------
    >>> hits = intersect_plane([[0, 2, 0], [0, 2, 0]], [[0, -1, 0], [1, 0, 0]],
    ...                        [0, 0, 0], [0, 1, 0])
    >>> hits.t
    array([ 2., inf])
    """
    o, d, lead = _rays(origins, directions)
    q = as_vector(point, "point", 3)
    n = _unit_vectors(as_vector(normal, "normal", 3), "normal")
    t = _plane_t(o, d, q, n, _t_min(t_min))
    normals = np.where(np.isfinite(t)[:, None], n, 0.0)
    return SurfaceHits(t.reshape(lead), normals.reshape(lead + (3,)))


class BoxHits(NamedTuple):
    """The result of :func:`intersect_box` (the slab method).

    Attributes
    ----------
    t : ndarray, shape (...)
        The nearest hit at or beyond ``t_min``: where the ray enters the box, or where it leaves
        it for a ray starting inside; ``inf`` for a miss.
    normals : ndarray, shape (..., 3)
        Outward unit normal of the face hit (an axis direction); zero for a miss.
    t_enter, t_exit : ndarray, shape (...)
        Where the ray's *line* enters and leaves the box (``t_enter > t_exit``: it misses).

    Examples
    --------
    >>> hits = intersect_box([0.5, 0.5, 5], [0, 0, -1], [0, 0, 0], [1, 1, 1])
    >>> float(hits.t), float(hits.t_exit), hits.normals
    (4.0, 5.0, array([0., 0., 1.]))
    """
    t: np.ndarray
    normals: np.ndarray
    t_enter: np.ndarray
    t_exit: np.ndarray


def intersect_box(origins, directions, lo, hi, t_min=0.0):
    r"""Ray-box intersection by the slab method (an axis-aligned box, as a BVH node's).

    The box is the intersection of three *slabs* :math:`lo_k \le x_k \le hi_k`. The ray's line
    is inside slab :math:`k` for :math:`t` between :math:`(lo_k - o_k)/d_k` and
    :math:`(hi_k - o_k)/d_k` (in either order), so it is inside the box for

    .. math:: t_{enter} = \max_k \min\left(\frac{lo_k - o_k}{d_k}, \frac{hi_k - o_k}{d_k}\right)
              \le t \le t_{exit} = \min_k \max(\dots)

    and it hits the box when :math:`t_{enter} \le t_{exit}` and :math:`t_{exit} \ge t_{min}`.
    A ray parallel to a slab (:math:`d_k = 0`) is inside it for all :math:`t` or for none,
    depending on :math:`o_k`. Six subtractions, six multiplications (with precomputed
    :math:`1/d_k`) and a few comparisons: far cheaper than testing what the box contains.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    lo, hi : array_like, shape (3,)
        The box's minimum and maximum corners (``lo <= hi``).
    t_min : float, optional

    Returns
    -------
    BoxHits

    Raises
    ------
    ValueError
        For zero directions, ``lo > hi``, a negative `t_min`, NaN, or malformed shapes.

    Examples
    --------
    A ray starting inside the unit cube leaves it through the face x = 1:

    >>> hits = intersect_box([0.5, 0.5, 0.5], [1, 0, 0], [0, 0, 0], [1, 1, 1])
    >>> float(hits.t), hits.normals
    (0.5, array([1., 0., 0.]))
    """
    o, d, lead = _rays(origins, directions)
    lo_v = as_vector(lo, "lo", 3)
    hi_v = as_vector(hi, "hi", 3)
    if np.any(lo_v > hi_v):
        raise ValueError(f"lo must not exceed hi in any coordinate (got lo = {lo_v.tolist()}, "
                         f"hi = {hi_v.tolist()})")
    t_min = _t_min(t_min)
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo_v - o) / d
        t2 = (hi_v - o) / d
    near, far = np.minimum(t1, t2), np.maximum(t1, t2)
    parallel = d == 0
    inside = (o >= lo_v) & (o <= hi_v)
    near = np.where(parallel, np.where(inside, -np.inf, np.inf), near)
    far = np.where(parallel, np.where(inside, np.inf, -np.inf), far)
    t_enter, t_exit = near.max(axis=1), far.min(axis=1)
    hit = (t_enter <= t_exit) & (t_exit >= t_min)
    from_outside = t_enter >= t_min
    t = np.where(hit, np.where(from_outside, t_enter, t_exit), np.inf)
    # the face: the slab whose entering (or leaving) plane defines t
    axis = np.where(from_outside, near.argmax(axis=1), far.argmin(axis=1))
    rows = np.arange(len(o))
    sign = np.sign(d[rows, axis]) * np.where(from_outside, -1.0, 1.0)
    normals = np.zeros_like(o)
    normals[rows, axis] = np.where(hit, sign, 0.0)
    return BoxHits(t.reshape(lead), normals.reshape(lead + (3,)), t_enter.reshape(lead),
                   t_exit.reshape(lead))


class TriangleHits(NamedTuple):
    """Nearest hits of rays with a set of triangles (:func:`intersect_triangles`,
    :meth:`BVH.intersect`), with the work it took.

    Attributes
    ----------
    t : ndarray, shape (...)
        Ray parameter of the nearest hit; ``inf`` for a miss.
    ids : ndarray of int, shape (...)
        Index of the triangle hit (the lowest index among equally near ones); -1 for a miss.
    u, v : ndarray, shape (...)
        Barycentric coordinates of the hit in its triangle: the point is
        :math:`(1 - u - v)\\, v_0 + u\\, v_1 + v\\, v_2` (0 for a miss).
    normals : ndarray, shape (..., 3)
        Unit normal of the triangle hit, :math:`(v_1 - v_0) \\times (v_2 - v_0)` normalized (the
        side from which the vertices are counter-clockwise); zero for a miss.
    triangle_tests : int
        Ray-triangle tests performed (rays x triangles for brute force).
    box_tests : int
        Ray-box (slab) tests performed (0 for brute force).

    Examples
    --------
    >>> hits = intersect_triangles([0.25, 0.25, 2], [0, 0, -1], [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]])
    >>> float(hits.t), int(hits.ids), float(hits.u), float(hits.v), hits.normals
    (2.0, 0, 0.25, 0.25, array([0., 0., 1.]))
    """
    t: np.ndarray
    ids: np.ndarray
    u: np.ndarray
    v: np.ndarray
    normals: np.ndarray
    triangle_tests: int
    box_tests: int


def _triangles(value, name="triangles"):
    t = as_array(value, name)
    if t.shape == (3, 3):
        t = t[None]
    if t.ndim != 3 or t.shape[1:] != (3, 3):
        raise ValueError(f"{name} must be an array of triangles of shape (m, 3, 3) (m triangles, "
                         f"3 vertices, 3 coordinates), got shape {t.shape}")
    if len(t) == 0:
        raise ValueError(f"{name} must contain at least one triangle, got an empty array")
    return t


def _soa(tris):
    """(9, m + 1) rows v0, e1, e2 (x, y, z each); column m is a zero triangle that never hits."""
    v0 = tris[:, 0]
    out = np.zeros((9, len(tris) + 1))
    out[0:3, :-1] = v0.T
    out[3:6, :-1] = (tris[:, 1] - v0).T
    out[6:9, :-1] = (tris[:, 2] - v0).T
    return out


def _unit_face_normals(tris):
    c = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    length = np.sqrt(_dot(c, c))
    return np.divide(c, length[:, None], out=np.zeros_like(c), where=length[:, None] > 0)


def _brute_force(o, d, soa, t_min, t_max):
    """Nearest hits of rays (p, 3) against all triangles; t_max is an array (p,)."""
    p, m = len(o), soa.shape[1] - 1
    best_t = np.full(p, np.inf)
    best_id = np.full(p, -1, dtype=np.intp)
    best_u, best_v = np.zeros(p), np.zeros(p)
    ray_chunk = max(1, min(p, 1 << 12))
    tri_chunk = max(1, (1 << 18) // ray_chunk)
    for r0 in range(0, p, ray_chunk):
        rs = slice(r0, r0 + ray_chunk)
        ot, dt = o[rs].T[:, :, None], d[rs].T[:, :, None]
        rows = np.arange(len(ot[0]))
        for s in range(0, m, tri_chunk):
            t, u, v = _moller_trumbore(ot, dt, soa[:, None, s:min(s + tri_chunk, m)])
            t[(t < t_min) | (t > t_max[rs, None])] = np.inf
            j = np.argmin(t, axis=1)                  # the lowest index among equal distances
            tj = t[rows, j]
            better = tj < best_t[rs]
            idx = np.nonzero(better)[0] + r0
            best_t[idx] = tj[better]
            best_id[idx] = j[better] + s
            best_u[idx] = u[rows, j][better]
            best_v[idx] = v[rows, j][better]
    return best_t, best_id, best_u, best_v, p * m, 0


class BVH:
    r"""A bounding volume hierarchy over triangles, built and traversed with numpy arrays.

    **Build** (once, :math:`O(P \log P)`): start with all triangles in the root; split every
    node's triangles at the *median* of their box centres along the axis where those centres
    spread most (an object-median split: balanced, depth :math:`\lceil \log_2(P /
    \text{leaf size}) \rceil`), until at most `leaf_size` triangles remain. All nodes of a level
    are split at once (one sort of all triangles by (node, centre) per level), so the build is
    vectorized. Each node stores the axis-aligned box of its triangles, padded by a hair
    (:math:`10^{-9}` of the coordinates' size) so that rounding never loses a hit.

    **Traversal** (:meth:`intersect`), for all rays at once: every ray keeps its own stack of
    nodes still to visit, and all stacks live in one numpy array. Each step pops one node per
    ray: a node whose box starts beyond the nearest hit found so far is skipped; at a leaf its
    triangles are tested (Möller-Trumbore); at an inner node both children's boxes are tested
    (the slab method) and the children hit are pushed, the farther first, so that the nearer
    one is visited first and its hits prune the other. The Python loop runs once per step (a
    few dozen to a few hundred steps), never once per ray or per node.

    The answer equals brute force exactly: the same nearest triangle, the same :math:`t`, u and
    v bit for bit, the lowest index among equally near triangles. Only the work differs: about
    :math:`O(\log P)` box tests and a few triangle tests per ray instead of :math:`P` triangle
    tests.

    Parameters
    ----------
    triangles : array_like, shape (m, 3, 3)
    leaf_size : int, optional
        At most this many triangles per leaf (default 4).

    Attributes
    ----------
    triangles : ndarray, shape (m, 3, 3)
    lo, hi : ndarray, shape (nodes, 3)
        The nodes' boxes; node 0 is the root.
    children : ndarray of int, shape (nodes, 2)
        The two children of each inner node (always consecutive numbers); -1 for leaves.
    leaves : list of ndarray
        ``leaves[k]`` holds the triangle indices of node k (empty for inner nodes).
    depth : int
        Levels below the root.

    Raises
    ------
    ValueError
        For malformed or empty triangles, NaN, or a leaf size below 1.

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> tris = rng.uniform(-1, 1, (2000, 1, 3)) + 0.05 * rng.normal(size=(2000, 3, 3))
    >>> bvh = BVH(tris)
    >>> o, d = np.zeros((500, 3)) + [0, 0, 5], rng.normal(size=(500, 3)) * 0.1 - [0, 0, 1]
    >>> fast = bvh.intersect(o, d)
    >>> slow = intersect_triangles(o, d, tris, accelerate=False)
    >>> bool(np.array_equal(fast.ids, slow.ids) and np.array_equal(fast.t, slow.t))
    True
    >>> fast.triangle_tests < slow.triangle_tests / 50      # 1,000,000 tests by brute force
    True
    """

    def __init__(self, triangles, leaf_size=4):
        tris = _triangles(triangles)
        self.leaf_size = _whole(leaf_size, "leaf_size", 1)
        self.triangles = tris
        self._soa = _soa(tris)
        self._normals = _unit_face_normals(tris)
        self._build()

    def _build(self):
        tris, leaf_size = self.triangles, self.leaf_size
        m = len(tris)
        tmin, tmax = tris.min(axis=1), tris.max(axis=1)
        centre = (tmin + tmax) / 2
        pad = 1e-9 * max(float(np.abs(tris).max()), 1e-300)
        n_max = 2 * m
        lo, hi = np.zeros((n_max, 3)), np.zeros((n_max, 3))
        children = np.full((n_max, 2), -1, dtype=np.intp)
        leaf_row = np.full(n_max, -1, dtype=np.intp)
        rows = []
        order = np.arange(m)
        # the segments of `order` that tile [0, m): one per node of the current level, plus the
        # leaves of earlier levels ("done"), which are carried along unchanged
        starts, ends = np.array([0]), np.array([m])
        node = np.array([0])
        done = np.array([False])
        n_nodes, n_rows, depth = 1, 0, 0
        while True:
            count = ends - starts
            seg = np.repeat(np.arange(len(starts)), count)
            box_lo = np.minimum.reduceat(tmin[order], starts)
            box_hi = np.maximum.reduceat(tmax[order], starts)
            now = ~done
            lo[node[now]] = box_lo[now] - pad
            hi[node[now]] = box_hi[now] + pad
            leaf = now & (count <= leaf_size)
            if leaf.any():
                k = np.nonzero(leaf)[0]
                table = np.full((len(k), leaf_size), m, dtype=np.intp)
                at = leaf[seg]
                slot = np.cumsum(leaf) - 1
                table[slot[seg[at]], np.arange(m)[at] - starts[seg[at]]] = order[at]
                table.sort(axis=1)                      # lowest index first within a leaf
                leaf_row[node[k]] = n_rows + np.arange(len(k))
                n_rows += len(k)
                rows.append(table)
            split = now & ~leaf
            done = done | leaf
            if not split.any():
                break
            depth += 1
            c_lo = np.minimum.reduceat(centre[order], starts)
            c_hi = np.maximum.reduceat(centre[order], starts)
            axis = np.argmax(c_hi - c_lo, axis=1)
            key = centre[order, axis[seg]]
            order = order[np.lexsort((key, seg))]     # sorted by centre within each segment
            k = np.nonzero(split)[0]
            mid = (starts[k] + ends[k]) // 2
            first = n_nodes + 2 * np.arange(len(k))
            n_nodes += 2 * len(k)
            children[node[k], 0] = first
            children[node[k], 1] = first + 1
            keep = ~split
            starts = np.concatenate([starts[keep], starts[k], mid])
            ends = np.concatenate([ends[keep], mid, ends[k]])
            node = np.concatenate([node[keep], first, first + 1])
            done = np.concatenate([done[keep], np.zeros(2 * len(k), dtype=bool)])
            by_start = np.argsort(starts, kind="stable")
            starts, ends, node, done = starts[by_start], ends[by_start], node[by_start], \
                done[by_start]
        self.lo, self.hi = lo[:n_nodes], hi[:n_nodes]
        self.children = children[:n_nodes]
        self.depth = depth
        self._leaf_row = leaf_row[:n_nodes]
        self._leaf_table = np.concatenate(rows)
        # the boxes of both children of every node in one row: 12 numbers, gathered at once
        c0 = np.where(self.children[:, 0] >= 0, self.children[:, 0], 0)
        c1 = np.where(self.children[:, 1] >= 0, self.children[:, 1], 0)
        self._child_boxes = np.ascontiguousarray(
            np.concatenate([self.lo[c0].T, self.hi[c0].T, self.lo[c1].T, self.hi[c1].T]))

    @property
    def leaves(self):
        m = len(self.triangles)
        return [self._leaf_table[r][self._leaf_table[r] < m] if r >= 0
                else np.zeros(0, dtype=np.intp) for r in self._leaf_row]

    def __repr__(self):
        return (f"BVH({len(self.triangles)} triangles, {len(self.lo)} nodes, depth {self.depth}, "
                f"leaf size {self.leaf_size})")

    def intersect(self, origins, directions, t_min=0.0, t_max=np.inf, any_hit=False):
        r"""The nearest triangle hit by each ray, by traversing the hierarchy.

        Parameters
        ----------
        origins, directions : array_like, shape (..., 3)
        t_min, t_max : float, optional
            Only hits with :math:`t_{min} \le t \le t_{max}` count.
        any_hit : bool, optional
            Stop each ray at the first hit found, nearest or not (enough for a shadow ray,
            which only asks *whether* something is in the way): ``t`` and ``ids`` are then
            *a* hit, not necessarily the nearest.

        Returns
        -------
        TriangleHits

        Raises
        ------
        ValueError
            For zero directions, NaN, malformed shapes, or ``t_max < t_min``.

        Examples
        --------
        Two parallel triangles; the ray from above hits the upper one first:

        >>> tris = [[[-1, -1, 0], [1, -1, 0], [0, 1, 0]], [[-1, -1, 2], [1, -1, 2], [0, 1, 2]]]
        >>> hits = BVH(tris, leaf_size=1).intersect([[0, 0, 5], [9, 9, 5]], [0, 0, -1])
        >>> hits.t, hits.ids, hits.box_tests
        (array([ 3., inf]), array([ 1, -1]), 4)
        """
        o, d, lead = _rays(origins, directions)
        t_min = _t_min(t_min)
        t_max = _t_max(t_max, t_min)
        t, ids, u, v, tri_tests, box_tests = self._intersect(o, d, t_min, np.full(len(o), t_max),
                                                             any_hit)
        return _triangle_hits(t, ids, u, v, self._normals, lead, tri_tests, box_tests)

    def _intersect(self, o, d, t_min, t_max, any_hit=False, chunk=1 << 17):
        """Traversal in chunks of rays (bounded memory); t_max is an array (p,)."""
        p = len(o)
        out = [np.full(p, np.inf), np.full(p, -1, dtype=np.intp), np.zeros(p), np.zeros(p)]
        tri_tests = box_tests = 0
        for s in range(0, p, chunk):
            res = self._traverse(o[s:s + chunk], d[s:s + chunk], t_min, t_max[s:s + chunk],
                                 any_hit)
            for arr, part in zip(out, res[:4]):
                arr[s:s + chunk] = part
            tri_tests += res[4]
            box_tests += res[5]
        return (*out, tri_tests, box_tests)

    def _traverse(self, o, d, t_min, t_max, any_hit):
        p = len(o)
        m = len(self.triangles)
        ot = np.ascontiguousarray(o.T)
        dt = np.ascontiguousarray(d.T)
        # 1/d with zero components replaced by a tiny positive number: the slab of a parallel
        # ray then spans (-huge, +huge) or lies wholly on one side, as it should (no 0 * inf)
        inv = 1.0 / np.where(dt == 0, 1e-300, dt)
        best_t = np.full(p, np.inf)
        best_id = np.full(p, -1, dtype=np.intp)
        best_u, best_v = np.zeros(p), np.zeros(p)
        depth = self.depth + 2
        stack_node = np.zeros(p * depth, dtype=np.intp)
        stack_t = np.zeros(p * depth)
        base = np.arange(p) * depth
        top = base.copy()                              # next free slot of each ray's stack
        lo, hi = self.lo[0], self.hi[0]
        tri_tests = 0
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            t1, t2 = (lo[:, None] - ot) * inv, (hi[:, None] - ot) * inv
            t_in = np.maximum(np.minimum(t1, t2).max(axis=0), t_min)
            t_out = np.minimum(np.maximum(t1, t2).min(axis=0), t_max)
            active = np.nonzero(t_in <= t_out)[0]
            stack_t[base[active]] = t_in[active]        # the root, node 0
            top[active] += 1
            box_tests = p
            leaf_row, table, boxes, first_child = (self._leaf_row, self._leaf_table,
                                                   self._child_boxes, self.children[:, 0])
            while active.size:
                top[active] -= 1
                slot = top[active]
                nodes = stack_node[slot]
                live = stack_t[slot] <= best_t[active]  # skip boxes beyond the nearest hit
                rays, nodes = active[live], nodes[live]
                rows = leaf_row[nodes]
                at_leaf = rows >= 0
                if at_leaf.any():
                    r = rays[at_leaf]
                    tri = table[rows[at_leaf]]                                 # (k, leaf_size)
                    t, u, v = _moller_trumbore(ot[:, r, None], dt[:, r, None], self._soa[:, tri])
                    t[(t < t_min) | (t > t_max[r, None])] = np.inf
                    tri_tests += int(np.count_nonzero(tri < m))
                    j = np.argmin(t, axis=1)
                    k = np.arange(len(r))
                    tj, idj = t[k, j], tri[k, j]
                    better = (tj < best_t[r]) | ((tj == best_t[r]) & (idj < best_id[r])
                                                 & np.isfinite(tj))
                    rb = r[better]
                    best_t[rb], best_id[rb] = tj[better], idj[better]
                    best_u[rb], best_v[rb] = u[k, j][better], v[k, j][better]
                    if any_hit:
                        top[rb] = base[rb]              # done: forget the rest of the stack
                if not at_leaf.all():
                    inner = ~at_leaf
                    r, n = rays[inner], nodes[inner]
                    b = boxes[:, n]
                    o_r, i_r = ot[:, r], inv[:, r]
                    bound = np.minimum(best_t[r], t_max[r])
                    near = []
                    hit = []
                    for c in (0, 6):                    # the slab test of both children
                        a1 = (b[c] - o_r[0]) * i_r[0]
                        a2 = (b[c + 3] - o_r[0]) * i_r[0]
                        t_in, t_out = np.minimum(a1, a2), np.maximum(a1, a2)
                        for axis in (1, 2):
                            a1 = (b[c + axis] - o_r[axis]) * i_r[axis]
                            a2 = (b[c + 3 + axis] - o_r[axis]) * i_r[axis]
                            np.maximum(t_in, np.minimum(a1, a2), out=t_in)
                            np.minimum(t_out, np.maximum(a1, a2), out=t_out)
                        np.maximum(t_in, t_min, out=t_in)
                        near.append(t_in)
                        hit.append(t_in <= np.minimum(t_out, bound))
                    box_tests += 2 * len(r)
                    second_first = near[1] < near[0]            # child 1 is the nearer one
                    first = first_child[n]
                    # push the farther child, then the nearer one (popped first)
                    for is_second, h, t_push in (
                            (~second_first, np.where(second_first, hit[0], hit[1]),
                             np.where(second_first, near[0], near[1])),
                            (second_first, np.where(second_first, hit[1], hit[0]),
                             np.where(second_first, near[1], near[0]))):
                        rr = r[h]
                        pos = top[rr]
                        stack_node[pos] = (first + is_second)[h]
                        stack_t[pos] = t_push[h]
                        top[rr] = pos + 1
                active = active[top[active] > base[active]]
        return best_t, best_id, best_u, best_v, tri_tests, box_tests


def _triangle_hits(t, ids, u, v, face_normals, lead, tri_tests, box_tests):
    hit = ids >= 0
    normals = np.zeros((len(t), 3))
    normals[hit] = face_normals[ids[hit]]
    u = np.where(hit, u, 0.0)
    v = np.where(hit, v, 0.0)
    return TriangleHits(t.reshape(lead), ids.reshape(lead), u.reshape(lead), v.reshape(lead),
                        normals.reshape(lead + (3,)), int(tri_tests), int(box_tests))


def intersect_triangles(origins, directions, triangles, t_min=0.0, t_max=np.inf,
                        accelerate=True):
    r"""Ray-triangle intersection (Möller-Trumbore) of many rays with many triangles.

    For each ray, solve :math:`o + t\,d = v_0 + u\,(v_1 - v_0) + v\,(v_2 - v_0)` for
    :math:`(t, u, v)` by Cramer's rule, with :math:`e_1 = v_1 - v_0`, :math:`e_2 = v_2 - v_0`,
    :math:`s = o - v_0`, :math:`p = d \times e_2`, :math:`q = s \times e_1`:

    .. math:: \begin{bmatrix} t \\ u \\ v \end{bmatrix} = \frac{1}{p \cdot e_1}
              \begin{bmatrix} q \cdot e_2 \\ p \cdot s \\ q \cdot d \end{bmatrix}

    The ray hits when :math:`u \ge 0`, :math:`v \ge 0`, :math:`u + v \le 1` (inside the
    triangle), :math:`p \cdot e_1 \ne 0` (not parallel to its plane) and :math:`t_{min} \le t
    \le t_{max}`; both sides of a triangle are hit. The nearest hit over all triangles is
    kept (the lowest index among equal :math:`t`). Brute force costs rays x triangles tests;
    with `accelerate` a :class:`BVH` is built (:math:`O(P \log P)`, once; pass a ready
    :class:`BVH` as `triangles` to reuse it) and the answer is exactly the same, with far
    fewer tests.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    triangles : array_like, shape (m, 3, 3), or BVH
    t_min, t_max : float, optional
    accelerate : bool, optional
        Build a BVH (default True). Ignored when `triangles` is a BVH.

    Returns
    -------
    TriangleHits
        ``t, ids, u, v, normals`` and the numbers of triangle and box tests.

    Raises
    ------
    ValueError
        For zero directions, NaN, malformed or empty triangles, a negative `t_min` or
        ``t_max < t_min``.

    Examples
    --------
    >>> tri = [[[0, 0, 0], [1, 0, 0], [0, 1, 0]]]
    >>> hits = intersect_triangles([[0.2, 0.3, 1], [0.9, 0.9, 1]], [0, 0, -1], tri,
    ...                            accelerate=False)
    >>> hits.t, hits.ids, hits.u, hits.v
    (array([ 1., inf]), array([ 0, -1]), array([0.2, 0. ]), array([0.3, 0. ]))
    """
    o, d, lead = _rays(origins, directions)
    t_min = _t_min(t_min)
    t_max = np.full(len(o), _t_max(t_max, t_min))
    if isinstance(triangles, BVH):
        bvh = triangles
    elif accelerate:
        bvh = BVH(triangles)
    else:
        tris = _triangles(triangles)
        res = _brute_force(o, d, _soa(tris), t_min, t_max)
        return _triangle_hits(*res[:4], _unit_face_normals(tris), lead, *res[4:])
    res = bvh._intersect(o, d, t_min, t_max)
    return _triangle_hits(*res[:4], bvh._normals, lead, *res[4:])


# ---------------------------------------------------------------------------------------------
# The camera: one ray per pixel sample
# ---------------------------------------------------------------------------------------------

class CameraRays(NamedTuple):
    """The rays of :func:`camera_rays`: shapes (height, width, samples, 3), row 0 at the bottom.

    Attributes
    ----------
    origins : ndarray, shape (height, width, samples, 3)
        All equal to the eye (a pinhole camera).
    directions : ndarray, shape (height, width, samples, 3)
        Unit vectors through the sample positions.

    Examples
    --------
    >>> rays = camera_rays([0, 0, 5], [0, 0, -1], [0, 1, 0], np.radians(90), 2, 2)
    >>> rays.directions.shape
    (2, 2, 1, 3)
    """
    origins: np.ndarray
    directions: np.ndarray


def _samples_per_pixel(value):
    s = _whole(value, "samples_per_pixel", 1)
    k = int(round(np.sqrt(s)))
    if k * k != s:
        raise ValueError(f"samples_per_pixel must be a perfect square (1, 4, 9, 16, ...) so that "
                         f"the samples form a k x k grid in each pixel, got {s}")
    return s, k


def camera_rays(eye, gaze, up, fov_y, width, height, samples_per_pixel=1, seed=None,
                jitter=False):
    r"""The primary rays of a pinhole camera: one per pixel sample, through the image plane.

    The camera is that of :func:`course_lib.viewing.look_at` (the eye at `eye`, looking along
    `gaze`, `up` giving the roll) and :func:`course_lib.viewing.perspective` (vertical field of
    view `fov_y`, aspect ``width / height``). A sample at viewport position :math:`(x, y)`
    (pixel :math:`(j, i)` covers :math:`[i, i+1] \times [j, j+1]`) has canonical coordinates
    :math:`x_c = 2x/W - 1`, :math:`y_c = 2y/H - 1`, and undoing the projection gives its
    direction in eye coordinates

    .. math:: d_e = \left(\frac{x_c}{P_{00}}, \frac{y_c}{P_{11}}, -1\right), \qquad
              P_{11} = \cot\frac{\theta}{2}, \quad P_{00} = \frac{P_{11}}{\text{aspect}}

    (the point of the near plane at distance 1 that projects there), turned into world
    coordinates with the transpose of the view rotation: :math:`d = x_e\, d_{e,x} + y_e\,
    d_{e,y} + z_e\, d_{e,z}`, then normalized. So a point along the ray projects (with
    :func:`course_lib.viewing.to_screen`) exactly onto the sample.

    **Supersampling**: with ``samples_per_pixel = k * k`` each pixel is divided into a k x k grid
    of sub-pixels; a sample sits at the centre of its sub-pixel (a regular grid), or, with
    ``jitter=True``, at a uniformly random position inside it (stratified sampling). One
    sample per pixel without jitter is the pixel centre :math:`(i + \tfrac12, j + \tfrac12)`.

    Parameters
    ----------
    eye, gaze, up : array_like, shape (3,)
        As for :func:`course_lib.viewing.look_at` (`gaze` is a direction, not a target point).
    fov_y : float
        Vertical field of view in radians, in (0, pi).
    width, height : int
        Image size in pixels.
    samples_per_pixel : int, optional
        A perfect square (1, 4, 9, ...).
    seed : int, numpy.random.Generator or None, optional
        Randomness for `jitter`.
    jitter : bool, optional
        Jitter each sample within its sub-pixel.

    Returns
    -------
    CameraRays
        ``origins`` and unit ``directions``, shape (height, width, samples, 3). **Row 0 is the
        bottom row** of the image; sample ``s = a * k + b`` is in sub-pixel row a (from the
        bottom) and column b.

    Raises
    ------
    ValueError
        For `fov_y` outside (0, pi), `up` parallel to `gaze`, zero vectors, a non-positive or
        fractional size, or a sample count that is not a perfect square.

    Examples
    --------
    A 90 degree camera on a 2 x 2 image: the pixel centres are at canonical (+-1/2, +-1/2); the
    top-right pixel (row 1, column 1) looks right, up and forwards:

    >>> rays = camera_rays([0, 0, 5], [0, 0, -1], [0, 1, 0], np.radians(90), 2, 2)
    >>> (rays.directions[1, 1, 0] * np.sqrt(6)).round(12)     # (0.5, 0.5, -1) normalized
    array([ 1.,  1., -2.])
    """
    view = viewing.look_at(eye, gaze, up)
    fov = as_scalar(fov_y, "fov_y")
    if not 0 < fov < np.pi:
        raise ValueError(f"fov_y must be an angle in radians between 0 and pi, got {fov}")
    w = _whole(width, "width", 1)
    h = _whole(height, "height", 1)
    s, k = _samples_per_pixel(samples_per_pixel)
    proj = viewing.perspective(fov, w / h, 1.0, 2.0)
    a, b = np.divmod(np.arange(s), k)                       # sub-pixel row a, column b
    if jitter:
        rng = np.random.default_rng(seed)
        sx = (b + rng.random((h, w, s))) / k
        sy = (a + rng.random((h, w, s))) / k
    else:
        sx = np.broadcast_to((b + 0.5) / k, (h, w, s))
        sy = np.broadcast_to((a + 0.5) / k, (h, w, s))
    x = (np.arange(w)[None, :, None] + sx) * (2.0 / w) - 1.0
    y = (np.arange(h)[:, None, None] + sy) * (2.0 / h) - 1.0
    axes = view[:3, :3]                                     # rows: x_e, y_e, z_e in the world
    d = ((x / proj[0, 0])[..., None] * axes[0] + (y / proj[1, 1])[..., None] * axes[1]
         - axes[2])
    d /= np.sqrt(_dot(d, d))[..., None]
    origins = np.broadcast_to(as_vector(eye, "eye", 3), d.shape).copy()
    return CameraRays(origins, d)


@dataclass(frozen=True, eq=False)
class Camera:
    """A pinhole camera: where it is, where it looks, its field of view and image size.

    See :func:`camera_rays` for the rays it shoots (row 0 of the image at the bottom).

    Attributes
    ----------
    eye, gaze, up : array_like, shape (3,)
        Position, viewing direction, and the up direction (not parallel to `gaze`).
    fov_y : float
        Vertical field of view in radians, in (0, pi).
    width, height : int
        Image size in pixels.

    Examples
    --------
    >>> cam = Camera([0, 1, 5], [0, 0, -1], [0, 1, 0], np.radians(45), 64, 48)
    >>> cam.rays().directions.shape, cam.rays(samples_per_pixel=4).directions.shape
    ((48, 64, 1, 3), (48, 64, 4, 3))
    >>> origin, direction = cam.pixel_ray(24, 32)      # just above and right of the centre
    >>> bool(np.allclose(direction, cam.rays().directions[24, 32, 0]))
    True
    """
    eye: object
    gaze: object
    up: object
    fov_y: float
    width: int
    height: int

    def __post_init__(self):
        viewing.look_at(self.eye, self.gaze, self.up)           # checks eye, gaze and up
        fov = as_scalar(self.fov_y, "fov_y")
        if not 0 < fov < np.pi:
            raise ValueError(f"fov_y must be an angle in radians between 0 and pi, got {fov}")
        object.__setattr__(self, "eye", as_vector(self.eye, "eye", 3))
        object.__setattr__(self, "gaze", as_vector(self.gaze, "gaze", 3))
        object.__setattr__(self, "up", as_vector(self.up, "up", 3))
        object.__setattr__(self, "fov_y", fov)
        object.__setattr__(self, "width", _whole(self.width, "width", 1))
        object.__setattr__(self, "height", _whole(self.height, "height", 1))

    def rays(self, samples_per_pixel=1, seed=None, jitter=False):
        """The camera's rays, :func:`camera_rays` with its parameters."""
        return camera_rays(self.eye, self.gaze, self.up, self.fov_y, self.width, self.height,
                           samples_per_pixel, seed, jitter)

    def resized(self, width, height):
        """The same camera with another image size."""
        return Camera(self.eye, self.gaze, self.up, self.fov_y, width, height)

    def pixel_ray(self, row, column):
        """The ray through the centre of pixel (`row`, `column`), row 0 at the bottom: the
        primary ray of :func:`trace_tree` for that pixel.

        Returns ``(origin, direction)``, both shape (3,), the direction a unit vector (the same
        ray as ``self.rays()`` gives for that pixel). Raises ValueError for a pixel outside the
        image.
        """
        j = _whole(row, "row", 0)
        i = _whole(column, "column", 0)
        if j >= self.height or i >= self.width:
            raise ValueError(f"pixel (row {j}, column {i}) lies outside the {self.width} x "
                             f"{self.height} image (rows 0..{self.height - 1}, columns "
                             f"0..{self.width - 1})")
        proj = viewing.perspective(self.fov_y, self.width / self.height, 1.0, 2.0)
        axes = viewing.look_at(self.eye, self.gaze, self.up)[:3, :3]
        x = (i + 0.5) * (2.0 / self.width) - 1.0
        y = (j + 0.5) * (2.0 / self.height) - 1.0
        d = (x / proj[0, 0]) * axes[0] + (y / proj[1, 1]) * axes[1] - axes[2]
        return self.eye.copy(), d / np.sqrt(d @ d)


# ---------------------------------------------------------------------------------------------
# Scenes: materials, objects, lights
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class Material:
    r"""A surface for the ray tracer: Phong coefficients plus reflection and refraction.

    The local colour is the Phong model (:func:`course_lib.shading.phong`) with the
    coefficients of `phong`; then a fraction :math:`k_r` (`reflectivity`) of the light seen in
    the mirror direction is added, and for a transparent material (`transparency` :math:`k_t >
    0`) the light seen through it, bent by Snell's law with the refractive index `ior`, split by
    Schlick's Fresnel factor :math:`F` into :math:`k_t F` (reflected) and :math:`k_t (1 - F)`
    (refracted). :math:`k_r + k_t \le 1` keeps a surface from returning more light than it
    receives. Glass: small diffuse and ambient coefficients, a highlight, :math:`k_t` near 1,
    index 1.5; a mirror: :math:`k_r` near 1.

    Attributes
    ----------
    phong : course_lib.shading.Material
        One colour per coefficient (e.g. from :func:`course_lib.shading.colored_material`).
    reflectivity : float
        :math:`k_r \in [0, 1]` (default 0).
    transparency : float
        :math:`k_t \in [0, 1]` (default 0).
    ior : float
        Refractive index, positive (default 1; glass 1.5, water 1.33, diamond 2.42).

    Examples
    --------
    >>> glass = Material(shading.Material(ka=0.0, kd=0.05, ks=0.5, shininess=100),
    ...                  transparency=0.9, ior=1.5)
    >>> glass.transparency, glass.ior
    (0.9, 1.5)
    """
    phong: shading.Material = shading.Material()
    reflectivity: float = 0.0
    transparency: float = 0.0
    ior: float = 1.0

    def __post_init__(self):
        if not isinstance(self.phong, shading.Material):
            raise TypeError(f"phong must be a course_lib.shading.Material, got "
                            f"{type(self.phong).__name__}")
        shading.material_per_point([self.phong], [0])     # checks the coefficients
        kr = as_scalar(self.reflectivity, "reflectivity")
        kt = as_scalar(self.transparency, "transparency")
        for k, name in ((kr, "reflectivity"), (kt, "transparency")):
            if not 0 <= k <= 1:
                raise ValueError(f"{name} must lie in [0, 1], got {k:g}")
        if kr + kt > 1 + 1e-12:
            raise ValueError(f"reflectivity + transparency must not exceed 1 (a surface cannot "
                             f"return more light than it receives), got {kr:g} + {kt:g}")
        object.__setattr__(self, "reflectivity", kr)
        object.__setattr__(self, "transparency", kt)
        object.__setattr__(self, "ior", _positive(self.ior, "ior",
                                                  "positive (a refractive index)"))


@dataclass(frozen=True, eq=False)
class Sphere:
    """A sphere: centre, radius and material.

    Attributes
    ----------
    center : array_like, shape (3,)
    radius : float
        Positive.
    material : Material

    Examples
    --------
    >>> Sphere([0, 1, 0], 1.0).radius
    1.0
    """
    center: object
    radius: float
    material: Material = Material()

    def __post_init__(self):
        object.__setattr__(self, "center", as_vector(self.center, "center", 3))
        object.__setattr__(self, "radius", _positive(self.radius, "radius",
                                                     "positive (the sphere's radius)"))
        _check_material(self.material)


@dataclass(frozen=True, eq=False)
class Plane:
    """An infinite plane, optionally with a checkerboard of two materials.

    Attributes
    ----------
    point : array_like, shape (3,)
        A point of the plane (also a corner of the checkerboard's squares).
    normal : array_like, shape (3,)
        Its normal (normalized here): the "outside" for refraction.
    material : Material
    checker : Material or None
        The material of every other square of a checkerboard, or None for a plain plane.
    checker_size : float
        The squares' side (positive).

    Examples
    --------
    >>> Plane([0, 0, 0], [0, 2, 0]).normal
    array([0., 1., 0.])
    """
    point: object
    normal: object
    material: Material = Material()
    checker: object = None
    checker_size: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "point", as_vector(self.point, "point", 3))
        object.__setattr__(self, "normal",
                           _unit_vectors(as_vector(self.normal, "normal", 3), "normal"))
        _check_material(self.material)
        if self.checker is not None:
            _check_material(self.checker, "checker")
        object.__setattr__(self, "checker_size", _positive(self.checker_size, "checker_size"))

    def _axes(self):
        """Two unit vectors spanning the plane: the checkerboard's axes."""
        n = self.normal
        helper = np.eye(3)[int(np.argmin(np.abs(n)))]
        a = np.cross(n, helper)
        a /= np.linalg.norm(a)
        return a, np.cross(n, a)


class Mesh:
    """A triangle mesh with a material and a :class:`BVH` (built once, here).

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
        Counter-clockwise seen from outside (the face normals point outwards).
    material : Material, optional
    smooth : bool, optional
        Shade with vertex normals interpolated across each triangle (Phong's normal
        interpolation, by the hit's barycentric coordinates) instead of the flat face normals.
    leaf_size : int, optional
        Of the BVH.

    Attributes
    ----------
    vertices, faces, material, smooth, bvh
    face_normals, vertex_normals : ndarray

    Raises
    ------
    ValueError
        For malformed vertices or faces.

    Examples
    --------
    >>> from course_lib import shapes
    >>> mesh = Mesh(*shapes.torus(segments=8, rings=4))
    >>> len(mesh.faces), mesh.bvh.depth
    (64, 4)
    """

    def __init__(self, vertices, faces, material=Material(), smooth=True, leaf_size=4):
        self.face_normals = shading.face_normals(vertices, faces)       # checks both
        self.vertex_normals = shading.vertex_normals(vertices, faces)
        self.vertices = as_points(vertices, "vertices", dims=3)
        self.faces = np.asarray(faces).astype(np.intp)
        _check_material(material)
        self.material = material
        self.smooth = bool(smooth)
        self.bvh = BVH(self.vertices[self.faces], leaf_size)

    def __repr__(self):
        return f"Mesh({len(self.vertices)} vertices, {len(self.faces)} faces, smooth={self.smooth})"

    def _shading_normals(self, ids, u, v):
        if not self.smooth:
            return self.face_normals[ids]
        f = self.faces[ids]
        vn = self.vertex_normals
        n = ((1 - u - v)[:, None] * vn[f[:, 0]] + u[:, None] * vn[f[:, 1]]
             + v[:, None] * vn[f[:, 2]])
        length = np.sqrt(_dot(n, n))
        ok = length > 1e-12
        return np.where(ok[:, None], n / np.where(ok, length, 1.0)[:, None],
                        self.face_normals[ids])


def _check_material(material, name="material"):
    if not isinstance(material, Material):
        raise TypeError(f"{name} must be a raytracing.Material, got {type(material).__name__}")


@dataclass(frozen=True, eq=False)
class Scene:
    """What the ray tracer renders: objects, lights, ambient light, background and a camera.

    Attributes
    ----------
    objects : sequence of Sphere, Plane or Mesh
    lights : sequence of course_lib.shading.Light
        From :func:`course_lib.shading.point_light` / :func:`course_lib.shading.directional_light`.
    ambient : float or array_like, shape (3,)
        The ambient intensity :math:`I_a` of the Phong model (default 1: the ambient term is
        then :math:`k_a`).
    background : float or array_like, shape (3,)
        The colour of rays that hit nothing.
    camera : Camera or None
        The default camera of :func:`render`.

    Examples
    --------
    >>> scene = Scene([Sphere([0, 0, 0], 1.0)], [shading.point_light([0, 5, 5])])
    >>> len(scene.objects), scene.background
    (1, array([0., 0., 0.]))
    """
    objects: tuple
    lights: tuple = ()
    ambient: object = 1.0
    background: object = 0.0
    camera: object = None

    def __post_init__(self):
        objects = tuple(self.objects)
        for k, obj in enumerate(objects):
            if not isinstance(obj, (Sphere, Plane, Mesh)):
                raise TypeError(f"objects[{k}] must be a Sphere, Plane or Mesh, got "
                                f"{type(obj).__name__}")
        lights = (self.lights,) if isinstance(self.lights, shading.Light) else tuple(self.lights)
        for k, light in enumerate(lights):
            if not isinstance(light, shading.Light):
                raise TypeError(f"lights[{k}] must be a course_lib.shading.Light (point_light or "
                                f"directional_light), got {type(light).__name__}")
        if self.camera is not None and not isinstance(self.camera, Camera):
            raise TypeError(f"camera must be a Camera or None, got {type(self.camera).__name__}")
        object.__setattr__(self, "objects", objects)
        object.__setattr__(self, "lights", lights)
        object.__setattr__(self, "ambient", _rgb(self.ambient, "ambient"))
        object.__setattr__(self, "background", _rgb(self.background, "background"))


# ---------------------------------------------------------------------------------------------
# The scene as arrays: nearest hits, surface data, shadow-ray transmission
# ---------------------------------------------------------------------------------------------

class _Compiled:
    """A scene turned into arrays once per render: what every generation of rays needs."""

    def __init__(self, scene):
        if not isinstance(scene, Scene):
            raise TypeError(f"scene must be a Scene, got {type(scene).__name__}")
        self.scene = scene
        objects = scene.objects
        materials = []

        def index(material):
            for k, known in enumerate(materials):
                if known is material:
                    return k
            materials.append(material)
            return len(materials) - 1

        self.material_of = np.array([index(obj.material) for obj in objects], dtype=np.intp)
        self.spheres = [(k, obj.center, obj.radius) for k, obj in enumerate(objects)
                        if isinstance(obj, Sphere)]
        self.planes = [(k, obj) for k, obj in enumerate(objects) if isinstance(obj, Plane)]
        self.meshes = [(k, obj) for k, obj in enumerate(objects) if isinstance(obj, Mesh)]
        self.checker_of = {k: index(obj.checker) for k, obj in self.planes
                           if obj.checker is not None}
        self.transparency_of = np.array([obj.material.transparency for obj in objects])
        self.phongs = [m.phong for m in materials]
        self.kr = np.array([m.reflectivity for m in materials])
        self.kt = np.array([m.transparency for m in materials])
        self.ior = np.array([m.ior for m in materials])
        self.centers = np.zeros((len(objects), 3))
        for k, c, _ in self.spheres:
            self.centers[k] = c
        self.lights = scene.lights
        self.ambient = scene.ambient
        self.background = scene.background

    def nearest(self, o, d, t_min=0.0):
        """Nearest object along each ray: t, object (-1: none), and triangle id, u, v."""
        p = len(o)
        t = np.full(p, np.inf)
        obj = np.full(p, -1, dtype=np.intp)
        tri = np.full(p, -1, dtype=np.intp)
        u, v = np.zeros(p), np.zeros(p)
        for k, c, r in self.spheres:
            tk = _first_root(*_sphere_roots(o, d, c, r), t_min)
            closer = tk < t
            t[closer], obj[closer] = tk[closer], k
        for k, plane in self.planes:
            tk = _plane_t(o, d, plane.point, plane.normal, t_min)
            closer = tk < t
            t[closer], obj[closer] = tk[closer], k
        for k, mesh in self.meshes:
            tk, ids, uk, vk, _, _ = mesh.bvh._intersect(o, d, t_min, t)
            closer = tk < t
            t[closer], obj[closer], tri[closer] = tk[closer], k, ids[closer]
            u[closer], v[closer] = uk[closer], vk[closer]
        return t, obj, tri, u, v

    def surface(self, o, d, t, obj, tri, u, v):
        """Hit points, outward geometric normals, shading normals and material indices."""
        points = o + t[:, None] * d
        normals = np.zeros_like(points)
        mat = self.material_of[obj]
        is_sphere = np.isin(obj, [k for k, _, _ in self.spheres])
        if is_sphere.any():
            n = points[is_sphere] - self.centers[obj[is_sphere]]
            normals[is_sphere] = n / np.sqrt(_dot(n, n))[:, None]
        shading_normals = normals
        for k, plane in self.planes:
            at = obj == k
            normals[at] = plane.normal
            if k in self.checker_of and at.any():
                a, b = plane._axes()
                rel = points[at] - plane.point
                parity = (np.floor(rel @ a / plane.checker_size)
                          + np.floor(rel @ b / plane.checker_size)) % 2 == 1
                mat[np.nonzero(at)[0][parity]] = self.checker_of[k]
        if self.meshes:
            shading_normals = normals.copy()
            for k, mesh in self.meshes:
                at = obj == k
                normals[at] = mesh.face_normals[tri[at]]
                shading_normals[at] = mesh._shading_normals(tri[at], u[at], v[at])
        return points, normals, shading_normals, mat

    def transmission(self, o, d, t_max):
        """Fraction of light passing along shadow rays up to t_max: the product of the
        transparencies of the objects in the way (0 as soon as an opaque one blocks)."""
        trans = np.ones(len(o))
        for k, c, r in self.spheres:
            blocked = _before(_first_root(*_sphere_roots(o, d, c, r), 0.0), t_max)
            trans[blocked] *= self.transparency_of[k]
        for k, plane in self.planes:
            blocked = _before(_plane_t(o, d, plane.point, plane.normal, 0.0), t_max)
            trans[blocked] *= self.transparency_of[k]
        for k, mesh in self.meshes:
            open_ = np.nonzero(trans > 0)[0]
            if open_.size:
                ids = mesh.bvh._intersect(o[open_], d[open_], 0.0, t_max[open_], any_hit=True)[1]
                trans[open_[ids >= 0]] *= self.transparency_of[k]
        return trans


class _Generation(NamedTuple):
    """What tracing one generation of rays gives (see _generation)."""
    local: np.ndarray          # (k, 3) local colour of each ray (background on a miss)
    hit: np.ndarray            # (k,) bool
    t: np.ndarray
    objects: np.ndarray
    points: np.ndarray         # (k, 3), nan on a miss
    normals: np.ndarray        # (k, 3) shading normals facing the ray, 0 on a miss
    children: list             # (kind, parent rows, origins, directions, factors)
    shadow_rays: int
    shadows: list              # (light, parent rows, origins, directions, visibility)


def _generation(c, o, d, spawn, shadows, eps, record=False):
    """Trace one generation of rays (unit directions): nearest hits, shadow rays, Phong,
    and the reflected and refracted rays of the next generation with their weight factors."""
    k = len(o)
    t, obj, tri, u, v = c.nearest(o, d)
    hit = obj >= 0
    local = np.empty((k, 3))
    local[:] = c.background
    points = np.full((k, 3), np.nan)
    facing = np.zeros((k, 3))
    children, shadow_records, n_shadow = [], [], 0
    rows = np.nonzero(hit)[0]
    if rows.size == 0:
        return _Generation(local, hit, t, obj, points, facing, children, 0, shadow_records)
    dd = d[rows]
    p, ng, ns, mat = c.surface(o[rows], dd, t[rows], obj[rows], tri[rows], u[rows], v[rows])
    nf = np.where((_dot(ns, dd) > 0)[:, None], -ns, ns)      # shading normal facing the ray
    ngf = np.where((_dot(ng, dd) > 0)[:, None], -ng, ng)     # geometric normal facing it
    visibility = None
    if shadows and c.lights:
        visibility = np.ones((len(rows), len(c.lights)))
        for j, light in enumerate(c.lights):
            if light.position is None:
                to_light = np.broadcast_to(light.direction, p.shape)
                dist = np.full(len(p), np.inf)
            else:
                to_light = light.position - p
                dist = np.sqrt(_dot(to_light, to_light))
                to_light = to_light / np.where(dist > 0, dist, 1.0)[:, None]
            cast = np.nonzero(_dot(nf, to_light) > 0)[0]    # lights behind add nothing anyway
            s_origin = p[cast] + eps * ngf[cast]
            s_dir = np.ascontiguousarray(to_light[cast])
            visibility[cast, j] = c.transmission(s_origin, s_dir, dist[cast])
            n_shadow += len(cast)
            if record:
                shadow_records.append((j, rows[cast], s_origin, s_dir, visibility[cast, j]))
    terms = shading.phong(p, nf, -dd, c.lights, shading.material_per_point(c.phongs, mat),
                          ambient=c.ambient, light_visibility=visibility, two_sided=True)
    local[rows] = terms.total
    points[rows] = p
    facing[rows] = nf
    if spawn:
        kr, kt, ior = c.kr[mat], c.kt[mat], c.ior[mat]
        d_dot_n = _dot(dd, nf)
        entering = _dot(dd, ng) < 0                          # from outside into the object
        eta1 = np.where(entering, 1.0, ior)
        eta2 = np.where(entering, ior, 1.0)
        fres = np.zeros(len(rows))
        clear = kt > 0
        if clear.any():
            fres[clear] = _schlick(np.clip(-d_dot_n[clear], 0.0, 1.0), eta1[clear], eta2[clear])
        f_reflect = kr + kt * fres
        f_refract = kt * (1.0 - fres)
        r = np.nonzero(f_reflect > 0)[0]
        if r.size:
            direction = dd[r] - 2.0 * d_dot_n[r, None] * nf[r]
            direction /= np.sqrt(_dot(direction, direction))[:, None]
            children.append(("reflected", rows[r], p[r] + eps * ngf[r], direction, f_reflect[r]))
        r = np.nonzero(f_refract > 0)[0]
        if r.size:
            direction, _ = _refract(dd[r], nf[r], eta1[r], eta2[r])
            children.append(("refracted", rows[r], p[r] - eps * ngf[r], direction, f_refract[r]))
    return _Generation(local, hit, t, obj, points, facing, children, n_shadow, shadow_records)


class SceneHits(NamedTuple):
    """The nearest object along each ray (:func:`intersect_scene`).

    Attributes
    ----------
    t : ndarray, shape (...)
        Distance to the hit (unit directions); ``inf`` for a miss.
    objects : ndarray of int, shape (...)
        Index into ``scene.objects``; -1 for a miss.
    points : ndarray, shape (..., 3)
        Hit points; NaN for a miss.
    normals : ndarray, shape (..., 3)
        Outward geometric unit normals; zero for a miss.

    Examples
    --------
    >>> scene = Scene([Sphere([0, 0, 0], 1.0), Plane([0, -1, 0], [0, 1, 0])])
    >>> intersect_scene(scene, [[0, 0, 5], [0, 0, 5]], [[0, 0, -1], [0, -1, -1]]).objects
    array([0, 1])
    """
    t: np.ndarray
    objects: np.ndarray
    points: np.ndarray
    normals: np.ndarray


def intersect_scene(scene, origins, directions, t_min=0.0):
    r"""The nearest object of a scene along each ray: the ray tracer's visibility question.

    Every object is intersected with every ray (:func:`intersect_sphere`,
    :func:`intersect_plane`, and each mesh through its :class:`BVH`) and the smallest
    :math:`t \ge t_{min}` wins (the earlier object on a tie).

    Parameters
    ----------
    scene : Scene
    origins, directions : array_like, shape (..., 3)
        Directions are normalized here, so ``t`` is a distance.
    t_min : float, optional

    Returns
    -------
    SceneHits

    Raises
    ------
    ValueError
        For zero directions, NaN or malformed shapes.
    TypeError
        If `scene` is not a Scene.

    Examples
    --------
    >>> scene = Scene([Sphere([0, 0, 0], 1.0)])
    >>> hits = intersect_scene(scene, [0, 0, 5], [0, 0, -2])
    >>> float(hits.t), int(hits.objects), hits.normals
    (4.0, 0, array([0., 0., 1.]))
    """
    c = _Compiled(scene)
    o, d, lead = _rays(origins, directions)
    d = d / np.sqrt(_dot(d, d))[:, None]
    t_min = _t_min(t_min)
    t, obj, tri, u, v = c.nearest(o, d, t_min)
    points = np.full_like(o, np.nan)
    normals = np.zeros_like(o)
    rows = np.nonzero(obj >= 0)[0]
    if rows.size:
        p, n, _, _ = c.surface(o[rows], d[rows], t[rows], obj[rows], tri[rows], u[rows], v[rows])
        points[rows], normals[rows] = p, n
    return SceneHits(t.reshape(lead), obj.reshape(lead), points.reshape(lead + (3,)),
                     normals.reshape(lead + (3,)))


# ---------------------------------------------------------------------------------------------
# Whitted ray tracing
# ---------------------------------------------------------------------------------------------

class RayCounts(NamedTuple):
    """How many rays of each kind :func:`render` traced.

    Attributes
    ----------
    primary : int
        Camera rays (pixels x samples per pixel).
    shadow : int
        Shadow rays (one per hit and light in front of the surface).
    reflected, refracted : int
        Secondary rays, over all generations.

    Examples
    --------
    >>> RayCounts(100, 80, 10, 5).total
    195
    """
    primary: int
    shadow: int
    reflected: int
    refracted: int

    @property
    def total(self):
        return self.primary + self.shadow + self.reflected + self.refracted


def _render_options(max_depth, epsilon, min_weight):
    depth = _whole(max_depth, "max_depth", 0)
    eps = _positive(epsilon, "epsilon", "positive (the offset of secondary rays)")
    mw = as_scalar(min_weight, "min_weight")
    if not 0 <= mw < 1:
        raise ValueError(f"min_weight must lie in [0, 1), got {mw}")
    return depth, eps, mw


def render(scene, camera=None, max_depth=3, shadows=True, supersampling=1, seed=None,
           jitter=False, epsilon=DEFAULT_EPSILON, min_weight=0.0, return_counts=False):
    r"""Whitted ray tracing of a scene: an image of shape (height, width, 3) in [0, 1].

    For every pixel sample a primary ray is shot (:func:`camera_rays`); at its nearest hit the
    colour is

    .. math:: I = I_{local} + (k_r + k_t F)\, I(\text{reflected}) + k_t (1 - F)\,
              I(\text{refracted})

    with :math:`I_{local}` the Phong model at the hit (:func:`course_lib.shading.phong`, both
    sides of a surface lit), each light's diffuse and specular terms multiplied by the answer of
    its shadow ray (1 lit, 0 blocked, the product of the transparencies :math:`k_t` of the
    objects crossed otherwise), :math:`F` Schlick's Fresnel factor (:func:`schlick`; 0 for
    opaque materials) and the recursion stopped after `max_depth` bounces. A ray that hits
    nothing sees the scene's background.

    **Vectorized by generations** instead of recursion: all primary rays are traced at once;
    the reflected and refracted rays of all their hits form the next generation, each carrying
    its pixel and its weight (the product of the factors on its path), and so on. Each
    generation adds ``weight * local colour`` to its pixels. This computes exactly the
    recursive sum of the ray tree (:func:`trace_tree`), breadth first.

    The pixel value is the mean of its samples, **clamped** to [0, 1] per channel (no tone
    mapping).

    Parameters
    ----------
    scene : Scene
    camera : Camera, optional
        Default: the scene's camera.
    max_depth : int, optional
        Bounces after the primary ray (0: no reflected or refracted rays).
    shadows : bool, optional
        Shoot shadow rays (False: every light is seen from everywhere).
    supersampling : int, optional
        Samples per pixel, a perfect square (1, 4, 9, ...): see :func:`camera_rays`.
    seed, jitter
        Jittered supersampling, see :func:`camera_rays`.
    epsilon : float, optional
        Offset of secondary rays from the surface along its normal (against shadow acne).
    min_weight : float, optional
        Rays whose weight falls below this are not traced (adaptive depth control; default 0:
        only `max_depth` stops the recursion).
    return_counts : bool, optional
        Also return the :class:`RayCounts`.

    Returns
    -------
    image : ndarray, shape (height, width, 3)
        RGB in [0, 1]; **row 0 is the bottom** (``plt.imshow(image, origin="lower")``).
    counts : RayCounts
        Only with `return_counts`.

    Raises
    ------
    ValueError
        For a negative `max_depth`, a non-positive `epsilon`, a bad sample count, or no camera.
    TypeError
        If `scene` is not a Scene or `camera` not a Camera.

    Examples
    --------
    >>> scene = example_scene("spheres")
    >>> image, counts = render(scene, scene.camera.resized(32, 24), return_counts=True)
    >>> image.shape, counts.primary, bool(0 <= image.min() and image.max() <= 1)
    ((24, 32, 3), 768, True)
    """
    c = _Compiled(scene)
    camera = scene.camera if camera is None else camera
    if camera is None:
        raise ValueError("camera must be a Camera (the scene has none: pass one)")
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a Camera, got {type(camera).__name__}")
    depth, eps, min_weight = _render_options(max_depth, epsilon, min_weight)
    rays = camera.rays(supersampling, seed, jitter)
    h, w, s, _ = rays.directions.shape
    o = rays.origins.reshape(-1, 3)
    d = rays.directions.reshape(-1, 3)
    n = len(o)
    colour = np.zeros((n, 3))
    pixel = np.arange(n)
    weight = np.ones(n)
    counts = {"primary": n, "shadow": 0, "reflected": 0, "refracted": 0}
    for level in range(depth + 1):
        g = _generation(c, o, d, level < depth, shadows, eps)
        counts["shadow"] += g.shadow_rays
        contribution = weight[:, None] * g.local
        for channel in range(3):
            colour[:, channel] += np.bincount(pixel, contribution[:, channel], minlength=n)
        parts = []
        for kind, parents, origins, directions, factors in g.children:
            wk = weight[parents] * factors
            keep = wk >= min_weight if min_weight > 0 else slice(None)
            counts[kind] += int(np.count_nonzero(wk[keep] >= 0))
            parts.append((pixel[parents][keep], origins[keep], directions[keep], wk[keep]))
        if not parts or sum(len(part[0]) for part in parts) == 0:
            break
        pixel, o, d, weight = (np.concatenate([part[i] for part in parts]) for i in range(4))
    image = np.clip(colour.reshape(h, w, s, 3).mean(axis=2), 0.0, 1.0)
    return (image, RayCounts(**counts)) if return_counts else image


@dataclass(eq=False)
class RayNode:
    r"""One ray of a ray tree (:func:`trace_tree`), with its children.

    Attributes
    ----------
    kind : str
        ``"primary"``, ``"reflected"``, ``"refracted"`` or ``"shadow"``.
    origin, direction : ndarray, shape (3,)
        The ray (unit direction).
    weight : float
        The product of the reflection / transmission factors from the root down to this ray:
        how much of what it sees reaches the pixel (a shadow ray carries its parent's weight).
    depth : int
        Bounces from the primary ray (0); a shadow ray has its parent's depth + 1.
    t : float
        Distance to the hit (inf: none; for a shadow ray, the distance to the light).
    hit, normal : ndarray, shape (3,), or None
        The hit point and the shading normal there (facing the ray); None on a miss and for
        shadow rays.
    object : int
        Index of the object hit in ``scene.objects``; -1 on a miss and for shadow rays.
    local : ndarray, shape (3,)
        The local (Phong) colour at the hit, the background colour on a miss, zero for a shadow
        ray.
    contribution : ndarray, shape (3,)
        ``weight * local``: what this ray adds to the pixel. The pixel's (unclamped) colour is
        the sum over the tree, :meth:`total`.
    light : int or None
        For a shadow ray: the index of its light.
    visibility : float or None
        For a shadow ray: the fraction of the light that gets through (1 lit, 0 blocked).
    children : list of RayNode
        Shadow rays first, then the reflected and the refracted ray.

    Examples
    --------
    >>> tree = trace_tree(example_scene("spheres"), [0, 1, 6], [0, 0, -1], max_depth=2)
    >>> [node.kind for node in tree.walk()][:3]
    ['primary', 'shadow', 'reflected']
    """
    kind: str
    origin: np.ndarray
    direction: np.ndarray
    weight: float
    depth: int
    t: float = np.inf
    hit: object = None
    normal: object = None
    object: int = -1
    local: np.ndarray = field(default_factory=lambda: np.zeros(3))
    contribution: np.ndarray = field(default_factory=lambda: np.zeros(3))
    light: object = None
    visibility: object = None
    children: list = field(default_factory=list)

    def walk(self):
        """All nodes of the subtree, depth first (this node first)."""
        yield self
        for child in self.children:
            yield from child.walk()

    def total(self):
        """The summed contributions of the subtree: the pixel colour before clamping."""
        return sum((node.contribution for node in self.walk()), np.zeros(3))

    def count(self, kind=None):
        """Nodes in the subtree (of one `kind`, or all)."""
        return sum(1 for node in self.walk() if kind is None or node.kind == kind)

    def __repr__(self):
        where = "miss" if self.hit is None else f"object {self.object} at t={self.t:.4g}"
        if self.kind == "shadow":
            where = f"light {self.light}, visibility {self.visibility:.3g}"
        return (f"RayNode({self.kind}, depth {self.depth}, weight {self.weight:.4g}, {where}, "
                f"{len(self.children)} children)")


def trace_tree(scene, origin, direction, max_depth=3, shadows=True, epsilon=DEFAULT_EPSILON,
               min_weight=0.0):
    r"""The ray tree of one ray: every reflected, refracted and shadow ray it spawns.

    The same computation as :func:`render` for a single ray, keeping every ray as a
    :class:`RayNode`: the primary ray is the root; a hit spawns one shadow ray per light in
    front of the surface, a reflected ray (weight factor :math:`k_r + k_t F`) and a refracted
    ray (:math:`k_t (1 - F)`; none under total internal reflection), down to `max_depth`. The
    pixel colour is ``clip(tree.total(), 0, 1)``.

    Parameters
    ----------
    scene : Scene
    origin : array_like, shape (3,)
    direction : array_like, shape (3,)
        Normalized here.
    max_depth, shadows, epsilon, min_weight
        As for :func:`render`.

    Returns
    -------
    RayNode
        The root (kind ``"primary"``).

    Raises
    ------
    ValueError
        For a zero direction, NaN, a negative `max_depth` or a non-positive `epsilon`.
    TypeError
        If `scene` is not a Scene.

    Examples
    --------
    A ray into the glass sphere of the example scene: it reflects off the glass and refracts
    into it; inside, it reflects (internally) and refracts out again:

    >>> scene = example_scene("spheres")
    >>> glass = scene.objects[3].center
    >>> eye = scene.camera.eye
    >>> tree = trace_tree(scene, eye, glass - eye, max_depth=2)
    >>> [(node.kind, node.depth) for node in tree.children]
    [('shadow', 1), ('reflected', 1), ('refracted', 1)]
    >>> refracted = tree.children[2]
    >>> [node.kind for node in refracted.children]
    ['shadow', 'reflected', 'refracted']
    """
    c = _Compiled(scene)
    o = as_vector(origin, "origin", 3)
    d = as_vector(direction, "direction", 3)
    _nonzero_vectors(d[None], "direction", ())
    d = d / np.linalg.norm(d)
    depth, eps, min_weight = _render_options(max_depth, epsilon, min_weight)
    root = RayNode("primary", o, d, 1.0, 0)
    level = [root]
    origins, directions = o[None], d[None]
    for generation in range(depth + 1):
        g = _generation(c, origins, directions, generation < depth, shadows, eps, record=True)
        for i, node in enumerate(level):
            node.t = float(g.t[i])
            node.local = g.local[i].copy()
            node.contribution = node.weight * node.local
            if g.hit[i]:
                node.hit, node.normal, node.object = g.points[i].copy(), g.normals[i].copy(), \
                    int(g.objects[i])
        for light, parents, s_origin, s_dir, vis in g.shadows:
            for r, so, sd, v in zip(parents, s_origin, s_dir, vis):
                parent = level[r]
                target = c.lights[light]
                dist = (np.inf if target.position is None
                        else float(np.linalg.norm(target.position - so)))
                parent.children.append(RayNode("shadow", so.copy(), sd.copy(), parent.weight,
                                               parent.depth + 1, t=dist, light=light,
                                               visibility=float(v)))
        next_level, next_o, next_d = [], [], []
        for kind, parents, k_origins, k_dirs, factors in g.children:
            for r, ko, kd, f in zip(parents, k_origins, k_dirs, factors):
                parent = level[r]
                weight = parent.weight * float(f)
                if min_weight > 0 and weight < min_weight:
                    continue
                child = RayNode(kind, ko.copy(), kd.copy(), weight, parent.depth + 1)
                parent.children.append(child)
                next_level.append(child)
                next_o.append(ko)
                next_d.append(kd)
        if not next_level:
            break
        level, origins, directions = next_level, np.array(next_o), np.array(next_d)
    return root


# ---------------------------------------------------------------------------------------------
# Example scenes
# ---------------------------------------------------------------------------------------------

def _checkered_floor(height=0.0, reflectivity=0.0):
    light = Material(shading.colored_material((0.9, 0.9, 0.85), ka=0.1, kd=0.8, ks=0.0),
                     reflectivity=reflectivity)
    dark = Material(shading.colored_material((0.12, 0.12, 0.15), ka=0.1, kd=0.8, ks=0.0),
                    reflectivity=reflectivity)
    return Plane([0.0, height, 0.0], [0.0, 1.0, 0.0], light, checker=dark, checker_size=1.0)


def _glass():
    return Material(shading.Material(ka=0.0, kd=0.0, ks=0.6, shininess=200.0),
                    transparency=0.95, ior=1.5)


def _rotation_x(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def example_scene(kind="spheres", width=640, height=480):
    r"""Classic scenes for the ray tracer, built in code (deterministic).

    * ``"spheres"``: Whitted's classic: a red diffuse sphere, a mirror sphere and a glass sphere
      (index 1.5) on a checkered floor, one point light; objects ``[floor, red, mirror, glass]``.
    * ``"mesh"``: a golden, slightly reflective torus (a 4,096-triangle mesh from
      :func:`course_lib.shapes.torus`, smooth-shaded, with a BVH) standing upright, leaning
      back a little, just above the checkered floor; objects ``[floor, torus]``.
    * ``"glass"``: a glass sphere in front of a checkered wall: refraction turns the pattern
      upside down, total internal reflection rings the rim; objects ``[wall, floor, glass]``.
    * ``"mirrors"``: a sphere between two parallel mirrors: every extra bounce of ``max_depth``
      adds another reflected copy; objects ``[left mirror, right mirror, floor, sphere]``.

    Parameters
    ----------
    kind : {"spheres", "mesh", "glass", "mirrors"}
    width, height : int, optional
        The image size of the scene's camera (default 640 x 480).

    Returns
    -------
    Scene
        With a camera.

    Raises
    ------
    ValueError
        For an unknown kind.

    Examples
    --------
    >>> scene = example_scene("spheres")
    >>> [type(obj).__name__ for obj in scene.objects], scene.camera.width
    (['Plane', 'Sphere', 'Sphere', 'Sphere'], 640)
    """
    ambient = 1.0
    if kind == "spheres":
        red = Material(shading.colored_material((0.9, 0.15, 0.1), ka=0.1, kd=0.8, ks=0.3,
                                                shininess=40.0))
        mirror = Material(shading.colored_material((0.9, 0.9, 0.9), ka=0.0, kd=0.05, ks=0.4,
                                                   shininess=200.0), reflectivity=0.85)
        objects = [_checkered_floor(reflectivity=0.2),
                   Sphere([-1.7, 0.8, -0.2], 0.8, red),
                   Sphere([0.1, 1.0, -1.6], 1.0, mirror),
                   Sphere([1.4, 0.7, 0.9], 0.7, _glass())]
        lights = [shading.point_light([-3.0, 6.0, 4.0], intensity=0.9)]
        background = (0.55, 0.7, 0.9)
        camera = Camera([0.0, 1.6, 6.0], [0.0, -0.12, -1.0], [0.0, 1.0, 0.0], np.radians(45),
                        width, height)
    elif kind == "mesh":
        from . import shapes

        v, f = shapes.torus(major=1.0, minor=0.35, segments=64, rings=32)
        v = v @ _rotation_x(np.radians(-25)).T + [0.0, 1.4, -0.5]
        gold = Material(shading.colored_material((0.95, 0.7, 0.2), ka=0.1, kd=0.6, ks=0.5,
                                                 shininess=60.0), reflectivity=0.3)
        objects = [_checkered_floor(), Mesh(v, f, gold, smooth=True)]
        lights = [shading.point_light([-3.0, 6.0, 4.0], intensity=0.9)]
        background = (0.55, 0.7, 0.9)
        camera = Camera([0.0, 1.8, 5.5], [0.0, -0.1, -1.0], [0.0, 1.0, 0.0], np.radians(45),
                        width, height)
    elif kind == "glass":
        wall = Plane([0.0, 0.0, -2.0], [0.0, 0.0, 1.0],
                     Material(shading.colored_material((0.9, 0.9, 0.85), ka=0.2, kd=0.8, ks=0.0)),
                     checker=Material(shading.colored_material((0.1, 0.3, 0.6), ka=0.2, kd=0.8,
                                                               ks=0.0)),
                     checker_size=0.5)
        objects = [wall, _checkered_floor(-1.0), Sphere([0.0, 0.0, 0.5], 1.0, _glass())]
        lights = [shading.point_light([2.0, 4.0, 5.0], intensity=0.8)]
        background = (0.0, 0.0, 0.0)
        camera = Camera([0.0, 0.3, 5.0], [0.0, -0.05, -1.0], [0.0, 1.0, 0.0], np.radians(40),
                        width, height)
    elif kind == "mirrors":
        mirror = Material(shading.colored_material((0.9, 0.9, 0.9), ka=0.02, kd=0.05, ks=0.0),
                          reflectivity=0.9)
        objects = [Plane([-2.0, 0.0, 0.0], [1.0, 0.0, 0.0], mirror),
                   Plane([2.0, 0.0, 0.0], [-1.0, 0.0, 0.0], mirror),
                   _checkered_floor(),
                   Sphere([0.0, 0.6, 0.0], 0.6,
                          Material(shading.colored_material((0.2, 0.5, 0.95), ka=0.15, kd=0.8,
                                                            ks=0.3, shininess=30.0)))]
        lights = [shading.point_light([0.0, 5.0, 3.0], intensity=0.9)]
        background = (0.55, 0.7, 0.9)
        camera = Camera([-0.8, 1.4, 5.0], [0.35, -0.15, -1.0], [0.0, 1.0, 0.0], np.radians(50),
                        width, height)
    else:
        raise ValueError(f"kind must be 'spheres', 'mesh', 'glass' or 'mirrors', got {kind!r}")
    return Scene(objects, lights, ambient, background, camera)
