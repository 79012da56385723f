#!/usr/bin/env python3
"""Build the course website, and its PDFs, from the stored notebooks: offline, no re-execution.

    python website/build.py                 # the HTML site in build/site/html
    python website/build.py --pdf           # and build/site/html/pdf/: one PDF per chapter
                                            # and one of the whole course (headless chromium)
    python website/build.py --serve         # then serve it on http://127.0.0.1:8000

COURSE_SITE_BUILD=<folder> builds somewhere other than build/site.

`make site` runs the second. The steps:

1. **Stage** (`stage`): copy the notebooks of notebooks/, exercises/ and solutions/ into
   build/site/src, each with a "where you are" box under its title (its place in the course
   map, links to open it live, its download and its PDF), every code cell collapsed
   (`hide-input`), and each explorer's output turned into its stored default-state picture
   with the explorer's one-line summary as alt text and caption (a widget view needs a kernel;
   a page shows the picture). Alongside: the landing page with the course map, the README's
   instructors' section and the benchmark results as pages, and the unchanged notebooks for
   download.
2. **Build** with Sphinx, myst-nb (`nb_execution_mode = "off"`: the stored outputs) and
   sphinx-book-theme (website/conf.py). MathJax is a local copy from npm (website/package.json,
   its version locked), served from the site: nothing is fetched when a page is viewed.
3. **Print** (`--pdf`): headless chromium prints every lesson, exercise and solution page with
   the site's print styles; pypdf joins them into a PDF per chapter and one for the course,
   with bookmarks.

Publishing: build/site/html is a static site; copy it to any static host (README).
"""
from __future__ import annotations

import argparse
import functools
import http.server
import os
import re
import shutil
import subprocess
import sys
import threading
import time
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]
HERE = ROOT / "website"
# where the site is built (tests/test_website.py builds into a temporary folder)
BUILD = Path(os.environ.get("COURSE_SITE_BUILD") or ROOT / "build" / "site").resolve()
SRC = BUILD / "src"
HTML = BUILD / "html"
NPM = ROOT / "build" / "website-npm"           # MathJax from npm, kept between builds
FOLDERS = ("notebooks", "exercises", "solutions")
WIDGET = "application/vnd.jupyter.widget-view+json"
# the README's Binder badge names the repository; OWNER/REPO until the course is published
BINDER = "https://mybinder.org/v2/gh/{repo}/HEAD?urlpath=lab/tree/{path}"
PLACEHOLDER_REPO = "OWNER/REPO"
# of MathJax's es5 folder, besides tex-mml-chtml.js: its fonts, the TeX extensions that
# \require loads, and the menu's parts (not the speech-rule engine's 4 MB, the menu's
# "explorer" is off by default)
MATHJAX_PARTS = ("output/chtml/fonts/woff-v2", "input/tex/extensions", "ui", "a11y")


# ---------------------------------------------------------------------------------------------
# What the course is made of
# ---------------------------------------------------------------------------------------------

def _title(nb):
    """The notebook's first `# ` heading."""
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                if line.startswith("# "):
                    return line[2:].strip()
    raise ValueError("a notebook of the course has no '# ' title")


@functools.lru_cache(maxsize=None)
def chapters(root=ROOT):
    """The chapters in course order: [{"stem", "number", "title", "short", "has": {folder}}]."""
    out = []
    for path in sorted((root / "notebooks").glob("ch*.ipynb")):
        title = _title(nbformat.read(path, as_version=4))
        match = re.match(r"Chapter (\d+)\s*[—-]\s*(.*)", title)
        number, rest = (int(match.group(1)), match.group(2)) if match else (None, title)
        short = re.split(r":", rest)[0].strip()
        out.append({"stem": path.stem, "number": number, "title": title, "short": short,
                    "has": [f for f in FOLDERS if (root / f / path.name).is_file()]})
    return tuple(out)


def repository():
    """OWNER/REPO of the course's GitHub repository, from the README's Binder badge."""
    if os.environ.get("COURSE_REPOSITORY"):
        return os.environ["COURSE_REPOSITORY"]
    match = re.search(r"mybinder\.org/v2/gh/([^/\s]+/[^/\s]+)/", (ROOT / "README.md").read_text())
    return match.group(1) if match else PLACEHOLDER_REPO


