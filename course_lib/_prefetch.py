"""Frames drawn before they are asked for: a slider answers in the browser, not in the kernel.

Every frame of a live explorer makes a round trip: the browser sends the new value to the
kernel, the kernel draws and encodes the picture, the browser decodes and paints it. On a
2-core machine that trip alone (websocket, Jupyter server, kernel, back) costs 25-40 ms
before the explorer has drawn anything (``python -m benchmarks --browser``). A picture that is
already in the page costs none of it.

So while the kernel has nothing else to do, a :class:`Prefetcher` draws the explorer's figure
at the values the student is likely to choose next (the neighbours of the slider moved last,
one step and then further out; one step of every other slider, linear or logarithmic, and of
either end of a range slider; the other state of each check box; never a menu, which may
replace the model) and sends each picture to the page with the
values of *every* control it was drawn at. The page keeps them
(:data:`course_lib._canvas._DECODER_ESM`); when a control changes in the browser and a picture
for the page's new values is there, the page paints it at once, and the kernel's own frame
follows a moment later (the text panels come with it; when its picture is the one kept, the
kernel only names it, and the page copies the kept one). A kernel frame is painted only if it
belongs to the values the page shows, so a stale frame never overwrites a newer one.

A prefetched picture must be the picture the kernel would draw. :func:`render_at` draws it
with every widget message and frame held back, then sets the values back and checks that the
figure and every widget of the explorer are exactly as before; a control that fails that
check (its picture depends on more than the controls, or setting it moves other controls) is
put back by hand and not drawn ahead again.

A 3D view turned by the mouse is one more control (:class:`View`): the kernel turns its axes
in whole degrees (:func:`turn_in_steps`), so the views a turn passes through are few and can be
drawn ahead like a slider's values, and the page turns its own copy of the view from the
mouse's moves exactly as the kernel will, and paints the picture kept for it.

What neither the controls nor the views show (a point dragged) clears the pictures on both
sides: the page clears them when the mouse goes down on the figure outside a 3D axes and
accepts new ones only once the kernel has seen the mouse go up; the kernel clears its list when
it sees it, and whenever one of its frames differs from the picture it sent for the same
values.
"""
import contextlib
import io
import time
import weakref
import zlib

import numpy as np

from ._canvas import _kernel_loop

__all__ = ["Prefetcher", "attach", "controls", "render_at"]

#: Pictures prefetched around the slider moved last (each side together).
FOCUS_FRAMES = 160
#: Pictures the kernel keeps track of (and the page keeps); beyond, the one least likely to be
#: wanted is dropped on both sides for each one more likely drawn (:meth:`Prefetcher.step`).
MAX_FRAMES = 300
#: Pictures further along the control moved last drawn before the other controls' steps.
AHEAD = 8
#: Seconds of drawing spent on prefetching after each input, at most.
BUDGET_S = 3.0
#: Seconds the kernel must have been idle before it prefetches.
IDLE_S = 0.04


def _tree(widget):
    """Every widget of a widget tree, depth first, each once."""
    seen, stack, out = set(), [widget], []
    while stack:
        w = stack.pop()
        if w is None or id(w) in seen:
            continue
        seen.add(id(w))
        out.append(w)
        stack.extend(reversed(list(getattr(w, "children", ()) or ())))
    return out


def controls(widget):
    """The controls of a widget tree whose values decide an explorer's picture: every value
    widget except the ones that only show something (text, images). Returns
    ``[(widget, name)]``, `name` the trait the page compares (``"index"`` for a choice among
    options, else ``"value"``).

    Examples
    --------
    >>> import ipywidgets as w
    >>> box = w.VBox([w.IntSlider(3), w.HTML("text"), w.Dropdown(options=["a", "b"])])
    >>> [(type(c).__name__, name) for c, name in controls(box)]
    [('IntSlider', 'value'), ('Dropdown', 'index')]
    """
    import ipywidgets as w
    from ipywidgets.widgets.widget_selection import _MultipleSelection, _Selection

    shown = (w.HTML, w.HTMLMath, w.Label, w.Image, w.Valid, w.Output)
    out = []
    for x in _tree(widget):
        if isinstance(x, shown) or not isinstance(x, w.ValueWidget):
            continue
        name = "index" if isinstance(x, (_Selection, _MultipleSelection)) else "value"
        out.append((x, name))
    return out


