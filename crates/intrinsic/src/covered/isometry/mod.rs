//! Whether two compact polyhedral surfaces of any kind — boundary loops, non-orientable pieces,
//! several pieces — are isometric ([`decide_isometry_on_cover`]).
//!
//! Dubois' Corollary 2 (Appendix A.3) covers closed surfaces: two are isometric iff their
//! canonical Delaunay tessellations (vertices: the singular points) are equal as portalgons.
//! [`crate::decide_isometry`] does that for closed orientable surfaces. Everything below is
//! ours; `docs/isometry_every_surface.md` has the reasoning at length.
//!
//! **What an isometry keeps.** A piece of K is a compact connected surface; an isometry maps
//! pieces onto pieces, boundary onto boundary, singular points onto singular points (an interior
//! vertex whose angle sum is not 2π, a boundary vertex whose angle sum is not π). So the number
//! of pieces, and per piece its topology (χ, orientability, boundary loops: exact counts), the
//! length of each boundary loop and the area, agree between isometric surfaces: when they do
//! not, "not isometric" is proven (lengths and areas by more than [`Tolerances::area_certificate`]
//! relative, far beyond their rounding).
//!
//! **A canonical tessellation per piece.** Given a vertex set V containing the corners of the
//! boundary, the triangulations of K that contain the boundary edges and whose interior edges
//! are all locally Delaunay all refine one tessellation, the Delaunay tessellation of (K, V).
//! Argument, through the cones of the cover: close each boundary loop by a cone whose apex edges
//! have length L (the cover D's construction). A boundary edge of a triangulation T of K has
//! one angle α < π opposite it in K and the cone's apex angle β = 2 asin(ℓ / 2L) on the other
//! side; an apex edge has two base angles, each below π/2. For L large enough (β < π − α for
//! every boundary edge of T and of T'), T plus the cones and T' plus the cones are Delaunay
//! triangulations of the same closed surface with the same vertices, in which every boundary
//! and apex edge is strictly Delaunay; Bobenko and Springborn's uniqueness of the Delaunay
//! tessellation of a closed surface then says T and T' merge into the same polygons. On a
//! non-orientable piece, the orientable double cover's Delaunay tessellation is unique, hence
//! invariant under the deck map, and the tessellation of K is its quotient; flipping mirror
//! edges together ([`CoveredTriangulation::flip_to_delaunay`]) keeps the triangulation a lift.
//! The tessellation is canonical when V is canonical: the singular points. Removing flat
//! vertices on K's cover is not done: V is the vertex set of K, and the tessellation is
//! canonical exactly when no vertex is flat (angle sum within a margin of 2π inside, π on the
//! boundary: [`Tolerances::flat_margin`] times the angle tolerance).
//!
//! **Comparison.** Each piece's tessellation becomes a [`TwistedMap`] (polygons, plain and
//! reversed gluings, boundary sides) and two are compared by [`compare_twisted`], Appendix A.3's
//! propagation with a sense per polygon (reflections: mirror images, and the local sense
//! changes of a non-orientable piece) and boundary sides marked. Pieces are paired by a
//! matching: first greedily (isometry is an equivalence, so a greedy pairing of isometric
//! pieces succeeds whenever one exists, up to tolerance), then, if that fails, by augmenting
//! paths over every pair with the same topology.
//!
//! **Verdicts.** Per pair of pieces: *the same* when a correspondence is found (an isometry up
//! to the length tolerance); *different* when an invariant differs, or when neither piece has a
//! flat vertex and the comparison fails with the default tolerances and with each of
//! co-circularity ×10³, ×10⁻³ and length ×10², ×10⁻² (as [`crate::decide_isometry`]'s step 4);
//! *unsure* otherwise (a flat vertex, or a variant finds a correspondence). The surfaces are
//! isometric when the pieces pair up with pairs that are the same; not isometric when no pairing
//! avoids a different pair (then every pairing contains a proven difference); otherwise
//! [`IsometryDecision::Undecided`] when the unsure pair has a flat vertex (the method's limit,
//! not rounding's), [`IsometryDecision::Undecidable`] when a tolerance variant matched. A
//! numerical breakdown of the flips is undecidable too.

