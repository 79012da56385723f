r"""Chapter 18 (lesson section on unsteady flow): streamlines, pathlines, streaklines and
timelines of a time-dependent velocity field, and line integral convolution (LIC).

**Four lines of an unsteady flow.** When the velocity :math:`v(x, t)` changes with time, four
different curves can be drawn from one place:

* a **streamline** at time :math:`t^*` is tangent to the *frozen* field
  :math:`v(\cdot, t^*)`: :math:`\mathrm{d}x/\mathrm{d}s = v(x, t^*)` (a snapshot; the
  integration parameter :math:`s` is not time) -- :func:`streamline_at`;
* a **pathline** is the trajectory of one particle, :math:`\mathrm{d}x/\mathrm{d}t = v(x, t)`,
  :math:`x(t_0) = x_0` (a long-exposure photograph of one tagged particle) -- :func:`pathline`;
* a **streakline** joins, at time :math:`t_1`, all the particles released from one point
  :math:`r` during :math:`[t_0, t_1]` (dye from a nozzle, smoke from a chimney) --
  :func:`streakline`;
* a **timeline** is a line of particles released together at :math:`t_0` and carried to
  :math:`t_1` (a row of hydrogen bubbles from a wire) -- :func:`timeline`.

In a **steady** field all three of streamline, pathline and streakline through a point are
the same curve; the timeline is another kind of curve in any flow. The example fields are
callables ``field(points, t)`` (points ``(..., 2)``, a time) returning velocities
``(..., 2)``: :func:`rotating_uniform_flow` (the textbook case where everything has a closed
form), :func:`double_gyre`, :func:`oscillating_vortex`, and :func:`steady_flow` (any
``v(points)`` as a field that ignores time). :func:`unsteady_field` makes them by name.

Particles are advected by the classic **RK4** scheme applied to
:math:`\dot x = v(x, t)`, time advancing with the stages (:math:`t_n`, :math:`t_n + h/2`,
:math:`t_n + h`); all particles move together, each with its own start time and step.

**Line integral convolution** (Cabral and Leedom 1993) shows a whole 2D steady field at once:
start from white noise, and replace each pixel by the average of the noise along the short
streamline through it, :math:`I(p) = \sum_k w_k\, N(\sigma_p(k h)) / \sum_k w_k` for
:math:`k = -n..n`, :math:`n = \lfloor L/h \rfloor`. Pixels on the same streamline average
nearly the same noise values, so the picture is streaky along the flow and noisy across it.
:class:`LICTraces` traces every pixel's streamline once (all pixels together, one step at a
time, bilinear velocity, unit speed, RK2 midpoint steps) and keeps the noise met at each
step; :meth:`LICTraces.image` then convolves with a box kernel by prefix sums (any
:math:`L` up to the traced one costs one subtraction per pixel) or with a Hann kernel.
:func:`lic` does both in one call. (*FastLIC*, Stalling and Hege 1995, goes further: it
slides one box window along a long streamline and reuses the sum for every pixel it
crosses.)
"""

import numpy as np

from .._validate import as_array, as_choice, as_points, as_scalar, as_whole
from .flow import streamline as _steady_streamline
from .grids import _lerp_grid

__all__ = [
    "LICTraces",
    "advect",
    "double_gyre",
    "lic",
    "oscillating_vortex",
    "pathline",
    "rotating_uniform_flow",
    "steady_flow",
    "streakline",
    "streamline_at",
    "timeline",
    "unsteady_field",
    "FIELD_KINDS",
]

#: The names :func:`unsteady_field` knows.
FIELD_KINDS = ("rotating", "double gyre", "oscillating vortex", "steady vortex")


# ---------------------------------------------------------------------------------------------
# Time-dependent example fields
# ---------------------------------------------------------------------------------------------

def _unsteady_xy(points):
    if not (isinstance(points, np.ndarray) and points.dtype == np.float64
            and points.ndim >= 1 and points.shape[-1] == 2):     # the integrators' fast path
        points = as_points(points, "points", dims=2)
    return points[..., 0], points[..., 1]


