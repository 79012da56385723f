"""Every lesson notebook, opened and run in JupyterLab in headless chromium: no error output,
no console error, no message in JupyterLab's log console, and every widget of the notebook
rendered (nbval only proves the kernel side)."""
from pathlib import Path

import pytest

from .lab import ROOT, WIDGET_VIEW, NotebookPage, expected_widget_cells

LESSONS = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "notebooks").glob("*.ipynb"))


@pytest.mark.parametrize("path", LESSONS, ids=lambda p: Path(p).stem)
def test_lesson_runs_in_jupyterlab_with_every_widget_rendered(lab, browser, path):
    notebook = NotebookPage(browser, lab, path).open().run_all()
    try:
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
            view = views.nth(k)
            drawn = view.locator(".jupyter-matplotlib, .widget-image, img")
            assert drawn.count() > 0, f"widget {k} shows no figure (ipympl canvas or image)"
    finally:
        notebook.close()
