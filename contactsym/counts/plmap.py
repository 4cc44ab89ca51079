"""Continuous piecewise-linear maps on the orthants of R^k: degree and preimage counts.

Such a map is ``G(z) = sum_j c_j^{sign z_j} z_j``: continuity across the facet z_j = 0
forces the pieces on either side to share every column but the j-th, so column j
depends on sign z_j alone (``plus[:, j]`` for z_j > 0, ``minus[:, j]`` for z_j < 0).
The equilibria of a scene are the solutions of ``G(z) + b = 0``, b carrying the load.

Facts used (for nonzero orthant determinants D_s = det[c_1^{s_1} ... c_k^{s_k}]):

- G is proper (``|G(z)|`` >= c ``|z|`` on every orthant), so its degree is defined, and for a
  b off the images of the facets (a regular value) ``deg = sum of sign D_s`` over the
  orthants s that hold a solution; the count is then congruent to deg mod 2.
- Coherent orientation (all D_s of one sign) holds iff G is a homeomorphism, i.e. one
  solution for every b (Samelson, Thrall and Wesler 1958 for the complementarity map,
  Kuhn and Loewen 1987 for orthant fans: each (k-2)-face lies in four orthants).
- The count is constant on each cell cut out of R^k by the hyperplanes spanned by the
  images of the facets; :meth:`OrthantMap.count_set` visits every cell next to a line
  where k - 1 of those hyperplanes meet (every cell, in general position).
- k = 2: the images of the four half-axes are V = (c_1^+, c_2^+, -c_1^-, -c_2^-), in the
  counter-clockwise order of the quadrants (+,+), (-,+), (-,-), (+,-); the turn from V_i
  to V_{i+1} has the sign of the i-th determinant and size below pi. The degree is the
  winding number of that closed polygon: see :func:`k2_label`.
"""

from __future__ import annotations

import itertools

import numpy as np

from ..arguments import between, checked, require

__all__ = ["OrthantMap", "orthant_patterns", "k2_quadrants", "k2_label", "count_label"]


@checked(k=between(1, 16))
def orthant_patterns(k: int) -> list[tuple[int, ...]]:
    """The 2^k sign patterns, (+1, ..., +1) first.

    Examples
    --------
    >>> orthant_patterns(2)
    [(1, 1), (1, -1), (-1, 1), (-1, -1)]
    """
    return list(itertools.product((1, -1), repeat=k))


#: The quadrants of k = 2 in counter-clockwise order, as the turns of the image polygon.
#:
#: >>> from contactsym.counts import k2_quadrants
#: >>> k2_quadrants[0], len(k2_quadrants)
#: ((1, 1), 4)
k2_quadrants = ((1, 1), (-1, 1), (-1, -1), (1, -1))

_WORDS = ["none", "one", "two", "three", "four", "five", "six", "seven", "eight"]


@checked(counts="Collection[int]")
def count_label(counts) -> str:
    """'unique', 'two or none', 'one or three', 'none, two or four', ...

    Examples
    --------
    >>> count_label({0, 2}), count_label({1}), count_label({0, 2, 4})
    ('two or none', 'unique', 'none, two or four')
    """
    require(bool(counts) and min(counts) >= 0, "count_label", "counts", counts, "the possible counts, e.g. {0, 2}")
    counts = tuple(sorted(counts))
    if counts == (1,):
        return "unique"
    if counts == (0, 2):
        return "two or none"
    words = [_WORDS[c] if c < len(_WORDS) else str(c) for c in counts]
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]


