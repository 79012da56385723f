"""Chapter 15 (lesson section 15.1): the pinhole camera, one primary ray per pixel sample."""

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .. import viewing
from .._validate import as_rng, as_scalar, as_vector, as_whole
from ._common import _dot

__all__ = ["Camera", "CameraRays", "camera_rays"]


# ---------------------------------------------------------------------------------------------
# The camera: one ray per pixel sample
# ---------------------------------------------------------------------------------------------

class CameraRays(NamedTuple):
    """The rays of :func:`camera_rays`: shapes (height, width, samples, 3), row 0 at the bottom.

    Attributes
    ----------
    origins : ndarray, shape (height, width, samples, 3)
        All equal to the eye (a pinhole camera).
    directions : ndarray, shape (height, width, samples, 3)
        Unit vectors through the sample positions.

    Examples
    --------
    >>> rays = camera_rays([0, 0, 5], [0, 0, -1], [0, 1, 0], np.radians(90), 2, 2)
    >>> rays.directions.shape
    (2, 2, 1, 3)
    """
    origins: np.ndarray
    directions: np.ndarray


def _samples_per_pixel(value):
    s = as_whole(value, "samples_per_pixel", 1)
    k = int(round(np.sqrt(s)))
    if k * k != s:
        raise ValueError(f"samples_per_pixel must be a perfect square (1, 4, 9, 16, ...) so that "
                         f"the samples form a k x k grid in each pixel, got {s}")
    return s, k


def camera_rays(eye, gaze, up, fov_y, width, height, samples_per_pixel=1, seed=None,
                jitter=False):
    r"""The primary rays of a pinhole camera: one per pixel sample, through the image plane.

    The camera is that of :func:`course_lib.viewing.look_at` (the eye at `eye`, looking along
    `gaze`, `up` giving the roll) and :func:`course_lib.viewing.perspective` (vertical field of
    view `fov_y`, aspect ``width / height``). A sample at viewport position :math:`(x, y)`
    (pixel :math:`(j, i)` covers :math:`[i, i+1] \times [j, j+1]`) has canonical coordinates
    :math:`x_c = 2x/W - 1`, :math:`y_c = 2y/H - 1`, and undoing the projection gives its
    direction in eye coordinates

    .. math:: d_e = \left(\frac{x_c}{P_{00}}, \frac{y_c}{P_{11}}, -1\right), \qquad
              P_{11} = \cot\frac{\theta}{2}, \quad P_{00} = \frac{P_{11}}{\text{aspect}}

    (the point of the near plane at distance 1 that projects there), turned into world
    coordinates with the transpose of the view rotation: :math:`d = x_e\, d_{e,x} + y_e\,
    d_{e,y} + z_e\, d_{e,z}`, then normalized. So a point along the ray projects (with
    :func:`course_lib.viewing.to_screen`) exactly onto the sample.

    **Supersampling**: with ``samples_per_pixel = k * k`` each pixel is divided into a k x k grid
    of sub-pixels; a sample sits at the centre of its sub-pixel (a regular grid), or, with
    ``jitter=True``, at a uniformly random position inside it (stratified sampling). One
    sample per pixel without jitter is the pixel centre :math:`(i + \tfrac12, j + \tfrac12)`.

    Parameters
    ----------
    eye, gaze, up : array_like, shape (3,)
        As for :func:`course_lib.viewing.look_at` (`gaze` is a direction, not a target point).
    fov_y : float
        Vertical field of view in radians, in (0, pi).
    width, height : int
        Image size in pixels.
    samples_per_pixel : int, optional
        A perfect square (1, 4, 9, ...).
    seed : int, numpy.random.Generator or None, optional
        Randomness for `jitter`.
    jitter : bool, optional
        Jitter each sample within its sub-pixel.

    Returns
    -------
    CameraRays
        ``origins`` and unit ``directions``, shape (height, width, samples, 3). **Row 0 is the
        bottom row** of the image; sample ``s = a * k + b`` is in sub-pixel row a (from the
        bottom) and column b.

    Raises
    ------
    ValueError
        For `fov_y` outside (0, pi), `up` parallel to `gaze`, zero vectors, a non-positive or
        fractional size, or a sample count that is not a perfect square.

    Examples
    --------
    A 90 degree camera on a 2 x 2 image: the pixel centres are at canonical (+-1/2, +-1/2); the
    top-right pixel (row 1, column 1) looks right, up and forwards:

    >>> rays = camera_rays([0, 0, 5], [0, 0, -1], [0, 1, 0], np.radians(90), 2, 2)
    >>> (rays.directions[1, 1, 0] * np.sqrt(6)).round(12)     # (0.5, 0.5, -1) normalized
    array([ 1.,  1., -2.])
    """
    view = viewing.look_at(eye, gaze, up)
    fov = as_scalar(fov_y, "fov_y")
    if not 0 < fov < np.pi:
        raise ValueError(f"fov_y must be an angle in radians between 0 and pi, got {fov}")
    w = as_whole(width, "width", 1)
    h = as_whole(height, "height", 1)
    s, k = _samples_per_pixel(samples_per_pixel)
    proj = viewing.perspective(fov, w / h, 1.0, 2.0)
    a, b = np.divmod(np.arange(s), k)                       # sub-pixel row a, column b
    if jitter:
        rng = as_rng(seed)
        sx = (b + rng.random((h, w, s))) / k
        sy = (a + rng.random((h, w, s))) / k
    else:
        sx = np.broadcast_to((b + 0.5) / k, (h, w, s))
        sy = np.broadcast_to((a + 0.5) / k, (h, w, s))
    x = (np.arange(w)[None, :, None] + sx) * (2.0 / w) - 1.0
    y = (np.arange(h)[:, None, None] + sy) * (2.0 / h) - 1.0
    axes = view[:3, :3]                                     # rows: x_e, y_e, z_e in the world
    d = ((x / proj[0, 0])[..., None] * axes[0] + (y / proj[1, 1])[..., None] * axes[1]
         - axes[2])
    d /= np.sqrt(_dot(d, d))[..., None]
    origins = np.broadcast_to(as_vector(eye, "eye", 3), d.shape).copy()
    return CameraRays(origins, d)


