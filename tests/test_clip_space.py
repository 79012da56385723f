"""Clipping in homogeneous coordinates (course_lib.clip_space).

Independent references:

* outcodes: the six inequalities -w <= x, y, z <= w typed out one by one;
* segments entirely in front of the eye (w > 0): clipping after the divide
  (course_lib.clipping.liang_barsky on [-1, 1]^3, itself tested against VTK's vtkBox), random;
* segments crossing the eye plane: the world-space segment clipped by VTK (vtkClipPolyData once
  per frustum plane, planes from the camera matrix), compared with the clip-space result mapped
  back through the inverse of projection @ view;
* Sutherland-Hodgman in clip space: shapely's intersection of a triangle in the plane z = 0
  (w = 1) with the square [-1, 1]^2, and, for a triangle crossing the eye plane, VTK clipping of
  the world-space triangle.
"""
import numpy as np
import pytest
import shapely
import vtk

from course_lib import clip_space, clipping, transforms, viewing

CAMERA = (viewing.perspective(np.radians(50), 1.2, 1.0, 10.0)
          @ viewing.look_at([0.5, -0.3, 4.0], [-0.1, 0.05, -1.0], [0.0, 1.0, 0.0]))


def typed_outcode(p):
    x, y, z, w = p
    return ((x < -w) * 1 + (x > w) * 2 + (y < -w) * 4 + (y > w) * 8 + (z < -w) * 16
            + (z > w) * 32)


def test_outcode_against_typed_inequalities():
    rng = np.random.default_rng(1)
    points = rng.uniform(-3, 3, (400, 4))
    points[:50, 3] = rng.uniform(0.1, 0.4, 50)              # many outside
    points[50:60] = np.round(points[50:60])                 # ties: on the boundary is inside
    codes = clip_space.clip_outcode(points)
    assert codes.tolist() == [typed_outcode(p) for p in points]


def test_outcode_examples_by_hand():
    assert clip_space.clip_outcode([1, 2, -3, 2]) == 16            # z < -w (y = w is inside)
    assert clip_space.clip_outcode([1, 2.5, -3, 2]) == 8 + 16       # y > w, z < -w
    assert clip_space.clip_outcode([2, -2, 2, 2]) == 0             # on the boundary
    assert clip_space.clip_outcode([0, 0, 0, -1]) == 63            # behind the eye: every bit
    assert clip_space.clip_outcode([0.5, 0, 0, -1]) == 63


def test_outcode_with_positive_w_equals_the_divided_outcode():
    rng = np.random.default_rng(2)
    p = rng.uniform(-3, 3, (300, 4))
    p[:, 3] = rng.uniform(0.2, 3, 300)
    assert np.array_equal(clip_space.clip_outcode(p),
                          clipping.outcode(p[:, :3] / p[:, 3:], -np.ones(3), np.ones(3)))


def test_segments_in_front_of_the_eye_match_clipping_after_the_divide():
    rng = np.random.default_rng(3)
    box = (-np.ones(3), np.ones(3))
    for _ in range(300):
        a, b = rng.uniform(-2.5, 2.5, (2, 4))
        a[3], b[3] = rng.uniform(0.3, 2.0, 2)
        r = clip_space.clip_segment_homogeneous(a, b)
        after = clipping.liang_barsky(a[:3] / a[3], b[:3] / b[3], *box)
        assert (r["clipped"] is None) == (after is None)
        if after is not None:
            ours = np.array([q[:3] / q[3] for q in r["clipped"]])
            assert np.allclose(ours, after, atol=1e-9)
        # the divide-first route agrees here too
        wrong = clip_space.clip_after_divide(a, b)
        assert not wrong["crosses_eye_plane"]
        assert (wrong["clipped"] is None) == (after is None)


