"""Chapter 12 (lesson sections 3.1, 3.2): materials and light sources of the local illumination
model."""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_rgb, as_scalar, as_vector
from ._common import _shininess, _unit

__all__ = ["Light", "Material", "attenuation", "colored_material", "directional_light",
    "material_per_point", "point_light"]


# ---------------------------------------------------------------------------------------------
# Materials and lights
# ---------------------------------------------------------------------------------------------

class Material(NamedTuple):
    r"""The reflection coefficients of a surface in the Phong model.

    Each coefficient is a number (grey), an RGB triple, or per-point RGB values of shape
    ``(..., 3)`` broadcasting against the shaded points (for a ray tracer's hits on different
    objects; see :func:`material_per_point`). The coefficients :math:`k_a, k_d, k_s` must lie in
    [0, 1] (fractions of the incoming light); :func:`phong` checks them. :math:`k_d + k_s \le 1`
    keeps a surface from reflecting more light than it receives; that is not enforced.

    Attributes
    ----------
    ka : float or array_like
        Ambient reflection coefficient :math:`k_a` (default 0.1).
    kd : float or array_like
        Diffuse reflection coefficient :math:`k_d` (default 0.7): the surface's colour.
    ks : float or array_like
        Specular reflection coefficient :math:`k_s` (default 0.2): the highlight's colour
        (white for plastics, the metal's colour for metals).
    shininess : float or array_like
        The specular exponent :math:`n > 0` (default 32); per point shape ``(...)``.
    emission : float or array_like
        Emitted light :math:`I_e \ge 0` (default 0).

    Examples
    --------
    >>> Material(kd=(0.8, 0.1, 0.1), shininess=50)
    Material(ka=0.1, kd=(0.8, 0.1, 0.1), ks=0.2, shininess=50, emission=0.0)
    """
    ka: object = 0.1
    kd: object = 0.7
    ks: object = 0.2
    shininess: object = 32.0
    emission: object = 0.0


def colored_material(color, ka=0.1, kd=0.7, ks=0.2, shininess=32.0, specular_color=1.0,
                     emission=0.0):
    """A :class:`Material` of a given colour: ``ka * color``, ``kd * color``,
    ``ks * specular_color``.

    Parameters
    ----------
    color : float or array_like, shape (3,)
        The surface colour (RGB in [0, 1]); it tints the ambient and diffuse terms.
    ka, kd, ks : float
        Scalar coefficients in [0, 1].
    shininess : float
        Specular exponent, positive.
    specular_color : float or array_like, shape (3,)
        Colour of the highlight (default white, as for plastic).
    emission : float or array_like, shape (3,)

    Returns
    -------
    Material

    Raises
    ------
    ValueError
        For a colour or coefficient outside [0, 1], or a non-positive shininess.

    Examples
    --------
    >>> m = colored_material((1.0, 0.5, 0.0), kd=0.6)
    >>> m.kd
    array([0.6, 0.3, 0. ])
    """
    color = as_rgb(color, "color")
    specular_color = as_rgb(specular_color, "specular_color")
    ka, kd, ks = (as_scalar(k, name) for k, name in ((ka, "ka"), (kd, "kd"), (ks, "ks")))
    for k, name in ((ka, "ka"), (kd, "kd"), (ks, "ks")):
        if not 0 <= k <= 1:
            raise ValueError(f"{name} must lie in [0, 1], got {k:g}")
    return Material(ka * color, kd * color, ks * specular_color,
                    float(_shininess(shininess)), as_rgb(emission, "emission", maximum=None))


