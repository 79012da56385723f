"""Tests of course_lib.viewing (look_at, frustum, perspective, orthographic, the textbook's simple
projections, viewport, to_screen, cross_ratio).

Expected values come from independent implementations (PyGLM, VTK), from closed forms typed out
below, or from mathematical properties. Nothing here is copied from the output of the code under
test.

Conventions of the references, worked out once:

* PyGLM (GLM) matrices are column-major: ``m[c][r]``, and ``m.to_list()`` is the list of
  columns, so ``np.array(m.to_list()).T`` is the usual row-major matrix (column vectors,
  p' = M p), which is what ``course_lib`` returns. ``glm.lookAt(eye, center, up)`` takes a
  *target point*, ours a *direction*: center = eye + gaze. ``glm.perspective`` takes the vertical
  field of view in radians, ``glm.frustum`` and ``glm.ortho`` take positive near/far distances and
  map them to NDC z = -1 / +1 (the ``RH_NO`` variants: right-handed eye space, depth range
  "negative one to one"), exactly our convention.
  Precision: ``glm.lookAt`` has a double overload (dvec3 arguments -> dmat4x4, checked to 1e-12),
  but in the installed PyGLM (2.8.3) ``perspective``, ``frustum`` and ``ortho`` only exist in
  single precision (any Python/numpy float gives a float32 ``mat4x4``; there is no double
  overload). For these three we round the parameters to float32 first, so that both sides start
  from the same numbers, and allow a relative error of 1e-6 (float32 has ~6e-8; a handful of
  operations). The double-precision check of the same matrices is done against VTK instead.
* VTK: ``vtkCamera`` with position E, focal point E + gaze, view up U. Its view transform
  (``GetModelViewTransformMatrix``, model transform = identity) is gluLookAt's: the direction of
  projection maps to -z, the view up (made perpendicular) to +y, the camera position to the
  origin; that is our look_at. ``GetProjectionTransformMatrix(aspect, -1, 1)`` is glFrustum's
  matrix with ``ymax = near tan(view_angle / 2)``, ``xmax = aspect ymax`` (the view angle is
  *vertical* by default and in *degrees*), the clipping range (near, far) being positive
  distances along the direction of projection, and the last two arguments the NDC depth of the
  near and far planes (-1 and +1: OpenGL's). VTK's 4x4 matrices are row-major for column vectors
  (``GetElement(i, j)`` = row i, column j), like ours. ``vtkPerspectiveTransform.Frustum`` and
  ``.Ortho`` are glFrustum / glOrtho in double precision.
"""
import numpy as np
import pytest
import vtk
from pyglm import glm           # "import glm" works too but is deprecated

from course_lib import viewing as V

PI = np.pi
ATOL = 1e-12


# ---------------------------------------------------------------------------------------------
# helpers (independent of the code under test)
# ---------------------------------------------------------------------------------------------

def rng(seed):
    return np.random.default_rng(seed)


def hdiv(m, points):
    """Apply a 4x4 matrix to points (rows), divide by w: written out here, not transforms.apply."""
    p = np.atleast_2d(np.asarray(points, dtype=float))
    h = np.concatenate([p, np.ones((len(p), 1))], axis=1) @ np.asarray(m, dtype=float).T
    return h[:, :3] / h[:, 3:]


def glm_np(m):
    """PyGLM matrix (column-major) -> row-major numpy array."""
    return np.array(m.to_list(), dtype=float).T


def vtk_np(m):
    return np.array([[m.GetElement(i, j) for j in range(4)] for i in range(4)])


def f32(x):
    return float(np.float32(x))


def random_camera(gen):
    """eye, gaze (any length), up (any length, not within ~3 degrees of +-gaze)."""
    while True:
        eye = gen.uniform(-10, 10, 3)
        gaze = gen.normal(size=3) * gen.uniform(0.1, 10)
        up = gen.normal(size=3) * gen.uniform(0.1, 10)
        s = np.linalg.norm(np.cross(gaze, up)) / (np.linalg.norm(gaze) * np.linalg.norm(up))
        if s > 0.05:
            return eye, gaze, up


def random_frustum(gen):
    """An asymmetric window (l < r, b < t, possibly not containing 0) and 0 < near < far."""
    l, r = np.sort(gen.uniform(-3, 3, 2))
    b, t = np.sort(gen.uniform(-3, 3, 2))
    r, t = r + 0.05, t + 0.05                       # some width and height
    n = gen.uniform(0.05, 5)
    f = n + gen.uniform(0.1, 200)
    return l, r, b, t, n, f


def cube_corners():
    return np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], dtype=float)


def frustum_corners(l, r, b, t, n, f):
    """Eye-space corners of a frustum in the order of cube_corners() (near first, then far):
    the near window at z = -n, the far one at z = -f, scaled by f / n (similar triangles)."""
    near = [[x, y, -n] for y in (b, t) for x in (l, r)]
    far = [[x * f / n, y * f / n, -f] for y in (b, t) for x in (l, r)]
    return np.array(near + far, dtype=float)


def collinear(points, rtol=1e-9):
    """Whether 3D points lie on one line: all cross products with the first direction ~ 0."""
    p = np.asarray(points, dtype=float)
    d = p[-1] - p[0]
    cr = np.cross(p - p[0], d)
    scale = np.linalg.norm(d) * np.abs(p - p[0]).max()
    return np.abs(cr).max() <= rtol * max(scale, 1e-300)


