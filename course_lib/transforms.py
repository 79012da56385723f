r"""Chapter 3: homogeneous 2D and 3D transformation matrices.

Points are column vectors, as in the textbook: a transformation ``M`` maps a point ``p`` to
``M @ p``. In homogeneous coordinates a 2D point ``(x, y)`` becomes ``(x, y, 1)`` and a 3D point
``(x, y, z, 1)``, so that every affine map :math:`\Phi(p) = A p + t`, translation included, is one
matrix multiplication:

.. math:: \begin{bmatrix} p' \\ 1 \end{bmatrix} =
          \begin{bmatrix} A & t \\ 0 & 1 \end{bmatrix} \begin{bmatrix} p \\ 1 \end{bmatrix}

2D matrices are 3x3 and 3D matrices 4x4. Angles are in radians; a positive angle turns
counter-clockwise when one looks from the positive end of the axis towards the origin.
Arrays of many points are stored as rows, shape ``(..., 2)`` or ``(..., 3)``; :func:`apply` takes
care of the homogeneous coordinate and of the division by it.
"""
import numpy as np

from ._validate import as_array, as_matrix, as_points, as_scalar, as_unit_vector, as_vector

__all__ = [
    "apply",
    "compose",
    "euler_zyx",
    "from_homogeneous",
    "inverse",
    "mirror",
    "rotate",
    "rotate_about",
    "rotate_axis",
    "rotate_axis_steps",
    "rotate_x",
    "rotate_y",
    "rotate_z",
    "scale",
    "shear_x",
    "shear_xy",
    "shear_xz",
    "shear_y",
    "shear_yz",
    "to_homogeneous",
    "translate",
]


# ---------------------------------------------------------------------------------------------
# Translation, scaling, mirroring
# ---------------------------------------------------------------------------------------------

def translate(d):
    r"""Translation by the vector `d` (2 or 3 numbers) as a homogeneous matrix.

    .. math:: T(d) = \begin{bmatrix} I & d \\ 0 & 1 \end{bmatrix}, \qquad T(d)^{-1} = T(-d)

    Parameters
    ----------
    d : array_like, shape (2,) or (3,)
        The displacement; its length chooses a 2D (3x3) or a 3D (4x4) matrix.

    Returns
    -------
    ndarray, shape (3, 3) or (4, 4)

    Raises
    ------
    ValueError
        If `d` is not 2 or 3 finite numbers.

    Examples
    --------
    >>> translate([1, 2]) @ [0, 0, 1]
    array([1., 2., 1.])
    >>> translate([1, 2, 3]) @ translate([-1, -2, -3])
    array([[1., 0., 0., 0.],
           [0., 1., 0., 0.],
           [0., 0., 1., 0.],
           [0., 0., 0., 1.]])
    """
    d = as_vector(d, "d", (2, 3))
    m = np.eye(len(d) + 1)
    m[:-1, -1] = d
    return m


def scale(factors):
    r"""Scaling about the origin by one factor per axis, as a homogeneous matrix.

    .. math:: S(s_x, s_y, s_z) = \operatorname{diag}(s_x, s_y, s_z, 1), \qquad
              S^{-1} = S(1/s_x, 1/s_y, 1/s_z)

    A factor below 1 shrinks, above 1 stretches, 1 leaves the axis alone, and a negative factor
    mirrors (see :func:`mirror`). A factor of 0 flattens the object onto a line or a plane (all
    zeros collapse it to the origin): the matrix is then singular and has no inverse.

    Parameters
    ----------
    factors : array_like, shape (2,) or (3,)
        ``(s_x, s_y)`` for 2D or ``(s_x, s_y, s_z)`` for 3D.

    Returns
    -------
    ndarray, shape (3, 3) or (4, 4)

    Examples
    --------
    >>> scale([2, 3]) @ [1, 1, 1]
    array([2., 3., 1.])
    """
    s = as_vector(factors, "factors", (2, 3))
    return np.diag(np.append(s, 1.0))


_MIRRORS = {
    # 2D: mirroring about an axis negates the other coordinate
    "x": (1, -1), "y": (-1, 1),
    # 3D: mirroring about a coordinate plane negates the coordinate not in the plane
    "xy": (1, 1, -1), "yz": (-1, 1, 1), "xz": (1, -1, 1), "origin": (-1, -1, -1),
}


