//! The native module `surftopo._native` of the surftopo Python package (pyo3, built by maturin).
//!
//! A thin layer over the libraries: numpy arrays in (`arrays.rs`), the library call with the GIL
//! released (long calls through `interrupt.rs`, so Ctrl-C stops them), numpy arrays and `scipy.sparse.csr_matrix` out, typed errors as the exceptions of
//! `surftopo._errors` (`errors.rs`). The public Python API, its docstrings and its type stubs are
//! in `python/surftopo/`.

mod arrays;
mod census;
mod covered;
mod errors;
mod interrupt;
mod intrinsic;
mod surface;
mod tufted;

use pyo3::prelude::*;

/// The native module: every function and class of the `surftopo` package.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(surface::read_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(surface::write_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(surface::info, m)?)?;
    m.add_function(wrap_pyfunction!(surface::irreducible, m)?)?;
    m.add_function(wrap_pyfunction!(surface::quadrangulate, m)?)?;
    m.add_function(wrap_pyfunction!(surface::tetrahedron, m)?)?;
    m.add_function(wrap_pyfunction!(surface::icosphere, m)?)?;
    m.add_function(wrap_pyfunction!(surface::torus, m)?)?;
    m.add_function(wrap_pyfunction!(surface::genus_surface, m)?)?;
    m.add_function(wrap_pyfunction!(surface::cavity_box, m)?)?;
    m.add_function(wrap_pyfunction!(surface::disk, m)?)?;
    m.add_function(wrap_pyfunction!(surface::annulus, m)?)?;
    m.add_function(wrap_pyfunction!(surface::mobius_band, m)?)?;
    m.add_function(wrap_pyfunction!(surface::projective_plane, m)?)?;
    m.add_function(wrap_pyfunction!(surface::klein_bottle, m)?)?;
    m.add_function(wrap_pyfunction!(surface::non_orientable, m)?)?;
    m.add_function(wrap_pyfunction!(intrinsic::intrinsic_delaunay, m)?)?;
    m.add_function(wrap_pyfunction!(intrinsic::laplacian, m)?)?;
    m.add_function(wrap_pyfunction!(intrinsic::_laplacian_timed, m)?)?;
    m.add_function(wrap_pyfunction!(intrinsic::isometric, m)?)?;
    m.add_function(wrap_pyfunction!(intrinsic::isometry_verdict, m)?)?;
    m.add_function(wrap_pyfunction!(intrinsic::flat_torus, m)?)?;
    m.add_function(wrap_pyfunction!(census::census, m)?)?;
    m.add_function(wrap_pyfunction!(census::canonical_form, m)?)?;
    m.add_class::<intrinsic::Portalgon>()?;
    m.add_class::<intrinsic::Intrinsic>()?;
    Ok(())
}
