r"""Ray-tree view: pick a pixel and see every ray the ray tracer shot for it, in the scene.

Left: the ray-traced image (click a pixel, or use the row / column sliders). Right: the scene
in 3D (spheres as wireframes, planes as grids, the light as a star, the eye as a dot) with the
pixel's **ray tree** (:func:`course_lib.raytracing.trace_tree`) drawn in it: the primary ray in
black, reflected rays in blue, refracted rays in green, shadow rays in orange (dotted grey when
blocked), each line as thick as its **weight** (the product of the :math:`k_r` and :math:`k_t
F` or :math:`k_t (1 - F)` factors on its path). Rays that leave the scene are drawn
:data:`MISS_LENGTH` long. Below: a table of the rays with their local colour and their
contribution ``weight × local``, which add up to the pixel's colour (before clamping to
[0, 1]).
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, raytracing as rt
from .._validate import as_choice
from . import _style
from ._base import Explorer, align, beside, checkbox, panel, read_controls, slider

__all__ = ["KINDS", "RAY_COLORS", "RayTreeExplorer", "State", "clip_segment", "example",
           "picture", "scene"]

KINDS = ("spheres", "glass", "mirrors")
IMAGE = (160, 120)          # width, height of the picking image
VIEW = (28, -30)            # elevation and azimuth of the 3D view (degrees, y up)
MISS_LENGTH = 2.5           # how far a ray that hits nothing is drawn
RAY_COLORS = {"primary": "#111111", "reflected": "#1f5fd6", "refracted": "#14a03c",
              "shadow": "#f08c00", "blocked": "#9a9a9a"}
LIMITS = {"spheres": ((-3.5, 3.5), (-0.5, 6.5), (-3.0, 6.5)),
          "glass": ((-3.0, 3.0), (-1.0, 4.5), (-2.0, 5.5)),
          "mirrors": ((-2.5, 2.5), (-0.5, 5.5), (-3.0, 5.5))}


@dataclass
class State:
    """The scene, the picked pixel (row 0 at the bottom) and the tracer's settings.

    Examples
    --------
    >>> State().kind, State().max_depth
    ('spheres', 3)
    """

    kind: str = "spheres"
    row: int = 47
    column: int = 131
    max_depth: int = 3
    shadows: bool = True


@lru_cache(maxsize=4)
def example(kind):
    """The example scene `kind` with its camera at the picking size (cached).

    Examples
    --------
    >>> example("glass").camera.width
    160
    """
    as_choice(kind, "kind", KINDS)
    return rt.example_scene(kind, *IMAGE)


@lru_cache(maxsize=16)
def picture(kind, max_depth, shadows):
    """The ray-traced picking image of a scene (cached), row 0 at the bottom.

    Examples
    --------
    >>> picture("spheres", 0, True).shape
    (120, 160, 3)
    """
    scn = example(kind)
    image = rt.render(scn, max_depth=max_depth, shadows=shadows)
    image.setflags(write=False)
    return image


def _object_name(scn, index):
    if index < 0:
        return "—"
    obj = scn.objects[index]
    m = obj.material
    what = ("glass" if m.transparency > 0 else "mirror" if m.reflectivity >= 0.5 else
            "floor" if isinstance(obj, rt.Plane) and abs(obj.normal[1]) > 0.9 else
            "wall" if isinstance(obj, rt.Plane) else "sphere")
    return f"{what} #{index}"


def scene(state):
    """Pure part: the pixel's ray tree, as segments to draw and rows of a table.

    Returns
    -------
    dict
        ``tree`` (the root :class:`course_lib.raytracing.RayNode`); ``nodes`` (all nodes,
        depth first); ``segments``: for each of ``primary``, ``reflected``, ``refracted``,
        ``shadow`` and ``blocked``, an array (k, 2, 3) of start and end points, clipped to the
        drawn box :data:`LIMITS` (rays leaving it are cut there); ``weights``: the matching
        weights; ``hits`` (h, 3) the hit points inside the box; ``pixel`` (the colour
        ``clip(tree.total(), 0, 1)``); ``image`` (the picking picture); ``rows`` (the table:
        one dict per ray); ``counts`` (rays per kind); ``text``.

    Examples
    --------
    >>> s = scene(State(kind="glass", row=60, column=80, max_depth=2))
    >>> s["counts"]["primary"], s["segments"]["primary"].shape
    (1, (1, 2, 3))
    """
    as_choice(state.kind, "kind", KINDS)
    scn = example(state.kind)
    origin, direction = scn.camera.pixel_ray(state.row, state.column)
    tree = rt.trace_tree(scn, origin, direction, max_depth=state.max_depth,
                         shadows=state.shadows)
    nodes = list(tree.walk())
    segments = {kind: [] for kind in RAY_COLORS}
    weights = {kind: [] for kind in RAY_COLORS}
    hits, rows = [], []
    for k, node in enumerate(nodes):
        if node.kind == "shadow":
            light = scn.lights[node.light]
            end = (light.position if light.position is not None
                   else node.origin + MISS_LENGTH * node.direction)
            kind = "shadow" if node.visibility > 0 else "blocked"
        else:
            length = node.t if np.isfinite(node.t) else MISS_LENGTH
            end = node.origin + length * node.direction
            kind = node.kind
            if node.hit is not None and all(lo <= x <= hi for x, (lo, hi)
                                            in zip(node.hit, LIMITS[state.kind])):
                hits.append(node.hit)
        piece = clip_segment(node.origin, end, LIMITS[state.kind])
        if piece is not None:
            segments[kind].append(piece)
            weights[kind].append(node.weight)
        if node.kind == "shadow":
            seen = ("lit" if node.visibility == 1 else "blocked" if node.visibility == 0
                    else f"{node.visibility:.2f} gets through")
        else:
            seen = _object_name(scn, node.object) if node.hit is not None else "background"
        rows.append({"index": k, "kind": node.kind, "depth": node.depth, "weight": node.weight,
                     "sees": seen, "local": node.local, "contribution": node.contribution})
    segments = {k: np.array(v, dtype=float).reshape(-1, 2, 3) for k, v in segments.items()}
    weights = {k: np.array(v, dtype=float) for k, v in weights.items()}
    counts = {kind: tree.count(kind) for kind in ("primary", "shadow", "reflected", "refracted")}
    total = tree.total()
    pixel = np.clip(total, 0.0, 1.0)
    text = (f"Pixel (row {state.row}, column {state.column}): {len(nodes)} rays — "
            f"{counts['shadow']} shadow, {counts['reflected']} reflected, "
            f"{counts['refracted']} refracted. Summed contributions "
            f"({total[0]:.3f}, {total[1]:.3f}, {total[2]:.3f})"
            + (", clamped to [0, 1]." if np.any(total > 1) else ".")
            + " A complete tree of depth d would have 2<sup>d+1</sup> − 1 reflected/refracted "
            f"nodes ({2 ** (state.max_depth + 1) - 1} here): misses, opaque surfaces and total "
            "internal reflection prune it.")
    return {"tree": tree, "nodes": nodes, "segments": segments, "weights": weights,
            "hits": np.array(hits, dtype=float).reshape(-1, 3), "pixel": pixel,
            "total": total, "image": picture(state.kind, state.max_depth, state.shadows),
            "rows": rows, "counts": counts, "text": text}


def clip_segment(p, q, limits):
    """The part of segment `p`-`q` inside the box `limits` (slab method), or None.

    Examples
    --------
    >>> clip_segment(np.zeros(3), np.array([4.0, 0, 0]), ((-1, 1), (-1, 1), (-1, 1)))
    array([[0., 0., 0.],
           [1., 0., 0.]])
    """
    d = q - p
    t0, t1 = 0.0, 1.0
    for k, (lo, hi) in enumerate(limits):
        if d[k] == 0:
            if not lo <= p[k] <= hi:
                return None
            continue
        a, b = sorted(((lo - p[k]) / d[k], (hi - p[k]) / d[k]))
        t0, t1 = max(t0, a), min(t1, b)
    if t0 > t1:
        return None
    return np.array([p + t0 * d, p + t1 * d])


def _swatch(rgb):
    c = np.clip(np.asarray(rgb), 0, 1)
    hex_colour = "#" + "".join(f"{int(round(255 * v)):02x}" for v in c)
    return (f"<span style='display:inline-block;width:12px;height:12px;background:{hex_colour};"
            f"border:1px solid #888;vertical-align:middle'></span>")


def _table(s):
    head = ("<table style='font-size:11px;border-collapse:collapse'><tr><th>#</th><th>ray</th>"
            "<th>depth</th><th>weight</th><th>sees</th><th>local</th>"
            "<th>contribution = weight × local</th></tr>")
    body = []
    for r in s["rows"]:
        indent = "&nbsp;&nbsp;" * r["depth"]
        colour = RAY_COLORS["blocked" if r["sees"] == "blocked" else r["kind"]]
        contribution = r["contribution"]
        body.append(f"<tr><td>{r['index']}</td><td style='color:{colour}'>{indent}{r['kind']}"
                    f"</td><td>{r['depth']}</td><td>{r['weight']:.3f}</td><td>{r['sees']}</td>"
                    f"<td>{_swatch(r['local'])}</td><td>{_swatch(contribution)} "
                    f"({contribution[0]:.3f}, {contribution[1]:.3f}, {contribution[2]:.3f})"
                    "</td></tr>")
    total = s["total"]
    body.append(f"<tr><td></td><td><b>pixel</b></td><td></td><td></td><td>sum</td><td></td>"
                f"<td>{_swatch(s['pixel'])} ({total[0]:.3f}, {total[1]:.3f}, {total[2]:.3f})"
                "</td></tr>")
    return head + "".join(body) + "</table>"


def _sphere_lines(center, radius, n=16):
    """Wireframe of a sphere: meridians and parallels as polylines, shape (k, m, 3)."""
    u = np.linspace(0, 2 * np.pi, 2 * n + 1)
    lines = []
    for v in np.linspace(0, np.pi, n // 2 + 1)[1:-1]:                 # parallels
        lines.append(np.column_stack([np.sin(v) * np.cos(u), np.full_like(u, np.cos(v)),
                                      np.sin(v) * np.sin(u)]))
    w = np.linspace(0, np.pi, n + 1)
    for a in np.linspace(0, 2 * np.pi, n, endpoint=False):           # meridians
        lines.append(np.column_stack([np.sin(w) * np.cos(a), np.cos(w), np.sin(w) * np.sin(a)]))
    return [center + radius * line for line in lines]


def _plane_lines(plane, limits, step=1.0):
    """Grid lines of a plane inside the box `limits` (a plane normal to an axis)."""
    axis = int(np.argmax(np.abs(plane.normal)))
    others = [k for k in range(3) if k != axis]
    level = plane.point[axis]
    lines = []
    for a, b in (others, others[::-1]):
        lo, hi = limits[a]
        for value in np.arange(np.ceil(lo / step) * step, hi + 1e-9, step):
            p, q = np.zeros(3), np.zeros(3)
            p[axis] = q[axis] = level
            p[a] = q[a] = value
            p[b], q[b] = limits[b]
            lines.append([p, q])
    return lines


class RayTreeExplorer(Explorer):
    """Click a pixel of the ray-traced image; its ray tree is drawn in the 3D scene and listed.

    In a notebook, after ``%matplotlib widget``, end a cell with ``RayTreeExplorer()``.

    Examples
    --------
    >>> explorer = RayTreeExplorer()
    >>> explorer.column.value = 20
    >>> explorer.current["segments"]["primary"].shape
    (1, 2, 3)
    """

    summary = ("Ray-tree view (interactive): click a pixel of the ray-traced image to see its "
               "primary, shadow, reflected and refracted rays drawn in the 3D scene, each as "
               "thick as its weight, with a table of their contributions.")

    def __init__(self, state=None):
        import ipywidgets as w
        from mpl_toolkits.mplot3d.art3d import Line3DCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(8.6, 4.2), dpi=90)
        self.ax_image = self.fig.add_axes((0.02, 0.12, 0.42, 0.8))
        self.ax_image.set(xticks=[], yticks=[])
        self.ax_image.set_title("click a pixel", fontsize=_style.TITLE)
        w_img, h_img = IMAGE
        self.picture = self.ax_image.imshow(s["image"], origin="lower", extent=(0, w_img, 0, h_img),
                                            interpolation="nearest")
        (self.marker,) = self.ax_image.plot([], [], "s", ms=9, mfc="none", mec="#ff2d95", mew=2)
        self.ax3d = self.fig.add_axes((0.45, 0.15, 0.55, 0.78), projection="3d")
        self.ax3d.set_title("the pixel's ray tree", fontsize=_style.TITLE)
        self.ax3d.view_init(elev=VIEW[0], azim=VIEW[1], vertical_axis="y")
        self.static = []
        self._draw_static(s)
        self.lines = {}
        for kind, colour in RAY_COLORS.items():
            style = ":" if kind in ("shadow", "blocked") else "-"
            collection = Line3DCollection([], colors=colour, linestyles=style, label=kind)
            self.ax3d.add_collection(collection)
            self.lines[kind] = collection
        (self.hit_points,) = self.ax3d.plot([], [], [], "o", color="#d0021b", ms=4,
                                            label="hit points")
        self.fig.legend(handles=[*self.lines.values(), self.hit_points], loc="lower center",
                        bbox_to_anchor=(0.72, 0.0), fontsize=_style.LEGEND, frameon=False, ncol=3,
                        columnspacing=1.2, handlelength=1.6)
        self.blitter = draw.Blitter(self.fig, [*self.lines.values(), self.hit_points,
                                               self.marker])

        self.kind = w.ToggleButtons(options=KINDS, value=self.state.kind,
                                    style={"button_width": _style.button_width(*KINDS)})
        self.row, self.column, self.depth = align([
            slider("pixel row", self.state.row, 0, h_img - 1, 1, kind=w.IntSlider),
            slider("pixel column", self.state.column, 0, w_img - 1, 1, kind=w.IntSlider),
            slider("max depth", self.state.max_depth, 0, 6, 1, kind=w.IntSlider)])
        self.shadows = checkbox("shadow rays", self.state.shadows)
        #: field of ``State`` -> its control (a click on the image sets row and column)
        self.controls = {"kind": self.kind, "max_depth": self.depth, "shadows": self.shadows,
                         "row": self.row, "column": self.column}
        for control in (self.kind, self.row, self.column, self.depth, self.shadows):
            control.observe(self._on_change, names="value")
        self._cid = self.fig.canvas.mpl_connect("button_press_event", self._on_click)
        self.info = panel(width="330px")
        self.table = panel()
        self._kind_drawn = self.state.kind
        # the figure is too wide for the controls beside it: they go under it, the table of
        # rays beside them
        self.widget = w.VBox([self.fig.canvas,
                              beside(w.VBox([self.kind, self.row, self.column, self.depth,
                                             self.shadows, self.info]),
                                     self.table, align="flex-start")])
        self.current = None
        self._quiet = False
        self._image_key = self._key()
        self._draw(s)

    def _draw_static(self, s):
        """The scene's objects, light and eye (drawn once per scene kind)."""
        from matplotlib.ticker import MaxNLocator
        from mpl_toolkits.mplot3d.art3d import Line3DCollection

        for artist in self.static:
            artist.remove()
        self.static = []
        ax = self.ax3d
        scn = example(self.state.kind)
        limits = LIMITS[self.state.kind]
        for obj in scn.objects:
            m = obj.material
            if isinstance(obj, rt.Sphere):
                colour = ("#5fa8d3" if m.transparency > 0 else "#7a7a7a" if m.reflectivity >= 0.5
                          else np.clip(np.broadcast_to(m.phong.kd, 3) * 1.1, 0, 1))
                lines = _sphere_lines(obj.center, obj.radius)
                alpha = 0.45
            elif isinstance(obj, rt.Plane):
                colour, alpha = "#b0b0b0", 0.5
                lines = _plane_lines(obj, limits)
            else:
                continue
            collection = Line3DCollection(lines, colors=[colour], linewidths=0.6, alpha=alpha)
            ax.add_collection(collection)
            self.static.append(collection)
        for light in scn.lights:
            if light.position is not None:
                self.static.extend(ax.plot(*light.position[:, None], "*", color="#ffc107",
                                           mec="#8a6d00", ms=14))
        self.static.extend(ax.plot(*scn.camera.eye[:, None], "o", color="k", ms=5))
        ax.set(xlim=limits[0], ylim=limits[1], zlim=limits[2], xlabel="x", ylabel="y (up)",
               zlabel="z")
        ax.set_box_aspect([hi - lo for lo, hi in limits])
        ax.tick_params(labelsize=_style.TICK, pad=0)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(MaxNLocator(4))
            axis.label.set_fontsize(_style.LABEL)
        ax.grid(False)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_pane_color((1.0, 1.0, 1.0, 0.0))

    def _on_change(self, change):
        if self._quiet:
            return
        read_controls(self.state, self.controls)
        self.update()

    def _key(self):
        return (self.state.kind, self.state.max_depth, self.state.shadows)

    def mouse_gestures(self):
        """The base class's gestures, and a click on the rendered image (picks that pixel).

        Examples
        --------
        >>> [g["kind"] for g in RayTreeExplorer().mouse_gestures()]
        ['turn', 'click']
        """
        x0, x1 = self.ax_image.get_xlim()
        y0, y1 = self.ax_image.get_ylim()
        pixel = self._canvas_fraction(self.ax_image, (x0 + 0.3 * (x1 - x0), y0 + 0.6 * (y1 - y0)))
        return super().mouse_gestures() + [{"kind": "click", "what": "a pixel of the image",
                                            "start": pixel, "end": pixel}]

    def _on_click(self, event):
        if event.inaxes is not self.ax_image or event.xdata is None:
            return
        column = int(np.clip(np.floor(event.xdata), 0, IMAGE[0] - 1))
        row = int(np.clip(np.floor(event.ydata), 0, IMAGE[1] - 1))
        self._quiet = True                      # one update for both sliders, not two
        try:
            self.row.value, self.column.value = row, column
        finally:
            self._quiet = False
        self._on_change(None)

    def update(self):
        """Recompute the tree and update the drawn rays in place (a new scene: a full redraw)."""
        s = scene(self.state)
        if self.state.kind != self._kind_drawn:
            self._draw_static(s)
            self._kind_drawn = self.state.kind
            self.blitter.forget_background()
        self._draw(s)
        self.blitter.update()

    def _draw(self, s):
        self.current = s
        if self._key() != self._image_key:
            self.picture.set_data(s["image"])
            self._image_key = self._key()
            self.blitter.forget_background()
        for kind, collection in self.lines.items():
            collection.set_segments(s["segments"][kind])
            collection.set_linewidths(0.8 + 3.2 * s["weights"][kind])
        hits = s["hits"]
        self.hit_points.set_data_3d(hits[:, 0], hits[:, 1], hits[:, 2])
        self.marker.set_data([self.state.column + 0.5], [self.state.row + 0.5])
        self.info.value = s["text"]
        self.table.value = _table(s)
