"""Headless tests of the linked parallel-coordinates and scatterplot-matrix explorers.

The scenes against the library and against computations typed here (the brush mask by loops,
the polyline raster of the selected records alone, the dots of the matrix by their pixel
positions), and the wiring: every control changes the picture, the mouse brushes (real
matplotlib events through tests/widget_harness.py), a slider moved back gives the first
picture back, and the link works both ways."""
import numpy as np
import pytest

from widget_harness import drag, mouse

from course_lib.dataviz import multidim as md
from course_lib.widgets import parallel_coordinates as W
from course_lib.widgets import scatterplot_matrix as S


def _loop_mask(table, brushes, how):
    out = []
    for row in table.data:
        inside = [all(lo <= row[k] <= hi for k, (lo, hi) in b.items()) for b in brushes]
        out.append(all(inside) if how == "AND" else any(inside))
    return np.array(out)


# ---------------------------------------------------------------------------------------------
# The pure parts
# ---------------------------------------------------------------------------------------------

def test_default_brushes_differ_under_and_or():
    for name in W.DATASETS:
        sel = W.Selection(name)
        brushes = list(sel.brushes.values())
        assert np.array_equal(sel.mask(), _loop_mask(sel.table, brushes, "AND"))
        sel.set_how("OR")
        assert np.array_equal(sel.mask(), _loop_mask(sel.table, brushes, "OR"))
        assert sel.mask().sum() > _loop_mask(sel.table, brushes, "AND").sum(), name


def test_scene_against_the_library():
    sel = W.Selection("cars (150)")
    sel.set_brush(("rect",), {3: (1200.0, 1800.0), 0: (15.0, 30.0)})
    state = W.State(selection=sel, order=[2, 0, 1, 3, 4, 5], flipped=[True] + [False] * 5,
                    image_size=(120, 60))
    s = W.scene(state)
    expected = md.parallel_coordinates(sel.table.data, order=[2, 0, 1, 3, 4, 5], flip=[0])
    expected[..., 0] /= 5
    assert np.allclose(s["lines"], expected)
    brushes = list(sel.brushes.values())
    assert np.array_equal(s["mask"], _loop_mask(sel.table, brushes, "AND"))
    # the highlighted layer is the raster of the selected polylines alone
    alone = md.rasterize_polylines(expected[s["mask"]], 120, 60, extent=(0, 1, 0, 1))
    assert np.array_equal(s["selected_counts"], alone)
    assert np.array_equal(s["counts"], md.rasterize_polylines(expected, 120, 60,
                                                              extent=(0, 1, 0, 1)))
    # mpg (attribute 0) is flipped and second: its brush [lo + 0.6 span, hi] is drawn at the
    # bottom of the axis at x = 1/5
    lo, hi = sel.table.data[:, 0].min(), sel.table.data[:, 0].max()
    x, a, b, kind = next(box for box in s["boxes"] if box[3] == "axis" and box[0] == 0.2)
    assert (a, b) == pytest.approx((0.0, 0.4)) and kind == "axis"
    assert s["low_labels"][1] == f"{hi:.4g}" and s["high_labels"][1] == f"{lo:.4g}"
    rect_rows = [box for box in s["boxes"] if box[3] == "rect"]
    assert sorted(round(box[0], 6) for box in rect_rows) == [0.2, 0.6]
    assert s["title"].startswith(f"{int(s['mask'].sum()):,} of 150")


