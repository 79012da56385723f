"""Tests of the chapter 14 exercises (course_lib.exercises.ch14).

For every exercise and many seeds: the statement reads, the right answer is accepted (also
rounded to 3 decimals and as a plain list), placeholders are "unanswered", garbage is "invalid",
and every anticipated mistake, rebuilt here from the question's attributes, is named by its
diagnosis. The right answers are computed here independently of the checkers (never with
course_lib.texturing, which the checkers call): bilinear samples with
``scipy.ndimage.map_coordinates``, barycentric coordinates with trimesh's
``points_to_barycentric``, perspective-correct texture coordinates by projecting a real 3D
triangle and finding the point of the triangle under the pixel, OpenGL's wrap rules, and the
mapping, mipmap and checkerboard formulas typed out below.
"""
import math

import numpy as np
import pytest
from scipy.ndimage import map_coordinates
from trimesh.triangles import points_to_barycentric

from course_lib.exercises import ch14
import exercise_harness as harness
from exercise_harness import SAME, SEEDS, Either
from course_lib.exercises.core import gap


# ---------------------------------------------------------------------------------------------
# Independent computations
# ---------------------------------------------------------------------------------------------

def scipy_bilinear(T, u, v):
    """Bilinear sample with texel centres at ((j + 1/2)/W, (i + 1/2)/H), by scipy."""
    h, w = T.shape
    return float(map_coordinates(np.asarray(T, float), [[v * h - 0.5], [u * w - 0.5]],
                                 order=1, mode="nearest")[0])


def nearest(ex):
    T, u, v = ex.texture, ex.u, ex.v
    i, j = int(np.floor(v * 4)), int(np.floor(u * 4))
    return float(T[i, j]), {
        "rounded": float(T[int(np.rint(v * 4)), int(np.rint(u * 4))]),
        "row and column swapped": float(T[j, i]),
        "rows counted from the top": float(np.flipud(T)[i, j]),
    }


def bilinear(ex):
    T, u, v = ex.texture, ex.u, ex.v
    x, y = u * 4 - 0.5, v * 4 - 0.5
    i, j = int(np.floor(y)), int(np.floor(x))
    a, b = x - j, y - i
    swapped = (b * (a * T[i, j] + (1 - a) * T[i, j + 1])
               + (1 - b) * (a * T[i + 1, j] + (1 - a) * T[i + 1, j + 1]))
    return scipy_bilinear(T, u, v), {
        "no half-texel offset": float(map_coordinates(T, [[v * 4], [u * 4]], order=1)[0]),
        "u and v swapped": scipy_bilinear(T.T, u, v),
        "nearest": float(T[int(v * 4), int(u * 4)]),
        "weights reversed": swapped,
        "rows counted from the top": scipy_bilinear(np.flipud(T), u, v),
    }


def gl_repeat(u, W):
    return math.floor((u - math.floor(u)) * W)


def gl_mirror(u, W):
    """OpenGL's mirrored repeat: the fraction, reversed on odd copies."""
    f = u - math.floor(u)
    if math.floor(u) % 2:
        f = 1 - f
    return min(math.floor(f * W), W - 1)


def wrap_modes(ex):
    u, W = ex.u, ex.width
    repeat = gl_repeat(u, W)
    clamp = min(max(math.floor(u * W), 0), W - 1)
    mirror = gl_mirror(u, W)
    right = np.array([repeat, clamp, mirror], dtype=float)
    mistakes = {
        "truncated toward zero": [int(u * W) % W, clamp, mirror],
        "sign dropped": [math.floor((abs(u) % 1) * W), clamp, mirror],
        "wrong copies mirrored": [repeat, clamp,
                                  W - 1 - repeat if math.floor(u) % 2 == 0 else repeat],
    }
    if u > 1:
        mistakes["one past the edge"] = [repeat, W, mirror]
    if math.floor(u) % 2:
        mistakes["mirrored off by one"] = [repeat, clamp, W - repeat]
    return right, mistakes


