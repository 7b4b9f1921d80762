//! The inputs, built as the papers made them.
//!
//! - Bricks ([`surftopo_mesh::generators::CavityBox::fit`]): the paper's brick with 3,844
//!   cavities (irreducible-triangulations paper, Figure 14), some of them replaced by holes.
//! - Simplified inputs: irreducible paper, Section 5.2: "triangulation B_i was obtained from
//!   triangulation B_{i-1} by a simplification process that approximately halved the number of
//!   triangles" (C_i likewise); quadrangulation paper, Section 4: "A2-A5 (resp. B2-B5) were
//!   generated from triangulation A1 (resp. B1)". The papers' processes (theirs unnamed, Graphite)
//!   are not available: we use [`surftopo_mesh::generators::simplify`] (random link-condition
//!   contractions, seed [`SIMPLIFY_SEED`]) down to the paper's triangle count. Decision: the
//!   quadrangulation hierarchy is simplified step by step (A2 from A1, A3 from A2, ...), as a
//!   "hierarchy" of the same surface; the irreducible chain is the paper's B_i from B_{i-1}.
//! - Shared meshes that stand in for the papers' models ([`STAND_INS`]), named as stand-ins.
//!
//! At the reduced scales (`--quick`, `--tiny`) the bricks have fewer cavities and holes (the
//! genus scaled alike) and every triangle count is divided by the same factor.

use std::path::PathBuf;

use surftopo_mesh::Surface;
use surftopo_mesh::generators::simplify;

use super::cache::{Cache, Recipe};
use surftopo_testkit::SharedMesh;

/// Seed of every simplification.
pub const SIMPLIFY_SEED: u64 = 1;

/// The papers' models and the shared mesh standing in for each (closest genus and size available;
/// Casting and Socket are the papers' own models).
pub const STAND_INS: [(&str, &str); 11] = [
    ("Armadillo", "armadillo_43k.obj.gz"),
    ("Botijo", "botijo_41k.off.gz"),
    ("Casting", "casting.off.gz"),
    ("Eros", "igea.ply.gz"),
    ("Fertility", "fertility_23k.off.gz"),
    ("Filigree", "thingi129110_sf.obj.gz"),
    ("Gargoyle", "gargoyle_50k.off.gz"),
    ("Hand", "hand1_50k.off.gz"),
    ("Happy Buddha", "boot.obj.gz"),
    ("Iphigenia", "pegasus.off.gz"),
    ("Socket", "socket.off.gz"),
];

/// How big the run is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum Scale {
    /// The papers' sizes.
    Full,
    /// Pits / 16, triangles / 32, stand-ins up to 100,000 triangles.
    Quick,
    /// Pits / 64, triangles / 512, a few inputs per group, stand-ins up to 11,000 triangles
    /// (for the test in CI, in debug).
    Tiny,
}

impl Scale {
    /// Divisor of the number of pits (cavities and holes).
    pub fn pit_divisor(self) -> u32 {
        match self {
            Scale::Full => 1,
            Scale::Quick => 16,
            Scale::Tiny => 64,
        }
    }

    /// Divisor of the triangle counts.
    pub fn triangle_divisor(self) -> u64 {
        match self {
            Scale::Full => 1,
            Scale::Quick => 32,
            Scale::Tiny => 512,
        }
    }

    /// Largest stand-in mesh run.
    pub fn max_stand_in_faces(self) -> usize {
        match self {
            Scale::Full => usize::MAX,
            Scale::Quick => 100_000,
            Scale::Tiny => 11_000,
        }
    }

    /// How many inputs of each group are run (the first ones).
    pub fn per_group(self) -> usize {
        match self {
            Scale::Tiny => 2,
            _ => usize::MAX,
        }
    }

    /// A paper's pit count at this scale (at least 1).
    pub fn pits(self, paper: u32) -> u32 {
        (paper / self.pit_divisor()).max(1)
    }

    /// A paper's triangle count at this scale.
    pub fn triangles(self, paper: u64) -> u64 {
        (paper / self.triangle_divisor()).max(8)
    }
}

