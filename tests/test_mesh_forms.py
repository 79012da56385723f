"""Tests of course_lib/mesh/forms.py and course_lib/mesh/brep.py.

Cross-checks: closed forms typed here (distances to a sphere, a torus and a box; the volume
and area of a sphere and a torus; the counts of the example solids counted by hand), trimesh
(watertightness, winding, volume, Euler number and connected bodies of triangulated B-reps and
tessellated patches; distances of sampled points to the mesh), scikit-image's marching cubes
(the surface area of the voxelized sphere) and numpy finite differences are independent of
the module's code.
"""
import numpy as np
import pytest
import trimesh
from skimage import measure

from course_lib.mesh import brep as B
from course_lib.mesh import forms as F
from course_lib.mesh import cube


# --------------------------------------------------------------------- implicit and CSG

def test_signed_functions_against_closed_forms():
    rng = np.random.default_rng(0)
    p = rng.uniform(-2, 2, (200, 3))
    assert np.allclose(F.implicit_sphere(p, (0.5, 0, 0), 1.2),
                       np.sqrt(((p - [0.5, 0, 0]) ** 2).sum(1)) - 1.2)
    # the torus: the distance to the nearest point of the centre circle, minus the tube radius
    phi = np.arctan2(p[:, 1], p[:, 0])
    circle = np.column_stack([1.5 * np.cos(phi), 1.5 * np.sin(phi), np.zeros(len(p))])
    assert np.allclose(F.implicit_torus(p, 1.5, 0.5),
                       np.linalg.norm(p - circle, axis=1) - 0.5)
    # the box: outside points by clamping to the box, inside by the nearest face
    q = np.clip(p, -1, 1)
    out = np.linalg.norm(p - q, axis=1)
    inside = np.all(np.abs(p) < 1, axis=1)
    expected = np.where(inside, -(1 - np.abs(p)).min(axis=1), out)
    assert np.allclose(F.implicit_box(p), expected)


def test_implicit_normals_of_a_torus_point_away_from_the_centre_circle():
    t = np.linspace(0, 2 * np.pi, 9)
    p = F.torus_patch(t / (2 * np.pi), np.roll(t, 3) / (2 * np.pi), 1.0, 0.4)
    phi = np.arctan2(p[:, 1], p[:, 0])
    centre = np.column_stack([np.cos(phi), np.sin(phi), np.zeros(len(p))])
    expected = (p - centre) / 0.4
    assert np.allclose(F.implicit_normals(F.implicit_torus, p), expected, atol=1e-6)
    with pytest.raises(ValueError, match="gradient"):
        F.implicit_normals(lambda q: np.zeros(q.shape[:-1]), [[0, 0, 0]])
    with pytest.raises(TypeError, match="function"):
        F.implicit_normals(3, [[0, 0, 0]])


def test_csg_membership_matches_boolean_logic():
    rng = np.random.default_rng(1)
    p = rng.uniform(-1.5, 1.5, (2000, 3))
    ball = lambda q: F.implicit_sphere(q, radius=1.2)                       # noqa: E731
    rod = lambda q: F.implicit_box(q, half=(0.4, 0.4, 2.0))                 # noqa: E731
    tree = ("difference", ("intersection", F.implicit_box, ball), rod)
    inside = (np.all(np.abs(p) < 1, 1) & (np.linalg.norm(p, axis=1) < 1.2)
              & ~(np.all(np.abs(p[:, :2]) < 0.4, 1) & (np.abs(p[:, 2]) < 2)))
    assert np.array_equal(F.classify_points(F.csg_evaluate(tree, p)) < 0, inside)
    union = F.csg_evaluate(("union", ball, rod), p) < 0
    assert np.array_equal(union, (np.linalg.norm(p, axis=1) < 1.2)
                          | (np.all(np.abs(p[:, :2]) < 0.4, 1) & (np.abs(p[:, 2]) < 2)))
    with pytest.raises(ValueError, match="operation"):
        F.csg_evaluate(("xor", ball, rod), p)
    with pytest.raises(TypeError, match="tree"):
        F.csg_evaluate(("union", ball), p)
    with pytest.raises(ValueError, match="tolerance"):
        F.classify_points([0.0], tolerance=-1)


# --------------------------------------------------------------------- voxels and conversions

