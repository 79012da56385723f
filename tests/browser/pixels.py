"""Comparing pictures (screenshots, or pixels read in the page): how many pixels changed, and
where."""
import io

import numpy as np
from PIL import Image


def load(png):
    return np.asarray(Image.open(io.BytesIO(png) if isinstance(png, bytes) else png)
                      .convert("RGB"), dtype=np.int16)


def changed_pixels(before, after, threshold=24):
    """The number of pixels whose colour changed by more than `threshold` (any channel)."""
    return changed_pixels_of(load(before), load(after), threshold)


def changed_pixels_of(a, b, threshold=24):
    """:func:`changed_pixels` of two RGB arrays (height, width, 3), cropped to the smaller."""
    a, b = np.asarray(a, np.int16), np.asarray(b, np.int16)
    if a.shape != b.shape:
        height, width = min(a.shape[0], b.shape[0]), min(a.shape[1], b.shape[1])
        a, b = a[:height, :width], b[:height, :width]
    return int((np.abs(a - b).max(axis=-1) > threshold).sum())


def changed_pixels_in(before, after, top, bottom, threshold=24):
    """Changed pixels between the heights `top` and `bottom` (fractions of the image, 0 = top)."""
    a, b = load(before), load(after)
    height = min(a.shape[0], b.shape[0])
    rows = slice(int(top * height), int(bottom * height))
    return changed_pixels_of(a[rows], b[rows], threshold)

