r"""Continuity explorer: two cubic Bézier segments joined at P3 = Q0, with curvature combs.

Drag any of the eight control points. Pick a continuity (C0, G1, C1, G2, C2): the points of the
second segment that the continuity fixes follow the first segment (drawn in orange) — Q0 for
C0, also Q1 for G1/C1 (G1 leaves Q1's distance free, C1 does not), also Q2 for G2/C2 (G2 lets
Q2 slide along a line parallel to the tangent). The curvature combs show the curvature along
both segments: at a G1 or C1 join the comb jumps, at a G2 or C2 join it closes up. The text
gives the measured continuity of the join (:func:`course_lib.curves.join_continuity`).
"""
from dataclasses import dataclass, field

import numpy as np

from .. import curves, draw, format as fmt
from . import _style
from ._base import Explorer, beside, bind, checkbox, panel, slider
from ._drag import DraggablePoints

__all__ = ["ContinuityExplorer", "MODES", "State", "scene"]

MODES = ("free", "C0", "G1", "C1", "G2", "C2")
LIMITS = (-1.0, 6.5)
SAMPLES = 80
TEETH = 30
FIXED = {"free": 0, "C0": 1, "G1": 2, "C1": 2, "G2": 3, "C2": 3}    # Q0..Q_{k-1} constrained


def _default_p():
    return np.array([[0.3, 1.0], [1.0, 3.6], [2.4, 4.0], [3.2, 3.0]])


def _default_q():
    return np.array([[3.2, 3.0], [3.68, 2.4], [4.8, 1.4], [6.0, 1.2]])


@dataclass
class State:
    """The two control polygons, the continuity imposed and the comb.

    Examples
    --------
    >>> State().continuity, State().P.shape, State().Q.shape
    ('G1', (4, 2), (4, 2))
    """

    P: np.ndarray = field(default_factory=_default_p)
    Q: np.ndarray = field(default_factory=_default_q)
    continuity: str = "G1"
    show_comb: bool = True
    comb_scale: float = 1.0


def _comb_lines(base, tips):
    """Teeth as one polyline with NaN breaks, and the tips' outline."""
    gap = np.full((len(base), 1, 2), np.nan)
    teeth = np.concatenate([base[:, None], tips[:, None], gap], axis=1).reshape(-1, 2)
    return teeth, tips


def scene(state):
    """Pure part: the constrained second segment, both curves, the combs and the text.

    Returns
    -------
    dict
        ``P``, ``Q`` (Q after the continuity is imposed), ``fixed`` (how many of Q's first
        points the continuity determines), ``curve_p``, ``curve_q`` (SAMPLES x 2),
        ``teeth_p``, ``teeth_q``, ``tips_p``, ``tips_q`` (the combs), ``join``
        (:class:`course_lib.curves.JoinContinuity`) and ``text``.

    Examples
    --------
    >>> s = scene(State(continuity="C1"))
    >>> s["fixed"], s["join"].C, s["join"].G
    (2, 1, 1)
    """
    p = np.asarray(state.P, dtype=float)
    q = np.asarray(state.Q, dtype=float)
    mode = state.continuity
    if mode != "free":
        q = curves.constrain_join(p, q, mode)
    t = np.linspace(0.0, 1.0, SAMPLES)
    s = {"P": p, "Q": q, "fixed": FIXED[mode],
         "curve_p": curves.bezier(p, t), "curve_q": curves.bezier(q, t)}
    tt = np.linspace(0.0, 1.0, TEETH)
    for name, pts in (("p", p), ("q", q)):
        base, tips = curves.curvature_comb(pts, tt, scale=state.comb_scale)
        s[f"teeth_{name}"], s[f"tips_{name}"] = _comb_lines(base, tips)
    join = curves.join_continuity(p, q, tol=1e-6)
    s["join"] = join
    s["text"] = _continuity_text(mode, join)
    return s


def _continuity_text(mode, join):
    if join.C < 0:
        measured = "the segments do not meet (no C0)"
    else:
        measured = f"C{join.C} and G{join.G}"
    ka, kb = join.curvatures
    angle = ("undefined (a zero tangent)" if np.isnan(join.tangent_angle)
             else f"{fmt.number(np.degrees(join.tangent_angle), 1)}°")
    rules = {
        "free": "nothing imposed: every point of Q moves freely.",
        "C0": "C0 fixes Q0 = P3 (3 points of Q free).",
        "G1": "G1 also puts Q1 on the ray from P3 away from P2; its distance (β1) stays free: "
              "drag Q1 along the ray.",
        "C1": "C1 fixes Q1 = P3 + (P3 − P2): P2 mirrored through the join (nothing free in "
              "Q0, Q1).",
        "G2": "G2 also puts Q2 on a line parallel to the tangent (free: β1 and β2, the slide "
              "along that line).",
        "C2": "C2 fixes Q2 = 2Q1 − Q0 + (P3 − 2P2 + P1) too: only Q3 stays free.",
    }
    return (f"<b>Imposed: {mode}</b> — {rules[mode]}<br>"
            f"<b>Measured at the join: {measured}.</b> Angle between the end tangents: "
            f"{angle}; curvature κ = {fmt.number(ka, 3)} (end of P) and {fmt.number(kb, 3)} "
            f"(start of Q)" + (" — the comb jumps." if abs(ka - kb) > 1e-6 * max(1, ka, kb)
                               else " — the comb closes up."))


