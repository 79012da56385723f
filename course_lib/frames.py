r"""Chapter 3: normals, coordinate frames, mirroring about a plane, scaling about a point.

Four things that follow from the homogeneous matrices of :mod:`course_lib.transforms`:

* **Normals.** A surface normal :math:`n` is perpendicular to every tangent :math:`t`. A map
  :math:`M` with linear part :math:`A` sends the tangents to :math:`A t`; the normal that stays
  perpendicular to them is :math:`n' = A^{-T} n`, the *inverse transpose*, because
  :math:`(A^{-T} n) \cdot (A t) = n^T A^{-1} A t = n \cdot t = 0`. :math:`A` itself works only
  when it is orthogonal times a uniform scale (:func:`preserves_normals`).
* **Frames.** A frame with origin :math:`o` and axes :math:`u_1, \dots, u_d` (given in world
  coordinates) has the frame-to-world matrix :math:`F = \begin{bmatrix} u_1 & \cdots & u_d & o
  \\ 0 & \cdots & 0 & 1 \end{bmatrix}` (:func:`frame_matrix`); world-to-frame is its inverse,
  :math:`\begin{bmatrix} R^T & -R^T o \\ 0 & 1 \end{bmatrix}` when the axes are orthonormal
  (:func:`world_to_frame`).
* **Mirroring** about any plane (:func:`mirror_plane`) or, in 2D, any line
  (:func:`mirror_line`): :math:`p' = p - 2\,((p - c) \cdot n)\, n` for a unit normal :math:`n`.
* **Scaling about a point** :math:`c`: :math:`T(c)\,S\,T(-c)` (:func:`scale_about`).

And, for homogeneous coordinates with :math:`w \neq 1`, :func:`describe_linear` and
:func:`is_rotation` say whether a matrix is a rotation once its uniform homogeneous factor is
divided out.
"""
from dataclasses import dataclass

import numpy as np

from . import transforms
from ._validate import as_array, as_matrix, as_points, as_vector

__all__ = [
    "LinearDescription",
    "chain",
    "describe_linear",
    "frame_matrix",
    "is_rotation",
    "mirror_line",
    "mirror_plane",
    "normal_matrix",
    "preserves_normals",
    "scale_about",
    "transform_normals",
    "world_to_frame",
]


# ---------------------------------------------------------------------------------------------
# Normals
# ---------------------------------------------------------------------------------------------

def _linear_part(M, dim, name="M"):
    """The d x d linear block of `M` (a d x d map or a (d+1) x (d+1) homogeneous matrix)."""
    m = as_matrix(M, name, sizes=(2, 3, 4))
    n = m.shape[0]
    if dim is None:
        dim = {2: 2, 3: 3, 4: 3}[n]
    if dim not in (2, 3):
        raise ValueError(f"dim must be 2 or 3, got {dim!r}")
    if n == dim:
        return m
    if n == dim + 1:
        last = m[dim]
        if np.any(last[:dim] != 0.0) or last[dim] == 0.0:
            raise ValueError(f"{name} is projective (its last row is not (0, ..., 0, w) with "
                             "w != 0): a perspective map moves normals differently at every "
                             "point and has no single normal matrix")
        return m[:dim, :dim] / last[dim]
    raise ValueError(f"{name} is {n}x{n}, which does not fit {dim}D: give a {dim}x{dim} linear "
                     f"map or a {dim + 1}x{dim + 1} homogeneous matrix")