mod pieces;

use crate::covered::CoveredTriangulation;
use crate::error::{DelaunayError, IsometryError};
use crate::geometry::Tolerances;
use crate::isometry::decision::IsometryDecision;
use crate::isometry::twisted::{MapMatch, TwistedMap, compare_twisted};
use crate::isometry::{IsometryOptions, ordinal};
use pieces::{FlatVertex, Piece, components, pieces, tessellations};

/// One of the two surfaces: its cover (flipped to Delaunay when first needed), its pieces and
/// their tessellations per co-circularity tolerance.
struct Surface<'a> {
    input: &'a CoveredTriangulation,
    index: usize,
    component: Vec<u32>,
    pieces: Vec<Piece>,
    flipped: Option<CoveredTriangulation>,
    maps: Vec<(f64, Vec<TwistedMap>)>,
}

impl<'a> Surface<'a> {
    fn new(input: &'a CoveredTriangulation, index: usize, options: &IsometryOptions) -> Self {
        let component = components(input);
        let margin = Tolerances::DEFAULT.flat_margin * options.angle_tolerance;
        let pieces = pieces(input, &component, margin);
        Self {
            input,
            index,
            component,
            pieces,
            flipped: None,
            maps: Vec::new(),
        }
    }

    /// The tessellation of piece `p` with co-circularity tolerance `cocircular`.
    fn map(
        &mut self,
        p: usize,
        cocircular: f64,
        options: &IsometryOptions,
    ) -> Result<&TwistedMap, IsometryError> {
        if self.flipped.is_none() {
            let mut tri = self.input.clone();
            tri.flip_to_delaunay(&options.delaunay)
                .map_err(|source| IsometryError::Delaunay {
                    surface: self.index,
                    source,
                })?;
            self.flipped = Some(tri);
        }
        let k = match self.maps.iter().position(|(c, _)| *c == cocircular) {
            Some(k) => k,
            None => {
                let tri = self.flipped.as_ref().expect("flipped above");
                let maps = tessellations(tri, &self.component, self.pieces.len(), cocircular);
                self.maps.push((cocircular, maps));
                self.maps.len() - 1
            }
        };
        Ok(&self.maps[k].1[p])
    }
}

/// The Delaunay tessellation of each connected piece of K (in the order of the pieces' first
/// faces on the cover), as [`decide_isometry_on_cover`] compares them: the cover flipped to
/// Delaunay with `options.delaunay`, co-circular triangles merged within
/// `options.cocircular_tolerance`.
///
/// # Errors
/// [`IsometryError::Delaunay`] (surface 0) when flipping fails.
pub fn piece_tessellations(
    tri: &CoveredTriangulation,
    options: &IsometryOptions,
) -> Result<Vec<TwistedMap>, IsometryError> {
    let mut surface = Surface::new(tri, 0, options);
    (0..surface.pieces.len())
        .map(|p| {
            surface
                .map(p, options.cocircular_tolerance, options)
                .cloned()
        })
        .collect()
}

/// The verdict on one pair of pieces.
#[derive(Clone, Debug, PartialEq)]
enum PairVerdict {
    Same(String),
    Different(String),
    /// A tolerance variant finds a correspondence: rounding cannot settle it.
    Unsure(String),
    /// A flat vertex is kept, so a failed comparison proves nothing.
    Flat(String),
}

/// Whether two surfaces of any kind are isometric, not isometric (proven), or undecidable in
/// double precision (see the module doc).
///
/// # Errors
/// [`IsometryError::Delaunay`] for unusable lengths (a degenerate triangle, a flip budget
/// exceeded); a numerical breakdown is [`IsometryDecision::Undecidable`] instead.
pub fn decide_isometry_on_cover(
    a: &CoveredTriangulation,
    b: &CoveredTriangulation,
    options: &IsometryOptions,
) -> Result<IsometryDecision, IsometryError> {
    let mut first = Surface::new(a, 0, options);
    let mut second = Surface::new(b, 1, options);
    if let Some(reason) = topology_differs(&first.pieces, &second.pieces) {
        return Ok(IsometryDecision::NotIsometric(reason));
    }
    match pair_up(&mut first, &mut second, options) {
        Err(IsometryError::Delaunay {
            surface,
            source: source @ DelaunayError::NumericalBreakdown { .. },
        }) => Ok(IsometryDecision::Undecidable(format!(
            "surface {surface}: {source}"
        ))),
        other => other,
    }
}