def _unsteady_pack(vx, vy):
    """Two component arrays (broadcast) as one array of 2-vectors, without negative zeros."""
    vx, vy = np.broadcast_arrays(vx, vy)
    out = np.empty(vx.shape + (2,))
    out[..., 0] = vx
    out[..., 1] = vy
    return out + 0.0


def rotating_uniform_flow(speed=1.0, omega=1.0, phase=0.0):
    r"""A uniform flow whose direction turns at the rate :math:`\omega`:
    :math:`v(x, t) = U(\cos\theta(t), \sin\theta(t))`, :math:`\theta(t) = \omega t + \varphi`.

    The same everywhere at each instant, so every **streamline** at time :math:`t` is a
    straight line along :math:`\theta(t)`. A particle from :math:`x_0` at :math:`t_0` moves on
    a circle of radius :math:`U/\omega` (its **pathline**):
    :math:`x(t) = x_0 + \tfrac{U}{\omega}(\sin\theta(t) - \sin\theta_0,\;
    \cos\theta_0 - \cos\theta(t))`. The **streakline** at :math:`t_1` of particles released
    from :math:`r` at the times :math:`\tau \in [t_0, t_1]` is
    :math:`r + \tfrac{U}{\omega}(\sin\theta(t_1) - \sin\theta(\tau),\; \cos\theta(\tau) -
    \cos\theta(t_1))`: an arc of the same radius bent the other way, the pathline of the
    particle released at :math:`t_0` turned by 180° about the midpoint of its chord (both run
    from :math:`r` to that particle). Three different curves from one point.

    Examples
    --------
    >>> v = rotating_uniform_flow(speed=2.0, omega=np.pi / 2)
    >>> np.round(v([[0.0, 0.0], [5.0, 1.0]], 1.0), 12)        # at t = 1 it blows along +y
    array([[0., 2.],
           [0., 2.]])
    """
    u, w, phi = (as_scalar(speed, "speed"), as_scalar(omega, "omega"),
                 as_scalar(phase, "phase"))
    if w == 0:
        raise ValueError("omega must not be zero (a flow that never turns is steady_flow)")

    def field(points, t):
        x, _ = _unsteady_xy(points)
        theta = w * np.asarray(t, dtype=float) + phi
        return _unsteady_pack(u * np.cos(theta) + 0 * x, u * np.sin(theta) + 0 * x)
    field.__name__ = "rotating_uniform_flow"
    field.params = {"speed": u, "omega": w, "phase": phi}
    return field


def double_gyre(amplitude=0.1, epsilon=0.25, omega=2 * np.pi / 10):
    r"""The double gyre on :math:`[0, 2] \times [0, 1]` (Shadden et al. 2005): two
    counter-rotating cells whose dividing line sways left and right.

    Stream function :math:`\psi = A \sin(\pi f(x, t)) \sin(\pi y)` with
    :math:`f = a(t) x^2 + b(t) x`, :math:`a = \varepsilon \sin\omega t`, :math:`b = 1 - 2a`;
    :math:`v = (-\partial_y \psi, \partial_x \psi) = (-\pi A \sin(\pi f)\cos(\pi y),\;
    \pi A \cos(\pi f)\sin(\pi y)\, \partial_x f)`. Divergence-free; with
    :math:`\varepsilon = 0` it is steady.

    Examples
    --------
    >>> v = double_gyre()
    >>> np.round(v([[0.5, 0.5], [1.0, 0.5]], 0.0), 6)      # the centre of the left gyre; x = 1
    array([[-0.      ,  0.      ],
           [-0.      , -0.314159]])
    """
    amp, eps, w = (as_scalar(amplitude, "amplitude"), as_scalar(epsilon, "epsilon"),
                   as_scalar(omega, "omega"))

    def field(points, t):
        x, y = _unsteady_xy(points)
        a = eps * np.sin(w * np.asarray(t, dtype=float))
        b = 1 - 2 * a
        f = a * x * x + b * x
        dfdx = 2 * a * x + b
        vx = -np.pi * amp * np.sin(np.pi * f) * np.cos(np.pi * y)
        vy = np.pi * amp * np.cos(np.pi * f) * np.sin(np.pi * y) * dfdx
        return _unsteady_pack(vx, vy)
    field.__name__ = "double_gyre"
    field.params = {"amplitude": amp, "epsilon": eps, "omega": w}
    return field


