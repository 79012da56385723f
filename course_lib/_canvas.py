"""The live path of an explorer's frames, from the kernel to the student's screen.

:func:`course_lib.draw.figure` hands every ipympl canvas to :func:`fast_frames`, which changes
four things of ipympl 0.10 / matplotlib's web canvas, each measured in JupyterLab
(``python -m benchmarks --browser``, benchmarks/results.md):

- **frames pushed** (:func:`_push_frames`): ``draw_idle`` draws and sends the frame itself,
  once the message being handled is done, instead of asking the browser to ask for it;
- **whole, cheap frames** (:func:`_whole_frames`): every frame whole (ipympl drops frames, and a
  dropped difference would leave stale pixels), opaque RGB at zlib level 1;
- **more mouse moves**: one per 15 ms instead of 33 (ipympl's ``pan_zoom_throttle``), the
  kernel merging what it cannot keep up with (:mod:`course_lib.widgets._base`);
- **decoded off the main thread** (:func:`frame_decoder`): ipympl's front end encodes every
  frame it receives back into a PNG data URL on the browser's main thread
  (``canvas.toDataURL()``, 12-28 ms for a 737 x 351 figure) and decodes it through an
  ``<img>``; a small front-end module replaces that handler with ``createImageBitmap`` (decoded
  off the main thread) and keeps frames in order.

The page's module also keeps the pictures :mod:`course_lib._prefetch` draws ahead and paints
one as soon as the explorer's controls reach its values; a kernel frame carries the values it
shows, and one the page has already moved past is not painted.

Only the explorers' figures are changed; a figure a student makes with ``%matplotlib widget``
keeps ipympl's own path, except for the front-end handler, which is ipympl's for every canvas
of the page once an explorer has been shown.
"""
import sys

import numpy as np

__all__ = ["fast_frames", "frame_decoder"]


def fast_frames(canvas):
    """Set up `canvas` (an ipympl ``Canvas``) for the explorers: hidden header and footer, the
    toolbar on the left, and the four changes of this module.

    Examples
    --------
    >>> from course_lib import draw
    >>> canvas = draw.figure(figsize=(2, 2)).canvas      # fast_frames has run on it
    >>> type(canvas).__name__ in ("Canvas", "FigureCanvasAgg")
    True
    """
    for name, value in (("header_visible", False), ("footer_visible", False),
                        ("toolbar_position", "left"), ("resizable", False)):
        if hasattr(canvas, name):
            setattr(canvas, name, value)
    if hasattr(canvas, "syncing_data_url"):
        # ipympl 0.10 keeps a copy of each frame in the widget state until the browser says it
        # is ready, but stores it without the "data:image/png;base64," prefix: a frame drawn in
        # that window reaches the browser as a broken image (a console error). The explorers
        # carry their own picture for readers without a kernel, so the copy is not needed.
        canvas.syncing_data_url = False
    if hasattr(canvas, "get_diff_image"):
        canvas.get_diff_image = _whole_frames(canvas)
    if hasattr(canvas, "pan_zoom_throttle"):
        canvas.pan_zoom_throttle = 15
    if hasattr(canvas, "on_msg") and hasattr(canvas, "draw_idle"):
        _push_frames(canvas)
        _placed_frames(canvas)
    if hasattr(canvas, "manager") and hasattr(canvas, "copy_from_bbox"):
        _turned_views(canvas)


def _kernel_loop():
    """The running IPython kernel's event loop, or None outside a kernel."""
    kernel_module = sys.modules.get("ipykernel.kernelbase")
    if kernel_module is None or not kernel_module.Kernel.initialized():
        return None
    return getattr(kernel_module.Kernel.instance(), "io_loop", None)


#: Seconds without a new input before the kernel draws values whose picture the page holds.
HELD_PAUSE_S = 0.15


