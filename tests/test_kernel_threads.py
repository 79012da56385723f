"""Widget messages that arrive on a kernel subshell are handled on the kernel's main thread.

JupyterLab 4.6 (its default ``commsOverSubshells: perCommTarget``) sends widget comm messages to
kernel subshells, and ipykernel 7 runs every subshell in a thread of its own. These tests play
that front end against a real kernel: they create a subshell, send a slider update on it exactly
as JupyterLab does, and look at the thread the explorer's callback ran on, and at the picture a
VTK explorer renders. The first test is the control: without course_lib.widgets the callback
does run on the subshell's thread, so the check below can fail.
"""
import time

import numpy as np
import pytest
from jupyter_client.manager import start_new_kernel

TIMEOUT = 60


@pytest.fixture
def kernel():
    manager, client = start_new_kernel(kernel_name="python3", startup_timeout=TIMEOUT)
    try:
        yield client
    finally:
        client.stop_channels()
        manager.shutdown_kernel(now=True)


def run(client, code):
    """Execute `code` on the main shell; return what it printed (raise on an error)."""
    printed = []

    def hook(msg):
        if msg["msg_type"] == "stream":
            printed.append(msg["content"]["text"])
        elif msg["msg_type"] == "error":
            printed.append("\n".join(msg["content"]["traceback"]))

    reply = client.execute_interactive(code, timeout=TIMEOUT, output_hook=hook)
    assert reply["content"]["status"] == "ok", "".join(printed)
    return "".join(printed)


def subshell(client):
    """A new kernel subshell, made the way JupyterLab makes one (a control request)."""
    if "kernel subshells" not in client.kernel_info(reply=True)["content"].get(
            "supported_features", []):
        pytest.skip("this ipykernel has no subshells: widget messages always reach the main "
                    "thread there")
    client.control_channel.send(client.session.msg("create_subshell_request", {}))
    reply = client.control_channel.get_msg(timeout=TIMEOUT)
    return reply["content"]["subshell_id"]


def send_on_subshell(client, subshell_id, comm_id, state):
    """A widget state update from the front end, sent on `subshell_id`."""
    msg = client.session.msg("comm_msg", {"comm_id": comm_id, "data": {
        "method": "update", "state": state, "buffer_paths": []}})
    msg["header"]["subshell_id"] = subshell_id
    client.shell_channel.send(msg)


def wait_for(client, code, expected, timeout=TIMEOUT):
    """Run `code` until it prints `expected` (the update is handled asynchronously)."""
    deadline = time.monotonic() + timeout
    while True:
        out = run(client, code).strip()
        if out == expected or time.monotonic() > deadline:
            return out
        time.sleep(0.2)


SLIDER = """
import threading, ipywidgets as w
threads, values = [], []
slider = w.IntSlider()
slider.observe(lambda change: (threads.append(threading.current_thread().name),
                               values.append(change.new)), names="value")
print(slider.comm.comm_id)
"""


def test_without_course_lib_a_subshell_message_runs_its_callback_off_the_main_thread(kernel):
    comm_id = run(kernel, SLIDER).strip()
    sid = subshell(kernel)
    # ipykernel routes a comm's first message to the thread that opened the comm (the main
    # one) and every later one to the subshell its front end sent it on
    for count, value in enumerate((3, 4), 1):
        send_on_subshell(kernel, sid, comm_id, {"value": value})
        assert wait_for(kernel, "print(len(threads))", str(count)) == str(count)
    assert run(kernel, "print(threads[1])").startswith(f"subshell-{sid}")


def test_course_lib_widgets_handles_subshell_messages_on_the_main_thread(kernel):
    run(kernel, "import course_lib.widgets")
    comm_id = run(kernel, SLIDER).strip()
    sid = subshell(kernel)
    for count, value in enumerate((3, 4, 5), 1):        # one at a time, as a student moves it
        send_on_subshell(kernel, sid, comm_id, {"value": value})
        assert wait_for(kernel, "print(len(threads))", str(count)) == str(count)
    assert run(kernel, "print(threads)").strip() == "['MainThread', 'MainThread', 'MainThread']"
    # a burst (a slider dragged fast) while the main thread is busy: the values still waiting
    # are merged into the newest, which is handled last; the order is kept
    run(kernel, "import time\nslider.observe(lambda change: time.sleep(0.2), names='value')")
    for value in range(10, 20):
        send_on_subshell(kernel, sid, comm_id, {"value": value})
    assert wait_for(kernel, "print(values[-1])", "19") == "19"
    time.sleep(0.5)
    values = eval(run(kernel, "print(values)"))
    burst = values[3:]
    assert burst == sorted(burst) and burst[-1] == 19, values
    assert len(burst) < 10, f"every stale value was handled in turn: {burst}"
    assert run(kernel, "print(set(threads))").strip() == "{'MainThread'}"
    handler = "get_ipython().kernel.shell_handlers['comm_msg']"
    forwarded, merged = run(kernel, f"print({handler}.forwarded, {handler}.merged)").split()
    assert int(forwarded) >= 12         # all but (at most) the first went to the subshell
    assert int(merged) == 10 - len(burst)


