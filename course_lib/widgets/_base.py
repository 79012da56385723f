"""What every explorer shares: its display (with and without a live kernel) and layout helpers."""
import base64
import io

from .. import draw

__all__ = ["Explorer", "beside", "degree_sliders", "figure_3d"]


def figure_3d(radius, title, size=4.3):
    """A square figure with one 3D axes (light reference frame, no box): ``(fig, ax)``.

    Examples
    --------
    >>> fig, ax = figure_3d(1.5, "demo")
    >>> ax.get_title(), ax.get_xlim()
    ('demo', (np.float64(-1.5), np.float64(1.5)))
    """
    fig = draw.figure(figsize=(size, size))
    ax = fig.add_subplot(projection="3d")
    fig.subplots_adjust(left=0, right=1, bottom=0.02, top=0.95)
    draw.setup_axes_3d(ax, radius=radius, title=title, box=False)
    return fig, ax


def degree_sliders(on_change, label_width="80px", **specs):
    """Sliders in whole degrees, ``name=(description, value, min, max)``, each calling
    `on_change` when moved; returned in a dict by name.

    Examples
    --------
    >>> sliders = degree_sliders(print, yaw=("yaw °", 30, -180, 180))
    >>> sliders["yaw"].value, sliders["yaw"].step
    (30.0, 1.0)
    """
    import ipywidgets as w

    sliders = {}
    for name, (description, value, low, high) in specs.items():
        slider = w.FloatSlider(value=value, min=low, max=high, step=1, description=description,
                               continuous_update=True, style={"description_width": label_width},
                               layout=w.Layout(width="330px"))
        slider.observe(on_change, names="value")
        sliders[name] = slider
    return sliders


def beside(canvas, controls):
    """The figure on the left and the controls on the right (wrapping below on narrow screens).

    Examples
    --------
    >>> import ipywidgets as w
    >>> type(beside(w.Label("figure"), w.Label("controls"))).__name__
    'HBox'
    """
    import ipywidgets as w

    return w.HBox([canvas, controls], layout=w.Layout(flex_flow="row wrap", align_items="center"))


class Explorer:
    """Base of the interactive explorers.

    A subclass builds ``self.widget`` (an ipywidgets container), ``self.fig`` (its matplotlib
    figure, or None), optionally ``self.blitter`` (a :class:`course_lib.draw.Blitter` of the
    artists that move) and ``update()``, which recomputes the pure scene and updates the drawn
    artists in place.

    Displaying an explorer shows the live widget. The display also carries a plain-text
    summary and a PNG of the figure in its current state, so that a notebook read without a
    kernel (GitHub, nbviewer, a PDF export) still shows the picture, and so that the stored text
    output does not depend on widget ids or versions.

    Examples
    --------
    >>> from course_lib.widgets.gimbal import GimbalExplorer
    >>> bundle = GimbalExplorer()._repr_mimebundle_()
    >>> sorted(bundle)
    ['application/vnd.jupyter.widget-view+json', 'image/png', 'text/plain']
    """

    #: One line said in place of the widget where it cannot be shown.
    summary = "An interactive explorer: run the notebook in JupyterLab to use it."
    widget = None
    fig = None
    blitter = None

    def update(self):  # pragma: no cover - every subclass overrides it
        raise NotImplementedError

    def png(self, dpi=72):
        """The figure in its current state as PNG bytes (None without a figure).

        Examples
        --------
        >>> from course_lib.widgets.quaternion import QuaternionExplorer
        >>> QuaternionExplorer().png()[:4]
        b'\\x89PNG'
        """
        if self.fig is None:
            return None
        buffer = io.BytesIO()
        save = self.blitter.savefig if self.blitter is not None else self.fig.savefig
        save(buffer, format="png", dpi=dpi)
        return buffer.getvalue()

    def _repr_mimebundle_(self, include=None, exclude=None):
        image = self.png()
        encoded = base64.b64encode(image).decode("ascii") if image is not None else None
        bundle = dict(self.widget._repr_mimebundle_(include=include, exclude=exclude) or {})
        bundle["text/plain"] = self.summary
        if encoded is not None:
            bundle["image/png"] = encoded
        return bundle
