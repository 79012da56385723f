"""Chapter 10 exercises: the kind of colour map a data set needs.

Part of :mod:`course_lib.exercises.ch10`, which imports every exercise from here.
"""
from ..core import Feedback, Worked, data_note, pick
from . import _Chapter10

__all__ = [
    "MAP_KINDS",
    "SCENARIOS",
    "ChooseMapKind",
]


#: The kinds of colour map.
MAP_KINDS = ("sequential", "diverging", "qualitative")

#: The data sets of the question: (what is shown, the kind of map it needs, what its values are,
#: whether they are ordered, their meaningful centre or None), typed out one by one.
_SCENARIO_TABLE = (
    # sequential: ordered, no special value in between
    ("the yearly rainfall in millimetres over a country", "sequential",
     "amounts from no rain to a lot of rain", True, None),
    ("the population density of the districts of a city", "sequential",
     "densities from nearly empty to crowded", True, None),
    ("the density of a CT scan, from air to bone", "sequential",
     "densities from air (low) to bone (high)", True, None),
    ("the wind speed over an ocean", "sequential", "speeds from calm to storm", True, None),
    ("the concentration of a pollutant in a river", "sequential",
     "concentrations from clean water to heavily polluted", True, None),
    ("the altitude of the terrain in a mountain range, all of it far above sea level",
     "sequential", "heights from the valleys to the peaks", True, None),
    ("the age of the trees in a forest, in years", "sequential",
     "ages from saplings to old trees", True, None),
    ("the number of visitors per day of each page of a website", "sequential",
     "counts from a few visitors to very many", True, None),
    ("the depth of the water in a lake", "sequential",
     "depths from the shallow shore to the deepest point", True, None),
    ("the brightness measured by each pixel of a camera sensor", "sequential",
     "intensities from dark to bright", True, None),
    ("the average household income of each district of a city", "sequential",
     "incomes from low to high", True, None),
    ("the traffic on each street of a city, in cars per hour", "sequential",
     "counts from empty streets to jams", True, None),
    # diverging: ordered, with a meaningful centre (a difference from a reference, mostly)
    ("the temperature anomaly: this year's temperature minus the 30-year average",
     "diverging", "deviations, warmer or colder than usual", True, "0, the long-term average"),
    ("the election margin: the share of party A minus the share of party B, per district",
     "diverging", "margins for A or for B", True, "0, a tie"),
    ("correlation coefficients between -1 and 1 in a matrix", "diverging",
     "correlations, negative or positive", True, "0, no correlation"),
    ("the profit or loss of each branch of a company", "diverging",
     "results, gains or losses", True, "0, breaking even"),
    ("the change of the population of each district: this census minus the last one, in "
     "per cent", "diverging", "changes, growth or shrinkage", True, "0 %, no change"),
    ("the error of a weather simulation: the simulated minus the measured temperature in each "
     "grid cell", "diverging", "errors, too warm or too cold", True, "0, perfect agreement"),
    ("the elevation on a map of a coast: the height of the ground minus sea level, from the "
     "sea floor to the hills", "diverging", "heights above and depths below the sea", True,
     "0, sea level"),
    ("the trade balance of each country: its exports minus its imports", "diverging",
     "balances, surpluses or deficits", True, "0, as much sold as bought"),
    ("the deviation of each pupil's test score: the score minus the class average",
     "diverging", "deviations above or below the average", True, "0, exactly the average"),
    ("the net migration of each region: the people moving in minus the people moving out",
     "diverging", "balances, gains or losses of people", True, "0, as many in as out"),
    ("the change of the thickness of a glacier: this year's thickness minus that of 1990, in "
     "metres", "diverging", "changes, thinner or thicker", True, "0, no change"),
    ("the goal difference of each football team: the goals scored minus the goals conceded",
     "diverging", "differences, positive or negative", True, "0, as many scored as conceded"),
    # qualitative: names, no order
    ("the land use of each parcel: forest, farmland, water, city", "qualitative",
     "names of land uses", False, None),
    ("the labels of a segmented scan: bone, muscle, fat, air", "qualitative",
     "names of tissues", False, None),
    ("the cluster number (1 to 6) that a clustering algorithm gave each point", "qualitative",
     "cluster numbers, mere names: cluster 4 is not 'more' than cluster 2", False, None),
    ("the land use planned for each zone of a new town: housing, industry, parks, roads",
     "qualitative", "names of land uses", False, None),
    ("the labels of a map of an election: the party that won each district", "qualitative",
     "names of parties", False, None),
    ("the soil type of each field, stored as labels: clay, sand, loam, peat", "qualitative",
     "names of soil types", False, None),
    ("the language spoken most at home in each region, as labels such as 'Dutch' or 'French'",
     "qualitative", "names of languages", False, None),
    ("the species of each tree of a park, given as labels in its tree register", "qualitative",
     "names of species", False, None),
    ("the material of each part of a machine, as labels: steel, aluminium, plastic, rubber",
     "qualitative", "names of materials", False, None),
    ("the blood group of each patient of a study, as labels: A, B, AB or O", "qualitative",
     "names of blood groups", False, None),
    ("the country of origin of each parcel in a shipment, as labels", "qualitative",
     "names of countries", False, None),
    ("the make of each car in a car park, as labels such as 'Fiat' or 'Volvo'", "qualitative",
     "names of car makes", False, None),
)

