"""What the tests of every chapter's exercises share (tests/test_exercises_chNN.py).

A chapter's test file keeps what is its own: the independent solvers (each returns the right
answer and the anticipated mistakes of one variant, rebuilt from the question's attributes),
the SPECS table (exercise name -> (solver, answer form)), the GARBAGE each form must reject,
and the tests only that chapter needs. The tests every chapter runs are built here by
:func:`common_tests`, and :func:`check_mistakes` checks that each anticipated mistake is named
by its diagnosis.

This is a plain module: pytest puts tests/ on ``sys.path`` (rootdir conftest, no package), so
a test file imports it as ``import exercise_harness``.
"""
import functools
import re

import numpy as np
import pytest

#: The seeds of the variants every test looks at.
SEEDS = range(200)
#: A mistake must be diagnosed in at least this many of the seeds (else the test is vacuous).
MIN_DIAGNOSED = 10
#: Answers closer than this are "the same".
SAME = 1e-9
#: Answers no exercise can read: checking them gives a verdict, never an exception.
ODD = [object(), [None, None, None], {1, 2, 3}, b"bytes", 1j, [[[]]], -1, True]
#: More odd answers: empty and unreadable containers.
EMPTY_ODD = [[], [object()], np.array([]), {"a"}]


class Either(list):
    """Several values a slip may give (e.g. either of two points): each is diagnosed as it."""


