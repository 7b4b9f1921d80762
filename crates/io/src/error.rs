//! Typed errors: every variant names the file and, where it applies, the
//! 1-based line (text formats) or the byte offset (binary formats).

use std::fmt;

use crate::Format;

/// Where in a file an error was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// 1-based line number (text formats and headers).
    Line(u64),
    /// Byte offset from the start of the (decompressed) file (binary formats).
    Offset(u64),
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line(n) => write!(f, "{n}"),
            Location::Offset(n) => write!(f, "byte {n}"),
        }
    }
}

/// Error of a reader or writer.
///
/// Messages start lowercase and are self-contained, e.g.
/// `mesh.obj:123: face index 9 out of range (8 vertices)`.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum IoError {
    /// The operating system or the gzip decoder failed.
    #[error("{file}: {source}")]
    Io {
        /// File name.
        file: String,
        /// Underlying error.
        #[source]
        source: std::io::Error,
    },
    /// The path has no known mesh extension.
    #[error(
        "{path}: unsupported file extension (expected .obj, .off, .ply or .stl, optionally followed by .gz)"
    )]
    UnsupportedFormat {
        /// The path as given.
        path: String,
    },
    /// The content matches no mesh format ([`crate::sniff_format`]): an input whose name does
    /// not say its format (standard input, no mesh extension).
    #[error(
        "{file}: cannot tell the mesh format from the content: {reason}; give the input a file name with its \
         extension (.obj, .off, .ply or .stl, optionally followed by .gz)"
    )]
    UnknownContent {
        /// The input's name.
        file: String,
        /// Why no format's test matched.
        reason: String,
    },
    /// The format can be read but not written.
    #[error("writing {format} files is not supported")]
    UnsupportedWrite {
        /// The format asked for.
        format: Format,
    },
    /// The header (OFF keyword and counts, PLY header) is malformed or unsupported.
    #[error("{file}:{at}: bad header: {message}")]
    BadHeader {
        /// File name.
        file: String,
        /// Where.
        at: Location,
        /// What.
        message: String,
    },
    /// A malformed number, token or record.
    #[error("{file}:{at}: {message}")]
    Parse {
        /// File name.
        file: String,
        /// Where.
        at: Location,
        /// What.
        message: String,
    },
    /// The input ended before the data its header or syntax announced.
    #[error("{file}:{at}: unexpected end of file, expected {expected}")]
    UnexpectedEof {
        /// File name.
        file: String,
        /// Where the input ended (last line, or the offset of the missing data).
        at: Location,
        /// What was still expected.
        expected: String,
    },
    /// A face refers to a vertex that does not exist.
    #[error("{file}:{at}: face index {index} out of range ({vertex_count} vertices)")]
    IndexOutOfRange {
        /// File name.
        file: String,
        /// Where.
        at: Location,
        /// The index as written in the file (1-based or negative for OBJ).
        index: i64,
        /// Number of vertices it was checked against.
        vertex_count: u64,
    },
    /// A coordinate is NaN or infinite (or overflows to infinity).
    #[error("{file}:{at}: non-finite coordinate {value} of vertex {vertex}")]
    NonFinite {
        /// File name.
        file: String,
        /// Where.
        at: Location,
        /// The vertex (0-based, in file order; for STL, corner `3t + k` of facet `t`).
        vertex: u64,
        /// The value read.
        value: f64,
    },
    /// A face with fewer than 3 vertices.
    #[error("{file}:{at}: face with {sides} vertices (at least 3 needed)")]
    FaceTooSmall {
        /// File name.
        file: String,
        /// Where.
        at: Location,
        /// Number of vertices of the face.
        sides: u64,
    },
    /// A count exceeds what a polygon soup can hold (32-bit indices).
    #[error("{file}:{at}: {message}")]
    TooLarge {
        /// File name.
        file: String,
        /// Where.
        at: Location,
        /// What.
        message: String,
    },
    /// The (decompressed) input is longer than the limit it is read with
    /// ([`crate::ReadLimits::max_bytes`]); nothing beyond the limit was kept in memory.
    #[error("{file}: input larger than the limit of {limit} bytes (decompressed)")]
    InputTooLarge {
        /// File name.
        file: String,
        /// The limit, in bytes.
        limit: u64,
    },
    /// Memory for the input could not be reserved.
    #[error("{file}: cannot reserve {bytes} bytes of memory for the input")]
    OutOfMemory {
        /// File name.
        file: String,
        /// The reservation that failed.
        bytes: u64,
    },
    /// The input has no face: it is empty, not a mesh in this format, binary data in a text
    /// format (then `binary_at` is the offset of the first byte that no text file holds), or a
    /// point cloud (vertices without faces: then `points` holds them, with their attributes).
    #[error(
        "{file}: no faces{}{}",
        points.as_ref().map(|p| format!(": a point cloud of {} vertices", p.vertex_count())).unwrap_or_default(),
        binary_at.map(|at| format!(" (binary data at byte {at}: not a text mesh file)")).unwrap_or_default()
    )]
    NoFaces {
        /// File name.
        file: String,
        /// Offset of the first NUL or other binary control byte, if any.
        binary_at: Option<u64>,
        /// The vertices read, when there are some (a point cloud).
        points: Option<Box<crate::PolygonSoup>>,
    },
    /// The soup cannot be written with the options asked for (a coordinate beyond the range of
    /// `float` for [`crate::PlyPrecision::Float`]).
    #[error("cannot write: {message}")]
    Unrepresentable {
        /// What.
        message: String,
    },
    /// The soup given to a writer is inconsistent (bad offsets, index out of
    /// range, face with fewer than 3 vertices, non-finite coordinate).
    #[error("cannot write invalid polygon soup: {message}")]
    InvalidSoup {
        /// What.
        message: String,
    },
}

