"""Chapter 15: small example scenes for the lesson and the tests."""

import numpy as np

from .. import shading
from .camera import Camera
from .scene import Mesh, Plane, Scene, Sphere, WhittedMaterial

__all__ = ["example_scene"]


# ---------------------------------------------------------------------------------------------
# Example scenes
# ---------------------------------------------------------------------------------------------

def _checkered_floor(height=0.0, reflectivity=0.0):
    light = WhittedMaterial(shading.colored_material((0.9, 0.9, 0.85), ka=0.1, kd=0.8, ks=0.0),
                     reflectivity=reflectivity)
    dark = WhittedMaterial(shading.colored_material((0.12, 0.12, 0.15), ka=0.1, kd=0.8, ks=0.0),
                    reflectivity=reflectivity)
    return Plane([0.0, height, 0.0], [0.0, 1.0, 0.0], light, checker=dark, checker_size=1.0)


def _glass():
    return WhittedMaterial(shading.Material(ka=0.0, kd=0.0, ks=0.6, shininess=200.0),
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
        red = WhittedMaterial(shading.colored_material((0.9, 0.15, 0.1), ka=0.1, kd=0.8, ks=0.3,
                                                shininess=40.0))
        mirror = WhittedMaterial(shading.colored_material((0.9, 0.9, 0.9), ka=0.0, kd=0.05, ks=0.4,
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
        from .. import shapes

        v, f = shapes.torus(major=1.0, minor=0.35, segments=64, rings=32)
        v = v @ _rotation_x(np.radians(-25)).T + [0.0, 1.4, -0.5]
        gold = WhittedMaterial(shading.colored_material((0.95, 0.7, 0.2), ka=0.1, kd=0.6, ks=0.5,
                                                 shininess=60.0), reflectivity=0.3)
        objects = [_checkered_floor(), Mesh(v, f, gold, smooth=True)]
        lights = [shading.point_light([-3.0, 6.0, 4.0], intensity=0.9)]
        background = (0.55, 0.7, 0.9)
        camera = Camera([0.0, 1.8, 5.5], [0.0, -0.1, -1.0], [0.0, 1.0, 0.0], np.radians(45),
                        width, height)
    elif kind == "glass":
        wall = Plane([0.0, 0.0, -2.0], [0.0, 0.0, 1.0],
                     WhittedMaterial(shading.colored_material((0.9, 0.9, 0.85), ka=0.2, kd=0.8, ks=0.0)),
                     checker=WhittedMaterial(shading.colored_material((0.1, 0.3, 0.6), ka=0.2, kd=0.8,
                                                               ks=0.0)),
                     checker_size=0.5)
        objects = [wall, _checkered_floor(-1.0), Sphere([0.0, 0.0, 0.5], 1.0, _glass())]
        lights = [shading.point_light([2.0, 4.0, 5.0], intensity=0.8)]
        background = (0.0, 0.0, 0.0)
        camera = Camera([0.0, 0.3, 5.0], [0.0, -0.05, -1.0], [0.0, 1.0, 0.0], np.radians(40),
                        width, height)
    elif kind == "mirrors":
        mirror = WhittedMaterial(shading.colored_material((0.9, 0.9, 0.9), ka=0.02, kd=0.05, ks=0.0),
                          reflectivity=0.9)
        objects = [Plane([-2.0, 0.0, 0.0], [1.0, 0.0, 0.0], mirror),
                   Plane([2.0, 0.0, 0.0], [-1.0, 0.0, 0.0], mirror),
                   _checkered_floor(),
                   Sphere([0.0, 0.6, 0.0], 0.6,
                          WhittedMaterial(shading.colored_material((0.2, 0.5, 0.95), ka=0.15, kd=0.8,
                                                            ks=0.3, shininess=30.0)))]
        lights = [shading.point_light([0.0, 5.0, 3.0], intensity=0.9)]
        background = (0.55, 0.7, 0.9)
        camera = Camera([-0.8, 1.4, 5.0], [0.35, -0.15, -1.0], [0.0, 1.0, 0.0], np.radians(50),
                        width, height)
    else:
        raise ValueError(f"kind must be 'spheres', 'mesh', 'glass' or 'mirrors', got {kind!r}")
    return Scene(objects, lights, ambient, background, camera)
