r"""Quadric explorer: a small ray-cast picture of a quadric (or a disk) and, beside it, the
function :math:`f(t)` along one pixel's ray, whose roots are the hits.

Every pixel's ray :math:`o + t d` is put into the quadric's :math:`\tilde x^T Q \tilde x`
(:func:`course_lib.raytracing.ray_quadratic`), giving :math:`f(t) = a t^2 + b t + c`; the
nearest root :math:`t \ge 0` whose point lies within the height :math:`|z| \le h` is the hit
(:func:`course_lib.raytracing.intersect_quadric` with ``clip=(-h, h)``), shaded by Lambert's law
with the gradient normal turned towards the eye: blue where the ray sees the outside
(:math:`f > 0` side), orange where it sees the inside through the cut. The chosen pixel is
marked by a red cross; the right panel plots its :math:`f(t)` (on an arcsinh scale), both roots
(filled: the hit; open: the other root, where the ray leaves, or a root rejected by the
height test). For the disk,
:math:`f(t) = n \cdot (o + t d - c)` is linear and its root is a hit only within the radius.
"""
from dataclasses import dataclass

import numpy as np

from .. import draw
from .. import raytracing as rt
from .._validate import as_choice
from . import _style
from ._base import Explorer, bind, labelled, panel, slider

__all__ = ["KINDS", "QuadricExplorer", "State", "scene"]

KINDS = ("sphere", "ellipsoid", "cylinder", "cone", "paraboloid", "hyperboloid1",
         "hyperboloid2", "disk")
SIZE = 96                                     # the picture is SIZE x SIZE pixels
T_MAX = 10.0                                  # the f(t) panel covers 0 <= t <= T_MAX
_EYE = np.array([3.4, -4.2, 2.3])
_LIGHT = np.array([0.2, -0.75, 0.63]) / np.linalg.norm([0.2, -0.75, 0.63])
_OUTSIDE = np.array([0.30, 0.55, 0.95])
_INSIDE = np.array([0.98, 0.62, 0.25])
_BACKGROUND = np.array([0.93, 0.93, 0.93])
_T = np.linspace(0.0, T_MAX, 241)
_RAYS = {}


def _rays():
    """The camera's ray directions (SIZE, SIZE, 3), computed once."""
    if "d" not in _RAYS:
        gaze = -_EYE / np.linalg.norm(_EYE)
        _RAYS["d"] = rt.camera_rays(_EYE, gaze, [0, 0, 1], np.radians(38), SIZE,
                                    SIZE).directions[:, :, 0]
    return _RAYS["d"]


@dataclass
class State:
    """The shape, its parameters and the pixel whose ray is plotted.

    Examples
    --------
    >>> State().kind, State().row
    ('hyperboloid1', 48)
    """

    kind: str = "hyperboloid1"
    radius: float = 0.6
    shape: float = 0.8
    height: float = 1.0
    row: int = 48
    col: int = 48


_NO_SHAPE = ("sphere", "cylinder", "disk")


def _matrix(state):
    r, s = float(state.radius), float(state.shape)
    if state.kind == "ellipsoid":
        return rt.quadric_matrix("ellipsoid", radii=(r * 1.6, r, r * s * 1.5))
    if state.kind == "paraboloid":
        return rt.quadric_matrix("paraboloid", slope=s * 1.5, center=(0, 0, -r))
    return rt.quadric_matrix(state.kind, radius=r, slope=s)