def _push_frames(canvas):
    """Make ``canvas.draw_idle()`` draw the figure and send the frame itself, once the
    message being handled is done, instead of asking the browser to ask for it.

    matplotlib's web canvas answers ``draw_idle`` by sending the browser a "draw" event; the
    browser replies with a draw request and only then does the kernel render and send the PNG:
    a round trip per frame, paid by every full redraw (a 3D view turned with the mouse, an
    explorer that changes its axes). Here the draw is queued on the kernel's event loop behind
    the messages already waiting, so several ``draw_idle`` calls (and several merged inputs)
    give one frame. Until the browser has shown the canvas (its "initialized" message), and
    outside a kernel, ``draw_idle`` is left as it was.

    A draw of values whose picture the page holds (:meth:`course_lib._prefetch.Prefetcher.holds`:
    drawn ahead and sent, so the page painted it when its controls got there) is put off until
    the inputs have paused for :data:`HELD_PAUSE_S`: while a slider is dragged through kept
    pictures the kernel updates its model at every input but leaves the two cores to the
    browser, and draws (and checks against the kept picture) only where the drag rests. A
    draw of values not held is queued at once, and takes the put-off one with it."""
    draw_idle = canvas.draw_idle
    canvas._course_shown = False
    canvas._course_draw_queued = False
    canvas._course_deferred = None          # the timer of a draw put off (see HELD_PAUSE_S)

    def seen(widget, content, buffers):
        if _initialized(content):
            canvas._course_shown = True

    def draw_now():
        canvas._course_draw_queued = False
        canvas.draw()

    def undefer(loop):
        if canvas._course_deferred is not None:
            loop.remove_timeout(canvas._course_deferred)
            canvas._course_deferred = None

    def queue(loop):
        undefer(loop)
        if not canvas._course_draw_queued:
            canvas._course_draw_queued = True
            loop.add_callback(draw_now)

    def deferred(loop):
        canvas._course_deferred = None
        queue(loop)

    def push():
        loop = _kernel_loop()
        if loop is None or not canvas._course_shown:
            return draw_idle()
        prefetch = getattr(canvas, "_course_prefetch", None)
        if prefetch is not None and prefetch.holds() and not canvas._course_draw_queued:
            # the page has painted its own copy of this picture: draw (and check) it once
            # the inputs pause, not at every one of a drag
            undefer(loop)
            canvas._course_deferred = loop.call_later(HELD_PAUSE_S, deferred, loop)
            return None
        queue(loop)
        return None

    canvas.on_msg(seen)
    canvas.draw_idle = push


def _turned_views(canvas):
    """Make ``canvas.draw()`` redraw only the 3D axes when nothing else of the figure changed.

    A 3D view turned by the mouse (or drawn ahead by :mod:`course_lib._prefetch`) needs a full
    redraw, and a full redraw repaints every axes of the figure: in an explorer that shows a 3D
    scene beside 2D plots (Slerp's angle curves, the hidden-surface explorer's buffers), the
    2D axes' ticks and texts cost more than the turned scene itself. Here the figure drawn
    without its 3D axes is kept (``canvas._course_rest``), and a draw in which no 2D axes and
    no figure-level artist has changed since (matplotlib marks a changed artist and its axes
    *stale*; the explorers' moving artists are *animated* and never part of it) pastes it back
    and draws the 3D axes on top: the same picture, as the 3D axes do not overlap the others
    (checked; else, and for a figure with no 2D part, the draw is matplotlib's own). Anything
    that draws the figure another way (a full draw, a ``savefig``) drops the kept picture. The
    draw ends with the figure's "draw_event", as matplotlib's does, so a
    :class:`course_lib.draw.Blitter` takes its background and paints its artists as usual."""
    from contextlib import ExitStack

    from matplotlib.backend_bases import DrawEvent

    fig = canvas.figure
    full_draw = canvas.draw
    canvas._course_rest = None
    canvas._course_partial_draws = 0
    mine = [False]

    def others_changed(turned):
        return any(child.stale for child in fig.get_children()
                   if child not in turned and child is not fig.patch)

    def overlapping(turned):
        flat = [ax for ax in fig.axes if ax not in turned]
        boxes = [ax.get_window_extent() for ax in flat]
        return any(ax.get_window_extent().overlaps(box) for ax in turned for box in boxes)

    def draw():
        turned = [ax for ax in fig.axes if ax.name == "3d" and ax.get_visible()]
        if not turned or len(turned) == len(fig.axes) and not fig.texts:
            return full_draw()
        renderer = canvas.get_renderer()
        rest = canvas._course_rest
        if rest is not None and (rest[0] is not renderer or others_changed(turned)):
            rest = canvas._course_rest = None
        if rest is None and overlapping(turned):
            return full_draw()
        if hasattr(canvas, "_png_is_old"):
            canvas._png_is_old = True
        mine[0] = True
        try:
            if rest is None:
                # the figure without its 3D axes (hidden as animated artists are), no event
                renderer.clear()
                with ExitStack() as hold:
                    hold.enter_context(canvas.callbacks.blocked(signal="draw_event"))
                    for ax in turned:
                        hold.callback(ax.set_animated, ax.get_animated())
                        ax.set_animated(True)
                    fig.draw(renderer)
                canvas._course_rest = (renderer, canvas.copy_from_bbox(fig.bbox))
            else:
                canvas.restore_region(rest[1])
                canvas._course_partial_draws += 1
            for ax in turned:
                ax.draw(renderer)
            DrawEvent("draw_event", canvas, renderer)._process()
        finally:
            mine[0] = False
            if getattr(canvas, "manager", None) is not None and \
                    hasattr(canvas.manager, "refresh_all"):
                canvas.manager.refresh_all()

    def drawn_elsewhere(event):
        if not mine[0]:
            canvas._course_rest = None

    canvas.mpl_connect("draw_event", drawn_elsewhere)
    canvas.draw = draw


