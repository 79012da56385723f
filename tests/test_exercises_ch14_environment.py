"""Tests of the environment-mapping exercises (course_lib/exercises/_ch14/environment.py), on
tests/exercise_harness.py.

The right answers and every anticipated slip are recomputed here, not with course_lib: the
OpenGL cube-map table is typed out below as a dict of face name -> (s_c, t_c, m_a) written as
signed axis letters; the sphere map is computed twice, by OpenGL's formula for m and from the
mirror ball's geometry (the ball's normal is the halfway vector of r and the direction to the
viewer, and (s, t) = (n_x + 1, n_y + 1)/2); the reflection of the view ray is the Householder
matrix I - 2 n n^T applied to I, checked by the mirror law (R.N = -I.N, R - I along N).
"""
import math
from types import SimpleNamespace

import numpy as np
import pytest

import exercise_harness as harness
from exercise_harness import SEEDS
from course_lib.exercises._ch14 import environment as module
from course_lib.exercises.core import gap
from course_lib.exercises.mock import ExamQuestion

CLASSES = [module.CubeMapFace, module.SphereMapCoordinates, module.EnvironmentReflection]
ch14 = SimpleNamespace(EXERCISES=CLASSES, **{c.__name__: c for c in CLASSES})

#: OpenGL 4.6, table 8.19 (cube map face selection): face -> (s_c, t_c, m_a).
GL_TABLE = {
    "+X": ("-z", "-y", "x"),
    "-X": ("+z", "-y", "x"),
    "+Y": ("+x", "+z", "y"),
    "-Y": ("+x", "-z", "y"),
    "+Z": ("+x", "-y", "z"),
    "-Z": ("-x", "-y", "z"),
}
ORDER = ["+X", "-X", "+Y", "-Y", "+Z", "-Z"]          # face numbers 0..5


def component(expr, r):
    """``"-z"`` of r: the signed component."""
    value = float(r["xyz".index(expr[-1])])
    return -value if expr.startswith("-") else value


def major_face(r):
    """The name of the face of the largest |r_i|, the first of x, y, z on a tie."""
    mags = [abs(float(x)) for x in r]
    k = mags.index(max(mags))
    return ("-" if r[k] < 0 else "+") + "XYZ"[k]


def flip(name):
    return ("+" if name[0] == "-" else "-") + name[1]


def read(r, name, signed_ma=False, sc_sign=1, tc_sign=1, mapped=True):
    """[face number, s, t] of direction r read on face `name` by the typed table."""
    sc_expr, tc_expr, ma_axis = GL_TABLE[name]
    sc, tc = sc_sign * component(sc_expr, r), tc_sign * component(tc_expr, r)
    ma = component("+" + ma_axis, r)
    d = ma if signed_ma else abs(ma)
    if not mapped:
        return [ORDER.index(name), sc / d, tc / d]
    return [ORDER.index(name), (sc / d + 1) / 2, (tc / d + 1) / 2]


def cube_face(ex):
    r = np.asarray(ex.direction, dtype=float)
    name = major_face(r)
    right = read(r, name)
    f, s, t = right
    mistakes = {
        "sc sign": read(r, name, sc_sign=-1),
        "tc sign": read(r, name, tc_sign=-1),
        "not mapped to [0, 1]": read(r, name, mapped=False),
        "s and t swapped": [f, t, s],
        "face sign": read(r, flip(name)),
    }
    if component("+" + GL_TABLE[name][2], r) < 0:
        mistakes["divided by signed m_a"] = read(r, name, signed_ma=True)
    k = int(np.argmax(r))                                  # the largest *value*
    signed = ("-" if r[k] < 0 else "+") + "XYZ"[k]
    if signed != name:
        mistakes["largest signed component"] = read(r, signed)
    mags = np.abs(r)
    tied = [j for j in range(3) if mags[j] == mags.max()]
    if len(tied) == 2:
        j = tied[1]
        mistakes["tie order"] = read(r, ("-" if r[j] < 0 else "+") + "XYZ"[j])
    return right, mistakes


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / math.sqrt(float(v @ v))


def householder(i, n):
    n = unit(n)
    return (np.eye(3) - 2 * np.outer(n, n)) @ np.asarray(i, dtype=float)


def sphere_formula(r, plus=1.0, factor=2.0, half=0.5):
    x, y, z = r
    m = factor * math.sqrt(x * x + y * y + (z + plus) ** 2)
    return [x / m + half, y / m + half]


def mirror_ball(r):
    """(s, t) where a mirror ball seen along -z shows direction r: its normal is the halfway
    vector of r and the direction to the viewer (0, 0, 1)."""
    n = unit(unit(r) + [0.0, 0.0, 1.0])
    return [(n[0] + 1) / 2, (n[1] + 1) / 2]


def reflection_of(ex):
    if ex.kind == "reflection":
        return np.asarray(ex.R, dtype=float)
    return householder(ex.I, ex.N)