def test_splom_scene_dots_and_rectangle():
    sel = W.Selection("correlation: clusters")
    sel.clear()
    sel.set_brush(("rect",), {0: (-1.0, 1.5), 1: (0.0, 3.0)})
    s = S.splom_scene(S.SplomState(selection=sel, side=100))
    d, size = 2, 50
    y = md.normalise_columns(sel.table.data)
    # a dot at the pixel of its normalised position (inset by the margin), 3 x 3 for 200 records
    pix = np.clip(np.floor((S.MARGIN + (1 - 2 * S.MARGIN) * y) * size), 0, size - 1).astype(int)
    expected = np.zeros((100, 100), int)
    mask = _loop_mask(sel.table, list(sel.brushes.values()), "AND")
    chosen = np.zeros((100, 100), int)
    for i in range(len(y)):
        for r, c in ((0, 1), (1, 0)):
            row0, col0 = (d - 1 - r) * size + pix[i, r], c * size + pix[i, c]
            for dr in range(3):
                for dc in range(3):
                    expected[min(row0 + dr, 99), min(col0 + dc, 99)] += 1
                    chosen[min(row0 + dr, 99), min(col0 + dc, 99)] += mask[i]
    assert np.array_equal(s["counts"], expected)
    assert np.array_equal(s["selected_counts"], chosen)
    lo = sel.table.data.min(axis=0)
    hi = sel.table.data.max(axis=0)
    x0 = S.MARGIN + (1 - 2 * S.MARGIN) * (-1.0 - lo[0]) / (hi[0] - lo[0])
    y0 = 0 + S.MARGIN + (1 - 2 * S.MARGIN) * (0.0 - lo[1]) / (hi[1] - lo[1])
    assert s["rect"][:2] == pytest.approx((x0, y0))
    names = S.splom_scene(S.SplomState(selection=sel, side=100, diagonal="names"))
    assert not np.array_equal(names["image"], s["image"])        # no histogram bars


# ---------------------------------------------------------------------------------------------
# The wiring
# ---------------------------------------------------------------------------------------------

def _picture(explorer):
    explorer.fig.canvas.draw()
    return np.asarray(explorer.fig.canvas.buffer_rgba()).copy()


def _changed(before, after):
    return int(np.count_nonzero(np.any(before != after, axis=-1)))


def test_every_control_changes_the_picture():
    pc = W.ParallelCoordinatesExplorer()
    checks = [
        ("range", lambda: setattr(pc.range, "value", (0.2, 0.9))),
        ("flip", lambda: setattr(pc.flip, "value", True)),
        ("swap", lambda: pc.swap.click()),
        ("how", lambda: setattr(pc.how, "value", "OR")),
        ("axis", lambda: setattr(pc.axis_menu, "value", 3)),
        ("clear", lambda: pc.clear.click()),
        ("dataset", lambda: setattr(pc.dataset, "value", "weather (10,000)")),
    ]
    for name, act in checks:
        before = _picture(pc)
        act()
        assert _changed(before, _picture(pc)) > 50, name


def test_slider_moved_back_gives_the_first_picture():
    pc = W.ParallelCoordinatesExplorer()
    first = _picture(pc)
    start = pc.range.value
    pc.range.value = (start[0] + 0.05, start[1])
    assert _changed(first, _picture(pc)) > 0
    pc.range.value = start
    assert _changed(first, _picture(pc)) == 0
    pc.flip.value = True
    pc.flip.value = False
    assert _changed(first, _picture(pc)) == 0


def test_controls_follow_the_chosen_axis():
    pc = W.ParallelCoordinatesExplorer()
    pc.axis_menu.value = 2
    assert pc.range.value == (0.0, 1.0) and not pc.flip.value      # no brush on horsepower
    pc.range.value = (0.5, 1.0)
    lo, hi = pc.selection.table.data[:, 2].min(), pc.selection.table.data[:, 2].max()
    assert pc.selection.brushes[("axis", 2)][2] == pytest.approx((lo + 0.5 * (hi - lo), hi))
    pc.flip.value = True
    pc.axis_menu.value = 0
    assert pc.range.value == (0.6, 1.0) and not pc.flip.value
    pc.axis_menu.value = 2
    assert pc.flip.value and pc.range.value == (0.5, 1.0)
    pc.range.value = (0.0, 1.0)                                   # the full range: no brush
    assert ("axis", 2) not in pc.selection.brushes


def test_swap_moves_the_chosen_axis_right():
    pc = W.ParallelCoordinatesExplorer()
    pc.axis_menu.value = 1
    pc.swap.click()
    assert pc.state.order == [0, 2, 1, 3, 4, 5]
    assert pc.current["labels"][2] == "cylinders"
    pc.axis_menu.value = 5
    pc.swap.click()                                               # the last wraps to the first
    assert pc.state.order == [5, 2, 1, 3, 4, 0]


