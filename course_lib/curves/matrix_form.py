"""matrix_form (being written)."""

__all__ = []
