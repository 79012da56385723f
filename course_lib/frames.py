"""frames (being written)."""
__all__ = []
