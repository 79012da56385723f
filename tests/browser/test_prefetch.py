"""Pictures drawn ahead (course_lib/_prefetch.py) in a real browser: a slider step is answered
from the page's kept pictures at once, each kept picture is the one the kernel then draws for
the same values (it finds the same checksum and names the picture instead of sending it), a
frame the page has already moved past is not painted, and the mouse on the figure (a control
point dragged) throws the kept pictures away until new ones come."""
import json
import time

import pytest

from .lab import NotebookPage, PageKernel, figure_canvas, page_explorers, widget_view

LESSON = "notebooks/ch07_curves_surfaces.ipynb"

# The kept pictures of the explorer whose first control has model id `id`
_KEPT = "(id) => (window.__coursePictures || []).find((p) => p.ids[0] === id)"

_STATS = "(id) => { const p = (%s)(id); return p && {entries: p.entries.size, shown: p.shown, " \
         "stale: p.stale, same: p.same, pressed: p.pressed, need: p.need, epoch: p.epoch, " \
         "current: p.current(), kernel: p.kernelKey}; }" % _KEPT

# The kept picture for the page's current values against the kernel's last frame (for the
# same values), pixel by pixel; and the canvas the student sees against the kernel's frame.
_COMPARE = r"""async (id) => {
  const p = (%s)(id);
  const pixels = (source) => {
    const c = new OffscreenCanvas(p.copy.width, p.copy.height);
    const ctx = c.getContext('2d', {willReadFrequently: true});
    ctx.drawImage(source, 0, 0);
    return ctx.getImageData(0, 0, c.width, c.height).data;
  };
  const differ = (a, b) => { let n = 0; for (let i = 0; i < a.length; i += 4)
    if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) n++; return n; };
  const kernel = pixels(p.copy);
  const entry = p.entries.get(p.current());
  const kept = entry ? pixels(await createImageBitmap(entry.blob)) : null;
  return {sameValues: p.kernelKey === p.current(), kept: kept && differ(kept, kernel),
          shown: differ(pixels(p.canvas.offscreen_canvas), kernel)};
}""" % _KEPT


def _wait(page, ident, test, timeout=30.0):
    deadline = time.monotonic() + timeout
    while True:
        stats = page.evaluate(_STATS, ident)
        if stats and test(stats) or time.monotonic() > deadline:
            return stats
        time.sleep(0.1)


def _opened(lab, browser, lesson, name):
    """The lesson run in the page, its kernel, and the widget view and first kept control's
    model id of its explorer of class `name` (which must draw pictures ahead)."""
    notebook = NotebookPage(browser, lab, lesson).open().run_all()
    kernel = PageKernel(lab, lesson)
    try:
        explorers = page_explorers(notebook, kernel)
        k = [e["class"] for e in explorers].index(name)
        assert explorers[k]["kept"], f"{name} draws no pictures ahead"
        yield notebook, kernel, widget_view(notebook, k), explorers[k]["kept"][0]
    finally:
        kernel.close()
        notebook.close()


@pytest.fixture(scope="module")
def bezier(lab, browser):
    yield from _opened(lab, browser, LESSON, "BezierExplorer")


def _steady(page, ident):
    """Until the kernel's last frame shows the page's values and nothing new comes."""
    last = None
    for _ in range(100):
        stats = page.evaluate(_STATS, ident)
        if stats["kernel"] == stats["current"] and stats == last:
            return stats
        last = stats
        time.sleep(0.2)
    return last


def test_a_slider_step_is_answered_by_a_kept_picture_that_the_kernel_then_confirms(bezier):
    notebook, kernel, view, ident = bezier
    page = notebook.page
    stats = _wait(page, ident, lambda s: s["entries"] >= 2)
    assert stats["entries"] >= 2, f"no pictures kept ahead: {stats}"
    slider = view.locator(".widget-slider").first
    slider.locator(".noUi-handle").first.focus()
    for step in range(6):
        before = page.evaluate(_STATS, ident)
        page.keyboard.press("ArrowRight" if step < 4 else "ArrowLeft")
        after = page.evaluate(_STATS, ident)
        # painted in the key's own handler: before any frame could come from the kernel
        assert after["shown"] == before["shown"] + 1, (step, before, after)
        assert after["current"] != before["current"]
        steady = _steady(page, ident)
        # the kernel drew the step itself and found it the very picture kept (same checksum):
        # it named it instead of sending it again
        assert steady["same"] > before["same"], (step, before, steady)
        got = page.evaluate(_COMPARE, ident)
        assert got["sameValues"], got
        assert got["kept"] == 0, f"step {step}: the kept picture differs from the kernel's " \
                                 f"in {got['kept']} pixels"
        assert got["shown"] == 0, f"step {step}: the student sees {got['shown']} pixels " \
                                  "other than the kernel's frame"
    assert notebook.console_errors == []