/// "a disk", "2 disks and an annulus".
fn kinds(pieces: &[Piece]) -> String {
    let mut names: Vec<String> = pieces.iter().map(|p| p.kind.name()).collect();
    names.sort();
    let mut parts: Vec<String> = Vec::new();
    let mut k = 0;
    while k < names.len() {
        let same = names[k..].iter().take_while(|n| **n == names[k]).count();
        parts.push(if same == 1 {
            format!("one {}", names[k])
        } else {
            format!("{same} of kind {}", names[k])
        });
        k += same;
    }
    parts.join(", ")
}

/// The proof that the pieces' numbers or topologies differ, if they do.
fn topology_differs(a: &[Piece], b: &[Piece]) -> Option<String> {
    let keys = |pieces: &[Piece]| {
        let mut keys: Vec<_> = pieces.iter().map(Piece::key).collect();
        keys.sort_unstable();
        keys
    };
    if a.len() != b.len() {
        return Some(format!(
            "the first has {} connected pieces ({}), the second {} ({})",
            a.len(),
            kinds(a),
            b.len(),
            kinds(b)
        ));
    }
    (keys(a) != keys(b)).then(|| {
        format!(
            "their pieces are different surfaces: {} against {} (Euler characteristic, \
             orientability or boundary loops differ)",
            kinds(a),
            kinds(b)
        )
    })
}

/// Relative difference beyond rounding.
fn differ(x: f64, y: f64) -> bool {
    (x - y).abs() > Tolerances::DEFAULT.area_certificate * x.abs().max(y.abs())
}

/// The verdict on piece `i` of the first against piece `j` of the second.
fn pair_verdict(
    first: &mut Surface,
    second: &mut Surface,
    i: usize,
    j: usize,
    options: &IsometryOptions,
) -> Result<PairVerdict, IsometryError> {
    let (p, q) = (first.pieces[i].clone(), second.pieces[j].clone());
    if p.key() != q.key() {
        return Ok(PairVerdict::Different(format!(
            "one is a {}, the other a {}",
            p.kind.name(),
            q.kind.name()
        )));
    }
    if differ(p.area, q.area) {
        return Ok(PairVerdict::Different(format!(
            "their areas {} and {} differ",
            p.area, q.area
        )));
    }
    let longest = p
        .loops
        .iter()
        .chain(&q.loops)
        .fold(0.0f64, |m, &x| m.max(x));
    if let Some(k) =
        (0..p.loops.len()).find(|&k| differ(p.loops[k] / longest, q.loops[k] / longest))
    {
        return Ok(PairVerdict::Different(format!(
            "their {} shortest boundary loops are {} and {} long",
            ordinal(k + 1),
            p.loops[k],
            q.loops[k]
        )));
    }
    let both_senses = options.allow_reflection || !p.kind.orientable;
    let compare = |first: &mut Surface,
                   second: &mut Surface,
                   cocircular: f64,
                   length: f64|
     -> Result<Result<MapMatch, String>, IsometryError> {
        let ma = first.map(i, cocircular, options)?;
        let mb = second.map(j, cocircular, options)?;
        Ok(compare_twisted(ma, mb, length, both_senses).map_err(|d| d.to_string()))
    };
    let default = compare(
        first,
        second,
        options.cocircular_tolerance,
        options.length_tolerance,
    )?;
    let difference = match default {
        Ok(found) => return Ok(PairVerdict::Same(found.reason())),
        Err(difference) => difference,
    };
    let flat = |flat: Option<FlatVertex>, which: &str| {
        flat.map(|v| {
            format!(
                "{} vertex {} of the {which} has angle sum {} (flat within the margin: \
                 removing flat vertices from a surface with boundary or without orientation is \
                 not implemented, so its Delaunay tessellation is not canonical)",
                if v.boundary { "boundary" } else { "interior" },
                v.vertex,
                v.angle
            )
        })
    };
    if let Some(reason) = flat(p.flat, "first").or_else(|| flat(q.flat, "second")) {
        return Ok(PairVerdict::Flat(format!(
            "the tessellations differ ({difference}), which proves nothing: {reason}"
        )));
    }
    let variants = [
        ("co-circularity", 1e3, 1.0),
        ("co-circularity", 1e-3, 1.0),
        ("length", 1.0, 1e2),
        ("length", 1.0, 1e-2),
    ];
    for (what, c, l) in variants {
        let (cocircular, length) = (
            options.cocircular_tolerance * c,
            options.length_tolerance * l,
        );
        if compare(first, second, cocircular, length)?.is_ok() {
            let value = if c != 1.0 { cocircular } else { length };
            return Ok(PairVerdict::Unsure(format!(
                "the tessellations differ with the default tolerances ({difference}) but match \
                 with {what} tolerance {value:e}"
            )));
        }
    }
    Ok(PairVerdict::Different(difference))
}