def gap(a, b):
    """The largest componentwise difference of two answers (infinite for other shapes)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return np.inf
    return float(np.abs(a - b).max())


def same(a, b, form=None):
    """Whether two answers of numbers agree to :data:`SAME` (the exercises' own
    :func:`course_lib.exercises.core.gap`): the ``same`` of :func:`mistakes_test` for chapters
    whose answers are all numbers."""
    from course_lib.exercises.core import gap as answer_gap

    return answer_gap(a, b) < SAME


def answer_key(value, decimals=6):
    """A hashable form of an answer, to count the distinct variants among seeds.

    Numbers are rounded to `decimals` (float noise is no new variant); words, lists of words
    and sets stay what they are; a tuple is keyed part by part.
    """
    if value is None or isinstance(value, str):
        return value
    if isinstance(value, (set, frozenset)):
        return tuple(sorted(value))
    if isinstance(value, tuple):
        return tuple(answer_key(part, decimals) for part in value)
    if isinstance(value, list) and value and isinstance(value[0], str):
        return tuple(value)
    return tuple(np.round(np.ravel(np.asarray(value, dtype=float)), decimals) + 0.0)


def significant(x, digits=3):
    """`x` rounded to `digits` significant digits, as a student writes it down."""
    return float(f"{x:.{digits}g}")


def wrong_answers(right, flips=False):
    """Wrong answers near and far from `right`, and off in one part at a time.

    With `flips` (answers of 0s and 1s) also the other value, in all parts and in each.
    """
    right = np.asarray(right, dtype=float)
    answers = [right + 0.37, right + 1000.5, 2 * right + 1.3, -right - 0.71]
    if flips and gap(1 - right, right) > SAME:
        answers.append(1 - right)
    for k in range(right.size if right.ndim else 0):
        one = right.copy()
        one[k] += 0.53
        answers.append(one)
        if flips:
            other = right.copy()
            other[k] = 1 - other[k]
            if gap(other, right) > SAME:
                answers.append(other)
    return answers


def advice_counts(exercises, solve, wrong):
    """Every answer of ``wrong(ex, right)`` is wrong and ends with the exercise's advice at
    most once (it used to be printed twice); returns (answers checked, answers advised), so
    that a test can also ask that the advice is given at all."""
    checked = advised = 0
    for ex in exercises:
        assert ex.advice
        right, _ = solve(ex)
        for answer in wrong(ex, right):
            fb = ex.check(answer)
            assert fb.status == "wrong", (ex, answer, fb)
            assert fb.message.count(ex.advice) <= 1, (ex, answer, fb.message)
            checked, advised = checked + 1, advised + (ex.advice in fb.message)
    return checked, advised


def variants(module, seeds=SEEDS):
    """``exercises(name, seeds)``: the variants of `module`'s exercise `name`, built once.

    Checking an answer does not change an exercise, so every test may share them.
    """
    @functools.lru_cache(maxsize=None)
    def built(name):
        cls = getattr(module, name)
        return tuple(cls(seed=seed) for seed in seeds)

    def exercises(name, seeds=seeds):
        every = built(name)
        return [every[seed] for seed in seeds]

    return exercises


def assert_accepted(ex, answers):
    """Every one of `answers` (spellings of the right answer) is correct."""
    for answer in answers:
        fb = ex.check(answer)
        assert fb.status == "correct", (ex, answer, fb)
        assert bool(fb)


def check_mistakes(name, specs, exercises, same, as_answer=None, min_message=40,
                   key_seeds=range(30)):
    """Each anticipated mistake of exercise `name` is diagnosed as itself.

    ``specs[name]`` is ``(solve, form)``; ``solve(ex)`` gives the right answer and a dict of
    anticipated mistakes (key -> value, or an :class:`Either` of values). A slip that gives the
    right answer in a variant (``same(value, right, form)``) must be accepted; any other must be
    "wrong", diagnosed with its key, explained in more than `min_message` characters, and every
    key met in `key_seeds` must be diagnosed in at least MIN_DIAGNOSED variants.
    """
    solve, form = specs[name]
    diagnosed = {}
    for ex in exercises(name):
        right, mistakes = solve(ex)
        for key, values in mistakes.items():
            for value in (values if isinstance(values, Either) else [values]):
                fb = ex.check(value if as_answer is None else as_answer(value, form))
                if same(value, right, form):     # in this variant the slip gives the right answer
                    assert fb.status == "correct", (ex, key, fb)
                    continue
                assert fb.status == "wrong", (ex, key, value, fb)
                assert fb.diagnosis == key, (ex, key, value, fb.diagnosis, fb.message)
                assert len(fb.message) > min_message
                diagnosed[key] = diagnosed.get(key, 0) + 1
    keys = set().union(*(solve(ex)[1] for ex in exercises(name, key_seeds)))
    for key in keys:
        assert diagnosed.get(key, 0) >= MIN_DIAGNOSED, (key, diagnosed)


def common_tests(module, specs, garbage, exercises, *, at_least, distinct=(20, 6),
                 words=r"\b(nan|inf)\b", clean=str.lower, newlines=r"\\neq?\b",
                 odd=ODD + EMPTY_ODD):
    """The tests every chapter runs, by name, for the chapter file's namespace.

    Parameters
    ----------
    module : module
        The chapter's exercise module (``EXERCISES`` lists its classes).
    specs : dict
        Exercise name -> (solver, answer form).
    garbage : dict
        Answer form -> answers that must be "invalid".
    exercises : callable
        ``exercises(name, seeds)`` from :func:`variants`.
    at_least : int
        How many exercises the chapter has at least.
    distinct : (int, int) or None
        Among the first ``distinct[0]`` seeds at least ``distinct[1]`` statements differ.
    words : str
        A pattern no statement may hold (after ``clean(text)``): a NaN or infinity shown.
    clean : callable
        The statement text as searched for `words`.
    newlines : str or None
        Escaped newlines ``\\n`` may not stand in a statement once this pattern (LaTeX such as
        ``\\neq``) is removed; None: not checked.
    odd : list or None
        Odd answers that give a verdict, never an exception; None: not checked.

    Returns
    -------
    dict
        Test name -> test function: ``globals().update(common_tests(...))``.
    """
    def test_exercise_list():
        assert len(module.EXERCISES) >= at_least
        assert len(set(module.EXERCISES)) == len(module.EXERCISES)
        assert {cls.__name__ for cls in module.EXERCISES} == set(specs)

    @pytest.mark.parametrize("cls", module.EXERCISES, ids=lambda cls: cls.__name__)
    def test_docstring_has_examples(cls):
        doc = cls.__doc__ or ""
        assert doc.strip() and "Examples\n    --------" in doc and ">>>" in doc
        assert cls.title and cls.title != "Exercise"

    @pytest.mark.parametrize("name", specs)
    def test_statement_reads(name):
        for ex in exercises(name):
            text = ex.statement()
            assert isinstance(text, str) and len(text) > 80
            assert not re.search(words, clean(text))
            if newlines is not None:
                assert "\\n" not in re.sub(newlines, "", text)       # no escaped newlines
            assert "**Answer:**" in text
            assert ex._repr_markdown_().startswith(f"**{ex.title}**")
        cls = getattr(module, name)
        assert cls(seed=5).statement() == cls(seed=5).statement()   # a seed is reproducible
        if distinct is not None:                                      # seeds differ
            n_seeds, n_distinct = distinct
            assert len({ex.statement() for ex in exercises(name, range(n_seeds))}) >= n_distinct

    @pytest.mark.parametrize("name", specs)
    def test_placeholders_are_unanswered(name):
        for ex in exercises(name, range(20)):
            for placeholder in (..., None):
                fb = ex.check(placeholder)
                assert fb.status == "unanswered" and not fb
                assert "`...`" in fb.message

    @pytest.mark.parametrize("name", specs)
    def test_garbage_is_invalid(name):
        _, form = specs[name]
        for ex in exercises(name, range(20)):
            for answer in garbage[form]:
                fb = ex.check(answer)
                assert fb.status == "invalid", (ex, answer, fb)
                assert fb.message

    def test_checks_never_raise_on_odd_input():
        for cls in module.EXERCISES:
            ex = cls(seed=3)
            for answer in odd:
                fb = ex.check(answer)
                assert fb.status in ("invalid", "wrong", "unanswered"), (cls, answer, fb)

    tests = [test_exercise_list, test_docstring_has_examples, test_statement_reads,
             test_placeholders_are_unanswered, test_garbage_is_invalid]
    if odd is not None:
        tests.append(test_checks_never_raise_on_odd_input)
    return {test.__name__: test for test in tests}


def mistakes_test(specs, exercises, same, **options):
    """``test_mistakes_are_diagnosed`` for every exercise of `specs` (see :func:`check_mistakes`)."""
    @pytest.mark.parametrize("name", specs)
    def test_mistakes_are_diagnosed(name):
        check_mistakes(name, specs, exercises, same, **options)

    return test_mistakes_are_diagnosed


def right_answer_test(specs, exercises, decimals=3):
    """``test_right_answer_is_accepted`` for answers of numbers: as computed, rounded, as lists."""
    @pytest.mark.parametrize("name", specs)
    def test_right_answer_is_accepted(name):
        solve, _ = specs[name]
        for ex in exercises(name):
            right, _ = solve(ex)
            assert_accepted(ex, [right, np.round(right, decimals), np.asarray(right).tolist()])

    return test_right_answer_is_accepted


def topic(module, specs):
    """The chapter module `module` narrowed to the exercises in `specs` (a chapter's exercises
    are split over topic test files: each file tests its own, and common_tests(topic(...), ...)
    checks exactly those)."""
    import types
    return types.SimpleNamespace(EXERCISES=tuple(cls for cls in module.EXERCISES
                                                 if cls.__name__ in specs),
                                 **{name: getattr(module, name) for name in specs})


def every_exercise_tested(module, specs, at_least):
    """A test: the chapter's test files (test_exercises_chNN.py with `specs`, and every
    test_exercises_chNN_*.py beside it) together test every exercise of ``module.EXERCISES``,
    each in exactly one file, and the chapter has at least `at_least` exercises."""
    import importlib
    from pathlib import Path

    chapter = module.__name__.rsplit(".", 1)[1]

    def test_every_exercise_is_tested_in_one_file():
        files = sorted(Path(__file__).parent.glob(f"test_exercises_{chapter}_*.py"))
        assert files
        tested = list(specs)
        for path in files:
            tested += list(importlib.import_module(path.stem).SPECS)
        assert sorted(tested) == sorted(cls.__name__ for cls in module.EXERCISES)
        assert len(module.EXERCISES) >= at_least

    return test_every_exercise_is_tested_in_one_file