def signed_area(p, q, r):
    (a, b), (c, d) = np.subtract(q, p), np.subtract(r, p)
    return 0.5 * float(a * d - b * c)


def trimesh_barycentric(P, A, B, C):
    tri = np.array([[[*A, 0.0], [*B, 0.0], [*C, 0.0]]])
    return points_to_barycentric(tri, np.array([[*P, 0.0]]))[0]


PERMUTATIONS = ((0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0))


def barycentric(ex):
    right = trimesh_barycentric(ex.P, ex.A, ex.B, ex.C)
    assert np.allclose(right @ np.array([ex.A, ex.B, ex.C]), ex.P)
    areas = np.array([signed_area(ex.P, ex.B, ex.C), signed_area(ex.A, ex.P, ex.C),
                      signed_area(ex.A, ex.B, ex.P)])
    total = signed_area(ex.A, ex.B, ex.C)
    return right, {
        "wrong vertex order": Either([right[list(p)] for p in PERMUTATIONS]),
        "unsigned areas": Either([np.abs(areas) / abs(total),
                                  np.abs(areas) / np.abs(areas).sum()]),
        "not divided by the total area": Either([areas, 2 * areas]),
    }


def interpolate_colour(ex):
    lam = trimesh_barycentric(ex.P, ex.A, ex.B, ex.C)
    c = np.asarray(ex.colours, float)
    areas = np.array([signed_area(ex.P, ex.B, ex.C), signed_area(ex.A, ex.P, ex.C),
                      signed_area(ex.A, ex.B, ex.P)])
    return lam @ c, {
        "wrong vertex order": Either([lam[list(p)] @ c for p in PERMUTATIONS]),
        "plain average": c.mean(axis=0),
        "not divided by the total area": areas @ c,
        "nearest corner": c[int(np.argmax(lam))],
    }


def perspective(ex):
    """Project a real triangle whose vertices have the depths w; find the point under the pixel.

    The camera looks along +z and projects (x, y, z) to (x/z, y/z); the pixel is the screen
    point with the given screen-space weights. The 3D point of the triangle on the pixel's ray
    has 3D barycentric weights mu; its texture coordinates are sum mu_k q_k.
    """
    lam, w, q = (np.asarray(x, float) for x in (ex.weights, ex.w, ex.uv))
    rng = np.random.default_rng(ex.seed)
    while True:
        X = np.column_stack([rng.uniform(-3, 3, size=(3, 2)), w])
        screen = X[:, :2] / X[:, 2:]
        if abs(np.linalg.det(np.column_stack([screen, np.ones(3)]))) > 0.1:
            break
    s = lam @ screen
    system = np.vstack([X[:, 0] - s[0] * X[:, 2], X[:, 1] - s[1] * X[:, 2], np.ones(3)])
    mu = np.linalg.solve(system, [0.0, 0.0, 1.0])
    right = mu @ q
    return right, {
        "linear in screen space": lam @ q,
        "multiplied by w": (lam * w) @ q / (lam @ w),
        "no division by the sum": (lam / w) @ q,
    }


def azimuth_u(x, z):
    return 0.5 + math.atan2(x, z) / (2 * math.pi)


def spherical(ex):
    x, y, z = np.asarray(ex.P, float) - np.asarray(ex.center, float)
    r = math.sqrt(x * x + y * y + z * z)
    assert abs(r - ex.radius) < 1e-12
    theta, phi = math.atan2(x, z), math.atan2(y, math.hypot(x, z))
    u, v = 0.5 + theta / (2 * math.pi), 0.5 + phi / math.pi
    # the inverse map gives the point back
    t, p = 2 * math.pi * (u - 0.5), math.pi * (v - 0.5)
    assert np.allclose(r * np.array([math.cos(p) * math.sin(t), math.sin(p),
                                     math.cos(p) * math.cos(t)]), [x, y, z])
    mistakes = {
        "compendium's elevation": [u, 0.5 + math.atan(y / math.hypot(x, y)) / math.pi],
        "u and v swapped": [v, u],
        "angles, not (u, v)": [theta, phi],
        "no offset": [theta / (2 * math.pi), phi / math.pi],
    }
    if z != 0:
        mistakes["atan instead of atan2"] = [0.5 + math.atan(x / z) / (2 * math.pi), v]
    if np.any(ex.center) and np.any(ex.P):
        px, py, pz = ex.P
        mistakes["centre not subtracted"] = [azimuth_u(px, pz), 0.5 + math.atan2(
            py, math.hypot(px, pz)) / math.pi]
    return np.array([u, v]), mistakes


