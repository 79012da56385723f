r"""Chapter 14: two-part texture mapping (Bier and Sloan's S-mapping and O-mapping).

A complicated object has no natural (u, v). Two-part mapping splits the problem:

1. **S-mapping** (surface): texture space onto a simple *intermediate surface* that has an
   easy parametrization: a ``"plane"``, a ``"cylinder"``, a ``"sphere"`` or a ``"box"``
   (:func:`s_map`: intermediate point -> (u, v), built on :func:`planar_map`,
   :func:`cylindrical_map`, :func:`spherical_map`).
2. **O-mapping** (object): every object point :math:`P` (normal :math:`N`) is sent to a point
   :math:`Q` of the intermediate surface (:func:`intermediate_points`), in one of four ways:

   * ``"reflected"``: along the view ray reflected about :math:`N`,
     :math:`r = d - 2 (d\cdot N) N` with :math:`d = P - E`. It depends on the eye: this is
     environment mapping (the texture is what the object mirrors);
   * ``"normal"``: along the object's normal :math:`N` from :math:`P`;
   * ``"centroid"``: along the line from the object's centroid :math:`C_o` through :math:`P`;
   * ``"intermediate_normal"``: the inverse direction, the point :math:`Q` of the surface
     whose own normal line passes through :math:`P` (for the sphere :math:`Q` is the radial
     projection from the sphere's centre, for the cylinder from its axis, for the plane the
     orthogonal projection, for the box the projection onto the nearest face).

   The first three shoot the ray :math:`P + t\,w` (:math:`t \ge 0`; for the plane the whole
   line) and take its first hit with the surface (from inside a closed surface, where it
   leaves).

The intermediate surfaces, with centre :math:`c` and size :math:`s`: the plane
:math:`z = c_z - s` behind the object (normal z; not through :math:`c`, or every centroid line
would meet it at the centroid), its square :math:`c \pm s` in x and y being texture space's unit
square; the
cylinder of radius :math:`s` about the y axis through :math:`c`, :math:`v \in [0, 1]` from
height :math:`-s` to :math:`s`; the sphere of radius :math:`s`; the cube :math:`c \pm s`, each
face carrying the whole texture, upright and unmirrored seen from outside (the face is the
major axis of :math:`Q - c`).

With a sphere object centred on the sphere's centre, ``"normal"``, ``"centroid"`` and
``"intermediate_normal"`` all give the plain spherical map: the three lines coincide.
"""

import numpy as np

from .._validate import as_choice, as_points, as_positive, as_vector
from ..raytracing.intersections import intersect_box, intersect_plane, intersect_sphere
from ..raytracing.optics import reflect_direction
from ._common import _dot
from .mappings import cylindrical_map, planar_map, spherical_map

__all__ = ["METHODS", "SURFACES", "box_face", "intermediate_points", "intersect_intermediate",
           "s_map", "two_part_map"]

SURFACES = ("plane", "cylinder", "sphere", "box")
METHODS = ("reflected", "normal", "centroid", "intermediate_normal")

_Y = np.array([0.0, 1.0, 0.0])
_Z = np.array([0.0, 0.0, 1.0])


def _surface(surface, center, size):
    surface = as_choice(surface, "surface", SURFACES)
    return surface, as_vector(center, "center", 3), as_positive(size, "size")


# ---------------------------------------------------------------------------------------------
# S-mapping
# ---------------------------------------------------------------------------------------------

def box_face(points, center=(0.0, 0.0, 0.0)):
    r"""The cube face a point (or direction from `center`) belongs to: the major axis.

    ``k = argmax |d_k|`` and the sign of :math:`d_k`, :math:`d = P - c`, numbered
    0 = +x, 1 = -x, 2 = +y, 3 = -y, 4 = +z, 5 = -z (as OpenGL's cube map faces).

    Parameters
    ----------
    points : array_like, shape (..., 3)
    center : array_like, shape (3,)

    Returns
    -------
    ndarray of int, shape (...)

    Raises
    ------
    ValueError
        For a point at the centre (no direction).

    Examples
    --------
    >>> box_face([[2, 1, 0], [0, -3, 1], [0.1, 0.2, -0.5]])
    array([0, 3, 5])
    """
    d = as_points(points, "points", dims=3) - as_vector(center, "center", 3)
    a = np.abs(d)
    if np.any(a.max(axis=-1) == 0):
        raise ValueError("points must not be at the center: the face is undefined there")
    k = np.argmax(a, axis=-1)
    sign = np.take_along_axis(d, k[..., None], axis=-1)[..., 0]
    return 2 * k + (sign < 0)