/// Pairs the pieces (see the module doc) and gives the verdict.
fn pair_up(
    first: &mut Surface,
    second: &mut Surface,
    options: &IsometryOptions,
) -> Result<IsometryDecision, IsometryError> {
    let n = first.pieces.len();
    let mut verdicts: Vec<Vec<Option<PairVerdict>>> = vec![vec![None; n]; n];
    let mut verdict = |first: &mut Surface, second: &mut Surface, i: usize, j: usize| {
        if verdicts[i][j].is_none() {
            verdicts[i][j] = Some(pair_verdict(first, second, i, j, options)?);
        }
        Ok::<_, IsometryError>(verdicts[i][j].clone().expect("set above"))
    };
    let same_kind = |first: &Surface, second: &Surface, i: usize, j: usize| {
        first.pieces[i].key() == second.pieces[j].key()
    };
    // Greedy first.
    let mut partner = vec![usize::MAX; n];
    let mut taken = vec![false; n];
    for (i, slot) in partner.iter_mut().enumerate() {
        for (j, used) in taken.iter_mut().enumerate() {
            if *used || !same_kind(first, second, i, j) {
                continue;
            }
            if let PairVerdict::Same(_) = verdict(first, second, i, j)? {
                *slot = j;
                *used = true;
                break;
            }
        }
    }
    let is_same = |v: &Option<PairVerdict>| matches!(v, Some(PairVerdict::Same(_)));
    let maybe = |v: &Option<PairVerdict>| {
        matches!(
            v,
            Some(PairVerdict::Same(_) | PairVerdict::Unsure(_) | PairVerdict::Flat(_))
        )
    };
    // If the greedy pairing fails: every pair of the same kind, then augmenting paths.
    let mut table = vec![vec![None; n]; n];
    let paired = if partner.iter().all(|&j| j != usize::MAX) {
        Some(partner)
    } else {
        for (i, row) in table.iter_mut().enumerate() {
            for (j, cell) in row.iter_mut().enumerate() {
                if same_kind(first, second, i, j) {
                    *cell = Some(verdict(first, second, i, j)?);
                }
            }
        }
        perfect_matching(n, |i, j| is_same(&table[i][j]))
    };
    if let Some(partner) = paired {
        return Ok(IsometryDecision::Isometric(described(
            &partner,
            &mut verdict,
            first,
            second,
        )?));
    }
    let pair_reason = |i: usize, j: usize| -> String {
        let text = match &table[i][j] {
            Some(
                PairVerdict::Same(r)
                | PairVerdict::Different(r)
                | PairVerdict::Unsure(r)
                | PairVerdict::Flat(r),
            ) => r.clone(),
            None => "they are different surfaces".into(),
        };
        if n == 1 {
            text
        } else {
            format!("piece {i} of the first against piece {j} of the second: {text}")
        }
    };
    match perfect_matching(n, |i, j| maybe(&table[i][j])) {
        Some(partner) => {
            let (i, j) = (0..n)
                .map(|i| (i, partner[i]))
                .find(|&(i, j)| !is_same(&table[i][j]))
                .expect("some pair of an unsure matching is unsure");
            Ok(match table[i][j] {
                Some(PairVerdict::Flat(_)) => IsometryDecision::Undecided(pair_reason(i, j)),
                _ => IsometryDecision::Undecidable(pair_reason(i, j)),
            })
        }
        None => {
            // A piece of the first with no possible partner names the proof; otherwise every
            // pairing meets a proven difference (Hall's condition fails).
            let lonely = (0..n).find(|&i| (0..n).all(|j| !maybe(&table[i][j])));
            Ok(IsometryDecision::NotIsometric(match lonely {
                Some(i) if n == 1 => pair_reason(i, 0),
                Some(i) => {
                    let j = (0..n).find(|&j| table[i][j].is_some()).unwrap_or(0);
                    format!(
                        "piece {i} of the first (a {}) is isometric to no piece of the second; \
                         e.g. {}",
                        first.pieces[i].kind.name(),
                        pair_reason(i, j)
                    )
                }
                None => "no pairing of the pieces of the first with those of the second avoids \
                         a pair proven not isometric"
                    .into(),
            }))
        }
    }
}

