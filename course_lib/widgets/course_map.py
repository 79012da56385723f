"""The start page's machinery: the map of the course, its table of links, the student's
progress; one call each, so that the page itself shows content, not plumbing.

The course's folder is found beside this package (a clone: ``make lab``, Binder) or, when
``course_lib`` is installed into site-packages (``pip install .``), from the working folder
(Jupyter runs the start page in ``notebooks/``). Each chapter's lessons, exercises and worked
solutions are found on disk (``chNN_topic.ipynb``), and its picture is the lesson's opening
explorer, rebuilt and rendered.
"""
import ast
import importlib
import io
import os
import re
import textwrap
from pathlib import Path

__all__ = ["Markdown", "course_map", "course_root", "course_table", "lessons", "your_progress"]

_WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


class Markdown:
    """Markdown shown as such in a notebook (and as plain text elsewhere).

    Examples
    --------
    >>> Markdown("**hi**")._repr_markdown_()
    '**hi**'
    """

    def __init__(self, text):
        self.text = text

    def _repr_markdown_(self):
        return self.text

    def __repr__(self):
        return self.text


def course_root():
    """The course's folder (the one holding ``notebooks/``).

    Examples
    --------
    >>> (course_root() / "notebooks").is_dir()
    True
    """
    import course_lib

    for folder in (Path(course_lib.__file__).resolve().parents[1], Path.cwd().resolve().parent,
                   Path.cwd().resolve()):
        if (folder / "notebooks").is_dir() and any((folder / "notebooks").glob("ch*.ipynb")):
            return folder
    raise FileNotFoundError("cannot find the course's notebooks/ folder: open the start page "
                            "from the course's notebooks/ folder")


def _chapter_notebooks(folder):
    """{chapter: path} of ``folder/chNN_topic.ipynb``."""
    found = {}
    for path in sorted(folder.glob("ch*.ipynb")):
        match = re.match(r"ch(\d\d)_", path.name)
        if match:
            found[int(match.group(1))] = path
    return found


def lessons(root=None):
    """{"notebooks" | "exercises" | "solutions": {chapter: path}} found on disk.

    Examples
    --------
    >>> 3 in lessons()["notebooks"]
    True
    """
    root = course_root() if root is None else Path(root)
    return {kind: _chapter_notebooks(root / kind) for kind in ("notebooks", "exercises",
                                                              "solutions")}


def _topic(path):
    """The chapter's topic, from the notebook's title."""
    import nbformat

    first = nbformat.read(path, as_version=4).cells[0].source.splitlines()[0]
    return re.sub(r"^#\s*Chapter \d+( exercises)?\s*[—:-]\s*", "", first).strip()


def _chapters(found):
    from ..exercises import mock

    return sorted(set(found["notebooks"]) | set(found["solutions"])
                  | set(mock.available_chapters()))


def _titles(found, chapters):
    titles = {}
    for ch in chapters:
        path = found["notebooks"].get(ch) or found["solutions"].get(ch)
        titles[ch] = _topic(path) if path else f"Chapter {ch}"
    return titles


def _lead_explorer_png(path, dpi=60):
    """The lesson's opening explorer (its first displayed widget made with no arguments),
    rebuilt and rendered as a PNG; None when the lesson opens with none."""
    import matplotlib.pyplot as plt
    import nbformat

    for cell in nbformat.read(path, as_version=4).cells:
        if cell.cell_type != "code" or not any(_WIDGET_VIEW in out.get("data", {})
                                               for out in cell.get("outputs", [])):
            continue
        code = "\n".join(line for line in cell.source.splitlines() if not line.startswith("%"))
        tree = ast.parse(code)
        imports = {alias.asname or alias.name: node.module for node in tree.body
                   if isinstance(node, ast.ImportFrom) and (node.module or "").startswith(
                       "course_lib.widgets") for alias in node.names}
        last = tree.body[-1] if tree.body else None
        if isinstance(last, ast.Expr) and isinstance(last.value, ast.Call) \
                and isinstance(last.value.func, ast.Name) and last.value.func.id in imports \
                and not last.value.args and not last.value.keywords:
            name = last.value.func.id
            explorer = getattr(importlib.import_module(imports[name]), name)()
            image = explorer.png(dpi=dpi)
            if explorer.fig is not None:
                plt.close(explorer.fig)
            return image
        return None
    return None


def course_map(columns=4):
    """The map of the course: one picture per chapter, its lesson's opening explorer.

    Returns
    -------
    IPython.display.Image
        A static picture (:func:`course_lib.draw.show`), shown as a cell's last value.

    Examples
    --------
    >>> course_map().data[:4]
    b'\\x89PNG'
    """
    import matplotlib.image as mpimg

    from .. import draw

    found = lessons()
    chapters = _chapters(found)
    titles = _titles(found, chapters)
    rows = -(-len(chapters) // columns)
    fig = draw.figure(figsize=(10, 2.55 * rows), dpi=80)
    for k, ch in enumerate(chapters):
        ax = fig.add_subplot(rows, columns, k + 1)
        ax.set_xticks([])
        ax.set_yticks([])
        label = textwrap.shorten(titles[ch], 44, placeholder="…")
        ax.set_title("\n".join(textwrap.wrap(f"{ch}. {label}", 30)), fontsize=8.5)
        lesson = found["notebooks"].get(ch)
        picture = _lead_explorer_png(lesson) if lesson else None
        if picture is not None:
            ax.imshow(mpimg.imread(io.BytesIO(picture), format="png"))
        else:
            ax.set_facecolor("0.93")
            ax.text(0.5, 0.5, "open the lesson" if lesson else "lesson coming", ha="center",
                    va="center", fontsize=10, color="0.35", transform=ax.transAxes)
        for spine in ax.spines.values():
            spine.set_color("0.8")
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.93, wspace=0.06,
                        hspace=0.42)
    return draw.show(fig)


def course_table():
    """Every chapter's lesson, exercises, worked solutions and concept questions, as links.

    Returns
    -------
    Markdown

    Examples
    --------
    >>> "| 3 |" in course_table().text
    True
    """
    from ..exercises import concepts

    root = course_root()
    found = lessons(root)
    chapters = _chapters(found)
    titles = _titles(found, chapters)

    def link(path, text):
        return (f"[{text}]({Path(os.path.relpath(path, root / 'notebooks')).as_posix()})"
                if path else "coming")

    table = ["| chapter | topic | lesson | exercises | worked solutions | concept questions |",
             "|---:|---|---|---|---|---:|"]
    for ch in chapters:
        table.append(f"| {ch} | {titles[ch]} | {link(found['notebooks'].get(ch), 'lesson')} "
                     f"| {link(found['exercises'].get(ch), 'exercises')} "
                     f"| {link(found['solutions'].get(ch), 'solutions')} "
                     f"| {len(concepts.QUESTIONS.get(ch, ()))} |")
    return Markdown("\n".join(table))


def your_progress(path=None):
    """The student's progress (:func:`course_lib.progress.progress_report`), shown as Markdown.

    Examples
    --------
    >>> import os, tempfile
    >>> your_progress(os.path.join(tempfile.mkdtemp(), "p.json")).text.startswith("**No results")
    True
    """
    from .. import progress

    return Markdown(progress.progress_report(path))
