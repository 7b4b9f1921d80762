//! surftopo-bench's library: the papers' experiments (`surftopo-bench papers`), shared by the
//! binary and its tests.

pub mod papers;
