//! `surftopo generate`: every surface generator (closed, with boundary, non-orientable, in
//! pieces), with optional subdivision, simplification, random flips, random vertex splits, holes,
//! copies and a random face order, applied in that order.

use crate::output::OutputKind;
use clap::Subcommand;
use std::path::PathBuf;
use surftopo_intrinsic::geometry::Scalar as _;
use surftopo_intrinsic::{self as intrinsic, IntrinsicTriangulation};
use surftopo_mesh::generators;
use surftopo_mesh::{CoveredSurface, Surface};

/// The arguments of `generate`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The surface.
    #[command(subcommand)]
    pub kind: Kind,
    #[command(flatten)]
    pub modifiers: Modifiers,
}

/// The surface to generate.
#[derive(Subcommand, Debug, Clone)]
pub enum Kind {
    /// The boundary of a tetrahedron (4 vertices, genus 0).
    Tetrahedron,
    /// An icosahedron refined by 1-to-4 splits, on the unit sphere (20 * 4^s triangles).
    Icosphere {
        /// Number of 1-to-4 refinements.
        #[arg(long, default_value_t = 3)]
        subdivisions: u32,
    },
    /// A torus of revolution as an m x n grid (2 m n triangles, genus 1).
    Torus {
        /// Grid size around the axis (at least 3).
        #[arg(long, default_value_t = 24)]
        m: u32,
        /// Grid size around the tube (at least 3).
        #[arg(long, default_value_t = 12)]
        n: u32,
    },
    /// A closed surface of any genus: a brick with `genus` through-holes in a grid.
    Genus {
        /// The genus.
        #[arg(long, default_value_t = 2)]
        genus: u32,
        /// Resolution: lattice steps per pit side, at least 1 (triangles grow with its square).
        #[arg(long, default_value_t = 2)]
        size: u32,
    },
    /// The papers' brick with square pits: cavities (genus unchanged) and through-holes (genus +1
    /// each), refined to about the requested number of triangles (irreducible-triangulations paper,
    /// Section 5.1, Figure 14 and Tables 3-5).
    CavityBox {
        /// Pits with a floor.
        #[arg(long, default_value_t = 3844)]
        cavities: u32,
        /// Pits through the brick.
        #[arg(long, default_value_t = 0)]
        holes: u32,
        /// Target number of triangles (the nearest reachable size is used).
        #[arg(long, default_value_t = 100_000)]
        triangles: u64,
    },
    /// The flat torus T_x of the intrinsic-Delaunay paper (Section 9): one vertex, two triangles
    /// (0,0), (1,0), (x,2); refined m x m when m > 1. Written as portalgon JSON (`-o OUT.json`),
    /// every triangle by its exact corners (with --flips, by lengths).
    FlatTorus {
        /// The parameter x: an integer, a decimal or a fraction p/q, read exactly (the flip
        /// algorithm needs x - 1 flips for integer x).
        #[arg(long)]
        x: intrinsic::geometry::Rational,
        /// Refinement: the same torus as an m x m grid of parallelograms.
        #[arg(long, default_value_t = 1)]
        m: u32,
    },
    /// A torus of revolution whose grid diagonals wind `shear` times around the tube (many flips).
    ShearedTorus {
        /// Grid size around the axis.
        #[arg(long, default_value_t = 64)]
        m: u32,
        /// Grid size around the tube.
        #[arg(long, default_value_t = 16)]
        n: u32,
        /// Windings of the diagonals.
        #[arg(long, default_value_t = 4)]
        shear: u32,
    },
    /// The unit square as an n x n grid: a disk (2 n^2 triangles).
    Disk {
        /// Grid size (at least 1).
        #[arg(long, default_value_t = 8)]
        n: u32,
    },
    /// An open cylinder: an annulus as an m x n grid (2 m n triangles).
    Annulus {
        /// Grid size around (at least 3).
        #[arg(long, default_value_t = 24)]
        m: u32,
        /// Grid size along (at least 1).
        #[arg(long, default_value_t = 4)]
        n: u32,
    },
    /// A Möbius band as an m x n grid glued with a half twist (2 m n triangles).
    MobiusBand {
        /// Grid size along the core circle (at least 5).
        #[arg(long, default_value_t = 24)]
        m: u32,
        /// Grid size across (at least 1).
        #[arg(long, default_value_t = 4)]
        n: u32,
    },
    /// The 6-vertex projective plane (10 triangles; refine it with --subdivide, --splits).
    ProjectivePlane,
    /// A Klein bottle as an m x n grid on the figure-8 immersion (2 m n triangles).
    KleinBottle {
        /// Grid size along the tube (at least 3).
        #[arg(long, default_value_t = 24)]
        m: u32,
        /// Grid size around the tube (at least 3).
        #[arg(long, default_value_t = 12)]
        n: u32,
    },
    /// The non-orientable surface N_k: a connected sum of k 6-vertex projective planes
    /// (3k + 3 vertices, 8k + 2 triangles).
    NonOrientable {
        /// The number k of crosscaps (at least 1).
        #[arg(long, default_value_t = 3)]
        crosscaps: u32,
    },
    /// Any mesh file, for the modifiers (e.g. holes cut into a closed mesh).
    Mesh {
        /// The mesh (.obj, .off, .ply, .stl, optionally .gz; any triangulated surface).
        #[arg(long)]
        input: PathBuf,
    },
    /// Random intrinsic flips of any input (an isometric re-triangulation), as portalgon JSON.
    IntrinsicFlips {
        /// A mesh or portalgon JSON file.
        #[arg(long)]
        input: PathBuf,
        /// Number of flips (at most 100 per edge, or 1000000).
        #[arg(long, default_value_t = 1000)]
        count: u64,
    },
}

