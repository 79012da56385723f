"""Spatial search for the data modules: which points lie in which boxes, and near neighbours.

A uniform grid of buckets over the points: each point goes into the bucket its coordinates
fall in, and a box (a triangle's or a cell's bounding box, or a query point widened by a
radius) only looks at the points of the buckets it overlaps. Everything is vectorised with
``np.repeat``: no Python loop over boxes or points, and the work is in proportion to the
number of candidate pairs instead of (boxes x points). The order of every result is fixed
(stable sorts, ties broken by index), so it is the same on every CPU.
"""
import numpy as np

#: Candidate pairs handled at once (bounds the memory of a search: a few arrays of this length).
_PAIR_BUDGET = 2_000_000


def _bucket_layout(points, typical):
    """Buckets over `points` (n, d): their origin, size, counts per axis, and the points sorted
    by bucket (order, start of each bucket, count of each bucket)."""
    n, d = points.shape
    low = points.min(axis=0)
    span = points.max(axis=0) - low
    cap = max(1, int(np.ceil((4 * n) ** (1.0 / d))))          # at most about 4n buckets
    size = np.maximum(np.asarray(typical, dtype=float), 1e-300)
    counts = np.clip(np.floor(span / size), 1, cap).astype(np.intp)
    width = np.where(span > 0, span / counts, 1.0)
    cell = np.clip(np.floor((points - low) / width), 0, counts - 1).astype(np.intp)
    bucket = np.ravel_multi_index(tuple(cell.T), tuple(counts))
    order = np.argsort(bucket, kind="stable")
    per_bucket = np.bincount(bucket, minlength=int(np.prod(counts)))
    start = np.concatenate([[0], np.cumsum(per_bucket)[:-1]])
    return low, width, counts, order, start, per_bucket


def _box_point_pairs(lo, hi, points):
    """All pairs (box i, point j) with point j inside the closed box [lo_i, hi_i].

    Parameters
    ----------
    lo, hi : ndarray, shape (m, d)
    points : ndarray, shape (n, d)

    Yields
    ------
    (box, point) : pair of intp arrays
        In chunks of at most about ``_PAIR_BUDGET`` candidate pairs; every pair once, in an
        order fixed by the input (boxes in order, then points by bucket and index).
    """
    m, d = lo.shape
    if m == 0 or len(points) == 0:
        return
    typical = np.median(hi - lo, axis=0) / 4           # a box spans about 5 buckets per axis
    low, width, counts, order, start, per_bucket = _bucket_layout(points, typical)
    top = points.max(axis=0)
    meets = np.all((hi >= low) & (lo <= top), axis=1)          # boxes that can hold a point
    b_lo = np.clip(np.floor((lo - low) / width), 0, counts - 1).astype(np.intp)
    b_hi = np.clip(np.floor((hi - low) / width), 0, counts - 1).astype(np.intp)
    spans = np.where(meets[:, None], b_hi - b_lo + 1, 0)
    n_buckets = np.prod(spans, axis=1)
    mean_per_bucket = len(points) / float(np.prod(counts))
    estimate = np.cumsum(n_buckets * (mean_per_bucket + 1.0))   # candidate pairs so far
    first = 0
    while first < m:
        before = estimate[first - 1] if first else 0.0
        last = max(int(np.searchsorted(estimate, before + _PAIR_BUDGET, side="right")),
                   first + 1)
        yield from _pairs_of_boxes(np.arange(first, min(last, m)), lo, hi, points, b_lo,
                                   spans, n_buckets, counts, order, start, per_bucket)
        first = last


def _pairs_of_boxes(boxes, lo, hi, points, b_lo, spans, n_buckets, counts, order, start,
                    per_bucket):
    """The pairs of one chunk of boxes (see :func:`_box_point_pairs`)."""
    d = lo.shape[1]
    nb = n_buckets[boxes]
    box = np.repeat(boxes, nb)
    if box.size == 0:
        return
    local = np.arange(box.size) - np.repeat(np.cumsum(nb) - nb, nb)
    cell = np.empty((box.size, d), dtype=np.intp)
    for axis in range(d - 1, -1, -1):                           # mixed-radix digits of `local`
        w = spans[box, axis]
        cell[:, axis] = b_lo[box, axis] + local % w
        local = local // w
    bucket = np.ravel_multi_index(tuple(cell.T), tuple(counts))
    inside = per_bucket[bucket]
    box2 = np.repeat(box, inside)
    if box2.size == 0:
        return
    offset = np.arange(box2.size) - np.repeat(np.cumsum(inside) - inside, inside)
    point = order[np.repeat(start[bucket], inside) + offset]
    p = points[point]
    keep = np.all((p >= lo[box2]) & (p <= hi[box2]), axis=1)
    yield box2[keep], point[keep]


