//! Test support for the surftopo crates (a dev-dependency only).
//!
//! - The shared real meshes: found through `SURFTOPO_MESHES` (a relative path is taken from the
//!   workspace root, so `SURFTOPO_MESHES=../shared/meshes cargo test --workspace` works from the
//!   checkout); listed by `manifest.json`; loaded as validated surfaces.
//! - Independent checkers of results, written without the algorithms' code, and an independent
//!   reading of OBJ text ([`obj_text`]) and of PLY files ([`ply_parse`]).

pub mod obj_text;
pub mod ply_parse;

use std::path::{Path, PathBuf};
use surftopo_mesh::Surface;

/// One mesh of the shared collection, as the manifest describes it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SharedMesh {
    /// File name inside the folder.
    pub file: String,
    /// Full path.
    pub path: PathBuf,
    /// Vertices (after welding where needed).
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Genus.
    pub genus: i64,
    /// Whether exactly coincident vertices must be welded first (`chair_soup.off.gz`).
    pub needs_weld: bool,
}

/// The shared meshes folder, or `None` (printing that real-mesh tests are skipped) when
/// `SURFTOPO_MESHES` is not set. Panics if it is set but holds no `manifest.json`: with the
/// variable, the real-mesh tests are mandatory.
pub fn shared_meshes_dir() -> Option<PathBuf> {
    let Some(dir) = std::env::var_os("SURFTOPO_MESHES") else {
        eprintln!("SURFTOPO_MESHES is not set: real-mesh tests skipped");
        return None;
    };
    let dir = PathBuf::from(dir);
    let dir = if dir.is_relative() {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(dir)
    } else {
        dir
    };
    assert!(
        dir.join("manifest.json").is_file(),
        "SURFTOPO_MESHES={} holds no manifest.json",
        dir.display()
    );
    Some(dir)
}

/// Panics unless `SURFTOPO_MESHES` is set: the first step of every test `shared_mesh_tests!`
/// declares, so that a test binary built with the variable but run without it fails instead of
/// passing over an empty list.
pub fn require_shared_meshes() {
    assert!(
        std::env::var_os("SURFTOPO_MESHES").is_some(),
        "SURFTOPO_MESHES is not set, but this test was built with it: set it, or rebuild the \
         tests without it to have them listed as ignored"
    );
}

/// Declares the tests that need the shared meshes: for each named function `f`, a test
/// `shared_mesh_tests::f` that calls [`require_shared_meshes`] then `f()`.
///
/// libtest has no runtime skip, so the choice is made when the tests are built: when
/// `SURFTOPO_MESHES` was not set while this crate was built (its build script sets the cfg
/// `surftopo_meshes` otherwise, and reruns when the variable changes), the tests are
/// `#[ignore = "needs SURFTOPO_MESHES"]` and `cargo test` lists them as ignored. The functions
/// stay ordinary functions of the test file (formatted and linted as such).
///
/// ```ignore
/// surftopo_testkit::shared_mesh_tests!(every_shared_mesh, a_sample_of_shared_meshes);
///
/// fn every_shared_mesh() {
///     for mesh in surftopo_testkit::shared_meshes() { /* ... */ }
/// }
/// ```
#[cfg(surftopo_meshes)]
#[macro_export]
macro_rules! shared_mesh_tests {
    ($($name:ident),+ $(,)?) => {
        mod shared_mesh_tests {
            $(
                #[test]
                fn $name() {
                    $crate::require_shared_meshes();
                    super::$name()
                }
            )+
        }
    };
}

/// Declares the tests that need the shared meshes (see the other definition): built without
/// `SURFTOPO_MESHES`, so every one is ignored, with the reason.
#[cfg(not(surftopo_meshes))]
#[macro_export]
macro_rules! shared_mesh_tests {
    ($($name:ident),+ $(,)?) => {
        mod shared_mesh_tests {
            $(
                #[test]
                #[ignore = "needs SURFTOPO_MESHES"]
                fn $name() {
                    $crate::require_shared_meshes();
                    super::$name()
                }
            )+
        }
    };
}

/// Every mesh listed in the manifest (empty when `SURFTOPO_MESHES` is unset), smallest first.
pub fn shared_meshes() -> Vec<SharedMesh> {
    let Some(dir) = shared_meshes_dir() else {
        return Vec::new();
    };
    let text = std::fs::read_to_string(dir.join("manifest.json")).expect("manifest.json readable");
    let manifest: serde_json::Value = serde_json::from_str(&text).expect("manifest.json is JSON");
    let number = |v: &serde_json::Value| v.as_i64().expect("manifest count");
    let mut list: Vec<SharedMesh> = manifest["meshes"]
        .as_array()
        .expect("manifest has a meshes array")
        .iter()
        .map(|m| {
            let file = m["file"].as_str().expect("file name").to_string();
            SharedMesh {
                path: dir.join(&file),
                file,
                vertices: number(&m["V"]) as usize,
                edges: number(&m["E"]) as usize,
                faces: number(&m["F"]) as usize,
                genus: number(&m["genus"]),
                needs_weld: m["passes_without_vertex_welding"] == serde_json::Value::Bool(false),
            }
        })
        .collect();
    list.sort_by_key(|m| (m.faces, m.file.clone()));
    list
}

