"""Headless tests of the LOD explorer: its scene against the screen-space error typed here
(eps * H / (2 d tan(fov / 2))), the level choice, the geomorph's ends (the finer level at the
switch distance, the coarser one at the end of the band) and the wiring (every control changes
the drawn mesh or the text)."""
import math

import numpy as np
import pytest

from course_lib.widgets import lod as W


def pixels(eps, d):
    return eps * W.HEIGHT / (2 * d * math.tan(math.radians(40) / 2))


@pytest.mark.parametrize("d, tau", [(10.0, 1.0), (95.0, 1.0), (150.0, 2.0), (400.0, 0.5)])
def test_level_is_the_coarsest_within_the_tolerance(d, tau):
    chain, _ = W.levels()
    s = W.scene(W.State(distance=d, tolerance=tau, geomorph=False))
    px = [pixels(e, d) for e in chain.errors]
    ok = [i for i, p in enumerate(px) if p <= tau]
    assert s["level"] == max(ok)
    assert s["screen_error"] == pytest.approx(px[s["level"]])
    assert s["faces"] == chain.face_counts[s["level"]]
    assert np.allclose(s["switch"] * 2 * tau * math.tan(math.radians(20)) / W.HEIGHT,
                       chain.errors)


def test_geomorph_ends_match_the_levels():
    chain, _ = W.levels()
    d2 = W.scene(W.State())["switch"][2]
    at = W.scene(W.State(distance=d2 * 1.000001, geomorph=True))
    fine_v, fine_f = chain.levels[1]
    assert at["alpha"] == pytest.approx(1.0, abs=1e-5)
    assert np.array_equal(at["triangles"], fine_f)
    assert np.allclose(at["vertices"], fine_v, atol=1e-5)
    end = W.scene(W.State(distance=d2 * (1 + W.BAND) * 0.999999, geomorph=True))
    coarse_v, _ = chain.levels[2]
    # every geomorphed vertex sits (almost) on a vertex of the coarser level
    gap = np.linalg.norm(end["vertices"][:, None] - coarse_v[None], axis=2).min(axis=1)
    assert end["alpha"] == pytest.approx(0.0, abs=1e-5) and gap.max() < 1e-4
    past = W.scene(W.State(distance=d2 * (1 + W.BAND) * 1.01, geomorph=True))
    assert past["alpha"] is None and past["faces"] == 320


def test_popping_jumps_and_geomorph_does_not():
    d2 = W.scene(W.State())["switch"][2]
    before = W.scene(W.State(distance=d2 * 0.999, geomorph=False))
    after = W.scene(W.State(distance=d2 * 1.001, geomorph=False))
    assert (before["faces"], after["faces"]) == (640, 320)
    smooth = W.scene(W.State(distance=d2 * 1.001, geomorph=True))
    assert smooth["faces"] == 640
    # the geomorphed mesh just past the switch is almost the mesh just before it
    assert np.abs(smooth["vertices"] - before["vertices"]).max() < 0.01


def test_bad_state():
    with pytest.raises(ValueError, match="distance"):
        W.scene(W.State(distance=0.0))
    with pytest.raises(ValueError, match="tolerance"):
        W.scene(W.State(tolerance=0.0))


def _picture(ex):
    return ([p.vertices.copy() for p in ex.mesh.get_paths()], ex.title.get_text(),
            ex.info.value, ex.tolerance_line.get_ydata()[0], ex.now_line.get_xdata()[0])


def _differs(a, b):
    if len(a[0]) != len(b[0]) or a[1:] != b[1:]:
        return True
    return any(not np.allclose(x, y) for x, y in zip(a[0], b[0]))


def test_every_control_changes_the_picture():
    ex = W.LODExplorer()
    start = _picture(ex)
    ex.distance.value = 300.0
    moved = _picture(ex)
    assert _differs(start, moved) and len(moved[0]) < len(start[0])
    assert ex.now_line.get_xdata()[0] == pytest.approx(300.0, rel=1e-3)
    ex.distance.value = 95.0
    ex.geomorph.value = False
    popped = _picture(ex)
    assert _differs(start, popped) and "Popping" in ex.info.value
    ex.tolerance.value = 4.0
    tol = _picture(ex)
    assert _differs(popped, tol) and ex.tolerance_line.get_ydata()[0] == 4.0
    s = W.scene(W.State(distance=ex.state.distance, tolerance=4.0, geomorph=False))
    assert len(ex.mesh.get_paths()) == len(s["polygons"])
