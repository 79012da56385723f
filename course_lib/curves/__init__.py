r"""Chapter 7: Bézier, B-spline and rational (NURBS) curves.

A curve of this chapter is a weighted sum of **control points** :math:`P_0, \dots, P_n`,

.. math:: C(t) = \sum_{i=0}^{n} F_i(t)\, P_i ,

where the blending functions :math:`F_i` are the Bernstein polynomials (Bézier curves), the
B-spline basis functions of a knot vector (B-spline curves), or either of them multiplied by
weights and divided by their weighted sum (rational Bézier curves and NURBS).

Conventions used throughout the module:

* Control points are the **rows** of an array of shape ``(n + 1, d)``, in any dimension
  ``d >= 1`` (a curve in 1D is a column, shape ``(n + 1, 1)``). At least two are needed.
* Every evaluation function is vectorized over the parameter: ``t`` may be a number or an array
  of any shape, and the result has shape ``t.shape + (d,)``.
* A Bézier curve is defined for :math:`t \in [0, 1]`. A B-spline of degree :math:`p` with
  ``n_control`` control points needs ``n_control + p + 1`` non-decreasing knots
  :math:`u_0 \le \dots \le u_{n+p+1}`; it is defined on its **domain**
  :math:`[u_p, u_{n_{control}}]` (see :func:`domain`), where the basis functions sum to one.
  Each knot span :math:`[u_k, u_{k+1})` is closed on the left and open on the right, except the
  last one, which also contains the end of the domain: ``t = b`` gives the left-hand limit of
  the curve, as ``scipy.interpolate.BSpline(..., extrapolate=False)`` does.
* A parameter outside the domain raises ``ValueError`` (no silent extrapolation); values within
  ``1e-12`` of the domain's length outside an end are rounded onto it.

References: L. Piegl and W. Tiller, *The NURBS Book*, 2nd ed., Springer 1997 (chapters 1-5 and
7); G. Farin, *Curves and Surfaces for CAGD*, 5th ed., Morgan Kaufmann 2002.

Files
-----

``bezier_curves.py``
    Chapter 7 (lesson section 1): Bernstein polynomials and Bezier curves, de Casteljau.
``bspline_curves.py``
    Chapter 7 (lesson section 2): B-splines: knot vectors, basis functions, de Boor's
    algorithm.
``rational_curves.py``
    Chapter 7 (lesson section 3): rational Bezier curves, NURBS, conics and the circle.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from ._common import NurbsCurve
from .bezier_curves import (bernstein, bezier, bezier_derivative, bezier_elevate,
    bezier_hodograph, bezier_subdivide, bezier_tangent, de_casteljau)
from .bspline_curves import (bspline, bspline_basis, bspline_basis_derivative, bspline_derivative,
    clamped_knots, de_boor, domain, find_span, insert_knot, uniform_knots)
from .rational_curves import (conic_type, nurbs, nurbs_circle, rational_bezier,
    rational_quadratic_conic)

__all__ = [
    "NurbsCurve",
    "bernstein",
    "bezier",
    "bezier_derivative",
    "bezier_elevate",
    "bezier_hodograph",
    "bezier_subdivide",
    "bezier_tangent",
    "bspline",
    "bspline_basis",
    "bspline_basis_derivative",
    "bspline_derivative",
    "clamped_knots",
    "conic_type",
    "de_boor",
    "de_casteljau",
    "domain",
    "find_span",
    "insert_knot",
    "nurbs",
    "nurbs_circle",
    "rational_bezier",
    "rational_quadratic_conic",
    "uniform_knots",
]

# continuity and curvature, the matrix form of cubics, interpolating curves (each module
# declares its __all__)
from . import continuity, interpolating, matrix_form  # noqa: E402
from .continuity import *  # noqa: E402,F401,F403
from .matrix_form import *  # noqa: E402,F401,F403
from .interpolating import *  # noqa: E402,F401,F403

__all__ = sorted(__all__ + continuity.__all__ + matrix_form.__all__ + interpolating.__all__)
