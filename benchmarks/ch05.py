"""Chapter 5: line and polygon clipping against shapely (GEOS), and the chapter's widgets."""
import numpy as np

from benchmarks import operation_row


def _segments(rng, n):
    """n random 2D segments around the unit box: end points in [-1, 2]^2 (about 3/4 visible)."""
    return rng.uniform(-1, 2, (n, 2)), rng.uniform(-1, 2, (n, 2))


def _polygons(rng, n, k=20):
    """n star-shaped polygons of k vertices, centred around the unit box, some crossing it."""
    centres = rng.uniform(-0.5, 1.5, (n, 1, 2))
    angles = np.sort(rng.uniform(0, 2 * np.pi, (n, k)), axis=1)
    radii = rng.uniform(0.2, 1.0, (n, k))
    return centres + np.stack([radii * np.cos(angles), radii * np.sin(angles)], axis=-1)


def operations(quick=False):
    import shapely

    from course_lib import clipping

    n = 2_000 if quick else 100_000
    n_poly = 50 if quick else 1_000
    repeat = 3 if quick else 15
    rng = np.random.default_rng(2026)
    lo, hi = np.zeros(2), np.ones(2)
    p0, p1 = _segments(rng, n)
    lines = shapely.linestrings(np.stack([p0, p1], axis=1))      # built once, not timed
    polys = _polygons(rng, n_poly)
    shapes = shapely.polygons(polys)
    ref = "shapely clip_by_rect"
    rows = [
        operation_row("clip 2D segments: Liang-Barsky, vectorized", n,
                      lambda: clipping.liang_barsky_many(p0, p1, lo, hi),
                      lambda: shapely.clip_by_rect(lines, 0.0, 0.0, 1.0, 1.0), ref, repeat),
        operation_row("clip 2D segments: Cohen-Sutherland, vectorized", n,
                      lambda: clipping.cohen_sutherland_many(p0, p1, lo, hi),
                      lambda: shapely.clip_by_rect(lines, 0.0, 0.0, 1.0, 1.0), ref, repeat),
        operation_row("clip 20-vertex polygons: Sutherland-Hodgman, loop", n_poly,
                      lambda: [clipping.sutherland_hodgman(p, lo, hi) for p in polys],
                      lambda: shapely.clip_by_rect(shapes, 0.0, 0.0, 1.0, 1.0), ref, repeat),
    ]
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch05_clip3d, ch05_hierarchical, ch05_bsp

    return (ch05_clip3d, ch05_hierarchical, ch05_bsp,)


def widgets(quick=False):
    """Median update of each clipping explorer while the student drags or steps."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import (clipping3d, cohen_sutherland, hidden_surface, liang_barsky,
                                    sutherland_hodgman, zbuffer)

    repeat = 5 if quick else 40
    rows = []

    def dragging(explorer, index):
        """Drag point `index` of the explorer along a small circle."""
        start = explorer.drag.points[index].copy()
        explorer.drag.press(*start)

        def move(i):
            angle = 0.3 * i
            explorer.drag.move(start[0] + 0.4 * np.cos(angle), start[1] + 0.4 * np.sin(angle))
        return move

    for name, cls in (("Cohen-Sutherland explorer (drag an end point)",
                       cohen_sutherland.CohenSutherlandExplorer),
                      ("Liang-Barsky explorer (drag an end point)",
                       liang_barsky.LiangBarskyExplorer),
                      ("Sutherland-Hodgman explorer (drag a vertex)",
                       sutherland_hodgman.SutherlandHodgmanExplorer)):
        explorer = cls()
        explorer.fig.canvas.draw()
        rows.append(widget_row(name, dragging(explorer, 1), explorer.fig.canvas.draw, repeat))
        plt.close(explorer.fig)
    for name, explorer, move in (
            ("3D clipping explorer (turn slider)", clipping3d.ClippingExplorer3D(),
             lambda ex, i: setattr(ex.turn, "value", -90 + (7 * i) % 180)),
            ("z-buffer trace (step slider)", zbuffer.ZBufferExplorer(),
             lambda ex, i: setattr(ex.step, "value", i % 5)),
            ("back faces and depth buffer (camera slider)",
             hidden_surface.HiddenSurfaceExplorer(),
             lambda ex, i: setattr(ex.azimuth, "value", -90 + (7 * i) % 180))):
        explorer.fig.canvas.draw()
        rows.append(widget_row(name, lambda i, ex=explorer, move=move: move(ex, i),
                               explorer.fig.canvas.draw, repeat))
        plt.close(explorer.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
