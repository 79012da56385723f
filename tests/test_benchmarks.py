"""The benchmark runner works (tiny sizes): it must not rot between real measurements."""
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_benchmarks_quick_run_writes_both_tables(tmp_path):
    output = tmp_path / "results.md"
    done = subprocess.run([sys.executable, "-m", "benchmarks", "--quick", "--output", str(output)],
                          cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    text = output.read_text()
    assert text.strip() == done.stdout.strip()
    rows = re.findall(r"^\| (quaternion -> matrix|[a-z].*?) \| ([\d,]+) \| ([\d.]+) \| (.+?) \| "
                      r"([\d.]+) \| ([\d.]+) \|$", text, re.M)
    assert {r[0] for r in rows} >= {"quaternion -> matrix", "matrix -> quaternion"}
    for name, size, ours, ref_name, ref, ratio in rows:
        assert float(ours) > 0 and float(ref) > 0, (name, ours, ref)
        # the table rounds every number to 3 significant digits (relative error <= 0.5 %):
        # allow for that in the printed ratio
        ours, ref, ratio = float(ours), float(ref), float(ratio)
        slack = ratio * 0.0101 + ratio * 0.005
        assert abs(ratio - ours / ref) <= slack, (name, ours, ref, ratio)
    widgets = re.findall(r"^\| (.*explorer.*|.*composer.*) \| ([\d.]+) \| ([\d.]+) \| ([\d.]+) \|",
                         text, re.M)
    assert len(widgets) >= 9
    assert all(float(median) > 0 for _, median, _, _ in widgets)