def oscillating_vortex(amplitude=0.5, omega=1.0, spin=1.0):
    r"""A solid-body vortex whose centre swings along x: :math:`c(t) = (a \sin\omega t, 0)`,
    :math:`v = s\,(-(y - c_y),\; x - c_x)`.

    The streamlines at each instant are circles about :math:`c(t)`, but particles do not
    follow them: a pathline is a circle about a moving centre.

    Examples
    --------
    >>> v = oscillating_vortex(amplitude=0.5, omega=np.pi / 2)
    >>> v([[1.5, 0.0]], 1.0)                               # centre at (0.5, 0) when t = 1
    array([[0., 1.]])
    """
    a, w, s = (as_scalar(amplitude, "amplitude"), as_scalar(omega, "omega"),
               as_scalar(spin, "spin"))

    def field(points, t):
        x, y = _unsteady_xy(points)
        cx = a * np.sin(w * np.asarray(t, dtype=float))
        return _unsteady_pack(-s * y, s * (x - cx))
    field.__name__ = "oscillating_vortex"
    field.params = {"amplitude": a, "omega": w, "spin": s}
    return field


def steady_flow(velocity):
    """A steady field ``v(points)`` (e.g. :func:`course_lib.scivis.example_vector_field`) as a
    time-dependent one ``field(points, t)`` that ignores `t`.

    Examples
    --------
    >>> from course_lib.scivis import example_vector_field
    >>> steady_flow(example_vector_field("vortex"))([[1.0, 0.0]], 7.0)
    array([[0., 1.]])
    """
    if not callable(velocity):
        raise TypeError(f"velocity must be a function of points, got {type(velocity).__name__}")

    def field(points, t):
        return velocity(points)
    field.__name__ = f"steady_{getattr(velocity, '__name__', 'flow')}"
    field.params = {}
    return field


def unsteady_field(kind="rotating", **params):
    """The example field `kind` (one of :data:`FIELD_KINDS`) with optional parameters.

    ``"rotating"`` is :func:`rotating_uniform_flow`, ``"double gyre"`` :func:`double_gyre`,
    ``"oscillating vortex"`` :func:`oscillating_vortex`, ``"steady vortex"`` the vortex
    :math:`(-y, x)` of :func:`course_lib.scivis.example_vector_field` (time-independent).

    Examples
    --------
    >>> unsteady_field("double gyre", epsilon=0.0).params["epsilon"]
    0.0
    """
    as_choice(kind, "kind", FIELD_KINDS)
    if kind == "steady vortex":
        from .data import example_vector_field
        if params:
            raise ValueError("the steady vortex takes no parameters")
        return steady_flow(example_vector_field("vortex"))
    maker = {"rotating": rotating_uniform_flow, "double gyre": double_gyre,
             "oscillating vortex": oscillating_vortex}[kind]
    return maker(**params)


# ---------------------------------------------------------------------------------------------
# Particles: RK4 in x and t
# ---------------------------------------------------------------------------------------------

def _sample_unsteady(field, points, t):
    """field(points, t) checked: one finite 2-vector per point."""
    v = np.asarray(field(points, t), dtype=float)
    if v.shape != points.shape:
        raise ValueError(f"field must return one 2-vector per point (shape {points.shape}), "
                         f"got shape {v.shape}")
    if not np.isfinite(v).all():
        raise ValueError("field returned NaN or infinite velocities")
    return v


def _check_unsteady_field(field):
    if not callable(field):
        raise TypeError("field must be a function field(points, t) -> velocities, got "
                        f"{type(field).__name__}")


