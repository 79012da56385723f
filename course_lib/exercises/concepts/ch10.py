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
]
