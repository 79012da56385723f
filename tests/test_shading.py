"""Tests of course_lib.shading (chapter 12).

References: closed forms typed out below (a lit sphere, attenuation, ambient occlusion of simple
configurations, derived in the comments), PyGLM's ``reflect`` (GLSL's, incoming direction),
trimesh's face normals, and hand-worked examples. Nothing is copied from the output of the code
under test.
"""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pyglm import glm           # GLSL's reflect, as a reference
from scipy import stats

from course_lib import shading as S
from course_lib import viewing, visibility

FAST = settings(max_examples=150, deadline=None, database=None)
BIG = 1e4                                   # "infinite" walls in the occlusion scenes


def rng(seed):
    return np.random.default_rng(seed)


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def random_units(gen, n):
    return unit(gen.normal(size=(n, 3)))


# ---------------------------------------------------------------------------------------------
# reflect, halfway
# ---------------------------------------------------------------------------------------------

def test_reflect_closed_form_and_glm():
    np.testing.assert_allclose(S.reflect([1, 2, 3], [0, 0, 1]), [-1, -2, 3])
    gen = rng(1)
    l_dir, n = random_units(gen, 500), random_units(gen, 500)
    r = S.reflect(l_dir, n)
    for k in range(0, 500, 7):             # GLSL reflect(I, N) = I - 2 dot(N, I) N, I incoming
        expected = glm.reflect(glm.vec3(*(-l_dir[k])), glm.vec3(*n[k]))
        np.testing.assert_allclose(r[k], list(expected), atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(r, axis=1), 1.0, atol=1e-12)
    np.testing.assert_allclose(np.sum(r * n, axis=1), np.sum(l_dir * n, axis=1), atol=1e-12)
    np.testing.assert_allclose(np.cross(r + l_dir, n), 0.0, atol=1e-12)   # R + L along N
    np.testing.assert_allclose(S.reflect(l_dir, 5 * n), r, atol=1e-12)     # n is normalized


def test_halfway_bisects_l_and_v():
    gen = rng(2)
    l_dir, v = random_units(gen, 300), random_units(gen, 300)
    keep = np.sum(l_dir * v, axis=1) > -0.99
    h = S.halfway(l_dir[keep] * 3, v[keep])
    np.testing.assert_allclose(np.linalg.norm(h, axis=1), 1.0, atol=1e-12)
    np.testing.assert_allclose(np.sum(h * l_dir[keep], 1), np.sum(h * v[keep], 1), atol=1e-12)
    # H is the normal that mirrors L into V
    np.testing.assert_allclose(S.reflect(l_dir[keep], h), v[keep], atol=1e-9)


# ---------------------------------------------------------------------------------------------
# the Phong model against a lit sphere
# ---------------------------------------------------------------------------------------------

def sphere_pixels(width):
    """Pixel centres of an orthographic view of the unit sphere from +z: (x, y, N, inside)."""
    xs = ((np.arange(width) + 0.5) / width * 2 - 1) * 1.2
    x, y = np.meshgrid(xs, xs)
    rr = x**2 + y**2
    normal = np.stack([x, y, np.sqrt(np.maximum(0.0, 1 - rr))], axis=-1)
    return x, y, normal, rr < 1


def closed_form(normal, l_dir, v, ka, kd, ks, n, ia=1.0, il=1.0):
    """I = Ia ka + Il [kd max(N.L, 0) + ks max(R.V, 0)^n], with R.V = 2 (N.L)(N.V) - L.V
    (expanding R = 2 (N.L) N - L) and no highlight where N.L <= 0."""
    nl = normal @ l_dir
    rv = 2 * nl * (normal @ v) - l_dir @ v
    spec = np.where(nl > 0, np.maximum(rv, 0.0) ** n, 0.0)
    return ia * ka + il * (kd * np.maximum(nl, 0.0) + ks * spec)


def test_phong_per_pixel_sphere_matches_closed_form_exactly():
    _, _, normal, inside = sphere_pixels(256)
    l_dir = unit([1.0, 2.0, 2.5])
    v = np.array([0.0, 0.0, 1.0])
    m = S.Material(ka=0.1, kd=0.6, ks=0.3, shininess=17)
    terms = S.phong(normal, normal, np.broadcast_to(v, normal.shape), S.directional_light(l_dir), m)
    assert terms.total.shape == (256, 256, 3)
    expected = closed_form(normal, l_dir, v, 0.1, 0.6, 0.3, 17)
    np.testing.assert_allclose(terms.total[inside][:, 0], expected[inside], atol=1e-12)
    np.testing.assert_allclose(terms.total, terms.emission + terms.ambient + terms.diffuse
                               + terms.specular, atol=1e-15)
    # the highlight peaks where N is the halfway vector of L and V
    peak = np.unravel_index(np.argmax(terms.specular[..., 0]), (256, 256))
    np.testing.assert_allclose(normal[peak], unit(l_dir + v), atol=0.01)


def test_phong_colours_multiply_channel_by_channel():
    _, _, normal, inside = sphere_pixels(64)
    l_dir = unit([-1.0, 0.5, 1.0])
    ka, kd, ks = np.array([0.1, 0.05, 0.0]), np.array([0.9, 0.4, 0.1]), np.array([0.2, 0.3, 0.4])
    il, ia = np.array([1.0, 0.8, 0.5]), np.array([0.3, 0.3, 0.6])
    m = S.Material(ka=ka, kd=kd, ks=ks, shininess=9, emission=(0.05, 0.0, 0.02))
    got = S.phong(None, normal[inside], [0, 0, 1], S.directional_light(l_dir, il), m,
                  ambient=ia).total
    for c in range(3):
        expected = closed_form(normal[inside], l_dir, np.array([0, 0, 1.0]), ka[c], kd[c], ks[c],
                               9, ia[c], il[c]) + [0.05, 0.0, 0.02][c]
        np.testing.assert_allclose(got[:, c], expected, atol=1e-12)


