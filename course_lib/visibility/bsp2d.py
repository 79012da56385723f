r"""Chapter 5, hidden-surface elimination (lesson section 5): BSP trees of line segments in the
plane, the form exam questions take (a floor plan seen from above, or polygons seen edge-on).

The 3D tree of :func:`course_lib.visibility.build_bsp` works on triangles; this module does the
same on segments, small enough to draw and to do by hand, and records every decision.

Convention (the same as the 3D tree: front = positive side of the line :math:`n \cdot x = c`):
a segment :math:`a \to b` has the normal :math:`n = (-(b_y - a_y),\ b_x - a_x)`, its direction
turned 90° counter-clockwise, so its **front is its left side** (walking from :math:`a` to
:math:`b`, the front is on the left hand). A point :math:`p` is in front when
:math:`s(p) = (b - a) \times (p - a) = n \cdot (p - a) > 0`.

Splitting names the parts of a segment ``c`` by their order from its start :math:`a`: ``c1``
(the part containing :math:`a`) and ``c2``; a part split again gets ``.1`` and ``.2``
(``c1.1``, ``c1.2``).
"""

from typing import NamedTuple

import numpy as np

from .._validate import as_array, as_choice, as_scalar, as_vector

__all__ = ["BSPNode2D", "BSPStep2D", "BSPTree2D", "BSPTraversal2D", "Fragment2D",
           "build_bsp_2d", "bsp2d_back_to_front", "bsp2d_front_to_back", "segment_side"]

_SEGMENT_NAMES = "abcdefghijklmnopqrstuvwxyz"


class Fragment2D(NamedTuple):
    """A segment or a part of one, as stored in a :class:`BSPTree2D`.

    Attributes
    ----------
    label : str
        ``"c"`` for a whole segment, ``"c1"``, ``"c2"``, ``"c1.2"`` for its parts.
    source : int
        Index of the input segment it comes from.
    start, end : ndarray, shape (2,)
        In the direction of the input segment (so its front side is the same).

    Examples
    --------
    >>> tree = build_bsp_2d([[[0, 0], [2, 0]]])
    >>> tree.root.fragments[0].label, tree.root.fragments[0].end.tolist()
    ('a', [2.0, 0.0])
    """
    label: str
    source: int
    start: np.ndarray
    end: np.ndarray


class BSPNode2D:
    """A node of a 2D BSP tree: a partition line, the fragments lying on it, two subtrees.

    Attributes
    ----------
    fragments : list of Fragment2D
        The partition (first) and any collinear fragments.
    normal : ndarray, shape (2,)
        Unit normal of the line, pointing to the front (left of the partition's direction).
    offset : float
        The line is ``normal . x = offset``.
    front, back : BSPNode2D or None

    Examples
    --------
    >>> tree = build_bsp_2d([[[0, 0], [2, 0]]])
    >>> tree.root.normal.tolist(), tree.root.offset, tree.root.label
    ([-0.0, 1.0], 0.0, 'a')
    """
    __slots__ = ("fragments", "normal", "offset", "front", "back")

    def __init__(self, fragments, normal, offset):
        self.fragments, self.normal, self.offset = fragments, normal, offset
        self.front = self.back = None

    @property
    def label(self):
        """The labels of the node's fragments, joined by ``+`` (the partition first)."""
        return "+".join(f.label for f in self.fragments)

    def __repr__(self):
        return f"BSPNode2D({self.label!r})"


