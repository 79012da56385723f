"""Rebuilding the stored notebooks neither reads nor adds to the rebuilder's own progress."""
import os

import nbformat

from course_lib.exercises import build


def test_executed_notebooks_record_nothing_in_the_callers_progress_file(tmp_path, monkeypatch):
    mine = tmp_path / "mine.json"
    monkeypatch.setenv("COURSE_PROGRESS_FILE", str(mine))
    monkeypatch.setenv("COURSE_RECORD_ATTEMPTS", "1")
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(
        "import os\n"
        "print(os.environ['COURSE_RECORD_ATTEMPTS'], os.environ['COURSE_PROGRESS_FILE'])\n"
        "from course_lib.exercises import ch12\n"
        "ex = ch12.SolidAngle(seed=0)\n"
        "ex.check(ex.expected).status")]
    out = build.execute(nb, tmp_path)
    printed = out.cells[0].outputs[0]["text"].split()
    assert printed[0] == "0" and printed[1] != str(mine)
    assert out.cells[0].outputs[-1]["data"]["text/plain"] == "'correct'"
    assert not mine.exists()
    # the caller's environment is as it was
    assert os.environ["COURSE_PROGRESS_FILE"] == str(mine)
    assert os.environ["COURSE_RECORD_ATTEMPTS"] == "1"
