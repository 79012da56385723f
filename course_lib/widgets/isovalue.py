r"""Isovalue explorers: marching squares on a 2D field with its cell cases, and marching cubes
in 3D.

**Isolines** (:class:`IsolineExplorer`). A coarse 2D field is sampled on a grid; every sample is
*above* the isovalue c (:math:`f \ge c`, a filled dot) or *below* (a hollow dot). Each cell
reads its four corners as a 4-bit case number (drawn in the cell), the 16-case table (the
legend on the right, with the cases present highlighted) says which cell edges the isoline
crosses, and linear interpolation along those edges places the points
(:func:`course_lib.scivis.marching_squares`). Cases 5 and 10 are **saddles**: the table cannot
tell whether the two above corners are joined through the cell or separated. The cells are
shaded orange; the midpoint decider (the mean of the four corners stands for the centre value)
picks one pairing, drawn solid, the other one dashed. The thin grey line is the isoline of the
bilinear interpolant of the samples, traced on a grid eight times finer: marching squares is its
straight-line approximation, and where the midpoint decider and the true topology of the
interpolant disagree, you see it.

**Isosurfaces** (:class:`IsosurfaceExplorer`). The same in 3D with
:func:`course_lib.scivis.marching_cubes`, rendered by pyvista off screen: outward faces (normals
towards lower values) gold, inner faces blue. The explorer counts vertices V, edges E and
triangles F, the Euler characteristic :math:`\chi = V - E + F` (2 per sphere-like closed
surface, 0 for a torus) and the **boundary edges**, used by one triangle only: holes, since the
surfaces here never reach the volume's border. Our table resolves ambiguous faces consistently
(the asymptotic decider) and has none; switch to the **classic table**, which decides each cube
on its own (``marching_cubes(..., table="classic")``, :func:`classic_marching_cubes`), and on
the noisy volume holes appear, drawn in red.
"""
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import draw, scivis
from .._validate import as_choice
from . import _style
from ._base import (Explorer, PlotterExplorer, align, beside, bind,
                    checkbox, labelled, nice_step, panel, pyvista_faces, set_range, slider)

__all__ = ["FIELDS", "IsolineExplorer", "IsosurfaceExplorer", "State", "State3D", "VOLUMES",
           "alternative_segments", "classic_marching_cubes", "example_data", "example_volume",
           "mesh_summary", "scene", "scene_3d"]

FIELDS = ("egg crate", "saddle", "hills", "ripple", "circle")
VOLUMES = ("blobs", "torus", "sphere", "noise", "ct")
TABLES = ("consistent", "classic")
MAX_SIZE = 24
FINE = 8                       # samples per cell edge for the bilinear interpolant's isoline
CORNERS = np.array([[0, 0], [1, 0], [1, 1], [0, 1]])       # (x, y) offsets of corners 0-3


@lru_cache(maxsize=None)
def example_data(kind="egg crate", size=12):
    """A 2D field on [-1, 1]^2 with `size` x `size` samples, for the isoline explorer.

    ``"egg crate"`` is :math:`\\sin(2.3 \\pi x + 0.5) \\sin(2.3 \\pi y + 0.9)`, a grid of bumps
    and pits with saddles between them (ambiguous cells at many levels); ``"saddle"`` is the
    single saddle :math:`2 (x - 0.13)(y + 0.08)`; the others come from
    :func:`course_lib.scivis.example_field_2d`.

    Returns
    -------
    course_lib.scivis.Field
        Cached: do not modify it.

    Examples
    --------
    >>> f = example_data("saddle", 5)
    >>> f.values.shape, f.spacing
    ((5, 5), (0.5, 0.5))
    """
    if kind in ("egg crate", "saddle"):
        axis = np.linspace(-1.0, 1.0, size)
        x, y = np.meshgrid(axis, axis)
        if kind == "egg crate":
            values = np.sin(2.3 * np.pi * x + 0.5) * np.sin(2.3 * np.pi * y + 0.9)
        else:
            values = 2.0 * (x - 0.13) * (y + 0.08)
        h = 2.0 / (size - 1)
        field = scivis.Field(values, (h, h), (-1.0, -1.0), 0.0)
    elif kind in FIELDS:
        field = scivis.example_field_2d(kind, size=size)
    else:
        raise ValueError(f"kind must be one of {FIELDS}, got {kind!r}")
    field.values.flags.writeable = False
    return field