class BSPTree2D(NamedTuple):
    """A 2D BSP tree of segments (:func:`build_bsp_2d`) and its statistics.

    Attributes
    ----------
    root : BSPNode2D
    fragments : list of Fragment2D
        Every stored fragment, in preorder (node by node).
    n_nodes : int
    n_splits : int
        Segments (or parts) cut in two during the build.
    depth : int
        Nodes on the longest root-to-leaf path.
    labels : list of str
        The input segments' labels.

    Examples
    --------
    >>> tree = build_bsp_2d([[[0, 0], [4, 0]], [[2, -1], [2, 1]]], order=[1, 0])
    >>> print(tree)
    b
    ├─ front: a1
    └─ back: a2
    >>> tree.n_nodes, tree.n_splits, tree.depth, tree.preorder()
    (3, 1, 2, ['b', 'a1', 'a2'])
    """
    root: BSPNode2D
    fragments: list
    n_nodes: int
    n_splits: int
    depth: int
    labels: list

    def __str__(self):
        return self.describe()

    def describe(self):
        """A text drawing of the tree: one node a line, front child above the back child.

        Returns
        -------
        str

        Examples
        --------
        >>> segs = [[[0, 0], [4, 0]], [[1, 1], [3, 1]], [[1, -1], [3, -1]]]
        >>> print(build_bsp_2d(segs).describe())
        a
        ├─ front: b
        └─ back: c
        """
        lines = [self.root.label]
        _draw_subtrees(self.root, "", lines)
        return "\n".join(lines)

    def preorder(self):
        """Node labels in preorder (node, front subtree, back subtree).

        Returns
        -------
        list of str

        Examples
        --------
        >>> build_bsp_2d([[[0, 0], [4, 0]], [[1, 1], [3, 1]]]).preorder()
        ['a', 'b']
        """
        out = []
        _walk_nodes(self.root, lambda node: out.append(node.label))
        return out

    def children(self):
        """For each node label, its (front child, back child) labels, None where empty.

        Returns
        -------
        dict

        Examples
        --------
        >>> build_bsp_2d([[[0, 0], [4, 0]], [[1, -1], [3, -1]]]).children()
        {'a': (None, 'b'), 'b': (None, None)}
        """
        out = {}
        _walk_nodes(self.root, lambda node: out.__setitem__(node.label, (
            node.front.label if node.front else None, node.back.label if node.back else None)))
        return out

    def split_segments(self):
        """The labels of the input segments that were cut, in input order.

        Examples
        --------
        >>> build_bsp_2d([[[0, 0], [4, 0]], [[2, -1], [2, 1]]]).split_segments()
        ['b']
        """
        cut = {f.source for f in self.fragments if f.label != self.labels[f.source]}
        return [self.labels[i] for i in sorted(cut)]


def _walk_nodes(node, visit):
    """Preorder (node, front, back) without recursion: a deep tree is no problem."""
    stack = [node]
    while stack:
        node = stack.pop()
        if node is not None:
            visit(node)
            stack += [node.back, node.front]


def _draw_subtrees(node, indent, lines):
    """The lines of the subtrees below `node`, front child first (no recursion)."""
    def push(node, indent):
        kids = [(k, c) for k, c in (("front", node.front), ("back", node.back)) if c is not None]
        for i, (kind, child) in reversed(list(enumerate(kids))):
            stack.append((child, kind, indent, i == len(kids) - 1))

    stack = []
    push(node, indent)
    while stack:
        child, kind, indent, last = stack.pop()
        lines.append(f"{indent}{'└─' if last else '├─'} {kind}: {child.label}")
        push(child, indent + ("   " if last else "│  "))


def _as_segments(segments, labels, order):
    segs = as_array(segments, "segments")
    if segs.ndim != 3 or segs.shape[1:] != (2, 2) or len(segs) == 0:
        raise ValueError("segments must be an array of shape (n, 2, 2): n >= 1 segments, each "
                         f"two end points (x, y), got shape {segs.shape}")
    length = np.hypot(*(segs[:, 1] - segs[:, 0]).T)
    if (length == 0).any():
        k = int(np.flatnonzero(length == 0)[0])
        raise ValueError(f"segments[{k}] has zero length (both end points are "
                         f"{segs[k, 0].tolist()}): it has no line to partition with")
    n = len(segs)
    if labels is None:
        labels = list(_SEGMENT_NAMES[:n]) if n <= 26 else [f"s{k}" for k in range(n)]
    if isinstance(labels, str) or len(labels) != n \
            or not all(isinstance(s, str) and s for s in labels):
        raise ValueError(f"labels must be {n} non-empty strings, one per segment, got {labels!r}")
    labels = list(labels)
    if len(set(labels)) != n:
        dup = next(s for s in labels if labels.count(s) > 1)
        raise ValueError(f"labels must be distinct, got {dup!r} twice")
    if order is None:
        order = list(range(n))
    else:
        if isinstance(order, str):
            order = list(order)
        order = [labels.index(o) if isinstance(o, str) and o in labels else o for o in order]
        ok = (len(order) == n and all(isinstance(o, (int, np.integer))
                                      and not isinstance(o, bool) for o in order)
              and sorted(int(o) for o in order) == list(range(n)))
        if not ok:
            raise ValueError(f"order must be a permutation of the {n} segment indices 0..{n - 1} "
                             f"(or of their labels), each once, got {order!r}")
        order = [int(o) for o in order]
    return segs, labels, order


