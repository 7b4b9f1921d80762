//! The input check shared by the three algorithms.

use surftopo_mesh::{EdgeId, FaceId, SurfaceMesh, VertexId};

use crate::IrreducibleError;

/// Checks that the (closed, connected, orientable) mesh is simplicial: no loop, no multi-edge, and
/// not the two-triangle sphere (the only closed connected surface with two faces on the same three
/// vertices). The algorithms call it before doing anything. O(E) time, two arrays of size V.
///
/// # Errors
/// The first problem found, naming the offending edges, vertices or faces: loops (in edge id
/// order) before multi-edges (in vertex id order) before the two-triangle sphere.
pub fn check_simplicial(mesh: &SurfaceMesh) -> Result<(), IrreducibleError> {
    if mesh.face_count() == 0 {
        return Err(IrreducibleError::Empty);
    }
    for e in mesh.edges() {
        let [a, b] = mesh.edge_vertices(e);
        if a == b {
            return Err(IrreducibleError::Loop { edge: e, vertex: a });
        }
    }
    let mut owner = vec![VertexId::INVALID; mesh.vertex_slots()];
    let mut via = vec![EdgeId::INVALID; mesh.vertex_slots()];
    for v in mesh.vertices() {
        for h in mesh.outgoing(v) {
            let w = mesh.dest(h);
            if owner[w.idx()] == v {
                return Err(IrreducibleError::MultiEdge {
                    edges: [via[w.idx()], h.edge()],
                    vertices: [v, w],
                });
            }
            owner[w.idx()] = v;
            via[w.idx()] = h.edge();
        }
    }
    if mesh.face_count() <= 2 {
        let mut faces = mesh.faces();
        let first = faces.next().unwrap_or(FaceId::INVALID);
        return Err(IrreducibleError::DuplicateFace {
            faces: [first, faces.next().unwrap_or(first)],
        });
    }
    Ok(())
}
