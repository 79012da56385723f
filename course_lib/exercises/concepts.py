r"""Concept questions: multiple-choice and true/false questions on what to know by heart.

Besides the numeric exercises of each chapter, the exam asks for facts: which properties an
affine or a projective map keeps, which clipping algorithm clips what against what, which
properties a Bézier, B-spline or NURBS curve has, what the Euler characteristic of a closed
manifold mesh is, which Phong term depends on the viewer, and so on. Each
:class:`ConceptQuestion` asks one such fact, with an explanation for *every* option: why it is
right, or why it is wrong. :data:`QUESTIONS` holds them per chapter; :func:`questions` lists
them.

An answer is given as the option's index (counted from 0), its letter (``"a"`` or ``"B"``) or
its text; a true/false question also takes ``True``/``False`` and ``"true"``, ``"t"``,
``"false"``, ``"f"``. ``check`` never raises: an unanswered ``...`` or ``None`` gives the same
"not answered yet" as the exercises, an unreadable answer says which forms are accepted, and a
wrong option is answered with its explanation followed by the right option's.
"""
from dataclasses import dataclass

import numpy as np

from .core import UNANSWERED, Feedback, is_unanswered

__all__ = ["KINDS", "QUESTIONS", "ConceptQuestion", "questions"]

#: The kinds of concept question.
KINDS = ("multiple choice", "true/false")
#: The options of every true/false question, in this order.
TRUE_FALSE = ("True", "False")
_LETTERS = "abcdefghijklmnopqrstuvwxyz"
_TRUE_WORDS = {"true": 0, "t": 0, "false": 1, "f": 1}


@dataclass(frozen=True)
class ConceptQuestion:
    r"""One multiple-choice or true/false question, with an explanation for every option.

    Parameters
    ----------
    chapter : int
        The chapter the question belongs to.
    key : str
        A unique, stable identifier, such as ``"ch07-bezier-convex-hull"``.
    kind : {"multiple choice", "true/false"}
    prompt : str
        The question (Markdown, may contain LaTeX).
    options : tuple of str
        The options, distinct; ``("True", "False")`` for a true/false question.
    correct : int
        The index of the right option (counted from 0).
    explanations : tuple of str
        One per option: why that option is right or wrong.

    Raises
    ------
    ValueError, TypeError
        When the fields are inconsistent (an explanation missing, options repeated, ``correct``
        out of range, a true/false question whose options are not ``("True", "False")``).

    Examples
    --------
    >>> q = ConceptQuestion(
    ...     chapter=3, key="demo-identity", kind="true/false",
    ...     prompt="The identity matrix is a rotation.", options=("True", "False"),
    ...     correct=0, explanations=("It rotates by angle 0.", "Angle 0 is a rotation too."))
    >>> q.check(True).status, q.check("t").status, q.check("b").status
    ('correct', 'correct', 'wrong')
    >>> q.check(...).status, q.check("maybe").status
    ('unanswered', 'invalid')
    >>> print(q.check(False))
    Not yet: *(b) False* is not right: Angle 0 is a rotation too. The right answer is *(a) True*: It rotates by angle 0.
    """

    chapter: int
    key: str
    kind: str
    prompt: str
    options: tuple
    correct: int
    explanations: tuple

    def __post_init__(self):
        if isinstance(self.chapter, bool) or not isinstance(self.chapter, (int, np.integer)):
            raise TypeError(f"chapter must be an integer, got {self.chapter!r}")
        if not isinstance(self.key, str) or not self.key:
            raise TypeError(f"key must be a non-empty string, got {self.key!r}")
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, got {self.kind!r}")
        object.__setattr__(self, "options", tuple(self.options))
        object.__setattr__(self, "explanations", tuple(self.explanations))
        if not all(isinstance(o, str) and o.strip() for o in self.options):
            raise TypeError(f"{self.key}: options must be non-empty strings")
        if self.kind == "true/false" and self.options != TRUE_FALSE:
            raise ValueError(f"{self.key}: a true/false question has the options {TRUE_FALSE}")
        if not 2 <= len(self.options) <= len(_LETTERS):
            raise ValueError(f"{self.key}: options must hold 2 to 26 options")
        if len({_norm(o) for o in self.options}) != len(self.options):
            raise ValueError(f"{self.key}: options must be distinct")
        if len(self.explanations) != len(self.options) or not all(
                isinstance(e, str) and e.strip() for e in self.explanations):
            raise ValueError(f"{self.key}: explanations must hold one non-empty string per "
                             "option")
        if isinstance(self.correct, bool) or not isinstance(self.correct, (int, np.integer)) \
                or not 0 <= self.correct < len(self.options):
            raise ValueError(f"{self.key}: correct must be an option index in "
                             f"0..{len(self.options) - 1}, got {self.correct!r}")

    # -- reading an answer -------------------------------------------------------------------

    @property
    def letters(self):
        """The letters of the options: ``("a", "b", ...)``."""
        return tuple(_LETTERS[:len(self.options)])

    def _label(self, i):
        return f"*({_LETTERS[i]}) {self.options[i]}*"

    def accepted_forms(self):
        """A sentence saying which answers this question understands (Markdown)."""
        n = len(self.options)
        forms = (f"the letter of an option (`\"a\"` to `\"{_LETTERS[n - 1]}\"`), its index "
                 f"counted from 0 (`0` to `{n - 1}`), or its text")
        if self.kind == "true/false":
            forms = ("`True` or `False` (also `\"true\"`, `\"t\"`, `\"false\"`, `\"f\"`), "
                     + forms)
        return f"Answer with {forms}."

    def read(self, answer):
        """The option index `answer` stands for, or None when it cannot be read.

        Examples
        --------
        >>> q = QUESTIONS[7][0]
        >>> q.read(q.letters[1].upper()) == q.read(1) == q.read(q.options[1]) == 1
        True
        >>> q.read("zz") is None, q.read(2.5) is None
        (True, True)
        """
        n = len(self.options)
        if isinstance(answer, (bool, np.bool_)):
            if self.kind != "true/false":
                return None
            return 0 if answer else 1
        if isinstance(answer, (int, np.integer, float, np.floating)):
            if float(answer).is_integer() and 0 <= answer < n:
                return int(answer)
            # a number that is not an index may be an option's text ("15" cases)
            text = f"{float(answer):g}"
            return next((i for i, o in enumerate(self.options) if _norm(o) == text), None)
        if not isinstance(answer, str):
            return None
        text = _norm(answer)
        if self.kind == "true/false" and text in _TRUE_WORDS:
            return _TRUE_WORDS[text]
        for i, option in enumerate(self.options):
            if text == _norm(option):
                return i
        letter = text.strip("()").rstrip(").")
        if len(letter) == 1 and letter in _LETTERS[:n]:
            return _LETTERS.index(letter)
        return None

    def check(self, answer):
        """Judge `answer`; never raises.

        Parameters
        ----------
        answer : int, str or bool
            An option's index (from 0), letter or text; ``True``/``False`` for a true/false
            question.

        Returns
        -------
        Feedback
            Correct: the right option's explanation. Wrong: the chosen option's explanation
            (why it is wrong) and the right one's; the diagnosis is ``"option <letter>"``.

        Examples
        --------
        >>> q = QUESTIONS[3][0]
        >>> q.check(q.correct).status, q.check(None).status, q.check([1]).status
        ('correct', 'unanswered', 'invalid')
        """
        if is_unanswered(answer):
            return Feedback("unanswered", UNANSWERED)
        try:
            i = self.read(answer)
        except Exception:                   # a checker must never stop the notebook
            i = None
        if i is None:
            return Feedback("invalid", f"Cannot tell which option {answer!r} means. "
                            + self.accepted_forms(), "unreadable")
        right = self.correct
        if i == right:
            return Feedback("correct", f"{self._label(right)}: {self.explanations[right]}")
        return Feedback("wrong", f"{self._label(i)} is not right: {self.explanations[i]} "
                        f"The right answer is {self._label(right)}: "
                        f"{self.explanations[right]}", f"option {_LETTERS[i]}")

    # -- display -----------------------------------------------------------------------------

    def markdown(self):
        """The question with its lettered options, as Markdown.

        Examples
        --------
        >>> print(QUESTIONS[7][0].markdown().splitlines()[0])  # doctest: +ELLIPSIS
        **Chapter 7, ...
        """
        head = "true or false?" if self.kind == "true/false" else "multiple choice"
        lines = [f"**Chapter {self.chapter}, {head}** `{self.key}`", "", self.prompt, ""]
        lines += [f"- **({letter})** {option}" for letter, option in
                  zip(self.letters, self.options)]
        return "\n".join(lines)

    def _repr_markdown_(self):
        return self.markdown()

    def show(self):
        """Display the question in a notebook (print it elsewhere); returns None."""
        try:
            from IPython.display import Markdown, display
        except ImportError:                 # pragma: no cover - IPython is a dependency
            print(self.markdown())
        else:
            display(Markdown(self.markdown()))

    def __repr__(self):
        return f"ConceptQuestion({self.key!r})"


