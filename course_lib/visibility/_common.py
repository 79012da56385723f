"""Shared input checks and constants of :mod:`course_lib.visibility`."""

from .._validate import as_matrix


# ---------------------------------------------------------------------------------------------
# Input checks built on the shared helpers
# ---------------------------------------------------------------------------------------------

def _camera(view, projection):
    return as_matrix(view, "view", 4), as_matrix(projection, "projection", 4)
