"""The project's own promises: one environment in two files, notebooks stored executed and
without widget state, exercises/ generated from solutions/, documented public API, layers."""
import ast
import importlib
import inspect
import json
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import nbformat
import pytest
import yaml

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK_DIRS = ("notebooks", "solutions", "exercises")
# Every module of course_lib is documented (found by walking the package, so a new module is
# covered the day it is added), and so is every package that re-exports a public API (a chapter
# package such as course_lib.visibility); the algorithm layer is every top-level module or package
# except the drawing layer, and must stay free of drawing libraries.
def _declares_api(name):
    import importlib.util

    return "__all__" in Path(importlib.util.find_spec(name).origin).read_text()


def _all_modules():
    import pkgutil

    import course_lib
    return sorted(info.name for info in pkgutil.walk_packages(course_lib.__path__, "course_lib.")
                  if not info.ispkg or _declares_api(info.name))


DRAWING_LAYER = {"course_lib.draw"}
# a private module (leading underscore) is internal unless it declares a public API (__all__)
ALL_MODULES = _all_modules()
INTERNAL_MODULES = {"course_lib.widgets._clip2d"} | {
    m for m in ALL_MODULES if m.rsplit(".", 1)[1].startswith("_") and not _declares_api(m)}
DOCUMENTED_MODULES = tuple(m for m in ALL_MODULES if m not in INTERNAL_MODULES)
ALGORITHM_MODULES = tuple(m for m in DOCUMENTED_MODULES
                          if m.count(".") == 1 and m not in DRAWING_LAYER) + (
    "course_lib.exercises.core",)


def all_notebooks():
    return sorted(p for d in NOTEBOOK_DIRS for p in (ROOT / d).glob("*.ipynb"))


def _requirement(text):
    match = re.fullmatch(r"\s*([A-Za-z0-9_.\-]+)\s*(.*?)\s*", text)
    return match.group(1).lower().replace("_", "-"), match.group(2).replace(" ", "")


def test_environment_yml_lists_the_same_packages_as_pyproject():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    wanted = dict(_requirement(r) for r in project["dependencies"])
    extras = project["optional-dependencies"]
    for r in extras["test"]:          # course_lib[site] in the test extra: the site extra, etc.
        self_reference = re.fullmatch(r"course_lib\[(\w+)\]", r.strip())
        wanted.update(_requirement(x) for x in (extras[self_reference.group(1)]
                                                if self_reference else [r]))
    env = yaml.safe_load((ROOT / "environment.yml").read_text())
    conda = [d for d in env["dependencies"] if isinstance(d, str)]
    have = dict(_requirement(d.replace("=", "==", 1) if re.fullmatch(r"[\w\-]+=[\d.]+", d)
                             else d) for d in conda)
    python = have.pop("python", None)
    have.pop("pip", None)
    # packages that conda-forge does not carry (or carries under another name) go in the
    # `pip:` subsection, spelled as on PyPI; together the two lists must equal pyproject's
    pip_section = [d for d in env["dependencies"] if isinstance(d, dict)]
    assert all(set(d) == {"pip"} for d in pip_section), "environment.yml: only a pip: subsection"
    for d in pip_section:
        for item in d["pip"]:
            name, spec = _requirement(item)
            assert name not in have, f"environment.yml lists {name} twice (conda and pip)"
            have[name] = spec
    assert have == wanted, (
        "environment.yml and pyproject.toml disagree:\n"
        f"  only in environment.yml: {sorted(set(have.items()) - set(wanted.items()))}\n"
        f"  only in pyproject.toml:  {sorted(set(wanted.items()) - set(have.items()))}")
    minimum = project["requires-python"].removeprefix(">=")
    assert python is not None and python.lstrip("=") >= minimum


@pytest.mark.parametrize("path", all_notebooks(), ids=lambda p: str(p.relative_to(ROOT)))
def test_notebook_is_stored_executed_without_widget_state(path):
    nb = json.loads(path.read_text())
    assert "widgets" not in nb["metadata"], (
        f"{path.name} stores widget state (application/vnd.jupyter.widget-state+json): "
        "clear it (Edit > Clear widget state, or re-run `make notebooks`)")
    assert "application/vnd.jupyter.widget-state+json" not in path.read_text()
    counts = [c.get("execution_count") for c in nb["cells"] if c["cell_type"] == "code"]
    assert counts == list(range(1, len(counts) + 1)), (
        f"{path.name} was not executed top to bottom in one run: execution counts {counts}; "
        "re-run `make notebooks`")
    for k, cell in enumerate(nb["cells"]):
        for out in cell.get("outputs", []):
            assert out["output_type"] != "error", f"{path.name} cell {k} stored an error"
            assert out.get("name") != "stderr", f"{path.name} cell {k} wrote to stderr"


def test_every_solution_notebook_has_an_up_to_date_exercise_notebook():
    from course_lib.exercises.build import stale_exercises

    assert list((ROOT / "solutions").glob("*.ipynb")), "no solution notebooks found"
    assert stale_exercises(ROOT) == [], "exercises/ is stale: run `make exercises`"


