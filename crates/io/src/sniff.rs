//! The format of a mesh file told from its content, for inputs whose name does not say it
//! (standard input, a file without a mesh extension).
//!
//! The tests, in order (the first that matches decides):
//! 1. PLY: the file starts with the line `ply` (the PLY magic).
//! 2. OFF: the first token (after blanks and `#` comments) is an OFF keyword (`OFF`, `COFF`,
//!    `NOFF`, `STOFF`, `nOFF`, ...). An OFF file without its optional keyword is not recognised.
//! 3. Binary STL: the length is exactly 84 + 50·n bytes, n the count at bytes 80..84. Text cannot
//!    pass this by accident: four printable bytes read as n ≥ 0x2020_2020, a file of 27 GB.
//! 4. ASCII STL: the first token is `solid` and a `facet` token follows within the first
//!    [`WINDOW`] bytes (or the bytes are not text: a binary STL whose header says `solid` and
//!    whose length is off, which the STL reader then reads as binary).
//! 5. OBJ: each of the first statement lines (up to 1000, comments and blank lines not counted)
//!    starts with an OBJ keyword, and one of them is `v` or `f`.
//!
//! Anything else is undecidable ([`IoError::UnknownContent`]): a name with the extension, or
//! `--format` in the CLI where it applies, is then needed. gzip data (the magic `1f 8b`) is
//! recognised by [`is_gzip`] and sniffed after decompression.

use crate::{Format, IoError};

/// How many leading bytes the OFF and STL tests look at: enough for any header, bounded so that
/// sniffing a large file costs nothing.
pub const WINDOW: usize = 1 << 16;

/// Whether `bytes` start with the gzip magic `1f 8b`.
pub fn is_gzip(bytes: &[u8]) -> bool {
    bytes.starts_with(&[0x1f, 0x8b])
}

/// The statements a Wavefront OBJ file may hold (the OBJ specification's keywords).
const OBJ_KEYWORDS: &[&[u8]] = &[
    b"v",
    b"vt",
    b"vn",
    b"vp",
    b"f",
    b"l",
    b"p",
    b"o",
    b"g",
    b"s",
    b"mg",
    b"usemtl",
    b"mtllib",
    b"cstype",
    b"deg",
    b"bmat",
    b"step",
    b"curv",
    b"curv2",
    b"surf",
    b"parm",
    b"trim",
    b"hole",
    b"scrv",
    b"sp",
    b"end",
    b"con",
    b"bevel",
    b"c_interp",
    b"d_interp",
    b"lod",
    b"shadow_obj",
    b"trace_obj",
    b"ctech",
    b"stech",
    b"call",
    b"csh",
    b"maplib",
    b"usemap",
];

/// The format of an uncompressed mesh file from its content (see the module's rules).
///
/// # Errors
/// [`IoError::UnknownContent`] naming `name` and why no rule matched.
pub fn sniff_format(bytes: &[u8], name: &str) -> Result<Format, IoError> {
    let unknown = |reason: String| IoError::UnknownContent {
        file: name.to_owned(),
        reason,
    };
    if bytes.is_empty() {
        return Err(unknown("the input is empty".into()));
    }
    if bytes.starts_with(b"ply\n") || bytes.starts_with(b"ply\r\n") {
        return Ok(Format::Ply);
    }
    let window = &bytes[..bytes.len().min(WINDOW)];
    let first = first_token(window);
    if is_off_keyword(first) {
        return Ok(Format::Off);
    }
    if is_binary_stl_size(bytes) {
        return Ok(Format::Stl);
    }
    if first.eq_ignore_ascii_case(b"solid")
        && (tokens(window).any(|t| t.eq_ignore_ascii_case(b"facet")) || !is_text(window))
    {
        return Ok(Format::Stl);
    }
    match obj_statements(bytes) {
        Ok(true) => Ok(Format::Obj),
        Ok(false) => Err(unknown(
            "no PLY or OFF header, not binary STL (the size is not 84 + 50·n bytes), no ASCII \
             STL facet, no OBJ vertex or face"
                .into(),
        )),
        Err(line) => Err(unknown(format!(
            "no PLY or OFF header, not binary STL (the size is not 84 + 50·n bytes), not ASCII \
             STL, and line {line} starts with no OBJ keyword"
        ))),
    }
}

/// Whether the length is 84 + 50·n with n the little-endian count at bytes 80..84.
fn is_binary_stl_size(bytes: &[u8]) -> bool {
    bytes.get(80..84).is_some_and(|b| {
        let n = u64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]]));
        84 + 50 * n == bytes.len() as u64
    })
}

/// Whether `token` is an OFF keyword: `OFF` after a prefix of letters and digits (`C`, `N`,
/// `ST`, `n`, `4`, ...), as the OFF reader accepts.
fn is_off_keyword(token: &[u8]) -> bool {
    token.len() >= 3
        && token[token.len() - 3..].eq_ignore_ascii_case(b"OFF")
        && token[..token.len() - 3]
            .iter()
            .all(u8::is_ascii_alphanumeric)
}

