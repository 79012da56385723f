"""hierarchical (being written)."""
__all__ = []
