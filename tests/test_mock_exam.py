"""Tests of the mock exam (course_lib.exercises.mock) and its widget (widgets.mock_exam).

Every exercise class of every chapter (found on disk, not listed) and every concept question
must give a valid exam question for 200 seeds, and its checker must work through the exam's
text field: the right answer typed in several equivalent forms is accepted, and each
anticipated mistake typed in is named by its own diagnosis. The right answers come from the
exercise's expected value (the chapters' own tests check those against independent
libraries); what is under test here is the text reading and the wrapping, so where an
exercise's answer has another form than its expected value, the answer is built here from the
statement's data. Exams: deterministic, balanced over chapters and kinds, validated arguments.
The widget is driven headless through a whole exam, and its score checked against a count
made here.
"""
import collections
import functools
import importlib
import json
import math
import re
import time
from pathlib import Path

import numpy as np
import pytest

from course_lib import progress
from course_lib.exercises import concepts, mock, mock_exam
from course_lib.exercises.core import Mistake
from course_lib.exercises.mock import ExamQuestion, read_answer
from course_lib.widgets.mock_exam import MockExamWidget, State, scene

ROOT = Path(__file__).resolve().parents[1]
SEEDS = range(200)
CHAPTER_FILES = sorted(int(m.group(1)) for p in (ROOT / "course_lib" / "exercises").glob("ch*.py")
                       if (m := re.fullmatch(r"ch(\d\d)\.py", p.name)))


@pytest.fixture(autouse=True)
def _private_progress(tmp_path, monkeypatch):
    """Nothing here may touch the real home: the progress file and the data folder are tmp."""
    monkeypatch.setenv(progress.ENV_VAR, str(tmp_path / "progress.json"))
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))


def _module(chapter):
    return importlib.import_module(f"course_lib.exercises.ch{chapter:02d}")


ALL_CLASSES = [(ch, cls) for ch in CHAPTER_FILES for cls in _module(ch).EXERCISES]
ALL_CONCEPTS = concepts.questions()


@functools.lru_cache(maxsize=None)
def variants(chapter, name):
    cls = getattr(_module(chapter), name)
    return [ExamQuestion(chapter, cls(seed=s)) for s in SEEDS]


# ---------------------------------------------------------------------------------------------
# Answers typed as text
# ---------------------------------------------------------------------------------------------

def plain(value):
    """`value` with numpy arrays and scalars made plain Python (what a student types)."""
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, (list, tuple)):
        return type(value)(plain(v) for v in value)
    if isinstance(value, (set, frozenset)):
        return {plain(v) for v in value}
    return value


def right_answer(ex):
    """The answer in the form the statement asks for."""
    name = type(ex).__name__
    if name == "LiangBarskyClip3D" and ex.expected is None:
        return "rejected"
    if name == "DesignOpacity":      # the statement asks for control points, not the samples
        return [(ex.low - ex.width, 0.0), (ex.low, ex.alpha), (ex.high, ex.alpha),
                (ex.high + ex.width, 0.0)]
    if name == "SaddleResolution":   # "a list of two pairs of edge numbers"
        return sorted(tuple(sorted(pair)) for pair in ex.expected)
    return ex.expected


#: Exercises whose `expected` (and anticipated mistakes) are samples, not answers.
NOT_ANSWER_FORM = {"DesignOpacity"}


def num(x):
    """A number as a student types it: whole numbers without a decimal point."""
    x = float(x)
    return str(int(x)) if x.is_integer() else repr(x)


def typed_forms(value):
    """Several ways to type `value` into the answer field."""
    value = plain(value)
    forms = [repr(value)]
    array = None
    if not isinstance(value, (str, set, dict)):
        try:
            array = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            array = None
    if array is not None and array.ndim == 1 and array.size > 1:
        forms.append(", ".join(num(x) for x in array))                          # 1, 2, 3
        forms.append(" ".join(num(x) for x in array))                           # 1 2 3
        forms.append(f"np.array({value!r})")                                    # pasted numpy
    if array is not None and array.ndim == 2 and array.size > 1:
        forms.append("; ".join(" ".join(num(x) for x in row) for row in array))
        forms.append("\n".join(", ".join(num(x) for x in row) for row in array))
    if array is not None and array.ndim == 0:
        forms.append(f"  {num(array)}  ")
    if isinstance(value, str):
        forms.append(value)                                                     # no quotes
    return forms


