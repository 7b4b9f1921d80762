//! `surftopo isomorphic`: whether two triangulated closed surfaces are isomorphic.

use crate::args::JsonArg;
use crate::failure::invalid;
use serde::Serialize;
use std::path::PathBuf;
use std::process::ExitCode;
use surftopo_census::{Triangulation, is_chiral};

/// The arguments of `isomorphic`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The first mesh (a closed triangulated surface, orientable or not; positions are ignored).
    pub a: PathBuf,
    /// The second mesh.
    pub b: PathBuf,
    #[command(flatten)]
    pub json: JsonArg,
}

/// What `--json` prints.
#[derive(Serialize)]
struct Report {
    isomorphic: bool,
    vertices: [usize; 2],
    faces: [usize; 2],
    euler_characteristic: [i64; 2],
    orientable: [bool; 2],
    chiral: [Option<bool>; 2],
}

/// Reads a mesh as a face list on its used vertices (renumbered in order of index).
fn read(path: &std::path::Path) -> anyhow::Result<Triangulation> {
    let (soup, _) = crate::input::read_soup(path, false)?;
    let triangles = crate::input::triangles(path, &soup)?;
    let mut index = vec![u32::MAX; soup.vertex_count()];
    let mut next = 0u32;
    let mut used: Vec<u32> = triangles.iter().flatten().copied().collect();
    used.sort_unstable();
    used.dedup();
    for v in used {
        index[v as usize] = next;
        next += 1;
    }
    let faces: Vec<[u32; 3]> = triangles
        .iter()
        .map(|f| f.map(|v| index[v as usize]))
        .collect();
    let original: Vec<u32> = {
        let mut o = vec![0; next as usize];
        for (v, &i) in index.iter().enumerate() {
            if i != u32::MAX {
                o[i as usize] = v as u32;
            }
        }
        o
    };
    Triangulation::new(faces).map_err(|e| {
        invalid(format!(
            "{}: {}",
            crate::input::name(path),
            renumbered_message(&e, &original)
        ))
    })
}

/// The error's message with vertex numbers back in the file's numbering.
fn renumbered_message(error: &surftopo_census::CensusError, original: &[u32]) -> String {
    use surftopo_census::CensusError as E;
    let o = |v: u32| original.get(v as usize).copied().unwrap_or(v);
    match error.clone() {
        E::DegenerateFace { face, vertex } => E::DegenerateFace {
            face,
            vertex: o(vertex),
        },
        E::EdgeFaceCount { edge, faces, face } => E::EdgeFaceCount {
            edge: edge.map(o),
            faces,
            face,
        },
        E::PinchedVertex { vertex, cycles } => E::PinchedVertex {
            vertex: o(vertex),
            cycles,
        },
        E::Disconnected { vertex } => E::Disconnected { vertex: o(vertex) },
        other => other,
    }
    .to_string()
}

/// Reads both meshes and decides whether they are isomorphic (canonical forms).
pub fn decide(
    a: &std::path::Path,
    b: &std::path::Path,
) -> anyhow::Result<(bool, Triangulation, Triangulation)> {
    let a = read(a)?;
    let b = read(b)?;
    let isomorphic = crate::progress::step("comparing canonical forms", || {
        a.is_orientable() == b.is_orientable() && surftopo_census::isomorphic(&a, &b)
    });
    Ok((isomorphic, a, b))
}

/// Runs `isomorphic`: exit 0 isomorphic, 1 not.
pub fn run(args: &Args) -> anyhow::Result<ExitCode> {
    let (isomorphic, a, b) = decide(&args.a, &args.b)?;
    if args.json.json {
        crate::output::print_json(&Report {
            isomorphic,
            vertices: [a.vertex_count(), b.vertex_count()],
            faces: [a.face_count(), b.face_count()],
            euler_characteristic: [a.euler_characteristic(), b.euler_characteristic()],
            orientable: [a.is_orientable(), b.is_orientable()],
            chiral: [is_chiral(&a), is_chiral(&b)],
        })?;
    } else {
        crate::output::emit(if isomorphic {
            "isomorphic\n"
        } else {
            "not isomorphic\n"
        })?;
    }
    Ok(ExitCode::from(if isomorphic { 0 } else { 1 }))
}
