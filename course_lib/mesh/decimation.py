"""decimation (being written)."""

__all__ = []