def _rk4_advect(field, x, t_start, t_end, n_steps, record=False):
    """Advect particles x (k, 2) from their times t_start (k,) to t_end (k,) with n_steps RK4
    steps each (h = (t_end - t_start) / n_steps per particle); all the positions if record."""
    h = (t_end - t_start) / n_steps
    t = t_start.copy()
    hc = h[:, None]
    path = [x.copy()] if record else None
    for _ in range(n_steps):
        k1 = _sample_unsteady(field, x, t)
        k2 = _sample_unsteady(field, x + 0.5 * hc * k1, t + 0.5 * h)
        k3 = _sample_unsteady(field, x + 0.5 * hc * k2, t + 0.5 * h)
        k4 = _sample_unsteady(field, x + hc * k3, t + h)
        x = x + hc / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        t = t + h
        if record:
            path.append(x.copy())
    return np.stack(path, axis=1) if record else x


def advect(field, points, t_start, t_end, n_steps=50, record=False):
    r"""Carry particles through the field, each from its own start time to its own end time,
    by `n_steps` RK4 steps each (step :math:`h_i = (t_{end,i} - t_{start,i})/n`).

    The one integrator behind :func:`pathline`, :func:`streakline` and :func:`timeline`; use
    it to move particles of all three kinds in one batch.

    Parameters
    ----------
    field : callable
    points : array_like, shape (k, 2)
    t_start, t_end : float or array_like, shape (k,)
    n_steps : int
    record : bool
        Return every step, shape (k, n_steps + 1, 2), instead of the end points (k, 2).

    Examples
    --------
    >>> v = rotating_uniform_flow()
    >>> np.round(advect(v, [[0, 0], [0, 0]], [0, np.pi / 2], np.pi, n_steps=30), 6)
    array([[ 0.,  2.],
           [-1.,  1.]])
    """
    _check_unsteady_field(field)
    p = as_points(points, "points", dims=2)
    if p.ndim != 2:
        raise ValueError(f"points must be particles, shape (k, 2), got {p.shape}")
    k = len(p)
    times = []
    for name, value in (("t_start", t_start), ("t_end", t_end)):
        arr = as_array(value, name)
        if arr.shape not in ((), (k,)):
            raise ValueError(f"{name} must be one time or one per particle ({k}), got shape "
                             f"{arr.shape}")
        times.append(np.broadcast_to(arr, (k,)).astype(float))
    a, b = times
    n = as_whole(n_steps, "n_steps", 1)
    return _rk4_advect(field, p.copy(), a, b, n, record=record)


def _unsteady_seeds(seeds, name):
    p = as_points(seeds, name, dims=2)
    return p.ndim == 1, p.reshape(-1, 2)


def streamline_at(field, seeds, t, step=0.05, n_steps=100, both=False, method="rk4"):
    r"""Streamlines of the field frozen at time `t`: :math:`\mathrm{d}x/\mathrm{d}s = v(x, t)`.

    Uses :func:`course_lib.scivis.streamline` on :math:`v(\cdot, t)`; with `both`, the line
    is traced forwards and backwards from the seed and joined (the seed in the middle), so it
    runs *through* the seed.

    Parameters
    ----------
    field : callable
        ``field(points (k, 2), t) -> (k, 2)``.
    seeds : array_like, shape (2,) or (k, 2)
    t : float
        The frozen time.
    step, n_steps, method
        As in :func:`course_lib.scivis.streamline` (step in units of the parameter s).
    both : bool
        Trace both ways (2 n_steps + 1 points) instead of forwards only.

    Returns
    -------
    ndarray, shape (n, 2) or (k, n, 2)
        NaN rows where a line stopped at a critical point.

    Examples
    --------
    >>> v = rotating_uniform_flow(omega=np.pi / 2)
    >>> np.round(streamline_at(v, [0.0, 0.0], 1.0, step=0.5, n_steps=2), 12)   # along +y
    array([[0. , 0. ],
           [0. , 0.5],
           [0. , 1. ]])
    """
    _check_unsteady_field(field)
    single, p = _unsteady_seeds(seeds, "seeds")
    time = as_scalar(t, "t")
    h = as_scalar(step, "step")
    if h <= 0:
        raise ValueError(f"step must be positive, got {h:g}")

    def frozen(points):
        return _sample_unsteady(field, points, time)
    fwd = _steady_streamline(frozen, p, h, n_steps, method=method)
    if both:
        back = _steady_streamline(frozen, p, -h, n_steps, method=method)
        fwd = np.concatenate([back[:, :0:-1], fwd], axis=1)
    return fwd[0] if single else fwd


