"""The browser tests can fail: a deliberately broken widget (an exception in its update) is
caught by the same checks the interaction tests make."""
import nbformat
from nbformat.v4 import new_code_cell, new_notebook

from .lab import ARTIFACTS, ROOT, NotebookPage
from .test_interactions import MIN_CHANGED, slider_changes_figure

BROKEN = """%matplotlib widget
from course_lib.widgets.quaternion import QuaternionExplorer


class BrokenExplorer(QuaternionExplorer):
    def update(self):
        raise RuntimeError("a deliberately broken widget")


BrokenExplorer()"""


def test_a_widget_whose_update_raises_fails_the_checks(lab, browser):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    nb = new_notebook(cells=[new_code_cell(BROKEN)])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3 (ipykernel)",
                                 "language": "python"}
    path = ARTIFACTS / "broken_widget.ipynb"
    nbformat.write(nb, path)
    notebook = NotebookPage(browser, lab, path.relative_to(ROOT).as_posix()).open().run_all()
    try:
        assert notebook.error_outputs() == []          # it builds fine...
        changed, before, after = slider_changes_figure(notebook, 0, 2, "broken-widget",
                                                       ".widget-html, .widget-htmlmath")
        # ...but moving its slider neither redraws nor updates the text, and the exception
        # lands in JupyterLab's log console: each of these fails the interaction tests
        assert changed < MIN_CHANGED
        assert before == after
        assert notebook.log_console_count() > 0
    finally:
        notebook.close()
