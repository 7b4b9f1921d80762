//! Stanford PLY reader: ascii, binary little and big endian.
//!
//! Vertices come from the `vertex` element's `x`, `y`, `z` (any scalar
//! type); faces from `face` elements (`vertex_indices` or `vertex_index`
//! list) and `tristrips` elements (`vertex_indices` list, -1 restarts a
//! strip). The vertex element's other scalar properties become per-vertex attributes
//! ([`crate::Attributes::vertex`]) with their names and types (`float` values of an ascii file
//! rounded to `float`, integer values checked to be whole and in range); what else is skipped
//! (list properties of vertices, properties of faces, other elements) is listed in
//! [`crate::Attributes::not_kept`].

use crate::error::{Ctx, IoError, Location};
use crate::soup::PolygonSoup;
use crate::text::{Lexer, NumErr, show};

/// Scalar property type.
use crate::attributes::ScalarType as Scalar;
use crate::attributes::VertexProperty;

#[derive(Clone, Copy, Debug)]
enum Kind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

#[derive(Debug)]
struct Property {
    name: Vec<u8>,
    kind: Kind,
}

#[derive(Debug)]
struct Element {
    name: Vec<u8>,
    count: u64,
    props: Vec<Property>,
    line: u64,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Encoding {
    Ascii,
    LittleEndian,
    BigEndian,
}

struct Header {
    encoding: Encoding,
    elements: Vec<Element>,
    /// Offset of the first body byte.
    body: usize,
    /// Line of the first body byte (ascii).
    body_line: u64,
}

/// What an element contributes to the soup.
#[derive(Clone, Copy)]
enum Role {
    /// Property indices of x, y, z.
    Vertex([usize; 3]),
    /// Property index of the vertex index list.
    Faces(usize),
    /// Property index of the strip list.
    Strips(usize),
    Skip,
}

/// Reads a PLY file held in memory.
pub(crate) fn read(buf: &[u8], ctx: Ctx<'_>) -> Result<PolygonSoup, IoError> {
    let hdr = header(buf, ctx)?;
    let roles = roles(&hdr, ctx)?;
    let nv = hdr
        .elements
        .iter()
        .zip(&roles)
        .find(|(_, r)| matches!(r, Role::Vertex(_)))
        .map_or(0, |(e, _)| e.count);
    let mut soup = PolygonSoup::new();
    let columns = vertex_columns(&hdr, &roles, &mut soup);
    // Every property of a record takes at least a byte, so no column grows beyond this
    // reservation (and all of them take at most 8 bytes per input byte); failing to reserve is
    // an error, not an abort.
    let per_record = hdr
        .elements
        .iter()
        .zip(&roles)
        .find(|(_, r)| matches!(r, Role::Vertex(_)))
        .map_or(1, |(e, _)| e.props.len().max(1));
    let records = usize::try_from(nv)
        .unwrap_or(usize::MAX)
        .min(buf.len() / per_record);
    for column in &mut soup.attributes.vertex {
        if column.values.try_reserve_exact(records).is_err() {
            return Err(IoError::OutOfMemory {
                file: ctx.name.to_owned(),
                bytes: records as u64 * 8,
            });
        }
    }
    let body = Body {
        buf,
        hdr: &hdr,
        roles: &roles,
        columns: &columns,
        nv,
    };
    match hdr.encoding {
        Encoding::Ascii => read_ascii(&body, soup, ctx),
        Encoding::LittleEndian => read_binary::<false>(&body, soup, ctx),
        Encoding::BigEndian => read_binary::<true>(&body, soup, ctx),
    }
}

/// What the body readers need to know besides the soup they fill.
struct Body<'a> {
    /// The whole file.
    buf: &'a [u8],
    hdr: &'a Header,
    /// Each element's role, in header order.
    roles: &'a [Role],
    /// Each vertex property's attribute column, or [`NO_COLUMN`].
    columns: &'a [usize],
    /// Number of vertices (records of the vertex element).
    nv: u64,
}

/// Not a column: see [`vertex_columns`].
const NO_COLUMN: usize = usize::MAX;

