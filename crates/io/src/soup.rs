//! The polygon soup: positions plus faces as flat index lists, no topology, and the attributes
//! read beside them ([`Attributes`]).

use crate::Format;
use crate::attributes::Attributes;

/// A polygon soup: positions and faces as index lists (0-based), faces stored flat.
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonSoup {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Concatenated vertex indices of all faces.
    pub face_indices: Vec<u32>,
    /// Face `k` is `face_indices[face_offsets[k] as usize..face_offsets[k + 1] as usize]`;
    /// length is the number of faces + 1 and it starts with 0.
    pub face_offsets: Vec<u32>,
    /// For each face, the 1-based line of the source file it came from (OBJ,
    /// ascii OFF/PLY/STL); empty when unknown (binary files, built in memory).
    pub face_lines: Vec<u32>,
    /// Texture coordinates, normals and other properties read beside positions (empty when
    /// none; see [`Attributes`]).
    pub attributes: Attributes,
}

/// What [`PolygonSoup::weld_exact`] merged.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Weld {
    /// Vertices merged into an earlier vertex of the same position.
    pub merged: usize,
    /// Of those, the vertices whose per-vertex attributes differed from the vertex they were
    /// merged into (theirs are dropped: the merged vertex keeps the first one's).
    pub conflicting: usize,
}

/// Error of [`PolygonSoup::triangles`]: a face that is not a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("face {face} has {sides} sides, not 3")]
pub struct NotTriangles {
    /// Index of the first non-triangular face.
    pub face: usize,
    /// Its number of vertices.
    pub sides: usize,
}

impl Default for PolygonSoup {
    fn default() -> Self {
        Self::new()
    }
}

impl PolygonSoup {
    /// An empty soup (no vertices, no faces).
    pub fn new() -> Self {
        PolygonSoup {
            positions: Vec::new(),
            face_indices: Vec::new(),
            face_offsets: vec![0],
            face_lines: Vec::new(),
            attributes: Attributes::default(),
        }
    }

    /// A soup of triangles.
    ///
    /// # Panics
    /// If there are more than `u32::MAX` indices in total.
    pub fn from_triangles(positions: Vec<[f64; 3]>, triangles: &[[u32; 3]]) -> Self {
        let mut soup = PolygonSoup {
            positions,
            face_indices: Vec::with_capacity(triangles.len() * 3),
            face_offsets: Vec::with_capacity(triangles.len() + 1),
            face_lines: Vec::new(),
            attributes: Attributes::default(),
        };
        soup.face_offsets.push(0);
        for t in triangles {
            soup.push_face(t);
        }
        soup
    }

    /// Number of vertices.
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of faces.
    pub fn face_count(&self) -> usize {
        self.face_offsets.len().saturating_sub(1)
    }

    /// Vertex indices of face `k`.
    ///
    /// # Panics
    /// If `k >= self.face_count()` or the offsets are inconsistent.
    pub fn face(&self, k: usize) -> &[u32] {
        let a = self.face_offsets[k] as usize;
        let b = self.face_offsets[k + 1] as usize;
        &self.face_indices[a..b]
    }

