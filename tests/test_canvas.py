"""The live path of an explorer's frames (course_lib/_canvas.py), without a browser: what the
kernel sends must rebuild, on the page, exactly the picture the figure shows."""
import io
import json

import numpy as np
from PIL import Image

from course_lib import draw


def _figure():
    fig = draw.figure(figsize=(3, 2))
    ax = fig.add_subplot()
    ax.set(xlim=(0, 1), ylim=(0, 1))
    (line,) = ax.plot([0.1, 0.2], [0.1, 0.2], lw=3)
    return fig, line


def _pixels(png):
    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB")).astype(int)


def _shown(fig):
    return np.asarray(fig.canvas.get_renderer().buffer_rgba())[..., :3].astype(int)


def _frame(fig):
    """Draw (as a push or a blit does) and return what reached the page: the PNG and its place
    (None for a whole frame), or (None, None) when nothing was sent."""
    canvas = fig.canvas
    sent = []
    canvas.send = lambda content, buffers=None: sent.append((json.loads(content["data"]),
                                                             buffers))
    canvas.draw()
    frames = [(bytes(b[0]), (m["x"], m["y"]) if "x" in m else None)
              for m, b in sent if m["type"] == "binary"]
    assert len(frames) <= 1
    return frames[0] if frames else (None, None)


def test_frames_are_whole_until_the_page_says_it_places_rectangles():
    fig, line = _figure()
    png, place = _frame(fig)
    assert place is None and np.array_equal(_pixels(png), _shown(fig))
    line.set_data([0.1, 0.9], [0.1, 0.9])
    png, place = _frame(fig)                       # still whole: no decoder has said "ready"
    assert place is None and np.array_equal(_pixels(png), _shown(fig))


def test_a_rectangle_placed_on_the_previous_frame_gives_the_new_frame():
    fig, line = _figure()
    fig.canvas._course_regions = True
    first, place = _frame(fig)
    assert place is None                           # nothing sent before: whole
    page = _pixels(first).copy()
    for end in (0.5, 0.3, 0.8):                    # a point dragged about
        line.set_data([0.1, end], [0.1, 1 - end])
        png, place = _frame(fig)
        patch = _pixels(png)
        x, y = place
        assert patch.shape[0] * patch.shape[1] < 0.8 * page.shape[0] * page.shape[1]
        page[y:y + patch.shape[0], x:x + patch.shape[1]] = patch
        assert np.array_equal(page, _shown(fig)), "the page would show stale pixels"
    assert _frame(fig)[0] is None                  # nothing changed: nothing is sent


def test_a_rectangle_is_sent_with_its_place_and_a_whole_frame_without():
    fig, line = _figure()
    canvas = fig.canvas
    sent = []
    canvas.send = lambda content, buffers=None: sent.append((json.loads(content["data"]),
                                                             buffers))
    canvas._course_regions = True
    canvas._course_shown = False
    canvas.draw()                                  # not shown yet: ipympl's own message
    line.set_data([0.1, 0.7], [0.1, 0.4])
    canvas.draw()
    kinds = [(m["type"], "x" in m) for m, _ in sent]
    assert kinds == [("binary", False), ("binary", True)], sent
    assert isinstance(sent[1][1][0], bytes) and sent[1][0]["x"] >= 0