def _norm(text):
    """`text` lower-cased with runs of white space made single, for comparing answers."""
    return " ".join(str(text).split()).lower()


def questions(chapter=None):
    """The concept questions of one chapter, or of every chapter, as a list.

    Parameters
    ----------
    chapter : int, optional
        One of the keys of :data:`QUESTIONS`; all chapters in order when omitted.

    Returns
    -------
    list of ConceptQuestion

    Raises
    ------
    ValueError
        For a chapter without concept questions.

    Examples
    --------
    >>> len(questions(7)) >= 8, len(questions()) == sum(map(len, QUESTIONS.values()))
    (True, True)
    """
    if chapter is None:
        return [q for ch in sorted(QUESTIONS) for q in QUESTIONS[ch]]
    if isinstance(chapter, bool) or not isinstance(chapter, (int, np.integer)) \
            or int(chapter) not in QUESTIONS:
        raise ValueError(f"chapter must be one of {sorted(QUESTIONS)}, got {chapter!r}")
    return list(QUESTIONS[int(chapter)])


# ---------------------------------------------------------------------------------------------
# The questions
# ---------------------------------------------------------------------------------------------

def _mc(chapter, key, prompt, *options_and_why, correct):
    """A multiple-choice question from (option, explanation) pairs."""
    options = tuple(o for o, _ in options_and_why)
    why = tuple(w for _, w in options_and_why)
    return ConceptQuestion(chapter, key, "multiple choice", prompt, options, correct, why)


def _tf(chapter, key, statement, truth, if_true, if_false):
    """A true/false question: `if_true` explains the option True, `if_false` the option False."""
    return ConceptQuestion(chapter, key, "true/false", statement, TRUE_FALSE,
                           0 if truth else 1, (if_true, if_false))


_ALL = []

_ALL += [
    _mc(3, "ch03-affine-preserves",
        "Which property does **every** affine map of the plane preserve?",
        ("Lengths of segments", "A shear or a non-uniform scaling changes lengths; only rigid "
         "motions keep them."),
        ("Ratios of lengths along one line", "An affine map sends $(1-t)A + tB$ to "
         "$(1-t)A' + tB'$, so a point that divides a segment in the ratio $t : 1-t$ still does "
         "after the map; in particular midpoints go to midpoints."),
        ("Angles between lines", "A shear turns a right angle into an oblique one; angles are "
         "kept by similarities only."),
        ("Areas", "A scaling by 2 in both directions multiplies every area by 4; an affine map "
         "multiplies areas by $|\\det A|$, which is 1 only for some maps."),
        correct=1),
    _tf(3, "ch03-affine-parallel",
        "An affine transformation maps parallel lines to parallel lines.", True,
        "Two parallel lines $p + t\\vec d$ and $q + t\\vec d$ become $Ap + \\vec t + tA\\vec d$ "
        "and $Aq + \\vec t + tA\\vec d$: the same direction $A\\vec d$, so they stay parallel.",
        "They do stay parallel: both images have the direction $A\\vec d$. It is the "
        "*perspective* projection that makes parallel lines meet at a vanishing point."),
    _mc(3, "ch03-translation-linear",
        "Why does computer graphics use $4 \\times 4$ homogeneous matrices for 3D points?",
        ("Because rotations cannot be written as $3 \\times 3$ matrices",
         "Rotations, scalings and shears are all linear and fit in a $3 \\times 3$ matrix."),
        ("To make the matrices invertible",
         "A $3 \\times 3$ rotation or scaling matrix is invertible already; the extra row does "
         "not change invertibility."),
        ("To store the colour of the point in the fourth coordinate",
         "The fourth coordinate $w$ is not a colour: it is 1 for points and 0 for directions."),
        ("Because a translation is not linear, but becomes a matrix product with the extra "
         "coordinate", "A translation moves the origin, so no $3 \\times 3$ matrix does it; with "
         "$w = 1$ the last column adds the displacement, and every affine map (and the "
         "projections) composes by matrix products."),
        correct=3),
    _tf(3, "ch03-compose-commute",
        "Rotating and then translating a point gives the same result as translating and then "
        "rotating it.", False,
        "Not in general: $R\\,T \\ne T\\,R$. Rotating first leaves the displacement unchanged, "
        "translating first makes the rotation swing the displacement around the origin too.",
        "Right: matrix products do not commute, so the order matters. $T R$ rotates about the "
        "origin and then moves; $R T$ moves and then rotates the moved point about the origin."),
    _mc(3, "ch03-inverse-rotation",
        "What is the inverse of a rotation matrix $R$?",
        ("$R^T$, its transpose", "A rotation matrix is orthogonal (its columns are orthonormal), "
         "so $R^T R = I$: the transpose undoes it, as does rotating by $-\\theta$."),
        ("$-R$", "Not in general: $(-R)R = -R^2$, which is not the identity. In 3D it never is "
         "($-R^2$ has determinant $-1$; $-R$ is a rotation combined with a point reflection "
         "through the origin). In 2D a turn by $\\pm 90°$ has $R^2 = -I$, so there $-R$ happens "
         "to be the inverse, because it equals $R^T$; the transpose is the rule that always "
         "works."),
        ("$R$ itself", "Only rotations by $0$ or by $\\pi$ are their own inverse."),
        ("It has none: rotations are not invertible", "Every rotation is invertible: rotate back "
         "by the opposite angle."),
        correct=0),
    _tf(3, "ch03-quat-double-cover",
        "The unit quaternions $q$ and $-q$ represent the same rotation.", True,
        "In $q\\,p\\,\\bar q$ the two signs cancel: $(-q)\\,p\\,(-\\bar q) = q\\,p\\,\\bar q$. "
        "Geometrically, $-q$ is the rotation by $2\\pi - \\theta$ about $-\\hat n$, which is the "
        "same rotation.",
        "They do: the sign cancels in $q\\,p\\,\\bar q$ (unit quaternions cover each rotation "
        "twice)."),
    _mc(3, "ch03-quat-half-angle",
        "Which unit quaternion rotates by the angle $\\theta$ about the unit axis $\\hat n$?",
        ("$(\\cos\\theta,\\ \\sin\\theta\\,\\hat n)$", "This is the classic slip: it rotates "
         "by $2\\theta$, because $q$ acts twice in $q\\,p\\,\\bar q$."),
        ("$(\\sin\\tfrac\\theta2,\\ \\cos\\tfrac\\theta2\\,\\hat n)$", "Sine and cosine are "
         "swapped: with $\\theta = 0$ this is not the identity quaternion $(1, \\vec 0)$."),
        ("$(\\cos\\tfrac\\theta2,\\ \\sin\\tfrac\\theta2\\,\\hat n)$", "The half angle is used "
         "because the sandwich $q\\,p\\,\\bar q$ applies $q$ twice; for $\\theta = 0$ it gives "
         "the identity $(1, \\vec 0)$."),
        ("$(\\theta,\\ \\hat n)$", "That is the axis-angle pair, not a unit quaternion (its "
         "length is not 1)."),
        correct=2),
    _tf(3, "ch03-quat-commute",
        "Quaternion multiplication is commutative: $q_1 q_2 = q_2 q_1$.", False,
        "It is not: the vector part of the product contains $\\vec v_1 \\times \\vec v_2$, which "
        "changes sign when the factors are swapped, just as rotations about different axes do "
        "not commute.",
        "Right: the cross product in the vector part flips sign with the order, so "
        "$q_1 q_2 \\ne q_2 q_1$ in general (they agree when the vector parts are parallel)."),
    _mc(3, "ch03-quat-matrix-entry",
        "In the rotation matrix of the unit quaternion $(s, x, y, z)$, what is the top-left "
        "entry?",
        ("$1 - 2y^2$", "A term is missing (this typo circulates in old notes): for a rotation "
         "about $z$ by $\\theta$ the entry must be $\\cos\\theta$, and $1 - 2y^2 = 1$ there."),
        ("$1 - 2x^2 - 2y^2$", "That is the bottom-right entry $r_{22}$, the one that involves "
         "the two axes other than $z$."),
        ("$s^2 + x^2 + y^2 + z^2$", "That is the squared length, 1 for every unit quaternion: "
         "the entry would always be 1."),
        ("$1 - 2y^2 - 2z^2$", "For a rotation about $z$ by $\\theta$, $z = \\sin\\tfrac\\theta2$ "
         "and the entry is $1 - 2\\sin^2\\tfrac\\theta2 = \\cos\\theta$, as it must be."),
        correct=3),
    _mc(3, "ch03-quat-advantage",
        "Which is a real advantage of unit quaternions over rotation matrices?",
        ("Rotating a single point costs fewer multiplications",
         "It costs more: the sandwich $q\\,p\\,\\bar q$ needs two quaternion products (even "
         "optimized, about twice the 9 multiplications of a $3 \\times 3$ matrix times a "
         "vector); convert to a matrix to rotate many points."),
        ("Composing two rotations is cheaper and the result is easy to renormalize; they "
         "interpolate smoothly (slerp)", "A quaternion product takes 16 multiplications against "
         "27 for a $3 \\times 3$ matrix product, rounding errors are removed by dividing by the "
         "length, and slerp interpolates at constant angular speed."),
        ("They also represent translations", "A unit quaternion only rotates; a translation "
         "still needs a vector or a homogeneous matrix."),
        ("Their product is commutative", "It is not: $q_1 q_2 \\ne q_2 q_1$ in general."),
        correct=1),
]