/// Sets up the soup's per-vertex attribute columns (the vertex element's scalar properties but
/// x, y, z, each name once) and lists what is skipped in `not_kept`; returns, for each property
/// of the vertex element, its column or [`NO_COLUMN`].
fn vertex_columns(hdr: &Header, roles: &[Role], soup: &mut PolygonSoup) -> Vec<usize> {
    let mut columns = Vec::new();
    let attributes = &mut soup.attributes;
    for (el, role) in hdr.elements.iter().zip(roles) {
        let name = show(&el.name);
        match *role {
            Role::Vertex(xyz) => {
                for (i, p) in el.props.iter().enumerate() {
                    let prop = String::from_utf8_lossy(&p.name).into_owned();
                    let column = match p.kind {
                        _ if xyz.contains(&i) => NO_COLUMN,
                        Kind::Scalar(scalar)
                            if crate::attributes::is_valid_name(&prop)
                                && !matches!(&prop[..], "x" | "y" | "z")
                                && attributes.vertex_property(&prop).is_none() =>
                        {
                            attributes.vertex.push(VertexProperty {
                                name: prop,
                                scalar,
                                values: Vec::new(),
                            });
                            attributes.vertex.len() - 1
                        }
                        Kind::Scalar(_) => {
                            let why = if crate::attributes::is_valid_name(&prop) {
                                "a repeated name"
                            } else {
                                "a name with control characters"
                            };
                            let what = format!("PLY vertex property '{}' ({why})", show(&p.name));
                            attributes.not_kept.push(what);
                            NO_COLUMN
                        }
                        Kind::List { .. } => {
                            let what = format!("PLY vertex list property '{}'", show(&p.name));
                            attributes.not_kept.push(what);
                            NO_COLUMN
                        }
                    };
                    columns.push(column);
                }
            }
            Role::Faces(k) | Role::Strips(k) => {
                for p in el
                    .props
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| i != k)
                    .map(|(_, p)| p)
                {
                    attributes.not_kept.push(format!(
                        "PLY {name} property '{}' ({} records)",
                        show(&p.name),
                        el.count
                    ));
                }
            }
            Role::Skip if el.count > 0 && !el.props.is_empty() => {
                attributes
                    .not_kept
                    .push(format!("PLY element '{name}' ({} records)", el.count));
            }
            Role::Skip => {}
        }
    }
    columns
}

fn header(buf: &[u8], ctx: Ctx<'_>) -> Result<Header, IoError> {
    let mut lx = Lexer::new(buf);
    if lx.token() != b"ply" || {
        lx.skip_blank();
        !lx.at_eol()
    } {
        return Err(ctx.bad_header(Location::Line(1), "missing 'ply' magic line"));
    }
    lx.skip_line();
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    loop {
        if lx.is_eof() {
            return Err(ctx.eof(lx.at(), "'end_header'"));
        }
        let at = lx.at();
        let kw = lx.token();
        match kw {
            b"" | b"comment" | b"obj_info" => {}
            b"format" => {
                let enc = match lx.token() {
                    b"ascii" => Encoding::Ascii,
                    b"binary_little_endian" => Encoding::LittleEndian,
                    b"binary_big_endian" => Encoding::BigEndian,
                    other => {
                        let msg = format!("unknown format '{}'", show(other));
                        return Err(ctx.bad_header(at, msg));
                    }
                };
                if encoding.replace(enc).is_some() {
                    return Err(ctx.bad_header(at, "second 'format' line"));
                }
            }
            b"element" => {
                let name = lx.token().to_vec();
                if name.is_empty() {
                    return Err(ctx.bad_header(at, "element without a name"));
                }
                let count = match lx.u64() {
                    Ok(n) => n,
                    Err(NumErr::Missing) => {
                        return Err(ctx.bad_header(at, "element without a count"));
                    }
                    Err(NumErr::Bad) => {
                        let msg = format!("bad element count '{}'", show(lx.peek_token()));
                        return Err(ctx.bad_header(at, msg));
                    }
                };
                elements.push(Element {
                    name,
                    count,
                    props: Vec::new(),
                    line: lx.line,
                });
            }
            b"property" => {
                let Some(el) = elements.last_mut() else {
                    return Err(ctx.bad_header(at, "property before any element"));
                };
                let ty = lx.token();
                let kind = if ty == b"list" {
                    let count = scalar(lx.token(), at, ctx)?;
                    let item = scalar(lx.token(), at, ctx)?;
                    if !count.is_int() {
                        return Err(ctx.bad_header(at, "list count type must be an integer type"));
                    }
                    Kind::List { count, item }
                } else {
                    Kind::Scalar(scalar(ty, at, ctx)?)
                };
                let name = lx.token().to_vec();
                if name.is_empty() {
                    return Err(ctx.bad_header(at, "property without a name"));
                }
                el.props.push(Property { name, kind });
            }
            b"end_header" => {
                lx.skip_line();
                break;
            }
            other => {
                let msg = format!("unknown header keyword '{}'", show(other));
                return Err(ctx.bad_header(at, msg));
            }
        }
        lx.skip_line();
    }
    let Some(encoding) = encoding else {
        return Err(ctx.bad_header(Location::Line(2), "no 'format' line"));
    };
    Ok(Header {
        encoding,
        elements,
        body: lx.pos,
        body_line: lx.line,
    })
}