def pathline(field, seeds, t0, t1, n_steps=100):
    r"""Pathlines: the trajectories :math:`\mathrm{d}x/\mathrm{d}t = v(x, t)`,
    :math:`x(t_0) = x_0`, by RK4 in x and t.

    With :math:`h = (t_1 - t_0)/n`: :math:`k_1 = v(x_n, t_n)`,
    :math:`k_2 = v(x_n + \tfrac h2 k_1, t_n + \tfrac h2)`,
    :math:`k_3 = v(x_n + \tfrac h2 k_2, t_n + \tfrac h2)`, :math:`k_4 = v(x_n + h k_3, t_n + h)`,
    :math:`x_{n+1} = x_n + \tfrac h6(k_1 + 2k_2 + 2k_3 + k_4)`. Unlike a streamline, the time
    moves with the particle. :math:`t_1 < t_0` traces backwards in time.

    Parameters
    ----------
    field : callable
        ``field(points (k, 2), t) -> (k, 2)``; `t` is a scalar or one time per point.
    seeds : array_like, shape (2,) or (k, 2)
        Positions at time `t0`.
    t0, t1 : float
        Start and end time.
    n_steps : int
        RK4 steps, >= 1.

    Returns
    -------
    ndarray, shape (n_steps + 1, 2) or (k, n_steps + 1, 2)
        The positions at the times ``np.linspace(t0, t1, n_steps + 1)``.

    Examples
    --------
    A particle in the rotating flow runs on a circle of radius U / omega = 1:

    >>> p = pathline(rotating_uniform_flow(), [0.0, 0.0], 0.0, np.pi, n_steps=40)
    >>> np.round(p[-1], 6)                    # half a turn: (sin pi, 1 - cos pi)
    array([0., 2.])
    """
    _check_unsteady_field(field)
    single, p = _unsteady_seeds(seeds, "seeds")
    a, b = as_scalar(t0, "t0"), as_scalar(t1, "t1")
    n = as_whole(n_steps, "n_steps", 1)
    k = len(p)
    out = _rk4_advect(field, p, np.full(k, a), np.full(k, b), n, record=True)
    return out[0] if single else out


def streakline(field, release_point, t0, t1, n_particles=50, n_steps=40):
    r"""The streakline at time `t1` of dye released continuously from `release_point` since
    `t0`: the positions at `t1` of the particles released at the times
    :math:`\tau_i` = ``np.linspace(t0, t1, n_particles)``.

    Each particle is advected from :math:`(r, \tau_i)` to :math:`t_1` by `n_steps` RK4 steps of
    its own length :math:`(t_1 - \tau_i)/n`; all particles move together.

    Parameters
    ----------
    field : callable
    release_point : array_like, shape (2,)
    t0, t1 : float
        The first release and the time of the picture (t1 >= t0).
    n_particles : int
        Particles released (>= 2), evenly in time.
    n_steps : int
        RK4 steps per particle.

    Returns
    -------
    ndarray, shape (n_particles, 2)
        Oldest particle (released at t0) first; the last one is still at the release point.

    Examples
    --------
    >>> s = streakline(rotating_uniform_flow(), [0.0, 0.0], 0.0, np.pi, n_particles=3)
    >>> np.round(s, 6)                        # released at 0, pi/2, pi
    array([[ 0.,  2.],
           [-1.,  1.],
           [ 0.,  0.]])
    """
    _check_unsteady_field(field)
    r = as_points(release_point, "release_point", dims=2)
    if r.shape != (2,):
        raise ValueError(f"release_point must be one point (x, y), got shape {r.shape}")
    a, b = as_scalar(t0, "t0"), as_scalar(t1, "t1")
    if b < a:
        raise ValueError(f"t1 must not be before t0 (dye is released from t0 to t1), got "
                         f"t0 = {a:g}, t1 = {b:g}")
    m = as_whole(n_particles, "n_particles", 2)
    n = as_whole(n_steps, "n_steps", 1)
    taus = np.linspace(a, b, m)
    return _rk4_advect(field, np.tile(r, (m, 1)), taus, np.full(m, b), n)


