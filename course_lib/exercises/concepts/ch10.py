"""The concept questions of chapter 10 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(10, "ch10-normalize",
        "Data values in $[i_{min}, i_{max}]$ are mapped linearly to $[n_{min}, n_{max}]$. "
        "Which formula?",
        ("$\\frac{i - i_{min}}{i_{max} - i_{min}}(n_{max} - n_{min}) + n_{min}$",
         "First to $[0, 1]$, then stretched to the new width and shifted to start at "
         "$n_{min}$."),
        ("$\\frac{i}{i_{max}}\\, n_{max}$", "It ignores both minimums: right only when both "
         "ranges start at 0."),
        ("$\\frac{i - i_{min}}{i_{max} - i_{min}}(n_{max} - n_{min})$",
         "The shift by $n_{min}$ is missing: the result starts at 0."),
        ("$\\frac{i - i_{min}}{n_{max} - n_{min}}(i_{max} - i_{min}) + n_{min}$",
         "The two widths are swapped."),
        correct=0),
    _tf(10, "ch10-rainbow",
        "The rainbow ('jet') colour map is perceptually uniform: equal steps in the data give "
        "equal perceived colour differences.", False,
        "It is not: its lightness goes up and down (yellow and cyan look bright, blue dark), "
        "creating false bands and hiding real changes. Use viridis-like maps.",
        "Right: jet's lightness is not monotonic, so it invents edges and hides others."),
    _mc(10, "ch10-diverging",
        "Which colour map suits data with a meaningful centre, such as a temperature anomaly "
        "around 0?",
        ("A sequential map (light to dark)", "It suggests an order from low to high, but no "
         "special middle value."),
        ("A qualitative map", "Qualitative maps are for categories without order."),
        ("A diverging map: two hues that meet at a neutral light colour at the centre value",
         "The eye sees at once the sign (hue) and the size (saturation) of the deviation."),
        ("A greyscale map", "Greyscale is sequential: it cannot show the sign around the "
         "centre."),
        correct=2),
    _mc(10, "ch10-qualitative",
        "Which colour map suits **categorical** data (land-use classes, labels)?",
        ("A sequential lightness ramp", "It implies an order the categories do not have."),
        ("A qualitative map of clearly distinct hues of similar lightness", "No class looks "
         "more important or 'larger' than another."),
        ("A diverging map", "It implies a centre and two directions."),
        ("The rainbow map with continuous interpolation", "Interpolating between categories "
         "makes no sense, and it implies order."),
        correct=1),
    _tf(10, "ch10-transfer-function",
        "A transfer function maps data values to visual properties such as colour and "
        "opacity.", True,
        "It is the general mapping; a colour map is a transfer function to colour, and in "
        "volume rendering it gives colour and opacity per sample.",
        "That is what a transfer function is."),
    _tf(10, "ch10-lightness-order",
        "For ordered data a good colour map has a lightness that increases (or decreases) "
        "monotonically.", True,
        "Lightness is the channel we read order from most reliably; a monotonic ramp keeps "
        "the order visible even in greyscale print and for colour-blind viewers.",
        "It is the key design rule of sequential maps (viridis, magma, greys...)."),
    _mc(10, "ch10-colorblind",
        "Which pair of hues is the worst to distinguish important classes for the most common "
        "colour-vision deficiency?",
        ("Blue and orange", "That pair stays distinct for red-green deficiencies; it is a "
         "common safe choice."),
        ("Black and white", "Lightness contrast is seen by everyone."),
        ("Dark blue and light yellow", "They differ strongly in lightness and in the blue-yellow "
         "channel, which red-green deficient viewers keep."),
        ("Red and green of similar lightness", "About 8% of men have a red-green deficiency "
         "and cannot tell these apart."),
        correct=3),
    _tf(10, "ch10-step-transfer",
        "A step (piecewise constant) transfer function can be used to highlight a chosen range "
        "of values.", True,
        "It gives one colour or opacity inside the range and another outside, like a "
        "threshold; smooth ramps avoid the hard edges where needed.",
        "It can: thresholding or banding is exactly a step transfer function."),
    _mc(10, "ch10-log-scale",
        "Data spans six orders of magnitude (from 1 to $10^6$). With a linear colour map, what "
        "happens?",
        ("Nearly all values get the colour of the low end; only the largest ones stand out",
         "Values below $10^4$ occupy 1% of the range; a logarithmic normalization spreads "
         "them out."),
        ("The map works well: linear is always the most honest", "Honest, but it hides all "
         "structure of the small values."),
        ("The values are clipped to $[0, 1]$", "Normalization maps the range, it does not "
         "clip it."),
        ("The colour map becomes diverging", "The kind of map does not change."),
        correct=0),
    # section 10.3: data aspects, grids and scattered data
    _mc(10, "ch10-level-postcode",
        "A table of customers has a column of postcodes (such as 3011, 5612, 9712). What is "
        "their level of measurement?",
        ("Interval: they are numbers with equal steps", "Numbers as symbols are not amounts: "
         "the difference 5612 - 3011 measures nothing."),
        ("Nominal: the digits are a label of an area", "Only 'same or different' means "
         "something; the mean of two postcodes names no place."),
        ("Ordinal: a larger postcode lies further north", "Any such order is an accident of "
         "how the codes were handed out, not a property the data are about."),
        ("Ratio: postcode 0 does not exist", "Ratios of codes are meaningless, and there is no "
         "amount whose absence a zero could mean."),
        correct=1),
    _tf(10, "ch10-celsius-ratio",
        "A temperature of 20 °C is twice as warm as 10 °C.", False,
        "No: °C is an interval scale with an arbitrary zero. In °F the same temperatures are 68 "
        "and 50 (a ratio of 1.36), in kelvin 293.15 and 283.15: only ratios of kelvin "
        "temperatures mean something.",
        "Right: the ratio depends on where the scale puts its zero, so it means nothing; "
        "differences (10 degrees warmer) do."),
    _mc(10, "ch10-grid-least-memory",
        "For the same 100 x 100 samples, which kind of grid stores the fewest numbers to give "
        "the position of every sample?",
        ("Rectilinear", "It stores one coordinate per sample along each axis: 100 + 100 "
         "numbers."),
        ("Curvilinear", "It stores every sample's position: 20,000 numbers."),
        ("Uniform: an origin, a spacing and a count per axis", "Six numbers for 10,000 "
         "positions: every position follows from the index."),
        ("Scattered", "Every position is stored, 20,000 numbers, and still nothing says which "
         "samples are neighbours."),
        correct=2),
    _mc(10, "ch10-scattered-vs-unstructured",
        "What does an unstructured grid store that scattered data do not?",
        ("The positions of the samples", "Both store every position."),
        ("A spacing per axis", "Neither has one: that is what uniform grids store."),
        ("The values at the samples", "Both store values; the difference is the topology."),
        ("The cells: which samples form each triangle or tetrahedron", "With cells a point "
         "can be located in a cell and interpolated from its corners; scattered data first "
         "need neighbours found or a triangulation built."),
        correct=3),
    _mc(10, "ch10-shepard-large-power",
        "In Shepard's method, $s(x) = \\sum w_i f_i / \\sum w_i$ with $w_i = 1/d_i^p$, what "
        "does the interpolant approach as the power $p$ grows very large?",
        ("The mean of all values", "That is the limit $p \\to 0$, where all weights become "
         "equal."),
        ("Nearest-neighbour interpolation: the closest sample's weight dominates all others",
         "The ratio of two weights is $(d_j/d_i)^p$, which goes to 0 for every farther sample, "
         "so the field becomes constant on Voronoi cells."),
        ("Linear interpolation on the Delaunay triangulation", "No weighting by distance "
         "alone gives the barycentric weights of a triangle."),
        ("It diverges: the weights become infinite", "The weights are normalised: only their "
         "ratios matter, and those stay between 0 and 1."),
        correct=1),
    _tf(10, "ch10-shepard-range",
        "Shepard's interpolant (global, with normalised weights) never takes a value below the "
        "smallest or above the largest data value.", True,
        "Right: it is a weighted mean with positive weights that sum to 1, so it stays within "
        "the data's range (unlike radial basis functions, which may overshoot).",
        "It does: normalised positive weights make every value a convex combination of the "
        "data, so it cannot leave their range."),
    _mc(10, "ch10-rbf-coefficients",
        "How are the coefficients $\\lambda_i$ of a radial-basis-function interpolant "
        "$s(x) = \\sum_i \\lambda_i\\,\\phi(\\lVert x - x_i \\rVert)$ found?",
        ("$\\lambda_i = f_i$", "That would interpolate only if the basis functions did not "
         "overlap; they do."),
        ("$\\lambda_i = 1/d_i^p$, as in Shepard's method", "Those are Shepard's weights, "
         "which depend on the query point; RBF coefficients do not."),
        ("By solving the $n \\times n$ linear system $s(x_j) = f_j$, with "
         "$A_{ji} = \\phi(\\lVert x_j - x_i \\rVert)$",
         "Every centre influences every sample, so the coefficients are coupled: one dense "
         "system, $O(n^3)$ to solve directly."),
        ("From the Delaunay triangulation of the samples", "RBFs need no triangulation; that is "
         "linear interpolation."),
        correct=2),
    _tf(10, "ch10-linear-outside-hull",
        "Linear interpolation on the Delaunay triangulation of scattered points gives a value "
        "at every point of the plane.", False,
        "No: the triangles cover only the convex hull of the samples; outside it there is no "
        "triangle and no value (Shepard and RBFs, in contrast, extrapolate).",
        "Right: outside the convex hull of the samples there is no triangle to interpolate in."),
]
