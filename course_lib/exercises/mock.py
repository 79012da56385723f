r"""Mock exams: a balanced, seeded set of questions drawn from every chapter.

:func:`mock_exam` picks ``n_questions`` questions spread evenly over the chosen chapters (their
counts differ by at most one), mixing the chapters' numeric exercises (the classes in each
``course_lib.exercises.chNN.EXERCISES``, each drawn with a variant seed of its own) with their
concept questions (:mod:`course_lib.exercises.concepts`). The same ``seed`` always gives the
same exam. The chapters are discovered, not listed: every module ``chNN`` of this package with
an ``EXERCISES`` list, and every chapter with concept questions.

Each :class:`ExamQuestion` renders its prompt as Markdown and checks an answer with the checker
of the exercise or concept question it wraps, so the feedback is the same diagnosis a student
gets in the exercise notebooks. An answer typed into a text field is read by
:func:`read_answer` (``"[[1, 0], [0, 1]]"``, ``"1, 2, 3"``, ``"sqrt(2)/2"``, ``"1 0; 0 1"``,
``"'rejected'"``) without ever calling :func:`eval`. :class:`Exam` keeps the feedback of each
submitted answer, the score per chapter and the questions to revisit; :mod:`course_lib.progress`
stores its :meth:`Exam.record`.
"""
import ast
import importlib
import math
import pkgutil
import re
import zlib

import numpy as np

from .core import Feedback, quietly

__all__ = ["Exam", "ExamQuestion", "available_chapters", "mock_exam", "read_answer",
           "study_plan"]

#: Module names of the chapters' exercises: ``ch03``, ``ch07``, ...
_CHAPTER_MODULE = re.compile(r"ch(\d\d)")
#: How the note that ends most exercise statements begins: it points at the exercise object's
#: attributes, which mean nothing in an exam typed into a text field.
_DATA_NOTE = "*The numbers of this question are the attributes"
#: The longest typed answer read (a matrix of a few hundred numbers is far shorter).
MAX_ANSWER_CHARS = 20_000
#: What an empty answer gets in an exam (there is no ``...`` to replace there).
UNANSWERED_HERE = ("Nothing to grade yet: type your answer (or choose an option) and submit "
                   "it.")
#: The most questions an exam may have.
MAX_QUESTIONS = 200

_FUNCTIONS = {"sqrt": math.sqrt, "sin": math.sin, "cos": math.cos, "tan": math.tan,
              "asin": math.asin, "acos": math.acos, "atan": math.atan, "atan2": math.atan2,
              "exp": math.exp, "log": math.log, "radians": math.radians,
              "degrees": math.degrees, "abs": abs}
_CONSTANTS = {"pi": math.pi, "e": math.e}
_ARRAY_CALLS = {"array", "asarray", "matrix"}
_BINARY = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b,
           ast.Mult: lambda a, b: a * b, ast.Div: lambda a, b: a / b,
           ast.Pow: lambda a, b: a ** b}


# ---------------------------------------------------------------------------------------------
# Reading a typed answer
# ---------------------------------------------------------------------------------------------

def _arith(node):
    """The value of an arithmetic expression tree made of whitelisted parts only."""
    if isinstance(node, ast.Expression):
        return _arith(node.body)
    if isinstance(node, ast.Constant) and isinstance(node.value, (int, float, str)) \
            and not isinstance(node.value, bool):
        return node.value
    if isinstance(node, ast.Constant) and isinstance(node.value, bool):
        return node.value
    if isinstance(node, (ast.List, ast.Tuple)):
        return [_arith(item) for item in node.elts]
    if isinstance(node, ast.Set):
        return {_arith(item) for item in node.elts}
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.UAdd, ast.USub)):
        value = float(_arith(node.operand))
        return -value if isinstance(node.op, ast.USub) else value
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        left, right = float(_arith(node.left)), float(_arith(node.right))
        if isinstance(node.op, ast.Pow) and abs(right) > 64:
            raise ValueError("exponent too large")
        return float(_BINARY[type(node.op)](left, right))
    if isinstance(node, ast.Name) and node.id in _CONSTANTS:
        return _CONSTANTS[node.id]
    if isinstance(node, ast.Call) and not node.keywords:
        name = _call_name(node.func)
        if name in _ARRAY_CALLS and len(node.args) == 1:        # np.array([...]) pasted
            return _arith(node.args[0])
        if name in _FUNCTIONS:
            return float(_FUNCTIONS[name](*(float(_arith(a)) for a in node.args)))
    raise ValueError(f"not allowed in an answer: {type(node).__name__}")


