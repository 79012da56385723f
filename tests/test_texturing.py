"""Tests of course_lib.texturing (chapter 14).

References: scipy.ndimage.map_coordinates for bilinear filtering, trimesh for barycentric
coordinates (when installed) and a 2x2 linear solve written here, scipy's Rotation for mapping
frames, and closed forms typed out below. Nothing is copied from the output of the code under
test.

The texel-centre convention under test: texel (i, j) (row i, column j) covers
u in [j/W, (j+1)/W], v in [i/H, (i+1)/H]; row 0 is v = 0. So the continuous array coordinates
(row, column) of (u, v) are (v H - 1/2, u W - 1/2), texel centres at integers. That is what we
pass to map_coordinates; its modes "grid-wrap", "nearest" and "reflect" are our "repeat",
"clamp" and "mirror".
"""
import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from scipy import ndimage
from scipy.spatial.transform import Rotation

from course_lib import texturing as T

FAST = settings(max_examples=120, deadline=None, database=None)
SCIPY_MODE = {"repeat": "grid-wrap", "clamp": "nearest", "mirror": "reflect"}


def rng(seed):
    return np.random.default_rng(seed)


def scipy_bilinear(texture, u, v, wrap):
    """Bilinear sampling by scipy, channel by channel, with our texel-centre convention."""
    h, w = texture.shape[:2]
    coords = np.stack([np.ravel(v) * h - 0.5, np.ravel(u) * w - 0.5])
    tex = np.asarray(texture, dtype=float)
    if tex.ndim == 2:
        out = ndimage.map_coordinates(tex, coords, order=1, mode=SCIPY_MODE[wrap])
        return out.reshape(np.shape(u))
    chans = [ndimage.map_coordinates(tex[..., c], coords, order=1, mode=SCIPY_MODE[wrap])
             for c in range(tex.shape[2])]
    return np.stack(chans, axis=-1).reshape(np.shape(u) + (tex.shape[2],))


# ---------------------------------------------------------------------------------------------
# bilinear and nearest sampling
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("wrap", ["repeat", "clamp", "mirror"])
def test_bilinear_matches_scipy_on_a_million_points(wrap):
    gen = rng(1)
    tex = gen.uniform(0, 1, (64, 48, 3))
    u = gen.uniform(-1.5, 2.5, 1_000_000)       # far outside [0, 1] too: the wrap mode matters
    v = gen.uniform(-1.5, 2.5, 1_000_000)
    got = T.bilinear_sample(tex, u, v, wrap)
    assert got.shape == (1_000_000, 3)
    np.testing.assert_allclose(got, scipy_bilinear(tex, u, v, wrap), atol=1e-12)


@pytest.mark.parametrize("shape", [(1, 1), (1, 5), (5, 1), (2, 2), (3, 7), (16, 16), (9, 4, 2),
                                   (4, 6, 4), (31, 17, 1)])
@pytest.mark.parametrize("dtype", [np.uint8, np.int16, np.float32, np.float64])
@pytest.mark.parametrize("wrap", ["repeat", "clamp", "mirror"])
def test_bilinear_matches_scipy_for_sizes_and_dtypes(shape, dtype, wrap):
    gen = rng(hash((shape, np.dtype(dtype).name, wrap)) % 2**32)
    tex = (gen.uniform(0, 100, shape)).astype(dtype)
    u = gen.uniform(-2, 3, (50, 40))
    v = gen.uniform(-2, 3, (50, 40))
    got = T.bilinear_sample(tex, u, v, wrap)
    assert got.dtype == np.float64 and got.shape == (50, 40) + shape[2:]
    np.testing.assert_allclose(got, scipy_bilinear(tex, u, v, wrap), atol=1e-9)


def test_bilinear_is_exact_at_texel_centres_and_reproduces_affine_textures():
    gen = rng(2)
    h, w = 13, 21
    tex = gen.normal(size=(h, w))
    i, j = np.meshgrid(np.arange(h), np.arange(w), indexing="ij")
    for wrap in ("repeat", "clamp", "mirror"):
        np.testing.assert_allclose(T.bilinear_sample(tex, (j + 0.5) / w, (i + 0.5) / h, wrap),
                                   tex, atol=1e-12)
    # an affine texture t = 2 col - 3 row + 1 is reproduced exactly between the centres
    affine = 2.0 * j - 3.0 * i + 1.0
    x = gen.uniform(0, w - 1, 5000)                 # column coordinate, between first and last
    y = gen.uniform(0, h - 1, 5000)
    got = T.bilinear_sample(affine, (x + 0.5) / w, (y + 0.5) / h, "clamp")
    np.testing.assert_allclose(got, 2 * x - 3 * y + 1, atol=1e-9)