@pytest.mark.parametrize("text, value", [
    ("[[1,0],[0,1]]", [[1, 0], [0, 1]]),
    ("1, 2, 3", (1, 2, 3)),
    ("1 2.5 3", [1.0, 2.5, 3.0]),
    ("1 0; 0 1", [[1.0, 0.0], [0.0, 1.0]]),
    ("1 0\n0 1", [[1.0, 0.0], [0.0, 1.0]]),
    ("-2.5", -2.5),
    ("sqrt(2)/2", math.sqrt(2) / 2),
    ("[cos(pi/3), -sin(pi/3)]", [0.5, -math.sqrt(3) / 2]),
    ("np.array([1., 2.])", [1.0, 2.0]),
    ("2**-1", 0.5),
    ("1 -2", [1.0, -2.0]),
    ("2 - 1", 1.0),
    ("'rejected'", "rejected"),
    ("rejected", "rejected"),
    ("closed manifold", "closed manifold"),
    ("ellipse, hyperbola", ["ellipse", "hyperbola"]),
    ("{1, 2}", {1, 2}),
    ("   ", None),
])
def test_read_answer_forms(text, value):
    got = read_answer(text)
    if isinstance(value, float) or (isinstance(value, list)
                                    and not any(isinstance(v, str) for v in value)):
        assert np.allclose(np.asarray(got, dtype=float), value, atol=1e-12)
        assert type(got) is type(value)
    else:
        assert got == value


def test_read_answer_never_runs_code(tmp_path):
    target = tmp_path / "pwned"
    for text in [f"open({str(target)!r}, 'w').write('x')",
                 f"__import__('pathlib').Path({str(target)!r}).touch()",
                 "[x for x in ().__class__.__base__.__subclasses__()]",
                 "sqrt.__globals__", "(lambda: 1)()"]:
        assert read_answer(text) == text                 # kept as text, nothing executed
    assert not target.exists()
    assert read_answer("9**9**9") == "9**9**9"           # no endless power computation
    assert read_answer("[" * 5000 + "]" * 5000) is not None     # deep nesting does not crash
    with pytest.raises(TypeError, match="text must be a string"):
        read_answer(3)


# ---------------------------------------------------------------------------------------------
# Every generator, 200 seeds, through the exam's text field
# ---------------------------------------------------------------------------------------------

def test_chapters_are_discovered_from_the_files():
    assert CHAPTER_FILES, "no chapter exercise modules found"
    assert set(mock.available_chapters()) == set(CHAPTER_FILES) | set(concepts.QUESTIONS)
    assert {ch for ch, n in mock.available_chapters().items() if n["numeric"]} \
        == set(CHAPTER_FILES)


@pytest.mark.parametrize("chapter, cls", ALL_CLASSES,
                         ids=[f"ch{ch:02d}-{cls.__name__}" for ch, cls in ALL_CLASSES])
def test_every_exercise_gives_a_valid_question_and_is_checked_from_text(chapter, cls):
    diagnosed = collections.Counter()
    for seed, question in zip(SEEDS, variants(chapter, cls.__name__)):
        ex = question.source
        assert (question.chapter, question.kind, question.seed) == (chapter, "numeric", seed)
        assert question.key == f"ch{chapter:02d}.{cls.__name__}"
        text = question.markdown()
        assert text.startswith(f"**Chapter {chapter} · ") and len(text) > 60
        assert "attributes" not in text.splitlines()[-1]      # the data note is dropped
        assert question.check("").status == "unanswered"
        assert question.check(None).status == "unanswered"
        answer = right_answer(ex)
        for typed in typed_forms(answer):
            feedback = question.check(typed)
            assert feedback.status == "correct", (seed, typed, str(feedback))
        assert question.check(plain(answer)).status == "correct"   # lists instead of arrays
        form = getattr(ex, "answer_form", None)
        if form == "matrix" and getattr(ex, "homogeneous_scale", False):
            scaled = repr((-2.5 * np.asarray(answer, dtype=float)).tolist())
            assert question.check(scaled).status == "correct", seed
        if form == "quaternion":
            assert question.check(repr((-np.asarray(answer)).tolist())).status == "correct"
        if form == "point":
            homogeneous = repr([*np.asarray(answer, dtype=float).tolist(), 1.0])
            assert question.check(homogeneous).status == "correct", seed
        if cls.__name__ in NOT_ANSWER_FORM:
            continue
        for mistake in getattr(ex, "_mistakes", ()):
            if not isinstance(mistake, Mistake):
                continue
            feedback = question.check(repr(plain(mistake.value)))
            assert (feedback.status, feedback.diagnosis) == ("wrong", mistake.key), \
                (seed, mistake.key, str(feedback))
            assert feedback.message == mistake.explanation or \
                mistake.explanation in feedback.message
            diagnosed[mistake.key] += 1
    assert question.check("certainly not an answer ][").status in ("invalid", "wrong")


