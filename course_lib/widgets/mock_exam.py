r"""Mock-exam widget: one question at a time, graded on submit, a score per chapter at the end.

The exam comes from :func:`course_lib.exercises.mock.mock_exam` (balanced over the chapters,
numeric exercises and concept questions mixed, the same seed giving the same exam). A numeric
question has a text field read by :func:`course_lib.exercises.mock.read_answer` (a list, a
matrix such as ``[[1, 0], [0, 1]]``, ``1, 2, 3``, ``sqrt(2)/2``, a quoted word; never
``eval``); a concept question has one button per option. **Submit** grades the answer with the
exercise's own checker and shows its diagnosis, once (an empty or unreadable answer is not
graded: it can be corrected); **Next** moves on (a question left without a graded answer counts
as not right). After the last question the widget shows the score per chapter and the
questions to revisit, and saves the result to the progress file (:mod:`course_lib.progress`).

The bar chart shows, per chapter of the exam, the questions answered right (green) and not right
(red) out of those asked (grey outline); its bars move by blitting.

**Adaptive** (the default): the exam is drawn from the student's history in the progress file
(:func:`course_lib.exercises.mock.study_plan`): weak chapters get more questions and what was
answered wrong comes back, later, in a new variant; the header says so. **Timed**
(``time_limit`` in minutes): a countdown ticks in the page; when it reaches zero the exam ends
and the questions not graded count as not right. The kernel keeps the deadline: an answer
submitted after it is not graded even if the page never said the time was up.
"""
import math
import time
import warnings
from dataclasses import dataclass

import numpy as np

from .. import draw, progress
from ..exercises import mock
from . import _countdown, _style
from ._base import Explorer, labelled

__all__ = ["MockExamWidget", "State", "scene"]

RIGHT, WRONG, ASKED = "#2e9d4f", "#d1495b", "0.55"
PLACEHOLDER = ("Your answer, e.g.  [[1, 0], [0, 1]]   or   1, 2, 3   or   sqrt(2)/2   or "
               "'rejected'")


@dataclass
class State:
    """Where the student is: the question shown, and whether the results page is shown.

    Examples
    --------
    >>> State().index, State().done
    (0, False)
    """

    index: int = 0
    done: bool = False
    timed_out: bool = False


def _graded(feedback):
    """Whether an answer was graded (right or wrong); an empty or unreadable one was not."""
    return feedback is not None and feedback.status in ("correct", "wrong")


def _results_markdown(exam, timed_out=False):
    right, total = exam.total()
    lines = [f"### Result: {right:g} of {total} right", ""]
    if timed_out:
        lines += ["**The time is up:** the questions not graded count as not right.", ""]
    lines += ["| chapter | right | asked |", "|---:|---:|---:|"]
    lines += [f"| {ch} | {r:g} | {t} |" for ch, (r, t) in exam.score().items()]
    partial = [q for k, q in enumerate(exam.questions) if 0 < exam.credit(k) < 1]
    if partial:
        lines += ["", f"Partial credit on {len(partial)} question"
                  f"{'s' if len(partial) > 1 else ''} (the share of its parts that are right)."]
    revisit = exam.to_revisit()
    lines.append("")
    if revisit:
        lines.append("**Questions to revisit** (rebuild a numeric one in its chapter's "
                     "exercise notebook with `SEED` set to its variant):")
        lines += [f"- {q.label}" for q in revisit]
    else:
        lines.append("**Every question right.** Try another seed, or more questions.")
    return "\n".join(lines)


def plan_note(exam):
    """What the header says of an adaptive exam's draw (HTML), or "" for a balanced one.

    Examples
    --------
    >>> wrong = [{"kind": "attempt", "key": "ch05.Outcodes", "seed": 1, "status": "wrong"}]
    >>> print(plan_note(mock.mock_exam(seed=1, chapters=[3, 5], n_questions=4, history=wrong)))
    ... # doctest: +NORMALIZE_WHITESPACE
    Drawn from your results: more questions from chapter 5; 1 question you got wrong comes
    back in a new variant.
    """
    plan = exam.plan
    if not plan:
        return ""
    asked = {q.chapter for q in exam}
    weak = sorted((ch for ch, w in plan["weights"].items() if ch in asked and w > 1.5),
                  key=lambda ch: -plan["weights"][ch])
    keys = {d["key"] for d in plan["due"]}
    back = sum(q.key in keys for q in exam)
    parts = []
    if weak:
        parts.append("more questions from chapter" + ("s " if len(weak) > 1 else " ")
                     + ", ".join(str(ch) for ch in weak))
    if back:
        parts.append(f"{back} question{'s' if back > 1 else ''} you got wrong "
                     f"come{'' if back > 1 else 's'} back in a new variant")
    return ("Drawn from your results: " + "; ".join(parts) + ".") if parts else ""


