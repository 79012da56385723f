"""Tests of the asymptotic decider (scivis.contour_lines), gradient normals and the volume
rendering methods of course_lib/scivis/volume_methods.py.

Cross-checks: the deciders against a fine sampling of the bilinear interpolant (which corners
the region f >= c connects, by scipy.ndimage.label) and against scikit-image's find_contours
(fully_connected "high"/"low" is a fixed saddle rule: it must agree with the asymptotic decider
cell by cell where that decider says the same); the gradient against numpy.gradient and the
analytic normal of a distance field; slicing and splatting against the course's ray casting
with the error bounds stated in each test.
"""
import numpy as np
import pytest
from scipy import ndimage
from skimage.measure import find_contours

from course_lib import scivis
from course_lib.colormaps import TransferFunction
from course_lib.scivis import volume_methods as vm
from course_lib.scivis.contour_lines import asymptotic_decider, isolines, marching_squares


# ---------------------------------------------------------------------------------------------
# The asymptotic decider
# ---------------------------------------------------------------------------------------------

def bilinear_joins_above(f, c, n=801):
    """Do the two above corners of a saddle cell lie in one connected piece of {f >= c}?
    f = (f0, f1, f2, f3) counter-clockwise from the bottom left; sampled on an n x n grid."""
    s, t = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))   # rows: t (y), cols: s (x)
    g = f[0] * (1 - s) * (1 - t) + f[1] * s * (1 - t) + f[2] * s * t + f[3] * (1 - s) * t
    labels, _ = ndimage.label(g >= c)
    corners = {0: labels[0, 0], 1: labels[0, -1], 2: labels[-1, -1], 3: labels[-1, 0]}
    above = [k for k in range(4) if f[k] >= c]
    return corners[above[0]] == corners[above[1]]


def test_the_worked_example_0_4_0_10_at_3():
    saddle, above = asymptotic_decider([0, 4, 0, 10], 3)
    assert saddle == pytest.approx(40 / 14) and above is False          # (0*0 - 4*10)/(0-14)
    assert np.mean([0, 4, 0, 10]) >= 3                                  # the midpoint: joined
    field = np.array([[0.0, 4.0], [10.0, 0.0]])                         # f0 f1 / f3 f2
    mid = marching_squares(field, 3)
    asy = marching_squares(field, 3, decider="asymptotic")
    assert not np.allclose(mid, asy)
    assert not bilinear_joins_above(np.array([0, 4, 0, 10.0]), 3)     # the field agrees


def test_decider_agrees_with_the_sampled_bilinear_interpolant():
    rng = np.random.default_rng(3)
    checked = disagree_midpoint = 0
    while checked < 60:
        f = rng.uniform(0, 10, 4)
        c = rng.uniform(2, 8)
        up = f >= c
        if not ((up[0] == up[2]) and (up[1] == up[3]) and up[0] != up[1]):
            continue
        saddle, above = asymptotic_decider(f, c)
        if abs(saddle - c) < 0.05:                  # too close for the sampled picture
            continue
        assert above == bilinear_joins_above(f, c), (f, c)
        disagree_midpoint += (f.mean() >= c) != above
        checked += 1
    assert disagree_midpoint > 0                    # the midpoint decider does differ sometimes


def test_decider_vectorises_and_rejects_bad_input():
    s, a = asymptotic_decider([[0, 4, 0, 10], [3, 0, 3, 0]], 1)
    assert np.allclose(s, [40 / 14, 9 / 6]) and a.tolist() == [True, True]
    with pytest.raises(ValueError, match="corners"):
        asymptotic_decider([1, 2, 3], 1)
    with pytest.raises(ValueError, match="no saddle"):
        asymptotic_decider([1, 2, 3, 2], 1)
    with pytest.raises(ValueError, match="decider"):
        marching_squares([[0, 1], [1, 0]], 0.5, decider="mean")


def _segment_set(segs):
    return sorted(tuple(np.round(np.sort(s, axis=0).ravel(), 6)) for s in segs)


