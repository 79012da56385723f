"""Run the benchmarks: ``python -m benchmarks [--quick] [--output PATH]``."""
import argparse
import datetime
import importlib
import os
import platform
import sys
from pathlib import Path

import numpy as np

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
    parser.add_argument("--output", type=Path, default=HERE / "results.md")
    args = parser.parse_args(argv)
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
    print(text)
    args.output.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
