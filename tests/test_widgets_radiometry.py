"""Headless tests of the radiometry explorer: the scene against E = I h / d^3 on the floor typed
here, the patch's solid angle against a scipy surface integral, and the wiring (sliders move
the drawn picture)."""
import matplotlib

matplotlib.use("module://ipympl.backend_nbagg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from scipy.integrate import dblquad  # noqa: E402

from course_lib.widgets import radiometry  # noqa: E402


def floor_irradiance(x, y, x0, h, intensity):
    """On a horizontal floor cos(theta) = h / d, so E = I h / d^3."""
    d = np.sqrt((x - x0) ** 2 + y ** 2 + h ** 2)
    return intensity * h / d ** 3


@pytest.mark.parametrize("h,x0,intensity", [(2.0, 0.0, 100.0), (0.7, -1.3, 35.0),
                                            (3.5, 1.9, 200.0)])
def test_scene_irradiance_map_and_profile(h, x0, intensity):
    s = radiometry.scene(radiometry.State(height=h, offset=x0, intensity=intensity))
    axis = np.linspace(-radiometry.EXTENT, radiometry.EXTENT, radiometry.GRID)
    xx, yy = np.meshgrid(axis, axis)                 # row = y, column = x (origin lower)
    assert np.allclose(s["irradiance"], floor_irradiance(xx, yy, x0, h, intensity))
    px = s["profile_x"]
    d2 = (px - x0) ** 2 + h * h
    assert np.allclose(s["cos_theta"], h / np.sqrt(d2))
    assert np.allclose(s["inv_d2_rel"], h * h / d2)
    assert np.allclose(s["profile_e"], intensity * s["cos_theta"] * s["inv_d2_rel"] / h ** 2)
    assert np.allclose(s["light"], [x0, 0, h])


@pytest.mark.parametrize("tilt,distance", [(0.0, 2.0), (60.0, 1.0), (85.0, 0.5), (30.0, 4.5)])
def test_patch_solid_angle_exact_and_approximate(tilt, distance):
    s = radiometry.scene(radiometry.State(tilt_deg=tilt, patch_distance=distance))
    side = radiometry.PATCH_SIDE
    t = np.radians(tilt)
    b1 = np.array([np.sin(t), 0, np.cos(t)])
    b2 = np.array([0.0, 1.0, 0.0])
    n = np.array([-np.cos(t), 0, np.sin(t)])
    c = np.array([distance, 0.0, 0.0])

    def integrand(v, u):
        x = c + u * b1 + v * b2
        r = np.linalg.norm(x)
        return abs(x @ n) / r ** 3

    exact, _ = dblquad(integrand, -side / 2, side / 2, -side / 2, side / 2, epsabs=1e-12)
    assert s["omega_exact"] == pytest.approx(exact, rel=1e-7)
    assert s["omega_approx"] == pytest.approx(side ** 2 * np.cos(t) / distance ** 2, rel=1e-12)
    assert f"{1e3 * exact:.3f} msr" in s["text"]


@pytest.mark.parametrize("tilt", [0.0, 70.0])
def test_approximation_improves_as_the_patch_recedes(tilt):
    # (near 40 degrees the two (s/D)^2 terms of the error nearly cancel: not a clean test)
    errors = [abs(s["omega_approx"] / s["omega_exact"] - 1) for s in
              (radiometry.scene(radiometry.State(tilt_deg=tilt, patch_distance=d))
               for d in (0.5, 1.0, 2.0, 4.0))]
    assert np.all(np.diff(errors) < 0)
    assert errors[-2] / errors[-1] == pytest.approx(4, rel=0.1)   # like (s/D)^2


def test_sliders_move_the_picture():
    ex = radiometry.RadiometryExplorer()
    ex.fig.canvas.draw()
    before = np.array(ex.image.get_array())
    ex.height.value = 1.0                               # what a student's drag does
    after = np.array(ex.image.get_array())
    assert not np.allclose(before, after)
    centre = radiometry.GRID // 2
    assert after[centre, centre] == pytest.approx(100.0)          # I / h^2 under the light
    ex.offset.value = 1.5
    assert ex.foot.get_xdata()[0] == pytest.approx(1.5)
    x = ex.e_line.get_xdata()
    assert np.allclose(ex.e_line.get_ydata(), floor_irradiance(x, 0.0, 1.5, 1.0, 100.0))
    ex.intensity.value = 50.0
    assert np.allclose(ex.e_line.get_ydata(), floor_irradiance(x, 0.0, 1.5, 1.0, 50.0))
    old_patch = np.array(ex.patch_line.get_xydata())
    ex.tilt.value = 70.0
    ex.distance.value = 4.0
    new_patch = np.array(ex.patch_line.get_xydata())
    assert not np.allclose(old_patch, new_patch)
    assert np.allclose(new_patch.mean(axis=0), [4.0, 0.0])        # centred at the distance
    length = np.linalg.norm(new_patch[1] - new_patch[0])
    assert length == pytest.approx(radiometry.PATCH_SIDE)
    assert "D = 4.00" in ex.info.value and "τ = 70°" in ex.info.value
    plt.close(ex.fig)


def test_display_bundle_has_a_picture():
    ex = radiometry.RadiometryExplorer()
    bundle = ex._repr_mimebundle_()
    assert "image/png" in bundle and "text/plain" in bundle
    plt.close(ex.fig)
