# The README's two commands. Each creates .venv when it is missing, installs the project with its
# test extra into it, and checks the few Debian packages headless 3D rendering needs.
#
#   make lab     open the course in JupyterLab
#   make test    run the whole suite: unit, property and cross-check tests, doctests, headless
#                widget tests and nbval over notebooks/, solutions/ and exercises/
#
# Other targets: make exercises (rebuild exercises/ from solutions/), make notebooks (re-execute
# every notebook and store its outputs), make benchmarks, make site (the course website and its
# PDFs in build/site/html, from the stored notebooks), make binder-dockerfile (the Dockerfile
# Binder builds), make hub-image (a JupyterHub's single-user image, hub/README.md), make clean
# (also removes build/runtime-venv, the tests' runtime-only venv).

PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
PYTEST_ARGS ?=
# JupyterLab refuses to run as root unless told (containers, some lab machines)
LAB_ARGS ?= $(if $(filter 0,$(shell id -u)),--allow-root,)

.PHONY: lab lecture screenshots test system-packages exercises notebooks benchmarks clean \
        binder-dockerfile site hub-image

lab: $(STAMP)
	@scripts/system-packages --warn-only --no-browser
	$(BIN)/jupyter lab --ServerApp.root_dir=. --LabApp.default_url=/lab/tree/notebooks/00_start_here.ipynb $(LAB_ARGS)

# lecture mode: figures drawn 1.5 times larger for a projector (SCALE=1.8 for more); present a
# lesson as slides with the deck button of the notebook toolbar (see the README)
lecture: $(STAMP)
	@scripts/system-packages --warn-only --no-browser
	COURSE_LECTURE=$(or $(SCALE),1) $(BIN)/jupyter lab --ServerApp.root_dir=. --LabApp.default_url=/lab/tree/notebooks/00_start_here.ipynb $(LAB_ARGS)

test: $(STAMP)
	@scripts/system-packages
	$(BIN)/python -m pytest -n 2 --dist loadscope --no-loadscope-reorder $(PYTEST_ARGS)

$(STAMP): pyproject.toml
	@scripts/system-packages --python-only
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

# the README's screenshots, taken by the end-to-end browser tests
screenshots: $(STAMP)
	@scripts/system-packages
	$(BIN)/python -m pytest -o addopts="" -p no:cacheprovider tests/browser/test_interactions.py tests/browser/test_lecture.py
	cp test-artifacts/browser/quaternion-explorer-widget.png docs/screenshots/quaternion-explorer.png
	cp test-artifacts/browser/bezier-editor-widget.png docs/screenshots/bezier-editor.png
	cp test-artifacts/browser/transfer-function-widget.png docs/screenshots/transfer-function-editor.png
	cp test-artifacts/browser/cohen-sutherland-widget.png docs/screenshots/cohen-sutherland.png
	cp test-artifacts/browser/lecture-slide-1.png docs/screenshots/lecture-slide.png

exercises: $(STAMP)
	$(BIN)/python -m course_lib.exercises.build

notebooks: $(STAMP)
	$(BIN)/python -m course_lib.exercises.build --execute

# the single-user image of a class's JupyterHub (hub/README.md): repo2docker with the course in
# /srv/course, outside the home folder the hub mounts each student's volume over, made read-only
# by postBuild; needs a container engine. IMAGE=registry/name:tag; PUSH=1 pushes it too
IMAGE ?= graphics-course:latest
hub-image: $(STAMP)
	$(BIN)/repo2docker --no-run --user-id 1000 --user-name jovyan --target-repo-dir /srv/course \
	  --image-name $(IMAGE) $(if $(PUSH),--push,) .

# the course website (Sphinx, myst-nb, the stored outputs) and its PDFs (headless chromium), in
# build/site/html; website/build.py --serve shows it on http://127.0.0.1:8000
site: $(STAMP)
	@scripts/system-packages --site
	$(BIN)/python website/build.py --pdf

benchmarks: $(STAMP)
	@scripts/system-packages
	$(BIN)/python -m benchmarks

# the Dockerfile Binder builds from apt.txt, environment.yml, postBuild and start, printed by
# repo2docker without a container engine (as on mybinder.org: user jovyan, uid 1000);
# tests/test_routes.py checks it
binder-dockerfile: $(STAMP)
	$(BIN)/repo2docker --no-build --debug --user-id 1000 --user-name jovyan .

clean:
	rm -rf $(VENV) build *.egg-info .pytest_cache
