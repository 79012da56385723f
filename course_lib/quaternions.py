r"""Chapter 3: quaternions, scalar first, for rotations in 3D.

A quaternion :math:`q = (s, \mathbf{v}) = (s, x, y, z) = s + x\,i + y\,j + z\,k` is stored as an
array whose last axis holds the four numbers **scalar first**, as in the textbook. (scipy's
``Rotation`` stores them scalar *last*, ``(x, y, z, s)``: convert with ``q[..., [1, 2, 3, 0]]``.)
Every function works on one quaternion, shape ``(4,)``, or on any stack of them, shape
``(..., 4)``, with numpy broadcasting.

The unit quaternion :math:`q = (\cos\frac{\theta}{2}, \sin\frac{\theta}{2}\,\hat{n})` rotates a
point :math:`p` by the angle :math:`\theta` about the axis :math:`\hat n` through the origin:
:math:`p' = q\, p\, \bar q`, where :math:`p` is written as the pure quaternion :math:`(0, p)`.
:math:`q` and :math:`-q` give the same rotation (the quaternions cover the rotations twice).
"""
import numpy as np

from ._linalg import dot as _dot
from ._validate import (as_array, as_points, as_quaternions, as_rotation_matrix,
                        broadcast_stacks)

__all__ = [
    "angle_between",
    "conjugate",
    "from_axis_angle",
    "from_matrix",
    "identity",
    "inverse",
    "multiply",
    "nlerp",
    "norm",
    "normalize",
    "rotate",
    "slerp",
    "to_axis_angle",
    "to_matrix",
]


def identity():
    """The identity quaternion (1, 0, 0, 0): the rotation by 0.

    Returns
    -------
    ndarray, shape (4,)

    Examples
    --------
    >>> identity()
    array([1., 0., 0., 0.])
    """
    return np.array([1.0, 0.0, 0.0, 0.0])


def from_axis_angle(axis, angle):
    r"""The unit quaternion of the rotation by `angle` radians about `axis`.

    .. math:: q = \left(\cos\frac{\theta}{2},\ \sin\frac{\theta}{2}\,\hat n\right),
              \qquad \hat n = \frac{\text{axis}}{\lVert \text{axis} \rVert}

    Note the half angle: a quaternion turns by :math:`\theta` because it acts twice, once from
    each side, in :math:`q\,p\,\bar q`.

    Parameters
    ----------
    axis : array_like, shape (..., 3)
        Rotation axes (any non-zero length; they are normalized).
    angle : float or array_like, shape (...)
        Angles in radians, counter-clockwise when looking from the tip of the axis.

    Returns
    -------
    ndarray, shape (..., 4)

    Raises
    ------
    ValueError
        If an axis is the zero vector (it has no direction) or a value is not finite.

    Examples
    --------
    >>> import numpy as np
    >>> np.round(from_axis_angle([0, 0, 1], np.pi / 2), 6)
    array([0.707107, 0.      , 0.      , 0.707107])
    """
    axis = as_points(axis, "axis", dims=3)
    angle = as_array(angle, "angle")
    broadcast_stacks(axis=(axis, 1), angle=(angle, 0))
    length = np.linalg.norm(axis, axis=-1)
    if np.any(length < 1e-12):
        raise ValueError("axis must not be the zero vector: it has no direction")
    half = 0.5 * angle
    n = axis / length[..., None]
    s = np.cos(half)
    v = np.sin(half)[..., None] * n
    s = np.broadcast_to(s, v.shape[:-1])
    return np.concatenate([s[..., None], v], axis=-1)


