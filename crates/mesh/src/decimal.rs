//! Decimal text of numbers for the text writers (OBJ, OFF, ascii PLY, portalgon JSON, Matrix
//! Market): appended to a byte buffer without `std::fmt`, which is several times slower.
//!
//! Floats are written by `zmij` (Schubfach): the shortest decimal that reads back to the same
//! double, `-0.0` and subnormals included, with an exponent (`1e+308`, `5e-324`) for very large
//! or small magnitudes — the same text `serde_json` writes.

/// Appends the shortest round-trip decimal of a finite `x` (`1.0`, `0.1`, `1e+308`). A
/// non-finite `x` gives `NaN`, `inf` or `-inf` (which no writer of this workspace emits: they
/// check first).
#[inline]
pub fn push_f64(out: &mut Vec<u8>, x: f64) {
    push_short(out, zmij::Buffer::new().format(x).as_bytes());
}

/// Appends the shortest decimal that reads back (as an `f32`) to the same bits of a finite `x`.
#[inline]
pub fn push_f32(out: &mut Vec<u8>, x: f32) {
    out.extend_from_slice(zmij::Buffer::new().format(x).as_bytes());
}

/// Appends the decimal digits of `v` (`0`, `42`).
#[inline]
pub fn push_u64(out: &mut Vec<u8>, v: u64) {
    push_short(out, itoa::Buffer::new().format(v).as_bytes());
}

/// Appends `s` (at most 32 bytes: a formatted number) by copies of known sizes: `s` into a
/// 32-byte array by two overlapping copies, the whole array onto `out`, then `out` truncated. A
/// copy of a known size is a few moves, where one of a variable size is a call to `memcpy` that
/// costs about as much as formatting the number.
#[inline]
fn push_short(out: &mut Vec<u8>, s: &[u8]) {
    let n = s.len();
    let mut text = [0u8; 32];
    if n >= 16 {
        text[..16].copy_from_slice(&s[..16]);
        text[n - 16..n].copy_from_slice(&s[n - 16..]);
    } else if n >= 8 {
        text[..8].copy_from_slice(&s[..8]);
        text[n - 8..n].copy_from_slice(&s[n - 8..]);
    } else if n >= 4 {
        text[..4].copy_from_slice(&s[..4]);
        text[n - 4..n].copy_from_slice(&s[n - 4..]);
    } else if n > 0 {
        // One to three bytes: the first, the middle and the last cover them.
        text[0] = s[0];
        text[n / 2] = s[n / 2];
        text[n - 1] = s[n - 1];
    }
    let start = out.len();
    out.extend_from_slice(&text);
    out.truncate(start + n);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn f(x: f64) -> String {
        let mut out = Vec::new();
        push_f64(&mut out, x);
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn f32_is_the_shortest_decimal_of_the_f32() {
        for x in [0.1f32, 1.0 / 3.0, -1e-7, f32::MAX, f32::MIN_POSITIVE / 8.0] {
            let mut out = Vec::new();
            push_f32(&mut out, x);
            let text = String::from_utf8(out).unwrap();
            assert_eq!(
                text.parse::<f32>().unwrap().to_bits(),
                x.to_bits(),
                "{text}"
            );
            // At most 9 significant digits (an f32 needs no more), not the f64's 17.
            let mantissa = text.split('e').next().unwrap();
            let digits = mantissa.bytes().filter(u8::is_ascii_digit).count();
            assert!(digits <= 10, "{text}");
        }
    }

    #[test]
    fn floats_round_trip() {
        assert_eq!(f(1.0), "1.0");
        assert_eq!(f(-0.0), "-0.0");
        assert_eq!(f(0.1), "0.1");
        assert_eq!(f(5e-324), "5e-324");
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        for _ in 0..10_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let x = f64::from_bits(state);
            if x.is_finite() {
                let back: f64 = f(x).parse().unwrap();
                assert_eq!(back.to_bits(), x.to_bits(), "{x:?}");
            }
        }
        for x in [
            1e308,
            1e-300,
            123456789.0,
            1e16,
            1e17,
            f64::MAX,
            f64::MIN_POSITIVE,
        ] {
            assert_eq!(f(x).parse::<f64>().unwrap(), x);
        }
    }

    #[test]
    fn integers() {
        let mut out = Vec::new();
        push_u64(&mut out, 0);
        out.push(b' ');
        push_u64(&mut out, u64::MAX);
        assert_eq!(out, b"0 18446744073709551615");
        out.extend_from_slice(b"kept");
        push_u64(&mut out, 7);
        assert_eq!(&out[out.len() - 5..], b"kept7");
        for v in (0..100_000u64)
            .chain((0..64).map(|k| 1 << k))
            .chain([u64::MAX - 1])
        {
            for v in [v, v.saturating_sub(1)] {
                out.clear();
                push_u64(&mut out, v);
                assert_eq!(out, v.to_string().as_bytes());
            }
        }
    }
}
