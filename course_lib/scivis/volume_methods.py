r"""Chapter 18 (lesson section 4): volume rendering beyond ray casting, and gradient normals.

Ray casting (:func:`~course_lib.scivis.volume_render`) walks along one ray per pixel. The same
integral of colour and opacity along the view direction can be computed in other orders:

* **Splatting** (object order, Westover 1990), :func:`splat_render`: every voxel is classified
  (value -> colour, opacity), then thrown at the image as a **footprint**, the integral along the
  view direction of its reconstruction kernel. For a 3D Gaussian of width :math:`\sigma` the
  footprint is a 2D Gaussian, :math:`F(r) = e^{-r^2 / 2\sigma^2} / (2\pi\sigma^2)`, the same for
  every voxel and every view (orthographic), so it is tabulated once. The voxels are gathered
  in **sheets** of constant view depth; inside a sheet the footprints add up (optical depth),
  and the sheets are composited in depth order. The order matters: back to front with the
  *over* operator, or front to back with the *under* operator (the one of ray casting); the
  wrong pairing shows the volume as if seen from behind.
* **Texture-based slicing** (the GPU method), :func:`slice_render`: the volume is resampled on a
  stack of planes, either **view-aligned** (perpendicular to the view direction, trilinear
  interpolation, any spacing) or **axis-aligned** (the volume's own sample planes along the axis
  nearest the view direction, bilinear interpolation inside each plane), and the planes are
  composited. A plane stands for a slab of thickness :math:`\Delta` along the ray, so its
  opacities are corrected, :math:`\alpha_\Delta = 1 - (1 - \alpha)^{\Delta / \ell}`.
  View-aligned slices are ray casting with all rays sampled on common planes: as the spacing
  shrinks, both converge to the same integral.
* **Shear-warp** (Lacroute and Levoy 1994), :func:`shear_warp`: the axis-aligned slices are
  sheared so that the view rays become perpendicular to them, composited in that sheared space
  (the *intermediate image*, on the slices' own grid) with 2D resampling only, and the result is
  warped once to the final image. The real method's speed comes from run-length encoding
  (skipping empty voxels and opaque pixels), which we leave out.
* **Pre- versus post-classification**: classify the voxels, then interpolate their colours
  and opacities (``classification="pre"``; interpolate the opacity-weighted colours
  :math:`\alpha c`, or colours bleed), or interpolate the values, then classify
  (``"post"``). They agree when the transfer function is linear in the value (interpolation
  and classification commute); with a sharp transfer function, pre-classification smears the
  sharp step over a whole cell and shows the grid as blocky rims, while post-classification
  finds the step inside the cell.

:func:`compare_renderers` renders one volume with one transfer function by all three methods
and reports the images, times and differences to ray casting.

**Gradients as normals.** The gradient by central differences (:func:`~course_lib.scivis.gradient`:
:math:`(f_{i+1} - f_{i-1}) / 2h` inside, the one-sided :math:`(f_1 - f_0)/h` at the borders,
as ``numpy.gradient`` with ``edge_order=1``) is perpendicular to the isosurfaces.
:func:`isosurface_normals` interpolates it to marching-cubes vertices (trilinearly, which on a
cell edge is linear along the edge) and turns it into unit normals pointing to lower values
(outward, as the triangles' winding); :func:`gradient_shading` shades volume samples with it
(Lambert plus optional Phong highlight), and :func:`gradient_opacity` modulates opacity by the
gradient magnitude (boundaries stand out, homogeneous regions fade).

Conventions as in :mod:`course_lib.scivis`: ``volume[k, j, i]`` is at
:math:`(x_0 + i\Delta x, y_0 + j\Delta y, z_0 + k\Delta z)`; images have row 0 at the bottom; the
eye looks down :math:`-z` of the view frame :math:`q = R (p - \text{centre})`. The image window
defaults to ``extent="sphere"`` (the same for every rotation).
"""

import time
from typing import NamedTuple

import numpy as np

from .._validate import as_choice, as_positive, as_scalar, as_unit_vector, as_vector
from ._common import _grid, _spacing
from .grids import _lerp_grid
from .isosurfaces import gradient
from .volume_rendering import _rgba_transfer, _view_window, volume_render

__all__ = ["Comparison", "classify", "compare_renderers",
    "gradient_opacity", "gradient_shading", "isosurface_normals", "shear_warp", "slice_render",
    "splat_render"]