def _whole_frames(canvas):
    """`get_diff_image` for an ipympl canvas: whole frames or, where the page can place them,
    the changed rectangle only; opaque RGB at zlib level 1.

    **No transparent differences.** matplotlib's web canvas normally sends a full-size frame
    whose unchanged pixels are transparent, painted over what the browser shows. But ipympl's
    front end (0.10) drops a frame whenever the next one arrives before it has finished
    decoding: a slider moved quickly leaves stale pixels on the student's screen for good
    (measured in JupyterLab: a slider moved and moved back did not give the first picture
    back). So a frame is either whole, or, once the page's :func:`frame_decoder` has said that
    it paints every frame in order at a given place (``canvas._course_regions``), the smallest
    rectangle holding every pixel that changed since the frame sent before, with its place.

    **Cheap to encode.** Encoding is the largest single cost of a blitted update. The figures
    are opaque (a white background), so the frame is sent as RGB without the alpha channel,
    at zlib level 1 instead of PIL's default 6: for the 737 x 351 slerp figure 6.9 ms and 40 kB
    against 16.8 ms and 41 kB (process time, measured 2026-12-02); a slider that moves a small
    part of a figure sends a small rectangle."""
    from io import BytesIO

    from PIL import Image

    canvas._course_regions = False
    canvas._course_last = None
    canvas._course_place = None

    def frame():
        if not canvas._png_is_old:
            return None
        canvas.set_image_mode("full")
        canvas._png_is_old = False
        pixels = np.asarray(canvas.get_renderer().buffer_rgba())
        last, canvas._course_last = canvas._course_last, pixels.copy()
        canvas._course_place = None
        prefetch = getattr(canvas, "_course_prefetch", None)
        if prefetch is not None and prefetch.decoder is None:
            prefetch = None
        rows = cols = None
        if canvas._course_regions and last is not None and last.shape == pixels.shape:
            changed = pixels.view(np.uint32)[..., 0] != last.view(np.uint32)[..., 0]
            rows = np.flatnonzero(changed.any(axis=1))
            # the same picture: nothing to send, unless the page may be showing another one
            # kept for these values (a ray tracer's preview where the kernel shows the full
            # image again, the frame it sent last): then the whole frame goes, and a "drop"
            if rows.size == 0 and (prefetch is None or not prefetch.kept_unlike(pixels)):
                return None
            cols = np.flatnonzero(changed.any(axis=0))
        kept = prefetch.frame_drawn(canvas._course_last) if prefetch is not None else None
        if kept:
            return None                              # the page holds this picture: told so
        if rows is not None and rows.size:           # (else: the whole frame, see above)
            y0, y1, x0, x1 = rows[0], rows[-1] + 1, cols[0], cols[-1] + 1
            pixels = pixels[y0:y1, x0:x1]
            canvas._course_place = (int(x0), int(y0))
        if pixels[..., 3].min() == 255:
            pixels = pixels[..., :3]
        with BytesIO() as png:
            Image.fromarray(np.ascontiguousarray(pixels)).save(png, format="png",
                                                              compress_level=1)
            return png.getvalue()
    return frame


