"""interpolating (being written)."""

__all__ = []