def test_rendered_sphere_matches_closed_form_and_phong_beats_gouraud_beats_flat():
    v, f = S.uv_sphere(segments=96, rings=48)
    view = viewing.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])
    proj = viewing.orthographic(-1.2, 1.2, -1.2, 1.2, 1, 10)
    l_dir = unit([1.0, 1.0, 2.0])
    m = S.Material(ka=0.1, kd=0.6, ks=0.3, shininess=20)
    _, _, normal, inside = sphere_pixels(96)
    inner = inside & (normal[..., 2] > 0.3)              # away from the faceted silhouette
    expected = closed_form(normal, l_dir, np.array([0, 0, 1.0]), 0.1, 0.6, 0.3, 20)
    errors = {}
    for shading in ("flat", "gouraud", "phong"):
        img = S.render_shaded(v, f, view, proj, 96, 96, S.directional_light(l_dir), m,
                              shading=shading, normals=v)
        assert np.all(img.ids[inner] >= 0) and np.all(img.ids[~inside] == -1)
        assert np.all(img.image[~inside] == 0)
        errors[shading] = np.abs(img.image[..., 0] - expected)[inner].max()
    assert errors["phong"] < 0.005
    assert errors["phong"] < errors["gouraud"] / 3 < errors["flat"] / 3


def test_rendered_sphere_in_perspective_with_a_point_light():
    # perspective camera at E, point light at Q: at each pixel take the analytic hit point of
    # the pixel's ray with the unit sphere and evaluate the closed form there
    eye, q = np.array([0.0, 0.0, 4.0]), np.array([2.0, 3.0, 4.0])
    view = viewing.look_at(eye, [0, 0, -1], [0, 1, 0])
    proj = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    v, f = S.uv_sphere(segments=128, rings=64)
    m = S.Material(ka=0.05, kd=0.7, ks=0.25, shininess=12)
    light = S.point_light(q, intensity=2.0, attenuation=(0.5, 0.1, 0.02))
    img = S.render_shaded(v, f, view, proj, 64, 64, light, m, shading="phong", normals=v)
    origins, dirs = visibility_rays(view, proj, 64)
    d = unit(dirs)
    b = np.sum(origins * d, axis=-1)
    disc = b**2 - (np.sum(origins**2, axis=-1) - 1)
    hit = disc > 0.05
    t = -b - np.sqrt(np.where(hit, disc, 0))
    p = origins + t[..., None] * d
    to_l = q - p
    dist = np.linalg.norm(to_l, axis=-1)
    att = 1 / (0.5 + 0.1 * dist + 0.02 * dist**2)
    nl = np.sum(p * to_l, -1) / dist
    vv = unit(eye - p)
    rv = 2 * nl * np.sum(p * vv, -1) - np.sum(to_l / dist[..., None] * vv, -1)
    expected = 0.05 + 2.0 * att * (0.7 * np.maximum(nl, 0)
                                   + 0.25 * np.where(nl > 0, np.maximum(rv, 0) ** 12, 0))
    err = np.abs(img.image[..., 0] - expected)[hit & (img.ids >= 0)]
    assert err.max() < 0.01


def visibility_rays(view, proj, width):
    """World-space rays through pixel centres, written from the inverse camera matrix."""
    inv = np.linalg.inv(proj @ view)
    s = (np.arange(width) + 0.5) / width * 2 - 1
    x, y = np.meshgrid(s, s)
    near = np.stack([x, y, -np.ones_like(x), np.ones_like(x)], -1) @ inv.T
    far = np.stack([x, y, np.ones_like(x), np.ones_like(x)], -1) @ inv.T
    near, far = near[..., :3] / near[..., 3:], far[..., :3] / far[..., 3:]
    return near, far - near


def test_blinn_phong_with_four_times_the_shininess_looks_alike_near_the_highlight():
    _, _, normal, inside = sphere_pixels(200)
    l_dir, v = unit([1.0, 0.0, 1.0]), np.array([0.0, 0.0, 1.0])
    light = S.directional_light(l_dir)
    n = 30
    spec = dict(ka=0.0, kd=0.0, ks=1.0)
    ph = S.phong(None, normal[inside], v, light, S.Material(**spec, shininess=n)).total[:, 0]
    b4 = S.blinn_phong(None, normal[inside], v, light,
                       S.Material(**spec, shininess=4 * n)).total[:, 0]
    b1 = S.blinn_phong(None, normal[inside], v, light, S.Material(**spec, shininess=n)).total[:, 0]
    # exact Blinn-Phong term written here: H = (L + V)/|L + V|
    h = unit(l_dir + v)
    expected = np.where(normal[inside] @ l_dir > 0,
                        np.maximum(normal[inside] @ h, 0) ** (4 * n), 0)
    np.testing.assert_allclose(b4, expected, atol=1e-12)
    assert abs(ph.max() - 1) < 0.01 and abs(b4.max() - 1) < 0.01      # pixels near the peak
    assert np.abs(ph - b4).max() < 0.15                 # the qualitative "looks alike" bound
    # the same exponent makes a much bigger Blinn highlight (about 4 times the area)
    assert (b1 > 0.5).sum() > 3 * (ph > 0.5).sum()
    assert 0.5 < (b4 > 0.5).sum() / (ph > 0.5).sum() < 2.0


