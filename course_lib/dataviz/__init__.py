r"""Chapter 10: visualization principles: the pipeline, data, good plots, multidimensional data.

(Normalisation, transfer functions and colour maps, the chapter's tone mapping, are in
:mod:`course_lib.colormaps`.)

* :mod:`~course_lib.dataviz.pipeline`: the stages of the visualization pipeline (data
  acquisition, filtering and enrichment, mapping, rendering) and which actions belong where;
  the uses of a visualization (exploratory, confirmatory, presentation).
* :mod:`~course_lib.dataviz.data_types`: levels of measurement (nominal, ordinal, interval,
  ratio), what each permits, and the dimensionality of a data set's domain and values.
* :mod:`~course_lib.dataviz.grids`: the kinds of grid (uniform, rectilinear, curvilinear,
  unstructured, scattered), telling them apart, and interpolating on them.
* :mod:`~course_lib.dataviz.scattered`: interpolating scattered data: nearest neighbour,
  linear on a Delaunay triangulation, Shepard's inverse-distance weighting, radial basis
  functions.
* :mod:`~course_lib.dataviz.integrity`: graphical integrity: the lie factor of a drawn
  encoding, the data-ink ratio, banking to 45 degrees, visual variables and the data they suit.
* :mod:`~course_lib.dataviz.multidim`: multidimensional data: scatterplot matrices, parallel
  coordinates and their point-line duality, glyphs (star plots, Chernoff faces), brushing.
* :mod:`~course_lib.dataviz.projection`: projection by principal components (PCA).

Conventions
-----------
A **table of records** is an array of shape ``(n, d)``: one row per record (an observation),
one column per variable (an *attribute*, a *dimension*), with a tuple of ``d`` names beside it.
Points of a domain are arrays of shape ``(n, 2)`` or ``(n, 3)``; values beside them ``(n,)``
or ``(n, k)``. Randomness is seeded (``seed=``) and the same on every CPU.
"""
from .pipeline import *  # noqa: F401,F403
from .data_types import *  # noqa: F401,F403
from .grids import *  # noqa: F401,F403
from .scattered import *  # noqa: F401,F403
from .integrity import *  # noqa: F401,F403
from .multidim import *  # noqa: F401,F403
from .projection import *  # noqa: F401,F403
from . import data_types, grids, integrity, multidim, pipeline, projection, scattered

__all__ = sorted(pipeline.__all__ + data_types.__all__ + grids.__all__ + scattered.__all__
                 + integrity.__all__ + multidim.__all__ + projection.__all__)
