"""Tests of course_lib.progress: where the file lives, appends under a lock that lose nothing
with several writers at once or a crash midway, bad files and bad records reported and set
aside (never overwritten, the good records kept), and the summaries (by hand here)."""
import json
import os
import shutil
import signal
import subprocess
import sys
import textwrap
import tempfile
import time
import warnings
from datetime import datetime, timezone
from pathlib import Path

import pytest

from course_lib import progress

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(autouse=True)
def _private_home(tmp_path, monkeypatch):
    """Nothing here may touch the real home: HOME, the data folder and the file are tmp."""
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    monkeypatch.setenv(progress.ENV_VAR, str(tmp_path / "progress.json"))


def record(seed=1, **score):
    """An exam record; `score` as ch3=(right, total), ..."""
    scores = {k[2:]: list(v) for k, v in score.items()} or {"3": [1, 2]}
    return {"seed": seed, "chapters": sorted(int(k) for k in scores),
            "n_questions": sum(t for _, t in scores.values()), "score": scores,
            "revisit": [{"chapter": 3, "key": "ch03.ComposeMatrix2D", "seed": 12,
                         "label": "Chapter 3: Compose (variant 12)"}]}


# --- where the file lives --------------------------------------------------------------------

def test_path_argument_then_environment_then_data_folder(tmp_path, monkeypatch):
    assert progress.progress_path(tmp_path / "a.json") == (tmp_path / "a.json").resolve()
    assert progress.progress_path() == (tmp_path / "progress.json").resolve()
    monkeypatch.delenv(progress.ENV_VAR)
    monkeypatch.setattr(sys, "platform", "linux")
    assert progress.progress_path() == (tmp_path / "data" / "graphics-course" /
                                        "progress.json").resolve()
    monkeypatch.delenv("XDG_DATA_HOME")
    assert progress.progress_path() == (tmp_path / "home" / ".local" / "share" /
                                        "graphics-course" / "progress.json").resolve()
    monkeypatch.setattr(sys, "platform", "darwin")
    assert progress.progress_path().parent.parent.name == "Application Support"


def test_a_file_inside_the_repository_is_refused(monkeypatch):
    with pytest.raises(ValueError, match="path .* inside the course repository"):
        progress.progress_path(ROOT / "progress.json")
    monkeypatch.setenv(progress.ENV_VAR, str(ROOT / "notebooks" / "p.json"))
    with pytest.raises(ValueError, match="COURSE_PROGRESS_FILE .* inside the course repo"):
        progress.read_history()
    with pytest.raises(TypeError, match="path must be a file path"):
        progress.progress_path(42)


# --- recording and reading -------------------------------------------------------------------

def lines(file):
    """The JSON values of the file's lines."""
    return [json.loads(line) for line in file.read_text().splitlines() if line.strip()]


def test_record_and_read_back(tmp_path):
    file = tmp_path / "progress.json"
    assert progress.read_history() == [] and not file.exists()   # reading creates nothing
    when = datetime(2026, 5, 4, 3, 2, 1, tzinfo=timezone.utc)
    stored = progress.record_exam(record(1, ch3=(1, 2), ch7=(0, 1)), when=when)
    progress.record_exam(record(2, ch5=(2, 2)))
    header, *records = lines(file)
    assert header == {"format": "graphics-course-progress", "version": 2}
    assert [(r["kind"], r["seed"]) for r in records] == [("exam", 1), ("exam", 2)]
    assert stored["date"] == "2026-05-04T03:02:01+00:00" == records[0]["date"]
    assert progress.read_history() == records
    assert sorted(p.name for p in tmp_path.iterdir()) == ["progress.json"]   # no temp left


def test_events_are_recorded_beside_the_exams(tmp_path):
    progress.record_event("attempt", key="ch05.Outcodes", seed=3, status="wrong",
                          diagnosis="bit order reversed", hints=0)
    progress.record_event("hint", key="ch05.Outcodes", seed=3, n=1)
    progress.record_exam(record(4))
    progress.record_event("attempt", key="ch05.Outcodes", seed=3, status="correct", hints=1)
    events = progress.read_events()
    assert [e["kind"] for e in events] == ["attempt", "hint", "exam", "attempt"]
    assert [e["seed"] for e in progress.read_history()] == [4]
    assert events[0]["credit"] == 0.0 and events[3]["credit"] == 1.0
    for bad in ({"kind": "attempt", "key": "k", "seed": 1.5, "status": "wrong"},
                {"kind": "attempt", "key": "k", "seed": 1, "status": "maybe"},
                {"kind": "chat", "key": "k", "seed": 1}):
        kind = bad.pop("kind")
        with pytest.raises(ValueError, match="not a valid"):
            progress.record_event(kind, **bad)
    assert len(progress.read_events()) == 4