def test_blinn_half_angle_in_the_plane_of_incidence():
    # N, L, V coplanar: angle(N, H) is exactly half of angle(R, V)
    alpha = np.linspace(0, 0.6, 50)                     # angle of V away from R
    theta = 0.5                                          # angle of incidence
    l_dir = [np.sin(theta), 0, np.cos(theta)]
    v = np.stack([-np.sin(theta + alpha), np.zeros_like(alpha), np.cos(theta + alpha)], -1)
    m = S.Material(ka=0, kd=0, ks=1, shininess=7)
    got = S.blinn_phong(None, [0, 0, 1], v, S.directional_light(l_dir), m).total[:, 0]
    np.testing.assert_allclose(got, np.cos(alpha / 2) ** 7, atol=1e-12)
    got = S.phong(None, [0, 0, 1], v, S.directional_light(l_dir), m).total[:, 0]
    np.testing.assert_allclose(got, np.cos(alpha) ** 7, atol=1e-12)


# ---------------------------------------------------------------------------------------------
# energy sanity, lights, attenuation
# ---------------------------------------------------------------------------------------------

unit3 = st.tuples(*[st.floats(-1, 1)] * 3).map(np.array).filter(lambda v: np.linalg.norm(v) > 0.1)


@FAST
@given(unit3, unit3, unit3, st.floats(0.5, 200))
def test_terms_are_non_negative_and_vanish_behind_the_surface(n, l_dir, v, shininess):
    t = S.phong(None, n, v, S.directional_light(l_dir), S.Material(shininess=shininess))
    b = S.blinn_phong(None, n, v, S.directional_light(l_dir), S.Material(shininess=shininess))
    for terms in (t, b):
        for field in terms:
            assert np.all(field >= 0)
        if unit(n) @ unit(l_dir) <= 0:
            assert np.all(terms.diffuse == 0) and np.all(terms.specular == 0)
        assert np.all(terms.total <= 0.1 + 0.7 + 0.2 + 1e-12)     # ka + kd + ks, Il = Ia = 1


def test_no_highlight_from_a_light_behind_the_surface_even_when_r_dot_v_is_positive():
    n, l_dir = [0, 0, 1], unit([1.0, 0.0, -0.1])       # light slightly below the horizon
    r = 2 * (np.dot(n, l_dir)) * np.array(n) - l_dir
    v = unit([-1.0, 0.0, 0.05])                         # grazing viewer
    assert r @ v > 0.9                                  # the naive formula would shine
    for model in (S.phong, S.blinn_phong):
        t = model(None, n, v, S.directional_light(l_dir), S.Material(ks=1.0, shininess=2))
        assert t.specular.max() == 0 and t.diffuse.max() == 0


def test_point_light_attenuation_and_several_lights_add_up():
    p = np.array([[0.0, 0.0, 0.0], [3.0, 0.0, 0.0]])
    nrm = np.array([0.0, 0.0, 1.0])
    light = S.point_light([0, 0, 2], intensity=(1.0, 0.5, 0.25), attenuation=(1, 0.5, 0.25))
    m = S.Material(ka=0, kd=0.8, ks=0.0)
    t = S.phong(p, nrm, [0, 0, 1], light, m)
    # point 0: d = 2, N.L = 1, f = 1/(1 + 1 + 1); point 1: d = sqrt(13), N.L = 2/sqrt(13)
    d1 = np.sqrt(13)
    f = np.array([1 / 3, 1 / (1 + 0.5 * d1 + 0.25 * 13)])
    cos = np.array([1.0, 2 / d1])
    np.testing.assert_allclose(t.diffuse, 0.8 * (f * cos)[:, None] * [1, 0.5, 0.25], atol=1e-12)
    np.testing.assert_allclose(S.attenuation([2.0, d1], 1, 0.5, 0.25), f)
    lights = [light, S.directional_light([1, 0, 1], 0.7), S.point_light([-1, 1, 1])]
    m = S.Material(ka=0.2, kd=0.5, ks=0.3, shininess=5, emission=0.1)
    v = S.view_directions(p, [1, 1, 4])
    together = S.phong(p, nrm, v, lights, m)
    alone = [S.phong(p, nrm, v, light_k, m) for light_k in lights]
    np.testing.assert_allclose(together.diffuse, sum(a.diffuse for a in alone), atol=1e-12)
    np.testing.assert_allclose(together.specular, sum(a.specular for a in alone), atol=1e-12)
    np.testing.assert_allclose(together.ambient, alone[0].ambient)
    np.testing.assert_allclose(together.total, sum(a.total for a in alone) - 2 * (0.2 + 0.1),
                               atol=1e-12)


def test_light_visibility_removes_only_that_lights_diffuse_and_specular():
    gen = rng(3)
    p, n = gen.normal(size=(50, 3)), random_units(gen, 50)
    v = random_units(gen, 50)
    lights = [S.point_light([0, 5, 0]), S.directional_light([0, 1, 1], 0.5)]
    m = S.Material(emission=0.05)
    vis = np.zeros((50, 2))
    vis[:, 1] = 1
    shadowed = S.phong(p, n, v, lights, m, light_visibility=vis, two_sided=True)
    only_second = S.phong(p, n, v, lights[1], m, two_sided=True)
    np.testing.assert_allclose(shadowed.total, only_second.total, atol=1e-12)
    dark = S.phong(p, n, v, lights, m, light_visibility=np.zeros((50, 2)))
    np.testing.assert_allclose(dark.total, 0.1 + 0.05)