def scene(state):
    """Pure part: the shaded picture, the chosen ray's f(t), its roots and the text.

    Returns a dict with ``image`` (SIZE, SIZE, 3) RGB with the cross drawn in, ``t``
    (the hit parameter per pixel, ``inf`` for a miss), ``coefficients`` (a, b, c of the chosen
    ray; a = 0 for the disk), ``curve`` (f(t) at ``t_samples`` on
    a sign-preserving arcsinh scale within [-1, 1], the roots unmoved), ``roots``
    (real roots), ``hit`` (the chosen ray's t) and ``text``.

    Examples
    --------
    >>> s = scene(State(kind="sphere", radius=1.0, row=48, col=48))
    >>> s["image"].shape, bool(np.isfinite(s["hit"]))
    ((96, 96, 3), True)
    >>> a, b, c = s["coefficients"]
    >>> bool(np.isclose(s["hit"], (-b - np.sqrt(b * b - 4 * a * c)) / (2 * a)))
    True
    """
    kind = as_choice(state.kind, "kind", KINDS)
    h = float(state.height)
    row, col = int(state.row), int(state.col)
    if not (0 <= row < SIZE and 0 <= col < SIZE):
        raise ValueError(f"row and col must lie in [0, {SIZE - 1}], got ({row}, {col})")
    d = _rays()
    flat = d.reshape(-1, 3)
    if kind == "disk":
        centre, normal = np.zeros(3), np.array([0.0, 0.35, 1.0]) / np.hypot(0.35, 1.0)
        hits = rt.intersect_disk(_EYE, flat, centre, normal, float(state.radius))
        n = hits.normals
        outside = (n @ _EYE - n @ centre) > 0
        n = np.where(outside[:, None], n, -n)
        t = hits.t
        dk = d[row, col]
        a, b, c = 0.0, float(normal @ dk), float(normal @ (_EYE - centre))
    else:
        Q = _matrix(state)
        hits = rt.intersect_quadric(_EYE, flat, Q, clip=(-h, h))
        t, n = hits.t, hits.normals
        outside = np.einsum("ij,ij->i", n, flat) < 0          # the gradient faces the eye
        n = np.where(outside[:, None], n, -n)
        dk = d[row, col]
        a, b, c = (float(v) for v in rt.ray_quadratic(_EYE, dk, Q))
    hit = np.isfinite(t)
    lambert = 0.25 + 0.75 * np.clip(n @ _LIGHT, 0.0, 1.0)
    colour = np.where(outside[:, None], _OUTSIDE, _INSIDE) * lambert[:, None]
    image = np.where(hit[:, None], colour, _BACKGROUND).reshape(SIZE, SIZE, 3)
    _cross(image, row, col)
    t = t.reshape(SIZE, SIZE)
    t_hit = float(t[row, col])
    f = a * _T ** 2 + b * _T + c
    top = max(float(np.abs(f).max()), 1e-12)
    soft = top / 50.0                  # arcsinh: linear near the roots, compressed far away
    if a != 0:
        disc = b * b - 4 * a * c
        roots = (np.sort(np.roots([a, b, c]).real) if disc >= 0 else np.array([]))
    else:
        roots = np.array([-c / b]) if b != 0 else np.array([])
    def signed(x):
        return f"{'−' if x < 0 else '+'} {abs(x):.3f}"

    equation = (f"f(t) = n·(o + t d − c) = {b:.3f} t {signed(c)}" if kind == "disk" else
                f"f(t) = {a:.3f} t² {signed(b)} t {signed(c)}")
    text = (f"<b>{kind}</b>: radius {state.radius:.2f}, shape {state.shape:.2f}"
            + ("" if kind == "disk" else f", cut at |z| ≤ {h:.2f}")
            + f". Pixel (row {row}, column {col}): {equation}; roots "
            + (", ".join(f"{x:.3f}" for x in roots) if len(roots) else "none (no real root)")
            + ("; hit at t = " + f"{t_hit:.3f}" if np.isfinite(t_hit) else "; no hit")
            + (" (a root outside the cut or behind the eye is rejected)."
               if len(roots) and not (np.isfinite(t_hit) and np.isclose(roots, t_hit).all())
               else "."))
    return {"image": image, "t": t, "coefficients": (a, b, c), "t_samples": _T,
            "curve": np.arcsinh(f / soft) / np.arcsinh(top / soft), "roots": roots, "hit": t_hit, "text": text}