def to_axis_angle(q):
    r"""Axis and angle of the rotation that the quaternion `q` represents.

    With :math:`q` normalized and turned so that :math:`s \ge 0` (allowed, as :math:`-q` is the
    same rotation): :math:`\theta = 2\,\operatorname{atan2}(\lVert v \rVert, s) \in [0, \pi]` and
    :math:`\hat n = v / \lVert v \rVert`. For the identity (:math:`\theta = 0`) every axis is
    right; ``(1, 0, 0)`` is returned.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Non-zero quaternions, not necessarily of unit length.

    Returns
    -------
    axis : ndarray, shape (..., 3)
        Unit axes.
    angle : ndarray, shape (...)
        Angles in radians, in [0, pi].

    Examples
    --------
    >>> import numpy as np
    >>> axis, angle = to_axis_angle(from_axis_angle([0, 2, 0], 1.25))
    >>> np.round(axis, 12), round(float(angle), 12)
    (array([0., 1., 0.]), 1.25)
    """
    q = normalize(q)
    q = np.where(q[..., :1] < 0, -q, q)
    v = q[..., 1:]
    vnorm = np.linalg.norm(v, axis=-1)
    angle = 2.0 * np.arctan2(vnorm, q[..., 0])
    safe = vnorm > 1e-15
    axis = np.where(safe[..., None], v / np.where(safe, vnorm, 1.0)[..., None], [1.0, 0.0, 0.0])
    return axis, angle


def multiply(q1, q2):
    r"""The Hamilton product :math:`q_1 q_2` (not commutative).

    .. math:: (s_1, v_1)(s_2, v_2) = (s_1 s_2 - v_1 \cdot v_2,\;
              s_1 v_2 + s_2 v_1 + v_1 \times v_2)

    As rotations, :math:`q_1 q_2` first rotates by :math:`q_2`, then by :math:`q_1`, just as the
    matrix product :math:`R_1 R_2` does.

    Parameters
    ----------
    q1, q2 : array_like, shape (..., 4)
        Quaternions; the stacks broadcast against each other.

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> i, j = [0, 1, 0, 0], [0, 0, 1, 0]
    >>> multiply(i, j), multiply(j, i)      # ij = k but ji = -k
    (array([0., 0., 0., 1.]), array([ 0.,  0.,  0., -1.]))
    """
    a = as_quaternions(q1, "q1", nonzero=False)
    b = as_quaternions(q2, "q2", nonzero=False)
    broadcast_stacks(q1=(a, 1), q2=(b, 1))
    s1, x1, y1, z1 = np.moveaxis(a, -1, 0)
    s2, x2, y2, z2 = np.moveaxis(b, -1, 0)
    return np.stack([
        s1 * s2 - x1 * x2 - y1 * y2 - z1 * z2,
        s1 * x2 + x1 * s2 + y1 * z2 - z1 * y2,
        s1 * y2 - x1 * z2 + y1 * s2 + z1 * x2,
        s1 * z2 + x1 * y2 - y1 * x2 + z1 * s2,
    ], axis=-1)


def conjugate(q):
    r"""The conjugate :math:`\bar q = (s, -v)`; for a unit quaternion it is the inverse rotation.

    Parameters
    ----------
    q : array_like, shape (..., 4)

    Returns
    -------
    ndarray, shape (..., 4)

    Examples
    --------
    >>> conjugate([1, 2, 3, 4])
    array([ 1., -2., -3., -4.])
    """
    q = as_quaternions(q, "q", nonzero=False)
    return q * np.array([1.0, -1.0, -1.0, -1.0])


def norm(q):
    r"""The length :math:`\lVert q \rVert = \sqrt{s^2 + x^2 + y^2 + z^2} = \sqrt{q \bar q}`.

    Parameters
    ----------
    q : array_like, shape (..., 4)

    Returns
    -------
    float or ndarray, shape (...)

    Examples
    --------
    >>> float(norm([1, 1, 1, 1]))
    2.0
    """
    q = as_quaternions(q, "q", nonzero=False)
    peak = np.abs(q).max(axis=-1)
    scaled = q / np.where(peak > 0, peak, 1.0)[..., None]
    return peak * np.sqrt(_dot(scaled, scaled))


