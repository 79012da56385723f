r"""Phong explorer: the four terms of the Phong model on a sphere, and flat / Gouraud / Phong
shading of a coarse sphere mesh side by side.

Top row: a sphere lit by a directional light and seen by an orthographic camera along -z, shaded
per pixel with normals computed analytically (:math:`N = (x, y, \sqrt{1 - x^2 - y^2})`); next
to it the terms it is the sum of, :math:`I = (I_e + I_g) + I_d + I_s` (emission and ambient,
diffuse, specular), each in its own small picture. Sliders set :math:`k_a, k_d, k_s`, the
shininess :math:`n`, the emission, the light's direction (two angles) and colour, the object's
colour, and switch between the Phong (:math:`R \cdot V`) and Blinn-Phong (:math:`N \cdot H`)
highlight.

Bottom row: the same model and light on a triangle mesh of the sphere, rendered by the z-buffer
with **flat** shading (one evaluation per triangle), **Gouraud** shading (evaluation at the
vertices, colours interpolated) and **Phong** shading (normals interpolated, evaluation per
pixel). The mesh is rasterized once per resolution: the z-buffer's perspective-correct
barycentric weights of every pixel are kept (:func:`course_lib.shading.barycentric_buffers`),
so a slider move only re-evaluates the illumination model
(``course_lib.shading.render_shaded(..., fragments=...)``, a few milliseconds instead of a
re-render).
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, shading, viewing
from .._validate import as_choice
from . import _style
from ._base import Explorer, align, beside, bind, degree_sliders, labelled, panel, slider

__all__ = ["MODELS", "PhongExplorer", "State", "interpolation_buffers", "light_direction",
           "scene", "sphere_normals"]

SIZE = 128                  # pixels of the analytic sphere and of each term (per side)
MESH_SIZE = 96              # pixels of each interpolated-shading picture
EXTENT = 1.08               # the sphere pictures show [-EXTENT, EXTENT]^2
EYE = np.array([0.0, 0.0, 4.0])
FOV_DEG = 32.0
BACKGROUND = 0.94
MODELS = ("Phong", "Blinn-Phong")
SHADINGS = ("flat", "gouraud", "phong")


@dataclass
class State:
    """Material, light and model of the explorer (colours as ``#rrggbb``; angles in degrees).

    Examples
    --------
    >>> s = State()
    >>> s.model, s.ks, s.segments
    ('Phong', 0.5, 12)
    """

    ka: float = 0.15
    kd: float = 0.7
    ks: float = 0.5
    shininess: float = 32.0
    emission: float = 0.0
    light_azimuth: float = 35.0
    light_elevation: float = 30.0
    light_color: str = "#ffffff"
    color: str = "#3f86e8"
    model: str = "Phong"
    segments: int = 12


def _hex_to_rgb(hex_color):
    """``#rrggbb`` -> RGB floats in [0, 1]."""
    h = hex_color.lstrip("#")
    if len(h) != 6:
        raise ValueError(f"colour must be '#rrggbb', got {hex_color!r}")
    return np.array([int(h[k:k + 2], 16) / 255.0 for k in (0, 2, 4)])


def light_direction(azimuth_deg, elevation_deg):
    r"""The unit vector towards a directional light, from two angles in degrees.

    .. math:: L = (\cos e \sin a,\ \sin e,\ \cos e \cos a)

    Azimuth :math:`a` turns about the vertical y axis from the viewer's direction +z towards +x
    (to the right on screen); elevation :math:`e` lifts the light towards +y (up). ``(0, 0)``
    is a light at the viewer.

    Examples
    --------
    >>> light_direction(0, 0).tolist(), np.round(light_direction(90, 0), 12).tolist()
    ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])
    """
    a, e = np.radians([azimuth_deg, elevation_deg])
    return np.array([np.cos(e) * np.sin(a), np.sin(e), np.cos(e) * np.cos(a)])


@lru_cache(maxsize=4)
def sphere_normals(size=SIZE):
    r"""Per-pixel normals of the unit sphere seen along -z (orthographic), and its mask.

    The pixel centres cover :math:`[-1.08, 1.08]^2` (row 0 at the bottom); inside the disk
    :math:`x^2 + y^2 < 1` the visible point is :math:`(x, y, \sqrt{1 - x^2 - y^2})`, which on
    the unit sphere is also its normal: no mesh, no interpolation.

    Returns
    -------
    normals : ndarray, shape (size, size, 3)
        Unit normals inside the disk (+z outside).
    mask : ndarray of bool, shape (size, size)

    Examples
    --------
    >>> n, mask = sphere_normals(8)
    >>> n.shape, bool(np.allclose(np.linalg.norm(n, axis=-1), 1)), int(mask.sum())
    ((8, 8, 3), True, 44)
    """
    s = ((np.arange(size) + 0.5) / size * 2 - 1) * EXTENT
    x, y = np.meshgrid(s, s)
    r2 = x * x + y * y
    mask = r2 < 1.0
    z = np.sqrt(np.maximum(0.0, 1.0 - r2))
    normals = np.where(mask[..., None], np.stack([x, y, z], axis=-1), [0.0, 0.0, 1.0])
    normals.setflags(write=False)
    mask.setflags(write=False)
    return normals, mask


def _camera():
    view = viewing.look_at(EYE, [0.0, 0.0, -1.0], [0.0, 1.0, 0.0])
    return view, viewing.perspective(np.radians(FOV_DEG), 1.0, 1.0, 10.0)


@lru_cache(maxsize=8)
def _sphere_buffers(segments):
    """The sphere mesh and its :func:`course_lib.shading.barycentric_buffers` (cached)."""
    v, f = shading.uv_sphere(segments=segments, rings=max(segments // 2, 2))
    view, proj = _camera()
    buffers = shading.barycentric_buffers(v, f, view, proj, MESH_SIZE, MESH_SIZE)
    for array in (v, f, *buffers):
        array.setflags(write=False)
    return v, f, buffers


def interpolation_buffers(segments):
    """The mesh sphere rasterized once: visible face and perspective-correct weights per pixel.

    The sphere mesh (:func:`course_lib.shading.uv_sphere` with `segments` and ``segments // 2``
    rings) drawn once by :func:`course_lib.shading.barycentric_buffers`: any per-vertex
    quantity (colours for Gouraud, positions and normals for Phong) is then interpolated by one
    weighted sum, without rasterizing again (``render_shaded(..., fragments=...)``).

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    faces : ndarray of int, shape (m, 3)
    ids : ndarray of int, shape (MESH_SIZE, MESH_SIZE)
        Visible face per pixel, -1 for background.
    weights : ndarray, shape (MESH_SIZE, MESH_SIZE, 3)
        Barycentric weights of the pixel centre in that face (0 on background).

    Examples
    --------
    >>> v, f, ids, w = interpolation_buffers(8)
    >>> len(f), bool(np.allclose(w[ids >= 0].sum(axis=1), 1))
    (48, True)
    """
    v, f, buffers = _sphere_buffers(segments)
    return v, f, buffers.ids, buffers.weights


def _interpolated(segments, model, light, material):
    """Flat, Gouraud and Phong pictures of the mesh sphere by
    :func:`course_lib.shading.render_shaded` on its cached buffers (exact sphere normals)."""
    v, f, buffers = _sphere_buffers(segments)
    view, proj = _camera()
    out = {}
    for name in SHADINGS:
        picture = shading.render_shaded(v, f, view, proj, MESH_SIZE, MESH_SIZE, light, material,
                                        shading=name, model=model, normals=v,
                                        background=BACKGROUND, fragments=buffers)
        out[name] = np.clip(picture.image, 0.0, 1.0)
    return out, len(f), len(v)


def scene(state):
    r"""Pure part: the sphere's picture and its terms, and the three interpolated shadings.

    Returns
    -------
    dict
        ``total``, ``ambient`` (emission + ambient), ``diffuse``, ``specular``: RGB pictures
        of shape (SIZE, SIZE, 3), clipped to [0, 1], background grey; ``raw``: the unclipped
        :class:`course_lib.shading.PhongTerms` inside the disk; ``mask``; ``light`` (the unit
        vector L); ``highlight`` (where on the picture :math:`N = H`, the centre of the
        highlight, or None if it is on the far side); ``flat``, ``gouraud``, ``phong``:
        pictures of shape (MESH_SIZE, MESH_SIZE, 3); ``triangles``, ``vertices``; ``text``.

    Examples
    --------
    >>> s = scene(State(ka=0.0, kd=0.0, ks=1.0, light_azimuth=0, light_elevation=0))
    >>> s["total"].shape, s["phong"].shape, s["highlight"]
    ((128, 128, 3), (96, 96, 3), (0.0, 0.0))
    >>> float(s["raw"].specular.max())        # light at the viewer: R = V at the centre
    1.0
    """
    as_choice(state.model, "model", MODELS)
    normals, mask = sphere_normals(SIZE)
    colour = _hex_to_rgb(state.color)
    light_rgb = _hex_to_rgb(state.light_color)
    direction = light_direction(state.light_azimuth, state.light_elevation)
    light = shading.directional_light(direction, intensity=light_rgb)
    material = shading.colored_material(colour, state.ka, state.kd, state.ks, state.shininess,
                                        emission=state.emission * colour)
    illuminate = shading.phong if state.model == "Phong" else shading.blinn_phong
    terms = illuminate(None, normals[mask], [0.0, 0.0, 1.0], light, material)
    out = {}
    for name, values in (("total", terms.total), ("ambient", terms.emission + terms.ambient),
                         ("diffuse", terms.diffuse), ("specular", terms.specular)):
        picture = np.full((SIZE, SIZE, 3), BACKGROUND)
        picture[mask] = np.clip(values, 0.0, 1.0)
        out[name] = picture
    h = direction + np.array([0.0, 0.0, 1.0])
    norm = np.linalg.norm(h)
    highlight = None
    if norm > 1e-9 and h[2] / norm > 0:
        highlight = (float(round(h[0] / norm, 12)), float(round(h[1] / norm, 12)))
    pictures, triangles, vertices = _interpolated(
        state.segments, "phong" if state.model == "Phong" else "blinn", light, material)
    out.update(pictures)
    angle = np.degrees(np.arccos(np.clip(direction[2], -1, 1)))
    over = float(terms.total.max())
    width = np.degrees(np.arccos(0.5 ** (1.0 / state.shininess)))
    if state.model == "Phong":
        spec = (f"Phong highlight: k<sub>s</sub> max(R·V, 0)<sup>n</sup>, half as bright "
                f"{width:.0f}° away from the mirror direction (n = {state.shininess:.0f}).")
    else:
        spec = (f"Blinn-Phong highlight: k<sub>s</sub> max(N·H, 0)<sup>n</sup>. The angle between N "
                f"and H is about half the angle between R and V, so the highlight is about twice as "
                f"wide as Phong's with the same n; n ≈ {4 * state.shininess:.0f} (4n) matches it.")
    text = (f"The light is {angle:.0f}° from the view direction. "
            + ("It is behind the sphere: most of the visible half gets only I<sub>e</sub> + "
               "I<sub>g</sub>. " if direction[2] < 0 else "")
            + spec
            + f" Brightest pixel: {over:.2f}"
            + (" — above 1, clipped to white (k<sub>a</sub> + k<sub>d</sub> + k<sub>s</sub> > 1 "
               "reflects more than the light brings)." if over > 1.0 + 1e-9 else ".")
            + f" Bottom row: a mesh of {triangles} triangles ({vertices} vertices). Flat: one "
            "colour per triangle. Gouraud: the model only at the vertices, so a highlight "
            "falling between them is smeared or lost. Phong: the normal interpolated and the "
            "model evaluated per pixel.")
    out.update(raw=terms, mask=mask, light=direction, highlight=highlight,
               triangles=triangles, vertices=vertices, text=text)
    return out


class PhongExplorer(Explorer):
    """Sliders for the material, the light and the model; the sphere, its terms, and three
    interpolated shadings of a mesh.

    In a notebook, after ``%matplotlib widget``, end a cell with ``PhongExplorer()``.

    Examples
    --------
    >>> explorer = PhongExplorer()
    >>> explorer.ks.value = 0.0
    >>> float(explorer.images["specular"].get_array()[80, 80].max()) == BACKGROUND
    False
    >>> explorer.model.value = "Blinn-Phong"
    >>> "Blinn-Phong" in explorer.info.value
    True
    """

    summary = ("Phong explorer (interactive): a sphere with its emission + ambient, diffuse and "
               "specular terms; k_a, k_d, k_s, shininess, light direction and colour, Phong or "
               "Blinn-Phong; flat, Gouraud and Phong shading of a sphere mesh side by side.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        # every picture is shown at its own pixel size (90 dpi): no resampling, and few pixels
        # for ipympl to encode on each move (that encoding dominates the update time)
        width, height = 600, 368
        self.fig = draw.figure(figsize=(width / 90, height / 90), dpi=90)
        ext = (-EXTENT, EXTENT, -EXTENT, EXTENT)
        self.images = {}
        self.axes = {}
        top, bottom, m = 196, 24, MESH_SIZE
        layout = {"total": (8, top), "ambient": (160, top), "diffuse": (312, top),
                  "specular": (464, top), "flat": (60, bottom), "gouraud": (252, bottom),
                  "phong": (444, bottom)}
        titles = {"total": "$I$\nsum of the terms",
                  "ambient": "$I_e + I_g$\nemission + ambient",
                  "diffuse": "$I_d$\ndiffuse",
                  "specular": "$I_s$\nspecular",
                  "flat": "flat shading", "gouraud": "Gouraud shading",
                  "phong": "Phong shading"}
        for name, (x, y) in layout.items():
            side = SIZE if name in ("total", "ambient", "diffuse", "specular") else m
            ax = self.fig.add_axes((x / width, y / height, side / width, side / height))
            ax.set(xticks=[], yticks=[])
            for spine in ax.spines.values():
                spine.set_visible(False)
            ax.set_title(titles[name], fontsize=_style.ANNOTATION, pad=3, linespacing=1.1)
            extent = ext if side == SIZE else None
            self.images[name] = ax.imshow(s[name], origin="lower", extent=extent,
                                          interpolation="nearest")
            self.axes[name] = ax
        for x, sign in ((148, "="), (300, "+"), (452, "+")):
            self.fig.text(x / width, (top + SIZE / 2) / height, sign, fontsize=_style.SYMBOL,
                          ha="center",
                          va="center", color="0.3")
        self.fig.text(0.5, (bottom + m + 26) / height,
                      "the same model on a sphere mesh: what is interpolated?",
                      fontsize=_style.LABEL, ha="center", color="0.3", style="italic")
        big = self.axes["total"]
        (self.sun,) = big.plot([], [], marker="*", ms=14, mec="0.2", mew=0.8, ls="none")
        (self.peak,) = big.plot([], [], "+", color="0.2", ms=9, mew=1.2)
        # under the picture, not on the sphere
        self.model_label = big.text(0.5, -0.03, "", transform=big.transAxes, ha="center",
                                    va="top", fontsize=_style.ANNOTATION, color="0.25",
                                    clip_on=False)
        self.blitter = draw.Blitter(self.fig, [*self.images.values(), self.sun, self.peak,
                                               self.model_label])

        st = self.state
        self.ka = slider("k_a ambient", st.ka, 0, 1, 0.01)
        self.kd = slider("k_d diffuse", st.kd, 0, 1, 0.01)
        self.ks = slider("k_s specular", st.ks, 0, 1, 0.01)
        self.shininess = labelled(w.FloatLogSlider, "shininess n", value=st.shininess, base=2,
                                  min=0, max=9, step=0.1)
        self.emission = slider("emission", st.emission, 0, 1, 0.01)
        sliders = degree_sliders(None, azimuth=("light azimuth °", st.light_azimuth, -180, 180),
                                 elevation=("light elevation °", st.light_elevation, -89, 89))
        self.azimuth, self.elevation = sliders["azimuth"], sliders["elevation"]
        self.light_color = labelled(w.ColorPicker, "light", value=st.light_color, concise=False)
        self.color = labelled(w.ColorPicker, "object", value=st.color)
        self.model = w.ToggleButtons(options=MODELS, value=st.model,
                                     style={"button_width": _style.button_width(*MODELS)})
        self.segments = slider("mesh segments", st.segments, 4, 32, 2, kind=w.IntSlider,
                               continuous_update=False)
        bind(st, {"ka": self.ka, "kd": self.kd, "ks": self.ks, "shininess": self.shininess,
                  "emission": self.emission, "light_azimuth": self.azimuth,
                  "light_elevation": self.elevation, "light_color": self.light_color,
                  "color": self.color, "model": self.model, "segments": self.segments},
             self.update)
        self.info = panel(width="330px")
        column1 = w.VBox(align([self.ka, self.kd, self.ks, self.shininess, self.emission]))
        column2 = w.VBox(align([self.azimuth, self.elevation, self.light_color, self.color,
                                self.segments]))
        self.widget = w.VBox([beside(self.fig.canvas, w.VBox([self.model, self.info]),
                                     align="flex-start"),
                              w.HBox([column1, column2], layout=w.Layout(flex_flow="row wrap",
                                                                         grid_gap="0 12px"))])
        self._draw(s)

    def update(self):
        """Recompute the scene and update the pictures in place."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        for name, image in self.images.items():
            image.set_data(s[name])
        lx, ly, lz = s["light"]
        self.sun.set_data([lx], [ly])
        self.sun.set_markerfacecolor("#ffd54f" if lz >= 0 else "none")
        if s["highlight"] is not None and s["raw"].specular.max() > 0:
            self.peak.set_data([s["highlight"][0]], [s["highlight"][1]])
        else:
            self.peak.set_data([], [])
        self.model_label.set_text(f"{self.state.model}, n = {self.state.shininess:.0f}")
        self.info.value = (s["text"] + " <i>Star: the point where N = L, straight towards the light "
                           "(hollow: the light is behind the sphere); cross: where N = H, the "
                           "centre of the highlight.</i>")