def mirror(about):
    r"""Mirroring about a coordinate axis (2D) or a coordinate plane (3D): a scaling by -1.

    In 2D ``mirror("x")`` reflects about the x axis, :math:`S(1, -1)`, and ``mirror("y")`` about
    the y axis, :math:`S(-1, 1)`. In 3D ``mirror("xy")`` reflects about the xy plane,
    :math:`S(1, 1, -1)`; likewise ``"yz"`` and ``"xz"``. ``"origin"`` is the 3D point reflection
    :math:`S(-1, -1, -1)`. Every mirror is its own inverse and has determinant -1: it turns
    a right-handed frame into a left-handed one, which no rotation can do.

    Parameters
    ----------
    about : {"x", "y", "xy", "yz", "xz", "origin"}

    Returns
    -------
    ndarray, shape (3, 3) or (4, 4)

    Raises
    ------
    ValueError
        For any other name.

    Examples
    --------
    >>> mirror("x") @ [2, 5, 1]
    array([ 2., -5.,  1.])
    >>> mirror("xy") @ [1, 2, 3, 1]
    array([ 1.,  2., -3.,  1.])
    """
    key = str(about).lower()
    key = {"zx": "xz", "zy": "yz", "yx": "xy"}.get(key, key)
    if key not in _MIRRORS:
        raise ValueError(f"about must be one of {sorted(_MIRRORS)}, got {about!r}")
    return scale(_MIRRORS[key])


# ---------------------------------------------------------------------------------------------
# Rotation
# ---------------------------------------------------------------------------------------------

def rotate(theta):
    r"""2D rotation about the origin by `theta` radians (counter-clockwise for theta > 0).

    .. math:: R(\theta) = \begin{bmatrix} \cos\theta & -\sin\theta & 0 \\
              \sin\theta & \cos\theta & 0 \\ 0 & 0 & 1 \end{bmatrix},
              \qquad R(\theta)^{-1} = R(-\theta) = R(\theta)^T

    Parameters
    ----------
    theta : float
        Angle in radians.

    Returns
    -------
    ndarray, shape (3, 3)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(rotate(np.pi / 2) @ [1, 0, 1], 12)
    array([0., 1., 1.])
    """
    theta = as_scalar(theta, "theta")
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s, 0.0],
                     [s, c, 0.0],
                     [0.0, 0.0, 1.0]])


def rotate_about(theta, center):
    r"""2D rotation by `theta` radians about the point `center`.

    Move the centre to the origin, rotate there, move it back:

    .. math:: R_c(\theta) = T(c)\, R(\theta)\, T(-c)

    (read from right to left: the rightmost matrix acts first).

    Parameters
    ----------
    theta : float
        Angle in radians.
    center : array_like, shape (2,)
        The fixed point of the rotation.

    Returns
    -------
    ndarray, shape (3, 3)

    Examples
    --------
    >>> import numpy as np
    >>> m = rotate_about(np.pi, [1, 1])
    >>> np.round(m @ [1, 1, 1], 12), np.round(m @ [2, 1, 1], 12)
    (array([1., 1., 1.]), array([0., 1., 1.]))
    """
    c = as_vector(center, "center", 2)
    return translate(c) @ rotate(theta) @ translate(-c)


def _rotate_3d(theta, i, j):
    """Rotation in the plane of axes i -> j (i.e. about the third axis), 4x4."""
    theta = as_scalar(theta, "theta")
    c, s = np.cos(theta), np.sin(theta)
    m = np.eye(4)
    m[i, i], m[i, j] = c, -s
    m[j, i], m[j, j] = s, c
    return m


def rotate_x(theta):
    r"""3D rotation about the x axis by `theta` radians.

    .. math:: R_x(\theta) = \begin{bmatrix} 1 & 0 & 0 & 0 \\ 0 & \cos\theta & -\sin\theta & 0 \\
              0 & \sin\theta & \cos\theta & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix}

    Parameters
    ----------
    theta : float
        Angle in radians; positive turns y towards z.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(rotate_x(np.pi / 2) @ [0, 1, 0, 1], 12)
    array([0., 0., 1., 1.])
    """
    return _rotate_3d(theta, 1, 2)


