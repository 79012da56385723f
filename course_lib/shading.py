r"""Chapter 12: local illumination (Phong, Blinn-Phong), interpolated shading, ambient occlusion.

**The Phong illumination model.** The light leaving a surface point towards the viewer is the sum
of four terms,

.. math:: I = I_e + I_g + I_d + I_s
          = I_e + I_a k_a + \sum_{\text{lights } l} f_{att}(d_l)\, I_l \left[
            k_d \max(N \cdot L_l, 0) + k_s \max(R_l \cdot V, 0)^n \right]

* :math:`I_e` **emission**: light the surface gives off itself (a lamp's shade); it does not
  depend on any light source and does not light anything else in this local model.
* :math:`I_g = I_a k_a` **ambient** (global) reflection: a constant stand-in for all the light
  that arrives indirectly, bounced off other surfaces, which a local model does not compute.
  :math:`I_a` is the ambient light intensity of the scene, :math:`0 \le k_a \le 1` the
  material's ambient reflection coefficient. Ambient occlusion (below) scales it down in
  creases and corners where that indirect light cannot reach.
* :math:`I_d = k_d I_l \max(N \cdot L, 0)` **diffuse** reflection (Lambert's cosine law): a
  matte surface scatters the light equally in all directions, so it looks equally bright from
  everywhere, and how much it receives falls with the cosine of the angle of incidence.
* :math:`I_s = k_s I_l \max(R \cdot V, 0)^n` **specular** reflection: the highlight, brightest
  when the viewer looks along the mirror direction :math:`R` of the light; the shininess
  exponent :math:`n` sets how fast it falls off (large :math:`n`: small, sharp highlight).
  (The course compendium calls this term "spatial reflection": it is *specular* reflection.)

All terms are colours: :math:`I_l, I_a, k_a, k_d, k_s, I_e` are RGB triples and the products
are taken channel by channel (a red material under white light reflects red). The diffuse and
specular terms are summed over the lights, each weakened by the attenuation
:math:`f_{att}(d) = 1 / (a + b\,d + c\,d^2)` of a point light at distance :math:`d`
(:math:`a = 1, b = c = 0`, no attenuation, is the default; :math:`c` alone is the physical
inverse-square law, which the constant and linear terms soften). Directional lights (the sun)
are infinitely far away: no attenuation and the same :math:`L` everywhere.

**Vector conventions** (the textbook's): all four vectors are unit vectors that start at the
surface point and point *away* from it:

* :math:`N` the surface normal (on the side the light and the viewer are on),
* :math:`L` towards the light (:math:`L = (P_{light} - P)/\lVert P_{light} - P \rVert`),
* :math:`V` towards the viewer (:math:`V = (E - P)/\lVert E - P\rVert` for an eye at
  :math:`E`; for a ray tracer, :math:`V = -d` for a ray of direction :math:`d`),
* :math:`R = 2 (N \cdot L) N - L`, the mirror image of :math:`L` about :math:`N`
  (:func:`reflect`).

A light behind the surface (:math:`N \cdot L \le 0`) contributes neither diffuse nor specular
light: without that test a highlight could appear on the dark side.

**Blinn-Phong** (:func:`blinn_phong`) replaces :math:`R \cdot V` by :math:`N \cdot H` with the
halfway vector :math:`H = (L + V) / \lVert L + V \rVert`. It is cheaper (no reflection per
light; for a directional light and a distant viewer :math:`H` is constant) and behaves better at
grazing angles. Because the angle between :math:`N` and :math:`H` is about *half* the angle
between :math:`R` and :math:`V` (exactly half when :math:`N, L, V` are coplanar), a highlight of
similar size needs about **four times** the exponent:
:math:`\cos^{4n}(\alpha/2) \approx (1 - \alpha^2/8)^{4n} \approx e^{-n\alpha^2/2} \approx
\cos^n \alpha`.

**Calling it from a ray tracer** (chapter 15). :func:`phong` and :func:`blinn_phong` are
vectorized over any number of surface points: pass the hit points ``(p, 3)``, their normals
``(p, 3)`` (flip them towards the viewer first, or pass ``two_sided=True``), the view
directions ``-ray_directions`` ``(p, 3)``, a list of :class:`Light` and a :class:`Material`
whose fields may be per-hit arrays (:func:`material_per_point` builds them from one material
per object and the object id of each hit). Shadow rays become ``light_visibility``, shape
``(p, n_lights)``, 1 where the light is visible and 0 where it is blocked; only the diffuse and
specular terms of that light are removed. The result's ``total`` is the local colour, shape
``(p, 3)``, to which the ray tracer adds its reflected and refracted contributions::

    terms = shading.phong(hit_points, hit_normals, -ray_dirs, lights,
                          shading.material_per_point(materials, object_ids),
                          light_visibility=unshadowed, two_sided=True)
    colour = terms.total + k_r * reflected + k_t * refracted

**Interpolated shading of a mesh** (:func:`render_shaded`): *flat* shading evaluates the model
once per face with the face normal (facets show); *Gouraud* shading evaluates it at the vertices
with averaged vertex normals (:func:`vertex_normals`) and interpolates the *colours* across the
triangle (cheap, smooth, but highlights inside a triangle are lost or smeared, and their shape
follows the mesh); *Phong* shading interpolates the *normals* (and positions) and evaluates the
model at every pixel with the renormalized normal (highlights are round and sit where they
should, at one evaluation per pixel).

**Ambient occlusion** (:func:`ambient_occlusion`). The fraction of the hemisphere above a point
that is open to the sky, weighted by the cosine of the angle to the normal:

.. math:: AO(P) = \frac{1}{\pi} \int_{\Omega} v(P, \omega) \cos\theta \, d\omega \in [0, 1]

with :math:`v = 1` when the ray from :math:`P` in direction :math:`\omega` escapes (within a
maximum distance) and 0 when it hits something. It multiplies the ambient term:
:math:`I_g = AO \cdot I_a k_a`. Monte Carlo with *cosine-weighted* directions
(:func:`cosine_sample_hemisphere`, probability density :math:`\cos\theta / \pi`) makes the
estimator simply the **fraction of unblocked rays**, :math:`\widehat{AO} = \frac1k \sum_i
v(\omega_i)`: the cosine and the :math:`1/\pi` cancel against the density. Each :math:`v` is a
0/1 (Bernoulli) variable, so the estimator is unbiased with variance
:math:`AO(1 - AO)/k \le 1/(4k)`: the error falls like :math:`1/\sqrt{k}` (four times the
rays for half the noise). Each sample costs one ray cast: :math:`O(P)` triangle tests by brute
force, about :math:`O(\log P)` with a bounding-volume hierarchy. (The course compendium leaves
this section empty.)
"""
from typing import NamedTuple

import numpy as np

from . import visibility
from ._validate import as_array, as_matrix, as_points, as_scalar, as_vector, broadcast_stacks

__all__ = [
    "AmbientOcclusion",
    "HeightField",
    "Light",
    "Material",
    "PhongTerms",
    "ShadedImage",
    "ambient_occlusion",
    "ambient_occlusion_closed_form",
    "attenuation",
    "blinn_phong",
    "colored_material",
    "cosine_sample_hemisphere",
    "directional_light",
    "face_normals",
    "halfway",
    "material_per_point",
    "phong",
    "point_light",
    "reflect",
    "render_shaded",
    "uv_sphere",
    "vertex_normals",
    "view_directions",
]