@checked(cross_sign="Callable | None")
def k2_label(det_signs: dict, cross_sign) -> str:
    """The counts of a k = 2 orthant map over all loads, from exact signs.

    Parameters
    ----------
    det_signs : dict
        Sign (+1 or -1) of the determinant of each quadrant.
    cross_sign : callable
        ``cross_sign(i)`` gives the sign of det(V_i, V_{i+2}) (indices mod 4, V as in
        the module docstring); it is asked only with exactly one odd determinant.

    Notes
    -----
    With turns t_i (|t_i| < pi, sign of the i-th determinant) summing to 2 pi deg:

    - four of one sign: deg = +-1, each direction covered once: unique;
    - two and two, adjacent: the polygon winds up and back, every direction in the
      swept sector twice, the rest never: two or none;
    - two and two, alternating: the four arcs share a common direction (none ends
      before another begins), so four occurs; outside the swept range none; two next
      to an end of the range unless V_0 || V_2 and V_1 || V_3: none, two or four;
    - one odd turn t_i: the other three sum to |t_i| < pi (deg = 0: two or none) or to
      2 pi + |t_i| (deg = +-1: the first two of them then sum past pi, one or three).
      Which, is the sign of det(V_{i+1}, V_{i+3}) times the sign of the majority:
      positive iff those two turns sum below pi.

    Examples
    --------
    >>> k2_label({(1, 1): 1, (-1, 1): -1, (-1, -1): 1, (1, -1): 1}, lambda i: -1)
    'one or three'
    >>> k2_label({(1, 1): 1, (-1, 1): -1, (-1, -1): 1, (1, -1): 1}, lambda i: 1)
    'two or none'
    """
    known = all(det_signs.get(q) in (1, -1) for q in k2_quadrants)
    require(known, "k2_label", "det_signs", det_signs, "a sign +1 or -1 for each quadrant (1, 1), (-1, 1), ...")
    turns = [det_signs[q] for q in k2_quadrants]
    negative = [i for i, s in enumerate(turns) if s < 0]
    if len(negative) in (0, 4):
        return "unique"
    if len(negative) == 2:
        i, j = negative
        return "two or none" if (j - i) % 2 else "none, two or four"
    odd = negative[0] if len(negative) == 1 else next(i for i, s in enumerate(turns) if s > 0)
    majority = -turns[odd]
    return "two or none" if majority * cross_sign((odd + 1) % 4) > 0 else "one or three"


