"""Peer triangle-to-quad converters for the quality benchmark (never used by the tests).

    python quad_peers.py gmsh|gmsh-blossom|blender IN.off OUT.off

Reads a triangle mesh (OFF), converts it with the chosen peer, writes the resulting polygon mesh
(the tool's vertices after the call; quads and the triangles left) as OFF and prints one JSON line
{"seconds": S, "cpu_seconds": C}: the wall-clock and process CPU time (all threads) of the
conversion call alone (mesh loading excluded).

- gmsh: Gmsh's Blossom recombination (the Blossom-Quad method of Remacle et al. 2012):
  the triangles become one discrete surface, `Mesh.RecombinationAlgorithm = 1` (Blossom),
  `Mesh.RecombineMinimumQuality = 0` (every pair may be used), then `gmsh.model.mesh.recombine()`.
- gmsh-blossom: the same without the topological optimisation and the node repositioning and
  smoothing that follow the pairing (`Mesh.RecombineOptimizeTopology = 0`,
  `Mesh.RecombineNodeRepositioning = 0`, `Mesh.Smoothing = 0`): the quads are pairs of the input's
  own triangles, as `surftopo quad --objective quality` makes them.
- blender: Blender's "Triangles to Quads" (`bmesh.ops.join_triangles`) with the operator's
  default thresholds (40 degrees for face and shape angles).

Set-up (not needed by the tests): a venv with `pip install gmsh bpy` (bpy needs Python 3.11).
"""

import json
import math
import sys
import time


def read_off(path):
    with open(path) as f:
        words = [w for line in f for w in line.split("#", 1)[0].split()]
    if not words or words[0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    pos = 4
    verts = []
    for _ in range(nv):
        verts.append(tuple(float(w) for w in words[pos : pos + 3]))
        pos += 3
    faces = []
    for _ in range(nf):
        k = int(words[pos])
        faces.append([int(w) for w in words[pos + 1 : pos + 1 + k]])
        pos += 1 + k
    return verts, faces


def write_off(path, verts, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(verts)} {len(faces)} 0\n")
        for v in verts:
            f.write(f"{v[0]!r} {v[1]!r} {v[2]!r}\n")
        for face in faces:
            f.write(f"{len(face)} {' '.join(map(str, face))}\n")


def run_gmsh(verts, faces, pairing_only=False):
    import gmsh

    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("peer")
    surface = gmsh.model.addDiscreteEntity(2)
    node_tags = list(range(1, len(verts) + 1))
    gmsh.model.mesh.addNodes(2, surface, node_tags, [c for v in verts for c in v])
    gmsh.model.mesh.addElementsByType(
        surface, 2, list(range(1, len(faces) + 1)), [i + 1 for f in faces for i in f]
    )
    gmsh.option.setNumber("Mesh.RecombinationAlgorithm", 1)
    gmsh.option.setNumber("Mesh.RecombineMinimumQuality", 0)
    if pairing_only:
        gmsh.option.setNumber("Mesh.RecombineOptimizeTopology", 0)
        gmsh.option.setNumber("Mesh.RecombineNodeRepositioning", 0)
        gmsh.option.setNumber("Mesh.Smoothing", 0)
    start, cpu = time.perf_counter(), time.process_time()
    gmsh.model.mesh.recombine()
    seconds = (time.perf_counter() - start, time.process_time() - cpu)
    # Recombination may move, add or remove nodes (topology optimisation, smoothing): the
    # output uses Gmsh's nodes after the call.
    tags, coords, _ = gmsh.model.mesh.getNodes()
    index = {int(t): i for i, t in enumerate(tags)}
    verts = [tuple(coords[3 * i : 3 * i + 3]) for i in range(len(tags))]
    out = []
    for kind, corners in ((2, 3), (3, 4)):
        _, nodes = gmsh.model.mesh.getElementsByType(kind, surface)
        nodes = [index[int(t)] for t in nodes]
        out.extend(nodes[i : i + corners] for i in range(0, len(nodes), corners))
    gmsh.finalize()
    return verts, out, seconds


def run_blender(verts, faces):
    import bpy  # noqa: F401 (bmesh is importable once bpy is)
    import bmesh

    bm = bmesh.new()
    bverts = [bm.verts.new(v) for v in verts]
    for f in faces:
        bm.faces.new([bverts[i] for i in f])
    bm.verts.index_update()
    bm.normal_update()
    threshold = math.radians(40.0)
    start, cpu = time.perf_counter(), time.process_time()
    bmesh.ops.join_triangles(
        bm,
        faces=list(bm.faces),
        angle_face_threshold=threshold,
        angle_shape_threshold=threshold,
    )
    seconds = (time.perf_counter() - start, time.process_time() - cpu)
    bm.verts.index_update()
    verts = [tuple(v.co) for v in bm.verts]
    out = [[v.index for v in f.verts] for f in bm.faces]
    bm.free()
    return verts, out, seconds


def main():
    runs = {
        "gmsh": run_gmsh,
        "gmsh-blossom": lambda v, f: run_gmsh(v, f, pairing_only=True),
        "blender": run_blender,
    }
    if len(sys.argv) != 4 or sys.argv[1] not in runs:
        raise SystemExit(__doc__)
    verts, faces = read_off(sys.argv[2])
    verts, out, seconds = runs[sys.argv[1]](verts, faces)
    write_off(sys.argv[3], verts, out)
    print(json.dumps({"seconds": seconds[0], "cpu_seconds": seconds[1]}))


if __name__ == "__main__":
    main()
