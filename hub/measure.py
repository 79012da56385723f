#!/usr/bin/env python3
"""Measure what one student's kernel needs, lesson by lesson, to size a JupyterHub.

    python hub/measure.py              # prints a Markdown table; --write puts it in hub/sizing.md

Each lesson runs top to bottom in a fresh kernel (scripts/execute-notebooks, one at a time so
the CPU figures are not shared), with one cell added at the end that reads the kernel's own
peak resident memory (``VmHWM`` of /proc/self/status: the most it ever held in RAM) and the CPU
seconds it used (user + system, `resource.getrusage`). A student who runs a whole lesson and
then plays with its explorers needs about this much; the explorers' updates add CPU while a
slider moves (benchmarks/results.md: 10-70 ms of kernel time per frame) but little memory.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell

ROOT = Path(__file__).resolve().parents[1]
PROBE = """\
import json, resource
status = dict(line.split(":", 1) for line in open("/proc/self/status"))
usage = resource.getrusage(resource.RUSAGE_SELF)
print(json.dumps({"peak_mib": int(status["VmHWM"].split()[0]) / 1024,
                  "now_mib": int(status["VmRSS"].split()[0]) / 1024,
                  "cpu_s": usage.ru_utime + usage.ru_stime}))
"""


def measure(lessons, python=sys.executable):
    """{lesson stem: {"peak_mib", "now_mib", "cpu_s", "wall_s"}}, each in a fresh kernel."""
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        env = {**os.environ, "PYDEVD_DISABLE_FILE_VALIDATION": "1",
               "COURSE_PROGRESS_FILE": str(Path(tmp) / "progress.json"),
               "VTK_DEFAULT_OPENGL_WINDOW": os.environ.get("VTK_DEFAULT_OPENGL_WINDOW",
                                                           "vtkEGLRenderWindow")}
        for path in lessons:
            nb = nbformat.read(path, as_version=4)
            nb.cells.append(new_code_cell(PROBE))
            copy = path.parent / f".measure_{path.name}"      # beside it: the lesson's folder
            nbformat.write(nb, copy)
            try:
                started = time.monotonic()
                done = subprocess.run([python, str(ROOT / "scripts" / "execute-notebooks"),
                                       "--json", str(copy)], env=env, capture_output=True,
                                      text=True)
                wall = time.monotonic() - started
            finally:
                copy.unlink()
            result = json.loads(done.stdout.strip().splitlines()[-1])
            if not result["ok"]:
                raise SystemExit(f"{path.name} failed: {result.get('error')}")
            last = max(result["outputs"], key=int)
            figures = json.loads(result["outputs"][last].strip().splitlines()[-1])
            results[path.stem] = {**figures, "wall_s": wall}
            print(f"  {path.stem}: peak {figures['peak_mib']:.0f} MiB, "
                  f"{figures['cpu_s']:.1f} CPU s", file=sys.stderr, flush=True)
    return results


def table(results):
    rows = ["| lesson | kernel peak memory (MiB) | after the last cell (MiB) | "
            "CPU seconds for the whole lesson |", "|---|---:|---:|---:|"]
    for stem, r in results.items():
        rows.append(f"| {stem} | {r['peak_mib']:.0f} | {r['now_mib']:.0f} | {r['cpu_s']:.1f} |")
    peaks = sorted(r["peak_mib"] for r in results.values())
    rows.append(f"| **largest / median** | **{peaks[-1]:.0f} / {peaks[len(peaks) // 2]:.0f}** "
                "| | |")
    return "\n".join(rows)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="write hub/sizing.md's table")
    args = parser.parse_args(argv)
    lessons = sorted((ROOT / "notebooks").glob("ch*.ipynb"))
    results = measure(lessons)
    text = table(results)
    print(text)
    if args.write:
        target = ROOT / "hub" / "sizing.md"
        page = target.read_text() if target.exists() else ""
        start, end = "<!-- measured: start -->", "<!-- measured: end -->"
        if start in page and end in page:
            page = page[:page.index(start) + len(start)] + "\n" + text + "\n" + \
                page[page.index(end):]
            target.write_text(page)


if __name__ == "__main__":
    main()
