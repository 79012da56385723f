r"""Projection-class explorer: one box under a perspective, parallel or oblique projection.

Turn the view (azimuth about the vertical z axis, elevation above the ground) and the class of
the projection changes with it, named live by :func:`course_lib.projections.classify_projection`:
a front view in perspective is a one-point perspective, raising or lowering the eye adds the
third vanishing point, and a parallel view from azimuth 45° and elevation 35.3° (the slider
step nearest 35.264°) is isometric.
In perspective the box's edges are extended (dashed) to the principal vanishing points of their
directions (:func:`course_lib.projections.principal_vanishing_points`); edges parallel to the
image plane have none and stay parallel. The oblique projection (cavalier, cabinet or general)
keeps the front face in true shape and draws depth at the chosen angle and length.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, projections
from .._validate import as_choice
from . import _style
from ._base import Explorer, beside, bind, panel, slider

__all__ = ["KINDS", "ProjectionClassExplorer", "State", "scene"]

KINDS = ("perspective", "parallel", "oblique")
#: The box: half sizes along x, y, z (a brick, so that isometric and dimetric differ visibly).
HALF = np.array([1.0, 0.7, 0.5])
_CORNERS = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], float) * HALF
#: Edges grouped by the axis they run along: 4 edges per axis, (corner, corner).
_EDGES = [[(a, b) for a in range(8) for b in range(a + 1, 8)
           if np.count_nonzero(_CORNERS[a] != _CORNERS[b]) == 1
           and _CORNERS[a][axis] != _CORNERS[b][axis]] for axis in range(3)]
_COLOURS = ("#1565c0", "#c62828", "#2e7d32")
LIMIT = 3.2
#: Perspective: the plane of projection at this distance from the eye; parallel views are
#: scaled by PARALLEL_SCALE, so that the box fills about as much of the picture.
PLANE = 2.0
PARALLEL_SCALE = 1.6


@dataclass
class State:
    """The projection kind, the view's azimuth and elevation, the eye's distance, the oblique
    angle and length.

    Examples
    --------
    >>> State().kind, State().azimuth_deg
    ('perspective', 35.0)
    """

    kind: str = "perspective"
    azimuth_deg: float = 35.0
    elevation_deg: float = 0.0
    distance: float = 3.5
    oblique_angle_deg: float = 30.0
    oblique_length: float = 0.5


def _matrix(state):
    kind = as_choice(state.kind, "kind", KINDS)
    az, el = np.radians(state.azimuth_deg), np.radians(state.elevation_deg)
    if kind == "perspective":
        return projections.perspective_view(az, el, state.distance, PLANE)
    zoom = np.diag([PARALLEL_SCALE, PARALLEL_SCALE, PARALLEL_SCALE, 1.0])
    if kind == "parallel":
        return zoom @ projections.axonometric(az, el)
    return zoom @ projections.oblique_projection(np.radians(state.oblique_angle_deg),
                                                 state.oblique_length)


def _polyline(segments):
    """Segments (n, 2, 2) as one polyline with NaN breaks, shape (3n, 2)."""
    if len(segments) == 0:
        return np.empty((0, 2))
    out = np.full((len(segments), 3, 2), np.nan)
    out[:, :2] = segments
    return out.reshape(-1, 2)


def scene(state):
    """Pure part: the projected edges per axis, the extensions to the vanishing points, the
    class and its explanation.

    Returns
    -------
    dict
        ``matrix`` (4x4), ``corners`` (8, 2) image points, ``edges`` (three polylines, one per
        axis), ``vanishing`` (three 2-vectors or None), ``extensions`` (three polylines, empty
        when the axis has no vanishing point), ``classification`` (the dict of
        :func:`course_lib.projections.classify_projection`) and ``text`` (HTML).

    Examples
    --------
    >>> scene(State(kind="perspective", azimuth_deg=0, elevation_deg=0))["classification"]["name"]
    'one-point perspective'
    >>> scene(State(kind="oblique", oblique_length=1.0))["classification"]["name"]
    'oblique cavalier'
    """
    m = _matrix(state)
    h = np.c_[_CORNERS, np.ones(8)] @ m.T
    corners = h[:, :2] / h[:, 3:]
    # the elevation slider moves in steps of 0.1°: "equal" foreshortening up to a relative 1e-3
    # makes its step 35.3° isometric (the exact angle is 35.264°)
    cls = projections.classify_projection(m, tol=1e-3)
    vps = [None if v is None else v[:2] for v in projections.principal_vanishing_points(m)]
    edges, extensions = [], []
    for axis in range(3):
        pairs = np.array(_EDGES[axis])
        segs = corners[pairs]                              # (4, 2, 2)
        edges.append(_polyline(segs))
        vp = vps[axis]
        if vp is None:
            extensions.append(np.empty((0, 2)))
            continue
        # from the end of each edge nearer the vanishing point on to it
        near = np.where(np.linalg.norm(segs[:, 1] - vp, axis=1)
                        < np.linalg.norm(segs[:, 0] - vp, axis=1), 1, 0)
        start = segs[np.arange(4), near]
        extensions.append(_polyline(np.stack([start, np.broadcast_to(vp, start.shape)], 1)))
    count = sum(v is not None for v in vps)
    shown = sum(v is not None and np.all(np.abs(v) <= LIMIT) for v in vps)
    extra = ""
    if state.kind == "perspective":
        extra = (f" Vanishing points: {count}" + (f" ({count - shown} outside the picture)"
                                                  if shown < count else "") + ".")
    elif cls["family"] == "orthographic":
        f = cls["foreshortening"]
        extra = f" Foreshortening of x, y, z: {f[0]:.3f}, {f[1]:.3f}, {f[2]:.3f}."
    text = (f"<b>{cls['name']}</b>: {cls['reason']}.{extra}<br>Preserves: {cls['preserves']}.")
    return {"matrix": m, "corners": corners, "edges": edges, "vanishing": vps,
            "extensions": extensions, "classification": cls, "text": text}


class ProjectionClassExplorer(Explorer):
    """Projection kind, azimuth, elevation, distance, oblique angle and length: the box, its
    vanishing points and the class of the projection named live.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ProjectionClassExplorer()``.

    Examples
    --------
    >>> explorer = ProjectionClassExplorer()
    >>> explorer.elevation.value = 20.0
    >>> explorer.title.get_text()
    'three-point perspective'
    """

    summary = ("Projection-class explorer (interactive): a box under a perspective, parallel "
               "or oblique projection from any azimuth and elevation, its edges extended to the "
               "vanishing points, and the class (one-/two-/three-point, multiview, isometric, "
               "dimetric, trimetric, cavalier, cabinet) named live.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(3.8, 3.6))
        ax = self.fig.add_axes((0.02, 0.02, 0.96, 0.88))
        ax.set(xlim=(-LIMIT, LIMIT), ylim=(-LIMIT, LIMIT), aspect="equal")
        ax.set_xticks([])
        ax.set_yticks([])
        self.edge_lines, self.extension_lines, self.vp_markers = [], [], []
        for axis, colour in enumerate(_COLOURS):
            (ext,) = ax.plot([], [], color=colour, lw=0.8, ls="--")
            (edge,) = ax.plot([], [], color=colour, lw=2.2, label=f"{'xyz'[axis]} edges")
            (vp,) = ax.plot([], [], "o", color=colour, ms=6, mec="k", mew=0.6)
            self.edge_lines.append(edge)
            self.extension_lines.append(ext)
            self.vp_markers.append(vp)
        self.title = ax.set_title("", fontsize=_style.TITLE)
        _style.legend(ax, loc="lower right", fontsize=_style.LEGEND, handlelength=1.2)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [*self.extension_lines, *self.edge_lines,
                                               *self.vp_markers, self.title])
        self.kind = w.ToggleButtons(options=KINDS, value=self.state.kind,
                                    style={"button_width": _style.button_width(*KINDS)})
        self.azimuth = slider("azimuth °", self.state.azimuth_deg, -180, 180, 1)
        self.elevation = slider("elevation °", self.state.elevation_deg, -90, 90, 0.1)
        self.distance = slider("eye distance", self.state.distance, 2.5, 12, 0.1)
        self.angle = slider("oblique angle φ °", self.state.oblique_angle_deg, 0, 180, 1)
        self.length = slider("depth length k", self.state.oblique_length, 0.1, 1.0, 0.05)
        bind(self.state, {"kind": self.kind, "azimuth_deg": self.azimuth,
                          "elevation_deg": self.elevation, "distance": self.distance,
                          "oblique_angle_deg": self.angle, "oblique_length": self.length},
             self.update)
        self.info = panel(width="620px")
        controls = w.VBox([self.kind, self.azimuth, self.elevation, self.distance, self.angle,
                           self.length])
        self.widget = w.VBox([beside(self.fig.canvas, controls), self.info])
        self._draw(scene(self.state))

    def update(self):
        """Recompute the scene and redraw the moving lines."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        oblique = self.state.kind == "oblique"
        self.azimuth.disabled = self.elevation.disabled = oblique
        self.distance.disabled = self.state.kind != "perspective"
        self.angle.disabled = self.length.disabled = not oblique
        for axis in range(3):
            self.edge_lines[axis].set_data(*s["edges"][axis].T)
            self.extension_lines[axis].set_data(*s["extensions"][axis].T)
            vp = s["vanishing"][axis]
            self.vp_markers[axis].set_data(([], []) if vp is None else ([vp[0]], [vp[1]]))
        self.title.set_text(s["classification"]["name"])
        self.info.value = s["text"]
