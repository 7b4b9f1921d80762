//! The portalgon JSON format (`surftopo-portalgon`, versions 1 and 2), read and written with serde.
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
//!   which keeps the surface oriented; version 2's `[[p, i], [q, j], true]` glues them in the
//!   same direction (orientation-reversing: [`PortalgonDoc::reversed`]). A side appears in at most one pair; sides in no pair are
//!   boundary. Matched sides must have equal lengths up to a relative tolerance
//!   (`|a - b| <= tolerance · max(a, b)`, default [`crate::DEFAULT_LENGTH_TOLERANCE`] = 1e-9).
//! - Every coordinate and length is a [`Number`]: a JSON number (the decimal it spells in exact
//!   mode, its nearest double in double precision) or a string holding an exact decimal or
//!   fraction (`"1000000000.333"`, `"3000000001/3"`); exact mode ([`PortalgonDoc::to_portalgon_in`]
//!   with rationals) reads them exactly, and the writer writes a number when the value is what
//!   its shortest text spells, a `"p/q"` string otherwise.
//! - `format` and `version` may be omitted; if present they must be `"surftopo-portalgon"` and 1
//!   or 2 (writers write 1 unless a gluing reverses orientation).
//!   An optional `comment` string is kept. Unknown fields are errors (typos do not pass silently).
//!
//! A triangulation (closed surface) needs every polygon to be a triangle and every side matched.
//! Written triangulations list triangles by `lengths` (exact: lengths round-trip bit for bit) or
//! by `corners` (laid out from the lengths), with `vertices`, and list pair `k` = edge `k`; reading
//! such a file back gives the same face, edge and vertex ids. Tessellations (any polygons) are
//! written with `corners`. Full description: `crates/intrinsic/PORTALGON_FORMAT.md`.

use crate::error::PortalgonError;
use crate::formats::text_blocks::{block_count, block_range, write_blocks};
use crate::geometry::{ParseRationalError, Point, Rational, Scalar};
use crate::portalgon::{PolygonId, Portalgon, check_polygon};
use crate::triangulation::IntrinsicTriangulation;
use crate::triangulation::convert::{TriangleGluing, is_clockwise, triangulation_from_gluing};
use crate::triangulation::dense_vertex_index;
use crate::triangulation::trig;
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::io::{Read, Write};
use surftopo_mesh::Side;
use surftopo_mesh::decimal::{push_f64, push_u64};

/// A JSON syntax or schema error; the message quotes the input (field names, strings), so
/// control characters are escaped ([`surftopo_mesh::printable`]).
fn json_error(e: &serde_json::Error) -> PortalgonError {
    PortalgonError::Json(surftopo_mesh::printable(&e.to_string()).into_owned())
}

/// The `format` field.
pub const FORMAT_NAME: &str = "surftopo-portalgon";
/// The `version` field of the newest format: 2 adds orientation-reversing gluings
/// ([`PortalgonDoc::reversed`]). Writers write 1 unless some gluing reverses orientation, so
/// version-1 readers read every orientable file; both versions are read.
pub const FORMAT_VERSION: u32 = 2;
/// The version without orientation-reversing gluings.
pub const ORIENTED_VERSION: u32 = 1;

fn format_name() -> String {
    FORMAT_NAME.to_string()
}
fn format_version() -> u32 {
    FORMAT_VERSION
}

/// The version a document needs: [`FORMAT_VERSION`] with an orientation-reversing gluing, else
/// [`ORIENTED_VERSION`].
fn needed_version(reversed: &[bool]) -> u32 {
    if reversed.iter().any(|&r| r) {
        FORMAT_VERSION
    } else {
        ORIENTED_VERSION
    }
}

/// A coordinate or a length of a portalgon file: a JSON number, or a string holding an exact
/// rational (an integer, a decimal with an optional exponent, or a fraction `"p/q"`;
/// [`Rational`]'s syntax).
///
/// A JSON number literal is the exact decimal it spells (`0.1` is 1/10, `1000000000000000001`
/// that integer) for exact arithmetic, and its nearest double (the correctly rounded value, as
/// every JSON reader takes it) for double precision: [`Number::Double`] when the two are the
/// same value, [`Number::Decimal`] otherwise. Written as a JSON number when the value is a
/// double or a decimal read as one (its exact digits), as a `"p/q"` (or integer) string
/// otherwise, so `f64` output is as before, bit for bit.
#[derive(Clone, Debug, PartialEq)]
pub enum Number {
    /// The exact value of a double (a JSON number).
    Double(f64),
    /// A JSON number literal whose exact value is not a double: `exact` in exact arithmetic,
    /// `nearest` (correctly rounded; infinite beyond the range of doubles) in double precision.
    Decimal {
        /// The decimal, exactly.
        exact: Rational,
        /// The double nearest to it.
        nearest: f64,
    },
    /// An exact rational that is not a double (a JSON string).
    Exact(Rational),
}

impl Number {
    /// The value of a scalar: a double for `f64`; for rationals a double when it is one whose
    /// shortest decimal text is its exact value (`0.5`, `3.0`: read back exactly as a number
    /// literal), `Exact` otherwise (the double nearest 0.1, whose shortest text `0.1` is 1/10,
    /// is written `"3602879701896397/36028797018963968"`). `Double(NaN)` for a non-finite
    /// double (rejected when written).
    pub fn from_scalar<S: Scalar>(v: &S) -> Self {
        if !S::EXACT {
            return Number::Double(v.to_f64());
        }
        match v.to_rational() {
            Some(r) => match r.as_exact_f64() {
                Some(x) if Self::shortest_text_is_exact(x) => Number::Double(x),
                _ => Number::Exact(r),
            },
            None => Number::Double(f64::NAN),
        }
    }

    /// Whether the shortest decimal text of `x` (what the writers write) spells `x` exactly.
    fn shortest_text_is_exact(x: f64) -> bool {
        let mut text = Vec::new();
        push_f64(&mut text, x);
        let text = std::str::from_utf8(&text).expect("ASCII");
        match crate::geometry::small_literal(text, x) {
            Some(decimal) => decimal.is_none(),
            None => text
                .parse::<Rational>()
                .is_ok_and(|r| r.as_exact_f64() == Some(x)),
        }
    }

