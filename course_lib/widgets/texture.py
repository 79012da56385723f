r"""Texture explorer: procedural textures mapped onto a plane, a sphere or a cylinder, and
nearest / bilinear / trilinear filtering under magnification and minification.

A procedural texture (checkerboard, stripes, marble, wood or noise; its parameters on sliders) is
computed at the texel centres of a ``size x size`` image. A mapping gives every vertex of the
object texture coordinates :math:`(u, v)` — :func:`course_lib.texturing.planar_map`,
:func:`~course_lib.texturing.spherical_map` or :func:`~course_lib.texturing.cylindrical_map`,
or the course compendium's uncorrected spherical formulas, to see what goes wrong — and the
texture is sampled with :func:`~course_lib.texturing.nearest_sample` or
:func:`~course_lib.texturing.bilinear_sample`: our sampler magnifies the ``size x size`` texture
to a 256 x 256 picture (nearest: blocks; bilinear: smooth ramps), which pyvista maps onto the
object off screen, interpolating the vertices' :math:`(u, v)` across each triangle as every
renderer does. The red line is the seam where :math:`u` jumps from 1 back to 0: the mesh has two
copies of the vertices there, one with :math:`u = 0` and one with :math:`u = 1`, so no triangle
interpolates across the jump.

Below, the same texture filtered three ways. Top: **magnified**, 8 x 8 texels around the
texture's centre spread over 64 x 64 pixels: nearest sampling shows the texels as blocks,
bilinear blends neighbours (and trilinear is the same here: under magnification the mipmap
level is 0). Bottom: **minified**, the texture tiled on a floor that recedes to the horizon, one
sample per pixel: far away a pixel covers many texels and one lookup picks an arbitrary one —
nearest *and* bilinear alias (moiré) — while trilinear filtering reads the mipmap level whose
texels are about one pixel wide, which already holds the average.
"""
import io
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, texturing
from .._validate import as_choice
from . import _style
from ._base import PlotterExplorer, align, beside, labelled, panel, read_controls, slider

__all__ = ["MAPPINGS", "SIZES", "State", "TEXTURES", "TextureExplorer", "compendium_map",
           "filtering", "mesh_grid", "scene", "texture_image", "texture_uv"]

TEXTURES = ("checkerboard", "stripes", "marble", "wood", "noise")
MAPPINGS = ("plane", "sphere", "cylinder", "sphere, compendium's formulas")
SAMPLINGS = ("nearest", "bilinear")
SIZES = (4, 8, 16, 32, 64, 128)
NOISE_SCALE = 4.0           # noise lattice cells across the texture (marble, wood)
MAGNIFIED = 64              # pixels of the magnified view (8 x 8 texels)
DISPLAY = 256               # side of the sampled picture handed to the renderer
FLOOR = (144, 72)           # width, height of the minified floor
LON, LAT = 97, 49           # sphere and cylinder mesh: vertices around and along
CYLINDER_RADIUS = 0.8
DEFAULTS = {"checkerboard": (8.0, 0.0), "stripes": (8.0, 0.0), "marble": (2.0, 3.0),
            "wood": (8.0, 0.6), "noise": (8.0, 0.0)}
"""Each texture's starting (frequency, strength), set when the texture is chosen."""
PALETTES = {
    "checkerboard": ((0.13, 0.18, 0.33), (0.96, 0.95, 0.90)),
    "stripes": ((0.20, 0.26, 0.62), (0.98, 0.82, 0.30)),
    "marble": ((0.22, 0.25, 0.33), (0.96, 0.95, 0.92)),
    "wood": ((0.47, 0.27, 0.12), (0.86, 0.64, 0.38)),
    "noise": ((0.08, 0.25, 0.15), (0.80, 0.92, 0.62)),
}


@dataclass
class State:
    """Texture, its parameters, sampling, mapping and the camera (angles in degrees).

    ``frequency`` is the texture's main parameter: squares per side (checkerboard), stripes
    per side (stripes), vein stripes per side (marble), rings per unit radius (wood), lattice
    cells per side (noise). ``strength`` is the turbulence amplitude (marble, wood).

    Examples
    --------
    >>> State().texture, State().mapping, State().size
    ('checkerboard', 'sphere', 64)
    """

    texture: str = "checkerboard"
    frequency: float = 8.0
    strength: float = 4.0
    size: int = 64
    sampling: str = "bilinear"
    mapping: str = "sphere"
    azimuth: float = 35.0
    elevation: float = 20.0


