"""Drawing helpers shared by the notebooks and the widgets (matplotlib, and pyvista set-up).

Figures are made with :func:`figure`, which keeps ipympl from showing a figure on its own when a
widget puts it inside a layout, and styles the canvas once for all widgets. The 3D helpers draw
coordinate frames and polygon meshes whose artists are later *updated* (never re-created), which
is what keeps widget updates fast.
"""
import functools
import os
import sys

import numpy as np

from .mesh.geometry import face_normals   # re-exported: the one (unit) face normal

__all__ = [
    "AXIS_COLORS",
    "Blitter",
    "configure_offscreen_vtk",
    "face_normals",
    "figure",
    "frame_3d",
    "lecture_scale",
    "mesh_3d",
    "offscreen_plotter",
    "set_frame_3d",
    "set_mesh_3d",
    "setup_axes_2d",
    "set_lecture_scale",
    "setup_axes_3d",
    "shade",
    "show",
    "text_marker",
]

#: The colours of the x, y and z axes in every figure (red, green, blue, as in most 3D tools).
AXIS_COLORS = ("#d62728", "#2ca02c", "#1f77b4")


def configure_offscreen_vtk():
    """Make VTK render off screen through EGL on a Linux machine without a display.

    Without a display VTK tries X11, prints a timestamped warning, and on a machine without GL
    libraries crashes. EGL (Debian packages ``libegl1`` and ``libgl1-mesa-dri``, which ``make``
    installs) renders without any display. Call before importing pyvista or vtk; a value already
    set in the environment is kept.

    Examples
    --------
    >>> configure_offscreen_vtk()
    """
    if sys.platform.startswith("linux") and not os.environ.get("DISPLAY"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")


def offscreen_plotter(width, height):
    """A pyvista plotter that renders off screen (through EGL without a display) on white.

    The 3D explorers draw their scene into it and show ``plotter.screenshot()`` as a picture.
    Its size follows :func:`lecture_scale`, like the matplotlib figures.

    Parameters
    ----------
    width, height : int
        Size of the picture in pixels at the laptop scale.

    Returns
    -------
    pyvista.Plotter

    Examples
    --------
    >>> plotter = offscreen_plotter(120, 90)
    >>> tuple(plotter.window_size)
    (120, 90)
    >>> plotter.close()
    """
    configure_offscreen_vtk()
    import pyvista as pv

    scale = lecture_scale()
    plotter = pv.Plotter(off_screen=True,
                         window_size=(round(width * scale), round(height * scale)))
    plotter.set_background("white")
    return plotter


#: the environment variable of lecture mode (``make lecture`` sets it): "1" for the default
#: projector scale, or a number such as "1.8"
LECTURE_ENV = "COURSE_LECTURE"
DEFAULT_LECTURE_SCALE = 1.5
_lecture_scale = None


def lecture_scale():
    """How much larger than on a laptop figures are drawn: 1 normally, about 1.5 in lecture mode.

    Lecture mode scales every figure the widgets and lessons make (text, lines and markers
    together, through the figure's dpi), so that a slider explorer reads from the back of a lecture
    room. It is on when the environment variable ``COURSE_LECTURE`` is set (``make lecture`` does
    that) or after :func:`set_lecture_scale`.

    Examples
    --------
    >>> set_lecture_scale(1.6); lecture_scale()
    1.6
    >>> set_lecture_scale(None)      # back to the environment's choice
    """
    if _lecture_scale is not None:
        return _lecture_scale
    value = os.environ.get(LECTURE_ENV, "").strip()
    if not value or value == "0":
        return 1.0
    try:
        scale = float(value)
    except ValueError:
        raise ValueError(f"environment variable {LECTURE_ENV} must be 1 or a scale such as 1.8, "
                         f"got {value!r}") from None
    return DEFAULT_LECTURE_SCALE if scale == 1 else scale


def set_lecture_scale(scale=DEFAULT_LECTURE_SCALE):
    """Draw the figures made from now on `scale` times larger (None: follow ``COURSE_LECTURE``).

    Parameters
    ----------
    scale : float or None
        Between 0.5 and 3; 1 is the laptop size.

    Examples
    --------
    >>> set_lecture_scale(2.0); figure(figsize=(2, 2)).dpi
    180.0
    >>> set_lecture_scale(None)
    >>> set_lecture_scale(7)
    Traceback (most recent call last):
    ...
    ValueError: scale must be between 0.5 and 3 (1 is the laptop size), got 7
    """
    global _lecture_scale
    if scale is not None:
        if not isinstance(scale, (int, float)) or not 0.5 <= scale <= 3:
            raise ValueError(f"scale must be between 0.5 and 3 (1 is the laptop size), got {scale!r}")
        scale = float(scale)
    _lecture_scale = scale


def figure(figsize=(4.5, 4.5), dpi=90, **kwargs):
    """A new matplotlib figure that is not displayed by itself.

    With the ipympl backend (``%matplotlib widget``) a figure created in a cell is shown at the
    end of the cell; a widget that places the canvas in its own layout would then show it twice.
    The canvas's header is hidden and the toolbar kept to the left.

    Parameters
    ----------
    figsize : (float, float)
        Size in inches; keep widget figures small, every pixel costs redraw time.
    dpi : float
        Multiplied by :func:`lecture_scale` (1 except in lecture mode).
    **kwargs
        Passed to ``matplotlib.pyplot.figure``.

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> fig.get_size_inches().tolist()
    [2.0, 2.0]
    """
    import matplotlib.pyplot as plt

    with plt.ioff():
        fig = plt.figure(figsize=figsize, dpi=dpi * lecture_scale(), **kwargs)
    canvas = fig.canvas
    for name, value in (("header_visible", False), ("footer_visible", False),
                        ("toolbar_position", "left"), ("resizable", False)):
        if hasattr(canvas, name):
            setattr(canvas, name, value)
    if hasattr(canvas, "get_diff_image"):          # an ipympl canvas: the live path of frames
        from ._canvas import fast_frames

        fast_frames(canvas)
    return fig


def setup_axes_2d(ax, limits, title=None, grid=True):
    """Equal-aspect 2D axes with labelled x and y and the given square limits.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    limits : (float, float)
        The same (min, max) for both axes.
    title : str, optional
    grid : bool, optional

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> ax = fig.add_subplot()
    >>> setup_axes_2d(ax, (-1, 1))
    >>> ax.get_xlim()
    (np.float64(-1.0), np.float64(1.0))
    """
    ax.set(xlim=limits, ylim=limits, xlabel="x", ylabel="y", aspect="equal")
    if title:
        ax.set_title(title)
    if grid:
        ax.grid(True, color="0.9", zorder=0)
    ax.axhline(0, color="0.6", lw=0.8, zorder=1.6)      # above the grid (zorder 1.5)
    ax.axvline(0, color="0.6", lw=0.8, zorder=1.6)


def setup_axes_3d(ax, radius=1.5, title=None, elev=22, azim=-60, box=True):
    """3D axes with equal scales on x, y, z over [-radius, radius].

    With ``box=True`` the usual matplotlib box with ticks, grid and labels. With ``box=False``
    the box is hidden and a light reference frame with labelled x, y, z axes drawn instead:
    it reads as well for geometry and redraws about twice as fast, which widgets need.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
    radius : float
    title : str, optional
    elev, azim : float
        Initial viewing angles in degrees (the student can drag the view).
    box : bool, optional

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> ax = fig.add_subplot(projection="3d")
    >>> setup_axes_3d(ax, radius=2)
    >>> ax.get_zlim()
    (np.float64(-2.0), np.float64(2.0))
    """
    lim = (-radius, radius)
    ax.set(xlim=lim, ylim=lim, zlim=lim)
    ax.set_box_aspect((1, 1, 1), zoom=1.0 if box else 1.35)
    ax.view_init(elev=elev, azim=azim)
    if box:
        ax.set(xlabel="x", ylabel="y", zlabel="z")
        ax.tick_params(labelsize=7, pad=0)
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.labelpad = -4
    else:
        ax.set_axis_off()
        end = 0.92 * radius
        for k, name in enumerate("xyz"):
            tip = np.zeros(3)
            tip[k] = end
            ax.plot(*np.array([-tip, tip]).T, color="0.75", lw=0.8)
            ax.text(*(1.06 * tip), name, color="0.35", fontsize=9, ha="center", va="center")
        circle = np.linspace(0, 2 * np.pi, 73)
        ax.plot(end * np.cos(circle), end * np.sin(circle), 0 * circle, color="0.85", lw=0.8)
    if title:
        # y given: matplotlib then skips placing the title clear of the axes at every draw,
        # which for a 3D axes costs a sixth of a full redraw (its bounding box is projected)
        ax.set_title(title, fontsize=10, y=1.0)


def frame_3d(ax, length=1.0, **style):
    """Three line artists for the x, y, z axes of a coordinate frame (in red, green, blue).

    Move them with :func:`set_frame_3d`.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
    length : float
        Length of each axis.
    **style
        Line properties, e.g. ``lw=3`` or ``alpha=0.3``.

    Returns
    -------
    list of three Line3D

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> lines = frame_3d(fig.add_subplot(projection="3d"))
    >>> len(lines)
    3
    """
    style = {"lw": 2.5, **style}
    lines = []
    for k in range(3):
        end = np.zeros(3)
        end[k] = length
        (line,) = ax.plot([0, end[0]], [0, end[1]], [0, end[2]], color=AXIS_COLORS[k], **style)
        lines.append(line)
    return lines


def set_frame_3d(lines, rotation, length=1.0, origin=(0.0, 0.0, 0.0)):
    """Point the frame's three lines along the columns of `rotation` (the rotated axes).

    Parameters
    ----------
    lines : list of three Line3D
        From :func:`frame_3d`.
    rotation : array_like, shape (3, 3)
        Its columns are the images of the x, y and z axes.
    length : float
    origin : array_like, shape (3,)

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> lines = frame_3d(fig.add_subplot(projection="3d"))
    >>> set_frame_3d(lines, np.eye(3)[:, [1, 2, 0]])
    >>> [float(v) for v in lines[0].get_data_3d()[1]]      # the x axis now points along y
    [0.0, 1.0]
    """
    o = np.asarray(origin, dtype=float)
    r = np.asarray(rotation, dtype=float)
    for k, line in enumerate(lines):
        end = o + length * r[:, k]
        line.set_data_3d([o[0], end[0]], [o[1], end[1]], [o[2], end[2]])


def shade(normals, base_color, light=(0.4, -0.5, 0.75), ambient=0.45):
    """Flat-shaded face colours: ``base_color`` dimmed by the angle to a fixed light.

    A Lambert term (chapter 12) gives the 3D shapes of the widgets their depth cue.

    Parameters
    ----------
    normals : array_like, shape (n, 3)
        Face normals (any length).
    base_color : array_like, shape (3,) or (n, 3)
        RGB in [0, 1].
    light : array_like, shape (3,)
        Direction towards the light.
    ambient : float
        The brightness of a face turned away from the light.

    Returns
    -------
    ndarray, shape (n, 3)

    Examples
    --------
    >>> shade([[0, 0, 1], [0, 0, -1]], [1.0, 0.5, 0.0], light=[0, 0, 1]).tolist()
    [[1.0, 0.5, 0.0], [0.45, 0.225, 0.0]]
    """
    n = np.asarray(normals, dtype=float)
    n = n / np.maximum(np.linalg.norm(n, axis=-1, keepdims=True), 1e-12)
    l_dir = np.asarray(light, dtype=float)
    l_dir = l_dir / np.linalg.norm(l_dir)
    lambert = np.clip(n @ l_dir, 0.0, 1.0)
    return np.asarray(base_color, dtype=float) * (ambient + (1 - ambient) * lambert)[:, None]


def mesh_3d(ax, vertices, faces, **style):
    """A Poly3DCollection for a polygon mesh, to be moved later with :func:`set_mesh_3d`.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
    vertices : array_like, shape (n, 3)
    faces : list of lists of int
        Vertex indices of each polygon.
    **style
        Collection properties (``edgecolor``, ``linewidth``, ``alpha``...).

    Returns
    -------
    mpl_toolkits.mplot3d.art3d.Poly3DCollection
        Of a subclass that projects a turned view in a few array operations (the same
        picture, several times faster for a mesh of a few hundred faces).

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> from mpl_toolkits.mplot3d.art3d import Poly3DCollection
    >>> mesh = mesh_3d(fig.add_subplot(projection="3d"), np.eye(3), [[0, 1, 2]])
    >>> isinstance(mesh, Poly3DCollection)      # one that projects a view faster
    True
    """
    v = np.asarray(vertices, dtype=float)
    style = {"edgecolor": "0.2", "linewidth": 0.6, **style}
    collection = _mesh_collection_class()([v[f] for f in faces], **style)
    ax.add_collection3d(collection)
    return collection


@functools.cache
def _mesh_collection_class():
    """Poly3DCollection with its view projection vectorized for a mesh of like polygons.

    Each time a 3D view turns, matplotlib projects every polygon of a Poly3DCollection and
    sorts them far to near, building one masked array and one path per polygon in Python:
    about 3 ms per hundred polygons, most of a 3D explorer's frame. When every polygon has the
    same number of corners (a triangle or quad mesh, all of :func:`mesh_3d`'s meshes), this
    class does the same in a few array operations: the same depths (the same `zsort`
    function per polygon), the same far-to-near order (a stable sort, as Python's `sorted`,
    so equal depths keep their order) and the same colours, so the picture is the same
    (``tests/test_draw_meshes.py`` compares them pixel by pixel). Anything else (polygons of
    mixed sizes, colour-mapped faces, clipping to the view limits, path codes) takes
    matplotlib's own code.
    """
    from matplotlib.collections import PolyCollection
    from mpl_toolkits.mplot3d import proj3d
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    class MeshCollection(Poly3DCollection):
        def do_3d_projection(self):
            slices = getattr(self, "_segslices", None)
            zsort = getattr(self, "_zsortfunc", None)
            if (not slices or self._A is not None or getattr(self, "_axlim_clip", False)
                    or getattr(self, "_codes3d", None) is not None
                    or zsort not in (np.average, np.min, np.max)
                    or np.ma.isMA(self._vec)):
                return super().do_3d_projection()
            n, corners = len(slices), slices[0].stop - slices[0].start
            if corners == 0 or self._vec.shape[1] != n * corners or any(
                    sl.start != k * corners for k, sl in enumerate(slices)):
                return super().do_3d_projection()
            txs, tys, tzs = proj3d._proj_transform_vec(self._vec, self.axes.M)
            depth = zsort(tzs.reshape(n, corners), axis=1)
            order = np.argsort(-depth, kind="stable")          # far to near, ties kept
            cface, cedge = self._facecolor3d, self._edgecolor3d
            if len(cface) != n:
                cface = cface.repeat(n, axis=0)
            if len(cedge) != n:
                cedge = cface if len(cedge) == 0 else cedge.repeat(n, axis=0)
            self._facecolors2d, self._edgecolors2d = cface[order], cedge[order]
            xy = np.stack([txs, tys], axis=-1).reshape(n, corners, 2)[order]
            PolyCollection.set_verts(self, xy, self._closed)
            if len(self._edgecolor3d) != len(cface):
                self._edgecolors2d = self._edgecolor3d
            if self._sort_zpos is not None:
                ztrans = proj3d._proj_transform_vec(
                    np.array([[0], [0], [self._sort_zpos], [1]]), self.axes.M)
                return ztrans[2][0]
            return np.min(tzs)

    return MeshCollection


def set_mesh_3d(collection, vertices, faces, facecolors=None):
    """Move a mesh drawn by :func:`mesh_3d` to new vertex positions (and recolour its faces).

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> mesh = mesh_3d(fig.add_subplot(projection="3d"), np.eye(3), [[0, 1, 2]])
    >>> set_mesh_3d(mesh, 2 * np.eye(3), [[0, 1, 2]], facecolors=[[1.0, 0.0, 0.0]])
    """
    v = np.asarray(vertices, dtype=float)
    collection.set_verts([v[f] for f in faces])
    if facecolors is not None:
        collection.set_facecolor(facecolors)


def text_marker(text, resolution=1000.0):
    r"""A marker shaped like `text` (as matplotlib's ``marker="$text$"``), its glyph outlines
    flattened into polygons.

    A scatter of mathtext markers is slow to redraw: before drawing a collection of one path,
    matplotlib measures the path's extent, and for a glyph's Bézier outline that means solving
    for the extrema of every curve (4-5 ms per collection here; the isoline explorer's 14
    case-number collections spent most of an update on it). The same outlines as polygons are
    measured by a min and a max, and draw the same pixels: 14 numbers redrawn in 3.8 ms
    instead of 39; at the explorers' 7-9 px no pixel more than 24 levels apart, larger only
    anti-aliased edge pixels, by at most 64 (measured 2026-12-06). Made once per text and
    resolution (4 ms each) and shared: the path is read-only.

    Parameters
    ----------
    text : str
        Mathtext without the dollars, e.g. ``"12"``.
    resolution : float
        The curves are flattened at this many units per marker size: 1000 keeps every segment
        far below a pixel at any marker size a figure uses.

    Returns
    -------
    matplotlib.path.Path
        Closed polygons only (MOVETO, LINETO, CLOSEPOLY), centred, its larger side 1 long (the
        scale of matplotlib's text markers), read-only; pass it as ``marker=``.

    Examples
    --------
    >>> path = text_marker("8")
    >>> from matplotlib.path import Path
    >>> sorted(set(path.codes.tolist())) == [Path.MOVETO, Path.LINETO, Path.CLOSEPOLY]
    True
    >>> extent = path.get_extents()
    >>> round(float(max(extent.width, extent.height)), 3)
    1.0
    """
    if not isinstance(text, str) or not text.strip():
        raise ValueError(f"text must be a non-empty string (mathtext without the dollars), got "
                         f"{text!r}")
    return _text_marker(text, float(resolution))


@functools.lru_cache(maxsize=None)
def _text_marker(text, resolution):
    from matplotlib.markers import MarkerStyle
    from matplotlib.path import Path
    from matplotlib.transforms import Affine2D

    marker = MarkerStyle(f"${text}$")
    outline = marker.get_path().transformed(marker.get_transform()
                                            + Affine2D().scale(resolution))
    polygons = [p for p in outline.to_polygons(closed_only=True) if len(p) >= 3]
    vertices = np.concatenate(polygons) / resolution
    codes = np.concatenate([[Path.MOVETO] + [Path.LINETO] * (len(p) - 2) + [Path.CLOSEPOLY]
                            for p in polygons])
    return Path(vertices, codes.astype(Path.code_type), readonly=True)


class Blitter:
    """Redraw only the moving artists of a figure: matplotlib's blitting, for fast widgets.

    A full redraw of a figure repaints its axes, ticks and text, which costs tens of
    milliseconds. The blitter keeps a picture of everything that does not move (taken after each
    full draw, e.g. when the student turns a 3D view) and on :meth:`update` pastes it back and
    draws only the given artists on top. Where the canvas cannot blit, :meth:`update` falls back
    to ``draw_idle``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    artists : list of Artist
        The artists that move. They are drawn after (on top of) the static ones; 3D polygon
        collections among them are ordered far to near, as ``Axes3D`` does. Still artists
        above a moving one in a 2D axes (outlines and labels over an image) are redrawn with
        them (``overlays``), so the live frame layers everything as the stored picture does.

    Examples
    --------
    >>> fig = figure(figsize=(2, 2))
    >>> (line,) = fig.add_subplot().plot([0, 1], [0, 1])
    >>> blitter = Blitter(fig, [line])
    >>> fig.canvas.draw()                # a full draw: takes the background
    >>> line.set_ydata([1, 0])
    >>> blitter.update()                 # pastes it back and redraws the line only
    """

    def __init__(self, fig, artists):
        self.fig = fig
        self.artists = list(artists)
        self.overlays = []
        self.background = None
        self._saving = False
        for artist in self.artists:
            artist.set_animated(True)
        self._promote_overlays()
        self._cid = fig.canvas.mpl_connect("draw_event", self._on_draw)

    def _on_draw(self, event):
        canvas = self.fig.canvas
        # a savefig draws with its own renderer and dpi: that picture is not the background
        if self._saving or not hasattr(canvas, "copy_from_bbox"):
            return
        if getattr(event, "renderer", None) is canvas.get_renderer():
            self.background = canvas.copy_from_bbox(self.fig.bbox)
            self._draw_artists()

    def _promote_overlays(self):
        """Treat as moving the still artists of 2D axes that lie above a moving one (a higher
        zorder: outlines and labels over an image). A full draw paints them after it; left in
        the background, the blitted moving artist would cover them. Artists since removed
        from their axes are dropped."""
        self.overlays = [a for a in self.overlays if a.axes is not None]
        known = {id(a) for a in self.artists + self.overlays}
        for ax in dict.fromkeys(a.axes for a in self.artists if a.axes is not None):
            if ax.name == "3d":
                continue
            low = min(a.get_zorder() for a in self.artists if a.axes is ax)
            for child in (*ax.images, *ax.collections, *ax.lines, *ax.patches, *ax.texts):
                if id(child) not in known and child.get_zorder() > low:
                    child.set_animated(True)
                    self.overlays.append(child)

    def _draw_artists(self):
        moving = self.artists + [a for a in self.overlays if a.axes is not None]
        polys = [a for a in moving if hasattr(a, "do_3d_projection")]
        others = [a for a in moving if not hasattr(a, "do_3d_projection")]
        # as a full draw paints them: by zorder, then in the order they were added to the axes
        place = {id(c): k for ax in dict.fromkeys(a.axes for a in others)
                 for k, c in enumerate(ax.get_children())}
        others.sort(key=lambda a: (a.get_zorder(), place.get(id(a), 0)))
        depth = {id(a): a.do_3d_projection() for a in polys}
        for artist in sorted(polys, key=lambda a: depth[id(a)], reverse=True) + others:
            artist.axes.draw_artist(artist)

    def update(self):
        """Show the artists' new state: blit if a background is ready, else a full redraw."""
        canvas = self.fig.canvas
        if self.background is None:
            self._promote_overlays()
            canvas.draw_idle()
            return
        canvas.restore_region(self.background)
        self._draw_artists()
        canvas.blit(self.fig.bbox)

    def forget_background(self):
        """After a change to a static artist: the next update redraws the whole figure."""
        self.background = None
        self._promote_overlays()

    def savefig(self, *args, **kwargs):
        """``fig.savefig`` with the moving artists included (animated artists are skipped
        by a plain savefig)."""
        self._saving = True
        drawn = self.artists + self.overlays
        for artist in drawn:
            artist.set_animated(False)
        try:
            self.fig.savefig(*args, **kwargs)
        finally:
            for artist in drawn:
                artist.set_animated(True)
            self._saving = False


def show(fig, dpi=None):
    """Show a finished static figure as a PNG image, and close it.

    Lesson figures that do not change are shown as pictures rather than as live ipympl
    canvases: they read the same on GitHub and in a PDF, cost no kernel round trips, and their
    stored output does not depend on widget ids.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    dpi : float, optional
        Resolution of the picture (default: the figure's own).

    Returns
    -------
    IPython.display.Image
        Displayed when it is the last value of a notebook cell.

    Examples
    --------
    >>> fig = figure(figsize=(1, 1))
    >>> image = show(fig)
    >>> image.data[:4]
    b'\\x89PNG'
    """
    import io

    import matplotlib.pyplot as plt
    from IPython.display import Image

    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=dpi or fig.dpi, bbox_inches="tight")
    plt.close(fig)
    return Image(data=buffer.getvalue(), format="png")
