"""distances (being written)."""

__all__ = []
