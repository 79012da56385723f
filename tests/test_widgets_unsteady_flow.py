"""Headless tests of the unsteady-flow explorer: its scene against the closed forms of the
rotating uniform flow typed here (a straight streamline, circular pathline and streakline)
and the steady vortex (all three on the circle through the release point), and its wiring
(every control changes the drawn lines)."""
import math

import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
import numpy as np                                                          # noqa: E402
import pytest                                                               # noqa: E402

from course_lib.widgets import unsteady_flow as W                           # noqa: E402


def test_rotating_preset_against_closed_forms():
    state = W.State(preset="rotating", time=0.3, release_x=0.6, release_y=0.7)
    s = W.scene(state)
    t = 0.3 * 2 * math.pi
    r = np.array([-3 + 0.6 * 6, -3 + 0.7 * 6])
    assert np.allclose(s["release"], r)
    th = lambda u: u + math.pi                                              # noqa: E731
    # streamline: the straight line through r along (cos th(t), sin th(t))
    line = s["streamline"][np.isfinite(s["streamline"][:, 0])]
    d = np.array([math.cos(th(t)), math.sin(th(t))])
    rel = line - r
    assert np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0]).max() < 1e-9
    # pathline: r + (sin th - sin th0, cos th0 - cos th), th0 = pi
    times = np.linspace(0, t, len(s["pathline"]))
    exp = np.column_stack([r[0] + np.sin(th(times)) - math.sin(th(0)),
                           r[1] + math.cos(th(0)) - np.cos(th(times))])
    assert np.abs(s["pathline"] - exp).max() < 1e-7
    taus = np.linspace(0, t, len(s["streakline"]))
    exp_streak = np.column_stack([r[0] + math.sin(th(t)) - np.sin(th(taus)),
                                  r[1] + np.cos(th(taus)) - math.cos(th(t))])
    assert np.abs(s["streakline"] - exp_streak).max() < 1e-7
    # the timeline of a uniform flow is the starting row shifted by the particle's motion
    assert np.allclose(s["timeline"] - s["timeline_start"], exp[-1] - r, atol=1e-7)
    assert s["gap"] > 0.3


def test_steady_preset_lines_coincide():
    s = W.scene(W.State(preset="steady vortex", time=0.55, release_x=0.8, release_y=0.5))
    r = np.hypot(*s["release"])
    for key in ("pathline", "streakline"):
        assert np.abs(np.hypot(*s[key].T) - r).max() < 1e-5
    line = s["streamline"][np.isfinite(s["streamline"][:, 0])]
    assert np.abs(np.hypot(*line.T) - r).max() < 1e-5
    assert s["gap"] < 1e-3 and "coincide" in s["text"]
    with pytest.raises(ValueError, match="preset"):
        W.scene(W.State(preset="hurricane"))


def test_every_control_changes_the_picture():
    ex = W.UnsteadyFlowExplorer()

    def drawn():
        return [np.array(a.get_xydata()) for a in (ex.stream, ex.path, ex.streak, ex.row)]

    for control, value in ((ex.time, 0.8), (ex.release_x, 0.3), (ex.release_y, 0.2),
                           (ex.preset, "double gyre")):
        before, text = drawn(), ex.info.value
        control.value = value
        after = drawn()
        assert any(b.shape != a.shape or not np.allclose(b, a, equal_nan=True)
                   for b, a in zip(before, after)), control.description
        assert ex.info.value != text
    assert ex.ax.get_xlim() == (0.0, 2.0)
    expected = W.scene(ex.state)
    assert np.allclose(ex.path.get_xydata(), expected["pathline"])
