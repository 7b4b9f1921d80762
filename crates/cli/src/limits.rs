//! Bounds on memory, set once from the global options `--max-input-bytes` and `--max-elements`:
//! every size that comes from an input or an option is checked against them before the memory
//! it implies is allocated.

use crate::failure::invalid;
use std::sync::OnceLock;

/// Default of `--max-elements`: the most vertices or faces an input may have, or a generator or
/// modifier may make (a built triangulation takes about 100 bytes per triangle, so the default
/// needs about 2.5 GB).
pub const DEFAULT_MAX_ELEMENTS: u64 = 25_000_000;

/// The limits in force.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// The most bytes read from one input file, after decompression (`--max-input-bytes`).
    pub max_input_bytes: u64,
    /// The most vertices or faces of an input or a generated surface (`--max-elements`).
    pub max_elements: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_input_bytes: surftopo_io::DEFAULT_MAX_INPUT_BYTES,
            max_elements: DEFAULT_MAX_ELEMENTS,
        }
    }
}

static LIMITS: OnceLock<Limits> = OnceLock::new();

/// Sets the limits for the rest of the run (the first call wins).
pub fn set(limits: Limits) {
    let _ = LIMITS.set(limits);
}

/// The limits in force (the defaults unless [`set`]).
pub fn get() -> Limits {
    LIMITS.get().copied().unwrap_or_default()
}

/// The reader limits of surftopo-io.
pub fn read_limits() -> surftopo_io::ReadLimits {
    surftopo_io::ReadLimits {
        max_bytes: get().max_input_bytes,
    }
}

/// Refuses `count` elements (`what`: "triangles", "faces", ...) asked for by `source` (an input
/// file, or the options that imply them) when it exceeds `--max-elements`, before anything of
/// that size is allocated.
pub fn check_elements(source: &str, count: u64, what: &str) -> anyhow::Result<()> {
    let max = get().max_elements;
    if count > max {
        return Err(invalid(format!(
            "{source}: {count} {what}, more than --max-elements {max} allows (raise it when the \
             machine has the memory: about 100 bytes per triangle)"
        )));
    }
    Ok(())
}
