r"""Slerp explorer: interpolating orientations with quaternions against Euler angles.

Two orientations are given by Euler angles (yaw, pitch, roll). A slider moves t from 0 to 1.
The F is drawn twice: turned by the quaternion slerp (orange, solid) and by linear interpolation
of the three Euler angles (purple, see-through). The paths traced by the tip of the F under both
methods are drawn too, and a second plot shows the angular speed along t: slerp turns about one
fixed axis at constant speed along the shortest way; the Euler path wanders and its speed varies.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, quaternions, shapes
from . import _style
from ._base import Explorer, labelled, panel, slider

__all__ = ["PRESETS", "SlerpExplorer", "State", "angular_speed", "euler_quaternions", "paths",
           "scene"]

F_VERTICES, F_FACES = shapes.letter_f_3d()
F_VERTICES = 0.7 * F_VERTICES[:, [0, 2, 1]] * [1, -1, 1]
TIP = F_VERTICES[np.argmax(F_VERTICES[:, 0] + F_VERTICES[:, 2])]
"""The top-right corner of the F's top bar: the point whose path is traced."""

SLERP_COLOR = np.array([0.95, 0.55, 0.1])
EULER_COLOR = np.array([0.55, 0.35, 0.75])

#: name -> (start, end) Euler angles (yaw, pitch, roll) in degrees.
PRESETS = {
    "tilt and turn": ((0, 0, 0), (160, 60, 160)),
    "same end, different angles": ((0, 0, 0), (180, 180, 180)),
    "into gimbal lock": ((0, 0, 0), (90, 90, 90)),
    "one axis only (they agree)": ((-60, 0, 0), (90, 0, 0)),
}


@dataclass
class State:
    """Everything the picture depends on.

    Examples
    --------
    >>> State().preset in PRESETS
    True
    """

    preset: str = "tilt and turn"
    t: float = 0.5


def euler_quaternions(angles_deg):
    r"""Quaternions of Euler angles (yaw, pitch, roll) in degrees, vectorized over rows.

    :math:`q = q_z(\text{yaw})\, q_y(\text{pitch})\, q_x(\text{roll})`, the quaternion form of
    :func:`course_lib.transforms.euler_zyx`.

    Examples
    --------
    >>> euler_quaternions([90, 0, 0]).round(4)       # yaw 90°: a quarter turn about z
    array([0.7071, 0.    , 0.    , 0.7071])
    """
    a = np.radians(np.asarray(angles_deg, dtype=float))
    qz = quaternions.from_axis_angle([0.0, 0.0, 1.0], a[..., 0])
    qy = quaternions.from_axis_angle([0.0, 1.0, 0.0], a[..., 1])
    qx = quaternions.from_axis_angle([1.0, 0.0, 0.0], a[..., 2])
    return quaternions.multiply(quaternions.multiply(qz, qy), qx)


def paths(preset, samples=81):
    """Orientations along t for both methods: ``(t, q_slerp, q_euler)``.

    Examples
    --------
    >>> t, q_slerp, q_euler = paths("tilt and turn", samples=5)
    >>> t.tolist(), q_slerp.shape, q_euler.shape
    ([0.0, 0.25, 0.5, 0.75, 1.0], (5, 4), (5, 4))
    """
    start, end = (np.asarray(e, dtype=float) for e in PRESETS[preset])
    t = np.linspace(0.0, 1.0, samples)
    q0, q1 = euler_quaternions(start), euler_quaternions(end)
    q_slerp = quaternions.slerp(q0, q1, t)
    q_euler = euler_quaternions(start + t[:, None] * (end - start))
    return t, q_slerp, q_euler


def angular_speed(q, t):
    """Angle turned per unit of t between consecutive orientations (degrees), at midpoints.

    Examples
    --------
    >>> import numpy as np
    >>> t = np.linspace(0, 1, 3)
    >>> q = euler_quaternions(np.column_stack([90 * t, 0 * t, 0 * t]))
    >>> mid, speed = angular_speed(q, t)
    >>> mid.tolist(), speed.round(6).tolist()
    ([0.25, 0.75], [90.0, 90.0])
    """
    step = quaternions.angle_between(q[:-1], q[1:])
    return 0.5 * (t[:-1] + t[1:]), np.degrees(step) / np.diff(t)


