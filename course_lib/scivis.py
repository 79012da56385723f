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
  opens a hole.)

**Volume rendering**

* :func:`volume_render`: **direct volume rendering by ray casting**. One ray per pixel goes
  through the volume; at regular steps the volume is sampled by **trilinear interpolation**
  (:func:`interpolate`), the sample is mapped to a colour :math:`c_i` and an opacity
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
  result but cannot stop early.
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
a CT-like head phantom) and :func:`example_vector_field` (a vortex, a saddle, a source, ...).

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
"""
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from ._validate import as_array, as_points, as_rotation_matrix, as_scalar, as_vector
from .colormaps import TransferFunction, rgba_transfer, transfer_preset

__all__ = [
    "CENTRE",
    "CUBE_CORNERS",
    "CUBE_EDGES",
    "Field",
    "SQUARE_SADDLES_CENTRE_ABOVE",
    "SQUARE_TABLE",
    "VolumeImage",
    "arrows",
    "composite",
    "cube_triangles",
    "enclosed_volume",
    "example_field_2d",
    "example_vector_field",
    "example_volume",
    "gradient",
    "hedgehog",
    "interpolate",
    "isolines",
    "join_segments",
    "marching_cubes",
    "marching_cubes_cases",
    "marching_squares",
    "marching_squares_cases",
    "mip",
    "sample_vector_field",
    "saddle_centre_above",
    "streamline",
    "surface_area",
    "view_rotation",
    "volume_render",
]


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _grid(value, name, ndim):
    """A finite float array with `ndim` axes of at least 2 samples each (NaN rejected)."""
    what = {2: "a 2D field, shape (ny, nx)", 3: "a 3D volume, shape (nz, ny, nx)"}[ndim]
    arr = np.asarray(value) if isinstance(value, np.ndarray) else None
    if arr is not None and arr.dtype.kind == "f" and np.isnan(arr).any():
        raise ValueError(f"{name} contains NaN (missing data): fill or mask it first, e.g. "
                         f"np.nan_to_num({name}, nan=value)")
    arr = as_array(value, name)
    if arr.ndim != ndim:
        raise ValueError(f"{name} must be {what}, got {arr.ndim} axes (shape {arr.shape})")
    if min(arr.shape) < 2:
        raise ValueError(f"{name} must have at least 2 samples along every axis, got shape "
                         f"{arr.shape}")
    return arr


def _spacing(value, dim, name="spacing"):
    s = as_vector(value, name, dim)
    if (s <= 0).any():
        raise ValueError(f"{name} must be positive along every axis (the distance between "
                         f"neighbouring samples), got {tuple(float(v) for v in s)}")
    return s


def _positive(value, name):
    v = as_scalar(value, name)
    if v <= 0:
        raise ValueError(f"{name} must be positive, got {v:g}")
    return v


def _whole(value, name, minimum):
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    v = as_scalar(value, name)
    if v != int(v) or v < minimum:
        raise ValueError(f"{name} must be a whole number >= {minimum}, got {value!r}")
    return int(v)


def _choice(value, name, options):
    if value not in options:
        raise ValueError(f"{name} must be one of {', '.join(map(repr, options))}, got {value!r}")
    return value


# ---------------------------------------------------------------------------------------------
# Example data
# ---------------------------------------------------------------------------------------------

class Field(NamedTuple):
    """Samples on a regular grid with its geometry: what the algorithms of this module take.

    Attributes
    ----------
    values : ndarray
        Shape (ny, nx) or (nz, ny, nx) for a scalar field, with a trailing axis of 2 or 3
        components for a vector field (last array axis = x, see the module's conventions).
    spacing : tuple of float
        Distance between neighbouring samples along x, y (, z).
    origin : tuple of float
        Coordinates (x, y(, z)) of ``values[0, 0(, 0)]``.
    level : float or None
        A level at which the field has an interesting isoline / isosurface.

    Examples
    --------
    >>> f = example_field_2d("circle", size=5)
    >>> f.spacing, f.origin, f.axes[0]
    ((0.5, 0.5), (-1.0, -1.0), array([-1. , -0.5,  0. ,  0.5,  1. ]))
    """
    values: np.ndarray
    spacing: tuple
    origin: tuple
    level: object = None

    @property
    def axes(self):
        """The sample coordinates along x, y (, z): 1-D arrays."""
        dim = len(self.spacing)
        shape = self.values.shape[:dim][::-1]
        return tuple(o + s * np.arange(n) for o, s, n in zip(self.origin, self.spacing, shape))


def _cube_grid(size, dim):
    n = _whole(size, "size", 2)
    h = 2.0 / (n - 1)
    axis = np.linspace(-1.0, 1.0, n)
    coords = np.meshgrid(*([axis] * dim), indexing="ij")[::-1]     # x varies along the last axis
    return coords, (h,) * dim, (-1.0,) * dim


_FIELDS_2D = ("hills", "saddle", "circle", "ripple")


def example_field_2d(kind="hills", size=64):
    r"""A 2D scalar field sampled on [-1, 1]^2 with `size` x `size` samples.

    * ``"hills"``: two Gaussian hills of different heights with a saddle between them (level
      0.5 gives two closed isolines, a lower level one around both);
    * ``"saddle"``: :math:`f = x^2 - y^2`, whose zero isoline is the two diagonals (ambiguous
      cells at the centre when `size` is even);
    * ``"circle"``: the distance to the origin :math:`\sqrt{x^2 + y^2}`; level 0.6 is a circle
      of radius 0.6 (circumference :math:`1.2 \pi`);
    * ``"ripple"``: :math:`\cos(8 r) e^{-r^2}`, rings around the centre.

    Returns
    -------
    Field
        ``values`` of shape (size, size), and a suggested ``level``.

    Examples
    --------
    >>> f = example_field_2d("saddle", size=3)
    >>> f.values
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  1.],
           [ 0., -1.,  0.]])
    """
    _choice(kind, "kind", _FIELDS_2D)
    (x, y), spacing, origin = _cube_grid(size, 2)
    if kind == "hills":
        values = (np.exp(-((x - 0.4) ** 2 + (y + 0.1) ** 2) / 0.12)
                  + 0.8 * np.exp(-((x + 0.45) ** 2 + (y - 0.15) ** 2) / 0.08))
        level = 0.5
    elif kind == "saddle":
        values, level = x ** 2 - y ** 2, 0.0
    elif kind == "circle":
        values, level = np.hypot(x, y), 0.6
    else:
        r = np.hypot(x, y)
        values, level = np.cos(8 * r) * np.exp(-r ** 2), 0.0
    return Field(values, spacing, origin, level)


_VOLUMES = ("sphere", "blobs", "torus", "ct")


def _smooth_inside(rho, eps):
    """About 1 where rho < 1, 0 where rho > 1, with a tanh ramp of half-width ~eps."""
    return 0.5 * (1.0 + np.tanh((1.0 - rho) / eps))


def example_volume(kind="sphere", size=64):
    r"""A 3D scalar volume sampled on [-1, 1]^3 with `size`^3 samples, higher values inside.

    * ``"sphere"``: :math:`f = 0.6 - |p|`; the level-0 isosurface is a sphere of radius 0.6
      (area :math:`4 \pi\, 0.6^2`, volume :math:`\frac43 \pi\, 0.6^3`);
    * ``"blobs"``: the sum of two Gaussian blobs ("metaballs"); at level 0.5 two separate
      surfaces, at a lower level one merged surface;
    * ``"torus"``: :math:`f = 0.2 - \sqrt{(\sqrt{x^2 + y^2} - 0.55)^2 + z^2}`, a ring around the
      z axis of radii R = 0.55, r = 0.2 at level 0 (area :math:`4 \pi^2 R r`, volume
      :math:`2 \pi^2 R r^2`, Euler characteristic 0);
    * ``"ct"``: a CT-like head phantom with values in [0, 1], facing +z (the default view of
      :func:`volume_render`): air 0, soft tissue 0.25, a bone shell (the skull, with two eye
      sockets) 0.8, brain 0.4, two fluid-filled ventricles 0.15 and a contrast-enhanced lesion
      1.0, with edges smoothed over about one voxel. Level 0.6 shows the skull and the lesion;
      see :func:`course_lib.colormaps.transfer_preset` for transfer functions made for it.

    Returns
    -------
    Field
        ``values`` of shape (size, size, size) (last axis x), spacing and origin, and a
        suggested ``level``.

    Examples
    --------
    >>> v = example_volume("sphere", size=5)
    >>> v.values.shape, v.spacing, v.level
    ((5, 5, 5), (0.5, 0.5, 0.5), 0.0)
    >>> float(v.values[2, 2, 2]), float(v.values[2, 2, 4])
    (0.6, -0.4)
    """
    _choice(kind, "kind", _VOLUMES)
    (x, y, z), spacing, origin = _cube_grid(size, 3)
    if kind == "sphere":
        values, level = 0.6 - np.sqrt(x ** 2 + y ** 2 + z ** 2), 0.0
    elif kind == "blobs":
        values = (np.exp(-((x - 0.35) ** 2 + y ** 2 + z ** 2) / (2 * 0.22 ** 2))
                  + np.exp(-((x + 0.4) ** 2 + (y - 0.1) ** 2 + (z + 0.05) ** 2)
                           / (2 * 0.18 ** 2)))
        level = 0.5
    elif kind == "torus":
        values, level = 0.2 - np.sqrt((np.hypot(x, y) - 0.55) ** 2 + z ** 2), 0.0
    else:
        eps = spacing[0]

        def inside(centre, radii):
            rho = np.sqrt(((x - centre[0]) / radii[0]) ** 2 + ((y - centre[1]) / radii[1]) ** 2
                          + ((z - centre[2]) / radii[2]) ** 2)
            return _smooth_inside(rho, eps / min(radii))

        head = inside((0, 0, 0), (0.75, 0.9, 0.8))
        skull_out = inside((0, 0, -0.02), (0.69, 0.84, 0.74))
        brain = inside((0, 0.02, -0.04), (0.57, 0.72, 0.61))
        sockets = (1 - inside((-0.25, 0.15, 0.62), (0.14, 0.14, 0.2))) \
            * (1 - inside((0.25, 0.15, 0.62), (0.14, 0.14, 0.2)))
        skull = np.clip(skull_out - brain, 0.0, 1.0) * sockets
        ventricles = (inside((-0.12, 0.1, -0.05), (0.07, 0.12, 0.25))
                      + inside((0.12, 0.1, -0.05), (0.07, 0.12, 0.25)))
        lesion = inside((0.25, -0.15, 0.1), (0.1, 0.1, 0.1))
        values = (0.25 * head + 0.55 * skull + 0.15 * brain - 0.25 * ventricles
                  + 0.6 * lesion)
        values = np.clip(values, 0.0, 1.0)
        level = 0.6
    return Field(values, spacing, origin, level)


_VECTOR_FIELDS = {
    2: {"vortex": lambda x, y: (-y, x), "saddle": lambda x, y: (x, -y),
        "source": lambda x, y: (x, y), "sink": lambda x, y: (-x, -y),
        "spiral": lambda x, y: (-y - 0.2 * x, x - 0.2 * y)},
    3: {"vortex": lambda x, y, z: (-y, x, 0 * z), "helix": lambda x, y, z: (-y, x, 0.2 + 0 * z),
        "source": lambda x, y, z: (x, y, z), "saddle": lambda x, y, z: (x, y, -2 * z)},
}


def example_vector_field(kind="vortex", dim=2):
    r"""An analytic velocity field: a function from points (..., dim) to vectors (..., dim).

    2D kinds: ``"vortex"`` :math:`(-y, x)` (circles around the origin, period :math:`2\pi`),
    ``"saddle"`` :math:`(x, -y)`, ``"source"`` :math:`(x, y)`, ``"sink"`` :math:`(-x, -y)`,
    ``"spiral"`` :math:`(-y - 0.2x, x - 0.2y)` (a vortex that also sinks).
    3D kinds: ``"vortex"`` :math:`(-y, x, 0)`, ``"helix"`` :math:`(-y, x, 0.2)` (helices of pitch
    :math:`0.4 \pi` around the z axis), ``"source"`` :math:`(x, y, z)`, ``"saddle"``
    :math:`(x, y, -2z)` (divergence-free).

    Examples
    --------
    >>> v = example_vector_field("vortex")
    >>> v([[1.0, 0.0], [0.0, 2.0]])
    array([[ 0.,  1.],
           [-2.,  0.]])
    """
    if dim not in (2, 3):
        raise ValueError(f"dim must be 2 or 3, got {dim!r}")
    formula = _VECTOR_FIELDS[dim].get(kind)
    if formula is None:
        raise ValueError(f"kind must be one of {', '.join(map(repr, _VECTOR_FIELDS[dim]))} for "
                         f"dim={dim}, got {kind!r}")

    def velocity(points):
        p = as_points(points, "points", dims=dim)
        v = np.stack(np.broadcast_arrays(*formula(*np.moveaxis(p, -1, 0))), axis=-1)
        return v + 0.0                               # no negative zeros

    velocity.__name__ = f"{kind}_{dim}d"
    return velocity


def sample_vector_field(velocity, size=16, dim=2):
    """Sample a velocity function on the grid [-1, 1]^dim with `size` samples per axis.

    Returns
    -------
    Field
        ``values`` of shape (size, size, 2) or (size, size, size, 3): the vector components
        (vx, vy(, vz)) in the last axis, the grid axes reversed (last grid axis = x).

    Examples
    --------
    >>> f = sample_vector_field(example_vector_field("source"), size=3)
    >>> f.values.shape, f.values[0, 2]
    ((3, 3, 2), array([ 1., -1.]))
    """
    if dim not in (2, 3):
        raise ValueError(f"dim must be 2 or 3, got {dim!r}")
    coords, spacing, origin = _cube_grid(size, dim)
    points = np.stack(coords, axis=-1)
    values = as_array(velocity(points), "velocity(points)")
    if values.shape != points.shape:
        raise ValueError(f"velocity must return one {dim}-vector per point, shape "
                         f"{points.shape}, got shape {values.shape}")
    return Field(values, spacing, origin, None)


# ---------------------------------------------------------------------------------------------
# Marching squares
# ---------------------------------------------------------------------------------------------
# A cell's corners and edges, counter-clockwise (x right, y up):
#
#     3 ---- e2 ---- 2        corner 0: field[i, j]       edge 0: corner 0 - corner 1
#     |              |        corner 1: field[i, j+1]     edge 1: corner 1 - corner 2
#    e3              e1       corner 2: field[i+1, j+1]   edge 2: corner 2 - corner 3
#     |              |        corner 3: field[i+1, j]     edge 3: corner 3 - corner 0
#     0 ---- e0 ---- 1
#
# case index = sum of 2^k over the corners k that are above the level (f >= level).

#: Marching squares: for each case 0-15, the isoline segments as (from edge, to edge), each
#: oriented with the above corners on its left. Saddles 5 and 10 as when the centre is below.
SQUARE_TABLE = (
    (),                    # 0  all below: no isoline
    ((0, 3),),             # 1  corner 0 above: cut it off
    ((1, 0),),             # 2  corner 1 above
    ((1, 3),),             # 3  bottom row above: a horizontal line
    ((2, 1),),             # 4  corner 2 above
    ((0, 3), (2, 1)),      # 5  saddle (0 and 2 above), centre below: two corners cut off
    ((2, 0),),             # 6  right column above: a vertical line
    ((2, 3),),             # 7  only corner 3 below
    ((3, 2),),             # 8  corner 3 above
    ((0, 2),),             # 9  left column above
    ((1, 0), (3, 2)),      # 10 saddle (1 and 3 above), centre below
    ((1, 2),),             # 11 only corner 2 below
    ((3, 1),),             # 12 top row above
    ((0, 1),),             # 13 only corner 1 below
    ((3, 0),),             # 14 only corner 0 below
    (),                    # 15 all above: no isoline
)

#: The saddle cases when the centre (the mean of the four corners) is above the level: the two
#: above corners are joined through the centre and the two below corners are cut off.
SQUARE_SADDLES_CENTRE_ABOVE = {5: ((0, 1), (2, 3)), 10: ((3, 0), (1, 2))}


def _square_lookup():
    """(32, 2, 2) array: [case + 16 * centre_above] -> two (from, to) edge pairs, -1 = none."""
    table = np.full((32, 2, 2), -1, dtype=np.intp)
    for case, segments in enumerate(SQUARE_TABLE):
        for above in (0, 1):
            segs = SQUARE_SADDLES_CENTRE_ABOVE.get(case, segments) if above else segments
            for k, seg in enumerate(segs):
                table[case + 16 * above, k] = seg
    return table


_SQUARE_LOOKUP = _square_lookup()


def _square_cases(f, level):
    above = (f >= level).astype(np.uint8)
    return (above[:-1, :-1] | (above[:-1, 1:] << 1) | (above[1:, 1:] << 2)
            | (above[1:, :-1] << 3))


def marching_squares_cases(field, level):
    """The case index 0-15 of every cell: bit k is set when corner k is above the level.

    Corner 0 is ``field[i, j]`` (bottom left), 1 is ``field[i, j+1]``, 2 ``field[i+1, j+1]``,
    3 ``field[i+1, j]``, counter-clockwise; "above" means ``value >= level``.

    Parameters
    ----------
    field : array_like, shape (ny, nx)
    level : float

    Returns
    -------
    ndarray of int, shape (ny - 1, nx - 1)
        ``cases[i, j]`` for the cell between rows i, i+1 and columns j, j+1.

    Examples
    --------
    >>> marching_squares_cases([[0, 2, 0], [2, 0, 2]], 1)
    array([[10,  5]])
    """
    f = _grid(field, "field", 2)
    return _square_cases(f, as_scalar(level, "level")).astype(np.intp)


def saddle_centre_above(field, level):
    """The midpoint decider: is the mean of each cell's four corners above the level?

    Only the saddle cells (cases 5 and 10) use it: True joins their above corners through the
    centre (:data:`SQUARE_SADDLES_CENTRE_ABOVE`), False their below corners.

    Returns
    -------
    ndarray of bool, shape (ny - 1, nx - 1)

    Examples
    --------
    >>> saddle_centre_above([[0, 2], [3, 0]], 1), saddle_centre_above([[0, 2], [3, 0]], 1.5)
    (array([[ True]]), array([[False]]))
    """
    f = _grid(field, "field", 2)
    return _centres(f) >= as_scalar(level, "level")


def _centres(f):
    return 0.25 * (f[:-1, :-1] + f[:-1, 1:] + f[1:, 1:] + f[1:, :-1])


# edge -> (row offset, column offset) of its canonical start corner, and its direction
# (0: along x (columns), 1: along y (rows))
_SQ_EDGE_START = np.array([[0, 0], [0, 1], [1, 0], [0, 0]])
_SQ_EDGE_AXIS = np.array([0, 1, 0, 1])


def _square_points(f, level, rows, cols, edges):
    """Crossing points (row, col index coordinates) on cell edges, computed per *grid* edge.

    The grid edge is always interpolated from its lower-index end, so two cells sharing an edge
    get bit-identical points (which lets :func:`join_segments` chain them exactly).
    """
    r0 = rows + _SQ_EDGE_START[edges, 0]
    c0 = cols + _SQ_EDGE_START[edges, 1]
    along_y = _SQ_EDGE_AXIS[edges] == 1
    r1, c1 = r0 + along_y, c0 + ~along_y
    f0, f1 = f[r0, c0], f[r1, c1]
    t = (level - f0) / (f1 - f0)
    return np.stack([r0 + t * along_y, c0 + t * ~along_y], axis=-1)


def marching_squares(field, level, spacing=(1.0, 1.0), origin=(0.0, 0.0)):
    r"""Isoline segments of a 2D field by marching squares.

    For each cell: the case index (:func:`marching_squares_cases`), the table
    :data:`SQUARE_TABLE` (saddles 5 and 10 resolved by the midpoint decider,
    :func:`saddle_centre_above`), and on each crossed edge the point of linear interpolation
    :math:`p = p_0 + t (p_1 - p_0)`, :math:`t = (c - f_0) / (f_1 - f_0)`.

    Parameters
    ----------
    field : array_like, shape (ny, nx)
        ``field[i, j]`` is the sample at :math:`x = x_0 + j \Delta x`, :math:`y = y_0 + i \Delta y`.
    level : float
        The isovalue c. A level outside the data range gives no segments (not an error).
    spacing : (float, float)
        :math:`(\Delta x, \Delta y)`, positive.
    origin : (float, float)
        :math:`(x_0, y_0)`, the position of ``field[0, 0]``.

    Returns
    -------
    ndarray, shape (m, 2, 2)
        m segments, each (start, end) as (x, y) points, oriented with higher values on the left.
        Cells are visited row by row; a segment ends where the next one of its isoline may
        start, with bit-identical coordinates (see :func:`join_segments`). A sample exactly at
        the level counts as above; where the isoline passes exactly through a sample, the
        zero-length pieces this makes are left out.

    Raises
    ------
    ValueError
        For a field that is not 2D with at least 2 x 2 samples, NaN in the field, or a
        non-positive spacing.

    Examples
    --------
    One cell with only its bottom-left corner above 1: the isoline cuts that corner off, from
    the bottom edge to the left edge (the corner on the left of the direction of travel):

    >>> marching_squares([[2, 0], [0, 0]], 1)
    array([[[0.5, 0. ],
            [0. , 0.5]]])
    """
    f = _grid(field, "field", 2)
    c = as_scalar(level, "level")
    dx, dy = _spacing(spacing, 2)
    x0, y0 = as_vector(origin, "origin", 2)
    cases = _square_cases(f, c).astype(np.intp)
    saddle = (cases == 5) | (cases == 10)
    ext = cases.copy()
    if saddle.any():
        ext[saddle] += 16 * (_centres(f)[saddle] >= c)
    segs = _SQUARE_LOOKUP[ext]                            # (ny-1, nx-1, 2, 2)
    rows, cols, slot = np.nonzero(segs[..., 0] >= 0)
    edges = segs[rows, cols, slot]                        # (m, 2): from edge, to edge
    start = _square_points(f, c, rows, cols, edges[:, 0])
    end = _square_points(f, c, rows, cols, edges[:, 1])
    # an isoline through a sample itself gives zero-length pieces next to it: drop them
    keep = (start != end).any(axis=1)
    ij = np.stack([start[keep], end[keep]], axis=1)       # (m, 2, (row, col))
    return np.stack([x0 + ij[..., 1] * dx, y0 + ij[..., 0] * dy], axis=-1)


def join_segments(segments):
    """Chain segments head to tail into polylines.

    A segment whose start point equals (exactly) the end point of another continues it. This
    is how :func:`marching_squares` output becomes whole isolines: its segments are oriented
    consistently and neighbouring cells compute shared points identically.

    Parameters
    ----------
    segments : array_like, shape (m, 2, d)

    Returns
    -------
    list of ndarray, each shape (k, d)
        The polylines, longest first; a closed one repeats its first point at the end.

    Examples
    --------
    >>> lines = join_segments([[[1, 0], [1, 1]], [[0, 0], [1, 0]], [[1, 1], [0, 0]]])
    >>> lines[0]
    array([[1., 0.],
           [1., 1.],
           [0., 0.],
           [1., 0.]])
    """
    segs = as_array(segments, "segments")
    if segs.size == 0:
        return []
    if segs.ndim != 3 or segs.shape[1] != 2 or segs.shape[2] not in (2, 3):
        raise ValueError(f"segments must have shape (m, 2, 2) or (m, 2, 3), got shape "
                         f"{segs.shape}")
    segs = segs + 0.0                                     # -0.0 and 0.0 are the same point
    starts = {p.tobytes(): k for k, p in enumerate(segs[:, 0])}
    nxt = np.array([starts.get(p.tobytes(), -1) for p in segs[:, 1]])
    has_prev = np.zeros(len(segs), bool)
    has_prev[nxt[nxt >= 0]] = True
    used = np.zeros(len(segs), bool)
    lines = []
    # open chains first (they start at a segment nothing leads into), then the closed loops
    for first in list(np.flatnonzero(~has_prev)) + list(range(len(segs))):
        if used[first]:
            continue
        chain, k = [first], nxt[first]
        used[first] = True
        while k >= 0 and not used[k]:
            chain.append(k)
            used[k] = True
            k = nxt[k]
        lines.append(np.concatenate([segs[chain, 0], segs[chain[-1:], 1]]))
    lines.sort(key=len, reverse=True)
    return lines


def isolines(field, level, spacing=(1.0, 1.0), origin=(0.0, 0.0)):
    """The isolines of a 2D field as polylines: :func:`marching_squares` + :func:`join_segments`.

    Returns
    -------
    list of ndarray, each shape (k, 2)
        (x, y) polylines, higher values on the left; closed ones end with their first point.

    Examples
    --------
    >>> f = example_field_2d("circle", size=41)
    >>> lines = isolines(f.values, 0.6, f.spacing, f.origin)
    >>> len(lines), bool(np.allclose(lines[0][0], lines[0][-1]))
    (1, True)
    """
    return join_segments(marching_squares(field, level, spacing, origin))


# ---------------------------------------------------------------------------------------------
# Marching cubes
# ---------------------------------------------------------------------------------------------
# Corner and edge numbering of Lorensen and Cline (1987) as in Paul Bourke's "Polygonising a
# scalar field" (1994), which most implementations follow:
#
#          7 ------ e6 ------ 6          z
#         /|                 /|          |  y
#       e7 |               e5 |          | /
#       /  e11             /  e10        |/
#      4 ------ e4 ------ 5   |          +----- x
#      |   |              |   |
#      |   3 ------ e2 ---|-- 2
#      e8 /               e9 /
#      | e3               | e1
#      |/                 |/
#      0 ------ e0 ------ 1

#: Corner k of a cube -> its (x, y, z) offset from corner 0.
CUBE_CORNERS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                         [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])

#: Edge k of a cube -> its two corners, the one with smaller coordinates first.
CUBE_EDGES = np.array([[0, 1], [1, 2], [3, 2], [0, 3], [4, 5], [5, 6], [7, 6], [4, 7],
                       [0, 4], [1, 5], [2, 6], [3, 7]])

# The six faces (z = 0, z = 1, y = 0, y = 1, x = 0, x = 1), each as its corners in
# counter-clockwise order seen from outside the cube: marching squares runs on each of them.
_CUBE_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5))
_EDGE_OF = {frozenset(map(int, pair)): k for k, pair in enumerate(CUBE_EDGES)}
_FACE_EDGES = tuple(tuple(_EDGE_OF[frozenset((cyc[m], cyc[(m + 1) % 4]))] for m in range(4))
                    for cyc in _CUBE_FACES)


def _face_case(case, face):
    return sum(((case >> q) & 1) << m for m, q in enumerate(_CUBE_FACES[face]))


def _ambiguous_faces(case):
    """Bit mask of the faces on which `case` has a saddle (diagonal corners above)."""
    return sum(1 << f for f in range(6) if _face_case(case, f) in (5, 10))


_EDGE_FACES = tuple(frozenset(f for f in range(6) if e in _FACE_EDGES[f]) for e in range(12))

#: In a triangle of :func:`cube_triangles`, this number stands for the extra vertex at the
#: centroid of a long loop (8 or more vertices).
CENTRE = 12


def _triangulate_loop(loop):
    """Triangles (i, m, j) of loop positions, none of whose diagonals lies in a cube face.

    A diagonal between two vertices on the same face would run along that face, where the
    neighbouring cube may draw the same diagonal: the edge would then belong to four
    triangles. Diagonals through the cube's interior are never shared. Returns None if no
    such triangulation exists (it always exists for loops of up to 7 vertices).
    """
    n = len(loop)

    def allowed(i, k):
        return k - i == 1 or not (_EDGE_FACES[loop[i]] & _EDGE_FACES[loop[k]])

    @lru_cache(maxsize=None)
    def solve(i, j):                          # the sub-polygon i, i+1, ..., j (chord i-j given)
        if j - i < 2:
            return ()
        for m in range(i + 1, j):
            if allowed(i, m) and allowed(m, j):
                left, right = solve(i, m), solve(m, j)
                if left is not None and right is not None:
                    return left + right + ((i, m, j),)
        return None

    return solve(0, n - 1)


def _trace_cube(case, connected):
    """One cube's triangles (edge triples, CENTRE for a loop's centroid) and the centre loop.

    Chain the six faces' isoline segments into loops, then triangulate each loop.
    """
    nxt = {}
    for f in range(6):
        sq = _face_case(case, f)
        segments = SQUARE_TABLE[sq]
        if sq in SQUARE_SADDLES_CENTRE_ABOVE and (connected >> f) & 1:
            segments = SQUARE_SADDLES_CENTRE_ABOVE[sq]
        for a, b in segments:
            nxt[_FACE_EDGES[f][a]] = _FACE_EDGES[f][b]
    triangles, centre_loop = [], ()
    while nxt:
        start = min(nxt)
        loop, e = [start], nxt.pop(start)
        while e != start:
            loop.append(e)
            e = nxt.pop(e)
        # The loop runs clockwise seen from the lower values, so every triangle is wound the
        # other way round to put its normal towards lower values.
        fan = _triangulate_loop(loop) if len(loop) < 8 else None
        if fan is None:                       # long loops: a fan around an extra centre vertex
            centre_loop = tuple(loop)
            n = len(loop)
            triangles += [(CENTRE, loop[(m + 1) % n], loop[m]) for m in range(n)]
        else:
            triangles += [(loop[i], loop[j], loop[m]) for i, m, j in fan]
    return triangles, centre_loop


def cube_triangles(case, connected_faces=0):
    """The triangles of one marching-cubes case, as triples of cube edge numbers.

    The table entry is built, not copied (see the module docstring): the isoline segments of
    the six faces (marching squares on each, seen from outside) chain into closed loops around
    the cube, and each loop is cut into a fan of triangles.

    Parameters
    ----------
    case : int
        0-255; bit k set when corner k (:data:`CUBE_CORNERS`) is above the level.
    connected_faces : int
        A 6-bit mask for the ambiguous faces: bit f set means that on face f (order z = 0,
        z = 1, y = 0, y = 1, x = 0, x = 1) the two above corners are connected through the
        face (the asymptotic decider found its saddle above the level). Bits of faces that are
        not ambiguous in this case are ignored.

    Returns
    -------
    ndarray of int, shape (k, 3)
        Each row: the edges (:data:`CUBE_EDGES`) on which the triangle's vertices lie, wound
        counter-clockwise seen from the side of lower values. Loops of up to 7 vertices are
        cut by diagonals through the cube's interior (never along a face, where a neighbour
        could draw the same diagonal); the rare loops of 8 or more vertices (only with
        ambiguous faces) are fanned around an extra vertex at their centroid, written
        :data:`CENTRE` (12).

    Examples
    --------
    Corner 0 alone above the level: one triangle cutting it off, on edges 0 (x), 3 (y) and 8
    (z); corners 0 and 1 above: a quadrilateral, two triangles:

    >>> cube_triangles(1)
    array([[0, 3, 8]])
    >>> cube_triangles(0b11).shape
    (2, 3)
    """
    case = _whole(case, "case", 0)
    if case > 255:
        raise ValueError(f"case must be a whole number in 0-255 (8 corner bits), got {case}")
    connected = _whole(connected_faces, "connected_faces", 0)
    if connected > 63:
        raise ValueError(f"connected_faces must be a 6-bit mask (0-63), got {connected}")
    triangles, _ = _trace_cube(case, connected & _ambiguous_faces(case))
    return np.array(triangles, dtype=np.intp).reshape(-1, 3)


@lru_cache(maxsize=1)
def _cube_lookup():
    """The whole table, index case + 256 * connected (ambiguous faces only) -> triangles,
    their count, and a 12-bit mask of the edges of the loop that has a centre vertex."""
    entries = {}
    for case in range(256):
        amb = _ambiguous_faces(case)
        sub = amb
        while True:                              # every subset of the ambiguous faces
            entries[case | (sub << 8)] = _trace_cube(case, sub)
            if sub == 0:
                break
            sub = (sub - 1) & amb
    most = max(len(t) for t, _ in entries.values())
    table = np.full((256 * 64, most, 3), -1, dtype=np.intp)
    counts = np.zeros(256 * 64, dtype=np.intp)
    centre_mask = np.zeros(256 * 64, dtype=np.intp)
    for index, (triangles, centre_loop) in entries.items():
        if triangles:
            table[index, :len(triangles)] = triangles
        counts[index] = len(triangles)
        centre_mask[index] = sum(1 << e for e in centre_loop)
    return table, counts, centre_mask


def _cube_cases(v, level):
    above = (v >= level).astype(np.uint8)
    nz, ny, nx = v.shape
    cases = np.zeros((nz - 1, ny - 1, nx - 1), dtype=np.uint8)
    for k, (ox, oy, oz) in enumerate(CUBE_CORNERS):
        cases |= above[oz:oz + nz - 1, oy:oy + ny - 1, ox:ox + nx - 1] << k
    return cases


def marching_cubes_cases(volume, level):
    """The case index 0-255 of every cell of a volume (bit k: corner k above the level).

    ``cases[k, j, i]`` is the cell whose corner 0 is ``volume[k, j, i]``; corner offsets as in
    :data:`CUBE_CORNERS` (x along the last axis).

    Examples
    --------
    >>> vol = np.zeros((2, 2, 2)); vol[0, 0, 0] = 1; vol[1, 1, 1] = 1
    >>> marching_cubes_cases(vol, 0.5)                  # corners 0 and 6: 1 + 64
    array([[[65]]])
    """
    v = _grid(volume, "volume", 3)
    return _cube_cases(v, as_scalar(level, "level")).astype(np.intp)


_CORNER_AXIS_ORDER = CUBE_CORNERS[:, ::-1]               # (z, y, x) offsets
_EDGE_AXIS = np.argmax(CUBE_CORNERS[CUBE_EDGES[:, 1]] - CUBE_CORNERS[CUBE_EDGES[:, 0]], axis=1)


def marching_cubes(volume, level, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0)):
    r"""The isosurface f = level of a volume as a triangle mesh, by marching cubes.

    Every cell gets its case index (:func:`marching_cubes_cases`); ambiguous faces are resolved
    by the asymptotic decider; the table (:func:`cube_triangles`) gives the triangles as cell
    edges; each crossed grid edge gets one vertex, by linear interpolation
    :math:`p = p_0 + t (p_1 - p_0)`, :math:`t = (c - f_0) / (f_1 - f_0)`, shared by all cells
    around that edge. All of it is vectorized over the cells.

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
        ``volume[k, j, i]`` is the sample at
        :math:`(x_0 + i \Delta x, y_0 + j \Delta y, z_0 + k \Delta z)`.
    level : float
        The isovalue. Outside the data range the surface is empty (not an error).
    spacing : (float, float, float)
        :math:`(\Delta x, \Delta y, \Delta z)`, positive.
    origin : (float, float, float)
        :math:`(x_0, y_0, z_0)`.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
        (x, y, z) points, one per crossed grid edge, in the order of the edges' numbers
        (position in ``volume.ravel()`` of the edge's lower end, times 3, plus its axis x, y, z
        as 0, 1, 2); then, in rare cells with a long loop (see :func:`cube_triangles`), its
        centroid.
    triangles : ndarray of int, shape (m, 3)
        Vertex indices, counter-clockwise seen from the lower values: normals (right-hand rule)
        point from the region ``volume >= level`` towards lower values. Where the surface does
        not reach the border of the volume it is closed and watertight (each edge shared by
        exactly two triangles, once in each direction).

    Raises
    ------
    ValueError
        For a volume that is not 3D with at least 2 samples per axis, NaN in it, or a
        non-positive spacing.

    Examples
    --------
    A single voxel above the level in the middle of a 3 x 3 x 3 volume gives an octahedron
    (6 vertices on the 6 edges around it, 8 triangles), with the enclosed volume positive:

    >>> vol = np.zeros((3, 3, 3)); vol[1, 1, 1] = 1.0
    >>> verts, tris = marching_cubes(vol, 0.5)
    >>> verts.shape, tris.shape
    ((6, 3), (8, 3))
    >>> float(enclosed_volume(verts, tris))          # (4/3) * 0.5**3, a regular octahedron
    0.16666666666666666
    """
    v = _grid(volume, "volume", 3)
    c = as_scalar(level, "level")
    sp = _spacing(spacing, 3)
    org = as_vector(origin, "origin", 3)
    nz, ny, nx = v.shape
    cases = _cube_cases(v, c).ravel()
    active = np.flatnonzero((cases != 0) & (cases != 255))
    if active.size == 0:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.intp)
    case = cases[active].astype(np.intp)
    cz, rest = np.divmod(active, (ny - 1) * (nx - 1))
    cy, cx = np.divmod(rest, nx - 1)
    base = (cz * ny + cy) * nx + cx                       # flat index of each cell's corner 0
    corner_offset = (_CORNER_AXIS_ORDER[:, 0] * ny + _CORNER_AXIS_ORDER[:, 1]) * nx \
        + _CORNER_AXIS_ORDER[:, 2]
    flat = v.ravel()
    # the asymptotic decider on the ambiguous faces
    connected = np.zeros(len(case), dtype=np.intp)
    for f, cycle in enumerate(_CUBE_FACES):
        bits = [(case >> q) & 1 for q in cycle]
        ambiguous = (bits[0] == bits[2]) & (bits[1] == bits[3]) & (bits[0] != bits[1])
        if ambiguous.any():
            b = base[ambiguous]
            f0, f1, f2, f3 = (flat[b + corner_offset[q]] for q in cycle)
            saddle = (f0 * f2 - f1 * f3) / ((f0 + f2) - (f1 + f3))
            connected[ambiguous] |= (saddle >= c).astype(np.intp) << f
    table, counts, centre_mask = _cube_lookup()
    index = case | (connected << 8)
    cell, slot = np.nonzero(np.arange(table.shape[1]) < counts[index][:, None])
    edges = table[index[cell], slot]                      # (m, 3) cube edge numbers

    def edge_ids(cells, e):                               # a number for every grid edge
        return 3 * (base[cells] + corner_offset[CUBE_EDGES[e, 0]]) + _EDGE_AXIS[e]

    centre = edges == CENTRE
    ids = edge_ids(cell[:, None], np.where(centre, 0, edges))
    ids[centre] = 3 * flat.size + np.broadcast_to(cell[:, None], edges.shape)[centre]
    unique, triangles = np.unique(ids, return_inverse=True)
    n_edge_vertices = int(np.searchsorted(unique, 3 * flat.size))
    point, axis = np.divmod(unique[:n_edge_vertices], 3)
    f0 = flat[point]
    f1 = flat[point + np.array([1, nx, nx * ny])[axis]]
    t = (c - f0) / (f1 - f0)
    iz, rest = np.divmod(point, nx * ny)
    iy, ix = np.divmod(rest, nx)
    index_coords = np.stack([ix, iy, iz], axis=1).astype(float)
    index_coords[np.arange(len(point)), axis] += t
    vertices = org + index_coords * sp
    if n_edge_vertices < len(unique):                     # centroids of long loops
        cells = unique[n_edge_vertices:] - 3 * flat.size
        members = (centre_mask[index[cells]][:, None] >> np.arange(12)) & 1    # (k, 12)
        k, e = np.nonzero(members)
        at = np.searchsorted(unique[:n_edge_vertices], edge_ids(cells[k], e))
        sums = np.zeros((len(cells), 3))
        np.add.at(sums, k, vertices[at])
        vertices = np.concatenate([vertices, sums / members.sum(axis=1)[:, None]])
    return vertices, triangles.reshape(-1, 3).astype(np.intp)


def _mesh(vertices, triangles):
    v = as_points(vertices, "vertices", dims=3)
    t = np.asarray(triangles)
    if v.ndim != 2:
        raise ValueError(f"vertices must be an (n, 3) array, got shape {v.shape}")
    if t.size == 0:
        return v, np.zeros((0, 3), dtype=np.intp)
    if t.ndim != 2 or t.shape[1] != 3 or not np.issubdtype(t.dtype, np.integer):
        raise ValueError(f"triangles must be an (m, 3) array of vertex indices, got shape "
                         f"{t.shape} and type {t.dtype}")
    if t.min() < 0 or t.max() >= len(v):
        raise ValueError(f"triangles refer to vertex {int(t.max())} but there are {len(v)} "
                         "vertices")
    return v, t


def surface_area(vertices, triangles):
    r"""Total area of a triangle mesh, :math:`\sum \frac12 |(b - a) \times (c - a)|`.

    Examples
    --------
    >>> surface_area([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    0.5
    """
    v, t = _mesh(vertices, triangles)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum())


def enclosed_volume(vertices, triangles):
    r"""Signed volume enclosed by a closed, consistently wound mesh (divergence theorem).

    .. math:: V = \frac16 \sum_{\text{triangles}} a \cdot (b \times c)

    Each term is the signed volume of the tetrahedron (origin, a, b, c); the parts outside the
    surface cancel. Positive when the normals point outwards (counter-clockwise seen from
    outside), as :func:`marching_cubes` makes them.

    Examples
    --------
    The unit tetrahedron, wound outwards:

    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> round(enclosed_volume(v, [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]), 12)
    0.166666666667
    """
    v, t = _mesh(vertices, triangles)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def gradient(field, spacing=None):
    r"""The gradient of a 2D field or 3D volume by central differences.

    .. math:: \frac{\partial f}{\partial x}\Big|_i \approx \frac{f_{i+1} - f_{i-1}}{2 \Delta x}

    inside, and the one-sided :math:`(f_1 - f_0) / \Delta x` at the borders. The gradient points
    towards higher values and is perpendicular to the isolines/isosurfaces: normalized and
    negated, it is the surface normal used to shade an isosurface or a volume rendering.

    Parameters
    ----------
    field : array_like, shape (ny, nx) or (nz, ny, nx)
    spacing : tuple of float, optional
        (dx, dy(, dz)); default all 1.

    Returns
    -------
    ndarray, shape field.shape + (d,)
        The components (df/dx, df/dy(, df/dz)) in the last axis, in coordinate order.

    Examples
    --------
    >>> gradient([[0, 1, 4], [0, 1, 4]])[0]          # f = x^2 on x = 0, 1, 2
    array([[1., 0.],
           [2., 0.],
           [3., 0.]])
    """
    f = as_array(field, "field")
    if f.ndim not in (2, 3) or min(f.shape) < 2:
        raise ValueError(f"field must be a 2D field (ny, nx) or 3D volume (nz, ny, nx) with at "
                         f"least 2 samples per axis, got shape {f.shape}")
    d = f.ndim
    sp = np.ones(d) if spacing is None else _spacing(spacing, d)
    out = np.empty(f.shape + (d,))
    for c in range(d):                        # coordinate c varies along array axis d - 1 - c
        axis = d - 1 - c
        g = np.moveaxis(out[..., c], axis, 0)
        a = np.moveaxis(f, axis, 0)
        g[1:-1] = (a[2:] - a[:-2]) / (2 * sp[c])
        g[0] = (a[1] - a[0]) / sp[c]
        g[-1] = (a[-1] - a[-2]) / sp[c]
    return out


# ---------------------------------------------------------------------------------------------
# Interpolation on grids
# ---------------------------------------------------------------------------------------------

def _lerp_grid(flat, dims, idx):
    """Multilinear interpolation at continuous index coordinates.

    flat : the grid raveled in C order (x fastest), shape (N,) or (N, k)
    dims : samples along x, y(, z)
    idx : list of d arrays of index coordinates along x, y(, z), any values (clamped)
    """
    strides = np.cumprod([1] + list(dims[:-1]))
    base, fracs = 0, []
    for c, n in enumerate(dims):
        u = np.clip(idx[c], 0.0, n - 1)
        i0 = np.minimum(u.astype(np.intp), n - 2)
        fracs.append(u - i0)
        base = base + i0 * strides[c]
    # corner k has bit c set when it is the upper neighbour along coordinate c
    values = [flat[base + sum(strides[c] for c in range(len(dims)) if (k >> c) & 1)]
              for k in range(2 ** len(dims))]
    for f in fracs:                                      # halve the list one coordinate at a time
        f = f if flat.ndim == 1 else f[:, None]
        values = [a + f * (b - a) for a, b in zip(values[::2], values[1::2])]
    return values[0]


def interpolate(grid, points, spacing=None, origin=None):
    r"""Bilinear (2D) or trilinear (3D) interpolation of grid samples at arbitrary points.

    In 3D, with :math:`(f_x, f_y, f_z)` the fractional position inside the cell,

    .. math:: f = \sum_{a, b, c \in \{0, 1\}} f_{i+a, j+b, k+c}\;
              w_a(f_x)\, w_b(f_y)\, w_c(f_z), \quad w_0(u) = 1 - u,\ w_1(u) = u,

    computed as seven linear interpolations: four along x, two along y, one along z. Points
    outside the grid take the value at the nearest point of its border (clamping).

    Parameters
    ----------
    grid : array_like
        Samples, shape (ny, nx) or (nz, ny, nx) (last axis x); with one more trailing axis
        (vector components) for vector data.
    points : array_like, shape (..., d)
        (x, y) or (x, y, z) positions; d decides whether the grid is 2D or 3D.
    spacing, origin : tuple of float, optional
        Grid geometry in coordinate order; default spacing 1 and origin 0.

    Returns
    -------
    ndarray, shape points.shape[:-1] (+ (k,) for vector data)

    Examples
    --------
    >>> interpolate([[0, 1], [2, 3]], [[0.5, 0.5], [1, 0], [0, 2]])
    array([1.5, 1. , 2. ])
    """
    p = as_points(points, "points", dims=(2, 3))
    d = p.shape[-1]
    g = as_array(grid, "grid")
    if g.ndim not in (d, d + 1) or min(g.shape[:d]) < 2 or (g.ndim == d + 1 and g.shape[-1] < 1):
        raise ValueError(f"grid must hold {d}D samples (shape with {d} axes of >= 2 samples, "
                         f"plus optionally an axis of vector components) for {d}D points, got "
                         f"shape {g.shape}")
    sp = np.ones(d) if spacing is None else _spacing(spacing, d)
    org = np.zeros(d) if origin is None else as_vector(origin, "origin", d)
    dims = g.shape[:d][::-1]
    flat = g.reshape(int(np.prod(dims)), -1) if g.ndim == d + 1 else g.ravel()
    q = ((p - org) / sp).reshape(-1, d)
    out = _lerp_grid(flat, dims, [q[:, c] for c in range(d)])
    return out.reshape(p.shape[:-1] + out.shape[1:])


# ---------------------------------------------------------------------------------------------
# Volume rendering
# ---------------------------------------------------------------------------------------------

class VolumeImage(NamedTuple):
    """The result of :func:`volume_render`.

    Attributes
    ----------
    rgb : ndarray, shape (height, width, 3)
        The picture composited over the background; row 0 at the bottom.
    alpha : ndarray, shape (height, width)
        Accumulated opacity A of each ray (0 where a ray misses the volume).
    samples : int
        Samples taken (trilinear interpolations and transfer-function look-ups).
    samples_saved : int
        Samples that early ray termination skipped.

    Examples
    --------
    >>> img = volume_render(np.ones((4, 4, 4)), "ramp", early_termination=None)
    >>> img.rgb.shape, img.samples, img.samples_saved
    ((4, 4, 3), 112, 0)
    """
    rgb: np.ndarray
    alpha: np.ndarray
    samples: int
    samples_saved: int


def view_rotation(azimuth=0.0, elevation=0.0):
    r"""The rotation of an orbiting view: turn by `azimuth` about y, then `elevation` about x.

    :math:`R = R_x(\text{elevation})\, R_y(\text{azimuth})`, angles in radians; pass it as
    ``rotation`` to :func:`volume_render` or :func:`mip`, which map a point p of the volume to
    view coordinates :math:`q = R (p - \text{centre})`.

    Examples
    --------
    >>> view_rotation(np.pi / 2).round(12) @ [0, 0, 1]       # the volume's z turns to view x
    array([1., 0., 0.])
    """
    a, e = as_scalar(azimuth, "azimuth"), as_scalar(elevation, "elevation")
    ry = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    rx = np.array([[1, 0, 0], [0, np.cos(e), -np.sin(e)], [0, np.sin(e), np.cos(e)]])
    return rx @ ry


class _Rays(NamedTuple):
    shape: tuple          # (height, width)
    hit: np.ndarray       # (p,) bool
    origins: np.ndarray   # (p, 3) world points, outside the volume, in front of it
    direction: np.ndarray  # (3,)
    t_near: np.ndarray    # (p,)
    length: np.ndarray    # (p,) path length inside the box (0 for a miss)


def _cast_rays(shape, sp, org, rotation, image_size, extent):
    """One orthographic ray per pixel, clipped to the box of the volume's samples."""
    nz, ny, nx = shape
    lo = org
    hi = org + sp * np.array([nx - 1, ny - 1, nz - 1])
    centre = 0.5 * (lo + hi)
    if rotation is None:
        rot = np.eye(3)
    else:
        rot = as_rotation_matrix(rotation, "rotation")
        if rot.shape != (3, 3):
            raise ValueError(f"rotation must be a single 3x3 rotation, got shape {rot.shape}")
    radius = 0.5 * np.linalg.norm(hi - lo)
    if isinstance(extent, str):
        _choice(extent, "extent", ("fit", "sphere"))
        if extent == "fit":
            q = (lo + (hi - lo) * CUBE_CORNERS - centre) @ rot.T
            umin, vmin = q[:, :2].min(axis=0)
            umax, vmax = q[:, :2].max(axis=0)
        else:
            umin = vmin = -radius
            umax = vmax = radius
    else:
        umin, umax, vmin, vmax = as_vector(extent, "extent", 4)
        if not (umin < umax and vmin < vmax):
            raise ValueError("extent must be (umin, umax, vmin, vmax) with umin < umax and "
                             f"vmin < vmax, got {tuple(float(e) for e in extent)}")
    if image_size is None:
        pixel = sp.min()
        size = (max(2, int(round((vmax - vmin) / pixel)) + 1),
                max(2, int(round((umax - umin) / pixel)) + 1))
    else:
        size = as_vector(image_size, "image_size", 2)
        if (size < 1).any() or (size != np.round(size)).any():
            raise ValueError(f"image_size must be (height, width) in whole pixels >= 1, got "
                             f"{tuple(image_size)}")
        size = (int(size[0]), int(size[1]))
    u, v = np.meshgrid(np.linspace(umin, umax, size[1]), np.linspace(vmin, vmax, size[0]))
    depth = radius + sp.max()
    origins = (centre + u.reshape(-1, 1) * rot[0] + v.reshape(-1, 1) * rot[1]
               + depth * rot[2])
    direction = np.where(np.abs(rot[2]) < 1e-14, 0.0, -rot[2])   # cos(pi/2) is 6e-17, not 0
    # the box, grown by a rounding error, so that rays along its faces are not lost
    slack = 1e-12 * max(radius, 1.0)
    lo, hi = lo - slack, hi + slack
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (lo - origins) / direction
        t2 = (hi - origins) / direction
    parallel = direction == 0                         # rays parallel to a pair of faces
    between = (origins >= lo) & (origins <= hi)
    t_lo = np.where(parallel, np.where(between, -np.inf, np.inf), np.minimum(t1, t2))
    t_hi = np.where(parallel, np.where(between, np.inf, -np.inf), np.maximum(t1, t2))
    t_near, t_far = t_lo.max(axis=1), t_hi.min(axis=1)
    hit = t_far >= t_near
    length = np.where(hit, t_far - t_near, 0.0)
    return _Rays(size, hit, origins, direction, np.where(hit, t_near, 0.0), length)


def _rgba_transfer(transfer, v):
    """A 4-channel TransferFunction, from a preset name, a (color, opacity) pair or itself."""
    lo, hi = float(v.min()), float(v.max())
    in_range = (lo, hi) if hi > lo else (lo, lo + 1.0)
    if isinstance(transfer, str):
        return transfer_preset(transfer, in_range)
    if isinstance(transfer, tuple) and len(transfer) == 2:
        return rgba_transfer(transfer[0], transfer[1], in_range=in_range)
    if not isinstance(transfer, TransferFunction) or transfer.channels != 4:
        raise TypeError("transfer must be a preset name ('ramp', 'skin', 'bone'), a (color, "
                        "opacity) pair of transfer functions, or a 4-channel (RGBA) "
                        "TransferFunction")
    values = transfer.values
    if ((values < 0) | (values > 1)).any():
        raise ValueError("transfer must give colours and opacities in [0, 1] (opacity 0 "
                         "transparent, 1 opaque); its control values leave that range")
    return transfer


def _march_setup(volume, spacing, origin, rotation, image_size, extent, step):
    v = _grid(volume, "volume", 3)
    sp = _spacing(spacing, 3)
    org = as_vector(origin, "origin", 3)
    h = 0.5 * sp.min() if step is None else _positive(step, "step")
    rays = _cast_rays(v.shape, sp, org, rotation, image_size, extent)
    # samples at t_near + k h, k = 0 .. floor(L / h): both ends of the path are sampled
    n = np.where(rays.hit, np.floor(rays.length / h + 1e-9).astype(np.intp) + 1, 0)
    return v, sp, org, h, rays, n


def volume_render(volume, transfer="ramp", rotation=None, image_size=None, step=None,
                  spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), extent="fit",
                  early_termination=0.99, background=(0.0, 0.0, 0.0), unit_length=None):
    r"""Direct volume rendering by ray casting, composited front to back.

    One orthographic ray per pixel, travelling along :math:`-z` of the view frame
    (:math:`q = R (p - \text{centre})`). Along each ray inside the volume's box, samples are
    taken at :math:`t_k = t_{near} + k h` (both ends included), each standing for the segment
    :math:`\Delta_k = \min(h, L - k h)` behind it (:math:`L` = path length). A sample's value
    (trilinear, :func:`interpolate`) gives colour :math:`c` and opacity :math:`\alpha` through
    the transfer function, corrected for the segment length,
    :math:`\alpha_k = 1 - (1 - \alpha)^{\Delta_k / \ell}` (:math:`\ell` = `unit_length`), and
    composited front to back:

    .. math:: C \leftarrow C + (1 - A)\,\alpha_k c_k, \qquad A \leftarrow A + (1 - A)\,\alpha_k .

    A ray stops when :math:`A \ge` `early_termination` (early ray termination): the samples
    behind could change its colour by less than :math:`1 - A`. The pixel is finally
    :math:`C + (1 - A)\,\text{background}`.

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
        Samples, last axis x (see the module's conventions).
    transfer : str, (color, opacity) or TransferFunction
        A preset name ("ramp", "skin", "bone"; :func:`course_lib.colormaps.transfer_preset`)
        stretched over the volume's value range; a pair (colour transfer function or colour map
        name, opacity transfer function) joined by :func:`course_lib.colormaps.rgba_transfer`
        with a colour map spread over the value range; or a 4-channel RGBA TransferFunction of
        the raw values. Opacities are per `unit_length` and must lie in [0, 1].
    rotation : array_like, shape (3, 3), optional
        The view rotation R (e.g. :func:`view_rotation`); default: look down -z of the volume.
    image_size : (int, int), optional
        (height, width). Default: one pixel per sample spacing over the extent (for the default
        view, exactly one ray through each column ``volume[:, j, i]``).
    step : float, optional
        Distance h between samples along a ray, > 0; default half the smallest spacing.
    spacing, origin : tuple of float
        The volume's geometry (x, y, z).
    extent : "fit", "sphere" or (umin, umax, vmin, vmax)
        The image window in view coordinates: pixel centres run from umin to umax (columns) and
        vmin to vmax (rows). "fit" hugs the volume's projected box; "sphere" is the square
        around its bounding sphere, the same for every rotation (use it when turning the view).
    early_termination : float in (0, 1] or None
        The opacity at which a ray stops; None never stops early.
    background : (r, g, b)
        Colour behind the volume.
    unit_length : float, optional
        The thickness for which the transfer function's opacity holds; default the smallest
        spacing (one voxel).

    Returns
    -------
    VolumeImage
        ``rgb`` (height, width, 3), ``alpha`` (height, width), and the sample counts.

    Raises
    ------
    ValueError
        For a non-3D volume or NaN in it, a non-positive step, spacing or unit length, an
        opacity outside [0, 1], or an early termination threshold outside (0, 1].

    Examples
    --------
    A uniform block 4 samples deep (path length 3) with opacity 0.5 per unit length: the
    transmittance is :math:`(1 - 0.5)^3`, whatever the step (Beer-Lambert):

    >>> tf = TransferFunction([0, 1], [[1, 1, 1, 0.5], [1, 1, 1, 0.5]])
    >>> for h in (1.0, 0.5, 0.1):
    ...     img = volume_render(np.ones((4, 4, 4)), tf, step=h, early_termination=None)
    ...     print(round(1 - float(img.alpha[0, 0]), 12))
    0.125
    0.125
    0.125
    """
    v, sp, org, h, rays, n = _march_setup(volume, spacing, origin, rotation, image_size, extent,
                                          step)
    tf = _rgba_transfer(transfer, v)
    unit = sp.min() if unit_length is None else _positive(unit_length, "unit_length")
    if early_termination is None:
        threshold = None
    else:
        threshold = as_scalar(early_termination, "early_termination")
        if not 0 < threshold <= 1:
            raise ValueError(f"early_termination must lie in (0, 1] (or be None), got "
                             f"{threshold:g}")
    bg = as_vector(background, "background", 3)
    flat, dims = v.ravel(), v.shape[::-1]
    pixels = len(rays.hit)
    out_c, out_a = np.zeros((pixels, 3)), np.zeros(pixels)
    ids = np.flatnonzero(rays.hit)
    # each ray in index coordinates: its first sample, and the move of one step
    start = ((rays.origins[ids] + rays.t_near[ids, None] * rays.direction) - org) / sp
    move = h * rays.direction / sp
    length, count = rays.length[ids], n[ids]
    color, alpha = np.zeros((len(ids), 3)), np.zeros(len(ids))
    taken = saved = 0
    k = 0
    while len(ids):
        q = start + k * move
        rgba = tf._evaluate(_lerp_grid(flat, dims, [q[:, 0], q[:, 1], q[:, 2]]), "right")
        segment = np.clip(length - k * h, 0.0, h)
        a = 1.0 - (1.0 - rgba[:, 3]) ** (segment / unit)          # opacity correction
        weight = (1.0 - alpha) * a
        color += weight[:, None] * rgba[:, :3]
        alpha += weight
        taken += len(ids)
        done = count <= k + 1
        if threshold is not None:
            early = (alpha >= threshold) & ~done
            saved += int((count[early] - (k + 1)).sum())
            done |= early
        if done.any():
            out_c[ids[done]], out_a[ids[done]] = color[done], alpha[done]
            keep = ~done
            ids, start, length, count, color, alpha = (
                ids[keep], start[keep], length[keep], count[keep], color[keep], alpha[keep])
        k += 1
    rgb = out_c + (1.0 - out_a)[:, None] * bg
    height, width = rays.shape
    return VolumeImage(rgb.reshape(height, width, 3), out_a.reshape(height, width), taken, saved)


def mip(volume, rotation=None, image_size=None, step=None, spacing=(1.0, 1.0, 1.0),
        origin=(0.0, 0.0, 0.0), extent="fit", fill=None):
    """Maximum intensity projection: the largest (trilinear) sample along each ray.

    Rays, samples and parameters as in :func:`volume_render` (samples at both ends of each
    path, every `step`). With the default view and a step that divides the z spacing, the
    samples include every grid point of a column, so the result is ``volume.max(axis=0)``.

    Parameters
    ----------
    fill : float, optional
        The value of pixels whose ray misses the volume; default the volume's minimum.

    Returns
    -------
    ndarray, shape (height, width)
        Row 0 at the bottom.

    Examples
    --------
    >>> vol = np.zeros((3, 2, 2)); vol[1, 0, 1] = 5.0; vol[2, 1, 1] = 2.0
    >>> mip(vol)
    array([[0., 5.],
           [0., 2.]])
    """
    v, sp, org, h, rays, n = _march_setup(volume, spacing, origin, rotation, image_size, extent,
                                          step)
    background = float(v.min()) if fill is None else as_scalar(fill, "fill")
    flat, dims = v.ravel(), v.shape[::-1]
    out = np.full(len(rays.hit), background)
    ids = np.flatnonzero(rays.hit)
    start = ((rays.origins[ids] + rays.t_near[ids, None] * rays.direction) - org) / sp
    move = h * rays.direction / sp
    count = n[ids]
    best = np.full(len(ids), -np.inf)
    k = 0
    while len(ids):
        q = start + k * move
        best = np.maximum(best, _lerp_grid(flat, dims, [q[:, 0], q[:, 1], q[:, 2]]))
        done = count <= k + 1
        if done.any():
            out[ids[done]] = best[done]
            keep = ~done
            ids, start, count, best = ids[keep], start[keep], count[keep], best[keep]
        k += 1
    return out.reshape(rays.shape)


def composite(colors, opacities, order="front-to-back", cumulative=False):
    r"""Composite samples along a ray, given front (index 0, nearest the eye) to back.

    Front to back: :math:`C \leftarrow C + (1 - A)\,\alpha_i c_i`,
    :math:`A \leftarrow A + (1 - A)\,\alpha_i`, for i = 0, 1, ...; back to front (the
    painter's "over" operator): :math:`C \leftarrow \alpha_i c_i + (1 - \alpha_i)\,C`,
    :math:`A \leftarrow \alpha_i + (1 - \alpha_i)\,A`, for i = n-1, ..., 0. Both give the same
    result; only front to back knows the opacity so far and can stop early. The colour is
    premultiplied (as seen over black); over a background b the pixel is
    :math:`C + (1 - A)\,b`.

    Parameters
    ----------
    colors : array_like, shape (..., n, 3) or (..., n)
        Sample colours (or grey levels).
    opacities : array_like, shape (..., n)
        Sample opacities in [0, 1].
    order : {"front-to-back", "back-to-front"}
    cumulative : bool
        If True, return the running values after each sample (in the order processed, indexed
        by sample): shapes (..., n, 3) / (..., n).

    Returns
    -------
    color : ndarray, shape (..., 3) or (...)
    alpha : ndarray, shape (...)

    Examples
    --------
    A red sample of opacity 0.5 in front of a blue one of opacity 0.5:

    >>> composite([[1, 0, 0], [0, 0, 1]], [0.5, 0.5])
    (array([0.5 , 0.  , 0.25]), 0.75)
    >>> composite([[1, 0, 0], [0, 0, 1]], [0.5, 0.5], order="back-to-front")
    (array([0.5 , 0.  , 0.25]), 0.75)
    """
    _choice(order, "order", ("front-to-back", "back-to-front"))
    a = as_array(opacities, "opacities")
    c = as_array(colors, "colors")
    if a.ndim == 0:
        raise ValueError("opacities must have one value per sample, shape (..., n)")
    grey = c.shape == a.shape
    if not grey and c.shape != a.shape + (3,):
        raise ValueError(f"colors must have shape opacities.shape + (3,) = {a.shape + (3,)} "
                         f"or opacities.shape = {a.shape}, got {c.shape}")
    if ((a < 0) | (a > 1)).any():
        raise ValueError("opacities must lie in [0, 1] (0 transparent, 1 opaque), got values "
                         f"from {a.min():g} to {a.max():g}")
    cc = c[..., None] if grey else c
    n = a.shape[-1]
    color, alpha = np.zeros(cc.shape[:-2] + cc.shape[-1:]), np.zeros(a.shape[:-1])
    steps_c, steps_a = np.zeros(cc.shape), np.zeros(a.shape)
    indices = range(n) if order == "front-to-back" else range(n - 1, -1, -1)
    for i in indices:
        ai, ci = a[..., i], cc[..., i, :]
        if order == "front-to-back":
            color = color + ((1 - alpha) * ai)[..., None] * ci
            alpha = alpha + (1 - alpha) * ai
        else:
            color = ai[..., None] * ci + (1 - ai)[..., None] * color
            alpha = ai + (1 - ai) * alpha
        steps_c[..., i, :], steps_a[..., i] = color, alpha
    if cumulative:
        return (steps_c[..., 0] if grey else steps_c), steps_a
    color = color[..., 0] if grey else color
    return color, (alpha if alpha.ndim else float(alpha))


# ---------------------------------------------------------------------------------------------
# Streamlines
# ---------------------------------------------------------------------------------------------

def _velocity_sampler(velocity, dim, spacing, origin, bounds):
    """(sampler(points (k, d)) -> (k, d), lower bounds, upper bounds, dim)."""
    if callable(velocity):
        def sampler(points):
            v = np.asarray(velocity(points), dtype=float)
            if v.shape != points.shape:
                raise ValueError(f"velocity must return one {dim}-vector per point (shape "
                                 f"{points.shape}), got shape {v.shape}")
            if not np.isfinite(v).all():
                raise ValueError("velocity returned NaN or infinite values")
            return v
        lo, hi = np.full(dim, -np.inf), np.full(dim, np.inf)
    else:
        g = as_array(velocity, "velocity")
        if g.ndim != dim + 1 or g.shape[-1] != dim or min(g.shape[:-1]) < 2:
            raise ValueError(f"velocity must be a function or a grid of {dim}D vectors, shape "
                             f"{'(ny, nx, 2)' if dim == 2 else '(nz, ny, nx, 3)'} (last grid "
                             f"axis x), got shape {g.shape}")
        sp = np.ones(dim) if spacing is None else _spacing(spacing, dim)
        org = np.zeros(dim) if origin is None else as_vector(origin, "origin", dim)
        dims = g.shape[:-1][::-1]
        flat = g.reshape(-1, dim)

        def sampler(points):
            q = (points - org) / sp
            return _lerp_grid(flat, dims, [q[:, c] for c in range(dim)])
        lo, hi = org, org + sp * (np.array(dims) - 1)
    if bounds is not None:
        b = as_array(bounds, "bounds")
        if b.shape != (2, dim) or (b[0] > b[1]).any():
            raise ValueError(f"bounds must be ((low x, low y, ...), (high x, high y, ...)), "
                             f"shape (2, {dim}), lows <= highs, got shape {b.shape}")
        lo, hi = np.maximum(lo, b[0]), np.minimum(hi, b[1])
    return sampler, lo, hi


def streamline(velocity, seeds, step, n_steps=100, method="rk4", spacing=None, origin=None,
               bounds=None, min_speed=1e-10):
    r"""Trace streamlines :math:`\mathrm{d}x/\mathrm{d}t = v(x)` from seed points.

    With step h and :math:`k_1 = v(x_n)`:

    * ``"euler"``: :math:`x_{n+1} = x_n + h k_1` (error per unit time O(h));
    * ``"rk2"`` (midpoint): :math:`x_{n+1} = x_n + h\, v(x_n + \tfrac h2 k_1)` (O(h^2));
    * ``"rk4"``: :math:`k_2 = v(x_n + \tfrac h2 k_1)`, :math:`k_3 = v(x_n + \tfrac h2 k_2)`,
      :math:`k_4 = v(x_n + h k_3)`, :math:`x_{n+1} = x_n + \tfrac h6 (k_1 + 2k_2 + 2k_3 + k_4)`
      (O(h^4)).

    A line **stops** at a point where the speed :math:`|v|` is below `min_speed` (a critical
    point: the flow stands still), or before a step that would leave the domain (the grid's
    extent, or `bounds`); the last point kept is inside. All seeds advance together.

    Parameters
    ----------
    velocity : callable or array_like
        A function mapping points (k, d) to velocities (k, d), or velocities sampled on a grid,
        shape (ny, nx, 2) or (nz, ny, nx, 3) (last grid axis x, components (vx, vy(, vz))),
        interpolated bilinearly / trilinearly (:func:`interpolate`; RK stages that fall outside
        use the nearest border value).
    seeds : array_like, shape (d,) or (k, d)
        Start points (x, y) or (x, y, z).
    step : float
        The integration step h; negative traces backwards (upstream). Not zero.
    n_steps : int
        Number of steps, >= 1.
    method : {"euler", "rk2", "rk4"}
    spacing, origin : tuple of float, optional
        The geometry of a velocity grid (default spacing 1, origin 0).
    bounds : array_like, shape (2, d), optional
        ((low x, low y, ...), (high x, high y, ...)): a box the lines must stay in.
    min_speed : float
        Speeds below this count as zero.

    Returns
    -------
    ndarray, shape (n_steps + 1, d) for one seed, (k, n_steps + 1, d) for several
        The points, starting with the seed; after a line stops, its remaining rows are NaN
        (matplotlib's ``plot`` simply leaves them out; ``line[np.isfinite(line[:, 0])]``
        keeps the valid part). A seed outside the domain gives a line of just the seed.

    Raises
    ------
    ValueError
        For a zero step, an unknown method, or a velocity of the wrong shape.

    Examples
    --------
    Euler on the vortex v = (-y, x) moves along the tangent and drifts outwards; RK4 stays on
    the unit circle:

    >>> vortex = example_vector_field("vortex")
    >>> streamline(vortex, [1.0, 0.0], step=0.5, n_steps=2, method="euler")
    array([[1.  , 0.  ],
           [1.  , 0.5 ],
           [0.75, 1.  ]])
    >>> line = streamline(vortex, [1.0, 0.0], step=0.1, n_steps=63)
    >>> float(np.linalg.norm(line[-1]).round(6))
    1.0
    """
    _choice(method, "method", ("euler", "rk2", "rk4"))
    p = as_points(seeds, "seeds", dims=(2, 3))
    single = p.ndim == 1
    p = p.reshape(-1, p.shape[-1])
    dim = p.shape[1]
    h = as_scalar(step, "step")
    if h == 0:
        raise ValueError("step must not be zero (a negative step traces upstream)")
    n = _whole(n_steps, "n_steps", 1)
    speed_min = as_scalar(min_speed, "min_speed")
    sampler, lo, hi = _velocity_sampler(velocity, dim, spacing, origin, bounds)

    def inside(x):
        return ((x >= lo) & (x <= hi)).all(axis=1)

    lines = np.full((len(p), n + 1, dim), np.nan)
    lines[:, 0] = p
    current = p.copy()
    alive = inside(p)
    for i in range(n):
        ids = np.flatnonzero(alive)
        if ids.size == 0:
            break
        x = current[ids]
        k1 = sampler(x)
        if method == "euler":
            new = x + h * k1
        elif method == "rk2":
            new = x + h * sampler(x + 0.5 * h * k1)
        else:
            k2 = sampler(x + 0.5 * h * k1)
            k3 = sampler(x + 0.5 * h * k2)
            k4 = sampler(x + h * k3)
            new = x + (h / 6.0) * (k1 + 2 * k2 + 2 * k3 + k4)
        ok = (np.linalg.norm(k1, axis=1) >= speed_min) & inside(new)
        alive[ids[~ok]] = False
        current[ids[ok]] = new[ok]
        lines[ids[ok], i + 1] = new[ok]
    return lines[0] if single else lines


# ---------------------------------------------------------------------------------------------
# Glyphs
# ---------------------------------------------------------------------------------------------

def _glyph_inputs(points, vectors, dims):
    p = as_points(points, "points", dims=dims)
    v = as_points(vectors, "vectors", dims=dims)
    if p.shape[-1] != v.shape[-1]:
        raise ValueError(f"points and vectors must have the same dimension, got {p.shape[-1]} "
                         f"and {v.shape[-1]}")
    shape = np.broadcast_shapes(p.shape, v.shape) if p.shape != v.shape else p.shape
    return np.broadcast_to(p, shape), np.broadcast_to(v, shape)


def hedgehog(points, vectors, scale=1.0, normalize=False):
    """Hedgehog glyphs: a line segment from each point along its vector, p -> p + scale v.

    Parameters
    ----------
    points, vectors : array_like, shape (..., d)
        Positions and vectors (2D or 3D), broadcast against each other.
    scale : float
        Length factor (choose it so that the longest segment is about one grid cell).
    normalize : bool
        If True, all segments have length `scale` (direction only; zero vectors stay points).

    Returns
    -------
    ndarray, shape (..., 2, d)
        (start, end) of each segment, ready for matplotlib's ``LineCollection``.

    Examples
    --------
    >>> hedgehog([[0, 0], [1, 1]], [[2, 0], [0, -1]], scale=0.5)
    array([[[0. , 0. ],
            [1. , 0. ]],
    <BLANKLINE>
           [[1. , 1. ],
            [1. , 0.5]]])
    """
    p, v = _glyph_inputs(points, vectors, (2, 3))
    s = as_scalar(scale, "scale")
    if normalize:
        length = np.linalg.norm(v, axis=-1, keepdims=True)
        v = np.where(length > 0, v / np.where(length > 0, length, 1.0), 0.0)
    return np.stack([p, p + s * v], axis=-2)


def arrows(points, vectors, scale=1.0, head_length=0.3, head_width=0.3, shaft_width=0.08):
    """2D arrow glyphs as closed outlines of 7 vertices, sized by the vector's length.

    An arrow of length L = scale |v| runs from the point p to the tip p + scale v: a shaft of
    width ``shaft_width * L`` and a triangular head of length ``head_length * L`` and width
    ``head_width * L`` (so arrow shapes stay similar: the size shows the magnitude).

    Parameters
    ----------
    points, vectors : array_like, shape (..., 2)
    scale : float
        Length factor.
    head_length, head_width, shaft_width : float
        Proportions of the arrow's length, positive; head_length at most 1.

    Returns
    -------
    ndarray, shape (..., 7, 2)
        Vertices counter-clockwise from the tail: tail right, shaft end right, head right,
        tip, head left, shaft end left, tail left (for ``PolyCollection``). A zero vector gives
        seven copies of its point.

    Examples
    --------
    >>> arrows([0, 0], [1, 0], head_length=0.25, head_width=0.5, shaft_width=0.1)
    array([[ 0.  , -0.05],
           [ 0.75, -0.05],
           [ 0.75, -0.25],
           [ 1.  ,  0.  ],
           [ 0.75,  0.25],
           [ 0.75,  0.05],
           [ 0.  ,  0.05]])
    """
    p, v = _glyph_inputs(points, vectors, 2)
    s = as_scalar(scale, "scale")
    hl = _positive(head_length, "head_length")
    if hl > 1:
        raise ValueError(f"head_length must be at most 1 (a fraction of the arrow), got {hl:g}")
    hw, sw = _positive(head_width, "head_width"), _positive(shaft_width, "shaft_width")
    d = s * v                                     # along the arrow, length L
    n = np.stack([-d[..., 1], d[..., 0]], axis=-1)  # to the left, also length L
    neck = p + (1 - hl) * d
    outline = [p - 0.5 * sw * n, neck - 0.5 * sw * n, neck - 0.5 * hw * n, p + d,
               neck + 0.5 * hw * n, neck + 0.5 * sw * n, p + 0.5 * sw * n]
    return np.stack(outline, axis=-2)
