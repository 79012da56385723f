r"""Environment-mapping explorer: a mirror sphere or torus in a procedural environment, its
reflections looked up in a cube map, a sphere map or a latitude-longitude map (or traced to
the walls of a room, for comparison), beside the map itself with the texel read marked.

**Left: the picture.** A pinhole camera orbits the object (azimuth, elevation) at
:data:`EYE` object radii from its centre, with a field of view of
:math:`2\arctan(`:data:`HALF_FOV`:math:`)`. Every pixel's view ray :math:`I` either misses the
object (the background: the environment in the direction :math:`I`) or hits it at :math:`P`
with the normal :math:`N` and reflects to :math:`R = I - 2 (N \cdot I) N`
(:func:`course_lib.texturing.reflect_view`).

* **environment map**: the pixel's colour is the map looked up at :math:`R` alone
  (:func:`course_lib.texturing.environment_lookup`); where :math:`P` is does not matter.
* **ray traced**: the environment is painted on the walls of a room, the cube of half-size
  :data:`ROOM` around the map's centre (the map is exactly the view from that centre), and the
  reflected ray is followed from :math:`P` to the wall it really hits, :math:`Q`: the colour is
  the environment in the direction of :math:`Q` *from the centre*. The object can be moved
  by ``offset`` along x away from the centre (the camera moves with it); the map cannot follow
  (the distant-environment assumption). On the torus, a reflected ray that hits the torus again
  is reflected a second time (the map has no self-reflection).

**Right: the map** as it is stored (the cube map unfolded as a cross, the sphere-map disc, the
latitude-longitude rectangle) with the texel the picked pixel reads (circle) and, when traced,
the direction of the wall point really hit (cross). A click on the picture picks a pixel.

The sphere map is made once, for the camera looking along -z (azimuth 0, elevation 0): orbit
away and the object reads the smeared rim of the disc, its singular direction; the cube and
lat-long maps do not depend on the view. The maps and the object's geometry for a view (hits,
normals, reflections, second bounces) are cached, so a control move costs at most one set of
SIZE x SIZE look-ups or wall hits.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from .._validate import as_choice, as_scalar
from ..raytracing import intersect_box, intersect_sphere
from ..texturing import environment as env
from . import _style
from ._base import Explorer, align, labelled, panel, slider

__all__ = ["EnvironmentMapExplorer", "EYE", "HALF_FOV", "KINDS", "OFFSET_MAX", "REFLECTIONS",
           "ROOM", "SHAPES", "SIZE", "State", "bounces", "camera", "display", "geometry", "maps",
           "scene"]

SIZE = 128                          # the picture's pixels per side
KINDS = ("cube", "sphere", "latlong")
SHAPES = ("sphere", "torus")
REFLECTIONS = ("map", "traced")
CUBE_N, SPHERE_N, LATLONG_H = 64, 128, 64
EYE = 3.4                           # the camera's distance from the object's centre
HALF_FOV = 0.42                     # tan of half the field of view (about 45 degrees in all)
ROOM = 6.0                          # the room's half-size (object radii) when traced
OFFSET_MAX = 2.5                    # the eye stays inside the room: OFFSET_MAX + EYE < ROOM
TORUS = (0.62, 0.3)                 # major and minor radius
TILT = np.radians(35.0)             # the torus's axis: y tilted about x
MARK = "#ff2d95"


@dataclass
class State:
    """What the picture depends on.

    Examples
    --------
    >>> State().kind, State().reflection, State().offset
    ('cube', 'map', 0.0)
    """
    environment: str = "room"
    kind: str = "cube"
    shape: str = "sphere"
    reflection: str = "map"
    azimuth_deg: float = 0.0
    elevation_deg: float = 15.0
    offset: float = 0.0                 # the object's x from the map's centre (traced only)
    pick_x: float = 0.62                # the picked pixel, fractions of the picture (x right,
    pick_y: float = 0.64                # y up)


def _frozen(*arrays):
    for a in arrays:
        a.setflags(write=False)
    return arrays


@lru_cache(maxsize=None)
def maps(environment, kind):
    """The (cached, read-only) map of `kind` for the named procedural environment.

    Examples
    --------
    >>> maps("room", "cube").shape, maps("sky", "latlong").shape
    ((6, 64, 64, 3), (64, 128, 3))
    """
    f = env.ENVIRONMENTS[environment]
    if kind == "cube":
        m = env.cube_map_from_function(f, CUBE_N)
    elif kind == "sphere":
        m = env.sphere_map_from_function(f, SPHERE_N, background=1.0)
    else:
        m = env.latlong_map_from_function(f, LATLONG_H)
    return _frozen(m)[0]


@lru_cache(maxsize=None)
def display(environment, kind):
    """The map as shown on the right (the cube map unfolded as a cross), read-only.

    Examples
    --------
    >>> display("room", "cube").shape
    (192, 256, 3)
    """
    m = maps(environment, kind)
    return _frozen(np.array(env.cube_cross(m)) if kind == "cube" else m)[0]


def camera(azimuth_deg, elevation_deg):
    """The orbit camera's axes as rows (right, up, back): `back` points from the object's centre
    to the eye; azimuth 0, elevation 0 looks along -z with +y up.

    Examples
    --------
    >>> camera(0, 0) + 0.0
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    az, el = np.radians(azimuth_deg), np.radians(elevation_deg)
    back = np.array([np.cos(el) * np.sin(az), np.sin(el), np.cos(el) * np.cos(az)])
    right = np.array([np.cos(az), 0.0, -np.sin(az)])
    return np.stack([right, np.cross(back, right), back])


