"""Tests of the concept questions: structure, the checker, and the facts they state.

The second half checks the facts that can be computed, each tied to the key of the question it
proves, against independent libraries (numpy, scipy, shapely, trimesh, scikit-image,
matplotlib's colour maps) or closed-form hand calculations.
"""
import itertools
import math

import numpy as np
import pytest
from scipy.interpolate import BSpline
from scipy.spatial import ConvexHull, Delaunay
from scipy.spatial.transform import Rotation

from course_lib.exercises import concepts
from course_lib.exercises.concepts import QUESTIONS, ConceptQuestion, questions
from course_lib.exercises.core import UNANSWERED, Feedback

CHAPTERS = (3, 4, 5, 6, 7, 10, 12, 14, 15, 18)
ALL = questions()
BY_KEY = {q.key: q for q in ALL}
IDS = [q.key for q in ALL]


def truth(key):
    """What the question `key` claims: True/False for a true/false question."""
    q = BY_KEY[key]
    assert q.kind == "true/false"
    return q.correct == 0


def answer_text(key):
    return BY_KEY[key].options[BY_KEY[key].correct]


# ---------------------------------------------------------------------------------------------
# Structure
# ---------------------------------------------------------------------------------------------

def test_every_chapter_has_at_least_eight():
    assert tuple(sorted(QUESTIONS)) == CHAPTERS
    for chapter in CHAPTERS:
        assert len(QUESTIONS[chapter]) >= 8, chapter
        assert all(q.chapter == chapter for q in QUESTIONS[chapter])
        assert questions(chapter) == list(QUESTIONS[chapter])


def test_keys_unique_and_stable_form():
    assert len(BY_KEY) == len(ALL)
    for q in ALL:
        assert q.key.startswith(f"ch{q.chapter:02d}-"), q.key
        assert q.key == q.key.lower() and " " not in q.key


@pytest.mark.parametrize("q", ALL, ids=IDS)
def test_question_well_formed(q):
    assert q.kind in concepts.KINDS
    assert len(q.options) == len(q.explanations) >= 2
    assert len({o.strip().lower() for o in q.options}) == len(q.options)
    assert all(e.strip() for e in q.explanations)
    assert 0 <= q.correct < len(q.options)
    if q.kind == "true/false":
        assert q.options == ("True", "False")
    else:
        assert len(q.options) >= 3
    # no option's text is also another option's letter (the forms must not clash)
    for i, text in enumerate(q.options):
        assert text.strip().lower() not in q.letters
        # nor the index of another option
        assert text.strip() not in {str(j) for j in range(len(q.options)) if j != i}


def test_correct_positions_are_mixed():
    for chapter in CHAPTERS:
        mc = [q.correct for q in QUESTIONS[chapter] if q.kind == "multiple choice"]
        assert len(set(mc)) >= 3, chapter
    tf = [q.correct for q in ALL if q.kind == "true/false"]
    assert 0.2 < sum(tf) / len(tf) < 0.8


def test_questions_rejects_unknown_chapter():
    with pytest.raises(ValueError, match="chapter"):
        questions(8)
    with pytest.raises(ValueError, match="chapter"):
        questions("7")


def test_constructor_rejects_inconsistent_fields():
    good = dict(chapter=3, key="x", kind="multiple choice", prompt="?", options=("a1", "b1"),
                correct=0, explanations=("e1", "e2"))
    ConceptQuestion(**good)
    for bad in (dict(correct=2), dict(correct=True), dict(explanations=("e1",)),
                dict(options=("same", "Same")), dict(kind="essay"),
                dict(kind="true/false")):
        with pytest.raises((ValueError, TypeError)):
            ConceptQuestion(**{**good, **bad})


# ---------------------------------------------------------------------------------------------
# The checker
# ---------------------------------------------------------------------------------------------

def right_forms(q):
    i = q.correct
    letter = q.letters[i]
    forms = [i, np.int64(i), float(i), letter, letter.upper(), f"({letter})", f"{letter})",
             q.options[i], q.options[i].upper(), "  " + q.options[i].lower() + " "]
    if q.kind == "true/false":
        word = q.options[i]
        forms += [word == "True", np.bool_(word == "True"), word.lower(), word[0].lower(),
                  word[0]]
    return forms


@pytest.mark.parametrize("q", ALL, ids=IDS)
def test_check_accepts_every_form_of_the_right_answer(q):
    for form in right_forms(q):
        fb = q.check(form)
        assert isinstance(fb, Feedback)
        assert fb.status == "correct", (form, fb)
        assert q.explanations[q.correct] in fb.message


@pytest.mark.parametrize("q", ALL, ids=IDS)
def test_check_rejects_every_wrong_option_with_its_explanation(q):
    for i, option in enumerate(q.options):
        if i == q.correct:
            continue
        for form in (i, q.letters[i], q.letters[i].upper(), option):
            fb = q.check(form)
            assert fb.status == "wrong" and not fb
            assert fb.diagnosis == f"option {q.letters[i]}"
            assert q.explanations[i] in fb.message
            assert q.explanations[q.correct] in fb.message
            assert fb.message.index(q.explanations[i]) < fb.message.index(
                q.explanations[q.correct])


def test_numeric_option_text():
    q = BY_KEY["ch18-mc-cases"]
    assert q.check(15) and q.check("15") and q.check(15.0)
    assert q.check(23).diagnosis == "option d"
    assert q.check(16).status == "invalid"


def test_true_false_forms():
    q = BY_KEY["ch03-quat-double-cover"]           # true
    for form in (True, "true", "TRUE", "t", "T", "a", 0, "True"):
        assert q.check(form).status == "correct", form
    for form in (False, "false", "f", "F", "b", 1, "False"):
        assert q.check(form).status == "wrong", form
    q = BY_KEY["ch03-quat-commute"]                # false
    assert q.check(False) and q.check("f") and q.check("false")
    assert not q.check(True) and not q.check("t")


@pytest.mark.parametrize("q", [QUESTIONS[7][0], QUESTIONS[4][0]], ids=lambda q: q.key)
def test_unanswered_is_the_exercises_message(q):
    for blank in (..., None):
        fb = q.check(blank)
        assert fb.status == "unanswered" and fb.message == UNANSWERED


@pytest.mark.parametrize("q", [BY_KEY["ch05-backface-sign"], BY_KEY["ch07-bspline-degree"]],
                         ids=lambda q: q.key)
def test_unreadable_answers_say_what_is_accepted(q):
    n = len(q.options)
    for bad in ("zz", "maybe", n, -1, 1.5, [0], {"a": 1}, object(), "", b"a"):
        fb = q.check(bad)
        assert fb.status == "invalid", bad
        assert "letter" in fb.message and "index" in fb.message and "text" in fb.message
    if q.kind == "multiple choice":
        assert q.check(True).status == "invalid"   # a bool is no option of a 4-way question
    else:
        assert "True" in q.check("maybe").message


def test_display():
    q = BY_KEY["ch04-fov"]
    md = q._repr_markdown_()
    assert q.prompt in md
    for letter, option in zip("abcd", q.options):
        assert f"**({letter})** {option}" in md
    assert "Chapter 4" in md and q.key in md
    assert repr(q) == "ConceptQuestion('ch04-fov')"


def test_frozen():
    q = ALL[0]
    with pytest.raises(AttributeError):
        q.correct = 0


# ---------------------------------------------------------------------------------------------
# The facts, verified independently (each tied to the question key it proves)
# ---------------------------------------------------------------------------------------------

RNG = np.random.default_rng(20240610)


def random_affine(dim=2):
    while True:
        A = RNG.normal(size=(dim, dim))
        if abs(np.linalg.det(A)) > 0.2:
            return A, RNG.normal(size=dim)


def test_fact_ch03_affine_preserves():
    assert answer_text("ch03-affine-preserves") == "Ratios of lengths along one line"
    length_changed = angle_changed = area_changed = 0
    for _ in range(50):
        A, t = random_affine()
        a, b = RNG.normal(size=(2, 2))
        s = RNG.uniform()
        p = (1 - s) * a + s * b
        fa, fb, fp = A @ a + t, A @ b + t, A @ p + t
        # the image point divides the image segment in the same ratio
        assert math.isclose(np.linalg.norm(fp - fa) / np.linalg.norm(fb - fa), s, rel_tol=1e-9)
        length_changed += not math.isclose(np.linalg.norm(fb - fa), np.linalg.norm(b - a))
        e1, e2 = A @ [1, 0], A @ [0, 1]
        angle_changed += abs(e1 @ e2) > 1e-6
        area_changed += not math.isclose(abs(np.linalg.det(A)), 1.0)
    assert length_changed and angle_changed and area_changed


def test_fact_ch03_affine_parallel():
    assert truth("ch03-affine-parallel")
    for _ in range(20):
        A, t = random_affine(3)
        d, p, q = RNG.normal(size=(3, 3))
        d1 = (A @ (p + d) + t) - (A @ p + t)
        d2 = (A @ (q + 2 * d) + t) - (A @ q + t)
        assert np.allclose(np.cross(d1, d2), 0, atol=1e-9)


def test_fact_ch03_compose_and_inverse():
    assert not truth("ch03-compose-commute")
    R = Rotation.from_euler("z", 0.7).as_matrix()
    T = np.eye(4)
    T[:3, 3] = [1, 2, 0]
    R4 = np.eye(4)
    R4[:3, :3] = R
    assert not np.allclose(T @ R4, R4 @ T)
    assert answer_text("ch03-inverse-rotation").startswith("$R^T$")
    for R in Rotation.random(10, random_state=1).as_matrix():
        assert np.allclose(R.T @ R, np.eye(3)) and not np.allclose(R @ R, np.eye(3))


def explanation_of(key, option_start):
    """The explanation of the option of question `key` whose text starts with `option_start`."""
    q = BY_KEY[key]
    matches = [e for o, e in zip(q.options, q.explanations) if o.startswith(option_start)]
    assert len(matches) == 1, (key, option_start)
    return matches[0]


def test_fact_ch03_minus_r_is_the_inverse_only_for_2d_quarter_turns():
    why = explanation_of("ch03-inverse-rotation", "$-R$")
    assert "In 3D it never is" in why and "\\pm 90°" in why and "R^2 = -I" in why
    # 2D, explicit matrices: a quarter turn either way squares to -I, so (-R) R = I there ...
    for theta in (np.pi / 2, -np.pi / 2):
        c, s = math.cos(theta), math.sin(theta)
        R = np.array([[c, -s], [s, c]])
        assert np.allclose(R @ R, -np.eye(2))
        assert np.allclose((-R) @ R, np.eye(2)) and np.allclose(-R, R.T)
    # ... and for no other 2D angle
    for theta in np.linspace(0.1, 2 * np.pi - 0.1, 50):
        if min(abs(theta - np.pi / 2), abs(theta - 3 * np.pi / 2)) < 1e-6:
            continue
        c, s = math.cos(theta), math.sin(theta)
        R = np.array([[c, -s], [s, c]])
        assert not np.allclose((-R) @ R, np.eye(2))
    # 3D: det(-R R) = (-1)^3 det(R)^2 = -1, never the identity (random rotations by scipy)
    for R in Rotation.random(50, random_state=4).as_matrix():
        M = (-R) @ R
        assert math.isclose(np.linalg.det(M), -1.0) and not np.allclose(M, np.eye(3))


