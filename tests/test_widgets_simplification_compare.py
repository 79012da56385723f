"""Headless tests of the simplification comparison explorer: its scene against the library
calls made here independently (and trimesh's closest points for the face colours), and its
wiring (the slider swaps the meshes and changes the picture and the text)."""
import numpy as np
import pytest

from course_lib.mesh import simplify_qem
from course_lib.widgets import simplification_compare as W
from course_lib.widgets.simplification import bumpy_sphere


def test_scene_meshes_are_the_three_methods_at_the_face_count():
    v, f = bumpy_sphere(3)
    s = W.scene(W.State(faces=300))
    qem = s["methods"]["QEM"]
    ref_v, ref_f, _ = simplify_qem(v, f, 300)
    assert np.array_equal(qem["faces"], ref_f) and np.allclose(qem["vertices"], ref_v)
    assert abs(len(s["methods"]["decimation"]["faces"]) - 300) <= 1
    # decimation keeps original vertices; clustering lands near the target (grid steps)
    dv = s["methods"]["decimation"]["vertices"]
    assert all((np.abs(v - p).max(axis=1) == 0).any() for p in dv)
    assert 0.6 < len(s["methods"]["clustering"]["faces"]) / 300 < 1.4
    for m in W.METHODS:
        assert f"<b>{m}</b>" in s["text"]


def test_face_errors_against_trimesh():
    trimesh = pytest.importorskip("trimesh")
    v, f = bumpy_sphere(3)
    s = W.scene(W.State(faces=200))
    original = trimesh.Trimesh(v, f, process=False)
    for m in W.METHODS:
        r = s["methods"][m]
        centre = r["vertices"][r["faces"]].mean(axis=1)
        _, ref, _ = trimesh.proximity.closest_point(original, centre)
        assert np.allclose(r["face_error"], ref, atol=1e-6)
        d = r["distance"]
        assert d.hausdorff >= r["face_error"].max() - 1e-9 or d.hausdorff > 0
        assert 0 < d.rms <= d.hausdorff


def test_qem_error_is_the_smallest_at_low_counts():
    s = W.scene(W.State(faces=120))
    rms = {m: s["methods"][m]["distance"].rms for m in W.METHODS}
    assert rms["QEM"] < rms["clustering"] and rms["QEM"] < rms["decimation"]


def test_bad_face_count():
    with pytest.raises(ValueError, match="faces must be one of"):
        W.scene(W.State(faces=333))


def test_slider_changes_picture_and_text():
    ex = W.SimplificationComparisonExplorer()
    before, text = ex.frame().copy(), ex.info.value
    ex.faces.value = 120
    assert ex.polys["QEM"].n_cells == 120
    assert np.array_equal(ex.frame(), ex.plotter.screenshot(return_img=True))
    assert not np.array_equal(ex.frame(), before) and ex.info.value != text
    assert np.allclose(ex.polys["decimation"].cell_data["error"],
                       W.scene(W.State(faces=120))["methods"]["decimation"]["face_error"])