# ---------------------------------------------------------------------------------------------
# 1. Stage
# ---------------------------------------------------------------------------------------------

def _where_box(folder, stem, title, chapter, index, total):
    """The MyST admonition under a page's title: its place in the course, open live, download."""
    path = f"{folder}/{stem}.ipynb"
    live = BINDER.format(repo=repository(), path=path)
    lines = []
    if chapter is not None:
        kind = {"notebooks": "lesson", "exercises": "exercises", "solutions": "solutions"}[folder]
        here = f"Chapter {chapter['number']} {kind}" if chapter["number"] else kind
        lines.append(f"**Where you are:** {here} — lesson {index} of {total} in the "
                     f"[course map](../index.md#course-map).")
        trio = []
        for other in chapter["has"]:
            label = {"notebooks": "lesson", "exercises": "exercises",
                     "solutions": "solutions"}[other]
            trio.append(f"**{label}**" if other == folder
                        else f"[{label}](../{other}/{stem}.ipynb)")
        lines.append("This chapter: " + " · ".join(trio) + ".")
        pdf = f"pdf/{stem}.pdf"
        pdf_link = f" · <a href=\"../{pdf}\">PDF of the chapter</a>"
    else:
        lines.append(f"**Where you are:** {title} — see the [course map](../index.md#course-map).")
        pdf_link = ""
    lines.append(
        f"**Run it live:** <a class=\"binder-link\" href=\"{live}\"><img "
        f"src=\"../_static/binder-badge.svg\" alt=\"Open this notebook on Binder\" "
        f"width=\"109\" height=\"20\"></a> (nothing to install), or on your machine "
        f"`make lab` and open `{path}` ([how to install](../instructors.md#run-the-course)). "
        f"{{download}}`Download the notebook <../_originals/{path}>`{pdf_link}.")
    body = "\n\n".join(lines)
    return f":::{{admonition}} This page as a notebook\n:class: course-where\n\n{body}\n:::\n"


def _alt_for_figures(nb):
    """{cell index: alt text} for static figures: the section they belong to."""
    heading, count, alts = None, {}, {}
    for k, cell in enumerate(nb.cells):
        if cell.cell_type == "markdown":
            for line in cell.source.splitlines():
                if line.startswith("#"):
                    heading = line.lstrip("#").strip()
        elif cell.cell_type == "code" and heading:
            if any("image/png" in o.get("data", {}) for o in cell.get("outputs", [])):
                count[heading] = count.get(heading, 0) + 1
                alts[k] = f"Figure {count[heading]} of the section “{heading}”"
    return alts


def _plain(value):
    return "".join(value) if isinstance(value, list) else str(value)


def stage_notebook(source, target, folder, chapter, index, total):
    """Copy the notebook at `source` to `target`, made into a page (see the module's text)."""
    nb = nbformat.read(source, as_version=4)
    title = _title(nb)
    if folder == "solutions":                        # the same title as the exercises otherwise
        first = nb.cells[0]
        first.source = re.sub(r"^# (.*?)exercises", r"# \1solutions", first.source, count=1,
                              flags=re.M)
        if first.source.startswith("# ") and "solutions" not in first.source.splitlines()[0]:
            first.source = first.source.replace("# ", "# Solutions: ", 1)
    alts = _alt_for_figures(nb)
    explorers = 0
    for k, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        tags = cell.metadata.setdefault("tags", [])
        if "hide-input" not in tags and cell.source.strip():
            tags.append("hide-input")
        if folder == "solutions" and "BEGIN SOLUTION" in cell.source:
            tags.append("course-solution")      # shown unfolded: the code is the answer
        for output in cell.get("outputs", []):
            data = output.get("data", {})
            if WIDGET in data:
                summary = " ".join(_plain(data.get("text/plain", "")).split())
                del data[WIDGET]
                if "image/png" not in data:         # no picture stored: say what it is
                    output["data"] = {"text/markdown": f"*An explorer, live in JupyterLab:* "
                                                       f"{summary}"}
                else:
                    explorers += 1
                    cell.metadata["mystnb"] = {
                        "image": {"alt": summary or "An explorer of this chapter",
                                  "classes": "explorer-picture"},
                        "figure": {"caption": f"*Live in JupyterLab:* {summary}",
                                   "name": f"{source.stem}-{folder}-explorer-{explorers}"}}
            elif "image/png" in data and k in alts:
                cell.metadata.setdefault("mystnb", {}).setdefault("image", {"alt": alts[k]})
    box = nbformat.v4.new_markdown_cell(_where_box(folder, source.stem, title, chapter,
                                                   index, total))
    nb.cells.insert(1, box)
    target.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, target)
    return explorers


