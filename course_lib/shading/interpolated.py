"""Chapter 12 (lesson section 5): vertex normals and flat, Gouraud and Phong shading of meshes."""

from typing import NamedTuple

import numpy as np

from .. import visibility
from .._validate import (as_choice, as_matrix, as_mesh, as_points, as_positive, as_rgb,
    as_vector, as_whole)
from ..mesh.geometry import face_cross_products, face_normals   # re-exported: the one face normal
from ._common import _dot
from .illumination import blinn_phong, _lights, phong
from .materials import Material

__all__ = ["BarycentricBuffers", "ShadedImage", "barycentric_buffers", "face_normals",
    "render_shaded", "uv_sphere", "vertex_normals"]


# ---------------------------------------------------------------------------------------------
# Meshes: normals and interpolated shading
# ---------------------------------------------------------------------------------------------



def vertex_normals(vertices, faces):
    r"""Vertex normals: the area-weighted average of the normals of the faces around a vertex.

    .. math:: N_v = \frac{\sum_{f \ni v} A_f \hat N_f}{\lVert \sum_{f \ni v} A_f \hat N_f \rVert}
              , \qquad A_f \hat N_f = \tfrac12 (v_1 - v_0) \times (v_2 - v_0)

    so summing the raw cross products (:func:`course_lib.mesh.face_cross_products`) does the
    weighting (big faces count more, slivers little). Used by Gouraud and Phong shading to make
    a faceted mesh look smooth. A vertex that belongs to no face (or whose faces' normals
    cancel) gets the zero vector.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)

    Returns
    -------
    ndarray, shape (n, 3)

    Raises
    ------
    ValueError
        For malformed vertices or faces.

    Examples
    --------
    The apex of a square pyramid: the four sloped faces average to straight up:

    >>> v = [[0, 0, 1], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]]
    >>> f = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    >>> vertex_normals(v, f)[0]
    array([0., 0., 1.])
    """
    v, f = as_mesh(vertices, faces)
    c = face_cross_products(v, f)
    acc = np.zeros_like(v)
    for k in range(3):
        np.add.at(acc, f[:, k], c)
    length = np.sqrt(_dot(acc, acc))
    scale = 1e-12 * max(float(np.sqrt(_dot(c, c)).max()), 1e-300)
    return np.divide(acc, length[:, None], out=np.zeros_like(acc),
                     where=length[:, None] > scale)


def uv_sphere(radius=1.0, segments=32, rings=16, center=(0.0, 0.0, 0.0)):
    """A triangle mesh of a sphere by longitude (segments) and latitude (rings), poles on y.

    The mesh to try the shading methods on: its vertices lie exactly on the sphere, so the
    exact normal at a vertex is ``(vertex - center) / radius``.

    Parameters
    ----------
    radius : float
    segments : int
        Divisions around the y axis (at least 3).
    rings : int
        Divisions from pole to pole (at least 2).
    center : array_like, shape (3,)

    Returns
    -------
    vertices : ndarray, shape (segments * (rings - 1) + 2, 3)
    faces : ndarray of int, shape (2 * segments * (rings - 1), 3)
        Counter-clockwise seen from outside.

    Raises
    ------
    ValueError
        For a non-positive radius or too few divisions.

    Examples
    --------
    >>> v, f = uv_sphere(segments=8, rings=4)
    >>> v.shape, f.shape, bool(np.allclose(np.linalg.norm(v, axis=1), 1))
    ((26, 3), (48, 3), True)
    """
    r = as_positive(radius, "radius")
    segments, rings = as_whole(segments, "segments", 3), as_whole(rings, "rings", 2)
    c = as_vector(center, "center", 3)
    lat = np.pi / 2 - np.pi * np.arange(1, rings) / rings           # from the north pole down
    lon = 2 * np.pi * np.arange(segments) / segments
    x = np.cos(lat)[:, None] * np.sin(lon)[None]
    z = np.cos(lat)[:, None] * np.cos(lon)[None]
    y = np.broadcast_to(np.sin(lat)[:, None], x.shape)
    body = np.stack([x, y, z], axis=-1).reshape(-1, 3)
    vertices = np.vstack([[0.0, 1.0, 0.0], body, [0.0, -1.0, 0.0]]) * r + c
    north, south = 0, len(vertices) - 1
    i = np.arange(segments)
    j = (i + 1) % segments
    faces = [np.stack([np.full(segments, north), 1 + i, 1 + j], -1)]
    for k in range(rings - 2):
        a, b = 1 + k * segments + i, 1 + k * segments + j
        a2, b2 = a + segments, b + segments
        faces += [np.stack([a, a2, b2], -1), np.stack([a, b2, b], -1)]
    last = 1 + (rings - 2) * segments
    faces.append(np.stack([last + i, np.full(segments, south), last + j], -1))
    return vertices, np.concatenate(faces).astype(np.intp)


