r"""Distributed ray tracing explorer: soft shadows, glossy reflection, depth of field and motion
blur on Whitted's spheres, refined progressively, with a panel of what a pixel integrates over.

The scene is :func:`course_lib.raytracing.example_scene` ("spheres") with its point light
widened into a disk (radius ``light radius``), glossy reflections (Phong exponent ``gloss``), a
thin-lens camera (``aperture`` radius, ``focal distance``) and the red sphere moving to the
right during the exposure (``shutter``). The picture is rendered by
:func:`course_lib.raytracing.progressive`: after a change the explorer shows the first sample
per pixel at once (a noisy image, tens of milliseconds at :data:`SIZE` pixels), then, while the
controls rest, adds one more sample per pixel every :data:`STEP_SECONDS` until the chosen
number is reached. Without a running event loop (a script, a test) the remaining samples wait
for :meth:`DistributedExplorer.settle`. Coming back to the values of the last finished picture
shows it again at once. The picture is shown on a matplotlib canvas one pixel for one, so its
frames take the explorers' own path to the page and, while the explorer rests, the first
samples of the next slider steps are drawn ahead (:mod:`course_lib._prefetch`).

The panel on the right shows the samples of the centre pixel in the domain chosen with the
buttons: the pixel's area, the light's disk, the reflection lobe (seen along its axis), the
lens aperture, or the shutter interval.
"""
import asyncio
import time
from dataclasses import dataclass, replace

import numpy as np

from .. import raytracing as rt
from .._validate import as_choice
from . import _style
from ._base import Explorer, align, beside, bind, panel, slider
from .raytracer import _on_screen, _png

__all__ = ["DOMAINS", "DistributedExplorer", "SIZE", "State", "domain_samples", "scene"]

SIZE = (80, 60)             # width, height of the rendered image
SCALE = 3                   # screen pixels per image pixel
INSET = SIZE[1] * SCALE     # the sampling panel is INSET x INSET pixels
STEP_SECONDS = 0.05         # pause between two refinement steps
DOMAINS = ("pixel", "light", "reflection", "lens", "time")
VELOCITY = np.array([1.2, 0.0, 0.0])     # the red sphere's motion per unit of time
MAX_APERTURE = 0.4
MAX_LIGHT = 1.5


@dataclass
class State:
    """The sample count, the four effects' parameters and the domain shown in the panel.

    Examples
    --------
    >>> State().samples, State().domain
    (8, 'light')
    """

    samples: int = 8
    light_radius: float = 0.6
    gloss: float = 60.0
    aperture: float = 0.08
    focal_distance: float = 6.0
    shutter: float = 0.5
    domain: str = "light"


def _options(state):
    return dict(light_radius=float(state.light_radius), gloss=float(state.gloss),
                aperture=float(state.aperture), focal_distance=float(state.focal_distance),
                shutter=float(state.shutter), motion={1: VELOCITY}, max_depth=2)


def domain_samples(state):
    """The samples of one pixel in the chosen domain, in the panel's coordinates.

    Returns ``(points, kind)``: ``points`` (samples, 2) in [-1, 1]^2 (``"pixel"``: the pixel
    square; ``"light"``, ``"lens"``: the disk at its radius relative to the slider's largest;
    ``"reflection"``: the lobe directions projected along the mirror direction, the unit disk
    being the whole hemisphere; ``"time"``: x is the time in the shutter [0, 1] mapped to
    [-1, 1], y spread for visibility).

    Examples
    --------
    >>> p, kind = domain_samples(State(domain="pixel", samples=4))
    >>> p.shape, kind, bool(np.all(np.abs(p) <= 1))
    ((4, 2), 'pixel', True)
    """
    kind = as_choice(state.domain, "domain", DOMAINS)
    n = int(state.samples)
    uv = rt.stratified(n, seed=0)
    if kind == "pixel":
        return 2 * uv - 1, kind
    if kind == "light":
        return rt.sample_disk(uv, state.light_radius / MAX_LIGHT), kind
    if kind == "lens":
        return rt.sample_disk(uv, state.aperture / MAX_APERTURE), kind
    if kind == "reflection":
        d = rt.sample_lobe([0.0, 0.0, 1.0], state.gloss, uv)
        return d[:, :2], kind
    t = (np.arange(n) + uv[:, 0]) / n * state.shutter
    return np.column_stack([2 * t - 1, uv[:, 1] - 0.5]), kind