def test_frames_the_page_has_moved_past_are_not_painted(bezier):
    notebook, kernel, view, ident = bezier
    page = notebook.page
    _steady(page, ident)
    slider = view.locator(".widget-slider").first
    slider.locator(".noUi-handle").first.focus()
    page.keyboard.press("ArrowRight")     # t is the control moved last: its range is drawn
    _wait(page, ident, lambda s: s["entries"] >= 12)
    _steady(page, ident)
    before = page.evaluate(_STATS, ident)
    painted = page.evaluate("(id) => (%s)(id).painted.length" % _KEPT, ident)
    # a slow kernel: each value of t takes 0.2 s more to draw, so that the frame of the first
    # step arrives long after the page has gone on (the kernel merges the steps in between)
    cell = _cell_of(kernel, "BezierExplorer")
    kernel.run("import time\n_course_slow = lambda change: time.sleep(0.2)\n"
               f"Out[{cell}].t.observe(_course_slow, names='value')")
    try:
        for _ in range(8):
            page.keyboard.press("ArrowLeft")
            time.sleep(0.03)
        stats = _steady(page, ident)
    finally:
        kernel.run(f"Out[{cell}].t.unobserve(_course_slow, names='value')")
    got = page.evaluate(_COMPARE, ident)
    assert got["sameValues"] and got["shown"] == 0, got
    # the pictures painted meanwhile went one way only: never back to a value left behind
    t = _t_index(kernel)
    keys = page.evaluate("([id, n]) => (%s)(id).painted.slice(n)" % _KEPT, [ident, painted])
    ts = [json.loads(key)[t] for key in keys if key is not None]
    assert len(ts) >= 2 and ts == sorted(ts, reverse=True), ts
    # the kernel answered some of the eight values after the page had moved on
    print(f"pictures painted: t = {ts}; stale kernel frames not painted: "
          f"{stats['stale'] - before['stale']}")


# Of the kept pictures `steps` steps of t (step 0.01) beyond the page's values, which are held
# and which decoded
_AHEAD = r"""([id, t, steps]) => {
  const p = (%s)(id);
  const now = JSON.parse(p.current());
  return steps.map((k) => {
    const values = [...now];
    values[t] = Number((now[t] + k * 0.01).toFixed(10));
    const entry = p.entries.get(JSON.stringify(values));
    return entry ? !!entry.bitmap : null;
  });
}""" % _KEPT

_UNDECODE = """(id) => { const p = (%s)(id);
  for (const e of p.entries.values()) { if (e.bitmap) e.bitmap.close();
                                        e.bitmap = null; e.decoding = null; }
  p.decoded = []; }""" % _KEPT


def test_a_slider_moving_has_its_next_kept_pictures_decoded_before_they_are_reached(bezier):
    """Decoding a kept picture takes 5-15 ms: begun only when the slider reaches it, the page
    has often moved on by then. The next values the way the slider moves are decoded ahead."""
    notebook, kernel, view, ident = bezier
    page = notebook.page
    _steady(page, ident)
    t = _t_index(kernel)
    slider = view.locator(".widget-slider").first
    slider.locator(".noUi-handle").first.focus()
    page.keyboard.press("ArrowLeft")
    page.keyboard.press("ArrowRight")          # t moves up: the kernel draws on that way
    deadline = time.monotonic() + 30
    while None in page.evaluate(_AHEAD, [ident, t, [1, 2, 3, 4]]):
        assert time.monotonic() < deadline, page.evaluate(_AHEAD, [ident, t, [1, 2, 3, 4]])
        time.sleep(0.1)
    _steady(page, ident)
    page.evaluate(_UNDECODE, ident)            # as if they had come long before
    page.keyboard.press("ArrowRight")
    deadline = time.monotonic() + 5
    while page.evaluate(_AHEAD, [ident, t, [1, 2, 3]]) != [True] * 3 and \
            time.monotonic() < deadline:
        time.sleep(0.05)
    assert page.evaluate(_AHEAD, [ident, t, [1, 2, 3]]) == [True] * 3
    assert notebook.console_errors == []