# ---------------------------------------------------------------------------------------------
# Small vector helpers and input checks
# ---------------------------------------------------------------------------------------------

def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


def _unit(value, name):
    """`value` as an array of 3D vectors (..., 3), each normalized; zero vectors are rejected."""
    v = as_points(value, name, dims=3)
    length = np.sqrt(_dot(v, v))
    if np.any(length == 0):
        index = np.unravel_index(np.argmin(length), length.shape) if length.ndim else ()
        where = f" (at index {tuple(int(i) for i in index)})" if length.ndim else ""
        raise ValueError(f"{name} must not contain zero vectors{where}: a zero vector has no "
                         "direction")
    return v / length[..., None]


def _rgb(value, name, low=0.0, high=None):
    """A colour: a number (grey), an RGB triple, or per-point colours (..., 3) or (..., 1)."""
    c = as_array(value, name)
    if c.ndim == 0:
        c = np.full(3, float(c))
    elif c.shape[-1] not in (1, 3):
        raise ValueError(f"{name} must be a number (grey) or RGB triples (shape (3,) or "
                         f"(..., 3)), got shape {c.shape}")
    if np.any(c < low) or (high is not None and np.any(c > high)):
        bad = c[(c < low) | ((c > high) if high is not None else False)].flat[0]
        rng = f"[{low:g}, {high:g}]" if high is not None else f">= {low:g}"
        raise ValueError(f"{name} must lie in {rng}, got {bad:g}")
    return c


def _shininess(value):
    n = as_array(value, "shininess")
    if np.any(n <= 0):
        raise ValueError(f"shininess must be positive (the specular exponent n), got "
                         f"{float(n[n <= 0].flat[0]):g}")
    return n


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
    color = _rgb(color, "color", 0.0, 1.0)
    specular_color = _rgb(specular_color, "specular_color", 0.0, 1.0)
    ka, kd, ks = (as_scalar(k, name) for k, name in ((ka, "ka"), (kd, "kd"), (ks, "ks")))
    for k, name in ((ka, "ka"), (kd, "kd"), (ks, "ks")):
        if not 0 <= k <= 1:
            raise ValueError(f"{name} must lie in [0, 1], got {k:g}")
    return Material(ka * color, kd * color, ks * specular_color,
                    float(_shininess(shininess)), _rgb(emission, "emission"))


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
            c = _rgb(getattr(m, field), field)
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
    """A light source: a point light (``position``) or a directional light (``direction``).

    Build it with :func:`point_light` or :func:`directional_light`.

    Attributes
    ----------
    position : ndarray, shape (3,), or None
        Where a point light is.
    direction : ndarray, shape (3,), or None
        For a directional light: the unit vector *towards* the light (the L of every point).
    intensity : ndarray, shape (3,)
        The light's RGB intensity :math:`I_l` (may exceed 1 for a bright light).
    attenuation : tuple of float
        :math:`(a, b, c)` of :math:`f_{att}(d) = 1/(a + b d + c d^2)`.

    Examples
    --------
    >>> point_light([0, 5, 0]).position
    array([0., 5., 0.])
    """
    position: object
    direction: object
    intensity: np.ndarray
    attenuation: tuple


def _attenuation_coefficients(value):
    abc = as_vector(value, "attenuation", 3)
    if np.any(abc < 0) or not np.any(abc > 0):
        raise ValueError(f"attenuation must be (a, b, c) >= 0, not all zero (f_att = 1 / (a + "
                         f"b d + c d^2)), got {tuple(abc.tolist())}")
    return tuple(abc.tolist())


def point_light(position, intensity=1.0, attenuation=(1.0, 0.0, 0.0)):
    r"""A point light at `position`, of RGB `intensity`, attenuated with distance.

    Parameters
    ----------
    position : array_like, shape (3,)
    intensity : float or array_like, shape (3,)
        :math:`I_l \ge 0`, grey or RGB.
    attenuation : (float, float, float)
        :math:`(a, b, c)`, all non-negative and not all zero: :math:`f_{att}(d) = 1/(a + b d +
        c d^2)` (default (1, 0, 0): none).

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
    intensity = _rgb(intensity, "intensity")
    if intensity.shape != (3,):
        raise ValueError(f"intensity must be one number or one RGB triple, got shape "
                         f"{intensity.shape}")
    return Light(as_vector(position, "position", 3), None, intensity,
                 _attenuation_coefficients(attenuation))


def directional_light(towards, intensity=1.0):
    """A directional light (infinitely far away, like the sun): the same L at every point.

    Parameters
    ----------
    towards : array_like, shape (3,)
        The direction from the surface *towards* the light (normalized here); e.g. (0, 1, 0)
        for a light straight above. (The light travels along ``-towards``.)
    intensity : float or array_like, shape (3,)

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
    intensity = _rgb(intensity, "intensity")
    if intensity.shape != (3,):
        raise ValueError(f"intensity must be one number or one RGB triple, got shape "
                         f"{intensity.shape}")
    return Light(None, _unit(as_vector(towards, "towards", 3), "towards"), intensity,
                 (1.0, 0.0, 0.0))


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


# ---------------------------------------------------------------------------------------------
# Vectors of the model
# ---------------------------------------------------------------------------------------------

def reflect(l, n):
    r"""The mirror direction :math:`R = 2 (N \cdot L) N - L` of `l` about the normal `n`.

    Convention: :math:`L` points *away* from the surface, towards the light, and so does the
    result :math:`R` (towards where the mirrored light goes). With the other common convention,
    an *incoming* direction :math:`D = -L` travelling towards the surface (a ray's direction),
    the same reflected vector is :math:`R = D - 2 (N \cdot D) N` (``reflect(-d, n)``). For unit
    :math:`L`, :math:`R` is a unit vector with :math:`N \cdot R = N \cdot L`.

    `n` is normalized here; `l` is used as given (so :math:`\lVert R \rVert = \lVert L
    \rVert`). Works on any stack of vectors, shape ``(..., 3)``, with broadcasting.

    Parameters
    ----------
    l : array_like, shape (..., 3)
        Direction(s) towards the light.
    n : array_like, shape (..., 3)
        Surface normal(s), not zero.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For a zero normal, non-finite values or shapes that do not broadcast.

    Examples
    --------
    Light from 45 degrees on the left leaves at 45 degrees on the right:

    >>> reflect([-1, 1, 0], [0, 1, 0])
    array([1., 1., 0.])
    >>> d = [1, -1, 0]                      # a ray travelling down-right hits the floor
    >>> reflect(-np.asarray(d), [0, 2, 0])  # bounces up-right: D - 2 (N.D) N
    array([1., 1., 0.])
    """
    lv = as_points(l, "l", dims=3)
    nv = _unit(n, "n")
    broadcast_stacks(l=(lv, 1), n=(nv, 1))
    return 2.0 * _dot(nv, lv)[..., None] * nv - lv


def halfway(l, v):
    r"""The halfway vector :math:`H = (L + V)/\lVert L + V \rVert` of Blinn-Phong.

    `l` and `v` are normalized first (both point away from the surface). :math:`H` is the
    normal a mirror would need to reflect the light into the eye, so :math:`N \cdot H = 1`
    exactly when :math:`R \cdot V = 1`.

    Parameters
    ----------
    l, v : array_like, shape (..., 3)
        Directions towards the light and towards the viewer.

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        For zero vectors, or :math:`L = -V` (light exactly behind the viewer's line: no
        halfway direction).

    Examples
    --------
    >>> halfway([0, 0, 1], [1, 0, 0]) * np.sqrt(2)
    array([1., 0., 1.])
    """
    s = _unit(l, "l") + _unit(v, "v")
    length = np.sqrt(_dot(s, s))
    if np.any(length < 1e-12):
        raise ValueError("l and v must not be opposite: L + V = 0 has no halfway direction")
    return s / length[..., None]


