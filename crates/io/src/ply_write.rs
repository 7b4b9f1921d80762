//! PLY writer: `double` x, y, z and a `vertex_indices` list per face, ascii
//! or binary (little or big endian).

use std::io::{self, Write};

use crate::PlyEncoding;
use crate::out::Out;
use crate::soup::PolygonSoup;

/// Writes the soup as PLY with the given encoding.
pub(crate) fn write<W: Write>(w: W, soup: &PolygonSoup, enc: PlyEncoding) -> io::Result<W> {
    let mut out = Out::new(w);
    // Face sizes up to 255 fit a `uchar` count.
    let wide = soup.faces().any(|f| f.len() > 255);
    out.bytes(b"ply\nformat ");
    out.bytes(match enc {
        PlyEncoding::Ascii => b"ascii",
        PlyEncoding::BinaryLittleEndian => b"binary_little_endian",
        PlyEncoding::BinaryBigEndian => b"binary_big_endian",
    });
    out.bytes(b" 1.0\nelement vertex ");
    out.u64(soup.positions.len() as u64);
    out.bytes(b"\nproperty double x\nproperty double y\nproperty double z\nelement face ");
    out.u64(soup.face_count() as u64);
    out.bytes(if wide {
        b"\nproperty list uint uint vertex_indices\nend_header\n"
    } else {
        b"\nproperty list uchar uint vertex_indices\nend_header\n"
    });
    match enc {
        PlyEncoding::Ascii => {
            for p in &soup.positions {
                out.point_line(b"", *p)?;
            }
            for f in soup.faces() {
                out.u64(f.len() as u64);
                out.index_line(f, 0)?;
            }
        }
        PlyEncoding::BinaryLittleEndian => {
            binary(&mut out, soup, wide, |b| b.to_le_bytes(), u32::to_le_bytes)?
        }
        PlyEncoding::BinaryBigEndian => {
            binary(&mut out, soup, wide, |b| b.to_be_bytes(), u32::to_be_bytes)?
        }
    }
    out.finish()
}

fn binary<W: Write>(
    out: &mut Out<W>,
    soup: &PolygonSoup,
    wide: bool,
    f64_bytes: impl Fn(f64) -> [u8; 8],
    u32_bytes: impl Fn(u32) -> [u8; 4],
) -> io::Result<()> {
    for p in &soup.positions {
        for &c in p {
            out.bytes(&f64_bytes(c));
        }
        out.flush_if_full()?;
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
