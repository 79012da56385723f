r"""Streamline explorer: seed points, integrator (Euler, RK2, RK4) and step size, with the error.

A streamline solves :math:`\mathrm{d}x/\mathrm{d}t = v(x)` from a seed point
(:func:`course_lib.scivis.streamline`). The fields offered here are **linear**,
:math:`v(x) = A x`, so the exact streamline is known in closed form,
:math:`x(t) = e^{tA} x_0` (:func:`exact_streamline`), and the error of each integrator can be
shown, not guessed: the dashed black curve is the exact path, the coloured polylines the
numerical ones, one dot per step. On the vortex, Euler's dots spiral outwards (every step goes
along the tangent, off the circle: the radius grows by :math:`\sqrt{1 + h^2}`), RK2 drifts
far less and RK4 stays on the circle for any reasonable step. The small panel on the right plots
the end-point error against the step on log-log axes: straight lines of slope 1, 2 and 4, the
**orders** of the three methods; the dot is the current setting. Drag the seeds with the mouse.
"""
from dataclasses import dataclass, field

import numpy as np

from .. import draw, scivis
from .._validate import as_choice
from . import _style
from ._base import Explorer, align, beside, bind, checkbox, labelled, panel, slider
from ._drag import DraggablePoints

__all__ = ["FIELDS", "METHODS", "State", "StreamlineExplorer", "convergence", "exact_streamline",
           "field_matrix", "scene"]

FIELDS = ("vortex", "spiral", "saddle", "sink")
METHODS = ("euler", "rk2", "rk4")
METHOD_NAMES = {"euler": "Euler", "rk2": "RK2 (midpoint)", "rk4": "RK4"}
METHOD_COLORS = {"euler": "#d62728", "rk2": "#ff7f0e", "rk4": "#1f77b4"}
MAX_SEEDS = 4
LIMIT = 2.0                                   # the domain [-2, 2]^2
BOUNDS = ((-LIMIT, -LIMIT), (LIMIT, LIMIT))
STEPS = 0.04 * 2.0 ** np.arange(5)            # step sizes of the convergence panel: 0.04-0.64
GLYPHS = 13                                   # arrow glyphs per side


def field_matrix(kind):
    """The matrix A of the linear field :math:`v(x) = A x` of
    :func:`course_lib.scivis.example_vector_field`, read off from v(e1) and v(e2).

    Examples
    --------
    >>> field_matrix("vortex")
    array([[ 0., -1.],
           [ 1.,  0.]])
    """
    as_choice(kind, "kind", FIELDS)
    v = scivis.example_vector_field(kind)
    return v(np.eye(2)).T                    # columns: the images of the basis vectors


def _linear_velocity(kind):
    """v(x) = A x evaluated directly: the same field as ``example_vector_field(kind)`` without
    its input checks, which cost more than the arithmetic when called at every RK stage."""
    a_t = field_matrix(kind).T

    def velocity(points):
        return points @ a_t
    return velocity


def exact_streamline(kind, seeds, times):
    r"""The exact streamlines :math:`x(t) = e^{tA} x_0` of a linear field at the given times.

    The matrix exponential comes from the eigendecomposition :math:`A = V \Lambda V^{-1}`:
    :math:`e^{tA} = V e^{t\Lambda} V^{-1}` (all the fields here have two independent
    eigenvectors; complex eigenvalues, as for the vortex, give a real result).

    Parameters
    ----------
    kind : str
        One of :data:`FIELDS`.
    seeds : array_like, shape (k, 2)
    times : array_like, shape (m,)

    Returns
    -------
    ndarray, shape (k, m, 2)

    Examples
    --------
    A quarter turn of the vortex takes (1, 0) to (0, 1):

    >>> np.round(exact_streamline("vortex", [[1.0, 0.0]], [0.0, np.pi / 2]), 12) + 0.0
    array([[[1., 0.],
            [0., 1.]]])
    """
    a = field_matrix(kind)
    lam, vec = np.linalg.eig(a)
    inv = np.linalg.inv(vec)
    t = np.asarray(times, dtype=float)
    # e^{tA} for every t: (m, 2, 2)
    expm = np.einsum("ij,mj,jk->mik", vec, np.exp(np.outer(t, lam)), inv).real
    p = np.asarray(seeds, dtype=float).reshape(-1, 2)
    return np.einsum("mik,sk->smi", expm, p)


def _errors(kind, seeds, line, step):
    """|x_n - x(t_n)| along numerical lines (k, n+1, 2); NaN after a line stopped."""
    exact = exact_streamline(kind, seeds, step * np.arange(line.shape[1]))
    return np.linalg.norm(line - exact, axis=-1)


