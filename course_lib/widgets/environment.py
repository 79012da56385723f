r"""Environment-mapping explorer: a mirror object in a procedural environment, looked up in a
cube map, a sphere map or a latitude-longitude map, beside the map itself.

Left: a mirror sphere (or a tilted mirror torus) seen orthographically from the orbiting
camera (azimuth, elevation); every pixel's reflection vector :math:`R = I - 2 (N \cdot I) N`
(:func:`course_lib.texturing.reflect_view`) is looked up in the chosen map, and the background
is the map seen straight along the view rays. Right: how that map stores the environment (the
cube map unfolded as a cross, the sphere-map disc, the latitude-longitude rectangle) with the
texel that the picked pixel reads marked (click a pixel of the object to pick it).

The sphere map is made once for the camera looking along -z (azimuth 0, elevation 0): orbit
away from it and the object starts to read the stretched rim of the disc, its singular
direction; the cube and lat-long maps do not depend on the view. Maps and the object's
geometry for a view are cached, so a control move is a look-up of SIZE x SIZE directions.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from ..texturing import environment as env
from . import _style
from ._base import Explorer, labelled, panel, slider

__all__ = ["EnvironmentMapExplorer", "KINDS", "SHAPES", "SIZE", "State", "geometry", "maps",
           "scene"]

SIZE = 128
KINDS = ("cube", "sphere", "latlong")
SHAPES = ("sphere", "torus")
CUBE_N, SPHERE_N, LATLONG_H = 64, 128, 64
_TORUS = (0.62, 0.3)                       # major and minor radius
_TILT = np.radians(35.0)


@dataclass
class State:
    """What the picture depends on."""
    environment: str = "room"
    kind: str = "cube"
    shape: str = "sphere"
    azimuth_deg: float = 0.0
    elevation_deg: float = 15.0
    pick_x: float = 0.62                   # the picked pixel, fractions of the image
    pick_y: float = 0.64


@lru_cache(maxsize=None)
def maps(environment, kind):
    """The (cached) map of `kind` for the named procedural environment."""
    f = env.ENVIRONMENTS[environment]
    if kind == "cube":
        return env.cube_map_from_function(f, CUBE_N)
    if kind == "sphere":
        return env.sphere_map_from_function(f, SPHERE_N, background=1.0)
    return env.latlong_map_from_function(f, LATLONG_H)


@lru_cache(maxsize=None)
def display(environment, kind):
    """The map as shown on the right (the cube map as a cross)."""
    m = maps(environment, kind)
    return env.cube_cross(m) if kind == "cube" else m


def _camera(azimuth_deg, elevation_deg):
    az, el = np.radians(azimuth_deg), np.radians(elevation_deg)
    back = np.array([np.cos(el) * np.sin(az), np.sin(el), np.cos(el) * np.cos(az)])
    right = np.array([np.cos(az), 0.0, -np.sin(az)])
    up = np.cross(back, right)
    return np.stack([right, up, back])


def _torus_hits(origins, direction, frame_world):
    """Sphere tracing of the tilted torus along parallel rays: (mask, points, normals)."""
    big, small = _TORUS
    c, s = np.cos(_TILT), np.sin(_TILT)
    rot = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])      # torus axis y tilted about x
    o = origins @ rot                                      # world -> torus local (rot^T p)
    d = direction @ rot
    t = np.zeros(len(o))
    for _ in range(48):
        p = o + t[:, None] * d
        q = np.hypot(np.hypot(p[:, 0], p[:, 2]) - big, p[:, 1]) - small
        t += q
    p = o + t[:, None] * d
    q = np.hypot(np.hypot(p[:, 0], p[:, 2]) - big, p[:, 1]) - small
    mask = np.abs(q) < 1e-3
    ring = np.hypot(p[:, 0], p[:, 2])
    centre = np.stack([p[:, 0], np.zeros_like(ring), p[:, 2]], -1) * (
        big / np.maximum(ring, 1e-12))[:, None]
    n = p - centre
    n /= np.maximum(np.linalg.norm(n, axis=1), 1e-12)[:, None]
    return mask, (p @ rot.T), n @ rot.T


@lru_cache(maxsize=64)
def geometry(shape, azimuth_deg, elevation_deg):
    """The object seen from the orbit camera: mask, world normals, view direction, frame."""
    frame = _camera(azimuth_deg, elevation_deg)
    if shape == "sphere":
        m = env.mirror_sphere(SIZE, eye_direction=frame[2], up=frame[1])
        return m["mask"], m["normals"], m["view"], frame
    g = (2 * np.arange(SIZE) + 1) / SIZE - 1
    y, x = np.meshgrid(g, g, indexing="ij")
    origins = (x.reshape(-1, 1) * frame[0] + y.reshape(-1, 1) * frame[1] + 3 * frame[2])
    mask, _, normals = _torus_hits(origins, -frame[2], frame)
    normals = np.where(mask[:, None], normals, 0.0)
    return mask.reshape(SIZE, SIZE), normals.reshape(SIZE, SIZE, 3), -frame[2], frame


def _map_position(kind, direction, shape):
    """Where `direction` is read in the displayed map, in its pixel units (x, y)."""
    d = np.asarray(direction, dtype=float)[None]
    if kind == "cube":
        return env.cross_position(d)[0] * CUBE_N
    if kind == "sphere":
        s, t = env.sphere_map_coordinates(d)
        return np.array([s[0] * shape[1], t[0] * shape[0]])
    u, v = env.latlong_coordinates(d)
    return np.array([u[0] * shape[1], v[0] * shape[0]])


def scene(state):
    """Pure part: the rendered image, the map shown, the picked pixel and its texel, the text."""
    mask, normals, view, frame = geometry(state.shape, float(state.azimuth_deg),
                                          float(state.elevation_deg))
    emap = maps(state.environment, state.kind)
    refl = np.broadcast_to(view, normals.shape).copy()
    refl[mask] = env.reflect_view(view, normals[mask])
    image = env.environment_lookup(state.kind, emap, refl.reshape(-1, 3)).reshape(
        SIZE, SIZE, -1)
    image = np.clip(image, 0, 1)
    shown = display(state.environment, state.kind)
    col = int(np.clip(state.pick_x * SIZE, 0, SIZE - 1))
    row = int(np.clip(state.pick_y * SIZE, 0, SIZE - 1))
    r = refl[row, col]
    on = bool(mask[row, col])
    face, s, t = env.cube_face_coordinates(r)
    texel = _map_position(state.kind, r, shown.shape)
    su, sv = env.sphere_map_coordinates(r)
    lu, lv = env.latlong_coordinates(r)
    what = ("reflection vector R = I − 2(N·I)N" if on else
            "no object here: the view ray itself")
    n = normals[row, col]
    text = (f"<b>pixel</b> (row {row}, column {col}): {what}<br>"
            + (f"N = ({n[0]:.2f}, {n[1]:.2f}, {n[2]:.2f}), " if on else "")
            + f"I = ({view[0]:.2f}, {view[1]:.2f}, {view[2]:.2f}), "
            f"<b>R = ({r[0]:.2f}, {r[1]:.2f}, {r[2]:.2f})</b><br>"
            f"cube map: face {env.CUBE_FACES[int(face)]}, s = {float(s):.3f}, "
            f"t = {float(t):.3f}; sphere map: s = {float(su):.3f}, t = {float(sv):.3f}; "
            f"lat-long: u = {float(lu):.3f}, v = {float(lv):.3f}<br>"
            f"<i>{_KIND_NOTE[state.kind]}</i>")
    return {"image": image, "mask": mask, "map": shown, "pixel": (col + 0.5, row + 0.5),
            "texel": texel, "reflection": r, "face": int(face), "text": text,
            "view": view, "frame": frame}


_KIND_NOTE = {
    "cube": "Cube map: six square faces, the face picked by R's largest component; the least "
            "distortion and independent of the view.",
    "sphere": "Sphere map: one picture of a mirror ball seen along −z, made for azimuth 0 and "
              "elevation 0; orbit away and the object reads the smeared rim (R = (0, 0, −1)).",
    "latlong": "Latitude–longitude map: azimuth across, elevation up; a seam behind (−z) "
               "and the poles (±y) stretched over whole rows.",
}


class EnvironmentMapExplorer(Explorer):
    """A mirror object in a cube, sphere or lat-long map, and the map with the texel read.

    In a notebook, after ``%matplotlib widget``, end a cell with ``EnvironmentMapExplorer()``.

    Examples
    --------
    >>> ex = EnvironmentMapExplorer()
    >>> ex.kind.value = "sphere"
    >>> "Sphere map" in ex.info.value
    True
    """

    summary = ("Environment-mapping explorer (interactive): a mirror sphere or torus in a "
               "procedural environment, looked up in a cube, sphere or latitude-longitude map, "
               "with the map shown beside it and the texel of a clicked pixel marked.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(7.6, 3.3))
        self.ax_image = self.fig.add_axes((0.02, 0.05, 0.38, 0.84))
        self.ax_map = self.fig.add_axes((0.44, 0.05, 0.54, 0.84))
        self.picture = self.ax_image.imshow(s["image"], origin="lower",
                                            extent=(0, SIZE, 0, SIZE), interpolation="nearest")
        self.ax_image.set_title("mirror object (click a pixel)", fontsize=_style.TITLE)
        (self.pixel_marker,) = self.ax_image.plot(*s["pixel"], "o", ms=8, mfc="none",
                                                  mec="#ff2d95", mew=2)
        self.map_image = self.ax_map.imshow(s["map"], origin="lower", interpolation="nearest")
        (self.texel_marker,) = self.ax_map.plot(*s["texel"], "o", ms=8, mfc="none",
                                                mec="#ff2d95", mew=2)
        self.map_title = self.ax_map.set_title("", fontsize=_style.TITLE)
        self._set_map_frame(s)
        for ax in (self.ax_image, self.ax_map):
            ax.set_xticks([])
            ax.set_yticks([])
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.picture, self.pixel_marker,
                                               self.map_image, self.texel_marker])
        self.environment = labelled(w.Dropdown, "environment", options=list(env.ENVIRONMENTS),
                                    value=self.state.environment)
        self.kind = labelled(w.Dropdown, "map", options=[
            ("cube map", "cube"), ("sphere map", "sphere"), ("latitude-longitude", "latlong")],
            value=self.state.kind)
        self.shape = labelled(w.Dropdown, "object", options=list(SHAPES),
                              value=self.state.shape)
        self.azimuth = slider("azimuth °", self.state.azimuth_deg, -180, 180, 5)
        self.elevation = slider("elevation °", self.state.elevation_deg, -80, 80, 5)
        self.controls = {"environment": self.environment, "kind": self.kind,
                         "shape": self.shape, "azimuth_deg": self.azimuth,
                         "elevation_deg": self.elevation}
        for control in self.controls.values():
            control.observe(self._on_change, names="value")
        self._cid = self.fig.canvas.mpl_connect("button_press_event", self._on_click)
        self.info = panel(width="760px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([self.environment, self.kind, self.shape],
                                     layout=w.Layout(flex_flow="row wrap")),
                              w.HBox([self.azimuth, self.elevation],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(s)

    def _set_map_frame(self, s):
        h, w_ = s["map"].shape[:2]
        self.map_image.set_extent((0, w_, 0, h))
        self.ax_map.set_xlim(0, w_)
        self.ax_map.set_ylim(0, h)
        self.map_title.set_text({"cube": "cube map, unfolded (−X −Z +X +Z; +Y, −Y)",
                                 "sphere": "sphere map (made looking along −z)",
                                 "latlong": "latitude–longitude map"}[self.state.kind])
        self._frame_kind = self.state.kind

    def _on_change(self, change):
        for name, control in self.controls.items():
            setattr(self.state, name, control.value)
        self.update()

    def mouse_gestures(self):
        """A click on the rendered object (picks that pixel).

        Examples
        --------
        >>> [g["kind"] for g in EnvironmentMapExplorer().mouse_gestures()]
        ['click']
        """
        pixel = self._canvas_fraction(self.ax_image, (0.35 * SIZE, 0.4 * SIZE))
        return super().mouse_gestures() + [{"kind": "click", "what": "a pixel of the object",
                                            "start": pixel, "end": pixel}]

    def _on_click(self, event):
        if event.inaxes is not self.ax_image or event.xdata is None:
            return
        self.state.pick_x = float(np.clip(event.xdata / SIZE, 0, 0.999))
        self.state.pick_y = float(np.clip(event.ydata / SIZE, 0, 0.999))
        self.update()

    def update(self):
        """Recompute the look-ups (maps and geometry cached) and update the artists."""
        s = scene(self.state)
        self._draw(s)
        if self._frame_kind != self.state.kind:
            self._set_map_frame(s)
            self.fig.canvas.draw_idle()              # the map's frame changed: a full redraw
        else:
            self.blitter.update()

    def _draw(self, s):
        self.picture.set_data(s["image"])
        self.pixel_marker.set_data([s["pixel"][0]], [s["pixel"][1]])
        self.map_image.set_data(s["map"])
        self.texel_marker.set_data([s["texel"][0]], [s["texel"][1]])
        self.info.value = s["text"]