def material_per_point(materials, ids):
    """One material per point from a list of materials and each point's material index.

    A ray tracer hits several objects, each with its own material: gather the coefficients of
    each hit into arrays so that one call of :func:`phong` shades all hits.

    Parameters
    ----------
    materials : sequence of Material
    ids : array_like of int, shape (...)
        The index into `materials` of each point.

    Returns
    -------
    Material
        With colour fields of shape ``(..., 3)`` and shininess of shape ``(...)``.

    Raises
    ------
    ValueError
        For an empty list or an index out of range.

    Examples
    --------
    >>> m = material_per_point([Material(kd=0.5), Material(kd=(1, 0, 0), shininess=8)], [1, 0, 1])
    >>> m.kd
    array([[1. , 0. , 0. ],
           [0.5, 0.5, 0.5],
           [1. , 0. , 0. ]])
    >>> m.shininess
    array([ 8., 32.,  8.])
    """
    materials = [materials] if isinstance(materials, Material) else list(materials)
    if not materials or not all(isinstance(m, Material) for m in materials):
        raise ValueError("materials must be a non-empty sequence of Material")
    ids = np.asarray(ids)
    if not np.issubdtype(ids.dtype, np.integer):
        raise ValueError(f"ids must be integer indices into materials, got type {ids.dtype}")
    if ids.size and (ids.min() < 0 or ids.max() >= len(materials)):
        raise ValueError(f"ids must lie in [0, {len(materials) - 1}], got "
                         f"{int(ids.min() if ids.min() < 0 else ids.max())}")
    fields = {}
    for field in ("ka", "kd", "ks", "emission"):
        rows = []
        for m in materials:
            c = as_rgb(getattr(m, field), field, maximum=None)
            if c.shape not in ((3,), (1,)):
                raise ValueError(f"{field} of each material must be one colour, got shape "
                                 f"{c.shape}")
            rows.append(np.broadcast_to(c, (3,)))
        fields[field] = np.array(rows)[ids]
    shin = []
    for m in materials:
        s = _shininess(m.shininess)
        if s.ndim:
            raise ValueError(f"shininess of each material must be one number, got shape {s.shape}")
        shin.append(float(s))
    return Material(fields["ka"], fields["kd"], fields["ks"], np.array(shin)[ids],
                    fields["emission"])


class Light(NamedTuple):
    r"""A light source: a point light (``position``) or a directional light (``direction``).

    Build it with :func:`point_light` or :func:`directional_light`.

    **Separate colours** (the textbook's light model, as in OpenGL's fixed pipeline): a light
    may give a different colour to each term it feeds. ``diffuse`` :math:`I_{d,l}` multiplies
    :math:`k_d (N \cdot L)`, ``specular`` :math:`I_{s,l}` multiplies :math:`k_s (R \cdot V)^n`,
    and ``ambient`` :math:`I_{a,l}` adds :math:`k_a I_{a,l}` to the ambient term (light the lamp
    spreads around the room, arriving from everywhere). Both ``diffuse`` and ``specular``
    default to ``intensity``, and ``ambient`` to 0, so a light built with one intensity behaves
    as the single-colour model :math:`I_l [k_d (N \cdot L) + k_s (R \cdot V)^n]`.

    Attributes
    ----------
    position : ndarray, shape (3,), or None
        Where a point light is.
    direction : ndarray, shape (3,), or None
        For a directional light: the unit vector *towards* the light (the L of every point).
    intensity : ndarray, shape (3,)
        The light's RGB intensity :math:`I_l` (may exceed 1 for a bright light): the default of
        ``diffuse`` and ``specular``.
    attenuation : tuple of float
        :math:`(a, b, c)` of :math:`f_{att}(d) = 1/(a + b d + c d^2)`.
    ambient : ndarray, shape (3,)
        :math:`I_{a,l}`, the light's contribution to the ambient light (default 0).
    diffuse : ndarray, shape (3,), or None
        :math:`I_{d,l}`, the colour of the diffuse light (None: ``intensity``).
    specular : ndarray, shape (3,), or None
        :math:`I_{s,l}`, the colour of the highlight (None: ``intensity``).

    Examples
    --------
    >>> point_light([0, 5, 0]).position
    array([0., 5., 0.])
    >>> lamp = point_light([0, 5, 0], diffuse=(1, 0.8, 0.6), specular=1, ambient=0.05)
    >>> lamp.diffuse, lamp.specular, lamp.ambient
    (array([1. , 0.8, 0.6]), array([1., 1., 1.]), array([0.05, 0.05, 0.05]))
    """
    position: object
    direction: object
    intensity: np.ndarray
    attenuation: tuple
    ambient: object = np.zeros(3)
    diffuse: object = None
    specular: object = None

    def colours(self):
        """The light's (ambient, diffuse, specular) RGB colours, the defaults filled in.

        Examples
        --------
        >>> [c.tolist() for c in directional_light([0, 0, 1], intensity=0.5).colours()]
        [[0.0, 0.0, 0.0], [0.5, 0.5, 0.5], [0.5, 0.5, 0.5]]
        """
        intensity = _light_colour(self.intensity, "intensity")
        ambient = _light_colour(self.ambient, "ambient")
        diffuse = _light_colour(self.diffuse, "diffuse")
        specular = _light_colour(self.specular, "specular")
        return (np.zeros(3) if ambient is None else ambient,
                intensity if diffuse is None else diffuse,
                intensity if specular is None else specular)