def test_separate_light_colours_feed_each_term_their_own_colour():
    """A light with ambient, diffuse and specular colours, against the model typed out: each
    term takes its own colour channel by channel; the light's ambient part is attenuated but
    neither shadowed nor switched off behind the surface."""
    rng = np.random.default_rng(4)
    points = rng.uniform(-1, 1, (50, 3)) * [1, 1, 0]
    normals = np.tile([0.0, 0.0, 1.0], (50, 1))
    eye = np.array([0.3, -0.2, 3.0])
    pos = np.array([0.5, 0.4, 2.0])
    ia, idf, isp = np.array([0.2, 0.1, 0.05]), np.array([1.0, 0.6, 0.2]), np.array([0.3, 0.9, 1.0])
    mat = S.Material(ka=(0.5, 0.4, 0.3), kd=(0.6, 0.5, 0.4), ks=(0.3, 0.2, 0.1), shininess=7)
    abc = (1.0, 0.2, 0.1)
    light = S.point_light(pos, attenuation=abc, ambient=ia, diffuse=idf, specular=isp)
    vis = rng.uniform(0, 1, (50, 1))
    got = S.phong(points, normals, eye - points, light, mat, ambient=0.1, light_visibility=vis)
    for k in range(50):
        to = pos - points[k]
        d = np.sqrt(to @ to)
        L, n = to / d, normals[k]
        V = (eye - points[k]) / np.linalg.norm(eye - points[k])
        R = 2 * (n @ L) * n - L
        f = 1 / (abc[0] + abc[1] * d + abc[2] * d * d)
        ambient = np.array(mat.ka) * (0.1 + f * ia)
        diffuse = f * vis[k, 0] * np.array(mat.kd) * idf * max(n @ L, 0)
        specular = f * vis[k, 0] * np.array(mat.ks) * isp * max(R @ V, 0) ** 7
        assert np.allclose(got.ambient[k], ambient, atol=1e-12)
        assert np.allclose(got.diffuse[k], diffuse, atol=1e-12)
        assert np.allclose(got.specular[k], specular, atol=1e-12)
        assert np.allclose(got.total[k], ambient + diffuse + specular, atol=1e-12)
    # behind the surface: no diffuse or specular, the light's ambient part stays
    below = S.phong(points, -normals, [0, 0, 1], light, mat, ambient=0.0)
    assert np.all(below.diffuse == 0) and np.all(below.specular == 0)
    assert np.all(below.ambient > 0)


def test_one_intensity_is_the_same_light_as_equal_separate_colours():
    rng = np.random.default_rng(5)
    p = rng.uniform(-1, 1, (30, 3))
    n = rng.normal(size=(30, 3))
    v = rng.normal(size=(30, 3))
    m = S.Material(ka=0.2, kd=0.5, ks=0.3, shininess=12)
    for make in (lambda **kw: S.point_light([0.2, 0.1, 3.0], attenuation=(1, 0.1, 0.05), **kw),
                 lambda **kw: S.directional_light([0.3, 0.2, 1.0], **kw)):
        one = S.phong(p, n, v, make(intensity=(0.9, 0.7, 0.4)), m, two_sided=True)
        three = S.phong(p, n, v, make(intensity=5.0, diffuse=(0.9, 0.7, 0.4),
                                      specular=(0.9, 0.7, 0.4), ambient=0.0), m, two_sided=True)
        for a, b in zip(one, three):
            assert np.array_equal(a, b)
        blinn_one = S.blinn_phong(p, n, v, make(intensity=0.8), m, two_sided=True)
        blinn_three = S.blinn_phong(p, n, v, make(diffuse=0.8, specular=0.8), m, two_sided=True)
        assert np.array_equal(blinn_one.total, blinn_three.total)


@pytest.mark.parametrize("field, value, message", [
    ("diffuse", (1, -0.1, 0), "diffuse must not be negative"),
    ("specular", (1, 1), "specular must be a number"),
    ("diffuse", [[1, 1, 1], [0, 0, 0]], "diffuse must be one number or one RGB triple"),
    ("ambient", np.nan, "ambient"),
])
def test_bad_light_colours_are_named(field, value, message):
    with pytest.raises(ValueError, match=message):
        S.point_light([0, 0, 1], **{field: value})
    with pytest.raises(ValueError, match=message):
        S.directional_light([0, 0, 1], **{field: value})


def test_two_sided_flips_normals_towards_the_viewer():
    light = S.directional_light([0, 0, 1])
    back = S.phong(None, [0, 0, -1], [0, 0, 1], light, S.Material())
    assert back.diffuse.max() == 0
    both = S.phong(None, [0, 0, -1], [0, 0, 1], light, S.Material(), two_sided=True)
    front = S.phong(None, [0, 0, 1], [0, 0, 1], light, S.Material())
    np.testing.assert_allclose(both.total, front.total)


