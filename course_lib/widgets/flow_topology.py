r"""Flow-topology explorer: critical points classified by their Jacobian, separatrices, and a
streamline integrated in the gridded field.

A field is chosen from presets (:data:`course_lib.scivis.topology.FLOW_PRESETS`) and sampled on a
grid; :func:`~course_lib.scivis.topology.critical_points` finds the zeros of its bilinear
interpolant, cell by cell, and marks each by its class (saddle, node, focus, centre). From every
saddle the four separatrices are traced (orange: unstable, leaving; blue: stable, arriving):
the topological skeleton. The two sliders deform the field: for the linear field they are the
trace and determinant of its Jacobian, and the small panel on the right shows where the point
sits in the trace-determinant plane, so moving a slider moves it through the classes (node,
focus, centre, saddle) as it crosses the parabola :math:`\Delta = \tau^2/4` and the axes. Drag
the white seed: its streamline is integrated in the gridded field (Euler, RK2 or RK4).
"""
import functools
from dataclasses import dataclass, field

import numpy as np

from .. import draw, scivis
from .._validate import as_choice
from ..scivis import topology
from . import _style
from ._base import Explorer, align, beside, bind, checkbox, labelled, panel, set_range, slider
from ._drag import DraggablePoints

__all__ = ["CLASS_STYLE", "FlowTopologyExplorer", "State", "scene"]

METHODS = ("euler", "rk2", "rk4")
METHOD_NAMES = {"euler": "Euler", "rk2": "RK2", "rk4": "RK4"}
STYLES = ("arrows", "streamlets")
#: class -> (marker, colour) of its critical points.
CLASS_STYLE = {
    "saddle": ("X", "#d62728"),
    "attracting node": ("o", "#1f77b4"),
    "repelling node": ("o", "#ff7f0e"),
    "attracting focus": ("s", "#2ca02c"),
    "repelling focus": ("s", "#9467bd"),
    "centre": ("*", "#8c564b"),
    "degenerate": ("P", "0.45"),
}
GRID = 33                 # nodes along y
GLYPHS = 13               # glyphs along y
SEPARATRIX_STEPS = 80
SEED_STEPS = 120


@dataclass
class State:
    """The preset field, its two parameters, the integrator, its step, the seed and the view.

    Examples
    --------
    >>> State().preset, State().p, State().q
    ('saddle and two foci', 1.0, 0.5)
    """

    preset: str = "saddle and two foci"
    p: float = 1.0
    q: float = 0.5
    method: str = "rk4"
    step: float = 0.15
    seed: np.ndarray = field(default_factory=lambda: np.array([-0.5, 0.75]))
    style: str = "arrows"
    show_separatrices: bool = True


@functools.lru_cache(maxsize=64)
def _topo_field_parts(preset, p, q):
    """The gridded field, its critical points, separatrices and glyphs (cached per field)."""
    f = topology.preset_field(preset, p, q, n=GRID)
    cps = topology.critical_points(f)
    g = f.values
    sp = np.array(f.spacing)
    speed = float(np.hypot(g[..., 0], g[..., 1]).max())
    h = 0.75 * float(sp.min())                      # an arc length: 3/4 cell per step
    eps = float(sp.min()) / 20
    seeds = {"unstable": [], "stable": []}
    for c in cps:
        if c.kind != "saddle":
            continue
        lam, vec = np.linalg.eig(c.jacobian)
        for name, e in (("unstable", vec[:, np.argmax(lam.real)].real),
                        ("stable", vec[:, np.argmin(lam.real)].real)):
            e = e / np.linalg.norm(e)
            seeds[name] += [c.position + eps * e, c.position - eps * e]
    seps = {}
    for name in ("unstable", "stable"):
        if seeds[name]:
            lines = topology.integrate_gridded(f, np.array(seeds[name]), h, SEPARATRIX_STEPS,
                                               "rk4", backward=name == "stable",
                                               min_speed=1e-9 * speed, normalize=True)
            seps[name] = lines
        else:
            seps[name] = []
    (x0, y0), (x1, y1) = topology.FLOW_PRESETS[preset][3]
    ny = GLYPHS
    nx = int(round(ny * (x1 - x0) / (y1 - y0)))
    cx = x0 + (np.arange(nx) + 0.5) * (x1 - x0) / nx
    cy = y0 + (np.arange(ny) + 0.5) * (y1 - y0) / ny
    pts = np.stack(np.meshgrid(cx, cy), axis=-1).reshape(-1, 2)
    vec = topology.bilinear_velocity(g[..., 0], g[..., 1], pts[:, 0], pts[:, 1], f.spacing,
                                     f.origin)
    cell = (y1 - y0) / ny
    norm = np.hypot(vec[:, 0], vec[:, 1])
    typical = max(float(np.percentile(norm, 80)), 1e-12)     # fast corners saturate
    vec = vec * np.minimum(1.0, typical / np.maximum(norm, 1e-300))[:, None]
    scale = 0.9 * cell / typical
    glyphs = scivis.arrows(pts, vec, scale=scale, head_length=0.35, head_width=0.45,
                           shaft_width=0.12)
    # streamlets: short lines both ways through the glyph centres, length ~ one cell
    hs = 0.1 * cell                                   # streamlets of equal length
    fwd = topology.integrate_gridded(f, pts, hs, 4, "rk2", min_speed=1e-9 * speed,
                                     normalize=True)
    bwd = topology.integrate_gridded(f, pts, hs, 4, "rk2", backward=True,
                                     min_speed=1e-9 * speed, normalize=True)
    streamlets = [np.vstack([b[::-1], a[1:]]) for a, b in zip(fwd, bwd)]
    return f, cps, seps, glyphs, streamlets, h