def test_the_mouse_on_the_figure_forgets_the_kept_pictures_until_new_ones_come(bezier):
    notebook, kernel, view, ident = bezier
    page = notebook.page
    _wait(page, ident, lambda s: s["entries"] >= 2)
    canvas = figure_canvas(view)
    box = canvas.bounding_box()
    # the default P1 of widgets/bezier.py (xlim = ylim = (-0.5, 5.5), left 0.1, right 0.98,
    # bottom 0.08, top 0.94)
    fx = 0.1 + (1.0 + 0.5) / 6 * 0.88
    fy = 1 - (0.08 + (3.8 + 0.5) / 6 * 0.86)
    page.mouse.move(box["x"] + fx * box["width"], box["y"] + fy * box["height"])
    page.mouse.down()
    held = _wait(page, ident, lambda s: s["pressed"], timeout=5)
    assert held["pressed"] and held["entries"] == 0, held
    page.mouse.move(box["x"] + (fx + 0.2) * box["width"], box["y"] + (fy + 0.2) * box["height"],
                    steps=8)
    page.mouse.up()
    moved = kernel.json("import json; print(json.dumps(Out[%d].state.points.tolist()))"
                        % _cell_of(kernel, "BezierExplorer"))
    assert abs(moved[1][0] - 1.0) > 0.3, f"the drag did not move P1: {moved}"
    stats = _wait(page, ident, lambda s: not s["pressed"] and s["entries"] >= 2)
    assert stats["need"] >= 1 and stats["entries"] >= 2, stats
    # the new pictures show the moved point: the next step's kept picture is the kernel's
    # (once the kernel has drawn it: the pictures kept first may lie the other way, where t
    # moved last)
    t = _t_index(kernel)
    deadline = time.monotonic() + 30
    while page.evaluate(_AHEAD, [ident, t, [1]]) == [None]:
        assert time.monotonic() < deadline, "the picture one step right never came"
        time.sleep(0.1)
    slider = view.locator(".widget-slider").first
    slider.locator(".noUi-handle").first.focus()
    page.keyboard.press("ArrowRight")
    _steady(page, ident)
    got = page.evaluate(_COMPARE, ident)
    assert got["sameValues"] and got["kept"] == 0 and got["shown"] == 0, got


def _t_index(kernel):
    """Where the t slider's value is among the values a kept picture is filed under."""
    return int(kernel.run(
        "print([c.description for c, _ in Out[%d].fig.canvas._course_prefetch.controls]"
        ".index('t'))" % _cell_of(kernel, "BezierExplorer")).strip())


def _cell_of(kernel, name):
    # the latest: another test of this browser session may have run the lesson in the same
    # kernel before (its explorers are still in Out, as the mouse and keys left them)
    return int(kernel.run("print(max(n for n, v in Out.items() if type(v).__name__ == %r))"
                          % name).strip())


# The page's copy of the first 3D view of the explorer whose first control has model id `id`
_VIEW = "(id) => { const p = (%s)(id); return {value: p.views[0].value, box: p.views[0].box, " \
        "turned: p.turned, shown: p.shown, entries: p.entries.size, turning: !!p.turn, " \
        "current: p.current(), kernel: p.kernelKey}; }" % _KEPT


@pytest.fixture(scope="module")
def gimbal(lab, browser):
    yield from _opened(lab, browser, "notebooks/ch03_transformations.ipynb", "GimbalExplorer")


# Whether the page holds the pictures of the 3D view `turns` whole degrees of azimuth either side
# of its present one (the other values as they are)
_HOLDS_TURNS = r"""([id, turns]) => {
  const p = (%s)(id);
  const now = JSON.parse(p.current());
  const view = now.length - 1;
  const [elev, azim] = now[view];
  for (let d = -turns; d <= turns; d++) {
    if (d === 0) continue;
    const key = JSON.stringify([...now.slice(0, view), [elev, azim + d]]);
    if (!p.entries.has(key)) return false;
  }
  return true;
}""" % _KEPT


