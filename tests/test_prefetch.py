"""Pictures drawn ahead (course_lib/_prefetch.py), without a browser.

The page shows a kept picture in place of the kernel's frame, so each one must be exactly the
frame the kernel draws when the student really sets that value; drawing one must leave the
explorer, its widgets and its figure as they were, and send nothing but the picture itself.
"""
import io
import json
import zlib
from unittest import mock

import ipywidgets as w
import numpy as np
import pytest
from PIL import Image

from course_lib import _prefetch
from test_widget_frames import _explorers      # every explorer class of course_lib.widgets

#: Plan entries checked per explorer: the first steps a student takes, both sides of the
#: control moved, and one further out (and then one step of every other control).
CHECKED = 6


def _live(explorer, control, name, value):
    """The frame drawn when `control` is really set to `value` (as the browser's message
    does, the draw request answered at once), and everything set back the same way."""
    canvas = explorer.fig.canvas
    old = getattr(control, name)
    canvas.draw_idle = canvas.draw
    try:
        setattr(control, name, value)
        frame = np.asarray(canvas.get_renderer().buffer_rgba()).copy()
        setattr(control, name, old)
    finally:
        del canvas.draw_idle
    return frame


def _turned(explorer, view, value):
    """The frame drawn when the mouse turns `view` (a :class:`course_lib._prefetch.View`) to
    `value`, as the browser's mouse messages do (press in the middle of the axes, one move,
    release), and the view set back."""
    from matplotlib.backend_bases import MouseEvent

    ax, canvas = view.ax, explorer.fig.canvas
    old = view.value
    canvas.draw()
    box = ax.bbox
    x0, y0 = box.x0 + box.width / 2, box.y0 + box.height / 2
    # 'azel': the azimuth turns back 180 degrees per width, the elevation per height
    x1 = x0 - (value[1] - old[1]) / 180 * box.width
    y1 = y0 - (value[0] - old[0]) / 180 * box.height
    for name, x, y in (("button_press_event", x0, y0), ("motion_notify_event", x1, y1),
                       ("button_release_event", x1, y1)):
        canvas.callbacks.process(name, MouseEvent(name, canvas, x, y, 1))
    assert view.value == tuple(map(float, value)), f"the mouse turned to {view.value}, " \
        f"not {value}"
    canvas.draw()
    frame = np.asarray(canvas.get_renderer().buffer_rgba()).copy()
    view.value = old
    canvas.draw()
    return frame


def _states(explorer):
    canvas = explorer.fig.canvas
    return [x.get_state() for x in _prefetch._tree(explorer.widget) if x is not canvas]


