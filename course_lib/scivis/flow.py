"""Chapter 18 (lesson section 5.1): streamlines of a vector field, integrated step by step."""

import numpy as np

from .._validate import as_array, as_choice, as_points, as_scalar, as_vector, as_whole
from ._common import _spacing
from .grids import _lerp_grid

__all__ = ["streamline"]


# ---------------------------------------------------------------------------------------------
# Streamlines
# ---------------------------------------------------------------------------------------------

def _velocity_sampler(velocity, dim, spacing, origin, bounds):
    """(sampler(points (k, d)) -> (k, d), lower bounds, upper bounds, dim)."""
    if callable(velocity):
        def sampler(points):
            v = np.asarray(velocity(points), dtype=float)
            if v.shape != points.shape:
                raise ValueError(f"velocity must return one {dim}-vector per point (shape "
                                 f"{points.shape}), got shape {v.shape}")
            if not np.isfinite(v).all():
                raise ValueError("velocity returned NaN or infinite values")
            return v
        lo, hi = np.full(dim, -np.inf), np.full(dim, np.inf)
    else:
        g = as_array(velocity, "velocity")
        if g.ndim != dim + 1 or g.shape[-1] != dim or min(g.shape[:-1]) < 2:
            raise ValueError(f"velocity must be a function or a grid of {dim}D vectors, shape "
                             f"{'(ny, nx, 2)' if dim == 2 else '(nz, ny, nx, 3)'} (last grid "
                             f"axis x), got shape {g.shape}")
        sp = np.ones(dim) if spacing is None else _spacing(spacing, dim)
        org = np.zeros(dim) if origin is None else as_vector(origin, "origin", dim)
        dims = g.shape[:-1][::-1]
        flat = g.reshape(-1, dim)

        def sampler(points):
            q = (points - org) / sp
            return _lerp_grid(flat, dims, [q[:, c] for c in range(dim)])
        lo, hi = org, org + sp * (np.array(dims) - 1)
    if bounds is not None:
        b = as_array(bounds, "bounds")
        if b.shape != (2, dim) or (b[0] > b[1]).any():
            raise ValueError(f"bounds must be ((low x, low y, ...), (high x, high y, ...)), "
                             f"shape (2, {dim}), lows <= highs, got shape {b.shape}")
        lo, hi = np.maximum(lo, b[0]), np.minimum(hi, b[1])
    return sampler, lo, hi


def streamline(velocity, seeds, step, n_steps=100, method="rk4", spacing=None, origin=None,
               bounds=None, min_speed=1e-10):
    r"""Trace streamlines :math:`\mathrm{d}x/\mathrm{d}t = v(x)` from seed points.

    With step h and :math:`k_1 = v(x_n)`:

    * ``"euler"``: :math:`x_{n+1} = x_n + h k_1` (error per unit time O(h));
    * ``"rk2"`` (midpoint): :math:`x_{n+1} = x_n + h\, v(x_n + \tfrac h2 k_1)` (O(h^2));
    * ``"rk4"``: :math:`k_2 = v(x_n + \tfrac h2 k_1)`, :math:`k_3 = v(x_n + \tfrac h2 k_2)`,
      :math:`k_4 = v(x_n + h k_3)`, :math:`x_{n+1} = x_n + \tfrac h6 (k_1 + 2k_2 + 2k_3 + k_4)`
      (O(h^4)).

    A line **stops** at a point where the speed :math:`|v|` is below `min_speed` (a critical
    point: the flow stands still), or before a step that would leave the domain (the grid's
    extent, or `bounds`); the last point kept is inside. All seeds advance together.

    Parameters
    ----------
    velocity : callable or array_like
        A function mapping points (k, d) to velocities (k, d), or velocities sampled on a grid,
        shape (ny, nx, 2) or (nz, ny, nx, 3) (last grid axis x, components (vx, vy(, vz))),
        interpolated bilinearly / trilinearly (:func:`interpolate`; RK stages that fall outside
        use the nearest border value).
    seeds : array_like, shape (d,) or (k, d)
        Start points (x, y) or (x, y, z).
    step : float
        The integration step h; negative traces backwards (upstream). Not zero.
    n_steps : int
        Number of steps, >= 1.
    method : {"euler", "rk2", "rk4"}
    spacing, origin : tuple of float, optional
        The geometry of a velocity grid (default spacing 1, origin 0).
    bounds : array_like, shape (2, d), optional
        ((low x, low y, ...), (high x, high y, ...)): a box the lines must stay in.
    min_speed : float
        Speeds below this count as zero.

    Returns
    -------
    ndarray, shape (n_steps + 1, d) for one seed, (k, n_steps + 1, d) for several
        The points, starting with the seed; after a line stops, its remaining rows are NaN
        (matplotlib's ``plot`` simply leaves them out; ``line[np.isfinite(line[:, 0])]``
        keeps the valid part). A seed outside the domain gives a line of just the seed.

    Raises
    ------
    ValueError
        For a zero step, an unknown method, or a velocity of the wrong shape.

    Examples
    --------
    Euler on the vortex v = (-y, x) moves along the tangent and drifts outwards; RK4 stays on
    the unit circle:

    >>> from course_lib.scivis import example_vector_field
    >>> vortex = example_vector_field("vortex")
    >>> streamline(vortex, [1.0, 0.0], step=0.5, n_steps=2, method="euler")
    array([[1.  , 0.  ],
           [1.  , 0.5 ],
           [0.75, 1.  ]])
    >>> line = streamline(vortex, [1.0, 0.0], step=0.1, n_steps=63)
    >>> float(np.linalg.norm(line[-1]).round(6))
    1.0
    """
    as_choice(method, "method", ("euler", "rk2", "rk4"))
    p = as_points(seeds, "seeds", dims=(2, 3))
    single = p.ndim == 1
    p = p.reshape(-1, p.shape[-1])
    dim = p.shape[1]
    h = as_scalar(step, "step")
    if h == 0:
        raise ValueError("step must not be zero (a negative step traces upstream)")
    n = as_whole(n_steps, "n_steps", 1)
    speed_min = as_scalar(min_speed, "min_speed")
    sampler, lo, hi = _velocity_sampler(velocity, dim, spacing, origin, bounds)

    def inside(x):
        return ((x >= lo) & (x <= hi)).all(axis=1)

    lines = np.full((len(p), n + 1, dim), np.nan)
    lines[:, 0] = p
    current = p.copy()
    alive = inside(p)
    for i in range(n):
        ids = np.flatnonzero(alive)
        if ids.size == 0:
            break
        x = current[ids]
        k1 = sampler(x)
        if method == "euler":
            new = x + h * k1
        elif method == "rk2":
            new = x + h * sampler(x + 0.5 * h * k1)
        else:
            k2 = sampler(x + 0.5 * h * k1)
            k3 = sampler(x + 0.5 * h * k2)
            k4 = sampler(x + h * k3)
            new = x + (h / 6.0) * (k1 + 2 * k2 + 2 * k3 + k4)
        ok = (np.linalg.norm(k1, axis=1) >= speed_min) & inside(new)
        alive[ids[~ok]] = False
        current[ids[ok]] = new[ok]
        lines[ids[ok], i + 1] = new[ok]
    return lines[0] if single else lines