fn scalar(name: &[u8], at: Location, ctx: Ctx<'_>) -> Result<Scalar, IoError> {
    Scalar::from_ply_name(name)
        .ok_or_else(|| ctx.bad_header(at, format!("unknown property type '{}'", show(name))))
}

fn roles(hdr: &Header, ctx: Ctx<'_>) -> Result<Vec<Role>, IoError> {
    let mut have_vertex = false;
    let mut out = Vec::with_capacity(hdr.elements.len());
    for el in &hdr.elements {
        let at = Location::Line(el.line);
        let find = |names: &[&[u8]]| el.props.iter().position(|p| names.contains(&&p.name[..]));
        let role = match &el.name[..] {
            b"vertex" if !have_vertex => {
                have_vertex = true;
                if el.count > u64::from(u32::MAX) {
                    let msg = format!("{} vertices (at most 2^32-1)", el.count);
                    return Err(ctx.too_large(at, msg));
                }
                let mut xyz = [0; 3];
                for (slot, axis) in xyz.iter_mut().zip([b"x", b"y", b"z"]) {
                    *slot = match find(&[axis]) {
                        Some(i) if matches!(el.props[i].kind, Kind::Scalar(_)) => i,
                        Some(_) => {
                            let msg = format!("vertex property '{}' is a list", axis[0] as char);
                            return Err(ctx.bad_header(at, msg));
                        }
                        None => {
                            let msg =
                                format!("vertex element has no '{}' property", axis[0] as char);
                            return Err(ctx.bad_header(at, msg));
                        }
                    };
                }
                Role::Vertex(xyz)
            }
            b"face" | b"tristrips" => {
                let names: &[&[u8]] = if el.name == b"face" {
                    &[b"vertex_indices", b"vertex_index"]
                } else {
                    &[b"vertex_indices"]
                };
                let Some(i) = find(names) else {
                    let msg = format!("'{}' element has no vertex_indices list", show(&el.name));
                    return Err(ctx.bad_header(at, msg));
                };
                match el.props[i].kind {
                    Kind::List { item, .. } if item.is_int() => {}
                    _ => {
                        let msg = "vertex_indices must be a list of an integer type";
                        return Err(ctx.bad_header(at, msg));
                    }
                }
                if el.name == b"face" {
                    Role::Faces(i)
                } else {
                    Role::Strips(i)
                }
            }
            _ => Role::Skip,
        };
        out.push(role);
    }
    Ok(out)
}

/// Checks a face vertex index against the vertex count.
#[inline]
fn check_index(v: i64, nv: u64, at: impl Fn() -> Location, ctx: Ctx<'_>) -> Result<u32, IoError> {
    if v >= 0 && (v as u64) < nv {
        Ok(v as u32)
    } else {
        Err(ctx.index(at(), v, nv))
    }
}

/// Ends a face read into `soup.face_indices` from `start`.
#[inline]
fn close_face(
    soup: &mut PolygonSoup,
    start: usize,
    at: Location,
    line: Option<u32>,
    ctx: Ctx<'_>,
) -> Result<(), IoError> {
    let sides = soup.face_indices.len() - start;
    if sides < 3 {
        return Err(ctx.too_small(at, sides as u64));
    }
    if soup.close_face().is_none() {
        return Err(ctx.too_large(at, "more than 2^32-1 face indices"));
    }
    if let Some(l) = line {
        soup.face_lines.push(l);
    }
    Ok(())
}

