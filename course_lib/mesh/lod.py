r"""Chapter 6 (lesson section: level of detail): discrete LODs, the screen-space error, progressive
meshes with geomorphs, and view-dependent refinement on the vertex hierarchy.

Discrete levels and the screen-space error
------------------------------------------
A **discrete LOD chain** is a list of versions of one model, finest first, each with a
*geometric error* :math:`\varepsilon` (object-space units: how far the level may stray from the
original surface). Here the levels come from :func:`simplify_qem` and the error of a level is the
largest QEM vertex error :math:`\sqrt{\bar v^T Q \bar v}` (the root of the summed squared
distances to the original planes merged into the vertex, an upper bound on its distance to each
of them), made non-decreasing along the chain.

An object-space length :math:`\varepsilon` at distance :math:`d` in front of a perspective camera
with vertical field of view :math:`\theta` and a viewport :math:`H` pixels high: the visible
half-height at distance :math:`d` is :math:`d\tan(\theta/2)` and maps to :math:`H/2` pixels, so

.. math:: \varepsilon_{screen} = \varepsilon \, \frac{H/2}{d \tan(\theta/2)}
          = \frac{\varepsilon H}{2 d \tan(\theta/2)} .

The renderer picks the **coarsest** level with :math:`\varepsilon_{screen} \le \tau` (a pixel
tolerance); level :math:`i` becomes acceptable at the switch distance
:math:`d_i = \varepsilon_i H / (2 \tau \tan(\theta/2))`. *Hysteresis* avoids flicker at a switch
distance: to go coarser the level must pass a stricter tolerance :math:`(1 - h)\tau`.

Progressive meshes (Hoppe 1996)
-------------------------------
The collapse record of :func:`simplify_qem` read backwards is a list of **vertex splits**: the
coarsest mesh (the *base mesh*) plus the splits rebuild every intermediate mesh, each split
putting back one vertex and (for an interior edge) two faces. :class:`ProgressiveMesh` moves to
any face count by applying splits (going up) or collapses (going down), and reproduces exactly
the meshes :meth:`SimplificationRecord.mesh_after` returns. A **geomorph** blends between two
counts: each vertex of the finer mesh moves from the position of the vertex that stands for it
in the coarser mesh to its own position, so the switch happens without a visible jump.

View-dependent refinement
-------------------------
The collapses form a **vertex hierarchy**: each collapse is a parent node whose two children are
its end points. A *cut* through the hierarchy is a mesh: every original face whose three corners
fall on three different cut nodes survives. :func:`view_dependent_faces` descends from the roots
and splits a node while its error, projected at its own distance from the viewer, exceeds the
pixel tolerance: near parts get fine, far parts stay coarse.
"""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_positive, as_scalar, as_whole, as_vector
from ._common import _compact
from .simplify import SimplificationRecord, simplify_qem

__all__ = ["LODChain", "ProgressiveMesh", "VertexSplit", "lod_chain", "screen_space_error",
           "select_level", "switch_distances", "view_dependent_faces"]


def _lod_fov(fov):
    f = as_scalar(fov, "fov")
    if not 0 < f < np.pi:
        raise ValueError(f"fov must be an angle in (0, pi) radians, got {fov!r}")
    return f


def _lod_positive(value, name):
    arr = as_array(value, name)
    if np.any(arr <= 0):
        raise ValueError(f"{name} must be > 0, got {arr.min() if arr.ndim else float(arr)!r}")
    return arr


