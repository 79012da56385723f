"""The ways a student gets the course, end to end.

- **pip**: `pip install .` without the test extra (exactly what a student installs) in a fresh
  virtual environment, and every notebook of notebooks/, solutions/ and exercises/ executed top
  to bottom in that environment's own kernel: a lesson that imports a test-only library fails
  here with the notebook, the cell and the error.
- **Binder**: the repository is copied into the home folder. The start page runs there, a mock
  exam recorded through the library shows up on it, and git sees no new or changed file (the
  progress file lands in a git-ignored per-user folder, see course_lib.progress).
- **Binder's build**: `repo2docker --no-build` prints the Dockerfile Binder would build (no
  container engine needed): it installs apt.txt, builds environment.yml, runs postBuild and
  starts through the `start` script, which gives VTK its EGL window.

The runtime-only environment is kept in build/runtime-venv (git-ignored; `make clean` removes
it) and rebuilt only when pyproject.toml or the Python version changes; course_lib is
reinstalled into it when its sources change.
"""
import concurrent.futures
import contextlib
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import nbformat
import pytest
import yaml
from nbformat.v4 import new_code_cell, new_notebook

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK_DIRS = ("notebooks", "solutions", "exercises")
RUNTIME_VENV = ROOT / "build" / "runtime-venv"
EXECUTE = ROOT / "scripts" / "execute-notebooks"
# what the kernels of a test must not inherit from the pytest process: its import path, the
# main environment, conftest's progress file, matplotlib's backend (nbval's kernels get none in
# CI either: ipykernel picks its inline default and the notebooks' %matplotlib widget ipympl)
PARENT_ONLY = ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "MPLBACKEND", "JUPYTER_PATH",
               "COURSE_PROGRESS_FILE", "XDG_DATA_HOME")
GIT = ("git", "-c", "core.excludesFile=/dev/null", "-c", "user.name=course tests",
       "-c", "user.email=tests@example.invalid", "-c", "commit.gpgsign=false",
       "-c", "init.defaultBranch=main")


def _tracked_files():
    """The repository's files as a fresh clone would have them (plus new, not ignored ones)."""
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("needs git and a git work tree (a clone of the course) to know which files "
                    "a student gets")
    listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others",
                             "--exclude-standard"], cwd=ROOT, capture_output=True, check=True)
    names = sorted({n for n in listed.stdout.decode().split("\0") if n})
    return [n for n in names if (ROOT / n).is_file()]        # a file deleted in the work tree


def copy_of_repository(target):
    """Copy the tracked files into `target` (as a student's clone, without .git)."""
    for name in _tracked_files():
        dest = target / name
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / name, dest)
    return target


def _private_dirs(folder):
    """Jupyter's, IPython's and matplotlib's folders in `folder`, not the real home's."""
    names = {"JUPYTER_CONFIG_DIR": "jupyter-config", "JUPYTER_DATA_DIR": "jupyter-data",
             "JUPYTER_RUNTIME_DIR": "jupyter-runtime", "IPYTHONDIR": "ipython",
             "MPLCONFIGDIR": "matplotlib", "XDG_CACHE_HOME": "cache",
             "XDG_CONFIG_HOME": "config"}
    for name in names.values():
        (folder / name).mkdir(parents=True, exist_ok=True)
    return {var: str(folder / name) for var, name in names.items()}


