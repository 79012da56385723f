"""Headless tests of the chapter 18 explorers: scenes against independent references
(scikit-image, scipy, trimesh, closed forms) and the wiring (sliders, dropdowns, drags)."""
import numpy as np
import pytest
import trimesh
from scipy.integrate import solve_ivp
from scipy.interpolate import RegularGridInterpolator
from scipy.linalg import expm
from skimage import measure

from course_lib import scivis
from course_lib.widgets import isovalue, streamlines


# --- isolines ---------------------------------------------------------------------------------

def _point_to_polylines(points, polylines):
    """Distance from each point to the nearest segment of a set of polylines."""
    segs = np.concatenate([np.stack([p[:-1], p[1:]], axis=1) for p in polylines])
    a, b = segs[:, 0], segs[:, 1]
    d = b - a
    t = np.clip(np.einsum("psk,sk->ps", points[:, None] - a, d)
                / np.maximum((d * d).sum(1), 1e-300), 0, 1)
    nearest = a + t[..., None] * d
    return np.linalg.norm(points[:, None] - nearest, axis=-1).min(axis=1)


@pytest.mark.parametrize("kind, level", [("egg crate", 0.1), ("egg crate", -0.35),
                                         ("hills", 0.2), ("circle", 0.6), ("saddle", 0.05)])
def test_isoline_scene_matches_scikit_image(kind, level):
    state = isovalue.State(field=kind, size=14, level=level)
    s = isovalue.scene(state)
    data = s["field"]
    contours = measure.find_contours(data.values, level)        # (row, col) index coordinates
    ref = [np.asarray(data.origin) + c[:, ::-1] * np.asarray(data.spacing) for c in contours]
    ends = s["segments"].reshape(-1, 2)
    assert len(ends) > 0
    # every segment end lies on an edge crossing of skimage's contours (same interpolation)
    assert _point_to_polylines(ends, ref).max() < 1e-9
    total = np.linalg.norm(s["segments"][:, 1] - s["segments"][:, 0], axis=1).sum()
    ref_total = sum(np.linalg.norm(np.diff(c, axis=0), axis=1).sum() for c in ref)
    assert total == pytest.approx(ref_total, rel=0.02)  # differs only in saddle cells


def test_isoline_cases_and_counts_by_hand():
    s = isovalue.scene(isovalue.State(field="hills", size=9, level=0.3))
    f = s["field"].values
    bits = (f >= 0.3).astype(int)
    hand = bits[:-1, :-1] + 2 * bits[:-1, 1:] + 4 * bits[1:, 1:] + 8 * bits[1:, :-1]
    assert np.array_equal(s["cases"], hand)
    assert np.array_equal(s["counts"], [np.sum(hand == k) for k in range(16)])
    assert len(s["above"]) == bits.sum() and len(s["below"]) == bits.size - bits.sum()


def test_reference_isoline_lies_on_the_bilinear_interpolant():
    s = isovalue.scene(isovalue.State(field="egg crate", size=10, level=0.2))
    data = s["field"]
    xs, ys = data.axes
    bilinear = RegularGridInterpolator((ys, xs), data.values, method="linear")
    pts = s["reference"].reshape(-1, 2)
    values = bilinear(pts[:, ::-1])
    # fine-grid marching squares is linear between fine samples: close to the level
    assert np.abs(values - 0.2).max() < 0.02


def test_alternative_segments_are_the_other_pairing_of_the_same_crossings():
    # a single saddle cell, corners 0 and 2 above
    field = np.array([[2.0, 0.0], [0.0, 3.0]])
    chosen = scivis.marching_squares(field, 1.0)
    other = isovalue.alternative_segments(field, 1.0)
    assert chosen.shape == other.shape == (2, 2, 2)
    # the same four edge crossings, by hand: edge 0 at x = 1/2, edge 1 at y = 1/3,
    # edge 2 (from corner 2 = (1, 1), value 3, to corner 3 = (0, 1), value 0) two thirds of
    # the way, at x = 1/3; edge 3 at y = 1/2
    hand = {(0.5, 0.0), (1.0, 1 / 3), (1 / 3, 1.0), (0.0, 0.5)}

    def as_set(segs):
        return {tuple(np.round(p, 9)) for p in segs.reshape(-1, 2)}
    rounded = {tuple(np.round(p, 9)) for p in hand}
    assert as_set(chosen) == as_set(other) == rounded
    pairs = {frozenset(map(tuple, np.round(seg, 9))) for seg in chosen}
    other_pairs = {frozenset(map(tuple, np.round(seg, 9))) for seg in other}
    assert pairs.isdisjoint(other_pairs)
    # centre mean 1.25 >= 1: the decider joins corners 0 and 2 through the cell, so the
    # chosen segments run from edge 0 to edge 1 and from edge 2 to edge 3
    assert frozenset({(0.5, 0.0), tuple(np.round((1.0, 1 / 3), 9))}) in pairs