def _canon(value):
    """A control's value as the page compares it (floats to 10 significant digits)."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(f"{float(value):.10g}")
    if isinstance(value, (tuple, list)):
        return tuple(_canon(v) for v in value)
    return repr(value)


def _plain(value):
    """A control's value for JSON."""
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def candidates(control, name):
    """The values of one control worth drawing ahead, nearest to its value first (its own
    value excluded): every step of a linear slider, a log slider (its exponent's steps) or a
    selection slider, one end of a range slider moved a step at a time, the other state of a
    check box. Others (menus and rows of choices, text) give none.

    Examples
    --------
    >>> import ipywidgets as w
    >>> candidates(w.IntSlider(value=2, min=0, max=4), "value")
    [1, 3, 0, 4]
    >>> candidates(w.Checkbox(True), "value")
    [False]
    >>> candidates(w.SelectionSlider(options=["a", "b", "c"], index=0), "index")
    [1, 2]
    >>> candidates(w.FloatLogSlider(value=0.01, base=10, min=-3, max=0, step=1), "value")
    [0.001, 0.1, 1.0]
    >>> candidates(w.IntRangeSlider(value=(2, 3), min=0, max=5), "value")
    [(1, 3), (3, 3), (2, 2), (2, 4), (0, 3), (2, 5)]
    >>> candidates(w.Dropdown(options=["a", "b", "c"], index=0), "index")
    []
    """
    import ipywidgets as w

    if isinstance(control, View):
        return control.steps()
    if getattr(control, "disabled", False):
        return []
    if isinstance(control, (w.Checkbox, w.ToggleButton)):
        return [not control.value]
    if name == "index":
        if not isinstance(control, w.SelectionSlider):
            # a menu or a row of choices may replace the explorer's model (a data set, a
            # preset): drawn only live
            return []
        n, now = len(control.options), control.index
        if not isinstance(now, int) or n > 200:
            return []
        return sorted((k for k in range(n) if k != now), key=lambda k: (abs(k - now), k))
    if isinstance(control, (w.IntSlider, w.FloatSlider)):
        ks = _steps(control, control.value)
        if ks is None:
            return []
        return [_on_grid(control, k) for k in ks]
    if isinstance(control, w.FloatLogSlider):
        # the page's slider moves the exponent by `step`; its value is base ** exponent
        low, high, step, base = control.min, control.max, control.step, control.base
        if not step or step <= 0 or high <= low or base <= 0 or base == 1 or control.value <= 0:
            return []
        count = int(round((high - low) / step))
        exponent = np.log(control.value) / np.log(base)
        here = int(round((exponent - low) / step))
        ks = sorted((k for k in range(count + 1) if 0 < abs(k - here) <= FOCUS_FRAMES),
                    key=lambda k: (abs(k - here), k))
        return [float(base ** round(low + k * step, 12)) for k in ks]
    if isinstance(control, (w.IntRangeSlider, w.FloatRangeSlider)):
        # one end moved at a time, the ends never crossing: both ends' steps, nearest first
        lo, hi = control.value
        ends = [_steps(control, lo), _steps(control, hi)]
        if None in ends:
            return []
        out = []
        for d in range(1, FOCUS_FRAMES + 1):
            for k in ends[0][2 * d - 2:2 * d]:
                if _on_grid(control, k) <= hi:
                    out.append((_on_grid(control, k), hi))
            for k in ends[1][2 * d - 2:2 * d]:
                if _on_grid(control, k) >= lo:
                    out.append((lo, _on_grid(control, k)))
        return out[:FOCUS_FRAMES]
    return []


def _steps(control, value):
    """The step numbers of a linear slider's positions around `value` (0 at its minimum),
    nearest first, up to :data:`FOCUS_FRAMES` each side; None for a slider without steps."""
    low, high, step = control.min, control.max, control.step
    if not step or step <= 0 or high <= low:
        return None
    count = int(round((high - low) / step))
    here = int(round((value - low) / step))
    return [k for d in range(1, min(count, FOCUS_FRAMES) + 1) for k in (here - d, here + d)
            if 0 <= k <= count]


def heading_first(values, now, heading):
    """`values` (a control's candidates, nearest first) reordered for a control that last
    moved by `heading` from `now`: those that way go three times as far as those back, and
    twice as far as those aside (the other end of a range slider).

    Examples
    --------
    >>> heading_first([4, 6, 3, 7, 2, 8, 1, 9], 5, 1)       # moved up last
    [6, 4, 7, 8, 9, 3, 2, 1]
    >>> heading_first([(1, 3), (3, 3), (2, 2), (2, 4), (0, 3), (2, 5)], (2, 3), (0, 1))
    [(1, 3), (3, 3), (2, 4), (2, 5), (2, 2), (0, 3)]
    """
    way = np.ravel(np.asarray(heading, dtype=float))

    def rank(item):
        j, value = item
        try:
            along = float(np.dot(np.subtract(value, now, dtype=float).ravel(), way))
        except (TypeError, ValueError):
            return j + 1
        return (j + 1) * (1 if along > 0 else 2 if along == 0 else 3)
    return [v for _, v in sorted(enumerate(values), key=lambda item: (rank(item), item[0]))]