_ALL += [
    _mc(4, "ch04-projective-preserves",
        "Which property does a perspective (projective) map preserve?",
        ("Ratios of distances along a line", "Not kept: equal steps along a rail look shorter "
         "further away, because each point is divided by its own depth."),
        ("Parallelism", "Parallel lines that are not parallel to the image plane meet at a "
         "vanishing point."),
        ("Straight lines, and the cross ratio of four collinear points",
         "A projective map sends lines to lines, and the cross ratio of four points on a line "
         "is the one ratio it keeps."),
        ("Angles", "Angles are not kept even by affine maps, let alone projective ones."),
        correct=2),
    _tf(4, "ch04-perspective-ratios",
        "The midpoint of a 3D segment projects, under a perspective projection, to the midpoint "
        "of the projected segment.", False,
        "Not in general: the end nearer the eye is magnified more (division by its depth), so "
        "the projected midpoint moves towards the far end. It is right only when both ends have "
        "the same depth.",
        "Right: perspective does not preserve ratios along a line. This is why attributes must "
        "be interpolated perspective-correctly (interpolate $a/w$ and $1/w$)."),
    _tf(4, "ch04-affine-cross-ratio",
        "Every affine map also preserves the cross ratio of four collinear points.", True,
        "An affine map preserves ordinary ratios along a line, and the cross ratio is a ratio of "
        "such ratios; affine maps are a special case of projective ones.",
        "It does preserve it: affine maps keep ratios along a line, hence also the cross ratio "
        "built from them."),
    _mc(4, "ch04-parallel-vs-perspective",
        "What distinguishes a parallel projection from a perspective projection?",
        ("The centre of projection is at infinity, so the projectors are parallel",
         "With the centre infinitely far away, all projecting lines share one direction; sizes "
         "no longer depend on the distance to the viewer."),
        ("It needs a homogeneous divide by $z$", "That is the perspective projection; a "
         "parallel projection leaves $w = 1$."),
        ("Its projectors always hit the plane at an oblique angle",
         "Orthographic projection is parallel with projectors perpendicular to the plane; only "
         "oblique projection uses slanted ones."),
        ("It makes distant objects smaller", "That is foreshortening, the mark of perspective."),
        correct=0),
    _mc(4, "ch04-oblique",
        "What is an oblique projection?",
        ("A perspective projection with a tilted image plane", "It has no centre of projection "
         "at a finite distance: it is parallel."),
        ("A parallel projection whose direction is not perpendicular to the projection plane",
         "Cavalier and cabinet views are examples: the plane faces the viewer, and depth shows "
         "as a slanted offset."),
        ("An orthographic projection onto one of the coordinate planes",
         "That is orthographic: its direction is the plane's normal."),
        ("A projection that keeps the $z$ coordinate unchanged", "An oblique projection onto "
         "the $xy$-plane shifts $x$ and $y$ by amounts proportional to $z$ and sets $z$ to 0."),
        correct=1),
    _mc(4, "ch04-ecs-axes",
        "Given the view direction $\\vec g$ and the up vector $\\vec{up}$ (not necessarily "
        "perpendicular to $\\vec g$), how are the eye-space axes found?",
        ("$z_e = \\vec g$, $x_e = \\vec g \\times \\vec{up}$, $y_e = \\vec{up}$",
         "The eye looks down $-z_e$, so $z_e$ is $-\\vec g$; and $\\vec{up}$ need not be "
         "perpendicular to the view direction, so it cannot be used as $y_e$ directly."),
        ("$z_e = -\\hat g$, $x_e = \\vec{up} \\times z_e$ normalized, $y_e = z_e \\times x_e$",
         "This gives a right-handed orthonormal frame in which the eye looks down $-z_e$; $y_e$ "
         "is the part of $\\vec{up}$ perpendicular to the view direction."),
        ("$x_e = \\vec{up}$, $y_e = \\vec g$, $z_e = x_e \\times y_e$", "The up vector "
         "becomes the vertical axis, not the horizontal one, and again it need not be "
         "perpendicular to $\\vec g$."),
        ("The eye axes are always the world axes; only the origin moves", "The camera may "
         "look in any direction: the axes rotate with it."),
        correct=1),
    _tf(4, "ch04-perspective-depth-nonlinear",
        "After a perspective projection matrix and the homogeneous divide, the depth value in "
        "canonical screen space is a linear function of the eye-space depth $z_e$.", False,
        "It is not: it has the form $a + b/z_e$, so it is spread very unevenly (most of the "
        "range goes to depths near the near plane). It is still monotonic, which is all the "
        "z-buffer needs.",
        "Right: the stored depth is $a + b / z_e$, a monotonic but non-linear function; this is "
        "why a near plane very close to the eye wastes z-buffer precision."),
    _mc(4, "ch04-fov",
        "A symmetric perspective view volume has vertical field of view $\\theta$, aspect ratio "
        "$a$ (width/height) and near plane at distance $n$. What is its top $t$ at the near "
        "plane?",
        ("$t = n \\tan\\theta$", "The full angle $\\theta$ spans from bottom to top; the top "
         "edge is only half of it above the axis."),
        ("$t = a\\, n \\tan\\tfrac\\theta2$", "The aspect ratio gives the right edge "
         "$r = a\\,t$, not the top."),
        ("$t = n \\sin\\tfrac\\theta2$", "The half height is the side opposite the half angle "
         "in a right triangle whose adjacent side is $n$: that is a tangent."),
        ("$t = n \\tan\\tfrac\\theta2$", "Half the field of view lies above the viewing axis, "
         "and at distance $n$ the opposite side is $n\\tan\\tfrac\\theta2$; then $b = -t$, "
         "$r = a\\,t$, $l = -r$."),
        correct=3),
    _tf(4, "ch04-clip-before-divide",
        "Clipping against the view volume is done in homogeneous clip coordinates, before the "
        "division by $w$.", True,
        "Before the divide the view volume is $-w \\le x, y, z \\le w$ and clipping is linear; "
        "points behind the eye have $w < 0$ and would be folded in front of it by the divide.",
        "It is done before: after dividing, points behind the eye would be mirrored into the "
        "view (their $w$ is negative) and could no longer be told apart."),
    _mc(4, "ch04-viewport",
        "The viewport transformation maps canonical screen space $[-1, 1]^2$ to the window "
        "$[x_{min}, x_{max}] \\times [y_{min}, y_{max}]$. What is it?",
        ("A rotation followed by a projection", "Nothing rotates: the two rectangles are axis "
         "aligned."),
        ("A scaling by half the window size and a translation to the window centre",
         "$x_v = \\tfrac{x_{max} - x_{min}}2 x + \\tfrac{x_{max} + x_{min}}2$ and likewise for "
         "$y$ (depth uses its own range, not the $y$ range)."),
        ("A perspective divide", "The divide happened before; the viewport map is affine."),
        ("A scaling by the full window size, without translation", "$[-1, 1]$ is 2 wide, so "
         "the factor is half the window size, and the centre $0$ must move to the window "
         "centre."),
        correct=1),
]