README_SECTIONS = ("## For instructors", "## The library")


def _instructors_page(staging):
    """The README's instructors' section (and how to install), as a page of the site."""
    readme = (ROOT / "README.md").read_text()
    start, end = (readme.index(h) for h in README_SECTIONS)
    section = readme[start:end].replace("## For instructors", "# For instructors", 1)
    section = re.sub(r"^###", "##", section, flags=re.M)
    install_end = readme.index("## The course")
    install = readme[readme.index("```sh"):install_end]
    for image in sorted(set(re.findall(r"\]\((docs/[^)]+\.png)\)", section))):
        (staging / image).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / image, staging / image)
    section = section.replace("](benchmarks/results.md)", "](speed.md)")
    section = section.replace("](hub/README.md)", "](hub.md)").replace("](hub/sizing.md)",
                                                                    "](sizing.md)")
    for name, page in (("README.md", "hub.md"), ("sizing.md", "sizing.md")):
        (staging / page).write_text((ROOT / "hub" / name).read_text())
    page = (section.rstrip() + "\n\n(run-the-course)=\n## Run the course, and publish this site"
            "\n\n" + install.strip() + "\n")
    (staging / "instructors.md").write_text(page)
    results = (ROOT / "benchmarks" / "results.md").read_text()
    (staging / "speed.md").write_text(results)


def _label(chapter):
    """The chapter's short name in the sidebar: "3 · Transformations and quaternions"."""
    return f"{chapter['number']} · {chapter['short']}" if chapter["number"] else chapter["short"]


def _landing(staging, counts):
    """index.md: what the course is, the course map and the toctrees of the sidebar."""
    rows = []
    for k, ch in enumerate(chapters(), 1):
        cells = []
        for folder, label in (("notebooks", "lesson"), ("exercises", "exercises"),
                              ("solutions", "solutions")):
            cells.append(f"[{label}]({folder}/{ch['stem']}.ipynb)" if folder in ch["has"]
                         else "—")
        rows.append(f"| {k} | {ch['number']} | {ch['short']} | {counts.get(ch['stem'], 0)} | "
                    + " | ".join(cells) + f" | <a href=\"pdf/{ch['stem']}.pdf\">PDF</a> |")
    toc = lambda caption, entries: (  # noqa: E731 - a small local formatter
        f"```{{toctree}}\n:caption: {caption}\n:maxdepth: 1\n:hidden:\n\n"
        + "\n".join(entries) + "\n```\n")
    page = [
        "# Graphics and Visualization, the course notebooks", "",
        "Lessons, explorers and exam practice for a university course on computer graphics "
        "and visualization, following the textbook *Graphics and Visualization: Principles "
        "and Algorithms* (Theoharis, Papaioannou, Platis, Patrikalakis). Every page here is a "
        "Jupyter notebook shown with its stored results: the text, the worked examples and a "
        "picture of every explorer. To move the sliders and drag the points, open a page live "
        "(the box under each title says how) or install the course with `make lab`.", "",
        "Start with [Start here](notebooks/00_start_here.ipynb). Each chapter has a lesson, "
        "exam-style exercises that check your answers and say why one is wrong, and their "
        "worked solutions; the [mock exam](notebooks/mock_exam.ipynb) draws from all of them. "
        "Instructors: see [For instructors](instructors.md). The whole course is also one "
        "<a href=\"pdf/course.pdf\">PDF</a> for reading offline or on paper.", "",
        "(course-map)=", "## Course map", "",
        "| # | chapter | topic | explorers | lesson | exercises | solutions | print |",
        "|--:|--:|---|--:|---|---|---|---|", *rows, "",
        toc("Start", ["Start here <notebooks/00_start_here>"]),
        toc("Lessons", [f"{_label(c)} <notebooks/{c['stem']}>" for c in chapters()]),
        toc("Exercises", [f"{_label(c)}: exercises <exercises/{c['stem']}>"
                          for c in chapters() if "exercises" in c["has"]]),
        toc("Solutions", [f"{_label(c)}: solutions <solutions/{c['stem']}>"
                          for c in chapters() if "solutions" in c["has"]]),
        toc("Exam", ["Mock exam <notebooks/mock_exam>"]),
        toc("For instructors", ["instructors", "hub", "sizing", "speed"]),
    ]
    (staging / "index.md").write_text("\n".join(page))