def segment_side(segment, points):
    r"""Which side of the line through `segment` (a -> b) each point lies on.

    :math:`s(p) = (b - a) \times (p - a)`: positive on the **front** (left of a -> b), negative
    behind, zero on the line. It is twice the signed area of the triangle :math:`a, b, p`.

    Parameters
    ----------
    segment : array_like, shape (2, 2)
    points : array_like, shape (..., 2)

    Returns
    -------
    ndarray, shape (...)
        The signed value :math:`s(p)` (its sign is the side).

    Raises
    ------
    ValueError
        For a malformed or zero-length segment or malformed points.

    Examples
    --------
    >>> segment_side([[0, 0], [2, 0]], [[1, 3], [1, -1], [5, 0]]).tolist()
    [6.0, -2.0, 0.0]
    """
    seg, _, _ = _as_segments([segment], None, None)
    p = as_array(points, "points")
    if p.ndim == 0 or p.shape[-1] != 2:
        raise ValueError(f"points must have shape (..., 2), got {p.shape}")
    a, b = seg[0]
    d = b - a
    return d[0] * (p[..., 1] - a[1]) - d[1] * (p[..., 0] - a[0])


def build_bsp_2d(segments, order=None, labels=None, choose="order", eps=1e-9):
    r"""Build a BSP tree of segments, taking the partitions in the given order.

    The rule of the exam questions: the first segment of the order is the root's partition.
    Every other segment lies in front of its line (left of its direction), behind it, on it
    (collinear: kept in the node), or straddles it: then it is cut at the crossing into two
    parts, each going to its side. A segment touching the line at one end goes to the side of
    its other end, uncut. Each subtree repeats this with the segments it received, the
    partition being the one that comes first in the order (a part keeps its segment's place).

    Parameters
    ----------
    segments : array_like, shape (n, 2, 2)
        Segment ``k`` runs from ``segments[k, 0]`` (a) to ``segments[k, 1]`` (b); its front is
        its left side.
    order : sequence of int or str, optional
        A permutation of the indices (or labels) giving the order in which segments become
        partitions; default 0, 1, ..., n-1.
    labels : sequence of str, optional
        Distinct names, default ``"a", "b", ...``.
    choose : {"order", "fewest_splits"}, optional
        ``"fewest_splits"``: at each node take the segment whose line cuts the fewest others
        (ties broken by `order`), a common heuristic for smaller trees.
    eps : float, optional
        A point within `eps` (in units of :math:`s` divided by the partition's length) of a
        line counts as on it.

    Returns
    -------
    BSPTree2D

    Raises
    ------
    ValueError
        For a wrong shape, a non-finite coordinate, a zero-length segment, duplicate or
        missing labels, or an order that is not a permutation.

    Examples
    --------
    >>> segs = [[[0, 0], [4, 0]], [[2, -2], [2, 2]], [[5, 1], [5, 3]]]
    >>> tree = build_bsp_2d(segs)
    >>> print(tree)
    a
    ├─ front: b2
    │  └─ back: c
    └─ back: b1
    >>> tree.n_splits, [f.label for f in tree.fragments]
    (1, ['a', 'b2', 'c', 'b1'])
    """
    segs, labels, order = _as_segments(segments, labels, order)
    as_choice(choose, "choose", ("order", "fewest_splits"))
    eps = as_scalar(eps, "eps")
    rank = {k: r for r, k in enumerate(order)}
    items = [Fragment2D(labels[k], k, segs[k, 0], segs[k, 1]) for k in order]
    splits = [0]
    root = _build_node(items, rank, choose, eps, splits, labels)
    frags, depth = [], _tree_depth(root)
    _walk_nodes(root, lambda node: frags.extend(node.fragments))
    count = []
    _walk_nodes(root, count.append)
    return BSPTree2D(root, frags, len(count), splits[0], depth, labels)


