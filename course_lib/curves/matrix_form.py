r"""Chapter 7 (cubic curves): the matrix form :math:`P(t) = T\,M\,G` and changes of basis.

Every cubic segment is a polynomial :math:`P(t) = a t^3 + b t^2 + c t + d`; a *form* of cubic
describes it by four geometric quantities G (control points, or end points and tangents) and a
4x4 **basis matrix** M with

.. math:: P(t) = T\, M\, G, \qquad T = [t^3,\ t^2,\ t,\ 1],

where G holds the four geometric quantities as rows (shape (4, d)). The rows of
:math:`M G` are the coefficients a, b, c, d; the columns of :math:`T M` are the four blending
functions. Changing form keeps the curve: :math:`M_1 G_1 = M_2 G_2`, so
:math:`G_2 = M_2^{-1} M_1 G_1`.
"""

import numpy as np

from .._validate import as_array, as_choice, as_whole

__all__ = ["BASIS_NAMES", "basis_functions", "basis_matrix", "convert_geometry",
           "cubic_matrix_eval", "power_row"]

BASIS_NAMES = ("bezier", "hermite", "bspline", "catmull-rom")

_MATRICES = {
    # G = [P0, P1, P2, P3]: the Bernstein polynomials (1-t)^3, 3t(1-t)^2, 3t^2(1-t), t^3
    "bezier": np.array([[-1, 3, -3, 1],
                        [3, -6, 3, 0],
                        [-3, 3, 0, 0],
                        [1, 0, 0, 0]], float),
    # G = [P0, P1, P0', P1']: end points and end tangents
    "hermite": np.array([[2, -2, 1, 1],
                         [-3, 3, -2, -1],
                         [0, 0, 1, 0],
                         [1, 0, 0, 0]], float),
    # G = [P_{i-1}, P_i, P_{i+1}, P_{i+2}]: one span of the uniform cubic B-spline
    "bspline": np.array([[-1, 3, -3, 1],
                         [3, -6, 3, 0],
                         [-3, 0, 3, 0],
                         [1, 4, 1, 0]], float) / 6.0,
    # G = [P_{i-1}, P_i, P_{i+1}, P_{i+2}]: from P_i to P_{i+1}, tangents (P_{i+1} - P_{i-1}) / 2
    "catmull-rom": np.array([[-1, 3, -3, 1],
                             [2, -5, 4, -1],
                             [-1, 0, 1, 0],
                             [0, 2, 0, 0]], float) / 2.0,
}


def basis_matrix(name):
    r"""The 4x4 basis matrix M of a cubic form, for :math:`P(t) = [t^3, t^2, t, 1]\, M\, G`.

    =============  =======================================  ================================
    name           geometry G (rows)                        M
    =============  =======================================  ================================
    "bezier"       P0, P1, P2, P3                           [[-1,3,-3,1],[3,-6,3,0],
                                                            [-3,3,0,0],[1,0,0,0]]
    "hermite"      P(0), P(1), P'(0), P'(1)                 [[2,-2,1,1],[-3,3,-2,-1],
                                                            [0,0,1,0],[1,0,0,0]]
    "bspline"      P_{i-1}, P_i, P_{i+1}, P_{i+2}           1/6 [[-1,3,-3,1],[3,-6,3,0],
                                                            [-3,0,3,0],[1,4,1,0]]
    "catmull-rom"  P_{i-1}, P_i, P_{i+1}, P_{i+2}           1/2 [[-1,3,-3,1],[2,-5,4,-1],
                                                            [-1,0,1,0],[0,2,0,0]]
    =============  =======================================  ================================

    Derivation (Hermite): with :math:`P(t) = T C`, the four conditions are the rows
    :math:`[0,0,0,1] C = P(0)`, :math:`[1,1,1,1] C = P(1)`, :math:`[0,0,1,0] C = P'(0)`,
    :math:`[3,2,1,0] C = P'(1)`; stacking them, :math:`A C = G`, so :math:`M = A^{-1}`.
    Bézier: expand the Bernstein polynomials and read off the coefficients of
    :math:`t^3, t^2, t, 1` (column i of M belongs to :math:`P_i`).

    Some books write :math:`T = [1, t, t^2, t^3]`: their M is this one with its rows in
    reverse order.

    Parameters
    ----------
    name : {"bezier", "hermite", "bspline", "catmull-rom"}

    Returns
    -------
    ndarray, shape (4, 4)
        A fresh copy.

    Examples
    --------
    >>> basis_matrix("hermite")[0]
    array([ 2., -2.,  1.,  1.])
    >>> basis_matrix("bspline").sum(axis=1) * 6     # blending functions sum to 1: [0,0,0,6]
    array([0., 0., 0., 6.])
    """
    return _MATRICES[as_choice(name, "name", BASIS_NAMES)].copy()