@pytest.mark.parametrize("question", ALL_CONCEPTS, ids=[q.key for q in ALL_CONCEPTS])
def test_every_concept_question_through_the_exam(question):
    q = ExamQuestion(question.chapter, question)
    assert (q.kind, q.key, q.seed, q.options) == ("concept", question.key, None,
                                                   question.options)
    text = q.markdown()
    assert question.prompt in text
    for letter, option in zip(question.letters, question.options):
        assert f"**({letter})** {option}" in text
    right = question.correct
    for typed in (question.letters[right], question.letters[right].upper(),
                  f" {question.options[right]} ", str(right)):
        assert q.check(typed).status == "correct", typed
    if question.kind == "true/false":
        assert q.check("True" if right == 0 else "False").status == "correct"
    for i, letter in enumerate(question.letters):
        if i == right:
            continue
        feedback = q.check(letter)
        assert (feedback.status, feedback.diagnosis) == ("wrong", f"option {letter}")
        assert question.explanations[i] in feedback.message          # why this one is wrong
        assert question.explanations[right] in feedback.message      # and what is right
    assert q.check("").status == "unanswered"
    assert q.check("zz").status == "invalid"


def test_every_chapter_has_concept_questions_of_both_kinds():
    assert set(concepts.QUESTIONS) >= set(CHAPTER_FILES)
    kinds = {q.kind for q in ALL_CONCEPTS}
    assert kinds == set(concepts.KINDS)


# ---------------------------------------------------------------------------------------------
# Exams
# ---------------------------------------------------------------------------------------------

def fingerprint(exam):
    return [(q.chapter, q.kind, q.key, q.seed, q.markdown()) for q in exam]


def test_same_seed_same_exam_and_seeds_differ():
    assert fingerprint(mock_exam(11)) == fingerprint(mock_exam(11))
    assert fingerprint(mock_exam(11, [3, 7], 5)) == fingerprint(mock_exam(11, (7, 3), 5))
    exams = {tuple((q.key, q.seed) for q in mock_exam(s)) for s in range(10)}
    assert len(exams) == 10


@pytest.mark.parametrize("chapters, n", [(None, 12), (None, 4), (None, 30), ([3], 5),
                                         ([5, 7, 18], 7), ([4, 6, 10, 12, 14, 15], 6)])
@pytest.mark.parametrize("seed", range(12))
def test_exams_are_balanced(chapters, n, seed):
    exam = mock_exam(seed, chapters=chapters, n_questions=n)
    chosen = sorted(chapters) if chapters else sorted(mock.available_chapters())
    assert len(exam) == n and list(exam.chapters) == chosen
    counts = collections.Counter(q.chapter for q in exam)
    assert set(counts) <= set(chosen)
    if n >= len(chosen):
        assert set(counts) == set(chosen)
    full = [counts.get(ch, 0) for ch in chosen]
    assert max(full) - min(full) <= 1                         # spread evenly
    assert [q.chapter for q in exam] == sorted(q.chapter for q in exam)
    kinds = collections.Counter(q.kind for q in exam)
    assert abs(kinds["numeric"] - kinds["concept"]) <= 1      # every chapter has both kinds
    for ch in chosen:                                         # no repeats while unused remain
        keys = [q.key for q in exam if q.chapter == ch]
        assert len(keys) == len(set(keys))


