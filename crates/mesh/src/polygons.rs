//! Polygon faces cut into triangles, for the algorithms that need triangles (a quad mesh, a cube
//! of quads, a prism with pentagons, as modellers and exporters write them).
//!
//! **The rule** (deterministic; ours, no paper): a triangle is kept; a polygon of k ≥ 4 sides is
//! cut into k − 2 triangles, each listing its corners in the polygon's order (so the triangles
//! inherit the polygon's orientation), by ear clipping in the polygon's plane:
//!
//! 1. The plane: the coordinate plane most parallel to the polygon's best-fit plane, i.e. the
//!    one dropping the largest component of Newell's normal. Dropping a coordinate is exact, and
//!    for a planar polygon it is an affine bijection of its plane (the dropped component is not
//!    zero), so orientations, collinearity and containment there are those in the polygon's own
//!    plane. Every sign below is Shewchuk's exact `orient2d` on the kept coordinates.
//! 2. Ears: a corner c with neighbours p, n (in the polygon left so far) is an ear when it is
//!    strictly convex (p, c, n turn the way the polygon does), no other corner left lies in
//!    the closed triangle p c n (on its sides included), and the diagonal p n is free (below). Only corners that are not strictly
//!    convex are tested for containment: in a simple polygon, the corner of the triangle nearest
//!    to c (farthest from the line p n) is not strictly convex, so it is among them.
//!    A diagonal is *free* when no face of the input has it as a side and no polygon cut
//!    before has it as a diagonal: cutting along a diagonal that is not free makes an edge of
//!    three or four triangles (a quad of triangles paired by `surftopo quad`, folded along its
//!    shared side, can have its other diagonal as an edge of the surface), so only free
//!    diagonals are cut while there is a choice.
//! 3. A quadrilateral (the common polygon) has two cuts, corner 0's diagonal and the other one.
//!    A cut is admissible when neither of its triangles has zero area in space; among the
//!    admissible ones, a free diagonal first, then one that is no other quadrilateral's
//!    diagonal (two quads sharing two sides at a vertex of two faces have one diagonal in
//!    common, which only one of them may cut), then one lying inside (its two triangles turn
//!    the polygon's way: for a quad that is not planar, the plane of step 1 may show it
//!    folded); then corner 0's diagonal unless the other makes the smallest
//!    [`crate::geometry::relative_height`] of the two triangles, in space, at least twice as
//!    large (a factor, not a rounding tolerance: shapes alike, such as a rectangle's two cuts,
//!    keep corner 0's fan whatever the rounding). When neither is admissible, steps 4 and 5 as
//!    for any polygon.
//! 4. Order: the ear cut is the first one around the polygon from a cursor, which starts at
//!    corner 1 and moves to the corner after each ear cut (so a convex polygon is cut into the
//!    fan of corner 0, as a polygon without that rule would commonly be read). An ear whose
//!    triangle is near-degenerate (height below
//!    [`crate::geometry::NEAR_DEGENERATE_RELATIVE_HEIGHT`] times its longest side, in space: a
//!    corner all but collinear with its neighbours, as a vertex splitting a side in floating
//!    point makes it) is passed over while there is another ear; then it is cut.
//! 5. When that finds none either, the first corner from there whose triangle has non-zero
//!    area in space (exact test: [`crate::geometry::is_zero_area_triangle`]) and whose
//!    diagonal is free is cut, else the first whose triangle has non-zero area, else the
//!    corner the turn stopped at.
//!
//! **Guarantee**: a simple polygon in a plane (collinear corners allowed) always has an ear
//! (two, by Meisters' two-ears theorem, whose proof holds for strictly convex ears empty in the
//! closed sense when the polygon is simple and not all collinear), cutting it leaves a simple
//! polygon that is not all collinear, and an ear's triangle has non-zero area: so no triangle is
//! degenerate whenever the polygon is simple in its plane — the case in which a non-degenerate
//! triangulation exists for sure (when, besides, no side of another face joins two of its
//! corners that are not neighbours: else its ears may not be free). A polygon that is not planar (a twisted quad) or not simple
//! in its plane has none of these guarantees (nor is a near-degenerate triangle always avoided
//! where a better-shaped triangulation exists: the passing over is greedy); step 3's fallback then still avoids a zero-area
//! triangle when the corner it reaches allows it. The result is always a triangulated disk
//! (k − 2 triangles, each side of the polygon in one triangle, each diagonal in two).
//!
//! A polygon that repeats a vertex, has a vertex index out of range or a non-finite coordinate
//! is cut into the fan of corner 0 (no geometry is read): the triangles then show the problem,
//! which building the surface reports on the polygon. Cost: O(k log k + k·r) for k corners of
//! which r are not strictly convex (the ears are kept in ordered sets; an ear test looks at the
//! r corners, and cutting an ear re-tests its two neighbours only), plus O(k) per fallback cut.
//! Exact while coordinate
//! differences are between about 1e-140 and 1e140 in magnitude (the predicates' products).

