"""continuity (being written)."""

__all__ = []
