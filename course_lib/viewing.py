r"""Chapter 4: projections and the viewing transformation (WCS -> ECS -> CSS -> VCS).

A point of the world coordinate system (WCS) reaches the screen in three steps, each a 4x4
matrix (column vectors, :math:`p' = M p`):

1. :func:`look_at` moves the world into the **eye coordinate system** (ECS): the eye at the
   origin, :math:`x_e` to the right, :math:`y_e` up, and :math:`z_e` pointing *towards the
   viewer*, so the camera looks down :math:`-z_e` (right-handed, as in the textbook and OpenGL).
2. :func:`perspective`, :func:`frustum` or :func:`orthographic` map the view volume onto the
   **canonical screen space** (CSS), the cube :math:`[-1, 1]^3`, after the homogeneous divide.
   The near plane goes to :math:`z = -1` and the far plane to :math:`z = +1`: in CSS depth grows
   *away* from the viewer (CSS is left-handed; OpenGL's normalized device coordinates agree).
3. :func:`viewport` maps CSS onto the pixels (and depth range) of the **viewport** (VCS).

**Near and far.** These functions take ``near`` and ``far`` as positive *distances* in front of
the eye, as OpenGL does. The textbook instead writes the planes as :math:`z_e = n` and
:math:`z_e = f` with *signed* coordinates; since the eye looks down :math:`-z_e`, its
:math:`n = -\text{near}` and :math:`f = -\text{far}` are negative, and :math:`f < n`. Both give
the same matrices once this substitution is made.

The textbook's simple projections are here too: :func:`simple_perspective` (:math:`P_{PER}`,
projection onto the plane :math:`z = d`), :func:`orthographic_xy` (:math:`P_{ORTHO}`) and
:func:`oblique` (:math:`P_{OBLI}`).
"""
import numpy as np

from . import transforms
from ._validate import as_matrix, as_scalar, as_vector

__all__ = [
    "cross_ratio",
    "frustum",
    "look_at",
    "oblique",
    "orthographic",
    "orthographic_xy",
    "perspective",
    "simple_perspective",
    "to_screen",
    "viewport",
]


def look_at(eye, gaze, up):
    r"""The WCS -> ECS matrix of a camera at `eye` looking along the direction `gaze`.

    The ECS axes, in world coordinates:

    .. math:: z_e = -\frac{g}{\lVert g \rVert}, \qquad
              x_e = \frac{up \times z_e}{\lVert up \times z_e \rVert}, \qquad
              y_e = z_e \times x_e

    (`up` need not be perpendicular to `gaze`: only its component perpendicular to it matters).
    A point :math:`p` has eye coordinates :math:`(x_e \cdot (p - E),\ y_e \cdot (p - E),\
    z_e \cdot (p - E))`, that is

    .. math:: M_{WCS \to ECS} = \begin{bmatrix} x_e^T & -x_e \cdot E \\ y_e^T & -y_e \cdot E
              \\ z_e^T & -z_e \cdot E \\ 0\;0\;0 & 1 \end{bmatrix}
              = R \, T(-E), \qquad R = \begin{bmatrix} x_e^T & 0 \\ y_e^T & 0 \\ z_e^T & 0
              \\ 0 & 1 \end{bmatrix}

    (translate the eye to the origin, then rotate the ECS axes onto x, y, z; the rows of R are
    the ECS axes because R is the inverse, i.e. the transpose, of the rotation whose columns
    they are).

    Parameters
    ----------
    eye : array_like, shape (3,)
        The position of the eye E (the centre of projection).
    gaze : array_like, shape (3,)
        The direction of view g (a direction, not a target point).
    up : array_like, shape (3,)
        A vector pointing "up" in the picture; must not be parallel to `gaze`.

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If `gaze` or `up` is zero, or `up` is parallel to `gaze` (the camera's roll would be
        undefined).

    Examples
    --------
    >>> import numpy as np
    >>> M = look_at(eye=[0, 0, 5], gaze=[0, 0, -1], up=[0, 1, 0])
    >>> transforms.apply(M, [0, 0, 0])        # the origin is 5 units in front of the eye
    array([ 0.,  0., -5.])
    """
    e = as_vector(eye, "eye", 3)
    g = as_vector(gaze, "gaze", 3)
    u = as_vector(up, "up", 3)
    if not np.any(g):
        raise ValueError("gaze must not be the zero vector: it is the direction of view")
    if not np.any(u):
        raise ValueError("up must not be the zero vector")
    z_e = -g / np.linalg.norm(g)
    x_dir = np.cross(u, z_e)
    if np.linalg.norm(x_dir) < 1e-9 * np.linalg.norm(u):
        raise ValueError("up must not be parallel to gaze: the camera's sideways direction "
                         "(up x z_e) would be zero, so its roll is undefined")
    x_e = x_dir / np.linalg.norm(x_dir)
    y_e = np.cross(z_e, x_e)
    m = np.eye(4)
    m[:3, :3] = np.array([x_e, y_e, z_e])
    m[:3, 3] = -m[:3, :3] @ e
    return m


