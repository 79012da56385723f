"""Relief mapping (course_lib.texturing.relief) cross-checked: bump normals against the exact
normal of the displaced surface P + eps h N (a plane exactly, a sphere as eps -> 0, by finite
differences), height derivatives against numpy.gradient and closed forms, tangent frames
against the analytic dP/du, dP/dv of the course's spherical and cylindrical maps (closed forms
typed here) and against VTK's vtkPolyDataTangents, the colour encoding round trip, TBN
orthonormality, and the silhouette of displacement versus bump mapping."""
import numpy as np
import pytest

from course_lib.texturing import relief as R
from course_lib.texturing.mappings import inverse_cylindrical_map, inverse_spherical_map


# --- height derivatives --------------------------------------------------------------------

def test_height_gradient_against_numpy_gradient_clamp():
    rng = np.random.default_rng(3)
    h = rng.random((7, 9))
    h_u, h_v = R.height_gradient(h, wrap="clamp")
    gv, gu = np.gradient(h, 1 / 7, 1 / 9)          # rows are v (spacing 1/H), columns u
    assert np.allclose(h_u, gu) and np.allclose(h_v, gv)


def test_height_gradient_repeat_matches_the_analytic_derivative():
    n = 256
    c = (np.arange(n) + 0.5) / n
    u, v = np.meshgrid(c, c)
    h = np.sin(2 * np.pi * u) * np.cos(4 * np.pi * v)
    h_u, h_v = R.height_gradient(h)                  # repeat: the border wraps
    assert np.allclose(h_u, 2 * np.pi * np.cos(2 * np.pi * u) * np.cos(4 * np.pi * v), atol=2e-3)
    assert np.allclose(h_v, -4 * np.pi * np.sin(2 * np.pi * u) * np.sin(4 * np.pi * v),
                       atol=5e-3)
    hu, hv = R.height_gradient_at(h, [0.3], [0.7])
    assert hu[0] == pytest.approx(2 * np.pi * np.cos(0.6 * np.pi) * np.cos(2.8 * np.pi), abs=5e-3)


def test_mirror_halves_the_edge_slope():
    h = np.tile((np.arange(4) + 0.5) / 4, (2, 1))
    h_u, _ = R.height_gradient(h, wrap="mirror")
    assert np.allclose(h_u[0], [0.5, 1, 1, 0.5])


# --- bump mapping --------------------------------------------------------------------------

def test_bump_on_a_plane_is_the_exact_normal_of_the_displaced_plane():
    # P = (2u, 3v, 0), displaced by h along z: P' = (2u, 3v, h); its normal is
    # P'_u x P'_v = (2, 0, h_u) x (0, 3, h_v) = (-3 h_u, -2 h_v, 6)
    rng = np.random.default_rng(0)
    hu, hv = rng.normal(size=(2, 50))
    pu, pv = np.array([2.0, 0, 0]), np.array([0, 3.0, 0])
    exact = np.stack([-3 * hu, -2 * hv, np.full(50, 6.0)], axis=-1)
    assert np.allclose(R.bump_normal(pu, pv, hu, hv, normalize=False), exact)
    unit = R.bump_normal(pu, pv, hu, hv)
    assert np.allclose(unit, exact / np.linalg.norm(exact, axis=1, keepdims=True))
    # the tangent-frame form agrees with h / |P_u|, h / |P_v|
    simple = R.bump_normal_tangent([0, 0, 1], [1, 0, 0], [0, 1, 0], hu / 2, hv / 3)
    assert np.allclose(simple, unit)


def _sphere(u, v):
    return inverse_spherical_map(u, v)