def scene(exam, state):
    """Pure part: the exam and the state -> the texts, buttons and bars to show.

    Returns
    -------
    dict
        ``header`` (HTML), ``question`` (Markdown, empty on the results page), ``kind``
        (``"numeric"``, ``"concept"`` or None), ``options`` (the buttons of a concept
        question), ``feedback`` (Markdown of the submitted answer, or ""), ``locked`` (the
        answer was graded right or wrong: Submit is off; an empty or unreadable answer may be
        corrected), ``next_label``, ``chapters``, ``right``, ``wrong`` (graded wrong) and
        ``asked`` (per chapter, for the bars), ``score`` (text) and ``results`` (Markdown of
        the results page, else "").

    Examples
    --------
    >>> exam = mock.mock_exam(seed=2, chapters=[3, 7], n_questions=2)
    >>> s = scene(exam, State())
    >>> s["header"].startswith("Question 1 of 2"), s["asked"], s["right"]
    (True, [1, 1], [0, 0])
    """
    scores = exam.score()
    chapters = list(scores)
    right = [scores[ch][0] for ch in chapters]
    asked = [scores[ch][1] for ch in chapters]
    answered = {ch: 0 for ch in chapters}
    for question, feedback in zip(exam.questions, exam.feedback):
        if _graded(feedback):
            answered[question.chapter] += 1
    wrong = [answered[ch] - r for ch, r in zip(chapters, right)]
    total_right, total = exam.total()
    base = {"chapters": chapters, "right": right, "wrong": wrong, "asked": asked,
            "score": f"{total_right} of {total} right"}
    if state.done:
        return {**base, "header": f"<b>Exam finished</b> (seed {exam.seed})", "question": "",
                "kind": None, "options": (), "feedback": "", "locked": True,
                "next_label": "Finished",
                "results": _results_markdown(exam, getattr(state, "timed_out", False))}
    question = exam[state.index]
    feedback = exam.feedback[state.index]
    if question.kind == "concept":
        options = (tuple(question.options) if question.source.kind == "true/false"
                   else tuple(question.source.letters))
    else:
        options = ()
    last = state.index == len(exam) - 1
    return {**base,
            "header": f"Question {state.index + 1} of {len(exam)} · chapter "
                      f"{question.chapter} · {'concept' if options else 'numeric'}",
            "question": question.markdown(), "kind": question.kind, "options": options,
            "feedback": feedback._repr_markdown_() if feedback is not None else "",
            "locked": _graded(feedback),
            "next_label": "See the results" if last else "Next question", "results": ""}


