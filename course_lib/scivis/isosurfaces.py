"""Chapter 18 (lesson section 3): isosurfaces by marching cubes."""

from functools import lru_cache

import numpy as np

from .._validate import as_array, as_choice, as_mesh, as_scalar, as_vector, as_whole
from ._common import _grid, _spacing
from .contour_lines import SQUARE_SADDLES_CENTRE_ABOVE, SQUARE_TABLE

__all__ = ["CENTRE", "CUBE_CORNERS", "CUBE_EDGES", "cube_triangles", "enclosed_volume",
    "gradient", "marching_cubes", "marching_cubes_cases", "surface_area"]


# ---------------------------------------------------------------------------------------------
# Marching cubes
# ---------------------------------------------------------------------------------------------
# Corner and edge numbering of Lorensen and Cline (1987) as in Paul Bourke's "Polygonising a
# scalar field" (1994), which most implementations follow:
#
#          7 ------ e6 ------ 6          z
#         /|                 /|          |  y
#       e7 |               e5 |          | /
#       /  e11             /  e10        |/
#      4 ------ e4 ------ 5   |          +----- x
#      |   |              |   |
#      |   3 ------ e2 ---|-- 2
#      e8 /               e9 /
#      | e3               | e1
#      |/                 |/
#      0 ------ e0 ------ 1

#: Corner k of a cube -> its (x, y, z) offset from corner 0.
CUBE_CORNERS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                         [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])

#: Edge k of a cube -> its two corners, the one with smaller coordinates first.
CUBE_EDGES = np.array([[0, 1], [1, 2], [3, 2], [0, 3], [4, 5], [5, 6], [7, 6], [4, 7],
                       [0, 4], [1, 5], [2, 6], [3, 7]])

# The six faces (z = 0, z = 1, y = 0, y = 1, x = 0, x = 1), each as its corners in
# counter-clockwise order seen from outside the cube: marching squares runs on each of them.
_CUBE_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5))
_EDGE_OF = {frozenset(map(int, pair)): k for k, pair in enumerate(CUBE_EDGES)}
_FACE_EDGES = tuple(tuple(_EDGE_OF[frozenset((cyc[m], cyc[(m + 1) % 4]))] for m in range(4))
                    for cyc in _CUBE_FACES)


def _face_case(case, face):
    return sum(((case >> q) & 1) << m for m, q in enumerate(_CUBE_FACES[face]))


def _ambiguous_faces(case):
    """Bit mask of the faces on which `case` has a saddle (diagonal corners above)."""
    return sum(1 << f for f in range(6) if _face_case(case, f) in (5, 10))


_EDGE_FACES = tuple(frozenset(f for f in range(6) if e in _FACE_EDGES[f]) for e in range(12))

#: In a triangle of :func:`cube_triangles`, this number stands for the extra vertex at the
#: centroid of a long loop (8 or more vertices).
CENTRE = 12


def _triangulate_loop(loop):
    """Triangles (i, m, j) of loop positions, none of whose diagonals lies in a cube face.

    A diagonal between two vertices on the same face would run along that face, where the
    neighbouring cube may draw the same diagonal: the edge would then belong to four
    triangles. Diagonals through the cube's interior are never shared. Returns None if no
    such triangulation exists (it always exists for loops of up to 7 vertices).
    """
    n = len(loop)

    def allowed(i, k):
        return k - i == 1 or not (_EDGE_FACES[loop[i]] & _EDGE_FACES[loop[k]])

    @lru_cache(maxsize=None)
    def solve(i, j):                          # the sub-polygon i, i+1, ..., j (chord i-j given)
        if j - i < 2:
            return ()
        for m in range(i + 1, j):
            if allowed(i, m) and allowed(m, j):
                left, right = solve(i, m), solve(m, j)
                if left is not None and right is not None:
                    return left + right + ((i, m, j),)
        return None

    return solve(0, n - 1)