def mathjax():
    """MathJax's es5 folder, installed from npm at the version website/package-lock.json locks."""
    done = subprocess.run([sys.executable, str(ROOT / "scripts" / "npm-ci"), str(HERE), str(NPM)],
                          check=True, stdout=subprocess.PIPE, text=True)
    es5 = Path(done.stdout.strip()) / "mathjax" / "es5"
    assert (es5 / "tex-mml-chtml.js").is_file(), f"no MathJax in {es5}"
    return es5


def stage():
    """Write build/site/src: the pages, the originals for download, the static files."""
    if SRC.exists():
        shutil.rmtree(SRC)
    SRC.mkdir(parents=True)
    counts = {}
    lessons = [c["stem"] for c in chapters()]
    by_stem = {c["stem"]: c for c in chapters()}
    for folder in FOLDERS:
        for path in sorted((ROOT / folder).glob("*.ipynb")):
            chapter = by_stem.get(path.stem)
            index = lessons.index(path.stem) + 1 if chapter else None
            n = stage_notebook(path, SRC / folder / path.name, folder, chapter, index,
                               len(lessons))
            if folder == "notebooks":
                counts[path.stem] = n
            original = SRC / "_originals" / folder / path.name
            original.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(path, original)
    _landing(SRC, counts)
    _instructors_page(SRC)
    shutil.copy2(HERE / "conf.py", SRC / "conf.py")
    static = SRC / "_static"
    shutil.copytree(HERE / "static", static)
    es5, mj = mathjax(), static / "mathjax"
    mj.mkdir()
    shutil.copy2(es5 / "tex-mml-chtml.js", mj)
    for part in MATHJAX_PARTS:                  # what the combined file loads on demand
        shutil.copytree(es5 / part, mj / part)
    return counts


# ---------------------------------------------------------------------------------------------
# 2. Build
# ---------------------------------------------------------------------------------------------

def build(jobs="auto", quiet=True):
    """sphinx-build of the staged pages into build/site/html; the seconds it took."""
    started = time.monotonic()
    if HTML.exists():                   # no page or picture of an earlier build left behind
        shutil.rmtree(HTML)
    command = [sys.executable, "-m", "sphinx", "-b", "html", "-j", str(jobs),
               "-W", "--keep-going", "-E", str(SRC), str(HTML)]
    if quiet:
        command.insert(3, "-q")
    subprocess.run(command, check=True)
    return time.monotonic() - started


# ---------------------------------------------------------------------------------------------
# 3. Print
# ---------------------------------------------------------------------------------------------

class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


def serve(directory, port=0):
    """A static server of `directory` on the loopback address (a thread); (server, base URL)."""
    handler = functools.partial(_Quiet, directory=str(directory))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", port), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server, f"http://127.0.0.1:{server.server_address[1]}"


FOOTER = ("<div style=\"font-size:8px;width:100%;padding:0 12mm;color:#555;display:flex;"
          "justify-content:space-between\"><span>{title}</span><span>page "
          "<span class=\"pageNumber\"></span> of <span class=\"totalPages\"></span></span></div>")


