"""Make ``exercises/`` from ``solutions/``, and re-execute the course's notebooks.

``solutions/chNN_topic.ipynb`` is the single source of a chapter's exercises. In its code cells
the worked answer sits between the lines ``### BEGIN SOLUTION`` and ``### END SOLUTION``
(nbgrader's convention); in Markdown cells between ``<!-- BEGIN SOLUTION -->`` and
``<!-- END SOLUTION -->`` (HTML comments, invisible when the solution notebook is read). A cell
tagged ``solution`` is dropped whole. The builder replaces each code region by a placeholder
that keeps the notebook running: every name the region assigns and the rest of the cell uses
becomes ``name = ...``, which the checkers report as "not answered yet".

The generated notebook is then executed, so ``exercises/`` is stored with the outputs a student
sees before answering (the questions and the "not answered yet" notes): it reads well on GitHub
and nbval can compare it. Never edit ``exercises/`` by hand; run ``make exercises``.

Command line::

    python -m course_lib.exercises.build              # rebuild and execute exercises/
    python -m course_lib.exercises.build --check      # exit 1 if exercises/ is stale
    python -m course_lib.exercises.build --execute    # also re-execute notebooks/ and solutions/
    python -m course_lib.exercises.build --execute solutions/ch03_transformations.ipynb
                                                      # one notebook (and its exercises)
"""
import argparse
import ast
import copy
import os
import re
import sys
from pathlib import Path

import nbformat

__all__ = ["build_exercise_notebook", "slide_types", "stale_exercises", "strip_code", "strip_markdown",
           "with_slides"]

ROOT = Path(__file__).resolve().parents[2]
CODE_BEGIN, CODE_END = "### BEGIN SOLUTION", "### END SOLUTION"
MD_BEGIN, MD_END = "<!-- BEGIN SOLUTION -->", "<!-- END SOLUTION -->"
MD_PLACEHOLDER = "*Your answer here.*"
SOLUTION_TAG = "solution"


class SolutionMarkerError(ValueError):
    """A solution region is not closed, or closed without being opened."""


def _regions(lines, begin, end, where):
    """Yield (start, stop) line indices of each region, markers included."""
    start = None
    for i, line in enumerate(lines):
        text = line.strip()
        if text == begin:
            if start is not None:
                raise SolutionMarkerError(f"{where}: line {i + 1} opens a solution region "
                                          f"inside another one (opened at line {start + 1})")
            start = i
        elif text == end:
            if start is None:
                raise SolutionMarkerError(f"{where}: line {i + 1} closes a solution region "
                                          "that was never opened")
            yield start, i
            start = None
    if start is not None:
        raise SolutionMarkerError(f"{where}: the solution region opened at line {start + 1} "
                                  f"is never closed with {end!r}")


#: Nodes with a scope of their own: what they assign is not visible after the region.
_OWN_SCOPE = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda, ast.ListComp,
              ast.SetComp, ast.DictComp, ast.GeneratorExp)


def _targets(node):
    """The assignment targets of one node (empty for a node that assigns nothing)."""
    if isinstance(node, ast.Assign):
        return node.targets
    if isinstance(node, (ast.AnnAssign, ast.AugAssign, ast.For, ast.AsyncFor, ast.NamedExpr)):
        return [node.target]
    if isinstance(node, (ast.With, ast.AsyncWith)):
        return [item.optional_vars for item in node.items if item.optional_vars is not None]
    return []


def _assigned_names(code):
    """Names `code` assigns, at any depth of its statements, in order of first assignment.

    Assignments inside ``if``, ``for``, ``while``, ``with`` and ``try`` count, and so do the
    targets of ``for`` loops and ``with ... as name``; those in the bodies of functions and
    classes, and in comprehensions, do not (they are not visible after the code).
    """
    names = []
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return names

    def visit(node):
        for target in _targets(node):
            for sub in ast.walk(target):
                if isinstance(sub, ast.Name) and sub.id not in names:
                    names.append(sub.id)
        for child in ast.iter_child_nodes(node):
            if not isinstance(child, _OWN_SCOPE):
                visit(child)

    visit(tree)
    return names


