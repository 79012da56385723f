"""Headless tests of the chapter 4 and 5 explorers: their scenes against independent references
(shapely, PyGLM, closed forms) and their wiring, including real mouse events for dragging."""
from pyglm import glm
import numpy as np
import pytest
import shapely

from course_lib.widgets import (camera, clipping3d, cohen_sutherland, liang_barsky,
                                sutherland_hodgman)
from course_lib.widgets._clip2d import BOX_MAX, BOX_MIN
from widget_harness import drag, mouse

BOX = shapely.box(*BOX_MIN, *BOX_MAX)


def shapely_segment(p0, p1):
    """The segment clipped to the window by shapely, as a sorted 2x2 array (or None)."""
    piece = shapely.LineString([p0, p1]).intersection(BOX)
    if piece.is_empty or piece.length == 0:
        return None
    return np.array(sorted(piece.coords))


def same_segment(ours, reference):
    if ours is None or reference is None:
        return ours is None and reference is None
    return np.allclose(np.array(sorted(map(tuple, np.asarray(ours)))), reference, atol=1e-9)


def closed_form_code(p):
    (x0, y0), (x1, y1) = BOX_MIN, BOX_MAX
    return (p[0] < x0) * 1 + (p[0] > x1) * 2 + (p[1] < y0) * 4 + (p[1] > y1) * 8


# --- Cohen-Sutherland ------------------------------------------------------------------------

@pytest.mark.parametrize("p0, p1", [((-2.5, -0.5), (2.2, 1.9)), ((-2, 0), (0, 0)),
                                    ((2, 2), (2.5, -2)), ((0, 0), (0.5, 0.5)),
                                    ((-2.9, 2.9), (2.9, -2.9))])
def test_cohen_sutherland_scene_against_shapely(p0, p1):
    state = cohen_sutherland.State(np.array(p0, float), np.array(p1, float), step=99)
    s = cohen_sutherland.scene(state)
    assert s["final"] and s["step"] == len(s["steps"]) - 1
    assert same_segment(s["result"], shapely_segment(p0, p1))
    first = cohen_sutherland.scene(cohen_sutherland.State(state.p0, state.p1, step=0))
    assert first["codes"] == [format(closed_form_code(p0), "04b"),
                              format(closed_form_code(p1), "04b")]


def test_cohen_sutherland_drag_and_step():
    ex = cohen_sutherland.CohenSutherlandExplorer()
    ex.fig.canvas.draw()
    ax = ex.drag.ax
    drag(ax, ex.state.p1, (0.5, 2.0))                     # move p1 above the window
    assert np.allclose(ex.state.p1, (0.5, 2.0))
    assert np.allclose(np.array(ex.ends.get_xydata())[1], (0.5, 2.0))
    expected = shapely_segment(ex.state.p0, ex.state.p1)
    assert expected is not None
    ex.step.value = ex.step.max
    assert same_segment(np.array(ex.result.get_xydata()), expected)
    ex.step.value = 0                                      # back to the first iteration
    assert ex.result.get_xydata().size == 0               # the result shows at the end only
    assert "Iteration 1" in ex.info.value
    mouse(ax, "button_press_event", (-2.9, -2.9))         # far from both points: no pick
    mouse(ax, "motion_notify_event", (0, 0))
    assert np.allclose(ex.state.p1, (0.5, 2.0)) and ex.drag.active is None


# --- Liang-Barsky ----------------------------------------------------------------------------

@pytest.mark.parametrize("p0, p1", [((-2.4, -1.6), (2.5, 1.6)), ((-2, 0.5), (2, 0.5)),
                                    ((0.2, -2), (0.2, 2)), ((2, 2), (2.9, 0)),
                                    ((-0.5, -0.5), (0.5, 0.2))])
def test_liang_barsky_scene_t_values_and_result(p0, p1):
    p0, p1 = np.array(p0, float), np.array(p1, float)
    s = liang_barsky.scene(liang_barsky.State(p0, p1, step=99))
    d = p1 - p0
    pq = {"left": (-d[0], p0[0] - BOX_MIN[0]), "right": (d[0], BOX_MAX[0] - p0[0]),
          "bottom": (-d[1], p0[1] - BOX_MIN[1]), "top": (d[1], BOX_MAX[1] - p0[1])}
    for marker in s["markers"]:
        p, q = pq[marker["side"]]
        if p == 0:
            assert marker["t"] is None
        else:
            assert marker["t"] == pytest.approx(q / p)
            assert marker["kind"] == ("entering" if p < 0 else "leaving")
            assert np.allclose(marker["point"], p0 + q / p * d)
    assert same_segment(s["result"], shapely_segment(p0, p1))