def test_marching_squares_asymptotic_matches_find_contours_per_saddle_rule():
    rng = np.random.default_rng(0)
    field = rng.uniform(0, 1, (12, 12))
    c = 0.5
    cases = scivis.marching_squares_cases(field, c)
    saddle = np.isin(cases, (5, 10))
    f = field
    corners = np.stack([f[:-1, :-1], f[:-1, 1:], f[1:, 1:], f[1:, :-1]], -1)[saddle]
    above = asymptotic_decider(corners, c)[1]
    assert above.any() and (~above).any()
    # skimage joins the high corners of every saddle with "high", the low ones with "low"
    for rule, keep in (("high", above), ("low", ~above)):
        ours = marching_squares(field, c, decider="asymptotic", cells=_cells(saddle, keep))
        theirs = []
        for line in find_contours(field, c, fully_connected=rule):
            pts = line[:, ::-1]                                        # (row, col) -> (x, y)
            for a, b in zip(pts[:-1], pts[1:]):
                mid = 0.5 * (a + b)
                cx, cy = np.floor(mid).astype(int)
                if _cells(saddle, keep)[cy, cx]:
                    theirs.append(np.array([a, b]))
        assert _segment_set(ours) == _segment_set(theirs)
    # away from saddles the deciders change nothing
    mid = marching_squares(field, c, cells=~saddle)
    asy = marching_squares(field, c, cells=~saddle, decider="asymptotic")
    assert np.array_equal(mid, asy)
    assert len(isolines(field, c, decider="asymptotic")) > 0


def _cells(saddle, keep):
    mask = np.zeros_like(saddle)
    mask[np.nonzero(saddle)[0][keep], np.nonzero(saddle)[1][keep]] = True
    return mask


# ---------------------------------------------------------------------------------------------
# Gradients as normals
# ---------------------------------------------------------------------------------------------

def test_gradient_is_numpy_gradient_with_one_sided_borders():
    rng = np.random.default_rng(1)
    vol = rng.normal(size=(5, 6, 7))
    sp = (0.5, 2.0, 1.5)
    ours = scivis.gradient(vol, sp)
    gz, gy, gx = np.gradient(vol, sp[2], sp[1], sp[0], edge_order=1)
    assert np.allclose(ours[..., 0], gx) and np.allclose(ours[..., 1], gy)
    assert np.allclose(ours[..., 2], gz)


def test_isosurface_normals_of_a_distance_field_point_outward():
    sphere = scivis.example_volume("sphere", size=32)      # f = 0.6 - |p|
    v, t = scivis.marching_cubes(sphere.values, 0.0, sphere.spacing, sphere.origin)
    n = vm.isosurface_normals(sphere.values, v, sphere.spacing, sphere.origin)
    exact = v / np.linalg.norm(v, axis=1, keepdims=True)
    assert np.allclose(np.linalg.norm(n, axis=1), 1)
    assert np.degrees(np.arccos(np.clip((n * exact).sum(1), -1, 1))).max() < 3.0
    # the gradient normals beat the triangles' own normals at the same vertices
    fn = np.cross(v[t[:, 1]] - v[t[:, 0]], v[t[:, 2]] - v[t[:, 0]])
    fn /= np.linalg.norm(fn, axis=1, keepdims=True)
    centres = v[t].mean(axis=1)
    face_err = np.arccos(np.clip((fn * centres / np.linalg.norm(centres, axis=1,
                                                                keepdims=True)).sum(1), -1, 1))
    vert_err = np.arccos(np.clip((n * exact).sum(1), -1, 1))
    assert vert_err.mean() < face_err.mean()
    with pytest.raises(ValueError, match="vertices"):
        vm.isosurface_normals(sphere.values, [1, 2, 3])


