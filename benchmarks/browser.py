"""Where the student is: every explorer timed in JupyterLab in headless chromium.

``python -m benchmarks --browser`` opens every lesson in JupyterLab (the browser tests' server
and chromium set-up, :mod:`tests.browser.lab`), runs it, and for every explorer measures

- **input -> frame**: from the input event (a slider's arrow key, one mouse move of a drag) to
  the first animation frame after the explorer's canvas was painted with the new picture;
  median and 90th percentile of single inputs given one at a time;
- **frames per second** while a slider is dragged with the mouse, or a point or a 3D view is
  dragged, continuously for two seconds (a 60 Hz mouse, moved by the page itself:
  :data:`DRIVE`), how often the input changed meanwhile, and how far the picture is behind
  when the mouse stops (the last frame after the last move);
- for every lesson, the time from opening it to every explorer live (Run All, every widget
  view rendered and showing its first frame from the kernel).

The single inputs are also followed through the whole path, so that the table says where a
frame's time goes: the browser's handling of the input until the websocket message leaves, the
trip to the kernel's subshell thread, the wait for the kernel's main thread, the work there
(the explorer's update and the PNG encoding), the trip back, and the browser's decoding and
painting. Browser times are ``performance.timeOrigin + performance.now()`` and kernel times
``time.time()``: the same clock of the same machine, in milliseconds.
"""
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

#: What the page records: inputs, websocket messages (their msg_id and parent's), frames.
INIT_SCRIPT = r"""
(() => {
  const log = window.__bench = {inputs: [], sends: [], recvs: [], frames: []};
  const now = () => performance.timeOrigin + performance.now();
  const VIEW = '.jp-OutputArea-output > .jupyter-widgets';
  const viewOf = (el) => {
    const view = el.closest(VIEW);
    return view ? [...document.querySelectorAll(VIEW)].indexOf(view) : -1;
  };
  document.addEventListener('keydown', () => log.inputs.push({t: now(), kind: 'key'}), true);
  document.addEventListener('mousemove', (e) => {
    if (e.buttons) log.inputs.push({t: now(), kind: 'move'});
  }, true);
  // frame: the animation frame's own time stamp, the same for every paint in that frame
  const shown = (view, drawn) => requestAnimationFrame(
      (frame) => log.frames.push({view, drawn, shown: now(), frame}));
  const drawImage = CanvasRenderingContext2D.prototype.drawImage;
  CanvasRenderingContext2D.prototype.drawImage = function (...args) {
    const result = drawImage.apply(this, args);
    const canvas = this.canvas;
    if (canvas && canvas.isConnected && canvas.parentElement &&
        canvas.parentElement.classList.contains('jupyter-matplotlib-canvas-div')) {
      shown(viewOf(canvas), now());
    }
    return result;
  };
  new MutationObserver((records) => {
    for (const r of records) {
      const img = r.target;
      if (img.tagName === 'IMG' && img.classList.contains('widget-image') && img.isConnected) {
        const view = viewOf(img);
        img.decode().then(() => shown(view, now())).catch(() => {});
      }
    }
  }).observe(document, {subtree: true, attributes: true, attributeFilter: ['src']});
  // the kernel websocket (protocol v1.kernel.websocket.jupyter.org: binary messages, offsets
  // then channel, header, parent header, metadata, content, buffers)
  const decoder = new TextDecoder();
  const parts = (data) => {
    try {
      const view = new DataView(data);
      const n = Number(view.getBigUint64(0, true));
      const offsets = [];
      for (let k = 0; k < n; k++) offsets.push(Number(view.getBigUint64(8 * (k + 1), true)));
      const part = (k) => decoder.decode(new Uint8Array(data, offsets[k], offsets[k + 1] - offsets[k]));
      return {channel: part(0), header: JSON.parse(part(1)), parent: JSON.parse(part(2)),
              buffers: Math.max(0, n - 5)};
    } catch (e) { return null; }
  };
  const NativeWebSocket = window.WebSocket;
  const send = NativeWebSocket.prototype.send;
  NativeWebSocket.prototype.send = function (data) {
    const t = now();
    if (data instanceof ArrayBuffer) {
      const p = parts(data);
      if (p && p.header.msg_type === 'comm_msg') log.sends.push({t, id: p.header.msg_id});
    }
    return send.call(this, data);
  };
  class TracedWebSocket extends NativeWebSocket {
    constructor(...args) {
      super(...args);
      this.addEventListener('message', (event) => {
        const t = now();
        if (event.data instanceof ArrayBuffer) {
          const p = parts(event.data);
          if (p && p.header.msg_type === 'comm_msg' && p.buffers > 0)
            log.recvs.push({t, parent: p.parent.msg_id, bytes: event.data.byteLength});
        }
      });
    }
  }
  window.WebSocket = TracedWebSocket;
})();
"""

