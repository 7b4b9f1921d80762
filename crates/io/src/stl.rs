//! STL reader, binary and ascii, and binary STL writer. Every facet gets its own 3 vertices (no
//! welding); ascii facets with more than 3 vertices become polygons.

use std::io::{self, Write};

use crate::error::{Ctx, IoError, Location};
use crate::out::Out;
use crate::soup::PolygonSoup;
use crate::text::{Lexer, show};

const HEADER: usize = 84;
const RECORD: usize = 50;

/// Reads an STL file held in memory: binary when `84 + 50 n` equals the
/// length, ascii when it starts with `solid` (unless that reading finds no
/// facet or fails and the bytes are not text), binary otherwise.
pub(crate) fn read(buf: &[u8], ctx: Ctx<'_>) -> Result<PolygonSoup, IoError> {
    let n = buf
        .get(80..84)
        .map(|b| u64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])));
    let exact_binary = n.is_some_and(|n| HEADER as u64 + RECORD as u64 * n == buf.len() as u64);
    if exact_binary {
        return read_binary(buf, ctx);
    }
    let mut lx = Lexer::new(buf);
    lx.skip_space(None);
    if lx.peek_token().eq_ignore_ascii_case(b"solid") {
        match read_ascii(buf, ctx) {
            Ok(soup) if soup.face_count() > 0 || !looks_binary(buf) => Ok(soup),
            // A binary file whose header starts with "solid" (and is truncated
            // or has trailing bytes): read it as binary if it is not text. Its
            // "name" line can swallow the whole body when it holds no newline,
            // leaving an ascii reading without facets.
            Ok(_) | Err(_) if looks_binary(buf) => read_binary(buf, ctx),
            other => other,
        }
    } else {
        read_binary(buf, ctx)
    }
}

fn looks_binary(buf: &[u8]) -> bool {
    buf.len() >= HEADER && buf.iter().any(|&b| b == 0 || b >= 0x80)
}

fn read_binary(buf: &[u8], ctx: Ctx<'_>) -> Result<PolygonSoup, IoError> {
    let Some(nb) = buf.get(80..84) else {
        return Err(ctx.eof(
            Location::Offset(buf.len() as u64),
            "84-byte binary STL header",
        ));
    };
    let n = u32::from_le_bytes([nb[0], nb[1], nb[2], nb[3]]) as usize;
    let have = (buf.len() - HEADER) / RECORD;
    if have < n {
        return Err(ctx.eof(
            Location::Offset((HEADER + have * RECORD) as u64),
            format!("triangle {} of {n}", have + 1),
        ));
    }
    if n > u32::MAX as usize / 3 {
        return Err(ctx.too_large(Location::Offset(80), format!("{n} triangles")));
    }
    let mut soup = PolygonSoup::new();
    let _ = soup.positions.try_reserve(3 * n);
    let _ = soup.face_indices.try_reserve(3 * n);
    let _ = soup.face_offsets.try_reserve(n);
    let data = &buf[HEADER..HEADER + n * RECORD];
    for (t, rec) in data.chunks_exact(RECORD).enumerate() {
        for k in 0..3 {
            let mut p = [0.0f64; 3];
            for (axis, c) in p.iter_mut().enumerate() {
                let o = 12 + 12 * k + 4 * axis;
                let v = f32::from_le_bytes([rec[o], rec[o + 1], rec[o + 2], rec[o + 3]]);
                if !v.is_finite() {
                    let at = Location::Offset((HEADER + t * RECORD + o) as u64);
                    return Err(ctx.non_finite(at, f64::from(v)));
                }
                *c = f64::from(v);
            }
            soup.positions.push(p);
        }
        let base = (3 * t) as u32;
        soup.face_indices
            .extend_from_slice(&[base, base + 1, base + 2]);
        soup.face_offsets.push(base + 3);
    }
    Ok(soup)
}

