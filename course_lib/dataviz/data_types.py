"""data_types (being written)."""

__all__ = []
