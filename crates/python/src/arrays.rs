//! numpy arrays in and out.
//!
//! Vertices: a float64 `(n, 3)` array is read in place when it is C-contiguous (the libraries take
//! `&[[f64; 3]]`), gathered once otherwise (Fortran order, strided views); anything else goes
//! through `numpy.asarray(x, dtype=float64)` first. Faces: int32 or int64 `(m, k)` arrays of any
//! layout, read once into the `u32` indices the libraries take, checking the range on the way;
//! other integer dtypes and nested lists go through `numpy.asarray` first. Results are handed to
//! numpy without a copy (the array owns the `Vec`).

use crate::errors::{Failure, invalid};
use numpy::ndarray::{Array1, Array2};
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
    ///
    /// Strings, complex numbers, booleans and objects are refused (numpy would convert the first
    /// silently and drop imaginary parts), so are arrays of another number of dimensions.
    pub fn extract(x: &Bound<'py, PyAny>) -> PyResult<Self> {
        let array: PyReadonlyArray2<'py, f64> = match x.extract() {
            Ok(a) => a,
            Err(_) => {
                let a = asarray(x, None)?;
                check_dtype_and_dimensions("vertices", &a, "fiu", "(n, 3)")?;
                a.call_method1("astype", ("float64",))?.extract()?
            }
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

/// Checks `0 <= value < vertex_count` for the index of face `face`.
#[inline]
fn checked(value: i64, face: usize, vertex_count: usize) -> Result<u32, Failure> {
    if (0..vertex_count as i64).contains(&value) {
        Ok(value as u32)
    } else {
        Err(Failure::Index {
            face,
            value,
            vertex_count,
        })
    }
}

/// One row of indices as `[u32; K]`, checked against `vertex_count`.
#[inline]
fn row<T: Into<i64>, const K: usize>(
    face: usize,
    values: impl Iterator<Item = T>,
    vertex_count: usize,
) -> Result<[u32; K], Failure> {
    let mut out = [0u32; K];
    for (slot, value) in out.iter_mut().zip(values) {
        *slot = checked(value.into(), face, vertex_count)?;
    }
    Ok(out)
}

/// The rows of a `(m, K)` index array as `[u32; K]`, checked against `vertex_count`; a
/// C-contiguous array is read as one flat slice.
fn read_rows<T: numpy::Element + Copy + Into<i64>, const K: usize>(
    array: &PyReadonlyArray2<'_, T>,
    vertex_count: usize,
) -> Result<Vec<[u32; K]>, Failure> {
    if array.is_c_contiguous()
        && let Ok(flat) = array.as_slice()
    {
        // The range by a minimum and maximum (branch-free, vectorised), then a plain conversion;
        // the checked conversion below finds the offending face otherwise.
        let (low, high) = flat.iter().fold((i64::MAX, i64::MIN), |(low, high), &v| {
            let v: i64 = v.into();
            (low.min(v), high.max(v))
        });
        if flat.is_empty() || (low >= 0 && high < vertex_count as i64) {
            let rows = flat.as_chunks::<K>().0;
            return Ok(rows
                .iter()
                .map(|r| r.map(|v| Into::<i64>::into(v) as u32))
                .collect());
        }
    }
    array
        .as_array()
        .rows()
        .into_iter()
        .enumerate()
        .map(|(face, r)| row(face, r.iter().copied(), vertex_count))
        .collect()
}

/// Takes `x` as an int32 or int64 array (other integer dtypes and lists through
/// `numpy.asarray(x).astype(int64)`), returning it and its shape `(m, k)`.
fn extract_indices<'py>(x: &Bound<'py, PyAny>) -> PyResult<(IndexArray<'py>, [usize; 2])> {
    let array: IndexArray<'py> = match x.extract() {
        Ok(a) => a,
        Err(_) => {
            let a = asarray(x, None)?;
            check_dtype_and_dimensions("faces", &a, "iu", "(m, k)")?;
            a.call_method1("astype", ("int64",))?.extract()?
        }
    };
    let shape = match &array {
        IndexArray::I32(a) => a.shape(),
        IndexArray::I64(a) => a.shape(),
    };
    let shape = [shape[0], shape[1]];
    Ok((array, shape))
}

