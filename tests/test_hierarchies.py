"""Cross-checks of course_lib.texturing.hierarchies (textbook 14.9, texture hierarchies).

Independent references: the arrays mipmap() actually builds and the closed form of the
geometric series (memory); the analytic derivatives of the perspective floor and numpy's
central differences (derivatives); mip_level(texel_footprint(...)) of the analytic derivatives
(level map); numpy's SVD (ellipse axes); per-texel loops (clipmap windows, tiles of a view); an
LRU cache written here with collections.OrderedDict (residency).
"""
import math
from collections import OrderedDict

import numpy as np
import pytest

from course_lib import texturing as T

RNG = np.random.default_rng(1418)


# --- memory -----------------------------------------------------------------------------------

@pytest.mark.parametrize("shape", [(1, 1), (4, 4), (2, 8), (64, 16), (256, 256), (1, 32)])
def test_memory_equals_the_arrays_of_mipmap(shape):
    levels = T.mipmap(np.zeros(shape + (4,), dtype=np.uint8))
    texels = sum(lvl.shape[0] * lvl.shape[1] for lvl in levels)
    m = T.pyramid_memory(shape, channels=4, bytes_per_channel=1)
    assert m.total == 4 * texels
    assert [s for s in m.shapes] == [lvl.shape[:2] for lvl in levels]
    floats = T.pyramid_memory(shape, channels=4, bytes_per_channel=8)
    assert floats.total == sum(lvl.nbytes for lvl in levels)         # mipmap() stores float64


@pytest.mark.parametrize("n", range(0, 12))
def test_memory_closed_form_of_the_series(n):
    side = 2 ** n
    m = T.pyramid_memory((side, side), channels=1)
    assert m.total == (4 ** (n + 1) - 1) // 3                         # 1 + 4 + ... + 4^n
    assert m.total < m.bound and math.isclose(m.bound, side * side * 4 / 3)
    v = T.pyramid_memory((side, side, side), channels=1)
    assert v.total == (8 ** (n + 1) - 1) // 7
    assert v.total < v.bound and math.isclose(v.bound, side ** 3 * 8 / 7)