class MockExamWidget(Explorer):
    """A mock exam in a notebook: question, answer field, Submit, Next, scores per chapter.

    Parameters
    ----------
    seed : int
        The exam's seed (the same seed, the same exam); the widget's seed box starts a new one.
    chapters : sequence of int, optional
        The chapters to draw from (all by default).
    n_questions : int
    progress_file : str or os.PathLike, optional
        Where the result is saved (see :func:`course_lib.progress.progress_path`).
    save : bool
        Save the result at the end of the exam.
    adaptive : bool
        Draw the exam from the history in the progress file (see the module's documentation);
        False: the balanced exam of the seed.
    time_limit : float, optional
        Minutes; a countdown, and the exam ends when it reaches zero.

    Examples
    --------
    >>> import os, tempfile
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> exam = MockExamWidget(seed=1, chapters=[3], n_questions=1, progress_file=file)
    >>> exam.submit_answer()                 # nothing typed: not answered yet, not locked
    >>> exam.shown["feedback"].startswith("\\u270f")
    True
    >>> exam.next()                          # skip it: the results page, saved to the file
    >>> exam.state.done, len(progress.read_history(file))
    (True, 1)
    """

    summary = ("Mock exam (interactive): one question at a time with an answer field, graded "
               "with the exercises' feedback, ending with a score per chapter and the questions "
               "to revisit.")

    def __init__(self, seed=0, chapters=None, n_questions=12, progress_file=None, save=True,
                 adaptive=True, time_limit=None):
        import ipywidgets as w

        if time_limit is not None and (isinstance(time_limit, bool) or not isinstance(
                time_limit, (int, float)) or not math.isfinite(time_limit)
                or not 0 < time_limit <= 600):
            raise ValueError("time_limit must be None or a number of minutes from 0 to 600, "
                             f"got {time_limit!r}")
        self.chapters, self.n_questions = chapters, n_questions
        self.progress_file, self.save = progress_file, save
        self.adaptive, self.time_limit = bool(adaptive), time_limit
        self._notes = []
        self.exam = self._draw(seed)
        self.state = State()
        self.saved = None
        self.shown = {}

        self.fig = draw.figure(figsize=(4.2, 2.6))
        self.ax = self.fig.add_subplot()
        self._build_bars()

        self.header = w.HTML()
        self.question_out = w.Output(layout=w.Layout(min_height="120px"))
        self.text = w.Textarea(placeholder=PLACEHOLDER,
                               layout=w.Layout(width="520px", height="64px"))
        self.choice = w.ToggleButtons(options=["a", "b"], value=None,
                                      style={"button_width": "auto"})
        self.submit_button = w.Button(description="Submit", button_style="primary",
                                      icon="check")
        self.next_button = w.Button(description="Next question", icon="arrow-right")
        self.feedback_out = w.Output()
        self.status = w.HTML()
        self.plan_html = w.HTML()
        self.countdown = None
        if time_limit is not None:
            self.countdown = _countdown.countdown(time_limit)
            self.countdown.observe(lambda change: change["new"] and self.time_up(),
                                   names="expired")
        self.seed_box = labelled(w.BoundedIntText, "seed", label_width="40px", body=110,
                                 value=int(seed), min=0, max=10**9)
        self.new_button = w.Button(description="New exam", icon="refresh")
        self.submit_button.on_click(lambda _: self.submit_answer())
        self.next_button.on_click(lambda _: self.next())
        self.new_button.on_click(lambda _: self.new_exam(self.seed_box.value))
        buttons = w.HBox([self.submit_button, self.next_button])
        side = w.VBox([self.fig.canvas, w.HBox([self.seed_box, self.new_button]), self.status])
        top = [self.countdown] if self.countdown is not None else []
        main = w.VBox([*top, self.header, self.plan_html, self.question_out, self.text,
                       self.choice, buttons, self.feedback_out], layout=w.Layout(width="560px"))
        self.widget = w.HBox([main, side], layout=w.Layout(flex_flow="row wrap"))
        self._show_question()

    def _draw(self, seed):
        """The exam of `seed`: adapted to the history in the progress file when adaptive."""
        history = None
        if self.adaptive:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", progress.ProgressFileWarning)
                try:
                    history = progress.read_events(self.progress_file)
                except (OSError, ValueError, TypeError) as exc:
                    caught.append(warnings.WarningMessage(str(exc), UserWarning, "", 0))
            self._notes = [str(c.message) for c in caught]
        return mock.mock_exam(seed, chapters=self.chapters, n_questions=self.n_questions,
                              history=history)

    # -- the figure ------------------------------------------------------------------------

    def _build_bars(self):
        ax = self.ax
        ax.clear()
        s = scene(self.exam, self.state)
        x = np.arange(len(s["chapters"]))
        ax.bar(x, s["asked"], color="none", edgecolor=ASKED, lw=1.2, label="asked")
        self.right_bars = ax.bar(x, s["right"], color=RIGHT, label="right")
        self.wrong_bars = ax.bar(x, s["wrong"], bottom=s["right"], color=WRONG,
                                 label="not right")
        ax.set_xticks(x, [str(ch) for ch in s["chapters"]])
        ax.set_xlabel("chapter")
        ax.set_ylabel("questions")
        ax.set_ylim(0, max(s["asked"]) + 0.6)
        ax.yaxis.get_major_locator().set_params(integer=True)
        # the legend above the axes, where no bar can hide it
        _style.legend(ax, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncols=3,
                      frameon=False, borderaxespad=0.1, handlelength=1.2, columnspacing=1.0)
        self.score_text = ax.text(0.01, 0.97, s["score"], transform=ax.transAxes, va="top",
                                  fontsize=_style.LABEL)
        _style.style_axes(ax)
        self.fig.subplots_adjust(left=0.14, right=0.98, bottom=0.2, top=0.86)
        self.blitter = draw.Blitter(self.fig, [*self.right_bars, *self.wrong_bars,
                                               self.score_text])

    def update(self):
        """Move the bars and the score to the exam's current results (blitting)."""
        s = scene(self.exam, self.state)
        for bar, right in zip(self.right_bars, s["right"]):
            bar.set_height(right)
        for bar, right, wrong in zip(self.wrong_bars, s["right"], s["wrong"]):
            bar.set_y(right)
            bar.set_height(wrong)
        self.score_text.set_text(s["score"])
        self.blitter.update()
        return s

    # -- showing -----------------------------------------------------------------------------

    @staticmethod
    def _markdown(out, text):
        """Show Markdown `text` in the Output widget `out` (set as its outputs: this works in
        a callback and without a kernel alike, and tests can read it back)."""
        out.outputs = ({"output_type": "display_data", "metadata": {},
                        "data": {"text/markdown": text, "text/plain": text}},) if text else ()

    def _show_question(self):
        s = self.update()
        self.header.value = s["header"]
        note = plan_note(self.exam) if not self.state.done else ""
        self.plan_html.value = f"<i>{note}</i>" if note else ""
        if self._notes and not self.status.value:
            self.status.value = "<b>Note:</b> " + " ".join(self._notes)
        self.shown = {"question": s["question"], "feedback": s["feedback"],
                      "results": s["results"]}
        self._markdown(self.question_out, s["question"] or s["results"])
        self._markdown(self.feedback_out, s["feedback"])
        numeric, concept = s["kind"] == "numeric", s["kind"] == "concept"
        self.text.layout.display = None if numeric else "none"
        self.choice.layout.display = None if concept else "none"
        if concept:
            self.choice.options = list(s["options"])
            self.choice.value = None
        self.text.value = ""
        self.text.disabled = self.choice.disabled = s["locked"]
        self.submit_button.disabled = s["locked"]
        self.submit_button.layout.display = "none" if self.state.done else None
        self.next_button.description = s["next_label"]
        self.next_button.disabled = self.state.done

    def current_answer(self):
        """What the student entered: the text typed, or the option button chosen (or None)."""
        if self.state.done:
            return None
        if self.exam[self.state.index].kind == "concept":
            return self.choice.value
        return self.text.value

    # -- actions -----------------------------------------------------------------------------

    def submit_answer(self, answer=None):
        """Grade the answer entered (or `answer`, typed text or a value) and show the feedback.

        An empty answer gives "not answered yet" and leaves the question open.
        """
        if self.state.done:
            return
        if self._past_deadline():
            self.time_up()
            return
        i = self.state.index
        if _graded(self.exam.feedback[i]):
            return                                   # graded once, as in an exam
        given = self.current_answer() if answer is None else answer
        self.exam.submit(i, given)
        s = self.update()
        self.shown["feedback"] = s["feedback"]
        self._markdown(self.feedback_out, s["feedback"])
        self.text.disabled = self.choice.disabled = s["locked"]
        self.submit_button.disabled = s["locked"]

    def _past_deadline(self):
        return self.countdown is not None and self.countdown.deadline <= time.time()

    def time_up(self):
        """End a timed exam: the questions not graded count as not right; results, saved."""
        if self.state.done:
            return
        for i, feedback in enumerate(self.exam.feedback):
            if feedback is None:
                self.exam.submit(i, None)
        self.state.done = self.state.timed_out = True
        if self.countdown is not None:
            self.countdown.stop("Time is up")
        self._save()
        self._show_question()

    def next(self):
        """The next question (an unsubmitted one counts as unanswered), or the results."""
        if self.state.done:
            return
        if self._past_deadline():
            self.time_up()
            return
        i = self.state.index
        if self.exam.feedback[i] is None:
            self.exam.submit(i, None)
        if i + 1 < len(self.exam):
            self.state.index = i + 1
        else:
            self.state.done = True
            if self.countdown is not None:
                self.countdown.stop(f"Finished with {self.countdown.left() / 60:.0f} min left")
            self._save()
        self._show_question()

    def new_exam(self, seed):
        """Start a new exam with `seed` (same chapters and length)."""
        self.exam = self._draw(int(seed))
        self.state = State()
        if self.countdown is not None:
            self.countdown.stopped = self.countdown.expired = False
            self.countdown.deadline = time.time() + 60.0 * float(self.time_limit)
        self.saved = None
        self.status.value = ""
        self._build_bars()
        self.blitter.forget_background()
        self.fig.canvas.draw_idle()
        self._show_question()

    def _save(self):
        if not self.save:
            return
        record = self.exam.record()
        if self.time_limit is not None:
            record.update(time_limit=float(self.time_limit), timed_out=self.state.timed_out)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", progress.ProgressFileWarning)
            try:
                self.saved = progress.record_exam(record, path=self.progress_file)
                where = progress.progress_path(self.progress_file)
                message = f"Result saved to <code>{where}</code>."
            except (OSError, ValueError, TypeError) as exc:
                message = f"<b>The result could not be saved:</b> {exc}"
        notes = " ".join([*self._notes, *(str(c.message) for c in caught
                                          if issubclass(c.category,
                                                        progress.ProgressFileWarning))])
        if notes and ("saved to" in notes or "could not be saved" in notes):
            message = ""                      # the note says where it went instead
        self.status.value = message + (f"{'<br>' if message else ''}<b>Note:</b> {notes}"
                                       if notes else "")
