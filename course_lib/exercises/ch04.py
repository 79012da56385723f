r"""Chapter 4 exercises: projections and the viewing transformation, exam style.

Each class is one kind of exam question about the road from world coordinates to pixels:
the textbook's simple projections (:math:`P_{PER}`, :math:`P_{OBLI}`, cavalier and cabinet), the
eye coordinate system and the WCS -> ECS matrix, the perspective and orthographic ECS -> CSS
matrices with the homogeneous divide, the viewport, and what a perspective projection keeps
(cross ratios, vanishing points); and the taxonomy of projections (classify a matrix,
axonometric foreshortening, a cabinet matrix, a camera's vanishing points and how many a box
has, projecting onto an arbitrary plane, from :mod:`course_lib.projections`). The ``seed`` draws numbers that work out by hand: camera frames
whose axes have rational components (rows such as :math:`\tfrac13(1, 2, 2)`), fields of view of
60, 90 or 120 degrees, near and far planes that give short decimals, small whole points.

The expected answers come from :mod:`course_lib.viewing` (and :mod:`course_lib.transforms`). Each
exercise names the slips it anticipates (the compendium's perspective matrix, the angle in
degrees, a forgotten homogeneous divide, the y axis flipped, ...), computes the answer each slip
would give, and draws its numbers again until those answers differ clearly from the right one and
from each other, so that a diagnosis is never ambiguous
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.viewing`): column vectors :math:`p' = M p`; the eye looks
down :math:`-z_e`; ``near`` and ``far`` are positive distances in front of the eye; the near plane
goes to :math:`z = -1` and the far plane to :math:`z = +1` in CSS; ``gaze`` is a direction, not a
point.

The exercises live in :mod:`course_lib.exercises._ch04`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch04.simple_perspective import SimplePerspectivePoint
from ._ch04.wcs_to_ecs import EyeCoordinateAxes, LookAtMatrix, PointToEyeCoordinates
from ._ch04.ecs_to_css import CssDepth, OrthographicMatrix, PerspectiveDivide, PerspectiveMatrix
from ._ch04.parallel import CavalierCabinet, ObliqueProjection
from ._ch04.css_to_vcs import ViewportMatrix, ViewportPixel
from ._ch04.perspective_keeps import CrossRatioUnderProjection, VanishingPoint
from ._ch04.taxonomy import (AxonometricForeshortening, CabinetMatrix, CameraVanishingPoint,
                             ClassifyProjection, PlaneProjectionPoint,
                             PrincipalVanishingCount)

__all__ = [
    "EXERCISES",
    "CavalierCabinet",
    "CrossRatioUnderProjection",
    "CssDepth",
    "EyeCoordinateAxes",
    "LookAtMatrix",
    "ObliqueProjection",
    "OrthographicMatrix",
    "PerspectiveDivide",
    "PerspectiveMatrix",
    "PointToEyeCoordinates",
    "SimplePerspectivePoint",
    "VanishingPoint",
    "ViewportMatrix",
    "ViewportPixel",
    "AxonometricForeshortening",
    "CabinetMatrix",
    "CameraVanishingPoint",
    "ClassifyProjection",
    "PlaneProjectionPoint",
    "PrincipalVanishingCount",
]

#: The exercises of chapter 4, in the order of the solutions notebook.
EXERCISES = (
    SimplePerspectivePoint,
    EyeCoordinateAxes,
    LookAtMatrix,
    PointToEyeCoordinates,
    PerspectiveMatrix,
    PerspectiveDivide,
    CssDepth,
    OrthographicMatrix,
    ObliqueProjection,
    CavalierCabinet,
    ViewportMatrix,
    ViewportPixel,
    CrossRatioUnderProjection,
    VanishingPoint,
    ClassifyProjection,
    AxonometricForeshortening,
    CabinetMatrix,
    CameraVanishingPoint,
    PrincipalVanishingCount,
    PlaneProjectionPoint,
)
