"""Headless tests of the chapter 15 explorers against geometry computed here: the ray tree's hit
points lie on the surfaces, reflections keep the angle, refractions obey Snell's law, shadow
rays aim at the light and are blocked exactly when a sphere lies in the way (own quadratic);
the explorer's camera orbit, its shadows and its materials against own ray-sphere tests."""
import asyncio
import threading

import numpy as np
import pytest

from course_lib.widgets import ray_tree, raytracer
from widget_harness import click


def segment_hits_sphere(p, q, center, radius, margin=0.0):
    """Does the open segment p-q pass within `radius + margin` of `center`? (own quadratic)"""
    d = q - p
    f = p - center
    a, b, c = d @ d, 2 * f @ d, f @ f - (radius + margin) ** 2
    disc = b * b - 4 * a * c
    if disc < 0:
        return False
    r1, r2 = (-b - np.sqrt(disc)) / (2 * a), (-b + np.sqrt(disc)) / (2 * a)
    return r2 > 1e-6 and r1 < 1 - 1e-6


def unit(v):
    return v / np.linalg.norm(v)


PIXELS = [(kind, row, col) for kind in ray_tree.KINDS for row in (20, 47, 60, 75)
          for col in (30, 60, 80, 100, 131)]


def objects(kind):
    return ray_tree.example(kind).objects


# --- the ray tree ----------------------------------------------------------------------------

@pytest.mark.parametrize("kind, row, col", PIXELS)
def test_tree_geometry(kind, row, col):
    s = ray_tree.scene(ray_tree.State(kind=kind, row=row, column=col, max_depth=4))
    objs = objects(kind)
    light = ray_tree.example(kind).lights[0].position
    for node in s["nodes"]:
        if node.kind == "shadow" or node.hit is None:
            continue
        for shadow in (c for c in node.children if c.kind == "shadow"):
            # from (next to) the hit point towards the light
            assert np.allclose(shadow.direction, unit(light - node.hit), atol=1e-9)
            assert np.linalg.norm(shadow.origin - node.hit) < 1e-3
            blockers = [o for o in objs if hasattr(o, "radius")
                        and segment_hits_sphere(shadow.origin, light, o.center, o.radius)]
            if not blockers:
                assert shadow.visibility == 1.0
            elif all(o.material.transparency == 0 for o in blockers):
                assert shadow.visibility == 0.0
        obj = objs[node.object]
        if hasattr(obj, "radius"):                 # on the sphere's surface
            assert abs(np.linalg.norm(node.hit - obj.center) - obj.radius) < 1e-9
            outward = unit(node.hit - obj.center)
        else:                                      # on the plane
            assert abs((node.hit - obj.point) @ obj.normal) < 1e-9
            outward = obj.normal
        assert np.allclose(node.hit, node.origin + node.t * node.direction, atol=1e-9)
        n = outward if outward @ node.direction < 0 else -outward       # facing the ray
        assert np.allclose(node.normal, n, atol=1e-9)
        for child in node.children:
            c = child.direction
            if child.kind == "reflected":          # equal angles, in the plane of d and n
                assert np.isclose(c @ n, -(node.direction @ n), atol=1e-9)
                assert abs(np.linalg.det([node.direction, n, c])) < 1e-9
            elif child.kind == "refracted":        # Snell's law, in the plane of incidence
                entering = outward @ node.direction < 0
                eta1, eta2 = (1.0, obj.material.ior) if entering else (obj.material.ior, 1.0)
                sin1 = np.linalg.norm(np.cross(node.direction, n))
                sin2 = np.linalg.norm(np.cross(c, n))
                assert np.isclose(eta1 * sin1, eta2 * sin2, atol=1e-9)
                assert c @ n < 0                   # it goes through the surface
                assert abs(np.linalg.det([node.direction, n, c])) < 1e-9
        if obj.material.transparency > 0 and node.depth < 4:
            kinds = [child.kind for child in node.children]
            entering = outward @ node.direction < 0
            eta = (1.0 / obj.material.ior) if entering else obj.material.ior
            sin1 = np.linalg.norm(np.cross(node.direction, n))
            assert ("refracted" in kinds) == (eta * sin1 < 1)   # total internal reflection


