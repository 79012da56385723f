"""The exercise machinery every chapter shares: diagnoses that teach, and the builder."""
import math

import nbformat
import numpy as np
import pytest
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

from course_lib.exercises import build
from course_lib.exercises.core import (DrawnExercise, Exercise, Feedback, Mistake,
                                       diagnose_matrix, diagnose_number, diagnose_parts,
                                       diagnose_vector, gap, parts_separated, read_floats,
                                       well_separated)

R90 = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])   # 2D rotation by 90°
M = np.array([[2.0, -1.0, 3.0], [1.0, 2.0, -1.0], [0.0, 0.0, 1.0]])


# --- diagnoses -------------------------------------------------------------------------------

@pytest.mark.parametrize("answer, status, diagnosis", [
    (M, "correct", "correct"),
    (M + 1e-4, "correct", "correct"),                       # rounding to 3 decimals passes
    (M.tolist(), "correct", "correct"),                     # nested lists are fine
    (M.T, "wrong", "transposed"),
    (np.linalg.inv(M), "wrong", "inverse"),
    (2 * M, "wrong", "scaled"),
    (-M, "wrong", "opposite sign"),
    (M * [[1, -1, 1], [1, 1, 1], [1, 1, 1]], "wrong", "sign"),
    (M + [[0, 0, 0.5], [0, 0, 0], [0, 0, 0]], "wrong", "entries differ"),
    (M[:2, :2], "invalid", "wrong shape"),
    ("M", "invalid", "not a number"),
    ([[1, 2], [3]], "invalid", "unreadable"),
    ([[np.nan] * 3] * 3, "invalid", "not finite"),
    (..., "unanswered", "unanswered"),
    (None, "unanswered", "unanswered"),
])
def test_diagnose_matrix(answer, status, diagnosis):
    feedback = diagnose_matrix(answer, M)
    assert (feedback.status, feedback.diagnosis) == (status, diagnosis), feedback.message
    assert bool(feedback) == (status == "correct")


def test_anticipated_mistakes_come_before_generic_ones():
    wrong_order = np.array([[0.0, -1.0, -2.0], [1.0, 0.0, 3.0], [0.0, 0.0, 1.0]])
    feedback = diagnose_matrix(wrong_order, M,
                               mistakes=[Mistake(wrong_order, "Wrong order.", "wrong order")])
    assert (feedback.status, feedback.diagnosis, feedback.message) == (
        "wrong", "wrong order", "Wrong order.")


def test_a_mistake_equal_to_the_right_answer_is_not_reported():
    """If a 'mistake' coincides with the answer for this variant, the answer is still right."""
    feedback = diagnose_matrix(M, M, mistakes=[Mistake(M, "Wrong order.", "wrong order")])
    assert feedback.status == "correct"


def test_homogeneous_matrix_asked_but_3x3_given():
    feedback = diagnose_matrix(np.eye(3), np.eye(4))
    assert feedback.diagnosis == "wrong shape" and "homogeneous 4x4" in feedback.message


def test_projective_matrices_accept_any_multiple():
    assert diagnose_matrix(-3 * M, M, homogeneous_scale=True).status == "correct"
    assert diagnose_matrix(-3 * M, M).status == "wrong"


def test_projective_mistakes_are_recognised_in_any_multiple():
    """A projective matrix and its multiples are the same transformation: so are the slips."""
    slip = M.copy()
    slip[2, :2] = [1.0, -2.0]
    mistakes = [Mistake(slip, "The bottom row is off.", "bottom row")]
    for factor in (1.0, -1.0, 2.5, -0.5):
        feedback = diagnose_matrix(np.round(factor * slip, 3), M, mistakes,
                                   homogeneous_scale=True)
        assert (feedback.status, feedback.diagnosis) == ("wrong", "bottom row"), factor
    assert diagnose_matrix(2.5 * slip, M, mistakes).diagnosis != "bottom row"
    assert diagnose_matrix(0 * slip, M, mistakes, homogeneous_scale=True).diagnosis \
        != "bottom row"                                    # zero is no multiple
    same = [Mistake(-2 * M, "A multiple of the answer.", "multiple")]
    assert diagnose_matrix(-2 * M, M, same, homogeneous_scale=True).status == "correct"