@dataclass
class State:
    """The field, its resolution, the isovalue, and whether case numbers are drawn.

    Examples
    --------
    >>> State().field, State().size, State().level
    ('egg crate', 12, 0.1)
    """

    field: str = "egg crate"
    size: int = 12
    level: float = 0.1
    show_cases: bool = True


def alternative_segments(field, level, spacing=(1.0, 1.0), origin=(0.0, 0.0)):
    """In each saddle cell (case 5 or 10), the segments of the pairing the decider rejected.

    Where :func:`course_lib.scivis.marching_squares` (midpoint decider) joins the two above
    corners through the cell, these segments separate them, and the other way round: the
    other reading of the same four corner values. That is marching squares with
    ``saddles="opposite"`` over the saddle cells only (``cells``).

    Returns
    -------
    ndarray, shape (m, 2, 2)
        Two segments per saddle cell, (start, end) as (x, y).

    Examples
    --------
    Corners 0 and 2 above 1 (case 5), mean 1.5 >= 1: the decider joins them through the
    centre; the rejected pairing cuts off corners 0 and 2 separately:

    >>> alternative_segments([[3, 0], [0, 3]], 1.0)
    array([[[0.66666667, 0.        ],
            [0.        , 0.66666667]],
    <BLANKLINE>
           [[0.33333333, 1.        ],
            [1.        , 0.33333333]]])
    """
    cases = scivis.marching_squares_cases(field, level)
    return scivis.marching_squares(field, level, spacing, origin, saddles="opposite",
                                   cells=(cases == 5) | (cases == 10))


def scene(state):
    """Pure part: classified samples, cell cases, isoline segments, saddles and the reference.

    Returns
    -------
    dict
        ``field`` (the :class:`course_lib.scivis.Field`), ``above`` and ``below`` ((k, 2) sample
        positions), ``cases`` (the (ny-1, nx-1) case numbers), ``labels`` (the crossed cells:
        centre (x, y) and case number), ``segments`` (marching squares, (m, 2, 2)),
        ``saddles`` (the saddle cells as closed squares, (s, 5, 2)), ``centre_above`` (the
        midpoint decider's answer per saddle cell), ``alternative`` (the rejected pairings),
        ``reference`` (segments of the bilinear interpolant's isoline), ``counts`` (cells per
        case 0-15) and ``text``.

    Examples
    --------
    >>> s = scene(State())
    >>> s["cases"].shape, int(s["counts"].sum()), len(s["saddles"]) > 0
    ((11, 11), 121, True)
    """
    data = example_data(state.field, int(state.size))
    f, (dx, dy), (x0, y0) = data.values, data.spacing, data.origin
    c = float(state.level)
    xs, ys = data.axes
    X, Y = np.meshgrid(xs, ys)
    above = f >= c
    cases = scivis.marching_squares_cases(f, c)
    segments = scivis.marching_squares(f, c, data.spacing, data.origin)
    crossed_i, crossed_j = np.nonzero((cases != 0) & (cases != 15))
    labels = (np.column_stack([x0 + (crossed_j + 0.5) * dx, y0 + (crossed_i + 0.5) * dy]),
              cases[crossed_i, crossed_j])
    si, sj = np.nonzero((cases == 5) | (cases == 10))
    square = np.vstack([CORNERS, CORNERS[:1]]) * [dx, dy]
    saddles = np.array([[x0 + j * dx, y0 + i * dy] + square for i, j in zip(si, sj)])
    centre_above = scivis.saddle_centre_above(f, c)[si, sj]
    n = (len(xs) - 1) * FINE + 1
    fine_x, fine_y = np.meshgrid(np.linspace(xs[0], xs[-1], n), np.linspace(ys[0], ys[-1], n))
    fine = scivis.multilinear_interpolate(f, np.stack([fine_x, fine_y], axis=-1),
                                          data.spacing, data.origin)
    reference = scivis.marching_squares(fine, c, (dx / FINE, dy / FINE), data.origin)
    counts = np.bincount(cases.ravel(), minlength=16)
    present = ", ".join(f"{k}×{counts[k]}" for k in range(1, 15) if counts[k])
    text = (f"<b>Isovalue c = {c:.3f}</b>: {int(above.sum())} of {above.size} samples are "
            f"above (f ≥ c, filled dots). {len(labels[1])} of {cases.size} cells are crossed "
            f"(cases 1-14; as case × cells: {present or 'none'}), giving "
            f"{len(segments)} segments.")
    if len(si):
        joined = int(centre_above.sum())
        text += (f" <b>{len(si)} saddle cell(s)</b> (cases 5 and 10, orange): the midpoint "
                 f"decider found the centre above c in {joined} of them and joined the above "
                 f"corners through the cell there, and separated them in the other "
                 f"{len(si) - joined}; the dashed lines are the rejected pairing.")
    else:
        text += " No saddle cells at this isovalue: every case has a single reading."
    text += (" Grey: the isoline of the bilinear interpolant of the samples (traced on a grid "
             f"{FINE} times finer).")
    return {"field": data, "above": np.column_stack([X[above], Y[above]]),
            "below": np.column_stack([X[~above], Y[~above]]), "cases": cases,
            "labels": labels, "segments": segments,
            "saddles": saddles.reshape(-1, 5, 2), "centre_above": centre_above,
            "alternative": alternative_segments(f, c, data.spacing, data.origin),
            "reference": reference, "counts": counts, "text": text}