def test_chapter_shares_over_many_seeds_are_fair():
    """With fewer questions than chapters, each chapter is chosen about equally often."""
    counts = collections.Counter(q.chapter for s in range(150) for q in mock_exam(s, None, 5))
    n_chapters = len(mock.available_chapters())
    expected = 150 * 5 / n_chapters
    assert all(abs(c - expected) < 0.35 * expected for c in counts.values()), counts


@pytest.mark.parametrize("kwargs, error, match", [
    (dict(seed="1"), TypeError, "seed"),
    (dict(seed=1.5), TypeError, "seed"),
    (dict(seed=1, n_questions=0), ValueError, "n_questions"),
    (dict(seed=1, n_questions=2.0), ValueError, "n_questions"),
    (dict(seed=1, chapters=[99]), ValueError, "chapters"),
    (dict(seed=1, chapters=[]), ValueError, "chapters"),
    (dict(seed=1, chapters="37"), ValueError, "chapters"),
    (dict(seed=1, chapters=3.0), TypeError, "chapters"),
])
def test_bad_arguments(kwargs, error, match):
    with pytest.raises(error, match=match):
        mock_exam(**kwargs)


def answer_right(question):
    if question.kind == "concept":
        return question.source.letters[question.source.correct]
    return repr(plain(right_answer(question.source)))


def answer_wrong(question):
    """An anticipated mistake where there is one (graded wrong), else unreadable text."""
    if question.kind == "concept":
        return question.source.letters[(question.source.correct + 1) % len(question.options)]
    if type(question.source).__name__ not in NOT_ANSWER_FORM:
        for mistake in getattr(question.source, "_mistakes", ()):
            if isinstance(mistake, Mistake):
                return repr(plain(mistake.value))
    return "'certainly wrong'"


def test_scores_and_questions_to_revisit():
    exam = mock_exam(5, n_questions=10)
    expected = collections.defaultdict(lambda: [0, 0])
    for i, q in enumerate(exam):
        right = i % 3 != 0
        feedback = exam.submit(i, answer_right(q) if right else answer_wrong(q))
        assert bool(feedback) == right, str(feedback)
        expected[q.chapter][0] += right
        expected[q.chapter][1] += 1
    assert exam.finished
    assert exam.score() == {ch: tuple(v) for ch, v in sorted(expected.items())}
    assert exam.total() == (sum(i % 3 != 0 for i in range(10)), 10)
    assert exam.to_revisit() == [q for i, q in enumerate(exam) if i % 3 == 0]
    record = exam.record()
    assert json.loads(json.dumps(record)) == record
    assert record["score"] == {str(ch): list(v) for ch, v in sorted(expected.items())}
    assert [r["key"] for r in record["revisit"]] == [q.key for q in exam.to_revisit()]
    with pytest.raises(IndexError, match="index"):
        exam.submit(10, "1")


def test_a_revisited_question_can_be_rebuilt_from_its_key_and_seed():
    exam = mock_exam(8, n_questions=10)
    for q in exam:
        if q.kind == "numeric":
            module, name = q.key.split(".")
            again = getattr(importlib.import_module(f"course_lib.exercises.{module}"), name)
            assert again(seed=q.seed).statement() == q.source.statement()


# ---------------------------------------------------------------------------------------------
# The widget, headless
# ---------------------------------------------------------------------------------------------

def bar_heights(widget):
    return ([b.get_height() for b in widget.right_bars],
            [b.get_height() for b in widget.wrong_bars])