def cross_ratio_params(a, b, c, d):
    """(A, B; C, D) for points at parameters a, b, c, d on a line: AC * BD / (BC * AD)."""
    return (c - a) * (d - b) / ((c - b) * (d - a))


# ---------------------------------------------------------------------------------------------
# matrices against PyGLM
# ---------------------------------------------------------------------------------------------

def test_look_at_matches_pyglm_lookat_in_double_precision():
    gen = rng(1)
    for _ in range(300):
        eye, gaze, up = random_camera(gen)
        expected = glm.lookAt(glm.dvec3(*eye), glm.dvec3(*(eye + gaze)), glm.dvec3(*up))
        assert isinstance(expected, glm.dmat4x4)              # really float64
        np.testing.assert_allclose(V.look_at(eye, gaze, up), glm_np(expected), rtol=0, atol=1e-12)


def test_perspective_matches_pyglm_perspective_float32():
    gen = rng(2)
    for _ in range(300):
        fov = f32(gen.uniform(0.05, PI - 0.05))
        aspect, n = f32(gen.uniform(0.2, 5)), f32(gen.uniform(0.05, 5))
        f = f32(n + gen.uniform(0.1, 200))
        expected = glm_np(glm.perspective(fov, aspect, n, f))    # float32 only: see module doc
        got = V.perspective(fov, aspect, n, f)
        np.testing.assert_allclose(got, expected, rtol=1e-6, atol=1e-6 * np.abs(expected).max())


def test_frustum_matches_pyglm_frustum_float32():
    gen = rng(3)
    for _ in range(300):
        params = [f32(x) for x in random_frustum(gen)]
        expected = glm_np(glm.frustum(*params))
        got = V.frustum(*params)
        np.testing.assert_allclose(got, expected, rtol=1e-6, atol=1e-6 * np.abs(expected).max())


def test_orthographic_matches_pyglm_ortho_float32():
    gen = rng(4)
    for _ in range(300):
        params = [f32(x) for x in random_frustum(gen)]
        expected = glm_np(glm.ortho(*params))
        got = V.orthographic(*params)
        np.testing.assert_allclose(got, expected, rtol=1e-6, atol=1e-6 * np.abs(expected).max())


# ---------------------------------------------------------------------------------------------
# matrices against VTK (double precision)
# ---------------------------------------------------------------------------------------------

def test_look_at_and_perspective_match_vtk_camera():
    gen = rng(5)
    for _ in range(300):
        eye, gaze, up = random_camera(gen)
        fov_deg = gen.uniform(1, 179)
        aspect = gen.uniform(0.2, 5)
        n = gen.uniform(0.05, 5)
        f = n + gen.uniform(0.1, 200)
        cam = vtk.vtkCamera()
        cam.SetPosition(*eye)
        cam.SetFocalPoint(*(eye + gaze))
        cam.SetViewUp(*up)
        cam.SetViewAngle(fov_deg)                    # vertical, degrees
        cam.SetClippingRange(n, f)
        np.testing.assert_allclose(cam.GetClippingRange(), (n, f), rtol=1e-15)   # not clamped
        view = vtk_np(cam.GetModelViewTransformMatrix())
        proj = vtk_np(cam.GetProjectionTransformMatrix(aspect, -1, 1))
        np.testing.assert_allclose(V.look_at(eye, gaze, up), view, rtol=0, atol=1e-12)
        np.testing.assert_allclose(V.perspective(np.radians(fov_deg), aspect, n, f), proj,
                                   rtol=1e-12, atol=1e-12 * np.abs(proj).max())


def test_frustum_and_orthographic_match_vtk_perspective_transform():
    gen = rng(6)
    for _ in range(300):
        l, r, b, t, n, f = random_frustum(gen)
        tf = vtk.vtkPerspectiveTransform()
        tf.Frustum(l, r, b, t, n, f)
        expected = vtk_np(tf.GetMatrix())
        np.testing.assert_allclose(V.frustum(l, r, b, t, n, f), expected,
                                   rtol=1e-12, atol=1e-12 * np.abs(expected).max())
        tf = vtk.vtkPerspectiveTransform()
        tf.Ortho(l, r, b, t, n, f)
        expected = vtk_np(tf.GetMatrix())
        np.testing.assert_allclose(V.orthographic(l, r, b, t, n, f), expected,
                                   rtol=1e-12, atol=1e-12 * np.abs(expected).max())


# ---------------------------------------------------------------------------------------------
# the view volumes land on the canonical cube
# ---------------------------------------------------------------------------------------------

def test_frustum_corners_land_on_cube_corners():
    gen = rng(10)
    for _ in range(300):
        l, r, b, t, n, f = random_frustum(gen)
        got = hdiv(V.frustum(l, r, b, t, n, f), frustum_corners(l, r, b, t, n, f))
        np.testing.assert_allclose(got, cube_corners(), rtol=0, atol=1e-12)


