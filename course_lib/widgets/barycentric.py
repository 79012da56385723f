r"""Barycentric explorer: drag a point P and the corners of a triangle ABC; see the three
sub-triangles whose areas are P's barycentric weights, and colour interpolation.

Joining P to the corners cuts the triangle into three: PBC (opposite A), APC (opposite B) and
ABP (opposite C). Their **signed** areas divided by the area of ABC are the barycentric
coordinates :math:`(\lambda_A, \lambda_B, \lambda_C)`, which add up to 1 and reproduce P,
:math:`P = \lambda_A A + \lambda_B B + \lambda_C C`. Inside the triangle all three are positive;
when P crosses an edge, the sub-triangle opposite that edge turns over (its corners go
clockwise) and its weight becomes negative. The same weights interpolate anything given at the
corners — here a colour (red, green, blue at A, B, C): the picture fills the triangle with
:math:`\lambda_A c_A + \lambda_B c_B + \lambda_C c_C`, which is what a rasterizer does with
vertex colours, normals and texture coordinates.
"""
from dataclasses import dataclass, field

import numpy as np

from .. import draw, texturing
from . import _style
from ._base import Explorer, bind, panel
from ._drag import DraggablePoints

__all__ = ["BarycentricExplorer", "COLORS", "State", "scene", "signed_area"]

LIMITS = (0.0, 10.0)
RESOLUTION = 120
COLORS = np.array([[0.90, 0.22, 0.20], [0.20, 0.72, 0.30], [0.20, 0.42, 0.95]])
"""The colours of the corners A, B, C (RGB in [0, 1])."""
NAMES = ("A", "B", "C")
SUB_NAMES = ("PBC", "APC", "ABP")
MODES = ("areas", "colours")


def _default_triangle():
    return np.array([[1.0, 1.2], [9.0, 2.2], [3.8, 8.8]])


@dataclass
class State:
    """The triangle's corners A, B, C (rows), the point P, and what the picture shows.

    Examples
    --------
    >>> State().triangle.shape, State().point.tolist(), State().mode
    ((3, 2), [4.5, 4.0], 'areas')
    """

    triangle: np.ndarray = field(default_factory=_default_triangle)
    point: np.ndarray = field(default_factory=lambda: np.array([4.5, 4.0]))
    mode: str = "areas"


def signed_area(a, b, c):
    r"""Signed area of the triangle (a, b, c): positive when its corners run counter-clockwise.

    .. math:: A(a, b, c) = \tfrac12 \big[(b_x - a_x)(c_y - a_y) - (b_y - a_y)(c_x - a_x)\big]

    Examples
    --------
    >>> signed_area([0, 0], [4, 0], [0, 3]), signed_area([0, 0], [0, 3], [4, 0])
    (6.0, -6.0)
    """
    a, b, c = (np.asarray(x, dtype=float) for x in (a, b, c))
    return 0.5 * float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


def _pixel_centres():
    s = LIMITS[0] + (np.arange(RESOLUTION) + 0.5) / RESOLUTION * (LIMITS[1] - LIMITS[0])
    x, y = np.meshgrid(s, s)
    return np.stack([x, y], axis=-1)


_PIXELS = _pixel_centres()