def test_an_exam_object_is_recorded(tmp_path):
    from course_lib.exercises import mock_exam

    exam = mock_exam(3, chapters=[3, 7], n_questions=4)
    exam.submit(0, exam[0].source.letters[exam[0].source.correct]
                if exam[0].kind == "concept" else repr(exam[0].source.expected.tolist()))
    for i in range(1, 4):
        exam.submit(i, "")
    stored = progress.record_exam(exam)
    assert stored["score"] == {"3": [1, 2], "7": [0, 2]}
    assert len(stored["revisit"]) == 3


@pytest.mark.parametrize("bad, error", [
    ("not a record", TypeError),
    ({"seed": 1}, ValueError),
    ({**record(), "score": {"3": [3, 2]}}, ValueError),        # more right than asked
    ({**record(), "seed": object()}, TypeError),               # not JSON
])
def test_bad_records_are_refused_and_nothing_is_written(tmp_path, bad, error):
    with pytest.raises(error, match="result"):
        progress.record_exam(bad)
    assert not (tmp_path / "progress.json").exists()


# --- many writers, crashes -------------------------------------------------------------------

WRITER = """
import sys
from course_lib import progress
name, n = sys.argv[1], int(sys.argv[2])
for k in range(n):
    progress.record_exam({"seed": k, "chapters": [3], "n_questions": 1,
                          "score": {"3": [k % 2, 1]}, "revisit": [{"label": name}]})
    progress.record_event("attempt", key=f"ch03.{name}", seed=k, status="wrong")
"""


def test_several_processes_recording_at_once_lose_nothing(tmp_path):
    """Four processes (two kernels of one student, twice over), 100 exams and 100 attempts
    each, all at once: every one of the 800 records is in the file, each line whole."""
    file = tmp_path / "progress.json"
    names = ["lesson", "mock", "third", "fourth"]
    procs = [subprocess.Popen([sys.executable, "-c", WRITER, name, "100"], cwd=tmp_path,
                              env={**os.environ, "PYTHONPATH": str(ROOT),
                                   progress.ENV_VAR: str(file)}) for name in names]
    for proc in procs:
        assert proc.wait(timeout=600) == 0
    with warnings.catch_warnings():
        warnings.simplefilter("error")                       # nothing is set aside
        events = progress.read_events()
    exams = [e for e in events if e["kind"] == "exam"]
    assert len(exams) == 400 and len(events) == 800
    for name in names:
        mine = [e["seed"] for e in exams if e["revisit"][0]["label"] == name]
        assert mine == list(range(100))                      # in order, none lost or doubled
    assert file.read_text().count('"format"') == 1           # one header


def test_a_save_does_not_read_the_history(tmp_path, monkeypatch):
    """Saving appends one line: it never reads (let alone rewrites) the history, so it costs
    the same for a 73 MB file as for an empty one."""
    file = tmp_path / "progress.json"
    progress.record_exam(record(1))
    size = file.stat().st_size

    def no_reading(*args, **kwargs):
        raise AssertionError("a save read the whole history")

    before = file.read_bytes()
    with monkeypatch.context() as patched:
        for name in ("_load", "_read_all", "_write_lines", "_lines_of"):
            patched.setattr(progress._records, name, no_reading)
        progress.record_exam(record(2))
        progress.record_event("hint", key="ch03.A", seed=1, n=1)
    assert file.stat().st_size > size and file.read_bytes()[:size] == before
    assert [e["seed"] for e in progress.read_events()] == [1, 2, 1]