def test_liang_barsky_widget_number_line():
    ex = liang_barsky.LiangBarskyExplorer()
    ex.fig.canvas.draw()
    ex.step.value = 1                                      # left and right processed
    s = liang_barsky.scene(ex.state)
    x, _ = ex.interval.get_data()
    assert np.allclose(x, [s["t_in"], s["t_out"]])
    drag(ex.drag.ax, ex.state.p0, (-2.0, 0.0))
    assert np.allclose(ex.state.p0, (-2.0, 0.0))
    ex.step.value = ex.step.max
    assert same_segment(np.array(ex.result.get_xydata()), shapely_segment(ex.state.p0, ex.state.p1))


# --- Sutherland-Hodgman ----------------------------------------------------------------------

def shoelace(poly):
    x, y = np.asarray(poly).T
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def test_sutherland_hodgman_scene_against_shapely():
    state = sutherland_hodgman.State()
    s = sutherland_hodgman.scene(state)
    expected = shapely.Polygon(state.polygon).intersection(BOX).area
    assert shoelace(s["after"]) == pytest.approx(expected, rel=1e-12)
    assert s["counts"][0] == len(state.polygon) and len(s["counts"]) == 5
    start = sutherland_hodgman.scene(sutherland_hodgman.State(step=0))
    assert start["side"] is None and np.array_equal(start["after"], state.polygon)


def test_sutherland_hodgman_widget_drag_vertex():
    ex = sutherland_hodgman.SutherlandHodgmanExplorer()
    ex.fig.canvas.draw()
    vertex = ex.state.polygon[4].copy()
    drag(ex.drag.ax, vertex, (0.2, 0.4))
    assert np.allclose(ex.state.polygon[4], (0.2, 0.4))
    drawn = ex.after.get_xy()
    expected = shapely.Polygon(ex.state.polygon).intersection(BOX).area
    assert shoelace(drawn[:-1] if np.allclose(drawn[0], drawn[-1]) else drawn) == \
        pytest.approx(expected, rel=1e-9)
    ex.step.value = 1
    assert "left" in ex.info.value


# --- camera explorer -------------------------------------------------------------------------

def glm_matrices(state):
    """View and projection matrices from PyGLM (column-major, hence the transposes)."""
    eye = np.array([state.eye_x, state.eye_y, state.eye_z])
    gaze = camera.gaze_direction(state.azimuth_deg, state.elevation_deg)
    view = np.array(glm.lookAt(glm.dvec3(*eye), glm.dvec3(*(eye + gaze)),
                               glm.dvec3(state.up_x, state.up_y, state.up_z)).to_list()).T
    if state.projection == "perspective":
        proj = np.array(glm.perspective(np.radians(state.fov_deg), 1.0, state.near,
                                        state.far).to_list()).T
    else:
        h = state.half_size
        proj = np.array(glm.ortho(-h, h, -h, h, state.near, state.far).to_list()).T
    return view, proj


@pytest.mark.parametrize("projection", ["perspective", "orthographic"])
def test_camera_matrices_match_pyglm(projection):
    state = camera.State(projection=projection, up_x=0.3, eye_z=2.0)
    view, proj = camera.camera_matrices(state)
    ref_view, ref_proj = glm_matrices(state)
    assert np.allclose(view, ref_view, atol=1e-12)
    assert np.allclose(proj, ref_proj, rtol=1e-6, atol=1e-6)      # glm.perspective: float32


def test_camera_picture_is_the_projection_of_the_world():
    state = camera.State()
    s = camera.scene(state)
    view, proj = glm_matrices(state)
    m = proj @ view
    # every vertex of the picture is the image of a point of some face (or of its clipping)
    for polygon in s["polygons"]:
        assert np.all(np.abs(polygon) <= 1 + 1e-9)
    # faces entirely inside the view volume appear unclipped, at their projected positions
    inside = []
    for face in camera._FACES:
        h = np.column_stack([face, np.ones(len(face))]) @ m.T
        css = h[:, :3] / h[:, 3:]
        if np.all(np.abs(css) < 1 - 1e-6) and np.all(h[:, 3] > 0):
            inside.append(css[:, :2])
    assert inside
    for expected in inside:       # Sutherland-Hodgman may start the polygon at another vertex
        assert any(p.shape == expected.shape
                   and any(np.allclose(np.roll(p, k, axis=0), expected, atol=1e-5)
                           for k in range(len(p)))
                   for p in s["polygons"])
    # the view volume's corners are the preimages of the cube's corners
    corners = s["volume"].reshape(-1, 3)
    corners = corners[~np.isnan(corners).any(axis=1)]
    h = np.column_stack([corners, np.ones(len(corners))]) @ m.T
    assert np.all(np.abs(h[:, :3] / h[:, 3:]) <= 1 + 1e-5)