def _pairs_within(data, query, radius):
    """All pairs (query i, data point j) with |data_j - query_i| <= radius, and their squared
    distances: three arrays, in a fixed order."""
    q_idx, p_idx, dist2 = [], [], []
    r = np.full(query.shape[1], float(radius))
    for qi, pj in _box_point_pairs(query - r, query + r, data):
        d2 = np.sum((data[pj] - query[qi]) ** 2, axis=1)
        keep = d2 <= radius * radius
        q_idx.append(qi[keep])
        p_idx.append(pj[keep])
        dist2.append(d2[keep])
    if not q_idx:
        return (np.zeros(0, np.intp), np.zeros(0, np.intp), np.zeros(0))
    return np.concatenate(q_idx), np.concatenate(p_idx), np.concatenate(dist2)


def _k_nearest(data, query, k):
    """The `k` nearest data points of every query point: indices and squared distances, shape
    (m, k) each, nearest first; ties are broken by the lower index.

    A radius search whose radius is guessed from the density of the data (about 2k points
    expected in the ball), doubled for the queries that found fewer than `k`.
    """
    n, d = data.shape
    m = len(query)
    index = np.empty((m, k), dtype=np.intp)
    dist2 = np.empty((m, k))
    span = np.ptp(np.vstack([data, query]), axis=0)
    volume = float(np.prod(np.maximum(span, span.max() * 1e-3 + 1e-300)))
    ball = np.pi if d == 2 else (4.0 / 3.0 * np.pi if d == 3 else 2.0)
    radius = (2.0 * k * volume / (n * ball)) ** (1.0 / d)
    pending = np.arange(m)
    while pending.size:
        qi, pj, d2 = _pairs_within(data, query[pending], radius)
        if qi.size and np.any(np.diff(qi) < 0):                 # grouped by query (it is)
            order = np.argsort(qi, kind="stable")
            qi, pj, d2 = qi[order], pj[order], d2[order]
        found = np.bincount(qi, minlength=pending.size)
        enough = np.flatnonzero(found >= k)
        if enough.size:
            idx, dd = _smallest_per_row(qi, pj, d2, found, enough, k, n)
            index[pending[enough]] = idx
            dist2[pending[enough]] = dd
        pending = pending[found < k]
        radius *= 2.0
    return index, dist2


def _smallest_per_row(qi, pj, d2, found, rows, k, n):
    """For the queries `rows` (each with at least k pairs), the k pairs of smallest distance,
    nearest first, ties by the lower index: (indices, squared distances), shape (len(rows), k).
    The pairs are grouped by query; `found` counts them per query."""
    width = int(found[rows].max())
    slot = np.full(len(found), -1, dtype=np.intp)
    slot[rows] = np.arange(len(rows))
    start = np.cumsum(found) - found
    row = slot[qi]
    keep = row >= 0
    col = (np.arange(qi.size) - start[qi])[keep]
    row = row[keep]
    dist = np.full((len(rows), width), np.inf)
    index = np.full((len(rows), width), n, dtype=np.intp)
    dist[row, col] = d2[keep]
    index[row, col] = pj[keep]
    kth = np.partition(dist, k - 1, axis=1)[:, k - 1:k]
    chosen = dist <= kth
    ties = np.flatnonzero(chosen.sum(axis=1) > k)
    for r in ties:                                   # equal distances at the k-th place: rare
        equal = np.flatnonzero(dist[r] == kth[r, 0])
        extra = k - int(np.count_nonzero(dist[r] < kth[r, 0]))
        drop = equal[np.argsort(index[r, equal], kind="stable")[extra:]]
        chosen[r, drop] = False
    rr, cc = np.nonzero(chosen)
    idx = index[rr, cc].reshape(len(rows), k)
    dd = dist[rr, cc].reshape(len(rows), k)
    order = np.lexsort((idx, dd), axis=-1)
    return np.take_along_axis(idx, order, 1), np.take_along_axis(dd, order, 1)
