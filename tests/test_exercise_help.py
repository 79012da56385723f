"""Every exercise helps on request: at least 3 hints, and a worked solution of the student's own
variant whose final answer the checker accepts (200 seeds each).

The worked solution computes its answer by the arithmetic its steps show, from the question's
numbers; the checker computes its expected answer with course_lib. The two agreeing over 200
seeds is the test (an answer copied from ``self.expected`` is refused: it would test nothing).
"""
import re
import warnings

import numpy as np
import pytest

from course_lib.exercises import mock
from course_lib.exercises.core import DrawnExercise, Guidance, Worked, exercise_key

CLASSES = [cls for classes in mock._numeric_pool().values() for cls in classes]
SEEDS = range(200)
#: Among the first 20 seeds, at least this many worked solutions must read differently: they
#: show each variant's own numbers, not generic prose.
DISTINCT_WORKED = 10


def _ids(cls):
    return exercise_key(cls)                  # ch05.Outcodes: -k ch05 picks a chapter


def _shares_memory(a, b):
    try:
        return np.shares_memory(np.asarray(a), np.asarray(b))
    except (TypeError, ValueError):                 # ragged: nothing shared as one array
        return False


@pytest.mark.parametrize("cls", CLASSES, ids=_ids)
def test_worked_solution_reaches_the_checkers_answer(cls):
    texts = set()
    for seed in SEEDS:
        ex = cls(seed=seed)
        worked = ex.worked()
        assert isinstance(worked, Worked), (cls, seed)
        assert len(worked.steps) >= 2, (cls, seed, "a worked solution has steps")
        expected = getattr(ex, "expected", None)
        if expected is not None and not isinstance(expected, (bool, int, float, str)):
            assert worked.answer is not expected and not _shares_memory(worked.answer, expected),\
                (cls, seed, "the worked answer must be computed by its steps, not copied")
        fb = ex.check(worked.answer)
        assert fb.status == "correct", (cls, seed, worked.answer, fb)
        if seed < 20:
            texts.add("\n".join(worked.steps))
        markdown = worked.markdown()
        assert "**Answer:**" in markdown and not re.search(r"\bnan\b", markdown.lower())
    assert len(texts) >= DISTINCT_WORKED, (cls, len(texts))


@pytest.mark.parametrize("cls", CLASSES, ids=_ids)
def test_at_least_three_hints_from_a_nudge_to_nearly_the_answer(cls):
    for seed in range(20):
        ex = cls(seed=seed)
        hints = list(ex.hints())
        assert len(hints) >= 3, (cls, seed)
        assert all(isinstance(h, str) and len(h.strip()) > 20 for h in hints), (cls, hints)
        assert len(set(hints)) == len(hints), (cls, "hints repeat")
        shown = [ex.hint() for _ in range(len(hints) + 1)]
        assert all(isinstance(g, Guidance) for g in shown)
        for k, (guidance, text) in enumerate(zip(shown, hints), 1):
            assert f"Hint {k} of {len(hints)}" in guidance.markdown and text in guidance.markdown
        assert "No more hints" in shown[-1].markdown
        assert ex.hints_shown == len(hints)


@pytest.mark.parametrize("cls", CLASSES, ids=_ids)
def test_the_solution_is_offered_after_an_attempt(cls):
    ex = cls(seed=7)
    first = ex.solution()
    assert isinstance(first, Guidance) and "Try it first" in first.markdown
    assert isinstance(ex.solution(reveal=True), Worked)
    fb = ex.check(...)
    assert fb.status == "unanswered" and ex.attempts == 0       # no attempt yet
    ex.check("not an answer")
    assert ex.attempts == 1 and isinstance(ex.solution(), Worked)


def test_a_wrong_answer_points_to_the_help():
    from course_lib.exercises import ch03
    ex = ch03.QuaternionFromAxisAngle(seed=1)
    fb = ex.check([9, 9, 9, 9])
    assert fb.status == "wrong"
    assert "hint()" in fb._repr_markdown_() and "solution()" in fb._repr_markdown_()
    assert "hint()" not in fb.message                      # the message itself stays the verdict
    right = ex.check(ex.worked().answer)
    assert right and right.footer is None