def _check_depths(near, far):
    near = as_scalar(near, "near")
    far = as_scalar(far, "far")
    if near <= 0:
        raise ValueError(f"near must be a positive distance in front of the eye, got {near}")
    if far <= near:
        raise ValueError(f"far must be greater than near (got near = {near}, far = {far})")
    return near, far


def _check_extent(low, high, low_name, high_name):
    low = as_scalar(low, low_name)
    high = as_scalar(high, high_name)
    if high <= low:
        raise ValueError(f"{high_name} must be greater than {low_name} "
                         f"(got {low_name} = {low}, {high_name} = {high})")
    return low, high


def frustum(left, right, bottom, top, near, far):
    r"""The ECS -> CSS matrix of a perspective view volume (a truncated pyramid).

    The window :math:`[l, r] \times [b, t]` lies on the near plane :math:`z_e = -\text{near}`;
    the pyramid's apex is the eye. With :math:`n = \text{near}`, :math:`f = \text{far}`:

    .. math:: M_{PERSP} = \begin{bmatrix}
              \frac{2n}{r-l} & 0 & \frac{r+l}{r-l} & 0 \\
              0 & \frac{2n}{t-b} & \frac{t+b}{t-b} & 0 \\
              0 & 0 & -\frac{f+n}{f-n} & -\frac{2fn}{f-n} \\
              0 & 0 & -1 & 0 \end{bmatrix}

    The last row makes :math:`w = -z_e`, the distance in front of the eye; dividing by it is the
    perspective foreshortening. After the divide, the near window lands on :math:`z = -1` and
    the far plane on :math:`z = +1`, and the 8 corners of the frustum land exactly on the corners
    of the cube :math:`[-1, 1]^3`. In the textbook's signed notation (:math:`z_e = n_s, f_s`
    with :math:`n_s = -n`, :math:`f_s = -f`) the same matrix reads
    :math:`\big[\frac{2n_s}{r-l}, 0, -\frac{r+l}{r-l}, 0;\ 0, \frac{2n_s}{t-b},
    -\frac{t+b}{t-b}, 0;\ 0, 0, \frac{f_s+n_s}{f_s-n_s}, -\frac{2 f_s n_s}{f_s-n_s};\
    0, 0, 1, 0\big]` up to an overall factor :math:`-1`, which the homogeneous divide cancels.

    Parameters
    ----------
    left, right, bottom, top : float
        The window on the near plane, in eye coordinates (``left < right``, ``bottom < top``).
    near, far : float
        Positive distances of the near and far planes in front of the eye (``0 < near < far``).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If ``left >= right``, ``bottom >= top``, ``near <= 0`` or ``far <= near``.

    Examples
    --------
    >>> import numpy as np
    >>> M = frustum(-1, 1, -1, 1, 1, 10)
    >>> transforms.apply(M, [[-1, -1, -1], [10, 10, -10]])    # near and far corners
    array([[-1., -1., -1.],
           [ 1.,  1.,  1.]])
    """
    l, r = _check_extent(left, right, "left", "right")
    b, t = _check_extent(bottom, top, "bottom", "top")
    n, f = _check_depths(near, far)
    return np.array([
        [2 * n / (r - l), 0.0, (r + l) / (r - l), 0.0],
        [0.0, 2 * n / (t - b), (t + b) / (t - b), 0.0],
        [0.0, 0.0, -(f + n) / (f - n), -2 * f * n / (f - n)],
        [0.0, 0.0, -1.0, 0.0],
    ])


