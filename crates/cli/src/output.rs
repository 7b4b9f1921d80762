//! Writing results: mesh files atomically through surftopo-io; JSON to stdout.

use std::path::Path;
use surftopo_io::{PolygonSoup, WriteOptions};
use surftopo_mesh::generators::Surface;

/// Writes a surface's live faces (dense vertex ids) to a mesh file, atomically.
pub fn write_surface(path: &Path, surface: &Surface) -> anyhow::Result<()> {
    let (positions, triangles) = surface.to_triangles();
    write_soup(path, &PolygonSoup::from_triangles(positions, &triangles))
}

/// Writes a polygon soup to a mesh file (format from the extension), atomically, under a
/// progress spinner (a gzip-compressed mesh of millions of faces takes seconds).
pub fn write_soup(path: &Path, soup: &PolygonSoup) -> anyhow::Result<()> {
    let written = crate::progress::step(&writing(path), || {
        surftopo_io::write_path(path, soup, &WriteOptions::default())
    });
    written.map_err(|e| match e {
        // The soup is surftopo's own: an inconsistent one is an internal failure.
        surftopo_io::IoError::InvalidSoup { .. } => anyhow::Error::new(e),
        surftopo_io::IoError::Io { source, .. } => crate::failure::unwritable(path, &source),
        other => crate::failure::invalid(other.to_string()),
    })
}

/// Prints a value as pretty JSON on stdout, every time (a number under a key ending in
/// `seconds`) rounded to the microsecond: a clock's last digits are noise, and
/// `0.0012000300000000002` is not a figure anyone reads.
pub fn print_json(value: &impl serde::Serialize) -> anyhow::Result<()> {
    let mut value = serde_json::to_value(value)?;
    round_times(&mut value);
    let mut text = serde_json::to_string_pretty(&value)?;
    text.push('\n');
    emit(&text)
}

/// Rounds, in place and at any depth, the numbers under keys ending in `seconds` to the
/// microsecond.
fn round_times(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Object(map) => {
            for (key, item) in map.iter_mut() {
                match item.as_f64() {
                    Some(seconds) if key.ends_with("seconds") && item.is_f64() => {
                        let rounded = (seconds * 1e6).round() / 1e6;
                        if let Some(number) = serde_json::Number::from_f64(rounded) {
                            *item = serde_json::Value::Number(number);
                        }
                    }
                    _ => round_times(item),
                }
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(round_times),
        _ => {}
    }
}

/// A duration for a summary line: three significant digits in µs, ms or s (`412 µs`,
/// `12.3 ms`, `1.23 s`, `123 s`), so that a fast step never reads `0.000 s`.
pub fn format_seconds(seconds: f64) -> String {
    let (value, unit) = if seconds < 1e-3 {
        (seconds * 1e6, "µs")
    } else if seconds < 1.0 {
        (seconds * 1e3, "ms")
    } else {
        (seconds, "s")
    };
    // The thresholds are those of the rounded value, so that 9.996 ms reads `10.0 ms`, not `10.00 ms`.
    let decimals = if value >= 99.95 {
        0
    } else if value >= 9.995 {
        1
    } else {
        2
    };
    format!("{value:.decimals$} {unit}")
}

/// Writes results to stdout. A closed pipe (`surftopo info x | head`) is not an error: see
/// [`is_broken_pipe`]; any other failure (a full disk) names stdout, exit code 2.
pub fn emit(text: &str) -> anyhow::Result<()> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(|e| {
            if e.kind() == std::io::ErrorKind::BrokenPipe {
                anyhow::Error::new(e)
            } else {
                crate::failure::invalid(format!("stdout: not written: {e}"))
            }
        })
}

/// Whether an error is stdout's reader having gone away.
pub fn is_broken_pipe(error: &anyhow::Error) -> bool {
    error.chain().any(|cause| {
        cause
            .downcast_ref::<std::io::Error>()
            .is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe)
    })
}

/// A progress message naming the output.
fn writing(path: &Path) -> String {
    format!("writing {}", crate::failure::shown(path))
}

/// Writes a file atomically (temporary sibling, then rename) with `fill` writing its contents,
/// under a progress spinner. Any failure (missing folder, read-only or full disk) is an
/// unwritable output: exit code 2, like mesh outputs.
pub fn write_file(
    path: &Path,
    fill: impl FnOnce(&mut std::io::BufWriter<&mut std::fs::File>) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    use std::io::Write;
    let mut failure = None;
    let result = crate::progress::step(&writing(path), || {
        surftopo_io::atomic_write(path, |mut file| {
            let mut writer = std::io::BufWriter::new(&mut file);
            if let Err(e) = fill(&mut writer) {
                failure = Some(e);
                return Err(std::io::Error::other("writing failed"));
            }
            writer.flush()?;
            drop(writer);
            Ok(file)
        })
    });
    match (failure, result) {
        (Some(e), _) => Err(crate::failure::unwritable(
            path,
            &crate::failure::message(&e),
        )),
        (None, Err(e)) => Err(crate::failure::unwritable(path, &e)),
        (None, Ok(())) => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::{format_seconds, round_times};

    #[test]
    fn durations_read_with_three_significant_digits_and_a_unit() {
        assert_eq!(format_seconds(0.0), "0.00 µs");
        assert_eq!(format_seconds(0.000_412_3), "412 µs");
        assert_eq!(format_seconds(0.001_200_03), "1.20 ms");
        assert_eq!(format_seconds(0.012_34), "12.3 ms");
        assert_eq!(format_seconds(0.5), "500 ms");
        assert_eq!(format_seconds(1.234_5), "1.23 s");
        assert_eq!(format_seconds(123.4), "123 s");
    }

    #[test]
    fn json_times_are_rounded_to_the_microsecond_and_other_numbers_kept() {
        let mut value = serde_json::json!({
            "seconds": 0.001_200_030_000_000_000_2,
            "quality": {"mean": 0.123_456_789_1, "total_seconds": 2.5e-9},
            "runs": [{"augmentation_seconds": 1.000_000_4}],
            "flips": 3
        });
        round_times(&mut value);
        assert_eq!(value["seconds"], 0.0012);
        assert_eq!(value["quality"]["mean"], 0.123_456_789_1);
        assert_eq!(value["quality"]["total_seconds"], 0.0);
        assert_eq!(value["runs"][0]["augmentation_seconds"], 1.0);
        assert_eq!(value["flips"], 3);
    }
}