/// One input: its name (the paper's), how it was made, and the surface.
pub struct Input {
    /// The paper's name (`B3`, `A1`, or the model, e.g. `Botijo`).
    pub name: String,
    /// How it was made, for the reports (e.g. `brick 3844 cavities, 0 holes` or `simplified
    /// from B2` or `stand-in: botijo_41k.off.gz`).
    pub made: String,
    /// The surface.
    pub surface: Surface,
}

/// The recipe of a brick with `cavities` cavities and `holes` holes (paper counts, scaled) and
/// the triangle count nearest `triangles` (scaled), and its description.
pub fn brick(scale: Scale, cavities: u32, holes: u32, triangles: u64) -> (String, Recipe) {
    let (c, h) = if holes == 0 {
        (scale.pits(cavities), 0)
    } else {
        let total = scale.pits(cavities + holes);
        let h = scale.pits(holes).min(total);
        (total - h, h)
    };
    let t = scale.triangles(triangles);
    (
        format!("brick: {c} cavities, {h} holes, target {t} triangles"),
        Recipe::brick(c, h, t),
    )
}

/// A chain of inputs: the first is `first`, each next one the previous simplified to the next
/// paper triangle count (scaled). `names[i]` names the i-th; at most `scale.per_group()` of them.
/// Only the inputs that `runs` accepts are handed to `each`; the others are built (or read from
/// `cache`) only where a later one needs them.
pub fn chain(
    scale: Scale,
    cache: &Cache,
    runs: impl Fn(&str) -> bool,
    names: &[&str],
    triangles: &[u64],
    first: (String, Recipe),
    mut each: impl FnMut(Input),
) {
    let mut recipe = first.1.clone();
    let mut previous: Option<&str> = None;
    for (i, (name, &target)) in names.iter().zip(triangles).enumerate() {
        if i >= scale.per_group() {
            break;
        }
        let made = match previous {
            None => first.0.clone(),
            Some(prev_name) => {
                recipe = recipe.simplified(scale.triangles(target) as usize, SIMPLIFY_SEED);
                format!("simplified from {prev_name} (seed {SIMPLIFY_SEED})")
            }
        };
        previous = Some(name);
        if runs(name) {
            each(Input {
                name: name.to_string(),
                made,
                surface: cache.get(&recipe),
            });
        }
    }
}

/// A group made as the papers made it: the brick nearest the first size, each next input the
/// previous one simplified ([`chain`]); `each` gets the inputs that `runs` accepts.
pub fn brick_chain(
    scale: Scale,
    cache: &Cache,
    runs: impl Fn(&str) -> bool,
    sizes: &[(&str, u64)],
    (cavities, holes): (u32, u32),
    each: impl FnMut(Input),
) {
    let names: Vec<&str> = sizes.iter().map(|s| s.0).collect();
    let triangles: Vec<u64> = sizes.iter().map(|s| s.1).collect();
    let first = brick(scale, cavities, holes, triangles[0]);
    chain(scale, cache, runs, &names, &triangles, first, each);
}

/// The shared meshes folder: `SURFTOPO_MESHES` (relative to the workspace root), else
/// `../shared/meshes` beside the workspace.
pub fn meshes_dir(given: Option<PathBuf>) -> Option<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = given
        .or_else(|| std::env::var_os("SURFTOPO_MESHES").map(PathBuf::from))
        .unwrap_or_else(|| PathBuf::from("../shared/meshes"));
    let dir = if dir.is_relative() {
        root.join(dir)
    } else {
        dir
    };
    dir.join("manifest.json").is_file().then_some(dir)
}

/// The shared mesh named `file` in `dir`'s manifest, if listed.
pub fn shared_mesh(dir: &std::path::Path, file: &str) -> Option<SharedMesh> {
    let text = std::fs::read_to_string(dir.join("manifest.json")).ok()?;
    let manifest: serde_json::Value = serde_json::from_str(&text).ok()?;
    let entry = manifest["meshes"]
        .as_array()?
        .iter()
        .find(|m| m["file"] == file)?;
    let count = |k: &str| entry[k].as_u64().unwrap_or(0) as usize;
    Some(SharedMesh {
        file: file.to_string(),
        path: dir.join(file),
        vertices: count("V"),
        edges: count("E"),
        faces: count("F"),
        genus: entry["genus"].as_i64().unwrap_or(0),
        needs_weld: entry["passes_without_vertex_welding"] == false,
    })
}