def perspective(fov_y, aspect, near, far):
    r"""The ECS -> CSS matrix of a symmetric perspective view volume.

    The vertical field of view :math:`\theta` and the aspect ratio (width / height) give the
    window on the near plane: :math:`t = n \tan\frac{\theta}{2}`, :math:`b = -t`,
    :math:`r = t \cdot \text{aspect}`, :math:`l = -r`; then it is :func:`frustum`.

    Parameters
    ----------
    fov_y : float
        Vertical field of view in radians, in (0, pi).
    aspect : float
        Width / height of the window, positive.
    near, far : float
        Positive distances of the near and far planes (``0 < near < far``).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        For a field of view outside (0, pi), a non-positive aspect, ``near <= 0`` or
        ``far <= near``.

    Examples
    --------
    >>> import numpy as np
    >>> M = perspective(np.radians(90), 2.0, 1.0, 100.0)
    >>> np.round(transforms.apply(M, [2.0, 1.0, -1.0]), 12)    # top-right corner of the window
    array([ 1.,  1., -1.])
    """
    fov = as_scalar(fov_y, "fov_y")
    if not 0 < fov < np.pi:
        raise ValueError(f"fov_y must be an angle in radians between 0 and pi, got {fov}")
    aspect = as_scalar(aspect, "aspect")
    if aspect <= 0:
        raise ValueError(f"aspect must be positive (width / height), got {aspect}")
    n, f = _check_depths(near, far)
    t = n * np.tan(fov / 2)
    r = t * aspect
    return frustum(-r, r, -t, t, n, f)


