r"""Clip before or after the divide: a segment that passes behind the eye, seen from above.

The camera sits at the origin and looks down :math:`-z` (a 90° perspective, near 1, far 6). The
segment runs from A, in front of the eye, to B, which the sliders move, also behind the eye. The
left panel shows eye coordinates from above (y = 0), the right one NDC (x and z after the
divide). Two routes: clip in clip space against :math:`-w \le x, y, z \le w`, then divide
(:func:`course_lib.clip_space.clip_segment_homogeneous`), or divide first and clip the NDC segment
to :math:`[-1, 1]^3` (:func:`course_lib.clip_space.clip_after_divide`). While B is in front of
the eye both agree; once B is behind it (w < 0), the divided B' is mirrored, and the divide-first
route keeps a piece of the segment's line that is not on the segment ("wrap-around").
"""
from dataclasses import dataclass

import numpy as np

from .. import clip_space, draw, format as fmt, transforms, viewing
from . import _style
from ._base import Explorer, align, beside, bind, panel, slider

__all__ = ["HomogeneousClipExplorer", "ROUTES", "State", "scene"]

ROUTES = ("clip space", "divide first")
CAMERA = viewing.perspective(np.radians(90), 1.0, 1.0, 6.0)
_INVERSE = np.linalg.inv(CAMERA)
_SAMPLES = np.linspace(0.0, 1.0, 241)
_CLIP, _WRONG = "C0", "#c62828"


@dataclass
class State:
    """A's x, B's x and z (eye coordinates, y = 0), and the route shown in bold.

    Examples
    --------
    >>> State().route
    'clip space'
    """

    a_x: float = 1.5
    b_x: float = -3.0
    b_z: float = 1.5
    route: str = "clip space"


def _to_eye(ndc_points):
    return transforms.apply(_INVERSE, ndc_points)


def scene(state):
    """Pure part: the segment, both routes' results in eye coordinates and NDC, and the text.

    Returns
    -------
    dict
        ``a``, ``b`` (eye coordinates), ``w`` (their clip-space w), ``clip_eye`` and
        ``divide_eye`` (the part each route keeps, mapped back to eye coordinates, 2x3, or
        None), ``images`` (NDC images of the segment's points with w > 0, k x 3, NaN between
        pieces), ``ndc_ends`` (A' and B', 2x3; B' NaN when w = 0 at B), ``clip_ndc``,
        ``divide_ndc`` (2x3 or None), ``crosses`` (w changes sign), ``route`` and ``text``.

    Examples
    --------
    >>> s = scene(State(b_z=-5.0))              # B in front of the eye: the routes agree
    >>> bool(np.allclose(s["clip_ndc"], s["divide_ndc"]))
    True
    >>> s = scene(State())                      # B behind the eye: they do not
    >>> s["crosses"], bool(np.allclose(s["clip_eye"], s["divide_eye"]))
    (True, False)
    """
    if state.route not in ROUTES:
        raise ValueError(f"route must be one of {ROUTES}, got {state.route!r}")
    a = np.array([float(state.a_x), 0.0, -3.0])
    b = np.array([float(state.b_x), 0.0, float(state.b_z)])
    ah, bh = CAMERA @ [*a, 1.0], CAMERA @ [*b, 1.0]
    result = clip_space.clip_segment_homogeneous(ah, bh)
    right = result["clipped"]
    clip_ndc = None if right is None else np.array([p[:3] / p[3] for p in right])
    # t is also the parameter of the eye-space segment (the matrix is linear)
    clip_eye = None if right is None else a + np.array(
        [result["t_in"], result["t_out"]])[:, None] * (b - a)
    if bh[3] == 0:
        divide_ndc, ndc_ends = None, np.array([ah[:3] / ah[3], [np.nan] * 3])
    else:
        wrong = clip_space.clip_after_divide(ah, bh)
        divide_ndc, ndc_ends = wrong["clipped"], wrong["ndc"]
    divide_eye = None if divide_ndc is None else _to_eye(divide_ndc)
    h = ah + _SAMPLES[:, None] * (bh - ah)
    front = h[:, 3] > 0.05
    images = np.where(front[:, None], h[:, :3] / np.where(front, h[:, 3], 1.0)[:, None], np.nan)
    crosses = bool(ah[3] * bh[3] < 0)
    text = _text(state.route, ah[3], bh[3], crosses, clip_eye, divide_eye)
    return {"a": a, "b": b, "w": (float(ah[3]), float(bh[3])), "clip_eye": clip_eye,
            "divide_eye": divide_eye, "images": images, "ndc_ends": ndc_ends,
            "clip_ndc": clip_ndc, "divide_ndc": divide_ndc, "crosses": crosses,
            "route": state.route, "text": text}


def _points(p):
    return "none" if p is None else " to ".join(
        f"({fmt.number(q[0], 2)}, {fmt.number(q[2], 2)})" for q in p)


def _text(route, wa, wb, crosses, clip_eye, divide_eye):
    head = f"w at A = {fmt.number(wa, 2)}, w at B = {fmt.number(wb, 2)}. "
    if wb == 0:
        head += "B lies on the eye plane (w = 0): it cannot be divided at all. "
    elif crosses:
        head += ("B is <b>behind the eye</b> (w < 0): dividing mirrors it through the centre, "
                 "and the NDC segment A'B' is the image of the line's other part, through "
                 "infinity. ")
    else:
        head += "Both ends are in front of the eye: the two routes agree. "
    kept = (f"Clip space keeps (x, z) {_points(clip_eye)}; divide first keeps "
            f"{_points(divide_eye)}.")
    if route == "clip space":
        note = ("<b>Shown: clip in clip space, then divide</b> (right): −w ≤ x, y, z ≤ w are "
                "linear, and no point with w ≤ 0 passes.")
    else:
        note = ("<b>Shown: divide first, then clip in NDC</b>"
                + (" (wrong here: the red piece is not on the segment)." if crosses
                   and divide_eye is not None else "."))
    return head + "<br>" + kept + "<br>" + note