def test_material_per_point_equals_separate_calls():
    gen = rng(4)
    mats = [S.Material(kd=(0.9, 0.1, 0.1), shininess=5),
            S.colored_material((0.2, 0.8, 0.3), ks=0.5, shininess=60),
            S.Material(ka=0.3, emission=(0.1, 0.2, 0.3))]
    ids = gen.integers(0, 3, 40)
    p, n, v = gen.normal(size=(40, 3)), random_units(gen, 40), random_units(gen, 40)
    lights = [S.point_light([1, 4, 2], (1, 0.9, 0.8)), S.directional_light([0, 1, 0], 0.3)]
    got = S.phong(p, n, v, lights, S.material_per_point(mats, ids), two_sided=True).total
    for k in range(40):
        expected = S.phong(p[k], n[k], v[k], lights, mats[ids[k]], two_sided=True).total
        np.testing.assert_allclose(got[k], expected, atol=1e-12)


# ---------------------------------------------------------------------------------------------
# normals of meshes
# ---------------------------------------------------------------------------------------------

def test_face_normals_match_trimesh_and_vertex_normals_are_area_weighted():
    import trimesh.triangles as trimesh_triangles
    from course_lib import shapes

    v, f = shapes.torus(segments=16, rings=8)
    fn = S.face_normals(v, f)
    ref, valid = trimesh_triangles.normals(v[f])
    assert valid.all()
    np.testing.assert_allclose(fn, ref, atol=1e-12)
    # vertex normals by a loop written here: sum of area * unit normal, normalized
    gen = rng(5)
    v = v + 0.05 * gen.normal(size=v.shape)          # irregular, so weighting matters
    acc = np.zeros_like(v)
    for tri in f:
        a, b, c = v[tri]
        cross = np.cross(b - a, c - a)
        area = np.linalg.norm(cross) / 2
        for k in tri:
            acc[k] += area * cross / np.linalg.norm(cross)
    np.testing.assert_allclose(S.vertex_normals(v, f), unit(acc), atol=1e-12)


def test_vertex_normals_of_a_sphere_point_outwards():
    v, f = S.uv_sphere(radius=2.0, segments=64, rings=32, center=(1, 0, 0))
    vn = S.vertex_normals(v, f)
    radial = unit(v - [1, 0, 0])
    assert np.min(np.sum(vn * radial, axis=1)) > 0.999
    # and the faces are counter-clockwise seen from outside
    centroids = v[f].mean(axis=1)
    assert np.all(np.sum(S.face_normals(v, f) * (centroids - [1, 0, 0]), axis=1) > 0)


# ---------------------------------------------------------------------------------------------
# ambient occlusion
# ---------------------------------------------------------------------------------------------

def quad(a, b, c, d):
    return [[a, b, c], [a, c, d]]


def floor_scene():
    return np.array(quad([-BIG, -BIG, 0], [BIG, -BIG, 0], [BIG, BIG, 0], [-BIG, BIG, 0]))


def wall_x(x, height):
    """The wall x = const, from the floor up to `height`, infinitely long in y."""
    return np.array(quad([x, -BIG, 0], [x, BIG, 0], [x, BIG, height], [x, -BIG, height]))


def within(ao, expected, sigmas=4):
    """|estimate - expected| within `sigmas` standard errors of the estimator (the standard
    error from the *expected* value: sqrt(p (1 - p) / k))."""
    k = ao.rays // np.size(ao.visibility)
    sigma = np.sqrt(expected * (1 - expected) / k)
    return np.all(np.abs(ao.visibility - expected) <= sigmas * sigma + 1e-12)


def test_cosine_weighted_directions_have_the_right_distribution():
    gen = rng(6)
    normals = np.vstack([random_units(gen, 20), [[0, 0, -1], [0, 0, 1], [1, 0, 0]]])
    d = S.cosine_sample_hemisphere(normals, 4000, seed=7)
    assert d.shape == (23, 4000, 3)
    np.testing.assert_allclose(np.linalg.norm(d, axis=-1), 1.0, atol=1e-12)
    cos = np.einsum("pkd,pd->pk", d, normals)
    assert cos.min() >= 0
    # density 2 cos(theta) for cos(theta): cos^2 is uniform on [0, 1] (Kolmogorov-Smirnov)
    assert stats.kstest(cos.ravel() ** 2, "uniform").pvalue > 1e-3
    # and the azimuth is uniform: the mean direction is along the normal
    np.testing.assert_allclose(d.mean(axis=1), normals * 2 / 3, atol=0.03)
    np.testing.assert_array_equal(S.cosine_sample_hemisphere(normals, 10, seed=3),
                                  S.cosine_sample_hemisphere(normals, 10, seed=3))


def test_ao_of_an_open_plane_is_exactly_one():
    gen = rng(8)
    pts = np.column_stack([gen.uniform(-5, 5, (100, 2)), np.zeros(100)])
    ao = S.ambient_occlusion(pts, [0, 0, 1], floor_scene(), samples=64, seed=1)
    assert np.all(ao.visibility == 1.0) and np.all(ao.std_error == 0)
    ao = S.ambient_occlusion(pts, [0, 0, 1], None, samples=8, seed=1)
    assert np.all(ao.visibility == 1.0)