def view_directions(points, eye):
    r"""Unit vectors from surface points towards the eye, :math:`V = (E - P)/\lVert E - P\rVert`.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    eye : array_like, shape (3,)

    Returns
    -------
    ndarray, shape (..., 3)

    Raises
    ------
    ValueError
        If a point coincides with the eye.

    Examples
    --------
    >>> view_directions([[0, 0, 0], [3, 0, 4]], [0, 0, 4])
    array([[ 0.,  0.,  1.],
           [-1.,  0.,  0.]])
    """
    p = as_points(points, "points", dims=3)
    e = as_vector(eye, "eye", 3)
    d = e - p
    if np.any(_dot(d, d) == 0):
        raise ValueError("points must not coincide with the eye: the view direction is undefined")
    return d / np.sqrt(_dot(d, d))[..., None]


# ---------------------------------------------------------------------------------------------
# The illumination models
# ---------------------------------------------------------------------------------------------

class PhongTerms(NamedTuple):
    """The result of :func:`phong` / :func:`blinn_phong`: the colour and its four terms.

    Every field has shape ``(..., 3)`` (RGB), the leading axes those of the shaded points.
    ``total = emission + ambient + diffuse + specular``; nothing is clamped to [0, 1] (clip
    for display with ``np.clip(total, 0, 1)``; sums over several lights may exceed 1).

    Attributes
    ----------
    total, emission, ambient, diffuse, specular : ndarray, shape (..., 3)
        :math:`I`, :math:`I_e`, :math:`I_g = I_a k_a`, :math:`I_d`, :math:`I_s`.

    Examples
    --------
    >>> t = phong([0, 0, 0], [0, 0, 1], [0, 0, 1], directional_light([0, 0, 1]), Material())
    >>> t.total
    array([1., 1., 1.])
    >>> t.ambient[0].item(), t.diffuse[0].item(), t.specular[0].item()
    (0.1, 0.7, 0.2)
    """
    total: np.ndarray
    emission: np.ndarray
    ambient: np.ndarray
    diffuse: np.ndarray
    specular: np.ndarray


def _lights(lights):
    if isinstance(lights, Light):
        return [lights]
    try:
        lights = list(lights)
    except TypeError:
        raise TypeError(f"lights must be a Light or a sequence of Light, got "
                        f"{type(lights).__name__}") from None
    if not all(isinstance(light, Light) for light in lights):
        raise TypeError("lights must be a Light or a sequence of Light (use point_light or "
                        "directional_light)")
    return lights


def _illuminate(points, normals, view, lights, material, ambient, light_visibility, two_sided,
                blinn):
    lights = _lights(lights)
    if not isinstance(material, Material):
        raise TypeError(f"material must be a Material, got {type(material).__name__}")
    n = _unit(normals, "normals")
    v = _unit(view, "view")
    p = None
    if points is not None:
        p = as_points(points, "points", dims=3)
    elif any(light.position is not None for light in lights):
        raise ValueError("points are needed for point lights (L and the distance depend on the "
                         "point); pass them, or use directional lights only")
    ka = _rgb(material.ka, "ka", 0.0, 1.0)
    kd = _rgb(material.kd, "kd", 0.0, 1.0)
    ks = _rgb(material.ks, "ks", 0.0, 1.0)
    ke = _rgb(material.emission, "emission")
    shin = _shininess(material.shininess)
    ia = _rgb(ambient, "ambient")
    stacks = dict(normals=(n, 1), view=(v, 1), ka=(ka, 1), kd=(kd, 1), ks=(ks, 1),
                  emission=(ke, 1), shininess=(shin, 0), ambient=(ia, 1))
    if p is not None:
        stacks["points"] = (p, 1)
    vis = None
    if light_visibility is not None:
        vis = as_array(light_visibility, "light_visibility")
        if vis.ndim == 0 or vis.shape[-1] != len(lights):
            raise ValueError(f"light_visibility must have one value per light in its last axis "
                             f"(shape (..., {len(lights)})), got shape {vis.shape}")
        if np.any(vis < 0) or np.any(vis > 1):
            raise ValueError("light_visibility must lie in [0, 1] (1 lit, 0 in shadow)")
        stacks["light_visibility"] = (vis, 1)
    lead = broadcast_stacks(**stacks)
    shape = lead + (3,)
    if two_sided:
        n = np.where((_dot(n, v) < 0)[..., None], -n, n)
    emission = np.broadcast_to(ke, shape).astype(float)
    amb = np.broadcast_to(ia * ka, shape).astype(float)
    diffuse = np.zeros(shape)
    specular = np.zeros(shape)
    for j, light in enumerate(lights):
        if light.position is None:
            l_dir = np.broadcast_to(light.direction, n.shape)
            strength = np.ones(())
        else:
            to_light = light.position - p
            dist = np.sqrt(_dot(to_light, to_light))
            if np.any(dist == 0):
                raise ValueError(f"a point coincides with point light {j}: the direction L to "
                                 "the light is undefined there")
            l_dir = to_light / dist[..., None]
            a, b, c = light.attenuation
            strength = 1.0 / (a + b * dist + c * dist * dist)
        if vis is not None:
            strength = strength * vis[..., j]
        n_dot_l = _dot(n, l_dir)
        lit = n_dot_l > 0
        if blinn:
            h = l_dir + v
            length = np.sqrt(_dot(h, h))
            with np.errstate(invalid="ignore", divide="ignore"):
                cos_spec = np.where(length > 1e-12, _dot(n, h) / length, 0.0)
        else:
            r = 2.0 * n_dot_l[..., None] * n - l_dir
            cos_spec = _dot(r, v)
        spec = np.where(lit, np.maximum(cos_spec, 0.0) ** shin, 0.0)
        incoming = light.intensity * np.asarray(strength)[..., None]
        diffuse = diffuse + kd * incoming * np.maximum(n_dot_l, 0.0)[..., None]
        specular = specular + ks * incoming * spec[..., None]
    diffuse = np.broadcast_to(diffuse, shape)
    specular = np.broadcast_to(specular, shape)
    total = emission + amb + diffuse + specular
    return PhongTerms(total, emission, amb, np.array(diffuse), np.array(specular))


