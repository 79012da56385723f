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
]