# ---------------------------------------------------------------------------------------------
# Gradient normals and shading
# ---------------------------------------------------------------------------------------------

def isosurface_normals(volume, vertices, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0)):
    r"""Unit normals at isosurface vertices from the volume's central-difference gradient.

    The gradient is computed at the samples (:func:`~course_lib.scivis.gradient`: central
    differences inside, one-sided at the borders), interpolated trilinearly to each vertex and
    normalized; :math:`\mathbf n = -\nabla f / |\nabla f|` points towards lower values, out of
    the region :math:`f \ge c` (the orientation of :func:`~course_lib.scivis.marching_cubes`'
    triangles).

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
    vertices : array_like, shape (n, 3)
        Points (x, y, z), e.g. from :func:`~course_lib.scivis.marching_cubes`.
    spacing, origin : tuple of float
        The volume's geometry (x, y, z).

    Returns
    -------
    ndarray, shape (n, 3)
        Unit normals; a vertex where the interpolated gradient vanishes gets the zero vector.

    Raises
    ------
    ValueError
        For a non-3D volume, NaN, a non-positive spacing or vertices not of shape (n, 3).

    Examples
    --------
    :math:`f = z` on a 3-sample cube: the normal is :math:`-\hat z` everywhere.

    >>> vol = np.broadcast_to(np.arange(3.0)[:, None, None], (3, 3, 3))
    >>> isosurface_normals(vol, [[1.0, 1.0, 0.5]])
    array([[ 0.,  0., -1.]])
    """
    v = _grid(volume, "volume", 3)
    sp = _spacing(spacing, 3)
    org = as_vector(origin, "origin", 3)
    p = np.asarray(vertices, dtype=float)
    if p.ndim != 2 or p.shape[1] != 3 or not np.isfinite(p).all():
        raise ValueError(f"vertices must be finite points of shape (n, 3), got shape {p.shape}")
    g = gradient(v, sp).reshape(-1, 3)
    q = (p - org) / sp
    at = _lerp_grid(g, v.shape[::-1], [q[:, 0], q[:, 1], q[:, 2]])
    length = np.linalg.norm(at, axis=1, keepdims=True)
    return np.where(length > 0, -at / np.where(length > 0, length, 1.0), 0.0) + 0.0


def gradient_shading(colors, gradients, light=(0.0, 0.0, 1.0), view=(0.0, 0.0, 1.0),
                     ambient=0.3, diffuse=0.7, specular=0.0, shininess=16.0):
    r"""Shade volume samples with their gradient as normal: Lambert plus an optional highlight.

    :math:`c' = c\,(k_a + k_d\,|\mathbf n \cdot \mathbf L|) + k_s\,|\mathbf n \cdot \mathbf H|^s`
    with :math:`\mathbf n = \nabla f / |\nabla f|` and the halfway vector
    :math:`\mathbf H = (\mathbf L + \mathbf V)/|\mathbf L + \mathbf V|`. Two-sided (absolute
    values): inside a volume a boundary is seen from either side. A zero gradient (a
    homogeneous region, no surface) gets the ambient and diffuse terms as if lit head on.

    Parameters
    ----------
    colors : array_like, shape (..., 3)
    gradients : array_like, shape (..., 3)
    light, view : (3,) vectors
        Directions towards the light and the eye (normalized here).
    ambient, diffuse, specular, shininess : float
        :math:`k_a, k_d, k_s \ge 0` and the exponent :math:`s > 0`.

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> gradient_shading([[1.0, 0.5, 0.0]], [[0.0, 0.0, -2.0]], light=(0, 0.6, 0.8))
    array([[0.86, 0.43, 0.  ]])
    """
    c = np.asarray(colors, dtype=float)
    g = np.asarray(gradients, dtype=float)
    if c.shape[-1:] != (3,) or g.shape != c.shape:
        raise ValueError(f"colors and gradients must both have shape (..., 3), got {c.shape} "
                         f"and {g.shape}")
    L, V = as_unit_vector(light, "light"), as_unit_vector(view, "view")
    for name, k in (("ambient", ambient), ("diffuse", diffuse), ("specular", specular)):
        if as_scalar(k, name) < 0:
            raise ValueError(f"{name} must be >= 0, got {k}")
    s = as_positive(shininess, "shininess")
    length = np.linalg.norm(g, axis=-1)
    n = g / np.where(length > 0, length, 1.0)[..., None]
    lambert = np.where(length > 0, np.abs(n @ L), 1.0)
    out = c * (ambient + diffuse * lambert)[..., None]
    if specular > 0:
        h = (L + V) / max(np.linalg.norm(L + V), 1e-12)
        out = out + (specular * np.abs(n @ h) ** s * (length > 0))[..., None]
    return out