def _tree_depth(node):
    deepest, stack = 0, [(node, 1)]
    while stack:
        node, level = stack.pop()
        if node is not None:
            deepest = max(deepest, level)
            stack += [(node.front, level + 1), (node.back, level + 1)]
    return deepest


def _line_sides(part, items, eps):
    """s at the start and end of every item, relative to the line of `part` (unit normal)."""
    d = part.end - part.start
    n = np.array([-d[1], d[0]]) / np.hypot(*d)
    starts = np.array([f.start for f in items])
    ends = np.array([f.end for f in items])
    s0, s1 = (starts - part.start) @ n, (ends - part.start) @ n
    s0[np.abs(s0) <= eps] = 0.0
    s1[np.abs(s1) <= eps] = 0.0
    return n, s0, s1


def _fewest_cuts(items, eps):
    cuts = []
    for p in items:
        _, s0, s1 = _line_sides(p, items, eps)
        cuts.append(int(np.sum(s0 * s1 < 0)))
    return int(np.argmin(cuts))        # the first of the minima: ties follow the order


def _part_label(label, source_label, k):
    return f"{label}{k}" if label == source_label else f"{label}.{k}"


def _build_node(items, rank, choose, eps, splits, names):
    """The tree of `items` (in order), built with an explicit stack (no recursion limit)."""
    root = _one_node(items, rank, choose, eps, splits, names)
    stack = [root]
    while stack:
        node, front, back = stack.pop()
        for attr, todo in (("front", front), ("back", back)):
            if todo:
                child = _one_node(todo, rank, choose, eps, splits, names)
                setattr(node, attr, child[0])
                stack.append(child)
    return root[0]


def _one_node(items, rank, choose, eps, splits, names):
    """One node: its partition, collinear fragments, and the sorted front and back lists."""
    pick = _fewest_cuts(items, eps) if choose == "fewest_splits" and len(items) > 2 else 0
    part = items[pick]
    rest = items[:pick] + items[pick + 1:]
    n = np.array([-(part.end - part.start)[1], (part.end - part.start)[0]])
    n = n / np.hypot(*n)
    node = BSPNode2D([part], n, float(n @ part.start))
    front, back = [], []
    if rest:
        _, s0, s1 = _line_sides(part, rest, eps)
        for f, a, b in zip(rest, s0, s1):
            if a == 0 and b == 0:
                node.fragments.append(f)
            elif a >= 0 and b >= 0:
                front.append(f)
            elif a <= 0 and b <= 0:
                back.append(f)
            else:
                splits[0] += 1
                x = f.start + a / (a - b) * (f.end - f.start)
                src = names[f.source]
                p1 = Fragment2D(_part_label(f.label, src, 1), f.source, f.start, x)
                p2 = Fragment2D(_part_label(f.label, src, 2), f.source, x, f.end)
                (front if a > 0 else back).append(p1)
                (back if a > 0 else front).append(p2)
    key = (lambda f: (rank[f.source], f.label))
    return node, sorted(front, key=key), sorted(back, key=key)



class BSPStep2D(NamedTuple):
    """One node's decision during a traversal (:func:`bsp2d_back_to_front`).

    Attributes
    ----------
    node : str
        The node's label.
    side : int
        +1: the eye is in front of the node's line, -1: behind it, 0: on it.
    value : float
        :math:`n \\cdot e - c`, the signed distance of the eye from the line.
    first, second : str
        ``"front"``/``"back"``: the subtree painted before the node and the one after.
    text : str
        The decision in words, for a worked solution.

    Examples
    --------
    >>> tree = build_bsp_2d([[[0, 0], [2, 0]]])
    >>> bsp2d_back_to_front(tree, [1, 3]).steps[0].side
    1
    """
    node: str
    side: int
    value: float
    first: str
    second: str
    text: str


