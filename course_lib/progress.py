r"""A student's progress: mock-exam results kept in a small JSON file in the user's data folder.

The file lives outside the repository, in the platform's folder for user data:
``$XDG_DATA_HOME/graphics-course/progress.json`` (``~/.local/share/...`` when the variable is
unset) on Linux and other Unix systems, ``~/Library/Application Support/graphics-course/`` on
macOS and ``%APPDATA%\graphics-course\`` on Windows. The environment variable
``COURSE_PROGRESS_FILE``, or the ``path`` argument of every function, chooses another file (the
tests use a temporary one); a path inside the course repository is refused, so that personal
results never end up in a commit.

Writing is atomic: the new content goes to a temporary file in the same folder, is flushed to
disk (``fsync``) and then replaces the old file in one step (``os.replace``), so a crash or a
killed kernel leaves either the old file or the new one, never half of one. A file that cannot
be read (not JSON, or JSON of another format or version) is never overwritten: it is renamed
with a ``.corrupt-<timestamp>`` suffix, a :class:`ProgressFileWarning` says so, and a new file is
started.

The file holds ``{"format": "graphics-course-progress", "version": 1, "exams": [...]}``, one
record per exam as made by :meth:`course_lib.exercises.mock.Exam.record` plus its ``date``.
"""
import contextlib
import json
import os
import sys
import tempfile
import warnings
from datetime import datetime, timezone
from pathlib import Path

__all__ = ["ENV_VAR", "FORMAT", "VERSION", "ProgressFileWarning", "chapter_scores",
           "progress_path", "progress_report", "read_history", "record_exam",
           "weakest_chapters"]

#: The environment variable that chooses the progress file.
ENV_VAR = "COURSE_PROGRESS_FILE"
#: The name of the file format, stored in the file.
FORMAT = "graphics-course-progress"
#: The version of the file format this module reads and writes.
VERSION = 1
_APP = "graphics-course"
_FILE = "progress.json"
_EXAM_KEYS = {"date": str, "seed": int, "chapters": list, "n_questions": int, "score": dict,
              "revisit": list}


class ProgressFileWarning(UserWarning):
    """A progress file could not be read and was set aside (its new name is in the message).

    Examples
    --------
    >>> issubclass(ProgressFileWarning, UserWarning)
    True
    """


def _data_home():
    """The platform's folder for user data."""
    home = Path.home()
    if sys.platform == "win32":
        return Path(os.environ.get("APPDATA") or home / "AppData" / "Roaming")
    if sys.platform == "darwin":
        return home / "Library" / "Application Support"
    xdg = os.environ.get("XDG_DATA_HOME")
    return Path(xdg) if xdg and Path(xdg).is_absolute() else home / ".local" / "share"


def _repository_root():
    """The course repository this package runs from (an editable install), or None."""
    root = Path(__file__).resolve().parent.parent
    return root if (root / "pyproject.toml").is_file() and (root / "course_lib").is_dir() \
        else None


def progress_path(path=None):
    """The progress file: `path`, else ``$COURSE_PROGRESS_FILE``, else the user's data folder.

    Parameters
    ----------
    path : str or os.PathLike, optional

    Returns
    -------
    pathlib.Path
        An absolute path (the file need not exist).

    Raises
    ------
    TypeError
        If `path` is not a path.
    ValueError
        If the file would lie inside the course repository.

    Examples
    --------
    >>> import os, tempfile
    >>> folder = tempfile.mkdtemp()
    >>> progress_path(os.path.join(folder, "p.json")).name
    'p.json'
    >>> saved = os.environ.pop("COURSE_PROGRESS_FILE", None)
    >>> progress_path().parts[-2:]
    ('graphics-course', 'progress.json')
    >>> os.environ["COURSE_PROGRESS_FILE"] = os.path.join(folder, "env.json")
    >>> progress_path().name
    'env.json'
    >>> if saved is None: del os.environ["COURSE_PROGRESS_FILE"]
    ... else: os.environ["COURSE_PROGRESS_FILE"] = saved
    """
    if path is None:
        env = os.environ.get(ENV_VAR, "").strip()
        path = env or _data_home() / _APP / _FILE
        name = ENV_VAR if env else "the default progress file"
    else:
        name = "path"
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a file path (str or os.PathLike), got "
                        f"{type(path).__name__}")
    resolved = Path(path).expanduser().resolve()
    root = _repository_root()
    if root is not None and resolved.is_relative_to(root):
        raise ValueError(f"{name} ({resolved}) lies inside the course repository ({root}); "
                         "progress is personal data: keep it in your data folder or a "
                         "temporary folder")
    return resolved