#: What the kernel records: when each comm message reached the subshell, when the main thread
#: started and ended handling it, and when each frame was encoded and sent (by parent msg_id).
KERNEL_PROBE = r"""
import time as _t
from ipywidgets.widgets.widget import _instances as _widgets
from ipympl.backend_nbagg import Canvas as _Canvas
_bench = {"arrive": {}, "start": {}, "end": {}, "encode": [], "sent": []}
_bench_current = [None]
def _trace(event, msg_id):
    _bench[event].setdefault(msg_id, _t.time() * 1000)
    _bench_current[0] = msg_id if event == "start" else None
get_ipython().kernel.shell_handlers["comm_msg"].trace = _trace
for _c in list(_widgets.values()):
    if isinstance(_c, _Canvas) and not hasattr(_c, "_bench_wrapped"):
        _c._bench_wrapped = True
        def _encode(*a, _diff=_c.get_diff_image, **kw):
            t0 = _t.time() * 1000
            out = _diff(*a, **kw)
            _bench["encode"].append((_bench_current[0], t0, _t.time() * 1000))
            return out
        _c.get_diff_image = _encode
        def _sent(data, _send=_c.send_binary):
            _bench["sent"].append((_bench_current[0], _t.time() * 1000))
            return _send(data)
        _c.send_binary = _sent
print("ok")
"""


#: How many times the page has painted a picture the kernel drew ahead (course_lib/_prefetch.py)
KEPT_SHOWN = "() => (window.__coursePictures || []).reduce((n, p) => n + p.shown, 0)"