def test_fact_ch03_quaternions():
    # scipy is scalar-last (x, y, z, s)
    assert truth("ch03-quat-double-cover") and not truth("ch03-quat-commute")
    for quat in Rotation.random(20, random_state=2).as_quat():
        assert np.allclose(Rotation.from_quat(quat).as_matrix(),
                           Rotation.from_quat(-quat).as_matrix())
    a, b = Rotation.random(2, random_state=3)
    assert not np.allclose((a * b).as_quat(), (b * a).as_quat())
    # half angle: (cos θ/2, sin θ/2 n) is the rotation by θ about n
    theta, n = 1.1, np.array([2.0, -1.0, 2.0]) / 3
    assert "\\cos\\tfrac\\theta2" in answer_text("ch03-quat-half-angle")
    q = np.r_[np.sin(theta / 2) * n, np.cos(theta / 2)]
    assert np.allclose(Rotation.from_quat(q).as_rotvec(), theta * n)
    # the top-left entry of the rotation matrix is 1 - 2y² - 2z², not 1 - 2y²
    assert answer_text("ch03-quat-matrix-entry") == "$1 - 2y^2 - 2z^2$"
    for x, y, z, s in Rotation.random(20, random_state=4).as_quat():
        m00 = Rotation.from_quat([x, y, z, s]).as_matrix()[0, 0]
        assert math.isclose(m00, 1 - 2 * y * y - 2 * z * z, abs_tol=1e-12)
    x, y, z, s = Rotation.from_euler("z", 1.0).as_quat()
    assert not math.isclose(Rotation.from_quat([x, y, z, s]).as_matrix()[0, 0], 1 - 2 * y * y)


def perspective(points, d=1.0):
    """Project onto the plane z = d through the origin (hand formula x d / z)."""
    points = np.asarray(points, dtype=float)
    return points[..., :2] * d / points[..., 2:3]


def cross_ratio(a, b, c, d):
    return (np.linalg.norm(c - a) * np.linalg.norm(d - b)) / (
        np.linalg.norm(c - b) * np.linalg.norm(d - a))


def test_fact_ch04_perspective_ratios_lines_cross_ratio():
    assert not truth("ch04-perspective-ratios") and truth("ch04-affine-cross-ratio")
    assert answer_text("ch04-projective-preserves").startswith("Straight lines")
    moved = 0
    for _ in range(30):
        a = RNG.uniform([-1, -1, 2], [1, 1, 4])
        b = RNG.uniform([-1, -1, 6], [1, 1, 9])
        ts = np.array([0.0, 0.3, 0.5, 0.8, 1.0])
        pts = a + ts[:, None] * (b - a)
        img = perspective(pts)
        # straight lines stay straight: all images collinear
        assert np.linalg.matrix_rank(img[1:] - img[0], tol=1e-9) == 1
        # the midpoint does not go to the midpoint
        moved += not np.allclose(img[2], (img[0] + img[4]) / 2, atol=1e-6)
        # cross ratio of four collinear points is kept
        assert math.isclose(cross_ratio(*pts[[0, 1, 3, 4]]), cross_ratio(*img[[0, 1, 3, 4]]),
                            rel_tol=1e-9)
    assert moved == 30
    # parallel lines meet at a vanishing point
    d = np.array([1.0, 0.5, 1.0])
    far = perspective(np.array([[0, 0, 1.0], [1, 0, 1.0]]) + 1e7 * d)
    assert np.allclose(far[0], far[1], atol=1e-6)


def test_fact_ch04_depth_and_fov():
    assert not truth("ch04-perspective-depth-nonlinear")
    n, f = 1.0, 10.0
    ze = -np.linspace(n, f, 7)
    # OpenGL-style depth: z_ndc = (f + n)/(f - n) + 2 f n / ((f - n) z_e)
    zndc = (f + n) / (f - n) + 2 * f * n / ((f - n) * ze)
    assert np.allclose(zndc[[0, -1]], [-1, 1])
    assert np.all(np.diff(zndc) > 0)
    assert not np.allclose(np.diff(zndc), np.diff(zndc)[0])      # not linear
    assert answer_text("ch04-fov") == "$t = n \\tan\\tfrac\\theta2$"
    theta = np.radians(60)
    corner = np.array([0.0, n * np.tan(theta / 2), -n])
    angle = np.degrees(np.arccos(corner @ [0, 0, -1] / np.linalg.norm(corner)))
    assert math.isclose(2 * angle, 60)


def test_fact_ch05_backface_sign_by_ray_casting():
    import trimesh
    assert answer_text("ch05-backface-sign") == "When $\\vec v \\cdot \\vec n > 0$"
    mesh = trimesh.creation.icosphere(subdivisions=2)
    eye = np.array([0.3, -0.2, 4.0])
    centers = mesh.triangles_center
    v = centers - eye
    back = np.einsum("ij,ij->i", v, mesh.face_normals) > 0
    # independent: the first face hit by the ray from the eye to each centre
    hit = mesh.ray.intersects_first(np.repeat(eye[None], len(centers), 0),
                                    v / np.linalg.norm(v, axis=1, keepdims=True))
    seen = hit == np.arange(len(centers))
    assert back.any() and (~back).any()
    edge_on = np.abs(np.einsum("ij,ij->i", v / np.linalg.norm(v, axis=1, keepdims=True),
                               mesh.face_normals)) < 0.05
    assert np.array_equal(seen[~edge_on], ~back[~edge_on])


def outcode(p, lo=(0.0, 0.0), hi=(1.0, 1.0)):
    x, y = p
    return (x < lo[0]) | (x > hi[0]) << 1 | (y < lo[1]) << 2 | (y > hi[1]) << 3


def test_fact_ch05_cohen_sutherland_by_shapely():
    from shapely.geometry import LineString, box
    assert "reject" in answer_text("ch05-cohen-sutherland")
    assert not truth("ch05-cs-or-nonzero")
    window = box(0, 0, 1, 1)
    rejected = missed_with_zero_and = 0
    for _ in range(2000):
        a, b = RNG.uniform(-1, 2, size=(2, 2))
        c1, c2 = outcode(a), outcode(b)
        hits = LineString([a, b]).intersects(window)
        if c1 & c2:
            rejected += 1
            assert not hits
        elif not hits:
            missed_with_zero_and += 1
        if not (c1 | c2):
            assert window.contains(LineString([a, b]))
    assert rejected > 100 and missed_with_zero_and > 0


def test_fact_ch05_liang_barsky_by_shapely():
    from shapely.geometry import LineString, box
    assert "largest entering" in answer_text("ch05-liang-barsky")
    window = box(0, 0, 1, 1)
    for _ in range(500):
        p0, p1 = RNG.uniform(-1, 2, size=(2, 2))
        d = p1 - p0
        tE, tL = 0.0, 1.0
        for p, q in ((-d[0], p0[0]), (d[0], 1 - p0[0]), (-d[1], p0[1]), (d[1], 1 - p0[1])):
            if abs(p) < 1e-15:
                if q < 0:
                    tE, tL = 1.0, 0.0
                continue
            t = q / p
            if p < 0:
                tE = max(tE, t)
            else:
                tL = min(tL, t)
        clipped = LineString([p0, p1]).intersection(window)
        if tE > tL:
            assert clipped.length < 1e-9
        else:
            assert math.isclose(clipped.length, (tL - tE) * np.linalg.norm(d), abs_tol=1e-9)


def test_fact_ch06_euler_and_edges():
    import trimesh
    assert "2 - 2g" in answer_text("ch06-euler-genus") and truth("ch06-euler-sphere")
    assert truth("ch06-closed-triangle-count") and answer_text("ch06-manifold-edge") == \
        "Exactly two"
    for mesh, genus in ((trimesh.creation.icosphere(3), 0), (trimesh.creation.box(), 0),
                        (trimesh.creation.cylinder(1, 2, sections=17), 0),
                        (trimesh.creation.torus(2, 0.5), 1)):
        V, E, F = len(mesh.vertices), len(mesh.edges_unique), len(mesh.faces)
        assert mesh.is_watertight
        assert V - E + F == 2 - 2 * genus == mesh.euler_number
        assert 3 * F == 2 * E
        counts = np.bincount(mesh.edges_unique_inverse, minlength=E)
        assert np.all(counts == 2)


def test_fact_ch06_halfedge_twin():
    assert truth("ch06-halfedge-twin") and not truth("ch06-halfedge-nonmanifold")
    import trimesh
    mesh = trimesh.creation.icosphere(1)
    halves = [(int(f[i]), int(f[(i + 1) % 3])) for f in mesh.faces for i in range(3)]
    index = {h: k for k, h in enumerate(halves)}
    assert len(index) == len(halves)
    twin = np.array([index[(b, a)] for a, b in halves])
    assert np.array_equal(twin[twin], np.arange(len(halves)))
    # a fin: three triangles on edge (0, 1) need three halves of one edge, one too many
    fin = [(0, 1, 2), (1, 0, 3), (0, 1, 4)]
    fin_halves = [(f[i], f[(i + 1) % 3]) for f in fin for i in range(3)]
    assert len(fin_halves) != len(set(fin_halves))


def bernstein_curve(P, t):
    n = len(P) - 1
    t = np.asarray(t)[:, None]
    return sum(math.comb(n, i) * t ** i * (1 - t) ** (n - i) * P[i] for i in range(n + 1))


def test_fact_ch07_bezier_convex_hull_endpoints_tangent():
    assert truth("ch07-bezier-convex-hull")
    assert answer_text("ch07-bezier-endpoints") == "The first and the last"
    assert answer_text("ch07-bezier-tangent") == "$n(P_1 - P_0)$"
    t = np.linspace(0, 1, 201)
    for n in range(2, 7):
        P = RNG.normal(size=(n + 1, 2))
        C = bernstein_curve(P, t)
        hull = Delaunay(P[ConvexHull(P).vertices])
        assert np.all(hull.find_simplex(C, tol=1e-9) >= 0)
        assert np.allclose(C[0], P[0]) and np.allclose(C[-1], P[-1])
        h = 1e-6
        deriv = (bernstein_curve(P, [h]) - bernstein_curve(P, [0.0]))[0] / h
        assert np.allclose(deriv, n * (P[1] - P[0]), atol=1e-4)


def test_fact_ch07_affine_but_not_projective():
    assert truth("ch07-bezier-affine") and not truth("ch07-bezier-projective")
    t = np.linspace(0, 1, 11)
    P = RNG.uniform([-1, -1, 2], [1, 1, 6], size=(4, 3))
    A, s = random_affine(3)
    assert np.allclose(bernstein_curve(P @ A.T + s, t), bernstein_curve(P, t) @ A.T + s)
    assert not np.allclose(bernstein_curve(perspective(P), t),
                           perspective(bernstein_curve(P, t)), atol=1e-3)
    # a rational curve with weights w_i = z_i of the projected points is the projected curve
    w = P[:, 2]
    Q = perspective(P)
    B = np.stack([math.comb(3, i) * t ** i * (1 - t) ** (3 - i) for i in range(4)], 1)
    rational = (B * w) @ Q / (B @ w)[:, None]
    assert np.allclose(rational, perspective(bernstein_curve(P, t)))


