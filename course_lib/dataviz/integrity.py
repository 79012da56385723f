"""integrity (being written)."""

__all__ = []
