//! [`Tolerances`]: the tolerances of rounded (`f64`, double-double) arithmetic in one value.
//!
//! Exact arithmetic decides everything exactly and reads none of them: the exact/rounded
//! decisions are methods of [`super::Scalar`] (`same_value`, `same_point`, `tie`, ...), which
//! take a tolerance from here and never evaluate it in exact mode. Each field says what it
//! decides and why its default is what it is. [`Tolerances::DEFAULT`] (also `Default`) holds
//! the values the library uses unless told otherwise; [`Tolerances::finer`] is the documented way
//! to make the decisions that identify things (lengths, angles, points, co-circularity) stricter,
//! for inputs whose features lie far below the defaults' scale.
//!
//! Two tolerances of the flipping route are options of their own calls: the Delaunay test's
//! (`DelaunayOptions::tolerance`, default [`Tolerances::delaunay`]) and the tessellation's
//! co-circularity (`delaunay_tessellation`'s argument, default [`Tolerances::cocircular`]).

/// The tolerances of rounded arithmetic (see the module doc). Lengths and distances are relative
/// to the longest side involved unless said otherwise.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Matched sides of a portalgon have equal lengths within this relative tolerance
    /// (`|a − b| ≤ length · max(a, b)`): far above the rounding of lengths computed from
    /// corners, far below any real difference. 1e-9.
    pub length: f64,
    /// A shortcut arc whose angle with a side has a sine below this runs along that side (a
    /// degenerate candidate, skipped in rounded arithmetic). 1e-9.
    pub shortcut_sine: f64,
    /// A vertex is flat when its angle sum is within this many radians of 2π. 1e-9.
    pub angle: f64,
    /// Flipping: an edge is flipped when `tan(γ/2) tan(δ/2)` exceeds `1 + delaunay` (γ + δ > π
    /// by about 1e-10 radians for well-shaped triangles). Lengths computed by flips carry
    /// rounding errors that grow with the triangles' aspect ratios (on Dubois' `T_x`, about
    /// `1e-16 · x³` in relative terms); a tolerance well above them keeps co-circular
    /// configurations from being flipped back and forth, and 1e-10 leaves `T_x`'s flip count
    /// exact up to `x ≈ 10³`. 1e-10.
    pub delaunay: f64,
    /// Two triangles are co-circular (merged in the Delaunay tessellation) when
    /// `|tan(γ/2) tan(δ/2) − 1|` is at most this. 1e-9.
    pub cocircular: f64,
    /// A flip is made (`IntrinsicTriangulation::flip_if_convex`) only when the two new triangles
    /// keep the quad's area to this relative tolerance. 1e-12.
    pub flip_area: f64,
    /// The wave: points of a constellation closer than this times the longest side are one.
    /// 1e-9.
    pub point: f64,
    /// The dual of the wave: sites closer than this times the longest side are one point (so
    /// near-co-circular sites make one polygon, as flipping merges near-co-circular triangles).
    /// 1e-9.
    pub dual: f64,
    /// The dual, when the traced Voronoi edges do not close up: built again pooling the sites
    /// of Voronoi vertices taken for one, then at this tolerance (`None`: no retry; set by
    /// [`Tolerances::with_retries`]).
    pub dual_retry: Option<f64>,
    /// The wave and the dual, when they still fail: run again with [`Tolerances::point`],
    /// [`Tolerances::dual`] and [`Tolerances::dual_retry`] times this (`None`: no retry; set by
    /// [`Tolerances::with_retries`]).
    pub finer_retry: Option<f64>,
    /// Dubois' reduction on a capped surface `T₁`: its checks of closings (a deleted vertex's
    /// corners meeting, re-glued sides of equal length) only measure the rounding of many merges,
    /// so they use at least this relative tolerance (`docs/dubois.md` §4). 1e-6.
    pub closing: f64,
    /// A bound computed in rounded arithmetic is enlarged by this relative margin so that it
    /// stays a bound (the number of outer iterations `N` with caps). 1e-9.
    pub bound_margin: f64,
    /// A polygon of a portalgon file given by exact corners (strings) is read in double
    /// precision only if what doubles hold of it (a triangle's rounded lengths, a larger
    /// polygon's rounded corners) has its exact area to this relative tolerance; else double
    /// precision cannot hold it (`T_x` for `x = 10³⁰` becomes a triangle of area 5·10²⁹ instead
    /// of 1) and the reading refuses it ([`crate::PortalgonError::BeyondDoubles`]: compute
    /// exactly). The rounding of a length moves a triangle's area by about `2⁻⁵³ · L² / A`
    /// relative, so this keeps needles of aspect ratio up to about 10⁷. 1e-9.
    pub exact_rounding: f64,
    /// The isometry test (`IsometryOptions::cocircular_tolerance`'s default; looser than
    /// [`Tolerances::cocircular`]): removing "flat" vertices whose angle sums are only within
    /// [`Tolerances::angle`] of 2π perturbs the metric slightly, differently for different
    /// triangulations of the same surface; on real meshes (fandisk) exactly co-circular quads
    /// then come out up to ~1e-8 off. The two tessellations compared must make the same merging
    /// decisions, so the test merges up to this. 1e-6.
    pub isometry_cocircular: f64,
    /// The isometry test (`IsometryOptions::length_tolerance`'s default, the CLI's
    /// `isometric --tolerance`): lengths and corners agree within this fraction of the longest
    /// side (well above the rounding of the flips and the flat-vertex removal, well below any
    /// difference a real surface shows). 1e-7.
    pub isometry_length: f64,
    /// The isometry test's certificate: total areas (and, per piece on the cover, boundary
    /// lengths and areas) differing by more than this relative amount prove two surfaces not
    /// isometric (far above the rounding of a sum of Kahan-accurate triangle areas). 1e-6.
    pub area_certificate: f64,
    /// The isometry test on the cover: a vertex counts as possibly flat when its angle sum is
    /// within this many times `IsometryOptions::angle_tolerance` of 2π (π on the boundary), the
    /// largest angle tolerance `decide_isometry`'s variants try. A factor, not a tolerance. 1e3.
    pub flat_margin: f64,
}

