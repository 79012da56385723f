"""Headless tests of the relief explorer: its scene against independent computations (the flat
sphere's normal is the point itself; the bump normal at the picked point from tangents typed
here; the normal map equal to bump mapping on the plane up to 8-bit rounding; the displaced
sphere's outline grows while bump and normal maps keep the flat outline) and the wiring (every
control and a click change the picture)."""
import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")
from types import SimpleNamespace

import numpy as np
import pytest

from course_lib.texturing import relief as R
from course_lib.widgets import relief as W


def test_flat_sphere_normals_are_the_points():
    s = W.scene(W.State(surface="sphere", mode="flat"))
    c = (np.arange(W.SIZE) + 0.5) / W.SIZE
    x, y = np.meshgrid(W.EXTENT * (2 * c - 1), W.EXTENT * (2 * c - 1))
    inside = x ** 2 + y ** 2 < 1
    assert np.array_equal(s["mask"], inside)
    z = np.sqrt(1 - x[inside] ** 2 - y[inside] ** 2)
    assert np.allclose(s["normals"][inside], np.stack([x[inside], y[inside], z], -1), atol=1e-9)
    assert np.allclose(s["image"][~inside], 1.0)


def test_bump_normal_at_the_picked_point():
    st = W.State(surface="sphere", mode="bump", height_map="bumps", strength=0.8)
    s = W.scene(st)
    f = s["frame"]
    theta, phi = 2 * np.pi * (f["u"] - 0.5), np.pi * (f["v"] - 0.5)
    pu = 2 * np.pi * np.cos(phi) * np.array([np.cos(theta), 0, -np.sin(theta)])
    pv = np.pi * np.array([-np.sin(phi) * np.sin(theta), np.cos(phi), -np.sin(phi) * np.cos(theta)])
    # h = (1 - cos 12 pi u)(1 - cos 12 pi v) / 4 in closed form, differentiated by hand
    k, u, v = 6, f["u"], f["v"]
    hu = 0.25 * 2 * np.pi * k * np.sin(2 * np.pi * k * u) * (1 - np.cos(2 * np.pi * k * v))
    hv = 0.25 * 2 * np.pi * k * np.sin(2 * np.pi * k * v) * (1 - np.cos(2 * np.pi * k * u))
    a = s["amplitude"]
    n = np.cross(pu, pv)
    bent = n + (a * hu * np.cross(n, pv) - a * hv * np.cross(n, pu)) / np.linalg.norm(n)
    bent /= np.linalg.norm(bent)
    assert np.allclose(f["bent"], bent, atol=0.03)      # texel differences vs the closed form
    assert np.allclose(np.cross(f["t"], f["b"]), f["n"])


def test_normal_map_equals_bump_on_the_plane_up_to_8_bits():
    bump = W.scene(W.State(surface="plane", mode="bump", height_map="noise"))["normals"]
    nmap = W.scene(W.State(surface="plane", mode="normal map", height_map="noise"))["normals"]
    angle = np.degrees(np.arccos(np.clip(np.sum(bump * nmap, -1), -1, 1)))
    assert np.median(angle) < 0.5 and angle.max() < 3


def test_only_displacement_changes_the_outline():
    flat = W.scene(W.State(mode="flat"))["mask"]
    for mode in ("bump", "normal map"):
        assert np.array_equal(W.scene(W.State(mode=mode, strength=1))["mask"], flat)
    moved = W.scene(W.State(mode="displacement", strength=1))["mask"]
    assert moved.sum() > flat.sum() * 1.03
    assert (moved & ~flat).sum() > 100                    # bumps poke out of the outline
    r = np.linalg.norm(R.displace([[0, 0, 1.0]], [[0, 0, 1.0]], [1.0], 0.08))
    assert r == pytest.approx(1.08)


def test_controls_and_click_change_the_picture():
    ex = W.ReliefExplorer()
    changes = {ex.height_map: "bricks", ex.azimuth: 150.0, ex.elevation: 70.0,
               ex.surface: "plane", ex.mode: "flat"}
    for control, value in changes.items():
        before = np.array(ex.picture.get_array())
        control.value = value
        assert not np.allclose(before, ex.picture.get_array()), control.description
    ex.mode.value = "bump"
    before = np.array(ex.picture.get_array())
    ex.strength.value = 0.1
    assert not np.allclose(before, ex.picture.get_array())
    xy = np.array(ex.arrows["t"].get_xydata())
    ex._on_click(SimpleNamespace(inaxes=ex.ax, xdata=20.0, ydata=100.0))
    assert not np.allclose(xy, ex.arrows["t"].get_xydata())
    assert ex.current["pixel"] == (100, 20)
    assert [g["kind"] for g in ex.mouse_gestures()] == ["click"]
