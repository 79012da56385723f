"""Headless tests of the distributed ray tracing explorer: its scene against the library and
against closed forms (the samples of the panel lie in their domain, the lobe's mean cosine is
(n + 1)/(n + 2), a zero-size light and aperture give Whitted's picture), and the wiring (every
control changes the picture; the image refines sample by sample)."""
import numpy as np
import pytest

from course_lib import raytracing as rt
from course_lib.widgets import distributed as W


def test_scene_is_the_progressive_render_and_converges():
    st = W.State(samples=3)
    s = W.scene(st)
    base = rt.example_scene("spheres", *W.SIZE)
    frames = list(rt.progressive(base, batch=1, batches=3, seed=0, **W._options(st)))
    assert np.array_equal(s["image"], frames[-1])
    reference = rt.render_distributed(base, samples=64, seed=9, **W._options(st))
    errors = [np.sqrt(np.mean((W.scene(st, samples=n)["image"] - reference) ** 2))
              for n in (1, 16)]
    assert errors[1] < errors[0] / 2


def test_without_effects_the_picture_is_whitted():
    st = W.State(samples=1, light_radius=0.0, gloss=np.inf, aperture=0.0, shutter=0.0)
    base = rt.example_scene("spheres", *W.SIZE)
    image = W.scene(st)["image"]
    whitted = rt.render(base, max_depth=2, supersampling=1)
    # antialiasing only moves the sample inside its pixel: most pixels agree closely
    assert np.mean(np.abs(image - whitted).max(axis=-1) < 0.05) > 0.8


def test_panel_samples_lie_in_their_domains():
    st = W.State(samples=16, light_radius=0.75, aperture=0.1, gloss=20.0, shutter=0.5)
    p, kind = W.domain_samples(W.State(**{**st.__dict__, "domain": "pixel"}))
    assert kind == "pixel"
    cells = sorted(map(tuple, np.floor((p + 1) / 2 * 4).astype(int).tolist()))
    assert cells == [(i, j) for i in range(4) for j in range(4)]
    p, _ = W.domain_samples(W.State(**{**st.__dict__, "domain": "light"}))
    assert np.hypot(*p.T).max() <= 0.75 / W.MAX_LIGHT + 1e-12
    p, _ = W.domain_samples(W.State(**{**st.__dict__, "domain": "lens"}))
    assert np.hypot(*p.T).max() <= 0.1 / W.MAX_APERTURE + 1e-12
    p, _ = W.domain_samples(W.State(**{**st.__dict__, "domain": "time"}))
    t = (p[:, 0] + 1) / 2
    assert t.min() >= 0 and t.max() <= 0.5
    # the lobe seen along its axis: cos = sqrt(1 - x^2 - y^2), mean (n + 1)/(n + 2)
    big = W.State(samples=4096, gloss=20.0, domain="reflection")
    p, _ = W.domain_samples(big)
    cos = np.sqrt(1 - np.sum(p ** 2, axis=1))
    assert cos.mean() == pytest.approx(21 / 22, abs=2e-3)


def test_bad_domain_and_samples():
    with pytest.raises(ValueError, match="domain"):
        W.domain_samples(W.State(domain="sky"))
    with pytest.raises(ValueError, match="samples"):
        W.scene(W.State(), samples=0)


def test_every_control_changes_the_picture():
    ex = W.DistributedExplorer(W.State(samples=2))
    assert ex.done == 2 and not ex.pending
    before = ex.png()
    moves = {"samples": (ex.samples, 6), "light": (ex.light, 1.2), "gloss": (ex.gloss, 5.0),
             "aperture": (ex.aperture, 0.3), "focus": (ex.focus, 3.5),
             "shutter": (ex.shutter, 1.0), "domain": (ex.domain, "lens")}
    for name, (control, value) in moves.items():
        old = control.value
        control.value = value
        ex.settle()
        assert ex.png() != before, name
        control.value = old
        ex.settle()
        assert ex.png() == before, name


def test_progressive_refinement():
    ex = W.DistributedExplorer(W.State(samples=4))
    ex.light.value = 1.0
    assert ex.done == 1 and ex.pending
    first = ex.current.copy()
    ex.settle()
    assert ex.done == 4 and not ex.pending
    assert not np.array_equal(first, ex.current)
    assert np.array_equal(ex.current, W.scene(ex.state)["image"])
    assert "4 of 4 samples" in ex.info.value
