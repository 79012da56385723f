"""What every explorer shares: its display (with and without a live kernel), layout helpers, and
the rule that widget messages are handled on the kernel's main thread."""
import base64
import contextvars
import functools
import io
import threading

import numpy as np

from .. import draw
from . import _style

__all__ = ["Explorer", "PlotterExplorer", "align", "beside", "bind", "checkbox", "degree_sliders", "figure_3d",
           "handle_comms_on_main_thread", "labelled", "panel", "pyvista_faces", "read_controls", "slider"]

_COMM_MESSAGES = ("comm_open", "comm_msg", "comm_close")


def handle_comms_on_main_thread(kernel=None):
    """Have the running IPython kernel handle every widget (comm) message on its main thread.

    JupyterLab 4.6 sends widget messages to *kernel subshells* by default (its setting
    ``commsOverSubshells`` is ``perCommTarget``), and ipykernel 7 runs each subshell in a thread
    of its own. A slider's callback then runs on a thread other than the one that made the
    explorer's figure. matplotlib is not thread-safe, and an OpenGL context belongs to the
    thread that created it: VTK, asked to render from another thread, draws black frames,
    prints "handleless buffer" errors and can abort the kernel.

    This wraps the kernel's three comm handlers so that a message arriving on a subshell thread
    is handed to the main thread's event loop and handled there, in the order received, with
    the message as its parent (so replies and outputs are routed as before). Every widget of
    the kernel then behaves as with ``commsOverSubshells`` set to ``disabled``, whatever the
    setting; what is lost is only that a widget answers while a cell is still running.
    Inputs that arrive faster than an explorer draws are merged: a newer value of the same
    slider, or a newer mouse move over the same figure, replaces the one still waiting, so the
    picture follows the latest input instead of falling behind (:func:`_on_main_thread`).
    Importing :mod:`course_lib.widgets` calls it; calling it again changes nothing.

    Parameters
    ----------
    kernel : ipykernel.kernelbase.Kernel, optional
        Default: the running kernel, if there is one.

    Returns
    -------
    bool
        True if the handlers of a kernel are (now) wrapped, False outside a kernel.

    Examples
    --------
    >>> handle_comms_on_main_thread()      # a doctest runs outside any kernel
    False
    """
    if kernel is None:
        try:
            from ipykernel.kernelbase import Kernel
        except ImportError:                       # pragma: no cover - ipykernel comes with lab
            return False
        if not Kernel.initialized():
            return False
        kernel = Kernel.instance()
    handlers = getattr(kernel, "shell_handlers", None)
    loop = getattr(kernel, "io_loop", None)
    if handlers is None or loop is None:
        return False
    for msg_type in _COMM_MESSAGES:
        handler = handlers.get(msg_type)
        if handler is not None and not getattr(handler, "_on_main_thread", False):
            handlers[msg_type] = _on_main_thread(handler, loop, threading.main_thread())
    return True


def _supersedes(new, old):
    """Whether comm message `new` makes the still unhandled `old` pointless: the same widget,
    and either a state update of the same fields (a slider's newer value) or another mouse move
    over the same ipympl canvas. Messages with binary buffers are never merged."""
    a, b = new["content"], old["content"]
    if a.get("comm_id") != b.get("comm_id") or new.get("buffers") or old.get("buffers"):
        return False
    da, db = a.get("data") or {}, b.get("data") or {}
    if da.get("method") == db.get("method") == "update":
        return (not da.get("buffer_paths") and not db.get("buffer_paths")
                and set(db.get("state") or {}) <= set(da.get("state") or {}))
    if da.get("method") == db.get("method") == "custom":
        ca, cb = da.get("content") or {}, db.get("content") or {}
        return ca.get("type") == cb.get("type") == "motion_notify"
    return False


