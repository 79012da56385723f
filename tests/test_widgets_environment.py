"""Headless tests of the environment-mapping explorer: its scene against computations typed here
(the camera's rays, the ray-sphere quadratic, R = I - 2(N.I)N, the OpenGL cube-face table, the
sphere-map and lat-long formulas, the exit point from the room's box, a torus's quartic solved
by numpy.roots) and the wiring (every control and a click change the picture, a slider moved
and moved back gives the first picture back, bad states are named)."""
import matplotlib
matplotlib.use("module://ipympl.backend_nbagg")

import numpy as np
import pytest

from course_lib.texturing import environment as env
from course_lib.widgets import environment as W
from widget_harness import click

CROSS_CELL = {"-X": (0, 1), "-Z": (1, 1), "+X": (2, 1), "+Z": (3, 1), "+Y": (1, 2), "-Y": (1, 0)}


def _opengl_face(r):
    """The OpenGL specification's table, typed here: (face name, s, t)."""
    rx, ry, rz = r
    ax, ay, az = abs(rx), abs(ry), abs(rz)
    if ax >= ay and ax >= az:
        name, sc, tc, ma = ("+X", -rz, -ry, rx) if rx > 0 else ("-X", rz, -ry, rx)
    elif ay >= az:
        name, sc, tc, ma = ("+Y", rx, rz, ry) if ry > 0 else ("-Y", rx, -rz, ry)
    else:
        name, sc, tc, ma = ("+Z", rx, -ry, rz) if rz > 0 else ("-Z", -rx, -ry, rz)
    return name, (sc / abs(ma) + 1) / 2, (tc / abs(ma) + 1) / 2


def _camera_rays(az_deg, el_deg):
    """The pinhole camera typed here: the eye on the orbit, rays through the pixel centres."""
    az, el = np.radians(az_deg), np.radians(el_deg)
    back = np.array([np.cos(el) * np.sin(az), np.sin(el), np.cos(el) * np.cos(az)])
    right = np.array([np.cos(az), 0, -np.sin(az)])
    up = np.cross(back, right)
    c = (np.arange(W.SIZE) + 0.5) / W.SIZE * 2 - 1
    y, x = np.meshgrid(c, c, indexing="ij")
    d = W.HALF_FOV * (x[..., None] * right + y[..., None] * up) - back
    return W.EYE * back, d / np.linalg.norm(d, axis=-1, keepdims=True)


def _mirror_sphere(az_deg, el_deg):
    """Hits on the unit sphere by the quadratic t^2 + 2 (E.d) t + |E|^2 - 1 = 0, normals and
    R = I - 2 (N.I) N; R = I off the sphere."""
    eye, d = _camera_rays(az_deg, el_deg)
    b = d @ eye
    disc = b * b - (eye @ eye - 1)
    mask = disc >= 0
    t = -b - np.sqrt(np.where(mask, disc, 0))
    n = eye + t[..., None] * d
    r = np.where(mask[..., None], d - 2 * np.sum(n * d, -1, keepdims=True) * n, d)
    return mask, n, r


def test_sphere_geometry_against_the_quadratic_typed_here():
    g = W.geometry("sphere", 35.0, -20.0)
    mask, n, r = _mirror_sphere(35.0, -20.0)
    assert np.array_equal(g["mask"], mask)
    assert np.allclose(g["normals"][mask], n[mask]) and np.allclose(g["points"][mask], n[mask])
    assert np.allclose(g["reflections"], r)
    assert 0.2 < mask.mean() < 0.6                       # the sphere fills part of the view
    with pytest.raises(ValueError):                      # cached arrays are read-only
        g["reflections"][0, 0, 0] = 1.0


def test_map_picture_is_the_environment_in_the_reflected_directions():
    # the axes environment is smooth: the map's look-ups stay within filtering error of it
    for kind in ("cube", "latlong"):
        s = W.scene(W.State(environment="axes", kind=kind, azimuth_deg=-60, elevation_deg=30))
        _, _, r = _mirror_sphere(-60, 30)
        expected = 0.5 + 0.45 * r / np.linalg.norm(r, axis=-1, keepdims=True)
        assert np.abs(s["image"] - expected).max() < 0.01, kind
    # the sphere map, made for this view (azimuth 0, elevation 0), away from its rim
    s = W.scene(W.State(environment="axes", kind="sphere", azimuth_deg=0, elevation_deg=0))
    mask, _, r = _mirror_sphere(0, 0)
    good = mask & (r[..., 2] > -0.5)
    expected = 0.5 + 0.45 * r
    assert np.abs(s["image"][good] - expected[good]).max() < 0.03