def _basis_or_matrix(value, name="M"):
    if isinstance(value, str):
        return basis_matrix(value)
    m = as_array(value, name)
    if m.shape != (4, 4):
        raise ValueError(f"{name} must be a basis name {BASIS_NAMES} or a 4x4 matrix, got "
                         f"shape {m.shape}")
    return m


def power_row(t, order=0):
    r"""The row :math:`T = [t^3, t^2, t, 1]` (or its `order`-th derivative) for each t.

    Differentiating the curve only differentiates T:
    :math:`P'(t) = [3t^2, 2t, 1, 0]\, M G`, :math:`P''(t) = [6t, 2, 0, 0]\, M G`.

    Parameters
    ----------
    t : float or array_like
    order : int, default 0
        0..3 (higher derivatives of a cubic vanish: zeros).

    Returns
    -------
    ndarray, shape t.shape + (4,)

    Examples
    --------
    >>> power_row(0.5)
    array([0.125, 0.25 , 0.5  , 1.   ])
    >>> power_row(0.5, order=1)
    array([0.75, 1.  , 1.  , 0.  ])
    """
    t = as_array(t, "t")
    k = as_whole(order, "order", 0, at_least=True)
    cols = []
    for power in (3, 2, 1, 0):
        if k > power:
            cols.append(np.zeros_like(t))
            continue
        factor = np.prod(np.arange(power - k + 1, power + 1), dtype=float)
        cols.append(factor * t ** (power - k))
    return np.stack(cols, axis=-1)


def _cubic_geometry(value, name="G"):
    g = as_array(value, name)
    if g.ndim != 2 or g.shape[0] != 4 or g.shape[1] < 1:
        raise ValueError(f"{name} must hold the 4 geometric quantities as rows, shape (4, d), "
                         f"got shape {g.shape}")
    return g


def cubic_matrix_eval(basis, G, t, order=0):
    r"""Evaluate :math:`P^{(k)}(t) = T^{(k)} M G` for a cubic form.

    Parameters
    ----------
    basis : str or array_like, shape (4, 4)
        A name of :func:`basis_matrix` or the matrix M itself.
    G : array_like, shape (4, d)
        The geometry: four points or vectors as rows, in the form's order.
    t : float or array_like
        Parameters (the segment is t in [0, 1]; any t is evaluated).
    order : int, default 0
        The derivative (0 = the point).

    Returns
    -------
    ndarray, shape t.shape + (d,)

    Examples
    --------
    >>> G = [[0, 0], [1, 2], [3, 2], [4, 0]]
    >>> cubic_matrix_eval("bezier", G, 0.5)           # (P0 + 3 P1 + 3 P2 + P3) / 8
    array([2. , 1.5])
    """
    m = _basis_or_matrix(basis, "basis")
    g = _cubic_geometry(G)
    return power_row(t, order) @ (m @ g)


def basis_functions(basis, t):
    r"""The four blending functions :math:`T M` of a form at t (columns: one per G row).

    Parameters
    ----------
    basis : str or array_like, shape (4, 4)
    t : float or array_like

    Returns
    -------
    ndarray, shape t.shape + (4,)

    Examples
    --------
    >>> basis_functions("bspline", 0.0) * 6        # the bell at its knots: 1/6, 4/6, 1/6
    array([1., 4., 1., 0.])
    """
    return power_row(t) @ _basis_or_matrix(basis, "basis")


def convert_geometry(G, from_, to):
    r"""The geometry of the same cubic in another form: :math:`G_{to} = M_{to}^{-1} M_{from} G`.

    For example Hermite -> Bézier gives :math:`P_0, P_0 + P'(0)/3, P_1 - P'(1)/3, P_1`, and
    B-spline -> Bézier gives :math:`((P_0 + 4P_1 + P_2)/6, (2P_1 + P_2)/3, (P_1 + 2P_2)/3,
    (P_1 + 4P_2 + P_3)/6)`. All four matrices are invertible, so every conversion exists.

    Parameters
    ----------
    G : array_like, shape (4, d)
    from_, to : str or array_like, shape (4, 4)
        Names of :func:`basis_matrix` (or matrices).

    Returns
    -------
    ndarray, shape (4, d)

    Examples
    --------
    >>> convert_geometry([[0, 0], [3, 0], [3, 3], [3, -3]], "hermite", "bezier").round(12) + 0
    array([[0., 0.],
           [1., 1.],
           [2., 1.],
           [3., 0.]])
    """
    g = _cubic_geometry(G)
    m_from = _basis_or_matrix(from_, "from_")
    m_to = _basis_or_matrix(to, "to")
    if abs(np.linalg.det(m_to)) < 1e-12:
        raise ValueError("to must be an invertible basis matrix (its blending functions must "
                         "be independent)")
    return np.linalg.solve(m_to, m_from @ g)
