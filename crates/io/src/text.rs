//! Byte-level lexer and number parsing shared by the text formats (OBJ, OFF,
//! ascii PLY, ascii STL). Works on the whole input in memory, tracks the
//! 1-based line, never allocates.

use crate::error::{Ctx, IoError, Location};

/// Blank within a line: space, tab, CR (so CRLF works), vertical tab, form feed.
#[inline]
pub(crate) fn is_blank(b: u8) -> bool {
    matches!(b, b' ' | b'\t' | b'\r' | 0x0b | 0x0c)
}

/// Why a number could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum NumErr {
    /// End of line or end of input where a number was expected.
    Missing,
    /// A token that is not a valid number of the expected kind.
    Bad,
}

/// Cursor over a text buffer.
pub(crate) struct Lexer<'a> {
    pub buf: &'a [u8],
    pub pos: usize,
    /// 1-based line of `pos`.
    pub line: u64,
    /// Treat `\` + newline as a blank (OBJ line continuation).
    continuation: bool,
}

impl<'a> Lexer<'a> {
    /// Starts at the beginning of `buf`, skipping a UTF-8 byte order mark.
    pub fn new(buf: &'a [u8]) -> Self {
        let pos = if buf.starts_with(b"\xEF\xBB\xBF") {
            3
        } else {
            0
        };
        Lexer {
            buf,
            pos,
            line: 1,
            continuation: false,
        }
    }

    /// Enables `\` line continuation.
    pub fn with_continuation(mut self) -> Self {
        self.continuation = true;
        self
    }

    /// Current line as a location.
    #[inline]
    pub fn at(&self) -> Location {
        Location::Line(self.line)
    }

    /// Current line, saturated to `u32` (for `face_lines`).
    #[inline]
    pub fn line_u32(&self) -> u32 {
        u32::try_from(self.line).unwrap_or(u32::MAX)
    }

    #[inline]
    pub fn peek(&self) -> Option<u8> {
        self.buf.get(self.pos).copied()
    }

    #[inline]
    pub fn peek_at(&self, k: usize) -> Option<u8> {
        self.buf.get(self.pos.wrapping_add(k)).copied()
    }

    #[inline]
    pub fn is_eof(&self) -> bool {
        self.pos >= self.buf.len()
    }

    /// True at end of line or end of input.
    #[inline]
    pub fn at_eol(&self) -> bool {
        matches!(self.peek(), None | Some(b'\n'))
    }

    /// True when byte `pos + k` ends a token (blank, newline or end of input).
    #[inline]
    pub fn ends_token_at(&self, k: usize) -> bool {
        match self.peek_at(k) {
            None | Some(b'\n') => true,
            Some(b'\\') => self.continuation && self.continuation_at(self.pos + k),
            Some(b) => is_blank(b),
        }
    }

    /// True when `\` [CR] LF starts at `i`.
    fn continuation_at(&self, i: usize) -> bool {
        let b = &self.buf[i.min(self.buf.len())..];
        b.starts_with(b"\\\n") || b.starts_with(b"\\\r\n")
    }

    /// Skips blanks within the line (and `\`-newline if continuation is on).
    #[inline]
    pub fn skip_blank(&mut self) {
        while let Some(&b) = self.buf.get(self.pos) {
            match b {
                _ if is_blank(b) => self.pos += 1,
                b'\\' if self.continuation && self.try_continuation() => {}
                _ => break,
            }
        }
    }

    /// At a `\`: consumes `\` [CR] LF and returns true, or returns false.
    fn try_continuation(&mut self) -> bool {
        let mut k = self.pos + 1;
        if self.buf.get(k) == Some(&b'\r') {
            k += 1;
        }
        if self.buf.get(k) == Some(&b'\n') {
            self.pos = k + 1;
            self.line += 1;
            true
        } else {
            false
        }
    }

    /// Consumes a newline if there is one.
    #[inline]
    pub fn newline(&mut self) -> bool {
        if self.peek() == Some(b'\n') {
            self.pos += 1;
            self.line += 1;
            true
        } else {
            false
        }
    }

