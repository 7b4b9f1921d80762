//! Geomview OFF (`OFF`, `COFF`, `NOFF`, `STOFF`, `nOFF`, ... ascii only).
//!
//! Read line by line: a vertex is the first 3 numbers of its line, a face is
//! `k i1 .. ik` and whatever follows on the line (colours, normals) is
//! ignored; values may continue on following lines. If that fails, the file
//! is re-read as a plain token stream (no values skipped), which accepts
//! writers that split lines oddly or put everything on one line.

use std::io::{self, Write};

use crate::attributes::{ScalarType, VertexProperty};
use crate::error::{Ctx, IoError};
use crate::out::Out;
use crate::soup::PolygonSoup;
use crate::text::{Lexer, show};

const COMMENT: Option<u8> = Some(b'#');

/// Reads an OFF file held in memory.
pub(crate) fn read(buf: &[u8], ctx: Ctx<'_>) -> Result<PolygonSoup, IoError> {
    match parse(buf, ctx, true) {
        Ok(soup) => Ok(soup),
        Err(e @ (IoError::BadHeader { .. } | IoError::TooLarge { .. })) => Err(e),
        Err(e) => parse(buf, ctx, false).map_err(|_| e),
    }
}

/// One pass; `lines`: skip the rest of each element's last line.
fn parse(buf: &[u8], ctx: Ctx<'_>, lines: bool) -> Result<PolygonSoup, IoError> {
    let mut lx = Lexer::new(buf);
    let (nv, nf, prefix) = header(&mut lx, ctx, lines)?;
    let remaining = buf.len().saturating_sub(lx.pos);
    let mut soup = PolygonSoup::new();
    // Cap reservations by what the rest of the input could hold.
    let _ = soup.positions.try_reserve(nv.min(remaining / 6));
    let nf_cap = nf.min(remaining / 8);
    let _ = soup.face_offsets.try_reserve(nf_cap);
    let _ = soup.face_lines.try_reserve(nf_cap);
    let _ = soup.face_indices.try_reserve(nf_cap * 3);

    // COFF: the numbers after x y z on a vertex's line are its colour (line mode only).
    let mut colours = (lines && prefix == "C").then(Colours::default);
    for i in 0..nv {
        let mut p = [0.0; 3];
        for (axis, c) in p.iter_mut().enumerate() {
            lx.skip_space(COMMENT);
            *c = match lx.f64() {
                Ok(v) => ctx.coordinate(lx.at(), i, v)?,
                Err(e) => {
                    let what = format!("{} coordinate of vertex {} of {nv}", AXES[axis], i + 1);
                    return Err(lx.num_error(ctx, e, &what));
                }
            };
        }
        soup.positions.push(p);
        if let Some(colours) = &mut colours {
            colours.read_line(&mut lx);
        }
        if lines {
            lx.skip_line();
        }
    }

    let mut prefix = prefix;
    if let Some(colours) = colours
        && colours.attach(&mut soup)
    {
        prefix.clear();
    }
    for (letters, what) in [
        ("C", "colours"),
        ("N", "normals"),
        ("ST", "texture coordinates"),
    ] {
        if prefix.contains(letters) {
            let what = format!("OFF vertex {what} ({prefix}OFF)");
            soup.attributes.not_kept.push(what);
        }
    }
    for j in 0..nf {
        lx.skip_space(COMMENT);
        let line = lx.line_u32();
        let k = match lx.u64() {
            Ok(k) => k,
            Err(e) => {
                let what = format!("vertex count of face {} of {nf}", j + 1);
                return Err(lx.num_error(ctx, e, &what));
            }
        };
        if k < 3 {
            return Err(ctx.too_small(lx.at(), k));
        }
        for _ in 0..k {
            lx.skip_space(COMMENT);
            match lx.i64() {
                Ok(v) if v >= 0 && (v as u64) < nv as u64 => soup.face_indices.push(v as u32),
                Ok(v) => return Err(ctx.index(lx.at(), v, nv as u64)),
                Err(e) => {
                    let what = format!("vertex index of face {} of {nf}", j + 1);
                    return Err(lx.num_error(ctx, e, &what));
                }
            }
        }
        if soup.close_face().is_none() {
            return Err(ctx.too_large(lx.at(), "more than 2^32-1 face indices"));
        }
        soup.face_lines.push(line);
        if lines {
            lx.skip_line();
        }
    }
    Ok(soup)
}

const AXES: [&str; 3] = ["x", "y", "z"];

/// The colours of a COFF file's vertices: 3 or 4 numbers after the position, integers 0 to 255
/// (`uchar`) or other numbers (`float`), the same count on every line.
#[derive(Default)]
struct Colours {
    /// Four numbers per vertex (alpha 0 when absent).
    values: Vec<f64>,
    /// The count of the first line; `None` once lines disagree or a number is malformed.
    count: Option<usize>,
    first: bool,
    integers: bool,
}

impl Colours {
    /// Reads the numbers after the position on the current line.
    fn read_line(&mut self, lx: &mut Lexer<'_>) {
        let mut numbers = [0.0; 4];
        let mut k = 0;
        while k < 4 {
            match lx.f64() {
                Ok(v) => numbers[k] = v,
                Err(crate::text::NumErr::Missing) => break,
                Err(crate::text::NumErr::Bad) => {
                    self.count = None;
                    self.first = true;
                    return;
                }
            }
            k += 1;
        }
        if !self.first {
            self.first = true;
            self.integers = true;
            self.count = Some(k).filter(|&k| k >= 3);
        } else if self.count != Some(k) {
            self.count = None;
        }
        if self.count.is_some() {
            self.integers &= numbers[..k]
                .iter()
                .all(|&v| v.fract() == 0.0 && (0.0..=255.0).contains(&v));
            self.values.extend_from_slice(&numbers);
        }
    }