def sphere_map(ex):
    raw = reflection_of(ex)
    r = unit(raw)
    right = sphere_formula(r)
    assert gap(right, mirror_ball(r)) < 1e-12            # two derivations agree
    s, t = right
    mistakes = {
        "no +1 on r_z": sphere_formula(r, plus=0.0),
        "no factor 2": sphere_formula(r, factor=1.0),
        "no +1/2": sphere_formula(r, half=0.0),
        "s and t swapped": [t, s],
    }
    if ex.kind == "reflection":
        mistakes["R not normalised"] = sphere_formula(raw)
    else:
        mistakes["reflection sign"] = sphere_formula(-r)
    return right, mistakes


def face_number(v):
    return ORDER.index(major_face(v))


def environment_reflection(ex):
    i, n = np.asarray(ex.I, dtype=float), np.asarray(ex.N, dtype=float)
    r = householder(i, n)
    nh = unit(n)
    assert math.isclose(r @ nh, -(i @ nh), abs_tol=1e-12)          # the mirror law
    assert np.linalg.norm(np.cross(r - i, n)) < 1e-12
    right = [*r, face_number(r)]
    slips = {
        "reflection sign": 2 * (nh @ i) * nh - i,
        "N not normalised": i - 2 * (n @ i) * n,
        "N normalised once": i - 2 * (nh @ i) * n,
        "factor 2 missing": i - (nh @ i) * nh,
    }
    mistakes = {key: [*v, face_number(v)] for key, v in slips.items()}
    mistakes["face sign"] = [*r, ORDER.index(flip(major_face(r)))]
    k = int(np.argmax(r))
    mistakes["largest signed component"] = [*r, ORDER.index(("-" if r[k] < 0 else "+")
                                                            + "XYZ"[k])]
    return right, mistakes


SPECS = {"CubeMapFace": (cube_face, "face3"),
         "SphereMapCoordinates": (sphere_map, "uv"),
         "EnvironmentReflection": (environment_reflection, "face4")}
GARBAGE = {
    "face3": ["I", {"I": 1}, [1, 2], [[1], [2, 3]], [math.nan, 0, 0], [1, math.inf, 0],
              [0.5, 0.2, 0.3], [7, 0.5, 0.5], [-1, 0.5, 0.5], ["Q", 0.5, 0.5],
              ["X", 0.5, 0.5], [0, "a", 0.5], [1, 2, 3, 4], [True, 0.5, 0.5], "+X 0.5"],
    "uv": ["s", {"s": 1}, [1, 2, 3], [[1], [2, 3]], [math.nan, 0], [1, math.inf]],
    "face4": ["R", {"R": 1}, [1, 2, 3], [[1, 2], [3, 4]], [0, 0, 1, math.nan],
              [0, 0, 1, 6], [0, 0, 1, 2.5], [0, 0, 1, "up"], [0, math.inf, 1, 2],
              [1, 2, 3, 4, 5], ["+X", 0, 0, 1]],
}
exercises = harness.variants(ch14, seeds=range(300))


same = harness.same


globals().update(harness.common_tests(ch14, SPECS, GARBAGE, exercises, at_least=3,
                                      distinct=(30, 10)))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same, key_seeds=SEEDS)
test_right_answer_is_accepted = harness.right_answer_test(SPECS, exercises)