def timeline(field, points, t0, t1, n_steps=100, record=False):
    r"""A timeline: the line of particles `points`, all released at `t0`, carried to `t1`.

    Parameters
    ----------
    field : callable
    points : array_like, shape (k, 2)
        The particles at `t0`, in order along the line.
    t0, t1 : float
    n_steps : int
        RK4 steps.
    record : bool
        Return every step, shape (n_steps + 1, k, 2), instead of the line at `t1`.

    Returns
    -------
    ndarray, shape (k, 2) (or (n_steps + 1, k, 2))
        The same particles in the same order: the count never changes.

    Examples
    --------
    >>> line = [[0.0, 0.0], [0.0, 1.0]]
    >>> np.round(timeline(rotating_uniform_flow(), line, 0.0, np.pi / 2, n_steps=20), 6)
    array([[1., 1.],
           [1., 2.]])
    """
    _check_unsteady_field(field)
    p = as_points(points, "points", dims=2)
    if p.ndim != 2:
        raise ValueError(f"points must be a line of particles, shape (k, 2), got {p.shape}")
    a, b = as_scalar(t0, "t0"), as_scalar(t1, "t1")
    n = as_whole(n_steps, "n_steps", 1)
    k = len(p)
    out = _rk4_advect(field, p, np.full(k, a), np.full(k, b), n, record=record)
    return np.swapaxes(out, 0, 1) if record else out


# ---------------------------------------------------------------------------------------------
# Line integral convolution
# ---------------------------------------------------------------------------------------------

def _lic_field(u, v):
    """Checked (u, v) pixel grids of the same 2D shape, finite."""
    out = []
    for name, comp in (("u", u), ("v", v)):
        arr = np.asarray(comp) if isinstance(comp, np.ndarray) else None
        if arr is not None and arr.dtype.kind == "f" and not np.isfinite(arr).all():
            raise ValueError(f"{name} must be finite (the velocity field has NaN or infinite "
                             f"values): fill or mask them first")
        arr = as_array(comp, name)
        if arr.ndim != 2 or min(arr.shape) < 2:
            raise ValueError(f"{name} must be a 2D grid of at least 2x2 pixels, shape (ny, nx), "
                             f"got shape {arr.shape}")
        out.append(arr)
    if out[0].shape != out[1].shape:
        raise ValueError(f"u and v must have the same shape, got {out[0].shape} and "
                         f"{out[1].shape}")
    return out


def _lic_noise(noise, shape, seed):
    if noise is None:
        return np.random.default_rng(seed).random(shape)
    n = as_array(noise, "noise")
    if n.shape != shape:
        raise ValueError(f"noise must have the shape of the field, {shape}, got {n.shape}")
    return n


