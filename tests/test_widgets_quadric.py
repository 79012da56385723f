"""Headless tests of the quadric explorer: its picture against an independent per-pixel
computation (numpy.roots of the quadratic typed here, the height test, the disk's plane and
radius), its f(t) against direct evaluation of x^T Q x along the ray, and the wiring (each
control changes the picture or the text)."""
import numpy as np
import pytest

from course_lib.widgets import quadric as W


def ray(row, col):
    return W._EYE, W._rays()[row, col]


def test_sphere_pixels_against_numpy_roots():
    st = W.State(kind="sphere", radius=0.9, height=2.0)
    s = W.scene(st)
    rng = np.random.default_rng(7)
    for row, col in rng.integers(0, W.SIZE, size=(60, 2)):
        o, d = ray(row, col)
        roots = np.roots([d @ d, 2 * o @ d, o @ o - 0.81])
        real = np.sort(roots[np.abs(roots.imag) < 1e-12].real)
        want = real[0] if len(real) and real[0] > 0 else np.inf
        assert np.isclose(s["t"][row, col], want) or (np.isinf(want) and
                                                        np.isinf(s["t"][row, col]))


def test_cylinder_height_test_and_curve():
    st = W.State(kind="cylinder", radius=0.6, height=0.5)
    s = W.scene(st)
    for row, col in ((48, 48), (30, 48), (70, 40), (60, 60)):
        o, d = ray(row, col)
        roots = np.roots([d[0]**2 + d[1]**2, 2 * (o[0] * d[0] + o[1] * d[1]),
                          o[0]**2 + o[1]**2 - 0.36])
        real = np.sort(roots[np.abs(roots.imag) < 1e-12].real)
        ok = [t for t in real if t > 0 and abs(o[2] + t * d[2]) <= 0.5]
        want = ok[0] if ok else np.inf
        got = s["t"][row, col]
        assert (np.isinf(want) and np.isinf(got)) or np.isclose(got, want)
    o, d = ray(st.row, st.col)
    a, b, c = s["coefficients"]
    f = [(o + t * d)[0]**2 + (o + t * d)[1]**2 - 0.36 for t in s["t_samples"]]
    assert np.allclose(a * s["t_samples"]**2 + b * s["t_samples"] + c, f)
    assert np.all(np.sign(s["curve"]) == np.sign(np.round(f, 14)))
    assert np.isclose(np.abs(s["curve"]).max(), 1.0)


def test_disk_hits_only_within_the_radius():
    s = W.scene(W.State(kind="disk", radius=0.7))
    n = np.array([0.0, 0.35, 1.0]) / np.hypot(0.35, 1.0)
    for row in range(0, W.SIZE, 7):
        for col in range(0, W.SIZE, 7):
            o, d = ray(row, col)
            t = -(o @ n) / (d @ n)
            inside = t > 0 and np.linalg.norm(o + t * d) <= 0.7
            assert np.isfinite(s["t"][row, col]) == inside


def test_picture_colours_and_errors():
    s = W.scene(W.State(kind="cylinder", height=0.8))
    img = s["image"]
    assert img.shape == (W.SIZE, W.SIZE, 3) and img.min() >= 0 and img.max() <= 1
    miss = np.isinf(s["t"])
    assert np.allclose(img[miss & (np.abs(np.arange(W.SIZE)[:, None] - 48) > 5)],
                       W._BACKGROUND)
    # the open top shows the inside (orange): red channel above blue somewhere
    hit = img[~miss]
    assert (hit[:, 0] > hit[:, 2]).any() and (hit[:, 2] > hit[:, 0]).any()
    with pytest.raises(ValueError, match="kind"):
        W.scene(W.State(kind="torus"))
    with pytest.raises(ValueError, match="row"):
        W.scene(W.State(row=200))


def test_each_control_changes_the_picture():
    ex = W.QuadricExplorer()
    for control, value in ((ex.kind, "cone"), (ex.kind, "hyperboloid1"), (ex.radius, 1.0),
                           (ex.shape, 1.5), (ex.height, 0.4), (ex.row, 30), (ex.col, 60)):
        image = np.array(ex.image.get_array()).copy()
        curve = np.array(ex.curve.get_ydata()).copy()
        text = ex.info.value
        control.value = value
        changed = (not np.allclose(image, ex.image.get_array())
                   or not np.allclose(curve, ex.curve.get_ydata()))
        assert changed and ex.info.value != text, control.description
    s = W.scene(ex.state)
    assert np.allclose(ex.image.get_array(), s["image"])
    assert np.allclose(ex.curve.get_ydata(), s["curve"])
