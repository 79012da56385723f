"""Tests of course_lib.visibility (chapter 5: z-buffer, ray casting, BSP painter, culling).

Expected values come from closed forms worked out here (plane equations, pixel counts of squares,
solid angles), from independent re-implementations written in this file (ray-plane intersection
with a point-in-triangle test, slab tests, segment-wall intersection with shapely), from Monte
Carlo sampling, or from cross-agreement between independent algorithms (z-buffer, ray casting
and the BSP painter must draw the same picture). Nothing is copied from the code's output.
"""
import numpy as np
import pytest
import shapely
from shapely.ops import unary_union

from course_lib import transforms, viewing
from course_lib import visibility as vis

RNG = np.random.default_rng


# ---------------------------------------------------------------------------------------------
# helpers (independent of the code under test)
# ---------------------------------------------------------------------------------------------

def centres(width, height):
    """Pixel centres as arrays (height, width): x = i + 0.5, y = j + 0.5, row 0 at the bottom."""
    return np.meshgrid(np.arange(width) + 0.5, np.arange(height) + 0.5)


def camera(eye=(0.0, 0.0, 5.0), target=(0.0, 0.0, 0.0), fov=50, near=1.0, far=20.0):
    eye = np.asarray(eye, float)
    view = viewing.look_at(eye, np.asarray(target, float) - eye, [0, 1, 0])
    return view, viewing.perspective(np.radians(fov), 1.0, near, far)


def window_depth(distance, near, far):
    """Viewport depth in [0, 1] of a point `distance` in front of the eye (perspective camera):
    z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) d), then (z_ndc + 1) / 2."""
    z_ndc = (far + near) / (far - near) - 2 * far * near / ((far - near) * distance)
    return (z_ndc + 1) / 2


def pixel_rays(view, projection, width, height):
    """Eye position and unit world directions through every pixel centre (height, width, 3),
    built from the camera's ECS axes and field of view (not from the code under test)."""
    inv_view = np.linalg.inv(view)
    eye = inv_view[:3, 3]
    x_e, y_e, z_e = inv_view[:3, 0], inv_view[:3, 1], inv_view[:3, 2]
    t = 1 / projection[1, 1]                    # tan(fov / 2) at distance 1
    r = 1 / projection[0, 0]
    cx, cy = centres(width, height)
    u = (cx / width * 2 - 1) * r
    v = (cy / height * 2 - 1) * t
    d = u[..., None] * x_e + v[..., None] * y_e - z_e
    return eye, d / np.linalg.norm(d, axis=-1, keepdims=True), -z_e


def ray_hits_triangle(o, d, tri, margin=0.0):
    """Closed form: t = n.(v0 - o) / n.d on the triangle's plane, then barycentric coordinates
    of the hit from areas (cross products with the normal). Returns (t, min barycentric)."""
    v0, v1, v2 = tri
    n = np.cross(v1 - v0, v2 - v0)
    denom = d @ n
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((v0 - o) @ n) / denom
    x = o + t[..., None] * d
    nn = n @ n
    b0 = np.cross(v2 - v1, x - v1) @ n / nn
    b1 = np.cross(v0 - v2, x - v2) @ n / nn
    b2 = np.cross(v1 - v0, x - v0) @ n / nn
    return t, np.minimum(np.minimum(b0, b1), b2)


def segment_distance(px, py, a, b):
    """Distance from points (px, py) to the segment a-b (2D)."""
    ab = b - a
    L = ab @ ab
    s = np.clip(((px - a[0]) * ab[0] + (py - a[1]) * ab[1]) / L, 0, 1) if L > 0 else 0 * px
    return np.hypot(px - (a[0] + s * ab[0]), py - (a[1] + s * ab[1]))


def near_any_edge(polygons_screen, width, height, radius=0.5):
    """Mask of pixels whose centre lies within `radius` of an edge of any screen polygon."""
    cx, cy = centres(width, height)
    mask = np.zeros((height, width), dtype=bool)
    for poly in polygons_screen:
        for k in range(len(poly)):
            mask |= segment_distance(cx, cy, poly[k, :2], poly[(k + 1) % len(poly), :2]) < radius
    return mask


def uv_sphere(n_around, n_up, radius=1.0, centre=(0, 0, 0)):
    """A closed triangulated sphere, faces counter-clockwise seen from outside."""
    th = np.linspace(0, np.pi, n_up + 1)
    ph = np.linspace(0, 2 * np.pi, n_around + 1)[:-1]
    T, PH = np.meshgrid(th, ph, indexing="ij")
    v = radius * np.stack([np.sin(T) * np.cos(PH), np.sin(T) * np.sin(PH), np.cos(T)], -1)
    v[0], v[-1] = [0, 0, radius], [0, 0, -radius]      # exact poles (sin(pi) is not 0)
    v = v.reshape(-1, 3) + centre
    faces = []
    for i in range(n_up):
        for j in range(n_around):
            a, b = i * n_around + j, i * n_around + (j + 1) % n_around
            c, d = a + n_around, b + n_around
            faces += [[a, c, d], [a, d, b]]
    return v, np.array(faces)


# ---------------------------------------------------------------------------------------------
# z-buffer: coverage, fill rule, depth
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("seed", range(6))
def test_single_triangle_depth_and_coverage_match_the_plane_and_shapely(seed):
    rng = RNG(seed)
    W, H = 40, 30
    tri = np.column_stack([rng.uniform(-5, W + 5, 3), rng.uniform(-5, H + 5, 3),
                           rng.uniform(0.05, 0.95, 3)])
    zb = vis.zbuffer([tri], W, H)
    # depth: the plane through the three screen vertices, z = z0 - (nx (x-x0) + ny (y-y0)) / nz
    n = np.cross(tri[1] - tri[0], tri[2] - tri[0])
    cx, cy = centres(W, H)
    plane_z = tri[0, 2] - (n[0] * (cx - tri[0, 0]) + n[1] * (cy - tri[0, 1])) / n[2]
    drawn = zb.ids == 0
    np.testing.assert_allclose(zb.depth[drawn], plane_z[drawn], rtol=0, atol=1e-12)
    assert np.all(np.isinf(zb.depth[~drawn])) and np.all(zb.ids[~drawn] == -1)
    # coverage: centres strictly inside (shapely), away from the boundary by more than 1e-9
    poly = shapely.Polygon(tri[:, :2])
    pts = shapely.points(cx.ravel(), cy.ravel())
    inside = shapely.contains(poly, pts).reshape(H, W)
    clear = (shapely.distance(poly.exterior, pts) > 1e-9).reshape(H, W)
    assert inside[clear].sum() > 0 or poly.area < 5
    np.testing.assert_array_equal(drawn[clear], inside[clear])


def _covered_count(triangles, W, H):
    counts = np.zeros((H, W), dtype=int)
    for tri in triangles:
        rows, cols, _ = vis.triangle_coverage(tri, W, H)
        np.add.at(counts, (rows, cols), 1)
    return counts