_ALL += [
    _mc(5, "ch05-backface-sign",
        "A closed opaque mesh has outward normals $\\vec n$. With $\\vec v$ the vector **from "
        "the eye to a point of a face**, when is the face a back face?",
        ("When $\\vec v \\cdot \\vec n < 0$", "Then the normal points towards the eye: the face "
         "is turned to the viewer (a front face). The sign is often stated the wrong way round."),
        ("When $\\vec v \\cdot \\vec n = 1$", "The test is about the sign of the dot product, "
         "not its size."),
        ("When $\\vec v \\cdot \\vec n > 0$", "The normal points away from the eye, along the "
         "line of sight: the face shows its back and is hidden by the front of the same closed "
         "object."),
        ("When $\\vec v \\times \\vec n = \\vec 0$", "Parallel vectors mean the face is seen "
         "straight on or straight from behind; the cross product cannot tell which."),
        correct=2),
    _tf(5, "ch05-backface-enough",
        "For a single closed convex object, back-face culling alone solves hidden-surface "
        "removal.", True,
        "On a convex closed object every front face is fully visible and every back face is "
        "hidden, and no two front faces overlap on screen.",
        "For one convex closed object it does suffice; for non-convex objects or several "
        "objects, front faces can hide each other and a z-buffer (or similar) is needed."),
    _tf(5, "ch05-backface-open",
        "Back-face culling can safely be used on an open surface such as a single sheet of "
        "paper.", False,
        "It cannot: the back of an open surface can be seen directly (nothing of the same "
        "object hides it), so culling would make it disappear.",
        "Right: culling relies on the object being closed and opaque, so that the front of the "
        "object always covers its back."),
    _mc(5, "ch05-cohen-sutherland",
        "In Cohen-Sutherland line clipping the end points get outcodes $c_1$ and $c_2$. What "
        "can be concluded when $c_1 \\wedge c_2 \\ne 0$ (bitwise AND)?",
        ("The segment lies entirely inside the window", "That is the case $c_1 \\vee c_2 = 0$: "
         "both end points inside."),
        ("The segment crosses the window and must be clipped", "When the AND is zero and the OR "
         "is not, it *may* cross: it has to be clipped to find out."),
        ("The segment lies entirely outside: reject it", "Both end points are on the outer side "
         "of the same boundary line (plane), so the whole segment is too."),
        ("Nothing: the outcodes must be recomputed", "The AND test is exactly the trivial "
         "reject test; no recomputation is needed."),
        correct=2),
    _tf(5, "ch05-cs-or-nonzero",
        "If the AND of the two outcodes is zero, the segment intersects the clipping window.",
        False,
        "Not necessarily: a segment from just above the window to just right of it can pass "
        "outside the corner, though its end points lie outside different boundaries. Such "
        "segments are clipped step by step and rejected later.",
        "Right: a zero AND only rules out the trivial rejection; a segment can still pass by a "
        "corner of the window."),
    _mc(5, "ch05-which-clipper",
        "Which algorithm clips a **polygon** against a convex clip region, one boundary at a "
        "time, producing a new polygon?",
        ("Liang-Barsky", "Liang-Barsky clips a line segment, using its parametric form and the "
         "entering/leaving parameters."),
        ("Cohen-Sutherland", "Cohen-Sutherland clips line segments using outcodes."),
        ("Ray casting", "Ray casting finds the nearest surface per pixel; it does not clip."),
        ("Sutherland-Hodgman", "It passes the polygon's vertex list through one clipper per "
         "boundary (plane), each emitting the inside vertices and the crossing points."),
        correct=3),
    _mc(5, "ch05-liang-barsky",
        "What does Liang-Barsky compute for the segment $p(t) = p_0 + t(p_1 - p_0)$, "
        "$t \\in [0, 1]$?",
        ("The largest entering parameter $t_E$ and the smallest leaving parameter $t_L$; the "
         "segment is rejected when $t_E > t_L$", "Each boundary gives one inequality in $t$; the "
         "visible part is $[t_E, t_L]$ (starting from $[0, 1]$)."),
        ("The outcodes of the two end points", "That is Cohen-Sutherland."),
        ("The smallest entering and the largest leaving parameter", "The other way round: the "
         "segment is inside only after it has entered through *all* boundaries (largest entry) "
         "and before it leaves through *any* (smallest exit)."),
        ("The intersection of the segment with each polygon edge", "That is closer to "
         "Sutherland-Hodgman's per-edge work; Liang-Barsky clips against an axis-aligned box."),
        correct=0),
    _tf(5, "ch05-occlusion-conservative",
        "Occlusion culling is conservative: it may keep primitives that turn out hidden, but it "
        "never removes a visible one.", True,
        "Culling only discards what is certainly hidden; whatever it leaves is resolved by the "
        "z-buffer, so an extra primitive costs time but never a wrong picture.",
        "It must be conservative: removing a visible primitive would leave a hole in the image, "
        "while keeping a hidden one only costs time."),
    _mc(5, "ch05-zbuffer",
        "Which statement about the z-buffer algorithm is right?",
        ("It needs the polygons sorted by depth", "It does not: each pixel keeps the nearest "
         "depth so far, so polygons can come in any order."),
        ("Its cost grows with the number of primitives and pixels covered, and it needs one "
         "depth value of memory per pixel", "It processes each primitive once, compares depth "
         "per covered pixel, and stores a depth buffer next to the colour buffer."),
        ("It handles transparent surfaces correctly in any order", "It keeps one surface per "
         "pixel; transparency needs sorting or special techniques."),
        ("It works in object space with exact precision", "It works in image space, with a "
         "depth resolution limited by the buffer's bits (z-fighting)."),
        correct=1),
    _mc(5, "ch05-raycasting-cost",
        "Brute-force ray casting for hidden-surface elimination tests every pixel's ray against "
        "every primitive. With $p$ pixels and $P$ primitives its cost is:",
        ("$O(p + P)$", "Every ray meets every primitive: the costs multiply, they do not add."),
        ("$O(p \\log P)$", "That needs an acceleration structure (a BVH, a grid) which brute "
         "force does not have."),
        ("$O(pP)$", "One intersection test per pixel and primitive; it is, however, trivially "
         "parallel across pixels."),
        ("$O(P^2)$", "Primitives are not tested against each other."),
        correct=2),
    _tf(5, "ch05-painter-cycles",
        "The painter's algorithm (draw back to front) can fail for polygons that overlap each "
        "other cyclically.", True,
        "Three polygons can each lie partly in front of the next; no drawing order is right, "
        "and polygons must be split (as a BSP tree does).",
        "It can fail: cyclic overlap has no valid back-to-front order, so polygons must be "
        "split first."),
]

