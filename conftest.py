"""Test-wide set-up: headless rendering and a matplotlib backend like the students'."""
import os
import tempfile

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