def screen_space_error(geometric_error, distance, fov, viewport_height):
    r"""The size in pixels of an object-space error seen at a distance in perspective.

    :math:`\varepsilon_{screen} = \varepsilon H / (2 d \tan(\theta/2))`: the half-height
    :math:`d \tan(\theta/2)` of the view volume at depth :math:`d` covers :math:`H/2` pixels.

    Parameters
    ----------
    geometric_error : float or array_like
        The error(s) in object-space units (>= 0).
    distance : float or array_like
        Distance(s) from the eye along the view axis (> 0); broadcast against the errors.
    fov : float
        Vertical field of view, radians in (0, pi).
    viewport_height : float
        The viewport's height in pixels (> 0).

    Returns
    -------
    float or ndarray

    Raises
    ------
    ValueError
        For a distance <= 0, a negative error, a fov outside (0, pi) or a height <= 0.

    Examples
    --------
    >>> round(float(screen_space_error(0.01, 10.0, np.pi / 2, 1000)), 6)   # 0.01*500/10
    0.5
    """
    eps = as_array(geometric_error, "geometric_error")
    if np.any(eps < 0):
        raise ValueError("geometric_error must be >= 0")
    d = _lod_positive(distance, "distance")
    f = _lod_fov(fov)
    h = as_positive(viewport_height, "viewport_height")
    out = eps * (h / 2) / (d * np.tan(f / 2))
    return float(out) if np.ndim(out) == 0 else out


def _lod_tolerance(tolerance):
    return as_positive(tolerance, "tolerance", "the pixel tolerance")


def _lod_errors(errors):
    e = as_array(errors, "errors")
    if e.ndim != 1 or len(e) == 0:
        raise ValueError(f"errors must be a non-empty list of level errors, got shape {e.shape}")
    if np.any(e < 0) or np.any(np.diff(e) < 0):
        raise ValueError("errors must be >= 0 and non-decreasing (finest level first)")
    return e


def switch_distances(errors, fov, viewport_height, tolerance):
    r"""The distance from which each level is acceptable: :math:`d_i = \varepsilon_i H /
    (2\tau\tan(\theta/2))`.

    Parameters
    ----------
    errors : array_like, shape (L,)
        Geometric errors of the levels, finest first (non-decreasing).
    fov, viewport_height, tolerance : float
        Field of view (radians), viewport height and the pixel tolerance :math:`\tau` (> 0).

    Returns
    -------
    ndarray, shape (L,)

    Examples
    --------
    >>> switch_distances([0.0, 0.01, 0.04], np.pi / 2, 1000, 1.0).round(6).tolist()
    [0.0, 5.0, 20.0]
    """
    e = _lod_errors(errors)
    f = _lod_fov(fov)
    h = as_positive(viewport_height, "viewport_height")
    return e * h / (2 * _lod_tolerance(tolerance) * np.tan(f / 2))


def select_level(errors, distance, fov, viewport_height, tolerance, current=None,
                 hysteresis=0.0):
    r"""The coarsest level whose screen-space error is within the pixel tolerance.

    Parameters
    ----------
    errors : array_like, shape (L,)
        Geometric errors of the levels, finest (index 0) first, non-decreasing.
    distance, fov, viewport_height : float
        As in :func:`screen_space_error`.
    tolerance : float
        The pixel tolerance :math:`\tau` (> 0).
    current : int, optional
        The level shown in the previous frame (for hysteresis).
    hysteresis : float, optional
        In [0, 1): going coarser than `current` needs :math:`\varepsilon_{screen} \le
        (1 - h)\tau`; going finer happens as soon as `current` exceeds :math:`\tau`.

    Returns
    -------
    int
        The level index (0 if even the finest level is too coarse).

    Examples
    --------
    >>> select_level([0.0, 0.01, 0.04], 12.0, np.pi / 2, 1000, 1.0)
    1
    >>> select_level([0.0, 0.01, 0.04], 21.0, np.pi / 2, 1000, 1.0, current=1, hysteresis=0.2)
    1
    """
    e = _lod_errors(errors)
    d = as_positive(distance, "distance")
    tau = _lod_tolerance(tolerance)
    h = as_scalar(hysteresis, "hysteresis")
    if not 0 <= h < 1:
        raise ValueError(f"hysteresis must be in [0, 1), got {hysteresis!r}")
    px = np.asarray(screen_space_error(e, d, fov, viewport_height))

    def coarsest(limit):
        ok = np.flatnonzero(px <= limit * (1 + 1e-12))
        return int(ok[-1]) if len(ok) else 0

    plain = coarsest(tau)
    if current is None:
        return plain
    current = as_whole(current, "current", 0, integer_type=True)
    if current >= len(e):
        raise ValueError(f"current must be a level index below {len(e)}, got {current}")
    if px[current] > tau * (1 + 1e-12):
        return plain                                  # too coarse now: refine at once
    return max(current, coarsest((1 - h) * tau))      # coarsen only past the stricter limit