class Bench:
    """One lesson open in the browser, with the page's and the kernel's records."""

    def __init__(self, notebook, kernel):
        self.notebook, self.kernel, self.page = notebook, kernel, notebook.page

    def log(self):
        return self.page.evaluate("() => window.__bench")

    def frames(self, view):
        return self.page.evaluate("(v) => window.__bench.frames.filter(f => f.view === v)", view)

    def frame_count(self, view):
        return self.page.evaluate(
            "(v) => window.__bench.frames.filter(f => f.view === v).length", view)

    def wait_quiet(self, view, quiet=0.25, timeout=5.0):
        """Until the view has shown no new frame for `quiet` seconds."""
        deadline = time.monotonic() + timeout
        count, since = self.frame_count(view), time.monotonic()
        while time.monotonic() < deadline:
            time.sleep(0.05)
            now = self.frame_count(view)
            if now != count:
                count, since = now, time.monotonic()
            elif time.monotonic() - since >= quiet:
                return

    def single(self, view, act, samples):
        """Latency of `samples` single inputs: ``act(k)`` gives input number k; the first frame
        the view shows after it ends the sample. Returns the samples (dicts of times)."""
        out = []
        for k in range(samples):
            self.wait_quiet(view)
            before = self.frame_count(view)
            inputs_before = self.page.evaluate("() => window.__bench.inputs.length")
            kept_before = self.page.evaluate(KEPT_SHOWN)
            act(k)
            try:
                self.page.wait_for_function(
                    "([v, n]) => window.__bench.frames.filter(f => f.view === v).length > n",
                    arg=[view, before], timeout=3000)
            except Exception:            # no frame: the input changed nothing (at a limit)
                continue
            log = self.log()
            inputs = log["inputs"][inputs_before:]
            frame = [f for f in log["frames"] if f["view"] == view][before]
            if not inputs:
                continue
            t_in = inputs[-1]["t"] if len(inputs) == 1 else inputs[0]["t"]
            sends = [s for s in log["sends"] if s["t"] >= t_in - 1 and s["t"] <= frame["shown"]]
            recvs = [r for r in log["recvs"] if r["t"] >= t_in and r["t"] <= frame["drawn"]]
            out.append({"input": t_in, "drawn": frame["drawn"], "shown": frame["shown"],
                        "send": sends[0] if sends else None,
                        "recv": recvs[-1] if recvs else None,
                        "kept": self.page.evaluate(KEPT_SHOWN) > kept_before})
        return out

    def continuous(self, view, start, path, seconds=2.0, handle=None):
        """Mouse down at `start`, then moved along ``path(fraction)`` for `seconds` by a
        60 Hz mouse in the page (:data:`DRIVE`), mouse up. Returns (frames per second, behind
        at release in ms, moves, share of the frames painted from pictures kept ahead, value
        changes per second). `handle`, a slider's read-out, counts the slider's value changes
        (ipywidgets writes it in the slider's own move handler); without it every move is a
        change."""
        mouse = self.page.mouse
        self.wait_quiet(view)
        mouse.move(*start)
        mouse.down()
        time.sleep(0.3)
        self.wait_quiet(view, quiet=0.2)
        points = [path(i / (RATE * seconds)) for i in range(int(RATE * seconds) + 1)]
        kept_before = self.page.evaluate(KEPT_SHOWN)
        done = self.page.evaluate(DRIVE, {"points": points, "rate": RATE,
                                          "handle": handle.element_handle() if handle else None})
        t0, t1 = done["t0"], done["t1"]
        kept = self.page.evaluate(KEPT_SHOWN) - kept_before
        self.wait_quiet(view, quiet=0.5, timeout=8)
        mouse.move(*points[-1])
        mouse.up()
        # a frame is an animation frame in which the view was painted (twice is once)
        frames = sorted({f["frame"]: f["shown"] for f in self.frames(view)}.values())
        during = [t for t in frames if t0 < t <= t1]
        after = [t for t in frames if t > t1]
        behind = (max(after) - t1) if after else 0.0
        self.wait_quiet(view)
        changes = done["changes"] if handle else done["moves"]
        return (len(during) / ((t1 - t0) / 1000), behind, done["moves"],
                min(1.0, kept / len(during)) if during else 0.0,
                changes / ((t1 - t0) / 1000))


#: Moves of the mouse per second while dragging: what a mouse reports to a page that draws at
#: 60 Hz (chromium hands the page one move per animation frame).
RATE = 60

