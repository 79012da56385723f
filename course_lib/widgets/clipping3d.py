r"""3D clipping explorer: a segment and a triangle clipped against a box or a view frustum.

Sliders turn and lift a segment and a triangle through the clip region. Against the box
:math:`[-1, 1]^3` the segment is clipped with Liang-Barsky (and its 6-bit outcodes shown) and the
triangle with Sutherland-Hodgman, plane by plane. Against a perspective view frustum the same
algorithms run with the frustum's six planes, taken from the camera's matrix (in clip space
they are :math:`-w \le x, y, z \le w`).
"""
from dataclasses import dataclass

import numpy as np

from .. import clipping, draw, format as fmt, transforms, viewing
from . import _style
from ._base import Explorer, align, beside, bind, degree_sliders, figure_3d, panel, slider

__all__ = ["ClippingExplorer3D", "REGIONS", "State", "region_planes", "scene"]

REGIONS = ("box", "frustum")
BOX_MIN, BOX_MAX = np.array([-1.0, -1.0, -1.0]), np.array([1.0, 1.0, 1.0])
_SEGMENT = np.array([[-2.2, -0.6, -0.4], [2.0, 0.9, 0.8]])
_TRIANGLE = np.array([[-1.8, -0.3, -0.6], [1.9, -1.2, -0.2], [0.3, 1.6, 1.5]])
_CAMERA = (viewing.perspective(np.radians(40), 1.0, 2.5, 5.5)
           @ viewing.look_at([0.0, -4.0, 0.6], [0.0, 1.0, -0.15], [0.0, 0.0, 1.0]))
_CUBE = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
_EDGES = np.array([(0, 1), (2, 3), (4, 5), (6, 7), (0, 2), (1, 3), (4, 6), (5, 7), (0, 4),
                   (1, 5), (2, 6), (3, 7)])


@dataclass
class State:
    """The clip region and how the segment and triangle are placed (degrees, units).

    Examples
    --------
    >>> State().region
    'box'
    """

    region: str = "box"
    turn_deg: float = 20.0
    tilt_deg: float = 0.0
    lift: float = 0.0


def region_planes(region):
    """The clip region's half-spaces ``(name, normal, offset)`` and its 12 edges.

    Examples
    --------
    >>> planes, edges = region_planes("frustum")
    >>> len(planes), edges.shape
    (6, (12, 2, 3))
    """
    if region == "box":
        return clipping.box_planes(BOX_MIN, BOX_MAX), _CUBE[_EDGES]
    if region == "frustum":
        corners = transforms.apply(np.linalg.inv(_CAMERA), _CUBE)
        return clipping.view_volume_planes(_CAMERA), corners[_EDGES]
    raise ValueError(f"region must be one of {REGIONS}, got {region!r}")


def scene(state):
    """Pure part: the placed segment and triangle, their clipped parts, and the explanation.

    Returns
    -------
    dict
        ``segment`` (2x3), ``clipped_segment`` (2x3 or None), ``triangle`` (3x3),
        ``polygon`` (the clipped triangle, k x 3), ``counts`` (vertices after each plane),
        ``edges`` (the region's 12 edges) and ``text``.

    Examples
    --------
    >>> s = scene(State(lift=5.0))            # lifted far above the box: nothing is left
    >>> s["clipped_segment"] is None, len(s["polygon"])
    (True, 0)
    """
    place = (transforms.translate([0.0, 0.0, state.lift])
             @ transforms.rotate_z(np.radians(state.turn_deg))
             @ transforms.rotate_x(np.radians(state.tilt_deg)))
    segment = transforms.apply(place, _SEGMENT)
    triangle = transforms.apply(place, _TRIANGLE)
    planes, edges = region_planes(state.region)
    steps = clipping.clip_polygon_steps(triangle, planes)
    counts = [3] + [len(poly) for _, poly in steps]
    polygon = steps[-1][1]
    if state.region == "box":
        clipped, lb = clipping.liang_barsky_steps(segment[0], segment[1], BOX_MIN, BOX_MAX)
        codes = [clipping.describe_outcode(clipping.outcode(p, BOX_MIN, BOX_MAX), dim=3)
                 for p in segment]
        last = lb[-1]
        seg_text = (f"Segment: outcodes p0 = {codes[0]}, p1 = {codes[1]}. Liang-Barsky ends "
                    f"with [t_in, t_out] = [{fmt.number(last['t_in'])}, "
                    f"{fmt.number(last['t_out'])}]")
    else:
        clipped = clipping.clip_segment(segment[0], segment[1], planes)
        seg_text = ("Segment: clipped against the six frustum planes (Cyrus-Beck, Liang-Barsky's "
                    "method for any convex region)")
    seg_text += ": nothing is left." if clipped is None else "."
    names = [name for name, _ in steps]
    tri_text = ("Triangle (Sutherland-Hodgman), vertices after each plane: 3 → "
                + " → ".join(f"{n} ({name})" for n, name in zip(counts[1:], names)) + ".")
    return {"segment": segment, "clipped_segment": None if clipped is None else np.array(clipped),
            "triangle": triangle, "polygon": polygon, "counts": counts, "edges": edges,
            "text": seg_text + "<br>" + tri_text}


