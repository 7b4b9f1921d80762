//! surftopo-irreducible: irreducible triangulations of compact surfaces by edge contractions.
//!
//! Paper: S. Ramaswami and M. Siqueira, "A fast algorithm for computing irreducible
//! triangulations of closed surfaces in E^d", preprint (Rutgers University, Camden, and
//! Universidade Federal do Rio Grande do Norte; no DOI or arXiv identifier could be verified).
//! Schipper's algorithm: H. Schipper, "Generating triangulations of 2-manifolds", in Computational
//! Geometry: Methods, Algorithms and Applications, LNCS 553, Springer, 1991, pp. 237–248,
//! doi:10.1007/3-540-54891-2_18.
//!
//! A triangulation is *irreducible* when
//! every edge fails the link condition (Section 2); the only irreducible triangulation of the sphere
//! is the tetrahedron boundary T4, the torus has 21 (7 to 10 vertices), and an irreducible
//! triangulation of genus g > 0 has at most 26g − 4 vertices (Theorem 4).
//!
//! Three algorithms, each in its own module, all reachable through [`reduce`]:
//! - [`ramaswami_siqueira`] — the paper's algorithm (Section 4, Algorithms 4.1–4.7): O(g² + gn) time,
//!   linear for genus 0, and no edge is ever tested twice against the link condition;
//! - [`schipper`] — Schipper's algorithm as Section 3 describes it (per-vertex link dictionaries, a
//!   lowest-degree vertex first);
//! - [`brute_force`] — the randomised brute force of Section 5 (seeded shuffle, passes until a pass
//!   contracts nothing).
//!
//! Each returns a [`Reduction`]: the irreducible triangulation (surviving vertices keep their input
//! ids; removed elements are tombstones), the contraction history — the stack S of Algorithm 4.5,
//! whose records [`SurfaceMesh::split_vertex`] replays exactly in reverse order — and the paper's
//! [`Counters`] (link-condition tests ℓ, edges tested more than once ε, contractions, seconds).
//! [`is_irreducible`] is an independent check of the result.
//!
//! [`reduce`] takes a closed, connected, orientable *simplicial* surface (a [`SurfaceMesh`]), as
//! the paper does; [`reduce_surface`] takes any compact surface (boundary loops, non-orientable
//! components, several pieces) as its [`ClosedCover`] and runs the same algorithms on it with Dey,
//! Edelsbrunner, Guha and Nekhayev's link condition for complexes with boundary; its result is
//! checked by [`is_irreducible_surface`], written from the triangles alone. Loops, multi-edges and
//! the two-triangle sphere are refused with an [`IrreducibleError`] naming the offending element,
//! before any work is done.

mod brute_force;
mod edge_lists;
mod error;
mod ramaswami_siqueira;
mod schipper;
mod tally;
mod validate;
mod verify;

pub use brute_force::brute_force;
pub use error::IrreducibleError;
pub use ramaswami_siqueira::ramaswami_siqueira;
pub use schipper::{LinkDictionaries, LinkTest, schipper, schipper_traced};
pub use validate::check_simplicial;
pub use verify::{is_irreducible, is_irreducible_surface};

pub use surftopo_mesh::{ClosedCover, Contraction, SurfaceMesh};

/// Which algorithm [`reduce`] runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Algorithm {
    /// Ramaswami–Siqueira (Section 4 of the paper): [`ramaswami_siqueira`].
    RamaswamiSiqueira,
    /// Schipper's algorithm (Section 3): [`schipper`].
    Schipper,
    /// The randomised brute force of Section 5, with the seed of its shuffle: [`brute_force`].
    BruteForce {
        /// Seed of the `ChaCha8Rng` that shuffles the edges.
        seed: u64,
    },
}

impl Algorithm {
    /// Every algorithm, the brute force with `seed`, in the order the CLI lists them.
    pub fn all(seed: u64) -> [Algorithm; 3] {
        [
            Algorithm::RamaswamiSiqueira,
            Algorithm::Schipper,
            Algorithm::BruteForce { seed },
        ]
    }

    /// The algorithm whose [`Self::name`] is `name`, the brute force with `seed`.
    pub fn from_name(name: &str, seed: u64) -> Option<Algorithm> {
        Self::all(seed).into_iter().find(|a| a.name() == name)
    }

    /// One line on the algorithm (the CLI's `--algorithm` help).
    pub fn summary(&self) -> &'static str {
        match self {
            Algorithm::RamaswamiSiqueira => {
                "Ramaswami–Siqueira (Section 4): O(g² + gn), linear for genus 0"
            }
            Algorithm::Schipper => "Schipper's algorithm (Section 3)",
            Algorithm::BruteForce { .. } => {
                "Randomised brute force (Section 5), seeded by `--seed`"
            }
        }
    }

    /// Short name: `rs`, `schipper` or `brute-force` (the CLI's `--algorithm` values).
    pub fn name(&self) -> &'static str {
        match self {
            Algorithm::RamaswamiSiqueira => "rs",
            Algorithm::Schipper => "schipper",
            Algorithm::BruteForce { .. } => "brute-force",
        }
    }
}

impl std::fmt::Display for Algorithm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// The paper's per-run figures (Section 5.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, serde::Serialize)]
pub struct Counters {
    /// ℓ: number of link-condition tests (RS does not count the degree-3 shortcut of Proposition 6,
    /// which is not a test; S and BF count every test they make).
    pub link_tests: u64,
    /// ε: number of edges (edge ids) tested more than once. Always 0 for RS.
    pub edges_tested_more_than_once: u64,
    /// Number of edge contractions of the surface (the length of the history, or half of it on a
    /// doubled non-orientable component, where each is made on both lifts).
    pub contractions: u64,
    /// Seconds spent in the algorithm alone (as the paper's `run()`): the input check is excluded,
    /// the algorithm's own set-up (attributes, dictionaries, shuffle) is included.
    pub seconds: f64,
}