def _on_grid(control, k):
    """The value of a linear slider's `k`-th position."""
    import ipywidgets as w

    value = control.min + k * control.step
    if isinstance(control, (w.IntSlider, w.IntRangeSlider)):
        return int(value)
    return float(round(value, 12))


def _axes_box(ax):
    """Where axes `ax` lies on its canvas: ``[left, top, right, bottom]``, fractions of the
    canvas with y pointing down, as the page measures the mouse."""
    x0, y0, x1, y1 = ax.get_position().extents
    return [float(x0), float(1 - y1), float(x1), float(1 - y0)]


class View:
    """A 3D axes' view as a control of its explorer: ``value`` is ``(elevation, azimuth)`` in
    degrees, whole degrees once the student has turned it (:func:`turn_in_steps`). Setting it
    turns the axes as the mouse does.

    Examples
    --------
    >>> from course_lib.widgets.gimbal import GimbalExplorer
    >>> ax = next(a for a in GimbalExplorer().fig.axes if a.name == "3d")
    >>> view = View(ax)
    >>> view.value = (10, 35)
    >>> view.value, (ax.elev, ax.azim)
    ((10.0, 35.0), (10, 35))
    >>> candidates(view, "value")[:4]     # a step of the azimuth either way, of the elevation
    [(10, 34), (10, 36), (9, 35), (11, 35)]
    """

    description = "3D view"

    def __init__(self, ax):
        self.ax = ax

    @property
    def value(self):
        return (float(self.ax.elev), float(self.ax.azim))

    @value.setter
    def value(self, value):
        ax = self.ax
        ax.view_init(elev=value[0], azim=value[1], roll=ax.roll,
                     vertical_axis=ax._axis_names[ax._vertical_axis])
        ax.stale = True

    def box(self):
        """Where the axes lies on its canvas: ``[left, top, right, bottom]``, fractions of the
        canvas with y pointing down, as the page measures the mouse."""
        return _axes_box(self.ax)

    def steps(self):
        """The views a turn reaches next, nearest first: the azimuth one whole degree at a
        time either way, the elevation every second step (a turn is mostly sideways)."""
        elev, azim = (whole_degrees(v) for v in self.value)
        out = []
        for d in range(1, FOCUS_FRAMES + 1):
            out += [(elev, azim - d), (elev, azim + d)]
            if d % 2 == 1:
                k = (d + 1) // 2
                out += [(elev - k, azim), (elev + k, azim)]
        return [v for v in out if _canon(v) != _canon(self.value)]


def whole_degrees(value):
    """A view angle rounded to whole degrees, halves up: ``floor(value + 0.5)``, the page's
    ``Math.floor(value + 0.5)``."""
    return int(np.floor(value + 0.5))


def turn_in_steps(ax):
    """Make the mouse turn 3D axes `ax` as ``'azel'`` does (a sideways drag turns the
    azimuth, a drag up and down the elevation: what the page predicts), showing the view in
    whole degrees: the views a turn passes through are then the few the kernel can draw
    ahead. The angle itself is kept exact while the button is down, so a slow drag turns
    too. Returns the callback connected in place of the axes' own.

    Examples
    --------
    >>> from matplotlib.backend_bases import MouseEvent
    >>> from course_lib.widgets.gimbal import GimbalExplorer
    >>> fig = GimbalExplorer().fig
    >>> ax = next(a for a in fig.axes if a.name == "3d")
    >>> _ = turn_in_steps(ax)
    >>> ax.view_init(elev=20, azim=30)
    >>> fig.canvas.draw()
    >>> x0, y = ax.bbox.x0 + 0.3 * ax.bbox.width, ax.bbox.y0 + ax.bbox.height / 2
    >>> fig.canvas.callbacks.process("button_press_event",
    ...                              MouseEvent("button_press_event", fig.canvas, x0, y, 1))
    >>> for k in range(1, 4):                      # a tenth of the axes' width each
    ...     fig.canvas.callbacks.process("motion_notify_event", MouseEvent(
    ...         "motion_notify_event", fig.canvas, x0 + 0.1 * k * ax.bbox.width, y, 1))
    ...     print(ax.elev, ax.azim)                # 18 degrees less each time
    20 12
    20 -6
    20 -24
    """
    import matplotlib as mpl

    canvas = ax.get_figure(root=True).canvas
    registry = canvas.callbacks
    for cid, ref in list(registry.callbacks.get("motion_notify_event", {}).items()):
        if ref() == ax._on_move:
            registry.disconnect(cid)
    exact = {}

    def pressed(event):
        exact.clear()

    def on_move(event):
        turning = (ax.button_pressed in ax._rotate_btn and ax.get_navigate_mode() is None)
        if turning and exact:
            ax.elev, ax.azim = exact["view"]
        with mpl.rc_context({"axes3d.mouserotationstyle": "azel"}):
            ax._on_move(event)
        if turning:
            exact["view"] = (ax.elev, ax.azim)
            ax.elev, ax.azim = whole_degrees(ax.elev), whole_degrees(ax.azim)

    registry.connect("button_press_event", pressed)
    registry.connect("motion_notify_event", on_move)
    ax._course_turn = (pressed, on_move)          # the registry holds them weakly
    return on_move