def normalize(q):
    r"""The unit quaternion :math:`q / \lVert q \rVert` (the same rotation as `q`).

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Non-zero quaternions.

    Returns
    -------
    ndarray, shape (..., 4)

    Raises
    ------
    ValueError
        For the zero quaternion, which has no direction.

    Examples
    --------
    >>> normalize([0, 0, 3, 4])
    array([0. , 0. , 0.6, 0.8])
    """
    return _unit_quaternion(as_quaternions(q, "q"))


def _unit_quaternion(q):
    """q / |q|, scaled first by its largest component so that squaring cannot overflow."""
    q = q / np.abs(q).max(axis=-1, keepdims=True)
    return q / np.sqrt(_dot(q, q))[..., None]


def inverse(q):
    r"""The multiplicative inverse :math:`q^{-1} = \bar q / \lVert q \rVert^2`.

    For a unit quaternion the inverse equals the conjugate, which is why the textbook writes
    :math:`p' = q p \bar q`; for other quaternions the two differ.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Non-zero quaternions.

    Returns
    -------
    ndarray, shape (..., 4)

    Raises
    ------
    ValueError
        For the zero quaternion.

    Examples
    --------
    >>> inverse([0, 0, 2, 0])
    array([ 0. ,  0. , -0.5,  0. ])
    >>> multiply([0, 0, 2, 0], inverse([0, 0, 2, 0]))
    array([1., 0., 0., 0.])
    """
    q = as_quaternions(q, "q")
    return conjugate(_unit_quaternion(q)) / norm(q)[..., None]


def rotate(q, points):
    r"""Rotate 3D points by the quaternion `q`: :math:`p' = q\,(0, p)\,\bar q`.

    `q` is normalized first (with a non-unit quaternion, :math:`q p \bar q` would also scale the
    point by :math:`\lVert q \rVert^2`). Multiplying out the two Hamilton products for a unit
    :math:`q = (s, \mathbf v)` gives

    .. math:: p' = p + 2s\,(\mathbf v \times p) + 2\,\mathbf v \times (\mathbf v \times p),

    which is what is computed: the same result as ``multiply(multiply(q, (0, p)),
    conjugate(q))[1:]`` with 18 instead of 28 multiplications per point.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Non-zero quaternions.
    points : array_like, shape (..., 3)
        Points as rows; they broadcast against `q` (one quaternion and many points, or one
        quaternion per point).

    Returns
    -------
    ndarray, shape (..., 3)

    Examples
    --------
    >>> import numpy as np
    >>> q = from_axis_angle([0, 0, 1], np.pi / 2)
    >>> np.round(rotate(q, [[1, 0, 0], [0, 1, 0]]), 12)
    array([[ 0.,  1.,  0.],
           [-1.,  0.,  0.]])
    """
    q = normalize(q)
    p = as_points(points, "points", dims=3)
    broadcast_stacks(q=(q, 1), points=(p, 1))
    s, v = q[..., :1], q[..., 1:]
    t = 2.0 * np.cross(v, p)
    return p + s * t + np.cross(v, t)


