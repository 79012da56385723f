"""Tests of the chapter 6 exercises (course_lib.exercises.ch06).

For every exercise and many seeds: the statement reads, the right answer is accepted,
placeholders are "unanswered", garbage is "invalid", and every anticipated mistake, rebuilt here
from the question's attributes, is named by its diagnosis. The right answers are computed here
independently of the checkers: trimesh (counts of real meshes, watertightness, winding
consistency), networkx (the fans of faces around a vertex), a half-edge table and winged-edge
records typed out from the face lists, the one-ring ordered by angle around the outward
direction, point-to-plane distances and a least-squares solve (numpy.linalg.lstsq) for the
quadric error metric; never with the course_lib function the checker calls.
"""
import math
from collections import Counter

import networkx as nx
import numpy as np
import pytest
import trimesh

from course_lib.exercises import ch06
import exercise_harness as harness
from exercise_harness import SAME, SEEDS, Either, gap


def cycle(face):
    return list(zip(face, face[1:] + face[:1]))


# ---------------------------------------------------------------------------------------------
# Independent tools
# ---------------------------------------------------------------------------------------------

def euler_counts(V, g, k):
    """E and F of a closed k-gon mesh of genus g: kF = 2E and V - E + F = 2 - 2g."""
    chi = 2 - 2 * g
    F = 2 * (V - chi) / (k - 2)
    return k * F / 2, F


def test_euler_count_formula_agrees_with_real_meshes():
    sphere = trimesh.creation.icosphere(subdivisions=2)
    torus = trimesh.creation.torus(major_radius=1.0, minor_radius=0.3)
    for m, g in ((sphere, 0), (torus, 1)):
        assert m.is_watertight and m.euler_number == 2 - 2 * g
        E, F = euler_counts(len(m.vertices), g, 3)
        assert (E, F) == (len(m.edges_unique), len(m.faces))
    box = trimesh.creation.box()                       # 12 triangles; as 6 quads: V=8, g=0
    assert euler_counts(8, 0, 4) == (12, 6) and box.euler_number == 2


def collapse_by_hand(faces, keep, drop):
    """Merge vertex `drop` into `keep`: faces with both disappear, the others are relabelled."""
    out = []
    for f in faces:
        if keep in f and drop in f:
            continue
        out.append([keep if v == drop else v for v in f])
    return out


def counts(faces):
    edges = {tuple(sorted(e)) for f in faces for e in cycle(list(f))}
    return len({v for f in faces for v in f}), len(edges), len(faces)


def test_collapse_counts_agree_with_real_collapses():
    m = trimesh.creation.icosphere(subdivisions=2)
    faces = m.faces.tolist()
    V, E, F = counts(faces)
    a, b = (int(x) for x in m.edges_unique[0])
    after = counts(collapse_by_hand(faces, a, b))
    assert after == (V - 1, E - 3, F - 2)
    # a boundary edge: cut out the fan of vertex 0 (a pentagonal hole), collapse an edge of
    # its rim (a triangular hole would close up: not a legal collapse)
    fan = [f for f in faces if 0 in f]
    opened = [f for f in faces if 0 not in f]
    V, E, F = counts(opened)
    a, b = [v for v in fan[0] if v != 0]
    assert len(fan) == 5
    assert counts(collapse_by_hand(opened, a, b)) == (V - 1, E - 2, F - 1)


def kind_by_hand(faces):
    """The MESH_KINDS name from edge face counts and networkx fans around each vertex."""
    per_edge = Counter(tuple(sorted(e)) for f in faces for e in cycle(f))
    if max(per_edge.values()) > 2:
        return "non-manifold edge"
    for v in {v for f in faces for v in f}:
        around = [k for k, f in enumerate(faces) if v in f]
        graph = nx.Graph()
        graph.add_nodes_from(around)
        for i in around:
            for j in around:
                shared = set(faces[i]) & set(faces[j])
                if i < j and v in shared and len(shared) >= 2:
                    graph.add_edge(i, j)
        if nx.number_connected_components(graph) > 1:
            return "non-manifold vertex"
    if min(per_edge.values()) == 1:
        return "manifold with boundary"
    return "closed manifold"


