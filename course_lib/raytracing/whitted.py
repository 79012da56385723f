"""Chapter 15 (lesson sections 15.3, 15.5): Whitted's recursive ray tracer and its ray tree."""

from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from .._validate import as_positive, as_scalar, as_vector, as_whole
from ._common import DEFAULT_EPSILON, _nonzero_vectors
from .camera import Camera
from .hits import _Compiled, _generation

__all__ = ["RayCounts", "RayNode", "render", "render_bands", "trace_tree"]


# ---------------------------------------------------------------------------------------------
# Whitted ray tracing
# ---------------------------------------------------------------------------------------------

class RayCounts(NamedTuple):
    """How many rays of each kind :func:`render` traced.

    Attributes
    ----------
    primary : int
        Camera rays (pixels x samples per pixel).
    shadow : int
        Shadow rays (one per hit and light in front of the surface).
    reflected, refracted : int
        Secondary rays, over all generations.

    Examples
    --------
    >>> RayCounts(100, 80, 10, 5).total
    195
    """
    primary: int
    shadow: int
    reflected: int
    refracted: int

    @property
    def total(self):
        return self.primary + self.shadow + self.reflected + self.refracted


def _render_options(max_depth, epsilon, min_weight):
    depth = as_whole(max_depth, "max_depth", 0)
    eps = as_positive(epsilon, "epsilon", "the offset of secondary rays")
    mw = as_scalar(min_weight, "min_weight")
    if not 0 <= mw < 1:
        raise ValueError(f"min_weight must lie in [0, 1), got {mw}")
    return depth, eps, mw


def render(scene, camera=None, max_depth=3, shadows=True, supersampling=1, seed=None,
           jitter=False, epsilon=DEFAULT_EPSILON, min_weight=0.0, return_counts=False):
    r"""Whitted ray tracing of a scene: an image of shape (height, width, 3) in [0, 1].

    For every pixel sample a primary ray is shot (:func:`camera_rays`); at its nearest hit the
    colour is

    .. math:: I = I_{local} + (k_r + k_t F)\, I(\text{reflected}) + k_t (1 - F)\,
              I(\text{refracted})

    with :math:`I_{local}` the Phong model at the hit (:func:`course_lib.shading.phong`, both
    sides of a surface lit), each light's diffuse and specular terms multiplied by the answer of
    its shadow ray (1 lit, 0 blocked, the product of the transparencies :math:`k_t` of the
    objects crossed otherwise), :math:`F` Schlick's Fresnel factor (:func:`schlick`; 0 for
    opaque materials) and the recursion stopped after `max_depth` bounces. A ray that hits
    nothing sees the scene's background.

    **Vectorized by generations** instead of recursion: all primary rays are traced at once;
    the reflected and refracted rays of all their hits form the next generation, each carrying
    its pixel and its weight (the product of the factors on its path), and so on. Each
    generation adds ``weight * local colour`` to its pixels. This computes exactly the
    recursive sum of the ray tree (:func:`trace_tree`), breadth first.

    The pixel value is the mean of its samples, **clamped** to [0, 1] per channel (no tone
    mapping).

    Parameters
    ----------
    scene : Scene
    camera : Camera, optional
        Default: the scene's camera.
    max_depth : int, optional
        Bounces after the primary ray (0: no reflected or refracted rays).
    shadows : bool, optional
        Shoot shadow rays (False: every light is seen from everywhere).
    supersampling : int, optional
        Samples per pixel, a perfect square (1, 4, 9, ...): see :func:`camera_rays`.
    seed, jitter
        Jittered supersampling, see :func:`camera_rays`.
    epsilon : float, optional
        Offset of secondary rays from the surface along its normal (against shadow acne).
    min_weight : float, optional
        Rays whose weight falls below this are not traced (adaptive depth control; default 0:
        only `max_depth` stops the recursion).
    return_counts : bool, optional
        Also return the :class:`RayCounts`.

    Returns
    -------
    image : ndarray, shape (height, width, 3)
        RGB in [0, 1]; **row 0 is the bottom** (``plt.imshow(image, origin="lower")``).
    counts : RayCounts
        Only with `return_counts`.

    Raises
    ------
    ValueError
        For a negative `max_depth`, a non-positive `epsilon`, a bad sample count, or no camera.
    TypeError
        If `scene` is not a Scene or `camera` not a Camera.

    Examples
    --------
    >>> from course_lib.raytracing import example_scene
    >>> scene = example_scene("spheres")
    >>> image, counts = render(scene, scene.camera.resized(32, 24), return_counts=True)
    >>> image.shape, counts.primary, bool(0 <= image.min() and image.max() <= 1)
    ((24, 32, 3), 768, True)
    """
    c, rays, options = _prepare(scene, camera, max_depth, supersampling, seed, jitter, epsilon,
                                min_weight, shadows)
    image, counts = _trace_rows(c, rays.origins, rays.directions, *options)
    return (image, RayCounts(**counts)) if return_counts else image


