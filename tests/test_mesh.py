"""Tests of course_lib.mesh (half-edge and winged-edge meshes, topology, QEM simplification).

Expected values come from independent references: trimesh (Euler number, watertightness,
winding consistency, components, face adjacency, normals, areas), OpenMesh (the half-edge
circulators: one-rings, faces around vertices, boundary flags, next/opposite steps),
fast-simplification and VTK's decimation via pyvista (the quality of a simplification), scipy
(least squares, graph components), and brute-force computations from the face list written out
below. Nothing is copied from the output of the code under test.

OpenMesh's vertex circulators run clockwise (seen from outside, CCW faces); ours run
counter-clockwise, so OpenMesh's lists are compared reversed.
"""
import numpy as np
import openmesh as om
import pytest
import pyvista as pv
import trimesh
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components as scipy_components

from course_lib import mesh as M

FAST = settings(max_examples=40, deadline=None, database=None, derandomize=True)  # reproducible


# ---------------------------------------------------------------------------------------------
# meshes and brute-force references
# ---------------------------------------------------------------------------------------------

def triangle_meshes():
    """The procedural triangle meshes, by name (small sizes: the tests loop over vertices)."""
    return {
        "tetrahedron": M.tetrahedron(),
        "cube (triangles)": M.cube(triangulated=True),
        "icosphere(2)": M.icosphere(2),
        "torus": M.torus(segments=16, rings=8),
        "double torus": M.double_torus(),
        "disc": M.disc(rings=3, segments=10),
    }


TRIANGLE_NAMES = list(triangle_meshes())
EXPECTED = {  # name: (chi, genus, boundary loops, closed), from topology, not from our code
    "tetrahedron": (2, 0, 0, True),
    "cube (triangles)": (2, 0, 0, True),
    "icosphere(2)": (2, 0, 0, True),
    "torus": (0, 1, 0, True),
    "double torus": (-2, 2, 0, True),
    "disc": (1, 0, 1, False),
}


def tri_mesh(v, f):
    return trimesh.Trimesh(np.asarray(v, float), np.asarray(f), process=False)


def compact(v, f):
    """Drop unused vertices, renumber (what a subset of faces needs before comparing)."""
    f = np.asarray(f)
    used = np.unique(f)
    new = np.full(len(v), -1)
    new[used] = np.arange(len(used))
    return np.asarray(v)[used], new[f]


def faces_by_vertex(faces):
    """Which faces use each vertex: one pass over the face list."""
    table = {}
    for fi, face in enumerate(faces):
        for x in face:
            table.setdefault(int(x), []).append(fi)
    return table


def brute_ring(faces, v, table=None):
    """Neighbours and faces of v, counter-clockwise, from the face list alone.

    In a counter-clockwise face (..., p, v, n, ...) the face lies between n and p, and walking
    counter-clockwise around v we meet n first, then p. Chain those steps; start after the gap
    for a boundary vertex. Returns (ring, faces, boundary?, number of separate fans).
    """
    succ, face_of = {}, {}
    candidates = range(len(faces)) if table is None else table.get(v, [])
    for fi in candidates:
        face = [int(x) for x in faces[fi]]
        if v in face:
            i = face.index(v)
            a, b = face[(i + 1) % len(face)], face[i - 1]
            succ[a], face_of[a] = b, fi
    heads = sorted(set(succ) - set(succ.values()))
    start = heads[0] if heads else min(succ)
    ring, fan = [start], []
    cur = start
    while cur in succ:
        fan.append(face_of[cur])
        cur = succ[cur]
        if cur == start:
            break
        ring.append(cur)
    neighbours = set(succ) | set(succ.values())
    separate = len(heads) > 1 or len(ring) < len(neighbours)
    return ring, fan, bool(heads), separate


def same_cycle(a, b):
    a, b = list(a), list(b)
    if len(a) != len(b):
        return False
    if not a:
        return True
    return any(a[i:] + a[:i] == b for i in range(len(a)))


def brute_bad_vertices(faces):
    """Vertices whose faces form more than one fan (the bow ties), from the face list."""
    faces = np.asarray(faces).tolist()
    table = faces_by_vertex(faces)
    return sorted(v for v in table if brute_ring(faces, v, table)[3])


def brute_boundary_loops(faces, n):
    """Boundary loops = components of the graph of edges that have one face (scipy)."""
    count = {}
    for face in faces:
        for a, b in zip(face, np.roll(face, -1)):
            key = (min(a, b), max(a, b))
            count[key] = count.get(key, 0) + 1
    edges = np.array([k for k, c in count.items() if c == 1]).reshape(-1, 2)
    if not len(edges):
        return 0
    g = coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(n, n))
    _, labels = scipy_components(g, directed=False)
    return len(np.unique(labels[np.unique(edges)]))


def random_subset(name, seed, keep):
    """A random subset of a procedural mesh's faces (holes, maybe bow ties), compacted."""
    v, f = triangle_meshes()[name]
    rng = np.random.default_rng(seed)
    mask = rng.random(len(f)) < keep
    mask[rng.integers(len(f))] = True
    return compact(v, f[mask])


def patch_removed(name, seed, size):
    """Remove a connected patch of faces (grown from a random face): one clean hole."""
    v, f = triangle_meshes()[name]
    rng = np.random.default_rng(seed)
    adj = tri_mesh(v, f).face_adjacency
    nbrs = [[] for _ in f]
    for a, b in adj:
        nbrs[a].append(b)
        nbrs[b].append(a)
    removed, frontier = set(), [int(rng.integers(len(f)))]
    while frontier and len(removed) < min(size, len(f) - 1):
        x = frontier.pop(0)
        if x not in removed:
            removed.add(x)
            frontier += nbrs[x]
    keep = np.array([i not in removed for i in range(len(f))])
    return compact(v, f[keep])


def holes(name, seed, k):
    """Remove up to k faces no two of which share a vertex, away from the rim: k new holes."""
    v, f = triangle_meshes()[name]
    rng = np.random.default_rng(seed)
    count = {}
    for face in f.tolist():
        for a, b in zip(face, face[1:] + face[:1]):
            count[(min(a, b), max(a, b))] = count.get((min(a, b), max(a, b)), 0) + 1
    chosen, used = [], {x for e, c in count.items() if c == 1 for x in e}
    for i in rng.permutation(len(f)):
        if not used & set(f[i].tolist()):
            chosen.append(i)
            used |= set(f[i].tolist())
        if len(chosen) == k:
            break
    return compact(v, np.delete(f, chosen, axis=0)), len(chosen)


def trimesh_components(v, f):
    t = tri_mesh(v, f)
    comps = trimesh.graph.connected_components(t.face_adjacency, nodes=np.arange(len(f)))
    return sorted(sorted(int(x) for x in c) for c in comps)


def our_face_pairs(mesh):
    h = np.flatnonzero((mesh.face >= 0) & (mesh.face[mesh.twin] >= 0))
    return {frozenset((int(mesh.face[x]), int(mesh.face[mesh.twin[x]]))) for x in h}


