"""Screen-space ambient occlusion (course_lib/shading/ssao.py), checked against the ray-traced
AO of the same view, against the camera's own geometry, and for its known artefacts."""

import numpy as np
import pytest

from course_lib import shading, viewing, visibility


def _quad(x0, x1, y0, y1, z0, z1, axis):
    """Two triangles of an axis-aligned rectangle (axis: the constant coordinate)."""
    if axis == "y":
        v = [[x0, y0, z0], [x1, y0, z0], [x1, y0, z1], [x0, y0, z1]]
    elif axis == "z":
        v = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0]]
    else:
        v = [[x0, y0, z0], [x0, y1, z0], [x0, y1, z1], [x0, y0, z1]]
    return np.array(v, float), np.array([[0, 1, 2], [0, 2, 3]])


def _mesh(*parts):
    verts, faces, base = [], [], 0
    for v, f in parts:
        verts.append(v)
        faces.append(f + base)
        base += len(v)
    return np.concatenate(verts), np.concatenate(faces)


def _camera(eye, target, fov=50.0, near=0.5, far=30.0):
    eye = np.asarray(eye, float)
    view = viewing.look_at(eye, np.asarray(target, float) - eye, [0, 1, 0])
    return view, viewing.perspective(np.radians(fov), 1.0, near, far)


FLOOR = _quad(-20, 20, 0, 0, -20, 20, "y")


def _both(v, f, view, proj, n=64, radius=0.5, samples=64, seed=0, **kw):
    gb = shading.g_buffer(v, f, view, proj, n, n)
    s = shading.ssao(gb.positions, gb.normals, proj, gb.mask, radius=radius, samples=samples,
                     seed=seed, **kw)
    rt = shading.ray_traced_occlusion(gb, v[f], samples=samples, seed=seed + 1)
    return gb, s, rt


# --- the G-buffer against the camera -----------------------------------------------------------

def test_g_buffer_positions_are_the_unprojected_pixel_centres():
    scene = shading.ssao_test_scene()
    n = 40
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, n, n)
    # the ray through pixel (i, j) in eye space: (x_ndc tan(fov/2) aspect, y_ndc tan(fov/2), -1)
    t = np.tan(np.radians(55) / 2)
    x = ((np.arange(n) + 0.5) * 2 / n - 1) * t
    y = ((np.arange(n) + 0.5) * 2 / n - 1) * t
    X, Y = np.meshgrid(x, y)
    depth = -gb.positions[..., 2]
    m = gb.mask
    assert m.all()
    assert np.allclose(gb.positions[..., 0][m], (X * depth)[m], atol=1e-9)
    assert np.allclose(gb.positions[..., 1][m], (Y * depth)[m], atol=1e-9)
    # the world point lies on the plane of its face, and view maps it to the eye-space point
    tri = scene.vertices[scene.faces[gb.ids[m]]]
    nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    assert np.allclose(np.einsum("pc,pc->p", gb.world_positions[m] - tri[:, 0], nrm), 0,
                       atol=1e-9)
    hom = np.c_[gb.world_positions[m], np.ones(m.sum())] @ scene.view.T
    assert np.allclose(hom[:, :3], gb.positions[m])
    # normals: unit, towards the eye (the eye is the origin of eye space)
    assert np.allclose(np.linalg.norm(gb.normals[m], axis=1), 1)
    assert (np.einsum("pc,pc->p", gb.normals[m], -gb.positions[m]) > 0).all()


def test_z_buffer_depth_matches_the_ray_cast_of_the_pixel_centres():
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 32, 32)
    rc = visibility.ray_cast_image(scene.vertices, scene.faces, scene.view, scene.projection,
                                   32, 32)
    assert np.allclose(gb.depth, rc.depth, atol=1e-9)
    # and the eye-space depth maps to that viewport depth: z_ndc = (f + n)/(f - n) + 2 f n/((f - n) z)
    n_, f_ = 0.5, 20.0
    z = gb.positions[..., 2]
    z_ndc = (f_ + n_) / (f_ - n_) + 2 * f_ * n_ / ((f_ - n_) * z)
    assert np.allclose((z_ndc + 1) / 2, rc.depth, atol=1e-9)


