r"""Screen-space ambient occlusion explorer: SSAO next to the ray-traced AO of the same view,
and their difference, on a scene with corners and an overhang.

The scene is :func:`course_lib.shading.ssao_test_scene` (a floor, a back wall, a box in the
corner, a shelf sticking out of the wall), drawn at SIZE x SIZE pixels. Its G-buffer
(:func:`course_lib.shading.g_buffer`) and the hit distances of MAX_SAMPLES cosine-weighted rays
per pixel (:func:`course_lib.shading.ray_traced_occlusion`) are computed once and cached, so
the ray-traced AO for any radius is a look-up; SSAO itself (:func:`course_lib.shading.ssao`)
is recomputed on every slider move (a few milliseconds at this size). Both use the linear
falloff, so that they estimate the same quantity where SSAO's assumptions hold.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, shading
from . import _style
from ._base import Explorer, bind, panel, slider

__all__ = ["MAX_SAMPLES", "SIZE", "SSAOExplorer", "State", "buffers", "ray_distances",
           "scene"]

SIZE = 96
MAX_SAMPLES = 32


@dataclass
class State:
    """The SSAO parameters.

    Examples
    --------
    >>> State().radius, State().samples, State().range_check
    (0.5, 16, True)
    """

    radius: float = 0.5
    samples: int = 16
    bias: float = 0.02
    blur: int = 4
    range_check: bool = True
    seed: int = 0


@lru_cache(maxsize=1)
def buffers():
    """The test scene and its G-buffer at SIZE x SIZE (cached).

    Examples
    --------
    >>> scene_, gb = buffers()
    >>> gb.positions.shape
    (96, 96, 3)
    """
    sc = shading.ssao_test_scene()
    return sc, shading.g_buffer(sc.vertices, sc.faces, sc.view, sc.projection, SIZE, SIZE)


@lru_cache(maxsize=1)
def ray_distances():
    """MAX_SAMPLES rays per pixel, cast once with no distance limit (cached, seeded).

    Examples
    --------
    >>> ray_distances().distances.shape
    (96, 96, 32)
    """
    sc, gb = buffers()
    return shading.ray_traced_occlusion(gb, sc.vertices[sc.faces], samples=MAX_SAMPLES, seed=7)


def _regions(gb):
    """Masks of the floor under the shelf and of the creases, in the image."""
    w = gb.world_positions
    under = gb.mask & (np.abs(w[..., 1]) < 1e-9) & (w[..., 0] > 0.3) & (w[..., 0] < 2.1) \
        & (w[..., 2] > -1.9) & (w[..., 2] < -1.2)
    return {"under the shelf": under}


def scene(state):
    r"""Pure part: the SSAO image, the ray-traced AO of the same view and radius, the
    difference and the text.

    Returns
    -------
    dict
        ``ssao``, ``ray`` (the ray-traced AO with the first `samples` rays, box-blurred like
        SSAO), ``difference`` (ssao - ray), ``mean_abs_difference``, ``under_shelf``
        (the two means on the floor under the shelf), ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["ssao"].shape, bool(s["mean_abs_difference"] < 0.1)
    ((96, 96), True)
    """
    sc, gb = buffers()
    k = int(state.samples)
    if not 1 <= k <= MAX_SAMPLES:
        raise ValueError(f"samples must be in 1 ... {MAX_SAMPLES}, got {state.samples!r}")
    blur = int(state.blur)
    s = shading.ssao(gb.positions, gb.normals, sc.projection, gb.mask, radius=state.radius,
                     samples=k, bias=state.bias, range_check=bool(state.range_check),
                     blur=blur, seed=int(state.seed))
    rt = ray_distances()
    ray = shading.RayTracedOcclusion(rt.distances[..., :k], rt.mask, rt.rays).visibility(
        state.radius)
    if blur > 1:
        ray = shading.box_blur(ray, gb.mask, blur)
    diff = s - ray
    mad = float(np.abs(diff[gb.mask]).mean())
    under = _regions(gb)["under the shelf"]
    us, ur = float(s[under].mean()), float(ray[under].mean())
    text = (f"<b>SSAO</b> with R = {state.radius:.2f}, k = {k} samples, bias = "
            f"{state.bias:.3f}, blur {blur}×{blur}; <b>ray-traced</b> AO with the same "
            f"radius and rays per pixel. Mean |SSAO − ray-traced| = {mad:.3f}; under the "
            f"shelf {us:.2f} vs {ur:.2f}. ")
    text += ("They agree in the creases between floor, wall and box and under the shelf, where "
             "the occluders are solid and seen by the camera. ")
    if not state.range_check:
        text += ("<b>Range check off:</b> red halos on the floor and wall around the front "
                 "edges of the box and the shelf: samples there land on surfaces far in front "
                 "of them, which SSAO takes for occluders (the ray tracer does not). ")
    else:
        text += ("With the range check, occluders further than R in depth are ignored: no "
                 "halos, but a little occlusion is lost where the occluder's visible face is "
                 "far in front (the wall just above the box, blue). ")
    if state.bias < 0.01:
        text += ("<b>Small bias:</b> the floor darkens itself (red speckle): depths are looked "
                 "up at pixel centres and a sample just above a tilted surface can seem behind "
                 "it. ")
    if blur <= 1:
        text += "Without blur the 4×4 noise tile of kernel rotations shows as a pattern. "
    text += ("SSAO cannot see geometry off-screen or hidden behind the front surface; its cost "
             "is samples × pixels, independent of the number of triangles.")
    return {"ssao": s, "ray": ray, "difference": diff, "mean_abs_difference": mad,
            "under_shelf": (us, ur), "text": text}


class SSAOExplorer(Explorer):
    """Radius, samples, bias, blur and range check; SSAO, ray-traced AO and their difference.

    In a notebook, after ``%matplotlib widget``, end a cell with ``SSAOExplorer()``.

    Examples
    --------
    >>> explorer = SSAOExplorer()
    >>> explorer.radius.value = 0.8
    >>> "R = 0.80" in explorer.info.value
    True
    """

    summary = ("SSAO explorer (interactive): screen-space ambient occlusion beside the "
               "ray-traced AO of the same view and their difference, with sliders for radius, "
               "samples, bias and blur and a range-check switch.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(9.0, 3.3))
        axes = [self.fig.add_axes((0.02 + 0.3 * i, 0.06, 0.26, 0.8)) for i in range(3)]
        self.images = [
            axes[0].imshow(s["ssao"], origin="lower", cmap="gray", vmin=0, vmax=1,
                           interpolation="nearest"),
            axes[1].imshow(s["ray"], origin="lower", cmap="gray", vmin=0, vmax=1,
                           interpolation="nearest"),
            axes[2].imshow(s["difference"], origin="lower", cmap="RdBu", vmin=-0.4, vmax=0.4,
                           interpolation="nearest")]
        self.fig.colorbar(self.images[2], cax=self.fig.add_axes((0.895, 0.06, 0.012, 0.8)))
        for ax in axes:
            ax.set_xticks([])
            ax.set_yticks([])
        # static titles (text is slow to redraw); the numbers go to the info panel
        self.titles = [ax.set_title(t) for ax, t in zip(axes, (
            "SSAO", "ray-traced AO, same R and k", "SSAO − ray-traced"))]
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, self.images)
        self.radius = slider("radius R", self.state.radius, 0.1, 1.5, 0.05)
        self.samples = slider("samples k", self.state.samples, 1, MAX_SAMPLES, 1,
                              kind=w.IntSlider)
        self.bias = slider("bias", self.state.bias, 0.0, 0.1, 0.005, readout_format=".3f")
        self.blur = slider("blur", self.state.blur, 1, 8, 1, kind=w.IntSlider)
        self.range_check = w.Checkbox(value=self.state.range_check, description="range check")
        bind(self.state, {"radius": self.radius, "samples": self.samples, "bias": self.bias,
                          "blur": self.blur, "range_check": self.range_check}, self.update)
        self.info = panel(width="860px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([self.radius, self.samples, self.bias, self.blur,
                                      self.range_check],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(s)

    def update(self):
        """Recompute SSAO (the G-buffer and the rays are cached) and update the images."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        for image, key in zip(self.images, ("ssao", "ray", "difference")):
            image.set_data(s[key])
        self.info.value = s["text"]
