"""Chapter 6, simplification beyond edge collapse: vertex clustering against VTK's
vtkQuadricClustering, vertex decimation against VTK's decimate_pro, the point-to-mesh distance
(of the Hausdorff estimate) against trimesh's closest_point, and the comparison explorer's
slider update."""
import numpy as np

from benchmarks import operation_row


def _bumpy(subdivisions):
    from course_lib.mesh import icosphere

    v, f = icosphere(subdivisions)
    r = 1 + 0.15 * np.sin(3 * v[:, 0]) * np.cos(2 * v[:, 1]) + 0.1 * v[:, 2] ** 2
    return v * r[:, None], f


def operations(quick=False):
    """Clustering and decimation of a bumpy sphere (20k faces quick, 80k full) to a tenth,
    and the exact distance of 5k (20k) surface samples to the mesh."""
    import pyvista as pv
    import trimesh
    import vtk

    from course_lib.mesh import decimate, point_mesh_distance, sample_surface, vertex_clustering

    v, f = _bumpy(5 if quick else 6)
    m = len(f)
    poly = pv.PolyData(v, np.column_stack([np.full(m, 3), f]).ravel())
    rows = []

    def vtk_clustering():
        qc = vtk.vtkQuadricClustering()
        qc.SetInputData(poly)
        qc.SetNumberOfDivisions(40, 40, 40)
        qc.Update()
        return qc.GetOutput()

    rows.append(operation_row(f"vertex clustering, quadric representatives, 40 cells across "
                              f"({m:,} faces)", m,
                              lambda: vertex_clustering(v, f, cells=40, representative="quadric"),
                              vtk_clustering, "VTK vtkQuadricClustering", 2 if quick else 5))
    target = m // 10
    rows.append(operation_row(f"vertex decimation to {target:,} faces ({m:,} faces)", m,
                              lambda: decimate(v, f, target),
                              lambda: poly.decimate_pro(0.9, preserve_topology=True),
                              "VTK decimate_pro (pyvista)", 1 if quick else 2))
    n = 5000 if quick else 20000
    coarse = vertex_clustering(v, f, cells=40)
    pts = sample_surface(coarse.vertices, coarse.faces, n, seed=0)[0]
    mesh = trimesh.Trimesh(v, f, process=False)
    rows.append(operation_row(f"exact distance of {n:,} surface samples to the mesh "
                              f"({m:,} faces)", n, lambda: point_mesh_distance(pts, v, f),
                              lambda: trimesh.proximity.closest_point(mesh, pts),
                              "trimesh closest_point (rtree)", 1 if quick else 3))
    return rows


def widgets(quick=False):
    """Median update of the comparison explorer's face-count slider (precomputed meshes:
    three copies into VTK polydata and one off-screen render)."""
    from benchmarks import widget_row
    from course_lib.widgets import simplification_compare as sc

    explorer = sc.SimplificationComparisonExplorer()
    levels = sc.LEVELS
    repeat = 5 if quick else 40
    return [widget_row("simplification comparison explorer (face-count slider)",
                       lambda i: setattr(explorer.faces, "value", levels[i % len(levels)]),
                       lambda: explorer.picture("jpeg"), repeat)]