def scene(state):
    """Pure part: state -> arrays and text to draw. Tested without a display.

    Returns
    -------
    dict
        ``slerp_vertices`` and ``euler_vertices`` (the F at t for each method), ``slerp_path``
        and ``euler_path`` (the tip's path over the whole of t), ``slerp_tip`` and
        ``euler_tip`` (the tip at t), ``speed_t``, ``slerp_speed``, ``euler_speed`` (degrees
        per unit t), ``turned`` (total angle turned by each method, degrees), ``direct``
        (the angle between the two end orientations, degrees), ``text``.

    Examples
    --------
    >>> s = scene(State("one axis only (they agree)", 0.5))
    >>> round(s["direct"]), round(s["turned"]["slerp"]), round(s["turned"]["euler"])
    (150, 150, 150)
    """
    t_all, q_slerp, q_euler = paths(state.preset)
    start, end = (np.asarray(e, dtype=float) for e in PRESETS[state.preset])
    q0, q1 = euler_quaternions(start), euler_quaternions(end)
    qs_t = quaternions.slerp(q0, q1, state.t)
    qe_t = euler_quaternions(start + state.t * (end - start))
    speed_t, slerp_speed = angular_speed(q_slerp, t_all)
    _, euler_speed = angular_speed(q_euler, t_all)
    turned = {"slerp": float(np.sum(slerp_speed * np.diff(t_all))),
              "euler": float(np.sum(euler_speed * np.diff(t_all)))}
    direct = float(np.degrees(quaternions.angle_between(q0, q1)))
    text = (f"The two end orientations differ by a single rotation of {direct:.0f}°. "
            f"Slerp turns {turned['slerp']:.0f}° in all, at a constant "
            f"{slerp_speed.mean():.0f}° per unit t; interpolating the Euler angles turns "
            f"{turned['euler']:.0f}°, at a speed between {euler_speed.min():.0f}° and "
            f"{euler_speed.max():.0f}° per unit t.")
    return {
        "slerp_vertices": quaternions.rotate(qs_t, F_VERTICES),
        "euler_vertices": quaternions.rotate(qe_t, F_VERTICES),
        "slerp_path": quaternions.rotate(q_slerp, TIP),
        "euler_path": quaternions.rotate(q_euler, TIP),
        "slerp_tip": quaternions.rotate(qs_t, TIP),
        "euler_tip": quaternions.rotate(qe_t, TIP),
        "speed_t": speed_t,
        "slerp_speed": slerp_speed,
        "euler_speed": euler_speed,
        "turned": turned,
        "direct": direct,
        "text": text,
    }


