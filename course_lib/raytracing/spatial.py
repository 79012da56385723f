"""spatial (being written)."""
__all__ = []