/// The stand-ins for `models` (the papers' names and triangle counts) that exist in `dir` and fit
/// the scale, loaded; where the stand-in has more triangles than the paper's model, also the
/// stand-in simplified to the paper's count (named `MODEL (simplified)`): on a closed surface of
/// the same genus, F fixes V and E, so it has the paper's V, E, F and genus (Botijo, Fertility).
pub fn stand_ins(
    scale: Scale,
    dir: Option<&std::path::Path>,
    models: &[(&str, u64)],
    mut each: impl FnMut(Input),
) {
    let Some(dir) = dir else {
        eprintln!("no shared meshes (SURFTOPO_MESHES or --meshes): stand-ins skipped");
        return;
    };
    for &(model, paper_faces) in models {
        let Some((_, file)) = STAND_INS.iter().find(|(m, _)| *m == model) else {
            continue;
        };
        let Some(mesh) = shared_mesh(dir, file) else {
            eprintln!("{file}: not in the manifest, skipped");
            continue;
        };
        if mesh.faces > scale.max_stand_in_faces() {
            continue;
        }
        let surface = surftopo_testkit::load(&mesh);
        let simplified = (paper_faces < mesh.faces as u64)
            .then(|| simplify(&surface, paper_faces as usize, SIMPLIFY_SEED));
        each(Input {
            name: model.to_string(),
            made: format!("stand-in: {file}"),
            surface,
        });
        if let Some(surface) = simplified {
            each(Input {
                name: format!("{model} (simplified)"),
                made: format!("stand-in: {file} simplified to {paper_faces} triangles"),
                surface,
            });
        }
    }
}

/// An input as the reports list it: its group, its name, how it was made and its sizes.
#[derive(Clone, Debug, Default, serde::Serialize, serde::Deserialize)]
pub struct Described {
    /// The group (`first` for the stand-ins, else the paper's group letter).
    pub group: String,
    /// The paper's name.
    pub input: String,
    /// How it was made.
    pub made: String,
    /// Vertices.
    pub vertices: usize,
    /// Edges.
    pub edges: usize,
    /// Faces.
    pub faces: usize,
    /// Genus.
    pub genus: i64,
}

impl Described {
    /// The description of `input` in `group`.
    pub fn of(group: &str, input: &Input) -> Self {
        let mesh = &input.surface.mesh;
        Self {
            group: group.into(),
            input: input.name.clone(),
            made: input.made.clone(),
            vertices: mesh.vertex_count(),
            edges: mesh.edge_count(),
            faces: mesh.face_count(),
            genus: mesh.genus(),
        }
    }
}

/// Every input of one paper's experiment, in the paper's order: the stand-ins of its first table
/// (`models`: the paper's model names and triangle counts), then, for each brick group (`groups`:
/// the group's letter, cavities, holes), the chain of its rows in `sizes` (the paper's names and
/// triangle counts; a row belongs to the group its name starts with). `each` gets the group
/// ("first" for the stand-ins) and the input; `options` says the scale and which inputs are
/// wanted; the bricks and their simplifications come from `cache`.
pub fn paper_inputs(
    options: &super::Options,
    cache: &Cache,
    meshes: Option<&std::path::Path>,
    models: &[(&str, u64)],
    sizes: &[(&str, u64)],
    groups: &[(&str, u32, u32)],
    mut each: impl FnMut(&str, Input),
) {
    let scale = options.scale();
    let runs = |n: &str| options.runs_input(n);
    stand_ins(scale, meshes, models, |i| each("first", i));
    for &(group, cavities, holes) in groups {
        let rows: Vec<(&str, u64)> = sizes
            .iter()
            .copied()
            .filter(|s| s.0.starts_with(group))
            .collect();
        brick_chain(scale, cache, runs, &rows, (cavities, holes), |i| {
            each(group, i)
        });
    }
}
