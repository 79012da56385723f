"""Level of detail: discrete chains, the screen-space error, progressive meshes, geomorphs and
view-dependent refinement (course_lib.mesh.lod)."""
import numpy as np
import pytest

from course_lib import transforms, viewing
from course_lib.mesh import (ProgressiveMesh, disc, icosphere, lod_chain, screen_space_error,
                             select_level, simplify_qem, switch_distances, view_dependent_faces)


def _bumpy(subdivisions=2):
    v, f = icosphere(subdivisions)
    s = 1 + 0.15 * np.sin(3 * v[:, 0]) * np.sin(4 * v[:, 1]) * np.sin(2 * v[:, 2] + 1)
    return v * s[:, None], f


@pytest.fixture(scope="module")
def pm():
    return ProgressiveMesh(*_bumpy(2), base_faces=40)


# --- screen-space error -------------------------------------------------------------------

@pytest.mark.parametrize("fov_deg, d, eps, height", [(60, 10.0, 0.05, 800), (90, 3.0, 0.2, 480),
                                                     (30, 40.0, 0.5, 1080)])
def test_screen_space_error_matches_a_projected_segment(fov_deg, d, eps, height):
    # two points eps apart vertically at depth d, through perspective + viewport (course_lib.viewing)
    fov = np.radians(fov_deg)
    P = viewing.perspective(fov, 1.0, 0.1, 1000.0)
    V = viewing.viewport(0, 0, height, height)
    pts = np.array([[0.0, 0.0, -d], [0.0, eps, -d]])
    pix = transforms.apply(V @ P, pts)
    assert screen_space_error(eps, d, fov, height) == pytest.approx(pix[1, 1] - pix[0, 1])


def test_screen_space_error_closed_form_and_broadcast():
    # 90 degrees: tan(45) = 1; 0.01 * 500 / 10 = 0.5 px
    assert screen_space_error(0.01, 10.0, np.pi / 2, 1000) == pytest.approx(0.5)
    out = screen_space_error([0.0, 0.02], [10.0, 20.0], np.pi / 2, 1000)
    assert np.allclose(out, [0.0, 0.5])


@pytest.mark.parametrize("kwargs, match", [
    (dict(distance=0.0), "distance"), (dict(distance=-1.0), "distance"),
    (dict(fov=0.0), "fov"), (dict(fov=np.pi), "fov"), (dict(fov=4.0), "fov"),
    (dict(viewport_height=0), "viewport_height"), (dict(geometric_error=-1.0), "geometric_error")])
def test_screen_space_error_rejects_bad_input(kwargs, match):
    args = dict(geometric_error=0.1, distance=5.0, fov=1.0, viewport_height=600)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        screen_space_error(**args)


def test_select_level_coarsest_acceptable_and_thresholds():
    errors = [0.0, 0.01, 0.04, 0.1]
    fov, H, tau = np.pi / 2, 1000, 1.0
    # d_i = eps_i * 500 / tau: 0, 5, 20, 50
    assert np.allclose(switch_distances(errors, fov, H, tau), [0, 5, 20, 50])
    for d, want in [(1.0, 0), (5.0, 1), (19.9, 1), (20.0, 2), (49.0, 2), (80.0, 3)]:
        assert select_level(errors, d, fov, H, tau) == want


def test_select_level_hysteresis():
    errors = [0.0, 0.01, 0.04]
    fov, H = np.pi / 2, 1000
    # at d = 21 level 2 has 0.952 px: fine without hysteresis, not with h = 0.2 (limit 0.8 px)
    assert select_level(errors, 21.0, fov, H, 1.0) == 2
    assert select_level(errors, 21.0, fov, H, 1.0, current=1, hysteresis=0.2) == 1
    assert select_level(errors, 26.0, fov, H, 1.0, current=1, hysteresis=0.2) == 2
    # coming closer: level 2 stays until it exceeds the tolerance itself
    assert select_level(errors, 21.0, fov, H, 1.0, current=2, hysteresis=0.2) == 2
    assert select_level(errors, 19.0, fov, H, 1.0, current=2, hysteresis=0.2) == 1


@pytest.mark.parametrize("kwargs, match", [
    (dict(tolerance=0.0), "tolerance"), (dict(tolerance=-2.0), "tolerance"),
    (dict(distance=0.0), "distance"), (dict(fov=-0.1), "fov"), (dict(fov=np.pi), "fov"),
    (dict(errors=[0.1, 0.0]), "errors"), (dict(hysteresis=1.0), "hysteresis"),
    (dict(current=5), "current")])
def test_select_level_rejects_bad_input(kwargs, match):
    args = dict(errors=[0.0, 0.1], distance=5.0, fov=1.0, viewport_height=600, tolerance=1.0)
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        select_level(**args)


def test_lod_chain_levels_are_simplify_qem_outputs():
    v, f = _bumpy(2)
    chain = lod_chain(v, f, [320, 160, 80, 40])
    assert chain.face_counts.tolist() == [320, 160, 80, 40]
    assert chain.errors[0] == 0 and np.all(np.diff(chain.errors) >= 0) and chain.errors[-1] > 0
    for (lv, lf), n in zip(chain.levels, [320, 160, 80, 40]):
        ov, of = simplify_qem(v, f, n)[:2]
        assert np.array_equal(lf, of) and np.allclose(lv, ov)
    with pytest.raises(ValueError, match="face_counts"):
        lod_chain(v, f, [80, 160])


