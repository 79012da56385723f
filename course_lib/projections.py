r"""Chapter 4: the taxonomy of planar geometric projections and vanishing points.

A *planar geometric projection* sends every point along a straight projector onto a plane. The
projectors either meet in a centre of projection (**perspective**) or are all parallel to one
direction of projection (**parallel**). Each branch splits by how a box's principal axes sit
against the plane of projection:

- perspective: **one-, two- or three-point**, the number of box axes *not* parallel to the plane
  (each such axis family of edges meets at its own principal vanishing point);
- parallel, projectors perpendicular to the plane (**orthographic**): **multiview** (front, top,
  side: the plane is parallel to a face of the box) or **axonometric** (the plane cuts all three
  axes): **isometric** (the three axes foreshortened equally), **dimetric** (two equally),
  **trimetric** (none equally);
- parallel, projectors oblique to the plane (**oblique**): **cavalier** (depth at full length,
  projectors at 45° to the plane), **cabinet** (depth at half length, at arctan 2 ≈ 63.4°), or a
  general oblique projection.

World frame of the constructors here: z is up; the front view looks along +y (from the -y
side), with world x to the right. Images are the first two coordinates after the homogeneous
divide (x right, y up). Column vectors: :math:`p' = M p`.

:func:`classify_projection` names the class of any 4x4 projection matrix (with the reason),
:func:`vanishing_point` computes the image of a direction's point at infinity
:math:`(d, 0)`, and :func:`project_onto_plane` builds the matrix of a perspective or parallel
projection onto an arbitrary plane.
"""
import numpy as np

from . import transforms, viewing
from ._validate import as_array, as_matrix, as_positive, as_scalar, as_vector

__all__ = [
    "PRESERVES",
    "axonometric",
    "cabinet",
    "cavalier",
    "centre_of_projection",
    "classify_projection",
    "dimetric",
    "foreshortening",
    "isometric",
    "multiview",
    "oblique_projection",
    "orbit_rotation",
    "perspective_view",
    "preserves_table",
    "principal_vanishing_points",
    "project_onto_plane",
    "vanishing_point",
]

#: The isometric elevation: arctan(1/sqrt 2) = arcsin(1/sqrt 3) ≈ 35.264°.
_ISO_ELEVATION = float(np.arctan(1 / np.sqrt(2)))

#: What each class keeps (a row per class; read by :func:`preserves_table`).
PRESERVES = (
    ("perspective (1, 2, 3-point)", "straight lines, cross ratios; parallel lines only if they "
     "are parallel to the plane", "no true lengths (foreshortening by distance)",
     "angles only in faces parallel to the plane"),
    ("orthographic multiview", "parallelism, ratios along a line",
     "true lengths of the two axes in the plane", "true angles in faces parallel to the plane"),
    ("isometric", "parallelism, ratios along a line",
     "all three axes scaled by the same sqrt(2/3) ≈ 0.816", "none (axes drawn 120° apart)"),
    ("dimetric", "parallelism, ratios along a line", "two axes scaled equally", "none"),
    ("trimetric", "parallelism, ratios along a line", "three different scales", "none"),
    ("oblique cavalier", "parallelism, ratios along a line",
     "true lengths of all three axes (depth at full length)",
     "true angles in faces parallel to the plane"),
    ("oblique cabinet", "parallelism, ratios along a line",
     "true lengths in the plane, depth halved", "true angles in faces parallel to the plane"),
)


def preserves_table():
    """What each class of projection preserves, as a Markdown table (from :data:`PRESERVES`).

    Returns
    -------
    str

    Examples
    --------
    >>> print(preserves_table().splitlines()[0])
    | class | keeps | lengths | angles |
    """
    lines = ["| class | keeps | lengths | angles |", "|---|---|---|---|"]
    lines += [f"| {a} | {b} | {c} | {d} |" for a, b, c, d in PRESERVES]
    return "\n".join(lines)


