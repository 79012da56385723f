"""Fixtures of the browser tests: one JupyterLab server and one chromium per test worker,
always stopped, also when a test fails."""
import hashlib

import pytest

from .lab import ROOT, LabServer, launch_browser


def _notebook_hashes():
    """Every file under the course's notebook folders, checkpoints included: a checkpoint
    JupyterLab writes beside a notebook it opens would count as a change to the course (the
    hub test, running beside these, checks the same folders)."""
    return {p: hashlib.sha256(p.read_bytes()).hexdigest()
            for folder in ("notebooks", "solutions", "exercises")
            for p in sorted((ROOT / folder).rglob("*"))
            if p.is_file() and "__pycache__" not in p.parts}


@pytest.fixture(scope="session")
def lab(tmp_path_factory):
    before = _notebook_hashes()
    server = LabServer(tmp_path_factory.mktemp("jupyterlab")).start()
    yield server
    server.stop()
    changed = [str(p.relative_to(ROOT)) for p, digest in _notebook_hashes().items()
               if before.get(p) != digest]
    assert not changed, f"the browser tests wrote to the repository's notebooks: {changed}"


@pytest.fixture(scope="session")
def browser(tmp_path_factory):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        context = launch_browser(playwright, tmp_path_factory.mktemp("chromium-profile"))
        yield context
        context.close()