def cylindrical(ex):
    x, y, z = np.asarray(ex.P, float) - np.asarray(ex.base, float)
    h = ex.height
    u, v = azimuth_u(x, z), y / h
    mistakes = {
        "azimuth from the x axis": [azimuth_u(z, x), v],
        "v not divided by the height": [u, y],
        "u and v swapped": [v, u],
    }
    if z != 0:
        mistakes["atan instead of atan2"] = [0.5 + math.atan(x / z) / (2 * math.pi), v]
    if ex.base[1] != 0:
        mistakes["base not subtracted"] = [u, ex.P[1] / h]
    return np.array([u, v]), mistakes


def planar(ex):
    n, e_u = np.asarray(ex.normal, float), np.asarray(ex.u_axis, float)
    e_v = np.array([n[1] * e_u[2] - n[2] * e_u[1], n[2] * e_u[0] - n[0] * e_u[2],
                    n[0] * e_u[1] - n[1] * e_u[0]])
    assert np.linalg.det(np.array([e_u, e_v, n])) > 0        # right-handed (e_u, e_v, n)
    d = np.asarray(ex.P, float) - np.asarray(ex.origin, float)
    su, sv = ex.size
    u, v = d @ e_u / su, d @ e_v / sv
    mistakes = {
        "v axis mirrored": [u, -v],
        "not divided by the size": [d @ e_u, d @ e_v],
        "origin ignored": [ex.P @ e_u / su, ex.P @ e_v / sv],
    }
    if abs(n[2]) != 1:
        mistakes["x and y taken"] = [d[0] / su, d[1] / sv]
    return np.array([u, v]), mistakes


def mip_level(ex):
    W, H = ex.width, ex.height
    steps = [(W * ex.du_dx, H * ex.dv_dx), (W * ex.du_dy, H * ex.dv_dy)]
    lengths = [math.hypot(a, b) for a, b in steps]
    rho = max(lengths)
    lam = math.log2(rho)
    w, h = W >> ex.k, H >> ex.k
    right = np.array([rho, lam, w, h], dtype=float)

    def part(index, *values):
        out = []
        for value in values:
            answer = right.copy()
            answer[index] = value
            out.append(answer)
        return Either(out)

    return right, {
        "lengths added": part(0, max(abs(a) + abs(b) for a, b in steps)),
        "min instead of max": part(0, min(lengths)),
        "not in texels": part(0, max(math.hypot(ex.du_dx, ex.dv_dx),
                                     math.hypot(ex.du_dy, ex.dv_dy))),
        "natural logarithm": part(1, math.log(rho)),
        "log10": part(1, math.log10(rho)),
        "half the logarithm": part(1, lam / 2),
        "off by one": part(1, lam + 1),
        "off by one level": Either(part(2, W / 2 ** (ex.k + 1), W / 2 ** (ex.k - 1))
                                   + part(3, H / 2 ** (ex.k + 1), H / 2 ** (ex.k - 1))),
        "quartered": Either(part(2, W / 4 ** ex.k) + part(3, H / 4 ** ex.k)),
    }