def _public_objects(module):
    names = getattr(module, "__all__", None)
    assert names, f"{module.__name__} must declare __all__ (its public API)"
    for name in names:
        obj = getattr(module, name)
        if inspect.isfunction(obj) or inspect.isclass(obj):
            yield name, obj


@pytest.mark.parametrize("module_name", DOCUMENTED_MODULES)
def test_public_functions_have_numpydoc_docstrings_with_a_doctest(module_name):
    module = importlib.import_module(module_name)
    missing = []
    for name, obj in _public_objects(module):
        doc = inspect.getdoc(obj) or ""
        if "Examples" not in doc or ">>>" not in doc:
            missing.append(name)
    assert not missing, f"{module_name}: no Examples section with a doctest in {missing}"


def test_algorithm_modules_do_not_import_drawing_libraries():
    code = ("import sys\n"
            + "".join(f"import {m}\n" for m in ALGORITHM_MODULES)
            + "import course_lib.exercises.ch03\n"
            + "print(sorted(m for m in ('matplotlib', 'ipywidgets', 'pyvista', 'vtk') "
              "if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, cwd=ROOT)
    assert out.stdout.strip() == "[]", f"an algorithm module pulls in {out.stdout.strip()}"


def test_readme_starts_with_the_two_commands():
    readme = (ROOT / "README.md").read_text()
    first_block = re.search(r"```(?:\w+)?\n(.*?)```", readme, re.S).group(1)
    commands = [line.split("#")[0].strip() for line in first_block.splitlines()
                if line.split("#")[0].strip()]
    assert commands == ["make lab", "make test"]


def test_ci_runs_the_readme_test_command_and_nothing_else():
    script = (ROOT / ".ci" / "run").read_text()
    commands = [line for line in script.splitlines() if line.strip().startswith("exec ")]
    assert commands == ["exec make test"]


def test_solution_code_regions_parse():
    """Solution cells stay valid Python once the builder puts placeholders in."""
    from course_lib.exercises.build import build_exercise_notebook
    import nbformat

    for path in sorted((ROOT / "solutions").glob("*.ipynb")):
        nb = build_exercise_notebook(nbformat.read(path, as_version=4), path.name)
        for cell in nb.cells:
            if cell.cell_type == "code":
                source = "\n".join(line for line in cell.source.splitlines()
                                   if not line.lstrip().startswith(("%", "!")))
                ast.parse(source)


@pytest.mark.parametrize("path", all_notebooks(), ids=lambda p: str(p.relative_to(ROOT)))
def test_notebook_carries_the_slide_metadata_of_lecture_mode(path):
    from course_lib.exercises.build import slide_types

    nb = nbformat.read(path, as_version=4)
    have = [c.metadata.get("slideshow", {}).get("slide_type", "-") for c in nb.cells]
    assert have == slide_types(nb), (
        f"{path.name}: slide metadata missing or stale; run "
        "`python -m course_lib.exercises.build --slides`")
    assert have[0] == "slide" and have.count("slide") >= 2 if len(have) > 3 else True


# One room per concept: a reader next to the textbook finds *the* implementation of a concept.
# A module that grows past about a thousand lines becomes a package, one topic a file (see
# CONTRIBUTING.md, Layout), and a function or class of the library is defined in one place only.
MAX_MODULE_LINES = 1000
# names that two modules define on purpose, each for a different concept, always used qualified
SAME_NAME_DIFFERENT_CONCEPT = {
    "inverse": "quaternions.inverse (conjugate / norm^2) vs transforms.inverse (of a matrix)",
    "rotate": "quaternions.rotate (q p q-bar) vs transforms.rotate (a rotation matrix)",
    "normalize": "quaternions.normalize (unit quaternion) vs colormaps.normalize (data onto [0, 1])",
}
# an old public name kept working for students' code, warning and pointing to the new one
DEPRECATED = {("clipping.py", "face_normals"): "the old name of face_cross_products (not unit)"}


def _library_files():
    return sorted(p for p in (ROOT / "course_lib").rglob("*.py") if "__pycache__" not in p.parts)


def test_no_module_of_the_library_is_longer_than_about_a_thousand_lines():
    long = {str(p.relative_to(ROOT)): n for p in _library_files()
            if (n := len(p.read_text().splitlines())) > MAX_MODULE_LINES}
    assert not long, (f"modules over {MAX_MODULE_LINES} lines: {long}; split them into a package "
                      "along their sections (CONTRIBUTING.md, Layout)")


def test_each_function_and_class_of_the_algorithm_layer_is_defined_once():
    # the widgets' scene/State/Explorer and the exercises' checkers follow per-module patterns
    places = {}
    for path in _library_files():
        rel = path.relative_to(ROOT / "course_lib")
        if rel.parts[0] in ("widgets", "exercises") or rel.name == "draw.py":
            continue
        for node in ast.parse(path.read_text()).body:
            if isinstance(node, (ast.FunctionDef, ast.ClassDef)) \
                    and (str(rel), node.name) not in DEPRECATED:
                places.setdefault(node.name, []).append(str(rel))
    twice = {name: where for name, where in places.items()
             if len(where) > 1 and name not in SAME_NAME_DIFFERENT_CONCEPT}
    assert not twice, ("defined in more than one module (one implementation, imported where it is "
                       f"needed; or, for two concepts, two names): {twice}")