def print_page(page, url, target, title):
    """Print the page at `url` to the PDF `target` (A4, the site's print styles, page numbers)."""
    page.goto(url, wait_until="load")
    page.emulate_media(media="print")
    page.evaluate("""async () => {
        for (const img of document.images) { img.loading = 'eager'; }
        await Promise.all([...document.images].map(img => img.complete ? null :
            new Promise(done => { img.onload = img.onerror = done; })));
        if (window.MathJax && MathJax.startup) { await MathJax.startup.promise; }
    }""")
    safe = title.replace("&", "&amp;").replace("<", "&lt;")
    page.pdf(path=str(target), format="A4", print_background=True,
             display_header_footer=True, header_template="<span></span>",
             footer_template=FOOTER.format(title=safe),
             margin={"top": "14mm", "bottom": "16mm", "left": "12mm", "right": "12mm"})


def make_pdfs(html=HTML, chromium=None):
    """One PDF per chapter (lesson, exercises, solutions) and course.pdf; {name: pages}."""
    from playwright.sync_api import sync_playwright
    from pypdf import PdfReader, PdfWriter

    chromium = chromium or shutil.which("chromium") or "/usr/bin/chromium"
    out = html / "pdf"
    parts = BUILD / "pdf-parts"
    out.mkdir(parents=True, exist_ok=True)
    parts.mkdir(parents=True, exist_ok=True)
    server, base = serve(html)
    printed = {}
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=chromium, headless=True,
                                        args=["--no-sandbox", "--disable-gpu"])
            page = browser.new_page()
            # nothing but the site itself: a request elsewhere would hang the print
            page.route(re.compile(r"^(?!http://127\.0\.0\.1[:/]).*"),
                       lambda route: route.abort())
            order = [("notebooks", "00_start_here", "Start here")]
            order += [(f, c["stem"], c["title"]) for c in chapters() for f in c["has"]]
            order += [("notebooks", "mock_exam", "Mock exam")]
            for folder, stem, title in order:
                target = parts / f"{folder}-{stem}.pdf"
                label = title if folder == "notebooks" else f"{title} — {folder}"
                print_page(page, f"{base}/{folder}/{stem}.html", target, label)
                printed[(folder, stem)] = (target, label)
            browser.close()
    finally:
        server.shutdown()

    def join(items, target):
        writer = PdfWriter()
        for path, label in items:
            start = len(writer.pages)
            writer.append(str(path))
            writer.add_outline_item(title=label, page_number=start)
        writer.add_metadata({"/Title": items[0][1] if len(items) == 1 else
                             "Graphics and Visualization: the course notebooks"})
        with open(target, "wb") as handle:
            writer.write(handle)
        return len(PdfReader(str(target)).pages)

    pages = {}
    for ch in chapters():
        items = [printed[(f, ch["stem"])] for f in ch["has"]]
        pages[ch["stem"]] = join(items, out / f"{ch['stem']}.pdf")
    pages["course"] = join([printed[k] for k in printed], out / "course.pdf")
    return pages


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pdf", action="store_true", help="also print the PDFs")
    parser.add_argument("--serve", action="store_true", help="serve the site afterwards")
    parser.add_argument("--port", type=int, default=8000)
    args = parser.parse_args(argv)
    started = time.monotonic()
    counts = stage()
    pages = sum(1 for folder in FOLDERS for _ in (SRC / folder).glob("*.ipynb"))
    print(f"staged {pages} pages, "
          f"{sum(counts.values())} explorer pictures ({time.monotonic() - started:.1f} s)")
    seconds = build()
    print(f"sphinx built {HTML} in {seconds:.1f} s")
    if args.pdf:
        t = time.monotonic()
        pages = make_pdfs()
        print(f"printed {len(pages) - 1} chapter PDFs and the course "
              f"({pages['course']} pages) in {time.monotonic() - t:.1f} s")
    size = sum(f.stat().st_size for f in HTML.rglob("*") if f.is_file())
    print(f"site: {size / 2**20:.1f} MiB in {HTML} ({time.monotonic() - started:.0f} s)")
    if args.serve:
        server, base = serve(HTML, args.port)
        print(f"serving {base}/index.html (Ctrl+C stops)")
        try:
            while True:
                time.sleep(3600)
        except KeyboardInterrupt:
            server.shutdown()


if __name__ == "__main__":
    main()
