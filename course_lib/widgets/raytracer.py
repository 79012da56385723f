r"""Ray tracer explorer: Whitted's scene re-rendered as you change depth, shadows, materials and
the camera.

The scene is the classic one of :func:`course_lib.raytracing.example_scene` ("spheres"): a red
diffuse sphere, a mirror sphere and a glass sphere on a checkered floor, one point light.
Sliders set the recursion depth (0 is ray casting with shadow rays), switch the shadow rays
off, change the mirror's reflectivity :math:`k_r`, the glass's transparency :math:`k_t` and
refractive index, the floor's reflectivity, and move the camera on a sphere around the scene
(azimuth, elevation, distance).

A full ray-traced image takes most of a second in numpy, far too slow to follow a slider. So
while a slider moves, the explorer renders a **low-resolution preview** (:data:`PREVIEW`
pixels, 1/16 of the rays, well under 100 ms), shown with big square pixels; once the slider
has been still for :data:`SETTLE_SECONDS` the **full image** (:data:`FULL`) replaces it. The
full image is traced :data:`BAND_ROWS` rows at a time (:func:`course_lib.raytracing.render_bands`)
on the kernel's event loop, so a slider moved while it is being made is answered after at most
one band (tens of milliseconds), not after the whole image: the rest of it is abandoned. Coming
back to the values of the last full image shows that image again at once.

The picture is shown on a matplotlib canvas one pixel for one (:meth:`Explorer.screen`), at
:data:`DISPLAY` pixels: its frames take the explorers' own path to the page, and while the
explorer rests the kernel draws ahead the previews of the next slider steps, which the page
shows without waiting for the kernel (:mod:`course_lib._prefetch`).
"""
import asyncio
import io
import time
from dataclasses import dataclass, replace

import numpy as np

from .. import raytracing as rt
from . import _style
from ._base import Explorer, align, beside, bind, checkbox, panel, slider

__all__ = ["BAND_ROWS", "DISPLAY", "FULL", "PREVIEW", "RayTracerExplorer", "State", "TARGET",
           "build_scene", "make_camera", "scene", "scene_bands"]

PREVIEW = (80, 60)          # width, height of the preview while a slider moves
FULL = (320, 240)           # width, height of the full image
DISPLAY = (480, 360)        # width, height on screen: the preview x 6, the full image x 1.5
SETTLE_SECONDS = 0.35       # a slider still this long counts as released
BAND_ROWS = 8               # full-image rows traced between two looks at the student's input
TARGET = np.array([0.0, 0.8, -0.2])
"""The point the camera orbits around and looks at (between the three spheres)."""
FOV_DEG = 45.0


@dataclass
class State:
    """Everything the picture depends on (camera angles in degrees).

    Examples
    --------
    >>> State().max_depth, State().shadows
    (3, True)
    """

    max_depth: int = 3
    shadows: bool = True
    mirror_reflectivity: float = 0.85
    glass_transparency: float = 0.95
    glass_ior: float = 1.5
    floor_reflectivity: float = 0.2
    azimuth: float = 0.0
    elevation: float = 7.0
    distance: float = 6.3


def build_scene(state):
    """The example scene ``"spheres"`` with the state's materials (objects ``[floor, red,
    mirror, glass]``).

    Examples
    --------
    >>> s = build_scene(State(glass_ior=1.33, mirror_reflectivity=0.5))
    >>> s.objects[3].material.ior, s.objects[2].material.reflectivity
    (1.33, 0.5)
    """
    base = rt.example_scene("spheres")
    floor, red, mirror, glass = base.objects
    kr = state.floor_reflectivity
    floor = rt.Plane(floor.point, floor.normal,
                     rt.WhittedMaterial(floor.material.phong, reflectivity=kr),
                     checker=rt.WhittedMaterial(floor.checker.phong, reflectivity=kr),
                     checker_size=floor.checker_size)
    mirror = rt.Sphere(mirror.center, mirror.radius,
                       replace(mirror.material, reflectivity=state.mirror_reflectivity))
    glass = rt.Sphere(glass.center, glass.radius,
                      replace(glass.material, transparency=state.glass_transparency,
                              ior=state.glass_ior))
    return rt.Scene([floor, red, mirror, glass], base.lights, base.ambient, base.background)