def _on_main_thread(handler, loop, main):
    """`handler(stream, ident, msg)`, run on thread `main` by its event loop `loop`.

    Messages wait for the main thread in a queue, in the order received. While the main thread
    is busy (an explorer drawing its frame), a slider sends newer values and ipympl newer mouse
    positions: a message that merely repeats the one waiting last in the queue with newer
    values (:func:`_supersedes`) takes its place, so the main thread renders the latest input
    instead of every stale one in turn (the front end does not wait for it: the subshell has
    already answered). A message that reaches the main thread directly (ipykernel sends a
    comm's first message there) while others still wait is queued behind them, so that the
    order the student acted in is kept. The wrapper counts the messages it handed over in
    ``forwarded`` (the browser tests read it to prove that JupyterLab really sent messages to a
    subshell), the ones merged into a newer one in ``merged`` and the direct ones queued in
    ``deferred``. Setting its ``trace`` to a callable
    ``trace(event, msg_id)`` reports "arrive", "start" and "end" of every forwarded message
    (the browser benchmark times a frame's path with it)."""
    waiting = []                       # [context, stream, ident, msg], oldest first
    lock = threading.Lock()

    def handle_oldest():
        with lock:
            context, stream, ident, msg = waiting.pop(0)
        trace = forward.trace
        if trace is not None:
            trace("start", msg["header"]["msg_id"])
        try:
            context.run(handler, stream, ident, msg)
        finally:
            if trace is not None:
                trace("end", msg["header"]["msg_id"])

    @functools.wraps(handler)
    def forward(stream, ident, msg):
        direct = threading.current_thread() is main
        if direct:
            # ipykernel sends a comm's first message (a button's first click) to the main
            # thread directly: while older messages of other widgets still wait (a slider
            # dragged just before), it waits behind them, or the click would act on a value
            # the slider is about to leave (and the slider's older value would win)
            if not comms_waiting():
                return handler(stream, ident, msg)
            forward.deferred += 1
        else:
            forward.forwarded += 1
        if forward.trace is not None:
            forward.trace("arrive", msg["header"]["msg_id"])
        # the context carries the message as the kernel's parent (set by the shell that got it)
        entry = [contextvars.copy_context(), stream, ident, msg]
        with lock:
            if not direct and waiting and _supersedes(msg, waiting[-1][3]):
                waiting[-1] = entry
                forward.merged += 1
                return None
            waiting.append(entry)
        loop.add_callback(handle_oldest)
        return None
    forward._on_main_thread = True
    forward.forwarded = 0
    forward.merged = 0
    forward.deferred = 0
    forward.trace = None
    forward.waiting = waiting
    _FORWARDERS.append(forward)
    return forward


#: Every wrapper made by :func:`_on_main_thread` (one per comm message type).
_FORWARDERS = []


def comms_waiting():
    """Whether a widget message is waiting for the kernel's main thread (then the kernel is
    not idle: :mod:`course_lib._prefetch` draws nothing ahead).

    Examples
    --------
    >>> comms_waiting()
    False
    """
    return any(forward.waiting for forward in _FORWARDERS)


def figure_3d(radius, title, size=4.3):
    """A square figure with one 3D axes (light reference frame, no box): ``(fig, ax)``.

    Examples
    --------
    >>> fig, ax = figure_3d(1.5, "demo")
    >>> ax.get_title(), ax.get_xlim()
    ('demo', (np.float64(-1.5), np.float64(1.5)))
    """
    fig = draw.figure(figsize=(size, size))
    ax = fig.add_subplot(projection="3d")
    fig.subplots_adjust(left=0, right=1, bottom=0.02, top=0.95)
    draw.setup_axes_3d(ax, radius=radius, title=title, box=False)
    _style.style_axes(ax)
    return fig, ax