def test_picked_pixel_cube_face_and_texel_marker():
    for pick in [(0.62, 0.64), (0.3, 0.45), (0.5, 0.2), (0.71, 0.5), (0.05, 0.95)]:
        state = W.State(pick_x=pick[0], pick_y=pick[1], azimuth_deg=40, elevation_deg=25)
        s = W.scene(state)
        mask, _, r = _mirror_sphere(40, 25)
        col, row = int(pick[0] * W.SIZE), int(pick[1] * W.SIZE)
        assert s["pixel"] == (col + 0.5, row + 0.5)
        assert s["on_object"] == bool(mask[row, col])
        rr = r[row, col]
        assert np.allclose(s["reflection"], rr)
        name, s_, t_ = _opengl_face(rr)
        assert env.CUBE_FACES[s["face"]] == name
        assert (s["s"], s["t"]) == pytest.approx((s_, t_))
        assert name in s["text"] and f"s = {s_:.3f}" in s["text"]
        # the marker lies in the cell of that face, on a texel showing the room's colour there
        x, y = s["texel"] / W.CUBE_N
        assert (int(x), int(y)) == CROSS_CELL[name]
        texel = s["map"][int(s["texel"][1]), int(s["texel"][0])]
        assert np.abs(texel - env.room_environment(rr[None])[0]).max() < 0.35


def test_sphere_and_latlong_texel_markers_by_their_formulas():
    _, _, r = _mirror_sphere(0, 15)
    rr = r[int(0.64 * W.SIZE), int(0.62 * W.SIZE)]
    s = W.scene(W.State(kind="sphere"))
    m = 2 * np.sqrt(rr[0] ** 2 + rr[1] ** 2 + (rr[2] + 1) ** 2)
    assert np.allclose(s["texel"], W.SPHERE_N * np.array([rr[0] / m + 0.5, rr[1] / m + 0.5]))
    s = W.scene(W.State(kind="latlong"))
    u = 0.5 + np.arctan2(rr[0], rr[2]) / (2 * np.pi)
    v = 0.5 + np.arcsin(rr[1] / np.linalg.norm(rr)) / np.pi
    assert np.allclose(s["texel"], [2 * W.LATLONG_H * u, W.LATLONG_H * v])


def _room_exit(o, d, half):
    """Where a ray from inside the box |x|, |y|, |z| <= half leaves it (typed here)."""
    with np.errstate(divide="ignore"):
        t = np.where(d != 0, (np.sign(d) * half - o) / d, np.inf).min(-1)
    return o + t[..., None] * d


def test_traced_picture_against_the_wall_hits_typed_here():
    state = W.State(reflection="traced", offset=1.5, azimuth_deg=-30, elevation_deg=10,
                    pick_x=0.3, pick_y=0.55)
    s = W.scene(state)
    mask, n, r = _mirror_sphere(-30, 10)
    eye, _ = _camera_rays(-30, 10)
    origins = np.where(mask[..., None], n, eye) + [1.5, 0, 0]
    q = _room_exit(origins, r, W.ROOM)
    assert np.allclose(np.abs(q).max(-1), W.ROOM)
    assert np.allclose(s["image"], env.room_environment(q.reshape(-1, 3)).reshape(s["image"].shape))
    row, col = int(0.55 * W.SIZE), int(0.3 * W.SIZE)
    qq, rr = q[row, col], r[row, col]
    angle = np.degrees(np.arccos(qq @ rr / np.linalg.norm(qq) / np.linalg.norm(rr)))
    assert s["error_deg"] == pytest.approx(angle)
    assert f"{angle:.1f}°" in s["text"]
    # the sine rule: the wall point seen from the centre is at most arcsin(|P| / ROOM) away
    assert angle <= np.degrees(np.arcsin(np.linalg.norm(origins[row, col]) / W.ROOM)) + 1e-9
    assert angle > 1.0
    x, y = s["true_texel"] / W.CUBE_N
    assert (int(x), int(y)) == CROSS_CELL[_opengl_face(qq)[0]]