    /// Stores the colours as `red green blue [alpha]`; false when they are not usable.
    fn attach(self, soup: &mut PolygonSoup) -> bool {
        let Some(count) = self.count else {
            return false;
        };
        let scalar = if self.integers {
            ScalarType::U8
        } else {
            ScalarType::F32
        };
        for (k, name) in ["red", "green", "blue", "alpha"][..count]
            .iter()
            .enumerate()
        {
            let values = self
                .values
                .chunks_exact(4)
                .map(|c| match scalar {
                    ScalarType::F32 => f64::from(c[k] as f32),
                    _ => c[k],
                })
                .collect();
            soup.attributes.vertex.push(VertexProperty {
                name: (*name).to_owned(),
                scalar,
                values,
            });
        }
        true
    }
}

/// Reads the keyword (optional) and the counts; returns (vertices, faces, the keyword's letters
/// before `OFF`).
fn header(
    lx: &mut Lexer<'_>,
    ctx: Ctx<'_>,
    lines: bool,
) -> Result<(usize, usize, String), IoError> {
    lx.skip_space(COMMENT);
    let tok = lx.peek_token();
    let mut dimension_follows = false;
    let mut letters = String::new();
    if tok.len() >= 3 && tok[tok.len() - 3..].eq_ignore_ascii_case(b"OFF") {
        let prefix = &tok[..tok.len() - 3];
        if !prefix.iter().all(u8::is_ascii_alphanumeric) {
            return Err(ctx.bad_header(lx.at(), format!("unknown keyword '{}'", show(tok))));
        }
        dimension_follows = prefix.last() == Some(&b'n');
        letters = String::from_utf8_lossy(prefix).into_owned();
        lx.pos += tok.len();
        if lx.peek_token().eq_ignore_ascii_case(b"BINARY") {
            return Err(ctx.bad_header(lx.at(), "binary OFF is not supported"));
        }
    } else if !tok.first().is_some_and(u8::is_ascii_digit) {
        return Err(if lx.is_eof() {
            ctx.eof(lx.at(), "OFF header")
        } else {
            ctx.bad_header(
                lx.at(),
                format!("expected OFF keyword, found '{}'", show(tok)),
            )
        });
    }
    if dimension_follows {
        let d = count(lx, ctx, "dimension")?;
        if d < 3 {
            return Err(ctx.bad_header(lx.at(), format!("dimension {d} < 3 is not supported")));
        }
    }
    let nv = count(lx, ctx, "vertex count")?;
    let nf = count(lx, ctx, "face count")?;
    // The edge count is optional in practice; in line mode take it only from
    // the same line.
    lx.skip_blank();
    if !lines || !(lx.at_eol() || lx.peek() == COMMENT) {
        count(lx, ctx, "edge count")?;
    }
    if lines {
        lx.skip_line();
    }
    if nv > u32::MAX as u64 {
        return Err(ctx.too_large(lx.at(), format!("{nv} vertices (at most 2^32-1)")));
    }
    let nf = usize::try_from(nf).map_err(|_| ctx.too_large(lx.at(), format!("{nf} faces")))?;
    Ok((nv as usize, nf, letters))
}

fn count(lx: &mut Lexer<'_>, ctx: Ctx<'_>, what: &str) -> Result<u64, IoError> {
    lx.skip_space(COMMENT);
    match lx.u64() {
        Ok(n) => Ok(n),
        Err(e) => Err(match lx.num_error(ctx, e, what) {
            IoError::Parse { file, at, message } => IoError::BadHeader { file, at, message },
            other => other,
        }),
    }
}

/// Writes `OFF` (`COFF` when the soup has per-vertex `red green blue [alpha]`), `V F 0`,
/// vertex lines (`x y z [r g b [a]]`) and `k i1 .. ik` face lines.
pub(crate) fn write<W: Write>(w: W, soup: &PolygonSoup) -> io::Result<W> {
    let mut out = Out::new(w);
    let colours = soup.attributes.off_colour_columns();
    out.bytes(if colours.is_some() {
        b"COFF\n"
    } else {
        b"OFF\n"
    });
    out.u64(soup.positions.len() as u64);
    out.byte(b' ');
    out.u64(soup.face_count() as u64);
    out.bytes(b" 0\n");
    match colours {
        None => {
            for p in &soup.positions {
                out.point_line(b"", *p)?;
            }
        }
        Some(columns) => {
            for (v, p) in soup.positions.iter().enumerate() {
                for (k, &c) in p.iter().enumerate() {
                    if k > 0 {
                        out.byte(b' ');
                    }
                    out.f64(c);
                }
                for &column in &columns {
                    out.byte(b' ');
                    out.f64(soup.attributes.vertex[column].values[v]);
                }
                out.byte(b'\n');
                out.flush_if_full()?;
            }
        }
    }
    for f in soup.faces() {
        out.u64(f.len() as u64);
        out.index_line(f, 0)?;
    }
    out.finish()
}
