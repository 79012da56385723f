"""Tests of the chapter 10 exercises on the visualization pipeline and exploration
(course_lib.exercises._ch10.pipeline).

The right answers are rebuilt here from tables typed by hand, never read from the catalogue
the checkers use: the stage of each action (by its key words), the step of Shneiderman's
mantra and the use of each scenario. The anticipated mistakes are rebuilt too: every action
moved to every other stage (diagnosed as "<right> as <given>"), every pair of actions swapped
(diagnosed by the first pair of neighbours out of order, found here by a loop), every other
step or use of a scenario.
"""
from types import SimpleNamespace

import pytest

import exercise_harness as harness
from course_lib.exercises._ch10 import pipeline as module

CLASSES = [module.PlacePipelineActions, module.OrderPipelineActions, module.MantraStep,
           module.VisualizationUse]
ch10 = SimpleNamespace(EXERCISES=CLASSES, **{c.__name__: c for c in CLASSES})

ORDER = ["data acquisition", "filtering and enrichment", "mapping", "rendering"]

#: The stage of every action, by words of the action (typed by hand).
STAGE_BY_WORDS = {
    "CT scanner": "data acquisition", "fluid-flow simulation": "data acquisition",
    "time series with a sensor": "data acquisition", "weather stations": "data acquisition",
    "satellite images": "data acquisition", "function on a grid": "data acquisition",
    "outliers": "filtering and enrichment", "median filter": "filtering and enrichment",
    "Gaussian filter": "filtering and enrichment", "resample": "filtering and enrichment",
    "missing values": "filtering and enrichment", "gradient magnitude":
    "filtering and enrichment", "vorticity": "filtering and enrichment",
    "normalise": "filtering and enrichment", "region of interest": "filtering and enrichment",
    "kelvin": "filtering and enrichment", "repeated measurements": "filtering and enrichment",
    "colour map": "mapping", "extract an isosurface": "mapping", "opacity transfer": "mapping",
    "glyphs": "mapping", "streamlines": "mapping", "contour lines": "mapping",
    "by a shape": "mapping", "bar lengths": "mapping", "terrain height": "mapping",
    "ray cast": "rendering", "camera": "rendering", "Phong shading": "rendering",
    "composite": "rendering", "rasterise": "rendering", "light sources": "rendering",
    "anti-alias": "rendering",
}


def stage_of(action):
    [stage] = [s for words, s in STAGE_BY_WORDS.items() if words in action]
    return stage


def place(ex):
    right = [stage_of(a) for a in ex.actions]
    mistakes = {}
    for i, r in enumerate(right):
        for given in ORDER:
            if given != r:
                wrong = list(right)
                wrong[i] = given
                mistakes.setdefault(f"{r} as {given}", harness.Either()).append(wrong)
    return right, mistakes


def order(ex):
    letters = "abcd"
    stage = {letters[i]: stage_of(a) for i, a in enumerate(ex.actions)}
    right = sorted(letters, key=lambda x: ORDER.index(stage[x]))
    mistakes = {}
    for p in range(4):
        for q in range(p + 1, 4):
            wrong = list(right)
            wrong[p], wrong[q] = wrong[q], wrong[p]
            for a, b in zip(wrong, wrong[1:]):
                if ORDER.index(stage[a]) > ORDER.index(stage[b]):
                    key = f"{stage[a]} before {stage[b]}"
                    break
            mistakes.setdefault(key, harness.Either()).append(wrong)
    return right, mistakes


#: The step of each mantra scenario, by words of it (typed by hand).
STEP_BY_WORDS = {
    "first shows all": "overview", "first draws every": "overview",
    "strip of small thumbnails": "overview", "a whole week": "overview",
    "before anything else": "overview", "start page": "overview",
    "time slider": "zoom and filter", "shorter than 2 km": "zoom and filter",
    "magnifies": "zoom and filter", "zooms to it": "zoom and filter",
    "hides the genes": "zoom and filter", "range of years": "zoom and filter",
    "tooltip": "details on demand", "panel lists": "details on demand",
    "reads its exact density": "details on demand", "full log line": "details on demand",
    "table opens": "details on demand", "full record": "details on demand",
}

