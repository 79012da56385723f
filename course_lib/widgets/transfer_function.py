r"""Transfer-function editor: drag the control points of an opacity curve, colour them, and see
the result live on a 2D scalar field and on a volume rendering of a CT-like head phantom.

A transfer function maps each (normalised) data value s in [0, 1] to a colour and an opacity.
Here it is piecewise linear between control points :math:`(s_k, c_k, \alpha_k)`: the editor
shows the opacity curve :math:`\alpha(s)` over the histograms of the two data sets, each control
point drawn in its colour, and the colour ramp :math:`c(s)` below it. The same function is
applied to

* a 48^3 CT-like volume (:func:`course_lib.scivis.example_volume` ``("ct")``), ray cast by
  :func:`course_lib.scivis.volume_render` into a 96 x 96 image. The opacity is per voxel of
  thickness: a ray through d voxels of opacity :math:`\alpha` keeps :math:`(1 - \alpha)^d` of
  the light behind them, so a small opacity adds up to a solid surface;
* a 2D field (:func:`course_lib.scivis.example_field_2d`, or the middle slice of the volume,
  normalised to [0, 1]), seen as a slab d voxels thick over a checkerboard: each sample's
  colour covers the checkerboard with the opacity :math:`1 - (1 - \alpha)^d` (a slider sets
  d), so transparency is visible.

While a point is dragged the view does not change, and neither do the data values sampled
along its rays: only their classification (value -> colour, opacity) does. The editor samples
the rays of the view once (:class:`RaySamples`, 48 x 48 rays, a sample every voxel) and on
every move only looks them up and composites them; when the point is dropped the volume is ray
cast in full by :func:`course_lib.scivis.volume_render` (96 x 96, a sample every half voxel).
Full renders are cached, so selecting a point or returning to an earlier function is free.
"""
from dataclasses import dataclass, field as _field
from functools import lru_cache

import numpy as np

from .. import colormaps, draw, scivis
from .._validate import as_choice
from . import _style
from ._base import Explorer, align, beside, bind, labelled, panel, slider
from ._drag import DraggablePoints

__all__ = ["FIELDS", "PRESETS", "RaySamples", "State", "TransferFunctionExplorer", "example_data",
           "preset_points", "render", "scene", "transfer"]

PRESETS = ("skin", "bone", "ramp")
FIELDS = ("hills", "ripple", "circle", "saddle", "CT slice")
RECOLOR_MAPS = ("grey", "hot", "viridis", "magma", "cividis", "coolwarm")
FIELD_SIZE = 96
VOLUME_SIZE = 48
IMAGE_SIZE = (96, 96)
PREVIEW_SIZE = (48, 48)
PREVIEW_STEP = 1.0                  # voxels between samples while dragging (full: 0.5)
EXTENT = (-0.95, 0.95, -0.95, 0.95)     # the image window in view coordinates: the whole head
MIN_GAP = 0.005                     # control points stay this far apart (and in order)
BINS = 64
FIGSIZE = (5.6, 4.9)
LUT_SIZE = 1024                     # entries of the preview's classification table
CURVE_SAMPLES = 256


def preset_points(name):
    """The control points of a preset of :func:`course_lib.colormaps.transfer_preset`.

    Returns
    -------
    points : ndarray, shape (n,)
        Normalised data values, increasing.
    colors : ndarray, shape (n, 3)
    opacities : ndarray, shape (n,)
        Per voxel.

    Examples
    --------
    >>> points, colors, opacities = preset_points("bone")
    >>> points.tolist(), opacities.tolist()
    ([0.0, 0.55, 0.75, 0.9, 1.0], [0.0, 0.0, 0.8, 0.8, 1.0])
    """
    as_choice(name, "name", PRESETS)
    tf = colormaps.transfer_preset(name)
    return tf.points.copy(), tf.values[:, :3].copy(), tf.values[:, 3].copy()


def _default(index):
    return lambda: preset_points("skin")[index]


@dataclass
class State:
    """Control points (value, colour, opacity), the 2D field and the thickness (in voxels) of
    the slab it stands for, the selected point, the view.

    Examples
    --------
    >>> s = State()
    >>> len(s.points), s.field, s.preview
    (8, 'hills', False)
    """

    points: np.ndarray = _field(default_factory=_default(0))
    colors: np.ndarray = _field(default_factory=_default(1))
    opacities: np.ndarray = _field(default_factory=_default(2))
    field: str = "hills"
    selected: int = 6
    thickness: float = 10.0
    azimuth: float = -30.0
    elevation: float = 10.0
    preview: bool = False


