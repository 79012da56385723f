"""Chapter 6: building mesh connectivity, and QEM simplification, against trimesh, OpenMesh and
fast-simplification.

References, and why they are fair:

* "build the adjacency": our ``HalfEdgeMesh.from_faces`` matches the two halves of every edge,
  links the boundary, and checks the input (non-manifold edges and vertices, winding). trimesh's
  ``Trimesh(vertices, faces, process=False)`` followed by ``face_adjacency`` and
  ``edges_unique`` does the comparable numpy work (unique edges by sorting, the face pairs across
  each edge) without the manifold checks; OpenMesh's ``TriMesh(points, faces)`` builds a real
  half-edge structure face by face in C++ (with its own manifold checks on insertion).
* simplification: fast-simplification (Fast-Quadric-Mesh-Simplification, C++) runs the same
  Garland-Heckbert quadric metric on the same input and target. Ours is a Python loop over the
  collapses, with numpy for the set-up; the target is under 5 s for 20,000 -> 2,000 faces.

The topic files of the chapter follow: the model forms' conversions (ch06_forms), clustering,
vertex decimation and Hausdorff distances against VTK and trimesh (ch06_decimation), levels of
detail and progressive meshes (ch06_lod).
"""
import numpy as np

from benchmarks import operation_row


def _bumpy_sphere(subdivisions):
    """An icosphere with a smooth radial bump pattern (so that the quadrics have work to do)."""
    from course_lib import mesh

    v, f = mesh.icosphere(subdivisions)
    scale = 1 + 0.15 * np.sin(3 * v[:, 0]) * np.sin(4 * v[:, 1]) * np.sin(2 * v[:, 2] + 1)
    return v * scale[:, None], f


def operations(quick=False):
    import fast_simplification
    import openmesh
    import trimesh

    from course_lib import mesh

    build_level, simplify_level = (3, 3) if quick else (6, 5)
    repeat = 3 if quick else 7
    v, f = mesh.icosphere(build_level)                       # 81,920 faces when not quick
    sv, sf = _bumpy_sphere(simplify_level)                   # 20,480 faces when not quick
    target = 200 if quick else 2_000
    reduction = 1 - target / len(sf)
    sv32, sf32 = sv.astype(np.float32), sf.astype(np.int32)

    def trimesh_adjacency():
        t = trimesh.Trimesh(v, f, process=False)
        return t.face_adjacency, t.edges_unique

    rows = [
        operation_row("half-edge build (icosphere)", len(f),
                      lambda: mesh.HalfEdgeMesh.from_faces(v, f), trimesh_adjacency,
                      "trimesh Trimesh + face_adjacency + edges_unique", repeat),
        operation_row("half-edge build (icosphere)", len(f),
                      lambda: mesh.HalfEdgeMesh.from_faces(v, f),
                      lambda: openmesh.TriMesh(v, f), "OpenMesh TriMesh(points, faces)", repeat),
        operation_row("winged-edge build (icosphere)", len(f),
                      lambda: mesh.WingedEdgeMesh.from_faces(v, f), trimesh_adjacency,
                      "trimesh Trimesh + face_adjacency + edges_unique", repeat),
        operation_row(f"QEM simplification to {target:,} faces", len(sf),
                      lambda: mesh.simplify_qem(sv, sf, target),
                      lambda: fast_simplification.simplify(sv32, sf32,
                                                           target_reduction=reduction),
                      "fast-simplification (C++)", 1 if not quick else repeat),
    ]
    for topic in _topics():
        rows += topic.operations(quick)
    return rows


def _topics():
    from benchmarks import ch06_decimation, ch06_forms, ch06_lod

    return (ch06_forms, ch06_decimation, ch06_lod,)


def widgets(quick=False):
    """Median update of each chapter-6 explorer: a half-edge step (blitted), a face-count move
    of the simplification replay (pyvista off screen, JPEG), a mesh change in the Euler
    explorer (a full mesh rebuild and count)."""
    import matplotlib

    matplotlib.use("module://ipympl.backend_nbagg")
    import matplotlib.pyplot as plt

    from benchmarks import widget_row
    from course_lib.widgets import euler, mesh_structure, simplification

    repeat = 5 if quick else 40
    rows = []
    ex = mesh_structure.HalfEdgeExplorer()
    ex.fig.canvas.draw()
    names = ("next", "opposite", "next", "previous", "opposite")
    rows.append(widget_row("half-edge explorer (step button)",
                           lambda i: ex.step(names[i % len(names)]), ex.fig.canvas.draw, repeat))
    plt.close(ex.fig)
    sx = simplification.SimplificationExplorer()
    rows.append(widget_row("simplification explorer (face-count slider, pyvista off screen)",
                           lambda i: setattr(sx.faces, "value", 1200 - 2 * (37 * i % 550)),
                           lambda: sx.png(), repeat))
    sx.plotter.close()
    eu = euler.EulerExplorer()
    eu.fig.canvas.draw()
    choices = list(euler.MESHES)
    rows.append(widget_row("Euler explorer (mesh choice)",
                           lambda i: setattr(eu.choice, "value", choices[i % len(choices)]),
                           eu.fig.canvas.draw, repeat))
    plt.close(eu.fig)
    for topic in _topics():
        rows += topic.widgets(quick)
    return rows
