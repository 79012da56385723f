"""Drive JupyterLab in headless chromium: start a server, open a notebook, run it, inspect it.

Measured facts this builds on (see CONTRIBUTING.md): Debian's chromium driven by PyPI's
playwright (never a downloaded browser), launched with a fresh profile and the flags below; a
JupyterLab server started as one plain background process on a free loopback port with a token,
polled on /api/status, stopped with SIGTERM; every Jupyter and matplotlib directory pointed into
a temporary folder so that nothing touches the user's home.
"""
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                  "--no-first-run", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync"]
ARTIFACTS = ROOT / "test-artifacts" / "browser"
IDLE_KERNEL = ".jp-Notebook-ExecutionIndicator[data-status='idle']"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LabServer:
    """A JupyterLab server on a free loopback port, with its own config and settings."""

    def __init__(self, tmp, env=None, windowing="none"):
        self.tmp = Path(tmp)
        self.windowing = windowing
        self.extra_env = dict(env or {})
        self.port = free_port()
        self.token = "course-test-token"
        self.url = f"http://127.0.0.1:{self.port}"
        self.process = None

    def environment(self):
        env = dict(os.environ)
        for name in ("JUPYTER_CONFIG_DIR", "JUPYTER_DATA_DIR", "JUPYTER_RUNTIME_DIR",
                     "IPYTHONDIR", "MPLCONFIGDIR", "XDG_CACHE_HOME", "XDG_CONFIG_HOME"):
            path = self.tmp / name.lower()
            path.mkdir(parents=True, exist_ok=True)
            env[name] = str(path)
        settings = self.tmp / "lab-settings" / "@jupyterlab" / "apputils-extension"
        settings.mkdir(parents=True, exist_ok=True)
        (settings / "notification.jupyterlab-settings").write_text(
            json.dumps({"fetchNews": "false", "checkForUpdates": False}))
        # render every cell: JupyterLab 4 virtualises long notebooks (cells out of view are not
        # laid out, so their prompts and widgets cannot be read); the benchmarks keep
        # JupyterLab's own default ("contentVisibility"), as a student has it
        tracker = self.tmp / "lab-settings" / "@jupyterlab" / "notebook-extension"
        tracker.mkdir(parents=True, exist_ok=True)
        (tracker / "tracker.jupyterlab-settings").write_text(
            json.dumps({"windowingMode": self.windowing}))
        # never write the notebooks under test back to the repository
        docmanager = self.tmp / "lab-settings" / "@jupyterlab" / "docmanager-extension"
        docmanager.mkdir(parents=True, exist_ok=True)
        (docmanager / "plugin.jupyterlab-settings").write_text(json.dumps({"autosave": False}))
        env["JUPYTERLAB_SETTINGS_DIR"] = str(self.tmp / "lab-settings")
        env.update(self.extra_env)
        env["JUPYTERLAB_WORKSPACES_DIR"] = str(self.tmp / "workspaces")
        return env

    def start(self, timeout=60):
        jupyter = Path(sys.executable).with_name("jupyter")
        log = open(self.tmp / "server.log", "w")
        self.process = subprocess.Popen(
            [str(jupyter), "lab", "--no-browser", "--allow-root", "--ip", "127.0.0.1",
             "--port", str(self.port), f"--IdentityProvider.token={self.token}",
             f"--ServerApp.root_dir={ROOT}", "--LabApp.expose_app_in_browser=True",
             # checkpoints (JupyterLab makes one for each notebook it opens) go to the
             # server's own folder, never beside the course's notebooks
             f"--FileCheckpoints.checkpoint_dir={self.tmp / 'checkpoints'}"],
            env=self.environment(), stdout=log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                raise RuntimeError(f"JupyterLab exited early:\n{(self.tmp / 'server.log').read_text()[-3000:]}")
            try:
                urllib.request.urlopen(f"{self.url}/api/status?token={self.token}", timeout=2)
                return self
            except OSError:
                time.sleep(0.3)
        self.stop()
        raise RuntimeError("JupyterLab did not answer within {timeout} s")

    def stop(self):
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        self.process = None


def launch_browser(playwright, profile):
    if not Path(CHROMIUM).exists():
        raise RuntimeError("chromium is not installed: scripts/system-packages installs the "
                           "Debian package 'chromium' (run `make test`, or apt-get install "
                           "chromium)")
    return playwright.chromium.launch_persistent_context(
        str(profile), executable_path=CHROMIUM, headless=True, args=CHROMIUM_FLAGS,
        viewport={"width": 1400, "height": 1000})


class NotebookPage:
    """One notebook open in JupyterLab: run it, find its widgets, read its errors."""

    opened = 0

    def __init__(self, context, server, path):
        self.page = context.new_page()
        self.console_errors = []
        self.page.on("console", lambda m: self.console_errors.append(m.text)
                     if m.type == "error" else None)
        self.page.on("pageerror", lambda e: self.console_errors.append(str(e)))
        self.server, self.path = server, path

    def open(self, timeout=90):
        """Open the notebook and wait until its kernel is started and idle.

        On a cold server the kernel specs may arrive after the notebook opens; JupyterLab then
        asks which kernel to start (a "Select Kernel" dialog): accept the proposed one."""
        # a workspace of its own for every page: no layout restored from an earlier test, and no
        # "?reset" (which reloads the page after a moment, destroying what a test is reading)
        NotebookPage.opened += 1
        workspace = f"test-{os.getpid()}-{NotebookPage.opened}"
        self.page.goto(f"{self.server.url}/lab/workspaces/{workspace}/tree/{self.path}"
                       f"?token={self.server.token}")
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            dialog = self.page.locator(".jp-Dialog:has-text('Select Kernel') .jp-mod-accept")
            if dialog.count():
                dialog.first.click()
            name = self.page.locator(".jp-KernelName").all_text_contents()
            idle = self.page.locator(IDLE_KERNEL)
            if idle.count() and name and "No Kernel" not in name[0] and name[0].strip():
                return self
            time.sleep(0.5)
        raise TimeoutError(f"{self.path}: no idle kernel after {timeout} s "
                           f"(kernel name shown: {name})")

    def run_all(self, timeout=300_000):
        """Clear the stored outputs, run every cell and wait until each code cell has run.

        Clearing first matters: the stored notebook already shows execution counts, so without
        it a kernel slow to start (a cold machine builds matplotlib's font cache) would look
        finished before its first cell ran."""
        self.menu("Edit", "Clear Outputs of All Cells")
        self.page.wait_for_function(
            "() => !document.querySelector('.jp-OutputArea-output')", timeout=30_000)
        self.menu("Run", "Run All Cells")
        code_cells = self.page.locator(".jp-CodeCell").count()
        deadline = time.monotonic() + timeout / 1000
        stalled = 0
        while time.monotonic() < deadline:
            prompts = self.page.locator(".jp-CodeCell .jp-InputPrompt").all_text_contents()
            done = [p for p in prompts if any(ch.isdigit() for ch in p)]
            if len(done) == code_cells:
                break
            # an error stops "Run All": nothing queued, kernel idle, yet cells not run
            queued = any("*" in p for p in prompts)
            idle = self.page.locator(IDLE_KERNEL).count() > 0
            stalled = stalled + 1 if done and not queued and idle else 0
            if stalled >= 10:
                raise RuntimeError(f"{self.path}: Run All stopped after {len(done)} of "
                                   f"{code_cells} cells: {self.error_outputs()[:2]}")
            time.sleep(0.5)
        else:
            raise TimeoutError(f"{self.path}: not every cell ran within {timeout / 1000:.0f} s")
        self.page.wait_for_selector(IDLE_KERNEL, timeout=timeout)
        self.wait_for_widgets()
        return self

    def menu(self, title, item):
        """Choose `item` in the menu `title` of JupyterLab's menu bar."""
        self.page.click(f".lm-MenuBar-itemLabel:text-is('{title}')", timeout=10_000)
        self.page.click(f".lm-Menu-itemLabel:text-is('{item}')", timeout=10_000)

    def wait_for_widgets(self, timeout=60):
        """Wait until every widget view the stored notebook holds is rendered (views are built
        asynchronously after their cell finishes), then a moment for the first ipympl frames."""
        expected = len(expected_widget_cells(self.path))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.page.locator(WIDGET_VIEW).count() >= expected:
                break
            time.sleep(0.5)
        time.sleep(2)

    def error_outputs(self):
        """Texts of error and stderr outputs in the notebook."""
        items = self.page.locator(".jp-OutputArea-output[data-mime-type="
                                  "'application/vnd.jupyter.stderr'], "
                                  ".jp-OutputArea-output[data-mime-type="
                                  "'application/vnd.jupyter.error'], "
                                  ".jp-RenderedText[data-mime-type='application/vnd.jupyter.error']")
        return [items.nth(k).inner_text()[:500] for k in range(items.count())]

    def widget_problems(self):
        """Outputs where a widget failed to show ('Error displaying widget' and the like)."""
        texts = self.page.locator(".jp-OutputArea-output:has-text('Error displaying widget'), "
                                  ".jp-OutputArea-output:has-text('Error rendering')")
        return [texts.nth(k).inner_text()[:300] for k in range(texts.count())]

    def log_console_count(self):
        """How many messages JupyterLab's log console has collected (widget callback errors
        end up there, not in a cell's output)."""
        item = self.page.locator(".jp-LogConsoleStatusItem")
        if not item.count():
            return 0
        text = item.first.inner_text().strip()
        digits = "".join(ch for ch in text if ch.isdigit())
        return int(digits) if digits else 0

    def screenshot(self, name, locator=None):
        ARTIFACTS.mkdir(parents=True, exist_ok=True)
        path = ARTIFACTS / f"{name}.png"
        (locator or self.page).screenshot(path=str(path))
        return path

    def close(self):
        self.page.close()


def expected_widget_cells(path):
    """Indices of the code cells whose stored outputs hold a widget view."""
    nb = json.loads((ROOT / path).read_text())
    cells = [c for c in nb["cells"] if c["cell_type"] == "code"]
    return [k for k, c in enumerate(cells)
            if any("application/vnd.jupyter.widget-view+json" in o.get("data", {})
                   for o in c.get("outputs", []))]


WIDGET_VIEW = ".jp-OutputArea-output > .jupyter-widgets"


def widget_view(notebook, index):
    """The `index`-th widget output of the notebook (in page order)."""
    view = notebook.page.locator(WIDGET_VIEW).nth(index)
    view.scroll_into_view_if_needed()
    time.sleep(0.5)
    return view


def press_slider(view, slider_index, key="ArrowRight", times=20):
    """Move a slider of a widget with the keyboard, as a student can."""
    slider = view.locator(".widget-slider").nth(slider_index)
    slider.locator(".noUi-handle, .ui-slider-handle").first.click()
    for _ in range(times):
        slider.page.keyboard.press(key)
    time.sleep(1.5)                                   # round trip through the kernel + redraw


def figure_canvas(view):
    """The ipympl canvas element of a widget (the figure's pixels)."""
    return view.locator(".jupyter-matplotlib canvas").first


def drag_on_canvas(canvas, start, end, steps=12, settle=1.5):
    """Drag with the mouse from `start` to `end`, given as fractions of the canvas (0..1, y down),
    then wait `settle` seconds (the round trip through the kernel). ``steps=0`` is a click."""
    box = canvas.bounding_box()
    page = canvas.page
    x0, y0 = box["x"] + start[0] * box["width"], box["y"] + start[1] * box["height"]
    x1, y1 = box["x"] + end[0] * box["width"], box["y"] + end[1] * box["height"]
    page.mouse.move(x0, y0)
    page.mouse.down()
    for k in range(1, steps + 1):
        page.mouse.move(x0 + (x1 - x0) * k / steps, y0 + (y1 - y0) * k / steps)
        time.sleep(0.03)
    page.mouse.up()
    time.sleep(settle)


def data_to_canvas_fraction(x, y, xlim, ylim, left, right, bottom, top):
    """Where data point (x, y) lies on a canvas, as fractions (y down), for axes placed with
    subplots_adjust(left, right, bottom, top) and limits xlim, ylim."""
    fx = left + (x - xlim[0]) / (xlim[1] - xlim[0]) * (right - left)
    fy = bottom + (y - ylim[0]) / (ylim[1] - ylim[0]) * (top - bottom)
    return fx, 1.0 - fy


class PageKernel:
    """A second client of the kernel a notebook page runs on (through its connection file in
    the server's runtime folder): it reads the explorers' state the page cannot show, such as
    where a draggable point lies, and proves the kernel is the same one at the end."""

    # generous: the calls check liveness and read state, not speed; on a loaded 2-core CI
    # machine a kernel may still be working through an explorer's queued frames for a while
    def __init__(self, server, path, timeout=120):
        from jupyter_client import BlockingKernelClient

        sessions = json.load(urllib.request.urlopen(
            f"{server.url}/api/sessions?token={server.token}", timeout=10))
        ids = [s["kernel"]["id"] for s in sessions if s["path"] == path]
        if len(ids) != 1:
            raise RuntimeError(f"{path}: {len(ids)} kernel sessions, expected 1")
        self.kernel_id = ids[0]
        self.server, self.timeout = server, timeout
        connection = server.tmp / "jupyter_runtime_dir" / f"kernel-{self.kernel_id}.json"
        self.client = BlockingKernelClient(connection_file=str(connection))
        self.client.load_connection_file()
        self.client.start_channels()
        self._only_own_output()
        self.client.wait_for_ready(timeout=timeout)

    def _only_own_output(self):
        """Receive no widget messages: the kernel broadcasts every frame and every picture
        drawn ahead (course_lib/_prefetch.py) to every client, tens of megabytes after a
        lesson is driven. A client that reads them slower than they come fills ZeroMQ's
        queue for it (1,000 messages), and the kernel then drops what comes next for it, the
        output of this client's own call among them ("Timeout waiting for output", the
        kernel idle). Comm messages go out under the topic ``comm-<id>``; status, errors and
        results under ``kernel.<id>.``, printed text under ``stream.``."""
        import zmq

        socket = self.client.iopub_channel.socket
        socket.setsockopt(zmq.UNSUBSCRIBE, b"")
        for topic in (b"kernel.", b"stream.", b"execute_result", b"display_data", b"error"):
            socket.setsockopt(zmq.SUBSCRIBE, topic)

    def run(self, code):
        """Execute `code` in the page's kernel; return what it printed (raise on an error)."""
        self._drain()
        printed, errors = [], []

        def hook(msg):
            if msg["msg_type"] == "stream":
                printed.append(msg["content"]["text"])
            elif msg["msg_type"] == "error":
                errors.append("\n".join(msg["content"]["traceback"]))

        reply = self.client.execute_interactive(code, timeout=self.timeout, output_hook=hook,
                                                store_history=False)
        if reply["content"]["status"] != "ok":
            raise RuntimeError("".join(errors))
        return "".join(printed)

    def _drain(self):
        """Read away the broadcast messages received since the last call. The kernel sends
        every client every widget message and frame (the explorers' pictures drawn ahead
        among them); a client that has not read for a while holds ZeroMQ's limit of them
        (1,000 per side), and the kernel then drops new ones for it, the answer to the next
        call among them (seen as a "Timeout waiting for output" with the kernel idle)."""
        import queue

        while True:
            try:
                self.client.get_iopub_msg(timeout=0.01)
            except queue.Empty:
                return

    def json(self, code):
        """`code` ends by printing a JSON document: return it parsed."""
        return json.loads(self.run(code).strip().splitlines()[-1])

    def state(self):
        """The kernel's execution state as the server sees it ('idle', 'busy', 'dead'...)."""
        info = json.load(urllib.request.urlopen(
            f"{self.server.url}/api/kernels/{self.kernel_id}?token={self.server.token}",
            timeout=10))
        return info["execution_state"]

    def close(self):
        self.client.stop_channels()


def cell_execution_counts(notebook):
    """The execution count of the cell of each widget view, in page order."""
    return notebook.page.evaluate(
        """(selector) => [...document.querySelectorAll(selector)].map(view => {
             const prompt = view.closest('.jp-CodeCell').querySelector('.jp-InputPrompt');
             const digits = prompt.textContent.match(/\\d+/);
             return digits ? Number(digits[0]) : null;
           })""", WIDGET_VIEW)


_EXPLORERS = """
import json
from course_lib.widgets._base import Explorer
def _kept(explorer):
    prefetch = getattr(getattr(getattr(explorer, "fig", None), "canvas", None),
                       "_course_prefetch", None)
    return [c for c, _ in prefetch.spec()] if prefetch is not None else []
print(json.dumps([{"class": type(Out.get(n)).__name__,
                   "gestures": Out[n].mouse_gestures() if isinstance(Out.get(n), Explorer)
                   else [],
                   "kept": _kept(Out[n]) if isinstance(Out.get(n), Explorer) else []}
                  for n in COUNTS]))
"""


def page_explorers(notebook, kernel):
    """For each widget view of the page, in page order, the class of the object its cell
    displayed, that explorer's mouse gestures and the model ids of the controls whose
    pictures it draws ahead (course_lib/_prefetch.py; read in the page's kernel)."""
    return kernel.json(_EXPLORERS.replace("COUNTS", repr(cell_execution_counts(notebook))))
