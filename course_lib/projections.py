"""projections (being written)."""
__all__ = []
