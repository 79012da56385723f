r"""LIC explorer: line integral convolution of a field, with the kernel length on a slider.

White noise (fixed seed) is smeared along the streamlines of a steady 2D field
(:func:`course_lib.scivis.lic`): each pixel becomes the average of the noise along the short
streamline through it, :math:`L` pixels forwards and backwards. Short kernels leave grainy
noise; longer ones draw long, smooth streaks that follow the flow.

**Why moving the slider is cheap.** Tracing every pixel's streamline is the expensive part
(:class:`course_lib.scivis.LICTraces`, about a third of a second for 128 x 128 pixels and
:math:`L_{max} = 24`). It is done once per field, for the longest kernel the slider offers,
and cached; the traces keep the noise met at each step. A box kernel of any shorter length is
then a difference of two **prefix sums** along the traces per pixel (and the Hann kernel one
weighted sum), a few milliseconds. The bar in the corner is :math:`2L`, the kernel's length.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw
from .._validate import as_choice
from ..scivis import LICTraces, example_vector_field
from . import _style
from ._base import Explorer, align, beside, bind, checkbox, labelled, panel, slider

__all__ = ["KERNELS", "PRESETS", "SIZE", "LICExplorer", "State", "field_on_pixels", "scene",
           "traces"]

SIZE = 128
MAX_LENGTH = 24.0
STEP = 0.5
PRESETS = ("vortex", "saddle", "spiral", "source", "vortex pair")
KERNELS = ("box", "hann")


@dataclass
class State:
    """The field, the kernel's half-length in pixels, its shape, and colouring by speed.

    Examples
    --------
    >>> State().preset, State().kernel_length
    ('vortex', 8.0)
    """

    preset: str = "vortex"
    kernel_length: float = 8.0
    kernel: str = "box"
    colour_by_speed: bool = False


def field_on_pixels(preset, size=SIZE):
    """The velocity (u, v) of a preset at the pixel centres of [-1, 1]^2, rows along y.

    ``"vortex pair"`` is two counter-rotating vortices at (-0.4, 0) and (0.4, 0), each
    :math:`\\pm(-(y - y_k), x - x_k) / (r_k^2 + 0.05)`; the others are
    :func:`course_lib.scivis.example_vector_field`.

    Examples
    --------
    >>> u, v = field_on_pixels("saddle", size=4)
    >>> u[0], v[:, 0]
    (array([-0.75, -0.25,  0.25,  0.75]), array([ 0.75,  0.25, -0.25, -0.75]))
    """
    as_choice(preset, "preset", PRESETS)
    c = -1 + (np.arange(size) + 0.5) * 2 / size
    x, y = np.meshgrid(c, c)
    if preset == "vortex pair":
        u, v = np.zeros_like(x), np.zeros_like(x)
        for xk, sign in ((-0.4, 1.0), (0.4, -1.0)):
            r2 = (x - xk) ** 2 + y ** 2 + 0.05
            u += sign * -y / r2
            v += sign * (x - xk) / r2
        return u, v
    w = example_vector_field(preset)(np.stack([x, y], axis=-1))
    return w[..., 0], w[..., 1]


@lru_cache(maxsize=len(PRESETS))
def traces(preset):
    """The cached :class:`course_lib.scivis.LICTraces` of a preset (noise seed 18, traced to
    :data:`MAX_LENGTH` pixels each way with steps of :data:`STEP`).

    Examples
    --------
    >>> traces("vortex").samples.shape
    (97, 128, 128)
    """
    u, v = field_on_pixels(preset)
    return LICTraces(u, v, max_length=MAX_LENGTH, step=STEP, seed=18)


def scene(state):
    """Pure part: the LIC image (RGB, opaque), the raw LIC values, the kernel bar and text.

    Examples
    --------
    >>> s = scene(State(kernel_length=0.2))
    >>> bool(np.allclose(s["lic"], traces("vortex").noise))     # no smearing: the noise
    True
    """
    from matplotlib import colormaps

    preset = as_choice(state.preset, "preset", PRESETS)
    kernel = as_choice(state.kernel, "kernel", KERNELS)
    length = float(np.clip(state.kernel_length, 0.1, MAX_LENGTH))
    tr = traces(preset)
    values = tr.image(length, kernel=kernel)
    # contrast stretch: the average of many samples has a smaller spread than the noise
    spread = max(float(values.std()), 1e-9)
    grey = np.clip(0.5 + (values - values.mean()) / (4.0 * spread), 0.0, 1.0)
    if state.colour_by_speed:
        u, v = field_on_pixels(preset)
        speed = np.hypot(u, v)
        speed = speed / max(float(np.percentile(speed, 98)), 1e-12)
        colour = colormaps["viridis"](np.clip(speed, 0, 1))[..., :3]
        rgb = colour * (0.25 + 0.75 * grey[..., None])
    else:
        rgb = np.repeat(grey[..., None], 3, axis=-1)
    m = int(np.floor(length / STEP + 1e-9))
    text = (f"<b>{preset}</b>, {kernel} kernel, L = {length:g} px each way: {2 * m + 1} noise "
            f"samples per pixel (step {STEP:g} px). Spread of the LIC values "
            f"{values.std():.3f} (white noise: {tr.noise.std():.3f}); the picture is "
            "contrast-stretched."
            + (" Colour: speed |v| (viridis), brightness: LIC." if state.colour_by_speed
               else ""))
    bar = np.array([[6.0, SIZE - 8.0], [6.0 + 2 * length, SIZE - 8.0]])
    return {"rgb": rgb, "lic": values, "bar": bar, "samples": 2 * m + 1, "text": text}


class LICExplorer(Explorer):
    """Field preset, kernel length and shape, colour by speed: the LIC image.

    In a notebook, after ``%matplotlib widget``, end a cell with ``LICExplorer()``.

    Examples
    --------
    >>> explorer = LICExplorer()
    >>> explorer.length.value = 16.0
    >>> "65 noise samples" in explorer.info.value
    True
    """

    summary = ("LIC explorer (interactive): line integral convolution of a 2D field; the "
               "kernel length smears the noise along the streamlines.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(3.9, 3.9))
        ax = self.fig.add_axes((0.03, 0.03, 0.94, 0.88))
        self.image = ax.imshow(s["rgb"], origin="lower", interpolation="nearest",
                               extent=(-0.5, SIZE - 0.5, -0.5, SIZE - 0.5))
        (self.bar,) = ax.plot([], [], color="#d62728", lw=3, solid_capstyle="butt")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("line integral convolution (bar: 2L)")
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image, self.bar])
        self.preset = labelled(w.Dropdown, "field", options=PRESETS, value=self.state.preset)
        self.length = slider("kernel L (px)", self.state.kernel_length, 0.5, MAX_LENGTH, 0.5)
        align([self.preset, self.length])
        self.kernel = w.ToggleButtons(options=KERNELS, value=self.state.kernel,
                                      style={"button_width": _style.button_width(*KERNELS)})
        self.colour = checkbox("colour by speed", self.state.colour_by_speed)
        bind(self.state, {"preset": self.preset, "kernel_length": self.length,
                          "kernel": self.kernel, "colour_by_speed": self.colour}, self.update)
        self.info = panel(width="340px")
        self.widget = beside(self.fig.canvas, w.VBox([self.preset, self.length, self.kernel,
                                                      self.colour, self.info]),
                             align="flex-start")
        self._draw(s)

    def update(self):
        """New image from the cached traces (prefix sums), blitted."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.image.set_data(s["rgb"])
        self.bar.set_data(*s["bar"].T)
        self.info.value = s["text"]
