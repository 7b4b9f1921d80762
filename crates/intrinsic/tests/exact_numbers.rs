//! Numbers of portalgon files in exact mode (issue 38, items 1 and 2): a JSON number literal is
//! the exact decimal it spells for exact arithmetic and its nearest double for double
//! precision; exact numbers beyond `MAX_INPUT_BITS` are refused with a typed error, never a
//! panic.

use proptest::prelude::*;
use surftopo_intrinsic::dubois::{FlatDelaunayOptions, delaunay_tessellation_flat};
use surftopo_intrinsic::geometry::{MAX_INPUT_BITS, ParseRationalError, Rational};
use surftopo_intrinsic::{PortalgonDoc, PortalgonError};

/// T_x by corners (Dubois, Section 9), each coordinate written as `number(value)`.
fn flat_torus_json(x: &str, x_plus_1: &str, number: impl Fn(&str) -> String) -> String {
    let (zero, one, two) = (number("0"), number("1"), number("2"));
    let (x, x1) = (number(x), number(x_plus_1));
    format!(
        r#"{{"polygons":[{{"corners":[[{zero},{zero}],[{one},{zero}],[{x},{two}]]}},
            {{"corners":[[{one},{zero}],[{x1},{two}],[{x},{two}]]}}],
            "matching":[[[0,0],[1,1]],[[0,1],[1,2]],[[0,2],[1,0]]]}}"#
    )
}

/// The canonical tessellation of T_x read exactly from `text`, as JSON (Theorem 1, exact).
fn exact_tessellation(text: &str) -> Result<String, String> {
    let doc = PortalgonDoc::from_json(text).map_err(|e| e.to_string())?;
    let p = doc
        .to_portalgon_in::<Rational>(0.0)
        .map_err(|e| e.to_string())?;
    let flat = delaunay_tessellation_flat(&p, &FlatDelaunayOptions::default())
        .map_err(|e| e.to_string())?;
    PortalgonDoc::from_portalgon(&flat.delaunay.tessellation)
        .to_json()
        .map_err(|e| e.to_string())
}

/// Item 2's repro: T_x at x = 10^18 + 1 written with integer literals. Read as doubles, x and
/// x + 1 would both be 10^18 and the side between them zero; read exactly, the tessellation is
/// the one the file with exact strings gives, and so are decimal literals (`0.5` steps).
#[test]
fn integer_and_decimal_literals_are_exact_in_exact_mode() {
    let literal = |v: &str| v.to_string();
    let string = |v: &str| format!("\"{v}\"");
    for (x, x1) in [
        ("1000000000000000001", "1000000000000000002"),
        (
            "123456789012345678901234567890",
            "123456789012345678901234567891",
        ),
        ("1000000000.1", "1000000001.1"),
        ("3.3e20", "330000000000000000001"),
    ] {
        let by_literals = exact_tessellation(&flat_torus_json(x, x1, literal)).unwrap();
        let by_strings = exact_tessellation(&flat_torus_json(x, x1, string)).unwrap();
        assert_eq!(by_literals, by_strings, "x = {x}");
    }
    // In double precision the same literals are their nearest doubles (x = x + 1 here).
    let doc = PortalgonDoc::from_json(&flat_torus_json(
        "1000000000000000001",
        "1000000000000000002",
        literal,
    ))
    .unwrap();
    let corners = doc.polygons[1].corners.as_ref().unwrap();
    assert_eq!(corners[1][0].to_f64(), 1e18);
    assert_eq!(
        corners[1][0].to_scalar::<Rational>().unwrap(),
        "1000000000000000002".parse().unwrap()
    );
    assert_eq!(corners[1][0].to_scalar::<f64>(), Some(1e18));
}

#[test]
fn a_literal_is_its_decimal_exactly_and_its_nearest_double_in_double_precision() {
    let doc = PortalgonDoc::from_json(
        r#"{"polygons":[{"corners":[[0.1,-0.1],[1e-3,2.5],[12345678901234567890,-0]]}]}"#,
    )
    .unwrap();
    let c = doc.polygons[0].corners.as_ref().unwrap();
    let exact = |i: usize, j: usize| c[i][j].to_scalar::<Rational>().unwrap();
    let r = |s: &str| s.parse::<Rational>().unwrap();
    assert_eq!(exact(0, 0), r("1/10"));
    assert_eq!(exact(0, 1), r("-1/10"));
    assert_eq!(exact(1, 0), r("1/1000"));
    assert_eq!(exact(1, 1), r("5/2"));
    assert_eq!(exact(2, 0), r("12345678901234567890"));
    assert_eq!(exact(2, 1), r("0"));
    assert_eq!(c[0][0].to_scalar::<f64>(), Some(0.1));
    assert_eq!(c[2][0].to_f64(), 12345678901234567890.0);
    // Written back, the literals keep their exact values.
    let again = PortalgonDoc::from_json(&doc.to_json().unwrap()).unwrap();
    assert_eq!(again, doc);
    let text = doc.to_json().unwrap();
    assert!(
        text.contains("[0.1,-0.1]") && text.contains("12345678901234567890"),
        "{text}"
    );
}

