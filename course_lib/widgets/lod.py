r"""LOD explorer: a bumpy sphere seen from a distance, its level chosen by the screen-space error.

Five levels of the bumpy sphere (1,280 down to 80 triangles) come from one
:func:`course_lib.mesh.simplify_qem` run (:func:`course_lib.mesh.lod_chain`), each with its
geometric error :math:`\varepsilon_i`. A camera with a 40° vertical field of view on a viewport
1080 pixels high sees the error of level :math:`i` at distance :math:`d` as
:math:`\varepsilon_i H / (2 d \tan 20°)` pixels; the explorer draws the coarsest level within the
pixel tolerance (:func:`course_lib.mesh.select_level`). The left panel shows that level
magnified to a fixed size (at its true size it would cover only the few pixels printed below);
the right panel plots every level's screen-space error against the distance, with the tolerance
and the switch distances. With *geomorph* on, for a stretch of 35 % of the distance past each
switch the mesh blends from the finer level into the coarser one
(:meth:`course_lib.mesh.ProgressiveMesh.geomorph`) instead of jumping (popping).
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, mesh
from . import _style
from ._base import Explorer, bind, checkbox, panel, slider
from .simplification import bumpy_sphere

__all__ = ["BAND", "FACE_COUNTS", "FOV", "HEIGHT", "LODExplorer", "State", "levels", "scene"]

FACE_COUNTS = (1280, 640, 320, 160, 80)
FOV = np.radians(40.0)          # vertical field of view of the virtual camera
HEIGHT = 1080                   # its viewport height in pixels
BAND = 0.35                     # a geomorph lasts from d_i to (1 + BAND) d_i
_LIGHT = np.array([-0.4, 0.5, 0.77]) / np.linalg.norm([-0.4, 0.5, 0.77])
_CACHE = {}
# a fixed turn of the model, so that the bumps face the camera at an angle
_C, _S = np.cos(0.5), np.sin(0.5)
_TURN = np.array([[1, 0, 0], [0, _C, -_S], [0, _S, _C]]) @ np.array([[_C, 0, _S], [0, 1, 0],
                                                                      [-_S, 0, _C]])


def levels():
    """The LOD chain and its progressive mesh, computed once.

    Returns
    -------
    chain : course_lib.mesh.LODChain
    pm : course_lib.mesh.ProgressiveMesh

    Examples
    --------
    >>> chain, pm = levels()
    >>> chain.face_counts.tolist()
    [1280, 640, 320, 160, 80]
    """
    if "chain" not in _CACHE:
        v, f = bumpy_sphere(3)
        chain = mesh.lod_chain(v @ _TURN.T, f, FACE_COUNTS)
        _CACHE["chain"] = chain
        _CACHE["pm"] = mesh.ProgressiveMesh(record=chain.record)
    return _CACHE["chain"], _CACHE["pm"]


@dataclass
class State:
    """The viewer's distance, the pixel tolerance, and popping or geomorphs.

    Examples
    --------
    >>> State().distance, State().geomorph
    (95.0, True)
    """

    distance: float = 95.0
    tolerance: float = 1.0
    geomorph: bool = True


def _lod_polygons(v, f, distance):
    """Visible triangles (back faces culled), far to near, projected from the eye at
    (0, 0, distance) and scaled to a fixed size; their Lambert grey levels."""
    depth = distance - v[:, 2]
    xy = v[:, :2] * ((distance - 1.2) / depth)[:, None]     # the silhouette keeps its size
    tri = v[f]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    centre = tri.mean(axis=1)
    to_eye = np.array([0.0, 0.0, distance]) - centre
    front = np.einsum("ij,ij->i", n, to_eye) > 0
    order = np.argsort(-np.linalg.norm(to_eye[front], axis=1), kind="stable")
    faces = f[front][order]
    normal = n[front][order]
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-300)
    shade = 0.25 + 0.7 * np.clip(normal @ _LIGHT, 0, 1)
    return xy[faces], shade


def scene(state):
    """Pure part: the level chosen, the mesh drawn (geomorphed or not), the plot's data, text.

    Returns
    -------
    dict
        ``level`` (index), ``faces`` (face count of the mesh drawn), ``screen_error`` (of the
        chosen level, pixels), ``switch`` (switch distances), ``alpha`` (geomorph blend: 1 =
        the finer level, 0 = the chosen one; None when not blending), ``vertices``,
        ``triangles`` (the mesh drawn), ``polygons``, ``shade`` (the visible projected
        triangles), ``size_px`` (the sphere's diameter on the real screen) and ``text``.

    Examples
    --------
    >>> s = scene(State(distance=95.0, tolerance=1.0, geomorph=False))
    >>> s["level"], s["faces"], s["alpha"] is None
    (2, 320, True)
    """
    chain, pm = levels()
    d = float(state.distance)
    tau = float(state.tolerance)
    if not d > 0:
        raise ValueError(f"distance must be > 0, got {state.distance!r}")
    if not tau > 0:
        raise ValueError(f"tolerance must be > 0, got {state.tolerance!r}")
    errors = chain.errors
    level = mesh.select_level(errors, d, FOV, HEIGHT, tau)
    switch = mesh.switch_distances(errors, FOV, HEIGHT, tau)
    px = mesh.screen_space_error(errors, d, FOV, HEIGHT)
    alpha = None
    if state.geomorph and level > 0 and d < (1 + BAND) * switch[level]:
        alpha = 1.0 - (d - switch[level]) / (BAND * switch[level])
        v, f = pm.geomorph(int(chain.face_counts[level]), int(chain.face_counts[level - 1]),
                           alpha)
    else:
        v, f = chain.levels[level]
    polygons, shade = _lod_polygons(v, f, d)
    size = float(mesh.screen_space_error(2.3, d, FOV, HEIGHT))
    text = (f"Distance {d:g}: level {level} ({chain.face_counts[level]} faces), geometric error "
            f"{errors[level]:.4f}, screen-space error <b>{px[level]:.2f} px</b> ≤ τ = {tau:g} px"
            + (f"; level {level + 1} would show {px[level + 1]:.2f} px."
               if level + 1 < len(errors) else ".")
            + f" On a {HEIGHT}-pixel-high viewport (fov 40°) the sphere is about "
              f"{size:.0f} px wide; the picture is magnified.")
    if alpha is not None:
        text += (f" <b>Geomorph</b>: blending level {level - 1} → {level}, "
                 f"α = {alpha:.2f} of the way still at the finer level ({len(f)} faces drawn, "
                 f"the split vertices sliding to their collapsed positions).")
    elif state.geomorph:
        text += " Geomorph on: no transition at this distance."
    else:
        text += " Popping: the level changes in one frame at each switch distance."
    return {"level": level, "faces": len(f), "screen_error": float(px[level]),
            "switch": switch, "alpha": alpha, "vertices": v, "triangles": f,
            "polygons": polygons, "shade": shade, "size_px": size, "text": text}


class LODExplorer(Explorer):
    """Move the viewer away and watch the level drop once its error falls below the tolerance.

    In a notebook, after ``%matplotlib widget``, end a cell with ``LODExplorer()``.

    Examples
    --------
    >>> explorer = LODExplorer()
    >>> explorer.distance.value = 300.0
    >>> explorer.state.distance, len(explorer.mesh.get_paths()) < 200
    (300.0, True)
    """

    summary = ("LOD explorer (interactive): a bumpy sphere's level of detail chosen by its "
               "screen-space error from the viewer's distance and a pixel tolerance, popping "
               "or geomorphing between levels, with the error-versus-distance plot.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import PolyCollection

        self.state = state or State()
        chain, _ = levels()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(6.4, 3.0))
        ax = self.fig.add_axes((0.02, 0.03, 0.40, 0.85))
        ax.set(xlim=(-1.3, 1.3), ylim=(-1.3, 1.3), aspect="equal")
        ax.axis("off")
        self.mesh = PolyCollection([], edgecolors="#202020", linewidths=0.3, cmap="gray",
                                   clim=(0, 1))
        ax.add_collection(self.mesh)
        self.title = ax.set_title("", fontsize=8)
        plot = self.fig.add_axes((0.53, 0.17, 0.45, 0.72))
        d = np.geomspace(5, 500, 100)
        for i in range(1, len(chain.errors)):
            plot.loglog(d, mesh.screen_space_error(chain.errors[i], d, FOV, HEIGHT),
                        color=f"C{i}", lw=1.2, label=f"level {i} ({chain.face_counts[i]})")
        plot.set(xlim=(5, 500), ylim=(0.05, 200), xlabel="distance d",
                 ylabel="screen-space error (px)")
        (self.tolerance_line,) = plot.plot([], [], color="k", lw=1, ls="--", label="tolerance τ")
        (self.switch_marks,) = plot.plot([], [], "v", color="k", ms=5)
        (self.now_line,) = plot.plot([], [], color="#c62828", lw=1)
        (self.now_dot,) = plot.plot([], [], "o", color="#c62828", ms=6)
        _style.legend(plot, loc="upper right", fontsize=6.5, handlelength=1.5)
        plot.tick_params(labelsize=7)
        plot.xaxis.label.set_size(8)
        plot.yaxis.label.set_size(8)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.mesh, self.title, self.tolerance_line,
                                               self.switch_marks, self.now_line, self.now_dot])
        self.distance = slider("distance", self.state.distance, 0.7, 2.7, 0.01,
                               kind=w.FloatLogSlider, readout_format=".0f")
        self.tolerance = slider("tolerance px", self.state.tolerance, 0.5, 8, 0.5)
        self.geomorph = checkbox("geomorph (else popping)", self.state.geomorph)
        bind(self.state, {"distance": self.distance, "tolerance": self.tolerance,
                          "geomorph": self.geomorph}, self.update)
        self.info = panel(width="640px")
        self.widget = w.VBox([self.fig.canvas, w.HBox([self.distance, self.tolerance]),
                              self.geomorph, self.info])
        self._draw(s)

    def update(self):
        """Choose the level for the new distance and tolerance and redraw the moving parts."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.mesh.set_verts(list(s["polygons"]))
        self.mesh.set_array(s["shade"])
        if s["alpha"] is None:
            self.title.set_text(f"level {s['level']}: {s['faces']} faces, "
                                f"{s['screen_error']:.2f} px")
        else:
            self.title.set_text(f"geomorph {s['level'] - 1}→{s['level']}, α = {s['alpha']:.2f} "
                                f"({s['faces']} faces)")
        tau, d = float(self.state.tolerance), float(self.state.distance)
        self.tolerance_line.set_data([5, 500], [tau, tau])
        sw = s["switch"][1:]
        self.switch_marks.set_data(sw, np.full(len(sw), tau))
        self.now_line.set_data([d, d], [0.05, 200])
        self.now_dot.set_data([d], [max(s["screen_error"], 0.05)])
        self.info.value = s["text"]