def rotate_y(theta):
    r"""3D rotation about the y axis by `theta` radians.

    .. math:: R_y(\theta) = \begin{bmatrix} \cos\theta & 0 & \sin\theta & 0 \\ 0 & 1 & 0 & 0 \\
              -\sin\theta & 0 & \cos\theta & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix}

    The minus sign sits below the diagonal, unlike :func:`rotate_x` and :func:`rotate_z`: a
    positive rotation about y turns z towards x (the cyclic order x -> y -> z -> x), so in the
    (x, z) plane the usual pattern appears transposed.

    Parameters
    ----------
    theta : float
        Angle in radians; positive turns z towards x.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(rotate_y(np.pi / 2) @ [0, 0, 1, 1], 12)
    array([1., 0., 0., 1.])
    """
    return _rotate_3d(theta, 2, 0)


def rotate_z(theta):
    r"""3D rotation about the z axis by `theta` radians.

    .. math:: R_z(\theta) = \begin{bmatrix} \cos\theta & -\sin\theta & 0 & 0 \\
              \sin\theta & \cos\theta & 0 & 0 \\ 0 & 0 & 1 & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix}

    Parameters
    ----------
    theta : float
        Angle in radians; positive turns x towards y.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(rotate_z(np.pi / 2) @ [1, 0, 0, 1], 12)
    array([0., 1., 0., 1.])
    """
    return _rotate_3d(theta, 0, 1)


def rotate_axis(axis, theta, point=(0.0, 0.0, 0.0)):
    r"""3D rotation by `theta` radians about the line through `point` with direction `axis`.

    The 3x3 part is Rodrigues' formula for the unit axis :math:`k`:

    .. math:: R = \cos\theta\, I + \sin\theta\, [k]_\times + (1 - \cos\theta)\, k k^T

    where :math:`[k]_\times` is the cross-product matrix; a line that does not pass through the
    origin adds the translations :math:`T(p)\, R\, T(-p)`. :func:`rotate_axis_steps` builds the
    same matrix the textbook's way, as a product of elementary rotations.

    Parameters
    ----------
    axis : array_like, shape (3,)
        Direction of the rotation axis; any non-zero length (it is normalized).
    theta : float
        Angle in radians, counter-clockwise when looking from the tip of `axis` back along it.
    point : array_like, shape (3,), optional
        A point on the axis (default: the origin).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If `axis` is the zero vector, or an argument has the wrong shape or is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> np.allclose(rotate_axis([0, 0, 1], 0.3), rotate_z(0.3))
    True
    >>> np.round(rotate_axis([1, 1, 1], 2 * np.pi / 3) @ [1, 0, 0, 1], 12)  # x -> y -> z -> x
    array([0., 1., 0., 1.])
    """
    k = as_unit_vector(axis, "axis", 3)
    theta = as_scalar(theta, "theta")
    p = as_vector(point, "point", 3)
    c, s = np.cos(theta), np.sin(theta)
    cross = np.array([[0.0, -k[2], k[1]],
                      [k[2], 0.0, -k[0]],
                      [-k[1], k[0], 0.0]])
    m = np.eye(4)
    m[:3, :3] = c * np.eye(3) + s * cross + (1.0 - c) * np.outer(k, k)
    if np.any(p):
        m = translate(p) @ m @ translate(-p)
    return m


def rotate_axis_steps(axis, theta, point=(0.0, 0.0, 0.0)):
    r"""The textbook's construction of a rotation about an arbitrary axis, step by step.

    For the unit axis :math:`u = (a, b, c)` through the point :math:`p`, with
    :math:`d = \sqrt{b^2 + c^2}`:

    1. :math:`T(-p)` moves the axis through the origin;
    2. :math:`R_x(\alpha)`, with :math:`\cos\alpha = c/d,\ \sin\alpha = b/d`, turns the axis into
       the xz plane, onto :math:`(a, 0, d)` (skipped when :math:`d = 0`: the axis is already x);
    3. :math:`R_y(\beta)`, with :math:`\cos\beta = d,\ \sin\beta = -a`, turns it onto +z;
    4. :math:`R_z(\theta)` performs the rotation;
    5. to 7. undo steps 3, 2 and 1 in reverse order.

    The product :math:`T(p) R_x(-\alpha) R_y(-\beta) R_z(\theta) R_y(\beta) R_x(\alpha) T(-p)`
    equals :func:`rotate_axis`.

    Parameters
    ----------
    axis, theta, point
        As for :func:`rotate_axis`.

    Returns
    -------
    list of (str, ndarray) pairs
        The label and the 4x4 matrix of each step, in the order they are applied; pass the
        matrices to :func:`compose` to get the whole rotation.

    Examples
    --------
    >>> import numpy as np
    >>> steps = rotate_axis_steps([1, 2, 2], 0.7, point=[1, 0, 0])
    >>> [label for label, _ in steps]
    ['T(-p)', 'R_x(alpha)', 'R_y(beta)', 'R_z(theta)', 'R_y(-beta)', 'R_x(-alpha)', 'T(p)']
    >>> np.allclose(compose(*[m for _, m in steps]), rotate_axis([1, 2, 2], 0.7, [1, 0, 0]))
    True
    """
    a, b, c = as_unit_vector(axis, "axis", 3)
    theta = as_scalar(theta, "theta")
    p = as_vector(point, "point", 3)
    d = np.hypot(b, c)
    alpha = np.arctan2(b, c) if d > 1e-12 else 0.0
    beta = np.arctan2(-a, d)
    return [
        ("T(-p)", translate(-p)),
        ("R_x(alpha)", rotate_x(alpha)),
        ("R_y(beta)", rotate_y(beta)),
        ("R_z(theta)", rotate_z(theta)),
        ("R_y(-beta)", rotate_y(-beta)),
        ("R_x(-alpha)", rotate_x(-alpha)),
        ("T(p)", translate(p)),
    ]


