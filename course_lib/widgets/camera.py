r"""Camera explorer: a camera in a small world, its view volume, and the picture it takes.

Sliders place the eye, aim the direction of view (two angles) and set the up vector (which need
not be perpendicular to the direction of view). On the left, the world with the camera's eye
coordinate axes (:math:`x_e` red, :math:`y_e` green, :math:`z_e` blue, pointing back at the
viewer) and its view volume: a frustum for a perspective camera, a box for an orthographic one,
a slanted box for an oblique one. On the right, what the camera sees: every face clipped to the
view volume (Sutherland-Hodgman against its six planes), taken through
:math:`M_{ECS \to CSS}\, M_{WCS \to ECS}` and the homogeneous divide into the canonical square,
and painted far to near. Below, both matrices.
"""
from dataclasses import dataclass

import numpy as np

from .. import clipping, draw, format as fmt, shapes, transforms, viewing
from . import _style
from ._base import Explorer, align, bind, panel, slider

__all__ = ["CameraExplorer", "PROJECTIONS", "State", "camera_matrices", "scene", "world"]

PROJECTIONS = ("perspective", "orthographic", "oblique")
_CUBE = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
_EDGES = [(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4), (1, 5),
          (2, 6), (3, 7)]
_LIGHT = (0.5, -0.3, 0.8)
_REACH = 7.0


def _box(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = np.array([[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                  [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]], dtype=float)
    faces = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]]
    return v, faces


def world():
    """The little world the camera looks at: faces (list of (k, 3) arrays), their colours, and
    the lines of a ground grid (list of 2x3 arrays).

    Examples
    --------
    >>> faces, colors, grid = world()
    >>> len(faces) == len(colors), len(grid)
    (True, 14)
    """
    faces, colors = [], []
    v, f = _box((0.4, -1.6, 0.0), (1.4, -0.6, 1.0))                       # a cube
    faces += [v[i] for i in f]
    colors += [(0.25, 0.55, 0.85)] * len(f)
    v, f = shapes.letter_f_3d(thickness=0.35)                              # an upright F
    v = 1.2 * v[:, [0, 2, 1]] * [1, -1, 1] + [-0.6, 0.3, 0.9]
    faces += [v[i] for i in f]
    colors += [(0.95, 0.55, 0.1)] * 2 + [(0.75, 0.75, 0.75)] * (len(f) - 2)
    apex = np.array([-1.6, -1.4, 1.4])                                    # a pyramid
    base = np.array([[-2.2, -2.0, 0], [-1.0, -2.0, 0], [-1.0, -0.8, 0], [-2.2, -0.8, 0]])
    faces.append(base[::-1])
    colors.append((0.4, 0.7, 0.35))
    for k in range(4):
        faces.append(np.array([base[k], base[(k + 1) % 4], apex]))
        colors.append((0.4, 0.7, 0.35))
    grid = [np.array([[x, -3, 0], [x, 3, 0]], float) for x in range(-3, 4)]
    grid += [np.array([[-3, y, 0], [3, y, 0]], float) for y in range(-3, 4)]
    normals = np.array([np.cross(p[1] - p[0], p[2] - p[0]) for p in faces])
    shaded = draw.shade(normals, np.array(colors), light=_LIGHT, ambient=0.5)
    return faces, [tuple(c) for c in shaded], grid


_FACES, _COLORS, _GRID = world()


@dataclass
class State:
    """The camera: eye, direction of view (angles in degrees), up, and the projection.

    Examples
    --------
    >>> State().projection
    'perspective'
    """

    eye_x: float = 4.5
    eye_y: float = -5.5
    eye_z: float = 3.0
    azimuth_deg: float = 128.0       # direction of view, about z from +x
    elevation_deg: float = -22.0     # and above (+) or below (-) the horizon
    up_x: float = 0.0
    up_y: float = 0.0
    up_z: float = 1.0
    projection: str = "perspective"
    fov_deg: float = 45.0            # perspective: vertical field of view
    half_size: float = 2.5           # orthographic and oblique: half the window's height
    near: float = 1.0
    far: float = 12.0
    oblique_deg: float = 45.0        # oblique: the angle of the receding axis in the picture
    oblique_scale: float = 0.5       # and its length factor (0.5 cabinet, 1 cavalier)