def test_bump_on_a_sphere_converges_to_the_displaced_sphere():
    rng = np.random.default_rng(1)
    u, v = rng.uniform(0.1, 0.9, 40), rng.uniform(0.2, 0.8, 40)

    def h(u, v):
        return np.sin(6 * np.pi * u) * np.cos(4 * np.pi * v)

    d = 1e-6
    pu = (_sphere(u + d, v) - _sphere(u - d, v)) / (2 * d)
    pv = (_sphere(u, v + d) - _sphere(u, v - d)) / (2 * d)
    hu = (h(u + d, v) - h(u - d, v)) / (2 * d)
    hv = (h(u, v + d) - h(u, v - d)) / (2 * d)
    errors = []
    for eps in (1e-1, 1e-2, 1e-3):
        def displaced(u, v):
            p = _sphere(u, v)
            return p * (1 + eps * h(u, v))[:, None]       # unit sphere: n = P
        qu = (displaced(u + d, v) - displaced(u - d, v)) / (2 * d)
        qv = (displaced(u, v + d) - displaced(u, v - d)) / (2 * d)
        exact = np.cross(qu, qv)
        exact /= np.linalg.norm(exact, axis=1, keepdims=True)
        bumped = R.bump_normal(pu, pv, eps * hu, eps * hv)
        flat = np.cross(pu, pv) / np.linalg.norm(np.cross(pu, pv), axis=1, keepdims=True)
        errors.append(np.abs(bumped - exact).max())
        assert np.abs(flat - exact).max() > 5 * errors[-1]     # the bump did most of the work
    # first-order method: the error falls like eps^2 (by about 100 per decade)
    assert errors[1] < errors[0] / 30 and errors[2] < errors[1] / 30


def test_bump_normal_sign_points_against_the_slope():
    n = R.bump_normal([1, 0, 0], [0, 1, 0], 1.0, 0.0)
    assert n[0] < 0 and n[2] > 0


def test_bump_normal_bad_input():
    with pytest.raises(ValueError, match="parallel"):
        R.bump_normal([1, 0, 0], [2, 0, 0], 0, 0)
    with pytest.raises(ValueError, match="h_u must be finite"):
        R.bump_normal([1, 0, 0], [0, 1, 0], np.nan, 0)
    with pytest.raises(ValueError, match="p_u"):
        R.bump_normal([1, 0], [0, 1, 0], 0, 0)


# --- tangent frames ------------------------------------------------------------------------

def test_triangle_tangent_frame_reproduces_a_linear_map():
    rng = np.random.default_rng(5)
    t_true, b_true, p0 = rng.normal(size=(3, 20, 3))
    uv = rng.uniform(size=(20, 3, 2))
    d = uv - uv[:, :1]
    pos = p0[:, None] + d[..., :1] * t_true[:, None] + d[..., 1:] * b_true[:, None]
    T, B, N = R.triangle_tangent_frame(pos, uv)
    assert np.allclose(T, t_true) and np.allclose(B, b_true)
    n = np.cross(t_true, b_true)
    assert np.allclose(np.abs(np.sum(N * n, axis=1)), np.linalg.norm(n, axis=1))


def test_triangle_tangent_frame_errors():
    with pytest.raises(ValueError, match="uvs must span"):
        R.triangle_tangent_frame([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0], [1, 1], [2, 2]])
    with pytest.raises(ValueError, match="positions must span"):
        R.triangle_tangent_frame([[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 0], [1, 0], [0, 1]])
    with pytest.raises(ValueError, match="positions must be"):
        R.triangle_tangent_frame([[0, 0, 0], [1, 0, 0]], [[0, 0], [1, 0], [0, 1]])
    with pytest.raises(ValueError, match="uvs must be finite"):
        R.triangle_tangent_frame([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 0], [1, np.inf], [0, 1]])


def _grid_mesh(surface, nu=40, nv=20, u0=0.05, u1=0.95, v0=0.1, v1=0.9):
    u, v = np.meshgrid(np.linspace(u0, u1, nu), np.linspace(v0, v1, nv))
    uv = np.stack([u.ravel(), v.ravel()], axis=1)
    verts = surface(uv[:, 0], uv[:, 1])
    idx = np.arange(nu * nv).reshape(nv, nu)
    a, b, c, d = idx[:-1, :-1], idx[:-1, 1:], idx[1:, 1:], idx[1:, :-1]
    faces = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                            np.stack([a, c, d], -1).reshape(-1, 3)])
    return verts, faces, uv


def _interior(nu, nv):
    keep = np.zeros((nv, nu), bool)
    keep[1:-1, 1:-1] = True
    return keep.ravel()


def _unit(x):
    return x / np.linalg.norm(x, axis=-1, keepdims=True)