def test_mouse_drag_on_an_axis_brushes_it_and_a_click_removes_it():
    pc = W.ParallelCoordinatesExplorer()
    pc.selection.clear()
    x = 3 / 5                                                     # the axis of weight
    drag(pc.ax, (x, 0.2), (x, 0.5))
    lo, hi = pc.selection.table.data[:, 3].min(), pc.selection.table.data[:, 3].max()
    assert pc.selection.brushes[("axis", 3)][3] == pytest.approx(
        (lo + 0.2 * (hi - lo), lo + 0.5 * (hi - lo)))
    assert pc.axis_menu.value == 3 and pc.range.value == (0.2, 0.5)
    weight = pc.selection.table.data[:, 3]
    assert np.array_equal(pc.current["mask"],
                          (weight >= lo + 0.2 * (hi - lo)) & (weight <= lo + 0.5 * (hi - lo)))
    mouse(pc.ax, "button_press_event", (x, 0.3))
    mouse(pc.ax, "button_release_event", (x, 0.3))
    assert ("axis", 3) not in pc.selection.brushes
    drag(pc.ax, (0.5 / 5, 0.2), (0.5 / 5, 0.8))                   # between axes: nothing
    assert not pc.selection.brushes


def test_drag_on_a_flipped_axis():
    pc = W.ParallelCoordinatesExplorer()
    pc.flip.value = True                                         # axis 0 (mpg) upside down
    drag(pc.ax, (0.0, 0.9), (0.0, 0.7))                          # near the top: low mpg
    lo, hi = pc.selection.table.data[:, 0].min(), pc.selection.table.data[:, 0].max()
    assert pc.selection.brushes[("axis", 0)][0] == pytest.approx(
        (lo + 0.1 * (hi - lo), lo + 0.3 * (hi - lo)))


def test_gestures_hit_what_they_name():
    both = S.link()
    pc, splom = both.pc, both.splom
    for explorer, ax in ((pc, pc.ax), (splom, splom.ax)):
        (gesture,) = explorer.mouse_gestures()
        inverse = ax.transData.inverted()
        height, width = explorer.fig.bbox.height, explorer.fig.bbox.width
        start, end = (inverse.transform((fx * width, (1 - fy) * height))
                      for fx, fy in (gesture["start"], gesture["end"]))
        before = _picture(explorer)
        drag(ax, start, end)
        assert _changed(before, _picture(explorer)) > 50
    assert ("rect",) in pc.selection.brushes
    assert set(pc.selection.brushes[("rect",)]) == {0, 5}       # year up, mpg across


def test_the_link_works_both_ways():
    both = S.link()
    pc, splom = both.pc, both.splom
    pc.brush_drag(2, 0.0, 0.4, final=True)
    assert np.array_equal(splom.current["mask"], pc.selection.mask())
    before = _picture(splom)
    pc.how.value = "OR"
    assert np.array_equal(splom.current["mask"], pc.current["mask"])
    assert _changed(before, _picture(splom)) > 50
    before = _picture(pc)
    drag(splom.ax, (0.2, 3.2), (0.7, 3.8))                     # panel row 2, col 0
    assert ("rect",) in pc.selection.brushes
    assert np.array_equal(pc.current["mask"], splom.current["mask"])
    assert _changed(before, _picture(pc)) > 50
    assert any(box[3] == "rect" for box in pc.current["boxes"])
    mouse(splom.ax, "button_press_event", (0.5, 3.5))            # a click removes it
    mouse(splom.ax, "button_release_event", (0.5, 3.5))
    assert ("rect",) not in pc.selection.brushes
    pc.dataset.value = "correlation: negative"                   # the matrix follows
    assert splom.current["d"] == 2 and splom.current["names"] == ("x", "y")
    before = _picture(splom)
    splom.diagonal.value = "names"
    assert _changed(before, _picture(splom)) > 50
    assert both.png()[:4] == b"\x89PNG"


def test_link_refuses_two_selections():
    pc = W.ParallelCoordinatesExplorer()
    with pytest.raises(ValueError, match="share pc's selection"):
        S.link(pc, S.ScatterplotMatrixExplorer())