def test_pairs_for_w_one_equal_the_box_table():
    rng = np.random.default_rng(4)
    for _ in range(50):
        a, b = rng.uniform(-2, 2, (2, 3))
        rows_h = clip_space.clip_segment_homogeneous([*a, 1], [*b, 1])["rows"]
        rows = clip_space.liang_barsky_table(a, b)
        # closed form: left p = -(bx - ax), q = ax + 1; right p = bx - ax, q = 1 - ax; ...
        d = b - a
        typed = [(-d[0], a[0] + 1), (d[0], 1 - a[0]), (-d[1], a[1] + 1), (d[1], 1 - a[1]),
                 (-d[2], a[2] + 1), (d[2], 1 - a[2])]
        assert np.allclose([(r["p"], r["q"]) for r in rows], typed)
        assert np.allclose([(r["p"], r["q"]) for r in rows_h], typed)
        # the rows clipping.liang_barsky_steps computes before it stops agree
        _, steps = clipping.liang_barsky_steps(a, b, -np.ones(3), np.ones(3))
        assert np.allclose([(s["p"], s["q"]) for s in steps], typed[:len(steps)])


def vtk_clip_world(points, planes):
    """Clip a segment or polygon (world coordinates) by each plane n.x <= c with VTK.

    VTK stores points in single precision: compare to about 1e-6.
    """
    pts = vtk.vtkPoints()
    for p in points:
        pts.InsertNextPoint(*map(float, p))
    cells = vtk.vtkCellArray()
    cells.InsertNextCell(len(points))
    for i in range(len(points)):
        cells.InsertCellPoint(i)
    poly = vtk.vtkPolyData()
    poly.SetPoints(pts)
    if len(points) == 2:
        poly.SetLines(cells)
    else:
        poly.SetPolys(cells)
    for _, n, c in planes:
        plane = vtk.vtkPlane()
        plane.SetNormal(*map(float, n))
        plane.SetOrigin(*map(float, n * c / (n @ n)))
        clip = vtk.vtkClipPolyData()
        clip.SetInputData(poly)
        clip.SetClipFunction(plane)
        clip.InsideOutOn()                     # keep n.(x - o) <= 0
        clip.Update()
        poly = clip.GetOutput()
    clean = vtk.vtkCleanPolyData()             # drop the points no cell uses any more
    clean.SetInputData(poly)
    clean.Update()
    out = clean.GetOutput().GetPoints()
    return np.zeros((0, 3)) if out is None else np.array(
        [out.GetPoint(i) for i in range(out.GetNumberOfPoints())])


def eye_depth(p):
    """Clip-space w of a world point (positive in front of the eye)."""
    return (CAMERA @ [*p, 1.0])[3]


@pytest.mark.parametrize("seed", range(6))
def test_segments_crossing_the_eye_plane_against_vtk(seed):
    rng = np.random.default_rng(10 + seed)
    planes = clipping.view_volume_planes(CAMERA)
    inverse = np.linalg.inv(CAMERA)
    eye = np.array([0.5, -0.3, 4.0])
    checked = 0
    while checked < 8:
        inside = transforms.apply(inverse, rng.uniform(-0.8, 0.8, 3))   # a point in the frustum
        behind = eye + rng.uniform(-2, 2, 3) + np.array([0.0, 0.0, 3.0])
        if eye_depth(behind) > -0.2:
            continue
        a, b = (inside, behind) if rng.random() < 0.5 else (behind, inside)
        r = clip_space.clip_segment_homogeneous(CAMERA @ [*a, 1], CAMERA @ [*b, 1])
        assert r["clipped"] is not None
        ours = transforms.apply(inverse, np.array(r["clipped"])[:, :3]
                                / np.array(r["clipped"])[:, 3:])
        # the same points directly: the world segment at t_in, t_out
        assert np.allclose(ours, [a + r["t_in"] * (b - a), a + r["t_out"] * (b - a)])
        reference = vtk_clip_world([a, b], planes)
        assert len(reference) == 2
        assert np.allclose(sorted(map(tuple, ours)), sorted(map(tuple, reference)), atol=1e-6)
        wrong = clip_space.clip_after_divide(CAMERA @ [*a, 1], CAMERA @ [*b, 1])
        assert wrong["crosses_eye_plane"]
        assert np.allclose(wrong["correct"], transforms.apply(CAMERA, ours))
        checked += 1