def _used_names(code):
    try:
        tree = ast.parse(code)
    except SyntaxError:
        return set(re.findall(r"[A-Za-z_]\w*", code))
    return {node.id for node in ast.walk(tree) if isinstance(node, ast.Name)}


def strip_code(source, where="cell"):
    """Replace each solution region of a code cell by a placeholder.

    Examples
    --------
    >>> src = "### BEGIN SOLUTION\\nt = 2\\nanswer = t * 3\\n### END SOLUTION\\nex.check(answer)"
    >>> print(strip_code(src))
    # YOUR ANSWER HERE
    answer = ...
    ex.check(answer)
    """
    lines = source.split("\n")
    regions = list(_regions(lines, CODE_BEGIN, CODE_END, where))
    for start, stop in reversed(regions):
        indent = lines[start][: len(lines[start]) - len(lines[start].lstrip())]
        body = "\n".join(line[len(indent):] if line.startswith(indent) else line
                         for line in lines[start + 1:stop])
        after = "\n".join(lines[stop + 1:])
        assigned = _assigned_names(body)
        used_after = _used_names(after)
        wanted = [name for name in assigned if name in used_after]
        placeholder = [indent + "# YOUR ANSWER HERE"]
        placeholder += [f"{indent}{name} = ..." for name in wanted]
        lines[start:stop + 1] = placeholder
    return "\n".join(lines)


def strip_markdown(source, where="cell"):
    """Replace each solution region of a Markdown cell by a placeholder line.

    Examples
    --------
    >>> print(strip_markdown("Why?\\n<!-- BEGIN SOLUTION -->\\nBecause.\\n<!-- END SOLUTION -->"))
    Why?
    *Your answer here.*
    """
    lines = source.split("\n")
    for start, stop in reversed(list(_regions(lines, MD_BEGIN, MD_END, where))):
        lines[start:stop + 1] = [MD_PLACEHOLDER]
    return "\n".join(lines)


def build_exercise_notebook(solution_nb, source_name):
    """The exercise notebook made from a solution notebook (not executed).

    Parameters
    ----------
    solution_nb : nbformat.NotebookNode
    source_name : str
        The solution notebook's path relative to the repository, recorded in the metadata.

    Returns
    -------
    nbformat.NotebookNode

    Examples
    --------
    >>> from nbformat.v4 import new_code_cell, new_notebook
    >>> sol = new_notebook(cells=[new_code_cell("### BEGIN SOLUTION\\nx = 1\\n### END SOLUTION\\n"
    ...                                         "ex.check(x)", execution_count=1)])
    >>> ex = build_exercise_notebook(sol, "solutions/demo.ipynb")
    >>> print(ex.cells[0].source)
    # YOUR ANSWER HERE
    x = ...
    ex.check(x)
    >>> ex.cells[0].execution_count is None, ex.metadata["course"]["generated_from"]
    (True, 'solutions/demo.ipynb')
    """
    nb = copy.deepcopy(solution_nb)
    cells = []
    for index, cell in enumerate(nb.cells):
        if SOLUTION_TAG in cell.get("metadata", {}).get("tags", []):
            continue
        where = f"{source_name}, cell {index}"
        if cell.cell_type == "code":
            cell.source = strip_code(cell.source, where)
            cell.outputs = []
            cell.execution_count = None
        elif cell.cell_type == "markdown":
            cell.source = strip_markdown(cell.source, where)
        cell.metadata.pop("execution", None)
        cells.append(cell)
    nb.cells = cells
    nb.metadata.pop("widgets", None)
    nb.metadata["course"] = {"generated_from": source_name,
                             "note": "generated by `make exercises`; edit the solution notebook"}
    return nb


WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def slide_types(nb):
    """The slide type of every cell when the notebook is presented (lecture mode).

    A chapter title or a ``##`` section starts a slide, a ``###`` subsection a sub-slide (reached
    with the down arrow), and every cell that shows an explorer starts a sub-slide of its own so
    that the widget fills the projector; all other cells continue the current slide.

    Parameters
    ----------
    nb : nbformat.NotebookNode

    Returns
    -------
    list of str
        ``"slide"``, ``"subslide"`` or ``"-"``, one per cell.

    Examples
    --------
    >>> from nbformat.v4 import new_notebook, new_markdown_cell, new_code_cell
    >>> nb = new_notebook(cells=[new_markdown_cell("# Chapter"), new_code_cell("x = 1"),
    ...                          new_markdown_cell("## 1. Section"), new_markdown_cell("text"),
    ...                          new_markdown_cell("### 1.1 Part")])
    >>> slide_types(nb)
    ['slide', '-', 'slide', '-', 'subslide']
    """
    types = []
    for k, cell in enumerate(nb.cells):
        first = cell.source.lstrip().split("\n", 1)[0] if cell.source.strip() else ""
        if k == 0 or (cell.cell_type == "markdown" and re.match(r"#{1,2} ", first)):
            kind = "slide"
        elif cell.cell_type == "markdown" and first.startswith("### "):
            kind = "subslide"
        elif cell.cell_type == "code" and types and types[-1] not in ("slide", "subslide") and any(
                WIDGET_VIEW in o.get("data", {}) for o in cell.get("outputs", [])):
            kind = "subslide"
        else:
            kind = "-"
        types.append(kind)
    return types


def with_slides(nb):
    """`nb` with its slide metadata set from :func:`slide_types` (in place, and returned).

    The cells that start a slide or sub-slide carry ``metadata.slideshow.slide_type``, read by
    jupyterlab-deck (live slides inside JupyterLab, widgets working), RISE and
    ``jupyter nbconvert --to slides``; the other cells carry none (they continue the slide).

    Examples
    --------
    >>> from nbformat.v4 import new_notebook, new_markdown_cell
    >>> nb = with_slides(new_notebook(cells=[new_markdown_cell("# Title")]))
    >>> nb.cells[0].metadata["slideshow"]
    {'slide_type': 'slide'}
    """
    for cell, kind in zip(nb.cells, slide_types(nb)):
        if kind == "-":
            # a continuation carries no metadata: jupyterlab-deck reads "-" as an unknown type
            # (and hides the cell), while RISE and nbconvert treat a missing type as "-"
            cell.metadata.pop("slideshow", None)
        else:
            cell.metadata["slideshow"] = {"slide_type": kind}
    return nb


def execute(nb, cwd, timeout=600):
    """Execute `nb` in a fresh kernel in directory `cwd` and return it with its outputs.

    No timing metadata and no widget state are stored, so that re-running gives the same file.
    The kernel records no exercise check and reads an empty progress file of its own: the
    stored outputs (the start page's progress table, the adaptive mock exam) must not depend on
    the progress of whoever rebuilds the notebooks, nor add to it.
    """
    import tempfile

    from nbclient import NotebookClient

    client = NotebookClient(nb, timeout=timeout, kernel_name="python3",
                            resources={"metadata": {"path": str(cwd)}},
                            record_timing=False, store_widget_state=False)
    keys = ("COURSE_RECORD_ATTEMPTS", "COURSE_PROGRESS_FILE")
    saved = {key: os.environ.get(key) for key in keys}
    with tempfile.TemporaryDirectory(prefix="course-build-") as folder:
        os.environ["COURSE_RECORD_ATTEMPTS"] = "0"
        os.environ["COURSE_PROGRESS_FILE"] = os.path.join(folder, "progress.json")
        try:
            client.execute()            # the kernel inherits the environment when it starts
        finally:
            for key, value in saved.items():
                if value is None:
                    os.environ.pop(key, None)
                else:
                    os.environ[key] = value
    nb.metadata.pop("widgets", None)
    return with_slides(nb)


def solution_notebooks(root=ROOT):
    """The solution notebooks, sorted."""
    return sorted((Path(root) / "solutions").glob("*.ipynb"))


def exercise_path(solution_path, root=ROOT):
    """Where the exercise notebook made from `solution_path` lives."""
    return Path(root) / "exercises" / Path(solution_path).name


