//! Attributes a polygon soup carries beside positions and faces: per-vertex scalar properties
//! (PLY properties beyond `x y z`; OBJ `vt`/`vn` when each vertex has one) and OBJ's per-corner
//! texture coordinates and normals (when a vertex's corners use different ones).
//!
//! Representation, chosen so that every reader's attributes survive a write to its own format
//! and a command that keeps the vertex list can carry them by renumbering alone:
//! - [`VertexProperty`]: a named column of one value per vertex, with the scalar type it is
//!   written with (PLY: as read; OBJ `vt`/`vn`: `double`). Values are stored as `f64`, which
//!   holds every PLY scalar type exactly. Texture coordinates are the pair `u v`, `s t` or
//!   `texture_u texture_v`; normals `nx ny nz`; colours `red green blue [alpha]`
//!   ([`Attributes::vertex_texcoords`], [`Attributes::vertex_normals`]).
//! - [`CornerTable`]: OBJ's `vt` (or `vn`) lines as read and, for every face corner (parallel
//!   to `face_indices`), the line it refers to. The OBJ reader turns a table into per-vertex
//!   properties when that loses nothing: every corner has an entry, the corners of each vertex
//!   agree, every vertex has a corner and every line is referenced; or, when no face refers to
//!   any line, when there is exactly one line per vertex (the convention of writers that list
//!   one `vn` per `v`).
//! - [`Attributes::not_kept`]: what a reader read past without keeping (PLY list properties of
//!   the vertex element, other elements' properties, OBJ statements other than `v vt vn f`),
//!   so that a caller can say so.
//!
//! Writers write what their format holds and leave out the rest;
//! [`PolygonSoup::unwritable`](crate::PolygonSoup::unwritable) describes what that is.

use crate::Format;

/// Scalar type of a vertex property, named as PLY names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ScalarType {
    /// `char` (`int8`).
    I8,
    /// `uchar` (`uint8`).
    U8,
    /// `short` (`int16`).
    I16,
    /// `ushort` (`uint16`).
    U16,
    /// `int` (`int32`).
    I32,
    /// `uint` (`uint32`).
    U32,
    /// `float` (`float32`).
    F32,
    /// `double` (`float64`).
    F64,
}

impl ScalarType {
    /// The type of a PLY type name (`uchar`, `uint8`, `float`, ...).
    pub fn from_ply_name(s: &[u8]) -> Option<Self> {
        Some(match s {
            b"char" | b"int8" => ScalarType::I8,
            b"uchar" | b"uint8" => ScalarType::U8,
            b"short" | b"int16" => ScalarType::I16,
            b"ushort" | b"uint16" => ScalarType::U16,
            b"int" | b"int32" => ScalarType::I32,
            b"uint" | b"uint32" => ScalarType::U32,
            b"float" | b"float32" => ScalarType::F32,
            b"double" | b"float64" => ScalarType::F64,
            _ => return None,
        })
    }

    /// The PLY type name written (`char`, `uchar`, ..., `float`, `double`).
    pub fn ply_name(self) -> &'static str {
        match self {
            ScalarType::I8 => "char",
            ScalarType::U8 => "uchar",
            ScalarType::I16 => "short",
            ScalarType::U16 => "ushort",
            ScalarType::I32 => "int",
            ScalarType::U32 => "uint",
            ScalarType::F32 => "float",
            ScalarType::F64 => "double",
        }
    }

    /// Size in bytes of a binary value.
    pub fn size(self) -> usize {
        match self {
            ScalarType::I8 | ScalarType::U8 => 1,
            ScalarType::I16 | ScalarType::U16 => 2,
            ScalarType::I32 | ScalarType::U32 | ScalarType::F32 => 4,
            ScalarType::F64 => 8,
        }
    }

    /// True for the integer types.
    pub fn is_int(self) -> bool {
        !matches!(self, ScalarType::F32 | ScalarType::F64)
    }

    /// The range of an integer type (`None` for floats).
    fn int_range(self) -> Option<(f64, f64)> {
        Some(match self {
            ScalarType::I8 => (f64::from(i8::MIN), f64::from(i8::MAX)),
            ScalarType::U8 => (0.0, f64::from(u8::MAX)),
            ScalarType::I16 => (f64::from(i16::MIN), f64::from(i16::MAX)),
            ScalarType::U16 => (0.0, f64::from(u16::MAX)),
            ScalarType::I32 => (f64::from(i32::MIN), f64::from(i32::MAX)),
            ScalarType::U32 => (0.0, f64::from(u32::MAX)),
            ScalarType::F32 | ScalarType::F64 => return None,
        })
    }

    /// True when `value` is exactly representable (integers: whole and in range; `float`:
    /// rounding to f32 keeps it, or it is not finite).
    pub fn holds(self, value: f64) -> bool {
        match self.int_range() {
            Some((lo, hi)) => value.fract() == 0.0 && (lo..=hi).contains(&value),
            None => {
                self == ScalarType::F64 || !value.is_finite() || f64::from(value as f32) == value
            }
        }
    }
}