# --- open floor, bias ---------------------------------------------------------------------------

def test_open_floor_is_unoccluded_for_both():
    view, proj = _camera([0, 3, 2], [0, 0, -1])
    gb, s, rt = _both(*FLOOR, view, proj, n=48, samples=32, bias=0.05)
    assert gb.mask.all()
    assert s.min() == 1.0
    assert rt.visibility(0.5).min() == 1.0 and rt.visibility(5.0, "none").min() == 1.0


def test_without_bias_the_floor_and_a_sphere_occlude_themselves():
    # the depth is looked up at pixel centres: a sample just above a surface that is tilted
    # to the view lands on a pixel whose stored point can be nearer than the sample
    view, proj = _camera([0, 3, 2], [0, 0, -1])
    gb = shading.g_buffer(*FLOOR, view, proj, 48, 48)
    no_bias = shading.ssao(gb.positions, gb.normals, proj, gb.mask, radius=0.5, samples=32,
                           bias=0.0, blur=1, seed=0)
    assert (no_bias < 1).mean() > 0.1
    v, f = shading.uv_sphere(1.0, 48, 24)
    view, proj = _camera([0, 0, 4], [0, 0, 0], fov=40)
    gb = shading.g_buffer(v, f, view, proj, 64, 64)
    args = (gb.positions, gb.normals, proj, gb.mask)
    no_bias = shading.ssao(*args, radius=0.1, samples=32, bias=0.0, blur=1, seed=2)
    biased = shading.ssao(*args, radius=0.1, samples=32, bias=0.05, blur=1, seed=2)
    # a convex sphere occludes nothing: ray-traced AO is 1 everywhere
    rt = shading.ray_traced_occlusion(gb, v[f], samples=16, seed=0)
    assert rt.visibility(0.1).min() == 1.0
    assert (no_bias[gb.mask] < 1).mean() > 0.5
    assert (biased[gb.mask] < 1).mean() < 0.01


# --- corner and overhang: agreement --------------------------------------------------------------

def test_corner_agrees_with_ray_traced_ao():
    walls = _mesh(FLOOR, _quad(-20, 20, 0, 10, -1, -1, "z"), _quad(-1, -1, 0, 10, -20, 20, "x"))
    view, proj = _camera([1.5, 1.5, 1.5], [-1, 0, -1], fov=60)
    gb, s, rt = _both(*walls, view, proj, n=64, radius=0.6, samples=64, bias=0.01)
    ray = shading.box_blur(rt.visibility(0.6), gb.mask, 4)
    inner = np.zeros_like(gb.mask)
    inner[8:-8, 8:-8] = True
    assert ray[inner].min() < 0.7                   # the corner really is dark
    assert np.abs(s - ray)[inner].mean() < 0.04


def test_test_scene_agrees_in_the_interior_also_under_the_shelf():
    scene = shading.ssao_test_scene()
    n = 96
    gb, s, rt = _both(scene.vertices, scene.faces, scene.view, scene.projection, n=n,
                      radius=0.5, samples=32, bias=0.01)
    ray = shading.box_blur(rt.visibility(0.5), gb.mask, 4)
    inner = np.zeros_like(gb.mask)
    inner[10:-10, 10:-10] = True
    assert np.abs(s - ray)[inner].mean() < 0.03
    # floor points under the shelf ([0.2, 2.2] x [-2, -1.1], below y = 0.7), away from its edges
    w = gb.world_positions
    under = gb.mask & (np.abs(w[..., 1]) < 1e-9) & (w[..., 0] > 0.6) & (w[..., 0] < 1.8) \
        & (w[..., 2] > -1.8) & (w[..., 2] < -1.3)
    assert under.sum() >= 20
    assert ray[under].mean() < 0.95                 # darker than the open floor (1)
    assert abs(s[under].mean() - ray[under].mean()) < 0.04


def test_falloff_none_is_the_hard_limited_ambient_occlusion():
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 8, 8)
    rt = shading.ray_traced_occlusion(gb, scene.vertices[scene.faces], samples=4000, seed=5)
    ao = shading.ambient_occlusion(gb.world_positions[gb.mask], gb.world_normals[gb.mask],
                                   scene.vertices[scene.faces], samples=4000, max_distance=0.7,
                                   seed=6)
    diff = rt.visibility(0.7, "none")[gb.mask] - ao.visibility
    assert np.all(np.abs(diff) < 5 * np.hypot(ao.std_error, ao.std_error) + 1e-9)