def scene(state):
    r"""Pure part: weights, signed areas, sub-triangles, the colour-interpolated picture.

    Returns
    -------
    dict
        ``weights`` :math:`(\lambda_A, \lambda_B, \lambda_C)` (NaN for a degenerate triangle),
        ``areas`` (signed areas of ABC, PBC, APC, ABP by name), ``sub_triangles`` (three 3x2
        arrays: PBC, APC, ABP), ``inside`` (bool), ``colour`` (P's interpolated colour, clipped
        to [0, 1]), ``raw_colour`` (unclipped: outside the triangle the weights extrapolate),
        ``image`` (RGBA, RESOLUTION x RESOLUTION, row 0 at the bottom, transparent outside
        the triangle), ``degenerate`` and ``text``.

    Examples
    --------
    >>> s = scene(State(triangle=np.array([[0.0, 0], [4, 0], [0, 4]]), point=np.array([1.0, 1])))
    >>> s["weights"].tolist(), s["areas"]["PBC"], s["inside"]
    ([0.5, 0.25, 0.25], 4.0, True)
    >>> scene(State(triangle=np.array([[0.0, 0], [4, 0], [0, 4]]),
    ...             point=np.array([3.0, 3])))["weights"].tolist()    # beyond the edge BC
    [-0.5, 0.75, 0.75]
    """
    tri = np.asarray(state.triangle, dtype=float)
    p = np.asarray(state.point, dtype=float)
    a, b, c = tri
    subs = [np.array([p, b, c]), np.array([a, p, c]), np.array([a, b, p])]
    areas = {"ABC": signed_area(a, b, c)}
    for name, sub in zip(SUB_NAMES, subs):
        areas[name] = signed_area(*sub)
    longest = max(np.sum((b - a) ** 2), np.sum((c - b) ** 2), np.sum((a - c) ** 2))
    degenerate = abs(areas["ABC"]) <= 1e-9 * max(longest, 1e-12)
    image = np.zeros((RESOLUTION, RESOLUTION, 4))
    if degenerate:
        weights = np.full(3, np.nan)
        raw = np.full(3, np.nan)
        colour = np.full(3, 0.5)
        inside = False
        text = ("The triangle is <b>degenerate</b> (its corners are on one line, area 0): "
                "barycentric coordinates are undefined. Drag a corner away.")
    else:
        weights = texturing.barycentric(p, a, b, c)
        raw = texturing.barycentric_interpolate(COLORS, weights)
        colour = np.clip(raw, 0.0, 1.0)
        inside = bool(np.all(weights >= 0))
        w = texturing.barycentric(_PIXELS, a, b, c)
        in_tri = np.all(w >= 0, axis=-1)
        image[..., :3] = np.clip(texturing.barycentric_interpolate(COLORS, w), 0.0, 1.0)
        image[..., 3] = in_tri
        ratio = " ".join(
            f"λ<sub>{n}</sub> = A({sub})/A(ABC) = {areas[sub]:.2f}/{areas['ABC']:.2f} = "
            f"<b>{wt:+.3f}</b>;" for n, sub, wt in zip(NAMES, SUB_NAMES, weights))
        text = (f"{ratio} sum = {weights.sum():.3f}. "
                f"Check: λ<sub>A</sub>A + λ<sub>B</sub>B + λ<sub>C</sub>C = "
                f"({(weights @ tri)[0]:.2f}, {(weights @ tri)[1]:.2f}) = P. ")
        if inside:
            text += "P is inside: all three weights are positive, each sub-triangle is a share."
        else:
            negative = [f"λ<sub>{NAMES[k]}</sub>" for k in range(3) if weights[k] < 0]
            text += (f"P is <b>outside</b>: {', '.join(negative)} negative — the sub-triangle(s) "
                     "opposite turned over (clockwise, negative signed area). The colour at P "
                     "is extrapolated, and clipped to [0, 1] to show it.")
        if areas["ABC"] < 0:
            text += (" (ABC itself is clockwise now: all signed areas flip sign, the ratios do "
                     "not.)")
    return {"weights": weights, "areas": areas, "sub_triangles": subs, "inside": inside,
            "colour": colour, "raw_colour": raw, "image": image, "degenerate": degenerate,
            "text": text}