def check_against_trimesh(v, f):
    t = tri_mesh(v, f)
    he = M.HalfEdgeMesh.from_faces(v, f)
    we = M.WingedEdgeMesh.from_faces(v, f)
    assert he.euler_characteristic() == we.euler_characteristic() == t.euler_number
    assert he.is_closed() == we.is_closed() == t.is_watertight
    assert t.is_winding_consistent                   # we accepted it: trimesh must agree
    comps = trimesh_components(v, f)
    assert sorted(sorted(c.tolist()) for c in he.connected_components()) == comps
    assert sorted(sorted(c.tolist()) for c in we.connected_components()) == comps
    ref_pairs = {frozenset(map(int, p)) for p in t.face_adjacency}
    assert our_face_pairs(he) == ref_pairs
    inner = we.right_face >= 0
    assert {frozenset(p) for p in zip(we.left_face[inner].tolist(),
                                      we.right_face[inner].tolist())} == ref_pairs
    assert he.n_edges == we.n_edges == len(t.edges_unique)
    assert {frozenset(e) for e in he.edges().tolist()} == {frozenset(e) for e in
                                                           t.edges_unique.tolist()}
    assert he.boundary_components() == we.boundary_components() == \
        brute_boundary_loops(f, len(v))
    return he


# ---------------------------------------------------------------------------------------------
# procedural meshes against trimesh; Euler characteristic and genus
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", TRIANGLE_NAMES)
def test_procedural_meshes_against_trimesh(name):
    v, f = triangle_meshes()[name]
    check_against_trimesh(v, f)


@pytest.mark.parametrize("name", TRIANGLE_NAMES)
def test_euler_characteristic_genus_and_boundaries(name):
    chi, genus, loops, closed = EXPECTED[name]
    v, f = triangle_meshes()[name]
    assert tri_mesh(v, f).euler_number == chi                  # the reference agrees
    for mesh in (M.HalfEdgeMesh.from_faces(v, f), M.WingedEdgeMesh.from_faces(v, f)):
        assert mesh.euler_characteristic() == chi
        assert mesh.genus() == genus
        assert mesh.boundary_components() == loops
        assert mesh.is_closed() is closed
        assert mesh.is_manifold() is True
        # Euler-Poincare with boundaries: chi = 2 - 2g - b for a connected surface
        assert chi == 2 - 2 * mesh.genus() - mesh.boundary_components()


def test_cube_of_quads_and_closed_meshes_face_outwards():
    v, f = M.cube()
    assert f.shape == (6, 4)
    m = M.HalfEdgeMesh.from_faces(v, f)
    assert (m.n_vertices, m.n_edges, m.n_faces, m.genus()) == (8, 12, 6, 0)
    # outward: each quad's normal points away from the centre (closed form: the face centre)
    centres = np.array([v[q].mean(axis=0) for q in f])
    np.testing.assert_allclose(M.face_normals(v, f), centres, atol=1e-15)
    for name in ("tetrahedron", "cube (triangles)", "icosphere(2)", "torus", "double torus"):
        assert tri_mesh(*triangle_meshes()[name]).volume > 0, name      # positive: outward
    dv, df = triangle_meshes()["disc"]
    np.testing.assert_allclose(tri_mesh(dv, df).face_normals, [[0, 0, 1]] * len(df))


def test_icosphere_sizes_and_radius():
    for s in range(4):
        v, f = M.icosphere(s, radius=2.0)
        assert f.shape == (20 * 4 ** s, 3) and v.shape == (10 * 4 ** s + 2, 3)
        np.testing.assert_allclose(np.linalg.norm(v, axis=1), 2.0)
        t = tri_mesh(v, f)
        assert t.is_watertight and t.is_winding_consistent and t.euler_number == 2
    assert M.icosphere(6)[1].shape == (81_920, 3)


def test_double_torus_is_a_closed_orientable_genus_two_surface():
    for seg, rings in ((24, 12), (12, 6), (36, 16)):
        v, f = M.double_torus(segments=seg, rings=rings)
        t = tri_mesh(v, f)
        assert t.is_watertight and t.is_winding_consistent and t.euler_number == -2
        assert t.volume > 0
        assert len(trimesh_components(v, f)) == 1
        m = check_against_trimesh(v, f)
        assert m.genus() == 2 and m.genus(per_component=True).tolist() == [2]
    # no two triangles meet except along shared edges: the two tori do not touch
    v, f = M.double_torus()
    assert np.min(np.abs(v[:, 0])) >= 0 and tri_mesh(v, f).is_volume


def test_genus_per_component_and_several_components():
    tv, tf = M.torus(segments=12, rings=6)
    sv, sf = M.icosphere(1)
    dv, df = M.double_torus()
    v = np.vstack([tv, sv + 5, dv + 20])
    f = np.vstack([tf, sf + len(tv), df + len(tv) + len(sv)])
    m = M.HalfEdgeMesh.from_faces(v, f)
    assert m.genus(per_component=True).tolist() == [1, 0, 2]
    assert m.genus() == 3
    assert m.euler_characteristic() == tri_mesh(v, f).euler_number == 0 + 2 - 2
    assert len(m.connected_components()) == 3
    check_against_trimesh(v, f)


def test_sphere_with_holes_and_annulus():
    v, f = M.icosphere(2)
    # remove k faces far apart (no two share a vertex): k holes, chi = 2 - k
    rng = np.random.default_rng(7)
    chosen, used = [], set()
    for i in rng.permutation(len(f)):
        if not used & set(f[i].tolist()):
            chosen.append(i)
            used |= set(f[i].tolist())
        if len(chosen) == 5:
            break
    keep = np.setdiff1d(np.arange(len(f)), chosen)
    m = M.HalfEdgeMesh.from_faces(v, f[keep])
    assert (m.euler_characteristic(), m.boundary_components(), m.genus()) == (-3, 5, 0)
    dv, df = M.disc(rings=3, segments=8)
    annulus = compact(dv, df[8:])                     # without the centre fan
    a = M.HalfEdgeMesh.from_faces(*annulus)
    assert (a.euler_characteristic(), a.boundary_components(), a.genus()) == (0, 2, 0)


@pytest.mark.parametrize("name", ["icosphere(2)", "torus", "double torus", "disc"])
@pytest.mark.parametrize("seed", range(4))
def test_random_face_subsets_against_trimesh_or_rejected(name, seed):
    for keep in (0.95, 0.7):
        v, f = random_subset(name, seed, keep)
        bad = brute_bad_vertices(f)
        if bad:
            with pytest.raises(ValueError, match=rf"vertex {bad[0]} is non-manifold"):
                M.HalfEdgeMesh.from_faces(v, f)
            assert {p.vertices[0] for p in M.mesh_problems(v, f)} == set(bad)
        else:
            check_against_trimesh(v, f)
    v, f = patch_removed(name, seed, size=6 + 4 * seed)
    if not brute_bad_vertices(f):
        m = check_against_trimesh(v, f)
        assert m.boundary_components() == brute_boundary_loops(f, len(v))
    (v, f), k = holes(name, seed, 2 + seed)
    assert not brute_bad_vertices(f)
    m = check_against_trimesh(v, f)
    expected_loops = k + EXPECTED[name][2]
    assert m.boundary_components() == brute_boundary_loops(f, len(v)) == expected_loops
    assert m.euler_characteristic() == EXPECTED[name][0] - k
    assert m.genus() == EXPECTED[name][1]


# ---------------------------------------------------------------------------------------------
# traversals against OpenMesh and brute force
# ---------------------------------------------------------------------------------------------

def openmesh_of(v, f):
    f = np.asarray(f)
    return om.TriMesh(v, f) if f.shape[1] == 3 else om.PolyMesh(v, f)