@pytest.mark.parametrize("x0, x1, y0, y1", [(2.3, 7.8, 1.2, 6.6), (0.9, 9.1, 3.2, 5.4)])
def test_square_of_two_triangles_fills_exactly_its_pixels(x0, x1, y0, y1):
    W, H = 12, 9
    a, b, c, d = [x0, y0, 0.5], [x1, y0, 0.5], [x1, y1, 0.5], [x0, y1, 0.5]
    for tris in ([[a, b, c], [a, c, d]], [[a, b, d], [b, c, d]]):      # both diagonals
        counts = _covered_count(tris, W, H)
        cx, cy = centres(W, H)
        expected = (cx > x0) & (cx < x1) & (cy > y0) & (cy < y1)
        assert expected.sum() > 10 and counts.max() == 1, "a pixel was drawn twice"
        np.testing.assert_array_equal(counts == 1, expected)
        zb = vis.zbuffer(tris, W, H)
        assert (zb.ids >= 0).sum() == expected.sum() == zb.writes == zb.fragments


def test_square_with_corners_on_pixel_centres_follows_the_documented_fill_rule():
    # corners exactly on centres: the left and top edges are in, the right and bottom ones out
    W, H = 10, 10
    x0, x1, y0, y1 = 1.5, 6.5, 2.5, 8.5
    a, b, c, d = [x0, y0, 0.5], [x1, y0, 0.5], [x1, y1, 0.5], [x0, y1, 0.5]
    cx, cy = centres(W, H)
    expected = (cx >= x0) & (cx < x1) & (cy > y0) & (cy <= y1)
    for tris in ([[a, b, c], [a, c, d]], [[a, b, d], [b, c, d]], [[c, b, a], [d, c, a]]):
        counts = _covered_count(tris, W, H)
        assert counts.max() == 1
        np.testing.assert_array_equal(counts == 1, expected)


@pytest.mark.parametrize("seed", range(3))
def test_jittered_mesh_is_watertight(seed):
    # a grid of vertices, half of them snapped onto pixel centres so that many edges run
    # exactly through centres; every centre strictly inside the outer border is drawn once
    rng = RNG(seed)
    W, H, n = 30, 24, 7
    xs = np.linspace(1.25, W - 1.25, n)
    ys = np.linspace(1.25, H - 1.25, n)
    X, Y = np.meshgrid(xs, ys)
    inner = (slice(1, -1), slice(1, -1))
    X[inner] += rng.uniform(-1, 1, X[inner].shape)
    Y[inner] += rng.uniform(-1, 1, Y[inner].shape)
    snap = rng.random(X.shape) < 0.5
    snap[0, :] = snap[-1, :] = snap[:, 0] = snap[:, -1] = False
    X[snap], Y[snap] = np.floor(X[snap]) + 0.5, np.floor(Y[snap]) + 0.5
    V = np.column_stack([X.ravel(), Y.ravel(), np.full(X.size, 0.5)])
    tris = []
    for j in range(n - 1):
        for i in range(n - 1):
            p, q, r, s = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            tris += [[p, q, r], [p, r, s]] if rng.random() < 0.5 else [[p, q, s], [q, r, s]]
    counts = _covered_count(V[np.array(tris)], W, H)
    cx, cy = centres(W, H)
    inside = (cx > xs[0]) & (cx < xs[-1]) & (cy > ys[0]) & (cy < ys[-1])
    assert counts.max() == 1, "overlap: some pixel is covered by two triangles"
    np.testing.assert_array_equal(counts == 1, inside)


@pytest.mark.parametrize("near_first", [True, False])
def test_two_parallel_squares_the_nearer_wins_everywhere(near_first):
    W, H = 16, 16
    far = [[[1, 1, 0.7], [15, 1, 0.7], [15, 15, 0.7]], [[1, 1, 0.7], [15, 15, 0.7], [1, 15, 0.7]]]
    near = [[[4, 3, 0.2], [12, 3, 0.2], [12, 11, 0.2]], [[4, 3, 0.2], [12, 11, 0.2], [4, 11, 0.2]]]
    tris = near + far if near_first else far + near
    near_ids = {0, 1} if near_first else {2, 3}
    zb = vis.zbuffer(tris, W, H)
    cx, cy = centres(W, H)
    in_near = (cx > 4) & (cx < 12) & (cy > 3) & (cy < 11)
    in_far = (cx > 1) & (cx < 15) & (cy > 1) & (cy < 15)
    assert np.isin(zb.ids[in_near], list(near_ids)).all()
    np.testing.assert_allclose(zb.depth[in_near], 0.2)
    assert not np.isin(zb.ids[in_far & ~in_near], list(near_ids)).any()
    np.testing.assert_allclose(zb.depth[in_far & ~in_near], 0.7)
    assert np.all(zb.ids[~in_far] == -1)
    # drawn far first, the near square overwrites; drawn near first, the far one is rejected
    assert zb.writes == (in_far.sum() + in_near.sum() if not near_first else in_far.sum())


def test_fragments_outside_the_depth_range_are_dropped():
    # a triangle whose depth runs from -0.5 to 1.5 across the image keeps only 0 <= z <= 1
    W, H = 20, 4
    tri = [[0, -10, -0.5], [20, -10, 1.5], [0, 30, -0.5]]
    tri2 = [[20, -10, 1.5], [20, 30, 1.5], [0, 30, -0.5]]
    zb = vis.zbuffer([tri, tri2], W, H)
    cx, _ = centres(W, H)
    z = -0.5 + 2 * cx / 20
    np.testing.assert_array_equal(zb.ids >= 0, (z >= 0) & (z <= 1))


def test_drawing_order_does_not_change_the_buffers():
    s = vis.random_scene(25, seed=3)
    tris = transforms.apply(viewing.viewport(0, 0, 40, 40),
                            transforms.apply(s.projection @ s.view, s.vertices))[s.faces]
    zb = vis.zbuffer(tris, 40, 40)
    perm = RNG(0).permutation(len(tris))
    zb2 = vis.zbuffer(tris[perm], 40, 40)
    np.testing.assert_array_equal(zb.depth, zb2.depth)
    np.testing.assert_array_equal(zb.ids, np.where(zb2.ids >= 0, perm[zb2.ids], -1))


def test_zbuffer_steps_replay_the_zbuffer():
    s = vis.random_scene(10, seed=5)
    tris = transforms.apply(viewing.viewport(0, 0, 24, 24),
                            transforms.apply(s.projection @ s.view, s.vertices))[s.faces]
    steps = list(vis.zbuffer_steps(tris, 24, 24))
    zb = vis.zbuffer(tris, 24, 24)
    assert [st.index for st in steps] == list(range(10))
    np.testing.assert_array_equal(steps[-1].ids, zb.ids)
    np.testing.assert_array_equal(steps[-1].depth, zb.depth)
    assert sum(int(st.written.sum()) for st in steps) == zb.writes
    prev = np.full((24, 24), np.inf)
    for st in steps:
        assert not (st.written & ~st.covered).any()
        assert np.all(st.ids[st.written] == st.index)
        assert np.all(st.depth <= prev)            # the depth buffer only ever decreases
        prev = st.depth


# ---------------------------------------------------------------------------------------------
# the whole pipeline: render_depth
# ---------------------------------------------------------------------------------------------

