"""What the chapter 14 exercises share: reading answers, drawing and wording helpers.

The exercises are in one module per topic of this package; import them from
:mod:`course_lib.exercises.ch14`.
"""

import functools

from ... import format as fmt
from ..core import DECIMALS, DrawnExercise, PartsAnswer, latex_vector


_num = fmt.number


def _n4(x):
    """A number of a worked step: 4 decimals, without trailing zeros."""
    return fmt.number(x, 4)


def _factor(x, decimals=4):
    """A number inside a product or a sum, bracketed when negative."""
    text = fmt.number(x, decimals)
    return f"({text})" if text.startswith("-") else text


_vec = functools.partial(latex_vector, max_denominator=1024)


# ---------------------------------------------------------------------------------------------
# Helpers
# ---------------------------------------------------------------------------------------------

def _texture_table(T):
    """A texture as a Markdown table drawn like the picture: the top row (largest v) first."""
    h, w = T.shape
    header = "| | " + " | ".join(f"$j = {j}$" for j in range(w)) + " |"
    rule = "|---" * (w + 1) + "|"
    rows = []
    for i in range(h - 1, -1, -1):
        where = " (top)" if i == h - 1 else " (bottom)" if i == 0 else ""
        rows.append(f"| $i = {i}${where} | " + " | ".join(_num(x) for x in T[i]) + " |")
    return "\n".join([header, rule] + rows)


class _Chapter14(DrawnExercise):
    """The chapter's base: "right direction, wrong length" means nothing for texture
    coordinates and lists of values (see ``DrawnExercise.vector_like``)."""

    vector_like = False


class _Parts(PartsAnswer, _Chapter14):
    """An answer made of several numbers, each with slips of its own (see PartsAnswer)."""


_ONE_NUMBER = "**Answer:** one number. " + DECIMALS
_UV = "**Answer:** a list of 2 numbers `[u, v]`. " + DECIMALS
_TEXELS = (r"Texel $(i, j)$ (row $i$, column $j$) covers $u \in [j/W, (j+1)/W]$ and "
           r"$v \in [i/H, (i+1)/H]$; row 0 is at $v = 0$, the **bottom** of the picture.")