def test_bilinear_clamp_is_constant_beyond_the_edge_and_repeat_tiles():
    tex = np.array([[0.0, 10.0], [20.0, 30.0]])
    # beyond the right edge, clamp gives the edge column's values (interpolated in v only)
    np.testing.assert_allclose(T.bilinear_sample(tex, [1.3, 5.0], [0.25, 0.25], "clamp"), 10.0)
    gen = rng(3)
    u, v = gen.uniform(0, 1, 100), gen.uniform(0, 1, 100)
    k = gen.integers(-5, 5, 100)
    np.testing.assert_allclose(T.bilinear_sample(tex, u + k, v - k, "repeat"),
                               T.bilinear_sample(tex, u, v, "repeat"), atol=1e-9)


@pytest.mark.parametrize("channels", [(), (3,)])
def test_nearest_closed_form_inside_texels_and_wrap_modes(channels):
    gen = rng(4)
    h, w = 7, 11
    tex = gen.normal(size=(h, w) + channels)
    n = 20_000
    i, j = gen.integers(0, h, n), gen.integers(0, w, n)
    fu, fv = gen.uniform(0.01, 0.99, n), gen.uniform(0.01, 0.99, n)   # strictly inside texel
    ku, kv = gen.integers(-3, 4, n), gen.integers(-3, 4, n)           # tile offsets
    u, v = (j + fu) / w + ku, (i + fv) / h + kv
    # repeat: the tile offset does not matter
    np.testing.assert_array_equal(T.nearest_sample(tex, u, v, "repeat"), tex[i, j])
    # mirror: odd tiles are flipped, j -> w - 1 - j
    jm = np.where(ku % 2 == 0, j, w - 1 - j)
    im = np.where(kv % 2 == 0, i, h - 1 - i)
    np.testing.assert_array_equal(T.nearest_sample(tex, u, v, "mirror"), tex[im, jm])
    # clamp: left of the texture -> column 0, right -> column w - 1
    jc = np.where(ku < 0, 0, np.where(ku > 0, w - 1, j))
    ic = np.where(kv < 0, 0, np.where(kv > 0, h - 1, i))
    np.testing.assert_array_equal(T.nearest_sample(tex, u, v, "clamp"), tex[ic, jc])


def test_row_zero_is_v_zero():
    tex = np.zeros((4, 4))
    tex[0] = 1.0                                   # the first row of the array
    assert T.nearest_sample(tex, 0.5, 0.1) == 1.0  # v near 0: the first row
    assert T.nearest_sample(tex, 0.5, 0.9) == 0.0
    np.testing.assert_allclose(T.uv_grid(3, 2)[1, 2], [2.5 / 3, 0.75])


# ---------------------------------------------------------------------------------------------
# barycentric coordinates
# ---------------------------------------------------------------------------------------------

def solve_barycentric(p, a, b, c):
    """Independent reference: p - a = s (b - a) + t (c - a) solved as a (least squares) system;
    in 3D that is the orthogonal projection onto the plane. Returns (1 - s - t, s, t)."""
    p, a, b, c = (np.asarray(x, dtype=float) for x in (p, a, b, c))
    out = np.empty(p.shape[:-1] + (3,))
    for idx in np.ndindex(p.shape[:-1]):
        m = np.stack([b[idx] - a[idx], c[idx] - a[idx]], axis=1)        # d x 2
        st_, *_ = np.linalg.lstsq(m, p[idx] - a[idx], rcond=None)
        out[idx] = [1 - st_.sum(), st_[0], st_[1]]
    return out


def cross2(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def random_triangles(gen, n, dim):
    tris = gen.uniform(-5, 5, (n, 3, dim))
    if dim == 2:
        area = cross2(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
    else:
        area = np.linalg.norm(np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]), axis=1)
    return tris[np.abs(area) > 0.5]