def test_ao_at_the_foot_of_a_wall_closed_form():
    # A point on the floor at distance a from an infinitely long wall of height h. Under the
    # cosine-weighted density the direction is Malley's (x, y, sqrt(1 - x^2 - y^2)) with
    # (x, y) uniform in the unit disk. The wall x = -a is hit iff the direction's projection
    # onto the xz plane makes an angle beta with the normal (tan beta = x / z) below
    # -atan(a/h). For fixed y, x is uniform on the chord [-r, r] (r = sqrt(1 - y^2)) and
    # x / sqrt(r^2 - x^2) = tan(beta) means x = r sin(beta): P(beta <= b) = (1 + sin b) / 2
    # whatever y. So the blocked fraction is (1 + sin(-atan(a/h))) / 2 = (1 - a/sqrt(a^2+h^2))/2
    # and AO = (1 + a / sqrt(a^2 + h^2)) / 2.
    a, h = 1.0, 2.0
    expected = (1 + a / np.sqrt(a**2 + h**2)) / 2
    scene = np.concatenate([floor_scene(), wall_x(-a, h)])
    ao = S.ambient_occlusion([0.0, 0.0, 0.0], [0, 0, 1], scene, samples=40_000, seed=11)
    assert within(ao, expected), (ao.visibility, expected)
    assert S.ambient_occlusion_closed_form("wall", a, h) == pytest.approx(expected, abs=1e-15)


def test_ao_in_a_trench_and_in_the_corner_of_a_box():
    # trench: two such walls at x = -a and x = +a: AO = 1 - 2 (1 - a/sqrt(a^2+h^2))/2
    a, h = 0.5, 1.5
    expected = a / np.sqrt(a**2 + h**2)
    scene = np.concatenate([floor_scene(), wall_x(-a, h), wall_x(a, h)])
    pts = np.array([[0.0, 0.0, 0.0], [0.0, 7.0, 0.0]])
    ao = S.ambient_occlusion(pts, [0, 0, 1], scene, samples=30_000, seed=12)
    assert within(ao, expected), (ao.visibility, expected)
    assert S.ambient_occlusion_closed_form("trench", a, h) == pytest.approx(expected)
    # corner: floor z = 0 and the infinitely high walls x = -1 and y = -2 (three mutually
    # perpendicular planes). A ray with dx < 0 reaches x = -1 at some height and so hits the
    # wall; likewise dy < 0. Only dx > 0 and dy > 0 escape: a quarter of the uniform disk of
    # Malley's method, AO = 1/4, whatever the distances to the walls.
    corner = np.concatenate([floor_scene(), wall_x(-1.0, BIG),
                             np.array(quad([-BIG, -2, 0], [BIG, -2, 0], [BIG, -2, BIG],
                                           [-BIG, -2, BIG]))])
    ao = S.ambient_occlusion([0.0, 0.0, 0.0], [0, 0, 1], corner, samples=40_000, seed=13)
    assert within(ao, 0.25), ao.visibility
    assert S.ambient_occlusion_closed_form("corner") == 0.25


def test_ao_under_a_ceiling_with_a_maximum_distance():
    # ceiling at height h: a ray at angle theta hits it at distance h / cos(theta); counted
    # only within D, i.e. blocked iff cos(theta) >= h / D. cos(theta) has density 2 cos, so
    # P(cos >= c) = 1 - c^2 and AO = (h / D)^2.
    h, big_d = 1.0, 2.5
    ceiling = np.array(quad([-BIG, -BIG, h], [BIG, -BIG, h], [BIG, BIG, h], [-BIG, BIG, h]))
    pts = np.column_stack([np.linspace(-3, 3, 5), np.zeros(5), np.zeros(5)])
    ao = S.ambient_occlusion(pts, [0, 0, 1], ceiling, samples=20_000, seed=14,
                             max_distance=big_d)
    assert within(ao, (h / big_d) ** 2), ao.visibility
    unlimited = S.ambient_occlusion(pts, [0, 0, 1], ceiling, samples=1000, seed=14)
    assert np.all(unlimited.visibility == 0.0)
    assert S.ambient_occlusion_closed_form("ceiling", height=h,
                                           max_distance=big_d) == pytest.approx(0.16)


def test_ao_error_shrinks_like_one_over_sqrt_k():
    corner = np.concatenate([floor_scene(), wall_x(-1.0, BIG),
                             np.array(quad([-BIG, -1, 0], [BIG, -1, 0], [BIG, -1, BIG],
                                           [-BIG, -1, BIG]))])
    gen = rng(15)
    pts = np.column_stack([gen.uniform(0, 3, (300, 2)), np.zeros(300)])   # all have AO = 1/4
    bvh = visibility.BVH(corner)
    ks = [16, 64, 256, 1024]
    rms = []
    for k in ks:
        ao = S.ambient_occlusion(pts, [0, 0, 1], bvh, samples=k, seed=k)
        rms.append(np.sqrt(np.mean((ao.visibility - 0.25) ** 2)))
    slope = np.polyfit(np.log(ks), np.log(rms), 1)[0]
    assert -0.6 < slope < -0.4, slope
    predicted = np.sqrt(0.25 * 0.75 / np.array(ks))            # the Bernoulli standard error
    np.testing.assert_allclose(rms, predicted, rtol=0.2)


def test_ao_is_seeded_and_brute_force_equals_bvh():
    from course_lib import shapes

    v, f = shapes.torus(major=1.0, minor=0.4, segments=16, rings=8)
    scene = np.concatenate([v[f], floor_scene() - [0, 0, 0.4]])
    gen = rng(16)
    pts = np.column_stack([gen.uniform(-2, 2, (30, 2)), np.full(30, -0.4)])
    a = S.ambient_occlusion(pts, [0, 0, 1], scene, samples=32, seed=5)
    b = S.ambient_occlusion(pts, [0, 0, 1], scene, samples=32, seed=5, accelerate=False)
    np.testing.assert_array_equal(a.visibility, b.visibility)
    assert a.triangle_tests < b.triangle_tests == 30 * 32 * len(scene)
    c = S.ambient_occlusion(pts, [0, 0, 1], scene, samples=32, seed=np.random.default_rng(5))
    np.testing.assert_array_equal(a.visibility, c.visibility)
    d = S.ambient_occlusion(pts, [0, 0, 1], scene, samples=32, seed=6)
    assert np.any(a.visibility != d.visibility)
    assert a.visibility.min() < 1 and np.all((0 <= a.visibility) & (a.visibility <= 1))