def _torus_local():
    c, s = np.cos(TILT), np.sin(TILT)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])     # columns: the torus's axes


def _torus_distance(p):
    big, small = TORUS
    return np.hypot(np.hypot(p[:, 0], p[:, 2]) - big, p[:, 1]) - small


def _torus_march(o, d, t, steps=40, tol=1e-4):
    """Sphere tracing in the torus's own axes from parameters `t`: (hit mask, t). Rays leave
    the loop once they hit or leave the bounding sphere."""
    reach = (TORUS[0] + TORUS[1]) * 1.001
    t = t.copy()
    hit = np.zeros(len(o), bool)
    live = np.arange(len(o))
    for _ in range(steps):
        p = o[live] + t[live, None] * d[live]
        q = _torus_distance(p)
        close = q < tol
        hit[live[close]] = True
        gone = (np.einsum("ij,ij->i", p, p) > reach * reach) & (np.einsum("ij,ij->i", p, d[live])
                                                                 > 0)
        t[live] += q
        live = live[~(close | gone)]
        if not len(live):
            break
    return hit, t


def _torus_normals(p):
    big = TORUS[0]
    ring = np.hypot(p[:, 0], p[:, 2])
    centre = np.stack([p[:, 0], np.zeros_like(ring), p[:, 2]], -1) * (
        big / np.maximum(ring, 1e-12))[:, None]
    n = p - centre
    return n / np.linalg.norm(n, axis=1)[:, None]


def _torus_hits(origins, directions, t_min=0.0):
    """Where rays (world axes, the torus at the origin) first hit the tilted torus beyond
    `t_min`: (mask, points, unit normals), all in world axes."""
    rot = _torus_local()
    o, d = origins @ rot, directions @ rot
    bound = intersect_sphere(o, d, [0, 0, 0], (TORUS[0] + TORUS[1]) * 1.001, t_min=t_min)
    start = np.where(np.isfinite(bound.t), np.maximum(bound.t, t_min), 0.0)
    # rays starting inside the bounding sphere (second bounces) march from t_min
    inside = np.einsum("ij,ij->i", o, o) < ((TORUS[0] + TORUS[1]) * 1.001) ** 2
    start = np.where(inside, t_min, start)
    candidates = np.flatnonzero(np.isfinite(bound.t) | inside)
    mask = np.zeros(len(o), bool)
    points = np.zeros_like(o)
    normals = np.zeros_like(o)
    if len(candidates):
        hit, t = _torus_march(o[candidates], d[candidates], start[candidates])
        idx = candidates[hit]
        p = o[idx] + t[hit, None] * d[idx]
        mask[idx] = True
        points[idx] = p @ rot.T
        normals[idx] = _torus_normals(p) @ rot.T
    return mask, points, normals


