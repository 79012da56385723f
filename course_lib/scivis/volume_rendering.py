"""Chapter 18 (lesson section 4): direct volume rendering: ray casting, compositing, MIP."""

from typing import NamedTuple

import numpy as np

from .._validate import (as_array, as_choice, as_positive, as_rotation_matrix, as_scalar,
    as_vector, as_whole)
from ..colormaps import rgba_transfer, transfer_preset, TransferFunction
from ._common import _grid, _spacing
from .grids import _lerp_grid
from .isosurfaces import CUBE_CORNERS

__all__ = ["RaySamples", "VolumeImage", "composite", "mip", "view_rotation",
    "volume_render"]


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


def _view_window(shape, sp, org, rotation, image_size, extent):
    """The volume's box (lo, hi, centre, bounding radius), the rotation, and the view
    coordinates (u, v) of every pixel centre, shape (height, width) each."""
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
        as_choice(extent, "extent", ("fit", "sphere"))
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
    return lo, hi, centre, radius, rot, u, v, size


def _cast_rays(shape, sp, org, rotation, image_size, extent):
    """One orthographic ray per pixel, clipped to the box of the volume's samples."""
    lo, hi, centre, radius, rot, u, v, size = _view_window(shape, sp, org, rotation, image_size,
                                                           extent)
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
    h = 0.5 * sp.min() if step is None else as_positive(step, "step")
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
    unit = sp.min() if unit_length is None else as_positive(unit_length, "unit_length")
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