def test_camera_reports_impossible_cameras_without_raising():
    ex = camera.CameraExplorer()
    for name, value in (("up_x", 0.0), ("up_y", 0.0), ("up_z", 0.0)):
        ex.controls[name].value = value
    assert "up must not be the zero vector" in ex.info.value
    ex.controls["up_z"].value = 1.0
    ex.controls["elevation_deg"].value = 89.0
    assert "WCS→ECS" in ex.info.value                      # nearly vertical still works
    ex.controls["near"].value = 6.0
    ex.controls["far"].value = 5.0
    assert "far must be greater than near" in ex.info.value
    ex.controls["far"].value = 12.0
    for projection in camera.PROJECTIONS:
        ex.controls["projection"].value = projection
        assert camera.scene(ex.state)["error"] is None


def test_oblique_camera_shears_along_the_direction_of_projection():
    state = camera.State(projection="oblique", oblique_deg=30, oblique_scale=0.5)
    view, proj = camera.camera_matrices(state)
    # two eye-space points one unit apart along the direction of projection: same picture
    dop = np.array([0.5 * np.cos(np.radians(30)), 0.5 * np.sin(np.radians(30)), -1.0])
    a = np.array([0.3, -0.2, -5.0, 1.0])
    b = a + np.append(dop, 0.0)
    pa, pb = proj @ a, proj @ b
    assert np.allclose(pa[:2] / pa[3], pb[:2] / pb[3])


# --- 3D clipping -----------------------------------------------------------------------------

@pytest.mark.parametrize("region", clipping3d.REGIONS)
@pytest.mark.parametrize("turn, lift", [(20, 0.0), (-70, 0.6), (140, -0.9), (0, 5.0)])
def test_clipping3d_results_lie_inside_and_on_the_input(region, turn, lift):
    s = clipping3d.scene(clipping3d.State(region=region, turn_deg=turn, lift=lift))
    planes, _ = clipping3d.region_planes(region)
    seg = s["clipped_segment"]
    if seg is not None:
        for point in seg:
            assert all(np.dot(n, point) <= c + 1e-9 for _, n, c in planes)
            a, b = s["segment"]
            assert np.linalg.norm(np.cross(point - a, b - a)) < 1e-9 * np.linalg.norm(b - a) + 1e-12
    tri = s["triangle"]
    normal = np.cross(tri[1] - tri[0], tri[2] - tri[0])
    for point in s["polygon"]:
        assert all(np.dot(n, point) <= c + 1e-9 for _, n, c in planes)
        assert abs(np.dot(point - tri[0], normal)) < 1e-9 * np.linalg.norm(normal)
    if lift == 5.0 and region == "box":
        assert seg is None and len(s["polygon"]) == 0


def test_clipping3d_box_segment_matches_sampling():
    """The kept part of the segment is exactly the part whose sample points are in the box."""
    s = clipping3d.scene(clipping3d.State(region="box", turn_deg=35, tilt_deg=20, lift=0.3))
    a, b = s["segment"]
    t = np.linspace(0, 1, 20001)
    points = a + t[:, None] * (b - a)
    inside = np.all(np.abs(points) <= 1, axis=1)
    kept = s["clipped_segment"]
    t_kept = sorted(np.dot(kept - a, b - a) / np.dot(b - a, b - a))
    assert t_kept[0] == pytest.approx(t[inside][0], abs=1e-4)
    assert t_kept[1] == pytest.approx(t[inside][-1], abs=1e-4)


def test_clipping3d_widget_controls():
    ex = clipping3d.ClippingExplorer3D()
    ex.lift.value = 2.4
    assert "nothing is left" in ex.info.value
    ex.region.value = "frustum"
    assert ex.state.region == "frustum" and "frustum" in ex.info.value


def sampled_interval(a, b, inside):
    """[t_in, t_out] of the sampled world segment's points that pass `inside` (or None)."""
    t = np.linspace(0, 1, 20001)
    ok = inside(a + t[:, None] * (b - a))
    return (t[ok][0], t[ok][-1]) if ok.any() else None


