"""brep (being written)."""

__all__ = []