def orbit_rotation(azimuth, elevation):
    r"""The rotation from the world (z up) into a view frame (x right, y up, z to the viewer).

    The viewer sits in the direction :math:`v = (\sin a \cos e,\ -\cos a \cos e,\ \sin e)` from
    the origin (azimuth :math:`a` about the vertical z axis, elevation :math:`e` above the
    ground); :math:`a = e = 0` is the front view along +y. The matrix is
    :math:`R_x(e - 90°)\, R_z(-a)`: turn the viewer's azimuth to the front, then tilt the world
    so that z is up and :math:`v` becomes the view z axis.

    Parameters
    ----------
    azimuth, elevation : float
        Angles in radians.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(orbit_rotation(0.0, 0.0) @ [0, 0, 1, 0], 12)     # world up is picture up
    array([0., 1., 0., 0.])
    """
    a = as_scalar(azimuth, "azimuth")
    e = as_scalar(elevation, "elevation")
    return transforms.rotate_x(e - np.pi / 2) @ transforms.rotate_z(-a)


def axonometric(azimuth, elevation):
    r"""An orthographic projection of the world seen from `azimuth` and `elevation`.

    :math:`P_{ORTHO}\, R`: rotate with :func:`orbit_rotation`, then drop the view z. When the view
    direction lies along a box axis it is a multiview projection; otherwise axonometric
    (isometric, dimetric or trimetric, see :func:`classify_projection`).

    Parameters
    ----------
    azimuth, elevation : float
        Angles in radians.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(axonometric(0, 0) @ [1, 2, 3, 1], 12)     # front view: (x, z)
    array([1., 3., 0., 1.])
    """
    return viewing.orthographic_xy() @ orbit_rotation(azimuth, elevation)


def isometric():
    r"""The isometric projection: azimuth 45°, elevation :math:`\arctan(1/\sqrt2) ≈ 35.264°`.

    The view direction :math:`(1, -1, 1)/\sqrt3` makes equal angles with the three axes, so each
    axis is foreshortened by :math:`\sqrt{2/3} ≈ 0.8165` and their images are 120° apart.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(foreshortening(isometric()), 4)
    array([0.8165, 0.8165, 0.8165])
    """
    return axonometric(np.pi / 4, _ISO_ELEVATION)


def dimetric(elevation):
    r"""A dimetric projection: azimuth 45° (x and y foreshortened equally), any `elevation`.

    Parameters
    ----------
    elevation : float
        Radians; :math:`\arctan(1/\sqrt2)` gives the isometric projection, 0 or 90° a multiview.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> f = foreshortening(dimetric(np.radians(20)))
    >>> bool(np.isclose(f[0], f[1]) and not np.isclose(f[0], f[2]))
    True
    """
    return axonometric(np.pi / 4, elevation)


def multiview(view="front"):
    """An orthographic multiview projection: the ``"front"``, ``"top"`` or ``"side"`` view.

    Front looks along +y (x right, z up), top looks down -z (x right, y up), side looks along -x
    from the +x side (y right, z up).

    Parameters
    ----------
    view : {"front", "top", "side"}

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        For another view name.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(multiview("top") @ [1, 2, 3, 1], 12)
    array([1., 2., 0., 1.])
    """
    angles = {"front": (0.0, 0.0), "top": (0.0, np.pi / 2), "side": (np.pi / 2, 0.0)}
    if view not in angles:
        raise ValueError(f"view must be one of 'front', 'top', 'side', got {view!r}")
    return axonometric(*angles[view])