def test_clip_after_divide_goes_wrong_across_the_eye_plane():
    """Typed example: from the centre of the screen to a point behind the eye."""
    a, b = np.array([0.0, 0.0, 0.5, 1.0]), np.array([2.0, 0.0, 0.5, -1.0])
    r = clip_space.clip_after_divide(a, b)
    # by hand: f_right = w - x goes 1 -> -3, p = 4, q = 1, t = 1/4; f_far = w - z: 0.5 -> -1.5,
    # t = 1/4; the bottom/top/near rows give t = 1/2, 1/2, 3/4: t_out = 1/4 -> (0.5, 0, 0.5, 0.5)
    assert np.allclose(r["correct"], [[0, 0, 0.5], [1, 0, 1]])
    assert np.allclose(r["ndc"][1], [-2, 0, -0.5])            # mirrored through the centre
    assert np.allclose(r["clipped"], [[0, 0, 0.5], [-1, 0, 0]])   # the wrong side of the screen


def test_segment_entirely_behind_the_eye_is_rejected():
    r = clip_space.clip_segment_homogeneous([0.1, 0, 0, -1], [-0.2, 0.3, 0.1, -2])
    assert r["clipped"] is None and r["codes"] == (63, 63)
    # after the divide both land inside the cube: the wrong route keeps them
    wrong = clip_space.clip_after_divide([0.1, 0, 0, -1], [-0.2, 0.3, 0.1, -2])
    assert wrong["clipped"] is not None and wrong["correct"] is None


def test_polygon_in_a_plane_against_shapely():
    rng = np.random.default_rng(5)
    square = shapely.box(-1, -1, 1, 1)
    for _ in range(40):
        tri = rng.uniform(-2.5, 2.5, (3, 2))
        w = rng.uniform(0.5, 2.0)
        tri_h = np.column_stack([tri * w, np.zeros(3), np.full(3, w)])     # same NDC points
        ours = clip_space.clip_polygon_homogeneous(tri_h)
        expected = shapely.Polygon(tri).intersection(square)
        if len(ours) < 3:
            assert expected.area < 1e-9
            continue
        ndc = ours[:, :2] / ours[:, 3:]
        assert np.isclose(shapely.Polygon(ndc).area, expected.area, atol=1e-9)
        assert shapely.Polygon(ndc).symmetric_difference(expected).area < 1e-9


def test_triangle_crossing_the_eye_plane_against_vtk():
    inverse = np.linalg.inv(CAMERA)
    a = transforms.apply(inverse, [-0.5, -0.2, 0.3])
    b = transforms.apply(inverse, [0.6, 0.1, -0.4])
    c = np.array([0.5, -0.3, 4.0]) + [0.3, 0.2, 2.0]                  # behind the eye
    assert eye_depth(c) < 0
    steps = clip_space.clip_polygon_homogeneous_steps([CAMERA @ [*p, 1] for p in (a, b, c)])
    assert [name for name, _ in steps] == list(clipping.BIT_NAMES)
    ours = steps[-1][1]
    assert np.all(ours[:, 3] > 0)
    world = transforms.apply(inverse, ours[:, :3] / ours[:, 3:])
    reference = vtk_clip_world([a, b, c], clipping.view_volume_planes(CAMERA))
    # our vertices are among VTK's (VTK's triangulation may add a point on an edge)
    distance = np.linalg.norm(world[:, None] - reference[None], axis=-1)
    assert distance.min(axis=1).max() < 1e-5                     # VTK's points are float32
    # and the same area: VTK's triangles against Newell's formula for our polygon
    newell = 0.5 * np.linalg.norm(np.cross(world, np.roll(world, -1, axis=0)).sum(axis=0))
    assert np.isclose(newell, vtk_area([a, b, c], clipping.view_volume_planes(CAMERA)),
                      rtol=1e-6)


