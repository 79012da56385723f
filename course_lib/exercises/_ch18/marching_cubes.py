"""Chapter 18 exercises: marching cubes.

Part of :mod:`course_lib.exercises.ch18`, which imports every exercise from here.
"""
import numpy as np

from ... import scivis
from ..core import Mistake, Worked, data_note, pick
from . import _Chapter18

__all__ = [
    "CubeTriangleCount",
]


# ---------------------------------------------------------------------------------------------
# Marching cubes
# ---------------------------------------------------------------------------------------------

def _loops(case):
    """The number of separate polygons (loops) of a case: components of its crossed edges."""
    triangles = scivis.cube_triangles(case)
    parent = list(range(13))

    def find(a):
        while parent[a] != a:
            a = parent[a]
        return a

    for tri in triangles:
        for a, b in zip(tri, tri[1:]):
            parent[find(int(a))] = find(int(b))
    return len({find(int(e)) for e in np.unique(triangles)})


def _crossed_edges(case):
    above = [(case >> k) & 1 for k in range(8)]
    return sum(above[a] != above[b] for a, b in scivis.CUBE_EDGES)


_CORNER_TABLE = ("| corner | " + " | ".join(str(k) for k in range(8)) + " |\n"
                 + "|---" * 9 + "|\n"
                 + "| $(x, y, z)$ | " + " | ".join(
                     f"$({x}, {y}, {z})$" for x, y, z in scivis.CUBE_CORNERS) + " |")


class CubeTriangleCount(_Chapter18):
    r"""How many triangles a marching-cubes case produces (cases without ambiguous faces).

    The isosurface crosses the edges between an above and a below corner; the crossings of each
    connected group form a polygon of :math:`m` vertices, cut into :math:`m - 2` triangles.

    Attributes: ``above`` (the corners above the level), ``case`` (the index).

    Examples
    --------
    >>> ex = CubeTriangleCount(seed=0)
    >>> ex.check(len(scivis.cube_triangles(ex.case))).status
    'correct'
    >>> ex.check(_crossed_edges(ex.case)).diagnosis       # the crossed edges: the vertices
    'vertices'
    """

    title = "Triangles of a marching-cubes case"
    answer_form = "number"
    what = "the number of triangles"
    may_coincide = ("one polygon", "corners", "one per polygon")
    advice = (r"Find the edges with one end above and one below; they group into polygons around "
              r"the above corners; a polygon with $m$ vertices gives $m - 2$ triangles.")

    def draw(self, rng):
        k = int(pick(rng, (1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 7)))
        self.above = tuple(sorted(int(i) for i in rng.choice(8, size=k, replace=False)))
        self.case = sum(1 << c for c in self.above)
        self.expected = len(scivis.cube_triangles(self.case))

    def acceptable(self):
        return scivis._ambiguous_faces(self.case) == 0

    def mistakes(self):
        edges, loops = _crossed_edges(self.case), _loops(self.case)
        return [
            Mistake(edges, r"That is the number of crossed edges, i.e. of **vertices**. The "
                    r"vertices form polygons; a polygon with $m$ vertices is cut into $m - 2$ "
                    r"triangles.", "vertices"),
            Mistake(edges - 2, r"You treated all the crossings as one polygon. Here they form "
                    rf"{loops} separate polygons (the above corners fall into {loops} groups "
                    r"that share no cube edge): each polygon of $m$ vertices gives $m - 2$ "
                    r"triangles.", "one polygon"),
            Mistake(len(self.above), r"The number of above corners is not the number of "
                    r"triangles: count the crossed edges (vertices), group them into polygons, "
                    r"and cut each polygon of $m$ vertices into $m - 2$ triangles.", "corners"),
            Mistake(loops, r"One triangle per polygon is only right for triangles. A polygon "
                    r"with $m$ vertices needs $m - 2$ triangles.", "one per polygon"),
        ]

    def statement(self):
        listed = (f"Corner {self.above[0]} is" if len(self.above) == 1 else
                  "Corners " + ", ".join(str(c) for c in self.above[:-1])
                  + f" and {self.above[-1]} are")
        return (
            r"A cube of a volume has its corners numbered as in the table (offsets from corner "
            r"0):" "\n\n" + _CORNER_TABLE + "\n\n"
            rf"{listed} above the isovalue, the others below. How many "
            r"triangles does marching cubes make in this cube? (No face of this cube is "
            r"ambiguous, so there is only one way to triangulate it.)" "\n\n"
            r"**Answer:** one whole number." "\n\n" + data_note("above", "case"))

    def _polygons(self):
        """The crossed edges (as corner pairs) and the polygons they form: on every face of the
        cube the two crossed edges (no face is ambiguous) are joined by one segment, and the
        segments close up into polygons. Each polygon is a list of corner pairs."""
        up = set(self.above)
        edges = [(int(a), int(b)) for a, b in scivis.CUBE_EDGES if (a in up) != (b in up)]
        corners = scivis.CUBE_CORNERS
        group = {e: e for e in edges}

        def root(e):
            while group[e] != e:
                e = group[e]
            return e

        for axis in range(3):
            for side in (0, 1):
                face = {k for k in range(8) if corners[k][axis] == side}
                on_face = [e for e in edges if set(e) <= face]
                if on_face:                      # exactly two: one segment across the face
                    group[root(on_face[0])] = root(on_face[1])
        polygons = {}
        for e in edges:
            polygons.setdefault(root(e), []).append(e)
        return edges, list(polygons.values())

    def hints(self):
        edges, polygons = self._polygons()
        return [
            r"Marching cubes puts one vertex on every edge whose two corners lie on different "
            r"sides of the isovalue; on every face the crossings are joined by a segment, the "
            r"segments close up into polygons, and a polygon with $m$ vertices is cut into "
            r"$m - 2$ triangles.",
            rf"Here {len(edges)} edges are crossed (corner pairs "
            + ", ".join(f"{a}-{b}" for a, b in edges) + r"): that many vertices.",
            (rf"The vertices form {len(polygons)} separate polygons, with "
             + " and ".join(str(len(p)) for p in polygons) + r" vertices; each gives $m - 2$ "
             r"triangles." if len(polygons) > 1 else
             rf"The vertices form one polygon with {len(polygons[0])} vertices: it gives "
             r"$m - 2$ triangles."),
        ]

    def worked(self):
        edges, polygons = self._polygons()
        counts = [len(p) - 2 for p in polygons]
        total = sum(counts)
        listed = "; ".join(
            f"polygon {i + 1} through the edges " + ", ".join(f"{a}-{b}" for a, b in p)
            + rf" ($m = {len(p)}$: ${len(p)} - 2 = {len(p) - 2}$ triangle"
            + ("s" if len(p) != 3 else "") + ")" for i, p in enumerate(polygons))
        return Worked([
            rf"The corners above are {', '.join(str(c) for c in self.above)}. A vertex lies on "
            rf"every edge from an above to a below corner: {len(edges)} edges, "
            + ", ".join(f"{a}-{b}" for a, b in edges) + ".",
            r"On each face of the cube that has crossings, exactly two of its edges are crossed "
            r"(no face is ambiguous), and a segment joins them; following the segments from face "
            r"to face closes the polygons: " + listed + ".",
            (rf"In all ${' + '.join(str(c) for c in counts)} = {total}$ triangles."
             if len(counts) > 1 else
             rf"So marching cubes makes {total} triangle{'s' if total != 1 else ''} in this "
             r"cube."),
        ], total)