@lru_cache(maxsize=16)
def _turbulence(size, octaves):
    t = texturing.turbulence(texturing.uv_grid(size, size) * NOISE_SCALE, octaves, seed=0)
    t.setflags(write=False)
    return t


@lru_cache(maxsize=64)
def texture_image(kind, frequency, strength, size):
    r"""The procedural texture at the texel centres of a ``size x size`` image, grey in [0, 1].

    * checkerboard: :func:`course_lib.texturing.checkerboard` with `frequency` squares per side;
    * stripes: :func:`course_lib.texturing.stripes`, `frequency` stripes per side, half width;
    * marble: :math:`\tfrac12[1 + \sin(2\pi f u + a\,T(4u, 4v))]` with the 4-octave
      turbulence :math:`T` (:func:`course_lib.texturing.marble` on coordinates scaled by 4);
    * wood: :math:`\operatorname{fract}(f\,\lVert (u, v) - (\tfrac12, \tfrac12)\rVert
      + a\,T(4u, 4v))` with 2 octaves (:func:`course_lib.texturing.wood`, scaled likewise);
    * noise: :math:`\tfrac12 + 0.7\,N(f u, f v)` with Perlin noise :math:`N`
      (:func:`course_lib.texturing.perlin_noise`).

    The turbulence does not depend on the sliders, so it is computed once per size and the
    sliders only redo the cheap outer formula. Cached: the same arguments return the same
    (read-only) array.

    Examples
    --------
    >>> texture_image("checkerboard", 2, 0, 4)
    array([[0., 0., 1., 1.],
           [0., 0., 1., 1.],
           [1., 1., 0., 0.],
           [1., 1., 0., 0.]])
    """
    as_choice(kind, "kind", TEXTURES)
    uv = texturing.uv_grid(size, size)
    if kind == "checkerboard":
        grey = texturing.checkerboard(uv, frequency)
    elif kind == "stripes":
        grey = texturing.stripes(uv, frequency, 0.5)
    elif kind == "marble":
        grey = 0.5 * (1 + np.sin(2 * np.pi * frequency * uv[..., 0]
                                 + strength * _turbulence(size, 4)))
    elif kind == "wood":
        x = frequency * np.hypot(uv[..., 0] - 0.5, uv[..., 1] - 0.5) \
            + strength * _turbulence(size, 2)
        grey = x - np.floor(x)
    else:
        grey = np.clip(0.5 + 0.7 * texturing.perlin_noise(uv * frequency, seed=0), 0.0, 1.0)
    grey.setflags(write=False)
    return grey


def _colour(grey, kind):
    """Grey values in [0, 1] to the texture's two-colour palette (marble: thin dark veins)."""
    dark, light = (np.array(c) for c in PALETTES[kind])
    t = np.asarray(grey) ** 0.4 if kind == "marble" else np.asarray(grey)
    return dark + t[..., None] * (light - dark)


@lru_cache(maxsize=8)
def mesh_grid(mapping):
    """The object's vertices as a structured grid, shape (a, b, 3), for a mapping's name.

    plane: the square [-1, 1]^2 in z = 0; sphere (both sphere mappings): the unit sphere,
    poles on y, LON x LAT vertices, longitude from -180° to 180° measured from +z towards +x,
    so that the first and last columns coincide on the seam behind the sphere (x = 0, z < 0);
    cylinder: radius 0.8 around the y axis, y in [-1, 1], open at the ends, the same columns.

    Examples
    --------
    >>> mesh_grid("plane").shape, mesh_grid("sphere").shape
    ((65, 65, 3), (97, 49, 3))
    """
    if mapping == "plane":
        s = np.linspace(-1.0, 1.0, 65)
        x, y = np.meshgrid(s, s, indexing="ij")
        grid = np.stack([x, y, np.zeros_like(x)], axis=-1)
    else:
        lon = np.linspace(-np.pi, np.pi, LON)
        if mapping == "cylinder":
            height = np.linspace(-1.0, 1.0, LAT)
            lo, hh = np.meshgrid(lon, height, indexing="ij")
            grid = np.stack([CYLINDER_RADIUS * np.sin(lo), hh, CYLINDER_RADIUS * np.cos(lo)],
                            axis=-1)
        else:
            lat = np.linspace(-np.pi / 2, np.pi / 2, LAT)
            lo, la = np.meshgrid(lon, lat, indexing="ij")
            grid = np.stack([np.cos(la) * np.sin(lo), np.sin(la), np.cos(la) * np.cos(lo)],
                            axis=-1)
    grid.setflags(write=False)
    return grid