def test_widget_drives_a_full_exam(tmp_path):
    file = tmp_path / "exam-progress.json"
    widget = MockExamWidget(seed=3, n_questions=8, progress_file=file)
    exam = widget.exam
    assert widget.png()[:4] == b"\x89PNG"
    bundle = widget._repr_mimebundle_()
    assert "image/png" in bundle and bundle["text/plain"] == widget.summary
    right_per_chapter, wrong_per_chapter = collections.Counter(), collections.Counter()
    for i, q in enumerate(exam):
        assert widget.state.index == i
        assert widget.shown["question"] == q.markdown()
        assert widget.question_out.outputs[0]["data"]["text/markdown"] == q.markdown()
        numeric = q.kind == "numeric"
        assert (widget.text.layout.display != "none") == numeric
        assert (widget.choice.layout.display != "none") == (not numeric)
        # an empty submission: "not answered yet", the question stays open
        widget.submit_answer()
        assert exam.feedback[i].status == "unanswered" and not widget.submit_button.disabled
        if numeric:                        # unreadable: reported, and may be corrected
            widget.text.value = "[[["
            widget.submit_button.click()
            if exam.feedback[i].status == "invalid":
                assert not widget.submit_button.disabled and not widget.text.disabled
        right = i % 2 == 0
        given = answer_right(q) if right else answer_wrong(q)
        if numeric:
            widget.text.value = given
        else:
            assert list(widget.choice.options) == (
                list(q.options) if q.source.kind == "true/false" else list(q.source.letters))
            widget.choice.value = (q.options[q.source.read(given)]
                                   if q.source.kind == "true/false" else given)
        widget.submit_button.click()
        feedback = exam.feedback[i]
        assert bool(feedback) == right
        graded = feedback.status in ("correct", "wrong")
        assert widget.submit_button.disabled == graded == widget.text.disabled
        assert widget.shown["feedback"] == feedback._repr_markdown_()
        assert widget.feedback_out.outputs[0]["data"]["text/markdown"].startswith(
            "\u2705" if right else ("\u274c", "\u26a0"))
        if graded:
            widget.submit_answer("another try")       # graded once: ignored
            assert exam.feedback[i] is feedback
        right_per_chapter[q.chapter] += right
        wrong_per_chapter[q.chapter] += feedback.status == "wrong"
        if i < len(exam) - 1:
            assert widget.next_button.description == "Next question"
        widget.next_button.click()
    assert widget.state.done and widget.next_button.disabled
    assert widget.submit_button.layout.display == "none"
    chapters = sorted({q.chapter for q in exam})
    asked = collections.Counter(q.chapter for q in exam)
    assert sum(wrong_per_chapter.values()) >= 2          # the test saw graded wrong answers
    assert exam.score() == {ch: (right_per_chapter[ch], asked[ch]) for ch in chapters}
    rights, wrongs = bar_heights(widget)
    assert rights == [right_per_chapter[ch] for ch in chapters]
    assert wrongs == [wrong_per_chapter[ch] for ch in chapters]
    results = widget.shown["results"]
    assert f"{sum(right_per_chapter.values())} of {len(exam)} right" in results
    for i, q in enumerate(exam):
        assert (q.label in results) == (i % 2 == 1)
    history = progress.read_history(file)
    assert len(history) == 1
    assert history[0]["score"] == {str(ch): [right_per_chapter[ch], asked[ch]]
                                   for ch in chapters}
    assert str(file) in widget.status.value


def test_widget_skipping_and_new_exam(tmp_path):
    widget = MockExamWidget(seed=4, chapters=[7, 12], n_questions=3, save=False)
    for _ in range(3):
        widget.next()                                   # nothing answered
    assert widget.state.done and widget.exam.total() == (0, 3)
    assert bar_heights(widget) == ([0, 0], [0, 0])      # skipped: neither right nor wrong
    assert not Path(progress.progress_path()).exists()  # save=False wrote nothing
    widget.seed_box.value = 9
    widget.new_button.click()
    assert widget.exam.seed == 9 and widget.state == State()
    assert fingerprint(widget.exam) == fingerprint(mock_exam(9, [7, 12], 3))
    s = scene(widget.exam, widget.state)
    assert s["header"].startswith("Question 1 of 3") and s["feedback"] == ""


def test_widget_reports_a_corrupt_progress_file(tmp_path):
    file = tmp_path / "progress.json"
    file.write_text("{ not json")
    widget = MockExamWidget(seed=2, chapters=[3], n_questions=1, progress_file=file)
    widget.next()
    assert "could not be read" in widget.status.value and ".corrupt-" in widget.status.value
    assert len(progress.read_history(file)) == 1
    assert [p.read_text() for p in tmp_path.glob("progress.json.corrupt-*")] == ["{ not json"]