class LODChain(NamedTuple):
    """A discrete LOD chain: levels finest first with their geometric errors.

    Attributes
    ----------
    levels : list of (vertices, faces)
    face_counts : ndarray of int
    errors : ndarray
        Geometric error of each level (non-decreasing; 0 for the original).
    steps : ndarray of int
        The number of collapses of each level in `record`.
    record : SimplificationRecord

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> chain = lod_chain(*icosphere(2), [320, 160, 80])
    >>> chain.face_counts.tolist(), float(chain.errors[0])
    ([320, 160, 80], 0.0)
    """
    levels: list
    face_counts: np.ndarray
    errors: np.ndarray
    steps: np.ndarray
    record: SimplificationRecord


def lod_chain(vertices, faces, face_counts):
    """Build a discrete LOD chain with :func:`simplify_qem` (one run down to the smallest count).

    Parameters
    ----------
    vertices, faces : array_like
        A manifold, consistently oriented triangle mesh.
    face_counts : sequence of int
        Target face counts, strictly decreasing (the first may be the original count).

    Returns
    -------
    LODChain

    Raises
    ------
    ValueError
        For counts that are not strictly decreasing or not positive.

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> chain = lod_chain(*icosphere(2), [320, 100])
    >>> len(chain.levels[1][1]), bool(chain.errors[1] > 0)
    (100, True)
    """
    counts = [as_whole(c, "face_counts", 1, integer_type=True) for c in face_counts]
    if not counts or np.any(np.diff(counts) >= 0):
        raise ValueError(f"face_counts must be strictly decreasing, got {list(face_counts)}")
    rec = simplify_qem(vertices, faces, counts[-1]).record
    steps = np.array([rec.steps_for(c) for c in counts], dtype=np.int64)
    levels = [rec.mesh_after(int(k)) for k in steps]
    raw = np.array([float(rec.errors_after(int(k)).max()) if k else 0.0 for k in steps])
    return LODChain(levels, np.array([len(f) for _, f in levels], dtype=np.int64),
                    np.maximum.accumulate(raw), steps, rec)


class VertexSplit(NamedTuple):
    """One vertex split: the inverse of a :class:`Collapse`.

    Attributes
    ----------
    vertex : int
        The vertex that splits (the collapse's ``kept``; original indexing).
    new_vertex : int
        The vertex it restores (the collapse's ``removed``).
    collapsed_position : ndarray, shape (3,)
        Where `vertex` sits before the split (the collapse's position).
    vertex_position : ndarray, shape (3,)
        Where `vertex` goes back to (it sat at the collapse position before).
    new_position : ndarray, shape (3,)
        The position of the restored vertex.
    faces_added : tuple of int
        The faces put back (original face indices).
    faces_relinked : tuple of int
        The faces whose corner `vertex` becomes `new_vertex` again.

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> pm = ProgressiveMesh(*icosphere(1), base_faces=40)
    >>> s = pm.splits[0]
    >>> len(s.faces_added), s.new_vertex != s.vertex
    (2, True)
    """
    vertex: int
    new_vertex: int
    collapsed_position: np.ndarray
    vertex_position: np.ndarray
    new_position: np.ndarray
    faces_added: tuple
    faces_relinked: tuple


