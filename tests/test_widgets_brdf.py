"""Headless tests of the BRDF explorer: its scene against formulas typed here (the Lambert value
rho/pi, the Phong lobe (n+2)/(2 pi) cos^n alpha, the lobe reflectances 1, 2 pi / (n + 2) and
cos(theta) for a sharp normalised lobe) and its wiring (the sliders move the drawn lines)."""
import math

import numpy as np
import pytest

from course_lib.widgets import brdf as W


def test_lambert_curve_is_a_circle_of_the_cosine():
    s = W.scene(W.State(model="Lambert", kd=0.6, theta_i_deg=25))
    t = s["v_angles"]
    assert np.allclose(s["f"], 0.6 / math.pi)
    assert np.allclose(s["g"], 0.6 / math.pi * np.cos(t))
    assert s["reflectance"] == pytest.approx(0.6)
    # the scaled polar curve of cos(t) is the circle x^2 + (y - 1/2)^2 = 1/4
    x, y = s["curve"].T
    assert np.allclose(x ** 2 + (y - 0.5) ** 2, 0.25)


@pytest.mark.parametrize("normalized", [True, False])
def test_phong_lobe_values(normalized):
    n, ks, kd, theta = 12.0, 0.5, 0.2, 35.0
    s = W.scene(W.State(model="Phong", shininess=n, ks=ks, kd=kd, theta_i_deg=theta,
                        normalized=normalized))
    t = s["v_angles"]
    # l at -theta, v at t (same plane): the angle between R and v is |t - theta|
    alpha = np.abs(t - math.radians(theta))
    lobe = ks * np.where(alpha < math.pi / 2, np.cos(alpha), 0.0) ** n
    if normalized:
        lobe *= (n + 2) / (2 * math.pi)
    assert np.allclose(s["f"], kd / math.pi + lobe, atol=1e-12)
    assert s["mirror"] == pytest.approx([math.sin(math.radians(theta)),
                                         math.cos(math.radians(theta))])
    assert np.argmax(s["g"]) != np.argmax(s["f"]) or theta == 0   # the cosine tilts the peak


def test_reflectances_against_closed_forms():
    for n in (5.0, 50.0):
        s = W.scene(W.State(model="Phong", theta_i_deg=0, shininess=n, kd=0.1, ks=0.9))
        assert s["lobe_reflectance"] == pytest.approx(1.0, abs=1e-7)
        assert s["reflectance"] == pytest.approx(1.0, abs=1e-7)
        u = W.scene(W.State(model="Phong", theta_i_deg=0, shininess=n, normalized=False))
        assert u["lobe_reflectance"] == pytest.approx(2 * math.pi / (n + 2), rel=1e-7)
    sharp = W.scene(W.State(model="Phong", theta_i_deg=60, shininess=500, kd=0, ks=1))
    assert sharp["reflectance"] == pytest.approx(0.5, abs=5e-3)       # about cos(theta_i)
    b = W.scene(W.State(model="Blinn-Phong", theta_i_deg=0, shininess=30, kd=0.3, ks=0.7))
    assert b["reflectance"] == pytest.approx(1.0, abs=1e-7)


def test_energy_verdicts():
    assert not W.scene(W.State(model="Phong", kd=0.7, ks=0.5, theta_i_deg=0))["conserving"]
    # unnormalised Phong with n = 1 and k_s = 1: 2 pi / 3 > 1
    s = W.scene(W.State(model="Phong", kd=0, ks=1, shininess=1, theta_i_deg=0,
                        normalized=False))
    assert s["reflectance"] == pytest.approx(2 * math.pi / 3, rel=1e-4)
    assert not s["conserving"] and "more energy" in s["text"]
    assert W.scene(W.State(kd=0.3, ks=0.6))["conserving"]
    with pytest.raises(ValueError, match="model"):
        W.scene(W.State(model="Cook-Torrance"))


def test_sliders_move_the_picture():
    ex = W.BRDFExplorer()
    before = np.array(ex.lobe_line.get_xydata())
    ex.theta.value = 70.0
    after = np.array(ex.lobe_line.get_xydata())
    assert not np.allclose(before, after)
    assert np.allclose(after, W.scene(W.State(theta_i_deg=70.0))["curve"])
    assert ex.incident_line.get_xdata()[1] == pytest.approx(-math.sin(math.radians(70)))
    ex.model.value = "Lambert"
    x, y = np.array(ex.lobe_line.get_xydata()).T
    assert np.allclose(x ** 2 + (y - 0.5) ** 2, 0.25)
    ex.model.value = "Phong"
    ex.kd.value, ex.ks.value = 0.8, 0.6
    assert "&gt; 1" in ex.info.value and ex.title.get_color() == "#c62828"
    ex.normalized.value = False
    assert ex.state.normalized is False
    assert "Unnormalised" in ex.info.value