def _attenuation_coefficients(value):
    abc = as_vector(value, "attenuation", 3)
    if np.any(abc < 0) or not np.any(abc > 0):
        raise ValueError(f"attenuation must be (a, b, c) >= 0, not all zero (f_att = 1 / (a + "
                         f"b d + c d^2)), got {tuple(abc.tolist())}")
    return tuple(abc.tolist())


def _light_colour(value, name):
    """One light colour: a non-negative number or RGB triple, as shape (3,); None stays None."""
    if value is None:
        return None
    c = as_rgb(value, name, maximum=None)
    if c.size == 1:
        c = np.full(3, float(c.reshape(-1)[0]))
    if c.shape != (3,):
        raise ValueError(f"{name} must be one number or one RGB triple, got shape {c.shape}")
    return c


def point_light(position, intensity=1.0, attenuation=(1.0, 0.0, 0.0), *, ambient=0.0,
                diffuse=None, specular=None):
    r"""A point light at `position`, of RGB `intensity`, attenuated with distance.

    Parameters
    ----------
    position : array_like, shape (3,)
    intensity : float or array_like, shape (3,)
        :math:`I_l \ge 0`, grey or RGB.
    attenuation : (float, float, float)
        :math:`(a, b, c)`, all non-negative and not all zero: :math:`f_{att}(d) = 1/(a + b d +
        c d^2)` (default (1, 0, 0): none).
    ambient, diffuse, specular : float or array_like, shape (3,), optional
        Separate colours for the three terms (see :class:`Light`): ``diffuse`` and ``specular``
        default to `intensity`, ``ambient`` to 0.

    Returns
    -------
    Light

    Raises
    ------
    ValueError
        For a malformed position, a negative intensity or bad attenuation coefficients.

    Examples
    --------
    >>> light = point_light([1, 2, 3], intensity=(1, 1, 0.5), attenuation=(1, 0, 0.1))
    >>> light.intensity, light.attenuation
    (array([1. , 1. , 0.5]), (1.0, 0.0, 0.1))
    """
    intensity = _light_colour(intensity, "intensity")
    return Light(as_vector(position, "position", 3), None, intensity,
                 _attenuation_coefficients(attenuation), _light_colour(ambient, "ambient"),
                 _light_colour(diffuse, "diffuse"), _light_colour(specular, "specular"))


def directional_light(towards, intensity=1.0, *, ambient=0.0, diffuse=None, specular=None):
    """A directional light (infinitely far away, like the sun): the same L at every point.

    Parameters
    ----------
    towards : array_like, shape (3,)
        The direction from the surface *towards* the light (normalized here); e.g. (0, 1, 0)
        for a light straight above. (The light travels along ``-towards``.)
    intensity : float or array_like, shape (3,)
    ambient, diffuse, specular : float or array_like, shape (3,), optional
        Separate colours for the three terms, as :func:`point_light`.

    Returns
    -------
    Light

    Raises
    ------
    ValueError
        For a zero direction or a negative intensity.

    Examples
    --------
    >>> directional_light([0, 0, 2]).direction
    array([0., 0., 1.])
    """
    intensity = _light_colour(intensity, "intensity")
    return Light(None, _unit(as_vector(towards, "towards", 3), "towards"), intensity,
                 (1.0, 0.0, 0.0), _light_colour(ambient, "ambient"),
                 _light_colour(diffuse, "diffuse"), _light_colour(specular, "specular"))


def attenuation(distance, a=1.0, b=0.0, c=0.0):
    r"""Distance attenuation of a point light, :math:`f_{att}(d) = 1 / (a + b d + c d^2)`.

    Unclamped (as in OpenGL); some books use :math:`\min(1, f_{att})` so that a light close to
    the surface is not brighter than the light itself: choose :math:`a \ge 1` for that.

    Parameters
    ----------
    distance : float or array_like
        Distances :math:`d \ge 0` from the light.
    a, b, c : float
        Constant, linear and quadratic coefficients, non-negative, not all zero.

    Returns
    -------
    ndarray
        Same shape as `distance`.

    Raises
    ------
    ValueError
        For negative distances or bad coefficients.

    Examples
    --------
    >>> attenuation([0.0, 1.0, 3.0], a=1, b=0, c=1)
    array([1. , 0.5, 0.1])
    """
    a, b, c = _attenuation_coefficients((a, b, c))
    d = as_array(distance, "distance")
    if np.any(d < 0):
        raise ValueError("distance must be non-negative")
    with np.errstate(divide="ignore"):
        return 1.0 / (a + b * d + c * d * d)
