//! numpy arrays in and out.
//!
//! Vertices: a float64 `(n, 3)` array is read in place when it is C-contiguous (the libraries take
//! `&[[f64; 3]]`), gathered once otherwise (Fortran order, strided views); anything else goes
//! through `numpy.asarray(x, dtype=float64)` first. Faces: int32 or int64 `(m, k)` arrays of any
//! layout, read once into the `u32` indices the libraries take, checking the range on the way;
//! other integer dtypes and nested lists go through `numpy.asarray` first. Results are handed to
//! numpy without a copy (the array owns the `Vec`).

use crate::errors::{Failure, invalid};
use numpy::ndarray::{Array1, Array2, ArrayView2};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use std::borrow::Cow;

/// Converts `x` with `numpy.asarray(x, **kwargs)`.
fn asarray<'py>(x: &Bound<'py, PyAny>, dtype: Option<&str>) -> PyResult<Bound<'py, PyAny>> {
    let numpy = x.py().import("numpy")?;
    match dtype {
        Some(d) => numpy.call_method1("asarray", (x, d)),
        None => numpy.call_method1("asarray", (x,)),
    }
}

/// A float64 `(n, 3)` array of vertex positions, held for reading.
pub struct VertexArray<'py>(PyReadonlyArray2<'py, f64>);

impl<'py> VertexArray<'py> {
    /// Takes `x` as float64 positions of shape `(n, 3)`.
    pub fn extract(x: &Bound<'py, PyAny>) -> PyResult<Self> {
        let array: PyReadonlyArray2<'py, f64> = match x.extract() {
            Ok(a) => a,
            Err(_) => asarray(x, Some("float64"))?.extract().map_err(|_| {
                PyTypeError::new_err("vertices: expected a float array of shape (n, 3)")
            })?,
        };
        let shape = array.shape();
        if shape[1] != 3 {
            return Err(invalid(format!(
                "vertices: expected shape (n, 3), got ({}, {})",
                shape[0], shape[1]
            ))
            .into());
        }
        Ok(Self(array))
    }

    /// The positions: the array's memory when C-contiguous, a copy otherwise.
    pub fn positions(&self) -> Cow<'_, [[f64; 3]]> {
        if self.0.is_c_contiguous()
            && let Ok(flat) = self.0.as_slice()
        {
            return Cow::Borrowed(flat.as_chunks::<3>().0);
        }
        let view = self.0.as_array();
        Cow::Owned(
            view.rows()
                .into_iter()
                .map(|r| [r[0], r[1], r[2]])
                .collect(),
        )
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.0.shape()[0]
    }
}

/// An int32 or int64 `(m, k)` array of vertex indices, held for reading.
#[derive(FromPyObject)]
enum IndexArray<'py> {
    I32(PyReadonlyArray2<'py, i32>),
    I64(PyReadonlyArray2<'py, i64>),
}

/// Reads the rows of an index array as `u32`, checking `0 <= i < vertex_count`.
fn read_rows<T: Copy + Into<i64>>(
    view: ArrayView2<'_, T>,
    vertex_count: usize,
) -> Result<Vec<u32>, Failure> {
    let mut out = Vec::with_capacity(view.len());
    for (face, row) in view.rows().into_iter().enumerate() {
        for &i in row {
            let value: i64 = i.into();
            if !(0..vertex_count as i64).contains(&value) {
                return Err(Failure::Index {
                    face,
                    value,
                    vertex_count,
                });
            }
            out.push(value as u32);
        }
    }
    Ok(out)
}

/// Faces as flat `u32` indices with `sides` per face.
pub struct Faces {
    /// Row-major indices.
    pub indices: Vec<u32>,
    /// Columns of the array (3 for triangles, 4 for quads).
    pub sides: usize,
}

impl Faces {
    /// Takes `x` as an integer `(m, k)` array of indices into `vertex_count` vertices, `k` being
    /// `sides` when given (else at least 3).
    pub fn extract(
        x: &Bound<'_, PyAny>,
        vertex_count: usize,
        sides: Option<usize>,
    ) -> PyResult<Self> {
        let array: IndexArray<'_> = match x.extract() {
            Ok(a) => a,
            Err(_) => {
                let a = asarray(x, None)?;
                let kind: String = a.getattr("dtype")?.getattr("kind")?.extract()?;
                if kind != "i" && kind != "u" {
                    return Err(PyTypeError::new_err(format!(
                        "faces: expected an integer array, got dtype {}",
                        a.getattr("dtype")?.str()?
                    )));
                }
                a.call_method1("astype", ("int64",))?.extract()?
            }
        };
        let shape = match &array {
            IndexArray::I32(a) => a.shape().to_vec(),
            IndexArray::I64(a) => a.shape().to_vec(),
        };
        let wanted = sides.map_or(shape[1] >= 3, |k| shape[1] == k);
        if !wanted {
            let expected = sides.map_or("(m, k) with k >= 3".to_string(), |k| format!("(m, {k})"));
            return Err(invalid(format!(
                "faces: expected shape {expected}, got ({}, {})",
                shape[0], shape[1]
            ))
            .into());
        }
        let indices = match &array {
            IndexArray::I32(a) => read_rows(a.as_array(), vertex_count),
            IndexArray::I64(a) => read_rows(a.as_array(), vertex_count),
        }?;
        Ok(Self {
            indices,
            sides: shape[1],
        })
    }

    /// Takes `x` as triangles `(m, 3)`.
    pub fn triangles(x: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<Vec<[u32; 3]>> {
        let faces = Self::extract(x, vertex_count, Some(3))?;
        Ok(faces.indices.as_chunks::<3>().0.to_vec())
    }
}

/// A `(rows, k)` array owning `flat` (row-major).
pub fn matrix<'py, T: numpy::Element>(
    py: Python<'py>,
    flat: Vec<T>,
    k: usize,
) -> Bound<'py, PyArray2<T>> {
    let rows = flat.len().checked_div(k).unwrap_or(0);
    Array2::from_shape_vec((rows, k), flat)
        .expect("the length is a multiple of k")
        .into_pyarray(py)
}

/// Vertex positions as a float64 `(n, 3)` array.
pub fn positions_array<'py>(py: Python<'py>, positions: &[[f64; 3]]) -> Bound<'py, PyArray2<f64>> {
    matrix(py, positions.as_flattened().to_vec(), 3)
}

/// Index rows (faces, quads, edges) as an int64 `(m, k)` array.
pub fn index_array<'py, const K: usize>(
    py: Python<'py>,
    rows: &[[u32; K]],
) -> Bound<'py, PyArray2<i64>> {
    matrix(
        py,
        rows.as_flattened().iter().map(|&i| i64::from(i)).collect(),
        K,
    )
}

/// A vector as a 1-D array.
pub fn vector<'py, T: numpy::Element>(py: Python<'py>, values: Vec<T>) -> Bound<'py, PyArray1<T>> {
    Array1::from_vec(values).into_pyarray(py)
}
