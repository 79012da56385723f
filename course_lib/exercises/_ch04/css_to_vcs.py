"""Chapter 4 exercises: CSS -> VCS.

Part of :mod:`course_lib.exercises.ch04`, which imports every exercise from here.
"""

import numpy as np

from ... import transforms as tf
from ... import viewing
from ..core import DECIMALS, DrawnExercise, Mistake, Worked, data_note, pick
from . import _MATRIX_4, PointAnswer, _mat, _num, _par, _vec

__all__ = [
    "ViewportMatrix",
    "ViewportPixel",
]


def _draw_viewport(ex, rng):
    ex.xmin = float(pick(rng, (0, 10, 20, 50, 100)))
    ex.ymin = float(pick(rng, (0, 20, 40, 60)))
    ex.xmax = ex.xmin + float(pick(rng, (320, 400, 640, 800)))
    ex.ymax = ex.ymin + float(pick(rng, (240, 300, 480, 600)))
    ex.zmin, ex.zmax = 0.0, 1.0


def _halves_and_centres(ex):
    """Half the size and the centre of the viewport along x, y and depth."""
    half = np.array([ex.xmax - ex.xmin, ex.ymax - ex.ymin, ex.zmax - ex.zmin]) / 2
    centre = np.array([ex.xmax + ex.xmin, ex.ymax + ex.ymin, ex.zmax + ex.zmin]) / 2
    return half, centre


def _viewport_hints(ex):
    half, centre = _halves_and_centres(ex)
    return [
        r"Each axis is mapped on its own: the cube's $-1 \dots 1$ goes onto "
        r"$x_{min} \dots x_{max}$ (and likewise for $y$ and depth), so scale by half the "
        r"viewport's size and shift to its centre.",
        rf"Half the sizes: $\frac{{x_{{max}}-x_{{min}}}}{{2}} = {_num(half[0])}$, "
        rf"$\frac{{y_{{max}}-y_{{min}}}}{{2}} = {_num(half[1])}$, "
        rf"$\frac{{z_{{max}}-z_{{min}}}}{{2}} = {_num(half[2])}$ (depth has its own range).",
        rf"The centres: $\frac{{x_{{max}}+x_{{min}}}}{{2}} = {_num(centre[0])}$, "
        rf"$\frac{{y_{{max}}+y_{{min}}}}{{2}} = {_num(centre[1])}$, "
        rf"$\frac{{z_{{max}}+z_{{min}}}}{{2}} = {_num(centre[2])}$: CSS 0 goes there.",
    ]


def _viewport_words(ex):
    return (rf"The viewport has its bottom-left corner at $(x_{{min}}, y_{{min}}) = "
            rf"({_num(ex.xmin)}, {_num(ex.ymin)})$ and its top-right corner at "
            rf"$(x_{{max}}, y_{{max}}) = ({_num(ex.xmax)}, {_num(ex.ymax)})$ (pixels, y up), "
            rf"and the depth range is $[z_{{min}}, z_{{max}}] = [{_num(ex.zmin)}, "
            rf"{_num(ex.zmax)}]$.")


class ViewportMatrix(DrawnExercise):
    r"""The CSS -> VCS matrix: scale by half the viewport's size, shift to its centre.

    Attributes: ``xmin``, ``ymin``, ``xmax``, ``ymax``, ``zmin``, ``zmax``.

    Examples
    --------
    >>> ex = ViewportMatrix(seed=11)
    >>> ex.check(ex.expected).status
    'correct'
    >>> printed = ex.expected.copy()
    >>> printed[2, 2] = (ex.ymax - ex.ymin) / 2           # the compendium's depth row
    >>> ex.check(printed).diagnosis
    'compendium depth row'
    """

    title = "The viewport matrix"

    def draw(self, rng):
        _draw_viewport(self, rng)
        self.expected = viewing.viewport(self.xmin, self.ymin, self.xmax, self.ymax, self.zmin,
                                         self.zmax)

    def mistakes(self):
        printed = self.expected.copy()
        printed[2, 2] = (self.ymax - self.ymin) / 2
        flipped = self.expected.copy()
        flipped[:3, 3] *= -1
        whole = self.expected.copy()
        whole[[0, 1, 2], [0, 1, 2]] *= 2
        y_down = self.expected.copy()
        y_down[1, 1] *= -1
        return [
            Mistake(printed, r"The depth row scales by $\frac{y_{max}-y_{min}}{2}$, as the "
                    r"compendium prints it; depth has its own range: the entry is "
                    r"$\frac{z_{max}-z_{min}}{2}$ (here it maps $[-1, 1]$ onto "
                    r"$[z_{min}, z_{max}]$).", "compendium depth row"),
            Mistake(flipped, r"The translations have the wrong sign: the centre of the cube "
                    r"(CSS 0) must go to the centre of the viewport, "
                    r"$\left(\frac{x_{max}+x_{min}}{2}, \frac{y_{max}+y_{min}}{2}, "
                    r"\frac{z_{max}+z_{min}}{2}\right)$.", "translation sign"),
            Mistake(whole, r"The scale factors are twice too large. The cube is 2 units wide "
                    r"($-1$ to $1$), so it is scaled by half the viewport's size: "
                    r"$\frac{x_{max}-x_{min}}{2}$ and so on.", "missing halves"),
            Mistake(y_down, r"You flipped y, as for an image whose rows are counted from the "
                    r"top. Here the viewport's y axis points up like CSS's, so the entry is "
                    r"$+\frac{y_{max}-y_{min}}{2}$.", "y flipped"),
        ]

    def hints(self):
        return _viewport_hints(self)

    def worked(self):
        half, centre = _halves_and_centres(self)
        M = np.diag([half[0], half[1], half[2], 1.0])
        M[:3, 3] = centre
        return Worked([
            rf"Half the sizes: $({_num(self.xmax)} - {_num(self.xmin)})/2 = {_num(half[0])}$, "
            rf"$({_num(self.ymax)} - {_num(self.ymin)})/2 = {_num(half[1])}$, "
            rf"$({_num(self.zmax)} - {_num(self.zmin)})/2 = {_num(half[2])}$: the diagonal.",
            rf"The centres: ${_vec(centre)}$: the last column (CSS 0 goes to the centre).",
            rf"$M_{{CSS \to VCS}} = {_mat(M)}$. Check: $(-1, -1, -1)$ goes to "
            rf"$({_num(self.xmin)}, {_num(self.ymin)}, {_num(self.zmin)})$.",
        ], M)

    def statement(self):
        return (
            _viewport_words(self) + r" Give the matrix $M_{CSS \to VCS}$ that maps the cube "
            r"$[-1, 1]^3$ of canonical screen space onto the viewport and the depth range "
            r"($(-1, -1, -1)$ to the bottom-left corner at depth $z_{min}$)." "\n\n"
            + _MATRIX_4 + "\n\n"
            + data_note("xmin", "ymin", "xmax", "ymax", "zmin", "zmax"))