def test_perspective_corners_land_on_cube_corners():
    gen = rng(11)
    for _ in range(300):
        fov, aspect = gen.uniform(0.05, PI - 0.05), gen.uniform(0.2, 5)
        n = gen.uniform(0.05, 5)
        f = n + gen.uniform(0.1, 200)
        t = n * np.tan(fov / 2)                     # half height of the near window
        corners = frustum_corners(-aspect * t, aspect * t, -t, t, n, f)
        got = hdiv(V.perspective(fov, aspect, n, f), corners)
        np.testing.assert_allclose(got, cube_corners(), rtol=0, atol=1e-12)


def test_orthographic_corners_land_on_cube_corners():
    gen = rng(12)
    for _ in range(300):
        l, r, b, t, n, f = random_frustum(gen)
        corners = np.array([[x, y, z] for z in (-n, -f) for y in (b, t) for x in (l, r)])
        got = hdiv(V.orthographic(l, r, b, t, n, f), corners)
        np.testing.assert_allclose(got, cube_corners(), rtol=0, atol=1e-12)


def _in_cube(ndc, margin=0.0):
    return np.all(np.abs(ndc) <= 1 - margin, axis=-1)


def _away_from_cube_boundary(ndc, margin=1e-6):
    return np.all(np.abs(np.abs(ndc) - 1) > margin, axis=-1)


def test_points_inside_the_frustum_map_inside_the_cube_and_outside_outside():
    gen = rng(13)
    total_in = total_out = 0
    for _ in range(100):
        l, r, b, t, n, f = random_frustum(gen)
        depth = gen.uniform(0.5 * n, 1.2 * f, 400)             # distance in front of the eye
        # window coordinates on the near plane, beyond the window on every side sometimes
        wx = gen.uniform(l - 0.5 * (r - l), r + 0.5 * (r - l), 400)
        wy = gen.uniform(b - 0.5 * (t - b), t + 0.5 * (t - b), 400)
        pts = np.column_stack([wx * depth / n, wy * depth / n, -depth])
        inside = (l <= wx) & (wx <= r) & (b <= wy) & (wy <= t) & (n <= depth) & (depth <= f)
        ndc = hdiv(V.frustum(l, r, b, t, n, f), pts)
        keep = _away_from_cube_boundary(ndc)
        np.testing.assert_array_equal(_in_cube(ndc)[keep], inside[keep])
        total_in += inside[keep].sum()
        total_out += (~inside[keep]).sum()
    assert total_in > 1000 and total_out > 1000              # both cases really exercised


def test_points_inside_the_ortho_box_map_inside_the_cube_and_outside_outside():
    gen = rng(14)
    total_in = total_out = 0
    for _ in range(100):
        l, r, b, t, n, f = random_frustum(gen)
        w, h, d = r - l, t - b, f - n
        pts = np.column_stack([gen.uniform(l - w / 2, r + w / 2, 400),
                               gen.uniform(b - h / 2, t + h / 2, 400),
                               gen.uniform(-f - d / 2, -n + d / 2, 400)])
        inside = ((l <= pts[:, 0]) & (pts[:, 0] <= r) & (b <= pts[:, 1]) & (pts[:, 1] <= t)
                  & (-f <= pts[:, 2]) & (pts[:, 2] <= -n))
        ndc = hdiv(V.orthographic(l, r, b, t, n, f), pts)
        keep = _away_from_cube_boundary(ndc)
        np.testing.assert_array_equal(_in_cube(ndc)[keep], inside[keep])
        total_in += inside[keep].sum()
        total_out += (~inside[keep]).sum()
    assert total_in > 1000 and total_out > 1000


def test_depth_is_monotonic_near_to_far():
    # CSS depth grows away from the viewer (near -> -1, far -> +1): strictly increasing in -z_e
    gen = rng(15)
    for _ in range(50):
        l, r, b, t, n, f = random_frustum(gen)
        depth = np.sort(gen.uniform(n, f, 50))
        for m in (V.frustum(l, r, b, t, n, f), V.orthographic(l, r, b, t, n, f)):
            z = hdiv(m, np.column_stack([np.zeros(50), np.zeros(50), -depth]))[:, 2]
            assert np.all(np.diff(z) > 0)


# ---------------------------------------------------------------------------------------------
# look_at: properties
# ---------------------------------------------------------------------------------------------

def test_look_at_geometric_properties():
    gen = rng(20)
    for _ in range(300):
        eye, gaze, up = random_camera(gen)
        m = V.look_at(eye, gaze, up)
        np.testing.assert_allclose(hdiv(m, eye)[0], [0, 0, 0], atol=1e-12)
        # eye + gaze is |gaze| in front of the eye, on the -z axis
        np.testing.assert_allclose(hdiv(m, eye + gaze)[0], [0, 0, -np.linalg.norm(gaze)],
                                   atol=1e-12)
        # up (made perpendicular to gaze) points up in the picture: x = 0, y > 0
        up_image = hdiv(m, eye + up)[0]
        assert abs(up_image[0]) <= 1e-12 and up_image[1] > 0
        r = m[:3, :3]
        np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-12)
        assert np.linalg.det(r) == pytest.approx(1.0, abs=1e-12)
        np.testing.assert_array_equal(m[3], [0, 0, 0, 1])
        # distances are kept (a rigid motion)
        p, q = gen.normal(size=(2, 3)) * 5
        img = hdiv(m, [p, q])
        assert np.linalg.norm(img[0] - img[1]) == pytest.approx(np.linalg.norm(p - q), rel=1e-12)


