//! Markdown pieces shared by the three reports: our number beside the paper's, with the ratio.

use super::numbers::value;

/// Our value beside the paper's: `ours / paper (×ratio)`, ratio = ours / paper; `–` for a
/// missing value of ours, the ratio left out where the paper's is 0 or either is missing.
pub fn beside(ours: Option<f64>, paper: &str, decimals: usize) -> String {
    let ours_text = ours.map_or("–".to_string(), |x| number(x, decimals));
    let p = value(paper);
    match ours {
        Some(x) if p.is_finite() && p != 0.0 && x.is_finite() => {
            format!("{ours_text} / {paper} (×{:.2})", x / p)
        }
        _ => format!("{ours_text} / {paper}"),
    }
}

/// `x` with `decimals` decimals and thousands separators in the integer part.
pub fn number(x: f64, decimals: usize) -> String {
    if !x.is_finite() {
        return "–".into();
    }
    let text = format!("{:.*}", decimals, x.abs());
    let (int, frac) = text
        .split_once('.')
        .map_or((text.as_str(), ""), |(a, b)| (a, b));
    let mut grouped = String::new();
    for (i, c) in int.chars().enumerate() {
        if i > 0 && (int.len() - i) % 3 == 0 {
            grouped.push(',');
        }
        grouped.push(c);
    }
    let sign = if x < 0.0 && text.chars().any(|c| c.is_ascii_digit() && c != '0') {
        "-"
    } else {
        ""
    };
    if frac.is_empty() {
        format!("{sign}{grouped}")
    } else {
        format!("{sign}{grouped}.{frac}")
    }
}

/// Seconds with 4 significant-ish decimals (`0.0123`, `12.35`).
pub fn seconds(x: f64) -> String {
    if !x.is_finite() {
        "–".into()
    } else if x >= 100.0 {
        format!("{x:.1}")
    } else if x >= 1.0 {
        format!("{x:.3}")
    } else {
        format!("{x:.5}")
    }
}

/// A markdown table row from cells.
pub fn row(cells: &[String]) -> String {
    format!("| {} |\n", cells.join(" | "))
}

/// A markdown table header with right-aligned columns after the first `left` ones.
pub fn header(columns: &[&str], left: usize) -> String {
    let align: Vec<&str> = (0..columns.len())
        .map(|i| if i < left { "---" } else { "---:" })
        .collect();
    format!("| {} |\n|{}|\n", columns.join(" | "), align.join("|"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_grouped_and_ratios_taken() {
        assert_eq!(number(1234567.891, 1), "1,234,567.9");
        assert_eq!(number(12.0, 0), "12");
        assert_eq!(number(-1234.0, 0), "-1,234");
        assert_eq!(beside(Some(20.0), "10.0", 1), "20.0 / 10.0 (×2.00)");
        assert_eq!(beside(None, "3,392", 0), "– / 3,392");
        assert_eq!(beside(Some(1.0), "0.0", 1), "1.0 / 0.0");
    }
}
