r"""Chapter 15 exercises: ray tracing, exam style.

Each class is one kind of exam question: where a ray first hits a sphere; where it hits a
triangle (the ray parameter and the barycentric coordinates, as in Möller-Trumbore); the mirror
direction of an incoming ray; the refracted direction by Snell's law; the critical angle of total
internal reflection; Schlick's Fresnel reflectance; whether a shadow ray is blocked and what the
point's intensity is then; the colour a chain of mirror bounces gives a pixel; how many rays a
pixel's ray tree holds; and what a bounding volume hierarchy saves. The ``seed`` draws numbers
that work out by hand: whole-number points, unit vectors with rational components such as
:math:`(\tfrac23, \tfrac23, \tfrac13)` or :math:`(0.6, 0.8, 0)`, barycentric coordinates in
eighths, angles of refraction that are multiples of 15 degrees, refractive indices of real
media. Counts (rays, levels, tests) are whole numbers, compared exactly; every real answer is
right to 3 significant digits (the course's one tolerance policy). A few variants are boundary
cases on purpose (a ray through a triangle's edge), labelled by an attribute ``boundary``.

The expected answers come from :mod:`course_lib.raytracing`. Each exercise names the slips it
anticipates (the far root of the quadratic, a direction taken as a unit vector when it is not,
:math:`u` and :math:`v` swapped, the Phong-model reflection formula applied to an incoming ray,
the ratio of refractive indices upside down, the angle's degrees fed to a cosine that takes
radians, Brewster's angle for the critical angle, the weights of a ray tree added instead of
multiplied, the primary ray forgotten in a count, ...),
computes the answer each slip would give, and draws its numbers again until those answers differ
clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`). Every exercise offers ``hint()`` (three
hints, from the idea to this variant's numbers) and ``solution()`` (this variant worked out).

Conventions (those of :mod:`course_lib.raytracing`): a ray is :math:`o + t\,d`; :math:`d` is the
direction the ray *travels* (towards the surface), so the mirror direction is
:math:`r = d - 2 (d \cdot n)\, n`; refractive indices :math:`\eta_1` (the medium the ray comes
from) and :math:`\eta_2`; a triangle point is :math:`(1 - u - v)\, v_0 + u\, v_1 + v\, v_2`.

The exercises live in :mod:`course_lib.exercises._ch15`, one module per topic (what the topics
share is in its ``__init__``); import them from here.
"""
from ._ch15.intersections import RaySphereHit, RayTriangleHit
from ._ch15.reflection_refraction import (CriticalAngle, ReflectedRay, RefractedRay,
                                          SchlickReflectance)
from ._ch15.ray_trees import MirrorChainColour, RayTreeCount, ShadowRay
from ._ch15.acceleration import BVHSavings

__all__ = [
    "EXERCISES",
    "BVHSavings",
    "CriticalAngle",
    "MirrorChainColour",
    "RaySphereHit",
    "RayTreeCount",
    "RayTriangleHit",
    "ReflectedRay",
    "RefractedRay",
    "SchlickReflectance",
    "ShadowRay",
]

#: The exercises of chapter 15, in the order of the solutions notebook.
EXERCISES = (
    RaySphereHit,
    RayTriangleHit,
    ReflectedRay,
    RefractedRay,
    CriticalAngle,
    SchlickReflectance,
    ShadowRay,
    MirrorChainColour,
    RayTreeCount,
    BVHSavings,
)

# Distributed ray tracing (issue 22)
from ._ch15.distributed import DistributedDomainChoice, SoftShadowShare  # noqa: E402

__all__ += ["DistributedDomainChoice", "SoftShadowShare"]
EXERCISES = EXERCISES + (DistributedDomainChoice, SoftShadowShare)
# Quadrics and implicit surfaces: a finite open cylinder, two disks
from ._ch15.quadrics import RayCylinderHit, RayDiskHit  # noqa: E402

__all__ += ["RayCylinderHit", "RayDiskHit"]
EXERCISES += (RayCylinderHit, RayDiskHit)
# Spatial subdivision (lesson section "Spatial subdivision: grids, octrees and kd-trees")
from ._ch15.spatial import GridDDACells, QuadtreeRayCells  # noqa: E402

__all__ += ["GridDDACells", "QuadtreeRayCells"]
EXERCISES = EXERCISES + (GridDDACells, QuadtreeRayCells)