def flipped_by_trimesh(faces):
    """The one face whose reversal makes the (triangulated) winding consistent, by trimesh."""
    n = max(max(f) for f in faces) + 1
    vertices = np.random.default_rng(0).normal(size=(n, 3))
    found = []
    for k in range(len(faces)):
        fixed = [f[::-1] if j == k else f for j, f in enumerate(faces)]
        tris = [[f[0], f[i], f[i + 1]] for f in fixed for i in range(1, len(f) - 1)]
        if trimesh.Trimesh(vertices, tris, process=False).is_winding_consistent:
            found.append(k)
    assert len(found) == 1
    return found[0]


def half_edges_by_hand(faces):
    """origin, next, prev, twin, face of the half-edges numbered face by face, corner by corner."""
    origin, nxt, prv, face = [], [], [], []
    for k, f in enumerate(faces):
        base = len(origin)
        for i, v in enumerate(f):
            origin.append(v)
            nxt.append(base + (i + 1) % len(f))
            prv.append(base + (i - 1) % len(f))
            face.append(k)
    target = [origin[n] for n in nxt]
    by_pair = {(o, t): h for h, (o, t) in enumerate(zip(origin, target))}
    twin = [by_pair[(t, o)] for o, t in zip(origin, target)]
    return {"origin": origin, "next": nxt, "prev": prv, "twin": twin, "face": face,
            "target": target}


def winged_record(faces, edges, e):
    """left/right faces and the four wings of edge e, from the face list."""
    a, b = edges[e]
    index = {frozenset(pair): k for k, pair in enumerate(edges)}

    def around(u, w):          # the face walking u -> w, the edge before and after
        for k, f in enumerate(faces):
            for i, (x, y) in enumerate(cycle(f)):
                if (x, y) == (u, w):
                    before = f[i - 1]
                    after = f[(i + 2) % len(f)]
                    return k, index[frozenset((before, u))], index[frozenset((w, after))]
        raise AssertionError("edge not on a face")

    lf, lp, ln = around(a, b)
    rf, rp, rn = around(b, a)
    return lf, rf, lp, ln, rp, rn


def one_ring_by_angle(ex):
    """The neighbours of v ordered counter-clockwise around the outward direction."""
    table = ex.table
    p = table.vertices
    v = ex.v
    normal = p[v] - p.mean(axis=0)
    normal /= np.linalg.norm(normal)
    neighbours = {b for f in ex.faces for a, b in cycle(f) if a == v}
    start = int(table.origin[table.next[ex.h]])
    u = p[start] - p[v]
    u -= (u @ normal) * normal
    u /= np.linalg.norm(u)
    w = np.cross(normal, u)

    def angle(n):
        d = p[n] - p[v]
        return math.atan2(d @ w, d @ u) % (2 * math.pi)

    return tuple(sorted(neighbours, key=angle))


def plane_from(n, point):
    """Unit normal and offset of the plane n . x = n . point."""
    n = np.asarray(n, dtype=float)
    length = np.linalg.norm(n)
    return n / length, float(n @ point) / length


def squared_distances(planes, x):
    return sum((n @ x - c) ** 2 for n, c in planes)


def outer_sum(rows):
    return sum(np.outer(r, r) for r in rows)


# ---------------------------------------------------------------------------------------------
# Per exercise: the expected answer and the anticipated mistakes, from the attributes
# ---------------------------------------------------------------------------------------------

def euler(ex):
    V, g, k = ex.V, ex.genus, ex.k

    def with_chi(chi):
        F = 2 * (V - chi) / (k - 2)
        return [k * F / 2, F]

    F_per_face = (V - (2 - 2 * g)) / (k - 1)
    return np.array(euler_counts(V, g, k)), {
        "genus ignored": with_chi(2),
        "no factor 2": with_chi(2 - g),
        "wrong sign": with_chi(2 + 2 * g),
        "edges counted per face": [k * F_per_face, F_per_face],
    }


def genus(ex):
    V, E, F, b = ex.V, ex.E, ex.F, ex.b
    assert 2 * E == 3 * F + ex.boundary_edges               # a triangle mesh with boundary
    chi = V - E + F
    right = (2 - b - chi) / 2
    assert right == int(right) >= 0
    return right, {
        "boundary ignored": (2 - chi) / 2,
        "no half": 2 - b - chi,
        "wrong sign": -right,
        "chi signs": (2 - b - (V + E - F)) / 2,
    }