impl IoError {
    /// The file name the error refers to, if any.
    pub fn file(&self) -> Option<&str> {
        match self {
            IoError::Io { file, .. }
            | IoError::BadHeader { file, .. }
            | IoError::Parse { file, .. }
            | IoError::UnexpectedEof { file, .. }
            | IoError::IndexOutOfRange { file, .. }
            | IoError::NonFinite { file, .. }
            | IoError::FaceTooSmall { file, .. }
            | IoError::TooLarge { file, .. }
            | IoError::InputTooLarge { file, .. }
            | IoError::OutOfMemory { file, .. }
            | IoError::NoFaces { file, .. }
            | IoError::UnknownContent { file, .. } => Some(file),
            IoError::UnsupportedFormat { path } => Some(path),
            IoError::UnsupportedWrite { .. }
            | IoError::InvalidSoup { .. }
            | IoError::Unrepresentable { .. } => None,
        }
    }

    /// The line or byte offset the error refers to, if any.
    pub fn location(&self) -> Option<Location> {
        match self {
            IoError::BadHeader { at, .. }
            | IoError::Parse { at, .. }
            | IoError::UnexpectedEof { at, .. }
            | IoError::IndexOutOfRange { at, .. }
            | IoError::NonFinite { at, .. }
            | IoError::FaceTooSmall { at, .. }
            | IoError::TooLarge { at, .. } => Some(*at),
            _ => None,
        }
    }
}

/// Builds located errors for one file; keeps reader code short.
#[derive(Clone, Copy)]
pub(crate) struct Ctx<'n> {
    pub name: &'n str,
    /// What to do with a NaN or infinite coordinate.
    pub non_finite: crate::NonFinite,
}

impl<'n> Ctx<'n> {
    /// A context refusing non-finite coordinates.
    pub fn new(name: &'n str) -> Self {
        Ctx {
            name,
            non_finite: crate::NonFinite::Refuse,
        }
    }

    /// Whether non-finite coordinates are kept rather than refused.
    #[inline]
    pub fn keeps_non_finite(self) -> bool {
        self.non_finite == crate::NonFinite::Keep
    }

    /// `value`, the coordinate of vertex `vertex` read at `at`, unless it is non-finite and
    /// such coordinates are refused.
    #[inline]
    pub fn coordinate(self, at: Location, vertex: usize, value: f64) -> Result<f64, IoError> {
        if value.is_finite() || self.keeps_non_finite() {
            Ok(value)
        } else {
            Err(self.non_finite(at, vertex, value))
        }
    }

    #[cold]
    pub fn bad_header(self, at: Location, message: impl Into<String>) -> IoError {
        IoError::BadHeader {
            file: self.name.to_owned(),
            at,
            message: message.into(),
        }
    }

    #[cold]
    pub fn parse(self, at: Location, message: impl Into<String>) -> IoError {
        IoError::Parse {
            file: self.name.to_owned(),
            at,
            message: message.into(),
        }
    }

    #[cold]
    pub fn eof(self, at: Location, expected: impl Into<String>) -> IoError {
        IoError::UnexpectedEof {
            file: self.name.to_owned(),
            at,
            expected: expected.into(),
        }
    }

    #[cold]
    pub fn index(self, at: Location, index: i64, vertex_count: u64) -> IoError {
        IoError::IndexOutOfRange {
            file: self.name.to_owned(),
            at,
            index,
            vertex_count,
        }
    }

    #[cold]
    pub fn non_finite(self, at: Location, vertex: usize, value: f64) -> IoError {
        IoError::NonFinite {
            file: self.name.to_owned(),
            at,
            vertex: vertex as u64,
            value,
        }
    }

    #[cold]
    pub fn too_small(self, at: Location, sides: u64) -> IoError {
        IoError::FaceTooSmall {
            file: self.name.to_owned(),
            at,
            sides,
        }
    }

    #[cold]
    pub fn too_large(self, at: Location, message: impl Into<String>) -> IoError {
        IoError::TooLarge {
            file: self.name.to_owned(),
            at,
            message: message.into(),
        }
    }

    #[cold]
    pub fn io(self, source: std::io::Error) -> IoError {
        IoError::Io {
            file: self.name.to_owned(),
            source,
        }
    }
}