/// A named per-vertex scalar property: one value per vertex.
#[derive(Clone, Debug, PartialEq)]
pub struct VertexProperty {
    /// Its name (PLY property name; `u`/`v`, `nx`/`ny`/`nz` for OBJ `vt`/`vn`).
    pub name: String,
    /// The type it is written with; every value is representable in it
    /// ([`ScalarType::holds`]), except that `float` values may be any `f64` (they are rounded
    /// when written).
    pub scalar: ScalarType,
    /// One value per vertex.
    pub values: Vec<f64>,
}

/// Per-corner values indexed through a table: OBJ `vt` or `vn` lines referred to by faces.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CornerTable {
    /// Numbers per entry (`vt`: 1 to 3, the largest count of any line, missing ones 0; `vn`: 3).
    pub width: usize,
    /// The entries, `width` numbers each, in file order.
    pub values: Vec<f64>,
    /// For each face corner (parallel to `PolygonSoup::face_indices`), its entry, or
    /// [`CornerTable::NONE`].
    pub corners: Vec<u32>,
}

impl CornerTable {
    /// A corner without an entry.
    pub const NONE: u32 = u32::MAX;

    /// Number of entries.
    pub fn len(&self) -> usize {
        self.values.len().checked_div(self.width).unwrap_or(0)
    }

    /// True when the table has no entry.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Entry `k`.
    ///
    /// # Panics
    /// If `k >= self.len()`.
    pub fn entry(&self, k: usize) -> &[f64] {
        &self.values[k * self.width..(k + 1) * self.width]
    }

    /// The entry of each vertex when the table is per-vertex in disguise (see the module
    /// documentation): `Some(entry of vertex v)` for every `v`, else `None`.
    pub(crate) fn per_vertex(&self, face_indices: &[u32], vertex_count: usize) -> Option<Vec<u32>> {
        let entries = self.len();
        if !self.corners.iter().any(|&c| c != Self::NONE) {
            return (entries == vertex_count).then(|| (0..vertex_count as u32).collect());
        }
        let mut of_vertex = vec![Self::NONE; vertex_count];
        let mut referenced = vec![false; entries];
        for (&v, &c) in face_indices.iter().zip(&self.corners) {
            if c == Self::NONE {
                return None;
            }
            let slot = &mut of_vertex[v as usize];
            if *slot == Self::NONE {
                *slot = c;
            } else if *slot != c {
                return None;
            }
            referenced[c as usize] = true;
        }
        let complete = of_vertex.iter().all(|&c| c != Self::NONE) && referenced.iter().all(|&r| r);
        complete.then_some(of_vertex)
    }
}

/// True when `name` can name a vertex property in every writer: not empty, no blank or control
/// character.
pub(crate) fn is_valid_name(name: &str) -> bool {
    !name.is_empty() && !name.chars().any(|c| c.is_whitespace() || c.is_control())
}

/// The attributes of a polygon soup (see the module documentation).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Attributes {
    /// Per-vertex properties, in file order.
    pub vertex: Vec<VertexProperty>,
    /// OBJ texture coordinates per face corner (`f v/vt`), when they are not per-vertex.
    pub corner_texcoords: Option<CornerTable>,
    /// OBJ normals per face corner (`f v//vn`), when they are not per-vertex.
    pub corner_normals: Option<CornerTable>,
    /// What the reader skipped, one description each (e.g. `PLY face property 'red'`).
    pub not_kept: Vec<String>,
}

