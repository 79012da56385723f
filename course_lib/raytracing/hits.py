"""Chapter 15 (lesson section 15.3): the scene as arrays: nearest hits, surface data, shadow rays.
"""

from typing import NamedTuple

import numpy as np

from .. import shading
from .._raycore import as_rays as _rays, as_t_min as _t_min
from ._common import _dot
from .intersections import _before, _first_root, _plane_t, _sphere_roots
from .optics import _refract, _schlick
from .scene import Mesh, Plane, Scene, Sphere

__all__ = ["SceneHits", "intersect_scene"]


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
