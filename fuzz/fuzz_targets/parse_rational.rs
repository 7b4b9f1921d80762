#![no_main]

//! The exact parser: any text is a rational within `MAX_INPUT_BITS` or a typed error, quickly;
//! what parses prints back to the same value, and its decimal text (when it has one) too.

use libfuzzer_sys::fuzz_target;
use surftopo_intrinsic::Number;
use surftopo_intrinsic::geometry::{MAX_INPUT_BITS, ParseRationalError, Rational};

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match text.parse::<Rational>() {
        Ok(r) => {
            assert!(r.bits() <= MAX_INPUT_BITS + 8, "{text:?}");
            assert_eq!(r.to_string().parse::<Rational>().as_ref(), Ok(&r));
            if let Some(decimal) = r.to_decimal() {
                assert_eq!(decimal.parse::<Rational>().as_ref(), Ok(&r));
            }
        }
        Err(ParseRationalError::TooLarge { bits, .. }) => assert!(bits > MAX_INPUT_BITS),
        Err(ParseRationalError::Syntax(_)) => {}
    }
    // As a JSON number literal: its nearest double is the one serde_json reads.
    if let Ok(n) = Number::from_literal(text.trim()) {
        if let Ok(x) = serde_json::from_str::<f64>(text.trim()) {
            assert_eq!(n.to_f64(), x, "{text:?}");
        }
    }
});
