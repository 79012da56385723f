"""Back-face culling and the z-buffer on a torus: what each removes, and what is left to do.

Sliders move the camera around a torus (and a box behind it). On the left the mesh with its
back faces greyed out; on the right the depth buffer of the picture, rendered with or without
back-face culling. On a torus (not convex) culling removes about half of the triangles, but
front faces still hide each other — the inner part of the ring — and only the depth test sorts
that out. The counts show the work: triangles drawn, fragments rasterized, depth writes.
"""
from dataclasses import dataclass

import numpy as np

from .. import clipping, draw, shapes, viewing, visibility
from . import _style
from ._base import Explorer, beside, bind, checkbox, degree_sliders, panel

__all__ = ["HiddenSurfaceExplorer", "State", "mesh", "scene"]

SIZE = 56


def mesh():
    """A torus and a box behind it, as one triangle mesh (faces oriented outwards).

    Examples
    --------
    >>> v, f = mesh()
    >>> v.shape[1], f.shape[1]
    (3, 3)
    """
    v1, f1 = shapes.torus(1.0, 0.38, 14, 7)
    lo, hi = np.array([-1.5, 1.5, -0.8]), np.array([1.5, 1.7, 0.8])
    v2 = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                   for z in (lo[2], hi[2])])
    quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [0, 2, 6, 4], [1, 5, 7, 3]]
    f2 = np.array([t for q in quads for t in ([q[0], q[1], q[2]], [q[0], q[2], q[3]])])
    return np.vstack([v1, v2]), np.vstack([f1, f2 + len(v1)])


VERTICES, FACES = mesh()


@dataclass
class State:
    """The camera's position on a sphere around the torus, and whether to cull back faces.

    Examples
    --------
    >>> State().cull
    True
    """

    azimuth_deg: float = -75.0
    elevation_deg: float = 35.0
    cull: bool = True


def camera(state):
    """View and projection matrices of the state's camera, and its eye point."""
    a, e = np.radians([state.azimuth_deg, state.elevation_deg])
    eye = 4.5 * np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
    up = [0.0, 0.0, 1.0] if abs(state.elevation_deg) < 89.5 else [0.0, 1.0, 0.0]
    view = viewing.look_at(eye, -eye, up)
    return view, viewing.perspective(np.radians(50), 1.0, 1.0, 12.0), eye


def scene(state):
    """Pure part: the culled faces and the z-buffer of the picture.

    Returns
    -------
    dict
        ``eye``, ``back`` (bool per face), ``depth`` (SIZE x SIZE, ``inf`` on background),
        ``drawn`` (triangles sent to the z-buffer), ``fragments``, ``writes``, ``visible``
        (pixels showing a triangle) and ``text``.

    Examples
    --------
    >>> culled, all_faces = scene(State(cull=True)), scene(State(cull=False))
    >>> culled["drawn"] < all_faces["drawn"], bool((culled["depth"] == all_faces["depth"]).all())
    (True, True)
    """
    view, proj, eye = camera(state)
    back = clipping.back_faces(VERTICES, FACES, eye=eye)
    faces = FACES[~back] if state.cull else FACES
    zb = visibility.render_depth(VERTICES, faces, view, proj, SIZE, SIZE)
    visible = int((zb.ids >= 0).sum())
    text = (f"{len(FACES)} triangles, {int(back.sum())} of them back faces. "
            + (f"With culling {len(faces)} are drawn" if state.cull
               else f"Without culling all {len(faces)} are drawn")
            + f": {zb.fragments} fragments rasterized, {zb.writes} depth-buffer writes for "
            f"{visible} visible pixels ({zb.fragments / max(visible, 1):.2f} fragments per "
            "visible pixel). The picture is the same either way: on a closed mesh the back "
            "faces are always hidden; culling only saves work. The inner side of the ring "
            "shows why culling alone is not enough: those faces face the eye and are hidden "
            "by the ring itself.")
    return {"eye": eye, "back": back, "depth": zb.depth, "drawn": len(faces),
            "fragments": zb.fragments, "writes": zb.writes, "visible": visible, "text": text}


class HiddenSurfaceExplorer(Explorer):
    """Camera sliders and a culling toggle; the mesh with its back faces, and the depth buffer.

    In a notebook, after ``%matplotlib widget``, end a cell with ``HiddenSurfaceExplorer()``.

    Examples
    --------
    >>> explorer = HiddenSurfaceExplorer()
    >>> explorer.cull.value = False
    >>> "Without culling" in explorer.info.value
    True
    """

    summary = ("Back-face culling and z-buffer explorer (interactive): a torus seen from a "
               "moving camera, its back faces, and the depth buffer of the picture.")

    def __init__(self, state=None):
        import ipywidgets as w
        import matplotlib

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(7.0, 3.4))
        world = self.fig.add_axes((0.0, 0.0, 0.5, 0.92), projection="3d")
        draw.setup_axes_3d(world, radius=1.9, title="back faces grey, seen from the side",
                           box=False, elev=25, azim=-5)
        self.mesh = draw.mesh_3d(world, VERTICES, FACES, edgecolor="0.35", linewidth=0.2)
        (self.eye,) = world.plot([], [], [], "ko", ms=6)
        (self.sight,) = world.plot([], [], [], color="0.3", lw=0.8, ls="--")
        image = self.fig.add_axes((0.52, 0.1, 0.36, 0.8))
        cmap = matplotlib.colormaps["viridis"].with_extremes(bad="white")
        self.depth = image.imshow(np.ma.masked_invalid(s["depth"]), origin="lower", cmap=cmap,
                                  vmin=0.6, vmax=1.0, extent=(0, SIZE, 0, SIZE),
                                  interpolation="nearest")
        self.fig.colorbar(self.depth, ax=image, fraction=0.046, pad=0.03, label="depth")
        image.set_title("the depth buffer (dark = near)")
        image.set(xticks=[], yticks=[])
        self.blitter = draw.Blitter(self.fig, [self.mesh, self.eye, self.sight, self.depth])
        _style.style_figure(self.fig)
        sliders = degree_sliders(None,
                                 azimuth=("camera azimuth °", self.state.azimuth_deg, -180, 180),
                                 elevation=("camera elevation °", self.state.elevation_deg, -89,
                                            89))
        self.azimuth, self.elevation = sliders.values()
        self.cull = checkbox("cull back faces", self.state.cull)
        bind(self.state, {"azimuth_deg": self.azimuth, "elevation_deg": self.elevation,
                          "cull": self.cull}, self.update)
        self.info = panel(width="330px")
        self.widget = w.VBox([self.fig.canvas, beside(w.VBox([*sliders.values(), self.cull]),
                                                      self.info)])
        self._draw(s)

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        colors = np.where(s["back"][:, None], [[0.7, 0.7, 0.7, 0.25]], [[0.95, 0.55, 0.1, 0.9]])
        self.mesh.set_facecolor(colors)
        eye = s["eye"] / np.linalg.norm(s["eye"]) * 1.9        # drawn inside the view box
        self.eye.set_data_3d([eye[0]], [eye[1]], [eye[2]])
        self.sight.set_data_3d([eye[0], 0], [eye[1], 0], [eye[2], 0])
        self.depth.set_data(np.ma.masked_invalid(s["depth"]))
        self.info.value = s["text"]