def test_isoline_explorer_wiring():
    ex = isovalue.IsolineExplorer()
    ex.level.value = -0.3
    s = isovalue.scene(ex.state)
    assert np.allclose(np.array(ex.segments.get_segments()), s["segments"])
    assert len(ex.saddle_cells.get_paths()) == len(s["saddles"])
    shown = sorted(k for k, marks in ex.labels.items() for _ in marks.get_offsets())
    assert shown == sorted(s["labels"][1].tolist())
    centres = np.concatenate([marks.get_offsets() for marks in ex.labels.values()])
    f = s["field"]
    # each number sits at the centre of a cell the isoline crosses (corners not all alike)
    j, i = np.round((centres - f.origin) / f.spacing - 0.5).astype(int).T
    assert np.all((s["cases"][i, j] != 0) & (s["cases"][i, j] != 15))
    assert "c = -0.300" in ex.info.value
    ex.field.value = "circle"
    ex.size.value = 6
    assert ex.state.size == 6 and ex.state.field == "circle"
    values = isovalue.example_data("circle", 6).values
    step = ex.level.step
    # the range covers the data, ends on whole steps, and is at most one step wider each side
    assert ex.level.min <= values.min() < ex.level.min + step
    assert ex.level.max - step < values.max() <= ex.level.max
    for end in (ex.level.min, ex.level.max, ex.level.value):
        assert abs(end / step - round(end / step)) < 1e-9
    above = ex.above.get_xydata()
    data = isovalue.example_data("circle", 6)
    assert len(above) == int((data.values >= ex.level.value).sum())
    ex.cases_box.value = False
    assert not any(len(marks.get_offsets()) for marks in ex.labels.values())
    assert ex.png()[:4] == b"\x89PNG"


def _browser_snap(slider):
    """What the browser's slider does when its range or step changes: snap the value to
    min + k step (noUiSlider) and send it back to the kernel."""
    k = round((slider.value - slider.min) / slider.step)
    slider.value = min(max(slider.min + k * slider.step, slider.min), slider.max)


def test_isoline_isovalue_survives_a_change_of_resolution_and_back():
    # the browser snaps the isovalue to its slider's grid at every change of range; a grid
    # that moved with the data's range left the value elsewhere after 12 -> 17 -> 12 samples
    # (a browser test saw the picture not come back, now and then)
    for field in isovalue.FIELDS:
        ex = isovalue.IsolineExplorer(isovalue.State(field=field))
        _browser_snap(ex.level)
        first, picture = ex.level.value, ex.png()
        for size in (*range(13, 18), *range(16, 11, -1)):
            ex.size.value = size
            _browser_snap(ex.level)
        assert ex.level.value == pytest.approx(first, abs=1e-12), field
        assert ex.state.level == ex.level.value
        assert ex.png() == picture, field


def test_isoline_example_data_rejects_unknown_fields():
    with pytest.raises(ValueError, match="kind"):
        isovalue.example_data("nope")


# --- isosurfaces ------------------------------------------------------------------------------

def test_mesh_summary_agrees_with_trimesh():
    for kind, level in (("torus", 0.0), ("blobs", 0.5), ("blobs", 0.3), ("sphere", 0.0)):
        data = isovalue.example_volume(kind)
        v, t = scivis.marching_cubes(data.values, level, data.spacing, data.origin)
        s = isovalue.mesh_summary(v, t)
        mesh = trimesh.Trimesh(v, t, process=False)
        assert s["euler"] == mesh.euler_number
        assert (s["boundary"] == 0) == mesh.is_watertight
        assert s["components"] == len(mesh.split(only_watertight=False))
    assert isovalue.mesh_summary(*scivis.marching_cubes(
        isovalue.example_volume("torus").values, 0.0))["genus"] == 1


