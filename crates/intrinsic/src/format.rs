//! The portalgon JSON format (`surftopo-portalgon`, version 1), read and written with serde.
//!
//! ```json
//! {
//!   "format": "surftopo-portalgon",
//!   "version": 1,
//!   "comment": "the flat torus T_3 of Dubois, Section 9",
//!   "polygons": [
//!     { "corners": [[0, 0], [1, 0], [3, 2]], "vertices": [0, 0, 0] },
//!     { "lengths": [1, 2.8284271247461903, 3.605551275463989], "vertices": [0, 0, 0] }
//!   ],
//!   "matching": [ [[0, 0], [1, 0]], [[0, 1], [1, 1]], [[0, 2], [1, 2]] ]
//! }
//! ```
//!
//! (The second triangle is the first turned by a half-turn, `(4, 2), (3, 2), (1, 0)`, given by its
//! lengths; each side is glued to the corresponding side of the other: one vertex, three edges.)
//!
//! - `polygons[p]` is polygon `p`, given by **either** `corners` (its corners counter-clockwise in
//!   its own plane, at least three) **or**, for a triangle only, `lengths` (its three side lengths).
//!   Side `i` runs from corner `i` to corner `i + 1` (mod the corner count); for `lengths`,
//!   `lengths[i]` is the length of side `i`.
//! - `vertices` (optional; on all polygons or none) labels each corner with a vertex number; labels
//!   must agree with the gluing (corners glued together share a label, distinct vertices have
//!   distinct labels) and form `0..V`. Written by this crate, they are the dense vertex indices that
//!   number the Laplacian's rows; when read, they become the vertex ids.
//! - `matching` lists pairs of sides `[[p, i], [q, j]]`: side `i` of polygon `p` is glued to side
//!   `j` of polygon `q`, running in opposite directions (the start of one is the end of the other),
//!   which keeps the surface oriented. A side appears in at most one pair; sides in no pair are
//!   boundary. Matched sides must have equal lengths up to a relative tolerance
//!   (`|a - b| <= tolerance · max(a, b)`, default [`crate::DEFAULT_LENGTH_TOLERANCE`] = 1e-9).
//! - `format` and `version` may be omitted; if present they must be `"surftopo-portalgon"` and 1.
//!   An optional `comment` string is kept. Unknown fields are errors (typos do not pass silently).
//!
//! A triangulation (closed surface) needs every polygon to be a triangle and every side matched.
//! Written triangulations list triangles by `lengths` (exact: lengths round-trip bit for bit) or
//! by `corners` (laid out from the lengths), with `vertices`, and list pair `k` = edge `k`; reading
//! such a file back gives the same face, edge and vertex ids. Tessellations (any polygons) are
//! written with `corners`. Full description: `crates/intrinsic/PORTALGON_FORMAT.md`.

use crate::convert::{TriangleGluing, is_clockwise, triangulation_from_gluing};
use crate::error::PortalgonError;
use crate::laplacian::dense_vertex_index;
use crate::portalgon::{Portalgon, check_polygon};
use crate::triangulation::IntrinsicTriangulation;
use crate::trig;
use serde::{Deserialize, Serialize};
use std::io::{Read, Write};
use surftopo_mesh::Side;

/// A JSON syntax or schema error; the message quotes the input (field names, strings), so
/// control characters are escaped ([`surftopo_mesh::printable`]).
fn json_error(e: &serde_json::Error) -> PortalgonError {
    PortalgonError::Json(surftopo_mesh::printable(&e.to_string()).into_owned())
}

/// The `format` field.
pub const FORMAT_NAME: &str = "surftopo-portalgon";
/// The `version` field.
pub const FORMAT_VERSION: u32 = 1;

fn format_name() -> String {
    FORMAT_NAME.to_string()
}
fn format_version() -> u32 {
    FORMAT_VERSION
}

/// A portalgon file, as parsed (see the module doc).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PortalgonDoc {
    /// Always `"surftopo-portalgon"`.
    #[serde(default = "format_name")]
    pub format: String,
    /// Always 1.
    #[serde(default = "format_version")]
    pub version: u32,
    /// Free text.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub comment: Option<String>,
    /// The polygons.
    pub polygons: Vec<PolygonDoc>,
    /// Pairs of glued sides `[[polygon, side], [polygon, side]]`.
    #[serde(default)]
    pub matching: Vec<[[usize; 2]; 2]>,
}

/// One polygon of a [`PortalgonDoc`].
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolygonDoc {
    /// Corners, counter-clockwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub corners: Option<Vec<[f64; 2]>>,
    /// Side lengths of a triangle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lengths: Option<Vec<f64>>,
    /// Vertex label of each corner.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices: Option<Vec<u32>>,
}