def check_traversals_against_openmesh(v, f):
    ref = openmesh_of(v, f)
    assert ref.n_faces() == len(f)
    he = M.HalfEdgeMesh.from_faces(v, f)
    we = M.WingedEdgeMesh.from_faces(v, f)
    flags = np.array([ref.is_boundary(ref.vertex_handle(i)) for i in range(len(v))])
    np.testing.assert_array_equal(he.boundary_vertices(), flags)
    np.testing.assert_array_equal(we.boundary_vertices(), flags)
    for i in range(len(v)):
        vh = ref.vertex_handle(i)
        ring = [x.idx() for x in ref.vv(vh)][::-1]            # OpenMesh: clockwise
        faces = [x.idx() for x in ref.vf(vh)][::-1]
        ours = he.vertex_one_ring(i)
        assert ours == we.vertex_one_ring(i)
        assert he.vertex_faces(i) == we.vertex_faces(i)
        assert he.is_boundary_vertex(i) == we.is_boundary_vertex(i) == flags[i]
        if flags[i]:       # an open fan: the very same sequence, from one rim to the other
            assert ours == ring, (i, ours, ring)
            assert he.vertex_faces(i) == faces
        else:
            assert same_cycle(ours, ring), (i, ours, ring)
            assert same_cycle(he.vertex_faces(i), faces)
        assert len(he.vertex_faces(i)) == len(ours) - flags[i]
    for fi in range(len(f)):
        ref_verts = [x.idx() for x in ref.fv(ref.face_handle(fi))]
        assert same_cycle(he.face_vertices(fi), ref_verts)
        assert he.face_vertices(fi) == we.face_vertices(fi) == list(f[fi])
        ref_nbrs = {x.idx() for x in ref.ff(ref.face_handle(fi))}
        assert set(he.face_neighbors(fi)) - {-1} == ref_nbrs
        assert set(we.face_neighbors(fi)) - {-1} == ref_nbrs
    return he, ref


@pytest.mark.parametrize("name", TRIANGLE_NAMES)
def test_traversals_against_openmesh(name):
    check_traversals_against_openmesh(*triangle_meshes()[name])


def test_traversals_of_quads_against_openmesh():
    check_traversals_against_openmesh(*M.cube())
    v, f = M.cube()
    check_traversals_against_openmesh(*compact(v, f[:4]))       # an open box: two loops


@pytest.mark.parametrize("seed", range(3))
def test_traversals_of_meshes_with_holes_against_openmesh(seed):
    for name in ("icosphere(2)", "torus"):
        v, f = patch_removed(name, seed, size=10)
        if not brute_bad_vertices(f):
            check_traversals_against_openmesh(v, f)


@pytest.mark.parametrize("name", TRIANGLE_NAMES)
def test_traversals_against_brute_force(name):
    v, f = triangle_meshes()[name]
    he = M.HalfEdgeMesh.from_faces(v, f)
    faces = f.tolist()
    table = faces_by_vertex(faces)
    for i in range(len(v)):
        ring, fan, on_border, _ = brute_ring(faces, i, table)
        if on_border:
            assert he.vertex_one_ring(i) == ring
            assert he.vertex_faces(i) == fan
        else:
            assert same_cycle(he.vertex_one_ring(i), ring)
            assert same_cycle(he.vertex_faces(i), fan)


def test_step_functions_against_openmesh():
    for v, f in (M.disc(rings=2, segments=5), M.torus(segments=6, rings=4), M.cube()):
        he, ref = check_traversals_against_openmesh(v, f)
        by_ends = {}
        for h in range(ref.n_halfedges()):
            hh = ref.halfedge_handle(h)
            by_ends[(ref.from_vertex_handle(hh).idx(), ref.to_vertex_handle(hh).idx())] = hh
        assert he.n_half_edges == ref.n_halfedges()

        def ends(h):
            return int(he.origin[h]), int(he.target[h])

        def ref_ends(hh):
            return ref.from_vertex_handle(hh).idx(), ref.to_vertex_handle(hh).idx()
        for h in range(he.n_half_edges):
            hh = by_ends[ends(h)]
            assert ends(he.next_half_edge(h)) == ref_ends(ref.next_halfedge_handle(hh))
            assert ends(he.previous_half_edge(h)) == ref_ends(ref.prev_halfedge_handle(hh))
            assert ends(he.opposite(h)) == ref_ends(ref.opposite_halfedge_handle(hh))
            assert (he.face[h] < 0) == ref.is_boundary(hh)
            if he.face[h] >= 0:
                assert he.face[h] == ref.face_handle(hh).idx()
            d = he.describe(h)
            assert (d["origin"], d["target"]) == ends(h) and d["twin"] == he.opposite(h)
            assert he.find_half_edge(*ends(h)) == h
            assert he.edge_faces(h) == (int(he.face[h]), int(he.face[he.twin[h]]))


def test_boundary_loops_follow_the_boundary_half_edges():
    v, f = M.disc(rings=2, segments=6)
    he, we = M.HalfEdgeMesh.from_faces(v, f), M.WingedEdgeMesh.from_faces(v, f)
    loops = he.boundary_loops()
    assert loops == we.boundary_loops()
    (loop,) = loops
    outer = list(range(7, 13))                          # the outer ring, counter-clockwise
    assert sorted(loop) == outer
    assert same_cycle(loop, outer[::-1])                 # the boundary runs clockwise
    hs = he.boundary_loops(half_edges=True)[0]
    assert all(he.face[h] == -1 for h in hs)
    assert [he.next_half_edge(h) for h in hs] == hs[1:] + hs[:1]
    es = we.boundary_loops(edges=True)[0]
    assert all(we.right_face[e] == -1 for e in es)
    # an open box of quads (cube without top and bottom): two loops of 4
    cv, cf = M.cube()
    box = M.HalfEdgeMesh.from_faces(cv, cf[2:])
    assert sorted(sorted(x) for x in box.boundary_loops()) == [[0, 1, 2, 3], [4, 5, 6, 7]]


def test_winged_edge_records_against_brute_force():
    for v, f in (M.tetrahedron(), M.disc(rings=2, segments=5), M.cube()):
        we = M.WingedEdgeMesh.from_faces(v, f)
        faces = [list(x) for x in f]

        def walk(face, a):
            """The vertex after / before a in a face."""
            i = face.index(a)
            return face[(i + 1) % len(face)], face[i - 1]

        def edge(a, b):
            return we.find_edge(a, b)
        records = we.records()
        assert len(records) == we.n_edges
        for r in records:
            s, e = r["start"], r["end"]
            left = faces[r["left_face"]]
            assert walk(left, s)[0] == e                   # the left face walks start -> end
            assert r["left_next"] == edge(e, walk(left, e)[0])
            assert r["left_prev"] == edge(walk(left, s)[1], s)
            if r["right_face"] >= 0:
                right = faces[r["right_face"]]
                assert walk(right, e)[0] == s              # the right face walks end -> start
                assert r["right_next"] == edge(s, walk(right, s)[0])
                assert r["right_prev"] == edge(walk(right, e)[1], e)
            else:
                # no face on the right: the wings link the boundary loop
                nxt, prv = records[r["right_next"]], records[r["right_prev"]]
                assert nxt["right_face"] == -1 and nxt["end"] == s
                assert prv["right_face"] == -1 and prv["start"] == e
            assert set(r) == {"edge", *M.WingedEdgeMesh.FIELDS}
        for vi in range(len(v)):
            assert vi in (we.start[we.vertex_edge[vi]], we.end[we.vertex_edge[vi]])
        for fi in range(len(f)):
            assert fi in we.edge_faces(we.face_edge[fi])
            assert len(we.face_edges(fi)) == len(f[fi])


