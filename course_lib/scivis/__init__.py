r"""Chapter 18: scientific visualization algorithms for scalar and vector fields.

Measured and simulated data usually come as samples on a regular grid: a 2D field (a height map,
a temperature slice), a 3D volume (a CT scan, a density), or a vector field (a flow). This module
implements the chapter's algorithms that turn such samples into pictures, on arrays small enough
to inspect and draw step by step.

**Scalar fields: contours and isosurfaces**

* :func:`marching_squares`: the **isolines** :math:`f(x, y) = c` of a 2D field. Each grid cell
  (the square between four neighbouring samples) is handled on its own: mark each corner as
  *above* (:math:`f \ge c`) or *below*; the four marks form a 4-bit **case index** (0-15,
  :func:`marching_squares_cases`); a 16-entry table (:data:`SQUARE_TABLE`) lists which cell
  edges the isoline crosses and how to join them; the crossing point on an edge from
  :math:`p_0` to :math:`p_1` is found by **linear interpolation**,
  :math:`p = p_0 + t (p_1 - p_0)` with :math:`t = (c - f_0) / (f_1 - f_0)`. Cases 5 and 10
  (diagonal corners above, the other two below) are **ambiguous saddles**: two pairs of
  segments are possible. We decide with the **midpoint decider**: the average of the four
  corners stands for the centre value; if it is above, the two above corners are joined
  through the centre. :func:`join_segments` and :func:`isolines` chain the segments into
  polylines.
* :func:`marching_cubes`: the **isosurface** :math:`f(x, y, z) = c` of a volume, the same idea
  one dimension up: 8 corners, an 8-bit case index (0-255), 12 edges, and a table of up to a
  few triangles per case (:func:`cube_triangles`). Vertices on an edge shared by up to four
  cells are computed once and shared (identified by a global edge number), so the mesh is
  connected, and closed where the surface does not leave the volume.

  *The ambiguity of the classic table.* Lorensen and Cline's original table (1987) and the
  widely copied 256-entry table of Paul Bourke decide each case without looking at the
  neighbours. A cube face with two diagonal above corners is an ambiguous face, like a
  marching-squares saddle, and two cubes sharing such a face may join its corners
  differently: the surface then has a **hole**. It is rare in smooth data but real (a
  known flaw; Dürst 1988, Nielson and Hamann 1991). Our table is therefore *built* rather
  than copied: for each case, and for each way of resolving its ambiguous faces, the isoline
  segments of the six faces are chained into closed loops around the cube (marching squares
  on each face), and each loop is cut into triangles. Ambiguous faces are resolved
  by the **asymptotic decider** (the value at the saddle point of the bilinear interpolant on
  the face, :math:`(f_0 f_2 - f_1 f_3) / (f_0 + f_2 - f_1 - f_3)`). Both cubes sharing a
  face see the same four values and decide the same way, so the surface is **watertight**:
  every edge of the mesh inside the volume is shared by exactly two triangles, once in each
  direction. A loop is cut into triangles only by diagonals through the cube's interior (a
  diagonal along a face could be drawn by the neighbour too, and its edge would then belong
  to four triangles); long loops of 8 to 12 vertices (only with ambiguous faces; some of them
  cannot be cut that way) are fanned around an extra vertex at their centroid. (Inside a cube
  there remain rarer ambiguities, tunnels through the cube, that Chernyaev's Marching Cubes 33
  resolves; our choice there is one consistent option among the possible ones, and never
  opens a hole.) ``marching_cubes(..., table="classic")`` uses the original table of Lorensen
  and Cline instead, where each cube decides its ambiguous faces alone and holes can appear.

**Volume rendering**

* :func:`volume_render`: **direct volume rendering by ray casting**. One ray per pixel goes
  through the volume; at regular steps the volume is sampled by **trilinear interpolation**
  (:func:`multilinear_interpolate`), the sample is mapped to a colour :math:`c_i` and an opacity
  :math:`\alpha_i` by a transfer function (:mod:`course_lib.colormaps`), and the samples are
  accumulated **front to back**:

  .. math:: C \leftarrow C + (1 - A)\,\alpha_i c_i, \qquad A \leftarrow A + (1 - A)\,\alpha_i .

  Opacities are given per unit length; a sample standing for a ray segment of length
  :math:`\Delta` gets the **opacity correction** :math:`\alpha_i = 1 - (1 - \alpha)^{\Delta}`,
  which makes the picture independent of the step size (the Beer-Lambert law: light through a
  uniform medium decays exponentially with distance). **Early ray termination** stops a ray
  once :math:`A` reaches a threshold: what lies behind can change the pixel by less than
  :math:`1 - A`. :func:`composite` does the compositing of given samples by hand, in either
  order; back to front, :math:`C \leftarrow \alpha_i c_i + (1 - \alpha_i) C`, gives the same
  result but cannot stop early. :class:`RaySamples` samples the rays of one view once, so
  that editing the transfer function only re-classifies and re-composites them.
* :func:`mip`: **maximum intensity projection**, the largest sample along each ray (angiography
  uses it to show vessels).

**Vector fields**

* :func:`streamline`: a **streamline** is tangent to the velocity everywhere:
  :math:`\mathrm{d}x / \mathrm{d}t = v(x)`. It is traced from a seed point by numerical
  integration with step :math:`h`: **Euler** :math:`x_{n+1} = x_n + h v(x_n)` (first order:
  on a circular flow it spirals outwards, the radius growing by :math:`\sqrt{1 + h^2}` per
  step), the midpoint method **RK2** (second order) and the classic **RK4** (fourth order).
* :func:`hedgehog` (a line segment per sample, along the vector) and :func:`arrows` (arrow
  shapes) are **glyphs**: small icons whose direction and size show the vector.
* :func:`gradient`: central differences, the gradient that shades isosurfaces and points
  along the steepest ascent.

Example data: :func:`example_field_2d`, :func:`example_volume` (a sphere, two blobs, a torus,
a CT-like head phantom, smooth noise) and :func:`example_vector_field` (a vortex, a saddle, a
source, ...).

Conventions
-----------
**Array axes are reversed with respect to coordinates**, as in images: a 2D field
``field[i, j]`` is the sample at :math:`x = x_0 + j\,\Delta x`, :math:`y = y_0 + i\,\Delta y`
(row i is y, column j is x), and a volume ``volume[k, j, i]`` is the sample at
:math:`(x_0 + i \Delta x, y_0 + j \Delta y, z_0 + k \Delta z)`: the **last axis is x**. This is
the layout of ``np.meshgrid(x, y)``, of ``plt.imshow(field, origin="lower")`` and
``plt.contour(x, y, field)``, and VTK's memory order, so a volume goes to pyvista as
``pv.ImageData(dimensions=volume.shape[::-1], spacing=spacing, origin=origin)`` with
``grid.point_data["f"] = volume.ravel()``. ``spacing`` and ``origin`` are given in coordinate
order (x, y[, z]), and every returned point is (x, y[, z]). (scikit-image works in
(row, col[, plane]) order: reverse its points' columns to compare.)

**Inside and orientation.** The region where the field is at least the level is "inside".
Isoline segments run with the higher values on their **left** (closed isolines around a
maximum run counter-clockwise); isosurface triangles are wound counter-clockwise seen from
outside, so their normals (right-hand rule) point **towards lower values**, out of the
inside region, and the signed volume of a closed surface is positive. (scikit-image's
``marching_cubes`` with its default ``gradient_direction="descent"`` uses the same
orientation.) For a signed distance function, which is negative inside, pass ``-sdf``.

**Images** from :func:`volume_render` and :func:`mip` follow the 2D field convention:
``image[i, j]`` is the pixel at view coordinates :math:`(u_j, v_i)`, **row 0 at the bottom**;
show them with ``plt.imshow(image, origin="lower")``. The eye looks down :math:`-z` of the
view frame; "front" is the side of large view z.

**Bad input.** NaN in a field or volume, a non-2D field or non-3D volume, a non-positive
spacing, a zero step, an opacity outside [0, 1] raise ``ValueError`` naming the argument.
A level outside the data range is not an error: the isoline or isosurface of a value the data
never takes is empty, and an empty result (no segments, no triangles) is returned without a
warning, so that a slider may sweep past the data range.

Efficiency
----------
For a grid of :math:`N` samples (:math:`N = n^2` or :math:`n^3`):

* Marching squares and cubes visit every cell once: :math:`O(N)` to compute the case indices,
  here a handful of whole-array numpy operations. Only the cells the surface crosses (about
  :math:`O(n)` in 2D, :math:`O(n^2)` in 3D) produce output; their table look-ups,
  interpolations and the vertex sharing (one sort of the crossed edges' numbers) are
  vectorized over all of them at once. No Python loop runs per cell.
* Ray casting costs :math:`O(p \cdot s)` samples for :math:`p` pixels and :math:`s` steps per
  ray, each a trilinear interpolation (8 reads) and a transfer-function look-up. All rays march
  together, one step at a time, and rays that leave the volume or terminate early are dropped
  from the arrays, so early termination saves real work on opaque data.
* Streamlines cost :math:`O(k)` velocity evaluations per step for :math:`k` seeds (1, 2 or 4
  per step for Euler, RK2, RK4); all seeds advance together.

Files
-----

``data.py``
    Chapter 18 (lesson section 1): example scalar fields, volumes and vector fields, generated.
``contour_lines.py``
    Chapter 18 (lesson section 2): isolines by marching squares, with the midpoint or the
    asymptotic decider for saddle cells.
``isosurfaces.py``
    Chapter 18 (lesson section 3): isosurfaces by marching cubes.
``grids.py``
    Chapter 18 (lesson section 1): bilinear and trilinear interpolation on regular grids.
    ``interpolate`` is :func:`multilinear_interpolate` under its old name (the same function).
``volume_rendering.py``
    Chapter 18 (lesson section 4): direct volume rendering: ray casting, compositing, MIP.
``flow.py``
    Chapter 18 (lesson section 5.1): streamlines of a vector field, integrated step by step.
``glyphs.py``
    Chapter 18 (lesson section 5): glyphs (arrows) for vector fields.
``volume_methods.py``
    Chapter 18 (lesson sections 3 and 4): normals and shading from the gradient; splatting,
    texture-based slicing and shear-warp beside ray casting; pre- and post-classification.
``topology.py``
    Chapter 18 (lesson section 6): gridded fields and their integration, critical points
    classified by the Jacobian's eigenvalues, separatrices.
``unsteady.py``
    Chapter 18 (lesson section 7): streamlines, pathlines, streaklines and timelines of
    time-dependent fields; line integral convolution.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from .data import (Field, example_field_2d, example_vector_field, example_volume,
    sample_vector_field)
from .contour_lines import (SQUARE_SADDLES_CENTRE_ABOVE, SQUARE_TABLE, asymptotic_decider,
    isolines, join_segments, marching_squares, marching_squares_cases, saddle_centre_above)
from .isosurfaces import (CENTRE, CUBE_CORNERS, CUBE_EDGES, cube_triangles, enclosed_volume,
    gradient, marching_cubes, marching_cubes_cases, surface_area, _ambiguous_faces)
from .grids import (interpolate, multilinear_interpolate)
from .volume_rendering import (RaySamples, VolumeImage, composite, mip, view_rotation,
    volume_render)
from .flow import (streamline)
from .glyphs import (arrows, hedgehog)

__all__ = [
    "CENTRE",
    "CUBE_CORNERS",
    "CUBE_EDGES",
    "Field",
    "RaySamples",
    "SQUARE_SADDLES_CENTRE_ABOVE",
    "SQUARE_TABLE",
    "VolumeImage",
    "arrows",
    "asymptotic_decider",
    "composite",
    "cube_triangles",
    "enclosed_volume",
    "example_field_2d",
    "example_vector_field",
    "example_volume",
    "gradient",
    "hedgehog",
    "isolines",
    "join_segments",
    "marching_cubes",
    "marching_cubes_cases",
    "marching_squares",
    "marching_squares_cases",
    "mip",
    "multilinear_interpolate",
    "sample_vector_field",
    "saddle_centre_above",
    "streamline",
    "surface_area",
    "view_rotation",
    "volume_render",
]

# Issue 22: splatting, slicing and classification order; flow topology and gridded integration;
# unsteady flow lines and line integral convolution (each module declares its __all__)
from . import topology, unsteady, volume_methods  # noqa: E402
from .volume_methods import *  # noqa: E402,F401,F403
from .topology import *  # noqa: E402,F401,F403
from .unsteady import *  # noqa: E402,F401,F403

__all__ = sorted(__all__ + volume_methods.__all__ + topology.__all__ + unsteady.__all__)
