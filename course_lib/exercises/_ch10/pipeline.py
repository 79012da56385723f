"""Chapter 10 exercises: the visualization pipeline and the methods of scientific exploration
(textbook 10.1, 10.2).

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
import numpy as np

from ...dataviz import pipeline as pl
from ..core import UNANSWERED, Feedback, Worked, data_note, has_placeholder, pick
from . import _Chapter10

__all__ = [
    "EXPLORATION_SCENARIOS",
    "MANTRA_SCENARIOS",
    "MantraStep",
    "OrderPipelineActions",
    "PlacePipelineActions",
    "VisualizationUse",
]

_LETTERS = "abcdefgh"


def _stage_list():
    return ", ".join(f"`'{s}'`" for s in pl.STAGES)


def _actions_by_stage():
    """{stage: tuple of the catalogue's actions in it}, in catalogue order."""
    return {s: tuple(a for a, (st, _) in pl.ACTIONS.items() if st == s) for s in pl.STAGES}


def _read_stage(text):
    """The stage a typed name stands for, or None."""
    try:
        return pl.canonical_stage(text)
    except (TypeError, ValueError):
        return None


def _order_sentence():
    return ("The stages run in the order " + " → ".join(pl.STAGES) + ": each takes what the "
            "one before gives (raw data → prepared data → geometry with visual attributes → "
            "an image).")


class PlacePipelineActions(_Chapter10):
    r"""Place each of five actions of a visualization project in its stage of the pipeline.

    Attributes: ``actions`` (five actions of :data:`course_lib.dataviz.ACTIONS`, at least one
    per stage, in the order asked), ``stages`` (the four stage names). The answer is the list
    of the five stages, in the order of the actions. A misplaced action is diagnosed as
    ``"<right stage> as <given stage>"`` (the first one), and every misplaced action is named
    with the reason it belongs elsewhere.

    Examples
    --------
    >>> ex = PlacePipelineActions(seed=0)
    >>> ex.check(list(ex.expected)).status
    'correct'
    >>> wrong = list(ex.expected); wrong[0] = "mapping" if wrong[0] != "mapping" else "rendering"
    >>> ex.check(wrong).diagnosis == f"{ex.expected[0]} as {wrong[0]}"
    True
    >>> ex.check(["mapping"]).status
    'invalid'
    """

    title = "Place actions in the pipeline"
    answer_form = "custom"
    stages = pl.STAGES

    def draw(self, rng):
        groups = _actions_by_stage()
        chosen = [pick(rng, groups[s]) for s in pl.STAGES]
        extra_stage = pick(rng, pl.STAGES)
        rest = [a for a in groups[extra_stage] if a not in chosen]
        chosen.append(pick(rng, rest))
        order = rng.permutation(len(chosen))
        self.actions = tuple(chosen[i] for i in order)
        self.expected = [pl.pipeline_stage(a) for a in self.actions]

    def separated(self, mistakes):
        return True

    def _read(self, answer):
        form = ("Give a list of 5 stage names, one per action in the order of the table, e.g. "
                f"`{['mapping'] * 5!r}`; the stages are " + _stage_list() + ".")
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        if isinstance(answer, dict):
            keys = {" ".join(str(k).lower().split()): v for k, v in answer.items()}
            if set(keys) != {a.lower() for a in self.actions}:
                return Feedback("invalid", form, "unreadable")
            answer = [keys[a.lower()] for a in self.actions]
        if isinstance(answer, (str, bytes)) or not isinstance(answer, (list, tuple, np.ndarray)):
            return Feedback("invalid", form, "unreadable")
        if len(answer) != len(self.actions):
            return Feedback("invalid", f"You gave {len(answer)} stages for "
                            f"{len(self.actions)} actions. " + form, "wrong length")
        stages = []
        for item in answer:
            stage = _read_stage(item) if isinstance(item, str) else None
            if stage is None:
                return Feedback("invalid", f"{item!r} is not a stage of the pipeline. " + form,
                                "unreadable")
            stages.append(stage)
        return stages

    def _check(self, answer):
        stages = self._read(answer)
        if isinstance(stages, Feedback):
            return stages
        wrong = [(a, g, r) for a, g, r in zip(self.actions, stages, self.expected) if g != r]
        if not wrong:
            return Feedback("correct", "Every action is in its stage. " + _order_sentence())
        action, given, right = wrong[0]
        lines = [f"“{a}” belongs to **{r}**, not {g}: {pl.ACTIONS[a][1]}." for a, g, r in wrong]
        return Feedback("wrong", f"{len(wrong)} of {len(self.actions)} actions are misplaced. "
                        + " ".join(lines), f"{right} as {given}")

    def statement(self):
        rows = "\n".join(f"| ({_LETTERS[i]}) | {a} |" for i, a in enumerate(self.actions))
        return (
            "A visualization project consists of the actions below. Name, for each, the stage "
            "of the visualization pipeline it belongs to: " + _stage_list() + ".\n\n"
            "| | action |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** a list of 5 stage names, in the order of the actions, e.g. "
            f"`{['rendering'] * 5!r}`." "\n\n" + data_note("actions", "stages"))

    def hints(self):
        return [
            "Ask what each action takes and what it gives. Acquisition produces raw data; "
            "filtering and enrichment turns data into better data (still numbers); mapping "
            "turns data into something drawable (geometry, colours, opacities); rendering "
            "turns that into pixels.",
            "Test for mapping: does the action decide how a value *looks* (a colour, an "
            "opacity, a shape, a surface to draw)? Test for rendering: does it need a camera, "
            "lights or pixels?",
            "Derived quantities (gradients, vorticity), resampling and normalising are "
            "enrichment and filtering: the result is a new field of numbers, not yet a "
            "picture. Here the first action, “" + self.actions[0] + "”, produces "
            + pl.STAGE_INFO[self.expected[0]].gives.split(":")[0].split(" (")[0] + ".",
        ]

    def worked(self):
        steps, answer = [], []
        for i, action in enumerate(self.actions):
            stage, why = pl.ACTIONS[action]
            steps.append(f"({_LETTERS[i]}) “{action}”: **{stage}**, {why}.")
            answer.append(stage)
        return Worked(steps, answer)


class OrderPipelineActions(_Chapter10):
    r"""Put four actions, one from each stage, in the order the pipeline performs them.

    Attributes: ``actions`` (four actions labelled a-d, one per stage, shuffled). The answer is
    the letters in pipeline order (a list such as ``['c', 'a', 'd', 'b']`` or the string
    ``"cadb"``). A wrong order is diagnosed by its first pair of neighbours in the wrong order,
    ``"<later stage> before <earlier stage>"``.

    Examples
    --------
    >>> ex = OrderPipelineActions(seed=1)
    >>> ex.check(list(ex.expected)).status, ex.check("".join(ex.expected)).status
    ('correct', 'correct')
    >>> swapped = [ex.expected[1], ex.expected[0]] + list(ex.expected[2:])
    >>> ex.check(swapped).diagnosis
    'filtering and enrichment before data acquisition'
    """

    title = "Order the pipeline"
    answer_form = "custom"

    def draw(self, rng):
        groups = _actions_by_stage()
        chosen = [pick(rng, groups[s]) for s in pl.STAGES]
        order = rng.permutation(len(chosen))
        self.actions = tuple(chosen[i] for i in order)
        letter_of = {a: _LETTERS[i] for i, a in enumerate(self.actions)}
        self.expected = [letter_of[a] for a in chosen]

    def acceptable(self):
        return self.expected != list(_LETTERS[:4])          # never given in order already

    def separated(self, mistakes):
        return True

    def _read(self, answer):
        n = len(self.actions)
        form = (f"Give the {n} letters in pipeline order, as a list such as "
                f"`{list(_LETTERS[:n][::-1])!r}` or a string such as "
                f"`'{_LETTERS[:n][::-1]}'`.")
        if has_placeholder(answer):
            return Feedback("unanswered", UNANSWERED)
        if isinstance(answer, str):
            items = [c for c in answer.lower() if c.isalpha()]
        elif isinstance(answer, (list, tuple)) and all(isinstance(a, str) for a in answer):
            items = [a.strip().lower().strip("()") for a in answer]
            texts = {a.lower(): _LETTERS[i] for i, a in enumerate(self.actions)}
            items = [texts.get(a, a) for a in items]
        else:
            return Feedback("invalid", form, "unreadable")
        if sorted(items) != list(_LETTERS[:n]):
            return Feedback("invalid", f"Use each of the letters {', '.join(_LETTERS[:n])} "
                            "exactly once. " + form, "unreadable")
        return items

    def _check(self, answer):
        letters = self._read(answer)
        if isinstance(letters, Feedback):
            return letters
        stage_of = {_LETTERS[i]: pl.pipeline_stage(a) for i, a in enumerate(self.actions)}
        rank = {s: k for k, s in enumerate(pl.STAGES)}
        if letters == self.expected:
            return Feedback("correct", "That is the pipeline's order. " + _order_sentence())
        for first, second in zip(letters, letters[1:]):
            if rank[stage_of[first]] > rank[stage_of[second]]:
                break
        later, earlier = stage_of[first], stage_of[second]
        action = self.actions[_LETTERS.index(first)]
        other = self.actions[_LETTERS.index(second)]
        return Feedback(
            "wrong", f"You put ({first}) “{action}” ({later}) before ({second}) “{other}” "
            f"({earlier}). The {later} stage takes "
            f"{pl.STAGE_INFO[later].takes}, which only the {earlier} stage (or a later one "
            "before it) produces. " + _order_sentence(), f"{later} before {earlier}")

    def statement(self):
        rows = "\n".join(f"| ({_LETTERS[i]}) | {a} |" for i, a in enumerate(self.actions))
        return (
            "The four actions below come from one visualization project, one from each stage "
            "of the visualization pipeline. In which order are they performed?\n\n"
            "| | action |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** the letters in the order performed, as a list such as "
            r"`['d', 'c', 'b', 'a']` or a string such as `'dcba'`." "\n\n"
            + data_note("actions"))

    def hints(self):
        first = self.actions[_LETTERS.index(self.expected[0])]
        return [
            "The pipeline's four stages are, in order: data acquisition, filtering and "
            "enrichment, mapping, rendering. Find the stage of each action, then sort.",
            "Acquisition creates the data, filtering changes data into better data, mapping "
            "turns data into drawable geometry and attributes, rendering makes pixels.",
            f"The first action is the one that produces the raw data: here “{first}”.",
        ]

    def worked(self):
        steps = []
        by_stage = {}
        for i, action in enumerate(self.actions):
            stage, why = pl.ACTIONS[action]
            by_stage[stage] = _LETTERS[i]
            steps.append(f"({_LETTERS[i]}) “{action}” is **{stage}**: {why}.")
        answer = [by_stage[s] for s in pl.STAGES]
        steps.append("In pipeline order (" + " → ".join(pl.STAGES) + "): "
                     + ", ".join(f"({x})" for x in answer) + ".")
        return Worked(steps, answer)


# ---------------------------------------------------------------------------------------------
# Choosing from a scenario: the step of Shneiderman's mantra, the use of a visualization
# ---------------------------------------------------------------------------------------------

#: Scenarios of an exploration and the step of Shneiderman's mantra each one is.
MANTRA_SCENARIOS = (
    ("A climate scientist opens 40 years of daily temperatures of 500 stations and first "
     "shows all of them in one heat map, one row per station.", "overview"),
    ("An analyst loads a table of two million taxi rides and first draws every pick-up point "
     "as a dot on one map of the city.", "overview"),
    ("A radiologist opens a new CT study and first looks at a strip of small thumbnails of all "
     "300 slices.", "overview"),
    ("An engineer plots a whole week of server response times in one chart, each minute "
     "reduced to its minimum and maximum.", "overview"),
    ("A biologist shows the expression of all 20,000 genes in all samples as one clustered "
     "colour matrix before anything else.", "overview"),
    ("The start page of a library's catalogue app shows every book of the collection as a "
     "small tile, coloured by subject.", "overview"),
    ("In a heat map of 40 years of temperatures, a scientist drags a time slider so that only "
     "the winter of 1996 is shown.", "zoom and filter"),
    ("On a map of two million taxi rides, an analyst hides every ride shorter than 2 km with "
     "a range slider.", "zoom and filter"),
    ("A radiologist magnifies the region around a suspicious spot in one CT slice.",
     "zoom and filter"),
    ("In a week-long chart of response times, an engineer drags over the hour of the outage "
     "and the chart zooms to it.", "zoom and filter"),
    ("In a matrix of gene expression, a biologist ticks a box that hides the genes whose "
     "expression does not change between the samples.", "zoom and filter"),
    ("In a library's catalogue app, a reader types a range of years to keep only the books "
     "published from 1900 to 1950.", "zoom and filter"),
    ("In a heat map of temperatures, a scientist hovers over one cell and a tooltip shows the "
     "station's name, the date and the exact temperature.", "details on demand"),
    ("On a map of taxi rides, an analyst clicks one dot and a panel lists that ride's fare, "
     "duration and time.", "details on demand"),
    ("A radiologist clicks a spot in a CT slice and reads its exact density and position.",
     "details on demand"),
    ("In a chart of response times, an engineer clicks the highest peak to see the full log "
     "line of the request that caused it.", "details on demand"),
    ("In a matrix of gene expression, a biologist selects one gene and a table opens with its "
     "name, its function and all its measured values.", "details on demand"),
    ("In a library's catalogue app, a reader clicks one tile to open the full record of that "
     "book.", "details on demand"),
)

#: Scenarios of a visualization and its use.
EXPLORATION_SCENARIOS = (
    ("A physicist gets the first output of a new turbulence simulation and clicks through "
     "slices and isosurfaces, looking for anything unusual.", "exploratory"),
    ("A data journalist receives a spreadsheet of all public contracts of a city and tries "
     "many kinds of charts to find a story.", "exploratory"),
    ("An engineer is handed the sensor logs of a failed bridge test and, without a suspicion "
     "yet, plots every sensor against time.", "exploratory"),
    ("A marine biologist looks at a new set of ocean temperature profiles in linked "
     "scatterplots with brushing, to see what is there.", "exploratory"),
    ("A geologist browses a newly recorded seismic volume slice by slice to see which "
     "structures it contains.", "exploratory"),
    ("A hospital analyst opens a year of emergency-room records for the first time and looks "
     "for patterns of any kind.", "exploratory"),
    ("A doctor checks whether the tumours of the treated patients shrank more than those of "
     "the control group, plotting both groups on the same scale.", "confirmatory"),
    ("A climate researcher tests the hypothesis that the Arctic warms faster than the rest of "
     "the world, plotting the regions' trends side by side with their uncertainty.",
     "confirmatory"),
    ("An engineer checks whether a new wing reduces the drag as the theory predicts, "
     "comparing measured and predicted pressure curves on common axes.", "confirmatory"),
    ("An economist verifies that unemployment rose after a factory closed, comparing the town "
     "with similar towns in small multiples.", "confirmatory"),
    ("A quality engineer checks whether the diameters of a batch of bolts stay within the "
     "tolerance, plotting them against the limits.", "confirmatory"),
    ("A traffic planner tests the expectation that a new bus lane shortened travel times, "
     "with the distributions before and after on one axis.", "confirmatory"),
    ("A researcher prepares the one figure of a paper that shows its main result to the "
     "readers.", "presentation"),
    ("A city's statistics office makes a chart of the population growth for its yearly "
     "report to the citizens.", "presentation"),
    ("A PhD student makes the slide of the defence that must let the committee see the "
     "result within ten seconds.", "presentation"),
    ("A newspaper publishes an infographic of the election results.", "presentation"),
    ("A company's annual report shows the shareholders the revenue of the last five years.",
     "presentation"),
    ("A museum designs a wall panel that explains sea-level rise to its visitors.",
     "presentation"),
)

_MANTRA_STEPS = tuple(step for step, _ in pl.MANTRA)
_MANTRA_WHAT = dict(pl.MANTRA)


class _ScenarioChoice(_Chapter10):
    """A choice among a few names for a scenario (the base of the two questions below)."""

    answer_form = "custom"
    menu = ()
    scenarios = ()

    def draw(self, rng):
        self.scenario, self.expected = pick(rng, self.scenarios)

    def separated(self, mistakes):
        return True

    def _reason(self, name):
        raise NotImplementedError

    def _check(self, answer):
        key, unreadable = self._menu_choice(answer, getattr(self, "aliases", None))
        if unreadable is not None:          # (a Feedback is falsy unless correct)
            return unreadable
        if key == self.expected:
            return Feedback("correct", f"Right: {self._reason(key)}")
        return Feedback("wrong", f"“{key}” would be {self._describe(key)}. Here: "
                        f"{self._reason(self.expected)}", f"{key} instead of {self.expected}")


class MantraStep(_ScenarioChoice):
    r"""Which step of Shneiderman's mantra (overview, zoom and filter, details on demand) an
    interaction in a scenario is.

    Attributes: ``scenario`` (the interaction, in words), ``menu`` (the three steps).

    Examples
    --------
    >>> ex = MantraStep(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [s for s in ex.menu if s != ex.expected][0]
    >>> ex.check(wrong).diagnosis == f"{wrong} instead of {ex.expected}"
    True
    """

    title = "Overview, zoom and filter, details on demand"
    menu = _MANTRA_STEPS
    scenarios = MANTRA_SCENARIOS
    aliases = {"details": "details on demand", "zoom": "zoom and filter",
               "filter": "zoom and filter", "zoom & filter": "zoom and filter",
               "overview first": "overview"}

    _CUES = {"overview": "the whole data set is shown at once, reduced to fit",
             "zoom and filter": "the view is narrowed to part of the data (a region, a time "
                                "span, the items matching a condition)",
             "details on demand": "the exact values of one item are asked for"}

    def _describe(self, step):
        return f"the step where {self._CUES[step]}: to {_MANTRA_WHAT[step]}"

    def _reason(self, step):
        return f"{self._CUES[step]}, which is **{step}** ({_MANTRA_WHAT[step]})."

    def statement(self):
        return (
            "Shneiderman's mantra of visual information seeking reads *overview first, zoom "
            "and filter, then details on demand*. Which of its three steps is this?\n\n"
            f"> {self.scenario}\n\n"
            r"**Answer:** one of the strings `'overview'`, `'zoom and filter'`, "
            r"`'details on demand'`." "\n\n" + data_note("scenario", "menu"))

    def hints(self):
        return [
            "Ask how much of the data the view shows after the action: all of it, a part of "
            "it, or a single item.",
            "An overview shows everything (reduced); zooming and filtering keep a part "
            "(a region, a time span, the items passing a condition); details on demand show "
            "the exact values of one item, usually on a click or hover.",
            "Look at the verb of the scenario: does it *show all*, *narrow down* or *ask "
            "for one item's values*?",
        ]

    def worked(self):
        step = self.expected
        what = {"overview": "all of the data, reduced to fit the screen",
                "zoom and filter": "only a part of the data",
                "details on demand": "the exact values of one item"}[step]
        return Worked([f"The scenario: {self.scenario}",
                       f"After this action the view shows {what}.",
                       f"So it is **{step}**: {_MANTRA_WHAT[step]}."], step)


class VisualizationUse(_ScenarioChoice):
    r"""Which use a visualization serves: exploratory, confirmatory (analysis) or
    presentation, and so what it needs.

    Attributes: ``scenario`` (in words), ``menu`` (the three uses).

    Examples
    --------
    >>> ex = VisualizationUse(seed=3)
    >>> ex.check(ex.expected).status
    'correct'
    >>> ex.check("decoration").status
    'invalid'
    """

    title = "Exploration, confirmation or presentation?"
    menu = tuple(pl.USES)
    scenarios = EXPLORATION_SCENARIOS
    aliases = {"analysis": "confirmatory", "confirmation": "confirmatory",
               "exploration": "exploratory", "explore": "exploratory",
               "present": "presentation", "explanatory": "presentation"}

    def _describe(self, use):
        u = pl.USES[use]
        return (f"the use for the question “{u.question}”, for {u.audience}; it needs "
                f"{u.needs[0]}")

    def _reason(self, use):
        u = pl.USES[use]
        return (f"the question is “{u.question}”, for {u.audience}: a **{use}** "
                f"visualization, which needs {u.needs[0]} and {u.needs[1]}.")

    def statement(self):
        return (
            "Visualizations serve three uses: **exploratory** (searching the data without a "
            "hypothesis), **confirmatory** (analysis: testing a hypothesis) and "
            "**presentation** (showing a result to others). Which use is this?\n\n"
            f"> {self.scenario}\n\n"
            r"**Answer:** one of the strings `'exploratory'`, `'confirmatory'`, "
            r"`'presentation'`." "\n\n" + data_note("scenario", "menu"))

    def hints(self):
        return [
            "Ask who looks at the picture and whether the question is already known.",
            "No question yet, only searching: exploratory. A definite hypothesis or "
            "expectation to check: confirmatory. A finished result shown to people who have "
            "not seen the data: presentation.",
            "Look for the words of the scenario: *looking for anything*, *tests / checks "
            "whether*, or *readers / report / slide / visitors*.",
        ]

    def worked(self):
        use = self.expected
        u = pl.USES[use]
        return Worked([f"The scenario: {self.scenario}",
                       f"Is a question already known, and who looks? Here: “{u.question}”, "
                       f"for {u.audience}.",
                       f"So the use is **{use}**; it needs " + "; ".join(u.needs) + "."], use)
