"""Chapter 15 (lesson section 15.3): the scene description: materials, objects and lights."""

from dataclasses import dataclass

import numpy as np

from .. import shading
from .._validate import as_points, as_positive, as_rgb, as_scalar, as_vector
from ._common import _dot, _unit_vectors
from .camera import Camera
from .intersections import BVH

__all__ = ["Mesh", "Plane", "Scene", "Sphere", "WhittedMaterial"]


# ---------------------------------------------------------------------------------------------
# Scenes: materials, objects, lights
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True, eq=False)
class WhittedMaterial:
    r"""A surface for the ray tracer: Phong coefficients plus reflection and refraction.

    (``raytracing.Material`` is its old name, the same class; :class:`course_lib.shading.Material`
    is the Phong material it contains.)

    The local colour is the Phong model (:func:`course_lib.shading.phong`) with the
    coefficients of `phong`; then a fraction :math:`k_r` (`reflectivity`) of the light seen in
    the mirror direction is added, and for a transparent material (`transparency` :math:`k_t >
    0`) the light seen through it, bent by Snell's law with the refractive index `ior`, split by
    Schlick's Fresnel factor :math:`F` into :math:`k_t F` (reflected) and :math:`k_t (1 - F)`
    (refracted). :math:`k_r + k_t \le 1` keeps a surface from returning more light than it
    receives. Glass: small diffuse and ambient coefficients, a highlight, :math:`k_t` near 1,
    index 1.5; a mirror: :math:`k_r` near 1. The Phong coefficients are a
    :class:`course_lib.shading.Material` (the `phong` field), not redefined here.

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
    >>> glass = WhittedMaterial(shading.Material(ka=0.0, kd=0.05, ks=0.5, shininess=100),
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
        object.__setattr__(self, "ior", as_positive(self.ior, "ior",
                                                   "a refractive index"))


@dataclass(frozen=True, eq=False)
class Sphere:
    """A sphere: centre, radius and material.

    Attributes
    ----------
    center : array_like, shape (3,)
    radius : float
        Positive.
    material : WhittedMaterial

    Examples
    --------
    >>> Sphere([0, 1, 0], 1.0).radius
    1.0
    """
    center: object
    radius: float
    material: WhittedMaterial = WhittedMaterial()

    def __post_init__(self):
        object.__setattr__(self, "center", as_vector(self.center, "center", 3))
        object.__setattr__(self, "radius", as_positive(self.radius, "radius",
                                                      "the sphere's radius"))
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
    material : WhittedMaterial
    checker : WhittedMaterial or None
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
    material: WhittedMaterial = WhittedMaterial()
    checker: object = None
    checker_size: float = 1.0

    def __post_init__(self):
        object.__setattr__(self, "point", as_vector(self.point, "point", 3))
        object.__setattr__(self, "normal",
                           _unit_vectors(as_vector(self.normal, "normal", 3), "normal"))
        _check_material(self.material)
        if self.checker is not None:
            _check_material(self.checker, "checker")
        object.__setattr__(self, "checker_size", as_positive(self.checker_size, "checker_size"))

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
    material : WhittedMaterial, optional
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

    def __init__(self, vertices, faces, material=WhittedMaterial(), smooth=True, leaf_size=4):
        self.vertex_normals = shading.vertex_normals(vertices, faces)   # checks both: triangles
        self.face_normals = shading.face_normals(vertices, faces)
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
    if not isinstance(material, WhittedMaterial):
        raise TypeError(f"{name} must be a raytracing.WhittedMaterial, got "
                        f"{type(material).__name__}")


@dataclass(frozen=True, eq=False)
class Scene:
    """What the ray tracer renders: objects, lights, ambient light, background and a camera.

    (The hidden-surface algorithms of chapter 5 take a different scene, triangles and a
    camera: :class:`course_lib.visibility.TriangleScene`.)

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
        object.__setattr__(self, "ambient", as_rgb(self.ambient, "ambient",
                                                      maximum=None, single=True))
        object.__setattr__(self, "background", as_rgb(self.background, "background",
                                                         maximum=None, single=True))
