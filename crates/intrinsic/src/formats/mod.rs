//! What the crate reads and writes: portalgon JSON (`PORTALGON_FORMAT.md`), Matrix Market, and
//! numpy's `.npy` / `.npz`; the text writers share a parallel block formatter.

pub(crate) mod matrix_market;
pub(crate) mod numpy;
pub(crate) mod portalgon_json;
pub(crate) mod text_blocks;