_ALL += [
    _mc(6, "ch06-manifold-edge",
        "In a closed 2-manifold polygon mesh, how many faces share each edge?",
        ("Exactly two", "Around every point the surface looks like a disk, so an edge has one "
         "face on each side; a boundary edge (one face) only appears on a surface with a "
         "boundary."),
        ("At least two", "Three or more faces at an edge (a 'fin') make the mesh non-manifold: "
         "no disk-shaped neighbourhood around the edge."),
        ("One or two", "One face means a boundary edge: the mesh would not be closed."),
        ("Any number, as long as the faces are triangles", "The face type does not matter; "
         "the count does."),
        correct=0),
    _tf(6, "ch06-euler-sphere",
        "Every closed polyhedral mesh that is topologically a sphere satisfies "
        "$V - E + F = 2$.", True,
        "A cube gives $8 - 12 + 6 = 2$, a tetrahedron $4 - 6 + 4 = 2$: the Euler "
        "characteristic depends only on the topology, not on the tessellation.",
        "It does hold for all of them (cube, tetrahedron, any triangulated sphere)."),
    _mc(6, "ch06-euler-genus",
        "A closed orientable manifold mesh has genus $g$ (number of handles, a torus has 1). "
        "What is $V - E + F$?",
        ("$2 + 2g$", "The sign is wrong: each handle *lowers* the Euler characteristic by 2."),
        ("$2 - g$", "Each handle lowers it by 2, not by 1."),
        ("$2 - 2g$", "A sphere gives 2, a torus 0, a two-holed torus $-2$."),
        ("Always 2", "Only for genus 0; a torus gives 0."),
        correct=2),
    _tf(6, "ch06-closed-triangle-count",
        "In a closed triangle mesh that is a 2-manifold, $3F = 2E$.", True,
        "Each triangle has 3 edges and each edge is shared by exactly 2 triangles, so counting "
        "edge-face incidences gives $3F = 2E$.",
        "It holds: 3 edges per triangle, 2 triangles per edge."),
    _mc(6, "ch06-halfedge-stores",
        "What does a half-edge typically store?",
        ("Its two end vertices, both faces and four neighbouring edges",
         "That is a winged edge; a half-edge keeps only one side of the edge."),
        ("Only the coordinates of its end points", "Then no neighbourhood could be walked "
         "without a search."),
        ("A list of all faces of the mesh", "That would cost $O(F)$ per edge."),
        ("The vertex it points to (or starts from), its face, the next half-edge around that "
         "face, and its twin", "With these the one-ring of a vertex or the loop of a face is "
         "walked in constant time per step: next, twin, next, ..."),
        correct=3),
    _tf(6, "ch06-halfedge-twin",
        "In a half-edge mesh, the twin of the twin of a half-edge is the half-edge itself.", True,
        "Each edge is split into two oppositely oriented halves that point to each other.",
        "It is: twin is an involution, the two halves of one edge refer to each other."),
    _tf(6, "ch06-halfedge-nonmanifold",
        "A plain half-edge structure can represent an edge shared by three faces.", False,
        "It cannot: an edge has exactly two halves, one per side, so a third face has no "
        "half-edge to use. Half-edge meshes are limited to (possibly bounded) manifolds.",
        "Right: two halves per edge means at most two faces per edge: non-manifold edges do "
        "not fit."),
    _mc(6, "ch06-edge-collapse",
        "Iterative edge collapse with the quadric error metric (QEM): which edge is collapsed "
        "next?",
        ("The longest edge", "Length alone ignores the shape: a long edge on a flat region "
         "can be removed cheaply, a short one on a sharp feature cannot."),
        ("The edge whose collapse adds the least error, i.e. the smallest quadric cost",
         "Edges sit in a priority queue keyed by the error of the best new vertex position; "
         "after each collapse the costs of the neighbouring edges are updated."),
        ("The edge furthest from the viewer", "View-dependent simplification exists, but QEM "
         "ranks edges by geometric error."),
        ("A random edge", "Random collapses destroy features; QEM orders them by cost."),
        correct=1),
    _mc(6, "ch06-qem-meaning",
        "What does the quadric of a vertex measure in QEM simplification?",
        ("The sum of squared distances from a point to the planes of the faces around the "
         "original vertex", "The quadric $Q$ is a sum of plane terms; $v^T Q v$ is that sum of "
         "squared distances, and minimizing it gives the new vertex position."),
        ("The curvature of the surface", "It is related, but it measures squared distances to "
         "planes, not curvature directly."),
        ("The number of faces around the vertex", "That is the valence."),
        ("The length of the collapsed edge", "The cost is a distance to planes, not the edge "
         "length."),
        correct=0),
    _tf(6, "ch06-volume-needs-closed",
        "A solid (volume) representation can be built only for an object whose surface is "
        "closed.", True,
        "Inside and outside are only defined when the surface encloses a region.",
        "It is needed: an open surface does not separate inside from outside."),
]

_ALL += [
    _tf(7, "ch07-bezier-convex-hull",
        "Every point of a Bézier curve lies in the convex hull of its control points.", True,
        "The Bernstein polynomials are non-negative on $[0, 1]$ and sum to 1, so each curve "
        "point is a convex combination of the control points.",
        "It holds for every Bézier curve: its points are weighted averages of the control "
        "points with non-negative weights that sum to 1."),
    _mc(7, "ch07-bezier-endpoints",
        "Which control points does a Bézier curve of degree $n$ pass through?",
        ("All of them", "Inner control points only pull the curve; in general it misses them."),
        ("The first and the last", "At $t = 0$ only $B_0^n$ is non-zero and at $t = 1$ only "
         "$B_n^n$: the curve interpolates its end points."),
        ("None of them", "It does pass through the first and last."),
        ("Only the middle one", "Inner points are generally missed."),
        correct=1),
    _mc(7, "ch07-bezier-tangent",
        "What is the tangent (derivative) of a degree-$n$ Bézier curve at $t = 0$?",
        ("$P_1 - P_0$", "The direction is right but the length lacks the factor $n$."),
        ("$n(P_n - P_0)$", "That joins the end points; the end tangent only involves the first "
         "edge of the control polygon."),
        ("$P_0$", "That is the point, not the tangent."),
        ("$n(P_1 - P_0)$", "The derivative is $n$ times a Bézier curve of the differences "
         "$P_{i+1} - P_i$; at $t = 0$ only the first difference counts."),
        correct=3),
    _tf(7, "ch07-bezier-affine",
        "Applying an affine map to the control points of a Bézier curve gives the same curve as "
        "applying it to every point of the curve.", True,
        "A curve point is an affine combination of the control points (weights summing to 1), "
        "and affine maps preserve affine combinations.",
        "It holds (affine invariance): weights summing to 1 make the combination commute with "
        "affine maps."),
    _tf(7, "ch07-bezier-projective",
        "A (polynomial) Bézier curve is also invariant under perspective projection: projecting "
        "the control points gives the projected curve.", False,
        "It is not: a perspective map divides each point by its own depth, which does not "
        "commute with weighted averages. Rational Bézier curves are projectively invariant "
        "(the weights absorb the $w$).",
        "Right: polynomial curves are only affinely invariant; rational curves with weights "
        "are also invariant under projective maps."),
    _mc(7, "ch07-bezier-local",
        "Moving one control point of a Bézier curve changes:",
        ("Only the segment between its two neighbours", "That is local control, a B-spline "
         "property."),
        ("Nothing but the tangent at that point", "The curve does not even pass through inner "
         "control points."),
        ("The whole curve (except the end points when the moved point is an inner one), most "
         "strongly near the parameter where its Bernstein polynomial peaks",
         "Every Bernstein polynomial is non-zero on all of $(0, 1)$: control is global, only "
         "'pseudo-local'."),
        ("Only the degree of the curve", "The degree is fixed by the number of control points."),
        correct=2),
    _mc(7, "ch07-variation-diminishing",
        "The variation-diminishing property of a planar Bézier curve says:",
        ("Any straight line crosses the curve at most as often as it crosses the control "
         "polygon", "The curve wiggles no more than its polygon; as a consequence, a convex "
         "control polygon gives a convex curve."),
        ("The curve is shorter than its control polygon's first edge", "There is no such "
         "bound."),
        ("The degree decreases after subdivision", "Subdivision keeps the degree."),
        ("The curve has fewer inflection points than its degree", "The property compares "
         "crossings with lines, not inflections with the degree."),
        correct=0),
    _tf(7, "ch07-bspline-degree",
        "The degree of a B-spline curve is fixed by the number of its control points.", False,
        "It is not: the degree $p$ is chosen freely (below the number of control points); "
        "with $n + 1$ control points and degree $p$ one needs $n + p + 2$ knots. Adding "
        "control points adds segments, not degree.",
        "Right: unlike a Bézier curve, a B-spline keeps its degree when control points are "
        "added: it gets more polynomial pieces instead."),
    _mc(7, "ch07-bspline-local",
        "Moving the control point $P_i$ of a B-spline of degree $p$ changes the curve only "
        "on:",
        ("The whole parameter range", "That is Bézier behaviour; B-spline basis functions have "
         "compact support."),
        ("The knot span $[u_i, u_{i+1})$", "The support of $N_{i,p}$ covers $p + 1$ spans, "
         "not one."),
        ("The $p + 1$ knot spans $[u_i, u_{i+p+1})$ where $N_{i,p}$ is non-zero", "Outside its "
         "support the basis function is zero, so the point has no influence there: local "
         "control."),
        ("The span between $P_{i-1}$ and $P_{i+1}$", "The influence is measured in parameter "
         "(knot spans), and covers $p + 1$ of them."),
        correct=2),
    _tf(7, "ch07-bspline-strong-hull",
        "Each point of a B-spline curve of degree $p$ lies in the convex hull of the $p + 1$ "
        "control points active on its knot span (strong convex hull property).", True,
        "On one span only $p + 1$ basis functions are non-zero, they are non-negative and sum "
        "to 1: a convex combination of those control points.",
        "It holds, and it is stronger than the convex hull of all control points."),
    _mc(7, "ch07-bspline-continuity",
        "A B-spline of degree $p$ has a knot of multiplicity $k$ inside its range. How smooth is "
        "it there?",
        ("$C^{p}$", "Only where there is no knot is the curve infinitely smooth; at a simple "
         "knot it is $C^{p-1}$."),
        ("$C^{p-k}$", "Each repetition of a knot removes one order of continuity; with $k = p$ "
         "the curve is only $C^0$ and passes through a control point."),
        ("$C^{k}$", "Repeating a knot lowers the smoothness, it does not raise it."),
        ("$C^{p+k}$", "The continuity cannot exceed the degree's."),
        correct=1),
    _mc(7, "ch07-rational-circle",
        "Which curves can represent a circular arc **exactly**?",
        ("Polynomial Bézier curves of high enough degree", "No polynomial parametrization "
         "traces a circle exactly; it can only approximate it."),
        ("Uniform B-splines", "They are polynomial piecewise: they also only approximate."),
        ("None: circles must be tessellated", "Rational curves do it exactly."),
        ("Rational Bézier curves and NURBS (for instance a rational quadratic with middle "
         "weight $\\cos\\tfrac\\alpha2$)", "The weights allow exact conic sections; a quarter "
         "circle is a rational quadratic with weights $1, \\tfrac{\\sqrt2}2, 1$."),
        correct=3),
    _tf(7, "ch07-rational-weights-one",
        "A rational Bézier curve whose weights are all equal is the ordinary (polynomial) "
        "Bézier curve of the same control points.", True,
        "With equal weights the denominator $\\sum w B_i^n = w$ is constant and cancels.",
        "It is: equal weights cancel between numerator and denominator."),
    _tf(7, "ch07-surface-variation",
        "Tensor-product Bézier surfaces have the variation-diminishing property, like Bézier "
        "curves.", False,
        "They keep the convex hull, end-point (corner) interpolation and affine invariance, but "
        "no variation-diminishing property is known for them.",
        "Right: it is the property the curves have and the surfaces lack."),
]