def test_memory_of_non_power_of_two_sizes_by_floor_halving():
    for _ in range(30):
        h, w = (int(x) for x in RNG.integers(1, 3000, size=2))
        total, a, b = 0, h, w
        while True:                          # OpenGL: max(1, floor(s / 2)), until 1 x 1
            total += a * b
            if a == b == 1:
                break
            a, b = max(1, a // 2), max(1, b // 2)
        assert T.pyramid_memory((h, w), channels=3, bytes_per_channel=2).total == 6 * total
    assert T.level_shapes((5, 3)) == [(5, 3), (2, 1), (1, 1)]
    # a 2:1 texture is a third of a texel above 4/3 N; a strip is near 2 N
    m = T.pyramid_memory((512, 1024), channels=1)
    assert math.isclose(m.total - m.bound, 1 / 3)
    assert T.pyramid_memory((1, 1024), channels=1).total == 2047


def test_memory_levels_and_errors():
    assert T.pyramid_memory((8, 8), channels=1, levels=2).total == 64 + 16
    with pytest.raises(ValueError, match=r"levels must be in \[1, 4\]"):
        T.pyramid_memory((8, 8), levels=5)
    with pytest.raises(ValueError, match="shape"):
        T.pyramid_memory((0, 8))
    with pytest.raises(ValueError, match="shape"):
        T.pyramid_memory((8, 8.5))
    with pytest.raises(ValueError, match="shape must have 2 or 3"):
        T.pyramid_memory((8,))
    with pytest.raises(TypeError, match="shape"):
        T.pyramid_memory(8)
    with pytest.raises(ValueError, match="channels"):
        T.pyramid_memory((8, 8), channels=0)
    with pytest.raises(TypeError, match="bytes_per_channel"):
        T.pyramid_memory((8, 8), bytes_per_channel=True)


# --- derivatives and the level map ------------------------------------------------------------

def test_quad_differences_of_the_perspective_floor():
    view = T.receding_plane(64, 48, tilt=math.radians(35), camera_height=1.5, focal=50.0)
    du_dx, dv_dx, du_dy, dv_dy = T.uv_derivatives(view.u, view.v)
    # each pair's difference equals the exact difference of the closed form; and the
    # analytic derivative at the pair's midpoint to second order (exactly for u along x)
    x = np.arange(64) + 0.5 - 32
    y = np.arange(48) + 0.5 - 24
    th, f, h, e = math.radians(35), 50.0, 1.5, 8.0

    def uv(xx, yy):
        s = f * math.sin(th) - yy * math.cos(th)
        return 0.5 + h * xx / s / e, h * (yy * math.sin(th) + f * math.cos(th)) / s / e

    for i in (0, 7, 46):
        for j in (0, 13, 62):
            j0, i0 = j & ~1, i & ~1
            assert math.isclose(du_dx[i, j], uv(x[j0 + 1], y[i])[0] - uv(x[j0], y[i])[0],
                                rel_tol=1e-9)
            assert math.isclose(dv_dy[i, j], uv(x[j], y[i0 + 1])[1] - uv(x[j], y[i0])[1],
                                rel_tol=1e-9)
    assert np.allclose(dv_dx, 0, atol=1e-15)
    # mean value theorem: a pair's difference lies between the analytic derivatives at the
    # pair's two pixels (u_x does not change along a row: there it is exact)
    assert np.allclose(du_dx, view.du_dx, rtol=1e-9)
    rows = np.arange(48) & ~1
    for d, a in ((du_dy, view.du_dy), (dv_dy, view.dv_dy)):
        lo, hi = np.minimum(a[rows], a[rows + 1]), np.maximum(a[rows], a[rows + 1])
        assert np.all(d >= lo - 1e-12) and np.all(d <= hi + 1e-12)
    # numpy's central differences (an independent estimate) agree with the analytic ones
    g_dv_dy, g_du_dx = np.gradient(view.v)[0], np.gradient(view.u)[1]
    assert np.allclose(g_du_dx[:, 1:-1], view.du_dx[:, 1:-1], rtol=1e-3)
    assert np.allclose(g_dv_dy[1:-1], view.dv_dy[1:-1], rtol=2e-2)


def test_analytic_derivatives_against_finite_differences_of_the_closed_form():
    eps = 1e-5
    for _ in range(10):
        w, h_img = 40, 30
        view = T.receding_plane(w, h_img, focal=30.0)
        # shift the camera's principal point by moving the image: compare u(x + eps)
        i, j = (int(RNG.integers(0, h_img)), int(RNG.integers(0, w)))
        th, f = math.radians(30), 30.0
        xx, yy = j + 0.5 - w / 2, i + 0.5 - h_img / 2

        def uv(a, b):
            s = f * math.sin(th) - b * math.cos(th)
            return 0.5 + a / s / 8.0, (b * math.sin(th) + f * math.cos(th)) / s / 8.0

        num = [(uv(xx + eps, yy)[k] - uv(xx - eps, yy)[k]) / (2 * eps) for k in (0, 1)]
        num += [(uv(xx, yy + eps)[k] - uv(xx, yy - eps)[k]) / (2 * eps) for k in (0, 1)]
        ana = [view.du_dx[i, j], view.dv_dx[i, j], view.du_dy[i, j], view.dv_dy[i, j]]
        assert np.allclose(num, ana, rtol=1e-6, atol=1e-10)


def test_level_map_against_mip_level_of_analytic_derivatives():
    shape = (512, 512)
    view = T.receding_plane(128, 96, focal=96.0)
    levels = len(T.level_shapes(shape))
    lam = T.level_map(shape, view.u, view.v, levels)
    ref = T.mip_level(T.texel_footprint(shape, view.du_dx, view.dv_dx, view.du_dy,
                                        view.dv_dy), levels)
    assert lam.shape == (96, 128)
    # the quad's difference is the derivative somewhere between the pair's pixels: the level
    # lies within the analytic levels of the quad's rows (up to the max of two lengths)
    rows = np.arange(96) & ~1
    lo, hi = np.minimum(ref[rows], ref[rows + 1]), np.maximum(ref[rows], ref[rows + 1])
    assert np.all(lam >= lo - 0.01) and np.all(lam <= hi + 0.01)
    assert np.abs(lam - ref).mean() < 0.05
    assert np.all(np.diff(lam.mean(axis=1)) >= -1e-9)      # coarser towards the horizon
    # an affine (u, v) image: differences are exact, the level equals the closed form
    x, y = np.meshgrid(np.arange(6), np.arange(4))
    lam = T.level_map((256, 128), 3 * x / 128 + y / 128, 4 * y / 256)
    assert np.allclose(lam, 0.5 * math.log2(max(3 ** 2, 1 + 4 ** 2)))


def test_derivative_and_plane_errors():
    with pytest.raises(ValueError, match="H, W >= 2"):
        T.uv_derivatives(np.zeros(5), np.zeros(5))
    with pytest.raises(ValueError, match="finite"):
        T.uv_derivatives(np.full((2, 2), np.nan), np.zeros((2, 2)))
    with pytest.raises(ValueError, match="same shape"):
        T.uv_derivatives(np.zeros((2, 3)), np.zeros((3, 2)))
    with pytest.raises(ValueError, match="tilt must be in"):
        T.receding_plane(tilt=2.0)
    with pytest.raises(ValueError, match="tilt is too small"):
        T.receding_plane(16, 16, tilt=0.1)
    with pytest.raises(ValueError, match="camera_height"):
        T.receding_plane(camera_height=0)
    with pytest.raises(ValueError, match="width"):
        T.receding_plane(width=0)


# --- anisotropy -------------------------------------------------------------------------------

def test_ellipse_axes_are_the_singular_values():
    d = RNG.normal(size=(4, 200)) / 64
    major, minor = T.footprint_axes((64, 128), *d, method="ellipse")
    for k in range(200):
        ux, vx, uy, vy = d[:, k]
        s = np.linalg.svd(np.array([[128 * ux, 128 * uy], [64 * vx, 64 * vy]]),
                          compute_uv=False)
        assert np.allclose([major[k], minor[k]], s, rtol=1e-9, atol=1e-12)
    lmaj, lmin = T.footprint_axes((64, 128), *d)
    # |J e| lies between the singular values: the lengths rule is inside the ellipse's axes
    assert np.all(minor <= lmin + 1e-12) and np.all(lmin <= lmaj) and np.all(lmaj <= major + 1e-12)
    perpendicular = T.footprint_axes((64, 64), 3 / 64, 4 / 64, -8 / 64, 6 / 64, method="ellipse")
    assert np.allclose(perpendicular, (10, 5))


def test_anisotropic_level_against_the_rule():
    for _ in range(100):
        minor = 2.0 ** RNG.uniform(0, 4)
        n = int(RNG.integers(1, 17))
        ang = RNG.uniform(0, 2 * math.pi)
        a = minor * n * np.array([math.cos(ang), math.sin(ang)])     # major along a
        b = minor * np.array([-math.sin(ang), math.cos(ang)])
        args = (a[0] / 256, a[1] / 256, b[0] / 256, b[1] / 256)
        lam, samples, ratio = T.anisotropic_level((256, 256), *args, max_anisotropy=16)
        assert int(samples) == n and math.isclose(float(ratio), n, rel_tol=1e-9)
        assert math.isclose(float(lam), max(0.0, math.log2(minor)), abs_tol=1e-9)
        iso = T.mip_level(T.texel_footprint((256, 256), *args))
        assert math.isclose(float(iso), max(0.0, math.log2(minor * n)), abs_tol=1e-9)
    # clamped at N_max: the level is log2(major / N_max), coarser than the minor axis
    lam, samples, _ = T.anisotropic_level((256, 256), 64 / 256, 0, 0, 1 / 256, max_anisotropy=4)
    assert int(samples) == 4 and math.isclose(float(lam), 4.0)
    lam, samples, ratio = T.anisotropic_level((256, 256), 8 / 256, 0, 0, 0)   # zero width
    assert int(samples) == 16 and np.isinf(ratio) and float(lam) == 0.0
    lam, samples, ratio = T.anisotropic_level((256, 256), 0, 0, 0, 0)
    assert int(samples) == 1 and float(ratio) == 1.0 and float(lam) == 0.0
    with pytest.raises(ValueError, match="max_anisotropy"):
        T.anisotropic_level((256, 256), 1, 0, 0, 1, max_anisotropy=0)
    with pytest.raises(ValueError, match="method"):
        T.footprint_axes((256, 256), 1, 0, 0, 1, method="box")


# --- clipmaps ---------------------------------------------------------------------------------

def brute_window(n, c, t):
    """Texels of an n-texel axis kept around t in [0, 1]: a loop over texel centres."""
    if n <= c:
        return list(range(n))
    p = t * n
    p = min(max(p, c / 2), n - c / 2)
    return [k for k in range(n) if p - c / 2 <= k + 0.5 < p + c / 2]


def test_clipmap_windows_against_a_per_texel_test():
    shape, c = (256, 128), 32
    layout = T.clipmap(shape, c)
    for _ in range(40):
        centre = RNG.uniform(0, 1, size=2)
        centre = np.round(centre * 64) / 64 if _ % 2 else centre        # ties on texel edges
        for lv, (h, w) in enumerate(layout.shapes):
            i0, i1, j0, j1 = T.clipmap_window(shape, c, lv, centre)
            rows, cols = brute_window(h, c, centre[1]), brute_window(w, c, centre[0])
            assert list(range(i0, i1)) == rows and list(range(j0, j1)) == cols
            assert (i1 - i0, j1 - j0) == layout.windows[lv]


def test_clipmap_layout_and_memory():
    layout = T.clipmap((16384, 16384), 512)
    assert layout.clipped.tolist() == [True] * 5 + [False] * 10
    assert layout.resident_texels == 5 * 512 ** 2 + (4 ** 10 - 1) // 3
    assert layout.full_texels == (4 ** 15 - 1) // 3
    assert layout.full_texels == T.pyramid_memory((16384, 16384), channels=1).total
    with pytest.raises(ValueError, match="clip_size must be a power of two.*got 500"):
        T.clipmap((1024, 1024), 500)
    with pytest.raises(ValueError, match="shape"):
        T.clipmap((1024, -1), 64)
    with pytest.raises(ValueError, match=r"level must be in \[0, 10\]"):
        T.clipmap_window((1024, 1024), 64, 11, (0.5, 0.5))
    with pytest.raises(ValueError, match="centre"):
        T.clipmap_window((1024, 1024), 64, 0, (1.5, 0.5))


def test_clipmap_level_used_against_a_loop():
    shape, c = (128, 128), 16
    layout = T.clipmap(shape, c)
    centre = (0.3, 0.6)
    u, v = RNG.uniform(0, 1, size=(2, 300))
    lv = RNG.integers(0, len(layout.shapes), size=300)
    used = T.clipmap_level_used(shape, c, centre, u, v, lv)
    for k in range(300):
        level = int(lv[k])
        while True:
            h, w = layout.shapes[level]
            i0, i1, j0, j1 = T.clipmap_window(shape, c, level, centre)
            i, j = min(int(v[k] * h), h - 1), min(int(u[k] * w), w - 1)
            if i0 <= i < i1 and j0 <= j < j1:
                break
            level += 1
        assert used[k] == level
    assert np.all(T.clipmap_level_used(shape, c, centre, 0.3, 0.6, np.arange(8)) == np.arange(8))
    with pytest.raises(ValueError, match=r"level must be in \[0, 7\]"):
        T.clipmap_level_used(shape, c, centre, 0.5, 0.5, 8)
    with pytest.raises(ValueError, match="u and v must be in"):
        T.clipmap_level_used(shape, c, centre, 1.5, 0.5, 0)


# --- virtual textures -------------------------------------------------------------------------

def test_tiles_needed_against_loops():
    shape, t = (1024, 1024), 64
    view = T.receding_plane(48, 36, focal=36.0, texture_extent=6.0)
    lam = T.level_map(shape, view.u, view.v)
    got = T.tiles_needed(shape, t, view.u, view.v, lam)
    last = len(T.tile_counts(shape, t)) - 1
    want = set()
    for i in range(36):
        for j in range(48):
            lv = min(int(math.floor(lam[i, j])), last)
            n = 1024 >> lv
            ti = (int(math.floor(view.v[i, j] * n)) % n) // t
            tj = (int(math.floor(view.u[i, j] * n)) % n) // t
            want.add((lv, ti, tj))
    assert [tuple(r) for r in got] == sorted(want)
    assert T.tile_counts((512, 1024), 128) == [(4, 8), (2, 4), (1, 2), (1, 1)]
    with pytest.raises(ValueError, match="tile must be a power of two"):
        T.tiles_needed(shape, 48, 0.5, 0.5, 0)
    with pytest.raises(ValueError, match="power-of-two sides"):
        T.tile_counts((1000, 1024), 64)
    with pytest.raises(ValueError, match="level must be non-negative"):
        T.tiles_needed(shape, t, 0.5, 0.5, -1)


class ReferenceLRU:
    """An LRU cache of tiles written from the definition, with an OrderedDict."""

    def __init__(self, budget, root):
        self.budget, self.root, self.d = budget, root, OrderedDict()

    def request(self, tiles):
        hits = misses = 0
        evicted = []
        for key in map(tuple, tiles):
            if key == self.root:
                hits += 1
                continue
            if key in self.d:
                hits += 1
                self.d.move_to_end(key)
                continue
            misses += 1
            if len(self.d) == self.budget:
                evicted.append(next(iter(self.d)))
                del self.d[evicted[-1]]
            self.d[key] = None
        return hits, misses, evicted

    def resolve(self, lv, i, j):
        while (lv, i, j) != self.root and (lv, i, j) not in self.d:
            lv, i, j = lv + 1, i // 2, j // 2
        return (lv, i, j)


def test_tile_cache_against_a_reference_lru():
    shape, t = (512, 512), 32
    counts = T.tile_counts(shape, t)
    root = (len(counts) - 1, 0, 0)
    for budget in (1, 5, 20):
        cache, ref = T.TileCache(shape, t, budget), ReferenceLRU(budget, root)
        for frame in range(30):
            lv = RNG.integers(0, len(counts), size=12)
            tiles = [(int(k), int(RNG.integers(0, counts[k][0])), int(RNG.integers(0, counts[k][1])))
                     for k in lv]
            got = cache.request(tiles)
            h, m, e = ref.request(tiles)
            assert (got["hits"], got["misses"], [tuple(x) for x in got["evicted"]]) == (h, m, e)
            assert cache.resident == list(ref.d)
            assert len(cache.resident) <= budget
            for k in range(len(counts)):
                table = cache.page_table(k)
                for i in range(counts[k][0]):
                    for j in range(counts[k][1]):
                        assert cache.resolve(k, i, j) == ref.resolve(k, i, j)
                        assert table[i, j] == ref.resolve(k, i, j)[0]


def test_tile_cache_errors():
    cache = T.TileCache((256, 256), 64, 4)
    with pytest.raises(ValueError, match="budget"):
        T.TileCache((256, 256), 64, 0)
    with pytest.raises(ValueError, match="outside level 0"):
        cache.request([(0, 4, 0)])
    with pytest.raises(ValueError, match=r"level must be in \[0, 2\]"):
        cache.resolve(3, 0, 0)
    with pytest.raises(ValueError, match=r"level must be in \[0, 2\]"):
        cache.page_table(5)
    assert cache.request([]) == {"hits": 0, "misses": 0, "evicted": []}


def test_quad_differences_against_a_loop_for_odd_sizes():
    for h, w in ((5, 7), (2, 2), (6, 3), (3, 2)):
        u, v = RNG.random((2, h, w))
        du_dx, dv_dx, du_dy, dv_dy = T.uv_derivatives(u, v)
        for i in range(h):
            for j in range(w):
                j0 = j - j % 2 if j - j % 2 + 1 < w else w - 2      # the quad's pair
                i0 = i - i % 2 if i - i % 2 + 1 < h else h - 2
                assert du_dx[i, j] == u[i, j0 + 1] - u[i, j0]
                assert dv_dx[i, j] == v[i, j0 + 1] - v[i, j0]
                assert du_dy[i, j] == u[i0 + 1, j] - u[i0, j]
                assert dv_dy[i, j] == v[i0 + 1, j] - v[i0, j]
