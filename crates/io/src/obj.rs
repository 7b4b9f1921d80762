//! Wavefront OBJ: `v`, `vt`, `vn` and `f` statements (`f v`, `v/vt`, `v//vn`, `v/vt/vn`);
//! everything else is skipped and counted in [`crate::Attributes::not_kept`] (comments aside).
//! Texture coordinates and normals become per-vertex attributes (`u v [w]`, `nx ny nz`) when
//! that loses nothing, else per-corner tables (see [`crate::Attributes`]).

use std::io::{self, Write};

use crate::attributes::{CornerTable, ScalarType, VertexProperty};
use crate::error::{Ctx, IoError, Location};
use crate::out::Out;
use crate::soup::PolygonSoup;
use crate::text::{Lexer, parse_i64_prefix, show};

/// The `vt` and `vn` statements read so far and the corners that refer to them.
#[derive(Default)]
struct Tables {
    /// Three numbers per `vt` line (missing ones 0).
    texcoords: Vec<f64>,
    /// Most numbers on a `vt` line.
    texcoord_width: usize,
    /// Three numbers per `vn` line.
    normals: Vec<f64>,
    /// Per corner `vt` index (0-based) or NONE; empty until a corner has one.
    corner_vt: Vec<u32>,
    /// Per corner `vn` index or NONE; empty until a corner has one.
    corner_vn: Vec<u32>,
    /// Largest positive 0-based `vt` / `vn` index, and a line where it occurs.
    max_vt: Option<(u32, u32)>,
    max_vn: Option<(u32, u32)>,
    /// Skipped statements: keyword and count.
    skipped: Vec<(Vec<u8>, u64)>,
    /// `v` statements with something after x y z (a colour, a weight), which is skipped.
    vertex_extras: u64,
}

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
    let mut tables = Tables::default();

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
                lx.skip_blank();
                if !lx.at_eol() && lx.peek() != Some(b'#') {
                    tables.vertex_extras += 1;
                }
                lx.skip_line();
            }
            b'f' if lx.ends_token_at(1) => {
                lx.pos += 1;
                let m = read_face(&mut lx, &mut soup, &mut tables, ctx)?;
                max_index = max_index.max(m);
            }
            b'v' if lx.ends_token_at(2) && matches!(lx.peek_at(1), Some(b't' | b'n')) => {
                let normal = lx.peek_at(1) == Some(b'n');
                lx.pos += 2;
                read_table_line(&mut lx, &mut tables, normal, ctx)?;
                lx.skip_line();
            }
            b'#' => lx.skip_line(),
            _ => {
                let keyword = lx.peek_token();
                match tables.skipped.iter_mut().find(|(k, _)| k == keyword) {
                    Some((_, n)) => *n += 1,
                    None => tables.skipped.push((keyword.to_vec(), 1)),
                }
                lx.skip_line();
            }
        }
    }

    if !soup.face_indices.is_empty() && max_index as usize >= soup.positions.len() {
        return Err(forward_reference_error(&soup, ctx));
    }
    attach_tables(&mut soup, tables, ctx)?;
    Ok(soup)
}

/// Reads the numbers of a `vt` (1 to 3) or `vn` (3) statement.
fn read_table_line(
    lx: &mut Lexer<'_>,
    tables: &mut Tables,
    normal: bool,
    ctx: Ctx<'_>,
) -> Result<(), IoError> {
    let (what, least) = if normal { ("vn", 3) } else { ("vt", 1) };
    let mut numbers = [0.0; 3];
    let mut count = 0;
    for (k, slot) in numbers.iter_mut().enumerate() {
        match lx.f64() {
            Ok(v) => {
                *slot = v;
                count += 1;
            }
            Err(crate::text::NumErr::Missing) if k >= least => break,
            Err(e) => return Err(lx.num_error(ctx, e, &format!("{what} number {}", k + 1))),
        }
    }
    let values = if normal {
        &mut tables.normals
    } else {
        tables.texcoord_width = tables.texcoord_width.max(count);
        &mut tables.texcoords
    };
    if values.len() / 3 >= u32::MAX as usize - 1 {
        return Err(ctx.too_large(lx.at(), format!("more than 2^32-2 {what} lines")));
    }
    values.extend_from_slice(&numbers);
    Ok(())
}

