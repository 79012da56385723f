r"""Chapter 10: normalisation, transfer functions and colour maps, with perceptual checks.

Visualization turns numbers into something the eye can read. Before a value can become a grey
level, a colour or an opacity, it is first brought to a common scale, then mapped through a
function the visualizer chooses:

* :func:`normalize`: the **linear normalisation** that maps the data range :math:`[a, b]`
  onto a target range :math:`[c, d]`,

  .. math:: n(v) = \frac{v - a}{b - a}\,(d - c) + c .

  Subtracting :math:`a` moves the smallest value to 0, dividing by :math:`b - a` brings the
  data to :math:`[0, 1]`, and scaling by :math:`d - c` and adding :math:`c` lands it on the
  target interval. A constant field (:math:`a = b`) has no spread to scale: we map it to the
  middle of the target range rather than divide by zero.
* :class:`TransferFunction`: a **transfer function** assigns each data value an output: an
  intensity (tone mapping), a colour, an opacity, or all of them (RGBA). Ours are
  piecewise-linear between control points (``kind="linear"``), or piecewise-constant
  (``kind="step"``, a *thresholding* or banding of the data); a point repeated twice in a
  linear function makes a jump. :func:`opacity_transfer` and :func:`color_transfer` check
  that opacities and colours lie in [0, 1]; :func:`rgba_transfer` joins a colour function
  and an opacity function into one RGBA function (exactly, on the union of their control
  points), and :func:`transfer_preset` has ready-made ones for CT-like volumes.
* :func:`apply_colormap`: a **colour map** is a transfer function from normalised values
  :math:`t \in [0, 1]` to colours, given here as :math:`n` control colours spaced evenly in
  :math:`t` and interpolated linearly in RGB. :data:`COLORMAP_NAMES` lists the maps shipped:
  the classic grey ramp, rainbow (the hue sweep blue - cyan - green - yellow - red of
  HSV), jet, hot (black - red - yellow - white), the diverging blue-white-red and cool-warm,
  and matplotlib's perceptually designed viridis, magma, inferno, plasma, cividis and turbo.
  Append ``"_r"`` to a name to reverse a map.

**Why the choice of colour map matters.** The eye reads *lightness* as magnitude far more
reliably than hue: hue has no natural order (is green more than yellow?), while darker-to-lighter
is read as less-to-more by everybody, and survives a black-and-white print and most forms of
colour blindness. A good map for ordered data has lightness that changes monotonically and
evenly along the map. The rainbow and jet maps do not: their lightness goes up and down (yellow
and cyan are much lighter than blue and red), which paints false edges into smooth data
(bands appear where the lightness jumps) and hides real features where it is flat.

The module measures this with the CIE colour spaces:

* :func:`srgb_to_linear`, :func:`srgb_to_xyz`, :func:`xyz_to_lab`, :func:`srgb_to_lab`:
  sRGB values are gamma-encoded; undoing the encoding gives linear light, a 3x3 matrix gives
  the CIE XYZ tristimulus values (D65 white), and a cube-root compression gives CIE L*a*b*,
  where :math:`L^*` (0 black .. 100 white) is perceived lightness and Euclidean distances
  approximate perceived colour differences.
* :func:`lightness` gives :math:`L^*` along a map, :func:`is_monotonic_lightness` the verdict,
  :func:`perceptual_steps` the colour difference :math:`\Delta E^*_{ab}` between neighbouring
  samples (even steps = perceptually uniform), :func:`luminance` and :func:`greyscale` what the
  map looks like printed in black and white.

Conventions
-----------
Colours are RGB triples of floats in [0, 1], **sRGB** (gamma-encoded, as stored in images and
shown by matplotlib), in the last axis of an array. Colour maps are ``(n, 3)`` arrays of control
colours at :math:`t_k = k / (n - 1)`.

**Missing data (NaN)** is common in measured fields. :func:`normalize` propagates NaN (a NaN
in gives a NaN out, and the range is taken over the other values); :func:`apply_colormap`
paints NaNs in a separate, conspicuous ``nan_color`` (magenta by default) so that holes in the
data stay visible instead of taking some colour of the map. Infinite values are rejected with
a ``ValueError``. Transfer functions, colour conversions and the volume algorithms of
:mod:`course_lib.scivis` reject NaN with a ``ValueError``.

The perceptual maps were sampled from matplotlib once, when this module was written: 64
control colours per map fitted by least squares to matplotlib's 256-entry tables and rounded to
4 decimals. At matplotlib's own sample points they agree within 3/255 per channel (less than
three steps of an 8-bit channel: 0.0101 for jet, whose kinks fall between control points, under
0.009 for the others; the root-mean-square difference is under 0.002); the grey, rainbow and
blue-white-red maps are exact, hot exact to 4 decimals.

Files
-----

``normalisation.py``
    Chapter 10 (lesson section 2): normalising data values onto [0, 1].
``transfer.py``
    Chapter 10 (lesson sections 3, 6): transfer functions from data values to colour and
    opacity, and applying a colour map with an opacity to data.
``maps.py``
    Chapter 10 (lesson section 4): colour maps: look-up, reversal, building from control
    colours.
``colour_science.py``
    Chapter 10 (lesson section 5): sRGB, linear RGB, CIE XYZ, CIE L*a*b* and colour
    differences.
``_data.py``
    Chapter 10: the control colours of the built-in colour maps.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from .normalisation import (normalize)
from ._data import (COLORMAP_NAMES)
from .maps import (colormap, sample_colormap)
from .transfer import (TransferFunction, apply_colormap, color_transfer, opacity_transfer,
    rgba_transfer, transfer_preset)
from .colour_science import (D65_WHITE, delta_e, greyscale, is_monotonic_lightness, lightness,
    linear_to_srgb, luminance, perceptual_steps, srgb_to_lab, srgb_to_linear, srgb_to_xyz,
    xyz_to_lab)

__all__ = [
    "COLORMAP_NAMES",
    "D65_WHITE",
    "TransferFunction",
    "apply_colormap",
    "color_transfer",
    "colormap",
    "delta_e",
    "greyscale",
    "is_monotonic_lightness",
    "lightness",
    "linear_to_srgb",
    "luminance",
    "normalize",
    "opacity_transfer",
    "perceptual_steps",
    "rgba_transfer",
    "sample_colormap",
    "srgb_to_lab",
    "srgb_to_linear",
    "srgb_to_xyz",
    "transfer_preset",
    "xyz_to_lab",
]
