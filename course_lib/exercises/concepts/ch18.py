"""The concept questions of chapter 18 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(18, "ch18-ms-ambiguous",
        "How many of the 16 marching-squares cases are ambiguous?",
        ("None", "The saddle cases are ambiguous."),
        ("Four", "Only the two checkerboard patterns are ambiguous."),
        ("Eight", "Most cases have a single way to connect the crossings."),
        ("Two: the diagonal cases, where opposite corners are inside", "Both the 'joined' and "
         "the 'separated' pair of segments are consistent with the corner signs; the cell "
         "average (or the asymptotic decider) chooses."),
        correct=3),
    _mc(18, "ch18-mc-cases",
        "Marching cubes has $2^8 = 256$ corner configurations. Using rotations and swapping "
        "inside with outside, how many distinct cases remain?",
        ("8", "Far too few: the cases differ in how many and which corners are inside."),
        ("256", "Symmetry collapses most of them."),
        ("15", "The classic table of 15 base cases (including the empty one) generates all "
         "256."),
        ("23", "That is the count with rotations only, without complementation."),
        correct=2),
    _tf(18, "ch18-mc-holes",
        "The original marching-cubes table can produce holes in the surface, because "
        "neighbouring cubes may resolve an ambiguous shared face differently.", True,
        "On a face with a saddle pattern the two cubes must agree on the connection; the "
        "asymptotic decider or extended tables fix this.",
        "It can: this is the known face-ambiguity problem of marching cubes."),
    _tf(18, "ch18-streamline-tangent",
        "A streamline is everywhere tangent to the velocity field at one instant.", True,
        "That is its definition; in a steady flow streamlines, pathlines and streaklines "
        "coincide.",
        "It is the definition of a streamline."),
    _tf(18, "ch18-streamlines-cross",
        "Two different streamlines of a steady, smooth vector field can cross at a point where "
        "the velocity is non-zero.", False,
        "They cannot: at such a point the field has one direction, and the solution through it "
        "is unique. Streamlines only meet at critical points (zero velocity).",
        "Right: uniqueness of solutions forbids crossings away from critical points."),
    _mc(18, "ch18-euler-integration",
        "Streamlines of a pure rotation $v = (-y, x)$ are circles. What does explicit Euler "
        "integration produce?",
        ("Exact circles", "Euler steps along the tangent leave the circle at every step."),
        ("An inward spiral", "Each tangent step moves *outward*: $|p + h v|^2 = (1 + h^2)|p|^2$."),
        ("An outward spiral: the radius grows by $\\sqrt{1 + h^2}$ per step",
         "A first-order method drifts; Runge-Kutta 4 is far more accurate for the same step."),
        ("A straight line", "It turns, though not enough."),
        correct=2),
    _mc(18, "ch18-front-to-back",
        "Why composite volume samples front to back in ray casting?",
        ("It allows early ray termination: stop once the accumulated opacity is close to 1",
         "Samples behind an almost opaque layer cannot change the pixel."),
        ("It gives a different (more correct) image than back to front", "Both orders give "
         "the same result, with the matching formulas."),
        ("It avoids the transfer function", "The transfer function is still needed to classify "
         "samples."),
        ("It makes the volume transparent", "Opacity comes from the transfer function."),
        correct=0),
    _tf(18, "ch18-isosurface-vs-dvr",
        "Direct volume rendering needs an intermediate polygonal surface, as marching cubes "
        "does.", False,
        "It does not: it casts rays through the volume and composites the colours and "
        "opacities of the samples; marching cubes extracts a surface.",
        "Right: direct volume rendering works on the samples, without polygons."),
    _mc(18, "ch18-ms-interp",
        "Where does marching squares put the isoline's crossing on a cell edge with corner "
        "values $f_0$ and $f_1$?",
        ("At the edge midpoint, always", "That is the cheap variant; it gives jagged lines."),
        ("At $t = \\frac{c - f_0}{f_1 - f_0}$ from the first corner (linear interpolation)",
         "Where the linear interpolation of the corner values equals the isovalue $c$."),
        ("At the corner with the larger value", "The crossing lies between the corners."),
        ("At $t = \\frac{f_1 - c}{f_1 - f_0}$", "Measured from the first corner this is "
         "$1 - t$: the crossing lands mirrored."),
        correct=1),
    _tf(18, "ch18-glyph-clutter",
        "Arrow glyphs drawn at every grid point of a dense vector field give the clearest "
        "picture.", False,
        "Dense glyphs overlap and clutter the view; subsample, or use streamlines or texture "
        "methods (LIC) for dense fields.",
        "Right: glyphs must be spaced out; otherwise they clutter."),
    # unsteady flow and line integral convolution
    _tf(18, "ch18-pathline-tangent",
        "In a time-dependent flow, a pathline is tangent at each of its points to the "
        "streamline through that point of the field frozen at the moment the particle passes "
        "there.", True,
        "The particle moves with the velocity v(x, t) of where and when it is, and a streamline "
        "of the field frozen at t has that direction at x. It touches that streamline only "
        "there: a moment later the particle follows another instant's field, which is why the "
        "two curves differ as a whole.",
        "It is true: dx/dt = v(x, t) is the direction of the frozen field's streamline at that "
        "point and time; the curves only differ as a whole."),
    _mc(18, "ch18-rotating-flow",
        "A uniform flow has speed U everywhere, and its direction turns at the constant rate "
        "ω. What is the pathline of a particle?",
        ("A straight line", "That is a streamline: at each instant the field is uniform, so "
         "its streamlines are straight, but the direction keeps turning."),
        ("A circle of radius U/ω", "The particle's velocity has constant length U and "
         "turns at the rate ω, like a point on a circle of radius U/ω."),
        ("An outward spiral", "The speed does not grow and the turning rate is constant: the "
         "curvature ω/U is constant, so the path closes."),
        ("The particle stays where it is", "The velocity is never zero: the particle moves "
         "with speed U all the time."),
        correct=1),
    _mc(18, "ch18-lic-kernel",
        "In line integral convolution, what happens when the kernel length L is increased?",
        ("The streaks get longer and smoother, and the contrast drops",
         "Each pixel averages more noise samples along its streamline (2L/h + 1), so the "
         "values vary less and neighbours along a streamline share more of them."),
        ("The picture turns back into the white noise", "That is the other end: with L close "
         "to 0 each pixel keeps its own noise value."),
        ("The colour starts to show the speed", "LIC uses only the direction; speed has to be "
         "added separately, e.g. by colour."),
        ("The streamlines get straighter", "The traces follow the field whatever their length; "
         "a longer kernel follows a curved streamline further."),
        correct=0),
    _tf(18, "ch18-lic-orientation",
        "A LIC image (with a symmetric kernel) shows along which lines the flow runs, but not "
        "which way along them it goes nor how fast.", True,
        "Reversing or scaling the field gives the same streamlines and the same average of the "
        "noise along them; orientation and speed need extra cues (animation of the kernel "
        "phase, arrows, colour).",
        "It is true: v and -v (or 2v) give the same picture, as only the streamline through "
        "each pixel matters."),
    # --- vector-field topology ---
    _mc(18, "ch18-topology-det-negative",
        "At a critical point of a 2D vector field the Jacobian has a negative determinant. "
        "What kind of point is it?",
        ("A saddle: the eigenvalues are real with opposite signs",
         "Their product is the determinant; a negative product needs one positive and one "
         "negative real eigenvalue, whatever the trace."),
        ("An attracting node", "A node has eigenvalues of one sign, so a positive determinant."),
        ("A focus", "A focus has a complex pair, whose product $|\\lambda|^2$ is positive."),
        ("It depends on the sign of the trace", "Only when the determinant is positive: then the "
         "trace decides attracting or repelling."),
        correct=0),
    _tf(18, "ch18-topology-centre-grid",
        "A centre found in a sampled (gridded) field is a robust result: small errors in the "
        "samples keep it a centre.", False,
        "A centre needs a trace of exactly 0; any small perturbation makes the real part of "
        "the eigenvalues non-zero and turns it into a weak focus, attracting or repelling.",
        "Right: the centre is the one class that sits on a boundary (trace 0) of the "
        "trace-determinant plane, so noise moves it into a focus."),
    _mc(18, "ch18-topology-separatrix",
        "How are the separatrices of a saddle traced?",
        ("Forward from the saddle itself", "The velocity is zero there: the line never "
         "starts."),
        ("Along the gradient of the speed", "Separatrices are streamlines, tangent to the "
         "velocity, not to a gradient."),
        ("Forward from seeds a small step along the eigenvector of the positive eigenvalue, "
         "backward from seeds along the eigenvector of the negative one",
         "The flow leaves along the unstable eigenvector and arrives along the stable one; "
         "integrating backward follows the arriving curves out of the saddle."),
        ("Forward along both eigenvectors", "Along the stable eigenvector the forward flow "
         "runs back into the saddle: those two curves must be traced backward."),
        correct=2),
    # Issue 22, volume methods: the asymptotic decider, normals, splatting, slicing, classification
    _mc(18, "ch18-asymptotic-decider",
        "A marching-squares cell has corners $f_0 = 0$, $f_1 = 4$, $f_2 = 0$, $f_3 = 10$ "
        "(counter-clockwise from the bottom left) and the level is 3. What does the asymptotic "
        "decider do?",
        ("Joins corners 1 and 3 through the cell, since the mean 3.5 is above 3",
         "That is the midpoint decider; the asymptotic decider uses the saddle value."),
        ("Keeps corners 1 and 3 apart: the saddle value $(0 - 40)/(0 - 14) \\approx 2.86$ is "
         "below 3", "The bilinear field dips below the level between them, so the below "
         "corners 0 and 2 are the ones joined."),
        ("Joins corners 0 and 2 because their values are equal", "Equal values say nothing; "
         "the comparison of the saddle value with the level decides."),
        ("Nothing: the cell is not ambiguous", "Corners 1 and 3 are above and 0 and 2 below: "
         "a saddle (case 10)."),
        correct=1),
    _tf(18, "ch18-central-difference-quadratic",
        "The central difference $(f_{i+1} - f_{i-1})/2h$ gives the exact derivative of a "
        "quadratic, whereas the forward difference $(f_{i+1} - f_i)/h$ is off by $a h$ for "
        "$f = a x^2$.", True,
        "The $h^2$ terms of the two neighbours cancel in the central difference; the forward "
        "difference keeps the term $a h$ (first-order error).",
        "It is true: the central difference is second-order accurate."),
    _mc(18, "ch18-splat-order",
        "Splatting composites sheets of splats back to front with the *over* operator "
        "$C \\leftarrow c + (1 - \\alpha) C$. What happens if the sheets are traversed front "
        "to back but the over operator is kept?",
        ("The same image: compositing order does not matter",
         "It matters: over puts each new layer in front of what is there."),
        ("The volume appears as seen from behind: the depth order is reversed",
         "Each later (farther) sheet is painted over the nearer ones."),
        ("The image gets more transparent", "The accumulated opacity is the same in any order; "
         "only the colours change."),
        ("Early termination stops the rendering too early", "Over does not terminate early."),
        correct=1),
    _mc(18, "ch18-slice-opacity",
        "View-aligned slices are made twice as dense. A slice used to have opacity $\\alpha$; "
        "what must its opacity become so that the picture stays the same?",
        ("$\\alpha / 2$", "Opacities do not add: two slices of $\\alpha/2$ let "
         "$(1 - \\alpha/2)^2 \\ne 1 - \\alpha$ through."),
        ("$1 - (1 - \\alpha)^{1/2}$", "Then two slices let $(1 - \\alpha)^{1/2 \\cdot 2} = "
         "1 - \\alpha$ through, as one did (opacity correction)."),
        ("$\\alpha$", "Twice as many slices of the same opacity make the volume more opaque."),
        ("$\\alpha^2$", "That makes it more transparent than the right value."),
        correct=1),
    _tf(18, "ch18-pre-post-classification",
        "With a transfer function that jumps from transparent to opaque at one value, "
        "classifying the voxels first and interpolating their colours (pre-classification) "
        "renders the same thin surface as interpolating the values and classifying each "
        "sample (post-classification).", False,
        "Pre-classification interpolates between a transparent and an opaque voxel, smearing "
        "the step over whole cells (blocky, blurred rims); post-classification finds the step "
        "inside the cell.",
        "False: the two orders agree only for transfer functions linear in the value."),
]