impl Tolerances {
    /// The library's tolerances (each field's doc gives its value and why).
    pub const DEFAULT: Self = Self {
        length: 1e-9,
        shortcut_sine: 1e-9,
        angle: 1e-9,
        delaunay: 1e-10,
        cocircular: 1e-9,
        flip_area: 1e-12,
        point: 1e-9,
        dual: 1e-9,
        dual_retry: None,
        finer_retry: None,
        closing: 1e-6,
        bound_margin: 1e-9,
        exact_rounding: 1e-9,
        isometry_cocircular: 1e-6,
        isometry_length: 1e-7,
        area_certificate: 1e-6,
        flat_margin: 1e3,
    };

    /// The wave's retries, as Dubois' rounded route sets them (`docs/dubois.md` §4): the dual
    /// again at 1e-8, then the wave and the dual a thousand times finer. A surface whose
    /// features are thousands of times smaller than its longest side can have whole clusters of
    /// sites within the default tolerance (on `seahorse2_100K.off`'s `T′`, 17 sites within
    /// 3.2e-5 of a Voronoi vertex against a longest side of 0.07); the coarse attempts come
    /// first because they merge near-co-circular vertices where the fine one may not.
    pub fn with_retries(self) -> Self {
        Self {
            dual_retry: Some(1e-8),
            finer_retry: Some(1e-3),
            ..self
        }
    }

    /// The tolerances that identify things (lengths, shortcut sines, angles, the flip test,
    /// co-circularity, points and the dual's sites, with its retry, the isometry test's
    /// co-circularity and lengths) times `factor`: below 1, stricter decisions, for inputs whose
    /// features are far below the defaults' scale (e.g. `Tolerances::default().finer(1e-3)`).
    /// The flip's area check, the closing checks, the bound margin, the area certificate and
    /// the flat margin are kept.
    pub fn finer(self, factor: f64) -> Self {
        Self {
            length: self.length * factor,
            shortcut_sine: self.shortcut_sine * factor,
            angle: self.angle * factor,
            delaunay: self.delaunay * factor,
            cocircular: self.cocircular * factor,
            isometry_cocircular: self.isometry_cocircular * factor,
            isometry_length: self.isometry_length * factor,
            ..self.finer_wave(factor)
        }
    }

    /// The wave's and the dual's tolerances times `factor` (what [`Tolerances::finer_retry`]
    /// runs with).
    pub fn finer_wave(self, factor: f64) -> Self {
        Self {
            point: self.point * factor,
            dual: self.dual * factor,
            dual_retry: self.dual_retry.map(|t| t * factor),
            ..self
        }
    }
}

impl Default for Tolerances {
    fn default() -> Self {
        Self::DEFAULT
    }
}

#[cfg(test)]
mod tests {
    use super::Tolerances;

    #[test]
    fn finer_scales_the_identifying_tolerances_and_keeps_the_checks() {
        let d = Tolerances::default().with_retries();
        let f = d.finer(1e-3);
        for (fine, coarse) in [
            (f.length, d.length),
            (f.shortcut_sine, d.shortcut_sine),
            (f.angle, d.angle),
            (f.delaunay, d.delaunay),
            (f.cocircular, d.cocircular),
            (f.point, d.point),
            (f.dual, d.dual),
            (f.dual_retry.unwrap(), d.dual_retry.unwrap()),
            (f.isometry_cocircular, d.isometry_cocircular),
            (f.isometry_length, d.isometry_length),
        ] {
            assert!((fine / coarse - 1e-3).abs() < 1e-12, "{fine} {coarse}");
        }
        assert_eq!(
            (f.flip_area, f.closing, f.bound_margin, f.finer_retry),
            (d.flip_area, d.closing, d.bound_margin, d.finer_retry)
        );
        assert_eq!(
            (f.area_certificate, f.flat_margin),
            (d.area_certificate, d.flat_margin)
        );
        assert_eq!(Tolerances::default().dual_retry, None);
    }
}