def test_messages_of_other_kinds_or_other_widgets_are_never_merged():
    from course_lib.widgets._base import _supersedes

    def update(comm, state, buffers=()):
        return {"content": {"comm_id": comm, "data": {"method": "update", "state": state,
                                                      "buffer_paths": list(buffers)}}}

    def mouse(comm, kind):
        return {"content": {"comm_id": comm, "data": {"method": "custom",
                                                      "content": {"type": kind}}}}
    assert _supersedes(update("a", {"value": 2}), update("a", {"value": 1}))
    assert not _supersedes(update("b", {"value": 2}), update("a", {"value": 1}))
    assert not _supersedes(update("a", {"value": 2}), update("a", {"value": 1, "index": 0}))
    assert not _supersedes(update("a", {"value": 2}, [["value"]]), update("a", {"value": 1}))
    assert _supersedes(mouse("a", "motion_notify"), mouse("a", "motion_notify"))
    assert not _supersedes(mouse("a", "motion_notify"), mouse("a", "button_press"))
    assert not _supersedes(mouse("a", "button_release"), mouse("a", "motion_notify"))


def test_a_message_that_reaches_the_main_thread_directly_waits_behind_older_ones():
    """ipykernel sends a comm's first message (a button's first click) to the main thread
    directly; a slider's values sent just before it on a subshell may still be waiting there.
    The click must be handled after them, as the student acted, not on the stale value."""
    import threading

    from course_lib.widgets import _base

    handled, callbacks = [], []

    class Loop:                                    # the kernel's event loop, run by hand
        def add_callback(self, callback):
            callbacks.append(callback)

    def message(comm, data):
        return {"header": {"msg_id": f"{comm}-{len(handled)}-{data}"},
                "content": {"comm_id": comm, "data": data}}

    forward = _base._on_main_thread(lambda stream, ident, msg: handled.append(
        msg["content"]["data"]), Loop(), threading.main_thread())
    try:
        slider = {"method": "update", "state": {"value": 0}, "buffer_paths": []}
        on_subshell = threading.Thread(target=forward, args=(None, [], message("s", slider)))
        on_subshell.start()
        on_subshell.join()
        assert handled == [] and _base.comms_waiting()
        click = {"method": "custom", "content": {"event": "click"}}
        forward(None, [], message("b", click))        # the button's first message, on main
        assert handled == [], "the click was handled before the slider's value waiting"
        assert forward.deferred == 1
        while callbacks:
            callbacks.pop(0)()
        assert handled == [slider, click]
        assert not _base.comms_waiting()
        forward(None, [], message("b", click))        # nothing waits: handled at once
        assert handled == [slider, click, click] and callbacks == []
    finally:
        _base._FORWARDERS.remove(forward)


def test_a_vtk_explorer_moved_from_a_subshell_renders_its_picture(kernel):
    """The surface explorer (pyvista/VTK, an OpenGL context made on the main thread): its lift
    slider moved on a subshell must give a real picture of the patch, not a black frame."""
    comm_id = run(kernel, "%matplotlib widget\n"             # as every lesson starts
                          "from course_lib.widgets.surface import SurfaceExplorer\n"
                          "explorer = SurfaceExplorer()\nbefore = explorer.frame().copy()\n"
                          "print(explorer.lift.comm.comm_id)").strip()
    sid = subshell(kernel)
    for value in (-0.5, -1.0):           # the first is routed to the main thread anyway
        send_on_subshell(kernel, sid, comm_id, {"value": value})
        assert wait_for(kernel, "print(explorer.state.lift)", str(value)) == str(value)
    # the frames the explorer's screen shows, before and after, as raw bytes and their shape
    pictures = run(kernel, "import base64; print(explorer.frame().shape[0], "
                           "explorer.frame().shape[1], base64.b64encode(before.tobytes()).decode(), "
                           "base64.b64encode(explorer.frame().tobytes()).decode())").split()
    from base64 import b64decode

    height, width = int(pictures[0]), int(pictures[1])
    before, after = (np.frombuffer(b64decode(p), np.uint8).reshape(height, width, 3).astype(float)
                     for p in pictures[2:])
    assert before.shape == after.shape
    # the background is white and the patch coloured: a black or noisy frame fails both
    assert (after.min(axis=-1) > 250).mean() > 0.3, "the white background is gone"
    changed = np.abs(after - before).max(axis=-1) > 24
    assert 0.005 < changed.mean() < 0.5, f"{changed.mean():.3f} of the pixels changed"