@pytest.mark.parametrize("answer, diagnosis, transform_words", [
    (M.T, "transposed", "column vectors"),
    (M * [[1, -1, 1], [1, 1, 1], [1, 1, 1]], "sign", "rotation"),
])
def test_generic_matrix_feedback_for_arrays_that_are_not_transformations(answer, diagnosis,
                                                                         transform_words):
    transformation = diagnose_matrix(answer, M)
    table = diagnose_matrix(answer, M, what="the table", transform=False)
    assert transformation.diagnosis == table.diagnosis == diagnosis
    assert transform_words in transformation.message
    assert transform_words not in table.message and "sin" not in table.message
    assert table.message.startswith({"transposed": "The table is transposed: rows and columns "
                                                   "are swapped.",
                                     "sign": "Right magnitudes but the wrong sign in entries "
                                             "(0, 1) (row, column"}[diagnosis])


def test_arrays_that_are_not_transformations_are_not_called_inverse_or_homogeneous():
    assert diagnose_matrix(np.linalg.inv(M), M).diagnosis == "inverse"
    assert diagnose_matrix(np.linalg.inv(M), M, transform=False).diagnosis == "entries differ"
    assert "homogeneous" in diagnose_matrix(np.eye(3), np.eye(4)).message
    assert "homogeneous" not in diagnose_matrix(np.eye(3), np.eye(4), transform=False).message
    scaled = diagnose_matrix(2 * M, M, what="the table", transform=False)
    assert scaled.diagnosis == "scaled" and scaled.message.startswith("The table is 2 times")


@pytest.mark.parametrize("answer, kwargs, diagnosis", [
    ([0, 0.6, 0.8], {"unit": True}, "correct"),
    ([0, 3, 4], {"unit": True}, "not normalized"),
    ([0, 1.2, 1.6], {}, "wrong length"),
    ([0, -0.6, -0.8], {}, "opposite sign"),
    ([0, -0.6, -0.8], {"sign_free": True}, "correct"),
    ([0.1, 0.6, 0.8], {}, "components differ"),
    ([0.6, 0.8], {}, "wrong shape"),
])
def test_diagnose_vector(answer, kwargs, diagnosis):
    assert diagnose_vector(answer, [0, 0.6, 0.8], **kwargs).diagnosis == diagnosis


@pytest.mark.parametrize("answer, kwargs, diagnosis", [
    (math.pi / 3, {"angle": True}, "correct"),
    (60, {"angle": True}, "degrees"),
    (math.pi / 3 + 2 * math.pi, {"angle": True}, "correct"),
    (-math.pi / 3, {"angle": True}, "opposite sign"),
    (1.3, {"angle": True}, "value differs"),
    ([1, 2], {}, "wrong shape"),
])
def test_diagnose_number(answer, kwargs, diagnosis):
    assert diagnose_number(answer, math.pi / 3, **kwargs).diagnosis == diagnosis


def test_feedback_displays():
    fb = diagnose_matrix(M.T, M)
    assert fb._repr_markdown_().startswith("\u274c **Not yet.**")
    assert str(fb).startswith("Not yet: The matrix is transposed")
    with pytest.raises(ValueError, match="status must be one of"):
        Feedback("maybe", "?")


class Twice(Exercise):
    title = "Twice"

    def setup(self, rng):
        self.x = int(rng.integers(1, 1000))

    def statement(self):
        return f"What is $2 \\times {self.x}$?"

    def check(self, answer):
        return diagnose_number(answer, 2 * self.x)


