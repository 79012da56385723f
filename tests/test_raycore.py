"""The one ray core (course_lib/_raycore.py) seen from chapter 5 and from chapter 15.

Chapter 5's ray casting (``visibility.ray_cast`` with and without a BVH, ``visibility.BVH.cast``:
packets of rays) and chapter 15's ray tracer (``raytracing.intersect_triangles`` with and
without a BVH, ``raytracing.BVH.intersect``: a stack per ray) must give the same nearest hits on
the same scenes: the same triangle, the same ``t`` bit for bit, ties going to the lower index.
References: trimesh's ray queries (``trimesh.ray.ray_triangle.RayMeshIntersector``, pure numpy)
and VTK's ``vtkOBBTree`` (an oriented-bounding-box tree, C++).
"""
import numpy as np
import pytest
import trimesh
from trimesh.ray.ray_triangle import RayMeshIntersector

from course_lib import raytracing as rt
from course_lib import visibility as vis


def random_scene(seed, m=400, duplicates=60):
    """A triangle soup with exact copies of some triangles (every hit on them is a tie), rays
    from a sphere around it towards it, some axis-aligned (zero direction components)."""
    gen = np.random.default_rng(seed)
    tris = gen.uniform(-1, 1, (m, 1, 3)) + 0.25 * gen.normal(size=(m, 3, 3))
    copies = gen.choice(m, duplicates, replace=False)
    tris = np.concatenate([tris, tris[copies]])
    tris = tris[gen.permutation(len(tris))]
    o = gen.normal(size=(700, 3))
    o = 3 * o / np.linalg.norm(o, axis=1, keepdims=True)
    d = -o + 2.0 * gen.normal(size=(700, 3))
    d[:100] = 0.0
    d[np.arange(100), gen.integers(0, 3, 100)] = gen.choice([-1.0, 1.0], 100)
    o[:100] = gen.uniform(-2, 2, (100, 3)) - 3 * d[:100]
    return tris, o, d


def all_nearest_hits(tris, o, d, leaf_size, t_min=0.0, t_max=np.inf):
    """(name, t, ids) of every way the course finds the nearest hits."""
    bvh = vis.BVH(tris, leaf_size=leaf_size)
    out = []
    for name, hits in [
            ("ch05 brute force", vis.ray_cast(o, d, tris, t_min=t_min, t_max=t_max)),
            ("ch05 BVH", vis.ray_cast(o, d, tris, t_min=t_min, t_max=t_max, accelerate=True)),
            ("ch05 BVH.cast", bvh.cast(o, d, t_min=t_min, t_max=t_max)),
            ("ch15 brute force", rt.intersect_triangles(o, d, tris, t_min, t_max,
                                                        accelerate=False)),
            ("ch15 BVH", rt.intersect_triangles(o, d, tris, t_min, t_max)),
            ("ch15 BVH.intersect", bvh.intersect(o, d, t_min=t_min, t_max=t_max)),
            ("ch15 through a ch05 BVH", rt.intersect_triangles(o, d, bvh, t_min, t_max)),
            ("ch05 through a ch15 BVH", vis.ray_cast(o, d, rt.BVH(tris, leaf_size), t_min,
                                                     t_max))]:
        out.append((name, hits.t, hits.ids))
    return out


def test_both_chapters_use_one_bvh_class():
    assert vis.BVH is rt.BVH
    assert vis.Hits is not rt.TriangleHits
    bvh = vis.BVH(random_scene(0)[0])
    for name in ("cast", "intersect", "triangles", "lo", "hi", "children", "leaves", "depth",
                 "leaf_size"):
        assert hasattr(bvh, name), name


@pytest.mark.parametrize("seed, leaf_size", [(0, 1), (1, 3), (2, 4), (3, 8)])
def test_chapter_5_and_chapter_15_find_the_same_nearest_hits(seed, leaf_size):
    tris, o, d = random_scene(seed)
    for t_min, t_max in ((0.0, np.inf), (0.6, 0.8)):
        results = all_nearest_hits(tris, o, d, leaf_size, t_min, t_max)
        _, t_ref, ids_ref = results[0]
        assert 0.1 < (ids_ref >= 0).mean() < 0.9           # a real mix of hits and misses
        for name, t, ids in results[1:]:
            np.testing.assert_array_equal(ids, ids_ref, err_msg=name)
            np.testing.assert_array_equal(t, t_ref, err_msg=name)
        hit = ids_ref >= 0
        assert np.all((t_ref[hit] >= t_min) & (t_ref[hit] <= t_max))


def test_ties_go_to_the_lower_index_in_both_chapters():
    # the same triangles twice: k and k + m are identical, so every hit is a tie
    tris, o, d = random_scene(4, duplicates=0)
    m = len(tris)
    twice = np.concatenate([tris, tris])
    for name, t, ids in all_nearest_hits(twice, o, d, 4):
        assert (ids >= 0).sum() > 100, name
        assert ids.max() < m, name