@lru_cache(maxsize=None)
def _level_step(field):
    """The isovalue slider's step for `field`: one per field, whatever its resolution."""
    values = example_data(field, MAX_SIZE).values
    return nice_step(values.max() - values.min())


def _draw_case_table(ax):
    """The 16 cases as small tiles (4 x 4): corners, the table's segments and the number.

    Drawn as a few collections, not one artist per line, dot and number: the explorer's tile
    highlights lie under the table, so the table is redrawn over them at every update (the
    blitter's overlays), and 100-odd artists cost about 5 ms of every frame.

    Returns the tiles' squares (16, 5, 2) in the legend axes' coordinates."""
    from matplotlib.collections import LineCollection

    mids = 0.5 * (CORNERS + np.roll(CORNERS, -1, axis=0))        # edge k's midpoint
    tiles, solid, dashed, dots, filled = [], [], [], [], []
    for case in range(16):
        col, row = case % 4, 3 - case // 4
        origin = np.array([col * 1.5, row * 1.5])
        tiles.append(origin + np.vstack([CORNERS, CORNERS[:1]]))
        solid += [origin + np.array([mids[a], mids[b]]) for a, b in scivis.SQUARE_TABLE[case]]
        dashed += [origin + np.array([mids[a], mids[b]])
                   for a, b in scivis.SQUARE_SADDLES_CENTRE_ABOVE.get(case, ())]
        dots += [origin + CORNERS[k] for k in range(4)]
        filled += [bool((case >> k) & 1) for k in range(4)]
    ax.add_collection(LineCollection(tiles, colors="0.6", linewidths=0.8))
    ax.add_collection(LineCollection(solid, colors="#1f5fbf", linewidths=1.6))
    ax.add_collection(LineCollection(dashed, colors="#1f5fbf", linewidths=1.0,
                                     linestyles="--"))
    dots, filled = np.array(dots), np.array(filled)
    ax.scatter(*dots.T, s=4 ** 2, c=np.where(filled, "0.15", "white"), edgecolors="0.15",
               linewidths=0.8, zorder=2)
    # the case numbers: bold digits as flattened markers (draw.text_marker), as tall as
    # annotation-sized text (a marker's size is its larger side, the width of two digits)
    digit = 0.75 * _style.ANNOTATION
    for case in range(16):
        col, row = case % 4, 3 - case // 4
        number = draw.text_marker(rf"\mathbf{{{case}}}")
        ax.scatter([col * 1.5 + 0.5], [row * 1.5 + 0.5], marker=number,
                   s=(digit / number.get_extents().height) ** 2, color="0.1", linewidths=0,
                   zorder=3)
    ax.set(xlim=(-0.3, 5.8), ylim=(-0.3, 5.8), aspect="equal")
    ax.set_axis_off()
    ax.set_title("the 16 cases (dot = above)\ndashed: the saddles'\nother pairing",
                 fontsize=_style.ANNOTATION)
    return np.array(tiles)