class ClippingExplorer3D(Explorer):
    """Turn and lift a segment and a triangle through a box or a frustum.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ClippingExplorer3D()``.

    Examples
    --------
    >>> explorer = ClippingExplorer3D()
    >>> explorer.region.value = "frustum"
    >>> "frustum" in explorer.info.value
    True
    """

    summary = ("3D clipping explorer (interactive): a segment and a triangle turned and lifted "
               "through a box or a view frustum, clipped by Liang-Barsky and Sutherland-Hodgman.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig, ax = figure_3d(2.2, "clipping in 3D", size=4.6)
        (self.edges,) = ax.plot([], [], [], color="#2e7d32", lw=1.2)
        (self.segment,) = ax.plot([], [], [], color="0.5", ls="--", lw=1.2)
        (self.kept,) = ax.plot([], [], [], color="C0", lw=3.5)
        self.triangle = draw.mesh_3d(ax, s["triangle"], [[0, 1, 2]], facecolors=(0.5, 0.5, 0.5,
                                     0.12), edgecolor="0.5", linestyle="--")
        self.polygon = draw.mesh_3d(ax, s["triangle"], [[0, 1, 2]],
                                    facecolors=(0.95, 0.55, 0.1, 0.8), edgecolor="#a04000")
        self.blitter = draw.Blitter(self.fig, [self.edges, self.triangle, self.polygon,
                                               self.segment, self.kept])
        sliders = degree_sliders(None, turn=("turn °", self.state.turn_deg, -180, 180),
                                 tilt=("tilt °", self.state.tilt_deg, -90, 90))
        self.turn, self.tilt = sliders.values()
        self.lift = slider("lift", self.state.lift, -2.5, 2.5, 0.05)
        align([self.turn, self.tilt, self.lift])
        self.region = w.ToggleButtons(options=REGIONS, value=self.state.region,
                                      style={"button_width": _style.button_width(*REGIONS)})
        bind(self.state, {"region": self.region, "turn_deg": self.turn, "tilt_deg": self.tilt,
                          "lift": self.lift}, self.update)
        self.info = panel(width="340px")
        self.widget = beside(self.fig.canvas, w.VBox([self.region, self.turn, self.tilt,
                                                      self.lift, self.info]))
        self._draw(s)

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        gaps = np.full((12, 1, 3), np.nan)
        self.edges.set_data_3d(*np.concatenate([s["edges"], gaps], axis=1).reshape(-1, 3).T)
        self.segment.set_data_3d(*s["segment"].T)
        kept = s["clipped_segment"]
        self.kept.set_data_3d(*(kept.T if kept is not None else ([], [], [])))
        draw.set_mesh_3d(self.triangle, s["triangle"], [[0, 1, 2]])
        polygon = s["polygon"]
        if len(polygon) >= 3:
            draw.set_mesh_3d(self.polygon, polygon, [list(range(len(polygon)))])
        else:
            self.polygon.set_verts([])
        self.info.value = s["text"]
