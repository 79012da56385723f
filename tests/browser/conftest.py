"""Fixtures of the browser tests: one JupyterLab server and one chromium per test worker,
always stopped, also when a test fails."""
import hashlib

import pytest

from .lab import ROOT, LabServer, launch_browser


def _notebook_hashes():
    return {p: hashlib.sha256(p.read_bytes()).hexdigest()
            for folder in ("notebooks", "solutions", "exercises")
            for p in sorted((ROOT / folder).glob("*.ipynb"))}


@pytest.fixture(scope="session")
def lab(tmp_path_factory):
    before = _notebook_hashes()
    server = LabServer(tmp_path_factory.mktemp("jupyterlab")).start()
    yield server
    server.stop()
    changed = [p.name for p, digest in _notebook_hashes().items() if before.get(p) != digest]
    assert not changed, f"the browser tests wrote to the repository's notebooks: {changed}"


@pytest.fixture(scope="session")
def browser(tmp_path_factory):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as playwright:
        context = launch_browser(playwright, tmp_path_factory.mktemp("chromium-profile"))
        yield context
        context.close()