/// The reason of an isometric pairing: the pair's reason for one piece, the pairing and the
/// first pair's reason for several.
fn described(
    partner: &[usize],
    verdict: &mut impl FnMut(
        &mut Surface,
        &mut Surface,
        usize,
        usize,
    ) -> Result<PairVerdict, IsometryError>,
    first: &mut Surface,
    second: &mut Surface,
) -> Result<String, IsometryError> {
    let reason = match verdict(first, second, 0, partner[0])? {
        PairVerdict::Same(r)
        | PairVerdict::Different(r)
        | PairVerdict::Unsure(r)
        | PairVerdict::Flat(r) => r,
    };
    if partner.len() == 1 {
        return Ok(reason);
    }
    let shown: Vec<String> = partner
        .iter()
        .enumerate()
        .take(8)
        .map(|(i, j)| format!("{i}→{j}"))
        .collect();
    Ok(format!(
        "the {} pieces pair up isometrically (first→second: {}{}); piece 0: {reason}",
        partner.len(),
        shown.join(", "),
        if partner.len() > 8 { ", ..." } else { "" }
    ))
}

/// A perfect matching of the bipartite graph on `n + n` vertices with edges `edge(i, j)`
/// (augmenting paths, Kuhn's algorithm): the partner of each left vertex.
fn perfect_matching(n: usize, edge: impl Fn(usize, usize) -> bool) -> Option<Vec<usize>> {
    let mut left_of = vec![usize::MAX; n];
    for i in 0..n {
        let mut seen = vec![false; n];
        if !augment(i, &edge, &mut seen, &mut left_of) {
            return None;
        }
    }
    let mut partner = vec![usize::MAX; n];
    for (j, &i) in left_of.iter().enumerate() {
        partner[i] = j;
    }
    Some(partner)
}

/// One augmenting-path search from left vertex `i` (iterative depth-first).
fn augment(
    i: usize,
    edge: &impl Fn(usize, usize) -> bool,
    seen: &mut [bool],
    left_of: &mut [usize],
) -> bool {
    let n = seen.len();
    // Stack of (left vertex, next right vertex to try); `via[k]` is the right vertex that led
    // to stack entry k + 1.
    let mut stack = vec![(i, 0usize)];
    let mut via: Vec<usize> = Vec::new();
    while let Some(top) = stack.last_mut() {
        let u = top.0;
        let Some(j) = (top.1..n).find(|&j| !seen[j] && edge(u, j)) else {
            stack.pop();
            via.pop();
            continue;
        };
        top.1 = j + 1;
        seen[j] = true;
        via.push(j);
        if left_of[j] == usize::MAX {
            // Flip the path: each right vertex on it takes the left vertex before it.
            for (k, &(u, _)) in stack.iter().enumerate() {
                left_of[via[k]] = u;
            }
            return true;
        }
        stack.push((left_of[j], 0));
    }
    false
}
