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


def classify(F: np.ndarray) -> list[tuple[int, bool, int]]:
    """(Euler characteristic, orientable, boundary loops) of each connected component, sorted:
    breadth-first search over faces through shared edges, a sign flipped across an edge that the
    two faces run the same way, boundary loops as cycles of edges in one face."""
    faces = F.tolist()
    on_edge = defaultdict(list)
    for f, face in enumerate(faces):
        for i in range(3):
            a, b = face[i], face[(i + 1) % 3]
            on_edge[(min(a, b), max(a, b))].append((f, a < b))
    sign: dict = {}
    pieces = []
    for start in range(len(faces)):
        if start in sign:
            continue
        sign[start] = False
        queue, members, orientable = [start], [], True
        while queue:
            f = queue.pop()
            members.append(f)
            face = faces[f]
            for i in range(3):
                a, b = face[i], face[(i + 1) % 3]
                for g, forward in on_edge[(min(a, b), max(a, b))]:
                    if g == f:
                        continue
                    want = sign[f] ^ (forward == (a < b))
                    if g not in sign:
                        sign[g] = want
                        queue.append(g)
                    elif sign[g] != want:
                        orientable = False
        vertices = {v for f in members for v in faces[f]}
        edges = {(min(a, b), max(a, b)) for f in members
                 for a, b in zip(faces[f], faces[f][1:] + faces[f][:1])}
        boundary = [e for e in edges if len(on_edge[e]) == 1]
        parent = {v: v for e in boundary for v in e}

        def find(v):
            while parent[v] != v:
                v = parent[v]
            return v

        for a, b in boundary:
            parent[find(a)] = find(b)
        loops = len({find(v) for v in parent})
        pieces.append((len(vertices) - len(edges) + len(members), orientable, loops))
    return sorted(pieces)


def is_irreducible_surface(F: np.ndarray) -> bool:
    """No edge contracts keeping the topology, by Dey, Edelsbrunner, Guha and Nekhayev's rule:
    with the boundary coned over one vertex ω, an edge ab contracts iff the common neighbours of
    a and b are exactly the vertices opposite ab, and no edge wz has both a-w-z and b-w-z faces."""
    omega = -1
    faces = {tuple(sorted(f)) for f in F.tolist()}
    count = edges_of(F)
    opposite = defaultdict(set)
    for a, b, c in F.tolist():
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            opposite[(min(u, v), max(u, v))].add(w)
    neighbours = defaultdict(set)
    for a, b in count:
        neighbours[a].add(b)
        neighbours[b].add(a)
    for (a, b), n in count.items():
        if n == 1:
            opposite[(a, b)].add(omega)
            faces.add(tuple(sorted((a, b, omega))))
            neighbours[a].add(omega)
            neighbours[b].add(omega)
    for (a, b) in count:
        common = neighbours[a] & neighbours[b]
        if common != opposite[(a, b)]:
            continue
        pairs = [(w, z) for w in common for z in common if w < z]
        if not any(tuple(sorted((a, w, z))) in faces and tuple(sorted((b, w, z))) in faces
                   for w, z in pairs):
            return False
    return True


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


def laplacian_spectrum(L) -> tuple[np.ndarray, np.ndarray, float]:
    """Checks what every cotan Laplacian is (symmetric, rows summing to zero, positive
    semi-definite) and returns its dense form, its eigenvalues (ascending) and its largest
    absolute entry, the scale of the tolerances."""
    dense = L.toarray()
    scale = np.abs(dense).max()
    assert np.abs(dense - dense.T).max() <= 1e-14 * scale
    assert np.abs(dense.sum(axis=1)).max() <= 1e-12 * scale
    eigenvalues = np.linalg.eigvalsh(dense)
    assert eigenvalues[0] >= -1e-10 * scale
    return dense, eigenvalues, scale


def triangle_areas(V: np.ndarray, F: np.ndarray) -> np.ndarray:
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1)


def dual_edges(F: np.ndarray) -> list[tuple[int, int]]:
    """The pairs of triangles sharing an edge (the dual graph of a surface's triangles)."""
    on_edge = defaultdict(list)
    for f, face in enumerate(F.tolist()):
        for i in range(3):
            a, b = face[i], face[(i + 1) % 3]
            on_edge[(min(a, b), max(a, b))].append(f)
    return [(fs[0], fs[1]) for fs in on_edge.values() if len(fs) == 2]


def maximum_matching_size(n: int, edges: list[tuple[int, int]]) -> int:
    """The size of a maximum matching of a graph on nodes 0..n-1, by Edmonds' blossom algorithm
    (the textbook version: a breadth-first alternating tree from each free node, odd cycles
    contracted through their base; O(n^3), for test graphs)."""
    adjacent = [[] for _ in range(n)]
    for a, b in edges:
        adjacent[a].append(b)
        adjacent[b].append(a)
    mate = [-1] * n

    def augment_from(root):
        parent = [-1] * n
        base = list(range(n))
        used = [False] * n
        used[root] = True
        queue = [root]

        def lca(a, b):
            seen = [False] * n
            while True:
                a = base[a]
                seen[a] = True
                if mate[a] == -1:
                    break
                a = parent[mate[a]]
            while True:
                b = base[b]
                if seen[b]:
                    return b
                b = parent[mate[b]]

        def mark(v, b, child, blossom):
            while base[v] != b:
                blossom[base[v]] = blossom[base[mate[v]]] = True
                parent[v] = child
                child = mate[v]
                v = parent[mate[v]]

        head = 0
        while head < len(queue):
            v = queue[head]
            head += 1
            for w in adjacent[v]:
                if base[v] == base[w] or mate[v] == w:
                    continue
                if w == root or (mate[w] != -1 and parent[mate[w]] != -1):
                    b = lca(v, w)
                    blossom = [False] * n
                    mark(v, b, w, blossom)
                    mark(w, b, v, blossom)
                    for u in range(n):
                        if blossom[base[u]]:
                            base[u] = b
                            if not used[u]:
                                used[u] = True
                                queue.append(u)
                elif parent[w] == -1:
                    parent[w] = v
                    if mate[w] == -1:
                        while w != -1:
                            pv = parent[w]
                            ppv = mate[pv]
                            mate[w], mate[pv] = pv, w
                            w = ppv
                        return True
                    used[mate[w]] = True
                    queue.append(mate[w])
        return False

    for v in range(n):
        if mate[v] == -1:
            augment_from(v)
    return sum(1 for v in range(n) if mate[v] != -1) // 2


def pairing_uses_triangles(Q: np.ndarray, T: np.ndarray, F: np.ndarray, n: int,
                           added_edges: np.ndarray) -> bool:
    """Every input triangle is a triangle left (a row of T), or half of one quad [a, d, b, c]
    (the triangles (a, b, c) and (b, a, d) glued along the diagonal a-b), or split at an added
    vertex w = corner 0 (numbered from n) of the quad [w, y, z, x], w the midpoint of the
    boundary edge x-y of the input triangle (x, y, z). Corner orders are not checked here."""
    want = Counter(tuple(sorted(t)) for t in F.tolist())
    got: Counter = Counter()
    for a, d, b, c in Q.tolist():
        if a >= n:
            x, y = added_edges[a - n].tolist()
            if (d, c) != (y, x):
                return False
            got[tuple(sorted((x, y, b)))] += 1
        else:
            got[tuple(sorted((a, b, c)))] += 1
            got[tuple(sorted((b, a, d)))] += 1
    for t in T.tolist():
        got[tuple(sorted(t))] += 1
    return got == want
