"""Tests of course_lib.scivis.unsteady: streamlines, pathlines, streaklines and timelines of
time-dependent fields, and line integral convolution.

Cross-checks: pathlines against scipy.integrate.solve_ivp (tight tolerances) on the double
gyre and the oscillating vortex; the closed forms of the rotating uniform flow typed here (the
streamline a straight line, the pathline and the streakline circular arcs); in steady fields
the three lines coincide (a hypothesis property test); LIC of a uniform flow against a row-wise
1D convolution typed here with np.convolve, the zero-length limit, and the correlation along
and across a circular flow.
"""
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings, strategies as st
from scipy.integrate import solve_ivp

from course_lib.scivis import example_vector_field
from course_lib.scivis import unsteady as U


# --- time-dependent fields and pathlines ------------------------------------------------------

def double_gyre_typed(t, p, A=0.1, eps=0.25, w=2 * math.pi / 10):
    x, y = p
    a = eps * math.sin(w * t)
    b = 1 - 2 * a
    f = a * x * x + b * x
    return [-math.pi * A * math.sin(math.pi * f) * math.cos(math.pi * y),
            math.pi * A * math.cos(math.pi * f) * math.sin(math.pi * y) * (2 * a * x + b)]


def test_double_gyre_matches_the_formula_typed_here_and_is_divergence_free():
    v = U.double_gyre()
    rng = np.random.default_rng(1)
    pts = rng.uniform([0, 0], [2, 1], size=(20, 2))
    for t in (0.0, 1.3, 7.7):
        assert np.allclose(v(pts, t), [double_gyre_typed(t, p) for p in pts], atol=1e-14)
        h = 1e-5
        div = ((v(pts + [h, 0], t)[:, 0] - v(pts - [h, 0], t)[:, 0])
               + (v(pts + [0, h], t)[:, 1] - v(pts - [0, h], t)[:, 1])) / (2 * h)
        assert np.abs(div).max() < 1e-8


@pytest.mark.parametrize("kind", ["double gyre", "oscillating vortex"])
def test_pathlines_match_solve_ivp(kind):
    field = U.unsteady_field(kind)
    seeds = np.array([[0.3, 0.4], [1.2, 0.7], [1.7, 0.2]])
    t0, t1 = 0.5, 6.5
    lines = U.pathline(field, seeds, t0, t1, n_steps=600)
    times = np.linspace(t0, t1, 601)
    for seed, line in zip(seeds, lines):
        ref = solve_ivp(lambda t, p: field(p[None], t)[0], (t0, t1), seed, method="DOP853",
                        rtol=1e-12, atol=1e-12, t_eval=times)
        assert np.abs(line - ref.y.T).max() < 1e-8


def test_backward_pathline_returns_to_the_seed():
    field = U.double_gyre()
    end = U.pathline(field, [0.4, 0.6], 0.0, 5.0, n_steps=400)[-1]
    back = U.pathline(field, end, 5.0, 0.0, n_steps=400)[-1]
    assert np.allclose(back, [0.4, 0.6], atol=1e-9)


# --- the rotating uniform flow: closed forms typed here --------------------------------------

U0, W, PHI = 1.5, 0.8, 0.3


def theta(t):
    return W * t + PHI


def test_rotating_flow_streamline_is_a_straight_line():
    field = U.rotating_uniform_flow(U0, W, PHI)
    t, h, n = 2.0, 0.1, 30
    line = U.streamline_at(field, [1.0, -1.0], t, step=h, n_steps=n)
    s = np.arange(n + 1) * h * U0
    expected = np.array([1.0, -1.0]) + s[:, None] * [math.cos(theta(t)), math.sin(theta(t))]
    assert np.allclose(line, expected, atol=1e-12)
    both = U.streamline_at(field, [1.0, -1.0], t, step=h, n_steps=n, both=True)
    assert both.shape == (2 * n + 1, 2) and np.allclose(both[n], [1.0, -1.0])
    assert np.allclose(both[0], [1.0, -1.0] - s[-1] * np.array([math.cos(theta(t)),
                                                                  math.sin(theta(t))]))