class LICTraces:
    r"""Every pixel's streamline traced once, forwards and backwards, with the noise met at
    each step: the expensive half of line integral convolution.

    Pixel ``(i, j)`` sits at :math:`(x, y) = (j, i)` (pixel units; ``u`` is the x component,
    as in the rest of :mod:`course_lib.scivis`). From each pixel centre, ``n`` steps of length
    `step` go along the *normalised* velocity (the midpoint rule, RK2, with the bilinearly
    interpolated field) and ``n`` steps against it, :math:`n = \lfloor L_{max}/h \rfloor`. A
    trace stops where it leaves the image or meets a speed below `min_speed`; later steps are
    marked invalid. The noise is read at the pixel containing each point (nearest).

    Attributes
    ----------
    samples : ndarray, shape (2n + 1, ny, nx)
        ``samples[n + k]`` is the noise at step k (negative: backwards); 0 where invalid.
    valid : ndarray of bool, same shape
    step, max_length : float
    points : ndarray, shape (2n + 1, ny, nx, 2)
        The traced positions (NaN where invalid), only with ``keep_points=True``.

    Examples
    --------
    >>> u, v = np.ones((3, 4)), np.zeros((3, 4))              # a flow along +x
    >>> tr = LICTraces(u, v, noise=np.arange(12.0).reshape(3, 4), max_length=1, step=1)
    >>> tr.samples[:, 0, 1], tr.valid[:, 0, 0]
    (array([0., 1., 2.]), array([False,  True,  True]))
    >>> tr.image(1)[0]                                         # (0+1)/2, (0+1+2)/3, ...
    array([0.5, 1. , 2. , 2.5])
    """

    def __init__(self, u, v, noise=None, max_length=10.0, step=0.5, seed=0, min_speed=1e-9,
                 keep_points=False):
        uu, vv = _lic_field(u, v)
        ny, nx = uu.shape
        self.noise = _lic_noise(noise, uu.shape, seed)
        self.max_length = as_scalar(max_length, "max_length")
        if self.max_length <= 0:
            raise ValueError(f"max_length (the kernel length) must be positive, got "
                             f"{self.max_length:g}")
        self.step = as_scalar(step, "step")
        if self.step <= 0:
            raise ValueError(f"step must be positive (pixels per step), got {self.step:g}")
        n = int(np.floor(self.max_length / self.step + 1e-9))
        self.n = n
        flat = np.stack([uu.ravel(), vv.ravel()], axis=-1)
        dims = (nx, ny)
        jj, ii = np.meshgrid(np.arange(nx, dtype=float), np.arange(ny, dtype=float))
        start = np.stack([jj.ravel(), ii.ravel()], axis=-1)
        noise_flat = self.noise.ravel()
        self.samples = np.zeros((2 * n + 1, ny * nx))
        self.valid = np.zeros((2 * n + 1, ny * nx), dtype=bool)
        self.samples[n] = noise_flat
        self.valid[n] = True
        pts = np.full((2 * n + 1, ny * nx, 2), np.nan) if keep_points else None
        if keep_points:
            pts[n] = start
        speed_min = float(min_speed)

        def direction(q):
            w = _lerp_grid(flat, dims, [q[:, 0], q[:, 1]])
            s = np.hypot(w[:, 0], w[:, 1])
            ok = s >= speed_min
            return w / np.where(ok, s, 1.0)[:, None], ok

        for sign in (1.0, -1.0):
            h = sign * self.step
            x = start.copy()
            ids = np.arange(ny * nx)
            for k in range(1, n + 1):
                d1, ok1 = direction(x)
                d2, ok2 = direction(x + 0.5 * h * d1)
                new = x + h * d2
                inside = ((new[:, 0] >= -0.5) & (new[:, 0] < nx - 0.5)
                          & (new[:, 1] >= -0.5) & (new[:, 1] < ny - 0.5))
                keep = ok1 & ok2 & inside
                x, ids = new[keep], ids[keep]
                if ids.size == 0:
                    break
                row = n + int(sign) * k
                pix = (np.floor(x[:, 1] + 0.5).astype(np.intp) * nx
                       + np.floor(x[:, 0] + 0.5).astype(np.intp))
                self.samples[row, ids] = noise_flat[pix]
                self.valid[row, ids] = True
                if keep_points:
                    pts[row, ids] = x
        self.samples = self.samples.reshape(2 * n + 1, ny, nx)
        self.valid = self.valid.reshape(2 * n + 1, ny, nx)
        self.points = None if pts is None else pts.reshape(2 * n + 1, ny, nx, 2)
        self._prefix = None

    def image(self, kernel_length=None, kernel="box", normalize=True):
        r"""The LIC image for a kernel of half-length `kernel_length` (at most the traced
        length): :math:`I = \sum_k w_k N_k / \sum_k w_k` over the valid steps
        :math:`|k| \le m = \lfloor L/h \rfloor`.

        ``"box"``: :math:`w_k = 1`, computed from prefix sums along the traces (two reads per
        pixel whatever :math:`m`). ``"hann"``: :math:`w_k = \tfrac12(1 + \cos(\pi k h / L))`,
        a weighted sum (smoother streaks, no ringing). `normalize` divides by the weights of
        the valid steps (pixels near the border, whose traces stop early, keep the noise's
        mean); without it the sum is divided by the full kernel's weight.

        Examples
        --------
        >>> tr = LICTraces(np.ones((2, 5)), np.zeros((2, 5)), noise=np.eye(2, 5), max_length=2,
        ...                step=1)
        >>> tr.image(1)[0], tr.image(2, kernel="hann")[0]
        (array([0.5       , 0.33333333, 0.        , 0.        , 0.        ]), array([0.66666667, 0.25      , 0.        , 0.        , 0.        ]))
        """
        length = self.max_length if kernel_length is None else as_scalar(kernel_length,
                                                                         "kernel_length")
        as_choice(kernel, "kernel", ("box", "hann"))
        if length <= 0:
            raise ValueError(f"kernel_length must be positive, got {length:g}")
        if length > self.max_length + 1e-9:
            raise ValueError(f"kernel_length must be at most the traced length "
                             f"{self.max_length:g}, got {length:g}")
        n = self.n
        m = min(n, int(np.floor(length / self.step + 1e-9)))
        if kernel == "box":
            if self._prefix is None:
                zero = np.zeros((1,) + self.samples.shape[1:])
                self._prefix = (np.concatenate([zero, np.cumsum(self.samples, axis=0)]),
                                np.concatenate([zero, np.cumsum(self.valid, axis=0)]))
            s, c = self._prefix
            total = s[n + m + 1] - s[n - m]
            weight = (c[n + m + 1] - c[n - m]) if normalize else float(2 * m + 1)
            return total / weight
        offsets = np.arange(-m, m + 1) * self.step
        w = 0.5 * (1 + np.cos(np.pi * offsets / length))
        sl = slice(n - m, n + m + 1)
        total = np.tensordot(w, self.samples[sl], axes=1)
        weight = np.tensordot(w, self.valid[sl], axes=1) if normalize else w.sum()
        return total / weight


