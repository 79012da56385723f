"""The progress file's records: reading, setting aside what is bad, appending under a lock
(see :mod:`course_lib.progress`)."""
import contextlib
import errno
import json
import math
import os
import shutil
import sys
import tempfile
import warnings
from datetime import datetime, timezone

from . import _where
from ._where import (_EXAM_KEYS, FORMAT, VERSION, ProgressFileWarning, _keep_hint, _locate,
                     progress_path)

try:                                    # POSIX; on Windows appends go without a lock
    import fcntl
except ImportError:                     # pragma: no cover - not on the CI's platform
    fcntl = None

# ---------------------------------------------------------------------------------------------
# The file: a header line, then one JSON record per line
# ---------------------------------------------------------------------------------------------

_HEADER = {"format": FORMAT, "version": VERSION}
_HEADER_LINE = json.dumps(_HEADER, sort_keys=True) + "\n"
#: What an attempt, hint or solution record holds besides its ``kind`` (type per key).
_EVENT_KEYS = {"date": str, "key": str, "seed": int}
_STATUSES = ("correct", "wrong", "invalid")
#: What happened to each file in this session: what was set aside and why (for the report).
_NOTICES = {}


def _plain_int(x):
    return isinstance(x, int) and not isinstance(x, bool)


def _number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


def _lacking(record, types):
    """The first key of `types` whose value in `record` is not of its type (a bool is no int),
    as the reason; None when all are."""
    for key, kind in types.items():
        if not isinstance(record.get(key), kind) or isinstance(record.get(key), bool):
            return f"it lacks a valid {key!r}"
    return None


def _exam_problem(exam):
    """Why `exam` is not a valid exam record; None if it is."""
    if not isinstance(exam, dict):
        return "it is not a record"
    lacking = _lacking(exam, _EXAM_KEYS)
    if lacking is not None:
        return lacking
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
    lacking = _lacking(record, _EVENT_KEYS)
    if lacking is not None:
        return lacking
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


def _lines_of(raw):
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


def _blank(raw):
    """Whether a file's bytes hold nothing (an empty file is as good as none)."""
    return not raw.strip(b"\x00 \n")


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
            records, bad = _lines_of(raw)
            if records is None:             # no progress file at all: set the whole aside
                if _blank(raw):
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
    records, bad = _lines_of(raw)
    if records is not None and not bad:
        return records, notices
    if records is None and _blank(raw):
        return [], notices                    # an empty file: as good as none
    try:
        repaired = _repair(file, notices)
    except OSError as exc:
        repaired = None
        what = ("the file could not be read" if records is None else
                f"{sum(b[2] is not None for b in bad)} of its records could not be read")
        why = bad if records is None else bad[0][1]
        notices.append(f"In the progress file {file} {what} ({why}), "
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
    return _read(path)


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
    return [r for r in _read(path) if r.get("kind", "exam") == "exam"]


def _read(path):
    """The records of the progress file, with what happened to it remembered and warned of
    (at the caller of the public reader)."""
    file = progress_path(path)
    records, notices = _load(file)
    _remember(file, notices)
    _warn(notices, stacklevel=4)
    return records


def _remember(file, notices):
    """Keep what happened to `file` in this session, for :func:`progress_report`; returns
    `notices`."""
    kept = _NOTICES.setdefault(file, [])
    kept.extend(n for n in notices if n not in kept)
    return notices


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

    Returns the notices (where it went instead, or that it could not be saved), which are
    also remembered for the report of the progress file; never raises OSError.
    """
    file, note, chosen = _locate(path)
    notices = []
    tried = []
    if note is None:
        try:
            _append(file, record, durable, notices)
            return _remember(file, notices)
        except OSError as exc:
            tried.append(f"{file} (chosen by {chosen}) cannot be written: "
                         f"{exc.strerror or exc}")
            if isinstance(exc, IsADirectoryError) or file.is_dir():
                tried[-1] = f"{file} (chosen by {chosen}) is a folder, not a file"
    else:
        tried.append(note)
    spare = _where._temporary_file()
    if spare == file and tried and note is None:
        notices.append(f"Your result could not be saved: {tried[0]}; {_keep_hint()}.")
        return _remember(file, notices)
    try:
        _append(spare, record, durable, notices, private=True)
    except OSError as exc:
        notices.append(f"Your result could not be saved: {'; '.join(tried)}, and the temporary "
                       f"file {spare} cannot be written either ({exc.strerror or exc}); "
                       f"{_keep_hint()}.")
        return _remember(file, notices)
    reason = tried[0]
    notices.append(f"{reason[0].upper()}{reason[1:]}, so this result was saved to {spare}, a "
                   "temporary file for this session only (it may be lost when the server "
                   f"stops): {_keep_hint()}.")
    return _remember(file, notices)


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
    _warn(_save(record, path, durable=True), stacklevel=2)
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
    _warn(_save(record, path, durable=False), stacklevel=2)
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


