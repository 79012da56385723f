"""Input checks shared by every algorithm module: one place, clear messages.

Every public function of ``course_lib`` passes its arguments through these helpers first, so that
a student's typo ends in a ``ValueError`` or ``TypeError`` that names the argument and says what
was expected, never in a NaN or a traceback from deep inside numpy.
"""
import numbers

import numpy as np

__all__ = [
    "as_array",
    "as_choice",
    "as_mesh",
    "as_positive",
    "as_rgb",
    "as_rng",
    "as_whole",
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


# ---------------------------------------------------------------------------------------------
# Counts, positive numbers, choices, triangle meshes, colours, random generators
# (each check once; the modules call these instead of keeping their own copies)
# ---------------------------------------------------------------------------------------------

def as_whole(value, name, minimum=0, *, integer_type=False, at_least=False):
    """Return `value` as an int >= `minimum` (a count, a size, a depth), or raise naming `name`.

    A float that is a whole number (``3.0``, as a slider gives) is accepted, unless
    `integer_type`: then only integer types are (``3.0`` is a TypeError, as for an index).
    A bool is never a number here: ``True`` would silently count as 1.

    Parameters
    ----------
    value : int or float
    name : str
        The argument's name, for the message.
    minimum : int
        The smallest value allowed.
    integer_type : bool
        Reject every value that is not of an integer type (TypeError), even a whole float.
    at_least : bool
        Word a value below `minimum` as "`name` must be at least `minimum`" (and a fraction
        as "must be a whole number"), instead of "`name` must be a whole number >= `minimum`";
        the messages of curves, surfaces and mesh read so.

    Returns
    -------
    int

    Raises
    ------
    TypeError
        For a bool, a string or None (and with `integer_type` any non-integer type).
    ValueError
        For a fraction, NaN, infinity, an array, or a value below `minimum`.

    Examples
    --------
    >>> as_whole(3.0, "samples", 1)
    3
    >>> as_whole(0, "samples", 1)
    Traceback (most recent call last):
    ...
    ValueError: samples must be a whole number >= 1, got 0
    >>> as_whole(2.5, "degree", at_least=True)
    Traceback (most recent call last):
    ...
    ValueError: degree must be a whole number, got 2.5
    >>> as_whole(True, "n")
    Traceback (most recent call last):
    ...
    TypeError: n must be a whole number, got a bool
    """
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name} must be a whole number, got a bool")
    wanted = "a whole number" if at_least else f"a whole number >= {minimum}"
    if integer_type:
        if not isinstance(value, numbers.Integral):
            raise TypeError(f"{name} must be {wanted}, got {value!r}")
        number = int(value)
    else:
        x = as_scalar(value, name)
        if not x.is_integer():
            raise ValueError(f"{name} must be {wanted}, got {x!r}")
        number = int(x)
    if number < minimum:
        bound = f"at least {minimum}" if at_least else wanted
        raise ValueError(f"{name} must be {bound}, got {number}")
    return number


def as_positive(value, name, what=None):
    """Return `value` as a finite float > 0 (a radius, a step, a length), or raise naming `name`.

    Parameters
    ----------
    value : float
    name : str
        The argument's name, for the message.
    what : str, optional
        What the number is, added to the message in parentheses ("the sphere's radius").

    Returns
    -------
    float

    Raises
    ------
    TypeError
        For a string or None.
    ValueError
        For zero, a negative number, NaN, infinity or an array.

    Examples
    --------
    >>> as_positive(2, "radius")
    2.0
    >>> as_positive(0, "radius", "the sphere's radius")
    Traceback (most recent call last):
    ...
    ValueError: radius must be positive (the sphere's radius), got 0
    """
    v = as_scalar(value, name)
    if not v > 0:
        raise ValueError(f"{name} must be positive{f' ({what})' if what else ''}, got {v:g}")
    return v


