"""Every figure that a stored notebook builds is also displayed.

A static figure is shown by ending its cell with ``draw.show(fig)``: the function returns a PNG
image, and a cell displays only the value of its *last* expression. A ``draw.show(...)`` earlier in
the cell (followed by a ``print``, inside a loop, assigned and forgotten) renders the picture and
throws it away. nbval cannot notice: it does not compare images, and the text outputs are the same
with or without the picture. Two independent checks catch it:

1. **the source**: every ``draw.show(...)`` (or a bare ``show(...)``) outside function bodies is
   the value of the cell's last statement, an argument of ``display(...)``, or assigned to a name
   that is displayed afterwards (the last expression, or passed to ``display``);
2. **the stored outputs**: a cell that makes a figure (``draw.figure(``, ``plt.figure(``,
   ``plt.subplots(``) has an ``image/png`` output stored.

The negative tests at the end feed both checkers synthetic bad cells (including the shape of the
two cells this test was written for), so a checker that accepted everything would fail.
"""
import ast
import re
from pathlib import Path

import nbformat
import pytest
from nbformat.v4 import new_code_cell, new_output

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted(path for folder in ("notebooks", "solutions", "exercises")
                   for path in (ROOT / folder).glob("*.ipynb"))
MAKES_FIGURE = re.compile(r"\b(?:draw\.figure|plt\.figure|plt\.subplots)\s*\(")
_OWN_SCOPE = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)


def python_source(source):
    """The cell's code with IPython magics and shell escapes blanked (line numbers kept)."""
    return "\n".join("" if line.lstrip().startswith(("%", "!")) else line
                     for line in source.splitlines())


def _is_show(node):
    """``draw.show(...)`` or a bare ``show(...)`` (not ``plt.show()``, which displays by itself)."""
    if not isinstance(node, ast.Call):
        return False
    f = node.func
    return (isinstance(f, ast.Name) and f.id == "show") or (
        isinstance(f, ast.Attribute) and f.attr == "show" and isinstance(f.value, ast.Name)
        and f.value.id == "draw")


def _is_display(node):
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
        and node.func.id == "display"


def _calls_with_parent(tree):
    """(call, parent node) for every call outside function, lambda and class bodies."""
    found = []

    def visit(node):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, _OWN_SCOPE):
                continue
            if isinstance(child, ast.Call):
                found.append((child, node))
            visit(child)

    visit(tree)
    return found


def undisplayed_shows(source):
    """Line numbers of the ``show(...)`` calls in a code cell whose picture is never displayed."""
    tree = ast.parse(python_source(source))
    if not tree.body:
        return []
    last = tree.body[-1]
    displayed = {arg.id for call, _ in _calls_with_parent(tree) if _is_display(call)
                 for arg in call.args if isinstance(arg, ast.Name)}
    if isinstance(last, ast.Expr) and isinstance(last.value, ast.Name):
        displayed.add(last.value.id)
    bad = []
    for call, parent in _calls_with_parent(tree):
        if not _is_show(call):
            continue
        if parent is last and isinstance(last, ast.Expr):
            continue                                            # the cell's value: displayed
        if _is_display(parent) and call in parent.args:
            continue
        if isinstance(parent, ast.Assign) and parent in tree.body and len(parent.targets) == 1 \
                and isinstance(parent.targets[0], ast.Name) and parent.targets[0].id in displayed:
            continue
        bad.append(call.lineno)
    return bad


def figure_not_stored(cell):
    """True when a code cell makes a figure but has no PNG among its stored outputs."""
    if not MAKES_FIGURE.search(cell.source):
        return False
    return not any("image/png" in out.get("data", {}) for out in cell.get("outputs", []))


def code_cells(path):
    nb = nbformat.read(path, as_version=4)
    return [(k, cell) for k, cell in enumerate(nb.cells) if cell.cell_type == "code"]


def test_the_notebooks_are_found():
    folders = {path.parent.name for path in NOTEBOOKS}
    assert folders == {"notebooks", "solutions", "exercises"}
    assert len(NOTEBOOKS) >= 25


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_shown_figure_is_the_value_of_its_cell(path):
    problems = [f"cell {k}, line {line}: draw.show(...) is not the cell's last expression, so "
                "its picture is thrown away; end the cell with it (print before it)"
                for k, cell in code_cells(path) for line in undisplayed_shows(cell.source)]
    assert not problems, f"{path.relative_to(ROOT)}:\n" + "\n".join(problems)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_figure_made_is_stored_as_a_picture(path):
    problems = [f"cell {k} makes a figure but stores no image/png output"
                for k, cell in code_cells(path) if figure_not_stored(cell)]
    assert not problems, f"{path.relative_to(ROOT)}:\n" + "\n".join(problems)


