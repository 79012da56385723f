"""What every explorer shares: how it displays itself, with and without a live kernel."""
import base64
import io


__all__ = ["Explorer"]


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
