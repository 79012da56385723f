r"""Mesh-structure explorer: walk a half-edge structure one pointer at a time.

A half-edge :math:`h` stores its origin vertex, its face, ``next`` and ``prev`` (the neighbouring
half-edges around that face) and ``twin`` (the half-edge running the other way along the same
edge, on the neighbouring face). Three buttons follow those pointers; the current half-edge is
drawn as a thick arrow inside its face, with its face, its ``next``, ``prev`` and ``twin``
highlighted. The same edge as a winged-edge record (start and end vertex, left and right face,
the four wing edges) is listed in a table beside it, so the two structures can be compared.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, mesh
from .._validate import as_choice
from . import _style
from ._base import Explorer, align, beside, bind, figure_3d, labelled, panel

__all__ = ["MESHES", "HalfEdgeExplorer", "State", "scene"]

#: The small meshes the explorer offers (a boundary appears in the disc and the open box).
MESHES = {
    "tetrahedron": lambda: mesh.tetrahedron(),
    "cube (quads)": lambda: mesh.cube(),
    "cube (triangles)": lambda: mesh.cube(triangulated=True),
    "disc (boundary)": lambda: mesh.disc(rings=2, segments=6),
}

_CACHE = {}


def _structures(name):
    """The half-edge and winged-edge structures of a named mesh (built once)."""
    as_choice(name, "mesh", list(MESHES))
    if name not in _CACHE:
        he = mesh.HalfEdgeMesh.from_faces(*MESHES[name]())
        _CACHE[name] = (he, mesh.WingedEdgeMesh.from_half_edges(he))
    return _CACHE[name]


@dataclass
class State:
    """The mesh and the current half-edge.

    Examples
    --------
    >>> State().half_edge
    0
    """

    mesh: str = "cube (quads)"
    half_edge: int = 0


def _inset(he, h, amount=0.18):
    """Half-edge `h` as a segment pulled towards its face's centre (beside its twin), shape (2, 3).

    A boundary half-edge (no face) is pulled away from the centre of the face on its twin's side.
    """
    v = he.vertices
    a, b = v[he.origin[h]], v[he.origin[he.next[h]]]
    f = he.face[h]
    if f >= 0:
        centre = v[he.face_vertices(f)].mean(axis=0)
        sign = 1.0
    else:
        centre = v[he.face_vertices(he.face[he.twin[h]])].mean(axis=0)
        sign = -1.0
    mid = 0.5 * (a + b)
    shift = sign * amount * (centre - mid)
    shrink = 0.12 * (b - a)
    return np.array([a + shrink + shift, b - shrink + shift])


def scene(state):
    """Pure part: the mesh, the current half-edge and its neighbours, the winged-edge record.

    Returns
    -------
    dict
        ``vertices``, ``faces`` (list of index lists), ``current``, ``next``, ``prev``, ``twin``
        (segments, shape (2, 3), drawn inside their faces), ``face`` (the current face's polygon,
        empty for a boundary half-edge), ``record`` (the half-edge's fields, see
        :meth:`course_lib.mesh.HalfEdgeMesh.describe`), ``winged`` (the winged-edge record of its
        edge), ``same_direction`` (does the edge record run the same way as the half-edge?) and
        ``text``.

    Examples
    --------
    >>> s = scene(State(mesh="tetrahedron", half_edge=0))
    >>> s["record"]["origin"], s["record"]["target"], s["winged"]["start"], s["winged"]["end"]
    (0, 1, 0, 1)
    """
    he, we = _structures(state.mesh)
    h = int(state.half_edge)
    if not 0 <= h < he.n_half_edges:
        raise ValueError(f"half_edge must be in 0..{he.n_half_edges - 1}, got {state.half_edge}")
    record = he.describe(h)
    u, w = record["origin"], record["target"]
    e = we.find_edge(u, w)
    winged = we.records()[e]
    same = winged["start"] == u
    f = record["face"]
    polygon = he.vertices[he.face_vertices(f)] if f >= 0 else np.empty((0, 3))
    side = "left" if same else "right"
    where = f"face {f}" if f >= 0 else "no face: a boundary half-edge (the rim of a hole)"
    text = (f"Half-edge {h} runs from vertex {u} to vertex {w}; {where}. "
            f"next = {record['next']}, prev = {record['prev']}, twin = {record['twin']}. "
            f"In the winged-edge table this is edge {e}, stored from {winged['start']} to "
            f"{winged['end']}: the half-edge's face is its <b>{side}</b> face, so a winged-edge "
            f"walk around face {f} must use the {side} wings.")
    return {"vertices": he.vertices, "faces": he.to_faces(), "current": _inset(he, h),
            "next": _inset(he, record["next"]), "prev": _inset(he, record["prev"]),
            "twin": _inset(he, record["twin"]), "face": polygon, "record": record,
            "winged": winged, "same_direction": bool(same), "text": text}


def _table(record, winged):
    """The two records as HTML tables side by side."""
    def rows(d):
        return "".join(f"<tr><td>{k}</td><td><b>{v}</b></td></tr>" for k, v in d.items())
    style = "border-collapse:collapse;margin-right:14px;font-size:12px"
    return (f"<div style='display:flex'><table style='{style}'><tr><th colspan=2>half-edge"
            f"</th></tr>{rows(record)}</table><table style='{style}'><tr><th colspan=2>"
            f"winged edge</th></tr>{rows(winged)}</table></div>")


class HalfEdgeExplorer(Explorer):
    """Choose a half-edge and follow next / previous / opposite (twin) through the mesh.

    Examples
    --------
    >>> explorer = HalfEdgeExplorer()
    >>> h = explorer.state.half_edge
    >>> explorer.step("next")
    >>> bool(explorer.state.half_edge == explorer.he.next[h])
    True
    """

    summary = ("Half-edge explorer (interactive): pick a half-edge and step next / previous / "
               "twin; the winged-edge record of the same edge is shown beside it.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig, self.ax = figure_3d(1.6, "half-edge walk", size=4.2)
        self.ax.computed_zorder = False        # the highlighted edges stay on top of the faces
        s = scene(self.state)
        self.he = _structures(self.state.mesh)[0]
        self.surface = draw.mesh_3d(self.ax, s["vertices"], s["faces"], facecolor="#dde6f0",
                                    edgecolor="0.35", alpha=0.35, zorder=1)
        (self.points,) = self.ax.plot(*s["vertices"].T, "o", color="0.3", ms=3)
        self.labels = [self.ax.text(*p * 1.12, str(i), fontsize=_style.ANNOTATION, color="0.25")
                       for i, p in enumerate(s["vertices"])]
        self.face = draw.mesh_3d(self.ax, np.zeros((3, 3)), [[0, 1, 2]], facecolor="#f5a623",
                                 edgecolor="none", alpha=0.45, zorder=2)
        self.lines = {}
        styles = {"current": ("#d0021b", 3.5, "-"), "next": ("#2a9d3a", 2, "-"),
                  "prev": ("#7b3fb5", 2, "-"), "twin": ("#1f5fbf", 2, "--")}
        for key, (color, width, dash) in styles.items():
            (self.lines[key],) = self.ax.plot([], [], [], dash, color=color, lw=width, label=key)
            self.lines[key].set_zorder(5)
        (self.head,) = self.ax.plot([], [], [], "o", color="#d0021b", ms=6, zorder=6,
                                    label="head of current")
        _style.legend(self.ax, loc="upper left", frameon=False, borderaxespad=0,
                      handlelength=1.5, labelspacing=0.25)
        self.blitter = draw.Blitter(self.fig, [self.face, *self.lines.values(), self.head])
        self.choice = labelled(w.Dropdown, "mesh", options=list(MESHES), value=self.state.mesh)
        self.index = labelled(w.BoundedIntText, "half-edge", value=self.state.half_edge, min=0,
                              max=self.he.n_half_edges - 1)
        align([self.choice, self.index])
        self.buttons = {}
        for name in ("previous", "next", "opposite"):
            button = w.Button(description=name, layout=w.Layout(
                width=_style.button_width("previous", "next", "opposite")))
            button.on_click(lambda _, name=name: self.step(name))
            self.buttons[name] = button
        self.choice.observe(self._on_mesh, names="value")
        bind(self.state, {"half_edge": self.index}, self.update)
        self.info = panel(width="380px")
        self.table = panel()
        controls = w.VBox([self.choice, self.index, w.HBox(list(self.buttons.values())),
                           self.info, self.table])
        self.widget = beside(self.fig.canvas, controls)
        self._draw(s)

    def step(self, name):
        """Follow one pointer from the current half-edge: "next", "previous" or "opposite"."""
        h = self.state.half_edge
        target = {"next": self.he.next, "previous": self.he.prev,
                  "opposite": self.he.twin}[name][h]
        self.index.value = int(target)          # runs update() through the observer

    def _on_mesh(self, change):
        self.state.mesh = change["new"]
        self.he = _structures(self.state.mesh)[0]
        s = scene(State(self.state.mesh, 0))
        draw.set_mesh_3d(self.surface, s["vertices"], s["faces"])
        self.points.set_data_3d(*s["vertices"].T)
        for label in self.labels:
            label.remove()
        self.labels = [self.ax.text(*p * 1.12, str(i), fontsize=_style.ANNOTATION, color="0.25")
                       for i, p in enumerate(s["vertices"])]
        self.state.half_edge = 0
        with self.index.hold_trait_notifications(), self.index.hold_sync():
            self.index.max = self.he.n_half_edges - 1
            self.index.value = 0
        self.blitter.forget_background()
        self.update()

    def update(self):
        """Recompute the scene and move the highlighted artists."""
        self._draw(scene(self.state))

    def _draw(self, s):
        for key, line in self.lines.items():
            line.set_data_3d(*s[key].T)
        self.head.set_data_3d(*s["current"][1:].T)
        if len(s["face"]):
            draw.set_mesh_3d(self.face, s["face"], [list(range(len(s["face"])))])
        else:
            draw.set_mesh_3d(self.face, np.zeros((3, 3)), [[0, 1, 2]])
        self.info.value = s["text"]
        self.table.value = _table(s["record"], s["winged"])
        self.blitter.update()