@pytest.mark.parametrize("cls", _explorers(), ids=lambda cls: cls.__name__)
def test_a_picture_drawn_ahead_is_the_frame_drawn_live_and_changes_nothing(cls, monkeypatch):
    explorer = cls()
    prefetch = _prefetch.attach(explorer)
    if prefetch is None:
        tree = _prefetch._tree(explorer.widget) if explorer.widget is not None else []
        canvases = sum(hasattr(x, "get_diff_image") for x in tree)
        assert canvases != 1 or any(isinstance(x, w.Output) for x in tree), \
            f"{cls.__name__} has one canvas of its own and no output area, yet no prefetcher"
        pytest.skip(f"{cls.__name__}: {canvases} figure canvases or an output area: "
                    "drawn only live")
    canvas = explorer.fig.canvas
    canvas.draw()
    sent = []
    monkeypatch.setattr(w.Widget, "_send", lambda self, msg, buffers=None: sent.append(msg))
    names = {id(c): n for c, n in prefetch.inputs}
    plan = prefetch.plan()
    if not plan:
        pytest.skip(f"{cls.__name__}: no control with values to draw ahead")
    prefetch.focus = plan[0][0]                       # as after the student's first step
    plan = prefetch.plan()
    chosen = plan[:CHECKED - 1] + plan[-1:]
    # and one step of every other control (log sliders, range sliders and check boxes too)
    for entry in plan:
        if all(entry[0] is not c for c, _, _ in chosen):
            chosen.append(entry)
    refused = []
    for control, value, values in chosen:
        before, states = np.asarray(canvas.get_renderer().buffer_rgba()).copy(), \
            _states(explorer)
        sent.clear()
        try:
            pixels, drawn_at = _prefetch.render_at(explorer, {control: value})
        except _prefetch.NotPrefetchable as why:
            refused.append((control, value, str(why)))
            continue
        assert sent == [], f"drawing ahead sent {len(sent)} widget message(s)"
        assert np.array_equal(np.asarray(canvas.get_renderer().buffer_rgba()), before), \
            "the figure is not as it was"
        assert _states(explorer) == states, "a widget is not as it was"
        live = (_turned(explorer, control, value) if isinstance(control, _prefetch.View)
                else _live(explorer, control, names[id(control)], value))
        differ = int((np.abs(live.astype(int) - pixels).max(axis=-1) > 0).sum())
        assert differ == 0, (f"{cls.__name__}: {control.description or type(control).__name__}"
                             f" = {value!r}: {differ} pixels differ from the live frame")
        assert len(drawn_at) == len(values) == len(prefetch.inputs)
    for control, value, why in refused:
        # refused only where the explorer itself does not come back: the live path, set and
        # set back, leaves a widget or the figure changed too
        states, before = _states(explorer), np.asarray(
            canvas.get_renderer().buffer_rgba()).copy()
        if isinstance(control, _prefetch.View):
            _turned(explorer, control, value)
        else:
            _live(explorer, control, names[id(control)], value)
        after = np.asarray(canvas.get_renderer().buffer_rgba())
        assert _states(explorer) != states or not np.array_equal(after, before), \
            f"{cls.__name__}: {control.description!r} = {value!r} refused ({why}), " \
            "yet setting it live and back changes nothing"
    assert len(refused) < len(chosen), f"{cls.__name__}: every picture refused: {refused}"


class _Decoder:
    """What the prefetcher sends the page, recorded."""

    def __init__(self):
        self.messages = []

    def send(self, content, buffers=None):
        self.messages.append((content, buffers))


def _bezier():
    from course_lib.widgets.bezier import BezierExplorer

    explorer = BezierExplorer()
    prefetch = _prefetch.attach(explorer)
    explorer.fig.canvas.draw()
    prefetch.decoder = _Decoder()
    return explorer, prefetch


def _gimbal(monkeypatch):
    """The gimbal explorer (one 3D axes) with a page keeping its pictures, ``wake`` recorded
    instead of scheduled: (explorer, prefetch, its view, the times woken, the page's message
    for a left press in the middle of the axes: canvas pixels from the top left)."""
    from course_lib.widgets.gimbal import GimbalExplorer

    explorer = GimbalExplorer()
    prefetch = _prefetch.attach(explorer)
    explorer.fig.canvas.draw()
    prefetch.decoder = _Decoder()
    woken = []
    monkeypatch.setattr(prefetch, "wake", lambda delay=0: woken.append(delay))
    (view,) = prefetch.views
    width, height = explorer.fig.bbox.width, explorer.fig.bbox.height
    left, top, right, bottom = view.box()
    press = {"type": "button_press", "button": 0,
             "x": (left + right) / 2 * width, "y": (top + bottom) / 2 * height}
    return explorer, prefetch, view, woken, press


def _page_messages(canvas):
    """What the canvas sends a page that has shown it and places rectangles, recorded."""
    sent = []
    canvas.send = lambda content, buffers=None: sent.append(json.loads(content["data"]))
    canvas._course_shown = True
    canvas._course_regions = True
    return sent


