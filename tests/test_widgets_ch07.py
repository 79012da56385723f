"""Headless tests of the chapter 7 editors: scenes against independent references (scipy,
the `bezier` package, closed forms) and the wiring (drag, buttons, sliders)."""
from math import comb

import bezier as bezier_pkg
import numpy as np
import pytest
from scipy.interpolate import BSpline

from course_lib.widgets import bezier, bspline, surface


def bernstein_curve(points, t):
    n = len(points) - 1
    weights = np.array([[comb(n, i) * s**i * (1 - s) ** (n - i) for i in range(n + 1)] for s in t])
    return weights @ points


# --- Bézier editor ---------------------------------------------------------------------------

@pytest.mark.parametrize("t", [0.0, 0.25, 0.4, 0.9, 1.0])
def test_bezier_scene_against_the_bezier_package(t):
    state = bezier.State(t=t)
    s = bezier.scene(state)
    curve = bezier_pkg.Curve(state.points.T, degree=len(state.points) - 1)
    assert np.allclose(s["curve"], curve.evaluate_multi(np.linspace(0, 1, bezier.SAMPLES)).T)
    assert np.allclose(s["point"], curve.evaluate(t)[:, 0])
    # the last level of the construction is the point; the one before spans the tangent
    assert np.allclose(s["levels"][-1][0], s["point"])
    a, b = s["levels"][-2]
    if np.linalg.norm(b - a) > 1e-12:
        assert np.allclose(s["tangent"], (b - a) / np.linalg.norm(b - a))


def test_bezier_convex_hull_contains_the_curve():
    rng = np.random.default_rng(3)
    for _ in range(20):
        points = rng.uniform(0, 5, (int(rng.integers(3, 9)), 2))
        s = bezier.scene(bezier.State(points=points))
        hull = s["hull"][:-1]
        edges = np.roll(hull, -1, axis=0) - hull
        rel = s["curve"][:, None, :] - hull[None]
        cross = edges[None, :, 0] * rel[..., 1] - edges[None, :, 1] * rel[..., 0]
        assert np.all(cross >= -1e-9)                    # left of every hull edge (CCW)


def test_bezier_editor_buttons_keep_or_split_the_curve():
    ex = bezier.BezierExplorer()
    before = np.array(ex.curve.get_xydata())
    ex.elevate()
    assert len(ex.state.points) == 5
    assert np.allclose(ex.curve.get_xydata(), before, atol=1e-12)    # elevation: same curve
    ex.t.value = 0.3
    original = ex.state.points.copy()
    ex.subdivide()
    left = bernstein_curve(ex.state.points, np.linspace(0, 1, 50))
    assert np.allclose(left, bernstein_curve(original, 0.3 * np.linspace(0, 1, 50)))
    assert "Subdivided" in ex.info.value
    ex.add_point()
    ex.remove_point()
    ex.remove_point()
    assert len(ex.state.points) == 4
    ex.drag.press(*ex.state.points[0])
    ex.drag.move(2.0, 2.0)
    assert np.allclose(ex.state.points[0], (2.0, 2.0))
    assert np.allclose(ex.curve.get_xydata()[0], (2.0, 2.0))        # endpoint interpolation


# --- B-spline / NURBS editor -----------------------------------------------------------------

@pytest.mark.parametrize("kind", ["clamped", "uniform", "repeated interior"])
@pytest.mark.parametrize("degree", [1, 2, 3, 4])
def test_bspline_scene_against_scipy(kind, degree):
    state = bspline.State(degree=degree, knots=kind)
    s = bspline.scene(state)
    assert s["error"] is None
    knots = s["knots"]
    assert len(knots) == len(state.points) + degree + 1
    reference = BSpline(knots, state.points, degree)(s["t"][:-1])
    assert np.allclose(s["curve"][:-1], reference, atol=1e-12)
    assert np.allclose(s["basis"].sum(axis=1), 1.0)


def test_repeated_interior_knots_make_the_curve_pass_through_a_control_point():
    state = bspline.State(degree=3, knots="repeated interior")
    knots = bspline.scene(state)["knots"]
    # a knot of multiplicity p: the curve interpolates a control point there (scipy evaluates)
    u = knots[4]
    assert np.count_nonzero(knots == u) == 3
    assert np.allclose(BSpline(knots, state.points, 3)(u), state.points[3])


def test_nurbs_weight_pulls_towards_the_point():
    state = bspline.State(selected=2)
    plain = bspline.scene(state)
    state.weights = state.weights.copy()
    state.weights[2] = 5.0
    heavy = bspline.scene(state)
    target = state.points[2]
    assert np.min(np.linalg.norm(heavy["curve"] - target, axis=1)) < \
        np.min(np.linalg.norm(plain["curve"] - target, axis=1))
    # the rational basis, recomputed here from scipy's B-spline basis
    knots = plain["knots"]
    basis = np.stack([BSpline.basis_element(knots[i:i + 5], extrapolate=False)(plain["t"][:-1])
                      for i in range(7)], axis=1)
    basis = np.nan_to_num(basis)
    rational = basis * state.weights
    rational /= rational.sum(axis=1, keepdims=True)
    assert np.allclose(heavy["basis"][:-1], rational, atol=1e-9)