class ProgressiveMesh:
    """A base mesh and the vertex splits that refine it, as in Hoppe's progressive meshes.

    Parameters
    ----------
    vertices, faces : array_like
        The full-resolution triangle mesh, or None with `record`.
    base_faces : int, optional
        The face count of the base mesh (simplify_qem's target).
    record : SimplificationRecord, optional
        Use this record instead of running :func:`simplify_qem`.

    Attributes
    ----------
    splits : list of VertexSplit
        Coarse to fine: ``splits[j]`` undoes the collapse ``len - 1 - j`` of the record.
    level : int
        The number of splits applied now (0 = base mesh).

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> pm = ProgressiveMesh(*icosphere(2), base_faces=60)
    >>> v, f = pm.mesh(200)
    >>> v0, f0 = simplify_qem(*icosphere(2), target_faces=200)[:2]
    >>> np.array_equal(f, f0) and np.allclose(v, v0)
    True
    """

    def __init__(self, vertices=None, faces=None, base_faces=None, record=None):
        if record is None:
            if vertices is None or faces is None or base_faces is None:
                raise ValueError("give vertices, faces and base_faces, or a record")
            record = simplify_qem(vertices, faces, base_faces).record
        elif not isinstance(record, SimplificationRecord):
            raise TypeError(f"record must be a SimplificationRecord, got {type(record).__name__}")
        self.record = record
        n, m = len(record.vertices), len(record.faces)
        corners = record.faces.copy()
        faces_at = [set() for _ in range(n)]
        for f, (a, b, c) in enumerate(corners.tolist()):
            faces_at[a].add(f)
            faces_at[b].add(f)
            faces_at[c].add(f)
        pos = record.vertices.copy()
        collapses = record.collapses
        relinked = []
        old_pos = []
        for c in collapses:                             # forward replay, to learn each relink
            gone = set(c.faces_removed)
            for f in gone:
                for x in corners[f]:
                    faces_at[x].discard(f)
            moved = sorted(faces_at[c.removed] - gone)
            for f in moved:
                corners[f][corners[f] == c.removed] = c.kept
            faces_at[c.kept].update(moved)
            faces_at[c.removed] = set()
            relinked.append(tuple(moved))
            old_pos.append(pos[c.kept].copy())
            pos[c.kept] = c.position
        self.splits = [VertexSplit(c.kept, c.removed, np.asarray(c.position, dtype=float), p,
                                   record.vertices[c.removed].copy(), tuple(c.faces_removed), r)
                       for c, p, r in zip(collapses[::-1], old_pos[::-1], relinked[::-1])]
        self._corners, self._pos = corners, pos
        self._alive = np.ones(m, dtype=bool)
        for c in collapses:
            self._alive[list(c.faces_removed)] = False
        self.level = 0
        self._counts = record.face_counts()[::-1].copy()

    def __len__(self):
        return len(self.splits)

    def __repr__(self):
        return (f"ProgressiveMesh({self._counts[0]} base faces + {len(self)} vertex splits -> "
                f"{self._counts[-1]} faces)")

    def face_counts(self):
        """The face count after j splits, j = 0 .. len(self) (coarse to fine).

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> ProgressiveMesh(*icosphere(1), base_faces=60).face_counts().tolist()
        [60, 62, 64, 66, 68, 70, 72, 74, 76, 78, 80]
        """
        return self._counts.copy()

    def level_for(self, n_faces):
        """The number of splits whose mesh matches :meth:`SimplificationRecord.steps_for`
        (`n_faces`): the finest mesh with at most `n_faces` faces, or the base mesh.

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> pm = ProgressiveMesh(*icosphere(1), base_faces=60)
        >>> pm.level_for(80), pm.level_for(71), pm.level_for(10)
        (10, 5, 0)
        """
        n = as_whole(n_faces, "n_faces", 0, integer_type=True)
        return len(self) - self.record.steps_for(n)

    def split(self):
        """Apply the next vertex split (one level finer).

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> pm = ProgressiveMesh(*icosphere(1), base_faces=60)
        >>> pm.split(); pm.level, len(pm.mesh(level=1)[1])
        (1, 62)
        """
        if self.level >= len(self):
            raise ValueError("the mesh is already at full resolution")
        s = self.splits[self.level]
        for f in s.faces_relinked:
            row = self._corners[f]
            row[row == s.vertex] = s.new_vertex
        self._alive[list(s.faces_added)] = True
        self._pos[s.vertex] = s.vertex_position
        self.level += 1

    def collapse(self):
        """Undo the last vertex split (one level coarser): an edge collapse.

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> pm = ProgressiveMesh(*icosphere(1), base_faces=60)
        >>> pm.go_to(3); pm.collapse(); pm.level
        2
        """
        if self.level == 0:
            raise ValueError("the mesh is already the base mesh")
        self.level -= 1
        s = self.splits[self.level]
        for f in s.faces_relinked:
            row = self._corners[f]
            row[row == s.new_vertex] = s.vertex
        self._alive[list(s.faces_added)] = False
        self._pos[s.vertex] = s.collapsed_position

    def go_to(self, level):
        """Apply splits or collapses until `level` splits are applied.

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> pm = ProgressiveMesh(*icosphere(1), base_faces=60)
        >>> pm.go_to(7); pm.go_to(2); pm.level
        2
        """
        level = as_whole(level, "level", 0, integer_type=True)
        if level > len(self):
            raise ValueError(f"level must be at most {len(self)}, got {level}")
        while self.level < level:
            self.split()
        while self.level > level:
            self.collapse()

    def mesh(self, n_faces=None, level=None):
        """The compacted mesh at a face count (or a number of splits), as
        :meth:`SimplificationRecord.mesh_after` returns it.

        Returns
        -------
        vertices : ndarray, shape (n', 3)
        faces : ndarray of int, shape (m', 3)

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> pm = ProgressiveMesh(*icosphere(1), base_faces=60)
        >>> [len(pm.mesh(n)[1]) for n in (80, 61, 70)]
        [80, 60, 70]
        """
        if (n_faces is None) == (level is None):
            raise ValueError("give exactly one of n_faces and level")
        self.go_to(self.level_for(n_faces) if level is None else level)
        return _compact(self._pos, self._corners[self._alive])

    def _representatives(self, level):
        """Each original vertex's representative at `level` splits."""
        rep = np.arange(len(self.record.vertices))
        for s in self.splits[level:]:
            rep[s.new_vertex] = s.vertex
        # chase chains (a representative merged again later, i.e. at a coarser level)
        while True:
            up = rep[rep]
            if np.array_equal(up, rep):
                return rep
            rep = up

    def geomorph(self, coarse_faces, fine_faces, alpha):
        r"""Blend between two levels: the fine mesh's connectivity with each vertex moved a
        fraction :math:`1 - \alpha` of the way from its representative in the coarse mesh.

        :math:`v(\alpha) = (1 - \alpha)\, v_{coarse}(\text{rep}(v)) + \alpha\, v_{fine}`:
        at :math:`\alpha = 0` the surface is exactly the coarse mesh (faces of the split
        vertices are degenerate, of zero area), at :math:`\alpha = 1` the fine mesh.

        Parameters
        ----------
        coarse_faces, fine_faces : int
            Face counts (as :meth:`mesh` takes them), coarse <= fine.
        alpha : float
            Blend in [0, 1].

        Returns
        -------
        vertices : ndarray, shape (n_fine, 3)
        faces : ndarray of int, shape (m_fine, 3)
            The fine mesh's faces (indices into `vertices`).

        Examples
        --------
        >>> from course_lib.mesh import icosphere
        >>> pm = ProgressiveMesh(*icosphere(2), base_faces=60)
        >>> v, f = pm.geomorph(100, 200, 1.0)
        >>> np.allclose(v, pm.mesh(200)[0])
        True
        """
        a = as_scalar(alpha, "alpha")
        if not 0 <= a <= 1:
            raise ValueError(f"alpha must be in [0, 1], got {alpha!r}")
        lc, lf = self.level_for(coarse_faces), self.level_for(fine_faces)
        if lc > lf:
            raise ValueError(f"coarse_faces must not be finer than fine_faces, got "
                             f"{coarse_faces} and {fine_faces}")
        self.go_to(lc)
        coarse_pos = self._pos.copy()
        self.go_to(lf)
        alive = self._corners[self._alive]
        used = np.zeros(len(self._pos), dtype=bool)
        used[alive] = True
        rep = self._representatives(lc)
        ids = np.flatnonzero(used)
        blended = (1 - a) * coarse_pos[rep[ids]] + a * self._pos[ids]
        new_index = np.cumsum(used) - 1
        return blended, new_index[alive].astype(np.int64)


