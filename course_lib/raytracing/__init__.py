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
the ray into the surface). ``reflect_direction(d, n)`` is computed as
:func:`course_lib.shading.reflect` ``(-d, n)``.

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
* **Directions**: a ray's :math:`d` points the way it travels (towards the surface it hits);
  the Phong vectors :math:`L, V, R` of :mod:`course_lib.shading` point *away* from the
  surface, so :math:`V = -d` and ``reflect_direction(d, n) == shading.reflect(-d, n)``.
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

Files
-----

``optics.py``
    Chapter 15 (lesson section 15.5): reflected and refracted directions, Fresnel and Schlick.
``intersections.py``
    Chapter 15 (lesson sections 15.2, 15.7): ray-object intersections, the slab test and the
    BVH (triangles, brute force and :class:`BVH` itself are in :mod:`course_lib._raycore`,
    shared with :mod:`course_lib.visibility`).
``quadrics.py``
    Chapter 15 (lesson section 15.3): every quadric as a 4 x 4 matrix, disks, finite cylinders,
    and any implicit surface by marching and bracketing.
``camera.py``
    Chapter 15 (lesson section 15.1): the pinhole camera, one primary ray per pixel sample.
``scene.py``
    Chapter 15 (lesson section 15.4): the scene description: materials, objects and lights.
``hits.py``
    Chapter 15 (lesson section 15.4): the scene as arrays: nearest hits, surface data, shadow
    rays.
``whitted.py``
    Chapter 15 (lesson sections 15.4, 15.6): Whitted's recursive ray tracer and its ray tree.
``spatial.py``
    Chapter 15 (lesson section 15.8): spatial subdivision: the uniform grid walked by 3D-DDA,
    the octree and the kd-tree, with their test counts beside the BVH.
``distributed.py``
    Chapter 15 (lesson section 15.11): distributed ray tracing: antialiasing, soft shadows,
    glossy reflection, depth of field and motion blur, each a seeded Monte Carlo estimate.
``examples.py``
    Chapter 15: small example scenes for the lesson and the tests.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from .optics import (fresnel, reflect_direction, refract_direction, schlick)
from .intersections import (BVH, BoxHits, SurfaceHits, TriangleHits, intersect_box,
    intersect_plane, intersect_sphere, intersect_triangles)
from .camera import (Camera, CameraRays, camera_rays)
from .scene import (Mesh, Plane, Scene, Sphere, WhittedMaterial)
from .scene import WhittedMaterial as Material     # its old name, the same class
from .hits import (SceneHits, intersect_scene)
from .whitted import (RayCounts, RayNode, render, render_bands, trace_tree)
from .examples import (example_scene)

__all__ = [
    "BVH",
    "BoxHits",
    "Camera",
    "CameraRays",
    "Mesh",
    "Plane",
    "RayCounts",
    "RayNode",
    "Scene",
    "SceneHits",
    "Sphere",
    "SurfaceHits",
    "TriangleHits",
    "WhittedMaterial",
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
    "render_bands",
    "schlick",
    "trace_tree",
]

# Issue 22: quadrics and implicit surfaces, spatial subdivision (grid, octree, kd-tree),
# distributed ray tracing (each module declares its __all__)
from . import distributed, quadrics, spatial  # noqa: E402
from .quadrics import *  # noqa: E402,F401,F403
from .spatial import *  # noqa: E402,F401,F403
from .distributed import *  # noqa: E402,F401,F403

__all__ = sorted(__all__ + quadrics.__all__ + spatial.__all__ + distributed.__all__)