    /// Skips to the start of the next line (or the end of input).
    #[inline]
    pub fn skip_line(&mut self) {
        loop {
            match self.buf[self.pos.min(self.buf.len())..]
                .iter()
                .position(|&b| b == b'\n')
            {
                Some(k) => {
                    let nl = self.pos + k;
                    self.pos = nl + 1;
                    self.line += 1;
                    if self.continuation && self.continued_before(nl) {
                        continue;
                    }
                }
                None => self.pos = self.buf.len(),
            }
            return;
        }
    }

    /// True when the newline at `nl` is preceded by `\` (optionally `\` CR).
    fn continued_before(&self, nl: usize) -> bool {
        let mut k = nl;
        if k > 0 && self.buf[k - 1] == b'\r' {
            k -= 1;
        }
        k > 0 && self.buf[k - 1] == b'\\'
    }

    /// Skips blanks, newlines and, when `comment` is given, comments running
    /// from that byte to the end of the line.
    pub fn skip_space(&mut self, comment: Option<u8>) {
        loop {
            self.skip_blank();
            match self.peek() {
                Some(b'\n') => {
                    self.pos += 1;
                    self.line += 1;
                }
                Some(c) if Some(c) == comment => self.skip_line(),
                _ => return,
            }
        }
    }

    /// The token at the cursor (after blanks), without consuming it.
    pub fn peek_token(&mut self) -> &'a [u8] {
        self.skip_blank();
        let buf = self.buf;
        let start = self.pos.min(buf.len());
        let mut len = 0;
        while start + len < buf.len() && !self.ends_token_at(start + len - self.pos) {
            len += 1;
        }
        &buf[start..start + len]
    }

    /// The next token on the line (empty at end of line).
    pub fn token(&mut self) -> &'a [u8] {
        let t = self.peek_token();
        self.pos += t.len();
        t
    }

    /// Reads a float on the current line.
    #[inline]
    pub fn f64(&mut self) -> Result<f64, NumErr> {
        self.skip_blank();
        let rest = self.buf.get(self.pos..).unwrap_or(&[]);
        if matches!(rest.first(), None | Some(b'\n')) {
            return Err(NumErr::Missing);
        }
        match fast_float2::parse_partial::<f64, _>(rest) {
            Ok((v, n)) if n > 0 && self.ends_token_at(n) => {
                self.pos += n;
                Ok(v)
            }
            _ => Err(NumErr::Bad),
        }
    }

    /// Reads a non-negative integer on the current line.
    #[inline]
    pub fn u64(&mut self) -> Result<u64, NumErr> {
        self.skip_blank();
        let rest = self.buf.get(self.pos..).unwrap_or(&[]);
        if matches!(rest.first(), None | Some(b'\n')) {
            return Err(NumErr::Missing);
        }
        match parse_u64_prefix(rest) {
            Some((v, n)) if self.ends_token_at(n) => {
                self.pos += n;
                Ok(v)
            }
            _ => Err(NumErr::Bad),
        }
    }

    /// Reads a signed integer on the current line.
    #[inline]
    pub fn i64(&mut self) -> Result<i64, NumErr> {
        self.skip_blank();
        let rest = self.buf.get(self.pos..).unwrap_or(&[]);
        if matches!(rest.first(), None | Some(b'\n')) {
            return Err(NumErr::Missing);
        }
        match parse_i64_prefix(rest) {
            Some((v, n)) if self.ends_token_at(n) => {
                self.pos += n;
                Ok(v)
            }
            _ => Err(NumErr::Bad),
        }
    }

    /// Turns a failed number read at the cursor into a located error:
    /// end of input gives `UnexpectedEof`, otherwise a `Parse` error quoting
    /// the offending token.
    #[cold]
    pub fn num_error(&mut self, ctx: Ctx<'_>, err: NumErr, what: &str) -> IoError {
        self.skip_blank();
        match err {
            NumErr::Missing if self.is_eof() => ctx.eof(self.at(), what),
            NumErr::Missing => ctx.parse(self.at(), format!("expected {what}, found end of line")),
            NumErr::Bad => {
                let tok = self.peek_token();
                ctx.parse(self.at(), format!("invalid {what} '{}'", show(tok)))
            }
        }
    }
}

