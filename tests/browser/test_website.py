"""The course website (`make site`, website/build.py): built from the stored notebooks, every page
opened in headless chromium with every request outside the loopback address blocked.

What a reader of the site must get: every page loads with no failed request and no broken
image, its mathematics typeset (no `$…$` left as text), a picture with alt text for every
explorer of its notebook, collapsible code, a way to open it live and to download it; links
between pages resolve; the search finds "de Casteljau"; the dark mode is dark; and the PDFs hold
every figure of their chapter. Screenshots of three pages in light and dark mode are written to
test-artifacts/website/ for a person to look at.

The expected counts come from the notebooks' JSON, read here, not from the site builder.
"""
import html.parser
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path
from urllib.parse import unquote, urljoin, urlparse

import pytest

from .lab import CHROMIUM, CHROMIUM_FLAGS, ROOT

WIDGET = "application/vnd.jupyter.widget-view+json"
FOLDERS = ("notebooks", "exercises", "solutions")
ARTIFACTS = ROOT / "test-artifacts" / "website"
LOOPBACK = re.compile(r"^(?!http://127\.0\.0\.1[:/]).*")
SHOTS = ("index", "notebooks/ch07_curves_surfaces", "solutions/ch07_curves_surfaces",
         "notebooks/00_start_here")


def _outputs(path):
    nb = json.loads(path.read_text())
    return [o for cell in nb["cells"] if cell["cell_type"] == "code"
            for o in cell.get("outputs", [])]


def explorers_in(path):
    """The explorer outputs of a stored notebook: its widget views."""
    return [o for o in _outputs(path) if WIDGET in o.get("data", {})]


def pictures_in(path):
    """The pictures a stored notebook shows: every image/png output (figures and explorers)."""
    return [o for o in _outputs(path) if "image/png" in o.get("data", {})]


NOTEBOOKS = sorted(p.relative_to(ROOT) for f in FOLDERS for p in (ROOT / f).glob("*.ipynb"))
LESSONS = sorted(p.stem for p in (ROOT / "notebooks").glob("ch*.ipynb"))


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """The site built with its PDFs into a temporary folder; (html folder, build output)."""
    build = tmp_path_factory.mktemp("site")
    started = time.monotonic()
    done = subprocess.run([sys.executable, str(ROOT / "website" / "build.py"), "--pdf"],
                          env={**os.environ, "COURSE_SITE_BUILD": str(build)},
                          capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, (
        f"website/build.py --pdf failed (a Sphinx warning is an error):\n"
        f"{done.stdout[-3000:]}\n{done.stderr[-6000:]}")
    print(f"\nsite built in {time.monotonic() - started:.0f} s:\n{done.stdout}")
    return build / "html", done.stdout


@pytest.fixture(scope="module")
def server(site):
    sys.path.insert(0, str(ROOT / "website"))
    try:
        import build as site_build
    finally:
        sys.path.pop(0)
    httpd, base = site_build.serve(site[0])
    yield base
    httpd.shutdown()


@pytest.fixture(scope="module")
def chromium():
    from playwright.sync_api import sync_playwright

    if not Path(CHROMIUM).exists():
        pytest.fail("chromium is not installed: scripts/system-packages installs it (make test)")
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, headless=True,
                                    args=CHROMIUM_FLAGS)
        yield browser
        browser.close()


class Visit:
    """One page opened with outside requests blocked; what went wrong while it loaded."""

    def __init__(self, context, url):
        self.problems = []
        page = self.page = context.new_page()
        page.route(LOOPBACK, self._block)
        page.on("requestfailed", lambda r: self.problems.append(
            f"request failed: {r.url} ({r.failure})"))
        page.on("response", lambda r: self.problems.append(f"HTTP {r.status}: {r.url}")
                if r.status >= 400 else None)
        page.on("console", lambda m: self.problems.append(f"console error: {m.text}")
                if m.type == "error" else None)
        page.on("pageerror", lambda e: self.problems.append(f"page error: {e}"))
        page.goto(url, wait_until="load")
        page.evaluate("""async () => {
            if (window.MathJax && MathJax.startup) { await MathJax.startup.promise; }
        }""")

    def _block(self, route):
        self.problems.append(f"asked for something outside the site: {route.request.url}")
        route.abort()


