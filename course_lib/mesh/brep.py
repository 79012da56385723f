r"""A minimal boundary representation (B-rep) and the Euler-Poincaré formula with rings.

A B-rep stores a solid by its boundary: **vertices**, **edges** and **faces**, where a face is
bounded by one **outer loop** and any number of **inner loops** (rings): the rim of a hole in
the face, such as the mouth of a drilled hole in the top face of a block. Loops list vertex
indices; an outer loop runs counter-clockwise seen from outside the solid, an inner loop
clockwise, so that the material of the face is always on the left. Every edge is then used
once in each direction by the loops of a closed solid.

The counts of a valid solid obey the **Euler-Poincaré formula**

.. math:: V - E + F - R = 2 (S - H),

with :math:`R` the rings (inner loops), :math:`S` the shells (connected boundary surfaces) and
:math:`H` the through-holes (the genus, summed over the shells). Without rings it is the mesh
formula :math:`V - E + F = 2 - 2g` of one closed surface. A face with a ring is not a disc, so
it is not a face in the mesh sense; cutting it into discs (e.g. triangulating it) adds edges,
one more than it adds faces per ring, and the :math:`-R` disappears: the triangulated solid
has :math:`V - E + F = 2(S - H)`, which :func:`brep_triangulate` lets you check.

Examples (:func:`brep_cube`, :func:`brep_drilled_cube`, :func:`brep_pocket_cube`,
:func:`brep_two_cubes`):

=======================  ===  ===  ===  ===  ===  ===  ====================
solid                    V    E    F    R    S    H    V - E + F - R
=======================  ===  ===  ===  ===  ===  ===  ====================
cube                     8    12   6    0    1    0    2 = 2(1 - 0)
cube with a through-hole 16   24   10   2    1    1    0 = 2(1 - 1)
cube with a pocket       16   24   11   1    1    0    2 = 2(1 - 0)
two separate cubes       16   24   12   0    2    0    4 = 2(2 - 0)
=======================  ===  ===  ===  ===  ===  ===  ====================
"""

import numpy as np

from .._validate import as_positive, as_whole
from ._common import _vertices

__all__ = ["BRep", "brep_counts", "brep_cube", "brep_drilled_cube", "brep_pocket_cube",
           "brep_triangulate", "brep_two_cubes", "euler_poincare_check"]