# ---------------------------------------------------------------------------------------------
# Reading, checking, setting aside
# ---------------------------------------------------------------------------------------------

def _problem(data):
    """Why `data` (parsed JSON) is not a progress file of this version; None if it is."""
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        return f"it is not a {FORMAT!r} file"
    if data.get("version") != VERSION:
        return f"it has format version {data.get('version')!r}; this course reads {VERSION}"
    exams = data.get("exams")
    if not isinstance(exams, list):
        return "its 'exams' entry is not a list"
    for k, exam in enumerate(exams):
        if not isinstance(exam, dict):
            return f"exam {k} is not a record"
        for key, kind in _EXAM_KEYS.items():
            if not isinstance(exam.get(key), kind) or isinstance(exam.get(key), bool):
                return f"exam {k} lacks a valid {key!r}"
        for chapter, pair in exam["score"].items():
            if not (chapter.isdigit() and isinstance(pair, list) and len(pair) == 2
                    and all(isinstance(x, int) and not isinstance(x, bool) for x in pair)
                    and 0 <= pair[0] <= pair[1]):
                return f"exam {k} has an invalid score for chapter {chapter!r}"
    return None


def _set_aside(file, reason):
    """Rename `file` with a .corrupt-<timestamp> suffix and warn; return the new path."""
    stamp = datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")
    target = file.with_name(f"{file.name}.corrupt-{stamp}")
    k = 1
    while target.exists():
        target = file.with_name(f"{file.name}.corrupt-{stamp}-{k}")
        k += 1
    os.replace(file, target)
    warnings.warn(f"The progress file {file} could not be read ({reason}). It was moved to "
                  f"{target} (nothing was deleted) and a new progress file will be started.",
                  ProgressFileWarning, stacklevel=3)
    return target


def _load(file):
    """The exam records of `file` ([] when it does not exist); a bad file is set aside."""
    try:
        raw = file.read_bytes()
    except FileNotFoundError:
        return []
    try:
        data = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        _set_aside(file, f"not valid JSON: {exc}")
        return []
    reason = _problem(data)
    if reason is not None:
        _set_aside(file, reason)
        return []
    return data["exams"]


def read_history(path=None):
    """The recorded exams, oldest first ([] when there is no progress file yet).

    A file that is not valid JSON, or not a progress file of this version, is renamed with a
    ``.corrupt-<timestamp>`` suffix (never deleted) and reported by a
    :class:`ProgressFileWarning`; the history then starts empty.

    Parameters
    ----------
    path : str or os.PathLike, optional
        See :func:`progress_path`.

    Returns
    -------
    list of dict

    Examples
    --------
    >>> import os, tempfile
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> read_history(file)
    []
    >>> _ = record_exam({"seed": 1, "chapters": [3], "n_questions": 2,
    ...                  "score": {"3": [1, 2]}, "revisit": []}, file)
    >>> [exam["score"] for exam in read_history(file)]
    [{'3': [1, 2]}]
    """
    return _load(progress_path(path))


# ---------------------------------------------------------------------------------------------
# Writing
# ---------------------------------------------------------------------------------------------

def _fsync_folder(folder):
    """Flush the folder's entry of the renamed file to disk (POSIX; a no-op elsewhere)."""
    if os.name != "posix":
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


def _write_atomic(file, data):
    """Write `data` as JSON to `file` atomically: temporary file, fsync, os.replace."""
    file.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=file.parent, prefix=f".{file.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            json.dump(data, handle, indent=1, sort_keys=True)
            handle.write("\n")
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, file)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise
    _fsync_folder(file.parent)