_ALL += [
    _mc(10, "ch10-normalize",
        "Data values in $[i_{min}, i_{max}]$ are mapped linearly to $[n_{min}, n_{max}]$. "
        "Which formula?",
        ("$\\frac{i - i_{min}}{i_{max} - i_{min}}(n_{max} - n_{min}) + n_{min}$",
         "First to $[0, 1]$, then stretched to the new width and shifted to start at "
         "$n_{min}$."),
        ("$\\frac{i}{i_{max}}\\, n_{max}$", "It ignores both minimums: right only when both "
         "ranges start at 0."),
        ("$\\frac{i - i_{min}}{i_{max} - i_{min}}(n_{max} - n_{min})$",
         "The shift by $n_{min}$ is missing: the result starts at 0."),
        ("$\\frac{i - i_{min}}{n_{max} - n_{min}}(i_{max} - i_{min}) + n_{min}$",
         "The two widths are swapped."),
        correct=0),
    _tf(10, "ch10-rainbow",
        "The rainbow ('jet') colour map is perceptually uniform: equal steps in the data give "
        "equal perceived colour differences.", False,
        "It is not: its lightness goes up and down (yellow and cyan look bright, blue dark), "
        "creating false bands and hiding real changes. Use viridis-like maps.",
        "Right: jet's lightness is not monotonic, so it invents edges and hides others."),
    _mc(10, "ch10-diverging",
        "Which colour map suits data with a meaningful centre, such as a temperature anomaly "
        "around 0?",
        ("A sequential map (light to dark)", "It suggests an order from low to high, but no "
         "special middle value."),
        ("A qualitative map", "Qualitative maps are for categories without order."),
        ("A diverging map: two hues that meet at a neutral light colour at the centre value",
         "The eye sees at once the sign (hue) and the size (saturation) of the deviation."),
        ("A greyscale map", "Greyscale is sequential: it cannot show the sign around the "
         "centre."),
        correct=2),
    _mc(10, "ch10-qualitative",
        "Which colour map suits **categorical** data (land-use classes, labels)?",
        ("A sequential lightness ramp", "It implies an order the categories do not have."),
        ("A qualitative map of clearly distinct hues of similar lightness", "No class looks "
         "more important or 'larger' than another."),
        ("A diverging map", "It implies a centre and two directions."),
        ("The rainbow map with continuous interpolation", "Interpolating between categories "
         "makes no sense, and it implies order."),
        correct=1),
    _tf(10, "ch10-transfer-function",
        "A transfer function maps data values to visual properties such as colour and "
        "opacity.", True,
        "It is the general mapping; a colour map is a transfer function to colour, and in "
        "volume rendering it gives colour and opacity per sample.",
        "That is what a transfer function is."),
    _tf(10, "ch10-lightness-order",
        "For ordered data a good colour map has a lightness that increases (or decreases) "
        "monotonically.", True,
        "Lightness is the channel we read order from most reliably; a monotonic ramp keeps "
        "the order visible even in greyscale print and for colour-blind viewers.",
        "It is the key design rule of sequential maps (viridis, magma, greys...)."),
    _mc(10, "ch10-colorblind",
        "Which pair of hues is the worst to distinguish important classes for the most common "
        "colour-vision deficiency?",
        ("Blue and orange", "That pair stays distinct for red-green deficiencies; it is a "
         "common safe choice."),
        ("Black and white", "Lightness contrast is seen by everyone."),
        ("Dark blue and light yellow", "They differ strongly in lightness and in the blue-yellow "
         "channel, which red-green deficient viewers keep."),
        ("Red and green of similar lightness", "About 8% of men have a red-green deficiency "
         "and cannot tell these apart."),
        correct=3),
    _tf(10, "ch10-step-transfer",
        "A step (piecewise constant) transfer function can be used to highlight a chosen range "
        "of values.", True,
        "It gives one colour or opacity inside the range and another outside, like a "
        "threshold; smooth ramps avoid the hard edges where needed.",
        "It can: thresholding or banding is exactly a step transfer function."),
    _mc(10, "ch10-log-scale",
        "Data spans six orders of magnitude (from 1 to $10^6$). With a linear colour map, what "
        "happens?",
        ("Nearly all values get the colour of the low end; only the largest ones stand out",
         "Values below $10^4$ occupy 1% of the range; a logarithmic normalization spreads "
         "them out."),
        ("The map works well: linear is always the most honest", "Honest, but it hides all "
         "structure of the small values."),
        ("The values are clipped to $[0, 1]$", "Normalization maps the range, it does not "
         "clip it."),
        ("The colour map becomes diverging", "The kind of map does not change."),
        correct=0),
]