/// Parses `[+]digits` at the start of `s`; `None` if no digit or overflow.
#[inline]
pub(crate) fn parse_u64_prefix(s: &[u8]) -> Option<(u64, usize)> {
    let start = usize::from(s.first() == Some(&b'+'));
    let mut i = start;
    let mut v: u64 = 0;
    while let Some(&b) = s.get(i) {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        v = v.wrapping_mul(10).wrapping_add(u64::from(d));
        i += 1;
    }
    match i - start {
        0 => None,
        // Up to 19 digits cannot overflow.
        1..=19 => Some((v, i)),
        _ => parse_u64_checked(&s[start..i]).map(|v| (v, i)),
    }
}

#[cold]
fn parse_u64_checked(digits: &[u8]) -> Option<u64> {
    digits.iter().try_fold(0u64, |v, &b| {
        v.checked_mul(10)?.checked_add(u64::from(b - b'0'))
    })
}

/// Parses `[+-]digits` at the start of `s`; `None` if no digit or overflow.
#[inline]
pub(crate) fn parse_i64_prefix(s: &[u8]) -> Option<(i64, usize)> {
    if s.first() == Some(&b'-') {
        let (v, n) = parse_u64_prefix(s.get(1..)?)?;
        if s.get(1) == Some(&b'+') {
            return None;
        }
        let v = 0i64.checked_sub_unsigned(v)?;
        Some((v, n + 1))
    } else {
        let (v, n) = parse_u64_prefix(s)?;
        Some((i64::try_from(v).ok()?, n))
    }
}

/// A token for an error message: lossy UTF-8, at most 40 characters, control characters escaped
/// ([`surftopo_mesh::printable`]).
pub(crate) fn show(tok: &[u8]) -> String {
    let s = String::from_utf8_lossy(tok);
    let s = if s.chars().count() > 40 {
        let mut t: String = s.chars().take(40).collect();
        t.push('…');
        std::borrow::Cow::Owned(t)
    } else {
        s
    };
    surftopo_mesh::printable(&s).into_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integers() {
        assert_eq!(parse_u64_prefix(b"123 "), Some((123, 3)));
        assert_eq!(parse_u64_prefix(b"+7"), Some((7, 2)));
        assert_eq!(parse_u64_prefix(b"x"), None);
        assert_eq!(parse_u64_prefix(b"99999999999999999999999"), None);
        assert_eq!(parse_i64_prefix(b"-12/3"), Some((-12, 3)));
        assert_eq!(parse_i64_prefix(b"-+1"), None);
        assert_eq!(
            parse_i64_prefix(b"-9223372036854775808"),
            Some((i64::MIN, 20))
        );
        assert_eq!(parse_i64_prefix(b"9223372036854775808"), None);
        assert_eq!(
            parse_u64_prefix(b"18446744073709551615"),
            Some((u64::MAX, 20))
        );
        assert_eq!(parse_u64_prefix(b"18446744073709551616"), None);
        assert_eq!(
            parse_u64_prefix(b"000000000000000000000042"),
            Some((42, 24))
        );
    }

    #[test]
    fn lexer_lines_and_continuation() {
        let mut lx = Lexer::new(b"a b\\\r\n c\n# x\n\n d").with_continuation();
        assert_eq!(lx.token(), b"a");
        assert_eq!(lx.token(), b"b");
        assert_eq!(lx.token(), b"c");
        assert_eq!(lx.line, 2);
        assert!(lx.newline());
        lx.skip_space(Some(b'#'));
        assert_eq!(lx.line, 5);
        assert_eq!(lx.token(), b"d");
        assert!(lx.is_eof());
    }

    #[test]
    fn numbers() {
        let mut lx = Lexer::new(b" 1.5e3\t-0 nan 1x\n");
        assert_eq!(lx.f64(), Ok(1500.0));
        let z = lx.f64().unwrap();
        assert!(z == 0.0 && z.is_sign_negative());
        assert!(lx.f64().unwrap().is_nan());
        assert_eq!(lx.f64(), Err(NumErr::Bad));
        lx.pos += 2;
        assert_eq!(lx.f64(), Err(NumErr::Missing));
    }
}
