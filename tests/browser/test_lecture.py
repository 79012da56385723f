"""Lecture mode in a real browser: JupyterLab started as `make lecture` starts it, a lesson
presented as slides with jupyterlab-deck (inside JupyterLab, so the widgets stay live), the
figures drawn at projector size. The screenshots of the slides are kept in
test-artifacts/browser/ (the README shows one, copied by `make screenshots`)."""
import time

import pytest

from .lab import LabServer, NotebookPage, figure_canvas

LECTURE_SCALE = 1.5          # course_lib.draw.DEFAULT_LECTURE_SCALE, what COURSE_LECTURE=1 means


@pytest.fixture(scope="module")
def lecture_lab(tmp_path_factory):
    server = LabServer(tmp_path_factory.mktemp("lecture"), env={"COURSE_LECTURE": "1"}).start()
    yield server
    server.stop()


def onscreen_cells(page):
    """Indices of the notebook cells the deck shows on the current slide."""
    return page.evaluate("() => Array.from(document.querySelectorAll('.jp-Notebook .jp-Cell'))"
                         ".flatMap((c, i) => c.classList.contains('jp-deck-mod-onscreen') ? "
                         "[i] : [])")


def test_a_lesson_is_presented_as_slides_with_live_widgets_at_projector_size(lecture_lab,
                                                                             browser):
    from course_lib.widgets.quaternion import QuaternionExplorer

    laptop = QuaternionExplorer()                      # this process: no lecture mode
    laptop_width = laptop.fig.get_size_inches()[0] * laptop.fig.dpi
    notebook = NotebookPage(browser, lecture_lab, "notebooks/ch03_transformations.ipynb")
    try:
        notebook.open().run_all()
        page = notebook.page
        page.locator(".jp-Notebook .jp-Cell").first.click()
        page.evaluate("() => window.jupyterapp.commands.execute('deck:start')")
        page.wait_for_selector("body[data-jp-deck-mode='presenting']", state="attached",
                               timeout=20_000)
        time.sleep(2)
        first = onscreen_cells(page)
        notebook.screenshot("lecture-slide-1")
        # the title slide: the chapter's title, and the quaternion explorer live under it
        assert first[0] == 0 and len(first) >= 2, first
        slide = page.locator(".jp-Cell.jp-deck-mod-onscreen")
        assert slide.locator(".jupyter-widgets .widget-slider").count() >= 3
        canvas = figure_canvas(slide.first.locator("xpath=..")).bounding_box()
        assert canvas["width"] == pytest.approx(LECTURE_SCALE * laptop_width, rel=0.03)
        # next slide, as the presenter does (the deck takes a moment to accept keys)
        for _ in range(10):
            page.keyboard.press("ArrowRight")
            time.sleep(1)
            if onscreen_cells(page) != first:
                break
        time.sleep(1)
        second = onscreen_cells(page)
        notebook.screenshot("lecture-slide-2")
        assert second and second[0] > first[-1], (first, second)
        heading = page.locator(".jp-Cell.jp-deck-mod-onscreen h2").first.inner_text()
        assert heading.startswith("1."), heading
        assert notebook.console_errors == [] and notebook.log_console_count() == 0
    finally:
        notebook.close()
