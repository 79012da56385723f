r"""3D clipping explorer: a segment and a triangle clipped against a box or a view frustum.

Sliders turn and lift a segment and a triangle through the clip region. Against the box
:math:`[-1, 1]^3` the segment is clipped with Liang-Barsky (and its 6-bit outcodes shown) and the
triangle with Sutherland-Hodgman, plane by plane. Against a perspective view frustum the same
algorithms run with the frustum's six planes, taken from the camera's matrix (in clip space
they are :math:`-w \le x, y, z \le w`: the segment is clipped there, in homogeneous
coordinates, with :func:`course_lib.clip_space.clip_segment_homogeneous`).

A step control walks through the six planes (left, right, bottom, top, near, far) one at a time,
as the 2D visualizers do: the current plane is outlined, the table of Liang-Barsky's
:math:`(p_k, q_k, t_k)` grows a row, :math:`[t_{in}, t_{out}]` shrinks, the entering and leaving
points are marked, and the triangle is shown as clipped by the planes so far.
"""
from dataclasses import dataclass

import numpy as np

from .. import clip_space, clipping, draw, format as fmt, transforms, viewing
from . import _style
from ._base import Explorer, align, beside, bind, degree_sliders, figure_3d, panel, slider
from ._clip2d import step_controls

__all__ = ["ClippingExplorer3D", "REGIONS", "State", "region_face", "region_planes", "scene"]

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
    step: int = 6
    """How many of the six planes are processed (0: none yet, 6: all, the result)."""


def _region_matrix(region):
    return np.eye(4) if region == "box" else _CAMERA


def region_face(region, side):
    """The four corners (world coordinates) of the region's face on plane `side` (0-5, in the
    order of :data:`course_lib.clipping.BIT_NAMES`), as a closed loop of 5 points.

    Examples
    --------
    >>> region_face("box", 0)[:, 0].tolist()          # the left face: x = -1
    [-1.0, -1.0, -1.0, -1.0, -1.0]
    """
    axis, value = side // 2, (-1.0 if side % 2 == 0 else 1.0)
    others = [a for a in range(3) if a != axis]
    square = np.zeros((5, 3))
    square[:, axis] = value
    square[:, others[0]] = [-1, 1, 1, -1, -1]
    square[:, others[1]] = [-1, -1, 1, 1, -1]
    if region == "frustum":
        return transforms.apply(np.linalg.inv(_CAMERA), square)
    return square


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
    """Pure part: the placed segment and triangle, clipped by the first ``state.step`` planes.

    The segment is clipped in homogeneous clip coordinates (for the box, w = 1), so the t of
    each row is the parameter of the world segment.

    Returns
    -------
    dict
        ``segment`` (2x3), ``clipped_segment`` (2x3 or None: the part kept by the planes so
        far), ``rows`` (Liang-Barsky's six rows, :func:`course_lib.clip_space.clip_segment_homogeneous`),
        ``step`` (clamped to 0-6), ``t_in``, ``t_out`` (after the planes so far), ``entering``,
        ``leaving`` (the points where the segment crosses the processed planes, k x 3),
        ``codes`` (the ends' 6-bit outcodes), ``triangle`` (3x3), ``polygon`` (the triangle
        clipped by the planes so far, k x 3), ``counts`` (vertices after each plane),
        ``face`` (the current plane's face outline, 5x3, or None at step 0), ``edges`` (the
        region's 12 edges) and ``text``.

    Examples
    --------
    >>> s = scene(State(lift=5.0))            # lifted far above the box: nothing is left
    >>> s["clipped_segment"] is None, len(s["polygon"])
    (True, 0)
    >>> scene(State(step=0))["t_in"], len(scene(State(step=0))["polygon"])
    (0.0, 3)
    """
    place = (transforms.translate([0.0, 0.0, state.lift])
             @ transforms.rotate_z(np.radians(state.turn_deg))
             @ transforms.rotate_x(np.radians(state.tilt_deg)))
    segment = transforms.apply(place, _SEGMENT)
    triangle = transforms.apply(place, _TRIANGLE)
    planes, edges = region_planes(state.region)
    k = min(max(int(state.step), 0), 6)
    steps = clipping.clip_polygon_steps(triangle, planes)
    counts = [3] + [len(poly) for _, poly in steps]
    polygon = triangle if k == 0 else steps[k - 1][1]
    m = _region_matrix(state.region)
    ends_h = np.column_stack([segment, np.ones(2)]) @ m.T
    result = clip_space.clip_segment_homogeneous(ends_h[0], ends_h[1])
    rows = result["rows"]
    t_in, t_out = (0.0, 1.0) if k == 0 else (rows[k - 1]["t_in"], rows[k - 1]["t_out"])
    a, d = segment[0], segment[1] - segment[0]
    clipped = None if t_in > t_out else np.array([a + t_in * d, a + t_out * d])
    crossed = [r for r in rows[:k] if r["t"] is not None and 0 <= r["t"] <= 1]
    entering = np.array([a + r["t"] * d for r in crossed if r["kind"] == "entering"])
    leaving = np.array([a + r["t"] * d for r in crossed if r["kind"] == "leaving"])
    codes = result["codes"]
    text = _explain(state.region, k, rows, codes, t_in, t_out, clipped, counts, steps)
    return {"segment": segment, "clipped_segment": clipped, "rows": rows, "step": k,
            "t_in": float(t_in), "t_out": float(t_out), "entering": entering.reshape(-1, 3),
            "leaving": leaving.reshape(-1, 3), "codes": codes, "triangle": triangle,
            "polygon": polygon, "counts": counts,
            "face": None if k == 0 else region_face(state.region, k - 1), "edges": edges,
            "text": text}