def render_bands(scene, camera=None, rows=16, max_depth=3, shadows=True, supersampling=1,
                 seed=None, jitter=False, epsilon=DEFAULT_EPSILON, min_weight=0.0):
    r"""Whitted ray tracing a band of image rows at a time: yields the image so far.

    The same rays and the same sum as :func:`render`, traced `rows` image rows at a time (every
    ray of a pixel is independent of every other pixel's, so splitting the image into bands
    changes nothing). Each step yields ``(image, counts, done)``: the image with the rows
    traced so far (the others black), the :class:`RayCounts` so far and how many rows are done;
    the last step's image is the finished picture. An interactive program can show something
    after each band, or (as :class:`course_lib.widgets.raytracer.RayTracerExplorer` does) answer
    the student's next input between two bands and abandon the rest.

    Parameters
    ----------
    scene, camera, max_depth, shadows, supersampling, seed, jitter, epsilon, min_weight
        As for :func:`render`.
    rows : int, optional
        Image rows per step (>= 1; the last band may be shorter).

    Yields
    ------
    image : ndarray, shape (height, width, 3)
        Row 0 is the bottom, as :func:`render`'s; rows not yet traced are 0.
    counts : RayCounts
        The rays traced so far.
    done : int
        Rows traced so far (from the bottom).

    Examples
    --------
    >>> from course_lib.raytracing import example_scene
    >>> scene = example_scene("spheres")
    >>> steps = list(render_bands(scene, scene.camera.resized(32, 24), rows=10))
    >>> [done for _, _, done in steps]
    [10, 20, 24]
    >>> bool(np.allclose(steps[-1][0], render(scene, scene.camera.resized(32, 24))))
    True
    """
    step = as_whole(rows, "rows", 1)
    c, rays, options = _prepare(scene, camera, max_depth, supersampling, seed, jitter, epsilon,
                                min_weight, shadows)
    h, w = rays.directions.shape[:2]
    image = np.zeros((h, w, 3))
    counts = dict.fromkeys(RayCounts._fields, 0)
    for start in range(0, h, step):
        band = slice(start, min(start + step, h))
        image[band], more = _trace_rows(c, rays.origins[band], rays.directions[band], *options)
        counts = {kind: counts[kind] + more[kind] for kind in counts}
        yield image.copy(), RayCounts(**counts), band.stop


def _prepare(scene, camera, max_depth, supersampling, seed, jitter, epsilon, min_weight,
             shadows):
    """Check the arguments of :func:`render`: the compiled scene, the camera's rays and the
    options of :func:`_trace_rows`."""
    c = _Compiled(scene)
    camera = scene.camera if camera is None else camera
    if camera is None:
        raise ValueError("camera must be a Camera (the scene has none: pass one)")
    if not isinstance(camera, Camera):
        raise TypeError(f"camera must be a Camera, got {type(camera).__name__}")
    depth, eps, min_weight = _render_options(max_depth, epsilon, min_weight)
    return c, camera.rays(supersampling, seed, jitter), (depth, bool(shadows), eps, min_weight)