class Double(DrawnExercise):
    """A small exercise of this test file (its key: ``test_exercise_help.Double``)."""

    title = "Double a number"
    answer_form = "number"
    what = "the double"

    def draw(self, rng):
        self.x = int(rng.integers(1, 10))
        self.expected = 2.0 * self.x

    def statement(self):
        return f"What is $2 \\times {self.x}$?"

    def hints(self):
        return ["Doubling means adding the number to itself.", f"Add {self.x} and {self.x}.",
                f"It is more than {self.x} and even."]

    def worked(self):
        return Worked([f"Add: ${self.x} + {self.x}$.", "That is the double."], self.x + self.x)


def test_checks_hints_and_solutions_are_recorded_in_a_notebook_but_not_in_an_exam(
        tmp_path, monkeypatch):
    from course_lib import progress
    from course_lib.exercises.mock import ExamQuestion

    file = tmp_path / "progress.json"
    monkeypatch.setenv(progress.ENV_VAR, str(file))
    monkeypatch.setenv(progress.RECORD_VAR, "1")
    ex = Double(seed=4)
    ex.check(...)                                          # not an attempt
    ex.hint()
    ex.check(-1)
    ex.solution()
    ex.check(ex.worked().answer)
    ExamQuestion(5, Double(seed=5)).check("3")             # the exam keeps its own record
    events = progress.read_events(file)
    assert [(e["kind"], e.get("status")) for e in events] == [
        ("hint", None), ("attempt", "wrong"), ("solution", None), ("attempt", "correct")]
    assert all(e["key"] == "test_exercise_help.Double" and e["seed"] == 4 for e in events)
    assert events[1]["hints"] == 1 and events[3]["credit"] == 1.0
    row = progress.topic_strength(events)["test_exercise_help.Double"]
    assert (row["attempts"], row["solved"], row["first_try"], row["hints"]) == (2, 1, 0, 1)
    monkeypatch.setenv(progress.RECORD_VAR, "0")
    ex.check(0)
    assert len(progress.read_events(file)) == 4


def test_recording_never_stops_an_exercise(tmp_path, monkeypatch):
    from course_lib import progress

    (tmp_path / "progress.json").mkdir()                   # a folder where the file should be
    monkeypatch.setenv(progress.ENV_VAR, str(tmp_path / "progress.json"))
    monkeypatch.setenv(progress.RECORD_VAR, "1")
    (tmp_path / "file").write_text("a file where the temporary folder should be")
    monkeypatch.setattr(progress._where, "_temporary_file",
                        lambda: tmp_path / "file" / "graphics-course" / "progress.json")
    ex = Double(seed=4)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert ex.check(-1).status == "wrong" and ex.check(ex.x * 2).status == "correct"
    assert any("could not be saved" in str(w.message) for w in caught)


@pytest.mark.parametrize("cls", CLASSES, ids=_ids)
def test_a_right_answer_rounded_to_two_decimals_is_right_or_close_never_a_mistake(cls):
    """Rounded answers get "close: give more digits" before any diagnosis (they used to get
    "wrong length" or "not normalized"): for every variant whose answer keeps 2 significant
    digits at 2 decimals, the rounded answer is right or "rounded"."""
    for seed in range(60):
        ex = cls(seed=seed)
        answer = ex.worked().answer
        try:
            value = np.asarray(answer, dtype=float)
        except (TypeError, ValueError):
            return                                            # not an answer of numbers
        if value.dtype.kind != "f" or not value.size or np.abs(value).max() < 0.1:
            continue
        rounded = np.round(value, 2)
        if np.array_equal(rounded, value):
            continue
        fb = ex.check(rounded.tolist())
        assert fb.status == "correct" or fb.diagnosis == "rounded", (ex, value, fb)