class IsolineExplorer(Explorer):
    """Marching squares: move the isovalue, change the field and its resolution.

    In a notebook, after ``%matplotlib widget``, end a cell with ``IsolineExplorer()``.

    Examples
    --------
    >>> explorer = IsolineExplorer()
    >>> explorer.level.value = 0.5
    >>> "c = 0.500" in explorer.info.value
    True
    >>> explorer.size.value = 8
    >>> explorer.state.size
    8
    """

    summary = ("Isoline explorer (interactive): marching squares on a coarse field, with the "
               "case number of every crossed cell, the 16-case table, and the saddle cells "
               "resolved by the midpoint decider.")

    def __init__(self, state=None):
        import ipywidgets as w
        from matplotlib.collections import LineCollection, PolyCollection

        self.state = state or State()
        s = scene(self.state)
        self.fig = draw.figure(figsize=(6.6, 4.1))
        grid = self.fig.add_gridspec(1, 2, width_ratios=(3.0, 1.55), left=0.085, right=0.995,
                                     bottom=0.11, top=0.93, wspace=0.04)
        ax = self.fig.add_subplot(grid[0])
        ax.set(xlim=(-1.08, 1.08), ylim=(-1.08, 1.08), aspect="equal", xlabel="x", ylabel="y")
        ax.set_title("marching squares")
        _style.style_axes(ax)
        self.ax = ax
        self.image = ax.imshow(s["field"].values, origin="lower", cmap="viridis", alpha=0.35,
                               extent=(-1, 1, -1, 1), interpolation="bilinear", zorder=0)
        self.grid_lines = LineCollection([], colors="0.7", linewidths=0.6, zorder=1)
        ax.add_collection(self.grid_lines)
        self.saddle_cells = PolyCollection([], facecolors="#ffb74d", edgecolors="#e65100",
                                           alpha=0.6, zorder=2)
        ax.add_collection(self.saddle_cells)
        self.reference = LineCollection([], colors="0.35", linewidths=0.8, zorder=3)
        ax.add_collection(self.reference)
        self.alternative = LineCollection([], colors="#1f5fbf", linewidths=1.2,
                                          linestyles="--", zorder=4)
        ax.add_collection(self.alternative)
        self.segments = LineCollection([], colors="#1f5fbf", linewidths=2.4, zorder=5)
        ax.add_collection(self.segments)
        (self.above,) = ax.plot([], [], "o", ms=5, color="0.1", zorder=6)
        (self.below,) = ax.plot([], [], "o", ms=5, mfc="white", mec="0.1", mew=0.9, zorder=6)
        # the case numbers as markers shaped like digits, one collection per case: far cheaper
        # to redraw than hundreds of text artists (each text is laid out on every blit), and
        # their outlines flattened (draw.text_marker: a Bézier glyph cost 4-5 ms per redraw). A
        # marker's size is its glyphs' height (one digit) or width (two): 0.75 of the
        # annotation size gives digits as tall as those of annotation-sized text.
        digit = 0.75 * _style.ANNOTATION
        self.labels = {k: ax.scatter(np.zeros(0), np.zeros(0), marker=draw.text_marker(str(k)),
                                     s=(digit ** 2 if k < 10 else (1.5 * digit) ** 2),
                                     color="#7b1fa2", linewidths=0,
                                     zorder=7) for k in range(1, 15)}
        legend_ax = self.fig.add_subplot(grid[1])
        tiles = _draw_case_table(legend_ax)
        self.tiles = PolyCollection(list(tiles), facecolors="none", edgecolors="none", zorder=0)
        legend_ax.add_collection(self.tiles)
        self.blitter = draw.Blitter(self.fig, [self.saddle_cells, self.reference,
                                               self.alternative, self.segments, self.above,
                                               self.below, *self.labels.values(),
                                               self.tiles])
        self.level = slider("isovalue c", self.state.level, 0, 10, 0.005, readout_format=".3f")
        self.field = labelled(w.Dropdown, "field", options=FIELDS, value=self.state.field)
        self.size = slider("samples", self.state.size, 4, MAX_SIZE, 1, kind=w.IntSlider)
        align([self.level, self.field, self.size])
        self._level_range()
        if self.level.value != self.state.level:        # put on the slider's grid
            self.state.level = self.level.value
            s = scene(self.state)
        self.cases_box = checkbox("case numbers", self.state.show_cases)
        bind(self.state, {"level": self.level}, self.update)
        for control in (self.field, self.size, self.cases_box):
            control.observe(self._on_layout, names="value")
        self.info = panel(width="330px")
        controls = w.VBox([self.level, self.field, self.size, self.cases_box, self.info])
        self.widget = beside(self.fig.canvas, controls)
        self._static(s)
        self._draw(s)

    def _level_range(self):
        # the step belongs to the field, not to its resolution: the isovalue stays on the
        # slider's grid when the resolution changes (the browser would snap it and send it back)
        values = example_data(self.state.field, int(self.state.size)).values
        set_range(self.level, values.min(), values.max(), _level_step(self.state.field))

    def _static(self, s):
        """The field image and the grid lines (redrawn only when the field changes)."""
        data = s["field"]
        xs, ys = data.axes
        self.image.set_data(data.values)
        self.image.set_clim(data.values.min(), data.values.max())
        lines = [[(x, ys[0]), (x, ys[-1])] for x in xs] + [[(xs[0], y), (xs[-1], y)] for y in ys]
        self.grid_lines.set_segments(lines)
        self.blitter.forget_background()

    def _on_layout(self, change):
        self.state.field, self.state.size = self.field.value, self.size.value
        self.state.show_cases = self.cases_box.value
        if change["owner"] is not self.cases_box:
            self._level_range()
            self.state.level = self.level.value
            self._static(scene(self.state))
        self.update()

    def update(self):
        """Recompute the scene and update the drawn artists (blitting)."""
        self._draw(scene(self.state))
        self.blitter.update()

    def _draw(self, s):
        self.segments.set_segments(s["segments"])
        self.reference.set_segments(s["reference"])
        self.alternative.set_segments(s["alternative"])
        self.saddle_cells.set_verts(s["saddles"])
        for artist, points in ((self.above, s["above"]), (self.below, s["below"])):
            artist.set_data(*(points.T if len(points) else ([], [])))
        centres, numbers = s["labels"]
        show = self.state.show_cases and int(self.state.size) <= 16
        for k, marks in self.labels.items():
            marks.set_offsets(centres[numbers == k] if show else np.zeros((0, 2)))
        colors = np.zeros((16, 4))
        present = s["counts"] > 0
        colors[present] = (1.0, 0.93, 0.6, 1.0)
        colors[[5, 10]] = np.where(present[[5, 10], None], (1.0, 0.72, 0.3, 1.0), 0.0)
        self.tiles.set_facecolor(colors)
        self.info.value = s["text"]