use std::collections::{BTreeSet, HashMap, HashSet};

use crate::geometry::{
    NEAR_DEGENERATE_RELATIVE_HEIGHT, Point3, is_zero_area_triangle, relative_height,
    repeats_a_vertex,
};

/// Triangles of polygon faces by the module's rule, with the face of each triangle.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PolygonTriangulation {
    /// The triangles: a triangle face as it is, a polygon's k − 2 triangles in the order cut.
    pub triangles: Vec<[u32; 3]>,
    /// For each triangle, the index of the face it comes from.
    pub face_of: Vec<u32>,
    /// Faces of more than three sides (cut into triangles).
    pub polygons: usize,
    /// Of those, the faces cut at least once by step 3's fallback (not simple, or not planar,
    /// in the plane chosen) or fanned without geometry (a repeated vertex, an index out of range,
    /// a non-finite coordinate).
    pub irregular: usize,
}

impl PolygonTriangulation {
    /// Whether every face was a triangle already.
    pub fn is_identity(&self) -> bool {
        self.polygons == 0
    }
}

/// Cuts every face of more than three sides into triangles by the module's rule; triangles are
/// kept as they are, faces of fewer than three vertices give no triangle (readers refuse them).
pub fn triangulate_polygons<'a>(
    positions: &[Point3],
    faces: impl IntoIterator<Item = &'a [u32]>,
) -> PolygonTriangulation {
    let faces: Vec<&[u32]> = faces.into_iter().collect();
    let mut out = PolygonTriangulation::default();
    let mut ears = EarClipper::default();
    if faces.iter().any(|f| f.len() > 3) {
        // The sides of every face: a diagonal among them is not free (step 2).
        for face in &faces {
            for (i, &a) in face.iter().enumerate() {
                ears.taken.insert(side(a, face[(i + 1) % face.len()]));
            }
            if let [a, b, c, d] = **face {
                for diagonal in [side(a, c), side(b, d)] {
                    *ears.quad_diagonals.entry(diagonal).or_default() += 1;
                }
            }
        }
    }
    for (f, &face) in faces.iter().enumerate() {
        let before = out.triangles.len();
        match face.len() {
            0..=2 => {}
            3 => out.triangles.push([face[0], face[1], face[2]]),
            _ => {
                out.polygons += 1;
                if !ears.cut(positions, face, &mut out.triangles) {
                    out.irregular += 1;
                }
                for t in &out.triangles[before..] {
                    for i in 0..3 {
                        ears.taken.insert(side(t[i], t[(i + 1) % 3]));
                    }
                }
            }
        }
        let added = out.triangles.len() - before;
        out.face_of.extend(std::iter::repeat_n(f as u32, added));
    }
    out
}