def test_traversal_index_checks():
    he = M.HalfEdgeMesh.from_faces(*M.tetrahedron())
    we = M.WingedEdgeMesh.from_faces(*M.tetrahedron())
    with pytest.raises(ValueError, match="v must be a vertex index from 0 to 3, got 4"):
        he.vertex_one_ring(4)
    with pytest.raises(TypeError, match="h must be an integer half-edge index"):
        he.opposite(1.5)
    with pytest.raises(ValueError, match="half-edge index from 0 to 11"):
        he.next_half_edge(12)
    with pytest.raises(ValueError, match="face index"):
        we.face_edges(-1)
    with pytest.raises(ValueError, match="edge index"):
        we.edge_faces(6)
    assert he.find_half_edge(0, 0) == -1 and we.find_edge(1, 1) == -1


def test_unused_vertices_are_not_part_of_the_surface():
    v, f = M.tetrahedron()
    v = np.vstack([v, [[5.0, 5.0, 5.0]]])                # vertex 4: no face uses it
    he = M.HalfEdgeMesh.from_faces(v, f)
    assert he.vertex_half_edge[4] == -1 and he.vertex_one_ring(4) == []
    assert he.n_vertices == 4 and he.euler_characteristic() == 2 and he.genus() == 0
    we = M.WingedEdgeMesh.from_faces(v, f)
    assert we.vertex_edge[4] == -1 and we.vertex_faces(4) == []


# ---------------------------------------------------------------------------------------------
# half-edge invariants (hypothesis over random meshes with holes)
# ---------------------------------------------------------------------------------------------

@FAST
@given(name=st.sampled_from(["icosphere(2)", "torus", "double torus", "disc", "cube (triangles)"]),
       seed=st.integers(0, 10_000), keep=st.floats(0.5, 1.0),
       how=st.sampled_from(["random", "patch", "holes"]))
def test_half_edge_invariants(name, seed, keep, how):
    if how == "random":
        v, f = random_subset(name, seed, keep)
    elif how == "patch":
        v, f = patch_removed(name, seed, size=int(30 * (1 - keep)) + 1)
    else:
        (v, f), _ = holes(name, seed, int(10 * (1 - keep)))
    if brute_bad_vertices(f):
        with pytest.raises(ValueError, match="non-manifold"):
            M.HalfEdgeMesh.from_faces(v, f)
        return
    m = M.HalfEdgeMesh.from_faces(v, f)
    h = np.arange(m.n_half_edges)
    np.testing.assert_array_equal(m.twin[m.twin], h)
    assert (m.twin != h).all()
    np.testing.assert_array_equal(m.next[m.prev], h)
    np.testing.assert_array_equal(m.prev[m.next], h)
    np.testing.assert_array_equal(m.face[m.next], m.face)
    np.testing.assert_array_equal(m.origin[m.twin], m.target)
    assert (m.face[m.twin] >= 0)[m.face < 0].all()           # a boundary half-edge's twin
    assert m.n_half_edges == 2 * len(tri_mesh(v, f).edges_unique)
    used = np.unique(f)
    np.testing.assert_array_equal(m.origin[m.vertex_half_edge[used]], used)
    np.testing.assert_array_equal(m.face[m.face_half_edge], np.arange(len(f)))
    # round trip: the same faces, same rotation (and so equal up to rotation)
    np.testing.assert_array_equal(m.to_faces(), f)
    w = M.WingedEdgeMesh.from_faces(v, f)
    np.testing.assert_array_equal(w.to_faces(), f)
    assert m.euler_characteristic() == tri_mesh(v, f).euler_number
    assert m.boundary_components() == brute_boundary_loops(f, len(v))


def test_to_faces_of_mixed_polygons():
    # a square pyramid: one quad and four triangles
    v = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0], [0, 0, 1.0]])
    faces = [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    for cls in (M.HalfEdgeMesh, M.WingedEdgeMesh):
        m = cls.from_faces(v, faces)
        assert m.to_faces() == faces
        assert (m.euler_characteristic(), m.genus(), m.is_closed()) == (2, 0, True)
    assert tri_mesh(v, [[0, 3, 2], [0, 2, 1]] + faces[1:]).volume > 0     # outward


# ---------------------------------------------------------------------------------------------
# bad input: clear messages
# ---------------------------------------------------------------------------------------------

def two_tetrahedra_sharing_a_vertex():
    v, f = M.tetrahedron()
    return np.vstack([v, v[1:] + [3.0, 0, 0]]), np.vstack([f, np.where(f == 0, 0, f + 3)])


def test_three_faces_on_an_edge_is_rejected():
    v, f = M.three_faces_on_an_edge()
    for cls in (M.HalfEdgeMesh, M.WingedEdgeMesh):
        with pytest.raises(ValueError, match=r"edge \(0, 1\) is shared by 3 faces \[0, 1, 2\]"):
            cls.from_faces(v, f)
    (p,) = M.mesh_problems(v, f)
    assert (p.kind, p.vertices, p.faces) == ("non-manifold edge", (0, 1), (0, 1, 2))


def test_bow_ties_are_rejected():
    with pytest.raises(ValueError, match=r"vertex 0 is non-manifold .*\[\[0\], \[1\]\]"):
        M.HalfEdgeMesh.from_faces(*M.bow_tie())
    # two closed fans (two tetrahedra sharing their vertex 0): no boundary anywhere
    v, f = two_tetrahedra_sharing_a_vertex()
    assert not brute_bad_vertices(f) == []
    with pytest.raises(ValueError, match=r"vertex 0 is non-manifold.*closed fans \[\[0, 1, 2\], "
                                         r"\[4, 5, 6\]\]"):
        M.WingedEdgeMesh.from_faces(v, f)
    (p,) = M.mesh_problems(v, f)
    assert p.kind == "non-manifold vertex" and p.vertices == (0,)


def test_inconsistent_winding_is_rejected_naming_faces_and_edge():
    v, f = M.cube(triangulated=True)
    f = f.copy()
    f[5] = f[5][::-1]
    assert not tri_mesh(v, f).is_winding_consistent              # the reference agrees
    with pytest.raises(ValueError, match="inconsistent winding") as info:
        M.HalfEdgeMesh.from_faces(v, f)
    problems = M.mesh_problems(v, f)
    assert {p.kind for p in problems} == {"inconsistent winding"}
    assert all(5 in p.faces for p in problems) and len(problems) == 3     # its three edges
    first = problems[0]
    assert str(info.value) == first.message
    a, b = first.vertices
    assert f"{a} -> {b}" in first.message and f"faces {first.faces[0]} and {first.faces[1]}" \
        in first.message


@pytest.mark.parametrize("faces, error, pattern", [
    ([[0, 1, 9]], ValueError, r"face 0 refers to vertex 9, but there are only 4 vertices"),
    ([[0, 1, 2], [0, -1, 2]], ValueError, r"face 1 refers to vertex -1"),
    ([[0, 1, 2], [0, 2, 2]], ValueError, r"face 1 is degenerate: it visits vertex 2 twice"),
    ([[0, 1]], ValueError, r"face 0 has 2 vertices \[0, 1\]; a face needs at least 3"),
    ([[0, 1, 2], [2, 3]], ValueError, r"face 1 has 2 vertices"),
    ([], ValueError, r"at least one face"),
    (np.zeros((0, 3), int), ValueError, r"at least one face"),
    ([0, 1, 2], ValueError, r"one flat list"),
    ([[0.0, 1.0, 2.0]], TypeError, r"integer vertex indices"),
    ([[0, 1, 2], ["a", "b", "c"]], TypeError, r"integer vertex indices"),
    ([[0, 1, 2], [0, 1.5, 2, 3]], TypeError, r"face 1 must be a list of integer"),
    ("abc", TypeError, r"faces must be a list of faces"),
    (None, TypeError, r"faces must be a list of faces"),
])
def test_bad_faces_are_rejected_with_a_clear_message(faces, error, pattern):
    v = M.tetrahedron()[0]
    with pytest.raises(error, match=pattern):
        M.HalfEdgeMesh.from_faces(v, faces)


def test_bad_vertices_are_rejected():
    with pytest.raises(ValueError, match="vertices"):
        M.HalfEdgeMesh.from_faces([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]])
    with pytest.raises(ValueError, match="finite"):
        M.HalfEdgeMesh.from_faces([[0, 0, 0], [1, 0, np.nan], [0, 1, 0]], [[0, 1, 2]])


