"""Chapter 15, distributed ray tracing: a small scene at 16 samples per pixel with every effect
(disk light, glossy reflection, thin lens, motion blur) against Whitted's render of the same
scene (one ray per pixel): the cost ratio is about the sample count, since each sample is one
path; and the distributed explorer's update (one sample per pixel at once, the rest while the
controls rest)."""
from benchmarks import operation_row


def operations(quick=False):
    """render_distributed at 16 spp vs raytracing.render at 1 spp (same scene and camera), and
    the soft-shadow estimate of 1,000 points with 64 shadow rays each vs 64,000 plain shadow
    rays through intersect_scene."""
    import numpy as np

    from course_lib import raytracing as rt

    w, h = (48, 36) if quick else (96, 72)
    scene = rt.example_scene("spheres", w, h)
    options = dict(light_radius=0.6, gloss=60.0, aperture=0.08, focal_distance=6.0,
                   shutter=0.5, motion={1: [1.2, 0.0, 0.0]})
    rows = [operation_row(f"distributed ray tracing {w}x{h}, 16 samples/pixel, all effects",
                          w * h, lambda: rt.render_distributed(scene, samples=16, **options),
                          lambda: rt.render(scene), "Whitted render, 1 ray/pixel",
                          2 if quick else 5)]
    n = 200 if quick else 1000
    rng = np.random.default_rng(0)
    points = np.column_stack([rng.uniform(-3, 3, n), np.zeros(n), rng.uniform(-3, 2, n)])
    light = scene.lights[0].position
    origins = np.repeat(points, 64, axis=0)
    directions = light - origins
    rows.append(operation_row(f"soft shadow of {n:,} points, 64 shadow rays each", n,
                              lambda: rt.soft_shadow(scene, points, light_radius=0.6,
                                                     samples=64),
                              lambda: rt.intersect_scene(scene, origins, directions, 1e-4),
                              "the same number of rays through intersect_scene",
                              2 if quick else 5))
    return rows


def widgets(quick=False):
    """Median update of the distributed explorer (the first sample per pixel at 80x60, a PNG of
    the picture and the panel); full = all 8 samples of the default state."""
    from benchmarks import widget_row
    from course_lib.widgets import distributed

    repeat = 5 if quick else 30
    explorer = distributed.DistributedExplorer()

    def full():                                  # restart and add every sample
        explorer.update()
        explorer.settle()

    return [widget_row("distributed explorer: first sample per pixel (80x60, depth 2); "
                       "full = the remaining samples",
                       lambda i: setattr(explorer.aperture, "value", 0.02 + 0.01 * (i % 30)),
                       full, repeat, target_ms=100.0)]