def gradient_opacity(alphas, gradients, scale):
    r"""Opacity modulated by the gradient magnitude: :math:`\alpha \min(1, |\nabla f| / g_0)`.

    Homogeneous regions (small gradient) fade; boundaries between materials stand out
    (Levoy 1988).

    Parameters
    ----------
    alphas : array_like, shape (...)
    gradients : array_like, shape (..., 3)
    scale : float
        :math:`g_0 > 0`, the gradient magnitude from which the opacity is kept whole.

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> gradient_opacity([0.8, 0.8], [[0, 0, 0.5], [0, 3, 4]], scale=1.0)
    array([0.4, 0.8])
    """
    a = np.asarray(alphas, dtype=float)
    g = np.asarray(gradients, dtype=float)
    if g.shape != a.shape + (3,):
        raise ValueError(f"gradients must have shape alphas.shape + (3,) = {a.shape + (3,)}, "
                         f"got {g.shape}")
    g0 = as_positive(scale, "scale")
    return a * np.minimum(1.0, np.linalg.norm(g, axis=-1) / g0)


# ---------------------------------------------------------------------------------------------
# Classification
# ---------------------------------------------------------------------------------------------

def classify(volume, transfer="ramp"):
    """Classify every voxel: its value -> (r, g, b, opacity) through the transfer function.

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
    transfer : str, (color, opacity) or TransferFunction
        As in :func:`~course_lib.scivis.volume_render` (a preset spans the volume's range).

    Returns
    -------
    ndarray, shape (nz, ny, nx, 4)
        Colours and opacities (per unit length), not premultiplied.

    Examples
    --------
    >>> classify(np.linspace(0, 1, 8).reshape(2, 2, 2), "ramp")[1, 1, 1]
    array([1., 1., 1., 1.])
    """
    v = _grid(volume, "volume", 3)
    tf = _rgba_transfer(transfer, v)
    return tf._evaluate(v.ravel(), "right").reshape(v.shape + (4,))


# ---------------------------------------------------------------------------------------------
# Shared: geometry and the compositing of layers
# ---------------------------------------------------------------------------------------------

def _vm_setup(volume, spacing, origin, rotation, image_size, extent):
    v = _grid(volume, "volume", 3)
    sp = _spacing(spacing, 3)
    org = as_vector(origin, "origin", 3)
    lo, hi, centre, radius, rot, u, w, size = _view_window(v.shape, sp, org, rotation,
                                                           image_size, extent)
    return v, sp, org, lo, hi, centre, radius, rot, u.ravel(), w.ravel(), size


def _vm_unit(unit_length, sp):
    return float(sp.min()) if unit_length is None else as_positive(unit_length, "unit_length")


def _vm_operator(order, operator):
    as_choice(order, "order", ("front-to-back", "back-to-front"))
    natural = "under" if order == "front-to-back" else "over"
    if operator is None:
        return natural
    return as_choice(operator, "operator", ("over", "under"))


def _vm_layer(state, color, alpha, operator):
    """Composite one layer (premultiplied colour `color`, opacity `alpha`) into `state`."""
    C, A = state
    if operator == "under":                      # the new layer lies behind what is there
        return C + (1.0 - A)[:, None] * color, A + (1.0 - A) * alpha
    return color + (1.0 - alpha)[:, None] * C, alpha + (1.0 - alpha) * A   # in front


class _VmImage(NamedTuple):
    rgb: np.ndarray
    alpha: np.ndarray
    layers: int


def _vm_finish(C, A, background, size):
    bg = as_vector(background, "background", 3)
    rgb = C + (1.0 - A)[:, None] * bg
    return _VmImage(rgb.reshape(size[0], size[1], 3), A.reshape(size), 0)


# ---------------------------------------------------------------------------------------------
# Texture-based slicing
# ---------------------------------------------------------------------------------------------

