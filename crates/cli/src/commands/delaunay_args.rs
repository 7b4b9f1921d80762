//! The arguments of `surftopo delaunay` (`--method`, `--exact` and the rest), shared by its two
//! runners: `delaunay.rs` (the intrinsic Delaunay triangulation) and `tufted.rs` (`--tufted`, and
//! meshes that are not manifolds); `isometric` takes `--method` and `--exact` too.

use crate::args::{JsonArg, WeldArg};
use crate::failure::invalid;
use std::path::PathBuf;
use surftopo_intrinsic::{DelaunayMethod, DelaunayRequest, RequestError};

/// The arguments of `delaunay`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// A mesh file, or a portalgon JSON file (`.json`, see crates/intrinsic/PORTALGON_FORMAT.md);
    /// `-` for standard input (JSON when it starts with `{`, else a mesh told by its content).
    pub input: PathBuf,
    /// The Delaunay triangulation, as portalgon JSON (.json). Optional: at least one output
    /// (this, --tessellation, --reduced, --laplacian, --mass) or --json is needed.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// The Delaunay tessellation (co-circular triangles merged), as portalgon JSON (.json): on
    /// a surface with boundary its boundary sides are unmatched, on a non-orientable one the
    /// gluings that reverse orientation are flagged (format version 2).
    #[arg(long)]
    pub tessellation: Option<PathBuf>,
    /// The cotan Laplacian (positive semidefinite: positive diagonal): Matrix Market (.mtx,
    /// symmetric storage), or `.npz` (scipy.sparse.load_npz reads it).
    #[arg(long)]
    pub laplacian: Option<PathBuf>,
    /// The lumped (barycentric) mass matrix: Matrix Market (.mtx, symmetric storage), `.npz`, or
    /// `.npy` (its diagonal as a vector).
    #[arg(long)]
    pub mass: Option<PathBuf>,
    /// Stop with an error after this many flips.
    #[arg(long)]
    pub max_flips: Option<u64>,
    /// Mollify degenerate input with this epsilon (relative to the mean edge length); with the
    /// tufted cover, its mollification factor (default 1e-5, 0 for none).
    #[arg(long)]
    pub mollify: Option<f64>,
    /// The Laplacian and mass matrix of the tufted cover (Sharp & Crane 2020) of any triangle
    /// soup: non-manifold edges and vertices, fins, duplicate faces, pieces. Taken, with a note,
    /// when a mesh is not a manifold. Gives --laplacian, --mass and --json.
    #[arg(long)]
    pub tufted: bool,
    #[command(flatten)]
    pub weld: WeldArg,
    #[command(flatten)]
    pub json: JsonArg,
    /// Corollary 1: the low-happiness triangulation after Dubois' reduction, as portalgon JSON
    /// (with --method dubois; --method auto then takes dubois).
    #[arg(long, value_name = "OUT.json")]
    pub reduced: Option<PathBuf>,
    /// The algorithm and the arithmetic.
    #[command(flatten)]
    pub method: MethodOptions,
}

/// The algorithm computing the Delaunay tessellation.
#[derive(clap::ValueEnum, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Method {
    /// Flipping unless a triangle's aspect ratio ℓ²/(2A) exceeds 1e5 (flipping would need about
    /// √(2·aspect) flips and lose digits in double precision); then dubois on a flat surface,
    /// flipping with cone points (voronoi with --exact). --mollify or --max-flips ask for flip,
    /// --reduced for dubois.
    #[default]
    Auto,
    /// Edge flipping (Bobenko–Springborn).
    Flip,
    /// The multi-source Voronoi wave and its dual (Dubois, Appendix D).
    Voronoi,
    /// Dubois' Theorem 1: Proposition 2 (Section 8's caps around the cone points, Section 4's
    /// reduction of the flat remainder, the caps put back), then the wave from the singular
    /// vertices (Proposition 3).
    Dubois,
}

impl From<Method> for DelaunayMethod {
    fn from(method: Method) -> Self {
        match method {
            Method::Auto => DelaunayMethod::Auto,
            Method::Flip => DelaunayMethod::Flip,
            Method::Voronoi => DelaunayMethod::Voronoi,
            Method::Dubois => DelaunayMethod::Dubois,
        }
    }
}

/// `--method` and `--exact`, shared by `delaunay` and `isometric`.
#[derive(clap::Args, Clone, Copy, Debug, Default)]
pub struct MethodOptions {
    /// The algorithm: auto (default), flip, voronoi, or dubois.
    #[arg(long, value_enum, default_value_t = Method::Auto)]
    pub method: Method,
    /// Compute in exact rational arithmetic (with --method voronoi or dubois; the input must be a
    /// portalgon JSON file given by exact corners).
    #[arg(long)]
    pub exact: bool,
    /// With --method dubois: run all 350 inner repetitions of ALGORITHM (Section 4.5) per outer
    /// iteration, as the paper does, instead of stopping at the first repetition that changes
    /// nothing (the output is the same; slower). On a mesh file, also run Proposition 2 (caps
    /// and ALGORITHM) instead of keeping the mesh, whose happiness is 1, as its output.
    #[arg(long)]
    pub faithful: bool,
}

impl MethodOptions {
    /// The library's request for these options (the outputs and limits left at their defaults).
    pub fn request(&self) -> DelaunayRequest {
        DelaunayRequest {
            method: self.method.into(),
            faithful: self.faithful,
            ..DelaunayRequest::default()
        }
    }

    /// Refuses `--exact` and `--faithful` where they cannot apply.
    ///
    /// # Errors
    /// An invalid-input error (exit 2).
    pub fn check(&self) -> anyhow::Result<()> {
        self.request().check(self.exact).map_err(request_error)
    }
}

/// A request the library refuses, as the options that make it (exit 2).
pub fn request_error(e: RequestError) -> anyhow::Error {
    invalid(match e {
        RequestError::FaithfulWithoutDubois => "--faithful applies to --method dubois only",
        RequestError::ExactFlip => {
            "--exact computes with --method voronoi or dubois only (the flip algorithm works on \
             lengths, which are square roots)"
        }
        RequestError::ReducedWithoutDubois => "--reduced applies to --method dubois only",
        RequestError::FlipLimitsWithoutFlip => {
            "--mollify and --max-flips apply to --method flip only"
        }
    })
}
