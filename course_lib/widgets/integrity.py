r"""Graphical-integrity explorer: the same yearly values drawn honestly and with a distortion,
the lie factor computed live, and a line chart at its banked aspect ratio.

Left, the values as bars from 0 (the dashed red line marks where a truncated axis would start).
Middle, the same values with the chosen distortion:

* **truncated axis**: bars from the baseline :math:`b` (the slider); lie factor
  :math:`v_1 / (v_1 - b)`;
* **3D bars**: bars seen in perspective, each earlier one :data:`RECESSION` further away, so
  that the later, nearer bars are drawn larger (:func:`course_lib.dataviz.drawn_sizes`,
  ``"perspective"``);
* **circles, radius ∝ value**: the eye compares areas, which grow with the square;
* **icons, both sides ∝ value**: the same for a picture scaled in width and height.

The title gives the lie factor (:func:`course_lib.dataviz.encoding_lie_factor`) between the
first and the last year, red when it is outside Tufte's 0.95-1.05. Right, a monthly series of
the same quantity in a frame of the chosen aspect ratio: banked to 45 degrees
(:func:`course_lib.dataviz.bank_to_45`, average absolute orientation), square, too flat or too
tall, with the mean absolute orientation of its segments on screen.

All data are invented for illustration.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import dataviz, draw
from .._validate import as_choice
from . import _style
from ._base import Explorer, labelled, panel, set_range, slider

__all__ = ["ASPECTS", "DATASETS", "DISTORTIONS", "GraphicalIntegrityExplorer", "State",
           "scene", "series_of"]

#: The data sets: name -> (title, unit, first year, yearly values, default baseline).
DATASETS = {
    "library budget": ("City library budget", "million €", 2019, (40.0, 42.0, 45.0, 47.0, 50.0),
                       35.0),
    "exam pass rate": ("Exam pass rate", "%", 2018, (81.0, 82.0, 84.0, 83.0, 85.0, 87.0), 75.0),
    "electric cars": ("Electric cars sold", "thousands", 2017,
                      (12.0, 18.0, 25.0, 34.0, 48.0, 60.0), 10.0),
}
#: The distortions of the middle picture and the encoding each uses.
DISTORTIONS = {"truncated axis": "bar", "3D bars": "perspective",
               "circles, radius ∝ value": "radius", "icons, both sides ∝ value": "icon"}
#: The aspect ratios of the right picture: name -> height / width (None: banked).
ASPECTS = {"banked to 45°": None, "square 1:1": 1.0, "flat 1:4": 0.25, "tall 4:1": 4.0}
#: How much further away each earlier 3D bar is (distance 1 + RECESSION (n - 1 - k)).
RECESSION = 0.25
#: The region of a bar chart in its panel (the panels span [0, 1] x [0, 1]).
X0, X1, Y0, Y1 = 0.16, 0.98, 0.1, 0.86
MAX_BARS = 8
MAX_TICKS = 7
_BLUE, _RED = "#1f77b4", "#c62828"


@dataclass
class State:
    """The data set, the distortion, the truncated axis' baseline and the line chart's aspect.

    Examples
    --------
    >>> State().distortion, State().baseline
    ('truncated axis', 35.0)
    """

    dataset: str = "library budget"
    distortion: str = "truncated axis"
    baseline: float = 35.0
    aspect: str = "banked to 45°"


def _ticks(lo, hi, count=5):
    """Round tick values from lo to at least hi, about `count` of them."""
    raw = (hi - lo) / count
    decade = 10.0 ** np.floor(np.log10(raw))
    step = next(m * decade for m in (1, 2, 2.5, 5, 10) if m * decade >= raw - 1e-12)
    start = np.floor(lo / step + 1e-9) * step
    stop = np.ceil(hi / step - 1e-9) * step
    return np.round(np.arange(start, stop + step / 2, step), 10)


def _max_baseline(values):
    """The highest baseline the slider offers: a little below the smallest value."""
    return float(np.floor(0.95 * min(values)))


@lru_cache(maxsize=None)
def series_of(dataset):
    """The monthly series of a data set (for the aspect ratio picture): the yearly values
    interpolated, with a seasonal swing and a little seeded noise.

    Examples
    --------
    >>> t, y = series_of("library budget")
    >>> len(t), round(float(t[0]), 3)
    (49, 2019.0)
    """
    _, _, first, values, _ = DATASETS[as_choice(dataset, "dataset", tuple(DATASETS))]
    years = first + np.arange(len(values))
    t = np.linspace(years[0], years[-1], 12 * (len(values) - 1) + 1)
    span = max(values) - min(values)
    rng = np.random.default_rng(len(values) * 100 + int(values[0]))
    y = (np.interp(t, years, values) + 0.12 * span * np.sin(2 * np.pi * (t - first))
         + rng.normal(0.0, 0.03 * span, t.size))
    return t, y


@lru_cache(maxsize=None)
def _banked(dataset):
    t, y = series_of(dataset)
    return dataviz.bank_to_45(t, y), dataviz.bank_to_45(t, y, "median")


def _bar_polys(values, lo, hi, n):
    """Rectangles of bars from `lo` in a chart whose value axis runs from lo to hi."""
    slot = (X1 - X0) / n
    centres = X0 + slot * (np.arange(n) + 0.5)
    tops = Y0 + (np.asarray(values) - lo) / (hi - lo) * (Y1 - Y0)
    half = 0.3 * slot
    return [np.array([[c - half, Y0], [c + half, Y0], [c + half, t], [c - half, t]])
            for c, t in zip(centres, tops)], centres, tops


def _perspective_polys(values, top, n):
    """3D bars in perspective: front, top and side face of each, far ones first.

    Bar k is at the distance ``1 + RECESSION (n - 1 - k)``: its width, height and depth are
    divided by it, and its foot rises towards the horizon as it recedes."""
    distance = 1.0 + RECESSION * (n - 1 - np.arange(n))
    slot = (X1 - X0) / n
    polys, colours, fronts, feet = [], [], [], []
    for k in range(n):
        scale = 1.0 / distance[k]
        w = 0.55 * slot * scale
        h = values[k] / top * (Y1 - Y0 - 0.06) * scale
        d = np.array([0.3, 0.2]) * slot * scale
        a = np.array([X0 + slot * (k + 0.2), Y0 + 0.3 * (1.0 - scale)])
        b, c, e = a + [w, 0], a + [w, h], a + [0, h]
        polys += [np.array([e, c, c + d, e + d]), np.array([b, b + d, c + d, c]),
                  np.array([a, b, c, e])]
        colours += ["#8fbbe0", "#135a8c", _BLUE]
        fronts.append((float(a[0] + w / 2), float(h), float(c[1]), float(a[1])))
        feet.append((a - 0.2 * d, b + 1.2 * d))
    floor = np.array([feet[0][0], feet[-1][0], [feet[-1][1][0], feet[-1][0][1]],
                      feet[-1][1], feet[0][1]])
    return [floor] + polys, ["0.9"] + colours, fronts


def _shape_polys(values, kind):
    """The first and the last value as circles (radius ~ value) or house icons (both sides ~
    value), side by side, bottom-aligned, the widths sharing the panel."""
    pair = np.array([values[0], values[-1]])
    gap = 0.06
    widths = (X1 - X0 - gap) * pair / pair.sum()
    scale = min(1.0, (Y1 - Y0 - 0.06) / (widths.max() * (1.0 if kind == "radius" else 1.1)))
    widths = widths * scale
    lefts = X0 + (X1 - X0 - widths.sum() - gap) / 2 + np.array([0.0, widths[0] + gap])
    polys, centres, tops, sizes = [], lefts + widths / 2, [], []
    for c, wd in zip(centres, widths):
        if kind == "radius":
            r = wd / 2
            t = np.linspace(0, 2 * np.pi, 64, endpoint=False)
            polys.append(np.column_stack([c + r * np.cos(t), Y0 + r + r * np.sin(t)]))
            tops.append(Y0 + 2 * r)
            sizes.append(np.pi * r * r)
        else:
            h = 1.1 * wd
            house = np.array([[-0.5, 0], [0.5, 0], [0.5, 0.62], [0, 1], [-0.5, 0.62]])
            polys.append(np.column_stack([c + wd * house[:, 0], Y0 + h * house[:, 1]]))
            tops.append(Y0 + h)
            sizes.append(0.81 * wd * h)                # the house's area (0.81 of its box)
    return polys, centres, np.array(tops), np.array(sizes)


def _fmt(v):
    return f"{v:g}"


def scene(state):
    """Pure part: the polygons, ticks and labels of both bar pictures, the lie factor, the
    framed line chart, and the text.

    Returns a dict: ``"values"``, ``"years"``, ``"honest"`` and ``"distorted"`` (each with
    ``"polys"``, ``"colors"``, ``"ticks"`` [(y, label)], ``"labels"`` [(x, y, text)]; the
    distorted one also ``"sizes"``, the drawn sizes the eye compares), ``"baseline_y"`` (the
    dashed line of the honest picture), ``"lie_factor"``, ``"effects"`` (data, shown),
    ``"aspect"`` (``"alpha"``, ``"frame"``, ``"line"``, ``"mean_angle"`` in degrees,
    ``"banked"``, ``"median"``), ``"title"``, ``"text"``. A baseline above
    :func:`_max_baseline` is clamped to it.

    Examples
    --------
    >>> s = scene(State(baseline=30))
    >>> round(s["lie_factor"], 6)                   # 40 / (40 - 30)
    4.0
    >>> round(scene(State(aspect="banked to 45°"))["aspect"]["mean_angle"], 6)
    45.0
    """
    dataset = as_choice(state.dataset, "dataset", tuple(DATASETS))
    distortion = as_choice(state.distortion, "distortion", tuple(DISTORTIONS))
    aspect_name = as_choice(state.aspect, "aspect", tuple(ASPECTS))
    title, unit, first, values, _ = DATASETS[dataset]
    values = np.array(values)
    n = len(values)
    years = [str(first + k) for k in range(n)]
    baseline = float(np.clip(state.baseline, 0.0, _max_baseline(values)))
    encoding = DISTORTIONS[distortion]

    # honest bars from 0
    ticks0 = _ticks(0.0, values.max())
    top0 = float(ticks0[-1])
    polys, centres, tops = _bar_polys(values, 0.0, top0, n)
    short = [y[2:] if n > 5 else y for y in years]
    honest = {"polys": polys, "colors": [_BLUE] * n,
              "ticks": [(Y0 + t / top0 * (Y1 - Y0), _fmt(t)) for t in ticks0],
              "labels": [(c, t + 0.015, _fmt(v)) for c, t, v in zip(centres, tops, values)],
              "years": [(c, Y0 - 0.02, y) for c, y in zip(centres, short)]}
    baseline_y = Y0 + baseline / top0 * (Y1 - Y0)

    # the distortion
    shown = values
    if encoding == "bar":
        ticks = _ticks(baseline, values.max())
        ticks = ticks[ticks >= baseline - 1e-9]
        top = float(ticks[-1])
        if ticks[0] > baseline + 1e-9:
            ticks = np.r_[baseline, ticks]
        polys, centres, tops = _bar_polys(values, baseline, top, n)
        colors = [_BLUE] * n
        sizes = tops - Y0
        tick_list = [(Y0 + (t - baseline) / (top - baseline) * (Y1 - Y0), _fmt(t))
                     for t in ticks]
        label_xy = list(zip(centres, tops))
        year_xy = [(c, Y0 - 0.02) for c in centres]
    elif encoding == "perspective":
        polys, colors, fronts = _perspective_polys(values, top0, n)
        sizes = np.array([h for _, h, _, _ in fronts])
        tick_list = []
        label_xy = [(x, y) for x, _, y, _ in fronts]
        year_xy = [(x, foot - 0.02) for x, _, _, foot in fronts]
    else:
        polys, centres, tops, sizes = _shape_polys(values, encoding)
        colors = [_BLUE] * 2
        tick_list = []
        label_xy = list(zip(centres, tops))
        year_xy = [(c, Y0 - 0.02) for c in centres]
        shown = values[[0, -1]]
        short = [years[0], years[-1]]
    distorted = {"polys": polys, "colors": colors, "ticks": tick_list, "sizes": sizes,
                 "labels": [(x, y + 0.015, _fmt(v)) for (x, y), v in zip(label_xy, shown)],
                 "years": [(x, y, t) for (x, y), t in zip(year_xy, short)]}
    lie = dataviz.encoding_lie_factor(values, encoding,
                                      baseline=baseline if encoding == "bar" else 0.0,
                                      recession=RECESSION)
    effect_data = dataviz.relative_change(values[0], values[-1])
    effect_shown = dataviz.relative_change(sizes[0], sizes[-1])

    # the line chart in a frame of the chosen aspect ratio
    banked, median = _banked(dataset)
    alpha = banked if ASPECTS[aspect_name] is None else ASPECTS[aspect_name]
    width, height = (0.84, 0.84 * alpha) if alpha <= 1 else (0.84 / alpha, 0.84)
    x0, y0 = 0.5 - width / 2, 0.47 - height / 2
    t, y = series_of(dataset)
    u = x0 + (t - t.min()) / np.ptp(t) * width
    w = y0 + (y - y.min()) / np.ptp(y) * height
    frame = np.array([[x0, y0], [x0 + width, y0], [x0 + width, y0 + height], [x0, y0 + height],
                      [x0, y0]])
    angles = np.degrees(np.arctan2(np.abs(np.diff(w)), np.abs(np.diff(u))))
    mean_angle = float(angles.mean())

    distorting = abs(lie - 1) > 0.05
    colour = _RED if distorting else "#2e7d32"
    size_word = {"bar": "bar lengths above the axis start", "perspective":
                 "drawn heights of the front faces", "radius": "circle areas (π r²)",
                 "icon": "icon areas (width × height)"}[encoding]
    text = (f"<b>{title}</b> ({unit}), {years[0]} → {years[-1]}: {_fmt(values[0])} → "
            f"{_fmt(values[-1])}, a change of <b>{100 * effect_data:.0f} %</b>. "
            f"{distortion.capitalize()}: the {size_word} change by "
            f"<b>{100 * effect_shown:.0f} %</b>. Lie factor = {100 * effect_shown:.0f} % / "
            f"{100 * effect_data:.0f} % = <b style='color:{colour}'>{lie:.2f}</b>"
            + (" (Tufte: outside 0.95-1.05 is a substantial distortion)." if distorting
               else " (honest).")
            + f"<br>Line chart: aspect ratio h/w = {alpha:.3g}, mean |angle| of the segments "
            f"{mean_angle:.1f}° (banked to 45°: {banked:.3g} by the average orientation, "
            f"{median:.3g} by the median slope).")
    return {"values": values, "years": years, "honest": honest, "distorted": distorted,
            "baseline": baseline, "baseline_y": baseline_y, "lie_factor": float(lie),
            "effects": (effect_data, effect_shown),
            "aspect": {"alpha": alpha, "frame": frame, "line": np.column_stack([u, w]),
                       "mean_angle": mean_angle, "banked": banked, "median": median},
            "title": f"{title} ({unit})", "text": text}


class GraphicalIntegrityExplorer(Explorer):
    """Data set, distortion, axis start and aspect ratio: the honest and the distorted chart,
    the lie factor, and a banked line chart.

    In a notebook, after ``%matplotlib widget``, end a cell with
    ``GraphicalIntegrityExplorer()``.

    Examples
    --------
    >>> explorer = GraphicalIntegrityExplorer()
    >>> explorer.baseline.value = 20.0
    >>> explorer.lie_title.get_text().splitlines()[0]
    'lie factor 2.00'
    """

    summary = ("Graphical-integrity explorer (interactive): yearly values drawn honestly and "
               "with a truncated axis, 3D bars, circles or icons, the lie factor computed "
               "live, and a line chart banked to 45 degrees.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection, PolyCollection

        self.state = state or State()
        self.fig = draw.figure(figsize=(7.8, 3.1), dpi=_style.DPI)
        boxes = ((0.0, 0.06, 0.32, 0.76), (0.335, 0.06, 0.32, 0.76), (0.675, 0.06, 0.32, 0.76))
        self.axes = [self.fig.add_axes(b) for b in boxes]
        for ax in self.axes:
            ax.set(xlim=(0, 1), ylim=(0, 1), aspect="equal")
            ax.axis("off")
        self.artists = {}
        moving = []
        for name, ax in zip(("honest", "distorted"), self.axes[:2]):
            grid = LineCollection([], colors="0.85", lw=0.8, zorder=1)
            polys = PolyCollection([], edgecolors="white", linewidths=0.6, zorder=2)
            ax.add_collection(grid)
            ax.add_collection(polys)
            axis = ax.plot([X0, X0], [Y0, Y1], color="0.3", lw=1, zorder=3)[0]
            ticks = [ax.text(X0 - 0.02, 0, "", ha="right", va="center", fontsize=_style.TICK,
                             zorder=3) for _ in range(MAX_TICKS)]
            labels = [ax.text(0, 0, "", ha="center", va="bottom", fontsize=_style.TICK - 1,
                              zorder=4) for _ in range(MAX_BARS)]
            years = [ax.text(0, 0, "", ha="center", va="top", fontsize=_style.TICK - 1,
                             zorder=3) for _ in range(MAX_BARS)]
            ax.plot([X0, X1], [Y0, Y0], color="0.3", lw=1, zorder=3)
            self.artists[name] = {"grid": grid, "polys": polys, "axis": axis, "ticks": ticks,
                                  "labels": labels, "years": years}
            moving += [grid, polys, axis, *ticks, *labels, *years]
        (self.baseline_line,) = self.axes[0].plot([], [], color=_RED, ls="--", lw=1.2, zorder=5)
        self.honest_title = self.axes[0].set_title("", fontsize=_style.TITLE)
        self.lie_title = self.axes[1].set_title("", fontsize=_style.TITLE)
        ax = self.axes[2]
        (self.frame_line,) = ax.plot([], [], color="0.4", lw=1)
        (self.series_line,) = ax.plot([], [], color=_BLUE, lw=1.1)
        self.aspect_title = ax.set_title("", fontsize=_style.TITLE)
        moving += [self.baseline_line, self.honest_title, self.lie_title, self.frame_line,
                   self.series_line, self.aspect_title]
        self.blitter = draw.Blitter(self.fig, moving)

        self.dataset = labelled(w.Dropdown, "data", options=list(DATASETS),
                                value=self.state.dataset)
        self.distortion = labelled(w.Dropdown, "distortion", options=list(DISTORTIONS),
                                   value=self.state.distortion)
        values = DATASETS[self.state.dataset][3]
        self.baseline = slider("axis starts at", self.state.baseline, 0,
                               _max_baseline(values), 1)
        self.aspect = labelled(w.Dropdown, "line chart", options=list(ASPECTS),
                               value=self.state.aspect)
        for control in (self.distortion, self.baseline, self.aspect):
            control.observe(self._on_change, names="value")
        self.dataset.observe(self._on_dataset, names="value")
        self.info = panel(width="720px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([w.VBox([self.dataset, self.distortion]),
                                      w.VBox([self.baseline, self.aspect])],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._draw(scene(self.state))

    def _read(self):
        self.state.dataset = self.dataset.value
        self.state.distortion = self.distortion.value
        self.state.baseline = float(self.baseline.value)
        self.state.aspect = self.aspect.value

    def _on_change(self, change=None):
        self._read()
        self.update()

    def _on_dataset(self, change):
        """A new data set: the slider's range follows its smallest value, its value the data
        set's default baseline (one update, after both are set)."""
        name = change["new"]
        self.baseline.unobserve(self._on_change, names="value")
        try:
            set_range(self.baseline, 0, _max_baseline(DATASETS[name][3]), 1,
                      value=DATASETS[name][4])
        finally:
            self.baseline.observe(self._on_change, names="value")
        self._on_change()

    def update(self):
        """Recompute the scene and redraw the moving artists (blitted)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        for name in ("honest", "distorted"):
            part, art = s[name], self.artists[name]
            art["polys"].set_verts(part["polys"])
            art["polys"].set_facecolor(part["colors"])
            ticks = part["ticks"]
            art["grid"].set_segments([[(X0, y), (X1, y)] for y, _ in ticks])
            art["axis"].set_visible(bool(ticks))
            for k, text in enumerate(art["ticks"]):
                if k < len(ticks):
                    text.set_position((X0 - 0.02, ticks[k][0]))
                    text.set_text(ticks[k][1])
                text.set_visible(k < len(ticks))
            for pool, items in ((art["labels"], part["labels"]), (art["years"], part["years"])):
                for k, text in enumerate(pool):
                    if k < len(items):
                        x, y, words = items[k]
                        text.set_position((x, y))
                        text.set_text(words)
                    text.set_visible(k < len(items))
        self.baseline_line.set_data([X0 - 0.01, X1], [s["baseline_y"]] * 2)
        self.honest_title.set_text(f"{s['title']}\nhonest: bars from 0")
        lie = s["lie_factor"]
        data_e, shown_e = s["effects"]
        sign = 1 if s["values"][-1] >= s["values"][0] else -1
        self.lie_title.set_text(f"lie factor {lie:.2f}\n"
                                f"drawn {sign * 100 * shown_e:+.0f} % for data "
                                f"{sign * 100 * data_e:+.0f} %")
        self.lie_title.set_color(_RED if abs(lie - 1) > 0.05 else "#2e7d32")
        a = s["aspect"]
        self.frame_line.set_data(a["frame"][:, 0], a["frame"][:, 1])
        self.series_line.set_data(a["line"][:, 0], a["line"][:, 1])
        self.aspect_title.set_text(f"monthly, h/w = {a['alpha']:.2g}\n"
                                   f"mean |angle| {a['mean_angle']:.0f}°")
        self.info.value = s["text"]
