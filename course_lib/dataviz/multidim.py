"""multidim (being written)."""

__all__ = []
