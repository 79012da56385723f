r"""Ambient-occlusion explorer: Monte Carlo estimates on a grid of floor points, their noise,
and how the noise falls like :math:`1/\sqrt{k}` with the number k of rays per point.

Every point of a 24 x 24 grid on the floor sends k rays into the hemisphere above it, drawn with
the cosine-weighted density (:func:`course_lib.shading.cosine_sample_hemisphere`); the estimate
of the ambient occlusion (the open, cosine-weighted fraction of the sky) is the fraction of rays
that escape (:func:`course_lib.shading.ambient_occlusion`). Three scenes: an **open floor**
(nothing blocks: exactly 1), a long **wall** of height 1 along the left edge (exact value known:
:math:`\tfrac12(1 + a/\sqrt{a^2 + h^2})` at distance :math:`a`, see
:func:`course_lib.shading.ambient_occlusion_closed_form`), and a **box by a wall** (no closed
form: contact shadows around the box and in the corner).

Each ray's result is a 0/1 (Bernoulli) variable, so a k-ray estimate has standard error
:math:`\sqrt{AO(1 - AO)/k} \le 1/(2\sqrt{k})`: four times the rays for half the noise. The
256 rays per point of a scene are cast once, seeded, when the scene is first shown (147,456
rays, about half a second); the sample slider then averages the first k of them, as a
progressive renderer does, so moving it is instant and the pictures are reproducible.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, shading
from .._validate import as_choice
from . import _style
from ._base import Explorer, bind, panel, slider

__all__ = ["KINDS", "MAX_SAMPLES", "OcclusionExplorer", "State", "convergence", "exact",
           "floor_points", "occluders", "ray_visibility", "scene"]

KINDS = ("open floor", "wall", "box by a wall")
GRID = 24
EXTENT = (0.0, 3.0, -1.5, 1.5)           # x0, x1, y0, y1 of the floor grid
WALL_HEIGHT = 1.0
WALL_LENGTH = 1000.0                     # long enough to be infinite for the closed form
BOX = ((1.0, 1.7), (-0.35, 0.35), (0.0, 0.7))
MAX_SAMPLES = 256


@dataclass
class State:
    """The scene, the number of rays per point and the random seed.

    Examples
    --------
    >>> State().kind, State().samples
    ('box by a wall', 16)
    """

    kind: str = "box by a wall"
    samples: int = 16
    seed: int = 0


def floor_points():
    """The centres of the GRID x GRID floor cells (z = 0), shape (GRID, GRID, 3), row 0 at
    the smallest y.

    Examples
    --------
    >>> p = floor_points()
    >>> p.shape, p[0, 0].tolist()
    ((24, 24, 3), [0.0625, -1.4375, 0.0])
    """
    x0, x1, y0, y1 = EXTENT
    x = x0 + (np.arange(GRID) + 0.5) / GRID * (x1 - x0)
    y = y0 + (np.arange(GRID) + 0.5) / GRID * (y1 - y0)
    xx, yy = np.meshgrid(x, y)
    return np.stack([xx, yy, np.zeros_like(xx)], axis=-1)


def _box_triangles(lo, hi):
    v = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                  for z in (lo[2], hi[2])])
    quads = [[0, 1, 3, 2], [4, 6, 7, 5], [0, 4, 5, 1], [2, 3, 7, 6], [1, 5, 7, 3]]  # no bottom
    return np.array([v[[q[0], q[1], q[2]]] for q in quads] + [v[[q[0], q[2], q[3]]]
                                                               for q in quads])


def occluders(kind):
    """The occluding triangles of a scene, shape (m, 3, 3) (none for the open floor).

    The wall is the rectangle x = 0, |y| <= 1000, 0 <= z <= 1 (two triangles); the box
    stands on the floor (five faces, ten triangles).

    Examples
    --------
    >>> [len(occluders(kind)) for kind in KINDS]
    [0, 2, 12]
    """
    as_choice(kind, "kind", KINDS)
    if kind == "open floor":
        return np.zeros((0, 3, 3))
    length, h = WALL_LENGTH, WALL_HEIGHT
    wall = np.array([[[0.0, -length, 0.0], [0.0, length, 0.0], [0.0, length, h]],
                     [[0.0, -length, 0.0], [0.0, length, h], [0.0, -length, h]]])
    if kind == "wall":
        return wall
    (x0, x1), (y0, y1), (z0, z1) = BOX
    return np.concatenate([wall, _box_triangles((x0, y0, z0), (x1, y1, z1))])


def _under_box():
    p = floor_points()
    (x0, x1), (y0, y1), _ = BOX
    return (p[..., 0] > x0) & (p[..., 0] < x1) & (p[..., 1] > y0) & (p[..., 1] < y1)


def exact(kind):
    r"""The exact ambient occlusion of the floor points, where a closed form exists.

    Open floor: 1 everywhere. Wall: :math:`\tfrac12\big(1 + a/\sqrt{a^2 + h^2}\big)` at
    distance :math:`a` from a wall of height :math:`h`
    (:func:`course_lib.shading.ambient_occlusion_closed_form`). Box by a wall: None.

    Examples
    --------
    >>> float(exact("open floor").min()), exact("box by a wall")
    (1.0, None)
    >>> round(float(exact("wall")[0, 0]), 4)            # a = 1/16 from a wall of height 1
    0.5312
    """
    if kind == "open floor":
        return np.ones((GRID, GRID))
    if kind == "wall":
        a = floor_points()[..., 0]
        return np.vectorize(lambda d: shading.ambient_occlusion_closed_form(
            "wall", distance=d, height=WALL_HEIGHT))(a)
    if kind in KINDS:
        return None
    raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")


@lru_cache(maxsize=8)
def ray_visibility(kind, seed=0):
    r"""Each of the MAX_SAMPLES rays of each floor point: 1 if it escapes, 0 if blocked.

    One call of :func:`course_lib.shading.ambient_occlusion` with the floor points repeated
    MAX_SAMPLES times and one sample each, so every ray's 0/1 result is kept (the mean of the
    first k is the k-sample estimate). Seeded: the same (kind, seed) gives the same rays. The
    handful of triangles is tested by brute force: for 2 or 12 triangles that is faster than
    walking a bounding-volume hierarchy in Python. Points under the box are NaN. Cached.

    Returns
    -------
    ndarray, shape (MAX_SAMPLES, GRID, GRID)

    Examples
    --------
    >>> rays = ray_visibility("wall")
    >>> rays.shape, sorted(np.unique(rays).tolist())
    ((256, 24, 24), [0.0, 1.0])
    """
    tris = occluders(kind)
    points = np.broadcast_to(floor_points(), (MAX_SAMPLES, GRID, GRID, 3))
    ao = shading.ambient_occlusion(points, [0.0, 0.0, 1.0], tris if len(tris) else None,
                                   samples=1, seed=seed, accelerate=False)
    rays = np.array(ao.visibility, dtype=float)
    if kind == "box by a wall":
        rays[:, _under_box()] = np.nan
    rays.setflags(write=False)
    return rays


@lru_cache(maxsize=8)
def convergence(kind, seed=0):
    r"""The noise of the k-ray estimate for every k = 1 ... MAX_SAMPLES.

    Returns
    -------
    dict
        ``k`` (1 ... MAX_SAMPLES), ``std_error`` (the mean over the floor of the *estimated*
        standard error :math:`\sqrt{\hat p(1 - \hat p)/k}`), ``rms_error`` (the root mean
        square difference from the exact value, or None without a closed form), ``bound``
        (:math:`1/(2\sqrt{k})`).

    Examples
    --------
    >>> c = convergence("open floor")
    >>> float(c["std_error"].max()), float(c["rms_error"].max())
    (0.0, 0.0)
    """
    rays = ray_visibility(kind, seed)
    k = np.arange(1, MAX_SAMPLES + 1)
    estimates = np.cumsum(rays, axis=0) / k[:, None, None]
    valid = ~np.isnan(rays[0])
    p = estimates[:, valid]
    std_error = np.sqrt(p * (1 - p) / k[:, None]).mean(axis=1)
    truth = exact(kind)
    rms = None if truth is None else np.sqrt(((p - truth[valid]) ** 2).mean(axis=1))
    return {"k": k, "std_error": std_error, "rms_error": rms, "bound": 0.5 / np.sqrt(k)}


def scene(state):
    r"""Pure part: the k-ray estimate on the floor, its standard error, the exact value where
    known, and the convergence curves.

    Returns
    -------
    dict
        ``estimate``, ``std_error`` (GRID x GRID; NaN under the box), ``exact`` (or None),
        ``error`` (estimate - exact, or None), ``convergence`` (see :func:`convergence`),
        ``mean_std_error``, ``rms_error`` (or None), ``rays`` (rays cast for this picture),
        ``text``.

    Examples
    --------
    >>> s = scene(State(kind="open floor", samples=5))
    >>> float(np.nanmin(s["estimate"])), float(np.nanmax(s["std_error"]))
    (1.0, 0.0)
    >>> s = scene(State(kind="wall", samples=64))
    >>> bool(s["rms_error"] < 2 / np.sqrt(64))
    True
    """
    as_choice(state.kind, "kind", KINDS)
    k = int(state.samples)
    if not 1 <= k <= MAX_SAMPLES:
        raise ValueError(f"samples must be in 1 ... {MAX_SAMPLES}, got {state.samples!r}")
    rays = ray_visibility(state.kind, int(state.seed))
    estimate = rays[:k].mean(axis=0)
    std_error = np.sqrt(estimate * (1 - estimate) / k)
    truth = exact(state.kind)
    error = None if truth is None else estimate - truth
    conv = convergence(state.kind, int(state.seed))
    mean_se = float(conv["std_error"][k - 1])
    rms = None if conv["rms_error"] is None else float(conv["rms_error"][k - 1])
    n_points = int((~np.isnan(rays[0])).sum())
    text = (f"<b>k = {k}</b> ray{'s' if k > 1 else ''} per point ({k * n_points:,} rays for "
            f"this picture). Mean estimated standard error {mean_se:.3f} "
            f"(at most 1/(2√k) = {0.5 / np.sqrt(k):.3f}).")
    if rms is not None:
        text += (f" Measured against the exact value: RMS error {rms:.3f}"
                 + (" — the open floor is exact for any k: no ray is ever blocked, "
                    "so there is no variance." if state.kind == "open floor" else "."))
    if k == 1:
        text += (" With one ray every estimate is 0 or 1 and the <i>estimated</i> error "
                 "√(p̂(1−p̂)/k) is 0: the error estimate needs a few rays itself.")
    text += (" Four times the rays halve the noise (slope −1/2 on the log-log plot). All "
             f"{MAX_SAMPLES} rays per point were cast once, seeded, when the scene was first "
             "shown (about half a second); the slider averages the first k.")
    return {"estimate": estimate, "std_error": std_error, "exact": truth, "error": error,
            "convergence": conv, "mean_std_error": mean_se, "rms_error": rms,
            "rays": k * n_points, "text": text}


class OcclusionExplorer(Explorer):
    """Sample slider, scene and seed; the AO estimate on the floor, its error, and the
    convergence plot.

    In a notebook, after ``%matplotlib widget``, end a cell with ``OcclusionExplorer()``.

    Examples
    --------
    >>> explorer = OcclusionExplorer()
    >>> explorer.samples.value = 64
    >>> list(explorer.marker.get_xdata())
    [64, 64]
    """

    summary = ("Ambient-occlusion explorer (interactive): Monte Carlo ambient occlusion on a "
               "floor next to a wall and a box; the noise falls like 1/sqrt(k) with the "
               "number k of rays per point.")

    def __init__(self, state=None):
        import ipywidgets as w
        import matplotlib
        from matplotlib.patches import Rectangle

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(8.4, 3.3))
        extent = EXTENT
        ax_ao = self.fig.add_axes((0.075, 0.15, 0.215, 0.7))
        ax_err = self.fig.add_axes((0.43, 0.15, 0.215, 0.7))
        ax_conv = self.fig.add_axes((0.8, 0.15, 0.185, 0.7))
        grey = matplotlib.colormaps["gray"].with_extremes(bad="#c9a66b")
        magma = matplotlib.colormaps["magma"].with_extremes(bad="#c9a66b")
        self.ao_image = ax_ao.imshow(s["estimate"], origin="lower", extent=extent, cmap=grey,
                                     vmin=0, vmax=1, interpolation="nearest")
        self.err_image = ax_err.imshow(np.abs(s["std_error"]), origin="lower", extent=extent,
                                       cmap=magma, vmin=0, vmax=0.5, interpolation="nearest")
        for image, left in ((self.ao_image, 0.297), (self.err_image, 0.652)):
            self.fig.colorbar(image, cax=self.fig.add_axes((left, 0.15, 0.012, 0.7)))
        self.outlines = []
        for ax in (ax_ao, ax_err):
            ax.set(xlabel="x", ylabel="y", xlim=(-0.12, 3.0), ylim=(-1.5, 1.5))
            wall = ax.axvspan(-0.12, 0.0, color="#8d6e63")
            (x0, x1), (y0, y1), _ = BOX
            box = Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, ec="#c62828", lw=1.2)
            ax.add_patch(box)
            self.outlines.append((wall, box))
        self.ao_title = ax_ao.set_title("")
        self.err_title = ax_err.set_title("")
        ax_conv.set(xscale="log", yscale="log", xlim=(1, MAX_SAMPLES), ylim=(2e-3, 0.7),
                    xlabel="rays per point k")
        ax_conv.set_title("noise vs k (log-log)")
        k = s["convergence"]["k"]
        ax_conv.plot(k, s["convergence"]["bound"], "--", color="0.5", lw=1,
                     label="bound 1/(2√k)")
        (self.se_line,) = ax_conv.plot([], [], color="C0", lw=1.5, label="mean estimated SE")
        (self.rms_line,) = ax_conv.plot([], [], color="C3", lw=1.5, label="RMS error vs exact")
        self.marker = ax_conv.axvline(k[0], color="0.2", lw=0.8)
        _style.legend(ax_conv, loc="lower left", handlelength=1.2, borderpad=0.3,
                      labelspacing=0.2, borderaxespad=0.3)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.ao_image, self.err_image, self.ao_title,
                                               self.err_title, self.se_line, self.rms_line,
                                               self.marker,
                                               *[a for pair in self.outlines for a in pair]])
        self.samples = slider("rays per point k", self.state.samples, 1, MAX_SAMPLES, 1,
                              kind=w.IntSlider, body=300)
        self.kind = w.ToggleButtons(options=KINDS, value=self.state.kind,
                                    style={"button_width": _style.button_width(*KINDS)})
        self.seed = slider("seed", self.state.seed, 0, 9, 1, kind=w.IntSlider, body=170,
                           continuous_update=False)
        bind(self.state, {"samples": self.samples, "kind": self.kind, "seed": self.seed},
             self.update)
        self.info = panel(width="760px")
        self.widget = w.VBox([self.fig.canvas, w.HBox([self.samples, self.seed],
                                                      layout=w.Layout(flex_flow="row wrap")),
                              self.kind,
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute the scene (the rays are cached per scene and seed) and update the
        pictures."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        k = self.state.samples
        self.ao_image.set_data(s["estimate"])
        if s["error"] is not None:
            self.err_image.set_data(np.abs(s["error"]))
            self.err_title.set_text("|estimate − exact|")
        else:
            self.err_image.set_data(s["std_error"])
            self.err_title.set_text("estimated standard error")
        self.ao_title.set_text(f"AO estimate, k = {k}")
        conv = s["convergence"]
        self.se_line.set_data(conv["k"][1:], conv["std_error"][1:])   # k = 1: estimated SE 0
        if conv["rms_error"] is not None and self.state.kind != "open floor":
            self.rms_line.set_data(conv["k"], np.maximum(conv["rms_error"], 1e-9))
        else:
            self.rms_line.set_data([], [])
        self.marker.set_xdata([k, k])
        for wall, box in self.outlines:
            wall.set_visible(self.state.kind != "open floor")
            box.set_visible(self.state.kind == "box by a wall")
        self.info.value = s["text"]