    /// A JSON number literal (`-12`, `0.1`, `2.5e-3`, as JSON spells numbers): a
    /// [`Number::Double`] when its exact value is its nearest double, else a
    /// [`Number::Decimal`].
    ///
    /// # Errors
    /// The text is not a number, or its exact value has more bits than
    /// [`crate::geometry::MAX_INPUT_BITS`] allows.
    pub fn from_literal(text: &str) -> Result<Self, String> {
        let nearest: f64 = text
            .parse()
            .map_err(|_| format!("not a number: {text:?}"))?;
        match crate::geometry::small_literal(text, nearest) {
            Some(None) => return Ok(Number::Double(nearest)),
            Some(Some(exact)) => return Ok(Number::Decimal { exact, nearest }),
            None => {}
        }
        let exact: Rational = text
            .parse()
            .map_err(|e: ParseRationalError| e.to_string())?;
        if exact.as_exact_f64() == Some(nearest) {
            return Ok(Number::Double(nearest));
        }
        Ok(Number::Decimal { exact, nearest })
    }

    /// The nearest double.
    pub fn to_f64(&self) -> f64 {
        match self {
            Number::Double(x) | Number::Decimal { nearest: x, .. } => *x,
            Number::Exact(r) => r.to_f64(),
        }
    }

    /// The value in the scalar type `S`: exact for rationals; a number literal's nearest
    /// double otherwise; `None` for a non-finite double.
    pub fn to_scalar<S: Scalar>(&self) -> Option<S> {
        match self {
            Number::Double(x) => S::from_f64(*x),
            Number::Decimal { exact, .. } if S::EXACT => Some(S::from_rational(exact)),
            Number::Decimal { nearest, .. } => S::from_f64(*nearest),
            Number::Exact(r) => Some(S::from_rational(r)),
        }
    }

    /// Whether double precision reads this number as written: a double or a number literal
    /// (not an exact string, whose double-precision reading is exact arithmetic rounded once).
    fn is_literal(&self) -> bool {
        !matches!(self, Number::Exact(_))
    }

    /// Whether the value is finite (strings and decimals always are).
    pub fn is_finite(&self) -> bool {
        !matches!(self, Number::Double(x) if !x.is_finite())
    }

    /// The JSON text of the value: a number for a double or a decimal, a string otherwise.
    fn json_text(&self) -> String {
        match self {
            Number::Double(x) => {
                let mut buf = Vec::new();
                push_f64(&mut buf, *x);
                String::from_utf8(buf).expect("ASCII")
            }
            Number::Decimal { exact, nearest } => {
                // The shortest text of the nearest double when it spells the decimal (`0.1`,
                // `1e300`), else every digit.
                let short = Number::Double(*nearest).json_text();
                if short.parse::<Rational>().as_ref() == Ok(exact) {
                    short
                } else {
                    exact
                        .to_decimal()
                        .expect("a decimal read from a literal has a finite decimal expansion")
                }
            }
            Number::Exact(r) => format!("\"{r}\""),
        }
    }
}

impl From<f64> for Number {
    fn from(x: f64) -> Self {
        Number::Double(x)
    }
}

impl Serialize for Number {
    fn serialize<Z: Serializer>(&self, serializer: Z) -> Result<Z::Ok, Z::Error> {
        match self {
            Number::Double(x) => serializer.serialize_f64(*x),
            Number::Decimal { .. } => serde_json::value::RawValue::from_string(self.json_text())
                .map_err(serde::ser::Error::custom)?
                .serialize(serializer),
            Number::Exact(r) => serializer.serialize_str(&r.to_string()),
        }
    }
}

impl<'de> Deserialize<'de> for Number {
    /// The JSON text of the value as written (`serde_json`'s raw values), so that a number
    /// literal is read exactly ([`Number::from_literal`]); a string holds a [`Rational`].
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        use serde::de::Error;
        let raw = Box::<serde_json::value::RawValue>::deserialize(deserializer)?;
        let text = raw.get();
        if text.starts_with('"') {
            let s: std::borrow::Cow<'_, str> =
                serde_json::from_str(text).map_err(D::Error::custom)?;
            let r: Rational = s.parse().map_err(D::Error::custom)?;
            return Ok(Number::from_scalar(&r));
        }
        if !text.starts_with(|c: char| c == '-' || c.is_ascii_digit()) {
            return Err(D::Error::custom(format!(
                "expected a number, or a string holding an exact decimal or fraction p/q, found {}",
                surftopo_mesh::printable(&text.chars().take(40).collect::<String>())
            )));
        }
        Number::from_literal(text).map_err(D::Error::custom)
    }
}

/// A portalgon file, as parsed (see the module doc).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(try_from = "RawDoc", into = "RawDoc")]
pub struct PortalgonDoc {
    /// Always `"surftopo-portalgon"`.
    pub format: String,
    /// 1, or 2 when some gluing reverses orientation ([`FORMAT_VERSION`]).
    pub version: u32,
    /// Free text.
    pub comment: Option<String>,
    /// The polygons.
    pub polygons: Vec<PolygonDoc>,
    /// Pairs of glued sides `[[polygon, side], [polygon, side]]`.
    pub matching: Vec<[[usize; 2]; 2]>,
    /// Per pair of `matching`, whether its sides run in the **same** direction (an
    /// orientation-reversing gluing: version 2, `[[p, i], [q, j], true]`); empty when none does.
    pub reversed: Vec<bool>,
}

/// The document as JSON holds it: a matching entry may carry its orientation flag.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDoc {
    #[serde(default = "format_name")]
    format: String,
    #[serde(default = "format_version")]
    version: u32,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    comment: Option<String>,
    polygons: Vec<PolygonDoc>,
    #[serde(default)]
    matching: Vec<RawPair>,
}

/// A matching entry: `[[p, i], [q, j]]`, or `[[p, i], [q, j], reversed]`.
struct RawPair([[usize; 2]; 2], bool);

impl Serialize for RawPair {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        use serde::ser::SerializeTuple;
        let mut t = serializer.serialize_tuple(if self.1 { 3 } else { 2 })?;
        t.serialize_element(&self.0[0])?;
        t.serialize_element(&self.0[1])?;
        if self.1 {
            t.serialize_element(&true)?;
        }
        t.end()
    }
}

