"""Headless tests of chapter 3's explorers: the pure scenes against independent maths, and the
wiring (a slider change moves the drawn artists as a student's drag would)."""
import base64

import numpy as np
import pytest
from scipy.spatial.transform import Rotation, Slerp

from course_lib.widgets import composer, gimbal, quaternion, slerp


def scipy_quat(q):
    """Our scalar-first quaternion as a scipy Rotation (scipy is scalar-last)."""
    return Rotation.from_quat(np.asarray(q)[..., [1, 2, 3, 0]])


# --- quaternion explorer ---------------------------------------------------------------------

@pytest.mark.parametrize("az, el, angle", [(-30, 60, 50), (0, 90, 90), (120, -45, -200),
                                           (10, 0, 360), (45, 30, 0)])
def test_quaternion_scene_matches_scipy(az, el, angle):
    s = quaternion.scene(quaternion.State(az, el, angle))
    a, e = np.radians(az), np.radians(el)
    axis = np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    ref = Rotation.from_rotvec(axis * np.radians(angle))
    assert np.allclose(s["axis"], axis)
    assert np.allclose(s["matrix"], ref.as_matrix(), atol=1e-12)
    assert np.allclose(s["vertices"], ref.apply(quaternion.F_VERTICES), atol=1e-12)
    # q itself: scalar first, half angle
    assert np.isclose(s["q"][0], np.cos(np.radians(angle) / 2))
    assert np.allclose(s["q"][1:], np.sin(np.radians(angle) / 2) * axis)
    # the arc ends where the reference vector ends up after the rotation
    start, end = s["arc"][1] - 0.9 * axis, s["arc"][-1] - 0.9 * axis
    assert np.allclose(ref.apply(start), end, atol=1e-12)


def test_quaternion_readout_names_the_components():
    s = quaternion.scene(quaternion.State(0, 90, 90))          # 90 degrees about z
    assert "0.707" in s["text"] and "45" in s["text"]
    assert r"\begin{matrix}" in s["text"]          # R_q, with room inside its brackets


def test_quaternion_slider_moves_the_drawing():
    ex = quaternion.QuaternionExplorer()
    ex.fig.canvas.draw()
    x_axis_before = np.array(ex.frame[0].get_data_3d())
    ex.angle.value = 170.0                                     # what a drag does
    x_axis_after = np.array(ex.frame[0].get_data_3d())
    assert not np.allclose(x_axis_before, x_axis_after)
    expected = quaternion.scene(quaternion.State(-30, 60, 170.0))["matrix"][:, 0]
    assert np.allclose(x_axis_after[:, 1], expected)
    assert "170" in ex.info.value
    ex.azimuth.value = 90.0
    ex.elevation.value = 0.0
    assert np.allclose(np.array(ex.axis_line.get_data_3d())[:, 1], [0, 1.6, 0], atol=1e-12)


def test_explorer_display_has_summary_widget_and_picture():
    ex = quaternion.QuaternionExplorer()
    bundle = ex._repr_mimebundle_()
    assert bundle["text/plain"].startswith("Quaternion explorer")
    assert "application/vnd.jupyter.widget-view+json" in bundle
    png = base64.b64decode(bundle["image/png"])
    assert png[:8] == b"\x89PNG\r\n\x1a\n"


def test_snapshot_includes_the_moving_artists():
    """Blitted artists are 'animated', which savefig skips unless the blitter re-enables them."""
    ex = quaternion.QuaternionExplorer()
    first = ex.png()
    ex.angle.value = -120.0
    second = ex.png()
    assert first != second


# --- slerp explorer --------------------------------------------------------------------------

@pytest.mark.parametrize("preset", list(slerp.PRESETS))
def test_slerp_path_matches_scipy(preset):
    start, end = slerp.PRESETS[preset]
    key = Rotation.from_euler("ZYX", [start, end], degrees=True)
    t, q_slerp, q_euler = slerp.paths(preset)
    ref = Slerp([0, 1], key)(t)
    assert np.allclose(Rotation.from_quat(q_slerp[:, [1, 2, 3, 0]]).as_matrix(), ref.as_matrix(),
                       atol=1e-9)
    ref_euler = Rotation.from_euler("ZYX", start + t[:, None] * (np.subtract(end, start)),
                                    degrees=True)
    assert np.allclose(scipy_quat(q_euler).as_matrix(), ref_euler.as_matrix(), atol=1e-9)


def test_slerp_turns_at_constant_speed_along_the_shortest_way():
    s = slerp.scene(slerp.State("tilt and turn", 0.3))
    start, end = slerp.PRESETS["tilt and turn"]
    key = Rotation.from_euler("ZYX", [start, end], degrees=True)
    direct = np.degrees((key[0].inv() * key[1]).magnitude())
    assert np.isclose(s["direct"], direct)
    assert np.allclose(s["slerp_speed"], direct, rtol=1e-6)
    assert np.isclose(s["turned"]["slerp"], direct, rtol=1e-6)
    assert s["turned"]["euler"] > direct + 20            # the Euler path is longer...
    assert np.ptp(s["euler_speed"]) > 50                  # ...and its speed is not constant