def test_mesh_problems_lists_everything_and_accepts_zero_area_faces():
    problems = M.mesh_problems(5, [[0, 1, 2], [0, 1, 2, 2], [0, 7, 1]])
    assert [p.kind for p in problems] == ["missing vertex"]
    problems = M.mesh_problems(5, [[0, 1, 1], [2, 3, 3], [0, 1]])
    assert [p.kind for p in problems] == ["too few vertices"]
    assert [p.kind for p in M.mesh_problems(5, [[0, 1, 1], [2, 3, 3]])] == ["degenerate face"] * 2
    # collinear points: zero area, but a valid face (documented choice)
    v = [[0, 0, 0], [1, 0, 0], [2, 0, 0]]
    assert M.mesh_problems(v, [[0, 1, 2]]) == []
    assert M.face_areas(v, [[0, 1, 2]]).tolist() == [0.0]
    assert M.HalfEdgeMesh.from_faces(v, [[0, 1, 2]]).boundary_components() == 1


# ---------------------------------------------------------------------------------------------
# normals, areas, quadrics
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", TRIANGLE_NAMES)
def test_normals_and_areas_against_trimesh(name):
    v, f = triangle_meshes()[name]
    t = tri_mesh(v, f)
    np.testing.assert_allclose(M.face_normals(v, f), t.face_normals, atol=1e-12)
    np.testing.assert_allclose(M.face_areas(v, f), t.area_faces, rtol=1e-12)


def test_polygon_area_by_newell_against_the_shoelace_formula():
    from course_lib.shapes import letter_f_3d
    v, f = letter_f_3d(thickness=0.3)
    outline = v[f[0]][:, :2]
    x, y = outline[:, 0], outline[:, 1]
    shoelace = 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))
    areas = M.face_areas(v, f)
    np.testing.assert_allclose(areas[:2], shoelace, rtol=1e-12)
    np.testing.assert_allclose(M.face_normals(v, f)[:2], [[0, 0, 1], [0, 0, -1]], atol=1e-12)


unit3 = st.tuples(*[st.floats(-1, 1)] * 3).map(np.array).filter(lambda n: np.linalg.norm(n) > .1)
point3 = st.tuples(*[st.floats(-10, 10)] * 3).map(np.array)


@FAST
@given(normal=unit3, anchor=point3, s=st.floats(-5, 5), t=st.floats(-5, 5), off=st.floats(-3, 3))
def test_plane_quadric_is_the_squared_distance(normal, anchor, s, t, off):
    n = normal / np.linalg.norm(normal)
    plane = np.append(n, -n @ anchor)
    K = M.plane_quadric(plane)
    np.testing.assert_allclose(K, np.outer(plane, plane))
    # two directions in the plane (closed form from the normal)
    a = np.cross(n, [1, 0, 0] if abs(n[0]) < 0.9 else [0, 1, 0])
    a /= np.linalg.norm(a)
    b = np.cross(n, a)
    on_plane = anchor + s * a + t * b
    assert abs(float(M.collapse_cost(K, on_plane))) <= 1e-9
    np.testing.assert_allclose(M.collapse_cost(K, on_plane + off * n), off ** 2, atol=1e-8)


def test_vertex_quadrics_closed_form_on_the_cube():
    v, f = M.cube(triangulated=True)
    Q = M.vertex_quadrics(v, f)
    # vertex 0 = (-1, -1, -1): the planes x = -1 (2 triangles), y = -1 (2), z = -1 (1 or 2)
    count = {axis: sum(1 for tri in f if 0 in tri and np.allclose(v[tri][:, axis], -1))
             for axis in range(3)}
    expected = sum(c * np.outer(p, p) for c, p in zip(
        count.values(), ([-1, 0, 0, -1], [0, -1, 0, -1], [0, 0, -1, -1])))
    np.testing.assert_allclose(Q[0], expected, atol=1e-15)
    assert sum(count.values()) == sum(1 for tri in f if 0 in tri)
    # every corner has cost zero at itself, and the optimal position of a corner is the corner
    np.testing.assert_allclose(M.collapse_cost(Q, v), 0, atol=1e-12)
    for i in range(8):
        x, cost = M.optimal_position(Q[i])
        np.testing.assert_allclose(x, v[i], atol=1e-12)
        assert abs(cost) < 1e-12
    # a point moved by d along x from corner 7 = (1,1,1): only the x planes see it
    x7 = sum(1 for tri in f if 7 in tri and np.allclose(v[tri][:, 0], 1))
    np.testing.assert_allclose(M.collapse_cost(Q[7], [1.5, 1, 1]), x7 * 0.25)


@FAST
@given(seed=st.integers(0, 10_000), k=st.integers(3, 8))
def test_collapse_cost_and_optimal_position_against_least_squares(seed, k):
    rng = np.random.default_rng(seed)
    normals = rng.normal(size=(k, 3))
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    d = rng.normal(size=k)
    planes = np.column_stack([normals, d])
    Q = M.plane_quadric(planes).sum(axis=0)
    x = rng.normal(size=3)
    np.testing.assert_allclose(M.collapse_cost(Q, x), np.sum((normals @ x + d) ** 2), rtol=1e-10)
    if np.linalg.cond(normals) > 1e3:
        return
    ref = np.linalg.lstsq(normals, -d, rcond=None)[0]
    pos, cost = M.optimal_position(Q)
    np.testing.assert_allclose(pos, ref, atol=1e-8)
    np.testing.assert_allclose(cost, np.sum((normals @ ref + d) ** 2), atol=1e-9)
    # the scalar Python path used inside simplify_qem gives the same answer
    q10 = Q[[0, 0, 0, 0, 1, 1, 1, 2, 2, 3], [0, 1, 2, 3, 1, 2, 3, 2, 3, 3]].tolist()
    p2, c2 = M._target10(q10, [0.0, 0, 0], [1.0, 0, 0])
    np.testing.assert_allclose(p2, ref, atol=1e-8)
    np.testing.assert_allclose(c2, cost, atol=1e-9)