/// What a generator makes: a surface with positions, or an intrinsic triangulation (lengths only).
pub enum Generated {
    /// Topology and 3D positions.
    Surface(CoveredSurface),
    /// Topology and edge lengths.
    Intrinsic(IntrinsicTriangulation),
}

/// Options common to every generator.
#[derive(clap::Args, Debug, Clone)]
pub struct Modifiers {
    /// Output mesh file (.obj, .off, .ply, .stl, optionally .gz), `-` for standard output (with
    /// --format); portalgon JSON (.json, a file) for flat-torus and intrinsic-flips.
    #[arg(short, long, global = true)]
    pub output: Option<PathBuf>,
    /// The output mesh's format: obj, off, ply or stl, optionally followed by .gz (e.g. ply.gz).
    /// Needed when the output is `-` (standard output) or its name has no mesh extension.
    #[arg(long, value_name = "FORMAT", global = true, value_parser = crate::output::MeshFormat::parse)]
    pub format: Option<crate::output::MeshFormat>,
    /// Levels of 1-to-4 midpoint subdivision applied after generation.
    #[arg(long, default_value_t = 0, global = true)]
    pub subdivide: u32,
    /// Simplify to at most this many faces by random link-condition contractions (topology kept),
    /// applied after subdivision.
    #[arg(long, global = true)]
    pub simplify: Option<usize>,
    /// Random simplicial edge flips applied after simplification (irregular connectivity); at
    /// most 100 per edge, or 1000000.
    #[arg(long, default_value_t = 0, global = true)]
    pub flips: usize,
    /// Random vertex splits applied after the flips.
    #[arg(long, default_value_t = 0, global = true)]
    pub splits: usize,
    /// Holes cut after the splits: each removes the faces around a random vertex at least three
    /// edges from the boundary and from the other holes (a new boundary loop each; genus g with b
    /// boundary loops from a genus-g surface). Refused when fewer fit.
    #[arg(long, default_value_t = 0, global = true)]
    pub cut_holes: usize,
    /// Copies side by side (a file of several pieces), made after the holes.
    #[arg(long, default_value_t = 1, global = true)]
    pub copies: u32,
    /// List the triangles in a random order, last (the same surface; measures how algorithms
    /// depend on the face order of a file).
    #[arg(long, global = true)]
    pub shuffle_faces: bool,
    /// Seed of the random simplification, flips, splits, holes and face order.
    #[arg(long, default_value_t = 1, global = true)]
    pub seed: u64,
}

