"""The concept questions of chapter 12 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _mc(12, "ch12-phong-view-dependent",
        "Which term of the Phong illumination model changes when only the viewer moves?",
        ("The diffuse term", "It depends on $\\vec n \\cdot \\vec l$ only: a matte surface "
         "looks equally bright from every direction."),
        ("The ambient term", "It is a constant $I_a k_a$."),
        ("The specular term", "It depends on the angle between the mirror direction "
         "$\\vec r$ and the direction to the viewer $\\vec v$: the highlight moves with the "
         "eye."),
        ("The emission term", "Emitted light is the same in every direction."),
        correct=2),
    _mc(12, "ch12-diffuse-law",
        "The diffuse term $I_d = I_l k_d \\max(0, \\hat n \\cdot \\hat l)$ follows which law?",
        ("Lambert's cosine law: the irradiance falls with the cosine of the angle of "
         "incidence", "A beam hitting at a slant spreads over a larger area, so each unit area "
         "receives less light."),
        ("Snell's law", "That governs refraction."),
        ("The inverse square law", "Distance attenuation is a separate factor, not the "
         "cosine."),
        ("Fresnel's law", "Fresnel gives how much is reflected versus refracted."),
        correct=0),
    _tf(12, "ch12-specular-exponent",
        "A larger shininess exponent $n$ in $(\\hat r \\cdot \\hat v)^n$ makes the specular "
        "highlight smaller and sharper.", True,
        "Raising a cosine below 1 to a higher power makes it fall off faster away from the "
        "mirror direction: a tighter highlight, like polished metal.",
        "It does: the cosine lobe narrows as the exponent grows."),
    _tf(12, "ch12-ambient-meaning",
        "The ambient term models light that reaches a point after bouncing between other "
        "surfaces, approximated as a constant.", True,
        "Local illumination ignores inter-reflections; the ambient term is a crude constant "
        "stand-in for them, so that unlit sides are not pitch black.",
        "That is exactly its purpose: a constant replacement for indirect light."),
    _mc(12, "ch12-blinn",
        "What does Blinn-Phong use instead of $\\hat r \\cdot \\hat v$?",
        ("$\\hat l \\cdot \\hat v$", "That ignores the surface orientation."),
        ("$\\hat n \\cdot \\hat h$ with the halfway vector $\\hat h = \\frac{\\hat l + \\hat "
         "v}{\\|\\hat l + \\hat v\\|}$", "The highlight peaks when the normal bisects light and "
         "view; it is cheaper (no reflection vector) and behaves better at grazing angles."),
        ("$\\hat n \\cdot \\hat l$", "That is the diffuse factor."),
        ("$\\hat r \\cdot \\hat l$", "Not a meaningful quantity for the highlight."),
        correct=1),
    _mc(12, "ch12-gouraud",
        "Gouraud shading computes lighting at the vertices and interpolates the colours. What is "
        "its typical artefact?",
        ("It cannot show diffuse shading", "Diffuse shading varies slowly and interpolates "
         "well."),
        ("It makes every face a single flat colour", "That is flat shading."),
        ("It is slower than Phong shading", "It is cheaper: lighting per vertex, not per "
         "pixel."),
        ("A specular highlight inside a triangle is missed or smeared, and the highlight "
         "jumps as the mesh moves", "Interpolating colours cannot create a peak that no "
         "vertex sees; Phong shading interpolates normals and lights per pixel."),
        correct=3),
    _tf(12, "ch12-phong-shading-normals",
        "Phong *shading* interpolates the vertex normals across a polygon and evaluates the "
        "lighting at every pixel.", True,
        "That is the difference from Gouraud shading (interpolated colours); the interpolated "
        "normal must be renormalized.",
        "It does; do not confuse the Phong *illumination model* with Phong *shading*, the "
        "interpolation method."),
    _tf(12, "ch12-diffuse-view",
        "Moving the camera changes the diffuse term of the Phong model at a fixed surface "
        "point.", False,
        "It does not: the diffuse term uses only the normal and the light direction.",
        "Right: the diffuse term is view-independent; only the specular term changes."),
    _mc(12, "ch12-ambient-occlusion",
        "What does ambient occlusion compute at a surface point?",
        ("The distance to the light source", "Ambient occlusion ignores the light sources."),
        ("The fraction of the hemisphere above the point that is not blocked by nearby "
         "geometry (usually cosine-weighted)", "Creases and corners see less of the sky and get "
         "darker; the factor scales the ambient term."),
        ("The colour of the nearest object", "Colour bleeding is a global-illumination effect, "
         "not ambient occlusion."),
        ("Whether the point is in the view frustum", "That is frustum culling."),
        correct=1),
    _tf(12, "ch12-negative-dot",
        "When $\\hat n \\cdot \\hat l < 0$ the diffuse and specular terms of that light must be "
        "set to 0.", True,
        "The light is behind the surface; without clamping, a negative cosine would subtract "
        "light.",
        "They must: the light shines on the other side of the surface."),
    _mc(12, "ch12-inverse-square",
        "A small lamp shines straight down on a desk. It is raised from 1 m to 2 m above the "
        "desk. What happens to the irradiance on the desk directly below it?",
        ("It halves", "That would be a $1/d$ law. The flux of the lamp through a cone spreads "
         "over an area that grows with the square of the distance."),
        ("It falls to a quarter", "$E = I \\cos\\theta / d^2$: twice the distance, a quarter "
         "of the irradiance (the same solid angle covers four times the area)."),
        ("It stays the same", "Only a directional light (the sun) gives the same irradiance at "
         "any distance; a point light's falls off with distance."),
        ("It falls to an eighth", "That would be $1/d^3$; the area a solid angle covers grows "
         "like $d^2$."),
        correct=1),
    _mc(12, "ch12-solid-angle-unit",
        "In which unit is a solid angle measured, and how large is the whole sphere of "
        "directions?",
        ("Degrees; 360", "Degrees measure plane angles."),
        ("Steradians; $2\\pi$", "$2\\pi$ sr is the hemisphere above a surface, half the "
         "sphere."),
        ("Steradians; $4\\pi$", "A solid angle is the area it cuts out of the unit sphere: the "
         "whole sphere has area $4\\pi$."),
        ("Square metres; $4\\pi r^2$", "That is an area at distance $r$; dividing by $r^2$ "
         "makes the solid angle independent of the distance."),
        correct=2),
    _tf(12, "ch12-radiance-distance",
        "The radiance arriving along a ray through empty space does not change with the "
        "distance travelled, although the irradiance a distant source gives does.", True,
        "Radiance is flux per unit projected area *per unit solid angle*: farther away, a "
        "patch receives less flux but the source covers a smaller solid angle, and the two "
        "cancel. That is why a wall looks equally bright from near and far.",
        "It is true: the $1/d^2$ loss of flux is matched by the $1/d^2$ shrinking of the "
        "solid angle the source fills, so the ratio, the radiance, is constant."),
    _mc(12, "ch12-brdf-definition",
        "What is the bidirectional reflectance distribution function $f_r(\\omega_i, "
        "\\omega_o)$ of a surface?",
        ("The fraction of the incident flux that is reflected, a number in [0, 1]", "That is "
         "the reflectance (albedo), an integral of the BRDF over the outgoing directions."),
        ("The ratio of the radiance reflected towards $\\omega_o$ to the irradiance arriving "
         "from $\\omega_i$, in 1/sr", "$f_r = dL_r / dE_i$; it may exceed 1 for a sharp lobe, "
         "since it is a density over directions."),
        ("The radiance a surface emits by itself", "That is emission, independent of the light "
         "received."),
        ("The angle between the incident and the reflected ray", "A mirror's angles are equal; "
         "a BRDF describes how much light goes in every direction."),
        correct=1),
    _mc(12, "ch12-lambert-brdf",
        "A matte (Lambertian) surface reflects a fraction $\\rho$ of the light it receives, "
        "equally in all directions. What is its BRDF?",
        ("$\\rho$", "Integrated over the hemisphere with the cosine weight that would reflect "
         "$\\pi\\rho$, more than it receives."),
        ("$\\rho / (2\\pi)$", "$2\\pi$ is the solid angle of the hemisphere, but the reflected "
         "flux weighs each direction by $\\cos\\theta$, and $\\int \\cos\\theta\\,d\\omega = "
         "\\pi$."),
        ("$\\rho / \\pi$", "The constant $f$ with $\\int_\\Omega f \\cos\\theta\\, d\\omega = "
         "\\pi f = \\rho$."),
        ("$\\rho \\cos\\theta$", "The cosine belongs to the irradiance, not to the BRDF, which "
         "is constant for a Lambertian surface."),
        correct=2),
    _tf(12, "ch12-reciprocity",
        "A physically plausible BRDF is unchanged when the incident and the outgoing directions "
        "are swapped.", True,
        "Helmholtz reciprocity: $f_r(\\omega_i, \\omega_o) = f_r(\\omega_o, \\omega_i)$. The "
        "original Phong model, as a BRDF $k_s \\cos^n\\alpha / \\cos\\theta_i$, breaks it; the "
        "modified Phong BRDF $k_s \\cos^n \\alpha$ keeps it.",
        "It is true; light paths can be followed either way, which is what lets a ray tracer "
        "trace from the eye."),
    _mc(12, "ch12-phong-normalisation",
        "Why is a normalised Phong BRDF multiplied by $(n+2)/(2\\pi)$?",
        ("To make the highlight brighter for every exponent", "Without it a larger exponent "
         "reflects less; the factor compensates exactly, it is not a brightness knob."),
        ("So that its reflectance at normal incidence is $k_s$ whatever the exponent $n$: "
         "$\\int \\cos^n\\alpha \\cos\\theta\\, d\\omega = 2\\pi/(n+2)$", "A sharper lobe "
         "concentrates the same reflected energy in fewer directions, so its peak must grow."),
        ("To convert degrees to radians", "No angle conversion is involved."),
        ("Because the hemisphere has solid angle $2\\pi$ and there are $n+2$ lights", "The "
         "number of lights has nothing to do with it."),
        correct=1),
    _mc(12, "ch12-fresnel-grazing",
        "What does the Fresnel factor predict for a glass or water surface seen at a grazing "
        "angle?",
        ("It reflects almost nothing", "That is at normal incidence, where glass reflects about "
         "4 %."),
        ("Its reflectance rises towards 1", "At grazing incidence almost all light is reflected: "
         "a lake mirrors the far shore while you see the bottom at your feet; Schlick: $F_0 + "
         "(1 - F_0)(1 - \\cos\\theta)^5 \\to 1$."),
        ("Its reflectance does not depend on the angle", "That would make $F$ a constant like "
         "$k_s$; Fresnel's equations depend on the angle."),
        ("It becomes completely transparent", "The transmitted part shrinks, not grows, at "
         "grazing angles."),
        correct=1),
    _mc(12, "ch12-ssao-input",
        "What does screen-space ambient occlusion use to decide whether a sample point near a "
        "pixel's surface is occluded?",
        ("Rays cast against every triangle of the scene", "That is ray-traced ambient "
         "occlusion; SSAO avoids it."),
        ("The depth buffer: the sample is projected to the screen and compared with the depth "
         "stored there", "Only what the z-buffer holds is known: the visible surfaces, seen "
         "from the camera."),
        ("The light sources' positions", "Ambient occlusion does not depend on the lights."),
        ("The texture coordinates of the pixel", "Textures play no part."),
        correct=1),
    _tf(12, "ch12-ssao-halo",
        "Without a range check, a floor seen behind a floating object gets a dark halo around "
        "the object's silhouette in SSAO.", True,
        "The object's depth is in front of the floor's samples near its outline, so they count "
        "as occluded although the object is far away; fading out occluders much further than "
        "the radius removes the halo.",
        "It does: the depth buffer cannot tell a near occluder from a far one in front, which "
        "is what the range check fixes."),
    _tf(12, "ch12-ssao-offscreen",
        "SSAO darkens a point under a shelf even when the shelf is outside the picture.", False,
        "Geometry that is not on the screen is not in the depth buffer, so SSAO cannot see it; "
        "ray-traced AO does.",
        "Right: off-screen (and hidden) geometry is missing from the depth buffer, a known "
        "limitation of screen-space methods."),
    _mc(12, "ch12-light-colours",
        "A lamp has a red diffuse colour and a white specular colour. How does a white "
        "plastic ball (white $k_d$, grey $k_s$) under it look?",
        ("Red, with a white highlight", "Each colour of the light feeds its own term: "
         "$k_d \\odot I_d$ is red, $k_s I_s$ white."),
        ("White, with a red highlight", "The colours are swapped: the highlight takes the "
         "specular colour."),
        ("Pink all over", "The terms are not mixed: the diffuse and specular terms each take "
         "one colour of the light."),
        ("Red, with a red highlight", "The highlight's colour is the light's specular colour "
         "(times $k_s$), white here."),
        correct=0),
]