def test_a_process_killed_mid_write_loses_only_its_own_line(tmp_path):
    """A real crash: the writer is killed (SIGKILL) with half its line written. The records
    before it are kept, the torn line is set aside, and the next save works."""
    file = tmp_path / "progress.json"
    progress.record_exam(record(1))
    started = tmp_path / "started"
    script = textwrap.dedent(f"""
        import os, time
        from course_lib import progress
        real_write = os.write

        def slow_write(fd, data):
            real_write(fd, data[: len(data) // 2])
            os.fsync(fd)
            open({str(started)!r}, "w").close()
            time.sleep(60)                                  # killed here

        os.write = slow_write
        progress.record_exam({record(2)!r}, path={str(file)!r})
    """)
    proc = subprocess.Popen([sys.executable, "-c", script], cwd=tmp_path,
                            env={**os.environ, "PYTHONPATH": str(ROOT)})
    try:
        for _ in range(600):
            if started.exists() or proc.poll() is not None:
                break
            time.sleep(0.05)
        assert started.exists(), "the writer never reached the middle of its write"
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=30)
    assert proc.returncode == -signal.SIGKILL
    progress.record_exam(record(3), path=file)               # the lock died with the writer
    with pytest.warns(progress.ProgressFileWarning, match="1 record .* could not be read"):
        assert [e["seed"] for e in progress.read_history(file)] == [1, 3]
    [aside] = tmp_path.glob("progress.json.rejected-*")
    assert aside.read_text().startswith("{") and '"seed": 2' not in file.read_text()


# --- bad files: a warning and a working page, never a traceback -------------------------------

HEADER = b'{"format": "graphics-course-progress", "version": 2}\n'
GOOD = json.dumps({**record(9), "kind": "exam", "date": "2026-01-01T00:00:00+00:00"}).encode()


@pytest.mark.parametrize("content, reason", [
    (b'{"format": "graphics-course-progress", "version": 1, "exams": [', "not valid JSON"),
    (b"\xff\xfe garbage", "not valid JSON"),
    (b'{"theme": "dark"}', "is not a 'graphics-course-progress' file"),
    (b"[1, 2, 3]", "is not a 'graphics-course-progress' file"),
    (b'{"format": "graphics-course-progress", "version": 7, "exams": []}', "version 7"),
    (b'{"format": "graphics-course-progress", "version": 1, "exams": {}}', "not a list"),
    (b"[" * 100_000 + b"]" * 100_000, "nested too deeply"),          # 200 kB of [[[...]]]
    (b"1" * 5000, "not valid JSON.*digits"),                          # a 5,000-digit integer
])
def test_files_that_are_no_progress_file_are_set_aside(tmp_path, content, reason):
    file = tmp_path / "progress.json"
    file.write_bytes(content)
    with pytest.warns(progress.ProgressFileWarning, match=reason) as caught:
        assert progress.read_history() == []
    aside = list(tmp_path.glob("progress.json.corrupt-*"))
    assert len(aside) == 1 and aside[0].read_bytes() == content     # kept, byte for byte
    assert str(aside[0]) in str(caught[0].message) and not file.exists()
    report = progress.progress_report()          # says what happened, not "no progress file"
    assert "could not be read" in report and str(aside[0]) in report
    assert "There is no progress file" not in report
    progress.record_exam(record(5))                                  # a fresh file starts
    assert [e["seed"] for e in progress.read_history()] == [5]
    assert aside[0].read_bytes() == content


@pytest.mark.parametrize("bad_line, reason", [
    (json.dumps({**record(2), "kind": "exam", "date": "d", "seed": 2.5}).encode(), "'seed'"),
    (json.dumps({**record(2), "kind": "exam", "date": "d",
                 "score": {"3": [3, 2]}}).encode(), "invalid score"),
    (b"[" * 100_000 + b"]" * 100_000, "nested too deeply"),
    (b'{"kind": "exam", "seed": ' + b"7" * 5000 + b"}", "not valid JSON"),
    (b"garbage", "not valid JSON"),
])
def test_one_bad_record_is_set_aside_and_the_others_kept(tmp_path, bad_line, reason):
    file = tmp_path / "progress.json"
    file.write_bytes(HEADER + GOOD + b"\n" + bad_line + b"\n" + GOOD + b"\n")
    with pytest.warns(progress.ProgressFileWarning, match=f"1 record .*{reason}.*other 2 "
                      "records are kept"):
        assert [e["seed"] for e in progress.read_history()] == [9, 9]
    [aside] = tmp_path.glob("progress.json.rejected-*")
    assert aside.read_bytes() == bad_line + b"\n"
    assert file.read_bytes().count(b"\n") == 3                        # header + 2 good
    assert "could not be read" in progress.progress_report()
    with warnings.catch_warnings():
        warnings.simplefilter("error")                                 # repaired: quiet now
        assert len(progress.read_history()) == 2