# ---------------------------------------------------------------------------------------------
# Marching cubes in 3D
# ---------------------------------------------------------------------------------------------

VOLUME_SIZE = 32


@lru_cache(maxsize=None)
def example_volume(kind="blobs", size=VOLUME_SIZE):
    """A volume for the isosurface explorer: :func:`course_lib.scivis.example_volume`,
    `size`^3 samples on [-1, 1]^3, cached and read-only.

    The kinds of :data:`VOLUMES`, among them ``"noise"`` (smooth random values with the
    outer layer of samples at -2, so that every isosurface inside closes before the border).

    Returns
    -------
    course_lib.scivis.Field
        Cached: do not modify it.

    Examples
    --------
    >>> v = example_volume("noise", 16)
    >>> v.values.shape, float(v.values[0, 0, 0])
    ((16, 16, 16), -2.0)
    """
    if kind not in VOLUMES:
        raise ValueError(f"kind must be one of {VOLUMES}, got {kind!r}")
    field = scivis.example_volume(kind, size=size)
    field.values.flags.writeable = False
    return field


def classic_marching_cubes(volume, level, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0)):
    """Marching cubes with the classic table: every cube decides its ambiguous faces alone.

    :func:`course_lib.scivis.marching_cubes` with ``table="classic"`` (the original table of
    Lorensen and Cline: a cube with at most 4 corners above cuts them off, one with more cuts
    off the corners below), so that two cubes sharing an ambiguous face may disagree and leave
    a hole. The explorer's "classic" button.

    Returns
    -------
    vertices : ndarray, shape (n, 3)
    triangles : ndarray, shape (m, 3)

    Examples
    --------
    Two cubes sharing an ambiguous face: the left one (3 corners above) separates the above
    corners of the face, the right one (5 above) joins them. The surfaces do not meet:
    edges used by one triangle only remain (a hole), while the consistent table closes it.

    >>> vol = np.zeros((2, 2, 3))
    >>> vol[0, 0, 1] = vol[1, 1, 1] = 1.0                # the shared face x = 1: diagonal
    >>> vol[0, 0, 0] = vol[1, 1, 2] = vol[1, 0, 2] = vol[0, 1, 2] = 1.0
    >>> vol = np.pad(vol, 1)                              # a frame of zeros: surfaces close
    >>> mesh_summary(*classic_marching_cubes(vol, 0.5))["boundary"]
    12
    >>> mesh_summary(*scivis.marching_cubes(vol, 0.5))["boundary"]
    0
    """
    return scivis.marching_cubes(volume, level, spacing, origin, table="classic")