def checkerboard(ex):
    s, p = ex.squares, np.asarray(ex.points, float)
    sums = [sum(math.floor(s * c) for c in row) for row in p]
    right = np.array([total % 2 for total in sums])
    return right, {
        "rounded": np.array([sum(round(s * c) for c in row) % 2 for row in p], dtype=float),
        "truncated toward zero": np.array([sum(int(s * c) for c in row) % 2 for row in p],
                                          dtype=float),
        "squares ignored": np.array([sum(math.floor(c) for c in row) % 2 for row in p],
                                    dtype=float),
        "no modulo": np.array(sums, dtype=float),
    }


NUMBER_GARBAGE = ["t", {"t": 1}, [1, 2], [[1], [2, 3]], [math.nan], math.inf]
UV_GARBAGE = ["uv", {"u": 1}, [[1, 2], [3]], [1, 2, 3], np.eye(2), [math.nan, 0]]
VECTOR3_GARBAGE = ["l", {"l": 1}, [[1, 2], [3]], [1, 2], np.eye(3), [math.nan, 0, 0]]
THREE_GARBAGE = ["j", {"j": 1}, [1, 2], [[1, 2, 3], [4, 5, 6]], [1, math.nan, 2], [1, 2, 3, 4]]
FOUR_GARBAGE = ["rho", {"r": 1}, [1, 2, 3], [[1, 2], [3, 4]], [1, 2, 3, math.nan], [1] * 5]
SIX_GARBAGE = ["T", {"t": 1}, [1, 0, 1, 0], [[1, 0, 1], [0, 1, 0]], [1, 0, 1, 0, 1, math.nan],
               [1] * 7]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "NearestSample": (nearest, "number"),
    "BilinearSample": (bilinear, "number"),
    "WrapModes": (wrap_modes, "three"),
    "BarycentricCoordinates": (barycentric, "vector3"),
    "InterpolateColour": (interpolate_colour, "vector3"),
    "PerspectiveCorrect": (perspective, "uv"),
    "SphericalMap": (spherical, "uv"),
    "CylindricalMap": (cylindrical, "uv"),
    "PlanarMap": (planar, "uv"),
    "MipLevel": (mip_level, "four"),
    "Checkerboard": (checkerboard, "six"),
}
GARBAGE = {"number": NUMBER_GARBAGE, "uv": UV_GARBAGE, "vector3": VECTOR3_GARBAGE,
           "three": THREE_GARBAGE, "four": FOUR_GARBAGE, "six": SIX_GARBAGE}


#: The chapter's exercises are split over topic files: this one tests those in SPECS
#: (tests/test_exercises_ch14_*.py the others), and test_every_exercise_is_tested_in_one_file
#: holds the union to the chapter's list.
TOPIC = harness.topic(ch14, SPECS)
exercises = harness.variants(TOPIC)


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(
    TOPIC, SPECS, GARBAGE, exercises, at_least=8, distinct=(30, 10),
    newlines=r"\\neq?\b|\\normal"))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, lambda a, b, form: gap(a, b) < SAME,
    key_seeds=SEEDS)


test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch14, SPECS, at_least=20)
def test_wrong_answers_get_teaching_feedback():
    """An answer no slip explains still says how to get it right."""
    for name in SPECS:
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 0.37)
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
            assert fb.message.count("$") >= 2            # the formula is spelt out


def test_numbers_are_nice_for_hand_work():
    for name in ("NearestSample", "BilinearSample"):
        for ex in exercises(name):
            assert ex.texture.shape == (4, 4) and np.all(ex.texture == np.round(ex.texture))
            for c in (ex.u, ex.v):
                assert abs(c * 20 - round(c * 20)) < 1e-9
    for ex in exercises("NearestSample"):
        assert len(set(ex.texture.ravel())) == 16        # the value names the texel
    for name in ("BarycentricCoordinates", "InterpolateColour"):
        for ex in exercises(name):
            corners = np.array([ex.A, ex.B, ex.C, ex.P])
            assert np.all(corners == np.round(corners))
    for ex in exercises("InterpolateColour"):
        assert np.all(trimesh_barycentric(ex.P, ex.A, ex.B, ex.C) > 0)   # inside
    for ex in exercises("SphericalMap"):
        assert ex.radius == round(ex.radius)