def orthographic(left, right, bottom, top, near, far):
    r"""The ECS -> CSS matrix of a parallel view volume (a box).

    The box :math:`[l, r] \times [b, t] \times [-f, -n]` of eye space is scaled and translated
    onto :math:`[-1, 1]^3`, the near face to :math:`z = -1` and the far face to :math:`z = +1`:

    .. math:: M_{ORTHO} = \begin{bmatrix}
              \frac{2}{r-l} & 0 & 0 & -\frac{r+l}{r-l} \\
              0 & \frac{2}{t-b} & 0 & -\frac{t+b}{t-b} \\
              0 & 0 & -\frac{2}{f-n} & -\frac{f+n}{f-n} \\
              0 & 0 & 0 & 1 \end{bmatrix}

    With the textbook's signed planes :math:`z_e = n_s = -n` and :math:`z_e = f_s = -f` the
    third row is the textbook's :math:`\big[0, 0, \frac{2}{f_s-n_s}, -\frac{n_s+f_s}{f_s-n_s}\big]`.

    Parameters
    ----------
    left, right, bottom, top : float
        The extent of the box across the view (``left < right``, ``bottom < top``).
    near, far : float
        Distances of the near and far faces in front of the eye (``0 < near < far``).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If ``left >= right``, ``bottom >= top``, ``near <= 0`` or ``far <= near``.

    Examples
    --------
    >>> M = orthographic(-2, 2, -1, 1, 1, 11)
    >>> transforms.apply(M, [[2, 1, -1], [-2, -1, -11]])
    array([[ 1.,  1., -1.],
           [-1., -1.,  1.]])
    """
    l, r = _check_extent(left, right, "left", "right")
    b, t = _check_extent(bottom, top, "bottom", "top")
    n, f = _check_depths(near, far)
    return np.array([
        [2 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
        [0.0, 2 / (t - b), 0.0, -(t + b) / (t - b)],
        [0.0, 0.0, -2 / (f - n), -(f + n) / (f - n)],
        [0.0, 0.0, 0.0, 1.0],
    ])


def simple_perspective(d):
    r"""The textbook's :math:`P_{PER}`: perspective projection onto the plane :math:`z = d`.

    The centre of projection is the origin and the plane of projection is :math:`z = d`
    (:math:`d` is the distance from the centre to the plane, not a distance from the point).
    By similar triangles a point :math:`(x, y, z)` projects to :math:`(xd/z,\ yd/z,\ d)`:

    .. math:: P_{PER} = \begin{bmatrix} d & 0 & 0 & 0 \\ 0 & d & 0 & 0 \\ 0 & 0 & d & 0 \\
              0 & 0 & 1 & 0 \end{bmatrix}, \qquad
              P_{PER} \begin{bmatrix} x \\ y \\ z \\ 1 \end{bmatrix} =
              \begin{bmatrix} xd \\ yd \\ zd \\ z \end{bmatrix} \to
              \begin{bmatrix} xd/z \\ yd/z \\ d \end{bmatrix}

    The matrix is singular (depth is lost: every point of a ray through the origin lands on the
    same image point), and points with :math:`z = 0` have no image.

    Parameters
    ----------
    d : float
        Distance of the plane of projection from the centre of projection (non-zero).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If `d` is 0.

    Examples
    --------
    >>> transforms.apply(simple_perspective(2), [3, 6, 4])
    array([1.5, 3. , 2. ])
    """
    d = as_scalar(d, "d")
    if d == 0:
        raise ValueError("d must not be 0: the plane of projection cannot contain the centre "
                         "of projection")
    return np.array([[d, 0, 0, 0], [0, d, 0, 0], [0, 0, d, 0], [0, 0, 1, 0]], dtype=float)


def oblique(dop, keep_depth=False):
    r"""The textbook's :math:`P_{OBLI}`: parallel projection along `dop` onto the xy plane.

    Every point slides along the direction of projection :math:`DOP` until :math:`z = 0`:
    :math:`p - \frac{z}{DOP_z} DOP`, so

    .. math:: P_{OBLI} = \begin{bmatrix} 1 & 0 & -\frac{DOP_x}{DOP_z} & 0 \\
              0 & 1 & -\frac{DOP_y}{DOP_z} & 0 \\ 0 & 0 & 0 & 0 \\ 0 & 0 & 0 & 1 \end{bmatrix}

    With :math:`DOP = (0, 0, \pm 1)` it is the orthographic projection :func:`orthographic_xy`.
    The cavalier (:math:`DOP` at 45° to the plane: depth drawn at full length) and cabinet (depth
    at half length) projections are the classic oblique ones.

    For an oblique *camera* the depth must survive for the depth test: with
    ``keep_depth=True`` the matrix keeps z (the entry :math:`(3, 3)` is 1), which makes it a
    shear that turns the direction of projection into the z axis; follow it with
    :func:`orthographic` to map the sheared box onto the canonical cube.

    Parameters
    ----------
    dop : array_like, shape (3,)
        The direction of projection; its z component must not be 0 (a direction parallel to the
        plane never reaches it).
    keep_depth : bool, optional
        Keep z instead of flattening onto the plane (default False: the textbook's matrix).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        If ``dop[2] == 0``.

    Examples
    --------
    >>> oblique([1, 0, -1]) @ [0, 0, -2, 1]      # (0, 0, -2) slides 2 units along x
    array([-2.,  0.,  0.,  1.])
    >>> oblique([1, 0, -1], keep_depth=True) @ [0, 0, -2, 1]
    array([-2.,  0., -2.,  1.])
    """
    v = as_vector(dop, "dop", 3)
    if not np.any(v) or abs(v[2]) <= 1e-12 * np.linalg.norm(v):
        raise ValueError("dop must have a non-zero z component: a direction parallel to the xy "
                         "plane never reaches it")
    m = np.eye(4)
    m[0, 2] = -v[0] / v[2]
    m[1, 2] = -v[1] / v[2]
    if not keep_depth:
        m[2, 2] = 0.0
    return m


def orthographic_xy():
    r"""The textbook's :math:`P_{ORTHO}`: orthographic projection onto the xy plane.

    .. math:: P_{ORTHO} = \begin{bmatrix} 1 & 0 & 0 & 0 \\ 0 & 1 & 0 & 0 \\ 0 & 0 & 0 & 0 \\
              0 & 0 & 0 & 1 \end{bmatrix}

    It simply drops z. (Renderers keep z for the depth test, which is why the viewing pipeline
    uses :func:`orthographic` instead, which maps depth into [-1, 1] rather than discarding it.)

    Returns
    -------
    ndarray, shape (4, 4)

    Examples
    --------
    >>> orthographic_xy() @ [1, 2, 3, 1]
    array([1., 2., 0., 1.])
    """
    return np.diag([1.0, 1.0, 0.0, 1.0])


def viewport(xmin, ymin, xmax, ymax, zmin=0.0, zmax=1.0):
    r"""The CSS -> VCS matrix: the cube :math:`[-1, 1]^3` onto a viewport and a depth range.

    Each axis is scaled by half the target's size and shifted to its centre:

    .. math:: M_{CSS \to VCS} = \begin{bmatrix}
              \frac{x_{max}-x_{min}}{2} & 0 & 0 & \frac{x_{max}+x_{min}}{2} \\
              0 & \frac{y_{max}-y_{min}}{2} & 0 & \frac{y_{max}+y_{min}}{2} \\
              0 & 0 & \frac{z_{max}-z_{min}}{2} & \frac{z_{max}+z_{min}}{2} \\
              0 & 0 & 0 & 1 \end{bmatrix}

    (The compendium prints :math:`\frac{y_{max}-y_{min}}{2}` in the third row, which scales
    depth by the viewport's height; the depth range is its own.)

    Parameters
    ----------
    xmin, ymin, xmax, ymax : float
        The viewport's bottom-left and top-right corners, in pixels.
    zmin, zmax : float, optional
        The depth range (default [0, 1], as a depth buffer stores it).

    Returns
    -------
    ndarray, shape (4, 4)

    Raises
    ------
    ValueError
        For a viewport of zero or negative width or height, or ``zmax <= zmin``.

    Examples
    --------
    >>> import numpy as np
    >>> M = viewport(0, 0, 640, 480)
    >>> transforms.apply(M, [[-1, -1, -1], [1, 1, 1], [0, 0, 0]]).tolist()
    [[0.0, 0.0, 0.0], [640.0, 480.0, 1.0], [320.0, 240.0, 0.5]]
    """
    x0, x1 = _check_extent(xmin, xmax, "xmin", "xmax")
    y0, y1 = _check_extent(ymin, ymax, "ymin", "ymax")
    z0, z1 = _check_extent(zmin, zmax, "zmin", "zmax")
    return np.array([
        [(x1 - x0) / 2, 0.0, 0.0, (x1 + x0) / 2],
        [0.0, (y1 - y0) / 2, 0.0, (y1 + y0) / 2],
        [0.0, 0.0, (z1 - z0) / 2, (z1 + z0) / 2],
        [0.0, 0.0, 0.0, 1.0],
    ])


def to_screen(points, view, projection, viewport_matrix):
    r"""World points through the whole pipeline: :math:`M_{VCS} \cdot \text{divide}(M_{proj}
    M_{view}\, p)`.

    Parameters
    ----------
    points : array_like, shape (..., 3)
        Points in world coordinates.
    view, projection, viewport_matrix : array_like, shape (4, 4)
        From :func:`look_at`, from :func:`perspective` (or another ECS -> CSS matrix), and from
        :func:`viewport`.

    Returns
    -------
    ndarray, shape (..., 3)
        Pixel x, y and depth.

    Raises
    ------
    ValueError
        If a point lies in the plane of the eye (w = 0): it has no image.

    Examples
    --------
    >>> import numpy as np
    >>> V = look_at([0, 0, 5], [0, 0, -1], [0, 1, 0])
    >>> P = perspective(np.radians(90), 1.0, 1.0, 10.0)
    >>> to_screen([0, 0, 0], V, P, viewport(0, 0, 100, 100)).round(3)   # centre of the image
    array([50.   , 50.   ,  0.889])
    """
    v = as_matrix(view, "view", 4)
    p = as_matrix(projection, "projection", 4)
    w = as_matrix(viewport_matrix, "viewport_matrix", 4)
    return transforms.apply(w, transforms.apply(p @ v, points))


def cross_ratio(a, b, c, d):
    r"""The cross ratio of four collinear points, the invariant of projective maps.

    .. math:: (A, B; C, D) = \frac{\overline{AC} \cdot \overline{BD}}
              {\overline{BC} \cdot \overline{AD}}

    with signed distances along the common line. Perspective projection changes lengths and
    even their ratios, but not this ratio of ratios.

    Parameters
    ----------
    a, b, c, d : array_like, shape (n,)
        Four distinct collinear points (2D or 3D).

    Returns
    -------
    float

    Raises
    ------
    ValueError
        If the points are not collinear, or B = C or A = D.

    Examples
    --------
    >>> cross_ratio([0, 0], [1, 0], [2, 0], [3, 0])      # (2 * 2) / (1 * 3)
    1.3333333333333333
    """
    given = [as_vector(p, name, (2, 3)) for p, name in zip((a, b, c, d), "abcd")]
    if len({p.size for p in given}) != 1:
        raise ValueError("a, b, c and d must all be 2D or all 3D points")
    pts = np.array(given)
    direction = pts[3] - pts[0]
    length = np.linalg.norm(direction)
    if length == 0:
        raise ValueError("a and d must be distinct points")
    u = direction / length
    offsets = pts - pts[0]
    s = offsets @ u
    if np.abs(offsets - np.outer(s, u)).max() > 1e-9 * max(1.0, np.abs(pts).max()):
        raise ValueError("the four points must lie on one straight line")
    ac, bd, bc, ad = s[2] - s[0], s[3] - s[1], s[2] - s[1], s[3] - s[0]
    if bc == 0:
        raise ValueError("b and c must be distinct points")
    return float(ac * bd / (bc * ad))