@pytest.mark.parametrize("dim", [2, 3])
def test_barycentric_matches_trimesh_inside_and_outside(dim):
    import trimesh.triangles as trimesh_triangles
    gen = rng(5)
    tris = random_triangles(gen, 4000, dim)
    # inside points from random convex weights, outside ones from weights with a negative entry
    w_in = gen.dirichlet([1, 1, 1], len(tris))
    w_out = gen.uniform(-2, 2, (len(tris), 3))
    w_out[:, 2] = 1 - w_out[:, 0] - w_out[:, 1]
    for w in (w_in, w_out):
        p = np.einsum("nk,nkd->nd", w, tris)
        if dim == 3:
            normal = np.cross(tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0])
            p = p + gen.normal(size=(len(p), 1)) * normal     # lift off the plane
        got = T.barycentric(p, tris[:, 0], tris[:, 1], tris[:, 2])
        ref = trimesh_triangles.points_to_barycentric(tris, p)
        np.testing.assert_allclose(got, ref, atol=1e-9)
        np.testing.assert_allclose(got, w, atol=1e-9)
    assert np.all(T.barycentric(np.einsum("nk,nkd->nd", w_in, tris), tris[:, 0], tris[:, 1],
                                tris[:, 2]) >= -1e-12)


@pytest.mark.parametrize("dim", [2, 3])
def test_barycentric_matches_a_linear_solve_and_broadcasts(dim):
    gen = rng(6)
    a, b, c = random_triangles(gen, 10, dim)[0]
    w = gen.uniform(-0.3, 1.0, (7, 9, 3))                     # many points, one triangle,
    w /= w.sum(axis=-1, keepdims=True)                        # some inside, some outside
    p = w @ np.stack([a, b, c]) + gen.normal(size=(7, 9, dim))
    got = T.barycentric(p, a, b, c)
    assert got.shape == (7, 9, 3)
    A, B, C = (np.broadcast_to(x, p.shape) for x in (a, b, c))
    np.testing.assert_allclose(got, solve_barycentric(p, A, B, C), atol=1e-9)
    np.testing.assert_allclose(got.sum(axis=-1), 1.0, atol=1e-12)
    inside = np.all(got >= 0, axis=-1)
    assert inside.any() and (~inside).any()


coord = st.floats(-100, 100, allow_nan=False, allow_infinity=False)
point2 = st.tuples(coord, coord).map(np.array)


@FAST
@given(point2, point2, point2, point2)
def test_barycentric_property_reconstructs_the_point_2d(p, a, b, c):
    scale = max(np.abs(np.stack([a, b, c])).max(), 1.0)
    area = cross2(b - a, c - a)
    assume(abs(area) > 1e-3 * scale**2)
    w = T.barycentric(p, a, b, c)
    assert abs(w.sum() - 1) < 1e-9
    np.testing.assert_allclose(w @ np.stack([a, b, c]), p, atol=1e-6 * scale)
    # inside iff p is on the inner side of every edge (orientation tests written here)
    sides = np.sign([cross2(c - b, p - b), cross2(a - c, p - c), cross2(b - a, p - a)])
    assume(np.all(np.abs(w) > 1e-9))
    assert bool(np.all(w > 0)) == bool(np.all(sides == np.sign(area)))


def test_interpolate_single_stacked_and_perspective_correct():
    w = np.array([[0.2, 0.3, 0.5], [1.0, 0.0, 0.0]])
    np.testing.assert_allclose(T.interpolate([1.0, 2.0, 4.0], w), [2.8, 1.0])
    rgb = np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1]])
    np.testing.assert_allclose(T.interpolate(rgb, w), w)           # identity colours
    per_point = np.array([[[0.0, 0], [1, 0], [0, 1]], [[5.0, 5], [6, 6], [7, 7]]])
    np.testing.assert_allclose(T.interpolate(per_point, w, stacked=True), [[0.3, 0.5], [5, 5]])
    np.testing.assert_allclose(T.interpolate([[1.0, 2, 3], [4, 5, 6]], w, stacked=True),
                               [0.2 + 0.6 + 1.5, 4.0])