def normal_matrix(M, dim=None):
    r"""The matrix that transforms normals: the inverse transpose of the linear part of `M`.

    .. math:: N = (A^{-1})^T, \qquad n' = N\, n

    where :math:`A` is the upper-left :math:`d \times d` block of `M`. Tangents transform with
    :math:`A`; :math:`N` keeps :math:`n' \cdot t' = n^T A^{-1} A\, t = n \cdot t = 0`. The
    translation of `M` does not matter: a normal is a direction.

    Parameters
    ----------
    M : array_like, shape (2, 2), (3, 3) or (4, 4)
        A linear map or a homogeneous affine matrix.
    dim : {2, 3}, optional
        The dimension of space. By default 2x2 means 2D, 3x3 a 3D linear map and 4x4 3D
        homogeneous; pass ``dim=2`` for a 3x3 homogeneous 2D matrix.

    Returns
    -------
    ndarray, shape (dim, dim)

    Raises
    ------
    ValueError
        If the linear part is singular: it flattens space, so the tangents of a surface no
        longer span a plane and no normal direction can be defined for the image.

    Examples
    --------
    >>> import numpy as np
    >>> normal_matrix(np.diag([2.0, 1.0]))          # stretch x by 2: normals shrink along x
    array([[0.5, 0. ],
           [0. , 1. ]])
    >>> normal_matrix(np.diag([0.0, 1.0]))
    Traceback (most recent call last):
    ...
    ValueError: M has a singular linear part (determinant 0): it flattens space onto a line or plane, so normals cannot be transformed (there is no inverse transpose)
    """
    a = _linear_part(M, dim)
    if np.linalg.matrix_rank(a) < a.shape[0]:
        raise ValueError("M has a singular linear part (determinant 0): it flattens space onto "
                         "a line or plane, so normals cannot be transformed (there is no "
                         "inverse transpose)")
    return np.linalg.inv(a).T


def transform_normals(normals, M, normalize=True):
    r"""Transform many normals (rows) by the inverse transpose of `M`'s linear part.

    Parameters
    ----------
    normals : array_like, shape (..., d)
        Normals as rows, d = 2 or 3.
    M : array_like
        A d x d linear map or a (d+1) x (d+1) homogeneous affine matrix.
    normalize : bool, default True
        Return unit normals. The inverse transpose changes lengths, so a shader that needs unit
        normals must normalise again.

    Returns
    -------
    ndarray, same shape as `normals`

    Raises
    ------
    ValueError
        If `M` does not fit the normals' dimension or its linear part is singular, or (with
        `normalize`) a normal is the zero vector.

    Examples
    --------
    >>> import numpy as np
    >>> from course_lib import transforms
    >>> n = [[1.0, 1.0]]                     # normal of the line x + y = 1
    >>> transform_normals(n, transforms.scale([2, 1]), normalize=False)
    array([[0.5, 1. ]])
    """
    n = as_points(normals, "normals")
    d = n.shape[-1]
    out = n @ normal_matrix(M, dim=d).T      # rows: (N n)^T = n^T N^T = n^T A^{-1}
    if normalize:
        length = np.linalg.norm(out, axis=-1, keepdims=True)
        if np.any(length < 1e-300):
            raise ValueError("normals contains the zero vector, which has no direction to "
                             "normalise")
        out /= length
    return out


def preserves_normals(M, dim=None, atol=1e-9):
    r"""Whether `M`'s own linear part maps normals to (multiples of) the right normals.

    True exactly when :math:`A^T A = k^2 I` for some :math:`k > 0`: :math:`A` is a rotation or
    mirror times a uniform scale :math:`k`. Then :math:`A^{-T} = A / k^2`, the same directions.
    A non-uniform scale or a shear tilts the naive normals :math:`A n`.

    Parameters
    ----------
    M : array_like
        As for :func:`normal_matrix`.
    dim : {2, 3}, optional
        As for :func:`normal_matrix`.
    atol : float
        Tolerance, relative to :math:`k^2`.

    Returns
    -------
    bool

    Examples
    --------
    >>> from course_lib import transforms
    >>> import numpy as np
    >>> preserves_normals(transforms.rotate_z(0.3) @ transforms.scale([2, 2, 2]))
    True
    >>> preserves_normals(transforms.scale([2, 1, 1]))
    False
    """
    a = _linear_part(M, dim)
    gram = a.T @ a
    k2 = np.trace(gram) / a.shape[0]
    return bool(k2 > 0 and np.allclose(gram, k2 * np.eye(a.shape[0]), atol=atol * k2, rtol=0))


# ---------------------------------------------------------------------------------------------
# Coordinate frames
# ---------------------------------------------------------------------------------------------