def phong(points, normals, view, lights, material=Material(), ambient=1.0,
          light_visibility=None, two_sided=False):
    r"""The Phong illumination model at many surface points: colour and each of its terms.

    .. math:: I = I_e + I_a k_a + \sum_l f_{att}(d_l)\, v_l\, I_l \left[k_d \max(N \cdot L_l, 0)
              + k_s \max(R_l \cdot V, 0)^n\right], \qquad R_l = 2 (N \cdot L_l) N - L_l

    (textbook section 12.4), with the specular term set to 0 where :math:`N \cdot L_l \le 0`
    (the light is behind the surface), :math:`v_l` the optional `light_visibility` (shadows)
    and every product taken per RGB channel. All inputs broadcast over leading axes: one call
    shades a whole image or all the hits of a ray tracer.

    Parameters
    ----------
    points : array_like, shape (..., 3), or None
        The surface points (needed for point lights: :math:`L` and the distance :math:`d`);
        None is allowed when all lights are directional.
    normals : array_like, shape (..., 3)
        Surface normals :math:`N` (normalized here; zero vectors are rejected).
    view : array_like, shape (..., 3)
        Directions from the points *towards the viewer*, :math:`V` (normalized here): e.g.
        :func:`view_directions` for an eye position, or ``-ray_directions`` in a ray tracer.
    lights : Light or sequence of Light
        :func:`point_light` and :func:`directional_light` objects.
    material : Material, optional
        Coefficients, one set or per-point arrays (:func:`material_per_point`).
    ambient : float or array_like, shape (3,) or (..., 3) or (..., 1), optional
        The ambient light intensity :math:`I_a` (default 1: then :math:`I_g = k_a`); multiply
        it by an ambient-occlusion factor ``ao[..., None]`` to darken creases.
    light_visibility : array_like, shape (..., n_lights), optional
        Per point and light, a factor in [0, 1] on that light's diffuse and specular terms:
        1 lit, 0 in shadow (from shadow rays), in between for soft shadows.
    two_sided : bool, optional
        Flip normals that face away from the viewer (:math:`N \cdot V < 0`) before shading, so
        both sides of a surface are lit (open meshes, ray-traced planes).

    Returns
    -------
    PhongTerms
        ``total, emission, ambient, diffuse, specular``, each of shape ``(..., 3)``.

    Raises
    ------
    ValueError
        For zero normals or view vectors, NaN or infinite input (naming the argument),
        :math:`k_a, k_d, k_s` outside [0, 1], a non-positive shininess, negative intensities,
        a point at the position of a point light, or shapes that do not broadcast.
    TypeError
        If `lights` are not :class:`Light` or `material` not a :class:`Material`.

    Examples
    --------
    A light at 60 degrees from the normal, viewer in the mirror direction (:math:`R = V`):

    >>> light = directional_light([np.sin(np.pi / 3), 0, np.cos(np.pi / 3)])
    >>> t = phong(None, [0, 0, 1], [-np.sin(np.pi / 3), 0, np.cos(np.pi / 3)], light,
    ...           Material(ka=0.1, kd=0.6, ks=0.3, shininess=10))
    >>> np.round(t.total, 6)               # 0.1 + 0.6 cos(60) + 0.3 * 1^10
    array([0.7, 0.7, 0.7])

    A red material under two lights, one of them behind the surface (it adds nothing):

    >>> lights = [point_light([0, 0, 2], intensity=(1, 1, 1)), directional_light([0, 0, -1])]
    >>> t = phong([0, 0, 0], [0, 0, 1], [0, 0, 1], lights, colored_material((1, 0, 0)))
    >>> np.round(t.total, 6)
    array([1. , 0.2, 0.2])
    """
    return _illuminate(points, normals, view, lights, material, ambient, light_visibility,
                       two_sided, blinn=False)


def blinn_phong(points, normals, view, lights, material=Material(), ambient=1.0,
                light_visibility=None, two_sided=False):
    r"""The Blinn-Phong model: as :func:`phong` with :math:`\max(N \cdot H, 0)^n` for the highlight.

    .. math:: I_s = k_s I_l \max(N \cdot H, 0)^n, \qquad H = \frac{L + V}{\lVert L + V\rVert}

    (and 0 where :math:`N \cdot L \le 0`). The other terms are those of :func:`phong`. Since
    :math:`\angle(N, H) \approx \tfrac12 \angle(R, V)`, use about **4 times** the Phong
    shininess for a similar highlight. Where :math:`L = -V` exactly, :math:`H` is undefined and
    the highlight is taken as 0.

    Parameters
    ----------
    points, normals, view, lights, material, ambient, light_visibility, two_sided
        As :func:`phong`.

    Returns
    -------
    PhongTerms

    Raises
    ------
    ValueError, TypeError
        As :func:`phong`.

    Examples
    --------
    Viewer in the mirror direction: :math:`H = N`, the highlight is at full strength in both
    models; 30 degrees off it, Blinn-Phong with 4n stays close to Phong with n:

    >>> light = directional_light([1, 0, 1])
    >>> m, m4 = Material(ka=0, kd=0, ks=1, shininess=20), Material(ka=0, kd=0, ks=1, shininess=80)
    >>> float(blinn_phong(None, [0, 0, 1], [-1, 0, 1], light, m).total[0])
    1.0
    >>> off = [-np.sin(np.radians(75)), 0, np.cos(np.radians(75))]     # 30 degrees from R
    >>> round(float(phong(None, [0, 0, 1], off, light, m).total[0]), 4)
    0.0563
    >>> round(float(blinn_phong(None, [0, 0, 1], off, light, m4).total[0]), 4)
    0.0624
    """
    return _illuminate(points, normals, view, lights, material, ambient, light_visibility,
                       two_sided, blinn=True)


# ---------------------------------------------------------------------------------------------
# Meshes: normals and interpolated shading
# ---------------------------------------------------------------------------------------------

def _mesh(vertices, faces):
    v = as_points(vertices, "vertices", dims=3)
    if v.ndim != 2 or len(v) == 0:
        raise ValueError(f"vertices must be an (n, 3) array with n >= 1, got shape {v.shape}")
    f = np.asarray(faces)
    if f.ndim != 2 or f.shape[1] != 3 or not np.issubdtype(f.dtype, np.integer) or len(f) == 0:
        raise ValueError(f"faces must be a non-empty (m, 3) array of vertex indices, got shape "
                         f"{f.shape} and type {f.dtype}")
    if f.min() < 0 or f.max() >= len(v):
        raise ValueError(f"faces refers to vertex {int(f.max() if f.max() >= len(v) else f.min())}"
                         f" but there are {len(v)} vertices")
    return v, f.astype(np.intp)


def _face_cross(v, f):
    return np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])


def face_normals(vertices, faces):
    r"""Unit normals of the triangles, :math:`N = \frac{(v_1 - v_0) \times (v_2 - v_0)}
    {\lVert (v_1 - v_0) \times (v_2 - v_0) \rVert}`.

    They point to the side from which the vertices appear counter-clockwise. A degenerate
    (zero-area) triangle gets the zero vector.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)

    Returns
    -------
    ndarray, shape (m, 3)

    Raises
    ------
    ValueError
        For malformed vertices or faces.

    Examples
    --------
    >>> face_normals([[0, 0, 0], [2, 0, 0], [0, 3, 0]], [[0, 1, 2], [0, 2, 1]])
    array([[ 0.,  0.,  1.],
           [ 0.,  0., -1.]])
    """
    v, f = _mesh(vertices, faces)
    c = _face_cross(v, f)
    length = np.sqrt(_dot(c, c))
    return np.divide(c, length[:, None], out=np.zeros_like(c), where=length[:, None] > 0)


def vertex_normals(vertices, faces):
    r"""Vertex normals: the area-weighted average of the normals of the faces around a vertex.

    .. math:: N_v = \frac{\sum_{f \ni v} A_f \hat N_f}{\lVert \sum_{f \ni v} A_f \hat N_f \rVert}
              , \qquad A_f \hat N_f = \tfrac12 (v_1 - v_0) \times (v_2 - v_0)

    so summing the raw cross products does the weighting (big faces count more, slivers
    little). Used by Gouraud and Phong shading to make a faceted mesh look smooth. A vertex that
    belongs to no face (or whose faces' normals cancel) gets the zero vector.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)

    Returns
    -------
    ndarray, shape (n, 3)

    Raises
    ------
    ValueError
        For malformed vertices or faces.

    Examples
    --------
    The apex of a square pyramid: the four sloped faces average to straight up:

    >>> v = [[0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]]
    >>> f = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    >>> vertex_normals(v, f)[0]
    array([0., 0., 1.])
    """
    v, f = _mesh(vertices, faces)
    c = _face_cross(v, f)
    acc = np.zeros_like(v)
    for k in range(3):
        np.add.at(acc, f[:, k], c)
    length = np.sqrt(_dot(acc, acc))
    scale = 1e-12 * max(float(np.sqrt(_dot(c, c)).max()), 1e-300)
    return np.divide(acc, length[:, None], out=np.zeros_like(acc),
                     where=length[:, None] > scale)