_ALL += [
    _mc(12, "ch12-phong-view-dependent",
        "Which term of the Phong illumination model changes when only the viewer moves?",
        ("The diffuse term", "It depends on $\\vec n \\cdot \\vec l$ only: a matte surface "
         "looks equally bright from every direction."),
        ("The ambient term", "It is a constant $I_a k_a$."),
        ("The specular term", "It depends on the angle between the mirror direction "
         "$\\vec r$ and the direction to the viewer $\\vec v$: the highlight moves with the "
         "eye."),
        ("The emission term", "Emitted light is the same in every direction."),
        correct=2),
    _mc(12, "ch12-diffuse-law",
        "The diffuse term $I_d = I_l k_d \\max(0, \\hat n \\cdot \\hat l)$ follows which law?",
        ("Lambert's cosine law: the irradiance falls with the cosine of the angle of "
         "incidence", "A beam hitting at a slant spreads over a larger area, so each unit area "
         "receives less light."),
        ("Snell's law", "That governs refraction."),
        ("The inverse square law", "Distance attenuation is a separate factor, not the "
         "cosine."),
        ("Fresnel's law", "Fresnel gives how much is reflected versus refracted."),
        correct=0),
    _tf(12, "ch12-specular-exponent",
        "A larger shininess exponent $n$ in $(\\hat r \\cdot \\hat v)^n$ makes the specular "
        "highlight smaller and sharper.", True,
        "Raising a cosine below 1 to a higher power makes it fall off faster away from the "
        "mirror direction: a tighter highlight, like polished metal.",
        "It does: the cosine lobe narrows as the exponent grows."),
    _tf(12, "ch12-ambient-meaning",
        "The ambient term models light that reaches a point after bouncing between other "
        "surfaces, approximated as a constant.", True,
        "Local illumination ignores inter-reflections; the ambient term is a crude constant "
        "stand-in for them, so that unlit sides are not pitch black.",
        "That is exactly its purpose: a constant replacement for indirect light."),
    _mc(12, "ch12-blinn",
        "What does Blinn-Phong use instead of $\\hat r \\cdot \\hat v$?",
        ("$\\hat l \\cdot \\hat v$", "That ignores the surface orientation."),
        ("$\\hat n \\cdot \\hat h$ with the halfway vector $\\hat h = \\frac{\\hat l + \\hat "
         "v}{\\|\\hat l + \\hat v\\|}$", "The highlight peaks when the normal bisects light and "
         "view; it is cheaper (no reflection vector) and behaves better at grazing angles."),
        ("$\\hat n \\cdot \\hat l$", "That is the diffuse factor."),
        ("$\\hat r \\cdot \\hat l$", "Not a meaningful quantity for the highlight."),
        correct=1),
    _mc(12, "ch12-gouraud",
        "Gouraud shading computes lighting at the vertices and interpolates the colours. What is "
        "its typical artefact?",
        ("It cannot show diffuse shading", "Diffuse shading varies slowly and interpolates "
         "well."),
        ("It makes every face a single flat colour", "That is flat shading."),
        ("It is slower than Phong shading", "It is cheaper: lighting per vertex, not per "
         "pixel."),
        ("A specular highlight inside a triangle is missed or smeared, and the highlight "
         "jumps as the mesh moves", "Interpolating colours cannot create a peak that no "
         "vertex sees; Phong shading interpolates normals and lights per pixel."),
        correct=3),
    _tf(12, "ch12-phong-shading-normals",
        "Phong *shading* interpolates the vertex normals across a polygon and evaluates the "
        "lighting at every pixel.", True,
        "That is the difference from Gouraud shading (interpolated colours); the interpolated "
        "normal must be renormalized.",
        "It does; do not confuse the Phong *illumination model* with Phong *shading*, the "
        "interpolation method."),
    _tf(12, "ch12-diffuse-view",
        "Moving the camera changes the diffuse term of the Phong model at a fixed surface "
        "point.", False,
        "It does not: the diffuse term uses only the normal and the light direction.",
        "Right: the diffuse term is view-independent; only the specular term changes."),
    _mc(12, "ch12-ambient-occlusion",
        "What does ambient occlusion compute at a surface point?",
        ("The distance to the light source", "Ambient occlusion ignores the light sources."),
        ("The fraction of the hemisphere above the point that is not blocked by nearby "
         "geometry (usually cosine-weighted)", "Creases and corners see less of the sky and get "
         "darker; the factor scales the ambient term."),
        ("The colour of the nearest object", "Colour bleeding is a global-illumination effect, "
         "not ambient occlusion."),
        ("Whether the point is in the view frustum", "That is frustum culling."),
        correct=1),
    _tf(12, "ch12-negative-dot",
        "When $\\hat n \\cdot \\hat l < 0$ the diffuse and specular terms of that light must be "
        "set to 0.", True,
        "The light is behind the surface; without clamping, a negative cosine would subtract "
        "light.",
        "They must: the light shines on the other side of the surface."),
]

_ALL += [
    _tf(14, "ch14-barycentric-sum",
        "The barycentric coordinates of a point in a triangle are non-negative and sum to 1, "
        "and each equals the area of the opposite sub-triangle divided by the whole area.",
        True,
        "Joining the point to the corners splits the triangle into three parts; the part "
        "opposite a corner, relative to the whole, is that corner's weight.",
        "It holds for points inside (outside, some coordinate turns negative)."),
    _mc(14, "ch14-triangle-interp",
        "How should texture coordinates be interpolated across a single triangle?",
        ("Bilinearly, from the triangle's bounding box", "A triangle has three corners; "
         "bilinear interpolation needs four and depends on the orientation of the box."),
        ("Nearest vertex", "That gives three constant patches, not a smooth mapping."),
        ("With barycentric coordinates (perspective-correct after projection)",
         "They give the unique linear interpolation of the three corner values."),
        ("By the polar angle around the centroid", "That is not a linear interpolation."),
        correct=2),
    _mc(14, "ch14-magnification",
        "A texture is **magnified** (one texel covers many pixels). Which filter removes the "
        "blocky look?",
        ("Mipmapping", "Mipmaps help minification, where many texels fall into one pixel."),
        ("Bilinear interpolation of the four nearest texels", "It blends neighbouring texels "
         "smoothly instead of repeating one."),
        ("Nearest-neighbour sampling", "That is what produces the blocks."),
        ("Supersampling the texture", "There is nothing to average: one texel already covers "
         "many pixels."),
        correct=1),
    _mc(14, "ch14-mipmap",
        "Why are mipmaps used, and what do they cost?",
        ("Against aliasing under minification; about a third more texture memory",
         "Prefiltered half-size levels are chosen by the pixel's footprint; the levels add "
         "$\\tfrac14 + \\tfrac1{16} + \\dots = \\tfrac13$ of the base size."),
        ("Against blockiness under magnification; twice the memory", "Magnification uses the "
         "base level with bilinear filtering; and the overhead is a third, not double."),
        ("To compress textures; they save memory", "They add memory."),
        ("For procedural textures only", "They prefilter image textures."),
        correct=0),
    _tf(14, "ch14-procedural",
        "A procedural texture is computed from a function of the coordinates, so it needs "
        "little memory and has no fixed resolution.", True,
        "It can be evaluated at any point and any scale (and in 3D for solid textures); the "
        "price is computation and harder antialiasing.",
        "It is true: no image is stored."),
    _mc(14, "ch14-mapping-type",
        "Which intermediate surface suits a texture on a bottle or a can?",
        ("Planar", "A plane projects along one direction and smears the texture on the sides."),
        ("Spherical", "Usable, but it distorts a long straight body; the poles squeeze."),
        ("Cube", "Possible, but it has seams at the cube edges around a round body."),
        ("Cylindrical: $u$ from the angle around the axis, $v$ from the height",
         "It matches the shape: a rectangle wrapped around it, with one seam."),
        correct=3),
    _tf(14, "ch14-spherical-poles",
        "A spherical mapping of a rectangular image squeezes the whole top row of the image "
        "into a single point (a pole).", True,
        "At the pole the longitude is undefined: all $u$ values meet there, so the texture is "
        "compressed and distorted near the poles.",
        "It does, for the latitude-longitude (spherical) mapping: the longitude is undefined at "
        "the pole, so the whole top row meets there. That is a property of this mapping, not of "
        "every way to put an image on a sphere: cube maps and octahedral maps have no such "
        "point (they have seams between their faces instead)."),
    _tf(14, "ch14-bump-silhouette",
        "Bump mapping changes the silhouette of an object.", False,
        "It does not: it perturbs only the normals used in lighting; the geometry and thus the "
        "outline stay the same. Displacement mapping moves the surface and changes it.",
        "Right: only the shading normals change, so outlines stay smooth."),
    _mc(14, "ch14-environment",
        "What does environment (reflection) mapping look up in a texture?",
        ("The surface normal as a colour", "That is a normal map."),
        ("The colour seen in the reflected view direction, from an image of the surroundings "
         "(cube or sphere map)", "A cheap imitation of mirror reflections, exact only for "
         "surroundings far away."),
        ("The height of the surface", "That is a displacement or bump map."),
        ("The shadow of the object", "Shadow maps store depths from the light."),
        correct=1),
]