def _placed_frames(canvas):
    """Send a rectangle made by :func:`_whole_frames` with its place (ipympl's "binary"
    message with ``x`` and ``y``, which only the :func:`frame_decoder`'s handler reads)."""
    import json

    send_binary = canvas.send_binary

    def new_page(widget, content, buffers):
        if not _initialized(content):
            return
        # a new page: whole frames until its frame decoder says it is ready. The decoder is
        # made now, when the page holds the canvas's model (a static figure, closed before
        # the page saw it, gets none)
        canvas._course_regions = False
        canvas._course_last = None
        prefetch = getattr(canvas, "_course_prefetch", None)
        if prefetch is not None:
            prefetch.decoder = None              # until the new page says it keeps pictures
        if getattr(canvas, "comm", None) is not None and \
                getattr(canvas, "_course_frame_decoder", None) is None:
            canvas._course_frame_decoder = _frame_decoder(canvas)

    def send(data):
        place, canvas._course_place = canvas._course_place, None
        prefetch = getattr(canvas, "_course_prefetch", None)
        content = {"type": "binary"}
        if prefetch is not None and prefetch.decoder is not None:
            content.update(prefetch.message())       # the values the frame shows
        if place is not None:
            content["x"], content["y"] = place
        if len(content) == 1:
            return send_binary(data)
        canvas.send({"data": json.dumps(content)}, buffers=[data])
    canvas.on_msg(new_page)
    canvas.send_binary = send


def _initialized(content):
    """Whether an ipympl canvas's message is its page's "initialized" (a new front end)."""
    return isinstance(content, dict) and content.get("type") == "initialized"