/// Appends the triangles of a strip list (-1 restarts; odd triangles are
/// flipped; degenerate ones skipped). Indices must already be checked.
fn push_strips(
    soup: &mut PolygonSoup,
    strip: &[i64],
    at: Location,
    line: Option<u32>,
    ctx: Ctx<'_>,
) -> Result<(), IoError> {
    for seg in strip.split(|&v| v == -1) {
        for (i, w) in seg.windows(3).enumerate() {
            let [a, b, c] = [w[0] as u32, w[1] as u32, w[2] as u32];
            if a == b || b == c || a == c {
                continue;
            }
            let tri = if i % 2 == 0 { [a, b, c] } else { [b, a, c] };
            let start = soup.face_indices.len();
            soup.face_indices.extend_from_slice(&tri);
            close_face(soup, start, at, line, ctx)?;
        }
    }
    Ok(())
}

#[inline(always)]
fn arr<const N: usize>(b: &[u8]) -> [u8; N] {
    let mut a = [0u8; N];
    a.copy_from_slice(&b[..N]);
    a
}

/// Reads a `$ty` of `$n` bytes from the start of `$b`, big-endian when `$be`.
macro_rules! decode {
    ($b:expr, $be:expr, $ty:ty, $n:literal) => {{
        let a = arr::<$n>($b);
        if $be {
            <$ty>::from_be_bytes(a)
        } else {
            <$ty>::from_le_bytes(a)
        }
    }};
}

/// What a decoded scalar is read as: integers are at most 32 bits, so both
/// conversions from an integer are exact.
trait FromScalar {
    fn from_int(i: i64) -> Self;
    fn from_float(x: f64) -> Self;
}

impl FromScalar for f64 {
    #[inline(always)]
    fn from_int(i: i64) -> f64 {
        i as f64
    }
    #[inline(always)]
    fn from_float(x: f64) -> f64 {
        x
    }
}

/// Floats read where an integer is wanted are truncated.
impl FromScalar for i64 {
    #[inline(always)]
    fn from_int(i: i64) -> i64 {
        i
    }
    #[inline(always)]
    fn from_float(x: f64) -> i64 {
        x as i64
    }
}

/// Decodes a scalar at the start of `b` (which holds at least its size).
#[inline(always)]
fn load<const BE: bool, T: FromScalar>(t: Scalar, b: &[u8]) -> T {
    match t {
        Scalar::I8 => T::from_int(decode!(b, BE, i8, 1).into()),
        Scalar::U8 => T::from_int(decode!(b, BE, u8, 1).into()),
        Scalar::I16 => T::from_int(decode!(b, BE, i16, 2).into()),
        Scalar::U16 => T::from_int(decode!(b, BE, u16, 2).into()),
        Scalar::I32 => T::from_int(decode!(b, BE, i32, 4).into()),
        Scalar::U32 => T::from_int(decode!(b, BE, u32, 4).into()),
        Scalar::F32 => T::from_float(decode!(b, BE, f32, 4).into()),
        Scalar::F64 => T::from_float(decode!(b, BE, f64, 8)),
    }
}

/// Decodes a scalar at the start of `b` as a double.
#[inline(always)]
fn load_f64<const BE: bool>(t: Scalar, b: &[u8]) -> f64 {
    load::<BE, f64>(t, b)
}

/// Decodes an integer scalar at the start of `b`; floats are truncated.
#[inline(always)]
fn load_i64<const BE: bool>(t: Scalar, b: &[u8]) -> i64 {
    load::<BE, i64>(t, b)
}

fn off(pos: usize) -> Location {
    Location::Offset(pos as u64)
}

fn record_name(el: &Element, r: u64) -> String {
    format!(
        "record {} of {} of element '{}'",
        r + 1,
        el.count,
        show(&el.name)
    )
}