#: The use of each scenario, by words of it (typed by hand).
USE_BY_WORDS = {
    "turbulence": "exploratory", "data journalist": "exploratory", "bridge test":
    "exploratory", "brushing": "exploratory", "seismic": "exploratory", "emergency-room":
    "exploratory", "tumours": "confirmatory", "Arctic": "confirmatory", "wing":
    "confirmatory", "factory closed": "confirmatory", "bolts": "confirmatory", "bus lane":
    "confirmatory", "figure of a paper": "presentation", "statistics office": "presentation", "defence":
    "presentation", "newspaper": "presentation", "annual report": "presentation", "museum":
    "presentation",
}


def by_words(table, text):
    [found] = [value for words, value in table.items() if words in text]
    return found


def mantra(ex):
    right = by_words(STEP_BY_WORDS, ex.scenario)
    return right, {f"{s} instead of {right}": s
                   for s in ("overview", "zoom and filter", "details on demand") if s != right}


def use(ex):
    right = by_words(USE_BY_WORDS, ex.scenario)
    return right, {f"{u} instead of {right}": u
                   for u in ("exploratory", "confirmatory", "presentation") if u != right}


SPECS = {"PlacePipelineActions": (place, "stages"), "OrderPipelineActions": (order, "letters"),
         "MantraStep": (mantra, "choice"), "VisualizationUse": (use, "choice")}
GARBAGE = {
    "stages": ["mapping", 3, ["mapping"], ["painting"] * 5, {"a": 1}, [1, 2, 3, 4, 5],
               ["mapping"] * 6],
    "letters": [3, ["a", "b"], "abcc", "xyz", {"a": 1}, [1, 2, 3, 4], "abcde"],
    "choice": ["rainbow", 1, ["overview"], {"a": 1}, b"overview", ""],
}

exercises = harness.variants(ch10)


def same(a, b, form):
    return a == b


globals().update(harness.common_tests(ch10, SPECS, GARBAGE, exercises, at_least=4))
test_mistakes_are_diagnosed = harness.mistakes_test(SPECS, exercises, same)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "stages":
            short = {"data acquisition": "Acquisition", "filtering and enrichment":
                     "filtering", "mapping": "Mapping", "rendering": " render "}
            answers = [right, tuple(right), [short[s] for s in right],
                       dict(zip(ex.actions, right))]
        elif form == "letters":
            answers = [right, "".join(right), ", ".join(right).upper(),
                       [f"({x})" for x in right], [ex.actions["abcd".index(x)] for x in right]]
        else:
            answers = [right, right.upper(), f" {right} "]
        harness.assert_accepted(ex, answers)


def test_catalogue_and_scenarios_agree_with_the_typed_tables():
    from course_lib.dataviz import pipeline as pl

    for action, (stage, _) in pl.ACTIONS.items():
        assert stage_of(action) == stage, action
    for text, step in module.MANTRA_SCENARIOS:
        assert by_words(STEP_BY_WORDS, text) == step, text
    for text, kind in module.EXPLORATION_SCENARIOS:
        assert by_words(USE_BY_WORDS, text) == kind, text
    for table, steps in ((module.MANTRA_SCENARIOS, 3), (module.EXPLORATION_SCENARIOS, 3)):
        kinds = [k for _, k in table]
        assert len(set(kinds)) == steps and min(kinds.count(k) for k in set(kinds)) >= 6


def test_place_actions_covers_every_stage_and_names_each_misplaced_action():
    for ex in exercises("PlacePipelineActions", range(60)):
        right, _ = place(ex)
        assert set(right) == set(ORDER) and len(ex.actions) == 5
        assert len(set(ex.actions)) == 5
        wrong = list(right)
        moved = [i for i in range(5) if right[i] in ("mapping", "rendering")]
        for i in moved:                       # swap mapping and rendering everywhere
            wrong[i] = "rendering" if right[i] == "mapping" else "mapping"
        fb = ex.check(wrong)
        assert fb.status == "wrong" and f"{len(moved)} of 5" in fb.message
        for i in moved:
            assert ex.actions[i] in fb.message


def test_order_is_never_given_already_sorted_and_every_stage_appears():
    for ex in exercises("OrderPipelineActions"):
        right, _ = order(ex)
        assert right != ["a", "b", "c", "d"]
        assert sorted(stage_of(a) for a in ex.actions) == sorted(ORDER)


def test_every_scenario_is_asked():
    asked = {module.MantraStep(seed=s).scenario for s in range(300)}
    assert asked == {t for t, _ in module.MANTRA_SCENARIOS}
    asked = {module.VisualizationUse(seed=s).scenario for s in range(300)}
    assert asked == {t for t, _ in module.EXPLORATION_SCENARIOS}
