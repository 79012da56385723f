"""quadrics (being written)."""
__all__ = []
