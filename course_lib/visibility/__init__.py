r"""Chapter 5: hidden-surface elimination and occlusion culling.

Culling throws away work that cannot change the picture; hidden-surface elimination (HSE) decides,
for what is left, which surface each pixel shows. This module implements the chapter's
algorithms on small, inspectable data, so that a notebook can draw every intermediate step.

**Hidden-surface elimination** (all three give the same picture, up to pixels whose centre lies
exactly on an edge):

* :func:`zbuffer` / :func:`render_depth`: the **z-buffer** (image precision). Rasterize the
  triangles in any order; a pixel keeps the fragment with the smallest depth seen so far.
  :func:`zbuffer_steps` replays it one triangle at a time.
* :func:`ray_cast` / :func:`ray_cast_image`: **ray casting**. One ray per pixel, each tested
  against the primitives; the nearest hit wins. :class:`BVH` is a bounding-volume hierarchy
  that skips most of those tests.
* :func:`build_bsp`, :func:`bsp_back_to_front`, :func:`painter_image`: the **painter's
  algorithm** (object precision ordering, then overwrite without a depth buffer), with the
  order from a **binary space partitioning (BSP) tree**; :func:`depth_sort` is the naive order
  that sorts by depth and :func:`painter_counterexample` shows where it breaks.

**Occlusion culling** (discard whole objects that are certainly hidden, before any of the above):

* from a point: :func:`shadow_frustum`, :func:`occlusion_cull`, :func:`occluder_solid_angle`,
  :func:`rank_occluders`;
* from a region: a 2D floor plan of cells and portals (:class:`FloorPlan`,
  :func:`example_floor_plan`), the stabbing-line test :func:`stabbing_line`, the potentially
  visible set :func:`pvs`, and :func:`visible_from_point` for one viewer.

Conventions
-----------
Screen triangles are in **viewport coordinates**, as :func:`course_lib.viewing.viewport` makes
them: pixel x to the right, pixel y **up**, depth z in [0, 1] growing away from the viewer
(near plane 0, far plane 1). Pixel ``(row j, column i)`` covers the square
:math:`[i, i+1] \times [j, j+1]` and is sampled at its centre :math:`(i + \tfrac12, j +
\tfrac12)`. **Row 0 is the bottom row**, so images are shown with
``plt.imshow(ids, origin="lower", extent=(0, width, 0, height))`` (without ``origin="lower"``
the picture is upside down). The depth buffer starts at ``+inf`` ("nothing drawn"), the id
buffer at -1 (background).

Efficiency issues
-----------------
Write :math:`P` for the number of primitives (triangles) and :math:`p` for the number of pixels.

* **Ray casting** tests every ray against every primitive: :math:`p \cdot P` ray-triangle tests,
  whatever the scene looks like. It parallelizes trivially (every ray is independent), but for a
  300 x 300 image of a 20,000-triangle model that is 1.8 billion tests. Bounding volumes are the
  cure: wrap groups of primitives in boxes, nest the boxes into a hierarchy, and skip a whole
  group when its box is missed or lies behind a hit already found. A ray then meets about
  :math:`O(\log P)` boxes and only a handful of triangles; the hierarchy costs
  :math:`O(P \log P)` to build, once, for a static scene. :func:`ray_cast` counts the tests so
  the difference can be seen, not just timed.
* **The z-buffer** visits each primitive once, :math:`O(P)`, and spends time proportional to the
  pixels it covers: the total is :math:`O(P + p \cdot d)` with :math:`d` the *depth complexity*
  (how many surfaces cover a pixel, on average). It needs :math:`O(p)` extra memory, one depth
  per pixel, and no sorting; order does not matter for correctness, only for how often a pixel
  is overwritten (front-to-back order wastes the fewest writes). Hardware does exactly this.
  Its weak points: limited depth precision (depth after the perspective divide is crowded near
  the far plane), and every hidden fragment is still rasterized.
* **The painter's algorithm** needs no depth memory but a correct back-to-front order. Sorting by
  depth costs :math:`O(P \log P)` per frame and is simply wrong for interpenetrating or
  cyclically overlapping polygons. A BSP tree gives a correct order for *every* viewpoint:
  it is built once, :math:`O(P \log P)` for good splits and up to :math:`O(P^2)` fragments for
  bad ones (splitting is why the choice of partition plane matters), and each frame costs one
  :math:`O(P')` traversal over the :math:`P'` fragments, with a single dot product per node.
  Every fragment is drawn, hidden or not: maximum overdraw.
* **Occlusion culling** shrinks :math:`P` before any of these run. From a point, each frame
  tests the :math:`n` objects' bounding volumes against the shadow frusta of :math:`k` chosen
  occluders: :math:`O(n k)` cheap plane tests, worth it when the culled objects are expensive
  (many triangles each). Few, large occluders give most of the benefit, hence
  :func:`rank_occluders`. From a region, the expensive part (the potentially visible set of each
  cell, by following stabbable portal sequences) is computed once offline; at run time the
  renderer looks up one row of a cells x cells boolean matrix, :math:`O(1)` per cell, at the
  price of :math:`O(\text{cells}^2)` bits of storage. Both are *conservative*: they may draw
  something hidden, never drop something visible; the z-buffer then finishes the job exactly.

Files
-----

``z_buffer.py``
    Chapter 5, hidden-surface elimination (lesson section 5): scan conversion and the z-buffer.
``ray_casting.py``
    Chapter 5, hidden-surface elimination (lesson section 5): ray casting, brute force and with
    a BVH (the rays, Möller-Trumbore, brute force and :class:`BVH` itself are in
    :mod:`course_lib._raycore`, shared with :mod:`course_lib.raytracing`).
``painter.py``
    Chapter 5, hidden-surface elimination (lesson section 5): the painter's algorithm, depth
    sort, BSP trees.
``occlusion.py``
    Chapter 5, occlusion culling from a point (lesson section 4.1): occluders and their
    shadows.
``portals.py``
    Chapter 5, occlusion culling from a region (lesson section 4.2): cells, portals, PVS.
``_common.py``
    the shared input checks (built on :mod:`course_lib._validate`)
"""