/// Refuses an array whose dtype kind is not one of `kinds` (numpy's `dtype.kind`: `f` float,
/// `i`/`u` integers) with a `TypeError`, and one that is not two-dimensional with an
/// `InvalidInputError` saying the shape wanted.
fn check_dtype_and_dimensions(
    what: &str,
    a: &Bound<'_, PyAny>,
    kinds: &str,
    shape: &str,
) -> PyResult<()> {
    let dtype = a.getattr("dtype")?;
    let kind: String = dtype.getattr("kind")?.extract()?;
    if !kinds.contains(kind.as_str()) {
        let wanted = if kinds.contains('f') {
            "real numbers"
        } else {
            "integers"
        };
        return Err(PyTypeError::new_err(format!(
            "{what}: expected {wanted}, got an array of dtype {}",
            dtype.str()?
        )));
    }
    let dimensions: usize = a.getattr("ndim")?.extract()?;
    if dimensions != 2 {
        return Err(invalid(format!(
            "{what}: expected a two-dimensional array of shape {shape}, got shape {}",
            a.getattr("shape")?.str()?
        ))
        .into());
    }
    Ok(())
}

/// The `InvalidInputError` of a faces array of the wrong shape.
fn wrong_shape(expected: &str, shape: [usize; 2]) -> PyErr {
    invalid(format!(
        "faces: expected shape {expected}, got ({}, {})",
        shape[0], shape[1]
    ))
    .into()
}

