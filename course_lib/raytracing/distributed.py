"""distributed (being written)."""
__all__ = []