def _trace_rows(c, origins, directions, depth, shadows, eps, min_weight):
    """Trace camera rays of shape (rows, width, samples, 3), generation by generation: the
    clamped mean colour per pixel (rows, width, 3) and the ray counts (a dict)."""
    h, w, s, _ = directions.shape
    o = origins.reshape(-1, 3)
    d = directions.reshape(-1, 3)
    n = len(o)
    colour = np.zeros((n, 3))
    pixel = np.arange(n)
    weight = np.ones(n)
    counts = {"primary": n, "shadow": 0, "reflected": 0, "refracted": 0}
    for level in range(depth + 1):
        g = _generation(c, o, d, level < depth, shadows, eps)
        counts["shadow"] += g.shadow_rays
        contribution = weight[:, None] * g.local
        for channel in range(3):
            colour[:, channel] += np.bincount(pixel, contribution[:, channel], minlength=n)
        parts = []
        for kind, parents, origins, directions, factors in g.children:
            wk = weight[parents] * factors
            keep = wk >= min_weight if min_weight > 0 else slice(None)
            counts[kind] += int(np.count_nonzero(wk[keep] >= 0))
            parts.append((pixel[parents][keep], origins[keep], directions[keep], wk[keep]))
        if not parts or sum(len(part[0]) for part in parts) == 0:
            break
        pixel, o, d, weight = (np.concatenate([part[i] for part in parts]) for i in range(4))
    return np.clip(colour.reshape(h, w, s, 3).mean(axis=2), 0.0, 1.0), counts


@dataclass(eq=False)
class RayNode:
    r"""One ray of a ray tree (:func:`trace_tree`), with its children.

    Attributes
    ----------
    kind : str
        ``"primary"``, ``"reflected"``, ``"refracted"`` or ``"shadow"``.
    origin, direction : ndarray, shape (3,)
        The ray (unit direction).
    weight : float
        The product of the reflection / transmission factors from the root down to this ray:
        how much of what it sees reaches the pixel (a shadow ray carries its parent's weight).
    depth : int
        Bounces from the primary ray (0); a shadow ray has its parent's depth + 1.
    t : float
        Distance to the hit (inf: none; for a shadow ray, the distance to the light).
    hit, normal : ndarray, shape (3,), or None
        The hit point and the shading normal there (facing the ray); None on a miss and for
        shadow rays.
    object : int
        Index of the object hit in ``scene.objects``; -1 on a miss and for shadow rays.
    local : ndarray, shape (3,)
        The local (Phong) colour at the hit, the background colour on a miss, zero for a shadow
        ray.
    contribution : ndarray, shape (3,)
        ``weight * local``: what this ray adds to the pixel. The pixel's (unclamped) colour is
        the sum over the tree, :meth:`total`.
    light : int or None
        For a shadow ray: the index of its light.
    visibility : float or None
        For a shadow ray: the fraction of the light that gets through (1 lit, 0 blocked).
    children : list of RayNode
        Shadow rays first, then the reflected and the refracted ray.

    Examples
    --------
    >>> from course_lib.raytracing import example_scene
    >>> tree = trace_tree(example_scene("spheres"), [0, 1, 6], [0, 0, -1], max_depth=2)
    >>> [node.kind for node in tree.walk()][:3]
    ['primary', 'shadow', 'reflected']
    """
    kind: str
    origin: np.ndarray
    direction: np.ndarray
    weight: float
    depth: int
    t: float = np.inf
    hit: object = None
    normal: object = None
    object: int = -1
    local: np.ndarray = field(default_factory=lambda: np.zeros(3))
    contribution: np.ndarray = field(default_factory=lambda: np.zeros(3))
    light: object = None
    visibility: object = None
    children: list = field(default_factory=list)

    def walk(self):
        """All nodes of the subtree, depth first (this node first)."""
        yield self
        for child in self.children:
            yield from child.walk()

    def total(self):
        """The summed contributions of the subtree: the pixel colour before clamping."""
        return sum((node.contribution for node in self.walk()), np.zeros(3))

    def count(self, kind=None):
        """Nodes in the subtree (of one `kind`, or all)."""
        return sum(1 for node in self.walk() if kind is None or node.kind == kind)

    def __repr__(self):
        where = "miss" if self.hit is None else f"object {self.object} at t={self.t:.4g}"
        if self.kind == "shadow":
            where = f"light {self.light}, visibility {self.visibility:.3g}"
        return (f"RayNode({self.kind}, depth {self.depth}, weight {self.weight:.4g}, {where}, "
                f"{len(self.children)} children)")