class BSPTraversal2D(NamedTuple):
    """A painting order from a BSP tree (:func:`bsp2d_back_to_front`).

    Attributes
    ----------
    labels : list of str
        Fragment labels in drawing order.
    fragments : list of Fragment2D
        The same fragments.
    steps : list of BSPStep2D
        The decision at each node, in the order the nodes were visited.

    Examples
    --------
    >>> tree = build_bsp_2d([[[0, 0], [2, 0]], [[0, 1], [2, 1]]])
    >>> bsp2d_back_to_front(tree, [1, 5]).labels
    ['a', 'b']
    """
    labels: list
    fragments: list
    steps: list


def bsp2d_back_to_front(tree, eye, eps=1e-9):
    r"""The painter's order of a 2D BSP tree seen from `eye`: farthest fragments first.

    At each node, find the eye's side of the partition line, :math:`s = n \cdot e - c`:
    paint the subtree on the **other** side first (it cannot hide anything on the eye's side),
    then the node's own fragments, then the subtree on the eye's side; recurse in both
    subtrees with the same rule, deciding the side afresh at every node. An eye **on** the
    line (:math:`|s| \le` `eps`) sees the node's fragments edge-on, and no ray from it enters
    both half-planes, so either order is right; this function then paints as if the eye were
    in front (back subtree first) and records ``side = 0``.

    Parameters
    ----------
    tree : BSPTree2D
    eye : array_like, shape (2,)
    eps : float, optional

    Returns
    -------
    BSPTraversal2D

    Raises
    ------
    TypeError
        If `tree` is not a :class:`BSPTree2D`.
    ValueError
        For a malformed eye.

    Examples
    --------
    >>> segs = [[[0, 0], [4, 0]], [[2, -2], [2, 2]], [[5, 1], [5, 3]]]
    >>> tree = build_bsp_2d(segs)
    >>> out = bsp2d_back_to_front(tree, [1, 1])
    >>> out.labels
    ['b1', 'a', 'c', 'b2']
    >>> [(s.node, s.side) for s in out.steps]
    [('a', 1), ('b1', 1), ('b2', 1), ('c', 1)]
    """
    if not isinstance(tree, BSPTree2D):
        raise TypeError(f"tree must be a BSPTree2D (from build_bsp_2d), got {type(tree).__name__}")
    e = as_vector(eye, "eye", 2)
    eps = as_scalar(eps, "eps")
    frags, steps = [], []
    _paint_2d(tree.root, e, eps, frags, steps)
    return BSPTraversal2D([f.label for f in frags], frags, steps)


def bsp2d_front_to_back(tree, eye, eps=1e-9):
    """The reverse of :func:`bsp2d_back_to_front`: nearest fragments first (the order for
    occlusion culling or a front-to-back fill); the steps are the same decisions.

    Parameters
    ----------
    tree : BSPTree2D
    eye : array_like, shape (2,)
    eps : float, optional

    Returns
    -------
    BSPTraversal2D

    Examples
    --------
    >>> tree = build_bsp_2d([[[0, 0], [2, 0]], [[0, 1], [2, 1]]])
    >>> bsp2d_front_to_back(tree, [1, 5]).labels
    ['b', 'a']
    """
    out = bsp2d_back_to_front(tree, eye, eps)
    return BSPTraversal2D(out.labels[::-1], out.fragments[::-1], out.steps)


def _paint_2d(node, e, eps, frags, steps):
    """Far subtree, node, near subtree at every node, with an explicit stack."""
    stack = [(True, node)]
    while stack:
        visit, node = stack.pop()
        if node is None:
            continue
        if not visit:
            frags.extend(node.fragments)
            continue
        value = float(node.normal @ e - node.offset)
        side = 0 if abs(value) <= eps else (1 if value > 0 else -1)
        near, far = ("back", "front") if side < 0 else ("front", "back")
        where = {1: "in front of", -1: "behind", 0: "on the line of"}[side]
        text = (f"eye {where} {node.label} (s = {value:.3g}): paint its {far} subtree, then "
                f"{node.label}, then its {near} subtree")
        if side == 0:
            text += " (on the line: either order is right, back first chosen)"
        steps.append(BSPStep2D(node.label, side, value, far, near, text))
        stack += [(True, getattr(node, near)), (False, node), (True, getattr(node, far))]
