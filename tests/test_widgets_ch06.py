"""Headless tests of the chapter 6 explorers: scenes against brute force over the face lists and
trimesh, and the wiring (buttons, dropdowns, sliders, the drawn artists and rendered meshes)."""
import numpy as np
import pytest
import trimesh

from course_lib.widgets import euler, mesh_structure, simplification


def directed_edges(faces):
    """(u, w) -> face, for every edge of every face in its listed order (brute force)."""
    out = {}
    for f, face in enumerate(faces):
        face = list(face)
        for i, u in enumerate(face):
            out[(u, face[(i + 1) % len(face)])] = f
    return out


# --- half-edge explorer ----------------------------------------------------------------------

@pytest.mark.parametrize("name", list(mesh_structure.MESHES))
def test_half_edge_scene_against_the_face_list(name):
    v, faces = mesh_structure.MESHES[name]()
    owner = directed_edges(faces)
    n_edges = len({tuple(sorted(e)) for e in owner})
    he = mesh_structure._structures(name)[0]
    assert he.n_half_edges == 2 * n_edges                    # every edge split in two
    for h in range(he.n_half_edges):
        s = mesh_structure.scene(mesh_structure.State(name, h))
        r = s["record"]
        u, w = r["origin"], r["target"]
        assert r["face"] == owner.get((u, w), -1)            # -1: boundary half-edge
        t = s["twin"]
        twin = mesh_structure.scene(mesh_structure.State(name, r["twin"]))["record"]
        assert (twin["origin"], twin["target"]) == (w, u)
        # the drawn arrow runs parallel to u -> w, in the same direction
        d, want = s["current"][1] - s["current"][0], v[w] - v[u]
        assert np.allclose(np.cross(d, want), 0, atol=1e-12) and np.dot(d, want) > 0
        assert np.allclose(t[1] - t[0], -(s["current"][1] - s["current"][0]))
        # winged edge: the same undirected edge; the half-edge's face is its left or right face
        wr = s["winged"]
        assert {wr["start"], wr["end"]} == {u, w}
        side = "left_face" if wr["start"] == u else "right_face"
        assert wr[side] == r["face"] and s["same_direction"] == (wr["start"] == u)
        if r["face"] >= 0:
            assert np.allclose(s["face"], v[list(faces[r["face"]])][:len(s["face"])])


def test_half_edge_scene_rejects_a_bad_index_or_mesh():
    with pytest.raises(ValueError, match="half_edge must be in"):
        mesh_structure.scene(mesh_structure.State("tetrahedron", 12))
    with pytest.raises(ValueError, match="mesh must be one of"):
        mesh_structure.scene(mesh_structure.State("teapot", 0))


def test_half_edge_buttons_walk_around_faces_and_across_edges():
    ex = mesh_structure.HalfEdgeExplorer()                   # cube of quads
    start = ex.state.half_edge
    seen = []
    for _ in range(4):
        ex.buttons["next"].click()
        seen.append(ex.state.half_edge)
    assert seen[-1] == start and len(set(seen)) == 4         # a quad: back after four steps
    ex.buttons["opposite"].click()
    twin = ex.state.half_edge
    assert twin != start
    ex.buttons["opposite"].click()
    assert ex.state.half_edge == start
    ex.buttons["next"].click()
    ex.buttons["previous"].click()
    assert ex.state.half_edge == start
    ex.index.value = twin
    s = mesh_structure.scene(mesh_structure.State("cube (quads)", twin))
    xs, ys, zs = ex.lines["current"].get_data_3d()
    assert np.allclose(np.c_[xs, ys, zs], s["current"])
    assert f"Half-edge {twin} " in ex.info.value and "winged edge" in ex.table.value


def test_half_edge_mesh_switch_resets_and_shows_boundary_half_edges():
    ex = mesh_structure.HalfEdgeExplorer()
    ex.choice.value = "disc (boundary)"
    v, faces = mesh_structure.MESHES["disc (boundary)"]()
    assert ex.index.max == 2 * len({tuple(sorted(e)) for e in directed_edges(faces)}) - 1
    boundary = [h for h in range(ex.index.max + 1) if ex.he.face[h] < 0]
    owner = directed_edges(faces)
    rim = [e for e in owner if e[::-1] not in owner]         # edges with one face only
    assert len(boundary) == len(rim) > 0
    ex.index.value = boundary[0]
    assert "boundary half-edge" in ex.info.value