@pytest.mark.parametrize("kind, row, col", PIXELS[::3])
def test_drawn_segments_and_pixel(kind, row, col):
    ex = ray_tree.RayTreeExplorer(ray_tree.State(kind=kind))
    ex.kind.value = kind
    ex.row.value = row
    ex.column.value = col
    objs = objects(kind)
    s = ex.current
    limits = ray_tree.LIMITS[kind]
    # the drawn primary ray starts at the eye; every drawn hit point lies on some surface
    primary = np.asarray(ex.lines["primary"]._segments3d)
    assert np.allclose(primary[0, 0], ray_tree.example(kind).camera.eye)
    xs, ys, zs = ex.hit_points.get_data_3d()
    for p in np.column_stack([xs, ys, zs]):
        gaps = [abs(np.linalg.norm(p - o.center) - o.radius) if hasattr(o, "radius")
                else abs((p - o.point) @ o.normal) for o in objs]
        assert min(gaps) < 1e-9
        assert all(lo - 1e-9 <= x <= hi + 1e-9 for x, (lo, hi) in zip(p, limits))
    # the segments end on hit points or on the box
    for kind_ in ("primary", "reflected", "refracted"):
        for a, b in np.asarray(ex.lines[kind_]._segments3d).reshape(-1, 2, 3):
            on_hit = len(xs) and np.min(np.linalg.norm(np.column_stack([xs, ys, zs]) - b,
                                                       axis=1)) < 1e-9
            on_box = any(np.isclose(b[k], v) for k in range(3) for v in limits[k])
            assert on_hit or on_box or np.isclose(np.linalg.norm(b - a), ray_tree.MISS_LENGTH)
    # the contributions in the table sum to the pixel of the rendered picture
    total = sum(r["contribution"] for r in s["rows"])
    weights_times_local = sum(r["weight"] * r["local"] for r in s["rows"])
    assert np.allclose(total, weights_times_local)
    assert np.allclose(np.clip(total, 0, 1), s["image"][row, col], atol=1e-9)
    assert np.allclose(ex.marker.get_data(), ([col + 0.5], [row + 0.5]))


def test_tree_counts_and_weights():
    # a primary ray through the centre of the glass sphere of the "glass" scene, depth 1:
    # root, reflected, refracted and the root's shadow ray
    ex = ray_tree.RayTreeExplorer(ray_tree.State(kind="glass", max_depth=1))
    scn = ray_tree.example("glass")
    cam = scn.camera
    glass = scn.objects[2]
    s = ex.current
    counts = s["counts"]
    assert counts["primary"] == 1
    assert counts["reflected"] + counts["refracted"] <= 2
    # depth 0: no secondary rays at all, for every pixel
    ex.depth.value = 0
    assert ex.current["counts"]["reflected"] == ex.current["counts"]["refracted"] == 0
    assert ex.current["segments"]["reflected"].shape == (0, 2, 3)
    # the weights of a glass hit's children are k_t F and k_t (1 - F): they sum to k_t
    ex.depth.value = 2
    row, col = cam.height // 2, cam.width // 2
    ex.row.value, ex.column.value = row, col
    root = ex.current["tree"]
    assert root.object == 2
    kids = {c.kind: c.weight for c in root.children if c.kind != "shadow"}
    assert np.isclose(kids["reflected"] + kids["refracted"], glass.material.transparency)
    # Schlick at this angle, computed here
    cos1 = -root.direction @ root.normal
    r0 = ((1 - glass.material.ior) / (1 + glass.material.ior)) ** 2
    f = r0 + (1 - r0) * (1 - cos1) ** 5
    assert np.isclose(kids["reflected"], glass.material.transparency * f)


def test_click_picks_the_pixel():
    ex = ray_tree.RayTreeExplorer()
    ex.fig.canvas.draw()
    click(ex.ax_image, (20.5, 33.5))
    assert (ex.row.value, ex.column.value) == (33, 20)
    assert (ex.state.row, ex.state.column) == (33, 20)
    o, d = ray_tree.example("spheres").camera.pixel_ray(33, 20)
    assert np.allclose(ex.current["tree"].direction, d)
    ex.kind.value = "mirrors"
    assert "Pixel (row 33" in ex.info.value and "<table" in ex.table.value


def test_tree_bad_kind():
    with pytest.raises(ValueError, match="kind"):
        ray_tree.scene(ray_tree.State(kind="cubes"))


# --- the ray tracer explorer -----------------------------------------------------------------