def execute_notebooks(python, notebooks, env, workers=2, prefix=()):
    """Execute `notebooks` with scripts/execute-notebooks run by `python`, `workers` at a time.

    Each worker is one runner process that takes notebook after notebook (each in a fresh
    kernel) from a shared queue, so the runner's start-up is paid once per worker. `prefix`: a
    command that starts the runner (Binder's start script). Returns the runner's JSON results,
    one per notebook, in the order given.
    """
    import queue
    import tempfile

    todo = queue.Queue()
    for k, path in enumerate(notebooks):
        todo.put((k, path))
    results = [None] * len(notebooks)

    def start():
        log = tempfile.TemporaryFile(mode="w+")
        proc = subprocess.Popen([*map(str, prefix), str(python), str(EXECUTE), "--json",
                                 "--stdin"], env=env, cwd=Path(notebooks[0]).parent,
                                stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=log,
                                text=True, bufsize=1)
        return proc, log

    def work():
        proc, log = start()
        try:
            while True:
                try:
                    k, path = todo.get_nowait()
                except queue.Empty:
                    return
                try:
                    proc.stdin.write(f"{path}\n")
                    proc.stdin.flush()
                    line = proc.stdout.readline()
                except BrokenPipeError:
                    line = ""
                if line.startswith("{"):
                    results[k] = json.loads(line)
                    continue
                proc.kill()                                   # the runner itself died
                proc.wait()
                log.seek(0)
                results[k] = {"notebook": str(path), "ok": False, "cell": None,
                              "seconds": None, "traceback": log.read()[-4000:],
                              "error": f"the runner exited with {proc.returncode}"}
                log.close()
                proc, log = start()
        finally:
            with contextlib.suppress(BrokenPipeError):
                proc.stdin.close()
            try:
                proc.wait(timeout=60)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
            log.close()

    with concurrent.futures.ThreadPoolExecutor(max_workers=workers) as pool:
        for future in [pool.submit(work) for _ in range(min(workers, len(notebooks)))]:
            future.result()
    return results


def _ends(text, keep=1500):
    """The first and the last `keep` characters of `text` (a kernel's own error comes first)."""
    return text if len(text) <= 2 * keep else f"{text[:keep]}\n[...]\n{text[-keep:]}"


def _failures(results, root):
    """A readable account of the notebooks that failed: notebook, cell, error, traceback."""
    lines = []
    for r in results:
        if not r["ok"]:
            name = Path(r["notebook"]).relative_to(root)
            lines += [f"--- {name}, cell {r.get('cell')}: {r.get('error')}",
                      textwrap.indent(r.get("source", ""), "    | ", lambda line: True),
                      _ends(r.get("traceback", ""))]
    return "\n".join(lines)


# ---------------------------------------------------------------------------------------------
# The pip route: lessons need only the runtime dependencies
# ---------------------------------------------------------------------------------------------

def _digest(root, names):
    """A hash of the files `names` under `root`: their paths and contents."""
    h = hashlib.sha256()
    for name in names:
        h.update(str(name).encode() + b"\0" + (root / name).read_bytes() + b"\0")
    return h.hexdigest()


@contextlib.contextmanager
def _locked(path):
    """An exclusive lock on `path` (two pytest workers never build the environment at once)."""
    import fcntl

    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w") as handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def runtime_environment(source):
    """build/runtime-venv with `pip install <source>` (no extras); its Python.

    Made anew when pyproject.toml or the Python version changed (the stamp holds their hash),
    else reused; `pip install` runs again when course_lib's sources changed.
    """
    python = RUNTIME_VENV / "bin" / "python"
    stamp = RUNTIME_VENV / ".course-stamp.json"
    wanted = {
        "dependencies": hashlib.sha256((source / "pyproject.toml").read_bytes()
                                       + sys.version.encode()).hexdigest(),
        "course_lib": _digest(source, sorted(
            p.relative_to(source) for p in (source / "course_lib").rglob("*")
            if p.is_file() and "__pycache__" not in p.parts)),
    }
    with _locked(RUNTIME_VENV.parent / "runtime-venv.lock"):
        have = json.loads(stamp.read_text()) if stamp.is_file() else {}
        if have.get("dependencies") != wanted["dependencies"] or not python.exists():
            shutil.rmtree(RUNTIME_VENV, ignore_errors=True)
            subprocess.run([sys.executable, "-m", "venv", str(RUNTIME_VENV)], check=True)
            have = {}
        if have != wanted:
            stamp.unlink(missing_ok=True)
            done = subprocess.run([str(python), "-m", "pip", "install", "--quiet",
                                   str(source)], capture_output=True, text=True)
            assert done.returncode == 0, (
                f"`pip install .` (no extras) failed in {RUNTIME_VENV}:\n{done.stderr[-3000:]}")
            stamp.write_text(json.dumps(wanted))
    return python


PROBE = [
    "import sys\nimport course_lib\nprint(sys.prefix)\nprint(course_lib.__file__)",
    "try:\n    import scipy\nexcept ModuleNotFoundError:\n    print('scipy: not installed')\n"
    "else:\n    print('scipy: installed at', scipy.__file__)",
]


