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
    # 10.7 multidimensional data
    _mc(10, "ch10-pc-negative",
        "Two adjacent axes of a parallel-coordinates plot show two attributes with a strong "
        "**negative** correlation. What do the records' lines between them look like?",
        ("Nearly parallel lines", "That is a positive correlation: high values go with high "
         "values, so every line runs from high to high (or low to low) and they stay side by "
         "side."),
        ("Lines that cross near one point between the two axes", "A record high on one axis is "
         "low on the other, so the order reverses and every pair of lines crosses; for an "
         "exact linear relation all lines pass through one point, at u = 1/(1 - m') with "
         "m' < 0, between the axes."),
        ("Lines that fan out from one point on the first axis", "Lines meet on an axis only "
         "when the records share that attribute's value."),
        ("Randomly crossing lines with no pattern", "That is what no correlation looks like: "
         "about half of the pairs cross, at scattered places."),
        correct=1),
    _tf(10, "ch10-pc-duality",
        "In parallel coordinates a point of the plane becomes a line, and the points of a "
        "straight line y = m x + c become lines that all pass through one common point (or "
        "are all parallel).", True,
        "Right: that is the point-line duality. With normalised slope m' the lines meet at "
        "u = 1/(1 - m'); for m' = 1 they are parallel (the point lies at infinity).",
        "It does hold: the line of (a, b) is v = a' + (b' - a')u, and for b' = m'a' + c' every "
        "such line passes through (1/(1 - m'), c'/(1 - m')), whatever a'."),
    _tf(10, "ch10-pc-order",
        "In a parallel-coordinates plot the relation between any two attributes can be read "
        "equally well, whatever the order of the axes.", False,
        "Only **adjacent** axes can be compared directly: the lines between two neighbouring "
        "axes show their relation, while non-adjacent pairs are hidden behind the axes in "
        "between. That is why tools let you reorder (and flip) axes.",
        "Right: only neighbouring axes show their relation; d attributes have d(d-1)/2 pairs "
        "but only d - 1 are neighbours in one order, so axes are reordered to explore."),
    _mc(10, "ch10-splom-count",
        "A scatterplot matrix shows d = 6 attributes. How many **different** scatter plots "
        "does it contain (a plot and its mirror image across the diagonal count once)?",
        ("36", "That counts all d x d panels, the diagonal (an attribute against itself) and "
         "both mirror images of every pair."),
        ("30", "That counts both triangles: the panel (i, j) is the panel (j, i) with its axes "
         "swapped."),
        ("15", "One per pair of attributes: d(d - 1)/2 = 6 x 5 / 2."),
        ("6", "That is the diagonal: one panel per attribute, usually a histogram or the "
         "name."),
        correct=2),
    _mc(10, "ch10-pca-first",
        "What is the first principal component of a table of records?",
        ("The attribute with the largest variance", "PCA looks for the best direction among "
         "all combinations of the attributes, not only the attribute axes."),
        ("The unit eigenvector of the covariance matrix with the largest eigenvalue: the "
         "direction along which the centred records spread most",
         "Maximising w^T C w with |w| = 1 gives C w = lambda w; the variance along w is "
         "lambda, largest for the first eigenvector."),
        ("The mean of the records", "The mean is subtracted first (centring); it is not a "
         "direction."),
        ("The eigenvector of the smallest eigenvalue", "That is the direction of the least "
         "spread: the last component, the one a projection drops first."),
        correct=1),
    _tf(10, "ch10-pca-standardise",
        "Before a PCA of attributes measured in very different units (a length in millimetres, "
        "a mass in tonnes), it is usually wise to standardise each attribute (divide by its "
        "standard deviation).", True,
        "Right: otherwise the attribute with the numerically largest spread dominates the "
        "first component just because of its unit; standardised, PCA works on the correlation "
        "matrix.",
        "It is wise: PCA follows the variance, and variance depends on the unit; millimetres "
        "give a spread a million times that of kilometres."),
    _tf(10, "ch10-brush-and-or",
        "Combining two brushes with AND always selects at least as many records as combining "
        "them with OR.", False,
        "It is the other way round: AND keeps the records inside both brushes, a subset of "
        "those inside either (OR).",
        "Right: the AND selection is contained in the OR selection."),
    _mc(10, "ch10-chernoff",
        "What is the main weakness of Chernoff faces as glyphs for multidimensional data?",
        ("They can show at most three attributes", "A face has many features (width, eyes, "
         "brows, nose, mouth...); a dozen or more attributes can be mapped."),
        ("People do not perceive the facial features equally: which attribute drives which "
         "feature changes what stands out, and some features (the mouth) dominate",
         "The mapping is arbitrary and the features are not perceptually comparable, so two "
         "mappings of the same data give different impressions."),
        ("They need a 3D display", "They are flat drawings."),
        ("They only work for categorical data", "Each feature varies continuously with a "
         "normalised numeric value."),
        correct=1),
]