def _trace_cube(case, connected):
    """One cube's triangles (edge triples, CENTRE for a loop's centroid) and the centre loop.

    Chain the six faces' isoline segments into loops, then triangulate each loop.
    """
    nxt = {}
    for f in range(6):
        sq = _face_case(case, f)
        segments = SQUARE_TABLE[sq]
        if sq in SQUARE_SADDLES_CENTRE_ABOVE and (connected >> f) & 1:
            segments = SQUARE_SADDLES_CENTRE_ABOVE[sq]
        for a, b in segments:
            nxt[_FACE_EDGES[f][a]] = _FACE_EDGES[f][b]
    triangles, centre_loop = [], ()
    while nxt:
        start = min(nxt)
        loop, e = [start], nxt.pop(start)
        while e != start:
            loop.append(e)
            e = nxt.pop(e)
        # The loop runs clockwise seen from the lower values, so every triangle is wound the
        # other way round to put its normal towards lower values.
        fan = _triangulate_loop(loop) if len(loop) < 8 else None
        if fan is None:                       # long loops: a fan around an extra centre vertex
            centre_loop = tuple(loop)
            n = len(loop)
            triangles += [(CENTRE, loop[(m + 1) % n], loop[m]) for m in range(n)]
        else:
            triangles += [(loop[i], loop[j], loop[m]) for i, m, j in fan]
    return triangles, centre_loop


def cube_triangles(case, connected_faces=0):
    """The triangles of one marching-cubes case, as triples of cube edge numbers.

    The table entry is built, not copied (see the module docstring): the isoline segments of
    the six faces (marching squares on each, seen from outside) chain into closed loops around
    the cube, and each loop is cut into a fan of triangles.

    Parameters
    ----------
    case : int
        0-255; bit k set when corner k (:data:`CUBE_CORNERS`) is above the level.
    connected_faces : int
        A 6-bit mask for the ambiguous faces: bit f set means that on face f (order z = 0,
        z = 1, y = 0, y = 1, x = 0, x = 1) the two above corners are connected through the
        face (the asymptotic decider found its saddle above the level). Bits of faces that are
        not ambiguous in this case are ignored.

    Returns
    -------
    ndarray of int, shape (k, 3)
        Each row: the edges (:data:`CUBE_EDGES`) on which the triangle's vertices lie, wound
        counter-clockwise seen from the side of lower values. Loops of up to 7 vertices are
        cut by diagonals through the cube's interior (never along a face, where a neighbour
        could draw the same diagonal); the rare loops of 8 or more vertices (only with
        ambiguous faces) are fanned around an extra vertex at their centroid, written
        :data:`CENTRE` (12).

    Examples
    --------
    Corner 0 alone above the level: one triangle cutting it off, on edges 0 (x), 3 (y) and 8
    (z); corners 0 and 1 above: a quadrilateral, two triangles:

    >>> cube_triangles(1)
    array([[0, 3, 8]])
    >>> cube_triangles(0b11).shape
    (2, 3)
    """
    case = as_whole(case, "case", 0)
    if case > 255:
        raise ValueError(f"case must be a whole number in 0-255 (8 corner bits), got {case}")
    connected = as_whole(connected_faces, "connected_faces", 0)
    if connected > 63:
        raise ValueError(f"connected_faces must be a 6-bit mask (0-63), got {connected}")
    triangles, _ = _trace_cube(case, connected & _ambiguous_faces(case))
    return np.array(triangles, dtype=np.intp).reshape(-1, 3)


@lru_cache(maxsize=1)
def _cube_lookup():
    """The whole table, index case + 256 * connected (ambiguous faces only) -> triangles,
    their count, and a 12-bit mask of the edges of the loop that has a centre vertex."""
    entries = {}
    for case in range(256):
        amb = _ambiguous_faces(case)
        sub = amb
        while True:                              # every subset of the ambiguous faces
            entries[case | (sub << 8)] = _trace_cube(case, sub)
            if sub == 0:
                break
            sub = (sub - 1) & amb
    most = max(len(t) for t, _ in entries.values())
    table = np.full((256 * 64, most, 3), -1, dtype=np.intp)
    counts = np.zeros(256 * 64, dtype=np.intp)
    centre_mask = np.zeros(256 * 64, dtype=np.intp)
    for index, (triangles, centre_loop) in entries.items():
        if triangles:
            table[index, :len(triangles)] = triangles
        counts[index] = len(triangles)
        centre_mask[index] = sum(1 << e for e in centre_loop)
    return table, counts, centre_mask


def _cube_cases(v, level):
    above = (v >= level).astype(np.uint8)
    nz, ny, nx = v.shape
    cases = np.zeros((nz - 1, ny - 1, nx - 1), dtype=np.uint8)
    for k, (ox, oy, oz) in enumerate(CUBE_CORNERS):
        cases |= above[oz:oz + nz - 1, oy:oy + ny - 1, ox:ox + nx - 1] << k
    return cases


