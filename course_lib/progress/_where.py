"""Where the progress file lives (see :mod:`course_lib.progress`)."""
import os
import sys
import tempfile
from pathlib import Path

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
    root = Path(__file__).resolve().parents[2]
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