def test_render_depth_matches_the_ray_plane_depth_of_a_tilted_triangle():
    near, far = 1.0, 20.0
    view, proj = camera(eye=(0.7, -0.4, 6.0), fov=45, near=near, far=far)
    tri = np.array([[-2.0, -1.5, -1.0], [2.5, -1.0, 1.0], [0.0, 2.5, -0.5]])
    W, H = 48, 40
    proj = viewing.perspective(np.radians(45), W / H, near, far)
    zb = vis.render_depth(tri, [[0, 1, 2]], view, proj, W, H)
    eye, dirs, forward = pixel_rays(view, proj, W, H)
    t, bmin = ray_hits_triangle(eye, dirs, tri)
    distance = t * (dirs @ forward)                 # distance in front of the eye, -z_e
    hit = bmin > 1e-9
    edge = np.abs(bmin) <= 1e-9
    np.testing.assert_array_equal((zb.ids == 0)[~edge], hit[~edge])
    np.testing.assert_allclose(zb.depth[hit], window_depth(distance[hit], near, far), atol=1e-12)


def test_perspective_correct_values_give_the_world_coordinate_of_the_surface():
    near, far = 0.5, 30.0
    view, proj = camera(eye=(0.0, 1.0, 0.0), target=(0.0, 0.0, -6.0), fov=60, near=near, far=far)
    # a long floor quad receding from the eye: x and z of the surface vary non-linearly on screen
    verts = np.array([[-3, -0.5, -1], [3, -0.5, -1], [3, -0.5, -25], [-3, -0.5, -25]], float)
    faces = [[0, 1, 2], [0, 2, 3]]
    W = H = 32
    zb = vis.render_depth(verts, faces, view, proj, W, H, values=verts[:, [0, 2]])
    eye, dirs, _ = pixel_rays(view, proj, W, H)
    t = (-0.5 - eye[1]) / dirs[..., 1]
    point = eye + t[..., None] * dirs
    inside = (np.abs(point[..., 0]) < 2.999) & (point[..., 2] < -1.001) & (point[..., 2] > -24.99)
    inside &= t > 0
    assert inside.sum() > 200
    np.testing.assert_array_equal(zb.ids >= 0, inside)
    np.testing.assert_allclose(zb.image[inside], point[inside][:, [0, 2]], rtol=1e-9, atol=1e-9)


def test_affine_values_interpolate_exactly_in_screen_space():
    W, H = 20, 20
    tri = np.array([[1.3, 2.1, 0.3], [18.2, 4.4, 0.6], [7.7, 19.0, 0.9]])
    # per-vertex values given by an affine function of screen position: 2x - 3y + 1
    f = lambda x, y: 2 * x - 3 * y + 1       # noqa: E731
    zb = vis.zbuffer([tri], W, H, values=[f(tri[:, 0], tri[:, 1])])
    cx, cy = centres(W, H)
    drawn = zb.ids == 0
    np.testing.assert_allclose(zb.image[drawn], f(cx, cy)[drawn], atol=1e-10)
    assert np.all(zb.image[~drawn] == 0.0)


def test_near_plane_clipping_of_a_floor_that_extends_behind_the_eye():
    near, far = 0.5, 40.0
    view, proj = camera(eye=(0.0, 1.0, 0.0), target=(0.0, 0.6, -5.0), fov=70, near=near, far=far)
    verts = np.array([[-8, 0, 6], [8, 0, 6], [8, 0, -30], [-8, 0, -30]], float)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    W = H = 36
    zb = vis.render_depth(verts, faces, view, proj, W, H)
    eye, dirs, forward = pixel_rays(view, proj, W, H)
    with np.errstate(divide="ignore"):
        t = -eye[1] / dirs[..., 1]
    point = eye + t[..., None] * dirs
    distance = t * (dirs @ forward)
    hit = (t > 0) & (np.abs(point[..., 0]) < 8) & (point[..., 2] > -30) & (distance <= far)
    hit &= (np.abs(np.abs(point[..., 0]) - 8) > 1e-6) & (np.abs(point[..., 2] + 30) > 1e-6)
    margin = (np.abs(distance - far) > 1e-3) | ~hit
    np.testing.assert_array_equal((zb.ids >= 0)[margin], hit[margin])
    ok = hit & margin
    np.testing.assert_allclose(zb.depth[ok], window_depth(distance[ok], near, far), atol=1e-9)
    rc = vis.ray_cast_image(verts, faces, view, proj, W, H)
    np.testing.assert_array_equal((rc.ids >= 0)[margin], hit[margin])


def test_back_face_culling_keeps_the_picture_of_a_closed_mesh_and_halves_the_work():
    v, f = uv_sphere(16, 12)
    view, proj = camera(eye=(1.0, 2.0, 4.0))
    full = vis.render_depth(v, f, view, proj, 40, 40)
    culled = vis.render_depth(v, f, view, proj, 40, 40, cull_back_faces=True)
    np.testing.assert_array_equal(full.ids, culled.ids)
    assert culled.fragments < 0.6 * full.fragments


# ---------------------------------------------------------------------------------------------
# ray casting
# ---------------------------------------------------------------------------------------------

def test_ray_triangle_agrees_with_the_closed_form_plane_intersection():
    rng = RNG(11)
    checked = 0
    for _ in range(40):
        tri = rng.normal(size=(3, 3))
        o = rng.normal(size=(200, 3)) * 2
        d = tri.mean(axis=0) + 0.7 * rng.normal(size=(200, 3)) - o      # aimed near it
        t, u, v = vis.ray_triangle(o, d, tri)
        t_ref, bmin = ray_hits_triangle(o, d, tri)
        clear = np.abs(bmin) > 1e-8
        expect_hit = (bmin > 0) & clear
        got_hit = np.isfinite(t)
        np.testing.assert_array_equal(got_hit[clear], expect_hit[clear])
        np.testing.assert_allclose(t[expect_hit], t_ref[expect_hit], rtol=1e-9, atol=1e-9)
        # the barycentric coordinates reproduce the hit point
        uh, vh = u[expect_hit, None], v[expect_hit, None]
        hit_pt = tri[0] + uh * (tri[1] - tri[0]) + vh * (tri[2] - tri[0])
        np.testing.assert_allclose(hit_pt, o[expect_hit] + t[expect_hit, None] * d[expect_hit],
                                   atol=1e-8)
        checked += expect_hit.sum()
    assert checked > 500


def test_brute_force_ray_cast_returns_the_nearest_hit_in_the_range():
    rng = RNG(2)
    tris = rng.uniform(-1, 1, (60, 1, 3)) + 0.4 * rng.normal(size=(60, 3, 3))
    o = rng.uniform(-2, 2, (300, 3))
    d = rng.normal(size=(300, 3))
    t_min, t_max = 0.3, 2.5
    hits = vis.ray_cast(o, d, tris, t_min=t_min, t_max=t_max)
    assert hits.triangle_tests == 300 * 60 and hits.box_tests == 0
    # reference: closed form per triangle, keep the smallest t in range
    T = np.full((300, 60), np.inf)
    for k, tri in enumerate(tris):
        t, bmin = ray_hits_triangle(o, d, tri)
        ok = (bmin >= 0) & (t >= t_min) & (t <= t_max)
        T[ok, k] = t[ok]
    ref_t = T.min(axis=1)
    np.testing.assert_allclose(hits.t, ref_t, rtol=1e-9)
    hit = np.isfinite(ref_t)
    assert hit.sum() > 30
    same = hits.ids[hit] == T[hit].argmin(axis=1)
    assert same.mean() > 0.99            # ties within rounding may pick either triangle
    assert np.all(hits.ids[~hit] == -1)


