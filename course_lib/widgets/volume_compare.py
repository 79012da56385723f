r"""Volume rendering compared: ray casting, texture slicing and splatting of one small volume.

The CT-like phantom (:func:`course_lib.scivis.example_volume`, SIZE\ :sup:`3` samples) is
rendered three ways with the same view, transfer-function preset and image window
(IMAGE x IMAGE pixels): ray casting (:func:`course_lib.scivis.volume_render`, no early
termination), view-aligned texture slicing (:func:`course_lib.scivis.slice_render`, the number
of slices and the classification order from the controls) and splatting
(:func:`course_lib.scivis.splat_render`, the kernel radius from its slider). Each image is
cached by the settings it depends on: moving the slices slider re-renders only the slicing,
the kernel slider only the splatting; the view angle and the preset re-render all three (about
0.1-0.2 s on these machines; the other controls a few tens of milliseconds).
"""
from dataclasses import dataclass
from functools import lru_cache
import time

import numpy as np

from .. import draw, scivis
from . import _style
from ._base import Explorer, bind, labelled, panel, slider

__all__ = ["IMAGE", "METHODS", "SIZE", "State", "VolumeCompareExplorer", "render", "scene",
           "volume"]

SIZE = 32
IMAGE = 72
METHODS = ("ray casting", "slicing", "splatting")


@dataclass
class State:
    """The view, the preset and each method's own setting.

    Examples
    --------
    >>> State().slices, State().classification, State().preset
    (48, 'post', 'skin')
    """

    azimuth_deg: float = 30.0
    slices: int = 48
    kernel_radius: float = 1.5
    classification: str = "post"
    preset: str = "skin"


@lru_cache(maxsize=1)
def volume():
    """The CT-like phantom at SIZE^3 (cached).

    Examples
    --------
    >>> volume().values.shape
    (32, 32, 32)
    """
    return scivis.example_volume("ct", size=SIZE)


def _geometry(azimuth_deg):
    vol = volume()
    return dict(rotation=scivis.view_rotation(np.radians(azimuth_deg), -0.35),
                image_size=(IMAGE, IMAGE), spacing=vol.spacing, origin=vol.origin,
                extent="sphere")


@lru_cache(maxsize=64)
def render(method, azimuth_deg, preset, setting=None, classification="post"):
    """One method's image and the seconds it took (cached by its arguments).

    `setting` is the number of slices for "slicing" (spread over the bounding sphere's
    diameter) and the kernel radius for "splatting"; ray casting samples every half spacing.

    Returns
    -------
    (ndarray, float)
        The RGB image (IMAGE, IMAGE, 3), clipped to [0, 1], and the time.

    Examples
    --------
    >>> img, seconds = render("ray casting", 30.0, "skin")
    >>> img.shape, seconds > 0
    ((72, 72, 3), True)
    """
    vol = volume()
    g = _geometry(azimuth_deg)
    start = time.perf_counter()
    if method == "ray casting":
        img = scivis.volume_render(vol.values, preset, early_termination=None, **g).rgb
    elif method == "slicing":
        diameter = float(np.linalg.norm(np.array(vol.spacing) * (np.array(vol.values.shape) - 1)))
        img = scivis.slice_render(vol.values, preset, slice_spacing=diameter / int(setting),
                                  classification=classification, **g).rgb
    elif method == "splatting":
        img = scivis.splat_render(vol.values, preset, kernel_radius=float(setting), **g).rgb
    else:
        raise ValueError(f"method must be one of {METHODS}, got {method!r}")
    return np.clip(img, 0.0, 1.0), time.perf_counter() - start