def _call_name(func):
    """``sqrt`` for ``sqrt``, ``np.sqrt``, ``math.sqrt`` and ``numpy.sqrt``; else None."""
    if isinstance(func, ast.Name):
        return func.id
    if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) \
            and func.value.id in ("np", "numpy", "math"):
        return func.attr
    return None


def _number(token):
    """A whole number as int (outcodes, indices, counts), any other number as float."""
    try:
        return int(token)
    except ValueError:
        return float(token)


def _number_rows(text):
    """``"1 0; 0 1"`` or lines of numbers as nested lists; None unless all are numbers."""
    rows = [row for row in re.split(r"[;\n]", text) if row.strip()]
    try:
        values = [[_number(tok) for tok in re.split(r"[,\s]+", row.strip()) if tok]
                  for row in rows]
    except ValueError:
        return None
    if not values or not all(values):
        return None
    if len(values) == 1:
        return values[0] if len(values[0]) > 1 else values[0][0]
    return values


def read_answer(text):
    r"""Read an answer typed as text into a Python value, safely (never with :func:`eval`).

    Tried in order: a Python literal (:func:`ast.literal_eval`: numbers, strings, nested lists
    and tuples, sets); numbers separated by spaces or commas, with rows separated by ``;`` or
    new lines (``"1 -2"`` is two numbers, not a difference); arithmetic with ``+ - * / **``,
    ``pi``, ``e`` and the functions ``sqrt``, ``sin``, ``cos``, ``tan``, ``asin``, ``acos``,
    ``atan``, ``atan2``, ``exp``, ``log``, ``radians``, ``degrees``, ``abs`` (also written
    ``np.sqrt`` or ``math.sqrt``), and a pasted ``np.array(...)``; words separated by commas
    (a list of strings); otherwise the text itself, stripped.

    Parameters
    ----------
    text : str
        What the student typed.

    Returns
    -------
    object
        None for an empty text (the question counts as not answered).

    Raises
    ------
    TypeError
        If `text` is not a string.

    Examples
    --------
    >>> read_answer("[[1, 0], [0, 1]]")
    [[1, 0], [0, 1]]
    >>> read_answer("1, 2, 3"), read_answer("1 0; 0 1"), read_answer("0.5 -2")
    ((1, 2, 3), [[1, 0], [0, 1]], [0.5, -2])
    >>> read_answer("[sqrt(2)/2, -1/2]")
    [0.7071067811865476, -0.5]
    >>> read_answer("closed manifold"), read_answer("convex hull, affine invariance")
    ('closed manifold', ['convex hull', 'affine invariance'])
    >>> read_answer("__import__('os').system('ls')")       # not run: kept as text
    "__import__('os').system('ls')"
    >>> read_answer("  ") is None
    True
    """
    if not isinstance(text, str):
        raise TypeError(f"text must be a string, got {type(text).__name__}")
    text = text.strip()
    if not text:
        return None
    if len(text) > MAX_ANSWER_CHARS:
        return text
    try:
        return ast.literal_eval(text)
    except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
        pass
    rows = _number_rows(text)              # before arithmetic: "1 -2" is [1, -2], not -1
    if rows is not None:
        return rows
    try:
        return _arith(ast.parse(text, mode="eval"))
    except (ValueError, TypeError, SyntaxError, ArithmeticError, MemoryError, RecursionError):
        pass
    if "," in text:
        parts = [part.strip().strip("'\"").strip() for part in text.split(",")]
        if all(re.fullmatch(r"[\w][\w\s.+-]*", part) for part in parts):
            return parts
    return text


# ---------------------------------------------------------------------------------------------
# The pool of questions
# ---------------------------------------------------------------------------------------------

def _exercise_modules():
    """{chapter: module name} of every ``chNN`` module of this package."""
    from . import __path__ as package_path

    found = {}
    for info in pkgutil.iter_modules(package_path):
        match = _CHAPTER_MODULE.fullmatch(info.name)
        if match:
            found[int(match.group(1))] = info.name
    return dict(sorted(found.items()))