def _face_frame(face):
    """Outward normal, u axis, v axis of a face (upright and unmirrored from outside)."""
    n = np.zeros(3)
    n[face // 2] = -1.0 if face % 2 else 1.0
    e_u = np.array([1.0, 0.0, 0.0]) if face in (2, 3) else np.cross(_Y, n)
    return n, e_u, np.cross(n, e_u)


def s_map(points, surface="sphere", center=(0.0, 0.0, 0.0), size=1.0):
    r"""S-mapping: texture coordinates of points of an intermediate surface.

    * plane (:math:`z = c_z - s`): :func:`planar_map` with normal z, the square :math:`c \pm s`
      in x, y -> the unit square;
    * cylinder: :func:`cylindrical_map` about y, base at :math:`c - s\hat y`, height
      :math:`2s`;
    * sphere: :func:`spherical_map` about :math:`c`;
    * box: the face :func:`box_face`, then :func:`planar_map` of that face, its corner
      :math:`c + s(n - e_u - e_v)` at (0, 0), side :math:`2s`.

    Points need not lie exactly on the surface: each map projects (the plane along z, the
    cylinder radially, the sphere centrally, the box face along its normal).

    Parameters
    ----------
    points : array_like, shape (..., 3)
    surface : {"plane", "cylinder", "sphere", "box"}
    center : array_like, shape (3,)
    size : float
        Half the plane's / box's side, the radius and half height of the cylinder, the radius
        of the sphere.

    Returns
    -------
    u, v : ndarray, shape (...)

    Examples
    --------
    >>> s_map([[1, 0.5, 0]], "box")             # face +x: u grows towards -z, v with y
    (array([0.5]), array([0.75]))
    >>> s_map([[0, 0, 1]], "cylinder")
    (array([0.5]), array([0.5]))
    """
    surface, c, s = _surface(surface, center, size)
    p = as_points(points, "points", dims=3)
    if surface == "plane":
        return planar_map(p, origin=c - s * np.array([1.0, 1.0, 0.0]), normal=_Z,
                          u_axis=[1, 0, 0], size=2 * s)
    if surface == "cylinder":
        return cylindrical_map(p, center=c - s * _Y, axis=_Y, height=2 * s)
    if surface == "sphere":
        return spherical_map(p, center=c)
    face = box_face(p, c)
    u, v = np.empty(face.shape), np.empty(face.shape)
    for f in range(6):
        sel = face == f
        if sel.any():
            n, e_u, e_v = _face_frame(f)
            u[sel], v[sel] = planar_map(p[sel], origin=c + s * (n - e_u - e_v), normal=n,
                                        u_axis=e_u, size=2 * s)
    return u, v


# ---------------------------------------------------------------------------------------------
# Ray - intermediate surface intersections
# ---------------------------------------------------------------------------------------------

def _cylinder_t(o, d, c, r):
    """First t >= 0 where o + t d meets the infinite cylinder |(p - c) x y| = r (axis y)."""
    f = (o - c)[:, [0, 2]]
    g = d[:, [0, 2]]
    a = _dot(g, g)
    b = _dot(f, g)
    cc = _dot(f, f) - r * r
    disc = b * b - a * cc
    ok = (a > 1e-300) & (disc >= 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        root = np.sqrt(np.where(ok, disc, 0.0))
        t1, t2 = (-b - root) / a, (-b + root) / a
    t = np.where(t1 >= 0, t1, np.where(t2 >= 0, t2, np.inf))
    return np.where(ok, t, np.inf)


def intersect_intermediate(origins, directions, surface="sphere", center=(0.0, 0.0, 0.0),
                           size=1.0):
    r"""Where rays :math:`o + t\,d` first meet an intermediate surface: the ray parameter t.

    The sphere, the box (slab method) and the plane use :func:`course_lib.raytracing`'s
    :func:`intersect_sphere`, :func:`intersect_box`, :func:`intersect_plane`; for the plane
    both directions of the line count (an O-mapping projects onto the plane from either
    side, so t may be negative). The cylinder (infinite, radius :math:`s`, axis y through
    :math:`c`) solves :math:`\lVert (f + t g) \rVert^2 = s^2` in the xz components
    (:math:`f = o - c`, :math:`g = d`): :math:`a t^2 + 2 b t + (f\cdot f - s^2) = 0`.

    Parameters
    ----------
    origins, directions : array_like, shape (..., 3)
    surface, center, size
        As :func:`s_map`.

    Returns
    -------
    ndarray, shape (...)
        ``inf`` where the ray misses (a ray parallel to the plane or the cylinder's axis, or
        leaving a closed surface it started outside of).

    Examples
    --------
    >>> intersect_intermediate([[0, 0, 0], [0.5, 0, 0]], [1, 0, 0], "cylinder", size=2.0)
    array([2. , 1.5])
    >>> intersect_intermediate([0, 0, 3], [0, 0, 1], "plane")      # the plane z = -1
    array(-4.)
    """
    surface, c, s = _surface(surface, center, size)
    o = as_points(origins, "origins", dims=3)
    d = as_points(directions, "directions", dims=3)
    if surface == "sphere":
        return intersect_sphere(o, d, c, s).t
    if surface == "box":
        return intersect_box(o, d, c - s, c + s).t
    if surface == "plane":
        forward = intersect_plane(o, d, c - s * _Z, _Z).t
        backward = intersect_plane(o, -np.asarray(d), c - s * _Z, _Z).t
        return np.where(np.isfinite(forward), forward, -backward)
    lead = np.broadcast_shapes(o.shape, d.shape)
    oo = np.broadcast_to(o, lead).reshape(-1, 3)
    dd = np.broadcast_to(d, lead).reshape(-1, 3)
    if np.any(~np.any(dd != 0, axis=-1)):
        raise ValueError("directions must not contain the zero vector: a ray needs a direction")
    return _cylinder_t(oo, dd, c, s).reshape(lead[:-1])


# ---------------------------------------------------------------------------------------------
# O-mapping and the whole two-part map
# ---------------------------------------------------------------------------------------------

def _nonzero_rows(v, name):
    if np.any(~np.any(v != 0, axis=-1)):
        raise ValueError(f"{name} must not contain the zero vector: it has no direction")
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def intermediate_points(points, normals=None, surface="sphere", method="normal",
                        center=(0.0, 0.0, 0.0), size=1.0, eye=None, centroid=None):
    r"""O-mapping: the intermediate surface's point :math:`Q` for each object point :math:`P`.

    See the module docstring for the four methods. Directions: ``"reflected"``
    :math:`r = d - 2 (d \cdot N) N`, :math:`d = P - E`
    (:func:`course_lib.raytracing.reflect_direction`); ``"normal"`` :math:`N`;
    ``"centroid"`` :math:`P - C_o`; then :math:`Q = P + t\,w` with t from
    :func:`intersect_intermediate`. ``"intermediate_normal"`` projects :math:`P` along the
    surface's normals (centrally onto the sphere, radially onto the cylinder, along z onto
    the plane, along the major axis onto the box face).

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Object points.
    normals : array_like, shape (..., 3), optional
        Object normals (not zero; normalized here); needed by ``"reflected"`` and
        ``"normal"``.
    surface : {"plane", "cylinder", "sphere", "box"}
    method : {"reflected", "normal", "centroid", "intermediate_normal"}
    center, size
        The intermediate surface, as :func:`s_map`.
    eye : array_like, shape (3,) or (..., 3), optional
        The eye point(s), for ``"reflected"`` (required there).
    centroid : array_like, shape (3,), optional
        The object's centroid for ``"centroid"`` (default: the mean of `points`).

    Returns
    -------
    q : ndarray, shape (..., 3)
        NaN rows where the ray misses the surface.
    hit : ndarray of bool, shape (...)

    Raises
    ------
    ValueError
        For unknown names (the valid ones are listed), missing or zero normals, a point at the
        centroid or at the centre, non-finite input.

    Examples
    --------
    >>> q, hit = intermediate_points([[0.5, 0, 0]], [[1, 0, 0]], "sphere", "normal", size=2)
    >>> q, hit
    (array([[2., 0., 0.]]), array([ True]))
    """
    surface, c, s = _surface(surface, center, size)
    method = as_choice(method, "method", METHODS)
    p = as_points(points, "points", dims=3)
    if method == "intermediate_normal":
        if surface == "plane":
            q = p.copy()
            q[..., 2] = c[2] - s
        elif surface == "sphere":
            d = _nonzero_rows(p - c, "points - center")
            q = c + s * d
        elif surface == "cylinder":
            d = p - c
            radial = d * [1.0, 0.0, 1.0]
            radial = _nonzero_rows(radial, "points (their distance from the cylinder's axis)")
            q = c + s * radial + d * _Y
        else:
            face = box_face(p, c)
            q = p.copy()
            k = face // 2
            side = np.where(face % 2, -1.0, 1.0)
            np.put_along_axis(q, k[..., None], (np.take(c, k) + side * s)[..., None], axis=-1)
        return q, np.ones(p.shape[:-1], bool)
    if method == "centroid":
        co = p.reshape(-1, 3).mean(axis=0) if centroid is None else as_vector(
            centroid, "centroid", 3)
        w = _nonzero_rows(p - co, "points - centroid")
    else:
        if normals is None:
            raise ValueError(f"normals are needed by method {method!r}")
        n = _nonzero_rows(as_points(normals, "normals", dims=3), "normals")
        if method == "normal":
            w = np.broadcast_to(n, np.broadcast_shapes(n.shape, p.shape))
        else:
            if eye is None:
                raise ValueError("eye is needed by method 'reflected' (the view ray starts there)")
            e = as_points(eye, "eye", dims=3)
            view = _nonzero_rows(np.broadcast_to(p - e, np.broadcast_shapes(p.shape, e.shape)),
                                 "points - eye")
            w = reflect_direction(view, n)
    p_b = np.broadcast_to(p, w.shape)
    t = intersect_intermediate(p_b, w, surface, c, s)
    hit = np.isfinite(t)
    q = np.where(hit[..., None], p_b + np.where(hit, t, 0.0)[..., None] * w, np.nan)
    return q, hit


def two_part_map(points, normals=None, surface="sphere", method="normal",
                 center=(0.0, 0.0, 0.0), size=1.0, eye=None, centroid=None):
    r"""Two-part mapping: O-mapping to the intermediate surface, then its S-mapping.

    :math:`(u, v) = S(O(P))`: :func:`intermediate_points` then :func:`s_map`.

    Parameters
    ----------
    points, normals, surface, method, center, size, eye, centroid
        As :func:`intermediate_points`.

    Returns
    -------
    u, v : ndarray, shape (...)
        NaN where the O-mapping's ray misses the surface (only possible for a ray parallel to
        the plane or the cylinder's axis, or from a point outside a closed surface).

    Examples
    --------
    A point on the unit sphere, mapped by its normal onto the sphere of radius 2: the
    spherical map of its direction.

    >>> two_part_map([[0, 0, 1]], [[0, 0, 1]], "sphere", "normal", size=2.0)
    (array([0.5]), array([0.5]))
    >>> two_part_map([[0, 0, 1]], [[0, 0, 1]], "cone")
    Traceback (most recent call last):
    ...
    ValueError: surface must be one of 'plane', 'cylinder', 'sphere', 'box', got 'cone'
    """
    surface, c, s = _surface(surface, center, size)
    q, hit = intermediate_points(points, normals, surface, method, c, s, eye, centroid)
    u = np.full(hit.shape, np.nan)
    v = np.full(hit.shape, np.nan)
    if hit.any():
        u[hit], v[hit] = s_map(q[hit], surface, c, s)
    return u, v