def compendium_map(points):
    r"""The course compendium's spherical formulas, taken literally (to show they are wrong).

    .. math:: \theta = \tan^{-1}(x / z), \qquad \varphi = \tan^{-1}\!\big(y / \sqrt{x^2 +
              y^2}\big), \qquad u = \tfrac12 + \frac{\theta}{2\pi}, \quad v = \tfrac12 +
              \frac{\varphi}{\pi}

    The one-argument arctangent only returns angles in :math:`(-\pi/2, \pi/2)`: the front and
    the back of the sphere (:math:`P` and :math:`-P` have the same :math:`x/z`) get the same
    half of the texture, u only covers [0.25, 0.75] and jumps where z = 0. With
    :math:`\sqrt{x^2 + y^2}` (instead of :math:`\sqrt{x^2 + z^2}`) the pole gets
    :math:`\varphi = \pi/4` instead of :math:`\pi/2`, and every point of the meridian x = 0 gets
    :math:`\pm\pi/4`. (Where z = 0 or x = y = 0 the ratio is taken as the numpy division gives
    it: ±inf, or 0 for 0/0.)

    Parameters
    ----------
    points : array_like, shape (..., 3)

    Returns
    -------
    u, v : ndarray

    Examples
    --------
    >>> u, v = compendium_map([[0, 0, 1], [0, 0, -1], [0, 1, 0]])
    >>> u.tolist(), v.tolist()               # front and back get the same u; the pole v = 3/4
    ([0.5, 0.5, 0.5], [0.5, 0.5, 0.75])
    """
    p = np.asarray(points, dtype=float)
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        theta = np.arctan(np.nan_to_num(x / z, nan=0.0))
        phi = np.arctan(np.nan_to_num(y / np.sqrt(x * x + y * y), nan=0.0))
    return 0.5 + theta / (2 * np.pi), 0.5 + phi / np.pi


@lru_cache(maxsize=8)
def texture_uv(mapping):
    r"""Texture coordinates (u, v) of the vertices of :func:`mesh_grid` for a mapping's name.

    plane: :func:`course_lib.texturing.planar_map` (the square's corner (-1, -1) at (0, 0),
    size 2); sphere: :func:`course_lib.texturing.spherical_map`; cylinder:
    :func:`course_lib.texturing.cylindrical_map` (base at y = -1, height 2); the compendium's:
    :func:`compendium_map`. On the seam column of the sphere and cylinder the first copy gets
    :math:`u = 0` and the last :math:`u = 1` (:math:`\sin(\pm\pi)` is a tiny number of the
    right sign, so atan2 returns :math:`\mp\pi`).

    Examples
    --------
    >>> u, v = texture_uv("sphere")
    >>> float(u[0, 10]), float(u[-1, 10]), float(u[LON // 2, 10])    # seam twice, then front
    (0.0, 1.0, 0.5)
    """
    grid = mesh_grid(mapping)
    if mapping == "plane":
        u, v = texturing.planar_map(grid, origin=(-1.0, -1.0, 0.0), size=2.0)
    elif mapping == "sphere":
        u, v = texturing.spherical_map(grid)
    elif mapping == "cylinder":
        u, v = texturing.cylindrical_map(grid, center=(0.0, -1.0, 0.0), height=2.0)
    elif mapping in MAPPINGS:
        u, v = compendium_map(grid)
    else:
        raise ValueError(f"mapping must be one of {MAPPINGS}, got {mapping!r}")
    for array in (u, v):
        array.setflags(write=False)
    return u, v