class SlerpExplorer(Explorer):
    """A t slider and a preset menu; the F under slerp and under Euler-angle interpolation.

    In a notebook, after ``%matplotlib widget``, end a cell with ``SlerpExplorer()``.

    Examples
    --------
    >>> explorer = SlerpExplorer()
    >>> explorer.t.value = 0.8              # what dragging the t slider does
    >>> bool((explorer.slerp_tip.get_data_3d()[0] == explorer.euler_tip.get_data_3d()[0]).all())
    False
    """

    summary = ("Slerp explorer (interactive): a t slider moves the F between two orientations "
               "by quaternion slerp and by interpolating Euler angles; the tip's paths and the "
               "angular speeds are compared.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(8.2, 3.9))
        grid = self.fig.add_gridspec(1, 2, width_ratios=(1.2, 1), left=0.0, right=0.97,
                                     bottom=0.13, top=0.9, wspace=0.12)
        ax = self.fig.add_subplot(grid[0], projection="3d")
        draw.setup_axes_3d(ax, radius=1.0, title="slerp (orange) vs Euler angles (purple)",
                           box=False)
        (self.slerp_path,) = ax.plot(*s["slerp_path"].T, color=SLERP_COLOR, lw=1.5)
        (self.euler_path,) = ax.plot(*s["euler_path"].T, color=EULER_COLOR, lw=1.5, ls="--")
        (self.slerp_tip,) = ax.plot(*s["slerp_tip"][:, None], "o", color=SLERP_COLOR, ms=5)
        (self.euler_tip,) = ax.plot(*s["euler_tip"][:, None], "o", color=EULER_COLOR, ms=5)
        self.euler_mesh = draw.mesh_3d(ax, s["euler_vertices"], F_FACES,
                                       facecolors=(*EULER_COLOR, 0.25), edgecolor=EULER_COLOR)
        self.slerp_mesh = draw.mesh_3d(ax, s["slerp_vertices"], F_FACES,
                                       facecolors=(*SLERP_COLOR, 0.85))
        speed = self.fig.add_subplot(grid[1])
        (self.slerp_speed,) = speed.plot(s["speed_t"], s["slerp_speed"], color=SLERP_COLOR,
                                         lw=2, label="slerp")
        (self.euler_speed,) = speed.plot(s["speed_t"], s["euler_speed"], color=EULER_COLOR,
                                         lw=2, ls="--", label="Euler angles")
        self.t_line = speed.axvline(self.state.t, color="0.3", lw=1)
        speed.set(xlim=(0, 1), xlabel="t", ylabel="angular speed (° per unit t)")
        speed.set_title("how fast the F turns")
        _style.legend(speed, loc="upper right")
        _style.style_figure(self.fig)
        speed.grid(True, color="0.9")
        self.speed_ax = speed
        self._rescale_speed(s)
        self.blitter = draw.Blitter(self.fig, [self.euler_mesh, self.slerp_mesh, self.slerp_path,
                                               self.euler_path, self.slerp_tip, self.euler_tip,
                                               self.slerp_speed, self.euler_speed, self.t_line])

        self.t = slider("t", self.state.t, 0.0, 1.0, 0.01, label_width="30px", body=300)
        self.preset = labelled(w.Dropdown, "orientations", options=list(PRESETS),
                               value=self.state.preset)
        self.t.observe(self._on_change, names="value")
        self.preset.observe(self._on_change, names="value")
        self.info = panel(s["text"], width="800px")
        self.widget = w.VBox([w.HBox([self.preset, self.t],
                                     layout=w.Layout(flex_flow="row wrap", grid_gap="0 12px")),
                              self.fig.canvas, self.info])

    def _rescale_speed(self, s):
        top = max(s["slerp_speed"].max(), s["euler_speed"].max())
        self.speed_ax.set_ylim(0, 1.15 * top + 1)

    def _on_change(self, change):
        preset_changed = self.preset.value != self.state.preset
        self.state.t = self.t.value
        self.state.preset = self.preset.value
        self.update(rescale=preset_changed)

    def update(self, rescale=False):
        """Recompute the scene and move the drawn artists (no re-plotting)."""
        s = scene(self.state)
        draw.set_mesh_3d(self.slerp_mesh, s["slerp_vertices"], F_FACES)
        draw.set_mesh_3d(self.euler_mesh, s["euler_vertices"], F_FACES)
        self.slerp_path.set_data_3d(*s["slerp_path"].T)
        self.euler_path.set_data_3d(*s["euler_path"].T)
        self.slerp_tip.set_data_3d(*s["slerp_tip"][:, None])
        self.euler_tip.set_data_3d(*s["euler_tip"][:, None])
        self.slerp_speed.set_data(s["speed_t"], s["slerp_speed"])
        self.euler_speed.set_data(s["speed_t"], s["euler_speed"])
        self.t_line.set_xdata([self.state.t, self.state.t])
        self.info.value = s["text"]
        if rescale:
            self._rescale_speed(s)          # the axis limits are static: redraw everything
            self.blitter.forget_background()
        self.blitter.update()
