"""Two-part mapping explorer: an intermediate surface (S-mapping) and an O-mapping chosen from
menus, a labelled checkerboard shown distorting on a sphere, a torus or a cube, and texture-
transform sliders (tiling, offset, rotation) with the transformed texture beside it."""
import functools
from dataclasses import dataclass

import numpy as np

from .. import draw
from ..raytracing.intersections import intersect_box, intersect_sphere, intersect_triangles
from ..texturing import nearest_sample
from ..texturing.texture_transforms import apply_texture_matrix, texture_matrix, transform_texture
from ..texturing.two_part import SURFACES, two_part_map
from . import _style
from ._base import Explorer, bind, panel, slider

__all__ = ["OBJECTS", "SIZE", "State", "TwoPartMappingExplorer", "geometry", "labelled_texture",
           "scene"]

SIZE = 128                       # the rendered object, pixels
OBJECTS = ("sphere", "torus", "cube")
EYE = np.array([1.7, 1.4, 2.9])
LIGHT = np.array([0.5, 0.8, 0.6]) / np.linalg.norm([0.5, 0.8, 0.6])
SURFACE_SIZE = 1.2               # the intermediate surfaces enclose every object
BACKGROUND = np.array([0.93, 0.93, 0.95])
MISS = np.array([0.55, 0.0, 0.55])

_FONT = {  # 3x5 digits, rows top to bottom
    "0": "111101101101111", "1": "010110010010111", "2": "111001111100111",
    "3": "111001111001111", "4": "101101111001001", "5": "111100111001111",
    "6": "111100111101111", "7": "111001010010010", "8": "111101111101111",
    "9": "111101111001111", "A": "010101111101101", "B": "110101110101110",
    "C": "111100100100111", "D": "110101101101110", "E": "111100111100111",
    "F": "111100111100100"}


@dataclass
class State:
    """Everything the picture depends on: the object, the intermediate surface (S-mapping),
    the O-mapping, and the texture matrix's tiling, offset and rotation (degrees).

    Examples
    --------
    >>> State().object, State().surface, State().method, State().tiling
    ('torus', 'cylinder', 'normal', 1.0)
    """
    object: str = "torus"
    surface: str = "cylinder"
    method: str = "normal"
    tiling: float = 1.0
    offset_u: float = 0.0
    offset_v: float = 0.0
    rotation_deg: float = 0.0