def test_rotating_flow_pathline_and_streakline_closed_forms():
    field = U.rotating_uniform_flow(U0, W, PHI)
    r = np.array([0.5, 0.25])
    t0, t1, R = 0.0, 4.0, U0 / W
    times = np.linspace(t0, t1, 201)
    path = U.pathline(field, r, t0, t1, n_steps=200)
    exp_path = np.array([[r[0] + R * (math.sin(theta(t)) - math.sin(theta(t0))),
                          r[1] + R * (math.cos(theta(t0)) - math.cos(theta(t)))]
                         for t in times])
    assert np.abs(path - exp_path).max() < 1e-9
    streak = U.streakline(field, r, t0, t1, n_particles=41, n_steps=100)
    taus = np.linspace(t0, t1, 41)
    exp_streak = np.array([[r[0] + R * (math.sin(theta(t1)) - math.sin(theta(tau))),
                            r[1] + R * (math.cos(theta(tau)) - math.cos(theta(t1)))]
                           for tau in taus])
    assert np.abs(streak - exp_streak).max() < 1e-8
    # the three differ: the streamline through r at t1 is straight, the other two are arcs
    # bent opposite ways, sharing their ends r and path[-1]
    assert np.allclose(streak[0], path[-1]) and np.allclose(streak[-1], r)
    mid = exp_path[100]
    assert np.linalg.norm(streak[20] - mid) > 0.5
    assert np.allclose(streak[20] + mid, r + path[-1], atol=1e-9)    # point reflection


def test_timeline_in_a_uniform_flow_moves_rigidly():
    field = U.rotating_uniform_flow(U0, W, PHI)
    line = np.column_stack([np.linspace(-1, 1, 9), np.zeros(9)])
    t0, t1 = 1.0, 3.0
    moved = U.timeline(field, line, t0, t1, n_steps=80)
    shift = U0 / W * np.array([math.sin(theta(t1)) - math.sin(theta(t0)),
                               math.cos(theta(t0)) - math.cos(theta(t1))])
    assert moved.shape == line.shape and np.allclose(moved, line + shift, atol=1e-10)


def test_timeline_conserves_particles_and_follows_each_pathline():
    field = U.double_gyre()
    line = np.column_stack([np.full(25, 0.9), np.linspace(0.05, 0.95, 25)])
    moved = U.timeline(field, line, 0.0, 4.0, n_steps=200)
    assert moved.shape == (25, 2) and np.isfinite(moved).all()
    each = U.pathline(field, line, 0.0, 4.0, n_steps=200)[:, -1]
    assert np.allclose(moved, each, atol=1e-12)
    assert np.linalg.norm(moved - line, axis=1).max() > 0.05      # it did move
    rec = U.timeline(field, line, 0.0, 4.0, n_steps=10, record=True)
    assert rec.shape == (11, 25, 2) and np.allclose(rec[0], line)


def test_advect_moves_each_particle_from_its_own_start_time():
    field = U.oscillating_vortex()
    pts = np.array([[0.5, 0.2], [1.0, -0.3], [-0.4, 0.9]])
    starts, ends = np.array([0.0, 1.5, 3.0]), np.array([4.0, 2.5, 0.5])
    moved = U.advect(field, pts, starts, ends, n_steps=100)
    for p, a, b, m in zip(pts, starts, ends, moved):
        ref = solve_ivp(lambda t, q: field(q[None], t)[0], (a, b), p, rtol=1e-12, atol=1e-12)
        assert np.allclose(m, ref.y[:, -1], atol=1e-8)
    with pytest.raises(ValueError, match="t_start must be one time or one per particle"):
        U.advect(field, pts, [0.0, 1.0], 2.0)
    with pytest.raises(ValueError, match="points"):
        U.advect(field, [0.0, 1.0], 0.0, 2.0)


# --- steady fields: the three lines coincide --------------------------------------------------

@settings(max_examples=25, deadline=None)
@given(kind=st.sampled_from(["vortex", "saddle", "spiral", "source"]),
       x=st.floats(-0.8, 0.8), y=st.floats(-0.8, 0.8), t0=st.floats(-3, 3))