_ALL += [
    _mc(15, "ch15-shadow-ray",
        "In Whitted ray tracing, how is it decided whether a hit point is in shadow for a "
        "point light?",
        ("By the sign of $\\hat n \\cdot \\hat v$", "That says whether the surface faces the "
         "viewer."),
        ("By casting a shadow ray from the point towards the light and checking for a hit "
         "before the light", "If anything lies between, the light's diffuse and specular "
         "contributions are dropped (start slightly off the surface to avoid self-"
         "shadowing)."),
        ("By the depth in the z-buffer", "That is the shadow-map technique of rasterization."),
        ("By the distance to the camera", "Shadows depend on the light, not the camera."),
        correct=1),
    _tf(15, "ch15-whitted-diffuse",
        "Classic (Whitted) recursive ray tracing captures mirror reflections and refraction "
        "but not diffuse inter-reflection (colour bleeding).", True,
        "It spawns only the reflected and refracted rays; diffuse light bouncing between "
        "surfaces needs path tracing or radiosity.",
        "It is true: diffuse inter-reflection is left to the ambient term."),
    _mc(15, "ch15-tir",
        "A ray leaves glass ($n_1 = 1.5$) into air ($n_2 = 1$). When is there no refracted ray?",
        ("Never", "Going from dense to less dense, large angles have no solution of Snell's "
         "law."),
        ("When the angle of incidence exceeds $\\arcsin(n_2 / n_1) \\approx 41.8°$",
         "Snell's law would need $\\sin\\theta_t > 1$: total internal reflection."),
        ("When the angle of incidence is below $41.8°$", "Small angles refract normally."),
        ("Always: light cannot leave glass", "It can, below the critical angle."),
        correct=1),
    _mc(15, "ch15-reflect",
        "The mirror direction of the incoming direction $\\vec d$ at a surface with unit normal "
        "$\\hat n$ is:",
        ("$\\vec d + 2(\\vec d \\cdot \\hat n)\\hat n$", "The sign is wrong: this keeps the "
         "tangential component and triples the normal one ($(\\vec d \\cdot \\hat n)\\hat n$ "
         "becomes $3(\\vec d \\cdot \\hat n)\\hat n$), so the length changes too (unless "
         "$\\vec d$ runs along the surface)."),
        ("$\\vec d - (\\vec d \\cdot \\hat n)\\hat n$", "That removes the normal component: "
         "a projection onto the surface, not a reflection."),
        ("$\\hat n - \\vec d$", "Not a reflection; its length is not even kept."),
        ("$\\vec d - 2(\\vec d \\cdot \\hat n)\\hat n$", "The normal component changes sign, "
         "the tangential one stays: the length is kept."),
        correct=3),
    _tf(15, "ch15-sphere-quadratic",
        "Intersecting a ray $o + t\\vec d$ with a sphere leads to a quadratic equation in $t$; "
        "a negative discriminant means the ray misses.", True,
        "Substituting the ray into $\\|p - C\\|^2 = r^2$ (centre $C$, radius $r$) gives "
        "$at^2 + bt + c = 0$ with $a = \\vec d \\cdot \\vec d$, $b = 2\\,\\vec d \\cdot (o - C)$, "
        "$c = \\|o - C\\|^2 - r^2$; the nearest hit is the smallest positive root.",
        "It is so: no real root, no intersection."),
    _mc(15, "ch15-acceleration",
        "What does a bounding volume hierarchy (BVH) change in ray tracing?",
        ("It makes the image more accurate", "The image is the same; only the speed changes."),
        ("It reduces the intersection tests per ray from linear to roughly logarithmic in the "
         "number of primitives", "A ray skips every subtree whose box it misses."),
        ("It removes the need for shadow rays", "Shadow rays are still cast (and sped up too)."),
        ("It is needed for refraction", "Refraction works without it."),
        correct=1),
    _tf(15, "ch15-recursion-depth",
        "Recursive ray tracing needs a depth limit (or a contribution threshold), because two "
        "facing mirrors would reflect forever.", True,
        "Each reflection spawns another ray; stopping at a maximum depth or when the weight "
        "becomes negligible ends the recursion.",
        "It does: without a limit the recursion may not end."),
    _mc(15, "ch15-antialias",
        "How does a ray tracer reduce jagged edges (aliasing)?",
        ("By tracing several rays per pixel (supersampling, possibly jittered) and averaging",
         "Averaging estimates the pixel's area coverage instead of a single point sample."),
        ("By increasing the recursion depth", "Depth concerns reflections, not edges."),
        ("By using point lights", "Lights do not change the sampling of the pixel."),
        ("By mipmapping the scene", "Mipmaps filter textures, not geometric edges."),
        correct=0),
    _tf(15, "ch15-point-light-hard",
        "With point lights a ray tracer produces soft shadows with penumbrae.", False,
        "A point is either seen from the light or not: shadows are hard. Soft shadows need area "
        "lights sampled with several shadow rays.",
        "Right: a single shadow ray per point light gives hard shadow edges."),
    _mc(15, "ch15-primary-rays",
        "How many primary rays does a basic ray tracer cast?",
        ("One per light source", "Shadow rays go to lights; primary rays go through pixels."),
        ("One per primitive", "That is object-order thinking (rasterization)."),
        ("One per pixel, from the eye through the pixel centre", "Every pixel gets its colour "
         "from the nearest hit of its primary ray and the rays spawned there."),
        ("One for the whole image", "Each pixel needs its own ray."),
        correct=2),
]

_ALL += [
    _mc(18, "ch18-ms-ambiguous",
        "How many of the 16 marching-squares cases are ambiguous?",
        ("None", "The saddle cases are ambiguous."),
        ("Four", "Only the two checkerboard patterns are ambiguous."),
        ("Eight", "Most cases have a single way to connect the crossings."),
        ("Two: the diagonal cases, where opposite corners are inside", "Both the 'joined' and "
         "the 'separated' pair of segments are consistent with the corner signs; the cell "
         "average (or the asymptotic decider) chooses."),
        correct=3),
    _mc(18, "ch18-mc-cases",
        "Marching cubes has $2^8 = 256$ corner configurations. Using rotations and swapping "
        "inside with outside, how many distinct cases remain?",
        ("8", "Far too few: the cases differ in how many and which corners are inside."),
        ("256", "Symmetry collapses most of them."),
        ("15", "The classic table of 15 base cases (including the empty one) generates all "
         "256."),
        ("23", "That is the count with rotations only, without complementation."),
        correct=2),
    _tf(18, "ch18-mc-holes",
        "The original marching-cubes table can produce holes in the surface, because "
        "neighbouring cubes may resolve an ambiguous shared face differently.", True,
        "On a face with a saddle pattern the two cubes must agree on the connection; the "
        "asymptotic decider or extended tables fix this.",
        "It can: this is the known face-ambiguity problem of marching cubes."),
    _tf(18, "ch18-streamline-tangent",
        "A streamline is everywhere tangent to the velocity field at one instant.", True,
        "That is its definition; in a steady flow streamlines, pathlines and streaklines "
        "coincide.",
        "It is the definition of a streamline."),
    _tf(18, "ch18-streamlines-cross",
        "Two different streamlines of a steady, smooth vector field can cross at a point where "
        "the velocity is non-zero.", False,
        "They cannot: at such a point the field has one direction, and the solution through it "
        "is unique. Streamlines only meet at critical points (zero velocity).",
        "Right: uniqueness of solutions forbids crossings away from critical points."),
    _mc(18, "ch18-euler-integration",
        "Streamlines of a pure rotation $v = (-y, x)$ are circles. What does explicit Euler "
        "integration produce?",
        ("Exact circles", "Euler steps along the tangent leave the circle at every step."),
        ("An inward spiral", "Each tangent step moves *outward*: $|p + h v|^2 = (1 + h^2)|p|^2$."),
        ("An outward spiral: the radius grows by $\\sqrt{1 + h^2}$ per step",
         "A first-order method drifts; Runge-Kutta 4 is far more accurate for the same step."),
        ("A straight line", "It turns, though not enough."),
        correct=2),
    _mc(18, "ch18-front-to-back",
        "Why composite volume samples front to back in ray casting?",
        ("It allows early ray termination: stop once the accumulated opacity is close to 1",
         "Samples behind an almost opaque layer cannot change the pixel."),
        ("It gives a different (more correct) image than back to front", "Both orders give "
         "the same result, with the matching formulas."),
        ("It avoids the transfer function", "The transfer function is still needed to classify "
         "samples."),
        ("It makes the volume transparent", "Opacity comes from the transfer function."),
        correct=0),
    _tf(18, "ch18-isosurface-vs-dvr",
        "Direct volume rendering needs an intermediate polygonal surface, as marching cubes "
        "does.", False,
        "It does not: it casts rays through the volume and composites the colours and "
        "opacities of the samples; marching cubes extracts a surface.",
        "Right: direct volume rendering works on the samples, without polygons."),
    _mc(18, "ch18-ms-interp",
        "Where does marching squares put the isoline's crossing on a cell edge with corner "
        "values $f_0$ and $f_1$?",
        ("At the edge midpoint, always", "That is the cheap variant; it gives jagged lines."),
        ("At $t = \\frac{c - f_0}{f_1 - f_0}$ from the first corner (linear interpolation)",
         "Where the linear interpolation of the corner values equals the isovalue $c$."),
        ("At the corner with the larger value", "The crossing lies between the corners."),
        ("At $t = \\frac{f_1 - c}{f_1 - f_0}$", "Measured from the first corner this is "
         "$1 - t$: the crossing lands mirrored."),
        correct=1),
    _tf(18, "ch18-glyph-clutter",
        "Arrow glyphs drawn at every grid point of a dense vector field give the clearest "
        "picture.", False,
        "Dense glyphs overlap and clutter the view; subsample, or use streamlines or texture "
        "methods (LIC) for dense fields.",
        "Right: glyphs must be spaced out; otherwise they clutter."),
]

QUESTIONS = {}
for _q in _ALL:
    QUESTIONS.setdefault(_q.chapter, [])
    QUESTIONS[_q.chapter].append(_q)
QUESTIONS = {ch: tuple(QUESTIONS.get(ch, ())) for ch in (3, 4, 5, 6, 7, 10, 12, 14, 15, 18)}
del _q