def _paint_panel(points, kind, state):
    """The sampling panel as an opaque RGB image (INSET x INSET), row 0 at the top."""
    size = INSET
    img = np.ones((size, size, 3))
    c = (size - 1) / 2
    r_px = 0.42 * size
    yy, xx = np.mgrid[0:size, 0:size]
    rr = np.hypot(xx - c, yy - c)
    grey = np.array([0.75, 0.75, 0.75])
    if kind == "pixel":
        k = max(1, int(round(np.sqrt(int(state.samples)))))
        for i in range(k + 1):
            g = int(round(c - r_px + 2 * r_px * i / k))
            img[int(c - r_px):int(c + r_px) + 1, g] = grey
            img[g, int(c - r_px):int(c + r_px) + 1] = grey
    elif kind == "time":
        y = int(c)
        img[y - 1:y + 2, int(c - r_px):int(c + r_px) + 1] = grey
        end = int(round(c - r_px + 2 * r_px * state.shutter))
        img[y - 6:y + 7, end - 1:end + 1] = [0.9, 0.3, 0.3]
    else:
        img[np.abs(rr - r_px) < 1.0] = grey                   # the whole domain
        if kind in ("light", "lens"):
            scale = (state.light_radius / MAX_LIGHT if kind == "light"
                     else state.aperture / MAX_APERTURE)
            img[np.abs(rr - r_px * scale) < 1.0] = [0.95, 0.75, 0.2]
    colour = {"pixel": (0.1, 0.3, 0.8), "light": (0.85, 0.55, 0.0),
              "reflection": (0.1, 0.55, 0.3), "lens": (0.45, 0.2, 0.7),
              "time": (0.8, 0.15, 0.1)}[kind]
    px = np.round(c + points[:, 0] * r_px).astype(int)
    py = np.round(c - points[:, 1] * r_px * (0.3 if kind == "time" else 1.0)).astype(int)
    for dx in (-2, -1, 0, 1, 2):
        for dy in (-2, -1, 0, 1, 2):
            if dx * dx + dy * dy <= 5:
                img[np.clip(py + dy, 0, size - 1), np.clip(px + dx, 0, size - 1)] = colour
    return img


_WHAT = {
    "pixel": "positions inside the pixel: antialiasing (edges become partial coverage)",
    "light": "points on the disk light: soft shadows (the penumbra is where only part of the "
             "disk is hidden)",
    "reflection": "directions of the Phong lobe around the mirror direction: glossy reflection "
                  "(seen along the lobe's axis; the circle is the whole hemisphere)",
    "lens": "points on the lens aperture: depth of field (sharp only at the focal distance)",
    "time": "instants while the shutter is open: motion blur of the red sphere",
}


def _camera():
    base = rt.example_scene("spheres", *SIZE)
    return base, base.camera


def scene(state, samples=None):
    """Pure part: the rendered image after `samples` samples per pixel (default: all of
    ``state.samples``), the sampling panel and the text.

    Returns a dict: ``image`` (height, width, 3) in [0, 1], row 0 at the bottom (the same as
    the last image of :func:`course_lib.raytracing.progressive` with one sample per step, seed
    0); ``panel`` (INSET, INSET, 3), row 0 at the top; ``points`` and ``kind`` of
    :func:`domain_samples`; ``samples``; ``text``.

    Examples
    --------
    >>> s = scene(State(samples=2))
    >>> s["image"].shape, s["panel"].shape, s["samples"]
    ((60, 80, 3), (180, 180, 3), 2)
    """
    n = int(state.samples) if samples is None else int(samples)
    if n < 1:
        raise ValueError(f"samples must be at least 1, got {n}")
    base, camera = _camera()
    image = None
    for image in rt.progressive(base, camera, batch=1, batches=n, seed=0, **_options(state)):
        pass
    points, kind = domain_samples(state)
    text = _text(state, n)
    return {"image": image, "panel": _paint_panel(points, kind, state), "points": points,
            "kind": kind, "samples": n, "text": text}