/// Reads the body of a binary PLY file, element by element.
fn read_binary<const BE: bool>(
    body: &Body<'_>,
    mut soup: PolygonSoup,
    ctx: Ctx<'_>,
) -> Result<PolygonSoup, IoError> {
    let Body { buf, hdr, .. } = *body;
    let mut pos = hdr.body;
    let mut strip: Vec<i64> = Vec::new();
    for (el, &role) in hdr.elements.iter().zip(body.roles) {
        if el.props.is_empty() || el.count == 0 {
            continue;
        }
        let remaining = buf.len() - pos;
        let all_scalar = el.props.iter().all(|p| matches!(p.kind, Kind::Scalar(_)));
        if all_scalar {
            // Fixed-size records: check the whole element fits, then decode.
            let stride: usize = el.props.iter().map(|p| prop_min_size(p.kind)).sum();
            let need = usize::try_from(el.count)
                .ok()
                .and_then(|n| n.checked_mul(stride))
                .filter(|&need| need <= remaining);
            let Some(need) = need else {
                let have = remaining / stride;
                return Err(ctx.eof(off(buf.len()), record_name(el, have as u64)));
            };
            if let Role::Vertex(xyz) = role {
                let records = &buf[pos..pos + need];
                read_vertices_fixed::<BE>(records, pos, el, xyz, stride, &mut soup, ctx)?;
                read_columns_fixed::<BE>(records, el, body.columns, stride, &mut soup);
            }
            pos += need;
        } else if let (Role::Faces(0), [prop]) = (role, &el.props[..])
            && let Kind::List { count, item } = prop.kind
        {
            // A valid face holds at least 3 indices.
            let cap = usize::try_from(el.count)
                .unwrap_or(usize::MAX)
                .min(remaining / (count.size() + 3 * item.size()));
            let _ = soup.face_offsets.try_reserve(cap);
            let _ = soup.face_indices.try_reserve(cap.saturating_mul(3));
            pos = faces_single_list::<BE>(buf, pos, el, count, item, body.nv, &mut soup, ctx)?;
        } else {
            pos = read_records::<BE>(body, el, role, pos, &mut soup, &mut strip, ctx)?;
        }
    }
    Ok(soup)
}

/// Reads one binary element of variable-size records (lists beside other properties) from
/// `pos`, property by property; returns the position after it.
fn read_records<const BE: bool>(
    body: &Body<'_>,
    el: &Element,
    role: Role,
    mut pos: usize,
    soup: &mut PolygonSoup,
    strip: &mut Vec<i64>,
    ctx: Ctx<'_>,
) -> Result<usize, IoError> {
    let Body { buf, nv, .. } = *body;
    let mut min_size: usize = el.props.iter().map(|p| prop_min_size(p.kind)).sum();
    if let Role::Faces(k) = role
        && let Kind::List { item, .. } = el.props[k].kind
    {
        min_size += 3 * item.size(); // a valid face holds at least 3 indices
    }
    let cap = usize::try_from(el.count)
        .unwrap_or(usize::MAX)
        .min((buf.len() - pos) / min_size);
    match role {
        Role::Vertex(_) => {
            let _ = soup.positions.try_reserve(cap);
        }
        Role::Faces(_) => {
            let _ = soup.face_offsets.try_reserve(cap);
            let _ = soup.face_indices.try_reserve(cap.saturating_mul(3));
        }
        _ => {}
    }
    for r in 0..el.count {
        let rec = pos;
        let face_start = soup.face_indices.len();
        let mut p3 = [0.0f64; 3];
        for (pi, p) in el.props.iter().enumerate() {
            match p.kind {
                Kind::Scalar(t) => {
                    let Some(b) = buf.get(pos..pos + t.size()) else {
                        return Err(ctx.eof(off(buf.len()), record_name(el, r)));
                    };
                    if let Role::Vertex(xyz) = role
                        && let Some(axis) = xyz.iter().position(|&k| k == pi)
                    {
                        let v = load_f64::<BE>(t, b);
                        p3[axis] = ctx.coordinate(off(pos), soup.positions.len(), v)?;
                    } else if let Role::Vertex(_) = role
                        && let Some(column) = soup.attributes.vertex.get_mut(body.columns[pi])
                    {
                        column.values.push(load_f64::<BE>(t, b));
                    }
                    pos += t.size();
                }
                Kind::List { count, item } => {
                    let Some(b) = buf.get(pos..pos + count.size()) else {
                        return Err(ctx.eof(off(buf.len()), record_name(el, r)));
                    };
                    let n = load_i64::<BE>(count, b);
                    if n < 0 {
                        return Err(ctx.parse(off(pos), format!("negative list length {n}")));
                    }
                    pos += count.size();
                    let isz = item.size();
                    let end = (n as u64)
                        .checked_mul(isz as u64)
                        .and_then(|bytes| (pos as u64).checked_add(bytes))
                        .filter(|&end| end <= buf.len() as u64);
                    let Some(end) = end else {
                        return Err(ctx.eof(off(buf.len()), record_name(el, r)));
                    };
                    let end = end as usize;
                    let items = &buf[pos..end];
                    match role {
                        Role::Faces(k) if k == pi => {
                            for (j, b) in items.chunks_exact(isz).enumerate() {
                                let v = load_i64::<BE>(item, b);
                                let i = check_index(v, nv, || off(pos + j * isz), ctx)?;
                                soup.face_indices.push(i);
                            }
                        }
                        Role::Strips(k) if k == pi => {
                            strip.clear();
                            let _ = strip.try_reserve(n as usize);
                            for (j, b) in items.chunks_exact(isz).enumerate() {
                                let v = load_i64::<BE>(item, b);
                                if v != -1 {
                                    check_index(v, nv, || off(pos + j * isz), ctx)?;
                                }
                                strip.push(v);
                            }
                            push_strips(soup, strip, off(rec), None, ctx)?;
                        }
                        _ => {}
                    }
                    pos = end;
                }
            }
        }
        match role {
            Role::Vertex(_) => soup.positions.push(p3),
            Role::Faces(_) => close_face(soup, face_start, off(rec), None, ctx)?,
            _ => {}
        }
    }
    Ok(pos)
}

