r"""Chapter 10 exercises: the pipeline, data, good plots, tone mapping, multidimensional data.

Each class is one kind of exam question, in the order of the lesson. The visualization
pipeline (10.1-10.2): place actions in its stages and order them, name the step of "overview
first, zoom and filter, details on demand" and the use (exploratory, confirmatory,
presentation) of a scenario. Data (10.3): classify attributes by level of measurement, name the
kind of grid of a data set and count its memory, interpolate scattered samples by Shepard's
method by hand, compare nearest-neighbour and linear values on a triangulation. Good plots
(10.4): the lie factor of a graphic, the data-ink ratio, banking to 45 degrees, the visual
variable for a kind of data. Tone mapping (10.5): normalise values from one range onto another
and undo it; evaluate a piecewise-linear transfer function and a step (thresholding) function;
design an opacity transfer function for a band of values; look a value up in a colour map;
compute the perceived lightness :math:`L^*` of a colour (background: perception, 10.6, is
outside the curriculum); tell from their lightness curves which colour maps can show an ordered
quantity; choose the kind of colour map (sequential, diverging, qualitative) a kind of data
needs. Multidimensional data (10.7): read a parallel-coordinates plot, the point-line duality
both ways, the records a brush selects, a vertex of a star glyph, a principal component
analysis by hand.

For the tone-mapping exercises, the ``seed`` draws numbers that work out by hand: whole
data ranges, values that fall on fifths or quarters of a colour-map interval, colour components in
steps of 0.2.

The expected answers come from :mod:`course_lib.colormaps`. Each exercise names the slips it
anticipates (the offset :math:`c` of the target range forgotten, a division by :math:`b`
instead of :math:`b - a`, a step function read where a linear one was meant, :math:`n` instead
of :math:`n - 1` intervals in a colour map, lightness computed from gamma-encoded values, ...),
computes the answer each slip would give, and draws its numbers again until those answers differ
clearly from the right one and from each other
(:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.colormaps`): colours are sRGB triples in [0, 1]; a colour
map of :math:`n` control colours places them at :math:`t_k = k / (n - 1)` and interpolates
linearly in RGB; a transfer function keeps its end values outside its control points; a step
function takes the value :math:`v_i` on :math:`[s_i, s_{i+1})`.

Every exercise helps on request: ``hint()`` gives the next of its hints, ``solution()`` works
the student's own variant out step by step (see :mod:`course_lib.exercises.core`).

The exercises live in :mod:`course_lib.exercises._ch10`, one module per topic (what the topics
share is in its ``__init__``); import them from here.
"""
from ._ch10.normalisation import Denormalize, NormalizeValues
from ._ch10.transfer import DesignOpacity, ThresholdBands, TransferValues
from ._ch10.colour_maps import ColormapLookup, LightnessOfColour, MonotonicMaps
from ._ch10.map_kinds import MAP_KINDS, SCENARIOS, ChooseMapKind
from ._ch10.pipeline import (MantraStep, OrderPipelineActions, PlacePipelineActions,
                             VisualizationUse)
from ._ch10.integrity import BankingAspect, ChooseVisualVariable, DataInkRatio, LieFactor
from ._ch10.multidim import (BrushSelection, DualLine, DualPoint, ReadParallelCoordinates,
                             StarGlyphVertex)
from ._ch10.pca import CovarianceEigen, ProjectRecord
from ._ch10.data import (GRID_SCENARIOS, ChooseGridKind, ClassifyLevels, GridMemory,
                         NearestVsLinear, ShepardByHand)

__all__ = [
    "EXERCISES",
    "MAP_KINDS",
    "SCENARIOS",
    "ChooseMapKind",
    "ColormapLookup",
    "Denormalize",
    "DesignOpacity",
    "LightnessOfColour",
    "MonotonicMaps",
    "NormalizeValues",
    "ThresholdBands",
    "TransferValues",
    # the pipeline and exploration (10.1, 10.2), good plots (10.4)
    "BankingAspect",
    "ChooseVisualVariable",
    "DataInkRatio",
    "LieFactor",
    "MantraStep",
    "OrderPipelineActions",
    "PlacePipelineActions",
    "VisualizationUse",
    # 10.7 multidimensional data
    "ReadParallelCoordinates",
    "DualLine",
    "DualPoint",
    "BrushSelection",
    "StarGlyphVertex",
    "CovarianceEigen",
    "ProjectRecord",
    # section 10.3, data aspects and scattered data (course_lib/exercises/_ch10/data.py)
    "GRID_SCENARIOS",
    "ChooseGridKind",
    "ClassifyLevels",
    "GridMemory",
    "NearestVsLinear",
    "ShepardByHand",
]

#: The exercises of chapter 10, in the order of the solutions notebook (the lesson's order).
EXERCISES = (
    # the pipeline and exploration (10.1, 10.2)
    PlacePipelineActions,
    OrderPipelineActions,
    MantraStep,
    VisualizationUse,
    # data: levels of measurement, grids, scattered data (10.3)
    ClassifyLevels,
    ChooseGridKind,
    GridMemory,
    ShepardByHand,
    NearestVsLinear,
    # good plots (10.4)
    LieFactor,
    DataInkRatio,
    BankingAspect,
    ChooseVisualVariable,
    # tone mapping: normalisation, transfer functions, colour maps (10.5)
    NormalizeValues,
    Denormalize,
    TransferValues,
    ThresholdBands,
    DesignOpacity,
    ColormapLookup,
    LightnessOfColour,
    MonotonicMaps,
    ChooseMapKind,
    # multidimensional data (10.7)
    ReadParallelCoordinates,
    DualLine,
    DualPoint,
    BrushSelection,
    StarGlyphVertex,
    CovarianceEigen,
    ProjectRecord,
)