/// Refuses the modifiers that need a surface mesh for a generator of intrinsic triangulations.
fn check_intrinsic_modifiers(modifiers: &Modifiers) -> anyhow::Result<()> {
    if modifiers.subdivide > 0
        || modifiers.splits > 0
        || modifiers.cut_holes > 0
        || modifiers.copies != 1
        || modifiers.simplify.is_some()
        || modifiers.shuffle_faces
    {
        return Err(crate::failure::invalid(
            "--subdivide, --simplify, --splits, --cut-holes, --copies and --shuffle-faces need a surface mesh; this generator makes an intrinsic triangulation",
        ));
    }
    Ok(())
}

/// `flat-torus` without `--flips`: T_x written by its exact corners (any rational x, however
/// large: no double-precision triangulation is built).
fn write_exact_flat_torus(
    x: &intrinsic::geometry::Rational,
    m: u32,
    modifiers: &Modifiers,
    output: &std::path::Path,
) -> anyhow::Result<()> {
    check_size(&format!("flat-torus --m {m}"), 2 * u64::from(m).pow(2))?;
    check_intrinsic_modifiers(modifiers)?;
    let exact = intrinsic::generators::flat_torus_portalgon(x, m)
        .map_err(|e| crate::failure::invalid(format!("flat-torus: {e}")))?;
    crate::output::write_file(output, |w| {
        Ok(intrinsic::PortalgonDoc::from_portalgon(&exact).write(w, false)?)
    })?;
    let (faces, edges) = (exact.polygon_count(), exact.side_count() / 2);
    let vertices = exact.vertex_classes().1;
    let genus = (2 + edges as i64 - vertices as i64 - faces as i64) / 2;
    crate::output::emit(&format!(
        "wrote {} (intrinsic, exact corners): {vertices} vertices, {edges} edges, {faces} faces, genus {genus}\n",
        crate::failure::shown(output),
    ))?;
    Ok(())
}

impl Kind {
    /// Whether the kind makes an intrinsic triangulation (written as portalgon JSON) rather than
    /// a surface with positions.
    pub fn is_intrinsic(&self) -> bool {
        matches!(self, Kind::FlatTorus { .. } | Kind::IntrinsicFlips { .. })
    }
}

/// Generates the surface or intrinsic triangulation of `kind` (without modifiers).
pub fn generate_any(kind: &Kind, seed: u64) -> anyhow::Result<Generated> {
    let invalid = |e: &dyn std::fmt::Display| crate::failure::invalid(format!("{e}"));
    Ok(match kind {
        Kind::FlatTorus { x, m } => {
            check_size(&format!("flat-torus --m {m}"), 2 * u64::from(*m).pow(2))?;
            Generated::Intrinsic(
                intrinsic::generators::flat_torus(x.to_f64(), *m)
                    .map_err(|e| invalid(&format!("flat-torus: {e}")))?,
            )
        }
        Kind::ShearedTorus { m, n, shear } => {
            if *m < 3 || *n < 3 {
                return Err(crate::failure::invalid(
                    "sheared-torus: m and n must be at least 3",
                ));
            }
            check_size(
                &format!("sheared-torus --m {m} --n {n}"),
                2 * u64::from(*m) * u64::from(*n),
            )?;
            Generated::Surface(generators::sheared_torus(*m, *n, *shear).into())
        }
        Kind::IntrinsicFlips { input, count } => {
            let mut tri = crate::commands::delaunay::load_intrinsic(input, false)?;
            let name = crate::failure::shown(input);
            // The lengths read must make valid triangles (no zero-area face), as every reader of
            // the written file checks: a file surftopo writes, surftopo reads.
            tri.validate()
                .map_err(|e| crate::failure::invalid(format!("{name}: {e}")))?;
            check_flips("intrinsic-flips --count", *count, tri.mesh().edge_count())?;
            intrinsic::generators::random_flips(&mut tri, *count, seed);
            // The flips keep every triangle valid as rounded; checked again before writing.
            tri.validate().map_err(|e| {
                crate::failure::numerical(format!(
                    "{name}: after the random flips: {e}; nothing written"
                ))
            })?;
            Generated::Intrinsic(tri)
        }
        other => Generated::Surface(generate(other)?),
    })
}