def euler_zyx(yaw, pitch, roll):
    r"""Rotation from Euler angles: yaw about z, then pitch about the new y, then roll about x.

    .. math:: R = R_z(\text{yaw})\, R_y(\text{pitch})\, R_x(\text{roll})

    This is the aircraft convention (intrinsic z-y'-x''). At pitch :math:`= \pm 90°` yaw and
    roll turn about the same axis and one degree of freedom is lost: *gimbal lock*.

    Parameters
    ----------
    yaw, pitch, roll : float
        Angles in radians.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.allclose(euler_zyx(0.1, 0.2, 0.3), rotate_z(0.1) @ rotate_y(0.2) @ rotate_x(0.3))
    True
    """
    return rotate_z(as_scalar(yaw, "yaw")) @ rotate_y(as_scalar(pitch, "pitch")) \
        @ rotate_x(as_scalar(roll, "roll"))


# ---------------------------------------------------------------------------------------------
# Shear
# ---------------------------------------------------------------------------------------------

def shear_x(a):
    r"""2D shear along x: :math:`x' = x + a y`, :math:`y' = y`.

    .. math:: SH_x(a) = \begin{bmatrix} 1 & a & 0 \\ 0 & 1 & 0 \\ 0 & 0 & 1 \end{bmatrix},
              \qquad SH_x(a)^{-1} = SH_x(-a)

    A shear keeps areas (its determinant is 1) and keeps lines parallel to x fixed in direction.

    Parameters
    ----------
    a : float
        Shear factor.

    Returns
    -------
    ndarray, shape (3, 3)

    Examples
    --------
    >>> shear_x(2) @ [0, 1, 1]
    array([2., 1., 1.])
    """
    m = np.eye(3)
    m[0, 1] = as_scalar(a, "a")
    return m


def shear_y(b):
    r"""2D shear along y: :math:`x' = x`, :math:`y' = y + b x`.

    .. math:: SH_y(b) = \begin{bmatrix} 1 & 0 & 0 \\ b & 1 & 0 \\ 0 & 0 & 1 \end{bmatrix}

    Parameters
    ----------
    b : float
        Shear factor.

    Returns
    -------
    ndarray, shape (3, 3)

    Examples
    --------
    >>> shear_y(2) @ [1, 0, 1]
    array([1., 2., 1.])
    """
    m = np.eye(3)
    m[1, 0] = as_scalar(b, "b")
    return m


def _shear_3d(a, b, driver, targets):
    m = np.eye(4)
    m[targets[0], driver] = as_scalar(a, "a")
    m[targets[1], driver] = as_scalar(b, "b")
    return m


def shear_xy(a, b):
    r"""3D shear of x and y in proportion to z: :math:`x' = x + a z`, :math:`y' = y + b z`.

    .. math:: SH_{xy}(a, b) = \begin{bmatrix} 1 & 0 & a & 0 \\ 0 & 1 & b & 0 \\
              0 & 0 & 1 & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix},
              \qquad SH_{xy}(a, b)^{-1} = SH_{xy}(-a, -b)

    Planes of constant z slide rigidly; the xy plane itself stays fixed. Volumes are kept
    (determinant 1).

    Parameters
    ----------
    a, b : float
        Shear factors of x and of y.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> shear_xy(2, 3) @ [0, 0, 1, 1]
    array([2., 3., 1., 1.])
    """
    return _shear_3d(a, b, driver=2, targets=(0, 1))