def gaze_direction(azimuth_deg, elevation_deg):
    """The unit direction of view from its azimuth and elevation (degrees).

    Examples
    --------
    >>> gaze_direction(90, 0).round(12) + 0.0
    array([0., 1., 0.])
    """
    a, e = np.radians([azimuth_deg, elevation_deg])
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def camera_matrices(state):
    """The view matrix (WCS -> ECS) and projection matrix (ECS -> CSS) of the state.

    Raises
    ------
    ValueError
        From :mod:`course_lib.viewing` for an impossible camera (up parallel to the direction
        of view, near >= far, ...).

    Examples
    --------
    >>> V, P = camera_matrices(State(projection="orthographic"))
    >>> V.shape, P[3].tolist()
    ((4, 4), [0.0, 0.0, 0.0, 1.0])
    """
    eye = [state.eye_x, state.eye_y, state.eye_z]
    up = [state.up_x, state.up_y, state.up_z]
    view = viewing.look_at(eye, gaze_direction(state.azimuth_deg, state.elevation_deg), up)
    h = state.half_size
    if state.projection == "perspective":
        proj = viewing.perspective(np.radians(state.fov_deg), 1.0, state.near, state.far)
    elif state.projection == "orthographic":
        proj = viewing.orthographic(-h, h, -h, h, state.near, state.far)
    elif state.projection == "oblique":
        angle = np.radians(state.oblique_deg)
        dop = [state.oblique_scale * np.cos(angle), state.oblique_scale * np.sin(angle), -1.0]
        # shear along the direction of projection, then the orthographic box; the window is
        # centred on the middle of the depth range so the picture stays in view
        middle = -(state.near + state.far) / 2
        shift = transforms.translate([-dop[0] * middle, -dop[1] * middle, 0.0])
        proj = (viewing.orthographic(-h, h, -h, h, state.near, state.far)
                @ shift @ viewing.oblique(dop, keep_depth=True))
    else:
        raise ValueError(f"projection must be one of {PROJECTIONS}, got {state.projection!r}")
    return view, proj


def scene(state):
    """Pure part: the camera, its view volume in the world, and the picture it takes.

    Returns
    -------
    dict
        ``error`` (a message, or None when the camera is valid; then nothing else is given),
        ``view`` and ``projection`` (the two matrices), ``eye``, ``axes`` (3x3, columns
        :math:`x_e, y_e, z_e` in world coordinates), ``volume`` (12 edges of the view volume,
        shape (12, 2, 3), cut to the world's reach, NaN where an edge is out of reach), ``polygons`` and ``colors`` (the clipped faces in the canonical
        square, far to near), ``lines`` (the clipped ground grid in the canonical square) and
        ``text`` (the matrices, HTML with LaTeX).

    Examples
    --------
    >>> s = scene(State())
    >>> s["error"] is None, s["volume"].shape, len(s["polygons"]) > 10
    (True, (12, 2, 3), True)
    >>> scene(State(up_x=0, up_y=0, up_z=0))["error"]
    'up must not be the zero vector'
    """
    try:
        view, proj = camera_matrices(state)
    except ValueError as error:
        return {"error": str(error)}
    m = proj @ view
    corners = transforms.apply(np.linalg.inv(m), _CUBE)
    edges = corners[np.array(_EDGES)]
    # draw the view volume only within the world's reach (a far plane can be far away)
    start, end, shown = clipping.liang_barsky_many(edges[:, 0], edges[:, 1], [-_REACH] * 3,
                                                   [_REACH] * 3)
    edges = np.where(shown[:, None, None], np.stack([start, end], axis=1), np.nan)
    planes = clipping.view_volume_planes(m)
    polygons, colors, depths = [], [], []
    for face, color in zip(_FACES, _COLORS):
        clipped = clipping.clip_polygon(face, planes)
        if len(clipped) >= 3:
            css = transforms.apply(m, clipped)
            polygons.append(css[:, :2])
            colors.append(color)
            depths.append(css[:, 2].mean())
    # far (z = +1) first: painter's order. Faces at equal depth (symmetric ones: equal up to a
    # last bit that depends on the CPU's BLAS and SIMD kernels) stay in their listed order: the
    # depths are rounded to 1e-9 (far below a depth-buffer step) and sorted stably.
    order = np.argsort(-np.round(depths, 9), kind="stable")
    lines = []
    for a, b in _GRID:
        piece = clipping.clip_segment(a, b, planes)
        if piece is not None:
            lines.append(transforms.apply(m, np.array(piece))[:, :2])
    axes = view[:3, :3].T                                   # columns: x_e, y_e, z_e in WCS
    eye = np.array([state.eye_x, state.eye_y, state.eye_z])
    text = (f"<i>M</i><sub>WCS→ECS</sub> = {fmt.matrix_html(view, 2)} &nbsp; "
            f"<i>M</i><sub>ECS→CSS</sub> = {fmt.matrix_html(proj, 2)}<br>"
            f"<i>x<sub>e</sub></i> = {fmt.vector_html(axes[:, 0], 2)}, "
            f"<i>y<sub>e</sub></i> = {fmt.vector_html(axes[:, 1], 2)}, "
            f"<i>z<sub>e</sub></i> = {fmt.vector_html(axes[:, 2], 2)} "
            "(the rows of the rotation part)")
    return {"error": None, "view": view, "projection": proj, "eye": eye, "axes": axes,
            "volume": edges, "polygons": [polygons[i] for i in order],
            "colors": [colors[i] for i in order], "lines": lines, "text": text}