#: The front-end module (ES module, run by anywidget in the page when the model is created):
#: it replaces ipympl's handler of a received frame, once for every canvas of the page.
_DECODER_ESM = r"""
// pictures decoded at most at once per explorer (each a few hundred kB), and kept in all
const KEEP_DECODED = 16, KEEP = 400;
// kept pictures decoded ahead of a control moving: its next values the same step further on
const DECODE_AHEAD = 4;
const canon = (v) => (typeof v === 'number' ? Number(v.toPrecision(10))
                      : Array.isArray(v) ? v.map(canon) : v);
const keyOf = (values) => JSON.stringify(values.map(canon));

function paint(canvas, source, key, fromKept) {
  const kept = canvas.__course;
  if (kept) {                        // the values of the pictures painted, newest last
    kept.painted.push(key);
    if (kept.painted.length > 200) kept.painted.shift();
    kept.displayed = fromKept ? key : null;
  }
  const context = canvas.offscreen_context;
  context.clearRect(0, 0, canvas.offscreen_canvas.width, canvas.offscreen_canvas.height);
  context.drawImage(source, 0, 0);
  canvas._for_each_view((view) => view.update_canvas());
}

function patch(proto) {
  if (proto.__courseFrames) return;
  proto.__courseFrames = true;
  proto.handle_binary = function (msg, buffers) {
    const data = buffers[0];
    const bytes = ArrayBuffer.isView(data) ? data : new Uint8Array(data);
    this.waiting_for_image = false;
    if (this.image) this.image.onload = null;     // a frame of ipympl's own path arriving late
    // decoded in parallel, away from the main thread; painted one after the other, in the
    // order sent (a rectangle must land on the frame it was computed against)
    const decoded = createImageBitmap(new Blob([bytes], {type: 'image/png'}));
    this.__coursePainted = (this.__coursePainted || Promise.resolve()).then(() => decoded)
      .then((bitmap) => {
        const pictures = this.__course;
        const target = pictures ? pictures.kernelCanvas() : this.offscreen_canvas;
        const context = pictures ? target.getContext('2d') : this.offscreen_context;
        if (msg.x === undefined) {
          context.clearRect(0, 0, target.width, target.height);
          context.drawImage(bitmap, 0, 0);
        } else {
          context.drawImage(bitmap, msg.x, msg.y);
        }
        bitmap.close();
        if (!pictures) {
          this._for_each_view((view) => view.update_canvas());
        } else if (pictures.kernelFrame(msg)) {
          paint(this, target, pictures.kernelKey, false);
        }  // else: drawn for values the page has already left; the frame for its values follows
      }).catch(() => {});
  };
}

// The pictures the kernel drew ahead (course_lib/_prefetch.py), by the values of every control
function pictures(canvas, controls, views, turns) {
  const p = {canvas, entries: new Map(), decoded: [], epoch: 0, need: 0, pressed: false,
             kernelKey: null, copy: null, shown: 0, missed: 0, stale: 0, painted: [],
             displayed: null, same: 0, seq: 0, seen: new Map(), shownSeq: 0,
             // each 3D axes: its box on the canvas (fractions, y down) and its view, [elev,
             // azim], as the kernel last showed it or as the mouse turning it will make it
             views: views.map((v) => ({box: v.box, value: v.view})), turn: null, turnUntil: 0,
             turned: 0,
             // each rendered 3D view the mouse turns by moving two sliders: its box and the
             // indices of its azimuth and elevation sliders among the controls
             turns, slide: null, slid: 0};
  // when the page was last at each set of values (a count of its changes): a kernel frame
  // for values the page reached after the picture on the screen is newer, and painted even
  // if the page has moved on since (a slider dragged faster than the kernel draws); one for
  // values reached before it is older, and never painted (the picture never goes back)
  p.newer = (key) => {
    if (key === null || key === p.current()) return true;
    const at = p.seen.get(key);
    return at === undefined || at > p.shownSeq;
  };
  p.reached = (key) => {             // the picture on the screen is that of `key`
    const at = key === null ? undefined : p.seen.get(key);
    p.shownSeq = key === p.current() ? p.seq : Math.max(p.shownSeq, at === undefined ? 0 : at);
  };
  p.values = () => [...controls.map(([model, name]) => model.get(name)),
                    ...p.views.map((v) => v.value)];
  p.current = () => keyOf(p.values());
  // a control moving (a slider dragged, a view turned) goes on the same way most likely:
  // its next values' pictures are decoded now, so that they are painted at once when reached
  // (a decoding takes 5-15 ms; begun only when reached, the page has often moved on by then)
  p.last = null;
  p.ahead = (now) => {
    const last = p.last;
    p.last = now;
    if (!last || last.length !== now.length) return;
    // every value that moved goes on the same way (a view turned by two sliders moves both)
    const moved = now.map((v, i) => i).filter((i) => keyOf([now[i]]) !== keyOf([last[i]]));
    if (moved.length === 0) return;
    const numbers = (v) => Array.isArray(v) ? v.every((x) => typeof x === 'number')
                                            : typeof v === 'number';
    if (!moved.every((i) => numbers(last[i]) && numbers(now[i])
                            && Array.isArray(last[i]) === Array.isArray(now[i]))) return;
    const further = (a, b, k) => Array.isArray(b) ? b.map((x, j) => x + k * (x - a[j]))
                                                  : b + k * (b - a);
    for (let k = 1; k <= DECODE_AHEAD; k++) {
      const values = [...now];
      for (const i of moved) values[i] = further(last[i], now[i], k);
      const key = keyOf(values);
      const entry = p.entries.get(key);
      if (entry && !entry.bitmap) p.decode(key, entry);
    }
  };
  // the views the kernel's frame shows become the page's (a slider may turn a view), except
  // while the mouse turns one and for a second after (frames drawn on the way still come)
  p.adopt = (state) => {
    if (!state || p.turn || performance.now() < p.turnUntil) return;
    p.views.forEach((v, k) => {
      const value = state[controls.length + k];
      if (Array.isArray(value)) v.value = value;
    });
  };
  p.kernelCanvas = () => {           // the kernel's last frame, whatever the page shows
    const {width, height} = canvas.offscreen_canvas;
    if (!p.copy) p.copy = document.createElement('canvas');
    if (p.copy.width !== width || p.copy.height !== height) {
      p.copy.width = width;
      p.copy.height = height;
    }
    return p.copy;
  };
  p.kernelFrame = (msg) => {         // whether to show it: it shows the page's values
    if (msg.epoch !== undefined) p.epoch = Math.max(p.epoch, msg.epoch);
    p.kernelKey = msg.state ? keyOf(msg.state) : null;
    const now = !msg.state || p.newer(p.kernelKey);
    if (now) p.reached(p.kernelKey); else p.stale += 1;
    if (now) p.adopt(msg.state);
    // (a frame the kernel sends is never the kept picture on the screen: for that one it
    // sends "same")
    return now;
  };
  const release = (entry) => {
    if (entry && entry.bitmap) entry.bitmap.close();
    if (entry) { entry.bitmap = null; entry.decoding = null; }
  };
  p.forget = () => {
    p.displayed = null;
    for (const entry of p.entries.values()) release(entry);
    p.entries.clear();
    p.decoded = [];
  };
  p.touch = (key) => {
    const k = p.decoded.indexOf(key);
    if (k >= 0) p.decoded.splice(k, 1);
    p.decoded.push(key);
    while (p.decoded.length > KEEP_DECODED) release(p.entries.get(p.decoded.shift()));
  };
  p.decode = (key, entry) => {
    if (!entry.decoding) {
      entry.decoding = createImageBitmap(entry.blob).then((bitmap) => {
        if (p.entries.get(key) !== entry || !entry.decoding) { bitmap.close(); return null; }
        entry.bitmap = bitmap;
        p.touch(key);
        return bitmap;
      }).catch(() => null);
    }
    return entry.decoding;
  };
  // the kernel's frame is the kept picture for msg.state: the page copies it, in the order
  // of the frames, instead of receiving it again
  p.sameAs = (msg, model) => {
    const key = keyOf(msg.state);
    canvas.__coursePainted = (canvas.__coursePainted || Promise.resolve()).then(async () => {
      p.epoch = Math.max(p.epoch, msg.epoch);
      const entry = p.entries.get(key);
      const bitmap = entry && (entry.bitmap || await p.decode(key, entry));
      if (!bitmap) {                 // not kept after all: ask for the whole frame
        p.kernelKey = null;
        model.send({type: 'whole', state: msg.state});
        return;
      }
      const copy = p.kernelCanvas();
      const context = copy.getContext('2d');
      context.clearRect(0, 0, copy.width, copy.height);
      context.drawImage(bitmap, 0, 0);
      p.kernelKey = key;
      p.same += 1;
      if (p.displayed !== key && p.newer(key)) {
        p.reached(key);
        paint(canvas, copy, key, false);
      }
      if (p.newer(key)) p.adopt(msg.state);
    }).catch(() => {});
  };
  p.receive = (msg, buffers) => {
    if (msg.type === 'clear') return p.forget();
    if (msg.type === 'drop') {       // this one picture kept is no longer the kernel's
      const key = keyOf(msg.state);
      release(p.entries.get(key));
      p.entries.delete(key);
      if (p.displayed === key) p.displayed = null;
      return;
    }
    if (msg.type !== 'frame') return;
    p.epoch = Math.max(p.epoch, msg.epoch);
    // drawn before the kernel saw the mouse go up on the figure: perhaps stale
    if (p.pressed || msg.epoch < p.need || p.entries.size >= KEEP) return;
    const data = buffers[0];
    const key = keyOf(msg.state);
    release(p.entries.get(key));
    const entry = {blob: new Blob([ArrayBuffer.isView(data) ? data : new Uint8Array(data)],
                                  {type: 'image/png'}), bitmap: null, decoding: null};
    p.entries.set(key, entry);
    if (p.decoded.length < KEEP_DECODED) p.decode(key, entry);   // the nearest come first
  };
  p.show = () => {                   // a control changed in the page
    if (p.batching) return;          // more controls change together: shown once, after
    const values = p.values();
    const key = keyOf(values);
    p.seq += 1;
    p.seen.delete(key);
    p.seen.set(key, p.seq);
    if (p.seen.size > 1000) p.seen.delete(p.seen.keys().next().value);
    if (p.pressed) return;
    const entry = p.entries.get(key);
    if (entry && entry.bitmap) {
      p.touch(key);
      p.reached(key);
      paint(canvas, entry.bitmap, key, true);
      p.shown += 1;
    } else if (entry) {
      p.decode(key, entry).then((bitmap) => {
        if (bitmap && !p.pressed && p.current() === key) {
          p.reached(key);
          paint(canvas, bitmap, key, true);
          p.shown += 1;
        }
      });
    } else if (p.copy && p.kernelKey === key) {
      p.reached(key);
      paint(canvas, p.copy, key, false);  // back to the values of the kernel's last frame
    } else {
      p.missed += 1;
    }
    p.ahead(values);
  };
  // the mouse on the figure may change what no control shows (a point, a view): the pictures
  // are forgotten, and new ones accepted once drawn after the kernel has seen the mouse go up
  const inside = (target) => Promise.all(Object.values(canvas.views || {}))
    .then((views) => views.some((view) => view && view.el && view.el.contains(target)));
  // ... except a press on a 3D axes: a turn, which the views in the values describe. The page
  // turns its copy of the view as the kernel will (course_lib._prefetch.turn_in_steps: the
  // 'azel' style, 180 degrees per width or height of the axes, shown in whole degrees) and
  // paints the picture kept for it, if any, while the mouse moves
  const at = (event, el) => {
    const r = el.getBoundingClientRect();
    return [(event.clientX - r.left) / r.width, (event.clientY - r.top) / r.height];
  };
  const within = (box, [x, y]) => box[0] <= x && x <= box[2] && box[1] <= y && y <= box[3];
  document.addEventListener('mousedown', (event) => {
    const el = event.target;
    inside(el).then((yes) => {
      if (!yes) return;
      const point = el.tagName === 'CANVAS' ? at(event, el) : null;
      // with the toolbar's pan or zoom chosen the mouse turns no view (as in the kernel)
      const toolbar = canvas.get('toolbar');
      const navigating = !!(toolbar && toolbar.get && toolbar.get('_current_action'));
      const k = point && event.button === 0 && !navigating
        ? p.views.findIndex((v) => within(v.box, point)) : -1;
      const s = point && event.button === 0 && !navigating && k < 0
        ? p.turns.findIndex((t) => within(t.box, point)) : -1;
      if (k >= 0) {
        p.turn = {k, el, from: point, exact: [...p.views[k].value]};
      } else if (s >= 0) {           // a rendered 3D view, turned by its two sliders
        const t = p.turns[s];
        p.slide = {t, el, from: point,
                   exact: t.controls.map((i) => controls[i][0].get(controls[i][1]))};
      } else {
        p.pressed = true;
        p.forget();
      }
    }).catch(() => {});
  }, true);
  // a slider's value nearest to x on its grid (as course_lib._prefetch._on_grid): an
  // azimuth slider a whole turn wide wraps around, any other stops at its ends
  const onGrid = (model, x) => {
    const [min, max, step] = ['min', 'max', 'step'].map((k) => model.get(k));
    if (max - min >= 360) x = min + ((((x - min) % 360) + 360) % 360);
    x = Math.min(max, Math.max(min, x));
    return Number((min + Math.round((x - min) / step) * step).toFixed(10));
  };
  document.addEventListener('mousemove', (event) => {
    const slide = p.slide;
    if (!slide || !(event.buttons & 1)) return;
    const point = at(event, slide.el);
    if (!within(slide.t.box, point)) return;
    const [w, h] = [slide.t.box[2] - slide.t.box[0], slide.t.box[3] - slide.t.box[1]];
    // as a 3D axes turns ('azel'): the azimuth against the mouse's x, the elevation with y
    slide.exact[0] -= ((point[0] - slide.from[0]) / w) * 180;
    slide.exact[1] += ((point[1] - slide.from[1]) / h) * 180;
    slide.from = point;
    // both sliders set before the page looks for the picture of their values (one picture
    // for the pair, not one for each half-way pair), then the kernel told
    const changed = [];
    p.batching = true;
    try {
      slide.t.controls.forEach((i, j) => {
        const [model, name] = controls[i];
        const value = onGrid(model, slide.exact[j]);
        if (model.get(name) !== value) { model.set(name, value); changed.push(model); }
      });
    } finally { p.batching = false; }
    if (changed.length) {
      p.show();                    // the kept picture painted
      changed.forEach((model) => model.save_changes());
      p.slid += 1;
    }
  }, true);
  document.addEventListener('mousemove', (event) => {
    const turn = p.turn;
    if (!turn || !(event.buttons & 1)) return;
    const view = p.views[turn.k];
    const point = at(event, turn.el);
    if (!within(view.box, point)) return;      // the kernel's axes ignore it too
    const [w, h] = [view.box[2] - view.box[0], view.box[3] - view.box[1]];
    turn.exact[0] += ((point[1] - turn.from[1]) / h) * 180;
    turn.exact[1] -= ((point[0] - turn.from[0]) / w) * 180;
    turn.from = point;
    const whole = turn.exact.map((v) => Math.floor(v + 0.5));
    if (whole[0] !== view.value[0] || whole[1] !== view.value[1]) {
      view.value = whole;
      p.turned += 1;
      p.show();
    }
  }, true);
  document.addEventListener('mouseup', () => {
    if (p.turn) { p.turn = null; p.turnUntil = performance.now() + 1000; }
    p.slide = null;
    if (p.pressed) { p.pressed = false; p.need = p.epoch + 1; }
  }, true);
  return p;
}

export default {
  async initialize({ model }) {
    // never fails: without the patch the canvas keeps ipympl's own path (whole frames)
    try {
      const ref = model.get('canvas') || '';
      const manager = model.widget_manager;
      const canvas = await manager.get_model(ref.replace(/^IPY_MODEL_/, ''));
      if (canvas && typeof canvas.handle_binary === 'function') {
        patch(Object.getPrototypeOf(canvas));
        const specs = model.get('controls') || [];
        const views = model.get('views') || [];
        const turns = model.get('turns') || [];
        if (specs.length || views.length) {
          const controls = await Promise.all(specs.map(
            ([id, name]) => manager.get_model(id).then((control) => [control, name])));
          const kept = pictures(canvas, controls, views, turns);
          kept.ids = specs.map(([id]) => id);
          canvas.__course = kept;
          // the browser tests and the benchmark read how often a kept picture was shown
          (window.__coursePictures = window.__coursePictures || []).push(kept);
          model.on('msg:custom', (msg, buffers) => (msg.type === 'same'
            ? kept.sameAs(msg, model) : kept.receive(msg, buffers || [])));
          for (const [control, name] of controls) control.on(`change:${name}`, kept.show);
        }
        model.send({type: 'ready'});
      }
    } catch (error) { /* the canvas was closed before the page saw it */ }
  },
};
"""


