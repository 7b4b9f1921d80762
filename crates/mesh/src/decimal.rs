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
    out.extend_from_slice(zmij::Buffer::new().format(x).as_bytes());
}

/// Appends the shortest decimal that reads back (as an `f32`) to the same bits of a finite `x`.
#[inline]
pub fn push_f32(out: &mut Vec<u8>, x: f32) {
    out.extend_from_slice(zmij::Buffer::new().format(x).as_bytes());
}

/// Appends the decimal digits of `v`.
#[inline]
pub fn push_u64(out: &mut Vec<u8>, mut v: u64) {
    let mut tmp = [0u8; 20];
    let mut i = tmp.len();
    loop {
        i -= 1;
        tmp[i] = b'0' + (v % 10) as u8;
        v /= 10;
        if v == 0 {
            break;
        }
    }
    out.extend_from_slice(&tmp[i..]);
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
    }
}