def lic(u, v, noise=None, kernel_length=10.0, step=0.5, kernel="box", seed=0,
        normalize=True):
    r"""Line integral convolution of a 2D steady field given on pixels.

    For each pixel, trace the streamline through it forwards and backwards for
    `kernel_length` (in pixels), step `step`, and average the noise met along it with a box
    or Hann kernel (:class:`LICTraces` and :meth:`LICTraces.image`). A kernel shorter than one
    step returns the noise itself.

    Parameters
    ----------
    u, v : array_like, shape (ny, nx)
        The x and y components of the velocity at each pixel (row i is y, column j is x).
    noise : array_like, shape (ny, nx), optional
        The input texture; default white noise in [0, 1) from `seed`.
    kernel_length : float
        Half-length L of the kernel in pixels (> 0).
    step : float
        Tracing step in pixels (> 0); smaller is more accurate and slower.
    kernel : {"box", "hann"}
    seed : int
        Seed of the default noise.
    normalize : bool
        Divide by the weights of the steps that stayed inside the image.

    Returns
    -------
    ndarray, shape (ny, nx)

    Raises
    ------
    ValueError
        For kernel_length <= 0, step <= 0, a noise of another shape, u and v of different
        shapes, or a non-finite field.

    Examples
    --------
    Along a uniform flow in x, each row is the noise averaged over 2L + 1 neighbours:

    >>> noise = np.array([[0.0, 3.0, 0.0, 3.0, 6.0]] * 2)
    >>> lic(np.ones((2, 5)), np.zeros((2, 5)), noise, kernel_length=1, step=1)[0]
    array([1.5, 1. , 2. , 3. , 4.5])
    """
    length = as_scalar(kernel_length, "kernel_length")
    if length <= 0:
        raise ValueError(f"kernel_length must be positive (pixels each way), got {length:g}")
    tr = LICTraces(u, v, noise=noise, max_length=length, step=step, seed=seed)
    return tr.image(kernel_length, kernel=kernel, normalize=normalize)