/// Size of a scalar, or of a list's count (its minimum size).
fn prop_min_size(k: Kind) -> usize {
    match k {
        Kind::Scalar(t) => t.size(),
        Kind::List { count, .. } => count.size(),
    }
}

/// Decodes the attribute columns of fixed-size vertex records (`data` holds exactly `count`
/// records), one column at a time.
fn read_columns_fixed<const BE: bool>(
    data: &[u8],
    el: &Element,
    columns: &[usize],
    stride: usize,
    soup: &mut PolygonSoup,
) {
    let mut offset = 0;
    for (p, &column) in el.props.iter().zip(columns) {
        let size = prop_min_size(p.kind);
        if let (Kind::Scalar(t), Some(column)) = (p.kind, soup.attributes.vertex.get_mut(column)) {
            column.values.extend(
                data.chunks_exact(stride)
                    .map(|rec| load_f64::<BE>(t, &rec[offset..])),
            );
        }
        offset += size;
    }
}

/// Decodes fixed-size vertex records; `data` holds exactly `count` records.
fn read_vertices_fixed<const BE: bool>(
    data: &[u8],
    base: usize,
    el: &Element,
    xyz: [usize; 3],
    stride: usize,
    soup: &mut PolygonSoup,
    ctx: Ctx<'_>,
) -> Result<(), IoError> {
    let mut offs = [0usize; 3];
    let mut types = [Scalar::F32; 3];
    for axis in 0..3 {
        offs[axis] = el.props[..xyz[axis]]
            .iter()
            .map(|p| prop_min_size(p.kind))
            .sum();
        if let Kind::Scalar(t) = el.props[xyz[axis]].kind {
            types[axis] = t;
        }
    }
    let _ = soup.positions.try_reserve(data.len() / stride);
    // Monomorphized loops for the usual all-float / all-double layouts.
    match types {
        [Scalar::F32, Scalar::F32, Scalar::F32] => {
            vertex_loop(data, base, offs, stride, soup, ctx, |_, b| {
                f64::from(load_f32::<BE>(b))
            })
        }
        [Scalar::F64, Scalar::F64, Scalar::F64] => {
            vertex_loop(data, base, offs, stride, soup, ctx, |_, b| {
                let a = arr::<8>(b);
                if BE {
                    f64::from_be_bytes(a)
                } else {
                    f64::from_le_bytes(a)
                }
            })
        }
        _ => vertex_loop(data, base, offs, stride, soup, ctx, |axis, b| {
            load_f64::<BE>(types[axis], b)
        }),
    }
}

#[inline(always)]
fn load_f32<const BE: bool>(b: &[u8]) -> f32 {
    let a = arr::<4>(b);
    if BE {
        f32::from_be_bytes(a)
    } else {
        f32::from_le_bytes(a)
    }
}