def test_every_notebook_runs_with_only_the_runtime_dependencies(tmp_path):
    started = time.monotonic()
    source = copy_of_repository(tmp_path / "clone")
    python = runtime_environment(source)
    built = time.monotonic() - started
    notebooks = sorted((p for d in NOTEBOOK_DIRS for p in (source / d).glob("*.ipynb")),
                       key=lambda p: -p.stat().st_size)          # the longest ones first
    for folder in NOTEBOOK_DIRS:
        assert any(p.parent.name == folder for p in notebooks), f"no notebook in {folder}/"
    probe = source / "notebooks" / "zz_probe_runtime_kernel.ipynb"
    nbformat.write(new_notebook(cells=[new_code_cell(c) for c in PROBE]), probe)

    env = {k: v for k, v in os.environ.items() if k not in PARENT_ONLY}
    env.update(_private_dirs(tmp_path / "private"), VIRTUAL_ENV=str(RUNTIME_VENV),
               PATH=f"{RUNTIME_VENV / 'bin'}{os.pathsep}{os.environ.get('PATH', '')}",
               COURSE_PROGRESS_FILE=str(tmp_path / "progress" / "progress.json"),
               VTK_DEFAULT_OPENGL_WINDOW="vtkEGLRenderWindow",
               PYDEVD_DISABLE_FILE_VALIDATION="1")
    results = execute_notebooks(python, [probe] + notebooks, env)
    probe_result, results = results[0], results[1:]

    # the kernel is the runtime environment's: its prefix, its course_lib, and no scipy
    assert probe_result["ok"], _failures([probe_result], source)
    prefix, module = probe_result["outputs"]["0"].split()
    assert Path(prefix).resolve() == RUNTIME_VENV.resolve(), (
        f"the notebooks ran in the kernel of {prefix}, not of {RUNTIME_VENV}")
    assert Path(module).resolve().is_relative_to(RUNTIME_VENV.resolve()), (
        f"course_lib came from {module}, not from the installed package")
    assert probe_result["outputs"]["1"].strip() == "scipy: not installed", (
        "the runtime-only environment has scipy (a test-only dependency): "
        + probe_result["outputs"]["1"])

    failed = [r for r in results if not r["ok"]]
    timing = ", ".join(f"{Path(r['notebook']).parent.name}/{Path(r['notebook']).stem} "
                       f"{r['seconds']} s" for r in results)
    print(f"\nruntime environment ready in {built:.0f} s; notebooks: {timing}; "
          f"total {time.monotonic() - started:.0f} s")
    assert not failed, (
        f"{len(failed)} of {len(results)} notebooks fail with only the runtime dependencies "
        f"(`pip install .` without [test]); a lesson may use only pyproject.toml's "
        f"[project] dependencies:\n{_failures(failed, source)}")
    # the start page finds the lessons beside it, although course_lib is in site-packages
    start = next(r for r in results if Path(r["notebook"]).name == "00_start_here.ipynb")
    page = "\n".join(start["outputs"].values())
    lessons = sorted(p.name for p in (source / "notebooks").glob("ch*.ipynb"))
    missing = [name for name in lessons if f"]({name})" not in page]
    assert not missing and "| coming" not in page, (
        f"the start page of a pip-installed course links no lesson for {missing}")


# ---------------------------------------------------------------------------------------------
# Binder: the repository is the home folder
# ---------------------------------------------------------------------------------------------

RECORD_EXAM = """
import json
from course_lib import progress
from course_lib.exercises import mock_exam

exam = mock_exam(11, chapters=[3, 7], n_questions=4)
first = exam[0]
right = (first.source.letters[first.source.correct] if first.kind == "concept"
         else repr(first.source.expected.tolist()))
assert exam.submit(0, right), "the right answer to question 0 was not accepted"
for i in range(1, len(exam)):
    exam.submit(i, "")
progress.record_exam(exam)
print(json.dumps({"file": str(progress.progress_path()), "chapters": [q.chapter for q in exam],
                  "module": progress.__file__}))
"""


def _git(home, *args):
    return subprocess.run([*GIT, *args], cwd=home, capture_output=True, text=True, check=True)


