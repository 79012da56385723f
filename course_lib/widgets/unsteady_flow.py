r"""Unsteady-flow explorer: the streamline, pathline, streakline and timeline from one release
point, drawn together as time runs.

Dye is released continuously from the release point (black star) from :math:`t_0 = 0` on; a
tagged particle leaves it at :math:`t_0`; a short row of particles (bubbles) through it is
released at :math:`t_0` too. At the time :math:`t` of the slider the picture shows

* the **streamline** through the release point of the field frozen at :math:`t` (blue),
* the **pathline** of the tagged particle, :math:`t_0 \to t` (red; the red dot is the
  particle now),
* the **streakline**: where all the dye released since :math:`t_0` is now (green dots),
* the **timeline**: the row of particles now (purple; dotted: where it started),

over grey arrows of the field at :math:`t` (:mod:`course_lib.scivis.unsteady`). In the
rotating uniform flow the streamline is straight while the pathline and the streakline are
circular arcs bent opposite ways; in the steady vortex the first three lie on one circle.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw
from .._validate import as_choice
from ..scivis import hedgehog
from ..scivis import unsteady as U
from . import _style
from ._base import Explorer, align, beside, bind, labelled, panel, slider

__all__ = ["PRESETS", "State", "UnsteadyFlowExplorer", "scene"]

#: name -> (field parameters, (x range), (y range), duration T)
PRESETS = {
    "rotating": ({"phase": np.pi}, (-3.0, 3.0), (-3.0, 3.0), 2 * np.pi),
    "double gyre": ({}, (0.0, 2.0), (0.0, 1.0), 15.0),
    "oscillating vortex": ({"amplitude": 0.8, "omega": 1.0}, (-2.0, 2.0), (-2.0, 2.0),
                           2 * np.pi),
    "steady vortex": ({}, (-2.0, 2.0), (-2.0, 2.0), 2 * np.pi),
}
GLYPHS = 13
STEPS = 80                      # RK4 steps of every particle (and the streamline)
COLOURS = {"streamline": "#1f77b4", "pathline": "#d62728", "streakline": "#2ca02c",
           "timeline": "#9467bd"}


@dataclass
class State:
    """The field, the time as a fraction of the preset's duration, and the release point as
    fractions of the domain's width and height.

    Examples
    --------
    >>> State().preset, State().time
    ('rotating', 0.4)
    """

    preset: str = "rotating"
    time: float = 0.4
    release_x: float = 0.7
    release_y: float = 0.75


def _field(preset):
    params = PRESETS[preset][0]
    return U.unsteady_field(preset, **params)


def _clip(line, xr, yr):
    """The line cut at its first point outside the box (NaN after it)."""
    line = np.array(line, dtype=float)
    out = ~((line[:, 0] >= xr[0]) & (line[:, 0] <= xr[1]) & (line[:, 1] >= yr[0])
            & (line[:, 1] <= yr[1]))
    return line, out


def _clip_both(line, centre, xr, yr):
    line, out = _clip(line, xr, yr)
    after = np.cumsum(out[centre:]) > 0
    before = np.cumsum(out[:centre + 1][::-1])[::-1] > 0
    line[centre:][after] = np.nan
    line[:centre + 1][before] = np.nan
    return line


def _distance_to_polyline(points, line):
    """The largest distance of `points` from the polyline `line` (its segments)."""
    a, b = line[:-1], line[1:]
    ab = b - a
    length2 = np.maximum((ab * ab).sum(axis=1), 1e-300)
    rel = points[:, None, :] - a[None]
    u = np.clip((rel * ab[None]).sum(axis=2) / length2, 0.0, 1.0)
    nearest = a[None] + u[..., None] * ab[None]
    return float(np.hypot(*(points[:, None, :] - nearest).transpose(2, 0, 1)).min(axis=1).max())


def scene(state):
    """Pure part: the four lines, the particle, the field's arrows at time t, and the text.

    Examples
    --------
    >>> s = scene(State(preset="steady vortex", time=0.25))
    >>> float(np.abs(np.hypot(*s["streakline"].T) - s["radius"]).max()) < 1e-6
    True
    """
    preset = as_choice(state.preset, "preset", tuple(PRESETS))
    params, xr, yr, duration = PRESETS[preset]
    field = _field(preset)
    t = float(np.clip(state.time, 0.0, 1.0)) * duration
    fx, fy = float(np.clip(state.release_x, 0, 1)), float(np.clip(state.release_y, 0, 1))
    r = np.array([xr[0] + fx * (xr[1] - xr[0]), yr[0] + fy * (yr[1] - yr[0])])
    size = max(xr[1] - xr[0], yr[1] - yr[0])
    half = 0.15 * (yr[1] - yr[0])
    row0 = np.column_stack([np.full(15, r[0]), np.linspace(r[1] - half, r[1] + half, 15)])
    # One batch of particles, all advanced together by RK4 (STEPS steps each):
    # 0, 1: the streamline through r forwards and backwards, in the field frozen at t with
    #       unit speed (their "time" is the arc length s; the field is read at t);
    # 2: the tagged particle, recorded: its pathline;
    # 3 .. 52: the dye released at the times tau: the streakline;
    # 53 ..: the row of bubbles released at t0: the timeline.
    reach = 1.7 * size
    taus = np.linspace(0.0, t, 50)
    starts = np.concatenate([[0.0, 0.0, 0.0], taus, np.zeros(15)])
    ends = np.concatenate([[reach, -reach], np.full(66, t)])
    particles = np.concatenate([np.tile(r, (53, 1)), row0])

    def batch(points, times):
        times = times.copy()
        times[:2] = t                                      # the streamline: frozen at t
        v = field(points, times)
        v[:2] /= np.maximum(np.hypot(v[:2, 0], v[:2, 1]), 1e-12)[:, None]    # unit speed
        return v
    moved = U.advect(batch, particles, starts, ends, n_steps=STEPS, record=True)
    stream = _clip_both(np.concatenate([moved[1, :0:-1], moved[0]]), STEPS, xr, yr)
    path, streak, row = moved[2], moved[3:53, -1], moved[53:, -1]
    gx, gy = np.meshgrid(np.linspace(*xr, GLYPHS), np.linspace(*yr, GLYPHS))
    grid = np.column_stack([gx.ravel(), gy.ravel()])
    vectors = field(grid, t)
    top = max(float(np.hypot(*vectors.T).max()), 1e-12)
    glyphs = hedgehog(grid, vectors, scale=0.6 * size / GLYPHS / top)
    # how far the dye is from the tagged particle's path: 0 in a steady flow
    gap = _distance_to_polyline(streak, path)
    text = (f"<b>{preset}</b>, t = {t:.2f} (of {duration:.2f}); release point "
            f"({r[0]:.2f}, {r[1]:.2f}), released since t<sub>0</sub> = 0.<br>"
            f"<span style='color:{COLOURS['streamline']}'>streamline</span>: tangent to the "
            f"field frozen at t; <span style='color:{COLOURS['pathline']}'>pathline</span>: "
            f"the particle released at t<sub>0</sub>, now at ({path[-1, 0]:.2f}, "
            f"{path[-1, 1]:.2f}); <span style='color:{COLOURS['streakline']}'>streakline"
            f"</span>: all the dye released since t<sub>0</sub>; "
            f"<span style='color:{COLOURS['timeline']}'>timeline</span>: the row released at "
            f"t<sub>0</sub>.<br>Largest distance of the streakline from the pathline: "
            f"<b>{gap:.3f}</b>" + (" (steady field: they coincide)" if gap < 1e-3 else "")
            + ".")
    return {"streamline": stream, "pathline": path, "streakline": streak, "timeline": row,
            "timeline_start": row0, "particle": path[-1], "release": r, "glyphs": glyphs,
            "xlim": xr, "ylim": yr, "t": t, "gap": gap, "radius": float(np.hypot(*r)),
            "text": text}


class UnsteadyFlowExplorer(Explorer):
    """Field preset, time and release point: streamline, pathline, streakline and timeline.

    In a notebook, after ``%matplotlib widget``, end a cell with ``UnsteadyFlowExplorer()``.

    Examples
    --------
    >>> explorer = UnsteadyFlowExplorer()
    >>> explorer.time.value = 0.9
    >>> "t = 5.65" in explorer.info.value
    True
    """

    summary = ("Unsteady-flow explorer (interactive): the streamline, pathline, streakline and "
               "timeline from one release point in a time-dependent field, as time runs.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(4.8, 4.8))
        ax = self.fig.add_axes((0.11, 0.25, 0.86, 0.68))
        ax.set(xlabel="x", ylabel="y", aspect="equal")
        self.ax = ax
        self.glyphs = LineCollection([], colors="0.75", linewidths=0.9, zorder=1)
        ax.add_collection(self.glyphs)
        (self.stream,) = ax.plot([], [], color=COLOURS["streamline"], lw=1.8, zorder=3,
                                 label="streamline at t")
        (self.path,) = ax.plot([], [], color=COLOURS["pathline"], lw=1.8, zorder=4,
                               label="pathline since t₀")
        (self.streak,) = ax.plot([], [], "o-", color=COLOURS["streakline"], ms=2.5, lw=0.8,
                                 zorder=5, label="streakline (dye)")
        (self.row0,) = ax.plot([], [], ":", color=COLOURS["timeline"], lw=1.2, zorder=2)
        (self.row,) = ax.plot([], [], ".-", color=COLOURS["timeline"], lw=1.4, ms=4, zorder=4,
                              label="timeline")
        (self.particle,) = ax.plot([], [], "o", color=COLOURS["pathline"], mec="k", ms=7,
                                   zorder=6)
        (self.release,) = ax.plot([], [], "*", color="k", ms=12, zorder=7,
                                  label="release point")
        self.title = ax.set_title("")
        self.fig.legend(loc="lower center", ncol=3, fontsize=_style.LEGEND, frameon=False,
                        handlelength=1.6, columnspacing=1.2, labelspacing=0.3)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.glyphs, self.stream, self.path, self.streak,
                                               self.row0, self.row, self.particle,
                                               self.release, self.title])
        self.preset = labelled(w.Dropdown, "field", options=tuple(PRESETS),
                               value=self.state.preset)
        self.time = slider("time t / T", self.state.time, 0, 1, 0.01)
        self.release_x = slider("release x", self.state.release_x, 0.05, 0.95, 0.01)
        self.release_y = slider("release y", self.state.release_y, 0.05, 0.95, 0.01)
        align([self.preset, self.time, self.release_x, self.release_y])
        bind(self.state, {"preset": self.preset, "time": self.time,
                          "release_x": self.release_x, "release_y": self.release_y},
             self.update)
        self.info = panel(width="360px")
        self.widget = beside(self.fig.canvas, w.VBox([self.preset, self.time, self.release_x,
                                                      self.release_y, self.info]),
                             align="flex-start")
        self._limits = None
        self._draw(s)

    def update(self):
        """Recompute the lines and redraw them (blitting; a new preset redraws the axes)."""
        s = scene(self.state)
        if self._draw(s):
            self.blitter.forget_background()
        self.blitter.update()

    def _draw(self, s):
        """Move the artists; True if the axes' limits changed (the background must go)."""
        limits = (tuple(s["xlim"]), tuple(s["ylim"]))
        changed = limits != self._limits
        if changed:
            self.ax.set(xlim=limits[0], ylim=limits[1])
            self._limits = limits
        self.glyphs.set_segments(list(s["glyphs"]))
        self.stream.set_data(*s["streamline"].T)
        self.path.set_data(*s["pathline"].T)
        self.streak.set_data(*s["streakline"].T)
        self.row0.set_data(*s["timeline_start"].T)
        self.row.set_data(*s["timeline"].T)
        self.particle.set_data([s["particle"][0]], [s["particle"][1]])
        self.release.set_data([s["release"][0]], [s["release"][1]])
        self.title.set_text(f"{self.state.preset}, t = {s['t']:.2f}")
        self.info.value = s["text"]
        return changed