def test_a_version_1_file_is_upgraded_keeping_its_valid_exams(tmp_path):
    file = tmp_path / "progress.json"
    old = {"format": "graphics-course-progress", "version": 1, "exams": [
        {**record(1), "date": "2026-01-01T00:00:00+00:00"}, {"seed": 1.5},
        {**record(2), "date": "2026-01-02T00:00:00+00:00"}]}
    file.write_text(json.dumps(old))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert [e["seed"] for e in progress.read_history()] == [1, 2]
    said = [str(w.message) for w in caught]
    assert any("1 record" in w and "exam 1" in w and "other 2 records are kept" in w
               for w in said), said
    assert any("upgraded" in w for w in said), said
    assert [json.loads(p.read_text()) for p in tmp_path.glob("progress.json.version-1-*")] \
        == [old]
    progress.record_exam(record(3))
    assert [e["seed"] for e in progress.read_history()] == [1, 2, 3]


def test_a_folder_at_the_path_gives_a_warning_and_the_temporary_file(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    monkeypatch.setattr(tempfile, "tempdir", None)
    (tmp_path / "tmp").mkdir()
    (tmp_path / "progress.json").mkdir()
    with pytest.warns(progress.ProgressFileWarning, match="is a folder"):
        assert progress.read_history() == []
    with pytest.warns(progress.ProgressFileWarning, match="is a folder, not a file.*saved to "
                      ".*temporary file.*COURSE_PROGRESS_FILE"):
        progress.record_exam(record(6))
    spare = tmp_path / "tmp" / f"graphics-course-{os.getuid()}" / "progress.json"
    assert [e["seed"] for e in progress.read_history(spare)] == [6]
    assert "is a folder" in progress.progress_report()


READ_ONLY = """
import json, warnings
from course_lib import progress
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    seeds = [e["seed"] for e in progress.read_history()]
    progress.record_exam({"seed": 7, "chapters": [3], "n_questions": 1, "score": {"3": [1, 1]},
                          "revisit": []})
print(json.dumps({"seeds": seeds, "warnings": [str(w.message) for w in caught],
                  "report": progress.progress_report()}))
"""


def test_a_corrupt_file_in_a_read_only_folder_is_reported_not_raised(tmp_path):
    folder = tmp_path / "ro"
    folder.mkdir()
    file = folder / "progress.json"
    content = HEADER + GOOD + b"\nbroken\n"
    file.write_bytes(content)
    (tmp_path / "tmp").mkdir()
    prefix = _read_only(folder)
    if prefix is None:
        pytest.skip("cannot make a read-only folder here (root without unshare/mount)")
    try:
        env = {"HOME": str(tmp_path), progress.ENV_VAR: str(file), "PYTHONPATH": str(ROOT),
               "TMPDIR": str(tmp_path / "tmp")}
        answer = _run(READ_ONLY, env, tmp_path, prefix)
    finally:
        folder.chmod(0o755)
    assert answer["seeds"] == [9]                          # the good record is still read
    said = " ".join(answer["warnings"])
    assert "nothing could be set aside" in said and "saved to" in said
    assert "temporary file" in said and "COURSE_PROGRESS_FILE" in said
    assert "nothing could be set aside" in answer["report"]
    assert file.read_bytes() == content                    # left as it was
    spare = tmp_path / "tmp" / f"graphics-course-{os.getuid()}" / "progress.json"
    assert [e["seed"] for e in progress.read_history(spare)] == [7]


def test_a_read_only_progress_file_is_not_replaced_but_warned_about(tmp_path):
    file = tmp_path / "progress.json"
    progress.record_exam(record(1))
    before = file.read_bytes()
    (tmp_path / "tmp").mkdir()
    prefix = _read_only(file)
    if prefix is None:
        pytest.skip("cannot make a read-only file here (root without unshare/mount)")
    try:
        env = {"HOME": str(tmp_path), progress.ENV_VAR: str(file), "PYTHONPATH": str(ROOT),
               "TMPDIR": str(tmp_path / "tmp")}
        answer = _run(READ_ONLY, env, tmp_path / "tmp", prefix)
    finally:
        file.chmod(0o644)
    assert answer["seeds"] == [1]
    [warning] = answer["warnings"]
    assert f"{file} (chosen by COURSE_PROGRESS_FILE) cannot be written" in warning
    assert "saved to" in warning and "temporary file for this session" in warning
    assert file.read_bytes() == before                     # not replaced


# --- summaries -------------------------------------------------------------------------------

def test_chapter_scores_and_weakest_chapters_by_hand():
    history = [record(1, ch3=(1, 2), ch5=(0, 1), ch7=(2, 2)),
               record(2, ch3=(1, 2), ch10=(1, 4), ch12=(1, 2))]
    assert progress.chapter_scores(history) == {3: (2, 4), 5: (0, 1), 7: (2, 2), 10: (1, 4),
                                                12: (1, 2)}
    # shares: ch5 0, ch10 0.25, ch3 0.5 (4 asked) before ch12 0.5 (2 asked); ch7 is perfect
    weakest = progress.weakest_chapters(history, n=4)
    assert [w["chapter"] for w in weakest] == [5, 10, 3, 12]
    assert [w["share"] for w in weakest] == [0.0, 0.25, 0.5, 0.5]
    assert [w["chapter"] for w in progress.weakest_chapters(history, n=2)] == [5, 10]
    with pytest.raises(ValueError, match="n must be"):
        progress.weakest_chapters(history, n=0)


def test_weakest_chapters_read_from_the_file_and_the_report():
    assert progress.weakest_chapters() == []
    assert progress.progress_report().startswith("**No results yet.**")
    progress.record_exam(record(1, ch4=(0, 2), ch6=(1, 1)))
    assert [w["chapter"] for w in progress.weakest_chapters()] == [4]
    report = progress.progress_report()
    assert "1 mock exam taken" in report and "| 4 | 0 | 2 | 0% |" in report
    assert "chapter 4 (0 of 2 right)" in report and "Chapter 3: Compose (variant 12)" in report


# --- Binder and hub layouts: HOME is the repository, or cannot be written -------------------

GIT = ("git", "-c", "core.excludesFile=/dev/null", "-c", "user.name=course tests",
       "-c", "user.email=tests@example.invalid", "-c", "commit.gpgsign=false",
       "-c", "init.defaultBranch=main")


def _needs_git():
    if shutil.which("git") is None:
        pytest.skip("git is not installed: it is needed to ask what .gitignore excludes")


def _git(folder, *args, check=True):
    return subprocess.run([*GIT, *args], cwd=folder, capture_output=True, text=True,
                          check=check)


def test_every_user_folder_allowed_in_the_repository_is_ignored_by_gitignore(tmp_path):
    """The rule (USER_FOLDERS) and .gitignore cannot drift apart: git itself, given only the
    repository's .gitignore, must ignore a progress file in every allowed folder."""
    _needs_git()
    assert ".local" in progress.USER_FOLDERS          # the default ~/.local/share/... needs it
    only_gitignore = tmp_path / "repo"
    only_gitignore.mkdir()
    shutil.copy(ROOT / ".gitignore", only_gitignore / ".gitignore")
    _git(only_gitignore, "init", "-q")

    def ignored(name):
        return _git(only_gitignore, "check-ignore", "-q", name, check=False).returncode == 0

    for folder in progress.USER_FOLDERS:
        name = f"{folder}/share/graphics-course/progress.json"
        assert ignored(name), f"{folder}/ is allowed for the progress file but not in .gitignore"
        assert progress.progress_path(ROOT / name) == (ROOT / name).resolve()   # allowed
        nested = ROOT / "notebooks" / folder / "progress.json"         # not at the top: refused
        assert not ignored(str(nested.relative_to(ROOT)))
        with pytest.raises(ValueError, match="inside the course repository"):
            progress.progress_path(nested)
    for name in ("progress.json", "notebooks/progress.json", "course_lib/progress.json",
                 ".localx/progress.json"):
        assert not ignored(name), f"the check is meaningless: git ignores {name}"
        with pytest.raises(ValueError, match="inside the course repository"):
            progress.progress_path(ROOT / name)


def _copy_of_course(target):
    """What the progress module needs of the repository: course_lib, pyproject, .gitignore."""
    shutil.copytree(ROOT / "course_lib", target / "course_lib",
                    ignore=shutil.ignore_patterns("__pycache__"))
    for name in ("pyproject.toml", ".gitignore"):
        shutil.copy(ROOT / name, target / name)
    return target


RECORD = """
import json, warnings
from course_lib import progress
from course_lib.exercises import mock_exam

exam = mock_exam(5, chapters=[3], n_questions=2)
for i in range(len(exam)):
    exam.submit(i, "")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    try:
        progress.record_exam(exam)
        error = None
    except OSError as exc:
        error = str(exc)
print(json.dumps({"module": progress.__file__, "file": str(progress.progress_path()),
                  "error": error, "exams": len(progress.read_history()),
                  "warnings": [str(w.message) for w in caught
                               if issubclass(w.category, progress.ProgressFileWarning)],
                  "report": progress.progress_report()}))
"""


def _run(script, env, cwd, prefix=()):
    """Run `script` in a fresh interpreter in `cwd` with exactly `env` (plus PATH); its JSON
    answer. (Not in the repository: `python -c` imports from its working folder first.)"""
    env = {"PATH": os.environ.get("PATH", ""), **env}
    done = subprocess.run([*prefix, sys.executable, "-c", script], env=env, cwd=cwd,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_with_home_in_a_copy_of_the_repository_the_exam_lands_in_an_ignored_folder(tmp_path):
    """Binder's layout: HOME is the repository, no XDG_DATA_HOME, no COURSE_PROGRESS_FILE."""
    _needs_git()
    home = _copy_of_course(tmp_path / "jovyan")
    _git(home, "init", "-q")
    _git(home, "add", "-A")
    _git(home, "commit", "-q", "-m", "the course")
    answer = _run(RECORD, {"HOME": str(home), "PYTHONPATH": str(home)}, cwd=home)
    assert Path(answer["module"]).is_relative_to(home)       # course_lib of the copy
    expected = home / ".local" / "share" / "graphics-course" / "progress.json"
    assert answer["error"] is None and answer["warnings"] == []
    assert Path(answer["file"]) == expected.resolve() and answer["exams"] == 1
    assert json.loads(expected.read_text().splitlines()[1])["seed"] == 5
    assert "`~/.local/share/graphics-course/progress.json`" in answer["report"]
    assert _git(home, "status", "--porcelain", "--untracked-files=all").stdout == ""
    assert _git(home, "check-ignore", "-q", str(expected), check=False).returncode == 0


def _read_only(path):
    """A command prefix under which `path` (a folder, or a file alone) is read-only, for root
    as well (a read-only bind mount in a private mount namespace; otherwise its mode); None
    when this machine cannot make one."""
    folder = path.is_dir()
    if os.geteuid() != 0:
        path.chmod(0o555 if folder else 0o444)
        return ()
    unshare = shutil.which("unshare")
    if unshare is None:
        return None
    prefix = (unshare, "--mount", "sh", "-c",
              'mount --bind -o ro "$0" "$0" && exec "$@"', str(path))
    write = 'touch "$0/probe"' if folder else 'echo x >> "$0"'
    probe = subprocess.run([*prefix, "sh", "-c", write, str(path)],
                           capture_output=True, text=True)
    return prefix if probe.returncode != 0 and "Read-only" in probe.stderr else None


def test_a_read_only_home_gives_a_temporary_file_and_says_which_variable_to_set(tmp_path):
    home = tmp_path / "home"
    home.mkdir()
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    prefix = _read_only(home)
    if prefix is None:
        pytest.skip("cannot make a read-only folder here (root without unshare/mount)")
    try:
        env = {"HOME": str(home), "PYTHONPATH": str(ROOT), "TMPDIR": str(temporary)}
        answer = _run(RECORD, env, tmp_path, prefix)
        fallback = temporary / f"graphics-course-{os.getuid()}" / "progress.json"
        assert answer["error"] is None, answer["error"]
        assert Path(answer["file"]) == fallback.resolve() and answer["exams"] == 1
        assert json.loads(fallback.read_text().splitlines()[1])["seed"] == 5
        assert fallback.parent.stat().st_mode & 0o777 == 0o700      # this user's only
        [warning] = answer["warnings"]
        for text in (warning, answer["report"]):
            assert f"{home / '.local' / 'share' / 'graphics-course'} cannot be written" in text
            assert "temporary file for this session only" in text
            assert "COURSE_PROGRESS_FILE" in text
        assert answer["report"].startswith("**1 mock exam taken**")
        # a file chosen explicitly is never replaced: the temporary file, and a warning
        # naming the file, what chose it and the variable
        chosen = {**env, "COURSE_PROGRESS_FILE": str(home / "mine" / "progress.json")}
        answer = _run(RECORD, chosen, tmp_path, prefix)
        assert answer["error"] is None and answer["exams"] == 0
        [warning] = answer["warnings"]
        assert f"{home / 'mine' / 'progress.json'} (chosen by COURSE_PROGRESS_FILE) cannot " \
            "be written" in warning
        assert "set the environment variable COURSE_PROGRESS_FILE" in warning
        assert f"saved to {fallback.resolve()}" in warning
        assert list(home.iterdir()) == []                           # nothing was written
    finally:
        home.chmod(0o755)


def test_a_data_folder_that_cannot_be_created_falls_back_to_a_temporary_file(tmp_path,
                                                                             monkeypatch):
    home = tmp_path / "home"
    home.mkdir()
    (home / ".local").write_text("a file where the data folder should be")
    monkeypatch.setenv("HOME", str(home))
    monkeypatch.delenv("XDG_DATA_HOME")
    monkeypatch.delenv(progress.ENV_VAR)
    monkeypatch.setattr(sys, "platform", "linux")
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    monkeypatch.setattr(tempfile, "tempdir", None)       # re-read TMPDIR
    (tmp_path / "tmp").mkdir()
    fallback = tmp_path / "tmp" / f"graphics-course-{os.getuid()}" / "progress.json"
    assert progress.progress_path() == fallback.resolve()
    assert progress.read_history() == [] and not fallback.parent.exists()   # reading makes none
    with pytest.warns(progress.ProgressFileWarning, match=r"\.local is not a folder.*"
                      r"temporary file for this session only.*COURSE_PROGRESS_FILE"):
        progress.record_exam(record(7))
    assert [e["seed"] for e in progress.read_history()] == [7]
    assert "cannot be written" in progress.progress_report()
    assert (home / ".local").read_text() == "a file where the data folder should be"


def test_a_temporary_folder_of_another_user_is_refused(tmp_path, monkeypatch):
    """Anyone may make folders in the shared temporary folder: never write into another's."""
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    (tmp_path / "home").write_text("not a folder")
    monkeypatch.delenv("XDG_DATA_HOME")
    monkeypatch.delenv(progress.ENV_VAR)
    monkeypatch.setattr(sys, "platform", "linux")
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    monkeypatch.setattr(tempfile, "tempdir", None)
    me = os.getuid() + 1                  # pretend to be another user than the folder's owner
    (tmp_path / f"graphics-course-{me}").mkdir()
    monkeypatch.setattr(os, "getuid", lambda: me)
    with pytest.warns(progress.ProgressFileWarning, match="could not be saved.*belongs to "
                      "another user.*COURSE_PROGRESS_FILE"):
        progress.record_exam(record(8))
    assert list((tmp_path / f"graphics-course-{me}").iterdir()) == []


def test_the_report_of_hints_without_a_checked_answer(tmp_path):
    """A student who asked for a hint and has not checked an answer yet (found by running the
    start page after an exercise notebook: a ZeroDivisionError): the chapter shows its hint
    and no share of first-try answers."""
    progress.record_event("hint", key="ch03.ComposeMatrix2D", seed=0, n=1)
    report = progress.progress_report()
    assert "**No mock exam taken yet**" in report
    assert "| 3 | 1 | 0 | 0 | — | 1 |" in report, report