def _frame_decoder(canvas):
    """A :func:`frame_decoder` for `canvas`, or None where anywidget is not installed."""
    try:
        return frame_decoder(canvas)
    except ImportError:                                  # pragma: no cover - a dependency
        return None


def frame_decoder(canvas):
    """An invisible widget whose front end makes ipympl decode frames off the main thread.

    ipympl's handler of a received frame (``handle_binary``) sets an ``<img>``'s source and,
    on the browser's main thread, encodes the canvas it has just drawn back into a PNG data URL
    (``toDataURL``, kept for saving the figure from its toolbar). This widget's module (run in
    the page by anywidget when the widget is created; it need not be displayed) replaces that
    handler on the prototype of ipympl's canvas model: ``createImageBitmap`` decodes the frame
    away from the main thread, a frame that finishes decoding after a newer one is dropped, and
    nothing is encoded back. The toolbar's save button then saves an older picture; the
    explorers' figures are saved by :meth:`course_lib.widgets._base.Explorer.png`.

    Parameters
    ----------
    canvas : ipympl.backend_nbagg.Canvas

    Returns
    -------
    anywidget.AnyWidget

    Examples
    --------
    >>> from course_lib import draw
    >>> canvas = draw.figure(figsize=(2, 2)).canvas
    >>> frame_decoder(canvas).canvas is canvas
    True
    """
    prefetch = getattr(canvas, "_course_prefetch", None)
    return _decoder_class()(canvas=canvas, controls=prefetch.spec() if prefetch else [],
                            views=prefetch.view_spec() if prefetch else [],
                            turns=prefetch.turn_spec() if prefetch else [])


