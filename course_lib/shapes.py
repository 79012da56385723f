"""Small test shapes for figures, widgets and exercises (numpy only).

The letter F is the course's standard object: it has no symmetry at all, so every rotation,
mirroring or shear of it can be told apart from every other at a glance.
"""
import numpy as np

from ._validate import as_positive, as_whole

__all__ = ["letter_f", "letter_f_3d", "torus", "unit_square"]

_F_OUTLINE = np.array([
    [0.0, 0.0], [0.35, 0.0], [0.35, 0.6], [0.8, 0.6], [0.8, 0.9], [0.35, 0.9],
    [0.35, 1.2], [1.0, 1.2], [1.0, 1.5], [0.0, 1.5],
])


def letter_f(closed=True):
    """The outline of a letter F in the unit box [0, 1] x [0, 1.5], counter-clockwise.

    Parameters
    ----------
    closed : bool, optional
        Repeat the first point at the end, ready for ``plot``.

    Returns
    -------
    ndarray, shape (11, 2) or (10, 2)

    Examples
    --------
    >>> letter_f().shape, letter_f(closed=False).shape
    ((11, 2), (10, 2))
    """
    return np.vstack([_F_OUTLINE, _F_OUTLINE[:1]]) if closed else _F_OUTLINE.copy()


def letter_f_3d(thickness=0.3, center=True):
    """A letter F extruded along z, as vertices and polygonal faces (outward orientation).

    The front face (z = thickness) and the back face (z = 0) are the two F outlines; each edge of
    the outline adds a rectangular side face. Faces are listed counter-clockwise seen from
    outside, so their normals (right-hand rule) point outwards.

    Parameters
    ----------
    thickness : float, optional
    center : bool, optional
        Move the F so that its bounding box is centred on the origin (handy for rotations).

    Returns
    -------
    vertices : ndarray, shape (20, 3)
    faces : list of lists of int
        ``faces[0]`` is the front face, ``faces[1]`` the back face, then the 10 sides.

    Examples
    --------
    >>> v, f = letter_f_3d()
    >>> v.shape, len(f), [len(face) for face in f[:3]]
    ((20, 3), 12, [10, 10, 4])
    """
    n = len(_F_OUTLINE)
    back = np.column_stack([_F_OUTLINE, np.zeros(n)])
    front = np.column_stack([_F_OUTLINE, np.full(n, float(thickness))])
    vertices = np.vstack([back, front])
    if center:
        vertices = vertices - (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    faces = [list(range(n, 2 * n)), list(range(n - 1, -1, -1))]
    faces += [[i, (i + 1) % n, n + (i + 1) % n, n + i] for i in range(n)]
    return vertices, faces


def unit_square(closed=True):
    """The unit square [0, 1]^2, counter-clockwise from the origin.

    Examples
    --------
    >>> unit_square(closed=False)
    array([[0., 0.],
           [1., 0.],
           [1., 1.],
           [0., 1.]])
    """
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    return np.vstack([square, square[:1]]) if closed else square


def torus(major=1.0, minor=0.4, segments=24, rings=12):
    """A closed triangle mesh of a torus around the z axis, faces oriented outwards.

    Parameters
    ----------
    major, minor : float
        Radius of the centre circle and of the tube.
    segments, rings : int
        Divisions around the z axis and around the tube (at least 3 each).

    Returns
    -------
    vertices : ndarray, shape (segments * rings, 3)
    faces : ndarray of int, shape (2 * segments * rings, 3)
        Counter-clockwise seen from outside.

    Examples
    --------
    >>> v, f = torus(segments=8, rings=4)
    >>> v.shape, f.shape
    ((32, 3), (64, 3))

    Closed, of genus 1 (:mod:`course_lib.mesh` counts it):

    >>> from course_lib.mesh import HalfEdgeMesh
    >>> HalfEdgeMesh.from_faces(*torus()).genus()
    1
    """
    major, minor = as_positive(major, "major"), as_positive(minor, "minor")
    segments = as_whole(segments, "segments", 3, integer_type=True, at_least=True)
    rings = as_whole(rings, "rings", 3, integer_type=True, at_least=True)
    u = np.linspace(0, 2 * np.pi, segments, endpoint=False)[:, None]
    v = np.linspace(0, 2 * np.pi, rings, endpoint=False)[None, :]
    radius = major + minor * np.cos(v)
    vertices = np.stack(np.broadcast_arrays(radius * np.cos(u), radius * np.sin(u),
                                            minor * np.sin(v)), axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(segments), np.arange(rings), indexing="ij")
    a = i * rings + j
    b = ((i + 1) % segments) * rings + j
    c = ((i + 1) % segments) * rings + (j + 1) % rings
    d = i * rings + (j + 1) % rings
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                            np.stack([a, c, d], -1).reshape(-1, 3)])
    return vertices, faces
