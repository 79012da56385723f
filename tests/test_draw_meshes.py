"""draw.mesh_3d's vectorized projection against matplotlib's own Poly3DCollection: the same
pixels, the same far-to-near order and colours, the same depth returned, for triangle and quad
meshes, every z-sort rule, many views, after the mesh moves (set_mesh_3d), and for meshes the
fast path leaves to matplotlib (polygons of mixed sizes)."""
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from course_lib import draw

VIEWS = [(22, -60), (5, 10), (60, 135), (-30, 200), (89, 0), (0, 90)]


def _triangles():
    rng = np.random.default_rng(4)
    vertices = rng.uniform(-1, 1, (60, 3))
    faces = [list(rng.choice(60, 3, replace=False)) for _ in range(40)]
    colours = rng.uniform(0.1, 0.9, (40, 4))
    colours[:, 3] = rng.uniform(0.5, 1.0, 40)
    return vertices, faces, {"facecolors": colours}


def _quads():
    u, v = np.meshgrid(np.linspace(-1, 1, 9), np.linspace(-1, 1, 7))
    vertices = np.column_stack([u.ravel(), v.ravel(), 0.6 * np.sin(2 * u.ravel()) * v.ravel()])
    faces = [[r * 9 + c, r * 9 + c + 1, (r + 1) * 9 + c + 1, (r + 1) * 9 + c]
             for r in range(6) for c in range(8)]
    return vertices, faces, {"facecolor": "#7fa7d9", "edgecolor": "0.1", "alpha": 0.8}


def _mixed():
    vertices, faces, style = _quads()
    return vertices, faces[:20] + [f[:3] for f in faces[20:]], style


def _pictures(vertices, faces, style, view, zsort, move=None):
    """RGBA pixels, and the projected collection, of the mesh drawn by draw.mesh_3d and by
    matplotlib's Poly3DCollection, each in a figure of its own."""
    out = []
    for fast in (True, False):
        fig = Figure(figsize=(3, 3), dpi=60)
        canvas = FigureCanvasAgg(fig)
        ax = fig.add_subplot(projection="3d")
        ax.set(xlim=(-1, 1), ylim=(-1, 1), zlim=(-1, 1))
        if fast:
            mesh = draw.mesh_3d(ax, vertices, faces, **style)
        else:
            mesh = Poly3DCollection([np.asarray(vertices)[f] for f in faces],
                                    **{"edgecolor": "0.2", "linewidth": 0.6, **style})
            ax.add_collection3d(mesh)
        mesh.set_zsort(zsort)
        if move is not None:
            moved = move(np.asarray(vertices))
            if fast:
                draw.set_mesh_3d(mesh, moved, faces)
            else:
                mesh.set_verts([moved[f] for f in faces])
        ax.view_init(*view)
        canvas.draw()
        out.append((np.asarray(canvas.buffer_rgba()).copy(), mesh))
    return out


@pytest.mark.parametrize("mesh", [_triangles, _quads, _mixed])
@pytest.mark.parametrize("zsort", ["average", "min", "max"])
def test_mesh_3d_draws_what_matplotlib_draws(mesh, zsort):
    vertices, faces, style = mesh()
    for view in VIEWS:
        (fast, ours), (slow, reference) = _pictures(vertices, faces, style, view, zsort)
        assert type(ours).__name__ == "MeshCollection"
        assert type(reference) is Poly3DCollection
        differ = np.count_nonzero(np.any(fast != slow, axis=-1))
        assert differ == 0, f"{mesh.__name__} seen from {view}: {differ} pixels differ"
        np.testing.assert_array_equal(ours.get_facecolor(), reference.get_facecolor())
        np.testing.assert_array_equal(ours.get_edgecolor(), reference.get_edgecolor())
        assert ours.do_3d_projection() == reference.do_3d_projection()
        for a, b in zip(ours.get_paths(), reference.get_paths(), strict=True):
            np.testing.assert_array_equal(a.vertices, b.vertices)
            np.testing.assert_array_equal(a.codes, b.codes)


def test_a_moved_mesh_is_drawn_where_it_moved():
    vertices, faces, style = _triangles()
    turn = np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1.0]])
    (fast, _), (slow, _) = _pictures(vertices, faces, style, (30, 40), "average",
                                     move=lambda v: 0.8 * v @ turn.T + [0.1, 0, 0])
    (before, _), _ = _pictures(vertices, faces, style, (30, 40), "average")
    assert np.array_equal(fast, slow)
    assert not np.array_equal(fast, before)          # the move did change the picture