READ_PAGE = """() => {
    const inCode = el => el.closest('pre, code, .highlight, script, style, mjx-container');
    const walker = document.createTreeWalker(document.querySelector('main') || document.body,
                                             NodeFilter.SHOW_TEXT);
    const text = [];
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
        if (!inCode(n.parentElement)) { text.push(n.textContent); }
    }
    const cells = [...document.querySelectorAll('div.cell')];
    const withInput = cells.filter(c => c.querySelector('.cell_input'));
    return {
        text: text.join(' '),
        math: document.querySelectorAll('mjx-container').length,
        broken: [...document.images].filter(i => !i.complete || i.naturalWidth === 0)
                                    .map(i => i.getAttribute('src')),
        explorers: [...document.querySelectorAll('img.explorer-picture')].map(
            i => ({alt: i.getAttribute('alt') || '', width: i.naturalWidth,
                   caption: (i.closest('figure')?.querySelector('figcaption')?.innerText
                             || '')})),
        openCode: withInput.filter(c => !c.querySelector('details .cell_input')).length,
        codeCells: withInput.length,
        solutionsShown: [...document.querySelectorAll('.tag_course-solution .cell_input')]
                        .filter(el => el.checkVisibility()).length,
        binder: [...document.querySelectorAll('a.binder-link')].map(a => a.href),
        download: [...document.querySelectorAll('a.download')].map(a => a.getAttribute('href')),
        prev: !!document.querySelector('a.left-prev'),
        next: !!document.querySelector('a.right-next'),
        search: !!document.querySelector('.search-button, .search-button-field, form.bd-search'),
        themeSwitch: !!document.querySelector('.theme-switch-button'),
        navCurrent: [...document.querySelectorAll('.bd-sidebar-primary a.current')]
                    .map(a => a.innerText),
    };
}"""

MATH_LEFT = re.compile(r"\$[^$\s][^$]*?\$|\\\(|\\\[")


def _pages(html):
    return sorted(p.relative_to(html).as_posix() for p in html.rglob("*.html")
                  if not p.relative_to(html).parts[0].startswith("_"))


def test_every_page_loads_whole_and_offline(site, server, chromium):
    html, _ = site
    pages = _pages(html)
    notebook_pages = {f"{p.with_suffix('')}.html" for p in NOTEBOOKS}
    missing = sorted(notebook_pages - set(pages))
    assert not missing, f"notebooks without a page on the site: {missing}"
    assert {"index.html", "search.html", "instructors.html"} <= set(pages)

    context = chromium.new_context(viewport={"width": 1400, "height": 1000})
    trouble = []
    for name in pages:
        visit = Visit(context, f"{server}/{name}")
        seen = visit.page.evaluate(READ_PAGE)
        visit.page.close()
        where = f"{name}: "
        trouble += [where + p for p in visit.problems]
        trouble += [where + f"broken image {src}" for src in seen["broken"]]
        left = MATH_LEFT.findall(seen["text"])
        if left:
            trouble.append(where + f"mathematics left as text: {left[:3]}")
        source = ROOT / Path(name).with_suffix(".ipynb")
        if source.is_file() and source.parent.name in FOLDERS:
            trouble += _check_notebook_page(where, source, seen)
    context.close()
    assert not trouble, "the site's pages:\n" + "\n".join(trouble[:60])