def test_exercise_seed_chooses_the_variant():
    assert Twice(seed=1).x == Twice(seed=1).x
    assert len({Twice(seed=s).x for s in range(20)}) > 10
    assert "(variant 7)" in Twice(seed=7)._repr_markdown_()
    with pytest.raises(TypeError, match="seed must be an integer"):
        Twice(seed="7")


class Thrice(Twice):
    title = "Thrice"            # the same draw as Twice, under another name


def test_each_exercise_class_draws_from_a_stream_of_its_own():
    """Exercises that share one SEED in a notebook do not share their numbers."""
    assert [Thrice(seed=s).x for s in range(5)] == [Thrice(seed=s).x for s in range(5)]
    assert [Thrice(seed=s).x for s in range(5)] != [Twice(seed=s).x for s in range(5)]


# --- drawn exercises -------------------------------------------------------------------------

class Sum(DrawnExercise):
    """a + b; the slips: a - b, and a * b (which equals a + b for a = b = 2)."""
    title = "A sum"
    answer_form = "number"
    what = "the sum"

    def draw(self, rng):
        self.a, self.b = (int(v) for v in rng.integers(0, 4, size=2))
        self.expected = self.a + self.b

    def mistakes(self):
        return [Mistake(self.a - self.b, "You subtracted.", "subtracted"),
                Mistake(self.a * self.b, "You multiplied.", "multiplied")]

    def statement(self):
        return f"What is ${self.a} + {self.b}$?"


class SumMayCoincide(Sum):
    may_coincide = ("multiplied",)


def test_drawn_exercise_redraws_until_the_mistakes_are_distinct():
    for seed in range(100):
        ex = Sum(seed=seed)
        values = [ex.expected, ex.a - ex.b, ex.a * ex.b]
        assert len(set(values)) == 3, (seed, values)     # b = 0, a = 0 or a = b = 2 never
        assert ex.check(ex.a * ex.b).diagnosis == "multiplied"
        assert ex.check(ex.a - ex.b).diagnosis == "subtracted"
        assert ex.check(ex.expected).status == "correct"


def test_a_mistake_that_may_coincide_is_dropped_where_it_does():
    coinciding = [ex for ex in map(SumMayCoincide, range(300)) if ex.a == ex.b == 2]
    assert coinciding, "no variant with a = b = 2 among 300 seeds"
    for ex in coinciding:
        assert [m.key for m in ex._mistakes] == ["subtracted"]
        assert ex.check(4).status == "correct"


class Impossible(Sum):
    def mistakes(self):
        return [Mistake(self.expected, "Always right.", "always")]


def test_drawn_exercise_gives_up_with_a_clear_error():
    with pytest.raises(RuntimeError, match="Impossible: found no variant"):
        Impossible(seed=0)


class Rotation(DrawnExercise):
    title = "A quaternion"
    answer_form = "quaternion"
    what = "the quaternion"

    def draw(self, rng):
        self.expected = np.array([0.5, 0.5, 0.5, 0.5]) * rng.choice([-1.0, 1.0], size=4)

    def mistakes(self):
        return [Mistake(self.expected * [1, -1, -1, -1], "The conjugate.", "conjugate")]

    def statement(self):
        return "?"


class Projected(DrawnExercise):
    title = "A projected point"
    answer_form = "point"
    projective_point = True
    what = "the point"

    def draw(self, rng):
        self.expected = np.array([1.0, 2.0, 3.0]) + rng.integers(0, 3)

    def statement(self):
        return "?"


class Table(DrawnExercise):
    title = "A table"
    answer_form = "custom"

    def draw(self, rng):
        self.expected = np.arange(4.0) + rng.integers(0, 3)

    def statement(self):
        return "?"


def test_drawn_exercise_checks_by_answer_form():
    q = Rotation(seed=1)
    assert q.check(-q.expected).status == "correct"
    assert q.check(-q.expected * [1, -1, -1, -1]).diagnosis == "conjugate"
    assert q.check(2 * q.expected).diagnosis == "not normalized"
    p = Projected(seed=1)
    assert p.check(np.append(p.expected, 1)).status == "correct"
    assert p.check(np.append(2 * p.expected, 2)).diagnosis == "no divide"
    assert p.check(p.expected + 1).status == "wrong"
    # a form of its own without a _check: reported, never raised
    assert Table(seed=1).check([0, 1, 2, 3]).status == "invalid"


