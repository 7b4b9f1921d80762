//! Readers and writers for polygon soups (positions + faces, no topology).
//!
//! Reads OBJ, OFF, PLY (ascii, binary little/big endian, `face` and
//! `tristrips` elements) and STL (ascii, binary); writes OBJ, OFF, PLY (ascii or binary,
//! `double` or `float`: [`WriteOptions`]) and binary STL. Texture coordinates, normals, colours
//! and other vertex properties are kept beside positions ([`Attributes`]); a writer writes what
//! its format holds and [`PolygonSoup::unwritable`] says what it leaves out. Paths ending in
//! `.gz` are read and written through gzip; an input whose name does not say its format is told
//! by its content ([`sniff_format`], [`read_path_detected`]). Errors name the
//! file and the line (text) or byte offset (binary), with control characters
//! of quoted input escaped; no input makes a reader panic, loop forever or
//! allocate beyond what the input could hold. Files are read within
//! [`ReadLimits`] (decompressed bytes), growing buffers fallibly, so a gzip
//! bomb or an endless file is a typed error, never an abort; an input
//! without faces is [`IoError::NoFaces`] (holding the vertices of a point cloud).
//!
//! ```
//! use surftopo_io::{Format, PolygonSoup, WriteOptions};
//! let soup = PolygonSoup::from_triangles(
//!     vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
//!     &[[0, 1, 2]],
//! );
//! let mut bytes = Vec::new();
//! surftopo_io::write(&mut bytes, &soup, Format::Obj, &WriteOptions::default()).unwrap();
//! let back = surftopo_io::read(&bytes[..], Format::Obj, "memory.obj").unwrap();
//! assert_eq!(back.face(0), &[0, 1, 2]);
//! ```

mod attributes;
mod error;
mod format;
mod fs;
mod obj;
mod off;
mod out;
mod ply;
mod ply_write;
mod sniff;
mod soup;
mod stl;
mod text;

use std::io::{self, Read, Write};

pub use attributes::{
    Attributes, CornerTable, NORMAL_NAMES, ScalarType, TEXCOORD_NAMES, VertexProperty,
};
pub use error::{IoError, Location};
pub use format::{Format, is_gzip_path};
pub use fs::{
    DEFAULT_MAX_INPUT_BYTES, ReadLimits, StagedFile, atomic_write, decompress_gzip, load_path,
    load_reader, read_bytes_detected, read_path, read_path_detected, read_path_with,
    read_path_with_non_finite, remove_temporaries_then, stage_path, stage_path_as, stage_write,
    write_encoded, write_path,
};
pub use sniff::{is_gzip, sniff_format};
pub use soup::{NotTriangles, PolygonSoup, Weld};

use error::Ctx;

/// Encoding of written PLY files.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PlyEncoding {
    /// `binary_little_endian` (the default).
    #[default]
    BinaryLittleEndian,
    /// `binary_big_endian`.
    BinaryBigEndian,
    /// `ascii`.
    Ascii,
}

/// Precision of the floating-point values a PLY file is written with.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum PlyPrecision {
    /// Positions as `double`; properties with their own type (the default: reading back gives
    /// the same bits).
    #[default]
    Double,
    /// Positions and `double` properties as `float` (rounded to nearest: half the size, about
    /// 7 significant digits).
    Float,
}

/// Options of [`write()`] and [`write_path`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub struct WriteOptions {
    /// Encoding of PLY output.
    pub ply_encoding: PlyEncoding,
    /// Float precision of PLY output.
    pub ply_precision: PlyPrecision,
    /// gzip level 0..=9 for `.gz` paths (default 6).
    pub gzip_level: u32,
}

impl Default for WriteOptions {
    fn default() -> Self {
        WriteOptions {
            ply_encoding: PlyEncoding::BinaryLittleEndian,
            ply_precision: PlyPrecision::Double,
            gzip_level: 6,
        }
    }
}

impl WriteOptions {
    /// Options with the given PLY encoding.
    pub fn with_ply_encoding(mut self, encoding: PlyEncoding) -> Self {
        self.ply_encoding = encoding;
        self
    }

    /// Options with the given PLY float precision.
    pub fn with_ply_precision(mut self, precision: PlyPrecision) -> Self {
        self.ply_precision = precision;
        self
    }

    /// Options with the given gzip level (clamped to 0..=9).
    pub fn with_gzip_level(mut self, level: u32) -> Self {
        self.gzip_level = level.min(9);
        self
    }
}

/// Parses a mesh file held in memory (uncompressed).
///
/// `bytes`: the whole file; `format`: how to parse it; `name`: the file name
/// used in error messages. Errors carry the 1-based line (text) or byte
/// offset (binary) of the problem; an input without a single face (empty,
/// another format, binary data in a text format) is [`IoError::NoFaces`].
pub fn read_bytes(bytes: &[u8], format: Format, name: &str) -> Result<PolygonSoup, IoError> {
    read_bytes_with(bytes, format, name, NonFinite::Refuse)
}