/// [`triangulate_polygons`], unless its triangles have a combinatorial problem (a non-manifold
/// edge, a duplicate triangle: quads whose both cuts have a flat triangle, side by side, as a
/// pairing of flipped triangles can make) that the fan of each polygon's corner 0 does not have:
/// then those fans, with the first problem of the rule's triangles (naming the polygon) as the
/// second value. Both are deterministic; the fans have no geometric guarantee (the rule's
/// triangles were no surface, which is worse for every algorithm that needs one).
pub fn triangulate_polygons_as_surface<'a>(
    positions: &[Point3],
    faces: impl IntoIterator<Item = &'a [u32]>,
) -> (PolygonTriangulation, Option<crate::BuildError>) {
    let faces: Vec<&[u32]> = faces.into_iter().collect();
    let cut = triangulate_polygons(positions, faces.iter().copied());
    if cut.is_identity() {
        return (cut, None);
    }
    let n = positions.len();
    let inspection = crate::inspect(n, &cut.triangles);
    if inspection.is_combinatorially_valid() {
        return (cut, None);
    }
    let mut fans = PolygonTriangulation {
        polygons: cut.polygons,
        irregular: cut.irregular,
        ..PolygonTriangulation::default()
    };
    for (k, face) in faces.iter().enumerate() {
        let added = face.len().saturating_sub(2);
        fan(face, &mut fans.triangles);
        fans.face_of.extend(std::iter::repeat_n(k as u32, added));
    }
    if !crate::inspect(n, &fans.triangles).is_combinatorially_valid() {
        return (cut, None);
    }
    let problem = inspection
        .problems
        .into_iter()
        .next()
        .map(|p| p.on_faces(&cut.face_of));
    (fans, problem)
}

/// A polygon soup inspected through the triangles the commands cut it into
/// ([`triangulate_polygons_as_surface`]): they have the same Euler characteristic, closedness,
/// orientability and vertex fans as the polygons, so the inspection of the triangles is that of
/// the polygons once the counts are corrected for the diagonals.
#[derive(Clone, Debug)]
pub struct PolygonInspection {
    /// The inspection, counted on the polygons: `faces` the polygons, `edges` without the
    /// diagonals, each piece's `faces` and `edges` likewise; problems name the polygon (the
    /// soup's face), geometric ones first ([`crate::geometry::problems`] on the polygons). A
    /// diagonal that coincides with a side of another face shows as a non-manifold edge.
    pub inspection: crate::Inspection,
    /// The triangles the polygons were cut into, with the polygon of each.
    pub cut: PolygonTriangulation,
    /// When ear clipping's triangles were no surface and the fans of corner 0 were taken, the
    /// first problem of ear clipping's triangles (naming the polygon).
    pub fans_because: Option<crate::BuildError>,
}

impl PolygonInspection {
    /// Whether every face is a triangle.
    pub fn all_triangles(&self) -> bool {
        self.cut.is_identity()
    }
}

/// Inspects a polygon soup (any mix of triangles and polygons) as [`PolygonInspection`] says.
pub fn inspect_polygons<'a>(
    positions: &[Point3],
    faces: impl IntoIterator<Item = &'a [u32]>,
) -> PolygonInspection {
    let faces: Vec<&[u32]> = faces.into_iter().collect();
    let (cut, fans_because) = triangulate_polygons_as_surface(positions, faces.iter().copied());
    let mut inspection = crate::inspect(positions.len(), &cut.triangles);
    if !cut.is_identity() {
        let diagonals = cut.triangles.len().saturating_sub(faces.len());
        inspection.faces = faces.len();
        inspection.edges -= diagonals.min(inspection.edges);
        inspection.problems = std::mem::take(&mut inspection.problems)
            .into_iter()
            .map(|p| p.on_faces(&cut.face_of))
            .collect();
        if let Some(component) = crate::face_components(positions.len(), &cut.triangles) {
            // Per piece: one face per polygon, one edge fewer per diagonal (a polygon of k
            // sides has k − 3 diagonals, cut into k − 2 triangles).
            for (t, &c) in component.iter().enumerate() {
                let piece = &mut inspection.surfaces[c as usize];
                if t > 0 && cut.face_of[t] == cut.face_of[t - 1] {
                    piece.faces -= 1;
                    piece.edges -= 1;
                }
            }
        }
    }
    inspection.add_problems_first(crate::geometry::problems(positions, faces));
    PolygonInspection {
        inspection,
        cut,
        fans_because,
    }
}