def transfer(state):
    """The state's RGBA transfer function of normalised data values.

    Examples
    --------
    >>> transfer(State())([0.0, 0.8])
    array([[0.  , 0.  , 0.  , 0.  ],
           [1.  , 1.  , 0.95, 0.3 ]])
    """
    values = np.column_stack([np.asarray(state.colors, float),
                              np.asarray(state.opacities, float)])
    return colormaps.TransferFunction(np.asarray(state.points, float), values)


@lru_cache(maxsize=None)
def example_data(kind="hills"):
    """The explorer's data, normalised to [0, 1]: a 2D field (``kind``) or the CT volume.

    Parameters
    ----------
    kind : str
        One of :data:`FIELDS` (a 96 x 96 field of :func:`course_lib.scivis.example_field_2d`,
        or ``"CT slice"``, the 48 x 48 middle slice z = 0 of the head) or ``"ct"`` (the 48^3
        head phantom).

    Returns
    -------
    course_lib.scivis.Field
        ``values`` normalised with :func:`course_lib.colormaps.normalize`. Cached: do not
        modify it.

    Examples
    --------
    >>> f = example_data("ripple")
    >>> f.values.shape, float(f.values.min()), float(f.values.max())
    ((96, 96), 0.0, 1.0)
    """
    if kind == "ct":
        data = scivis.example_volume("ct", size=VOLUME_SIZE)
    elif kind == "CT slice":
        ct = scivis.example_volume("ct", size=VOLUME_SIZE)
        data = ct._replace(values=ct.values[VOLUME_SIZE // 2], spacing=ct.spacing[:2],
                           origin=ct.origin[:2])
    elif kind in FIELDS:
        data = scivis.example_field_2d(kind, size=FIELD_SIZE)
    else:
        raise ValueError(f"kind must be one of {FIELDS + ('ct',)}, got {kind!r}")
    values = colormaps.normalize(data.values)
    values.flags.writeable = False
    return data._replace(values=values)


def render(tf, volume=None, azimuth=-30.0, elevation=10.0):
    """Ray cast a volume through a transfer function: the editor's 3D view when no point moves.

    Calls :func:`course_lib.scivis.volume_render` with an orthographic view turned by
    `azimuth` and `elevation` (degrees, :func:`course_lib.scivis.view_rotation`) over
    :data:`EXTENT`, 96 x 96 pixels, a sample every half voxel, opacity per voxel, early ray
    termination at 0.99 and a black background. (While a point is dragged the editor uses the
    faster :class:`RaySamples` instead.)

    Parameters
    ----------
    tf : course_lib.colormaps.TransferFunction
        Four channels (r, g, b, opacity) of the volume values.
    volume : course_lib.scivis.Field, optional
        Default: the CT phantom of :func:`example_data`.
    azimuth, elevation : float
        View angles in degrees.

    Returns
    -------
    course_lib.scivis.VolumeImage

    Examples
    --------
    >>> img = render(colormaps.transfer_preset("bone"))
    >>> img.rgb.shape, img.samples > 0
    ((96, 96, 3), True)
    """
    vol = example_data("ct") if volume is None else volume
    voxel = min(vol.spacing)
    return scivis.volume_render(
        vol.values, tf, rotation=scivis.view_rotation(*np.radians([azimuth, elevation])),
        image_size=IMAGE_SIZE, step=0.5 * voxel, spacing=vol.spacing, origin=vol.origin,
        extent=EXTENT, unit_length=voxel)


class RaySamples(scivis.RaySamples):
    r"""The data values along every ray of one view, sampled once: the editor's preview.

    :class:`course_lib.scivis.RaySamples` for the editor's view: orthographic, turned by
    `azimuth` and `elevation` (degrees, :func:`course_lib.scivis.view_rotation`) over
    :data:`EXTENT`, a sample every `step` voxels, the opacity per voxel, a classification
    table of :data:`LUT_SIZE` entries over [0, 1]. While the student drags a control point the
    view stays the same, so the editor samples the rays once and, on every move, only looks
    the samples up in the new transfer function and composites them
    (:meth:`~course_lib.scivis.RaySamples.composite`).

    Parameters
    ----------
    volume : course_lib.scivis.Field
        The volume, values normalised to [0, 1].
    azimuth, elevation : float
        View angles in degrees (:func:`course_lib.scivis.view_rotation`).
    image_size : (int, int)
        (height, width) in pixels.
    step : float
        Distance between samples in voxels.

    Examples
    --------
    >>> rays = RaySamples(example_data("ct"), -30, 10, (8, 8), 2.0)
    >>> img = rays.composite(colormaps.transfer_preset("bone"))
    >>> img.rgb.shape, img.alpha.shape
    ((8, 8, 3), (8, 8))
    """

    def __init__(self, volume, azimuth=-30.0, elevation=10.0, image_size=PREVIEW_SIZE,
                 step=PREVIEW_STEP):
        voxel = float(min(volume.spacing))
        super().__init__(volume.values, scivis.view_rotation(*np.radians([azimuth, elevation])),
                         image_size, float(step) * voxel, volume.spacing, volume.origin,
                         EXTENT, unit_length=voxel, value_range=(0.0, 1.0), lut_size=LUT_SIZE)


@lru_cache(maxsize=8)
def _ray_samples(azimuth, elevation):
    return RaySamples(example_data("ct"), azimuth, elevation)


@lru_cache(maxsize=16)
def _render_cached(key):
    points, values, azimuth, elevation = key
    tf = colormaps.TransferFunction(np.array(points), np.array(values).reshape(len(points), 4))
    return render(tf, None, azimuth, elevation)


def _checkerboard(shape, squares=8, light=0.93, dark=0.78):
    rows, cols = np.indices(shape)
    size = max(1, shape[1] // squares)
    return np.where(((rows // size) + (cols // size)) % 2 == 0, light, dark)


@lru_cache(maxsize=None)
def _histograms(kind):
    edges = np.linspace(0.0, 1.0, BINS + 1)
    out = []
    for data in (example_data(kind).values, example_data("ct").values):
        counts, _ = np.histogram(data, bins=edges)
        logs = np.log10(1.0 + counts)
        out.append(0.95 * logs / logs.max())
    return edges, out[0], out[1]


def _hex(color):
    return "#" + "".join(f"{int(round(255 * c)):02x}" for c in color)


def scene(state):
    """Pure part: the transfer function applied to the 2D field and to the volume.

    Returns
    -------
    dict
        ``transfer`` (the TransferFunction), ``field_rgb`` (the field's colours blended over a
        checkerboard by opacity, 96 x 96 x 3), ``volume`` (the
        :class:`course_lib.scivis.VolumeImage`, 48 x 48 while ``state.preview``, else
        96 x 96), ``curve`` (256 x 2: value, opacity), ``strip`` (1 x 256 x 3: the colour
        ramp), ``handles`` (n x 2: the control points in the editor), ``colors`` (n x 3),
        ``histogram`` (bin edges, field and volume heights: log counts scaled to [0, 0.95])
        and ``text``.

    Examples
    --------
    >>> s = scene(State(preview=True))
    >>> s["field_rgb"].shape, s["volume"].rgb.shape, s["curve"].shape
    ((96, 96, 3), (48, 48, 3), (256, 2))
    """
    tf = transfer(state)
    data = example_data(state.field).values
    rgba = tf(data)
    checker = _checkerboard(data.shape)[..., None]
    alpha = 1.0 - (1.0 - rgba[..., 3:]) ** float(state.thickness)
    field_rgb = alpha * rgba[..., :3] + (1.0 - alpha) * checker
    if state.preview:
        image = _ray_samples(float(state.azimuth), float(state.elevation)).composite(tf)
    else:
        image = _render_cached((tuple(np.round(tf.points, 6)),
                                tuple(np.round(tf.values, 6).ravel()),
                                float(state.azimuth), float(state.elevation)))
    s = np.linspace(0.0, 1.0, CURVE_SAMPLES)
    table = tf(s)
    k = int(min(max(state.selected, 0), len(state.points) - 1))
    a = float(state.opacities[k])
    d = float(state.thickness)
    text = (f"<b>Point {k}</b> at data value s = {state.points[k]:.3f}: colour "
            f"<span style='background:{_hex(state.colors[k])}'>&nbsp;&nbsp;&nbsp;&nbsp;</span> "
            f"{_hex(state.colors[k])}, opacity α = {a:.3f} per voxel. One voxel of it hides "
            f"{100 * a:.0f} % of what lies behind; a slab of {d:g} voxels hides "
            f"1 − (1 − α)<sup>{d:g}</sup> = {100 * (1 - (1 - a) ** d):.0f} % (the 2D view shows "
            "the field as such a slab over a checkerboard).")
    total = image.samples + image.samples_saved
    skipped = "would skip" if state.preview else "skipped"
    text += (f"<br>Ray casting: {image.samples:,} samples; early ray termination {skipped} "
             f"{image.samples_saved:,} ({100 * image.samples_saved / max(total, 1):.0f} %)."
             + (" <i>Preview while dragging: 48 × 48 pixels, a sample every voxel, the rays "
                "sampled once for the view; only classification and compositing are redone.</i>"
                if state.preview else ""))
    return {"transfer": tf, "field_rgb": field_rgb, "volume": image,
            "curve": np.column_stack([s, table[:, 3]]), "strip": table[None, :, :3],
            "handles": np.column_stack([state.points, state.opacities]),
            "colors": np.asarray(state.colors, float), "histogram": _histograms(state.field),
            "text": text}


class TransferFunctionExplorer(Explorer):
    """Drag opacity control points; pick colours, presets and the 2D field; turn the volume.

    In a notebook, after ``%matplotlib widget``, end a cell with
    ``TransferFunctionExplorer()``. Click a point to select it (its value, opacity and colour
    can then also be typed or picked); "add point" splits the segment after the selected one
    without changing the function.

    Examples
    --------
    >>> explorer = TransferFunctionExplorer()
    >>> explorer.preset.value = "bone"
    >>> len(explorer.state.points)
    5
    >>> x, y = explorer.drag.points[2]
    >>> explorer.drag.press(x, y); explorer.drag.move(x, 0.3)
    >>> explorer.state.preview, float(explorer.state.opacities[2])
    (True, 0.3)
    >>> explorer.drag.release()
    >>> explorer.state.preview
    False
    """

    summary = ("Transfer-function editor (interactive): drag the opacity curve's control points, "
               "colour them, choose a preset; the function is applied live to a 2D field and "
               "to a ray-cast CT volume, over the data's histograms.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self._syncing = False
        self.fig = draw.figure(figsize=FIGSIZE)
        grid = self.fig.add_gridspec(3, 2, height_ratios=(3.0, 2.0, 0.22), left=0.1,
                                     right=0.98, bottom=0.09, top=0.95, hspace=0.3,
                                     wspace=0.12)
        field_ax = self.fig.add_subplot(grid[0, 0])
        f = example_data(self.state.field)
        (x0, x1), (y0, y1) = ((a[0], a[-1]) for a in f.axes)
        self.field_image = field_ax.imshow(s["field_rgb"], origin="lower",
                                           extent=(x0, x1, y0, y1), interpolation="bilinear")
        field_ax.set_title("2D field: a slab over a checkerboard")
        field_ax.set(xlabel="x", ylabel="y", xticks=[x0, (x0 + x1) / 2, x1],
                     yticks=[y0, (y0 + y1) / 2, y1])
        volume_ax = self.fig.add_subplot(grid[0, 1])
        self.volume_image = volume_ax.imshow(s["volume"].rgb, origin="lower",
                                             extent=(0, 1, 0, 1), interpolation="bilinear")
        volume_ax.set_title("volume (ray casting)")
        volume_ax.set_axis_off()
        self.volume_ax = volume_ax
        ax = self.fig.add_subplot(grid[1, :])
        ax.set(xlim=(-0.015, 1.015), ylim=(-0.04, 1.06), ylabel="opacity α",
               yticks=[0, 0.5, 1])
        ax.tick_params(labelbottom=False)
        ax.grid(True, color="0.92")
        edges, field_hist, volume_hist = s["histogram"]
        self.volume_hist = ax.stairs(volume_hist, edges, fill=True, color="0.82",
                                     label="histogram: CT volume (log)")
        self.field_hist = ax.stairs(field_hist, edges, color="#1f77b4", lw=1.2,
                                    label="histogram: 2D field (log)")
        (self.fill,) = ax.fill([0, 1], [0, 0], color="#ff7f0e", alpha=0.15, lw=0)
        (self.curve,) = ax.plot([], [], color="#c45500", lw=2, label="opacity α(s)")
        self.handles = ax.scatter(s["handles"][:, 0], s["handles"][:, 1], s=70,
                                  c=s["colors"], edgecolors="0.1", linewidths=1.2, zorder=5)
        (self.selected,) = ax.plot([], [], "o", ms=14, mfc="none", mec="#d62728", mew=2,
                                   zorder=6)
        _style.legend(ax, loc="upper left", framealpha=0.85, handlelength=1.2, borderpad=0.3,
                      labelspacing=0.2)
        self.ax = ax
        strip_ax = self.fig.add_subplot(grid[2, :], sharex=ax)
        self.strip = strip_ax.imshow(s["strip"], aspect="auto", extent=(0, 1, 0, 1),
                                     interpolation="nearest")
        strip_ax.set(yticks=[], xlabel="normalised data value s (the strip: colour c(s))")
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.field_image, self.volume_image, self.fill,
                                               self.curve, self.handles, self.selected,
                                               self.strip])
        self.drag = DraggablePoints(ax, s["handles"], self._on_drag, radius=10,
                                    on_press=self._on_pick, on_release=self._on_release)

        self.preset = labelled(w.Dropdown, "preset", options=("custom",) + PRESETS,
                               value="skin")
        self.field = labelled(w.Dropdown, "2D field", options=FIELDS, value=self.state.field)
        self.point = slider("point", self.state.selected, 0, len(self.state.points) - 1, 1,
                            kind=w.IntSlider)
        self.value = slider("value s", 0, 0, 1, 0.005, continuous_update=False,
                            readout_format=".3f")
        self.opacity = slider("opacity α", 0, 0, 1, 0.005, continuous_update=False,
                              readout_format=".3f")
        self.color = labelled(w.ColorPicker, "colour")
        self.thickness = slider("2D slab d", self.state.thickness, 1, 30, 1,
                                continuous_update=False)
        self.azimuth = slider("view azimuth °", self.state.azimuth, -180, 180, 5,
                              continuous_update=False)
        column = align([self.preset, self.field, self.point, self.value, self.opacity,
                        self.color, self.thickness, self.azimuth])
        width = column[0].layout.width
        self.recolor = w.Dropdown(options=("colour all points from a map…",) + RECOLOR_MAPS,
                                  layout=w.Layout(width=width))
        button = w.Layout(width=_style.button_width("add point", "remove point"))
        add = w.Button(description="add point", layout=button)
        remove = w.Button(description="remove point", layout=button)
        add.on_click(lambda _: self.add_point())
        remove.on_click(lambda _: self.remove_point())
        self.preset.observe(self._on_preset, names="value")
        self.field.observe(self._on_field, names="value")
        self.point.observe(self._on_point, names="value")
        for control in (self.value, self.opacity, self.color):
            control.observe(self._on_edit, names="value")
        self.recolor.observe(self._on_recolor, names="value")
        bind(self.state, {"azimuth": self.azimuth, "thickness": self.thickness}, self.update)
        self.info = panel(width=width)
        controls = w.VBox([self.preset, self.field, self.point, self.value, self.opacity,
                           self.color, w.HBox([add, remove]), self.recolor, self.thickness,
                           self.azimuth,
                           self.info])
        self.widget = beside(self.fig.canvas, controls, align="flex-start")
        self._sync_controls()
        self._draw(s)

    # --- editing ----------------------------------------------------------------------------
    def _sync_controls(self):
        """Show the selected point's values in the controls (without triggering edits)."""
        k = self.state.selected
        self._syncing = True
        try:
            with self.point.hold_sync():
                self.point.max = len(self.state.points) - 1
                self.point.value = k
            self.value.value = float(self.state.points[k])
            self.opacity.value = float(self.state.opacities[k])
            self.color.value = _hex(self.state.colors[k])
        finally:
            self._syncing = False

    def _custom(self):
        self._syncing = True
        try:
            self.preset.value = "custom"
        finally:
            self._syncing = False

    def _set_points(self, points, colors, opacities, selected):
        self.state.points = np.array(points, float)
        self.state.colors = np.array(colors, float)
        self.state.opacities = np.array(opacities, float)
        self.state.selected = int(min(max(selected, 0), len(points) - 1))
        self.drag.set_points(np.column_stack([self.state.points, self.state.opacities]))
        self._sync_controls()
        self.update()

    def _clamp_value(self, k, value):
        pts = self.state.points
        lo = pts[k - 1] + MIN_GAP if k > 0 else 0.0
        hi = pts[k + 1] - MIN_GAP if k < len(pts) - 1 else 1.0
        return float(min(max(value, lo), hi))

    def add_point(self):
        """Split the segment after the selected point (before it, for the last point) by a new
        point on the current function: nothing changes until it is moved."""
        pts, k = self.state.points, self.state.selected
        if len(pts) >= 16:
            return
        i = k if k < len(pts) - 1 else k - 1
        if pts[i + 1] - pts[i] < 2 * MIN_GAP:
            return
        s = 0.5 * (pts[i] + pts[i + 1])
        rgba = transfer(self.state)(s)
        self._custom()
        self._set_points(np.insert(pts, i + 1, s),
                         np.insert(self.state.colors, i + 1, rgba[:3], axis=0),
                         np.insert(self.state.opacities, i + 1, rgba[3]), i + 1)

    def remove_point(self):
        """Remove the selected point (two always stay)."""
        if len(self.state.points) <= 2:
            return
        k = self.state.selected
        self._custom()
        self._set_points(np.delete(self.state.points, k),
                         np.delete(self.state.colors, k, axis=0),
                         np.delete(self.state.opacities, k), min(k, len(self.state.points) - 2))

    # --- events -----------------------------------------------------------------------------
    def _on_pick(self, index):
        self.state.selected = index
        self._sync_controls()

    def _on_drag(self, index, xy):
        s = self._clamp_value(index, xy[0])
        a = float(min(max(xy[1], 0.0), 1.0))
        self.state.points = self.state.points.copy()
        self.state.opacities = self.state.opacities.copy()
        self.state.points[index], self.state.opacities[index] = s, a
        self.drag.points[index] = (s, a)
        self.state.selected = index
        self.state.preview = True
        if self.preset.value != "custom":
            self._custom()
        self.update()

    def _on_release(self):
        self.state.preview = False
        self._sync_controls()
        self.update()

    def _on_preset(self, change):
        if self._syncing or change["new"] == "custom":
            return
        points, colors, opacities = preset_points(change["new"])
        self._set_points(points, colors, opacities, len(points) - 2)

    def _on_field(self, change):
        self.state.field = change["new"]
        self.update()

    def _on_point(self, change):
        if self._syncing:
            return
        self.state.selected = change["new"]
        self._sync_controls()
        self.update()

    def _on_edit(self, change):
        if self._syncing:
            return
        k = self.state.selected
        points, colors = self.state.points.copy(), self.state.colors.copy()
        opacities = self.state.opacities.copy()
        if change["owner"] is self.value:
            points[k] = self._clamp_value(k, change["new"])
        elif change["owner"] is self.opacity:
            opacities[k] = change["new"]
        else:
            hex_value = change["new"].lstrip("#")
            if len(hex_value) != 6:
                return
            colors[k] = [int(hex_value[i:i + 2], 16) / 255 for i in (0, 2, 4)]
        self._custom()
        self._set_points(points, colors, opacities, k)

    def _on_recolor(self, change):
        if self._syncing or change["new"] not in RECOLOR_MAPS:
            return
        colors = colormaps.apply_colormap(self.state.points, change["new"], in_range=(0, 1))
        self._syncing = True
        try:
            self.recolor.value = self.recolor.options[0]
        finally:
            self._syncing = False
        self._custom()
        self._set_points(self.state.points, colors, self.state.opacities, self.state.selected)

    def update(self):
        """Recompute the scene and update the drawn artists (blitting)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.field_image.set_data(s["field_rgb"])
        self.volume_image.set_data(s["volume"].rgb)
        curve = s["curve"]
        self.curve.set_data(*curve.T)
        self.fill.set_xy(np.vstack([[0, 0], curve, [1, 0]]))
        self.handles.set_offsets(s["handles"])
        self.handles.set_facecolors(s["colors"])
        k = self.state.selected
        self.selected.set_data([s["handles"][k, 0]], [s["handles"][k, 1]])
        self.strip.set_data(s["strip"])
        edges, field_hist, volume_hist = s["histogram"]
        if not np.array_equal(self.field_hist.get_data().values, field_hist):
            self.field_hist.set_data(field_hist, edges)
            self.blitter.forget_background()
        self.info.value = s["text"]