def _holds_turns(page, ident, turns, timeout=60.0):
    """Until the kernel has drawn (and the page keeps) the views `turns` degrees either side."""
    deadline = time.monotonic() + timeout
    while not page.evaluate(_HOLDS_TURNS, [ident, turns]):
        assert time.monotonic() < deadline, (
            f"the views {turns} degrees either side never came",
            page.evaluate("(id) => { const p = (%s)(id); return [p.current(), "
                          "[...p.entries.keys()].slice(-8)]; }" % _KEPT, ident))
        time.sleep(0.1)


def _kernel_view(kernel):
    return kernel.json("import json; ax = next(a for a in Out[%d].fig.axes if a.name == '3d');"
                       " print(json.dumps([float(ax.elev), float(ax.azim)]))"
                       % _cell_of(kernel, "GimbalExplorer"))


def test_a_3d_view_turned_by_the_mouse_is_answered_by_kept_pictures_and_the_kernel_agrees(
        gimbal):
    notebook, kernel, view, ident = gimbal
    page = notebook.page
    _wait(page, ident, lambda s: s["entries"] >= 4)
    start = page.evaluate(_VIEW, ident)
    assert start["value"] == _kernel_view(kernel), (start, _kernel_view(kernel))
    canvas = figure_canvas(view)
    box = canvas.bounding_box()
    left, top, right, bottom = start["box"]
    # the middle of the 3D axes; one degree of azimuth is 1/180 of its width
    x = box["x"] + (left + right) / 2 * box["width"]
    y = box["y"] + (top + bottom) / 2 * box["height"]
    degree = (right - left) * box["width"] / 180
    page.mouse.move(x, y)
    page.mouse.down()
    elev, azim = start["value"]
    for k, turn in enumerate((1.2, 3.3, -2.2)):       # degrees to the right (azimuth falls)
        # while the button is held and the mouse rests, the kernel draws the next views ahead
        # (on a loaded machine a view can take 0.1 s): the turn below (3.3 degrees at most, so
        # within 4 degrees on the whole-pixel mouse) reaches one of them
        _holds_turns(page, ident, 4)
        before = page.evaluate(_VIEW, ident)
        x += turn * degree
        page.mouse.move(x, y)
        after = page.evaluate(_VIEW, ident)
        azim -= turn
        # the page turned its copy, in whole degrees (the browser moves the mouse by whole
        # pixels: within a degree of the turn asked for)...
        assert after["value"][0] == elev and abs(after["value"][1] - azim) <= 1, (k, after)
        assert after["turned"] == before["turned"] + 1
        # ... and painted the kept picture (in the move's own handler if it was decoded, a
        # decoding later if not)
        painted = _wait(page, ident, lambda s: s["shown"] > before["shown"], timeout=2)
        assert painted["shown"] == before["shown"] + 1, (k, before, painted)
        # the kernel turned its axes to the very view the page computed
        deadline = time.monotonic() + 30
        while _kernel_view(kernel) != after["value"] and time.monotonic() < deadline:
            time.sleep(0.2)
        assert _kernel_view(kernel) == after["value"], (k, after)
    page.mouse.up()
    steady = _steady(page, ident)
    # the kernel's frame is the picture kept for the view both sides reached
    assert _kernel_view(kernel) == page.evaluate(_VIEW, ident)["value"]
    assert steady["kernel"] == steady["current"], steady
    got = page.evaluate(_COMPARE, ident)
    assert got["sameValues"] and got["kept"] == 0 and got["shown"] == 0, got
    assert notebook.console_errors == []


# The toolbar's chosen action ('pan', 'zoom' or '') as the page's canvas model has it
_ACTION = "(id) => { const t = (%s)(id).canvas.get('toolbar'); " \
          "return t && t.get ? t.get('_current_action') : null; }" % _KEPT


