"""The timed mock exam in the page: the countdown ticks in the browser, and when it reaches
zero the page tells the kernel, which ends the exam and saves it (no kernel message per tick)."""
import re
import time

import nbformat
from nbformat.v4 import new_code_cell, new_notebook

from .lab import ARTIFACTS, ROOT, NotebookPage, PageKernel

TIMED = """%matplotlib widget
import os, tempfile
os.environ["COURSE_PROGRESS_FILE"] = os.path.join(tempfile.mkdtemp(), "progress.json")
from course_lib.widgets.mock_exam import MockExamWidget

exam = MockExamWidget(seed=1, chapters=[3], n_questions=2, time_limit=0.15)   # 9 seconds
exam"""


def test_the_countdown_ticks_in_the_page_and_ends_the_exam_at_zero(lab, browser):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    nb = new_notebook(cells=[new_code_cell(TIMED)])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3 (ipykernel)",
                                 "language": "python"}
    path = ARTIFACTS / "timed_exam.ipynb"
    nbformat.write(nb, path)
    relative = path.relative_to(ROOT).as_posix()
    notebook = NotebookPage(browser, lab, relative).open().run_all()
    kernel = None
    try:
        assert notebook.error_outputs() == []
        timer = notebook.page.locator(".course-countdown")
        timer.wait_for(timeout=60_000)
        seen = set()
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline:
            seen.add(timer.inner_text())
            if "Time is up" in seen:
                break
            time.sleep(0.2)
        ticking = sorted(t for t in seen if re.fullmatch(r"Time left: 0:0\d", t))
        assert len(ticking) >= 3, seen                 # it counted down in the page
        assert "Time is up" in seen, seen              # and stopped at zero
        kernel = PageKernel(lab, relative)
        state = kernel.json("import json\nfrom course_lib import progress\n"
                            "print(json.dumps({'done': exam.state.done, "
                            "'timed_out': exam.state.timed_out, "
                            "'saved': [e.get('timed_out') for e in progress.read_history()]}))")
        assert state == {"done": True, "timed_out": True, "saved": [True]}, state
        assert "The time is up" in notebook.page.locator(".jp-Cell-outputArea").first.inner_text()
        notebook.screenshot("timed-exam")
    finally:
        if kernel is not None:
            kernel.close()
        notebook.close()