impl<'de> Deserialize<'de> for RawPair {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = RawPair;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(
                    "a pair of sides [[p, i], [q, j]], optionally followed by true or false",
                )
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<RawPair, A::Error> {
                use serde::de::Error;
                let a = seq
                    .next_element()?
                    .ok_or_else(|| A::Error::invalid_length(0, &self))?;
                let b = seq
                    .next_element()?
                    .ok_or_else(|| A::Error::invalid_length(1, &self))?;
                let reversed = seq.next_element()?.unwrap_or(false);
                if seq.next_element::<serde::de::IgnoredAny>()?.is_some() {
                    return Err(A::Error::invalid_length(4, &self));
                }
                Ok(RawPair([a, b], reversed))
            }
        }
        deserializer.deserialize_seq(Visitor)
    }
}

impl TryFrom<RawDoc> for PortalgonDoc {
    type Error = String;
    fn try_from(raw: RawDoc) -> Result<Self, String> {
        let reversed: Vec<bool> = raw.matching.iter().map(|p| p.1).collect();
        let any = reversed.iter().any(|&r| r);
        if let Some(k) = reversed.iter().position(|&r| r)
            && raw.version < FORMAT_VERSION
            && raw.format == FORMAT_NAME
        {
            return Err(format!(
                "matching entry {k} reverses orientation, which needs \"version\": {FORMAT_VERSION} \
                 (the file says {})",
                raw.version
            ));
        }
        Ok(Self {
            format: raw.format,
            version: raw.version,
            comment: raw.comment,
            polygons: raw.polygons,
            matching: raw.matching.iter().map(|p| p.0).collect(),
            reversed: if any { reversed } else { Vec::new() },
        })
    }
}

impl From<PortalgonDoc> for RawDoc {
    fn from(doc: PortalgonDoc) -> Self {
        let version = doc.version.max(needed_version(&doc.reversed));
        let matching = doc
            .matching
            .iter()
            .enumerate()
            .map(|(k, &p)| RawPair(p, doc.reversed.get(k).copied().unwrap_or(false)))
            .collect();
        RawDoc {
            format: doc.format,
            version,
            comment: doc.comment,
            polygons: doc.polygons,
            matching,
        }
    }
}

/// One polygon of a [`PortalgonDoc`].
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolygonDoc {
    /// Corners, counter-clockwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub corners: Option<Vec<[Number; 2]>>,
    /// Side lengths of a triangle.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lengths: Option<Vec<Number>>,
    /// Vertex label of each corner.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertices: Option<Vec<u32>>,
}

impl PolygonDoc {
    /// Whether the polygon has three sides (by corners or lengths).
    pub fn is_triangle(&self) -> bool {
        match (&self.corners, &self.lengths) {
            (Some(c), _) => c.len() == 3,
            (None, Some(l)) => l.len() == 3,
            (None, None) => false,
        }
    }
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
    /// A document of the oriented format (no reversed pairs, no comment) with these polygons and
    /// this matching: the header every writer here puts out.
    fn oriented(polygons: Vec<PolygonDoc>, matching: Vec<[[usize; 2]; 2]>) -> Self {
        Self {
            format: format_name(),
            version: ORIENTED_VERSION,
            comment: None,
            polygons,
            matching,
            reversed: Vec::new(),
        }
    }

    /// Parses JSON text.
    ///
    /// # Errors
    /// [`PortalgonError::Json`] (with line and column), [`PortalgonError::Version`].
    pub fn from_json(text: &str) -> Result<Self, PortalgonError> {
        let doc: Self = serde_json::from_str(text).map_err(|e| json_error(&e))?;
        doc.check_header()?;
        Ok(doc)
    }