@pytest.fixture(scope="module")
def big_sphere():
    v, f = uv_sphere(100, 100)          # 20,000 triangles
    return v[f]


def test_bvh_equals_brute_force_exactly_and_does_far_fewer_tests(big_sphere):
    tris = big_sphere
    assert len(tris) == 20_000
    rng = RNG(7)
    o = rng.normal(size=(400, 3))
    o = 3 * o / np.linalg.norm(o, axis=1, keepdims=True)
    d = -o + 0.4 * rng.normal(size=(400, 3))           # most rays hit, some miss
    brute = vis.ray_cast(o, d, tris)
    fast = vis.ray_cast(o, d, tris, accelerate=True)
    np.testing.assert_array_equal(fast.ids, brute.ids)
    np.testing.assert_array_equal(fast.t, brute.t)
    assert 50 < (brute.ids >= 0).sum() < 400
    assert brute.triangle_tests == 400 * 20_000
    assert fast.triangle_tests < 0.1 * brute.triangle_tests
    assert fast.triangle_tests < 0.001 * brute.triangle_tests    # in fact ~ tens per ray
    # and from inside the sphere, where every ray hits
    d = rng.normal(size=(200, 3))
    inside = vis.ray_cast(np.zeros(3), d, vis.BVH(tris))
    assert np.all(inside.ids >= 0)
    distance = inside.t * np.linalg.norm(d, axis=1)     # the facets lie within 1 - cos(pi/100)
    assert np.all((distance > 0.999) & (distance <= 1 + 1e-12))


def test_equal_distances_go_to_the_lower_index_with_and_without_the_bvh(big_sphere):
    # the mesh twice: triangle k and k + 20,000 are identical, so every hit is a tie
    tris = np.concatenate([big_sphere[:5000], big_sphere[:5000]])
    rng = RNG(12)
    o = rng.normal(size=(300, 3))
    o = 3 * o / np.linalg.norm(o, axis=1, keepdims=True)
    d = -o + 0.3 * rng.normal(size=(300, 3))
    for hits in (vis.ray_cast(o, d, tris), vis.ray_cast(o, d, tris, accelerate=True)):
        assert (hits.ids >= 0).sum() > 20
        assert hits.ids.max() < 5000


def test_bvh_handles_rays_parallel_to_box_faces_and_shared_bvh_reuse():
    # axis-aligned rays through a grid of axis-aligned squares: many zero direction components
    squares = []
    for i in range(5):
        for j in range(5):
            x, y = i - 2.0, j - 2.0
            squares += [[[x, y, -i], [x + 1, y, -i], [x + 1, y + 1, -i]],
                        [[x, y, -i], [x + 1, y + 1, -i], [x, y + 1, -i]]]
    squares = np.array(squares)
    bvh = vis.BVH(squares, leaf_size=2)
    rng = RNG(0)
    o = np.column_stack([rng.uniform(-3, 3, 500), rng.uniform(-3, 3, 500), np.full(500, 5.0)])
    for d in ([0, 0, -1], [0, 0, -2]):
        a, b = vis.ray_cast(o, d, bvh), vis.ray_cast(o, d, squares)
        np.testing.assert_array_equal(a.ids, b.ids)
        np.testing.assert_array_equal(a.t, b.t)


@pytest.mark.parametrize("leaf_size", [1, 3])
def test_bvh_median_split_sends_equal_centres_left_by_triangle_index(leaf_size):
    # equal triangles strung along x, many at the same x: every split is along x and most meet
    # ties at the median. Ties go left by lower triangle index (not in the order of whichever
    # CPU-specific partition kernel numpy picks), so leaf by leaf from left to right the
    # triangles are those sorted by (x, index)
    x = RNG(3).integers(0, 5, 60).astype(float)
    shape = np.array([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [0.0, 0.5, 0.0]])
    tris = shape[None] + np.column_stack([x, np.zeros(60), np.zeros(60)])[:, None]
    bvh = vis.BVH(tris, leaf_size=leaf_size)
    expected = sorted(range(60), key=lambda i: (x[i], i))
    leaves = sorted(map(tuple, bvh._spans[bvh.children[:, 0] < 0]))   # (start, end) in _order
    assert [s for s, _ in leaves] == [0] + [e for _, e in leaves[:-1]] and leaves[-1][1] == 60
    for s, e in leaves:
        assert 1 <= e - s <= leaf_size
        assert sorted(bvh._order[s:e].tolist()) == sorted(expected[s:e])


# ---------------------------------------------------------------------------------------------
# the three hidden-surface methods agree
# ---------------------------------------------------------------------------------------------

def _screen_polygons(polys, scene, W, H):
    vp = viewing.viewport(0, 0, W, H)
    return [viewing.to_screen(p, scene.view, scene.projection, vp) for p in polys]


@pytest.mark.parametrize("seed", range(4))
def test_zbuffer_ray_casting_and_bsp_painter_draw_the_same_picture(seed):
    W = H = 64
    scene = vis.random_scene(14, seed=seed, size=0.9)
    tris = scene.vertices[scene.faces]
    zb = vis.render_depth(*scene, W, H)
    rc = vis.ray_cast_image(*scene, W, H, accelerate=seed % 2 == 0)
    eye = np.linalg.inv(scene.view)[:3, 3]
    polys, ids = vis.bsp_back_to_front(vis.build_bsp(tris), eye)
    painted = vis.painter_image(polys, ids, scene.view, scene.projection, W, H)
    # exclude pixels within half a pixel of an edge of a triangle or of a BSP fragment
    edges = near_any_edge(_screen_polygons(list(tris) + polys, scene, W, H), W, H)
    covered = zb.ids >= 0
    assert covered.sum() > 400
    assert (covered & ~edges).sum() > max(150, 0.3 * covered.sum())
    keep = ~edges
    np.testing.assert_array_equal(rc.ids[keep], zb.ids[keep])
    np.testing.assert_array_equal(painted.ids[keep], zb.ids[keep])
    both = keep & covered
    np.testing.assert_allclose(rc.depth[both], zb.depth[both], atol=1e-9)


def test_bsp_painter_agrees_with_the_zbuffer_under_an_orthographic_camera():
    W = H = 40
    scene = vis.random_scene(12, seed=21, size=0.9)
    proj = viewing.orthographic(-2, 2, -2, 2, 1, 10)
    zb = vis.render_depth(scene.vertices, scene.faces, scene.view, proj, W, H)
    bsp = vis.render_painter(scene.vertices, scene.faces, scene.view, proj, W, H)
    fragments = vis.bsp_back_to_front(vis.build_bsp(scene.vertices[scene.faces]), [0, 0, 1, 0])[0]
    s = scene._replace(projection=proj)
    edges = near_any_edge(_screen_polygons(list(scene.vertices[scene.faces]) + fragments, s,
                                           W, H), W, H)
    assert (zb.ids >= 0).sum() > 200
    np.testing.assert_array_equal(bsp.ids[~edges], zb.ids[~edges])


