"""Summaries of the progress file: scores per chapter, strength per topic, the report (see
:mod:`course_lib.progress`)."""
import re
import warnings
from pathlib import Path

from ._records import _NOTICES, read_events, read_history
from ._where import ProgressFileWarning, _keep_hint, _locate

# ---------------------------------------------------------------------------------------------
# Summaries
# ---------------------------------------------------------------------------------------------

def chapter_scores(history):
    """``{chapter: (right, total)}`` summed over the exams of `history`, in chapter order.

    Examples
    --------
    >>> chapter_scores([{"score": {"3": [1, 2], "7": [2, 2]}}, {"score": {"3": [0, 1]}}])
    {3: (1, 3), 7: (2, 2)}
    """
    totals = {}
    for exam in history:
        for chapter, (right, total) in exam["score"].items():
            r, t = totals.get(int(chapter), (0, 0))
            totals[int(chapter)] = (r + right, t + total)
    return dict(sorted(totals.items()))


def weakest_chapters(history=None, n=3, path=None):
    """The `n` chapters with the lowest share of right answers over the recorded exams.

    Ties go to the chapter with more questions asked (the evidence is stronger), then to the
    earlier chapter. Chapters answered perfectly are left out: they are not weak.

    Parameters
    ----------
    history : list of dict, optional
        Exam records; read from the progress file when omitted.
    n : int
        How many chapters at most.
    path : str or os.PathLike, optional
        The progress file, when `history` is omitted.

    Returns
    -------
    list of dict
        ``{"chapter", "right", "total", "share"}``, weakest first.

    Examples
    --------
    >>> history = [{"score": {"3": [1, 2], "5": [0, 1], "7": [2, 2]}}]
    >>> [(w["chapter"], w["share"]) for w in weakest_chapters(history)]
    [(5, 0.0), (3, 0.5)]
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ValueError(f"n must be a positive whole number, got {n!r}")
    if history is None:
        history = read_history(path)
    rows = [{"chapter": ch, "right": r, "total": t, "share": r / t}
            for ch, (r, t) in chapter_scores(history).items() if t > 0 and r < t]
    rows.sort(key=lambda row: (row["share"], -row["total"], row["chapter"]))
    return rows[:n]


def _short(file):
    """`file` with the home folder written ``~`` (shorter, and the same for every student)."""
    try:
        return "~/" + file.relative_to(Path.home().resolve()).as_posix()
    except ValueError:
        return str(file)


def topic_strength(events):
    """Per exercise (a topic of the exam), how the student did: from the attempts recorded.

    Parameters
    ----------
    events : list of dict
        Records of :func:`read_events`.

    Returns
    -------
    dict
        ``{key: {"chapter", "attempts", "variants", "solved", "first_try", "hints",
        "solutions", "share"}}``: answers checked, variants tried, variants solved, variants
        solved at their first attempt without a hint, hints and solutions seen, and ``share``
        = solved at first try / variants tried. In key order.

    Examples
    --------
    >>> events = [{"kind": "attempt", "key": "ch05.Outcodes", "seed": 1, "status": "wrong",
    ...            "hints": 0}, {"kind": "hint", "key": "ch05.Outcodes", "seed": 1},
    ...           {"kind": "attempt", "key": "ch05.Outcodes", "seed": 1, "status": "correct",
    ...            "hints": 1},
    ...           {"kind": "attempt", "key": "ch05.Outcodes", "seed": 2, "status": "correct",
    ...            "hints": 0}]
    >>> row = topic_strength(events)["ch05.Outcodes"]
    >>> row["attempts"], row["variants"], row["solved"], row["first_try"], row["share"]
    (3, 2, 2, 1, 0.5)
    """
    rows, first = {}, {}
    for event in events:
        kind, key = event.get("kind"), event.get("key")
        if kind not in ("attempt", "hint", "solution") or not isinstance(key, str):
            continue
        match = re.match(r"ch(\d\d)\.", key)
        row = rows.setdefault(key, {"chapter": int(match.group(1)) if match else None,
                                    "attempts": 0, "variants": 0, "solved": 0,
                                    "first_try": 0, "hints": 0, "solutions": 0,
                                    "_seen": set(), "_solved": set()})
        variant = event.get("seed")
        if kind == "hint":
            row["hints"] += 1
        elif kind == "solution":
            row["solutions"] += 1
            row["_solved"].add(("shown", variant))   # seeing the solution is no solve
        else:
            row["attempts"] += 1
            if variant not in row["_seen"]:
                row["_seen"].add(variant)
                first[(key, variant)] = (event.get("status") == "correct"
                                         and not event.get("hints", 0))
                row["first_try"] += first[(key, variant)]
            if event.get("status") == "correct" and variant not in row["_solved"]:
                row["_solved"].add(variant)
                row["solved"] += 1
    for row in rows.values():
        row["variants"] = len(row.pop("_seen"))
        row.pop("_solved")
        row["share"] = row["first_try"] / row["variants"] if row["variants"] else 0.0
    return dict(sorted(rows.items()))


def weakest_topics(events, n=5):
    """The `n` exercises tried with the lowest share solved at the first try (none perfect).

    Ties go to the exercise with more variants tried, then to the key.

    Examples
    --------
    >>> ev = [{"kind": "attempt", "key": k, "seed": 1, "status": s}
    ...       for k, s in [("ch03.A", "wrong"), ("ch05.B", "correct"), ("ch07.C", "wrong")]]
    >>> [row["key"] for row in weakest_topics(ev)]
    ['ch03.A', 'ch07.C']
    """
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ValueError(f"n must be a positive whole number, got {n!r}")
    rows = [{"key": key, **row} for key, row in topic_strength(events).items()
            if row["variants"] and row["first_try"] < row["variants"]]
    rows.sort(key=lambda row: (row["share"], -row["variants"], row["key"]))
    return rows[:n]


def _notice_lines(file):
    notices = _NOTICES.get(file) or []
    return ["", *[f"**Note:** {notice}" for notice in notices]] if notices else []


def progress_report(path=None):
    """The student's progress as Markdown: exams, score per chapter, exercises by topic.

    Whatever happened to the file on reading (records set aside, an upgrade, a folder in its
    place) is said at the end.

    Parameters
    ----------
    path : str or os.PathLike, optional
        See :func:`progress_path`.

    Returns
    -------
    str

    Examples
    --------
    >>> import os, tempfile
    >>> from course_lib.progress import record_exam
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> progress_report(file).startswith("**No results yet.**")
    True
    >>> _ = record_exam({"seed": 1, "chapters": [3, 5], "n_questions": 3,
    ...                  "score": {"3": [2, 2], "5": [0, 1]}, "revisit": []}, file)
    >>> "chapter 5 (0 of 1 right)" in progress_report(file)
    True
    """
    file, note, _ = _locate(path)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProgressFileWarning)    # said in the report instead
        events = read_events(file)
    shown = _short(file)
    notes = _notice_lines(file)
    warning = [] if note is None else [
        "", f"**Note:** {note}, so your results are kept in `{shown}`, a temporary file for "
        f"this session only (it may be lost when the server stops): {_keep_hint()}."]
    history = [e for e in events if e.get("kind") == "exam"]
    topics = topic_strength(events)
    if not history and not topics:
        where = (f"There is no progress file at `{shown}` yet" if not file.exists() else
                 f"The progress file `{shown}` holds no results yet")
        if notes:
            where = f"Nothing readable is left in `{shown}` (see the note below)"
        return "\n".join([
            f"**No results yet.** {where}: check an exercise in `exercises/` or take a mock "
            "exam in `notebooks/mock_exam.ipynb`, and your progress per chapter and topic will "
            "show up here.", *notes, *warning])
    lines = []
    if history:
        scores = chapter_scores(history)
        last = history[-1]
        lines += [f"**{len(history)} mock exam{'s' if len(history) > 1 else ''} taken**, the "
                  f"last on {last['date'][:10]} (progress file: `{shown}`).", "",
                  "| chapter | right | asked | share |", "|---:|---:|---:|---:|"]
        lines += [f"| {ch} | {_score_text(r)} | {t} | {100 * r / t:.0f}% |"
                  for ch, (r, t) in scores.items()]
        weak = weakest_chapters(history)
        lines.append("")
        if weak:
            listed = ", ".join(f"chapter {w['chapter']} ({_score_text(w['right'])} of "
                               f"{w['total']} right)" for w in weak)
            lines.append(f"**Weakest chapters:** {listed}. Reread those lessons and redo their "
                         "exercises with a new `SEED`; the next mock exam asks more of them.")
        else:
            lines.append("**Every question answered right so far.** Try a longer exam.")
        if last["revisit"]:
            lines += ["", "To revisit from the last exam: "
                      + "; ".join(item.get("label", item.get("key", "?"))
                                  for item in last["revisit"]) + "."]
    else:
        lines.append(f"**No mock exam taken yet** (progress file: `{shown}`).")
    if topics:
        tried = sum(row["variants"] for row in topics.values())
        lines += ["", f"**Exercises:** {len(topics)} kinds tried, {tried} variants; "
                  "per chapter:", "",
                  "| chapter | kinds tried | variants | solved | right at first try | hints |",
                  "|---:|---:|---:|---:|---:|---:|"]
        per = {}
        for row in topics.values():
            agg = per.setdefault(row["chapter"], [0, 0, 0, 0, 0])
            for k, name in enumerate(("variants", "solved", "first_try", "hints")):
                agg[k + 1] += row[name]
            agg[0] += 1
        for ch, (kinds, variants, solved, first_try, hints) in sorted(
                per.items(), key=lambda item: (item[0] is None, item[0] or 0)):
            # a chapter whose exercises were only opened for hints has no answer checked yet
            share = f"{100 * first_try / variants:.0f}%" if variants else "—"
            lines.append(f"| {ch if ch is not None else '?'} | {kinds} | {variants} | {solved} "
                         f"| {share} | {hints} |")
        weak = weakest_topics(events, n=3)
        if weak:
            lines += ["", "**Topics to practise:** " + ", ".join(
                f"`{row['key']}` ({row['first_try']} of {row['variants']} right at first try)"
                for row in weak) + "."]
    return "\n".join(lines + notes + warning)


def _score_text(x):
    """A score as written: 3, or 2.5 with partial credit."""
    return f"{x:g}" if isinstance(x, float) else str(x)