def test_in_a_steady_field_streamline_pathline_and_streakline_coincide(kind, x, y, t0):
    assume(math.hypot(x, y) > 0.05)          # not at the critical point, where lines stop
    field = U.steady_flow(example_vector_field(kind))
    m, T = 21, 1.0
    h = T / (m - 1)
    stream = U.streamline_at(field, [x, y], t0 + 5.0, step=h, n_steps=m - 1)
    path = U.pathline(field, [x, y], t0, t0 + T, n_steps=m - 1)
    streak = U.streakline(field, [x, y], t0, t0 + T, n_particles=m, n_steps=40)
    assert np.allclose(stream, path, atol=1e-12)
    assert np.allclose(streak[::-1], path, atol=1e-6)


# --- line integral convolution ----------------------------------------------------------------

def row_average(noise, m):
    """Each pixel's mean over its row neighbours j - m .. j + m that exist (np.convolve)."""
    ones = np.ones(2 * m + 1)
    out = np.empty_like(noise)
    for i, row in enumerate(noise):
        out[i] = (np.convolve(row, ones, mode="same")
                  / np.convolve(np.ones_like(row), ones, mode="same"))
    return out


@pytest.mark.parametrize("length,step", [(3, 1.0), (4, 0.5), (2.5, 0.5)])
def test_lic_of_a_uniform_flow_averages_along_rows(length, step):
    rng = np.random.default_rng(3)
    noise = rng.random((12, 20))
    u, v = np.full((12, 20), 2.0), np.zeros((12, 20))
    out = U.lic(u, v, noise, kernel_length=length, step=step)
    if step == 1.0:
        assert np.allclose(out, row_average(noise, int(length)), atol=1e-12)
    else:
        # half-pixel steps: sample k lands in pixel round(j + k/2) (halves round up), so each
        # neighbour is counted twice, the centre once, plus the ends
        m = int(length / step)
        expected = np.empty_like(noise)
        for i in range(12):
            for j in range(20):
                vals = [noise[i, int(math.floor(j + k * step + 0.5))] for k in range(-m, m + 1)
                        if -0.5 <= j + k * step < 19.5]
                expected[i, j] = sum(vals) / len(vals)
        assert np.allclose(out, expected, atol=1e-12)
    # the flow runs along x: the columns of a vertical flow are the transposed picture
    out_t = U.lic(v.T, u.T, noise.T, kernel_length=length, step=step)
    assert np.allclose(out_t, out.T, atol=1e-12)


def test_lic_hann_kernel_on_a_uniform_flow():
    noise = np.random.default_rng(5).random((3, 15))
    L = 4.0
    out = U.lic(np.ones((3, 15)), np.zeros((3, 15)), noise, kernel_length=L, step=1.0,
                kernel="hann")
    j = 7
    w = [0.5 * (1 + math.cos(math.pi * k / L)) for k in range(-4, 5)]
    expected = sum(wk * noise[1, j + k] for wk, k in zip(w, range(-4, 5))) / sum(w)
    assert out[1, j] == pytest.approx(expected, abs=1e-12)


def test_lic_short_kernel_is_the_noise():
    rng = np.random.default_rng(9)
    u, v = rng.normal(size=(2, 16, 16))
    noise = rng.random((16, 16))
    assert np.array_equal(U.lic(u, v, noise, kernel_length=0.3, step=0.5), noise)
    tr = U.LICTraces(u, v, noise, max_length=6.0, step=0.5)
    assert np.allclose(tr.image(0.2), noise)


def circular(n=96):
    y, x = np.mgrid[0:n, 0:n] - (n - 1) / 2
    return -y, x


def test_lic_is_correlated_along_a_circular_flow_not_across():
    u, v = circular()
    out = U.lic(u, v, kernel_length=8, step=0.5, seed=2)
    # right of the centre the flow runs along +y (down the rows); above it along -x
    band = out[40:56, 66:90]
    along = np.corrcoef(band[:-1].ravel(), band[1:].ravel())[0, 1]
    across = np.corrcoef(band[:, :-1].ravel(), band[:, 1:].ravel())[0, 1]
    top = out[66:90, 40:56]
    along2 = np.corrcoef(top[:, :-1].ravel(), top[:, 1:].ravel())[0, 1]
    across2 = np.corrcoef(top[:-1].ravel(), top[1:].ravel())[0, 1]
    assert along > 0.8 and along2 > 0.8
    assert across < 0.4 and across2 < 0.4
    assert out.std() < np.random.default_rng(2).random((96, 96)).std()   # averaging