def test_singular_quadric_falls_back_to_end_points_or_midpoint():
    flat = M.plane_quadric([0, 0, 1, 0]) * 3                   # three faces in z = 0
    with pytest.raises(ValueError, match="singular"):
        M.optimal_position(flat)
    x, cost = M.optimal_position(flat, [0, 0, 1], [0, 0, -0.5])
    np.testing.assert_allclose(x, [0, 0, 0.25])                # the midpoint: z = 0.25
    assert cost == pytest.approx(3 * 0.25 ** 2)
    x, cost = M.optimal_position(flat, [0, 0, 1], [2, 0, 0])
    np.testing.assert_allclose(x, [2, 0, 0]) and cost == 0
    # two planes (a crease): still singular (a line of minima)
    crease = M.plane_quadric(np.array([[1, 0, 0, 0], [0, 1, 0, 0.0]])).sum(axis=0)
    q10 = crease[[0, 0, 0, 0, 1, 1, 1, 2, 2, 3], [0, 1, 2, 3, 1, 2, 3, 2, 3, 3]].tolist()
    p, c = M._target10(q10, [1.0, 0, 0], [0.0, 0, 5])
    assert p == [0.0, 0, 5] and c == 0


def test_quadric_helpers_reject_bad_shapes():
    with pytest.raises(ValueError, match="4 coordinates"):
        M.plane_quadric([0, 0, 1])
    with pytest.raises(ValueError, match="Q must be a 4x4"):
        M.collapse_cost(np.eye(3), [0, 0, 0])
    with pytest.raises(ValueError, match="Q must be a 4x4 quadric"):
        M.optimal_position(np.eye(4)[:3])


# ---------------------------------------------------------------------------------------------
# QEM simplification
# ---------------------------------------------------------------------------------------------

def bumpy_sphere(subdivisions):
    v, f = M.icosphere(subdivisions)
    scale = 1 + 0.15 * np.sin(3 * v[:, 0]) * np.sin(4 * v[:, 1]) * np.sin(2 * v[:, 2] + 1)
    return v * scale[:, None], f


def poly(v, f):
    return pv.PolyData(np.asarray(v, float), np.column_stack([np.full(len(f), 3), f]).ravel())


def surface_samples(v, f, n, seed):
    rng = np.random.default_rng(seed)
    a = trimesh.Trimesh(v, f, process=False).area_faces
    idx = rng.choice(len(f), n, p=a / a.sum())
    r = rng.random((n, 2))
    r[r.sum(axis=1) > 1] = 1 - r[r.sum(axis=1) > 1]
    t = v[f[idx]]
    return t[:, 0] + r[:, :1] * (t[:, 1] - t[:, 0]) + r[:, 1:] * (t[:, 2] - t[:, 0])


def distances(points, v, f):
    """Point-to-surface distances (VTK's cell locator via pyvista), and the closest cells."""
    cells, closest = poly(v, f).find_closest_cell(points, return_closest_point=True)
    return np.linalg.norm(points - closest, axis=1), cells


def two_sided(v0, f0, v1, f1, seed=0):
    """Mean and max of the point-to-surface distances, both ways (a sampled Hausdorff)."""
    d01 = distances(surface_samples(v0, f0, 6000, seed), v1, f1)[0]
    d10 = distances(surface_samples(v1, f1, 6000, seed + 1), v0, f0)[0]
    d = np.concatenate([d01, d10])
    return d.mean(), d.max()


@pytest.fixture(scope="module")
def bumpy():
    v, f = bumpy_sphere(3)                            # 1,280 faces
    return v, f, M.simplify_qem(v, f, 160)


def test_simplification_reaches_the_target_and_stays_a_closed_manifold(bumpy):
    v, f, out = bumpy
    assert len(out.faces) == 160
    assert out.record.stop_reason == "reached the target: 160 faces (target 160)"
    t = tri_mesh(out.vertices, out.faces)
    assert t.is_watertight and t.is_winding_consistent and t.euler_number == 2
    assert t.volume > 0
    m = M.HalfEdgeMesh.from_faces(out.vertices, out.faces)        # manifold, or it raises
    assert m.genus() == 0 and len(m.connected_components()) == 1
    assert len(out.vertices) == len(np.unique(out.faces))         # compacted
    assert (M.face_areas(out.vertices, out.faces) > 1e-6).all()
    assert len(out.record) == (len(f) - 160) // 2


def test_no_face_is_flipped(bumpy):
    v, f, out = bumpy
    centres = out.vertices[out.faces].mean(axis=1)
    _, cells = distances(centres, v, f)
    original = tri_mesh(v, f).face_normals[cells]
    ours = tri_mesh(out.vertices, out.faces).face_normals
    cosines = (original * ours).sum(axis=1)
    assert cosines.min() > 0.3, cosines.min()
    assert np.median(cosines) > 0.95


def test_no_face_is_flipped_where_collapses_would_fold():
    # flat disc: every collapse inside it keeps the plane, so a fold shows as a -z normal
    v, f = M.disc(rings=6, segments=24)
    out = M.simplify_qem(v, f, 40)
    assert out.record.rejections["flipped face"] > 0
    np.testing.assert_allclose(tri_mesh(out.vertices, out.faces).face_normals,
                               [[0, 0, 1]] * len(out.faces), atol=1e-9)
    # a coarse torus taken far down: folds would turn faces inside out
    v, f = M.torus(segments=16, rings=8)
    out = M.simplify_qem(v, f, 60)
    centres = out.vertices[out.faces].mean(axis=1)
    _, cells = distances(centres, v, f)
    cosines = (tri_mesh(v, f).face_normals[cells] *
               tri_mesh(out.vertices, out.faces).face_normals).sum(axis=1)
    assert cosines.min() > 0.3, cosines.min()
    # a tiny angle limit refuses most collapses
    strict = M.simplify_qem(*bumpy_sphere(2), 100, max_angle=1e-3)
    assert strict.record.rejections["flipped face"] > 0


def test_simplification_error_is_like_the_reference_libraries(bumpy):
    import fast_simplification
    v, f, out = bumpy
    reduction = 1 - 160 / len(f)
    fv, ff = fast_simplification.simplify(v, f, target_reduction=reduction)
    dec = poly(v, f).decimate(reduction)
    dv, df = dec.points, dec.faces.reshape(-1, 4)[:, 1:]
    assert abs(len(ff) - 160) <= 4 and abs(len(df) - 160) <= 4
    ours = two_sided(v, f, out.vertices, out.faces)
    fast = two_sided(v, f, fv, ff)
    vtk = two_sided(v, f, dv, df)
    best_mean, best_max = min(fast[0], vtk[0]), min(fast[1], vtk[1])
    assert ours[0] <= 1.5 * best_mean, (ours, fast, vtk)
    assert ours[1] <= 2.0 * best_max, (ours, fast, vtk)
    # and much better than a naive simplification (a coarser icosphere, same face count ~)
    cv, cf = M.icosphere(2)
    naive = two_sided(v, f, cv * np.linalg.norm(v, axis=1).mean(), cf)
    assert ours[0] < naive[0] / 2


