"""clustering (being written)."""

__all__ = []
