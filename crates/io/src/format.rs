//! File formats and their detection from a path's extension.

use std::fmt;
use std::path::Path;

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// Wavefront OBJ (read and write).
    Obj,
    /// Geomview OFF, ascii (read and write).
    Off,
    /// Stanford PLY, ascii or binary (read and write).
    Ply,
    /// STL, ascii or binary (read; written binary).
    Stl,
}

impl Format {
    /// All formats.
    pub const ALL: [Format; 4] = [Format::Obj, Format::Off, Format::Ply, Format::Stl];

    /// Format from a file extension without the dot (case-insensitive).
    pub fn from_extension(ext: &str) -> Option<Format> {
        Some(match ext.to_ascii_lowercase().as_str() {
            "obj" => Format::Obj,
            "off" => Format::Off,
            "ply" => Format::Ply,
            "stl" => Format::Stl,
            _ => return None,
        })
    }

    /// Format from a path's extension, ignoring a trailing `.gz`
    /// (case-insensitive): `mesh.OBJ.gz` is OBJ.
    pub fn from_path(path: &Path) -> Option<Format> {
        let name = path.file_name()?.to_string_lossy().to_ascii_lowercase();
        let name = name.strip_suffix(".gz").unwrap_or(&name);
        let (_, ext) = name.rsplit_once('.')?;
        Format::from_extension(ext)
    }

    /// The usual extension (lowercase, no dot).
    pub fn extension(self) -> &'static str {
        match self {
            Format::Obj => "obj",
            Format::Off => "off",
            Format::Ply => "ply",
            Format::Stl => "stl",
        }
    }

    /// True when [`crate::write()`] supports the format: every format (STL is written binary).
    pub fn can_write(self) -> bool {
        true
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Format::Obj => "OBJ",
            Format::Off => "OFF",
            Format::Ply => "PLY",
            Format::Stl => "STL",
        })
    }
}

/// True when the path ends in `.gz` (case-insensitive): read and written
/// through gzip.
pub fn is_gzip_path(path: &Path) -> bool {
    path.file_name()
        .is_some_and(|n| n.to_string_lossy().to_ascii_lowercase().ends_with(".gz"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn detection() {
        assert_eq!(Format::from_path(Path::new("a/b.OBJ")), Some(Format::Obj));
        assert_eq!(Format::from_path(Path::new("x.off.GZ")), Some(Format::Off));
        assert_eq!(Format::from_path(Path::new("x.tar.gz")), None);
        assert_eq!(Format::from_path(Path::new("ply")), None);
        assert_eq!(Format::from_path(Path::new(".gz")), None);
        assert!(is_gzip_path(Path::new("m.ply.gz")));
        assert!(!is_gzip_path(Path::new("m.ply")));
    }
}