class HomogeneousClipExplorer(Explorer):
    """Move B behind the eye and compare clipping in clip space with clipping after the divide.

    In a notebook, after ``%matplotlib widget``, end a cell with ``HomogeneousClipExplorer()``.

    Examples
    --------
    >>> explorer = HomogeneousClipExplorer()
    >>> explorer.route.value = "divide first"
    >>> "divide first" in explorer.info.value
    True
    """

    summary = ("Clip before or after the divide (interactive): a segment from a point in front "
               "of the eye to one behind it, clipped in clip space and after the divide, in "
               "eye coordinates and in NDC.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        self.fig = draw.figure(figsize=(7.4, 3.7))
        left = self.fig.add_subplot(1, 2, 1)
        right = self.fig.add_subplot(1, 2, 2)
        self.fig.subplots_adjust(left=0.08, right=0.98, bottom=0.13, top=0.91, wspace=0.25)
        top = transforms.apply(_INVERSE, [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]])
        left.fill(top[:, 0], top[:, 2], color="#e8f3e8", zorder=0)
        left.axhline(0, color="0.3", lw=0.8)
        left.plot(0, 0, "k^", ms=7)
        left.text(5.7, 0.3, "eye plane w = 0", ha="right", fontsize=_style.ANNOTATION)
        left.set(xlim=(-6, 6), ylim=(-10, 4), aspect="equal", xlabel="x (eye)",
                 ylabel="z (eye)", title="eye coordinates, from above")
        right.fill([-1, 1, 1, -1], [-1, -1, 1, 1], color="#e8f3e8", zorder=0)
        right.set(xlim=(-3, 3), ylim=(-3, 3), aspect="equal", xlabel="x (NDC)",
                  ylabel="z (NDC)", title="NDC, after the divide")
        (self.line,) = left.plot([], [], ":", color="0.6", lw=0.8)
        (self.segment,) = left.plot([], [], "--", color="0.35", lw=1.2)
        (self.ends,) = left.plot([], [], "o", color="0.2", ms=5)
        (self.clip_eye,) = left.plot([], [], color=_CLIP, lw=4, solid_capstyle="butt")
        (self.divide_eye,) = left.plot([], [], color=_WRONG, lw=4, solid_capstyle="butt")
        (self.images,) = right.plot([], [], color=_CLIP, lw=1, alpha=1.0)
        (self.chord,) = right.plot([], [], "--", color=_WRONG, lw=1)
        (self.ndc_ends,) = right.plot([], [], "o", color="0.2", ms=5)
        (self.clip_ndc,) = right.plot([], [], color=_CLIP, lw=4, solid_capstyle="butt")
        (self.divide_ndc,) = right.plot([], [], color=_WRONG, lw=4, solid_capstyle="butt")
        self.labels = [axes.text(0, 0, name, fontsize=_style.ANNOTATION, clip_on=True)
                       for axes, name in ((left, "A"), (left, "B"), (right, "A'"),
                                          (right, "B'"))]
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [self.line, self.segment, self.ends,
                                               self.clip_eye, self.divide_eye, self.images,
                                               self.chord, self.ndc_ends, self.clip_ndc,
                                               self.divide_ndc, *self.labels])
        self.a_x = slider("A: x", self.state.a_x, -2.5, 2.5, 0.1)
        self.b_x = slider("B: x", self.state.b_x, -5.0, 5.0, 0.1)
        self.b_z = slider("B: z", self.state.b_z, -8.0, 3.5, 0.1)
        align([self.a_x, self.b_x, self.b_z])
        self.route = w.ToggleButtons(options=ROUTES, value=self.state.route,
                                     style={"button_width": _style.button_width(*ROUTES)})
        bind(self.state, {"a_x": self.a_x, "b_x": self.b_x, "b_z": self.b_z,
                          "route": self.route}, self.update)
        self.info = panel(width="330px")
        self.widget = beside(self.fig.canvas, w.VBox([self.route, self.a_x, self.b_x,
                                                      self.b_z, self.info]))
        self._draw(scene(self.state))

    def update(self):
        """Recompute the scene and move the drawn artists."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        a, b = s["a"], s["b"]
        far = a + np.array([-4.0, 4.0])[:, None] * (b - a)
        self.line.set_data(far[:, 0], far[:, 2])
        self.segment.set_data([a[0], b[0]], [a[2], b[2]])
        self.ends.set_data([a[0], b[0]], [a[2], b[2]])
        clip_first = s["route"] == "clip space"
        for artist, points, bold in ((self.clip_eye, s["clip_eye"], clip_first),
                                     (self.divide_eye, s["divide_eye"], not clip_first),
                                     (self.clip_ndc, s["clip_ndc"], clip_first),
                                     (self.divide_ndc, s["divide_ndc"], not clip_first)):
            artist.set_data(*((points[:, 0], points[:, 2]) if points is not None
                              else ([], [])))
            artist.set_linewidth(5 if bold else 1.5)
        self.images.set_data(s["images"][:, 0], s["images"][:, 2])
        ends = s["ndc_ends"]
        self.chord.set_data(ends[:, 0], ends[:, 2])
        self.ndc_ends.set_data(ends[:, 0], ends[:, 2])
        for label, p in zip(self.labels, [a, b, *ends]):
            label.set_position((p[0] + 0.15, p[2] + 0.15) if np.isfinite(p).all()
                               else (np.nan, np.nan))
        self.info.value = s["text"]
