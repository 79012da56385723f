"""Numbers that are pleasant by hand (:func:`pick`, :func:`small_ints`), numbers as LaTeX and the
statement's last line (:func:`data_note`, :data:`DECIMALS`).

Part of :mod:`course_lib.exercises.core`, which imports everything from here.
"""

from fractions import Fraction

import numpy as np

from ... import format as fmt

__all__ = [
    "data_note",
    "latex_fraction",
    "latex_vector",
    "pick",
    "small_ints",
]


#: The note on precision that ends most statements.
DECIMALS = "Give at least 3 decimals (or let numpy compute them)."


def pick(rng, options):
    """One element of the sequence `options`, drawn with `rng`.

    Unlike ``rng.choice`` it keeps the element as it is (a tuple stays a tuple).

    Examples
    --------
    >>> import numpy as np
    >>> pick(np.random.default_rng(0), [(1, 2), (3, 4)]) in [(1, 2), (3, 4)]
    True
    """
    return options[int(rng.integers(len(options)))]


def small_ints(rng, n, low=-3, high=3):
    """A non-zero vector of `n` whole numbers in [low, high], as floats.

    Examples
    --------
    >>> import numpy as np
    >>> v = small_ints(np.random.default_rng(0), 3)
    >>> v.shape, bool(v.any()), bool(np.all(np.abs(v) <= 3)), bool(np.all(v == np.round(v)))
    ((3,), True, True, True)
    """
    while True:
        v = rng.integers(low, high + 1, size=n).astype(float)
        if np.any(v):
            return v


def data_note(*names):
    """The note that ends a statement: where the question's numbers are, as attributes.

    Examples
    --------
    >>> print(data_note("theta", "d"))
    *The numbers of this question are the attributes `.theta`, `.d` of the exercise object.*
    """
    listed = ", ".join(f"`.{name}`" for name in names)
    return f"*The numbers of this question are the attributes {listed} of the exercise object.*"


def latex_fraction(x, max_denominator=64):
    r"""A number as LaTeX: a short decimal when it has one, else a simple fraction (``\tfrac``).

    Parameters
    ----------
    x : float
    max_denominator : int
        The largest denominator a fraction may have; a number that is no such fraction (to
        1e-12) is written as a decimal.

    Returns
    -------
    str

    Examples
    --------
    >>> latex_fraction(0.25), latex_fraction(1 / 3), latex_fraction(-2 / 7)
    ('0.25', '\\tfrac{1}{3}', '-\\tfrac{2}{7}')
    >>> latex_fraction(1 / 127), latex_fraction(1 / 127, max_denominator=1024)
    ('0.008', '\\tfrac{1}{127}')
    """
    x = float(x)
    if abs(round(x, 3) - x) < 1e-12:
        return fmt.number(x)
    f = Fraction(x).limit_denominator(max_denominator)
    if abs(float(f) - x) > 1e-12:
        return fmt.number(x)
    sign = "-" if f < 0 else ""
    return rf"{sign}\tfrac{{{abs(f.numerator)}}}{{{f.denominator}}}"


def latex_vector(v, max_denominator=64):
    r"""A vector as LaTeX, its components as short decimals or simple fractions.

    Parameters
    ----------
    v : array_like
    max_denominator : int
        As for :func:`latex_fraction`.

    Returns
    -------
    str

    Examples
    --------
    >>> print(latex_vector([0.5, 1 / 3, 2]))
    (0.5,\ \tfrac{1}{3},\ 2)
    """
    return "(" + r",\ ".join(latex_fraction(x, max_denominator) for x in np.ravel(v)) + ")"
