"""The design card's widgets respond in a real browser: a slider moved with the keyboard, a
control point dragged with the mouse, a clipping step taken with a button. Each test compares
screenshots of the figure before and after (pixels changed inside the figure) and reads the text
panel; the screenshots are kept in test-artifacts/browser/."""
import pytest

from .lab import (NotebookPage, data_to_canvas_fraction, drag_on_canvas, figure_canvas,
                  press_slider, widget_view)
from .pixels import changed_pixels, changed_pixels_in

MIN_CHANGED = 400            # pixels: redrawing a curve or a shape changes thousands


@pytest.fixture(scope="module")
def open_notebook(lab, browser):
    """Open and run a notebook once per module; closed at the end, also after a failure."""
    opened = {}

    def get(path):
        if path not in opened:
            opened[path] = NotebookPage(browser, lab, path).open().run_all()
        return opened[path]
    yield get
    for notebook in opened.values():
        notebook.close()


def slider_changes_figure(notebook, view_index, slider_index, name, text_selector):
    """Move a slider; return (pixels changed in the figure, text before, text after)."""
    view = widget_view(notebook, view_index)
    canvas = figure_canvas(view)
    text = view.locator(text_selector).first
    before_text = text.inner_text()
    before = notebook.screenshot(f"{name}-before", canvas).read_bytes()
    press_slider(view, slider_index)
    after = notebook.screenshot(f"{name}-after", canvas).read_bytes()
    notebook.screenshot(f"{name}-widget", view)
    return changed_pixels(before, after), before_text, text.inner_text()


def test_quaternion_slider_turns_the_f_and_changes_the_matrix(open_notebook):
    notebook = open_notebook("notebooks/ch03_transformations.ipynb")
    changed, before, after = slider_changes_figure(notebook, 0, 2, "quaternion-explorer",
                                                   ".widget-html, .widget-htmlmath")
    assert changed > MIN_CHANGED
    assert before != after and "70" in after          # 50 + 20 steps of 1 degree
    assert notebook.log_console_count() == 0 and notebook.console_errors == []


def test_bezier_control_point_dragged_with_the_mouse_redraws_the_curve(open_notebook):
    notebook = open_notebook("notebooks/ch07_curves_surfaces.ipynb")
    view = widget_view(notebook, 0)
    canvas = figure_canvas(view)
    before_text = view.locator(".widget-html").last.inner_text()
    before = notebook.screenshot("bezier-editor-before", canvas).read_bytes()
    layout = dict(xlim=(-0.5, 5.5), ylim=(-0.5, 5.5), left=0.1, right=0.98, bottom=0.08,
                  top=0.94)                       # widgets/bezier.py's figure
    start = data_to_canvas_fraction(1.0, 3.8, **layout)        # the default P1
    end = data_to_canvas_fraction(3.0, 1.0, **layout)
    drag_on_canvas(canvas, start, end)
    after = notebook.screenshot("bezier-editor-after", canvas).read_bytes()
    notebook.screenshot("bezier-editor-widget", view)
    assert changed_pixels(before, after) > MIN_CHANGED
    assert view.locator(".widget-html").last.inner_text() != before_text   # new curve point
    assert notebook.log_console_count() == 0 and notebook.console_errors == []


def test_clipping_visualizer_steps_back_and_the_clipped_segment_changes(open_notebook):
    notebook = open_notebook("notebooks/ch05_culling_hse.ipynb")
    view = widget_view(notebook, 0)                    # Cohen-Sutherland, at its last step
    canvas = figure_canvas(view)
    before = notebook.screenshot("cohen-sutherland-before", canvas).read_bytes()
    assert "accept" in view.locator(".widget-html").last.inner_text()
    view.locator("button[title='previous step']").click()
    # the segment is one clip longer (the new picture within 10 s: on a loaded machine the
    # round trip through the kernel can take more than a second)
    for _ in range(20):
        view.page.wait_for_timeout(500)
        after = notebook.screenshot("cohen-sutherland-after", canvas).read_bytes()
        if changed_pixels(before, after) > MIN_CHANGED // 4:
            break
    notebook.screenshot("cohen-sutherland-widget", view)
    assert changed_pixels(before, after) > MIN_CHANGED // 4
    text = view.locator(".widget-html").last.inner_text()
    assert "clip" not in text or "moves to the intersection" in text
    assert notebook.log_console_count() == 0 and notebook.console_errors == []


def test_transfer_function_point_dragged_up_changes_the_rendered_images(open_notebook):
    notebook = open_notebook("notebooks/ch10_visualization_principles.ipynb")
    view = widget_view(notebook, 0)                     # the transfer-function editor
    canvas = figure_canvas(view)
    readout = view.locator(".widget-slider:has-text('opacity α') .widget-readout").first
    point = view.locator(".widget-slider:has-text('point') .widget-readout").first
    before_opacity = float(readout.inner_text())
    before = notebook.screenshot("transfer-function-before", canvas).read_bytes()
    # where the "skin" preset's point 6, at (0.8, 0.3), and the drop at (0.8, 0.75) lie on the
    # canvas: the same figure built headless (the lesson's explorer has its default layout)
    from course_lib.widgets.transfer_function import TransferFunctionExplorer
    headless = TransferFunctionExplorer()
    start = headless._canvas_fraction(headless.drag.ax, (0.8, 0.3))
    end = headless._canvas_fraction(headless.drag.ax, (0.8, 0.75))
    drag_on_canvas(canvas, start, end)
    view.page.wait_for_timeout(2500)                   # the full ray cast after the drop
    after = notebook.screenshot("transfer-function-after", canvas).read_bytes()
    notebook.screenshot("transfer-function-widget", view)
    # the 2D field and the volume rendering (the top half of the figure) were re-rendered
    assert changed_pixels_in(before, after, 0.0, 0.5) > MIN_CHANGED
    assert before_opacity == pytest.approx(0.3, abs=0.01)   # the preset's point 6
    assert point.inner_text().strip() == "6"            # the dragged point is selected
    after_opacity = float(readout.inner_text())
    assert 0.6 < after_opacity < 0.9, after_opacity     # where the mouse let go (0.75)
    assert notebook.log_console_count() == 0 and notebook.console_errors == []