def views(fig):
    """The :class:`View` of every 3D axes of `fig` (the same objects on every call)."""
    out = []
    for ax in fig.axes:
        if ax.name == "3d":
            if getattr(ax, "_course_view", None) is None:
                ax._course_view = View(ax)
            out.append(ax._course_view)
    return out


def inputs(explorer):
    """Everything of `explorer` the page can change: its :func:`controls` and the views of its
    3D axes, ``[(control, trait name)]``."""
    return controls(explorer.widget) + [(v, "value") for v in views(explorer.fig)]


@contextlib.contextmanager
def _ahead(explorer):
    """``explorer.drawing_ahead`` is True while inside: its updates draw values the student has
    not chosen (and are taken back), so an explorer leaves its own work alone meanwhile."""
    explorer.drawing_ahead = True
    try:
        yield
    finally:
        del explorer.drawing_ahead              # back to the class's False


@contextlib.contextmanager
def _held(canvas):
    """Nothing leaves the kernel while inside: no widget message (of any widget), no frame;
    a requested redraw is recorded instead of queued (the list yielded)."""
    import ipywidgets as w

    requests = []
    manager = getattr(canvas, "manager", None)
    saved_send = w.Widget.__dict__["_send"]
    saved_idle = canvas.__dict__.get("draw_idle")
    saved_refresh = manager.__dict__.get("refresh_all") if manager is not None else None
    png_old = getattr(canvas, "_png_is_old", None)
    w.Widget._send = lambda self, msg, buffers=None: None
    canvas.draw_idle = lambda *args, **kwargs: requests.append(True)
    if manager is not None:
        manager.refresh_all = lambda *args, **kwargs: None
    try:
        yield requests
    finally:
        w.Widget._send = saved_send
        if saved_idle is None:
            del canvas.draw_idle
        else:
            canvas.draw_idle = saved_idle
        if manager is not None:
            if saved_refresh is None:
                del manager.refresh_all
            else:
                manager.refresh_all = saved_refresh
        if png_old is not None:
            canvas._png_is_old = png_old


def _snapshot(explorer):
    """A function that puts back the explorer's model (its ``state``, the positions of its
    draggable points) as it is now: an update may change more than its picture (imposing a
    continuity moves the constrained points)."""
    from .widgets._drag import DraggablePoints

    def copied(value):
        # data is copied; anything else a state holds (a drawing object, a cache) is kept as
        # it is: copying a figure would make a new canvas, a new widget
        if isinstance(value, np.ndarray):
            return value.copy()
        if isinstance(value, list):
            return [copied(v) for v in value]
        if isinstance(value, dict):
            return {k: copied(v) for k, v in value.items()}
        if type(value) is tuple:
            return tuple(copied(v) for v in value)
        return value

    state = getattr(explorer, "state", None)
    saved = ({k: copied(v) for k, v in vars(state).items()} if hasattr(state, "__dict__")
             else None)
    points = [(d, d.points.copy()) for d in vars(explorer).values()
              if isinstance(d, DraggablePoints)]

    def restore():
        if saved is not None:
            vars(state).update({k: copied(v) for k, v in saved.items()})
        for drag, where in points:
            if drag.points.shape == where.shape:
                drag.points[...] = where
            else:
                drag.points = where.copy()
    return restore


def _same(a, b):
    try:
        return bool(a is b or a == b)
    except Exception:                        # arrays and the like: compared by identity
        return False


def _picture(canvas):
    return np.asarray(canvas.get_renderer().buffer_rgba()).copy()


def _states(widgets):
    return [w.get_state() for w in widgets]


class NotPrefetchable(RuntimeError):
    """The explorer's picture or widgets were not the same after setting the values back."""


