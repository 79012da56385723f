"""Fingerprints of every order-sensitive result the course shows, printed as JSON.

``tests/test_determinism.py`` runs this script in subprocesses under several CPU dispatch
settings (``NPY_DISABLE_CPU_FEATURES``, ``OPENBLAS_CORETYPE``) and compares the outputs.
numpy picks its sort/partition kernels (and its SIMD float loops) by CPU features at run time,
and OpenBLAS picks its kernels by CPU: a result that depends on how ties come out of a sort,
or on the last bit of a dot product near a threshold, differs between machines and breaks the
stored notebook outputs on some of them.

Each entry has two parts. ``exact``: a SHA-256 of everything discrete in the result (orders,
trees, indices, counts, strings, shapes, which values are infinite), or the count itself,
compared exactly. ``floats``: a summary of its finite floating-point values (their number and
two correctly rounded weighted sums), compared to a relative 1e-9: the last bit of a float may
differ between kernels (that is numpy's and OpenBLAS's business), but no order, count, tree,
printed text or visibly different value may.

Covered: the BVH (:class:`course_lib.visibility.BVH` is :class:`course_lib.raytracing.BVH`;
both traversals, ``cast`` and ``intersect``) on meshes whose box centres tie, the BSP trees and
painter's orders, occluder ranking and the PVS, the half-edge and winged-edge builds, QEM
simplification records, marching squares and cubes, ambient occlusion, the camera, z-buffer and
simplification widgets, every chapter's exercise generators over a range of seeds and the mock
exam, and the counted outputs the lesson notebooks print (recomputed here with the same calls
as the notebook cells).

Run ``python tests/determinism_probe.py`` to print the JSON (``--only PREFIX`` for a part,
``--runtime`` for the dispatch and BLAS kernels in use only).
"""
import hashlib
import importlib
import json
import math
import re
import sys

import numpy as np

#: Exercise variants fingerprinted per exercise class.
EXERCISE_SEEDS = range(40)
#: Mock exams fingerprinted.
EXAM_SEEDS = range(4)

_ADDRESS = re.compile(r" at 0x[0-9a-fA-F]+")


def _feed(h, floats, x, depth=0):
    """Feed the exact, discrete part of `x` into the hash `h`, and its floats into `floats`.

    Integers, booleans, strings, shapes, dtypes and the positions of non-finite values go into
    the hash; finite floating-point values go to `floats` (compared to a relative 1e-9: numpy's
    SIMD loops and OpenBLAS's kernels may round the last bit differently, and that is fine as
    long as no order, count, tree or printed text changes with it).
    """
    if depth > 12:
        raise ValueError(f"structure too deep to fingerprint: {type(x).__name__}")
    if isinstance(x, (np.ndarray, np.generic)):
        a = np.asarray(x)
        h.update(f"A{a.dtype.str}{a.shape}".encode())
        if a.dtype == object:
            for item in a.ravel():
                _feed(h, floats, item, depth + 1)
        elif a.dtype.kind in "fc":
            a = np.concatenate([a.real.ravel(), a.imag.ravel()]) if a.dtype.kind == "c" else a
            a = a.astype(np.float64).ravel()
            finite = np.isfinite(a)
            h.update(np.packbits(finite).tobytes() + np.ascontiguousarray(a[~finite]).tobytes())
            floats.append(a[finite])
        else:
            h.update(np.ascontiguousarray(a).tobytes())
    elif isinstance(x, (float, complex)):
        _feed(h, floats, np.array(x), depth + 1)
    elif x is None or isinstance(x, (bool, int, str, bytes)):
        h.update(f"{type(x).__name__}:{x!r};".encode())
    elif isinstance(x, (list, tuple)):
        h.update(f"L{type(x).__name__}{len(x)}(".encode())
        for item in x:
            _feed(h, floats, item, depth + 1)
        h.update(b")")
    elif isinstance(x, (set, frozenset)):
        h.update(f"S{len(x)}(".encode())
        for item in sorted(x, key=repr):        # sets here hold ints, strings or tuples of them
            _feed(h, floats, item, depth + 1)
        h.update(b")")
    elif isinstance(x, dict):
        h.update(f"D{len(x)}(".encode())
        for k in sorted(x, key=repr):
            _feed(h, floats, k, depth + 1)
            _feed(h, floats, x[k], depth + 1)
        h.update(b")")
    elif hasattr(x, "__dict__") and not callable(x):
        h.update(f"O{type(x).__name__}(".encode())
        _feed(h, floats, {k: v for k, v in vars(x).items() if not callable(v)}, depth + 1)
        h.update(b")")
    else:
        h.update(f"R{type(x).__name__}:{_ADDRESS.sub('', repr(x))};".encode())