def test_fact_ch07_bspline_degree_local_hull_continuity():
    assert not truth("ch07-bspline-degree") and truth("ch07-bspline-strong-hull")
    assert "p + 1" in answer_text("ch07-bspline-local")
    assert answer_text("ch07-bspline-continuity") == "$C^{p-k}$"
    p = 3
    for n_ctrl in (4, 6, 9):
        knots = np.r_[[0] * p, np.linspace(0, 1, n_ctrl - p + 1), [1] * p]
        spline = BSpline(knots, RNG.normal(size=(n_ctrl, 2)), p)
        assert spline.k == p                         # the degree stays p
    n_ctrl = 8
    knots = np.r_[[0] * p, np.linspace(0, 1, n_ctrl - p + 1), [1] * p]
    C = RNG.normal(size=(n_ctrl, 2))
    u = np.linspace(0, 1, 801)[:-1]
    i = 3
    C2 = C.copy()
    C2[i] += [1.0, -2.0]
    changed = np.any(np.abs(BSpline(knots, C2, p)(u) - BSpline(knots, C, p)(u)) > 1e-12,
                     axis=1)
    assert np.all((u[changed] >= knots[i]) & (u[changed] < knots[i + p + 1]))
    assert changed.any()
    # strong convex hull: the points of span [u_j, u_j+1) lie in the hull of P_{j-p..j}
    curve = BSpline(knots, C, p)
    for j in range(p, n_ctrl):
        uu = np.linspace(knots[j], knots[j + 1], 30, endpoint=False)
        hull = Delaunay(C[j - p:j + 1])
        assert np.all(hull.find_simplex(curve(uu), tol=1e-9) >= 0)
    # a double knot inside a cubic: C1 but not C2 there
    knots = np.array([0, 0, 0, 0, 1, 2, 2, 3, 4, 4, 4, 4], dtype=float)
    curve = BSpline(knots, RNG.normal(size=(len(knots) - p - 1, 2)), p)
    eps = 1e-7
    for order, continuous in ((0, True), (1, True), (2, False)):
        d = curve.derivative(order) if order else curve
        jump = np.abs(d(2 - eps) - d(2 + eps)).max()
        assert (jump < 1e-4) == continuous


def test_fact_ch07_rational_circle():
    assert "rational" in answer_text("ch07-rational-circle").lower()
    assert truth("ch07-rational-weights-one")
    P = np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    t = np.linspace(0, 1, 101)
    B = np.stack([(1 - t) ** 2, 2 * t * (1 - t), t ** 2], 1)
    w = np.array([1, math.sqrt(2) / 2, 1])
    arc = (B * w) @ P / (B @ w)[:, None]
    assert np.allclose(np.linalg.norm(arc, axis=1), 1)
    assert not np.allclose(np.linalg.norm(bernstein_curve(P, t), axis=1), 1, atol=1e-2)
    # equal weights: the polynomial curve
    w = np.full(3, 2.7)
    assert np.allclose((B * w) @ P / (B @ w)[:, None], bernstein_curve(P, t))


def test_fact_ch10_normalize():
    assert answer_text("ch10-normalize").endswith("+ n_{min}$")
    i = RNG.uniform(3, 9, 50)
    lo, hi = 10.0, 30.0
    out = (i - i.min()) / (i.max() - i.min()) * (hi - lo) + lo
    assert math.isclose(out.min(), lo) and math.isclose(out.max(), hi)
    assert np.allclose(out, np.interp(i, [i.min(), i.max()], [lo, hi]))


def test_fact_ch10_rainbow_lightness():
    import matplotlib
    from skimage.color import rgb2lab
    assert not truth("ch10-rainbow") and truth("ch10-lightness-order")
    x = np.linspace(0, 1, 256)
    L = {name: rgb2lab(matplotlib.colormaps[name](x)[None, :, :3])[0, :, 0]
         for name in ("jet", "viridis")}
    assert np.all(np.diff(L["viridis"]) > 0)
    assert np.any(np.diff(L["jet"]) > 0.1) and np.any(np.diff(L["jet"]) < -0.1)


def test_fact_ch12_phong_terms():
    assert answer_text("ch12-phong-view-dependent") == "The specular term"
    assert not truth("ch12-diffuse-view") and truth("ch12-specular-exponent")
    n = np.array([0.0, 0.0, 1.0])
    light = np.array([1.0, 0.0, 1.0]) / math.sqrt(2)
    r = 2 * (n @ light) * n - light
    views = RNG.normal(size=(50, 3))
    views[:, 2] = np.abs(views[:, 2]) + 0.1
    views /= np.linalg.norm(views, axis=1, keepdims=True)
    diffuse = np.full(len(views), max(0.0, n @ light))    # no view in the formula
    assert np.ptp(diffuse) == 0
    spec = np.clip(views @ r, 0, None)
    assert np.ptp(spec) > 0.1
    # higher exponent: narrower lobe (smaller solid angle above half maximum)
    angles = np.linspace(0, np.pi / 2, 1000)
    widths = [angles[np.cos(angles) ** e >= 0.5].max() for e in (5, 50)]
    assert widths[1] < widths[0]
    # Blinn: n.h = 1 exactly when v is the mirror direction r
    h = (light + r) / np.linalg.norm(light + r)
    assert math.isclose(n @ h, 1.0)


def test_fact_ch12_radiometry():
    """Inverse square, the steradian count of the sphere and the constancy of radiance, from
    first principles with scipy's numerical integration."""
    from scipy.integrate import dblquad
    assert "quarter" in answer_text("ch12-inverse-square")
    # irradiance under a small lamp of intensity I: E = I / d^2, the flux through a small disk
    # of the desk over its area
    I, a = 3.0, 1e-3
    for d in (1.0, 2.0):
        flux = dblquad(lambda r, phi: I * d / (d * d + r * r) ** 1.5 * r, 0, 2 * np.pi, 0, a)[0]
        E = flux / (np.pi * a * a)
        assert math.isclose(E, I / d**2, rel_tol=1e-5)
    assert "4\\pi" in answer_text("ch12-solid-angle-unit")
    sphere = dblquad(lambda theta, phi: np.sin(theta), 0, 2 * np.pi, 0, np.pi)[0]
    assert math.isclose(sphere, 4 * np.pi, rel_tol=1e-12)
    # a square emitter of side s, radiance L, seen along its normal from d: the flux on a unit
    # receiver falls like 1/d^2, the solid angle too, and their ratio (the radiance) stays L
    assert truth("ch12-radiance-distance")
    L, side = 2.0, 0.01
    ratios = []
    for d in (1.0, 3.0):
        cos4 = lambda y, x: d**2 / (x * x + y * y + d * d) ** 2     # cos_s cos_l / r^2
        E = L * dblquad(cos4, -side / 2, side / 2, -side / 2, side / 2)[0]
        omega = dblquad(lambda y, x: d / (x * x + y * y + d * d) ** 1.5, -side / 2, side / 2,
                        -side / 2, side / 2)[0]
        ratios.append(E / omega)
    assert np.allclose(ratios, L, rtol=1e-4)


def test_fact_ch12_brdfs():
    from scipy.integrate import dblquad
    hemisphere = lambda f: dblquad(lambda t, p: f(t, p) * np.cos(t) * np.sin(t), 0, 2 * np.pi,
                                   0, np.pi / 2)[0]
    assert "1/sr" in answer_text("ch12-brdf-definition")
    rho = 0.7
    assert answer_text("ch12-lambert-brdf") == "$\\rho / \\pi$"
    assert math.isclose(hemisphere(lambda t, p: rho / np.pi), rho, rel_tol=1e-10)
    assert hemisphere(lambda t, p: rho / (2 * np.pi)) < rho < hemisphere(lambda t, p: rho)
    # Phong normalisation at normal incidence: alpha = theta
    assert "2\\pi/(n+2)" in answer_text("ch12-phong-normalisation")
    for n in (1, 10, 50):
        raw = hemisphere(lambda t, p: np.cos(t) ** n)
        assert math.isclose(raw, 2 * np.pi / (n + 2), rel_tol=1e-8)
        assert math.isclose((n + 2) / (2 * np.pi) * raw, 1.0, rel_tol=1e-8)
    # reciprocity: modified Phong cos^n(alpha) is symmetric; the original one is not
    assert truth("ch12-reciprocity")
    nrm = np.array([0.0, 0.0, 1.0])
    l, v = RNG.normal(size=(2, 200, 3))
    l[:, 2], v[:, 2] = np.abs(l[:, 2]) + 0.1, np.abs(v[:, 2]) + 0.1
    l /= np.linalg.norm(l, axis=1, keepdims=True)
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    cos_alpha = lambda a, b: np.clip(np.sum((2 * a[:, 2:3] * nrm - a) * b, axis=1), 0, None)
    assert np.allclose(cos_alpha(l, v) ** 8, cos_alpha(v, l) ** 8)
    original = lambda a, b: cos_alpha(a, b) ** 8 / a[:, 2]
    assert not np.allclose(original(l, v), original(v, l))
    # Fresnel for glass (n = 1.5), unpolarised, from Fresnel's equations typed here
    def fresnel(theta, eta=1.5):
        st = np.sin(theta) / eta
        ct = np.sqrt(1 - st * st)
        ci = np.cos(theta)
        rs = (ci - eta * ct) / (ci + eta * ct)
        rp = (eta * ci - ct) / (eta * ci + ct)
        return 0.5 * (rs * rs + rp * rp)
    assert "rises towards 1" in answer_text("ch12-fresnel-grazing")
    assert math.isclose(fresnel(0.0), 0.04, rel_tol=1e-12)
    assert fresnel(np.radians(89.9)) > 0.98
    assert np.all(np.diff(fresnel(np.radians(np.linspace(60, 89.9, 50)))) > 0)


def test_fact_ch12_light_colours():
    from course_lib import shading
    assert answer_text("ch12-light-colours").startswith("Red, with a white highlight")
    # the model typed out: white k_d, grey k_s under a red diffuse, white specular light
    kd, ks, Id, Is = np.ones(3), 0.5, np.array([1.0, 0, 0]), np.ones(3)
    diffuse = kd * Id * 0.8
    highlight = ks * Is * 1.0
    assert diffuse[1] == diffuse[2] == 0 and np.ptp(highlight) == 0
    lamp = shading.directional_light([0.6, 0, 0.8], diffuse=Id, specular=Is)
    t = shading.phong(None, [0, 0, 1], [-0.6, 0, 0.8], lamp,
                      shading.Material(ka=0, kd=1, ks=ks, shininess=10))
    assert np.allclose(t.diffuse, diffuse) and np.allclose(t.specular, highlight)


def test_fact_ch14_barycentric_and_mipmap():
    from shapely.geometry import Polygon
    assert truth("ch14-barycentric-sum")
    for _ in range(20):
        A, B, C = RNG.normal(size=(3, 2))
        lam = RNG.dirichlet([1, 1, 1])
        P = lam[0] * A + lam[1] * B + lam[2] * C
        whole = Polygon([A, B, C]).area
        areas = [Polygon([P, B, C]).area, Polygon([A, P, C]).area, Polygon([A, B, P]).area]
        assert np.allclose(np.array(areas) / whole, lam)
    assert "a third" in answer_text("ch14-mipmap")
    size = 1024
    levels = [size >> k for k in range(11)]
    extra = sum(s * s for s in levels[1:]) / size ** 2
    assert extra < 1 / 3 and math.isclose(extra, 1 / 3, rel_tol=1e-5)