def test_voxel_volume_and_memory():
    values, occ, spacing, origin = F.voxelize(F.implicit_sphere, (-1, -1, -1), (1, 1, 1), 40)
    volume = occ.sum() * np.prod(spacing)
    assert abs(volume - 4 / 3 * np.pi) < 0.02 * 4 / 3 * np.pi
    # the sample of cell (i, j, k) sits at origin + (i, j, k) * spacing
    k, j, i = 3, 17, 25
    x = origin + np.array([i, j, k]) * spacing
    assert np.isclose(values[k, j, i], np.linalg.norm(x) - 1)
    assert F.voxel_memory(128) == 128 ** 3 // 8
    assert F.voxel_memory(2 * 128) == 8 * F.voxel_memory(128)
    with pytest.raises(ValueError, match="lower and upper"):
        F.voxelize(F.implicit_sphere, (1, 1, 1), (0, 0, 0), 4)
    with pytest.raises(ValueError, match="resolution"):
        F.voxelize(F.implicit_sphere, (0, 0, 0), (1, 1, 1), 1)
    with pytest.raises(TypeError, match="function"):
        F.voxelize("sphere", (0, 0, 0), (1, 1, 1), 4)


def test_voxels_to_mesh_against_scikit_image():
    values, _, spacing, origin = F.voxelize(F.implicit_sphere, (-1.3,) * 3, (1.3,) * 3, 24)
    v, t = F.voxels_to_mesh(values, spacing, origin)
    tm = trimesh.Trimesh(v, t, process=False)
    ours = tm.area
    assert tm.is_winding_consistent and abs(tm.volume - 4 / 3 * np.pi) < 0.05 * 4 / 3 * np.pi
    sv, st, _, _ = measure.marching_cubes(values, 0.0, spacing=tuple(spacing[::-1]))
    theirs = measure.mesh_surface_area(sv, st)
    assert abs(ours - theirs) < 1e-6 * theirs
    assert abs(ours - 4 * np.pi) < 0.03 * 4 * np.pi


def test_sampled_points_lie_on_the_mesh_and_follow_area():
    v, t = F.tessellate(F.torus_patch, 24, 12, wrap_u=True, wrap_v=True)
    p, n = F.sample_point_cloud(v, t, 500, seed=3)
    mesh = trimesh.Trimesh(v, t, process=False)
    _, dist, tri = trimesh.proximity.closest_point(mesh, p)
    assert dist.max() < 1e-9
    assert np.allclose(np.abs((n * mesh.face_normals[tri]).sum(1)), 1.0)
    # two triangles of areas 1 and 3: about a quarter of the samples on the first
    v2 = [[0, 0, 0], [1, 0, 0], [0, 2, 0], [3, 0, 1], [0, 0, 1], [0, 2, 1]]
    p2, _ = F.sample_point_cloud(v2, [[0, 1, 2], [3, 5, 4]], 4000, seed=0)
    share = np.mean(p2[:, 2] == 0)
    assert abs(share - 0.25) < 0.03
    assert np.array_equal(F.sample_point_cloud(v, t, 10, seed=5)[0], F.sample_point_cloud(v, t, 10, seed=5)[0])
    with pytest.raises(ValueError, match="3 vertices"):
        F.sample_point_cloud(*cube(), 10)
    with pytest.raises(ValueError, match="count"):
        F.sample_point_cloud(v, t, 0)