@pytest.mark.parametrize("seed", range(3))
def test_bsp_order_is_back_to_front_for_every_overlapping_pair(seed):
    scene = vis.random_scene(10, seed=100 + seed, size=0.9)
    tris = scene.vertices[scene.faces]
    eye = np.linalg.inv(scene.view)[:3, 3]
    for choose in ("first", "fewest_splits"):
        polys, _ = vis.bsp_back_to_front(vis.build_bsp(tris, choose=choose), eye)
        screen = _screen_polygons(polys, scene, 100, 100)
        shapes = [shapely.Polygon(p[:, :2]) for p in screen]
        pv_inv = np.linalg.inv(scene.projection @ scene.view)
        pairs = 0
        for i in range(len(polys)):
            for j in range(i + 1, len(polys)):
                overlap = shapes[i].intersection(shapes[j])
                if overlap.area < 1e-3:
                    continue
                pairs += 1
                x, y = overlap.representative_point().coords[0]
                ndc = [x / 50 - 1, y / 50 - 1, 0.0]
                target = transforms.apply(pv_inv, ndc)
                d = target - eye
                depth = []
                for poly in (polys[i], polys[j]):
                    n = np.cross(poly[1] - poly[0], poly[2] - poly[0])
                    depth.append(((poly[0] - eye) @ n) / (d @ n))
                assert depth[1] <= depth[0] + 1e-9, f"polygon {j} drawn after {i} but farther"
        assert pairs > 5


@pytest.mark.parametrize("kind", ["cyclic", "interpenetrating"])
def test_depth_sort_fails_on_the_counterexamples_but_the_bsp_order_does_not(kind):
    W = H = 64
    scene = vis.painter_counterexample(kind)
    tris = scene.vertices[scene.faces]
    zb = vis.render_depth(*scene, W, H)
    naive = vis.render_painter(*scene, W, H, order="depth_sort")
    bsp = vis.render_painter(*scene, W, H, order="bsp")
    eye = np.linalg.inv(scene.view)[:3, 3]
    fragments = vis.bsp_back_to_front(vis.build_bsp(tris), eye)[0]
    edges = near_any_edge(_screen_polygons(list(tris) + fragments, scene, W, H), W, H)
    assert (naive.ids != zb.ids)[~edges].sum() > 40
    np.testing.assert_array_equal(bsp.ids[~edges], zb.ids[~edges])
    # the naive order is "farthest vertex first", checked by hand for the interpenetrating pair
    if kind == "interpenetrating":
        assert vis.depth_sort(tris, scene.view).tolist() == [1, 0]


def test_cyclic_counterexample_is_truly_cyclic_and_does_not_intersect():
    scene = vis.painter_counterexample("cyclic")
    tris = scene.vertices[scene.faces]
    planks = [tris[2 * k:2 * k + 2] for k in range(3)]
    # no two planks intersect: no edge of one crosses the other (independent segment tests)
    for a in range(3):
        for b in range(3):
            if a == b:
                continue
            for tri in planks[a]:
                for k in range(3):
                    p, q = tri[k], tri[(k + 1) % 3]
                    for other in planks[b]:
                        t, bmin = ray_hits_triangle(p, q - p, other)
                        assert not (0 <= t <= 1 and bmin >= 0)
    # from the eye, plank k is nearer than plank k + 1 somewhere: a cycle 0 > 1 > 2 > 0
    zb = vis.render_depth(*scene, 64, 64)
    owner = np.full(64 * 64, -1)                  # faces 2k and 2k + 1 make plank k
    flat = zb.ids.ravel()
    owner[flat >= 0] = flat[flat >= 0] // 2
    eye, dirs, _ = pixel_rays(scene.view, scene.projection, 64, 64)
    over = set()
    for pix in np.flatnonzero(owner >= 0):
        d = dirs.reshape(-1, 3)[pix]
        for k in range(3):
            if k == owner[pix]:
                continue
            for tri in planks[k]:
                t, bmin = ray_hits_triangle(eye, d[None], tri)
                if bmin[0] > 0:
                    over.add((int(owner[pix]), k))
    assert {(0, 1), (1, 2), (2, 0)} <= over
    assert not ({(1, 0), (2, 1), (0, 2)} & over)


def test_split_polygon_parts_tile_the_original():
    rng = RNG(4)
    for _ in range(50):
        tri = rng.normal(size=(3, 3))
        n = rng.normal(size=3)
        c = float(rng.normal() * 0.3)
        front, back = vis.split_polygon(tri, n, c)
        s = tri @ n - c
        if np.all(s > 0):
            assert back is None and front is not None
            continue
        if np.all(s < 0):
            assert front is None and back is not None
            continue
        assert front is not None and back is not None
        assert np.all(front @ n - c >= -1e-9) and np.all(back @ n - c <= 1e-9)
        # areas add up (vector area via cross products)
        area = lambda p: np.linalg.norm(sum(np.cross(p[k], p[(k + 1) % len(p)])     # noqa: E731
                                           for k in range(len(p)))) / 2
        assert area(front) + area(back) == pytest.approx(area(tri), rel=1e-9)
        assert len(front) + len(back) == 7          # a triangle cut in two: 3 + 4 vertices


def test_bsp_tree_statistics():
    v, f = uv_sphere(12, 8)
    tree = vis.build_bsp(v[f])
    # a closed convex object: every face plane has all the others behind it -> no splits, and
    # the degenerate pole triangles (zero area) are left out
    n_degenerate = 2 * 12
    assert tree.n_splits == 0 and tree.n_polygons == len(f) - n_degenerate
    crossing = [[[0, -1, -1], [0, 1, -1], [0, 0, 1]], [[-1, -0.5, 0], [1, -0.5, 0], [0, 1, 0]]]
    tree = vis.build_bsp(crossing)
    assert tree.n_splits == 1 and tree.n_polygons == 3 and tree.n_nodes == 3


# ---------------------------------------------------------------------------------------------
# from-point occlusion culling
# ---------------------------------------------------------------------------------------------

def segment_hits_polygon(p, q, poly):
    """Do the segments p -> q[i] cross the convex planar polygon (before q[i])? Independent test:
    intersect with the polygon's plane, then shapely's point-in-polygon in 2D plane coordinates."""
    q = np.atleast_2d(q)
    n = np.cross(poly[1] - poly[0], poly[2] - poly[0])
    denom = (q - p) @ n
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((poly[0] - p) @ n) / denom
    x = p + t[:, None] * (q - p)
    u = (poly[1] - poly[0]) / np.linalg.norm(poly[1] - poly[0])
    w = np.cross(n / np.linalg.norm(n), u)
    flat = shapely.Polygon([((v - poly[0]) @ u, (v - poly[0]) @ w) for v in poly]).buffer(1e-9)
    inside = shapely.contains_xy(flat, (x - poly[0]) @ u, (x - poly[0]) @ w)
    return (np.abs(denom) > 1e-15) & (t >= 0) & (t <= 1) & inside


def segment_hits_box(p, q, lo, hi):
    """Slab test: does the segment p -> q meet the box [lo, hi]?"""
    d = q - p
    t0, t1 = 0.0, 1.0
    for k in range(3):
        if abs(d[k]) < 1e-15:
            if not lo[k] <= p[k] <= hi[k]:
                return False
            continue
        a, b = sorted(((lo[k] - p[k]) / d[k], (hi[k] - p[k]) / d[k]))
        t0, t1 = max(t0, a), min(t1, b)
    return t0 <= t1 + 1e-12


