"""Tests of course_lib.frames: normals, frames, mirrors, scaling about a point, is_rotation.

Cross-checks: trimesh (a transformed mesh's face normals recomputed from its faces, and
trimesh.transformations.reflection_matrix), numpy.linalg.inv, explicit dot products, a
Householder reflection and closed forms typed here.
"""
import math

import numpy as np
import pytest
import trimesh
from trimesh import transformations as tt

from course_lib import frames, transforms


def angle_deg(a, b):
    a = a / np.linalg.norm(a, axis=-1, keepdims=True)
    b = b / np.linalg.norm(b, axis=-1, keepdims=True)
    return np.degrees(np.arccos(np.clip(np.sum(a * b, axis=-1), -1, 1)))


SHEAR = np.array([[1.0, 0.8, 0.0, 0.0], [0.0, 1.0, 0.3, 0.0], [0.0, 0.0, 1.0, 0.0],
                  [0.0, 0.0, 0.0, 1.0]])
CASES = {
    "non-uniform scale": np.diag([3.0, 1.0, 0.5, 1.0]),
    "shear": SHEAR,
    "everything": (transforms.translate([1, -2, 3]) @ transforms.rotate_axis([1, 2, 2], 0.7)
                   @ SHEAR @ np.diag([2.0, 0.5, 1.5, 1.0])),
}


@pytest.mark.parametrize("name", CASES)
def test_inverse_transpose_normals_match_the_transformed_mesh(name):
    M = CASES[name]
    mesh = trimesh.creation.icosphere(subdivisions=2)
    before = mesh.face_normals.copy()
    moved = mesh.copy()
    moved.apply_transform(M)
    recomputed = moved.face_normals                 # from the moved faces' cross products
    ours = frames.transform_normals(before, M)
    assert np.allclose(ours, recomputed, atol=1e-9)
    naive = before @ M[:3, :3].T
    assert angle_deg(naive, recomputed).max() > 5.0  # the naive normals are measurably wrong


def test_normal_matrix_is_the_inverse_transpose_and_ignores_translation():
    M = CASES["everything"]
    assert np.allclose(frames.normal_matrix(M), np.linalg.inv(M[:3, :3]).T)
    assert np.allclose(frames.normal_matrix(M[:3, :3]), np.linalg.inv(M[:3, :3]).T)
    m2 = np.array([[2.0, 1.0, 5.0], [0.0, 1.0, -1.0], [0.0, 0.0, 1.0]])
    assert np.allclose(frames.normal_matrix(m2, dim=2), [[0.5, 0.0], [-0.5, 1.0]])


def test_2d_normals_stay_perpendicular_to_transformed_tangents():
    rng = np.random.default_rng(0)
    t = rng.normal(size=(50, 2))
    n = t[:, ::-1] * [1, -1]                                 # perpendicular by construction
    M = np.array([[2.0, 0.7, 1.0], [0.2, 0.5, 3.0], [0.0, 0.0, 1.0]])
    out = frames.transform_normals(n, M, normalize=False)
    assert np.allclose(np.sum(out * (t @ M[:2, :2].T), axis=1), 0.0)
    unit = frames.transform_normals(n, M)
    assert np.allclose(np.linalg.norm(unit, axis=1), 1.0)


def test_preserves_normals():
    assert frames.preserves_normals(transforms.rotate_axis([1, 1, 0], 0.4) @ np.diag([2, 2, 2, 1]))
    assert frames.preserves_normals(transforms.mirror("xy"))
    assert not frames.preserves_normals(CASES["shear"])
    assert not frames.preserves_normals(np.diag([1.0, 2.0]))