def test_the_map_is_right_for_a_point_at_the_centre_only():
    errors = []
    for offset in (0.0, 1.0, 2.0):
        base = W.scene(W.State(reflection="map"))["image"]
        traced = W.scene(W.State(reflection="traced", offset=offset))
        errors.append(np.abs(traced["image"] - base).max(-1).mean())
    assert errors[0] < errors[1] < errors[2]
    # the map's own picture does not depend on the offset (it cannot)
    a = W.scene(W.State(offset=0.0))["image"]
    b = W.scene(W.State(offset=2.0))["image"]
    assert np.array_equal(a, b)


def _torus_first_hit(o, d, t_min):
    """The smallest root t > t_min of the torus's quartic (|p|^2 + a^2 - b^2)^2 = 4 a^2 (x^2 +
    z^2), p = o + t d in the torus's own axes (d unit), by numpy.roots; inf if none."""
    a, b = W.TORUS
    k = o @ o + a * a - b * b
    od = o @ d
    coeff = [1.0, 4 * od, 2 * k + 4 * od ** 2 - 4 * a * a * (d[0] ** 2 + d[2] ** 2),
             4 * k * od - 8 * a * a * (o[0] * d[0] + o[2] * d[2]),
             k * k - 4 * a * a * (o[0] ** 2 + o[2] ** 2)]
    roots = np.roots(coeff)
    real = roots[(np.abs(roots.imag) < 1e-7) & (roots.real > t_min)].real
    return real.min() if len(real) else np.inf


def test_torus_hits_and_second_bounces_against_the_quartic():
    g = W.geometry("torus", 20.0, 30.0)
    b = W.bounces("torus", 20.0, 30.0)
    c, s = np.cos(W.TILT), np.sin(W.TILT)
    rot = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])          # local -> world
    rng = np.random.default_rng(5)
    rows, cols = rng.integers(0, W.SIZE, (2, 400))
    agree = 0
    for i, j in zip(rows, cols):
        t = _torus_first_hit(g["eye"] @ rot, g["rays"][i, j] @ rot, 0.0)
        if np.isfinite(t) == bool(g["mask"][i, j]):
            agree += 1
        if np.isfinite(t) and g["mask"][i, j]:
            assert np.allclose(g["points"][i, j], g["eye"] + t * g["rays"][i, j], atol=1e-3)
    assert agree >= 396                                   # grazing rays may differ
    hit = np.argwhere(b["self_hit"])
    assert 100 < len(hit) < g["mask"].sum()
    assert not W.bounces("sphere", 20.0, 30.0)["self_hit"].any()
    for i, j in hit[rng.choice(len(hit), 40, replace=False)]:
        p, r = g["points"][i, j], g["reflections"][i, j]
        t = _torus_first_hit(p @ rot, r @ rot, 2e-3)
        q = p + t * r
        assert np.allclose(b["origins"][i, j], q, atol=2e-3)
        # the second reflection, typed here with the torus's normal at q
        ql = q @ rot
        ring = np.array([ql[0], 0, ql[2]]) * W.TORUS[0] / np.hypot(ql[0], ql[2])
        nn = (ql - ring) / np.linalg.norm(ql - ring) @ rot.T
        assert np.allclose(b["directions"][i, j], r - 2 * (nn @ r) * nn, atol=2e-2)


@pytest.mark.parametrize("change, match", [
    ({"environment": "desert"}, "environment must be one of"),
    ({"kind": "dual paraboloid"}, "kind must be one of"),
    ({"shape": "teapot"}, "shape must be one of"),
    ({"reflection": "raster"}, "reflection must be one of"),
    ({"elevation_deg": 90.0}, "elevation_deg must be in"),
    ({"azimuth_deg": float("nan")}, "azimuth_deg must be finite"),
    ({"offset": 3.0}, "offset must be in"),
    ({"pick_x": 1.5}, "pick_x must be a fraction"),
    ({"pick_y": "middle"}, "pick_y must be a number"),
])
def test_bad_states_are_named(change, match):
    with pytest.raises((ValueError, TypeError), match=match):
        W.scene(W.State(**change))


