r"""Chapter 12 exercises: light and radiometry, local illumination, BRDFs, interpolated shading,
ambient occlusion, exam style.

Each class is one kind of exam question: a solid angle (of a cone, a small patch, a region of the
sphere), the irradiance a point light gives at a distance and an angle, radiance against
intensity; the mirror direction :math:`R`; the diffuse, the specular and the whole Phong
intensity of a point under a grey light; Blinn-Phong's halfway vector and highlight; the
attenuation of a point light with distance; a matte surface under several lights; the Phong
colour under a light of separate ambient, diffuse and specular colours; which interpolated
shading method (flat, Gouraud, Phong) suits a situation, and Gouraud against Phong shading at the
midpoint of an edge; the radiance a Lambertian surface reflects, the normalisation of a Phong
lobe, the reflectance of a lobe (energy conservation), Schlick's Fresnel factor; ambient
occlusion from a list of sample rays, and its closed form next to a wall or in a trench; the
screen-space AO of a pixel from its kernel samples, and the samples SSAO needs for a noise
level. The ``seed`` draws numbers that
work out by hand: unit vectors with rational components such as :math:`(\tfrac23, \tfrac13,
\tfrac23)` or :math:`(0.6, 0, 0.8)`, distances that are whole numbers, small exponents, angles
that are multiples of 15 degrees.

The expected answers come from :mod:`course_lib.shading`. Each exercise names the slips it
anticipates (the incoming-direction reflection formula with the wrong sign, a normal left
unnormalised, a negative cosine not clamped, the exponent put on the coefficient, the ambient or
the emission term forgotten, :math:`1/d` for the attenuation, ...), computes the answer each slip
would give, and draws its numbers again until those answers differ clearly from the right one
and from each other (:class:`~course_lib.exercises.core.DrawnExercise`).

Conventions (those of :mod:`course_lib.shading` and the textbook): :math:`N, L, V, R` are unit
vectors that start at the surface point and point *away* from it (:math:`L` towards the light,
:math:`V` towards the viewer), :math:`R = 2 (N \cdot L) N - L`; a light with
:math:`N \cdot L \le 0` adds neither diffuse nor specular light; a point light at distance
:math:`d` is weakened by :math:`f_{att}(d) = 1 / (a + b d + c d^2)`; all lights here are grey
(one intensity for all three channels), so every intensity is one number, except in
:class:`PhongLightColours`, whose light has three RGB colours.

The boundary cases of the clamps :math:`\max(\cdot, 0)` (a light behind the surface, a viewer
away from the mirror direction, a halfway vector below the surface) are variants of their own,
labelled by the attribute ``boundary`` (None for the common case) and drawn in about 15 % of
the seeds: a case to know, not the usual answer. Every exercise gives step-by-step hints
(``hint()``) and the worked solution of its variant (``solution()``).

The exercises live in :mod:`course_lib.exercises._ch12`, one module per topic (what
the topics share is in its ``__init__``); import them from here.
"""
from ._ch12.radiometry import PointLightIrradiance, RadianceIntensity, SolidAngle
from ._ch12.vectors import ReflectionVector
from ._ch12.phong import (BlinnPhongHighlight, DiffuseTerm, DistanceAttenuation, PhongTotal,
                          SeveralLights, SpecularTerm)
from ._ch12.interpolation import SHADING_METHODS, GouraudVersusPhong, ShadingMethodChoice
from ._ch12.brdf import LambertRadiance, LobeReflectance, PhongNormalization, SchlickFresnel
from ._ch12.ambient_occlusion import AmbientOcclusionSamples, AmbientOcclusionWall
from ._ch12.light_colours import PhongLightColours
from ._ch12.ssao import SSAOPixel, SSAOSampleCount

__all__ = [
    "EXERCISES",
    "SHADING_METHODS",
    "AmbientOcclusionSamples",
    "AmbientOcclusionWall",
    "BlinnPhongHighlight",
    "DiffuseTerm",
    "DistanceAttenuation",
    "GouraudVersusPhong",
    "LambertRadiance",
    "LobeReflectance",
    "PhongLightColours",
    "PhongNormalization",
    "PhongTotal",
    "PointLightIrradiance",
    "RadianceIntensity",
    "ReflectionVector",
    "SSAOPixel",
    "SSAOSampleCount",
    "SchlickFresnel",
    "SeveralLights",
    "ShadingMethodChoice",
    "SolidAngle",
    "SpecularTerm",
]

#: The exercises of chapter 12, in the order of the solutions notebook.
EXERCISES = (
    SolidAngle,
    PointLightIrradiance,
    RadianceIntensity,
    ReflectionVector,
    DiffuseTerm,
    SpecularTerm,
    PhongTotal,
    BlinnPhongHighlight,
    DistanceAttenuation,
    SeveralLights,
    PhongLightColours,
    ShadingMethodChoice,
    GouraudVersusPhong,
    LambertRadiance,
    PhongNormalization,
    LobeReflectance,
    SchlickFresnel,
    AmbientOcclusionSamples,
    AmbientOcclusionWall,
    SSAOPixel,
    SSAOSampleCount,
)