def test_fact_ch15_reflection_refraction_sphere():
    assert answer_text("ch15-reflect") == "$\\vec d - 2(\\vec d \\cdot \\hat n)\\hat n$"
    for _ in range(20):
        n = RNG.normal(size=3)
        n /= np.linalg.norm(n)
        d = RNG.normal(size=3)
        r = d - 2 * (d @ n) * n
        assert math.isclose(np.linalg.norm(r), np.linalg.norm(d))
        assert math.isclose(r @ n, -(d @ n))
        # Householder reflection: the same thing as a matrix
        assert np.allclose((np.eye(3) - 2 * np.outer(n, n)) @ d, r)
    assert "41.8" in answer_text("ch15-tir")
    critical = math.degrees(math.asin(1 / 1.5))
    assert math.isclose(critical, 41.81, abs_tol=0.01)
    for angle, refracts in ((40.0, True), (43.0, False)):
        assert (1.5 * math.sin(math.radians(angle)) <= 1) == refracts
    assert truth("ch15-sphere-quadratic")
    import trimesh
    sphere = trimesh.creation.icosphere(5)
    for _ in range(20):
        o = RNG.normal(size=3) * 3
        d = RNG.normal(size=3)
        d /= np.linalg.norm(d)
        b = 2 * d @ o
        c = o @ o - 1
        disc = b * b - 4 * c
        if abs(disc) < 0.1:
            continue
        hits, _, _ = sphere.ray.intersects_location([o], [d])
        ahead = disc > 0 and (-b + math.sqrt(disc)) / 2 > 0
        assert (len(hits) > 0) == ahead


def test_fact_ch15_reflect_with_the_wrong_sign_triples_the_normal_part():
    why = explanation_of("ch15-reflect", "$\\vec d + 2")
    assert "keeps the tangential component and triples the normal one" in why
    rng = np.random.default_rng(15)            # its own generator: the shared RNG's draws stay put
    for _ in range(50):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        d = rng.normal(size=3)
        normal = (d @ n) * n
        tangential = d - normal
        wrong = d + 2 * (d @ n) * n
        wrong_normal = (wrong @ n) * n
        assert np.allclose(wrong - wrong_normal, tangential)        # tangential part unchanged
        assert np.allclose(wrong_normal, 3 * normal)                # normal part tripled
        assert not math.isclose(np.linalg.norm(wrong), np.linalg.norm(d))   # length not kept
    # along the surface (d . n = 0) nothing changes at all, the only case with the length kept
    n, d = np.array([0.0, 0.0, 1.0]), np.array([1.0, 2.0, 0.0])
    assert np.allclose(d + 2 * (d @ n) * n, d)


def test_fact_ch18_marching_squares_and_cubes_cases():
    assert "Two" in answer_text("ch18-ms-ambiguous")
    # corners in order around the square: ambiguous when the pattern alternates
    ambiguous = [c for c in range(16)
                 if all(((c >> i) & 1) != ((c >> ((i + 1) % 4)) & 1) for i in range(4))]
    assert len(ambiguous) == 2
    assert answer_text("ch18-mc-cases") == "15"
    corners = np.array(list(itertools.product((0, 1), repeat=3)))
    rotations = [R for R in Rotation.create_group("O").as_matrix()]
    centred = corners - 0.5
    perms = []
    for R in rotations:
        moved = np.rint((centred @ np.rint(R).T) + 0.5).astype(int)
        perms.append([int(np.flatnonzero((corners == m).all(1))[0]) for m in moved])
    assert len(perms) == 24

    def classes(with_complement):
        seen, count = set(), 0
        for case in range(256):
            if case in seen:
                continue
            count += 1
            for perm in perms:
                image = sum(1 << perm[i] for i in range(8) if case >> i & 1)
                seen.add(image)
                if with_complement:
                    seen.add(255 ^ image)
        return count
    assert classes(True) == 15 and classes(False) == 23


def test_fact_ch18_marching_squares_interpolation():
    from skimage.measure import find_contours
    assert answer_text("ch18-ms-interp").startswith("At $t = \\frac{c - f_0}")
    f0, f1, c = 0.2, 1.4, 0.5
    grid = np.array([[f0, f1], [f0, f1]])
    contour = find_contours(grid, c)[0]
    assert np.allclose(contour[:, 1], (c - f0) / (f1 - f0))


def test_fact_ch18_euler_spiral_and_compositing():
    from scipy.integrate import solve_ivp
    assert "outward" in answer_text("ch18-euler-integration")
    h, p = 0.1, np.array([1.0, 0.0])
    for k in range(1, 21):
        p = p + h * np.array([-p[1], p[0]])
        assert math.isclose(np.linalg.norm(p), (1 + h * h) ** (k / 2))
    rk = solve_ivp(lambda t, y: [-y[1], y[0]], (0, 2.0), [1.0, 0.0], method="RK45",
                   rtol=1e-9, atol=1e-12)
    assert math.isclose(np.linalg.norm(rk.y[:, -1]), 1.0, rel_tol=1e-6)
    # front-to-back and back-to-front compositing agree
    assert "early ray termination" in answer_text("ch18-front-to-back")
    colours, alphas = RNG.uniform(size=(30, 3)), RNG.uniform(0, 0.5, size=30)
    back = np.zeros(3)
    for col, a in zip(colours[::-1], alphas[::-1]):
        back = a * col + (1 - a) * back
    front, acc = np.zeros(3), 0.0
    for col, a in zip(colours, alphas):
        front += (1 - acc) * a * col
        acc += (1 - acc) * a
    assert np.allclose(front, back)


def test_fact_ch18_marching_cubes_sphere_is_closed_manifold():
    import trimesh
    from skimage.measure import marching_cubes
    assert truth("ch18-mc-holes")          # the table can make holes: here it does not
    g = np.linspace(-1.3, 1.3, 28)
    x, y, z = np.meshgrid(g, g, g, indexing="ij")
    verts, faces, _, _ = marching_cubes(x ** 2 + y ** 2 + z ** 2, 1.0)
    mesh = trimesh.Trimesh(verts, faces)
    assert mesh.is_watertight and mesh.euler_number == 2


def test_fact_ch14_hierarchies():
    from course_lib import texturing
    # the 4/3 and 8/7 bounds: closed forms of the series against summed level sizes
    assert "quarter" in answer_text("ch14-pyramid-bound")
    for n in range(1, 11):
        side = 2 ** n
        two = sum((side >> k) ** 2 for k in range(n + 1))
        three = sum((side >> k) ** 3 for k in range(n + 1))
        assert two == (4 ** (n + 1) - 1) // 3 < 4 / 3 * side ** 2
        assert three < 8 / 7 * side ** 3
    # anisotropic filtering: the level of the short axis, N samples along the long one
    assert "short axis" in answer_text("ch14-anisotropic")
    lam, samples, _ = texturing.anisotropic_level((256, 256), 2 / 256, 0, 0, 16 / 256)
    iso = texturing.mip_level(texturing.texel_footprint((256, 256), 2 / 256, 0, 0, 16 / 256))
    assert float(lam) == 1.0 and int(samples) == 8 and float(iso) == 4.0
    # clipmaps: memory grows with the number of levels, not with the texture's area
    assert truth("ch14-clipmap-virtual")
    small, big = texturing.clipmap((4096, 4096), 512), texturing.clipmap((65536, 65536), 512)
    assert big.full_texels / small.full_texels > 200
    assert big.resident_texels - small.resident_texels == 4 * 512 ** 2


def test_fact_ch14_relief():
    from course_lib.texturing import relief
    # a normal close to the tangent frame's N encodes as light blue (0.5, 0.5, 1)
    assert "0.5, 0.5, 1" in answer_text("ch14-normal-map-blue")
    assert np.allclose(relief.encode_normals([0, 0, 1]), [0.5, 0.5, 1])
    tilted = relief.encode_normals([0.2, -0.1, 1.0])
    assert tilted[2] > 0.97 and abs(tilted[0] - 0.5) < 0.11 and abs(tilted[1] - 0.5) < 0.06
    # bump mapping keeps the points (outline), displacement moves them
    assert "outline" in BY_KEY["ch14-relief-limits"].explanations[1]
    p = np.array([[1.0, 0, 0]])
    assert np.allclose(relief.displace(p, p, [1.0], 0.1), [[1.1, 0, 0]])
    # a mirrored texture gives handedness -1, the tangent-space answer uses it
    assert "handedness" in answer_text("ch14-normal-map-space")
    _, _, _, w = relief.vertex_tangent_frames([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]],
                                              [[0, 0], [-1, 0], [0, 1]])
    assert np.all(w == -1)


def test_fact_ch14_two_part():
    from course_lib.texturing import texture_transforms, two_part
    assert "intermediate surface" in answer_text("ch14-two-part-purpose")
    assert "reflected" in answer_text("ch14-two-part-view-dependent")
    pts = RNG.normal(size=(30, 3)) * 0.3
    nrm = RNG.normal(size=(30, 3))
    for method in two_part.METHODS:
        a = two_part.two_part_map(pts, nrm, "sphere", method, size=2, eye=(0, 0, 5))
        b = two_part.two_part_map(pts, nrm, "sphere", method, size=2, eye=(4, 1, 0))
        assert np.allclose(a, b) == (method != "reflected"), method
    # the picture moves opposite to the offset: the texel at u in [0, 1/8) shows at 7/8 - 1
    assert not truth("ch14-texture-matrix-opposite")
    tex = np.zeros((1, 8))
    tex[0, 2] = 1.0                                   # a feature at u = 0.25..0.375
    moved = texture_transforms.transform_texture(tex, texture_transforms.texture_matrix(
        offset=(0.25, 0)), filter="nearest")
    assert moved[0, 0] == 1.0                         # now at u = 0..0.125: moved by -0.25