fn read_ascii(buf: &[u8], ctx: Ctx<'_>) -> Result<PolygonSoup, IoError> {
    let mut lx = Lexer::new(buf);
    let mut soup = PolygonSoup::new();
    // Start of the current facet in `positions`, and its line.
    let mut facet: Option<(usize, u32)> = None;
    loop {
        lx.skip_space(None);
        if lx.is_eof() {
            break;
        }
        let at = lx.at();
        let kw = lx.token();
        if kw.eq_ignore_ascii_case(b"vertex") {
            let Some(_) = facet else {
                return Err(ctx.parse(at, "'vertex' outside a facet"));
            };
            let mut p = [0.0f64; 3];
            for (axis, c) in p.iter_mut().enumerate() {
                *c = match lx.f64() {
                    Ok(v) if v.is_finite() => v,
                    Ok(v) => return Err(ctx.non_finite(lx.at(), v)),
                    Err(e) => {
                        let what = format!("{} coordinate", ["x", "y", "z"][axis]);
                        return Err(lx.num_error(ctx, e, &what));
                    }
                };
            }
            if soup.positions.len() >= u32::MAX as usize {
                return Err(ctx.too_large(at, "more than 2^32-1 vertices"));
            }
            soup.positions.push(p);
        } else if kw.eq_ignore_ascii_case(b"facet") {
            if facet.is_some() {
                return Err(ctx.parse(at, "'facet' inside a facet (missing 'endfacet')"));
            }
            facet = Some((soup.positions.len(), lx.line_u32()));
            // `normal nx ny nz`: ignored (may even be nan).
            if lx.peek_token().eq_ignore_ascii_case(b"normal") {
                for _ in 0..4 {
                    lx.token();
                }
            }
        } else if kw.eq_ignore_ascii_case(b"endfacet") {
            let Some((start, line)) = facet.take() else {
                return Err(ctx.parse(at, "'endfacet' without 'facet'"));
            };
            let end = soup.positions.len();
            if end - start < 3 {
                return Err(ctx.too_small(at, (end - start) as u64));
            }
            soup.face_indices.extend(start as u32..end as u32);
            if soup.close_face().is_none() {
                return Err(ctx.too_large(at, "more than 2^32-1 face indices"));
            }
            soup.face_lines.push(line);
        } else if kw.eq_ignore_ascii_case(b"solid") || kw.eq_ignore_ascii_case(b"endsolid") {
            lx.skip_line(); // name
        } else if kw.eq_ignore_ascii_case(b"outer") {
            if !lx.token().eq_ignore_ascii_case(b"loop") {
                return Err(ctx.parse(at, "expected 'outer loop'"));
            }
        } else if kw.eq_ignore_ascii_case(b"endloop") {
        } else {
            return Err(ctx.parse(at, format!("unexpected '{}' in ascii STL", show(kw))));
        }
    }
    if facet.is_some() {
        return Err(ctx.eof(lx.at(), "'endfacet'"));
    }
    Ok(soup)
}

/// The header of written files: 80 bytes that do not start with `solid`, so no reader takes the
/// file for ascii STL.
const WRITTEN_HEADER: &[u8; 80] =
    b"binary STL written by surftopo                                                  ";

/// Writes binary STL: the header, the triangle count, then per triangle its unit normal (zero
/// for a degenerate triangle), its corners as `f32` (rounded to nearest: STL holds single
/// precision) and a zero attribute count. Polygons are cut into triangle fans (STL holds
/// triangles only); shared vertices are not kept (each facet lists its corners).
///
/// # Errors
/// `InvalidInput` before writing anything when the fans have more than 2^32 - 1 triangles (the
/// count is a `u32`); the writer's errors.
pub(crate) fn write<W: Write>(w: W, soup: &PolygonSoup) -> io::Result<W> {
    let triangles: u64 = soup.faces().map(|f| f.len().saturating_sub(2) as u64).sum();
    let count = u32::try_from(triangles).map_err(|_| {
        io::Error::new(
            io::ErrorKind::InvalidInput,
            format!("{triangles} triangles: binary STL holds at most 2^32-1"),
        )
    })?;
    let mut out = Out::new(w);
    out.bytes(WRITTEN_HEADER);
    out.bytes(&count.to_le_bytes());
    for face in soup.faces() {
        for i in 1..face.len().saturating_sub(1) {
            let corners = [face[0], face[i], face[i + 1]].map(|v| soup.positions[v as usize]);
            for c in normal(corners) {
                out.bytes(&(c as f32).to_le_bytes());
            }
            for p in corners {
                for c in p {
                    out.bytes(&(c as f32).to_le_bytes());
                }
            }
            out.bytes(&[0, 0]);
            out.flush_if_full()?;
        }
    }
    out.finish()
}

/// The unit normal of a triangle by the right-hand rule, zero when it is degenerate (or its
/// cross product is not finite).
fn normal([a, b, c]: [[f64; 3]; 3]) -> [f64; 3] {
    let (u, v) = (
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
        [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
    );
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if length > 0.0 && length.is_finite() {
        n.map(|x| x / length)
    } else {
        [0.0; 3]
    }
}
