"""The concept questions of chapter 7 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _tf(7, "ch07-bezier-convex-hull",
        "Every point of a Bézier curve lies in the convex hull of its control points.", True,
        "The Bernstein polynomials are non-negative on $[0, 1]$ and sum to 1, so each curve "
        "point is a convex combination of the control points.",
        "It holds for every Bézier curve: its points are weighted averages of the control "
        "points with non-negative weights that sum to 1."),
    _mc(7, "ch07-bezier-endpoints",
        "Which control points does a Bézier curve of degree $n$ pass through?",
        ("All of them", "Inner control points only pull the curve; in general it misses them."),
        ("The first and the last", "At $t = 0$ only $B_0^n$ is non-zero and at $t = 1$ only "
         "$B_n^n$: the curve interpolates its end points."),
        ("None of them", "It does pass through the first and last."),
        ("Only the middle one", "Inner points are generally missed."),
        correct=1),
    _mc(7, "ch07-bezier-tangent",
        "What is the tangent (derivative) of a degree-$n$ Bézier curve at $t = 0$?",
        ("$P_1 - P_0$", "The direction is right but the length lacks the factor $n$."),
        ("$n(P_n - P_0)$", "That joins the end points; the end tangent only involves the first "
         "edge of the control polygon."),
        ("$P_0$", "That is the point, not the tangent."),
        ("$n(P_1 - P_0)$", "The derivative is $n$ times a Bézier curve of the differences "
         "$P_{i+1} - P_i$; at $t = 0$ only the first difference counts."),
        correct=3),
    _tf(7, "ch07-bezier-affine",
        "Applying an affine map to the control points of a Bézier curve gives the same curve as "
        "applying it to every point of the curve.", True,
        "A curve point is an affine combination of the control points (weights summing to 1), "
        "and affine maps preserve affine combinations.",
        "It holds (affine invariance): weights summing to 1 make the combination commute with "
        "affine maps."),
    _tf(7, "ch07-bezier-projective",
        "A (polynomial) Bézier curve is also invariant under perspective projection: projecting "
        "the control points gives the projected curve.", False,
        "It is not: a perspective map divides each point by its own depth, which does not "
        "commute with weighted averages. Rational Bézier curves are projectively invariant "
        "(the weights absorb the $w$).",
        "Right: polynomial curves are only affinely invariant; rational curves with weights "
        "are also invariant under projective maps."),
    _mc(7, "ch07-bezier-local",
        "Moving one control point of a Bézier curve changes:",
        ("Only the segment between its two neighbours", "That is local control, a B-spline "
         "property."),
        ("Nothing but the tangent at that point", "The curve does not even pass through inner "
         "control points."),
        ("The whole curve (except the end points when the moved point is an inner one), most "
         "strongly near the parameter where its Bernstein polynomial peaks",
         "Every Bernstein polynomial is non-zero on all of $(0, 1)$: control is global, only "
         "'pseudo-local'."),
        ("Only the degree of the curve", "The degree is fixed by the number of control points."),
        correct=2),
    _mc(7, "ch07-variation-diminishing",
        "The variation-diminishing property of a planar Bézier curve says:",
        ("Any straight line crosses the curve at most as often as it crosses the control "
         "polygon", "The curve wiggles no more than its polygon; as a consequence, a convex "
         "control polygon gives a convex curve."),
        ("The curve is shorter than its control polygon's first edge", "There is no such "
         "bound."),
        ("The degree decreases after subdivision", "Subdivision keeps the degree."),
        ("The curve has fewer inflection points than its degree", "The property compares "
         "crossings with lines, not inflections with the degree."),
        correct=0),
    _tf(7, "ch07-bspline-degree",
        "The degree of a B-spline curve is fixed by the number of its control points.", False,
        "It is not: the degree $p$ is chosen freely (below the number of control points); "
        "with $n + 1$ control points and degree $p$ one needs $n + p + 2$ knots. Adding "
        "control points adds segments, not degree.",
        "Right: unlike a Bézier curve, a B-spline keeps its degree when control points are "
        "added: it gets more polynomial pieces instead."),
    _mc(7, "ch07-bspline-local",
        "Moving the control point $P_i$ of a B-spline of degree $p$ changes the curve only "
        "on:",
        ("The whole parameter range", "That is Bézier behaviour; B-spline basis functions have "
         "compact support."),
        ("The knot span $[u_i, u_{i+1})$", "The support of $N_{i,p}$ covers $p + 1$ spans, "
         "not one."),
        ("The $p + 1$ knot spans $[u_i, u_{i+p+1})$ where $N_{i,p}$ is non-zero", "Outside its "
         "support the basis function is zero, so the point has no influence there: local "
         "control."),
        ("The span between $P_{i-1}$ and $P_{i+1}$", "The influence is measured in parameter "
         "(knot spans), and covers $p + 1$ of them."),
        correct=2),
    _tf(7, "ch07-bspline-strong-hull",
        "Each point of a B-spline curve of degree $p$ lies in the convex hull of the $p + 1$ "
        "control points active on its knot span (strong convex hull property).", True,
        "On one span only $p + 1$ basis functions are non-zero, they are non-negative and sum "
        "to 1: a convex combination of those control points.",
        "It holds, and it is stronger than the convex hull of all control points."),
    _mc(7, "ch07-bspline-continuity",
        "A B-spline of degree $p$ has a knot of multiplicity $k$ inside its range. How smooth is "
        "it there?",
        ("$C^{p}$", "Only where there is no knot is the curve infinitely smooth; at a simple "
         "knot it is $C^{p-1}$."),
        ("$C^{p-k}$", "Each repetition of a knot removes one order of continuity; with $k = p$ "
         "the curve is only $C^0$ and passes through a control point."),
        ("$C^{k}$", "Repeating a knot lowers the smoothness, it does not raise it."),
        ("$C^{p+k}$", "The continuity cannot exceed the degree's."),
        correct=1),
    _mc(7, "ch07-rational-circle",
        "Which curves can represent a circular arc **exactly**?",
        ("Polynomial Bézier curves of high enough degree", "No polynomial parametrization "
         "traces a circle exactly; it can only approximate it."),
        ("Uniform B-splines", "They are polynomial piecewise: they also only approximate."),
        ("None: circles must be tessellated", "Rational curves do it exactly."),
        ("Rational Bézier curves and NURBS (for instance a rational quadratic with middle "
         "weight $\\cos\\tfrac\\alpha2$)", "The weights allow exact conic sections; a quarter "
         "circle is a rational quadratic with weights $1, \\tfrac{\\sqrt2}2, 1$."),
        correct=3),
    _tf(7, "ch07-rational-weights-one",
        "A rational Bézier curve whose weights are all equal is the ordinary (polynomial) "
        "Bézier curve of the same control points.", True,
        "With equal weights the denominator $\\sum w B_i^n = w$ is constant and cancels.",
        "It is: equal weights cancel between numerator and denominator."),
    _tf(7, "ch07-surface-variation",
        "Tensor-product Bézier surfaces have the variation-diminishing property, like Bézier "
        "curves.", False,
        "They keep the convex hull, end-point (corner) interpolation and affine invariance, but "
        "no variation-diminishing property is known for them.",
        "Right: it is the property the curves have and the surfaces lack."),
    # --- interpolating curves (textbook 7.5) ---
    _tf(7, "ch07-interp-runge",
        "Interpolating more and more equally spaced samples of a smooth function with one "
        "polynomial through all of them always brings the polynomial closer to the function.",
        False,
        "Not always: for $1/(1 + 25x^2)$ on $[-1, 1]$ the error near the ends grows with the "
        "degree (Runge's phenomenon). The polynomial must pass through every sample and swings "
        "in between; piecewise cubics (splines) avoid it.",
        "Right: it is false, and the counter-example is Runge's function, whose equispaced "
        "interpolants oscillate more and more near the ends."),
    _mc(7, "ch07-interp-catmull-rom-tangent",
        "A Catmull-Rom spline with uniform parameters has, at an inner point $P_i$, the "
        "tangent:",
        ("$P_{i+1} - P_i$", "That is the forward difference: it ignores $P_{i-1}$ and gives "
         "a tangent parallel to one edge only."),
        ("$\\tfrac12 (P_{i+1} - P_{i-1})$", "The central difference of the two neighbours "
         "(two parameter steps apart, hence the half): the curve at $P_i$ runs parallel to the "
         "chord of its neighbours."),
        ("$P_{i+1} - P_{i-1}$", "Twice too long: the two neighbours are two parameter steps "
         "apart."),
        ("$0$", "Zero tangents give a cardinal spline with tension $s = 0$, not Catmull-Rom."),
        correct=1),
    _mc(7, "ch07-interp-spline-local",
        "You move one data point of a **natural cubic spline** (C2, through all the points). "
        "Which part of the curve changes?",
        ("Only the two segments next to the point", "That is true of Catmull-Rom (local "
         "tangents), not of the C2 spline."),
        ("Only the four nearest segments", "The influence decays away from the point, but it "
         "never becomes exactly zero."),
        ("In general every segment", "The tangents solve one tridiagonal system whose inverse "
         "is full: every second derivative depends on every point (the influence decays fast, "
         "but is not zero). C2 and locality cannot both be had with interpolating cubics."),
        ("None: a spline only approximates its points", "A cubic spline through the points "
         "interpolates them: the moved point is on the new curve."),
        correct=2),
    _tf(7, "ch07-interp-natural-end",
        "A natural cubic spline has zero second derivative at both of its end points.", True,
        "That is the definition of the natural end condition: $M_0 = M_n = 0$ closes the "
        "system (the curve leaves its ends straight, like a flexible ruler let loose).",
        "It is true: the natural end rows are $M_0 = 0$ and $M_n = 0$; the clamped ends give "
        "the end tangents instead."),
    _tf(7, "ch07-interp-chord-duplicate",
        "Chord-length parameterisation works even when two consecutive data points "
        "coincide.", False,
        "A repeated point gives a parameter step of length 0: two parameter values are equal "
        "and the spline's system divides by $h_i = 0$. Remove duplicates first.",
        "Right: equal consecutive points make $t_i = t_{i+1}$, which an interpolating spline "
        "cannot handle."),
    _mc(7, "ch07-continuity-g1-vs-c1",
        "Two curve segments meet with end tangents $A'(1) = (2, 2)$ and $B'(0) = (4, 4)$. "
        "Their join is:",
        ("$C^1$", "$C^1$ needs the derivative vectors themselves equal, length included; "
         "here $B'(0) = 2A'(1)$."),
        ("$G^1$ but not $C^1$", "The unit tangents agree (same direction, positive factor "
         "2) but the speed jumps: geometric, not parametric, continuity."),
        ("Neither $G^1$ nor $C^1$", "Parallel tangents pointing the same way are exactly "
         "what $G^1$ asks for."),
        ("A cusp", "A cusp has tangents pointing in opposite directions; these point the same "
         "way."),
        correct=1),
    _tf(7, "ch07-continuity-opposite-tangents",
        "A join whose end tangents lie on the same line but point in opposite directions is "
        "$G^1$.", False,
        "$G^1$ needs equal unit tangents, $B'(0) = \\beta A'(1)$ with $\\beta > 0$; opposite "
        "directions make the curve turn back on itself (a cusp).",
        "Right: the direction matters, not only the line."),
    _mc(7, "ch07-continuity-curvature-circle",
        "What is the curvature $\\kappa = \\lVert P' \\times P'' \\rVert / \\lVert P' "
        "\\rVert^3$ of a circle of radius $r$?",
        ("$r$", "The curvature is the inverse of the radius of the osculating circle."),
        ("$1/r$", "With $P = r(\\cos t, \\sin t)$: $|P' \\times P''| = r^2$ and "
         "$|P'|^3 = r^3$."),
        ("$1/r^2$", "The cross product gives $r^2$, divided by $r^3$: one power of $r$ is left."),
        ("It depends on the parametrization", "Curvature is a property of the shape: any "
         "regular parametrization gives $1/r$."),
        correct=1),
    _tf(7, "ch07-continuity-g2-needs-c2",
        "Two cubic segments can be $G^2$ at their join without being $C^1$.", True,
        "$G^2$ fixes the direction of the tangent and the curvature vector, not the speed: "
        "$B'(0) = \\beta_1 A'(1)$, $B''(0) = \\beta_1^2 A''(1) + \\beta_2 A'(1)$ with "
        "$\\beta_1 \\ne 1$ is $G^2$ and not $C^1$.",
        "It can: geometric continuity ignores the speed, so the derivatives may differ."),
    _mc(7, "ch07-matrix-form-t-row",
        "In the matrix form $P(t) = T\\,M\\,G$ of a cubic Bézier curve with the basis "
        "matrix whose first row is $[-1, 3, -3, 1]$, the row $T$ is:",
        ("$[1, t, t^2, t^3]$", "That order belongs to a matrix with its rows reversed; with "
         "this $M$ the first row multiplies $t^3$."),
        ("$[t^3, t^2, t, 1]$", "The first row of $M$ holds the coefficients of $t^3$ "
         "(those of $-P_0 + 3P_1 - 3P_2 + P_3$)."),
        ("$[B_0^3(t), \\dots, B_3^3(t)]$", "Those are the products $T M$, the blending "
         "functions, not $T$."),
        ("$[P_0, P_1, P_2, P_3]$", "That is the geometry $G$."),
        correct=1),
]