def view_dependent_faces(pm, eye, fov, viewport_height, tolerance):
    r"""Refine the vertex hierarchy only where the projected error exceeds the tolerance.

    Each collapse of the record is a node of the hierarchy whose children are its two end
    points; its error is :math:`\sqrt{\text{cost}}` (made no smaller than its children's) and its
    position the collapse position. Starting at the roots (the base mesh's vertices), a node is
    split while :func:`screen_space_error` of its error at its distance from `eye` exceeds
    `tolerance`. The active nodes form a cut; every original face whose corners map to three
    different active nodes is kept.

    Parameters
    ----------
    pm : ProgressiveMesh
    eye : array_like, shape (3,)
        The viewer's position.
    fov, viewport_height, tolerance : float
        As in :func:`select_level`.

    Returns
    -------
    vertices : ndarray, shape (n', 3)
    faces : ndarray of int, shape (m', 3)
        The active mesh, compacted.
    refined : ndarray of bool, shape (n',)
        Whether each vertex is an original (fully refined) vertex.

    Examples
    --------
    >>> from course_lib.mesh import icosphere
    >>> pm = ProgressiveMesh(*icosphere(2), base_faces=60)
    >>> v, f, _ = view_dependent_faces(pm, [0, 0, 100.0], np.pi / 3, 500, 1e9)
    >>> len(f)          # everything too small to matter: the base mesh
    60
    """
    if not isinstance(pm, ProgressiveMesh):
        raise TypeError(f"pm must be a ProgressiveMesh, got {type(pm).__name__}")
    eye = as_vector(eye, "eye", 3)
    fov = _lod_fov(fov)
    height = as_positive(viewport_height, "viewport_height")
    tau = _lod_tolerance(tolerance)
    rec = pm.record
    n, collapses = len(rec.vertices), rec.collapses
    total = n + len(collapses)
    pos = np.zeros((total, 3))
    pos[:n] = rec.vertices
    err = np.zeros(total)
    parent = np.full(total, -1)
    node = np.arange(n)
    for k, c in enumerate(collapses):
        me = n + k
        kids = (node[c.kept], node[c.removed])
        parent[list(kids)] = me
        pos[me] = c.position
        err[me] = max(np.sqrt(max(c.cost, 0.0)), err[kids[0]], err[kids[1]])
        node[c.kept] = me
    dist = np.maximum(np.linalg.norm(pos - eye, axis=1), 1e-12)
    expand = (err * (height / 2) / (dist * np.tan(fov / 2)) > tau) & (np.arange(total) >= n)
    active_rep = np.arange(total)
    opened = np.zeros(total, dtype=bool)          # every ancestor and the node itself expand
    for x in range(total - 1, -1, -1):            # parents come after their children
        p = parent[x]
        if p < 0:
            opened[x] = expand[x]
        elif opened[p]:
            opened[x] = expand[x]
        else:
            active_rep[x] = active_rep[p]
    corners = active_rep[rec.faces]
    keep = ((corners[:, 0] != corners[:, 1]) & (corners[:, 1] != corners[:, 2])
            & (corners[:, 2] != corners[:, 0]))
    v, f = _compact(pos, corners[keep])
    used = np.zeros(total, dtype=bool)
    used[corners[keep]] = True
    return v, f, np.flatnonzero(used) < n
