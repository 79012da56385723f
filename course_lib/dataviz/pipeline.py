"""pipeline (being written)."""

__all__ = []
