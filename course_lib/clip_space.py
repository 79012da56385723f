"""clip_space (being written)."""
__all__ = []
