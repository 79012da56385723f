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
A file chosen explicitly (the variable or ``path``) that cannot be written is never replaced
either: that save goes to the same temporary file, with a warning naming the file, what chose
it and the variable.

What the file holds
-------------------
One JSON value per line (JSON Lines): the header ``{"format": "graphics-course-progress",
"version": 2}``, then one record per line, each with its ``kind`` and ``date``: ``"exam"`` (a
finished mock exam, as made by :meth:`course_lib.exercises.mock.Exam.record`), ``"attempt"``
(an exercise's answer checked: its ``key`` such as ``"ch05.Outcodes"``, ``seed``, ``status``,
``diagnosis``, ``credit`` and the ``hints`` seen before it), ``"hint"`` and ``"solution"``.

Writing
-------
A record is **appended** as one line, under an exclusive lock (``flock``) that every writer
takes: two kernels of one student (a lesson and the mock exam) saving at the same moment both
keep their records, and a save costs the same however long the history is. This was chosen
over rewriting the whole file under a lock, which is also lossless but grows with the history
(9.7 s per save for 73 MB). Exam results are flushed to disk (``fsync``); a crash can cut
at most the line being written, which the next reader sets aside and the next writer ends.

Bad files
---------
Nothing is ever deleted, and a bad file never stops a page. A record that cannot be read (not
JSON, nested thousands deep, an integer of thousands of digits, a float seed, more right than
asked...) is moved to ``<file>.rejected-<time>`` and the others are kept; a file that is no
progress file at all is renamed ``<file>.corrupt-<time>``; a version-1 file (one JSON
document) is upgraded, keeping a copy. A :class:`ProgressFileWarning` says each of these, and
:func:`progress_report` repeats it. A progress file that cannot be written (a folder in its
place, a read-only file or folder) is left alone: the result goes to the session's temporary
file, with a warning naming ``COURSE_PROGRESS_FILE``.
"""
import contextlib
import errno
import json
import math
import os
import re
import shutil
import sys
import tempfile
import warnings
from datetime import datetime, timezone
from pathlib import Path

try:                                    # POSIX; on Windows appends go without a lock
    import fcntl
except ImportError:                     # pragma: no cover - not on the CI's platform
    fcntl = None

__all__ = ["ENV_VAR", "FORMAT", "RECORD_VAR", "USER_FOLDERS", "VERSION", "ProgressFileWarning",
           "chapter_scores", "progress_path", "progress_report", "read_events", "read_history",
           "record_event", "record_exam", "recording", "topic_strength", "weakest_chapters",
           "weakest_topics"]

#: The environment variable that chooses the progress file.
ENV_VAR = "COURSE_PROGRESS_FILE"
#: The name of the file format, stored in the file.
FORMAT = "graphics-course-progress"
#: The version of the file format this module reads and writes.
VERSION = 2
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
# The file: a header line, then one JSON record per line
# ---------------------------------------------------------------------------------------------

_HEADER = {"format": FORMAT, "version": VERSION}
_HEADER_LINE = json.dumps(_HEADER, sort_keys=True) + "\n"
#: What each kind of record holds besides its ``kind`` and ``date`` (type per key).
_EVENT_KEYS = {"key": str, "seed": int}
_STATUSES = ("correct", "wrong", "invalid")
#: What happened to each file in this session: what was set aside and why (for the report).
_NOTICES = {}


def _plain_int(x):
    return isinstance(x, int) and not isinstance(x, bool)


def _number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _exam_problem(exam):
    """Why `exam` is not a valid exam record; None if it is."""
    if not isinstance(exam, dict):
        return "it is not a record"
    for key, kind in _EXAM_KEYS.items():
        if not isinstance(exam.get(key), kind) or isinstance(exam.get(key), bool):
            return f"it lacks a valid {key!r}"
    for chapter, pair in exam["score"].items():
        if not (chapter.isdigit() and isinstance(pair, list) and len(pair) == 2
                and _number(pair[0]) and _plain_int(pair[1]) and 0 <= pair[0] <= pair[1]):
            return f"it has an invalid score for chapter {chapter!r}"
    return None


def _record_problem(record):
    """Why `record` (one line of the file, parsed) is not a valid record; None if it is."""
    if not isinstance(record, dict):
        return "it is not a record"
    kind = record.get("kind")
    if kind == "exam":
        return _exam_problem(record)
    if kind not in ("attempt", "hint", "solution"):
        return f"it is of no known kind ({str(kind)[:40]!r})"
    if not isinstance(record.get("date"), str):
        return "it lacks a valid 'date'"
    for key, type_ in _EVENT_KEYS.items():
        if not isinstance(record.get(key), type_) or isinstance(record.get(key), bool):
            return f"it lacks a valid {key!r}"
    if kind == "attempt":
        if record.get("status") not in _STATUSES:
            return "it lacks a valid 'status'"
        credit = record.get("credit", 0.0)
        if not _number(credit) or not 0 <= credit <= 1:
            return "its 'credit' is not a share from 0 to 1"
        if not _plain_int(record.get("hints", 0)) or record.get("hints", 0) < 0:
            return "its 'hints' is not a count"
    return None


def _parse(raw):
    """The JSON value of `raw` bytes, or the reason it has none (a str in a tuple)."""
    try:
        return json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        # ValueError: not JSON, or an integer of thousands of digits; RecursionError: nesting
        kind = "nested too deeply" if isinstance(exc, RecursionError) else "not valid JSON"
        return (f"{kind}: {str(exc)[:120]}",)


def _is_header(value):
    return isinstance(value, dict) and value.get("format") == FORMAT \
        and value.get("version") == VERSION and "exams" not in value


def _split(raw):
    """``(records, bad)`` of a file's bytes; `bad` lists ``(line number, reason, bytes)``.

    Returns ``(None, reason)`` when the file is no progress file at all (neither this version's
    header line nor a whole version-1 document).
    """
    lines = raw.split(b"\n")
    first = _parse(lines[0]) if lines[0].strip() else ("an empty first line",)
    if not _is_header(first):
        return _from_version_1(raw)
    records, bad = [], []
    for number, line in enumerate(lines[1:], start=2):
        if not line.strip():
            continue
        value = _parse(line)
        reason = value[0] if isinstance(value, tuple) else _record_problem(value)
        if reason is None:
            records.append(value)
        else:
            bad.append((number, reason, line))
    return records, bad


def _from_version_1(raw):
    """The records of a version-1 file (one JSON document, ``{"exams": [...]}``)."""
    data = _parse(raw)
    if isinstance(data, tuple):
        return None, data[0]
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        return None, f"it is not a {FORMAT!r} file"
    if data.get("version") != 1:
        return None, (f"it has format version {data.get('version')!r}; this course reads "
                      f"{VERSION} (and 1)")
    exams = data.get("exams")
    if not isinstance(exams, list):
        return None, "its 'exams' entry is not a list"
    records, bad = [], []
    for k, exam in enumerate(exams):
        reason = _exam_problem(exam)
        if reason is None:
            records.append({**exam, "kind": "exam"})
        else:
            bad.append((f"exam {k}", reason, json.dumps(exam).encode()))
    return records, bad + [("version 1", "upgraded", None)]


def _stamp():
    return datetime.now(timezone.utc).strftime("%Y%m%dT%H%M%SZ")


def _free_name(file, suffix):
    target = file.with_name(f"{file.name}.{suffix}-{_stamp()}")
    k = 1
    while target.exists():
        target = file.with_name(f"{file.name}.{suffix}-{_stamp()}-{k}")
        k += 1
    return target


@contextlib.contextmanager
def _lock(file):
    """An exclusive lock on `file` (created if missing), held by every writer of it.

    Yields the open descriptor, or None when `file` was replaced while we waited (the caller
    tries again). POSIX ``flock``; elsewhere no lock (appends stay whole lines).
    """
    fd = os.open(file, os.O_RDWR | os.O_APPEND | os.O_CREAT, 0o600)
    try:
        if fcntl is not None:
            fcntl.flock(fd, fcntl.LOCK_EX)
        try:
            now = os.stat(file)
        except FileNotFoundError:
            now = None
        mine = os.fstat(fd)
        yield fd if now is not None and (now.st_ino, now.st_dev) == (mine.st_ino, mine.st_dev) \
            else None
    finally:
        os.close(fd)                          # releases the lock


def _read_all(fd):
    os.lseek(fd, 0, os.SEEK_SET)
    chunks = []
    while True:
        chunk = os.read(fd, 1 << 20)
        if not chunk:
            return b"".join(chunks)
        chunks.append(chunk)


def _rewrite(file, records, bad, notices):
    """Under the lock: keep `records` in `file`, move the `bad` lines to a side file."""
    rejected = [b for b in bad if b[2] is not None]
    if rejected:
        aside = _free_name(file, "rejected")
        aside.write_bytes(b"".join(line + b"\n" for _, _, line in rejected))
        listed = "; ".join(f"{'line ' if isinstance(n, int) else ''}{n}: {why}"
                           for n, why, _ in rejected[:3]) + ("; ..." if len(rejected) > 3 else "")
        notices.append(f"{len(rejected)} record{'s' if len(rejected) > 1 else ''} of the "
                       f"progress file {file} could not be read ({listed}). "
                       f"{'They were' if len(rejected) > 1 else 'It was'} moved to {aside} "
                       f"(nothing was deleted); your other {len(records)} records are kept.")
    if any(b[1] == "upgraded" for b in bad):
        backup = _free_name(file, "version-1")
        shutil.copy2(file, backup)
        notices.append(f"The progress file {file} was upgraded to this course's format; the "
                       f"old file was kept as {backup}.")
    _write_lines(file, records)


def _write_lines(file, records):
    """Replace `file` by the header and `records`, atomically (temporary file, fsync, replace)."""
    fd, temporary = tempfile.mkstemp(dir=file.parent, prefix=f".{file.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(_HEADER_LINE)
            for record in records:
                handle.write(json.dumps(record, sort_keys=True) + "\n")
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, file)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temporary)
        raise
    _fsync_folder(file.parent)


def _repair(file, notices):
    """Set aside what cannot be read in `file`, keeping the rest; returns the good records.

    Done under the writers' lock, on the file as it is then. When the folder cannot be written
    the file is left as it is and the notice says so.
    """
    for _ in range(5):
        with _lock(file) as fd:
            if fd is None:
                continue
            raw = _read_all(fd)
            records, bad = _split(raw)
            if records is None:             # no progress file at all: set the whole aside
                if not raw.strip(b"\x00 \n"):
                    return []
                target = _free_name(file, "corrupt")
                os.replace(file, target)
                _fsync_folder(file.parent)
                notices.append(f"The progress file {file} could not be read ({bad}). It was "
                               f"moved to {target} (nothing was deleted) and a new progress "
                               "file will be started.")
                return []
            if bad:
                _rewrite(file, records, bad, notices)
            return records
    return None


def _load(file):
    """``(records, notices)`` of `file`; what cannot be read is set aside (and noticed).

    Never raises: a file that cannot be opened, or a folder where nothing can be set aside,
    gives an empty or partial history and a notice.
    """
    notices = []
    try:
        raw = file.read_bytes()
    except FileNotFoundError:
        return [], notices
    except IsADirectoryError:
        notices.append(f"The progress file {file} is a folder, not a file: your results "
                       "cannot be read or saved there. Remove or rename that folder, or "
                       f"{_keep_hint()}.")
        return [], notices
    except OSError as exc:
        notices.append(f"The progress file {file} cannot be read ({exc.strerror or exc}).")
        return [], notices
    records, bad = _split(raw)
    if records is not None and not bad:
        return records, notices
    if records is None and not raw.strip(b"\x00 \n"):
        return [], notices                    # an empty file: as good as none
    try:
        repaired = _repair(file, notices)
    except OSError as exc:
        repaired = None
        what = ("the file could not be read" if records is None else
                f"{sum(b[2] is not None for b in bad)} of its records could not be read")
        notices.append(f"In the progress file {file} {what} ({bad if records is None else bad[0][1]}), "
                       f"and nothing could be set aside ({exc.strerror or exc}): "
                       "the readable records are used, the file is left as it is.")
    if repaired is None:
        repaired = records or []
    return repaired, notices


def _warn(notices, stacklevel=3):
    for notice in notices:
        warnings.warn(notice, ProgressFileWarning, stacklevel=stacklevel + 1)


def read_events(path=None):
    """Every record of the progress file, oldest first: exams, attempts, hints, solutions.

    Records that cannot be read are moved to a side file (``<file>.rejected-<time>``, never
    deleted) and a :class:`ProgressFileWarning` says so; the others are kept.

    Parameters
    ----------
    path : str or os.PathLike, optional
        See :func:`progress_path`.

    Returns
    -------
    list of dict
        Each with its ``kind`` (``"exam"``, ``"attempt"``, ``"hint"`` or ``"solution"``).

    Examples
    --------
    >>> import os, tempfile
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> _ = record_event("attempt", key="ch05.Outcodes", seed=3, status="wrong", path=file)
    >>> [(e["kind"], e["key"], e["status"]) for e in read_events(file)]
    [('attempt', 'ch05.Outcodes', 'wrong')]
    """
    file = progress_path(path)
    records, notices = _load(file)
    _remember(file, notices)
    _warn(notices)
    return records


def read_history(path=None):
    """The recorded exams, oldest first ([] when there is no progress file yet).

    What cannot be read is set aside and reported (see :func:`read_events`); the other
    records are kept.

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
    file = progress_path(path)
    records, notices = _load(file)
    _remember(file, notices)
    _warn(notices)
    return [r for r in records if r.get("kind", "exam") == "exam"]


