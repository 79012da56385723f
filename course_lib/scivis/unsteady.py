"""unsteady (being written)."""
__all__ = []