def make_camera(state, width, height):
    r"""The camera on a sphere around :data:`TARGET`, looking at it.

    .. math:: e = T + \rho\,(\cos\varepsilon \sin\alpha,\ \sin\varepsilon,\
              \cos\varepsilon \cos\alpha)

    with azimuth :math:`\alpha` about the vertical y axis (0: in front, on +z) and elevation
    :math:`\varepsilon` above the horizontal plane through the target.

    Examples
    --------
    >>> cam = make_camera(State(azimuth=90, elevation=0, distance=5), 32, 24)
    >>> np.round(cam.eye, 12).tolist()
    [5.0, 0.8, -0.2]
    """
    a, e = np.radians([state.azimuth, state.elevation])
    eye = TARGET + state.distance * np.array([np.cos(e) * np.sin(a), np.sin(e),
                                              np.cos(e) * np.cos(a)])
    return rt.Camera(eye, TARGET - eye, [0.0, 1.0, 0.0], np.radians(FOV_DEG), width, height)


def scene(state, preview=False):
    """Pure part: the rendered image and what it cost.

    Parameters
    ----------
    state : State
    preview : bool
        Render at :data:`PREVIEW` instead of :data:`FULL` resolution.

    Returns
    -------
    dict
        ``image`` (height, width, 3) in [0, 1], row 0 at the bottom; ``counts``
        (:class:`course_lib.raytracing.RayCounts`); ``camera``; ``preview``; ``text``.

    Examples
    --------
    >>> s = scene(State(max_depth=0), preview=True)
    >>> s["image"].shape, s["counts"].reflected
    ((60, 80, 3), 0)
    """
    width, height = PREVIEW if preview else FULL
    camera = make_camera(state, width, height)
    image, counts = rt.render(build_scene(state), camera, max_depth=state.max_depth,
                              shadows=state.shadows, return_counts=True)
    return _result(state, preview, image, counts, camera)


def scene_bands(state, rows=BAND_ROWS):
    """The full image of :func:`scene`, traced `rows` image rows at a time: yields None after
    each band but the last, then the same dict as ``scene(state)``.

    Examples
    --------
    >>> steps = list(scene_bands(State(max_depth=0), rows=100))
    >>> steps[:-1], steps[-1]["image"].shape
    ([None, None], (240, 320, 3))
    """
    camera = make_camera(state, *FULL)
    for image, counts, done in rt.render_bands(build_scene(state), camera, rows,
                                               max_depth=state.max_depth,
                                               shadows=state.shadows):
        if done < camera.height:
            yield None
    yield _result(state, False, image, counts, camera)


def _result(state, preview, image, counts, camera):
    width, height = camera.width, camera.height
    depth = state.max_depth
    if depth == 0:
        what = ("Depth 0: ray casting with shadow rays — the mirror and the glass show only "
                "their own (dark) local colour.")
    else:
        what = (f"Depth {depth}: up to {depth} bounce{'s' if depth > 1 else ''} after the "
                f"primary ray; mirror-in-mirror paths longer than that come out black.")
    text = (f"<b>{'Preview' if preview else 'Full image'} {width}×{height}</b>: "
            f"{counts.primary:,} primary, {counts.shadow:,} shadow, {counts.reflected:,} "
            f"reflected and {counts.refracted:,} refracted rays ({counts.total:,} in all). "
            + what
            + ("" if state.shadows else " Shadow rays off: every light reaches every point, "
               "so the shadows vanish and the floor under the spheres is lit."))
    return {"image": image, "counts": counts, "camera": camera, "preview": preview,
            "text": text}