def mesh_summary(vertices, triangles):
    """Counts that tell whether a triangle mesh is a closed surface, and of which kind.

    Returns
    -------
    dict
        ``V`` (vertices used by a triangle), ``E`` (edges), ``F`` (triangles), ``euler``
        (:math:`\\chi = V - E + F`), ``boundary`` (edges of one triangle only: the rims of
        holes), ``nonmanifold`` (edges of three or more), ``components`` (connected pieces),
        ``genus`` (of a closed orientable surface, :math:`g = C - \\chi / 2` summed over the C
        components; None when there are boundary edges) and ``boundary_edges`` ((b, 2) vertex
        indices).

    Examples
    --------
    A tetrahedron: 4 - 6 + 4 = 2, closed, one component, genus 0:

    >>> s = mesh_summary(np.eye(4)[:, :3], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    >>> s["euler"], s["boundary"], s["components"], s["genus"]
    (2, 0, 1, 0)
    """
    t = np.asarray(triangles, dtype=np.intp).reshape(-1, 3)
    if len(t) == 0:
        return {"V": 0, "E": 0, "F": 0, "euler": 0, "boundary": 0, "nonmanifold": 0,
                "components": 0, "genus": None, "boundary_edges": np.zeros((0, 2), np.intp)}
    pairs = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    edges, uses = np.unique(pairs, axis=0, return_counts=True)
    used = np.unique(t)
    # connected components: propagate the smallest vertex number along edges
    parent = np.arange(int(t.max()) + 1)
    a, b = edges[:, 0], edges[:, 1]
    while True:
        low = np.minimum(parent[a], parent[b])
        before = parent.copy()
        np.minimum.at(parent, a, low)
        np.minimum.at(parent, b, low)
        parent = parent[parent]
        if np.array_equal(parent, before):
            break
    components = len(np.unique(parent[used]))
    V, E, F = len(used), len(edges), len(t)
    euler = V - E + F
    boundary = int((uses == 1).sum())
    closed = boundary == 0 and not (uses > 2).any()
    return {"V": V, "E": E, "F": F, "euler": euler, "boundary": boundary,
            "nonmanifold": int((uses > 2).sum()), "components": components,
            "genus": components - euler // 2 if closed else None,
            "boundary_edges": edges[uses == 1]}