@functools.lru_cache(maxsize=1)
def labelled_texture(n=64):
    """A 4x4 checkerboard, cells labelled 0..F (row 0 = v = 0 holds 0..3), a red corner cell at
    (u, v) = (0, 0) and a blue one at (1, 1): distortion, mirroring and turning all read."""
    cell = n // 4
    i, j = np.mgrid[0:n, 0:n]
    light = ((i // cell + j // cell) % 2 == 0)
    tex = np.where(light[..., None], [0.95, 0.85, 0.45], [0.2, 0.45, 0.35]).astype(float)
    tex[:cell // 3, :cell // 3] = [0.9, 0.1, 0.1]
    tex[n - cell // 3:, n - cell // 3:] = [0.1, 0.2, 0.9]
    scale = max(cell // 8, 1)
    for k, ch in enumerate("0123456789ABCDEF"):
        r, c = divmod(k, 4)
        glyph = np.array([int(b) for b in _FONT[ch]], bool).reshape(5, 3)[::-1]   # v up
        glyph = np.kron(glyph, np.ones((scale, scale), bool))
        gh, gw = glyph.shape
        y0, x0 = r * cell + (cell - gh) // 2, c * cell + (cell - gw) // 2
        ink = [0.05, 0.05, 0.05] if (r + c) % 2 == 0 else [1.0, 1.0, 1.0]
        tex[y0:y0 + gh, x0:x0 + gw][glyph] = ink
    return tex


def _camera_rays(n=SIZE):
    forward = -EYE / np.linalg.norm(EYE)
    right = np.cross(forward, [0, 1, 0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    s = np.tan(np.radians(17.0))
    x = (np.arange(n) + 0.5) / n * 2 - 1
    xx, yy = np.meshgrid(x, x)                  # row 0 at the bottom (origin="lower")
    d = forward + s * (xx[..., None] * right + yy[..., None] * up)
    return d / np.linalg.norm(d, axis=-1, keepdims=True)


def _torus_triangles(big=0.6, small=0.27, nu=48, nv=24):
    a = np.linspace(0, 2 * np.pi, nu + 1)
    b = np.linspace(0, 2 * np.pi, nv + 1)
    aa, bb = np.meshgrid(a, b, indexing="ij")
    pts = np.stack([(big + small * np.cos(bb)) * np.cos(aa), small * np.sin(bb),
                    (big + small * np.cos(bb)) * np.sin(aa)], -1)
    p00, p10, p01, p11 = pts[:-1, :-1], pts[1:, :-1], pts[:-1, 1:], pts[1:, 1:]
    return np.concatenate([np.stack([p00, p10, p11], -2).reshape(-1, 3, 3),
                           np.stack([p00, p11, p01], -2).reshape(-1, 3, 3)])


def _tilt(p):
    """The torus turned 35 degrees about x, so that its hole shows."""
    c, s = np.cos(np.radians(35)), np.sin(np.radians(35))
    r = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    return p @ r.T, r


@functools.lru_cache(maxsize=len(OBJECTS))
def geometry(obj):
    """The object seen from the eye: hit points, unit normals, the pixel mask, Lambert shade.

    Cached per object (ray cast once); the torus's normals are its exact ones (point minus the
    nearest point of its core circle), not the triangles'."""
    d = _camera_rays().reshape(-1, 3)
    if obj == "sphere":
        hits = intersect_sphere(EYE, d, [0, 0, 0], 0.8)
        t, normals = hits.t, hits.normals
    elif obj == "cube":
        hits = intersect_box(EYE, d, [-0.6] * 3, [0.6] * 3)
        t, normals = hits.t, hits.normals
    else:
        tris, r = _tilt(_torus_triangles().reshape(-1, 3))
        t = intersect_triangles(EYE, d, tris.reshape(-1, 3, 3)).t
        normals = None
    mask = np.isfinite(t)
    p = EYE + t[mask, None] * d[mask]
    if normals is None:
        local = p @ r                            # back to the untilted torus
        core = local * [1, 0, 1]
        core = 0.6 * core / np.linalg.norm(core, axis=1, keepdims=True)
        n = local - core
        n = (n / np.linalg.norm(n, axis=1, keepdims=True)) @ r.T
    else:
        n = normals[mask]
    shade = 0.3 + 0.7 * np.clip(n @ LIGHT, 0, 1)
    return p, n, mask.reshape(SIZE, SIZE), shade


def _notes(state):
    notes = []
    if state.object == "sphere" and state.method in ("normal", "centroid"):
        notes.append("On the centred sphere the normal line passes through the centroid: "
                     "'object normal' and 'centroid' give the same picture.")
    if state.object == "sphere" and state.surface == "sphere" and state.method != "reflected":
        notes.append("Sphere on sphere: every non-reflected method is the plain spherical map.")
    if state.method == "reflected":
        notes.append("Reflected ray: depends on the eye (environment mapping); the texture "
                     "is what the object mirrors.")
    if state.surface == "cylinder" and state.method != "intermediate_normal":
        notes.append("Rays along the cylinder's axis never meet it (magenta).")
    if state.surface == "plane":
        notes.append("Plane: projected along z, so the side faces get stretched stripes.")
    return notes


def scene(state):
    """Pure part: state -> the rendered object (SIZE, SIZE, 3), the transformed texture
    (64, 64, 3), the texture matrix, the object's (u, v), the number of missed pixels and the
    text.

    Examples
    --------
    >>> s = scene(State(object="sphere", surface="sphere", tiling=2))
    >>> s["image"].shape, s["texture"].shape, s["misses"]
    ((128, 128, 3), (64, 64, 3), 0)
    >>> s["matrix"].tolist()
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 1.0]]
    """
    p, n, mask, shade = geometry(state.object)
    m = texture_matrix(tiling=state.tiling, offset=(state.offset_u, state.offset_v),
                       rotation=np.radians(state.rotation_deg))
    u, v = two_part_map(p, n, state.surface, state.method, size=SURFACE_SIZE, eye=EYE,
                        centroid=(0, 0, 0))
    hit = np.isfinite(u)
    colour = np.broadcast_to(MISS, p.shape).copy()
    tex = labelled_texture()
    if hit.any():
        u2, v2 = apply_texture_matrix(m, u[hit], v[hit])
        colour[hit] = nearest_sample(tex, u2, v2, wrap="repeat")
    image = np.broadcast_to(BACKGROUND, (SIZE, SIZE, 3)).copy()
    image[mask] = colour * shade[:, None]
    side = transform_texture(tex, m, filter="nearest")
    names = {"reflected": "reflected ray", "normal": "object normal", "centroid": "centroid",
             "intermediate_normal": "intermediate surface's normal"}
    text = (f"<b>{state.object}</b>, S-mapping on the <b>{state.surface}</b>, O-mapping by the "
            f"<b>{names[state.method]}</b>; texture matrix M = T(offset) S({state.tiling:g}) "
            f"R({state.rotation_deg:g}°): the picture turns by {0.0 - state.rotation_deg:g}° and "
            f"shrinks by {state.tiling:g}.<br>" + "<br>".join(_notes(state)))
    return {"image": image, "texture": side, "matrix": m, "u": u, "v": v,
            "misses": int((~hit).sum()), "text": text}


class TwoPartMappingExplorer(Explorer):
    """Menus for the object, the intermediate surface and the O-mapping; sliders for tiling,
    offset and rotation of the texture.

    In a notebook, after ``%matplotlib widget``, end a cell with ``TwoPartMappingExplorer()``.

    Examples
    --------
    >>> explorer = TwoPartMappingExplorer()
    >>> explorer.method.value = "reflected"
    >>> "environment mapping" in explorer.info.value
    True
    """

    summary = ("Two-part mapping explorer (interactive): a labelled checkerboard on a sphere, "
               "torus or cube through a plane, cylinder, sphere or box intermediate surface and "
               "one of four O-mappings, with tiling, offset and rotation sliders.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(6.0, 3.2))
        ax0 = self.fig.add_axes((0.02, 0.04, 0.5, 0.84))
        ax1 = self.fig.add_axes((0.58, 0.16, 0.38, 0.68))
        self.images = [
            ax0.imshow(s["image"], origin="lower", interpolation="nearest"),
            ax1.imshow(s["texture"], origin="lower", interpolation="nearest",
                       extent=(0, 1, 0, 1))]
        ax0.set_xticks([])
        ax0.set_yticks([])
        ax1.set_xlabel("u")
        ax1.set_ylabel("v")
        ax0.set_title("the object")
        ax1.set_title("texture seen through M")
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, self.images)
        self.object = w.Dropdown(options=list(OBJECTS), value=self.state.object,
                                 description="object")
        self.surface = w.Dropdown(options=list(SURFACES), value=self.state.surface,
                                  description="S: surface")
        self.method = w.Dropdown(options=[("reflected ray", "reflected"),
                                          ("object normal", "normal"),
                                          ("centroid", "centroid"),
                                          ("intermediate normal", "intermediate_normal")],
                                 value=self.state.method, description="O: method")
        self.tiling = slider("tiling", self.state.tiling, 0.5, 4.0, 0.5)
        self.offset_u = slider("offset u", self.state.offset_u, 0.0, 1.0, 0.05)
        self.offset_v = slider("offset v", self.state.offset_v, 0.0, 1.0, 0.05)
        self.rotation = slider("rotation °", self.state.rotation_deg, -180, 180, 5)
        bind(self.state, {"object": self.object, "surface": self.surface, "method": self.method,
                          "tiling": self.tiling, "offset_u": self.offset_u,
                          "offset_v": self.offset_v, "rotation_deg": self.rotation}, self.update)
        self.info = panel(width="620px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([self.object, self.surface, self.method],
                                     layout=w.Layout(flex_flow="row wrap")),
                              w.HBox([self.tiling, self.offset_u, self.offset_v, self.rotation],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute the mapping (the object's hits are cached) and update both images."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.images[0].set_data(s["image"])
        self.images[1].set_data(s["texture"])
        self.info.value = s["text"]