def test_vertex_frames_match_the_analytic_sphere_tangents():
    verts, faces, uv = _grid_mesh(_sphere)
    T, B, N, w = R.vertex_tangent_frames(verts, faces, uv, normals=verts)
    theta, phi = 2 * np.pi * (uv[:, 0] - 0.5), np.pi * (uv[:, 1] - 0.5)
    e1, e2, a = np.array([0, 0, 1.0]), np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    dpu = 2 * np.pi * np.cos(phi)[:, None] * (-np.sin(theta)[:, None] * e1
                                               + np.cos(theta)[:, None] * e2)
    dpv = np.pi * (-np.sin(phi)[:, None] * (np.cos(theta)[:, None] * e1
                                             + np.sin(theta)[:, None] * e2) + np.cos(phi)[:, None] * a)
    inner = _interior(40, 20)                     # the border's one-sided averages are worse
    assert np.abs(T - _unit(dpu))[inner].max() < 0.02
    assert np.abs(B - _unit(dpv))[inner].max() < 0.02
    assert np.abs(T - _unit(dpu)).max() < 0.1
    assert np.all(w == 1)
    frame = np.stack([T, B, N], axis=-1)
    assert np.allclose(np.einsum("nji,njk->nik", frame, frame), np.eye(3), atol=1e-12)


def test_vertex_frames_match_the_analytic_cylinder_tangents():
    def cyl(u, v):
        return inverse_cylindrical_map(u, v, radius=0.5, height=2.0)
    verts, faces, uv = _grid_mesh(cyl, v0=0.0, v1=1.0)
    normals = verts * [1, 0, 1]
    T, B, N, w = R.vertex_tangent_frames(verts, faces, uv, normals=normals)
    theta = 2 * np.pi * (uv[:, 0] - 0.5)
    dpu = np.stack([np.cos(theta), 0 * theta, -np.sin(theta)], axis=1)   # e1 = z, e2 = x
    assert np.abs(T - dpu)[_interior(40, 20)].max() < 0.01
    assert np.allclose(B, [0, 1, 0], atol=1e-12)


def test_vertex_frames_handedness_of_a_mirrored_texture():
    verts, faces, uv = _grid_mesh(_sphere, nu=12, nv=8)
    _, _, _, w = R.vertex_tangent_frames(verts, faces, uv * [-1, 1], normals=verts)
    assert np.all(w == -1)


def test_vertex_frames_against_vtk_polydata_tangents():
    vtk = pytest.importorskip("vtk")
    from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    verts, faces, uv = _grid_mesh(_sphere, nu=30, nv=16)
    poly = vtk.vtkPolyData()
    pts = vtk.vtkPoints()
    pts.SetData(numpy_to_vtk(verts.copy()))
    poly.SetPoints(pts)
    cells = vtk.vtkCellArray()
    for f in faces:
        cells.InsertNextCell(3, [int(i) for i in f])
    poly.SetPolys(cells)
    poly.GetPointData().SetNormals(numpy_to_vtk(verts.copy()))
    poly.GetPointData().SetTCoords(numpy_to_vtk(uv.copy()))
    filt = vtk.vtkPolyDataTangents()
    filt.SetInputData(poly)
    filt.Update()
    ref = vtk_to_numpy(filt.GetOutput().GetPointData().GetTangents())[:, :3]
    T, _, _, _ = R.vertex_tangent_frames(verts, faces, uv, normals=verts)
    assert np.abs(T - _unit(ref))[_interior(30, 16)].max() < 0.03


def test_vertex_frames_name_the_degenerate_face():
    verts = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]
    uv = [[0, 0], [1, 0], [0, 1], [2, -1]]                  # face 1: collinear uvs
    with pytest.raises(ValueError, match=r"faces\[1\]: uvs must span"):
        R.vertex_tangent_frames(verts, [[0, 1, 2], [1, 3, 2]], uv)


# --- normal maps ---------------------------------------------------------------------------