def _numeric_pool():
    """{chapter: tuple of Exercise classes} for every chapter module with exercises."""
    pool = {}
    for chapter, name in _exercise_modules().items():
        module = importlib.import_module(f"{__package__}.{name}")
        classes = tuple(getattr(module, "EXERCISES", ()))
        if classes:
            pool[chapter] = classes
    return pool


def _concept_pool():
    """{chapter: tuple of ConceptQuestion}; empty while the concepts module does not exist."""
    try:
        concepts = importlib.import_module(f"{__package__}.concepts")
    except ModuleNotFoundError as exc:
        if exc.name != f"{__package__}.concepts":
            raise
        return {}
    return {int(ch): tuple(qs) for ch, qs in sorted(concepts.QUESTIONS.items()) if qs}


def available_chapters():
    """The chapters a mock exam can draw from, with how many questions of each kind they have.

    Returns
    -------
    dict
        ``{chapter: {"numeric": number of exercise classes, "concept": number of concept
        questions}}``, in chapter order.

    Examples
    --------
    >>> chapters = available_chapters()
    >>> 7 in chapters and chapters[7]["numeric"] > 0
    True
    """
    numeric, concept = _numeric_pool(), _concept_pool()
    return {ch: {"numeric": len(numeric.get(ch, ())), "concept": len(concept.get(ch, ()))}
            for ch in sorted(set(numeric) | set(concept))}


# ---------------------------------------------------------------------------------------------
# Questions and exams
# ---------------------------------------------------------------------------------------------

class ExamQuestion:
    r"""One question of a mock exam: a seeded numeric exercise or a concept question.

    Parameters
    ----------
    chapter : int
    source : Exercise or ConceptQuestion
        What the question asks and how it is checked.

    Attributes
    ----------
    chapter : int
    kind : {"numeric", "concept"}
    key : str
        A stable name: ``"ch07.DeCasteljauPoint"`` for an exercise (with :attr:`seed` it
        rebuilds the question), the concept question's key otherwise.
    seed : int or None
        The exercise's variant; None for a concept question.
    title : str
    options : tuple of str or None
        A concept question's options (None for an exercise).

    Examples
    --------
    >>> from course_lib.exercises import ch03
    >>> q = ExamQuestion(3, ch03.ShearedBoxVolume(seed=5))
    >>> q.kind, q.key, q.seed
    ('numeric', 'ch03.ShearedBoxVolume', 5)
    >>> q.check(str(float(q.source.expected))).status, q.check("").status
    ('correct', 'unanswered')
    """

    def __init__(self, chapter, source):
        self.chapter = int(chapter)
        self.source = source
        self.options = getattr(source, "options", None)
        if self.options is not None:
            self.kind, self.key, self.seed = "concept", source.key, None
            self.title = ("True or false?" if source.kind == "true/false"
                          else "Multiple choice")
        else:
            self.kind, self.seed = "numeric", int(source.seed)
            self.key = f"ch{self.chapter:02d}.{type(source).__name__}"
            self.title = source.title

    @property
    def label(self):
        """A short name for lists of questions: ``'Chapter 7: <title> (variant 12)'``."""
        variant = f" (variant {self.seed})" if self.seed is not None else f" ({self.key})"
        return f"Chapter {self.chapter}: {self.title}{variant}"

    def markdown(self):
        """The question as Markdown (LaTeX inside), as the exam shows it."""
        if self.kind == "concept":
            lines = [f"**Chapter {self.chapter} · {self.title}**", "", self.source.prompt, ""]
            lines += [f"- **({letter})** {option}"
                      for letter, option in zip(self.source.letters, self.options)]
            return "\n".join(lines)
        paragraphs = self.source.statement().split("\n\n")
        statement = "\n\n".join(p for p in paragraphs
                                if not p.lstrip().startswith(_DATA_NOTE)).rstrip()
        return f"**Chapter {self.chapter} · {self.title}**\n\n{statement}"

    def _repr_markdown_(self):
        return self.markdown()

    def check(self, answer):
        """Judge `answer` with the checker of the exercise or concept question; never raises.

        A string is read with :func:`read_answer` first (a concept question first tries the
        text as it is: an option's letter or wording).

        Parameters
        ----------
        answer : object
            A value, or the text typed into the exam's answer field.

        Returns
        -------
        Feedback
        """
        try:
            feedback = None
            if isinstance(answer, str):
                if self.kind == "concept" and answer.strip():
                    feedback = self.source.check(answer.strip())
                    if feedback.status == "invalid":
                        feedback = None
                answer = read_answer(answer)
            if feedback is None:
                with quietly():              # the exam keeps its own record
                    feedback = self.source.check(answer)
        except Exception as exc:             # a checker must never stop the exam
            return Feedback("invalid", f"Your answer could not be checked ({exc}); give it in "
                            "the form the question asks for.", "unreadable")
        if feedback.status == "unanswered":
            return Feedback("unanswered", UNANSWERED_HERE)
        return feedback

    def __repr__(self):
        return f"ExamQuestion({self.label!r})"