class BarycentricExplorer(Explorer):
    """Drag P and the corners; the sub-triangles or the interpolated colours, the weights as
    bars, and the colour at P.

    In a notebook, after ``%matplotlib widget``, end a cell with ``BarycentricExplorer()``.

    Examples
    --------
    >>> explorer = BarycentricExplorer()
    >>> explorer.drag.press(4.5, 4.0); explorer.drag.move(2.0, 2.0); explorer.drag.release()
    >>> explorer.state.point.tolist()
    [2.0, 2.0]
    >>> explorer.mode.value = "colours"
    >>> explorer.fill.get_visible(), explorer.patches[0].get_visible()
    (True, False)
    """

    summary = ("Barycentric explorer (interactive): drag a point and the corners of a triangle; "
               "the signed areas of the three sub-triangles are the weights, which also "
               "interpolate the corners' colours.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.patches import Polygon, Rectangle

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(6.6, 4.3))
        ax = self.fig.add_axes((0.08, 0.1, 0.56, 0.84))
        draw.setup_axes_2d(ax, LIMITS, title="drag P and the corners A, B, C")
        self.ax = ax
        self.fill = ax.imshow(s["image"], origin="lower", extent=(*LIMITS, *LIMITS),
                              interpolation="nearest", zorder=1.6)
        self.patches = []
        for k in range(3):
            patch = Polygon(np.zeros((3, 2)), closed=True, facecolor=(*COLORS[k], 0.35),
                            edgecolor=COLORS[k], lw=1.2, zorder=2)
            ax.add_patch(patch)
            self.patches.append(patch)
        (self.outline,) = ax.plot([], [], color="0.15", lw=1.8, zorder=3)
        self.markers = ax.scatter(np.zeros(4), np.zeros(4), s=[90, 90, 90, 120],
                                  edgecolors="0.1", linewidths=1.2, zorder=5)
        # the names as marker glyphs: a path drawn on each move costs far less than a text
        self.labels = [ax.plot([], [], marker=f"$\\mathbf{{{name}}}$", ms=_style.LABEL, color="0.1",
                               ls="none",
                               zorder=6)[0] for name in (*NAMES, "P")]
        self.area_labels = [ax.text(0, 0, "", fontsize=_style.ANNOTATION, ha="center",
                                    va="center", zorder=4,
                                    color="0.1") for _ in range(3)]
        bars = self.fig.add_axes((0.75, 0.47, 0.22, 0.43))
        bars.set_title("weights λ")
        bars.axhline(0, color="0.3", lw=0.8)
        bars.axhline(1, color="0.7", lw=0.8, ls="--")
        bars.set(ylim=(-1.0, 1.6), xlim=(-0.6, 2.6), xticks=[0, 1, 2],
                 xticklabels=["λ_A", "λ_B", "λ_C"])
        self.bars = [Rectangle((k - 0.35, 0), 0.7, 0, color=COLORS[k], zorder=2)
                     for k in range(3)]
        for rect in self.bars:
            bars.add_patch(rect)
        self.bar_values = [bars.text(k, 0, "", ha="center", fontsize=_style.ANNOTATION, zorder=3)
                           for k in range(3)]
        swatch = self.fig.add_axes((0.75, 0.08, 0.22, 0.25))
        swatch.set(xticks=[], yticks=[], xlim=(0, 1), ylim=(0, 1))
        swatch.set_title("colour at P")
        self.swatch = Rectangle((0, 0), 1, 1, color="0.5")
        swatch.add_patch(self.swatch)
        self.swatch_text = swatch.text(0.5, 0.5, "", ha="center", va="center",
                                       fontsize=_style.ANNOTATION)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.fill, *self.patches, self.outline,
                                               self.markers, *self.labels, *self.area_labels,
                                               *self.bars, *self.bar_values, self.swatch,
                                               self.swatch_text])
        self.drag = DraggablePoints(ax, np.vstack([self.state.triangle, self.state.point]),
                                    self._on_drag)
        self.mode = w.ToggleButtons(options=MODES, value=self.state.mode,
                                    description="show",
                                    style={"button_width": _style.button_width(*MODES)})
        bind(self.state, {"mode": self.mode}, self.update)
        self.info = panel(width="700px")
        self.widget = w.VBox([self.fig.canvas, self.mode, self.info])
        self._draw(s)

    def _on_drag(self, index, xy):
        points = self.drag.points
        self.state.triangle = points[:3].copy()
        self.state.point = points[3].copy()
        self.update()

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        tri, p = self.state.triangle, self.state.point
        areas_mode = self.state.mode == "areas"
        self.fill.set_data(s["image"])
        self.fill.set_visible(not areas_mode)
        for k, (patch, sub) in enumerate(zip(self.patches, s["sub_triangles"])):
            patch.set_xy(sub)
            negative = s["areas"][SUB_NAMES[k]] * s["areas"]["ABC"] < 0
            patch.set_visible(areas_mode)
            patch.set_hatch("////" if negative else None)
            patch.set_linestyle("--" if negative else "-")
        self.outline.set_data(*np.vstack([tri, tri[:1]]).T)
        self.markers.set_offsets(np.vstack([tri, p]))
        self.markers.set_facecolor(np.vstack([COLORS, s["colour"]]))
        centre = tri.mean(axis=0)
        for k, label in enumerate(self.labels):
            at = tri[k] if k < 3 else p
            away = at - centre
            away = away / max(np.linalg.norm(away), 1e-9) * 0.45
            x, y = at + away
            label.set_data([x], [y])
        for k, label in enumerate(self.area_labels):
            if areas_mode and not s["degenerate"]:
                label.set_position(s["sub_triangles"][k].mean(axis=0))
                label.set_text(f"{SUB_NAMES[k]}\n{s['areas'][SUB_NAMES[k]]:+.1f}")
            else:
                label.set_text("")
        for k, (rect, value) in enumerate(zip(self.bars, self.bar_values)):
            wt = 0.0 if s["degenerate"] else float(s["weights"][k])
            shown = float(np.clip(wt, -0.95, 1.55))
            rect.set_height(shown)
            value.set_text("—" if s["degenerate"] else f"{wt:+.2f}")
            value.set_position((k, shown + (0.05 if shown >= 0 else -0.13)))
        self.swatch.set_color(s["colour"])
        r, g, b = s["colour"]
        self.swatch_text.set_text(f"({r:.2f}, {g:.2f}, {b:.2f})"
                                  + ("" if s["inside"] else "\nextrapolated, clipped"))
        self.swatch_text.set_color("white" if 0.3 * r + 0.59 * g + 0.11 * b < 0.5 else "black")
        self.info.value = s["text"]
