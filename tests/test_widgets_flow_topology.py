"""Headless tests of the flow-topology explorer: its scene against closed forms typed here (the
linear field's single critical point at the origin with the trace and determinant the sliders
set, and its class by the eigenvalues from numpy; the Duffing field's zeros at 0 and +-sqrt(k);
the double gyre's centres) and its wiring (every control changes the drawn picture)."""
import io

import numpy as np
import pytest
from PIL import Image

import widget_harness as harness
from course_lib.widgets import flow_topology as W


def _class(tr, det):
    lam = np.linalg.eigvals(np.array([[tr / 2, 1.0], [tr * tr / 4 - det, tr / 2]]))
    if det < 0:
        return "saddle"
    if np.abs(lam.imag).max() > 1e-6:
        return "centre" if tr == 0 else ("attracting focus" if tr < 0 else "repelling focus")
    return "attracting node" if tr < 0 else "repelling node"


@pytest.mark.parametrize("tr,det", [(-1.0, 1.25), (-2.5, 1.0), (1.0, 2.0), (2.5, 1.0),
                                    (0.0, 1.5), (0.5, -1.0)])
def test_linear_field_classes_follow_the_sliders(tr, det):
    s = W.scene(W.State(preset="linear", p=tr, q=det))
    (cp,) = s["points"]
    assert np.allclose(cp.position, 0, atol=1e-12)
    assert cp.kind == _class(tr, det)
    td = s["trace_det"][cp.kind]
    assert np.allclose(td, [[tr, det]])
    if cp.kind == "saddle":
        assert len(s["unstable"]) and len(s["stable"])
    else:
        assert len(s["unstable"]) == 0


def test_duffing_and_double_gyre_points():
    k = 0.64
    s = W.scene(W.State(preset="saddle and two foci", p=k, q=0.5))
    xs = sorted(float(c.position[0]) for c in s["points"])
    assert np.allclose(xs, [-np.sqrt(k), 0, np.sqrt(k)], atol=0.02)
    assert s["by_class"]["saddle"].shape == (1, 2)
    g = W.scene(W.State(preset="double gyre", p=0.0, q=0.25))
    assert np.allclose(g["by_class"]["centre"], [[0.5, 0.5], [1.5, 0.5]])


def test_seed_line_is_the_gridded_streamline():
    from course_lib.scivis.topology import integrate_gridded, preset_field
    st = W.State(preset="linear", p=-1.0, q=1.25, method="euler", step=0.1,
                 seed=np.array([1.0, -0.5]))
    s = W.scene(st)
    ref = integrate_gridded(preset_field("linear", st.p, st.q, n=W.GRID), st.seed, 0.1,
                            W.SEED_STEPS, "euler")
    assert np.allclose(s["line"], ref)
    # one Euler step by hand: v = J p with J = [[-0.5, 1], [-1, -0.5]]
    assert np.allclose(s["line"][1], [1.0, -0.5] + 0.1 * np.array([-1.0, -0.75]))


def _picture(ex):
    buffer = io.BytesIO()
    buffer.write(ex.png(dpi=60))
    return np.asarray(Image.open(buffer).convert("RGB")).astype(int)


def _changed(a, b):
    return int((np.abs(a - b).sum(axis=-1) > 30).sum())


def test_every_control_changes_the_picture():
    ex = W.FlowTopologyExplorer()                 # the default state: each control matters
    assert ex.state.preset == "saddle and two foci"
    settings = [(ex.method, "euler"), (ex.step, 0.25), (ex.p, 0.5), (ex.q, 0.2),
                (ex.style, "streamlets"), (ex.sep_box, False), (ex.preset, "linear"),
                (ex.q, -0.5), (ex.p, 1.0), (ex.preset, "double gyre"), (ex.q, 0.45),
                (ex.p, 7.0)]
    for control, value in settings:
        before = _picture(ex)
        text = ex.info.value
        control.value = value
        assert _changed(before, _picture(ex)) > 20, (control.description, value)
        assert ex.info.value != text or control is ex.sep_box or control is ex.style


def test_sliders_relabel_with_the_preset():
    ex = W.FlowTopologyExplorer(W.State(preset="linear", p=-1.0, q=1.25))
    assert ex.p.description == "trace"
    ex.preset.value = "saddle and two foci"
    assert ex.p.description == "stiffness k" and ex.state.p == ex.p.value == 1.0
    assert "saddle" in ex.info.value
    ex.p.value = -0.4                             # one point left: a focus or a node
    assert len(W.scene(ex.state)["points"]) == 1


def test_dragging_the_seed_moves_the_streamline():
    ex = W.FlowTopologyExplorer()
    before = np.array(ex.line.get_xydata())
    harness.drag(ex.ax, tuple(ex.state.seed), (1.5, -1.0))
    assert np.allclose(ex.state.seed, [1.5, -1.0], atol=0.05)
    after = np.array(ex.line.get_xydata())
    assert not np.allclose(before[:5], after[:5])
    assert np.allclose(after[0], ex.state.seed)


def test_bad_state():
    with pytest.raises(ValueError, match="preset"):
        W.scene(W.State(preset="hurricane"))
    with pytest.raises(ValueError, match="method"):
        W.scene(W.State(method="rk3"))