# --- adaptive exams: weak chapters weigh more, what was wrong comes back --------------------

def attempt(key, seed, right):
    return {"kind": "attempt", "key": key, "seed": seed, "status": "correct" if right else
            "wrong", "hints": 0, "date": "2026-01-01T00:00:00+00:00"}


def exam_record(questions):
    """An exam record made of (key, seed, credit) triples."""
    return {"kind": "exam", "date": "2026-01-02T00:00:00+00:00",
            "questions": [{"chapter": int(k[2:4]), "key": k, "seed": s, "credit": c}
                          for k, s, c in questions]}


def test_without_a_history_the_exam_is_the_balanced_one():
    for seed in range(5):
        plain = mock_exam(seed, chapters=[3, 5, 7], n_questions=9)
        for history in (None, []):
            same = mock_exam(seed, chapters=[3, 5, 7], n_questions=9, history=history)
            assert [(q.key, q.seed) for q in same] == [(q.key, q.seed) for q in plain]
            assert same.plan is None


def test_an_adaptive_exam_is_deterministic_per_seed_and_history():
    history = [attempt("ch05.Outcodes", 1, False), attempt("ch03.ShearImage", 2, True)]
    draws = [[(q.key, q.seed) for q in mock_exam(s, [3, 5, 7], 9, history=list(history))]
             for s in (4, 4, 5)]
    assert draws[0] == draws[1] and draws[0] != draws[2]
    other = [attempt("ch07.BSplinePoint", 1, False)]
    assert [(q.key, q.seed) for q in mock_exam(4, [3, 5, 7], 9, history=other)] != draws[0]


def test_weak_chapters_get_more_questions_and_every_chapter_keeps_one():
    # chapter 5 all wrong (weight 3), chapter 3 all right (weight 1), chapter 7 unknown (1.5)
    history = [attempt("ch05.Outcodes", k, False) for k in range(4)] + \
              [attempt("ch03.ShearImage", k, True) for k in range(4)]
    for seed in range(20):
        counts = collections.Counter(q.chapter for q in mock_exam(seed, [3, 5, 7], 11,
                                                                  history=history))
        # by hand: one each, then 8 shared 3 : 1 : 1.5 -> 4.36, 1.45, 2.18, floored 4, 1, 2;
        # the one left goes to the largest remainder, chapter 3's 0.45
        assert counts == {5: 1 + 4, 3: 1 + 1 + 1, 7: 1 + 2}
    few = [collections.Counter(q.chapter for q in mock_exam(s, [3, 5, 7], 2, history=history))
           for s in range(10)]
    assert all(c == {5: 1, 7: 1} for c in few)       # fewer questions than chapters: heaviest


def test_a_wrong_answer_comes_back_in_a_new_variant_then_spaced_out():
    key = "ch07.BSplinePoint"

    def due(history):
        return [d["key"] for d in mock.study_plan(history)["due"]]

    history = [attempt(key, 3, False)]
    assert due(history) == [key]                               # due in the next exam
    for seed in range(10):
        exam = mock_exam(seed, chapters=[7], n_questions=4, history=history)
        asked = [q for q in exam if q.key == key]
        assert len(asked) == 1 and asked[0].seed != 3          # a variant not seen
        assert exam.questions.index(asked[0]) == 0             # reviews come first
    history.append(exam_record([(key, 11, 1.0)]))               # right in exam 1: box 1
    assert due(history) == []                                   # not in exam 2 ...
    history.append(exam_record([("ch07.BernsteinValues", 5, 1.0)]))
    assert due(history) == [key]                                # ... but in exam 3 (2 later)
    history.append(exam_record([(key, 12, 1.0)]))               # right again in exam 3: box 2
    for _ in range(3):
        assert due(history) == []                               # exams 4, 5, 6
        history.append(exam_record([("ch07.BernsteinValues", 5, 1.0)]))
    assert due(history) == [key]                                # exam 7 (4 later)
    history.append(exam_record([(key, 13, 1.0)]))               # third right: out
    assert all(due(history + [exam_record([])] * k) == [] for k in range(12))
    history.append(exam_record([(key, 14, 0.5)]))               # partly wrong: back at once
    assert due(history) == [key]