def _text(state, n):
    effects = []
    if state.light_radius > 0:
        effects.append(f"disk light of radius {state.light_radius:g}")
    effects.append("perfect mirrors" if np.isinf(state.gloss) else f"gloss n = {state.gloss:g}")
    if state.aperture > 0:
        effects.append(f"lens radius {state.aperture:g} focused at {state.focal_distance:g}")
    if state.shutter > 0:
        effects.append(f"shutter {state.shutter:g} (the red sphere moves "
                       f"{np.linalg.norm(VELOCITY) * state.shutter:.2g} to the right)")
    return (f"<b>{n} of {int(state.samples)} samples per pixel</b> ({SIZE[0]}×{SIZE[1]}); "
            + ", ".join(effects) + ". Noise falls like 1/√N. "
            f"<br>Panel: the {int(state.samples)} samples of a pixel over the "
            f"{_WHAT[state.domain]}.")


def _begin(state):
    """The progressive render of `state` (one sample per pixel per step) and its panel."""
    base, camera = _camera()
    frames = rt.progressive(base, camera, batch=1, batches=int(state.samples), seed=0,
                            **_options(state))
    points, kind = domain_samples(state)
    return frames, _paint_panel(points, kind, state)


def _compose(image, panel_rgb):
    """The picture shown, row 0 at the bottom (as :func:`._on_screen` wants it): the render
    enlarged beside the panel."""
    top = np.flipud(image)
    big = np.repeat(np.repeat(top, SCALE, axis=0), SCALE, axis=1)
    gap = np.ones((big.shape[0], 8, 3))
    return np.flipud(np.concatenate([big, gap, panel_rgb], axis=1))


