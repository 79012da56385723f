"""Chapter 15, spatial subdivision: the uniform grid (3D-DDA), the octree and the kd-tree on an
icosphere of 81,920 triangles (20,480 in the quick run): build time against the course BVH's
build, and nearest hits of the same rays against trimesh's Embree intersector (the reference
library, measured in the same run; trimesh's own Python intersector when Embree is missing) and
the course BVH. The rows' names carry the triangle tests per ray (deterministic). The grid and
trees walk each ray in Python (the triangle tests of a cell are vectorized): they show the test
counts of the lesson, not a fast tracer. Also the explorer's update."""
import numpy as np

from benchmarks import operation_row


def _rays(count, seed=15):
    rng = np.random.default_rng(seed)
    o = rng.normal(size=(count, 3))
    o = 3 * o / np.linalg.norm(o, axis=1, keepdims=True)
    d = -o / 3 + 0.35 * rng.normal(size=(count, 3))
    return o, d / np.linalg.norm(d, axis=1, keepdims=True)


def operations(quick=False):
    """Build and intersect: grid, octree and kd-tree against the BVH and trimesh/Embree."""
    import trimesh
    import trimesh.ray

    from course_lib.raytracing import BVH
    from course_lib.raytracing.spatial import KDTree, Octree, UniformGrid

    mesh = trimesh.creation.icosphere(5 if quick else 6)
    v, f = np.asarray(mesh.vertices), np.asarray(mesh.faces)
    m = len(f)
    o, d = _rays(50 if quick else 400)
    p = len(o)
    repeat = 2 if quick else 3
    if trimesh.ray.has_embree:
        from trimesh.ray.ray_pyembree import RayMeshIntersector
        ref_name = "trimesh + Embree (intersects_first)"
    else:                                            # pragma: no cover - Embree missing
        from trimesh.ray.ray_triangle import RayMeshIntersector
        ref_name = "trimesh ray_triangle (intersects_first; Embree missing)"
    ref = RayMeshIntersector(mesh)
    ref.intersects_first(o[:1], d[:1])               # build Embree's scene once, untimed
    bvh = BVH(v[f])
    builds = {"uniform grid": lambda: UniformGrid(v, f),
              "octree": lambda: Octree(v, f),
              "kd-tree (median split)": lambda: KDTree(v, f)}
    rows = []
    bvh_hits = bvh.intersect(o, d)
    for name, build in builds.items():
        rows.append(operation_row(f"build a {name} over {m:,} triangles", m, build,
                                  lambda: BVH(v[f]), "building the course BVH", repeat))
        s = build()
        hits = s.intersect(o, d)
        assert np.array_equal(hits.ids, bvh_hits.ids)
        rows.append(operation_row(
            f"{name}: nearest hits of {p} rays, {m:,} triangles ({hits.triangle_tests / p:.1f} "
            f"triangle tests and {hits.cells_visited / p:.1f} cells per ray; BVH "
            f"{bvh_hits.triangle_tests / p:.1f} tests)", p,
            lambda: s.intersect(o, d), lambda: ref.intersects_first(o, d), ref_name, repeat))
    rows.append(operation_row(f"course BVH: nearest hits of {p} rays, {m:,} triangles", p,
                              lambda: bvh.intersect(o, d), lambda: ref.intersects_first(o, d),
                              ref_name, repeat))
    return rows


def widgets(quick=False):
    """Median update of the spatial explorer: the angle slider with the grid and the kd-tree."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import spatial

    repeat = 5 if quick else 40
    rows = []
    explorer = spatial.SpatialExplorer()
    explorer.fig.canvas.draw()
    for name in ("grid", "kd-tree"):
        explorer.structure.value = name
        rows.append(widget_row(f"spatial explorer ({name}, angle slider)",
                               lambda i: setattr(explorer.angle, "value",
                                                 float(-170 + 7 * (i % 48))),
                               explorer.fig.canvas.draw, repeat))
    plt.close(explorer.fig)
    return rows