/// The shared meshes with at most `max_faces` faces.
pub fn shared_meshes_up_to(max_faces: usize) -> Vec<SharedMesh> {
    shared_meshes()
        .into_iter()
        .filter(|m| m.faces <= max_faces)
        .collect()
}

/// Reads and validates a shared mesh (welding it first where the manifest says so).
pub fn load(mesh: &SharedMesh) -> Surface {
    let soup = surftopo_io::read_path(&mesh.path).unwrap_or_else(|e| panic!("{}: {e}", mesh.file));
    let (positions, triangles) = {
        let triangles = soup
            .triangles()
            .unwrap_or_else(|e| panic!("{}: {e}", mesh.file));
        if mesh.needs_weld {
            let (welded, map) = surftopo_mesh::geometry::weld_exact(&soup.positions);
            let triangles = triangles
                .iter()
                .map(|t| t.map(|i| map[i as usize]))
                .collect();
            (welded, triangles)
        } else {
            (soup.positions, triangles)
        }
    };
    let surface = Surface::from_triangles(positions, &triangles)
        .unwrap_or_else(|e| panic!("{}: {e}", mesh.file));
    assert_eq!(
        (surface.mesh.vertex_count(), surface.mesh.face_count()),
        (mesh.vertices, mesh.faces),
        "{}: counts differ from the manifest",
        mesh.file
    );
    surface
}

/// The unit cube `[0, 1]³`: corner `k` at `(k & 1, (k >> 1) & 1, (k >> 2) & 1)` and its six
/// square faces, each counter-clockwise seen from outside.
pub fn unit_cube() -> (Vec<[f64; 3]>, [[u32; 4]; 6]) {
    let corners = (0..8u32)
        .map(|k| [k & 1, (k >> 1) & 1, (k >> 2) & 1].map(f64::from))
        .collect();
    let faces = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    (corners, faces)
}

/// Independent check that polygons (any sizes) form a closed, connected, consistently oriented
/// 2-manifold: every directed edge used once and its reverse used once, every vertex's faces one
/// fan. Returns `V - E + F` over the referenced vertices. Uses only hash maps over index pairs.
///
/// # Errors
/// A description of the first defect found.
pub fn check_closed_oriented_manifold(polygons: &[Vec<u32>]) -> Result<i64, String> {
    use std::collections::{HashMap, HashSet};
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    for (f, p) in polygons.iter().enumerate() {
        if p.len() < 3 {
            return Err(format!("face {f} has {} vertices", p.len()));
        }
        for i in 0..p.len() {
            let (a, b) = (p[i], p[(i + 1) % p.len()]);
            if a == b {
                return Err(format!("face {f} repeats vertex {a}"));
            }
            if directed.insert((a, b), f).is_some() {
                return Err(format!("directed edge ({a}, {b}) used twice (face {f})"));
            }
        }
    }
    for &(a, b) in directed.keys() {
        if !directed.contains_key(&(b, a)) {
            return Err(format!(
                "edge ({a}, {b}) has no opposite: boundary or bad orientation"
            ));
        }
    }
    // Fans: at each vertex, successor map "incoming edge (x, v) -> outgoing edge (v, y) of the same
    // face"; following the reverse of the outgoing edge must visit every face at v in one cycle.
    let mut next_in_face: HashMap<(u32, u32), u32> = HashMap::new();
    let mut faces_at: HashMap<u32, (usize, (u32, u32))> = HashMap::new();
    for p in polygons {
        for i in 0..p.len() {
            let (a, b, c) = (p[i], p[(i + 1) % p.len()], p[(i + 2) % p.len()]);
            next_in_face.insert((a, b), c);
            faces_at.entry(b).or_insert((0, (a, b))).0 += 1;
        }
    }
    for (&v, &(count, start)) in &faces_at {
        let (mut x, mut steps, mut seen) = (start.0, 0usize, HashSet::new());
        loop {
            let y = next_in_face[&(x, v)];
            steps += 1;
            if !seen.insert(y) || steps > count {
                break;
            }
            x = y;
            if (x, v) == start {
                break;
            }
        }
        if steps != count {
            return Err(format!("vertex {v}: its {count} faces do not form one fan"));
        }
    }
    let vertices = faces_at.len() as i64;
    let edges = (directed.len() / 2) as i64;
    Ok(vertices - edges + polygons.len() as i64)
}

/// One connected component of a triangulated surface, as [`classify_surface`] finds it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Piece {
    /// V − E + F.
    pub euler_characteristic: i64,
    /// Whether its faces can be oriented consistently.
    pub orientable: bool,
    /// Its boundary loops.
    pub boundary_loops: usize,
}

