"""Chapter 7 exercises: Properties.

Part of :mod:`course_lib.exercises.ch07`, which imports every exercise from here.
"""

from ..core import Feedback, Worked, data_note, pick, read_names
from . import _Chapter7

__all__ = [
    "PROPERTY_MENU",
    "CurveProperties",
]


#: The menu of properties: name -> what it means.
PROPERTY_MENU = {
    "convex hull": "every point lies in the convex hull of the control points",
    "strong convex hull": "each polynomial piece lies in the convex hull of only the control "
                          "points active on it (p + 1 of them per direction)",
    "local control": "moving one control point changes only a limited part of the "
                     "curve (surface)",
    "pseudo-local control": "moving one control point changes the whole curve (surface), "
                            "most strongly near that point",
    "affine invariance": "transforming the control points by an affine map transforms the "
                         "curve (surface) by the same map",
    "projective invariance": "the same for projective maps (perspective projections)",
    "variation diminishing": "no line (plane) crosses the curve more often than it crosses "
                             "the control polygon",
    "endpoint interpolation": "the curve passes through its first and last control points "
                              "(the surface through its four corner control points)",
    "exact conics": "can represent circles (for surfaces: spheres, cylinders) exactly",
    "independent degree": "the degree can be chosen independently of the number of control "
                          "points",
}

_KINDS = ("Bézier curve", "B-spline curve", "rational Bézier curve", "NURBS curve",
          "Bézier surface", "B-spline surface", "NURBS surface")


def _properties_of(kind):
    """The properties from PROPERTY_MENU that hold for `kind` (clamped knots, weights > 0)."""
    spline = "B-spline" in kind or "NURBS" in kind
    rational = "rational" in kind or "NURBS" in kind
    surface = kind.endswith("surface")
    holds = {"convex hull", "affine invariance", "endpoint interpolation"}
    if spline:
        holds |= {"strong convex hull", "local control", "independent degree"}
    else:
        holds.add("pseudo-local control")
    if rational:
        holds |= {"projective invariance", "exact conics"}
    if not surface:
        holds.add("variation diminishing")
    return holds


#: Why each property of the menu holds or fails for a type: {name: (if it holds, if it fails)}.
#: ``{thing}`` stands for "curve" or "surface"; a property that holds for every type has one
#: sentence for both.
_PROPERTY_REASONS = {
    "convex hull": 2 * (
        r"**Convex hull** holds for every type here: the blending functions are "
        r"non-negative (weights positive) and add up to 1, so each point is a convex "
        r"combination of the control points.",),
    "affine invariance": 2 * (
        r"**Affine invariance** holds for every type here: the blending functions add "
        r"up to 1, so mapping the control points by an affine map maps every point of "
        r"the {thing} by it.",),
    "endpoint interpolation": 2 * (
        r"**Endpoint interpolation** holds: the first and last blending functions are "
        r"1 at the ends (for B-splines thanks to the clamped knots), so the curve starts "
        r"and ends at the end control points, and a patch passes through its corners.",),
    "strong convex hull": (
        r"**Strong convex hull** holds for B-splines and NURBS: "
        r"on one knot span only $p + 1$ basis functions are non-zero, so each piece "
        r"lies in the hull of those few control points.",
        r"**Strong convex hull** is a B-spline property (each piece "
        r"in the hull of its $p + 1$ active points). A Bézier {thing}"
        r" is a single piece whose blending functions involve all control points: it "
        r"has the ordinary convex hull property only."),
    "local control": (
        r"**Local control** holds for B-splines and NURBS: "
        r"$N_{i,p}$ is zero outside $[u_i, u_{i+p+1})$, so moving $P_i$ changes only "
        r"that part.",
        r"**Local control** is B-spline only. Every Bernstein polynomial "
        r"is non-zero on the whole open interval $(0, 1)$, so moving one control point of "
        r"a Bézier {thing} moves every point except the ends: pseudo-local "
        r"control."),
    "independent degree": (
        r"**Independent degree** holds for B-splines and NURBS: "
        r"more control points mean more knots and pieces, while the degree $p$ "
        r"stays whatever you choose.",
        r"**Independent degree** is B-spline only: a Bézier {thing}"
        r" with $n + 1$ control points (per direction) has degree $n$, so more points "
        r"mean a higher degree."),
    "pseudo-local control": (
        r"**Pseudo-local control** holds for Bézier types: moving $P_i$ moves "
        r"every point of the {thing} (all Bernstein polynomials are positive inside "
        r"the domain), most near the parameter $i / n$.",
        r"**Pseudo-local control** describes Bézier types, whose every point moves "
        r"when one control point moves. B-splines and NURBS have true **local** "
        r"control instead."),
    "projective invariance": (
        r"**Projective invariance** holds for rational types: transform the "
        r"homogeneous control points $(w_i P_i, w_i)$ and the new last coordinates "
        r"are the new weights.",
        r"**Projective invariance** needs weights, i.e. a rational type. A "
        r"perspective map divides by a coordinate that changes along the "
        r"{thing}; a polynomial {thing} has no weights to absorb it, so it is only "
        r"affinely invariant."),
    "exact conics": (
        r"**Exact conics** hold for rational types: with weights "
        r"$(1, \cos\frac{\theta}{2}, 1)$ a quadratic arc is exactly a circular arc, "
        r"and NURBS surfaces give exact spheres and cylinders.",
        r"**Exact conics** need weights: a circle has no polynomial parametrisation, so "
        r"a non-rational {thing} can only approximate it."),
    "variation diminishing": (
        r"**Variation diminishing** holds for every curve type here (with positive "
        r"weights): a line crosses the curve at most as often as the control polygon.",
        r"**Variation diminishing** does not carry over to surfaces: there is no "
        r"counterpart of it for tensor-product patches."),
}


