r"""Transformation composer: build a 2D transformation from a list of basic ones.

The student lists operations (translate, rotate, scale, shear, mirror, rotate about a point),
each with its sliders. The F is drawn after every step, the composed matrix
:math:`M = M_n \cdots M_2 M_1` is printed (the operation applied first stands rightmost), and a
toggle applies the same operations in the reverse order: the result moves, because matrix
products do not commute. The result of the other order stays on the figure as a dashed outline.
"""
import re
from dataclasses import dataclass, field

import numpy as np

from .. import draw, format as fmt, shapes, transforms
from .._validate import as_choice
from . import _style
from ._base import Explorer, beside, labelled, panel

__all__ = ["ComposerExplorer", "OPERATIONS", "Operation", "State", "scene"]

MAX_OPERATIONS = 5
SHAPE = shapes.letter_f()


def _deg(x):
    return np.radians(x)


#: kind -> (parameter labels, slider ranges, default values, matrix builder, LaTeX name)
OPERATIONS = {
    "translate": (("dx", "dy"), ((-3, 3), (-3, 3)), (2.0, 0.5),
                  lambda a, b: transforms.translate([a, b]),
                  lambda a, b: f"T({fmt.number(a, 2)}, {fmt.number(b, 2)})"),
    "rotate": (("θ °",), ((-180, 180),), (45.0,),
               lambda a: transforms.rotate(_deg(a)),
               lambda a: f"R({fmt.number(a, 1)}°)"),
    "scale": (("sx", "sy"), ((-2, 2), (-2, 2)), (1.5, 1.0),
              lambda a, b: transforms.scale([a, b]),
              lambda a, b: f"S({fmt.number(a, 2)}, {fmt.number(b, 2)})"),
    "shear x": (("a",), ((-2, 2),), (0.5,),
                lambda a: transforms.shear_x(a),
                lambda a: f"SH_x({fmt.number(a, 2)})"),
    "shear y": (("b",), ((-2, 2),), (0.5,),
                lambda b: transforms.shear_y(b),
                lambda b: f"SH_y({fmt.number(b, 2)})"),
    "mirror about x": ((), (), (), lambda: transforms.mirror("x"), lambda: "S(1, -1)"),
    "mirror about y": ((), (), (), lambda: transforms.mirror("y"), lambda: "S(-1, 1)"),
    "rotate about point": (("θ °", "cx", "cy"), ((-180, 180), (-3, 3), (-3, 3)),
                           (90.0, 1.0, 1.0),
                           lambda a, cx, cy: transforms.rotate_about(_deg(a), [cx, cy]),
                           lambda a, cx, cy: (f"R_{{({fmt.number(cx, 2)}, {fmt.number(cy, 2)})}}"
                                              f"({fmt.number(a, 1)}°)")),
}


@dataclass
class Operation:
    """One step: its kind (a key of OPERATIONS) and its parameters (defaults if omitted).

    Examples
    --------
    >>> Operation("translate", (1, 2)).latex()
    'T(1, 2)'
    >>> Operation("rotate").params
    (45.0,)
    """

    kind: str
    params: tuple = None

    def __post_init__(self):
        as_choice(self.kind, "kind", list(OPERATIONS))
        defaults = OPERATIONS[self.kind][2]
        self.params = tuple(defaults if self.params is None else self.params)
        if len(self.params) != len(defaults):
            raise ValueError(f"a {self.kind} operation takes {len(defaults)} parameters "
                             f"({', '.join(OPERATIONS[self.kind][0]) or 'none'}), "
                             f"got {len(self.params)}")

    def matrix(self):
        """The operation's 3x3 homogeneous matrix.

        Examples
        --------
        >>> Operation("scale", (2, 3)).matrix()
        array([[2., 0., 0.],
               [0., 3., 0.],
               [0., 0., 1.]])
        """
        return OPERATIONS[self.kind][3](*self.params)

    def html(self):
        """The operation's name with its parameters in HTML, e.g. ``SH<sub>x</sub>(0.5)``.

        Examples
        --------
        >>> Operation("rotate about point", (90, 1, 1)).html()
        'R<sub>(1, 1)</sub>(90°)'
        """
        name = self.latex()
        name = re.sub(r"_\{(.*?)\}", r"<sub>\1</sub>", name)
        return re.sub(r"_(\w)", r"<sub>\1</sub>", name).replace("-", "\u2212")

    def latex(self):
        """The operation's name with its parameters, e.g. ``T(2, 0.5)``.

        Examples
        --------
        >>> Operation("shear x", (0.5,)).latex()
        'SH_x(0.5)'
        """
        return OPERATIONS[self.kind][4](*self.params)


def _default_operations():
    return [Operation("translate"), Operation("rotate")]


@dataclass
class State:
    """The list of operations, in the order they are listed, and the order toggle.

    Examples
    --------
    >>> [op.kind for op in State().operations]
    ['translate', 'rotate']
    """

    operations: list = field(default_factory=_default_operations)
    reverse: bool = False