def _ray_tracer_on_a_page(monkeypatch):
    """A ray tracer whose pictures a page keeps, and what its canvas sends that page."""
    from course_lib.widgets.raytracer import RayTracerExplorer

    explorer = RayTracerExplorer()
    prefetch = _prefetch.attach(explorer)
    canvas = explorer.fig.canvas
    canvas.draw()
    prefetch.decoder = _Decoder()
    monkeypatch.setattr(prefetch, "wake", lambda delay=0: None)
    return explorer, prefetch, canvas, _page_messages(canvas)


def _control(prefetch, description):
    return next(c for c, _ in prefetch.controls if c.description == description)


def test_the_plan_takes_one_step_of_every_control_then_goes_further_along_the_one_moved():
    explorer, prefetch = _bezier()
    t = _control(prefetch, "t")
    first = [(c.description, v) for c, v, _ in prefetch.plan()]
    # untouched: one step either side of the slider, the other state of each check box
    assert first[:2] == [("t", 0.39), ("t", 0.41)]
    assert len(first) == 2 + sum(isinstance(c, w.Checkbox) for c, _ in prefetch.controls)
    t.value = 0.5                                   # the student moves t up
    plan = [(c.description, v) for c, v, _ in prefetch.plan()]
    # a step either side, then on the way it moved three steps for every one back
    assert sorted(plan[:2]) == [("t", 0.49), ("t", 0.51)]
    further = [v for d, v in plan[2:] if d == "t"]
    assert further[:4] == [0.52, 0.53, 0.54, 0.48]
    # as many as FOCUS_FRAMES, or every other position of the slider if it has fewer
    assert len(further) + 2 == min(_prefetch.FOCUS_FRAMES, round((t.max - t.min) / t.step))
    head = further[:len(further) // 2]             # before the steps up run out
    ups = [v for v in head if v > 0.5]
    assert len(ups) >= 2.5 * (len(head) - len(ups)), further
    t.value = 0.45                                  # and then down
    # ranks (place in the nearest-first list, times 1 on the way, 3 back): 0.44 1, 0.43 3,
    # 0.42 5, 0.46 6, 0.41 7
    assert [v for c, v, _ in prefetch.plan() if c is t][:5] == [0.44, 0.43, 0.42, 0.46, 0.41]


def test_a_step_sends_the_picture_and_the_values_the_page_will_have():
    explorer, prefetch = _bezier()
    control, value, values = prefetch.plan()[0]
    prefetch.step()
    (content, buffers), = prefetch.decoder.messages
    assert content["type"] == "frame" and content["state"] == values
    assert content["epoch"] == 0
    picture = np.asarray(Image.open(io.BytesIO(buffers[0])).convert("RGB"))
    live = _live(explorer, control, "value", value)[..., :3]
    assert np.array_equal(picture, live)
    assert prefetch.key(values) in prefetch.sent
    assert prefetch.plan()[0][:2] != (control, value)            # not drawn twice


def test_when_the_pictures_kept_are_many_the_least_likely_makes_room_on_both_sides(
        monkeypatch):
    """Kept pictures are bounded: once there are MAX_FRAMES, a step drops the kept picture
    least likely to be wanted (first those no single move of one control from the current
    values reaches), and only if the next one planned is more likely."""
    explorer, prefetch = _bezier()
    monkeypatch.setattr(_prefetch, "MAX_FRAMES", 3)
    t = _control(prefetch, "t")
    for _ in range(4):
        prefetch.step()
    # full, and none kept is less likely than the next planned: nothing dropped, nothing drawn
    assert len(prefetch.decoder.messages) == 3 and prefetch.dropped == 0
    kept = {tuple(m["state"]) for m, _ in prefetch.decoder.messages}
    t.value = 0.7                                  # far along: what was kept is less likely
    now = prefetch.values()
    unreachable = [values for values in kept
                   if sum(a != b for a, b in zip(values, now)) > 1]
    assert unreachable, "a kept picture two controls away from the new values"
    prefetch.step()
    (drop, _), (frame, _) = prefetch.decoder.messages[-2:]
    assert drop["type"] == "drop" and tuple(drop["state"]) in unreachable
    assert frame["type"] == "frame"
    assert frame["state"][prefetch.inputs.index((t, "value"))] in (0.69, 0.71)
    assert len(prefetch.sent) == 3 and prefetch.key(drop["state"]) not in prefetch.sent
    assert prefetch.dropped == 1


def test_a_kernel_frame_is_not_sent_again_when_the_page_holds_it_and_clears_it_if_unlike():
    explorer, prefetch = _bezier()
    t = _control(prefetch, "t")
    prefetch.step()                                  # t = 0.39 drawn ahead
    canvas = explorer.fig.canvas
    t.value = 0.5                                    # values never drawn ahead: sent
    assert prefetch.frame_drawn(np.asarray(canvas.get_renderer().buffer_rgba())) is None
    t.value = 0.39                                   # the student goes to the kept one
    frame = np.asarray(canvas.get_renderer().buffer_rgba())
    assert prefetch.frame_drawn(frame) is True       # the same picture: only named
    assert prefetch.decoder.messages[-1][0] == {"type": "same", "state": prefetch.values(),
                                                "epoch": 0}
    assert prefetch.frame_drawn(255 - frame) is False    # unlike it (a point moved)
    assert prefetch.decoder.messages[-1][0] == {"type": "clear"} and not prefetch.sent


def test_a_ray_tracers_full_image_forgets_only_the_preview_kept_for_its_values(monkeypatch):
    """The ray tracer shows a preview at once and the full image once the sliders rest: the
    full image is unlike the preview drawn ahead for the same values, yet every other preview
    kept is still the kernel's first answer for its values. Only that one is forgotten, on
    both sides; the full image, once kept for the values of the last full image, is drawn
    ahead for them when they are a step away."""
    from course_lib.widgets.raytracer import RayTracerExplorer

    explorer = RayTracerExplorer()
    prefetch = _prefetch.attach(explorer)
    canvas = explorer.fig.canvas
    canvas.draw()
    prefetch.decoder = _Decoder()
    depth = _control(prefetch, "recursion depth")
    monkeypatch.setattr(prefetch, "wake", lambda delay=0: None)
    for _ in range(4):
        prefetch.step()                              # depth 2 and 4 first, then the others
    drawn = {tuple(m["state"]) for m, _ in prefetch.decoder.messages}
    assert len(drawn) == 4
    depth.value = 4                                  # the student goes to a kept preview
    canvas.draw()
    assert explorer.current["preview"]
    assert prefetch.frame_drawn(np.asarray(canvas.get_renderer().buffer_rgba())) is True
    explorer.settle()                                # the sliders rest: the full image
    canvas.draw()                                    # its frame, unlike the preview kept
    assert prefetch.key() not in prefetch.sent
    last, _ = prefetch.decoder.messages[-1]
    assert last == {"type": "drop", "state": prefetch.values()}
    assert len(prefetch.sent) == 3                   # the other previews are still kept
    full_4 = np.asarray(canvas.get_renderer().buffer_rgba()).copy()
    depth.value = 3                                  # a step away, back to the start
    canvas.draw()
    assert explorer.current["preview"]               # (the first full image is not kept)
    pixels, values = _prefetch.render_at(explorer, {depth: 4})
    assert values[prefetch.inputs.index((depth, "value"))] == 4
    assert np.array_equal(pixels, full_4)
    depth.value = 4                                  # the last full image's values: at once
    canvas.draw()
    assert not explorer.current["preview"]
    assert np.array_equal(pixels, np.asarray(canvas.get_renderer().buffer_rgba()))


def test_drawing_ahead_leaves_a_refinement_under_way_alone(monkeypatch):
    """Pictures drawn ahead while an explorer refines its own (the ray tracer waiting to trace
    its full image, the distributed ray tracer half way through its samples): each is the
    picture the student's input would show first, and the refinement goes on untouched, its
    timer kept and its picture and status the same."""
    from course_lib.widgets.distributed import DistributedExplorer, State
    from course_lib.widgets.raytracer import RayTracerExplorer

    armed = []

    class Loop:                                      # the kernel's loop, its timers recorded
        def call_later(self, delay, callback, *args):
            handle = mock.Mock()
            armed.append(handle)
            return handle

    monkeypatch.setattr("asyncio.get_running_loop", lambda: Loop())
    tracer = RayTracerExplorer()
    distributed = DistributedExplorer(State(samples=6))
    tracer.mirror.value = 0.5                        # a preview; the full image to come
    distributed.light.value = 0.9                    # the first of 6 samples shown
    distributed._tick()
    distributed._tick()                              # ... three shown
    assert distributed.done == 3 and tracer.pending
    for explorer, control, value in ((tracer, tracer.depth, 4),
                                     (distributed, distributed.light, 0.95)):
        canvas = explorer.fig.canvas
        canvas.draw()
        timer = explorer._timer
        status, done = explorer.status.value, getattr(explorer, "done", None)
        pixels, _ = _prefetch.render_at(explorer, {control: value})
        assert explorer._timer is timer and not timer.cancel.called
        assert explorer.status.value == status and getattr(explorer, "done", None) == done
        old = control.value
        live = _live(explorer, control, "value", value)
        assert np.array_equal(pixels, live), type(explorer).__name__
        control.value = old


def test_a_draw_of_values_the_page_holds_waits_for_the_inputs_to_pause(monkeypatch):
    """While a slider is dragged through pictures the page keeps, the kernel updates its model
    at each input but draws only once the inputs pause (then it checks the kept picture, as
    ever); a value the page does not hold is drawn at once, and takes the put-off draw with
    it; nothing is drawn ahead while a draw is put off; and a press on the figure (a point
    about to be dragged) makes nothing held, so that every frame of the drag is drawn."""
    from course_lib import _canvas

    class Loop:                                     # the kernel's loop, run by hand
        def __init__(self):
            self.timers, self.callbacks, self.removed = [], [], []

        def call_later(self, delay, callback, *args):
            self.timers.append((delay, callback, args))
            return len(self.timers) - 1

        def remove_timeout(self, handle):
            self.removed.append(handle)

        def add_callback(self, callback):
            self.callbacks.append(callback)

    loop = Loop()
    monkeypatch.setattr(_canvas, "_kernel_loop", lambda: loop)
    explorer, prefetch = _bezier()
    canvas = explorer.fig.canvas
    canvas._course_shown = True
    monkeypatch.setattr(prefetch, "wake", lambda delay=0: None)
    t = _control(prefetch, "t")
    prefetch.step()
    prefetch.step()                                  # t = 0.39 and 0.41 drawn ahead, sent
    drawn = []
    monkeypatch.setattr(canvas, "draw", lambda: drawn.append(t.value))

    def move(value):                 # a slider's input, whose update asks for a whole draw
        t.value = value
        canvas.draw_idle()

    move(0.39)                                       # held: its draw is put off
    assert prefetch.holds()
    assert loop.callbacks == [] and canvas._course_deferred == 0
    assert loop.timers[0][0] == _canvas.HELD_PAUSE_S
    assert prefetch._busy(explorer)                  # nothing drawn ahead meanwhile
    move(0.41)                                       # held too: put off again, from now
    assert loop.removed == [0] and canvas._course_deferred == 1 and loop.callbacks == []
    move(0.45)                                       # not held: drawn at once
    assert not prefetch.holds()
    assert loop.removed == [0, 1] and canvas._course_deferred is None
    assert len(loop.callbacks) == 1
    loop.callbacks.pop()()
    assert drawn == [0.45]
    move(0.41)
    _, callback, args = loop.timers[-1]
    callback(*args)                                  # the inputs paused: drawn now
    loop.callbacks.pop()()
    assert drawn == [0.45, 0.41] and canvas._course_deferred is None
    # a press on the figure but off any 3D axes: a point may move, nothing is held
    prefetch._mouse(canvas, {"type": "button_press", "button": 0, "x": 5, "y": 5}, [])
    assert not prefetch.holds()
    move(0.39)
    assert len(loop.callbacks) == 1                  # drawn at once


def test_the_frame_the_page_holds_is_named_not_sent_and_sent_whole_if_it_asks():
    explorer, prefetch = _bezier()
    canvas = explorer.fig.canvas
    sent = _page_messages(canvas)
    canvas.draw()                                    # the page has the first frame
    prefetch.step()                                  # t = 0.39 drawn ahead
    before = len(sent)
    _control(prefetch, "t").value = 0.39
    assert len(sent) == before, "the kept picture was sent again"
    assert prefetch.decoder.messages[-1][0]["type"] == "same"
    # the page had not kept it: it asks for the whole frame
    from course_lib._canvas import _decoder_class

    decoder = _decoder_class()(canvas=canvas, controls=prefetch.spec())
    canvas.draw_idle = canvas.draw                   # no kernel loop here: draw at once
    decoder._on_ready(decoder, {"type": "whole", "state": prefetch.values()}, [])
    assert sent[-1]["type"] == "binary" and "x" not in sent[-1], sent[-1]
    assert sent[-1]["state"] == prefetch.values()


def test_the_mouse_let_go_on_the_figure_makes_every_picture_sent_stale():
    explorer, prefetch = _bezier()
    prefetch.step()
    assert prefetch.sent
    prefetch._mouse(explorer.fig.canvas, {"type": "motion_notify"}, [])
    assert prefetch.sent and prefetch.epoch == 0
    prefetch._mouse(explorer.fig.canvas, {"type": "button_release"}, [])
    assert not prefetch.sent and prefetch.epoch == 1
    prefetch.step()
    assert prefetch.decoder.messages[-1][0]["epoch"] == 1


def test_a_press_on_a_3d_axes_starts_a_turn_drawn_ahead_and_keeps_the_pictures(monkeypatch):
    explorer, prefetch, view, woken, press = _gimbal(monkeypatch)
    canvas = explorer.fig.canvas
    prefetch.step()
    assert prefetch.sent
    width = explorer.fig.bbox.width
    left = view.box()[0]
    woken.clear()
    prefetch._mouse(canvas, press, [])
    # the view is what the student moves now; no frame follows a press, so it wakes itself
    assert prefetch.turning is view and prefetch.focus is view and woken
    assert [c for c, _, _ in prefetch.plan()[:12]] == [view] * 12
    prefetch._mouse(canvas, {"type": "button_release"}, [])
    # a turn leaves every picture valid: the views are among their values
    assert prefetch.sent and prefetch.epoch == 0 and prefetch.turning is None
    # a press beside the axes (in the figure's margin) may move what no control shows
    prefetch._mouse(canvas, {**press, "x": 0.5 * left * width}, [])
    prefetch._mouse(canvas, {"type": "button_release"}, [])
    assert not prefetch.sent and prefetch.epoch == 1
    # with the toolbar's pan chosen a press on the axes pans: not a turn, and the pictures
    # drawn before (of the view unpanned) are stale
    prefetch.sent[("stale",)] = 0
    view.ax.set_navigate_mode("PAN")
    prefetch._mouse(canvas, press, [])
    assert prefetch.turning is None
    prefetch._mouse(canvas, {"type": "button_release"}, [])
    assert not prefetch.sent and prefetch.epoch == 2


def test_a_view_being_turned_is_drawn_ahead_the_way_it_turns(monkeypatch):
    explorer, prefetch, view, _, press = _gimbal(monkeypatch)
    canvas = explorer.fig.canvas
    view.value = (20.0, 30.0)
    prefetch._mouse(canvas, press, [])
    for azim in (29.0, 28.0):              # the axes turn (their own handler), then the message
        view.value = (20.0, azim)
        prefetch._mouse(canvas, {"type": "motion_notify"}, [])
    ahead = [v for c, v, _ in prefetch.plan() if c is view][:12]
    assert ahead[0] == (20, 27), ahead
    lower = sum(v[1] < 28 for v in ahead)
    higher = sum(v[1] > 28 for v in ahead)
    assert lower >= 2.5 * higher, ahead


def test_each_move_of_a_turn_renews_the_drawing_budget_as_a_sliders_change_does(monkeypatch):
    """A turn held for long (the button down, the mouse moving now and then) goes on being
    drawn ahead: each move that turns the view is an input, and the budget of drawing after
    an input starts again (a loaded machine spent it before the next move, and the views
    around the new one never came)."""
    explorer, prefetch, view, _, press = _gimbal(monkeypatch)
    canvas = explorer.fig.canvas
    prefetch._mouse(canvas, press, [])
    prefetch.spent = _prefetch.BUDGET_S                # spent while the mouse rested
    prefetch._mouse(canvas, {"type": "motion_notify"}, [])
    assert prefetch.spent == _prefetch.BUDGET_S        # a move that turned nothing
    elev, azim = view.value
    view.value = (elev, azim - 1)                      # the axes' own handler turned it
    prefetch._mouse(canvas, {"type": "motion_notify"}, [])
    assert prefetch.spent == 0.0


def test_a_kernel_frame_carries_the_values_it_shows_once_a_page_keeps_pictures():
    explorer, prefetch = _bezier()
    canvas = explorer.fig.canvas
    sent = _page_messages(canvas)
    _control(prefetch, "t").value = 0.7
    canvas.draw()
    assert sent[-1]["type"] == "binary" and sent[-1]["state"] == prefetch.values()
    assert sent[-1]["epoch"] == 0
    prefetch.decoder = None                          # a new page, not ready yet
    _control(prefetch, "t").value = 0.6
    canvas.draw()
    assert "state" not in sent[-1]


def test_a_picture_whose_explorer_does_not_come_back_is_refused_and_the_control_skipped():
    explorer, prefetch = _bezier()
    t = _control(prefetch, "t")
    calls = []
    moving = explorer.blitter.artists[0]

    def drift(change):              # an update with a memory the model does not hold
        calls.append(change["new"])
        moving.set_alpha(1.0 - 0.1 * len(calls))
        explorer.update()
    t.observe(drift, names="value")
    prefetch.step()
    assert id(t) in prefetch.skip and prefetch.enabled
    assert [m for m, _ in prefetch.decoder.messages if m["type"] == "frame"] == []
    assert all(c is not t for c, _, _ in prefetch.plan())


def test_values_are_compared_as_the_page_compares_them():
    key = _prefetch.Prefetcher.key
    prefetch = type("P", (), {"values": lambda self: None})()
    assert key(prefetch, [0.1 + 0.2, 3, True, "a", [1.0, 2.5]]) == \
        key(prefetch, [0.3, 3, True, "a", (1, 2.5)])
    assert key(prefetch, [0.3]) != key(prefetch, [0.31])
    assert zlib.crc32(b"") == 0                      # the checksum used for pictures


def test_a_frame_the_kernel_sent_before_is_sent_again_whole_if_the_page_keeps_another(
        monkeypatch):
    """The page may keep, for the values the kernel now shows, a picture that is not the
    kernel's: a ray tracer's preview drawn ahead while its cached full image was another's,
    where the kernel shows the full image of these values again, the very frame it sent last
    (the inputs between were never drawn: the page held them). That frame must still reach the
    page, whole, with a "drop" for the kept picture: else the preview stays on the screen
    (seen in the browser: a slider moved and moved back left 33,534 pixels of the preview)."""
    explorer, prefetch, canvas, sent = _ray_tracer_on_a_page(monkeypatch)
    full = np.asarray(canvas.get_renderer().buffer_rgba()).copy()
    assert not explorer.current["preview"]
    # the page was sent another picture for these values (a preview, say), and the
    # kernel's last frame is the full image
    prefetch.sent[prefetch.key()] = _prefetch._crc(255 - full)
    # the kernel draws these values again: its cached full image, the frame it sent last
    explorer.update()
    canvas.draw()
    assert np.array_equal(np.asarray(canvas.get_renderer().buffer_rgba()), full)
    assert prefetch.decoder.messages[-1][0] == {"type": "drop", "state": prefetch.values()}
    frames = [m for m in sent if m["type"] == "binary"]
    assert len(frames) == 1 and "x" not in frames[0], sent          # whole
    assert frames[0]["state"] == prefetch.values()
    assert prefetch.key() not in prefetch.sent
    # and once the page has it, the same frame again is nothing to send
    canvas._png_is_old = True
    canvas.draw()
    assert len([m for m in sent if m["type"] == "binary"]) == 1, sent


def test_a_drag_on_a_rendered_view_turns_it_by_its_sliders_and_keeps_the_pictures():
    """A pyvista view is a picture on the canvas, turned by two sliders: a drag across it
    moves those sliders in the page (as a 3D axes turns), so the pictures kept (of the
    sliders' values) stay good. The page is told which two, and where the picture lies; a
    press and release on it leave the pictures kept alone, where a press on a figure's points
    (a point dragged) makes them stale."""
    from course_lib.widgets.isovalue import IsosurfaceExplorer

    explorer = IsosurfaceExplorer()
    prefetch = _prefetch.attach(explorer)
    (spec,) = prefetch.turn_spec()
    azimuth, elevation = (prefetch.controls[k][0] for k in spec["controls"])
    assert (azimuth, elevation) == (explorer.azimuth, explorer.elevation)
    # the picture fills the canvas: its box, as the page measures the mouse (y down)
    assert spec["box"] == [0.0, 0.0, 1.0, 1.0]
    assert {"kind": "turn", "what": "the 3D view", "start": (0.35, 0.5), "end": (0.65, 0.5),
            "sliders": ["view azimuth °", "view elevation °"]} in explorer.mouse_gestures()
    prefetch.sent[("kept",)] = 1
    width, height = explorer.fig.canvas.figure.bbox.size
    press = {"type": "button_press", "button": 0, "x": 0.4 * width, "y": 0.5 * height}
    prefetch._mouse(None, press, [])
    assert prefetch.sliding and prefetch.sent
    prefetch._mouse(None, {"type": "button_release", "button": 0, "x": 5, "y": 5}, [])
    assert not prefetch.sliding and prefetch.sent and prefetch.epoch == 0
    # another button than the left one turns nothing: as a point's drag, it may change what
    # the values do not show
    prefetch._mouse(None, {**press, "button": 2}, [])
    assert not prefetch.sliding and not prefetch.sent


def test_explorers_without_a_rendered_view_have_no_turn():
    explorer, prefetch = _bezier()
    assert prefetch.turn_spec() == [] and prefetch.turns is None
    assert all(g["kind"] != "turn" for g in explorer.mouse_gestures())


def test_a_ray_tracers_full_image_shown_live_always_goes_whole(monkeypatch):
    """Whatever the page keeps for the values (a preview the kernel no longer counts on, say),
    a full image the kernel shows live reaches it whole, even if it is the frame sent last;
    pictures drawn ahead and previews go as before (nothing when unchanged)."""
    explorer, prefetch, canvas, sent = _ray_tracer_on_a_page(monkeypatch)
    explorer.update()                                # the cached full image again, unchanged
    canvas.draw()
    frames = [m for m in sent if m["type"] == "binary"]
    assert len(frames) == 1 and "x" not in frames[0], sent
    assert frames[0]["state"] == prefetch.values()
    explorer._full = None                            # now a preview: drawn, then unchanged
    explorer.update()
    canvas.draw()
    assert len([m for m in sent if m["type"] == "binary"]) == 2
    canvas._png_is_old = True
    canvas.draw()
    assert len([m for m in sent if m["type"] == "binary"]) == 2, sent