def marching_cubes_cases(volume, level):
    """The case index 0-255 of every cell of a volume (bit k: corner k above the level).

    ``cases[k, j, i]`` is the cell whose corner 0 is ``volume[k, j, i]``; corner offsets as in
    :data:`CUBE_CORNERS` (x along the last axis).

    Examples
    --------
    >>> vol = np.zeros((2, 2, 2)); vol[0, 0, 0] = 1; vol[1, 1, 1] = 1
    >>> marching_cubes_cases(vol, 0.5)                  # corners 0 and 6: 1 + 64
    array([[[65]]])
    """
    v = _grid(volume, "volume", 3)
    return _cube_cases(v, as_scalar(level, "level")).astype(np.intp)


_CORNER_AXIS_ORDER = CUBE_CORNERS[:, ::-1]               # (z, y, x) offsets
_EDGE_AXIS = np.argmax(CUBE_CORNERS[CUBE_EDGES[:, 1]] - CUBE_CORNERS[CUBE_EDGES[:, 0]], axis=1)


#: Per case: corners above the level, and the bit mask of its ambiguous faces.
_CORNERS_ABOVE = np.array([bin(case).count("1") for case in range(256)])
_AMBIGUOUS_FACES = np.array([_ambiguous_faces(case) for case in range(256)], dtype=np.intp)


def _decide_faces(case, base, corner_offset, flat, c):
    """The asymptotic decider: per cell, the 6-bit mask of ambiguous faces joined through."""
    connected = np.zeros(len(case), dtype=np.intp)
    for f, cycle in enumerate(_CUBE_FACES):
        bits = [(case >> q) & 1 for q in cycle]
        ambiguous = (bits[0] == bits[2]) & (bits[1] == bits[3]) & (bits[0] != bits[1])
        if ambiguous.any():
            b = base[ambiguous]
            f0, f1, f2, f3 = (flat[b + corner_offset[q]] for q in cycle)
            saddle = (f0 * f2 - f1 * f3) / ((f0 + f2) - (f1 + f3))
            connected[ambiguous] |= (saddle >= c).astype(np.intp) << f
    return connected