# --- artefacts -----------------------------------------------------------------------------------

def test_haloing_without_range_check():
    # a small square floating 1.5 above the floor, seen from above: the floor pixels around its
    # silhouette get samples that land on it, far in front of them
    square = _quad(-0.5, 0.5, 1.5, 1.5, -0.5, 0.5, "y")
    v, f = _mesh(FLOOR, square)
    view, proj = _camera([0, 4, 0.01], [0, 0, 0], fov=50)
    gb = shading.g_buffer(v, f, view, proj, 64, 64)
    args = (gb.positions, gb.normals, proj, gb.mask)
    kw = dict(radius=0.5, samples=32, bias=0.01, blur=1, seed=0)
    halo = shading.ssao(*args, range_check=False, **kw)
    fixed = shading.ssao(*args, range_check=True, **kw)
    floor = gb.mask & (np.abs(gb.world_positions[..., 1]) < 1e-9)
    w = gb.world_positions
    # the square hides the floor out to 0.5 * 4 / 2.5 = 0.8: the floor just outside that
    ring = np.max(np.abs(w[..., [0, 2]]), axis=-1)
    near = floor & (ring > 0.8) & (ring < 0.95)
    assert near.sum() > 10
    rt = shading.ray_traced_occlusion(gb, v[f], samples=32, seed=1)
    assert rt.visibility(0.5)[near].min() == 1.0    # the square is 1.5 away: out of range
    assert halo[near].mean() < 0.85
    assert fixed[near].mean() > 0.99


def test_occluder_beyond_the_radius_does_not_darken():
    wall = _quad(-20, 20, 0, 5, -1, -1, "z")
    v, f = _mesh(FLOOR, wall)
    view, proj = _camera([0, 2, 3], [0, 0, -1])
    gb = shading.g_buffer(v, f, view, proj, 96, 96)
    w = gb.world_positions
    strip = gb.mask & (np.abs(w[..., 1]) < 1e-9) & (w[..., 2] > -0.6) & (w[..., 2] < -0.5)
    assert strip.sum() > 5                          # floor 0.4 to 0.5 from the wall
    args = (gb.positions, gb.normals, proj, gb.mask)
    small = shading.ssao(*args, radius=0.3, samples=32, bias=0.03, seed=0, blur=1)
    large = shading.ssao(*args, radius=1.0, samples=32, bias=0.03, seed=0, blur=1)
    rt = shading.ray_traced_occlusion(gb, v[f], samples=32, seed=1)
    assert small[strip].min() == 1.0 and rt.visibility(0.3)[strip].min() == 1.0
    assert large[strip].mean() < 0.95 and rt.visibility(1.0)[strip].mean() < 0.95


def _hidden_case(with_occluder, off_screen):
    if off_screen:       # looking straight down: the floor is seen for |x| < 3 tan 20 = 1.09
        view, proj = _camera([0, 3, 0.001], [0, 0, 0], fov=40)
        front = []
        occluder = [_quad(-1.3, -1.3, 0, 0.3, -20, 20, "x")]      # its top projects to -1.44
    else:
        view, proj = _camera([0, 1, 5], [0, 0, 0], fov=40)
        front = [_quad(-1, 0, 0, 2, 1, 1, "z")]        # a tall board near the camera
        occluder = [_quad(-0.9, -0.1, 0, 0.5, 0, 0, "z"), _quad(-0.1, -0.1, 0, 0.5, -0.5, 0, "x"),
                    _quad(-0.9, -0.1, 0.5, 0.5, -0.5, 0, "y")]   # a box behind the board
    v, f = _mesh(FLOOR, *front, *(occluder if with_occluder else []))
    gb = shading.g_buffer(v, f, view, proj, 64, 64)
    s = shading.ssao(gb.positions, gb.normals, proj, gb.mask, radius=0.5, samples=32,
                     bias=0.03, seed=0)
    rt = shading.ray_traced_occlusion(gb, v[f], samples=64, seed=1).visibility(0.5)
    return gb, s, rt, 2 + 2 * len(front)