#: Fixed weights in [1, 2) for the float summaries (exactly rounded arithmetic only: the same
#: on every machine).
_WEIGHTS = 1.0 + np.modf(np.arange(1, 1 << 16) * 0.6180339887498949)[0]


def fingerprint(x):
    """``(exact, floats)``: the SHA-256 of the discrete part of `x`, and a float summary.

    The summary is ``[n, sum w_i x_i, sum |w_i x_i|]`` over the n finite floats of `x`, with
    fixed positive weights, each sum correctly rounded (:func:`math.fsum`), so it does not
    depend on numpy's summation order. Two results whose floats differ only in rounding agree
    to about 1e-16 relative; a changed value moves the weighted sum.
    """
    h, floats = hashlib.sha256(), []
    _feed(h, floats, x)
    values = np.concatenate(floats) if floats else np.zeros(0)
    w = np.resize(_WEIGHTS, len(values))
    products = (values * w).tolist()
    return h.hexdigest()[:24], [len(values), math.fsum(products),
                                math.fsum(abs(v) for v in products)]


class Probe(dict):
    """name -> ``{"exact": digest or count, "floats": [n, sum, abs sum]}``."""

    def add(self, name, value):
        if name in self:
            raise KeyError(f"duplicate probe entry {name!r}")
        if isinstance(value, (int, np.integer)) and not isinstance(value, bool):
            self[name] = {"exact": int(value), "floats": [0, 0.0, 0.0]}
        else:
            exact, floats = fingerprint(value)
            self[name] = {"exact": exact, "floats": floats}


# ---------------------------------------------------------------------------------------------
# Test meshes whose box centres tie (sorts and partitions must break the ties themselves)
# ---------------------------------------------------------------------------------------------

def _torus_ch05():
    from course_lib import shapes
    v, f = shapes.torus(1.0, 0.45, 40, 20)               # notebooks/ch05: 1,600 triangles
    return v, f


def _tie_triangles():
    """900 small triangles on a coarse lattice: many share their centre exactly."""
    rng = np.random.default_rng(7)
    centres = rng.integers(0, 5, (900, 3)).astype(float)
    shape = np.array([[-0.25, -0.25, 0.0], [0.25, -0.25, 0.0], [0.0, 0.25, 0.125]])
    return centres[:, None, :] + shape[None]


def _icosphere_triangles():
    from course_lib import mesh
    v, f = mesh.icosphere(3)                             # symmetric: equal centre coordinates
    return v[f]


def _rays(tris, n=1500, seed=3):
    """Rays from above the triangles' box towards points spread over it."""
    rng = np.random.default_rng(seed)
    pts = tris.reshape(-1, 3)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    size = float((hi - lo).max())
    o = (lo + hi) / 2 + [0.0, 0.0, 2.0 * size] + rng.uniform(-0.2, 0.2, (n, 3)) * size
    return o, lo + rng.uniform(0, 1, (n, 3)) * (hi - lo) - o


# ---------------------------------------------------------------------------------------------
# The parts
# ---------------------------------------------------------------------------------------------

def _bvh_cases():
    """(name, triangles, ray origins, ray directions, leaf size) for both BVHs."""
    v, f = _torus_ch05()
    inputs = {"torus": v[f], "ties": _tie_triangles(), "icosphere": _icosphere_triangles()}
    for name, tris in inputs.items():
        o, d = _rays(tris)
        for leaf in (1, 4):
            yield name, tris, o, d, leaf


def part_visibility_bvh(p):
    from course_lib import visibility
    for name, tris, o, d, leaf in _bvh_cases():
        bvh = visibility.BVH(tris, leaf_size=leaf)
        key = f"visibility.BVH/{name}/leaf{leaf}"
        p.add(key + "/order", bvh._order)
        p.add(key + "/tree", (bvh.lo, bvh.hi, bvh.children, bvh._spans, bvh._axes))
        p.add(key + "/depth", bvh.depth)
        hits = bvh.cast(o, d)
        p.add(key + "/hits", (hits.t, hits.ids))
        p.add(key + "/triangle_tests", hits.triangle_tests)
        p.add(key + "/box_tests", hits.box_tests)