def as_choice(value, name, options):
    """Return `value` if it is one of `options` (names of methods, modes, kinds), else raise.

    Parameters
    ----------
    value : object
    name : str
        The argument's name, for the message.
    options : sequence
        The allowed values, listed in the message in this order.

    Returns
    -------
    object
        `value` itself.

    Raises
    ------
    ValueError
        For any other value.

    Examples
    --------
    >>> as_choice("rk4", "method", ("euler", "rk2", "rk4"))
    'rk4'
    >>> as_choice("rk3", "method", ("euler", "rk2", "rk4"))
    Traceback (most recent call last):
    ...
    ValueError: method must be one of 'euler', 'rk2', 'rk4', got 'rk3'
    """
    try:
        if value in options:
            return value
    except (TypeError, ValueError):                 # e.g. an array compared with a name
        pass
    raise ValueError(f"{name} must be one of {', '.join(map(repr, options))}, got {value!r}")


def as_mesh(vertices, faces, faces_name="faces", *, empty=False):
    """Return a triangle mesh as ``(vertices, faces)``: float (n, 3) and intp (m, 3) arrays.

    The rule: a mesh has at least one vertex and at least one triangle, and every index refers
    to a vertex. A single triangle ``[a, b, c]`` is accepted as ``[[a, b, c]]``. A measure of a
    surface (its area, its volume) passes ``empty=True``: the isosurface of a level the data
    never takes has no triangles, and its area is 0, not an error.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
        Finite vertex positions, n >= 1.
    faces : array_like of int, shape (m, 3)
        Vertex indices of the triangles, m >= 1.
    faces_name : str
        The name of the faces argument, for the messages ("faces", "triangles").
    empty : bool
        Accept a mesh without triangles (and then without vertices): (0, 3) arrays.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    faces : ndarray of intp, shape (m, 3)

    Raises
    ------
    ValueError
        For malformed vertices, faces that are not an (m, 3) integer array, an empty face
        list, or an index outside 0..n-1.

    Examples
    --------
    >>> v, f = as_mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [0, 1, 2])
    >>> v.shape, f.tolist()
    ((3, 3), [[0, 1, 2]])
    >>> as_mesh(v, [[0, 1, 3]])
    Traceback (most recent call last):
    ...
    ValueError: faces refers to vertex 3 but there are 3 vertices
    >>> [a.shape for a in as_mesh(np.zeros((0, 3)), np.zeros((0, 3), int), empty=True)]
    [(0, 3), (0, 3)]
    """
    v = as_points(vertices, "vertices", dims=3)
    if empty and v.ndim == 2 and np.size(faces) == 0:
        return v, np.zeros((0, 3), np.intp)
    if v.ndim != 2 or len(v) == 0:
        raise ValueError(f"vertices must be an (n, 3) array with n >= 1, got shape {v.shape}")
    try:
        f = np.asarray(faces)
    except (TypeError, ValueError):                 # ragged lists
        raise ValueError(f"{faces_name} must be an (m, 3) array of vertex indices (triangles "
                         f"only), got {_kind(faces)} of rows of different lengths") from None
    if f.size == 0 and f.ndim in (1, 2) and f.shape[-1] in (0, 3):       # [] or (0, 3)
        raise ValueError(f"{faces_name} must contain at least one triangle, got an empty array")
    if f.shape == (3,):
        f = f[None]
    if f.ndim != 2 or f.shape[1] != 3 or not _is_integer_array(f):
        raise ValueError(f"{faces_name} must be an (m, 3) array of vertex indices (triangles "
                         f"only), got shape {f.shape} and type {f.dtype}")
    low, high = int(f.min()), int(f.max())
    if low < 0 or high >= len(v):
        bad = high if high >= len(v) else low
        raise ValueError(f"{faces_name} refers to vertex {bad} but there are {len(v)} vertices")
    return v, f.astype(np.intp)