def collapses(ex):
    i, j, V, E, F = ex.n_interior, ex.n_boundary, ex.V, ex.E, ex.F
    right = np.array([V - i - j, E - 3 * i - 2 * j, F - 2 * i - j])
    assert right[0] - right[1] + right[2] == V - E + F        # Euler's number is kept
    mistakes = {
        "two vertices removed": [V - 2 * (i + j), right[1], right[2]],
        "no vertex removed": [V, right[1], right[2]],
        "one edge per collapse": [right[0], E - i - j, right[2]],
        "one face per collapse": [right[0], right[1], F - i - j],
    }
    if j:
        mistakes["boundary as interior"] = Either([[right[0], E - 3 * (i + j), right[2]],
                                                   [right[0], right[1], F - 2 * (i + j)]])
    return right, mistakes


def manifoldness(ex):
    right = kind_by_hand(ex.faces)
    if right == "closed manifold":
        n = max(max(f) for f in ex.faces) + 1
        tris = [[f[0], f[i], f[i + 1]] for f in ex.faces for i in range(1, len(f) - 1)]
        assert trimesh.Trimesh(np.random.default_rng(1).normal(size=(n, 3)), tris,
                               process=False).is_watertight
    return right, {f"said {name}": name for name in ch06.MESH_KINDS if name != right}


def flipped(ex):
    right = flipped_by_trimesh(ex.faces)
    shared = Counter(tuple(sorted(e)) for e in cycle(ex.faces[right]))
    neighbours = [k for k, f in enumerate(ex.faces) if k != right
                  and any(tuple(sorted(e)) in shared for e in cycle(f))]
    others = [k for k in range(len(ex.faces)) if k != right and k not in neighbours]
    mistakes = {"a neighbour": Either(neighbours)}
    if others:
        mistakes["consistent face"] = Either(others)
    return right, mistakes


def winged(ex):
    # the edge list covers every edge once, in the direction of one of its faces
    assert Counter(frozenset(e) for f in ex.faces for e in cycle(f)) == \
        Counter({frozenset(e): 2 for e in ex.edges})
    lf, rf, lp, ln, rp, rn = winged_record(ex.faces, ex.edges, ex.e)
    return (lf, rf, lp, ln, rp, rn), {
        "left and right swapped": (rf, lf, rp, rn, lp, ln),
        "prev and next swapped": (lf, rf, ln, lp, rn, rp),
        "right walk reversed": (lf, rf, lp, ln, rn, rp),
        "wings of the other face": (lf, rf, rp, rn, lp, ln),
    }


def walk(ex):
    mine = half_edges_by_hand(ex.faces)
    for name in ("origin", "next", "prev", "twin", "face"):      # the table shown is right
        assert list(getattr(ex.table, name)) == mine[name], name

    def follow(ops):
        h = ex.h
        for op in ops:
            h = mine[op][h]
        return h

    g = follow(ex.ops)
    swap = {"next": "prev", "prev": "next", "twin": "twin"}
    reverse, swapped = follow(ex.ops[::-1]), follow([swap[o] for o in ex.ops])
    t = mine["target"]
    return np.array([g, t[g]]), {
        "inside out": [reverse, t[reverse]],
        "next and prev swapped": [swapped, t[swapped]],
        "origin, not target": [g, mine["origin"][g]],
    }


def one_ring(ex):
    mine = half_edges_by_hand(ex.faces)
    assert mine["origin"][ex.h] == ex.v
    right = one_ring_by_angle(ex)
    first, *rest = right
    rotations = Either([right[k:] + right[:k] for k in range(1, len(right))])
    return right, {"clockwise": tuple([first] + rest[::-1]), "wrong start": rotations}


def quadric(ex):
    planes = [plane_from(n, ex.point) for n in ex.normals]
    rows = [np.append(n, -c) for n, c in planes]
    right = outer_sum(rows)
    rng = np.random.default_rng(7)
    for x in rng.normal(size=(5, 3)):                      # v^T Q v = sum of squared distances
        assert math.isclose(np.append(x, 1) @ right @ np.append(x, 1),
                            squared_distances(planes, x), rel_tol=1e-9, abs_tol=1e-12)
    raw = [np.append(n, -(n @ ex.point)) for n in ex.normals]
    return right, {
        "not normalised": outer_sum(raw),
        "sign of d": outer_sum([np.append(n, c) for n, c in planes]),
        "summed planes first": np.outer(sum(rows), sum(rows)),
        "3x3 block": right[:3, :3],
    }