def part_raytracing_bvh(p):
    from course_lib import raytracing as rt
    for name, tris, o, d, leaf in _bvh_cases():
        bvh = rt.BVH(tris, leaf_size=leaf)
        key = f"raytracing.BVH/{name}/leaf{leaf}"
        p.add(key + "/leaves", bvh.leaves)
        p.add(key + "/tree", (bvh.lo, bvh.hi, bvh.children))
        p.add(key + "/depth", bvh.depth)
        hits = bvh.intersect(o, d)
        p.add(key + "/hits", (hits.t, hits.ids))
        p.add(key + "/triangle_tests", hits.triangle_tests)
        p.add(key + "/box_tests", hits.box_tests)


def _bsp_nodes(node, out):
    """Pre-order list of every BSP node's plane, ids and polygons."""
    stack = [node]
    while stack:
        n = stack.pop()
        if n is None:
            out.append(None)
            continue
        out.append((n.normal, n.offset, list(n.ids), list(n.polygons)))
        stack += [n.back, n.front]
    return out


def part_painter(p):
    from course_lib import viewing, visibility
    scenes = {kind: visibility.painter_counterexample(kind)
              for kind in ("cyclic", "interpenetrating")}
    scenes["random40"] = visibility.random_scene(40, seed=5)
    eyes = [[0.0, 0.0, 5.0], [3.0, -2.0, 4.0], [-4.0, 1.0, -3.0], [0.0, 0.0, 1.0, 0.0]]
    for name, s in scenes.items():
        tris = s.vertices[s.faces]
        for choose in ("first", "fewest_splits"):
            tree = visibility.build_bsp(tris, choose=choose)
            key = f"bsp/{name}/{choose}"
            p.add(key + "/nodes", _bsp_nodes(tree.root, []))
            p.add(key + "/counts", (tree.n_nodes, tree.n_polygons, tree.n_splits, tree.depth))
            for k, eye in enumerate(eyes):
                polys, ids = visibility.bsp_back_to_front(tree, eye)
                p.add(f"{key}/back_to_front/{k}", (ids, polys))
        for key_kind in ("farthest", "centroid"):
            p.add(f"depth_sort/{name}/{key_kind}", visibility.depth_sort(tris, s.view, key_kind))
        for order in ("bsp", "depth_sort"):
            img = visibility.render_painter(s.vertices, s.faces, s.view, s.projection, 48, 48,
                                            order=order)
            p.add(f"render_painter/{name}/{order}", (img.ids, img.fragments))
    # ties: a wall of equal triangles facing an oblique camera (equal depth keys)
    cols, rows = np.meshgrid(np.arange(6.0), np.arange(4.0))
    base = np.array([[0.0, 0.0, 0.0], [0.8, 0.0, 0.0], [0.0, 0.8, 0.0]])
    wall = base[None] + np.stack([cols.ravel(), rows.ravel(), np.zeros(cols.size)], axis=1)[:, None]
    for eye in ([2.5, 1.5, 6.0], [9.0, 5.0, 4.0]):
        view = viewing.look_at(eye, np.array([2.5, 1.5, 0.0]) - eye, [0, 1, 0])
        for key_kind in ("farthest", "centroid"):
            p.add(f"depth_sort/wall/{eye}/{key_kind}", visibility.depth_sort(wall, view,
                                                                             key_kind))
    # notebooks/ch05 (painter's counterexample cell): the counts it prints
    scene = visibility.painter_counterexample("cyclic")
    size = 96
    reference = visibility.render_depth(*scene, size, size)
    naive = visibility.render_painter(*scene, size, size, order="depth_sort")
    bsp = visibility.render_painter(*scene, size, size, order="bsp")
    tree = visibility.build_bsp(scene.vertices[scene.faces])
    p.add("notebook/ch05/bsp_counts", (tree.n_nodes, tree.n_splits, tree.n_polygons))
    p.add("notebook/ch05/painter_wrong_pixels", int((naive.ids != reference.ids).sum()))
    p.add("notebook/ch05/bsp_wrong_pixels", int((bsp.ids != reference.ids).sum()))