#: The mouse while dragging, moved by the page itself: a move per animation frame, to where a
#: hand moving at constant speed along the path would be by then (late frames skip points, as
#: a real mouse does). Sending each move from the benchmark through the browser's remote
#: protocol managed only about 25 a second on the 2-core machine, less than a student's mouse.
#: Each move is a pointermove then a mousemove (the buttons held) at the element under the
#: point, as chromium sends them: the sliders listen to the first, the figures to the second.
DRIVE = r"""({points, rate, handle}) => new Promise((resolve) => {
  const now = () => performance.timeOrigin + performance.now();
  const t0 = now();
  let last = -1, moves = 0, changes = 0;
  let value = handle ? handle.textContent : null;
  const move = () => {
    const i = Math.min(points.length - 1, Math.floor((now() - t0) * rate / 1000));
    if (i !== last) {
      const [x, y] = points[i];
      const target = document.elementFromPoint(x, y) || document.body;
      const common = {clientX: x, clientY: y, screenX: x, screenY: y, buttons: 1, button: 0,
                      bubbles: true, cancelable: true, composed: true, view: window};
      target.dispatchEvent(new PointerEvent('pointermove', {...common, pointerId: 1,
                                                            pointerType: 'mouse',
                                                            isPrimary: true}));
      target.dispatchEvent(new MouseEvent('mousemove', common));
      moves += 1;
      last = i;
      if (handle) {
        const now_value = handle.textContent;
        if (now_value !== value) { changes += 1; value = now_value; }
      }
    }
    if (i < points.length - 1) requestAnimationFrame(move);
    else resolve({t0, t1: now(), moves, changes});
  };
  requestAnimationFrame(move);
})"""


#: How far apart the browser's and the kernel's clocks may read the same moment (ms): a stage
#: shorter than minus this was matched to the wrong input.
CLOCK_SLACK_MS = 2


def _breakdown(samples, kernel_log):
    """Median milliseconds of each stage of a frame's path, over the samples that could be
    followed from the input to the frame (the frame's message names the input's message as its
    parent, or the newer one it was merged into)."""
    stages = {"input -> message sent": [], "to the kernel (subshell)": [],
              "wait for the main thread": [], "update (before encoding)": [],
              "PNG encode": [], "back to the browser": [], "decode + draw": [],
              "until painted": []}
    arrive, start = kernel_log["arrive"], kernel_log["start"]
    encodes = sorted((t0, t1) for _, t0, t1 in kernel_log["encode"])
    sents = sorted(t for _, t in kernel_log["sent"])
    for s in samples:
        if s["send"] is None or s["recv"] is None:
            continue
        parent, own = s["recv"]["parent"], s["send"]["id"]
        if parent not in start or own not in arrive:
            continue
        encode = next(((t0, t1) for t0, t1 in encodes if t0 >= start[parent]), None)
        if encode is None or encode[1] > s["recv"]["t"]:
            continue
        sent = next((t for t in sents if t >= encode[1]), encode[1])
        times = [s["send"]["t"] - s["input"], arrive[own] - s["send"]["t"],
                 start[parent] - arrive[own], encode[0] - start[parent], encode[1] - encode[0],
                 s["recv"]["t"] - sent, s["drawn"] - s["recv"]["t"], s["shown"] - s["drawn"]]
        if min(times) < -CLOCK_SLACK_MS:
            # out of order (a stage ends before it begins): the frame was matched to a trace
            # that is not its input's, so it cannot be followed; leave it out
            continue
        for name, ms in zip(stages, times):
            stages[name].append(ms)
    return {name: (statistics.median(v) if v else None) for name, v in stages.items()}