def edge_planes(ex):
    return ([plane_from(n, ex.v1) for n in ex.normals1]
            + [plane_from(n, ex.v2) for n in ex.normals2])


def cost(ex):
    planes = edge_planes(ex)
    mid = (ex.v1 + ex.v2) / 2
    right = squared_distances(planes, mid)
    A = sum(np.outer(n, n) for n, _ in planes)
    return right, {
        "no homogeneous 1": mid @ A @ mid,
        "one quadric": Either([squared_distances(planes[:2], mid),
                               squared_distances(planes[2:], mid)]),
        "averaged": right / 2,
        "square root": math.sqrt(right),
    }


def optimal(ex):
    planes = edge_planes(ex)
    N = np.array([n for n, _ in planes])
    c = np.array([c for _, c in planes])
    x, *_ = np.linalg.lstsq(N, c, rcond=None)
    right = np.array([*x, squared_distances(planes, x)])
    A = N.T @ N
    b = -N.T @ c
    wrong = np.linalg.solve(A, b)
    mid = (ex.v1 + ex.v2) / 2
    return right, {
        "sign of b": [*wrong, squared_distances(planes, wrong)],
        "midpoint": [*mid, squared_distances(planes, mid)],
        "no homogeneous 1": [*x, x @ A @ x],
    }


NUMBERS_GARBAGE = ["E", {"E": 1}, [1], [1, 2, 3, 4, 5], [[1], [2, 3]], [1, math.nan], 7.5]
NUMBER_GARBAGE = ["g", {"g": 1}, [1, 2], [[1, 2]], math.nan]
INDEX_GARBAGE = ["f0", {"f": 1}, [1, 2], 1.5, math.inf, True]
RECORD_GARBAGE = ["e", {"left_face": 1}, [1, 2, 3], [0.5] * 6, [[1, 2], [3]],
                  [math.nan] * 6, [True] * 6]
RING_GARBAGE = ["ring", {"a": 1}, [1, 2], [0.5, 1, 2, 3], [[1, 2], [3]], [True] * 4]
NAME_GARBAGE = ["torus", 3, ["closed manifold"], {"a": 1}, "manifold", b"closed manifold"]
MATRIX_GARBAGE = ["Q", {"Q": 1}, [[1, 2], [3]], np.ones(5), np.ones((5, 5)),
                  [[math.nan] * 4] * 4]
POINT4_GARBAGE = ["x", {"x": 1}, [1, 2, 3], [1, 2, 3, 4, 5], [[1, 2], [3, 4]],
                  [math.nan, 1, 2, 3]]

# class name: (independent answer and mistakes, answer form)
SPECS = {
    "EulerCounts": (euler, "numbers"),
    "GenusFromCounts": (genus, "number"),
    "EdgeCollapseCounts": (collapses, "numbers"),
    "Manifoldness": (manifoldness, "name"),
    "FlippedFace": (flipped, "index"),
    "WingedEdgeRecord": (winged, "record"),
    "HalfEdgeWalk": (walk, "numbers"),
    "OneRing": (one_ring, "ring"),
    "VertexQuadric": (quadric, "matrix"),
    "CollapseCost": (cost, "number"),
    "OptimalPosition": (optimal, "point4"),
}
GARBAGE = {"numbers": NUMBERS_GARBAGE, "number": NUMBER_GARBAGE, "index": INDEX_GARBAGE,
           "record": RECORD_GARBAGE, "ring": RING_GARBAGE, "name": NAME_GARBAGE,
           "matrix": MATRIX_GARBAGE, "point4": POINT4_GARBAGE}
DISCRETE = {"name", "index", "record", "ring"}


#: The chapter's exercises may be split over topic files: this one tests those in SPECS,
#: tests/test_exercises_ch06_*.py the others, and test_every_exercise_is_tested_in_one_file
#: holds the union to the chapter's list.
TOPIC = harness.topic(ch06, SPECS)
exercises = harness.variants(TOPIC)


def as_answer(value, form):
    if form in ("record", "ring"):
        return list(value)
    return value


def same(a, b, form):
    if form in DISCRETE:
        return a == b
    return gap(a, b) < SAME


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------

globals().update(harness.common_tests(TOPIC, SPECS, GARBAGE, exercises, at_least=10, newlines=None))
test_mistakes_are_diagnosed = harness.mistakes_test(
    SPECS, exercises, same, as_answer=as_answer,
    key_seeds=SEEDS)