class BRep:
    """A boundary representation: vertices, and faces made of an outer loop and inner loops.

    Parameters
    ----------
    vertices : array_like, shape (n, 3)
    faces : sequence of sequences of loops
        ``faces[f][0]`` is the outer loop of face f (a list of at least 3 vertex indices,
        counter-clockwise seen from outside), ``faces[f][1:]`` its inner loops (rings,
        clockwise seen from outside).

    Raises
    ------
    ValueError
        A loop with fewer than 3 vertices or a repeated vertex, an index out of range, or loops
        that do not close the solid (an edge not used exactly once in each direction).

    Examples
    --------
    >>> b = brep_drilled_cube()
    >>> b.V, b.E, b.F, b.R, b.S, b.H
    (16, 24, 10, 2, 1, 1)
    """

    def __init__(self, vertices, faces):
        self.vertices = _vertices(vertices)
        if isinstance(faces, (str, bytes)) or not hasattr(faces, "__len__") or len(faces) == 0:
            raise TypeError("faces must be a non-empty list of faces, each a list of loops")
        n = len(self.vertices)
        loops = []
        for f, face in enumerate(faces):
            if isinstance(face, (str, bytes)) or not hasattr(face, "__len__") or len(face) == 0:
                raise TypeError(f"faces[{f}] must be a list of loops (outer loop first), "
                                f"got {face!r}")
            this = []
            for k, loop in enumerate(face):
                arr = np.asarray(loop)
                if arr.ndim != 1 or not np.issubdtype(arr.dtype, np.integer):
                    raise TypeError(f"faces[{f}][{k}] must be a list of vertex indices, "
                                    f"got {loop!r}")
                if len(arr) < 3 or len(np.unique(arr)) != len(arr):
                    raise ValueError(f"faces[{f}][{k}] must have at least 3 distinct vertices, "
                                     f"got {arr.tolist()}")
                if arr.min() < 0 or arr.max() >= n:
                    raise ValueError(f"faces[{f}][{k}] refers to a vertex outside 0..{n - 1}: "
                                     f"{arr.tolist()}")
                this.append(arr.astype(np.int64))
            loops.append(this)
        self.faces = loops
        self._check_closed()

    def _directed(self):
        """The directed edges (a, b) of all loops, and the face of each."""
        pairs, owner = [], []
        for f, face in enumerate(self.faces):
            for loop in face:
                pairs.append(np.column_stack([loop, np.roll(loop, -1)]))
                owner.append(np.full(len(loop), f))
        return np.concatenate(pairs), np.concatenate(owner)

    def _check_closed(self):
        d, _ = self._directed()
        keys, counts = np.unique(d, axis=0, return_counts=True)
        if np.any(counts > 1):
            a, b = keys[np.argmax(counts > 1)]
            raise ValueError(f"the edge {a}->{b} is used twice in the same direction: the "
                             "loops are not consistently oriented (outer loops "
                             "counter-clockwise, inner loops clockwise seen from outside)")
        code = d[:, 0] * len(self.vertices) + d[:, 1]
        back = d[:, 1] * len(self.vertices) + d[:, 0]
        missing = ~np.isin(back, code)
        if np.any(missing):
            a, b = d[np.argmax(missing)]
            raise ValueError(f"the edge {a}->{b} has no partner {b}->{a}: the faces do not "
                             "close the solid (every edge must bound exactly two faces)")

    @property
    def V(self):
        """The number of vertices used by the loops."""
        return int(len(np.unique(np.concatenate([l for f in self.faces for l in f]))))

    @property
    def E(self):
        """The number of edges: the directed loop edges, each edge counted once."""
        return int(len(self._directed()[0]) // 2)

    @property
    def F(self):
        """The number of faces."""
        return len(self.faces)

    @property
    def R(self):
        """The number of rings: inner loops, over all faces."""
        return int(sum(len(face) - 1 for face in self.faces))

    @property
    def S(self):
        """The number of shells: groups of faces connected through shared edges."""
        d, owner = self._directed()
        parent = np.arange(self.F)

        def root(i):
            while parent[i] != i:
                parent[i] = parent[parent[i]]
                i = parent[i]
            return i

        index = {(int(a), int(b)): int(f) for (a, b), f in zip(d, owner)}
        for (a, b), f in zip(d, owner):
            ra, rb = root(int(f)), root(index[(int(b), int(a))])
            if ra != rb:
                parent[max(ra, rb)] = min(ra, rb)
        return int(len({root(i) for i in range(self.F)}))

    @property
    def H(self):
        r"""The number of through-holes, from the formula: :math:`H = S - (V - E + F - R)/2`."""
        return int(self.S - (self.V - self.E + self.F - self.R) // 2)


def brep_counts(brep):
    """The counts V, E, F, R, S, H of a B-rep as a dict.

    Examples
    --------
    >>> brep_counts(brep_pocket_cube())
    {'V': 16, 'E': 24, 'F': 11, 'R': 1, 'S': 1, 'H': 0}
    """
    if not isinstance(brep, BRep):
        raise TypeError(f"brep must be a BRep, got a {type(brep).__name__}")
    return {k: getattr(brep, k) for k in "VEFRSH"}


def euler_poincare_check(V, E, F, R, S, H):
    r"""Check :math:`V - E + F - R = 2(S - H)` for the counts of a solid.

    Parameters
    ----------
    V, E, F, R, S, H : int >= 0
        Vertices, edges, faces, rings (inner loops), shells (at least 1) and through-holes.

    Returns
    -------
    int
        The common value :math:`V - E + F - R`.

    Raises
    ------
    ValueError
        If the counts disagree: the message names them and both sides.

    Examples
    --------
    >>> euler_poincare_check(16, 24, 10, 2, 1, 1)              # the drilled cube
    0
    >>> euler_poincare_check(16, 24, 10, 0, 1, 1)              # the two rings forgotten
    Traceback (most recent call last):
    ...
    ValueError: inconsistent counts V=16, E=24, F=10, R=0, S=1, H=1: V - E + F - R = 2 but 2(S - H) = 0
    """
    counts = {"V": V, "E": E, "F": F, "R": R, "S": S, "H": H}
    c = {k: as_whole(v, k, minimum=1 if k == "S" else 0) for k, v in counts.items()}
    left = c["V"] - c["E"] + c["F"] - c["R"]
    right = 2 * (c["S"] - c["H"])
    if left != right:
        names = ", ".join(f"{k}={v}" for k, v in c.items())
        raise ValueError(f"inconsistent counts {names}: V - E + F - R = {left} but "
                         f"2(S - H) = {right}")
    return left


def brep_triangulate(brep):
    """Triangles of the faces of a B-rep, without new vertices: a mesh to count with.

    A face without rings (convex) becomes a fan from its first vertex. A face with one ring
    whose inner loop has as many vertices as the outer loop (a square hole in a square face)
    becomes the strip of quads between the two loops, two triangles each. Other faces are
    refused.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    triangles : ndarray of int, shape (m, 3)

    Raises
    ------
    ValueError
        For a face with more than one ring, or a ring that does not match its outer loop.

    Examples
    --------
    >>> v, t = brep_triangulate(brep_drilled_cube())
    >>> V, F = len(v), len(t)
    >>> E = 3 * F // 2                                          # closed: 2 triangles an edge
    >>> V, E, F, V - E + F                                      # 2 - 2g with g = 1
    (16, 48, 32, 0)
    """
    if not isinstance(brep, BRep):
        raise TypeError(f"brep must be a BRep, got a {type(brep).__name__}")
    v = brep.vertices
    tris = []
    for f, face in enumerate(brep.faces):
        outer = face[0]
        if len(face) == 1:
            tris += [(outer[0], outer[k], outer[k + 1]) for k in range(1, len(outer) - 1)]
            continue
        if len(face) > 2 or len(face[1]) != len(outer):
            raise ValueError(f"faces[{f}] has rings that brep_triangulate cannot cut: only one "
                             "ring with as many vertices as the outer loop is supported")
        inner = face[1][::-1]                      # counter-clockwise, like the outer loop
        start = int(np.argmin(np.linalg.norm(v[inner] - v[outer[0]], axis=1)))
        inner = np.roll(inner, -start)
        m = len(outer)
        for k in range(m):
            a, b = outer[k], outer[(k + 1) % m]
            c, d = inner[(k + 1) % m], inner[k]
            tris += [(a, b, c), (a, c, d)]
    return v.copy(), np.array(tris, dtype=np.int64)


# ---------------------------------------------------------------------------------------------
# Example solids
# ---------------------------------------------------------------------------------------------

def _box_loops(lo, hi, first=0):
    """The 8 corners of the box [lo, hi] and its 6 faces, counter-clockwise from outside."""
    i = np.arange(8)
    bits = np.column_stack([i & 1, (i >> 1) & 1, (i >> 2) & 1])
    corners = np.where(bits == 1, hi, lo).astype(float)
    quads = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]
    return corners, [[[first + q for q in quad]] for quad in quads]


def brep_cube(size=1.0):
    """The cube [0, size]^3 as a B-rep: V=8, E=12, F=6, R=0, S=1, H=0.

    Examples
    --------
    >>> brep_counts(brep_cube())
    {'V': 8, 'E': 12, 'F': 6, 'R': 0, 'S': 1, 'H': 0}
    """
    s = as_positive(size, "size")
    v, faces = _box_loops(np.zeros(3), np.full(3, s))
    return BRep(v, faces)


def _drilled(depth):
    """The cube [0, 3]^3 with the square [1, 2]^2 cut down from the top, to z = 3 - depth."""
    sq = np.array([[0, 0], [3, 0], [3, 3], [0, 3]], float)          # outer, ccw from +z
    hole = np.array([[1, 1], [1, 2], [2, 2], [2, 1]], float)        # cw from +z (a ring)
    bottom_z = 3.0 - depth
    v = np.vstack([np.column_stack([sq, np.zeros(4)]),             # 0-3 bottom corners
                   np.column_stack([sq, np.full(4, 3.0)]),         # 4-7 top corners
                   np.column_stack([hole, np.full(4, 3.0)]),       # 8-11 mouth of the hole
                   np.column_stack([hole, np.full(4, bottom_z)])])  # 12-15 its lower end
    top_ring = [8, 9, 10, 11]
    faces = [[[4, 5, 6, 7], top_ring],                             # top, with a ring
             [[0, 1, 5, 4]], [[1, 2, 6, 5]], [[2, 3, 7, 6]], [[3, 0, 4, 7]]]   # the 4 sides
    for k in range(4):                                             # the walls of the hole
        a, b = top_ring[k], top_ring[(k + 1) % 4]
        faces.append([[a + 4, b + 4, b, a]])
    lower_ring = [15, 14, 13, 12]                                  # reversed: cw from below
    if depth >= 3.0:                                               # through: bottom ring
        faces.append([[0, 3, 2, 1], lower_ring])
    else:                                                          # pocket: a floor
        faces.append([[0, 3, 2, 1]])
        faces.append([lower_ring])
    return v, faces


def brep_drilled_cube():
    r"""The cube [0, 3]^3 with a square through-hole [1, 2]^2 along z.

    Counted by hand: 8 corners of the block plus 4 corners of the hole's mouth on the top and 4
    on the bottom, :math:`V = 16`; 12 edges of the block, 4 + 4 around the two mouths and 4
    along the hole, :math:`E = 24`; 6 faces of the block and 4 walls of the hole,
    :math:`F = 10`; the top and bottom faces each have an inner loop, :math:`R = 2`; one shell,
    one through-hole: :math:`S = 1, H = 1`. Check:
    :math:`16 - 24 + 10 - 2 = 0 = 2(1 - 1)`.

    Examples
    --------
    >>> brep_counts(brep_drilled_cube())
    {'V': 16, 'E': 24, 'F': 10, 'R': 2, 'S': 1, 'H': 1}
    """
    v, faces = _drilled(3.0)
    return BRep(v, faces)


def brep_pocket_cube(depth=2.0):
    r"""The cube [0, 3]^3 with a square blind pocket [1, 2]^2 cut ``depth`` down from the top.

    The top face has one ring, the pocket has 4 walls and a floor: :math:`V = 16`,
    :math:`E = 24`, :math:`F = 11`, :math:`R = 1`, :math:`S = 1`, :math:`H = 0`:
    :math:`16 - 24 + 11 - 1 = 2 = 2(1 - 0)`. A pocket is a ring but no hole.

    Parameters
    ----------
    depth : float, 0 < depth < 3

    Examples
    --------
    >>> brep_counts(brep_pocket_cube())
    {'V': 16, 'E': 24, 'F': 11, 'R': 1, 'S': 1, 'H': 0}
    """
    d = as_positive(depth, "depth")
    if d >= 3:
        raise ValueError(f"depth must be between 0 and 3 (exclusive; 3 is a through-hole), "
                         f"got {depth!r}")
    v, faces = _drilled(d)
    return BRep(v, faces)


def brep_two_cubes(gap=1.0):
    """Two separate unit cubes, ``gap`` apart along x: two shells, S = 2.

    Examples
    --------
    >>> brep_counts(brep_two_cubes())
    {'V': 16, 'E': 24, 'F': 12, 'R': 0, 'S': 2, 'H': 0}
    """
    g = as_positive(gap, "gap", "the cubes must not touch")
    v1, f1 = _box_loops(np.zeros(3), np.ones(3))
    v2, f2 = _box_loops(np.array([1 + g, 0, 0]), np.array([2 + g, 1, 1]), first=8)
    return BRep(np.vstack([v1, v2]), f1 + f2)