_DECODER_CLASS = None


def _decoder_class():
    global _DECODER_CLASS
    if _DECODER_CLASS is None:
        import anywidget
        import traitlets
        from ipywidgets import widget_serialization
        from ipympl.backend_nbagg import Canvas

        class _FrameDecoder(anywidget.AnyWidget):
            _esm = _DECODER_ESM
            canvas = traitlets.Instance(Canvas).tag(sync=True, **widget_serialization)
            #: ``[[model id, trait]]`` of the explorer's controls (:mod:`course_lib._prefetch`)
            controls = traitlets.List().tag(sync=True)
            #: each 3D axes' place and view (:meth:`course_lib._prefetch.Prefetcher.view_spec`)
            views = traitlets.List().tag(sync=True)
            #: each rendered view turned by two sliders
            #: (:meth:`course_lib._prefetch.Prefetcher.turn_spec`)
            turns = traitlets.List().tag(sync=True)

            def __init__(self, **kwargs):
                super().__init__(**kwargs)
                self.on_msg(self._on_ready)

            def _on_ready(self, widget, content, buffers):
                if isinstance(content, dict) and content.get("type") == "whole":
                    # the page did not keep a picture the kernel counted on: the next
                    # frame whole, and that picture no longer counted on
                    prefetch = getattr(self.canvas, "_course_prefetch", None)
                    if prefetch is not None:
                        prefetch.sent.pop(prefetch.key(content.get("state") or []), None)
                    self.canvas._course_last = None
                    self.canvas._png_is_old = True
                    self.canvas.draw_idle()
                if isinstance(content, dict) and content.get("type") == "ready":
                    # frames from now on are painted in order; the next one is whole (the
                    # one before may have been dropped by ipympl's own handler)
                    self.canvas._course_last = None
                    self.canvas._course_regions = True
                    prefetch = getattr(self.canvas, "_course_prefetch", None)
                    if prefetch is not None and (self.controls or self.views):
                        prefetch.ready(self)

        _DECODER_CLASS = _FrameDecoder
    return _DECODER_CLASS