class ViewportPixel(PointAnswer, DrawnExercise):
    r"""The viewport coordinates (pixel x, y and depth) of a point of canonical screen space.

    Attributes: ``xmin``, ``ymin``, ``xmax``, ``ymax``, ``zmin``, ``zmax``, ``q`` (the CSS point).

    Examples
    --------
    >>> ex = ViewportPixel(seed=12)
    >>> ex.check(ex.expected).status
    'correct'
    >>> x, y, z = ex.expected
    >>> ex.check([x, ex.ymin + ex.ymax - y, z]).diagnosis
    'y flipped'
    """

    title = "From CSS to the viewport"
    what = "the point in viewport coordinates"

    def draw(self, rng):
        _draw_viewport(self, rng)
        quarters = np.arange(-4, 5) / 4
        self.q = np.array([float(pick(rng, quarters)) for _ in range(3)])
        self.expected = tf.apply(viewing.viewport(self.xmin, self.ymin, self.xmax, self.ymax,
                                                  self.zmin, self.zmax), self.q)

    def mistakes(self):
        x, y, z = self.expected
        qx, qy, qz = self.q
        w, h = self.xmax - self.xmin, self.ymax - self.ymin
        return [
            Mistake([x, self.ymin + self.ymax - y, z], r"You flipped y, as if rows were counted "
                    r"from the top. The viewport's y axis points up, like CSS's: "
                    r"$y_v = \frac{y_{max}-y_{min}}{2}\,y + \frac{y_{max}+y_{min}}{2}$.",
                    "y flipped"),
            Mistake([x, y, h / 2 * qz + (self.zmin + self.zmax) / 2], r"Depth was scaled by "
                    r"half the viewport's *height*, as the compendium's matrix has it. Depth "
                    r"has its own range: $z_v = \frac{z_{max}-z_{min}}{2}\,z + "
                    r"\frac{z_{max}+z_{min}}{2}$.", "compendium depth row"),
            Mistake([x - self.xmin, y - self.ymin, z], r"The viewport does not start at pixel "
                    r"$(0, 0)$: add its corner, the translation is "
                    r"$\frac{x_{max}+x_{min}}{2}$, not $\frac{x_{max}-x_{min}}{2}$.",
                    "offset missing"),
            Mistake([w / 2 * qx + self.xmin, h / 2 * qy + self.ymin, z], r"CSS runs from $-1$ "
                    r"to $1$, so its centre 0 goes to the centre of the viewport: "
                    r"$x_v = x_{min} + \frac{w}{2}\,(x + 1)$ (you left out the $+1$).",
                    "centre shift missing"),
        ]

    def statement(self):
        return (
            _viewport_words(self) + rf" A point has the CSS coordinates $q = {_vec(self.q)}$. "
            r"Where does it land: which pixel coordinates $(x_v, y_v)$ and which depth $z_v$?"
            "\n\n" r"**Answer:** a list of 3 numbers `[x_v, y_v, z_v]` (not rounded to whole "
            r"pixels). " + DECIMALS + "\n\n"
            + data_note("xmin", "ymin", "xmax", "ymax", "zmin", "zmax", "q"))

    def hints(self):
        return _viewport_hints(self)[:2] + [
            r"So $x_v = \frac{x_{max}-x_{min}}{2}\,x + \frac{x_{max}+x_{min}}{2}$ and so on; "
            rf"for $x = {_num(self.q[0])}$ that is "
            rf"${_num(_halves_and_centres(self)[0][0])} \cdot {_par(self.q[0])} + "
            rf"{_num(_halves_and_centres(self)[1][0])}$.",
        ]

    def worked(self):
        half, centre = _halves_and_centres(self)
        point = half * self.q + centre
        names = ("x", "y", "z")
        return Worked([
            rf"Half the sizes ${_vec(half)}$ and the centres ${_vec(centre)}$ of the viewport and "
            r"the depth range.",
            ", ".join(rf"${names[k]}_v = {_num(half[k])} \cdot {_par(self.q[k])} + "
                      rf"{_num(centre[k])} = {_num(point[k])}$" for k in range(3)) + ".",
            rf"The point lands at ${_vec(point)}$ (pixels, y up, and depth).",
        ], point)