def test_drawn_exercise_check_never_raises():
    for answer in (object(), {1, 2}, b"x", 1j, [[[]]], [None] * 3, [1, "a"]):
        for ex in (Sum(seed=2), Rotation(seed=2), Projected(seed=2)):
            assert ex.check(answer).status in ("invalid", "wrong", "unanswered"), (ex, answer)


def test_separation_helpers():
    assert gap([1, 2], [1, 2.5]) == 0.5 and gap([1], [1, 2]) == math.inf
    assert gap([1, 0], [-1, 0], sign_free=True) == 0.0
    assert gap([3, 6], [1, 2], projective=True) == 0.0 and gap([3, 6], [1, 2]) == 4.0
    right = np.array([1.0, 2.0])
    assert well_separated(right, [Mistake([2, 1], "", "a"), Mistake([3, 3], "", "b")])
    assert not well_separated(right, [Mistake([2, 1], "", "a"), Mistake([2, 1.01], "", "b")])
    # the same slip may be listed twice (e.g. two ways to reach it)
    assert well_separated(right, [Mistake([2, 1], "", "a"), Mistake([2, 1], "", "a")])
    assert not well_separated(right, [Mistake(-right, "", "a")], sign_free=True)
    assert not well_separated(right, [Mistake([2, 1], "", "a"), Mistake([4, 2], "", "b")],
                              projective=True)
    assert read_floats([[1, 2], [3]]) is None and read_floats({1.0}) is None
    assert read_floats((1, 2)).tolist() == [1.0, 2.0]


@pytest.mark.parametrize("ulps", [-2, -1, 0, 1, 2])
def test_a_distance_of_exactly_apart_is_apart_whatever_its_last_bit(ulps):
    # 0.375 and 0.425 are 0.05 apart; which side of 0.05 the computed difference falls on
    # depends on the last bit of the slip's value (the CPU's BLAS kernel, say): the variant a
    # seed gives must not
    slip = 0.425
    for _ in range(abs(ulps)):
        slip = math.nextafter(slip, math.copysign(math.inf, ulps))
    assert well_separated(0.375, [Mistake(slip, "", "a")])
    assert well_separated(0.0, [Mistake(1.0, "", "a"), Mistake(1.0 - (slip - 0.375), "", "b")])
    assert parts_separated([("x", 0.375, [Mistake(slip, "", "a")])])
    # clearly closer than 0.05 still is not
    assert not well_separated(0.375, [Mistake(0.4249, "", "a")])
    assert not parts_separated([("x", 0.375, [Mistake(0.4249, "", "a")])])


def test_diagnose_parts_names_the_slip_and_the_numbers():
    parts = [("the first", 1.0, [Mistake(-1.0, "Sign slip in the first number.", "sign")]),
             ("the second", 2.0, [])]
    feedback = diagnose_parts([-1, 2], parts, "your answer", "`[a, b]`")
    assert (feedback.status, feedback.diagnosis) == ("wrong", "sign")
    assert "Right: the second." in feedback.message
    assert diagnose_parts([1, 3], parts, "your answer", "`[a, b]`").diagnosis == "value differs"
    assert diagnose_parts([1], parts, "your answer", "`[a, b]`").status == "invalid"


# --- the builder -----------------------------------------------------------------------------

def test_strip_code_keeps_the_names_the_cell_uses_and_the_indentation():
    src = ("a = 1\n"
           "    ### BEGIN SOLUTION\n"
           "    helper = 2\n"
           "    M, q = helper * a, 3\n"
           "    ### END SOLUTION\n"
           "ex.check(M)")
    assert build.strip_code(src) == "a = 1\n    # YOUR ANSWER HERE\n    M = ...\nex.check(M)"