def _as_record(result):
    """The JSON-ready record of an Exam or of a record dict (validated)."""
    record = result.record() if hasattr(result, "record") else result
    if not isinstance(record, dict):
        raise TypeError("result must be an Exam or the dict of Exam.record(), got "
                        f"{type(result).__name__}")
    try:
        record = json.loads(json.dumps(record))
    except (TypeError, ValueError) as exc:
        raise TypeError(f"result must hold JSON data only: {exc}") from None
    return record


def record_exam(result, path=None, when=None):
    """Add a finished exam to the progress file (written atomically) and return its record.

    Parameters
    ----------
    result : Exam or dict
        A :class:`course_lib.exercises.mock.Exam` or the dict of its ``record()``.
    path : str or os.PathLike, optional
        See :func:`progress_path`.
    when : datetime.datetime, optional
        The time to store (now, in UTC, by default).

    Returns
    -------
    dict
        The record stored, with its ``date``.

    Raises
    ------
    TypeError, ValueError
        If `result` is not an exam record (nothing is written then).

    Examples
    --------
    >>> import os, tempfile
    >>> from datetime import datetime, timezone
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> rec = record_exam({"seed": 4, "chapters": [7], "n_questions": 1,
    ...                    "score": {"7": [0, 1]}, "revisit": []}, file,
    ...                   when=datetime(2026, 1, 2, tzinfo=timezone.utc))
    >>> rec["date"], len(read_history(file))
    ('2026-01-02T00:00:00+00:00', 1)
    """
    record = _as_record(result)
    when = when or datetime.now(timezone.utc)
    if not isinstance(when, datetime):
        raise TypeError(f"when must be a datetime, got {type(when).__name__}")
    record["date"] = when.isoformat(timespec="seconds")
    reason = _problem({"format": FORMAT, "version": VERSION, "exams": [record]})
    if reason is not None:
        raise ValueError(f"result is not an exam record: {reason.replace('exam 0', 'it')}")
    file = progress_path(path)
    exams = _load(file)
    exams.append(record)
    _write_atomic(file, {"format": FORMAT, "version": VERSION, "exams": exams})
    return record


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


def progress_report(path=None):
    """The student's progress as Markdown: exams taken, score per chapter, weakest chapters.

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
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> progress_report(file).startswith("**No results yet.**")
    True
    >>> _ = record_exam({"seed": 1, "chapters": [3, 5], "n_questions": 3,
    ...                  "score": {"3": [2, 2], "5": [0, 1]}, "revisit": []}, file)
    >>> "chapter 5 (0 of 1 right)" in progress_report(file)
    True
    """
    file = progress_path(path)
    history = read_history(file)
    shown = _short(file)
    if not history:
        return (f"**No results yet.** There is no progress file at `{shown}` (or it holds no "
                "exam): take a mock exam in `notebooks/mock_exam.ipynb`, and your scores per "
                "chapter will show up here.")
    scores = chapter_scores(history)
    last = history[-1]
    lines = [f"**{len(history)} mock exam{'s' if len(history) > 1 else ''} taken**, the last "
             f"on {last['date'][:10]} (progress file: `{shown}`).", "",
             "| chapter | right | asked | share |", "|---:|---:|---:|---:|"]
    lines += [f"| {ch} | {r} | {t} | {100 * r / t:.0f}% |" for ch, (r, t) in scores.items()]
    weak = weakest_chapters(history)
    lines.append("")
    if weak:
        listed = ", ".join(f"chapter {w['chapter']} ({w['right']} of {w['total']} right)"
                           for w in weak)
        lines.append(f"**Weakest chapters:** {listed}. Reread those lessons and redo their "
                     "exercises with a new `SEED`.")
    else:
        lines.append("**Every question answered right so far.** Try a longer exam.")
    if last["revisit"]:
        lines += ["", "To revisit from the last exam: "
                  + "; ".join(item.get("label", item.get("key", "?"))
                              for item in last["revisit"]) + "."]
    return "\n".join(lines)