def to_matrix(q, homogeneous=False):
    r"""The rotation matrix of the quaternion :math:`q = (s, x, y, z)`.

    For a unit quaternion:

    .. math:: R_q = \begin{bmatrix}
              1 - 2y^2 - 2z^2 & 2xy - 2sz & 2xz + 2sy \\
              2xy + 2sz & 1 - 2x^2 - 2z^2 & 2yz - 2sx \\
              2xz - 2sy & 2yz + 2sx & 1 - 2x^2 - 2y^2 \end{bmatrix}

    (The course compendium prints the top-left entry as :math:`1 - 2y^2`; that matrix is not a
    rotation.) A non-unit quaternion is handled exactly by replacing each factor 2 by
    :math:`2 / \lVert q \rVert^2`, which gives the rotation of :math:`q / \lVert q \rVert`.

    Parameters
    ----------
    q : array_like, shape (..., 4)
        Non-zero quaternions.
    homogeneous : bool, optional
        Return 4x4 homogeneous matrices (as in the textbook) instead of 3x3 ones.

    Returns
    -------
    ndarray, shape (..., 3, 3) or (..., 4, 4)

    Examples
    --------
    >>> import numpy as np
    >>> np.round(to_matrix(from_axis_angle([1, 0, 0], np.pi / 2)), 12)
    array([[ 1.,  0.,  0.],
           [ 0.,  0., -1.],
           [ 0.,  1.,  0.]])
    """
    q = as_quaternions(q, "q", nonzero=False)
    n = 4 if homogeneous else 3
    flat = q.reshape(-1, 4)
    count = flat.shape[0]
    # Planar layout, in blocks: every temporary below is one contiguous row of at most _BLOCK
    # numbers, so it stays in cache and numpy never allocates (and page-faults) big temporaries.
    # This keeps the function within reach of scipy's compiled code (see benchmarks/).
    planar = flat.T.copy()
    out = np.zeros((n, n, count))
    for lo in range(0, count, _BLOCK):
        s, x, y, z = planar[:, lo:lo + _BLOCK]
        o = out[..., lo:lo + _BLOCK]
        with np.errstate(over="ignore"):
            norm2 = s * s + x * x + y * y + z * z
        if not np.all((norm2 >= 1e-24) & (norm2 < 1e300)):
            if np.any(norm2 < 1e-24):
                raise ValueError("q must not be the zero quaternion: it has no inverse and "
                                 "represents no rotation")
            # huge components: squaring them overflowed; rescale this block and start again
            s, x, y, z = planar[:, lo:lo + _BLOCK] / np.abs(planar[:, lo:lo + _BLOCK]).max(0)
            norm2 = s * s + x * x + y * y + z * z
        k = 2.0 / norm2
        xk, yk, zk = x * k, y * k, z * k
        xx, yy, zz = x * xk, y * yk, z * zk
        xy, xz, yz = x * yk, x * zk, y * zk
        sx, sy, sz = s * xk, s * yk, s * zk
        np.subtract(1.0 - yy, zz, out=o[0, 0])
        np.subtract(xy, sz, out=o[0, 1])
        np.add(xz, sy, out=o[0, 2])
        np.add(xy, sz, out=o[1, 0])
        np.subtract(1.0 - xx, zz, out=o[1, 1])
        np.subtract(yz, sx, out=o[1, 2])
        np.subtract(xz, sy, out=o[2, 0])
        np.add(yz, sx, out=o[2, 1])
        np.subtract(1.0 - xx, yy, out=o[2, 2])
    if homogeneous:
        out[3, 3] = 1.0
    return np.moveaxis(out, -1, 0).reshape(q.shape[:-1] + (n, n))


_BLOCK = 8192


