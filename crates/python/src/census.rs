//! `census` and `canonical_form`: the census of irreducible triangulations of a closed surface,
//! and canonical forms of triangulated closed surfaces, orientable or not (`surftopo-census`).

use crate::arrays::{faces, index_array};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use surftopo_census::{CensusError, CensusOptions, SurfaceKind, Triangulation};

/// The exception of a census error: `InvalidMeshError` naming the face, edge or vertex for a
/// face list that is not a closed surface, `InvalidInputError` otherwise.
fn census_error(py: Python<'_>, e: &CensusError) -> PyErr {
    let fields = PyDict::new(py);
    let class = (|| -> PyResult<&str> {
        let kind = format!("{e:?}");
        let kind = kind
            .split([' ', '{', '('])
            .next()
            .unwrap_or_default()
            .to_string();
        fields.set_item("kind", kind)?;
        Ok(match e {
            CensusError::DegenerateFace { face, vertex } => {
                fields.set_item("face", face)?;
                fields.set_item("vertex", vertex)?;
                "InvalidMeshError"
            }
            CensusError::UnusedVertex { vertex }
            | CensusError::PinchedVertex { vertex, .. }
            | CensusError::Disconnected { vertex } => {
                fields.set_item("vertex", vertex)?;
                "InvalidMeshError"
            }
            CensusError::DuplicateFace { faces } => {
                fields.set_item("face", faces[1])?;
                "InvalidMeshError"
            }
            CensusError::EdgeFaceCount { edge, face, .. } => {
                fields.set_item("edge", (edge[0], edge[1]))?;
                fields.set_item("face", face)?;
                "InvalidMeshError"
            }
            CensusError::Empty => "InvalidMeshError",
            _ => "InvalidInputError",
        })
    })();
    let made = class.and_then(|class| {
        py.import("surftopo._errors")
            .and_then(|m| m.getattr(class))
            .and_then(|c| c.call((e.to_string(),), Some(&fields)))
    });
    match made {
        Ok(value) => PyErr::from_value(value),
        Err(err) => err,
    }
}

/// Every irreducible triangulation of `surface`, up to isomorphism (mirror images identified),
/// as int64 `(m, 3)` face arrays on vertices `0..n`, canonically labelled, sorted by vertex count.
#[pyfunction]
#[pyo3(signature = (surface, max_vertices = None))]
pub fn census<'py>(
    py: Python<'py>,
    surface: &str,
    max_vertices: Option<usize>,
) -> PyResult<Vec<Bound<'py, PyAny>>> {
    let kind = SurfaceKind::parse(surface).map_err(|e| census_error(py, &e))?;
    // Ctrl-C: `interruptible` raises KeyboardInterrupt; the search, asking its stop hook every
    // few thousand nodes, then ends on its thread.
    let result = crate::interrupt::interruptible(py, move |stop| {
        let stop = || stop.is_set();
        surftopo_census::census(
            kind,
            CensusOptions {
                max_vertices,
                stop: Some(&stop),
                ..Default::default()
            },
        )
    })?;
    let result = result.map_err(|e| census_error(py, &e))?;
    Ok(result
        .triangulations
        .iter()
        .map(|t| index_array(py, t.faces()).into_any())
        .collect())
}

/// The canonical form of a closed triangulated surface given by its faces on vertices `0..n`
/// (every index used): an int64 `(m, 3)` array, equal for two face lists iff they are
/// isomorphic (mirror images included).
#[pyfunction]
pub fn canonical_form<'py>(
    py: Python<'py>,
    faces_array: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyAny>> {
    let list = faces::<3>(faces_array, u32::MAX as usize)?;
    let t = py
        .detach(|| Triangulation::new(list))
        .map_err(|e| census_error(py, &e))?;
    let form = py.detach(|| surftopo_census::canonical_form(&t));
    Ok(index_array(py, form.faces()).into_any())
}
