r"""Chapter 7 exercises: Bézier, B-spline and NURBS curves and surfaces, exam style.

Each class is one kind of exam question: a Bézier point by de Casteljau's algorithm and one
level of its triangle, the Bernstein polynomials, the end tangent, subdivision and degree
elevation; a clamped knot vector, the B-spline basis functions by the Cox-de Boor recursion,
the support of one of them, the control points active at a parameter and a B-spline point by
de Boor's algorithm; a rational quadratic Bézier point, the circular arc as a rational quadratic,
the type of conic a set of weights gives; a point of a Bézier patch; and which properties hold
for which kind of curve or surface. The ``seed`` draws numbers that work out by hand: control
points with small whole coordinates, parameters among :math:`\tfrac14, \tfrac13, \tfrac12,
\tfrac23, \tfrac34` (tenths too for the Bernstein values), whole-number knots.

Every exercise helps on request: ``hint()`` gives the next of its hints, ``solution()`` works
the student's own variant out step by step (see :mod:`course_lib.exercises.core`).

The expected answers come from :mod:`course_lib.curves` and :mod:`course_lib.surfaces`. Each
exercise names the slips it anticipates (the binomial coefficient left out, :math:`t` and
:math:`1 - t` swapped, a forgotten division by the sum of the weighted basis functions, the
sine of the half angle, ...), computes the answer each slip would give, and draws its numbers
again until those answers differ clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.curves`): control points are the rows of an array; a
B-spline with the :math:`n + 1` control points :math:`P_0, \dots, P_n` and degree :math:`p` has
:math:`n + p + 2` knots and lives on :math:`[u_p, u_{n+1}]`; a fraction with a zero denominator
in the Cox-de Boor recursion counts as 0; weights are positive; the control grid of a patch is
indexed ``grid[i, j]``, ``i`` along :math:`u` and ``j`` along :math:`v`.

The exercises live in :mod:`course_lib.exercises._ch07`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch07.bezier import (BernsteinValues, BezierEndTangent, BezierSubdivision, DeCasteljauLevel,
                           DeCasteljauPoint, DegreeElevation)
from ._ch07.bsplines import (ActiveControlPoints, BSplinePoint, BasisSupport, ClampedKnotVector,
                             CoxDeBoorBasis)
from ._ch07.rational import CircleArc, ConicType, RationalBezierPoint
from ._ch07.patches import BezierSurfacePoint
from ._ch07.properties import PROPERTY_MENU, CurveProperties
from ._ch07.interpolating import (CatmullRomPoint, CatmullRomTangent, HermitePoint,
                                  SplineSecondDerivatives)
from ._ch07.continuity import C1JoinPoint, JoinContinuityCheck, MatrixFormPoint

__all__ = [
    "EXERCISES",
    "PROPERTY_MENU",
    "ActiveControlPoints",
    "BSplinePoint",
    "BasisSupport",
    "BernsteinValues",
    "BezierEndTangent",
    "BezierSubdivision",
    "BezierSurfacePoint",
    "CircleArc",
    "ClampedKnotVector",
    "ConicType",
    "CoxDeBoorBasis",
    "CurveProperties",
    "DeCasteljauLevel",
    "DeCasteljauPoint",
    "DegreeElevation",
    "RationalBezierPoint",
    # interpolating curves
    "CatmullRomPoint",
    "CatmullRomTangent",
    "HermitePoint",
    "SplineSecondDerivatives",
    "C1JoinPoint",
    "JoinContinuityCheck",
    "MatrixFormPoint",
]

#: The exercises of chapter 7, in the order of the solutions notebook.
EXERCISES = (
    DeCasteljauPoint,
    DeCasteljauLevel,
    BernsteinValues,
    BezierEndTangent,
    BezierSubdivision,
    DegreeElevation,
    ClampedKnotVector,
    CoxDeBoorBasis,
    BasisSupport,
    ActiveControlPoints,
    BSplinePoint,
    RationalBezierPoint,
    CircleArc,
    ConicType,
    BezierSurfacePoint,
    CurveProperties,
    # continuity and the matrix form of cubics
    JoinContinuityCheck,
    MatrixFormPoint,
    C1JoinPoint,
    # interpolating curves
    HermitePoint,
    CatmullRomTangent,
    CatmullRomPoint,
    SplineSecondDerivatives,
)
