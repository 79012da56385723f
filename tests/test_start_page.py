"""The start page shows content, not plumbing: short cells calling course_lib.widgets.course_map,
a table linking every lesson, exercise and solution found on disk, and the student's progress."""
import re
from pathlib import Path

import nbformat

from course_lib.widgets import course_map

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "notebooks" / "00_start_here.ipynb"


def test_every_code_cell_of_the_start_page_is_a_short_call():
    cells = [c for c in nbformat.read(PAGE, as_version=4).cells if c.cell_type == "code"]
    assert cells
    for cell in cells:
        code = [line for line in cell.source.splitlines()
                if line.strip() and not line.lstrip().startswith(("#", "%"))]
        assert len(code) <= 3, cell.source
        assert not re.search(r"^\s*(def|class|for|while)\b", cell.source, re.M), cell.source


def test_the_map_comes_before_the_progress_and_the_how_to():
    sources = [c.source for c in nbformat.read(PAGE, as_version=4).cells]
    where = {name: next(k for k, s in enumerate(sources) if name in s)
             for name in ("course_map()", "your_progress()", "## How to use")}
    assert where["course_map()"] < where["your_progress()"] < where["## How to use"]


def test_the_table_links_every_notebook_on_disk():
    table = course_map.course_table().text
    for kind in ("notebooks", "exercises", "solutions"):
        for path in sorted((ROOT / kind).glob("ch*.ipynb")):
            link = path.name if kind == "notebooks" else f"../{kind}/{path.name}"
            assert f"]({link})" in table, (kind, path.name)
    chapters = {int(m) for m in re.findall(r"^\| (\d+) \|", table, re.M)}
    assert chapters == {int(p.name[2:4]) for p in (ROOT / "notebooks").glob("ch*.ipynb")}


def test_the_map_is_one_picture_per_chapter():
    image = course_map.course_map()
    assert image.data[:4] == b"\x89PNG"


def test_your_progress_is_markdown_of_the_report(tmp_path):
    from course_lib import progress
    file = tmp_path / "p.json"
    progress.record_event("attempt", key="ch05.Outcodes", seed=1, status="wrong", path=file)
    shown = course_map.your_progress(file)
    assert shown._repr_markdown_() == progress.progress_report(file)
    assert "Topics to practise" in shown.text and "ch05.Outcodes" in shown.text
