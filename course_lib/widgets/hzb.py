"""Hierarchical z-buffer explorer: a 64 x 64 depth buffer, its z-pyramid and a box to test.

The picture is one level of the pyramid (nearest-neighbour enlarged to the screen): the depth
pyramid (max of 2 x 2) in HZB mode, the occluders' opacity pyramid (mean of 2 x 2) in HOM mode.
The box's screen rectangle is tinted pink, with its nearest depth as a swatch in the middle
(on the picture's scale), and the texels of the shown level that cover it are outlined: red
when the box is rejected there, black when it must be drawn. The text compares the texels read
with the pixels a full-resolution test reads, and names the level the hierarchical test would
pick by itself (at most 2 x 2 texels). In HOM mode the texels at least as opaque as the
threshold are tinted blue; the threshold slider is live in HOM mode only.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, visibility
from . import _style
from ._base import Explorer, bind, labelled, panel, slider

__all__ = ["HZBExplorer", "State", "scene", "depth_buffers"]

SIZE = 64
SCALE = 2                      # screen pixels per buffer pixel in the picture
FAR_WALL = 0.9
_TRIANGLES = np.array([
    [[0, 0, 0.3], [52, 0, 0.35], [0, 52, 0.4]],          # a big occluder, lower left
    [[18, 64, 0.5], [64, 18, 0.55], [64, 64, 0.5]],      # another, upper right
    [[30, 6, 0.2], [62, 4, 0.25], [46, 34, 0.2]],        # a near one in front
    [[6, 50, 0.6], [22, 48, 0.6], [12, 62, 0.65]],       # a small far one
])


def depth_buffers():
    """The explorer's scene: the occluders' depth buffer and the full one (with a far wall).

    Returns
    -------
    (ndarray, ndarray)
        Both (64, 64): occluders only (``inf`` elsewhere), and with the far wall at depth 0.9.

    Examples
    --------
    >>> occ, full = depth_buffers()
    >>> bool(np.isinf(occ).any()), float(full.max())
    (True, 0.9)
    """
    occ, full = _buffers()
    return occ.copy(), full.copy()


@lru_cache(maxsize=1)
def _buffers():
    occ = visibility.zbuffer(_TRIANGLES, SIZE, SIZE).depth
    return occ, np.where(np.isinf(occ), FAR_WALL, occ)


@lru_cache(maxsize=1)
def _pyramids():
    occ, full = _buffers()
    return (visibility.z_pyramid(full), visibility.occlusion_map_pyramid(np.isfinite(occ) * 1.0),
            visibility.depth_estimation_buffer(occ, 8))


@dataclass
class State:
    """The mode, the pyramid level shown and the box (lower-left pixel, side, nearest depth).

    Examples
    --------
    >>> State().mode, State().level
    ('HZB', 3)
    """

    mode: str = "HZB"
    level: int = 3
    x: int = 10
    y: int = 12
    size: int = 14
    z_near: float = 0.5
    threshold: float = 0.9


def _viridis():
    import matplotlib
    return matplotlib.colormaps["viridis"](np.linspace(0, 1, 256))[:, :3]


_LUT = _viridis()


def _rect(state):
    x0 = int(np.clip(state.x, 0, SIZE - 1))
    y0 = int(np.clip(state.y, 0, SIZE - 1))
    side = max(int(state.size), 1)
    return (x0, y0, min(x0 + side - 1, SIZE - 1), min(y0 + side - 1, SIZE - 1))


def scene(state):
    """Pure part: the picture (an opaque RGB image), the test's result and the text.

    Returns
    -------
    dict
        ``image`` (128, 128, 3) RGB, row 0 at the bottom; ``level_values`` (the shown level);
        ``rect``; ``rejected`` (at the shown level); ``texels`` (texels read there);
        ``pixels`` (pixels of the rectangle); ``auto`` (the level :func:`hzb_level` picks) and
        ``auto_rejected``; ``full_rejected`` (the per-pixel test, HZB mode); ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["image"].shape, s["texels"], s["pixels"]
    ((128, 128, 3), 6, 196)
    """
    hzb, hom, deb = _pyramids()
    pyr = hzb if state.mode == "HZB" else hom
    level = int(np.clip(state.level, 0, len(pyr.levels) - 1))
    rect = _rect(state)
    i0, j0, i1, j1 = rect
    z = float(state.z_near)
    values = pyr.levels[level]
    f = 2 ** level
    big = np.repeat(np.repeat(values, f, axis=0), f, axis=1)[:SIZE, :SIZE]
    if state.mode == "HZB":
        rgb = _LUT[np.clip((np.nan_to_num(big, posinf=1.0) * 255).astype(int), 0, 255)]
        rejected, _, texels = visibility.hzb_test(hzb, rect, z, level=level)
        auto_rej, auto, _ = visibility.hzb_test(hzb, rect, z)
        full_rej = visibility.full_test(_buffers()[1], rect, z)[0]
    else:
        rgb = np.repeat(big[..., None], 3, axis=2) * 0.85 + 0.1
        # texels at least as opaque as the threshold count as opaque: tinted blue
        opaque = big >= state.threshold
        rgb[opaque] = 0.6 * rgb[opaque] + 0.4 * np.array([0.2, 0.5, 1.0])
        t = visibility.hom_test(hom, rect, z, deb, state.threshold, level=level)
        rejected = t.culled
        texels = t.reads                       # with the descent into partly covered texels
        a = visibility.hom_test(hom, rect, z, deb, state.threshold)
        auto_rej, auto = a.culled, a.level
        full_rej = None
    pixels = (i1 - i0 + 1) * (j1 - j0 + 1)
    img = np.repeat(np.repeat(rgb, SCALE, axis=0), SCALE, axis=1)
    s = SCALE
    tint = np.array([0.95, 0.35, 0.75])
    img[j0 * s:(j1 + 1) * s, i0 * s:(i1 + 1) * s] = 0.55 * img[j0 * s:(j1 + 1) * s,
                                                              i0 * s:(i1 + 1) * s] + 0.45 * tint
    # a swatch in the box's middle: its nearest depth on the picture's scale, so moving the
    # box in depth shows, and a swatch darker than the covering texels means nearer than them
    own = (_LUT[int(np.clip(z, 0.0, 1.0) * 255)] if state.mode == "HZB"
           else np.full(3, 0.85 * z + 0.1))
    w_box, h_box = (i1 - i0 + 1) * s, (j1 - j0 + 1) * s
    half = max(min(w_box, h_box) // 2, 2)
    cx, cy = i0 * s + w_box // 2, j0 * s + h_box // 2
    img[max(cy - half // 2, 0):cy + (half + 1) // 2,
        max(cx - half // 2, 0):cx + (half + 1) // 2] = own
    edge = np.array([0.9, 0.05, 0.05]) if rejected else np.array([0.05, 0.05, 0.05])
    a0, b0, a1, b1 = (i0 >> level) * f * s, (j0 >> level) * f * s, \
        min(((i1 >> level) + 1) * f, SIZE) * s, min(((j1 >> level) + 1) * f, SIZE) * s
    step = f * s
    # texel borders, 2 px wide (only the outer one where texels are too small to outline)
    cols = list(range(a0, a1, step)) + [a1] if step > 4 else [a0, a1]
    rows = list(range(b0, b1, step)) + [b1] if step > 4 else [b0, b1]
    for c in cols:
        img[b0:b1, max(c - 1, 0):min(c + 1, SIZE * s)] = edge
    for r in rows:
        img[max(r - 1, 0):min(r + 1, SIZE * s), a0:a1] = edge
    word = "REJECTED (not drawn)" if rejected else "kept (drawn)"
    if state.mode == "HZB":
        how = (f"box nearest depth {z:.2f} vs the farthest depth of the {texels} covering "
               f"texel(s) {values[j0 >> level:(j1 >> level) + 1, i0 >> level:(i1 >> level) + 1].max():.2f}")
        full = (f"The full per-pixel test reads {pixels} pixels and says "
                f"{'hidden' if full_rej else 'visible'}. (The HOM threshold, "
                f"{state.threshold:.2f}, counts in HOM mode only.)")
    else:
        how = (f"covering opacities min {t.opacities.min():.2f} vs threshold "
               f"{state.threshold:.2f} ({'opaque' if t.opaque else 'not opaque'}, after "
               f"descending into partly covered texels); depth "
               f"estimate {'passed' if t.behind else 'failed'}")
        full = ("Blue texels are at least as opaque as the threshold. HOM is approximate: "
                "with a threshold below 1 it may cull a box seen through small gaps.")
    text = (f"<b>{state.mode}, level {level}: {word}</b>. {how}. Texels read: {texels} "
            f"(a full test reads {pixels} pixels). The automatic choice (at most 2 x 2 texels) "
            f"is level {auto}: {'rejected' if auto_rej else 'kept'}. {full}")
    return {"image": img, "level_values": values, "rect": rect, "rejected": bool(rejected),
            "texels": int(texels), "pixels": int(pixels), "auto": int(auto),
            "auto_rejected": bool(auto_rej), "full_rejected": full_rej, "text": text}


class HZBExplorer(Explorer):
    """Move a box over a depth buffer and see which pyramid texels decide whether it is hidden.

    In a notebook, after ``%matplotlib widget``, end a cell with ``HZBExplorer()``.

    Examples
    --------
    >>> ex = HZBExplorer()
    >>> ex.z_near.value = 0.95
    >>> "REJECTED" in ex.info.value
    True
    """

    summary = ("Hierarchical z-buffer explorer (interactive): a 64 x 64 depth buffer, its "
               "z-pyramid (or occlusion map) and the texels that test a box.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(4.2, 4.2))
        ax = self.fig.add_axes([0.1, 0.07, 0.85, 0.8])
        self.image = ax.imshow(s["image"], origin="lower", extent=(0, SIZE, 0, SIZE),
                               interpolation="nearest")
        ax.set_title("box pink, its depth in the middle\n"
                     "covering texels: red rejects, black keeps",
                     fontsize=_style.LABEL)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image])
        self.mode = labelled(w.Dropdown, "mode", options=["HZB", "HOM"], value=self.state.mode)
        self.level = slider("level", self.state.level, 0, 6, 1, kind=w.IntSlider)
        self.x = slider("box x", self.state.x, 0, SIZE - 1, 1, kind=w.IntSlider)
        self.y = slider("box y", self.state.y, 0, SIZE - 1, 1, kind=w.IntSlider)
        self.size = slider("box size", self.state.size, 1, SIZE, 1, kind=w.IntSlider)
        self.z_near = slider("box depth", self.state.z_near, 0.0, 1.0, 0.01)
        self.threshold = slider("HOM threshold", self.state.threshold, 0.5, 1.0, 0.05)
        bind(self.state, {"mode": self.mode, "level": self.level, "x": self.x, "y": self.y,
                          "size": self.size, "z_near": self.z_near,
                          "threshold": self.threshold}, self.update)
        self.info = panel(width="420px")
        controls = w.VBox([self.mode, self.level, self.x, self.y, self.size, self.z_near,
                           self.threshold])
        self.widget = w.VBox([w.HBox([self.fig.canvas, controls]), self.info])
        self.info.value = s["text"]
        self.threshold.disabled = self.state.mode != "HOM"

    def update(self):
        """Recompute the scene and repaint the image."""
        self.threshold.disabled = self.state.mode != "HOM"     # the threshold is HOM's alone
        s = scene(self.state)
        self.image.set_data(s["image"])
        self.info.value = s["text"]
        self.blitter.update()