# ---------------------------------------------------------------------------------------------
# the checkers themselves: they must flag bad cells and accept good ones
# ---------------------------------------------------------------------------------------------

BAD = {
    "a print after the show (the bug this test was written for)":
        "fig = draw.figure()\nax = fig.add_subplot()\ndraw.show(fig)\nprint('depth steps')",
    "more code after the show":
        "fig = draw.figure()\ndraw.show(fig)\nP = viewing.perspective(1.0, 1.0, 0.1, 100.0)\nz = P[2, 2]",
    "the show inside a loop":
        "for name in names:\n    fig = draw.figure()\n    draw.show(fig)",
    "a loop after the show":
        "fig = draw.figure()\ndraw.show(fig)\nfor name in names:\n    print(name)",
    "the show inside an if":
        "%matplotlib widget\nif ready:\n    draw.show(fig)",
    "assigned and never displayed":
        "image = draw.show(fig)\nprint('done')",
    "a bare show imported from draw":
        "from course_lib.draw import show\nshow(fig)\nx = 1",
    "in a comprehension":
        "images = [draw.show(f) for f in figures]",
    "the last expression is another value":
        "draw.show(fig)\nfig",
}

GOOD = {
    "the last expression": "fig = draw.figure()\nax = fig.add_subplot()\ndraw.show(fig)",
    "after a magic": "%matplotlib widget\nfig = draw.figure()\ndraw.show(fig)",
    "printing first": "print('depth steps')\nfig = draw.figure()\ndraw.show(fig)",
    "assigned, then the last expression": "image = draw.show(fig)\nprint(1)\nimage",
    "assigned, then displayed": "image = draw.show(fig)\ndisplay(image)\nprint(1)",
    "passed to display": "for f in figures:\n    display(draw.show(f))\nprint('all shown')",
    "returned by a helper": "def picture(fig):\n    return draw.show(fig)\n\npicture(fig)",
    "plt.show is a display by itself": "plt.show()\nprint(1)",
    "no figure at all": "x = 1\nprint(x)",
}


@pytest.mark.parametrize("name", BAD)
def test_the_source_checker_flags_a_thrown_away_figure(name):
    assert undisplayed_shows(BAD[name]), name


@pytest.mark.parametrize("name", GOOD)
def test_the_source_checker_accepts_a_displayed_figure(name):
    assert undisplayed_shows(GOOD[name]) == [], name


def test_the_source_checker_names_the_line():
    assert undisplayed_shows("x = 1\n\ndraw.show(fig)\nprint(x)") == [3]
    assert undisplayed_shows("draw.show(a)\ndraw.show(b)") == [1]      # only the last one shows


def png_output():
    return new_output("display_data", data={"image/png": "iVBORw0KGgo=", "text/plain": "<Image>"})


def test_the_output_checker_flags_a_figure_without_a_stored_picture():
    source = "fig = draw.figure()\ndraw.show(fig)\nprint('steps')"
    printed_only = new_code_cell(source, outputs=[new_output("stream", name="stdout", text="steps\n")])
    assert figure_not_stored(printed_only)
    assert figure_not_stored(new_code_cell("fig, ax = plt.subplots()\nax.plot([1, 2])"))
    assert not figure_not_stored(new_code_cell("fig = draw.figure()\ndraw.show(fig)",
                                               outputs=[png_output()]))
    assert not figure_not_stored(new_code_cell("print(1)"))


def test_the_checkers_catch_a_real_cell_broken_again():
    # the depth figure of chapter 4 with the print moved back after the picture
    path = ROOT / "notebooks" / "ch04_projections_viewing.ipynb"
    cell = next(cell for _, cell in code_cells(path) if "16-bit depth buffer" in cell.source)
    assert undisplayed_shows(cell.source) == [] and not figure_not_stored(cell)
    lines = cell.source.splitlines()
    show = next(k for k, line in enumerate(lines) if line.startswith("draw.show("))
    broken = "\n".join(lines[:show + 1] + ["print('the picture is lost')"])
    assert undisplayed_shows(broken) == [show + 1]
    assert figure_not_stored(new_code_cell(broken, outputs=[
        new_output("stream", name="stdout", text="the picture is lost\n")]))
