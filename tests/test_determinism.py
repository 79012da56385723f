"""Every result the course shows is the same whatever SIMD and BLAS kernels the CPU gets.

numpy dispatches its sort/partition kernels and its SIMD float loops by CPU features at run
time (ties come out of an AVX-512, an AVX2 and a baseline quicksort in different orders), and
OpenBLAS picks its kernels by CPU (dot products may differ in the last bit). A BVH split that
leaves ties to the kernel, or a threshold met exactly up to rounding, then gives other counts,
trees and exercise variants on another machine, and the stored notebook outputs fail there.

``determinism_probe.py`` fingerprints the order-sensitive builds (both BVHs, the BSP trees and
painter's orders, the half-edge builds, QEM records, marching squares/cubes, the widgets' depth
orders, the exercise generators over many seeds, the counts the notebooks print). It runs here
in subprocesses: once with numpy's default dispatch, then with the machine's highest dispatch
targets disabled, with all of them disabled (baseline code only), and with other OpenBLAS
kernels; discrete results must agree exactly, floats to a relative 1e-9. The settings are built
from what numpy reports for this machine, so the test works on any CPU; a setting that does not
take effect fails the test rather than passing vacuously.
"""
import json
import os
import platform
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import determinism_probe as probe

PROBE = Path(__file__).with_name("determinism_probe.py")
#: Floats of a result may differ by this much (relative to their weighted absolute sum).
RTOL = 1e-9
#: OpenBLAS core types to force on x86: the generic SSE3 kernels run on every x86-64 CPU;
#: Haswell's (AVX2 with FMA) only where the CPU has those.
GENERIC_CORE, FMA_CORE = "Prescott", "Haswell"


def _environment(env_changes):
    env = dict(os.environ)
    for name, value in env_changes.items():
        if value is None:
            env.pop(name, None)
        else:
            env[name] = value
    return env


def run_probe(env_changes, *args):
    """The probe's JSON output in a subprocess whose environment is changed by `env_changes`
    (name -> value, or None to remove the variable)."""
    done = subprocess.run([sys.executable, str(PROBE), *args], env=_environment(env_changes),
                          capture_output=True, text=True, timeout=900, cwd=PROBE.parent)
    assert done.returncode == 0, f"the probe failed under {env_changes}:\n{done.stderr[-3000:]}"
    return json.loads(done.stdout)


def differences(reference, other):
    """The names of the entries that differ: exactly in their discrete part, or in their floats
    by more than RTOL."""
    ref, got = reference["fingerprints"], other["fingerprints"]
    out = []
    for name in sorted(set(ref) | set(got)):
        a, b = ref.get(name), got.get(name)
        if a is None or b is None:
            out.append(f"{name}: only in {'the reference' if b is None else 'this run'}")
            continue
        if a["exact"] != b["exact"]:
            out.append(f"{name}: {a['exact']} -> {b['exact']}")
            continue
        (n1, s1, abs1), (n2, s2, abs2) = a["floats"], b["floats"]
        if n1 != n2 or abs(s1 - s2) > RTOL * max(abs1, abs2):
            out.append(f"{name}: floats {a['floats']} -> {b['floats']}")
    return out


@pytest.fixture(scope="module")
def reference():
    """The probe under numpy's default dispatch (NPY_DISABLE_CPU_FEATURES removed), OpenBLAS as
    inherited."""
    return run_probe({"NPY_DISABLE_CPU_FEATURES": None})


def dispatch_setting(reference, kind):
    """(environment changes, features disabled) for a dispatch setting, or a skip."""
    found = reference["runtime"]["dispatch_enabled"]     # lowest first, as numpy lists them
    if kind == "highest targets disabled":
        if len(found) < 2:
            pytest.skip(f"this CPU has fewer than two SIMD dispatch targets ({found}): the "
                        "'all disabled' setting covers it")
        off = found[1:]
    else:
        if not found:
            pytest.skip("numpy dispatches to no SIMD target above its baseline on this CPU")
        off = found
    return {"NPY_DISABLE_CPU_FEATURES": " ".join(off)}, off        # OpenBLAS as inherited