def _frame_axes(origin, axes):
    """Validated origin (d,) and axes (d, d) (rows), with a clear word for dependent axes."""
    axes = as_array(axes, "axes")
    if axes.ndim != 2 or axes.shape[0] != axes.shape[1] or axes.shape[0] not in (2, 3):
        raise ValueError("axes must be 2 vectors of 2 numbers (2D) or 3 vectors of 3 numbers "
                         f"(3D), one axis per row, got shape {axes.shape}")
    d = axes.shape[0]
    o = as_vector(origin, "origin", d)
    lengths = np.linalg.norm(axes, axis=1)
    for k in range(d):
        if lengths[k] < 1e-12:
            raise ValueError(f"axes[{k}] is the zero vector: a frame axis needs a direction")
    unit = axes / lengths[:, None]
    for i in range(d):
        for j in range(i + 1, d):
            if abs(abs(unit[i] @ unit[j]) - 1.0) < 1e-9:
                raise ValueError(f"axes[{i}] and axes[{j}] are parallel: the axes of a frame "
                                 "must be independent, or some points have no coordinates")
    if abs(np.linalg.det(unit)) < 1e-9:
        raise ValueError("axes are coplanar (linearly dependent): the axes of a frame must span "
                         "space, or some points have no coordinates")
    return o, axes


def frame_matrix(origin, axes):
    r"""The frame-to-world matrix of a frame: its axes and origin as columns.

    .. math:: F = \begin{bmatrix} u_1 & u_2 & u_3 & o \\ 0 & 0 & 0 & 1 \end{bmatrix},
              \qquad p_{world} = F\, p_{frame}

    A point with frame coordinates :math:`(a, b, c)` is :math:`o + a u_1 + b u_2 + c u_3`.

    Parameters
    ----------
    origin : array_like, shape (d,)
        The frame's origin in world coordinates, d = 2 or 3.
    axes : array_like, shape (d, d)
        The frame's axes in world coordinates, **one axis per row**. They need not be unit or
        orthogonal, but must be independent.

    Returns
    -------
    ndarray, shape (d + 1, d + 1)

    Raises
    ------
    ValueError
        If an axis is zero, two axes are parallel or the three are coplanar.

    Examples
    --------
    >>> frame_matrix([5, 1], [[0, 1], [-1, 0]])
    array([[ 0., -1.,  5.],
           [ 1.,  0.,  1.],
           [ 0.,  0.,  1.]])
    >>> frame_matrix([0, 0], [[1, 1], [2, 2]])
    Traceback (most recent call last):
    ...
    ValueError: axes[0] and axes[1] are parallel: the axes of a frame must be independent, or some points have no coordinates
    """
    o, axes = _frame_axes(origin, axes)
    d = len(o)
    f = np.eye(d + 1)
    f[:d, :d] = axes.T
    f[:d, d] = o
    return f


def world_to_frame(origin, axes):
    r"""The world-to-frame matrix: the inverse of :func:`frame_matrix`.

    With orthonormal axes (the rows of :math:`R^T`) the inverse needs no elimination:

    .. math:: F^{-1} = \begin{bmatrix} R^T & -R^T o \\ 0 & 1 \end{bmatrix}

    i.e. a point's frame coordinates are the dot products :math:`u_i \cdot (p - o)`. Other
    axes use the general inverse of :func:`course_lib.transforms.inverse`.

    Parameters
    ----------
    origin, axes
        As for :func:`frame_matrix`.

    Returns
    -------
    ndarray, shape (d + 1, d + 1)

    Examples
    --------
    >>> import numpy as np
    >>> m = world_to_frame([5, 1], [[0, 1], [-1, 0]])
    >>> m @ [5, 3, 1]                     # two units up from the origin: along the first axis
    array([2., 0., 1.])
    """
    o, axes = _frame_axes(origin, axes)
    d = len(o)
    if np.allclose(axes @ axes.T, np.eye(d), atol=1e-12, rtol=0):
        m = np.eye(d + 1)
        m[:d, :d] = axes                   # R^T: the axes as rows
        m[:d, d] = -axes @ o
        return m
    return transforms.inverse(frame_matrix(o, axes))