@lru_cache(maxsize=32)
def geometry(shape, azimuth_deg, elevation_deg):
    """The object seen from the orbit camera, relative to the object's centre (cached).

    Returns
    -------
    dict of read-only arrays
        ``frame`` (3, 3) the camera's right, up, back; ``eye`` (3,) its position; per pixel
        (SIZE, SIZE, ...): ``rays`` the unit view directions I, ``mask`` where the object is hit,
        ``points`` P and ``normals`` N (zero off the object), ``reflections`` R (I off the
        object: the background reads the view direction).

    Examples
    --------
    >>> g = geometry("sphere", 0.0, 0.0)
    >>> g["mask"][64, 64], g["reflections"][64, 64].round(2)   # the middle: back to the eye
    (np.True_, array([0.02, 0.02, 1.  ]))
    """
    frame = camera(azimuth_deg, elevation_deg)
    eye = EYE * frame[2]
    g = (2 * np.arange(SIZE) + 1) / SIZE - 1
    y, x = np.meshgrid(g, g, indexing="ij")                    # row 0 is the bottom
    rays = (HALF_FOV * x.reshape(-1, 1) * frame[0] + HALF_FOV * y.reshape(-1, 1) * frame[1]
            - frame[2])
    rays /= np.linalg.norm(rays, axis=1)[:, None]
    if shape == "sphere":
        hits = intersect_sphere(eye, rays, [0, 0, 0], 1.0)
        mask = np.isfinite(hits.t)
        points = np.where(mask[:, None], eye + np.where(mask, hits.t, 0)[:, None] * rays, 0.0)
        normals = hits.normals
    else:
        mask, points, normals = _torus_hits(np.broadcast_to(eye, rays.shape), rays)
    refl = rays.copy()
    refl[mask] = env.reflect_view(rays[mask], normals[mask])
    shaped = {k: a.reshape((SIZE, SIZE) + a.shape[1:]) for k, a in
              (("rays", rays), ("mask", mask), ("points", points), ("normals", normals),
               ("reflections", refl))}
    out = {"frame": frame, "eye": eye, **shaped}
    _frozen(*out.values())
    return out


@lru_cache(maxsize=32)
def bounces(shape, azimuth_deg, elevation_deg):
    """Where each pixel's ray finally leaves the object, relative to its centre (cached): the
    eye and I off the object, P and R on it, and, on the torus, the second hit and its
    reflection where R runs into the torus again (a third hit is ignored).

    Returns
    -------
    dict of read-only arrays (SIZE, SIZE, ...)
        ``origins``, ``directions`` and ``self_hit`` (bool: the ray hit the object twice).

    Examples
    --------
    >>> int(bounces("sphere", 0.0, 0.0)["self_hit"].sum())     # a sphere never sees itself
    0
    >>> int(bounces("torus", 0.0, 15.0)["self_hit"].sum()) > 100
    True
    """
    g = geometry(shape, azimuth_deg, elevation_deg)
    mask = g["mask"].reshape(-1)
    origins = np.where(mask[:, None], g["points"].reshape(-1, 3), g["eye"])
    directions = g["reflections"].reshape(-1, 3).copy()
    self_hit = np.zeros(len(mask), bool)
    if shape == "torus" and mask.any():
        idx = np.flatnonzero(mask)
        again, p2, n2 = _torus_hits(origins[idx], directions[idx], t_min=2e-3)
        sub = idx[again]
        self_hit[sub] = True
        origins[sub] = p2[again]
        directions[sub] = env.reflect_view(directions[sub], n2[again])
    out = {"origins": origins.reshape(SIZE, SIZE, 3),
           "directions": directions.reshape(SIZE, SIZE, 3),
           "self_hit": self_hit.reshape(SIZE, SIZE)}
    _frozen(*out.values())
    return out


def _wall_hits(origins, directions, offset):
    """Where rays from `origins` (relative to the object, which sits at x = offset) meet the
    room's walls, relative to the room's centre (the map's centre)."""
    o = origins + np.array([offset, 0.0, 0.0])
    hits = intersect_box(o, directions, [-ROOM] * 3, [ROOM] * 3)
    return o + hits.t[..., None] * directions


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


def _angle(a, b):
    c = np.dot(a, b) / (np.linalg.norm(a) * np.linalg.norm(b))
    return float(np.degrees(np.arccos(np.clip(c, -1, 1))))


