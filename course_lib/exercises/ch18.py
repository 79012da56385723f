r"""Chapter 18 exercises: isolines, isosurfaces, volume rendering and streamlines, exam style.

Each class is one kind of exam question: the case index of a marching-squares cell, the points
where the isoline crosses its edges, and the resolution of an ambiguous (saddle) cell by the
midpoint decider; the number of triangles a marching-cubes case produces; compositing samples
along a ray front to back by hand, the sample at which early ray termination stops, and the
opacity correction for another step size; a maximum intensity projection of a tiny volume; one
step of the classic Runge-Kutta method (RK4) and the outward drift of Euler's method on a
circular flow; the asymptotic decider, a central-difference normal and the order of splats;
classifying a critical point from its Jacobian and one step in a gridded field; which line a dye
release shows, two Euler steps of a pathline and a LIC pixel. The ``seed`` draws numbers that work out by hand: whole corner values, opacities
in tenths and twentieths, small whole matrices. Case indices and counts are whole numbers,
compared exactly; every real answer is right to 3 significant digits (the course's one
tolerance policy). A few variants are boundary cases on purpose (a corner value equal to the
level), labelled by an attribute ``boundary``.

The expected answers come from :mod:`course_lib.scivis`. Each exercise names the slips it
anticipates (the corners numbered clockwise, the below corners counted, midpoints instead of
interpolated points, :math:`1 - A` forgotten in the compositing, the RK4 weights replaced by an
average, ...), computes the answer each slip would give, and draws its numbers again until those
answers differ clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`). Every exercise offers ``hint()`` (three
hints, from the idea to this variant's numbers) and ``solution()`` (this variant worked out).

Conventions (those of :mod:`course_lib.scivis`): a corner is *above* when its value is at least
the level; the corners of a square cell are numbered counter-clockwise from the bottom left
(0 bottom left, 1 bottom right, 2 top right, 3 top left) and its edges from the bottom
(edge k runs from corner k to corner k + 1); a cube's corners and edges are
:data:`~course_lib.scivis.CUBE_CORNERS` and :data:`~course_lib.scivis.CUBE_EDGES`; samples along
a ray are listed front (nearest the eye) first.

The exercises live in :mod:`course_lib.exercises._ch18`, one module per topic (what the topics
share is in its ``__init__``); import them from here.
"""
from ._ch18.marching_squares import SaddleResolution, SquareCaseIndex, SquareCrossings
from ._ch18.marching_cubes import CubeTriangleCount
from ._ch18.volume_rendering import (CompositeFrontToBack, EarlyTermination,
                                     MaxIntensityProjection, OpacityCorrection)
from ._ch18.streamlines import EulerDrift, RK4Step

from ._ch18.deciders import AsymptoticDecider
from ._ch18.volume_methods import CentralDifferenceNormal, SplatOrder
from ._ch18.topology import ClassifyCriticalPoint, GriddedFieldStep
from ._ch18.unsteady import FlowLineKind, LICPixel, PathlineEulerSteps

__all__ = [
    "EXERCISES",
    "AsymptoticDecider",
    "CentralDifferenceNormal",
    "ClassifyCriticalPoint",
    "CompositeFrontToBack",
    "CubeTriangleCount",
    "EarlyTermination",
    "EulerDrift",
    "FlowLineKind",
    "GriddedFieldStep",
    "LICPixel",
    "MaxIntensityProjection",
    "OpacityCorrection",
    "PathlineEulerSteps",
    "RK4Step",
    "SaddleResolution",
    "SplatOrder",
    "SquareCaseIndex",
    "SquareCrossings",
]

#: The exercises of chapter 18, in the order of the solutions notebook.
EXERCISES = (
    SquareCaseIndex,
    SquareCrossings,
    SaddleResolution,
    CubeTriangleCount,
    CompositeFrontToBack,
    EarlyTermination,
    OpacityCorrection,
    MaxIntensityProjection,
    RK4Step,
    EulerDrift,
    AsymptoticDecider,
    CentralDifferenceNormal,
    SplatOrder,
    ClassifyCriticalPoint,
    GriddedFieldStep,
    FlowLineKind,
    PathlineEulerSteps,
    LICPixel,
)