def _cross(image, row, col):
    """A red cross around pixel (row, col), leaving the pixel itself visible."""
    red = np.array([0.85, 0.1, 0.1])
    for k in (2, 3, 4):
        for r, c in ((row + k, col), (row - k, col), (row, col + k), (row, col - k)):
            if 0 <= r < SIZE and 0 <= c < SIZE:
                image[r, c] = red


class QuadricExplorer(Explorer):
    """Shape menu, radius / shape / height sliders, the chosen pixel: the picture and f(t).

    In a notebook, after ``%matplotlib widget``, end a cell with ``QuadricExplorer()``.

    Examples
    --------
    >>> explorer = QuadricExplorer()
    >>> explorer.kind.value = "cylinder"
    >>> "cylinder" in explorer.info.value
    True
    """

    summary = ("Quadric explorer (interactive): a ray-cast quadric or disk with Lambert "
               "shading, and the quadratic f(t) along one pixel's ray with its roots marked.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(7.2, 3.3))
        ax = self.fig.add_axes((0.02, 0.06, 0.44, 0.84))
        self.image = ax.imshow(s["image"], origin="lower", interpolation="nearest")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("ray cast (+ = the chosen pixel)", fontsize=9)
        fx = self.fig.add_axes((0.56, 0.16, 0.41, 0.72))
        fx.set(xlim=(0, T_MAX), ylim=(-1.1, 1.1), xlabel="t along the ray")
        fx.axhline(0.0, color="0.5", lw=0.8)
        fx.set_title("f(o + t d) (arcsinh scale): its roots", fontsize=9)
        (self.curve,) = fx.plot(s["t_samples"], s["curve"], color="C0", lw=2)
        (self.hit_mark,) = fx.plot([], [], "o", color="#c62828", ms=8, label="hit")
        (self.root_marks,) = fx.plot([], [], "o", mfc="white", mec="0.3", ms=8,
                                     label="other root")
        _style.legend(fx, loc="upper right", fontsize=7)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.image, self.curve, self.hit_mark,
                                               self.root_marks])
        self.kind = labelled(w.Dropdown, "shape", options=list(KINDS), value=self.state.kind)
        self.radius = slider("radius", self.state.radius, 0.2, 1.5, 0.05)
        self.shape = slider("shape (slope, c)", self.state.shape, 0.2, 2.0, 0.05)
        self.height = slider("cut |z| ≤ h", self.state.height, 0.2, 2.0, 0.05)
        self.row = slider("pixel row", self.state.row, 0, SIZE - 1, 1, kind=w.IntSlider)
        self.col = slider("pixel column", self.state.col, 0, SIZE - 1, 1, kind=w.IntSlider)
        bind(self.state, {"kind": self.kind, "radius": self.radius, "shape": self.shape,
                          "height": self.height, "row": self.row, "col": self.col}, self.update)
        self.info = panel(width="720px")
        self.widget = w.VBox([self.fig.canvas,
                              w.HBox([w.VBox([self.kind, self.radius, self.shape]),
                                      w.VBox([self.height, self.row, self.col])],
                                     layout=w.Layout(flex_flow="row wrap")),
                              self.info])
        self._enable()
        self._draw(s)

    def update(self):
        """Recompute the picture (the camera's rays are cached) and update the artists."""
        self._enable()
        self._draw(scene(self.state))
        self.blitter.update()

    def _enable(self):
        # a sphere, a cylinder and a disk have no second shape parameter; a disk is not cut
        self.shape.disabled = self.state.kind in _NO_SHAPE
        self.height.disabled = self.state.kind == "disk"

    def _draw(self, s):
        self.image.set_data(s["image"])
        self.curve.set_data(s["t_samples"], s["curve"])
        roots = [x for x in s["roots"] if 0 <= x <= T_MAX]
        hit = [x for x in roots if np.isclose(x, s["hit"])]
        rejected = [x for x in roots if not np.isclose(x, s["hit"])]
        self.hit_mark.set_data(hit, [0.0] * len(hit))
        self.root_marks.set_data(rejected, [0.0] * len(rejected))
        self.info.value = s["text"]
