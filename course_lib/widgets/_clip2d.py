"""What the 2D clipping visualizers share: the clip window, its figure, the step controls, and
:class:`StepExplorer`, their wiring (drag the input, step through the algorithm)."""
import numpy as np

from .. import clipping, draw
from . import _style
from ._base import Explorer, beside, labelled, panel
from ._drag import DraggablePoints

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
                ax.text(x, y, format(code, "04b"), ha="center", va="center", fontsize=_style.LABEL,
                        color="0.55", family="monospace", zorder=1)
    _style.style_axes(ax)
    return fig, ax


def step_controls(on_step, count):
    """An integer step slider with back/forward buttons: ``(slider, box)``. A button that
    cannot move (back at the first step, forward at the last) is greyed out."""
    import ipywidgets as w

    slider = labelled(w.IntSlider, "step", value=count - 1, min=0, max=max(count - 1, 0),
                      continuous_update=True)
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


class StepExplorer(Explorer):
    """Base of the step-by-step clipping visualizers: the student drags the input's points and
    steps through the algorithm with a slider and back/forward buttons, next to the pseudocode.

    A subclass draws its figure and artists (``self.fig``, ``self.blitter``), then calls
    :meth:`_wire`, and defines what differs: :meth:`_scene` (its module's ``scene``),
    :meth:`_step_count`, :meth:`_draw`, and, if its points are not ``p0`` and ``p1`` of the
    state, :meth:`_move`.

    Examples
    --------
    >>> from course_lib.widgets.cohen_sutherland import CohenSutherlandExplorer
    >>> explorer = CohenSutherlandExplorer()
    >>> isinstance(explorer, StepExplorer), explorer.step.value == explorer.step.max
    (True, True)
    """

    def _wire(self, ax, points, info_width):
        """Make `points` of `ax` draggable, add the step controls (at the last step) and the
        pseudocode panel `info_width` wide, build ``self.widget`` and draw the scene."""
        import ipywidgets as w

        self.drag = DraggablePoints(ax, points, self._on_drag)
        count = self._step_count()
        self.step, controls = step_controls(self._on_step, count)
        self.step.value = self.state.step = count - 1
        self.info = panel(width=info_width)
        self.widget = beside(self.fig.canvas, w.VBox([controls, self.info]), align="flex-start")
        self._draw(self._scene())

    def _scene(self):  # pragma: no cover - every subclass overrides it
        """The pure scene of the current state."""
        raise NotImplementedError

    def _step_count(self):  # pragma: no cover - every subclass overrides it
        """How many steps the step slider offers for the current state."""
        raise NotImplementedError

    def _draw(self, s):  # pragma: no cover - every subclass overrides it
        """Move the drawn artists to scene `s` and show its text."""
        raise NotImplementedError

    def _move(self, index, xy):
        """Point `index` was dragged to `xy`: store it in the state (end point p0 or p1)."""
        setattr(self.state, f"p{index}", xy)

    def _on_drag(self, index, xy):
        self._move(index, xy)
        set_step_count(self.step, self._step_count())
        self.state.step = self.step.value
        self.update()

    def _on_step(self, change):
        self.state.step = change["new"]
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(self._scene())
        self.blitter.update()
