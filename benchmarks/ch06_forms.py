"""Chapter 6, the forms of a model: conversions of a pipeline (mesh -> point cloud,
implicit -> voxels -> mesh, parametric -> mesh) against trimesh and scikit-image on the same
input. This topic has no explorer (a static figure gallery), so no widget rows."""
from benchmarks import operation_row


def operations(quick=False):
    """Area-weighted sampling of a tessellated torus against ``trimesh.sample.sample_surface``;
    marching cubes of a voxelized torus (:func:`course_lib.mesh.forms.voxels_to_mesh`) against
    ``skimage.measure.marching_cubes``; voxelizing the implicit torus against evaluating the
    same closed form with a plain numpy expression on the same grid (the cost of the wrapper)."""
    import numpy as np
    import trimesh
    from skimage import measure

    from course_lib.mesh import forms

    repeat = 2 if quick else 7
    n = 48 if quick else 96
    v, t = forms.tessellate(forms.torus_patch, 2 * n, n, wrap_u=True, wrap_v=True)
    tm = trimesh.Trimesh(v, t, process=False)
    count = 2000 if quick else 20000
    rows = [operation_row(
        f"mesh -> point cloud, {count} samples on {len(t)} triangles", count,
        lambda: forms.sample_point_cloud(v, t, count, seed=0),
        lambda: trimesh.sample.sample_surface(tm, count, seed=0),
        "trimesh.sample.sample_surface", repeat)]
    res = 32 if quick else 64
    f = lambda p: forms.implicit_torus(p, 1.0, 0.4)                  # noqa: E731
    values, _, spacing, origin = forms.voxelize(f, (-1.5,) * 3, (1.5,) * 3, res)
    rows.append(operation_row(
        f"voxels -> mesh, marching cubes of a {res}^3 torus", res ** 3,
        lambda: forms.voxels_to_mesh(values, spacing, origin),
        lambda: measure.marching_cubes(values, 0.0, spacing=tuple(spacing)),
        "skimage.measure.marching_cubes", repeat))

    def plain():
        g = origin[0] + spacing[0] * np.arange(res)
        z, y, x = np.meshgrid(g, g, g, indexing="ij")
        return np.hypot(np.hypot(x, y) - 1.0, z) - 0.4

    rows.append(operation_row(
        f"implicit -> voxels, torus on a {res}^3 grid", res ** 3,
        lambda: forms.voxelize(f, (-1.5,) * 3, (1.5,) * 3, res),
        plain, "plain numpy closed form, same grid", repeat))
    return rows


def widgets(quick=False):
    """The model forms have no explorer: no widget rows."""
    return []