def test_normal_errors():
    with pytest.raises(ValueError, match="singular.*normals cannot be transformed"):
        frames.normal_matrix(np.diag([1.0, 0.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="projective"):
        frames.normal_matrix([[1, 0, 0], [0, 1, 0], [1, 0, 1]], dim=2)
    with pytest.raises(ValueError, match="M must be"):
        frames.normal_matrix(np.eye(5))
    with pytest.raises(ValueError, match="does not fit 2D"):
        frames.transform_normals([[1.0, 0.0]], np.eye(4))
    with pytest.raises(ValueError, match="zero vector"):
        frames.transform_normals([[0.0, 0.0, 0.0]], np.eye(4))
    with pytest.raises(ValueError, match="normals"):
        frames.transform_normals([[1.0, 0.0, 0.0, 0.0]], np.eye(4))


# ---------------------------------------------------------------------------------------------
# Frames
# ---------------------------------------------------------------------------------------------

def test_frame_coordinates_are_dot_products_for_orthonormal_axes():
    R = transforms.rotate_axis([2, 3, 6], 1.1)[:3, :3]
    axes, o = R.T, np.array([1.0, -2.0, 0.5])              # axes as rows
    F, W = frames.frame_matrix(o, axes), frames.world_to_frame(o, axes)
    assert np.allclose(W, np.linalg.inv(F))
    p = np.array([0.3, 4.0, -1.0])
    coords = (W @ np.append(p, 1))[:3]
    assert np.allclose(coords, [axes[i] @ (p - o) for i in range(3)])
    assert np.allclose(F @ np.append(coords, 1), np.append(p, 1))


def test_general_axes_use_the_general_inverse():
    o, axes = [1.0, 2.0], [[2.0, 1.0], [1.0, 3.0]]
    W = frames.world_to_frame(o, axes)
    assert np.allclose(W, np.linalg.inv(frames.frame_matrix(o, axes)))
    # the point o + 2 u1 - u2 has coordinates (2, -1)
    p = np.array(o) + 2 * np.array(axes[0]) - np.array(axes[1])
    assert np.allclose(W @ np.append(p, 1), [2.0, -1.0, 1.0])


def test_chain_of_frames():
    a = (np.array([2.0, 0.0]), np.array([[0.0, 1.0], [-1.0, 0.0]]))
    b = (np.array([1.0, 1.0]), np.array([[1.0, 0.0], [0.0, 1.0]]) * 0.5)
    p = np.array([3.0, 4.0])
    inner = b[0] + p[0] * b[1][0] + p[1] * b[1][1]          # p in frame a's coordinates
    world = a[0] + inner[0] * a[1][0] + inner[1] * a[1][1]
    assert np.allclose(frames.chain(a, b) @ np.append(p, 1), np.append(world, 1))
    assert np.allclose(frames.chain(frames.frame_matrix(*a)), frames.frame_matrix(*a))


def test_frame_errors():
    with pytest.raises(ValueError, match=r"axes\[1\] is the zero vector"):
        frames.frame_matrix([0, 0, 0], [[1, 0, 0], [0, 0, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="parallel"):
        frames.world_to_frame([0, 0, 0], [[1, 0, 0], [-2, 0, 0], [0, 0, 1]])
    with pytest.raises(ValueError, match="coplanar"):
        frames.frame_matrix([0, 0, 0], [[1, 0, 0], [0, 1, 0], [1, 1, 0]])
    with pytest.raises(ValueError, match="one axis per row"):
        frames.frame_matrix([0, 0], [[1, 0, 0], [0, 1, 0]])
    with pytest.raises(ValueError, match="origin"):
        frames.frame_matrix([0, 0], np.eye(3))
    with pytest.raises(ValueError, match="at least one"):
        frames.chain()
    with pytest.raises(ValueError, match="do not mix"):
        frames.chain(np.eye(3), np.eye(4))


# ---------------------------------------------------------------------------------------------
# Mirrors and scaling about a point
# ---------------------------------------------------------------------------------------------

def test_mirror_plane_against_householder_and_trimesh():
    c, n = np.array([1.0, 2.0, -1.0]), np.array([1.0, 2.0, 2.0])
    M = frames.mirror_plane(c, n)
    assert np.allclose(M, tt.reflection_matrix(c, n))
    u = n / 3.0
    H = np.eye(3) - 2 * np.outer(u, u)
    rng = np.random.default_rng(1)
    for p in rng.normal(size=(5, 3)):
        by_hand = c + H @ (p - c)
        assert np.allclose(transforms.apply(M, p), by_hand)
    assert np.allclose(M @ M, np.eye(4)) and np.isclose(np.linalg.det(M), -1.0)


def test_mirror_line_matches_the_composite():
    c, phi = np.array([1.0, -2.0]), math.radians(30)
    expected = (transforms.translate(c) @ transforms.rotate(phi) @ transforms.mirror("x")
                @ transforms.rotate(-phi) @ transforms.translate(-c))
    assert np.allclose(frames.mirror_line(c, [math.cos(phi), math.sin(phi)]), expected)


def test_scale_about_against_composition_by_hand():
    c, s = np.array([1.0, 2.0, 3.0]), np.array([2.0, -1.0, 0.5])
    T = np.eye(4)
    T[:3, 3] = c
    Ti = np.eye(4)
    Ti[:3, 3] = -c
    assert np.allclose(frames.scale_about(c, s), T @ np.diag(np.append(s, 1)) @ Ti)
    assert np.allclose(frames.scale_about(c, s) @ np.append(c, 1), np.append(c, 1))
    assert np.allclose(frames.scale_about([1, 1], 2) @ [3, 1, 1], [5, 1, 1])


def test_mirror_and_scale_errors():
    with pytest.raises(ValueError, match="normal must not be the zero vector"):
        frames.mirror_plane([0, 0, 0], [0, 0, 0])
    with pytest.raises(ValueError, match="direction must not be the zero vector"):
        frames.mirror_line([0, 0], [0, 0])
    with pytest.raises(ValueError, match="point"):
        frames.mirror_plane([0, 0], [0, 0, 1])
    with pytest.raises(ValueError, match="factors"):
        frames.scale_about([0, 0], [1, 2, 3])


# ---------------------------------------------------------------------------------------------
# Is it a rotation?
# ---------------------------------------------------------------------------------------------

EXAM = [[0, -3, 0], [3, 0, 0], [0, 0, 3]]


def test_exam_matrix_both_readings():
    d = frames.describe_linear(EXAM)
    assert d.is_rotation and d.w == 3.0 and math.isclose(d.angle_deg, 90.0)
    assert "w = 3" in d.text and "90" in d.text
    lin = frames.describe_linear(EXAM, homogeneous=False)
    assert not lin.is_rotation and lin.kind == "scaled rotation"
    assert math.isclose(lin.factor, 3.0) and math.isclose(lin.angle_deg, 90.0)
    assert np.allclose(lin.axis, [0, 0, 1])
    # the homogeneous reading maps (x, y, 1) to (-3y, 3x, 3) = (-y, x, 1)
    assert np.allclose(transforms.apply(EXAM, [2.0, 5.0]), [-5.0, 2.0])


@pytest.mark.parametrize("axis,angle", [([1, 2, 2], 0.9), ([0, 3, 4], math.pi), ([1, 0, 0], 2.0)])
def test_3d_rotations_angle_and_axis(axis, angle):
    from scipy.spatial.transform import Rotation
    R = Rotation.from_rotvec(np.array(axis) / np.linalg.norm(axis) * angle).as_matrix()
    M = np.eye(4) * 2.0
    M[:3, :3] = 2.0 * R
    d = frames.describe_linear(M)
    assert d.is_rotation and math.isclose(d.angle_deg, math.degrees(angle))
    u = np.array(axis) / np.linalg.norm(axis)
    assert np.isclose(abs(d.axis @ u), 1.0)


def test_other_kinds():
    assert frames.describe_linear(transforms.mirror("x")).kind == "mirror"
    assert frames.describe_linear(np.diag([2.0, -2.0, 1.0])).kind == "scaled mirror"
    assert frames.describe_linear(transforms.shear_x(1.0)).kind == "other"
    assert frames.describe_linear(np.diag([2.0, 1.0])  , homogeneous=False).kind == "other"
    moved = transforms.translate([1, 0]) @ transforms.rotate(0.5)
    assert frames.describe_linear(moved).kind == "rigid motion"
    assert not frames.is_rotation(moved)
    assert frames.is_rotation(transforms.rotate(-0.5) * -2.0)      # w = -2 divides out
    assert frames.is_rotation(np.eye(3), homogeneous=False)


def test_describe_errors():
    with pytest.raises(ValueError, match="2x2, which cannot be homogeneous"):
        frames.describe_linear(np.eye(2))
    with pytest.raises(ValueError, match="projective"):
        frames.describe_linear([[1, 0, 0], [0, 1, 0], [0, 1, 1]])
    with pytest.raises(ValueError, match="projective"):
        frames.is_rotation(np.diag([1.0, 1.0, 0.0]))