def test_binder_layout_start_page_shows_a_recorded_exam_and_git_stays_clean(tmp_path):
    home = copy_of_repository(tmp_path / "jovyan")
    _git(home, "init", "-q")
    _git(home, "add", "-A")
    _git(home, "commit", "-q", "-m", "the course as Binder copies it")
    env = {k: v for k, v in os.environ.items()
           if k not in PARENT_ONLY and not k.startswith(("JUPYTER_", "XDG_"))
           and k not in ("IPYTHONDIR", "MPLCONFIGDIR", "DISPLAY", "VTK_DEFAULT_OPENGL_WINDOW")}
    # no display and no VTK variable: the kernels start through Binder's start script
    env.update(HOME=str(home), PYTHONPATH=str(home), PYDEVD_DISABLE_FILE_VALIDATION="1")
    start_page = home / "notebooks" / "00_start_here.ipynb"
    progress_file = home / ".local" / "share" / "graphics-course" / "progress.json"

    def report():
        """The start page's progress report, after running the whole page."""
        probe = new_code_cell("import os, course_lib\nprint(course_lib.__file__)\n"
                              "print(os.environ.get('VTK_DEFAULT_OPENGL_WINDOW'))")
        nb = nbformat.read(start_page, as_version=4)
        shown = [k for k, c in enumerate(nb.cells) if "your_progress()" in c.source]
        assert len(shown) == 1, "the start page should show your_progress() once"
        nb.cells.append(probe)
        run = home / "notebooks" / ".start_page_run.ipynb"    # removed below: git must not see it
        nbformat.write(nb, run)
        try:
            [result] = execute_notebooks(sys.executable, [run], env, workers=1,
                                         prefix=[home / "start"])
        finally:
            run.unlink()
        assert result["ok"], _failures([result], home)
        outputs = result["outputs"]
        module, window = outputs[str(len(nb.cells) - 1)].split()
        assert Path(module).is_relative_to(home), f"course_lib came from {module}, not the copy"
        assert window == "vtkEGLRenderWindow", "Binder's start script did not set VTK's window"
        assert not any("bad X server" in text for text in outputs.values())
        return outputs[str(shown[0])], result

    before, first = report()
    assert before.startswith("**No results yet.**"), before
    assert "`~/.local/share/graphics-course/progress.json`" in before, before
    assert not progress_file.exists()

    done = subprocess.run([sys.executable, "-c", RECORD_EXAM], env=env, cwd=home / "notebooks",
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    saved = json.loads(done.stdout.strip().splitlines()[-1])
    assert Path(saved["module"]).is_relative_to(home)
    assert Path(saved["file"]) == progress_file.resolve() and progress_file.is_file()
    # four questions over two chapters: two each, in chapter order; only the first is right
    assert saved["chapters"] == [3, 3, 7, 7]
    header, *stored = [json.loads(line) for line in progress_file.read_text().splitlines()]
    assert header == {"format": "graphics-course-progress", "version": 2}
    assert [(e["seed"], e["score"]) for e in stored] == [(11, {"3": [1, 2], "7": [0, 2]})]

    after, second = report()
    assert after.startswith("**1 mock exam taken**"), after
    assert "| 3 | 1 | 2 | 50% |" in after and "| 7 | 0 | 2 | 0% |" in after, after
    assert "chapter 7 (0 of 2 right), chapter 3 (1 of 2 right)" in after, after

    status = _git(home, "status", "--porcelain", "--untracked-files=all").stdout
    assert status == "", f"Binder's session left files git would commit:\n{status}"
    ignored = _git(home, "status", "--porcelain", "--ignored", "--untracked-files=all").stdout
    assert "!! .local/share/graphics-course/progress.json" in ignored.splitlines(), ignored
    print(f"\nstart page in the Binder layout: {first['seconds']} s, then {second['seconds']} s")


# ---------------------------------------------------------------------------------------------
# Binder's build: what repo2docker makes of apt.txt, environment.yml, postBuild and start
# ---------------------------------------------------------------------------------------------

def _apt_packages(text):
    """Packages of an apt.txt, read as repo2docker reads it (a '#' starts a comment)."""
    return [line.partition("#")[0].strip() for line in text.splitlines()
            if line.partition("#")[0].strip()]


def test_repo2docker_builds_apt_txt_environment_yml_postbuild_and_start(tmp_path):
    repo2docker = Path(sys.executable).with_name("repo2docker")
    assert repo2docker.exists(), (
        "repo2docker is missing: it is in the test extra (pip install -e '.[test]')")
    source = copy_of_repository(tmp_path / "repo")
    started = time.monotonic()
    # as on mybinder.org: user jovyan with uid 1000; run outside the repository, since
    # repo2docker reads a repo2docker_config.py from its working folder
    done = subprocess.run([str(repo2docker), "--no-build", "--debug", "--user-id", "1000",
                           "--user-name", "jovyan", str(source)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    seconds = time.monotonic() - started
    assert done.returncode == 0, done.stderr[-3000:]
    dockerfile = done.stdout
    assert dockerfile.lstrip().startswith("FROM "), dockerfile[:500]

    # apt.txt: the libraries VTK renders off screen with (tests/test_environment.py and
    # HEADLESS.md: libegl1 and libgl1-mesa-dri), installed as root before environment.yml
    wanted = _apt_packages((source / "apt.txt").read_text())
    assert {"libegl1", "libgl1-mesa-dri"} <= set(wanted), wanted
    # and the same GL libraries as the make route installs (scripts/system-packages)
    make_route = re.search(r"^\s*packages=\(([^)]*)\)", (source / "scripts" / "system-packages")
                           .read_text(), re.M)
    assert make_route and set(make_route.group(1).split()) <= set(wanted), make_route
    installs = re.findall(r"apt-get install --yes --no-install-recommends ([^&\n]+)",
                          dockerfile)
    assert [sorted(line.split()) for line in installs] == [sorted(wanted)], installs

    # environment.yml: the conda buildpack, with environment.yml's Python
    env = yaml.safe_load((source / "environment.yml").read_text())
    python = next(d for d in env["dependencies"] if isinstance(d, str)
                  and re.fullmatch(r"python[=<>]=?[\d.]+", d))
    version = re.search(r"[\d.]+", python).group()
    assert f"Building conda environment for python={version}" in done.stderr, done.stderr
    assert 'env update -p ${NB_PYTHON_PREFIX} --file "environment.yml"' in dockerfile

    # postBuild runs as the user after the repository is copied (owned by the user, so that
    # `pip install -e .` can write there), and installs course_lib itself
    assert "COPY --chown=1000:1000 src/ ${REPO_DIR}/" in dockerfile
    assert dockerfile.index("src/ ${REPO_DIR}/") < dockerfile.index("RUN ./postBuild")
    post_build = (source / "postBuild").read_text()
    assert re.search(r"^pip install --no-deps -e \.$", post_build, re.M), post_build
    assert os.access(source / "postBuild", os.X_OK)

    # start: every process of the container gets VTK's EGL window (Binder has no display)
    assert 'ENV R2D_ENTRYPOINT="${REPO_DIR}/start"' in dockerfile
    assert os.access(source / "start", os.X_OK)
    bare = {k: v for k, v in os.environ.items() if k != "VTK_DEFAULT_OPENGL_WINDOW"}
    shown = subprocess.run([str(source / "start"), sys.executable, "-c",
                            "import os, sys; print(os.environ['VTK_DEFAULT_OPENGL_WINDOW'], "
                            "sys.argv[1:])", "passed", "on"], env=bare, capture_output=True,
                           text=True, timeout=60, check=True)
    assert shown.stdout.split() == ["vtkEGLRenderWindow", "['passed',", "'on']"], shown.stdout
    print(f"\nrepo2docker --no-build: {seconds:.1f} s")


def test_readme_binder_badge_opens_the_start_page_in_jupyterlab():
    readme = (ROOT / "README.md").read_text()
    badges = re.findall(r"\[!\[[^\]]*\]\((https://mybinder\.org/badge_logo\.svg)\)\]"
                        r"\((https://mybinder\.org/v2/gh/[^)\s]+)\)", readme)
    assert len(badges) == 1, "the README needs one 'launch Binder' badge"
    url = badges[0][1]
    target = re.search(r"[?&]urlpath=([^&]+)", url)
    assert target and target.group(1) == "lab/tree/notebooks/00_start_here.ipynb", url
    assert (ROOT / "notebooks" / "00_start_here.ipynb").is_file()