def test_perspective_correct_weights_recover_the_3d_barycentric_coordinates():
    from course_lib import transforms, viewing

    gen = rng(7)
    proj = viewing.perspective(np.radians(60), 1.0, 0.5, 50.0)
    for _ in range(50):
        tri = gen.uniform(-2, 2, (3, 3)) + [0, 0, -6]             # in front of the eye
        w3 = gen.dirichlet([1, 1, 1])
        point = w3 @ tri                                           # a point on the triangle
        clip = transforms.to_homogeneous(np.vstack([tri, point])) @ proj.T
        ndc = clip[:, :2] / clip[:, 3:]                            # the screen positions
        screen_w = T.barycentric(ndc[3], ndc[0], ndc[1], ndc[2])   # screen-space weights
        corrected = T.perspective_weights(screen_w, clip[:3, 3])
        np.testing.assert_allclose(corrected, w3, atol=1e-9)
        uv = gen.uniform(0, 1, (3, 2))
        np.testing.assert_allclose(T.perspective_interpolate(uv, screen_w, clip[:3, 3]), w3 @ uv,
                                   atol=1e-9)
        if np.ptp(clip[:3, 3]) > 0.5:                              # plain interpolation is off
            assert np.abs(screen_w - w3).max() > 1e-4


# ---------------------------------------------------------------------------------------------
# mappings
# ---------------------------------------------------------------------------------------------

def test_spherical_map_axis_points_closed_form():
    pts = {(0, 0, 1): (0.5, 0.5), (1, 0, 0): (0.75, 0.5), (-1, 0, 0): (0.25, 0.5),
           (0, 1, 0): (0.5, 1.0), (0, -1, 0): (0.5, 0.0)}
    for p, (u, v) in pts.items():
        got = T.spherical_map(np.array(p) * 3.0 + [1, 2, 3], center=[1, 2, 3])
        np.testing.assert_allclose(got, (u, v), atol=1e-12)
    # -z is the seam: just to the +x side u is near 1, just to the -x side near 0
    u_pos, _ = T.spherical_map([1e-9, 0, -1])
    u_neg, _ = T.spherical_map([-1e-9, 0, -1])
    assert u_pos > 1 - 1e-6 and u_neg < 1e-6


def test_spherical_map_is_the_corrected_textbook_formula():
    gen = rng(8)
    p = gen.normal(size=(1000, 3)) * gen.uniform(0.1, 10, (1000, 1))
    x, y, z = p.T
    theta = np.arctan2(x, z)                          # the azimuth, with both signs resolved
    phi = np.arctan(y / np.sqrt(x**2 + z**2))         # elevation: horizontal distance in xz
    u, v = T.spherical_map(p)
    np.testing.assert_allclose(u, 0.5 + theta / (2 * np.pi), atol=1e-12)
    np.testing.assert_allclose(v, 0.5 + phi / np.pi, atol=1e-12)
    # the compendium's elevation atan(y / sqrt(x^2 + y^2)) is wrong: at the north pole it says
    # pi/4 instead of pi/2
    assert np.isclose(np.arctan(1 / np.sqrt(0 + 1)), np.pi / 4)
    assert T.spherical_map([0, 1, 0])[1] == 1.0


def test_spherical_round_trips_and_custom_axis_via_scipy_rotation():
    gen = rng(9)
    u, v = gen.uniform(0.001, 0.999, 5000), gen.uniform(0.001, 0.999, 5000)
    p = T.inverse_spherical_map(u, v, center=[1, -1, 2], radius=2.5)
    np.testing.assert_allclose(np.linalg.norm(p - [1, -1, 2], axis=1), 2.5, atol=1e-12)
    np.testing.assert_allclose(T.spherical_map(p, center=[1, -1, 2]), (u, v), atol=1e-9)
    d = gen.normal(size=(5000, 3))
    back = T.inverse_spherical_map(*T.spherical_map(d))
    np.testing.assert_allclose(back, d / np.linalg.norm(d, axis=1, keepdims=True), atol=1e-9)
    # a rotated frame: rotating the points by R and the axes by R changes nothing
    r = Rotation.random(random_state=3)
    u1, v1 = T.spherical_map(d)
    u2, v2 = T.spherical_map(r.apply(d), axis=r.apply([0, 1, 0]), reference=r.apply([0, 0, 1]))
    np.testing.assert_allclose(u2, u1, atol=1e-9)
    np.testing.assert_allclose(v2, v1, atol=1e-9)