def test_look_at_closed_form_textbook_camera():
    # eye on +z looking at the origin, y up: a pure translation by -eye
    np.testing.assert_allclose(V.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0]),
                               [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -5], [0, 0, 0, 1]],
                               atol=ATOL)
    # eye on +x looking along -x, z up: x_e = up x z_e = z x x = y, y_e = z_e x x_e = z
    np.testing.assert_allclose(V.look_at([3, 0, 0], [-2, 0, 0], [0, 0, 7]),
                               [[0, 1, 0, 0], [0, 0, 1, 0], [1, 0, 0, -3], [0, 0, 0, 1]],
                               atol=ATOL)


def test_look_at_up_not_perpendicular_to_gaze():
    # only up's component perpendicular to gaze matters: up and up + k gaze give the same matrix
    gen = rng(21)
    for _ in range(100):
        eye, gaze, up = random_camera(gen)
        k = gen.uniform(-3, 3)
        np.testing.assert_allclose(V.look_at(eye, gaze, up + k * gaze), V.look_at(eye, gaze, up),
                                   atol=1e-10)
        np.testing.assert_allclose(V.look_at(eye, gaze, 7.5 * up), V.look_at(eye, gaze, up),
                                   atol=1e-12)


@pytest.mark.parametrize("gaze, up, name", [
    ([0, 0, -1], [0, 0, 3], "up"),          # antiparallel
    ([0, 0, -1], [0, 0, -2], "up"),         # parallel
    ([1, 2, 3], [-2, -4, -6], "up"),
    ([0, 0, 0], [0, 1, 0], "gaze"),
    ([0, 0, -1], [0, 0, 0], "up"),
])
def test_look_at_degenerate_cameras_raise(gaze, up, name):
    with pytest.raises(ValueError, match=rf"\b{name}\b"):
        V.look_at([1, 2, 3], gaze, up)


# ---------------------------------------------------------------------------------------------
# the textbook's simple projections, viewport, to_screen
# ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("d", [1.0, 2.5, -3.0, 0.01])
def test_simple_perspective_closed_form(d):
    gen = rng(30)
    pts = gen.uniform(-10, 10, (500, 3))
    pts = pts[np.abs(pts[:, 2]) > 0.1]
    x, y, z = pts.T
    expected = np.column_stack([x * d / z, y * d / z, np.full_like(x, d)])
    np.testing.assert_allclose(hdiv(V.simple_perspective(d), pts), expected, rtol=1e-12,
                               atol=1e-12)
    # every point of a ray through the centre of projection has the same image
    k = gen.uniform(-5, 5, (len(pts), 1))
    k[np.abs(k) < 0.1] = 1.0
    np.testing.assert_allclose(hdiv(V.simple_perspective(d), k * pts), expected, rtol=1e-12,
                               atol=1e-12)


def test_simple_perspective_matrix_closed_form():
    np.testing.assert_array_equal(V.simple_perspective(2.0),
                                  [[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 1, 0]])


def test_oblique_slides_points_along_dop_to_z0():
    gen = rng(31)
    for _ in range(200):
        dop = gen.normal(size=3)
        if abs(dop[2]) < 0.05:
            continue
        pts = gen.uniform(-10, 10, (50, 3))
        # closed form: p - (z / dop_z) dop, which has z = 0
        expected = pts - (pts[:, 2] / dop[2])[:, None] * dop
        got = hdiv(V.oblique(dop), pts)
        np.testing.assert_allclose(got, expected, rtol=1e-12, atol=1e-11)
        np.testing.assert_array_equal(got[:, 2], 0.0)
        # the image minus the point is parallel to dop (it slid along dop)
        np.testing.assert_allclose(np.cross(got - pts, dop), 0, atol=1e-10)
        # keep_depth: same x, y, z kept
        kept = hdiv(V.oblique(dop, keep_depth=True), pts)
        np.testing.assert_allclose(kept[:, :2], expected[:, :2], rtol=1e-12, atol=1e-11)
        np.testing.assert_array_equal(kept[:, 2], pts[:, 2])


def test_oblique_cavalier_and_cabinet_closed_forms():
    # cavalier: dop at 45 degrees to the plane, depth drawn at full length
    a = np.radians(30)                        # direction of the receding axis in the picture
    cav = hdiv(V.oblique([np.cos(a), np.sin(a), -1.0]), [[0, 0, -1]])[0]
    assert np.hypot(*cav[:2]) == pytest.approx(1.0, abs=1e-12)
    cab = hdiv(V.oblique([np.cos(a) / 2, np.sin(a) / 2, -1.0]), [[0, 0, -1]])[0]
    assert np.hypot(*cab[:2]) == pytest.approx(0.5, abs=1e-12)


@pytest.mark.parametrize("dop", [[0, 0, 1], [0, 0, -1], [0, 0, 3.5]])
def test_oblique_along_z_is_orthographic_xy(dop):
    np.testing.assert_array_equal(V.oblique(dop), V.orthographic_xy())
    np.testing.assert_array_equal(V.orthographic_xy(), np.diag([1.0, 1.0, 0.0, 1.0]))


