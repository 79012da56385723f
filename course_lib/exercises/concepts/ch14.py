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
    # texture hierarchies (textbook 14.9)
    _mc(14, "ch14-pyramid-bound",
        "Why does the full mipmap chain of a square 2D texture cost less than $\\tfrac43$ of "
        "the texture, and what is the bound for a 3D (volume) texture?",
        ("Each level has a quarter of the texels of the one before, so the chain is "
         "$N(1 + \\tfrac14 + \\tfrac1{16} + \\dots) < \\tfrac43 N$; in 3D each level has an "
         "eighth: $\\tfrac87 N$",
         "Halving every side divides the texels by $2^d$ in $d$ dimensions; the geometric series "
         "sums to $1/(1 - 2^{-d})$."),
        ("Each level has half the texels, so the chain is under $2N$; in 3D $\\tfrac43 N$",
         "Halving **both** sides quarters a 2D level; $1 + \\tfrac12 + \\dots = 2$ is the series "
         "of a 1D texture."),
        ("Because the 1 x 1 level is not stored; in 3D the bound is the same",
         "The 1 x 1 level is stored (it is the average colour), and a volume's levels shrink "
         "by 8, so its bound is smaller: $\\tfrac87$."),
        ("Because the levels are compressed; in 3D $2N$",
         "Nothing is compressed: the count follows from the sizes alone."),
        correct=0),
    _mc(14, "ch14-anisotropic",
        "A floor seen at a grazing angle looks blurred in the distance with trilinear "
        "filtering. What does anisotropic filtering change?",
        ("It picks the level of the footprint's short axis and averages several samples "
         "along the long axis",
         "The footprint is a long thin ellipse; one isotropic level must cover its long axis "
         "and so blurs the short one. $N \\approx P_{max}/P_{min}$ samples at "
         "$\\log_2 P_{min}$ keep it sharp without aliasing."),
        ("It uses a finer level everywhere", "A finer level with one sample aliases along "
         "the long axis: the moire comes back."),
        ("It blends between the two nearest levels", "That is trilinear filtering, which "
         "still uses a square (isotropic) footprint."),
        ("It stores extra mipmap levels squeezed in one direction only", "Those are "
         "rip-maps, another remedy (4 times the memory); anisotropic filtering as GPUs do it "
         "uses the ordinary mip chain."),
        correct=0),
    _tf(14, "ch14-clipmap-virtual",
        "Clipmaps and virtual textures let a renderer use textures far larger than memory, "
        "because a view only needs fine texels near the viewer and coarse texels further away.",
        True,
        "A pixel needs level $\\log_2 \\rho$, which grows with distance: a clipmap keeps a "
        "fixed window of every fine level around the viewer (memory grows with the number of "
        "levels, not the texture's area); a virtual texture loads only the tiles the current "
        "view samples and falls back to a coarser resident tile until a missing one arrives.",
        "It is true: the memory a view needs is set by the screen's pixels, not by the "
        "texture's size."),
    # relief mapping (bump, normal and displacement maps)
    _mc(14, "ch14-relief-limits",
        "A brick wall is bump mapped with deep mortar grooves. What can the bump map *not* "
        "show?",
        ("Light and dark sides of each brick that follow the light", "It can: that is exactly "
         "what the perturbed normals change, pixel by pixel."),
        ("Bricks that stick out of the wall's outline and shadow each other at a grazing "
         "light", "Right: the points do not move, so the outline stays flat and no brick can "
         "hide or shadow another; that needs displacement (or parallax/shadow tricks)."),
        ("Highlights on the edges of the bricks", "It can: the specular term uses the perturbed "
         "normal too."),
        ("A different look when the light moves", "It can: the shading is recomputed with the "
         "new light direction and the bumped normals."),
        correct=1),
    _mc(14, "ch14-normal-map-blue",
        "Why do tangent-space normal maps look mostly light blue?",
        ("Blue is the colour channel with the most bits", "All three channels have the same "
         "8 bits."),
        ("Most perturbed normals are close to the unperturbed normal $(0, 0, 1)$ of the "
         "tangent frame, which encodes as $(0.5, 0.5, 1)$", "Right: $c = (n + 1)/2$ maps "
         "$n_z \\approx 1$ to a full blue channel and $n_x, n_y \\approx 0$ to mid red and "
         "green."),
        ("The blue channel stores the height", "A normal map stores a direction; the height "
         "is in a bump or displacement map."),
        ("Blue marks the front faces", "Nothing about facing is stored; the colour is the "
         "normal's components."),
        correct=1),
    _mc(14, "ch14-normal-map-space",
        "A character's mesh is skinned (it bends at the joints) and its left half uses the "
        "right half's texture mirrored. Which normal map works?",
        ("An object-space map: it stores the final normals directly", "Those normals are fixed "
         "in the object's frame: when an arm bends they do not turn with it, and a mirrored "
         "copy would need its own texels."),
        ("A tangent-space map, with per-vertex (T, B, N) that deform with the mesh and a "
         "handedness sign for the mirrored half", "Right: the stored normal is relative to "
         "the surface, so it follows any deformation, and the sign $w$ flips $B$ where the "
         "texture is mirrored."),
        ("Either: the two kinds store the same numbers", "They differ: an object-space texel "
         "is a direction in the object's frame, a tangent-space texel one relative to the "
         "surface."),
        ("Neither: a bending mesh needs displacement mapping", "A normal map works on "
         "deforming meshes if it is in tangent space."),
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
    # environment mapping
    _mc(14, "ch14-env-distant",
        "An environment map is rendered from the centre of a room whose walls are about 3 m "
        "away. A mirror ball is placed 2 m from that centre, near one wall, and looks its "
        "reflections up in the map. What goes wrong?",
        ("Nothing: the map stores directions, and a direction is the same everywhere",
         "The look-up uses only the direction, but what a direction shows depends on where "
         "you stand: the map holds the view from its centre. That is exact only for "
         "surroundings infinitely far away."),
        ("It reflects the wrong parts of the room: a reflected ray leaving the ball hits "
         "another point of the wall than the ray with the same direction from the map's "
         "centre, here up to $\\arcsin(2/3) \\approx 42°$ off",
         "Right: the map assumes a distant environment. For an offset $d$ and walls at "
         "distance $R$ the look-up misses by up to $\\arcsin(d/R)$ (rays perpendicular to "
         "the offset), and not at all along it; it is fine for a small object at the centre "
         "or a far environment (a sky)."),
        ("Its reflections turn blurry, because the map's resolution falls with the distance "
         "from the centre", "The map's resolution does not depend on where the object "
         "stands; the error is a shift of what is reflected, not a blur."),
        ("It starts to reflect itself", "The map is rendered without the object (or the "
         "object would hide the room); a direction-only look-up can never show the object, "
         "wherever it stands."),
        correct=1),
    _tf(14, "ch14-env-self-reflection",
        "With environment mapping, a teapot's spout can be seen reflected in the teapot's "
        "own body.", False,
        "It cannot: the map holds only the surroundings seen from one point, rendered "
        "without the teapot, and the look-up asks for a direction, never a position. The "
        "reflected ray from the body that would hit the spout gets the room behind the spout. "
        "Self-reflections (and reflections of nearby objects) need ray tracing, or a map "
        "rendered for each reflector without itself.",
        "Right: a direction-only look-up in a map of the surroundings cannot find the object "
        "itself; the reflected ray from the body towards the spout shows the room behind it."),
    _mc(14, "ch14-env-sphere-map",
        "A sphere map was made for a viewer looking along $-z$. What are its two weak "
        "points?",
        ("None: a single disc holds every direction, so it suits every view",
         "It holds every direction, but indexed in eye space for one viewing direction: "
         "when the camera turns, the map must be remade (or the reflections come from the "
         "wrong side of the world)."),
        ("It is correct for one viewing direction only, and the direction straight behind "
         "the ball, $r = (0, 0, -1)$, is smeared over the whole rim of the disc",
         "Right: $m = 2\\sqrt{r_x^2 + r_y^2 + (r_z + 1)^2}$ is 0 there; the directions "
         "close to it are spread around the whole rim, so they are badly sampled and "
         "neighbouring directions land on opposite sides of the disc."),
        ("Its singular direction is $r = (0, 0, 1)$, straight back at the viewer, at the "
         "centre of the disc", "That direction maps to $(s, t) = (\\tfrac12, "
         "\\tfrac12)$, the best-sampled point of the disc; the singular one is "
         "$(0, 0, -1)$, behind the ball."),
        ("It has a seam along a meridian, like a latitude-longitude map",
         "It has no seam; its one bad place is the rim, where the direction behind the ball "
         "is spread out."),
        correct=1),
    _mc(14, "ch14-env-cube-vs-sphere",
        "Why do renderers prefer cube maps to sphere maps for reflections?",
        ("A cube map needs a single texture look-up with one pair of coordinates",
         "It needs the choice of a face first (the major axis), then $(s, t)$ on it; "
         "graphics hardware does both, but it is six images, not one."),
        ("A cube map has no seams", "It has twelve edges where faces meet; classic "
         "filtering stays within one face and can show them (hence seamless cube-map "
         "filtering)."),
        ("A cube map can be made from one photograph of a mirror ball",
         "That photograph is a sphere map; a cube map takes six 90° views (or resampling)."),
        ("A cube map does not depend on the viewer and has no singular direction, so one "
         "map serves every viewpoint; the price is six faces and seams along the edges",
         "Right: it is indexed by world-space directions and distorts little (a texel at a "
         "face's corner covers $1/(3\\sqrt3)$ of the solid angle of one at its centre); "
         "a sphere map must be remade when the view turns and smears the direction behind "
         "the ball over its rim."),
        correct=3),
]