def test_classic_table_opens_holes_only_where_faces_are_ambiguous():
    data = isovalue.example_volume("noise")
    v, t = isovalue.classic_marching_cubes(data.values, 0.1, data.spacing, data.origin)
    assert not trimesh.Trimesh(v, t, process=False).is_watertight
    assert isovalue.mesh_summary(v, t)["boundary"] > 0
    v2, t2 = scivis.marching_cubes(data.values, 0.1, data.spacing, data.origin)
    assert trimesh.Trimesh(v2, t2, process=False).is_watertight
    # a sphere has no ambiguous faces: the classic table gives the same surface as skimage
    sphere = isovalue.example_volume("sphere")
    v3, t3 = isovalue.classic_marching_cubes(sphere.values, sphere.level, sphere.spacing,
                                             sphere.origin)
    sv, sf, _, _ = measure.marching_cubes(sphere.values, sphere.level,
                                          spacing=sphere.spacing[::-1])
    assert measure.mesh_surface_area(v3, t3) == pytest.approx(measure.mesh_surface_area(sv, sf),
                                                              rel=1e-3)


def test_isosurface_normals_point_to_lower_values():
    s = isovalue.scene_3d(isovalue.State3D(volume="sphere", level=0.0))
    data = s["field"]
    # the sphere field grows inwards: the outward normal is along the position from its centre
    centre = np.asarray(data.origin) + (np.array(data.values.shape[::-1]) - 1) / 2 * np.asarray(
        data.spacing)
    radial = s["vertices"] - centre
    radial /= np.linalg.norm(radial, axis=1, keepdims=True)
    assert np.einsum("ij,ij->i", s["normals"], radial).min() > 0.95
    assert s["summary"]["euler"] == 2


def test_isosurface_explorer_wiring():
    ex = isovalue.IsosurfaceExplorer()
    ex.level.value = 0.3
    s = isovalue.scene_3d(ex.state)
    assert ex.mesh.n_cells == s["summary"]["F"]
    assert "1 connected piece" in ex.info.value
    ex.level.value = ex.level.max + 1.0                # clamped by the slider: still valid
    ex.volume.value = "noise"
    ex.table.value = "classic"
    assert ex.holes_actor.visibility
    assert "boundary edges" in ex.info.value
    ex.table.value = "consistent"
    assert not ex.holes_actor.visibility
    assert ex.png()[:4] == b"\x89PNG"
    ex.plotter.close()


# --- streamlines ------------------------------------------------------------------------------

@pytest.mark.parametrize("kind", streamlines.FIELDS)
def test_exact_streamline_against_scipy_expm_and_solve_ivp(kind):
    a = streamlines.field_matrix(kind)
    v = scivis.example_vector_field(kind)
    pts = np.random.default_rng(1).normal(size=(5, 2))
    assert np.allclose(v(pts), pts @ a.T)                      # the field is linear, v = A x
    times = np.linspace(0, 3, 7)
    seeds = np.array([[0.7, -0.2], [0.1, 0.9]])
    ours = streamlines.exact_streamline(kind, seeds, times)
    for k, seed in enumerate(seeds):
        ref = np.array([expm(t * a) @ seed for t in times])
        assert np.allclose(ours[k], ref, atol=1e-12)
        sol = solve_ivp(lambda t, y: v(y), (0, 3), seed, t_eval=times, rtol=1e-11, atol=1e-12)
        assert np.allclose(ours[k], sol.y.T, atol=1e-8)


def test_euler_on_the_vortex_grows_by_sqrt_one_plus_h_squared():
    state = streamlines.State(method="euler", step=0.25, duration=2.0,
                              seeds=np.array([[0.5, 0.0]]))
    s = streamlines.scene(state)
    h, n = s["step"], s["n_steps"]
    radii = np.linalg.norm(s["lines"][0], axis=1)
    assert np.allclose(radii, 0.5 * (1 + h * h) ** (np.arange(n + 1) / 2))
    # the error is the distance to the exact point (cos T, sin T) / 2 after the turn
    end = 0.5 * np.array([np.cos(n * h), np.sin(n * h)])
    assert s["errors"][0] == pytest.approx(np.linalg.norm(s["lines"][0, -1] - end))