def uv_sphere(radius=1.0, segments=32, rings=16, center=(0.0, 0.0, 0.0)):
    """A triangle mesh of a sphere by longitude (segments) and latitude (rings), poles on y.

    The mesh to try the shading methods on: its vertices lie exactly on the sphere, so the
    exact normal at a vertex is ``(vertex - center) / radius``.

    Parameters
    ----------
    radius : float
    segments : int
        Divisions around the y axis (at least 3).
    rings : int
        Divisions from pole to pole (at least 2).
    center : array_like, shape (3,)

    Returns
    -------
    vertices : ndarray, shape (segments * (rings - 1) + 2, 3)
    faces : ndarray of int, shape (2 * segments * (rings - 1), 3)
        Counter-clockwise seen from outside.

    Raises
    ------
    ValueError
        For a non-positive radius or too few divisions.

    Examples
    --------
    >>> v, f = uv_sphere(segments=8, rings=4)
    >>> v.shape, f.shape, bool(np.allclose(np.linalg.norm(v, axis=1), 1))
    ((26, 3), (48, 3), True)
    """
    r = as_scalar(radius, "radius")
    if r <= 0:
        raise ValueError(f"radius must be positive, got {r}")
    if int(segments) != segments or segments < 3 or int(rings) != rings or rings < 2:
        raise ValueError(f"segments must be a whole number >= 3 and rings >= 2, got {segments} "
                         f"and {rings}")
    segments, rings = int(segments), int(rings)
    c = as_vector(center, "center", 3)
    lat = np.pi / 2 - np.pi * np.arange(1, rings) / rings           # from the north pole down
    lon = 2 * np.pi * np.arange(segments) / segments
    x = np.cos(lat)[:, None] * np.sin(lon)[None]
    z = np.cos(lat)[:, None] * np.cos(lon)[None]
    y = np.broadcast_to(np.sin(lat)[:, None], x.shape)
    body = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    vertices = np.vstack([[0.0, 1.0, 0.0], body, [0.0, -1.0, 0.0]]) * r + c
    north, south = 0, len(vertices) - 1
    i = np.arange(segments)
    j = (i + 1) % segments
    faces = [np.stack([np.full(segments, north), 1 + i, 1 + j], -1)]
    for k in range(rings - 2):
        a, b = 1 + k * segments + i, 1 + k * segments + j
        a2, b2 = a + segments, b + segments
        faces += [np.stack([a, a2, b2], -1), np.stack([a, b2, b], -1)]
    last = 1 + (rings - 2) * segments
    faces.append(np.stack([last + i, np.full(segments, south), last + j], -1))
    return vertices, np.concatenate(faces).astype(np.intp)


class ShadedImage(NamedTuple):
    """The result of :func:`render_shaded`: buffers of shape (height, width), row 0 at the bottom.

    Attributes
    ----------
    image : ndarray, shape (height, width, 3)
        The shaded colour (unclamped), `background` where nothing is drawn.
    ids : ndarray of int, shape (height, width)
        The visible face, -1 for background.
    depth : ndarray, shape (height, width)
        Viewport depth in [0, 1], inf on background.

    Examples
    --------
    >>> from course_lib import viewing
    >>> v, f = uv_sphere(segments=12, rings=6)
    >>> V = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    >>> img = render_shaded(v, f, V, P, 16, 16, directional_light([0, 0, 1]))
    >>> img.image.shape, int((img.ids >= 0).sum()) > 50
    ((16, 16, 3), True)
    """
    image: np.ndarray
    ids: np.ndarray
    depth: np.ndarray


def _eye_and_view(view, projection):
    """Eye position (None for a parallel projection) and the constant V of a parallel view."""
    parallel = np.allclose(projection[3], [0.0, 0.0, 0.0, 1.0])
    rot, t = view[:3, :3], view[:3, 3]
    if parallel:
        return None, rot[2] / np.linalg.norm(rot[2])        # z_e points towards the viewer
    return -np.linalg.solve(rot, t), None