def _remember(file, notices):
    """Keep what happened to `file` in this session, for :func:`progress_report`."""
    kept = _NOTICES.setdefault(file, [])
    kept.extend(n for n in notices if n not in kept)


# ---------------------------------------------------------------------------------------------
# Writing: one line appended under a lock, whatever the size of the history
# ---------------------------------------------------------------------------------------------

def _fsync_folder(folder):
    """Flush the folder's entry of a renamed file to disk (POSIX; a no-op elsewhere)."""
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


def _append(file, record, durable, notices, private=False):
    """Append `record` as one line to `file`, under the writers' lock.

    A new file gets the header first; a file that is not this version's (a version-1 file, a
    damaged one) is repaired first (see :func:`_repair`); a last line cut short by a crash is
    ended before the new one. `durable`: fsync (exam results; attempts are not worth a disk
    flush each).
    """
    if private:
        _private_folder(file.parent)
    else:
        file.parent.mkdir(parents=True, exist_ok=True)
    line = (json.dumps(record, sort_keys=True) + "\n").encode("utf-8")
    for _ in range(20):
        with _lock(file) as fd:
            if fd is None:                     # replaced (repaired) meanwhile: open it again
                continue
            size = os.fstat(fd).st_size
            if size:
                os.lseek(fd, 0, os.SEEK_SET)
                first = os.read(fd, len(_HEADER_LINE) + 64).split(b"\n")[0]
                if not _is_header(_parse(first)):
                    break                      # not this version's: repair, then append
                os.lseek(fd, size - 1, os.SEEK_SET)
                if os.read(fd, 1) != b"\n":
                    line_out = b"\n" + line    # the last write was cut short
                else:
                    line_out = line
            else:
                line_out = _HEADER_LINE.encode() + line
            os.write(fd, line_out)
            if durable:
                os.fsync(fd)
            return
    else:
        raise OSError(errno.EAGAIN, f"the progress file {file} kept changing")
    _repair(file, notices)
    _append(file, record, durable, notices, private)