def _picture(ex):
    return np.array(ex.picture.get_array())


def test_every_control_changes_the_picture_and_comes_back():
    ex = W.EnvironmentMapExplorer()
    assert ex.offset.disabled                           # the map cannot know the offset
    for control, value in [(ex.azimuth, 25.0), (ex.elevation, -10.0)]:
        first, text = _picture(ex), ex.info.value
        old = control.value
        control.value = value
        assert not np.array_equal(first, _picture(ex)), control.description
        assert ex.info.value != text
        control.value = old
        assert np.array_equal(first, _picture(ex)), control.description
    for control, value in [(ex.environment, "sky"), (ex.kind, "sphere"), (ex.shape, "torus"),
                           (ex.environment, "axes"), (ex.kind, "latlong")]:
        before, text = _picture(ex), ex.info.value
        shown = np.array(ex.map_image.get_array())
        control.value = value
        assert not np.array_equal(before, _picture(ex)), (control.description, value)
        if control is ex.environment or control is ex.kind:
            assert not np.array_equal(shown, np.array(ex.map_image.get_array()))
        expected = W.scene(ex.state)
        assert np.array_equal(_picture(ex), expected["image"])
    ex.reflection.value = "traced"
    assert not ex.offset.disabled
    assert "Ray traced" in ex.info.value and len(ex.true_marker.get_xdata()) == 1
    first, text = _picture(ex), ex.info.value
    ex.offset.value = 1.25
    assert not np.array_equal(first, _picture(ex)) and ex.info.value != text
    ex.offset.value = 0.0
    assert np.array_equal(first, _picture(ex))
    ex.reflection.value = "map"
    assert ex.offset.disabled and len(ex.true_marker.get_xdata()) == 0


def test_a_click_moves_the_pick_and_its_texel():
    ex = W.EnvironmentMapExplorer()
    ex.fig.canvas.draw()
    pixel = np.array(ex.pixel_marker.get_xydata())
    texel = np.array(ex.texel_marker.get_xydata())
    click(ex.ax_image, (40.2, 50.7))                    # a real matplotlib button_press_event
    assert np.allclose(ex.pixel_marker.get_xydata(), [[40.5, 50.5]])
    assert not np.allclose(texel, ex.texel_marker.get_xydata())
    assert (ex.state.pick_x, ex.state.pick_y) == pytest.approx((40.2 / W.SIZE, 50.7 / W.SIZE))
    assert "row 50, column 40" in ex.info.value
    click(ex.ax_map, (10.0, 10.0))                      # a click on the map picks nothing
    assert np.allclose(ex.pixel_marker.get_xydata(), [[40.5, 50.5]])
    assert not np.allclose(pixel, ex.pixel_marker.get_xydata())
    assert [g["kind"] for g in ex.mouse_gestures()] == ["click"]


def test_the_live_frame_matches_the_stored_picture_after_a_new_map():
    # a new map redraws the whole figure (face names removed or added); the blitted frames
    # after it must still show what a full draw shows
    import io

    from PIL import Image

    ex = W.EnvironmentMapExplorer()
    canvas = ex.fig.canvas
    canvas.draw_idle = canvas.draw
    canvas.draw()
    for control, value in [(ex.kind, "sphere"), (ex.azimuth, 40.0), (ex.kind, "cube"),
                           (ex.reflection, "traced"), (ex.offset, 1.0)]:
        control.value = value
        live = np.asarray(canvas.get_renderer().buffer_rgba())[..., :3].astype(int)
        buffer = io.BytesIO()
        ex.blitter.savefig(buffer, format="png", dpi=ex.fig.dpi)
        stored = np.asarray(Image.open(buffer).convert("RGB")).astype(int)
        assert (np.abs(live - stored).max(axis=-1) > 24).mean() <= 0.015, (control, value)
    assert len(ex.face_labels) == 6