def render_shaded(vertices, faces, view, projection, width, height, lights, material=Material(),
                  shading="phong", model="phong", normals=None, ambient=1.0, background=0.0,
                  cull_back_faces=False, two_sided=False):
    r"""Render a triangle mesh with flat, Gouraud or Phong (per-pixel) shading.

    The z-buffer of :func:`course_lib.visibility.render_depth` decides the visible face of each
    pixel; the illumination model (:func:`phong` or :func:`blinn_phong`) gives the colour:

    * ``shading="flat"``: once per face, at its centroid, with the face normal
      (:func:`face_normals`); the whole face gets that colour.
    * ``shading="gouraud"``: at every vertex with the vertex normal; the *colours* are
      interpolated across each triangle (perspective-correctly, by the z-buffer).
    * ``shading="phong"``: vertex positions and normals are interpolated to every pixel, the
      normal renormalized (interpolation shortens it), and the model evaluated there.

    The viewer: for a perspective `projection` the eye is the centre of projection of `view`
    and :math:`V = (E - P)/\lVert E - P \rVert` per point; for a parallel projection (last row
    ``(0, 0, 0, 1)``) :math:`V` is the camera's :math:`z_e` axis everywhere.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
        Counter-clockwise seen from outside (the face normals point outwards).
    view, projection : array_like, shape (4, 4)
        E.g. :func:`course_lib.viewing.look_at` and :func:`course_lib.viewing.perspective`.
    width, height : int
        Image size in pixels.
    lights : Light or sequence of Light
    material : Material, optional
        One material for the whole mesh.
    shading : {"flat", "gouraud", "phong"}
    model : {"phong", "blinn"}
        The illumination model.
    normals : array_like, shape (n, 3), optional
        Vertex normals (default :func:`vertex_normals`); for an analytic surface pass the exact
        ones (a sphere's: ``(v - centre) / radius``). Not used by flat shading.
    ambient : float or array_like, shape (3,)
        Ambient light :math:`I_a`.
    background : float or array_like, shape (3,)
        Colour of the pixels where nothing is drawn.
    cull_back_faces : bool
    two_sided : bool
        Light back faces too (their normals flipped towards the viewer).

    Returns
    -------
    ShadedImage
        Show with ``plt.imshow(np.clip(result.image, 0, 1), origin="lower")``.

    Raises
    ------
    ValueError
        For malformed input, an unknown `shading` or `model`, or a bad material or light.

    Examples
    --------
    A flat-shaded sphere has one colour per face; Phong shading varies within faces:

    >>> from course_lib import viewing
    >>> v, f = uv_sphere(segments=12, rings=6)
    >>> V = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    >>> light = directional_light([1, 1, 1])
    >>> flat = render_shaded(v, f, V, P, 32, 32, light, shading="flat")
    >>> smooth = render_shaded(v, f, V, P, 32, 32, light, shading="phong")
    >>> def colours_per_face(result):
    ...     seen = result.ids >= 0
    ...     return max(len(np.unique(result.image[result.ids == i][:, 0]))
    ...                for i in np.unique(result.ids[seen]))
    >>> colours_per_face(flat), colours_per_face(smooth) > 5
    (1, True)
    """
    if shading not in ("flat", "gouraud", "phong"):
        raise ValueError(f"shading must be 'flat', 'gouraud' or 'phong', got {shading!r}")
    if model not in ("phong", "blinn"):
        raise ValueError(f"model must be 'phong' or 'blinn', got {model!r}")
    illuminate = phong if model == "phong" else blinn_phong
    v, f = _mesh(vertices, faces)
    view = as_matrix(view, "view", 4)
    projection = as_matrix(projection, "projection", 4)
    bg = np.broadcast_to(_rgb(background, "background"), (3,))
    lights = _lights(lights)
    eye, v_const = _eye_and_view(view, projection)

    def view_of(points):
        if eye is None:
            return np.broadcast_to(v_const, points.shape)
        d = eye - points
        return d / np.sqrt(_dot(d, d))[..., None]

    def shade(points, nrm):
        return illuminate(points, nrm, view_of(points), lights, material, ambient,
                          two_sided=two_sided).total

    if shading != "flat":
        vn = vertex_normals(v, f) if normals is None else as_points(normals, "normals", dims=3)
        if vn.shape != v.shape:
            raise ValueError(f"normals must hold one normal per vertex, shape {v.shape}, got "
                             f"{vn.shape}")
    if shading == "flat":
        zb = visibility.render_depth(v, f, view, projection, width, height,
                                     cull_back_faces=cull_back_faces)
        seen = np.unique(zb.ids[zb.ids >= 0])
        colours = np.zeros((len(f), 3))
        if len(seen):
            colours[seen] = shade(v[f[seen]].mean(axis=1), face_normals(v, f[seen]))
        image = colours[np.maximum(zb.ids, 0)]
    elif shading == "gouraud":
        used = np.sqrt(_dot(vn, vn)) > 0
        colours = np.zeros((len(v), 3))
        if used.any():
            colours[used] = shade(v[used], vn[used])
        zb = visibility.render_depth(v, f, view, projection, width, height, values=colours,
                                     cull_back_faces=cull_back_faces)
        image = zb.image
    else:
        zb = visibility.render_depth(v, f, view, projection, width, height,
                                     values=np.hstack([v, vn]), cull_back_faces=cull_back_faces)
        image = np.zeros((zb.ids.shape[0], zb.ids.shape[1], 3))
        mask = zb.ids >= 0
        if mask.any():
            points, nrm = zb.image[mask][:, :3], zb.image[mask][:, 3:]
            length = np.sqrt(_dot(nrm, nrm))
            fallback = length < 1e-9                  # opposite normals cancelled: use the face's
            if fallback.any():
                nrm[fallback] = face_normals(v, f[zb.ids[mask][fallback]])
            image[mask] = shade(points, nrm)
    image = np.where((zb.ids >= 0)[..., None], image, bg)
    return ShadedImage(image, zb.ids, zb.depth)


# ---------------------------------------------------------------------------------------------
# Ambient occlusion
# ---------------------------------------------------------------------------------------------

def _rng(seed):
    return seed if isinstance(seed, np.random.Generator) else np.random.default_rng(seed)


def _tangent_frame(n):
    """Two unit tangents b1, b2 with (b1, b2, n) right-handed and orthonormal, for unit n.

    The branch-free construction of Duff et al. (2017), robust for every n including -z.
    """
    sign = np.where(n[..., 2] >= 0, 1.0, -1.0)
    a = -1.0 / (sign + n[..., 2])
    b = n[..., 0] * n[..., 1] * a
    b1 = np.stack([1 + sign * n[..., 0] ** 2 * a, sign * b, -sign * n[..., 0]], axis=-1)
    b2 = np.stack([b, sign + n[..., 1] ** 2 * a, -n[..., 1]], axis=-1)
    return b1, b2


def cosine_sample_hemisphere(normals, samples, seed=None):
    r"""Random unit directions above each normal, with density :math:`\cos\theta / \pi`.

    Malley's method: a point uniform in the unit disk, :math:`(r\cos\phi, r\sin\phi)` with
    :math:`r = \sqrt{\xi_1}`, :math:`\phi = 2\pi\xi_2`, lifted onto the hemisphere,
    :math:`z = \sqrt{1 - r^2}` (projecting a cosine-weighted hemisphere onto its base gives a
    uniform disk), then turned into the frame of the normal.

    Parameters
    ----------
    normals : array_like, shape (..., 3)
        Not zero (normalized here).
    samples : int
        Directions per normal, k >= 1.
    seed : int, numpy.random.Generator or None

    Returns
    -------
    ndarray, shape (..., k, 3)
        Unit vectors with positive dot product with their normal.

    Raises
    ------
    ValueError
        For zero normals or a sample count below 1.

    Examples
    --------
    The mean of cos(theta) under this density is 2/3:

    >>> d = cosine_sample_hemisphere([0, 0, 1], 200_000, seed=1)
    >>> d.shape, bool(abs(d[:, 2].mean() - 2 / 3) < 0.005), bool((d[:, 2] >= 0).all())
    ((200000, 3), True, True)
    """
    n = _unit(normals, "normals")
    k = _count(samples, "samples")
    xi = _rng(seed).random(n.shape[:-1] + (k, 2))
    r = np.sqrt(xi[..., 0])
    phi = 2 * np.pi * xi[..., 1]
    z = np.sqrt(np.maximum(0.0, 1.0 - xi[..., 0]))
    b1, b2 = _tangent_frame(n)
    return ((r * np.cos(phi))[..., None] * b1[..., None, :]
            + (r * np.sin(phi))[..., None] * b2[..., None, :] + z[..., None] * n[..., None, :])


def _count(value, name):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    k = as_scalar(value, name)
    if k < 1 or k != int(k):
        raise ValueError(f"{name} must be a whole number >= 1, got {value!r}")
    return int(k)