def slice_render(volume, transfer="ramp", rotation=None, image_size=None, slice_spacing=None,
                 spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), extent="sphere",
                 slices="view", classification="post", background=(0.0, 0.0, 0.0),
                 unit_length=None, light=None, gradient_scale=None):
    r"""Direct volume rendering by texture-based slicing, composited front to back.

    The volume is resampled on a stack of planes and the planes are composited like layers of
    paint, front to back, :math:`C \leftarrow C + (1 - A)\,\alpha' c`,
    :math:`A \leftarrow A + (1 - A)\,\alpha'`, with the opacity of a plane standing for a
    slab of thickness :math:`\Delta` along the ray corrected,
    :math:`\alpha' = 1 - (1 - \alpha)^{\Delta / \ell}`.

    * ``slices="view"``: planes of constant view depth every `slice_spacing`, from the front of
      the volume's bounding sphere, sampled by trilinear interpolation (a 3D texture). Each
      stands for :math:`\Delta` = `slice_spacing`.
    * ``slices="axis"``: the volume's own sample planes perpendicular to the axis nearest the
      view direction (2D textures), sampled bilinearly where each ray crosses them. A ray at
      angle :math:`\theta` to that axis crosses planes :math:`h/\cos\theta` apart: that is its
      :math:`\Delta` (`slice_spacing` is ignored; the first and last plane stand for half a
      slab each, the trapezoid rule). This is what shear-warp composites.

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
    transfer : str, (color, opacity) or TransferFunction
        As in :func:`~course_lib.scivis.volume_render`.
    rotation : array_like, shape (3, 3), optional
        View rotation (:func:`~course_lib.scivis.view_rotation`).
    image_size : (int, int), optional
        (height, width), default one pixel per smallest spacing.
    slice_spacing : float, optional
        Distance between view-aligned slices, > 0; default half the smallest spacing.
    spacing, origin : tuple of float
        The volume's geometry.
    extent : "sphere", "fit" or (umin, umax, vmin, vmax)
        The image window, as in :func:`~course_lib.scivis.volume_render` (default "sphere").
    slices : {"view", "axis"}
    classification : {"post", "pre"}
        "post": interpolate the values, then classify; "pre": classify the voxels, then
        interpolate the opacity-weighted colours :math:`\alpha c` and the opacities.
    background : (r, g, b)
    unit_length : float, optional
        Thickness for which the transfer function's opacity holds (default the smallest
        spacing).
    light : (3,) vector, optional
        Direction towards a light in the volume's frame: shade each sample with its
        interpolated central-difference gradient (:func:`gradient_shading`, two-sided Lambert).
    gradient_scale : float, optional
        If given, modulate the opacity by the gradient magnitude (:func:`gradient_opacity`).

    Returns
    -------
    result : NamedTuple
        ``rgb`` (height, width, 3), ``alpha`` (height, width), ``layers`` (slices composited).

    Raises
    ------
    ValueError
        For a bad volume (not 3D, NaN), a non-positive spacing, slice spacing or unit length,
        an unknown `slices` or `classification`.

    Examples
    --------
    A uniform block 4 samples deep with opacity 0.5 per unit length, seen along z: the path
    through it is 3 long, so :math:`1 - A = 0.5^3` with either kind of slices:

    >>> from course_lib.colormaps import TransferFunction
    >>> tf = TransferFunction([0, 1], [[1, 1, 1, 0.5], [1, 1, 1, 0.5]])
    >>> for kind in ("view", "axis"):
    ...     img = slice_render(np.ones((4, 4, 4)), tf, image_size=(3, 3), extent="fit",
    ...                        slice_spacing=0.25, slices=kind)
    ...     print(kind, round(1 - float(img.alpha[1, 1]), 6))
    view 0.125
    axis 0.125
    """
    v, sp, org, lo, hi, centre, radius, rot, u, w, size = _vm_setup(
        volume, spacing, origin, rotation, image_size, extent)
    as_choice(slices, "slices", ("view", "axis"))
    as_choice(classification, "classification", ("post", "pre"))
    tf = _rgba_transfer(transfer, v)
    unit = _vm_unit(unit_length, sp)
    step = 0.5 * float(sp.min()) if slice_spacing is None else as_positive(slice_spacing,
                                                                           "slice_spacing")
    dims = v.shape[::-1]
    flat = v.ravel()
    if classification == "pre":
        rgba = tf._evaluate(flat, "right")
        flat_rgba = np.concatenate([rgba[:, :3] * rgba[:, 3:], rgba[:, 3:]], axis=1)
    grads = None
    if light is not None or gradient_scale is not None:
        grads = gradient(v, sp).reshape(-1, 3)
        L = as_unit_vector(light, "light") if light is not None else None
        g0 = as_positive(gradient_scale, "gradient_scale") if gradient_scale is not None \
            else None
    base = centre + u[:, None] * rot[0] + w[:, None] * rot[1]          # (p, 3) on depth 0
    slack = 1e-9 * max(radius, 1.0)
    if slices == "view":
        depths = np.arange(radius, -radius - 1e-9, -step)
        planes = [(base + d * rot[2], step) for d in depths]
    else:
        axis = int(np.argmax(np.abs(rot[2])))
        cos = float(rot[2][axis])
        n_axis = dims[axis]
        order = range(n_axis - 1, -1, -1) if cos > 0 else range(n_axis)   # front first
        thick = float(sp[axis]) / abs(cos)
        planes = []
        for m in order:
            t = (org[axis] + m * sp[axis] - base[:, axis]) / cos
            p = base + t[:, None] * rot[2]
            p[:, axis] = org[axis] + m * sp[axis]                     # exactly on the plane
            planes.append((p, thick * (0.5 if m in (0, n_axis - 1) else 1.0)))
    C, A = np.zeros((len(u), 3)), np.zeros(len(u))
    for p, delta in planes:
        inside = np.all((p >= lo - slack) & (p <= hi + slack), axis=1)
        if not inside.any():
            continue
        q = (p[inside] - org) / sp
        idx = [q[:, 0], q[:, 1], q[:, 2]]
        if classification == "post":
            rgba = tf._evaluate(_lerp_grid(flat, dims, idx), "right")
            color, alpha = rgba[:, :3], rgba[:, 3]
        else:
            pm = _lerp_grid(flat_rgba, dims, idx)
            alpha = pm[:, 3]
            color = pm[:, :3] / np.where(alpha > 0, alpha, 1.0)[:, None]
        if grads is not None:
            g = _lerp_grid(grads, dims, idx)
            if L is not None:
                color = gradient_shading(color, g, light=L)
            if g0 is not None:
                alpha = gradient_opacity(alpha, g, g0)
        a = 1.0 - (1.0 - np.clip(alpha, 0.0, 1.0)) ** (delta / unit)
        full_c, full_a = np.zeros((len(u), 3)), np.zeros(len(u))
        full_c[inside], full_a[inside] = a[:, None] * color, a
        C, A = _vm_layer((C, A), full_c, full_a, "under")
    return _vm_finish(C, A, background, size)._replace(layers=len(planes))


