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
from ._where import (ENV_VAR, FORMAT, USER_FOLDERS, VERSION, ProgressFileWarning,
                     progress_path)
from ._records import RECORD_VAR, read_events, read_history, record_event, record_exam, recording
from ._summaries import (chapter_scores, progress_report, topic_strength, weakest_chapters,
                         weakest_topics)

__all__ = ["ENV_VAR", "FORMAT", "RECORD_VAR", "USER_FOLDERS", "VERSION", "ProgressFileWarning",
           "chapter_scores", "progress_path", "progress_report", "read_events", "read_history",
           "record_event", "record_exam", "recording", "topic_strength", "weakest_chapters",
           "weakest_topics"]