def shear_xz(a, b):
    r"""3D shear of x and z in proportion to y: :math:`x' = x + a y`, :math:`z' = z + b y`.

    .. math:: SH_{xz}(a, b) = \begin{bmatrix} 1 & a & 0 & 0 \\ 0 & 1 & 0 & 0 \\
              0 & b & 1 & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix}

    Parameters
    ----------
    a, b : float
        Shear factors of x and of z.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> shear_xz(2, 3) @ [0, 1, 0, 1]
    array([2., 1., 3., 1.])
    """
    return _shear_3d(a, b, driver=1, targets=(0, 2))


def shear_yz(a, b):
    r"""3D shear of y and z in proportion to x: :math:`y' = y + a x`, :math:`z' = z + b x`.

    .. math:: SH_{yz}(a, b) = \begin{bmatrix} 1 & 0 & 0 & 0 \\ a & 1 & 0 & 0 \\
              b & 0 & 1 & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix}

    Parameters
    ----------
    a, b : float
        Shear factors of y and of z.

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> shear_yz(2, 3) @ [1, 0, 0, 1]
    array([1., 2., 3., 1.])
    """
    return _shear_3d(a, b, driver=0, targets=(1, 2))


# ---------------------------------------------------------------------------------------------
# Composition, inversion, application
# ---------------------------------------------------------------------------------------------

def compose(*matrices):
    r"""The single matrix that applies `matrices` one after the other, first to last.

    Because points are column vectors, the transformation applied first stands rightmost:
    ``compose(A, B, C)`` is :math:`C\,B\,A`. Matrix products do not commute, so the order
    matters (try ``compose(T, R)`` against ``compose(R, T)``).

    Parameters
    ----------
    *matrices : array_like
        One or more 3x3 (2D) or 4x4 (3D) matrices, all of the same size, in the order in which
        they act.

    Returns
    -------
    ndarray, shape (3, 3) or (4, 4)

    Raises
    ------
    ValueError
        If no matrix is given, or they differ in size.

    Examples
    --------
    >>> import numpy as np
    >>> m = compose(translate([1, 0]), rotate(np.pi / 2))   # translate first, then rotate
    >>> np.round(m @ [0, 0, 1], 12)
    array([0., 1., 1.])
    """
    if not matrices:
        raise ValueError("compose needs at least one matrix")
    result = None
    for k, m in enumerate(matrices):
        m = as_matrix(m, f"matrices[{k}]")
        if result is None:
            result = m.copy()
        elif m.shape != result.shape:
            raise ValueError(f"matrices[{k}] is {m.shape[0]}x{m.shape[1]} but matrices[0] is "
                             f"{result.shape[0]}x{result.shape[1]}: do not mix 2D and 3D")
        else:
            result = m @ result
    return result


def inverse(M):
    r"""Inverse of a homogeneous transformation matrix.

    For an affine matrix (last row :math:`0 \dots 0\ 1`) the block formula is used:

    .. math:: \begin{bmatrix} A & t \\ 0 & 1 \end{bmatrix}^{-1} =
              \begin{bmatrix} A^{-1} & -A^{-1} t \\ 0 & 1 \end{bmatrix}

    Any other invertible matrix (a projective one) is inverted as a whole.

    Parameters
    ----------
    M : array_like, shape (3, 3) or (4, 4)

    Returns
    -------
    ndarray, same shape as `M`

    Raises
    ------
    ValueError
        If `M` is singular, e.g. a scaling with a factor of 0, which flattens space and cannot be
        undone.

    Examples
    --------
    >>> import numpy as np
    >>> np.allclose(inverse(translate([1, 2, 3])), translate([-1, -2, -3]))
    True
    >>> inverse(scale([2, 0]))
    Traceback (most recent call last):
    ...
    ValueError: M is singular (determinant 0): it flattens space, e.g. a scale factor of 0, and cannot be inverted
    """
    m = as_matrix(M, "M")
    n = m.shape[0] - 1
    # affine only if the last row is exactly (0, ..., 0, 1): a nearly affine matrix is projective
    affine = bool(np.all(m[n, :n] == 0.0) and m[n, n] == 1.0)
    block = m[:n, :n] if affine else m
    if np.linalg.matrix_rank(block) < block.shape[0]:
        raise ValueError("M is singular (determinant 0): it flattens space, e.g. a scale factor "
                         "of 0, and cannot be inverted")
    if not affine:
        return np.linalg.inv(m)
    a_inv = np.linalg.inv(block)
    result = np.eye(n + 1)
    result[:n, :n] = a_inv
    result[:n, n] = -a_inv @ m[:n, n]
    return result