/// Generates the surface of `kind` (without modifiers); intrinsic kinds are refused.
pub fn generate(kind: &Kind) -> anyhow::Result<CoveredSurface> {
    let grid = |name: &str, m: u32, n: u32, least: (u32, u32)| {
        if m < least.0 || n < least.1 {
            return Err(crate::failure::invalid(format!(
                "{name}: --m must be at least {} and --n at least {}",
                least.0, least.1
            )));
        }
        check_size(
            &format!("{name} --m {m} --n {n}"),
            2 * u64::from(m) * u64::from(n),
        )
    };
    Ok(match kind {
        Kind::Disk { n } => {
            grid("disk", *n, *n, (1, 1))?;
            generators::disk(*n)
        }
        Kind::Annulus { m, n } => {
            grid("annulus", *m, *n, (3, 1))?;
            generators::annulus(*m, *n)
        }
        Kind::MobiusBand { m, n } => {
            grid("mobius-band", *m, *n, (5, 1))?;
            generators::mobius_band(*m, *n)
        }
        Kind::ProjectivePlane => generators::projective_plane(),
        Kind::KleinBottle { m, n } => {
            grid("klein-bottle", *m, *n, (3, 3))?;
            generators::klein_bottle(*m, *n)
        }
        Kind::NonOrientable { crosscaps } => {
            if *crosscaps == 0 {
                return Err(crate::failure::invalid(
                    "non-orientable: --crosscaps must be at least 1",
                ));
            }
            check_size(
                &format!("non-orientable --crosscaps {crosscaps}"),
                8 * u64::from(*crosscaps) + 2,
            )?;
            generators::crosscaps(*crosscaps)
        }
        Kind::Mesh { input } => crate::input::read_covered(input, false)?.surface,
        other => generate_closed(other)?.into(),
    })
}

/// Generates the closed orientable surface of `kind` (without modifiers).
fn generate_closed(kind: &Kind) -> anyhow::Result<Surface> {
    Ok(match *kind {
        Kind::FlatTorus { .. } | Kind::ShearedTorus { .. } | Kind::IntrinsicFlips { .. } => {
            return match generate_any(kind, 0)? {
                Generated::Surface(surface) => surface
                    .into_plain()
                    .ok_or_else(|| crate::failure::invalid("not a closed orientable surface")),
                Generated::Intrinsic(_) => Err(crate::failure::invalid(
                    "an intrinsic triangulation has no positions",
                )),
            };
        }
        Kind::Tetrahedron => generators::tetrahedron(),
        Kind::Icosphere { subdivisions } => {
            if subdivisions > 10 {
                return Err(crate::failure::invalid(
                    "icosphere: at most 10 subdivisions (21M triangles)",
                ));
            }
            check_size(
                &format!("icosphere --subdivisions {subdivisions}"),
                20 * 4u64.pow(subdivisions),
            )?;
            generators::icosphere(subdivisions)
        }
        Kind::Torus { m, n } => {
            if m < 3 || n < 3 {
                return Err(crate::failure::invalid("torus: m and n must be at least 3"));
            }
            check_size(
                &format!("torus --m {m} --n {n}"),
                2 * u64::from(m) * u64::from(n),
            )?;
            generators::torus(m, n)
        }
        Kind::Genus { genus, size } => {
            if size == 0 {
                return Err(crate::failure::invalid("genus: --size must be at least 1"));
            }
            // F = 4 W^2 + 16 W s + 12 g s^2 with W = (2k + 1) s, k = ceil(sqrt(g)) (see genus_surface).
            let (g, s) = (u64::from(genus), u64::from(size));
            let k = g.isqrt() + u64::from(g.isqrt().pow(2) < g);
            let w = (2 * k + 1) * s;
            check_size(
                &format!("genus --genus {genus} --size {size}"),
                4 * w * w + 16 * w * s + 12 * g * s * s,
            )?;
            generators::genus_surface(genus, size)
        }
        Kind::CavityBox {
            cavities,
            holes,
            triangles,
        } => {
            let source =
                format!("cavity-box --cavities {cavities} --holes {holes} --triangles {triangles}");
            check_size(&source, triangles)?;
            check_size(
                &source,
                generators::CavityBox::fit(cavities, holes, triangles).triangle_count(),
            )?;
            generators::cavity_box(cavities, holes, triangles)
        }
        _ => unreachable!("the other kinds are generated by `generate`"),
    })
}

