"""Every lesson run in JupyterLab with its default settings, and every control of every
explorer driven there.

First, as a student opens a lesson: Run All, then no error output, no browser console error, no
message in JupyterLab's log console, and every widget of the stored notebook rendered with a
figure (nbval only proves the kernel side); every explorer's view with its control labels whole
and nothing past its output area's right edge (:mod:`.look`), with a screenshot of each.

JupyterLab 4.6 sends widget messages to kernel subshells by default, so a callback runs on a
thread other than the one that made the explorer's figure (see
:func:`course_lib.widgets._base.handle_comms_on_main_thread`). For every lesson, after Run All,
this moves each slider, picks another entry of each menu and toggle group, clicks each button,
ticks each check box, types into each field and performs each mouse gesture of each figure
(drag a point, turn a 3D view, click a pixel), and checks after each one that the explorer's
picture changed; at the end, that the kernel is the same one (it did not die and restart), that
it really received messages on a subshell, and that nothing reached stderr, the browser console,
JupyterLab's log console or the server log (where VTK's and a dying kernel's messages land).
"""
import re
from pathlib import Path

from .controls import drive
from .look import look_problems
from .lab import (ROOT, WIDGET_VIEW, NotebookPage, PageKernel, expected_widget_cells,
                  page_explorers)

NOTEBOOKS = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "notebooks").glob("*.ipynb"))
MIN_CHANGED = 30             # pixels: a moved marker or a recoloured patch changes more

# Controls that may leave the picture as it is, and why: "text" ones must change the
# explorer's text instead; "none" ones may change nothing visible (an option is given where
# only that option of a menu is meant).
EXPECTED = {
    ("HiddenSurfaceExplorer", "checkbox|\u200bcull back faces|1", None): (
        "text", "culling saves work and must not change the picture: the lesson's point"),
    ("CameraExplorer", "slider|up z|1", None): (
        "text", "up is only a direction: (0, 0, 0.5) gives the same camera as (0, 0, 1)"),
    ("TransferFunctionExplorer", "menu|preset|1", "custom"): (
        "none", "'custom' names the student's own edits; choosing it keeps the points"),
    ("TransferFunctionExplorer", "menu||1", "grey"): (
        "none", "the preset chosen just before ('ramp') is already grey"),
    ("RayTracerExplorer", "button|render full image|1", None): (
        "none", "the full image is already shown once the sliders rest"),
    ("SurfaceExplorer", "toggles|Bézier/B-spline/NURBS|1", "NURBS"): (
        "text", "with every weight 1 (the default) a NURBS patch is its B-spline patch"),
    ("FlowTopologyExplorer", "toggles|Euler/RK2/RK4|1", "RK2"): (
        "text", "RK2 and RK4 trace the same seed line to within a pixel at the default step "
        "(on the double gyre their ends are 5e-5 apart): the text names the method"),
    ("FlowTopologyExplorer", "toggles|Euler/RK2/RK4|1", "RK4"): (
        "text", "as for RK2: the two fourth- and second-order lines coincide on screen"),
    ("MockExamWidget", "textarea||1", None): (
        "none", "an answer is read when it is submitted"),
    ("MockExamWidget", "number|seed|1", None): (
        "none", "the seed is read by 'New exam'"),
    ("MockExamWidget", "button|Submit|1", None): ("text", "the feedback is text"),
    ("MockExamWidget", "button|Next question|1", None): ("text", "a question is text"),
    ("MockExamWidget", "button|New exam|1", None): ("text", "a question is text"),
}

# What the server's log must never show: VTK errors, a C++ abort, a kernel that died.
SERVER_LOG_PROBLEMS = re.compile(r"ERR\||terminate called|KernelRestarter|restarting kernel|"
                                 r"[Kk]ernel .* died|Segmentation fault|Traceback")


# The error a Jupyter server logs when it writes to the websocket of a page that has closed it
PAGE_GONE = re.compile(r"^tornado\.(websocket\.WebSocketClosedError|iostream\.StreamClosedError)")


def _page_gone(lines, k):
    """Whether line `k` of the server log begins a traceback that ends in :data:`PAGE_GONE`
    (the traceback's last line is the first after it that is not indented)."""
    if not lines[k].startswith("Traceback"):
        return False
    end = next((line for line in lines[k + 1:] if line.strip() and not line[0].isspace()),
               "")
    return bool(PAGE_GONE.match(end))


