"""draw.text_marker: the flattened glyph markers draw what matplotlib's mathtext markers draw."""
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.markers import MarkerStyle
from matplotlib.path import Path
from shapely.geometry import MultiLineString, MultiPoint

from course_lib import draw


def _render(markers, size):
    fig = Figure(figsize=(max(4.0, 1.6 * size * (len(markers) + 1) / 90), 1.5), dpi=90)
    FigureCanvasAgg(fig)
    ax = fig.add_axes([0, 0, 1, 1])
    ax.set(xlim=(0, len(markers) + 1), ylim=(0, 1))
    ax.axis("off")
    for k, marker in enumerate(markers, start=1):
        ax.scatter([k], [0.5], marker=marker, s=size ** 2, color="#7b1fa2", linewidths=0)
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int)


TEXTS = [str(k) for k in range(1, 15)] + ["A", "x_2"]


@pytest.mark.parametrize("text", TEXTS)
def test_the_polygons_follow_the_glyph_curves(text):
    # points on matplotlib's own Bézier outline (the mathtext marker, at its marker scale)
    # lie on the flattened outline, to a thousandth of the marker's size
    marker = MarkerStyle(f"${text}$")
    outline = marker.get_path().transformed(marker.get_transform())
    t = np.linspace(0, 1, 9)
    samples = np.vstack([curve(t) for curve, _ in outline.iter_bezier()])
    flat = draw.text_marker(text)
    edges = MultiLineString([np.vstack([p, p[:1]]) for p in flat.to_polygons()])
    distances = [edges.distance(point) for point in MultiPoint(samples).geoms]
    assert max(distances) < 1e-3


@pytest.mark.parametrize("size", [7, 14, 40])
def test_flattened_markers_draw_the_pixels_of_mathtext_markers(size):
    reference = _render([f"${t}$" for t in TEXTS], size)        # matplotlib's own glyphs
    flat = _render([draw.text_marker(t) for t in TEXTS], size)
    ink = (reference.min(axis=-1) < 200).sum()
    assert ink > 15 * len(TEXTS) * (size / 7) ** 2              # the glyphs were drawn at all
    difference = np.abs(reference - flat).max(axis=-1)
    # only the anti-aliased edges differ, and by less than a quarter of an edge pixel's cover
    assert difference.max() <= 64
    assert (difference > 24).sum() <= 0.02 * ink


def test_holes_stay_holes():
    # "8": its outline and its two holes, closed polygons and nothing else
    path = draw.text_marker("8")
    assert len(path.to_polygons()) == 3
    assert set(path.codes.tolist()) == {Path.MOVETO, Path.LINETO, Path.CLOSEPOLY}
    reference = _render(["$8$"], 40)
    flat = _render([path], 40)
    # the holes' centres are unpainted in both (a lost winding would fill them)
    assert (reference.min(axis=-1) > 200).sum() == pytest.approx(
        (flat.min(axis=-1) > 200).sum(), rel=0.01)


@pytest.mark.parametrize("bad", ["", "   ", None, 8])
def test_bad_text_is_refused_by_name(bad):
    with pytest.raises(ValueError, match="text must be a non-empty string"):
        draw.text_marker(bad)


def test_a_list_is_refused_by_name_too():
    # checked before the cache, which would fail on an unhashable argument
    with pytest.raises(ValueError, match="text must be a non-empty string"):
        draw.text_marker(["1"])


def test_the_shared_path_cannot_be_changed():
    path = draw.text_marker("3")
    assert draw.text_marker("3") is path
    with pytest.raises(AttributeError):
        path.vertices = path.vertices * 2