def test_local_control_moves_only_the_support():
    state = bspline.State(selected=1)
    s0 = bspline.scene(state)
    state.points = state.points.copy()
    state.points[1] += [0.5, -0.7]
    s1 = bspline.scene(state)
    lo, hi = s0["support"]
    outside = (s0["t"] < lo) | (s0["t"] > hi)
    assert outside.any()
    assert np.allclose(s0["curve"][outside], s1["curve"][outside], atol=1e-12)
    assert not np.allclose(s0["curve"][~outside], s1["curve"][~outside])


def test_bspline_editor_controls():
    ex = bspline.BSplineExplorer()
    ex.drag.press(*ex.state.points[4])                    # clicking a point selects it
    assert ex.point.value == 4 and ex.state.selected == 4
    ex.drag.release()
    ex.weight.value = 3.0
    assert ex.state.weights[4] == pytest.approx(3.0) and "NURBS" in ex.info.value
    ex.point.value = 2
    assert ex.weight.value == pytest.approx(1.0)           # the slider shows P2's weight
    ex.knot_text.value = "0, 0, 0, 1"
    assert "knots must have" in ex.info.value and ex.curve.get_xydata().size == 0
    ex.knot_text.value = "0,0,0,0,0.2,0.4,0.6,1,1,1,1"
    assert "knots must have" not in ex.info.value
    ex.knot_text.value = "0, zero, 1"
    assert "numbers separated by commas" in ex.info.value
    ex.knots.value = "clamped"
    ex.add_point()
    assert len(ex.state.points) == 8 and len(ex.state.weights) == 8
    ex.degree.value = 5
    ex.remove_point()
    ex.remove_point()
    assert len(ex.state.points) == 6                      # degree 5 needs at least 6 points


# --- surface explorer ------------------------------------------------------------------------

def test_surface_bspline_patch_moves_only_over_the_support():
    s = surface.scene(surface.State(kind="B-spline", i=3, j=4, lift=1.0))
    knots = np.concatenate([np.zeros(3), np.linspace(0, 1, 7)[1:-1], np.ones(3)])
    u = np.linspace(0, 1, surface.SAMPLES)
    inside_u = (u >= knots[3]) & (u < knots[6])
    inside_v = (u >= knots[4]) & (u < knots[7])
    expected = np.outer(inside_u, inside_v)
    # where both basis functions are non-zero the patch moves; elsewhere it does not
    assert np.array_equal(s["changed"][:-1, :-1], expected[:-1, :-1])
    bez = surface.scene(surface.State(kind="Bézier"))
    assert bez["changed"][1:-1, 1:-1].all()               # Bézier: global control


def test_surface_against_a_tensor_product_of_scipy_splines():
    state = surface.State(kind="B-spline", lift=0.7)
    s = surface.scene(state)
    knots = np.concatenate([np.zeros(3), np.linspace(0, 1, 7)[1:-1], np.ones(3)])
    u = np.linspace(0, 1, surface.SAMPLES)[:-1]
    bu = np.stack([BSpline(knots, np.eye(8)[i], 2)(u) for i in range(8)], axis=1)
    expected = np.einsum("ui,vj,ijk->uvk", bu, bu, s["grid"])
    assert np.allclose(s["surface"][:-1, :-1], expected, atol=1e-12)


def test_surface_explorer_renders_off_screen():
    ex = surface.SurfaceExplorer()
    first = ex.frame().copy()
    ex.lift.value = -1.0
    # the screen shows the plotter's new frame
    assert np.array_equal(ex.frame(), ex.plotter.screenshot(return_img=True))
    assert not np.array_equal(ex.frame(), first)
    ex.kind.value = "NURBS"
    ex.weight.value = 5.0
    assert "pulls the patch" in ex.info.value
    assert ex.png()[:4] == b"\x89PNG"


def test_labels_hide_while_dragging_and_come_back_on_release():
    ex = bezier.BezierExplorer()
    ex.drag.press(*ex.state.points[2])
    ex.drag.move(2.0, 2.0)
    shown = [label.get_text() for label in ex.labels if label.get_text()]
    assert shown == ["P2"]                                 # only the dragged point's label
    ex.drag.release()
    assert [label.get_text() for label in ex.labels[:4]] == ["P0", "P1", "P2", "P3"]


def test_surface_weight_is_greyed_out_unless_the_patch_is_rational():
    ex = surface.SurfaceExplorer()
    for kind in surface.KINDS:
        ex.kind.value = kind
        assert ex.weight.disabled == (kind != "NURBS")
        # and a weight changes the patch exactly when it is enabled
        heavy = surface.State(**{**vars(ex.state), "weight": 4.0})
        moved = not np.allclose(surface.scene(heavy)["surface"], surface.scene(ex.state)["surface"])
        assert moved == (kind == "NURBS")


def test_the_knot_fields_example_fits_and_differs_from_the_presets():
    """Typing the hint's example gives a valid curve, other than any preset's."""
    ex = bspline.BSplineExplorer()
    for degree, extra in ((3, 0), (2, 2), (5, 1)):
        ex.degree.value = degree
        for _ in range(extra):
            ex.add_point()
        example = ex.knot_example()
        assert example in ex.knot_text.placeholder
        knots = [float(x) for x in example.split(",")]
        assert len(knots) == len(ex.state.points) + degree + 1
        ex.knot_text.value = example
        typed = bspline.scene(ex.state)
        assert typed["error"] is None, typed["error"]
        for preset in bspline.KNOT_PRESETS:
            if preset != "custom":
                other = bspline.scene(bspline.State(**{**vars(ex.state), "knots": preset}))
                assert other["error"] is not None or not np.allclose(other["curve"],
                                                                      typed["curve"])
        ex.knots.value = "clamped"