def test_viewport_maps_cube_corners_and_centre():
    gen = rng(32)
    for _ in range(200):
        x0, x1 = np.sort(gen.uniform(-500, 2000, 2))
        y0, y1 = np.sort(gen.uniform(-500, 2000, 2))
        z0, z1 = np.sort(gen.uniform(-2, 2, 2))
        m = V.viewport(x0, y0, x1, y1, z0, z1)
        cube = cube_corners()
        expected = np.column_stack([np.where(cube[:, 0] < 0, x0, x1),
                                    np.where(cube[:, 1] < 0, y0, y1),
                                    np.where(cube[:, 2] < 0, z0, z1)])
        np.testing.assert_allclose(hdiv(m, cube), expected, rtol=1e-12, atol=1e-9)
        np.testing.assert_allclose(hdiv(m, [0, 0, 0])[0], [(x0 + x1) / 2, (y0 + y1) / 2,
                                                           (z0 + z1) / 2], rtol=1e-12, atol=1e-9)


def test_viewport_default_depth_range_is_0_1():
    np.testing.assert_allclose(hdiv(V.viewport(0, 0, 640, 480), [[-1, -1, -1], [1, 1, 1]]),
                               [[0, 0, 0], [640, 480, 1]], atol=ATOL)


def test_to_screen_is_the_three_steps():
    gen = rng(33)
    for _ in range(100):
        eye, gaze, up = random_camera(gen)
        view = V.look_at(eye, gaze, up)
        proj = V.perspective(gen.uniform(0.2, 2.5), gen.uniform(0.5, 2), 0.1, 100)
        vp = V.viewport(0, 0, 800, 600)
        # points in front of the camera (w = distance along gaze > 0)
        g = gaze / np.linalg.norm(gaze)
        pts = eye + gen.uniform(0.5, 50, (100, 1)) * g + gen.normal(size=(100, 3)) * 3
        pts = pts[(pts - eye) @ g > 0.2]
        eye_space = hdiv(view, pts)
        css = hdiv(proj, eye_space)
        expected = hdiv(vp, css)
        np.testing.assert_allclose(V.to_screen(pts, view, proj, vp), expected, rtol=1e-9,
                                   atol=1e-8)


def test_to_screen_point_in_the_plane_of_the_eye_raises():
    view = V.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])
    proj = V.perspective(1.0, 1.0, 1.0, 10.0)
    with pytest.raises(ValueError):
        V.to_screen([1.0, 2.0, 5.0], view, proj, V.viewport(0, 0, 10, 10))


# ---------------------------------------------------------------------------------------------
# the compendium's errors, as executable facts
# ---------------------------------------------------------------------------------------------

def test_compendium_perspective_matrix_misses_the_cube_but_ours_hits_it():
    gen = rng(40)
    misses = 0
    for _ in range(100):
        l, r, b, t, n, f = random_frustum(gen)
        ns, fs = -n, -f                             # the textbook's signed planes
        compendium = np.array([[2 / (r - l), 0, 0, 0],
                               [0, 2 / (t - b), 0, 0],
                               [0, 0, 2 / (fs - ns), -2 * ns * fs / (fs - ns)],
                               [0, 0, 1, 0]])
        corners = frustum_corners(l, r, b, t, n, f)
        wrong = hdiv(compendium, corners)
        misses += np.abs(wrong - cube_corners()).max() > 1e-3
        np.testing.assert_allclose(hdiv(V.frustum(l, r, b, t, n, f), corners), cube_corners(),
                                   atol=1e-12)
    assert misses == 100


def test_compendium_viewport_depth_row_is_wrong_for_non_square_viewports():
    x0, y0, x1, y1, z0, z1 = 0.0, 0.0, 640.0, 480.0, 0.0, 1.0
    compendium = np.array([[(x1 - x0) / 2, 0, 0, (x1 + x0) / 2],
                           [0, (y1 - y0) / 2, 0, (y1 + y0) / 2],
                           [0, 0, (y1 - y0) / 2, (z1 + z0) / 2],
                           [0, 0, 0, 1]])
    ends = [[0, 0, -1], [0, 0, 1]]
    assert not np.allclose(hdiv(compendium, ends)[:, 2], [z0, z1])     # -239.5 and 240.5
    np.testing.assert_allclose(hdiv(V.viewport(x0, y0, x1, y1, z0, z1), ends)[:, 2], [z0, z1],
                               atol=ATOL)


def test_textbook_signed_perspective_is_minus_ours_and_gives_the_same_points():
    gen = rng(41)
    for _ in range(200):
        l, r, b, t, n, f = random_frustum(gen)
        ns, fs = -n, -f
        textbook = np.array([
            [2 * ns / (r - l), 0, -(r + l) / (r - l), 0],
            [0, 2 * ns / (t - b), -(t + b) / (t - b), 0],
            [0, 0, (fs + ns) / (fs - ns), -2 * fs * ns / (fs - ns)],
            [0, 0, 1, 0]])
        ours = V.frustum(l, r, b, t, n, f)
        np.testing.assert_allclose(textbook, -ours, rtol=1e-12, atol=1e-12)
        pts = gen.uniform(-5, 5, (50, 3))
        pts[:, 2] = -gen.uniform(0.1, 50, 50)
        np.testing.assert_allclose(hdiv(textbook, pts), hdiv(ours, pts), rtol=1e-10, atol=1e-10)