def blas_setting(reference, kind):
    """Environment changes that make OpenBLAS run other kernels than the reference's, or a skip."""
    core = reference["runtime"]["openblas_core"]
    if core is None or platform.machine().lower() not in ("x86_64", "amd64"):
        pytest.skip("numpy's BLAS is not an OpenBLAS whose kernels can be chosen here (x86)")
    if kind == "generic OpenBLAS kernels":
        candidates = [{"OPENBLAS_CORETYPE": GENERIC_CORE}]
    else:
        candidates = [{"OPENBLAS_CORETYPE": None}] if os.environ.get("OPENBLAS_CORETYPE") else []
        if reference["runtime"]["fma"]:
            candidates.append({"OPENBLAS_CORETYPE": FMA_CORE})
    for changes in candidates:                  # the first that really changes the kernels
        changes = {"NPY_DISABLE_CPU_FEATURES": None, **changes}
        if run_probe(changes, "--runtime")["runtime"]["openblas_core"] != core:
            return changes
    pytest.skip(f"no other OpenBLAS kernels to try on this CPU (it runs {core})")


SETTINGS = ["highest targets disabled", "all targets disabled", "generic OpenBLAS kernels",
            "other OpenBLAS kernels"]


@pytest.mark.parametrize("setting", SETTINGS)
def test_results_do_not_depend_on_simd_or_blas_kernels(reference, setting):
    if "targets" in setting:
        changes, off = dispatch_setting(reference, setting)
    else:
        changes, off = blas_setting(reference, setting), []
    other = run_probe(changes)
    # the setting took effect (else the comparison below proves nothing)
    enabled = reference["runtime"]["dispatch_enabled"]
    assert other["runtime"]["dispatch_enabled"] == [f for f in enabled if f not in off], changes
    if "OPENBLAS_CORETYPE" in changes:
        assert other["runtime"]["openblas_core"] != reference["runtime"]["openblas_core"], changes
    differ = differences(reference, other)
    assert not differ, (f"{len(differ)} results differ under {changes} "
                        f"(runtime {other['runtime']} vs {reference['runtime']}):\n"
                        + "\n".join(differ[:40]))


def test_the_probe_covers_the_order_sensitive_builds(reference):
    names = reference["fingerprints"]
    for prefix in ("visibility.BVH/", "raytracing.BVH/", "bsp/", "depth_sort/", "render_painter/",
                   "rank_occluders", "pvs/", "half_edge/", "winged_edge/", "qem/",
                   "marching_squares/", "marching_cubes/", "widget/camera/", "widget/zbuffer/",
                   "widget/simplification/", "exercises/", "mock_exam/", "notebook/ch05/",
                   "notebook/ch12/", "notebook/ch15/", "dataviz/delaunay/", "dataviz/pca/",
                   "simplification/clustering/", "simplification/decimation/",
                   "simplification/progressive/"):
        assert any(name.startswith(prefix) for name in names), prefix
    from course_lib.exercises import mock
    chapters = {name.split("/")[1] for name in names if name.startswith("exercises/")}
    assert chapters == {str(ch) for ch in mock._exercise_modules()}
    # the counts printed by notebooks/ch05 (the BVH cell) are there as numbers
    assert reference["fingerprints"]["notebook/ch05/bvh_triangle_tests"]["exact"] > 0


def test_fingerprints_see_every_order_and_forgive_only_rounding():

    order = np.array([3, 1, 2, 0])
    x = np.linspace(0.1, 1.0, 50)
    base = probe.fingerprint((order, x))
    assert probe.fingerprint((order[[1, 0, 2, 3]], x))[0] != base[0]       # an order
    assert probe.fingerprint((order, x[::-1]))[0] == base[0]               # floats: summary
    assert abs(probe.fingerprint((order, x[::-1]))[1][1] - base[1][1]) > 1e-3
    last_bit = np.nextafter(x, 2.0)
    assert probe.fingerprint((order, last_bit))[0] == base[0]
    assert abs(probe.fingerprint((order, last_bit))[1][1] - base[1][1]) <= RTOL * base[1][2]
    assert probe.fingerprint((order, np.r_[x[:-1], np.inf]))[0] != base[0]  # inf is discrete
    assert probe.fingerprint({2: "b", 1: "a"}) == probe.fingerprint({1: "a", 2: "b"})