def test_slerp_same_end_orientation_does_not_move():
    s = slerp.scene(slerp.State("same end, different angles", 0.5))
    assert s["direct"] < 1e-6 and s["turned"]["slerp"] < 1e-6
    assert s["turned"]["euler"] > 180


def test_slerp_widget_t_and_preset():
    ex = slerp.SlerpExplorer()
    ex.fig.canvas.draw()
    before = np.array(ex.slerp_tip.get_data_3d())
    ex.t.value = 0.9
    after = np.array(ex.slerp_tip.get_data_3d())
    assert not np.allclose(before, after)
    assert np.allclose(after[:, 0], slerp.scene(slerp.State("tilt and turn", 0.9))["slerp_tip"])
    assert list(ex.t_line.get_xdata()) == [0.9, 0.9]
    ylim = ex.speed_ax.get_ylim()
    ex.preset.value = "same end, different angles"
    assert ex.speed_ax.get_ylim() != ylim                 # rescaled for the new speeds
    assert "0°" in ex.info.value


# --- gimbal explorer -------------------------------------------------------------------------

@pytest.mark.parametrize("pitch", [-90, -60, 0, 35, 89, 90])
def test_gimbal_determinant_is_minus_cos_pitch(pitch):
    s = gimbal.scene(gimbal.State(17, pitch, -40))
    assert np.isclose(s["det"], -np.cos(np.radians(pitch)), atol=1e-12)
    assert np.isclose(s["axis_angle"], 90 - abs(pitch), atol=1e-6)
    assert s["locked"] == (abs(pitch) == 90)


def test_gimbal_orientation_matches_scipy_euler():
    s = gimbal.scene(gimbal.State(-25, 35, 25))
    ref = Rotation.from_euler("ZYX", [-25, 35, 25], degrees=True)
    assert np.allclose(s["vertices"], 0.75 * ref.apply(quaternion.F_VERTICES), atol=1e-12)


def test_gimbal_lock_loses_the_axis_perpendicular_to_yaw_and_pitch():
    s = gimbal.scene(gimbal.State(30, 90, 10))
    yaw_axis, pitch_axis, roll_axis = s["pivots"]
    assert np.allclose(np.cross(yaw_axis, roll_axis), 0, atol=1e-12)   # roll axis along z
    lost = s["lost_axis"]
    assert np.isclose(lost @ yaw_axis, 0) and np.isclose(lost @ pitch_axis, 0)
    # no combination of the three pivot axes has a component along the lost axis
    assert np.allclose(s["pivots"] @ lost, 0, atol=1e-12)
    assert "Gimbal lock" in s["text"]


def test_gimbal_widget_shows_and_hides_the_lost_axis():
    ex = gimbal.GimbalExplorer()
    assert len(ex.lost.get_data_3d()[0]) == 0
    ex.pitch.value = 90
    assert len(ex.lost.get_data_3d()[0]) == 2
    assert "Gimbal lock" in ex.info.value
    ex.pitch.value = 10
    assert len(ex.lost.get_data_3d()[0]) == 0


# --- transformation composer ----------------------------------------------------------------

def rot(deg):
    c, s = np.cos(np.radians(deg)), np.sin(np.radians(deg))
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def trans(dx, dy):
    return np.array([[1, 0, dx], [0, 1, dy], [0, 0, 1.0]])


def test_composer_default_is_rotation_after_translation():
    s = composer.scene(composer.State())          # translate (2, 0.5), then rotate 45 degrees
    assert np.allclose(s["matrix"], rot(45) @ trans(2, 0.5))
    assert np.allclose(s["other_matrix"], trans(2, 0.5) @ rot(45))
    assert not s["commute"]
    f = np.column_stack([composer.SHAPE, np.ones(len(composer.SHAPE))])
    assert np.allclose(s["steps"][0], (f @ trans(2, 0.5).T)[:, :2])
    assert np.allclose(s["steps"][-1], (f @ (rot(45) @ trans(2, 0.5)).T)[:, :2])
    assert r"R(45°)\,T(2, 0.5)" in s["text"]


def test_composer_reverse_order():
    s = composer.scene(composer.State(reverse=True))
    assert np.allclose(s["matrix"], trans(2, 0.5) @ rot(45))


def test_composer_commuting_operations_are_recognised():
    ops = [composer.Operation("rotate", (30,)), composer.Operation("rotate", (50,))]
    s = composer.scene(composer.State(ops))
    assert s["commute"] and np.allclose(s["matrix"], rot(80))
    assert "commute" in s["text"]
    empty = composer.scene(composer.State([]))
    assert np.allclose(empty["matrix"], np.eye(3)) and empty["steps"] == []