def _check_notebook_page(where, source, seen):
    """What a page made from the notebook at `source` must have."""
    trouble = []
    expected = explorers_in(source)
    if len(seen["explorers"]) != len(expected):
        trouble.append(where + f"{len(seen['explorers'])} explorer pictures, the notebook has "
                       f"{len(expected)} explorers")
    for k, (shown, output) in enumerate(zip(seen["explorers"], expected)):
        summary = " ".join("".join(output["data"]["text/plain"]).split())
        if not shown["alt"].strip() or shown["alt"] != summary:
            trouble.append(where + f"explorer {k + 1}: alt text {shown['alt']!r}, expected its "
                           f"summary {summary!r}")
        if shown["width"] < 100:
            trouble.append(where + f"explorer {k + 1}: picture {shown['width']} px wide")
    if seen["openCode"]:
        trouble.append(where + f"{seen['openCode']} of {seen['codeCells']} code cells cannot be "
                       "collapsed")
    if source.parent.name == "solutions":       # the worked answers: shown, not folded
        answers = [c for c in json.loads(source.read_text())["cells"]
                   if c["cell_type"] == "code" and "BEGIN SOLUTION" in "".join(c["source"])]
        if not answers or seen["solutionsShown"] != len(answers):
            trouble.append(where + f"{seen['solutionsShown']} worked answers shown unfolded, "
                           f"the notebook has {len(answers)}")
    relative = source.relative_to(ROOT).as_posix()
    if not any(link.endswith(f"urlpath=lab/tree/{relative}") for link in seen["binder"]):
        trouble.append(where + f"no Binder link opening {relative}: {seen['binder']}")
    if not any(link.endswith(f"/{source.name}") for link in seen["download"]):
        trouble.append(where + f"no download of {source.name}: {seen['download']}")
    if not (seen["prev"] and seen["next"]):
        trouble.append(where + "no previous/next links")
    if not (seen["search"] and seen["themeSwitch"]):
        trouble.append(where + "no search box or no light/dark switch")
    if not seen["navCurrent"]:
        trouble.append(where + "the sidebar's course map does not mark this page")
    return trouble