def test_cylindrical_map_closed_form_and_round_trip():
    gen = rng(10)
    u, v = T.cylindrical_map([[0, 3, 5], [2, 0, 0], [0, -1, -4e-12 + 0]], height=6)
    np.testing.assert_allclose(u[:2], [0.5, 0.75], atol=1e-12)
    np.testing.assert_allclose(v, [0.5, 0.0, -1 / 6], atol=1e-12)
    uu, vv = gen.uniform(0.001, 0.999, 3000), gen.uniform(-2, 2, 3000)
    p = T.inverse_cylindrical_map(uu, vv, center=[1, 1, 1], radius=0.7, axis=[1, 1, 0], height=3)
    axis = np.array([1, 1, 0]) / np.sqrt(2)
    rel = p - 1
    radial = rel - np.outer(rel @ axis, axis)
    np.testing.assert_allclose(np.linalg.norm(radial, axis=1), 0.7, atol=1e-12)
    np.testing.assert_allclose(rel @ axis, 3 * vv, atol=1e-12)
    got = T.cylindrical_map(p, center=[1, 1, 1], axis=[1, 1, 0], height=3)
    np.testing.assert_allclose(got, (uu, vv), atol=1e-9)
    # the distance from the axis does not matter
    far = 1 + radial * 5 + np.outer(rel @ axis, axis)
    np.testing.assert_allclose(T.cylindrical_map(far, center=[1, 1, 1], axis=[1, 1, 0],
                                                 height=3)[0], uu, atol=1e-9)


def test_planar_map_projection_orientation_and_round_trip():
    gen = rng(11)
    normal = np.array([1.0, 2.0, 2.0]) / 3
    p = gen.normal(size=(500, 3))
    u, v = T.planar_map(p, origin=[1, 0, 0], normal=normal, u_axis=[0, 0, 1], size=(2, 0.5))
    # moving along the normal changes nothing
    u2, v2 = T.planar_map(p + 3.7 * normal, origin=[1, 0, 0], normal=normal, u_axis=[0, 0, 1],
                          size=(2, 0.5))
    np.testing.assert_allclose(u2, u, atol=1e-12)
    np.testing.assert_allclose(v2, v, atol=1e-12)
    # the round trip lands on the foot of the perpendicular
    back = T.inverse_planar_map(u, v, origin=[1, 0, 0], normal=normal, u_axis=[0, 0, 1],
                                size=(2, 0.5))
    foot = p - np.outer((p - [1, 0, 0]) @ normal, normal)
    np.testing.assert_allclose(back, foot, atol=1e-12)
    # default frame for the normal z: u = x, v = y; (e_u, e_v, n) right-handed
    np.testing.assert_allclose(T.planar_map([[3.0, 4.0, 9.0]]), ([3.0], [4.0]))
    e_u = T.inverse_planar_map(1, 0, normal=normal) - T.inverse_planar_map(0, 0, normal=normal)
    e_v = T.inverse_planar_map(0, 1, normal=normal) - T.inverse_planar_map(0, 0, normal=normal)
    np.testing.assert_allclose(np.cross(e_u, e_v), normal, atol=1e-12)


def test_seam_unwrap_makes_interpolation_take_the_short_way():
    # a triangle straddling the seam of the sphere behind the origin
    verts = np.array([[0.05, 0.0, -1.0], [-0.05, 0.0, -1.0], [0.0, 0.05, -1.0]])
    u, _ = T.spherical_map(verts)
    assert np.ptp(u) > 0.9                             # raw: 0.99 and 0.01
    fixed = T.seam_unwrap(u)
    assert np.ptp(fixed) < 0.05
    mid = T.interpolate(fixed, [1 / 3, 1 / 3, 1 / 3])
    assert abs((mid % 1.0) - 1.0) < 0.02 or (mid % 1.0) < 0.02   # near the seam, not u = 0.5
    np.testing.assert_array_equal(T.seam_unwrap([0.2, 0.3, 0.4]), [0.2, 0.3, 0.4])


# ---------------------------------------------------------------------------------------------
# procedural textures
# ---------------------------------------------------------------------------------------------

def test_checkerboard_values_period_and_neighbours():
    gen = rng(12)
    p = gen.uniform(-3, 3, (2000, 2))
    c = T.checkerboard(p, squares=5)
    assert set(np.unique(c)) <= {0.0, 1.0}
    np.testing.assert_array_equal(T.checkerboard(p + [0.4, 0.0], squares=5), c)   # period 2/5
    np.testing.assert_array_equal(T.checkerboard(p + [0.2, 0.2], squares=5), c)
    np.testing.assert_array_equal(T.checkerboard(p + [0.2, 0.0], squares=5), 1 - c)  # neighbour
    img = T.checkerboard(T.uv_grid(16, 16), squares=4)
    assert img.mean() == 0.5 and img[0, 0] == 0 and img[0, 4] == 1
    solid = T.checkerboard(gen.uniform(-2, 2, (100, 3)), squares=3)
    assert set(np.unique(solid)) == {0.0, 1.0}


