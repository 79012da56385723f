"""What the headless widget tests share: real matplotlib mouse events on an explorer's axes.

A test sends the same events a student's mouse sends (press, motions, release), through the
canvas's callback registry, so that the explorer's own handlers (``DraggablePoints``, click
handlers) run exactly as in the browser."""
import numpy as np
from matplotlib.backend_bases import MouseEvent

__all__ = ["click", "drag", "mouse"]


def mouse(ax, kind, xy, button=1):
    """Send a real matplotlib mouse event at data position `xy`, as a student's mouse does."""
    x, y = ax.transData.transform(xy)
    event = MouseEvent(kind, ax.figure.canvas, x, y, button=button)
    ax.figure.canvas.callbacks.process(kind, event)


def drag(ax, start, end, steps=4):
    """Press at `start`, move to `end` in `steps` motions, release there."""
    mouse(ax, "button_press_event", start)
    for t in np.linspace(0, 1, steps + 1)[1:]:
        mouse(ax, "motion_notify_event", (1 - t) * np.asarray(start) + t * np.asarray(end))
    mouse(ax, "button_release_event", end)


def click(ax, xy, button=1):
    """A press of `button` at data position `xy` (what a click handler listens to)."""
    mouse(ax, "button_press_event", xy, button=button)