@pytest.mark.parametrize("region", clipping3d.REGIONS)
@pytest.mark.parametrize("step", range(7))
def test_clipping3d_steps_keep_the_part_inside_the_planes_so_far(region, step):
    """After k planes the kept part is the part of the segment that satisfies the first k of the
    typed inequalities -w <= x, y, z <= w (w = 1 for the box), sampled."""
    state = clipping3d.State(region=region, turn_deg=35, tilt_deg=20, lift=0.3, step=step)
    s = clipping3d.scene(state)
    m = np.eye(4) if region == "box" else clipping3d._CAMERA
    signs = [(0, 1), (0, -1), (1, 1), (1, -1), (2, 1), (2, -1)]   # w + x >= 0, w - x >= 0, ...

    def inside(points):
        h = np.column_stack([points, np.ones(len(points))]) @ m.T
        ok = np.ones(len(points), bool)
        for axis, sign in signs[:step]:
            ok &= h[:, 3] + sign * h[:, axis] >= 0
        return ok

    a, b = s["segment"]
    expected = sampled_interval(a, b, inside)
    if expected is None:
        assert s["clipped_segment"] is None
    else:
        assert s["t_in"] == pytest.approx(expected[0], abs=1e-4)
        assert s["t_out"] == pytest.approx(expected[1], abs=1e-4)
    for point in s["polygon"]:                # the triangle clipped by the same planes
        h = m @ [*point, 1]
        assert all(h[3] + sign * h[axis] >= -1e-9 for axis, sign in signs[:step])
    assert (s["face"] is None) == (step == 0)


def test_clipping3d_box_rows_are_the_typed_pairs():
    s = clipping3d.scene(clipping3d.State(region="box", turn_deg=-50, lift=0.4))
    (x0, y0, z0), (x1, y1, z1) = s["segment"]
    typed = [(x0 - x1, 1 + x0), (x1 - x0, 1 - x0), (y0 - y1, 1 + y0), (y1 - y0, 1 - y0),
             (z0 - z1, 1 + z0), (z1 - z0, 1 - z0)]
    assert np.allclose([(r["p"], r["q"]) for r in s["rows"]], typed)


def test_clipping3d_every_control_changes_the_picture():
    ex = clipping3d.ClippingExplorer3D()
    assert ex.step.value == 6 and ex.step.max == 6

    def picture():
        return (np.concatenate([np.ravel(np.asarray(line.get_data_3d(), float))
                                for line in (ex.kept, ex.face, ex.enter_pts, ex.leave_pts)]),
                ex.info.value)

    for control, value in ((ex.step, 2), (ex.step, 0), (ex.step, 4), (ex.turn, -60.0),
                           (ex.tilt, 25.0), (ex.lift, 0.5), (ex.region, "frustum")):
        before = picture()
        control.value = value
        after = picture()
        assert after[1] != before[1]
        assert before[0].shape != after[0].shape or not np.allclose(before[0], after[0],
                                                                   equal_nan=True)
    ex.step.value = 0
    assert "no plane yet" in ex.info.value and len(ex.face.get_data_3d()[0]) == 0
    ex.step.value = 5
    assert "Plane 5 (near)" in ex.info.value
    started = clipping3d.ClippingExplorer3D(clipping3d.State(region="frustum", step=3))
    assert started.step.value == 3 and "Plane 3 (bottom)" in started.info.value


# --- z-buffer trace and hidden-surface explorer ---------------------------------------------

from course_lib.widgets import hidden_surface, zbuffer  # noqa: E402


def brute_force_zbuffer(triangles, width, height):
    """An independent z-buffer: every pixel centre against every triangle, nearest wins
    (inside test and depth by barycentric coordinates, computed here from scratch)."""
    ids = np.full((height, width), -1)
    depth = np.full((height, width), np.inf)
    for j in range(height):
        for i in range(width):
            x, y = i + 0.5, j + 0.5
            for k, tri in enumerate(triangles):
                (x0, y0, z0), (x1, y1, z1), (x2, y2, z2) = tri
                det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)
                l1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det
                l2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det
                l0 = 1 - l1 - l2
                if min(l0, l1, l2) > 1e-9:                     # strictly inside
                    z = l0 * z0 + l1 * z1 + l2 * z2
                    if z < depth[j, i]:
                        depth[j, i], ids[j, i] = z, k
    return ids, depth