def test_fact_ch14_environment():
    from course_lib.texturing import environment as env
    # the distant-environment assumption: off the centre by d, walls at R, the look-up misses by
    # up to arcsin(d / R) (rays perpendicular to the offset), by nothing along the offset
    assert "arcsin" in answer_text("ch14-env-distant")
    d, R = 2.0, 3.0
    offset = np.array([0.0, d, 0.0])
    perpendicular = env.distant_environment_error(offset, [[1, 0, 0], [0, 0, -1]], R)
    assert np.allclose(perpendicular, math.asin(d / R))                    # 41.8 degrees
    assert np.allclose(env.distant_environment_error(offset, [[0, 1, 0], [0, -1, 0]], R), 0,
                       atol=1e-7)
    dirs = RNG.normal(size=(500, 3))
    errors = env.distant_environment_error(offset, dirs, R)
    assert errors.max() <= math.asin(d / R) + 1e-12
    for u, err in zip(dirs[:40] / np.linalg.norm(dirs[:40], axis=1, keepdims=True), errors):
        pu = offset @ u                                 # the wall point the ray really hits
        q = offset + (-pu + math.sqrt(pu * pu - offset @ offset + R * R)) * u
        assert math.isclose(err, math.acos(np.clip(q @ u / np.linalg.norm(q), -1, 1)),
                            abs_tol=1e-9)
    assert env.distant_environment_error(offset, [1, 0, 0], 100.0) < math.asin(0.021)
    # no self-reflection: the ray reflected from the body towards the spout hits the spout,
    # but the look-up only gets the direction and returns the room
    assert not truth("ch14-env-self-reflection")
    p, incident = np.array([0.8, 0.0, 0.6]), np.array([0.0, 0.0, -1.0])   # n = p on a unit ball
    r = env.reflect_view(incident, p)
    assert np.allclose(r, incident - 2 * (p @ incident) * p) and np.allclose(r, [0.96, 0, -0.28])
    spout, radius = p + 1.0 * r, 0.2
    b, c = r @ (p - spout), (p - spout) @ (p - spout) - radius ** 2
    assert b * b - c > 0 and -b - math.sqrt(b * b - c) > 0                 # the ray hits it
    cube = env.cube_map_from_function(env.room_environment, 16)
    room = {tuple(np.round(c, 6)) for c in env.room_environment(RNG.normal(size=(4000, 3)))}
    seen = env.sample_cube_map(cube, [r], "nearest")[0]
    assert tuple(np.round(seen, 6)) in room                                # a wall, not a spout
    # the sphere map: (0, 0, 1) at the centre; along (sin a, 0, -cos a) closed form
    # s = (1 + cos(a/2)) / 2, so the directions near (0, 0, -1) go round the whole rim
    assert "(0, 0, -1)" in answer_text("ch14-env-sphere-map")
    s, t = env.sphere_map_coordinates([[0, 0, 1]])
    assert np.allclose([s[0], t[0]], 0.5)
    a = np.radians([10.0, 60.0, 120.0, 170.0, 179.0])
    s, _ = env.sphere_map_coordinates(np.stack([np.sin(a), 0 * a, -np.cos(a)], -1))
    assert np.allclose(s, (1 + np.cos(a / 2)) / 2)
    phi = np.linspace(0, 2 * np.pi, 24, endpoint=False)
    eps = np.radians(1.0)
    cap = np.stack([np.sin(eps) * np.cos(phi), np.sin(eps) * np.sin(phi),
                    -np.cos(eps) * np.ones_like(phi)], -1)
    s, t = env.sphere_map_coordinates(cap)
    assert np.all(np.hypot(s - 0.5, t - 0.5) > 0.499)                      # on the rim ...
    assert np.allclose(np.arctan2(t - 0.5, s - 0.5) % (2 * np.pi), phi)    # ... all round it
    # view dependence: the map made for another view holds other colours
    turn = np.array([[0.0, 0, 1], [0, 1, 0], [-1, 0, 0]])                  # 90 degrees about y
    front = env.sphere_map_from_function(env.axes_environment, 32)
    side = env.sphere_map_from_function(env.axes_environment, 32, view=turn)
    assert np.abs(front - side).max() > 0.3
    # a cube map's texels: the corner texel covers 1/(3 sqrt 3) of the centre texel's solid
    # angle (exact solid angles of rectangles on the plane z = 1), the face 4 pi / 6
    assert "viewer" in answer_text("ch14-env-cube-vs-sphere")

    def corner_angle(x, y):                # the solid angle of [0, x] x [0, y] on z = 1
        return math.atan(x * y / math.sqrt(1 + x * x + y * y))

    def texel(x0, x1, y0, y1):
        return (corner_angle(x1, y1) - corner_angle(x0, y1) - corner_angle(x1, y0)
                + corner_angle(x0, y0))

    h = 1 / 256
    ratio = texel(1 - h, 1, 1 - h, 1) / texel(0, h, 0, h)
    assert math.isclose(ratio, 1 / (3 * math.sqrt(3)), rel_tol=0.01)
    assert math.isclose(4 * corner_angle(1, 1), 4 * math.pi / 6)


def test_fact_ch10_pipeline_and_good_plots():
    # the pipeline's order, the mantra and the stage of marching cubes
    assert answer_text("ch10-pipeline-order").startswith("Data acquisition, filtering")
    assert answer_text("ch10-mantra").startswith("Overview first")
    assert not truth("ch10-isosurface-stage")
    # circles with radius ~ value: the areas (pi r^2, computed here) exaggerate the change
    assert not truth("ch10-radius-honest")
    r1, r2 = 2.0, 3.0                                     # a change of +50 %
    area1, area2 = math.pi * r1 ** 2, math.pi * r2 ** 2
    lie = ((area2 - area1) / area1) / ((r2 - r1) / r1)
    assert math.isclose(lie, 2.5) and math.isclose(lie, 2 + 0.5)
    # bars 40 and 50 on an axis from 30: lengths 10 and 20
    assert answer_text("ch10-truncated-axis") == "L = 4"
    assert math.isclose(((20 - 10) / 10) / ((50 - 40) / 40), 4.0)
    # banking: at the banked aspect ratio the mean |orientation| of a sine's segments is 45
    # degrees (found here by bisection on the mean angle, without the library)
    assert truth("ch10-banking")
    x = np.linspace(0, 4 * np.pi, 200)
    y = np.sin(x)
    dx, dy = np.diff(x) / np.ptp(x), np.abs(np.diff(y)) / np.ptp(y)

    def mean_angle(alpha):
        return np.degrees(np.arctan2(alpha * dy, dx)).mean()

    lo, hi = 1e-3, 1e3
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if mean_angle(mid) < 45 else (lo, mid)
    assert math.isclose(mean_angle(lo), 45, abs_tol=1e-6)
    assert mean_angle(1.0) > 60 and mean_angle(lo / 4) < 30       # square: too steep
    assert answer_text("ch10-visual-variable-nominal") == "Colour hue"
    assert not truth("ch10-small-multiples-scales")


def test_fact_ch10_multidim():
    # parallel coordinates of y = m x + c: the lines v = a' + (b' - a') u of its points share
    # one point, between the axes exactly for a negative normalised slope; a perfect linear
    # relation on the data's own ranges has m' = +-1 (parallel lines, or one crossing at 1/2)
    assert answer_text("ch10-pc-negative").startswith("Lines that cross near one point")
    assert truth("ch10-pc-duality")
    for m_n, c_n in ((-2.0, 0.9), (-0.5, 0.3), (0.4, 0.1), (3.0, -0.5)):
        a = RNG.uniform(0, 1, 6)
        b = m_n * a + c_n
        u, v = np.linalg.solve([[b[0] - a[0], -1.0], [b[1] - a[1], -1.0]], [-a[0], -a[1]])
        assert np.allclose(a + (b - a) * u, v)                        # every line meets there
        assert math.isclose(u, 1 / (1 - m_n)) and (0 < u < 1) == (m_n < 0)
    x = RNG.uniform(3, 9, 50)
    for m in (2.5, -0.7):
        y = m * x + 4
        xn, yn = (x - x.min()) / np.ptp(x), (y - y.min()) / np.ptp(y)
        slopes = yn - xn
        assert np.allclose(slopes, 0) if m > 0 else np.allclose(xn + slopes * 0.5, 0.5)
    # adjacent axes only: d - 1 neighbours among d(d - 1)/2 pairs; the matrix has 15 plots
    assert not truth("ch10-pc-order")
    assert answer_text("ch10-splom-count") == "15"
    assert len(list(itertools.combinations(range(6), 2))) == 15 and 6 - 1 < 15
    # the first principal component: the direction of largest variance (numpy's SVD)
    assert answer_text("ch10-pca-first").startswith("The unit eigenvector")
    data = RNG.normal(size=(400, 3)) @ np.array([[3, 1, 0], [0, 1, 0.5], [0, 0, 0.2]])
    centred = data - data.mean(axis=0)
    w = np.linalg.svd(centred, full_matrices=False)[2][0]
    directions = RNG.normal(size=(2000, 3))
    directions /= np.linalg.norm(directions, axis=1, keepdims=True)
    assert np.var(centred @ w) >= np.var(centred @ directions.T, axis=0).max()
    values, vectors = np.linalg.eigh(np.cov(centred.T))
    assert np.isclose(abs(vectors[:, -1] @ w), 1)
    # units: the same lengths in millimetres dominate the first component; standardised not
    assert truth("ch10-pca-standardise")
    lengths = RNG.normal(size=500)
    masses = 0.6 * lengths + 0.8 * RNG.normal(size=500)
    table = np.column_stack([1000 * lengths, masses / 1000])      # mm and tonnes
    first = np.linalg.svd(table - table.mean(axis=0), full_matrices=False)[2][0]
    assert abs(first[0]) > 0.999999
    z = (table - table.mean(axis=0)) / table.std(axis=0)
    first = np.linalg.svd(z, full_matrices=False)[2][0]
    assert np.allclose(np.abs(first), 1 / math.sqrt(2))
    # brushes: AND is contained in OR
    assert not truth("ch10-brush-and-or")
    a, b = RNG.uniform(size=(2, 300)) < 0.4
    assert ((a & b) <= (a | b)).all() and (a & b).sum() < (a | b).sum()
    assert "perceive" in answer_text("ch10-chernoff")


def test_fact_ch10_data():
    """Section 10.3: levels of measurement, grid memory, Shepard, RBFs, linear interpolation."""
    from scipy.interpolate import RBFInterpolator, griddata

    assert answer_text("ch10-level-postcode").startswith("Nominal")
    # "the mean postcode is closest to 5612" does not survive a one-to-one relabelling, which
    # is admissible for names: statements about means of codes are meaningless
    codes = np.array([3011.0, 5612.0, 9712.0])
    new = np.array([1000.0, 9000.0, 2000.0])                        # the same areas renamed
    closest = np.argmin(np.abs(codes - codes.mean()))
    assert closest == 1 and np.argmin(np.abs(new - new.mean())) != closest
    assert not truth("ch10-celsius-ratio")
    c = np.array([10.0, 20.0])
    assert c[1] / c[0] == 2 and not math.isclose((c[1] * 1.8 + 32) / (c[0] * 1.8 + 32), 2)
    assert math.isclose((c[1] * 1.8 + 32) / (c[0] * 1.8 + 32), 68 / 50)
    assert "Uniform" in answer_text("ch10-grid-least-memory")
    stored = {"uniform": 2 + 2 + 2, "rectilinear": 100 + 100, "curvilinear": 2 * 100 * 100}
    assert min(stored, key=stored.get) == "uniform" and stored["uniform"] == 6
    assert answer_text("ch10-scattered-vs-unstructured").startswith("The cells")
    rng = np.random.default_rng(10)
    p = rng.uniform(size=(40, 2))
    f = rng.uniform(size=40)
    q = rng.uniform(size=(200, 2))
    d = np.linalg.norm(q[:, None] - p[None], axis=2)
    assert "Nearest" in answer_text("ch10-shepard-large-power")
    order = np.sort(d, axis=1)
    clear = order[:, 1] > 1.2 * order[:, 0]
    w = (order[:, :1] / d) ** 200                                    # 1/d^200, scaled
    sharp = (w @ f) / w.sum(axis=1)
    assert np.allclose(sharp[clear], griddata(p, f, q[clear], "nearest"), atol=1e-9)
    assert truth("ch10-shepard-range")
    for power in (0.5, 1, 2, 4):
        s = (d ** -power @ f) / np.sum(d ** -power, axis=1)
        assert f.min() <= s.min() and s.max() <= f.max()
    step = np.where(p[:, 0] > 0.5, 1.0, 0.0)                        # a jump: RBFs overshoot
    rbf = RBFInterpolator(p, step, kernel="gaussian", epsilon=4.0, degree=-1)(q)
    assert rbf.max() > 1.0 or rbf.min() < 0.0
    assert "linear system" in answer_text("ch10-rbf-coefficients")
    a = np.exp(-(4.0 * np.linalg.norm(p[:, None] - p[None], axis=2)) ** 2)
    lam = np.linalg.solve(a, f)
    by_hand = np.exp(-(4.0 * d) ** 2) @ lam
    assert np.allclose(by_hand, RBFInterpolator(p, f, kernel="gaussian", epsilon=4.0,
                                                degree=-1)(q), atol=1e-6)
    assert not truth("ch10-linear-outside-hull")
    outside = np.array([[2.0, 2.0], [-1.0, 0.5]])
    assert Delaunay(p).find_simplex(outside).tolist() == [-1, -1]
    assert np.isnan(griddata(p, f, outside, "linear")).all()


