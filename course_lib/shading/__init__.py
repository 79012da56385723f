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
  (:func:`reflect`), pointing away from the surface too. A ray tracer's incoming direction
  :math:`d` points *towards* the surface: its mirror direction is ``reflect(-d, n)``, which
  :func:`course_lib.raytracing.reflect_direction` ``(d, n)`` computes.

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
should, at one evaluation per pixel). :func:`barycentric_buffers` rasterizes a mesh once (the
visible face and barycentric weights per pixel), so that ``render_shaded(...,
fragments=...)`` re-shades it without a new z-buffer pass.

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

Files
-----

``radiometry.py``
    Chapter 12 (lesson section 1): radiometric quantities, solid angles, irradiance from point
    and area lights.
``vectors.py``
    Chapter 12 (lesson section 2): the vectors of the model: normal, light, view, reflection,
    halfway.
``materials.py``
    Chapter 12 (lesson sections 3.1, 3.2): materials, and light sources of one intensity or of
    separate ambient, diffuse and specular colours.
``illumination.py``
    Chapter 12 (lesson sections 3, 4): the Lambert, Phong and Blinn-Phong models.
``interpolated.py``
    Chapter 12 (lesson section 5): vertex normals and flat, Gouraud and Phong shading of
    meshes.
``brdf.py``
    Chapter 12 (lesson section 6): BRDFs (Lambert, Phong, Blinn-Phong, mirror), Fresnel and
    Schlick, the reflectance equation, reflectance and the energy/reciprocity checks.
``occlusion.py``
    Chapter 12 (lesson section 7): ambient occlusion, sampled by rays and in closed form.
``ssao.py``
    Chapter 12 (lesson section 7.1): ambient occlusion in screen space (SSAO) from a G-buffer.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from .materials import (Light, Material, attenuation, colored_material, directional_light,
    material_per_point, point_light)
from .vectors import (halfway, reflect, view_directions)
from .illumination import (PhongTerms, blinn_phong, phong)
from .interpolated import (BarycentricBuffers, ShadedImage, barycentric_buffers, face_normals,
    render_shaded, uv_sphere, vertex_normals)
from .occlusion import (AmbientOcclusion, HeightField, ambient_occlusion,
    ambient_occlusion_closed_form, cosine_sample_hemisphere)
from .radiometry import (QUANTITIES, PointIrradiance, Quantity, cone_solid_angle,
    emitter_intensity, isotropic_intensity, lambertian_exitance, lambertian_radiance,
    patch_solid_angle, point_light_irradiance, polygon_light_irradiance, polygon_solid_angle,
    small_light_irradiance, spherical_region_solid_angle)
from .ssao import (GBuffer, RayTracedOcclusion, SSAOScene, box_blur, g_buffer,
    positions_from_depth, ray_traced_occlusion, ssao, ssao_kernel, ssao_test_scene)
from .brdf import (BRDFCheck, blinn_phong_brdf, blinn_phong_normalization, check_brdf,
    combined_brdf, fresnel_dielectric, fresnel_schlick, hemispherical_reflectance, lambert_brdf,
    mirror_radiance, phong_brdf, phong_normalization, reflected_radiance, schlick_f0)

__all__ = [
    "ambient_occlusion",
    "ambient_occlusion_closed_form",
    "AmbientOcclusion",
    "attenuation",
    "barycentric_buffers",
    "BarycentricBuffers",
    "blinn_phong",
    "blinn_phong_brdf",
    "blinn_phong_normalization",
    "box_blur",
    "BRDFCheck",
    "check_brdf",
    "colored_material",
    "combined_brdf",
    "cone_solid_angle",
    "cosine_sample_hemisphere",
    "directional_light",
    "emitter_intensity",
    "face_normals",
    "fresnel_dielectric",
    "fresnel_schlick",
    "g_buffer",
    "GBuffer",
    "halfway",
    "HeightField",
    "hemispherical_reflectance",
    "isotropic_intensity",
    "lambert_brdf",
    "lambertian_exitance",
    "lambertian_radiance",
    "Light",
    "Material",
    "material_per_point",
    "mirror_radiance",
    "patch_solid_angle",
    "phong",
    "phong_brdf",
    "phong_normalization",
    "PhongTerms",
    "point_light",
    "positions_from_depth",
    "point_light_irradiance",
    "PointIrradiance",
    "polygon_light_irradiance",
    "polygon_solid_angle",
    "QUANTITIES",
    "Quantity",
    "ray_traced_occlusion",
    "RayTracedOcclusion",
    "reflect",
    "reflected_radiance",
    "render_shaded",
    "schlick_f0",
    "ShadedImage",
    "small_light_irradiance",
    "spherical_region_solid_angle",
    "ssao",
    "ssao_kernel",
    "ssao_test_scene",
    "SSAOScene",
    "uv_sphere",
    "vertex_normals",
    "view_directions",
]
