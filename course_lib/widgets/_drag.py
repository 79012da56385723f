"""Points the student drags with the mouse on an ipympl canvas, and the pseudocode panel."""
import html

import numpy as np

__all__ = ["DraggablePoints", "pseudocode_html"]


class DraggablePoints:
    """Let the mouse pick up and move the points of a 2D axes.

    A press within `radius` (in pixels) of a point picks it up, moving the mouse moves it, the
    release drops it. Each move calls ``on_move(index, xy)``; the owner updates its state and
    redraws. Positions are clamped to the axes' limits so a point cannot be lost off screen.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    points : array_like, shape (n, 2)
        The initial positions (the object keeps its own copy in ``self.points``).
    on_move : callable
        ``on_move(index, xy)`` after every move.
    radius : float
        The pick tolerance in pixels.
    on_press : callable, optional
        ``on_press(index)`` when a point is picked up (e.g. to select it).
    on_release : callable, optional
        ``on_release()`` when a dragged point is dropped.

    Examples
    --------
    >>> from course_lib import draw
    >>> fig = draw.figure(figsize=(3, 3))
    >>> ax = fig.add_subplot()
    >>> _ = ax.set(xlim=(0, 1), ylim=(0, 1))
    >>> moved = []
    >>> drag = DraggablePoints(ax, [[0.2, 0.2]], lambda i, xy: moved.append((i, xy.tolist())))
    >>> drag.press(0.21, 0.2); drag.move(0.5, 0.6); drag.release()
    >>> moved
    [(0, [0.5, 0.6])]
    """

    def __init__(self, ax, points, on_move, radius=12.0, on_press=None, on_release=None):
        self.ax = ax
        self.points = np.array(points, dtype=float)
        self.on_move = on_move
        self.on_press = on_press
        self.on_release = on_release
        self.radius = radius
        self.active = None
        canvas = ax.figure.canvas
        # keep the connection ids: the callbacks live as long as this object
        self._cids = [canvas.mpl_connect("button_press_event", self._on_press),
                      canvas.mpl_connect("motion_notify_event", self._on_motion),
                      canvas.mpl_connect("button_release_event", self._on_release)]

    # --- the three gestures, in data coordinates (also what tests call) ---------------------
    def press(self, x, y):
        """Pick up the point nearest to (x, y) if it is within the pick radius."""
        screen = self.ax.transData.transform(self.points)
        at = self.ax.transData.transform([x, y])
        distance = np.hypot(*(screen - at).T)
        k = int(np.argmin(distance))
        self.active = k if distance[k] <= self.radius else None
        if self.active is not None and self.on_press is not None:
            self.on_press(self.active)

    def move(self, x, y):
        """Move the picked-up point to (x, y), clamped to the axes."""
        if self.active is None:
            return
        (x0, x1), (y0, y1) = sorted(self.ax.get_xlim()), sorted(self.ax.get_ylim())
        self.points[self.active] = [min(max(x, x0), x1), min(max(y, y0), y1)]
        self.on_move(self.active, self.points[self.active].copy())

    def release(self):
        """Drop the point."""
        dropped = self.active is not None
        self.active = None
        if dropped and self.on_release is not None:
            self.on_release()

    def set_points(self, points):
        """Replace the positions (e.g. after a preset), without calling ``on_move``."""
        self.points = np.array(points, dtype=float)

    # --- matplotlib events --------------------------------------------------------------------
    def _on_press(self, event):
        if event.inaxes is self.ax and event.button == 1 and event.xdata is not None:
            self.press(event.xdata, event.ydata)

    def _on_motion(self, event):
        if self.active is not None and event.inaxes is self.ax and event.xdata is not None:
            self.move(event.xdata, event.ydata)

    def _on_release(self, event):
        self.release()


def pseudocode_html(lines, current=None, note=None):
    """An algorithm's pseudocode as HTML, with line `current` highlighted and a note below.

    Parameters
    ----------
    lines : list of str
        The pseudocode, indentation included.
    current : int or None
        The index of the line to highlight.
    note : str, optional
        What happens at this step (HTML allowed).

    Returns
    -------
    str

    Examples
    --------
    >>> "background" in pseudocode_html(["repeat:", "    clip"], current=1)
    True
    """
    rows = []
    for k, line in enumerate(lines):
        text = html.escape(line).replace(" ", "&nbsp;")
        style = ("background:#ffe08a;font-weight:bold;" if k == current else "")
        rows.append(f"<div style='{style}padding:0 4px'>{text}</div>")
    body = ("<div style='font-family:monospace;font-size:12px;line-height:1.45;"
            "border:1px solid #ccc;border-radius:4px;padding:4px 0;background:#fafafa'>"
            + "".join(rows) + "</div>")
    if note:
        body += f"<div style='margin-top:6px;font-size:13px'>{note}</div>"
    return body