impl Counters {
    fn of(tally: &tally::TestTally, contractions: u64, start: std::time::Instant) -> Self {
        Counters {
            link_tests: tally.link_tests,
            edges_tested_more_than_once: tally.repeated_edges,
            contractions,
            seconds: start.elapsed().as_secs_f64(),
        }
    }
}

/// The result of a reduction.
#[derive(Clone, Debug)]
pub struct Reduction {
    /// The irreducible triangulation, with tombstones: surviving vertices keep their input ids.
    pub mesh: SurfaceMesh,
    /// The stack S of Algorithm 4.5 in contraction order: record `i` is the `i`-th contraction.
    /// Replaying `mesh.split_vertex(&history[i])` for `i` from last to first gives back the input
    /// mesh exactly (same ids, same half-edges).
    pub history: Vec<Contraction>,
    /// ℓ, ε, contractions and seconds.
    pub counters: Counters,
}

impl Reduction {
    /// Runs `reduce` on a closed orientable `mesh` (each vertex its own class: [`Plain`]) once
    /// [`check_simplicial`] has passed; the counters are taken from the tally `reduce` returns,
    /// the seconds counted from after the check.
    pub(crate) fn of_plain_run(
        mut mesh: SurfaceMesh,
        reduce: impl FnOnce(
            &mut SurfaceMesh,
            &surftopo_mesh::Plain,
        ) -> (Vec<Contraction>, tally::TestTally, u64),
    ) -> Result<Self, IrreducibleError> {
        check_simplicial(&mesh)?;
        let start = std::time::Instant::now();
        let plain = surftopo_mesh::Plain {
            slots: mesh.vertex_slots(),
        };
        let (history, tally, contractions) = reduce(&mut mesh, &plain);
        let counters = Counters::of(&tally, contractions, start);
        Ok(Self {
            mesh,
            history,
            counters,
        })
    }
}

/// Computes an irreducible triangulation of `mesh` with the chosen algorithm.
///
/// # Errors
/// [`IrreducibleError`] if the input is not simplicial (see [`check_simplicial`]); nothing is done
/// then.
pub fn reduce(mesh: SurfaceMesh, algorithm: Algorithm) -> Result<Reduction, IrreducibleError> {
    match algorithm {
        Algorithm::RamaswamiSiqueira => ramaswami_siqueira(mesh),
        Algorithm::Schipper => schipper(mesh),
        Algorithm::BruteForce { seed } => brute_force(mesh, seed),
    }
}

/// The result of [`reduce_surface`].
#[derive(Clone, Debug)]
pub struct SurfaceReduction {
    /// The irreducible triangulation, as its cover with tombstones: surviving vertices keep
    /// their classes (the input's vertex ids); [`ClosedCover::surface_triangles`] lists it.
    pub cover: ClosedCover,
    /// The contractions of the cover's mesh in order (both lifts of each contraction of a
    /// doubled component, one after the other); replaying `split_vertex` from last to first
    /// gives back the input cover.
    pub history: Vec<Contraction>,
    /// ℓ, ε, contractions (of the surface) and seconds.
    pub counters: Counters,
}

/// An irreducible triangulation of any compact surface: closed or with boundary, orientable or
/// not, in one piece or several (each reduced on its own), with the chosen algorithm.
///
/// What the paper covers and what is ours: the paper treats closed orientable surfaces (its DCEL
/// is orientable; its conclusion states that the algorithm extends to non-orientable ones with
/// the same bounds in the Euler genus h, and names surfaces with boundary as the next step). Here
/// every algorithm runs unchanged on the surface's [`ClosedCover`]: its vertices are the cover's
/// vertex classes, each contraction is made on every lift, and the link condition is the one of
/// Dey, Edelsbrunner, Guha and Nekhayev for complexes with boundary, with the apexes closing the
/// boundary loops counted as one vertex ω that is never processed nor contracted (so RS and S
/// treat ω as a vertex of degree ∞ that is always trapped; RS's decision 9 finds the critical
/// cycles through ω from the lte side). A component is irreducible when no edge satisfies that
/// condition: a closed surface as in the paper; a disk reduces to one triangle.
///
/// # Errors
/// [`IrreducibleError`] if the cover's mesh is not simplicial (nothing is done then; a cover
/// built from a soup always is).
pub fn reduce_surface(
    mut cover: ClosedCover,
    algorithm: Algorithm,
) -> Result<SurfaceReduction, IrreducibleError> {
    if cover.is_plain() {
        let reduction = reduce(cover.mesh, algorithm)?;
        return Ok(SurfaceReduction {
            cover: ClosedCover::plain(reduction.mesh),
            history: reduction.history,
            counters: reduction.counters,
        });
    }
    check_simplicial(&cover.mesh)?;
    let start = std::time::Instant::now();
    let (mesh, sheets) = (&mut cover.mesh, &cover.sheets);
    let (history, tally, contractions) = match algorithm {
        Algorithm::RamaswamiSiqueira => ramaswami_siqueira::run(mesh, sheets),
        Algorithm::Schipper => schipper::run_lifted(mesh, sheets, |_, _, _| {}),
        Algorithm::BruteForce { seed } => brute_force::run(mesh, sheets, seed),
    };
    let counters = Counters::of(&tally, contractions, start);
    Ok(SurfaceReduction {
        cover,
        history,
        counters,
    })
}