def shear_warp(volume, transfer="ramp", rotation=None, image_size=None,
               spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), extent="sphere",
               background=(0.0, 0.0, 0.0), unit_length=None):
    r"""Shear-warp volume rendering (orthographic): composite sheared slices, then warp.

    With the principal axis a (the volume axis most parallel to the view direction
    :math:`\mathbf d`), the ray through a point :math:`(b, c)` of the first slice meets slice m
    (at :math:`x_a = x_{a,0} + m h_a`) at :math:`(b + m h_a d_b/d_a,\; c + m h_a d_c/d_a)`: each
    slice is only *translated* (the shear) relative to the first. The slices are resampled
    bilinearly on one 2D grid with the voxel spacing (the intermediate image), post-classified,
    opacity-corrected for the path :math:`h_a / |d_a|` between slices (half at the first and
    last slice) and composited front to back there. The **warp** then maps each final pixel to
    the point where its ray meets the first slice's plane and samples the intermediate image
    bilinearly: one 2D resampling for the whole image.

    Parameters
    ----------
    volume, transfer, rotation, image_size, spacing, origin, extent, background, unit_length
        As in :func:`slice_render`.

    Returns
    -------
    result : NamedTuple
        ``rgb`` (height, width, 3), ``alpha`` (height, width), ``layers`` (slices).

    Raises
    ------
    ValueError
        For a bad volume or a non-positive spacing or unit length.

    Examples
    --------
    A uniform block seen along z, opacity 0.5 per unit: transmittance :math:`0.5^3`:

    >>> from course_lib.colormaps import TransferFunction
    >>> tf = TransferFunction([0, 1], [[1, 1, 1, 0.5], [1, 1, 1, 0.5]])
    >>> img = shear_warp(np.ones((4, 4, 4)), tf, image_size=(3, 3), extent="fit")
    >>> round(1 - float(img.alpha[1, 1]), 6)
    0.125
    """
    v, sp, org, lo, hi, centre, radius, rot, u, w, size = _vm_setup(
        volume, spacing, origin, rotation, image_size, extent)
    tf = _rgba_transfer(transfer, v)
    unit = _vm_unit(unit_length, sp)
    d = rot[2]
    a = int(np.argmax(np.abs(d)))
    b, c = [k for k in range(3) if k != a]
    dims = v.shape[::-1]
    n_a = dims[a]
    k_b, k_c = d[b] / d[a], d[c] / d[a]
    reach = (n_a - 1) * sp[a]
    b0 = lo[b] - max(0.0, reach * k_b)
    c0 = lo[c] - max(0.0, reach * k_c)
    nb = int(np.ceil((hi[b] - min(0.0, reach * k_b) - b0) / sp[b] + 1e-9)) + 1
    nc = int(np.ceil((hi[c] - min(0.0, reach * k_c) - c0) / sp[c] + 1e-9)) + 1
    gb, gc = np.meshgrid(b0 + sp[b] * np.arange(nb), c0 + sp[c] * np.arange(nc))
    gb, gc = gb.ravel(), gc.ravel()
    flat = v.ravel()
    C, A = np.zeros((len(gb), 3)), np.zeros(len(gb))
    order = range(n_a - 1, -1, -1) if d[a] > 0 else range(n_a)          # front first
    thick = float(sp[a]) / abs(float(d[a]))
    slack = 1e-9
    for m in order:
        idx = [None, None, None]
        idx[a] = np.full(len(gb), float(m))
        idx[b] = (gb + m * sp[a] * k_b - org[b]) / sp[b]                  # the shear
        idx[c] = (gc + m * sp[a] * k_c - org[c]) / sp[c]
        inside = ((idx[b] >= -slack) & (idx[b] <= dims[b] - 1 + slack)
                  & (idx[c] >= -slack) & (idx[c] <= dims[c] - 1 + slack))
        rgba = tf._evaluate(_lerp_grid(flat, dims, idx), "right")
        delta = thick * (0.5 if m in (0, n_a - 1) else 1.0)
        alpha = np.where(inside, 1.0 - (1.0 - np.clip(rgba[:, 3], 0, 1)) ** (delta / unit), 0.0)
        C, A = _vm_layer((C, A), alpha[:, None] * rgba[:, :3], alpha, "under")
    # the warp: final pixel -> where its ray meets the plane of slice 0 -> intermediate image
    base = centre + u[:, None] * rot[0] + w[:, None] * rot[1]
    t = (org[a] - base[:, a]) / d[a]
    hit = base + t[:, None] * d
    ib, ic = (hit[:, b] - b0) / sp[b], (hit[:, c] - c0) / sp[c]
    inside = (ib >= -slack) & (ib <= nb - 1 + slack) & (ic >= -slack) & (ic <= nc - 1 + slack)
    layers = np.concatenate([C, A[:, None]], axis=1)
    warped = _lerp_grid(layers, (nb, nc), [ib, ic]) * inside[:, None]
    return _vm_finish(warped[:, :3], warped[:, 3], background, size)._replace(layers=n_a)