/// How [`PortalgonDoc::from_triangulation`] writes triangles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TriangleStyle {
    /// By their three side lengths (exact).
    #[default]
    Lengths,
    /// By corners laid out in the plane from the lengths.
    Corners,
}

impl PortalgonDoc {
    /// Parses JSON text.
    ///
    /// # Errors
    /// [`PortalgonError::Json`] (with line and column), [`PortalgonError::Version`].
    pub fn from_json(text: &str) -> Result<Self, PortalgonError> {
        let doc: Self = serde_json::from_str(text).map_err(|e| json_error(&e))?;
        doc.check_header()?;
        Ok(doc)
    }

    /// Parses JSON from a reader.
    ///
    /// # Errors
    /// As [`Self::from_json`]; [`PortalgonError::Io`].
    pub fn read<R: Read>(reader: R) -> Result<Self, PortalgonError> {
        let doc: Self = serde_json::from_reader(std::io::BufReader::new(reader)).map_err(|e| {
            if e.is_io() {
                PortalgonError::Io(e.to_string())
            } else {
                json_error(&e)
            }
        })?;
        doc.check_header()?;
        Ok(doc)
    }

    /// Writes JSON (compact, or pretty-printed).
    ///
    /// # Errors
    /// [`PortalgonError::Io`]; [`PortalgonError::NonFinite`] if a number is NaN or infinite (JSON
    /// cannot hold it).
    pub fn write<W: Write>(&self, writer: W, pretty: bool) -> Result<(), PortalgonError> {
        self.check_finite()?;
        let mut w = std::io::BufWriter::new(writer);
        let result = if pretty {
            serde_json::to_writer_pretty(&mut w, self)
        } else {
            serde_json::to_writer(&mut w, self)
        };
        result.map_err(|e| PortalgonError::Io(e.to_string()))?;
        w.write_all(b"\n")
            .and_then(|()| w.flush())
            .map_err(|e| PortalgonError::Io(e.to_string()))
    }

    /// The JSON text (compact).
    ///
    /// # Errors
    /// As [`Self::write`].
    pub fn to_json(&self) -> Result<String, PortalgonError> {
        let mut out = Vec::new();
        self.write(&mut out, false)?;
        Ok(String::from_utf8(out).expect("serde_json writes UTF-8"))
    }

    fn check_header(&self) -> Result<(), PortalgonError> {
        if self.format != FORMAT_NAME || self.version != FORMAT_VERSION {
            return Err(PortalgonError::Version {
                format: self.format.clone(),
                version: self.version,
            });
        }
        Ok(())
    }

    fn check_finite(&self) -> Result<(), PortalgonError> {
        for (polygon, p) in self.polygons.iter().enumerate() {
            let corners = p.corners.iter().flatten().flatten();
            let lengths = p.lengths.iter().flatten();
            if let Some(index) = corners.chain(lengths).position(|x| !x.is_finite()) {
                return Err(PortalgonError::NonFinite { polygon, index });
            }
        }
        Ok(())
    }

    /// Number of sides of each polygon, checking that each gives exactly one shape.
    fn side_counts(&self) -> Result<Vec<usize>, PortalgonError> {
        if self.polygons.is_empty() {
            return Err(PortalgonError::Empty);
        }
        self.polygons
            .iter()
            .enumerate()
            .map(|(polygon, p)| {
                let k = match (&p.corners, &p.lengths) {
                    (Some(c), None) => c.len(),
                    (None, Some(l)) if l.len() == 3 => 3,
                    (None, Some(l)) => {
                        return Err(PortalgonError::LengthsNotTriangle {
                            polygon,
                            count: l.len(),
                        });
                    }
                    _ => return Err(PortalgonError::Shape { polygon }),
                };
                if k < 3 {
                    return Err(PortalgonError::TooFewCorners {
                        polygon,
                        corners: k,
                    });
                }
                if let Some(v) = &p.vertices
                    && v.len() != k
                {
                    return Err(PortalgonError::VertexLabels {
                        polygon,
                        detail: format!("{} labels for {k} corners", v.len()),
                    });
                }
                Ok(k)
            })
            .collect()
    }

    /// Checks the matching's side references and that no side is matched twice.
    fn checked_pairs(&self, counts: &[usize]) -> Result<Vec<[[usize; 2]; 2]>, PortalgonError> {
        let mut offset = vec![0usize; counts.len() + 1];
        for (p, &k) in counts.iter().enumerate() {
            offset[p + 1] = offset[p] + k;
        }
        let mut used = vec![false; offset[counts.len()]];
        for pair in &self.matching {
            for &[polygon, side] in pair {
                if polygon >= counts.len() || side >= counts[polygon] {
                    return Err(PortalgonError::NoSuchSide { polygon, side });
                }
                let u = &mut used[offset[polygon] + side];
                if *u {
                    return Err(PortalgonError::MatchedTwice { polygon, side });
                }
                *u = true;
            }
        }
        Ok(self.matching.clone())
    }

