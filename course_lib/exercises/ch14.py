r"""Chapter 14 exercises: sampling, barycentric coordinates, mappings, environment maps, mipmaps,
texture matrices, relief and texture hierarchies, exam style.

Each class is one kind of exam question: the nearest texel and a bilinear sample of a small
texture; the texel a repeating, clamping or mirroring texture uses for a coordinate outside
[0, 1]; the barycentric coordinates of a point, inside or outside its triangle, and a colour
interpolated with them; perspective-correct interpolation of texture coordinates; the
spherical, cylindrical and planar texture coordinates of a point; two-part mapping onto a
cylinder; the cube-map face and (s, t) of a direction, sphere-map coordinates and a reflection
vector's face; the texel footprint, the mipmap level and the size of a level; a checkerboard; a
texture matrix; a bump-mapped normal, a triangle's tangent frame and a decoded normal-map texel;
and the memory of a mip pyramid and of a clipmap. The ``seed`` draws numbers that work
out by hand: 4 x 4 textures of whole numbers, coordinates that are multiples of 0.05,
triangles with whole-number corners, points at whole-number distances from a centre. Answers
that are whole numbers (texel columns, the sides of a mipmap level, checker values) are compared
exactly: ``3.0`` is 3, and one off is wrong (and said to be). Every exercise gives step-by-step
hints (``hint()``) and the worked solution of its variant (``solution()``).

The expected answers come from :mod:`course_lib.texturing`. Each exercise names the slips it
anticipates (the half-texel offset forgotten, rows and columns swapped, rows counted from the
top of the picture, unsigned areas, :math:`\tan^{-1}(x/z)` instead of
:math:`\operatorname{atan2}`, the course compendium's :math:`\sqrt{x^2 + y^2}`, linear instead
of perspective-correct interpolation, the wrong logarithm, ...), computes the answer each slip
would give, and draws its numbers again until those answers differ clearly from the right one
and from each other (:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.texturing`): texel ``(i, j)`` is row ``i``, column
``j`` of the array and covers :math:`u \in [j/W, (j+1)/W]`, :math:`v \in [i/H, (i+1)/H]`; its
centre is at :math:`((j + \tfrac12)/W, (i + \tfrac12)/H)`; row 0 is at :math:`v = 0`, the
*bottom* of the picture. The spherical map with the pole on :math:`y` is
:math:`u = \tfrac12 + \operatorname{atan2}(x, z)/2\pi`, :math:`v = \tfrac12 + \arcsin(y/r)/\pi`
(the compendium's formulas corrected); barycentric coordinates are ratios of **signed** areas.

The exercises live in :mod:`course_lib.exercises._ch14`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch14.sampling import BilinearSample, NearestSample, WrapModes
from ._ch14.barycentric import BarycentricCoordinates, InterpolateColour, PerspectiveCorrect
from ._ch14.mappings import CylindricalMap, PlanarMap, SphericalMap
from ._ch14.two_part import TextureTransform, TwoPartMapping
from ._ch14.environment import CubeMapFace, EnvironmentReflection, SphereMapCoordinates
from ._ch14.mipmaps import Checkerboard, MipLevel
from ._ch14.relief import DecodeNormalTexel, PerturbedNormal, TangentFrame
from ._ch14.hierarchies import ClipmapMemory, PyramidMemory

__all__ = [
    "EXERCISES",
    "BarycentricCoordinates",
    "BilinearSample",
    "Checkerboard",
    "ClipmapMemory",
    "CubeMapFace",
    "CylindricalMap",
    "DecodeNormalTexel",
    "EnvironmentReflection",
    "InterpolateColour",
    "MipLevel",
    "NearestSample",
    "PerspectiveCorrect",
    "PerturbedNormal",
    "PlanarMap",
    "PyramidMemory",
    "SphereMapCoordinates",
    "SphericalMap",
    "TangentFrame",
    "TextureTransform",
    "TwoPartMapping",
    "WrapModes",
]

#: The exercises of chapter 14, in the order of the lesson's sections and of the solutions
#: notebook.
EXERCISES = (
    NearestSample,                  # 1-2 texture space, sampling
    BilinearSample,
    WrapModes,
    BarycentricCoordinates,         # 3 barycentric coordinates
    InterpolateColour,
    PerspectiveCorrect,
    SphericalMap,                   # 4 mappings
    CylindricalMap,
    PlanarMap,
    TwoPartMapping,                 # 5 two-part mapping
    CubeMapFace,                    # 6 environment mapping
    SphereMapCoordinates,
    EnvironmentReflection,
    MipLevel,                       # 7 mipmaps
    Checkerboard,                   # 8 procedural textures
    TextureTransform,               # 9 texture transformations
    PerturbedNormal,                # 10 relief
    TangentFrame,
    DecodeNormalTexel,
    PyramidMemory,                  # 11 texture hierarchies
    ClipmapMemory,
)