@pytest.mark.parametrize("off_screen", [False, True])
def test_off_screen_and_hidden_geometry_is_not_counted(off_screen):
    gb1, s1, rt1, shown = _hidden_case(True, off_screen)
    gb0, s0, rt0, _ = _hidden_case(False, off_screen)
    assert not (gb1.ids >= shown).any()             # the occluder is nowhere in the image
    assert np.array_equal(s1, s0)                   # so SSAO cannot know about it
    w = gb1.world_positions
    if off_screen:
        near = gb1.mask & (w[..., 0] < -0.9)
    else:
        near = gb1.mask & (np.abs(w[..., 1]) < 1e-9) & (w[..., 0] > 0) & (w[..., 0] < 0.3) \
            & (w[..., 2] > -0.5) & (w[..., 2] < 0)
    assert near.sum() >= 5
    assert rt0[near].min() == 1.0 and rt1[near].mean() < 0.98   # the rays do see it


# --- blur, determinism, kernel -------------------------------------------------------------------

def test_blur_preserves_a_constant_and_ignores_uncovered_pixels():
    rng = np.random.default_rng(0)
    mask = rng.random((20, 30)) < 0.7
    img = np.where(mask, 0.37, rng.random((20, 30)))
    out = shading.box_blur(img, mask, 4)
    assert np.allclose(out[mask], 0.37)
    assert np.array_equal(out[~mask], img[~mask])
    # one pixel by hand: the mean over the covered pixels of rows/cols i-2..i+1
    img2 = rng.random((20, 30))
    out2 = shading.box_blur(img2, mask, 4)
    i, j = np.argwhere(mask[2:-2, 2:-2])[0] + 2
    win = (slice(i - 2, i + 2), slice(j - 2, j + 2))
    assert np.isclose(out2[i, j], img2[win][mask[win]].mean())


def test_kernel_is_cosine_weighted_with_uniform_lengths():
    k = shading.ssao_kernel(20000, seed=1)
    length = np.linalg.norm(k, axis=1)
    cos = k[:, 2] / length
    assert abs(cos.mean() - 2 / 3) < 0.01           # E[cos] under cos/pi is 2/3
    assert abs(length.mean() - 0.5) < 0.005 and length.max() <= 1
    assert np.allclose(np.linalg.norm(shading.ssao_kernel(10, "none", seed=0), axis=1), 1)


def test_deterministic_under_a_seed():
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 32, 32)
    args = (gb.positions, gb.normals, scene.projection, gb.mask)
    a = shading.ssao(*args, seed=4)
    assert np.array_equal(a, shading.ssao(*args, seed=4))
    assert not np.array_equal(a, shading.ssao(*args, seed=5))


def test_hand_kernel_counts_occluded_samples():
    # a floor seen straight from above; a kernel of 2 samples straight up: unoccluded
    view, proj = _camera([0, 3, 0.001], [0, 0, 0], fov=40)
    wall = _quad(0.2, 0.2, 0, 3, -20, 20, "x")
    v, f = _mesh(FLOOR, wall)
    gb = shading.g_buffer(v, f, view, proj, 32, 32)
    kernel = [[0, 0, 0.5], [0, 0, 1.0]]
    s = shading.ssao(gb.positions, gb.normals, proj, gb.mask, kernel=kernel, radius=0.5,
                     noise_size=1, blur=1)
    floor = gb.mask & (np.abs(gb.world_positions[..., 1]) < 1e-9)
    assert np.all(s[floor] == 1.0)


# --- errors --------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def small():
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 8, 8)
    return gb, scene.projection