class RaySamples:
    r"""The volume sampled along every ray of one view, once: classify and composite later.

    Sampling a volume along the rays (trilinear interpolation) is most of the work of ray
    casting, and it does not depend on the transfer function: only the *classification* of the
    samples (value -> colour and opacity) and their compositing do. While a transfer function
    is edited and the view stays the same, the samples can be taken once; each new function
    then costs one table look-up per sample and the front-to-back compositing of all rays at
    once, as cumulative products:

    .. math:: \alpha_k' = 1 - (1 - \alpha_k)^{h/\ell}, \quad
              T_k = \prod_{j<k} (1 - \alpha_j'), \quad
              C = \sum_k T_k\, \alpha_k'\, c_k, \quad A = 1 - T_n ,

    the same sums as the loop of :func:`composite` (:math:`T_k = 1 - A` before sample k).

    The rays are those of :func:`volume_render` (one orthographic ray per pixel, along -z of
    the view frame); the samples lie on common planes of constant view depth, every `step`
    from the front of the volume's bounding sphere to its back (not from where each ray
    enters the box, as in :func:`volume_render`: so all rays have the same number of samples
    and are composited as one array). Samples outside the volume's box count as empty
    (opacity 0). There is no early ray termination: every sample is composited (the count of
    those it would have skipped is reported instead).

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
        Samples, last axis x.
    rotation : array_like, shape (3, 3), optional
        The view rotation (e.g. :func:`view_rotation`); default: look down -z of the volume.
    image_size : (int, int), optional
        (height, width); default as in :func:`volume_render`.
    step : float, optional
        Distance h between samples along a ray, > 0; default half the smallest spacing.
    spacing, origin : tuple of float
        The volume's geometry (x, y, z).
    extent : "fit", "sphere" or (umin, umax, vmin, vmax)
        The image window in view coordinates, as in :func:`volume_render`.
    unit_length : float, optional
        The thickness for which the transfer function's opacity holds; default the smallest
        spacing (one voxel).
    value_range : (float, float), optional
        The values the classification table spans (default the volume's minimum and maximum,
        or minimum + 1 for a constant volume); samples outside it take the entry at its
        nearer end.
    lut_size : int
        Entries of the classification table (default 1024): each sample takes the entry
        nearest to its value, an error below the transfer function's slope times
        (range / 2 (lut_size - 1)).

    Attributes
    ----------
    samples : ndarray, shape (rays hit, depths)
        The sample values of the rays that hit the volume's box, front to back; NaN outside
        the box.
    inside : ndarray of bool, same shape
        Which samples lie inside the box.
    hit : ndarray of bool, shape (height * width,)
        Which pixels' rays meet the box.
    shape : (int, int)
        (height, width).
    step, unit : float
        h and the unit length :math:`\ell`.

    Raises
    ------
    ValueError
        As :func:`volume_render` for its parameters; for a `value_range` that is not
        increasing or a `lut_size` below 2.

    Examples
    --------
    A uniform block 4 samples deep with opacity 0.5 per unit length, seen along z: the
    central ray crosses a path of length 3; the depth planes every 0.5 from the bounding
    sphere's front put 6 samples inside, each standing for 0.5, so its transmittance is
    :math:`(1 - 0.5)^{6 \cdot 0.5}`, here :func:`volume_render`'s :math:`(1 - 0.5)^3`:

    >>> from course_lib.colormaps import TransferFunction
    >>> tf = TransferFunction([0, 1], [[1, 1, 1, 0.5], [1, 1, 1, 0.5]])
    >>> rays = RaySamples(np.ones((4, 4, 4)), image_size=(3, 3), step=0.5, value_range=(0, 1))
    >>> int(rays.inside.sum(axis=1)[4]), round(1 - float(rays.composite(tf).alpha[1, 1]), 6)
    (6, 0.125)
    """

    def __init__(self, volume, rotation=None, image_size=None, step=None,
                 spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), extent="fit",
                 unit_length=None, value_range=None, lut_size=1024):
        values = _grid(volume, "volume", 3)
        sp = _spacing(spacing, 3)
        org = as_vector(origin, "origin", 3)
        self.unit = float(sp.min()) if unit_length is None else as_positive(unit_length,
                                                                          "unit_length")
        self.step = 0.5 * float(sp.min()) if step is None else as_positive(step, "step")
        if value_range is None:                        # a constant volume: one unit above
            low = float(values.min())
            value_range = (low, max(float(values.max()), low + 1.0))
        lo_value, hi_value = as_vector(value_range, "value_range", 2)
        if not lo_value < hi_value:
            raise ValueError(f"value_range must be (low, high) with low < high, got "
                             f"{tuple(float(x) for x in value_range)}")
        self.value_range = (float(lo_value), float(hi_value))
        self.lut_size = as_whole(lut_size, "lut_size", 2)
        lo, hi, centre, radius, rot, u, v, size = _view_window(values.shape, sp, org, rotation,
                                                               image_size, extent)
        depth = np.arange(radius, -radius - 1e-9, -self.step)          # front to back
        points = (centre + u.reshape(-1, 1, 1) * rot[0] + v.reshape(-1, 1, 1) * rot[1]
                  + depth[None, :, None] * rot[2])
        slack = 1e-9 * radius
        inside = np.all((points >= lo - slack) & (points <= hi + slack), axis=-1)
        self.shape = size
        self.hit = inside.any(axis=1)
        used = inside[self.hit].any(axis=0)                  # drop depths no ray uses
        first, last = np.argmax(used), len(used) - np.argmax(used[::-1])
        inside = inside[self.hit, first:last]
        q = (points[self.hit, first:last] - org) / sp          # index coordinates
        flat = q.reshape(-1, 3)
        samples = _lerp_grid(values.ravel(), values.shape[::-1],
                             [flat[:, 0], flat[:, 1], flat[:, 2]]).reshape(q.shape[:-1])
        self.samples = np.where(inside, samples, np.nan)
        self.inside = inside
        # classification by a lookup table over value_range: each sample's entry is found
        # once here, so a new transfer function costs one gather
        scaled = (samples - lo_value) / (hi_value - lo_value)
        index = np.rint(np.clip(scaled, 0.0, 1.0) * (self.lut_size - 1)).astype(np.intp)
        self._index = np.where(inside, index, self.lut_size)

    def composite(self, transfer, background=(0.0, 0.0, 0.0), termination=0.99):
        """Classify the samples through `transfer` and composite them front to back.

        The transfer function is tabulated at `lut_size` values over `value_range`, the
        opacity correction applied to the table (in single precision), and each sample takes
        the entry nearest to its value.

        Parameters
        ----------
        transfer : str, (color, opacity) or TransferFunction
            As in :func:`volume_render` (a preset or a pair is spread over `value_range`).
        background : (r, g, b)
            Colour behind the volume.
        termination : float in (0, 1]
            The opacity at which early ray termination would stop a ray (for the count).

        Returns
        -------
        VolumeImage
            ``samples`` counts the samples inside the volume that early ray termination at
            opacity `termination` would take, ``samples_saved`` those it would skip.

        Examples
        --------
        >>> rays = RaySamples(np.ones((4, 4, 4)), image_size=(2, 2))
        >>> img = rays.composite("ramp")
        >>> img.rgb.shape, img.samples + img.samples_saved == int(rays.inside.sum())
        ((2, 2, 3), True)
        """
        tf = _rgba_transfer(transfer, np.array(self.value_range))
        bg = as_vector(background, "background", 3)
        threshold = as_scalar(termination, "termination")
        if not 0 < threshold <= 1:
            raise ValueError(f"termination must lie in (0, 1], got {threshold:g}")
        n = self.lut_size
        table = np.zeros((n + 1, 4), np.float32)       # the last row: outside, empty
        table[:-1] = tf.lookup_table(n, self.value_range)
        table[:-1, 3] = 1.0 - (1.0 - table[:-1, 3]) ** (self.step / self.unit)  # per step
        alpha = table[:, 3][self._index]
        through = np.cumprod(1.0 - alpha, axis=1)                 # T after each sample
        before = np.ones_like(through)
        before[:, 1:] = through[:, :-1]
        weight = before * alpha
        color = np.stack([(weight * table[:, c][self._index]).sum(axis=1) for c in range(3)],
                         axis=1).astype(float)
        opacity = (1.0 - through[:, -1]).astype(float)
        saved = int((self.inside & (before <= 1.0 - threshold)).sum())
        pixels = int(np.prod(self.shape))
        out_c, out_a = np.zeros((pixels, 3)), np.zeros(pixels)
        out_c[self.hit], out_a[self.hit] = color, opacity
        rgb = out_c + (1.0 - out_a)[:, None] * bg
        return VolumeImage(rgb.reshape(*self.shape, 3), out_a.reshape(self.shape),
                           int(self.inside.sum()) - saved, saved)


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
    as_choice(order, "order", ("front-to-back", "back-to-front"))
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
