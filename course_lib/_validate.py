"""Input checks shared by every algorithm module: one place, clear messages.

Every public function of ``course_lib`` passes its arguments through these helpers first, so that
a student's typo ends in a ``ValueError`` or ``TypeError`` that names the argument and says what
was expected, never in a NaN or a traceback from deep inside numpy.
"""
import numbers

import numpy as np

__all__ = [
    "as_array",
    "broadcast_stacks",
    "as_matrix",
    "as_points",
    "as_quaternions",
    "as_rotation_matrix",
    "as_scalar",
    "as_unit_vector",
    "as_vector",
]


def as_array(value, name):
    """Return `value` as a finite float array, or raise naming `name`.

    Examples
    --------
    >>> as_array([1, 2], "p")
    array([1., 2.])
    >>> as_array("abc", "p")
    Traceback (most recent call last):
    ...
    TypeError: p must be numbers, got a str
    """
    if isinstance(value, (str, bytes)) or value is None or value is Ellipsis:
        raise TypeError(f"{name} must be numbers, got {_kind(value)}")
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be numbers (an array of equal-length rows), "
                        f"got {_kind(value)}") from None
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} must be finite, got a value that is NaN or infinite")
    return arr


def as_scalar(value, name):
    """Return `value` as a finite float, or raise naming `name`.

    Examples
    --------
    >>> as_scalar(2, "theta")
    2.0
    >>> as_scalar([1, 2], "theta")
    Traceback (most recent call last):
    ...
    ValueError: theta must be a single number, got shape (2,)
    """
    if isinstance(value, (str, bytes)) or value is None or value is Ellipsis:
        raise TypeError(f"{name} must be a number, got {_kind(value)}")
    arr = as_array(value, name)
    if arr.shape != ():
        raise ValueError(f"{name} must be a single number, got shape {arr.shape}")
    return float(arr)


def as_vector(value, name, dim):
    """Return `value` as a finite float vector of length `dim` (an int or a tuple of allowed ints).

    Examples
    --------
    >>> as_vector([1, 2, 3], "d", 3)
    array([1., 2., 3.])
    >>> as_vector([1, 2], "d", 3)
    Traceback (most recent call last):
    ...
    ValueError: d must be a vector of 3 numbers, got shape (2,)
    """
    dims = (dim,) if isinstance(dim, int) else tuple(dim)
    v = as_array(value, name)
    if v.ndim != 1 or v.shape[0] not in dims:
        raise ValueError(f"{name} must be a vector of {_or(dims)} numbers, got shape {v.shape}")
    return v


def as_unit_vector(value, name, dim=3):
    """Like `as_vector`, normalized; a zero vector has no direction and is rejected.

    Examples
    --------
    >>> as_unit_vector([0, 0, 2], "axis")
    array([0., 0., 1.])
    >>> as_unit_vector([0, 0, 0], "axis")
    Traceback (most recent call last):
    ...
    ValueError: axis must not be the zero vector: it has no direction
    """
    v = as_vector(value, name, dim)
    length = np.linalg.norm(v)
    if length < 1e-12:
        raise ValueError(f"{name} must not be the zero vector: it has no direction")
    return v / length


def as_points(value, name, dims=(2, 3)):
    """Return `value` as a float array of points shaped ``(..., d)`` with `d` in `dims`.

    A single point ``[x, y]`` is accepted as well as an ``(n, 2)`` array of points.

    Examples
    --------
    >>> as_points([[0, 1], [2, 3]], "points").shape
    (2, 2)
    >>> as_points([[0, 1, 2, 3]], "points")
    Traceback (most recent call last):
    ...
    ValueError: points must have 2 or 3 coordinates in the last axis (shape (..., 2) or (..., 3)), got shape (1, 4)
    """
    dims = (dims,) if isinstance(dims, int) else tuple(dims)
    p = as_array(value, name)
    if p.ndim == 0 or p.shape[-1] not in dims:
        shapes = " or ".join(f"(..., {d})" for d in dims)
        raise ValueError(f"{name} must have {_or(dims)} coordinates in the last axis "
                         f"(shape {shapes}), got shape {p.shape}")
    return p


def as_quaternions(value, name, nonzero=True):
    """Return `value` as quaternions ``(s, x, y, z)``, shape ``(..., 4)``; zero ones are rejected.

    Examples
    --------
    >>> as_quaternions([1, 0, 0, 0], "q")
    array([1., 0., 0., 0.])
    >>> as_quaternions([0, 1, 0], "q")
    Traceback (most recent call last):
    ...
    ValueError: q must have 4 components (s, x, y, z) in the last axis, got shape (3,)
    >>> as_quaternions([0, 0, 0, 0], "q")
    Traceback (most recent call last):
    ...
    ValueError: q must not be the zero quaternion: it has no inverse and represents no rotation
    """
    q = as_array(value, name)
    if q.ndim == 0 or q.shape[-1] != 4:
        raise ValueError(f"{name} must have 4 components (s, x, y, z) in the last axis, "
                         f"got shape {q.shape}")
    if nonzero and np.any(np.einsum("...i,...i->...", q, q) < 1e-24):
        raise ValueError(f"{name} must not be the zero quaternion: it has no inverse and "
                         "represents no rotation")
    return q