def _check(state):
    as_choice(state.environment, "environment", tuple(env.ENVIRONMENTS))
    as_choice(state.kind, "kind", KINDS)
    as_choice(state.shape, "shape", SHAPES)
    as_choice(state.reflection, "reflection", REFLECTIONS)
    az = as_scalar(state.azimuth_deg, "azimuth_deg")
    el = as_scalar(state.elevation_deg, "elevation_deg")
    if not -89 <= el <= 89:
        raise ValueError(f"elevation_deg must be in [-89, 89], got {el:g}")
    offset = as_scalar(state.offset, "offset")
    if abs(offset) > OFFSET_MAX:
        raise ValueError(f"offset must be in [-{OFFSET_MAX:g}, {OFFSET_MAX:g}] (the camera "
                         f"must stay inside the room), got {offset:g}")
    for name in ("pick_x", "pick_y"):
        v = as_scalar(getattr(state, name), name)
        if not 0 <= v <= 1:
            raise ValueError(f"{name} must be a fraction of the picture in [0, 1], got {v:g}")
    return az, el, offset


def scene(state):
    r"""Pure part: the picture, the map shown, the picked pixel, its texel(s) and the text.

    Returns
    -------
    dict
        ``image`` (SIZE, SIZE, 3) row 0 at the bottom; ``map`` the displayed map; ``pixel``
        (x, y) and ``texel`` (x, y) in their pictures' pixel units; ``true_texel`` (x, y) of the
        wall point really hit (traced), or None; ``reflection`` the picked pixel's look-up
        direction; ``on_object``; ``face``, ``s``, ``t`` of its cube-map look-up; ``error_deg``
        the angle between the direction looked up and the direction of the wall point hit
        (traced, else None); ``text``.

    Raises
    ------
    ValueError
        For an unknown environment, kind, shape or reflection, an elevation outside
        [-89, 89], an offset outside [-OFFSET_MAX, OFFSET_MAX] or a pick outside the picture.

    Examples
    --------
    >>> s = scene(State())
    >>> s["image"].shape, s["face"], s["true_texel"] is None
    ((128, 128, 3), 2, True)
    """
    az, el, offset = _check(state)
    g = geometry(state.shape, az, el)
    f = env.ENVIRONMENTS[state.environment]
    mask = g["mask"]
    col = int(min(state.pick_x * SIZE, SIZE - 1))
    row = int(min(state.pick_y * SIZE, SIZE - 1))
    on = bool(mask[row, col])
    r = g["reflections"][row, col]
    shown = display(state.environment, state.kind)
    traced = state.reflection == "traced"
    if traced:
        b = bounces(state.shape, az, el)
        walls = _wall_hits(b["origins"].reshape(-1, 3), b["directions"].reshape(-1, 3), offset)
        image = f(walls).reshape(SIZE, SIZE, 3)
        q = walls[row * SIZE + col]
        error = _angle(r, q)
        true_texel = _map_position(state.kind, q, shown.shape)
        twice = bool(b["self_hit"][row, col])
    else:
        image = env.environment_lookup(state.kind, maps(state.environment, state.kind),
                                       g["reflections"].reshape(-1, 3)).reshape(SIZE, SIZE, 3)
        error, true_texel, twice = None, None, False
    image = np.clip(image, 0, 1)
    face, s_, t_ = (float(x) for x in env.cube_face_coordinates(r))
    texel = _map_position(state.kind, r, shown.shape)
    n = g["normals"][row, col]
    i_ = g["rays"][row, col]
    vec = lambda v: f"({v[0]:.2f}, {v[1]:.2f}, {v[2]:.2f})"
    if state.kind == "cube":
        where = (f"cube map face <b>{env.CUBE_FACES[int(face)]}</b>, s = {s_:.3f}, "
                 f"t = {t_:.3f}")
    elif state.kind == "sphere":
        su, sv = (float(x) for x in env.sphere_map_coordinates(r))
        where = f"sphere map s = {su:.3f}, t = {sv:.3f}"
    else:
        lu, lv = (float(x) for x in env.latlong_coordinates(r))
        where = f"lat-long map u = {lu:.3f}, v = {lv:.3f}"
    text = (f"<b>pixel</b> (row {row}, column {col}): "
            + (f"I = {vec(i_)}, N = {vec(n)}, <b>R = I − 2(N·I)N = {vec(r)}</b>" if on else
               f"background, the view ray I = {vec(i_)} itself")
            + f" → {where} (circle).<br>")
    if traced:
        text += (f"<b>Ray traced</b> in a room of half-size {ROOM:g} with the object at "
                 f"x = {offset:g} from the map's centre: the wall is really hit in the direction "
                 f"{vec(q / np.linalg.norm(q))} (cross), <b>{error:.1f}°</b> from the direction "
                 "the map would read"
                 + (" (after a second reflection on the torus itself: the map has no "
                    "self-reflection)" if twice else "") + ". ")
        text += (f"The map is exact only for a point at its centre: a ray leaving from P "
                 f"meets the walls at most arcsin(|P|/{ROOM:g}) from the direction looked up "
                 f"(the sine rule), here up to arcsin({abs(offset) + 1:g}/{ROOM:g}) ≈ "
                 f"{np.degrees(np.arcsin((abs(offset) + 1) / ROOM)):.0f}° (one reflection).")
    else:
        text += _KIND_NOTE[state.kind]
    return {"image": image, "mask": mask, "map": shown, "pixel": (col + 0.5, row + 0.5),
            "texel": texel, "true_texel": true_texel, "reflection": r, "on_object": on,
            "face": int(face), "s": s_, "t": t_, "error_deg": error, "text": text}