def from_matrix(m, atol=1e-6):
    r"""The unit quaternion of a rotation matrix, exact for every rotation (Shepperd's method).

    The textbook's recipe, :math:`s = \frac12\sqrt{1 + m_{00} + m_{11} + m_{22}}` and
    :math:`x = (m_{21} - m_{12}) / 4s`, ..., divides by :math:`s`, which is 0 for a turn by 180
    degrees and small near it: the result is then inaccurate or undefined. Each of the four
    components can be found from the diagonal the same way:

    .. math:: 4s^2 = 1 + m_{00} + m_{11} + m_{22}, \quad 4x^2 = 1 + m_{00} - m_{11} - m_{22},
    .. math:: 4y^2 = 1 - m_{00} + m_{11} - m_{22}, \quad 4z^2 = 1 - m_{00} - m_{11} + m_{22}

    The largest of the four is at least 1/4, so taking its square root and dividing the
    off-diagonal sums and differences by it (e.g. for :math:`x`:
    :math:`s = (m_{21} - m_{12})/4x`, :math:`y = (m_{01} + m_{10})/4x`,
    :math:`z = (m_{02} + m_{20})/4x`) is always well conditioned.

    Parameters
    ----------
    m : array_like, shape (..., 3, 3) or (..., 4, 4)
        Rotation matrices (a 4x4 one must be a pure rotation: no translation).
    atol : float, optional
        Tolerance of the check that `m` is a rotation.

    Returns
    -------
    ndarray, shape (..., 4)
        Unit quaternions with :math:`s \ge 0` (of the pair :math:`\pm q`, the one with the
        non-negative scalar part).

    Raises
    ------
    ValueError
        If `m` is not a rotation matrix (not orthonormal, or a mirror with determinant -1).

    Examples
    --------
    >>> import numpy as np
    >>> half_turn = np.diag([1.0, -1.0, -1.0])        # 180 degrees about x: s = 0
    >>> from_matrix(half_turn)
    array([0., 1., 0., 0.])
    """
    r = as_rotation_matrix(m, "m", atol=atol)
    m00, m01, m02 = r[..., 0, 0], r[..., 0, 1], r[..., 0, 2]
    m10, m11, m12 = r[..., 1, 0], r[..., 1, 1], r[..., 1, 2]
    m20, m21, m22 = r[..., 2, 0], r[..., 2, 1], r[..., 2, 2]
    # 4 * (s^2, x^2, y^2, z^2), from the diagonal
    four_sq = np.stack([1 + m00 + m11 + m22, 1 + m00 - m11 - m22,
                        1 - m00 + m11 - m22, 1 - m00 - m11 + m22], axis=-1)
    best = np.argmax(four_sq, axis=-1)
    big = 0.5 * np.sqrt(np.take_along_axis(four_sq, best[..., None], axis=-1)[..., 0])
    # 4 * (pairwise products): row b holds 4*c_b*(s, x, y, z) for the largest component c_b
    diff_x, diff_y, diff_z = m21 - m12, m02 - m20, m10 - m01
    sum_xy, sum_xz, sum_yz = m01 + m10, m02 + m20, m12 + m21
    rows = np.stack([
        np.stack([4 * big * big, diff_x, diff_y, diff_z], axis=-1),
        np.stack([diff_x, 4 * big * big, sum_xy, sum_xz], axis=-1),
        np.stack([diff_y, sum_xy, 4 * big * big, sum_yz], axis=-1),
        np.stack([diff_z, sum_xz, sum_yz, 4 * big * big], axis=-1),
    ], axis=-2)
    q = np.take_along_axis(rows, best[..., None, None], axis=-2)[..., 0, :] / (4 * big[..., None])
    q = np.where(q[..., :1] < 0, -q, q)
    return q / np.sqrt(_dot(q, q))[..., None]


def angle_between(q0, q1):
    r"""The angle of the rotation that takes orientation `q0` to orientation `q1`.

    .. math:: \theta = 2 \arccos \lvert \hat q_0 \cdot \hat q_1 \rvert \in [0, \pi]

    (the absolute value because :math:`q` and :math:`-q` are the same orientation). It is the
    geodesic distance between the two orientations.

    Parameters
    ----------
    q0, q1 : array_like, shape (..., 4)
        Non-zero quaternions.

    Returns
    -------
    float or ndarray, shape (...)
        Angles in radians.

    Examples
    --------
    >>> import numpy as np
    >>> q = from_axis_angle([0, 1, 0], 0.5)
    >>> round(float(angle_between(identity(), q)), 12), round(float(angle_between(q, -q)), 12)
    (0.5, 0.0)
    """
    a, b = normalize(q0), normalize(q1)
    broadcast_stacks(q0=(a, 1), q1=(b, 1))
    b = np.where((_dot(a, b) < 0)[..., None], -b, b)
    # arccos|a.b| is the angle between the two 4D unit vectors; 2 atan2(|a - b|, |a + b|) is the
    # same angle but stays accurate when it is tiny, where arccos of a number near 1 loses digits
    return 4.0 * np.arctan2(np.linalg.norm(a - b, axis=-1), np.linalg.norm(a + b, axis=-1))