/// Checks the corners' `vt`/`vn` indices against the final counts and stores the tables in
/// the soup: per-vertex when that loses nothing, else per-corner; skipped statements go to
/// `not_kept`.
fn attach_tables(soup: &mut PolygonSoup, tables: Tables, ctx: Ctx<'_>) -> Result<(), IoError> {
    let corners = soup.face_indices.len();
    let nv = soup.positions.len();
    let width = tables.texcoord_width.max(2);
    let texcoords = (
        tables.texcoords.len() / 3,
        width,
        tables.texcoords,
        tables.corner_vt,
    );
    let normals = (
        tables.normals.len() / 3,
        3,
        tables.normals,
        tables.corner_vn,
    );
    for ((count, width, values, mut corner), max, what, names) in [
        (texcoords, tables.max_vt, "vt", &["u", "v", "w"][..]),
        (normals, tables.max_vn, "vn", &["nx", "ny", "nz"][..]),
    ] {
        if let Some((index, line)) = max
            && index as usize >= count
        {
            let message = format!(
                "{what} index {} out of range ({count} {what} lines)",
                index + 1
            );
            return Err(ctx.parse(Location::Line(u64::from(line)), message));
        }
        if count == 0 {
            continue;
        }
        corner.resize(corners, CornerTable::NONE);
        let table = CornerTable {
            width,
            values: values
                .chunks_exact(3)
                .flat_map(|e| e[..width].iter().copied())
                .collect(),
            corners: corner,
        };
        match table.per_vertex(&soup.face_indices, nv) {
            Some(entry_of) => {
                for (k, name) in names[..width].iter().enumerate() {
                    let values = entry_of
                        .iter()
                        .map(|&e| table.values[e as usize * width + k])
                        .collect();
                    soup.attributes.vertex.push(VertexProperty {
                        name: (*name).to_owned(),
                        scalar: ScalarType::F64,
                        values,
                    });
                }
            }
            None if what == "vt" => soup.attributes.corner_texcoords = Some(table),
            None => soup.attributes.corner_normals = Some(table),
        }
    }
    if tables.vertex_extras > 0 {
        soup.attributes.not_kept.push(format!(
            "OBJ numbers after x y z (colours or weights) on {} 'v' statements",
            tables.vertex_extras
        ));
    }
    for (keyword, n) in tables.skipped {
        soup.attributes
            .not_kept
            .push(format!("OBJ '{}' statements ({n})", show(&keyword)));
    }
    Ok(())
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
fn read_face(
    lx: &mut Lexer<'_>,
    soup: &mut PolygonSoup,
    tables: &mut Tables,
    ctx: Ctx<'_>,
) -> Result<u32, IoError> {
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
        // `a`, `a/b`, `a//c`, `a/b/c`.
        let mut end = n;
        if rest.get(end) == Some(&b'/') {
            end += 1;
            let corner = soup.face_indices.len();
            if let Some((t, k)) = parse_i64_prefix(&rest[end..]) {
                let count = tables.texcoords.len() / 3;
                let i = table_index(lx, t, count, &mut tables.max_vt, "vt", ctx)?;
                set_corner(&mut tables.corner_vt, corner, i);
                end += k;
            }
            if rest.get(end) == Some(&b'/') {
                end += 1;
                let Some((t, k)) = parse_i64_prefix(&rest[end..]) else {
                    return Err(bad_index(lx, ctx));
                };
                let count = tables.normals.len() / 3;
                let i = table_index(lx, t, count, &mut tables.max_vn, "vn", ctx)?;
                set_corner(&mut tables.corner_vn, corner, i);
                end += k;
            }
            if !lx.ends_token_at(end) || rest[n + 1..end].is_empty() {
                return Err(bad_index(lx, ctx));
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

/// Resolves a `vt`/`vn` index of a face corner (1-based, or negative: relative to the `count`
/// lines so far); positive ones are checked at the end (they may refer to later lines).
#[inline]
fn table_index(
    lx: &Lexer<'_>,
    t: i64,
    count: usize,
    max: &mut Option<(u32, u32)>,
    what: &str,
    ctx: Ctx<'_>,
) -> Result<u32, IoError> {
    let count = count as i64;
    let index = if t > 0 && t < i64::from(u32::MAX) {
        let i = (t - 1) as u32;
        if max.is_none_or(|(m, _)| i > m) {
            *max = Some((i, lx.line_u32()));
        }
        i
    } else if t < 0 && count + t >= 0 {
        (count + t) as u32
    } else {
        let message = format!("{what} index {t} out of range ({count} {what} lines)");
        return Err(ctx.parse(lx.at(), message));
    };
    Ok(index)
}

/// Records corner `corner`'s table entry, filling the corners before it with NONE.
#[inline]
fn set_corner(corners: &mut Vec<u32>, corner: usize, entry: u32) {
    corners.resize(corner, CornerTable::NONE);
    corners.push(entry);
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

/// Where the `vt` or `vn` entry of a face corner comes from when writing.
enum Source<'a> {
    None,
    /// One line per vertex, from these per-vertex columns; a corner's entry is its vertex.
    PerVertex(Vec<&'a [f64]>),
    /// The per-corner table.
    PerCorner(&'a CornerTable),
}

impl Source<'_> {
    /// Writes the source's lines (`vt ...` / `vn ...`), for `vertex_count` vertices.
    fn write_lines<W: Write>(
        &self,
        out: &mut Out<W>,
        prefix: &[u8],
        vertex_count: usize,
    ) -> io::Result<()> {
        let line = |out: &mut Out<W>, numbers: &mut dyn Iterator<Item = f64>| {
            out.bytes(prefix);
            for (k, x) in numbers.enumerate() {
                if k > 0 {
                    out.byte(b' ');
                }
                out.f64(x);
            }
            out.byte(b'\n');
            out.flush_if_full()
        };
        match self {
            Source::None => Ok(()),
            Source::PerVertex(columns) => {
                (0..vertex_count).try_for_each(|v| line(out, &mut columns.iter().map(|c| c[v])))
            }
            Source::PerCorner(table) => {
                (0..table.len()).try_for_each(|k| line(out, &mut table.entry(k).iter().copied()))
            }
        }
    }

    /// The 0-based entry of corner `corner` (of vertex `vertex`), if any.
    #[inline]
    fn entry(&self, corner: usize, vertex: u32) -> Option<u32> {
        match self {
            Source::None => None,
            Source::PerVertex(_) => Some(vertex),
            Source::PerCorner(table) => {
                Some(table.corners[corner]).filter(|&c| c != CornerTable::NONE)
            }
        }
    }
}

/// Writes `v x y z`, `vt`, `vn` and `f a b c ...` (1-based; `a/t`, `a//n`, `a/t/n` when the
/// corner has a texture coordinate or normal) lines. Texture coordinates and normals come from
/// the per-corner tables, else from the per-vertex `u v [w]` (or `s t`, `texture_u texture_v`)
/// and `nx ny nz` columns (one `vt`/`vn` line per vertex); other per-vertex properties are not
/// written.
pub(crate) fn write<W: Write>(w: W, soup: &PolygonSoup) -> io::Result<W> {
    let mut out = Out::new(w);
    for p in &soup.positions {
        out.point_line(b"v ", *p)?;
    }
    let attributes = &soup.attributes;
    let columns = |indices: &[usize]| {
        Source::PerVertex(
            indices
                .iter()
                .map(|&i| &attributes.vertex[i].values[..])
                .collect(),
        )
    };
    let texcoords = match (&attributes.corner_texcoords, attributes.obj_vt_columns()) {
        (Some(table), _) => Source::PerCorner(table),
        (None, Some(indices)) => columns(&indices),
        (None, None) => Source::None,
    };
    let normals = match (&attributes.corner_normals, attributes.obj_vn_columns()) {
        (Some(table), _) => Source::PerCorner(table),
        (None, Some(indices)) => columns(&indices),
        (None, None) => Source::None,
    };
    let n = soup.positions.len();
    texcoords.write_lines(&mut out, b"vt ", n)?;
    normals.write_lines(&mut out, b"vn ", n)?;
    if matches!((&texcoords, &normals), (Source::None, Source::None)) {
        for f in soup.faces() {
            out.byte(b'f');
            out.index_line(f, 1)?;
        }
        return out.finish();
    }
    for w in soup.face_offsets.windows(2) {
        out.byte(b'f');
        for corner in w[0] as usize..w[1] as usize {
            let v = soup.face_indices[corner];
            out.byte(b' ');
            out.u64(u64::from(v) + 1);
            let t = texcoords.entry(corner, v);
            let normal = normals.entry(corner, v);
            if t.is_some() || normal.is_some() {
                out.byte(b'/');
            }
            if let Some(t) = t {
                out.u64(u64::from(t) + 1);
            }
            if let Some(normal) = normal {
                out.byte(b'/');
                out.u64(u64::from(normal) + 1);
            }
        }
        out.byte(b'\n');
        out.flush_if_full()?;
    }
    out.finish()
}