def vtk_area(points, planes):
    pts = vtk.vtkPoints()
    for p in points:
        pts.InsertNextPoint(*map(float, p))
    tri = vtk.vtkCellArray()
    tri.InsertNextCell(3)
    for i in range(3):
        tri.InsertCellPoint(i)
    poly = vtk.vtkPolyData()
    poly.SetPoints(pts)
    poly.SetPolys(tri)
    for _, n, c in planes:
        plane = vtk.vtkPlane()
        plane.SetNormal(*map(float, n))
        plane.SetOrigin(*map(float, n * c / (n @ n)))
        clip = vtk.vtkClipPolyData()
        clip.SetInputData(poly)
        clip.SetClipFunction(plane)
        clip.InsideOutOn()
        clip.Update()
        poly = clip.GetOutput()
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputData(poly)
    mass = vtk.vtkMassProperties()
    mass.SetInputConnection(triangles.GetOutputPort())
    mass.Update()
    return mass.GetSurfaceArea()


def test_errors():
    with pytest.raises(ValueError, match="p0_h.*4 coordinates"):
        clip_space.clip_segment_homogeneous([1, 2, 3], [1, 2, 3, 1])
    with pytest.raises(ValueError, match="both have w = 0"):
        clip_space.clip_segment_homogeneous([1, 0, 0, 0], [0, 1, 0, 0])
    with pytest.raises(ValueError, match="zero vector"):
        clip_space.clip_outcode([[0, 0, 0, 0]])
    with pytest.raises(ValueError, match="single homogeneous points"):
        clip_space.clip_segment_homogeneous([[1, 2, 3, 1]] * 2, [1, 2, 3, 1])
    with pytest.raises(ValueError, match="p1_h has w = 0"):
        clip_space.clip_after_divide([0, 0, 0, 1], [1, 0, 0, 0])
    with pytest.raises(ValueError, match="at least 3 vertices"):
        clip_space.clip_polygon_homogeneous([[0, 0, 0, 1], [1, 0, 0, 1]])
    with pytest.raises(TypeError, match="poly_h must be numbers"):
        clip_space.clip_polygon_homogeneous("triangle")
    with pytest.raises(ValueError, match="finite"):
        clip_space.boundary_values([np.nan, 0, 0, 1])
    with pytest.raises(ValueError, match="3 coordinates"):
        clip_space.liang_barsky_table([0, 0], [1, 1], [-1, -1], [1, 1])


def test_one_end_at_infinity():
    # from the centre towards the point at infinity in direction +x: leaves through the right
    r = clip_space.clip_segment_homogeneous([0, 0, 0, 1], [1, 0, 0, 0])
    assert np.isclose(r["t_out"], 0.5)                      # w - x: 1 -> -1
    assert np.allclose(r["clipped"][1][:3] / r["clipped"][1][3], [1, 0, 0])


def test_table_text_lists_six_rows():
    text = clip_space.table_text(clip_space.liang_barsky_table([-2, 0.5, 0], [2, 0.5, 3]))
    lines = text.splitlines()
    assert len(lines) == 7 and [ln.split()[0] for ln in lines[1:]] == list(clipping.BIT_NAMES)


def test_many_segments_match_one_at_a_time():
    rng = np.random.default_rng(7)
    a, b = rng.uniform(-3, 3, (2, 400, 4))
    a[:100, 3] = np.abs(a[:100, 3])
    q0, q1, t, visible = clip_space.clip_segments_homogeneous(a, b)
    for i in range(len(a)):
        r = clip_space.clip_segment_homogeneous(a[i], b[i])
        assert visible[i] == (r["clipped"] is not None)
        if visible[i]:
            assert np.allclose(t[i], [r["t_in"], r["t_out"]])
            assert np.allclose([q0[i], q1[i]], r["clipped"])
    assert 20 < visible.sum() < 380
    with pytest.raises(ValueError, match="segment 1 has w = 0 at both ends"):
        clip_space.clip_segments_homogeneous([[0, 0, 0, 1], [1, 0, 0, 0]],
                                             [[1, 0, 0, 1], [0, 1, 0, 0]])
    with pytest.raises(ValueError, match=r"shape \(n, 4\)"):
        clip_space.clip_segments_homogeneous([0, 0, 0, 1], [1, 0, 0, 1])
