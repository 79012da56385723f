"""What the 2D clipping visualizers share: the clip window, its figure, the step controls."""
import numpy as np

from .. import clipping, draw

BOX_MIN = np.array([-1.0, -1.0])
BOX_MAX = np.array([1.5, 1.0])
LIMITS = (-3.0, 3.0)


def window_figure(title, figsize=(4.6, 4.6), regions=False):
    """A figure with the clip window drawn (and, optionally, the 9 outcode regions labelled)."""
    fig = draw.figure(figsize=figsize)
    ax = fig.add_subplot()
    fig.subplots_adjust(left=0.11, right=0.98, bottom=0.1, top=0.93)
    draw.setup_axes_2d(ax, LIMITS, title=title, grid=False)
    (x0, y0), (x1, y1) = BOX_MIN, BOX_MAX
    ax.fill([x0, x1, x1, x0], [y0, y0, y1, y1], color="#e8f3e8", zorder=0)
    ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], color="#2e7d32", lw=1.5, zorder=2)
    if regions:
        for x in (x0, x1):
            ax.axvline(x, color="#2e7d32", lw=0.6, ls=":", zorder=1)
        for y in (y0, y1):
            ax.axhline(y, color="#2e7d32", lw=0.6, ls=":", zorder=1)
        xs = ((LIMITS[0] + x0) / 2, (x0 + x1) / 2, (x1 + LIMITS[1]) / 2)
        ys = ((LIMITS[0] + y0) / 2, (y0 + y1) / 2, (y1 + LIMITS[1]) / 2)
        for x in xs:
            for y in ys:
                code = clipping.outcode([x, y], BOX_MIN, BOX_MAX)
                ax.text(x, y, format(code, "04b"), ha="center", va="center", fontsize=10,
                        color="0.55", family="monospace", zorder=1)
    return fig, ax


def step_controls(on_step, count):
    """An integer step slider with back/forward buttons: ``(slider, box)``. A button that
    cannot move (back at the first step, forward at the last) is greyed out."""
    import ipywidgets as w

    slider = w.IntSlider(value=count - 1, min=0, max=max(count - 1, 0), description="step",
                         continuous_update=True, layout=w.Layout(width="300px"))
    back = w.Button(icon="step-backward", tooltip="previous step", layout=w.Layout(width="40px"))
    forward = w.Button(icon="step-forward", tooltip="next step", layout=w.Layout(width="40px"))
    back.on_click(lambda _: setattr(slider, "value", max(slider.value - 1, slider.min)))
    forward.on_click(lambda _: setattr(slider, "value", min(slider.value + 1, slider.max)))

    def at_the_ends(change=None):
        back.disabled = slider.value <= slider.min
        forward.disabled = slider.value >= slider.max
    slider.observe(at_the_ends, names=["value", "max"])
    at_the_ends()
    slider.observe(on_step, names="value")
    return slider, w.HBox([back, slider, forward])


def set_step_count(slider, count):
    """Give the step slider `count` steps, keeping its value when it still fits."""
    value = min(slider.value, count - 1)
    with slider.hold_sync():                  # the browser gets the new range and value at once
        slider.max = max(count - 1, 0)
        slider.value = value