def render_at(explorer, settings):
    """The explorer's figure drawn with `settings` (``{control: value}``, `value` for the
    control's trait named by :func:`controls`), as RGBA pixels, and the values of every control
    it was drawn at; everything is set back afterwards, and nothing reaches the browser.

    Raises :class:`NotPrefetchable` (after setting everything back as well as it can) if the
    figure or a widget of the explorer is not exactly as before.

    Examples
    --------
    >>> from course_lib.widgets.bezier import BezierExplorer
    >>> ex = BezierExplorer()
    >>> ex.fig.canvas.draw()
    >>> t = next(c for c, name in controls(ex.widget) if c.description == "t")
    >>> pixels, values = render_at(ex, {t: 0.9})
    >>> pixels.shape[-1], 0.9 in values, t.value == 0.9
    (4, True, False)
    """
    canvas = explorer.fig.canvas
    every = inputs(explorer)
    names = dict((id(c), n) for c, n in every)
    tree = [w for w in _tree(explorer.widget) if w is not canvas]
    blitter = explorer.blitter
    background = blitter.background if blitter is not None else None
    before = _picture(canvas)
    states = _states(tree)
    saved = {c: getattr(c, n) for c, n in every}
    widgets = {c: {k: c._trait_values.get(k) for k in c.keys} for c, _ in every
               if not isinstance(c, View)}
    # a view turned needs the whole figure drawn, as the mouse's turn does
    turned = any(isinstance(c, View) for c in settings)
    restore = _snapshot(explorer)
    values = None
    by_hand = False
    with _held(canvas) as requests, _ahead(explorer):
        try:
            for control, value in settings.items():
                setattr(control, names[id(control)], value)
            if requests or turned or (blitter is not None and blitter.background is None):
                canvas.draw()
            pixels = _picture(canvas)
            values = [_plain(getattr(c, n)) for c, n in every]
        finally:
            requests.clear()
            if blitter is not None:
                blitter.background = background
            # the ones set first (a choice may set other controls), then any other changed;
            # then the model, which an update may have changed beyond the controls
            for control in [*settings, *saved]:
                if getattr(control, names[id(control)]) != saved[control]:
                    setattr(control, names[id(control)], saved[control])
            restore()
            if requests or turned or (blitter is not None and blitter.background is None):
                canvas.draw()
            if not np.array_equal(_picture(canvas), before) or _states(tree) != states:
                # setting the controls back set others in turn (a preset chosen anew resets
                # the selected point): put every control's traits back as they were without
                # telling anyone (the page never saw them change), then the model, and draw
                # the model as it was
                by_hand = True
                for control, traits in widgets.items():
                    for name, value in traits.items():
                        if not _same(control._trait_values.get(name), value):
                            control._trait_values[name] = value
                restore()
                requests.clear()
                explorer.update()
                if requests or (blitter is not None and blitter.background is None):
                    canvas.draw()
    if not np.array_equal(_picture(canvas), before):
        raise NotPrefetchable("the figure is not the same after setting the values back")
    changed = [w for w, s in zip(tree, states) if w.get_state() != s]
    if changed:
        for widget in changed:                       # the page must see what the kernel has
            widget.send_state()
        raise NotPrefetchable(f"{len(changed)} widget(s) not the same after setting the "
                              "values back")
    if by_hand:
        # back, but only by hand: setting this control moves others, so it is drawn live
        raise NotPrefetchable("the explorer came back only when its controls were put back "
                              "without their callbacks")
    return pixels, values


def _png(pixels):
    from PIL import Image

    if pixels[..., 3].min() == 255:
        pixels = pixels[..., :3]
    with io.BytesIO() as out:
        Image.fromarray(np.ascontiguousarray(pixels)).save(out, format="png", compress_level=1)
        return out.getvalue()


def _crc(pixels):
    return zlib.crc32(np.ascontiguousarray(pixels).data)