@pytest.mark.parametrize("body, name", [
    ("if a > 0:\n    M = a\nelse:\n    M = -a", "M"),
    ("for M in range(3):\n    pass", "M"),
    ("for i, (M, k) in enumerate([(1, 2)]):\n    pass", "M"),
    ("while True:\n    M = 1\n    break", "M"),
    ("with open(__file__) as M:\n    pass", "M"),
    ("with open(__file__) as f:\n    M = f.read()", "M"),
    ("try:\n    M = 1 / a\nexcept ZeroDivisionError:\n    M = 0", "M"),
    ("try:\n    pass\nfinally:\n    M = 1", "M"),
    ("if a:\n    for k in range(2):\n        if k:\n            M = k", "M"),
    ("if (M := a + 1) > 0:\n    pass", "M"),
])
def test_strip_code_finds_assignments_inside_compound_statements(body, name):
    """A name assigned inside an if/for/with/try still gets its `name = ...` placeholder."""
    src = "### BEGIN SOLUTION\n" + body + "\n### END SOLUTION\nex.check(M)"
    assert build.strip_code(src) == f"# YOUR ANSWER HERE\n{name} = ...\nex.check(M)"


def test_placeholders_follow_the_order_of_first_assignment():
    src = ("### BEGIN SOLUTION\nif a:\n    B = 1\nelse:\n    A = 2\nfor C in []:\n    pass\n"
           "### END SOLUTION\nex.check(C, A, B)")
    assert build.strip_code(src) == ("# YOUR ANSWER HERE\nB = ...\nA = ...\nC = ...\n"
                                     "ex.check(C, A, B)")


@pytest.mark.parametrize("body", [
    "def f():\n    M = 1\n    return M",
    "class K:\n    M = 1",
    "values = [M for M in range(3)]",
    "values = {M: 1 for M in range(3)}",
    "values = list(M for M in range(3))",
    "values = [(M := k) for k in range(3)]",
    "f = lambda M=1: M",
])
def test_strip_code_ignores_names_local_to_functions_classes_and_comprehensions(body):
    src = "### BEGIN SOLUTION\n" + body + "\n### END SOLUTION\nex.check(M)"
    assert build.strip_code(src) == "# YOUR ANSWER HERE\nex.check(M)"


def test_a_stripped_region_with_compound_statements_runs():
    src = ("a = 3\n### BEGIN SOLUTION\nif a > 0:\n    M = a\nelse:\n    M = -a\n"
           "for k in range(2):\n    total = k\n### END SOLUTION\nresult = (M, total)")
    namespace = {}
    exec(build.strip_code(src), namespace)
    assert namespace["result"] == (..., ...)


def test_strip_code_without_later_use_leaves_a_comment_only():
    assert build.strip_code("### BEGIN SOLUTION\nprint(1)\n### END SOLUTION") == \
        "# YOUR ANSWER HERE"


@pytest.mark.parametrize("src, message", [
    ("### BEGIN SOLUTION\nx = 1", "never closed"),
    ("x = 1\n### END SOLUTION", "never opened"),
    ("### BEGIN SOLUTION\n### BEGIN SOLUTION\n### END SOLUTION", "inside another"),
])
def test_unbalanced_markers_are_reported_with_their_place(src, message):
    with pytest.raises(build.SolutionMarkerError, match=message):
        build.strip_code(src, where="solutions/x.ipynb, cell 3")


