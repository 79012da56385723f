"""Numbers, vectors and matrices as LaTeX, HTML or plain text, for notebooks, widgets and exercises.

Only formatting: numpy in, strings out. Entries are rounded for reading (``-0`` shown as ``0``).
The explorers' live panels use the HTML forms: a browser lays them out at once, where LaTeX
would be typeset by MathJax again at every move of a slider (tens of milliseconds each time).
"""
import numpy as np

from ._validate import as_array

__all__ = ["matrix_html", "matrix_latex", "matrix_text", "number", "vector_html",
           "vector_latex"]


def number(x, decimals=3):
    """A number rounded to `decimals` places, without trailing zeros and without ``-0``.

    Parameters
    ----------
    x : float
    decimals : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> number(0.5), number(-1e-17), number(2.0), number(1 / 3)
    ('0.5', '0', '2', '0.333')
    """
    value = round(float(x), decimals)
    if value == 0:
        value = 0.0
    text = f"{value:.{decimals}f}".rstrip("0").rstrip(".") if decimals > 0 else f"{value:.0f}"
    return text if text not in ("", "-") else "0"


def _entries(m, decimals):
    return [[number(v, decimals) for v in row] for row in m]


def matrix_latex(M, decimals=3, padded=False):
    r"""A matrix as a LaTeX ``bmatrix``, entries rounded to `decimals` places.

    Parameters
    ----------
    M : array_like, shape (rows, cols)
    decimals : int, optional
    padded : bool, optional
        Leave a space between the brackets and the entries (the explorers' panels: their
        MathJax draws a ``bmatrix``'s brackets against the digits).

    Returns
    -------
    str

    Examples
    --------
    >>> matrix_latex([[1, 0.5], [0, 1]])
    '\\begin{bmatrix} 1 & 0.5 \\\\ 0 & 1 \\end{bmatrix}'
    >>> matrix_latex([[1]], padded=True)
    '\\left[\\;\\begin{matrix} 1 \\end{matrix}\\;\\right]'
    """
    m = np.atleast_2d(as_array(M, "M"))
    rows = r" \\ ".join(" & ".join(row) for row in _entries(m, decimals))
    if padded:
        return r"\left[\;\begin{matrix} " + rows + r" \end{matrix}\;\right]"
    return r"\begin{bmatrix} " + rows + r" \end{bmatrix}"


def vector_latex(v, decimals=3, column=False):
    r"""A vector as LaTeX: a row ``(x, y, z)``, or a column ``bmatrix`` with ``column=True``.

    Parameters
    ----------
    v : array_like, shape (n,)
    decimals : int, optional
    column : bool, optional

    Returns
    -------
    str

    Examples
    --------
    >>> vector_latex([1, 0.25, -2])
    '(1,\\ 0.25,\\ -2)'
    """
    v = as_array(v, "v").ravel()
    if column:
        return matrix_latex(v[:, None], decimals)
    return "(" + r",\ ".join(number(x, decimals) for x in v) + ")"


def matrix_text(M, decimals=3):
    """A matrix as aligned plain text, one row per line, for ``<pre>`` blocks and terminals.

    Parameters
    ----------
    M : array_like, shape (rows, cols)
    decimals : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> print(matrix_text([[1, -0.5], [0, 10]]))
    [  1  -0.5 ]
    [  0  10   ]
    """
    m = np.atleast_2d(as_array(M, "M"))
    cells = [[text.partition(".") for text in row] for row in _entries(m, decimals)]
    # align each column on the decimal point: whole part right-aligned, fraction left-aligned
    whole_width = [max(len(row[j][0]) for row in cells) for j in range(m.shape[1])]
    frac_width = [max(len(row[j][2]) for row in cells) for j in range(m.shape[1])]
    lines = []
    for row in cells:
        parts = []
        for j, (whole, _, frac) in enumerate(row):
            dot = "." if frac else (" " if frac_width[j] else "")
            parts.append(whole.rjust(whole_width[j]) + dot + frac.ljust(frac_width[j]))
        lines.append("[ " + "  ".join(f" {p}" for p in parts) + " ]")
    return "\n".join(lines)


def _html_number(text):
    """A formatted number for HTML: a true minus sign (U+2212) instead of the hyphen."""
    return text.replace("-", "\u2212")


#: The two sides of a bracket around a matrix: a thin line with short serifs at the ends.
_BRACKET = "border:1.5px solid currentColor;width:3px;padding:0;{side}:none"


def matrix_html(M, decimals=3):
    """A matrix as an HTML table between square brackets, entries rounded to `decimals`
    places and aligned on the right, with room between the brackets and the digits.

    Parameters
    ----------
    M : array_like, shape (rows, cols)
    decimals : int, optional

    Returns
    -------
    str

    Examples
    --------
    >>> html = matrix_html([[1, -0.5], [0, 2]])
    >>> html.count("<tr>"), "\u22120.5" in html
    (2, True)
    """
    m = np.atleast_2d(as_array(M, "M"))
    rows = []
    for k, row in enumerate(_entries(m, decimals)):
        cells = "".join(f"<td style='padding:1px 6px;text-align:right'>{_html_number(v)}</td>"
                        for v in row)
        if k == 0:
            left = (f"<td rowspan='{len(m)}' style='{_BRACKET.format(side='border-right')}'>"
                    "</td>")
            right = (f"<td rowspan='{len(m)}' style='{_BRACKET.format(side='border-left')}'>"
                     "</td>")
            cells = left + cells + right
        rows.append(f"<tr>{cells}</tr>")
    return ("<table style='display:inline-table;border-collapse:collapse;"
            "vertical-align:middle;margin:2px 4px;font-variant-numeric:tabular-nums;"
            "line-height:1.25'>" + "".join(rows) + "</table>")


def vector_html(v, decimals=3, column=False):
    """A vector as HTML: a row ``(x, y, z)`` with true minus signs, or a bracketed column
    with ``column=True``.

    Examples
    --------
    >>> vector_html([1, 0.25, -2])
    '(1, 0.25, \u22122)'
    """
    v = as_array(v, "v").ravel()
    if column:
        return matrix_html(v[:, None], decimals)
    return "(" + ", ".join(_html_number(number(x, decimals)) for x in v) + ")"