def test_gradient_shading_and_opacity():
    out = vm.gradient_shading([[1, 1, 1], [1, 1, 1]], [[0, 0, 5], [0, 0, 0]], light=(0, 0, 1),
                              ambient=0.2, diffuse=0.5)
    assert np.allclose(out, [[0.7] * 3, [0.7] * 3])
    tilted = vm.gradient_shading([[1, 1, 1]], [[0, 3, 4]], light=(0, 0, 1), ambient=0.0,
                                 diffuse=1.0)
    assert np.allclose(tilted, 0.8)                                      # cos = 4/5
    assert np.allclose(vm.gradient_opacity([1.0], [[0, 0, 0.25]], 0.5), 0.5)
    with pytest.raises(ValueError, match="shape"):
        vm.gradient_shading([[1, 1, 1]], [[1, 1]])
    with pytest.raises(ValueError, match="scale"):
        vm.gradient_opacity([1.0], [[0, 0, 1]], 0)


# ---------------------------------------------------------------------------------------------
# Slicing and splatting against ray casting
# ---------------------------------------------------------------------------------------------

BLOBS = scivis.example_volume("blobs", size=24)
VIEW = dict(rotation=scivis.view_rotation(0.5, -0.3), image_size=(32, 32),
            spacing=BLOBS.spacing, origin=BLOBS.origin, extent="sphere")
#: opaque enough to matter: translucent blue for middling values, red for high ones
TF = TransferFunction([0.0, 0.3, 0.6, 1.0], [[0, 0, 0, 0], [0.1, 0.3, 1.0, 0.3],
                                             [1.0, 0.5, 0.2, 0.6], [1.0, 0.1, 0.1, 0.9]])


def _values():
    v = BLOBS.values
    return (v - v.min()) / (v.max() - v.min())


def _raycast(step=None):
    return scivis.volume_render(_values(), TF, step=step, early_termination=None, **VIEW).rgb


@pytest.mark.parametrize("slices", ["view", "axis"])
def test_slicing_is_close_to_ray_casting(slices):
    img = vm.slice_render(_values(), TF, slices=slices, **VIEW).rgb
    assert np.abs(img - _raycast()).mean() < 0.01


def test_slicing_converges_to_ray_casting_as_the_spacing_shrinks():
    ref = _raycast(step=0.004)
    errors = [np.abs(vm.slice_render(_values(), TF, slice_spacing=h, **VIEW).rgb - ref).mean()
              for h in (0.16, 0.08, 0.04, 0.02)]
    assert all(b < a for a, b in zip(errors, errors[1:])), errors
    assert errors[-1] < 0.1 * errors[0] and errors[-1] < 2e-3


def test_splatting_is_close_to_ray_casting():
    img = vm.splat_render(_values(), TF, **VIEW).rgb
    assert np.abs(img - _raycast()).mean() < 0.03


def test_compositing_order_and_operator():
    # two slabs at different depths: blue (value 0.5) in front of red (value 1)
    vol = np.zeros((12, 12, 12))
    vol[7:10, 3:9, 3:9] = 0.5                            # large z: in front (the eye is on +z)
    vol[2:5, 3:9, 3:9] = 1.0
    tf = TransferFunction([0.0, 0.25, 0.5, 0.75, 1.0], [[0, 0, 0, 0], [0, 0, 0, 0],
                                                        [0, 0, 1, 0.8], [0, 0, 0, 0],
                                                        [1, 0, 0, 0.8]])
    geo = dict(image_size=(12, 12), extent="fit")
    btf = vm.splat_render(vol, tf, order="back-to-front", **geo).rgb
    ftb = vm.splat_render(vol, tf, order="front-to-back", **geo).rgb
    wrong = vm.splat_render(vol, tf, order="front-to-back", operator="over", **geo).rgb
    assert np.allclose(btf, ftb)
    centre = btf[6, 6]
    assert centre[2] > centre[0]                       # blue (the front blob) wins
    assert wrong[6, 6, 0] > wrong[6, 6, 2]             # the wrong pairing shows the back one
    assert np.abs(wrong - btf).mean() > 0.05
    # the same with three layers by hand
    c = np.array([[0.5, 0, 0], [0, 0.25, 0], [0, 0, 0.1]])  # premultiplied, front first
    a = np.array([0.5, 0.5, 0.2])
    C, A = np.zeros(3), 0.0
    for ci, ai in zip(c, a):                               # front to back, under
        C, A = C + (1 - A) * ci, A + (1 - A) * ai
    C2, A2 = np.zeros(3), 0.0
    for ci, ai in zip(c[::-1], a[::-1]):                   # back to front, over
        C2, A2 = ci + (1 - ai) * C2, ai + (1 - ai) * A2
    assert np.allclose(C, C2) and np.isclose(A, A2)