def marching_cubes(volume, level, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0),
                   table="consistent"):
    r"""The isosurface f = level of a volume as a triangle mesh, by marching cubes.

    Every cell gets its case index (:func:`marching_cubes_cases`); ambiguous faces are resolved
    by the asymptotic decider; the table (:func:`cube_triangles`) gives the triangles as cell
    edges; each crossed grid edge gets one vertex, by linear interpolation
    :math:`p = p_0 + t (p_1 - p_0)`, :math:`t = (c - f_0) / (f_1 - f_0)`, shared by all cells
    around that edge. All of it is vectorized over the cells.

    With ``table="classic"`` the ambiguous faces are resolved as in the original table of
    Lorensen and Cline (1987): 15 classes of cases, the others derived by rotation and by
    swapping above and below (complementary symmetry), so that a cube with at most 4 corners
    above cuts those corners off and one with more cuts off the corners below. On an ambiguous
    face (two diagonal corners above, two below) each cube then decides alone, whatever its
    neighbour does; two cubes sharing the face may decide differently, and the surface has a
    **hole** there (edges of one triangle only).

    Parameters
    ----------
    volume : array_like, shape (nz, ny, nx)
        ``volume[k, j, i]`` is the sample at
        :math:`(x_0 + i \Delta x, y_0 + j \Delta y, z_0 + k \Delta z)`.
    level : float
        The isovalue. Outside the data range the surface is empty (not an error).
    spacing : (float, float, float)
        :math:`(\Delta x, \Delta y, \Delta z)`, positive.
    origin : (float, float, float)
        :math:`(x_0, y_0, z_0)`.
    table : {"consistent", "classic"}
        ``"consistent"``: ambiguous faces by the asymptotic decider, the same answer for both
        cubes sharing a face (watertight surfaces); ``"classic"``: each cube by its own corner
        count, as above (holes possible; no long loops, so no centre vertices).

    Returns
    -------
    vertices : ndarray, shape (n, 3)
        (x, y, z) points, one per crossed grid edge, in the order of the edges' numbers
        (position in ``volume.ravel()`` of the edge's lower end, times 3, plus its axis x, y, z
        as 0, 1, 2); then, in rare cells with a long loop (see :func:`cube_triangles`), its
        centroid.
    triangles : ndarray of int, shape (m, 3)
        Vertex indices, counter-clockwise seen from the lower values: normals (right-hand rule)
        point from the region ``volume >= level`` towards lower values. Where the surface does
        not reach the border of the volume it is closed and watertight (each edge shared by
        exactly two triangles, once in each direction).

    Raises
    ------
    ValueError
        For a volume that is not 3D with at least 2 samples per axis, NaN in it, a
        non-positive spacing, or an unknown `table`.

    Examples
    --------
    A single voxel above the level in the middle of a 3 x 3 x 3 volume gives an octahedron
    (6 vertices on the 6 edges around it, 8 triangles), with the enclosed volume positive:

    >>> vol = np.zeros((3, 3, 3)); vol[1, 1, 1] = 1.0
    >>> verts, tris = marching_cubes(vol, 0.5)
    >>> verts.shape, tris.shape
    ((6, 3), (8, 3))
    >>> float(enclosed_volume(verts, tris))          # (4/3) * 0.5**3, a regular octahedron
    0.16666666666666666

    Two cubes sharing an ambiguous face x = 1: the classic table lets the left one (3 corners
    above) separate the face's above corners and the right one (5 above) join them, so edges of
    one triangle only remain (a hole); the consistent table closes it:

    >>> vol = np.zeros((2, 2, 3))
    >>> vol[0, 0, 1] = vol[1, 1, 1] = 1.0                # the shared face x = 1: diagonal
    >>> vol[0, 0, 0] = vol[1, 1, 2] = vol[1, 0, 2] = vol[0, 1, 2] = 1.0
    >>> vol = np.pad(vol, 1)                              # a frame of zeros: surfaces close
    >>> def rims(triangles):                              # edges used by one triangle only
    ...     edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]],
    ...                                     triangles[:, [2, 0]]]), axis=1)
    ...     return int((np.unique(edges, axis=0, return_counts=True)[1] == 1).sum())
    >>> rims(marching_cubes(vol, 0.5, table="classic")[1]), rims(marching_cubes(vol, 0.5)[1])
    (12, 0)
    """
    v = _grid(volume, "volume", 3)
    c = as_scalar(level, "level")
    sp = _spacing(spacing, 3)
    org = as_vector(origin, "origin", 3)
    as_choice(table, "table", ("consistent", "classic"))
    nz, ny, nx = v.shape
    cases = _cube_cases(v, c).ravel()
    active = np.flatnonzero((cases != 0) & (cases != 255))
    if active.size == 0:
        return np.zeros((0, 3)), np.zeros((0, 3), dtype=np.intp)
    case = cases[active].astype(np.intp)
    cz, rest = np.divmod(active, (ny - 1) * (nx - 1))
    cy, cx = np.divmod(rest, nx - 1)
    base = (cz * ny + cy) * nx + cx                       # flat index of each cell's corner 0
    corner_offset = (_CORNER_AXIS_ORDER[:, 0] * ny + _CORNER_AXIS_ORDER[:, 1]) * nx \
        + _CORNER_AXIS_ORDER[:, 2]
    flat = v.ravel()
    if table == "classic":                                # the cube's corner count decides
        connected = np.where(_CORNERS_ABOVE[case] > 4, _AMBIGUOUS_FACES[case], 0)
    else:                                                 # the asymptotic decider
        connected = _decide_faces(case, base, corner_offset, flat, c)
    lookup, counts, centre_mask = _cube_lookup()
    index = case | (connected << 8)
    cell, slot = np.nonzero(np.arange(lookup.shape[1]) < counts[index][:, None])
    edges = lookup[index[cell], slot]                     # (m, 3) cube edge numbers

    def edge_ids(cells, e):                               # a number for every grid edge
        return 3 * (base[cells] + corner_offset[CUBE_EDGES[e, 0]]) + _EDGE_AXIS[e]

    centre = edges == CENTRE
    ids = edge_ids(cell[:, None], np.where(centre, 0, edges))
    ids[centre] = 3 * flat.size + np.broadcast_to(cell[:, None], edges.shape)[centre]
    unique, triangles = np.unique(ids, return_inverse=True)
    n_edge_vertices = int(np.searchsorted(unique, 3 * flat.size))
    point, axis = np.divmod(unique[:n_edge_vertices], 3)
    f0 = flat[point]
    f1 = flat[point + np.array([1, nx, nx * ny])[axis]]
    t = (c - f0) / (f1 - f0)
    iz, rest = np.divmod(point, nx * ny)
    iy, ix = np.divmod(rest, nx)
    index_coords = np.stack([ix, iy, iz], axis=1).astype(float)
    index_coords[np.arange(len(point)), axis] += t
    vertices = org + index_coords * sp
    if n_edge_vertices < len(unique):                     # centroids of long loops
        cells = unique[n_edge_vertices:] - 3 * flat.size
        members = (centre_mask[index[cells]][:, None] >> np.arange(12)) & 1    # (k, 12)
        k, e = np.nonzero(members)
        at = np.searchsorted(unique[:n_edge_vertices], edge_ids(cells[k], e))
        sums = np.zeros((len(cells), 3))
        np.add.at(sums, k, vertices[at])
        vertices = np.concatenate([vertices, sums / members.sum(axis=1)[:, None]])
    return vertices, triangles.reshape(-1, 3).astype(np.intp)