class _Links(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if attrs.get("id"):
            self.ids.add(attrs["id"])
        for key in ("href", "src"):
            if attrs.get(key) and (tag, key) in {("a", "href"), ("img", "src"),
                                                 ("link", "href"), ("script", "src")}:
                self.links.append(attrs[key])


def test_links_between_pages_resolve(site):
    """Every link, picture and script of every page points at a file of the site (and an
    anchor on it); the downloads are the repository's notebooks, byte for byte."""
    html, _ = site
    parsed = {}
    for path in html.rglob("*.html"):
        if path.relative_to(html).parts[0] == "_static":      # the theme's templates
            continue
        parser = _Links()
        parser.feed(path.read_text(encoding="utf-8"))
        parsed[path] = parser
    broken, downloads = [], {}
    for path, parser in parsed.items():
        base = "http://site/" + path.relative_to(html).as_posix()
        for link in parser.links:
            url = urlparse(urljoin(base, link))
            if url.scheme in ("mailto", "javascript", "data") or url.netloc not in ("site", ""):
                continue
            target = html / unquote(url.path.lstrip("/"))
            if target.is_dir():
                target = target / "index.html"
            if not target.is_file():
                broken.append(f"{path.relative_to(html)} → {link}")
            elif url.fragment and target.suffix == ".html" and target in parsed \
                    and url.fragment not in parsed[target].ids:
                broken.append(f"{path.relative_to(html)} → {link} (no such anchor)")
            elif "_downloads" in target.parts and target.suffix == ".ipynb":
                downloads[target.name] = target
    assert not broken, "links that lead nowhere:\n" + "\n".join(sorted(set(broken))[:40])
    names = {p.name for p in NOTEBOOKS}
    assert set(downloads) == names, f"downloads missing: {sorted(names - set(downloads))}"
    for name, target in downloads.items():
        folder = next(p.parent for p in NOTEBOOKS if p.name == name
                      and target.read_bytes() == (ROOT / p).read_bytes())
        assert folder, f"the download {name} is not the repository's notebook"


def test_search_finds_de_casteljau(site, server, chromium):
    context = chromium.new_context(viewport={"width": 1400, "height": 1000})
    visit = Visit(context, f"{server}/search.html?q=de+Casteljau")
    page = visit.page
    page.wait_for_selector("#search-results ul.search li", timeout=30_000)
    found = page.eval_on_selector_all("#search-results ul.search li a",
                                      "links => links.map(a => a.getAttribute('href'))")
    context.close()
    assert any("notebooks/ch07_curves_surfaces" in (h or "") for h in found), (
        f"searching 'de Casteljau' did not find the chapter 7 lesson: {found}")
    assert not visit.problems, visit.problems


def _luminance(rgb):
    r, g, b = (int(v) / 255 for v in re.findall(r"\d+", rgb)[:3])
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


@pytest.mark.parametrize("scheme", ["light", "dark"])
def test_screenshots_in_light_and_dark_mode(site, server, chromium, scheme):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    context = chromium.new_context(viewport={"width": 1400, "height": 1000},
                                   color_scheme=scheme)
    for name in SHOTS:
        visit = Visit(context, f"{server}/{name}.html")
        page = visit.page
        theme = page.evaluate("document.documentElement.dataset.theme")
        background = page.evaluate("getComputedStyle(document.body).backgroundColor")
        text = page.evaluate("getComputedStyle(document.querySelector('main p') || "
                             "document.body).color")
        shot = ARTIFACTS / f"{name.replace('/', '-')}-{scheme}.png"
        page.screenshot(path=str(shot))
        explorer = page.locator("figure:has(img.explorer-picture)")
        if explorer.count():                    # and the first explorer's picture, whole
            explorer.first.scroll_into_view_if_needed()
            page.screenshot(path=str(shot.with_name(shot.stem + "-explorer.png")))
        page.close()
        assert theme == scheme, f"{name}: the page's theme is {theme}, the reader's {scheme}"
        if scheme == "dark":
            assert _luminance(background) < 0.2 < _luminance(text), (name, background, text)
        else:
            assert _luminance(background) > 0.8 > _luminance(text), (name, background, text)
        assert not visit.problems, visit.problems
    context.close()


def test_pdfs_hold_every_figure_of_their_chapter(site):
    """One PDF per chapter (its lesson, exercises and solutions) and one of the course; each
    holds as many pictures as its notebooks show, and its first page is not blank."""
    import pypdfium2
    from pypdf import PdfReader

    html, _ = site
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    total = 0
    for stem in LESSONS:
        path = html / "pdf" / f"{stem}.pdf"
        assert path.is_file(), f"no PDF of {stem}"
        reader = PdfReader(str(path))
        parts = [ROOT / f / f"{stem}.ipynb" for f in FOLDERS if (ROOT / f / f"{stem}.ipynb").is_file()]
        expected = sum(len(pictures_in(p)) for p in parts)
        images = sum(len(page.images) for page in reader.pages)
        assert images == expected, (
            f"{path.name}: {images} pictures in the PDF, {expected} in the notebooks of the "
            "chapter (an explorer or a figure did not print)")
        assert len(reader.outline) == len(parts), f"{path.name}: bookmarks {reader.outline}"
        total += len(reader.pages)
        document = pypdfium2.PdfDocument(str(path))
        picture = document[0].render(scale=1).to_pil().convert("L")
        lo, hi = picture.getextrema()
        picture.save(ARTIFACTS / f"{stem}-page1.png")
        assert hi - lo > 128, f"{path.name}: the first page is blank"
        document.close()
    assert _green_tick_printed(html / "pdf" / f"{LESSONS[0]}.pdf"), (
        "the feedback's ✅ is not printed in colour: an empty box (no emoji font; "
        "scripts/system-packages installs fonts-noto-color-emoji)")
    course = PdfReader(str(html / "pdf" / "course.pdf"))
    assert len(course.pages) > total, "course.pdf holds fewer pages than its chapters"
    assert len(course.outline) >= len(LESSONS)


def _green_tick_printed(path):
    """Whether the first ✅ of the PDF at `path` is drawn green (a glyph, not an empty box)."""
    import pypdfium2

    document = pypdfium2.PdfDocument(str(path))
    try:
        for page in document:
            text = page.get_textpage()
            index = text.get_text_range().find("\u2705")
            if index < 0:
                continue
            left, bottom, right, top = text.get_charbox(index)
            scale = 3
            picture = page.render(scale=scale).to_pil().convert("RGB")
            box = picture.crop((int(left * scale), int(picture.height - top * scale),
                                int(right * scale) + 1, int(picture.height - bottom * scale) + 1))
            pixels = box.load()
            green = sum(1 for x in range(box.width) for y in range(box.height)
                        if pixels[x, y][1] > pixels[x, y][0] + 30
                        and pixels[x, y][1] > pixels[x, y][2] + 30)
            return green > 0.1 * box.width * box.height
        raise AssertionError(f"{path.name}: no ✅ found (the solutions' feedback), or it was "
                             "printed as a box without an emoji font")
    finally:
        document.close()