def check_rendered(notebook, path):
    """The lesson as Run All leaves it: no error, every widget view shown with a figure."""
    notebook.screenshot(Path(path).stem)
    assert notebook.error_outputs() == [], "a cell produced an error or wrote to stderr"
    assert notebook.widget_problems() == []
    assert notebook.console_errors == [], "the browser console reported errors"
    assert notebook.log_console_count() == 0, "JupyterLab's log console caught messages " \
        "(an exception in a widget callback lands there)"
    expected = len(expected_widget_cells(path))
    views = notebook.page.locator(WIDGET_VIEW)
    assert views.count() == expected, f"{views.count()} widget outputs, {expected} expected"
    for k in range(views.count()):
        drawn = views.nth(k).locator(".jupyter-matplotlib, .widget-image, img")
        assert drawn.count() > 0, f"widget {k} shows no figure (ipympl canvas or image)"


def drive_lesson(lab, browser, path):
    """Run All in one lesson, then drive every control of every explorer it shows."""
    log = lab.tmp / "server.log"
    log_start = log.stat().st_size
    notebook = NotebookPage(browser, lab, path).open().run_all()
    kernel = PageKernel(lab, path)
    try:
        check_rendered(notebook, path)
        if not expected_widget_cells(path):
            return
        kernel.run("_course_same_kernel = 'yes'")
        explorers = page_explorers(notebook, kernel)
        views = notebook.page.locator(WIDGET_VIEW)
        assert views.count() == len(explorers)
        # first the look, as Run All leaves it: every label whole, nothing clipped
        looks = []
        for k, explorer in enumerate(explorers):
            view = views.nth(k)
            view.scroll_into_view_if_needed()
            notebook.screenshot(f"{Path(path).stem}-{k}-{explorer['class']}", view)
            looks += look_problems(view, explorer["class"])
        assert looks == [], "\n".join(looks)
        done, problems = [], []
        for k, explorer in enumerate(explorers):
            view = views.nth(k)
            view.scroll_into_view_if_needed()
            name = explorer["class"]
            expected = {(key, option): how for (cls, key, option), (how, _) in EXPECTED.items()
                        if cls == name}
            lines, wrong = drive(view, explorer["gestures"], MIN_CHANGED, expected)
            done += [f"{name}: {line}" for line in lines]
            problems += [f"{name}: {line}" for line in wrong]
        print("\n".join(done))
        assert kernel.state() != "dead"
        assert kernel.run("print(_course_same_kernel)").strip() == "yes", \
            "the kernel was restarted (it died during the interactions)"
        forwarded = int(kernel.run(
            "print(get_ipython().kernel.shell_handlers['comm_msg'].forwarded)"))
        assert problems == [], "\n".join(problems)
        # ipykernel sends a comm's first message to the main thread and only later ones to
        # its subshell: a lesson whose every control sends one message (the mock exam's
        # buttons and fields) may forward none, and proves nothing either way
        if any(e["class"] != "MockExamWidget" for e in explorers):
            assert forwarded > 0, "no widget message came on a subshell: not JupyterLab's default"
        else:
            print(f"subshell check not applicable: {forwarded} forwarded, every control of "
                  "the mock exam sends a single message")
        assert notebook.error_outputs() == [], "a cell produced an error or wrote to stderr"
        assert notebook.console_errors == [], "the browser console reported errors"
        assert notebook.log_console_count() == 0, "JupyterLab's log console caught messages"
        with open(log, errors="replace") as f:
            f.seek(log_start)
            lines = f.readlines()
        # each problem with the lines that follow it (a traceback's frames and its error), but
        # the server's own traceback of a websocket that a page (another test's) had closed
        bad = ["".join(lines[k:k + 25]) for k, line in enumerate(lines)
               if SERVER_LOG_PROBLEMS.search(line) and not _page_gone(lines, k)]
        assert bad == [], "the server log (the kernel's stderr) shows:\n" + "".join(bad[:4])
    finally:
        kernel.close()
        notebook.close()


def _lesson_class(path):
    """A test class for one lesson: ``--dist loadscope`` gives each class to one worker, so the
    lessons spread over the workers (one module of parametrized tests would keep them all on
    one worker, about twenty minutes end to end)."""
    def test_lesson_runs_and_every_control_of_every_explorer_changes_its_picture(
            self, lab, browser):
        drive_lesson(lab, browser, path)

    name = "TestLesson_" + re.sub(r"\W", "_", Path(path).stem)
    return name, type(name, (), {
        "__doc__": f"{path}: Run All, then every control of every explorer.",
        "test_lesson_runs_and_every_control_of_every_explorer_changes_its_picture":
            test_lesson_runs_and_every_control_of_every_explorer_changes_its_picture})


for _path in NOTEBOOKS:
    _name, _cls = _lesson_class(_path)
    globals()[_name] = _cls
del _path, _name, _cls
