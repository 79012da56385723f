r"""Chapter 5 exercises: back-face culling, clipping and hidden-surface elimination, exam style.

Each class is one kind of exam question: the back-face test, Cohen-Sutherland outcodes, its
trivial accept/reject test, the clipped segment and the number of intersections it computes,
Liang-Barsky's :math:`p_k, q_k, t_k` table, its :math:`[t_{in}, t_{out}]` interval and the clipped
segment in 3D, Sutherland-Hodgman against one side and against a whole rectangle, the z-buffer on
a 4 x 4 grid, the painter's algorithm (its order, and where it goes wrong) and the cost of ray
casting with and without bounding volumes; clipping in clip space before the divide (6-bit
outcodes from :math:`-w \le x, y, z \le w`, Liang-Barsky's six pairs, the exit point, a
Sutherland-Hodgman step), hierarchical occlusion culling (a z-pyramid level, the hierarchical
z-buffer test, an occlusion query, an occlusion map's opacity) and BSP trees of segments built
and traversed by hand. The ``seed`` draws small whole numbers, so that every
intersection is a short fraction and every grid can be filled in by hand.

The clipping answers come from :mod:`course_lib.clipping`. The z-buffer, the painter's algorithm
and the ray counts are computed by the small closed-form functions of these modules (barycentric
coordinates at pixel centres, a sort, a product), so that the exercises stand on their own.
Every exercise names the slips it anticipates (the compendium's sign in the back-face test, a
reversed bit order, entering and leaving swapped, a missing intersection vertex, a missing depth
test, ...) and draws its numbers again until each slip gives an answer of its own.

Counts, indices, outcodes and ids are whole numbers, compared exactly (``5.0`` is 5), with an
"off by one" diagnosis for counts. Boundary cases (a point on the line of a side, a segment
through a corner, a segment parallel to a side) are not left to chance: the clipping exercises
draw one on purpose in about 15 % of the seeds, name it in their ``boundary`` attribute (None
otherwise) and say so in the worked solution; their other variants have none.

Conventions (those of :mod:`course_lib.clipping`): a point on the boundary of the clip region is
inside; outcode bits left = 1, right = 2, bottom = 4, top = 8, near = 16, far = 32; the back-face
test uses the view vector from the eye to the face.

The exercises live in :mod:`course_lib.exercises._ch05`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch05.back_faces import BackFaceCulling
from ._ch05.cohen_sutherland import (CohenSutherlandClip, CohenSutherlandDecision,
                                     CohenSutherlandIntersections, Outcodes)
from ._ch05.liang_barsky import LiangBarskyClip3D, LiangBarskyInterval, LiangBarskyTable
from ._ch05.sutherland_hodgman import SutherlandHodgmanArea, SutherlandHodgmanOneSide
from ._ch05.zbuffer import ZBufferIds, ZBufferWrites
from ._ch05.painter import PainterFailure, PaintersOrder
from ._ch05.ray_casting import RayCastingCount

from ._ch05.clip3d import (ClipSpaceExitPoint, ClipSpaceLiangBarskyPairs, ClipSpaceOutcode,
                           ClipSpaceSutherlandHodgman)
from ._ch05.hierarchical import (HOMOpacity, HZBRejection, OcclusionQueryCount,
                                 ZPyramidNextLevel)
from ._ch05.bsp import BSPBuildTree, BSPPaintOrder

__all__ = [
    "EXERCISES",
    "BSPBuildTree",
    "BSPPaintOrder",
    "BackFaceCulling",
    "ClipSpaceExitPoint",
    "ClipSpaceLiangBarskyPairs",
    "ClipSpaceOutcode",
    "ClipSpaceSutherlandHodgman",
    "CohenSutherlandClip",
    "CohenSutherlandDecision",
    "CohenSutherlandIntersections",
    "HOMOpacity",
    "HZBRejection",
    "LiangBarskyClip3D",
    "LiangBarskyInterval",
    "LiangBarskyTable",
    "OcclusionQueryCount",
    "Outcodes",
    "PainterFailure",
    "PaintersOrder",
    "RayCastingCount",
    "SutherlandHodgmanArea",
    "SutherlandHodgmanOneSide",
    "ZBufferIds",
    "ZBufferWrites",
    "ZPyramidNextLevel",
]

#: The exercises of chapter 5, in the order of the solutions notebook.
EXERCISES = (
    BackFaceCulling,
    Outcodes,
    CohenSutherlandDecision,
    CohenSutherlandClip,
    CohenSutherlandIntersections,
    LiangBarskyTable,
    LiangBarskyInterval,
    LiangBarskyClip3D,
    SutherlandHodgmanOneSide,
    SutherlandHodgmanArea,
    ZBufferIds,
    ZBufferWrites,
    PaintersOrder,
    PainterFailure,
    RayCastingCount,
    ClipSpaceOutcode,
    ClipSpaceLiangBarskyPairs,
    ClipSpaceExitPoint,
    ClipSpaceSutherlandHodgman,
    ZPyramidNextLevel,
    HZBRejection,
    OcclusionQueryCount,
    HOMOpacity,
    BSPBuildTree,
    BSPPaintOrder,
)