def oblique_projection(angle, length):
    r"""An oblique projection onto the front plane: depth drawn at `angle` with `length`.

    Faces parallel to the world xz plane keep their true shape; a unit step into the picture
    (world +y) is drawn as a segment of length `length` at `angle` above the image x axis:
    :func:`viewing.oblique` with :math:`DOP = (k\cos\varphi, k\sin\varphi, 1)` applied after the
    front :func:`orbit_rotation`. The projectors make the angle :math:`\arctan(1/k)` with the
    plane: 45° for the cavalier (:math:`k = 1`), 63.4° for the cabinet (:math:`k = 1/2`).

    Parameters
    ----------
    angle : float
        Radians.
    length : float
        Positive drawn length of a unit of depth.

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If `length` is not positive.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(oblique_projection(0.0, 0.5) @ [0, 1, 0, 1], 12)   # depth 1 -> 0.5 to the right
    array([0.5, 0. , 0. , 1. ])
    """
    phi = as_scalar(angle, "angle")
    k = as_positive(length, "length")
    return viewing.oblique([k * np.cos(phi), k * np.sin(phi), 1.0]) @ orbit_rotation(0.0, 0.0)


def cavalier(angle=np.pi / 4):
    """The cavalier projection (depth at full length), see :func:`oblique_projection`.

    Examples
    --------
    >>> classify_projection(cavalier())["name"]
    'oblique cavalier'
    """
    return oblique_projection(angle, 1.0)


def cabinet(angle=np.pi / 4):
    """The cabinet projection (depth at half length), see :func:`oblique_projection`.

    Examples
    --------
    >>> classify_projection(cabinet(np.radians(30)))["name"]
    'oblique cabinet'
    """
    return oblique_projection(angle, 0.5)


def perspective_view(azimuth, elevation, distance=5.0, d=1.0):
    r"""A perspective projection from an eye at `distance` from the origin, onto a plane at `d`.

    The eye sits at :math:`\text{distance}\cdot v` (see :func:`orbit_rotation`) and looks at the
    origin; the plane of projection is perpendicular to the view direction at distance `d` in
    front of the eye: :math:`P_{PER}(-d)\, T(0, 0, -\text{distance})\, R`. Image x, y are the
    first two coordinates after the divide. A front view (:math:`a, e` multiples of 90°) is a
    one-point perspective of an axis-aligned box, elevation 0 a two-point one, otherwise three.

    Parameters
    ----------
    azimuth, elevation : float
        Radians.
    distance, d : float
        Positive distances of the origin and of the plane from the eye.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> transforms.apply(perspective_view(0, 0, 5, 1), [1, 0, 0]).round(3)   # 5 ahead: x / 5
    array([ 0.2,  0. , -1. ])
    """
    dist = as_positive(distance, "distance")
    d = as_positive(d, "d")
    return (viewing.simple_perspective(-d) @ transforms.translate([0.0, 0.0, -dist])
            @ orbit_rotation(azimuth, elevation))


def _as_axes(axes):
    if axes is None:
        return np.eye(3)
    a = as_array(axes, "axes")
    if a.shape != (3, 3):
        raise ValueError(f"axes must be 3 directions as the rows of a 3x3 array, got shape "
                         f"{a.shape}")
    lengths = np.linalg.norm(a, axis=1)
    if np.any(lengths < 1e-12):
        raise ValueError("axes must not contain a zero vector: each row is an edge direction")
    return a / lengths[:, None]


def _as_projection(matrix):
    """The checked matrix and the rows that carry its image (x, y[, z], w)."""
    m = as_matrix(matrix, "matrix", 4)
    if not np.any(m[3]):
        raise ValueError("matrix must have a non-zero last row: with w = 0 everywhere no point "
                         "has an image")
    s = np.linalg.svd(m, compute_uv=False)
    # rank 3: a projection whose image points are (x, y, z) on a plane; rank 4: a camera that
    # keeps depth, whose image is (x, y) after the divide
    rows = [0, 1, 2, 3] if s[3] <= 1e-10 * s[0] else [0, 1, 3]
    s = np.linalg.svd(m[rows], compute_uv=False)
    if s[2] <= 1e-10 * s[0]:
        raise ValueError("matrix is singular in the wrong way: it maps space onto a line or a "
                         "point, not onto a plane (its image rows have rank < 3)")
    return m, rows


def _linear_image(m, rows):
    """The 2x3 linear part of a parallel projection in an orthonormal basis of its image."""
    lin = m[rows[:-1], :3] / m[3, 3]
    u, s, vt = np.linalg.svd(lin)
    return s[:2, None] * vt[:2]