def surface_area(vertices, triangles):
    r"""Total area of a triangle mesh, :math:`\sum \frac12 |(b - a) \times (c - a)|`.

    An empty mesh, as :func:`marching_cubes` returns for a level outside the data's range, has
    area 0.

    Examples
    --------
    >>> surface_area([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    0.5
    >>> surface_area(*marching_cubes(np.zeros((3, 3, 3)), 1.0))
    0.0
    """
    v, t = as_mesh(vertices, triangles, "triangles", empty=True)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum())


def enclosed_volume(vertices, triangles):
    r"""Signed volume enclosed by a closed, consistently wound mesh (divergence theorem).

    .. math:: V = \frac16 \sum_{\text{triangles}} a \cdot (b \times c)

    Each term is the signed volume of the tetrahedron (origin, a, b, c); the parts outside the
    surface cancel. Positive when the normals point outwards (counter-clockwise seen from
    outside), as :func:`marching_cubes` makes them. An empty mesh encloses volume 0.

    Examples
    --------
    The unit tetrahedron, wound outwards:

    >>> v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    >>> round(enclosed_volume(v, [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]), 12)
    0.166666666667
    """
    v, t = as_mesh(vertices, triangles, "triangles", empty=True)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)


def gradient(field, spacing=None):
    r"""The gradient of a 2D field or 3D volume by central differences.

    .. math:: \frac{\partial f}{\partial x}\Big|_i \approx \frac{f_{i+1} - f_{i-1}}{2 \Delta x}

    inside, and the one-sided :math:`(f_1 - f_0) / \Delta x` at the borders. The gradient points
    towards higher values and is perpendicular to the isolines/isosurfaces: normalized and
    negated, it is the surface normal used to shade an isosurface or a volume rendering.

    Parameters
    ----------
    field : array_like, shape (ny, nx) or (nz, ny, nx)
    spacing : tuple of float, optional
        (dx, dy(, dz)); default all 1.

    Returns
    -------
    ndarray, shape field.shape + (d,)
        The components (df/dx, df/dy(, df/dz)) in the last axis, in coordinate order.

    Examples
    --------
    >>> gradient([[0, 1, 4], [0, 1, 4]])[0]          # f = x^2 on x = 0, 1, 2
    array([[1., 0.],
           [2., 0.],
           [3., 0.]])
    """
    f = as_array(field, "field")
    if f.ndim not in (2, 3) or min(f.shape) < 2:
        raise ValueError(f"field must be a 2D field (ny, nx) or 3D volume (nz, ny, nx) with at "
                         f"least 2 samples per axis, got shape {f.shape}")
    d = f.ndim
    sp = np.ones(d) if spacing is None else _spacing(spacing, d)
    out = np.empty(f.shape + (d,))
    for c in range(d):                        # coordinate c varies along array axis d - 1 - c
        axis = d - 1 - c
        g = np.moveaxis(out[..., c], axis, 0)
        a = np.moveaxis(f, axis, 0)
        g[1:-1] = (a[2:] - a[:-2]) / (2 * sp[c])
        g[0] = (a[1] - a[0]) / sp[c]
        g[-1] = (a[-1] - a[-2]) / sp[c]
    return out
