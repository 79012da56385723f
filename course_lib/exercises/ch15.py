r"""Chapter 15 exercises: ray tracing, exam style.

Each class is one kind of exam question: where a ray first hits a sphere; where it hits a
triangle (the ray parameter and the barycentric coordinates, as in Möller-Trumbore); the mirror
direction of an incoming ray; the refracted direction by Snell's law; the critical angle of total
internal reflection; Schlick's Fresnel reflectance; whether a shadow ray is blocked and what the
point's intensity is then; the colour a chain of mirror bounces gives a pixel; how many rays a
pixel's ray tree holds; what a bounding volume hierarchy saves; a ray against an open cylinder
and against disks (quadrics); the cells a 3D-DDA and a quadtree visit (spatial subdivision);
and what distributed ray tracing spreads its rays over, with a soft shadow's share of the light.
The ``seed`` draws numbers
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

from ._ch15.quadrics import RayCylinderHit, RayDiskHit
from ._ch15.spatial import GridDDACells, QuadtreeRayCells
from ._ch15.distributed import DistributedDomainChoice, SoftShadowShare

__all__ = [
    "EXERCISES",
    "BVHSavings",
    "CriticalAngle",
    "DistributedDomainChoice",
    "GridDDACells",
    "MirrorChainColour",
    "QuadtreeRayCells",
    "RayCylinderHit",
    "RayDiskHit",
    "RaySphereHit",
    "RayTreeCount",
    "RayTriangleHit",
    "ReflectedRay",
    "RefractedRay",
    "SchlickReflectance",
    "ShadowRay",
    "SoftShadowShare",
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
    RayCylinderHit,
    RayDiskHit,
    GridDDACells,
    QuadtreeRayCells,
    DistributedDomainChoice,
    SoftShadowShare,
)