def scene(state):
    """Pure part: state -> the F after each step, the composed matrix and its formula.

    Returns
    -------
    dict
        ``original`` (the F), ``steps`` (the F after each applied operation, the last one is
        the result), ``labels`` (the LaTeX name of each applied operation), ``matrix`` (the
        composed 3x3 matrix), ``other_matrix`` and ``other_result`` (the same operations in
        the other order), ``commute`` (whether both orders give the same matrix) and ``text``
        (the formula, HTML with LaTeX).

    Examples
    --------
    >>> s = scene(State([Operation("translate", (1, 0)), Operation("rotate", (90,))]))
    >>> s["matrix"].round(12) + 0.0              # R(90°) T(1, 0): the rotation acts last
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  1.],
           [ 0.,  0.,  1.]])
    >>> s["commute"]
    False
    """
    ops = list(reversed(state.operations)) if state.reverse else list(state.operations)
    matrices = [op.matrix() for op in ops]
    steps, current = [], np.eye(3)
    for m in matrices:
        current = m @ current
        steps.append(transforms.apply(current, SHAPE))
    if matrices:
        composed = transforms.compose(*matrices)
        other = transforms.compose(*matrices[::-1])
    else:
        composed = other = np.eye(3)
    labels = [op.latex() for op in ops]
    names = [op.html() for op in ops]
    commute = bool(np.allclose(composed, other))
    product = "&thinsp;".join(reversed(names)) if names else "I"
    order = "listed order reversed" if state.reverse else "listed order"
    text = (f"Applied in the {order}, first to last: {', '.join(names) or 'nothing'}.<br>"
            f"<i>M</i> = {product} = {fmt.matrix_html(composed, 2)}<br>"
            + ("The other order gives the <i>same</i> matrix: these operations commute."
               if commute else
               f"The other order gives <i>M′</i> = {fmt.matrix_html(other, 2)} ≠ <i>M</i> "
               "(dashed outline): matrix products do not commute."))
    return {"original": SHAPE, "steps": steps, "labels": labels, "matrix": composed,
            "other_matrix": other, "other_result": transforms.apply(other, SHAPE),
            "commute": commute, "text": text}


class _Row:
    """The controls of one operation: kind menu, up to three sliders, up and remove buttons."""

    def __init__(self, composer, operation):
        import ipywidgets as w

        self.composer = composer
        self.kind = w.Dropdown(options=list(OPERATIONS), value=operation.kind,
                               layout=w.Layout(width="165px"))
        names = [name for spec in OPERATIONS.values() for name in spec[0]]
        self.sliders = [labelled(w.FloatSlider, "", _style.label_width(*names, minimum=32),
                                 body=180, step=0.05, continuous_update=True,
                                 readout_format=".2f") for _ in range(3)]
        self.up = w.Button(icon="arrow-up", tooltip="move up", layout=w.Layout(width="34px"))
        self.remove = w.Button(icon="times", tooltip="remove", layout=w.Layout(width="34px"))
        self._configure(operation.kind, operation.params)
        self.kind.observe(self._on_kind, names="value")
        for s in self.sliders:
            s.observe(self._on_value, names="value")
        self.up.on_click(lambda _: composer.move_up(self))
        self.remove.on_click(lambda _: composer.remove(self))
        self.box = w.HBox([self.kind, *self.sliders, self.up, self.remove])

    def _configure(self, kind, params):
        labels, ranges, _, _, _ = OPERATIONS[kind]
        self._configuring = True
        for k, slider in enumerate(self.sliders):
            if k < len(labels):
                # one message to the browser: a value sent before its new range would be
                # clipped there to the old range and sent back (choosing "rotate" after a shear
                # gave 2° instead of 45°)
                with slider.hold_sync():
                    slider.description = labels[k]
                    slider.min, slider.max = -1e9, 1e9          # never clip while switching
                    slider.value = params[k]
                    slider.min, slider.max = ranges[k]
                    slider.step = 1.0 if "°" in labels[k] else 0.05
                slider.layout.display = None
            else:
                slider.layout.display = "none"
        self._configuring = False

    def operation(self):
        n = len(OPERATIONS[self.kind.value][0])
        return Operation(self.kind.value, tuple(s.value for s in self.sliders[:n]))

    def _on_kind(self, change):
        self._configure(change["new"], OPERATIONS[change["new"]][2])
        self.composer.refresh()

    def _on_value(self, change):
        if not self._configuring:
            self.composer.refresh()


