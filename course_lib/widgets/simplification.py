r"""Simplification explorer: replay a QEM edge-collapse simplification one face count at a time.

:func:`course_lib.mesh.simplify_qem` reduces a bumpy sphere of 1,280 triangles to 80 and keeps
the record of every collapse. The slider picks a face count; the mesh after that many collapses
is rendered (pyvista, off screen) with each vertex coloured by its quadric error
:math:`\sqrt{\bar v^T Q \bar v}` (how far it lies from the planes of the original faces it now
stands for), and the five cheapest edges still in the priority queue are drawn in red and listed
with their cost: the first of them that passes the validity checks is the next to go.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, mesh
from . import _style
from ._base import PlotterExplorer, beside, bind, panel, pyvista_faces, slider

__all__ = ["START_FACES", "TARGET_FACES", "SimplificationExplorer", "State", "bumpy_sphere",
           "scene"]

TARGET_FACES = 80
START_FACES = 1280
TOP = 5
_RECORD = {}


def bumpy_sphere(subdivisions=3):
    """An icosphere with a smooth radial bump pattern: flat and curved regions side by side.

    Examples
    --------
    >>> v, f = bumpy_sphere(3)
    >>> len(f)
    1280
    """
    v, f = mesh.icosphere(subdivisions)
    scale = 1 + 0.15 * np.sin(3 * v[:, 0]) * np.sin(4 * v[:, 1]) * np.sin(2 * v[:, 2] + 1)
    return v * scale[:, None], f


def _record():
    """The collapse record of the explorer's mesh (computed once)."""
    if "record" not in _RECORD:
        _RECORD["record"] = mesh.simplify_qem(*bumpy_sphere(3), TARGET_FACES).record
    return _RECORD["record"]


@dataclass
class State:
    """The face count to show.

    Examples
    --------
    >>> State().faces
    400
    """

    faces: int = 400


def scene(state):
    """Pure part: the mesh at the requested face count, its vertex errors, the queue's head.

    Returns
    -------
    dict
        ``vertices``, ``faces`` (the mesh after ``steps`` collapses), ``steps``, ``errors`` (one
        per vertex), ``queue`` (the :data:`TOP` cheapest candidate collapses,
        :meth:`course_lib.mesh.SimplificationRecord.queue_after`), ``segments`` (their edges,
        shape (TOP, 2, 3)), ``max_error`` (over the whole record, for a fixed colour scale)
        and ``text``.

    Examples
    --------
    >>> s = scene(State(faces=1000))
    >>> len(s["faces"]), s["steps"]
    (1000, 140)
    """
    rec = _record()
    n = int(state.faces)
    if not TARGET_FACES <= n <= START_FACES:
        raise ValueError(f"faces must be in {TARGET_FACES}..{START_FACES}, got {state.faces}")
    k = rec.steps_for(n)
    v, f = rec.mesh_after(k)
    errors = rec.errors_after(k)
    queue = rec.queue_after(k, top=TOP)
    _, pos, _ = rec._replay(k)
    segments = np.array([[pos[e.kept], pos[e.removed]] for e in queue]).reshape(-1, 2, 3)
    if "max_error" not in _RECORD:
        _RECORD["max_error"] = float(rec.errors_after(len(rec)).max())
    text = (f"{len(f)} faces, {len(v)} vertices after {k} of {len(rec)} collapses. "
            f"Largest vertex error now {errors.max():.4f} (the sphere has radius about 1).")
    return {"vertices": v, "faces": f, "steps": k, "errors": errors, "queue": queue,
            "segments": segments, "max_error": _RECORD["max_error"], "text": text}


def _queue_table(queue):
    rows = "".join(f"<tr><td>{i + 1}</td><td>{e.kept}–{e.removed}</td><td>{e.cost:.2e}</td>"
                   f"<td>({e.position[0]:.2f}, {e.position[1]:.2f}, {e.position[2]:.2f})</td></tr>"
                   for i, e in enumerate(queue))
    return ("<table style='font-size:12px'><tr><th>#</th><th>edge</th><th>cost</th>"
            f"<th>new position</th></tr>{rows}</table>")



class SimplificationExplorer(PlotterExplorer):
    """Slide the face count down and watch the quadric error grow where the mesh was bumpy.

    Examples
    --------
    >>> explorer = SimplificationExplorer()
    >>> explorer.faces.value = 200
    >>> explorer.poly.n_cells, explorer.png()[:4]
    (200, b'\\x89PNG')
    """

    summary = ("Simplification explorer (interactive): replay QEM edge collapses from 1,280 to "
               "80 faces, vertices coloured by quadric error, the priority queue's head listed.")

    def __init__(self, state=None):
        import ipywidgets as w

        draw.configure_offscreen_vtk()
        import pyvista as pv

        self.state = state or State()
        s = scene(self.state)
        self.plotter = draw.offscreen_plotter(420, 380)
        self.poly = pv.PolyData(s["vertices"], pyvista_faces(s["faces"]))
        self.poly["error"] = s["errors"]
        self.plotter.add_mesh(self.poly, scalars="error", cmap="viridis",
                              clim=(0, 0.5 * s["max_error"]), show_edges=True, edge_color="#303030",
                              line_width=0.5,
                              scalar_bar_args=_style.scalar_bar("error"))
        _style.clear_title(self.plotter.scalar_bars["error"])
        self.candidates = pv.PolyData(s["segments"].reshape(-1, 3),
                                      lines=_lines(len(s["segments"])))
        self.plotter.add_mesh(self.candidates, color="#d0021b", line_width=5)
        # the focal point a little to the right of the mesh: the mesh sits left of the colour bar
        right = 0.3 * np.array([0.55, 0.83, 0.0])
        self.plotter.camera_position = [(3.6, -2.4, 2.0) + right, right, (0, 0, 1)]
        screen = self.screen()
        self.faces = slider("faces", self.state.faces, TARGET_FACES, START_FACES, 2,
                            kind=w.IntSlider)
        bind(self.state, {"faces": self.faces}, self.update)
        self.info = panel(width="380px")
        self.table = panel()
        self.widget = beside(screen, w.VBox([self.faces, self.info, self.table]),
                             align="flex-start")
        self._draw(s)

    def update(self):
        """Replay the record to the slider's face count and render the new mesh."""
        self._draw(scene(self.state))

    def _draw(self, s):
        import pyvista as pv

        new = pv.PolyData(s["vertices"], pyvista_faces(s["faces"]))
        new["error"] = s["errors"]
        self.poly.copy_from(new)
        self.poly.set_active_scalars("error")
        self.candidates.copy_from(pv.PolyData(s["segments"].reshape(-1, 3),
                                              lines=_lines(len(s["segments"]))))
        self.show()
        self.info.value = (s["text"] + " Red: the cheapest edges in the priority queue "
                           "(the next collapses).")
        self.table.value = _queue_table(s["queue"])


def _lines(k):
    return np.column_stack([np.full(k, 2), 2 * np.arange(k), 2 * np.arange(k) + 1]).ravel()