/// Names of the per-vertex texture coordinate pairs, in the order they are looked for.
pub const TEXCOORD_NAMES: [[&str; 2]; 3] = [["u", "v"], ["s", "t"], ["texture_u", "texture_v"]];
/// Names of the per-vertex normal components.
pub const NORMAL_NAMES: [&str; 3] = ["nx", "ny", "nz"];

impl Attributes {
    /// True when there is nothing beyond positions and faces (and nothing was skipped).
    pub fn is_empty(&self) -> bool {
        self.vertex.is_empty()
            && self.corner_texcoords.is_none()
            && self.corner_normals.is_none()
            && self.not_kept.is_empty()
    }

    /// Index of the vertex property called `name`.
    pub fn vertex_property(&self, name: &str) -> Option<usize> {
        self.vertex.iter().position(|p| p.name == name)
    }

    /// Indices of the per-vertex texture coordinates ([`TEXCOORD_NAMES`], first pair found).
    pub fn vertex_texcoords(&self) -> Option<[usize; 2]> {
        TEXCOORD_NAMES
            .iter()
            .find_map(|[u, v]| Some([self.vertex_property(u)?, self.vertex_property(v)?]))
    }

    /// Indices of the per-vertex normals (`nx ny nz`).
    pub fn vertex_normals(&self) -> Option<[usize; 3]> {
        let [x, y, z] = NORMAL_NAMES.map(|n| self.vertex_property(n));
        Some([x?, y?, z?])
    }

    /// The per-vertex properties OBJ writes as `vt` (when there is no per-corner table): the
    /// texture coordinate pair, and `w` beside `u v`.
    pub(crate) fn obj_vt_columns(&self) -> Option<Vec<usize>> {
        if self.corner_texcoords.is_some() {
            return None;
        }
        let uv = self.vertex_texcoords()?;
        let mut columns = uv.to_vec();
        if self.vertex[uv[0]].name == "u"
            && let Some(w) = self.vertex_property("w")
        {
            columns.push(w);
        }
        Some(columns)
    }

    /// The per-vertex properties OFF writes as a colour (`red green blue [alpha]`, all of one
    /// type: integers 0 to 255 or floats).
    pub(crate) fn off_colour_columns(&self) -> Option<Vec<usize>> {
        let mut columns = Vec::new();
        for name in ["red", "green", "blue"] {
            columns.push(self.vertex_property(name)?);
        }
        columns.extend(self.vertex_property("alpha"));
        let scalar = self.vertex[columns[0]].scalar;
        let uniform = columns.iter().all(|&c| {
            let s = self.vertex[c].scalar;
            s == scalar && matches!(s, ScalarType::U8 | ScalarType::F32 | ScalarType::F64)
        });
        uniform.then_some(columns)
    }

    /// The per-vertex properties OBJ writes as `vn` (when there is no per-corner table).
    pub(crate) fn obj_vn_columns(&self) -> Option<[usize; 3]> {
        if self.corner_normals.is_some() {
            return None;
        }
        self.vertex_normals()
    }

    /// The per-vertex properties renumbered: new vertex `new_of(old)`'s values are old vertex
    /// `old`'s (`None`: the old vertex is gone); `new_count` vertices. The per-corner tables and
    /// `not_kept` are left out: the caller knows whether its faces still match them.
    pub fn renumbered_vertices(
        &self,
        new_count: usize,
        new_of: impl Fn(usize) -> Option<usize>,
    ) -> Attributes {
        let vertex = self
            .vertex
            .iter()
            .map(|p| {
                let mut values = vec![0.0; new_count];
                for (old, &x) in p.values.iter().enumerate() {
                    if let Some(new) = new_of(old) {
                        values[new] = x;
                    }
                }
                VertexProperty {
                    name: p.name.clone(),
                    scalar: p.scalar,
                    values,
                }
            })
            .collect();
        Attributes {
            vertex,
            ..Attributes::default()
        }
    }

