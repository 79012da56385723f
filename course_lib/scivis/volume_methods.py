"""volume_methods (being written)."""
__all__ = []