def _on_screen(image, size=None):
    """An image stored row 0 at the bottom as uint8 pixels row 0 at the top, resized to `size`
    (width, height): by whole multiples, each pixel a square block (a preview's big pixels),
    otherwise bilinearly."""
    from PIL import Image

    pixels = np.flipud(np.round(np.clip(image, 0, 1) * 255).astype(np.uint8))
    if size is None or tuple(size) == pixels.shape[1::-1]:
        return np.ascontiguousarray(pixels)
    width, height = size
    sx, sy = width / pixels.shape[1], height / pixels.shape[0]
    if sx == sy == int(sx):
        return np.repeat(np.repeat(pixels, int(sx), axis=0), int(sx), axis=1)
    return np.asarray(Image.fromarray(pixels).resize((width, height), Image.BILINEAR))


def _png(pixels):
    """PNG bytes of uint8 pixels."""
    from PIL import Image

    buffer = io.BytesIO()
    Image.fromarray(pixels).save(buffer, format="png", compress_level=1)
    return buffer.getvalue()


class RayTracerExplorer(Explorer):
    """Sliders for recursion depth, shadows, materials and camera; a preview while sliding and
    the full ray-traced image when the slider rests.

    In a live kernel the full image is rendered :data:`SETTLE_SECONDS` after the last change,
    on the kernel's event loop, `band_rows` rows at a time: a change while it is being made
    abandons it and shows the new preview. Without a running event loop (a script, a test) the full
    image waits for :meth:`settle` (or the "render full image" button).

    Examples
    --------
    >>> explorer = RayTracerExplorer()
    >>> explorer.depth.value = 1                    # a student's slider move
    >>> explorer.current["image"].shape, explorer.pending, explorer.frame().shape
    ((60, 80, 3), True, (360, 480, 3))
    >>> explorer.settle()
    >>> explorer.current["image"].shape, explorer.pending
    ((240, 320, 3), False)
    >>> explorer.depth.value = 3                    # back: no full image of depth 3 kept
    >>> explorer.current["preview"], explorer.pending
    (True, True)
    >>> explorer.depth.value = 1                    # back to the last full image's values
    >>> explorer.current["preview"], explorer.pending
    (False, False)
    """

    summary = ("Ray tracer explorer (interactive): Whitted's spheres — recursion depth, shadow "
               "rays on/off, mirror k_r, glass k_t and refractive index, floor k_r, camera "
               "orbit; a low-resolution preview while sliding, the full image on release.")

    refines = True                  # a preview, then the full image

    def __init__(self, state=None, settle_seconds=SETTLE_SECONDS, band_rows=BAND_ROWS):
        import ipywidgets as w

        self.state = state or State()
        self.settle_seconds = settle_seconds
        self.band_rows = band_rows
        self.pending = False
        self.bands_traced = 0           # bands of full images traced (abandoned ones too)
        self._timer = None
        self._bands = None
        self._full = None               # (state, scene) of the last full image shown
        self.last_ms = 0.0
        canvas = self.screen(*DISPLAY)
        st = self.state
        options = {}
        self.depth = slider("recursion depth", st.max_depth, 0, 6, 1, kind=w.IntSlider, **options)
        self.shadows = checkbox("shadow rays", st.shadows)
        self.mirror = slider("mirror k_r", st.mirror_reflectivity, 0, 1, 0.05, **options)
        self.glass = slider("glass k_t", st.glass_transparency, 0, 1, 0.05, **options)
        self.ior = slider("glass index η", st.glass_ior, 1.0, 2.5, 0.01, **options)
        self.floor = slider("floor k_r", st.floor_reflectivity, 0, 1, 0.05, **options)
        self.azimuth = slider("camera azimuth °", st.azimuth, -180, 180, 2, **options)
        self.elevation = slider("camera elevation °", st.elevation, 2, 70, 1, **options)
        self.distance = slider("camera distance", st.distance, 3.0, 12.0, 0.1, **options)
        # k_r + k_t <= 1 for the glass (its own k_r is 0), always true on [0, 1]
        bind(st, {"max_depth": self.depth, "shadows": self.shadows,
                  "mirror_reflectivity": self.mirror, "floor_reflectivity": self.floor,
                  "glass_ior": self.ior, "glass_transparency": self.glass,
                  "azimuth": self.azimuth, "elevation": self.elevation,
                  "distance": self.distance}, self.update)
        self.full_button = w.Button(description="render full image", icon="image",
                                    layout=w.Layout(width=_style.button_width(
                                        "render full image", "__")))        # and the icon
        self.full_button.on_click(lambda _: self.settle())
        self.status = w.HTML()
        self.info = panel(width=f"{DISPLAY[0]}px")
        align([self.depth, self.mirror, self.glass, self.ior, self.floor, self.azimuth,
               self.elevation, self.distance])
        controls = w.VBox([self.depth, self.shadows, self.mirror, self.glass, self.ior,
                           self.floor, self.azimuth, self.elevation, self.distance,
                           self.full_button, self.status])
        self.widget = w.VBox([beside(canvas, controls), self.info])
        self.current = None
        self._render(preview=False)

    @property
    def working(self):
        """The full image is being traced, band by band, on the event loop."""
        return self._bands is not None

    def update(self):
        """A slider moved: show the preview now, and the full image once the slider rests (at
        once if it is the last full image's). Drawn ahead (:attr:`drawing_ahead`), only the
        picture and its text."""
        ahead = self.drawing_ahead
        if self._full is not None and self._full[0] == self.state:
            if not ahead:
                self._cancel()
                self.pending = False
            self._show(self._full[1], self.last_ms, status=not ahead)
            return
        self._render(preview=True, status=not ahead)
        if not ahead:
            self.pending = True
            self._schedule_full()

    def _schedule_full(self):
        self._cancel()
        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:            # no event loop (a script or a test): wait for settle()
            return
        self._timer = loop.call_later(self.settle_seconds, self._start_full, loop)

    def _cancel(self):
        """Forget a full image waiting to start or half made (a newer input came)."""
        if self._timer is not None:
            self._timer.cancel()
            self._timer = None
        self._bands = None

    def _start_full(self, loop):
        self._timer = None
        self._bands = scene_bands(self.state, self.band_rows)
        self._band_seconds = 0.0
        self.status.value = f"<i>tracing the full image {FULL[0]}×{FULL[1]}…</i>"
        self._timer = loop.call_soon(self._next_band, loop)

    def _next_band(self, loop):
        """Trace one band of the full image, then give the event loop back: an input that came
        meanwhile (queued on the loop, see :func:`._base.handle_comms_on_main_thread`) is
        handled before the next band and cancels it."""
        self._timer = None
        start = time.perf_counter()
        s = next(self._bands)
        self._band_seconds += time.perf_counter() - start
        self.bands_traced += 1
        if s is None:
            self._timer = loop.call_soon(self._next_band, loop)
            return
        self._bands = None
        self._show(s, 1e3 * self._band_seconds)
        self.pending = False

    def settle(self):
        """Render the full image now (what happens when the slider has come to rest)."""
        self._cancel()
        self._render(preview=False)
        self.pending = False

    def _render(self, preview, status=True):
        start = time.perf_counter()
        s = scene(self.state, preview)
        self._show(s, 1e3 * (time.perf_counter() - start), status)

    def _show(self, s, ms, status=True):
        self.current = s
        # a full image shown live goes whole: the page may show a preview it keeps for these
        # values that the kernel no longer counts on
        self.show_frame(_on_screen(s["image"], DISPLAY), whole=status and not s["preview"])
        self.info.value = s["text"]
        if not status:
            return
        self.last_ms = ms
        if not s["preview"]:
            self._full = (replace(self.state), s)
        self.status.value = (f"<i>preview {PREVIEW[0]}×{PREVIEW[1]} in {ms:.0f} ms — "
                             "the full image follows when the slider rests</i>"
                             if s["preview"] else f"<i>full image {FULL[0]}×{FULL[1]}</i>")

    def png(self, dpi=None):
        """The current picture as PNG bytes, as the canvas shows it (for readers without a
        kernel)."""
        return _png(self.frame())