def test_textbook_signed_orthographic_third_row():
    gen = rng(42)
    for _ in range(100):
        l, r, b, t, n, f = random_frustum(gen)
        ns, fs = -n, -f
        np.testing.assert_allclose(V.orthographic(l, r, b, t, n, f)[2],
                                   [0, 0, 2 / (fs - ns), -(ns + fs) / (fs - ns)], rtol=1e-12)


# ---------------------------------------------------------------------------------------------
# what affine and projective maps keep
# ---------------------------------------------------------------------------------------------

def random_affine(gen):
    m = np.eye(4)
    while True:
        a = gen.normal(size=(3, 3))
        if abs(np.linalg.det(a)) > 0.1:
            break
    m[:3, :3] = a
    m[:3, 3] = gen.normal(size=3) * 5
    return m


def angle(u, v):
    return np.arccos(np.clip(u @ v / (np.linalg.norm(u) * np.linalg.norm(v)), -1, 1))


def test_affine_maps_keep_ratios_parallels_and_affine_combinations_not_angles_or_lengths():
    gen = rng(50)
    changed_angles = changed_lengths = 0
    for _ in range(200):
        m = random_affine(gen)
        a, b = gen.normal(size=(2, 3)) * 5
        s = gen.uniform(-2, 3, 20)
        line = a + s[:, None] * (b - a)
        img = hdiv(m, line)
        ia, ib = hdiv(m, [a, b])
        # ratios of distances along a line are kept: the image is at the same parameter s
        np.testing.assert_allclose(img, ia + s[:, None] * (ib - ia), rtol=1e-10, atol=1e-10)
        # parallel lines stay parallel
        d = gen.normal(size=3)
        p, q = gen.normal(size=(2, 3)) * 5
        dp = np.subtract(*hdiv(m, [p + d, p]))
        dq = np.subtract(*hdiv(m, [q + 2.5 * d, q]))
        np.testing.assert_allclose(np.cross(dp, dq), 0, atol=1e-9 * np.linalg.norm(dp) ** 2)
        # affine combinations (weights summing to 1) are kept
        pts = gen.normal(size=(5, 3)) * 5
        w = gen.normal(size=5)
        w[-1] = 1 - w[:-1].sum()
        np.testing.assert_allclose(hdiv(m, w @ pts)[0], w @ hdiv(m, pts), rtol=1e-9, atol=1e-9)
        # angles and distances are not kept in general
        u, v = gen.normal(size=(2, 3))
        iu, iv = hdiv(m, [u, v]) - hdiv(m, [0, 0, 0])
        changed_angles += abs(angle(iu, iv) - angle(u, v)) > 1e-6
        changed_lengths += abs(np.linalg.norm(iu) - np.linalg.norm(u)) > 1e-6
    assert changed_angles >= 190 and changed_lengths >= 190


def random_perspective_map(gen):
    eye, gaze, up = random_camera(gen)
    m = V.perspective(gen.uniform(0.3, 2.5), gen.uniform(0.5, 2), gen.uniform(0.1, 1),
                      gen.uniform(20, 100)) @ V.look_at(eye, gaze, up)
    return m, eye, gaze / np.linalg.norm(gaze)


def random_projective_4x4(gen):
    while True:
        m = gen.normal(size=(4, 4))
        m[3] = [gen.normal(), gen.normal(), gen.normal(), 3.0]   # non-trivial last row
        if abs(np.linalg.det(m)) > 0.1:
            return m


def _line_with_positive_w(gen, m, k=6):
    """k points on a random line, all with w > 0.2 (the line does not cross w = 0 between)."""
    while True:
        a, d = gen.normal(size=3) * 5, gen.normal(size=3)
        s = np.sort(gen.uniform(-3, 3, k))
        pts = a + s[:, None] * d
        w = np.concatenate([pts, np.ones((k, 1))], axis=1) @ m[3]
        if np.all(w > 0.2):
            return pts, s, d


@pytest.mark.parametrize("kind", ["camera", "random 4x4"])
def test_projective_maps_keep_lines_and_cross_ratios(kind):
    gen = rng(51 if kind == "camera" else 52)
    for _ in range(200):
        m = random_perspective_map(gen)[0] if kind == "camera" else random_projective_4x4(gen)
        pts, s, _ = _line_with_positive_w(gen, m)
        img = hdiv(m, pts)
        assert collinear(img, rtol=1e-7)
        expected = cross_ratio_params(*s[:4])
        assert V.cross_ratio(*img[:4]) == pytest.approx(expected, rel=1e-6, abs=1e-9)
        assert V.cross_ratio(*pts[:4]) == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("kind", ["camera", "random 4x4"])
def test_projective_maps_do_not_keep_ratios_of_distances(kind):
    gen = rng(53 if kind == "camera" else 54)
    deviation = []
    for _ in range(200):
        m = random_perspective_map(gen)[0] if kind == "camera" else random_projective_4x4(gen)
        pts, _, _ = _line_with_positive_w(gen, m, k=2)
        mid = pts.mean(axis=0)
        ia, ib, im = hdiv(m, [pts[0], pts[1], mid])
        # the image of the midpoint, as a fraction of the way from the image of a to that of b
        frac = (im - ia) @ (ib - ia) / ((ib - ia) @ (ib - ia))
        deviation.append(abs(frac - 0.5))
    deviation = np.array(deviation)
    assert deviation.min() > 1e-9 and np.median(deviation) > 1e-3