class ComposerExplorer(Explorer):
    """A list of 2D operations with sliders, the F after each step and the composed matrix.

    In a notebook, after ``%matplotlib widget``, end a cell with ``ComposerExplorer()``.

    Examples
    --------
    >>> explorer = ComposerExplorer()
    >>> explorer.add("scale", (2, 2))       # what the "add operation" button does
    >>> [op.kind for op in explorer.state.operations]
    ['translate', 'rotate', 'scale']
    >>> explorer.reverse.value = True       # apply them in the reverse order
    >>> bool(scene(explorer.state)["commute"])
    False
    """

    summary = ("Transformation composer (interactive): a list of 2D operations with sliders, "
               "the F after each step, the composed matrix, and a toggle that reverses the "
               "order.")

    def __init__(self, state=None):
        import ipywidgets as w

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(4.6, 4.6))
        ax = self.fig.add_subplot()
        self.fig.subplots_adjust(left=0.12, right=0.98, bottom=0.1, top=0.94)
        draw.setup_axes_2d(ax, (-4.5, 4.5), title="M = Mₙ ⋯ M₂ M₁ (rightmost first)")
        ax.plot(*SHAPE.T, color="0.45", lw=1.2, ls="--", label="original")
        self.step_lines, self.step_labels = [], []
        for _ in range(MAX_OPERATIONS - 1):
            (line,) = ax.plot([], [], color="C0", lw=0.9, alpha=0.45)
            self.step_lines.append(line)
        for _ in range(MAX_OPERATIONS):
            self.step_labels.append(ax.text(0, 0, "", color="C0", fontsize=_style.ANNOTATION,
                                            ha="center",
                                            va="center", weight="bold"))
        (self.other,) = ax.plot([], [], color="C1", lw=1.5, ls="--", label="other order")
        (self.result,) = ax.fill(SHAPE[:, 0], SHAPE[:, 1], facecolor=(0.12, 0.47, 0.71, 0.35),
                                 edgecolor="C0", lw=2.2, label="result")
        _style.legend(ax, loc="lower left", borderpad=0.3, labelspacing=0.25, handlelength=1.5)
        _style.style_figure(self.fig)
        self.blitter = draw.Blitter(self.fig, [*self.step_lines, *self.step_labels, self.other,
                                               self.result])

        self.rows = []
        self.rows_box = w.VBox([])
        self.add_button = w.Button(description="add operation", icon="plus",
                                   layout=w.Layout(width=_style.button_width("add operation__")))
        self.add_button.on_click(lambda _: self.add())
        self.reverse = w.ToggleButton(value=self.state.reverse,
                                      description="apply in reverse order", icon="exchange",
                                      layout=w.Layout(
                                          width=_style.button_width("apply in reverse order__")))
        self.reverse.observe(lambda _: self.refresh(), names="value")
        self.info = panel(s["text"], width="500px")
        for op in self.state.operations:
            self._append_row(op)
        self.widget = w.VBox([self.rows_box, w.HBox([self.add_button, self.reverse]),
                              beside(self.fig.canvas, self.info)])
        self._draw(s)

    # --- list editing -----------------------------------------------------------------------
    def _append_row(self, operation):
        row = _Row(self, operation)
        self.rows.append(row)
        self._show_rows()
        self.add_button.disabled = len(self.rows) >= MAX_OPERATIONS

    def add(self, kind="scale", params=None):
        """Append an operation (what the "add operation" button does)."""
        if len(self.rows) >= MAX_OPERATIONS:
            return
        self._append_row(Operation(kind, params))
        self.refresh()

    def remove(self, row):
        """Remove an operation from the list."""
        self.rows.remove(row)
        self._show_rows()
        self.add_button.disabled = False
        self.refresh()

    def move_up(self, row):
        """Swap an operation with the one before it."""
        k = self.rows.index(row)
        if k > 0:
            self.rows[k - 1], self.rows[k] = self.rows[k], self.rows[k - 1]
            self._show_rows()
            self.refresh()

    def _show_rows(self):
        self.rows_box.children = [r.box for r in self.rows]
        for k, row in enumerate(self.rows):           # the first operation cannot move up
            row.up.layout.visibility = "hidden" if k == 0 else "visible"

    def refresh(self):
        """Read the controls into the state and update the picture."""
        self.state.operations = [row.operation() for row in self.rows]
        self.state.reverse = self.reverse.value
        self.update()

    # --- drawing ----------------------------------------------------------------------------
    def update(self):
        """Recompute the scene and move the drawn artists (no re-plotting)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        steps = s["steps"]
        for k, line in enumerate(self.step_lines):
            if k < len(steps) - 1:
                line.set_data(*steps[k].T)
            else:
                line.set_data([], [])
        for k, label in enumerate(self.step_labels):
            if k < len(steps):
                x, y = steps[k][:-1].mean(axis=0)
                label.set_position((x, y))
                label.set_text(str(k + 1))
            else:
                label.set_text("")
        result = steps[-1] if steps else SHAPE
        self.result.set_xy(result)
        if s["commute"] or not steps:
            self.other.set_data([], [])
        else:
            self.other.set_data(*s["other_result"].T)
        self.info.value = s["text"]