def as_rgb(value, name, *, maximum=1.0, grey=True, single=False):
    """Return `value` as RGB colours, shape ``(..., 3)``, or raise naming `name`.

    Two kinds of RGB triple pass through here: a colour or reflectance, each component in
    [0, 1] (the default), and a light's intensity, non-negative and unbounded
    (``maximum=None``). Components within 1e-9 of the range (rounding) are clipped onto it.

    Parameters
    ----------
    value : float or array_like, shape (3,) or (..., 3)
    name : str
        The argument's name, for the messages.
    maximum : float or None
        The largest component allowed; None for no bound (intensities).
    grey : bool
        Accept a single number as the grey ``(g, g, g)``, and ``(..., 1)`` stacks of greys
        (returned as they are: they broadcast against RGB).
    single : bool
        Accept one triple only (or a number), not a stack.

    Returns
    -------
    ndarray, shape (3,) or (..., 3) (or (..., 1) for greys)

    Raises
    ------
    TypeError
        For strings or None.
    ValueError
        For a wrong shape, NaN, infinity, or a component outside the range.

    Examples
    --------
    >>> as_rgb(0.5, "color")
    array([0.5, 0.5, 0.5])
    >>> as_rgb([2.0, 2.0, 1.0], "intensity", maximum=None)
    array([2., 2., 1.])
    >>> as_rgb([[0, 0, 0], [1.2, 0, 0]], "rgb", grey=False)
    Traceback (most recent call last):
    ...
    ValueError: rgb must lie in [0, 1], got 1.2 at index (1, 0)
    """
    c = as_array(value, name)
    high = np.inf if maximum is None else maximum
    bad = (c < -1e-9) | (c > high + 1e-9)
    if bad.any():
        index = tuple(int(i) for i in np.argwhere(bad)[0])
        where = "" if not index else f" at index {index if len(index) > 1 else index[0]}"
        rule = "not be negative" if maximum is None else f"lie in [0, {maximum:g}]"
        raise ValueError(f"{name} must {rule}, got {c[index]:g}{where}")
    if grey and c.ndim == 0:
        c = np.full(3, float(c))
    if single and c.shape != (3,):
        raise ValueError(f"{name} must be {'a number (grey) or ' if grey else ''}an RGB triple "
                         f"(r, g, b), got shape {c.shape}")
    if c.ndim == 0 or c.shape[-1] not in ((1, 3) if grey else (3,)):
        raise ValueError(f"{name} must be {'a number (grey) or ' if grey else ''}RGB triples "
                         f"with 3 components (r, g, b) in the last axis (shape (3,) or "
                         f"(..., 3)), got shape {c.shape}")
    return np.clip(c, 0.0, high)


def as_rng(seed, name="seed"):
    """Return a ``numpy.random.Generator`` for `seed`; a Generator passes through unchanged.

    Parameters
    ----------
    seed : None, int >= 0, numpy.random.Generator, SeedSequence or BitGenerator
        None gives fresh entropy (a different result every run); a whole number the same
        sequence every run; a Generator is used (and advanced) as it is.
    name : str
        The argument's name, for the message.

    Returns
    -------
    numpy.random.Generator

    Raises
    ------
    TypeError
        For a bool, a float, a string or any other type.
    ValueError
        For a negative seed.

    Examples
    --------
    >>> g = np.random.default_rng(1)
    >>> as_rng(g) is g
    True
    >>> as_rng(-1)
    Traceback (most recent call last):
    ...
    ValueError: seed must be None, a whole number >= 0 or a numpy.random.Generator, got -1
    """
    if isinstance(seed, np.random.Generator):
        return seed
    wanted = f"{name} must be None, a whole number >= 0 or a numpy.random.Generator"
    if seed is None or isinstance(seed, (np.random.SeedSequence, np.random.BitGenerator)):
        return np.random.default_rng(seed)
    if isinstance(seed, (bool, np.bool_)):
        raise TypeError(f"{wanted}, got a bool")
    if not isinstance(seed, numbers.Integral):
        raise TypeError(f"{wanted}, got {_kind(seed)}")
    if seed < 0:
        raise ValueError(f"{wanted}, got {int(seed)}")
    return np.random.default_rng(int(seed))


def _is_integer_array(a):
    return np.issubdtype(a.dtype, np.integer) and not np.issubdtype(a.dtype, np.bool_)


def _or(items):
    items = [str(i) for i in items]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " or " + items[-1]


def _kind(value):
    if value is None:
        return "None"
    if value is Ellipsis:
        return "... (nothing filled in)"
    return f"a {type(value).__name__}"