def test_stripes_duty_cycle_and_period():
    gen = rng(13)
    p = gen.uniform(0, 10, (200_000, 2))
    s = T.stripes(p, count=3, width=0.3)
    assert abs(s.mean() - 0.3) < 0.01
    np.testing.assert_array_equal(T.stripes(p + [1 / 3, 0.7], count=3, width=0.3), s)
    d = T.stripes(p, count=2, width=0.5, direction=[0, 1])
    np.testing.assert_array_equal(d, ((2 * p[:, 1]) % 1 < 0.5).astype(float))


@pytest.mark.parametrize("dim", [2, 3])
def test_perlin_noise_is_zero_on_the_lattice_with_unit_slope_and_bounded(dim):
    gen = rng(14)
    lattice = gen.integers(-300, 300, (500, dim)).astype(float)
    np.testing.assert_array_equal(T.perlin_noise(lattice, seed=5), 0.0)
    # near a lattice point the noise is g . (P - c) with a unit gradient g (the fade has zero
    # slope there, so the other corners do not contribute): the finite-difference gradient
    # has length 1
    h = 1e-6
    grads = np.stack([(T.perlin_noise(lattice + h * e, seed=5)
                       - T.perlin_noise(lattice - h * e, seed=5)) / (2 * h)
                      for e in np.eye(dim)], axis=-1)
    np.testing.assert_allclose(np.linalg.norm(grads, axis=1), 1.0, atol=1e-5)
    n = T.perlin_noise(gen.uniform(-50, 50, (200_000, dim)), seed=5)
    assert np.abs(n).max() <= np.sqrt(dim) / 2 + 1e-12
    assert abs(n.mean()) < 0.01 and n.std() > 0.1


@pytest.mark.parametrize("noise", [T.perlin_noise, T.value_noise])
def test_noise_is_deterministic_seeded_periodic_and_continuous(noise):
    gen = rng(15)
    p = gen.uniform(-20, 20, (5000, 2))
    a = noise(p, seed=7)
    np.testing.assert_array_equal(noise(p, seed=7), a)
    np.testing.assert_array_equal(noise(p, seed=np.random.default_rng(7)),
                                  noise(p, seed=np.random.default_rng(7)))
    assert np.abs(noise(p, seed=8) - a).max() > 0.1
    np.testing.assert_allclose(noise(p + [256.0, -512.0], seed=7), a, atol=1e-9)
    # smooth: a small step changes the value a little (derivative of the fade <= 15/8)
    step = noise(p + 1e-4, seed=7) - a
    assert np.abs(step).max() < 1e-3
    assert np.abs(a).max() <= 1.0


def test_value_noise_at_lattice_points_are_the_random_values():
    pts = np.array([[i, j] for i in range(20) for j in range(20)], dtype=float)
    vals = T.value_noise(pts, seed=3)
    assert np.all(np.abs(vals) <= 1) and len(np.unique(vals)) > 100
    # between lattice points the noise is a convex blend of the four corner values
    mid = T.value_noise(pts[:10] + 0.5, seed=3)
    for k in range(10):
        corners = T.value_noise(pts[k] + np.array([[0, 0], [0, 1], [1, 0], [1, 1]]), seed=3)
        np.testing.assert_allclose(mid[k], corners.mean(), atol=1e-12)  # fade(1/2) = 1/2