class BarycentricBuffers(NamedTuple):
    """The result of :func:`barycentric_buffers`: buffers of shape (height, width).

    Attributes
    ----------
    ids : ndarray of int, shape (height, width)
        The visible face, -1 for background.
    weights : ndarray, shape (height, width, 3)
        The perspective-correct barycentric weights of the pixel centre in that face, for its
        corners in the order of the face's vertices (0 on background).
    depth : ndarray, shape (height, width)
        Viewport depth in [0, 1], inf on background.
    drawn : ndarray of bool, shape (height, width)
        ``ids >= 0``: the pixels the mesh covers.
    drawn_vertices, drawn_weights : ndarray, shape (p, 3)
        For the p drawn pixels in row order, the three vertex indices of the visible face and
        their weights: a per-vertex quantity q is ``einsum("pk,pkc->pc", drawn_weights,
        q[drawn_vertices])`` there.

    Examples
    --------
    >>> from course_lib import viewing
    >>> v, f = uv_sphere(segments=8, rings=4)
    >>> V = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    >>> barycentric_buffers(v, f, V, P, 8, 6).weights.shape
    (6, 8, 3)
    """
    ids: np.ndarray
    weights: np.ndarray
    depth: np.ndarray
    drawn: np.ndarray
    drawn_vertices: np.ndarray
    drawn_weights: np.ndarray


def barycentric_buffers(vertices, faces, view, projection, width, height,
                        cull_back_faces=False):
    r"""Rasterize a mesh once: the visible face of every pixel and its barycentric weights.

    The z-buffer (:func:`course_lib.visibility.render_depth`) draws every triangle with its
    own three corners carrying the values (1, 0, 0), (0, 1, 0), (0, 0, 1): the interpolated
    "colour" of a pixel is then exactly the perspective-correct barycentric weights
    :math:`(w_0, w_1, w_2)` of the pixel centre in its visible triangle. Any per-vertex
    quantity q (colours for Gouraud shading, positions and normals for Phong shading) is then
    :math:`\sum_k w_k q_{f_k}` at that pixel, without rasterizing again: pass the result as
    ``fragments`` to :func:`render_shaded` to re-shade a mesh whose view has not changed (new
    material, light or model) at the cost of the illumination model alone.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
    view, projection : array_like, shape (4, 4)
    width, height : int
    cull_back_faces : bool

    Returns
    -------
    BarycentricBuffers
        ``ids``, ``weights`` and ``depth``, and the same for the drawn pixels only.

    Raises
    ------
    ValueError
        For malformed input.

    Examples
    --------
    The weights of every drawn pixel sum to 1 and interpolate the vertices to a point of the
    visible face:

    >>> from course_lib import viewing
    >>> v, f = uv_sphere(segments=12, rings=6)
    >>> V = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    >>> buffers = barycentric_buffers(v, f, V, P, 16, 16)
    >>> seen = buffers.ids >= 0
    >>> bool(np.allclose(buffers.weights[seen].sum(axis=1), 1)), int(seen.sum()) > 50
    (True, True)
    """
    v, f = as_mesh(vertices, faces)
    corners = np.tile(np.eye(3), (len(f), 1))
    zb = visibility.render_depth(v[f].reshape(-1, 3), np.arange(3 * len(f)).reshape(-1, 3),
                                 view, projection, width, height, values=corners,
                                 cull_back_faces=cull_back_faces)
    drawn = zb.ids >= 0
    weights = np.where(drawn[..., None], zb.image, 0.0)
    return BarycentricBuffers(zb.ids, weights, zb.depth, drawn, f[zb.ids[drawn]], weights[drawn])


class _Raster(NamedTuple):
    ids: np.ndarray
    image: np.ndarray
    depth: np.ndarray


def _at_pixels(buffers, values):
    """Per-vertex `values` interpolated to the drawn pixels of `buffers`: (mask, values there)."""
    return buffers.drawn, np.einsum("pk,pkc->pc", buffers.drawn_weights,
                                    values[buffers.drawn_vertices])


