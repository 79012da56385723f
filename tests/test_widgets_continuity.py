"""Headless tests of the continuity explorer: its scene against formulas typed here (the C1
mirror rule, the C2 rule, equal curvatures at G2 computed from the control points by the end
formula kappa(0) = (n-1)/n |d0 x d1| / |d0|^3), and its wiring (mouse drags, toggles, comb)."""
import matplotlib

matplotlib.use("module://ipympl.backend_nbagg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from course_lib.widgets import continuity as W  # noqa: E402
from widget_harness import drag  # noqa: E402


def _end_kappa(p):
    """Curvature at t = 1 of a cubic from its last three points (typed here)."""
    d0, d1 = p[3] - p[2], p[2] - p[1]
    return 2 / 3 * abs(d0[0] * d1[1] - d0[1] * d1[0]) / np.linalg.norm(d0) ** 3


def _start_kappa(q):
    d0, d1 = q[1] - q[0], q[2] - q[1]
    return 2 / 3 * abs(d0[0] * d1[1] - d0[1] * d1[0]) / np.linalg.norm(d0) ** 3


def test_c1_and_c2_rules():
    s = W.scene(W.State(continuity="C1"))
    P, Q = s["P"], s["Q"]
    assert np.allclose(Q[0], P[3]) and np.allclose(Q[1], 2 * P[3] - P[2])
    s = W.scene(W.State(continuity="C2"))
    P, Q = s["P"], s["Q"]
    assert np.allclose(Q[2], 2 * Q[1] - Q[0] + P[3] - 2 * P[2] + P[1])
    assert (s["join"].C, s["join"].G) == (2, 2)


@pytest.mark.parametrize("mode, c, g", [("C0", 0, 0), ("G1", 0, 1), ("C1", 1, 1),
                                        ("G2", 0, 2), ("C2", 2, 2)])
def test_each_mode_reaches_its_continuity(mode, c, g):
    state = W.State(Q=np.array([[3.0, 2.0], [3.0, 1.0], [5.0, 3.0], [6.0, 1.0]]), continuity=mode)
    s = W.scene(state)
    assert s["join"].G >= g and s["join"].C >= c
    if mode in ("G2",):
        assert _start_kappa(s["Q"]) == pytest.approx(_end_kappa(s["P"]))
    if mode == "G1":
        assert _start_kappa(s["Q"]) != pytest.approx(_end_kappa(s["P"]))
    assert s["fixed"] == {"C0": 1, "G1": 2, "C1": 2, "G2": 3, "C2": 3}[mode]


def test_comb_teeth_have_length_scale_times_curvature():
    s = W.scene(W.State(comb_scale=2.0))
    teeth = s["teeth_p"].reshape(-1, 3, 2)
    lengths = np.linalg.norm(teeth[:, 1] - teeth[:, 0], axis=1)
    assert lengths[-1] == pytest.approx(2.0 * _end_kappa(s["P"]))
    assert np.allclose(teeth[:, 1], s["tips_p"])


def test_free_mode_leaves_q_alone_and_reports_no_join():
    q = np.array([[4.0, 4.0], [5.0, 5.0], [5.5, 4.0], [6.0, 3.0]])
    s = W.scene(W.State(Q=q, continuity="free"))
    assert np.array_equal(s["Q"], q)
    assert s["join"].C == -1 and "do not meet" in s["text"]


def test_toggle_moves_the_constrained_points_and_changes_the_text():
    ex = W.ContinuityExplorer()
    before = np.array(ex.curve_q.get_xydata())
    text = ex.info.value
    ex.mode.value = "C2"
    assert not np.allclose(ex.curve_q.get_xydata(), before)
    assert ex.info.value != text and "C2" in ex.info.value
    assert len(ex.fixed.get_xydata()) == 3


def test_comb_controls_change_the_picture():
    ex = W.ContinuityExplorer()
    teeth = np.array(ex.comb_p.get_xydata())
    ex.scale.value = 2.5
    assert not np.allclose(np.nan_to_num(ex.comb_p.get_xydata()), np.nan_to_num(teeth))
    ex.comb_box.value = False
    assert len(ex.comb_p.get_xydata()) == 0 and len(ex.tips_q.get_xydata()) == 0


def test_dragging_p2_makes_the_constrained_q1_follow():
    ex = W.ContinuityExplorer()
    ex.mode.value = "C1"
    p2 = ex.state.P[2].copy()
    drag(ex.ax, p2, p2 + [0.5, 0.3])
    assert np.allclose(ex.state.P[2], p2 + [0.5, 0.3])
    assert np.allclose(ex.state.Q[1], 2 * ex.state.P[3] - ex.state.P[2])
    assert np.allclose(ex.drag.points[5], ex.state.Q[1])          # the handle followed too
    assert np.allclose(ex.poly_q.get_xydata()[1], ex.state.Q[1])


def test_dragging_q1_along_g1_keeps_the_direction():
    ex = W.ContinuityExplorer()
    ex.mode.value = "G1"
    q1 = ex.state.Q[1].copy()
    drag(ex.ax, q1, q1 + [0.6, 0.2])
    P, Q = ex.state.P, ex.state.Q
    t_p = (P[3] - P[2]) / np.linalg.norm(P[3] - P[2])
    t_q = (Q[1] - Q[0]) / np.linalg.norm(Q[1] - Q[0])
    assert np.allclose(t_p, t_q)
    assert not np.allclose(Q[1], q1)