# --- progressive meshes -------------------------------------------------------------------

def test_progressive_mesh_reproduces_simplify_qem_at_every_count(pm):
    v, f = _bumpy(2)
    assert pm.face_counts()[0] == 40 and pm.face_counts()[-1] == 320
    for n in [320, 300, 222, 150, 100, 64, 40]:
        ov, of = simplify_qem(v, f, n)[:2]
        pv, pf = pm.mesh(n)
        assert np.array_equal(pf, of), n
        assert np.array_equal(pv, ov), n


def test_progressive_mesh_up_and_down_in_any_order():
    v, f = disc(rings=4, segments=16)          # a boundary: one-face splits too
    p = ProgressiveMesh(v, f, base_faces=30)
    rec = p.record
    rng = np.random.default_rng(3)
    for level in rng.integers(0, len(p) + 1, size=12):
        pv, pf = p.mesh(level=int(level))
        rv, rf = rec.mesh_after(len(p) - int(level))
        assert np.array_equal(pf, rf) and np.allclose(pv, rv)


def test_vertex_split_counts(pm):
    # each split adds one vertex and two faces on a closed mesh (Euler: V - E + F stays 2)
    counts = pm.face_counts()
    assert np.all(np.diff(counts) == 2)
    v0, f0 = pm.mesh(level=0)
    v1, f1 = pm.mesh(level=1)
    assert (len(v1) - len(v0), len(f1) - len(f0)) == (1, 2)


def test_geomorph_endpoints_are_the_two_levels(pm):
    cv, cf = pm.mesh(100)
    fv, ff = pm.mesh(200)
    g1, gf = pm.geomorph(100, 200, 1.0)
    assert np.array_equal(gf, ff) and np.allclose(g1, fv)
    g0, gf0 = pm.geomorph(100, 200, 0.0)
    # at alpha = 0 every vertex sits on a vertex of the coarse mesh, and the non-degenerate
    # triangles are exactly the coarse triangles
    d = np.linalg.norm(g0[:, None] - cv[None], axis=2)
    near = d.argmin(axis=1)
    assert np.allclose(d.min(axis=1), 0)
    tri = near[gf0]
    keep = (tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])
    canon = lambda t: {tuple(np.roll(r, -int(np.argmin(r)))) for r in t.tolist()}  # noqa: E731
    assert canon(tri[keep]) == canon(cf)
    # halfway: every vertex on the segment between its two ends
    gh, _ = pm.geomorph(100, 200, 0.5)
    assert np.allclose(gh, (g0 + g1) / 2)
    with pytest.raises(ValueError, match="alpha"):
        pm.geomorph(100, 200, 1.5)
    with pytest.raises(ValueError, match="coarse_faces"):
        pm.geomorph(200, 100, 0.5)


def test_progressive_mesh_errors(pm):
    with pytest.raises(ValueError, match="level"):
        pm.mesh(level=len(pm) + 1)
    with pytest.raises(ValueError, match="exactly one"):
        pm.mesh()
    with pytest.raises(TypeError, match="record"):
        ProgressiveMesh(record="abc")


def _same_triangles(v1, f1, v2, f2):
    """The same triangles (as oriented triples of positions), whatever the vertex order."""
    if len(v1) != len(v2) or len(f1) != len(f2):
        return False
    d = np.linalg.norm(v1[:, None] - v2[None], axis=2)
    if not np.allclose(d.min(axis=1), 0):
        return False
    m = d.argmin(axis=1)[f1]
    canon = lambda t: {tuple(np.roll(r, -int(np.argmin(r)))) for r in t.tolist()}  # noqa: E731
    return canon(m) == canon(f2)


# --- view-dependent refinement ------------------------------------------------------------

def test_view_dependent_extremes(pm):
    v, f = _bumpy(2)
    bv, bf = pm.mesh(level=0)
    av, af, ref = view_dependent_faces(pm, [0, 0, 50.0], 1.0, 500, 1e9)
    assert _same_triangles(av, af, bv, bf) and not ref.all()
    av, af, ref = view_dependent_faces(pm, [0, 0, 50.0], 1.0, 500, 1e-9)
    assert _same_triangles(av, af, v, f) and ref.all()


def test_view_dependent_is_finer_near_the_viewer(pm):
    v, f, refined = view_dependent_faces(pm, [0, 0, 2.5], np.radians(60), 400, 8.0)
    assert 40 < len(f) < 320
    near = v[:, 2] > 0.3
    far = v[:, 2] < -0.3
    assert refined[near].mean() > refined[far].mean() + 0.3
    # farther away: fewer faces
    counts = [len(view_dependent_faces(pm, [0, 0, d], np.radians(60), 400, 4.0)[1])
              for d in (2.5, 6.0, 20.0)]
    assert counts[0] >= counts[1] >= counts[2]
    with pytest.raises(ValueError, match="tolerance"):
        view_dependent_faces(pm, [0, 0, 3.0], 1.0, 400, 0.0)
    with pytest.raises(TypeError, match="ProgressiveMesh"):
        view_dependent_faces("pm", [0, 0, 3.0], 1.0, 400, 1.0)
