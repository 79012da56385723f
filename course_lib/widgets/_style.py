"""The look every explorer shares, in one place: one scale of font sizes for the figures and the
widths of the controls' labels.

**Figures.** Every explorer figure is made by :func:`course_lib.draw.figure` at :data:`DPI`
(which that function multiplies by the lecture scale, so in projector mode the text grows with
the rest). Sizes are in points; at 90 dpi one point is 1.25 screen pixels, so the smallest text,
:data:`TICK` = 9 pt, is 11 px high on a laptop at 100 %.

**Controls.** JupyterLab writes a widget's description in 13 px text and cuts a description
wider than its box with "...". :func:`label_width` gives a box wide enough for the whole text
(estimated generously: a student's font may be wider than the one the tests run with), and
:func:`course_lib.widgets._base.labelled` uses it unless told otherwise.

Examples
--------
>>> TICK <= LEGEND <= LABEL <= TITLE
True
>>> label_width("k_s specular")
'106px'
"""
import math

__all__ = ["ANNOTATION", "DPI", "LABEL", "LEGEND", "PICTURE_LABEL", "PICTURE_TITLE", "SYMBOL",
           "TICK", "TITLE", "scalar_bar",
           "button_width", "label_width", "legend", "px", "style_axes", "style_figure"]

#: Dots per inch of every explorer figure (before the lecture scale).
DPI = 90
#: Tick labels and colour-bar numbers.
TICK = 9
#: Legend entries.
LEGEND = 9
#: Numbers and names written into a picture (point labels, case numbers, captions).
ANNOTATION = 9
#: Axis labels and short explanatory lines.
LABEL = 10
#: Titles of axes.
TITLE = 10.5
#: Large signs between pictures (the Phong explorer's "+" and "=").
SYMBOL = 16

#: Text in the rendered 3D pictures (pyvista scalar bars), in pixels at the laptop scale.
PICTURE_LABEL = 12
#: Titles in the rendered 3D pictures.
PICTURE_TITLE = 13

#: Width in CSS pixels of one character of a control's 13 px text, taken generously.
CHAR_PX = 8
#: Room left after a description's text (ipywidgets pads the label on the right).
LABEL_PAD = 10
#: The narrowest description box, so that short labels of one column line up.
MIN_LABEL = 80
#: Room a button's border and padding take besides its text.
BUTTON_PAD = 28


def px(width):
    """A CSS width in pixels as a number: ``px("120px") == 120``.

    Examples
    --------
    >>> px("120px"), px(64)
    (120, 64)
    """
    return int(round(float(str(width).removesuffix("px"))))


def label_width(*texts, minimum=MIN_LABEL):
    """A description width (CSS, e.g. ``"106px"``) that shows every one of `texts` whole.

    Examples
    --------
    >>> label_width("x"), label_width("eye x", "gaze azimuth °")
    ('80px', '122px')
    """
    longest = max((len(text) for text in texts), default=0)
    return f"{max(minimum, math.ceil(longest * CHAR_PX) + LABEL_PAD)}px"


def button_width(*texts, minimum=0):
    """A button width (CSS) that shows every one of `texts` whole; also a toggle-button group's
    ``button_width``.

    Examples
    --------
    >>> button_width("render full image")
    '164px'
    """
    longest = max((len(text) for text in texts), default=0)
    return f"{max(minimum, math.ceil(longest * CHAR_PX) + BUTTON_PAD)}px"


def style_axes(ax):
    """Tick labels, axis labels and the title of one axes (2D or 3D) in the shared sizes.

    Examples
    --------
    >>> from course_lib import draw
    >>> ax = draw.figure(figsize=(2, 2)).add_subplot()
    >>> _ = ax.set_title("t"); style_axes(ax)
    >>> ax.title.get_fontsize(), ax.xaxis.get_ticklabels()[0].get_fontsize()
    (10.5, 9.0)
    """
    ax.tick_params(labelsize=TICK)
    axes = [ax.xaxis, ax.yaxis] + ([ax.zaxis] if hasattr(ax, "zaxis") else [])
    for axis in axes:
        axis.label.set_fontsize(LABEL)
    ax.title.set_fontsize(TITLE)
    legend = ax.get_legend()
    if legend is not None:
        for text in legend.get_texts():
            text.set_fontsize(LEGEND)


def style_figure(fig):
    """:func:`style_axes` for every axes of `fig` (colour bars included); returns `fig`.

    Examples
    --------
    >>> from course_lib import draw
    >>> fig = draw.figure(figsize=(2, 2))
    >>> ax = fig.add_subplot(); _ = ax.plot([0, 1], label="a"); _ = ax.legend(fontsize=6)
    >>> ax.get_legend().get_texts()[0].get_fontsize()
    6.0
    >>> style_figure(fig).axes[0].get_legend().get_texts()[0].get_fontsize()
    9.0
    """
    for ax in fig.axes:
        style_axes(ax)
    return fig


def legend(ax, **options):
    """``ax.legend`` in the shared legend size (further `options` go to it).

    Examples
    --------
    >>> from course_lib import draw
    >>> ax = draw.figure(figsize=(2, 2)).add_subplot(); _ = ax.plot([0, 1], label="a")
    >>> legend(ax, loc="upper left").get_texts()[0].get_fontsize()
    9.0
    """
    options.setdefault("fontsize", LEGEND)
    return ax.legend(**options)


def clear_title(bar):
    """Keep a vertical pyvista/VTK scalar bar's title clear of its top label (VTK draws the
    two touching); `bar` is the ``vtkScalarBarActor``. Returns it.

    Examples
    --------
    >>> import vtk
    >>> clear_title(vtk.vtkScalarBarActor()).GetVerticalTitleSeparation() > 0
    True
    """
    from .. import draw

    bar.SetVerticalTitleSeparation(round(8 * draw.lecture_scale()))
    return bar


def scalar_bar(title, **options):
    """Arguments for a pyvista scalar bar (``add_mesh(..., scalar_bar_args=...)``): a thin
    vertical bar along the right edge of the picture, its text in the shared picture sizes
    (scaled with the lecture scale, like the picture), three labels with two decimals.
    Further `options` override these.

    Examples
    --------
    >>> args = scalar_bar("error")
    >>> args["title"], args["vertical"], args["label_font_size"] >= PICTURE_LABEL
    ('error', True, True)
    """
    from .. import draw

    scale = draw.lecture_scale()
    args = {"title": title, "vertical": True, "position_x": 0.86, "position_y": 0.12,
            "width": 0.05, "height": 0.72, "n_labels": 3, "fmt": "%.2f",
            "title_font_size": round(PICTURE_TITLE * scale),
            "label_font_size": round(PICTURE_LABEL * scale), "color": "#262626"}
    args.update(options)
    return args