def centre_of_projection(matrix):
    r"""The centre of projection (perspective) or the direction of projection (parallel).

    Every point of a projector has the same image, so the projectors all pass through the
    homogeneous null vector :math:`k` of the image rows :math:`(x, y, w)` of the matrix:
    :math:`k = (c, 1)` for a perspective projection with centre :math:`c`, :math:`k = (d, 0)`
    for a parallel one along :math:`d`.

    Parameters
    ----------
    matrix : array_like, shape (4, 4)

    Returns
    -------
    kind : str
        ``"perspective"`` or ``"parallel"``.
    vector : ndarray, shape (3,)
        The centre (perspective) or the unit direction of projection (parallel; sign chosen so
        that its largest component is positive).

    Raises
    ------
    ValueError
        For a matrix that is not 4x4 or maps space onto less than a plane.

    Examples
    --------
    >>> import numpy as np
    >>> kind, c = centre_of_projection(viewing.simple_perspective(2))
    >>> kind, np.round(c, 12) + 0.0
    ('perspective', array([0., 0., 0.]))
    """
    m, rows = _as_projection(matrix)
    k = np.linalg.svd(m[rows])[2][-1]
    if abs(k[3]) > 1e-9 * np.linalg.norm(k[:3]):
        return "perspective", k[:3] / k[3]
    d = k[:3] / np.linalg.norm(k[:3])
    return "parallel", d * np.sign(d[np.argmax(np.abs(d))])


def vanishing_point(matrix, direction):
    r"""The vanishing point of a direction: the image of its point at infinity :math:`(d, 0)`.

    Points :math:`p + t d` of a line tend, as :math:`t \to \infty`, to the image of the
    homogeneous point :math:`(d, 0)`: :math:`M (d, 0)^T = (X, Y, Z, W)` divided by :math:`W`.
    All lines of direction :math:`d` meet there. When :math:`W = 0` (the direction is parallel
    to the plane of projection, or the projection is parallel) there is no vanishing point:
    such lines stay parallel in the picture.

    Parameters
    ----------
    matrix : array_like, shape (4, 4)
        A projection (or a whole camera, e.g. ``perspective @ look_at``).
    direction : array_like, shape (3,) or (n, 3)
        One or many directions (non-zero; their length does not matter).

    Returns
    -------
    ndarray, shape (3,), or None
        For one direction: the vanishing point (the divided x, y, z), or None when the direction
        is parallel to the plane of projection.
    ndarray, shape (n, 3)
        For many directions: one row each; the rows of directions without a vanishing point are
        ``inf``.

    Raises
    ------
    ValueError
        For a matrix that is not 4x4, or a zero direction.

    Examples
    --------
    >>> P = viewing.simple_perspective(2)
    >>> vanishing_point(P, [1, 0, 1])          # (2, 0, 2, 1) / 1
    array([2., 0., 2.])
    >>> vanishing_point(P, [1, 0, 0]) is None  # parallel to the plane z = 2
    True
    """
    m, _ = _as_projection(matrix)
    d = as_array(direction, "direction")
    single = d.ndim == 1
    d2 = np.atleast_2d(d)
    if d2.ndim != 2 or d2.shape[1] != 3:
        raise ValueError(f"direction must have shape (3,) or (n, 3), got {d.shape}")
    lengths = np.linalg.norm(d2, axis=1)
    if np.any(lengths == 0):
        raise ValueError("direction must not be the zero vector: it has no point at infinity")
    h = (d2 / lengths[:, None]) @ m[:, :3].T
    scale = np.linalg.norm(m[:, :3], axis=(0, 1))
    none = np.abs(h[:, 3]) <= 1e-12 * scale
    out = np.full((len(d2), 3), np.inf)
    ok = ~none
    out[ok] = h[ok, :3] / h[ok, 3:]
    if single:
        return None if none[0] else out[0]
    return out


