"""The exercise machinery every chapter shares: diagnoses that teach, and the builder."""
import math

import nbformat
import numpy as np
import pytest
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

from course_lib.exercises import build
from course_lib.exercises.core import (Exercise, Feedback, Mistake, diagnose_matrix,
                                       diagnose_number, diagnose_vector)

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
    (1.0, {"angle": True}, "value differs"),
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


# --- the builder -----------------------------------------------------------------------------

def test_strip_code_keeps_the_names_the_cell_uses_and_the_indentation():
    src = ("a = 1\n"
           "    ### BEGIN SOLUTION\n"
           "    helper = 2\n"
           "    M, q = helper * a, 3\n"
           "    ### END SOLUTION\n"
           "ex.check(M)")
    assert build.strip_code(src) == "a = 1\n    # YOUR ANSWER HERE\n    M = ...\nex.check(M)"


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