def test_build_drops_solution_cells_and_outputs_and_strips_markdown():
    nb = new_notebook(cells=[
        new_markdown_cell("Why?\n<!-- BEGIN SOLUTION -->\nBecause.\n<!-- END SOLUTION -->"),
        new_code_cell("### BEGIN SOLUTION\nx = 1\n### END SOLUTION\nex.check(x)",
                      execution_count=4, outputs=[nbformat.v4.new_output("stream", text="ok")]),
        new_code_cell("print('only in the solutions')", metadata={"tags": ["solution"]}),
    ])
    nb.metadata["widgets"] = {"application/vnd.jupyter.widget-state+json": {}}
    ex = build.build_exercise_notebook(nb, "solutions/x.ipynb")
    assert [c.cell_type for c in ex.cells] == ["markdown", "code"]
    assert ex.cells[0].source == "Why?\n*Your answer here.*"
    assert ex.cells[1].outputs == [] and ex.cells[1].execution_count is None
    assert "widgets" not in ex.metadata
    assert "Because" not in nbformat.writes(ex)


def test_stale_exercises_notices_edits(tmp_path):
    (tmp_path / "solutions").mkdir()
    (tmp_path / "exercises").mkdir()
    sol = new_notebook(cells=[new_code_cell("### BEGIN SOLUTION\nx = 1\n### END SOLUTION\nx")])
    nbformat.write(sol, tmp_path / "solutions" / "ch01.ipynb")
    built = build.build_exercise_notebook(sol, "solutions/ch01.ipynb")
    nbformat.write(built, tmp_path / "exercises" / "ch01.ipynb")
    assert build.stale_exercises(tmp_path) == []
    sol.cells[0].source = sol.cells[0].source.replace("x = 1", "x = 2\ny = 3")
    nbformat.write(sol, tmp_path / "solutions" / "ch01.ipynb")
    assert build.stale_exercises(tmp_path) == []      # the solution changed, not the exercise
    sol.cells.append(new_code_cell("print('new exercise')"))
    nbformat.write(sol, tmp_path / "solutions" / "ch01.ipynb")
    assert build.stale_exercises(tmp_path) == [
        "exercises/ch01.ipynb differs from a build of solutions/ch01.ipynb"]
    nbformat.write(new_notebook(), tmp_path / "exercises" / "orphan.ipynb")
    assert "exercises/orphan.ipynb has no solution notebook" in build.stale_exercises(tmp_path)


def test_sign_free_answers_recognise_negated_mistakes():
    """-q is the same rotation as q, so a mistake's negative is the same mistake."""
    expected = np.array([0.5, 0.5, 0.5, 0.5])
    conjugate = expected * [1, -1, -1, -1]
    mistake = Mistake(conjugate, "That is the conjugate.", "conjugate")
    for answer in (conjugate, -conjugate):
        feedback = diagnose_vector(answer, expected, mistakes=[mistake], sign_free=True)
        assert (feedback.status, feedback.diagnosis) == ("wrong", "conjugate")
    assert diagnose_vector(-expected, expected, mistakes=[mistake], sign_free=True).status == \
        "correct"


def test_feedback_keeps_the_case_of_the_answer_name():
    assert diagnose_matrix(M, M, what="the matrix M").message == "The matrix M is right."


def test_numbers_no_slip_explains_get_the_hint_once():
    # diagnose_parts ends its "some of your numbers are off" with the hint, and DrawnExercise.check
    # adds the hint to an unexplained verdict: a student was told the same thing twice
    import importlib

    checked = 0
    for chapter in ("ch04", "ch05", "ch06", "ch07", "ch12", "ch14", "ch15", "ch18"):
        module = importlib.import_module(f"course_lib.exercises.{chapter}")
        for name in module.__all__:
            cls = getattr(module, name)
            if not (isinstance(cls, type) and issubclass(cls, DrawnExercise)):
                continue
            ex = cls(seed=0)
            parts = getattr(ex, "_parts", None)
            parts = parts() if callable(parts) else parts
            if not ex.advice or not isinstance(parts, list) \
                    or not all(np.ndim(expected) == 0 for _, expected, _ in parts):
                continue
            feedback = ex.check([float(expected) + 1000.5 for _, expected, _ in parts])
            assert feedback.status == "wrong", (name, feedback)
            assert feedback.message.count(ex.advice) <= 1, (name, feedback.message)
            checked += 1
    assert checked >= 10, f"only {checked} exercises answer in several numbers"