def principal_vanishing_points(matrix, axes=None):
    """The vanishing points of a box's three edge directions (the world axes by default).

    Parameters
    ----------
    matrix : array_like, shape (4, 4)
    axes : array_like, shape (3, 3), optional
        The box's edge directions as rows.

    Returns
    -------
    list of (ndarray of shape (3,) or None)
        One entry per axis; None for an axis parallel to the plane of projection. The number of
        entries that are not None is the number of points of the perspective.

    Examples
    --------
    >>> vps = principal_vanishing_points(viewing.simple_perspective(1))
    >>> [v is None for v in vps]          # only z recedes: one-point perspective
    [True, True, False]
    """
    a = _as_axes(axes)
    return [vanishing_point(matrix, row) for row in a]


def foreshortening(matrix, axes=None):
    r"""The drawn length of a unit step along each axis under a parallel projection.

    For a parallel matrix :math:`M` (last row :math:`(0, 0, 0, w)`) a unit vector :math:`a`
    moves the image by :math:`\lVert M_{2\times3}\, a \rVert / w`.

    Parameters
    ----------
    matrix : array_like, shape (4, 4)
        A parallel projection.
    axes : array_like, shape (3, 3), optional
        Directions as rows (normalised here); the world axes by default.

    Returns
    -------
    ndarray, shape (3,)

    Raises
    ------
    ValueError
        For a perspective matrix (its foreshortening depends on the distance).

    Examples
    --------
    >>> foreshortening(multiview("front"))
    array([1., 0., 1.])
    """
    m, rows = _as_projection(matrix)
    if np.any(np.abs(m[3, :3]) > 1e-12 * np.abs(m).max()):
        raise ValueError("matrix is a perspective projection: its foreshortening depends on the "
                         "distance, so give a parallel projection")
    a = _as_axes(axes)
    lengths = np.linalg.norm(a @ _linear_image(m, rows).T, axis=1)
    return np.where(lengths < 1e-12, 0.0, lengths)


def _oblique_depth_factor(rows, dop):
    """Angle between the projectors and the plane, and the drawn length of a unit of depth."""
    pinv = np.linalg.pinv(rows)                      # columns: preimages in the plane ⟂ dop
    a1, a2 = pinv[:, 0], pinv[:, 1]
    p, q, r = a1 @ a1, a2 @ a2, a1 @ a2
    # preimages a1 + s d, a2 + t d orthogonal and of equal length: s^4 + (p - q) s^2 - r^2 = 0
    s2 = (-(p - q) + np.sqrt((p - q) ** 2 + 4 * r * r)) / 2
    if s2 > 1e-14 * (p + q):
        s = np.sqrt(s2)
        t = -r / s
    else:
        s, t = 0.0, np.sqrt(max(p - q, 0.0))
    normal = np.cross(a1 + s * dop, a2 + t * dop)
    sin_angle = abs(normal @ dop) / np.linalg.norm(normal)
    angle = np.arcsin(min(sin_angle, 1.0))
    return angle, np.sqrt(max(1 - sin_angle ** 2, 0.0)) / sin_angle


