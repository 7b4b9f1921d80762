"""Independent checks of surftopo's results, written from the definitions (no surftopo code)."""

from __future__ import annotations

from collections import Counter, defaultdict

import numpy as np


def edges_of(F: np.ndarray) -> Counter:
    """Undirected edges of the faces, with the number of faces containing each."""
    count: Counter = Counter()
    for face in F.tolist():
        for i in range(len(face)):
            a, b = face[i], face[(i + 1) % len(face)]
            count[(min(a, b), max(a, b))] += 1
    return count


def euler_characteristic(F: np.ndarray) -> int:
    return len(np.unique(F)) - len(edges_of(F)) + len(F)


def is_closed_oriented(F: np.ndarray) -> bool:
    """Every directed half-edge once, and its reverse once: closed and consistently oriented."""
    directed: Counter = Counter()
    for face in F.tolist():
        for i in range(len(face)):
            directed[(face[i], face[(i + 1) % len(face)])] += 1
    return all(n == 1 and directed[(b, a)] == 1 for (a, b), n in directed.items())


def is_irreducible(F: np.ndarray) -> bool:
    """No edge satisfies the link condition (its endpoints share only its two opposite vertices),
    or the surface is the tetrahedron (whose edges all satisfy it but cannot be contracted)."""
    neighbours = defaultdict(set)
    for a, b, c in F.tolist():
        for u, v in ((a, b), (b, c), (c, a)):
            neighbours[u].add(v)
            neighbours[v].add(u)
    if len(neighbours) == 4:
        return True
    return all(len(neighbours[u] & neighbours[v]) > 2 for (u, v) in edges_of(F))


def quads_pair_triangles(Q: np.ndarray, F: np.ndarray) -> bool:
    """Every quad (a, b, c, d) is two input triangles glued along a diagonal, counter-clockwise as
    the input, and every input triangle is in exactly one quad."""
    triangles = {tuple(np.roll(t, -int(np.argmin(t)))) for t in F.tolist()}
    used: set = set()

    def canon(t):
        t = list(t)
        k = t.index(min(t))
        return tuple(t[k:] + t[:k])

    for a, b, c, d in Q.tolist():
        for pair in (((a, b, c), (a, c, d)), ((b, c, d), (b, d, a))):
            first, second = canon(pair[0]), canon(pair[1])
            if first in triangles and second in triangles:
                used.update((first, second))
                break
        else:
            return False
    return len(used) == len(triangles) == 2 * len(Q)


def triangle_areas(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)