def test_with_the_toolbars_pan_chosen_a_drag_on_the_3d_axes_predicts_no_turn(gimbal):
    """The toolbar's pan (or zoom) makes a drag on the axes pan it: the kernel turns nothing,
    so the page must neither turn its copy of the view nor paint a kept view for the drag."""
    notebook, kernel, view, ident = gimbal
    page = notebook.page
    _steady(page, ident)
    before = page.evaluate(_VIEW, ident)
    start = _kernel_view(kernel)
    canvas = figure_canvas(view)
    box = canvas.bounding_box()
    left, top, right, bottom = before["box"]
    x = box["x"] + (left + right) / 2 * box["width"]
    y = box["y"] + (top + bottom) / 2 * box["height"]
    page.mouse.move(x, y)                             # the toolbar fades in over the figure
    pan = view.locator("button[title^='Left button pans']").first
    pan.click()
    cell = _cell_of(kernel, "GimbalExplorer")
    mode = "print(next(a for a in Out[%d].fig.axes if a.name == '3d').get_navigate_mode())" \
        % cell
    deadline = time.monotonic() + 30
    while kernel.run(mode).strip() != "PAN" and time.monotonic() < deadline:
        time.sleep(0.2)
    # and the page's copy of the toolbar, which the page reads at the press, has heard of it
    # (the kernel sets it after the click, and the page only when that change comes back)
    while page.evaluate(_ACTION, ident) != "pan" and time.monotonic() < deadline:
        time.sleep(0.1)
    try:
        assert kernel.run(mode).strip() == "PAN"
        assert page.evaluate(_ACTION, ident) == "pan"
        page.mouse.move(x, y)
        page.mouse.down()
        for k in range(1, 11):                        # 20 degrees' worth of a turn
            page.mouse.move(x + k * 2 * (right - left) * box["width"] / 180, y)
            time.sleep(0.03)
        during = page.evaluate(_VIEW, ident)
        page.mouse.up()
        assert not during["turning"] and during["turned"] == before["turned"], during
        assert during["value"] == before["value"], during
        assert _kernel_view(kernel) == start
    finally:
        page.mouse.move(x, y)
        pan.click()
        while kernel.run(mode).strip() != "None" and time.monotonic() < deadline + 30:
            time.sleep(0.2)
    assert notebook.console_errors == []


@pytest.fixture(scope="module")
def ray_tracer(lab, browser):
    yield from _opened(lab, browser, "notebooks/ch15_ray_tracing.ipynb", "RayTracerExplorer")


_HAS = "([id, key]) => (%s)(id).entries.has(key)" % _KEPT
# Marks every picture the page keeps now, and returns their values
_MARK = "(id) => { const p = (%s)(id); for (const e of p.entries.values()) e.marked = true; " \
        "return [...p.entries.keys()]; }" % _KEPT
# The values of the marked pictures still kept (not forgotten, nor received again since)
_MARKED = "(id) => [...(%s)(id).entries].filter(([k, e]) => e.marked).map(([k]) => k)" % _KEPT


def test_a_ray_tracers_full_image_replaces_only_the_preview_kept_for_its_values(ray_tracer):
    """A key on the ray tracer's depth slider paints the preview kept for the new depth at
    once; the kernel's preview is that picture; then the full image comes, and the page shows
    it and forgets the preview kept for those values (the kernel said "drop"), but not the
    previews kept for the other values."""
    notebook, kernel, view, ident = ray_tracer
    page = notebook.page
    stats = _wait(page, ident, lambda s: s["entries"] >= 4)
    assert stats["entries"] >= 4, f"no previews kept ahead: {stats}"
    cell = _cell_of(kernel, "RayTracerExplorer")
    slider = view.locator(".widget-slider").first
    slider.locator(".noUi-handle").first.focus()
    before = page.evaluate(_STATS, ident)
    kept = page.evaluate(_MARK, ident)
    page.keyboard.press("ArrowRight")
    after = page.evaluate(_STATS, ident)
    key = after["current"]
    assert key in kept
    assert after["shown"] == before["shown"] + 1, (before, after)     # painted in the handler
    # the kernel's full image, traced once the slider has rested
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and kernel.run(
            f"print(Out[{cell}].pending or Out[{cell}].current['preview'])").strip() != "False":
        time.sleep(0.2)
    steady = _steady(page, ident)
    assert steady["kernel"] == key == steady["current"], steady
    assert steady["same"] > before["same"], (before, steady)    # its preview: the kept one
    assert not page.evaluate(_HAS, [ident, key]), "the preview kept for the full image's " \
                                                   "values is still kept"
    # every other picture kept before the key is still kept, the very same (not forgotten
    # and sent again)
    assert sorted(page.evaluate(_MARKED, ident)) == sorted(k for k in kept if k != key)
    got = page.evaluate(_COMPARE, ident)
    assert got["sameValues"] and got["kept"] is None and got["shown"] == 0, got
    assert notebook.console_errors == []
