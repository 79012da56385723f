"""The frame a student sees live is the picture the notebook stores.

Live, an explorer blits: it pastes back a picture of its still artists and draws the moving ones
on top (``draw.Blitter``). Stored, the figure is drawn whole, every artist in zorder. The two
must agree: a still outline or label above a moving image has to be redrawn after the image, or
the live frame hides it (the z-buffer trace showed no triangle outlines and no numbers live).
Up to 1.5 % of the pixels may differ (antialiased edges where an image meets its axes' frame,
3D depth ties); the z-buffer's lost overlays were 5.4 %.
"""
import importlib
import inspect
import io
import pkgutil

import numpy as np
import pytest
from PIL import Image

import course_lib.widgets as widgets
from course_lib.widgets._base import Explorer

TOLERANCE = 0.015


def _explorers():
    found = []
    for info in pkgutil.iter_modules(widgets.__path__):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"course_lib.widgets.{info.name}")
        found += [cls for _, cls in inspect.getmembers(module, inspect.isclass)
                  if issubclass(cls, Explorer) and cls is not Explorer
                  and cls.__module__ == module.__name__]
    return found


@pytest.mark.parametrize("explorer", _explorers(), ids=lambda cls: cls.__name__)
def test_the_live_frame_shows_what_the_stored_picture_shows(explorer):
    ex = explorer()
    if ex.fig is None or ex.blitter is None:
        pytest.skip(f"{explorer.__name__} shows a rendered image, not a blitted figure")
    canvas = ex.fig.canvas
    canvas.draw_idle = canvas.draw             # what the browser's draw request leads to
    canvas.draw()                              # the first full frame: takes the background
    ex.update()                                # a blitted frame
    live = np.asarray(canvas.get_renderer().buffer_rgba())[..., :3].astype(int)
    buffer = io.BytesIO()
    ex.blitter.savefig(buffer, format="png", dpi=ex.fig.dpi)
    stored = np.asarray(Image.open(buffer).convert("RGB")).astype(int)
    assert live.shape == stored.shape
    differ = (np.abs(live - stored).max(axis=-1) > 24).mean()
    assert differ <= TOLERANCE, f"{100 * differ:.1f} % of the live frame differs"
