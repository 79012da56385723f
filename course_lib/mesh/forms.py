"""forms (being written)."""

__all__ = []
