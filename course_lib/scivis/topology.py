"""topology (being written)."""
__all__ = []