def scene(state):
    """Pure part: the three images, their times and differences to ray casting, and the text.

    Returns
    -------
    dict
        ``images`` (method -> RGB), ``times`` (seconds, as first computed), ``differences``
        (mean absolute difference to ray casting), ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["differences"]["ray casting"], s["images"]["slicing"].shape
    (0.0, (72, 72, 3))
    """
    if state.classification not in ("pre", "post"):
        raise ValueError(f"classification must be 'pre' or 'post', got {state.classification!r}")
    az = float(state.azimuth_deg)
    runs = {"ray casting": render("ray casting", az, state.preset),
            "slicing": render("slicing", az, state.preset, int(state.slices),
                              state.classification),
            "splatting": render("splatting", az, state.preset, float(state.kernel_radius))}
    images = {k: v[0] for k, v in runs.items()}
    times = {k: v[1] for k, v in runs.items()}
    ref = images["ray casting"]
    diffs = {k: float(np.abs(img - ref).mean()) for k, img in images.items()}
    text = (f"<b>{state.preset}</b> preset, view azimuth {az:.0f}°. "
            f"Ray casting {1e3 * times['ray casting']:.0f} ms; "
            f"slicing ({int(state.slices)} view-aligned slices, {state.classification}-"
            f"classified) {1e3 * times['slicing']:.0f} ms, mean |difference| "
            f"{diffs['slicing']:.4f}; splatting (kernel radius {float(state.kernel_radius):.2f} "
            f"voxels, pre-classified) {1e3 * times['splatting']:.0f} ms, mean |difference| "
            f"{diffs['splatting']:.4f}. ")
    if int(state.slices) < 24:
        text += ("<b>Few slices:</b> wood-grain rings where each slice cuts the surfaces. ")
    if state.classification == "pre":
        text += ("<b>Pre-classification</b> interpolates colours: sharp features of the "
                 "transfer function blur into the grid's blocky rims. ")
    if float(state.kernel_radius) < 1.2:
        text += ("<b>Small kernels</b> no longer overlap: the voxel grid shows through the "
                 "splats. ")
    text += "(Times are those of the first computation; images are cached.)"
    return {"images": images, "times": times, "differences": diffs, "text": text}


class VolumeCompareExplorer(Explorer):
    """Ray casting, slicing and splatting side by side; view, slices, kernel, classification.

    In a notebook, after ``%matplotlib widget``, end a cell with ``VolumeCompareExplorer()``.

    Examples
    --------
    >>> explorer = VolumeCompareExplorer()
    >>> explorer.slices.value = 16
    >>> "16 view-aligned slices" in explorer.info.value
    True
    """

    summary = ("Volume rendering compared (interactive): one CT-like volume by ray casting, "
               "texture slicing and splatting, with the view angle, the number of slices, the "
               "splat kernel, pre/post-classification and the transfer function as controls.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(7.2, 2.7))
        axes = [self.fig.add_axes((0.02 + 0.33 * i, 0.02, 0.3, 0.8)) for i in range(3)]
        self.images = [ax.imshow(s["images"][m], origin="lower", interpolation="nearest")
                       for ax, m in zip(axes, METHODS)]
        for ax, m in zip(axes, METHODS):
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title(m)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, self.images)
        self.azimuth = slider("view azimuth °", self.state.azimuth_deg, -180, 180, 15)
        self.slices = slider("slices", self.state.slices, 8, 128, 8, kind=w.IntSlider)
        self.kernel = slider("splat radius", self.state.kernel_radius, 0.75, 3.0, 0.25)
        self.classification = labelled(w.Dropdown, "classification", options=["post", "pre"],
                                       value=self.state.classification)
        self.preset = labelled(w.Dropdown, "transfer", options=["ramp", "skin", "bone"],
                               value=self.state.preset)
        bind(self.state, {"azimuth_deg": self.azimuth, "slices": self.slices,
                          "kernel_radius": self.kernel, "classification": self.classification,
                          "preset": self.preset}, self.update)
        self.info = panel(width="720px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([self.azimuth, self.slices, self.kernel,
                                      self.classification, self.preset],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(s)

    def update(self):
        """Re-render what the changed control affects (the rest is cached); update the images."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        for image, m in zip(self.images, METHODS):
            image.set_data(s["images"][m])
        self.info.value = s["text"]