WALL = [[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]]


def test_boxes_behind_a_wall_are_culled_beside_or_in_front_are_not():
    eye = [0, 0, 5]
    boxes = [
        [[-0.5, -0.5, -3], [0.5, 0.5, -2]],     # behind, centred: hidden
        [[-1, -1, -0.5], [1, 1, -0.1]],         # right behind: hidden
        [[4, 4, -3], [5, 5, -2]],               # beside: visible
        [[-0.5, -0.5, 1], [0.5, 0.5, 2]],       # in front: visible
        [[1.5, -0.5, -3], [3.5, 0.5, -2]],      # behind but sticks out of the shadow: visible
        [[-0.5, -0.5, -0.5], [0.5, 0.5, 0.5]],  # pierces the wall: not culled (conservative)
    ]
    culled, by = vis.occlusion_cull(eye, [WALL], boxes, return_index=True)
    assert culled.tolist() == [True, True, False, False, False, False]
    assert by.tolist() == [0, 0, -1, -1, -1, -1]
    # the shadow pyramid widens with distance: at z = -5 its half-width is 2 * 10 / 5 = 4
    wide = [[[-3.9, -3.9, -5.5], [3.9, 3.9, -5]], [[-4.1, -3.9, -5.5], [3.9, 3.9, -5]]]
    assert vis.occlusion_cull(eye, [WALL], wide).tolist() == [True, False]
    spheres = [[0, 0, -3, 1.0], [0, 0, -3, 2.5], [0, 0, 3, 0.1]]
    # half-width of the shadow at z = -3 is 2 * 8 / 5 = 3.2; the side planes are tilted, so the
    # largest sphere fitting at the axis has radius 3.2 * cos(atan(2 / 5)) = 2.97
    assert vis.occlusion_cull(eye, [WALL], spheres).tolist() == [True, True, False]
    assert vis.occlusion_cull(eye, [WALL], [[0, 0, -3, 3.0]]).tolist() == [False]


def test_box_occluder_hides_what_is_behind_it_not_what_is_in_front():
    eye = [0, 0, 10]
    occluder = [[-2, -2, -1], [2, 2, 1]]
    boxes = [[[-0.5, -0.5, -4], [0.5, 0.5, -3]],     # behind: hidden
             [[-0.5, -0.5, 3], [0.5, 0.5, 4]],       # between eye and occluder: visible
             [[-0.5, -0.5, -0.5], [0.5, 0.5, 0.5]],  # inside the solid occluder: hidden
             [[-0.5, -0.5, 0.5], [0.5, 0.5, 1.5]],   # sticks out of its front face: visible
             [[2.5, -0.5, -4], [3.5, 0.5, -3]]]      # behind, but outside the shadow
    assert vis.occlusion_cull(eye, [occluder], boxes).tolist() == [True, False, True, False,
                                                                  False]
    # seen from a corner direction the silhouette is a hexagon: 6 side planes + 3 front faces
    n, c = vis.shadow_frustum([5, 6, 7], occluder)
    assert len(n) == 9
    assert vis.occlusion_cull([5, 6, 7], [occluder], [[[-6, -7, -8], [-5, -6, -7]]]).tolist() \
        == [True]


def test_eye_in_the_occluder_plane_or_inside_a_box_culls_nothing():
    boxes = [[[-0.5, -0.5, -3], [0.5, 0.5, -2]]]
    assert vis.shadow_frustum([5, 0, 0], WALL) is None
    assert not vis.occlusion_cull([5, 0, 0], [WALL], boxes).any()
    assert vis.shadow_frustum([0, 0, 0], [[-1, -1, -1], [1, 1, 1]]) is None


@pytest.mark.parametrize("seed", range(4))
def test_culling_is_conservative_every_culled_box_is_hidden(seed):
    rng = RNG(seed)
    eye = rng.uniform(-1, 1, 3) + [0, 0, 6]
    # a few convex polygon occluders (rotated rectangles) and box occluders near z = 0
    occluders = []
    for _ in range(3):
        a, b = rng.uniform(0.8, 2.5, 2)
        rect = np.array([[-a, -b, 0], [a, -b, 0], [a, b, 0], [-a, b, 0]])
        rot = transforms.rotate_axis(rng.normal(size=3), rng.uniform(-0.5, 0.5))[:3, :3]
        occluders.append(rect @ rot.T + rng.uniform(-1.5, 1.5, 3) * [1, 1, 0.3])
    lo = rng.uniform(-2, 1, 3) * [1, 1, 0.3] - [0, 0, 1]
    occluders.append(np.array([lo, lo + rng.uniform(0.8, 2, 3)]))
    centres_ = rng.uniform([-4, -4, -8], [4, 4, 4], (600, 3))     # behind and in front
    half = rng.uniform(0.05, 0.6, (600, 3))
    boxes = np.stack([centres_ - half, centres_ + half], axis=1)
    culled, by = vis.occlusion_cull(eye, occluders, boxes, return_index=True)
    assert culled.sum() >= 5, "the test scene should hide something"
    bits = (np.arange(8)[:, None] >> np.arange(3)) & 1
    for k in range(len(boxes)):
        lo_k, hi_k = boxes[k]
        corners = np.where(bits.astype(bool), hi_k, lo_k)
        if culled[k]:
            # every corner and some inner points are hidden behind the occluder named
            points = np.vstack([corners, lo_k + rng.random((12, 3)) * (hi_k - lo_k)])
            occ = occluders[by[k]]
            if len(occ) == 2:
                assert all(segment_hits_box(eye, x, occ[0], occ[1]) for x in points)
            else:
                assert segment_hits_polygon(eye, points, occ).all()
        else:
            # the shadow of a convex polygon is convex: a box with all corners hidden by one
            # polygon must have been culled (the test is conservative, but not blind)
            for occ in occluders[:3]:
                assert not segment_hits_polygon(eye, corners, occ).all()


def test_solid_angle_closed_forms_and_monte_carlo():
    # a cube face seen from the cube's centre: 4 pi / 6; a whole box from inside: 4 pi
    face = [[-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]]
    box = [[-1, -1, -1], [1, 1, 1]]
    omega = vis.occluder_solid_angle([0, 0, 0], [face, box])
    np.testing.assert_allclose(omega, [4 * np.pi / 6, 4 * np.pi], rtol=1e-12)
    # a square of side 2a at distance h on the axis: 4 arcsin(a^2 / (a^2 + h^2))
    a, h = 0.7, 2.3
    sq = [[-a, -a, 0], [a, -a, 0], [a, a, 0], [-a, a, 0]]
    assert vis.occluder_solid_angle([0, 0, h], [sq])[0] == pytest.approx(
        4 * np.arcsin(a * a / (a * a + h * h)), rel=1e-12)
    # Monte Carlo: fraction of random directions from the eye that hit the occluder
    rng = RNG(9)
    eye = np.array([0.3, -0.2, 1.5])
    dirs = rng.normal(size=(200_000, 3))
    dirs /= np.linalg.norm(dirs, axis=1, keepdims=True)
    tri_a = np.array(sq[:3], float); tri_b = np.array([sq[0], sq[2], sq[3]], float)
    hits = np.zeros(len(dirs), bool)
    for tri in (tri_a, tri_b):
        t, bmin = ray_hits_triangle(eye, dirs, tri)
        hits |= (t > 0) & (bmin >= 0)
    box2 = np.array([[-0.5, -0.5, -1.0], [0.5, 0.4, -0.3]])
    t1 = (box2[0] - eye) / dirs
    t2 = (box2[1] - eye) / dirs
    box_hits = (np.minimum(t1, t2).max(1) <= np.maximum(t1, t2).min(1)) & \
        (np.maximum(t1, t2).min(1) > 0)
    got = vis.occluder_solid_angle(eye, [sq, box2])
    for value, frac in zip(got, (hits.mean(), box_hits.mean())):
        sigma = 4 * np.pi * np.sqrt(frac * (1 - frac) / len(dirs))
        assert abs(value - 4 * np.pi * frac) < 4 * sigma