def chain(*frames):
    r"""The frame-to-world matrix of the last of nested frames.

    ``frames[0]`` is given in world coordinates, ``frames[1]`` in the coordinates of
    ``frames[0]``, and so on (a robot arm, a scene graph). A point with coordinates :math:`p`
    in the last frame is at :math:`F_0 F_1 \cdots F_k\, p` in the world: the outermost frame
    stands leftmost (the opposite order of :func:`course_lib.transforms.compose`, which lists
    maps in the order they act).

    Parameters
    ----------
    *frames : array_like or tuple
        Frame-to-world matrices, or ``(origin, axes)`` pairs for :func:`frame_matrix`.

    Returns
    -------
    ndarray, shape (d + 1, d + 1)

    Examples
    --------
    >>> import numpy as np
    >>> arm = chain(([2, 0], [[0, 1], [-1, 0]]), ([1, 0], [[1, 0], [0, 1]]))
    >>> arm @ [1, 0, 1]           # 2 units along the inner x axis, which is world y
    array([2., 2., 1.])
    """
    if not frames:
        raise ValueError("chain needs at least one frame")
    result = None
    for k, f in enumerate(frames):
        if isinstance(f, tuple) and len(f) == 2:
            f = frame_matrix(*f)
        f = as_matrix(f, f"frames[{k}]")
        if result is not None and f.shape != result.shape:
            raise ValueError(f"frames[{k}] is {f.shape[0]}x{f.shape[0]} but frames[0] is "
                             f"{result.shape[0]}x{result.shape[0]}: do not mix 2D and 3D")
        result = f.copy() if result is None else result @ f
    return result


# ---------------------------------------------------------------------------------------------
# Mirroring and scaling about a point
# ---------------------------------------------------------------------------------------------

def _reflection(point, normal, d, name):
    c = as_vector(point, "point", d)
    n = as_vector(normal, name, d)
    length = np.linalg.norm(n)
    if length < 1e-12:
        raise ValueError(f"{name} must not be the zero vector: it has no direction, so it "
                         "defines no mirror")
    n = n / length
    m = np.eye(d + 1)
    m[:d, :d] -= 2.0 * np.outer(n, n)          # Householder: I - 2 n n^T
    m[:d, d] = 2.0 * (n @ c) * n               # keeps every point of the mirror in place
    return m


def mirror_plane(point, normal):
    r"""Mirroring about the plane through `point` with normal `normal`, as a 4x4 matrix.

    .. math:: p' = p - 2\,\big((p - c) \cdot n\big)\, n, \qquad
              M = \begin{bmatrix} I - 2 n n^T & 2 (n \cdot c)\, n \\ 0 & 1 \end{bmatrix}

    for the unit normal :math:`n`. The linear block is a Householder reflection: symmetric,
    orthogonal, determinant -1, its own inverse.

    Parameters
    ----------
    point : array_like, shape (3,)
        Any point of the plane.
    normal : array_like, shape (3,)
        A normal of the plane (any non-zero length).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If `normal` is zero.

    Examples
    --------
    >>> mirror_plane([0, 0, 1], [0, 0, 2]) @ [1, 2, 3, 1]      # about the plane z = 1
    array([ 1.,  2., -1.,  1.])
    """
    return _reflection(point, normal, 3, "normal")


def mirror_line(point, direction):
    r"""Mirroring about the 2D line through `point` with direction `direction`, 3x3.

    The line's normal is the direction turned by 90 degrees; the formula is that of
    :func:`mirror_plane`. Equal to :math:`T(c)\,R(\varphi)\,S(1, -1)\,R(-\varphi)\,T(-c)`.

    Parameters
    ----------
    point : array_like, shape (2,)
    direction : array_like, shape (2,)
        Non-zero.

    Returns
    -------
    ndarray, shape (3, 3)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(mirror_line([0, 0], [1, 1]) @ [2, 0, 1], 12)   # about y = x
    array([0., 2., 1.])
    """
    u = as_vector(direction, "direction", 2)
    if np.linalg.norm(u) < 1e-12:
        raise ValueError("direction must not be the zero vector: it has no direction, so it "
                         "defines no mirror")
    return _reflection(point, [-u[1], u[0]], 2, "direction")