@pytest.mark.parametrize("kind, params, expected", [
    ("scale", (2, -1), np.diag([2.0, -1.0, 1.0])),
    ("shear x", (0.5,), np.array([[1, 0.5, 0], [0, 1, 0], [0, 0, 1.0]])),
    ("shear y", (0.5,), np.array([[1, 0, 0], [0.5, 1, 0], [0, 0, 1.0]])),
    ("mirror about x", (), np.diag([1.0, -1.0, 1.0])),
    ("mirror about y", (), np.diag([-1.0, 1.0, 1.0])),
    ("rotate about point", (90, 1, 1), trans(1, 1) @ rot(90) @ trans(-1, -1)),
])
def test_composer_operation_matrices(kind, params, expected):
    assert np.allclose(composer.Operation(kind, params).matrix(), expected)


def test_composer_rejects_bad_operations():
    with pytest.raises(ValueError, match="kind must be one of"):
        composer.Operation("twist")
    with pytest.raises(ValueError, match="takes 2 parameters"):
        composer.Operation("translate", (1,))


def test_composer_widget_editing():
    ex = composer.ComposerExplorer()
    ex.fig.canvas.draw()
    result_before = ex.result.get_xy().copy()
    ex.rows[1].sliders[0].value = 90                       # rotate by 90 instead of 45
    assert np.allclose(ex.state.operations[1].params, (90,))
    f = np.column_stack([composer.SHAPE, np.ones(len(composer.SHAPE))])
    assert np.allclose(ex.result.get_xy(), (f @ (rot(90) @ trans(2, 0.5)).T)[:, :2])
    assert not np.allclose(ex.result.get_xy(), result_before)
    ex.reverse.value = True
    assert np.allclose(ex.result.get_xy(), (f @ (trans(2, 0.5) @ rot(90)).T)[:, :2])
    ex.reverse.value = False
    ex.add("scale", (2, 1))
    assert [op.kind for op in ex.state.operations] == ["translate", "rotate", "scale"]
    assert len(ex.rows_box.children) == 3
    ex.move_up(ex.rows[2])
    assert [op.kind for op in ex.state.operations] == ["translate", "scale", "rotate"]
    ex.rows[0].kind.value = "shear x"                      # sliders switch to the new kind
    assert ex.state.operations[0] == composer.Operation("shear x", (0.5,))
    assert ex.rows[0].sliders[1].layout.display == "none"
    ex.remove(ex.rows[0])
    assert [op.kind for op in ex.state.operations] == ["scale", "rotate"]
    for _ in range(5):
        ex.add()
    assert len(ex.rows) == composer.MAX_OPERATIONS and ex.add_button.disabled


def test_the_frames_sent_to_the_browser_are_whole_lossless_pngs_of_the_canvas():
    """draw.figure encodes ipympl's frames faster (zlib level 1) and whole (never only the
    pixels that changed since the last frame, which the browser may have dropped): every frame
    is exactly the canvas, also the second one after a small change."""
    import io

    from PIL import Image

    explorer = quaternion.QuaternionExplorer()
    canvas = explorer.fig.canvas
    canvas.draw()
    for angle in (120.0, 121.0):                          # the second frame differs a little
        explorer.angle.value = angle
        canvas._png_is_old = True
        png = canvas.get_diff_image()
        frame = np.asarray(Image.open(io.BytesIO(png)).convert("RGBA"))
        assert np.array_equal(frame, np.asarray(canvas.get_renderer().buffer_rgba()))
        assert canvas._current_image_mode == "full"
    from PIL import Image as again
    assert again.Image.save.__name__ == "save"          # PIL is left as it was


def test_composer_changes_a_sliders_range_and_value_in_one_message():
    """Switching a row to another operation sends each slider's new range and value together:
    a value that reached the browser before its new range was clipped there to the old one
    and sent back (choosing "rotate" after a shear gave 2 degrees instead of 45)."""
    ex = composer.ComposerExplorer()
    row = ex.rows[0]
    row.kind.value = "shear x"                          # slider 0: a in [-2, 2]
    sent = []
    for slider in row.sliders:
        slider._send = lambda msg, buffers=None, s=slider: sent.append((s, msg))
    row.kind.value = "rotate"                            # slider 0: θ in [-180, 180], 45
    updates = [msg["state"] for s, msg in sent if s is row.sliders[0]
               and msg.get("method") == "update"]
    with_value = [u for u in updates if "value" in u]
    assert len(with_value) == 1
    assert with_value[0]["value"] == 45.0
    assert with_value[0]["min"] == -180 and with_value[0]["max"] == 180
    assert row.sliders[0].value == 45.0


def test_composer_hides_move_up_on_the_first_operation():
    ex = composer.ComposerExplorer()
    assert [r.up.layout.visibility for r in ex.rows] == ["hidden", "visible"]
    ex.move_up(ex.rows[1])
    assert [r.up.layout.visibility for r in ex.rows] == ["hidden", "visible"]
    ex.add("scale")
    assert [r.up.layout.visibility for r in ex.rows] == ["hidden", "visible", "visible"]
    ex.remove(ex.rows[0])
    assert [r.up.layout.visibility for r in ex.rows] == ["hidden", "visible"]