def test_ao_over_a_height_field():
    flat = S.HeightField(np.zeros((12, 9)), (-1, 1, -2, 2))
    pts, nrm = flat.points().reshape(-1, 3), flat.normals().reshape(-1, 3)
    assert np.all(S.ambient_occlusion(pts, nrm, height_field=flat, samples=32,
                                      seed=0).visibility == 1.0)
    # a step of height 2 for x <= -1: its face is the slope between the grid columns at
    # x = -1 and x = -1 + dx, so the wall stands at a distance between 1 - dx and 1: the AO of
    # the point at the origin lies between the closed forms for those two distances
    x = np.linspace(-4, 4, 161)
    dx = x[1] - x[0]
    heights = np.zeros((3, 161))
    heights[:, x <= -1] = 2.0
    field = S.HeightField(heights, (-4, 4, -1000, 1000))         # long in y: "infinite"
    ao = S.ambient_occlusion([0.0, 0.0, 0.0], [0, 0, 1], height_field=field, samples=20_000,
                             seed=17)
    low = (1 + (1 - dx) / np.hypot(1 - dx, 2)) / 2
    high = (1 + 1 / np.hypot(1, 2)) / 2
    sigma = 0.5 / np.sqrt(20_000)
    assert low - 4 * sigma <= ao.visibility <= high + 4 * sigma, (low, ao.visibility, high)
    np.testing.assert_allclose(field.height([-1.0 + dx / 2, 0.5], [3.0, 0.0]), [1.0, 0.0])


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