def test_outside_points_are_asked():
    outside = [ex for ex in exercises("BarycentricCoordinates")
               if np.any(barycentric(ex)[0] < 0)]
    assert 20 <= len(outside) < 200
    modes = exercises("WrapModes")
    assert any(ex.u < 0 for ex in modes) and any(ex.u > 1 for ex in modes)
    assert any(math.floor(ex.u) % 2 for ex in modes) and any(
        math.floor(ex.u) % 2 == 0 for ex in modes)


def test_perspective_construction_agrees_with_the_closed_form():
    """The projected-triangle construction equals sum(lam q / w) / sum(lam / w)."""
    for ex in exercises("PerspectiveCorrect", range(50)):
        lam, w, q = ex.weights, ex.w, ex.uv
        closed = (lam / w) @ q / (lam / w).sum()
        assert np.allclose(perspective(ex)[0], closed)


# ---------------------------------------------------------------------------------------------
# Whole numbers, variety, advice
# ---------------------------------------------------------------------------------------------

def anticipated(answer, mistakes):
    """Whether `answer` is one of the anticipated mistakes."""
    return any(gap(answer, value) < SAME for values in mistakes.values()
               for value in (values if isinstance(values, Either) else [values]))


#: The entries of an answer that are whole numbers: texel columns, the sides of a mipmap level,
#: checker values.
WHOLE = {"WrapModes": (0, 1, 2), "MipLevel": (2, 3), "Checkerboard": tuple(range(6))}


@pytest.mark.parametrize("name", WHOLE)
def test_whole_numbers_are_compared_exactly(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, mistakes = solve(ex)
        right = np.asarray(right, dtype=float)
        assert ex.check([float(x) for x in right]).status == "correct"      # 3.0 is 3
        assert ex.check([int(x) if k in WHOLE[name] else x
                         for k, x in enumerate(right)]).status == "correct"
        for k in WHOLE[name]:
            nearly = right.copy()
            nearly[k] += 0.001                        # within any tolerance, but not whole
            assert ex.check(nearly).status == "wrong", (ex, nearly)
            for step in (1, -1):
                answer = right.copy()
                answer[k] += step
                fb = ex.check(answer)
                assert fb.status == "wrong", (ex, answer, fb)
                if anticipated(answer, mistakes):
                    continue
                if name == "Checkerboard":
                    # one point of the other colour, or a value that is neither 0 nor 1
                    key = "components differ" if answer[k] in (0, 1) else "not 0 or 1"
                    assert fb.diagnosis == key and f"[{k}]" in fb.message, (ex, answer, fb)
                else:
                    assert fb.diagnosis == "off by one", (ex, answer, fb)


def test_the_mipmap_sizes_and_wrap_columns_are_exact_integers():
    for ex in exercises("WrapModes"):
        assert ex.expected.dtype.kind == "i"
    for ex in exercises("Checkerboard"):
        assert ex.expected.dtype.kind == "i" and set(ex.expected) <= {0, 1}
        assert len(ex.points) == 6
    for ex in exercises("MipLevel"):
        assert ex.width % 2 ** ex.k == 0 and ex.height % 2 ** ex.k == 0


#: Distinct right answers among 300 seeds that every exercise reaches.
MIN_VARIANTS = 30


@pytest.mark.parametrize("name", SPECS)
def test_enough_distinct_variants(name):
    cls = getattr(ch14, name)
    answers = {harness.answer_key(cls(seed=seed).expected, decimals=9) for seed in range(300)}
    assert len(answers) >= MIN_VARIANTS, (name, len(answers))


@pytest.mark.parametrize("name", SPECS)
def test_the_advice_is_given_at_most_once(name):
    checked, shown = harness.advice_counts(
        exercises(name), SPECS[name][0], lambda ex, right: harness.wrong_answers(right, True))
    assert shown >= checked // 4            # the advice is given, where no slip explains