/// Takes `x` as faces with `K` sides `(m, K)` into `vertex_count` vertices.
pub fn faces<const K: usize>(x: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<Vec<[u32; K]>> {
    let (array, shape) = extract_indices(x)?;
    if shape[1] != K {
        return Err(wrong_shape(&format!("(m, {K})"), shape));
    }
    Ok(match &array {
        IndexArray::I32(a) => read_rows::<i32, K>(a, vertex_count),
        IndexArray::I64(a) => read_rows::<i64, K>(a, vertex_count),
    }?)
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

/// Faces of any number of sides (at least three each), as flat indices and offsets.
#[derive(Clone, Debug, Default)]
pub struct Polygons {
    /// The faces' vertex indices, one after the other.
    pub indices: Vec<u32>,
    /// Where each face starts in `indices`, then `indices.len()`.
    pub offsets: Vec<usize>,
}

impl Polygons {
    /// The faces in order.
    pub fn faces(&self) -> impl Iterator<Item = &[u32]> {
        self.offsets.windows(2).map(|w| &self.indices[w[0]..w[1]])
    }

    /// Appends a face.
    fn push(&mut self, face: &[u32]) {
        if self.offsets.is_empty() {
            self.offsets.push(0);
        }
        self.indices.extend_from_slice(face);
        self.offsets.push(self.indices.len());
    }
}

/// The faces a function that needs triangles takes: triangles, or polygons that it cuts.
pub enum FaceArg {
    /// An `(m, 3)` array: triangles as given.
    Triangles(Vec<[u32; 3]>),
    /// Anything else: faces of three sides or more.
    Polygons(Polygons),
}

/// The triangles of a [`FaceArg`], with the face each comes from when polygons were cut.
pub struct Triangulated {
    /// The triangles: as given, or the polygons cut by
    /// `surftopo_mesh::triangulate_polygons_as_surface` (the CLI's rule).
    pub triangles: Vec<[u32; 3]>,
    /// The input face of each triangle, when polygons were cut.
    pub polygon_of: Option<Vec<u32>>,
    /// The input's faces, when they were not all triangles given as an `(m, 3)` array.
    pub polygons: Option<Polygons>,
}

impl FaceArg {
    /// The faces as slices.
    pub fn faces(&self) -> Box<dyn Iterator<Item = &[u32]> + '_> {
        match self {
            FaceArg::Triangles(t) => Box::new(t.iter().map(|t| &t[..])),
            FaceArg::Polygons(p) => Box::new(p.faces()),
        }
    }

    /// Renumbers every vertex index through `map`.
    pub fn renumber(&mut self, map: &[u32]) {
        let indices = match self {
            FaceArg::Triangles(t) => t.as_flattened_mut(),
            FaceArg::Polygons(p) => &mut p.indices[..],
        };
        indices.iter_mut().for_each(|i| *i = map[*i as usize]);
    }

    /// The triangles (polygons cut by the CLI's rule, with `positions`; call without the GIL).
    pub fn triangulated(self, positions: &[[f64; 3]]) -> Triangulated {
        match self {
            FaceArg::Triangles(triangles) => Triangulated {
                triangles,
                polygon_of: None,
                polygons: None,
            },
            FaceArg::Polygons(polygons) => {
                let (cut, _) =
                    surftopo_mesh::triangulate_polygons_as_surface(positions, polygons.faces());
                let identity = cut.is_identity();
                Triangulated {
                    triangles: cut.triangles,
                    polygon_of: (!identity).then_some(cut.face_of),
                    polygons: Some(polygons),
                }
            }
        }
    }
}

impl Triangulated {
    /// A failure naming a triangle, naming the input face (the polygon) instead.
    pub fn on_faces(&self, failure: Failure) -> Failure {
        match (failure, &self.polygon_of) {
            (Failure::Build(e), Some(map)) => Failure::Build(e.on_faces(map)),
            (failure, _) => failure,
        }
    }
}

/// Takes `x` as faces into `vertex_count` vertices, in any form `read_mesh` returns them: an
/// `(m, k)` integer array (`k >= 3`), the same padded with trailing -1 (`polygons="padded"`:
/// each row's face ends before its first -1), or a list of 1-D sequences (`polygons="list"`).
/// An `(m, 3)` array is read as triangles without a copy of its rows' structure.
pub fn any_faces(x: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<FaceArg> {
    let is_sequence =
        x.is_instance_of::<pyo3::types::PyList>() || x.is_instance_of::<pyo3::types::PyTuple>();
    let ragged = if is_sequence {
        // A list of rows of one length is an array; rows of several lengths are polygons.
        match asarray(x, None) {
            Ok(a) => {
                let kind: String = a.getattr("dtype")?.getattr("kind")?.extract()?;
                let dimensions: usize = a.getattr("ndim")?.extract()?;
                !(dimensions == 2 && "iu".contains(kind.as_str())) && dimensions != 0
            }
            Err(_) => true,
        }
    } else {
        // A 1-D object array: one face per element.
        x.getattr("dtype").is_ok_and(|d| {
            d.getattr("kind")
                .and_then(|k| k.extract::<String>())
                .is_ok_and(|k| k == "O")
        }) && x.getattr("ndim").and_then(|n| n.extract::<usize>()).ok() == Some(1)
    };
    if ragged {
        return face_list(x, vertex_count).map(FaceArg::Polygons);
    }
    let (array, shape) = extract_indices(x)?;
    if shape[1] == 3 {
        return Ok(FaceArg::Triangles(match &array {
            IndexArray::I32(a) => read_rows::<i32, 3>(a, vertex_count),
            IndexArray::I64(a) => read_rows::<i64, 3>(a, vertex_count),
        }?));
    }
    if shape[1] < 3 {
        return Err(wrong_shape("(m, k) with k >= 3", shape));
    }
    let rows: Vec<Vec<i64>> = match &array {
        IndexArray::I32(a) => a
            .as_array()
            .rows()
            .into_iter()
            .map(|r| r.iter().map(|&v| i64::from(v)).collect())
            .collect(),
        IndexArray::I64(a) => a
            .as_array()
            .rows()
            .into_iter()
            .map(|r| r.to_vec())
            .collect(),
    };
    let mut polygons = Polygons::default();
    for (face, row) in rows.iter().enumerate() {
        // Trailing -1 entries are padding.
        let sides = row
            .iter()
            .rposition(|&v| v != -1)
            .map_or(0, |last| last + 1);
        polygons.push(&polygon(face, &row[..sides], vertex_count)?);
    }
    Ok(FaceArg::Polygons(polygons))
}

/// A list of faces, each a 1-D sequence of integers.
fn face_list(x: &Bound<'_, PyAny>, vertex_count: usize) -> PyResult<Polygons> {
    let mut polygons = Polygons::default();
    for (face, item) in x.try_iter()?.enumerate() {
        let a = asarray(&item?, None)?;
        let kind: String = a.getattr("dtype")?.getattr("kind")?.extract()?;
        let dimensions: usize = a.getattr("ndim")?.extract()?;
        if !"iu".contains(kind.as_str()) || dimensions != 1 {
            return Err(PyTypeError::new_err(format!(
                "faces: face {face}: expected a sequence of vertex indices (integers), got an \
                 array of dtype {} and shape {}",
                a.getattr("dtype")?.str()?,
                a.getattr("shape")?.str()?
            )));
        }
        let values: Vec<i64> = a
            .call_method1("astype", ("int64",))?
            .call_method0("tolist")?
            .extract()?;
        polygons.push(&polygon(face, &values, vertex_count)?);
    }
    if polygons.offsets.is_empty() {
        polygons.offsets.push(0);
    }
    Ok(polygons)
}

/// One face's indices, checked: at least three, each in `0..vertex_count`.
fn polygon(face: usize, values: &[i64], vertex_count: usize) -> Result<Vec<u32>, Failure> {
    if values.len() < 3 {
        return Err(invalid(format!(
            "faces: face {face} has {} vertices; a face needs at least 3",
            values.len()
        )));
    }
    values
        .iter()
        .map(|&v| checked(v, face, vertex_count))
        .collect()
}