def _from_buffers(buffers, f, values):
    """What the z-buffer would give for per-vertex `values`, from the weights of `buffers`."""
    if values is None:
        return _Raster(buffers.ids, None, buffers.depth)
    seen, at_pixels = _at_pixels(buffers, values)
    image = np.zeros(buffers.ids.shape + values.shape[1:])
    image[seen] = at_pixels
    return _Raster(buffers.ids, image, buffers.depth)


class ShadedImage(NamedTuple):
    """The result of :func:`render_shaded`: buffers of shape (height, width), row 0 at the bottom.

    Attributes
    ----------
    image : ndarray, shape (height, width, 3)
        The shaded colour (unclamped), `background` where nothing is drawn.
    ids : ndarray of int, shape (height, width)
        The visible face, -1 for background.
    depth : ndarray, shape (height, width)
        Viewport depth in [0, 1], inf on background.

    Examples
    --------
    >>> from course_lib.shading import directional_light
    >>> from course_lib import viewing
    >>> v, f = uv_sphere(segments=12, rings=6)
    >>> V = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    >>> img = render_shaded(v, f, V, P, 16, 16, directional_light([0, 0, 1]))
    >>> img.image.shape, int((img.ids >= 0).sum()) > 50
    ((16, 16, 3), True)
    """
    image: np.ndarray
    ids: np.ndarray
    depth: np.ndarray


def _eye_and_view(view, projection):
    """Eye position (None for a parallel projection) and the constant V of a parallel view."""
    parallel = np.allclose(projection[3], [0.0, 0.0, 0.0, 1.0])
    rot, t = view[:3, :3], view[:3, 3]
    if parallel:
        return None, rot[2] / np.linalg.norm(rot[2])        # z_e points towards the viewer
    return -np.linalg.solve(rot, t), None