/// Independent classification of a triangulated surface (triangles over any vertex ids; a
/// compact 2-manifold, possibly with boundary, possibly non-orientable, in pieces): one [`Piece`]
/// per connected component, sorted. Only hash maps over index pairs and a breadth-first search.
///
/// # Errors
/// A description of the first defect that keeps the triangles from being a surface: an edge in
/// more than two faces, or a boundary vertex on more than two boundary edges.
pub fn classify_surface(triangles: &[[u32; 3]]) -> Result<Vec<Piece>, String> {
    use std::collections::{HashMap, HashSet};
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    // Per undirected edge: the faces on it, and whether each runs it from min to max.
    let mut on_edge: HashMap<(u32, u32), Vec<(usize, bool)>> = HashMap::new();
    for (f, t) in triangles.iter().enumerate() {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            on_edge.entry(key(a, b)).or_default().push((f, a < b));
        }
    }
    let mut boundary_degree: HashMap<u32, usize> = HashMap::new();
    for (&(a, b), faces) in &on_edge {
        match faces.len() {
            1 => {
                for v in [a, b] {
                    *boundary_degree.entry(v).or_default() += 1;
                }
            }
            2 => {}
            n => return Err(format!("edge ({a}, {b}) is in {n} faces")),
        }
    }
    if let Some((v, d)) = boundary_degree.iter().find(|&(_, &d)| d != 2) {
        return Err(format!("vertex {v} is on {d} boundary edges"));
    }
    let mut sign: Vec<Option<bool>> = vec![None; triangles.len()];
    let mut pieces = Vec::new();
    for start in 0..triangles.len() {
        if sign[start].is_some() {
            continue;
        }
        sign[start] = Some(false);
        let mut queue = vec![start];
        let (mut faces, mut orientable) = (Vec::new(), true);
        while let Some(f) = queue.pop() {
            faces.push(f);
            let t = triangles[f];
            for i in 0..3 {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                for &(g, forward) in &on_edge[&key(a, b)] {
                    if g == f {
                        continue;
                    }
                    // Two faces oriented alike traverse their shared edge in opposite directions.
                    let want = sign[f].unwrap() ^ (forward == (a < b));
                    match sign[g] {
                        None => {
                            sign[g] = Some(want);
                            queue.push(g);
                        }
                        Some(s) if s != want => orientable = false,
                        Some(_) => {}
                    }
                }
            }
        }
        let vertices: HashSet<u32> = faces.iter().flat_map(|&f| triangles[f]).collect();
        let edges: HashSet<(u32, u32)> = faces
            .iter()
            .flat_map(|&f| {
                let t = triangles[f];
                (0..3).map(move |i| key(t[i], t[(i + 1) % 3]))
            })
            .collect();
        // Boundary loops: walk the boundary edges of this piece as cycles.
        let boundary: Vec<(u32, u32)> = edges
            .iter()
            .copied()
            .filter(|e| on_edge[e].len() == 1)
            .collect();
        let mut next: HashMap<u32, Vec<u32>> = HashMap::new();
        for &(a, b) in &boundary {
            next.entry(a).or_default().push(b);
            next.entry(b).or_default().push(a);
        }
        let (mut seen, mut loops) = (HashSet::new(), 0);
        for &(a, _) in &boundary {
            if !seen.insert(a) {
                continue;
            }
            loops += 1;
            let mut stack = vec![a];
            while let Some(v) = stack.pop() {
                for &w in &next[&v] {
                    if seen.insert(w) {
                        stack.push(w);
                    }
                }
            }
        }
        pieces.push(Piece {
            euler_characteristic: vertices.len() as i64 - edges.len() as i64 + faces.len() as i64,
            orientable,
            boundary_loops: loops,
        });
    }
    pieces.sort();
    Ok(pieces)
}

#[cfg(test)]
mod tests {
    use super::check_closed_oriented_manifold;

    #[test]
    fn the_checker_accepts_a_cube_and_rejects_defects() {
        let cube: Vec<Vec<u32>> = vec![
            vec![0, 3, 2, 1],
            vec![4, 5, 6, 7],
            vec![0, 1, 5, 4],
            vec![1, 2, 6, 5],
            vec![2, 3, 7, 6],
            vec![3, 0, 4, 7],
        ];
        assert_eq!(check_closed_oriented_manifold(&cube), Ok(2));
        let mut open = cube.clone();
        open.pop();
        assert!(check_closed_oriented_manifold(&open).is_err());
        let mut flipped = cube.clone();
        flipped[0].reverse();
        assert!(check_closed_oriented_manifold(&flipped).is_err());
        // Two cubes sharing vertex 0: closed and oriented, but vertex 0 has two fans.
        let mut pinched = cube.clone();
        pinched.extend(
            cube.iter()
                .map(|f| f.iter().map(|&v| if v == 0 { 0 } else { v + 7 }).collect()),
        );
        let err = check_closed_oriented_manifold(&pinched).unwrap_err();
        assert!(err.contains("vertex 0"), "{err}");
    }
}