def labelled(kind, description, label_width=None, width=None, body=None, **options):
    """A control of ipywidgets class `kind` labelled `description`, the label shown whole.

    The label is `label_width` wide (CSS; default :func:`._style.label_width` of the
    description, so that it is never cut) and the whole control `width` (default: the label and
    `body` pixels for the control itself, :data:`CONTROL_BODY` unless given; a given width too
    small for the label and :data:`MIN_BODY` is widened; a menu's default body fits its longest
    entry). Further `options` go to the class.

    Examples
    --------
    >>> import ipywidgets as w
    >>> menu = labelled(w.Dropdown, "mapping", options=["planar", "sphere"], width="260px")
    >>> menu.value, menu.style.description_width, menu.layout.width
    ('planar', '80px', '260px')
    >>> labelled(w.FloatSlider, "oblique angle φ °").style.description_width
    '146px'
    """
    import ipywidgets as w

    label_width = label_width or _style.label_width(description)
    label = _style.px(label_width)
    if body is None and issubclass(kind, w.Dropdown) and options.get("options") is not None:
        # a menu as wide as its longest entry (with room for its arrow)
        entries = [o[0] if isinstance(o, tuple) else str(o) for o in options["options"]]
        body = max(CONTROL_BODY, _style.px(_style.button_width(*entries)))
    total = (label + (body or CONTROL_BODY) if width is None
             else max(_style.px(width), label + MIN_BODY))
    return kind(description=description, style={"description_width": label_width},
                layout=w.Layout(width=f"{total}px"), **options)


#: Pixels a slider's track and read-out (or a menu's box) take beside the label by default.
CONTROL_BODY = 220
#: The least room left for them when a width is given.
MIN_BODY = 150


def slider(description, value, low, high, step, on_change=None, *, kind=None,
           label_width=None, width=None, body=None, continuous_update=True, **options):
    """A slider labelled `description` that follows the mouse (unless `continuous_update` is
    False: then it reports its value when released).

    The one slider factory of the explorers: `kind` is the ipywidgets class (default
    ``FloatSlider``; ``IntSlider`` etc.), the description `label_width` wide (default: wide
    enough to show it whole) and the whole slider `width` (:func:`labelled`); further
    `options` go to the class. With `on_change`, the slider calls it when its value moves.

    Examples
    --------
    >>> s = slider("k_a ambient", 0.2, 0, 1, 0.01)
    >>> type(s).__name__, s.value, s.max, s.step, s.style.description_width, s.layout.width
    ('FloatSlider', 0.2, 1.0, 0.01, '98px', '318px')
    >>> import ipywidgets as w
    >>> slider("depth", 2, 0, 6, 1, kind=w.IntSlider, width="340px").value
    2
    """
    import ipywidgets as w

    control = labelled(kind or w.FloatSlider, description, label_width, width, body, value=value,
                       min=low, max=high, step=step, continuous_update=continuous_update,
                       **options)
    if on_change is not None:
        control.observe(on_change, names="value")
    return control


def set_range(control, low, high, step, value=None):
    """Give a float slider a new range whose ends and value lie on the grid of `step`.

    The browser's slider snaps its value to ``min + k * step`` whenever the range or the step
    changes, and sends the snapped value back: with a range taken from the data (``lo``,
    ``(hi - lo) / 400``), every change of the data moved the value a little, so a slider moved
    and moved back did not give the first picture back. Here the ends are rounded outwards to
    whole multiples of `step` and the value (the current one, or `value`) to the nearest
    multiple inside the range, so the browser's snap changes nothing; min, max, step and value
    reach the browser in one message (never a value clipped to a stale range).

    Examples
    --------
    >>> s = slider("c", 0.1, 0, 1, 0.01)
    >>> set_range(s, -0.987, 0.9551, 0.005)
    >>> s.min, s.max, s.step, s.value
    (-0.99, 0.96, 0.005, 0.1)
    >>> set_range(s, 0.2, 0.5, 0.05); s.value     # clipped into the new range
    0.2
    """
    step = float(step)
    low = round(float(np.floor(low / step)) * step, 12)
    high = round(float(np.ceil(high / step)) * step, 12)
    value = control.value if value is None else value
    value = round(float(np.clip(np.round(value / step) * step, low, high)), 12)
    with control.hold_sync():
        control.min, control.max = -1e9, 1e9         # widen first: min <= max at every step
        control.value = value
        control.min, control.max = low, high
        control.step = step


def nice_step(span, count=400):
    """The 1-2-2.5-5 number nearest above ``span / count``: a slider step that keeps
    round values round.

    Examples
    --------
    >>> nice_step(1.9), nice_step(4.5), nice_step(1.35), nice_step(0.99, 200)
    (0.005, 0.02, 0.005, 0.005)
    """
    raw = float(span) / count
    decade = 10.0 ** np.floor(np.log10(raw))
    return float(next(m * decade for m in (1, 2, 2.5, 5, 10) if m * decade >= raw * (1 - 1e-9)))