def slerp(q0, q1, t, shortest=True):
    r"""Spherical linear interpolation between two orientations.

    .. math:: \operatorname{slerp}(q_0, q_1; t) = \frac{\sin((1-t)\Omega)}{\sin\Omega}\, q_0
              + \frac{\sin(t\Omega)}{\sin\Omega}\, q_1, \qquad \cos\Omega = q_0 \cdot q_1

    The result moves along the great arc of the unit 4D sphere at constant speed: the object
    turns about one fixed axis with constant angular velocity. With ``shortest=True`` (the
    default) :math:`q_1` is replaced by :math:`-q_1` when :math:`q_0 \cdot q_1 < 0`, so that the
    shorter of the two ways round is taken. When :math:`\Omega` is tiny the formula is replaced by
    normalized linear interpolation, which agrees with it to rounding error.

    Parameters
    ----------
    q0, q1 : array_like, shape (..., 4)
        Start and end orientations (non-zero; they are normalized).
    t : float or array_like
        Interpolation parameter(s), 0 gives `q0` and 1 gives `q1`; values outside [0, 1]
        extrapolate along the same arc. An array of `t` with single `q0`, `q1` gives one
        quaternion per `t`.
    shortest : bool, optional
        Take the shorter way round (default True).

    Returns
    -------
    ndarray, shape ``t.shape + (4,)`` broadcast with the quaternions' leading axes

    Examples
    --------
    >>> import numpy as np
    >>> q0, q1 = identity(), from_axis_angle([0, 0, 1], np.pi / 2)
    >>> np.allclose(slerp(q0, q1, 0.5), from_axis_angle([0, 0, 1], np.pi / 4))
    True
    >>> slerp(q0, q1, [0, 0.5, 1]).shape
    (3, 4)
    """
    a = normalize(q0)
    b = normalize(q1)
    t = as_array(t, "t")
    broadcast_stacks(q0=(a, 1), q1=(b, 1), t=(t, 0))
    d = _dot(a, b)
    if shortest:
        b = np.where((d < 0)[..., None], -b, b)
        d = np.abs(d)
    d = np.clip(d, -1.0, 1.0)
    omega = np.arccos(d)
    sin_omega = np.sin(omega)
    tt = t[..., None]
    small = sin_omega < 1e-9
    safe_sin = np.where(small, 1.0, sin_omega)[..., None]
    om = omega[..., None]
    w0 = np.where(small[..., None], 1.0 - tt, np.sin((1.0 - tt) * om) / safe_sin)
    w1 = np.where(small[..., None], tt, np.sin(tt * om) / safe_sin)
    q = w0 * a + w1 * b
    return q / np.sqrt(_dot(q, q))[..., None]


def nlerp(q0, q1, t, shortest=True):
    r"""Normalized linear interpolation: :math:`\frac{(1-t) q_0 + t q_1}{\lVert \cdot \rVert}`.

    It follows the same great arc as :func:`slerp` but not at constant speed: it moves slower
    near the ends and faster in the middle (for a 180 degree turn, noticeably). It is cheaper,
    which is why games often use it for small steps.

    Parameters
    ----------
    q0, q1 : array_like, shape (..., 4)
        Start and end orientations (non-zero).
    t : float or array_like
        Interpolation parameter(s).
    shortest : bool, optional
        Flip `q1` when :math:`q_0 \cdot q_1 < 0` (default True).

    Returns
    -------
    ndarray, shape ``t.shape + (4,)`` broadcast with the quaternions' leading axes

    Raises
    ------
    ValueError
        If the interpolated quaternion is zero (opposite quaternions with ``shortest=False``
        at their midpoint).

    Examples
    --------
    >>> import numpy as np
    >>> q0, q1 = identity(), from_axis_angle([0, 0, 1], np.pi / 2)
    >>> np.allclose(nlerp(q0, q1, 0.5), slerp(q0, q1, 0.5))   # equal at the midpoint only
    True
    """
    a = normalize(q0)
    b = normalize(q1)
    t = as_array(t, "t")
    broadcast_stacks(q0=(a, 1), q1=(b, 1), t=(t, 0))
    t = t[..., None]
    if shortest:
        b = np.where((_dot(a, b) < 0)[..., None], -b, b)
    q = (1.0 - t) * a + t * b
    return normalize(q)