def test_encode_decode_round_trip():
    rng = np.random.default_rng(7)
    n = _unit(rng.normal(size=(200, 3)))
    assert np.allclose(R.decode_normals(R.encode_normals(n)), n)
    eight = R.encode_normals(n, bits=8)
    assert eight.dtype == np.uint8
    back = R.decode_normals(eight)
    angle = np.degrees(np.arccos(np.clip(np.sum(back * n, axis=1), -1, 1)))
    assert angle.max() < 0.5                    # 8 bits: within half a degree
    assert np.allclose(R.encode_normals([0, 0, 1]), [0.5, 0.5, 1.0])   # the blue of normal maps


def test_decode_errors():
    with pytest.raises(ValueError, match=r"colors must lie in \[0, 1\]"):
        R.decode_normals([1.2, 0.5, 0.5])
    with pytest.raises(ValueError, match="grey"):
        R.decode_normals([0.5, 0.5, 0.5])
    with pytest.raises(ValueError, match="bits"):
        R.encode_normals([0, 0, 1], bits=16)


def test_tangent_object_round_trip_and_tbn():
    rng = np.random.default_rng(8)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    t, b, n = q.T
    nt = _unit(rng.normal(size=(50, 3)))
    obj = R.tangent_to_object(nt, t, b, n)
    assert np.allclose(obj, nt @ q.T)                        # M n_t with M = [T B N]
    assert np.allclose(R.object_to_tangent(obj, t, b, n), nt)
    assert np.allclose(R.object_to_tangent(obj, t, b, n), obj @ q)   # M^T for orthonormal
    with pytest.raises(ValueError, match="linearly independent"):
        R.object_to_tangent([0, 0, 1], [1, 0, 0], [1, 0, 0], [0, 0, 1])


def test_normal_map_from_height_matches_bump_on_a_plane():
    h = R.bumps_height(32, count=2)
    rgb = R.normal_map_from_height(h, strength=0.05, extent=(2.0, 1.0))
    h_u, h_v = R.height_gradient(h)
    bump = R.bump_normal([2.0, 0, 0], [0, 1.0, 0], 0.05 * h_u, 0.05 * h_v)
    assert np.allclose(R.decode_normals(rgb), bump)


# --- displacement: silhouettes -------------------------------------------------------------

def test_displacement_changes_the_silhouette_bump_does_not():
    verts, faces, uv = _grid_mesh(_sphere, nu=80, nv=40, u0=0, u1=1, v0=0.02, v1=0.98)
    h = R.bumps_height(64, count=4)
    from course_lib.texturing import bilinear_sample
    heights = bilinear_sample(h, uv[:, 0], uv[:, 1])
    moved = R.displace(verts, verts, heights, strength=0.2)
    r_flat = np.hypot(verts[:, 0], verts[:, 1]).max()      # outline seen along z
    r_moved = np.hypot(moved[:, 0], moved[:, 1]).max()
    assert r_flat <= 1 + 1e-12 and r_moved > 1.1
    # bump mapping changes normals only: the shaded points (and so the outline) stay put
    T, B, N, _ = R.vertex_tangent_frames(verts, faces, uv, normals=verts)
    assert np.isfinite(T).all()


def test_height_map_errors():
    with pytest.raises(ValueError, match="height must be a 2D"):
        R.height_gradient(np.zeros((4, 4, 3)))
    with pytest.raises(ValueError, match="height must be finite"):
        R.height_gradient([[0, np.nan], [0, 0]])
    with pytest.raises(ValueError, match="wrap"):
        R.height_gradient(np.zeros((4, 4)), wrap="tile")
    with pytest.raises(ValueError, match="heights must be finite"):
        R.displace([0, 0, 0], [0, 0, 1], np.inf)


def test_demo_height_maps():
    b = R.bricks_height(64, rows=4, columns=2)
    assert b.max() == 1.0 and b.min() == 0.0
    n = R.noise_height(64, seed=2)
    assert np.allclose(n, R.noise_height(64, seed=2))
    assert abs(n[:, 0] - n[:, -1]).max() < 0.2                # periodic in u
    img = R.shade_normals(np.dstack([np.zeros((2, 2)), np.zeros((2, 2)), np.ones((2, 2))]),
                          light=(0, 0, 1), model="blinn-phong")
    assert np.allclose(img, 1.0)                               # 0.1 + 0.7 + 0.3, clipped