def scale_about(point, factors):
    r"""Scaling by `factors` about the fixed point `point`: :math:`T(c)\,S\,T(-c)`.

    Read from the right: move :math:`c` to the origin, scale there, move back. The result is
    :math:`p' = c + S (p - c)`, so the last column is :math:`c - S c`.

    Parameters
    ----------
    point : array_like, shape (d,)
        The fixed point, d = 2 or 3.
    factors : array_like, shape (d,) or float
        One factor per axis, or one for all.

    Returns
    -------
    ndarray, shape (d + 1, d + 1)

    Examples
    --------
    >>> scale_about([1, 1], [2, 3]) @ [2, 2, 1]
    array([3., 4., 1.])
    """
    c = as_vector(point, "point", (2, 3))
    f = as_array(factors, "factors")
    if f.ndim == 0:
        f = np.full(len(c), float(f))
    f = as_vector(f, "factors", len(c))
    return transforms.translate(c) @ transforms.scale(f) @ transforms.translate(-c)


# ---------------------------------------------------------------------------------------------
# Homogeneous matrices with w != 1: is it a rotation?
# ---------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class LinearDescription:
    """What :func:`describe_linear` finds out about a matrix.

    Attributes
    ----------
    kind : str
        ``"rotation"``, ``"scaled rotation"``, ``"mirror"``, ``"scaled mirror"``,
        ``"rigid motion"`` (rotation plus translation) or ``"other"``.
    is_rotation : bool
        A rotation about the origin once the homogeneous factor is divided out.
    w : float
        The homogeneous factor divided out (1 for a linear map).
    factor : float
        The uniform scale :math:`k` of the linear part (:math:`A^T A = k^2 I`), NaN if none.
    angle_deg : float
        The rotation angle in degrees (signed in 2D, in [0, 180] in 3D), NaN if none.
    axis : ndarray or None
        The unit rotation axis in 3D (None in 2D, for 0 degrees, or if no rotation).
    text : str
        A sentence explaining the verdict.

    Examples
    --------
    >>> describe_linear([[0, -3, 0], [3, 0, 0], [0, 0, 3]]).kind
    'rotation'
    """
    kind: str
    is_rotation: bool
    w: float
    factor: float
    angle_deg: float
    axis: object
    text: str


def _angle_axis(r):
    """Angle in degrees (and 3D unit axis) of an orthonormal r with det +1."""
    if r.shape[0] == 2:
        return float(np.degrees(np.arctan2(r[1, 0], r[0, 0]))), None
    cos = np.clip((np.trace(r) - 1.0) / 2.0, -1.0, 1.0)
    angle = float(np.degrees(np.arccos(cos)))
    if angle < 1e-9:
        return 0.0, None
    skew = np.array([r[2, 1] - r[1, 2], r[0, 2] - r[2, 0], r[1, 0] - r[0, 1]])
    if np.linalg.norm(skew) > 1e-6:
        return angle, skew / np.linalg.norm(skew)
    # a half turn: r = 2 a a^T - I, so r + I has columns along the axis
    col = (r + np.eye(3))[:, int(np.argmax(np.diag(r)))]
    return angle, col / np.linalg.norm(col)


