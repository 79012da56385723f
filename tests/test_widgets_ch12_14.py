"""Headless tests of the chapter 12 and 14 explorers: their scenes against closed forms computed
here (the Phong terms on a sphere, barycentric weights from a 2x2 solve, the spherical and
cylindrical angles, the exact ambient occlusion of a floor by a wall) and their wiring (sliders,
toggles, real mouse events for dragging)."""
import numpy as np
import pytest

from course_lib import shading, texturing, viewing
from course_lib.widgets import barycentric, occlusion, phong, texture
from widget_harness import drag


def hex_rgb(text):
    return np.array([int(text[k:k + 2], 16) / 255 for k in (1, 3, 5)])


# --- Phong explorer --------------------------------------------------------------------------

def analytic_sphere(state, size=phong.SIZE):
    """The Phong / Blinn-Phong sphere computed from the formulas, pixel by pixel."""
    s = ((np.arange(size) + 0.5) / size * 2 - 1) * phong.EXTENT
    x, y = np.meshgrid(s, s)
    inside = x**2 + y**2 < 1
    n = np.stack([x[inside], y[inside], np.sqrt(1 - x[inside] ** 2 - y[inside] ** 2)], axis=-1)
    az, el = np.radians([state.light_azimuth, state.light_elevation])
    light = np.array([np.cos(el) * np.sin(az), np.sin(el), np.cos(el) * np.cos(az)])
    view = np.array([0.0, 0.0, 1.0])
    colour, intensity = hex_rgb(state.color), hex_rgb(state.light_color)
    n_dot_l = n @ light
    if state.model == "Phong":
        r = 2 * n_dot_l[:, None] * n - light
        cos_spec = r @ view
    else:
        h = (light + view) / np.linalg.norm(light + view)
        cos_spec = n @ h
    spec = np.where(n_dot_l > 0, np.maximum(cos_spec, 0) ** state.shininess, 0.0)
    diffuse = state.kd * colour * intensity * np.maximum(n_dot_l, 0)[:, None]
    specular = state.ks * intensity * spec[:, None]
    ambient = (state.ka + state.emission) * colour * np.ones_like(diffuse)
    return inside, ambient, diffuse, specular


@pytest.mark.parametrize("model", phong.MODELS)
@pytest.mark.parametrize("azimuth, elevation, shininess", [(35, 30, 32), (-70, -20, 5),
                                                           (0, 0, 200), (150, 10, 20)])
def test_phong_sphere_against_the_formulas(model, azimuth, elevation, shininess):
    state = phong.State(model=model, light_azimuth=azimuth, light_elevation=elevation,
                        shininess=shininess, emission=0.1, light_color="#ffe0c0",
                        color="#3366cc")
    s = phong.scene(state)
    inside, ambient, diffuse, specular = analytic_sphere(state)
    assert np.array_equal(s["mask"], inside)
    for name, expected in (("ambient", ambient), ("diffuse", diffuse), ("specular", specular),
                           ("total", ambient + diffuse + specular)):
        assert np.allclose(s[name][inside], np.clip(expected, 0, 1), atol=1e-12), name
        assert np.all(s[name][~inside] == phong.BACKGROUND)
    assert np.allclose(s["raw"].total, ambient + diffuse + specular, atol=1e-12)


def test_phong_highlight_centre_is_where_n_equals_h():
    state = phong.State(ka=0, kd=0, ks=1, shininess=400, light_azimuth=40, light_elevation=25)
    s = phong.scene(state)
    light = phong.light_direction(40, 25)
    h = (light + [0, 0, 1]) / np.linalg.norm(light + [0, 0, 1])
    assert np.allclose(s["highlight"], h[:2])
    row, col = np.unravel_index(np.argmax(s["specular"][..., 0]), s["mask"].shape)
    centres = ((np.arange(phong.SIZE) + 0.5) / phong.SIZE * 2 - 1) * phong.EXTENT
    assert abs(centres[col] - h[0]) < 0.02 and abs(centres[row] - h[1]) < 0.02


def test_blinn_phong_needs_about_four_times_the_exponent():
    width = {}
    for model, n in (("Phong", 20), ("Blinn-Phong", 20), ("Blinn-Phong", 80)):
        s = phong.scene(phong.State(ka=0, kd=0, ks=1, shininess=n, model=model,
                                    light_azimuth=30, light_elevation=0))
        width[model, n] = int((s["raw"].specular[:, 0] > 0.5).sum())      # highlight area
    assert width["Blinn-Phong", 20] > 2.5 * width["Phong", 20]
    assert 0.6 < width["Blinn-Phong", 80] / width["Phong", 20] < 1.5