# ---------------------------------------------------------------------------------------------
# Splatting
# ---------------------------------------------------------------------------------------------

def splat_render(volume, transfer="ramp", rotation=None, image_size=None, kernel_radius=1.5,
                 spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), extent="sphere",
                 order="back-to-front", operator=None, sheet_thickness=None,
                 background=(0.0, 0.0, 0.0), unit_length=None):
    r"""Direct volume rendering by splatting Gaussian footprints, sheet by sheet.

    Each voxel i is classified (colour :math:`c_i`, opacity :math:`\alpha_i` per unit length
    :math:`\ell`, i.e. extinction :math:`\tau_i = -\ln(1 - \alpha_i)/\ell`) and reconstructed
    by a 3D Gaussian of width :math:`\sigma` = `kernel_radius` / 3 (in units of the smallest
    spacing, truncated at the radius). Integrated along the view direction, the Gaussian is
    the 2D **footprint** :math:`F(r) = e^{-r^2/2\sigma^2}/(2\pi\sigma^2)`, the same for all
    voxels. Voxels are sorted into **sheets** of constant view depth (`sheet_thickness` thick);
    in a sheet the footprints add up to an optical depth
    :math:`\kappa = \sum_i \tau_i V F(|x - x_i|)` (V the voxel volume) per pixel, giving the
    sheet opacity :math:`1 - e^{-\kappa}` and the :math:`\tau F`-weighted mean colour. The
    sheets are composited in depth `order` with the `operator` that fits it ("over" back to
    front: :math:`C \leftarrow c + (1 - \alpha) C`; "under" front to back:
    :math:`C \leftarrow C + (1 - A) c`, premultiplied colours). Both give the same picture;
    the other pairing reverses the depth order (the volume seen from behind).

    Splatting classifies before it reconstructs: it is a pre-classified method.

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
    transfer : str, (color, opacity) or TransferFunction
        As in :func:`~course_lib.scivis.volume_render`.
    rotation : array_like, shape (3, 3), optional
    image_size : (int, int), optional
    kernel_radius : float
        The footprint's radius in units of the smallest spacing, > 0 (default 1.5; much
        below 1.2 the kernels no longer overlap enough and the grid shows).
    spacing, origin : tuple of float
    extent : "sphere", "fit" or (umin, umax, vmin, vmax)
    order : {"back-to-front", "front-to-back"}
        The order in which sheets are composited.
    operator : {None, "over", "under"}
        None: the operator that fits `order`; give the other one to see the mistake.
    sheet_thickness : float, optional
        Depth of a sheet, > 0; default the smallest spacing.
    background : (r, g, b)
    unit_length : float, optional

    Returns
    -------
    result : NamedTuple
        ``rgb`` (height, width, 3), ``alpha`` (height, width), ``layers`` (sheets).

    Raises
    ------
    ValueError
        For a bad volume, a non-positive spacing, kernel radius or sheet thickness, an unknown
        order or operator.

    Examples
    --------
    One opaque-ish voxel in the middle of an empty volume: its splat is brightest at the
    centre pixel and falls off as a Gaussian; back to front and front to back agree:

    >>> vol = np.zeros((5, 5, 5)); vol[2, 2, 2] = 1.0
    >>> a = splat_render(vol, "ramp", image_size=(5, 5), extent="fit").alpha
    >>> b = splat_render(vol, "ramp", image_size=(5, 5), extent="fit",
    ...                  order="front-to-back").alpha
    >>> int(np.argmax(a)), bool(np.allclose(a, b)), bool(a[2, 2] > a[2, 3] > a[2, 4])
    (12, True, True)
    """
    v, sp, org, lo, hi, centre, radius, rot, u, w, size = _vm_setup(
        volume, spacing, origin, rotation, image_size, extent)
    r = as_positive(kernel_radius, "kernel_radius")
    op = _vm_operator(order, operator)
    unit = _vm_unit(unit_length, sp)
    thick = float(sp.min()) if sheet_thickness is None else as_positive(sheet_thickness,
                                                                         "sheet_thickness")
    tf = _rgba_transfer(transfer, v)
    rgba = tf._evaluate(v.ravel(), "right")
    alpha = np.clip(rgba[:, 3], 0.0, 1.0 - 1e-9)
    tau = -np.log1p(-alpha) / unit
    keep = np.flatnonzero(tau > 0)
    height, width = size
    C, A = np.zeros((height * width, 3)), np.zeros(height * width)
    if len(keep) == 0:
        return _vm_finish(C, A, background, size)
    k, j, i = np.unravel_index(keep, v.shape)
    points = org + sp * np.stack([i, j, k], axis=1)
    q = (points - centre) @ rot.T                     # view coordinates (u, v, depth)
    u0, u1, v0, v1 = u.min(), u.max(), w.min(), w.max()
    du = (u1 - u0) / max(width - 1, 1) if width > 1 else 1.0
    dv = (v1 - v0) / max(height - 1, 1) if height > 1 else 1.0
    col, row = (q[:, 0] - u0) / du, (q[:, 1] - v0) / dv
    sigma = r * float(sp.min()) / 3.0
    reach = r * float(sp.min())
    ox = np.arange(-int(np.ceil(reach / du)) - 1, int(np.ceil(reach / du)) + 2)
    oy = np.arange(-int(np.ceil(reach / dv)) - 1, int(np.ceil(reach / dv)) + 2)
    offx, offy = [a.ravel() for a in np.meshgrid(ox, oy)]
    mass = 1.0 - np.exp(-reach ** 2 / (2 * sigma ** 2))   # the truncated Gaussian's 2D mass
    weight = tau[keep] * float(np.prod(sp))                # tau_i V
    colors = rgba[keep, :3]
    sheet = np.floor((radius + sp.max() - q[:, 2]) / thick).astype(np.intp)   # 0 = front
    by_sheet = np.argsort(sheet, kind="stable")
    bounds = np.searchsorted(sheet[by_sheet], np.arange(sheet.max() + 2))
    sheets = range(sheet.max() + 1) if order == "front-to-back" else range(sheet.max(), -1, -1)
    pixels = height * width
    for s in sheets:
        ids = by_sheet[bounds[s]:bounds[s + 1]]
        if len(ids) == 0:
            continue
        px = np.rint(col[ids])[:, None].astype(np.intp) + offx
        py = np.rint(row[ids])[:, None].astype(np.intp) + offy
        d2 = ((u0 + px * du - q[ids, 0, None]) ** 2 + (v0 + py * dv - q[ids, 1, None]) ** 2)
        ok = (d2 <= reach ** 2) & (px >= 0) & (px < width) & (py >= 0) & (py < height)
        foot = np.exp(-d2 / (2 * sigma ** 2)) / (2 * np.pi * sigma ** 2 * mass)
        kappa_i = (weight[ids, None] * foot)[ok]
        target = (py * width + px)[ok]
        kappa = np.bincount(target, kappa_i, minlength=pixels)
        tinted = np.stack([np.bincount(target, kappa_i * np.broadcast_to(
            colors[ids, c, None], ok.shape)[ok], minlength=pixels) for c in range(3)], axis=1)
        a = -np.expm1(-kappa)
        mean_c = tinted / np.where(kappa > 0, kappa, 1.0)[:, None]
        C, A = _vm_layer((C, A), a[:, None] * mean_c, a, op)
    return _vm_finish(C, A, background, size)._replace(layers=len(sheets))


