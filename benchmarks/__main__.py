"""Run the benchmarks: ``python -m benchmarks [--quick] [--browser] [--output PATH]``.

Without ``--browser``: the library against reference libraries, and the explorers' updates in
the kernel. With ``--browser``: every explorer timed in JupyterLab in headless chromium
(:mod:`benchmarks.browser`); its section of results.md is replaced and the rest kept."""
import argparse
import datetime
import importlib
import os
import platform
import sys
from pathlib import Path

import numpy as np

from . import browser

HERE = Path(__file__).resolve().parent
# one module per chapter, benchmarks/chNN.py, each with operations(quick) and widgets(quick)
CHAPTERS = [f"benchmarks.{p.stem}" for p in sorted(HERE.glob("ch[0-9][0-9].py"))]


def _number(value):
    """Three significant digits, never in exponent form and never rounded to 0.00: a reference
    that takes microseconds still shows (0.00312, not 0.00)."""
    if value >= 100:
        return f"{value:.0f}"
    return np.format_float_positional(value, precision=3, fractional=False, trim="-")


def _table(rows, columns):
    head = "| " + " | ".join(title for title, _ in columns) + " |"
    rule = "|" + "|".join("---" if title in ("operation", "reference", "widget update")
                          else "---:" for title, _ in columns) + "|"
    body = ["| " + " | ".join(fmt(row) for _, fmt in columns) + " |" for row in rows]
    return "\n".join([head, rule, *body])


OPERATION_COLUMNS = [
    ("operation", lambda r: r["operation"]),
    ("size", lambda r: f"{r['size']:,}"),
    ("ours (ms)", lambda r: _number(r["ours_ms"])),
    ("reference", lambda r: r["reference"]),
    ("reference (ms)", lambda r: _number(r["reference_ms"])),
    ("ratio ours/ref", lambda r: _number(r["ratio"])),
]
WIDGET_COLUMNS = [
    ("widget update", lambda r: r["widget"]),
    ("median (ms)", lambda r: f"{r['median_ms']:.1f}"),
    ("90th percentile (ms)", lambda r: f"{r['p90_ms']:.1f}"),
    ("full redraw (ms)", lambda r: f"{r['full_ms']:.1f}"),
    ("target (ms)", lambda r: f"< {r['target_ms']:.0f}"),
]


def main(argv=None):
    parser = argparse.ArgumentParser(description="Time course_lib against reference libraries.")
    parser.add_argument("--quick", action="store_true", help="tiny sizes (a smoke test)")
    parser.add_argument("--browser", action="store_true",
                        help="time every explorer in JupyterLab in headless chromium")
    parser.add_argument("--lesson", action="append", default=None,
                        help="with --browser: only this notebook (repeatable)")
    parser.add_argument("--output", type=Path, default=HERE / "results.md")
    args = parser.parse_args(argv)
    if args.browser:
        return _browser(args)
    from course_lib.draw import configure_offscreen_vtk

    configure_offscreen_vtk()
    operations, widgets = [], []
    for name in CHAPTERS:
        module = importlib.import_module(name)
        operations += module.operations(args.quick)
        widgets += module.widgets(args.quick)
    import scipy

    machine = (f"{datetime.date.today()}, {platform.machine()} with {os.cpu_count()} cores, "
               f"Python {platform.python_version()}, numpy {np.__version__}, "
               f"scipy {scipy.__version__}" + (" (quick run: tiny sizes)" if args.quick else ""))
    text = "\n\n".join([
        "# Benchmarks", f"Measured by `python -m benchmarks` on {machine}.",
        "Medians of repeated runs; the reference runs on the same input in the same process.",
        "## Operations", _table(operations, OPERATION_COLUMNS),
        "## Widget updates",
        "One update = what one slider move costs in the kernel: recompute the scene, redraw the "
        "moving artists (blitting) and encode the PNG that ipympl sends to the browser. A full "
        "redraw happens when the student turns a 3D view or the figure is first shown.",
        _table(widgets, WIDGET_COLUMNS),
    ]) + "\n"
    old = args.output.read_text() if args.output.exists() else ""
    kept = old[old.index(browser.SECTION):] if browser.SECTION in old else ""
    print(text)
    args.output.write_text(browser.with_section(text, kept))
    return 0


def _machine(quick):
    return (f"{datetime.date.today()}, {platform.machine()} with {os.cpu_count()} cores"
            + (" (quick run: fewer samples)" if quick else ""))


def _browser(args):
    rows, lessons = browser.run(args.quick, args.lesson)
    section = browser.report(rows, lessons, _machine(args.quick))
    print(section)
    if args.lesson:
        print("(one lesson measured: results.md left as it is)")
        return 0
    old = args.output.read_text() if args.output.exists() else "# Benchmarks\n"
    args.output.write_text(browser.with_section(old, section))
    return 0


if __name__ == "__main__":
    sys.exit(main())
