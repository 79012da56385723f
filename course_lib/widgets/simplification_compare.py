r"""Simplification comparison explorer: clustering, vertex decimation and QEM at one face count.

The same bumpy sphere (1,280 triangles) is simplified three ways to about the same number of
faces, chosen on the slider: vertex clustering on a grid (:func:`course_lib.mesh.vertex_clustering`
with quadric representatives; the grid is chosen to give the face count closest to the target),
vertex decimation (:func:`course_lib.mesh.decimate`) and QEM edge collapse
(:func:`course_lib.mesh.simplify_qem`). Each face is coloured by the distance of its centre to the
original surface, and the text gives each method's Hausdorff and RMS distance
(:func:`course_lib.mesh.surface_distance`). Everything is computed once, when the explorer is
built; the slider only swaps precomputed meshes.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw
from ..mesh.clustering import vertex_clustering
from ..mesh.decimation import decimate
from ..mesh.distances import point_mesh_distance, surface_distance
from ..mesh.simplify import simplify_qem
from . import _style
from ._base import PlotterExplorer, beside, bind, labelled, panel, pyvista_faces
from .simplification import bumpy_sphere

__all__ = ["LEVELS", "METHODS", "SimplificationComparisonExplorer", "State", "scene"]

#: The face counts the slider offers (the original has 1,280).
LEVELS = (800, 500, 300, 200, 120)
METHODS = ("clustering", "decimation", "QEM")
_CACHE = {}
_SAMPLES = 1500
#: Decimation's feature angle here: the coarse levels have dihedral angles beyond 30 degrees
#: everywhere, and corners are never removed; 80 degrees lets it reach 120 faces.
_FEATURE = np.radians(80)


def _original():
    if "original" not in _CACHE:
        _CACHE["original"] = bumpy_sphere(3)
    return _CACHE["original"]


def _clustered(v, f, target):
    """The quadric vertex clustering whose face count is closest to `target` (cells 2..40)."""
    best = None
    for cells in range(2, 41):
        out = vertex_clustering(v, f, cells=cells, representative="quadric")
        if best is None or abs(len(out.faces) - target) < abs(len(best[0].faces) - target):
            best = (out, cells)
        if len(out.faces) > target:
            break
    return best[0].vertices, best[0].faces, f"{best[1]} cells across"


def _level(target):
    """The three simplifications at `target` faces, their face errors and surface distances."""
    if target in _CACHE:
        return _CACHE[target]
    v, f = _original()
    if "qem" not in _CACHE:
        _CACHE["qem"] = simplify_qem(v, f, min(LEVELS)).record
    rec = _CACHE["qem"]
    meshes = {"clustering": _clustered(v, f, target)}
    d = decimate(v, f, target, feature_angle=_FEATURE)
    meshes["decimation"] = (d.vertices, d.faces, "vertices removed")
    meshes["QEM"] = (*rec.mesh_after(rec.steps_for(target)), "edges collapsed")
    out = {}
    for name, (mv, mf, note) in meshes.items():
        centre = mv[mf].mean(axis=1)
        err = point_mesh_distance(centre, v, f)
        dist = surface_distance(v, f, mv, mf, samples=_SAMPLES, seed=0)
        out[name] = {"vertices": mv, "faces": mf, "face_error": err, "distance": dist,
                     "note": note}
    _CACHE[target] = out
    return out


@dataclass
class State:
    """The face count to reach (one of :data:`LEVELS`).

    Examples
    --------
    >>> State().faces
    300
    """

    faces: int = 300


def scene(state):
    """Pure part: the three simplified meshes at the state's face count, with their errors.

    Returns
    -------
    dict
        ``methods``: for each name of :data:`METHODS` a dict with ``vertices``, ``faces``,
        ``face_error`` (distance of each face's centre to the original surface), ``distance``
        (a :class:`course_lib.mesh.SurfaceDistance`) and ``note``; ``clim`` (the colour
        scale's top, the same for every level), ``text``.

    Examples
    --------
    >>> s = scene(State(faces=500))
    >>> [abs(len(s["methods"][m]["faces"]) - 500) <= 60 for m in METHODS]
    [True, True, True]
    """
    n = int(state.faces)
    if n not in LEVELS:
        raise ValueError(f"faces must be one of {LEVELS}, got {state.faces!r}")
    level = _level(n)
    if "clim" not in _CACHE:
        worst = _level(min(LEVELS))
        _CACHE["clim"] = float(max(np.percentile(worst[m]["face_error"], 95) for m in METHODS))
    lines = []
    for m in METHODS:
        r = level[m]
        d = r["distance"]
        lines.append(f"<b>{m}</b>: {len(r['faces'])} faces ({r['note']}), Hausdorff "
                     f"{d.hausdorff:.4f}, RMS {d.rms:.4f}")
    text = (f"Target {n} faces (the original has {len(_original()[1])}; radius about 1). "
            + "; ".join(lines) + ".")
    return {"methods": level, "clim": _CACHE["clim"], "text": text}


class SimplificationComparisonExplorer(PlotterExplorer):
    """Three simplifications side by side at one face count, faces coloured by their error.

    Examples
    --------
    >>> explorer = SimplificationComparisonExplorer()
    >>> explorer.faces.value = 120
    >>> explorer.polys["QEM"].n_cells, explorer.png()[:4]
    (120, b'\\x89PNG')
    """

    summary = ("Simplification comparison (interactive): vertex clustering, vertex decimation "
               "and QEM edge collapse of one mesh at the same face count, faces coloured by "
               "their distance to the original, Hausdorff and RMS distances listed.")

    def __init__(self, state=None):
        import ipywidgets as w

        draw.configure_offscreen_vtk()
        import pyvista as pv

        self.state = state or State()
        for n in LEVELS:                      # precompute every level: the slider only swaps
            scene(State(faces=n))
        s = scene(self.state)
        scale = draw.lecture_scale()
        # three meshes and, in a narrow fourth column of its own, the colour bar: laid over
        # the third mesh its labels were unreadable on the dark faces
        self.plotter = pv.Plotter(off_screen=True, shape=(1, 4), border=False,
                                  col_weights=[9, 9, 9, 3],
                                  window_size=(round(820 * scale), round(260 * scale)))
        self.plotter.set_background("white")
        self.polys = {}
        for i, m in enumerate(METHODS):
            r = s["methods"][m]
            self.plotter.subplot(0, i)
            poly = pv.PolyData(r["vertices"], pyvista_faces(r["faces"]))
            poly.cell_data["error"] = r["face_error"]
            self.polys[m] = poly
            actor = self.plotter.add_mesh(poly, scalars="error", cmap="viridis",
                                          clim=(0, s["clim"]), show_edges=True,
                                          edge_color="#303030", line_width=0.5,
                                          show_scalar_bar=False)
            self.plotter.add_text(m, font_size=9, color="black")
            self.plotter.camera_position = [(3.2, -2.2, 1.8), (0, 0, 0), (0, 0, 1)]
        self.plotter.subplot(0, 3)
        _style.clear_title(self.plotter.add_scalar_bar(mapper=actor.mapper, **_style.scalar_bar(
            "distance", position_x=0.3, position_y=0.08, width=0.16, height=0.72)))
        screen = self.screen()
        self.faces = labelled(w.SelectionSlider, "faces", options=list(LEVELS),
                              value=self.state.faces, continuous_update=True)
        bind(self.state, {"faces": self.faces}, self.update)
        self.info = panel(width="820px")
        self.widget = w.VBox([screen, beside(self.faces, self.info, align="flex-start")])
        self._draw(s)

    def update(self):
        """Swap in the precomputed meshes of the slider's face count and render."""
        self._draw(scene(self.state))

    def _draw(self, s):
        import pyvista as pv

        for m in METHODS:
            r = s["methods"][m]
            new = pv.PolyData(r["vertices"], pyvista_faces(r["faces"]))
            new.cell_data["error"] = r["face_error"]
            self.polys[m].copy_from(new)
            self.polys[m].set_active_scalars("error", preference="cell")
        self.show()
        self.info.value = s["text"]