def own_first_hit(o, d, objs):
    """Nearest object index hit by the ray o + t d among spheres and planes (own maths)."""
    best, which = np.inf, -1
    for k, obj in enumerate(objs):
        if hasattr(obj, "radius"):
            f = o - obj.center
            b, c = f @ d, f @ f - obj.radius**2
            disc = b * b - c
            if disc < 0:
                continue
            t = -b - np.sqrt(disc)
        else:
            denom = d @ obj.normal
            if denom == 0:
                continue
            t = ((obj.point - o) @ obj.normal) / denom
        if 1e-9 < t < best:
            best, which = t, k
    return which, best


def test_camera_orbit():
    ex = raytracer.RayTracerExplorer()
    ex.azimuth.value = 90.0
    ex.elevation.value = 30.0
    ex.distance.value = 8.0
    cam = ex.current["camera"]
    a, e = np.radians(90), np.radians(30)
    expected = raytracer.TARGET + 8 * np.array([np.cos(e) * np.sin(a), np.sin(e),
                                                np.cos(e) * np.cos(a)])
    assert np.allclose(cam.eye, expected)
    _, d = cam.pixel_ray(cam.height // 2, cam.width // 2)     # (almost) the view's centre
    assert np.linalg.norm(np.cross(d, unit(raytracer.TARGET - expected))) < 0.05


def test_preview_then_full_image():
    ex = raytracer.RayTracerExplorer()
    assert ex.current["image"].shape == (raytracer.FULL[1], raytracer.FULL[0], 3)
    first = ex.png()
    ex.mirror.value = 0.3
    assert ex.pending and ex.current["preview"]
    assert ex.current["image"].shape == (raytracer.PREVIEW[1], raytracer.PREVIEW[0], 3)
    assert ex.png() != first
    ex.full_button.click()
    assert not ex.pending
    assert ex.current["image"].shape == (raytracer.FULL[1], raytracer.FULL[0], 3)
    assert ex.state.mirror_reflectivity == 0.3
    from PIL import Image
    import io
    from skimage.transform import resize
    shown = np.asarray(Image.open(io.BytesIO(ex.png()))).astype(float)
    assert shown.shape == (raytracer.DISPLAY[1], raytracer.DISPLAY[0], 3)
    assert np.array_equal(shown, ex.frame())                # png() is what the canvas shows
    # the full image enlarged x 1.5 (skimage's bilinear resize, pixel centres as PIL's)
    full = np.flipud(ex.current["image"]) * 255
    expected = resize(full, shown.shape, order=1, mode="edge", anti_aliasing=False)
    assert np.abs(shown - expected).max() <= 1.5
    # a preview is shown with big square pixels: each of its pixels a 6 x 6 block
    ex.mirror.value = 0.35
    assert ex.pending and ex.current["preview"]
    blocks = ex.frame().reshape(60, 6, 80, 6, 3).astype(float)
    assert np.all(blocks == blocks[:, :1, :, :1])
    assert np.array_equal(blocks[:, 0, :, 0], np.round(np.flipud(ex.current["image"]) * 255))
    ex.mirror.value = 0.3                         # back to the full image's values: at once
    assert not ex.pending and not ex.current["preview"]
    assert np.array_equal(ex.frame(), shown)


def test_the_full_image_comes_in_bands_and_an_input_between_two_abandons_it(monkeypatch):
    """On an event loop, as in a live kernel: the full image is traced band by band once the
    sliders rest. A slider moved while a band is being traced (a kernel queues the student's
    message on the loop, as here) is answered before the next band: its preview is shown at
    once, the half-made image is dropped (never shown, no band of it traced after) and the new
    state's full image follows, the same as the whole-image render of that state."""
    bands = 240 // 60
    real = raytracer.scene_bands
    loop = asyncio.new_event_loop()
    shown, traced_then, made = [], [], {}

    def move_mirror():                      # the student's input, handled on the loop
        traced_then.append(made["explorer"].bands_traced)
        made["explorer"].mirror.value = 0.3

    def bands_with_an_input(state, rows):
        for k, s in enumerate(real(state, rows)):
            if k == 1 and not traced_then:  # arrives while the first full image's band 2 is
                loop.call_soon_threadsafe(move_mirror)      # traced (from the kernel's shell)
            yield s

    async def student():
        ex = made["explorer"] = raytracer.RayTracerExplorer(settle_seconds=0.01, band_rows=60)
        show = ex.show_frame

        def recorded(pixels, **how):         # each picture put on the canvas
            shown.append((ex.current["preview"], ex.state.max_depth,
                          ex.state.mirror_reflectivity))
            show(pixels, **how)

        ex.show_frame = recorded
        ex.depth.value = 1
        for _ in range(20000):
            await asyncio.sleep(0.001 if ex.pending else 0)
            if not ex.pending:
                return ex
        raise AssertionError(f"no full image after 20000 turns of the loop ({shown})")

    monkeypatch.setattr(raytracer, "scene_bands", bands_with_an_input)
    out = {}

    def run():                      # a loop of its own, on a thread of its own
        try:
            out["explorer"] = loop.run_until_complete(student())
        except BaseException as error:          # re-raised on the test's thread below
            out["error"] = error
        finally:
            loop.close()

    thread = threading.Thread(target=run)
    thread.start()
    thread.join(120)
    assert not thread.is_alive(), "the event loop did not finish within 120 s"
    if "error" in out:
        raise out["error"]
    explorer = out["explorer"]
    assert traced_then == [2], "the input was handled before or after the band it came in"
    # the depth-1 image was abandoned after 2 bands; the mirror's image took all of its own
    assert explorer.bands_traced == 2 + bands
    assert shown == [(True, 1, 0.85), (True, 1, 0.3), (False, 1, 0.3)]
    whole = raytracer.scene(raytracer.State(max_depth=1, mirror_reflectivity=0.3))
    assert np.allclose(explorer.current["image"], whole["image"])
    assert explorer.current["counts"] == whole["counts"]
    assert explorer.current["text"] == whole["text"]


def test_shadows_against_own_geometry():
    ex = raytracer.RayTracerExplorer()
    ex.floor.value = 0.0
    ex.depth.value = 0
    on = ex.current["image"]
    ex.shadows.value = False
    off = ex.current["image"]
    scn = raytracer.build_scene(ex.state)
    light = scn.lights[0].position
    cam = ex.current["camera"]
    shadowed = lit = 0
    for row in range(cam.height):
        for col in range(cam.width):
            o, d = cam.pixel_ray(row, col)
            k, t = own_first_hit(o, d, scn.objects)
            if k != 0:
                continue                                     # not the floor
            p = o + t * d
            near = [segment_hits_sphere(p, light, s.center, s.radius, m)
                    for s in scn.objects[1:] for m in (-0.03, 0.03)]
            if not any(near):                                # clearly lit
                assert np.allclose(on[row, col], off[row, col])
                lit += 1
            elif (near[0] or near[2]) and not near[5]:          # clearly behind red / mirror
                floor = scn.objects[0]
                ka_colours = [0.1 * np.array([0.9, 0.9, 0.85]), 0.1 * np.array([0.12, 0.12, 0.15])]
                assert any(np.allclose(on[row, col], c, atol=1e-9) for c in ka_colours), floor
                assert off[row, col].sum() > on[row, col].sum() + 0.1
                shadowed += 1
    assert shadowed > 20 and lit > 200


def test_mirror_reflectivity_changes_only_mirror_pixels():
    state = raytracer.State(floor_reflectivity=0.0, glass_transparency=0.0, max_depth=2)
    dull = raytracer.scene(raytracer.State(**{**state.__dict__, "mirror_reflectivity": 0.0}),
                           preview=True)["image"]
    shiny = raytracer.scene(state, preview=True)["image"]
    scn = raytracer.build_scene(state)
    cam = raytracer.make_camera(state, *raytracer.PREVIEW)
    changed = np.any(np.abs(shiny - dull) > 1e-12, axis=-1)
    mirror = scn.objects[2]
    for row, col in zip(*np.nonzero(changed)):
        o, d = cam.pixel_ray(row, col)
        k, _ = own_first_hit(o, d, scn.objects)
        assert k == 2 or segment_hits_sphere(o, o + 20 * d, mirror.center, mirror.radius, 0.05)
    assert changed.sum() > 50


def test_material_and_depth_sliders_reach_the_scene():
    ex = raytracer.RayTracerExplorer()
    ex.ior.value = 1.33
    ex.glass.value = 0.5
    ex.depth.value = 5
    scn = raytracer.build_scene(ex.state)
    assert scn.objects[3].material.ior == 1.33
    assert scn.objects[3].material.transparency == 0.5
    assert ex.current["counts"].primary == raytracer.PREVIEW[0] * raytracer.PREVIEW[1]
    ex.depth.value = 0
    assert ex.current["counts"].reflected == ex.current["counts"].refracted == 0
    assert "Depth 0" in ex.info.value