def part_occlusion(p):
    from course_lib import visibility
    square = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], float)
    occluders = [square + [3 * i, 0, -2 * (i % 2)] for i in range(-2, 3)]
    occluders += [square * [1, 1, 0] + [-3 * i, 0, -2 * (i % 2)] for i in range(-2, 3)]  # ties
    p.add("rank_occluders", visibility.rank_occluders([0, 0, 6], occluders))
    plan = visibility.example_floor_plan()
    visible, witnesses = visibility.pvs(plan, return_witnesses=True)
    p.add("pvs/visible", visible)
    p.add("pvs/witnesses", witnesses)


def part_notebook_counts(p):
    from course_lib import raytracing as rt
    from course_lib import viewing, visibility
    # notebooks/ch05: "with a bounding-volume hierarchy: N ray-triangle tests + M box tests"
    sphere_v, sphere_f = _torus_ch05()
    view = viewing.look_at([0.0, -3.5, 2.5], [0.0, 3.5, -2.5], [0, 0, 1])
    proj = viewing.perspective(np.radians(45), 1.0, 0.5, 20.0)
    zb = visibility.render_depth(sphere_v, sphere_f, view, proj, 64, 64)
    fast = visibility.ray_cast_image(sphere_v, sphere_f, view, proj, 64, 64, accelerate=True)
    p.add("notebook/ch05/bvh_triangle_tests", fast.triangle_tests)
    p.add("notebook/ch05/bvh_box_tests", fast.box_tests)
    p.add("notebook/ch05/zbuffer_fragments", zb.fragments)
    p.add("notebook/ch05/same_ids", int((fast.ids == zb.ids).sum()))
    # notebooks/ch15: the torus mesh's BVH against brute force
    mesh_scene = rt.example_scene("mesh", 80, 60)
    torus = mesh_scene.objects[1]
    rays = mesh_scene.camera.rays()
    o, d = rays.origins.reshape(-1, 3), rays.directions.reshape(-1, 3)
    hits = torus.bvh.intersect(o, d)
    p.add("notebook/ch15/bvh", repr(torus.bvh))
    p.add("notebook/ch15/bvh_triangle_tests", hits.triangle_tests)
    p.add("notebook/ch15/bvh_box_tests", hits.box_tests)
    p.add("notebook/ch15/bvh_hits", (hits.t, hits.ids))
    # notebooks/ch15: the ray counts of a recursive render (smaller image, same scene)
    spheres = rt.example_scene("spheres", 40, 30)
    for depth, min_weight in ((2, 0.0), (8, 1 / 255)):
        image, counts = rt.render(spheres, max_depth=depth, min_weight=min_weight,
                                  return_counts=True)
        p.add(f"notebook/ch15/render/{depth}/{min_weight:.4f}/rays", counts.total)
        p.add(f"notebook/ch15/render/{depth}/{min_weight:.4f}/image", image)
    image, counts = rt.render(rt.example_scene("mesh", 32, 24), max_depth=2, return_counts=True)
    p.add("notebook/ch15/render/mesh/rays", counts.total)
    p.add("notebook/ch15/render/mesh/image", image)


