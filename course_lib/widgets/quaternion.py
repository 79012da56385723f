r"""Quaternion explorer: rotate a letter F about any axis and read off q and its matrix.

Sliders choose the rotation axis (by two angles: azimuth around z and elevation above the xy
plane) and the rotation angle. The figure shows the original frame faintly, the rotated frame
in bold, the axis as a black line with an arc sweeping the angle, and the F turned by the
quaternion :math:`q = (\cos\frac{\theta}{2}, \sin\frac{\theta}{2}\hat n)`. Beside it: the four
components of :math:`q` and the equivalent 3x3 rotation matrix.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, format as fmt, quaternions, shapes
from ._base import Explorer, beside, bind, degree_sliders, figure_3d, panel

__all__ = ["QuaternionExplorer", "State", "axis_from_angles", "readout", "scene"]

F_VERTICES, F_FACES = shapes.letter_f_3d()
F_VERTICES = 0.6 * F_VERTICES[:, [0, 2, 1]] * [1, -1, 1]
"""The F stands upright in the xz plane, its front facing -y (towards the default view)."""
F_COLORS = np.array([[0.95, 0.55, 0.1]] + [[0.3, 0.45, 0.8]] + [[0.8, 0.8, 0.8]] * 10)
"""Front of the F orange, back blue, sides grey: the two sides are told apart at a glance."""


LIGHT = (0.35, -0.8, 0.5)
"""Light from about where the default view looks from, so the visible faces are lit."""


@dataclass
class State:
    """Everything the picture depends on (angles in degrees, as on the sliders).

    Examples
    --------
    >>> State(angle_deg=90).angle_deg
    90
    """

    azimuth_deg: float = -30.0
    elevation_deg: float = 60.0
    angle_deg: float = 50.0


def axis_from_angles(azimuth_deg, elevation_deg):
    """The unit axis with the given azimuth (about z, from x) and elevation (above xy).

    Examples
    --------
    >>> axis_from_angles(90, 0).round(12) + 0.0
    array([0., 1., 0.])
    """
    az, el = np.radians(azimuth_deg), np.radians(elevation_deg)
    return np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])


def _perpendicular(n):
    """A unit vector perpendicular to the unit vector n."""
    helper = np.array([0.0, 0.0, 1.0]) if abs(n[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(n, helper)
    return u / np.linalg.norm(u)


def scene(state):
    """Pure part: state -> everything drawn and printed. Tested without a display.

    Returns
    -------
    dict
        ``axis`` (unit vector), ``angle`` (radians), ``q`` (scalar first), ``matrix`` (3x3),
        ``frame`` (the matrix's columns: the rotated x, y, z axes), ``vertices`` (the rotated F),
        ``face_colors``, ``axis_line`` (2x3 points), ``arc`` (points sweeping the angle about
        the axis), and ``text`` (the readout, HTML).

    Examples
    --------
    >>> s = scene(State(azimuth_deg=0, elevation_deg=90, angle_deg=90))   # 90° about z
    >>> s["q"].round(4)
    array([0.7071, 0.    , 0.    , 0.7071])
    >>> s["frame"][:, 0].round(12) + 0.0          # the x axis now points along y
    array([0., 1., 0.])
    """
    n = axis_from_angles(state.azimuth_deg, state.elevation_deg)
    theta = np.radians(state.angle_deg)
    q = quaternions.from_axis_angle(n, theta)
    m = quaternions.to_matrix(q)
    vertices = quaternions.rotate(q, F_VERTICES)
    normals = draw.face_normals(vertices, F_FACES)
    u = 0.55 * _perpendicular(n)
    sweep = quaternions.from_axis_angle(n, np.linspace(0.0, theta, 40))
    arc = quaternions.rotate(sweep, u) + 0.9 * n
    return {
        "axis": n,
        "angle": theta,
        "q": q,
        "matrix": m,
        "frame": m,
        "vertices": vertices,
        "face_colors": draw.shade(normals, F_COLORS, light=LIGHT),
        "axis_line": np.array([-1.6 * n, 1.6 * n]),
        "arc": np.vstack([0.9 * n, arc]),
        "text": readout(n, theta, q, m),
    }


def readout(n, theta, q, m):
    """The quaternion and its matrix as HTML, for the panel beside the figure.

    Examples
    --------
    >>> import numpy as np
    >>> "45°" in readout(np.array([0, 0, 1.0]), np.pi / 2, np.array([0.7, 0, 0, 0.7]), np.eye(3))
    True
    """
    half = fmt.number(np.degrees(theta / 2), 1)
    return (
        f"<b>axis</b> <i>n̂</i> = {fmt.vector_html(n)}, <b>angle</b> "
        f"<i>θ</i> = {fmt.number(np.degrees(theta), 1)}°<br>"
        f"<i>q</i> = (cos <sup>θ</sup>&frasl;<sub>2</sub>, sin <sup>θ</sup>&frasl;<sub>2</sub> "
        f"<i>n̂</i>) = (cos {half}°, sin {half}° <i>n̂</i>)<br>"
        f"<i>q</i> = (<i>s, x, y, z</i>) = {fmt.vector_html(q)}<br>"
        f"‖<i>q</i>‖ = {fmt.number(quaternions.norm(q))}<br>"
        f"<i>R<sub>q</sub></i> = {fmt.matrix_html(m)}"
    )


class QuaternionExplorer(Explorer):
    """Sliders for the axis and the angle; the rotated F, frame and axis in 3D; q and R_q.

    In a notebook, after ``%matplotlib widget``, end a cell with ``QuaternionExplorer()``.

    Examples
    --------
    >>> explorer = QuaternionExplorer()
    >>> explorer.angle.value = 120          # what dragging the angle slider does
    >>> explorer.state.angle_deg, "120°" in explorer.info.value
    (120.0, True)
    """

    summary = ("Quaternion explorer (interactive): sliders for the rotation axis and angle, the "
               "rotated F and frame in 3D, the quaternion and its rotation matrix.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig, ax = figure_3d(1.25, "p' = q p q̄")
        draw.frame_3d(ax, lw=1.2, alpha=0.35, ls="--")
        self.frame = draw.frame_3d(ax, lw=2.5)
        draw.set_frame_3d(self.frame, s["frame"])
        (self.axis_line,) = ax.plot(*s["axis_line"].T, color="black", lw=1.5)
        (self.arc,) = ax.plot(*s["arc"].T, color="black", lw=1.2)
        (self.arc_end,) = ax.plot(*s["arc"][-1:].T, "o", color="black", ms=4)
        draw.mesh_3d(ax, F_VERTICES, F_FACES, facecolors=(0.6, 0.6, 0.6, 0.08),
                     edgecolor=(0.35, 0.35, 0.35, 0.5), linestyle="--")
        self.mesh = draw.mesh_3d(ax, s["vertices"], F_FACES, facecolors=s["face_colors"])
        self.blitter = draw.Blitter(self.fig, [self.mesh, *self.frame, self.axis_line, self.arc,
                                               self.arc_end])

        sliders = degree_sliders(
            None,
            azimuth=("axis azimuth °", self.state.azimuth_deg, -180, 180),
            elevation=("axis elevation °", self.state.elevation_deg, -90, 90),
            angle=("angle θ °", self.state.angle_deg, -360, 360))
        self.azimuth, self.elevation, self.angle = sliders.values()
        bind(self.state, {"azimuth_deg": self.azimuth, "elevation_deg": self.elevation,
                          "angle_deg": self.angle}, self.update)
        self.info = panel(s["text"], width="400px")
        self.widget = beside(self.fig.canvas, w.VBox([*sliders.values(), self.info]))

    def update(self):
        """Recompute the scene and move the drawn artists (no re-plotting)."""
        s = scene(self.state)
        draw.set_frame_3d(self.frame, s["frame"])
        self.axis_line.set_data_3d(*s["axis_line"].T)
        self.arc.set_data_3d(*s["arc"].T)
        self.arc_end.set_data_3d(*s["arc"][-1:].T)
        draw.set_mesh_3d(self.mesh, s["vertices"], F_FACES, s["face_colors"])
        self.info.value = s["text"]
        self.blitter.update()