_KIND_NOTE = {
    "cube": "<i>Cube map</i>: six square faces; R's largest component picks the face, the two "
            "others divided by it give (s, t). Little distortion, and it does not depend on "
            "the view.",
    "sphere": "<i>Sphere map</i>: the picture of a mirror ball seen along −z, made for "
              "azimuth 0 and elevation 0. Its whole rim is one direction, (0, 0, −1), straight "
              "away from that viewer: the background, which looks along it, is smeared, and "
              "orbit away and the object reads the smeared rim too.",
    "latlong": "<i>Latitude–longitude map</i>: azimuth across, elevation up. A seam behind "
               "(−z, u = 0 = 1) and the poles (±y) stretched over whole rows.",
}


class EnvironmentMapExplorer(Explorer):
    """A mirror sphere or torus in a cube, sphere or lat-long map (or traced to the room's
    walls), and the map with the texel read.

    In a notebook, after ``%matplotlib widget``, end a cell with ``EnvironmentMapExplorer()``.

    Examples
    --------
    >>> ex = EnvironmentMapExplorer()
    >>> ex.kind.value = "sphere"
    >>> "Sphere map" in ex.info.value
    True
    >>> ex.offset.disabled, ex.reflection.options[1]
    (True, ('ray traced in a room', 'traced'))
    """

    summary = ("Environment-mapping explorer (interactive): a mirror sphere or torus in a "
               "procedural environment, looked up in a cube, sphere or latitude-longitude map "
               "or traced to the walls of a room, with the map shown beside it and the texel "
               "of a clicked pixel marked.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(7.8, 3.35))
        self.ax_image = self.fig.add_axes((0.01, 0.03, 0.37, 0.86))
        self.ax_map = self.fig.add_axes((0.41, 0.03, 0.58, 0.86))
        self.picture = self.ax_image.imshow(s["image"], origin="lower",
                                            extent=(0, SIZE, 0, SIZE), interpolation="nearest")
        self.ax_image.set_title("mirror object (click a pixel)")
        (self.pixel_marker,) = self.ax_image.plot(*s["pixel"], "o", ms=9, mfc="none",
                                                  mec=MARK, mew=2)
        self.map_image = self.ax_map.imshow(s["map"], origin="lower", interpolation="nearest")
        (self.texel_marker,) = self.ax_map.plot(*s["texel"], "o", ms=9, mfc="none", mec=MARK,
                                                mew=2)
        (self.true_marker,) = self.ax_map.plot([], [], "x", ms=9, color="k", mew=2.5)
        self.map_title = self.ax_map.set_title("")
        self.face_labels = []
        for ax in (self.ax_image, self.ax_map):
            ax.set_xticks([])
            ax.set_yticks([])
        self._set_map_frame(s)
        _style.style_figure(self.fig)
        # the map is still while the view, the offset or the pick move: in the background
        self.blitter = draw.Blitter(self.fig, [self.picture, self.pixel_marker,
                                               self.texel_marker, self.true_marker])
        self.environment = labelled(w.Dropdown, "environment", options=list(env.ENVIRONMENTS),
                                    value=self.state.environment)
        self.kind = labelled(w.Dropdown, "map", options=[
            ("cube map", "cube"), ("sphere map", "sphere"), ("latitude-longitude", "latlong")],
            value=self.state.kind)
        self.shape = labelled(w.Dropdown, "object", options=list(SHAPES),
                              value=self.state.shape)
        self.reflection = labelled(w.Dropdown, "reflection", options=[
            ("looked up in the map", "map"), ("ray traced in a room", "traced")],
            value=self.state.reflection)
        self.azimuth = slider("azimuth °", self.state.azimuth_deg, -180, 180, 5)
        self.elevation = slider("elevation °", self.state.elevation_deg, -80, 80, 5)
        self.offset = slider("offset x", self.state.offset, -OFFSET_MAX, OFFSET_MAX, 0.25)
        align([self.environment, self.kind, self.shape, self.reflection])
        align([self.azimuth, self.elevation, self.offset])
        self.controls = {"environment": self.environment, "kind": self.kind,
                         "shape": self.shape, "reflection": self.reflection,
                         "azimuth_deg": self.azimuth, "elevation_deg": self.elevation,
                         "offset": self.offset}
        for control in self.controls.values():
            control.observe(self._on_change, names="value")
        self._cid = self.fig.canvas.mpl_connect("button_press_event", self._on_click)
        self.info = panel(width="700px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([w.VBox([self.environment, self.kind, self.shape,
                                              self.reflection]),
                                      w.VBox([self.azimuth, self.elevation, self.offset])],
                                     layout=w.Layout(flex_flow="row wrap",
                                                     grid_gap="0 16px")),
                              self.info])
        self._draw(s)

    def _set_map_frame(self, s):
        """The map axes for the current kind: extent, limits, title, face names."""
        h, w_ = s["map"].shape[:2]
        self.map_image.set_extent((0, w_, 0, h))
        self.ax_map.set_xlim(0, w_)
        self.ax_map.set_ylim(0, h)
        self.map_title.set_text({"cube": "cube map, unfolded (seen from inside)",
                                 "sphere": "sphere map (made looking along −z)",
                                 "latlong": "latitude–longitude map"}[self.state.kind])
        for label in self.face_labels:
            label.remove()
        self.face_labels = []
        if self.state.kind == "cube":
            for face, ((c, r), _) in env._CROSS.items():
                self.face_labels.append(self.ax_map.text(
                    (c + 0.06) * CUBE_N, (r + 0.94) * CUBE_N, env.CUBE_FACES[face],
                    ha="left", va="top", fontsize=_style.ANNOTATION, color="k", zorder=1.5,
                    bbox={"boxstyle": "round,pad=0.15", "fc": "white", "ec": "none",
                          "alpha": 0.8}))
        self._frame = (self.state.environment, self.state.kind)

    def _on_change(self, change):
        for name, control in self.controls.items():
            setattr(self.state, name, control.value)
        self.update()

    def mouse_gestures(self):
        """A click on the picture (picks that pixel).

        Examples
        --------
        >>> [g["kind"] for g in EnvironmentMapExplorer().mouse_gestures()]
        ['click']
        """
        pixel = self._canvas_fraction(self.ax_image, (0.35 * SIZE, 0.4 * SIZE))
        return super().mouse_gestures() + [{"kind": "click", "what": "a pixel of the picture",
                                            "start": pixel, "end": pixel}]

    def _on_click(self, event):
        if event.inaxes is not self.ax_image or event.xdata is None:
            return
        self.state.pick_x = float(np.clip(event.xdata / SIZE, 0, 1))
        self.state.pick_y = float(np.clip(event.ydata / SIZE, 0, 1))
        self.update()

    def update(self):
        """Recompute the look-ups (maps and geometry cached) and update the artists."""
        s = scene(self.state)
        self._draw(s)
        if self._frame != (self.state.environment, self.state.kind):
            self._set_map_frame(s)
            self.blitter.forget_background()
            self.fig.canvas.draw_idle()              # another map: a full redraw
        else:
            self.blitter.update()

    def _draw(self, s):
        self.current = s
        self.offset.disabled = self.state.reflection != "traced"
        self.picture.set_data(s["image"])
        self.pixel_marker.set_data([s["pixel"][0]], [s["pixel"][1]])
        self.map_image.set_data(s["map"])
        self.texel_marker.set_data([s["texel"][0]], [s["texel"][1]])
        if s["true_texel"] is None:
            self.true_marker.set_data([], [])
        else:
            self.true_marker.set_data([s["true_texel"][0]], [s["true_texel"][1]])
        self.info.value = s["text"]