    fn labels_present(&self) -> Result<bool, PortalgonError> {
        let with = self
            .polygons
            .iter()
            .filter(|p| p.vertices.is_some())
            .count();
        if with != 0 && with != self.polygons.len() {
            let polygon = self
                .polygons
                .iter()
                .position(|p| p.vertices.is_none())
                .unwrap_or(0);
            return Err(PortalgonError::VertexLabels {
                polygon,
                detail: "missing (labels must be given on every polygon or on none)".into(),
            });
        }
        Ok(with != 0)
    }

    /// The portalgon: corners as given, triangles given by lengths laid out in the plane; every
    /// polygon validated ([`check_polygon`], strict triangle inequality for lengths), matched sides
    /// of equal length within `tolerance`. Polygon `p` gets id `p`, its side `i` the id of its
    /// `i`-th side.
    ///
    /// # Errors
    /// Any [`PortalgonError`] about shapes or the matching.
    pub fn to_portalgon(&self, tolerance: f64) -> Result<Portalgon, PortalgonError> {
        let counts = self.side_counts()?;
        let pairs = self.checked_pairs(&counts)?;
        let labelled = self.labels_present()?;
        let mut out = Portalgon::new();
        for (polygon, p) in self.polygons.iter().enumerate() {
            let corners = match (&p.corners, &p.lengths) {
                (Some(c), _) => {
                    check_polygon(polygon, c)?;
                    c.clone()
                }
                (None, Some(l)) => {
                    let lengths = [l[0], l[1], l[2]];
                    if !trig::is_triangle(l[0], l[1], l[2]) {
                        return Err(PortalgonError::TriangleInequality { polygon, lengths });
                    }
                    vec![
                        [0.0, 0.0],
                        [l[0], 0.0],
                        trig::third_corner(l[0], l[1], l[2]),
                    ]
                }
                (None, None) => unreachable!("side_counts checked the shape"),
            };
            let q = out.add_polygon(&corners)?;
            if labelled {
                out.set_vertex_labels(q, p.vertices.as_deref().unwrap_or_default())?;
            }
        }
        for [[p, i], [q, j]] in pairs {
            let (s, t) = (
                out.side(crate::PolygonId(p as u32), i),
                out.side(crate::PolygonId(q as u32), j),
            );
            out.glue(s, t, tolerance)?;
        }
        Ok(out)
    }

    /// The intrinsic triangulation of a closed triangular portalgon file: every polygon a
    /// triangle, every side matched. Lengths are taken as given (`lengths`) or measured
    /// (`corners`, which must not run clockwise); face `p` is polygon `p`, edge `k` is pair `k`,
    /// vertex ids are the labels if given. Triangle inequalities are checked later, by
    /// [`IntrinsicTriangulation::validate`] (so that degenerate input can still be mollified).
    ///
    /// # Errors
    /// [`PortalgonError::NotTriangle`], [`PortalgonError::Unmatched`],
    /// [`PortalgonError::UnequalSides`], [`PortalgonError::NotCounterClockwise`],
    /// [`PortalgonError::NonFinite`], [`PortalgonError::Gluing`], ...
    pub fn to_triangulation(
        &self,
        tolerance: f64,
    ) -> Result<IntrinsicTriangulation, PortalgonError> {
        let counts = self.side_counts()?;
        if let Some(polygon) = counts.iter().position(|&k| k != 3) {
            return Err(PortalgonError::NotTriangle {
                polygon,
                sides: counts[polygon],
            });
        }
        let pairs = self.checked_pairs(&counts)?;
        let labelled = self.labels_present()?;
        let mut sides = Vec::with_capacity(self.polygons.len());
        for (polygon, p) in self.polygons.iter().enumerate() {
            let l = match (&p.corners, &p.lengths) {
                (Some(c), _) => {
                    if let Some(index) = c
                        .iter()
                        .position(|x| !(x[0].is_finite() && x[1].is_finite()))
                    {
                        return Err(PortalgonError::NonFinite { polygon, index });
                    }
                    if is_clockwise(c) {
                        return Err(PortalgonError::NotCounterClockwise {
                            polygon,
                            area: crate::portalgon::signed_area(c),
                        });
                    }
                    [0, 1, 2].map(|i| {
                        let (a, b) = (c[i], c[(i + 1) % 3]);
                        (a[0] - b[0]).hypot(a[1] - b[1])
                    })
                }
                (None, Some(l)) => [l[0], l[1], l[2]],
                (None, None) => unreachable!("side_counts checked the shape"),
            };
            if let Some(index) = l.iter().position(|x| !x.is_finite()) {
                return Err(PortalgonError::NonFinite { polygon, index });
            }
            if let Some(side) = l.iter().position(|x| *x < 0.0) {
                return Err(PortalgonError::NegativeLength {
                    polygon,
                    side,
                    value: l[side],
                });
            }
            sides.push(l);
        }
        let glue: Vec<(Side, Side)> = pairs
            .iter()
            .map(|&[[p, i], [q, j]]| {
                (
                    Side {
                        face: p as u32,
                        side: i as u8,
                    },
                    Side {
                        face: q as u32,
                        side: j as u8,
                    },
                )
            })
            .collect();
        let labels: Vec<[u32; 3]> = if labelled {
            self.polygons
                .iter()
                .map(|p| {
                    let v = p.vertices.as_deref().unwrap_or_default();
                    [v[0], v[1], v[2]]
                })
                .collect()
        } else {
            Vec::new()
        };
        let polygon_index: Vec<usize> = (0..self.polygons.len()).collect();
        triangulation_from_gluing(&TriangleGluing {
            sides: &sides,
            pairs: &glue,
            labels: labelled.then_some(&labels[..]),
            polygon_index: &polygon_index,
            tolerance,
        })
    }

