"""Chapter 18 (lesson section 1): example scalar fields, volumes and vector fields, generated."""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_points, as_whole

__all__ = ["Field", "example_field_2d", "example_vector_field", "example_volume",
    "sample_vector_field"]


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
    n = as_whole(size, "size", 2)
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
    as_choice(kind, "kind", _FIELDS_2D)
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


_VOLUMES = ("sphere", "blobs", "torus", "ct", "noise")


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
      see :func:`course_lib.colormaps.transfer_preset` for transfer functions made for it;
    * ``"noise"``: smooth random values in [-1, 1] (seed 18: white noise blurred by three
      passes of a box filter of 3 samples along each axis, scaled to [-1, 1]) with the outer
      layer of samples set to -2, so that every isosurface above -2 closes before the border;
      its many saddles make ambiguous faces for :func:`marching_cubes` at most levels.

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
    >>> n = example_volume("noise", size=16)
    >>> float(n.values[0, 0, 0]), float(n.values[1:-1, 1:-1, 1:-1].max()), n.level
    (-2.0, 1.0, 0.3)
    """
    as_choice(kind, "kind", _VOLUMES)
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
    elif kind == "noise":
        values = np.random.default_rng(18).normal(size=x.shape)
        for axis in range(3):
            for _ in range(3):
                values = (np.roll(values, 1, axis) + values + np.roll(values, -1, axis)) / 3
        values = 2 * (values - values.min()) / (values.max() - values.min()) - 1
        values[[0, -1]] = values[:, [0, -1]] = values[:, :, [0, -1]] = -2.0
        level = 0.3
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
    as_choice(dim, "dim", (2, 3))
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
    as_choice(dim, "dim", (2, 3))
    coords, spacing, origin = _cube_grid(size, dim)
    points = np.stack(coords, axis=-1)
    values = as_array(velocity(points), "velocity(points)")
    if values.shape != points.shape:
        raise ValueError(f"velocity must return one {dim}-vector per point, shape "
                         f"{points.shape}, got shape {values.shape}")
    return Field(values, spacing, origin, None)