@pytest.mark.parametrize("kind", ["camera", "random 4x4"])
def test_parallel_lines_meet_at_the_vanishing_point(kind):
    gen = rng(55 if kind == "camera" else 56)
    not_parallel = 0
    for _ in range(100):
        m = random_perspective_map(gen)[0] if kind == "camera" else random_projective_4x4(gen)
        d = gen.normal(size=3)
        h = m @ np.append(d, 0.0)                  # the image of the point at infinity
        if abs(h[3]) < 1e-3:
            continue                                # direction parallel to the image plane
        vanishing = h[:3] / h[3]
        directions = []
        for _ in range(4):
            while True:
                p = gen.normal(size=3) * 5
                pts = p + np.array([0.0, 1.0])[:, None] * d
                if np.all(np.concatenate([pts, np.ones((2, 1))], axis=1) @ m[3] > 0.2):
                    break
            img = hdiv(m, pts)
            assert collinear(np.vstack([img, vanishing]), rtol=1e-7)
            directions.append(img[1] - img[0])
        u, v = directions[0], directions[1]
        sin = np.linalg.norm(np.cross(u, v)) / (np.linalg.norm(u) * np.linalg.norm(v))
        not_parallel += sin > 1e-6
    assert not_parallel >= 80                      # the images are not parallel in general


def test_cross_ratio_closed_forms():
    assert V.cross_ratio([0, 0], [1, 0], [2, 0], [3, 0]) == pytest.approx(4 / 3, rel=1e-15)
    # harmonic division: (-1, 1; 0, inf)-like, A=-1, B=1, C=1/3, D=3: (4/3)(2) / ((-2/3)(4)) = -1
    assert V.cross_ratio([-1, 0, 0], [1, 0, 0], [1 / 3, 0, 0], [3, 0, 0]) == \
        pytest.approx(-1.0, rel=1e-14)
    gen = rng(57)
    for _ in range(200):
        a, d = gen.normal(size=3) * 3, gen.normal(size=3)
        s = gen.uniform(-5, 5, 4)
        if min(abs(s[2] - s[1]), abs(s[3] - s[0])) < 0.05:
            continue
        pts = a + s[:, None] * d
        assert V.cross_ratio(*pts) == pytest.approx(cross_ratio_params(*s), rel=1e-9)
        # 2D too (the xy plane)
        pts2 = np.array([0.5, -1.0]) + s[:, None] * d[:2]
        assert V.cross_ratio(*pts2) == pytest.approx(cross_ratio_params(*s), rel=1e-9)


@pytest.mark.parametrize("points, pattern", [
    (([0, 0], [1, 0], [2, 0.5], [3, 0]), "line"),              # not collinear
    (([0, 0, 0], [1, 1, 1], [2, 2, 2.1], [3, 3, 3]), "line"),
    (([0, 0], [1, 0], [1, 0], [3, 0]), r"\bb\b.*\bc\b"),        # B = C
    (([0, 0], [1, 0], [2, 0], [0, 0]), r"\ba\b.*\bd\b"),        # A = D
    (([0, 0], [1, 0], [2, 0], [3, 0, 0]), "2D"),                # mixed dimensions
    (([0, 0, 0, 0], [1, 0, 0, 0], [2, 0, 0, 0], [3, 0, 0, 0]), r"\ba\b"),   # 4D
    (([0, np.nan], [1, 0], [2, 0], [3, 0]), "finite"),
])
def test_cross_ratio_errors(points, pattern):
    with pytest.raises(ValueError, match=pattern):
        V.cross_ratio(*points)


# ---------------------------------------------------------------------------------------------
# bad input
# ---------------------------------------------------------------------------------------------

GOOD = {
    "frustum": dict(left=-1.0, right=1.0, bottom=-1.0, top=1.0, near=1.0, far=10.0),
    "orthographic": dict(left=-1.0, right=1.0, bottom=-1.0, top=1.0, near=1.0, far=10.0),
    "perspective": dict(fov_y=1.0, aspect=1.5, near=1.0, far=10.0),
    "viewport": dict(xmin=0.0, ymin=0.0, xmax=640.0, ymax=480.0, zmin=0.0, zmax=1.0),
    "simple_perspective": dict(d=2.0),
    "oblique": dict(dop=[1.0, 0.5, -1.0]),
    "look_at": dict(eye=[1.0, 2.0, 3.0], gaze=[0.0, 0.0, -1.0], up=[0.0, 1.0, 0.0]),
}


def _with(func, **changes):
    kwargs = dict(GOOD[func])
    kwargs.update(changes)
    return func, kwargs


