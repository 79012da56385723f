"""Timings of course_lib against reference libraries, measured in the same run.

``python -m benchmarks`` prints two tables and writes them to ``benchmarks/results.md``:

* operations: operation, size, our median, the reference library's median on the same input,
  and the ratio (ours / reference; below 1 means we are faster);
* widget updates: the median time of one update as a student's slider move triggers it
  (recompute the scene, redraw the moving artists, encode the picture ipympl sends), its
  90th percentile, and the time of a full redraw (what turning a 3D view costs).

Each chapter adds a module ``benchmarks/chNN.py`` with ``operations(quick)`` and
``widgets(quick)`` functions returning rows; ``benchmarks/__main__.py`` lists the modules.
"""
import statistics
import time


def median_time(func, repeat=15, warmup=2):
    """Median wall time of ``func()`` in seconds over `repeat` runs, after `warmup` runs."""
    for _ in range(warmup):
        func()
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def timings(func, repeat=40, warmup=3):
    """All wall times of ``func(i)`` in seconds, i = 0 .. repeat-1, after `warmup` runs."""
    for i in range(warmup):
        func(i)
    times = []
    for i in range(repeat):
        start = time.perf_counter()
        func(i)
        times.append(time.perf_counter() - start)
    return times


def operation_row(name, size, ours, reference, reference_name, repeat=15):
    """Time `ours` and `reference` (no-argument callables) on the same input; one table row."""
    t_ours = median_time(ours, repeat)
    t_ref = median_time(reference, repeat)
    return {"operation": name, "size": size, "ours_ms": 1e3 * t_ours,
            "reference": reference_name, "reference_ms": 1e3 * t_ref, "ratio": t_ours / t_ref}


def widget_row(name, update, full_draw, repeat=40, target_ms=50.0):
    """Time a widget's update (``update(i)``) and full redraw (``full_draw()``); one row."""
    times = sorted(timings(update, repeat))
    full = median_time(full_draw, repeat=max(5, repeat // 4))
    return {"widget": name, "median_ms": 1e3 * statistics.median(times),
            "p90_ms": 1e3 * times[int(0.9 * (len(times) - 1))], "full_ms": 1e3 * full,
            "target_ms": target_ms}