def test_turbulence_marble_and_wood_ranges_and_closed_forms():
    gen = rng(16)
    p = gen.uniform(-5, 5, (20_000, 2))
    t = T.turbulence(p, octaves=4, seed=2)
    assert t.min() >= 0 and t.max() <= (np.sqrt(2) / 2) * (1 + 0.5 + 0.25 + 0.125)
    one = np.abs(T.perlin_noise(p, seed=2))
    np.testing.assert_allclose(T.turbulence(p, octaves=1, seed=2), one, atol=1e-12)
    m = T.marble(p, seed=2)
    assert m.min() >= 0 and m.max() <= 1
    np.testing.assert_allclose(T.marble(p, frequency=3, strength=0),
                               0.5 + 0.5 * np.sin(6 * np.pi * p[:, 0]), atol=1e-12)
    w = T.wood(p, seed=2)
    assert w.min() >= 0 and w.max() < 1
    r = np.hypot(p[:, 0] - 0.5, p[:, 1] + 1)
    np.testing.assert_allclose(T.wood(p, rings=4, strength=0, center=[0.5, -1]),
                               (4 * r) % 1.0, atol=1e-9)
    solid = T.wood(gen.uniform(-1, 1, (100, 3)), seed=1)
    assert solid.shape == (100,)
    np.testing.assert_array_equal(T.marble(p, seed=2), m)      # deterministic
    np.testing.assert_array_equal(T.turbulence(p, seed=np.random.default_rng(9)),
                                  T.turbulence(p, seed=np.random.default_rng(9)))
    assert not np.array_equal(T.turbulence(p, seed=3), t)


# ---------------------------------------------------------------------------------------------
# mipmaps
# ---------------------------------------------------------------------------------------------