def to_homogeneous(points):
    """Append the homogeneous coordinate 1 to each point: ``(..., d)`` -> ``(..., d + 1)``.

    Parameters
    ----------
    points : array_like, shape (..., d)

    Returns
    -------
    ndarray, shape (..., d + 1)

    Examples
    --------
    >>> to_homogeneous([[1, 2], [3, 4]])
    array([[1., 2., 1.],
           [3., 4., 1.]])
    """
    p = as_points(points, "points", dims=(1, 2, 3))
    return np.concatenate([p, np.ones(p.shape[:-1] + (1,))], axis=-1)


def from_homogeneous(points):
    """Divide by the last coordinate and drop it: ``(..., d + 1)`` -> ``(..., d)``.

    This is the *homogeneous divide* (the perspective divide of chapter 4).

    Parameters
    ----------
    points : array_like, shape (..., d + 1)

    Returns
    -------
    ndarray, shape (..., d)

    Raises
    ------
    ValueError
        If a point has last coordinate 0: it is a point at infinity (a direction), which has no
        Cartesian coordinates.

    Examples
    --------
    >>> from_homogeneous([2, 4, 6, 2])
    array([1., 2., 3.])
    """
    p = as_points(points, "points", dims=(2, 3, 4))
    w = p[..., -1:]
    if np.any(np.abs(w) < 1e-300):
        raise ValueError("points contains a point with homogeneous coordinate w = 0: it lies at "
                         "infinity (it is a direction) and has no Cartesian coordinates")
    return p[..., :-1] / w


def apply(M, points):
    r"""Apply the transformation `M` to many points at once, with the homogeneous divide.

    Each point :math:`p` (a row of `points`) becomes :math:`M \begin{bmatrix} p \\ 1
    \end{bmatrix}`, divided by its last coordinate :math:`w`. For affine matrices :math:`w` stays
    1; projective matrices (chapter 4) need the division. A 3x3 matrix given 3D points is used as
    a plain linear map (no homogeneous coordinate).

    Parameters
    ----------
    M : array_like, shape (3, 3) or (4, 4)
        A 2D homogeneous matrix (3x3) for 2D points, a 3D one (4x4) for 3D points, or a 3x3
        linear map for 3D points.
    points : array_like, shape (..., 2) or (..., 3)
        One point or any stack of points, as rows.

    Returns
    -------
    ndarray, same shape as `points`

    Raises
    ------
    ValueError
        If the matrix size does not fit the points' dimension, or a point is mapped to infinity.

    Examples
    --------
    >>> import numpy as np
    >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> apply(translate([2, 3]), square)
    array([[2., 3.],
           [3., 3.],
           [3., 4.],
           [2., 4.]])
    >>> apply(np.diag([1, 1, 1, 2.0]), [2, 4, 6])    # w = 2: the result is divided by it
    array([1., 2., 3.])
    """
    m = as_matrix(M, "M")
    p = as_points(points, "points")
    d = p.shape[-1]
    if m.shape[0] == d:          # a 3x3 linear map applied to 3D points
        return p @ m.T
    if m.shape[0] != d + 1:
        raise ValueError(f"M is {m.shape[0]}x{m.shape[0]} but the points are {d}D: use a "
                         f"{d + 1}x{d + 1} homogeneous matrix for {d}D points")
    # one product for all d + 1 output coordinates, then in-place updates: big temporary arrays
    # cost more than the arithmetic (fresh memory has to be faulted in)
    out = p @ m[:, :d].T
    out += m[:, d]
    w = out[..., d]
    if np.all(w == 1.0):
        return out[..., :d]
    if np.any(np.abs(w) < 1e-300):
        raise ValueError("M maps a point to infinity (homogeneous coordinate w = 0 after the "
                         "transformation)")
    out[..., :d] /= w[..., None]
    return out[..., :d]