def _seams(mapping):
    """Polylines (k, m, 3) where u jumps, slightly outside the surface."""
    if mapping == "plane":
        return np.zeros((0, 2, 3))
    t = np.linspace(-1.0, 1.0, 41)
    if mapping == "cylinder":
        r = 1.01 * CYLINDER_RADIUS
        return np.array([np.column_stack([np.zeros_like(t), t, np.full_like(t, -r)])])
    lat = t * np.pi / 2
    c, s = 1.01 * np.cos(lat), 1.01 * np.sin(lat)
    if mapping == "sphere":
        return np.array([np.column_stack([np.zeros_like(t), s, -c])])
    return np.array([np.column_stack([c, s, np.zeros_like(t)]),
                     np.column_stack([-c, s, np.zeros_like(t)])])


def filtering(texture_rgb):
    """Nearest, bilinear and trilinear sampling of a texture, magnified and minified.

    Parameters
    ----------
    texture_rgb : ndarray, shape (size, size, 3)
        A power-of-two texture.

    Returns
    -------
    dict
        ``magnified``: 8 x 8 texels around (1/2, 1/2) on MAGNIFIED x MAGNIFIED pixels, as a dict
        ``nearest``, ``bilinear``, ``trilinear`` (level 0: equal to bilinear); ``minified``: the
        texture tiled on a receding floor (FLOOR pixels, one sample per pixel centre) by the
        three methods; ``level``: the floor's mipmap level per pixel
        (:func:`course_lib.texturing.mip_level` of the texel footprint).

    Examples
    --------
    >>> f = filtering(np.stack([texture_image("checkerboard", 8, 0, 32)] * 3, axis=-1))
    >>> f["minified"]["trilinear"].shape, bool(f["level"].max() > 3)
    ((72, 144, 3), True)
    """
    size = texture_rgb.shape[0]
    pyramid = texturing.mipmap(texture_rgb)
    s = (np.arange(MAGNIFIED) + 0.5) / MAGNIFIED
    mu, mv = np.meshgrid(0.5 + (s - 0.5) * 8 / size, 0.5 + (s - 0.5) * 8 / size)
    magnified = {"nearest": texturing.nearest_sample(texture_rgb, mu, mv),
                 "bilinear": texturing.bilinear_sample(texture_rgb, mu, mv),
                 "trilinear": texturing.trilinear_sample(pyramid, mu, mv, 0.0)}
    w, h = FLOOR
    cx, cy = np.meshgrid(np.arange(w) + 0.5, np.arange(h) + 0.5)
    depth = (h + 1.0) - cy                         # a camera 1 above the floor, looking level
    u = (cx - w / 2) / depth * 0.5
    v = h / depth * 0.5
    du_dy, du_dx = np.gradient(u)
    dv_dy, dv_dx = np.gradient(v)
    level = texturing.mip_level(texturing.texel_footprint(texture_rgb.shape, du_dx, dv_dx,
                                                          du_dy, dv_dy), len(pyramid))
    minified = {"nearest": texturing.nearest_sample(texture_rgb, u, v),
                "bilinear": texturing.bilinear_sample(texture_rgb, u, v),
                "trilinear": texturing.trilinear_sample(pyramid, u, v, level)}
    return {"magnified": magnified, "minified": minified, "level": level}