def block_mean(tex, fy, fx):
    h, w = tex.shape[:2]
    return tex.reshape(h // fy, fy, w // fx, fx, *tex.shape[2:]).mean(axis=(1, 3))


@pytest.mark.parametrize("shape", [(1, 1), (8, 8), (64, 16), (4, 32, 3), (2, 1)])
def test_mipmap_level_sizes_and_box_filter_averages(shape):
    gen = rng(17)
    tex = gen.uniform(0, 255, shape).astype(np.uint8)
    levels = T.mipmap(tex)
    h, w = shape[:2]
    assert len(levels) == int(np.log2(max(h, w))) + 1
    for k, lvl in enumerate(levels):
        fy, fx = min(2**k, h), min(2**k, w)
        assert lvl.shape == (h // fy, w // fx) + shape[2:]
        np.testing.assert_allclose(lvl, block_mean(tex.astype(float), fy, fx), atol=1e-9)
    np.testing.assert_allclose(levels[-1].reshape(-1, *shape[2:])[0], tex.mean(axis=(0, 1)))


def test_trilinear_at_integer_levels_is_bilinear_and_blends_linearly():
    gen = rng(18)
    tex = gen.uniform(0, 1, (32, 64, 3))
    pyr = T.mipmap(tex)
    u, v = gen.uniform(-1, 2, 4000), gen.uniform(-1, 2, 4000)
    for lvl in range(len(pyr)):
        np.testing.assert_allclose(T.trilinear_sample(pyr, u, v, lvl),
                                   scipy_bilinear(pyr[lvl], u, v, "repeat"), atol=1e-12)
    lam = gen.uniform(0, len(pyr) - 1, 4000)
    lo = np.floor(lam).astype(int)
    expected = np.empty((4000, 3))
    for k in range(4000):
        a = scipy_bilinear(pyr[lo[k]], u[k:k + 1], v[k:k + 1], "repeat")[0]
        b = scipy_bilinear(pyr[min(lo[k] + 1, len(pyr) - 1)], u[k:k + 1], v[k:k + 1],
                           "repeat")[0]
        expected[k] = a + (lam[k] - lo[k]) * (b - a)
    np.testing.assert_allclose(T.trilinear_sample(pyr, u, v, lam), expected, atol=1e-12)
    np.testing.assert_allclose(T.trilinear_sample(tex, u, v, 50.0), np.broadcast_to(
        tex.mean(axis=(0, 1)), (4000, 3)), atol=1e-12)


def test_mip_level_and_footprint():
    np.testing.assert_allclose(T.mip_level([1 / 8, 1, 4, 8, 2**20], levels=6), [0, 0, 2, 3, 5])
    # 256 x 128 texture, u changes by 1/32 per pixel along x: 8 texels; v by 1/16 along y: 8
    assert T.texel_footprint((128, 256), 1 / 32, 0, 0, 1 / 16) == 8.0
    assert T.texel_footprint((128, 256), 0, 3 / 128, 4 / 256, 0) == 4.0      # hypot(0,3) vs 4


def test_aliasing_demo_trilinear_is_close_to_the_supersampled_truth():
    d = T.aliasing_demo(96, 72, supersample=6)
    far = slice(36, None)
    err_nearest = np.abs(d.nearest[far] - d.reference[far]).mean()
    err_trilinear = np.abs(d.trilinear[far] - d.reference[far]).mean()
    assert err_trilinear < 0.1 and err_nearest > 3 * err_trilinear
    assert d.level[-1].mean() > d.level[0].mean()          # farther rows use coarser levels
    assert set(np.unique(d.nearest)) <= {0.0, 1.0}


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

def test_bad_textures_coordinates_and_wrap_modes():
    for tex in (np.zeros(5), np.zeros((2, 2, 2, 2)), np.zeros((0, 3)), 3.0):
        with pytest.raises(ValueError, match="texture"):
            T.bilinear_sample(tex, 0.5, 0.5)
        with pytest.raises(ValueError, match="texture"):
            T.nearest_sample(tex, 0.5, 0.5)
    with pytest.raises(ValueError, match="u must be finite"):
        T.bilinear_sample(np.zeros((2, 2)), [0.1, np.nan], 0.5)
    with pytest.raises(ValueError, match="v must be finite"):
        T.nearest_sample(np.zeros((2, 2)), 0.5, np.inf)
    with pytest.raises(ValueError, match="wrap must be one of"):
        T.bilinear_sample(np.zeros((2, 2)), 0.5, 0.5, wrap="wrap")
    with pytest.raises(ValueError, match="u and v"):
        T.bilinear_sample(np.zeros((2, 2)), [0.1, 0.2], [0.1, 0.2, 0.3])
    with pytest.raises(TypeError, match="texture"):
        T.bilinear_sample("image.png", 0.5, 0.5)


def test_bad_triangles_and_weights():
    with pytest.raises(ValueError, match="degenerate"):
        T.barycentric([0, 0], [0, 0], [1, 1], [2, 2])                    # collinear
    with pytest.raises(ValueError, match="degenerate"):
        T.barycentric([0, 0, 0], [1, 1, 1], [1, 1, 1], [1, 1, 1])         # a point
    with pytest.raises(ValueError, match=r"index \(1,\)"):
        T.barycentric([0, 0], [[0, 0], [0, 0]], [[1, 0], [1, 0]], [[0, 1], [2, 0]])
    with pytest.raises(ValueError, match="must all be 2D or all 3D"):
        T.barycentric([0, 0], [0, 0, 0], [1, 0, 0], [0, 1, 0])
    with pytest.raises(ValueError, match="p must be finite"):
        T.barycentric([np.nan, 0], [0, 0], [1, 0], [0, 1])
    with pytest.raises(ValueError, match="weights"):
        T.interpolate([1, 2, 3], [0.5, 0.5])
    with pytest.raises(ValueError, match="values"):
        T.interpolate([1, 2], [0.2, 0.3, 0.5])
    with pytest.raises(ValueError, match="w must be positive"):
        T.perspective_weights([0.2, 0.3, 0.5], [1, 0, 2])


def test_bad_mapping_and_procedural_arguments():
    with pytest.raises(ValueError, match="center"):
        T.spherical_map([1, 2, 3], center=[1, 2, 3])
    with pytest.raises(ValueError, match="normal"):
        T.planar_map([1, 2, 3], normal=[0, 0, 0])
    with pytest.raises(ValueError, match="parallel"):
        T.cylindrical_map([1, 2, 3], axis=[0, 0, 1], reference=[0, 0, 2])
    with pytest.raises(ValueError, match="height"):
        T.cylindrical_map([1, 2, 3], height=0)
    with pytest.raises(ValueError, match="points"):
        T.perlin_noise([1, 2, 3, 4])
    with pytest.raises(ValueError, match="power of two"):
        T.mipmap(np.zeros((6, 8)))
    with pytest.raises(ValueError, match="level"):
        T.trilinear_sample(np.zeros((4, 4)), 0.5, 0.5, -1)
    with pytest.raises(ValueError, match="footprint"):
        T.mip_level(0.0)
    with pytest.raises(ValueError, match="squares"):
        T.checkerboard([0.5, 0.5], squares=0)


def test_interpolate_is_barycentric_interpolate_under_its_old_name():
    # one name per concept: texturing interpolates inside a triangle, scivis on a grid
    from course_lib import scivis
    assert T.interpolate is T.barycentric_interpolate
    assert T.barycentric_interpolate is not scivis.multilinear_interpolate
    assert "interpolate" not in T.__all__ and "barycentric_interpolate" in T.__all__