def test_replaying_the_record_reproduces_every_stage(bumpy):
    v, f, out = bumpy
    rec = out.record
    fv, ff = rec.mesh_after(len(rec))
    np.testing.assert_array_equal(ff, out.faces)
    np.testing.assert_allclose(fv, out.vertices)
    v0, f0 = rec.mesh_after(0)
    np.testing.assert_allclose(v0, v)
    np.testing.assert_array_equal(f0, f)
    counts = rec.face_counts()
    assert counts[0] == len(f) and counts[-1] == 160 and (np.diff(counts) == -2).all()
    rng = np.random.default_rng(3)
    for k in rng.integers(1, len(rec), 4):
        kv, kf = rec.mesh_after(int(k))
        assert len(kf) == counts[k]
        t = tri_mesh(kv, kf)
        assert t.is_watertight and t.is_winding_consistent and t.euler_number == 2
    stages = rec.meshes_at([1000, 500, 161])
    assert [len(s[1]) for s in stages] == [1000, 500, 160]
    for c in rec.collapses[:20]:
        assert c.kept != c.removed and len(c.faces_removed) == 2
        assert all(c.kept in f[x] and c.removed in f[x] for x in c.faces_removed)  # original ids
        assert c.cost >= 0
    first = rec.collapses[0]
    Q = M.vertex_quadrics(v, f)
    assert first.cost == pytest.approx(M.collapse_cost(Q[first.kept] + Q[first.removed],
                                                       first.position), abs=1e-12)
    with pytest.raises(ValueError, match="at most the number of collapses"):
        rec.mesh_after(len(rec) + 1)


def test_first_collapse_is_the_cheapest_edge():
    v, f = bumpy_sphere(2)
    out = M.simplify_qem(v, f, len(f) - 2)
    (c,) = out.record.collapses
    Q = M.vertex_quadrics(v, f)
    edges = tri_mesh(v, f).edges_unique
    costs = []
    for a, b in edges:          # brute force: the optimum of every edge, by least squares
        q = Q[a] + Q[b]
        try:
            x = np.linalg.solve(q[:3, :3], -q[:3, 3])
        except np.linalg.LinAlgError:
            x = (v[a] + v[b]) / 2
        costs.append(M.collapse_cost(q, x))
    assert c.cost == pytest.approx(min(costs), rel=1e-6, abs=1e-15)
    # the bumpy sphere is symmetric: several edges tie for the cheapest (to the last bits, which
    # the BLAS decides), and any of them is right
    cheapest = [set(e.tolist()) for e, cost in zip(edges, costs)
                if cost <= min(costs) * (1 + 1e-6) + 1e-15]
    assert {c.kept, c.removed} in cheapest and len(cheapest) < len(edges) // 4