#: Data sets and the kind of colour map each needs.
SCENARIOS = tuple((text, kind) for text, kind, *_ in _SCENARIO_TABLE)
#: What the values of each data set are, whether they are ordered, and their centre (or None).
_SCENARIO_VALUES = {text: values for text, _, *values in _SCENARIO_TABLE}

_KIND_REASONS = {
    "sequential": "ordered values from low to high with no special value in between: a "
                  "sequential map, one hue or a perceptual map like viridis, its lightness rising "
                  "with the value",
    "diverging": "values on both sides of a meaningful centre (zero, the average): a diverging "
                 "map, two hues that meet in a light neutral colour at the centre, so that the "
                 "sign and the size of the deviation both show",
    "qualitative": "categories without any order: a qualitative map, clearly different hues of "
                   "similar lightness, so that no category looks like 'more' than another",
}


class ChooseMapKind(_Chapter10):
    r"""Which kind of colour map (sequential, diverging, qualitative) a data set needs.

    Attributes: ``scenario`` (the data set, in words), ``menu`` (:data:`MAP_KINDS`).

    Examples
    --------
    >>> ex = ChooseMapKind(seed=0)
    >>> ex.check(ex.expected).status
    'correct'
    >>> wrong = [k for k in MAP_KINDS if k != ex.expected][0]
    >>> ex.check(wrong).diagnosis == f"{wrong} instead of {ex.expected}"
    True
    >>> ex.check("rainbow").status
    'invalid'
    """

    title = "Choose the kind of colour map"
    answer_form = "custom"
    menu = MAP_KINDS

    def draw(self, rng):
        self.scenario, self.expected = pick(rng, SCENARIOS)

    def separated(self, mistakes):
        return True

    def hints(self):
        values, _, _ = _SCENARIO_VALUES[self.scenario]
        return [
            r"Two questions decide: do the values have an order (less and more)? And if so, is "
            r"there a special value in the middle, such as 0 or an average, with deviations on "
            r"both sides?",
            r"Categories without order need a *qualitative* map; ordered values without a special "
            r"middle a *sequential* one; ordered values around a meaningful centre a "
            r"*diverging* one.",
            f"Here the values are {values}. Is there an order, and is one value in the middle "
            "special?",
        ]

    def worked(self):
        values, ordered, centre = _SCENARIO_VALUES[self.scenario]
        if not ordered:
            kind = "qualitative"
            steps = [f"The values are {values}: categories, with no order.",
                     "Without an order, no colour may look like more than another: "
                     "distinct hues of similar lightness."]
        else:
            kind = "diverging" if centre is not None else "sequential"
            middle = (f"Yes: {centre}, with deviations on both sides of it." if centre
                      else "No: no value in between is special; the values simply run from "
                      "low to high.")
            steps = [f"The values are {values}: they are ordered.",
                     "Is there a meaningful centre? " + middle]
        steps.append(f"So the answer is **{kind}**: {_KIND_REASONS[kind].split(': ', 1)[1]}.")
        return Worked(steps, kind)

    def _check(self, answer):
        kind, unreadable = self._menu_choice(answer)
        if unreadable is not None:          # (a Feedback is falsy unless correct)
            return unreadable
        if kind == self.expected:
            return Feedback("correct", f"Right: these are {_KIND_REASONS[kind]}.")
        return Feedback("wrong", f"A {kind} map is meant for {_KIND_REASONS[kind].split(':')[0]}."
                        f" These data are {_KIND_REASONS[self.expected]}.",
                        f"{kind} instead of {self.expected}")

    def statement(self):
        return (
            rf"You are to show **{self.scenario}** on a map or in an image. Which kind of colour "
            r"map suits these data: a *sequential* map (one direction, light to dark), a "
            r"*diverging* map (two directions from a neutral centre) or a *qualitative* map "
            r"(distinct colours without order)?" "\n\n"
            r"**Answer:** one of the strings `'sequential'`, `'diverging'`, `'qualitative'`."
            "\n\n" + data_note("scenario", "menu"))
