"""Headless tests of the two-part mapping explorer: the scene against the library and closed
forms computed here, and the wiring (every control changes the picture or, where it
legitimately cannot, the text)."""
import numpy as np

from course_lib.texturing import nearest_sample, spherical_map, texture_matrix
from course_lib.widgets import two_part as tp


def test_sphere_on_sphere_is_the_spherical_map_with_the_texture_matrix():
    state = tp.State(object="sphere", surface="sphere", method="normal", tiling=2.0,
                     offset_u=0.25, rotation_deg=90.0)
    s = tp.scene(state)
    p, n, mask, shade = tp.geometry("sphere")
    assert np.allclose(np.linalg.norm(p, axis=1), 0.8)          # the hits lie on the sphere
    u, v = spherical_map(p)
    assert np.allclose(s["u"], u) and np.allclose(s["v"], v)
    # M typed here: (u, v) -> rotate 90 deg about the centre (1 - v, u), scale 2, add (0.25, 0)
    u2, v2 = 2 * (1 - v) + 0.25, 2 * u
    assert np.allclose(s["matrix"] @ np.stack([u, v, np.ones_like(u)]), [u2, v2, np.ones_like(u)])
    colour = nearest_sample(tp.labelled_texture(), u2, v2) * shade[:, None]
    assert np.allclose(s["image"][mask], colour, atol=1e-12)
    assert np.allclose(s["image"][~mask], tp.BACKGROUND)


def test_side_view_is_the_texture_seen_through_the_matrix():
    s = tp.scene(tp.State(offset_u=0.5))
    tex = tp.labelled_texture()
    assert np.array_equal(s["texture"], np.roll(tex, -32, axis=1))     # u + 1/2: half a width
    assert np.allclose(s["matrix"], texture_matrix(offset=(0.5, 0)))


def test_normal_and_centroid_agree_on_the_sphere_and_the_text_says_so():
    a = tp.scene(tp.State(object="sphere", method="normal", surface="box"))
    b = tp.scene(tp.State(object="sphere", method="centroid", surface="box"))
    assert np.allclose(a["image"], b["image"])
    assert a["text"] != b["text"] and "same picture" in b["text"]
    c = tp.scene(tp.State(object="torus", method="normal", surface="box"))
    d = tp.scene(tp.State(object="torus", method="centroid", surface="box"))
    assert not np.allclose(c["image"], d["image"])


def test_cylinder_misses_along_its_axis():
    s = tp.scene(tp.State(object="cube", surface="cylinder", method="normal"))
    assert s["misses"] > 100 and "magenta" in s["text"]
    assert tp.scene(tp.State(object="cube", surface="box"))["misses"] == 0


def test_wiring_every_control_changes_the_picture():
    ex = tp.TwoPartMappingExplorer()
    for control, value in ((ex.object, "sphere"), (ex.object, "cube"), (ex.surface, "sphere"),
                           (ex.surface, "box"), (ex.surface, "plane"), (ex.surface, "cylinder"),
                           (ex.method, "reflected"), (ex.method, "centroid"),
                           (ex.method, "intermediate_normal"), (ex.method, "normal"),
                           (ex.tiling, 2.0), (ex.offset_u, 0.3), (ex.offset_v, 0.4),
                           (ex.rotation, 45.0)):
        before = np.array(ex.images[0].get_array())
        text = ex.info.value
        control.value = value
        after = np.array(ex.images[0].get_array())
        assert not np.array_equal(before, after) or text != ex.info.value, (control, value)
        assert not np.array_equal(before, after), (control.description, value)
    expected = tp.scene(tp.State(object="cube", surface="cylinder", method="normal", tiling=2.0,
                                 offset_u=0.3, offset_v=0.4, rotation_deg=45.0))
    assert np.allclose(ex.images[0].get_array(), expected["image"])
    assert np.allclose(ex.images[1].get_array(), expected["texture"])