@checked(plus="RealArray", minus="RealArray")
class OrthantMap:
    """A numeric piecewise-linear map on orthants, possibly a batch of them.

    Parameters
    ----------
    plus, minus : array_like, shape (..., k, k)
        Column j is the j-th column on z_j > 0 (``plus``) or z_j < 0 (``minus``).

    Examples
    --------
    >>> G = OrthantMap([[2.0]], [[-1.0]])  # slope 2 on z > 0, -1 on z < 0
    >>> G.count([[-1.0], [1.0]])[0]
    array([2, 0])
    >>> G.degree(), G.count_set()
    (0, {0, 2})
    """

    def __init__(self, plus, minus):
        self.plus = np.asarray(plus, dtype=float)
        self.minus = np.asarray(minus, dtype=float)
        square = self.plus.ndim >= 2 and self.plus.shape[-1] == self.plus.shape[-2]
        require(
            square and self.plus.shape == self.minus.shape,
            "OrthantMap",
            "plus, minus",
            (plus, minus),
            "two k x k arrays",
        )
        self.k = self.plus.shape[-1]
        self.patterns = orthant_patterns(self.k)

    def matrix(self, pattern) -> np.ndarray:
        """The matrix of the piece on the orthant of ``pattern``."""
        chosen = np.array(pattern) > 0
        return np.where(chosen, self.plus, self.minus)

    def determinants(self) -> dict:
        return {p: np.linalg.det(self.matrix(p)) for p in self.patterns}

    def vertices(self) -> np.ndarray:
        """Images of the 2k half-axes: (..., 2k, k), +e_j then -e_j."""
        plus = np.swapaxes(self.plus, -1, -2)
        minus = -np.swapaxes(self.minus, -1, -2)
        return np.concatenate([plus, minus], axis=-2)

    def solutions(self, b, tol: float = 1e-9):
        """For each orthant the solution of G(z) + b = 0 there, and whether it lies inside.

        Returns ``{pattern: (z, inside, on_edge)}``; ``on_edge`` marks loads whose solution
        sits within ``tol`` (relative) of a face, where the count is not decided.
        """
        b = np.asarray(b, dtype=float)
        out = {}
        for p in self.patterns:
            M = np.broadcast_to(self.matrix(p), b.shape[:-1] + (self.k, self.k))
            size = np.abs(M).max(axis=(-2, -1)) ** self.k
            singular = ~(np.abs(np.linalg.det(M)) > tol * size)  # a non-isolated solution set: undecided
            safe = np.where(singular[..., None, None], np.eye(self.k), M)
            z = np.linalg.solve(safe, -b[..., None])[..., 0]
            scale = np.maximum(np.abs(z).max(axis=-1, keepdims=True), np.abs(b).max(axis=-1, keepdims=True))
            signed = z * np.array(p)
            inside = np.all(signed > tol * scale, axis=-1) & ~singular
            on_edge = np.any(np.abs(signed) <= tol * scale, axis=-1) & np.all(signed > -tol * scale, axis=-1)
            out[p] = (z, inside, on_edge | singular)
        return out

    def count(self, b, tol: float = 1e-9) -> tuple[np.ndarray, np.ndarray]:
        """Number of solutions of G(z) + b = 0 for each load, and a mask of undecided loads.

        b has shape (..., k), broadcast against the batch of maps.
        """
        solved = self.solutions(b, tol)
        counts = sum(inside.astype(int) for _, inside, _ in solved.values())
        undecided = np.any([edge for _, _, edge in solved.values()], axis=0)
        return counts, undecided

    def degree(self) -> int:
        """The degree of one map (no batch): signed count at a load off every facet image."""
        dets = self.determinants()
        loads = self._cell_loads()
        solved = self.solutions(loads)
        regular = ~np.any([edge for _, _, edge in solved.values()], axis=0)
        if not regular.any():
            raise ValueError("no regular load found: the map is degenerate")
        first = int(np.argmax(regular))
        return int(sum(np.sign(dets[p]) for p, (_, inside, _) in solved.items() if inside[first]))

    def _facet_spans(self) -> np.ndarray:
        """For each facet, the images of its k - 1 edges: (k 2^(k-1), k - 1, k)."""
        V = self.vertices()
        spans = []
        for j in range(self.k):
            others = [i for i in range(self.k) if i != j]
            for sides in itertools.product((0, 1), repeat=self.k - 1):
                spans.append([V[i + self.k * side] for i, side in zip(others, sides)])
        return np.array(spans)

    def _hyperplane_normals(self) -> np.ndarray:
        spans = self._facet_spans()
        if self.k == 2:
            normals = np.stack([-spans[:, 0, 1], spans[:, 0, 0]], axis=-1)
        elif self.k == 3:
            normals = np.cross(spans[:, 0], spans[:, 1])
        else:
            normals = np.array([np.linalg.svd(np.vstack([rows, np.zeros((1, self.k))]))[2][-1] for rows in spans])
        return normals / np.linalg.norm(normals, axis=-1, keepdims=True)

    def _cell_loads(self, eps: float = 1e-4) -> np.ndarray:
        """A load inside every cell next to a line where k - 1 facet hyperplanes meet: (n, k)."""
        if self.k == 1:
            return np.array([[1.0], [-1.0]])
        normals = self._hyperplane_normals()
        chosen = np.array(list(itertools.combinations(range(len(normals)), self.k - 1)))
        bases = normals[chosen]  # (pairs, k - 1, k)
        if self.k == 2:
            lines = np.stack([bases[:, 0, 1], -bases[:, 0, 0]], axis=-1)
        elif self.k == 3:
            lines = np.cross(bases[:, 0], bases[:, 1])
        else:
            lines = np.array([np.linalg.svd(np.vstack([b, np.zeros((1, self.k))]))[2][-1] for b in bases])
        length = np.linalg.norm(lines, axis=-1)
        keep = length > 1e-9  # hyperplanes that meet in a line
        lines, bases = lines[keep] / length[keep, None], bases[keep]
        offsets = np.array(list(itertools.product((1, -1), repeat=self.k - 1)), dtype=float)
        shifts = eps * np.einsum("sa,lak->lsk", offsets, bases)
        loads = np.concatenate([lines[:, None] + shifts, -lines[:, None] + shifts], axis=1)
        return loads.reshape(-1, self.k)

    def count_set(self) -> set:
        """The counts that loads in open cells produce (one map, no batch).

        Each load sits in an open cell or is marked undecided; steps of three sizes reach
        thin cells (a cell narrower than the smallest step is missed, a count never invented).
        """
        loads = np.concatenate([self._cell_loads(eps) for eps in (1e-3, 1e-6, 1e-9)])
        counts, undecided = self.count(loads, tol=1e-12)
        return set(counts[~undecided].tolist())