@pytest.mark.parametrize("name", SPECS)
def test_right_answer_is_accepted(name):
    solve, form = SPECS[name]
    for ex in exercises(name):
        right, _ = solve(ex)
        if form == "name":
            answers = [right, right.upper(), right.replace(" ", "_")]
        elif form == "index":
            answers = [right, float(right), np.int64(right), [right]]
        elif form in ("record", "ring"):
            answers = [list(right), tuple(right), np.array(right)]
            if form == "record":
                answers.append(dict(zip(ch06.WingedEdgeRecord.fields, right)))
        else:
            answers = [right, np.round(right, 3), np.asarray(right).tolist()]
        harness.assert_accepted(ex, answers)


def test_wrong_answers_get_teaching_feedback():
    """An answer no slip explains still says how to get it right."""
    for name in ("EulerCounts", "EdgeCollapseCounts", "GenusFromCounts", "CollapseCost",
                 "OptimalPosition", "VertexQuadric", "HalfEdgeWalk"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(20)):
            right, _ = solve(ex)
            fb = ex.check(np.asarray(right) + 7.37)
            assert fb.status == "wrong" and len(fb.message) > 80, (ex, fb)
    for ex in exercises("WingedEdgeRecord", range(20)):
        right, _ = winged(ex)
        fb = ex.check([right[0], right[1]] + [ex.e] * 4)         # e is no wing of itself
        assert fb.status == "wrong" and "left_prev" in fb.message and "left_face" not in \
            fb.message.split(".")[0]


def test_manifold_feedback_names_the_evidence():
    """A wrong kind is answered with the edge or vertex that decides it."""
    for ex in exercises("Manifoldness"):
        right, _ = manifoldness(ex)
        per_edge = Counter(tuple(sorted(e)) for f in ex.faces for e in cycle(f))
        for said in ch06.MESH_KINDS:
            if said == right:
                continue
            message = ex.check(said).message
            if right == "non-manifold edge":
                crowded = [e for e, c in per_edge.items() if c > 2]
                assert any(f"({a}, {b})" in message for a, b in crowded), message
            elif right == "non-manifold vertex":
                assert "fans" in message and "vertex" in message
            elif right == "manifold with boundary" and said == "closed manifold":
                border = sum(1 for c in per_edge.values() if c == 1)
                assert f"{border} edges have only one face" in message


def test_every_kind_and_mesh_is_asked():
    assert {ex.expected for ex in exercises("Manifoldness")} == set(ch06.MESH_KINDS)
    assert {ex.shape for ex in exercises("WingedEdgeRecord")} == {
        "tetrahedron", "square pyramid", "triangular prism", "octahedron"}
    assert {ex.k for ex in exercises("EulerCounts")} == {3, 4}
    assert {ex.b for ex in exercises("GenusFromCounts")} == {0, 1, 2, 3}


def test_small_meshes_are_outward_and_consistent():
    """The shuffled meshes keep counter-clockwise faces seen from outside (trimesh)."""
    for name, make in ch06._SMALL.items():
        vertices, faces = make()
        rng = np.random.default_rng(3)
        vertices, faces = ch06._shuffled(rng, vertices, faces)
        tris = [[f[0], f[i], f[i + 1]] for f in faces for i in range(1, len(f) - 1)]
        m = trimesh.Trimesh(vertices, tris, process=False)
        assert m.is_watertight and m.is_winding_consistent and m.volume > 0, name


def test_numbers_are_nice_for_hand_work():
    for ex in exercises("VertexQuadric"):
        assert np.all(ex.point == np.round(ex.point))
        assert all(np.all(n == np.round(n)) for n in ex.normals)
    for name in ("CollapseCost", "OptimalPosition"):
        for ex in exercises(name):
            assert np.all(ex.v1 == np.round(ex.v1)) and np.all(ex.v2 == np.round(ex.v2))
            # each quadric is zero at its own vertex
            assert abs(np.append(ex.v1, 1) @ ex.Q1 @ np.append(ex.v1, 1)) < 1e-12
            assert abs(np.append(ex.v2, 1) @ ex.Q2 @ np.append(ex.v2, 1)) < 1e-12


# ---------------------------------------------------------------------------------------------
# Whole numbers, the advice once, variety
# ---------------------------------------------------------------------------------------------