def test_pre_and_post_classification():
    sharp = TransferFunction([0.0, 0.499, 0.5, 1.0], [[1, 1, 1, 0], [1, 1, 1, 0],
                                                      [1, 0.8, 0.6, 1], [1, 0.8, 0.6, 1]])
    pre = vm.slice_render(_values(), sharp, classification="pre", **VIEW).rgb
    post = vm.slice_render(_values(), sharp, classification="post", **VIEW).rgb
    assert np.abs(pre - post).max() > 0.1
    linear = TransferFunction([0.0, 1.0], [[0.2, 0.6, 0.9, 0.0], [0.2, 0.6, 0.9, 0.8]])
    pre = vm.slice_render(_values(), linear, classification="pre", **VIEW).rgb
    post = vm.slice_render(_values(), linear, classification="post", **VIEW).rgb
    assert np.allclose(pre, post, atol=1e-12)


def test_compare_renderers_reports_all_three():
    c = vm.compare_renderers(_values(), TF, rotation=VIEW["rotation"], image_size=(24, 24),
                             spacing=BLOBS.spacing, origin=BLOBS.origin)
    assert set(c.images) == set(c.times) == set(c.differences) == {"ray casting", "slicing",
                                                                  "splatting"}
    assert c.differences["ray casting"] == 0 and c.differences["slicing"] < 0.01
    assert all(t > 0 for t in c.times.values())


def test_bad_input_is_named():
    with pytest.raises(ValueError, match="volume"):
        vm.splat_render(np.ones((4, 4)))
    with pytest.raises(ValueError, match="volume"):
        vm.slice_render(np.full((3, 3, 3), np.nan))
    with pytest.raises(ValueError, match="spacing"):
        vm.slice_render(np.ones((3, 3, 3)), spacing=(1, 0, 1))
    with pytest.raises(ValueError, match="spacing"):
        vm.splat_render(np.ones((3, 3, 3)), spacing=(1, -1, 1))
    with pytest.raises(ValueError, match="kernel_radius"):
        vm.splat_render(np.ones((3, 3, 3)), kernel_radius=0)
    with pytest.raises(ValueError, match="slice_spacing"):
        vm.slice_render(np.ones((3, 3, 3)), slice_spacing=-0.1)
    with pytest.raises(ValueError, match="classification"):
        vm.slice_render(np.ones((3, 3, 3)), classification="middle")
    with pytest.raises(ValueError, match="order"):
        vm.splat_render(np.ones((3, 3, 3)), order="sideways")


@pytest.mark.parametrize("azimuth, elevation", [(0.0, 0.0), (0.5, -0.3), (1.2, 0.4),
                                                (2.5, -1.0)])
def test_shear_warp_is_close_to_ray_casting_from_any_side(azimuth, elevation):
    view = dict(VIEW, rotation=scivis.view_rotation(azimuth, elevation))
    ref = scivis.volume_render(_values(), TF, early_termination=None, **view).rgb
    sw = vm.shear_warp(_values(), TF, **view).rgb
    axis = vm.slice_render(_values(), TF, slices="axis", **view).rgb
    assert np.abs(sw - ref).mean() < 0.004          # measured 0.0009-0.0013 (image mean 0.02)
    # the same samples as axis-aligned slicing, up to the warp's one extra resampling
    assert np.abs(sw - axis).mean() < 0.004
    with pytest.raises(ValueError, match="spacing"):
        vm.shear_warp(_values(), TF, spacing=(0, 1, 1))