def checkbox(description, value=False):
    """A check box with its description right of the box, no wider than both (ipywidgets'
    default box is 300 px wide and indented by a label width, so two of them side by side
    pushed a control column past its figure).

    Examples
    --------
    >>> box = checkbox("convex hull", True)
    >>> box.value, box.indent, box.layout.width
    (True, False, 'auto')
    """
    import ipywidgets as w

    return w.Checkbox(value=value, description=description, indent=False,
                      layout=w.Layout(width="auto"))


def align(controls):
    """Line up the labelled `controls` of one column: the same label width (the widest one's)
    and the same overall width (the widest control's, once its label is widened); returns
    them.

    Examples
    --------
    >>> a, b = slider("x", 0, 0, 1, 0.1), slider("shininess n", 0, 0, 1, 0.1, body=250)
    >>> [(c.style.description_width, c.layout.width) for c in align([a, b])]
    [('98px', '348px'), ('98px', '348px')]
    """
    controls = list(controls)
    labels = [_style.px(c.style.description_width) for c in controls]
    widest = max(labels, default=0)
    total = max((_style.px(c.layout.width) - label + widest
                 for c, label in zip(controls, labels)), default=0)
    for control in controls:
        control.style.description_width = f"{widest}px"
        control.layout.width = f"{total}px"
    return controls


def degree_sliders(on_change, label_width=None, **specs):
    """Sliders in whole degrees, ``name=(description, value, min, max)``, each calling
    `on_change` when moved; returned in a dict by name.

    Examples
    --------
    >>> sliders = degree_sliders(print, yaw=("yaw °", 30, -180, 180))
    >>> sliders["yaw"].value, sliders["yaw"].step
    (30.0, 1.0)
    """
    sliders = {name: slider(description, value, low, high, 1, on_change,
                            label_width=label_width)
               for name, (description, value, low, high) in specs.items()}
    align(sliders.values())
    return sliders


#: What every panel's text is wrapped in: ipywidgets gives an HTML widget's text the line
#: height of a control (28 px), which spaces a paragraph as if double-spaced.
PANEL_OPEN = "<div style='line-height: 1.45'>"


@functools.cache
def _panel_class(math):
    import ipywidgets as w
    from traitlets import validate

    class Panel(w.HTMLMath if math else w.HTML):
        """An HTML (or HTMLMath) widget whose text is set in its normal line height."""

        @validate("value")
        def _tight(self, proposal):
            value = proposal["value"]
            if not value or value.startswith(PANEL_OPEN):
                return value
            return f"{PANEL_OPEN}{value}</div>"

    Panel.__name__ = Panel.__qualname__ = "MathPanel" if math else "Panel"
    return Panel


def panel(value="", width=None, math=False):
    """A text panel (an ``HTML`` widget, ``HTMLMath`` with `math`) `width` wide (CSS, default:
    as wide as its text), its lines spaced as text rather than as controls.

    Examples
    --------
    >>> info = panel("two<br>lines", width="300px")
    >>> info.value.startswith(PANEL_OPEN), "two<br>lines" in info.value, info.layout.width
    (True, True, '300px')
    >>> type(panel(math=True)).__mro__[1].__name__
    'HTMLMath'
    """
    import ipywidgets as w

    layout = w.Layout(width=width) if width is not None else w.Layout()
    return _panel_class(bool(math))(value=value, layout=layout)


def read_controls(state, controls):
    """Copy each control's value into its field of `state`: ``controls`` maps field -> control.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> state = SimpleNamespace(t=0.0)
    >>> read_controls(state, {"t": slider("t", 0.5, 0, 1, 0.1)})
    >>> state.t
    0.5
    """
    for name, control in controls.items():
        setattr(state, name, control.value)


