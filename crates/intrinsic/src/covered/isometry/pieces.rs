//! The connected pieces of a [`CoveredTriangulation`]'s surface K, their invariants, and the
//! Delaunay tessellation of each piece as a [`TwistedMap`] (see the parent module's doc).

use crate::covered::CoveredTriangulation;
use crate::flip::tessellation::is_cocircular;
use crate::isometry::twisted::TwistedMap;
use std::f64::consts::{PI, TAU};
use surftopo_mesh::{EdgeId, FaceId, SurfaceKind, UnionFind};

/// A vertex that may be flat: its angle sum is within the flatness margin of 2π (inside) or π
/// (on the boundary).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FlatVertex {
    /// The vertex of K.
    pub vertex: u32,
    /// Its angle sum.
    pub angle: f64,
    /// Whether it lies on the boundary.
    pub boundary: bool,
}

/// One connected component of K with its invariants.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Piece {
    /// Its topology: χ, orientability, boundary loops (exact).
    pub kind: SurfaceKind,
    /// The length of each boundary loop, sorted.
    pub loops: Vec<f64>,
    /// Its area.
    pub area: f64,
    /// Its first vertex of K that may be flat, if any.
    pub flat: Option<FlatVertex>,
}

impl Piece {
    /// The exact part of the invariants, for sorting and comparing.
    pub fn key(&self) -> (i64, bool, usize) {
        (
            self.kind.euler_characteristic,
            self.kind.orientable,
            self.kind.boundary_loops,
        )
    }
}

/// The component of every face of the cover D (a component of D is the lift of one of K),
/// numbered in the order of their smallest face ids; `u32::MAX` for dead face slots.
pub(crate) fn components(tri: &CoveredTriangulation) -> Vec<u32> {
    let mesh = tri.tri.mesh();
    let mut sets = UnionFind::new(mesh.face_slots());
    for h in mesh.halfedges() {
        sets.union(mesh.face(h).0, mesh.face(h.twin()).0);
    }
    let mut component = vec![u32::MAX; mesh.face_slots()];
    let mut roots = vec![u32::MAX; mesh.face_slots()];
    let mut count = 0;
    for f in mesh.faces() {
        let root = sets.find(f.0) as usize;
        if roots[root] == u32::MAX {
            roots[root] = count;
            count += 1;
        }
        component[f.idx()] = roots[root];
    }
    component
}

/// The pieces of K, in the order of [`components`], with their invariants; a vertex is taken
/// as possibly flat when its angle sum is within `flat_margin` radians of 2π (π on the
/// boundary).
pub(crate) fn pieces(
    tri: &CoveredTriangulation,
    component: &[u32],
    flat_margin: f64,
) -> Vec<Piece> {
    let cover = &tri.tri;
    let mesh = cover.mesh();
    let count = component
        .iter()
        .filter(|&&c| c != u32::MAX)
        .max()
        .map_or(0, |&c| c as usize + 1);
    let of_edge = |e: EdgeId| component[mesh.face(e.halfedge()).idx()] as usize;
    let (mut faces, mut edges, mut area) =
        (vec![0usize; count], vec![0usize; count], vec![0.0; count]);
    let mut orientable = vec![true; count];
    let classes = tri.surface_vertex_count();
    let mut angle = vec![0.0f64; classes];
    let mut vertex_piece = vec![u32::MAX; classes];
    for f in tri.surface_faces() {
        let c = component[f.idx()];
        faces[c as usize] += 1;
        area[c as usize] += cover.face_area(f);
        if tri.mirror(mesh.face_halfedge(f)).is_some() {
            orientable[c as usize] = false;
        }
        for h in mesh.face_halfedges(f) {
            let v = tri.class(mesh.origin(h)) as usize;
            angle[v] += cover.corner_angle(h);
            vertex_piece[v] = c;
        }
    }
    let mut on_boundary = vec![false; classes];
    // Boundary loops by their apex (on a doubled piece, the smaller of the two lifts' apexes).
    let mut loop_length: Vec<(usize, u32, f64)> = Vec::new();
    let mut loop_of_apex = vec![u32::MAX; mesh.vertex_slots()];
    for e in tri.surface_edges() {
        edges[of_edge(e)] += 1;
        if !tri.is_boundary_edge(e) {
            continue;
        }
        for v in mesh.edge_vertices(e) {
            on_boundary[tri.class(v) as usize] = true;
        }
        let h = e.halfedge();
        let virtual_side = if tri.is_real_face(mesh.face(h)) {
            h.twin()
        } else {
            h
        };
        let apex_corner = mesh.prev(virtual_side);
        let apex = mesh.origin(apex_corner);
        let key = match tri.mirror(apex_corner) {
            Some(m) => apex.min(mesh.dest(m)),
            None => apex,
        };
        let slot = &mut loop_of_apex[key.idx()];
        if *slot == u32::MAX {
            *slot = loop_length.len() as u32;
            loop_length.push((of_edge(e), key.0, 0.0));
        }
        loop_length[*slot as usize].2 += cover.length(e);
    }
    let mut vertices = vec![0usize; count];
    let mut flat: Vec<Option<FlatVertex>> = vec![None; count];
    for v in 0..classes {
        let c = vertex_piece[v];
        if c == u32::MAX {
            continue;
        }
        vertices[c as usize] += 1;
        let boundary = on_boundary[v];
        let target = if boundary { PI } else { TAU };
        if (angle[v] - target).abs() <= flat_margin && flat[c as usize].is_none() {
            flat[c as usize] = Some(FlatVertex {
                vertex: v as u32,
                angle: angle[v],
                boundary,
            });
        }
    }
    (0..count)
        .map(|c| {
            let mut loops: Vec<f64> = loop_length
                .iter()
                .filter(|l| l.0 == c)
                .map(|l| l.2)
                .collect();
            loops.sort_by(f64::total_cmp);
            Piece {
                kind: SurfaceKind::new(faces[c], edges[c], vertices[c], orientable[c], loops.len()),
                loops,
                area: area[c],
                flat: flat[c],
            }
        })
        .collect()
}