def _end_error(kind, seeds, line, step):
    """The error at the last point each line reached (the global error), and that point's n."""
    err = _errors(kind, seeds, line, step)
    last = np.array([np.flatnonzero(np.isfinite(e)).max() for e in err])
    return err[np.arange(len(err)), last], last


def convergence(kind, seed, duration, steps=STEPS):
    """End-point error against step size for the three integrators, from one seed.

    Each method integrates from `seed` over the time span `duration` (the step is adjusted
    down to divide it exactly) without a domain box, and the distance to the exact end point
    :math:`e^{TA} x_0` is recorded.

    Returns
    -------
    dict
        ``steps`` (the steps used, (s,)) and, per method name, the errors (s,).

    Examples
    --------
    Halving the step roughly halves Euler's error (order 1) and divides RK4's by 16:

    >>> c = convergence("vortex", [1.0, 0.0], 2.0, steps=[0.1, 0.05])
    >>> float(c["euler"][0] / c["euler"][1]).__round__(1), float(c["rk4"][0] / c["rk4"][1]) > 15
    (2.0, True)
    """
    seed = np.asarray(seed, dtype=float)
    v = _linear_velocity(kind)
    counts = np.maximum(1, np.ceil(duration / np.asarray(steps, float) - 1e-9).astype(int))
    used = duration / counts
    end = exact_streamline(kind, seed[None], [duration])[0, 0]
    out = {"steps": used}
    for method in METHODS:
        errors = []
        for h, n in zip(used, counts):
            line = scivis.streamline(v, seed, h, int(n), method=method)
            errors.append(np.linalg.norm(line[-1] - end))
        out[method] = np.array(errors)
    return out


@dataclass
class State:
    """The field, the integrator, the step h, the time span T, and the seed points.

    Examples
    --------
    >>> State().method, State().step, State().seeds.shape
    ('euler', 0.2, (3, 2))
    """

    kind: str = "vortex"
    method: str = "euler"
    step: float = 0.2
    duration: float = 2 * np.pi
    seeds: np.ndarray = field(default_factory=lambda: np.array([[0.5, 0.0], [1.0, 0.0],
                                                                [0.0, -1.5]]))
    show_exact: bool = True


def scene(state):
    r"""Pure part: numerical and exact streamlines, the errors, and the glyphs.

    Returns
    -------
    dict
        ``lines`` ((k, n+1, 2) numerical, NaN after a line stopped at the domain's edge),
        ``step`` (the step used: the set step adjusted so that n steps take exactly T),
        ``exact`` ((k, m, 2) exact paths, sampled densely over the same time), ``errors``
        ((k,) the distance between each line's last point and the exact position at that
        time), ``n_steps``, ``glyphs`` (arrow outlines (g, 7, 2) of the field, length scaled
        so the longest is one glyph cell) and ``text``.

    Examples
    --------
    One Euler step of h = 0.5 from (1, 0) on the vortex goes to (1, 0.5), off the circle:

    >>> s = scene(State(step=0.5, duration=0.5, seeds=np.array([[1.0, 0.0]])))
    >>> s["lines"][0].tolist()
    [[1.0, 0.0], [1.0, 0.5]]
    >>> float(s["errors"][0]).__round__(4)                 # |(1, 0.5) - (cos .5, sin .5)|
    0.1241
    """
    as_choice(state.method, "method", METHODS)
    seeds = np.asarray(state.seeds, dtype=float).reshape(-1, 2)
    n = max(1, int(round(state.duration / state.step)))
    h = state.duration / n                      # the step, adjusted so that n steps reach T
    v = _linear_velocity(state.kind)
    lines = scivis.streamline(v, seeds, h, n, method=state.method, bounds=BOUNDS)
    lines = lines.reshape(len(seeds), n + 1, 2)
    errors, last = _end_error(state.kind, seeds, lines, h)
    exact = exact_streamline(state.kind, seeds, np.linspace(0.0, state.duration, 240))
    exact = np.where((np.abs(exact) <= LIMIT).all(axis=-1, keepdims=True), exact, np.nan)
    axis = np.linspace(-LIMIT, LIMIT, GLYPHS + 2)[1:-1]
    points = np.stack(np.meshgrid(axis, axis), axis=-1).reshape(-1, 2)
    vectors = v(points)
    cell = axis[1] - axis[0]
    scale = 0.85 * cell / np.linalg.norm(vectors, axis=1).max()
    glyphs = scivis.arrows(points, vectors, scale=scale, head_length=0.35, head_width=0.45,
                           shaft_width=0.12)
    name = METHOD_NAMES[state.method]
    steps = f"{n} step{'s' if n > 1 else ''}"
    text = (f"<b>{name}</b>, step h = {h:.3f}, {steps} up to T = {n * h:.2f}: "
            + ", ".join(f"seed {k + 1}: error {e:.2g}" for k, e in enumerate(errors))
            + " (distance from the exact position at the line's last time).")
    if state.kind == "vortex" and state.method == "euler":
        r0 = np.linalg.norm(seeds[0])
        r_n = np.linalg.norm(lines[0, last[0]])
        text += (f" On the vortex every Euler step multiplies the radius by √(1 + h²) = "
                 f"{np.sqrt(1 + h * h):.4f}: seed 1 went from r = {r0:.3f} to {r_n:.3f} in "
                 f"{last[0]} steps (predicted {r0 * (1 + h * h) ** (last[0] / 2):.3f}).")
    ends = lines[np.arange(len(seeds)), last]
    still = np.linalg.norm(v(ends), axis=1) < 1e-10       # a critical point: v = 0
    resting = [k + 1 for k in range(len(seeds)) if last[k] < n and still[k]]
    stopped = [k + 1 for k in range(len(seeds)) if last[k] < n and not still[k]]
    if resting:
        text += (f" Line(s) {', '.join(map(str, resting))} start(s) at a critical point, "
                 "where v = 0: the flow stands still and there is no line to trace.")
    if stopped:
        text += (f" Line(s) {', '.join(map(str, stopped))} left the domain "
                 f"[−{LIMIT:g}, {LIMIT:g}]² and stopped there.")
    return {"lines": lines, "exact": exact, "errors": errors, "n_steps": n, "step": h,
            "last": last,
            "glyphs": glyphs, "text": text}