class Exam:
    """A mock exam: its questions, the feedback on the answers submitted, the scores.

    Made by :func:`mock_exam`. Submit an answer with :meth:`submit` (the last submission of a
    question counts); :meth:`score` gives the score per chapter, :meth:`to_revisit` the
    questions not answered right, :meth:`record` a summary for :mod:`course_lib.progress`.

    Parameters
    ----------
    seed : int
    chapters : sequence of int
    questions : sequence of ExamQuestion

    Examples
    --------
    >>> exam = mock_exam(seed=1, chapters=[3, 7], n_questions=4)
    >>> len(exam), exam.finished
    (4, False)
    >>> _ = [exam.submit(i, "") for i in range(len(exam))]
    >>> exam.finished, exam.total()
    (True, (0, 4))
    """

    def __init__(self, seed, chapters, questions):
        self.seed = int(seed)
        self.chapters = tuple(int(c) for c in chapters)
        self.questions = list(questions)
        self.feedback = [None] * len(self.questions)
        #: The :func:`study_plan` the questions were drawn by (None: a balanced exam).
        self.plan = None

    def __len__(self):
        return len(self.questions)

    def __getitem__(self, index):
        return self.questions[index]

    def __iter__(self):
        return iter(self.questions)

    def submit(self, index, answer):
        """Check `answer` to question `index`, keep the feedback and return it.

        Raises
        ------
        IndexError
            If `index` is not a question of the exam.
        """
        if isinstance(index, bool) or not isinstance(index, (int, np.integer)) \
                or not 0 <= index < len(self.questions):
            raise IndexError(f"index must be a question number in 0..{len(self) - 1}, "
                             f"got {index!r}")
        feedback = self.questions[index].check(answer)
        self.feedback[index] = feedback
        return feedback

    @property
    def finished(self):
        """Whether every question has been submitted (an empty answer counts as submitted)."""
        return all(f is not None for f in self.feedback)

    def credit(self, index):
        """The marks question `index` earned, 0 to 1: partial for a multi-part answer."""
        feedback = self.feedback[index]
        return 0.0 if feedback is None else float(feedback.credit)

    def score(self):
        """``{chapter: (right, total)}`` over the exam's questions, in chapter order.

        ``right`` sums the credit of each answer: 1 for a right one, the share of its parts
        that are right for a multi-part answer (partial credit), 0 otherwise; a whole number
        when every credit is.
        """
        result = {}
        for k, question in enumerate(self.questions):
            right, total = result.get(question.chapter, (0, 0))
            result[question.chapter] = (right + self.credit(k), total + 1)
        return {ch: (_tidy(r), t) for ch, (r, t) in sorted(result.items())}

    def total(self):
        """``(right, total)`` over the whole exam (right with partial credit)."""
        scores = self.score().values()
        return _tidy(sum(r for r, _ in scores)), sum(t for _, t in scores)

    def to_revisit(self):
        """The questions not answered fully right (wrong, partly right, unreadable or not
        answered), in order."""
        return [q for k, q in enumerate(self.questions) if self.credit(k) < 1]

    def record(self):
        """A JSON-ready summary: seed, chapters, score per chapter and questions to revisit.

        Returns
        -------
        dict
            ``seed``, ``chapters``, ``n_questions``, ``score`` (``{str(chapter): [right,
            total]}``), ``revisit`` (a list of ``{"chapter", "key", "seed", "label"}``) and
            ``questions`` (every question's ``chapter``, ``key``, ``seed`` and ``credit``: what
            the next exam's :func:`study_plan` reads).
        """
        return {
            "seed": self.seed,
            "chapters": list(self.chapters),
            "n_questions": len(self.questions),
            "score": {str(ch): [r, t] for ch, (r, t) in self.score().items()},
            "revisit": [{"chapter": q.chapter, "key": q.key, "seed": q.seed, "label": q.label}
                        for q in self.to_revisit()],
            "questions": [{"chapter": q.chapter, "key": q.key, "seed": q.seed,
                           "credit": round(self.credit(k), 4)}
                          for k, q in enumerate(self.questions)],
        }

    def __repr__(self):
        right, total = self.total()
        return (f"Exam(seed={self.seed}, chapters={list(self.chapters)}, "
                f"{len(self)} questions, {right}/{total} right so far)")


