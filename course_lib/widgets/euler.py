r"""Euler explorer: V, E, F, boundary loops and genus of the procedural meshes, checked live.

For a connected orientable surface with :math:`g` handles and :math:`b` boundary loops,
:math:`V - E + F = 2 - 2g - b`. Pick a mesh and refine it: V, E and F change, their alternating
sum does not (a topological invariant), and the genus read off the formula matches the number of
holes one can see.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, mesh
from .._validate import as_choice
from ._base import Explorer, align, beside, bind, figure_3d, labelled, panel, slider

__all__ = ["MESHES", "EulerExplorer", "State", "scene"]

#: name -> function(refinement level 0..3) -> (vertices, faces)
MESHES = {
    "tetrahedron": lambda r: mesh.tetrahedron(),
    "cube": lambda r: mesh.cube(),
    "icosphere": lambda r: mesh.icosphere(r),
    "disc": lambda r: mesh.disc(rings=1 + r, segments=6 + 3 * r),
    "torus": lambda r: mesh.torus(segments=8 + 4 * r, rings=4 + 2 * r),
    "double torus": lambda r: mesh.double_torus(segments=12 + 4 * r, rings=6 + 2 * r),
}


@dataclass
class State:
    """The mesh and how finely it is made (ignored by the tetrahedron and the cube).

    Examples
    --------
    >>> State().mesh
    'torus'
    """

    mesh: str = "torus"
    refinement: int = 1


def scene(state):
    r"""Pure part: the mesh (scaled to fit radius 1.4) and its topological numbers.

    Returns
    -------
    dict
        ``vertices``, ``faces``, ``V``, ``E``, ``F``, ``chi`` (V - E + F), ``boundaries`` (b),
        ``genus`` (from :math:`\chi = 2 - 2g - b`), ``closed``, ``manifold`` and ``text``.

    Examples
    --------
    >>> s = scene(State("torus", 0))
    >>> s["V"], s["E"], s["F"], s["chi"], s["genus"]
    (32, 96, 64, 0, 1)
    """
    as_choice(state.mesh, "mesh", list(MESHES))
    r = int(state.refinement)
    if not 0 <= r <= 3:
        raise ValueError(f"refinement must be in 0..3, got {state.refinement}")
    v, f = MESHES[state.mesh](r)
    he = mesh.HalfEdgeMesh.from_faces(v, f)
    V, E, F = he.n_vertices, he.n_edges, he.n_faces
    chi, b = V - E + F, he.boundary_components()
    genus = (2 - b - chi) // 2
    assert genus == he.genus()                       # the library's own count agrees
    ok = "✓" if chi == 2 - 2 * genus - b else "✗"
    text = (f"V − E + F = {V} − {E} + {F} = <b>{chi}</b>; b = {b} boundary loop(s); "
            f"2 − 2g − b = {chi} gives <b>g = {genus}</b> {ok}. "
            f"{'Closed' if he.is_closed() else 'Open'}, "
            f"{'manifold' if he.is_manifold() else 'non-manifold'}.")
    scale = 1.4 / np.abs(he.vertices).max()
    faces = f.tolist() if isinstance(f, np.ndarray) else [list(x) for x in f]
    return {"vertices": he.vertices * scale, "faces": faces, "V": V, "E": E, "F": F,
            "chi": chi, "boundaries": b, "genus": genus, "closed": he.is_closed(),
            "manifold": he.is_manifold(), "text": text}


class EulerExplorer(Explorer):
    """Choose a procedural mesh and refine it; V − E + F and the genus are recomputed live.

    Examples
    --------
    >>> explorer = EulerExplorer()
    >>> explorer.choice.value = "double torus"
    >>> "g = 2" in explorer.info.value
    True
    """

    summary = ("Euler explorer (interactive): V, E, F, boundary loops and genus of the "
               "procedural meshes; refining changes V, E, F but not V − E + F.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig, self.ax = figure_3d(1.5, "V − E + F = 2 − 2g − b", size=4.2)
        s = scene(self.state)
        self.surface = draw.mesh_3d(self.ax, s["vertices"], s["faces"], linewidth=0.4)
        self.blitter = draw.Blitter(self.fig, [self.surface])
        self.choice = labelled(w.Dropdown, "mesh", options=list(MESHES), value=self.state.mesh)
        self.refinement = slider("refine", self.state.refinement, 0, 3, 1, kind=w.IntSlider)
        align([self.choice, self.refinement])
        bind(self.state, {"mesh": self.choice, "refinement": self.refinement}, self.update)
        self.info = panel(width="360px")
        self.widget = beside(self.fig.canvas, w.VBox([self.choice, self.refinement, self.info]))
        self._draw(s)

    def update(self):
        """Build the chosen mesh, count, and redraw it."""
        self._draw(scene(self.state))

    def _draw(self, s):
        colors = draw.shade(draw.face_normals(s["vertices"], s["faces"]), (0.55, 0.7, 0.9))
        draw.set_mesh_3d(self.surface, s["vertices"], s["faces"], facecolors=colors)
        self.info.value = s["text"]
        self.blitter.update()