def _save(record, path, durable):
    """Append `record` to the progress file; on failure to the session's temporary file.

    Returns ``(file or None, notices)``; never raises OSError.
    """
    file, note, chosen = _locate(path)
    notices = []
    tried = []
    if note is None:
        try:
            _append(file, record, durable, notices)
            return file, notices
        except OSError as exc:
            tried.append(f"{file} (chosen by {chosen}) cannot be written: "
                         f"{exc.strerror or exc}")
            if isinstance(exc, IsADirectoryError) or file.is_dir():
                tried[-1] = f"{file} (chosen by {chosen}) is a folder, not a file"
    else:
        tried.append(note)
    spare = _temporary_file()
    if spare == file and tried and note is None:
        notices.append(f"Your result could not be saved: {tried[0]}; {_keep_hint()}.")
        return None, notices
    try:
        _append(spare, record, durable, notices, private=True)
    except OSError as exc:
        notices.append(f"Your result could not be saved: {'; '.join(tried)}, and the temporary "
                       f"file {spare} cannot be written either ({exc.strerror or exc}); "
                       f"{_keep_hint()}.")
        return None, notices
    reason = tried[0]
    notices.append(f"{reason[0].upper()}{reason[1:]}, so this result was saved to {spare}, a "
                   "temporary file for this session only (it may be lost when the server "
                   f"stops): {_keep_hint()}.")
    return spare, notices


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


