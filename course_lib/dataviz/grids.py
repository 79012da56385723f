"""grids (being written)."""

__all__ = []