def test_tessellated_torus_is_closed_with_genus_one_and_converges():
    volumes = []
    for n in (16, 64):
        v, t = F.tessellate(F.torus_patch, n, n // 2, wrap_u=True, wrap_v=True)
        m = trimesh.Trimesh(v, t, process=False)
        assert m.is_watertight and m.is_winding_consistent and m.euler_number == 0
        volumes.append(m.volume)
    exact = 2 * np.pi ** 2 * 1.0 * 0.4 ** 2
    assert abs(volumes[1] - exact) < abs(volumes[0] - exact) < 0.15 * exact
    assert volumes[1] > 0                                      # outward normals
    v, t = F.tessellate(lambda u, w: np.stack([u, w, 0 * u], -1), 3, 2)
    assert len(v) == 12 and len(t) == 12                        # an open 3 x 2 grid
    with pytest.raises(ValueError, match="at least 3"):
        F.tessellate(F.torus_patch, 2, 8, wrap_u=True)
    with pytest.raises(TypeError, match="evaluate"):
        F.tessellate(None, 2, 2)


def test_tessellated_bezier_patch_against_the_bernstein_sum():
    from scipy.special import comb
    from course_lib import surfaces

    grid = surfaces.hill_grid(4, 3)
    v, t = F.tessellate(lambda u, w: surfaces.bezier_surface(grid, u[:, 0], w[0]), 5, 4)
    m, n = grid.shape[0] - 1, grid.shape[1] - 1
    expected = []
    for u in np.arange(6) / 5:                     # vertex i * 5 + j is (u_i, v_j)
        for w in np.arange(5) / 4:
            bu = [comb(m, i) * u ** i * (1 - u) ** (m - i) for i in range(m + 1)]
            bw = [comb(n, j) * w ** j * (1 - w) ** (n - j) for j in range(n + 1)]
            expected.append(np.einsum("i,j,ijk->k", bu, bw, grid))
    assert np.allclose(v, expected)
    assert t.shape == (2 * 5 * 4, 3)
    assert trimesh.Trimesh(v, t, process=False).is_winding_consistent


def test_model_forms_table():
    assert set(F.MODEL_FORMS) == {"mesh", "implicit", "parametric", "csg", "voxels",
                                  "point cloud", "brep"}
    for row in F.MODEL_FORMS.values():
        assert set(F.FORM_PROPERTIES) <= set(row)
    assert F.MODEL_FORMS["mesh"]["render"] and not F.MODEL_FORMS["mesh"]["exact"]
    assert F.MODEL_FORMS["csg"]["inside test"] and F.MODEL_FORMS["implicit"]["inside test"]
    assert not F.MODEL_FORMS["point cloud"]["inside test"]


# --------------------------------------------------------------------- B-reps

HAND = {  # counted by hand: V, E, F, R, S, H
    "cube": (8, 12, 6, 0, 1, 0),
    "drilled": (16, 24, 10, 2, 1, 1),
    "pocket": (16, 24, 11, 1, 1, 0),
    "two cubes": (16, 24, 12, 0, 2, 0),
}
SOLIDS = {"cube": B.brep_cube, "drilled": B.brep_drilled_cube, "pocket": B.brep_pocket_cube,
          "two cubes": B.brep_two_cubes}
VOLUMES = {"cube": 1.0, "drilled": 27.0 - 3.0, "pocket": 27.0 - 2.0, "two cubes": 2.0}


@pytest.mark.parametrize("name", sorted(SOLIDS))
def test_brep_counts_by_hand_and_by_trimesh(name):
    b = SOLIDS[name]()
    counts = tuple(B.brep_counts(b).values())
    assert counts == HAND[name]
    V, E, Fc, R, S, H = counts
    assert B.euler_poincare_check(*counts) == 2 * (S - H)
    v, t = B.brep_triangulate(b)
    m = trimesh.Trimesh(v, t, process=False)
    assert m.is_watertight and m.is_winding_consistent
    assert np.isclose(m.volume, VOLUMES[name])                 # faces oriented outwards
    bodies = m.split(only_watertight=False)
    assert len(bodies) == S
    assert sum((2 - body.euler_number) // 2 for body in bodies) == H
    # the mesh form: V - E + F = 2(S - H) once the rings are triangulated away
    assert m.euler_number == 2 * (S - H)
    assert len(m.vertices) == V


def test_euler_poincare_errors_name_the_counts():
    with pytest.raises(ValueError, match=r"V=16, E=24, F=10, R=0, S=1, H=1.*= 2 but 2\(S - H\) = 0"):
        B.euler_poincare_check(16, 24, 10, 0, 1, 1)
    with pytest.raises(ValueError, match="S"):
        B.euler_poincare_check(8, 12, 6, 0, 0, 0)
    with pytest.raises((TypeError, ValueError), match="E"):
        B.euler_poincare_check(8, 12.5, 6, 0, 1, 0)


def test_brep_bad_input():
    v, faces = B._box_loops(np.zeros(3), np.ones(3))
    with pytest.raises(ValueError, match="no partner"):
        B.BRep(v, faces[:-1])                                  # an open box
    flipped = [f if k else [f[0][::-1]] for k, f in enumerate(faces)]
    with pytest.raises(ValueError, match="same direction"):
        B.BRep(v, flipped)
    with pytest.raises(ValueError, match="outside 0..7"):
        B.BRep(v, faces[:-1] + [[[1, 3, 7, 9]]])
    with pytest.raises(ValueError, match="at least 3 distinct"):
        B.BRep(v, [[[0, 1]]])
    with pytest.raises(TypeError, match="faces"):
        B.BRep(v, "faces")
    with pytest.raises(ValueError, match="depth"):
        B.brep_pocket_cube(3.0)
    with pytest.raises(TypeError, match="BRep"):
        B.brep_counts("cube")


def test_example_solids_refuse_bad_sizes():
    with pytest.raises(TypeError, match="size"):
        B.brep_cube("a")
    with pytest.raises(ValueError, match="gap"):
        B.brep_two_cubes(0)
    with pytest.raises(ValueError, match="depth"):
        B.brep_pocket_cube(-1)
    with pytest.raises(TypeError, match="tolerance"):
        F.classify_points([0.0], "x")
    with pytest.raises(ValueError, match="minor"):
        F.implicit_torus([0, 0, 0], 1.0, 1.0)
    with pytest.raises(ValueError, match="half"):
        F.implicit_box([0, 0, 0], half=(1, 0, 1))
