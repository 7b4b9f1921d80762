//! Wavefront OBJ: `v` and `f` statements; everything else is skipped.

use std::io::{self, Write};

use crate::error::{Ctx, IoError, Location};
use crate::out::Out;
use crate::soup::PolygonSoup;
use crate::text::{Lexer, parse_i64_prefix, show};

/// Reads an OBJ file held in memory.
pub(crate) fn read(buf: &[u8], ctx: Ctx<'_>) -> Result<PolygonSoup, IoError> {
    let mut lx = Lexer::new(buf).with_continuation();
    let mut soup = PolygonSoup::new();
    // Typical meshes spend 60-80 bytes per vertex (one `v` line, two `f`
    // lines); reserving more is cheap (untouched pages cost nothing).
    let est = buf.len() / 48;
    let _ = soup.positions.try_reserve(est);
    let _ = soup.face_indices.try_reserve(est * 6);
    let _ = soup.face_offsets.try_reserve(est * 2);
    let _ = soup.face_lines.try_reserve(est * 2);
    // Largest 0-based positive index seen; positive indices may refer to
    // vertices defined later, so they are checked once at the end.
    let mut max_index: u32 = 0;

    loop {
        lx.skip_blank();
        let Some(b) = lx.peek() else { break };
        match b {
            b'\n' => {
                lx.newline();
            }
            b'v' if lx.ends_token_at(1) => {
                lx.pos += 1;
                read_vertex(&mut lx, &mut soup, ctx)?;
                lx.skip_line();
            }
            b'f' if lx.ends_token_at(1) => {
                lx.pos += 1;
                let m = read_face(&mut lx, &mut soup, ctx)?;
                max_index = max_index.max(m);
            }
            _ => lx.skip_line(),
        }
    }

    if !soup.face_indices.is_empty() && max_index as usize >= soup.positions.len() {
        return Err(forward_reference_error(&soup, ctx));
    }
    Ok(soup)
}

#[inline]
fn read_vertex(lx: &mut Lexer<'_>, soup: &mut PolygonSoup, ctx: Ctx<'_>) -> Result<(), IoError> {
    let (start, line) = (lx.pos, lx.line);
    let x = lx.f64();
    let y = lx.f64();
    let z = lx.f64();
    match (x, y, z) {
        (Ok(x), Ok(y), Ok(z))
            if ctx.keeps_non_finite() || (x.is_finite() && y.is_finite() && z.is_finite()) =>
        {
            if soup.positions.len() >= u32::MAX as usize {
                return Err(ctx.too_large(lx.at(), "more than 2^32-1 vertices"));
            }
            soup.positions.push([x, y, z]);
            Ok(())
        }
        _ => Err(vertex_error(lx.buf, start, line, soup.positions.len(), ctx)),
    }
}

/// Re-reads a vertex statement's coordinates to name the first bad one.
#[cold]
fn vertex_error(buf: &[u8], start: usize, line: u64, vertex: usize, ctx: Ctx<'_>) -> IoError {
    let mut lx = Lexer::new(buf).with_continuation();
    lx.pos = start;
    lx.line = line;
    for axis in ["x", "y", "z"] {
        match lx.f64() {
            Ok(v) if !v.is_finite() => return ctx.non_finite(lx.at(), vertex, v),
            Ok(_) => {}
            Err(e) => return lx.num_error(ctx, e, &format!("{axis} coordinate")),
        }
    }
    ctx.parse(lx.at(), "bad vertex")
}

/// Reads the indices of an `f` statement up to the end of the line; returns
/// the largest positive (0-based) index.
#[inline]
fn read_face(lx: &mut Lexer<'_>, soup: &mut PolygonSoup, ctx: Ctx<'_>) -> Result<u32, IoError> {
    let line = lx.line_u32();
    let start = soup.face_indices.len();
    let nv = soup.positions.len() as i64;
    let mut max_index = 0u32;
    loop {
        lx.skip_blank();
        if lx.at_eol() {
            break;
        }
        let rest = &lx.buf[lx.pos..];
        let Some((v, n)) = parse_i64_prefix(rest) else {
            return Err(bad_index(lx, ctx));
        };
        // `a`, `a/b`, `a//c`, `a/b/c`: skip what follows the vertex index.
        let mut end = n;
        if rest.get(end) == Some(&b'/') {
            while !lx.ends_token_at(end) {
                end += 1;
            }
        } else if !lx.ends_token_at(n) {
            return Err(bad_index(lx, ctx));
        }
        let idx = if v > 0 {
            match u32::try_from(v - 1) {
                Ok(i) => i,
                Err(_) => return Err(ctx.index(lx.at(), v, nv as u64)),
            }
        } else if v < 0 && nv + v >= 0 {
            (nv + v) as u32
        } else {
            return Err(ctx.index(lx.at(), v, nv as u64));
        };
        if v > 0 {
            max_index = max_index.max(idx);
        }
        soup.face_indices.push(idx);
        lx.pos += end;
    }
    let sides = soup.face_indices.len() - start;
    if sides < 3 {
        return Err(ctx.too_small(lx.at(), sides as u64));
    }
    if soup.close_face().is_none() {
        return Err(ctx.too_large(lx.at(), "more than 2^32-1 face indices"));
    }
    soup.face_lines.push(line);
    Ok(max_index)
}

#[cold]
fn bad_index(lx: &mut Lexer<'_>, ctx: Ctx<'_>) -> IoError {
    let tok = lx.peek_token();
    ctx.parse(lx.at(), format!("invalid face vertex '{}'", show(tok)))
}

/// Names the first face whose positive index exceeds the final vertex count.
#[cold]
fn forward_reference_error(soup: &PolygonSoup, ctx: Ctx<'_>) -> IoError {
    let nv = soup.positions.len();
    for (k, f) in soup.faces().enumerate() {
        if let Some(&i) = f.iter().find(|&&i| i as usize >= nv) {
            let line = soup.face_lines.get(k).copied().unwrap_or(0);
            return ctx.index(Location::Line(u64::from(line)), i64::from(i) + 1, nv as u64);
        }
    }
    ctx.parse(Location::Line(0), "face index out of range")
}

/// Writes `v x y z` and `f a b c ...` (1-based) lines.
pub(crate) fn write<W: Write>(w: W, soup: &PolygonSoup) -> io::Result<W> {
    let mut out = Out::new(w);
    for p in &soup.positions {
        out.point_line(b"v ", *p)?;
    }
    for f in soup.faces() {
        out.byte(b'f');
        out.index_line(f, 1)?;
    }
    out.finish()
}