def bind(state, controls, then):
    """Bind controls to the fields of `state`: when any of them moves, every field is read
    from its control (:func:`read_controls`) and ``then()`` runs (usually the explorer's
    ``update``).

    `controls` maps a field of `state` to the control that sets it. Returns the handler the
    controls call (``handler(change)``), e.g. to call it by hand or to observe more controls.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> state = SimpleNamespace(a=1.0, b=2.0)
    >>> controls = {"a": slider("a", 1, 0, 5, 1), "b": slider("b", 2, 0, 5, 1)}
    >>> _ = bind(state, controls, lambda: print("update", state.a, state.b))
    >>> controls["b"].value = 4
    update 1.0 4.0
    """
    def on_change(change=None):
        read_controls(state, controls)
        then()
    for control in controls.values():
        control.observe(on_change, names="value")
    return on_change


def beside(canvas, controls, align="center"):
    """The figure on the left and the controls right next to it (wrapping below on narrow
    screens).

    The figure keeps its own width: ipympl lets its canvas grow to fill the row, which left a
    gap of a few hundred pixels between a figure and its controls.

    Examples
    --------
    >>> import ipywidgets as w
    >>> box = beside(w.Label("figure"), w.Label("controls"))
    >>> type(box).__name__, box.children[0].layout.flex
    ('HBox', '0 0 auto')
    """
    import ipywidgets as w

    if hasattr(canvas, "layout"):
        canvas.layout.flex = "0 0 auto"
    return w.HBox([canvas, controls], layout=w.Layout(flex_flow="row wrap", align_items=align,
                                                      grid_gap="0 12px"))