def test_rk4_scene_lines_match_scipy():
    state = streamlines.State(kind="spiral", method="rk4", step=0.05, duration=3.0)
    s = streamlines.scene(state)
    v = scivis.example_vector_field("spiral")
    times = s["step"] * np.arange(s["n_steps"] + 1)
    for k, seed in enumerate(state.seeds):
        sol = solve_ivp(lambda t, y: v(y), (0, times[-1]), seed, t_eval=times, rtol=1e-11,
                        atol=1e-12)
        assert np.allclose(s["lines"][k], sol.y.T, atol=1e-6)


def test_convergence_orders():
    c = streamlines.convergence("vortex", [1.0, 0.5], 2.0)
    for method, order in (("euler", 1), ("rk2", 2), ("rk4", 4)):
        slope = np.polyfit(np.log(c["steps"][:3]), np.log(c[method][:3]), 1)[0]
        assert slope == pytest.approx(order, abs=0.25)


def test_lines_stop_at_the_domain():
    state = streamlines.State(kind="saddle", method="rk4", step=0.1, duration=5.0,
                              seeds=np.array([[1.0, 1.0]]))
    s = streamlines.scene(state)
    line = s["lines"][0]
    valid = line[np.isfinite(line[:, 0])]
    assert np.abs(valid).max() <= streamlines.LIMIT
    assert s["last"][0] < s["n_steps"] and "left the domain" in s["text"]


def test_a_seed_at_a_critical_point_is_reported_as_such():
    s = streamlines.scene(streamlines.State(seeds=np.array([[0.0, 0.0], [1.9, 0.0]]),
                                            method="euler", step=0.2))
    assert np.isnan(s["lines"][0, 1:]).all() and s["errors"][0] == 0
    assert "Line(s) 1 start(s) at a critical point" in s["text"]
    assert "Line(s) 2 left the domain" in s["text"]     # Euler spirals out of [-2, 2]^2


def test_streamline_explorer_wiring():
    ex = streamlines.StreamlineExplorer()
    ex.method.value = "rk2"
    ex.step.value = 0.1
    s = streamlines.scene(ex.state)
    v = scivis.example_vector_field(ex.state.kind)
    ref = scivis.streamline(v, ex.state.seeds, s["step"], s["n_steps"], method="rk2",
                            bounds=streamlines.BOUNDS)
    for k, line in enumerate(ex.lines):
        drawn = np.asarray(line.get_xydata())
        assert np.allclose(drawn, ref[k], equal_nan=True)
    assert "RK2" in ex.info.value
    # drag seed 1 to (0.8, 0.3): the first line now starts there
    ex.drag.press(*ex.state.seeds[0])
    ex.drag.move(0.8, 0.3)
    ex.drag.release()
    assert np.allclose(ex.lines[0].get_xydata()[0], [0.8, 0.3])
    # the error panel's RK2 curve is for the new seed, and the ring is on the current setting
    c = streamlines.convergence(ex.state.kind, [0.8, 0.3], ex.state.duration)
    assert np.allclose(ex.curves["rk2"].get_ydata(), np.maximum(c["rk2"], 1e-16))
    ex.kind.value = "sink"
    assert len(ex.glyphs.get_paths()) == streamlines.GLYPHS ** 2
    ex.exact_box.value = False
    assert len(ex.exact[0].get_xdata()) == 0
    assert ex.png()[:4] == b"\x89PNG"


def test_streamline_explorer_rejects_bad_input():
    with pytest.raises(ValueError, match="seeds"):
        streamlines.StreamlineExplorer(streamlines.State(seeds=np.zeros((6, 2))))
    with pytest.raises(ValueError, match="method"):
        streamlines.scene(streamlines.State(method="heun"))
    with pytest.raises(ValueError, match="kind"):
        streamlines.field_matrix("tornado")
