"""Chapter 15: Whitted ray tracing at 640x480, and the BVH against trimesh's ray queries.

* The 640x480 render (spheres on a checkered, slightly reflective floor, shadows, mirror and
  glass, depth 3; target under 5 s) has no reference ray tracer installed to compare with: its
  reference row is the same image at depth 0 (ray casting with shadow rays), so the ratio shows
  what the reflected and refracted generations cost.
* 100,000 rays against an 80,000-triangle torus through our numpy BVH, against trimesh's ray
  queries on the same rays: with Embree (``trimesh.ray.ray_pyembree``, compiled C++, needs the
  ``embreex`` package) when it is importable, and always against trimesh's pure-numpy intersector
  (``trimesh.ray.ray_triangle``, needs ``rtree``). That one first collects, per ray, the triangles
  whose boxes meet the ray's bounding box and tests them all: on these rays it takes about 20 ms
  per ray, so it runs on a subset of the rays (the row says how many) and our BVH is timed on the
  same subset. BVH build times are a separate row (Embree's scene build is timed the same way:
  a fresh intersector's first query of one ray).
"""
import numpy as np

from benchmarks import median_time, operation_row


def _row(name, size, ours, reference, reference_name, repeat, reference_repeat):
    """operation_row with fewer repeats for a slow reference (one warm-up run each)."""
    t_ours = median_time(ours, repeat, warmup=1)
    t_ref = median_time(reference, reference_repeat, warmup=1)
    return {"operation": name, "size": size, "ours_ms": 1e3 * t_ours,
            "reference": reference_name, "reference_ms": 1e3 * t_ref, "ratio": t_ours / t_ref}


def _torus_rays(n_rays, segments, seed=15):
    """An (segments x segments x 2)-triangle torus and rays from a sphere of radius 4 aimed at
    random points of its bounding box (about half of them hit)."""
    from course_lib import shapes

    v, f = shapes.torus(major=1.0, minor=0.35, segments=segments, rings=segments)
    rng = np.random.default_rng(seed)
    o = rng.normal(size=(n_rays, 3))
    o = 4.0 * o / np.linalg.norm(o, axis=1, keepdims=True)
    target = rng.uniform(v.min(axis=0), v.max(axis=0), (n_rays, 3))
    d = target - o
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    return v, f, o, d


def _embree():
    try:
        import embreex  # noqa: F401
        from trimesh.ray import ray_pyembree
    except ImportError:
        return None
    return ray_pyembree.RayMeshIntersector


def operations(quick=False):
    import trimesh
    from trimesh.ray import ray_triangle

    from course_lib import raytracing as rt

    rows = []
    width, height = (64, 48) if quick else (640, 480)
    scene = rt.example_scene("spheres", width, height)
    rows.append(_row(f"ray-trace {width}x{height} (Whitted), spheres + plane, shadows, depth 3",
                     width * height, lambda: rt.render(scene, max_depth=3),
                     lambda: rt.render(scene, max_depth=0),
                     "same scene, depth 0 (ray casting + shadows)", 1 if quick else 3,
                     1 if quick else 3))

    n_rays, segments, subset = (2_000, 40, 20) if quick else (100_000, 200, 500)
    v, f, o, d = _torus_rays(n_rays, segments)
    tris = v[f]
    mesh = trimesh.Trimesh(v, f, process=False)
    bvh = rt.BVH(tris)
    tag = f"{len(f):,} triangles"
    embree = _embree()
    repeat = 1 if quick else 5
    if embree is not None:
        def embree_build():
            embree(mesh).intersects_first(o[:1], d[:1])

        rows.append(_row(f"build the BVH, {tag}", len(f), lambda: rt.BVH(tris), embree_build,
                         "trimesh + Embree scene build", repeat, repeat))
        intersector = embree(mesh)
        rows.append(_row(f"nearest hit of {n_rays:,} rays, {tag}, BVH", n_rays,
                         lambda: bvh.intersect(o, d), lambda: intersector.intersects_first(o, d),
                         "trimesh + Embree intersects_first", repeat, repeat))
    numpy_intersector = ray_triangle.RayMeshIntersector(mesh)
    numpy_intersector.intersects_first(o[:1], d[:1])            # builds its rtree once
    rows.append(_row(f"nearest hit of {subset:,} of those rays, {tag}, BVH", subset,
                     lambda: bvh.intersect(o[:subset], d[:subset]),
                     lambda: numpy_intersector.intersects_first(o[:subset], d[:subset]),
                     "trimesh ray_triangle (numpy + rtree)", repeat, 1))
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch15_quadrics, ch15_spatial, ch15_distributed

    return (ch15_quadrics, ch15_spatial, ch15_distributed,)


def widgets(quick=False):
    """Median update of the ray-tracer explorer's preview (80x60, depth 3, target 100 ms) and
    its full image on release (320x240); the ray-tree view's pixel pick (target 50 ms)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import ray_tree, raytracer

    repeat = 5 if quick else 30
    rows = []
    explorer = raytracer.RayTracerExplorer()
    rows.append(widget_row("ray tracer explorer: preview while sliding (80x60, depth 3); "
                           "full = 320x240 image on release",
                           lambda i: setattr(explorer.azimuth, "value", -40.0 + 2.0 * (i % 40)),
                           explorer.settle, repeat, target_ms=100.0))
    tree = ray_tree.RayTreeExplorer()
    tree.fig.canvas.draw()
    rows.append(widget_row("ray-tree view: pick a pixel (spheres, depth 3)",
                           lambda i: setattr(tree.column, "value", 40 + (i % 80)),
                           tree.fig.canvas.draw, repeat))
    plt.close(tree.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