/// Refuses a surface of `triangles` triangles asked for by `source` (the options) beyond
/// `--max-elements`, before allocating it.
fn check_size(source: &str, triangles: u64) -> anyhow::Result<()> {
    crate::limits::check_elements(source, triangles, "triangles")
}

/// The most random flips per edge `--flips` and `intrinsic-flips --count` accept beyond
/// [`MIN_FLIP_CAP`]: far more than random flips need to mix, and a bound on the time they take.
pub const MAX_FLIPS_PER_EDGE: u64 = 100;

/// Flips always allowed, whatever the mesh size (a second's work).
pub const MIN_FLIP_CAP: u64 = 1_000_000;

/// Refuses `count` random flips of a mesh with `edges` edges beyond
/// `max(MAX_FLIPS_PER_EDGE · edges, MIN_FLIP_CAP)` (the flip loops would otherwise run for days).
fn check_flips(option: &str, count: u64, edges: usize) -> anyhow::Result<()> {
    let max = (MAX_FLIPS_PER_EDGE * edges as u64).max(MIN_FLIP_CAP);
    if count > max {
        return Err(crate::failure::invalid(format!(
            "{option} {count}: at most {MAX_FLIPS_PER_EDGE} flips per edge (or {MIN_FLIP_CAP}) are \
             made: {max} for this mesh's {edges} edges"
        )));
    }
    Ok(())
}

/// Applies the modifiers to a generated surface: subdivision, simplification, flips, splits,
/// holes, copies, face order.
pub fn modify(
    mut surface: CoveredSurface,
    modifiers: &Modifiers,
) -> anyhow::Result<CoveredSurface> {
    let faces = |s: &CoveredSurface| s.cover.surface_faces().count() as u64;
    if modifiers.subdivide > 0 {
        let grown = faces(&surface).saturating_mul(4u64.saturating_pow(modifiers.subdivide));
        check_size(&format!("--subdivide {}", modifiers.subdivide), grown)?;
        surface = generators::subdivide_midpoint_covered(&surface, modifiers.subdivide);
    }
    if let Some(target) = modifiers.simplify {
        surface = generators::simplify_covered(&surface, target, modifiers.seed);
    }
    if modifiers.flips > 0 {
        let edges = (faces(&surface) * 3).div_ceil(2) as usize;
        check_flips("--flips", modifiers.flips as u64, edges)?;
        surface = generators::random_flips_covered(&surface, modifiers.flips, modifiers.seed);
    }
    if modifiers.splits > 0 {
        check_size(
            &format!("--splits {}", modifiers.splits),
            faces(&surface) + 2 * modifiers.splits as u64,
        )?;
        let before = surface.positions.len();
        surface =
            generators::random_vertex_splits_covered(&surface, modifiers.splits, modifiers.seed);
        // Each split adds one vertex (a boundary vertex's split adds one face only, so faces
        // do not count them); a split with no non-flat placement is left out.
        let made = surface.positions.len().saturating_sub(before);
        if made < modifiers.splits {
            stderr_println!(
                "note: --splits {}: {made} made, the others left out (no placement of the new \
                 vertex keeps every face around it from being flat)",
                modifiers.splits
            );
        }
    }
    if modifiers.cut_holes > 0 {
        let (holed, cut) = generators::cut_holes(&surface, modifiers.cut_holes, modifiers.seed);
        if cut < modifiers.cut_holes {
            return Err(crate::failure::invalid(format!(
                "--cut-holes {}: only {cut} holes fit (each needs a vertex three edges from the \
                 boundary and from the other holes): refine the surface first (--subdivide)",
                modifiers.cut_holes
            )));
        }
        surface = holed;
    }
    if modifiers.copies != 1 {
        if modifiers.copies == 0 {
            return Err(crate::failure::invalid("--copies must be at least 1"));
        }
        check_size(
            &format!("--copies {}", modifiers.copies),
            faces(&surface).saturating_mul(u64::from(modifiers.copies)),
        )?;
        surface = generators::copies(&surface, modifiers.copies);
    }
    if modifiers.shuffle_faces {
        surface = generators::shuffle_faces_covered(&surface, modifiers.seed);
    }
    Ok(surface)
}