@dataclass(frozen=True, eq=False)
class Camera:
    """A pinhole camera: where it is, where it looks, its field of view and image size.

    See :func:`camera_rays` for the rays it shoots (row 0 of the image at the bottom).

    Attributes
    ----------
    eye, gaze, up : array_like, shape (3,)
        Position, viewing direction, and the up direction (not parallel to `gaze`).
    fov_y : float
        Vertical field of view in radians, in (0, pi).
    width, height : int
        Image size in pixels.

    Examples
    --------
    >>> cam = Camera([0, 1, 5], [0, 0, -1], [0, 1, 0], np.radians(45), 64, 48)
    >>> cam.rays().directions.shape, cam.rays(samples_per_pixel=4).directions.shape
    ((48, 64, 1, 3), (48, 64, 4, 3))
    >>> origin, direction = cam.pixel_ray(24, 32)      # just above and right of the centre
    >>> bool(np.allclose(direction, cam.rays().directions[24, 32, 0]))
    True
    """
    eye: object
    gaze: object
    up: object
    fov_y: float
    width: int
    height: int

    def __post_init__(self):
        viewing.look_at(self.eye, self.gaze, self.up)           # checks eye, gaze and up
        fov = as_scalar(self.fov_y, "fov_y")
        if not 0 < fov < np.pi:
            raise ValueError(f"fov_y must be an angle in radians between 0 and pi, got {fov}")
        object.__setattr__(self, "eye", as_vector(self.eye, "eye", 3))
        object.__setattr__(self, "gaze", as_vector(self.gaze, "gaze", 3))
        object.__setattr__(self, "up", as_vector(self.up, "up", 3))
        object.__setattr__(self, "fov_y", fov)
        object.__setattr__(self, "width", as_whole(self.width, "width", 1))
        object.__setattr__(self, "height", as_whole(self.height, "height", 1))

    def rays(self, samples_per_pixel=1, seed=None, jitter=False):
        """The camera's rays, :func:`camera_rays` with its parameters."""
        return camera_rays(self.eye, self.gaze, self.up, self.fov_y, self.width, self.height,
                           samples_per_pixel, seed, jitter)

    def resized(self, width, height):
        """The same camera with another image size."""
        return Camera(self.eye, self.gaze, self.up, self.fov_y, width, height)

    def pixel_ray(self, row, column):
        """The ray through the centre of pixel (`row`, `column`), row 0 at the bottom: the
        primary ray of :func:`trace_tree` for that pixel.

        Returns ``(origin, direction)``, both shape (3,), the direction a unit vector (the same
        ray as ``self.rays()`` gives for that pixel). Raises ValueError for a pixel outside the
        image.
        """
        j = as_whole(row, "row", 0)
        i = as_whole(column, "column", 0)
        if j >= self.height or i >= self.width:
            raise ValueError(f"pixel (row {j}, column {i}) lies outside the {self.width} x "
                             f"{self.height} image (rows 0..{self.height - 1}, columns "
                             f"0..{self.width - 1})")
        proj = viewing.perspective(self.fov_y, self.width / self.height, 1.0, 2.0)
        axes = viewing.look_at(self.eye, self.gaze, self.up)[:3, :3]
        x = (i + 0.5) * (2.0 / self.width) - 1.0
        y = (j + 0.5) * (2.0 / self.height) - 1.0
        d = (x / proj[0, 0]) * axes[0] + (y / proj[1, 1]) * axes[1] - axes[2]
        return self.eye.copy(), d / np.sqrt(d @ d)
