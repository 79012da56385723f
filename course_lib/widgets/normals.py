r"""Normals explorer: why normals transform with the inverse transpose.

A 2D shape (an ellipse's parent, the unit circle, or a polygon) is mapped by
:math:`A = H(h)\,S(s_x, s_y)` (a non-uniform scale, then a shear :math:`x \mathrel{+}= h\,y`).
At sample points of the transformed outline two normals are drawn: the naive :math:`A n`
(red), which leans off the perpendicular as soon as the scale is non-uniform or sheared, and
the inverse-transpose :math:`A^{-T} n` (:func:`course_lib.frames.transform_normals`, green),
which stays perpendicular to the transformed tangent :math:`A t`. The title gives the worst
angle between the two, in degrees.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw, frames
from .._validate import as_choice
from . import _style
from ._base import Explorer, bind, panel, slider

__all__ = ["SHAPES", "NormalsExplorer", "State", "scene"]

SHAPES = ("circle", "polygon")
LENGTH = 0.8                                        # drawn length of a normal
_CIRCLE_T = np.linspace(0.0, 2 * np.pi, 16, endpoint=False) + np.pi / 16
_OUTLINE_T = np.linspace(0.0, 2 * np.pi, 121)
_POLYGON = np.array([[-1.0, -0.8], [1.1, -0.8], [1.1, 0.1], [0.2, 1.0], [-1.0, 0.6]])


@dataclass
class State:
    """The shape and the map's scale factors and shear.

    Examples
    --------
    >>> State().shape, State().sx
    ('circle', 2.0)
    """

    shape: str = "circle"
    sx: float = 2.0
    sy: float = 0.7
    shear: float = 0.0


def _shape(name):
    """Outline (m, 2), sample points (k, 2), their unit tangents and outward unit normals."""
    if name == "circle":
        outline = np.stack([np.cos(_OUTLINE_T), np.sin(_OUTLINE_T)], axis=-1)
        n = np.stack([np.cos(_CIRCLE_T), np.sin(_CIRCLE_T)], axis=-1)
        return outline, n.copy(), np.stack([-n[:, 1], n[:, 0]], axis=-1), n
    closed = np.vstack([_POLYGON, _POLYGON[:1]])
    edges = np.diff(closed, axis=0)
    t = edges / np.linalg.norm(edges, axis=1, keepdims=True)
    mid = closed[:-1] + 0.5 * edges
    return closed, mid, t, np.stack([t[:, 1], -t[:, 0]], axis=-1)   # CCW: outward = t turned -90


def _unit(v):
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _segments(base, direction):
    """Line data for many segments base -> base + LENGTH direction, separated by NaN."""
    k = len(base)
    out = np.full((3 * k, 2), np.nan)
    out[0::3] = base
    out[1::3] = base + LENGTH * direction
    return out


def _rounded_dot(a, b):
    """The largest |a . b| of paired rows, as text; rounding noise below 1e-12 shown as 0."""
    worst = float(np.abs(np.sum(a * b, axis=1)).max())
    return "0" if worst < 1e-12 else f"{worst:.2g}"


def scene(state):
    """Pure part: the transformed shape, the naive and the correct normals, the angle errors.

    Examples
    --------
    >>> s = scene(State(sx=1.0, sy=1.0, shear=0.0))     # the identity: no error
    >>> round(s["worst_deg"], 9)
    0.0
    >>> scene(State(sx=2.0, sy=1.0, shape="circle"))["worst_deg"] > 15
    True
    """
    shape = as_choice(state.shape, "shape", SHAPES)
    sx, sy, h = float(state.sx), float(state.sy), float(state.shear)
    if sx == 0 or sy == 0:
        raise ValueError("sx and sy must not be 0: a zero scale flattens the shape and has no "
                         "normal matrix")
    A = np.array([[1.0, h], [0.0, 1.0]]) @ np.diag([sx, sy])
    outline, points, tangents, normals = _shape(shape)
    moved_outline = outline @ A.T
    base = points @ A.T
    naive = _unit(normals @ A.T)
    correct = frames.transform_normals(normals, A)
    new_tangents = _unit(tangents @ A.T)
    errors = np.degrees(np.arccos(np.clip(np.sum(naive * correct, axis=1), -1.0, 1.0)))
    worst = float(errors.max())
    # symmetric samples tie: round first, so that the first of them wins on every CPU
    worst_index = int(np.argmax(np.round(errors, 6)))
    text = (f"A = H({h:g}) S({sx:g}, {sy:g}) = [[{A[0, 0]:.3g}, {A[0, 1]:.3g}], "
            f"[{A[1, 0]:.3g}, {A[1, 1]:.3g}]]. "
            f"<b style='color:#c62828'>Naive A n</b>: worst {worst:.1f}° off the perpendicular. "
            f"<b style='color:#2e7d32'>A<sup>−T</sup> n</b>: perpendicular to the transformed "
            f"tangents (largest |n'·t'| = {_rounded_dot(correct, new_tangents)}).")
    if frames.preserves_normals(A):
        text += " A is a rotation/mirror times a uniform scale here, so A n is right too."
    return {"A": A, "outline": outline, "moved_outline": moved_outline, "base": base,
            "naive": naive, "correct": correct, "tangents": new_tangents, "errors": errors,
            "worst_deg": worst, "worst_index": worst_index,
            "naive_lines": _segments(base, naive),
            "correct_lines": _segments(base, correct), "text": text}


class NormalsExplorer(Explorer):
    """Shape toggle, s_x, s_y and shear sliders: the naive normals A n (red) lean off the
    transformed outline, the inverse-transpose normals (green) stay perpendicular.

    In a notebook, after ``%matplotlib widget``, end a cell with ``NormalsExplorer()``.

    Examples
    --------
    >>> explorer = NormalsExplorer()
    >>> explorer.shear.value = 1.0
    >>> explorer.state.shear
    1.0
    """

    summary = ("Normals explorer (interactive): a shape under a non-uniform scale and a shear; "
               "the naive normals A n lean off the surface, the inverse-transpose normals "
               "stay perpendicular; the worst angle error in degrees.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(4.8, 3.6))
        ax = self.fig.add_axes((0.1, 0.13, 0.87, 0.78))
        ax.set(xlim=(-6.2, 6.2), ylim=(-4.2, 4.2), aspect="equal")
        ax.set_xlabel("x", fontsize=8)
        ax.set_ylabel("y", fontsize=8)
        ax.tick_params(labelsize=7)
        (self.original_line,) = ax.plot([], [], color="0.75", lw=1, ls="--", label="original")
        (self.shape_line,) = ax.plot([], [], color="0.2", lw=1.5, label="transformed")
        (self.naive_line,) = ax.plot([], [], color="#c62828", lw=1.8, label="A n (naive)")
        (self.correct_line,) = ax.plot([], [], color="#2e7d32", lw=1.8,
                                       label="A⁻ᵀ n (right)")
        (self.worst_marker,) = ax.plot([], [], "o", mfc="none", mec="#c62828", mew=1.5, ms=12,
                                       label="worst naive normal")
        self.title = ax.set_title("", fontsize=9)
        _style.legend(ax, loc="lower right", fontsize=7, handlelength=1.5)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.original_line, self.shape_line,
                                               self.naive_line, self.correct_line,
                                               self.worst_marker, self.title])
        self.shape = w.ToggleButtons(options=SHAPES, value=self.state.shape,
                                     style={"button_width": _style.button_width(*SHAPES)})
        self.sx = slider("s_x", self.state.sx, 0.25, 3.0, 0.05)
        self.sy = slider("s_y", self.state.sy, 0.25, 3.0, 0.05)
        self.shear = slider("shear h", self.state.shear, -1.5, 1.5, 0.05)
        bind(self.state, {"shape": self.shape, "sx": self.sx, "sy": self.sy,
                          "shear": self.shear}, self.update)
        self.info = panel(width="600px")
        self.widget = w.VBox([self.fig.canvas, self.shape,
                              w.HBox([self.sx, self.sy, self.shear],
                                     layout=w.Layout(flex_flow="row wrap")), self.info])
        self._draw(s)

    def update(self):
        """Recompute the scene and redraw the moving lines."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.original_line.set_data(*s["outline"].T)
        self.shape_line.set_data(*s["moved_outline"].T)
        self.naive_line.set_data(*s["naive_lines"].T)
        self.correct_line.set_data(*s["correct_lines"].T)
        if s["worst_deg"] > 0.05:                 # ring the sample whose naive normal is worst
            self.worst_marker.set_data(*s["base"][s["worst_index"]][:, None])
        else:
            self.worst_marker.set_data([], [])
        self.title.set_text(f"worst naive normal error: {s['worst_deg']:.1f}°")
        self.info.value = s["text"]