def _explain(region, k, rows, codes, t_in, t_out, clipped, counts, steps):
    """The explorer's text: outcodes, the (p, q, t) table so far, the interval, the polygon."""
    where = ("the box [-1, 1]³" if region == "box" else
             "the view frustum, in clip space −w ≤ x, y, z ≤ w")
    head = (f"Clipping against {where}. Outcodes p0 = {clipping.describe_outcode(codes[0], 3)}, "
            f"p1 = {clipping.describe_outcode(codes[1], 3)}.")
    cells = []
    for j, r in enumerate(rows):
        if j >= k:
            cells.append(f"<tr style='color:#aaa'><td>{r['side']}</td><td colspan=4>"
                         "not yet</td></tr>")
            continue
        t = "–" if r["t"] is None else fmt.number(r["t"])
        style = " style='font-weight:bold;background:#fff3d6'" if j == k - 1 else ""
        cells.append(f"<tr{style}><td>{r['side']}</td><td>{fmt.number(r['p'])}</td>"
                     f"<td>{fmt.number(r['q'])}</td><td>{t}</td><td>{r['kind']}</td></tr>")
    table = ("<table style='font-size:90%'><tr><th>side</th><th>p</th><th>q</th><th>t = q/p"
             "</th><th></th></tr>" + "".join(cells) + "</table>")
    if k == 0:
        step_text = "Step 0: no plane yet; [t_in, t_out] = [0, 1]"
    else:
        r = rows[k - 1]
        step_text = (f"Plane {k} ({r['side']}): [t_in, t_out] = [{fmt.number(t_in)}, "
                     f"{fmt.number(t_out)}]")
    step_text += ": nothing is left." if clipped is None else "."
    names = [name for name, _ in steps]
    shown = " → ".join(f"<b>{n} ({name})</b>" if j == k - 1 else f"{n} ({name})"
                       for j, (n, name) in enumerate(zip(counts[1:], names)))
    tri = f"Triangle (Sutherland-Hodgman), vertices after each plane: 3 → {shown}."
    return head + "<br>" + table + step_text + "<br>" + tri


class ClippingExplorer3D(Explorer):
    """Turn and lift a segment and a triangle through a box or a frustum; step plane by plane.

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
        (self.face,) = ax.plot([], [], [], color="#e65100", lw=2.5)
        (self.enter_pts,) = ax.plot([], [], [], "o", color="#2e7d32", ms=7, mec="white")
        (self.leave_pts,) = ax.plot([], [], [], "o", color="#c62828", ms=7, mec="white")
        self.triangle = draw.mesh_3d(ax, s["triangle"], [[0, 1, 2]], facecolors=(0.5, 0.5, 0.5,
                                     0.12), edgecolor="0.5", linestyle="--")
        self.polygon = draw.mesh_3d(ax, s["triangle"], [[0, 1, 2]],
                                    facecolors=(0.95, 0.55, 0.1, 0.8), edgecolor="#a04000")
        self.blitter = draw.Blitter(self.fig, [self.edges, self.face, self.triangle,
                                               self.polygon, self.segment, self.kept,
                                               self.enter_pts, self.leave_pts])
        sliders = degree_sliders(None, turn=("turn °", self.state.turn_deg, -180, 180),
                                 tilt=("tilt °", self.state.tilt_deg, -90, 90))
        self.turn, self.tilt = sliders.values()
        self.lift = slider("lift", self.state.lift, -2.5, 2.5, 0.05)
        align([self.turn, self.tilt, self.lift])
        self.region = w.ToggleButtons(options=REGIONS, value=self.state.region,
                                      style={"button_width": _style.button_width(*REGIONS)})
        bind(self.state, {"region": self.region, "turn_deg": self.turn, "tilt_deg": self.tilt,
                          "lift": self.lift}, self.update)
        self.info = panel(width="380px")
        self.step, steps = step_controls(self._on_step, 7)
        self.step.value = self.state.step = min(max(int(self.state.step), 0), 6)
        self.widget = beside(self.fig.canvas, w.VBox([self.region, self.turn, self.tilt,
                                                      self.lift, steps, self.info]))
        self._draw(s)

    def _on_step(self, change):
        self.state.step = change["new"]
        self.update()

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
        face = s["face"]
        self.face.set_data_3d(*(face.T if face is not None else ([], [], [])))
        self.enter_pts.set_data_3d(*s["entering"].T)
        self.leave_pts.set_data_3d(*s["leaving"].T)
        draw.set_mesh_3d(self.triangle, s["triangle"], [[0, 1, 2]])
        polygon = s["polygon"]
        if len(polygon) >= 3:
            draw.set_mesh_3d(self.polygon, polygon, [list(range(len(polygon)))])
        else:
            self.polygon.set_verts([])
        self.info.value = s["text"]
