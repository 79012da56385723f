"""Texture matrices against chapter 3's matrices, scikit-image's AffineTransform and scipy's
ndimage.affine_transform; the inverse relation (the picture moves opposite to the matrix)."""
import numpy as np
import pytest
from scipy import ndimage
from skimage.transform import AffineTransform

from course_lib import transforms
from course_lib.texturing import texture_transforms as tt
from course_lib.texturing import nearest_sample


def test_texture_matrix_is_the_composition_and_skimage_agrees():
    m = tt.texture_matrix(tiling=(2, 3), offset=(0.1, -0.2), rotation=0.4, center=(0.5, 0.5),
                          shear=0.3)
    expected = transforms.compose(transforms.shear_x(0.3),
                                  transforms.rotate_about(0.4, [0.5, 0.5]),
                                  transforms.scale([2, 3]), transforms.translate([0.1, -0.2]))
    assert np.allclose(m, expected)
    # scikit-image builds the same rotation about the centre from its own parts
    c = AffineTransform(translation=(-0.5, -0.5))
    r = AffineTransform(rotation=0.4)
    back = AffineTransform(translation=(0.5, 0.5))
    sk = (back.params @ r.params @ c.params)
    assert np.allclose(tt.texture_matrix(rotation=0.4), sk)
    rng = np.random.default_rng(1)
    uv = rng.uniform(-1, 2, (50, 2))
    full = AffineTransform(matrix=m)(uv)
    u2, v2 = tt.apply_texture_matrix(m, uv[:, 0], uv[:, 1])
    assert np.allclose(np.stack([u2, v2], -1), full)


def test_tile_two_by_three_then_rotate_quarter_turn_about_centre_closed_form():
    m = transforms.compose(tt.tile(2, 3), transforms.rotate_about(np.pi / 2, [0.5, 0.5]))
    # typed by hand: (u, v) -> (2u, 3v) -> rotate 90 deg about (1/2, 1/2): (1 - 3v, 2u)
    u, v = 0.2, 0.1
    assert np.allclose(m @ [u, v, 1], [0.5 - (3 * v - 0.5), 0.5 + (2 * u - 0.5), 1])
    wrong = transforms.compose(transforms.rotate_about(np.pi / 2, [0.5, 0.5]), tt.tile(2, 3))
    assert not np.allclose(m, wrong)


def test_the_picture_moves_opposite_to_the_offset():
    tex = np.zeros((8, 8))
    tex[0, 0] = 1.0                                   # a marked texel at u, v in [0, 1/8)
    moved = tt.transform_texture(tex, tt.texture_matrix(offset=(0.25, 0)), filter="nearest",
                                 wrap="repeat")
    i, j = np.argwhere(moved == 1.0)[0]
    assert (i, j) == (0, 6)                           # u - 0.25 = -0.25 = 0.75 -> column 6
    assert np.array_equal(moved, np.roll(tex, -2, axis=1))
    # two repeats each way: the marked 2x2 block appears 2 x 2 times at half its size (1 texel)
    tiled = tt.transform_texture(np.kron(tex, np.ones((2, 2))), tt.tile(2), filter="nearest")
    assert tiled.sum() == 4
    assert tiled[0, 0] == tiled[0, 8] == tiled[8, 0] == tiled[8, 8] == 1


def test_resampling_against_scipy_affine_transform():
    rng = np.random.default_rng(3)
    tex = rng.random((32, 32))
    m = tt.texture_matrix(tiling=1.5, rotation=0.3, offset=(0.05, 0.1))
    ours = tt.transform_texture(tex, m, wrap="repeat", filter="bilinear")
    # scipy maps output array index (y, x) to input index: x = u W - 1/2, so
    # x_in = W (M u)_0 - 1/2 with u = (x + 1/2) / W; the same for y; A in (row, col) order
    h, w = tex.shape
    to_uv = np.array([[0, 1 / w, 0.5 / w], [1 / h, 0, 0.5 / h], [0, 0, 1]])  # (y, x, 1) -> (u, v, 1)
    from_uv = np.array([[0, h, -0.5], [w, 0, -0.5], [0, 0, 1]])             # (u, v, 1) -> (y, x, 1)
    a = from_uv @ m @ to_uv
    ref = ndimage.affine_transform(tex, a, order=1, mode="grid-wrap")
    assert np.allclose(ours, ref, atol=1e-9)


def test_nearest_texel_matches_sampling_the_transformed_coordinates():
    tex = np.arange(16.0).reshape(4, 4)
    m = tt.texture_matrix(rotation=np.pi / 2)
    out = tt.transform_texture(tex, m, filter="nearest")
    assert np.array_equal(out, np.rot90(tex, k=-1)) or np.array_equal(out, np.rot90(tex, k=1))
    # by hand: output texel (i, j) = (0, 0) at (1/8, 1/8) -> rotated about the centre by +90:
    # (1 - 1/8, 1/8) -> input column 3, row 0
    assert out[0, 0] == tex[0, 3] == nearest_sample(tex, 7 / 8, 1 / 8)


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="repeats_u must not be 0"):
        tt.tile(0)
    with pytest.raises(ValueError, match="tiling"):
        tt.texture_matrix(tiling=(1, 2, 3))
    with pytest.raises(ValueError, match="offset"):
        tt.texture_matrix(offset=(np.nan, 0))
    with pytest.raises(ValueError, match="matrix must be affine"):
        tt.apply_texture_matrix([[1, 0, 0], [0, 1, 0], [1, 0, 1]], 0.5, 0.5)
    with pytest.raises(ValueError, match="matrix must be a 3x3"):
        tt.apply_texture_matrix(np.eye(4), 0.5, 0.5)
    with pytest.raises(ValueError, match="filter must be one of 'bilinear', 'nearest'"):
        tt.transform_texture(np.zeros((2, 2)), np.eye(3), filter="cubic")
    with pytest.raises(ValueError, match="wrap"):
        tt.transform_texture(np.zeros((2, 2)), np.eye(3), wrap="tile")
    with pytest.raises(ValueError, match="u must be finite"):
        tt.apply_texture_matrix(np.eye(3), np.inf, 0.5)