def stale_exercises(root=ROOT):
    """Exercise notebooks missing or whose cells differ from a fresh build (outputs ignored).

    Returns
    -------
    list of str
        One line per problem; empty when ``exercises/`` is up to date.

    Examples
    --------
    >>> import tempfile, nbformat
    >>> from nbformat.v4 import new_notebook
    >>> root = Path(tempfile.mkdtemp())
    >>> (root / "solutions").mkdir(); (root / "exercises").mkdir()
    >>> nbformat.write(new_notebook(), root / "solutions" / "ch99.ipynb")
    >>> stale_exercises(root)
    ['exercises/ch99.ipynb is missing (made from solutions/ch99.ipynb)']
    """
    problems = []
    expected_names = set()
    for path in solution_notebooks(root):
        target = exercise_path(path, root)
        expected_names.add(target.name)
        rel = path.relative_to(root).as_posix()
        if not target.exists():
            problems.append(f"{target.relative_to(root)} is missing (made from {rel})")
            continue
        built = build_exercise_notebook(nbformat.read(path, as_version=4), rel)
        stored = nbformat.read(target, as_version=4)
        want = [(c.cell_type, c.source) for c in built.cells]
        have = [(c.cell_type, c.source) for c in stored.cells]
        if want != have:
            problems.append(f"{target.relative_to(root)} differs from a build of {rel}")
        elif stored.metadata.get("course") != built.metadata["course"]:
            problems.append(f"{target.relative_to(root)} lacks the generated-from metadata")
    for target in sorted((Path(root) / "exercises").glob("*.ipynb")):
        if target.name not in expected_names:
            problems.append(f"{target.relative_to(root)} has no solution notebook")
    return problems


def build_all(root=ROOT, run=True, log=print, only=None):
    """Rebuild exercise notebooks from their solution notebooks (and execute them).

    `only` restricts the build to these solution notebooks (default: all of them).
    """
    for path in (solution_notebooks(root) if only is None else only):
        path = Path(path).resolve()
        rel = path.relative_to(root).as_posix()
        nb = build_exercise_notebook(nbformat.read(path, as_version=4), rel)
        target = exercise_path(path, root)
        target.parent.mkdir(exist_ok=True)
        if run:
            nb = execute(nb, target.parent)
        nbformat.write(nb, target)
        log(f"wrote {target.relative_to(root)}")


def execute_in_place(paths, log=print):
    """Re-execute notebooks and store their outputs."""
    for path in paths:
        nb = execute(nbformat.read(path, as_version=4), Path(path).parent)
        nbformat.write(nb, path)
        log(f"executed {Path(path).relative_to(ROOT) if ROOT in Path(path).parents else path}")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true",
                        help="only report whether exercises/ is stale (exit status 1 if so)")
    parser.add_argument("--execute", action="store_true",
                        help="also re-execute notebooks/ and solutions/ in place")
    parser.add_argument("--slides", action="store_true",
                        help="only (re)write the slide metadata of every notebook")
    parser.add_argument("notebooks", nargs="*",
                        help="with --execute: only these notebooks (default: all)")
    args = parser.parse_args(argv)
    if args.check:
        problems = stale_exercises()
        for line in problems:
            print(line)
        return 1 if problems else 0
    if args.slides:
        for folder in ("notebooks", "solutions", "exercises"):
            for path in sorted((ROOT / folder).glob("*.ipynb")):
                nbformat.write(with_slides(nbformat.read(path, as_version=4)), path)
        return 0
    named = [Path(p).resolve() for p in args.notebooks]
    if args.execute:
        paths = named or sorted((ROOT / "notebooks").glob("*.ipynb")) + solution_notebooks()
        execute_in_place([p for p in paths if p.parent.name != "exercises"])
    # named notebooks: rebuild only the exercises made from the named solution notebooks
    build_all(only=[p for p in named if p.parent.name == "solutions"] if named else None)
    return 0


if __name__ == "__main__":
    sys.exit(main())