def _topo_joined(lines):
    """Lines (list of (m, 2)) as one polyline with NaN rows between them."""
    if not lines:
        return np.zeros((0, 2))
    parts = []
    for line in lines:
        parts += [line, np.full((1, 2), np.nan)]
    return np.vstack(parts)


def scene(state):
    r"""Pure part: the field's glyphs, critical points by class, separatrices, the seed's line.

    Returns
    -------
    dict
        ``field`` (the gridded Field), ``points`` (list of CriticalPoint), ``by_class`` (class
        -> (k, 2) positions), ``trace_det`` (class -> (k, 2) (trace, determinant) of its
        points), ``unstable``/``stable`` (polylines, NaN between separatrices), ``glyphs``
        (arrow outlines) and ``streamlets`` (short lines through the glyph centres),
        ``line`` (the seed's streamline),
        ``domain`` and ``text``.

    Examples
    --------
    The linear field with trace -1 and determinant 1.25 has an attracting focus at the origin:

    >>> s = scene(State(preset="linear", p=-1.0, q=1.25, seed=np.array([1.2, 0.6])))
    >>> [c.kind for c in s["points"]], s["by_class"]["attracting focus"].tolist()
    (['attracting focus'], [[0.0, 0.0]])
    >>> s["trace_det"]["attracting focus"].round(6).tolist()
    [[-1.0, 1.25]]
    """
    as_choice(state.preset, "preset", tuple(topology.FLOW_PRESETS))
    as_choice(state.method, "method", METHODS)
    as_choice(state.style, "style", STYLES)
    f, cps, seps, glyphs, streamlets, _ = _topo_field_parts(state.preset, float(state.p),
                                                       float(state.q))
    by_class = {k: np.array([c.position for c in cps if c.kind == k]).reshape(-1, 2)
                for k in CLASS_STYLE}
    trace_det = {k: np.array([[np.trace(c.jacobian), np.linalg.det(c.jacobian)]
                              for c in cps if c.kind == k]).reshape(-1, 2) for k in CLASS_STYLE}
    line = topology.integrate_gridded(f, np.asarray(state.seed, float), state.step, SEED_STEPS,
                                      state.method)
    names = topology.FLOW_PRESETS[state.preset][0]
    rows = []
    for c in cps:
        lam = c.eigenvalues
        ev = (f"{lam[0].real:.3g} ± {abs(lam[0].imag):.3g}i" if abs(lam[0].imag) > 1e-12
              else f"{lam[0].real:.3g}, {lam[1].real:.3g}")
        rows.append(f"({c.position[0]:.2f}, {c.position[1]:.2f}): <b>{c.kind}</b>, "
                    f"λ = {ev}")
    text = (f"<b>{state.preset}</b>, {names[0]} = {state.p:.2f}, {names[1]} = {state.q:.2f}: "
            f"{len(cps)} critical point{'s' if len(cps) != 1 else ''}"
            + ("<br>" + "<br>".join(rows[:8]) if rows else "")
            + (f"<br>… and {len(rows) - 8} more" if len(rows) > 8 else "")
            + f"<br>Seed streamline: {METHOD_NAMES[state.method]}, h = {state.step:.3f}, "
            f"{len(line) - 1} steps in the grid"
            + (" (stopped at the border or a critical point)." if len(line) <= SEED_STEPS
               else "."))
    if state.preset == "linear":
        c = cps[0].reason if cps else ""
        text += f"<br>Why: {c}."
    none = np.zeros((0, 2))
    show = state.show_separatrices
    return {"field": f, "points": cps, "by_class": by_class, "trace_det": trace_det,
            "unstable": _topo_joined(seps["unstable"]) if show else none,
            "stable": _topo_joined(seps["stable"]) if show else none,
            "glyphs": glyphs, "streamlets": streamlets, "line": line,
            "domain": topology.FLOW_PRESETS[state.preset][3], "text": text}