def measure_lesson(browser, server, path, samples, seconds, only=None):
    """Rows of one lesson (one per explorer control measured) and its time to live."""
    from tests.browser.lab import (WIDGET_VIEW, NotebookPage, PageKernel,
                                   expected_widget_cells, page_explorers)

    notebook = NotebookPage(browser, server, path)
    page = notebook.page
    page.add_init_script(INIT_SCRIPT)
    expected = len(expected_widget_cells(path))
    began = time.monotonic()
    notebook.open()
    opened = time.monotonic()
    notebook.menu("Edit", "Clear Outputs of All Cells")
    page.wait_for_function("() => !document.querySelector('.jp-OutputArea-output')",
                           timeout=30_000)
    run_began = time.monotonic()
    notebook.menu("Run", "Run All Cells")
    deadline = time.monotonic() + 300
    while time.monotonic() < deadline:
        live = page.evaluate(
            """(sel) => { const views = [...document.querySelectorAll(sel)];
                 const shown = new Set(window.__bench.frames.map(f => f.view));
                 // a picture set before its element was attached is no mutation: count an
                 // image widget as live once it holds a decoded picture
                 const pictured = (v) => [...v.querySelectorAll('img.widget-image')]
                     .some(i => i.complete && i.naturalWidth > 0);
                 return views.map((v, k) => !v.querySelector('canvas, img.widget-image')
                                            || shown.has(k) || pictured(v)); }""", WIDGET_VIEW)
        if len(live) >= expected and all(live):
            break
        time.sleep(0.1)
    live_at = time.monotonic()
    notebook.page.wait_for_selector(".jp-Notebook-ExecutionIndicator[data-status='idle']",
                                    timeout=300_000)
    lesson = {"lesson": Path(path).stem, "explorers": expected,
              "kernel_s": opened - began, "run_all_s": live_at - run_began,
              "open_to_live_s": live_at - began}
    rows = []
    if not expected:
        notebook.close()
        return rows, lesson
    time.sleep(1.0)
    kernel = PageKernel(server, path)
    try:
        explorers = page_explorers(notebook, kernel)
        kernel.run(KERNEL_PROBE)
        bench = Bench(notebook, kernel)
        views = page.locator(WIDGET_VIEW)
        for k, explorer in enumerate(explorers):
            if only is not None and explorer["class"] not in only:
                continue
            view = views.nth(k)
            view.scroll_into_view_if_needed()
            time.sleep(0.3)
            rows += measure_explorer(bench, k, view, explorer, samples, seconds)
            page.mouse.move(1, 1)
    finally:
        kernel.close()
        notebook.close()
    return rows, lesson


def measure_explorer(bench, k, view, explorer, samples, seconds):
    name = explorer["class"]
    page = bench.page
    rows = []
    sliders = view.locator(".widget-slider")
    chosen = None
    for s in range(sliders.count()):
        handle = sliders.nth(s).locator(".noUi-handle").first
        disabled = sliders.nth(s).locator(".noUi-target[disabled]").count() > 0
        if handle.count() and handle.is_visible() and not disabled:
            chosen = s
            break
    if chosen is not None:
        slider = sliders.nth(chosen)
        label = slider.locator(".widget-label").first.inner_text().strip()
        handle = slider.locator(".noUi-handle").first
        low, now, high = (float(handle.get_attribute(f"aria-value{end}"))
                          for end in ("min", "now", "max"))
        up, down = ("ArrowRight", "ArrowLeft") if high - now >= now - low else \
            ("ArrowLeft", "ArrowRight")
        handle.focus()

        def press(i):
            page.keyboard.press(up if i % 2 == 0 else down)
        got = bench.single(k, press, samples)
        track = slider.locator(".noUi-target").first.bounding_box()
        box = handle.bounding_box()
        x0, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        span = 0.3 * track["width"]
        # towards the farther end, as the handle lies now (its aria-valuenow can lag behind
        # the key presses above: a 3-value slider at its top read "middle" and was dragged
        # past its end, changing nothing)
        direction = 1 if x0 <= track["x"] + track["width"] / 2 else -1

        def along(f):                     # out and back twice
            phase = (2 * f) % 1.0
            return (x0 + direction * span * (1 - abs(2 * phase - 1)), y)
        fps, behind, moves, kept, changes = bench.continuous(
            k, (x0, y), along, seconds, handle=slider.locator(".widget-readout").first)
        rows.append(_row(name, f"slider '{label}'", got, fps, behind, moves, kept, changes,
                         bench.kernel.json("import json; print(json.dumps(_bench))")))
    canvas = view.locator(".jupyter-matplotlib-canvas-div canvas").last
    for gesture in explorer["gestures"]:
        if gesture["kind"] == "click":
            continue
        # the whole figure in sight: a point lying outside the window gets no mouse (the
        # slider rows above may have scrolled a tall figure's top or bottom out of it)
        canvas.evaluate("(el) => el.scrollIntoView({block: 'center'})")
        box = canvas.bounding_box()
        at = lambda fx, fy: (box["x"] + fx * box["width"], box["y"] + fy * box["height"])
        (sx, sy), (ex, ey) = at(*gesture["start"]), at(*gesture["end"])
        mouse = page.mouse
        mouse.move(sx, sy)
        mouse.down()
        bench.wait_quiet(k)
        steps = max(samples, 2)

        def step(i):
            f = (i + 1) / steps
            mouse.move(sx + (ex - sx) * f, sy + (ey - sy) * f)
        got = bench.single(k, step, samples)
        mouse.up()
        bench.wait_quiet(k)

        # the point now lies at the end of the gesture: drag it back and forth from there
        def along(f):
            phase = 1 - abs(2 * ((2 * f) % 1.0) - 1)
            return (ex + (sx - ex) * phase, ey + (sy - ey) * phase)
        # a rendered view turned through its sliders changes as often as their values do
        # (the first, the azimuth, for this sideways drag): counted on its read-out
        readout = None
        for s in range(sliders.count()):
            label = sliders.nth(s).locator(".widget-label").first
            if gesture.get("sliders") and label.count() and \
                    label.inner_text().strip() == gesture["sliders"][0]:
                readout = sliders.nth(s).locator(".widget-readout").first
        fps, behind, moves, kept, changes = bench.continuous(k, (ex, ey), along, seconds,
                                                             handle=readout)
        rows.append(_row(name, f"{gesture['kind']} {gesture['what']}", got, fps, behind, moves,
                         kept, changes,
                         bench.kernel.json("import json; print(json.dumps(_bench))")))
    return rows