/// Past `MAX_INPUT_BITS`, as a string or a literal: a typed error naming the limit (item 1's
/// 3,000-digit corner, a 100,000-digit fraction); `1e-1000` (3,323 bits) is within it.
#[test]
fn numbers_past_the_input_limit_are_refused_with_a_typed_error() {
    let thousands = format!("1{}", "0".repeat(3000));
    let fraction = format!("{}/{}", "7".repeat(50_000), "3".repeat(50_000));
    for text in [
        thousands.clone(),
        fraction.clone(),
        "1e2000".into(),
        "1e-1300".into(),
    ] {
        match text.parse::<Rational>() {
            Err(ParseRationalError::TooLarge { bits, .. }) => assert!(bits > MAX_INPUT_BITS),
            other => panic!("{}: {other:?}", &text[..10]),
        }
        for json in [
            format!(r#"{{"polygons":[{{"corners":[[0,0],[1,0],["{text}",1]]}}]}}"#),
            format!(r#"{{"polygons":[{{"corners":[[0,0],[1,0],[{text},1]]}}]}}"#),
        ] {
            if json.contains('/') && !json.contains('"') {
                continue; // a fraction is a string only
            }
            match PortalgonDoc::from_json(&json) {
                Err(PortalgonError::Json(message)) => {
                    assert!(message.contains(&MAX_INPUT_BITS.to_string()), "{message}")
                }
                other => panic!("{other:?}"),
            }
        }
    }
    let small: Rational = "1e-1000".parse().unwrap();
    assert!(small.bits() > 3300 && small.bits() <= MAX_INPUT_BITS);
    let at_limit = format!("1{}", "0".repeat(1200));
    assert!(at_limit.parse::<Rational>().is_ok());
}

proptest! {
    /// A literal's double is the correctly rounded value serde_json's float parser gives, and
    /// its exact value is the decimal: `Double` exactly when the two agree.
    #[test]
    fn literals_round_like_json_readers_and_keep_their_decimal(
        mantissa in 0u64..u64::MAX, point in 0usize..22, exponent in -330i32..330, negative: bool,
        integer in proptest::option::of(0u64..u64::MAX),
    ) {
        let digits = mantissa.to_string();
        let point = point.min(digits.len());
        let text = match integer {
            Some(v) => format!("{}{v}", if negative { "-" } else { "" }),
            None => format!(
                "{}{}.{}e{exponent}",
                if negative { "-" } else { "" },
                if point == 0 { "0" } else { &digits[..point] },
                if point == digits.len() { "0" } else { &digits[point..] },
            ),
        };
        let doc = PortalgonDoc::from_json(&format!(
            r#"{{"polygons":[{{"corners":[[{text},0],[1,0],[0,1]]}}]}}"#
        )).unwrap();
        let number = &doc.polygons[0].corners.as_ref().unwrap()[0][0];
        let by_json: f64 = serde_json::from_str(&text).unwrap_or(f64::INFINITY * if negative { -1.0 } else { 1.0 });
        let nearest = number.to_f64();
        prop_assert!(nearest == by_json || (nearest.is_infinite() && by_json.is_infinite()), "{text}: {nearest} vs {by_json}");
        let exact: Rational = text.parse().unwrap();
        prop_assert_eq!(number.to_scalar::<Rational>().unwrap(), exact.clone());
        let is_double = matches!(number, surftopo_intrinsic::Number::Double(_));
        prop_assert_eq!(is_double, exact.as_exact_f64() == Some(nearest), "{}", text);
        // Every double's shortest text is read as that double, exactly.
        if nearest.is_finite() {
            let shortest = format!("{nearest:?}");
            let doc = PortalgonDoc::from_json(&format!(
                r#"{{"polygons":[{{"corners":[[{shortest},0],[1,0],[0,1]]}}]}}"#
            )).unwrap();
            let again = &doc.polygons[0].corners.as_ref().unwrap()[0][0];
            prop_assert_eq!(again.to_f64(), nearest);
        }
    }
}