_VIEW_RATIO = 4 / 3                  # the view's width : height, for every preset


class FlowTopologyExplorer(Explorer):
    """Choose a preset field, deform it with two sliders, see its critical points and
    separatrices; drag the seed to integrate one streamline in the gridded field.

    In a notebook, after ``%matplotlib widget``, end a cell with ``FlowTopologyExplorer()``.

    Examples
    --------
    >>> ex = FlowTopologyExplorer(State(preset="linear", p=-1.0, q=1.25))
    >>> ex.q.value = -1.0                      # determinant < 0: the point becomes a saddle
    >>> "saddle" in ex.info.value
    True
    """

    summary = ("Flow topology explorer (interactive): critical points classified by the "
               "eigenvalues of the Jacobian, separatrices from the saddles, and a streamline "
               "integrated in the gridded field.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection, PolyCollection
        from matplotlib.lines import Line2D

        self.state = state or State()
        self.state.seed = np.asarray(self.state.seed, dtype=float).reshape(2)
        self.fig = draw.figure(figsize=(6.4, 3.6))
        grid = self.fig.add_gridspec(1, 2, width_ratios=(2.2, 1.0), left=0.1, right=0.98,
                                     bottom=0.13, top=0.9, wspace=0.3)
        ax = self.fig.add_subplot(grid[0, 0])
        self.ax = ax
        ax.set_aspect("equal")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_title("critical points and separatrices")
        self.glyphs = PolyCollection([], facecolors="0.78", edgecolors="none", zorder=1)
        ax.add_collection(self.glyphs)
        self.streamlets = LineCollection([], colors="0.6", linewidths=0.8, zorder=1)
        ax.add_collection(self.streamlets)
        (self.unstable,) = ax.plot([], [], "-", color="#e6550d", lw=1.6, zorder=3)
        (self.stable,) = ax.plot([], [], "-", color="#3182bd", lw=1.6, zorder=3)
        (self.line,) = ax.plot([], [], ".-", color="k", lw=1.2, ms=3, zorder=4)
        self.markers = {k: ax.plot([], [], m, color=c, ms=8, mec="k", mew=0.6, zorder=5)[0]
                        for k, (m, c) in CLASS_STYLE.items()}
        (self.seed,) = ax.plot([], [], "o", color="white", mec="k", mew=1.4, ms=9, zorder=6)
        handles = [Line2D([], [], ls="none", marker=m, color=c, mec="k", mew=0.6, ms=6,
                          label=k) for k, (m, c) in CLASS_STYLE.items() if k != "degenerate"]
        handles += [Line2D([], [], color="#e6550d", lw=1.6, label="unstable separatrix"),
                    Line2D([], [], color="#3182bd", lw=1.6, label="stable separatrix"),
                    Line2D([], [], color="k", lw=1.4, marker="o", mfc="white", ms=5,
                           label="seed streamline (drag)")]
        self.fig.legend(handles=handles, loc="lower right", fontsize=6.5, ncol=1,
                        bbox_to_anchor=(0.985, 0.02), framealpha=0.95, borderpad=0.3,
                        labelspacing=0.25, handlelength=1.4)
        td = self.fig.add_axes([0.735, 0.55, 0.245, 0.35])
        tau = np.linspace(-3, 3, 121)
        td.plot(tau, tau ** 2 / 4, color="0.4", lw=1)
        td.axhline(0, color="0.4", lw=0.8)
        td.plot([0, 0], [0, 3], color="0.4", lw=0.8)
        td.set(xlim=(-3, 3), ylim=(-2, 3))
        td.set_xlabel("trace τ", labelpad=0)
        td.set_ylabel("det Δ", labelpad=0)
        td.set_title("Δ = τ²/4", fontsize=_style.ANNOTATION)
        td.tick_params(labelsize=6)
        for label, xy in (("saddle", (0, -1.4)), ("focus", (-1.3, 2.3)), ("node", (-2.6, 0.5))):
            td.text(*xy, label, fontsize=6, color="0.3", ha="center" if label == "saddle"
                    else "left")
        self.td = td
        self.td_points = {k: td.plot([], [], m, color=c, ms=6, mec="k", mew=0.5, zorder=5)[0]
                          for k, (m, c) in CLASS_STYLE.items()}
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.glyphs, self.streamlets, self.unstable,
                                               self.stable, self.line, *self.markers.values(),
                                               self.seed, *self.td_points.values()])
        self.drag = DraggablePoints(ax, self.state.seed[None], self._on_drag)
        names, defaults, ranges, _ = topology.FLOW_PRESETS[self.state.preset]
        self.preset = labelled(w.Dropdown, "field", options=tuple(topology.FLOW_PRESETS),
                               value=self.state.preset)
        self.p = slider(names[0], self.state.p, *ranges[0], 0.05, readout_format=".2f")
        self.q = slider(names[1], self.state.q, *ranges[1], 0.05, readout_format=".2f")
        self.method = w.ToggleButtons(options=[(METHOD_NAMES[m], m) for m in METHODS],
                                      value=self.state.method, style={"button_width": "auto"})
        self.step = slider("step h", self.state.step, 0.01, 0.3, 0.01, readout_format=".2f")
        self.style = w.ToggleButtons(options=list(STYLES), value=self.state.style,
                                     style={"button_width": "auto"})
        self.sep_box = checkbox("separatrices", self.state.show_separatrices)
        align([self.preset, self.p, self.q, self.step])
        self.preset.observe(self._on_preset, names="value")
        self._quiet = False
        bind(self.state, {"p": self.p, "q": self.q, "method": self.method, "step": self.step,
                          "style": self.style, "show_separatrices": self.sep_box},
             self._on_control)
        self.info = panel(width="330px")
        controls = w.VBox([self.preset, self.p, self.q, self.method, self.step, self.style,
                           self.sep_box, self.info])
        self.widget = beside(self.fig.canvas, controls, align="flex-start")
        self._limits()
        self._draw(scene(self.state))

    def _limits(self):
        # every preset's view padded to one width : height (4 : 3), so that the equal-aspect
        # axes keep the same box on the canvas whichever field is shown
        (x0, y0), (x1, y1) = topology.FLOW_PRESETS[self.state.preset][3]
        w, h = x1 - x0, y1 - y0
        w, h = max(w, h * _VIEW_RATIO), max(h, w / _VIEW_RATIO)
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        self.ax.set(xlim=(cx - w / 2, cx + w / 2), ylim=(cy - h / 2, cy + h / 2))
        self.blitter.forget_background()

    def _on_preset(self, change):
        # the seed keeps its place on the screen (the axes box does not change between presets)
        self.ax.apply_aspect()
        on_screen = self.ax.transData.transform(np.asarray(self.state.seed, float))
        self.state.preset = change["new"]
        names, defaults, ranges, ((x0, y0), (x1, y1)) = topology.FLOW_PRESETS[self.state.preset]
        self.state.p, self.state.q = defaults
        self._limits()
        self.ax.apply_aspect()
        x, y = self.ax.transData.inverted().transform(on_screen)
        # ... unless that is outside the new field's domain: then the nearest point inside it
        mx, my = 0.02 * (x1 - x0), 0.02 * (y1 - y0)
        self.state.seed = np.array([min(max(x, x0 + mx), x1 - mx),
                                    min(max(y, y0 + my), y1 - my)])
        self.drag.points[0] = self.state.seed
        self._quiet = True                  # the sliders move: one update at the end
        try:
            self.p.description, self.q.description = names
            set_range(self.p, *ranges[0], 0.05, defaults[0])
            set_range(self.q, *ranges[1], 0.05, defaults[1])
        finally:
            self._quiet = False
        self.state.p, self.state.q = self.p.value, self.q.value
        self._limits()
        self.update()

    def _on_control(self):
        if not self._quiet:
            self.update()

    def _on_drag(self, index, xy):
        self.state.seed = np.array(xy, dtype=float)
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists (blitting)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        if self.state.style == "arrows":
            self.glyphs.set_verts(list(s["glyphs"]))
            self.streamlets.set_segments([])
        else:
            self.glyphs.set_verts([])
            self.streamlets.set_segments(s["streamlets"])
        self.unstable.set_data(*s["unstable"].T)
        self.stable.set_data(*s["stable"].T)
        self.line.set_data(*s["line"].T)
        self.seed.set_data([self.state.seed[0]], [self.state.seed[1]])
        for k in CLASS_STYLE:
            self.markers[k].set_data(*s["by_class"][k].T)
            td = np.clip(s["trace_det"][k], [-2.9, -1.9], [2.9, 2.9])
            self.td_points[k].set_data(*td.T)
        self.info.value = s["text"]
