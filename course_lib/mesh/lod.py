"""lod (being written)."""

__all__ = []