/// Runs `generate`.
pub fn run(args: &Args) -> anyhow::Result<()> {
    let (kind, modifiers) = (&args.kind, &args.modifiers);
    let output = modifiers
        .output
        .as_ref()
        .ok_or_else(|| crate::failure::invalid("generate: an output file is needed (-o OUT)"))?;
    let holds = match (kind.is_intrinsic(), modifiers.format) {
        (true, Some(_)) => {
            return Err(crate::failure::invalid(
                "--format: this generator writes portalgon JSON, not a mesh",
            ));
        }
        (true, None) => OutputKind::Portalgon,
        (false, format) => crate::output::mesh_kind(format),
    };
    crate::output::check_outputs(&[("-o", output, holds)])?;
    if let (Kind::FlatTorus { x, m }, 0) = (kind, modifiers.flips) {
        return write_exact_flat_torus(x, *m, modifiers, output);
    }
    let generated = crate::progress::step("generating", || generate_any(kind, modifiers.seed))?;
    let (mesh, what) = match generated {
        Generated::Surface(surface) => {
            let surface =
                crate::progress::step("applying the modifiers", || modify(surface, modifiers))?;
            let (positions, triangles) = surface.to_triangles();
            let soup = surftopo_io::PolygonSoup::from_triangles(positions, &triangles);
            crate::output::write_soup_as(output, &soup, modifiers.format)?;
            let counts = crate::commands::irreducible::Counts::of(&triangles);
            let genus = counts
                .genus
                .map_or(String::new(), |g| format!(", genus {g}"));
            return crate::output::emit(&format!(
                "wrote {}: {} vertices, {} edges, {} faces{genus} ({})\n",
                crate::output::name(output),
                counts.vertices,
                counts.edges,
                counts.faces,
                counts.names()
            ));
        }
        Generated::Intrinsic(mut tri) => {
            check_intrinsic_modifiers(modifiers)?;
            if modifiers.flips > 0 {
                check_flips("--flips", modifiers.flips as u64, tri.mesh().edge_count())?;
                intrinsic::generators::random_flips(
                    &mut tri,
                    modifiers.flips as u64,
                    modifiers.seed,
                );
            }
            crate::output::write_file(output, |w| {
                Ok(tri.write_json(w, intrinsic::TriangleStyle::Lengths)?)
            })?;
            (tri.into_parts().0, " (intrinsic)")
        }
    };
    crate::output::emit(&format!(
        "wrote {}{what}: {} vertices, {} edges, {} faces, genus {}\n",
        crate::output::name(output),
        mesh.vertex_count(),
        mesh.edge_count(),
        mesh.face_count(),
        mesh.genus()
    ))?;
    Ok(())
}