class CameraExplorer(Explorer):
    """Sliders for the eye, the direction of view, up and the projection; world and picture.

    In a notebook, after ``%matplotlib widget``, end a cell with ``CameraExplorer()``.

    Examples
    --------
    >>> explorer = CameraExplorer()
    >>> explorer.controls["projection"].value = "orthographic"
    >>> explorer.state.projection, "ECS→CSS" in explorer.info.value
    ('orthographic', True)
    """

    summary = ("Camera explorer (interactive): eye, direction of view, up and projection "
               "sliders; the view volume in the world and the picture the camera takes.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection, PolyCollection
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(8.4, 4.2))
        world_ax = self.fig.add_axes((0.0, 0.0, 0.52, 0.93), projection="3d")
        draw.setup_axes_3d(world_ax, radius=5.5, title="the world (WCS)", box=False,
                           elev=28, azim=-35)
        for line in _GRID:
            world_ax.plot(*line.T, color="0.85", lw=0.6)
        world_ax.add_collection3d(Poly3DCollection(_FACES, facecolors=_COLORS, edgecolor="0.3",
                                                   linewidth=0.4))
        (self.eye_point,) = world_ax.plot([], [], [], "ko", ms=5)
        self.ecs_axes = draw.frame_3d(world_ax, lw=2.2)
        (self.volume,) = world_ax.plot([], [], [], color="0.2", lw=1.0)
        image = self.fig.add_axes((0.57, 0.1, 0.4, 0.8))
        image.set(xlim=(-1, 1), ylim=(-1, 1), aspect="equal", xticks=[-1, 0, 1],
                  yticks=[-1, 0, 1], xlabel="x (CSS)", ylabel="y (CSS)")
        image.set_title("what the camera sees")
        image.set_facecolor("#f4f7fb")
        self.grid_lines = LineCollection([], colors="0.8", linewidths=0.6)
        self.image_faces = PolyCollection([], edgecolors="0.3", linewidths=0.4)
        image.add_collection(self.grid_lines)
        image.add_collection(self.image_faces)
        self.message = image.text(0, 0, "", ha="center", va="center", color="#c62828",
                                  fontsize=_style.ANNOTATION, wrap=True)
        self.blitter = draw.Blitter(self.fig, [self.eye_point, *self.ecs_axes, self.volume,
                                               self.grid_lines, self.image_faces, self.message])

        self.controls = {name: slider(description, getattr(self.state, name), low, high, step,
                                      body=180)
                         for name, (description, low, high, step) in self.SLIDERS.items()}
        projection = w.ToggleButtons(options=PROJECTIONS, value=self.state.projection,
                                     style={"button_width": "auto"})   # each fits its name
        self.controls["projection"] = projection
        bind(self.state, self.controls, self._on_change)
        c = self.controls
        for names in (("eye_x", "eye_y", "eye_z", "azimuth_deg", "elevation_deg"),
                      ("up_x", "up_y", "up_z", "near", "far"),
                      ("fov_deg", "half_size", "oblique_deg", "oblique_scale")):
            align(c[name] for name in names)
        columns = w.HBox([
            w.VBox([w.HTML("<b>eye</b>"), c["eye_x"], c["eye_y"], c["eye_z"],
                    w.HTML("<b>direction of view</b>"), c["azimuth_deg"], c["elevation_deg"]]),
            w.VBox([w.HTML("<b>up</b>"), c["up_x"], c["up_y"], c["up_z"],
                    w.HTML("<b>view volume</b>"), c["near"], c["far"]]),
            w.VBox([projection, c["fov_deg"], c["half_size"], c["oblique_deg"],
                    c["oblique_scale"]]),
        ], layout=w.Layout(flex_flow="row wrap", grid_gap="0 8px"))
        self.info = panel()
        _style.style_figure(self.fig)
        self.widget = w.VBox([self.fig.canvas, columns, self.info])
        self._enable_projection_controls()
        self._draw(s)

    #: The sliders, field of ``State`` -> (description, min, max, step).
    SLIDERS = {"eye_x": ("eye x", -8, 8, 0.1), "eye_y": ("eye y", -8, 8, 0.1),
               "eye_z": ("eye z", -2, 8, 0.1),
               "azimuth_deg": ("gaze azimuth °", -180, 180, 1),
               "elevation_deg": ("gaze elevation °", -89, 89, 1),
               "up_x": ("up x", -1, 1, 0.1), "up_y": ("up y", -1, 1, 0.1),
               "up_z": ("up z", -1, 1, 0.1),
               "fov_deg": ("fov °", 10, 120, 1), "half_size": ("half size", 0.5, 6, 0.1),
               "near": ("near", 0.1, 6, 0.1), "far": ("far", 1, 25, 0.1),
               "oblique_deg": ("oblique angle φ °", 0, 90, 1),
               "oblique_scale": ("oblique scale k", 0, 1, 0.05)}

    #: The sliders each projection reads (the others are greyed out: moving them would do
    #: nothing to the picture).
    PROJECTION_CONTROLS = {"perspective": ("fov_deg",),
                           "orthographic": ("half_size",),
                           "oblique": ("half_size", "oblique_deg", "oblique_scale")}

    def _enable_projection_controls(self):
        used = self.PROJECTION_CONTROLS[self.state.projection]
        for name in set().union(*self.PROJECTION_CONTROLS.values()):
            self.controls[name].disabled = name not in used

    def _on_change(self):
        self._enable_projection_controls()
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        if s["error"] is not None:
            self.message.set_text("This camera is impossible:\n" + s["error"])
            self.info.value = f"<span style='color:#c62828'><b>{s['error']}</b></span>"
            return
        self.message.set_text("")
        eye = s["eye"]
        self.eye_point.set_data_3d([eye[0]], [eye[1]], [eye[2]])
        draw.set_frame_3d(self.ecs_axes, s["axes"], origin=eye)
        edges = s["volume"]
        gaps = np.full((len(edges), 1, 3), np.nan)
        path = np.concatenate([edges, gaps], axis=1).reshape(-1, 3)
        self.volume.set_data_3d(*path.T)
        self.image_faces.set_verts(s["polygons"])
        self.image_faces.set_facecolor(s["colors"])
        self.grid_lines.set_segments(s["lines"])
        self.info.value = s["text"]
