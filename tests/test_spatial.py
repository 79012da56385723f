"""Tests of course_lib.raytracing.spatial: the uniform grid (3D-DDA), the octree and the kd-tree.

References: brute force of :mod:`course_lib._raycore` (every ray against every triangle) and the
BVH, which must give the same (t, triangle) bit for bit; trimesh's ``RayMeshIntersector`` as an
independent ray tracer; and, for the walks, cells found by brute force in this file (every cell
or leaf box tested against the ray with a slab test typed here, kept when the ray crosses it over
a stretch of positive length, sorted by entry parameter). Nothing is copied from the output of
the code under test.
"""
import numpy as np
import pytest
import trimesh
from trimesh.ray.ray_triangle import RayMeshIntersector

from course_lib import raytracing as rt
from course_lib._raycore import brute_force, triangle_soa
from course_lib.raytracing.spatial import KDTree, Octree, UniformGrid, compare_structures


def unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def soup(seed, m=150):
    gen = np.random.default_rng(seed)
    tris = gen.uniform(-1, 1, (m, 1, 3)) + 0.25 * gen.normal(size=(m, 3, 3))
    return tris.reshape(-1, 3), np.arange(3 * m).reshape(m, 3)


def rays(seed, n=120, distance=3.0):
    gen = np.random.default_rng(seed + 100)
    o = distance * unit(gen.normal(size=(n, 3)))
    d = unit(-o / distance + 0.5 * gen.normal(size=(n, 3)))
    d[::7] = unit(gen.normal(size=(len(d[::7]), 3)))     # some rays point anywhere
    o[::5] = gen.uniform(-0.5, 0.5, (len(o[::5]), 3))    # some start inside the scene
    return o, d


def meshes():
    yield "icosphere", trimesh.creation.icosphere(subdivisions=2)
    yield "torus", trimesh.creation.torus(major_radius=1.0, minor_radius=0.35)
    for seed in (0, 1):
        v, f = soup(seed)
        yield f"soup{seed}", trimesh.Trimesh(v, f, process=False)


def builders():
    return [("grid", lambda v, f: UniformGrid(v, f)),
            ("grid7", lambda v, f: UniformGrid(v, f, resolution=[7, 3, 5])),
            ("grid_h", lambda v, f: UniformGrid(v, f, cell_size=0.3)),
            ("octree", lambda v, f: Octree(v, f, max_depth=6, leaf_size=4)),
            ("kdtree", lambda v, f: KDTree(v, f, leaf_size=4)),
            ("kdtree_shallow", lambda v, f: KDTree(v, f, max_depth=2, leaf_size=1))]


@pytest.mark.parametrize("mesh_name, mesh", list(meshes()))
def test_hits_equal_brute_force_the_bvh_and_trimesh(mesh_name, mesh):
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    o, d = rays(len(mesh_name))
    tris = v[f]
    t_ref, id_ref = brute_force(o, d, triangle_soa(tris), 0.0, np.full(len(o), np.inf))[:2]
    bvh = rt.BVH(tris).intersect(o, d)
    assert np.array_equal(bvh.t, t_ref) and np.array_equal(bvh.ids, id_ref)
    # trimesh: an independent intersector (hit or miss, distance)
    where, ray_idx, tri_idx = RayMeshIntersector(mesh).intersects_location(
        o, d, multiple_hits=True)
    t_tm = np.full(len(o), np.inf)
    dist = np.einsum("ij,ij->i", where - o[ray_idx], d[ray_idx])
    np.minimum.at(t_tm, ray_idx, dist)
    hit = np.isfinite(t_ref)
    assert hit.sum() > 20 and (~hit).sum() > 5
    assert np.array_equal(np.isfinite(t_tm), hit)
    assert np.allclose(t_tm[hit], t_ref[hit], atol=1e-9)
    for name, build in builders():
        s = build(v, f)
        h = s.intersect(o, d)
        assert np.array_equal(h.t, t_ref), name
        assert np.array_equal(h.ids, id_ref), name
        assert h.cells_visited <= h.nodes_visited


@pytest.mark.parametrize("seed", range(3))
def test_mailboxing_never_changes_the_result_and_saves_tests(seed):
    v, f = soup(seed)
    o, d = rays(seed)
    for name, build in builders():
        s = build(v, f)
        a, b = s.intersect(o, d), s.intersect(o, d, mailbox=False)
        assert np.array_equal(a.t, b.t) and np.array_equal(a.ids, b.ids), name
        assert a.triangle_tests <= b.triangle_tests
        assert a.cells_visited == b.cells_visited