/// The Delaunay tessellation of each piece of K as a [`TwistedMap`] (indexed like
/// [`components`]), from a Delaunay triangulation on the cover: the triangles of K are merged
/// across the interior edges whose two triangles are co-circular within `cocircular` (a
/// spanning forest of them, as [`crate::delaunay_tessellation`] does, so every polygon is a
/// disk); each polygon is laid out by unfolding its triangles on the cover starting from its
/// smallest face, which lifts it once (on a doubled piece, each triangle of K is met either as
/// itself or as its mirror copy); a side is glued plainly to the side across its edge when that
/// side was laid as itself, reversed when its mirror copy was; a side across which lies a
/// virtual (cone) triangle is a boundary side.
pub(crate) fn tessellations(
    tri: &CoveredTriangulation,
    component: &[u32],
    count: usize,
    cocircular: f64,
) -> Vec<TwistedMap> {
    let cover = &tri.tri;
    let mesh = cover.mesh();
    // The triangle of K each real face of D stands for.
    let surface_face = |f: FaceId| {
        if tri.is_surface_face(f) {
            f
        } else {
            let m = tri
                .mirror(mesh.face_halfedge(f))
                .expect("a mirror copy has a mirror");
            mesh.face(m)
        }
    };
    let mut regions = UnionFind::new(mesh.face_slots());
    let mut merged = vec![false; mesh.edge_slots()];
    for e in tri.surface_edges() {
        if tri.is_boundary_edge(e) || !is_cocircular(cover, e, cocircular) {
            continue;
        }
        let h = e.halfedge();
        let [f, g] = [h, h.twin()].map(|x| surface_face(mesh.face(x)).0);
        let (rf, rg) = (regions.find(f), regions.find(g));
        if rf == rg {
            continue;
        }
        regions.union(rf, rg);
        merged[e.idx()] = true;
        if let Some(m) = tri.mirror(h) {
            merged[m.edge().idx()] = true;
        }
    }
    let mut maps: Vec<TwistedMap> = (0..count).map(|_| TwistedMap::new()).collect();
    let mut side_of = vec![u32::MAX; mesh.halfedge_slots()];
    let mut placed = vec![false; mesh.face_slots()];
    let mut position = vec![[f64::NAN; 2]; mesh.halfedge_slots()];
    let (mut queue, mut walk, mut corners) = (Vec::new(), Vec::new(), Vec::new());
    for f0 in tri.surface_faces() {
        if placed[f0.idx()] {
            continue;
        }
        placed[f0.idx()] = true;
        cover.lay_out_region(
            f0,
            &merged,
            &mut placed,
            surface_face,
            &mut position,
            &mut queue,
        );
        let start = queue
            .iter()
            .flat_map(|&f| mesh.face_halfedges(f))
            .filter(|h| !merged[h.edge().idx()])
            .min()
            .expect("a polygon has a side");
        walk.clear();
        let mut h = start;
        loop {
            walk.push(h);
            h = mesh.next(h);
            while merged[h.edge().idx()] {
                h = mesh.next(h.twin());
            }
            if h == start {
                break;
            }
        }
        corners.clear();
        corners.extend(walk.iter().map(|h| position[h.idx()]));
        let map = &mut maps[component[f0.idx()] as usize];
        let first = map.push_polygon(&corners);
        for (i, &h) in walk.iter().enumerate() {
            side_of[h.idx()] = first + i as u32;
        }
    }
    for h in mesh.halfedges() {
        let s = side_of[h.idx()];
        if s == u32::MAX {
            continue;
        }
        let t = h.twin();
        if !tri.is_real_face(mesh.face(t)) {
            continue;
        }
        let (other, reversed) = if side_of[t.idx()] != u32::MAX {
            (side_of[t.idx()], false)
        } else {
            let m = tri
                .mirror(t)
                .expect("a side laid as its mirror copy has a mirror");
            (side_of[m.idx()], true)
        };
        if s <= other {
            maps[component[mesh.face(h).idx()] as usize].glue(s, other, reversed);
        }
    }
    maps
}