class Explorer:
    """Base of the interactive explorers.

    A subclass builds ``self.widget`` (an ipywidgets container), ``self.fig`` (its matplotlib
    figure, or None), optionally ``self.blitter`` (a :class:`course_lib.draw.Blitter` of the
    artists that move) and ``update()``, which recomputes the pure scene and updates the drawn
    artists in place.

    Displaying an explorer shows the live widget. The display also carries a plain-text
    summary and a PNG of the figure in its current state, so that a notebook read without a
    kernel (GitHub, nbviewer, a PDF export) still shows the picture, and so that the stored text
    output does not depend on widget ids or versions.

    Examples
    --------
    >>> from course_lib.widgets.gimbal import GimbalExplorer
    >>> bundle = GimbalExplorer()._repr_mimebundle_()
    >>> sorted(bundle)
    ['application/vnd.jupyter.widget-view+json', 'image/png', 'text/plain']
    """

    #: One line said in place of the widget where it cannot be shown.
    summary = "An interactive explorer: run the notebook in JupyterLab to use it."
    widget = None
    fig = None
    blitter = None
    #: True while the explorer has work of its own queued on the kernel's event loop (a
    #: picture refined step by step): nothing is drawn ahead meanwhile (:mod:`course_lib._prefetch`)
    working = False
    #: True if the picture an input gives is later replaced by a finer one of the same values
    #: (a preview, then the full image): a kernel frame unlike the picture drawn ahead for its
    #: values is that finer picture, not a sign that every picture drawn ahead is stale
    refines = False
    #: True while :mod:`course_lib._prefetch` draws the explorer at values the student has not
    #: chosen (each update is taken back by the next): an update then draws its picture and
    #: leaves the explorer's own work on the event loop (a settle timer, a refinement), and
    #: the status lines that report it, alone
    drawing_ahead = False
    #: ``(azimuth slider, elevation slider)`` that a drag across the :meth:`screen` turns, as
    #: the mouse turns a 3D axes (180 degrees per width, and per height), or None: the page
    #: moves the two sliders itself and paints the pictures drawn ahead for their values
    #: (the pyvista explorers, whose view is a rendered picture, not a matplotlib 3D axes)
    turned_by = None

    def update(self):  # pragma: no cover - every subclass overrides it
        raise NotImplementedError

    def mouse_gestures(self):
        """What a student can do with the mouse on this explorer's figure, one gesture each.

        Every draggable set of points gives a ``"drag"`` of its first point a little towards
        the middle of its axes; every 3D axes a ``"turn"`` (a horizontal drag across it, which
        turns the view). Explorers that answer a click add a ``"click"``. Positions are
        fractions of the figure's canvas with y pointing down, as a browser measures them; the
        browser tests and benchmarks perform these gestures with a real mouse.

        Returns
        -------
        list of dict
            ``{"kind": "drag" | "turn" | "click", "what": str, "start": (x, y), "end": (x, y)}``
            (a click has ``end == start``); a rendered view turned through two sliders
            (``turned_by``) adds ``"sliders"``, their descriptions.

        Examples
        --------
        >>> from course_lib.widgets.bezier import BezierExplorer
        >>> [g["kind"] for g in BezierExplorer().mouse_gestures()]
        ['drag']
        >>> from course_lib.widgets.gimbal import GimbalExplorer
        >>> [g["kind"] for g in GimbalExplorer().mouse_gestures()]
        ['turn']
        """
        from ._drag import DraggablePoints

        if self.fig is None:
            return []
        gestures = []
        for name, value in vars(self).items():
            if isinstance(value, DraggablePoints) and len(value.points):
                x0, x1 = value.ax.get_xlim()
                y0, y1 = value.ax.get_ylim()
                start = value.points[0]
                end = start + 0.25 * (np.array([(x0 + x1) / 2, (y0 + y1) / 2]) - start)
                gestures.append({"kind": "drag", "what": f"{name}: point 0",
                                 "start": self._canvas_fraction(value.ax, start),
                                 "end": self._canvas_fraction(value.ax, end)})
        for k, ax in enumerate(self.fig.axes):
            if ax.name == "3d":
                box = ax.get_position()
                y = float(1.0 - (box.y0 + box.y1) / 2)
                gestures.append({"kind": "turn", "what": f"3D axes {k}",
                                 "start": (float(box.x0 + 0.35 * box.width), y),
                                 "end": (float(box.x0 + 0.65 * box.width), y)})
        if self.turned_by is not None:
            # (the sliders it moves named: the view changes only as often as their values)
            gestures.append({"kind": "turn", "what": "the 3D view",
                             "start": (0.35, 0.5), "end": (0.65, 0.5),
                             "sliders": [c.description for c in self.turned_by]})
        return gestures

    def _canvas_fraction(self, ax, xy):
        """Where data point `xy` of `ax` lies on the canvas: fractions, y down."""
        x, y = ax.transData.transform(np.asarray(xy, dtype=float))
        return (float(x / self.fig.bbox.width), float(1.0 - y / self.fig.bbox.height))

    def png(self, dpi=72):
        """The figure in its current state as PNG bytes (None without a figure).

        Examples
        --------
        >>> from course_lib.widgets.quaternion import QuaternionExplorer
        >>> QuaternionExplorer().png()[:4]
        b'\\x89PNG'
        """
        if self.fig is None:
            return None
        buffer = io.BytesIO()
        save = self.blitter.savefig if self.blitter is not None else self.fig.savefig
        save(buffer, format="png", dpi=dpi)
        return buffer.getvalue()

    def screen(self, width, height):
        """A matplotlib canvas of `width` x `height` pixels that shows a picture made by the
        explorer itself (a ray-traced image, a VTK frame) one pixel for one
        (:meth:`show_frame`); returns the canvas for the explorer's layout, and it becomes
        ``self.fig``'s.

        Shown on a canvas rather than an image widget, the pictures take the explorers' own path
        to the page (pushed, decoded off the browser's main thread: :mod:`course_lib._canvas`)
        and the page keeps the pictures the kernel draws ahead for the explorer's sliders
        (:mod:`course_lib._prefetch`): a slider step is shown from the page's own copy,
        instead of a round trip through the kernel.

        Examples
        --------
        >>> explorer = Explorer()
        >>> canvas = explorer.screen(40, 30)
        >>> explorer.show_frame(np.zeros((30, 40, 3), np.uint8))
        >>> explorer.frame().shape, canvas is explorer.fig.canvas
        ((30, 40, 3), True)
        """
        from .. import draw

        dpi = 100 * draw.lecture_scale()        # draw.figure multiplies by the same scale
        self.fig = draw.figure(figsize=(width / dpi, height / dpi), dpi=100)
        ax = self.fig.add_axes((0, 0, 1, 1))
        ax.set_axis_off()
        self._frame = ax.imshow(np.full((height, width, 3), 255, np.uint8), aspect="auto",
                                interpolation="nearest", resample=False)
        canvas = self.fig.canvas
        if hasattr(canvas, "toolbar_visible"):
            canvas.toolbar_visible = False          # nothing to pan or zoom in a picture
        return canvas

    def show_frame(self, pixels, whole=False):
        """Show `pixels` ((height, width, 3) uint8, row 0 at the top) on the :meth:`screen`.
        ``whole=True`` sends the page the whole frame even if it is the one sent last (a
        finished picture, which must replace whatever the page shows for its values)."""
        self._frame.set_data(pixels)
        if whole:
            self.fig.canvas._course_last = None
        self.fig.canvas.draw_idle()

    def frame(self):
        """The picture the :meth:`screen` shows, (height, width, 3) uint8."""
        return np.asarray(self._frame.get_array())

    def _repr_mimebundle_(self, include=None, exclude=None):
        from .._prefetch import attach

        attach(self)                    # its next pictures drawn ahead, once a page keeps them
        image = self.png()
        encoded = base64.b64encode(image).decode("ascii") if image is not None else None
        bundle = dict(self.widget._repr_mimebundle_(include=include, exclude=exclude) or {})
        bundle["text/plain"] = self.summary
        if encoded is not None:
            bundle["image/png"] = encoded
        return bundle