/// Whether the bytes hold no NUL, no C0 control other than blanks and line breaks, and no byte
/// of 0x80 and above that is not valid UTF-8.
fn is_text(bytes: &[u8]) -> bool {
    let valid = match std::str::from_utf8(bytes) {
        Ok(_) => true,
        // A window may cut a character: only an error before the last 3 bytes counts.
        Err(e) => e.error_len().is_none() && e.valid_up_to() + 4 > bytes.len(),
    };
    valid
        && bytes
            .iter()
            .all(|&b| b >= 0x20 || matches!(b, b'\t' | b'\n' | 0x0b | 0x0c | b'\r'))
}

/// The whitespace-separated tokens of `bytes`.
fn tokens(bytes: &[u8]) -> impl Iterator<Item = &[u8]> {
    bytes
        .split(|b| b.is_ascii_whitespace())
        .filter(|t| !t.is_empty())
}

/// The first token after blanks and `#` comment lines.
fn first_token(bytes: &[u8]) -> &[u8] {
    bytes
        .split(|&b| b == b'\n')
        .map(|line| line.split(|&b| b == b'#').next().unwrap_or_default())
        .find_map(|line| tokens(line).next())
        .unwrap_or_default()
}

/// How many statements the OBJ test reads: enough to see a file's first vertices, bounded so
/// that sniffing a large file costs nothing.
const OBJ_STATEMENTS: usize = 1000;

/// Whether the statement lines of `bytes` are OBJ: `Ok(true)` when each of the first
/// [`OBJ_STATEMENTS`] starts with an OBJ keyword and one is `v` or `f`, `Ok(false)` when all do
/// but none is, `Err(line)` (1-based) for the first that does not. Comment and blank lines do
/// not count; a line continued with `\` is one statement.
fn obj_statements(bytes: &[u8]) -> Result<bool, u64> {
    let mut geometry = false;
    let mut continued = false;
    let mut statements = 0;
    for (index, line) in bytes.split(|&b| b == b'\n').enumerate() {
        let was_continued = continued;
        let body = line.strip_suffix(b"\r").unwrap_or(line);
        continued = body.ends_with(b"\\");
        if was_continued {
            continue;
        }
        let Some(keyword) = tokens(body).next() else {
            continue;
        };
        if keyword.starts_with(b"#") {
            continue;
        }
        if !OBJ_KEYWORDS.contains(&keyword) {
            return Err(index as u64 + 1);
        }
        geometry |= keyword == b"v" || keyword == b"f";
        statements += 1;
        if statements == OBJ_STATEMENTS && geometry {
            break;
        }
    }
    Ok(geometry)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sniff(bytes: &[u8]) -> Option<Format> {
        sniff_format(bytes, "x").ok()
    }

    #[test]
    fn each_format_is_told_by_its_own_rule() {
        assert_eq!(
            sniff(b"ply\nformat ascii 1.0\nend_header\n"),
            Some(Format::Ply)
        );
        assert_eq!(sniff(b"# made by hand\n\nCOFF\n3 1 0\n"), Some(Format::Off));
        assert_eq!(sniff(b"OFF 4 4 6\n"), Some(Format::Off));
        let mut stl = vec![b' '; 80];
        stl.extend_from_slice(&2u32.to_le_bytes());
        stl.extend_from_slice(&[0; 100]);
        assert_eq!(sniff(&stl), Some(Format::Stl));
        stl[..5].copy_from_slice(b"solid");
        assert_eq!(sniff(&stl), Some(Format::Stl), "a binary STL saying solid");
        assert_eq!(
            sniff(b"solid x\n facet normal 0 0 1\n outer loop\n"),
            Some(Format::Stl)
        );
        assert_eq!(
            sniff(b"# cube\nmtllib a.mtl\no cube\nv 0 0 0\nvt 0 0\nf 1 2 3\n"),
            Some(Format::Obj)
        );
        assert_eq!(sniff(b"v 0 0 0 \\\n  extra\nf 1 1 1\n"), Some(Format::Obj));
    }

    #[test]
    fn other_content_is_undecidable_and_says_why() {
        let e = sniff_format(b"", "<stdin>").unwrap_err();
        assert_eq!(e.to_string().matches("empty").count(), 1, "{e}");
        assert!(e.to_string().starts_with("<stdin>: "), "{e}");
        let e = sniff_format(b"v 0 0 0\nhello world\n", "m").unwrap_err();
        assert!(e.to_string().contains("line 2"), "{e}");
        assert_eq!(sniff(b"# only a comment\ng group\n"), None);
        assert_eq!(sniff(b"solid nothing\nendsolid\n"), None);
        assert_eq!(sniff(b"4 4 6\n0 0 0\n"), None, "OFF without its keyword");
        assert_eq!(sniff(b"plywood\n"), None);
        assert_eq!(sniff(b"\x00\x01\x02"), None);
    }

    #[test]
    fn a_long_comment_before_the_vertices_is_still_obj() {
        let mut obj = b"#".repeat(WINDOW + 10);
        obj.extend_from_slice(b"\nusemtl a\nv 0 0 0\nf 1 1 1\n");
        assert_eq!(sniff(&obj), Some(Format::Obj));
        let mut many = b"v 0 0 0\n".repeat(OBJ_STATEMENTS);
        many.extend_from_slice(b"not obj\n");
        assert_eq!(
            sniff(&many),
            Some(Format::Obj),
            "only the first statements are read"
        );
    }

    #[test]
    fn gzip_magic() {
        assert!(is_gzip(&[0x1f, 0x8b, 8, 0]));
        assert!(!is_gzip(b"ply\n"));
    }
}