# ---------------------------------------------------------------------------------------------
# Comparison
# ---------------------------------------------------------------------------------------------

class Comparison(NamedTuple):
    """The result of :func:`compare_renderers`.

    Attributes
    ----------
    images : dict
        Method name ("ray casting", "slicing", "splatting") -> rgb (height, width, 3).
    times : dict
        Method name -> seconds (one run, wall clock).
    differences : dict
        Method name -> mean absolute difference to ray casting over all pixels and channels.

    Examples
    --------
    >>> c = compare_renderers(np.ones((4, 4, 4)), image_size=(4, 4))
    >>> sorted(c.images), c.differences["ray casting"]
    (['ray casting', 'slicing', 'splatting'], 0.0)
    """
    images: dict
    times: dict
    differences: dict


def compare_renderers(volume, transfer="ramp", rotation=None, image_size=(64, 64),
                      spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), step=None,
                      kernel_radius=1.5, slices="view", classification="post"):
    """Render one volume with one transfer function by ray casting, slicing and splatting.

    The same view window (``extent="sphere"``), image size and unit length for all three; ray
    casting and slicing sample every `step` (default half the smallest spacing), without
    early ray termination, so that the comparison is of the methods, not of their shortcuts.

    Parameters
    ----------
    volume, transfer, rotation, image_size, spacing, origin
        As in :func:`~course_lib.scivis.volume_render`.
    step : float, optional
        The ray-casting step and the view-aligned slice spacing.
    kernel_radius : float
        The splats' radius (:func:`splat_render`).
    slices, classification : str
        Passed to :func:`slice_render`.

    Returns
    -------
    Comparison
        ``images``, ``times`` (seconds) and ``differences`` (mean absolute difference to ray
        casting) keyed by "ray casting", "slicing", "splatting".

    Examples
    --------
    >>> from course_lib.scivis import example_volume
    >>> blobs = example_volume("blobs", size=16)
    >>> c = compare_renderers(blobs.values, spacing=blobs.spacing, origin=blobs.origin,
    ...                       image_size=(16, 16))
    >>> c.differences["slicing"] < 0.02
    True
    """
    geometry = dict(rotation=rotation, image_size=image_size, spacing=spacing, origin=origin,
                    extent="sphere")
    runs = {
        "ray casting": lambda: volume_render(volume, transfer, step=step,
                                             early_termination=None, **geometry).rgb,
        "slicing": lambda: slice_render(volume, transfer, slice_spacing=step, slices=slices,
                                        classification=classification, **geometry).rgb,
        "splatting": lambda: splat_render(volume, transfer, kernel_radius=kernel_radius,
                                          **geometry).rgb,
    }
    images, times = {}, {}
    for name, run in runs.items():
        start = time.perf_counter()
        images[name] = run()
        times[name] = time.perf_counter() - start
    ref = images["ray casting"]
    differences = {name: float(np.abs(img - ref).mean()) for name, img in images.items()}
    return Comparison(images, times, differences)