def test_bad_vectors_and_coefficients():
    light = S.directional_light([0, 0, 1])
    with pytest.raises(ValueError, match="normals must not contain zero vectors"):
        S.phong(None, [[0, 0, 1], [0, 0, 0]], [0, 0, 1], light)
    with pytest.raises(ValueError, match="view must not contain zero"):
        S.phong(None, [0, 0, 1], [0, 0, 0], light)
    with pytest.raises(ValueError, match="normals must be finite"):
        S.phong(None, [0, np.nan, 1], [0, 0, 1], light)
    with pytest.raises(ValueError, match="points must be finite"):
        S.phong([np.inf, 0, 0], [0, 0, 1], [0, 0, 1], light)
    with pytest.raises(ValueError, match="shininess must be positive"):
        S.phong(None, [0, 0, 1], [0, 0, 1], light, S.Material(shininess=0))
    for field in ("ka", "kd", "ks"):
        with pytest.raises(ValueError, match=rf"{field} must lie in \[0, 1\]"):
            S.phong(None, [0, 0, 1], [0, 0, 1], light, S.Material(**{field: 1.5}))
        with pytest.raises(ValueError, match=rf"{field} must lie in \[0, 1\]"):
            S.phong(None, [0, 0, 1], [0, 0, 1], light, S.Material(**{field: (0.5, -0.1, 0)}))
    with pytest.raises(ValueError, match="kd must be finite"):
        S.phong(None, [0, 0, 1], [0, 0, 1], light, S.Material(kd=np.nan))
    with pytest.raises(ValueError, match="points are needed"):
        S.phong(None, [0, 0, 1], [0, 0, 1], S.point_light([0, 0, 1]))
    with pytest.raises(ValueError, match="coincides with point light"):
        S.phong([0, 0, 1], [0, 0, 1], [0, 0, 1], S.point_light([0, 0, 1]))
    with pytest.raises(ValueError, match="light_visibility"):
        S.phong(None, [0, 0, 1], [0, 0, 1], light, light_visibility=[1, 1])
    with pytest.raises(ValueError, match="normals holds a stack"):
        S.phong(None, np.ones((3, 3)), np.ones((2, 3)), light)
    with pytest.raises(TypeError, match="lights"):
        S.phong(None, [0, 0, 1], [0, 0, 1], [[0, 0, 1]])
    with pytest.raises(ValueError, match="towards must not contain zero"):
        S.directional_light([0, 0, 0])
    with pytest.raises(ValueError, match="attenuation"):
        S.point_light([0, 0, 1], attenuation=(0, 0, 0))
    with pytest.raises(ValueError, match="intensity"):
        S.point_light([0, 0, 1], intensity=-1)
    with pytest.raises(ValueError, match="n must not contain zero"):
        S.reflect([1, 0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="opposite"):
        S.halfway([1, 0, 0], [-2, 0, 0])


# --- rasterize once, shade many times ----------------------------------------------------------

@pytest.mark.parametrize("projection", ["perspective", "orthographic"])
def test_barycentric_weights_interpolate_to_the_point_seen_at_the_pixel_centre(projection):
    v, f = S.uv_sphere(segments=10, rings=5)
    view = viewing.look_at([0.5, 0.3, 4], [-0.1, -0.05, -1], [0, 1, 0])
    proj = (viewing.perspective(np.radians(35), 1.5, 1.0, 10.0) if projection == "perspective"
            else viewing.orthographic(-1.5, 1.5, -1, 1, 1, 10))
    width, height = 24, 16
    buffers = S.barycentric_buffers(v, f, view, proj, width, height)
    seen = buffers.ids >= 0
    assert seen.sum() > 100 and (buffers.weights[~seen] == 0).all()
    w = buffers.weights[seen]
    assert (w >= -1e-9).all() and np.allclose(w.sum(axis=1), 1)
    # the interpolated point lies in its face and projects onto the pixel centre
    points = np.einsum("pk,pkc->pc", w, v[f[buffers.ids[seen]]])
    clip = np.column_stack([points, np.ones(len(points))]) @ (proj @ view).T
    ndc = clip[:, :3] / clip[:, 3:]
    rows, cols = np.nonzero(seen)
    np.testing.assert_allclose(ndc[:, 0], (cols + 0.5) / width * 2 - 1, atol=1e-9)
    np.testing.assert_allclose(ndc[:, 1], (rows + 0.5) / height * 2 - 1, atol=1e-9)
    np.testing.assert_allclose(buffers.depth[seen], (ndc[:, 2] + 1) / 2, atol=1e-9)
    # the same visible faces as the plain z-buffer
    zb = visibility.render_depth(v, f, view, proj, width, height)
    np.testing.assert_array_equal(buffers.ids, zb.ids)


@pytest.mark.parametrize("model", ["phong", "blinn"])
@pytest.mark.parametrize("cull", [False, True])
def test_render_shaded_on_cached_fragments_equals_a_fresh_render(model, cull):
    v, f = S.uv_sphere(segments=14, rings=7)
    view = viewing.look_at([0, 0.5, 4], [0, -0.12, -1], [0, 1, 0])
    proj = viewing.perspective(np.radians(40), 1.0, 1.0, 10.0)
    buffers = S.barycentric_buffers(v, f, view, proj, 40, 40, cull_back_faces=cull)
    m = S.Material(ka=0.1, kd=0.6, ks=0.5, shininess=30)
    for light in (S.directional_light([1, 1, 1]), S.point_light([2, 3, 4], intensity=1.5)):
        for shading in ("flat", "gouraud", "phong"):
            for normals in (None, v):
                args = (v, f, view, proj, 40, 40, light, m)
                kwargs = dict(shading=shading, model=model, normals=normals, background=0.3,
                              cull_back_faces=cull)
                fresh = S.render_shaded(*args, **kwargs)
                cached = S.render_shaded(*args, **kwargs, fragments=buffers)
                np.testing.assert_array_equal(cached.ids, fresh.ids)
                np.testing.assert_allclose(cached.image, fresh.image, atol=1e-12)
                np.testing.assert_allclose(cached.depth, fresh.depth, atol=1e-12)


def test_render_shaded_rejects_fragments_of_another_size():
    v, f = S.uv_sphere(segments=8, rings=4)
    view = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    proj = viewing.perspective(1.0, 1.0, 1.0, 10.0)
    light = S.directional_light([0, 0, 1])
    buffers = S.barycentric_buffers(v, f, view, proj, 8, 6)
    with pytest.raises(ValueError, match="fragments must be the BarycentricBuffers"):
        S.render_shaded(v, f, view, proj, 6, 8, light, fragments=buffers)
    with pytest.raises(ValueError, match="fragments must be the BarycentricBuffers"):
        S.render_shaded(v, f, view, proj, 8, 6, light, fragments=(buffers.ids,))
    with pytest.raises(ValueError, match="faces refers to vertex"):
        S.barycentric_buffers(v, f + 100, view, proj, 8, 6)


def test_bad_meshes_and_occlusion_arguments():
    v, f = S.uv_sphere(segments=8, rings=4)
    view = viewing.look_at([0, 0, 4], [0, 0, -1], [0, 1, 0])
    proj = viewing.perspective(1.0, 1.0, 1.0, 10.0)
    light = S.directional_light([0, 0, 1])
    with pytest.raises(ValueError, match="shading must be"):
        S.render_shaded(v, f, view, proj, 8, 8, light, shading="smooth")
    with pytest.raises(ValueError, match="model must be"):
        S.render_shaded(v, f, view, proj, 8, 8, light, model="cook-torrance")
    with pytest.raises(ValueError, match="faces refers to vertex"):
        S.vertex_normals(v, f + 100)
    with pytest.raises(ValueError, match="normals must hold one normal per vertex"):
        S.render_shaded(v, f, view, proj, 8, 8, light, normals=v[:3])
    with pytest.raises(ValueError, match="samples must be a whole number"):
        S.ambient_occlusion([0, 0, 0], [0, 0, 1], samples=0)
    with pytest.raises(ValueError, match="max_distance must be positive"):
        S.ambient_occlusion([0, 0, 0], [0, 0, 1], max_distance=0)
    with pytest.raises(ValueError, match="normals must not contain zero"):
        S.ambient_occlusion([0, 0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="scene must be triangles"):
        S.ambient_occlusion([0, 0, 0], [0, 0, 1], np.zeros((2, 4, 3)))
    with pytest.raises(ValueError, match="heights"):
        S.ambient_occlusion([0, 0, 0], [0, 0, 1],
                            height_field=S.HeightField(np.zeros(4), (0, 1, 0, 1)))
    with pytest.raises(ValueError, match="kind must be"):
        S.ambient_occlusion_closed_form("sphere")