    /// Parses JSON text in memory (faster than [`Self::read`] on a reader).
    ///
    /// # Errors
    /// As [`Self::from_json`]; [`PortalgonError::Json`] for text that is not UTF-8.
    pub fn from_slice(bytes: &[u8]) -> Result<Self, PortalgonError> {
        let doc: Self = serde_json::from_slice(bytes).map_err(|e| json_error(&e))?;
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

    /// Writes JSON (compact, or pretty-printed). Compact output is written by hand
    /// (`write_compact`, on several threads), with the bytes `serde_json::to_writer` gives for the document.
    ///
    /// # Errors
    /// [`PortalgonError::Io`]; [`PortalgonError::NonFinite`] if a number is NaN or infinite (JSON
    /// cannot hold it).
    pub fn write<W: Write>(&self, writer: W, pretty: bool) -> Result<(), PortalgonError> {
        self.check_finite()?;
        if !pretty {
            return write_compact(
                writer,
                self.version.max(needed_version(&self.reversed)),
                self.comment.as_deref(),
                self.polygons.len(),
                |p, buf| push_polygon(buf, &self.polygons[p]),
                self.matching.len(),
                |k| {
                    let reversed = self.reversed.get(k).copied().unwrap_or(false);
                    (self.matching[k], reversed)
                },
            );
        }
        let mut w = std::io::BufWriter::new(writer);
        serde_json::to_writer_pretty(&mut w, self)
            .map_err(|e| PortalgonError::Io(e.to_string()))?;
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
        if self.format != FORMAT_NAME
            || !(ORIENTED_VERSION..=FORMAT_VERSION).contains(&self.version)
        {
            return Err(PortalgonError::Version {
                format: self.format.clone(),
                version: self.version,
            });
        }
        Ok(())
    }

    fn check_finite(&self) -> Result<(), PortalgonError> {
        for (polygon, p) in self.polygons.iter().enumerate() {
            if let Some(index) = p
                .corners
                .iter()
                .flatten()
                .position(|c| !(c[0].is_finite() && c[1].is_finite()))
                .or_else(|| p.lengths.iter().flatten().position(|x| !x.is_finite()))
            {
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

    /// Checks the matching's side references, that no side is matched twice and that no
    /// gluing reverses orientation (an oriented portalgon).
    fn checked_pairs(&self, counts: &[usize]) -> Result<Vec<[[usize; 2]; 2]>, PortalgonError> {
        self.checked_sides(counts)?;
        if let Some(k) = self.reversed.iter().position(|&r| r) {
            let [polygon, side] = self.matching[k][0];
            return Err(PortalgonError::ReversedGluing { polygon, side });
        }
        Ok(self.matching.clone())
    }

    /// Checks the matching's side references and that no side is matched twice (or to itself).
    fn checked_sides(&self, counts: &[usize]) -> Result<(), PortalgonError> {
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
        Ok(())
    }

    /// Whether every side of every polygon is glued, checked on the file's structure alone
    /// (O(sides), before any corner is read or polygon checked): the first free side is named.
    ///
    /// # Errors
    /// [`PortalgonError::Unmatched`], and the structural errors of the matching
    /// ([`PortalgonError::NoSuchSide`], [`PortalgonError::MatchedTwice`], ...).
    pub fn check_closed(&self) -> Result<(), PortalgonError> {
        let counts = self.side_counts()?;
        let pairs = self.checked_pairs(&counts)?;
        let mut glued: Vec<Vec<bool>> = counts.iter().map(|&k| vec![false; k]).collect();
        for [polygon, side] in pairs.iter().flatten() {
            glued[*polygon][*side] = true;
        }
        for (polygon, sides) in glued.iter().enumerate() {
            if let Some(side) = sides.iter().position(|&g| !g) {
                return Err(PortalgonError::Unmatched { polygon, side });
            }
        }
        Ok(())
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
        self.to_portalgon_in::<f64>(tolerance)
    }

    /// Whether every polygon is given by its corners (the input of exact mode: lengths are
    /// square roots in general).
    pub fn has_corners_only(&self) -> bool {
        self.polygons.iter().all(|p| p.corners.is_some())
    }

    /// The portalgon in the scalar type `S` ([`Self::to_portalgon`] for `f64`). In exact mode
    /// (`S::EXACT`) corners are read exactly (numbers as the doubles they are, strings as the
    /// rationals they hold), matched sides must have exactly equal lengths, and a polygon given by
    /// `lengths` is refused ([`PortalgonError::LengthsNotExact`]).
    ///
    /// # Errors
    /// As [`Self::to_portalgon`]; [`PortalgonError::LengthsNotExact`].
    pub fn to_portalgon_in<S: Scalar>(
        &self,
        tolerance: f64,
    ) -> Result<Portalgon<S>, PortalgonError> {
        let counts = self.side_counts()?;
        let pairs = self.checked_pairs(&counts)?;
        let labelled = self.labels_present()?;
        let mut out = Portalgon::empty();
        for (polygon, p) in self.polygons.iter().enumerate() {
            let corners: Vec<Point<S>> = match (&p.corners, &p.lengths) {
                (Some(c), _) => {
                    if !S::EXACT {
                        corners_held_by_doubles(polygon, c)?;
                    }
                    let c = scalar_corners(polygon, c)?;
                    check_polygon(polygon, &c)?;
                    c
                }
                (None, Some(_)) if S::EXACT => {
                    return Err(PortalgonError::LengthsNotExact { polygon });
                }
                (None, Some(l)) => {
                    let l: Vec<f64> = l.iter().map(Number::to_f64).collect();
                    let lengths = [l[0], l[1], l[2]];
                    if !trig::is_triangle(l[0], l[1], l[2]) {
                        return Err(PortalgonError::TriangleInequality { polygon, lengths });
                    }
                    let third = trig::third_corner(l[0], l[1], l[2]);
                    [[0.0, 0.0], [l[0], 0.0], third]
                        .iter()
                        .map(|c| [S::from_f64(c[0]), S::from_f64(c[1])])
                        .map(|c| c[0].clone().zip(c[1].clone()).map(|(x, y)| [x, y]))
                        .collect::<Option<Vec<_>>>()
                        .ok_or(PortalgonError::NonFinite { polygon, index: 0 })?
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
                out.side(PolygonId(p as u32), i),
                out.side(PolygonId(q as u32), j),
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
        let sides = self.triangle_sides()?;
        let glue: Vec<(Side, Side)> = pairs
            .iter()
            .map(|&pair| pair.map(as_side))
            .map(|[a, b]| (a, b))
            .collect();
        let labels: Vec<[u32; 3]> = if labelled {
            self.triangle_labels()
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

    /// The side lengths of every polygon of a file of triangles: given (`lengths`) or measured
    /// (`corners`, which must not run clockwise; exact corners measured exactly, then rounded
    /// once). Triangle inequalities are not checked (degenerate input may be mollified).
    ///
    /// # Errors
    /// [`PortalgonError::NotCounterClockwise`], [`PortalgonError::NonFinite`],
    /// [`PortalgonError::NegativeLength`].
    pub(crate) fn triangle_sides(&self) -> Result<Vec<[f64; 3]>, PortalgonError> {
        let mut sides = Vec::with_capacity(self.polygons.len());
        for (polygon, p) in self.polygons.iter().enumerate() {
            let l = match (&p.corners, &p.lengths) {
                (Some(c), _) if c.iter().flatten().all(Number::is_literal) => {
                    let c: Vec<Point<f64>> = scalar_corners(polygon, c)?;
                    if is_clockwise(&c) {
                        return Err(PortalgonError::NotCounterClockwise {
                            polygon,
                            area: crate::portalgon::signed_area(&c),
                        });
                    }
                    [0, 1, 2].map(|i| {
                        let (a, b) = (c[i], c[(i + 1) % 3]);
                        (a[0] - b[0]).hypot(a[1] - b[1])
                    })
                }
                (Some(c), _) => {
                    // Exact corners that are not all doubles: the orientation and the squared
                    // lengths exactly, then one rounding and a square root.
                    let c: Vec<Point<Rational>> = scalar_corners(polygon, c)?;
                    let area = crate::portalgon::signed_area(&c);
                    if area.sign() == std::cmp::Ordering::Less {
                        return Err(PortalgonError::NotCounterClockwise {
                            polygon,
                            area: area.to_f64(),
                        });
                    }
                    let l = [0, 1, 2].map(|i| {
                        crate::geometry::dist2(&c[i], &c[(i + 1) % 3])
                            .to_f64()
                            .sqrt()
                    });
                    held_by_doubles(polygon, &area, trig::area(l[0], l[1], l[2]))?;
                    l
                }
                (None, Some(l)) => [l[0].to_f64(), l[1].to_f64(), l[2].to_f64()],
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
        Ok(sides)
    }

    /// Whether the surface is not one closed oriented piece: some gluing reverses orientation,
    /// some side is free or the gluing has several pieces
    /// ([`crate::CoveredTriangulation::from_doc`] reads it). Structural only (no number read).
    pub fn needs_cover(&self) -> bool {
        let counts: Vec<usize> = self
            .polygons
            .iter()
            .map(|p| match (&p.corners, &p.lengths) {
                (Some(c), None) => c.len(),
                (None, Some(l)) => l.len(),
                _ => 0,
            })
            .collect();
        let sides: usize = counts.iter().sum();
        if self.reversed.contains(&true) || 2 * self.matching.len() != sides {
            return true;
        }
        let mut pieces = surftopo_mesh::UnionFind::new(counts.len());
        for &[[p, _], [q, _]] in &self.matching {
            if p < counts.len() && q < counts.len() {
                pieces.union(p as u32, q as u32);
            }
        }
        (0..counts.len() as u32).any(|p| pieces.find(p) != 0)
    }

    /// The checked pieces of a file of triangles glued in any way, for
    /// [`crate::CoveredTriangulation::from_doc`]: the side lengths
    /// ([`Self::triangle_sides`]), the pairs as sides, per pair whether it reverses
    /// orientation, and each corner's label if the file gives them.
    ///
    /// # Errors
    /// [`PortalgonError::NotTriangle`], the matching's structural errors
    /// ([`PortalgonError::NoSuchSide`], [`PortalgonError::MatchedTwice`]), the lengths' errors,
    /// [`PortalgonError::VertexLabels`] (labels on some polygons only).
    pub(crate) fn twisted_parts(&self) -> Result<TwistedParts, PortalgonError> {
        let counts = self.side_counts()?;
        if let Some(polygon) = counts.iter().position(|&k| k != 3) {
            return Err(PortalgonError::NotTriangle {
                polygon,
                sides: counts[polygon],
            });
        }
        self.checked_sides(&counts)?;
        let labelled = self.labels_present()?;
        let sides = self.triangle_sides()?;
        let pairs = self
            .matching
            .iter()
            .map(|&pair| pair.map(as_side))
            .map(|[a, b]| (a, b))
            .collect();
        let reversed = (0..self.matching.len())
            .map(|k| self.reversed.get(k).copied().unwrap_or(false))
            .collect();
        let labels = labelled.then(|| self.triangle_labels());
        Ok(TwistedParts {
            sides,
            pairs,
            reversed,
            labels,
        })
    }

    /// The file with every polygon of more than three sides cut into triangles (each polygon
    /// in its own plane, [`crate::geometry::triangulate_polygon`]: O(k log k) exact predicates,
    /// no flat triangle), for [`crate::CoveredTriangulation::from_doc`]: the polygon's sides
    /// keep their gluings (reversed or not) or stay free, the diagonals are glued plainly,
    /// labels are kept. Returns it with the file's polygon of each triangle. Checked first on
    /// the file itself, so that errors name its polygons and sides: the matching's structure,
    /// every polygon simple and counter-clockwise (corners needed beyond three sides), glued
    /// sides of equal lengths within `tolerance`.
    ///
    /// # Errors
    /// [`PortalgonError::NoSuchSide`], [`PortalgonError::MatchedTwice`],
    /// [`PortalgonError::LengthsNotTriangle`], [`PortalgonError::NotSimple`] and the other
    /// shape errors of [`check_polygon`], [`PortalgonError::UnequalSides`].
    pub(crate) fn cut_into_triangles(
        &self,
        tolerance: f64,
    ) -> Result<(PortalgonDoc, Vec<usize>), PortalgonError> {
        let counts = self.side_counts()?;
        self.checked_sides(&counts)?;
        self.labels_present()?;
        let mut offset = vec![0usize; counts.len() + 1];
        for (p, &k) in counts.iter().enumerate() {
            offset[p + 1] = offset[p] + k;
        }
        let mut length = vec![0.0f64; offset[counts.len()]];
        // Per side of the file: the triangle side it becomes.
        let mut new_side = vec![[0usize; 2]; offset[counts.len()]];
        let (mut polygons, mut matching, mut reversed) = (Vec::new(), Vec::new(), Vec::new());
        let mut polygon_of = Vec::new();
        for (polygon, p) in self.polygons.iter().enumerate() {
            let k = counts[polygon];
            let corners = match &p.corners {
                Some(c) => {
                    corners_held_by_doubles(polygon, c)?;
                    let points: Vec<Point<f64>> = scalar_corners(polygon, c)?;
                    check_polygon(polygon, &points)?;
                    for i in 0..k {
                        let (a, b) = (points[i], points[(i + 1) % k]);
                        length[offset[polygon] + i] = (a[0] - b[0]).hypot(a[1] - b[1]);
                    }
                    points
                }
                None => {
                    let l = p.lengths.as_deref().unwrap_or_default();
                    for (i, x) in l.iter().enumerate() {
                        length[offset[polygon] + i] = x.to_f64();
                    }
                    Vec::new()
                }
            };
            if k == 3 {
                for i in 0..3 {
                    new_side[offset[polygon] + i] = [polygons.len(), i];
                }
                polygons.push(p.clone());
                polygon_of.push(polygon);
                continue;
            }
            let triangles =
                crate::geometry::triangulate_polygon(&corners).ok_or(PortalgonError::NotAnArc {
                    polygon,
                    i: 0,
                    j: 0,
                })?;
            let mut diagonal = std::collections::HashMap::new();
            let given = p.corners.as_deref().unwrap_or_default();
            for t in triangles {
                let q = polygons.len();
                for (s, (a, b)) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])]
                    .into_iter()
                    .enumerate()
                {
                    if b == (a + 1) % k {
                        new_side[offset[polygon] + a] = [q, s];
                    } else if let Some(other) = diagonal.remove(&(b, a)) {
                        matching.push([other, [q, s]]);
                        reversed.push(false);
                    } else {
                        diagonal.insert((a, b), [q, s]);
                    }
                }
                polygons.push(PolygonDoc {
                    corners: Some(t.iter().map(|&c| given[c].clone()).collect()),
                    lengths: None,
                    vertices: p
                        .vertices
                        .as_ref()
                        .map(|v| t.iter().map(|&c| v[c]).collect()),
                });
                polygon_of.push(polygon);
            }
        }
        for (k, &[[p, i], [q, j]]) in self.matching.iter().enumerate() {
            let (a, b) = (length[offset[p] + i], length[offset[q] + j]);
            if (a - b).abs() > tolerance * a.max(b) {
                return Err(PortalgonError::UnequalSides {
                    polygon_a: p,
                    side_a: i,
                    polygon_b: q,
                    side_b: j,
                    length_a: a,
                    length_b: b,
                    tolerance,
                });
            }
            matching.push([new_side[offset[p] + i], new_side[offset[q] + j]]);
            reversed.push(self.reversed.get(k).copied().unwrap_or(false));
        }
        let doc = PortalgonDoc {
            format: self.format.clone(),
            version: self.version,
            comment: None,
            polygons,
            matching,
            reversed,
        };
        Ok((doc, polygon_of))
    }

    /// The labels of a file of labelled triangles.
    fn triangle_labels(&self) -> Vec<[u32; 3]> {
        self.polygons
            .iter()
            .map(|p| {
                let v = p.vertices.as_deref().unwrap_or_default();
                [v[0], v[1], v[2]]
            })
            .collect()
    }

    /// The document of a portalgon: live polygons in id order (renumbered densely) with their
    /// corners, labels if every corner has one, and the matching.
    /// Exact corners are written exactly (`Number::from_scalar`).
    pub fn from_portalgon<S: Scalar>(p: &Portalgon<S>) -> Self {
        let (dense, _) = p.compacted();
        let labelled = dense.sides().all(|s| dense.vertex_label(s).is_some());
        let polygons = dense
            .polygons()
            .map(|q| PolygonDoc {
                corners: Some(
                    dense
                        .corners(q)
                        .iter()
                        .map(|c| [Number::from_scalar(&c[0]), Number::from_scalar(&c[1])])
                        .collect(),
                ),
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
        Self::oriented(polygons, matching)
    }

    /// The document of a triangulation: live faces in id order, side `i` = `face_halfedges(f)[i]`,
    /// labels = dense vertex indices, pair `k` = the `k`-th live edge (its half-edge `2k` first).
    pub fn from_triangulation(tri: &IntrinsicTriangulation, style: TriangleStyle) -> Self {
        let mesh = tri.mesh();
        let (dense, _) = dense_vertex_index(tri);
        let mut polygons = Vec::with_capacity(mesh.face_count());
        for f in mesh.faces() {
            let vertices = Some(
                mesh.face_halfedges(f)
                    .iter()
                    .map(|&h| dense[mesh.origin(h).idx()])
                    .collect(),
            );
            polygons.push(match style {
                TriangleStyle::Lengths => PolygonDoc {
                    corners: None,
                    lengths: Some(
                        tri.face_sides(f)
                            .iter()
                            .map(|&l| Number::Double(l))
                            .collect(),
                    ),
                    vertices,
                },
                TriangleStyle::Corners => PolygonDoc {
                    corners: Some(
                        tri.layout_face(f)
                            .iter()
                            .map(|c| [Number::Double(c[0]), Number::Double(c[1])])
                            .collect(),
                    ),
                    lengths: None,
                    vertices,
                },
            });
        }
        let sides = TriangulationSides::new(tri);
        let matching = (0..sides.edges.len()).map(|k| sides.pair(k)).collect();
        Self::oriented(polygons, matching)
    }
}

/// A file of triangles glued in any way, checked ([`PortalgonDoc::twisted_parts`]).
pub(crate) struct TwistedParts {
    /// The side lengths of each triangle.
    pub sides: Vec<[f64; 3]>,
    /// The matching's pairs.
    pub pairs: Vec<(Side, Side)>,
    /// Per pair, whether it reverses orientation.
    pub reversed: Vec<bool>,
    /// Each corner's label, if the file gives them.
    pub labels: Option<Vec<[u32; 3]>>,
}

/// A `[polygon, side]` of a file of triangles as a [`Side`].
fn as_side([p, i]: [usize; 2]) -> Side {
    Side {
        face: p as u32,
        side: i as u8,
    }
}

/// The live faces and edges of a triangulation in id order, and the side of its document each
/// half-edge is (`[face rank among live faces, index in face_halfedges]`, by half-edge id): the
/// numbering of [`PortalgonDoc::from_triangulation`]'s polygons and pairs.
struct TriangulationSides {
    faces: Vec<surftopo_mesh::FaceId>,
    edges: Vec<surftopo_mesh::EdgeId>,
    side: Vec<[u32; 2]>,
}

impl TriangulationSides {
    fn new(tri: &IntrinsicTriangulation) -> Self {
        let mesh = tri.mesh();
        let faces: Vec<_> = mesh.faces().collect();
        let mut side = vec![[u32::MAX; 2]; mesh.halfedge_slots()];
        for (k, &f) in faces.iter().enumerate() {
            for (i, h) in mesh.face_halfedges(f).into_iter().enumerate() {
                side[h.idx()] = [k as u32, i as u32];
            }
        }
        Self {
            faces,
            edges: mesh.edges().collect(),
            side,
        }
    }

    /// Pair `k` of the matching: the `k`-th live edge, its half-edge `2k` first.
    fn pair(&self, k: usize) -> [[usize; 2]; 2] {
        let h = self.edges[k].halfedge();
        [h, h.twin()].map(|h| self.side[h.idx()].map(|x| x as usize))
    }
}

/// Polygons per block of the JSON writers ([`crate::formats::text_blocks`]): about half a megabyte of
/// triangles by lengths.
const POLYGONS_PER_BLOCK: usize = 4096;
/// Pairs of the matching per block: about a quarter of a megabyte.
const PAIRS_PER_BLOCK: usize = 8192;

/// Writes the compact JSON of a portalgon document by hand, polygons and pairs formatted in
/// blocks on several threads ([`crate::formats::text_blocks`]): the header, `polygon(p, buf)` appending
/// polygon `p`'s object for each `p < polygons`, then the pairs `pair(k)`. Bytes are those of
/// `serde_json::to_writer` on the [`PortalgonDoc`] (numbers by the same shortest round-trip
/// formatting, [`surftopo_mesh::decimal`]); callers check finiteness first.
fn write_compact<W: Write>(
    mut out: W,
    version: u32,
    comment: Option<&str>,
    polygons: usize,
    polygon: impl Fn(usize, &mut Vec<u8>) + Sync,
    pairs: usize,
    pair: impl Fn(usize) -> ([[usize; 2]; 2], bool) + Sync,
) -> Result<(), PortalgonError> {
    let mut head = Vec::new();
    head.extend_from_slice(b"{\"format\":");
    serde_json::to_writer(&mut head, FORMAT_NAME).map_err(|e| json_error(&e))?;
    head.extend_from_slice(b",\"version\":");
    push_u64(&mut head, u64::from(version));
    if let Some(c) = comment {
        head.extend_from_slice(b",\"comment\":");
        serde_json::to_writer(&mut head, c).map_err(|e| json_error(&e))?;
    }
    head.extend_from_slice(b",\"polygons\":[");
    out.write_all(&head).map_err(io_error)?;
    let polygon_blocks = block_count(polygons, POLYGONS_PER_BLOCK);
    let pair_blocks = block_count(pairs, PAIRS_PER_BLOCK);
    // Block `polygon_blocks` is the text between the polygons and the pairs.
    write_blocks(&mut out, polygon_blocks + 1 + pair_blocks, |k, buf| {
        if k < polygon_blocks {
            for p in block_range(k, POLYGONS_PER_BLOCK, polygons) {
                if p > 0 {
                    buf.push(b',');
                }
                polygon(p, buf);
            }
        } else if k == polygon_blocks {
            buf.extend_from_slice(b"],\"matching\":[");
        } else {
            for e in block_range(k - polygon_blocks - 1, PAIRS_PER_BLOCK, pairs) {
                if e > 0 {
                    buf.push(b',');
                }
                let ([a, b], reversed) = pair(e);
                push_pair(buf, a, b);
                if reversed {
                    buf.pop();
                    buf.extend_from_slice(b",true]");
                }
            }
        }
    })
    .map_err(io_error)?;
    out.write_all(b"]}\n")
        .and_then(|()| out.flush())
        .map_err(io_error)
}

/// `[[p,i],[q,j]]`; the side indices of triangles (below 10) with the punctuation around them.
fn push_pair(buf: &mut Vec<u8>, [p, i]: [usize; 2], [q, j]: [usize; 2]) {
    buf.extend_from_slice(b"[[");
    push_u64(buf, p as u64);
    if i < 10 && j < 10 {
        buf.extend_from_slice(&[b',', b'0' + i as u8, b']', b',', b'[']);
        push_u64(buf, q as u64);
        buf.extend_from_slice(&[b',', b'0' + j as u8, b']', b']']);
        return;
    }
    buf.push(b',');
    push_u64(buf, i as u64);
    buf.extend_from_slice(b"],[");
    push_u64(buf, q as u64);
    buf.push(b',');
    push_u64(buf, j as u64);
    buf.extend_from_slice(b"]]");
}

/// A [`Number`]: a JSON number for a double or a decimal, a string for an exact rational.
fn push_number(buf: &mut Vec<u8>, x: &Number) {
    match x {
        Number::Double(v) => push_f64(buf, *v),
        other => buf.extend_from_slice(other.json_text().as_bytes()),
    }
}

/// `[a,b,...]`, `item` writing each element.
fn push_list<T>(buf: &mut Vec<u8>, items: &[T], mut item: impl FnMut(&mut Vec<u8>, &T)) {
    buf.push(b'[');
    for (i, x) in items.iter().enumerate() {
        if i > 0 {
            buf.push(b',');
        }
        item(buf, x);
    }
    buf.push(b']');
}

/// The object of one polygon, its fields in the order serde writes them.
fn push_polygon(buf: &mut Vec<u8>, polygon: &PolygonDoc) {
    buf.push(b'{');
    let mut first = true;
    let mut key = |buf: &mut Vec<u8>, name: &[u8]| {
        if !first {
            buf.push(b',');
        }
        first = false;
        buf.extend_from_slice(name);
    };
    if let Some(c) = &polygon.corners {
        key(buf, b"\"corners\":");
        push_list(buf, c, |buf, p| push_list(buf, p, push_number));
    }
    if let Some(l) = &polygon.lengths {
        key(buf, b"\"lengths\":");
        push_list(buf, l, push_number);
    }
    if let Some(v) = &polygon.vertices {
        key(buf, b"\"vertices\":");
        push_list(buf, v, |buf, &x| push_u64(buf, u64::from(x)));
    }
    buf.push(b'}');
}

/// The object of a triangle by lengths with its vertex labels, as [`push_polygon`] writes it.
fn push_triangle(buf: &mut Vec<u8>, lengths: [f64; 3], vertices: [u32; 3]) {
    buf.extend_from_slice(b"{\"lengths\":[");
    push_f64(buf, lengths[0]);
    buf.push(b',');
    push_f64(buf, lengths[1]);
    buf.push(b',');
    push_f64(buf, lengths[2]);
    buf.extend_from_slice(b"],\"vertices\":[");
    push_u64(buf, u64::from(vertices[0]));
    buf.push(b',');
    push_u64(buf, u64::from(vertices[1]));
    buf.push(b',');
    push_u64(buf, u64::from(vertices[2]));
    buf.extend_from_slice(b"]}");
}

fn io_error(e: std::io::Error) -> PortalgonError {
    PortalgonError::Io(e.to_string())
}

/// Whether what doubles hold of a polygon given by exact corners, of area `exact` (a positive
/// area: a polygon degenerate exactly is refused as such later), has area `rounded` within
/// [`Tolerances::exact_rounding`](crate::geometry::Tolerances::exact_rounding) of it.
///
/// # Errors
/// [`PortalgonError::BeyondDoubles`].
fn held_by_doubles(polygon: usize, exact: &Rational, rounded: f64) -> Result<(), PortalgonError> {
    if exact.sign() != std::cmp::Ordering::Greater {
        return Ok(());
    }
    let exact_area = exact.to_f64();
    let tolerance = crate::geometry::Tolerances::DEFAULT.exact_rounding;
    // NaN (not a triangle once rounded) fails the comparison too.
    if (rounded - exact_area).abs() <= tolerance * exact_area {
        Ok(())
    } else {
        Err(PortalgonError::BeyondDoubles {
            polygon,
            exact_area,
            rounded_area: rounded,
        })
    }
}

/// For a polygon read in double precision whose corners include an exact string (not a double,
/// not a number literal): its corners rounded to doubles are a valid polygon
/// ([`check_polygon`]) of its exact area ([`held_by_doubles`]). Corners all given as numbers
/// are doubles already: nothing to check.
///
/// # Errors
/// The polygon's own [`check_polygon`] error when it is invalid exactly;
/// [`PortalgonError::BeyondDoubles`] when only its rounding is.
fn corners_held_by_doubles(polygon: usize, corners: &[[Number; 2]]) -> Result<(), PortalgonError> {
    if corners.iter().flatten().all(Number::is_literal) {
        return Ok(());
    }
    let exact: Vec<Point<Rational>> = scalar_corners(polygon, corners)?;
    check_polygon(polygon, &exact)?;
    let rounded: Vec<Point<f64>> = scalar_corners(polygon, corners)?;
    let rounded_area = if check_polygon(polygon, &rounded).is_ok() {
        // The exact area of the rounded corners: only their rounding is measured.
        let as_rational = |x: &f64| Rational::from_f64(*x).expect("finite: checked");
        let r: Vec<Point<Rational>> = rounded
            .iter()
            .map(|p| p.each_ref().map(as_rational))
            .collect();
        crate::portalgon::signed_area(&r).to_f64()
    } else {
        f64::NAN
    };
    held_by_doubles(
        polygon,
        &crate::portalgon::signed_area(&exact),
        rounded_area,
    )
}

/// The corners of polygon `polygon` in the scalar type `S`.
fn scalar_corners<S: Scalar>(
    polygon: usize,
    corners: &[[Number; 2]],
) -> Result<Vec<Point<S>>, PortalgonError> {
    corners
        .iter()
        .enumerate()
        .map(|(index, c)| match (c[0].to_scalar(), c[1].to_scalar()) {
            (Some(x), Some(y)) => Ok([x, y]),
            _ => Err(PortalgonError::NonFinite { polygon, index }),
        })
        .collect()
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

    /// Writes this triangulation as a portalgon file: the bytes of
    /// [`PortalgonDoc::from_triangulation`]'s compact JSON; by lengths formatted from the mesh
    /// (in blocks, on several threads) without building the document.
    ///
    /// # Errors
    /// [`PortalgonError::Io`], [`PortalgonError::NonFinite`].
    pub fn write_json<W: Write>(
        &self,
        writer: W,
        style: TriangleStyle,
    ) -> Result<(), PortalgonError> {
        if style == TriangleStyle::Corners {
            return PortalgonDoc::from_triangulation(self, style).write(writer, false);
        }
        let mesh = self.mesh();
        let sides = TriangulationSides::new(self);
        if let Some((polygon, lengths)) = sides
            .faces
            .iter()
            .map(|&f| self.face_sides(f))
            .enumerate()
            .find(|(_, l)| !l.iter().all(|x| x.is_finite()))
        {
            let index = lengths.iter().position(|x| !x.is_finite()).unwrap_or(0);
            return Err(PortalgonError::NonFinite { polygon, index });
        }
        let (dense, _) = dense_vertex_index(self);
        write_compact(
            writer,
            ORIENTED_VERSION,
            None,
            sides.faces.len(),
            |p, buf| {
                let f = sides.faces[p];
                let vertices = mesh.face_halfedges(f).map(|h| dense[mesh.origin(h).idx()]);
                push_triangle(buf, self.face_sides(f), vertices);
            },
            sides.edges.len(),
            |k| (sides.pair(k), false),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::generators::{flat_torus, random_flips};

    /// The reference: serde_json's compact serialization of the document.
    fn serde_bytes(doc: &PortalgonDoc) -> Vec<u8> {
        let mut bytes = serde_json::to_vec(doc).unwrap();
        bytes.push(b'\n');
        bytes
    }

    #[test]
    fn hand_written_json_is_serde_json_byte_for_byte() {
        // 70: 9,800 triangles and 14,700 pairs, several blocks of each.
        let mut big = flat_torus(1.3, 70).unwrap();
        random_flips(&mut big, 3000, 11);
        let mut streamed = Vec::new();
        big.write_json(&mut streamed, TriangleStyle::Lengths)
            .unwrap();
        let doc = PortalgonDoc::from_triangulation(&big, TriangleStyle::Lengths);
        assert!(doc.polygons.len() > 2 * POLYGONS_PER_BLOCK);
        assert!(doc.matching.len() > PAIRS_PER_BLOCK);
        assert_eq!(streamed, serde_bytes(&doc));
        let mut tri = flat_torus(1.3, 5).unwrap();
        random_flips(&mut tri, 40, 7);
        for style in [TriangleStyle::Lengths, TriangleStyle::Corners] {
            let mut streamed = Vec::new();
            tri.write_json(&mut streamed, style).unwrap();
            let doc = PortalgonDoc::from_triangulation(&tri, style);
            assert_eq!(streamed, serde_bytes(&doc));
            let back = IntrinsicTriangulation::read_json(&streamed[..], 1e-9).unwrap();
            assert_eq!(back.mesh().face_count(), tri.mesh().face_count());
        }
        let mut doc = PortalgonDoc::from_triangulation(&tri, TriangleStyle::Lengths);
        doc.comment = Some("a \"quoted\"\nline\u{1}, é".into());
        doc.polygons[0].lengths = None;
        doc.polygons[0].corners = Some(vec![
            [Number::Double(0.0), Number::Double(-0.0)],
            [Number::Exact("1/3".parse().unwrap()), Number::Double(1e300)],
            [
                Number::Double(5e-324),
                Number::Exact("-7/3".parse().unwrap()),
            ],
        ]);
        doc.polygons[1].vertices = None;
        let mut written = Vec::new();
        doc.write(&mut written, false).unwrap();
        assert_eq!(written, serde_bytes(&doc));
        // Read back, the text is the same (1e300 and 5e-324 now as the decimals they spell,
        // with the same nearest doubles).
        let back = PortalgonDoc::from_json(std::str::from_utf8(&written).unwrap()).unwrap();
        assert_eq!(back.to_json().unwrap().as_bytes(), &written[..]);
        let corners = back.polygons[0].corners.as_ref().unwrap();
        assert_eq!(corners[1][1].to_f64(), 1e300);
        assert_eq!(corners[2][0].to_f64(), 5e-324);
        assert_eq!(
            corners[1][0],
            doc.polygons[0].corners.as_ref().unwrap()[1][0]
        );
    }

    #[test]
    fn non_finite_lengths_are_refused_before_writing() {
        let doc = PortalgonDoc::oriented(
            vec![PolygonDoc {
                lengths: Some(vec![1.0.into(), f64::NAN.into(), 1.0.into()]),
                ..PolygonDoc::default()
            }],
            Vec::new(),
        );
        let mut out = Vec::new();
        assert!(matches!(
            doc.write(&mut out, false),
            Err(PortalgonError::NonFinite {
                polygon: 0,
                index: 1
            })
        ));
        assert!(out.is_empty());
    }
}
