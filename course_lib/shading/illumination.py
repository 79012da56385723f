"""Chapter 12 (lesson sections 3, 4): the Lambert, Phong and Blinn-Phong models."""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_points, as_rgb, broadcast_stacks
from ._common import _dot, _shininess, _unit
from .materials import Light, Material

__all__ = ["PhongTerms", "blinn_phong", "phong"]


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
    >>> from course_lib.shading import directional_light
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
    ka = as_rgb(material.ka, "ka")
    kd = as_rgb(material.kd, "kd")
    ks = as_rgb(material.ks, "ks")
    ke = as_rgb(material.emission, "emission", maximum=None)
    shin = _shininess(material.shininess)
    ia = as_rgb(ambient, "ambient", maximum=None)
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
        light_ambient, light_diffuse, light_specular = light.colours()
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
        if np.any(light_ambient > 0):        # attenuated, never shadowed: it is indirect light
            amb = amb + ka * light_ambient * np.asarray(strength)[..., None]
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
        weight = np.asarray(strength)[..., None]
        diffuse = diffuse + kd * light_diffuse * weight * np.maximum(n_dot_l, 0.0)[..., None]
        specular = specular + ks * light_specular * weight * spec[..., None]
    amb = np.broadcast_to(amb, shape)
    diffuse = np.broadcast_to(diffuse, shape)
    specular = np.broadcast_to(specular, shape)
    total = emission + amb + diffuse + specular
    return PhongTerms(total, emission, np.array(amb), np.array(diffuse), np.array(specular))


def phong(points, normals, view, lights, material=Material(), ambient=1.0,
          light_visibility=None, two_sided=False):
    r"""The Phong illumination model at many surface points: colour and each of its terms.

    .. math:: I = I_e + I_a k_a + \sum_l f_{att}(d_l)\, v_l\, I_l \left[k_d \max(N \cdot L_l, 0)
              + k_s \max(R_l \cdot V, 0)^n\right], \qquad R_l = 2 (N \cdot L_l) N - L_l

    (textbook section 12.4), with the specular term set to 0 where :math:`N \cdot L_l \le 0`
    (the light is behind the surface), :math:`v_l` the optional `light_visibility` (shadows)
    and every product taken per RGB channel. All inputs broadcast over leading axes: one call
    shades a whole image or all the hits of a ray tracer.

    A light with **separate colours** (``point_light(..., ambient=, diffuse=, specular=)``, see
    :class:`Light`) feeds each term its own colour:

    .. math:: I = I_e + k_a \Big(I_a + \sum_l f_{att}(d_l) I_{a,l}\Big) + \sum_l f_{att}(d_l)
              \, v_l \left[k_d I_{d,l} \max(N \cdot L_l, 0) + k_s I_{s,l}
              \max(R_l \cdot V, 0)^n\right]

    The light's ambient part :math:`I_{a,l}` is attenuated with distance like the rest (as in
    OpenGL) but is not removed by shadows or by the light facing away: it stands for light the
    lamp spreads around the scene, arriving from every direction.

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
        :func:`point_light` and :func:`directional_light` objects, of one intensity or with
        separate ambient, diffuse and specular colours.
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

    >>> from course_lib.shading import colored_material, directional_light, point_light
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

    A lamp with a warm diffuse colour, a white highlight and a little ambient light of its own,
    on a grey material (ka = 0.2, kd = 0.5, ks = 0.4), seen along the normal under it:

    >>> lamp = point_light([0, 0, 2], diffuse=(1, 0.5, 0), specular=1, ambient=0.5)
    >>> grey = Material(ka=0.2, kd=0.5, ks=0.4)
    >>> np.round(phong([0, 0, 0], [0, 0, 1], [0, 0, 1], lamp, grey, ambient=0).total, 6)
    array([1.  , 0.75, 0.5 ])
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

    >>> from course_lib.shading import directional_light
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
