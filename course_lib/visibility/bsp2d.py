"""bsp2d (being written)."""
__all__ = []