def classify_projection(matrix, axes=None, tol=1e-6):
    r"""Name the class of a 4x4 planar projection, with the reason and what it preserves.

    1. The null vector of the image rows (x, y, w) gives the centre or the direction of
       projection (:func:`centre_of_projection`): perspective or parallel.
    2. Perspective: the plane of projection has the normal :math:`n = (M_{30}, M_{31},
       M_{32})` (the points with :math:`w = 0` form the plane through the centre parallel to
       it). Each box axis :math:`a` with :math:`n \cdot a \ne 0` recedes to a vanishing point:
       their count makes a one-, two- or three-point perspective.
    3. Parallel: the image rows are orthogonal and of equal length exactly when the projectors
       are perpendicular to the plane (**orthographic**). Then the foreshortening factors of
       the axes decide: one zero (an axis along the projectors) is a multiview projection;
       three equal ones isometric, two dimetric, none trimetric.
    4. Otherwise **oblique**: the plane on which the image is undistorted makes an angle
       :math:`\alpha` with the projectors, and a unit of depth is drawn with length
       :math:`\cot\alpha`: 1 is cavalier, 1/2 cabinet.

    Parameters
    ----------
    matrix : array_like, shape (4, 4)
    axes : array_like, shape (3, 3), optional
        The box's (object's) axes as rows; the world axes by default.
    tol : float, optional
        Relative tolerance for "equal" and "zero".

    Returns
    -------
    dict
        ``name`` (e.g. ``"two-point perspective"``, ``"isometric"``, ``"oblique cabinet"``),
        ``family`` (``"perspective"``, ``"orthographic"`` or ``"oblique"``), ``reason`` (a
        sentence), ``preserves`` (a sentence), and ``vanishing`` (perspective: the number of
        principal vanishing points), ``foreshortening`` (orthographic: the three factors) or
        ``depth_length`` and ``angle`` (oblique: the drawn length of a unit of depth and the
        angle in radians between the projectors and the plane).

    Raises
    ------
    ValueError
        For a matrix that is not 4x4, whose last row is zero, or that maps space onto less than
        a plane; for bad `axes`.

    Examples
    --------
    >>> classify_projection(viewing.simple_perspective(1))["name"]
    'one-point perspective'
    >>> classify_projection(isometric())["name"]
    'isometric'
    """
    m, image_rows = _as_projection(matrix)
    a = _as_axes(axes)
    kind, vec = centre_of_projection(m)
    names = ("x", "y", "z") if axes is None else ("first", "second", "third")
    if kind == "perspective":
        n = m[3, :3] / np.linalg.norm(m[3, :3])
        receding = np.abs(a @ n) > tol
        count = int(receding.sum())
        parallel = [names[i] for i in range(3) if not receding[i]]
        label = {1: "one", 2: "two", 3: "three"}[count]
        if count == 3:
            why = "no box axis is parallel to the plane of projection: three vanishing points"
        else:
            others = ("the other edges meet at one vanishing point" if count == 1 else
                      "the edges of the two other axes meet at two vanishing points")
            why = (f"the box's {' and '.join(parallel)} edges are parallel to the image plane "
                   f"(they stay parallel); {others}")
        return {"name": f"{label}-point perspective", "family": "perspective",
                "reason": why, "vanishing": count,
                "preserves": "straight lines and cross ratios; not parallelism of receding "
                             "edges, not ratios of lengths"}
    rows = _linear_image(m, image_rows)
    gram = rows @ rows.T
    scale = np.sqrt(np.trace(gram) / 2)
    if abs(gram[0, 1]) <= tol * scale ** 2 and abs(gram[0, 0] - gram[1, 1]) <= tol * scale ** 2:
        f = np.linalg.norm(a @ rows.T, axis=1) / scale
        f = np.where(f < tol, 0.0, f)
        out = {"family": "orthographic", "foreshortening": f,
               "preserves": "parallel lines and ratios along a line"}
        if np.any(f == 0):
            out.update(name="orthographic multiview",
                       reason="the projectors run along a box axis: one face is seen in true "
                              "shape and size, the receding axis vanishes",
                       preserves="parallel lines, ratios, true lengths and angles in the faces "
                                 "parallel to the plane")
            return out
        equal = [abs(f[i] - f[j]) <= tol * max(f) for i, j in ((0, 1), (0, 2), (1, 2))]
        if all(equal):
            out.update(name="isometric", reason=f"the projectors make equal angles with the "
                       f"three axes: all foreshortened by {f[0]:.4f} (sqrt(2/3) ≈ 0.8165)")
        elif any(equal):
            out.update(name="dimetric", reason=f"two axes are foreshortened equally "
                       f"(factors {f[0]:.3f}, {f[1]:.3f}, {f[2]:.3f})")
        else:
            out.update(name="trimetric", reason=f"the three axes are foreshortened differently "
                       f"(factors {f[0]:.3f}, {f[1]:.3f}, {f[2]:.3f})")
        return out
    angle, depth = _oblique_depth_factor(rows, vec)
    if abs(depth - 1) <= 1e-4:
        name, what = "oblique cavalier", "depth drawn at full length (projectors at 45°)"
    elif abs(depth - 0.5) <= 1e-4:
        name, what = "oblique cabinet", "depth drawn at half length (projectors at 63.4°)"
    else:
        name, what = "oblique (general)", f"depth drawn at {depth:.3f} of its length"
    return {"name": name, "family": "oblique", "depth_length": float(depth),
            "angle": float(angle),
            "reason": f"the projectors are not perpendicular to the plane: {what}",
            "preserves": "parallel lines, ratios along a line, true shape of faces parallel to "
                         "the plane"}


