"""Headless tests of the clip-before-or-after-the-divide explorer
(course_lib/widgets/homogeneous_clip.py): its scene against sampling with the typed inequalities
-w <= x, z <= w (clip space) and |x|, |z| <= 1 (NDC), and its wiring."""
import matplotlib

matplotlib.use("module://ipympl.backend_nbagg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from course_lib.widgets import homogeneous_clip as hc  # noqa: E402

T = np.linspace(0, 1, 40001)


def sampled(points, inside):
    ok = inside(points)
    if not ok.any():
        return None
    idx = np.flatnonzero(ok)
    assert np.all(np.diff(idx) == 1)                 # one piece (convex region, a line)
    return points[[idx[0], idx[-1]]]


@pytest.mark.parametrize("a_x, b_x, b_z", [(1.5, -3.0, 1.5), (0.0, 2.0, 2.5), (-1.0, 4.0, -5.0),
                                           (2.0, -4.5, 3.0), (0.5, 0.3, -7.5)])
def test_both_routes_against_sampling(a_x, b_x, b_z):
    s = hc.scene(hc.State(a_x=a_x, b_x=b_x, b_z=b_z))
    a, b = s["a"], s["b"]
    world = a + T[:, None] * (b - a)
    h = np.column_stack([world, np.ones(len(T))]) @ hc.CAMERA.T
    expected = sampled(world, lambda p: (np.abs(h[:, 0]) <= h[:, 3])
                       & (np.abs(h[:, 2]) <= h[:, 3]))
    assert (expected is None) == (s["clip_eye"] is None)
    if expected is not None:
        assert np.allclose(s["clip_eye"], expected, atol=1e-3)
    ah, bh = hc.CAMERA @ [*a, 1], hc.CAMERA @ [*b, 1]
    na, nb = ah[:3] / ah[3], bh[:3] / bh[3]
    ndc = na + T[:, None] * (nb - na)
    wrong = sampled(ndc, lambda p: np.all(np.abs(p) <= 1, axis=1))
    assert (wrong is None) == (s["divide_ndc"] is None)
    if wrong is not None:
        assert np.allclose(s["divide_ndc"], wrong, atol=1e-3 * np.abs(nb - na).max() + 1e-9)
    assert s["crosses"] == (b_z > 0)
    if b_z < 0 and expected is not None:               # in front of the eye: the routes agree
        assert np.allclose(s["clip_ndc"], s["divide_ndc"])


def test_divide_first_keeps_points_off_the_segment():
    s = hc.scene(hc.State(a_x=1.5, b_x=-3.0, b_z=1.5))
    a, b = s["a"], s["b"]
    for p in s["divide_eye"]:
        t = np.dot(p - a, b - a) / np.dot(b - a, b - a)
        assert np.allclose(a + t * (b - a), p)        # on the segment's line ...
    ts = [np.dot(p - a, b - a) / np.dot(b - a, b - a) for p in s["divide_eye"]]
    assert max(ts) <= 1e-9 and min(ts) < -0.3         # ... but beyond A, not on the segment


def test_b_on_the_eye_plane_is_not_divided():
    s = hc.scene(hc.State(b_z=0.0))
    assert s["divide_ndc"] is None and np.isnan(s["ndc_ends"][1]).all()
    assert s["clip_eye"] is not None and "cannot be divided" in s["text"]


def test_bad_route():
    with pytest.raises(ValueError, match="route must be one of"):
        hc.scene(hc.State(route="both"))


def test_every_control_changes_the_picture():
    ex = hc.HomogeneousClipExplorer()

    def picture():
        lines = (ex.segment, ex.clip_eye, ex.divide_eye, ex.images, ex.chord, ex.clip_ndc,
                 ex.divide_ndc)
        return (np.concatenate([np.ravel(np.asarray(line.get_xydata(), float)) for line in lines]
                               + [[line.get_linewidth() for line in lines]]), ex.info.value)

    for control, value in ((ex.route, "divide first"), (ex.a_x, 0.4), (ex.b_x, 1.0),
                           (ex.b_z, -4.0), (ex.b_z, 2.0), (ex.route, "clip space")):
        before = picture()
        control.value = value
        after = picture()
        assert after[1] != before[1]
        assert after[0].shape != before[0].shape or not np.allclose(after[0], before[0],
                                                                   equal_nan=True)
    ex.route.value = "divide first"
    assert ex.divide_eye.get_linewidth() > ex.clip_eye.get_linewidth()