def scene(state, with_filtering=True):
    r"""Pure part: the texture, its sampled picture, the mesh with its (u, v), the seam, the
    filtering pictures and the explanation.

    Parameters
    ----------
    state : State
    with_filtering : bool
        Also compute the filtering pictures (they depend on the texture only).

    Returns
    -------
    dict
        ``grey`` (size x size in [0, 1]), ``texture`` (its RGB colours), ``display`` (the
        texture sampled at the texel centres of a DISPLAY x DISPLAY picture by the chosen
        method, RGB, row 0 at v = 0), ``points`` (the mesh grid, (a, b, 3)), ``u``, ``v``
        (a, b), ``seams`` (polylines (k, m, 3)), ``filtering`` (see :func:`filtering`, or
        None), ``text``.

    Examples
    --------
    >>> s = scene(State(mapping="sphere"))
    >>> s["points"].shape, s["display"].shape, s["seams"].shape
    ((97, 49, 3), (256, 256, 3), (1, 41, 3))
    >>> float(s["u"].min()), float(s["u"].max())
    (0.0, 1.0)
    """
    for value, options, name in ((state.texture, TEXTURES, "texture"),
                                 (state.mapping, MAPPINGS, "mapping"),
                                 (state.sampling, SAMPLINGS, "sampling"),
                                 (state.size, SIZES, "size")):
        as_choice(value, name, options)
    grey = texture_image(state.texture, float(state.frequency), float(state.strength),
                         int(state.size))
    rgb = _colour(grey, state.texture)
    u, v = texture_uv(state.mapping)
    display = _display(state.texture, float(state.frequency), float(state.strength),
                       int(state.size), state.sampling)
    texels = f"{state.size} x {state.size} texels"
    mapping_text = {
        "plane": "Planar mapping: u and v are the point's coordinates in the plane, scaled to "
                 "[0, 1] — no seam, no distortion (on a plane).",
        "sphere": "Spherical mapping: u = 1/2 + atan2(x, z)/2π (longitude), v = 1/2 + "
                  "asin(y/r)/π (latitude). Near the poles a whole row of texels squeezes into "
                  "a point; at the red seam u jumps from 1 back to 0.",
        "cylinder": "Cylindrical mapping: u from the angle around the axis, v = height / "
                    "cylinder height — no pole distortion, a seam (red) where u jumps.",
        "sphere, compendium's formulas": (
            "The compendium's formulas: θ = tan⁻¹(x/z) only covers half a turn, so the front "
            "and the back show the <b>same half</b> of the texture, mirrored, and u jumps where "
            "z = 0 (red lines); φ = tan⁻¹(y/√(x² + y²)) reaches only 45° at the poles, so the "
            "top and bottom quarters of the texture are never used. Compare with 'sphere'.")}
    text = (f"{state.texture.capitalize()} texture, {texels}, magnified by <b>{state.sampling}</b>"
            " sampling. "
            + mapping_text[state.mapping])
    if state.texture in ("checkerboard", "stripes", "noise") and state.frequency > state.size / 2:
        text += (f" <b>Aliasing</b>: {state.frequency:g} periods need at least "
                 f"{2 * state.frequency:g} texels per side (two samples per period), the texture "
                 f"has {state.size}: sampled at its texel centres, the pattern turns into a "
                 "coarser false one (or a flat colour).")
    if state.texture in ("marble", "wood", "noise") and state.mapping != "plane":
        text += (" This texture does not tile (its left and right edges differ), so the seam "
                 "shows as a discontinuity.")
    return {"grey": grey, "texture": rgb, "points": mesh_grid(state.mapping), "u": u, "v": v,
            "display": display, "seams": _seams(state.mapping),
            "filtering": filtering(rgb) if with_filtering else None, "text": text}


@lru_cache(maxsize=16)
def _display(kind, frequency, strength, size, sampling):
    """The texture magnified to DISPLAY x DISPLAY by our sampler (cached: turning the view
    does not resample it)."""
    rgb = _colour(texture_image(kind, frequency, strength, size), kind)
    sample = texturing.nearest_sample if sampling == "nearest" else texturing.bilinear_sample
    centres = (np.arange(DISPLAY) + 0.5) / DISPLAY
    display = sample(rgb, *np.meshgrid(centres, centres), wrap="repeat")
    display.setflags(write=False)
    return display


def _structured_points(array):
    return np.column_stack([array[..., k].ravel(order="F") for k in range(3)])