class ContinuityExplorer(Explorer):
    """Two cubic Bézier segments, a continuity toggle and curvature combs.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ContinuityExplorer()``.

    Examples
    --------
    >>> explorer = ContinuityExplorer()
    >>> explorer.mode.value = "C1"
    >>> np.round(explorer.state.Q[1], 9).tolist()   # P2 mirrored through P3
    [4.0, 2.0]
    """

    summary = ("Continuity explorer (interactive): two cubic Bézier segments; impose C0, G1, C1, "
               "G2 or C2 at the join and watch the constrained control points follow and the "
               "curvature comb jump or close up.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(4.8, 4.8))
        ax = self.fig.add_subplot()
        self.fig.subplots_adjust(left=0.1, right=0.98, bottom=0.08, top=0.94)
        draw.setup_axes_2d(ax, LIMITS, title="Two Bézier segments and their join")
        self.ax = ax
        (self.comb_p,) = ax.plot([], [], color="#90caf9", lw=0.8, zorder=1)
        (self.comb_q,) = ax.plot([], [], color="#a5d6a7", lw=0.8, zorder=1)
        (self.tips_p,) = ax.plot([], [], color="#1e88e5", lw=1, zorder=2, label="curvature comb")
        (self.tips_q,) = ax.plot([], [], color="#43a047", lw=1, zorder=2)
        (self.poly_p,) = ax.plot([], [], "--", color="0.5", lw=1, zorder=3,
                                 label="control polygons")
        (self.poly_q,) = ax.plot([], [], "--", color="0.5", lw=1, zorder=3)
        (self.curve_p,) = ax.plot([], [], color="C0", lw=2.5, zorder=4, label="segment P")
        (self.curve_q,) = ax.plot([], [], color="C2", lw=2.5, zorder=4, label="segment Q")
        (self.points,) = ax.plot([], [], "o", color="0.2", ms=8, mec="white", zorder=6)
        (self.fixed,) = ax.plot([], [], "o", color="#fb8c00", ms=10, mec="0.2", zorder=7,
                                label="fixed by the continuity")
        _style.legend(ax, loc="upper right", fontsize=_style.ANNOTATION, handlelength=1.5,
                      borderpad=0.3, labelspacing=0.25)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.comb_p, self.comb_q, self.tips_p, self.tips_q,
                                               self.poly_p, self.poly_q, self.curve_p,
                                               self.curve_q, self.points, self.fixed])
        self.drag = DraggablePoints(ax, np.vstack([self.state.P, self.state.Q]), self._on_drag,
                                    on_release=self.update)
        self.mode = w.ToggleButtons(options=MODES, value=self.state.continuity,
                                    description="impose",
                                    style={"button_width": _style.button_width(*MODES)})
        self.comb_box = checkbox("curvature comb", self.state.show_comb)
        self.scale = slider("comb scale", self.state.comb_scale, 0.1, 3.0, 0.1)
        bind(self.state, {"continuity": self.mode, "show_comb": self.comb_box,
                          "comb_scale": self.scale}, self.update)
        self.info = panel(width="340px")
        controls = w.VBox([self.mode, self.comb_box, self.scale, self.info])
        self.widget = beside(self.fig.canvas, controls)
        self.update()

    def _on_drag(self, index, xy):
        pts = self.drag.points
        self.state.P = pts[:4].copy()
        self.state.Q = pts[4:].copy()
        self.update()

    def update(self):
        """Impose the continuity, recompute the scene and move the drawn artists."""
        s = scene(self.state)
        self.state.Q = s["Q"].copy()
        self.drag.points[4:] = s["Q"]                   # the constrained points follow
        self._draw(s)
        self.blitter.update()

    def _draw(self, s):
        p, q = s["P"], s["Q"]
        self.poly_p.set_data(*p.T)
        self.poly_q.set_data(*q.T)
        self.curve_p.set_data(*s["curve_p"].T)
        self.curve_q.set_data(*s["curve_q"].T)
        self.points.set_data(*np.vstack([p, q]).T)
        fixed = q[:s["fixed"]]
        self.fixed.set_data(fixed[:, 0], fixed[:, 1])
        for line, key in ((self.comb_p, "teeth_p"), (self.comb_q, "teeth_q"),
                          (self.tips_p, "tips_p"), (self.tips_q, "tips_q")):
            if self.state.show_comb:
                line.set_data(*s[key].T)
            else:
                line.set_data([], [])
        self.info.value = s["text"]