#: What each property needs, as the worked solutions reason: None (every type here has it),
#: or the trait that decides it and whether the type must have it ("spline": a B-spline or
#: NURBS; "rational": with weights; "surface").
_NEEDS = {
    "convex hull": None,
    "affine invariance": None,
    "endpoint interpolation": None,
    "strong convex hull": ("spline", True),
    "local control": ("spline", True),
    "independent degree": ("spline", True),
    "pseudo-local control": ("spline", False),
    "projective invariance": ("rational", True),
    "exact conics": ("rational", True),
    "variation diminishing": ("surface", False),
}
#: How many properties of the menu a question shows.
_SHOWN = 6


def _traits(kind):
    """{"spline", "rational", "surface"} -> whether `kind` has it, read from its name."""
    return {"spline": "B-spline" in kind or "NURBS" in kind,
            "rational": "rational" in kind or "NURBS" in kind,
            "surface": kind.endswith("surface")}


def _property_reason(name, kind, holds):
    """Why property `name` holds (holds=True) or fails for `kind`: a sentence for feedback."""
    if_holds, if_fails = _PROPERTY_REASONS[name]
    thing = "surface" if kind.endswith("surface") else "curve"
    return (if_holds if holds else if_fails).replace("{thing}", thing)


def _normalise_property(text):
    name = " ".join(text.strip().lower().replace("-", " ").replace("_", " ").split())
    name = name.removesuffix(" property")
    name = name.replace("pseudo local", "pseudo-local")
    aliases = {"end point interpolation": "endpoint interpolation",
               "endpoints interpolation": "endpoint interpolation",
               "affine": "affine invariance", "projective": "projective invariance",
               "conics": "exact conics", "local": "local control"}
    return aliases.get(name, name)