class DistributedExplorer(Explorer):
    """Samples per pixel, light size, gloss, aperture, focal distance and shutter: the picture
    refines progressively; the panel shows what one pixel integrates over.

    Examples
    --------
    >>> explorer = DistributedExplorer()
    >>> explorer.aperture.value = 0.2          # a student's slider move
    >>> explorer.done, explorer.pending
    (1, True)
    >>> explorer.settle()
    >>> explorer.done, explorer.pending
    (8, False)
    >>> explorer.aperture.value = 0.1          # back to a finished picture's values? no
    >>> explorer.done
    1
    >>> explorer.aperture.value = 0.2; explorer.done         # yes: shown again at once
    8
    """

    summary = ("Distributed ray tracing explorer (interactive): samples per pixel, disk light "
               "radius (soft shadows), gloss exponent, lens aperture and focal distance (depth "
               "of field), shutter (motion blur); the image refines sample by sample and a "
               "panel shows the samples of one pixel in the chosen domain.")

    refines = True                  # one sample per pixel, then more

    def __init__(self, state=None, step_seconds=STEP_SECONDS):
        import ipywidgets as w

        self.state = state or State()
        self.step_seconds = step_seconds
        self._timer = None
        self._frames = None
        self.done = 0
        self.pending = False
        self._live = None               # (state, image, panel, text) of the picture shown
        self._finished = None           # the same of the last finished picture, with its
                                        # samples, its last step's time and its status line
        self.last_ms = 0.0
        st = self.state
        canvas = self.screen(SIZE[0] * SCALE + 8 + INSET, INSET)
        self.samples = slider("samples / pixel", st.samples, 1, 64, 1, kind=w.IntSlider)
        self.light = slider("light radius", st.light_radius, 0.0, MAX_LIGHT, 0.05)
        self.gloss = slider("gloss exponent", st.gloss, 1.0, 1000.0, 1.0)
        self.aperture = slider("lens radius", st.aperture, 0.0, MAX_APERTURE, 0.01)
        self.focus = slider("focal distance", st.focal_distance, 3.0, 10.0, 0.1)
        self.shutter = slider("shutter", st.shutter, 0.0, 1.0, 0.05)
        self.domain = w.ToggleButtons(options=DOMAINS, value=st.domain,
                                      style={"button_width": _style.button_width(*DOMAINS)})
        bind(st, {"samples": self.samples, "light_radius": self.light, "gloss": self.gloss,
                  "aperture": self.aperture, "focal_distance": self.focus,
                  "shutter": self.shutter, "domain": self.domain}, self.update)
        self.status = w.HTML()
        self.info = panel(width="640px")
        align([self.samples, self.light, self.gloss, self.aperture, self.focus, self.shutter])
        controls = w.VBox([self.samples, self.light, self.gloss, self.aperture, self.focus,
                           self.shutter, self.status])
        self.widget = w.VBox([beside(canvas, controls), self.domain, self.info])
        self._restart()
        self.settle()

    # ----------------------------------------------------------------------------------------
    def _restart(self):
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        self._frames, self._panel = _begin(self.state)
        self.done = 0
        self.current = None
        self._step()

    def _step(self):
        """One more sample per pixel (returns False when all are done)."""
        start = time.perf_counter()
        try:
            self.current = next(self._frames)
        except StopIteration:
            self.pending = False
            return False
        self.done += 1
        self.pending = self.done < int(self.state.samples)
        self.show_frame(_on_screen(_compose(self.current, self._panel)))
        self.last_ms = 1e3 * (time.perf_counter() - start)
        self.info.value = _text(self.state, self.done)
        self.status.value = (f"<i>{self.done}/{int(self.state.samples)} samples, last step "
                             f"{self.last_ms:.0f} ms</i>")
        self._live = (replace(self.state), self.current, self._panel, self.info.value)
        if not self.pending:
            self._finished = self._live + (self.done, self.last_ms, self.status.value)
        return True

    def _tick(self):
        self._timer = None
        if self._step() and self.pending:
            self._schedule()

    def _schedule(self):
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:            # no event loop (a script or a test): wait for settle()
            return
        self._timer = loop.call_later(self.step_seconds, self._tick)

    def update(self):
        """A control changed: show one sample per pixel now and refine while the controls rest
        (or the last finished picture at once, if its values are back). Drawn ahead
        (:attr:`drawing_ahead`), only the picture and its text: the refinement under way is
        left alone, and shown again when its values come back."""
        if self.drawing_ahead:
            for kept in (self._live, self._finished):
                if kept is not None and kept[0] == self.state:
                    _, image, panel, info = kept[:4]
                    break
            else:
                frames, panel = _begin(self.state)
                image, info = next(frames), _text(self.state, 1)
            self.show_frame(_on_screen(_compose(image, panel)))
            self.info.value = info
            return
        if self._finished is not None and self._finished[0] == self.state:
            if self._timer is not None:
                self._timer.cancel()
                self._timer = None
            (_, self.current, self._panel, self.info.value, self.done, self.last_ms,
             self.status.value) = self._finished
            self._live = self._finished[:4]
            self._frames = None
            self.pending = False
            self.show_frame(_on_screen(_compose(self.current, self._panel)))
            return
        self._restart()
        if self.pending:
            self._schedule()

    def settle(self):
        """Add all the remaining samples now."""
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        while self.pending and self._step():
            pass
        self.pending = False

    def png(self, dpi=None):
        """The current picture as PNG bytes, as the canvas shows it (for readers without a
        kernel)."""
        return _png(self.frame())