def test_fact_ch07_interpolating():
    from scipy.interpolate import BarycentricInterpolator, CubicSpline
    assert not truth("ch07-interp-runge")
    f = lambda x: 1 / (1 + 25 * x ** 2)                               # noqa: E731
    x = np.linspace(-1, 1, 2001)
    errors = [np.abs(BarycentricInterpolator(np.linspace(-1, 1, n), f(np.linspace(-1, 1, n)))(x)
                     - f(x)).max() for n in (5, 11, 17)]
    assert errors[0] < errors[1] < errors[2]
    assert answer_text("ch07-interp-catmull-rom-tangent") == "$\\tfrac12 (P_{i+1} - P_{i-1})$"
    assert answer_text("ch07-interp-spline-local").startswith("In general every segment")
    t = np.arange(9.0)
    y = RNG.normal(size=9)
    y2 = y.copy()
    y2[4] += 1.0
    u = np.linspace(0, 8, 801)
    moved = np.abs(CubicSpline(t, y2, bc_type="natural")(u)
                   - CubicSpline(t, y, bc_type="natural")(u))
    assert moved[u < 1].max() > 1e-4 and moved[u > 7].max() > 1e-4   # even the end segments
    assert truth("ch07-interp-natural-end")
    s = CubicSpline(t, y, bc_type="natural")
    assert np.allclose(s([0, 8], 2), 0)
    assert not truth("ch07-interp-chord-duplicate")
    pts = np.array([[0, 0], [1, 1], [1, 1], [2, 0]], float)
    steps = np.linalg.norm(np.diff(pts, axis=0), axis=1)
    with pytest.raises(ValueError):
        CubicSpline(np.r_[0, np.cumsum(steps)], pts)


def test_fact_ch06_forms_and_rings():
    import trimesh
    from course_lib.mesh import brep
    assert answer_text("ch06-brep-euler-rings") == "$R = 2$, $H = 1$"
    assert truth("ch06-pocket-no-hole") and not truth("ch06-voxel-memory")
    assert "implicit" in answer_text("ch06-form-inside-test").lower()
    for solid, rings, holes in ((brep.brep_drilled_cube(), 2, 1),
                                (brep.brep_pocket_cube(), 1, 0)):
        v, t = brep.brep_triangulate(solid)
        mesh = trimesh.Trimesh(v, t, process=False)
        assert solid.R == rings and mesh.euler_number == 2 - 2 * holes
        assert solid.V - solid.E + solid.F - solid.R == 2 * (1 - holes)
    assert 16 - 24 + 10 - 2 == 0 and 16 - 24 + 11 - 1 == 2
    assert (2 * 64) ** 3 == 8 * 64 ** 3


def test_fact_ch06_lod():
    # the screen-space error: project two points eps apart at depth d with a perspective
    # matrix typed here (OpenGL form) and a viewport H pixels high
    eps, d, fov, H = 0.03, 7.0, np.radians(50), 900
    f = 1 / np.tan(fov / 2)
    P = np.array([[f, 0, 0, 0], [0, f, 0, 0], [0, 0, -1.01, -0.2], [0, 0, -1, 0]])
    y = [(P @ [0, h, -d, 1])[1] / (P @ [0, h, -d, 1])[3] * H / 2 for h in (0.0, eps)]
    assert answer_text("ch06-lod-screen-error") == "$\\varepsilon H / (2 d \\tan(\\theta/2))$"
    assert np.isclose(y[1] - y[0], eps * H / (2 * d * np.tan(fov / 2)))
    assert answer_text("ch06-lod-which-level").startswith("The coarsest level whose screen")
    # a progressive mesh reproduces simplify_qem's meshes exactly
    from course_lib.mesh import ProgressiveMesh, icosphere, simplify_qem
    assert truth("ch06-lod-pm-exact") and truth("ch06-lod-hysteresis")
    pm = ProgressiveMesh(*icosphere(2), base_faces=50)
    for n in (50, 120, 250):
        v, faces = pm.mesh(n)
        v0, f0 = simplify_qem(*icosphere(2), target_faces=n)[:2]
        assert np.array_equal(faces, f0) and np.allclose(v, v0)
    assert answer_text("ch06-lod-geomorph").startswith("It moves each vertex")
    g0, _ = pm.geomorph(120, 250, 0.0)
    coarse, _ = pm.mesh(120)
    assert np.allclose(np.linalg.norm(g0[:, None] - coarse[None], axis=2).min(axis=1), 0)


def test_fact_ch07_continuity_curvature_matrix_form():
    # G1 vs C1: B'(0) = 2 A'(1) has equal unit tangents, unequal derivatives
    a, b = np.array([2.0, 2.0]), np.array([4.0, 4.0])
    assert np.allclose(a / np.linalg.norm(a), b / np.linalg.norm(b)) and not np.allclose(a, b)
    assert answer_text("ch07-continuity-g1-vs-c1") == "$G^1$ but not $C^1$"
    # opposite tangents: unit tangents differ (a cusp), so not G1
    assert not truth("ch07-continuity-opposite-tangents")
    assert not np.allclose(a / np.linalg.norm(a), -a / np.linalg.norm(a))
    # circle curvature 1/r from finite differences of r (cos t, sin t)
    assert answer_text("ch07-continuity-curvature-circle") == "$1/r$"
    for r in (0.5, 2.0, 3.0):
        t, h = 0.7, 1e-4
        P = lambda s: r * np.array([np.cos(s), np.sin(s)])        # noqa: E731
        d1 = (P(t + h) - P(t - h)) / (2 * h)
        d2 = (P(t + h) - 2 * P(t) + P(t - h)) / h ** 2
        kappa = abs(d1[0] * d2[1] - d1[1] * d2[0]) / np.linalg.norm(d1) ** 3
        assert kappa == pytest.approx(1 / r, rel=1e-6)
    # G2 without C1: beta constraints with beta1 = 2 on a Bezier join, by hand
    assert truth("ch07-continuity-g2-needs-c2")
    A = np.array([[0, 0], [1, 0], [2, 0], [3, 1]], float)
    a1, a2 = 3 * (A[3] - A[2]), 6 * (A[3] - 2 * A[2] + A[1])
    b1, b2 = 2 * a1, 4 * a2 + 1.5 * a1
    cross = lambda u, v: u[0] * v[1] - u[1] * v[0]                # noqa: E731
    assert cross(a1, a2) / np.linalg.norm(a1) ** 3 == pytest.approx(
        cross(b1, b2) / np.linalg.norm(b1) ** 3) and not np.allclose(a1, b1)
    # T = [t^3, t^2, t, 1] with the Bezier matrix gives the Bernstein polynomials
    assert answer_text("ch07-matrix-form-t-row") == "$[t^3, t^2, t, 1]$"
    M = np.array([[-1, 3, -3, 1], [3, -6, 3, 0], [-3, 3, 0, 0], [1, 0, 0, 0]])
    for t in (0.2, 0.5, 0.9):
        bern = [math.comb(3, i) * t ** i * (1 - t) ** (3 - i) for i in range(4)]
        assert np.allclose(np.array([t ** 3, t ** 2, t, 1]) @ M, bern)
        assert not np.allclose(np.array([1, t, t ** 2, t ** 3]) @ M, bern)


def test_fact_ch06_decimation():
    """Clustering closes small holes, decimation keeps original vertices, Hausdorff is
    one-sided per direction, a half-edge collapse costs at least the full collapse."""
    import trimesh
    from scipy.spatial.distance import directed_hausdorff
    from course_lib.mesh import torus
    from course_lib.mesh.clustering import vertex_clustering
    from course_lib.mesh.decimation import (decimate, full_edge_collapse_cost,
                                            half_edge_collapse_cost)
    assert not truth("ch06-clustering-topology") and truth("ch06-decimation-subset")
    assert answer_text("ch06-hausdorff-one-sided").startswith("d(A -> B) = 0")
    assert answer_text("ch06-half-edge-collapse").startswith("u moves onto w")
    v, f = torus(major=1.0, minor=0.85, segments=32, rings=16)      # hole of radius 0.15
    out = vertex_clustering(v, f, cells=5)      # the hole lies inside the middle cells
    assert trimesh.Trimesh(v, f, process=False).euler_number == 0       # genus 1
    assert trimesh.Trimesh(out.vertices, out.faces, process=False).euler_number == 2  # genus 0
    d = decimate(v, f, target_faces=200)
    assert all((np.abs(v - p).max(axis=1) == 0).any() for p in d.vertices)
    patch = np.array([[0.0, 0], [0.1, 0], [0, 0.1]])
    big = np.array([[x, y] for x in np.linspace(0, 1, 11) for y in np.linspace(0, 1, 11)])
    assert directed_hausdorff(patch, big)[0] == 0 and directed_hausdorff(big, patch)[0] > 1
    e = np.array([[0, 1], [1, 0], [0, 16], [16, 0]])
    assert np.all(full_edge_collapse_cost(v, f, e)[1] <= half_edge_collapse_cost(v, f, e) + 1e-12)


def test_fact_ch03_normals_frames():
    """The inverse transpose keeps normals perpendicular (A n does not under a non-uniform
    scale), A works for a rotation times a uniform scale, world-to-frame is [R^T, -R^T o], the
    exam's 3w matrix is a 90 degree rotation, and I - 2 n n^T is trimesh's reflection."""
    from trimesh import transformations as tt
    assert answer_text("ch03-normal-matrix").startswith("$(A^{-1})^T$")
    A = np.array([[2.0, 0.0], [0.0, 0.5]])
    t, n = np.array([1.0, 1.0]), np.array([1.0, -1.0])           # n . t = 0
    assert abs((np.linalg.inv(A).T @ n) @ (A @ t)) < 1e-12
    assert abs((A @ n) @ (A @ t)) > 1                              # the naive normal is off
    S = np.array([[1.0, 0.7], [0.0, 1.0]])                         # a shear: A^-1 n is off too
    assert abs((np.linalg.inv(S) @ n) @ (S @ t)) > 0.1
    assert truth("ch03-normal-uniform-scale")
    B = 3.0 * Rotation.from_euler("z", 0.4).as_matrix()
    for nn in RNG.normal(size=(5, 3)):
        a, b = B @ nn, np.linalg.inv(B).T @ nn
        assert np.allclose(np.cross(a, b), 0, atol=1e-9) and a @ b > 0
    assert answer_text("ch03-world-to-frame").startswith("$\\begin{bmatrix} R^T & -R^T o")
    R, o = Rotation.from_euler("xyz", [0.3, -0.2, 0.9]).as_matrix(), np.array([1.0, 2.0, 3.0])
    F = np.eye(4)
    F[:3, :3], F[:3, 3] = R, o
    W = np.eye(4)
    W[:3, :3], W[:3, 3] = R.T, -R.T @ o
    assert np.allclose(W, np.linalg.inv(F))
    assert truth("ch03-homogeneous-multiple")
    M = np.array([[0, -3, 0], [3, 0, 0], [0, 0, 3]], dtype=float)
    x, y = 2.0, 5.0
    image = M @ [x, y, 1]
    assert np.allclose(image[:2] / image[2], [-y, x])
    assert answer_text("ch03-mirror-plane") == "$I - 2 n n^T$"
    u = np.array([2.0, 3.0, 6.0]) / 7
    assert np.allclose(tt.reflection_matrix([0, 0, 0], u)[:3, :3], np.eye(3) - 2 * np.outer(u, u))