def _row(name, what, samples, fps, behind, moves, kept, changes, kernel_log):
    latency = [s["shown"] - s["input"] for s in samples]
    return {"explorer": name, "input": what, "samples": len(latency),
            "kept_single": sum(s["kept"] for s in samples), "kept_continuous": kept,
            "median_ms": statistics.median(latency) if latency else float("nan"),
            "p90_ms": float(np.percentile(latency, 90)) if latency else float("nan"), "fps": fps, "behind_ms": behind,
            "moves": moves, "changes_per_s": changes, "breakdown": _breakdown(samples, kernel_log)}


def run(quick=False, notebooks=None, only=None):
    """Measure every lesson (or the given notebook paths; only the explorer classes named in
    `only`, if given); returns (rows, lessons)."""
    from playwright.sync_api import sync_playwright

    from tests.browser.lab import LabServer, launch_browser

    paths = notebooks or sorted(p.relative_to(ROOT).as_posix()
                                for p in (ROOT / "notebooks").glob("*.ipynb"))
    samples, seconds = (5, 1.0) if quick else (15, 2.0)
    rows, lessons = [], []
    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "lab").mkdir()
        server = LabServer(Path(tmp) / "lab", windowing="contentVisibility").start()
        try:
            with sync_playwright() as playwright:
                context = launch_browser(playwright, Path(tmp) / "profile")
                try:
                    for path in paths:
                        got, lesson = measure_lesson(context, server, path, samples, seconds, only)
                        rows += got
                        lessons.append(lesson)
                        print(f"{lesson['lesson']}: live in {lesson['open_to_live_s']:.1f} s; "
                              + "; ".join(f"{r['explorer']} {r['input']}: "
                                          f"{r['median_ms']:.0f} ms, {r['fps']:.0f} fps"
                                          for r in got), flush=True)
                finally:
                    context.close()
        finally:
            server.stop()
    return rows, lessons


TARGET_MS, TARGET_FPS = 30, 30
SECTION = "## In the browser"


def _ms(value):
    return "–" if value is None or value != value else f"{value:.0f}"