def test_rank_occluders_prefers_near_and_large():
    eye = [0, 0, 3]
    small_near = [[-0.5, -0.5, 2], [0.5, -0.5, 2], [0.5, 0.5, 2], [-0.5, 0.5, 2]]   # 4 sr-ish
    big_far = [[-4, -4, -20], [4, -4, -20], [4, 4, -20], [-4, 4, -20]]
    medium = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    # closed forms 4 arcsin(a^2 / (a^2 + h^2)): 0.5/1 -> 0.80, 4/23 -> 0.12, 1/3 -> 0.38
    assert vis.rank_occluders(eye, [big_far, small_near, medium]).tolist() == [1, 2, 0]
    assert vis.rank_occluders(eye, [big_far, small_near, medium], k=1).tolist() == [1]


# ---------------------------------------------------------------------------------------------
# from-region: cells, portals and the PVS
# ---------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def plan():
    return vis.example_floor_plan()


@pytest.fixture(scope="module")
def wall_geometry(plan):
    """Walls built independently with shapely: cell boundaries minus the doors."""
    bounds = unary_union([shapely.box(*c).boundary for c in plan.cells])
    doors = unary_union([shapely.LineString(p) for p in plan.portals])
    walls = bounds.difference(doors)
    shapely.prepare(walls)
    return walls


def test_pvs_is_reflexive_symmetric_and_contains_the_neighbours(plan):
    V = vis.pvs(plan)
    n = len(plan.cells)
    assert V.shape == (n, n) and V.dtype == bool
    assert V.diagonal().all()
    np.testing.assert_array_equal(V, V.T)
    for a, b in plan.links:
        assert V[a, b] and V[b, a]


def test_pvs_of_the_u_shaped_plan_checked_by_hand(plan):
    V = vis.pvs(plan)
    # the bottom corridor 0-1-2-3 has its doors in line: all see each other
    assert V[0, 1:4].all()
    # around one corner: 1 sees 4 (slope 1/3 .. 1/2 through the doors fits), 0 does not
    # (it would need slope <= 1/4 to pass the door of 0|1 .. 2|3 and >= 1/3 for 3|4)
    assert V[1, 4] and not V[0, 4]
    # around two corners (through 3 and 5) nothing is visible
    for a, b in [(0, 8), (2, 6), (1, 7), (0, 5), (2, 7)]:
        assert not V[a, b], (a, b)
    # up the right column and into the corner room: 3 sees 6 (line (7.5, 2) -> (6.5, 4))
    assert V[3, 6] and V[3, 5]


def test_pvs_agrees_with_sampled_sight_lines(plan, wall_geometry):
    V = vis.pvs(plan)
    rng = RNG(1)
    n = len(plan.cells)
    samples = 8_000
    for a in range(n):
        for b in range(a + 1, n):
            ca, cb = plan.cells[a], plan.cells[b]
            pa = rng.uniform(ca[:2], ca[2:], (samples, 2))
            pb = rng.uniform(cb[:2], cb[2:], (samples, 2))
            free = ~shapely.intersects(shapely.linestrings(np.stack([pa, pb], 1)), wall_geometry)
            if V[a, b]:
                assert free.any(), f"cells {a} and {b} are marked visible but no sight line found"
            else:
                assert not free.any(), f"cells {a} and {b} are marked hidden but see each other"


def test_witness_lines_pass_through_their_portals(plan):
    V, witnesses = vis.pvs(plan, return_witnesses=True)
    assert set(witnesses) == {(a, b) for a in range(len(V)) for b in range(len(V))
                              if V[a, b] and a != b}
    for (a, b), (cells, portals, (point, direction)) in witnesses.items():
        assert cells[0] == a and cells[-1] == b and len(portals) == len(cells) - 1
        line = shapely.LineString([point - 100 * direction, point + 100 * direction])
        for m in portals:
            assert line.distance(shapely.LineString(plan.portals[m])) < 1e-9


def test_stabbing_line_hand_checked_cases():
    # doors one above the other on the same wall line x = 0: only the wall line itself touches
    # both, and it does not cross them
    assert vis.stabbing_line([[0, 1], [0, 3]], [[0, 0], [0, 2]]) is None
    # doors at x = 0, 1, 2 of width 1 whose bottoms rise by 0.4 and 0.8: slope 0.4 passes
    assert vis.stabbing_line([[0, 1], [1, 1.4], [2, 1.8]], [[0, 0], [1, 0.4], [2, 0.8]])
    # rising by 1.2 then 2.4: the first pair needs slope in [0.2, 2.2], the second pair and
    # the whole run need (2.4 - 1) / 2 = 0.7 .. (3.4 - 0) / 2 = 1.7: still fine
    assert vis.stabbing_line([[0, 1], [1, 2.2], [2, 3.4]], [[0, 0], [1, 1.2], [2, 2.4]])
    # a zig-zag: up by 1.5 then down by 1.5 with unit doors cannot be seen through
    assert vis.stabbing_line([[0, 1], [1, 2.5], [2, 1]], [[0, 0], [1, 1.5], [2, 0]]) is None
    # the direction of travel matters: the same doors crossed backwards are fine, crossing
    # one of them the wrong way round is not
    assert vis.stabbing_line([[2, 0], [1, 0]], [[2, 1], [1, 1]]) is not None
    assert vis.stabbing_line([[0, 1], [1, 0]], [[0, 0], [1, 1]]) is None


def test_stabbing_line_against_a_brute_force_search():
    rng = RNG(3)
    found = missed = 0
    for trial in range(150):
        k = int(rng.integers(2, 5))
        xs = np.cumsum(rng.uniform(0.5, 1.5, k))          # vertical doors left to right
        lows = rng.uniform(-1, 1, k)
        widths = rng.uniform(0.2, 1.0, k)
        left = np.column_stack([xs, lows + widths])        # travelling +x, up is left
        right = np.column_stack([xs, lows])
        line = vis.stabbing_line(left, right)
        # brute force: lines through random points of the first and the last door
        ya = rng.uniform(lows[0], lows[0] + widths[0], 3000)
        yb = rng.uniform(lows[-1], lows[-1] + widths[-1], 3000)
        slope = (yb - ya) / (xs[-1] - xs[0])
        y_at = ya[:, None] + slope[:, None] * (xs[None, :] - xs[0])
        passes = np.all((y_at >= lows) & (y_at <= lows + widths), axis=1).any()
        if passes:
            assert line is not None, f"trial {trial}: a stabbing line exists but none was found"
        if line is not None:
            point, direction = line
            assert direction[0] > 0                        # crosses the doors forwards
            y_line = point[1] + (xs - point[0]) * direction[1] / direction[0]
            assert np.all(y_line >= lows - 1e-7) and np.all(y_line <= lows + widths + 1e-7)
            found += 1
        else:
            missed += 1
    assert found > 20 and missed > 20


