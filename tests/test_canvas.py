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


# --- a turned 3D view redraws the 3D axes only -----------------------------------------------

def _scene_beside_a_plot(inset=False):
    """A 3D mesh beside a 2D plot (as Slerp's and the hidden-surface explorer's figures); the
    2D plot's curve moved by a Blitter, as the explorers' moving artists are."""
    fig = draw.figure(figsize=(6, 3))
    ax3 = fig.add_subplot(121, projection="3d")
    draw.setup_axes_3d(ax3, 1.2, "scene")
    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    draw.mesh_3d(ax3, vertices, [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]],
                 facecolors=["#d62728", "#2ca02c", "#1f77b4", "#ff7f0e"])
    ax2 = (fig.add_axes([0.3, 0.3, 0.3, 0.3]) if inset else fig.add_subplot(122))
    ax2.set(xlim=(0, 1), ylim=(0, 1), title="a plot")
    ax2.plot([0, 1], [0.2, 0.8], color="0.5")
    (moving,) = ax2.plot([0, 1], [0.5, 0.5], lw=2)
    blitter = draw.Blitter(fig, [moving])
    drawn = []
    original = type(ax2).draw
    ax2.draw = lambda renderer: (drawn.append(1), original(ax2, renderer))[1]
    fig.canvas.draw()
    return fig, ax3, ax2, moving, blitter, drawn


def _matplotlibs_own(fig):
    """The picture of matplotlib's own full draw (the Blitter's artists painted on it)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg.draw(fig.canvas)
    return _shown(fig)


def test_a_turned_view_redraws_the_3d_axes_only_and_gives_matplotlibs_picture():
    fig, ax3, ax2, moving, blitter, drawn = _scene_beside_a_plot()
    views = [(20, 30), (25, 40), (10, 75), (60, -120)]
    ours = []
    before = len(drawn)
    for elev, azim in views:
        ax3.view_init(elev=elev, azim=azim)
        fig.canvas.draw()
        ours.append(_shown(fig).copy())
    assert len(drawn) == before, "the 2D axes were redrawn for a turned 3D view"
    assert fig.canvas._course_partial_draws == len(views)
    for (elev, azim), picture in zip(views, ours):
        ax3.view_init(elev=elev, azim=azim)
        assert np.array_equal(picture, _matplotlibs_own(fig)), (elev, azim)


def test_a_change_beside_the_3d_axes_is_drawn_with_the_next_turn():
    fig, ax3, ax2, moving, blitter, drawn = _scene_beside_a_plot()
    # a moving (animated) artist changed: the kept figure still holds, the Blitter paints it
    moving.set_ydata([0.1, 0.9])
    blitter.update()
    ax3.view_init(elev=35, azim=10)
    fig.canvas.draw()
    partial = fig.canvas._course_partial_draws
    assert partial == 1
    picture = _shown(fig).copy()
    assert np.array_equal(picture, _matplotlibs_own(fig))
    # a still artist of the 2D axes changed: the next turn redraws the 2D axes too
    fig.canvas.draw()                             # (keeps a new figure: matplotlib drew last)
    ax2.set_title("a new title")
    ax3.view_init(elev=40, azim=20)
    before = len(drawn)
    fig.canvas.draw()
    assert len(drawn) == before + 1 and fig.canvas._course_partial_draws == partial
    picture = _shown(fig).copy()
    assert np.array_equal(picture, _matplotlibs_own(fig))
    # a savefig draws the figure its own way: the next turn draws it anew as well
    fig.canvas.draw()
    fig.savefig(io.BytesIO(), format="png", dpi=50)
    ax3.view_init(elev=45, azim=25)
    before = len(drawn)
    fig.canvas.draw()
    assert len(drawn) == before + 1
    assert np.array_equal(_shown(fig).copy(), _matplotlibs_own(fig))


def test_a_plot_over_the_3d_axes_is_always_drawn_whole():
    fig, ax3, ax2, moving, blitter, drawn = _scene_beside_a_plot(inset=True)
    before = len(drawn)
    ax3.view_init(elev=30, azim=50)
    fig.canvas.draw()
    assert len(drawn) == before + 1 and fig.canvas._course_partial_draws == 0
    assert np.array_equal(_shown(fig).copy(), _matplotlibs_own(fig))