    /// Descriptions of the per-corner tables (for a warning that they were dropped).
    pub fn corner_descriptions(&self) -> Vec<String> {
        let mut out = Vec::new();
        for (table, what) in [
            (&self.corner_texcoords, "texture coordinates (vt)"),
            (&self.corner_normals, "normals (vn)"),
        ] {
            if let Some(t) = table {
                let corners = t
                    .corners
                    .iter()
                    .filter(|&&c| c != CornerTable::NONE)
                    .count();
                out.push(format!(
                    "per-corner {what}: {} values on {corners} face corners",
                    t.len()
                ));
            }
        }
        out
    }

    /// Checks the attributes against a soup of `vertex_count` vertices and `corner_count` face
    /// corners: one value per vertex, names unique, non-empty and without blanks, integer values
    /// representable in their type, corner tables of one entry per corner and indices in range.
    pub(crate) fn validate(&self, vertex_count: usize, corner_count: usize) -> Result<(), String> {
        for (i, p) in self.vertex.iter().enumerate() {
            if p.values.len() != vertex_count {
                return Err(format!(
                    "vertex property '{}' has {} values for {vertex_count} vertices",
                    p.name,
                    p.values.len()
                ));
            }
            if !is_valid_name(&p.name) {
                return Err(format!("vertex property {i} has the name {:?}", p.name));
            }
            if matches!(&p.name[..], "x" | "y" | "z")
                || self.vertex[..i].iter().any(|q| q.name == p.name)
            {
                return Err(format!("vertex property '{}' is named twice", p.name));
            }
            if p.scalar.is_int()
                && let Some(v) = p.values.iter().position(|&x| !p.scalar.holds(x))
            {
                return Err(format!(
                    "vertex property '{}' of vertex {v}: {} is not a {}",
                    p.name,
                    p.values[v],
                    p.scalar.ply_name()
                ));
            }
        }
        for (table, what) in [
            (&self.corner_texcoords, "texture coordinate"),
            (&self.corner_normals, "normal"),
        ] {
            let Some(t) = table else { continue };
            if t.width == 0 || t.width > 3 || t.values.len() % t.width != 0 {
                return Err(format!(
                    "per-corner {what} table of width {} holds {} numbers",
                    t.width,
                    t.values.len()
                ));
            }
            if t.corners.len() != corner_count {
                return Err(format!(
                    "per-corner {what} table has {} corners for {corner_count}",
                    t.corners.len()
                ));
            }
            let n = t.len();
            if let Some(&c) = t
                .corners
                .iter()
                .find(|&&c| c != CornerTable::NONE && c as usize >= n)
            {
                return Err(format!(
                    "per-corner {what} index {c} out of range ({n} entries)"
                ));
            }
        }
        Ok(())
    }

    /// What a writer of `format` leaves out, one description each (empty: nothing).
    pub fn unwritable(&self, format: Format) -> Vec<String> {
        let mut out = Vec::new();
        let name_list = |props: &[&VertexProperty]| {
            props
                .iter()
                .map(|p| p.name.as_str())
                .collect::<Vec<_>>()
                .join(" ")
        };
        let count = self.vertex.first().map_or(0, |p| p.values.len());
        let kept: Vec<usize> = match format {
            Format::Obj => {
                let mut kept = self.obj_vt_columns().unwrap_or_default();
                kept.extend(self.obj_vn_columns().into_iter().flatten());
                kept
            }
            Format::Ply => (0..self.vertex.len()).collect(),
            Format::Off => self.off_colour_columns().unwrap_or_default(),
            Format::Stl => Vec::new(),
        };
        let dropped: Vec<&VertexProperty> = (0..self.vertex.len())
            .filter(|i| !kept.contains(i))
            .map(|i| &self.vertex[i])
            .collect();
        if !dropped.is_empty() {
            out.push(format!(
                "per-vertex {} ({count} vertices): {format} cannot hold them",
                name_list(&dropped),
            ));
        }
        if format != Format::Obj {
            for d in self.corner_descriptions() {
                out.push(format!("{d}: {format} cannot hold per-corner values"));
            }
        }
        out
    }
}