def test_visible_from_point_is_within_the_pvs_and_agrees_with_sampled_rays(plan, wall_geometry):
    V = vis.pvs(plan)
    rng = RNG(8)
    for k in range(len(plan.cells)):
        c = plan.cells[k]
        p = rng.uniform(c[:2] + 0.05, c[2:] - 0.05)
        seen = vis.visible_from_point(plan, p).visible
        assert seen[k]
        assert not (seen & ~V[k]).any()
        for b in range(len(plan.cells)):
            if b == k:
                continue
            cb = plan.cells[b]
            q = rng.uniform(cb[:2], cb[2:], (4000, 2))
            free = ~shapely.intersects(
                shapely.linestrings(np.stack([np.broadcast_to(p, q.shape), q], 1)),
                wall_geometry)
            if seen[b]:
                assert free.any(), (p, b)
            else:
                assert not free.any(), (p, b)


def test_field_of_view_restricts_the_visible_cells(plan):
    p = [7.0, 1.0]
    everything = vis.visible_from_point(plan, p).visible
    up = vis.visible_from_point(plan, p, [0, 1], np.radians(40)).visible
    left = vis.visible_from_point(plan, p, [-1, 0], np.radians(40)).visible
    assert not (up & ~everything).any() and not (left & ~everything).any()
    assert up[[3, 4, 5]].all() and not up[[0, 1, 2]].any()     # looking up the right column
    assert left[[0, 1, 2, 3]].all() and not left[[4, 5]].any()


def test_walls_have_the_length_of_the_boundaries_minus_the_doors(plan, wall_geometry):
    segments = vis.walls(plan)
    total = unary_union([shapely.LineString(s) for s in segments]).length
    assert total == pytest.approx(wall_geometry.length, rel=1e-12)
    # 9 rooms of perimeter 8, 8 shared walls of length 2 counted once, 8 doors of width 1
    assert wall_geometry.length == pytest.approx(9 * 8 - 8 * 2 - 8 * 1)
    assert vis.cell_of(plan, [[1, 1], [7, 3], [3, 3]]).tolist() == [0, 4, -1]


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

GOOD_TRI = [[[0, 0, 0.5], [4, 0, 0.5], [0, 4, 0.5]]]


@pytest.mark.parametrize("triangles, match", [
    ([[0, 0, 0.5], [4, 0, 0.5]], r"triangles must be an array of triangles of shape \(m, 3, 3\)"),
    (np.zeros((2, 4, 3)), r"shape \(m, 3, 3\)"),
    (np.zeros((2, 3, 2)), r"shape \(m, 3, 3\)"),
    (np.zeros((0, 3, 3)), "at least one triangle"),
    ([[[0, 0, np.nan], [4, 0, 0.5], [0, 4, 0.5]]], "finite"),
    ([[[0, 0, np.inf], [4, 0, 0.5], [0, 4, 0.5]]], "finite"),
])
def test_zbuffer_rejects_malformed_triangles(triangles, match):
    with pytest.raises(ValueError, match=match):
        vis.zbuffer(triangles, 4, 4)


@pytest.mark.parametrize("width, height", [(0, 4), (4, -1), (2.5, 4), (4, np.nan)])
def test_zbuffer_rejects_bad_sizes(width, height):
    with pytest.raises(ValueError, match="width|height"):
        vis.zbuffer(GOOD_TRI, width, height)


def test_other_bad_input_is_rejected_with_clear_messages():
    view, proj = camera()
    with pytest.raises(ValueError, match="values"):
        vis.zbuffer(GOOD_TRI, 4, 4, values=[[1, 2]])
    with pytest.raises(ValueError, match="faces refers to vertex 5"):
        vis.render_depth(np.zeros((3, 3)), [[0, 1, 5]], view, proj, 4, 4)
    with pytest.raises(ValueError, match="faces must contain at least one triangle"):
        vis.render_depth(np.zeros((3, 3)), np.zeros((0, 3), int), view, proj, 4, 4)
    with pytest.raises(ValueError, match="projection must be a 4x4"):
        vis.render_depth(np.zeros((3, 3)), [[0, 1, 2]], view, np.eye(3), 4, 4)
    with pytest.raises(ValueError, match="zero vector"):
        vis.ray_cast([0, 0, 0], [[0, 0, 0], [0, 0, 1]], GOOD_TRI)
    with pytest.raises(ValueError, match="at least one ray"):
        vis.ray_cast(np.zeros((0, 3)), np.zeros((0, 3)), GOOD_TRI)
    with pytest.raises(ValueError, match="finite"):
        vis.ray_cast([0, 0, np.nan], [0, 0, 1], GOOD_TRI)
    with pytest.raises(ValueError, match="t_max"):
        vis.ray_cast([0, 0, 0], [0, 0, 1], GOOD_TRI, t_min=2, t_max=1)
    with pytest.raises(ValueError, match="choose"):
        vis.build_bsp(GOOD_TRI, choose="random")
    with pytest.raises(ValueError, match="degenerate"):
        vis.build_bsp([[[0, 0, 0], [1, 1, 1], [2, 2, 2]]])
    with pytest.raises(ValueError, match="not convex"):
        vis.occlusion_cull([0, 0, 5], [[[0, 0, 0], [2, 0, 0], [1, 0.2, 0], [2, 2, 0], [0, 2, 0]]],
                           [[[0, 0, -1], [1, 1, 0]]])
    with pytest.raises(ValueError, match="not planar"):
        vis.shadow_frustum([0, 0, 5], [[0, 0, 0], [1, 0, 0], [1, 1, 0.5], [0, 1, 0]])
    with pytest.raises(ValueError, match="objects must be boxes"):
        vis.occlusion_cull([0, 0, 5], [WALL], [[0, 0, 0]])
    with pytest.raises(ValueError, match="overlap"):
        vis.floor_plan([[0, 0, 2, 2], [1, 0, 3, 2]], np.zeros((0, 2, 2)), np.zeros((0, 2), int))
    with pytest.raises(ValueError, match="does not lie on the wall"):
        vis.floor_plan([[0, 0, 2, 2], [2, 0, 4, 2]], [[[1, 0.5], [1, 1.5]]], [[0, 1]])
    with pytest.raises(ValueError, match="not inside any cell"):
        vis.visible_from_point(vis.example_floor_plan(), [3, 3])
    with pytest.raises(ValueError, match="fov"):
        vis.visible_from_point(vis.example_floor_plan(), [1, 1], [1, 0], np.pi)
    with pytest.raises(TypeError, match="FloorPlan"):
        vis.pvs([[0, 0, 1, 1]])


def test_scene_is_triangle_scene_under_its_old_name():
    # the hidden-surface test scene (triangles + camera), not the ray tracer's Scene
    from course_lib import raytracing
    assert vis.Scene is vis.TriangleScene is type(vis.random_scene(3, seed=0))
    assert vis.TriangleScene is not raytracing.Scene and "Scene" not in vis.__all__
