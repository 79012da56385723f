"""Comparing screenshots: how many pixels changed, and where."""
import io

import numpy as np
from PIL import Image


def load(png):
    return np.asarray(Image.open(io.BytesIO(png) if isinstance(png, bytes) else png)
                      .convert("RGB"), dtype=np.int16)


def changed_pixels(before, after, threshold=24):
    """The number of pixels whose colour changed by more than `threshold` (any channel)."""
    a, b = load(before), load(after)
    if a.shape != b.shape:
        height, width = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
        a, b = a[:height, :width], b[:height, :width]
    return int((np.abs(a - b).max(axis=-1) > threshold).sum())