def project_onto_plane(point_on_plane, normal, centre=None, direction=None):
    r"""The 4x4 matrix of a projection onto the plane :math:`n \cdot x = h`, :math:`h = n \cdot p_0`.

    **Perspective** from a centre :math:`c`: the projector :math:`c + t (x - c)` meets the plane
    where :math:`t = (h - n\cdot c) / n\cdot(x - c)`; multiplying by the denominator,

    .. math:: M = \begin{bmatrix} (h - n\cdot c) I + c\, n^T & -h\, c \\
              n^T & -n \cdot c \end{bmatrix}.

    **Parallel** along :math:`d`: :math:`x - \frac{n\cdot x - h}{n \cdot d} d`, i.e.

    .. math:: M = \begin{bmatrix} I - \frac{d\, n^T}{n\cdot d} & \frac{h}{n\cdot d} d \\
              0 & 1 \end{bmatrix}.

    With :math:`c = 0`, :math:`n = (0, 0, 1)`, :math:`h = d` the first is the textbook's
    :math:`P_{PER}` (times :math:`d`); the image points are 3D points of the plane.

    Parameters
    ----------
    point_on_plane, normal : array_like, shape (3,)
        A point of the plane and its normal (any non-zero length).
    centre : array_like, shape (3,), optional
        The centre of projection (give exactly one of `centre` and `direction`).
    direction : array_like, shape (3,), optional
        The direction of projection.

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        For a zero normal, neither or both of centre and direction, a centre on the plane, or a
        direction zero or parallel to the plane.

    Examples
    --------
    >>> M = project_onto_plane([0, 0, 2], [0, 0, 1], centre=[0, 0, 0])
    >>> transforms.apply(M, [3, 6, 4])          # the P_PER example with d = 2
    array([1.5, 3. , 2. ])
    """
    p0 = as_vector(point_on_plane, "point_on_plane", 3)
    n = as_vector(normal, "normal", 3)
    if np.linalg.norm(n) < 1e-12:
        raise ValueError("normal must not be the zero vector: it fixes the plane's orientation")
    n = n / np.linalg.norm(n)
    h = n @ p0
    if (centre is None) == (direction is None):
        raise ValueError("give exactly one of centre (perspective) and direction (parallel)")
    m = np.zeros((4, 4))
    if centre is not None:
        c = as_vector(centre, "centre", 3)
        gap = h - n @ c
        if abs(gap) <= 1e-12 * max(1.0, np.abs(c).max()):
            raise ValueError("centre must not lie on the plane: every projector would lie in "
                             "the plane and the image would be a line")
        m[:3, :3] = gap * np.eye(3) + np.outer(c, n)
        m[:3, 3] = -h * c
        m[3, :3] = n
        m[3, 3] = -n @ c
        return m
    d = as_vector(direction, "direction", 3)
    if np.linalg.norm(d) < 1e-12:
        raise ValueError("direction must not be the zero vector")
    d = d / np.linalg.norm(d)
    nd = n @ d
    if abs(nd) <= 1e-12:
        raise ValueError("direction must not be parallel to the plane: its projectors would "
                         "never reach it")
    m[:3, :3] = np.eye(3) - np.outer(d, n) / nd
    m[:3, 3] = h / nd * d
    m[3, 3] = 1.0
    return m