#[inline(always)]
fn vertex_loop(
    data: &[u8],
    base: usize,
    offs: [usize; 3],
    stride: usize,
    soup: &mut PolygonSoup,
    ctx: Ctx<'_>,
    load: impl Fn(usize, &[u8]) -> f64,
) -> Result<(), IoError> {
    for (i, rec) in data.chunks_exact(stride).enumerate() {
        let x = load(0, &rec[offs[0]..]);
        let y = load(1, &rec[offs[1]..]);
        let z = load(2, &rec[offs[2]..]);
        let p = [x, y, z];
        let finite = x.is_finite() && y.is_finite() && z.is_finite();
        if !(finite || ctx.keeps_non_finite()) {
            let axis = p.iter().position(|c| !c.is_finite()).unwrap_or(0);
            let at = off(base + i * stride + offs[axis]);
            return Err(ctx.non_finite(at, soup.positions.len(), p[axis]));
        }
        soup.positions.push(p);
    }
    Ok(())
}

/// Reads a `face` element whose only property is the index list; returns
/// the position after it.
#[allow(clippy::too_many_arguments)]
fn faces_single_list<const BE: bool>(
    buf: &[u8],
    pos: usize,
    el: &Element,
    count: Scalar,
    item: Scalar,
    nv: u64,
    soup: &mut PolygonSoup,
    ctx: Ctx<'_>,
) -> Result<usize, IoError> {
    let i32_item = |b: &[u8]| {
        let a = arr::<4>(b);
        i64::from(if BE {
            i32::from_be_bytes(a)
        } else {
            i32::from_le_bytes(a)
        })
    };
    let u32_item = |b: &[u8]| {
        let a = arr::<4>(b);
        i64::from(if BE {
            u32::from_be_bytes(a)
        } else {
            u32::from_le_bytes(a)
        })
    };
    let u8_count = |b: &[u8]| i64::from(b[0]);
    let any_count = |b: &[u8]| load_i64::<BE>(count, b);
    let any_item = |b: &[u8]| load_i64::<BE>(item, b);
    let (cs, is) = (count.size(), item.size());
    match (count, item) {
        (Scalar::U8, Scalar::I32) => {
            face_loop(buf, pos, el, u8_count, 1, i32_item, 4, nv, soup, ctx)
        }
        (Scalar::U8, Scalar::U32) => {
            face_loop(buf, pos, el, u8_count, 1, u32_item, 4, nv, soup, ctx)
        }
        _ => face_loop(buf, pos, el, any_count, cs, any_item, is, nv, soup, ctx),
    }
}

#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn face_loop(
    buf: &[u8],
    mut pos: usize,
    el: &Element,
    load_count: impl Fn(&[u8]) -> i64,
    cs: usize,
    load_item: impl Fn(&[u8]) -> i64,
    is: usize,
    nv: u64,
    soup: &mut PolygonSoup,
    ctx: Ctx<'_>,
) -> Result<usize, IoError> {
    for r in 0..el.count {
        let rec = pos;
        let Some(cb) = buf.get(pos..pos + cs) else {
            return Err(ctx.eof(off(buf.len()), record_name(el, r)));
        };
        let n = load_count(cb);
        if n < 0 {
            return Err(ctx.parse(off(pos), format!("negative list length {n}")));
        }
        pos += cs;
        let end = (n as u64)
            .checked_mul(is as u64)
            .and_then(|bytes| (pos as u64).checked_add(bytes))
            .filter(|&end| end <= buf.len() as u64);
        let Some(end) = end else {
            return Err(ctx.eof(off(buf.len()), record_name(el, r)));
        };
        let end = end as usize;
        let start = soup.face_indices.len();
        for (j, b) in buf[pos..end].chunks_exact(is).enumerate() {
            let v = load_item(b);
            if v < 0 || v as u64 >= nv {
                return Err(ctx.index(off(pos + j * is), v, nv));
            }
            soup.face_indices.push(v as u32);
        }
        close_face(soup, start, off(rec), None, ctx)?;
        pos = end;
    }
    Ok(pos)
}