    /// Iterator over the faces' index lists.
    ///
    /// # Panics
    /// While iterating, if the offsets are inconsistent (see [`Self::validate`]).
    pub fn faces(&self) -> impl ExactSizeIterator<Item = &[u32]> + '_ {
        self.face_offsets
            .windows(2)
            .map(|w| &self.face_indices[w[0] as usize..w[1] as usize])
    }

    /// The 1-based source line of face `k`, when known.
    pub fn face_line(&self, k: usize) -> Option<u32> {
        self.face_lines.get(k).copied()
    }

    /// Appends a vertex and returns its index.
    ///
    /// # Panics
    /// If the index would not fit a `u32`.
    pub fn push_vertex(&mut self, p: [f64; 3]) -> u32 {
        let index = u32::try_from(self.positions.len()).expect("more than 2^32 vertices");
        self.positions.push(p);
        index
    }

    /// Appends a face (any number of vertices). Leaves `face_lines` alone.
    ///
    /// # Panics
    /// If the total number of indices would exceed `u32::MAX`.
    pub fn push_face(&mut self, face: &[u32]) {
        if self.face_offsets.is_empty() {
            self.face_offsets.push(0);
        }
        self.face_indices.extend_from_slice(face);
        let end = u32::try_from(self.face_indices.len()).expect("more than u32::MAX face indices");
        self.face_offsets.push(end);
    }

    /// True when every face has exactly 3 vertices.
    pub fn is_all_triangles(&self) -> bool {
        self.face_offsets
            .windows(2)
            .all(|w| w[1].wrapping_sub(w[0]) == 3)
    }

    /// The faces as triangles, or the first face that is not one.
    pub fn triangles(&self) -> Result<Vec<[u32; 3]>, NotTriangles> {
        let mut out = Vec::with_capacity(self.face_count());
        for (k, f) in self.faces().enumerate() {
            match *f {
                [a, b, c] => out.push([a, b, c]),
                _ => {
                    return Err(NotTriangles {
                        face: k,
                        sides: f.len(),
                    });
                }
            }
        }
        Ok(out)
    }

    /// Checks the invariants writers rely on: offsets start at 0, increase
    /// and end at `face_indices.len()`; every face has at least 3 vertices;
    /// every index is a vertex; every coordinate is finite; `face_lines` is
    /// empty or has one entry per face. Returns a description of the first
    /// violation.
    pub fn validate(&self) -> Result<(), String> {
        if self.face_offsets.is_empty() {
            if self.face_indices.is_empty() {
                return Ok(());
            }
            return Err("face_offsets is empty but face_indices is not".into());
        }
        if self.face_offsets[0] != 0 {
            return Err("face_offsets does not start with 0".into());
        }
        let last = *self.face_offsets.last().unwrap_or(&0) as usize;
        if last != self.face_indices.len() {
            return Err(format!(
                "face_offsets ends at {last} but there are {} face indices",
                self.face_indices.len()
            ));
        }
        for (k, w) in self.face_offsets.windows(2).enumerate() {
            if w[1] < w[0] {
                return Err(format!("face_offsets decreases at face {k}"));
            }
            if w[1] - w[0] < 3 {
                return Err(format!("face {k} has {} vertices", w[1] - w[0]));
            }
        }
        let n = self.positions.len();
        if let Some((i, &v)) = self
            .face_indices
            .iter()
            .enumerate()
            .find(|&(_, &v)| v as usize >= n)
        {
            return Err(format!(
                "face index {v} (position {i} in face_indices) out of range ({n} vertices)"
            ));
        }
        if let Some(i) = self
            .positions
            .iter()
            .position(|p| !p.iter().all(|c| c.is_finite()))
        {
            return Err(format!("vertex {i} has a non-finite coordinate"));
        }
        if !self.face_lines.is_empty() && self.face_lines.len() != self.face_count() {
            return Err(format!(
                "face_lines has {} entries for {} faces",
                self.face_lines.len(),
                self.face_count()
            ));
        }
        self.attributes
            .validate(self.positions.len(), self.face_indices.len())
    }

    /// What a writer of `format` leaves out of this soup's attributes, one description each
    /// (empty: nothing is lost; what the reader skipped is [`Attributes::not_kept`]).
    pub fn unwritable(&self, format: Format) -> Vec<String> {
        self.attributes.unwritable(format)
    }

    /// Merges vertices of exactly equal positions (`-0` equal to `0`;
    /// [`surftopo_mesh::geometry::weld_exact`]): faces are renumbered, per-vertex attributes
    /// follow their vertex, the merged vertex keeping the values of its first vertex; per-corner
    /// tables are unchanged (they follow the corners).
    pub fn weld_exact(&mut self) -> Weld {
        let (positions, map) = surftopo_mesh::geometry::weld_exact(&self.positions);
        let mut weld = Weld {
            merged: self.positions.len() - positions.len(),
            conflicting: 0,
        };
        if weld.merged == 0 {
            return weld;
        }
        for i in &mut self.face_indices {
            *i = map[*i as usize];
        }
        let mut first = vec![u32::MAX; positions.len()];
        for (old, &new) in map.iter().enumerate() {
            let slot = &mut first[new as usize];
            if *slot == u32::MAX {
                *slot = old as u32;
            } else if self
                .attributes
                .vertex
                .iter()
                .any(|p| p.values[old].to_bits() != p.values[*slot as usize].to_bits())
            {
                weld.conflicting += 1;
            }
        }
        let attributes = self.attributes.renumbered_vertices(positions.len(), |old| {
            (first[map[old] as usize] == old as u32).then_some(map[old] as usize)
        });
        self.attributes.vertex = attributes.vertex;
        self.positions = positions;
        weld
    }

    /// Appends a face during parsing; `None` if the index total overflows u32.
    #[inline]
    pub(crate) fn close_face(&mut self) -> Option<()> {
        let end = u32::try_from(self.face_indices.len()).ok()?;
        self.face_offsets.push(end);
        Some(())
    }
}
