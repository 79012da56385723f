r"""Gimbal-lock explorer: three nested rings turned by yaw, pitch and roll.

An orientation given by Euler angles is a set of three nested gimbals: the outer ring turns
about the world z axis (yaw), carries the middle ring that turns about its own y axis (pitch),
which carries the inner ring that turns about its own x axis (roll), which carries the F:
:math:`R = R_z(\text{yaw})\, R_y(\text{pitch})\, R_x(\text{roll})`.

The three pivot axes, in world coordinates, are the columns of

.. math:: J = \big[\, e_z,\ R_z e_y,\ R_z R_y e_x \,\big], \qquad \det J = -\cos(\text{pitch}),

and an angular velocity is a combination of them. While :math:`\det J \neq 0` they span all of
space: the F can start turning in any direction. At pitch :math:`= \pm 90°` the roll axis lines
up with the yaw axis, :math:`\det J = 0`, and no change of the three angles turns the F about
the third direction: that is gimbal lock. Quaternions (and matrices) have no such point.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, transforms
from ._base import Explorer, beside, bind, degree_sliders, figure_3d, panel
from .quaternion import F_COLORS, F_FACES, F_VERTICES, LIGHT

__all__ = ["GimbalExplorer", "State", "gimbal_frames", "scene"]

RING_RADII = (1.2, 1.02, 0.86)
AXIS_NAMES = ("yaw (outer ring, about z)", "pitch (middle ring, about its y)",
              "roll (inner ring, about its x)")
RING_COLORS = (draw.AXIS_COLORS[2], draw.AXIS_COLORS[1], draw.AXIS_COLORS[0])
_CIRCLE = np.linspace(0.0, 2.0 * np.pi, 97)


@dataclass
class State:
    """Euler angles in degrees, as on the sliders.

    Examples
    --------
    >>> State(pitch_deg=90).pitch_deg
    90
    """

    yaw_deg: float = -25.0
    pitch_deg: float = 35.0
    roll_deg: float = 25.0


def gimbal_frames(yaw, pitch, roll):
    """The three ring frames (3x3 rotations): R_z(yaw), then R_y(pitch), then R_x(roll).

    Examples
    --------
    >>> import numpy as np
    >>> outer, middle, inner = gimbal_frames(np.pi / 2, 0.0, 0.0)
    >>> outer[:, 0].round(12) + 0.0               # yaw 90°: the outer ring's x axis is y
    array([0., 1., 0.])
    """
    f1 = transforms.rotate_z(yaw)[:3, :3]
    f2 = f1 @ transforms.rotate_y(pitch)[:3, :3]
    f3 = f2 @ transforms.rotate_x(roll)[:3, :3]
    return f1, f2, f3


def scene(state):
    """Pure part: state -> rings, pivot axes, the F and the lock diagnosis.

    Returns
    -------
    dict
        ``rings`` (three arrays of circle points), ``pivots`` (three unit axes: yaw, pitch,
        roll, in world coordinates), ``vertices`` and ``face_colors`` of the F, ``det``
        (:math:`\\det J`), ``axis_angle`` (the angle between the yaw and roll axes, degrees),
        ``lost_axis`` (the direction no gimbal can turn about when locked, else None),
        ``locked`` (bool) and ``text``.

    Examples
    --------
    >>> s = scene(State(yaw_deg=10, pitch_deg=90, roll_deg=0))
    >>> s["locked"], round(s["det"], 12) + 0.0, round(s["axis_angle"], 6)
    (True, 0.0, 0.0)
    """
    yaw, pitch, roll = np.radians([state.yaw_deg, state.pitch_deg, state.roll_deg])
    f1, f2, f3 = gimbal_frames(yaw, pitch, roll)
    c, s = np.cos(_CIRCLE), np.sin(_CIRCLE)
    zero = np.zeros_like(c)
    rings = [
        np.column_stack([zero, c, s]) * RING_RADII[0] @ f1.T,   # contains z and the pitch axis
        np.column_stack([c, s, zero]) * RING_RADII[1] @ f2.T,   # contains pitch and roll axes
        np.column_stack([c, zero, s]) * RING_RADII[2] @ f3.T,   # contains the roll axis
    ]
    pivots = np.array([[0.0, 0.0, 1.0], f1[:, 1], f2[:, 0]])
    det = float(np.linalg.det(pivots.T))
    axis_angle = float(np.degrees(np.arccos(np.clip(abs(pivots[0] @ pivots[2]), 0.0, 1.0))))
    locked = abs(det) < 1e-9
    lost = np.cross(pivots[0], pivots[1]) if locked else None
    vertices = 0.75 * F_VERTICES @ f3.T
    colors = draw.shade(draw.face_normals(vertices, F_FACES), F_COLORS, light=LIGHT)
    if locked:
        text = (f"<b>Gimbal lock.</b> The roll axis lies along the yaw axis (angle between them "
                f"{axis_angle:.1f}°) and det J = {det:+.3f}: yaw and roll now turn the F about "
                "the same axis. No combination of the three angles can start a turn about the "
                "dashed grey axis.")
    elif abs(det) < 0.26:
        text = (f"<b>Close to gimbal lock</b> (|pitch| > 75°): the yaw and roll axes are only "
                f"{axis_angle:.1f}° apart and det J = {det:+.3f}. A small turn about the "
                "direction perpendicular to the yaw and pitch axes now needs large, fast changes "
                "of yaw and roll.")
    else:
        text = (f"Angle between the yaw and roll axes: {axis_angle:.1f}°; det J = {det:+.3f} "
                f"(= -cos pitch). The three pivot axes span space: every small turn is "
                "possible. Move pitch to ±90° to lose one.")
    return {"rings": rings, "pivots": pivots, "vertices": vertices, "face_colors": colors,
            "det": det, "axis_angle": axis_angle, "lost_axis": lost, "locked": locked,
            "text": text}


class GimbalExplorer(Explorer):
    """Yaw, pitch and roll sliders turning three nested rings and the F inside them.

    In a notebook, after ``%matplotlib widget``, end a cell with ``GimbalExplorer()``.

    Examples
    --------
    >>> explorer = GimbalExplorer()
    >>> explorer.pitch.value = 90           # what dragging the pitch slider does
    >>> "Gimbal lock" in explorer.info.value
    True
    """

    summary = ("Gimbal-lock explorer (interactive): yaw, pitch and roll sliders turn three "
               "nested rings; at pitch = ±90° two ring axes line up and a degree of freedom is "
               "lost.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig, ax = figure_3d(1.3, "R = R_z(yaw) R_y(pitch) R_x(roll)")
        self.rings, self.pivots = [], []
        for k in range(3):
            (ring,) = ax.plot(*s["rings"][k].T, color=RING_COLORS[k], lw=3, alpha=0.85)
            (pivot,) = ax.plot(*self._pivot_line(s["pivots"][k], k).T, color=RING_COLORS[k],
                               lw=1.2, ls="--")
            self.rings.append(ring)
            self.pivots.append(pivot)
        (self.lost,) = ax.plot([], [], [], color="0.4", lw=2, ls=(0, (2, 2)))
        self.mesh = draw.mesh_3d(ax, s["vertices"], F_FACES, facecolors=s["face_colors"])
        self.blitter = draw.Blitter(self.fig, [self.mesh, *self.rings, *self.pivots, self.lost])
        self._set_lost(s)

        sliders = degree_sliders(None,
                                 yaw=("yaw °", self.state.yaw_deg, -180, 180),
                                 pitch=("pitch °", self.state.pitch_deg, -90, 90),
                                 roll=("roll °", self.state.roll_deg, -180, 180))
        self.yaw, self.pitch, self.roll = sliders.values()
        bind(self.state, {"yaw_deg": self.yaw, "pitch_deg": self.pitch, "roll_deg": self.roll},
             self.update)
        legend = "<br>".join(f"<span style='color:{RING_COLORS[k]}'>&#9679;</span> "
                             f"{AXIS_NAMES[k]}" for k in range(3))
        self.info = panel(s["text"], width="330px")
        self.widget = beside(self.fig.canvas,
                             w.VBox([*sliders.values(), panel(legend), self.info]))

    @staticmethod
    def _pivot_line(axis, k):
        reach = RING_RADII[k] + 0.12
        return np.array([-reach * axis, reach * axis])

    def _set_lost(self, s):
        if s["lost_axis"] is None:
            self.lost.set_data_3d([], [], [])
        else:
            self.lost.set_data_3d(*np.array([-1.3 * s["lost_axis"], 1.3 * s["lost_axis"]]).T)

    def update(self):
        """Recompute the scene and move the drawn artists (no re-plotting)."""
        s = scene(self.state)
        for k in range(3):
            self.rings[k].set_data_3d(*s["rings"][k].T)
            self.pivots[k].set_data_3d(*self._pivot_line(s["pivots"][k], k).T)
        self._set_lost(s)
        draw.set_mesh_3d(self.mesh, s["vertices"], F_FACES, s["face_colors"])
        self.info.value = s["text"]
        self.blitter.update()