def describe_linear(M, homogeneous=True):
    r"""Say whether `M` is a rotation, up to the homogeneous factor :math:`w`, and why.

    A homogeneous point :math:`(x, y, w)` is the same point as :math:`(x/w, y/w, 1)`, so a
    homogeneous matrix and any non-zero multiple of it are the same map. Divide the matrix by
    its bottom-right entry :math:`w`, then look at the linear block :math:`A`: a rotation if
    :math:`A^T A = I` and :math:`\det A = +1`, a mirror if the determinant is -1, and a scaled
    rotation if :math:`A^T A = k^2 I` with :math:`k \neq 1`.

    Parameters
    ----------
    M : array_like, shape (2, 2), (3, 3) or (4, 4)
        A homogeneous matrix (3x3 for 2D, 4x4 for 3D), or with ``homogeneous=False`` a linear
        map (2x2 or 3x3), which is not divided by anything.
    homogeneous : bool, default True

    Returns
    -------
    LinearDescription

    Raises
    ------
    ValueError
        If a homogeneous `M` is projective or has :math:`w = 0`, or a 2x2 matrix is called
        homogeneous.

    Examples
    --------
    >>> m = [[0, -3, 0], [3, 0, 0], [0, 0, 3]]
    >>> d = describe_linear(m)                 # a 2D homogeneous matrix
    >>> d.is_rotation, d.w, d.angle_deg
    (True, 3.0, 90.0)
    >>> d = describe_linear(m, homogeneous=False)    # a 3D linear map
    >>> d.kind, d.factor, d.angle_deg
    ('scaled rotation', 3.0, 90.0)
    """
    m = as_matrix(M, "M", sizes=(2, 3, 4))
    n = m.shape[0]
    if homogeneous:
        if n == 2:
            raise ValueError("M is 2x2, which cannot be homogeneous (2D homogeneous matrices "
                             "are 3x3); pass homogeneous=False for a 2D linear map")
        d = n - 1
        w = float(m[d, d])
        if np.any(m[d, :d] != 0.0) or w == 0.0:
            raise ValueError("M is projective (its last row is not (0, ..., 0, w) with w != 0):"
                             " it is no rotation, scaling or mirror of space")
        a, t = m[:d, :d] / w, m[:d, d] / w
    else:
        d, w, a, t = n, 1.0, m, np.zeros(n)
    gram = a.T @ a
    k2 = float(np.trace(gram)) / d
    uniform = k2 > 0 and np.allclose(gram, k2 * np.eye(d), atol=1e-9 * max(k2, 1.0), rtol=0)
    divided = f"dividing by w = {w:g} leaves the linear block " if w != 1.0 else "the linear block "
    nan = float("nan")
    if not uniform:
        return LinearDescription("other", False, w, nan, nan, None, (
            f"No: {divided}with A^T A not a multiple of I, so it changes angles (a non-uniform "
            "scale or a shear); it is no rotation, even up to a factor."))
    k = float(np.sqrt(k2))
    r = a / k
    det = float(np.linalg.det(r))
    moved = bool(np.linalg.norm(t) > 1e-12)
    if det < 0:
        kind = "mirror" if abs(k - 1) < 1e-9 else "scaled mirror"
        return LinearDescription(kind, False, w, k, nan, None, (
            f"No: {divided}with A^T A = {k2:g} I but determinant < 0, so it contains a "
            f"mirroring (it reverses orientation){'' if kind == 'mirror' else f' and a scale {k:g}'}"
            "; no rotation does that."))
    angle, axis = _angle_axis(r)
    about = "" if axis is None else f" about the axis ({', '.join(f'{x:.4g}' for x in axis)})"
    if abs(k - 1) > 1e-9:
        what = ("a homogeneous" if homogeneous else "a linear")
        return LinearDescription("scaled rotation", False, w, k, angle, axis, (
            f"No, as {what} matrix: {divided}with A^T A = {k2:g} I, a rotation by "
            f"{angle:.4g} degrees{about} times a uniform scale {k:g}."))
    if moved:
        return LinearDescription("rigid motion", False, w, 1.0, angle, axis, (
            f"Not about the origin: {divided}orthonormal with determinant +1 (a rotation by "
            f"{angle:.4g} degrees{about}), but the last column adds a translation."))
    return LinearDescription("rotation", True, w, 1.0, angle, axis, (
        f"Yes: {divided}orthonormal (A^T A = I) with determinant +1, a rotation by "
        f"{angle:.4g} degrees{about}."))


def is_rotation(M, homogeneous=True):
    """Whether `M` is a rotation about the origin, up to the homogeneous factor (see
    :func:`describe_linear`, which also says why).

    Parameters
    ----------
    M : array_like
    homogeneous : bool, default True

    Returns
    -------
    bool

    Examples
    --------
    >>> is_rotation([[0, -3, 0], [3, 0, 0], [0, 0, 3]])
    True
    >>> is_rotation([[0, -3, 0], [3, 0, 0], [0, 0, 3]], homogeneous=False)
    False
    """
    return describe_linear(M, homogeneous).is_rotation