def test_lic_is_deterministic_with_a_seed():
    u, v = circular(32)
    a = U.lic(u, v, kernel_length=5, seed=7)
    assert np.array_equal(a, U.lic(u, v, kernel_length=5, seed=7))
    assert not np.allclose(a, U.lic(u, v, kernel_length=5, seed=8))


def test_lic_prefix_sums_equal_direct_box_sums():
    u, v = circular(24)
    tr = U.LICTraces(u, v, max_length=6, step=0.5, seed=1)
    for L in (0.5, 2.0, 3.7, 6.0):
        m = int(L / 0.5)
        sl = slice(tr.n - m, tr.n + m + 1)
        direct = tr.samples[sl].sum(0) / tr.valid[sl].sum(0)
        assert np.allclose(tr.image(L), direct, atol=1e-12)
        assert np.allclose(U.lic(u, v, kernel_length=L, step=0.5, seed=1), direct)


def test_lic_stops_at_critical_points_and_borders():
    u, v = np.zeros((5, 5)), np.zeros((5, 5))
    noise = np.arange(25.0).reshape(5, 5)
    assert np.array_equal(U.lic(u, v, noise, kernel_length=3), noise)
    tr = U.LICTraces(np.ones((4, 6)), np.zeros((4, 6)), np.ones((4, 6)), max_length=3,
                     step=1, keep_points=True)
    assert tr.valid[:, 0, 0].tolist() == [False] * 3 + [True] * 4
    assert np.allclose(tr.points[4, 2, 1], [2.0, 2.0])


# --- errors -----------------------------------------------------------------------------------

def test_errors():
    u, v = np.ones((4, 4)), np.zeros((4, 4))
    with pytest.raises(ValueError, match="kernel_length"):
        U.lic(u, v, kernel_length=0)
    with pytest.raises(ValueError, match="kernel_length"):
        U.lic(u, v, kernel_length=-2)
    with pytest.raises(ValueError, match="step"):
        U.lic(u, v, step=0)
    with pytest.raises(ValueError, match="noise"):
        U.lic(u, v, noise=np.ones((3, 4)))
    bad = u.copy()
    bad[1, 2] = np.nan
    with pytest.raises(ValueError, match="u must be finite"):
        U.lic(bad, v)
    with pytest.raises(ValueError, match="same shape"):
        U.lic(u, np.zeros((4, 5)))
    with pytest.raises(ValueError, match="kernel"):
        U.lic(u, v, kernel="gauss")
    tr = U.LICTraces(u, v, max_length=2)
    with pytest.raises(ValueError, match="at most"):
        tr.image(3)
    field = U.double_gyre()
    with pytest.raises(TypeError, match="field"):
        U.pathline("gyre", [0, 0], 0, 1)
    with pytest.raises(ValueError, match="t1 must not be before t0"):
        U.streakline(field, [0.5, 0.5], 2.0, 1.0)
    with pytest.raises(ValueError, match="release_point"):
        U.streakline(field, [[0.5, 0.5], [1, 1]], 0.0, 1.0)
    with pytest.raises(ValueError, match="n_steps"):
        U.pathline(field, [0.5, 0.5], 0.0, 1.0, n_steps=0)
    with pytest.raises(ValueError, match="step must be positive"):
        U.streamline_at(field, [0.5, 0.5], 0.0, step=0)
    with pytest.raises(ValueError, match="one 2-vector per point"):
        U.pathline(lambda p, t: np.zeros(3), [0.5, 0.5], 0.0, 1.0)
    with pytest.raises(ValueError, match="NaN"):
        U.pathline(lambda p, t: p * np.nan, [0.5, 0.5], 0.0, 1.0)
    with pytest.raises(ValueError, match="kind"):
        U.unsteady_field("tornado")
    with pytest.raises(ValueError, match="omega"):
        U.rotating_uniform_flow(omega=0)
    with pytest.raises(ValueError, match="points"):
        U.timeline(field, [0.5, 0.5], 0.0, 1.0)