def _tidy(x):
    """`x` as an int when it is a whole number (scores without partial credit stay ints)."""
    return int(round(x)) if abs(x - round(x)) < 1e-9 else round(float(x), 4)


# ---------------------------------------------------------------------------------------------
# Spaced review: what the history says to ask
# ---------------------------------------------------------------------------------------------

#: A chapter's weight in an adaptive exam: 1 + WEAK_WEIGHT * (share not right); a chapter with
#: no results yet weighs UNKNOWN_WEIGHT.
WEAK_WEIGHT, UNKNOWN_WEIGHT = 2.0, 1.5
#: After this many right answers in a row a question leaves the review (Leitner boxes 1, 2, 3:
#: due again 2, 4 and 8 exams later).
REVIEW_BOXES = 3


def _chapter_of(key):
    match = re.match(r"ch(\d\d)\.", key) if isinstance(key, str) else None
    return int(match.group(1)) if match else None


def study_plan(history):
    """What a history of results says the next exam should ask: weak chapters, due reviews.

    Spaced review (Leitner's boxes): a question answered wrong (in an exam, or an exercise
    checked in a notebook) comes back in the next exam, in a new variant; each right answer
    after that puts it further off (due again 2, then 4 exams later) until, after
    :data:`REVIEW_BOXES` right answers, it leaves the review. A chapter weighs
    ``1 + 2 * (share not right)`` over its exam questions and first tries of exercises.

    Parameters
    ----------
    history : list of dict
        Records from :func:`course_lib.progress.read_events` (or only exams, oldest first).

    Returns
    -------
    dict
        ``weights`` ({chapter: weight} for chapters with results), ``due`` (keys due now, in
        the order they fell due, each with its ``chapter`` and the ``seen`` variants) and
        ``exams`` (how many exams the history holds).

    Examples
    --------
    >>> wrong = {"kind": "attempt", "key": "ch05.Outcodes", "seed": 3, "status": "wrong"}
    >>> plan = study_plan([wrong])
    >>> [d["key"] for d in plan["due"]], plan["weights"]
    (['ch05.Outcodes'], {5: 3.0})
    >>> later = {"kind": "attempt", "key": "ch05.Outcodes", "seed": 8, "status": "correct"}
    >>> study_plan([wrong, later])["due"]          # right once: due again 2 exams later
    []
    """
    exams, boxes, seen, tally = 0, {}, {}, {}

    def outcome(key, seed, right, chapter, first=True):
        seen.setdefault(key, set()).add(seed)
        if chapter is not None and first:
            r, t = tally.get(chapter, (0.0, 0))
            tally[chapter] = (r + right, t + 1)
        if right < 1:
            boxes[key] = (0, exams + 1)
        elif key in boxes:
            box = boxes[key][0] + 1
            if box >= REVIEW_BOXES:
                del boxes[key]
            else:
                boxes[key] = (box, exams + 2 ** box)

    tried = set()
    for event in history:
        kind = event.get("kind", "exam")
        if kind == "exam":
            exams += 1
            questions = event.get("questions")
            if questions is None:          # an older record: only the wrong ones are listed
                questions = [{**q, "credit": 0.0} for q in event.get("revisit", ())]
            for q in questions:
                outcome(q.get("key"), q.get("seed"), float(q.get("credit", 0.0)),
                        q.get("chapter"))
        elif kind == "attempt" and event.get("status") in ("correct", "wrong"):
            variant = (event.get("key"), event.get("seed"))
            outcome(variant[0], variant[1], float(event["status"] == "correct"),
                    _chapter_of(variant[0]), first=variant not in tried)
            tried.add(variant)
    weights = {ch: 1.0 + WEAK_WEIGHT * (1.0 - r / t) for ch, (r, t) in sorted(tally.items())
               if t}
    due = [{"key": key, "chapter": _chapter_of(key), "seen": sorted(
            (s for s in seen.get(key, ()) if s is not None), key=repr)}
           for key, (box, when) in boxes.items() if when <= exams + 1 and key is not None]
    return {"weights": weights, "due": due, "exams": exams}