def trace_tree(scene, origin, direction, max_depth=3, shadows=True, epsilon=DEFAULT_EPSILON,
               min_weight=0.0):
    r"""The ray tree of one ray: every reflected, refracted and shadow ray it spawns.

    The same computation as :func:`render` for a single ray, keeping every ray as a
    :class:`RayNode`: the primary ray is the root; a hit spawns one shadow ray per light in
    front of the surface, a reflected ray (weight factor :math:`k_r + k_t F`) and a refracted
    ray (:math:`k_t (1 - F)`; none under total internal reflection), down to `max_depth`. The
    pixel colour is ``clip(tree.total(), 0, 1)``.

    Parameters
    ----------
    scene : Scene
    origin : array_like, shape (3,)
    direction : array_like, shape (3,)
        Normalized here.
    max_depth, shadows, epsilon, min_weight
        As for :func:`render`.

    Returns
    -------
    RayNode
        The root (kind ``"primary"``).

    Raises
    ------
    ValueError
        For a zero direction, NaN, a negative `max_depth` or a non-positive `epsilon`.
    TypeError
        If `scene` is not a Scene.

    Examples
    --------
    A ray into the glass sphere of the example scene: it reflects off the glass and refracts
    into it; inside, it reflects (internally) and refracts out again:

    >>> from course_lib.raytracing import example_scene
    >>> scene = example_scene("spheres")
    >>> glass = scene.objects[3].center
    >>> eye = scene.camera.eye
    >>> tree = trace_tree(scene, eye, glass - eye, max_depth=2)
    >>> [(node.kind, node.depth) for node in tree.children]
    [('shadow', 1), ('reflected', 1), ('refracted', 1)]
    >>> refracted = tree.children[2]
    >>> [node.kind for node in refracted.children]
    ['shadow', 'reflected', 'refracted']
    """
    c = _Compiled(scene)
    o = as_vector(origin, "origin", 3)
    d = as_vector(direction, "direction", 3)
    _nonzero_vectors(d[None], "direction", ())
    d = d / np.linalg.norm(d)
    depth, eps, min_weight = _render_options(max_depth, epsilon, min_weight)
    root = RayNode("primary", o, d, 1.0, 0)
    level = [root]
    origins, directions = o[None], d[None]
    for generation in range(depth + 1):
        g = _generation(c, origins, directions, generation < depth, shadows, eps, record=True)
        for i, node in enumerate(level):
            node.t = float(g.t[i])
            node.local = g.local[i].copy()
            node.contribution = node.weight * node.local
            if g.hit[i]:
                node.hit, node.normal, node.object = g.points[i].copy(), g.normals[i].copy(), \
                    int(g.objects[i])
        for light, parents, s_origin, s_dir, vis in g.shadows:
            for r, so, sd, v in zip(parents, s_origin, s_dir, vis):
                parent = level[r]
                target = c.lights[light]
                dist = (np.inf if target.position is None
                        else float(np.linalg.norm(target.position - so)))
                parent.children.append(RayNode("shadow", so.copy(), sd.copy(), parent.weight,
                                               parent.depth + 1, t=dist, light=light,
                                               visibility=float(v)))
        next_level, next_o, next_d = [], [], []
        for kind, parents, k_origins, k_dirs, factors in g.children:
            for r, ko, kd, f in zip(parents, k_origins, k_dirs, factors):
                parent = level[r]
                weight = parent.weight * float(f)
                if min_weight > 0 and weight < min_weight:
                    continue
                child = RayNode(kind, ko.copy(), kd.copy(), weight, parent.depth + 1)
                parent.children.append(child)
                next_level.append(child)
                next_o.append(ko)
                next_d.append(kd)
        if not next_level:
            break
        level, origins, directions = next_level, np.array(next_o), np.array(next_d)
    return root