def render_shaded(vertices, faces, view, projection, width, height, lights, material=Material(),
                  shading="phong", model="phong", normals=None, ambient=1.0, background=0.0,
                  cull_back_faces=False, two_sided=False, fragments=None):
    r"""Render a triangle mesh with flat, Gouraud or Phong (per-pixel) shading.

    The z-buffer of :func:`course_lib.visibility.render_depth` decides the visible face of each
    pixel; the illumination model (:func:`phong` or :func:`blinn_phong`) gives the colour:

    * ``shading="flat"``: once per face, at its centroid, with the face normal
      (:func:`face_normals`); the whole face gets that colour.
    * ``shading="gouraud"``: at every vertex with the vertex normal; the *colours* are
      interpolated across each triangle (perspective-correctly, by the z-buffer).
    * ``shading="phong"``: vertex positions and normals are interpolated to every pixel, the
      normal renormalized (interpolation shortens it), and the model evaluated there.

    The viewer: for a perspective `projection` the eye is the centre of projection of `view`
    and :math:`V = (E - P)/\lVert E - P \rVert` per point; for a parallel projection (last row
    ``(0, 0, 0, 1)``) :math:`V` is the camera's :math:`z_e` axis everywhere.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : array_like of int, shape (m, 3)
        Counter-clockwise seen from outside (the face normals point outwards).
    view, projection : array_like, shape (4, 4)
        E.g. :func:`course_lib.viewing.look_at` and :func:`course_lib.viewing.perspective`.
    width, height : int
        Image size in pixels.
    lights : Light or sequence of Light
    material : Material, optional
        One material for the whole mesh.
    shading : {"flat", "gouraud", "phong"}
    model : {"phong", "blinn"}
        The illumination model.
    normals : array_like, shape (n, 3), optional
        Vertex normals (default :func:`vertex_normals`); for an analytic surface pass the exact
        ones (a sphere's: ``(v - centre) / radius``). Not used by flat shading.
    ambient : float or array_like, shape (3,)
        Ambient light :math:`I_a`.
    background : float or array_like, shape (3,)
        Colour of the pixels where nothing is drawn.
    cull_back_faces : bool
    two_sided : bool
        Light back faces too (their normals flipped towards the viewer).
    fragments : BarycentricBuffers, optional
        The mesh already rasterized with this `view`, `projection`, size and culling
        (:func:`barycentric_buffers`): the z-buffer is not run again, per-vertex values are
        interpolated by its weights (the same pictures, up to rounding).

    Returns
    -------
    ShadedImage
        Show with ``plt.imshow(np.clip(result.image, 0, 1), origin="lower")``.

    Raises
    ------
    ValueError
        For malformed input, an unknown `shading` or `model`, or a bad material or light.

    Examples
    --------
    A flat-shaded sphere has one colour per face; Phong shading varies within faces:

    >>> from course_lib.shading import directional_light
    >>> from course_lib import viewing
    >>> v, f = uv_sphere(segments=12, rings=6)
    >>> V = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    >>> P = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    >>> light = directional_light([1, 1, 1])
    >>> flat = render_shaded(v, f, V, P, 32, 32, light, shading="flat")
    >>> smooth = render_shaded(v, f, V, P, 32, 32, light, shading="phong")
    >>> def colours_per_face(result):
    ...     seen = result.ids >= 0
    ...     return max(len(np.unique(result.image[result.ids == i][:, 0]))
    ...                for i in np.unique(result.ids[seen]))
    >>> colours_per_face(flat), colours_per_face(smooth) > 5
    (1, True)

    Rasterized once, shaded again with another light without a new z-buffer pass:

    >>> buffers = barycentric_buffers(v, f, V, P, 32, 32)
    >>> again = render_shaded(v, f, V, P, 32, 32, light, shading="phong", fragments=buffers)
    >>> bool(np.allclose(again.image, smooth.image))
    True
    """
    as_choice(shading, "shading", ("flat", "gouraud", "phong"))
    as_choice(model, "model", ("phong", "blinn"))
    illuminate = phong if model == "phong" else blinn_phong
    v, f = as_mesh(vertices, faces)
    view = as_matrix(view, "view", 4)
    projection = as_matrix(projection, "projection", 4)
    bg = np.broadcast_to(as_rgb(background, "background", maximum=None), (3,))
    lights = _lights(lights)
    eye, v_const = _eye_and_view(view, projection)
    if fragments is not None and (not isinstance(fragments, BarycentricBuffers)
                                  or fragments.ids.shape != (height, width)):
        raise ValueError(f"fragments must be the BarycentricBuffers of this mesh and view, of "
                         f"shape (height, width) = {(height, width)}")

    def raster(values=None):                  # the z-buffer, or the weights of `fragments`
        if fragments is not None:
            return _from_buffers(fragments, f, values)
        return visibility.render_depth(v, f, view, projection, width, height, values=values,
                                       cull_back_faces=cull_back_faces)

    def view_of(points):
        if eye is None:
            return np.broadcast_to(v_const, points.shape)
        d = eye - points
        return d / np.sqrt(_dot(d, d))[..., None]

    def shade(points, nrm):
        return illuminate(points, nrm, view_of(points), lights, material, ambient,
                          two_sided=two_sided).total

    if shading != "flat":
        vn = vertex_normals(v, f) if normals is None else as_points(normals, "normals", dims=3)
        if vn.shape != v.shape:
            raise ValueError(f"normals must hold one normal per vertex, shape {v.shape}, got "
                             f"{vn.shape}")
    if shading == "flat":
        zb = raster()
        seen = np.unique(zb.ids[zb.ids >= 0])
        colours = np.zeros((len(f), 3))
        if len(seen):
            colours[seen] = shade(v[f[seen]].mean(axis=1), face_normals(v, f[seen]))
        image = colours[np.maximum(zb.ids, 0)]
    elif shading == "gouraud":
        used = np.sqrt(_dot(vn, vn)) > 0
        colours = np.zeros((len(v), 3))
        if used.any():
            colours[used] = shade(v[used], vn[used])
        zb = raster(colours)
        image = zb.image
    else:
        if fragments is not None:                  # straight to the drawn pixels
            zb = fragments
            mask, at_pixels = _at_pixels(fragments, np.hstack([v, vn]))
        else:
            zb = raster(np.hstack([v, vn]))
            mask = zb.ids >= 0
            at_pixels = zb.image[mask]
        image = np.zeros((zb.ids.shape[0], zb.ids.shape[1], 3))
        if mask.any():
            points, nrm = at_pixels[:, :3], at_pixels[:, 3:]
            length = np.sqrt(_dot(nrm, nrm))
            fallback = length < 1e-9                  # opposite normals cancelled: use the face's
            if fallback.any():
                nrm[fallback] = face_normals(v, f[zb.ids[mask][fallback]])
            image[mask] = shade(points, nrm)
    image = np.where((zb.ids >= 0)[..., None], image, bg)
    return ShadedImage(image, zb.ids, zb.depth)