# --- simplification explorer -----------------------------------------------------------------

@pytest.mark.parametrize("n", [1280, 1000, 402, 80])
def test_simplification_scene_is_a_closed_sphere_with_the_requested_faces(n):
    s = simplification.scene(simplification.State(n))
    t = trimesh.Trimesh(s["vertices"], s["faces"], process=False)
    assert len(s["faces"]) == n
    assert t.is_watertight and t.euler_number == 2           # still a sphere
    assert len(s["errors"]) == len(s["vertices"])
    if n == 1280:
        assert s["steps"] == 0 and s["errors"].max() < 1e-6  # nothing collapsed: no error
    else:
        assert s["errors"].max() > 0
    # the queue's edges are edges of the current mesh, cheapest first
    edges = {tuple(sorted(e)) for f in s["faces"] for e in ((f[0], f[1]), (f[1], f[2]),
                                                            (f[2], f[0]))}
    lookup = {tuple(np.round(p, 12)): i for i, p in enumerate(s["vertices"])}
    costs = [e.cost for e in s["queue"]]
    assert costs == sorted(costs) and len(costs) == simplification.TOP
    for a, b in s["segments"]:
        i, j = lookup[tuple(np.round(a, 12))], lookup[tuple(np.round(b, 12))]
        assert tuple(sorted((i, j))) in edges


def test_simplification_scene_rejects_a_face_count_out_of_range():
    with pytest.raises(ValueError, match="faces must be in"):
        simplification.scene(simplification.State(10))


def test_simplification_slider_rerenders_the_mesh():
    ex = simplification.SimplificationExplorer()
    before = ex.frame().copy()
    ex.faces.value = 120
    s = simplification.scene(simplification.State(120))
    assert ex.poly.n_cells == 120 and np.allclose(ex.poly.points, s["vertices"])
    assert np.allclose(ex.poly["error"], s["errors"])
    assert ex.candidates.n_lines == simplification.TOP
    # the screen shows the plotter's new frame
    assert np.array_equal(ex.frame(), ex.plotter.screenshot(return_img=True))
    assert not np.array_equal(ex.frame(), before) and "120 faces" in ex.info.value
    assert ex.table.value.count("<tr>") == simplification.TOP + 1
    ex.plotter.close()


# --- Euler explorer --------------------------------------------------------------------------

@pytest.mark.parametrize("name", list(euler.MESHES))
@pytest.mark.parametrize("r", [0, 2])
def test_euler_scene_against_trimesh_and_topology(name, r):
    s = euler.scene(euler.State(name, r))
    faces = s["faces"]
    tri = [[f[0], f[i], f[i + 1]] for f in faces for i in range(1, len(f) - 1)]
    t = trimesh.Trimesh(s["vertices"], tri, process=False)
    edges = {tuple(sorted(e)) for e in directed_edges(faces)}
    assert (s["V"], s["E"], s["F"]) == (len(s["vertices"]), len(edges), len(faces))
    if all(len(f) == 3 for f in faces):                       # trimesh counts triangles
        assert s["chi"] == t.euler_number
    assert s["closed"] == t.is_watertight
    expected = {"tetrahedron": (0, 0), "cube": (0, 0), "icosphere": (0, 0), "disc": (0, 1),
                "torus": (1, 0), "double torus": (2, 0)}[name]  # (genus, boundary loops)
    assert (s["genus"], s["boundaries"]) == expected
    assert s["chi"] == 2 - 2 * expected[0] - expected[1]


def test_euler_explorer_redraws_on_every_choice():
    ex = euler.EulerExplorer()
    for name, r in (("cube", 0), ("icosphere", 2), ("double torus", 1)):
        ex.choice.value = name
        ex.refinement.value = r
        s = euler.scene(euler.State(name, r))
        ex.fig.canvas.draw()
        assert len(ex.surface.get_facecolor()) == len(s["faces"])
        assert f"g = {s['genus']}" in ex.info.value and str(s["E"]) in ex.info.value