def as_matrix(value, name, sizes=(3, 4)):
    """Return `value` as a square float matrix whose size is one of `sizes`.

    Examples
    --------
    >>> as_matrix(np.eye(3), "M").shape
    (3, 3)
    >>> as_matrix(np.ones((3, 4)), "M")
    Traceback (most recent call last):
    ...
    ValueError: M must be a 3x3 or 4x4 matrix, got shape (3, 4)
    """
    sizes = (sizes,) if isinstance(sizes, int) else tuple(sizes)
    m = as_array(value, name)
    if m.ndim != 2 or m.shape[0] != m.shape[1] or m.shape[0] not in sizes:
        wanted = " or ".join(f"{n}x{n}" for n in sizes)
        raise ValueError(f"{name} must be a {wanted} matrix, got shape {m.shape}")
    return m


def as_rotation_matrix(value, name, atol=1e-6):
    """Return `value` as a stack of 3x3 rotation matrices, shape ``(..., 3, 3)``.

    A homogeneous 4x4 matrix is accepted when it is a pure rotation (no translation, no
    projective row). The matrix must be orthonormal (``R^T R = I``) with determinant +1, within
    `atol`; a mirror (determinant -1), a scale or a shear is rejected with the reason.

    Examples
    --------
    >>> as_rotation_matrix(np.eye(4), "m").shape
    (3, 3)
    >>> as_rotation_matrix(np.diag([1.0, 1.0, -1.0]), "m")
    Traceback (most recent call last):
    ...
    ValueError: m is not a rotation: its determinant is -1, so it contains a mirroring
    """
    m = as_array(value, name)
    if m.ndim < 2 or m.shape[-2:] not in ((3, 3), (4, 4)):
        raise ValueError(f"{name} must be a 3x3 rotation matrix or a homogeneous 4x4 one "
                         f"(shape (..., 3, 3) or (..., 4, 4)), got shape {m.shape}")
    if m.shape[-1] == 4:
        extra = np.concatenate([m[..., 3, :3], m[..., :3, 3]], axis=-1)
        if not (np.allclose(extra, 0, atol=atol) and np.allclose(m[..., 3, 3], 1, atol=atol)):
            raise ValueError(f"{name} is a 4x4 matrix with a translation or a projective part; "
                             "only a pure rotation has a quaternion")
        m = m[..., :3, :3]
    gram_error = np.abs(np.swapaxes(m, -1, -2) @ m - np.eye(3)).max(axis=(-2, -1))
    det = np.linalg.det(m)
    bad = (gram_error > atol) | (np.abs(det - 1) > atol)
    if bad.any():
        index = np.unravel_index(np.argmax(bad), bad.shape) if bad.ndim else ()
        where = f" (matrix at index {tuple(int(i) for i in index)})" if bad.ndim else ""
        d, g = float(np.asarray(det)[index]), float(np.asarray(gram_error)[index])
        if abs(abs(d) - 1) < atol and d < 0 and g <= atol:
            reason = "its determinant is -1, so it contains a mirroring"
        else:
            reason = (f"R^T R differs from the identity by up to {g:.3g} and det(R) = {d:.6g}; "
                      "a rotation is orthonormal with determinant +1")
        raise ValueError(f"{name} is not a rotation{where}: {reason}")
    return m


def broadcast_stacks(**stacks):
    """The common shape of the leading axes of several stacks, or a ValueError naming them.

    Each keyword is ``name=(array, trailing)``: the array and how many of its last axes are one
    item (1 for vectors and quaternions, 0 for scalars such as angles).

    Examples
    --------
    >>> broadcast_stacks(q=(np.ones((5, 4)), 1), points=(np.ones((5, 3)), 1))
    (5,)
    >>> broadcast_stacks(q=(np.ones((3, 4)), 1), points=(np.ones((2, 3)), 1))
    Traceback (most recent call last):
    ...
    ValueError: q holds a stack of shape (3,) and points one of shape (2,): they must be equal, or one of them a single item
    """
    leading = {name: np.shape(a)[:np.ndim(a) - trailing] for name, (a, trailing) in stacks.items()}
    names = list(leading)
    for i, first in enumerate(names):
        for second in names[i + 1:]:
            try:
                np.broadcast_shapes(leading[first], leading[second])
            except ValueError:
                raise ValueError(f"{first} holds a stack of shape {leading[first]} and {second} "
                                 f"one of shape {leading[second]}: they must be equal, or one of "
                                 "them a single item") from None
    return np.broadcast_shapes(*leading.values())


def _or(items):
    items = [str(i) for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " or " + items[-1]


def _kind(value):
    if value is None:
        return "None"
    if value is Ellipsis:
        return "... (nothing filled in)"
    return f"a {type(value).__name__}"