/// The triangles of one polygon (corners in the polygon's order), by the module's rule.
pub fn triangulate_polygon(positions: &[Point3], face: &[u32]) -> Vec<[u32; 3]> {
    triangulate_polygons(positions, [face]).triangles
}

/// The undirected side of two vertices.
fn side(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The fan of corner 0.
fn fan(face: &[u32], out: &mut Vec<[u32; 3]>) {
    out.extend((1..face.len() - 1).map(|i| [face[0], face[i], face[i + 1]]));
}

/// Scratch space of the ear clipping, reused between polygons.
#[derive(Default)]
struct EarClipper {
    /// The polygon's vertices.
    vertices: Vec<u32>,
    /// The corners projected on the chosen coordinate plane.
    points: Vec<robust::Coord<f64>>,
    /// The corners in space.
    space: Vec<Point3>,
    prev: Vec<usize>,
    next: Vec<usize>,
    /// Whether a corner left is strictly convex.
    convex: Vec<bool>,
    /// Corners that are not strictly convex (the only ones an ear test looks at).
    reflex: BTreeSet<usize>,
    /// The ears (step 2), and those of them whose triangle is not near-degenerate.
    ears: BTreeSet<usize>,
    well_shaped: BTreeSet<usize>,
    /// The sides of the input's faces and the diagonals cut so far (a diagonal among them is
    /// not free).
    taken: HashSet<(u32, u32)>,
    /// How many quadrilaterals have each pair of opposite corners as a diagonal.
    quad_diagonals: HashMap<(u32, u32), u32>,
}

impl EarClipper {
    /// Cuts `face` (k ≥ 4 corners) into triangles appended to `out`; returns false when the
    /// fallback or a fan was needed.
    fn cut(&mut self, positions: &[Point3], face: &[u32], out: &mut Vec<[u32; 3]>) -> bool {
        let k = face.len();
        let usable = face.iter().all(|&v| {
            positions
                .get(v as usize)
                .is_some_and(|p| p.iter().all(|c| c.is_finite()))
        });
        if !usable || repeats_a_vertex(face) {
            fan(face, out);
            return false;
        }
        self.vertices.clear();
        self.vertices.extend_from_slice(face);
        self.space.clear();
        self.space
            .extend(face.iter().map(|&v| positions[v as usize]));
        let (axis, sign) = dominant_axis(&self.space);
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        self.points.clear();
        self.points.extend(
            self.space
                .iter()
                .map(|p| robust::Coord { x: p[i], y: p[j] }),
        );
        if k == 4
            && let Some(triangles) = self.quadrilateral(face, sign)
        {
            out.extend(triangles);
            return true;
        }
        self.prev.clear();
        self.prev.extend((0..k).map(|c| (c + k - 1) % k));
        self.next.clear();
        self.next.extend((0..k).map(|c| (c + 1) % k));
        self.convex.clear();
        self.convex.resize(k, false);
        self.reflex.clear();
        for c in 0..k {
            self.convex[c] = sign != 0.0 && self.turn(c, sign) > 0.0;
            if !self.convex[c] {
                self.reflex.insert(c);
            }
        }
        self.ears.clear();
        self.well_shaped.clear();
        for c in 0..k {
            self.classify(c, sign);
        }
        let mut regular = true;
        let (mut left, mut cursor) = (k, 1);
        while left > 3 {
            // The first well-shaped ear from the cursor on, else the first ear, else the
            // fallback (step 5).
            let chosen = match first_from(&self.well_shaped, cursor)
                .or_else(|| first_from(&self.ears, cursor))
            {
                Some(c) => c,
                None => {
                    // No ear: the polygon is not simple (or not planar) in the plane chosen.
                    regular = false;
                    self.fallback(cursor)
                }
            };
            cursor = self.clip(chosen, face, sign, out);
            left -= 1;
        }
        let (p, n) = (self.prev[cursor], self.next[cursor]);
        out.push([face[p], face[cursor], face[n]]);
        regular
    }

    /// Step 5: the first corner from `cursor` on whose triangle has non-zero area in space and
    /// whose diagonal is free, else the first of non-zero area, else `cursor`.
    fn fallback(&self, cursor: usize) -> usize {
        let around = || {
            std::iter::successors(Some(cursor), |&c| {
                Some(self.next[c]).filter(|&n| n != cursor)
            })
        };
        around()
            .find(|&c| !self.flat_in_space(c) && self.free(self.prev[c], self.next[c]))
            .or_else(|| around().find(|&c| !self.flat_in_space(c)))
            .unwrap_or(cursor)
    }

    /// Whether the diagonal between corners `a` and `b` is free (step 2).
    fn free(&self, a: usize, b: usize) -> bool {
        !self
            .taken
            .contains(&side(self.vertices[a], self.vertices[b]))
    }

    /// `sign` times the exact orientation of the corner `c` with its neighbours left: positive
    /// when strictly convex.
    fn turn(&self, c: usize, sign: f64) -> f64 {
        let (p, n) = (self.prev[c], self.next[c]);
        sign * robust::orient2d(self.points[p], self.points[c], self.points[n])
    }

    /// Step 3: the two triangles of the quadrilateral `face` along the admissible diagonal
    /// ranked first (free, then no other quadrilateral's, then inside, then corner 0's unless the other makes triangles at
    /// least twice as well-shaped); `None` when neither is admissible.
    fn quadrilateral(&self, face: &[u32], sign: f64) -> Option<[[u32; 3]; 2]> {
        let turns = |[a, b, c]: [usize; 3]| {
            sign * robust::orient2d(self.points[a], self.points[b], self.points[c]) > 0.0
        };
        let flat = |[a, b, c]: [usize; 3]| {
            is_zero_area_triangle(self.space[a], self.space[b], self.space[c])
        };
        let shape =
            |[a, b, c]: [usize; 3]| relative_height(self.space[a], self.space[b], self.space[c]);
        let options = [
            ([[0, 1, 2], [0, 2, 3]], (0, 2)),
            ([[3, 0, 1], [1, 2, 3]], (1, 3)),
        ]
        .map(|(pair, (a, b))| {
            (!pair.iter().any(|&t| flat(t))).then(|| {
                let own = self.quad_diagonals.get(&side(face[a], face[b])) <= Some(&1);
                let rank = (self.free(a, b), own, pair.iter().all(|&t| turns(t)));
                (rank, shape(pair[0]).min(shape(pair[1])), pair)
            })
        });
        let best = match options {
            [Some(a), Some(b)] if b.0 > a.0 || (b.0 == a.0 && b.1 >= 2.0 * a.1) => Some(b.2),
            [Some(a), _] => Some(a.2),
            [None, b] => b.map(|b| b.2),
        };
        best.map(|pair| pair.map(|t| t.map(|c| face[c])))
    }

    /// Whether the triangle of corner `c` and its neighbours has zero area in space.
    fn flat_in_space(&self, c: usize) -> bool {
        is_zero_area_triangle(
            self.space[self.prev[c]],
            self.space[c],
            self.space[self.next[c]],
        )
    }

    /// Step 2: `c` strictly convex, no corner left that is not strictly convex in the closed
    /// triangle of `c` and its neighbours.
    fn is_ear(&self, c: usize, sign: f64) -> bool {
        if !self.convex[c] {
            return false;
        }
        let (p, n) = (self.prev[c], self.next[c]);
        if !self.free(p, n) {
            return false;
        }
        let [a, b, d] = [self.points[p], self.points[c], self.points[n]];
        let inside = |q: robust::Coord<f64>| {
            sign * robust::orient2d(a, b, q) >= 0.0
                && sign * robust::orient2d(b, d, q) >= 0.0
                && sign * robust::orient2d(d, a, q) >= 0.0
        };
        !self
            .reflex
            .iter()
            .any(|&r| r != p && r != n && inside(self.points[r]))
    }

    /// Files `c` among the ears and the well-shaped ears, as it is now.
    fn classify(&mut self, c: usize, sign: f64) {
        self.ears.remove(&c);
        self.well_shaped.remove(&c);
        if self.is_ear(c, sign) {
            self.ears.insert(c);
            let shape = relative_height(
                self.space[self.prev[c]],
                self.space[c],
                self.space[self.next[c]],
            );
            if shape >= NEAR_DEGENERATE_RELATIVE_HEIGHT {
                self.well_shaped.insert(c);
            }
        }
    }

    /// Cuts the ear at `c`: appends its triangle, unlinks `c`, updates its neighbours'
    /// convexity and ears (in a simple polygon no other corner's ear changes: a corner that
    /// turned convex still lies where it did, and a triangle holding it holds a corner that is
    /// not strictly convex, by the lemma of step 2); returns the next corner.
    fn clip(&mut self, c: usize, face: &[u32], sign: f64, out: &mut Vec<[u32; 3]>) -> usize {
        let (p, n) = (self.prev[c], self.next[c]);
        out.push([face[p], face[c], face[n]]);
        self.next[p] = n;
        self.prev[n] = p;
        self.reflex.remove(&c);
        self.ears.remove(&c);
        self.well_shaped.remove(&c);
        for v in [p, n] {
            self.convex[v] = sign != 0.0 && self.turn(v, sign) > 0.0;
            if self.convex[v] {
                self.reflex.remove(&v);
            } else {
                self.reflex.insert(v);
            }
        }
        for v in [p, n] {
            self.classify(v, sign);
        }
        n
    }
}

/// The first element of `set` from `from` on, wrapping around (corner order around the
/// polygon: the corners left keep their cyclic order).
fn first_from(set: &BTreeSet<usize>, from: usize) -> Option<usize> {
    set.range(from..)
        .next()
        .or_else(|| set.iter().next())
        .copied()
}

/// The axis of the largest component of the polygon's Newell normal, and that component's sign
/// (0 when the normal is zero: no plane; then no corner counts as convex and the fallback
/// cuts). Computed on differences from corner 0 scaled by their largest magnitude, so large or
/// tiny coordinates neither overflow nor vanish.
fn dominant_axis(corners: &[Point3]) -> (usize, f64) {
    let o = corners[0];
    let scale = corners
        .iter()
        .flat_map(|p| (0..3).map(move |a| (p[a] - o[a]).abs()))
        .fold(0.0f64, f64::max);
    if !(scale > 0.0 && scale.is_finite()) {
        return (2, 0.0);
    }
    let d: Vec<Point3> = corners
        .iter()
        .map(|p| [0, 1, 2].map(|a| (p[a] - o[a]) / scale))
        .collect();
    let mut normal = [0.0f64; 3];
    for (k, p) in d.iter().enumerate() {
        let q = d[(k + 1) % d.len()];
        normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
        normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
        normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    let axis = (0..3)
        .max_by(|&a, &b| normal[a].abs().total_cmp(&normal[b].abs()).then(b.cmp(&a)))
        .unwrap_or(2);
    let sign = if normal[axis] > 0.0 {
        1.0
    } else if normal[axis] < 0.0 {
        -1.0
    } else {
        0.0
    };
    (axis, sign)
}