@dataclass
class State3D:
    """The volume, the isovalue, the table, and the camera (degrees).

    Examples
    --------
    >>> State3D().volume, State3D().table
    ('blobs', 'consistent')
    """

    volume: str = "blobs"
    level: float = 0.5
    table: str = "consistent"
    azimuth: float = 30.0
    elevation: float = 20.0


def scene_3d(state):
    """Pure part: the isosurface mesh, its normals (from the gradient) and its counts.

    Returns
    -------
    dict
        ``field``, ``vertices``, ``triangles``, ``normals`` (unit, per vertex: the negated,
        normalised gradient, trilinearly interpolated: towards lower values), ``summary``
        (:func:`mesh_summary`) and ``text``.

    Examples
    --------
    >>> s = scene_3d(State3D(volume="torus", level=0.0))
    >>> s["summary"]["euler"], s["summary"]["boundary"], s["summary"]["genus"]
    (0, 0, 1)
    """
    data = example_volume(state.volume)
    as_choice(state.table, "table", TABLES)
    vertices, triangles = scivis.marching_cubes(data.values, state.level, data.spacing,
                                                data.origin, table=state.table)
    normals = np.zeros_like(vertices)
    if len(vertices):
        g = scivis.multilinear_interpolate(_gradient(state.volume), vertices, data.spacing,
                                           data.origin)
        normals = -g / np.maximum(np.linalg.norm(g, axis=1, keepdims=True), 1e-12)
    summary = mesh_summary(vertices, triangles)
    text = (f"<b>{state.volume}, isovalue {state.level:.3f}, {state.table} table</b>: "
            f"V = {summary['V']:,} vertices, E = {summary['E']:,} edges, F = {summary['F']:,} "
            f"triangles; Euler characteristic χ = V − E + F = {summary['euler']}; "
            f"{summary['components']} connected piece(s).")
    if summary["F"] == 0:
        text += " The isovalue lies outside the data: no surface."
    elif summary["boundary"] == 0 and summary["nonmanifold"] == 0:
        text += (f" Every edge is shared by exactly two triangles: closed (watertight), "
                 f"total genus {summary['genus']} (χ = 2 per sphere-like piece, 0 per torus).")
    else:
        text += (f" <b style='color:#c62828'>{summary['boundary']} boundary edges</b> (red): "
                 "edges of one triangle only, the rims of holes where two cubes resolved "
                 "their shared ambiguous face differently.")
    return {"field": data, "vertices": vertices, "triangles": triangles, "normals": normals,
            "summary": summary, "text": text}


@lru_cache(maxsize=None)
def _gradient(kind):
    data = example_volume(kind)
    return scivis.gradient(data.values, data.spacing)