class Prefetcher:
    """Draws an explorer's next pictures while the kernel is idle and sends them to the page
    (through the canvas's frame decoder, once its page has said it keeps them).

    The kernel side of the scheme in this module's docstring: it follows which control the
    student moved last (the focus), counts the mouse releases on the figure (the page's
    pictures from before the last release are refused there), remembers the pictures sent and
    their checksums, and spends at most :data:`BUDGET_S` seconds of drawing after each
    input.

    Examples
    --------
    >>> from course_lib.widgets.bezier import BezierExplorer
    >>> explorer = BezierExplorer()
    >>> prefetch = Prefetcher(explorer)
    >>> [(c.description, v) for c, v, _ in prefetch.plan()][:2]   # t, one step either side
    [('t', 0.39), ('t', 0.41)]
    >>> prefetch.step()              # no page keeps pictures yet (no decoder): nothing drawn
    >>> prefetch.frames
    0
    """

    def __init__(self, explorer):
        self.explorer = weakref.ref(explorer)
        self.canvas = explorer.fig.canvas
        self.controls = controls(explorer.widget)
        self.views = views(explorer.fig)
        for view in self.views:
            turn_in_steps(view.ax)
        # what the page can change, in the order of values(): the controls, then the views
        self.inputs = self.controls + [(v, "value") for v in self.views]
        # a rendered 3D view that a drag turns by moving two of the controls (the explorer's
        # ``turned_by``): the indices of those controls, or None
        pair = getattr(explorer, "turned_by", None) or ()
        index = {id(c): k for k, (c, n) in enumerate(self.controls) if n == "value"}
        self.turns = [index[id(c)] for c in pair] if pair and \
            all(id(c) in index for c in pair) else None
        self.sliding = False           # the mouse is turning such a view, press to release
        self.turning = None            # the view the mouse is turning, between press and release
        self.sent = {}                 # canonical values -> checksum of the picture sent
        self.sent_values = {}          # canonical values -> the values, as the page has them
        self.epoch = 0                 # mouse releases on the figure seen by the kernel
        self.focus = None
        self.heading = None            # (control, how far it moved last): the way it goes
        self._turned_from = None       # the view at the turn's last mouse move
        self.decoder = None
        self.enabled = True
        self.skip = set()              # ids of controls whose pictures cannot be drawn ahead
        self.drawing = False
        self.spent = 0.0
        self.handle = None
        self.frames = 0                # pictures sent (the tests read it)
        self.dropped = 0               # pictures dropped to make room for likelier ones
        for control, name in self.controls:
            control.observe(self._moved, names=name)
        self.canvas.on_msg(self._mouse)

    # -- what the kernel knows of the page ---------------------------------------------------
    def spec(self):
        """``[[model id, trait]]`` of every control, in the order of :meth:`values`."""
        return [[c.model_id, n] for c, n in self.controls]

    def view_spec(self):
        """Each 3D axes' place on the canvas and view, in the order of :meth:`values` (after
        the controls): ``[{"box": [left, top, right, bottom], "view": [elev, azim]}]``."""
        return [{"box": v.box(), "view": list(v.value)} for v in self.views]

    def turn_spec(self):
        """The rendered 3D view a drag turns by moving two controls (:attr:`turns`), as
        ``[{"box": [left, top, right, bottom], "controls": [azimuth, elevation]}]`` (indices
        among the controls), or ``[]``."""
        if self.turns is None:
            return []
        return [{"box": self._screen_box(), "controls": list(self.turns)}]

    def _screen_box(self):
        """Where the picture lies on the canvas (its axes; the whole canvas if it has none),
        as :meth:`View.box` gives a 3D axes'."""
        axes = self.canvas.figure.axes
        return _axes_box(axes[0]) if axes else [0.0, 0.0, 1.0, 1.0]

    def values(self):
        return [_plain(getattr(c, n)) for c, n in self.inputs]

    def key(self, values=None):
        return tuple(_canon(v) for v in (self.values() if values is None else values))

    def holds(self):
        """Whether the page was sent the picture of the current values (and keeps it)."""
        return self.decoder is not None and self.key() in self.sent

    def ready(self, decoder):
        """A page keeps this explorer's pictures from now on (it has none yet)."""
        self.decoder = decoder
        self.sent.clear()
        self.wake()

    def _moved(self, change):
        if self.drawing:
            return
        owner = change["owner"]
        self.focus = owner
        self.spent = 0.0
        self.heading = None
        if not isinstance(change["new"], (bool, str)):
            try:
                moved = np.subtract(change["new"], change["old"], dtype=float)
            except (TypeError, ValueError):
                return
            if np.all(np.isfinite(moved)) and np.any(moved):
                self.heading = (owner, moved)

    def _mouse(self, widget, content, buffers):
        if not isinstance(content, dict):
            return
        if content.get("type") == "button_press":
            # on a 3D axes the press starts a turn, which the views in the pictures' values
            # describe (the next views drawn ahead while the mouse rests); anywhere else it
            # may move what no control shows (a point)
            self.turning = self._view_at(content)
            # or on a rendered view turned by two sliders: the page moves them, and the
            # pictures kept are those of their values; nothing is stale
            self.sliding = self.turning is None and self._on_turned_picture(content)
            if self.turning is not None:
                self.focus = self.turning
                self.spent = 0.0
                self._turned_from = self.turning.value
                self.wake()                # no frame follows a press: nothing else wakes it
            elif not self.sliding:
                # the page forgot its pictures at the press: none is held while the mouse
                # may move what the values do not show (every frame of a drag is drawn now)
                self.sent.clear()
        elif content.get("type") == "motion_notify" and self.turning is not None:
            # (after the axes' own handler: ipympl's runs first) the way the view turns
            now = self.turning.value
            last, self._turned_from = self._turned_from, now
            if last is not None and now != last:
                self.heading = (self.turning, np.subtract(now, last, dtype=float))
                self.spent = 0.0           # an input, as a slider's change is
        elif content.get("type") == "button_release":
            if self.sliding:
                self.sliding = False
            elif self.turning is not None:
                self.focus, self.turning = self.turning, None
            else:
                # a point dragged: every picture drawn before is stale
                self.epoch += 1
                self.sent.clear()
            self.spent = 0.0

    def _at(self, content):
        """A left press's point as fractions of the canvas (y down), or None (another button,
        or no point)."""
        try:
            fx = float(content["x"]) / self.canvas.figure.bbox.width
            fy = float(content["y"]) / self.canvas.figure.bbox.height
        except (KeyError, TypeError, ValueError, ZeroDivisionError):
            return None
        return None if content.get("button", 0) != 0 else (fx, fy)

    def _on_turned_picture(self, content):
        """Whether a mouse message's point lies on the picture a drag turns
        (:meth:`turn_spec`), the toolbar's pan and zoom off."""
        point = self._at(content)
        axes = self.canvas.figure.axes
        if self.turns is None or point is None or \
                (axes and axes[0].get_navigate_mode() is not None):
            return False
        left, top, right, bottom = self._screen_box()
        return left <= point[0] <= right and top <= point[1] <= bottom

    def _view_at(self, content):
        """The view whose axes holds a mouse message's point (x, y: canvas pixels from the top
        left), or None."""
        point = self._at(content)
        if point is None:
            return None
        fx, fy = point
        for view in self.views:
            if view.ax.get_navigate_mode() is not None:
                return None                # the toolbar's pan or zoom: the mouse moves no view
            left, top, right, bottom = view.box()
            if left <= fx <= right and top <= fy <= bottom:
                return view
        return None

    def kept_unlike(self, pixels):
        """Whether the page was sent a picture for the current values that is not `pixels`."""
        crc = self.sent.get(self.key())
        return crc is not None and crc != _crc(pixels)

    def frame_drawn(self, pixels):
        """The kernel has drawn a frame of the current values: if the page was sent this very
        picture for them, tell it so and return True (the frame need not be sent); if it was
        sent a different one, clear both sides (a point moved meanwhile), or, for an explorer
        that ``refines`` its pictures, forget that one picture on both sides, and return False
        (the page may be showing that other picture: the frame must be sent, whole); None if
        it was sent none. Prefetch again later."""
        key = self.key()
        crc = self.sent.get(key)
        self.wake()
        if crc is None:
            return None
        if crc != _crc(pixels):
            explorer = self.explorer()
            if getattr(explorer, "refines", False):
                # the explorer's own finer picture of the same values (a ray tracer's full
                # image after its preview): only the picture kept for them is not its first
                del self.sent[key]
                self.decoder.send({"type": "drop", "state": self.values()})
            else:
                self.clear()
            return False
        self.decoder.send({"type": "same", "state": self.values(), "epoch": self.epoch})
        return True

    def clear(self):
        self.sent.clear()
        if self.decoder is not None:
            self.decoder.send({"type": "clear"})

    def message(self):
        """What a kernel frame carries: the values it shows and the kernel's epoch."""
        return {"state": self.values(), "epoch": self.epoch}

    # -- drawing ahead -----------------------------------------------------------------------
    def plan(self):
        """``[(control, value, values)]`` still to draw for the current values, most likely
        first; `values` are those of every control in the page once the student has set
        `control` to `value` (the picture is kept under them: a choice that sets other
        controls in the kernel is found in the page before those reach it)."""
        return [item for item in self._wanted() if self.key(item[2]) not in self.sent]

    def _wanted(self):
        """:meth:`plan` with the pictures already sent: every picture worth keeping for the
        current values, most likely first (a value may come twice)."""
        movable = [(c, n) for c, n in self.inputs if id(c) not in self.skip]
        lists = {id(c): candidates(c, n) for c, n in movable}
        focus = self.focus
        if focus is None or not lists.get(id(focus)):
            focus = next((c for c, n in movable if lists[id(c)] and n == "value"
                          and not isinstance(c.value, bool)), None)
        def near(c):
            # a step either side: of each end of a range slider
            return 4 if isinstance(c.value, tuple) else 2

        order = []
        moved = focus is not None and self.focus is not None
        if moved and self.heading is not None and self.heading[0] is focus:
            # a control being dragged goes on the same way most likely
            name = next(n for c, n in movable if c is focus)
            lists[id(focus)] = heading_first(lists[id(focus)], getattr(focus, name),
                                             self.heading[1])
        if focus is not None:
            # the control moved goes on moving most likely: a few steps further along it
            # first (then the others' single steps, which each new value of it renews)
            first = near(focus) + (AHEAD if moved else 0)
            order += [(focus, v) for v in lists[id(focus)][:first]]
        for c, _ in movable:
            if c is not focus:
                order += [(c, v) for v in lists[id(c)][:near(c)]]
        if moved:
            # further out only once the student has moved a control: an explorer nobody
            # touches costs a step either side of each control
            order += [(focus, v) for v in lists[id(focus)][first:FOCUS_FRAMES]]
        now = self.values()
        index = {id(c): k for k, (c, _) in enumerate(self.inputs)}
        out = []
        for control, value in order:
            values = list(now)
            values[index[id(control)]] = _plain(value)
            out.append((control, value, values))
        return out

    def _make_room(self, plan):
        """Drop the kept picture least likely to be wanted, on both sides, if it is less
        likely than the next one planned (`plan`'s first); return whether one was dropped.

        The likelihood is the place in :meth:`_wanted` (the current values' own picture
        first of all); pictures not wanted at all go first, the oldest of them first."""
        rank = {self.key(): -1}
        for r, (_, _, values) in enumerate(self._wanted()):
            rank.setdefault(self.key(values), r)
        least = len(rank) + 1
        victim, worst = None, rank.get(self.key(plan[0][2]), least)
        for key in self.sent:                   # oldest first: the first of equals is kept
            r = rank.get(key, least)
            if r > worst and key in self.sent_values:
                victim, worst = key, r
        if victim is None:
            return False
        del self.sent[victim]
        self.decoder.send({"type": "drop", "state": self.sent_values.pop(victim)})
        self.dropped += 1
        return True

    def wake(self, delay=IDLE_S):
        """Prefetch once the kernel has been idle for `delay` seconds."""
        loop = _kernel_loop()
        if loop is None or self.decoder is None or not self.enabled:
            return
        if self.handle is not None:
            loop.remove_timeout(self.handle)
        self.handle = loop.call_later(delay, self.step)

    def _busy(self, explorer):
        from .widgets._base import comms_waiting

        canvas = self.canvas
        return (comms_waiting() or getattr(canvas, "_course_draw_queued", False)
                or getattr(canvas, "_course_deferred", None) is not None
                or getattr(canvas, "_png_is_old", False) or getattr(explorer, "working", False))

    def step(self):
        """Draw and send one picture, then come back for the next."""
        self.handle = None
        explorer = self.explorer()
        if explorer is None or not self.enabled or self.decoder is None:
            return
        if self._busy(explorer):
            return self.wake()
        if self.spent >= BUDGET_S:
            return
        plan = self.plan()
        if not plan or (len(self.sent) >= MAX_FRAMES and not self._make_room(plan)):
            return
        control, value, values = plan[0]
        began = time.perf_counter()
        self.drawing = True
        try:
            pixels, _ = render_at(explorer, {control: value})
        except Exception:
            # this control is drawn only live from now on (after three such, every control);
            # the page is sent the kernel's picture again in case it is not the same
            self.skip.add(id(control))
            self.enabled = len(self.skip) < 3
            self.canvas.draw_idle()
            return
        finally:
            self.drawing = False
        png = _png(pixels)
        key = self.key(values)
        self.sent[key] = _crc(pixels)
        self.sent_values[key] = values
        if len(self.sent_values) > 2 * MAX_FRAMES:          # forget those no longer kept
            self.sent_values = {k: v for k, v in self.sent_values.items() if k in self.sent}
        self.decoder.send({"type": "frame", "state": values, "epoch": self.epoch},
                          buffers=[png])
        self.frames += 1
        self.spent += time.perf_counter() - began
        self.wake(0.0)


def attach(explorer):
    """Give a displayed explorer's ipympl canvas a :class:`Prefetcher` (once); explorers
    without one canvas of their own, or with an output area, are left alone. Returns the
    prefetcher or None.

    Examples
    --------
    >>> from course_lib.widgets.bezier import BezierExplorer
    >>> explorer = BezierExplorer()
    >>> attach(explorer) is attach(explorer) is explorer.fig.canvas._course_prefetch
    True
    """
    fig = getattr(explorer, "fig", None)
    canvas = getattr(fig, "canvas", None)
    if canvas is None or not hasattr(canvas, "on_msg") or explorer.widget is None:
        return None
    existing = getattr(canvas, "_course_prefetch", None)
    if existing is not None:
        return existing
    import ipywidgets as w

    tree = _tree(explorer.widget)
    canvases = [x for x in tree if hasattr(x, "get_diff_image")]
    if canvases != [canvas] or any(isinstance(x, w.Output) for x in tree):
        return None
    canvas._course_prefetch = Prefetcher(explorer)
    return canvas._course_prefetch