class StreamlineExplorer(Explorer):
    """Pick the field and integrator, set the step and time span, drag the seed points.

    In a notebook, after ``%matplotlib widget``, end a cell with ``StreamlineExplorer()``.

    Examples
    --------
    >>> explorer = StreamlineExplorer()
    >>> explorer.method.value = "rk4"
    >>> "RK4" in explorer.info.value
    True
    >>> explorer.drag.press(1.0, 0.0); explorer.drag.move(1.2, 0.0); explorer.drag.release()
    >>> explorer.state.seeds[1].tolist()
    [1.2, 0.0]
    """

    summary = ("Streamline explorer (interactive): Euler, RK2 and RK4 streamlines from "
               "draggable seeds against the exact path, with the error and its order.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import PolyCollection
        from matplotlib.ticker import LogLocator

        self.state = state or State()
        self.state.seeds = np.asarray(self.state.seeds, dtype=float).reshape(-1, 2)
        k = len(self.state.seeds)
        if not 1 <= k <= MAX_SEEDS:
            raise ValueError(f"seeds must hold 1 to {MAX_SEEDS} points, got {k}")
        self.fig = draw.figure(figsize=(6.6, 4.0))
        grid = self.fig.add_gridspec(2, 2, width_ratios=(2.3, 1.5), height_ratios=(1.6, 1),
                                     left=0.095, right=0.985, bottom=0.11, top=0.93, wspace=0.38,
                                     hspace=0.32)
        ax = self.fig.add_subplot(grid[:, 0])
        draw.setup_axes_2d(ax, (-LIMIT, LIMIT), title="streamlines: numerical vs exact",
                           grid=False)
        ticks = np.arange(-LIMIT, LIMIT + 0.5, 1.0)
        ax.set(xticks=ticks, yticks=ticks)
        self.ax = ax
        self.glyphs = PolyCollection([], facecolors="0.78", edgecolors="none", zorder=0)
        ax.add_collection(self.glyphs)
        self.exact = [ax.plot([], [], "--", color="0.1", lw=1.1, zorder=2,
                              label="exact" if j == 0 else None)[0] for j in range(k)]
        self.lines = [ax.plot([], [], ".-", lw=1.6, ms=4, zorder=3)[0] for j in range(k)]
        ax.plot([], [], ".-", color="0.45", lw=1.6, ms=4, label="numerical: a dot per step")
        self.ends = [ax.plot([], [], "x", ms=8, mew=2, zorder=4)[0] for j in range(k)]
        (self.seeds,) = ax.plot([], [], "o", color="white", mec="0.1", mew=1.5, ms=10,
                                zorder=5, label="seeds (drag)")
        _style.legend(ax, loc="lower left", framealpha=0.9, handlelength=1.5, borderpad=0.3,
                      labelspacing=0.2, borderaxespad=0.3)
        err_ax = self.fig.add_subplot(grid[0, 1])
        err_ax.set(xscale="log", yscale="log", xlim=(0.03, 1.3), ylim=(1e-9, 1e2))
        err_ax.set_xlabel("step h", labelpad=1)
        err_ax.set_ylabel("end-point error")
        err_ax.set_title("error vs step (seed 1)")
        err_ax.yaxis.set_major_locator(LogLocator(numticks=4))
        err_ax.grid(True, which="major", lw=0.4, color="0.85")
        self.curves = {m: err_ax.plot([], [], "o-", ms=3, lw=1.2, color=METHOD_COLORS[m],
                                      label=METHOD_NAMES[m])[0] for m in METHODS}
        (self.current,) = err_ax.plot([], [], "o", ms=9, mfc="none", mec="k", mew=1.5)
        _style.legend(err_ax, loc="lower right", handlelength=1.2, borderpad=0.2,
                      labelspacing=0.1, borderaxespad=0.2, markerscale=0.8)
        self.err_ax = err_ax
        note = self.fig.add_subplot(grid[1, 1])
        note.set_axis_off()
        note.text(-0.12, 1.0, "slope of the line = order:\nEuler 1, RK2 2, RK4 4.\nHalving h "
                  "divides the\nerror by 2, 4 or 16.\n(The ringed dot: the\n"
                  "current h and T.)", fontsize=_style.ANNOTATION, va="top", color="0.2")
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [*self.exact, *self.lines, *self.ends, self.seeds,
                                               *self.curves.values(), self.current])
        self.drag = DraggablePoints(ax, self.state.seeds, self._on_drag,
                                    on_release=self._on_release)
        self.kind = labelled(w.Dropdown, "field", options=FIELDS, value=self.state.kind)
        names = [METHOD_NAMES[m] for m in METHODS]
        self.method = w.ToggleButtons(options=list(zip(names, METHODS)), value=self.state.method,
                                      style={"button_width": "auto"})        # fits each name
        self.step = labelled(w.FloatLogSlider, "step h", value=self.state.step, base=10,
                             min=np.log10(0.04), max=0.0, step=0.02, readout_format=".3f")
        self.duration = slider("time T", self.state.duration, 0.5, 2 * np.pi, 0.05,
                               readout_format=".2f", continuous_update=False)
        align([self.kind, self.step, self.duration])
        self.exact_box = checkbox("exact path", self.state.show_exact)
        self.kind.observe(self._on_kind, names="value")
        self.duration.observe(self._on_duration, names="value")
        bind(self.state, {"method": self.method, "step": self.step,
                          "show_exact": self.exact_box}, self.update)
        self.info = panel(width="340px")
        controls = w.VBox([self.kind, self.method, self.step, self.duration, self.exact_box,
                           self.info])
        self.widget = beside(self.fig.canvas, controls, align="flex-start")
        self._static()
        self._convergence()
        self._draw(scene(self.state))

    # --- parts recomputed only now and then ---------------------------------------------------
    def _static(self):
        """The glyphs of the field (change only with the field)."""
        self.glyphs.set_verts(list(scene(State(kind=self.state.kind, step=0.5, duration=0.5,
                                               seeds=self.state.seeds[:1]))["glyphs"]))
        self.blitter.forget_background()

    def _convergence(self):
        """The error-vs-step curves for seed 1 (not while a seed is being dragged)."""
        c = convergence(self.state.kind, self.state.seeds[0], self.state.duration)
        self._errors = c
        for m in METHODS:
            positive = np.maximum(c[m], 1e-16)            # an exact 0 has no logarithm
            self.curves[m].set_data(c["steps"], positive)

    # --- events -------------------------------------------------------------------------------
    def _on_drag(self, index, xy):
        self.state.seeds = self.drag.points.copy()
        self.update()

    def _on_release(self):
        self._convergence()
        self.update()

    def _on_kind(self, change):
        self.state.kind = change["new"]
        self._static()
        self._convergence()
        self.update()

    def _on_duration(self, change):
        self.state.duration = change["new"]
        self._convergence()
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists (blitting)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        for j in range(len(self.lines)):
            line = s["lines"][j]
            self.lines[j].set_data(*line.T)
            self.lines[j].set_color(METHOD_COLORS[self.state.method])
            self.ends[j].set_color(METHOD_COLORS[self.state.method])
            end = line[s["last"][j]]
            self.ends[j].set_data([end[0]], [end[1]])
            exact = s["exact"][j] if self.state.show_exact else np.zeros((0, 2))
            self.exact[j].set_data(*exact.T)
        self.seeds.set_data(*self.state.seeds.T)
        for m in METHODS:
            self.curves[m].set_alpha(1.0 if m == self.state.method else 0.35)
        # the current setting on the error panel (seed 1 reaching T inside the domain)
        if s["last"][0] == s["n_steps"]:
            self.current.set_data([s["step"]], [max(float(s["errors"][0]), 1e-16)])
        else:
            self.current.set_data([], [])
        self.info.value = s["text"]