/// What a reader does with a coordinate that is NaN or infinite (or overflows to infinity).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum NonFinite {
    /// Stop with [`IoError::NonFinite`], naming the file, the line or byte offset and the
    /// vertex (the default: no algorithm can use such a vertex).
    #[default]
    Refuse,
    /// Keep the value in the soup, for a caller that reports such vertices among other problems
    /// (`surftopo info`); what consumes the soup must check the coordinates itself.
    Keep,
}

/// [`read_bytes`], with `non_finite` saying whether NaN and infinite coordinates are refused
/// or kept.
pub fn read_bytes_with(
    bytes: &[u8],
    format: Format,
    name: &str,
    non_finite: NonFinite,
) -> Result<PolygonSoup, IoError> {
    let ctx = Ctx { name, non_finite };
    let soup = match format {
        Format::Obj => obj::read(bytes, ctx),
        Format::Off => off::read(bytes, ctx),
        Format::Ply => ply::read(bytes, ctx),
        Format::Stl => stl::read(bytes, ctx),
    }?;
    if soup.face_count() == 0 {
        let text = matches!(format, Format::Obj | Format::Off);
        let binary_at = text.then(|| first_binary_byte(bytes)).flatten();
        let points = (soup.vertex_count() > 0 && binary_at.is_none()).then(|| Box::new(soup));
        return Err(IoError::NoFaces {
            file: name.to_owned(),
            binary_at,
            points,
        });
    }
    Ok(soup)
}

/// Offset of the first byte no text file holds: NUL or a C0 control other than tab, newline,
/// vertical tab, form feed and carriage return.
fn first_binary_byte(bytes: &[u8]) -> Option<u64> {
    bytes
        .iter()
        .position(|&b| b < 0x20 && !matches!(b, b'\t' | b'\n' | 0x0b | 0x0c | b'\r'))
        .map(|i| i as u64)
}

/// Reads a whole (uncompressed) stream and parses it.
///
/// `reader`: the file's bytes (read to the end; any `BufRead` or `Read`,
/// e.g. `&[u8]` or a `File`); `format`: how to parse it; `name`: the file
/// name used in error messages. At most [`DEFAULT_MAX_INPUT_BYTES`] are read
/// ([`IoError::InputTooLarge`] beyond).
pub fn read(reader: impl Read, format: Format, name: &str) -> Result<PolygonSoup, IoError> {
    let mut bytes = Vec::new();
    reader
        .take(DEFAULT_MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| Ctx::new(name).io(e))?;
    if bytes.len() as u64 > DEFAULT_MAX_INPUT_BYTES {
        return Err(IoError::InputTooLarge {
            file: name.to_owned(),
            limit: DEFAULT_MAX_INPUT_BYTES,
        });
    }
    read_bytes(&bytes, format, name)
}

/// Writes the soup in `format`, uncompressed.
///
/// `writer`: the destination (buffered internally); `soup`: what to write;
/// `format`: OBJ, OFF, PLY or (binary) STL; `options`: PLY encoding (gzip
/// level is only used by [`write_path`]). Fails with [`IoError::InvalidSoup`]
/// before writing anything if the soup is inconsistent (see
/// [`PolygonSoup::validate`]), and with [`IoError::Io`] (file `<writer>`) if
/// the writer fails (or an STL would have more than 2^32 - 1 triangles).
pub fn write(
    writer: impl Write,
    soup: &PolygonSoup,
    format: Format,
    options: &WriteOptions,
) -> Result<(), IoError> {
    check_writable(soup, format, options)?;
    write_unchecked(writer, soup, format, options)
        .map(drop)
        .map_err(|e| Ctx::new("<writer>").io(e))
}

fn check_writable(
    soup: &PolygonSoup,
    format: Format,
    options: &WriteOptions,
) -> Result<(), IoError> {
    if !format.can_write() {
        return Err(IoError::UnsupportedWrite { format });
    }
    soup.validate()
        .map_err(|message| IoError::InvalidSoup { message })?;
    if format == Format::Ply && options.ply_precision == PlyPrecision::Float {
        let too_large = |x: f64| x.is_finite() && (x as f32).is_infinite();
        if let Some(v) = soup
            .positions
            .iter()
            .position(|p| p.iter().any(|&c| too_large(c)))
        {
            return Err(IoError::Unrepresentable {
                message: format!("vertex {v} has a coordinate beyond the range of a float"),
            });
        }
    }
    Ok(())
}

fn write_unchecked<W: Write>(
    writer: W,
    soup: &PolygonSoup,
    format: Format,
    options: &WriteOptions,
) -> io::Result<W> {
    match format {
        Format::Obj => obj::write(writer, soup),
        Format::Off => off::write(writer, soup),
        Format::Ply => ply_write::write(writer, soup, options),
        Format::Stl => stl::write(writer, soup),
    }
}
