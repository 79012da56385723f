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
    # the visualization pipeline and exploration (10.1, 10.2), good plots (10.4)
    _mc(10, "ch10-pipeline-order",
        "In which order do the stages of the visualization pipeline work on the data?",
        ("Filtering and enrichment, data acquisition, mapping, rendering",
         "Nothing can be filtered before it has been acquired (measured or simulated)."),
        ("Data acquisition, mapping, filtering and enrichment, rendering",
         "Filtering and enrichment work on data (numbers); once mapped, the data are "
         "geometry and colours, and cleaning them there is too late."),
        ("Data acquisition, filtering and enrichment, mapping, rendering",
         "Raw data are cleaned and enriched, then turned into geometry with visual "
         "attributes, which the renderer turns into pixels."),
        ("Data acquisition, filtering and enrichment, rendering, mapping",
         "Rendering needs the geometry and colours that mapping produces: it comes last."),
        correct=2),
    _tf(10, "ch10-isosurface-stage",
        "Extracting an isosurface with marching cubes belongs to the rendering stage of the "
        "pipeline.", False,
        "It turns data into geometry (triangles), which is mapping; rendering then projects "
        "and shades those triangles.",
        "Right: marching cubes maps a scalar field to geometry, the mapping stage; rendering "
        "(camera, shading, z-buffer) comes after it."),
    _mc(10, "ch10-mantra",
        "Shneiderman's *visual information-seeking mantra* reads:",
        ("Details first, then context on demand", "The opposite: without an overview one "
         "does not know which details matter."),
        ("Filter, map, render", "Those are stages of the pipeline, not the steps of "
         "exploring."),
        ("Explore, confirm, present", "Those are the three uses of a visualization."),
        ("Overview first, zoom and filter, then details on demand", "See everything reduced, "
         "narrow it to what matters, and ask for exact values only when needed."),
        correct=3),
    _mc(10, "ch10-exploratory-needs",
        "What does an **exploratory** visualization need most?",
        ("Fast, interactive views of all the data, to look in many ways quickly",
         "Without a hypothesis yet, the analyst searches: speed and interaction matter "
         "more than polish."),
        ("A polished, annotated single figure", "That is what a presentation needs, for an "
         "audience that has not seen the data."),
        ("Confidence intervals on every value", "Uncertainty matters most when a hypothesis is "
         "tested (confirmatory analysis)."),
        ("A print-ready colour scheme", "Looks matter for presentation; while exploring, "
         "rough views are fine."),
        correct=0),
    _tf(10, "ch10-radius-honest",
        "Showing values by circles whose radius is proportional to the value is honest: its "
        "lie factor is 1.", False,
        "The eye compares areas, which grow with the square of the radius: a change of 50 % "
        "looks like one of 125 %, a lie factor of 2.5 (in general 2 + e).",
        "Right: the area, which readers compare, grows with the square of the value; make "
        "the area, not the radius, proportional to the value."),
    _mc(10, "ch10-truncated-axis",
        "Bars show 40 (last year) and 50 (this year) on a value axis that starts at 30. What "
        "is the lie factor?",
        ("L = 1: honest", "That is true only for bars drawn from 0. Here the drawn lengths are 10 and 20."),
        ("L = 1.25", "That is the ratio 50 / 40 of the values, not a ratio of effects."),
        ("L = 4", "The drawn lengths grow from 10 to 20, +100 %, for data that grow by +25 %: "
         "100 / 25 = 4."),
        ("L = 2", "That is the ratio of the drawn lengths, 20 / 10; divide the relative changes "
         "instead."),
        correct=2),
    _mc(10, "ch10-data-ink",
        "Which change raises the **data-ink ratio** of a bar chart without losing any data?",
        ("Adding a 3D effect to the bars", "The side and top faces add ink that shows no "
         "value: the ratio falls."),
        ("Erasing the heavy background grid and the frame", "They show no data; without them "
         "a larger share of the ink is data ink."),
        ("Adding a picture behind the bars", "Decoration (chartjunk) adds non-data ink."),
        ("Erasing every second bar", "That raises nothing: it loses data."),
        correct=1),
    _tf(10, "ch10-banking",
        "Banking to 45° chooses a line chart's aspect ratio so that its segments are, on "
        "average, at 45°, where differences in slope are judged best.", True,
        "Cleveland's experiments: slopes near 45° are compared most accurately; a too flat "
        "chart hides changes, a too tall one makes all of them look alike.",
        "It is exactly that: the aspect ratio is chosen from the data so that the (median or "
        "average) absolute orientation of the segments is 45°."),
    _mc(10, "ch10-visual-variable-nominal",
        "On a map (position is taken) you want to show which party won each district. Which "
        "visual variable suits these **nominal** data best?",
        ("Lightness (value)", "Lightness has an order: the darker party would look like "
         "'more'."),
        ("Size", "Size implies an order and amounts that parties do not have."),
        ("Texture density", "Density is read as an order, which the parties do not have."),
        ("Colour hue", "Distinct hues separate categories at a glance without implying an "
         "order."),
        correct=3),
    _tf(10, "ch10-small-multiples-scales",
        "In small multiples each panel should get its own vertical scale, fitted to its data, "
        "so that no space is wasted.", False,
        "Small multiples are read by comparing panels; with different scales the same height "
        "means different values and the comparison misleads. Use one common scale.",
        "Right: the panels share one scale, so that equal heights mean equal values."),
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