from .z_buffer import (ZBuffer, ZBufferStep, render_depth, triangle_coverage, zbuffer,
    zbuffer_steps)
from .ray_casting import (BVH, Hits, RayCastImage, ray_cast, ray_cast_image, ray_triangle)
from .painter import (BSPNode, BSPTree, Painted, Scene, build_bsp, bsp_back_to_front, depth_sort,
    painter_counterexample, painter_image, random_scene, render_painter, split_polygon)
from .occlusion import (occluder_solid_angle, occlusion_cull, rank_occluders, shadow_frustum)
from .portals import (FloorPlan, PointVisibility, cell_of, example_floor_plan, floor_plan, pvs,
    stabbing_line, visible_from_point, walls)
from .painter import TriangleScene        # Scene: its old name, the same class

__all__ = [
    "BSPNode",
    "BSPTree",
    "BVH",
    "FloorPlan",
    "Hits",
    "Painted",
    "PointVisibility",
    "RayCastImage",
    "TriangleScene",
    "ZBuffer",
    "ZBufferStep",
    "build_bsp",
    "bsp_back_to_front",
    "cell_of",
    "depth_sort",
    "example_floor_plan",
    "floor_plan",
    "occluder_solid_angle",
    "occlusion_cull",
    "painter_counterexample",
    "painter_image",
    "pvs",
    "random_scene",
    "rank_occluders",
    "ray_cast",
    "ray_cast_image",
    "ray_triangle",
    "render_depth",
    "render_painter",
    "shadow_frustum",
    "split_polygon",
    "stabbing_line",
    "triangle_coverage",
    "visible_from_point",
    "walls",
    "zbuffer",
    "zbuffer_steps",
]

# Issue 21: hierarchical occlusion (z-pyramid, occlusion queries, occlusion maps) and a 2D BSP
# tree of segments for practice by hand (each module declares its __all__)
from . import bsp2d, hierarchical  # noqa: E402
from .hierarchical import *  # noqa: E402,F401,F403
from .bsp2d import *  # noqa: E402,F401,F403

__all__ = sorted(__all__ + hierarchical.__all__ + bsp2d.__all__)