def test_fact_ch04_taxonomy():
    """Two-point perspective for a level camera, isometric foreshortening sqrt(2/3), the cabinet's
    half depth at arctan 2, vanishing points as images of (d, 0), orthographic = perpendicular
    projectors: checked with scipy rotations and far points, not with course_lib."""
    assert answer_text("ch04-two-point-perspective") == "Two"
    assert not truth("ch04-isometric-true-length")
    assert answer_text("ch04-cabinet").startswith("At half length")
    assert truth("ch04-vanishing-point-homogeneous")
    assert answer_text("ch04-orthographic-vs-oblique").startswith("Whether the projectors")
    # a level camera turned 30 degrees about the vertical: image plane normal = view direction
    view = Rotation.from_euler("z", 30, degrees=True).apply([0.0, 1.0, 0.0])
    assert sum(abs(axis @ view) > 1e-9 for axis in np.eye(3)) == 2
    # isometric: the unit axes seen along (1, 1, 1)/sqrt 3 keep sqrt(2/3) of their length
    v = np.ones(3) / np.sqrt(3)
    lengths = [np.linalg.norm(a - (a @ v) * v) for a in np.eye(3)]
    assert np.allclose(lengths, np.sqrt(2 / 3)) and not np.allclose(lengths, 1)
    # cabinet: projectors at arctan 2 to the plane z = 0 draw a unit of depth with length 1/2
    alpha = np.arctan(2.0)
    dop = np.array([np.cos(alpha), 0.0, -np.sin(alpha)])
    p = np.array([0.0, 0.0, 1.0])
    image = p - p[2] / dop[2] * dop
    assert math.isclose(np.linalg.norm(image[:2]), 0.5)
    # the vanishing point: far points of a line under P_PER (d = 2) tend to P (d, 0) / w
    d, P = np.array([1.0, 2.0, 4.0]), np.diag([2.0, 2.0, 2.0, 0.0])
    P[3, 2] = 1.0
    far = P @ np.append(np.array([1.0, -1.0, 3.0]) + 1e9 * d, 1.0)
    vp = P @ np.append(d, 0.0)
    assert np.allclose(far[:3] / far[3], vp[:3] / vp[3], atol=1e-6)


def test_fact_ch05_hierarchical():
    """The z-pyramid is a block max (skimage), the HZB never rejects a box the per-pixel test
    shows, a threshold below 1 culls a box seen through a gap, and front-to-back querying culls
    more than back to front."""
    from skimage.measure import block_reduce
    from course_lib import visibility as V
    assert not truth("ch05-hzb-conservative")
    assert "farthest" in answer_text("ch05-zpyramid-reduction")
    assert "stalls" in answer_text("ch05-occlusion-query-cost")
    assert "show through" in answer_text("ch05-hom-approximate")
    depth = RNG.uniform(0, 1, (32, 32))
    p = V.z_pyramid(depth)
    assert np.array_equal(p.levels[2], block_reduce(depth, (4, 4), np.max))
    rects = np.sort(RNG.integers(0, 32, (500, 2, 2)), axis=1).reshape(500, 4)  # i0 j0 i1 j1
    z = RNG.uniform(0.9, 1.0, 500)
    hzb = V.hzb_cull(p, rects, z).rejected
    shown = np.array([(depth[j0:j1 + 1, i0:i1 + 1] > zn).any()
                      for (i0, j0, i1, j1), zn in zip(rects, z)])
    assert not (hzb & shown).any() and hzb.any()
    cov = np.ones((16, 16))
    cov[3, 3] = 0
    deb = V.depth_estimation_buffer(np.where(cov > 0, 0.2, np.inf), 4)
    t = V.hom_test(V.occlusion_map_pyramid(cov), (0, 0, 15, 15), 0.5, deb, threshold=0.9)
    assert t.culled and V.occlusion_query(np.where(cov > 0, 0.2, np.inf), (0, 0, 15, 15), 0.5)
    r = [(0, 0, 15, 15), (2, 2, 9, 9), (5, 5, 12, 12)]
    zs = [0.1, 0.5, 0.7]
    assert (V.draw_if_visible(r, zs, 16, 16).drawn.sum()
            < V.draw_if_visible(r, zs, 16, 16, order="back_to_front").drawn.sum())


def test_fact_ch05_bsp():
    from course_lib.visibility import bsp2d_back_to_front, build_bsp_2d
    from shapely.geometry import LineString, Point
    assert answer_text("ch05-bsp-traversal").startswith("The back subtree")
    assert truth("ch05-bsp-any-viewpoint") and truth("ch05-bsp-root-whole")
    rng = np.random.default_rng(5)
    for _ in range(10):
        a = rng.uniform(-4, 4, (8, 2))
        segs = np.stack([a, a + rng.uniform(-3, 3, (8, 2))], axis=1)
        order = rng.permutation(8).tolist()
        tree = build_bsp_2d(segs, order=order)
        first = tree.labels[order[0]]
        assert [f.label for f in tree.fragments if f.source == order[0]] == [first]
        # from several eyes, the one fixed tree gives an order in which a later fragment is
        # never behind an earlier one along a ray (checked with shapely)
        for eye in rng.uniform(-5, 5, (3, 2)):
            out = bsp2d_back_to_front(tree, eye)
            lines = [LineString([f.start, f.end]) for f in out.fragments]
            for ang in np.linspace(0, 2 * np.pi, 90, endpoint=False) + 0.01:
                ray = LineString([eye, eye + 50 * np.array([np.cos(ang), np.sin(ang)])])
                dists = [Point(eye).distance(ln.intersection(ray)) for ln in lines
                         if ln.intersects(ray)]
                assert all(d1 <= d0 + 1e-9 for d0, d1 in zip(dists, dists[1:]))


def test_fact_ch05_clip_space_before_the_divide():
    """Checked with the six inequalities typed out and world points sampled along segments."""
    from course_lib.viewing import look_at, perspective
    assert answer_text("ch05-clip-space-why").startswith("A segment with an end behind the eye")
    assert not truth("ch05-clip-space-w-negative") and truth("ch05-clip-space-t-world")
    # no point with w < 0 is inside
    p = RNG.uniform(-3, 3, (5000, 4))
    p[:, 3] = -np.abs(p[:, 3]) - 1e-3
    inside = (np.abs(p[:, :3]) <= p[:, 3:]).all(axis=1)
    assert not inside.any()
    m = perspective(np.radians(60), 1.0, 1.0, 20.0) @ look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])
    for _ in range(50):
        a = np.array([*RNG.uniform(-0.5, 0.5, 2), RNG.uniform(-3, 1)])      # in front of the eye
        b = np.array([*RNG.uniform(-4, 4, 2), RNG.uniform(6.5, 9)])         # behind it (z > 5)
        ha, hb = m @ [*a, 1], m @ [*b, 1]
        assert ha[3] > 0 > hb[3]
        # the visible part by sampling the world segment densely (t is the world parameter)
        ts = np.linspace(0, 1, 20001)
        h = ha + ts[:, None] * (hb - ha)
        seen = (np.abs(h[:, :3]) <= h[:, 3:]).all(axis=1)
        # clip space: the same t as in the world (M is linear on homogeneous coordinates)
        world = a + ts[:, None] * (b - a)
        hw = np.column_stack([world, np.ones(len(ts))]) @ m.T
        assert np.allclose(hw, h)
        # the divide-first route: the NDC segment between the divided ends, sampled
        na, nb = ha[:3] / ha[3], hb[:3] / hb[3]
        ndc_line = na + ts[:, None] * (nb - na)
        kept = (np.abs(ndc_line) <= 1).all(axis=1)
        true_images = h[seen, :3] / h[seen, 3:]
        # points the wrong route keeps that are the image of no visible point of the segment
        far = [np.min(np.linalg.norm(true_images - q, axis=1)) for q in ndc_line[kept][::200]]
        if max(far, default=0) > 0.05:
            break
    else:
        raise AssertionError("dividing first never went wrong")


def test_fact_ch15_distributed():
    from course_lib.raytracing import Camera, lens_rays
    rng = np.random.default_rng(1522)          # its own generator: the shared RNG's draws stay put
    # noise of a mean of N samples: quadrupling N halves the standard deviation
    assert answer_text("ch15-distributed-noise") == "By a factor of 2"
    stds = [rng.random((4000, n)).mean(axis=1).std() for n in (16, 64)]
    assert stds[0] / stds[1] == pytest.approx(2.0, rel=0.1)
    # depth of field: the rays of a pixel start all over the aperture and meet on the focal plane
    assert answer_text("ch15-distributed-dof").startswith("the lens aperture")
    cam = Camera([0, 0, 0], [0, 0, -1], [0, 1, 0], math.radians(50), 3, 3)
    rays = lens_rays(cam, samples=64, aperture=0.25, focal_distance=3.0, antialias=False)
    o, d = rays.origins[1, 1], rays.directions[1, 1]
    assert np.ptp(o[:, 0]) > 0.3                                   # spread over the lens
    on_focal_plane = o + ((-3.0 - o[:, 2]) / d[:, 2])[:, None] * d
    assert np.allclose(on_focal_plane, [0.0, 0.0, -3.0])           # one point in focus
    # Cook's trick: N paths per pixel whatever the number of effects
    assert not truth("ch15-distributed-cost")
    assert rays.directions.shape == (3, 3, 64, 3)


def test_fact_ch15_quadrics():
    # the cylinder's normal: the numerical gradient of x^2 + y^2 - r^2, normalised
    assert answer_text("ch15-cylinder-normal") == "$(x/r,\\ y/r,\\ 0)$"
    rng = np.random.default_rng(1515)
    r = 1.7
    f = lambda p: p[0] ** 2 + p[1] ** 2 - r * r          # noqa: E731
    for phi, z in zip(rng.uniform(0, 2 * np.pi, 20), rng.uniform(-3, 3, 20)):
        p = np.array([r * np.cos(phi), r * np.sin(phi), z])
        h = 1e-6
        g = np.array([(f(p + e) - f(p - e)) / (2 * h) for e in np.eye(3) * h])
        assert np.allclose(g / np.linalg.norm(g), [p[0] / r, p[1] / r, 0], atol=1e-6)
    # a depends on d only: fit the quadratic f(o + t d) for several origins
    assert truth("ch15-quadric-a-direction-only")
    A = rng.normal(size=(4, 4))
    Q = A + A.T
    d = rng.normal(size=3)
    leading = []
    for o in rng.normal(size=(5, 3)) * 3:
        ts = np.array([-1.0, 0.0, 2.0])
        vals = [np.r_[o + t * d, 1] @ Q @ np.r_[o + t * d, 1] for t in ts]
        leading.append(np.polyfit(ts, vals, 2)[0])
    assert np.allclose(leading, np.r_[d, 0] @ Q @ np.r_[d, 0])
    # a thin torus between two samples of the same sign: numpy.roots finds real roots anyway
    assert not truth("ch15-implicit-sampling")
    R, s = 2.0, 0.05
    o, d = np.array([-5.0, 0.0, 0.0]), np.array([1.0, 0.0, 0.0])
    torus = lambda p: (p @ p + R * R - s * s) ** 2 - 4 * R * R * (p[0] ** 2 + p[1] ** 2)  # noqa
    ts = np.linspace(0, 10, 5)                           # step 2.5 > the tube's 0.1
    vals = np.array([torus(o + t * d) for t in ts])
    assert np.all(vals > 0)                              # no change of sign
    # along x: (x^2 + R^2 - s^2)^2 - 4 R^2 x^2 with x = t - 5
    x2 = np.roots([1.0, 2 * (R * R - s * s) - 4 * R * R, (R * R - s * s) ** 2])
    assert np.all(np.isreal(x2)) and np.all(x2.real > 0)  # four real roots x = +-sqrt(x2)