def _weighted_counts(rng, chapters, n, weights):
    """How many questions each chapter gets, in proportion to its weight (at least one each
    while there are enough questions); the largest remainders get the rest, ties by `rng`."""
    w = np.array([weights.get(ch, UNKNOWN_WEIGHT) for ch in chapters], dtype=float)
    place = np.argsort(rng.permutation(len(chapters)))     # chapter i's place in a shuffle
    if n < len(chapters):
        ranked = sorted(range(len(chapters)), key=lambda i: (-w[i], int(place[i])))
        return {ch: int(i in ranked[:n]) for i, ch in enumerate(chapters)}
    counts = np.ones(len(chapters), dtype=int)
    share = w / w.sum() * (n - len(chapters))
    counts += np.floor(share + 1e-9).astype(int)
    rest = share - np.floor(share + 1e-9)
    left = n - int(counts.sum())
    ranked = sorted(range(len(chapters)), key=lambda i: (-round(rest[i], 9), -w[i],
                                                         int(place[i])))
    for i in ranked[:left]:
        counts[i] += 1
    return {ch: int(c) for ch, c in zip(chapters, counts)}


def _check_chapters(chapters, available):
    if chapters is None:
        return list(available)
    if isinstance(chapters, (int, np.integer)) and not isinstance(chapters, bool):
        chapters = [chapters]
    try:
        chosen = list(chapters)
    except TypeError:
        raise TypeError("chapters must be None or a list of chapter numbers, got "
                        f"{type(chapters).__name__}") from None
    if not chosen:
        raise ValueError("chapters must name at least one chapter (or be None for all)")
    for ch in chosen:
        if isinstance(ch, bool) or not isinstance(ch, (int, np.integer)) \
                or int(ch) not in available:
            raise ValueError(f"chapters must be chapter numbers among {list(available)}, "
                             f"got {ch!r}")
    return sorted({int(ch) for ch in chosen})


def _per_chapter(rng, chapters, n):
    """How many questions each chapter gets: n // k each, one more for n % k of them."""
    base, extra = divmod(n, len(chapters))
    lucky = set(rng.permutation(len(chapters))[:extra].tolist())
    return {ch: base + (i in lucky) for i, ch in enumerate(chapters)}