def slab_cells(lo, hi, o, d):
    """Entry and exit parameters of the ray o + t d (t >= 0) in boxes lo, hi (k, 3)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t1, t2 = (lo - o) / d, (hi - o) / d
    t_in = np.maximum(np.minimum(t1, t2).max(axis=1), 0.0)
    t_out = np.maximum(t1, t2).min(axis=1)
    return t_in, t_out


@pytest.mark.parametrize("seed", range(4))
def test_dda_visits_exactly_the_cells_the_ray_crosses_in_order(seed):
    v, f = soup(seed, 40)
    grid = UniformGrid(v, f, resolution=[6, 4, 5])
    ii, jj, kk = np.meshgrid(*[np.arange(n) for n in grid.resolution], indexing="ij")
    idx = np.stack([ii.ravel(), jj.ravel(), kk.ravel()], axis=1)
    lo = grid.lo + idx * (grid.hi - grid.lo) / grid.resolution
    hi = grid.lo + (idx + 1) * (grid.hi - grid.lo) / grid.resolution
    o, d = rays(seed, 40)
    for r in range(len(o)):
        t_in, t_out = slab_cells(lo, hi, o[r], d[r])
        crossed = np.nonzero(t_out - t_in > 1e-9)[0]
        expected = [tuple(int(x) for x in idx[c]) for c in crossed[np.argsort(t_in[crossed])]]
        cells, t_enter, t_exit = grid.traverse(o[r], d[r])
        assert cells == expected
        if cells:
            assert np.allclose(t_enter, np.sort(t_in[crossed]), atol=1e-9)
            assert np.allclose(t_exit[:-1], t_enter[1:])


def test_dda_by_hand_on_a_small_grid():
    # the unit square split 4 x 4 x 1 (cells of 1/4), one triangle covering it
    v = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    grid = UniformGrid(v, [[0, 1, 2], [0, 1, 3]], resolution=[4, 4, 1])
    # the ray (0.1, 0.05, 0.5) + t (1, 0.4, 0): walls x = 0.25, 0.5, 0.75, 1 at t = 0.15, 0.4,
    # 0.65, 0.9; y = 0.25 at t = 0.5 (y = 0.5 at 1.125, after the ray has left at x = 1)
    cells, t_enter, t_exit = grid.traverse([0.1, 0.05, 0.5], [1, 0.4, 0])
    assert cells == [(0, 0, 0), (1, 0, 0), (2, 0, 0), (2, 1, 0), (3, 1, 0)]
    assert np.allclose(t_enter, [0, 0.15, 0.4, 0.5, 0.65])
    assert np.isclose(t_exit[-1], 0.9)


def leaf_boxes(tree):
    leaves = np.nonzero(tree.children[:, 0] < 0)[0]
    return leaves, tree.node_lo[leaves], tree.node_hi[leaves]


@pytest.mark.parametrize("cls", [Octree, KDTree])
@pytest.mark.parametrize("seed", range(3))
def test_tree_walks_visit_the_leaves_crossed_front_to_back(cls, seed):
    v, f = soup(seed, 80)
    tree = cls(v, f, max_depth=4, leaf_size=3)
    leaves, lo, hi = leaf_boxes(tree)
    o, d = rays(seed, 40)
    for r in range(len(o)):
        t_in, t_out = slab_cells(lo, hi, o[r], d[r])
        crossed = np.nonzero(t_out - t_in > 1e-9)[0]
        expected = leaves[crossed[np.argsort(t_in[crossed])]].tolist()
        cells, t_enter, t_exit = tree.traverse(o[r], d[r])
        assert sorted(cells) == sorted(expected)
        assert cells == expected
        assert np.all(np.diff(t_enter) > 0)
        if cells:
            assert np.allclose(t_exit[:-1], t_enter[1:])


def test_octree_children_are_the_eight_octants():
    v, f = soup(0, 60)
    tree = Octree(v, f, max_depth=1, leaf_size=1)
    mid = (tree.lo + tree.hi) / 2
    kids = tree.children[0]
    assert np.allclose(tree.node_lo[kids].min(axis=0), tree.lo)
    assert np.allclose(tree.node_hi[kids[7]], tree.hi) and np.allclose(tree.node_lo[kids[7]], mid)
    vol = np.prod(tree.node_hi[kids] - tree.node_lo[kids], axis=1)
    assert np.allclose(vol, np.prod(tree.hi - tree.lo) / 8)


def test_grid_cells_list_the_triangles_whose_box_overlaps_them():
    v, f = soup(2, 30)
    grid = UniformGrid(v, f, resolution=3)
    tris = v[f]
    size = (grid.hi - grid.lo) / 3
    for cell in [(0, 0, 0), (1, 1, 1), (2, 0, 1)]:
        lo = grid.lo + np.array(cell) * size
        hi = lo + size
        over = np.all((tris.min(axis=1) <= hi + 1e-6) & (tris.max(axis=1) >= lo - 1e-6), axis=1)
        inner = np.all((tris.min(axis=1) < hi - 1e-6) & (tris.max(axis=1) > lo + 1e-6), axis=1)
        got = set(grid.cell_triangles(cell).tolist())
        assert set(np.nonzero(inner)[0]) <= got <= set(np.nonzero(over)[0])


def test_resolution_rule_of_thumb():
    mesh = trimesh.creation.icosphere(subdivisions=3)          # 1280 triangles in a cube
    grid = UniformGrid(mesh.vertices, mesh.faces)
    n = round((3 * 1280) ** (1 / 3))                           # about 16 cells per axis
    assert np.all(np.abs(grid.resolution - n) <= 1)


def test_the_structures_save_tests_on_a_big_mesh():
    mesh = trimesh.creation.icosphere(subdivisions=3)
    o, d = rays(5, 60)
    rows = compare_structures(mesh.vertices, mesh.faces, o, d,
                              ("grid", "octree", "kdtree", "bvh", "brute"))
    assert all(r.agrees for r in rows)
    brute = rows[-1].tests_per_ray
    assert brute == len(mesh.faces)
    assert all(r.tests_per_ray < brute / 20 for r in rows[:-1])


def test_errors():
    v = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    f = [[0, 1, 2]]
    with pytest.raises(ValueError, match="cell_size"):
        UniformGrid(v, f, cell_size=0)
    with pytest.raises(ValueError, match="cell_size"):
        UniformGrid(v, f, cell_size=-1)
    with pytest.raises(ValueError, match="resolution"):
        UniformGrid(v, f, resolution=0)
    with pytest.raises(ValueError, match="resolution"):
        UniformGrid(v, f, resolution=[2, 2])
    with pytest.raises(ValueError, match="not both"):
        UniformGrid(v, f, resolution=2, cell_size=0.5)
    with pytest.raises(ValueError, match="max_depth"):
        Octree(v, f, max_depth=-1)
    with pytest.raises(ValueError, match="max_depth"):
        KDTree(v, f, max_depth=-1)
    with pytest.raises(ValueError, match="leaf_size"):
        Octree(v, f, leaf_size=0)
    with pytest.raises(ValueError, match="at least one triangle"):
        KDTree(v, np.zeros((0, 3), int))
    with pytest.raises(ValueError, match="degenerate"):
        UniformGrid([[0, 0, 0], [1, 1, 1], [2, 2, 2]], f)
    grid = UniformGrid(v, f)
    with pytest.raises(ValueError, match="directions"):
        grid.intersect([[0, 0, 1]], [[0, 0, 0]])
    with pytest.raises(ValueError):
        grid.intersect([[0, 0, 1, 2]], [[0, 0, 1, 2]])
    with pytest.raises(ValueError, match="one ray"):
        grid.traverse([[0, 0, 1], [0, 0, 2]], [0, 0, -1])
    with pytest.raises(ValueError, match="structures"):
        compare_structures(v, f, [[0, 0, 1]], [0, 0, -1], ("quadtree",))


@pytest.mark.parametrize("seed", range(2))
def test_walk_is_the_start_of_the_traversal_and_gives_the_hit(seed):
    v, f = soup(seed, 60)
    o, d = rays(seed, 30)
    for name, build in builders():
        s = build(v, f)
        hits = s.intersect(o, d)
        for r in range(len(o)):
            w = s.walk(o[r], d[r])
            cells = s.traverse(o[r], d[r])[0]
            assert w.cells == cells[:len(w.cells)]
            assert w.t == hits.t[r] and w.id == hits.ids[r]
            tested = np.concatenate(w.tested) if w.tested else np.zeros(0, int)
            assert len(set(tested.tolist())) == len(tested)      # mailboxing: once each
            if w.id >= 0:
                assert w.id in tested


def test_a_quadtree_octree_halves_two_axes_and_still_finds_the_hits():
    v, f = soup(4, 60)
    tree = Octree(v, f, max_depth=5, leaf_size=2, axes=(0, 1))
    inner = tree.children[:, 0] >= 0
    assert tree.children.shape[1] == 4
    kids = tree.children[0]
    assert np.allclose(tree.node_lo[kids, 2], tree.lo[2])           # z is never split
    assert np.allclose(tree.node_hi[kids, 2], tree.hi[2])
    assert inner.any()
    o, d = rays(4, 50)
    ref = brute_force(o, d, triangle_soa(v[f]), 0.0, np.full(len(o), np.inf))
    h = tree.intersect(o, d)
    assert np.array_equal(h.t, ref[0]) and np.array_equal(h.ids, ref[1])
    with pytest.raises(ValueError, match="axes"):
        Octree(v, f, axes=(0, 3))
    with pytest.raises(ValueError, match="axes"):
        Octree(v, f, axes=())