class PlotterExplorer(Explorer):
    """An explorer that shows the frames of an off-screen pyvista plotter (``self.plotter``).

    The 3D explorers (isosurface, simplification, surface, texture) draw into a
    :func:`course_lib.draw.offscreen_plotter`; this base gives them one way to take its frame
    (:meth:`picture`) and one to show it live (:meth:`screen`, :meth:`show`). The texture
    explorer, which has a figure of its own beside the 3D view, shows its frames in an image
    widget instead (an explorer whose pictures are drawn ahead has one canvas).

    Examples
    --------
    >>> from course_lib.widgets.isovalue import IsosurfaceExplorer
    >>> explorer = IsosurfaceExplorer()
    >>> isinstance(explorer, PlotterExplorer), explorer.png()[:4], explorer.picture("jpeg")[:2]
    (True, b'\\x89PNG', b'\\xff\\xd8')
    """

    def picture(self, kind="png"):
        """The current picture, rendered off screen, as PNG or JPEG bytes (JPEG for the live
        view: it encodes several times faster)."""
        from PIL import Image

        self.plotter.render()
        buffer = io.BytesIO()
        image = Image.fromarray(self.plotter.screenshot(return_img=True))
        image.save(buffer, format=kind, **({"quality": 90} if kind == "jpeg" else {}))
        return buffer.getvalue()

    def png(self, dpi=None):
        """The current picture as PNG bytes (for readers without a kernel)."""
        return self.picture("png")

    def screen(self, width=None, height=None):
        """A matplotlib canvas, the size of the plotter's frames unless given, that shows them in
        the widget (:meth:`show`); returns the canvas for the explorer's layout
        (:meth:`Explorer.screen`).

        Examples
        --------
        >>> from course_lib.widgets.isovalue import IsosurfaceExplorer
        >>> explorer = IsosurfaceExplorer()
        >>> explorer.frame().shape[:2] == tuple(explorer.plotter.window_size)[::-1]
        True
        """
        default_width, default_height = self.plotter.window_size
        return super().screen(width or default_width, height or default_height)

    def show(self):
        """Render the plotter and show its frame on the :meth:`screen`."""
        self.plotter.render()
        self.show_frame(self.plotter.screenshot(return_img=True))


def pyvista_faces(triangles):
    """Triangles (m, 3) in pyvista's flat cell layout ``[3, a, b, c, 3, ...]``.

    Examples
    --------
    >>> pyvista_faces(np.array([[0, 1, 2], [2, 1, 3]])).tolist()
    [3, 0, 1, 2, 3, 2, 1, 3]
    """
    triangles = np.asarray(triangles)
    return np.column_stack([np.full(len(triangles), 3), triangles]).ravel()