/// Reads the body of an ASCII PLY file, record by record.
fn read_ascii(
    body: &Body<'_>,
    mut soup: PolygonSoup,
    ctx: Ctx<'_>,
) -> Result<PolygonSoup, IoError> {
    let Body {
        buf,
        hdr,
        roles,
        columns,
        nv,
    } = *body;
    let mut lx = Lexer::new(buf);
    lx.pos = hdr.body;
    lx.line = hdr.body_line;
    let mut strip: Vec<i64> = Vec::new();
    for (el, &role) in hdr.elements.iter().zip(roles) {
        if el.props.is_empty() {
            continue;
        }
        let remaining = buf.len().saturating_sub(lx.pos);
        let cap = usize::try_from(el.count).unwrap_or(usize::MAX);
        match role {
            Role::Vertex(_) => {
                let _ = soup.positions.try_reserve(cap.min(remaining / 6));
            }
            Role::Faces(_) => {
                let cap = cap.min(remaining / 8);
                let _ = soup.face_offsets.try_reserve(cap);
                let _ = soup.face_lines.try_reserve(cap);
                let _ = soup.face_indices.try_reserve(cap * 3);
            }
            _ => {}
        }
        for r in 0..el.count {
            lx.skip_space(None);
            if lx.is_eof() {
                return Err(ctx.eof(lx.at(), record_name(el, r)));
            }
            let line = lx.line_u32();
            let rec_at = lx.at();
            let face_start = soup.face_indices.len();
            let mut p3 = [0.0f64; 3];
            for (pi, p) in el.props.iter().enumerate() {
                lx.skip_space(None);
                match p.kind {
                    Kind::Scalar(t) => {
                        let (axis, column) = match role {
                            Role::Vertex(xyz) => (xyz.iter().position(|&k| k == pi), columns[pi]),
                            _ => (None, NO_COLUMN),
                        };
                        if let Some(axis) = axis {
                            p3[axis] = match lx.f64() {
                                Ok(v) => ctx.coordinate(lx.at(), soup.positions.len(), v)?,
                                Err(e) => {
                                    let what = format!("vertex {}", show(&p.name));
                                    return Err(lx.num_error(ctx, e, &what));
                                }
                            };
                        } else if let Some(column) = soup.attributes.vertex.get_mut(column) {
                            let what = || format!("vertex {}", show(&p.name));
                            let value = match lx.f64() {
                                Ok(v) if t == Scalar::F32 => f64::from(v as f32),
                                Ok(v) if t.holds(v) => v,
                                Ok(v) => {
                                    let message =
                                        format!("{} {v} is not a {}", what(), t.ply_name());
                                    return Err(ctx.parse(lx.at(), message));
                                }
                                Err(e) => return Err(lx.num_error(ctx, e, &what())),
                            };
                            column.values.push(value);
                        } else if lx.token().is_empty() {
                            return Err(ctx.eof(lx.at(), record_name(el, r)));
                        }
                    }
                    Kind::List { .. } => {
                        let n = match lx.u64() {
                            Ok(n) => n,
                            Err(e) => return Err(lx.num_error(ctx, e, "list length")),
                        };
                        let target = matches!(role, Role::Faces(k) | Role::Strips(k) if k == pi);
                        strip.clear();
                        for _ in 0..n {
                            lx.skip_space(None);
                            if !target {
                                if lx.token().is_empty() {
                                    return Err(ctx.eof(lx.at(), record_name(el, r)));
                                }
                                continue;
                            }
                            let v = match lx.i64() {
                                Ok(v) => v,
                                Err(e) => return Err(lx.num_error(ctx, e, "vertex index")),
                            };
                            if let Role::Strips(_) = role {
                                if v != -1 {
                                    check_index(v, nv, || lx.at(), ctx)?;
                                }
                                strip.push(v);
                            } else {
                                let i = check_index(v, nv, || lx.at(), ctx)?;
                                soup.face_indices.push(i);
                            }
                        }
                        if target && matches!(role, Role::Strips(_)) {
                            push_strips(&mut soup, &strip, rec_at, Some(line), ctx)?;
                        }
                    }
                }
            }
            match role {
                Role::Vertex(_) => soup.positions.push(p3),
                Role::Faces(_) => close_face(&mut soup, face_start, rec_at, Some(line), ctx)?,
                _ => {}
            }
        }
    }
    Ok(soup)
}