def mock_exam(seed, chapters=None, n_questions=12, history=None):
    """A balanced, deterministic mock exam over the chosen chapters.

    The questions are spread evenly (the chapters' counts differ by at most one; with fewer
    questions than chapters, a seeded choice of chapters gets one each), alternate between
    numeric exercises and concept questions (a chapter without one kind gives the other), never
    repeat a concept question or an exercise class while a chapter has unused ones, and appear
    in chapter order.

    Parameters
    ----------
    seed : int
        The same seed gives the same exam.
    chapters : sequence of int, optional
        The chapters to draw from; all of :func:`available_chapters` by default.
    n_questions : int
        How many questions, 1 to 200.
    history : list of dict, optional
        The student's records (:func:`course_lib.progress.read_events`). With results in it
        the exam adapts (:func:`study_plan`): weak chapters get more of the questions (every
        chapter chosen keeps one at least), and the questions due for review come first in
        their chapter, each in a variant the student has not seen. The same seed and history
        give the same exam; without a history the exam is the balanced one.

    Returns
    -------
    Exam
        Its ``plan`` is the :func:`study_plan` used (None without a history).

    Raises
    ------
    TypeError, ValueError
        For a seed that is not an integer, an unknown chapter or a bad number of questions.

    Examples
    --------
    >>> exam = mock_exam(seed=7, chapters=[3, 7], n_questions=6)
    >>> [q.chapter for q in exam]
    [3, 3, 3, 7, 7, 7]
    >>> [q.key for q in exam] == [q.key for q in mock_exam(7, [3, 7], 6)]
    True
    >>> wrong = [{"kind": "attempt", "key": "ch07.BSplinePoint", "seed": 1, "status": "wrong"}]
    >>> adaptive = mock_exam(seed=7, chapters=[3, 7], n_questions=6, history=wrong)
    >>> first = [q for q in adaptive if q.chapter == 7][0]     # the review comes first
    >>> [q.chapter for q in adaptive].count(7), first.key, first.seed != 1
    (4, 'ch07.BSplinePoint', True)
    """
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise TypeError(f"seed must be an integer, got {type(seed).__name__}")
    if isinstance(n_questions, bool) or not isinstance(n_questions, (int, np.integer)) \
            or not 1 <= n_questions <= MAX_QUESTIONS:
        raise ValueError(f"n_questions must be a whole number from 1 to {MAX_QUESTIONS}, "
                         f"got {n_questions!r}")
    numeric, concept = _numeric_pool(), _concept_pool()
    available = sorted(set(numeric) | set(concept))
    if not available:
        raise ValueError("there are no exercises or concept questions to draw an exam from")
    chosen = _check_chapters(chapters, available)
    if history is not None and not isinstance(history, (list, tuple)):
        raise TypeError("history must be a list of progress records (progress.read_events()), "
                        f"got {type(history).__name__}")
    plan = study_plan(history) if history else None
    adaptive = plan is not None and (plan["weights"] or plan["due"])
    rng = np.random.default_rng([int(seed) & 0xFFFFFFFF, zlib.crc32(b"mock exam")])
    counts = (_weighted_counts(rng, chosen, int(n_questions), plan["weights"]) if adaptive
              else _per_chapter(rng, chosen, int(n_questions)))
    numeric_first = bool(rng.integers(2))
    slot = 0
    questions = []
    for ch in chosen:
        classes = list(numeric.get(ch, ()))
        asked = list(concept.get(ch, ()))
        class_order = [classes[i] for i in rng.permutation(len(classes))]
        concept_order = [asked[i] for i in rng.permutation(len(asked))]
        used_classes = used_concepts = 0
        reviews = _reviews(plan, ch, class_order, concept_order) if adaptive else []
        for review in reviews[:(counts[ch] + 1) // 2]:      # at most half a chapter's share
            questions.append(_review_question(ch, review, rng))
            if isinstance(review[0], type):
                class_order.remove(review[0])
            else:
                concept_order.remove(review[0])
        for _ in range(counts[ch] - min(len(reviews), (counts[ch] + 1) // 2)):
            want_numeric = (slot % 2 == 0) == numeric_first
            slot += 1
            fresh_concept = used_concepts < len(concept_order)
            if class_order and (want_numeric or not fresh_concept):
                cls = class_order[used_classes % len(class_order)]
                used_classes += 1
                questions.append(ExamQuestion(ch, cls(seed=int(rng.integers(1_000_000)))))
            else:                            # a concept question (repeated only if nothing else)
                questions.append(ExamQuestion(ch, concept_order[used_concepts
                                                                % len(concept_order)]))
                used_concepts += 1
    exam = Exam(seed, chosen, questions)
    exam.plan = plan
    return exam


def _reviews(plan, chapter, classes, concepts):
    """The questions of `chapter` due for review: (class or concept question, seen seeds)."""
    by_key = {f"ch{chapter:02d}.{cls.__name__}": cls for cls in classes}
    by_key.update({q.key: q for q in concepts})
    return [(by_key[d["key"]], d["seen"]) for d in plan["due"]
            if d["chapter"] == chapter and d["key"] in by_key]


def _review_question(chapter, review, rng):
    """A review question: a concept question as it is, an exercise in a variant not seen."""
    source, seen = review
    if not isinstance(source, type):
        return ExamQuestion(chapter, source)
    seen = {s for s in seen if isinstance(s, int)}
    while True:
        variant = int(rng.integers(1_000_000))
        if variant not in seen:
            return ExamQuestion(chapter, source(seed=variant))