def test_old_exam_records_without_their_questions_still_count():
    old = {"kind": "exam", "seed": 1, "chapters": [5], "n_questions": 2,
           "score": {"5": [1, 2]}, "revisit": [{"chapter": 5, "key": "ch05.Outcodes",
                                                "seed": 9, "label": "x"}]}
    plan = mock.study_plan([old])
    assert [d["key"] for d in plan["due"]] == ["ch05.Outcodes"] and plan["weights"] == {5: 3.0}


def test_partial_credit_counts_in_the_exam_score():
    from course_lib.exercises.core import PartsAnswer
    chapter, cls = next((ch, c) for ch, classes in mock._numeric_pool().items()
                        for c in classes if issubclass(c, PartsAnswer))
    ex = cls(seed=0)
    parts = ex._parts
    answer = [float(p[1]) for p in parts]
    answer[0] = float(parts[0][1]) + 1000.0                     # one part wrong, far off
    exam = mock.Exam(0, [chapter], [ExamQuestion(chapter, ex)])
    fb = exam.submit(0, repr(answer))
    share = (len(parts) - 1) / len(parts)
    assert fb.status == "wrong" and fb.credit == pytest.approx(share)
    right, total = exam.total()
    assert right == pytest.approx(share, abs=1e-4) and total == 1
    record = exam.record()
    assert record["questions"][0]["credit"] == pytest.approx(share, abs=1e-4)
    assert progress._records._exam_problem({**record, "date": "d"}) is None


def test_widget_adapts_to_the_progress_file_and_says_so(tmp_path):
    file = tmp_path / "progress.json"
    for k in range(3):
        progress.record_event("attempt", key="ch05.Outcodes", seed=k, status="wrong",
                              path=file)
    widget = MockExamWidget(seed=2, chapters=[3, 5], n_questions=6, progress_file=file)
    assert widget.exam.plan is not None
    assert [q.chapter for q in widget.exam].count(5) > 3
    assert widget.exam[[q.chapter for q in widget.exam].index(5)].key == "ch05.Outcodes"
    assert "more questions from chapter 5" in widget.plan_html.value
    assert "comes back in a new variant" in widget.plan_html.value
    balanced = MockExamWidget(seed=2, chapters=[3, 5], n_questions=6, progress_file=file,
                              adaptive=False)
    assert [q.key for q in balanced.exam] == [q.key for q in mock_exam(2, [3, 5], 6)]
    assert balanced.plan_html.value == ""


def test_a_timed_exam_ends_when_the_page_says_the_time_is_up(tmp_path):
    file = tmp_path / "progress.json"
    widget = MockExamWidget(seed=1, chapters=[3], n_questions=3, progress_file=file,
                            time_limit=10)
    assert 599 < widget.countdown.left() <= 600
    widget.submit_answer("[[1, 0], [0, 1]]")                 # graded (wrong or right)
    widget.countdown.expired = True                          # what the page sends at 0:00
    assert widget.state.done and widget.state.timed_out
    assert widget.countdown.stopped and widget.countdown.final == "Time is up"
    assert "The time is up" in widget.shown["results"]
    [saved] = progress.read_history(file)
    assert saved["timed_out"] is True and saved["time_limit"] == 10.0
    assert sum(f is not None for f in widget.exam.feedback) == 3


def test_an_answer_after_the_deadline_is_not_graded_even_if_the_page_was_silent(tmp_path,
                                                                              monkeypatch):
    widget = MockExamWidget(seed=1, chapters=[3], n_questions=2, save=False, time_limit=1)
    now = time.time()
    monkeypatch.setattr(time, "time", lambda: now + 61)
    widget.submit_answer("1, 2, 3")
    assert widget.state.timed_out and all(not f for f in widget.exam.feedback)
    with pytest.raises(ValueError, match="time_limit"):
        MockExamWidget(seed=1, chapters=[3], n_questions=1, save=False, time_limit=0)