@pytest.mark.parametrize("name", SPECS)
def test_answers_to_three_significant_digits_are_accepted(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        rounded = [harness.significant(x) if x != 0 else 0.0 for x in right]
        assert ex.check(rounded).status == "correct", (ex, rounded)


@pytest.mark.parametrize("name", SPECS)
def test_expected_answers_agree_with_the_typed_computation(name):
    solve, _ = SPECS[name]
    for ex in exercises(name):
        assert gap(ex.expected, solve(ex)[0]) < 1e-12, ex


@pytest.mark.parametrize("name", SPECS)
def test_worked_solution_and_hints(name):
    solve, _ = SPECS[name]
    for ex in exercises(name, range(40)):
        worked = ex.worked()
        assert gap(worked.answer, solve(ex)[0]) < 1e-9 and ex.check(worked.answer)
        assert len(ex.hints()) >= 3


@pytest.mark.parametrize("name", SPECS)
def test_seeds_give_many_different_answers(name):
    answers = {harness.answer_key(ex.expected) for ex in exercises(name)}
    assert len(answers) >= 30, (name, len(answers))


def test_faces_may_be_given_by_name_or_number_in_several_spellings():
    spellings = {0: ["+X", "x+", "posx", "positive x", "+x face"], 1: ["-X", "\u2212x", "NEGX"],
                 2: ["+Y", "Y+"], 3: ["-y", "negative_y"], 4: ["+z"], 5: ["-Z", "GL_TEXTURE_CUBE_MAP_NEGATIVE_Z"]}
    seen = set()
    for ex in exercises("CubeMapFace", range(120)):
        f, s, t = cube_face(ex)[0]
        seen.add(f)
        for name in spellings[f]:
            assert ex.check([name, s, t]).status == "correct", (ex, name)
        assert ex.check((float(f), s, t)).status == "correct"
        assert ex.check(np.array([f, s, t])).status == "correct"
        assert ex.check(f"{ORDER[f]}, {s!r}, {t!r}").status == "correct"   # typed as text
        wrong = ORDER[(f + 2) % 6]
        fb = ex.check([wrong, s, t])
        assert fb.status == "wrong", (ex, wrong, fb)
    assert seen == set(range(6))
    for ex in exercises("EnvironmentReflection", range(60)):
        rx, ry, rz, f = environment_reflection(ex)[0]
        assert ex.check([rx, ry, rz, ORDER[f]]).status == "correct"
        assert ex.check([rx, ry, rz, ORDER[f].lower()[::-1]]).status == "correct"   # "x+"


def test_the_exam_reads_a_face_name_typed_as_text():
    for seed in range(30):
        q = ExamQuestion(14, module.CubeMapFace(seed=seed))
        f, s, t = cube_face(q.source)[0]
        for typed in (f"{ORDER[f]}, {s!r}, {t!r}", f"['{ORDER[f]}', {s!r}, {t!r}]",
                      f"{f}, {s!r}, {t!r}"):
            assert q.check(typed).status == "correct", typed
        assert q.check(f"{ORDER[f]}, {t!r}").status == "invalid"


def test_a_right_face_with_wrong_coordinates_says_so():
    for ex in exercises("CubeMapFace", range(60)):
        f, s, t = cube_face(ex)[0]
        for answer in ([f, s + 0.31, t], [ORDER[f], s + 0.31, t]):
            fb = ex.check(answer)
            assert (fb.status, fb.diagnosis) == ("wrong", "components differ"), (ex, fb)
            assert f"{ORDER[f]} is right" in fb.message and "$s$" in fb.message
            assert ex.advice in fb.message                      # how to get it right


def test_coordinates_rounded_to_two_decimals_are_called_close():
    checked = 0
    for name, at in (("CubeMapFace", 1), ("EnvironmentReflection", 0)):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(100)):
            right = solve(ex)[0]
            x = right[at]
            if abs(round(x, 2) - x) <= 0.0025:
                continue
            nearly = list(right)
            nearly[at] = round(x, 2)
            face = 0 if name == "CubeMapFace" else 3
            for answer in (nearly, [ORDER[v] if k == face else v for k, v in enumerate(nearly)]):
                fb = ex.check(answer)
                assert (fb.status, fb.diagnosis) == ("wrong", "rounded"), (ex, answer, fb)
                checked += 1
    assert checked >= 40


def test_boundary_cases_are_a_labelled_tenth_to_a_fifth_of_the_seeds():
    labelled = 0
    for ex in exercises("CubeMapFace"):
        mags = np.abs(ex.direction)
        ties = int(np.sum(mags == mags.max()))
        assert ties == (2 if ex.boundary is not None else 1), ex
        assert ex.boundary in (None, "tie between two axes")
        said = "boundary case" in ex.worked().markdown().lower()
        assert said == (ex.boundary is not None), ex
        told = "leaves the choice" in ex.statement()
        assert told == (ex.boundary is not None), ex
        labelled += ex.boundary is not None
        if ex.boundary is not None:
            # both tied faces show the same point of their shared edge
            f, s, t = cube_face(ex)[0]
            assert 0 in (s, t) or 1 in (s, t)
            other = cube_face(ex)[1]["tie order"]
            assert 0 in other[1:] or 1 in other[1:]
            assert "implementation" in ex.worked().markdown()
    assert 0.10 <= labelled / 300 <= 0.20, labelled


def test_other_variants_have_no_ties_and_no_singular_direction():
    for ex in exercises("EnvironmentReflection"):
        r = np.asarray(environment_reflection(ex)[0][:3])
        mags = np.sort(np.abs(r))
        assert mags[2] - mags[1] > 0.05 and np.sort(r)[2] - np.sort(r)[1] > 0.05
        assert float(np.asarray(ex.N) @ ex.N) >= 2 and float(np.asarray(ex.N) @ ex.I) < 0
    for ex in exercises("SphereMapCoordinates"):
        r = unit(reflection_of(ex))
        assert r[2] > -0.95                                   # far from r = (0, 0, -1)
        s, t = ex.expected
        assert (s - 0.5) ** 2 + (t - 0.5) ** 2 <= 0.25 + 1e-12   # inside the disc
    kinds = {ex.kind for ex in exercises("SphereMapCoordinates")}
    assert kinds == {"reflection", "view"}


def test_the_straight_view_reads_the_normal():
    """Looking straight along -z, the sphere map shows at (s, t) = ((n_x + 1)/2, (n_y + 1)/2)
    the mirror ball's point of normal n: a "view" variant with I = (0, 0, -1) answers so."""
    found = 0
    for ex in exercises("SphereMapCoordinates"):
        if ex.kind == "view" and np.allclose(ex.I, [0, 0, -1]):
            n = np.asarray(ex.N, dtype=float)
            assert gap(ex.expected, [(n[0] + 1) / 2, (n[1] + 1) / 2]) < 1e-12
            found += 1
    assert found >= 1
