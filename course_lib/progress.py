r"""A student's progress: mock-exam results kept in a small JSON file in the user's data folder.

Where the file lives
--------------------
By default in the platform's folder for user data: ``$XDG_DATA_HOME/graphics-course/progress.json``
(``~/.local/share/...`` when the variable is unset) on Linux and other Unix systems,
``~/Library/Application Support/graphics-course/`` on macOS and ``%APPDATA%\graphics-course\`` on
Windows. The environment variable ``COURSE_PROGRESS_FILE``, or the ``path`` argument of every
function, chooses another file (the tests use a temporary one).

Personal results must never end up in a commit, so a file inside the course repository is
refused, with one exception: the repository's per-user folders :data:`USER_FOLDERS`
(``.local/``, ``.cache/``, ``.config/``, ``.jupyter/``, ``.ipython/`` at its top level). Those
are the folders that programs create in the home folder, and on Binder (or any hub that copies
the course into the home folder) the home folder *is* the repository: the default file is then
``<repository>/.local/share/graphics-course/progress.json``. The repository's ``.gitignore``
excludes every one of these folders, so a file in them cannot be committed by accident
(``tests/test_progress.py`` checks each with ``git check-ignore``, so that this list and
``.gitignore`` cannot drift apart). Any other place in the repository (next to the notebooks, in
``course_lib/``) stays refused with a :class:`ValueError`.

When the default folder cannot be written (a hub with a read-only home folder, a data folder
on a read-only file system), the results of the session go to a per-user file in the system's
temporary folder, ``<tmp>/graphics-course-<uid>/progress.json``, so that the start page and the
mock exam still work; saving an exam there issues a :class:`ProgressFileWarning` (the mock
exam's widget shows it) and the progress report says so, both naming ``COURSE_PROGRESS_FILE``,
the variable to set to keep the results: a temporary file may be lost when the server stops.
A file chosen explicitly (the variable or ``path``) is never redirected: when it cannot be
written, :func:`record_exam` raises an :class:`OSError` that names the file and the variable.

Writing
-------
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
import errno
import json
import os
import sys
import tempfile
import warnings
from datetime import datetime, timezone
from pathlib import Path

__all__ = ["ENV_VAR", "FORMAT", "USER_FOLDERS", "VERSION", "ProgressFileWarning",
           "chapter_scores", "progress_path", "progress_report", "read_history", "record_exam",
           "weakest_chapters"]

#: The environment variable that chooses the progress file.
ENV_VAR = "COURSE_PROGRESS_FILE"
#: The name of the file format, stored in the file.
FORMAT = "graphics-course-progress"
#: The version of the file format this module reads and writes.
VERSION = 1
#: The repository's top-level folders where a progress file may lie: the per-user folders that
#: programs create in the home folder, which is the repository on Binder. ``.gitignore`` must
#: exclude each one (``tests/test_progress.py`` checks it with ``git check-ignore``).
USER_FOLDERS = (".local", ".cache", ".config", ".jupyter", ".ipython")
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


def _in_user_folder(file, root):
    """Whether `file` (resolved, inside `root`) lies in one of the :data:`USER_FOLDERS`."""
    parts = file.relative_to(root).parts
    return len(parts) > 1 and parts[0] in USER_FOLDERS


def _unwritable(folder):
    """Why `folder` can be neither written nor created, or None if it can (nothing is made).

    The folder, or else its nearest existing ancestor, must be a folder this user may write in.
    """
    for candidate in (folder, *folder.parents):
        if os.path.exists(candidate):
            if not os.path.isdir(candidate):
                return f"{candidate} is not a folder"
            if not os.access(candidate, os.W_OK | os.X_OK):
                return f"{candidate} is read-only"
            return None
    return f"none of {folder}'s parent folders exists"


def _temporary_file():
    """The per-user progress file of the session when the data folder cannot be written."""
    user = os.getuid() if hasattr(os, "getuid") else os.environ.get("USERNAME", "user")
    return Path(tempfile.gettempdir()).resolve() / f"{_APP}-{user}" / _FILE


def _locate(path=None):
    """``(file, note, name)``: the progress file, why it is a temporary one (None if it is not),
    and what chose it (``"path"``, the variable's name, or ``"the default progress file"``).

    See :func:`progress_path` for the rules.
    """
    default = False
    if path is None:
        env = os.environ.get(ENV_VAR, "").strip()
        default = not env
        path = env or _data_home() / _APP / _FILE
        name = ENV_VAR if env else "the default progress file"
    else:
        name = "path"
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a file path (str or os.PathLike), got "
                        f"{type(path).__name__}")
    resolved = Path(path).expanduser().resolve()
    root = _repository_root()
    if root is not None and resolved.is_relative_to(root) \
            and not _in_user_folder(resolved, root):
        folders = ", ".join(f"{f}/" for f in USER_FOLDERS)
        raise ValueError(f"{name} ({resolved}) lies inside the course repository ({root}); "
                         "progress is personal data: keep it in your data folder, a "
                         "temporary folder, or one of the repository's git-ignored per-user "
                         f"folders ({folders})")
    if default:
        reason = _unwritable(resolved.parent)
        if reason is not None:
            return _temporary_file(), (
                f"your data folder {resolved.parent} cannot be written ({reason})"), name
    return resolved, None, name


def _keep_hint():
    """What to do to keep the results: the variable to set, and how."""
    return (f"set the environment variable {ENV_VAR} to a file in a folder you can write "
            f"(in a notebook: import os; os.environ[{ENV_VAR!r}] = "
            "'/a/writable/folder/progress.json') to keep your results")


def progress_path(path=None):
    """The progress file: `path`, else ``$COURSE_PROGRESS_FILE``, else the user's data folder.

    A file inside the course repository is refused unless it lies in one of its git-ignored
    per-user folders (:data:`USER_FOLDERS`; on Binder the home folder is the repository). When
    the default folder cannot be written, the session's results go to a per-user temporary
    file instead (see the module's documentation).

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
        If the file would lie inside the course repository, outside its per-user folders.

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
    return _locate(path)[0]


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


def _private_folder(folder):
    """Make `folder` for this user only (mode 0700), refusing one that another user owns.

    The session's temporary progress file lives in the shared temporary folder, where anyone
    could have made a folder of that name first.
    """
    folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    if hasattr(os, "getuid"):
        info = os.lstat(folder)
        if os.path.islink(folder) or info.st_uid != os.getuid():
            raise PermissionError(errno.EACCES, f"{folder} belongs to another user")


def _write_atomic(file, data, private=False, chosen=None):
    """Write `data` as JSON to `file` atomically: temporary file, fsync, os.replace.

    `private`: `file` is the session's temporary file (its folder is made for this user only).
    An error making the folder or the temporary file names `file`, what `chosen` it, and what
    to do about it.
    """
    try:
        if private:
            _private_folder(file.parent)
        else:
            file.parent.mkdir(parents=True, exist_ok=True)
        fd, temporary = tempfile.mkstemp(dir=file.parent, prefix=f".{file.name}.",
                                         suffix=".tmp")
    except OSError as exc:
        by = f" (chosen by {chosen})" if chosen else ""
        raise type(exc)(exc.errno, f"cannot write the progress file {file}{by}: "
                        f"{exc.strerror or exc}; {_keep_hint()}") from exc
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
    OSError
        If the file cannot be written; the message names the file and ``COURSE_PROGRESS_FILE``.

    Warns
    -----
    ProgressFileWarning
        When the default data folder cannot be written and the result went to the session's
        temporary file instead (see the module's documentation).

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
    file, note, chosen = _locate(path)
    exams = _load(file)
    exams.append(record)
    _write_atomic(file, {"format": FORMAT, "version": VERSION, "exams": exams},
                  private=note is not None, chosen=chosen)
    if note is not None:
        warnings.warn(f"{note[0].upper()}{note[1:]}, so this result was saved to {file}, a "
                      "temporary file for this session only (it may be lost when the server "
                      f"stops): {_keep_hint()}.", ProgressFileWarning, stacklevel=2)
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
    file, note, _ = _locate(path)
    history = read_history(file)
    shown = _short(file)
    warning = [] if note is None else [
        "", f"**Note:** {note}, so your results are kept in `{shown}`, a temporary file for "
        f"this session only (it may be lost when the server stops): {_keep_hint()}."]
    if not history:
        return "\n".join([
            f"**No results yet.** There is no progress file at `{shown}` (or it holds no "
            "exam): take a mock exam in `notebooks/mock_exam.ipynb`, and your scores per "
            "chapter will show up here.", *warning])
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
    return "\n".join(lines + warning)