def test_both_traversals_do_far_fewer_tests_than_brute_force():
    tris, o, d = random_scene(5, m=3000)
    bvh = vis.BVH(tris)
    brute = vis.ray_cast(o, d, tris)
    assert brute.triangle_tests == len(o) * len(tris) and brute.box_tests == 0
    assert rt.intersect_triangles(o, d, tris, accelerate=False).triangle_tests == \
        brute.triangle_tests
    for hits in (bvh.cast(o, d), bvh.intersect(o, d)):
        assert 0 < hits.triangle_tests < brute.triangle_tests / 20
        assert hits.box_tests > 0


def test_any_hit_finds_a_hit_exactly_where_the_nearest_hit_exists():
    tris, o, d = random_scene(6)
    bvh = rt.BVH(tris)
    nearest = bvh.intersect(o, d, t_max=3.0)
    anyhit = bvh.intersect(o, d, t_max=3.0, any_hit=True)
    np.testing.assert_array_equal(anyhit.ids >= 0, nearest.ids >= 0)
    hit = anyhit.ids >= 0
    assert np.all(anyhit.t[hit] >= nearest.t[hit]) and np.all(anyhit.t[hit] <= 3.0)
    assert anyhit.triangle_tests <= nearest.triangle_tests


def trimesh_first_hits(tris, o, d):
    """Triangle id and ray parameter of the first hit of each ray, by trimesh (-1, inf: miss)."""
    mesh = trimesh.Trimesh(tris.reshape(-1, 3), np.arange(3 * len(tris)).reshape(-1, 3),
                           process=False)
    locations, ray_ids, tri_ids = RayMeshIntersector(mesh).intersects_location(
        o, d, multiple_hits=True)
    ids = np.full(len(o), -1)
    t = np.full(len(o), np.inf)
    along = np.einsum("ij,ij->i", locations - o[ray_ids], d[ray_ids]) \
        / np.einsum("ij,ij->i", d[ray_ids], d[ray_ids])
    for r, tk, k in zip(ray_ids, along, tri_ids):
        if tk < t[r] - 1e-12 or (abs(tk - t[r]) <= 1e-12 and k < ids[r]):
            t[r], ids[r] = tk, k
    return ids, t


def test_both_chapters_match_trimesh():
    tris, o, d = random_scene(7, duplicates=0)
    ids, t = trimesh_first_hits(tris, o, d)
    hit = ids >= 0
    assert 0.2 < hit.mean() < 0.95
    for name, t_ours, ids_ours in all_nearest_hits(tris, o, d, 4):
        np.testing.assert_array_equal(ids_ours >= 0, hit, err_msg=name)
        assert (ids_ours[hit] == ids[hit]).mean() > 0.99, name   # ties within rounding
        np.testing.assert_allclose(t_ours[hit], t[hit], rtol=1e-9, atol=1e-9, err_msg=name)


def test_both_chapters_match_vtk_obb_tree():
    vtk = pytest.importorskip("vtkmodules.all")
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray

    tris, o, d = random_scene(8, m=200, duplicates=0)
    o, d = o[:150], d[:150]
    points = vtk.vtkPoints()
    points.SetData(numpy_to_vtk(tris.reshape(-1, 3), deep=True))
    cells = vtk.vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 3 * len(tris) + 1, 3), deep=True),
                  numpy_to_vtkIdTypeArray(np.arange(3 * len(tris)), deep=True))
    poly = vtk.vtkPolyData()
    poly.SetPoints(points)
    poly.SetPolys(cells)
    tree = vtk.vtkOBBTree()
    tree.SetDataSet(poly)
    tree.BuildLocator()
    ids = np.full(len(o), -1)
    t = np.full(len(o), np.inf)
    far = 10.0                                  # every triangle lies within t < 10 of the origins
    for r in range(len(o)):
        found, cell_ids = vtk.vtkPoints(), vtk.vtkIdList()
        tree.IntersectWithLine(o[r], o[r] + far * d[r], found, cell_ids)
        for k in range(found.GetNumberOfPoints()):
            tk = np.dot(np.array(found.GetPoint(k)) - o[r], d[r]) / np.dot(d[r], d[r])
            if tk < t[r]:
                t[r], ids[r] = tk, cell_ids.GetId(k)
    hit = ids >= 0
    assert 0.2 < hit.mean() < 0.95
    for name, t_ours, ids_ours in all_nearest_hits(tris, o, d, 4):
        # VTK's tolerance may count a hit a hair outside an edge: compare where both agree on
        # hitting, and require almost all rays to agree
        both = hit & (ids_ours >= 0)
        assert ((ids_ours >= 0) == hit).mean() > 0.98, name
        assert (ids_ours[both] == ids[both]).mean() > 0.98, name
        same = both & (ids_ours == ids)
        np.testing.assert_allclose(t_ours[same], t[same], rtol=1e-6, atol=1e-6, err_msg=name)
