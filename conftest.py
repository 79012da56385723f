"""Test-wide set-up: headless rendering and a matplotlib backend like the students'."""
import json
import os
import tempfile
from collections import defaultdict
from pathlib import Path

import matplotlib
import pytest
from hypothesis import settings

from course_lib.draw import configure_offscreen_vtk

# Property tests draw the same examples on every run (CI must not turn red on the day a random
# draw finds a case; a failure then reproduces everywhere). HYPOTHESIS_PROFILE=explore draws new
# examples each run, to look for cases the fixed draw misses.
settings.register_profile("course", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "course"))

# the shared checks of tests/test_exercises_chNN.py: show pytest's detailed assertion messages
pytest.register_assert_rewrite("exercise_harness")

# The ipympl backend, as under `%matplotlib widget`: it works without a browser, and setting a
# widget's value runs the same callbacks a student's drag runs.
matplotlib.use("module://ipympl.backend_nbagg")
configure_offscreen_vtk()            # before anything imports vtk (also inherited by kernels)
os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")   # quiet kernel start-up
# the mock exam's progress file: never the student's real one (kernels and servers inherit this)
os.environ["COURSE_PROGRESS_FILE"] = os.path.join(
    tempfile.mkdtemp(prefix="course-progress-"), "progress.json")
# and no exercise check recorded in it: the notebooks' kernels would otherwise record their
# checks, and the adaptive mock exam of a later notebook would depend on which ran first
os.environ["COURSE_RECORD_ATTEMPTS"] = "0"


@pytest.fixture(autouse=True)
def _close_figures():
    """Each test starts and ends without open figures (widgets make one each)."""
    yield
    import matplotlib.pyplot as plt

    plt.close("all")


# Scheduling. `make test` spreads the suite over two workers by scope (a module, a test class, a
# notebook: --dist loadscope), each scope on one worker. A few scopes take minutes (a lesson
# driven in the browser, the website built and visited, the hub) and most take a second; the
# long ones must start first, or one worker ends alone with the last of them while the other
# idles (seen: 7-8 minutes of a 36-minute run). So the collection is ordered longest scope
# first, from the seconds each took in a measured run (tests/scope_seconds.json; scopes not in it
# come after, in their usual order; the tests inside a scope keep theirs), and make test passes
# --no-loadscope-reorder (xdist's own order is by number of tests: a 1,600-test module of
# milliseconds first, a one-test lesson of minutes last). COURSE_SCOPE_SECONDS=write rewrites
# the file from the run (all phases of every test, summed per scope).
SCOPE_SECONDS = Path(__file__).parent / "tests" / "scope_seconds.json"
_measured = defaultdict(float)


def _scope(nodeid):
    """The unit --dist loadscope sends to one worker (as xdist's LoadScopeScheduling splits)."""
    return nodeid.rsplit("::", 1)[0]


def pytest_collection_modifyitems(config, items):
    try:
        seconds = json.loads(SCOPE_SECONDS.read_text())
    except FileNotFoundError:
        return
    first = {}
    for k, item in enumerate(items):
        first.setdefault(_scope(item.nodeid), k)
    items.sort(key=lambda item: (-seconds.get(_scope(item.nodeid), 0.0),
                                 first[_scope(item.nodeid)]))


def pytest_runtest_logreport(report):
    if os.environ.get("COURSE_SCOPE_SECONDS") == "write":
        _measured[_scope(report.nodeid)] += report.duration


def pytest_sessionfinish(session):
    if (os.environ.get("COURSE_SCOPE_SECONDS") == "write" and _measured
            and not hasattr(session.config, "workerinput")):      # the controller only
        kept = {scope: round(t, 1) for scope, t in sorted(_measured.items()) if t >= 1.0}
        SCOPE_SECONDS.write_text(json.dumps(kept, indent=1) + "\n")
