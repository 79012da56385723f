"""scattered (being written)."""

__all__ = []