class HeightField(NamedTuple):
    r"""A terrain :math:`z = h(x, y)`: heights on a regular grid, bilinear in between.

    ``heights[i, j]`` is the height at :math:`x = x_0 + j\,(x_1 - x_0)/(n_x - 1)`,
    :math:`y = y_0 + i\,(y_1 - y_0)/(n_y - 1)` (row 0 at :math:`y_0`, as an image shown with
    ``origin="lower"``). Outside the extent there is nothing (rays leave the terrain). Used as
    an occluder by :func:`ambient_occlusion`, which marches rays over it.

    Attributes
    ----------
    heights : ndarray, shape (ny, nx)
        At least 2 x 2.
    extent : tuple of float
        ``(x0, x1, y0, y1)``.

    Examples
    --------
    >>> field = HeightField(np.array([[0.0, 1.0], [2.0, 3.0]]), (0, 1, 0, 1))
    >>> field.height([0.5, 1.0], [0.5, 0.0]).tolist()
    [1.5, 1.0]
    >>> field.points().shape, field.normals()[0, 0].round(4).tolist()
    ((2, 2, 3), [-0.4082, -0.8165, 0.4082])
    """
    heights: np.ndarray
    extent: tuple

    def _grid(self):
        h = as_array(self.heights, "heights")
        if h.ndim != 2 or min(h.shape) < 2:
            raise ValueError(f"heights must be a 2D grid of at least 2 x 2, got shape {h.shape}")
        x0, x1, y0, y1 = as_vector(self.extent, "extent", 4)
        if not (x1 > x0 and y1 > y0):
            raise ValueError(f"extent must be (x0, x1, y0, y1) with x1 > x0 and y1 > y0, got "
                             f"{tuple(self.extent)}")
        return h, x0, x1, y0, y1

    def height(self, x, y):
        """Bilinearly interpolated height at (x, y); -inf outside the extent."""
        h, x0, x1, y0, y1 = self._grid()
        x, y = np.broadcast_arrays(as_array(x, "x"), as_array(y, "y"))
        ny, nx = h.shape
        gx = (x - x0) / (x1 - x0) * (nx - 1)
        gy = (y - y0) / (y1 - y0) * (ny - 1)
        inside = (gx >= 0) & (gx <= nx - 1) & (gy >= 0) & (gy <= ny - 1)
        j = np.clip(np.floor(gx).astype(np.intp), 0, nx - 2)
        i = np.clip(np.floor(gy).astype(np.intp), 0, ny - 2)
        fx, fy = np.clip(gx - j, 0, 1), np.clip(gy - i, 0, 1)
        z = ((1 - fy) * ((1 - fx) * h[i, j] + fx * h[i, j + 1])
             + fy * ((1 - fx) * h[i + 1, j] + fx * h[i + 1, j + 1]))
        return np.where(inside, z, -np.inf)

    def points(self):
        """The grid points, shape (ny, nx, 3)."""
        h, x0, x1, y0, y1 = self._grid()
        ny, nx = h.shape
        x, y = np.meshgrid(np.linspace(x0, x1, nx), np.linspace(y0, y1, ny))
        return np.stack([x, y, h], axis=-1)

    def normals(self):
        r"""Unit normals at the grid points, :math:`(-h_x, -h_y, 1)` normalized (central
        differences inside, one-sided at the border)."""
        h, x0, x1, y0, y1 = self._grid()
        ny, nx = h.shape
        hy, hx = np.gradient(h, (y1 - y0) / (ny - 1), (x1 - x0) / (nx - 1))
        n = np.stack([-hx, -hy, np.ones_like(h)], axis=-1)
        return n / np.sqrt(_dot(n, n))[..., None]


def _march(field, o, d, t_max, step):
    """True where the ray o + t d (unit d) passes below the height field for some t <= t_max."""
    h, x0, x1, y0, y1 = field._grid()
    top = float(h.max())
    occluded = np.zeros(len(o), dtype=bool)
    # where each ray leaves the box [x0, x1] x [y0, y1] x [-inf, top]
    with np.errstate(divide="ignore", invalid="ignore"):
        exits = [np.where(d[:, 0] > 0, (x1 - o[:, 0]) / d[:, 0],
                          np.where(d[:, 0] < 0, (x0 - o[:, 0]) / d[:, 0], np.inf)),
                 np.where(d[:, 1] > 0, (y1 - o[:, 1]) / d[:, 1],
                          np.where(d[:, 1] < 0, (y0 - o[:, 1]) / d[:, 1], np.inf)),
                 np.where(d[:, 2] > 0, (top - o[:, 2]) / d[:, 2], np.inf)]
    end = np.minimum(np.minimum.reduce(exits), t_max)
    active = np.nonzero(end >= step)[0]
    t = step
    while len(active):
        p = o[active] + t * d[active]
        below = p[:, 2] < field.height(p[:, 0], p[:, 1])
        occluded[active[below]] = True
        active = active[~below & (end[active] >= t + step)]
        t += step
    return occluded


class AmbientOcclusion(NamedTuple):
    r"""The result of :func:`ambient_occlusion`.

    Attributes
    ----------
    visibility : ndarray, shape (...)
        The estimated cosine-weighted unoccluded fraction in [0, 1] (1 = open sky).
    std_error : ndarray, shape (...)
        Its estimated standard error :math:`\sqrt{\widehat{AO}(1 - \widehat{AO})/k}`.
    rays : int
        Rays cast (points x samples).
    triangle_tests : int
        Ray-triangle tests performed (the cost).

    Examples
    --------
    >>> ao = ambient_occlusion([[0, 0, 0]], [[0, 0, 1]], samples=16, seed=0)
    >>> ao.visibility.tolist(), ao.rays
    ([1.0], 16)
    """
    visibility: np.ndarray
    std_error: np.ndarray
    rays: int
    triangle_tests: int