def fluent(row):
    """Does a row keep up while dragging: at least :data:`TARGET_FPS` frames a second, or, where
    the input itself changes less often than that (a slider of few values), a frame for (at
    least 90 % of) every change? A slider that moves four times a second cannot show thirty
    different pictures."""
    changes = row.get("changes_per_s", float("inf"))
    # a drag that changed nothing measured nothing
    return changes > 0 and row["fps"] >= min(TARGET_FPS, 0.9 * changes)


def meets(row):
    return row["median_ms"] <= TARGET_MS and fluent(row)


def report(rows, lessons, machine):
    """The Markdown section of results.md for the browser measurements."""
    met = [r for r in rows if meets(r)]
    lines = [
        SECTION, "",
        f"Measured by `python -m benchmarks --browser` on {machine}: JupyterLab with its default "
        "settings in headless chromium (software rendering, 1400 x 1000), every lesson run, "
        "every explorer driven with the keyboard and the mouse as a student does. Input -> "
        "frame: from the key press or mouse move to the first animation frame after the "
        "explorer's canvas was painted with the answer (single inputs, one at a time). "
        "Continuous: a slider handle dragged with the mouse, or a point or a 3D view dragged, "
        f"for two seconds by a {RATE} Hz mouse moved in the page; changes = how often a second "
        "the input changed (a slider's value; every move of a drag); behind = how long the "
        "picture kept changing after the mouse stopped. Kept: how many of the single inputs, "
        "and what share of the frames while dragging, the page answered with a picture the "
        "kernel had drawn ahead (course_lib/_prefetch.py) instead of waiting for the kernel. "
        f"Targets: median <= {TARGET_MS} ms, and >= {TARGET_FPS} fps while dragging (or, where "
        f"the input changes less than {TARGET_FPS} times a second, a frame for every change); "
        f"{len(met)} of {len(rows)} rows meet both.", "",
        "| explorer | input | input -> frame median (ms) | 90th pct (ms) | continuous (fps) "
        "| changes (/s) | behind at release (ms) | kept: single | kept: dragging "
        "| targets met |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for r in rows:
        changes = r.get("changes_per_s")
        lines.append(f"| {r['explorer']} | {r['input']} | {_ms(r['median_ms'])} | "
                     f"{_ms(r['p90_ms'])} | {r['fps']:.0f} | {_ms(changes)} | "
                     f"{_ms(r['behind_ms'])} | {r.get('kept_single', 0)}/{r['samples']} | "
                     f"{100 * r.get('kept_continuous', 0):.0f} % | "
                     f"{'yes' if meets(r) else 'no'} |")
    stages = list(rows[0]["breakdown"]) if rows else []
    lines += ["", "### Where a frame's time goes", "",
              "Medians (ms) of the single inputs above that the kernel answered (not a picture "
              "kept ahead), followed through the page's websocket and the kernel: browser "
              "clock and kernel clock are the same machine's.", "",
              "| explorer | input | " + " | ".join(stages) + " |",
              "|---|---|" + "---:|" * len(stages)]
    for r in rows:
        lines.append(f"| {r['explorer']} | {r['input']} | "
                     + " | ".join(_ms(r["breakdown"][s]) for s in stages) + " |")
    lines += ["", "### Opening a lesson", "",
              "From opening the notebook to its kernel ready, then from Run All to every "
              "explorer showing its first frame from the kernel.", "",
              "| lesson | explorers | kernel ready (s) | Run All -> all live (s) "
              "| open -> all live (s) |", "|---|---:|---:|---:|---:|"]
    for lesson in lessons:
        lines.append(f"| {lesson['lesson']} | {lesson['explorers']} | {lesson['kernel_s']:.1f} "
                     f"| {lesson['run_all_s']:.1f} | {lesson['open_to_live_s']:.1f} |")
    return "\n".join(lines) + "\n"


def with_section(text, section):
    """`text` (results.md) with its browser section replaced by `section` (or added)."""
    head = text.split(SECTION)[0].rstrip("\n")
    return head + "\n\n" + section if section else head + "\n"
