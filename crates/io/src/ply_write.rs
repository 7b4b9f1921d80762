//! PLY writer: x, y, z (`double`, or `float` with [`PlyPrecision::Float`]), then every
//! per-vertex property of the soup's [`Attributes`](crate::Attributes) with its own type (a
//! `double` property becomes `float` with [`PlyPrecision::Float`]), and a `vertex_indices` list
//! per face; ascii or binary (little or big endian). Per-corner tables are not written (PLY has
//! no standard per-corner property; [`crate::PolygonSoup::unwritable`] reports them).

use std::io::{self, Write};

use crate::out::Out;
use crate::soup::PolygonSoup;
use crate::{PlyEncoding, PlyPrecision, ScalarType, WriteOptions};

/// Writes the soup as PLY with the given encoding and precision.
pub(crate) fn write<W: Write>(w: W, soup: &PolygonSoup, options: &WriteOptions) -> io::Result<W> {
    let (enc, precision) = (options.ply_encoding, options.ply_precision);
    let mut out = Out::new(w);
    // Face sizes up to 255 fit a `uchar` count.
    let wide = soup.faces().any(|f| f.len() > 255);
    let position = match precision {
        PlyPrecision::Double => ScalarType::F64,
        PlyPrecision::Float => ScalarType::F32,
    };
    let columns: Vec<(ScalarType, &[f64])> = soup
        .attributes
        .vertex
        .iter()
        .map(|p| {
            let scalar = match (p.scalar, precision) {
                (ScalarType::F64, PlyPrecision::Float) => ScalarType::F32,
                (s, _) => s,
            };
            (scalar, &p.values[..])
        })
        .collect();
    out.bytes(b"ply\nformat ");
    out.bytes(match enc {
        PlyEncoding::Ascii => b"ascii",
        PlyEncoding::BinaryLittleEndian => b"binary_little_endian",
        PlyEncoding::BinaryBigEndian => b"binary_big_endian",
    });
    out.bytes(b" 1.0\nelement vertex ");
    out.u64(soup.positions.len() as u64);
    out.byte(b'\n');
    for axis in ["x", "y", "z"] {
        property_line(&mut out, position, axis);
    }
    for (p, &(scalar, _)) in soup.attributes.vertex.iter().zip(&columns) {
        property_line(&mut out, scalar, &p.name);
    }
    out.bytes(b"element face ");
    out.u64(soup.face_count() as u64);
    out.bytes(if wide {
        b"\nproperty list uint uint vertex_indices\nend_header\n"
    } else {
        b"\nproperty list uchar uint vertex_indices\nend_header\n"
    });
    match enc {
        PlyEncoding::Ascii => {
            for (v, p) in soup.positions.iter().enumerate() {
                for (k, &c) in p.iter().enumerate() {
                    if k > 0 {
                        out.byte(b' ');
                    }
                    ascii_value(&mut out, position, c);
                }
                for &(scalar, values) in &columns {
                    out.byte(b' ');
                    ascii_value(&mut out, scalar, values[v]);
                }
                out.byte(b'\n');
                out.flush_if_full()?;
            }
            for f in soup.faces() {
                out.u64(f.len() as u64);
                out.index_line(f, 0)?;
            }
        }
        PlyEncoding::BinaryLittleEndian => {
            binary::<W, false>(&mut out, soup, wide, position, &columns)?
        }
        PlyEncoding::BinaryBigEndian => {
            binary::<W, true>(&mut out, soup, wide, position, &columns)?
        }
    }
    out.finish()
}

fn property_line<W: Write>(out: &mut Out<W>, scalar: ScalarType, name: &str) {
    out.bytes(b"property ");
    out.bytes(scalar.ply_name().as_bytes());
    out.byte(b' ');
    out.bytes(name.as_bytes());
    out.byte(b'\n');
}

/// One value in ascii: integers as integers, `float` as the shortest decimal of the nearest
/// f32, `double` as the shortest decimal reading back to the same bits.
fn ascii_value<W: Write>(out: &mut Out<W>, scalar: ScalarType, x: f64) {
    match scalar {
        ScalarType::F64 => out.f64(x),
        ScalarType::F32 => out.f32(x as f32),
        _ => {
            // Integer types hold whole values in range (`PolygonSoup::validate`).
            if x < 0.0 {
                out.byte(b'-');
            }
            out.u64(x.abs() as u64);
        }
    }
}

/// One value in binary, in `scalar`'s type (integers are whole and in range:
/// `PolygonSoup::validate`).
#[inline]
fn binary_value<W: Write, const BE: bool>(out: &mut Out<W>, scalar: ScalarType, x: f64) {
    macro_rules! put {
        ($v:expr) => {{
            let v = $v;
            out.bytes(&if BE { v.to_be_bytes() } else { v.to_le_bytes() });
        }};
    }
    match scalar {
        ScalarType::I8 => put!(x as i8),
        ScalarType::U8 => put!(x as u8),
        ScalarType::I16 => put!(x as i16),
        ScalarType::U16 => put!(x as u16),
        ScalarType::I32 => put!(x as i32),
        ScalarType::U32 => put!(x as u32),
        ScalarType::F32 => put!(x as f32),
        ScalarType::F64 => put!(x),
    }
}

fn binary<W: Write, const BE: bool>(
    out: &mut Out<W>,
    soup: &PolygonSoup,
    wide: bool,
    position: ScalarType,
    columns: &[(ScalarType, &[f64])],
) -> io::Result<()> {
    let u32_bytes = |i: u32| if BE { i.to_be_bytes() } else { i.to_le_bytes() };
    if columns.is_empty() && position == ScalarType::F64 {
        for p in &soup.positions {
            for &c in p {
                out.bytes(&if BE { c.to_be_bytes() } else { c.to_le_bytes() });
            }
            out.flush_if_full()?;
        }
    } else {
        for (v, p) in soup.positions.iter().enumerate() {
            for &c in p {
                binary_value::<W, BE>(out, position, c);
            }
            for &(scalar, values) in columns {
                binary_value::<W, BE>(out, scalar, values[v]);
            }
            out.flush_if_full()?;
        }
    }
    for f in soup.faces() {
        if wide {
            out.bytes(&u32_bytes(f.len() as u32));
        } else {
            out.byte(f.len() as u8);
        }
        for &i in f {
            out.bytes(&u32_bytes(i));
        }
        out.flush_if_full()?;
    }
    Ok(())
}