class IsosurfaceExplorer(PlotterExplorer):
    """Marching cubes in 3D: isovalue, volume, consistent or classic table, camera.

    The picture is rendered by pyvista off screen and shown on a matplotlib canvas
    (:meth:`PlotterExplorer.screen`).

    Examples
    --------
    >>> explorer = IsosurfaceExplorer()
    >>> explorer.level.value = 0.3                     # the two blobs merge
    >>> "1 connected piece" in explorer.info.value
    True
    """

    summary = ("Isosurface explorer (interactive): marching cubes with an isovalue slider; "
               "Euler characteristic, watertightness, and the holes of a classic table.")

    def __init__(self, state=None):
        import ipywidgets as w

        draw.configure_offscreen_vtk()
        import pyvista as pv

        self.pv = pv
        self.state = state or State3D()
        s = scene_3d(self.state)
        self.plotter = draw.offscreen_plotter(420, 380)
        # start from a placeholder triangle and a placeholder line (pyvista refuses empty meshes);
        # _draw replaces their contents and hides whichever is empty
        self.mesh = pv.PolyData(np.eye(3), pyvista_faces(np.array([[0, 1, 2]])))
        self.actor = self.plotter.add_mesh(self.mesh, color="#e8b04a", smooth_shading=False,
                                           backface_params={"color": "#4a78c8"},
                                           specular=0.3)
        self.actor.prop.interpolation = "gouraud"
        self.holes = pv.PolyData(np.eye(3), lines=np.array([2, 0, 1]))
        self.holes_actor = self.plotter.add_mesh(self.holes, color="#d0021b", line_width=6)
        self.box = pv.Box(bounds=(-1, 1, -1, 1, -1, 1)).outline()
        self.plotter.add_mesh(self.box, color="#9e9e9e", line_width=1)
        screen = self.screen()
        self.volume = labelled(w.Dropdown, "volume", options=VOLUMES, value=self.state.volume)
        self.level = slider("isovalue", self.state.level, 0, 10, 0.1, readout_format=".3f")
        self.table = w.ToggleButtons(options=TABLES, value=self.state.table,
                                     style={"button_width": _style.button_width(*TABLES)},
                                     tooltips=("our table: ambiguous faces by the asymptotic "
                                               "decider", "each cube decides alone"))
        self.azimuth = slider("view azimuth °", self.state.azimuth, -180, 180, 5)
        self.elevation = slider("view elevation °", self.state.elevation, -80, 80, 5)
        self.turned_by = (self.azimuth, self.elevation)    # and a drag across the view
        align([self.volume, self.level, self.azimuth, self.elevation])
        self._level_range()
        if self.level.value != self.state.level:        # put on the slider's grid
            self.state.level = self.level.value
            s = scene_3d(self.state)
        self.volume.observe(self._on_volume, names="value")
        self._on_change = bind(self.state, {"level": self.level, "table": self.table,
                                            "azimuth": self.azimuth,
                                            "elevation": self.elevation}, self.update)
        self.info = panel(width="340px")
        self.widget = beside(screen, w.VBox([self.volume, self.level, self.table,
                                                 self.azimuth, self.elevation, self.info]),
                             align="flex-start")
        self._draw(s)

    def _level_range(self, value=None):
        values = example_volume(self.state.volume).values
        inner = values[values > -2.0] if self.state.volume == "noise" else values
        lo, hi = inner.min(), inner.max()
        set_range(self.level, lo, hi, nice_step(hi - lo, 200), value)

    def _on_volume(self, change):
        self.state.volume = change["new"]
        self._level_range(float(example_volume(self.state.volume).level))
        self._on_change(None)

    def update(self):
        """Recompute the isosurface, update the pyvista meshes and render a new picture."""
        self._draw(scene_3d(self.state))

    def _draw(self, s):
        pv = self.pv
        if len(s["triangles"]):
            new = pv.PolyData(s["vertices"], pyvista_faces(s["triangles"]))
            new.point_data.set_array(s["normals"], "Normals")
            new.point_data.active_normals_name = "Normals"
            self.mesh.copy_from(new, deep=False)
        self.actor.visibility = bool(len(s["triangles"]))
        rims = s["summary"]["boundary_edges"]
        if len(rims):
            lines = np.column_stack([np.full(len(rims), 2), rims]).ravel()
            self.holes.copy_from(pv.PolyData(s["vertices"], lines=lines), deep=False)
        self.holes_actor.visibility = bool(len(rims))
        a, e = np.radians([self.state.azimuth - 90.0, self.state.elevation])
        eye = 6.8 * np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])
        self.plotter.camera_position = [tuple(eye), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0)]
        self.show()
        self.info.value = s["text"]
