"""The concept questions of chapter 14 (see :mod:`course_lib.exercises.concepts`)."""
from .question import _mc, _tf

__all__ = ["QUESTIONS"]

#: The chapter's questions, in the order the mock exam and the lessons list them.
QUESTIONS = [
    _tf(14, "ch14-barycentric-sum",
        "The barycentric coordinates of a point in a triangle are non-negative and sum to 1, "
        "and each equals the area of the opposite sub-triangle divided by the whole area.",
        True,
        "Joining the point to the corners splits the triangle into three parts; the part "
        "opposite a corner, relative to the whole, is that corner's weight.",
        "It holds for points inside (outside, some coordinate turns negative)."),
    _mc(14, "ch14-triangle-interp",
        "How should texture coordinates be interpolated across a single triangle?",
        ("Bilinearly, from the triangle's bounding box", "A triangle has three corners; "
         "bilinear interpolation needs four and depends on the orientation of the box."),
        ("Nearest vertex", "That gives three constant patches, not a smooth mapping."),
        ("With barycentric coordinates (perspective-correct after projection)",
         "They give the unique linear interpolation of the three corner values."),
        ("By the polar angle around the centroid", "That is not a linear interpolation."),
        correct=2),
    _mc(14, "ch14-magnification",
        "A texture is **magnified** (one texel covers many pixels). Which filter removes the "
        "blocky look?",
        ("Mipmapping", "Mipmaps help minification, where many texels fall into one pixel."),
        ("Bilinear interpolation of the four nearest texels", "It blends neighbouring texels "
         "smoothly instead of repeating one."),
        ("Nearest-neighbour sampling", "That is what produces the blocks."),
        ("Supersampling the texture", "There is nothing to average: one texel already covers "
         "many pixels."),
        correct=1),
    _mc(14, "ch14-mipmap",
        "Why are mipmaps used, and what do they cost?",
        ("Against aliasing under minification; about a third more texture memory",
         "Prefiltered half-size levels are chosen by the pixel's footprint; the levels add "
         "$\\tfrac14 + \\tfrac1{16} + \\dots = \\tfrac13$ of the base size."),
        ("Against blockiness under magnification; twice the memory", "Magnification uses the "
         "base level with bilinear filtering; and the overhead is a third, not double."),
        ("To compress textures; they save memory", "They add memory."),
        ("For procedural textures only", "They prefilter image textures."),
        correct=0),
    _tf(14, "ch14-procedural",
        "A procedural texture is computed from a function of the coordinates, so it needs "
        "little memory and has no fixed resolution.", True,
        "It can be evaluated at any point and any scale (and in 3D for solid textures); the "
        "price is computation and harder antialiasing.",
        "It is true: no image is stored."),
    _mc(14, "ch14-mapping-type",
        "Which intermediate surface suits a texture on a bottle or a can?",
        ("Planar", "A plane projects along one direction and smears the texture on the sides."),
        ("Spherical", "Usable, but it distorts a long straight body; the poles squeeze."),
        ("Cube", "Possible, but it has seams at the cube edges around a round body."),
        ("Cylindrical: $u$ from the angle around the axis, $v$ from the height",
         "It matches the shape: a rectangle wrapped around it, with one seam."),
        correct=3),
    _tf(14, "ch14-spherical-poles",
        "A spherical mapping of a rectangular image squeezes the whole top row of the image "
        "into a single point (a pole).", True,
        "At the pole the longitude is undefined: all $u$ values meet there, so the texture is "
        "compressed and distorted near the poles.",
        "It does, for the latitude-longitude (spherical) mapping: the longitude is undefined at "
        "the pole, so the whole top row meets there. That is a property of this mapping, not of "
        "every way to put an image on a sphere: cube maps and octahedral maps have no such "
        "point (they have seams between their faces instead)."),
    _tf(14, "ch14-bump-silhouette",
        "Bump mapping changes the silhouette of an object.", False,
        "It does not: it perturbs only the normals used in lighting; the geometry and thus the "
        "outline stay the same. Displacement mapping moves the surface and changes it.",
        "Right: only the shading normals change, so outlines stay smooth."),
    _mc(14, "ch14-environment",
        "What does environment (reflection) mapping look up in a texture?",
        ("The surface normal as a colour", "That is a normal map."),
        ("The colour seen in the reflected view direction, from an image of the surroundings "
         "(cube or sphere map)", "A cheap imitation of mirror reflections, exact only for "
         "surroundings far away."),
        ("The height of the surface", "That is a displacement or bump map."),
        ("The shadow of the object", "Shadow maps store depths from the light."),
        correct=1),
    # texture transformations and two-part mapping
    _mc(14, "ch14-two-part-purpose",
        "What problem does two-part (S-mapping + O-mapping) texture mapping solve?",
        ("It gives (u, v) to an arbitrary object that has no natural parametrization, through a "
         "simple intermediate surface that has one", "The S-mapping puts the texture on a "
         "plane, cylinder, sphere or box; the O-mapping carries each object point to that "
         "surface."),
        ("It removes aliasing under minification", "That is mipmapping's job; two-part mapping "
         "only decides which (u, v) a point gets."),
        ("It makes the mapping free of distortion on every object", "It cannot: the O-mapping "
         "stretches the texture wherever the object's shape departs from the intermediate "
         "surface."),
        ("It interpolates texture coordinates across triangles perspective-correctly",
         "That is done after the mapping, by the rasterizer with 1/w."),
        correct=0),
    _mc(14, "ch14-two-part-view-dependent",
        "Which of the four O-mappings changes when only the eye moves?",
        ("The object's normal", "The normal belongs to the object: it does not depend on the "
         "eye."),
        ("The line through the object's centroid", "The centroid and the point are fixed on "
         "the object."),
        ("The intermediate surface's normal", "Only the two surfaces are involved."),
        ("The reflected view ray: that is environment mapping", "The view direction is "
         "mirrored about the normal, so the texture slides over the object as the eye moves, "
         "like a reflection."),
        correct=3),
    _tf(14, "ch14-texture-matrix-opposite",
        "Adding an offset of +0.25 to the texture coordinates (the texture matrix T(0.25, 0)) "
        "moves the picture on the surface by +0.25 in u.", False,
        "The matrix maps coordinates: the point that used to see u = 0 now sees u = 0.25, so "
        "the feature at u = 0.25 appears where u = 0 was; the picture moves by -0.25. To move "
        "it by +0.25 use the inverse matrix T(-0.25, 0).",
        "Right: the picture moves the opposite way, by -0.25 (the inverse of the matrix)."),
]