def _date(when):
    when = when or datetime.now(timezone.utc)
    if not isinstance(when, datetime):
        raise TypeError(f"when must be a datetime, got {type(when).__name__}")
    return when.isoformat(timespec="seconds")


def record_exam(result, path=None, when=None):
    """Add a finished exam to the progress file and return its record.

    The record is appended as one line under a lock, so two kernels saving at once both keep
    their results, and a save costs the same however long the history is. When the file cannot
    be written (a folder in its place, a read-only file or folder) the result goes to the
    session's temporary file and a :class:`ProgressFileWarning` says where and why.

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
        The record stored, with its ``date`` (and ``kind`` ``"exam"``).

    Raises
    ------
    TypeError, ValueError
        If `result` is not an exam record (nothing is written then).

    Warns
    -----
    ProgressFileWarning
        When the result went to the session's temporary file, or could not be saved at all,
        or when unreadable records of the file were set aside.

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
    record["date"] = _date(when)
    record["kind"] = "exam"
    reason = _exam_problem(record)
    if reason is not None:
        raise ValueError(f"result is not an exam record: {reason}")
    file, notices = _save(record, path, durable=True)
    _remember(progress_path(path), notices)
    _warn(notices, stacklevel=2)
    return record


def record_event(kind, key, seed, path=None, when=None, **fields):
    """Append one exercise event (an attempt, a hint, a solution shown) to the progress file.

    Parameters
    ----------
    kind : {"attempt", "hint", "solution"}
    key : str
        The exercise: ``"ch05.Outcodes"``.
    seed : int
        Its variant.
    path : str or os.PathLike, optional
    when : datetime.datetime, optional
    **fields
        An attempt's ``status`` (``"correct"``, ``"wrong"``, ``"invalid"``), ``diagnosis``,
        ``credit`` (0 to 1) and ``hints`` (how many were shown before it); a hint's ``n``.

    Returns
    -------
    dict
        The record stored.

    Raises
    ------
    ValueError
        If the record is not valid (nothing is written).

    Examples
    --------
    >>> import os, tempfile
    >>> file = os.path.join(tempfile.mkdtemp(), "progress.json")
    >>> record_event("hint", key="ch03.Slerp", seed=1, n=1, path=file)["kind"]
    'hint'
    """
    record = {"kind": kind, "key": key, "seed": seed, "date": _date(when), **fields}
    if kind == "attempt":
        record.setdefault("credit", float(record.get("status") == "correct"))
        record.setdefault("hints", 0)
    try:
        record = json.loads(json.dumps(record))
    except (TypeError, ValueError) as exc:
        raise ValueError(f"the {kind} record must hold JSON data only: {exc}") from None
    reason = _record_problem(record)
    if reason is not None:
        raise ValueError(f"not a valid {kind} record: {reason}")
    _, notices = _save(record, path, durable=False)
    _remember(progress_path(path), notices)
    _warn(notices, stacklevel=2)
    return record


#: The environment variable that turns the recording of exercise attempts on ("1") or off
#: ("0"); by default it is on inside a notebook's kernel and off elsewhere (scripts, tests).
RECORD_VAR = "COURSE_RECORD_ATTEMPTS"


def recording():
    """Whether exercise checks, hints and solutions are recorded (see :data:`RECORD_VAR`).

    Examples
    --------
    >>> import os
    >>> saved = os.environ.get("COURSE_RECORD_ATTEMPTS")
    >>> os.environ["COURSE_RECORD_ATTEMPTS"] = "0"
    >>> recording()
    False
    >>> _ = os.environ.pop("COURSE_RECORD_ATTEMPTS") if saved is None else None
    """
    value = os.environ.get(RECORD_VAR, "").strip().lower()
    if value in ("0", "no", "false", "off"):
        return False
    if value in ("1", "yes", "true", "on"):
        return True
    return "ipykernel" in sys.modules


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
        lines += [f"| {ch} | {_count(r)} | {t} | {100 * r / t:.0f}% |"
                  for ch, (r, t) in scores.items()]
        weak = weakest_chapters(history)
        lines.append("")
        if weak:
            listed = ", ".join(f"chapter {w['chapter']} ({_count(w['right'])} of {w['total']} "
                               "right)" for w in weak)
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
            lines.append(f"| {ch if ch is not None else '?'} | {kinds} | {variants} | {solved} "
                         f"| {100 * first_try / variants:.0f}% | {hints} |")
        weak = weakest_topics(events, n=3)
        if weak:
            lines += ["", "**Topics to practise:** " + ", ".join(
                f"`{row['key']}` ({row['first_try']} of {row['variants']} right at first try)"
                for row in weak) + "."]
    return "\n".join(lines + notes + warning)


def _count(x):
    """A score as written: 3, or 2.5 with partial credit."""
    return f"{x:g}" if isinstance(x, float) else str(x)
