r"""Relief explorer: one height map on a lit plane or sphere, shaded flat, bump mapped, normal
mapped or truly displaced, with the tangent frame (T, B, N) at a picked point.

The picture is an orthographic view along :math:`-z` (the viewer at :math:`+z`), 128 x 128
pixels. The plane :math:`P = (u, v, 0)` fills the image; the unit sphere is textured with
:func:`course_lib.texturing.spherical_map` (pole on :math:`y`). The world height is
:math:`a\,h(u, v)` with :math:`h \in [0, 1]` and the amplitude :math:`a` = strength x 0.03
(plane) or x 0.08 (sphere).

* **flat**: the surface's own normal.
* **bump**: Blinn's normal :func:`course_lib.texturing.bump_normal` from the analytic tangents
  :math:`P_u, P_v` and the height derivatives :math:`a h_u, a h_v`.
* **normal map**: an 8-bit tangent-space map baked from the height map
  (:func:`course_lib.texturing.normal_map_from_height`, texture square = the plane's 1 x 1, or
  the sphere's equator scale :math:`2\pi \times \pi`), decoded and taken to object space with
  the orthonormal (T, B, N). On the sphere it matches bump mapping at the equator only: the
  map does not know that texels shrink by :math:`\cos\varphi` towards the poles.
* **displacement**: the points really move, :math:`P' = P + a h N`; on the sphere a dense grid
  of displaced points is splatted into a z-buffer and its normals are the finite-difference
  normals of the displaced grid. The dashed circle is the undisplaced outline: only this mode
  leaves it.

A click on the image picks the point whose frame is drawn (T red, B green, N blue, the
perturbed normal black; their projections on the image plane).
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from ..texturing import relief as R
from ..texturing.mappings import spherical_map
from ..texturing.sampling import bilinear_sample
from . import _style
from ._base import Explorer, bind, panel, slider

__all__ = ["HEIGHT_MAPS", "MODES", "ReliefExplorer", "State", "SURFACES", "scene"]

HEIGHT_MAPS = ("bumps", "bricks", "noise")
SURFACES = ("plane", "sphere")
MODES = ("flat", "bump", "normal map", "displacement")
SIZE = 128                         # image pixels
TEXTURE = 128                      # height map texels
EXTENT = 1.25                      # the sphere's image covers [-EXTENT, EXTENT]^2
AMPLITUDE = {"plane": 0.03, "sphere": 0.08}
GRID = (384, 192)                  # displaced sphere: samples in u and v


@dataclass
class State:
    """Height map, surface, mode, light direction, strength and the picked point.

    Examples
    --------
    >>> State().mode, State().surface
    ('bump', 'sphere')
    """

    height_map: str = "bumps"
    surface: str = "sphere"
    mode: str = "bump"
    light_azimuth_deg: float = 35.0
    light_elevation_deg: float = 40.0
    strength: float = 0.6
    pick_x: float = 0.62           # fractions of the image, x right, y up
    pick_y: float = 0.58


@lru_cache(maxsize=None)
def _height(name):
    if name == "bumps":
        h = R.bumps_height(TEXTURE, count=6)
    elif name == "bricks":
        h = R.bricks_height(TEXTURE, rows=8, columns=4, mortar=0.12)
    else:
        h = R.noise_height(TEXTURE, frequency=6.0, octaves=3, seed=3)
    h.setflags(write=False)
    return h


@lru_cache(maxsize=None)
def _gradient(name):
    return R.height_gradient(_height(name), wrap="repeat")


@lru_cache(maxsize=None)
def _geometry(surface):
    """Per pixel: mask, P, u, v, P_u, P_v, unit T, B, N (the undisplaced surface)."""
    c = (np.arange(SIZE) + 0.5) / SIZE
    if surface == "plane":
        u, v = np.meshgrid(c, c)
        mask = np.ones((SIZE, SIZE), bool)
        p = np.stack([u, v, np.zeros_like(u)], axis=-1)
        pu = np.broadcast_to([1.0, 0.0, 0.0], p.shape)
        pv = np.broadcast_to([0.0, 1.0, 0.0], p.shape)
    else:
        x, y = np.meshgrid(EXTENT * (2 * c - 1), EXTENT * (2 * c - 1))
        rr = x * x + y * y
        mask = rr < 1.0
        z = np.sqrt(np.clip(1.0 - rr, 0.0, None))
        p = np.stack([x, y, z], axis=-1)
        u, v = np.full(x.shape, 0.5), np.full(x.shape, 0.5)
        u[mask], v[mask] = spherical_map(p[mask])
        theta, phi = 2 * np.pi * (u - 0.5), np.pi * (v - 0.5)
        # P = (cos phi sin theta, sin phi, cos phi cos theta): dP/du and dP/dv
        pu = 2 * np.pi * np.stack([np.cos(phi) * np.cos(theta), 0 * phi,
                                   -np.cos(phi) * np.sin(theta)], axis=-1)
        pv = np.pi * np.stack([-np.sin(phi) * np.sin(theta), np.cos(phi),
                               -np.sin(phi) * np.cos(theta)], axis=-1)
    t = pu / np.maximum(np.linalg.norm(pu, axis=-1, keepdims=True), 1e-12)
    b = pv / np.linalg.norm(pv, axis=-1, keepdims=True)
    n = np.cross(t, b)
    return dict(mask=mask, p=p, u=u, v=v, pu=np.array(pu), pv=np.array(pv), t=t, b=b, n=n)


@lru_cache(maxsize=8)
def _normal_map(name, surface, amplitude):
    extent = (1.0, 1.0) if surface == "plane" else (2 * np.pi, np.pi)
    rgb8 = np.round(255 * R.normal_map_from_height(_height(name), amplitude, extent)).astype(
        np.uint8)
    return rgb8, R.decode_normals(rgb8)


@lru_cache(maxsize=4)
def _displaced_sphere(name, amplitude):
    """Splat a dense displaced sphere into a z-buffer: (mask, per-pixel normals)."""
    gu, gv = GRID
    u, v = np.meshgrid((np.arange(gu) + 0.5) / gu, (np.arange(gv) + 0.5) / gv)
    theta, phi = 2 * np.pi * (u - 0.5), np.pi * (v - 0.5)
    n = np.stack([np.cos(phi) * np.sin(theta), np.sin(phi), np.cos(phi) * np.cos(theta)], -1)
    q = R.displace(n, n, bilinear_sample(_height(name), u, v), amplitude)
    qu = np.roll(q, -1, axis=1) - np.roll(q, 1, axis=1)          # periodic in u
    qv = np.gradient(q, axis=0)
    normal = np.cross(qu, qv)
    normal /= np.maximum(np.linalg.norm(normal, axis=-1, keepdims=True), 1e-300)
    q, normal = q.reshape(-1, 3), normal.reshape(-1, 3)
    front = q[:, 2] > -0.2
    q, normal = q[front], normal[front]
    col = np.floor((q[:, 0] / EXTENT + 1) / 2 * SIZE).astype(int)
    row = np.floor((q[:, 1] / EXTENT + 1) / 2 * SIZE).astype(int)
    ok = (col >= 0) & (col < SIZE) & (row >= 0) & (row < SIZE)
    pixel, depth, normal = (row * SIZE + col)[ok], q[ok, 2], normal[ok]
    order = np.argsort(-depth, kind="stable")
    first_pixel, first = np.unique(pixel[order], return_index=True)
    out = np.zeros((SIZE * SIZE, 3))
    out[first_pixel] = normal[order[first]]
    mask = np.zeros(SIZE * SIZE, bool)
    mask[first_pixel] = True
    return mask.reshape(SIZE, SIZE), out.reshape(SIZE, SIZE, 3)


def light_direction(azimuth_deg, elevation_deg):
    """The unit vector towards the light: azimuth in the image plane from +x, elevation
    towards the viewer (+z).

    Examples
    --------
    >>> light_direction(0, 90).round(12) + 0.0
    array([0., 0., 1.])
    """
    a, e = np.radians(azimuth_deg), np.radians(elevation_deg)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def scene(state):
    """State -> the shaded image, the per-pixel normals and mask, and the picked frame.

    Examples
    --------
    >>> s = scene(State(mode="flat"))
    >>> s["image"].shape, s["mask"].sum() < 128 * 128
    ((128, 128, 3), np.True_)
    """
    g = _geometry(state.surface)
    amp = float(state.strength) * AMPLITUDE[state.surface]
    mask = g["mask"]
    normals = np.array(g["n"])
    if state.mode == "bump":
        h_u, h_v = _gradient(state.height_map)
        hu = bilinear_sample(h_u, g["u"][mask], g["v"][mask])
        hv = bilinear_sample(h_v, g["u"][mask], g["v"][mask])
        normals[mask] = R.bump_normal(g["pu"][mask], g["pv"][mask], amp * hu, amp * hv)
    elif state.mode == "normal map":
        _, decoded = _normal_map(state.height_map, state.surface, amp)
        nt = bilinear_sample(decoded, g["u"][mask], g["v"][mask])
        normals[mask] = R.tangent_to_object(nt, g["t"][mask], g["b"][mask], g["n"][mask])
    elif state.mode == "displacement":
        if state.surface == "sphere":
            mask, normals = _displaced_sphere(state.height_map, amp)
        else:                        # seen head-on, a displaced plane keeps its (u, v) pixels
            h_u, h_v = _gradient(state.height_map)
            hu = bilinear_sample(h_u, g["u"], g["v"])
            hv = bilinear_sample(h_v, g["u"], g["v"])
            normals = np.stack([-amp * hu, -amp * hv, np.ones_like(hu)], axis=-1)
            normals /= np.linalg.norm(normals, axis=-1, keepdims=True)
    light = light_direction(state.light_azimuth_deg, state.light_elevation_deg)
    image = R.shade_normals(normals, light=light, model="blinn-phong", mask=mask)
    col = int(np.clip(state.pick_x * SIZE, 0, SIZE - 1))
    row = int(np.clip(state.pick_y * SIZE, 0, SIZE - 1))
    inside = bool(g["mask"][row, col])
    frame = None
    if inside:
        frame = dict(t=g["t"][row, col], b=g["b"][row, col], n=g["n"][row, col],
                     bent=normals[row, col] if mask[row, col] else g["n"][row, col],
                     u=float(g["u"][row, col]), v=float(g["v"][row, col]))
    text = _text(state, frame, light, mask, g["mask"])
    return dict(image=image, normals=normals, mask=mask, light=light, frame=frame,
                pixel=(row, col), amplitude=amp, text=text)


def _vec(x):
    return "(" + ", ".join(f"{c:+.2f}" for c in x) + ")"


def _text(state, frame, light, mask, flat_mask):
    lines = [f"<b>{state.mode}</b> on the {state.surface}, height map <i>{state.height_map}</i>,"
             f" L = {_vec(light)}."]
    if frame is None:
        lines.append("Click on the surface to see its tangent frame.")
    else:
        lines.append(f"At (u, v) = ({frame['u']:.3f}, {frame['v']:.3f}): "
                     f"<span style='color:#c62828'>T = {_vec(frame['t'])}</span>, "
                     f"<span style='color:#2e7d32'>B = {_vec(frame['b'])}</span>, "
                     f"<span style='color:#1565c0'>N = {_vec(frame['n'])}</span>, "
                     f"shading normal N' = {_vec(frame['bent'])}.")
    if state.mode == "displacement" and state.surface == "sphere":
        grown = int(mask.sum()) - int(flat_mask.sum())
        lines.append(f"The outline moved: {grown:+d} pixels of silhouette area. Bump and normal "
                     "maps never change it.")
    return "<br>".join(lines)


class ReliefExplorer(Explorer):
    """Height map and surface menus, mode buttons, light sliders, strength; click to pick.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ReliefExplorer()``.

    Examples
    --------
    >>> explorer = ReliefExplorer()
    >>> explorer.mode.value = "flat"
    >>> explorer.picture.get_array().shape
    (128, 128, 3)
    """

    summary = ("Relief explorer (interactive): a height map on a lit plane or sphere, shaded "
               "flat, with bump mapping, with a normal map or truly displaced (only that changes "
               "the outline), and the tangent frame at a clicked point.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(3.6, 3.6))
        self.ax = self.fig.add_axes((0.02, 0.02, 0.96, 0.9))
        self.ax.set_axis_off()
        self.picture = self.ax.imshow(np.ones((SIZE, SIZE, 3)), origin="lower",
                                      extent=(0, SIZE, 0, SIZE), interpolation="nearest")
        t = np.linspace(0, 2 * np.pi, 200)
        r = SIZE / 2 / EXTENT
        (self.outline,) = self.ax.plot(SIZE / 2 + r * np.cos(t), SIZE / 2 + r * np.sin(t),
                                       color="0.4", lw=0.8, ls="--")
        self.arrows = {k: self.ax.plot([], [], color=c, lw=2)[0] for k, c in
                       (("t", "#c62828"), ("b", "#2e7d32"), ("n", "#1565c0"), ("bent", "k"))}
        (self.marker,) = self.ax.plot([], [], "o", color="#ffc107", mec="k", ms=5)
        self.title = self.ax.set_title("", fontsize=9)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.picture, self.outline, *self.arrows.values(),
                                               self.marker, self.title])
        self.height_map = w.Dropdown(options=HEIGHT_MAPS, value=self.state.height_map,
                                     description="height map", layout=w.Layout(width="220px"))
        self.surface = w.ToggleButtons(options=SURFACES, value=self.state.surface,
                                       style={"button_width": _style.button_width(*SURFACES)})
        self.mode = w.ToggleButtons(options=MODES, value=self.state.mode,
                                    style={"button_width": _style.button_width(*MODES)})
        self.azimuth = slider("light azimuth °", self.state.light_azimuth_deg, -180, 180, 1)
        self.elevation = slider("light elevation °", self.state.light_elevation_deg, 5, 90, 1)
        self.strength = slider("strength", self.state.strength, 0, 1, 0.02)
        self.controls = {"height_map": self.height_map, "surface": self.surface,
                         "mode": self.mode, "light_azimuth_deg": self.azimuth,
                         "light_elevation_deg": self.elevation, "strength": self.strength}
        bind(self.state, self.controls, self.update)
        self.info = panel(width="620px")
        self._click = self.fig.canvas.mpl_connect("button_press_event", self._on_click)
        self.widget = w.VBox([
            w.HBox([self.fig.canvas,
                    w.VBox([self.height_map, self.surface, self.mode, self.azimuth,
                            self.elevation, self.strength])],
                   layout=w.Layout(flex_flow="row wrap")),
            self.info])
        self._draw(scene(self.state))

    def mouse_gestures(self):
        """A click on the image (picks the point whose frame is drawn).

        Examples
        --------
        >>> [g["kind"] for g in ReliefExplorer().mouse_gestures()]
        ['click']
        """
        point = self._canvas_fraction(self.ax, (0.35 * SIZE, 0.45 * SIZE))
        return super().mouse_gestures() + [{"kind": "click", "what": "a point of the surface",
                                            "start": point, "end": point}]

    def _on_click(self, event):
        if event.inaxes is not self.ax or event.xdata is None:
            return
        self.state.pick_x = float(np.clip(event.xdata / SIZE, 0, 1))
        self.state.pick_y = float(np.clip(event.ydata / SIZE, 0, 1))
        self.update()

    def update(self):
        """Recompute the scene (static parts cached) and redraw the image and the frame."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.current = s
        self.picture.set_data(s["image"])
        self.outline.set_visible(self.state.surface == "sphere")
        row, col = s["pixel"]
        x0, y0 = col + 0.5, row + 0.5
        frame = s["frame"]
        for key, line in self.arrows.items():
            if frame is None:
                line.set_data([], [])
            else:
                d = 22.0 * frame[key]
                line.set_data([x0, x0 + d[0]], [y0, y0 + d[1]])
        self.marker.set_data([x0], [y0])
        self.title.set_text(f"{self.state.mode}: T red, B green, N blue, N' black")
        self.info.value = s["text"]