    /// The document of a portalgon: live polygons in id order (renumbered densely) with their
    /// corners, labels if every corner has one, and the matching.
    pub fn from_portalgon(p: &Portalgon) -> Self {
        let (dense, _) = p.compacted();
        let labelled = dense.sides().all(|s| dense.vertex_label(s).is_some());
        let polygons = dense
            .polygons()
            .map(|q| PolygonDoc {
                corners: Some(dense.corners(q)),
                lengths: None,
                vertices: labelled.then(|| {
                    dense
                        .polygon_sides(q)
                        .iter()
                        .map(|&s| dense.vertex_label(s).expect("labelled"))
                        .collect()
                }),
            })
            .collect();
        let matching = dense
            .sides()
            .filter_map(|s| {
                let t = dense.mate(s)?;
                (s < t).then(|| [s, t].map(|x| [dense.owner(x).idx(), dense.side_index(x)]))
            })
            .collect();
        Self {
            format: format_name(),
            version: FORMAT_VERSION,
            comment: None,
            polygons,
            matching,
        }
    }

    /// The document of a triangulation: live faces in id order, side `i` = `face_halfedges(f)[i]`,
    /// labels = dense vertex indices, pair `k` = the `k`-th live edge (its half-edge `2k` first).
    pub fn from_triangulation(tri: &IntrinsicTriangulation, style: TriangleStyle) -> Self {
        let mesh = tri.mesh();
        let (dense, _) = dense_vertex_index(tri);
        let mut rank = vec![u32::MAX; mesh.face_slots()];
        let mut polygons = Vec::with_capacity(mesh.face_count());
        for (k, f) in mesh.faces().enumerate() {
            rank[f.idx()] = k as u32;
            let vertices = Some(
                mesh.face_halfedges(f)
                    .iter()
                    .map(|&h| dense[mesh.origin(h).idx()])
                    .collect(),
            );
            polygons.push(match style {
                TriangleStyle::Lengths => PolygonDoc {
                    corners: None,
                    lengths: Some(tri.face_sides(f).to_vec()),
                    vertices,
                },
                TriangleStyle::Corners => PolygonDoc {
                    corners: Some(tri.layout_face(f).to_vec()),
                    lengths: None,
                    vertices,
                },
            });
        }
        let side = |h: surftopo_mesh::HalfedgeId| {
            let f = mesh.face(h);
            let i = mesh
                .face_halfedges(f)
                .iter()
                .position(|&g| g == h)
                .expect("h is in its face");
            [rank[f.idx()] as usize, i]
        };
        let matching = mesh
            .edges()
            .map(|e| [side(e.halfedge()), side(e.halfedge().twin())])
            .collect();
        Self {
            format: format_name(),
            version: FORMAT_VERSION,
            comment: None,
            polygons,
            matching,
        }
    }
}

impl IntrinsicTriangulation {
    /// Reads a closed triangular portalgon file ([`PortalgonDoc::read`] then
    /// [`PortalgonDoc::to_triangulation`]).
    ///
    /// # Errors
    /// Any [`PortalgonError`].
    pub fn read_json<R: Read>(reader: R, tolerance: f64) -> Result<Self, PortalgonError> {
        PortalgonDoc::read(reader)?.to_triangulation(tolerance)
    }

    /// Writes this triangulation as a portalgon file ([`PortalgonDoc::from_triangulation`]).
    ///
    /// # Errors
    /// [`PortalgonError::Io`], [`PortalgonError::NonFinite`].
    pub fn write_json<W: Write>(
        &self,
        writer: W,
        style: TriangleStyle,
    ) -> Result<(), PortalgonError> {
        PortalgonDoc::from_triangulation(self, style).write(writer, false)
    }
}