@pytest.mark.parametrize("name, genus", [("torus", 1), ("double torus", 2)])
def test_simplification_keeps_the_genus(name, genus):
    v, f = triangle_meshes()[name]
    out = M.simplify_qem(v, f, len(f) // 4)
    m = M.HalfEdgeMesh.from_faces(out.vertices, out.faces)
    assert m.genus() == genus and m.is_closed()
    assert tri_mesh(out.vertices, out.faces).euler_number == 2 - 2 * genus


def test_simplification_keeps_the_boundary_exactly():
    v, f = M.disc(rings=6, segments=24)
    v = v + np.column_stack([np.zeros((len(v), 2)), 0.1 * v[:, 0] ** 2])  # gently curved
    out = M.simplify_qem(v, f, 60)
    m = M.HalfEdgeMesh.from_faces(out.vertices, out.faces)
    assert m.boundary_components() == 1 and m.genus() == 0
    rim = np.arange(1 + 5 * 24, 1 + 6 * 24)
    (loop,) = m.boundary_loops()
    # the same 24 rim points, in the same cyclic order, unmoved
    np.testing.assert_allclose(np.sort(out.vertices[loop], axis=0), np.sort(v[rim], axis=0))
    original_loop = M.HalfEdgeMesh.from_faces(v, f).boundary_loops()[0]
    mapping = {tuple(np.round(v[i], 12)): i for i in original_loop}
    assert same_cycle([mapping[tuple(np.round(out.vertices[i], 12))] for i in loop],
                      original_loop)
    # down to the minimum: a 24-gon needs 22 triangles
    low = M.simplify_qem(v, f, 0)
    assert len(low.faces) == 22 and low.record.stop_reason.startswith("stopped at 22 faces")


def test_simplification_stops_and_says_why():
    out = M.simplify_qem(*M.tetrahedron(), 2)
    assert len(out.faces) == 4 and out.record.stop_reason.startswith("stopped at 4 faces")
    assert out.record.rejections["valence"] > 0
    for (v, f), genus in ((M.torus(segments=10, rings=5), 1), (M.double_torus(), 2)):
        out = M.simplify_qem(v, f, 0)                    # as far as it goes
        t = tri_mesh(out.vertices, out.faces)
        assert t.euler_number == 2 - 2 * genus and t.is_watertight and t.is_winding_consistent
        assert M.mesh_problems(out.vertices, out.faces) == []
        assert out.record.rejections["link condition"] > 0
        assert out.record.stop_reason.startswith(f"stopped at {len(out.faces)} faces")
    out = M.simplify_qem(*M.icosphere(1), 100)
    assert len(out.faces) == 80 and "nothing to do" in out.record.stop_reason
    out = M.simplify_qem(*M.icosphere(2), 101, record=False)
    assert len(out.faces) == 100 and out.record.collapses == []


def collapsible_edges(v0, f0, out, cos_limit=0.0):
    """Edges of a simplified mesh that could still be collapsed under the documented rules.

    Written from the rules, from the face lists: the merged vertices' quadric is the sum of the
    original quadrics of all the vertices merged into them (read from the record); boundary
    edges and edges between two boundary vertices are not collapsible; an edge with one
    boundary end collapses onto it; else the optimum of the quadric, or the best of the end
    points and the midpoint when the 3x3 block is (nearly) singular; the link condition; no
    vertex left with fewer than 3 neighbours (2 on the boundary); no face turning by 90 degrees
    or more, or becoming degenerate.
    """
    v, f = out.vertices, out.faces
    rep = np.arange(len(v0))
    for c in out.record.collapses:
        rep[c.removed] = c.kept
    for _ in range(len(out.record.collapses) + 1):
        rep = rep[rep]
    original = np.unique(rep[np.unique(f0)])                 # output vertex i <- original[i]
    assert len(original) == len(v)
    Q0 = M.vertex_quadrics(v0, f0)
    Q = np.zeros((len(v0), 4, 4))
    np.add.at(Q, rep, Q0)
    Q = Q[original]
    count, faces_at, nbrs = {}, [set() for _ in v], [set() for _ in v]
    for fi, face in enumerate(f.tolist()):
        for a, b in zip(face, face[1:] + face[:1]):
            count[(min(a, b), max(a, b))] = count.get((min(a, b), max(a, b)), 0) + 1
            nbrs[a].add(b)
            nbrs[b].add(a)
        for a in face:
            faces_at[a].add(fi)
    border = {x for e, c in count.items() if c == 1 for x in e}
    found = []
    for (a, b), c in count.items():
        if c != 2 or (a in border and b in border):
            continue
        shared = faces_at[a] & faces_at[b]
        opposite = {x for fi in shared for x in f[fi]} - {a, b}
        if nbrs[a] & nbrs[b] != opposite:
            continue
        if len(nbrs[a] | nbrs[b]) - 2 < 3 or any(
                len(nbrs[x]) - 1 < (2 if x in border else 3) for x in opposite):
            continue
        q = Q[a] + Q[b]
        if a in border or b in border:
            p = v[a] if a in border else v[b]
        elif np.linalg.det(q[:3, :3]) > 1e-10 * np.trace(q[:3, :3]) ** 3:
            p = np.linalg.solve(q[:3, :3], -q[:3, 3])
        else:
            cands = [v[a], v[b], (v[a] + v[b]) / 2]
            p = min(cands, key=lambda x: float(M.collapse_cost(q, x)))
        ok = True
        for fi in (faces_at[a] | faces_at[b]) - shared:
            t_old = v[f[fi]]
            t_new = np.where(np.isin(f[fi], [a, b])[:, None], p, t_old)
            n_old = np.cross(t_old[1] - t_old[0], t_old[2] - t_old[0])
            n_new = np.cross(t_new[1] - t_new[0], t_new[2] - t_new[0])
            if (np.linalg.norm(n_new) < 1e-12 or
                    n_old @ n_new <= cos_limit * np.linalg.norm(n_old) * np.linalg.norm(n_new)):
                ok = False
                break
        if ok:
            found.append((a, b))
    return found


@pytest.mark.parametrize("mesh", ["disc", "torus", "double torus", "bumpy"])
def test_when_simplification_stops_early_no_edge_is_left_to_collapse(mesh):
    v, f = {"disc": M.disc(rings=5, segments=16), "torus": M.torus(segments=12, rings=6),
            "double torus": M.double_torus(), "bumpy": bumpy_sphere(1)}[mesh]
    out = M.simplify_qem(v, f, 0)
    assert out.record.stop_reason.startswith("stopped at")
    assert collapsible_edges(v, f, out) == []


def test_simplification_rejects_bad_input():
    with pytest.raises(ValueError, match="triangle mesh"):
        M.simplify_qem(*M.cube(), 4)
    with pytest.raises(ValueError, match="edge \\(0, 1\\)"):
        M.simplify_qem(*M.three_faces_on_an_edge(), 1)
    with pytest.raises(ValueError, match="target_faces must be at least 0"):
        M.simplify_qem(*M.icosphere(1), -1)
    with pytest.raises(TypeError, match="target_faces must be a whole number"):
        M.simplify_qem(*M.icosphere(1), 10.5)
    with pytest.raises(ValueError, match="max_angle"):
        M.simplify_qem(*M.icosphere(1), 10, max_angle=0)


def test_procedural_parameters_are_checked():
    with pytest.raises(ValueError, match="subdivisions must be at least 0"):
        M.icosphere(-1)
    with pytest.raises(ValueError, match="radius must be positive"):
        M.disc(radius=0)
    with pytest.raises(ValueError, match="segments must be at least 6"):
        M.double_torus(segments=4)
    with pytest.raises(ValueError, match="minor must be smaller"):
        M.double_torus(major=1, minor=2)
    with pytest.raises(TypeError, match="rings must be a whole number"):
        M.torus(rings=3.5)


# ---------------------------------------------------------------------------------------------
# replaying the record: errors and the top of the priority queue, against brute force
# ---------------------------------------------------------------------------------------------

def merged_groups(rec, k):
    """Original vertices merged into each survivor after k collapses (following the record)."""
    groups = {i: {i} for i in range(len(rec.vertices))}
    for c in rec.collapses[:k]:
        groups[c.kept] |= groups.pop(c.removed)
    return groups


def squared_plane_distances(v, f, corner_vertices, point):
    """Sum of squared distances of `point` to the planes of the faces touching the vertices
    (each face once per touching corner, as Q = sum of the corners' quadrics counts it);
    unit normals from trimesh."""
    t = tri_mesh(v, f)
    n, anchor = t.face_normals, v[f[:, 0]]
    total = 0.0
    for x in corner_vertices:
        for face in np.flatnonzero((f == x).any(axis=1)):
            total += float(np.dot(n[face], point - anchor[face])) ** 2
    return total


@pytest.mark.parametrize("k", [0, 7, 40])
def test_errors_after_k_collapses_against_plane_distances(bumpy, k):
    v, f, out = bumpy
    rec = out.record
    groups = merged_groups(rec, k)
    survivors = sorted(groups)
    pos = {i: rec.vertices[i] for i in survivors}
    for c in rec.collapses[:k]:
        pos[c.kept] = c.position
    errors = rec.errors_after(k)
    mv, _ = rec.mesh_after(k)
    assert len(errors) == len(mv) == len(survivors)
    for j, i in enumerate(survivors[::37]):
        want = np.sqrt(squared_plane_distances(v, f, groups[i], pos[i]))
        assert errors[survivors.index(i)] == pytest.approx(want, abs=1e-7)


@pytest.mark.parametrize("k", [0, 5, 60, 129])
def test_queue_after_k_collapses_is_the_cheapest_edges(k):
    v, f = bumpy_sphere(2)
    rec = M.simplify_qem(v, f, 60).record
    groups = merged_groups(rec, k)
    head = rec.queue_after(k, top=6)
    costs = [e.cost for e in head]
    assert costs == sorted(costs)
    mv, mf = rec.mesh_after(k)
    n_edges = len(np.unique(np.sort(np.r_[mf[:, [0, 1]], mf[:, [1, 2]], mf[:, [2, 0]]], axis=1),
                            axis=0))
    assert len(rec.queue_after(k, top=10_000)) == n_edges          # closed: every edge queued
    for e in head:
        # the cost is the squared distance sum of the position to both groups' original planes
        want = squared_plane_distances(v, f, groups[e.kept] | groups[e.removed], e.position)
        assert e.cost == pytest.approx(want, abs=1e-10)
        # and the position minimizes it: least squares over those planes, when well posed
        t = tri_mesh(v, f)
        rows = [face for x in groups[e.kept] | groups[e.removed]
                for face in np.flatnonzero((f == x).any(axis=1))]
        normals = t.face_normals[rows]
        offsets = -np.einsum("ij,ij->i", normals, v[f[rows, 0]])
        if np.linalg.cond(normals) < 1e3:
            best = np.linalg.lstsq(normals, -offsets, rcond=None)[0]
            assert np.allclose(e.position, best, atol=1e-8)
        assert len(e.faces_removed) == 2
    if k < len(rec):                      # no collapse was refused here: the next is the head
        assert sum(rec.rejections.values()) == 0
        assert rec.collapses[k].cost == pytest.approx(costs[0], rel=1e-9, abs=1e-14)


def test_queue_after_keeps_the_boundary_end_point_and_checks_arguments():
    v, f = M.disc(rings=3, segments=10)
    rec = M.simplify_qem(v, f, 20).record
    border = M.HalfEdgeMesh.from_faces(v, f).boundary_vertices()
    for e in rec.queue_after(0, top=1000):
        assert not (border[e.kept] and border[e.removed])
        if border[e.removed] or border[e.kept]:
            assert border[e.kept] and np.allclose(e.position, v[e.kept])
    with pytest.raises(ValueError, match="k must be at most"):
        rec.queue_after(len(rec) + 1)
    with pytest.raises((ValueError, TypeError), match="top"):
        rec.queue_after(0, top=-1)