def part_mesh(p):
    from course_lib import mesh
    from course_lib.widgets.simplification import TARGET_FACES, bumpy_sphere
    meshes = {"tetrahedron": mesh.tetrahedron(), "cube": mesh.cube(), "icosphere2":
              mesh.icosphere(2), "torus": mesh.torus(), "double_torus": mesh.double_torus(),
              "disc": mesh.disc()}
    for name, (v, f) in meshes.items():
        he = mesh.HalfEdgeMesh.from_faces(v, f)
        p.add(f"half_edge/{name}", {k: val for k, val in vars(he).items()
                                    if isinstance(val, np.ndarray)})
        p.add(f"half_edge/{name}/edges", he.edges())
        we = mesh.WingedEdgeMesh.from_faces(v, f)
        p.add(f"winged_edge/{name}", we.records())
    for name, make in (("three_faces_on_an_edge", mesh.three_faces_on_an_edge),
                       ("bow_tie", mesh.bow_tie)):
        p.add(f"mesh_problems/{name}", [tuple(problem) for problem in mesh.mesh_problems(*make())])
    runs = {"icosphere3_200": (mesh.icosphere(3), 200),
            "bumpy3_widget": (bumpy_sphere(3), TARGET_FACES),
            "bumpy4_500": (bumpy_sphere(4), 500)}          # notebooks/ch06
    for name, ((v, f), target) in runs.items():
        out = mesh.simplify_qem(v, f, target)
        rec = out.record
        key = f"qem/{name}"
        p.add(key + "/collapses", [tuple(c)
                                   for c in rec.collapses])
        p.add(key + "/result", (out.vertices, out.faces))
        p.add(key + "/stop_reason", rec.stop_reason)
        p.add(key + "/rejections", rec.rejections)
        for k in (0, len(rec) // 2):
            p.add(f"{key}/queue_after/{k}", [tuple(c)
                                             for c in rec.queue_after(k)])


def part_scivis(p):
    from course_lib import scivis, shading
    for kind in ("hills", "circle", "ripple", "saddle"):
        try:
            field = scivis.example_field_2d(kind, size=24)
        except ValueError:
            continue
        segs = scivis.marching_squares(field.values, field.level, field.spacing, field.origin)
        p.add(f"marching_squares/{kind}", segs)
        p.add(f"isolines/{kind}", scivis.isolines(field.values, field.level, field.spacing,
                                                  field.origin))
    for kind, size in (("sphere", 16), ("sphere", 32), ("torus", 48)):
        vol = scivis.example_volume(kind, size=size)
        p.add(f"marching_cubes/{kind}{size}", scivis.marching_cubes(vol.values, vol.level,
                                                                    vol.spacing, vol.origin))
    # notebooks/ch12: ambient occlusion with triangles (through the BVH)
    up = np.array([0.0, 0.0, 1.0])
    wall_x = np.array([[[0, -50, 0], [0, 50, 0], [0, 50, 50]], [[0, -50, 0], [0, 50, 50],
                                                                 [0, -50, 50]]], float)
    wall_y = np.array([[[-50, 0, 0], [50, 0, 0], [50, 0, 50]], [[-50, 0, 0], [50, 0, 50],
                                                                 [-50, 0, 50]]], float)
    corner = shading.ambient_occlusion([[0.3, 0.2, 0.0]], up, np.concatenate([wall_x, wall_y]),
                                       samples=4000, seed=1)
    p.add("notebook/ch12/ao_corner", (corner.visibility, corner.std_error))
    tris = _icosphere_triangles() * 0.5 + [0.0, 0.0, 0.6]
    pts = np.stack(np.meshgrid(np.linspace(-1, 1, 12), np.linspace(-1, 1, 12), [0.0]),
                   -1).reshape(-1, 3)
    ao = shading.ambient_occlusion(pts, np.tile(up, (len(pts), 1)), tris, samples=64, seed=2)
    p.add("ambient_occlusion/icosphere", (ao.visibility, ao.std_error))


def part_dataviz(p):
    """Chapter 10: the Delaunay triangulation (Bowyer-Watson; a square grid's points are
    cocircular four at a time, so the diagonals are ties), nearest neighbours (equidistant
    queries), the parallel-coordinates raster and brushes, and PCA's axes."""
    from course_lib import dataviz
    from course_lib.widgets import parallel_coordinates, scattered
    samples, values = scattered.sample_points(60)
    g = np.stack(np.meshgrid(np.arange(5.0), np.arange(4.0)), -1).reshape(-1, 2)
    for name, pts in (("explorer", samples), ("grid", g)):
        p.add(f"dataviz/delaunay/{name}", dataviz.delaunay_triangulation(pts))
    query = np.stack(np.meshgrid(np.arange(0, 4.01, 0.5), np.arange(0, 3.01, 0.5)), -1)
    p.add("dataviz/nearest/grid", dataviz.nearest_interpolate(
        g, np.arange(len(g), dtype=float), query.reshape(-1, 2)))
    s = parallel_coordinates.scene(parallel_coordinates.State())
    p.add("dataviz/parallel_coordinates", (s["mask"], s["counts"], s["selected_counts"],
                                           s["title"]))
    cars = dataviz.cars_table()
    p.add("dataviz/pca/cars", dataviz.pca(cars.data, k=2, standardise=True))


def part_simplification(p):
    """Chapter 6: vertex clustering and vertex decimation (a flat grid: every criterion ties at
    0), the levels of detail and the progressive mesh's meshes."""
    from course_lib import mesh
    from course_lib.widgets.simplification import bumpy_sphere
    sv, sf = bumpy_sphere(2)
    g = np.stack(np.meshgrid(np.arange(5.0), np.arange(5.0)), -1).reshape(-1, 2)
    gv = np.column_stack([g, np.zeros(len(g))])
    gf = np.array([[i * 5 + j, i * 5 + j + 1, i * 5 + j + 6] for i in range(4) for j in range(4)]
                  + [[i * 5 + j, i * 5 + j + 6, i * 5 + j + 5] for i in range(4) for j in range(4)])
    for name, (v, f) in (("sphere", (sv, sf)), ("grid", (gv, gf))):
        for rep in ("mean", "quadric"):
            c = mesh.vertex_clustering(v, f, cells=4, representative=rep)
            p.add(f"simplification/clustering/{name}/{rep}", (c.vertices, c.faces))
        d = mesh.decimate(v, f, max(2, len(f) // 4), feature_angle=np.pi / 2)
        p.add(f"simplification/decimation/{name}", (d.vertices, d.faces))
    pm = mesh.ProgressiveMesh(sv, sf, base_faces=len(sf) // 10)
    for n in (len(sf), len(sf) // 2, len(sf) // 8):
        p.add(f"simplification/progressive/{n}", pm.mesh(n))


def part_widgets(p):
    from course_lib.widgets import camera, simplification, zbuffer
    states = [camera.State(),
              camera.State(eye_x=0.0, eye_y=-6.0, eye_z=0.0, azimuth_deg=90.0,
                           elevation_deg=0.0),                  # symmetric: equal depths
              camera.State(projection="orthographic", eye_x=0.0, eye_y=0.0, eye_z=6.0,
                           azimuth_deg=90.0, elevation_deg=-90.0, up_x=0.0, up_y=1.0,
                           up_z=0.0),
              camera.State(projection="oblique")]
    for k, state in enumerate(states):
        s = camera.scene(state)
        p.add(f"widget/camera/{k}", (s.get("error"), s.get("colors"), s.get("polygons")))
    for name in zbuffer.ORDERS:
        s = zbuffer.scene(zbuffer.State(order=name, step=len(zbuffer.TRIANGLES)))
        p.add(f"widget/zbuffer/{name}", (s["order"], s["ids"], s["writes"]))
    for faces in (simplification.START_FACES, 400, simplification.TARGET_FACES):
        s = simplification.scene(simplification.State(faces=faces))
        p.add(f"widget/simplification/{faces}", s)


def part_exercises(p):
    from course_lib.exercises import mock
    for chapter, name in mock._exercise_modules().items():
        module = importlib.import_module(f"course_lib.exercises.{name}")
        for cls in module.EXERCISES:
            variants = []
            for seed in EXERCISE_SEEDS:
                ex = cls(seed=seed)
                variants.append((vars(ex), ex.statement()))
            p.add(f"exercises/{chapter}/{cls.__name__}", variants)
    for seed in EXAM_SEEDS:
        exam = mock.mock_exam(seed)
        p.add(f"mock_exam/{seed}", [(q.key, q.seed, q.markdown()) for q in exam.questions])


PARTS = {name[5:]: fn for name, fn in globals().items() if name.startswith("part_")}


def runtime():
    """What numpy and OpenBLAS dispatch to in this process (the setting under test)."""
    from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    return {"dispatch_enabled": [f for f in __cpu_dispatch__ if __cpu_features__.get(f)],
            "openblas_core": openblas_core(),
            "fma": bool(__cpu_features__.get("AVX2") and __cpu_features__.get("FMA3"))}


def openblas_core():
    """The core type OpenBLAS chose (None when numpy's BLAS is not a findable OpenBLAS)."""
    import ctypes
    import glob
    import os
    folder = os.path.join(os.path.dirname(os.path.dirname(np.__file__)), "numpy.libs")
    for path in glob.glob(os.path.join(folder, "*openblas*")):
        lib = ctypes.CDLL(path)
        for name in ("scipy_openblas_get_corename64_", "scipy_openblas_get_corename",
                     "openblas_get_corename64_", "openblas_get_corename"):
            fn = getattr(lib, name, None)
            if fn is not None:
                fn.restype = ctypes.c_char_p
                return fn().decode()
    return None


def main(argv):
    if "--runtime" in argv:
        json.dump({"runtime": runtime()}, sys.stdout)
        return
    only = argv[argv.index("--only") + 1] if "--only" in argv else ""
    p = Probe()
    for name, fn in PARTS.items():
        if name.startswith(only):
            fn(p)
    json.dump({"runtime": runtime(), "fingerprints": p}, sys.stdout, indent=0, sort_keys=True)


if __name__ == "__main__":
    main(sys.argv[1:])