@pytest.mark.parametrize("order", list(zbuffer.ORDERS))
def test_zbuffer_trace_final_buffers_match_brute_force(order):
    ids, depth = brute_force_zbuffer(zbuffer.TRIANGLES, zbuffer.WIDTH, zbuffer.HEIGHT)
    s = zbuffer.scene(zbuffer.State(order, step=len(zbuffer.TRIANGLES)))
    assert np.array_equal(s["ids"], ids)
    assert np.allclose(s["depth"], depth)
    visible = int((ids >= 0).sum())
    assert sum(s["writes"]) >= visible and f"At least {visible} writes" in s["text"]


def test_zbuffer_trace_steps():
    s0 = zbuffer.scene(zbuffer.State(step=0))
    assert (s0["ids"] == -1).all() and np.isinf(s0["depth"]).all() and s0["covered"] is None
    first = zbuffer.scene(zbuffer.State(step=1))                # triangle 0 into empty buffers
    assert np.array_equal(first["covered"], first["written"])
    assert np.array_equal(first["ids"] == 0, first["covered"])
    ex = zbuffer.ZBufferExplorer()
    ex.step.value = 3
    assert "triangle 2" in ex.info.value
    marked = np.array(ex.marks[0][1].get_xydata())             # the × of the written pixels
    written = zbuffer.scene(ex.state)["written"]
    assert len(marked) == written.sum()
    ex.order.value = "reversed (3, 2, 1, 0)"
    assert zbuffer.scene(ex.state)["current"] == 1


def test_hidden_surface_culling_changes_work_not_the_picture():
    for azimuth in (-75, 10, 140):
        culled = hidden_surface.scene(hidden_surface.State(azimuth, 30, cull=True))
        full = hidden_surface.scene(hidden_surface.State(azimuth, 30, cull=False))
        assert np.array_equal(culled["depth"], full["depth"])
        assert culled["drawn"] < full["drawn"] and culled["fragments"] < full["fragments"]
        # the back faces, from the eye: n . (face - eye) >= 0, recomputed here
        v, f = hidden_surface.VERTICES, hidden_surface.FACES
        n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
        expected = np.einsum("ij,ij->i", n, v[f[:, 0]] - culled["eye"]) >= 0
        assert np.array_equal(culled["back"], expected)


def test_hidden_surface_widget():
    ex = hidden_surface.HiddenSurfaceExplorer()
    ex.azimuth.value = 30
    s = hidden_surface.scene(ex.state)
    assert np.array_equal(np.ma.filled(ex.depth.get_array(), np.inf), s["depth"])
    ex.cull.value = False
    assert "Without culling" in ex.info.value


def test_camera_greys_out_the_sliders_its_projection_does_not_read():
    ex = camera.CameraExplorer()
    c = ex.controls
    projection_sliders = ("fov_deg", "half_size", "oblique_deg", "oblique_scale")
    for name, used in (("perspective", {"fov_deg"}), ("orthographic", {"half_size"}),
                       ("oblique", {"half_size", "oblique_deg", "oblique_scale"})):
        c["projection"].value = name
        assert {s for s in projection_sliders if not c[s].disabled} == used
        # an enabled slider changes the camera; a greyed-out one would not have
        for s in projection_sliders:
            before = camera.camera_matrices(ex.state)[1]
            changed = camera.State(**{**vars(ex.state), s: getattr(ex.state, s) * 1.2})
            moves = not np.allclose(camera.camera_matrices(changed)[1], before)
            assert moves == (s in used), (name, s)


@pytest.mark.parametrize("explorer", [cohen_sutherland.CohenSutherlandExplorer,
                                      liang_barsky.LiangBarskyExplorer,
                                      sutherland_hodgman.SutherlandHodgmanExplorer])
def test_step_buttons_are_greyed_out_at_the_ends(explorer):
    ex = explorer()
    back, forward = _step_buttons(ex)
    ex.step.value = ex.step.max
    assert forward.disabled and not back.disabled
    back.click()
    assert ex.step.value == ex.step.max - 1 and not forward.disabled
    ex.step.value = 0
    assert back.disabled and not forward.disabled


def _step_buttons(ex):
    """The back and forward buttons beside the explorer's step slider."""
    import ipywidgets as w

    def walk(widget):
        if isinstance(widget, w.Box):
            if ex.step in widget.children:
                return [c for c in widget.children if isinstance(c, w.Button)]
            for child in widget.children:
                found = walk(child)
                if found:
                    return found
        return None
    return walk(ex.widget)