def ambient_occlusion(points, normals, scene=None, samples=64, max_distance=np.inf, seed=None,
                      height_field=None, accelerate=True, offset=None, step=None):
    r"""Ambient occlusion by Monte Carlo hemisphere sampling: the open fraction above each point.

    For each point, `samples` directions are drawn with density :math:`\cos\theta/\pi`
    (:func:`cosine_sample_hemisphere`) and a ray cast in each; a ray is blocked when it hits the
    `scene` (or passes below the `height_field`) within `max_distance`. The estimate is the
    fraction of rays that are *not* blocked,

    .. math:: \widehat{AO} = \frac{1}{k}\sum_{i=1}^k v(P, \omega_i) \approx
              \frac{1}{\pi}\int_\Omega v(P, \omega)\cos\theta\, d\omega

    unbiased, with variance :math:`AO(1-AO)/k \le 1/(4k)` (standard error :math:`\le
    1/(2\sqrt k)`). A finite `max_distance` counts only nearby geometry (the usual choice:
    distant walls should not darken a point), which also makes rays cheaper.

    Cost: one ray per sample, :math:`k` per point; each ray costs :math:`P` triangle tests by
    brute force or about :math:`O(\log P)` with a bounding-volume hierarchy
    (:class:`course_lib.visibility.BVH`, the default `accelerate`). Height fields are marched
    in steps of `step` (half a grid cell by default): cost proportional to the ray's length in
    cells; thin features narrower than a step can be missed.

    Rays start at :math:`P + \epsilon N` (`offset` :math:`\epsilon`) so that the surface the
    point lies on does not block its own rays; :math:`\epsilon` is a bias (geometry closer
    than it is missed), keep it far below the scene's features.

    Parameters
    ----------
    points : array_like, shape (..., 3)
    normals : array_like, shape (..., 3)
        The surface normals at the points (normalized here; not zero).
    scene : array_like, shape (m, 3, 3), or course_lib.visibility.BVH, optional
        Occluding triangles (both sides block). Pass a ready BVH to reuse it.
    samples : int
        Rays per point, :math:`k`.
    max_distance : float
        Only hits within this distance occlude (default: any distance).
    seed : int, numpy.random.Generator or None
    height_field : HeightField, optional
        A terrain that occludes as well.
    accelerate : bool
        Build a BVH over `scene` (ignored for a BVH; brute force otherwise).
    offset : float, optional
        How far above the surface (along the normal) the rays start; default
        :math:`10^{-6} (1 + \max \lVert P \rVert_\infty)`, a little above the rounding
        error of the points' coordinates.
    step : float, optional
        Marching step for the height field.

    Returns
    -------
    AmbientOcclusion
        ``visibility`` (shape of the points' leading axes), ``std_error``, ``rays``,
        ``triangle_tests``.

    Raises
    ------
    ValueError
        For zero normals, NaN input, a sample count below 1, a non-positive `max_distance`,
        or a malformed scene.

    Examples
    --------
    A point on the floor in the corner of two tall walls sees a quarter of the (cosine-weighted)
    sky: only directions with both dx > 0 and dy > 0 escape.

    >>> big = 1e3
    >>> walls = [[[-1, -big, 0], [-1, big, 0], [-1, 0, big]],      # the wall x = -1
    ...          [[-big, -1, 0], [big, -1, 0], [0, -1, big]]]      # the wall y = -1
    >>> ao = ambient_occlusion([0, 0, 0], [0, 0, 1], walls, samples=20_000, seed=3)
    >>> bool(abs(ao.visibility - 0.25) < 4 * ao.std_error)
    True
    """
    p = as_points(points, "points", dims=3)
    n = _unit(normals, "normals")
    lead = broadcast_stacks(points=(p, 1), normals=(n, 1))
    p = np.broadcast_to(p, lead + (3,)).reshape(-1, 3)
    n = np.broadcast_to(n, lead + (3,)).reshape(-1, 3)
    k = _count(samples, "samples")
    t_max = np.inf if np.isscalar(max_distance) and np.isposinf(max_distance) \
        else as_scalar(max_distance, "max_distance")
    if t_max <= 0:
        raise ValueError(f"max_distance must be positive, got {t_max}")
    if height_field is not None and not isinstance(height_field, HeightField):
        raise TypeError(f"height_field must be a HeightField, got {type(height_field).__name__}")
    if len(p) == 0:
        empty = np.zeros(lead)
        return AmbientOcclusion(empty + 1.0, empty, 0, 0)
    dirs = cosine_sample_hemisphere(n, k, seed)                        # (P, k, 3)
    eps = 1e-6 * (1.0 + float(np.abs(p).max())) if offset is None else as_scalar(offset,
                                                                                  "offset")
    if eps < 0:
        raise ValueError(f"offset must be non-negative, got {eps}")
    if isinstance(scene, visibility.BVH):
        pass
    elif scene is not None:
        scene = as_array(scene, "scene")
        if scene.shape == (3, 3):
            scene = scene[None]
        if scene.ndim != 3 or scene.shape[1:] != (3, 3):
            raise ValueError(f"scene must be triangles of shape (m, 3, 3) or a BVH, got shape "
                             f"{scene.shape}")
        if len(scene) == 0:
            scene = None
        elif accelerate:
            scene = visibility.BVH(scene)
    origins = np.repeat(p + eps * n, k, axis=0)
    d = dirs.reshape(-1, 3)
    blocked = np.zeros(len(d), dtype=bool)
    tests = 0
    if scene is not None:
        hits = visibility.ray_cast(origins, d, scene, t_min=0.0, t_max=t_max)
        blocked |= hits.ids >= 0
        tests = hits.triangle_tests
    if height_field is not None:
        hmin = height_field._grid()
        cell = min((hmin[2] - hmin[1]) / (hmin[0].shape[1] - 1),
                   (hmin[4] - hmin[3]) / (hmin[0].shape[0] - 1))
        s = 0.5 * cell if step is None else as_scalar(step, "step")
        if s <= 0:
            raise ValueError(f"step must be positive, got {s}")
        rest = ~blocked
        if rest.any():
            blocked[rest] = _march(height_field, origins[rest], d[rest], t_max, s)
    vis = 1.0 - blocked.reshape(-1, k).mean(axis=1)
    err = np.sqrt(vis * (1 - vis) / k)
    return AmbientOcclusion(vis.reshape(lead), err.reshape(lead), len(d), tests)


def ambient_occlusion_closed_form(kind, distance=1.0, height=np.inf, max_distance=np.inf):
    r"""Exact cosine-weighted ambient occlusion of simple configurations (to check estimates).

    The key fact: under the density :math:`\cos\theta/\pi`, a direction's angle :math:`\beta`
    from the normal *projected onto a vertical plane* (:math:`\tan\beta = d_x / d_z`) has
    :math:`P(\beta \le b) = (1 + \sin b)/2` (for a uniform point in the disk, :math:`d_x` is
    uniform on each chord). So an infinitely long wall seen under the projected angles
    :math:`[\beta_1, \beta_2]` blocks :math:`(\sin\beta_2 - \sin\beta_1)/2` of the rays (the
    2D view factor). And :math:`\cos\theta` itself has density :math:`2\cos\theta`, so
    :math:`P(\cos\theta \ge c) = 1 - c^2`.

    * ``"plane"``: a point on an open plane: 1.
    * ``"wall"``: a point on the floor at `distance` :math:`a` from an infinitely long wall of
      `height` :math:`h`: the wall spans :math:`\beta \in [-\pi/2, -\arctan(a/h)]`, so
      :math:`AO = 1 - \tfrac12 (1 - a/\sqrt{a^2 + h^2}) = \tfrac12 (1 + a / \sqrt{a^2 + h^2})`
      (1/2 for an infinitely high wall).
    * ``"trench"``: the middle of the floor of an infinitely long trench of half-width
      :math:`a` (`distance`) and depth :math:`h`: two such walls,
      :math:`AO = a / \sqrt{a^2 + h^2}`.
    * ``"corner"``: a floor point in the corner of two perpendicular, infinitely high and long
      walls (the floor and two walls of a box): only :math:`d_x > 0, d_y > 0` escape, a quarter
      of the uniform disk: 1/4 (whatever the distances to the walls).
    * ``"ceiling"``: a point under an infinite parallel ceiling at `height` :math:`h`, counting
      hits within `max_distance` :math:`D`: a ray at angle :math:`\theta` hits at
      :math:`h/\cos\theta`, blocked when :math:`\cos\theta \ge h/D`:
      :math:`AO = (h/D)^2` for :math:`D > h`, else 1.

    Parameters
    ----------
    kind : {"plane", "wall", "trench", "corner", "ceiling"}
    distance : float
        :math:`a > 0` (wall, trench).
    height : float
        :math:`h > 0` (wall, trench, ceiling); may be inf for wall and trench.
    max_distance : float
        :math:`D` (ceiling).

    Returns
    -------
    float

    Raises
    ------
    ValueError
        For an unknown kind or non-positive sizes.

    Examples
    --------
    >>> ambient_occlusion_closed_form("wall", distance=1.0, height=np.sqrt(3))   # (1 + 1/2)/2
    0.75
    >>> ambient_occlusion_closed_form("trench", distance=1.0, height=np.inf)
    0.0
    >>> ambient_occlusion_closed_form("ceiling", height=1.0, max_distance=2.0)
    0.25
    """
    a = np.inf if np.isscalar(distance) and np.isposinf(distance) else as_scalar(distance,
                                                                                  "distance")
    h = np.inf if np.isscalar(height) and np.isposinf(height) else as_scalar(height, "height")
    big_d = (np.inf if np.isscalar(max_distance) and np.isposinf(max_distance)
             else as_scalar(max_distance, "max_distance"))
    if a <= 0 or h <= 0 or big_d <= 0:
        raise ValueError("distance, height and max_distance must be positive")
    if kind == "plane":
        return 1.0
    if kind == "corner":
        return 0.25
    if kind in ("wall", "trench"):
        ratio = 0.0 if np.isinf(h) else a / np.hypot(a, h)
        return float((1 + ratio) / 2 if kind == "wall" else ratio)
    if kind == "ceiling":
        if np.isinf(h):
            return 1.0
        return float((h / big_d) ** 2) if big_d > h else 1.0
    raise ValueError(f"kind must be 'plane', 'wall', 'trench', 'corner' or 'ceiling', got {kind!r}")