class CurveProperties(_Chapter7):
    r"""Which of the listed properties hold for a given kind of curve or surface.

    Each question shows 6 of the 10 properties of :data:`PROPERTY_MENU` (at least one that holds
    and one that does not); the answer is the set of those that hold (a property of the menu
    that is not shown may be listed too when it holds). Each property missing or wrongly
    claimed is explained. Its diagnosis is ``"missing: <name>"`` or
    ``"extra: <name>"`` for the first such property in menu order.

    Attributes: ``kind`` (e.g. ``"NURBS curve"``), ``menu`` (the names of the properties shown).

    Examples
    --------
    >>> ex = CurveProperties(seed=2)
    >>> len(ex.menu), ex.check(sorted(ex.expected)).status
    (6, 'correct')
    >>> extra = next(name for name in ex.menu if name not in ex.expected)
    >>> ex.check(sorted(ex.expected | {extra})).diagnosis == "extra: " + extra
    True
    >>> ex.check(["convex hull", "smoothness"]).status
    'invalid'
    """

    title = "Which properties hold?"
    answer_form = "custom"

    def draw(self, rng):
        self.kind = str(pick(rng, _KINDS))
        names = tuple(PROPERTY_MENU)
        chosen = set(rng.choice(len(names), size=_SHOWN, replace=False).tolist())
        self.menu = tuple(name for k, name in enumerate(names) if k in chosen)
        self.expected = _properties_of(self.kind) & set(self.menu)

    def acceptable(self):
        return 1 <= len(self.expected) <= len(self.menu) - 1

    def hints(self):
        traits = _traits(self.kind)
        words = [("a spline (B-spline or NURBS)" if traits["spline"] else
                  "a Bézier type, one polynomial piece"),
                 "rational (it has weights)" if traits["rational"] else "not rational",
                 "a surface" if traits["surface"] else "a curve"]
        return [
            r"Sort the type by three questions: is it a spline (B-spline, NURBS) or a Bézier "
            r"type? Does it have weights (rational)? Is it a curve or a surface? Each property "
            r"depends on one of these, or holds for every type here.",
            r"Every type here has convex hull, affine invariance and endpoint interpolation "
            r"(clamped knots). Strong convex hull, local control and independent degree come "
            r"with splines, pseudo-local control with Bézier types; projective invariance and "
            r"exact conics need weights; variation diminishing holds for curves only.",
            f"A {self.kind} is " + ", ".join(words) + ". Go down the list with that.",
        ]

    def worked(self):
        traits = _traits(self.kind)
        steps = [f"A {self.kind}: spline {'yes' if traits['spline'] else 'no'}, rational "
                 f"{'yes' if traits['rational'] else 'no'}, surface "
                 f"{'yes' if traits['surface'] else 'no'}."]
        holding = []
        for name in self.menu:
            need = _NEEDS[name]
            holds = need is None or traits[need[0]] == need[1]
            if holds:
                holding.append(name)
            steps.append(("Yes: " if holds else "No: ")
                         + _property_reason(name, self.kind, holds))
        return Worked(steps, sorted(holding))

    def separated(self, mistakes):
        return True

    def _read(self, answer):
        form = ("Give a list of property names from the table, e.g. "
                f"`{[self.menu[0]]!r}` (`[]` if none holds).")
        return read_names(answer, tuple(PROPERTY_MENU), form,
                          "is not a property of the menu. The names are:", _normalise_property)

    def _judge(self, answer):
        names = self._read(answer)
        if isinstance(names, Feedback):
            return names
        # A property of the full menu that the table does not show may be named too: one that
        # holds is simply true (it is not asked about), one that fails is an error.
        holds = _properties_of(self.kind)
        wrong = [name for name in PROPERTY_MENU
                 if ((name in names) != (name in self.expected) if name in self.menu
                     else name in names and name not in holds)]
        if not wrong:
            return Feedback("correct", f"Exactly these {len(self.expected)} properties of the "
                            f"table hold for a {self.kind}.")
        first = wrong[0]
        key = ("missing: " if first in self.expected else "extra: ") + first
        missing = [n for n in wrong if n in self.expected]
        extra = [n for n in wrong if n not in self.expected]
        summary = []
        if missing:
            summary.append("Missing: " + ", ".join(f"`{n}`" for n in missing))
        if extra:
            summary.append(("should" if missing else "Should") + " not be there: "
                           + ", ".join(f"`{n}`" for n in extra))
        reasons = " ".join(_property_reason(n, self.kind, n in self.expected) for n in wrong)
        return Feedback("wrong", f"{'; '.join(summary)}. {reasons}", key)

    def statement(self):
        rows = "\n".join(f"| `{name}` | {PROPERTY_MENU[name]} |" for name in self.menu)
        article = "an" if self.kind[0] in "AEIOU" else "a"
        return (
            rf"Which of the following properties hold for {article} **{self.kind}**? "
            r"B-splines and NURBS have clamped knot vectors, rational types have positive "
            r"weights, and each B-spline has more control points than its degree plus one." "\n\n"
            "| name | meaning |\n|---|---|\n" + rows + "\n\n"
            r"**Answer:** the list of the names of all properties in the table that hold, "
            f"spelled as in the table, e.g. `{[self.menu[0]]!r}` (the order does not matter)."
            "\n\n"
            + data_note("kind", "menu"))
