"""Headless tests of the BSP explorer: its scene against the worked example typed by hand and
an independent ray check of the order, and the wiring (every control changes the drawing)."""
import matplotlib

matplotlib.use("module://ipympl.backend_nbagg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from course_lib.widgets import bsp as W  # noqa: E402


def test_scene_of_the_lesson_plan_by_hand():
    s = W.scene(W.State(preset="lesson", eye_x=1, eye_y=4, step=5))
    assert s["order"] == ["d", "b1", "a", "c", "b2"]           # worked out in the lesson
    assert s["current"] == "b2" and s["painted"] == 5
    assert s["edges"] == [("b2", "c", "b"), ("b1", "d", "b"), ("a", "b2", "f"),
                          ("a", "b1", "f")[:2] + ("b",)]
    s = W.scene(W.State(preset="lesson", eye_x=4, eye_y=1, step=0))
    assert s["order"] == ["b2", "c", "a", "b1", "d"] and s["current"] is None
    assert s["line"] is None
    # from (4, 1) the eye is behind b1 (x > 2): painting b1 (step 4) takes the "behind" branch
    s = W.scene(W.State(preset="lesson", eye_x=4, eye_y=1, step=4))
    assert s["current"] == "b1" and "behind" in W.PSEUDOCODE[s["line"] - 1]
    s = W.scene(W.State(preset="lesson", eye_x=1, eye_y=4, step=3))
    assert s["current"] == "a" and "in front" in W.PSEUDOCODE[s["line"] - 1]


@pytest.mark.parametrize("preset", list(W.PRESETS))
@pytest.mark.parametrize("order", W.ORDERS)
def test_every_order_paints_nearer_fragments_later(preset, order):
    rng = np.random.default_rng(3)
    for ex, ey in rng.uniform(-1, 9, (3, 2)):
        s = W.scene(W.State(preset=preset, order=order, eye_x=ex, eye_y=ey))
        frags = s["fragments"]
        eye = np.array([ex, ey])
        for ang in np.linspace(0, 2 * np.pi, 240, endpoint=False) + 1e-3:
            d = np.array([np.cos(ang), np.sin(ang)])
            ts = []
            for p, q in frags:
                e = q - p
                den = d[0] * e[1] - d[1] * e[0]
                if abs(den) < 1e-12:
                    continue
                w = p - eye
                t = (w[0] * e[1] - w[1] * e[0]) / den
                u = (w[0] * d[1] - w[1] * d[0]) / den
                if t > 0 and 0 <= u <= 1:
                    ts.append(t)
            assert all(b <= a + 1e-9 for a, b in zip(ts, ts[1:]))


def test_orders_give_different_trees():
    trees = {o: W.scene(W.State(preset="room", order=o))["tree"] for o in W.ORDERS}
    assert len({t.describe() for t in trees.values()}) >= 3
    assert trees["fewest splits"].n_splits <= min(t.n_splits for t in trees.values())


def test_bad_state():
    with pytest.raises(ValueError, match="preset"):
        W.scene(W.State(preset="castle"))
    with pytest.raises(ValueError, match="order"):
        W.scene(W.State(order="random"))


def picture(ex):
    return ex.png(), ex.info.value


@pytest.mark.parametrize("control, value", [("preset", "lesson"), ("order", "reversed order"),
                                            ("eye_x", 6.0), ("eye_y", 0.0), ("step", 2)])
def test_every_control_changes_the_drawing(control, value):
    ex = W.BSPExplorer()
    before = picture(ex)
    getattr(ex, control).value = value
    after = picture(ex)
    assert before[0] != after[0] and before[1] != after[1]
    assert getattr(ex.state, control) == value
    s = W.scene(ex.state)
    drawn = [np.asarray(seg) for seg in ex.segments.get_segments()]
    assert all(np.allclose(a, b) for a, b in zip(drawn, s["fragments"]))
    assert ex.step.max == len(s["order"])


@pytest.mark.parametrize("order", W.ORDERS[1:])
def test_every_build_order_changes_the_default_picture(order):
    ex = W.BSPExplorer()
    before = ex.png()
    ex.order.value = order
    assert ex.png() != before


def test_step_range_follows_the_tree():
    ex = W.BSPExplorer()
    assert ex.step.max == 10
    ex.preset.value = "lesson"
    assert ex.step.max == 5 and ex.state.step == 4
    ex.preset.value = "pinwheel"
    n = len(W.scene(ex.state)["order"])
    assert ex.step.max == n > 5
    ex.step.value = n
    assert ex.nodes[0].get_text() and ex.state.step == n