@pytest.mark.parametrize("segments", [6, 12])
@pytest.mark.parametrize("model", phong.MODELS)
def test_interpolated_shading_equals_render_shaded(segments, model):
    """The cached barycentric weights give the pictures render_shaded draws from scratch."""
    state = phong.State(segments=segments, model=model, light_azimuth=25, light_elevation=35)
    s = phong.scene(state)
    v, f = shading.uv_sphere(segments=segments, rings=segments // 2)
    view = viewing.look_at(phong.EYE, [0, 0, -1], [0, 1, 0])
    proj = viewing.perspective(np.radians(phong.FOV_DEG), 1.0, 1.0, 10.0)
    colour = hex_rgb(state.color)
    material = shading.colored_material(colour, state.ka, state.kd, state.ks, state.shininess)
    light = shading.directional_light(phong.light_direction(25, 35))
    for method in ("flat", "gouraud", "phong"):
        reference = shading.render_shaded(v, f, view, proj, phong.MESH_SIZE, phong.MESH_SIZE,
                                          light, material, shading=method, normals=v,
                                          model="phong" if model == "Phong" else "blinn",
                                          background=phong.BACKGROUND)
        assert np.allclose(s[method], np.clip(reference.image, 0, 1), atol=1e-9), method


def test_gouraud_loses_the_highlight_and_flat_is_faceted():
    state = phong.State(segments=8, shininess=100, light_azimuth=30, light_elevation=20)
    s = phong.scene(state)
    _, f, ids, _ = phong.interpolation_buffers(8)
    seen = ids >= 0
    assert s["phong"][seen].max() - s["gouraud"][seen].max() > 0.15   # Gouraud misses it
    for face in np.unique(ids[ids >= 0]):
        assert len(np.unique(s["flat"][ids == face], axis=0)) == 1     # one colour per face


def test_phong_explorer_wiring():
    ex = phong.PhongExplorer()
    ex.ks.value = 0.0
    mask = phong.sphere_normals()[1]
    assert np.all(np.asarray(ex.images["specular"].get_array())[mask] == 0)
    ex.kd.value = 0.3
    ex.azimuth.value = -60
    ex.elevation.value = 10
    expected = phong.scene(ex.state)
    assert np.allclose(ex.images["total"].get_array(), expected["total"])
    assert np.allclose(ex.images["gouraud"].get_array(), expected["gouraud"])
    light = phong.light_direction(-60, 10)
    assert np.allclose([ex.sun.get_xdata()[0], ex.sun.get_ydata()[0]], light[:2])
    ex.light_color.value = "#ff0000"                 # red light on a blue object: no diffuse
    assert np.asarray(ex.images["diffuse"].get_array())[mask][:, 2].max() == 0
    ex.model.value = "Blinn-Phong"
    assert "Blinn-Phong" in ex.info.value and "Blinn-Phong" in ex.model_label.get_text()
    ex.segments.value = 20
    assert f"{2 * 20 * 9} triangles" in ex.info.value
    assert ex.png()[:4] == b"\x89PNG"


# --- barycentric explorer --------------------------------------------------------------------

def solve_weights(p, tri):
    """lambda_B, lambda_C from (B - A, C - A) [lambda_B, lambda_C]^T = P - A."""
    a, b, c = tri
    lb, lc = np.linalg.solve(np.column_stack([b - a, c - a]), p - a)
    return np.array([1 - lb - lc, lb, lc])


def test_barycentric_weights_against_a_linear_solve():
    rng = np.random.default_rng(14)
    for _ in range(200):
        tri = rng.uniform(0, 10, (3, 2))
        (bx, by), (cx, cy) = tri[1] - tri[0], tri[2] - tri[0]
        if abs(bx * cy - by * cx) < 1.0:
            continue
        p = rng.uniform(-2, 12, 2)
        s = barycentric.scene(barycentric.State(triangle=tri, point=p))
        expected = solve_weights(p, tri)
        assert np.allclose(s["weights"], expected, atol=1e-9)
        assert s["inside"] == bool(np.all(expected >= 0))
        total = s["areas"]["ABC"]
        assert np.isclose(s["areas"]["PBC"] + s["areas"]["APC"] + s["areas"]["ABP"], total)
        assert np.allclose([s["areas"][n] / total for n in ("PBC", "APC", "ABP")], expected)
        assert np.allclose(s["raw_colour"], expected @ barycentric.COLORS)


def test_barycentric_picture_interpolates_the_corner_colours():
    state = barycentric.State()
    s = barycentric.scene(state)
    centres = (np.arange(barycentric.RESOLUTION) + 0.5) / barycentric.RESOLUTION * 10
    rng = np.random.default_rng(1)
    for i, j in rng.integers(0, barycentric.RESOLUTION, (300, 2)):
        w = solve_weights(np.array([centres[j], centres[i]]), state.triangle)
        inside = np.all(w >= 0)
        assert s["image"][i, j, 3] == float(inside)
        if inside:
            assert np.allclose(s["image"][i, j, :3], np.clip(w @ barycentric.COLORS, 0, 1))


def test_barycentric_degenerate_triangle_is_reported():
    s = barycentric.scene(barycentric.State(triangle=np.array([[0.0, 0], [1, 1], [2, 2]])))
    assert s["degenerate"] and np.all(np.isnan(s["weights"])) and "degenerate" in s["text"]


def test_barycentric_explorer_drag_with_real_mouse_events():
    ex = barycentric.BarycentricExplorer()
    ex.fig.canvas.draw()
    drag(ex.ax, ex.state.point, (8.0, 7.0))                   # P beyond the edge BC
    assert np.allclose(ex.state.point, (8.0, 7.0))
    expected = solve_weights(np.array([8.0, 7.0]), ex.state.triangle)
    assert expected[0] < 0
    heights = [bar.get_height() for bar in ex.bars]
    assert np.allclose(heights, np.clip(expected, -0.95, 1.55))
    assert np.allclose(ex.swatch.get_facecolor()[:3], np.clip(expected @ barycentric.COLORS,
                                                              0, 1))
    assert ex.patches[0].get_hatch() == "////"                # the turned-over sub-triangle
    assert "outside" in ex.info.value
    drag(ex.ax, ex.state.triangle[0], (2.0, 0.5))             # move corner A
    assert np.allclose(ex.state.triangle[0], (2.0, 0.5))
    assert np.allclose(np.asarray(ex.outline.get_xydata())[[0, 3]], [(2.0, 0.5), (2.0, 0.5)])
    assert np.allclose(ex.markers.get_offsets()[0], (2.0, 0.5))
    ex.mode.value = "colours"
    assert ex.fill.get_visible() and not any(p.get_visible() for p in ex.patches)
    assert np.allclose(ex.fill.get_array(), barycentric.scene(ex.state)["image"])


# --- texture explorer ------------------------------------------------------------------------

def angular_close(a, b, atol=1e-9):
    d = np.abs(a - b)
    return np.all(np.minimum(d, 1 - d) < atol)


def test_spherical_and_cylindrical_uv_against_the_angles():
    p = texture.mesh_grid("sphere")
    u, v = texture.texture_uv("sphere")
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    off_pole = np.hypot(x, z) > 1e-9
    assert angular_close(u[off_pole], (0.5 + np.arctan2(x, z) / (2 * np.pi))[off_pole])
    assert np.allclose(v, 0.5 + np.arcsin(np.clip(y, -1, 1)) / np.pi)
    assert np.all(u[0] == 0) and np.all(u[-1] == 1)           # both copies of the seam column
    p = texture.mesh_grid("cylinder")
    u, v = texture.texture_uv("cylinder")
    assert angular_close(u, 0.5 + np.arctan2(p[..., 0], p[..., 2]) / (2 * np.pi))
    assert np.allclose(v, (p[..., 1] + 1) / 2)
    p = texture.mesh_grid("plane")
    u, v = texture.texture_uv("plane")
    assert np.allclose(u, (p[..., 0] + 1) / 2) and np.allclose(v, (p[..., 1] + 1) / 2)


def test_compendium_formulas_use_half_the_texture():
    p = texture.mesh_grid("sphere")
    u, v = texture.texture_uv("sphere, compendium's formulas")
    assert u.min() >= 0.25 and u.max() <= 0.75                # tan^-1(x/z): half a turn only
    uc, _ = texture.compendium_map(-p)
    assert np.allclose(uc, u)                                 # P and -P get the same u
    assert np.isclose(v.max(), 0.75)                          # the pole at 45 degrees, not 90
    correct_u, correct_v = texturing.spherical_map(p[1:-1, 1:-1])
    assert np.abs(correct_v - v[1:-1, 1:-1]).max() > 0.2


def test_texture_images_against_closed_forms_and_the_library():
    size = 32
    uv = texturing.uv_grid(size, size)
    checker = texture.texture_image("checkerboard", 8, 0, size)
    expected = (np.floor(8 * uv[..., 0]) + np.floor(8 * uv[..., 1])) % 2
    assert np.array_equal(checker, expected)
    stripes = texture.texture_image("stripes", 4, 0, size)
    assert np.array_equal(stripes, ((4 * uv[..., 0]) % 1 < 0.5).astype(float))
    s = texture.NOISE_SCALE
    marble = texture.texture_image("marble", 2.0, 3.0, size)
    assert np.allclose(marble, texturing.marble(uv * s, frequency=2.0 / s, strength=3.0))
    wood = texture.texture_image("wood", 8.0, 0.6, size)
    assert np.allclose(wood, texturing.wood(uv * s, rings=8.0 / s, strength=0.6,
                                            center=(s / 2, s / 2)))
    noise = texture.texture_image("noise", 8.0, 0, size)
    assert np.allclose(noise, np.clip(0.5 + 0.7 * texturing.perlin_noise(uv * 8), 0, 1))


@pytest.mark.parametrize("size", [4, 16, 64])
def test_nearest_display_repeats_each_texel(size):
    s = texture.scene(texture.State(size=size, frequency=2, sampling="nearest"),
                      with_filtering=False)
    k = texture.DISPLAY // size
    assert np.array_equal(s["display"], np.repeat(np.repeat(s["texture"], k, 0), k, 1))
    b = texture.scene(texture.State(size=size, frequency=2, sampling="bilinear"),
                      with_filtering=False)
    assert not np.array_equal(b["display"], s["display"])      # bilinear blends neighbours


def test_filtering_panel_trilinear_removes_the_moire():
    s = texture.scene(texture.State(texture="checkerboard", size=64, frequency=8))
    f = s["filtering"]
    mean = s["texture"].reshape(-1, 3).mean(axis=0)
    far = slice(-12, None)                                    # rows near the horizon
    err = {m: np.abs(f["minified"][m][far] - mean).mean() for m in ("nearest", "bilinear",
                                                                     "trilinear")}
    assert err["trilinear"] < 0.05 and err["nearest"] > 5 * err["trilinear"]
    assert err["bilinear"] > 3 * err["trilinear"]            # bilinear does not help far away
    assert np.allclose(f["magnified"]["trilinear"], f["magnified"]["bilinear"])
    assert len(np.unique(f["magnified"]["nearest"].reshape(-1, 3), axis=0)) == 2


def test_texture_explorer_wiring():
    ex = texture.TextureExplorer()
    first = ex.image.value
    assert first[:2] == b"\xff\xd8"
    ex.sampling.value = "nearest"
    assert ex.image.value != first
    ex.mapping.value = "sphere, compendium's formulas"
    assert "same half" in ex.info.value
    tcoords = np.asarray(ex.grids["sphere"].active_texture_coordinates)
    u, _ = texture.texture_uv("sphere, compendium's formulas")
    assert np.allclose(tcoords[:, 0], u.ravel(order="F"))
    ex.texture.value = "marble"                               # parameters reset for marble
    assert (ex.frequency.value, ex.strength.value) == texture.DEFAULTS["marble"]
    assert not ex.strength.disabled
    expected = texture.scene(ex.state)["filtering"]["minified"]["trilinear"]
    assert np.allclose(ex.panel["minified", "trilinear"].get_array(), np.clip(expected, 0, 1))
    ex.mapping.value = "cylinder"
    assert ex.actors["cylinder"].GetVisibility() and not ex.actors["sphere"].GetVisibility()
    seam = np.asarray(ex.seam.points)                         # the cylinder's seam, behind it
    assert np.allclose(seam[:, 0], 0) and np.allclose(seam[:, 2], -1.01 * texture.CYLINDER_RADIUS)
    assert np.allclose(np.sort(seam[:, 1])[[0, -1]], [-1, 1])
    ex.mapping.value = "plane"
    assert not ex.seam_actor.GetVisibility()
    ex.texture.value = "stripes"
    assert ex.strength.disabled
    assert ex.png()[:4] == b"\x89PNG"
    ex.plotter.close()


# --- ambient-occlusion explorer --------------------------------------------------------------

@pytest.mark.parametrize("samples", [1, 7, 64, 256])
def test_open_floor_is_exactly_unoccluded_for_any_sample_count(samples):
    s = occlusion.scene(occlusion.State(kind="open floor", samples=samples))
    assert np.all(s["estimate"] == 1.0) and np.all(s["std_error"] == 0.0)


def test_wall_estimate_against_the_closed_form():
    a = occlusion.floor_points()[..., 0]
    exact = 0.5 * (1 + a / np.sqrt(a**2 + occlusion.WALL_HEIGHT**2))
    s = occlusion.scene(occlusion.State(kind="wall", samples=256))
    assert np.allclose(s["exact"], exact)
    error = s["estimate"] - exact
    assert abs(error.mean()) < 0.006                          # unbiased: 576 points average out
    assert np.abs(error).max() < 5 * 0.5 / np.sqrt(256)
    assert np.all(s["estimate"][:, 0] < s["estimate"][:, -1] + 0.1)   # darker at the wall


def test_ao_noise_falls_like_one_over_root_k():
    conv = occlusion.convergence("wall")
    rms = conv["rms_error"]
    for k in (4, 16, 64):
        assert 1.5 < rms[k - 1] / rms[4 * k - 1] < 2.6           # 4x the rays: half the error
    slope = np.polyfit(np.log(conv["k"][7:]), np.log(rms[7:]), 1)[0]
    assert -0.6 < slope < -0.4
    se = conv["std_error"]
    scaled = se[15:] * np.sqrt(conv["k"][15:])                # SE * sqrt(k) about constant
    assert scaled.max() / scaled.min() < 1.3
    assert np.all(se[1:] <= conv["bound"][1:])


def test_ao_is_seeded_and_the_box_darkens_its_surroundings():
    a = occlusion.ray_visibility("box by a wall", 0)
    assert a is occlusion.ray_visibility("box by a wall", 0)
    b = occlusion.ray_visibility("wall", 1)
    c = occlusion.ray_visibility("wall", 0)
    assert not np.array_equal(b, c)
    s = occlusion.scene(occlusion.State(kind="box by a wall", samples=256))
    est = s["estimate"]
    assert np.isnan(est[occlusion._under_box()]).all()
    wall_only = occlusion.scene(occlusion.State(kind="wall", samples=256))["estimate"]
    near_box = (slice(9, 15), slice(6, 8))                    # just left of the box
    assert est[near_box].mean() < wall_only[near_box].mean() - 0.05


def test_occlusion_explorer_wiring():
    ex = occlusion.OcclusionExplorer(occlusion.State(kind="wall"))
    ex.samples.value = 32
    rays = occlusion.ray_visibility("wall", 0)
    assert np.allclose(ex.ao_image.get_array(), rays[:32].mean(axis=0))
    assert list(ex.marker.get_xdata()) == [32, 32]
    assert ex.err_title.get_text() == "|estimate − exact|"
    assert len(ex.rms_line.get_xdata()) == occlusion.MAX_SAMPLES
    ex.kind.value = "box by a wall"
    assert ex.err_title.get_text() == "estimated standard error"
    assert len(ex.rms_line.get_xdata()) == 0
    assert ex.outlines[0][1].get_visible()
    ex.seed.value = 3
    expected = occlusion.ray_visibility("box by a wall", 3)[:32].mean(axis=0)
    assert np.allclose(np.ma.filled(ex.ao_image.get_array(), np.nan), expected, equal_nan=True)
    assert "k = 32" in ex.info.value


def test_texture_explorer_seam_follows_the_mapping():
    ex = texture.TextureExplorer()                            # starts on the sphere
    seam = np.asarray(ex.seam.points)
    assert np.allclose(np.linalg.norm(seam, axis=1), 1.01)    # a meridian just off the sphere
    ex.mapping.value = "cylinder"                             # same number of seam points
    seam = np.asarray(ex.seam.points)
    assert np.allclose(np.hypot(seam[:, 0], seam[:, 2]), 1.01 * texture.CYLINDER_RADIUS)
    assert np.allclose(seam[:, 0], 0) and np.all(seam[:, 2] < 0)
    ex.plotter.close()
