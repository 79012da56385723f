r"""Radiometry explorer: a point light over a plane, the inverse-square and cosine laws, and the
solid angle of a small patch.

An isotropic point light of intensity :math:`I` hangs at the height :math:`h` above the floor
:math:`z = 0`, at the horizontal offset :math:`x_0`. The floor's irradiance is
:math:`E = I\cos\theta/d^2` (:func:`course_lib.shading.point_light_irradiance`); on a horizontal
floor :math:`\cos\theta = h/d`, so :math:`E = I h/d^3`, which falls off far faster than the
:math:`1/d^2` alone. The profile along :math:`y = 0` shows the two factors, the cosine and the
inverse square (each 1 under the light), and their product.

The third panel is a small square patch (side :math:`s`) seen from a point at the distance
:math:`D`, its normal tilted by :math:`\tau` from the line of sight; the info panel compares its
exact solid angle (:func:`course_lib.shading.polygon_solid_angle`) with the small-patch value
:math:`s^2\cos\tau/D^2` (:func:`course_lib.shading.patch_solid_angle`).

The floor's grid of points is built once; an update evaluates 6,561 irradiances (vectorized)
and redraws the moving artists only (blitting).
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, shading
from . import _style
from ._base import Explorer, bind, panel, slider

__all__ = ["EXTENT", "GRID", "PATCH_SIDE", "RadiometryExplorer", "State", "VMAX", "patch_corners",
           "scene"]

GRID = 81
EXTENT = 3.0                      # the floor shown is [-3, 3] x [-3, 3] m
PATCH_SIDE = 0.5                  # the square patch of the solid-angle panel, m
VMAX = 50.0                       # top of the colour scale, W/m²
_AXIS = np.linspace(-EXTENT, EXTENT, GRID)
_XX, _YY = np.meshgrid(_AXIS, _AXIS)
_FLOOR = np.stack([_XX, _YY, np.zeros_like(_XX)], axis=-1)
_PROFILE_X = np.linspace(-EXTENT, EXTENT, 241)
_PROFILE = np.stack([_PROFILE_X, np.zeros_like(_PROFILE_X), np.zeros_like(_PROFILE_X)], -1)
_UP = np.array([0.0, 0.0, 1.0])


@dataclass
class State:
    """The light (height, offset, intensity) and the patch (tilt, distance).

    Examples
    --------
    >>> State().height, State().intensity
    (2.0, 100.0)
    """

    height: float = 2.0
    offset: float = 0.0
    intensity: float = 100.0
    tilt_deg: float = 30.0
    patch_distance: float = 2.0


def patch_corners(tilt_deg, distance, side=PATCH_SIDE):
    r"""The corners (4, 3) of a square patch centred at (D, 0, 0), seen from the origin along +x,
    its normal tilted by `tilt_deg` from the line of sight (in the x-z plane); and its normal.

    Examples
    --------
    >>> corners, normal = patch_corners(0, 2.0)
    >>> corners[:, 0].tolist(), normal.tolist()
    ([2.0, 2.0, 2.0, 2.0], [-1.0, 0.0, 0.0])
    """
    t = np.radians(tilt_deg)
    c = np.array([distance, 0.0, 0.0])
    n = np.array([-np.cos(t), 0.0, np.sin(t)])
    b1 = np.array([np.sin(t), 0.0, np.cos(t)])
    b2 = np.array([0.0, 1.0, 0.0])
    h = side / 2
    corners = c + h * np.array([-b1 - b2, b1 - b2, b1 + b2, -b1 + b2])
    return corners, n + 0.0


def scene(state):
    r"""Pure part: the floor's irradiance map, the profile along y = 0 and the patch's solid
    angle, exact and approximate.

    Returns
    -------
    dict
        ``light`` (3,), ``irradiance`` (GRID, GRID), ``profile_x``, ``cos_theta``,
        ``inv_d2_rel`` (:math:`h^2/d^2`, the 1/d² factor relative to its value under the
        light), ``profile_e`` (W/m²), ``corners``, ``normal``, ``omega_exact``,
        ``omega_approx``, ``text``.

    Examples
    --------
    >>> s = scene(State(height=2.0, offset=0.0, intensity=100.0))
    >>> float(s["irradiance"][GRID // 2, GRID // 2])          # I / h^2 under the light
    25.0
    >>> bool(abs(s["omega_approx"] / s["omega_exact"] - 1) < 0.02)
    True
    """
    light = np.array([float(state.offset), 0.0, float(state.height)])
    floor = shading.point_light_irradiance(_FLOOR, _UP, light, state.intensity)
    prof = shading.point_light_irradiance(_PROFILE, _UP, light, state.intensity)
    h = float(state.height)
    corners, normal = patch_corners(state.tilt_deg, state.patch_distance)
    exact = float(shading.polygon_solid_angle(corners, [0.0, 0.0, 0.0]))
    approx = float(shading.patch_solid_angle(PATCH_SIDE ** 2, normal,
                                             [state.patch_distance, 0.0, 0.0], [0.0, 0.0, 0.0]))
    e0 = state.intensity / h ** 2
    x1 = state.offset + h                                 # 45 degrees off the vertical
    e1 = state.intensity * np.cos(np.pi / 4) / (2 * h * h)
    err = (approx - exact) / exact if exact > 0 else 0.0
    text = (f"<b>Under the light</b> (x = {state.offset:.2f}): E = I/h² = {state.intensity:.0f}"
            f"/{h:.2f}² = <b>{e0:.2f} W/m²</b>. At x = {x1:.2f} (45° off the vertical, "
            f"d = √2·h): cos θ = 0.707, 1/d² halves, E = {e1:.2f} W/m² = E₀·cos³45°. "
            "Far away E ≈ I h/d³.<br>"
            f"<b>Patch</b> {PATCH_SIDE:g} m × {PATCH_SIDE:g} m at D = {state.patch_distance:.2f} "
            f"m, tilted τ = {state.tilt_deg:.0f}°: exact Ω = {1e3 * exact:.3f} msr, small-patch "
            f"A cos τ / D² = {1e3 * approx:.3f} msr (error {100 * err:+.2f} %, falls like "
            "(s/D)²).")
    return {"light": light, "irradiance": floor.irradiance, "profile_x": _PROFILE_X,
            "cos_theta": prof.cos_theta, "inv_d2_rel": h * h * prof.inv_d2,
            "profile_e": prof.irradiance, "corners": corners, "normal": normal,
            "omega_exact": exact, "omega_approx": approx, "text": text}


class RadiometryExplorer(Explorer):
    """Light height, offset and intensity; patch tilt and distance. The floor's irradiance,
    its profile with the cosine and 1/d² factors, and a patch's solid angle.

    In a notebook, after ``%matplotlib widget``, end a cell with ``RadiometryExplorer()``.

    Examples
    --------
    >>> explorer = RadiometryExplorer()
    >>> explorer.height.value = 1.0
    >>> float(explorer.image.get_array()[GRID // 2, GRID // 2])
    100.0
    """

    summary = ("Radiometry explorer (interactive): a point light over a floor; the irradiance "
               "E = I cos θ / d² with its cosine and inverse-square factors, and the solid "
               "angle of a tilted patch, exact and A cos θ / d².")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(9.0, 3.0))
        ax_map = self.fig.add_axes((0.06, 0.15, 0.22, 0.7))
        ax_prof = self.fig.add_axes((0.42, 0.15, 0.24, 0.7))
        ax_patch = self.fig.add_axes((0.80, 0.15, 0.19, 0.7))
        self.image = ax_map.imshow(s["irradiance"], origin="lower", cmap="inferno", vmin=0,
                                   vmax=VMAX, extent=(-EXTENT, EXTENT, -EXTENT, EXTENT),
                                   interpolation="nearest")
        self.fig.colorbar(self.image, cax=self.fig.add_axes((0.29, 0.15, 0.012, 0.7)),
                          extend="max", label="E [W/m²]")
        ax_map.axhline(0, color="w", lw=0.6, ls=":")
        (self.foot,) = ax_map.plot([s["light"][0]], [0], "c+", ms=10, mew=1.5)
        ax_map.set(xlabel="x [m]", ylabel="y [m]", title="floor irradiance E")
        (self.e_line,) = ax_prof.plot(s["profile_x"], s["profile_e"], color="C3", lw=2,
                                      label="E = I cos θ / d²")
        ax_prof.set(xlim=(-EXTENT, EXTENT), ylim=(0, VMAX), xlabel="x [m] (along y = 0)",
                    ylabel="E [W/m²]")
        twin = ax_prof.twinx()
        (self.cos_line,) = twin.plot(s["profile_x"], s["cos_theta"], color="C0", lw=1.2,
                                     label="cos θ")
        (self.inv_line,) = twin.plot(s["profile_x"], s["inv_d2_rel"], color="C2", lw=1.2,
                                     ls="--", label="h²/d² (1/d², relative)")
        twin.set(ylim=(0, 1.05), ylabel="factor (1 under the light)")
        handles = [self.e_line, self.cos_line, self.inv_line]
        # a figure legend above the axes: not redrawn with the moving curves
        self.fig.legend(handles, [h.get_label() for h in handles], loc="lower center",
                        bbox_to_anchor=(0.54, 0.86), ncol=3, fontsize=7, handlelength=1.5,
                        frameon=False, columnspacing=1.0)
        ax_patch.plot([0], [0], "ko", ms=4)
        (self.patch_line,) = ax_patch.plot([], [], color="C1", lw=3)
        (self.rays,) = ax_patch.plot([], [], color="0.5", lw=0.8)
        (self.normal_line,) = ax_patch.plot([], [], color="C1", lw=1)
        ax_patch.set(xlim=(-0.2, 5.3), ylim=(-1.5, 1.5), aspect="equal", xlabel="x [m]",
                     ylabel="z [m]")
        ax_patch.set_title("patch seen from a point", fontsize=9)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image, self.foot, self.e_line,
                                               self.cos_line, self.inv_line, self.patch_line,
                                               self.rays, self.normal_line])
        self.height = slider("light height h [m]", self.state.height, 0.5, 4.0, 0.05)
        self.offset = slider("light offset x₀ [m]", self.state.offset, -2.0, 2.0, 0.05)
        self.intensity = slider("intensity I [W/sr]", self.state.intensity, 10.0, 200.0, 5.0)
        self.tilt = slider("patch tilt τ [°]", self.state.tilt_deg, 0.0, 89.0, 1.0)
        self.distance = slider("patch distance D [m]", self.state.patch_distance, 0.3, 5.0, 0.05)
        bind(self.state, {"height": self.height, "offset": self.offset,
                          "intensity": self.intensity, "tilt_deg": self.tilt,
                          "patch_distance": self.distance}, self.update)
        self.info = panel(width="860px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([w.VBox([self.height, self.offset, self.intensity]),
                                      w.VBox([self.tilt, self.distance])]),
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute the scene and update the moving artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.image.set_data(s["irradiance"])
        self.foot.set_data([s["light"][0]], [0.0])
        self.e_line.set_ydata(s["profile_e"])
        self.cos_line.set_ydata(s["cos_theta"])
        self.inv_line.set_ydata(s["inv_d2_rel"])
        c = s["corners"]
        ends = np.array([(c[0] + c[3]) / 2, (c[1] + c[2]) / 2])[:, [0, 2]]   # side view x-z
        self.patch_line.set_data(ends[:, 0], ends[:, 1])
        self.rays.set_data([ends[0, 0], 0, ends[1, 0]], [ends[0, 1], 0, ends[1, 1]])
        mid = ends.mean(axis=0)
        tip = mid + 0.4 * s["normal"][[0, 2]]
        self.normal_line.set_data([mid[0], tip[0]], [mid[1], tip[1]])
        self.info.value = s["text"]