def test_fact_ch18_unsteady():
    from scipy.integrate import solve_ivp
    from course_lib.scivis import lic
    # a pathline is tangent to the frozen field where it passes (double gyre typed here)
    assert answer_text("ch18-pathline-tangent") == "True"

    def gyre(t, p, A=0.1, eps=0.25, w=2 * math.pi / 10):
        a = eps * math.sin(w * t)
        f, dfdx = a * p[0] ** 2 + (1 - 2 * a) * p[0], 2 * a * p[0] + 1 - 2 * a
        return np.array([-math.pi * A * math.sin(math.pi * f) * math.cos(math.pi * p[1]),
                         math.pi * A * math.cos(math.pi * f) * math.sin(math.pi * p[1]) * dfdx])

    sol = solve_ivp(gyre, (0, 8), [0.3, 0.4], dense_output=True, rtol=1e-11, atol=1e-12)
    for t in (1.0, 4.0, 7.0):
        tangent = (sol.sol(t + 1e-5) - sol.sol(t - 1e-5)) / 2e-5
        assert np.allclose(tangent, gyre(t, sol.sol(t)), atol=1e-6)
    # the rotating uniform flow: pathlines are circles of radius U / omega
    assert answer_text("ch18-rotating-flow").startswith("A circle")
    U, w = 1.5, 0.6
    path = solve_ivp(lambda t, p: [U * math.cos(w * t), U * math.sin(w * t)], (0, 20), [0, 0],
                     rtol=1e-11, atol=1e-12, t_eval=np.linspace(0, 20, 200)).y.T
    centre = np.array([0.0, U / w])              # x(t) = (U/w) (sin wt, 1 - cos wt)
    assert np.allclose(np.linalg.norm(path - centre, axis=1), U / w, atol=1e-8)
    # a longer box kernel averages more samples: the spread falls like 1 / sqrt(2L + 1)
    assert "longer and smoother" in answer_text("ch18-lic-kernel")
    noise = RNG.random(200000)
    spreads = [np.convolve(noise, np.ones(2 * L + 1) / (2 * L + 1), mode="valid").std()
               for L in (1, 4, 16)]
    assert spreads[0] > spreads[1] > spreads[2]
    assert math.isclose(spreads[2] * math.sqrt(33), noise.std(), rel_tol=0.05)
    # LIC ignores orientation and speed
    assert answer_text("ch18-lic-orientation") == "True"
    y, x = np.mgrid[0:40, 0:40] - 19.5
    u, v = -y + 0.3 * x, x
    ref = lic(u, v, kernel_length=6, seed=3)
    assert np.allclose(lic(-u, -v, kernel_length=6, seed=3), ref)
    assert np.allclose(lic(2.5 * u, 2.5 * v, kernel_length=6, seed=3), ref)


def test_fact_ch18_topology():
    from scipy.integrate import solve_ivp
    from course_lib.scivis.topology import (critical_points, gridded_field, integrate_gridded,
                                            separatrices)
    # a negative determinant always gives real eigenvalues of opposite signs (a saddle)
    assert answer_text("ch18-topology-det-negative").startswith("A saddle")
    for _ in range(500):
        j = RNG.normal(size=(2, 2))
        lam = np.linalg.eigvals(j)
        if np.linalg.det(j) < 0:
            assert np.all(np.isreal(lam)) and lam.real.min() < 0 < lam.real.max()
    # a centre is not robust: a tiny change of the trace makes the orbit spiral
    assert truth("ch18-topology-centre-grid") is False

    def radius_after(trace):
        a = np.array([[trace / 2, -1.0], [1.0, trace / 2]])
        sol = solve_ivp(lambda t, y: a @ y, (0, 4 * np.pi), [1.0, 0.0], rtol=1e-10, atol=1e-12)
        return np.linalg.norm(sol.y[:, -1])
    assert math.isclose(radius_after(0.0), 1.0, rel_tol=1e-6)
    assert radius_after(0.01) > 1.05 and radius_after(-0.01) < 0.95
    # separatrices: forward along the unstable eigenvector, backward along the stable one
    assert "backward" in answer_text("ch18-topology-separatrix")
    axis = np.linspace(-1, 1, 21)
    x, y = np.meshgrid(axis, axis)
    f = gridded_field(x + 2 * y, 0.5 * x - y, axis[1] - axis[0], (-1.0, -1.0))
    (saddle,) = critical_points(f)
    lam, vec = np.linalg.eig(np.array([[1.0, 2.0], [0.5, -1.0]]))
    e_s = vec[:, np.argmin(lam)]
    seed = saddle.position + 0.01 * e_s
    forward = integrate_gridded(f, seed, 0.01, 300)          # runs back into the saddle
    assert np.linalg.norm(forward[-1] - saddle.position) < 0.01
    sep = separatrices(f, saddle, n=2000)["stable"][0]
    assert np.linalg.norm(sep[-1] - saddle.position) > 0.5   # traced backward: goes out


def test_fact_ch15_spatial():
    """Spatial subdivision: the teapot in a stadium, object vs space subdivision, mailboxing and
    the early exit, checked on meshes with course_lib.raytracing.spatial against brute force."""
    import trimesh
    from course_lib._raycore import BVH, brute_force, triangle_soa
    from course_lib.raytracing.spatial import Octree, UniformGrid

    rng = np.random.default_rng(1522)
    # the teapot in a stadium: a fine sphere of radius 0.5 and a stadium floor 1000 wide
    ball = trimesh.creation.icosphere(4, radius=0.5)
    floor = np.array([[-500, -500, -2], [500, -500, -2], [500, 500, -2], [-500, 500, -2],
                      [-500, -500, 300.0]])
    v = np.vstack([ball.vertices, floor])
    k = len(ball.vertices)
    f = np.vstack([ball.faces, [[k, k + 1, k + 2], [k, k + 2, k + 3], [k, k + 1, k + 4]]])
    o = np.tile([0.0, 0.0, 5.0], (30, 1))
    d = np.column_stack([rng.uniform(-0.05, 0.05, (30, 2)), -np.ones(30)])
    ref = brute_force(o, d, triangle_soa(v[f]), 0.0, np.full(30, np.inf))
    grid, tree = UniformGrid(v, f), Octree(v, f, max_depth=12, leaf_size=8)
    g, t = grid.intersect(o, d), tree.intersect(o, d)
    assert np.array_equal(g.ids, ref[1]) and np.array_equal(t.ids, ref[1])
    assert not truth("ch15-teapot-stadium")
    assert g.triangle_tests > 10 * t.triangle_tests        # the grid's crowded cell
    # object vs space subdivision: a BVH lists each triangle once; a grid duplicates
    assert answer_text("ch15-object-vs-space").startswith("Space subdivision cuts space")
    mesh = trimesh.creation.torus(1.0, 0.3)
    leaves = BVH(mesh.vertices[mesh.faces], leaf_size=4).leaves
    listed = np.concatenate(leaves)
    assert np.array_equal(np.sort(listed), np.arange(len(mesh.faces)))
    assert UniformGrid(mesh.vertices, mesh.faces).references > len(mesh.faces)
    # mailboxing: same hits, fewer tests
    assert answer_text("ch15-mailboxing").startswith("It remembers")
    o = rng.normal(size=(100, 3)) * 3
    d = -o + rng.normal(size=(100, 3))
    a = UniformGrid(mesh.vertices, mesh.faces).intersect(o, d)
    b = UniformGrid(mesh.vertices, mesh.faces).intersect(o, d, mailbox=False)
    assert np.array_equal(a.ids, b.ids) and a.triangle_tests < b.triangle_tests
    # the early exit: a long triangle listed in the first cell is hit beyond it, a small one
    # in the second cell nearer; accepting the first hit found would be wrong
    assert not truth("ch15-grid-early-exit")
    v = [[0.2, -1, -1], [0.2, 1, -1], [3.9, 0, 1],              # slanted, from x=0.2 to 3.9
         [1.5, -1, -1], [1.5, 1, -1], [1.5, 0, 1]]               # a wall at x = 1.5
    grid = UniformGrid(v, [[0, 1, 2], [3, 4, 5]], resolution=[4, 1, 1])
    o, d = np.array([[0.0, 0, 0]]), np.array([[1.0, 0, 0]])
    cells, t_in, t_out = grid.traverse(o[0], d[0])
    first = grid.cell_triangles(cells[0])
    assert first.tolist() == [0]
    t0 = (0.2 + 3.7 / 2)                                         # the slanted one at z = 0
    assert t0 > t_out[0]                                         # hit beyond the first cell
    assert grid.intersect(o, d).ids.tolist() == [1]              # the wall at t = 1.5 is nearer
    assert brute_force(o, d, triangle_soa(np.array(v)[[[0, 1, 2], [3, 4, 5]]]), 0.0,
                       np.array([np.inf]))[1].tolist() == [1]


def test_fact_ch18_volume_methods():
    # the asymptotic decider's example, by sampling the bilinear interpolant densely
    assert "saddle value" in answer_text("ch18-asymptotic-decider")
    f0, f1, f2, f3, c = 0.0, 4.0, 0.0, 10.0, 3.0
    s, t = np.meshgrid(np.linspace(0, 1, 1001), np.linspace(0, 1, 1001))
    g = f0 * (1 - s) * (1 - t) + f1 * s * (1 - t) + f2 * s * t + f3 * (1 - s) * t
    from scipy import ndimage
    mid = (f0 * f2 - f1 * f3) / (f0 + f2 - f1 - f3)
    assert np.isclose(mid, 40 / 14) and mid < c <= (f0 + f1 + f2 + f3) / 4
    labels, _ = ndimage.label(g >= c)                # rows t, columns s
    assert labels[0, -1] != labels[-1, 0]            # corners 1 and 3 are not connected
    # the saddle value is the interpolant's value where both partial derivatives vanish
    den = f0 + f2 - f1 - f3
    s0, t0 = (f0 - f3) / den, (f0 - f1) / den
    assert np.isclose(f0 * (1 - s0) * (1 - t0) + f1 * s0 * (1 - t0) + f2 * s0 * t0
                      + f3 * (1 - s0) * t0, mid)
    # central differences are exact for a quadratic, forward ones off by a h
    a, h, x = 1.7, 0.3, 0.8
    f = lambda u: a * u * u  # noqa: E731
    assert np.isclose((f(x + h) - f(x - h)) / (2 * h), 2 * a * x)
    assert np.isclose((f(x + h) - f(x)) / h - 2 * a * x, a * h)
    assert answer_text("ch18-central-difference-quadratic") == "True"
    # the over operator traversed front to back paints the far layer on top
    layers = [(np.array([0, 0, 1.0]), 0.9), (np.array([1.0, 0, 0]), 0.9)]   # front first

    def over(seq):
        C, A = np.zeros(3), 0.0
        for col, al in seq:
            C, A = al * col + (1 - al) * C, al + (1 - al) * A
        return C, A
    right, wrong = over(layers[::-1]), over(layers)
    assert right[0][2] > right[0][0] and wrong[0][0] > wrong[0][2]
    assert np.isclose(right[1], wrong[1])
    assert "behind" in answer_text("ch18-splat-order")
    # opacity correction: two slices of 1 - (1 - alpha)^(1/2) let through 1 - alpha
    alpha = 0.6
    assert np.isclose((1 - (1 - (1 - alpha) ** 0.5)) ** 2, 1 - alpha)
    assert not np.isclose((1 - alpha / 2) ** 2, 1 - alpha)
    assert answer_text("ch18-slice-opacity").startswith("$1 - (1 - ")
    # a step transfer function: classify-then-interpolate is not interpolate-then-classify
    step = lambda v: (np.asarray(v) >= 0.5).astype(float)  # noqa: E731
    v0, v1, w = 0.0, 1.0, 0.3
    assert (1 - w) * step(v0) + w * step(v1) != step((1 - w) * v0 + w * v1)
    assert answer_text("ch18-pre-post-classification") == "False"