BAD_VALUES = [
    (_with("frustum", near=0.0), "near"),
    (_with("frustum", near=-1.0), "near"),
    (_with("frustum", far=1.0), "far"),
    (_with("frustum", far=0.5), "far"),
    (_with("frustum", left=1.0), "left"),
    (_with("frustum", left=2.0), "left"),
    (_with("frustum", bottom=1.0), "bottom"),
    (_with("frustum", top=-3.0), "top"),
    (_with("orthographic", near=0.0), "near"),
    (_with("orthographic", near=-2.0), "near"),
    (_with("orthographic", far=1.0), "far"),
    (_with("orthographic", right=-1.0), "right"),
    (_with("orthographic", top=-1.0), "top"),
    (_with("perspective", fov_y=0.0), "fov_y"),
    (_with("perspective", fov_y=PI), "fov_y"),
    (_with("perspective", fov_y=-0.5), "fov_y"),
    (_with("perspective", fov_y=4.0), "fov_y"),
    (_with("perspective", fov_y=90.0), "fov_y"),           # degrees by mistake
    (_with("perspective", aspect=0.0), "aspect"),
    (_with("perspective", aspect=-1.0), "aspect"),
    (_with("perspective", near=0.0), "near"),
    (_with("perspective", far=0.5), "far"),
    (_with("viewport", xmax=0.0), "xmax"),
    (_with("viewport", xmax=-10.0), "xmax"),
    (_with("viewport", ymax=0.0), "ymax"),
    (_with("viewport", zmax=0.0), "zmax"),
    (_with("viewport", zmin=2.0), "zmin"),
    (_with("simple_perspective", d=0.0), r"\bd\b"),
    (_with("oblique", dop=[1.0, 1.0, 0.0]), "dop"),
    (_with("oblique", dop=[0.0, 0.0, 0.0]), "dop"),
]
for _func, _args in GOOD.items():                  # NaN and inf in every argument
    for _name, _value in _args.items():
        for _bad in (np.nan, np.inf, -np.inf):
            _v = _bad if np.ndim(_value) == 0 else [_value[0], _bad, _value[2]]
            BAD_VALUES.append((_with(_func, **{_name: _v}), rf"\b{_name}\b.*finite"))
BAD_SHAPES = [
    (_with("frustum", left=[1.0, 2.0]), "left"),
    (_with("perspective", aspect=[[1.0]]), "aspect"),
    (_with("viewport", zmax=np.ones(2)), "zmax"),
    (_with("simple_perspective", d=[]), r"\bd\b"),
    (_with("oblique", dop=[1.0, 1.0]), "dop"),
    (_with("oblique", dop=[[1.0, 1.0, 1.0]]), "dop"),
    (_with("look_at", eye=[0.0, 0.0]), "eye"),
    (_with("look_at", gaze=[0.0, 0.0, -1.0, 0.0]), "gaze"),
    (_with("look_at", up=np.ones((2, 3))), "up"),
]


def _id(call):
    func, kwargs = call
    return func + "-" + "-".join(f"{k}={v!r}" for k, v in kwargs.items()
                                 if v is not GOOD[func].get(k))


@pytest.mark.parametrize("call, name", BAD_VALUES + BAD_SHAPES,
                         ids=[_id(c) for c, _ in BAD_VALUES + BAD_SHAPES])
def test_bad_values_raise_value_error_naming_the_argument(call, name):
    func, kwargs = call
    with pytest.raises(ValueError, match=name):
        getattr(V, func)(**kwargs)


STRINGS = [_with(func, **{name: "1"}) for func, args in GOOD.items() for name in args] + \
    [_with(func, **{name: None}) for func, args in GOOD.items() for name in args]


@pytest.mark.parametrize("call", STRINGS, ids=[_id(c) for c in STRINGS])
def test_strings_and_none_raise_type_error(call):
    func, kwargs = call
    with pytest.raises(TypeError):
        getattr(V, func)(**kwargs)


def test_cross_ratio_with_a_string_raises_type_error():
    # BUG: cross_ratio compares np.size of its arguments before validating them, so a string
    # among points gives "must all be 2D or all 3D points" (ValueError) instead of a TypeError
    # naming the argument.
    with pytest.raises(TypeError, match=r"\ba\b"):
        V.cross_ratio("ab", [1, 0], [2, 0], [3, 0])
    with pytest.raises(TypeError, match=r"\bc\b"):
        V.cross_ratio([0, 0], [1, 0], "c", [3, 0])


def test_to_screen_validates_its_matrices_by_name():
    # BUG: to_screen passes view, projection and viewport_matrix to numpy / transforms.apply
    # unchecked. A 3x3 view ends in numpy's matmul error, a string in "could not convert string
    # to float" (ValueError, not TypeError), NaN in "M must be finite" (the wrong name), and a
    # 3x3 viewport_matrix is silently applied as a linear map (apply's 3x3 rule): wrong pixels,
    # no error.
    pts = [[0.0, 0.0, 0.0]]
    good = dict(view=V.look_at([0, 0, 5], [0, 0, -1], [0, 1, 0]),
                projection=V.perspective(1.0, 1.0, 1.0, 10.0),
                viewport_matrix=V.viewport(0, 0, 100, 100))
    cases = [("view", np.eye(3), ValueError), ("projection", np.eye(3), ValueError),
             ("viewport_matrix", np.eye(3), ValueError), ("view", np.full((4, 4), np.nan),
                                                          ValueError),
             ("projection", "abc", TypeError), ("viewport_matrix", np.ones((4, 3)), ValueError)]
    failures = []
    for name, value, error in cases:
        kwargs = dict(good, **{name: value})
        try:
            V.to_screen(pts, **kwargs)
            failures.append(f"{name}={value!r}: no error")
        except error as exc:
            if name not in str(exc):
                failures.append(f"{name}: {type(exc).__name__} not naming it: {exc}")
        except Exception as exc:                      # noqa: BLE001 - the wrong kind of error
            failures.append(f"{name}: {type(exc).__name__} instead of {error.__name__}: {exc}")
    assert not failures, "\n".join(failures)