#: The exercises whose answer is made of whole numbers (counts, indices), compared exactly.
WHOLE = ("EulerCounts", "GenusFromCounts", "EdgeCollapseCounts", "FlippedFace",
         "WingedEdgeRecord", "HalfEdgeWalk", "OneRing")


def one_off(right):
    """Every answer that is `right` with one entry one larger or one smaller."""
    entries = [int(v) for v in np.ravel(right)]
    for i in range(len(entries)):
        for step in (-1, 1):
            wrong = list(entries)
            wrong[i] += step
            yield wrong if np.ndim(right) else wrong[0]


@pytest.mark.parametrize("name", WHOLE)
def test_whole_numbers_are_exact_and_may_be_given_as_floats(name):
    solve, _ = SPECS[name]
    counts = name in ("EulerCounts", "GenusFromCounts", "EdgeCollapseCounts")
    off_by_one = 0
    for ex in exercises(name):
        right, mistakes = solve(ex)
        as_floats = [float(v) for v in np.ravel(right)]
        for answer in (as_floats, np.array(as_floats)) if np.ndim(right) else \
                (float(right), np.float64(right)):
            assert ex.check(answer).status == "correct", (ex, answer)
        for wrong in one_off(right):
            fb = ex.check(wrong)
            assert fb.status == "wrong", (ex, wrong, fb)
            if counts and fb.diagnosis not in mistakes:
                assert fb.diagnosis == "off by one", (ex, wrong, fb)
                off_by_one += 1
    assert not counts or off_by_one >= harness.MIN_DIAGNOSED


def test_index_answers_out_of_range_or_counted_from_one_are_wrong():
    for ex in exercises("FlippedFace", range(30)):
        for k in (-1, len(ex.faces)):
            fb = ex.check(k)
            assert (fb.status, fb.diagnosis) == ("wrong", "out of range"), (ex, fb)
            assert str(len(ex.faces) - 1) in fb.message
    for name in ("WingedEdgeRecord", "OneRing"):
        solve, _ = SPECS[name]
        for ex in exercises(name, range(30)):
            right, _ = solve(ex)
            fb = ex.check([v + 1 for v in right])
            assert (fb.status, fb.diagnosis) == ("wrong", "counted from 1"), (ex, fb)
            fb = ex.check([99] + list(right[1:]))
            assert (fb.status, fb.diagnosis) == ("wrong", "out of range"), (ex, fb)


def unexplained(ex, right, form):
    """Wrong answers no slip explains: each entry off on its own, then all entries off."""
    values = [int(v) if form in DISCRETE else float(v) for v in np.ravel(right)]
    if form == "record":
        size = len(ex.edges)
    elif form == "ring":
        size = ex.table.n_vertices
    else:
        size = None

    def shifted(v):
        return (v + 2) % size if size else v + 7.37

    for i in range(len(values)):
        yield [shifted(v) if j == i else v for j, v in enumerate(values)]
    yield [shifted(v) for v in values]


@pytest.mark.parametrize("name", ["EulerCounts", "EdgeCollapseCounts", "HalfEdgeWalk",
                                  "OptimalPosition", "WingedEdgeRecord", "OneRing"])
def test_the_advice_ends_a_wrong_verdict_at_most_once(name):
    solve, form = SPECS[name]
    _, advised = harness.advice_counts(exercises(name), solve,
                                       lambda ex, right: unexplained(ex, right, form))
    assert advised >= harness.MIN_DIAGNOSED            # the advice is given, once


#: The fewest distinct answers among 300 seeds. 30 unless the answer has few values in
#: itself: the genus (0 to 3), one of the four kinds of mesh, the index of one face of a mesh
#: of at most 8 faces. (Their questions still differ from seed to seed.)
FEWEST_ANSWERS = {"GenusFromCounts": 4, "Manifoldness": 4, "FlippedFace": 8}


@pytest.mark.parametrize("name", SPECS)
def test_seeds_give_many_different_answers(name):
    cls = getattr(ch06, name)
    answers = {harness.answer_key(cls(seed=seed).expected) for seed in range(300)}
    assert len(answers) >= FEWEST_ANSWERS.get(name, 30), (name, len(answers))


test_every_exercise_is_tested_in_one_file = harness.every_exercise_tested(
    ch06, SPECS, at_least=10)