def test_errors(small):
    gb, proj = small
    pos, nrm, m = gb.positions, gb.normals, gb.mask
    bad = pos.copy()
    bad[3, 3, 2] = np.nan
    with pytest.raises(ValueError, match="positions"):
        shading.ssao(bad, nrm, proj, m)
    zero = nrm.copy()
    zero[2, 5] = 0
    with pytest.raises(ValueError, match="normals.*zero"):
        shading.ssao(pos, zero, proj, m)
    # a zero normal outside the mask is fine
    m2 = m.copy()
    m2[2, 5] = False
    assert shading.ssao(pos, zero, proj, m2)[2, 5] == 1.0
    with pytest.raises(ValueError, match="radius"):
        shading.ssao(pos, nrm, proj, m, radius=0)
    with pytest.raises(ValueError, match="samples"):
        shading.ssao(pos, nrm, proj, m, samples=0)
    with pytest.raises(ValueError, match="bias"):
        shading.ssao(pos, nrm, proj, m, bias=-0.1)
    with pytest.raises(ValueError, match="normals"):
        shading.ssao(pos, nrm[:4], proj, m)
    with pytest.raises(ValueError, match="mask"):
        shading.ssao(pos, nrm, proj, m[:4])
    with pytest.raises(ValueError, match="positions"):
        shading.ssao(pos[..., :2], nrm[..., :2], proj, m)
    with pytest.raises(ValueError, match="projection"):
        shading.ssao(pos, nrm, np.eye(3), m)
    with pytest.raises(ValueError, match="falloff"):
        shading.ssao(pos, nrm, proj, m, falloff="cubic")
    with pytest.raises(TypeError, match="gbuffer"):
        shading.ray_traced_occlusion(pos, np.zeros((1, 3, 3)))
    rt = shading.ray_traced_occlusion(gb, np.zeros((1, 3, 3)) + np.eye(3), samples=2, seed=0)
    with pytest.raises(ValueError, match="radius"):
        rt.visibility(-1)


def test_positions_from_the_depth_buffer_alone_are_the_g_buffers_points():
    """What a GPU keeps is the z-buffer's depth: unprojecting it gives back the points that
    the G-buffer interpolated from the triangles' corners (two independent routes), and SSAO
    from those points is SSAO from the G-buffer."""
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 48, 48)
    pos, mask = shading.positions_from_depth(gb.depth, scene.projection)
    assert np.array_equal(mask, gb.mask) and mask.any()
    # and where nothing is drawn (inf in the z-buffer) nothing comes back
    P = viewing.perspective(np.radians(60), 1.0, 1.0, 10.0)
    square = [[-1, -1, -3], [1, -1, -3], [1, 1, -3], [-1, 1, -3]]
    small = shading.g_buffer(square, [[0, 1, 2], [0, 2, 3]], np.eye(4), P, 12, 12)
    small_pos, small_mask = shading.positions_from_depth(small.depth, P)
    assert np.array_equal(small_mask, small.mask) and not small_mask.all()
    assert np.all(small_pos[~small_mask] == 0) and np.allclose(small_pos[small_mask, 2], -3)
    assert np.allclose(pos[mask], gb.positions[mask], atol=1e-9)
    # the unprojection typed out for one pixel: NDC from the pixel centre and the depth
    i, j = np.argwhere(mask)[len(np.argwhere(mask)) // 2]
    ndc = np.array([2 * (j + 0.5) / 48 - 1, 2 * (i + 0.5) / 48 - 1, 2 * gb.depth[i, j] - 1, 1])
    eye = np.linalg.solve(np.asarray(scene.projection, float), ndc)
    assert np.allclose(eye[:3] / eye[3], pos[i, j])
    a = shading.ssao(gb.positions, gb.normals, scene.projection, gb.mask, seed=2)
    b = shading.ssao(pos, gb.normals, scene.projection, mask, seed=2)
    assert np.allclose(a, b, atol=1e-12)


@pytest.mark.parametrize("bad, message", [
    (lambda d: np.where(d == d.max(), np.nan, d), "depth must not contain NaN"),
    (lambda d: d * 2, "depth must lie in \\[0, 1\\]"),
    (lambda d: d[0], "depth must be a 2D buffer"),
])
def test_a_bad_depth_buffer_is_named(bad, message):
    scene = shading.ssao_test_scene()
    gb = shading.g_buffer(scene.vertices, scene.faces, scene.view, scene.projection, 16, 16)
    depth = np.where(gb.mask, gb.depth, 0.3)
    with pytest.raises(ValueError, match=message):
        shading.positions_from_depth(bad(depth), scene.projection)
