r"""Chapter 14: texturing: sampling, barycentric weights, mappings, procedural textures, mipmaps.

A texture is an image glued onto a surface: every surface point gets texture coordinates
:math:`(u, v)` (from a *mapping*: :func:`planar_map`, :func:`spherical_map`,
:func:`cylindrical_map`, or from per-vertex coordinates interpolated with :func:`barycentric`
weights), and the texture is *sampled* there (:func:`nearest_sample`, :func:`bilinear_sample`,
:func:`trilinear_sample` with a :func:`mipmap`). Procedural textures (:func:`checkerboard`,
:func:`perlin_noise`, :func:`marble`, :func:`wood`, ...) compute the colour from the
coordinates instead of looking it up.

Conventions
-----------
**Textures** are arrays of shape ``(H, W)`` (grey) or ``(H, W, C)`` (C channels, e.g. RGB), of
any numeric type; results are float. **Texel** ``(i, j)`` (row i, column j) covers the square
:math:`u \in [j/W, (j+1)/W]`, :math:`v \in [i/H, (i+1)/H]` of texture space and its **centre**
is at :math:`((j + \tfrac12)/W, (i + \tfrac12)/H)`: texel centres are where a texture
reproduces its texels exactly. **Row 0 is v = 0**, the *bottom* of the picture, as in OpenGL and
as :mod:`course_lib.visibility` stores images: show a texture with
``plt.imshow(texture, origin="lower", extent=(0, 1, 0, 1))`` (without ``origin="lower"`` it is
upside down; image files store the top row first, so flip them with ``texture[::-1]``).
In array coordinates (continuous row :math:`y`, column :math:`x`, texel centres at integers):

.. math:: x = u W - \tfrac12, \qquad y = v H - \tfrac12

**Wrap modes**, for :math:`(u, v)` outside :math:`[0, 1]`: ``"repeat"`` tiles the texture
(only the fractional part counts; OpenGL's ``GL_REPEAT``), ``"clamp"`` uses the nearest edge
texel (``GL_CLAMP_TO_EDGE``), ``"mirror"`` tiles it with every other copy mirrored
(``GL_MIRRORED_REPEAT``). scipy's ``ndimage.map_coordinates`` calls them ``"grid-wrap"``,
``"nearest"`` and ``"reflect"``.

Mappings (the course compendium's spherical formulas, corrected)
----------------------------------------------------------------
With the textbook's axes, the pole of a sphere on :math:`y` and the azimuth measured in the
:math:`xz` plane from :math:`+z` towards :math:`+x`, for :math:`d = P - C`,
:math:`r = \lVert d \rVert`:

.. math:: \theta = \operatorname{atan2}(d_x, d_z) \in (-\pi, \pi], \qquad
          \varphi = \arcsin(d_y / r) = \operatorname{atan2}\!\left(d_y,
          \sqrt{d_x^2 + d_z^2}\right) \in [-\tfrac\pi2, \tfrac\pi2]

.. math:: u = \tfrac12 + \frac{\theta}{2\pi}, \qquad v = \tfrac12 + \frac{\varphi}{\pi}

The compendium writes :math:`\theta = \tan^{-1}(x/z)` and an elevation
:math:`\tan^{-1}\big(y/\sqrt{x^2 + y^2}\big)`. Two mistakes: the elevation's horizontal
distance must be :math:`\sqrt{x^2 + z^2}` (the azimuth lives in the :math:`xz` plane; with
:math:`x^2 + y^2`, :math:`y` appears on both sides and the pole is not at :math:`\pi/2`), and
:math:`\tan^{-1}(x/z)` only covers half the circle (:math:`x/z` is the same for :math:`P` and
:math:`-P`): the two-argument :math:`\operatorname{atan2}` is needed.

* The **seam**: :math:`u` jumps from 1 to 0 across the half-plane behind the sphere
  (:math:`d_x = 0, d_z < 0`). A triangle straddling it gets :math:`u` values like 0.97 and 0.02
  and interpolates through the *whole* texture, a visible smeared stripe; :func:`seam_unwrap`
  shifts such a triangle's small :math:`u` by 1 (sample with ``wrap="repeat"``).
* The **poles**: :math:`u` is undefined at :math:`d = \pm r\,\hat y` (set to 1/2 here), and the
  whole top (bottom) row of the texture is squeezed into one point. The area of the sphere per
  unit of texture area is :math:`2\pi^2 r^2 \cos\varphi`: texels near the poles shrink by
  :math:`\cos\varphi`, the equator is the least distorted.

:func:`cylindrical_map` uses the same azimuth for :math:`u` and the height along the axis
(divided by the cylinder's height) for :math:`v`; it has the same seam, no pole distortion
(area per texel is constant), and is undefined on the axis itself. :func:`planar_map` projects
along the plane's normal: no seam, but everything along the normal gets the same texel
(stretched stripes on surfaces nearly parallel to the normal).

Files
-----

``sampling.py``
    Chapter 14 (lesson sections 1, 2): texture space, wrap modes, nearest and bilinear
    sampling.
``triangle_interpolation.py``
    Chapter 14 (lesson section 3): barycentric coordinates, perspective-correct interpolation.
    ``interpolate`` is :func:`barycentric_interpolate` under its old name (the same function).
``mappings.py``
    Chapter 14 (lesson section 4): mapping a surface to texture space.
``procedural.py``
    Chapter 14 (lesson section 5): procedural textures.
``mipmaps.py``
    Chapter 14 (lesson section 6): aliasing, mipmaps and trilinear filtering.
``hierarchies.py``
    Chapter 14 (textbook 14.9): texture hierarchies: level maps from screen-space
    derivatives, anisotropic filtering's level, a pyramid's memory, clipmaps, virtual textures.
``relief.py``
    Chapter 14 (textbook 14.7.1, 14.7.2): bump mapping, tangent frames, normal maps, and
    displacement mapping for contrast.
``texture_transforms.py``
    Chapter 14: texture transformations (tiling, offset, rotation, shear as 3x3 texture
    matrices; the picture moves opposite to the matrix).
``two_part.py``
    Chapter 14: two-part mapping (Bier and Sloan's S-mapping onto a plane, cylinder, sphere
    or box, and the four O-mappings).
``environment.py``
    Chapter 14 (lesson section: environment mapping): cube maps (the OpenGL face table),
    sphere maps, latitude-longitude maps, mirror look-ups and their limitations.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from ._common import (WRAP_MODES)
from .sampling import (bilinear_sample, nearest_sample, uv_grid)
from .triangle_interpolation import (barycentric, barycentric_interpolate, interpolate,
    perspective_interpolate, perspective_weights)
from .mappings import (cylindrical_map, inverse_cylindrical_map, inverse_planar_map,
    inverse_spherical_map, planar_map, seam_unwrap, spherical_map)
from .procedural import (checkerboard, marble, perlin_noise, stripes, turbulence, value_noise,
    wood)
from .mipmaps import (AliasingDemo, aliasing_demo, mip_level, mipmap, texel_footprint,
    trilinear_sample)
from .hierarchies import (ClipmapLayout, PlaneView, PyramidMemory, TileCache,
    anisotropic_level, clipmap, clipmap_level_used, clipmap_window, footprint_axes, level_map,
    level_shapes, pyramid_memory, receding_plane, tile_counts, tiles_needed, uv_derivatives)
from .relief import (bricks_height, bump_normal, bump_normal_tangent, bumps_height,
    decode_normals, displace, encode_normals, height_gradient, height_gradient_at, noise_height,
    normal_map_from_height, object_to_tangent, shade_normals, tangent_to_object,
    triangle_tangent_frame, vertex_tangent_frames)
from .texture_transforms import (apply_texture_matrix, texture_matrix, tile, transform_texture)
from .two_part import (box_face, intermediate_points, intersect_intermediate, s_map,
    two_part_map)
from .environment import (CUBE_FACES, cube_cross, cube_face_coordinates, cube_face_direction,
    cube_map_from_function, distant_environment_error, environment_lookup, latlong_coordinates,
    latlong_direction, latlong_map_from_function, mirror_sphere, reflect_view,
    sample_cube_map, sample_latlong_map, sample_sphere_map, sphere_map_coordinates,
    sphere_map_direction, sphere_map_from_function)

__all__ = [
    "AliasingDemo",
    "WRAP_MODES",
    "aliasing_demo",
    "barycentric",
    "barycentric_interpolate",
    "bilinear_sample",
    "checkerboard",
    "cylindrical_map",
    "inverse_cylindrical_map",
    "inverse_planar_map",
    "inverse_spherical_map",
    "marble",
    "mip_level",
    "mipmap",
    "nearest_sample",
    "perlin_noise",
    "perspective_interpolate",
    "perspective_weights",
    "planar_map",
    "seam_unwrap",
    "spherical_map",
    "stripes",
    "texel_footprint",
    "trilinear_sample",
    "turbulence",
    "uv_grid",
    "value_noise",
    "wood",
    # hierarchies.py
    "ClipmapLayout", "PlaneView", "PyramidMemory", "TileCache", "anisotropic_level", "clipmap",
    "clipmap_level_used", "clipmap_window", "footprint_axes", "level_map", "level_shapes",
    "pyramid_memory", "receding_plane", "tile_counts", "tiles_needed", "uv_derivatives",
    # relief mapping (relief.py)
    "bricks_height", "bump_normal", "bump_normal_tangent", "bumps_height", "decode_normals",
    "displace", "encode_normals", "height_gradient", "height_gradient_at", "noise_height",
    "normal_map_from_height", "object_to_tangent", "shade_normals", "tangent_to_object",
    "triangle_tangent_frame", "vertex_tangent_frames",
    # texture transformations, two-part mapping
    "apply_texture_matrix",
    "box_face",
    "intermediate_points",
    "intersect_intermediate",
    "s_map",
    "texture_matrix",
    "tile",
    "transform_texture",
    "two_part_map",
    # environment mapping
    "CUBE_FACES",
    "cube_cross",
    "cube_face_coordinates",
    "cube_face_direction",
    "cube_map_from_function",
    "distant_environment_error",
    "environment_lookup",
    "latlong_coordinates",
    "latlong_direction",
    "latlong_map_from_function",
    "mirror_sphere",
    "reflect_view",
    "sample_cube_map",
    "sample_latlong_map",
    "sample_sphere_map",
    "sphere_map_coordinates",
    "sphere_map_direction",
    "sphere_map_from_function",
]