class TextureExplorer(PlotterExplorer):
    """Texture, parameters, texture size, sampling, mapping and camera; the textured object
    rendered off screen, and the filtering panel.

    In a notebook, after ``%matplotlib widget``, end a cell with ``TextureExplorer()``.

    Examples
    --------
    >>> explorer = TextureExplorer()
    >>> explorer.mapping.value = "sphere, compendium's formulas"
    >>> "same half" in explorer.info.value, explorer.png()[:4]
    (True, b'\\x89PNG')
    """

    summary = ("Texture explorer (interactive): checkerboard, stripes, marble, wood or noise on a "
               "plane, sphere or cylinder (planar, spherical, cylindrical mapping), nearest or "
               "bilinear sampling, and nearest / bilinear / trilinear filtering magnified and "
               "minified.")

    def __init__(self, state=None):
        import ipywidgets as w

        draw.configure_offscreen_vtk()
        import pyvista as pv

        self.state = state or State()
        s = scene(self.state)
        self.plotter = draw.offscreen_plotter(400, 340)
        # no multisampling: in software OpenGL it triples the time of every frame
        self.plotter.disable_anti_aliasing()
        self.grids, self.actors = {}, {}
        for name in ("plane", "sphere", "cylinder"):
            grid_points = mesh_grid(name)
            grid = pv.StructuredGrid(*[grid_points[..., k] for k in range(3)])
            u, v = texture_uv(name)
            grid.active_texture_coordinates = np.column_stack([u.ravel(order="F"),
                                                               v.ravel(order="F")])
            self.grids[name] = grid
            self.actors[name] = self.plotter.add_mesh(grid, texture=self._texture(s), ambient=0.35,
                                                      diffuse=0.7, specular=0.0)
        self._uv_of = {name: name for name in self.grids}
        self.seam = pv.PolyData(np.zeros((2, 3)), lines=[2, 0, 1])
        self.seam_actor = self.plotter.add_mesh(self.seam, color="#d0021b", line_width=3)
        self._seam_of = None
        self._set_camera()
        self.image = w.Image(format="jpeg", layout=w.Layout(width="400px"))

        self.fig = draw.figure(figsize=(7.4, 3.5))
        self.panel = {}
        titles = {"nearest": "nearest", "bilinear": "bilinear", "trilinear": "trilinear"}
        for row, (key, rect_y, height) in enumerate((("magnified", 0.53, 0.36),
                                                      ("minified", 0.03, 0.36))):
            for col, method in enumerate(titles):
                ax = self.fig.add_axes((0.02 + 0.33 * col, rect_y, 0.3, height))
                ax.set(xticks=[], yticks=[])
                image = s["filtering"][key][method]
                self.panel[key, method] = ax.imshow(np.clip(image, 0, 1), origin="lower",
                                                    interpolation="nearest", aspect="auto")
                label = (f"{method}" + (" (= bilinear)"
                                        if key == "magnified" and method == "trilinear" else ""))
                ax.set_title(f"{key}: {label}", fontsize=_style.ANNOTATION)
        self.blitter = draw.Blitter(self.fig, list(self.panel.values()))

        st, options = self.state, {}
        self._busy = False
        self.texture = labelled(w.Dropdown, "texture", options=TEXTURES, value=st.texture,
                                **options)
        self.texture.observe(self._on_texture, names="value")
        self.frequency = slider("frequency", st.frequency, 1, 32, 1, **options)
        self.strength = slider("turbulence", st.strength, 0, 8, 0.1, **options)
        self.size = labelled(w.SelectionSlider, "texels", options=SIZES, value=st.size,
                             **options)
        self.sampling = w.ToggleButtons(options=SAMPLINGS, value=st.sampling,
                                        style={"button_width": _style.button_width(*SAMPLINGS)})
        self.mapping = labelled(w.Dropdown, "mapping", options=MAPPINGS, value=st.mapping,
                                **options)
        self.azimuth = slider("view azimuth °", st.azimuth, -180, 180, 2, **options)
        self.elevation = slider("view elevation °", st.elevation, -80, 80, 2, **options)
        align([self.texture, self.frequency, self.strength, self.size, self.mapping,
               self.azimuth, self.elevation])
        #: field of ``State`` -> its control (the texture menu also resets two sliders)
        self.controls = {"texture": self.texture, "frequency": self.frequency,
                         "strength": self.strength, "size": self.size,
                         "sampling": self.sampling, "mapping": self.mapping,
                         "azimuth": self.azimuth, "elevation": self.elevation}
        for name, control in self.controls.items():
            if name != "texture":
                control.observe(self._on_change, names="value")
        self.info = panel(width="320px")
        controls = w.VBox([self.texture, self.frequency, self.strength, self.size,
                           self.sampling, self.mapping, self.azimuth, self.elevation, self.info])
        self.widget = w.VBox([beside(self.image, controls, align="flex-start"), self.fig.canvas])
        self._texture_key = None
        self._picture_key = None
        self._draw(s)

    def _set_camera(self):
        a, e = np.radians([self.state.azimuth, self.state.elevation])
        eye = 4.6 * np.array([np.cos(e) * np.sin(a), np.sin(e), np.cos(e) * np.cos(a)])
        up = (0.0, 1.0, 0.0) if abs(self.state.elevation) < 89 else (0.0, 0.0, -1.0)
        self.plotter.camera_position = [tuple(eye), (0.0, 0.0, 0.0), up]

    def _on_texture(self, change):
        frequency, strength = DEFAULTS[change["new"]]
        self._busy = True                     # one update for the three changes
        try:
            self.frequency.value, self.strength.value = frequency, strength
        finally:
            self._busy = False
        self._on_change(change)

    def _on_change(self, change):
        if self._busy:
            return
        read_controls(self.state, self.controls)
        self.update()

    def _key(self):
        st = self.state
        return (st.texture, st.frequency, st.strength, st.size)

    def update(self):
        """Recompute the scene; re-render the object, and the panel if the texture changed."""
        refilter = self._key() != self._texture_key
        self._draw(scene(self.state, with_filtering=refilter))
        if refilter:
            self.blitter.update()

    @staticmethod
    def _texture(s):
        import pyvista as pv

        picture = np.round(255 * np.clip(s["display"], 0, 1)).astype(np.uint8)
        texture = pv.Texture(np.ascontiguousarray(picture[::-1]))   # pyvista: first row on top
        texture.interpolate = True
        texture.repeat = True
        return texture

    def _draw(self, s):
        st = self.state
        name = "sphere" if st.mapping.startswith("sphere") else st.mapping
        for key, actor in self.actors.items():
            actor.SetVisibility(key == name)
        grid = self.grids[name]
        if self._uv_of.get(name) != st.mapping:
            grid.active_texture_coordinates = np.column_stack([s["u"].ravel(order="F"),
                                                               s["v"].ravel(order="F")])
            self._uv_of[name] = st.mapping
        picture_key = self._key() + (st.sampling, name)
        if self._picture_key != picture_key:            # a new texture picture for the actor
            self.actors[name].texture = self._texture(s)
            self._picture_key = picture_key
        seams = s["seams"]
        if len(seams):
            points = seams.reshape(-1, 3)
            m = seams.shape[1]
            lines = np.concatenate([np.r_[m, np.arange(k * m, (k + 1) * m)]
                                    for k in range(len(seams))])
            if self._seam_of != st.mapping:              # a new seam for a new mapping
                self.seam.points = points
                self.seam.lines = lines
                self._seam_of = st.mapping
            self.seam_actor.SetVisibility(True)
        else:
            self.seam_actor.SetVisibility(False)
        self.strength.disabled = st.texture not in ("marble", "wood")
        self._set_camera()
        self.image.value = self.picture("jpeg")
        if s["filtering"] is not None:
            for (key, method), image in self.panel.items():
                image.set_data(np.clip(s["filtering"][key][method], 0, 1))
            self._texture_key = self._key()
        self.info.value = s["text"]

    def png(self, dpi=72):
        """The rendered object above the filtering panel, as one PNG (for readers without a
        kernel)."""
        from PIL import Image

        top = Image.open(io.BytesIO(self.picture("png"))).convert("RGB")
        buffer = io.BytesIO()
        self.blitter.savefig(buffer, format="png", dpi=dpi)
        bottom = Image.open(io.BytesIO(buffer.getvalue())).convert("RGB")
        width = max(top.width, bottom.width)
        sheet = Image.new("RGB", (width, top.height + bottom.height), "white")
        sheet.paste(top, ((width - top.width) // 2, 0))
        sheet.paste(bottom, ((width - bottom.width) // 2, top.height))
        out = io.BytesIO()
        sheet.save(out, format="png")
        return out.getvalue()
